// scene.frag.glsl - the fragment shader of every program (day, lit tiles,
// lit room). The preamble render/hol_program.c builds from a program's key
// comes first: HOL_LIT (0 day, 1 lit tiles, 2 lit room), HOL_FLAT (the
// {4,4} grid), HOL_WEDGE (discard outside a branch's wedge), HOL_NIGHT (1
// night, 2 between dusk and night),
// HOL_VLIT (1: a lit tile's small props, lit and fogged per vertex:
// scene.vert.glsl's hol_vlight),
// HOL_FX (HOL_PROG_FX_*: 0 lanterns, 1 fireflies, 2 spots; a value has
// the code of those below it: test with >=), HOL_TX_ROWS (u_tx's rows of
// per-light values), HOL_SHD (1: the tile's shadow mask, HOL_SHM_N its
// side, HOL_SHM_R its range, HOL_SHM_W and _H the masks a row and a column
// of their texture: core/hol_shadow.h), HOL_LAMPS (the lit room's
// trees and hedges take the lanterns' light; 0: its backdrop and outer
// ground, ambient and sun only), HOL_TEXT (the overlays' program:
// flat colours and glyphs, with alpha), HOL_SPREAD (the atlas's field
// reach, core/hol_face.h), and the lights' constants of
// render/hol_light.h (HOL_LIGHT_D0_M, ...).
// The draw's values (the fog, the eye, the mode, the output's encoding,
// the lights' rows of u_tx, ...) are read through HOL_K* names: flat
// varyings that scene.vert.glsl's hol_draw_values writes, as SwiftShader
// loads a uniform for every fragment and every use (docs/web.md).
// Whole-line // comments and blank lines are left out of the C string the
// build makes (render/shaders/glsl_c.sh); "@include F" inserts F there.
//
// cos of HOL_LIGHT_SPOT_OUTER_DEG and _INNER_DEG (35 and 25 degrees)
#define HOL_SPOT_COS_O 0.8191520443
#define HOL_SPOT_COS_I 0.9063077870
precision highp float;
// the small props' programs (HOL_VLIT) take their colour from the vertex
// shader alone (v_vc): the other varyings are plain, unused globals there
// (SwiftShader sets up every varying of every triangle: a tuft's blades
// are many small ones)
#if HOL_VLIT
#define HOL_IN
in vec3 v_vc;
#else
#define HOL_IN in
#endif
// a tile's ground (HOL_FLOOR): no normal, Lambert term's horizontal part
// or point (scene.vert.glsl)
#if HOL_VLIT || HOL_FLOOR
#define HOL_INN
#else
#define HOL_INN in
#endif
#if HOL_FLOOR
#define HOL_INF
#else
#define HOL_INF in
#endif
HOL_INN vec3 v_nrm;
HOL_IN vec4 v_col;
HOL_INF vec3 v_wpos;
uniform vec4 u_id;
uniform vec4 u_wedge;
uniform int u_wmode;
// The draw's values (HOL_K*): flat varyings from the vertex shader
// (scene.vert.glsl's hol_draw_values: SwiftShader loads a uniform for
// every fragment and every use, a varying once for the fragment's quad),
// but in the overlays' and the small props' programs the uniforms.
#if HOL_TEXT || HOL_VLIT
#define HOL_KV 0
uniform int u_mode;
uniform vec3 u_eye;
uniform vec3 u_fog;
uniform float u_fogd;
uniform int u_lin;
#define HOL_KMODE float(u_mode)
#define HOL_KEYE u_eye
#define HOL_KFOG u_fog
#define HOL_KFOGD u_fogd
#define HOL_KLIN float(u_lin)
#else
#define HOL_KV 1
flat in vec4 v_k0, v_k1, v_k2;
#define HOL_KMODE v_k1.w
#define HOL_KEYE v_k1.xyz
#define HOL_KFOG v_k0.rgb
#define HOL_KFOGD v_k0.w
#define HOL_KLIN v_k2.x
#endif
#if HOL_TEXT
in vec2 v_uv;
uniform sampler2D u_atlas;
#endif
#if HOL_LIT
// lighting (hol_light.h): 1 a tile with its hyperbolic frame; 2 the
// room's own meshes (no tile: ambient, fog by room distance)
HOL_IN vec3 v_loc;
#if HOL_KV
#define HOL_KLONLY v_k2.y
#define HOL_KLIGHT v_k2.z
#define HOL_KMPU2 v_k2.w
#else
uniform highp int u_light;
uniform int u_lonly;
uniform float u_mpu2;
#define HOL_KLONLY float(u_lonly)
#define HOL_KLIGHT float(u_light)
#define HOL_KMPU2 u_mpu2
#endif
#if HOL_LIT == 1
HOL_IN vec4 v_L;
HOL_IN float v_Le;
HOL_INN vec4 v_th;
#if HOL_SHD
uniform sampler2D u_shm;
HOL_IN vec2 v_st;
#endif
// per-light values (u_tx[5]: a lantern's weight, in every lit tile's
// program: lanterns merged by the budget weigh more than 1); the eye's
// height
#if HOL_KV
flat in float v_k3;
flat in vec4 v_tx5;
#define HOL_KEYEH v_k3
#define HOL_KTX5 v_tx5
#if HOL_FX >= 1
flat in vec4 v_tx4, v_tx6;
#define HOL_KTX4 v_tx4
#define HOL_KTX6 v_tx6
#endif
#if HOL_FX >= 2
flat in vec4 v_tx3;
#define HOL_KTX3 v_tx3
#else
#define HOL_KTX3 vec4(-2.0)
#endif
#else
uniform float u_eyeh;
uniform vec4 u_tx[HOL_TX_ROWS];
#define HOL_KEYEH u_eyeh
#define HOL_KTX3 u_tx[3]
#define HOL_KTX4 u_tx[4]
#define HOL_KTX5 u_tx[5]
#define HOL_KTX6 u_tx[6]
#endif
// spots (HOL_PROG_FX_SPOTS) and up
#if HOL_FX >= 2
HOL_IN vec4 v_U;
#else
const vec4 v_U = vec4(0.0);
#endif
#endif
@include sky.glsl
#endif
out vec4 o_col;
// linear light out (docs/lighting.md#linear-light): the sRGB buffer takes
// it as it is; else encoded here by square roots (the sRGB curve within
// 0.1 of a code: tests/test_render_light.c), and in the lit programs
// dithered by +-1/2 code, a pattern of the pixel (no bands in the dark):
// the tiles' and the room's trees and hedges, not the room's backdrop and
// outer ground (HOL_LAMPS 0: ambient and sun on flat faces, no lantern's
// gradient to band; its many layers behind the hedges are shaded on
// SwiftShader all the same)
vec4 hol_lin_out(vec3 c) {
  if (HOL_KLIN == 1.0) return vec4(c, 1.0);
  c = max(c, 0.0);
  vec3 s = sqrt(c);
  vec3 e = mix(12.92 * c, HOL_SRGB_A * s + HOL_SRGB_B * sqrt(s) + HOL_SRGB_C * c + HOL_SRGB_D,
               step(vec3(0.0031308), c));
#if HOL_LIT == 1 || HOL_LAMPS
// the R2 sequence's plane over the pixel in the window (one dot, one
// fract; no uniform: llvmpipe loads a uniform per pixel): spread evenly
// over every few pixels
  e += fract(dot(gl_FragCoord.xy, vec2(0.7548776662, 0.5698402910))) * (1.0 / 255.0) -
       0.5 / 255.0;
#endif
  return vec4(e, 1.0);
}
#if HOL_LIT == 1
// The shadows of a tile (render/hol_light.h, core/hol_shadow.h): every
// trunk's shadow from every light of the tile, rastered on the CPU into
// the tile's mask, one byte a light slot; u_shr: 1 / (2 A) (A the tile's
// Klein half side), then the mask's first texel centre in u_shm's
// coordinates. The Klein point k maps to the mask's texel centres (k = +-A
// on the edge ones: v_st, per vertex in scene.vert.glsl, as the map is
// affine); the bilinear mix t of the stored bytes holds u =
// (2 t - 1) R, the occlusion is clamp(1/2 + u, 0, 1), and each light is
// multiplied by 1 - that = clamp(R + 1/2 - 2 R t, 0, 1).
#if HOL_SHD
vec4 hol_shadow(float g) {
  return hol_shadow_of(texture(u_shm, v_st));
}
#else
vec4 hol_shadow(float g) {
  return vec4(1.0);
}
#endif
// all four slots (an empty slot lies far beyond the radius).
// k the fragment's Klein point; hyperbolic: g = 1/sqrt(1 - |k|^2) and
// cosh x = g L, L = -<(k, 1), l>_L = l.z - k.l.xy, so the squared chord
// c^2 = 2 (cosh x - 1) = 2 g L - 2, sinh x = sqrt(c^2 (1 + c^2/4)),
// x = log(cosh x + sinh x); flat: the slot's z is |l|^2/2 and
// c^2 = |k - l|^2 = 2 L + |k|^2, x = c
#if HOL_FX
// per slot: u_tx[4] the light's height, [5] a lantern's weight, [6] a
// firefly's (the second sum, ff); a spot (u_tx[3] its sin(tilt), -2:
// none) multiplies by its cone: cos(angle) = (x <u,t> + sin(tilt) dh)
// / d, x <u,t> = x <u,p> / sinh x = g x U / sh (flat: U), metres per
// unit folded into u (render/hol_light.h)
// One slot (dh its height over the point, th its Lambert term's
// horizontal part, sd its shadow factor, st its spot's sin(tilt)), then
// the four: slot by slot, so that few values live at once (the same
// numbers; SwiftShader compiled the side-by-side form of these programs
// into code whose cost jumped by a third with unrelated changes:
// docs/performance.md, night against day on the web)
#define HOL_V float
float hol_light(float L, float U, float g, float o, float dh, float nup, float th, float sd,
                float st) {
  float c2 = max(2.0 * g * L + o, 0.0);
@include falloff.glsl
  float id = inversesqrt(max(d2, 1e-8));
  float f = w * w * num / den * sd;
// the cone: only the programs of frames with a spot (HOL_FX 2 and up)
// spots (HOL_PROG_FX_SPOTS) and up
#if HOL_FX >= 2
#if HOL_FLAT
  float hz = U;
#else
  float hz = g * x * U / sh;
#endif
  float cone = smoothstep(HOL_SPOT_COS_O, HOL_SPOT_COS_I, (hz + st * dh) * id);
  f *= mix(cone, 1.0, step(st, -1.5));
#endif
  return f * hol_lambert(th, xm, dh, id, nup);
}
float hol_lights(vec4 L, vec4 U, float g, float o, float y, float nup, vec4 th, out float ff) {
  vec4 dh = HOL_KTX4 - y, sd = hol_shadow(g), st = HOL_KTX3;
  vec4 f = vec4(hol_light(L.x, U.x, g, o, dh.x, nup, th.x, sd.x, st.x),
                hol_light(L.y, U.y, g, o, dh.y, nup, th.y, sd.y, st.y),
                hol_light(L.z, U.z, g, o, dh.z, nup, th.z, sd.z, st.z),
                hol_light(L.w, U.w, g, o, dh.w, nup, th.w, sd.w, st.w));
  ff = dot(f, HOL_KTX6);
  return dot(f, HOL_KTX5);
}
#undef HOL_V
#else
#define HOL_V vec4
float hol_lights(vec4 L, float g2, float o, float dh, float nup, vec4 th) {
  vec4 c2 = max(g2 * L + o, 0.0);
@include falloff.glsl
  vec4 f = w * w * num / den * hol_shadow(0.5 * g2) * HOL_KTX5;
  return dot(f, hol_lambert(th, xm, vec4(dh), inversesqrt(max(d2, 1e-8)), nup));
}
#undef HOL_V
#endif
#endif
#if HOL_LIT == 2 && HOL_LAMPS
// The room's trees and hedges (HOL_LAMPS: render/hol_render_gpu.c's
// hol__room_lights): lit per vertex by the tiles' law (scene.vert.glsl's
// hol_room_light) at the knot heights 0, 0.65, 1.3, 1.95 and 3.25 m, and
// here linearly between the knots by the fragment's height (above 3.25 m
// the last two knots' line, not below 0: the crowns' faint light falling
// off); docs/lighting.md says where that departs
in vec4 v_rl;
in float v_rk;
float hol_room_lam(float y) {
  float t = y * (1.0 / 0.65);
  vec4 hat = max(1.0 - abs(t - vec4(0.0, 1.0, 2.0, 3.0)), 0.0);
  return t > 3.0 ? max(mix(v_rl.w, v_rk, 0.5 * (t - 3.0)), 0.0) : dot(hat, v_rl);
}
#endif
void main() {
#if HOL_TEXT
// a glyph (alpha HOL_MESH_GLYPH): the signed distance d in atlas pixels,
// an edge of one screen pixel (half on each side); anything else is opaque
  float td = (texture(u_atlas, v_uv).r * 255.0 - 128.0) * (HOL_SPREAD / 128.0);
  float tw = max(0.5 * length(fwidth(v_uv * vec2(textureSize(u_atlas, 0)))), 1e-3);
  float ta = v_col.a > 0.1 ? smoothstep(-tw, tw, td) : 1.0;
  if (HOL_KMODE == 1.0) {
    if (ta < 0.5) discard;
    o_col = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
// an authored colour as it is (scene.vert.glsl decodes it for an sRGB
// buffer)
  o_col = vec4(v_col.rgb, ta);
  return;
#endif
#if HOL_WEDGE
  if (u_wmode == 1) {
    vec2 d = v_wpos.xz - HOL_KEYE.xz;
    float e = -1e-4 * length(d);
    if (u_wedge.x * d.y - u_wedge.y * d.x < e ||
        d.x * u_wedge.w - d.y * u_wedge.z < e) discard;
  }
#endif
#if HOL_VLIT
// a small prop: lit, fogged and toned per vertex (scene.vert.glsl's
// hol_vlight); u_lonly's light, fog and fireflies as they are
  o_col = HOL_KLONLY == 1.0 ? vec4(v_vc, 1.0) : hol_lin_out(v_vc);
#else
  if (HOL_KMODE == 1.0) {
    o_col = v_col.a > 0.5 ? u_id : vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  if (HOL_KMODE == 2.0) {
    o_col = vec4(v_col.rgb, 1.0);
    return;
  }
#if HOL_FLOOR
// a tile's ground: its normal straight up, towards the eye (above it);
// the room's distance (toeye) is not its fog's (u_light is 1)
  vec3 toeye = vec3(0.0), n = vec3(0.0, 1.0, 0.0);
  float sgn = 1.0;
#else
  vec3 toeye = HOL_KEYE - v_wpos;
  vec3 n = v_nrm;
  if (dot(n, n) < 1e-6) n = vec3(0.0, 1.0, 0.0);
  n = normalize(n);
  float sgn = dot(n, toeye) < 0.0 ? -1.0 : 1.0;
  n *= sgn;
#endif
  float d = max(dot(n, normalize(vec3(0.35, 0.85, 0.40))), 0.0);
#if HOL_LIT == 0
// the sky's light, linear (docs/lighting.md)
  vec3 c = v_col.rgb * (0.2458 + 0.9115 * d);
  float dist = length(toeye) * HOL_KFOGD;
  float f = exp(-dist * dist);
  o_col = hol_lin_out(mix(HOL_KFOG, c, f));
#else
  float lam = 0.0, lamf = 0.0, de2 = dot(toeye, toeye);
#if HOL_LIT == 1
  if (HOL_KLIGHT == 1.0) {
// the Lambert term's horizontal part, the normal turned to the eye as n is
#if HOL_FLOOR
    vec4 th = vec4(0.0);
#else
    vec4 th = sgn * v_th;
#endif
    vec2 go = hol_go(v_loc.xz);
    float g = go.x, o = go.y;
#if HOL_FX
    lam = hol_lights(v_L, v_U, g, o, v_loc.y, n.y, th, lamf);
#else
    lam = hol_lights(v_L, 2.0 * g, o, HOL_LIGHT_HEIGHT_M - v_loc.y, n.y, th);
#endif
// fog by the true distance from the eye (sky.glsl)
    de2 = hol_eye_d2(g, o, v_Le, v_loc.y);
  }
#endif
// the room's (u_light 2 or 3: always, in its programs)
#if HOL_LIT == 2 && HOL_LAMPS
  lam = hol_room_lam(v_wpos.y);
#endif
// the lanterns' sum mapped back (fireflies' lamf as it is: faint)
  lam = hol_tone(lam);
  float f = exp(-de2 * (HOL_KFOGD * HOL_KFOGD));
  vec3 c = hol_lit(v_col.rgb, d, lam, lamf);
#if HOL_LIT == 1
  // a lantern's glass: unlit (the room has none)
  if (abs(v_col.a - 100.0 / 255.0) < 0.01) c = v_col.rgb * 1.5;
#endif
// the light alone (u_lonly: the tests' frames) chosen, not branched to:
// SwiftShader runs the rest of a shader under a mask after a return in a
// branch
  o_col = HOL_KLONLY == 1.0 ? vec4(hol_light_only(lam, f, lamf), 1.0) : hol_lin_out(mix(HOL_KFOG, c, f));
#endif
#endif
}
