// sky.glsl - included by scene.frag.glsl and scene.vert.glsl (@include, in
// the lit programs): the sky's and the lights' colours and the tone map.
// the sky (docs/rendering.md#lighting): ambient, sun and lantern colours,
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
// docs/rendering.md#tone-map): Reinhard's curve with the white level K =
// HOL_LIGHT_TONE_K, l K / (K + l): slope 1 at 0 (a faint pool keeps its
// value), never above K, so K times the lanterns' colour (0.75 in red) is
// the most light the lanterns give a surface: a trunk beside one glows
// below its own colour, not clipped white.
float hol_tone(float l) {
  return l * HOL_LIGHT_TONE_K / (HOL_LIGHT_TONE_K + l);
}
