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
out vec3 v_nrm;
out vec4 v_col;
out vec3 v_wpos;
#if HOL_LIT
uniform float u_klein;
// the Klein point (x, y) of a tile's floor, height
out vec3 v_loc;
#endif
// the tile's four light slots and the eye, in the tile's own frame
// (hol__item_lights): the x, y, z of lights 0..3, then the eye's; L =
// l.z - k.l.xy is affine in the vertex, so interpolation is exact
#if HOL_LIT == 2
// the room's meshes (trees, hedges): their lanterns' cells (u_tl, as in
// scene.frag.glsl), 3 in u_light a flat room; per vertex the floor parts
// of the lights, per lantern (hol_room_floor): the squared floor distance
// (metres), the hyperbolic factor of the falloff, and <n_h, t> times the
// floor distance (metres) of the Lambert term
uniform vec4 u_tl[4];
uniform highp int u_light;
uniform float u_mpu2;
out vec4 v_rx;
out vec4 v_rq;
out vec4 v_rh;
// A point's Klein point k in the frame of each lantern's cell (its centre
// the light's foot): cosh x = g = 1 / sqrt(1 - |k|^2), c^2 = 2 g - 2
// (flat: c^2 = |k|^2, x = c); the floor direction to the light -k / |k|.
void hol_room_floor(vec3 p, vec3 n) {
  float fl = u_light == 3 ? 1.0 : 0.0;
  vec4 kx = (p.x - u_tl[0]) * u_klein, kz = (u_tl[1] - p.z) * u_klein;
  vec4 kk = kx * kx + kz * kz;
  vec4 g = inversesqrt(max(1.0 - kk, 1e-6));
  vec4 c2 = mix(2.0 * g - 2.0, kk, fl);
  vec4 sh = mix(sqrt(c2 + 0.25 * c2 * c2), sqrt(kk), fl) + 1e-6;
  vec4 x = mix(log(1.0 + 0.5 * c2 + sh), sh, fl);
  v_rx = x * x * u_mpu2;
  v_rq = mix(((1.0 - HOL_LIGHT_PHYS) * sh + HOL_LIGHT_PHYS * x) / sh, vec4(1.0), fl);
  v_rh = -(n.x * kx - n.z * kz) * inversesqrt(max(kk, 1e-20)) * x * sqrt(u_mpu2);
}
#endif
#if HOL_LIT == 1
uniform vec4 u_tl[4];
out vec4 v_L;
out float v_Le;
// the vertex's normal in the tile's own frame (the lights' Lambert term)
out vec3 v_nl;
// the tile's trunk shadow pairs (hol__item_shadows): three half-planes
// each, affine
#if HOL_SHD
uniform vec4 u_ts[13];
out HOL_SV v_S1;
out HOL_SV v_S2;
out HOL_SV v_S3;
#endif
// spots (HOL_PROG_FX_SPOTS) and up
#if HOL_FX >= 2
uniform vec4 u_tx[HOL_TX_ROWS];
// <u, (k, 1)>: a spot's direction, affine too
out vec4 v_U;
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
  v_nl = a_nrm;
#if HOL_SHD
  v_S1 = HOL_SV((v_loc.x * u_ts[0] + v_loc.z * u_ts[1] + u_ts[2]) HOL_SW);
  v_S2 = HOL_SV((v_loc.x * u_ts[3] + v_loc.z * u_ts[4] + u_ts[5]) HOL_SW);
  v_S3 = HOL_SV((v_loc.x * u_ts[6] + v_loc.z * u_ts[7] + u_ts[8]) HOL_SW);
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
#if HOL_LIT == 2
  hol_room_floor(w.xyz, v_nrm);
#endif
  v_col = a_col;
  gl_Position = u_vp * w;
}
