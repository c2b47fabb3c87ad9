/* test_render_cull.c - the resident meshes may have their back faces
 * culled (render/hol_render_gpu.c's hol__cull): every triangle of the
 * room's mesh (every room size, the marked tree) and of tile meshes of
 * every object, game object, pole and lantern is wound counter-clockwise
 * seen from its vertices' normal side (the geometric normal, the cross
 * product of its edges, within 90 degrees of the first vertex's normal)
 * or is the inner twin of one that is, and has an area; a frustum whose open bottom is above the ground (a
 * pine's crown) carries its inner faces too, so from below one still
 * sees into it. The referee is the cross product, not the renderer. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "../render/hol_mesh.h"
#include "../render/hol_render.h"
#include "../render/hol_scene.h"

#define NV 100000
#define NI 200000
static hol_vertex vbuf[NV];
static uint32_t ibuf[NI];

/* 1 when triangle i (its first index) of m has a twin from i0 on: the
 * same vertices wound the other way (an inner face: hol_mesh_frustum). */
static int twin(const hol_mesh *m, uint32_t i0, uint32_t i)
{
    const uint32_t *t = &m->idx[i];
    for (uint32_t j = i0; j + 2 < m->ni; j += 3) {
        const uint32_t *o = &m->idx[j];
        for (int r = 0; r < 3; r++)
            if (o[r] == t[0] && o[(r + 1) % 3] == t[2] && o[(r + 2) % 3] == t[1])
                return 1;
    }
    return 0;
}

/* Triangles of m from index i0 wound against their normal and with no
 * twin (out_flat: of
 * no area); returns how many triangles. */
static int wound(const hol_mesh *m, uint32_t i0, int *out_bad, int *out_flat)
{
    int n = 0;
    *out_bad = *out_flat = 0;
    for (uint32_t i = i0; i + 2 < m->ni; i += 3, n++) {
        const hol_vertex *a = &m->v[m->idx[i]], *b = &m->v[m->idx[i + 1]],
                         *c = &m->v[m->idx[i + 2]];
        double u[3], v[3];
        for (int k = 0; k < 3; k++) {
            u[k] = b->pos[k] - a->pos[k];
            v[k] = c->pos[k] - a->pos[k];
        }
        double g[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (len < 1e-12) {
            (*out_flat)++;
            continue;
        }
        double d = g[0] * a->nrm[0] + g[1] * a->nrm[1] + g[2] * a->nrm[2];
        *out_bad += d <= 0 && !twin(m, i0, i);
    }
    return n;
}

static void test_room_meshes_wound_outward(void **state)
{
    (void)state;
    hol_scene *s;
    assert_int_equal(hol_scene_create(NULL, &s), HOL_OK);
    for (int cols = 3; cols <= 5; cols++)
        for (int rows = 3; rows <= 5; rows++) {
            hol_room u;
            assert_int_equal(hol_room_start_in(5, cols, rows, &u), HOL_OK);
            hol_mesh m;
            hol_mesh_init(&m, vbuf, NV, ibuf, NI);
            uint32_t back[2];
            hol_scene_room(s, &m, &u, NULL, 1.0, back);
            hol_scene_tree_mark(s, &m, 1, 1, 1.0);
            assert_false(m.overflow);
            int bad, flat, n = wound(&m, 0, &bad, &flat);
            assert_true(n > 1000);
            assert_int_equal(bad, 0);
            assert_int_equal(flat, 0);
        }
    hol_scene_destroy(NULL, s);
}

static void test_tile_meshes_wound_outward(void **state)
{
    (void)state;
    hol_scene *s;
    assert_int_equal(hol_scene_create(NULL, &s), HOL_OK);
    hol_world *w;
    hol_world_desc wd = {0};
    wd.seed = 3;
    assert_int_equal(hol_world_make(&wd, &w), HOL_OK);
    hol_room u = hol_room_start();
    assert_int_equal(hol_world_update(w, &u), HOL_OK);
    static const char *addr[] = {"O", "N", "E", "S", "W", "Nf", "Ef", "Sf", "Wf", "Nl", "Nr", "El"};
    int tiles = 0;
    for (size_t a = 0; a < sizeof addr / sizeof addr[0]; a++)
        for (int kind = 0; kind <= HOL_RENDER_OBJ_MARKER; kind++) {
            hol_tile t;
            assert_int_equal(hol_tile_parse(addr[a], (ptrdiff_t)strlen(addr[a]), &t), HOL_OK);
            hol_mesh m;
            hol_mesh_init(&m, vbuf, NV, ibuf, NI);
            uint32_t props;
            hol_scene_tile(s, &m, t, w, 0, kind % 2 ? (int)a & 3 : -1,
                           kind | (a % 2 ? HOL_SCENE_LANTERN : 0), 1.0, &props, NULL);
            assert_false(m.overflow);
            int bad, flat, n = wound(&m, 0, &bad, &flat);
            assert_true(n >= 32); /* the ground alone is 32 */
            assert_int_equal(bad, 0);
            assert_int_equal(flat, 0);
            tiles++;
        }
    assert_true(tiles >= 60);
    hol_world_destroy(w);
    hol_scene_destroy(NULL, s);
}

/* A cone on the ground: one triangle a side, no inner faces; a crown's
 * cone above the ground: its inner faces too, each the same three
 * vertices as an outer one, wound the other way. */
static void test_frustum_inside(void **state)
{
    (void)state;
    static const uint8_t rgb[3] = {1, 2, 3};
    hol_mesh m;
    hol_mesh_init(&m, vbuf, NV, ibuf, NI);
    hol_mesh_frustum(&m, 8, 0.5f, 0.0f, 0.0f, 1.0f, rgb);
    assert_int_equal(m.ni, 8 * 3);
    assert_int_equal(m.nv, 8 * 3);
    hol_mesh_clear(&m);
    hol_mesh_frustum(&m, 8, 0.5f, 2.2f, 0.0f, 3.9f, rgb);
    assert_int_equal(m.ni, 2 * 8 * 3);
    for (uint32_t i = 0; i < 8 * 3; i += 3) {
        const uint32_t *o = &m.idx[i], *in = &m.idx[8 * 3 + i];
        assert_int_equal(in[0], o[0]);
        assert_int_equal(in[1], o[2]);
        assert_int_equal(in[2], o[1]);
    }
    int bad, flat;
    assert_int_equal(wound(&m, 0, &bad, &flat), 16);
    assert_int_equal(bad, 0); /* the 8 inner faces have their twins */
    memcpy(&m.idx[0], &m.idx[8 * 3], 3 * sizeof m.idx[0]);
    m.ni = 3; /* an inner face alone: wound against its normal */
    assert_int_equal(wound(&m, 0, &bad, &flat), 1);
    assert_int_equal(bad, 1);
    assert_int_equal(flat, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_room_meshes_wound_outward),
        cmocka_unit_test(test_tile_meshes_wound_outward),
        cmocka_unit_test(test_frustum_inside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
