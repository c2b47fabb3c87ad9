/* hol_scene.c - procedural meshes for the forest. */
#include "hol_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HOL__TPL_V 4096
#define HOL__TPL_I 8192

enum { HOL__T_TREE, HOL__T_COUNT };

struct hol_scene {
    hol_mesh tpl[HOL__T_COUNT];
    hol_vertex v[HOL__T_COUNT][HOL__TPL_V];
    uint32_t i[HOL__T_COUNT][HOL__TPL_I];
};

static const uint8_t hol__trunk[3] = {110, 78, 52};
static const uint8_t hol__leaf[3] = {46, 120, 58};
static const uint8_t hol__hedge[3] = {38, 96, 44};

void hol_scene_sky(float out_rgb[3])
{
    out_rgb[0] = 0.70f;
    out_rgb[1] = 0.82f;
    out_rgb[2] = 0.93f;
}

hol_err hol_scene_create(hol_scene **out)
{
    hol_scene *s = calloc(1, sizeof *s);
    if (!s)
        return HOL_ENOMEM;
    for (int k = 0; k < HOL__T_COUNT; k++)
        hol_mesh_init(&s->tpl[k], s->v[k], HOL__TPL_V, s->i[k], HOL__TPL_I);
    /* tree: trunk taller than any eye, so the seam behind a vertex stays
     * hidden, and a two-tier crown */
    hol_mesh *t = &s->tpl[HOL__T_TREE];
    hol_mesh_frustum(t, 7, 0.10f, 0.0f, 0.08f, 3.2f, hol__trunk);
    hol_mesh_frustum(t, 8, 0.75f, 2.2f, 0.0f, 4.0f, hol__leaf);
    hol_mesh_frustum(t, 8, 0.55f, 3.3f, 0.0f, 4.8f, hol__leaf);
    *out = s;
    return HOL_OK;
}

void hol_scene_destroy(hol_scene *s)
{
    free(s);
}

void hol_scene_room(const hol_scene *s, hol_mesh *out, const hol_view *view,
                    struct hol_world *world)
{
    (void)view;
    (void)world;
    for (int j = 0; j <= HOL_ROOM_SIZE; j++)
        for (int i = 0; i <= HOL_ROOM_SIZE; i++) {
            hol_place p = {(float)i, 0, (float)j, 0.7f * (float)(i * 4 + j), 1};
            hol_mesh_append(out, &s->tpl[HOL__T_TREE], p);
        }
    /* hedges on the boundary, 2 m high, 0.3 m thick, outside the room */
    const float h = 2.0f, th = 0.3f, n = (float)HOL_ROOM_SIZE;
    float boxes[4][6] = {
        {-th, 0, -th, n + th, h, 0},  /* north */
        {-th, 0, n, n + th, h, n + th}, /* south */
        {-th, 0, 0, 0, h, n},         /* west */
        {n, 0, 0, n + th, h, n},      /* east */
    };
    for (int k = 0; k < 4; k++)
        hol_mesh_box(out, boxes[k], boxes[k] + 3, hol__hedge);
}

static void hol__hash_rgb(uint64_t h, uint8_t rgb[3])
{
    /* grass greens varied by the hash: a plain biome-like tint */
    static const uint8_t base[4][3] = {
        {96, 160, 70}, {60, 120, 70}, {80, 140, 110}, {170, 140, 60}};
    const uint8_t *b = base[h & 3];
    int dv = (int)((h >> 8) & 31) - 16;
    for (int k = 0; k < 3; k++) {
        int v = b[k] + dv;
        rgb[k] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
    }
}

void hol_scene_tile(const hol_scene *s, hol_mesh *out, hol_tile t,
                    struct hol_world *world, int bare)
{
    (void)s;
    (void)world;
    (void)bare;
    uint64_t h = hol_tile_hash(t);
    uint8_t rgb[3];
    hol__hash_rgb(h, rgb);
    hol_mesh_quad_y(out, -0.5f, -0.5f, 0.5f, 0.5f, 0.0f, rgb, HOL_MESH_FLOOR);
    /* heading marker: a darker strip along the heading edge (-z) */
    uint8_t dark[3] = {(uint8_t)(rgb[0] * 3 / 5), (uint8_t)(rgb[1] * 3 / 5),
                       (uint8_t)(rgb[2] * 3 / 5)};
    hol_mesh_quad_y(out, -0.2f, -0.45f, 0.2f, -0.35f, 0.002f, dark, HOL_MESH_FLOOR);
}
