// scene.vert.glsl - the vertex shader of every program; the preamble and
// its defines as in scene.frag.glsl.
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_nrm;
layout(location = 2) in vec4 a_col;
#if HOL_TEXT
// a glyph's atlas point (render/hol_mesh.h's HOL_MESH_GLYPH)
layout(location = 3) in vec2 a_uv;
out vec2 v_uv;
#endif
uniform mat4 u_vp;
uniform mat4 u_model;
// as scene.frag.glsl's (a uniform of both stages keeps one precision)
uniform mediump int u_mode;
uniform mediump int u_lin;
#if !HOL_TEXT
uniform vec3 u_eye;
uniform vec3 u_fog;
uniform float u_fogd;
#endif
#if HOL_LIT
uniform highp int u_light;
uniform mediump int u_lonly;
uniform float u_mpu2;
uniform float u_eyeh;
#endif
#if HOL_LIT == 1
uniform vec4 u_tx[HOL_TX_ROWS];
#endif
// falloff.glsl's and sky.glsl's values, as scene.frag.glsl's (HOL_K*):
// here the uniforms themselves
#define HOL_KMPU2 u_mpu2
#define HOL_KEYEH u_eyeh
// The draw's values for the fragment shader (scene.frag.glsl's HOL_KV):
// flat, so that a fragment takes them from its triangle, not from the
// uniforms (SwiftShader loads a uniform for every fragment and every use:
// docs/performance.md); not the overlays' nor the small props' programs
// (HOL_VLIT: a tuft's many small triangles set up no more varyings).
#if !HOL_TEXT && !HOL_VLIT
flat out vec4 v_k0, v_k1, v_k2;
#if HOL_LIT == 1
flat out float v_k3;
flat out vec4 v_tx5;
#if HOL_FX >= 1
flat out vec4 v_tx4, v_tx6;
#endif
#if HOL_FX >= 2
flat out vec4 v_tx3;
#endif
#endif
// v_k0: the fog's colour and density; v_k1: the eye, the mode; v_k2:
// the output's encoding (u_lin), and lit: the light-only frames, the
// lighting (u_light), the metres per unit squared; v_k3: the eye's
// height; v_tx*: u_tx's rows 3-6 (spots' tilts, heights, lanterns' and
// fireflies' weights) as the program's effects need them
void hol_draw_values() {
  v_k0 = vec4(u_fog, u_fogd);
  v_k1 = vec4(u_eye, float(u_mode));
#if HOL_LIT
  v_k2 = vec4(float(u_lin), float(u_lonly), float(u_light), u_mpu2);
#else
  v_k2 = vec4(float(u_lin), 0.0, 0.0, 0.0);
#endif
#if HOL_LIT == 1
  v_k3 = u_eyeh;
  v_tx5 = u_tx[5];
#if HOL_FX >= 1
  v_tx4 = u_tx[4];
  v_tx6 = u_tx[6];
#endif
#if HOL_FX >= 2
  v_tx3 = u_tx[3];
#endif
#endif
}
#endif
// the small props' programs (HOL_VLIT) give the fragment their colour
// alone (v_vc, scene.frag.glsl): the other varyings are plain globals
#if HOL_VLIT
#define HOL_OUT
#else
#define HOL_OUT out
#endif
// a tile's ground (HOL_FLOOR): its normal is straight up, so the normal,
// the Lambert term's horizontal part and the point (only for the turn to
// the eye) are plain globals too
#if HOL_VLIT || HOL_FLOOR
#define HOL_OUTN
#else
#define HOL_OUTN out
#endif
#if HOL_FLOOR
#define HOL_OUTF
#else
#define HOL_OUTF out
#endif
HOL_OUTN vec3 v_nrm;
HOL_OUT vec4 v_col;
HOL_OUTF vec3 v_wpos;
#if HOL_LIT
uniform float u_klein;
// the Klein point (x, y) of a tile's floor, height
HOL_OUT vec3 v_loc;
#endif
// the tile's four light slots and the eye, in the tile's own frame
// (hol__item_lights): the x, y, z of lights 0..3, then the eye's; L =
// l.z - k.l.xy is affine in the vertex, so interpolation is exact
#if HOL_LIT == 2 && HOL_LAMPS
// the room's trees and hedges (HOL_LAMPS), lit per vertex: their lanterns'
// cells (u_tl: x, z in room metres, heights, weights), 3 in u_light a
// flat room; the light at the vertex's floor point at the knot heights
// 0, 0.65, 1.3, 1.95 m
// (v_rl) and 3.25 m (v_rk), which the fragment interpolates by its own
// height (scene.frag.glsl: the light's change with height is followed
// without cutting the meshes)
uniform vec4 u_tl[4];
out vec4 v_rl;
out float v_rk;
// At height y over the vertex's floor point: the distance d^2, the fade w,
// the Lambert term (the normal's vertical part, then h the horizontal
// part times x) and the falloff, summed over the lanterns.
float hol_room_at(float y, vec4 x, vec4 q, vec4 h, float nup) {
  float dh = HOL_LIGHT_HEIGHT_M - y;
  vec4 d2 = x * x * u_mpu2 + dh * dh;
  vec4 w = max(1.0 - d2 * (1.0 / (HOL_LIGHT_RADIUS_M * HOL_LIGHT_RADIUS_M)), 0.0);
  vec4 lb = 0.3 + 0.7 * max((nup * max(dh, 0.0) + h) * inversesqrt(max(d2, 1e-8)), 0.0);
  return dot(w * w * q / (1.0 + d2 * (1.0 / (HOL_LIGHT_D0_M * HOL_LIGHT_D0_M))) * lb, u_tl[3]);
}
// A point's Klein point k in the frame of each lantern's cell (its centre
// the light's foot): cosh x = g = 1 / sqrt(1 - |k|^2), c^2 = 2 g - 2
// (flat: c^2 = |k|^2, x = c); the floor direction to the light -k / |k|.
// Then the tiles' law (falloff.glsl, hol_lambert): every room lantern
// hangs at HOL_LIGHT_HEIGHT_M; the normal turned to the eye; the light at
// each knot height into v_rl and v_rk.
void hol_room_light(vec3 p, vec3 n) {
  float fl = u_light == 3 ? 1.0 : 0.0;
  vec4 kx = (p.x - u_tl[0]) * u_klein, kz = (u_tl[1] - p.z) * u_klein;
  vec4 kk = kx * kx + kz * kz;
  vec4 g = inversesqrt(max(1.0 - kk, 1e-6));
  vec4 c2 = mix(2.0 * g - 2.0, kk, fl);
  vec4 sh = mix(sqrt(c2 + 0.25 * c2 * c2), sqrt(kk), fl) + 1e-6;
  vec4 x = mix(log(1.0 + 0.5 * c2 + sh), sh, fl);
  vec4 q = mix(((1.0 - HOL_LIGHT_PHYS) * sh + HOL_LIGHT_PHYS * x) / sh, vec4(1.0), fl);
  vec3 nn = dot(n, n) < 1e-6 ? vec3(0.0, 1.0, 0.0) : normalize(n);
  nn *= dot(nn, u_eye - p) < 0.0 ? -1.0 : 1.0;
  vec4 h = -(nn.x * kx - nn.z * kz) * inversesqrt(max(kk, 1e-20)) * x * sqrt(u_mpu2);
  float nup = max(nn.y, 0.0);
  v_rl = vec4(hol_room_at(0.0, x, q, h, nup), hol_room_at(0.65, x, q, h, nup),
              hol_room_at(1.3, x, q, h, nup), hol_room_at(1.95, x, q, h, nup));
  v_rk = hol_room_at(3.25, x, q, h, nup);
}
#endif
#if HOL_LIT == 1
uniform vec4 u_tl[4];
HOL_OUT vec4 v_L;
HOL_OUT float v_Le;
// the Lambert term's horizontal part per light: <n_h, t>, n_h the
// normal's floor part in the tile's Klein frame (v_loc's z is -z), t the
// unit floor direction to the light's foot: minus the gradient of cosh x
// = g L (g^2 L k - l.xy up to g; flat: k - l.xy). Per vertex: t turns
// little over a prop's face, and the floor's n_h is 0.
HOL_OUTN vec4 v_th;
#if HOL_SHD
// the shadow mask's point (scene.frag.glsl's hol_shadow): affine in the
// Klein point, so interpolation is exact
uniform vec4 u_shr;
HOL_OUT vec2 v_st;
#endif
vec4 hol_th(vec3 nrm, vec2 k) {
  vec3 nl = dot(nrm, nrm) < 1e-6 ? vec3(0.0, 1.0, 0.0) : normalize(nrm);
#if HOL_FLAT
  float a = 1.0;
#else
  float a = 1.0 / max(1.0 - dot(k, k), 1e-6);
#endif
  vec4 gx = a * k.x * v_L - u_tl[0], gy = a * k.y * v_L - u_tl[1];
  return -(gx * nl.x - gy * nl.z) * inversesqrt(max(gx * gx + gy * gy, 1e-20));
}
#if HOL_FX >= 2
// <u, (k, 1)>: a spot's direction, affine too
HOL_OUT vec4 v_U;
#endif
#if HOL_VLIT
// A tile's small props (grass tufts, flowers, mushrooms: the renderer's
// hol__item.props), lit, fogged and toned per vertex: scene.frag.glsl's
// lit tile at the vertex (its four slots by the same law, falloff.glsl,
// and the same Lambert term, the normal turned to the eye, the shadow
// mask read at the vertex's own point; the sun's term; the fog by the
// true distance), its colour in linear light (v_vc), which the fragment
// only writes; spots are not followed (a tile with a spot in its slots
// keeps the per-fragment light). docs/lighting.md says where
// that departs.
#if HOL_SHD
uniform sampler2D u_shm;
#endif
@include sky.glsl
out vec3 v_vc;
#define HOL_V vec4
void hol_vlight(vec3 wp, vec3 wn, vec4 th, vec3 cl) {
  vec2 go = hol_go(v_loc.xz);
  float g = go.x, o = go.y;
  vec3 n = dot(wn, wn) < 1e-6 ? vec3(0.0, 1.0, 0.0) : normalize(wn);
  float sgn = dot(n, u_eye - wp) < 0.0 ? -1.0 : 1.0;
  n *= sgn;
  th *= sgn;
  vec4 dh = u_tx[4] - v_loc.y;
  vec4 c2 = max(2.0 * g * v_L + o, 0.0);
@include falloff.glsl
#if HOL_SHD
  vec4 sd = hol_shadow_of(textureLod(u_shm, v_st, 0.0));
#else
  vec4 sd = vec4(1.0);
#endif
  vec4 f = w * w * num / den * sd * hol_lambert(th, xm, dh, inversesqrt(max(d2, 1e-8)), n.y);
  float lam = hol_tone(dot(f, u_tx[5])), lamf = dot(f, u_tx[6]);
// the fog as scene.frag.glsl's, by the true distance from the eye
  float fog = exp(-hol_eye_d2(g, o, v_Le, v_loc.y) * (u_fogd * u_fogd));
  float sun = max(dot(n, normalize(vec3(0.35, 0.85, 0.40))), 0.0);
  v_vc = u_lonly == 1 ? hol_light_only(lam, fog, lamf) : mix(u_fog, hol_lit(cl, sun, lam, lamf), fog);
}
#undef HOL_V
#endif
#endif
void main() {
  vec4 w = u_model * vec4(a_pos, 1.0);
#if HOL_LIT
  v_loc = vec3(a_pos.x * u_klein, a_pos.y, -a_pos.z * u_klein);
#endif
#if HOL_LIT == 1
  v_L = u_tl[2] - v_loc.x * u_tl[0] - v_loc.z * u_tl[1];
  v_Le = u_tl[3].z - v_loc.x * u_tl[3].x - v_loc.z * u_tl[3].y;
#if !HOL_FLOOR
  v_th = hol_th(a_nrm, v_loc.xz);
#endif
#if HOL_SHD
  v_st = clamp(v_loc.xz * u_shr.x + 0.5, 0.0, 1.0) *
             vec2((HOL_SHM_N - 1.0) / (HOL_SHM_W * HOL_SHM_N),
                  (HOL_SHM_N - 1.0) / (HOL_SHM_H * HOL_SHM_N)) +
         u_shr.yz;
#endif
// spots (HOL_PROG_FX_SPOTS) and up
#if HOL_FX >= 2
  v_U = v_loc.x * u_tx[0] + v_loc.z * u_tx[1] - u_tx[2];
#endif
#endif
#if HOL_TEXT
  v_uv = a_uv;
#endif
  v_wpos = w.xyz;
  v_nrm = mat3(u_model) * a_nrm;
#if HOL_LIT == 2 && HOL_LAMPS
  hol_room_light(w.xyz, v_nrm);
#endif

// the colours are authored in sRGB: the lit mode (0) takes them to linear
// light here, once a vertex (docs/lighting.md#linear-light); the flat
// mode and the overlays' program keep them as authored, but for an sRGB
// buffer (u_lin), which encodes what is written: it takes them decoded
  vec3 cl = mix(a_col.rgb * (1.0 / 12.92), pow((a_col.rgb + 0.055) * (1.0 / 1.055), vec3(2.4)),
                step(vec3(0.04045), a_col.rgb));
#if HOL_TEXT
  v_col = vec4(u_lin == 1 ? cl : a_col.rgb, a_col.a);
#else
  v_col = vec4(u_mode == 0 || u_lin == 1 ? cl : a_col.rgb, a_col.a);
#endif
#if HOL_LIT == 1 && HOL_VLIT
  hol_vlight(w.xyz, v_nrm, v_th, cl);
#endif
#if !HOL_TEXT && !HOL_VLIT
  hol_draw_values();
#endif
  gl_Position = u_vp * w;
}
