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
#if HOL_LIT == 1
uniform vec4 u_tl[4];
out vec4 v_L;
out float v_Le;
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
  v_col = a_col;
  gl_Position = u_vp * w;
}
