// sky.glsl - included by scene.frag.glsl and scene.vert.glsl (@include, in
// the lit programs): the sky's and the lights' colours, the tone map, a
// lit tile's Lambert term, shadow factor and distance from the eye (the
// fog's), a surface's lit colour and the light-only frames' output.
// the sky (docs/lighting.md): ambient, sun and lantern colours,
// linear light (calibrated through the sRGB curve: #linear-light)
// HOL_NIGHT 2: a sky between dusk and night (a lighting cycle), the
// frame's mix of the two (render/hol_render_gpu.c's hol__frame_lights)
#if HOL_NIGHT == 2
uniform vec3 u_amb, u_sun;
#elif HOL_NIGHT
const vec3 u_amb = vec3(0.0129, 0.0151, 0.0276), u_sun = vec3(0.0117, 0.0151, 0.0347);
#else
const vec3 u_amb = vec3(0.0980, 0.0772, 0.0873), u_sun = vec3(0.2174, 0.1039, 0.0661);
#endif
const vec3 u_lcol = vec3(1.76, 0.99, 0.34), u_fcol = vec3(0.31, 0.51, 0.11);
// The tone map of the lanterns' sum l (render/hol_light.h,
// docs/lighting.md#tone-map): Reinhard's curve with the white level K =
// HOL_LIGHT_TONE_K, l K / (K + l): slope 1 at 0 (a faint pool keeps its
// value), never above K, so K times the lanterns' colour (0.75 in red) is
// the most light the lanterns give a surface: a trunk beside one glows
// below its own colour, not clipped white.
float hol_tone(float l) {
  return l * HOL_LIGHT_TONE_K / (HOL_LIGHT_TONE_K + l);
}
// A surface's linear colour cl lit by the sky (sun: its Lambert term
// towards the sun), the lanterns' toned sum lam and the fireflies' lamf:
// the fragment's (the lit tiles and room) and the small props' vertex's.
vec3 hol_lit(vec3 cl, float sun, float lam, float lamf) {
  return cl * (u_amb + u_sun * sun + u_lcol * lam + u_fcol * lamf);
}
// What the light-only frames (u_lonly: the tests') write instead: the
// lanterns' sum, the fog's factor f and the fireflies' sum, each at most 1.
vec3 hol_light_only(float lam, float f, float lamf) {
  return vec3(min(lam, 1.0), f, min(lamf, 1.0));
}
#if HOL_LIT == 1
// A lit tile's Klein point k: g = 1 / sqrt(1 - |k|^2) and o = -2, so that
// the squared chord to a slot is c^2 = 2 g L + o (scene.frag.glsl's
// hol_lights); flat: g = 1, o = |k|^2.
vec2 hol_go(vec2 k) {
  float kk = dot(k, k);
#if HOL_FLAT
  return vec2(1.0, kk);
#else
  return vec2(inversesqrt(max(1.0 - kk, 1e-6)), -2.0);
#endif
}
// The Lambert term of every surface (trunks, posts, props and the floor):
// max(n_up, 0) max(dh, 0) / d plus the horizontal part <n_h, t> x / d,
// t the unit floor direction from the point to each light's foot in the
// tile's Klein frame (th = <n_h, t> per vertex: scene.vert.glsl; the
// floor's n_h is 0, so its term is the floor's law unchanged), x / d =
// xm / d with xm the floor distance in metres (falloff.glsl's: x times
// the metres per unit, no square root of its own); the four slots at
// once or one.
vec4 hol_lambert(vec4 th, vec4 xm, vec4 dh, vec4 id, float nup) {
  return 0.3 + 0.7 * max((max(nup, 0.0) * max(dh, 0.0) + th * xm) * id, 0.0);
}
float hol_lambert(float th, float xm, float dh, float id, float nup) {
  return 0.3 + 0.7 * max((max(nup, 0.0) * max(dh, 0.0) + th * xm) * id, 0.0);
}
#if HOL_SHD
// A tile's shadow mask read at a point (t, the bilinear mix of its bytes)
// to each slot's factor (scene.frag.glsl's hol_shadow says how).
vec4 hol_shadow_of(vec4 t) {
  return clamp(t * (-2.0 * HOL_SHM_R) + (HOL_SHM_R + 0.5), 0.0, 1.0);
}
#endif
// Fog by the true distance from the eye: the floor distance x from the
// squared chord c^2 to the eye as for a light (falloff.glsl: x = log(cosh
// x + sinh x), cosh x = 1 + c^2/2, sinh x = sqrt(c^2 (1 + c^2/4))); flat:
// x^2 = c^2. Then D^2 = x^2 (metres) + dh^2, returned; g and o as the
// lights', le the eye's L, y the point's height.
float hol_eye_d2(float g, float o, float le, float y) {
  float ce2 = max(2.0 * g * le + o, 0.0);
#if HOL_FLAT
  float xe2 = ce2;
#else
  float xe = log(1.0 + 0.5 * ce2 + sqrt(ce2 + 0.25 * ce2 * ce2));
  float xe2 = xe * xe;
#endif
  float dh = HOL_KEYEH - y;
  return xe2 * HOL_KMPU2 + dh * dh;
}
#endif
