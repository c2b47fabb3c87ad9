/* hol_scene.c - procedural low-poly meshes for the forest. */
#include "hol_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_world.h"

#define HOL__TPL_V 2048
#define HOL__TPL_I 4096
#define HOL__PI_2 1.5707963267948966f
#define HOL__PROPS_MAX 64 /* a tile's small props: at most 48 tufts */

enum {
    HOL__T_PINE, HOL__T_BIRCH, HOL__T_OAK, HOL__T_MAPLE, /* = hol_tree_kind */
    HOL__T_TUFT, HOL__T_FLOWER, HOL__T_ROCK, HOL__T_MUSHROOM, HOL__T_LOG,
    HOL__T_FLAG, HOL__T_KEY, HOL__T_CHEST, HOL__T_CHEST_OPEN, HOL__T_POLE,
    HOL__T_MARKER, HOL__T_TREE_MARK, HOL__T_COUNT
};

struct hol_scene {
    hol_mesh tpl[HOL__T_COUNT];
    hol_vertex v[HOL__T_COUNT][HOL__TPL_V];
    uint32_t i[HOL__T_COUNT][HOL__TPL_I];
};

static const uint8_t hol__trunk[3] = {104, 74, 50};
static const uint8_t hol__hedge[3] = {56, 118, 60};
static const uint8_t hol__white[3] = {255, 255, 255};
/* the tutorial's marks: violet, a colour no prop, flag or pole has */
static const uint8_t hol__mark[3] = {150, 90, 255};
static const uint8_t hol__mark_dark[3] = {96, 58, 170};

/* A ring of 16 flat blocks of radius r on the ground. */
static void hol__ring(hol_mesh *m, float r)
{
    hol_vertex tv[64];
    uint32_t ti[128];
    hol_mesh tmp;
    hol_mesh_init(&tmp, tv, 64, ti, 128);
    float half = r * 0.21f; /* a little over pi r / 16: the blocks meet */
    hol_mesh_box(&tmp, (const float[3]){-half, 0.005f, r - 0.03f},
                 (const float[3]){half, 0.045f, r + 0.03f}, hol__mark);
    for (int k = 0; k < 16; k++)
        hol_mesh_append(m, &tmp, (hol_place){0, 0, 0, (float)k * 0.3926991f, 1});
}

/* Vertices from v0 on glow (drawn unlit, bright). */
static void hol__glow(hol_mesh *m, uint32_t v0)
{
    for (uint32_t i = v0; i < m->nv; i++)
        m->v[i].rgba[3] = HOL_MESH_GLOW;
}

/* The lesson's marker (a glowing ring, a violet post and a glowing orb:
 * no cloth, nothing red) and the marked tree's bands and ring. */
static void hol__build_marks(hol_scene *s)
{
    hol_mesh *m = &s->tpl[HOL__T_MARKER];
    hol__ring(m, 0.32f);
    hol__glow(m, 0);
    hol_mesh_frustum(m, 6, 0.035f, 0.0f, 0.025f, 1.0f, hol__mark_dark);
    uint32_t g = m->nv;
    hol_mesh_blob(m, (const float[3]){0, 1.1f, 0}, 0.11f, 0.11f, 0.11f, hol__mark);
    hol__glow(m, g);
    m = &s->tpl[HOL__T_TREE_MARK];
    hol__ring(m, 0.30f);
    hol_mesh_frustum(m, 8, 0.125f, 1.00f, 0.125f, 1.16f, hol__mark);
    hol_mesh_frustum(m, 8, 0.12f, 1.36f, 0.12f, 1.52f, hol__mark);
    hol__glow(m, 0);
}

void hol_scene_sky(float out_rgb[3])
{
    out_rgb[0] = 0.70f;
    out_rgb[1] = 0.82f;
    out_rgb[2] = 0.93f;
}

static void hol__build_templates(hol_scene *s)
{
    hol_mesh *m;
    /* trees: trunks 3.2 m, taller than any standing eye, so the seam behind
     * each vertex stays hidden; crowns start above 2.2 m */
    m = &s->tpl[HOL__T_PINE];
    hol_mesh_frustum(m, 8, 0.09f, 0.0f, 0.07f, 3.2f, hol__trunk);
    hol_mesh_frustum(m, 8, 0.80f, 2.2f, 0.0f, 3.9f, (const uint8_t[3]){34, 92, 52});
    hol_mesh_frustum(m, 8, 0.60f, 3.2f, 0.0f, 4.6f, (const uint8_t[3]){40, 104, 58});
    hol_mesh_frustum(m, 8, 0.40f, 4.1f, 0.0f, 5.2f, (const uint8_t[3]){46, 116, 64});
    m = &s->tpl[HOL__T_BIRCH];
    hol_mesh_frustum(m, 8, 0.085f, 0.0f, 0.07f, 3.6f, (const uint8_t[3]){225, 222, 210});
    hol_mesh_blob(m, (const float[3]){0, 3.6f, 0}, 0.75f, 1.1f, 0.75f,
                  (const uint8_t[3]){120, 170, 70});
    m = &s->tpl[HOL__T_OAK];
    hol_mesh_frustum(m, 8, 0.11f, 0.0f, 0.08f, 3.2f, hol__trunk);
    hol_mesh_blob(m, (const float[3]){0, 3.5f, 0}, 1.1f, 0.9f, 1.1f,
                  (const uint8_t[3]){60, 120, 50});
    hol_mesh_blob(m, (const float[3]){0.3f, 4.1f, 0.2f}, 0.7f, 0.6f, 0.7f,
                  (const uint8_t[3]){70, 135, 56});
    m = &s->tpl[HOL__T_MAPLE];
    hol_mesh_frustum(m, 8, 0.10f, 0.0f, 0.075f, 3.2f, hol__trunk);
    hol_mesh_blob(m, (const float[3]){0, 3.6f, 0}, 0.95f, 1.0f, 0.95f,
                  (const uint8_t[3]){200, 90, 40});
    /* a grass tuft: three thin blades */
    m = &s->tpl[HOL__T_TUFT];
    for (int k = 0; k < 3; k++) {
        hol_mesh tmp;
        hol_vertex tv[64];
        uint32_t ti[128];
        hol_mesh_init(&tmp, tv, 64, ti, 128);
        hol_mesh_frustum(&tmp, 3, 0.012f, 0.0f, 0.0f, 0.14f + 0.03f * k,
                         (const uint8_t[3]){70, 150, 60});
        hol_place p = {0.02f * (k - 1), 0, 0.015f * (k % 2), 1.1f * k, 1};
        hol_mesh_append(m, &tmp, p);
    }
    m = &s->tpl[HOL__T_FLOWER]; /* white petals: tinted per flower */
    hol_mesh_frustum(m, 3, 0.008f, 0.0f, 0.006f, 0.22f, (const uint8_t[3]){60, 130, 50});
    hol_mesh_blob(m, (const float[3]){0, 0.23f, 0}, 0.045f, 0.03f, 0.045f, hol__white);
    m = &s->tpl[HOL__T_ROCK];
    hol_mesh_blob(m, (const float[3]){0, 0.06f, 0}, 0.20f, 0.16f, 0.15f,
                  (const uint8_t[3]){130, 130, 125});
    hol_mesh_blob(m, (const float[3]){0.14f, 0.03f, 0.08f}, 0.10f, 0.08f, 0.09f,
                  (const uint8_t[3]){115, 115, 112});
    m = &s->tpl[HOL__T_MUSHROOM];
    hol_mesh_frustum(m, 6, 0.025f, 0.0f, 0.02f, 0.10f, (const uint8_t[3]){235, 230, 215});
    hol_mesh_frustum(m, 8, 0.08f, 0.09f, 0.0f, 0.16f, (const uint8_t[3]){200, 40, 35});
    /* half a log, lying from the tile centre to its partner edge (-z):
     * the two halves meet on the shared edge */
    m = &s->tpl[HOL__T_LOG];
    hol_mesh_box(m, (const float[3]){-0.13f, 0.0f, -0.5f}, (const float[3]){0.13f, 0.24f, 0.05f},
                 (const uint8_t[3]){120, 84, 52});
    hol_mesh_box(m, (const float[3]){-0.10f, 0.02f, 0.05f}, (const float[3]){0.10f, 0.22f, 0.07f},
                 (const uint8_t[3]){196, 160, 110});
    m = &s->tpl[HOL__T_FLAG];
    hol_mesh_frustum(m, 6, 0.02f, 0.0f, 0.02f, 1.4f, (const uint8_t[3]){220, 220, 220});
    hol_mesh_box(m, (const float[3]){0.02f, 1.05f, -0.01f}, (const float[3]){0.40f, 1.35f, 0.01f},
                 (const uint8_t[3]){220, 30, 30});
    m = &s->tpl[HOL__T_KEY];
    hol_mesh_blob(m, (const float[3]){0, 0.45f, 0}, 0.08f, 0.08f, 0.03f,
                  (const uint8_t[3]){240, 200, 40});
    hol_mesh_box(m, (const float[3]){-0.015f, 0.15f, -0.015f}, (const float[3]){0.015f, 0.40f, 0.015f},
                 (const uint8_t[3]){240, 200, 40});
    hol_mesh_box(m, (const float[3]){0.015f, 0.17f, -0.012f}, (const float[3]){0.07f, 0.21f, 0.012f},
                 (const uint8_t[3]){240, 200, 40});
    hol_mesh_frustum(m, 8, 0.12f, 0.0f, 0.10f, 0.15f, (const uint8_t[3]){150, 150, 150});
    m = &s->tpl[HOL__T_CHEST];
    hol_mesh_box(m, (const float[3]){-0.25f, 0, -0.17f}, (const float[3]){0.25f, 0.28f, 0.17f},
                 (const uint8_t[3]){130, 80, 40});
    hol_mesh_box(m, (const float[3]){-0.26f, 0.28f, -0.18f}, (const float[3]){0.26f, 0.38f, 0.18f},
                 (const uint8_t[3]){150, 95, 45});
    hol_mesh_box(m, (const float[3]){-0.04f, 0.22f, -0.19f}, (const float[3]){0.04f, 0.32f, -0.17f},
                 (const uint8_t[3]){240, 200, 40});
    /* the open chest: the lid stands up at the back (-z), gold inside */
    m = &s->tpl[HOL__T_CHEST_OPEN];
    hol_mesh_box(m, (const float[3]){-0.25f, 0, -0.17f}, (const float[3]){0.25f, 0.28f, 0.17f},
                 (const uint8_t[3]){130, 80, 40});
    hol_mesh_box(m, (const float[3]){-0.26f, 0.28f, -0.28f}, (const float[3]){0.26f, 0.66f, -0.18f},
                 (const uint8_t[3]){150, 95, 45});
    hol_mesh_blob(m, (const float[3]){0, 0.29f, 0}, 0.21f, 0.08f, 0.14f,
                  (const uint8_t[3]){250, 210, 50});
    m = &s->tpl[HOL__T_POLE]; /* white: tinted per objective */
    hol_mesh_frustum(m, 6, 0.035f, 0.0f, 0.035f, 2.6f, hol__white);
    hol_mesh_blob(m, (const float[3]){0, 2.65f, 0}, 0.09f, 0.09f, 0.09f, hol__white);
    hol__build_marks(s);
}

hol_err hol_scene_create(const hol_alloc *a, hol_scene **out)
{
    hol_scene *s = hol_alloc_mem(a, sizeof *s);
    if (!s)
        return HOL_ENOMEM;
    memset(s, 0, sizeof *s);
    for (int k = 0; k < HOL__T_COUNT; k++)
        hol_mesh_init(&s->tpl[k], s->v[k], HOL__TPL_V, s->i[k], HOL__TPL_I);
    hol__build_templates(s);
    for (int k = 0; k < HOL__T_COUNT; k++)
        if (s->tpl[k].overflow) {
            hol_alloc_release(a, s);
            return HOL_ENOMEM;
        }
    *out = s;
    return HOL_OK;
}

void hol_scene_destroy(const hol_alloc *a, hol_scene *s)
{
    if (s)
        hol_alloc_release(a, s);
}

/* small deterministic generator for placements inside a tile */
static uint64_t hol__mix(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

static float hol__unit(uint64_t *x)
{
    return (float)(hol__mix(x) >> 40) / 16777216.0f;
}

/* The tree standing on room vertex (i,j): the vertex as a corner of the
 * adjacent cell nearest the user's cell (ties: the first of NW, SW, SE, NE
 * corners), reached by the room walk columns first, then rows. This does
 * not depend on where the eye is inside the cell, so trees never change
 * while the user stands still or looks around. */
static int hol__vertex_tree(const hol_room *user, struct hol_world *world, int i,
                            int j, hol_tree *out)
{
    if (!world)
        return 0;
    /* the four cells around the vertex and the vertex's corner in each */
    static const int dc[4] = {0, 0, -1, -1}, dr[4] = {0, -1, -1, 0};
    int best = -1, best_d = 1 << 30;
    for (int a = 0; a < 4; a++) {
        int c = i + dc[a], r = j + dr[a];
        if (c < 0 || c >= hol_room_cols(user) || r < 0 || r >= hol_room_rows(user))
            continue;
        int d = abs(c - user->col) + abs(r - user->row);
        if (d < best_d) {
            best_d = d;
            best = a;
        }
    }
    if (best < 0)
        return 0;
    /* corner a of cell (i+dc, j+dr) is the vertex: a = 0 NW, 1 SW, 2 SE, 3 NE */
    int c = i + dc[best], r = j + dr[best];
    hol_room st = *user;
    while (st.col != c)
        if (hol_room_step(&st, st.col < c ? HOL_DIR_E : HOL_DIR_W))
            return 0;
    while (st.row != r)
        if (hol_room_step(&st, st.row < r ? HOL_DIR_S : HOL_DIR_N))
            return 0;
    return hol_world_tree(hol_world_seed(world), st.tile, (st.orient + best) & 3, out) ==
           HOL_OK;
}

/* Forest ground outside the room (not floor: no tile is there; seen only
 * from above the hedges): a ring round the W x D metres of the room. */
static void hol__outer_ground(hol_mesh *out, float W, float D)
{
    static const uint8_t outer[3] = {52, 84, 44};
    const float R = 40.0f;
    int64_t b = hol_mesh_reserve(out, 8, 24);
    if (b < 0)
        return;
    const float xy[8][2] = {{-R, -R}, {W + R, -R}, {W + R, D + R}, {-R, D + R},
                            {0, 0}, {W, 0}, {W, D}, {0, D}};
    for (int k = 0; k < 8; k++) {
        hol_vertex *v = &out->v[out->nv++];
        memset(v, 0, sizeof *v);
        v->pos[0] = xy[k][0];
        v->pos[1] = -0.01f;
        v->pos[2] = xy[k][1];
        v->nrm[1] = 127;
        memcpy(v->rgba, outer, 3);
        v->rgba[3] = HOL_MESH_PROP;
    }
    /* the ring between the outer and the inner square, its triangles
     * wound counter-clockwise seen from above (every mesh's front face is
     * its normal's side: the room and tile passes cull back faces) */
    for (int k = 0; k < 4; k++) {
        uint32_t o0 = (uint32_t)b + (uint32_t)k, o1 = (uint32_t)b + (uint32_t)((k + 1) & 3);
        uint32_t i0 = o0 + 4, i1 = o1 + 4;
        uint32_t t[6] = {o0, i1, o1, o0, i0, i1};
        memcpy(out->idx + out->ni, t, sizeof t);
        out->ni += 6;
    }
}

/* A backdrop forest beyond the hedges (decoration in the room frame: no
 * floor, no tiles; seen over the hedge tops): 40 trees per 12 m of the
 * room's perimeter, walked clockwise from the north-west corner. */
static void hol__backdrop(const hol_scene *s, hol_mesh *out, float W, float D)
{
    uint64_t rs = 0x666f72657374ull;
    const float P = 2 * W + 2 * D;
    const int n = (int)lroundf(40.0f * P / 12.0f);
    for (int k = 0; k < n; k++) {
        float t = (float)k / (float)n * P, d = 0.9f + 2.2f * hol__unit(&rs);
        float x, z;
        if (t < W) {
            x = t; z = -d;
        } else if (t < W + D) {
            x = W + d; z = t - W;
        } else if (t < 2 * W + D) {
            x = 2 * W + D - t; z = D + d;
        } else {
            x = -d; z = P - t;
        }
        hol_place p = {x + 0.3f * hol__unit(&rs), 0, z, hol__unit(&rs) * 6.28f,
                       1.0f + 0.6f * hol__unit(&rs)};
        int kind = (int)(hol__mix(&rs) % 4);
        hol_mesh_append(out, &s->tpl[kind], p);
    }
}

/* Hedges on the boundary, 2 m high, 0.3 m thick, outside the room, in
 * slightly varied segments of about 0.5 m. */
static void hol__hedges(hol_mesh *out, float W, float D)
{
    const float h = 2.0f, th = 0.3f;
    for (int side = 0; side < 4; side++) {
        float len = side < 2 ? W : D;
        int nseg = (int)lroundf(len / 0.5f);
        float seg = len / (float)nseg;
        for (int k = 0; k < nseg; k++) {
            float a = k * seg - (k == 0 ? th : 0), b = (k + 1) * seg + (k == nseg - 1 ? th : 0);
            float hh = h + 0.06f * (float)((k * 5 + side * 3) % 4);
            float lo[3], hi[3];
            if (side == 0) { /* north */
                lo[0] = a; lo[2] = -th; hi[0] = b; hi[2] = 0;
            } else if (side == 1) { /* south */
                lo[0] = a; lo[2] = D; hi[0] = b; hi[2] = D + th;
            } else if (side == 2) { /* west */
                lo[0] = -th; lo[2] = a; hi[0] = 0; hi[2] = b;
            } else { /* east */
                lo[0] = W; lo[2] = a; hi[0] = W + th; hi[2] = b;
            }
            lo[1] = 0;
            hi[1] = hh;
            uint8_t c[3] = {hol__hedge[0], (uint8_t)(hol__hedge[1] + 6 * (k % 3)), hol__hedge[2]};
            hol_mesh_box(out, lo, hi, c);
            float top[3] = {0.5f * (lo[0] + hi[0]), hh, 0.5f * (lo[2] + hi[2])};
            uint8_t c2[3] = {(uint8_t)(c[0] + 8), (uint8_t)(c[1] + 10), (uint8_t)(c[2] + 6)};
            hol_mesh_blob(out, top, 0.34f, 0.16f, 0.34f, c2);
        }
    }
}

void hol_scene_room(const hol_scene *s, hol_mesh *out, const hol_room *user,
                    struct hol_world *world, double cell_m, uint32_t out_backdrop[2])
{
    int cols = hol_room_cols(user), rows = hol_room_rows(user);
    float m = cell_m > 0 ? (float)cell_m : 1.0f;
    for (int j = 0; j <= rows; j++)
        for (int i = 0; i <= cols; i++) {
            hol_tree tr = {(uint8_t)((i * 7 + j * 3) % 4), (uint8_t)((i + j) % 4)};
            hol__vertex_tree(user, world, i, j, &tr);
            float sc = 0.85f + 0.1f * (float)(tr.size & 3);
            hol_place p = {(float)i * m, 0, (float)j * m, 0.7f * (float)(i * 4 + j), sc};
            hol_mesh_append(out, &s->tpl[tr.kind & 3], p);
        }
    float W = (float)cols * m, D = (float)rows * m;
    uint32_t back0 = out->ni;
    hol__outer_ground(out, W, D);
    hol__backdrop(s, out, W, D);
    if (out_backdrop) {
        out_backdrop[0] = back0;
        out_backdrop[1] = out->ni;
    }
    hol__hedges(out, W, D);
}

void hol_scene_tree_mark(const hol_scene *s, hol_mesh *out, int vx, int vz, double cell_m)
{
    float m = cell_m > 0 ? (float)cell_m : 1.0f;
    hol_mesh_append(out, &s->tpl[HOL__T_TREE_MARK], (hol_place){(float)vx * m, 0, (float)vz * m, 0, 1});
}

static void hol__biome_rgb(int biome, uint64_t h, uint8_t rgb[3])
{
    static const uint8_t base[HOL_BIOME_COUNT][3] = {
        {104, 168, 72},  /* meadow */
        {70, 116, 62},   /* pine */
        {78, 136, 112},  /* wetland */
        {172, 142, 66},  /* autumn */
    };
    const uint8_t *b = base[biome < HOL_BIOME_COUNT ? biome : 0];
    int dv = (int)((h >> 8) & 15) - 8;
    for (int k = 0; k < 3; k++) {
        int v = b[k] + dv;
        rgb[k] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
    }
}

/* The ground: a 4 x 4 grid with a little per-vertex shade variation. */
static void hol__ground(hol_mesh *out, uint64_t h, const uint8_t rgb[3])
{
    enum { N = 4 };
    int64_t b = hol_mesh_reserve(out, (N + 1) * (N + 1), N * N * 6);
    if (b < 0)
        return;
    uint64_t rs = h ^ 0x67726f756e64ull;
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            int dv = (int)(hol__mix(&rs) % 25) - 12;
            uint8_t c[3];
            for (int k = 0; k < 3; k++) {
                int v = rgb[k] + dv;
                c[k] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
            }
            hol_vertex *v = &out->v[out->nv++];
            memset(v, 0, sizeof *v);
            v->pos[0] = -0.5f + (float)i / N;
            v->pos[2] = -0.5f + (float)j / N;
            v->nrm[1] = 127;
            memcpy(v->rgba, c, 3);
            v->rgba[3] = HOL_MESH_FLOOR;
        }
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            uint32_t a = (uint32_t)b + (uint32_t)(j * (N + 1) + i);
            uint32_t t[6] = {a, a + N + 1, a + N + 2, a, a + N + 2, a + 1};
            memcpy(out->idx + out->ni, t, sizeof t);
            out->ni += 6;
        }
}

/* A floor strip (water) from the tile centre to edge d. */
static void hol__creek_arm(hol_mesh *out, int d, const uint8_t rgb[3])
{
    static const float w = 0.13f;
    float x0, z0, x1, z1;
    switch (d & 3) {
    case 0: x0 = -w; x1 = w; z0 = -0.5f; z1 = 0; break;
    case 1: x0 = -0.5f; x1 = 0; z0 = -w; z1 = w; break;
    case 2: x0 = -w; x1 = w; z0 = 0; z1 = 0.5f; break;
    default: x0 = 0; x1 = 0.5f; z0 = -w; z1 = w; break;
    }
    hol_mesh_quad_y(out, x0, z0, x1, z1, 0.003f, rgb, HOL_MESH_FLOOR);
}

/* A prop placed at q in a tile of m metres a side: its place scales with
 * the cell, its size does not. */
static void hol__put(hol_mesh *out, const hol_mesh *tpl, hol_place q, float m)
{
    q.x *= m;
    q.z *= m;
    hol_mesh_append(out, tpl, q);
}

static void hol__put_tinted(hol_mesh *out, const hol_mesh *tpl, hol_place q, float m,
                            const uint8_t tint[3])
{
    q.x *= m;
    q.z *= m;
    hol_mesh_append_tinted(out, tpl, q, tint);
}

/* The ground built since vertex v0 (a unit tile) scaled to m metres. */
static void hol__scale_ground(hol_mesh *out, uint32_t v0, float m)
{
    for (uint32_t i = v0; i < out->nv && !out->overflow; i++) {
        out->v[i].pos[0] *= m;
        out->v[i].pos[2] *= m;
    }
}

/* A lantern: a dark post 18 cm beside the centre, an arm, the glass over
 * the centre at the light's height (render/hol_light.h: 1.3 m). */
static void hol__lantern(hol_mesh *out)
{
    static const uint8_t iron[3] = {40, 36, 34}, glass[3] = {255, 214, 140};
    const float px = -0.18f, top = 1.42f;
    float lo[3] = {px - 0.02f, 0, -0.02f}, hi[3] = {px + 0.02f, top, 0.02f};
    hol_mesh_box(out, lo, hi, iron);
    float alo[3] = {px, top - 0.03f, -0.012f}, ahi[3] = {0.012f, top, 0.012f};
    hol_mesh_box(out, alo, ahi, iron);
    uint32_t g0 = out->nv;
    float c[3] = {0, 1.3f, 0};
    hol_mesh_blob(out, c, 0.07f, 0.10f, 0.07f, glass);
    for (uint32_t i = g0; i < out->nv; i++)
        out->v[i].rgba[3] = HOL_MESH_GLOW;
}

/* A tile's small props (grass tufts, flowers, mushrooms): their
 * templates, places (unit tile) and tints (NULL: none), chosen from rs in
 * the order they always were, so a tile's props stay where they were;
 * hol_scene_tile appends them last (the renderer lights them per vertex
 * at dusk and night: hol_scene.h). */
typedef struct hol__props {
    int n;
    uint8_t tpl[HOL__PROPS_MAX];
    hol_place q[HOL__PROPS_MAX];
    const uint8_t *tint[HOL__PROPS_MAX];
} hol__props;

static void hol__prop(hol__props *sp, int tpl, hol_place q, const uint8_t *tint)
{
    if (sp->n >= HOL__PROPS_MAX)
        return;
    sp->tpl[sp->n] = (uint8_t)tpl;
    sp->q[sp->n] = q;
    sp->tint[sp->n++] = tint;
}

static void hol__small_props(const hol_tile_content *c, int ncreek, uint64_t *rs,
                             hol__props *sp)
{
    static const uint8_t cols[4][3] = {
        {240, 240, 250}, {250, 210, 60}, {220, 80, 150}, {140, 110, 230}};
    sp->n = 0;
    /* a few tufts on every tile but the wettest */
    if (c->object != HOL_OBJ_GRASS && c->object != HOL_OBJ_NONE && c->object != HOL_OBJ_POOL)
        for (int k = 0; k < 10; k++) {
            hol_place q = {hol__unit(rs) * 0.9f - 0.45f, 0, hol__unit(rs) * 0.9f - 0.45f,
                           hol__unit(rs) * 6.28f, 0.7f + 0.4f * hol__unit(rs)};
            if (ncreek && fabsf(q.x) < 0.18f && fabsf(q.z) < 0.18f)
                continue;
            hol__prop(sp, HOL__T_TUFT, q, NULL);
        }
    if (c->object == HOL_OBJ_GRASS || c->object == HOL_OBJ_NONE) {
        int n = c->object == HOL_OBJ_GRASS ? 48 : 20;
        for (int k = 0; k < n; k++) {
            hol_place q = {hol__unit(rs) * 0.8f - 0.4f, 0, hol__unit(rs) * 0.8f - 0.4f,
                           hol__unit(rs) * 6.28f, 0.8f + 0.5f * hol__unit(rs)};
            hol__prop(sp, HOL__T_TUFT, q, NULL);
        }
    } else if (c->object == HOL_OBJ_FLOWERS) {
        for (int k = 0; k < 12; k++) {
            hol_place q = {hol__unit(rs) * 0.7f - 0.35f, 0, hol__unit(rs) * 0.7f - 0.35f, 0,
                           0.8f + 0.4f * hol__unit(rs)};
            hol__prop(sp, HOL__T_FLOWER, q, cols[hol__mix(rs) & 3]);
        }
    } else if (c->object == HOL_OBJ_MUSHROOM) {
        for (int k = 0; k < 5; k++) {
            hol_place q = {hol__unit(rs) * 0.6f - 0.3f, 0, hol__unit(rs) * 0.6f - 0.3f, 0,
                           0.7f + 0.6f * hol__unit(rs)};
            hol__prop(sp, HOL__T_MUSHROOM, q, NULL);
        }
    }
}

void hol_scene_tile(const hol_scene *s, hol_mesh *out, hol_tile t,
                    struct hol_world *world, int bare, int pole, int kind, double cell_m,
                    uint32_t *out_props, uint32_t *out_ground)
{
    const float m = cell_m > 0 ? (float)cell_m : 1.0f;
    const uint32_t v0 = out->nv, i0 = out->ni;
    const int lantern = (kind & HOL_SCENE_LANTERN) != 0;
    kind &= 0xff;
    uint64_t h = hol_tile_hash(t);
    hol_tile_content c;
    memset(&c, 0, sizeof c);
    int have = world && hol_world_get(world, t, &c) == HOL_OK;
    if (!have) {
        c.biome = (uint8_t)(h % HOL_BIOME_COUNT);
        c.object = HOL_OBJ_NONE;
        c.log_partner = -1;
    }
    uint8_t rgb[3];
    hol__biome_rgb(c.biome, h, rgb);
    hol__ground(out, h, rgb);
    if (!have) {
        /* placeholder: a darker strip on the heading edge shows the frame */
        uint8_t dark[3] = {(uint8_t)(rgb[0] * 3 / 5), (uint8_t)(rgb[1] * 3 / 5),
                           (uint8_t)(rgb[2] * 3 / 5)};
        hol_mesh_quad_y(out, -0.2f, -0.45f, 0.2f, -0.35f, 0.002f, dark, HOL_MESH_FLOOR);
    }
    /* water is ground too: creeks run to the middle of their edges, so they
     * continue across every edge whatever the neighbour's frame */
    static const uint8_t water[3] = {60, 120, 190};
    int ncreek = 0;
    for (int d = 0; d < 4; d++)
        if (c.conn[d] == HOL_CONN_CREEK) {
            hol__creek_arm(out, d, water);
            ncreek++;
        }
    if (ncreek || c.object == HOL_OBJ_POOL) {
        float r = c.object == HOL_OBJ_POOL ? 0.28f : 0.13f;
        hol_mesh_quad_y(out, -r, -r, r, r, 0.004f, water, HOL_MESH_FLOOR);
    }
    hol__scale_ground(out, v0, m);
    *out_props = out->ni;
    if (out_ground)
        *out_ground = out->ni - i0;
    if (bare)
        return;
    uint64_t rs = h ^ 0x5eedull;
    hol__props sp;
    hol__small_props(&c, ncreek, &rs, &sp);
    float rot = (float)(c.rotation & 3) * HOL__PI_2;
    hol_place p = {0, 0, 0, rot, 1};
    switch (c.object) {
    case HOL_OBJ_LOG:
        p.yaw = (float)((c.log_partner >= 0 ? c.log_partner : c.rotation) & 3) * HOL__PI_2;
        p.scale = m; /* the half log reaches the edge */
        hol_mesh_append(out, &s->tpl[HOL__T_LOG], p);
        break;
    case HOL_OBJ_SPRING: {
        for (int k = 0; k < 5; k++) {
            float a = k * 1.2566f;
            hol_place q = {0.2f * cosf(a), 0, 0.2f * sinf(a), a, 0.35f};
            hol__put(out, &s->tpl[HOL__T_ROCK], q, m);
        }
        break;
    }
    case HOL_OBJ_ROCK:
        hol_mesh_append(out, &s->tpl[HOL__T_ROCK], p);
        break;
    default: /* game objects: drawn below, as the app says */
        break;
    }
    static const int game_tpl[] = {-1,          HOL__T_FLAG,       HOL__T_KEY,
                                   HOL__T_CHEST, HOL__T_CHEST_OPEN, HOL__T_MARKER};
    if (kind > 0 && kind < (int)(sizeof game_tpl / sizeof game_tpl[0])) {
        /* the key is small: shown half as large again */
        hol_place g = {0, 0, 0, 0, kind == HOL_RENDER_OBJ_KEY ? 1.5f : 1};
        hol_mesh_append(out, &s->tpl[game_tpl[kind]], g);
    }
    if (pole >= 0) {
        static const uint8_t pc[4][3] = {
            {255, 60, 40}, {40, 120, 255}, {250, 220, 40}, {200, 60, 220}};
        hol_place q = {0.3f, 0, 0.3f, 0, 1};
        hol__put_tinted(out, &s->tpl[HOL__T_POLE], q, m, pc[pole & 3]);
    }
    if (lantern)
        hol__lantern(out);
    /* the small props last: their index range is the tile's end */
    *out_props = out->ni;
    for (int k = 0; k < sp.n; k++) {
        const hol_mesh *tpl = &s->tpl[sp.tpl[k]];
        if (sp.tint[k])
            hol__put_tinted(out, tpl, sp.q[k], m, sp.tint[k]);
        else
            hol__put(out, tpl, sp.q[k], m);
    }
}
