/* hol_render.c - render queue, stencil portals, GL execution. */
#include "hol_render.h"

#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "hol_gl.h"
#include "hol_hud.h"
#include "hol_light.h"
#include "hol_mesh.h"
#include "hol_scene.h"

#include "../core/hol_hyper.h"
#include "../core/hol_world.h"

#define HOL__STR2(x) #x
#define HOL__STR(x) HOL__STR2(x)
/* cos of HOL_LIGHT_SPOT_OUTER_DEG and _INNER_DEG (35 and 25 degrees) */
#define HOL__SPOT_COS_O 0.8191520443
#define HOL__SPOT_COS_I 0.9063077870

/* GPU memory layout. The static buffers hold the room meshes and a pool of
 * tile meshes that stay resident across frames; the dynamic buffers get the
 * per-frame leaf polygons and HUD (a few KB). */
#define HOL__ROOM_V (1u << 16)
#define HOL__ROOM_I (1u << 17)
/* Tile meshes resident at once: a frame shows at most ~40 tiles in the
 * 3 x 3 room and 65 in a 5 x 5 one (test_render_tiles counts them). The
 * static buffers hold HOL__SLOTS_FIRST slots at create, HOL__SLOTS_MID
 * from the first frame that needs more, all of them from the first that
 * needs more again (hol__static_grow): llvmpipe clears a buffer it
 * allocates, 24 MB for all the slots, about 0.1 s of a picture's
 * start-up, 6 MB with the first 16 (a picture from the room's middle cell
 * builds about 14 tiles). */
#define HOL__SLOTS 96
#define HOL__SLOTS_FIRST 16
#define HOL__SLOTS_MID 48
/* shader program slots: 48 kinds x 3 shadow variants (hol__prog_exists) */
#define HOL__NPROG 144
#define HOL__SLOT_V 8192u
#define HOL__SLOT_I 16384u
#define HOL__HUD_V (1u << 14) /* the resident minimap, after the room */
#define HOL__HUD_I (1u << 15)
#define HOL__HUD_VBASE HOL__ROOM_V
#define HOL__HUD_IBASE HOL__ROOM_I
#define HOL__SLOT_VBASE(k) (HOL__ROOM_V + HOL__HUD_V + (uint32_t)(k) * HOL__SLOT_V)
#define HOL__SLOT_IBASE(k) (HOL__ROOM_I + HOL__HUD_I + (uint32_t)(k) * HOL__SLOT_I)
#define HOL__DYN_V (1u << 16)
#define HOL__DYN_I (1u << 17)
#define HOL__MAX_ITEMS 1024

typedef struct hol__slot {
    int used;
    hol_tile tile;
    int bare, pole, kind, have; /* have: content came from the world */
    double cell_m;
    hol_tile_content content;
    uint64_t last_frame;
    uint32_t nidx;
} hol__slot;

enum {
    HOL__PASS_STENCIL = 0,
    HOL__PASS_ROOM = 1,
    HOL__PASS_TILE = 2,
    HOL__PASS_HAND = 3, /* the minimap on a quad in the hand (world space) */
    HOL__PASS_FADE = 4, /* the safety fade over the scene (blended) */
    HOL__PASS_HUD = 5,
    HOL__PASS_PANEL = 6 /* a headset's UI panel in the world, over all */
};
enum { HOL__MODE_LIT = 0, HOL__MODE_ID = 1, HOL__MODE_FLAT = 2 };

typedef struct hol__item {
    uint32_t key;
    uint8_t pass;
    uint8_t dyn; /* 1: dynamic buffers */
    uint8_t ref, mask;
    int16_t branch;
    float wedge[4]; /* w0, w1 (x, z) when the view has wedges */
    int8_t nl;      /* lit tiles: lights (-1: no hyperbolic frame) */
    float tl[4][4]; /* u_tl: its lights and the eye in the tile's own frame */
    float tx[7][4]; /* u_tx: the spots' tangents (3) and sines, heights,
                       lantern and firefly weights (hol__item_lights) */
    float ts[13][4]; /* u_ts: its trunk shadow pairs (hol__item_shadows) */
    int8_t nsh;      /* how many (0: the programs without shadows) */
    uint32_t first, count; /* index range */
    float model[16];
} hol__item;

/* A shader program and its uniforms (-1: not in this program). */
typedef struct hol__prog {
    GLuint prog;
    GLint u_vp, u_model, u_mode, u_id, u_eye, u_fog, u_fogd, u_lin, u_wedge, u_wmode;
    GLint u_light, u_klein, u_mpu2, u_tl, u_eyeh, u_lonly, u_tx, u_ts;
} hol__prog;

struct hol_render {
    hol_render_desc desc;
    hol_gl gl;
    hol_scene *scene;
    GLuint vao[2], vbo[2], ibo[2]; /* [0] static, [1] dynamic */
    hol__prog progs[HOL__NPROG]; /* [0] day (the picture without lights), [1] lit
                            tiles, [2] lit room meshes (no tile code), [3]
                            lit tiles of the flat {4,4}; [4 + k] the same
                            able to discard outside a branch's wedge (the
                            others have no discard, so llvmpipe tests depth
                            before shading); [8 + k] the lit ones at night
                            ([k] at dusk: the sky's colours are constants,
                            uniforms cost llvmpipe a load per pixel);
                            [16 + k] the lit tiles' with fireflies (HOL_FX
                            1: per-light heights and weights), [32 + k] and
                            spots (HOL_FX 2): only frames that have them pay;
                            [48 v + k] the lit tiles' for tiles with up
                            to 4 (v 0), none (1) or up to two (2) trunk
                            shadow pairs (HOL_SHD 4, 0, 2) */
    hol__prog *pg;      /* this frame's */
    hol_light_frame lights; /* this frame's (at dusk and night) */
    hol_mesh dyn;     /* per-frame geometry */
    hol_mesh scratch; /* one room or tile mesh before upload */
    hol_vertex *verts;
    uint32_t *idx;
    hol__item items[HOL__MAX_ITEMS];
    int nitems;
    hol__item *sorted[HOL__MAX_ITEMS];
    hol_view view;
    /* resident meshes */
    hol__slot slots[HOL__SLOTS];
    int slot_cap; /* slots the static buffers hold now */
    uint64_t frame;
    int room_valid, room_bare;
    int room_tree[3];  /* the marked tree the room mesh has (marked, vx, vz) */
    hol_room room_user;
    double room_cell;
    struct hol_world *room_world;
    uint32_t room_nidx;
    int hud_valid;
    uint64_t hud_key;
    uint32_t hud_nidx;
    /* this frame's counters */
    long uploaded;
    int tiles_built;
};

static const char *hol__vs =
    "layout(location = 0) in vec3 a_pos;\n"
    "layout(location = 1) in vec3 a_nrm;\n"
    "layout(location = 2) in vec4 a_col;\n"
    "uniform mat4 u_vp;\n"
    "uniform mat4 u_model;\n"
    "out vec3 v_nrm;\n"
    "out vec4 v_col;\n"
    "out vec3 v_wpos;\n"
    "#if HOL_LIT\n"
    "uniform float u_klein;\n"
    "out vec3 v_loc;\n" /* the Klein point (x, y) of a tile's floor, height */
    "#endif\n"
    /* the tile's four light slots and the eye, in the tile's own frame
     * (hol__item_lights): the x, y, z of lights 0..3, then the eye's; L =
     * l.z - k.l.xy is affine in the vertex, so interpolation is exact */
    "#if HOL_LIT == 1\n"
    "uniform vec4 u_tl[4];\n"
    "out vec4 v_L;\n"
    "out float v_Le;\n"
    /* the tile's trunk shadow pairs (hol__item_shadows): three half-planes
     * each, affine */
    "#if HOL_SHD\n"
    "uniform vec4 u_ts[13];\n"
    "out HOL_SV v_S1;\n"
    "out HOL_SV v_S2;\n"
    "out HOL_SV v_S3;\n"
    "#endif\n"
    "#if HOL_FX == 2\n"
    "uniform vec4 u_tx[7];\n"
    "out vec4 v_U;\n" /* <u, (k, 1)>: a spot's direction, affine too */
    "#endif\n"
    "#endif\n"
    "void main() {\n"
    "  vec4 w = u_model * vec4(a_pos, 1.0);\n"
    "#if HOL_LIT\n"
    "  v_loc = vec3(a_pos.x * u_klein, a_pos.y, -a_pos.z * u_klein);\n"
    "#endif\n"
    "#if HOL_LIT == 1\n"
    "  v_L = u_tl[2] - v_loc.x * u_tl[0] - v_loc.z * u_tl[1];\n"
    "  v_Le = u_tl[3].z - v_loc.x * u_tl[3].x - v_loc.z * u_tl[3].y;\n"
    "#if HOL_SHD\n"
    "  v_S1 = HOL_SV((v_loc.x * u_ts[0] + v_loc.z * u_ts[1] + u_ts[2]) HOL_SW);\n"
    "  v_S2 = HOL_SV((v_loc.x * u_ts[3] + v_loc.z * u_ts[4] + u_ts[5]) HOL_SW);\n"
    "  v_S3 = HOL_SV((v_loc.x * u_ts[6] + v_loc.z * u_ts[7] + u_ts[8]) HOL_SW);\n"
    "#endif\n"
    "#if HOL_FX == 2\n"
    "  v_U = v_loc.x * u_tx[0] + v_loc.z * u_tx[1] - u_tx[2];\n"
    "#endif\n"
    "#endif\n"
    "  v_wpos = w.xyz;\n"
    "  v_nrm = mat3(u_model) * a_nrm;\n"
    "  v_col = a_col;\n"
    "  gl_Position = u_vp * w;\n"
    "}\n";

/* After "#version 300 es" and "#define HOL_LIT 0|1" (hol__make_prog): the
 * day program is exactly the shader before lights; the lit one (dusk and
 * night) adds the hyperboloid point, the lanterns and the fog by the true
 * distance. */

/* The lights' falloff in GLSL, shared by hol_lights' two forms: from c2
 * (the squared chord to each light) and dh (the height above the point) to
 * d2 (the squared H2 x E distance, metres), num / den (the blended falloff)
 * and w (the fade to 0 at HOL_LIGHT_RADIUS_M); sh and x (sinh and the floor
 * distance) in hyperbolic programs. */
#define HOL__FALLOFF_GLSL \
    "#if HOL_FLAT\n" \
    "  vec4 d2 = c2 * u_mpu2 + dh * dh;\n" \
    "  vec4 den = 1.0 + d2 * (1.0 / (" HOL__STR(HOL_LIGHT_D0_M) " * " HOL__STR(HOL_LIGHT_D0_M) "));\n" \
    "  vec4 num = vec4(1.0);\n" \
    "#else\n" \
    /* s = x / sinh x as one quotient with the inverse square: (1 - B + B s) \
     * / (1 + d^2/D0^2) = ((1 - B) sh + B x) / (sh (1 + d^2/D0^2)), sh and x \
     * nudged by 1e-6 so that s is 1 at the light's foot */ \
    "  vec4 sh = sqrt(c2 + 0.25 * c2 * c2) + 1e-6;\n" \
    "  vec4 x = log(1.0 + 0.5 * c2 + sh);\n" \
    "  vec4 d2 = x * x * u_mpu2 + dh * dh;\n" \
    "  vec4 num = (1.0 - " HOL__STR(HOL_LIGHT_PHYS) ") * sh + " HOL__STR(HOL_LIGHT_PHYS) " * x;\n" \
    "  vec4 den = sh * (1.0 + d2 * (1.0 / (" HOL__STR(HOL_LIGHT_D0_M) " * " HOL__STR(HOL_LIGHT_D0_M) ")));\n" \
    "#endif\n" \
    "  vec4 w = max(1.0 - d2 * (1.0 / (" HOL__STR(HOL_LIGHT_RADIUS_M) " * " HOL__STR(HOL_LIGHT_RADIUS_M) ")), 0.0);\n"

/* The trunk shadows of a tile (hol_light.h): up to four light-trunk pairs.
 * Per pair, three affine functions of the Klein point (hol_light_wedge)
 * interpolated exactly: times g, sinh of the signed distance to the two
 * geodesics from the light tangent to the trunk and to the one through
 * the trunk perpendicular to the light, over the soft edge's width 2 e, so
 * the occlusion is a linear ramp 2 e wide centred on the shadow's edge;
 * u_ts[9 + p] is pair p's light slot (one-hot), so the sum gathers each
 * light's occlusions; the light is multiplied by 1 - that (0 at least). */
#define HOL__SHADOW_GLSL \
    "#if HOL_SHD\n" \
    "vec4 hol_shadow(float g) {\n" \
    "  HOL_SV occ = clamp(min(min(v_S1, v_S2), v_S3) * g + 0.5, 0.0, 1.0);\n" \
    "#if HOL_SHD == 2\n" \
    "  return 1.0 - min(u_ts[9] * occ.x + u_ts[10] * occ.y, 1.0);\n" \
    "#else\n" \
    "  return 1.0 - min(u_ts[9] * occ.x + u_ts[10] * occ.y + u_ts[11] * occ.z +\n" \
    "                   u_ts[12] * occ.w, 1.0);\n" \
    "#endif\n" \
    "}\n" \
    "#else\n" \
    "vec4 hol_shadow(float g) {\n" \
    "  return vec4(1.0);\n" \
    "}\n" \
    "#endif\n"

static const char *hol__fs =
    "precision highp float;\n"
    "in vec3 v_nrm;\n"
    "in vec4 v_col;\n"
    "in vec3 v_wpos;\n"
    "uniform int u_mode;\n"
    "uniform vec4 u_id;\n"
    "uniform vec3 u_eye;\n"
    "uniform vec3 u_fog;\n"
    "uniform float u_fogd;\n"
    "uniform int u_lin;\n"
    "uniform vec4 u_wedge;\n"
    "uniform int u_wmode;\n"
    "#if HOL_LIT\n"
    /* lighting (hol_light.h): 1 a tile with its hyperbolic frame; 2 the
     * room's own meshes (no tile: ambient, fog by room distance) */
    "in vec3 v_loc;\n"
    "uniform int u_light;\n"
    "uniform int u_lonly;\n"
    "uniform float u_mpu2;\n"
    "uniform float u_eyeh;\n"
    "#if HOL_LIT == 1\n"
    "in vec4 v_L;\n"
    "in float v_Le;\n"
    "#if HOL_SHD\n"
    "in HOL_SV v_S1;\n"
    "in HOL_SV v_S2;\n"
    "in HOL_SV v_S3;\n"
    "uniform vec4 u_ts[13];\n"
    "#endif\n"
    "#if HOL_FX\n"
    "uniform vec4 u_tx[7];\n"
    "#endif\n"
    "#if HOL_FX == 2\n"
    "in vec4 v_U;\n"
    "#else\n"
    "const vec4 v_U = vec4(0.0);\n"
    "#endif\n"
    "#endif\n"
    /* the sky (docs/rendering.md#lighting): ambient, sun and lantern colours */
    "#if HOL_NIGHT\n"
    "const vec3 u_amb = vec3(0.07, 0.08, 0.13), u_sun = vec3(0.05, 0.06, 0.10);\n"
    "#else\n"
    "const vec3 u_amb = vec3(0.30, 0.26, 0.28), u_sun = vec3(0.28, 0.17, 0.11);\n"
    "#endif\n"
    "const vec3 u_lcol = vec3(3.0, 2.25, 1.25), u_fcol = vec3(1.4, 2.0, 0.6);\n"
    "#endif\n"
    "out vec4 o_col;\n"
    "vec4 hol_out(vec3 c) {\n"
    "  if (u_lin == 0) return vec4(c, 1.0);\n"
    "  c = clamp(c, 0.0, 1.0);\n"
    "  return vec4(mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)),\n"
    "                  step(vec3(0.04045), c)), 1.0);\n"
    "}\n"
    "#if HOL_LIT == 1\n"
    /* all four slots at once (an empty slot lies far beyond the radius).
     * k the fragment's Klein point; hyperbolic: g = 1/sqrt(1 - |k|^2) and
     * cosh x = g L, L = -<(k, 1), l>_L = l.z - k.l.xy, so the squared chord
     * c^2 = 2 (cosh x - 1) = 2 g L - 2, sinh x = sqrt(c^2 (1 + c^2/4)),
     * x = log(cosh x + sinh x); flat: the slot's z is |l|^2/2 and
     * c^2 = |k - l|^2 = 2 L + |k|^2, x = c */
    HOL__SHADOW_GLSL
    "#if HOL_FX\n"
    /* per slot: u_tx[4] the light's height, [5] a lantern's weight, [6] a
     * firefly's (the second sum, ff); a spot (u_tx[3] its sin(tilt), -2:
     * none) multiplies by its cone: cos(angle) = (x <u,t> + sin(tilt) dh)
     * / d, x <u,t> = x <u,p> / sinh x = g x U / sh (flat: U), metres per
     * unit folded into u (render/hol_light.h) */
    "float hol_lights(vec4 L, vec4 U, float g, float o, float y, float nup, out float ff) {\n"
    "  vec4 c2 = max(2.0 * g * L + o, 0.0);\n"
    "  vec4 dh = u_tx[4] - y;\n"
    HOL__FALLOFF_GLSL
    "  vec4 id = inversesqrt(max(d2, 1e-8));\n"
    "  vec4 f = w * w * num / den;\n"
    "  f *= hol_shadow(g);\n"
    /* the cone: only the programs of frames with a spot (HOL_FX 2) */
    "#if HOL_FX == 2\n"
    "  {\n"
    "#if HOL_FLAT\n"
    "    vec4 hz = U;\n"
    "#else\n"
    "    vec4 hz = g * x * U / sh;\n"
    "#endif\n"
    "    vec4 cone = smoothstep(vec4(" HOL__STR(HOL__SPOT_COS_O) "), vec4(" HOL__STR(HOL__SPOT_COS_I) "),\n"
    "                           (hz + u_tx[3] * dh) * id);\n"
    "    f *= mix(cone, vec4(1.0), step(u_tx[3], vec4(-1.5)));\n"
    "  }\n"
    "#endif\n"
    "  f *= 0.3 + (0.7 * max(nup, 0.0)) * max(dh, 0.0) * id;\n"
    "  ff = dot(f, u_tx[6]);\n"
    "  return dot(f, u_tx[5]);\n"
    "}\n"
    "#else\n"
    "float hol_lights(vec4 L, float g2, float o, float dh, float nup) {\n"
    "  vec4 c2 = max(g2 * L + o, 0.0);\n"
    HOL__FALLOFF_GLSL
    "  vec4 f = w * w * num / den * hol_shadow(0.5 * g2);\n"
    "  return dot(f, 0.3 + (0.7 * max(nup, 0.0) * max(dh, 0.0)) * inversesqrt(max(d2, 1e-8)));\n"
    "}\n"
    "#endif\n"
    "#endif\n"
    "void main() {\n"
    "#if HOL_WEDGE\n"
    "  if (u_wmode == 1) {\n"
    "    vec2 d = v_wpos.xz - u_eye.xz;\n"
    "    float e = -1e-4 * length(d);\n"
    "    if (u_wedge.x * d.y - u_wedge.y * d.x < e ||\n"
    "        d.x * u_wedge.w - d.y * u_wedge.z < e) discard;\n"
    "  }\n"
    "#endif\n"
    "  if (u_mode == 1) {\n"
    "    o_col = v_col.a > 0.5 ? u_id : vec4(0.0, 0.0, 0.0, 1.0);\n"
    "    return;\n"
    "  }\n"
    "  if (u_mode == 2) {\n"
    "    o_col = hol_out(v_col.rgb);\n"
    "    return;\n"
    "  }\n"
    "  vec3 toeye = u_eye - v_wpos;\n"
    "  vec3 n = v_nrm;\n"
    "  if (dot(n, n) < 1e-6) n = vec3(0.0, 1.0, 0.0);\n"
    "  n = normalize(n);\n"
    "  if (dot(n, toeye) < 0.0) n = -n;\n"
    "  float d = max(dot(n, normalize(vec3(0.35, 0.85, 0.40))), 0.0);\n"
    "#if HOL_LIT == 0\n"
    "  vec3 c = v_col.rgb * (0.50 + 0.60 * d);\n"
    "  float dist = length(toeye) * u_fogd;\n"
    "  float f = exp(-dist * dist);\n"
    "  o_col = hol_out(mix(u_fog, c, f));\n"
    "#else\n"
    "  float lam = 0.0, lamf = 0.0, de2 = dot(toeye, toeye);\n"
    "#if HOL_LIT == 1\n"
    "  if (u_light == 1) {\n"
    "    vec2 k = v_loc.xz;\n"
    "    float kk = dot(k, k);\n"
    "#if HOL_FLAT\n"
    "    float g = 1.0, o = kk;\n"
    "#else\n"
    "    float g = inversesqrt(max(1.0 - kk, 1e-6)), o = -2.0;\n"
    "#endif\n"
    "#if HOL_FX\n"
    "    lam = hol_lights(v_L, v_U, g, o, v_loc.y, n.y, lamf);\n"
    "#else\n"
    "    lam = hol_lights(v_L, 2.0 * g, o, " HOL__STR(HOL_LIGHT_HEIGHT_M) " - v_loc.y, n.y);\n"
    "#endif\n"
    /* fog: the chord 2 sinh(x/2) of the floor distance x (a function of
     * the true distance, within 4 % of it to 3 m; no log per pixel) */
    "    float ce2 = max(2.0 * g * v_Le + o, 0.0);\n"
    "    float dh = u_eyeh - v_loc.y;\n"
    "    de2 = ce2 * u_mpu2 + dh * dh;\n"
    "  }\n"
    "#endif\n"
    "  float f = exp(-de2 * (u_fogd * u_fogd));\n"
    "  if (u_lonly == 1) {\n"
    "    o_col = vec4(min(lam, 1.0), f, min(lamf, 1.0), 1.0);\n"
    "    return;\n"
    "  }\n"
    "  vec3 c = v_col.rgb * (u_amb + u_sun * d + u_lcol * lam + u_fcol * lamf);\n"
    "  if (abs(v_col.a - 100.0 / 255.0) < 0.01) c = v_col.rgb * 1.2;\n" /* glass */
    "  o_col = hol_out(mix(u_fog, c, f));\n"
    "#endif\n"
    "}\n";

static GLuint hol__shader(const hol_gl *gl, GLenum type, int n, const char *const *src)
{
    GLuint s = gl->CreateShader(type);
    gl->ShaderSource(s, n, src, NULL);
    gl->CompileShader(s);
    GLint ok = 0;
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl->DeleteShader(s);
        return 0;
    }
    return s;
}

/* Program k (struct hol_render's progs): the day shader (exactly the
 * picture before lights) or a lit one (dusk and night); 0 ok. */
static int hol__make_prog(hol_render *r, hol__prog *pg, int k)
{
    char pre[256];
    static const int lit[4] = {0, 1, 2, 1}, shd[3] = {4, 0, 2};
    static const char *const sv[5][2] = {{"float", ""}, {"float", ".x"}, {"vec2", ".xy"},
                                         {"float", ""}, {"vec4", ""}};
    int nsh = shd[k / 48];
    snprintf(pre, sizeof pre,
             "#version 300 es\n#define HOL_LIT %d\n#define HOL_FLAT %d\n#define HOL_WEDGE %d\n"
             "#define HOL_NIGHT %d\n#define HOL_FX %d\n#define HOL_SHD %d\n"
             "#define HOL_SV %s\n#define HOL_SW %s\n",
             lit[k % 4], k % 4 == 3, k % 8 >= 4, k % 16 >= 8, k % 48 / 16, nsh, sv[nsh][0],
             sv[nsh][1]);
    const char *fsrc[2] = {pre, hol__fs};
    const char *vsrc[2] = {fsrc[0], hol__vs};
    GLuint vs = hol__shader(&r->gl, GL_VERTEX_SHADER, 2, vsrc);
    GLuint fs = hol__shader(&r->gl, GL_FRAGMENT_SHADER, 2, fsrc);
    if (!vs || !fs) {
        if (vs)
            r->gl.DeleteShader(vs);
        if (fs)
            r->gl.DeleteShader(fs);
        return 1;
    }
    pg->prog = r->gl.CreateProgram();
    r->gl.AttachShader(pg->prog, vs);
    r->gl.AttachShader(pg->prog, fs);
    r->gl.LinkProgram(pg->prog);
    r->gl.DeleteShader(vs);
    r->gl.DeleteShader(fs);
    GLint ok = 0;
    r->gl.GetProgramiv(pg->prog, GL_LINK_STATUS, &ok);
    if (!ok) { /* none left half-made: a later frame or prepare tries again */
        r->gl.DeleteProgram(pg->prog);
        pg->prog = 0;
        return 1;
    }
    static const char *const names[] = {"u_vp", "u_model", "u_mode", "u_id", "u_eye",
                                        "u_fog", "u_fogd", "u_lin", "u_wedge", "u_wmode",
                                        "u_light", "u_klein", "u_mpu2", "u_tl", "u_eyeh",
                                        "u_lonly", "u_tx", "u_ts"};
    GLint *loc[] = {&pg->u_vp, &pg->u_model, &pg->u_mode, &pg->u_id, &pg->u_eye,
                    &pg->u_fog, &pg->u_fogd, &pg->u_lin, &pg->u_wedge, &pg->u_wmode,
                    &pg->u_light, &pg->u_klein, &pg->u_mpu2, &pg->u_tl, &pg->u_eyeh,
                    &pg->u_lonly, &pg->u_tx, &pg->u_ts};
    for (size_t i = 0; i < sizeof loc / sizeof loc[0]; i++)
        *loc[i] = r->gl.GetUniformLocation(pg->prog, names[i]);
    return 0;
}

/* The vertex layout of vao[k] (bound), read from vbo[k]. */
static void hol__vao_attribs(hol_render *r, int k)
{
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[k]);
    r->gl.EnableVertexAttribArray(0);
    r->gl.EnableVertexAttribArray(1);
    r->gl.EnableVertexAttribArray(2);
    r->gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, pos));
    r->gl.VertexAttribPointer(1, 3, GL_BYTE, GL_TRUE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, nrm));
    r->gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, rgba));
}

/* A new buffer of new_bytes for target (bound first to it: WebGL 2 fixes a
 * buffer's type at its first binding, and one first bound to a copy
 * target can never be an element array), old's first old_bytes copied in
 * (old 0: none), old deleted. Leaves target unbound. */
static GLuint hol__buffer_grown(hol_render *r, GLenum target, GLuint old, size_t old_bytes,
                                size_t new_bytes)
{
    GLuint b = 0;
    r->gl.GenBuffers(1, &b);
    r->gl.BindBuffer(target, b);
    r->gl.BufferData(target, (GLsizeiptr)new_bytes, NULL, GL_DYNAMIC_DRAW);
    if (old) {
        r->gl.BindBuffer(GL_COPY_READ_BUFFER, old);
        r->gl.CopyBufferSubData(GL_COPY_READ_BUFFER, target, 0, 0, (GLsizeiptr)old_bytes);
        r->gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
        r->gl.DeleteBuffers(1, &old);
    }
    r->gl.BindBuffer(target, 0);
    return b;
}

/* The static buffers (the room, the minimap, then the tile slots) made
 * for cap slots: new ones, what the old ones held copied in, vao[0]
 * pointed at them. Leaves no vertex array bound. */
static void hol__static_grow(hol_render *r, int cap)
{
    r->gl.BindVertexArray(0); /* the element binding below is vertex array 0's */
    r->vbo[0] = hol__buffer_grown(r, GL_ARRAY_BUFFER, r->vbo[0],
                                  HOL__SLOT_VBASE(r->slot_cap) * sizeof(hol_vertex),
                                  HOL__SLOT_VBASE(cap) * sizeof(hol_vertex));
    r->ibo[0] = hol__buffer_grown(r, GL_ELEMENT_ARRAY_BUFFER, r->ibo[0],
                                  HOL__SLOT_IBASE(r->slot_cap) * sizeof(uint32_t),
                                  HOL__SLOT_IBASE(cap) * sizeof(uint32_t));
    r->slot_cap = cap;
    r->gl.BindVertexArray(r->vao[0]);
    r->gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo[0]);
    hol__vao_attribs(r, 0);
    r->gl.BindVertexArray(0);
}

/* Whether program k is one of the renderer's: day has no night variant,
 * FX and the variants without shadows only the lit tiles'. */
static int hol__prog_exists(int k)
{
    if (k >= 48)
        return k % 2 && hol__prog_exists(k % 48);
    return k < 16 ? k % 4 || k < 8 : k % 2;
}

int hol_render_prepare(hol_render *r)
{
    int left = 0, made = 0;
    for (int k = 0; k < HOL__NPROG; k++) {
        if (!hol__prog_exists(k) || r->progs[k].prog)
            continue;
        if (!made) {
            made = 1;
            if (hol__make_prog(r, &r->progs[k], k))
                return -1;
            continue;
        }
        left++;
    }
    return left;
}

hol_err hol_render_create(const hol_render_desc *desc, hol_render **out)
{
    hol_render_desc d;
    memset(&d, 0, sizeof d);
    if (desc)
        d = *desc;
    hol_render *r = hol_alloc_mem(&d.alloc, sizeof *r);
    if (!r)
        return HOL_ENOMEM;
    memset(r, 0, sizeof *r);
    r->desc = d;
    /* the CPU-side stores: dynamic + scratch */
    r->verts = hol_alloc_mem(&d.alloc, (HOL__DYN_V + HOL__ROOM_V) * sizeof *r->verts);
    r->idx = hol_alloc_mem(&d.alloc, (HOL__DYN_I + HOL__ROOM_I) * sizeof *r->idx);
    if (!r->verts || !r->idx || hol_scene_create(&d.alloc, &r->scene)) {
        hol_alloc_release(&d.alloc, r->verts);
        hol_alloc_release(&d.alloc, r->idx);
        hol_alloc_release(&d.alloc, r);
        return HOL_ENOMEM;
    }
    hol_mesh_init(&r->dyn, r->verts, HOL__DYN_V, r->idx, HOL__DYN_I);
    hol_mesh_init(&r->scratch, r->verts + HOL__DYN_V, HOL__ROOM_V, r->idx + HOL__DYN_I,
                  HOL__ROOM_I);
    hol_err gerr = hol_gl_load(&r->gl, r->desc.getproc);
    if (gerr) {
        hol_alloc_release(&d.alloc, r->verts);
        hol_alloc_release(&d.alloc, r->idx);
        hol_scene_destroy(&d.alloc, r->scene);
        hol_alloc_release(&d.alloc, r);
        return gerr;
    }
    /* the day program now (it proves the GL compiles the shaders); the
     * others when a frame first uses one (hol__use_progs), or all now
     * (desc.all_programs), or by hol_render_prepare */
    int bad = hol__make_prog(r, &r->progs[0], 0);
    for (int k = 1; k < HOL__NPROG && d.all_programs; k++)
        if (hol__prog_exists(k))
            bad = bad || hol__make_prog(r, &r->progs[k], k);
    if (bad) {
        hol_render_destroy(r);
        return HOL_EUNSUPPORTED;
    }
    r->pg = &r->progs[0];
    r->gl.GenVertexArrays(2, r->vao);
    r->gl.GenBuffers(1, &r->vbo[1]);
    r->gl.GenBuffers(1, &r->ibo[1]);
    r->gl.BindVertexArray(r->vao[1]);
    r->gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo[1]);
    hol__vao_attribs(r, 1);
    hol__static_grow(r, d.all_programs ? HOL__SLOTS : HOL__SLOTS_FIRST);
    if (r->gl.GetError() != GL_NO_ERROR) {
        hol_render_destroy(r);
        return HOL_EUNSUPPORTED;
    }
    *out = r;
    return HOL_OK;
}

void hol_render_destroy(hol_render *r)
{
    if (!r)
        return;
    for (int k = 0; k < HOL__NPROG; k++)
        if (r->progs[k].prog)
            r->gl.DeleteProgram(r->progs[k].prog);
    if (r->vao[0])
        r->gl.DeleteVertexArrays(2, r->vao);
    if (r->vbo[0])
        r->gl.DeleteBuffers(2, r->vbo);
    if (r->ibo[0])
        r->gl.DeleteBuffers(2, r->ibo);
    hol_alloc d = r->desc.alloc;
    hol_scene_destroy(&d, r->scene);
    hol_alloc_release(&d, r->verts);
    hol_alloc_release(&d, r->idx);
    hol_alloc_release(&d, r);
}

void hol_render_set_world(hol_render *r, struct hol_world *world)
{
    r->desc.world = world;
    hol_render_invalidate(r);
}

void hol_render_invalidate(hol_render *r)
{
    for (int i = 0; i < HOL__SLOTS; i++)
        r->slots[i].used = 0;
    r->room_valid = 0;
    r->hud_valid = 0;
}

static uint64_t hol__fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

const hol_view *hol_render_last_view(const hol_render *r)
{
    return &r->view;
}

static void hol__identity(float m[16])
{
    memset(m, 0, 16 * sizeof(float));
    m[0] = m[5] = m[10] = m[15] = 1;
}

/* Column-major model matrix of a quad in the world: the square [-1, 1]^2
 * (z = 0) scaled to sx x sy (half sides, metres) and moved by (ox, oy) in
 * its own plane, turned by the quaternion q (all zero: identity), moved to
 * pos. */
static void hol__quad_matrix(const double pos[3], const double q[4], double sx, double sy,
                             double ox, double oy, float m[16])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (n < 1e-12) {
        x = y = z = 0;
        w = 1;
    } else {
        x /= n, y /= n, z /= n, w /= n;
    }
    double rot[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                     2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                     2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    hol__identity(m);
    for (int r = 0; r < 3; r++) {
        m[r] = (float)(rot[3 * r] * sx);
        m[4 + r] = (float)(rot[3 * r + 1] * sy);
        m[8 + r] = (float)rot[3 * r + 2];
        m[12 + r] = (float)(pos[r] + rot[3 * r] * ox + rot[3 * r + 1] * oy);
    }
}

/* The hand's minimap quad: hand_size a side, at hand_pos, hand_orient. */
static void hol__hand_matrix(const hol_frame_desc *f, float m[16])
{
    double half = (f->hand_size > 0 ? f->hand_size : 0.25) / 2;
    hol__quad_matrix(f->hand_pos, f->hand_orient, half, half, 0, 0, m);
}

static hol__item *hol__push(hol_render *r, int pass, uint32_t first, uint32_t count)
{
    if (r->nitems >= HOL__MAX_ITEMS || count == 0)
        return NULL;
    hol__item *it = &r->items[r->nitems++];
    memset(it, 0, sizeof *it);
    it->pass = (uint8_t)pass;
    it->first = first;
    it->count = count;
    it->branch = -1;
    hol__identity(it->model);
    return it;
}

/* Upload the scratch mesh to the static buffers at (vbase, ibase), its
 * indices shifted by vbase. */
static void hol__upload_scratch(hol_render *r, uint32_t vbase, uint32_t ibase)
{
    hol_mesh *m = &r->scratch;
    for (uint32_t i = 0; i < m->ni; i++)
        m->idx[i] += vbase;
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[0]);
    r->gl.BufferSubData(GL_ARRAY_BUFFER, (GLintptr)(vbase * sizeof(hol_vertex)),
                        (GLsizeiptr)(m->nv * sizeof(hol_vertex)), m->v);
    r->gl.BindVertexArray(r->vao[0]);
    r->gl.BufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)(ibase * sizeof(uint32_t)),
                        (GLsizeiptr)(m->ni * sizeof(uint32_t)), m->idx);
    r->gl.BindVertexArray(0);
    r->uploaded += (long)(m->nv * sizeof(hol_vertex) + m->ni * sizeof(uint32_t));
}

/* The resident mesh of tile t: reused while the tile's content is the
 * same, else (re)built into the least recently used slot. */
static int hol__tile_range(hol_render *r, hol_tile t, int bare, int pole, int kind,
                           double cell_m, uint32_t *first, uint32_t *count)
{
    hol_tile_content c;
    memset(&c, 0, sizeof c);
    int have = r->desc.world && hol_world_get(r->desc.world, t, &c) == HOL_OK;
    int free_slot = -1, lru = -1;
    for (int i = 0; i < HOL__SLOTS; i++) {
        hol__slot *sl = &r->slots[i];
        if (!sl->used) {
            if (free_slot < 0)
                free_slot = i;
            continue;
        }
        if (hol_tile_eq(sl->tile, t) && sl->bare == bare && sl->pole == pole && sl->kind == kind &&
            sl->have == have && sl->cell_m == cell_m &&
            (!have || !memcmp(&sl->content, &c, sizeof c))) {
            sl->last_frame = r->frame;
            *first = HOL__SLOT_IBASE(i);
            *count = sl->nidx;
            return 1;
        }
        if (sl->last_frame != r->frame &&
            (lru < 0 || sl->last_frame < r->slots[lru].last_frame))
            lru = i;
    }
    int k = free_slot >= 0 ? free_slot : lru;
    if (k < 0)
        return 0;
    hol_mesh_clear(&r->scratch);
    r->scratch.cap_v = HOL__SLOT_V;
    r->scratch.cap_i = HOL__SLOT_I;
    hol_scene_tile(r->scene, &r->scratch, t, r->desc.world, bare, pole, kind, cell_m);
    r->scratch.cap_v = HOL__ROOM_V;
    r->scratch.cap_i = HOL__ROOM_I;
    if (r->scratch.overflow)
        return 0;
    if (k >= r->slot_cap)
        hol__static_grow(r, k < HOL__SLOTS_MID ? HOL__SLOTS_MID : HOL__SLOTS);
    uint32_t vbase = HOL__SLOT_VBASE(k);
    uint32_t ibase = HOL__SLOT_IBASE(k);
    hol__upload_scratch(r, vbase, ibase);
    hol__slot *sl = &r->slots[k];
    sl->used = 1;
    sl->tile = t;
    sl->bare = bare;
    sl->pole = pole;
    sl->kind = kind;
    sl->have = have;
    sl->cell_m = cell_m;
    sl->content = c;
    sl->last_frame = r->frame;
    sl->nidx = r->scratch.ni;
    r->tiles_built++;
    *first = ibase;
    *count = sl->nidx;
    return 1;
}

static int hol__cmp_item(const void *a, const void *b)
{
    const hol__item *x = *(const hol__item *const *)a, *y = *(const hol__item *const *)b;
    return x->key < y->key ? -1 : x->key > y->key;
}

static double hol__now(clockid_t id)
{
    struct timespec ts = {0, 0}; /* stays zero where the clock is missing (wasm) */
    clock_gettime(id, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* glClearColor of an sRGB-authored colour: with desc.srgb the GL encodes
 * what is written, so the colour is given linear (as the shader does). */
static void hol__clear_colour(hol_render *r, float red, float green, float blue)
{
    float c[3] = {red, green, blue};
    for (int k = 0; k < 3 && r->desc.srgb; k++)
        c[k] = c[k] <= 0.04045f ? c[k] / 12.92f : powf((c[k] + 0.055f) / 1.055f, 2.4f);
    r->gl.ClearColor(c[0], c[1], c[2], 1);
}

static void hol__fade_rgb(const hol_frame_desc *f, uint8_t out[3])
{
    static const uint8_t def[3] = HOL_RENDER_FADE_RGB;
    int set = f->fade_rgb[0] || f->fade_rgb[1] || f->fade_rgb[2];
    memcpy(out, set ? f->fade_rgb : def, 3);
}

/* Pass 0 of the queue: one stencil polygon per leaf, in NDC. */
static hol_err hol__queue_leaves(hol_render *r, const hol_frame_desc *f)
{
    const hol_view *v = &r->view;
    for (int k = 0; k < v->nleaves; k++) {
        float xy[8][2];
        int n = hol_view_leaf_ndc(&f->cam, &v->leaves[k], xy);
        if (n < 3)
            continue;
        int64_t b = hol_mesh_reserve(&r->dyn, (uint32_t)n, (uint32_t)(3 * (n - 2)));
        if (b < 0)
            return HOL_ENOMEM;
        uint32_t i0 = r->dyn.ni;
        for (int i = 0; i < n; i++) {
            hol_vertex *vx = &r->dyn.v[r->dyn.nv++];
            memset(vx, 0, sizeof *vx);
            vx->pos[0] = xy[i][0];
            vx->pos[1] = xy[i][1];
        }
        for (int i = 1; i + 1 < n; i++) {
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b;
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b + (uint32_t)i;
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b + (uint32_t)i + 1;
        }
        hol__item *it = hol__push(r, HOL__PASS_STENCIL, i0, r->dyn.ni - i0);
        if (!it)
            return HOL_ENOMEM;
        it->dyn = 1;
        it->ref = v->leaves[k].code;
        it->mask = 0xff;
        it->key = (uint32_t)k;
    }
    return HOL_OK;
}

/* Pass 1: the room's own meshes, resident while the user's state and the
 * world stay the same. */
static hol_err hol__queue_room(hol_render *r, const hol_frame_desc *f, double cell_m)
{
    int tree[3] = {f->tree_marked != 0, f->tree_marked ? f->tree_vertex[0] : 0,
                   f->tree_marked ? f->tree_vertex[1] : 0};
    if (!r->room_valid || r->room_world != r->desc.world || r->room_cell != cell_m ||
        memcmp(&r->room_user, &f->user, sizeof f->user) || memcmp(r->room_tree, tree, sizeof tree)) {
        hol_mesh_clear(&r->scratch);
        hol_scene_room(r->scene, &r->scratch, &f->user, r->desc.world, cell_m);
        if (tree[0])
            hol_scene_tree_mark(r->scene, &r->scratch, tree[1], tree[2], cell_m);
        memcpy(r->room_tree, tree, sizeof tree);
        if (r->scratch.overflow)
            return HOL_ENOMEM;
        hol__upload_scratch(r, 0, 0);
        r->room_nidx = r->scratch.ni;
        r->room_user = f->user;
        r->room_cell = cell_m;
        r->room_world = r->desc.world;
        r->room_valid = 1;
    }
    hol__item *it = hol__push(r, HOL__PASS_ROOM, 0, r->room_nidx);
    if (it)
        it->key = 1u << 24;
    return HOL_OK;
}

/* The guide pole (objective index, or -1) and the game object kind on
 * tile t. */
static void hol__tile_marks(const hol_frame_desc *f, hol_tile t, int *pole, int *kind)
{
    *pole = -1;
    *kind = 0;
    for (int o = 0; o < f->nobjectives && o < HOL_RENDER_MAX_OBJECTIVES &&
                    !(f->flags & HOL_RENDER_NO_POLES); o++)
        if (hol_tile_eq(f->objectives[o], t)) {
            *pole = o;
            break;
        }
    for (int o = 0; o < f->nobjects && o < HOL_RENDER_MAX_OBJECTIVES; o++)
        if (hol_tile_eq(f->object_tiles[o], t)) {
            *kind = f->object_kinds[o];
            break;
        }
    for (int o = 0; f->lighting && o < f->nlanterns && o < HOL_RENDER_MAX_LANTERNS; o++)
        if (hol_tile_eq(f->lanterns[o], t)) {
            *kind |= HOL_SCENE_LANTERN; /* shown at dusk and night */
            break;
        }
}

/* A point of the user's frame in the tile's own frame (inv: the inverse of
 * the tile's frame), as the shader's slot takes it: x, y and z (hyperbolic)
 * or |p|^2/2 (flat, where z is 1). */
static void hol__tile_slot(const double inv[9], const double p[3], int flat, float out[3])
{
    double q[3];
    for (int i = 0; i < 3; i++)
        q[i] = inv[3 * i] * p[0] + inv[3 * i + 1] * p[1] + inv[3 * i + 2] * p[2];
    out[0] = (float)q[0];
    out[1] = (float)q[1];
    out[2] = (float)(flat ? (q[0] * q[0] + q[1] * q[1]) / 2 : q[2]);
}

/* A spot's tangent u at light point l (user frame) in the tile's own frame
 * (the vertex shader's U = u.xy k - u.z): u itself (its z the Lorentz
 * part) on the hyperboloid; flat, u.z = u.xy . l, so U = u . (k - l). */
static void hol__tile_tangent(const double inv[9], const double u[3], const double l[3],
                              int flat, float out[3])
{
    double a[3], b[3];
    for (int i = 0; i < 3; i++) {
        a[i] = inv[3 * i] * u[0] + inv[3 * i + 1] * u[1] + (flat ? 0 : inv[3 * i + 2] * u[2]);
        b[i] = inv[3 * i] * l[0] + inv[3 * i + 1] * l[1] + inv[3 * i + 2] * l[2];
    }
    out[0] = (float)a[0];
    out[1] = (float)a[1];
    out[2] = (float)(flat ? a[0] * b[0] + a[1] * b[1] : a[2]);
}

/* A lit tile's trunk shadow pairs (hol_light.h; the shader's hol_shadow),
 * u_ts: [3 j + i] coefficient i (k_x, k_y, 1) of half-plane j of each pair
 * (hol_light_wedge; an empty pair's are 0, 0, -1: no shadow); [9 + p]
 * pair p's light slot, one-hot. */
static void hol__item_shadows(const hol_light_frame *lf, hol__item *it, const double fr[9],
                              const double inv[9], const int idx[], int n)
{
    double lp[HOL_LIGHT_PER_TILE][3];
    for (int k = 0; k < n; k++) {
        const double *p = lf->pos[idx[k]];
        for (int i = 0; i < 3; i++)
            lp[k][i] = inv[3 * i] * p[0] + inv[3 * i + 1] * p[1] + inv[3 * i + 2] * p[2];
    }
    hol_shadow_set ss;
    hol_light_shadows(lf, fr, (const double(*)[3])lp, idx, n, &ss);
    memset(it->ts, 0, sizeof it->ts);
    it->nsh = (int8_t)ss.n;
    for (int m = 0; m < HOL_SHADOW_TRUNKS; m++) {
        if (m >= ss.n) {
            it->ts[2][m] = it->ts[5][m] = it->ts[8][m] = -1;
            continue;
        }
        double h[3][3];
        hol_light_wedge(lf, lp[ss.slot[m]], ss.trunk[m], h);
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                it->ts[3 * j + i][m] = (float)h[j][i];
        it->ts[9 + m][ss.slot[m]] = 1;
    }
}

/* A lit tile's lights and the eye in the tile's own frame (u_tl: the
 * lights' x, y, z as four-slot vectors, then the eye's point; an empty
 * slot lies far beyond the radius), so the shader needs no matrix. */
static void hol__item_lights(hol_render *r, hol__item *it, hol_tile t)
{
    double fr[9], inv[9];
    int idx[HOL_LIGHT_PER_TILE];
    int n = hol_light_tile(&r->lights, t, fr, idx);
    it->nl = (int8_t)n;
    it->nsh = 0;
    if (n < 0)
        return;
    /* the inverse of the frame: Lorentz J F^T J (flat: the rigid motion's) */
    int flat = r->lights.flat;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            inv[3 * i + j] = fr[3 * j + i] * (!flat && (i == 2) != (j == 2) ? -1 : 1);
    if (flat) {
        for (int i = 0; i < 2; i++)
            inv[3 * i + 2] = -(fr[i] * fr[2] + fr[3 + i] * fr[5]);
        inv[6] = inv[7] = 0;
        inv[8] = 1;
    }
    const hol_light_frame *lf = &r->lights;
    for (int k = 0; k < HOL_LIGHT_PER_TILE; k++) {
        float v[3] = {0, 0, 1e4f}, u[3] = {0, 0, 0};
        int i = k < n ? idx[k] : -1;
        if (i >= 0) {
            hol__tile_slot(inv, lf->pos[i], flat, v);
            hol__tile_tangent(inv, lf->sd[i], lf->pos[i], flat, u);
        }
        for (int j = 0; j < 3; j++) {
            it->tl[j][k] = v[j];
            it->tx[j][k] = u[j];
        }
        it->tx[3][k] = i >= 0 ? (float)lf->ssin[i] : -2.0f;
        it->tx[4][k] = i >= 0 ? (float)lf->h[i] : (float)HOL_LIGHT_HEIGHT_M;
        it->tx[5][k] = i >= 0 && !lf->ff[i] ? 1.0f : 0.0f;
        it->tx[6][k] = i >= 0 && lf->ff[i] ? (float)HOL_LIGHT_FF_WEIGHT : 0.0f;
    }
    hol__tile_slot(inv, r->lights.eye, flat, it->tl[3]);
    it->tl[3][3] = 0;
    hol__item_shadows(lf, it, fr, inv, idx, n);
}

/* A firefly's sprite (render/hol_light.h): when tile t has one of the
 * frame's fireflies, a small glowing blob at its place in the tile's own
 * frame, drawn like the tile's item (its stencil, wedge, matrix and
 * lights) from the dynamic buffer after every tile; nonzero: out of
 * room. */
static int hol__queue_firefly(hol_render *r, const hol__item *tile_it, hol_tile t)
{
    int i = hol_light_ff_of(&r->lights, t);
    if (i < 0)
        return 0;
    static const uint8_t glow[3] = {HOL_FF_SPRITE_RGB};
    const double *p = r->lights.ff_xzh[i];
    float c[3] = {(float)p[0], (float)p[2], (float)p[1]};
    uint32_t v0 = r->dyn.nv, i0 = r->dyn.ni;
    hol_mesh_blob(&r->dyn, c, HOL_FF_SPRITE_M, HOL_FF_SPRITE_M, HOL_FF_SPRITE_M, glow);
    if (r->dyn.overflow)
        return 1;
    for (uint32_t v = v0; v < r->dyn.nv; v++)
        r->dyn.v[v].rgba[3] = HOL_MESH_GLOW; /* unlit, as a lantern's glass */
    hol__item *it = hol__push(r, HOL__PASS_TILE, i0, r->dyn.ni - i0);
    if (!it)
        return 1;
    *it = *tile_it;
    it->first = i0;
    it->count = r->dyn.ni - i0;
    it->dyn = 1;
    it->key = 2u << 24 | 0xffu << 16 | (uint32_t)(uint16_t)tile_it->branch;
    return 0;
}

/* Pass 2: one draw per branch of its tile's resident mesh, placed in the
 * branch's cell, nearest cells first. */
static hol_err hol__queue_tiles(hol_render *r, const hol_frame_desc *f, int bare,
                                double cell_m)
{
    const hol_view *v = &r->view;
    for (int k = 0; k < v->nbranches; k++) {
        const hol_view_branch *br = &v->branches[k];
        if (br->err)
            continue;
        uint32_t first, count;
        int pole, kind;
        hol__tile_marks(f, br->state.tile, &pole, &kind);
        if (!hol__tile_range(r, br->state.tile, bare, pole, kind, cell_m, &first, &count))
            return HOL_ENOMEM;
        hol__item *it = hol__push(r, HOL__PASS_TILE, first, count);
        if (!it)
            return HOL_ENOMEM;
        it->ref = br->ref;
        it->mask = br->mask;
        it->branch = (int16_t)k;
        for (int j = 0; j < 2; j++) {
            it->wedge[j] = (float)br->w0[j];
            it->wedge[2 + j] = (float)br->w1[j];
        }
        it->key = 2u << 24 | (uint32_t)br->nsteps << 16 | (uint32_t)k;
        if (f->lighting)
            hol__item_lights(r, it, br->state.tile);
        /* tile frame -> room: the tile's heading is room north turned
         * clockwise by orient quarter turns */
        double a = -(double)br->state.orient * 1.5707963267948966;
        float c = (float)cos(a), s = (float)sin(a);
        c = fabsf(c) < 1e-6f ? 0.0f : c;
        s = fabsf(s) < 1e-6f ? 0.0f : s;
        /* x' = x c + z s, z' = -x s + z c (counter-clockwise by a) */
        float *m = it->model;
        m[0] = c;
        m[2] = -s;
        m[8] = s;
        m[10] = c;
        m[12] = (float)((br->state.col + 0.5) * cell_m);
        m[14] = (float)((br->state.row + 0.5) * cell_m);
        if (f->lighting && !bare && hol__queue_firefly(r, it, br->state.tile))
            return HOL_ENOMEM;
    }
    return HOL_OK;
}

/* The fade: one screen quad, blended by the constant alpha f->fade. */
static hol_err hol__queue_fade(hol_render *r, const hol_frame_desc *f)
{
    uint8_t rgb[3];
    hol__fade_rgb(f, rgb);
    int64_t b = hol_mesh_reserve(&r->dyn, 4, 6);
    if (b < 0)
        return HOL_ENOMEM;
    uint32_t i0 = r->dyn.ni;
    static const float q[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; i++) {
        hol_vertex *vx = &r->dyn.v[r->dyn.nv++];
        memset(vx, 0, sizeof *vx);
        vx->pos[0] = q[i][0];
        vx->pos[1] = q[i][1];
        memcpy(vx->rgba, rgb, 3);
        vx->rgba[3] = 255;
    }
    static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++)
        r->dyn.idx[r->dyn.ni++] = (uint32_t)b + tri[i];
    hol__item *it = hol__push(r, HOL__PASS_FADE, i0, 6);
    if (!it)
        return HOL_ENOMEM;
    it->key = (uint32_t)HOL__PASS_FADE << 24;
    it->dyn = 1;
    return HOL_OK;
}

/* What the resident minimap is a function of: the user's state, the
 * objectives, the path, the marks, where it is (hand or HUD) and the HUD's
 * size. */
static uint64_t hol__map_key(const hol_frame_desc *f, int hand)
{
    uint64_t key = 0xcbf29ce484222325ull;
    int nobj = f->nobjectives < 0 ? 0 : f->nobjectives > HOL_RENDER_MAX_OBJECTIVES
                                            ? HOL_RENDER_MAX_OBJECTIVES : f->nobjectives;
    key = hol__fnv(key, &f->user, sizeof f->user);
    key = hol__fnv(key, &nobj, sizeof nobj);
    key = hol__fnv(key, f->objectives, (size_t)nobj * sizeof f->objectives[0]);
    key = hol__fnv(key, &f->npath, sizeof f->npath);
    if (f->path && f->npath > 0)
        key = hol__fnv(key, f->path, (size_t)f->npath);
    key = hol__fnv(key, &hand, sizeof hand);
    int nm = f->nmarks < 0 ? 0 : f->nmarks > HOL_RENDER_MAX_MARKS ? HOL_RENDER_MAX_MARKS
                                                                  : f->nmarks;
    key = hol__fnv(key, &nm, sizeof nm);
    key = hol__fnv(key, f->marks, (size_t)nm * sizeof f->marks[0]);
    if (!hand) {
        key = hol__fnv(key, &f->cam.width, sizeof f->cam.width);
        key = hol__fnv(key, &f->cam.height, sizeof f->cam.height);
    }
    return key;
}

/* The minimap (on the HUD or in the hand; resident while its inputs stay
 * the same) and the live part: the user's arrow and the text. */
/* The headset's panel: the text block and, unless the map is in the hand,
 * the resident map (the hand's square layout) and the user's arrow beside
 * it, each a quad placed in the panel's plane (render/hol_hud.h). */
static hol_err hol__queue_panel(hol_render *r, const hol_frame_desc *f)
{
    if (f->flags & HOL_RENDER_PANEL_LAYER)
        return HOL_OK; /* the runtime shows it (hol_render_panel_image) */
    int map = (f->flags & HOL_RENDER_MINIMAP) && !(f->flags & HOL_RENDER_MINIMAP_HAND);
    double px = f->panel_px > 0 ? f->panel_px : HOL_RENDER_PANEL_PX;
    double wide = HOL_HUD_PANEL_W + (map ? HOL_HUD_PANEL_GAP + HOL_HUD_PANEL_MAP : 0);
    double left = -wide / 2, top = HOL_HUD_PANEL_MAP / 2;
    uint32_t i0 = r->dyn.ni;
    float wh[2];
    hol_hud_build_panel_text(&r->dyn, f, wh);
    hol__item *it = hol__push(r, HOL__PASS_PANEL, i0, r->dyn.ni - i0);
    if (it) {
        it->key = (uint32_t)HOL__PASS_PANEL << 24 | 2;
        it->dyn = 1;
        hol__quad_matrix(f->panel_pos, f->panel_orient, wh[0] / 2 * px, wh[1] / 2 * px,
                         (left + wh[0] / 2) * px, (top - wh[1] / 2) * px, it->model);
    }
    if (!map)
        return HOL_OK;
    float m[16];
    double half = HOL_HUD_PANEL_MAP / 2;
    hol__quad_matrix(f->panel_pos, f->panel_orient, half * px, half * px,
                     (left + HOL_HUD_PANEL_W + HOL_HUD_PANEL_GAP + half) * px, 0, m);
    hol__item *mi = hol__push(r, HOL__PASS_PANEL, HOL__HUD_IBASE, r->hud_nidx);
    if (mi) {
        mi->key = (uint32_t)HOL__PASS_PANEL << 24;
        memcpy(mi->model, m, sizeof m);
    }
    i0 = r->dyn.ni;
    hol_hud_build_hand_arrow(&r->dyn, f);
    hol__item *ai = hol__push(r, HOL__PASS_PANEL, i0, r->dyn.ni - i0);
    if (ai) {
        ai->key = (uint32_t)HOL__PASS_PANEL << 24 | 1;
        ai->dyn = 1;
        memcpy(ai->model, m, sizeof m);
    }
    return HOL_OK;
}

static hol_err hol__queue_hud(hol_render *r, const hol_frame_desc *f)
{
    int panel = (f->flags & HOL_RENDER_PANEL) != 0;
    /* the map's square layout: in the hand, or on the headset's panel */
    if (panel && !(f->flags & HOL_RENDER_MINIMAP))
        return hol__queue_panel(r, f); /* the text alone */
    int hand = (f->flags & HOL_RENDER_MINIMAP_HAND) != 0 || panel;
    uint64_t key = hol__map_key(f, hand);
    if (!r->hud_valid || r->hud_key != key) {
        hol_mesh_clear(&r->scratch);
        r->scratch.cap_v = HOL__HUD_V;
        r->scratch.cap_i = HOL__HUD_I;
        if (hand)
            hol_hud_build_hand_map(&r->scratch, f);
        else
            hol_hud_build_map(&r->scratch, f, f->cam.width, f->cam.height);
        r->scratch.cap_v = HOL__ROOM_V;
        r->scratch.cap_i = HOL__ROOM_I;
        if (r->scratch.overflow)
            return HOL_ENOMEM;
        hol__upload_scratch(r, HOL__HUD_VBASE, HOL__HUD_IBASE);
        r->hud_nidx = r->scratch.ni;
        r->hud_key = key;
        r->hud_valid = 1;
    }
    if (panel && !(f->flags & HOL_RENDER_MINIMAP_HAND))
        return hol__queue_panel(r, f);
    int map_pass = hand ? HOL__PASS_HAND : HOL__PASS_HUD;
    float hand_m[16];
    if (hand)
        hol__hand_matrix(f, hand_m);
    hol__item *map = hol__push(r, map_pass, HOL__HUD_IBASE, r->hud_nidx);
    if (map) {
        map->key = (uint32_t)map_pass << 24;
        if (hand)
            memcpy(map->model, hand_m, sizeof hand_m);
    }
    uint32_t i0 = r->dyn.ni;
    if (hand) {
        hol_hud_build_hand_arrow(&r->dyn, f);
        hol__item *it = hol__push(r, HOL__PASS_HAND, i0, r->dyn.ni - i0);
        if (it) {
            it->key = (uint32_t)HOL__PASS_HAND << 24 | 1;
            it->dyn = 1;
            memcpy(it->model, hand_m, sizeof hand_m);
        }
        if (panel) /* the map in the hand, the text on the panel */
            return hol__queue_panel(r, f);
        i0 = r->dyn.ni;
        hol_hud_build_text(&r->dyn, f, f->cam.width, f->cam.height);
    } else {
        hol_hud_build_live(&r->dyn, f, f->cam.width, f->cam.height);
    }
    hol__item *it = hol__push(r, HOL__PASS_HUD, i0, r->dyn.ni - i0);
    if (it) {
        it->key = (uint32_t)HOL__PASS_HUD << 24 | 1;
        it->dyn = 1;
    }
    return HOL_OK;
}

/* The HUD text alone (the minimap off). */
static hol_err hol__queue_text(hol_render *r, const hol_frame_desc *f)
{
    uint32_t i0 = r->dyn.ni;
    hol_hud_build_text(&r->dyn, f, f->cam.width, f->cam.height);
    hol__item *it = hol__push(r, HOL__PASS_HUD, i0, r->dyn.ni - i0);
    if (it) {
        it->key = (uint32_t)HOL__PASS_HUD << 24 | 1;
        it->dyn = 1;
    }
    return HOL_OK;
}

/* Build the queue of a frame: the view, then each pass's items. */
static hol_err hol__build(hol_render *r, const hol_frame_desc *f)
{
    int eu = (f->flags & HOL_RENDER_EUCLIDEAN) != 0;
    int bare = (f->flags & HOL_RENDER_BARE) != 0;
    double m = f->cell_m > 0 ? f->cell_m : 1.0;
    if (!(m >= 0.5 && m <= 1.5))
        return HOL_EARG;
    hol_err err = hol_view_build(&f->user, f->cam.eye[0] / m, f->cam.eye[2] / m, eu, &r->view);
    if (err)
        return err;
    if (f->lighting && (err = hol_light_prepare(f, r->desc.world, &r->lights)))
        return err;
    hol_mesh_clear(&r->dyn);
    r->nitems = 0;
    r->frame++;
    r->uploaded = 0;
    r->tiles_built = 0;
    if (!r->view.wedges && (err = hol__queue_leaves(r, f)))
        return err;
    if (!bare && (err = hol__queue_room(r, f, m)))
        return err;
    if ((err = hol__queue_tiles(r, f, bare, m)))
        return err;
    if (f->fade > 0 && !(f->flags & HOL_RENDER_IDS) && (err = hol__queue_fade(r, f)))
        return err;
    if (!(f->flags & HOL_RENDER_NO_HUD)) {
        if (f->flags & (HOL_RENDER_MINIMAP | HOL_RENDER_PANEL))
            err = hol__queue_hud(r, f);
        else if (f->flags & HOL_RENDER_HUD_TEXT)
            err = hol__queue_text(r, f);
        if (err)
            return err;
    }
    return r->dyn.overflow ? HOL_ENOMEM : HOL_OK;
}

/* The frame's rectangle: viewport, and the scissor its clear keeps to. */
static void hol__viewport(hol_render *r, const hol_frame_desc *f)
{
    r->gl.Viewport(f->vp_x, f->vp_y, f->cam.width, f->cam.height);
    r->gl.Enable(GL_SCISSOR_TEST);
    r->gl.Scissor(f->vp_x, f->vp_y, f->cam.width, f->cam.height);
}

/* Fully faded: the boundary colour alone, no view. */
static hol_err hol__frame_faded(hol_render *r, const hol_frame_desc *f)
{
    uint8_t rgb[3];
    hol__fade_rgb(f, rgb);
    hol__viewport(r, f);
    r->gl.DepthMask(GL_TRUE);
    r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    r->gl.StencilMask(0xff);
    hol__clear_colour(r, rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f);
    r->gl.ClearDepthf(1.0f);
    r->gl.ClearStencil(HOL_VIEW_STENCIL_CLEAR);
    r->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    r->gl.Disable(GL_SCISSOR_TEST);
    return r->desc.debug ? hol_render_check(r) : HOL_OK;
}

/* The sky of a frame's lighting (day: hol_scene_sky) and its fog density
 * per metre. */
static float hol__sky(const hol_frame_desc *f, float rgb[3])
{
    static const float skies[3][3] = {{0, 0, 0}, {0.46f, 0.36f, 0.44f}, {0.03f, 0.04f, 0.08f}};
    if (f->lighting == HOL_RENDER_DUSK || f->lighting == HOL_RENDER_NIGHT) {
        memcpy(rgb, skies[f->lighting], sizeof skies[0]);
        return f->lighting == HOL_RENDER_DUSK ? 0.10f : 0.15f;
    }
    hol_scene_sky(rgb);
    return 0.06f;
}

/* The per-frame uniforms of dusk and night (hol_light.h). */
static void hol__frame_lights(hol_render *r, const hol_frame_desc *f)
{
    const hol_light_frame *lf = &r->lights;
    r->gl.Uniform1i(r->pg->u_lonly, (f->flags & HOL_RENDER_LIGHT_ONLY) != 0);
    r->gl.Uniform1f(r->pg->u_klein, (float)lf->klein);
    r->gl.Uniform1f(r->pg->u_mpu2, (float)(lf->metres_per_unit * lf->metres_per_unit));
    r->gl.Uniform1f(r->pg->u_eyeh, (float)lf->eye_h);
}

/* This frame's program of a kind (0 day, 1 lit tiles with up to 4 trunk
 * shadow pairs, 2 lit room, 3, 4 lit tiles with none, up to two): the
 * lit tiles' hyperbolic or flat, with the wedge's discard when the view
 * has wedges. */
static hol__prog *hol__prog_of(hol_render *r, const hol_frame_desc *f, int kind)
{
    int var = kind >= 3 ? kind - 2 : 0;
    if (var)
        kind = 1;
    if (kind == 1 && r->lights.flat)
        kind = 3;
    if (kind && f->lighting == HOL_RENDER_NIGHT)
        kind += 8;
    if (kind % 2)
        kind += 16 * r->lights.fx;
    return &r->progs[kind + (r->view.wedges ? 4 : 0) + 48 * var];
}

/* Compile, if not yet, the programs of the kinds first..last (kinds as in
 * hol__prog_of, last <= first) this frame uses: a command that draws only
 * the day compiles 1 or 2 programs of the 78 (each costs llvmpipe about
 * 8 ms of CPU). HOL_EUNSUPPORTED if one does not compile. */
static hol_err hol__use_progs(hol_render *r, const hol_frame_desc *f, int first, int last)
{
    for (int k = first; k >= last; k--) {
        hol__prog *pg = hol__prog_of(r, f, k);
        if (!pg->prog && hol__make_prog(r, pg, (int)(pg - r->progs)))
            return HOL_EUNSUPPORTED;
    }
    return HOL_OK;
}

/* Clear the frame (sky, or black for IDs), upload this frame's dynamic
 * geometry, and set the program's per-frame uniforms; vp receives the
 * view-projection matrix. */
static void hol__frame_begin(hol_render *r, const hol_frame_desc *f, float vp[16])
{
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    float sky[3];
    float fogd = hol__sky(f, sky);
    hol__viewport(r, f);
    r->gl.Disable(GL_CULL_FACE);
    r->gl.Disable(GL_BLEND);
    r->gl.Disable(GL_DITHER);
    r->gl.DepthMask(GL_TRUE);
    r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    r->gl.StencilMask(0xff);
    if (ids)
        r->gl.ClearColor(0, 0, 0, 1);
    else
        hol__clear_colour(r, sky[0], sky[1], sky[2]);
    r->gl.ClearDepthf(1.0f);
    r->gl.ClearStencil(HOL_VIEW_STENCIL_CLEAR);
    r->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    r->gl.BindVertexArray(r->vao[1]);
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[1]);
    r->gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(r->dyn.nv * sizeof(hol_vertex)), r->dyn.v,
                     GL_STREAM_DRAW);
    r->gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(r->dyn.ni * sizeof(uint32_t)),
                     r->dyn.idx, GL_STREAM_DRAW);
    r->uploaded += (long)(r->dyn.nv * sizeof(hol_vertex) + r->dyn.ni * sizeof(uint32_t));
    float view[16], proj[16];
    hol_camera_matrices(&f->cam, view, proj);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0;
            for (int k = 0; k < 4; k++)
                s += proj[4 * k + j] * view[4 * i + k];
            vp[4 * i + j] = s;
        }
    /* the per-frame uniforms of every program the frame uses: day's, or
     * at dusk and night the room's then the tiles' (current at the end) */
    int first = f->lighting ? 4 : 0, last = f->lighting ? 1 : 0;
    for (int k = first; k >= last; k--) {
        r->pg = hol__prog_of(r, f, k);
        r->gl.UseProgram(r->pg->prog);
        r->gl.Uniform3f(r->pg->u_eye, (float)f->cam.eye[0], (float)f->cam.eye[1],
                        (float)f->cam.eye[2]);
        r->gl.Uniform3f(r->pg->u_fog, sky[0], sky[1], sky[2]);
        r->gl.Uniform1f(r->pg->u_fogd, fogd);
        r->gl.Uniform1i(r->pg->u_lin, r->desc.srgb != 0);
        r->gl.Uniform1i(r->pg->u_wmode, 0);
        r->gl.Uniform1i(r->pg->u_light, k == 2 ? 2 : 0);
        if (f->lighting)
            hol__frame_lights(r, f);
    }
}

/* The GL state of a pass (vp: the view-projection, for the passes in the
 * world). */
static void hol__set_pass_as(hol_render *r, const hol_frame_desc *f, int pass, const float vp[16],
                             hol__prog *want)
{
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    float ident[16];
    hol__identity(ident);
    if (want) { /* the room's meshes: the program without tile code */
        if (want != r->pg) {
            r->pg = want;
            r->gl.UseProgram(want->prog);
        }
    }
    r->gl.Uniform1i(r->pg->u_wmode, 0); /* the tile pass sets it per branch */
    switch (pass) {
    case HOL__PASS_STENCIL:
        r->gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        r->gl.Disable(GL_DEPTH_TEST);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Enable(GL_STENCIL_TEST);
        r->gl.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, ident);
        r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        break;
    case HOL__PASS_ROOM:
    case HOL__PASS_TILE:
        r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        r->gl.Enable(GL_DEPTH_TEST);
        r->gl.DepthFunc(GL_LESS);
        r->gl.DepthMask(GL_TRUE);
        r->gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        if (pass == HOL__PASS_ROOM)
            r->gl.Disable(GL_STENCIL_TEST);
        else
            r->gl.Enable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_LIT);
        r->gl.Uniform4f(r->pg->u_id, 0, 0, 0, 1);
        if (pass == HOL__PASS_ROOM)
            r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        if (f->lighting) /* the tile pass sets it per tile */
            r->gl.Uniform1i(r->pg->u_light, 2);
        break;
    case HOL__PASS_HAND:
        /* in the world: hidden where the scene is nearer; its coplanar
         * layers are painted in order (no depth writes) */
        r->gl.Enable(GL_DEPTH_TEST);
        r->gl.DepthFunc(GL_LEQUAL);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Disable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        break;
    case HOL__PASS_PANEL:
        /* in the world, drawn last over everything (no depth test): the
         * text is never hidden by a hedge or a trunk nearer than it */
        r->gl.Disable(GL_BLEND);
        r->gl.Disable(GL_DEPTH_TEST);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Disable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        break;
    case HOL__PASS_FADE:
        r->gl.Disable(GL_DEPTH_TEST);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Disable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, ident);
        r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        r->gl.Uniform1i(r->pg->u_mode, HOL__MODE_FLAT);
        r->gl.Enable(GL_BLEND);
        r->gl.BlendColor(0, 0, 0, (float)f->fade);
        r->gl.BlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
        break;
    default:
        r->gl.Disable(GL_BLEND);
        r->gl.Disable(GL_DEPTH_TEST);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Disable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, ident);
        r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        break;
    }
}

/* The GL state of a pass: at dusk and night the room's meshes take the
 * program without tile code, and the tile pass's state goes to both tile
 * programs (with trunk shadows, current at the end, and without). */
static void hol__set_pass(hol_render *r, const hol_frame_desc *f, int pass, const float vp[16])
{
    for (int k = 3; k <= 4 && f->lighting && pass == HOL__PASS_TILE; k++)
        hol__set_pass_as(r, f, pass, vp, hol__prog_of(r, f, k));
    hol__set_pass_as(r, f, pass, vp,
                     f->lighting ? hol__prog_of(r, f, pass == HOL__PASS_ROOM ? 2 : 1) : NULL);
}

/* A lit tile's frame and lights (a tile without a frame: as the room). */
static void hol__item_uniforms(hol_render *r, const hol__item *it)
{
    r->gl.Uniform1i(r->pg->u_light, it->nl < 0 ? 2 : 1);
    if (it->nl < 0)
        return;
    r->gl.Uniform4fv(r->pg->u_tl, 4, &it->tl[0][0]);
    r->gl.Uniform4fv(r->pg->u_tx, 7, &it->tx[0][0]);
    if (it->nsh) /* the variant for two reads the first two of each */
        r->gl.Uniform4fv(r->pg->u_ts, 13, &it->ts[0][0]);
}

/* Execute the sorted queue, skipping redundant state changes. */
static void hol__execute(hol_render *r, const hol_frame_desc *f, const float vp[16],
                         hol_render_stats *st)
{
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    int cur_vao = 1, cur_pass = -1, cur_ref = -1, cur_mask = -1;
    for (int i = 0; i < r->nitems; i++) {
        const hol__item *it = r->sorted[i];
        if (it->pass != cur_pass) {
            cur_pass = it->pass;
            cur_ref = cur_mask = -1;
            st->state_changes++;
            hol__set_pass(r, f, cur_pass, vp);
        }
        if (cur_pass == HOL__PASS_STENCIL) {
            r->gl.StencilFunc(GL_ALWAYS, it->ref, 0xff);
            st->state_changes++;
            st->stencil_passes++;
        } else if (cur_pass == HOL__PASS_TILE) {
            if (it->ref != cur_ref || it->mask != cur_mask) {
                r->gl.StencilFunc(GL_EQUAL, it->ref, it->mask);
                cur_ref = it->ref;
                cur_mask = it->mask;
                st->state_changes++;
            }
            if (f->lighting) { /* a tile with no shadow pair: the program without */
                int nsh = it->nl >= 0 ? it->nsh : 0;
                hol__prog *want = hol__prog_of(r, f, nsh > 2 ? 1 : nsh ? 4 : 3);
                if (want != r->pg) {
                    r->pg = want;
                    r->gl.UseProgram(want->prog);
                    st->state_changes++;
                }
            }
            r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, it->model);
            if (f->lighting)
                hol__item_uniforms(r, it);
            if (r->view.wedges) {
                r->gl.Uniform1i(r->pg->u_wmode, it->branch > 0);
                r->gl.Uniform4f(r->pg->u_wedge, it->wedge[0], it->wedge[1], it->wedge[2],
                                it->wedge[3]);
            }
            if (ids) {
                int id = it->branch + 1;
                r->gl.Uniform4f(r->pg->u_id, (float)(id & 255) / 255.0f, (float)(id >> 8) / 255.0f,
                                0, 1);
            }
            st->branches += !it->dyn; /* a firefly's sprite is no branch */
        } else if (cur_pass == HOL__PASS_HAND || cur_pass == HOL__PASS_PANEL) {
            r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, it->model);
        }
        if (it->dyn != cur_vao) {
            cur_vao = it->dyn;
            r->gl.BindVertexArray(r->vao[cur_vao]);
            st->state_changes++;
        }
        r->gl.DrawElements(GL_TRIANGLES, (GLsizei)it->count, GL_UNSIGNED_INT,
                           (const void *)(uintptr_t)(it->first * sizeof(uint32_t)));
        st->draw_calls++;
        st->triangles += it->count / 3;
    }
}

hol_err hol_render_frame(hol_render *r, const hol_frame_desc *f,
                         hol_render_stats *out_stats)
{
    double c0 = hol__now(CLOCK_PROCESS_CPUTIME_ID), w0 = hol__now(CLOCK_MONOTONIC);
    int maxw = r->desc.max_width > 0 ? r->desc.max_width : 4096;
    int maxh = r->desc.max_height > 0 ? r->desc.max_height : 4096;
    if (f->cam.width <= 0 || f->cam.height <= 0 || f->cam.width > maxw ||
        f->cam.height > maxh)
        return HOL_EARG;
    hol_render_stats st;
    memset(&st, 0, sizeof st);
    if (f->fade >= 1 && !(f->flags & HOL_RENDER_IDS)) {
        hol_err err = hol__frame_faded(r, f);
        if (f->flags & HOL_RENDER_WAIT)
            r->gl.Finish();
        st.cpu_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
        st.wall_ms = hol__now(CLOCK_MONOTONIC) - w0;
        if (out_stats)
            *out_stats = st;
        return err;
    }
    hol_err err = hol__build(r, f);
    if (!err)
        err = f->lighting ? hol__use_progs(r, f, 4, 1) : hol__use_progs(r, f, 0, 0);
    if (err)
        return err;
    for (int i = 0; i < r->nitems; i++)
        r->sorted[i] = &r->items[i];
    qsort(r->sorted, (size_t)r->nitems, sizeof r->sorted[0], hol__cmp_item);
    st.build_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    float vp[16];
    hol__frame_begin(r, f, vp);
    st.state_changes += 2;
    hol__execute(r, f, vp, &st);
    r->gl.Disable(GL_BLEND);
    r->gl.BindVertexArray(0);
    r->gl.Disable(GL_SCISSOR_TEST);
    if (f->flags & HOL_RENDER_WAIT)
        r->gl.Finish(); /* the figures include the GPU's time */
    st.cpu_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    st.uploaded_bytes = r->uploaded;
    st.tiles_built = r->tiles_built;
    st.wall_ms = hol__now(CLOCK_MONOTONIC) - w0;
    if (r->desc.debug && hol_render_check(r))
        return HOL_EUNSUPPORTED;
    if (out_stats)
        *out_stats = st;
    return HOL_OK;
}

/* The panel alone (hol_render_panel_key, _image): g is f with the panel
 * at the origin, unturned, the map beside the text or none (a map in the
 * hand is not the panel's), queued into the dynamic mesh. */
static hol_err hol__queue_panel_only(hol_render *r, const hol_frame_desc *f, hol_frame_desc *g)
{
    *g = *f;
    uint32_t keep = HOL_RENDER_MINIMAP | HOL_RENDER_NO_HOT_COLD | HOL_RENDER_NO_ARROW;
    g->flags = (f->flags & keep) | HOL_RENDER_PANEL;
    if (f->flags & HOL_RENDER_MINIMAP_HAND)
        g->flags &= ~(uint32_t)HOL_RENDER_MINIMAP;
    memset(g->panel_pos, 0, sizeof g->panel_pos);
    static const double unturned[4] = {0, 0, 0, 1};
    memcpy(g->panel_orient, unturned, sizeof unturned);
    g->lighting = 0;
    g->fade = 0;
    hol_mesh_clear(&r->dyn);
    r->nitems = 0;
    hol_err err = hol__queue_hud(r, g);
    return err ? err : r->dyn.overflow ? HOL_ENOMEM : HOL_OK;
}

uint64_t hol_render_panel_key(hol_render *r, const hol_frame_desc *f)
{
    hol_frame_desc g;
    uint64_t key = 0xcbf29ce484222325ull;
    if (hol__queue_panel_only(r, f, &g))
        return key; /* an overflow draws nothing: never equal to a drawn key */
    key = hol__fnv(key, &g.flags, sizeof g.flags);
    key = hol__fnv(key, &g.panel_px, sizeof g.panel_px);
    key = hol__fnv(key, r->dyn.v, r->dyn.nv * sizeof r->dyn.v[0]);
    key = hol__fnv(key, r->dyn.idx, r->dyn.ni * sizeof r->dyn.idx[0]);
    for (int i = 0; i < r->nitems; i++) {
        key = hol__fnv(key, r->items[i].model, sizeof r->items[i].model);
        key = hol__fnv(key, &r->items[i].count, sizeof r->items[i].count);
    }
    if (g.flags & HOL_RENDER_MINIMAP)
        key = hol__fnv(key, &r->hud_key, sizeof r->hud_key);
    return key ^ 1; /* never the overflow's */
}

hol_err hol_render_panel_image(hol_render *r, const hol_frame_desc *f, int w, int h)
{
    int maxw = r->desc.max_width > 0 ? r->desc.max_width : 4096;
    int maxh = r->desc.max_height > 0 ? r->desc.max_height : 4096;
    if (w <= 0 || h <= 0 || w > maxw || h > maxh)
        return HOL_EARG;
    hol_frame_desc g;
    hol_err err = hol__queue_panel_only(r, f, &g);
    if (!err)
        err = hol__use_progs(r, &g, 0, 0);
    if (err)
        return err;
    for (int i = 0; i < r->nitems; i++)
        r->sorted[i] = &r->items[i];
    qsort(r->sorted, (size_t)r->nitems, sizeof r->sorted[0], hol__cmp_item);
    g.cam.width = w;
    g.cam.height = h;
    g.vp_x = g.vp_y = 0;
    float vp[16];
    hol__frame_begin(r, &g, vp); /* uploads the text; clears to the sky */
    r->gl.ClearColor(0, 0, 0, 0);
    r->gl.Clear(GL_COLOR_BUFFER_BIT);
    /* the box (panel plane, metres) onto the whole image */
    double box[4];
    hol_hud_panel_box((g.flags & HOL_RENDER_MINIMAP) != 0, g.panel_px, box);
    memset(vp, 0, sizeof vp);
    vp[0] = (float)(2 / box[0]);
    vp[5] = (float)(2 / box[1]);
    vp[10] = 1;
    vp[12] = (float)(-2 * box[2] / box[0]);
    vp[13] = (float)(-2 * box[3] / box[1]);
    vp[15] = 1;
    hol_render_stats st;
    memset(&st, 0, sizeof st);
    hol__execute(r, &g, vp, &st);
    r->gl.Disable(GL_BLEND);
    r->gl.BindVertexArray(0);
    r->gl.Disable(GL_SCISSOR_TEST);
    return r->desc.debug ? hol_render_check(r) : HOL_OK;
}

hol_err hol_render_check(hol_render *r)
{
    int bad = 0;
    /* every error flag the GL holds (at most a few: one per kind) */
    for (int i = 0; i < 8 && r->gl.GetError() != GL_NO_ERROR; i++)
        bad = 1;
    return bad ? HOL_EUNSUPPORTED : HOL_OK;
}

void hol_render_read_rgba(hol_render *r, int w, int h, uint8_t *out_rgba)
{
    r->gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    r->gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out_rgba);
    size_t row = (size_t)w * 4;
    uint8_t tmp[4 * 1024];
    for (int y = 0; y < h / 2; y++) {
        uint8_t *a = out_rgba + (size_t)y * row, *b = out_rgba + (size_t)(h - 1 - y) * row;
        for (size_t o = 0; o < row; o += sizeof tmp) {
            size_t n = row - o < sizeof tmp ? row - o : sizeof tmp;
            memcpy(tmp, a + o, n);
            memcpy(a + o, b + o, n);
            memcpy(b + o, tmp, n);
        }
    }
}

int hol_render_decode_id(const uint8_t rgba[4])
{
    return (int)rgba[0] + 256 * (int)rgba[1] - 1;
}
