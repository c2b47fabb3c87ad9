/* test_render_slice.c - hol_mesh_slice_y (render/hol_mesh.h), which cuts
 * the lit room's trees and hedges in bands of height for their per-vertex
 * light (issue 38). No GL: the meshes alone.
 *
 * - test_bands: a hedge's box and a trunk's frustum cut at 0.65, 1.3 and
 *   1.95 m: every new triangle lies in one band, the area is kept, every
 *   triangle keeps its winding (its normal on the side of the vertex
 *   normal), and the copy is appended after the original (untouched).
 * - test_closed: the cut box is still closed with no T-junction: every
 *   edge, by its two end points' exact bits, is used by exactly two
 *   triangles, so no crack can open between bands or faces.
 * - test_overflow: past the capacity the mesh says so and keeps whole
 *   polygons only.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../render/hol_mesh.h"

#define CAP_V 4096
#define CAP_I 12288

static hol_vertex vbuf[CAP_V];
static uint32_t ibuf[CAP_I];
static const float ys[3] = {0.65f, 1.3f, 1.95f};

static void tri_geom(const hol_mesh *m, uint32_t t, double out_n[3], double *out_area,
                     double *out_lo, double *out_hi)
{
    const float *a = m->v[m->idx[t]].pos, *b = m->v[m->idx[t + 1]].pos,
                *c = m->v[m->idx[t + 2]].pos;
    double u[3], w[3];
    for (int k = 0; k < 3; k++) {
        u[k] = (double)b[k] - a[k];
        w[k] = (double)c[k] - a[k];
    }
    out_n[0] = u[1] * w[2] - u[2] * w[1];
    out_n[1] = u[2] * w[0] - u[0] * w[2];
    out_n[2] = u[0] * w[1] - u[1] * w[0];
    *out_area = 0.5 * sqrt(out_n[0] * out_n[0] + out_n[1] * out_n[1] + out_n[2] * out_n[2]);
    *out_lo = fmin(a[1], fmin(b[1], c[1]));
    *out_hi = fmax(a[1], fmax(b[1], c[1]));
}

/* The area of [first, end) and checks of each triangle: one band, winding. */
static double check_range(const hol_mesh *m, uint32_t first, uint32_t end, int banded)
{
    double area = 0;
    for (uint32_t t = first; t < end; t += 3) {
        double n[3], a, lo, hi;
        tri_geom(m, t, n, &a, &lo, &hi);
        area += a;
        if (a < 1e-12)
            continue;
        const int8_t *vn = m->v[m->idx[t]].nrm;
        assert_true(n[0] * vn[0] + n[1] * vn[1] + n[2] * vn[2] > 0);
        if (!banded)
            continue;
        int band = 0;
        while (band < 3 && lo >= ys[band] - 1e-6)
            band++;
        if (band < 3 && hi > ys[band] + 1e-6)
            fail_msg("triangle %u spans %.4f..%.4f across the plane %.2f", t, lo, hi,
                     ys[band]);
    }
    return area;
}

static void make_pieces(hol_mesh *m)
{
    hol_mesh_init(m, vbuf, CAP_V, ibuf, CAP_I);
    hol_mesh_box(m, (const float[3]){0, 0, 0}, (const float[3]){0.5f, 2.06f, 0.3f},
                 (const uint8_t[3]){40, 90, 40});
    hol_mesh_frustum(m, 8, 0.09f, 0.0f, 0.07f, 3.2f, (const uint8_t[3]){104, 74, 50});
}

static void test_bands(void **state)
{
    (void)state;
    hol_mesh m;
    make_pieces(&m);
    uint32_t n0 = m.ni, v0 = m.nv;
    hol_vertex before[64];
    memcpy(before, m.v, sizeof before);
    double want = check_range(&m, 0, n0, 0);
    hol_mesh_slice_y(&m, 0, n0, ys, 3);
    assert_false(m.overflow);
    assert_true(m.ni > n0 && m.nv > v0);
    assert_memory_equal(before, m.v, sizeof before);
    double got = check_range(&m, n0, m.ni, 1);
    print_message("area %.6f before, %.6f after; %u triangles from %u\n", want, got,
                  (m.ni - n0) / 3, n0 / 3);
    assert_true(fabs(got - want) < 1e-5 * want);
}

typedef struct edge {
    uint32_t p[2][3]; /* the end points' bits, the smaller first */
} edge;

static int edge_cmp(const void *a, const void *b)
{
    return memcmp(a, b, sizeof(edge));
}

static void test_closed(void **state)
{
    (void)state;
    hol_mesh m;
    hol_mesh_init(&m, vbuf, CAP_V, ibuf, CAP_I);
    hol_mesh_box(&m, (const float[3]){0, 0, 0}, (const float[3]){0.5f, 2.06f, 0.3f},
                 (const uint8_t[3]){40, 90, 40});
    uint32_t n0 = m.ni;
    hol_mesh_slice_y(&m, 0, n0, ys, 3);
    static edge e[CAP_I];
    size_t ne = 0;
    for (uint32_t t = n0; t < m.ni; t += 3)
        for (int k = 0; k < 3; k++) {
            uint32_t a[3], b[3];
            memcpy(a, m.v[m.idx[t + k]].pos, sizeof a);
            memcpy(b, m.v[m.idx[t + (k + 1) % 3]].pos, sizeof b);
            int swap = memcmp(a, b, sizeof a) > 0;
            memcpy(e[ne].p[0], swap ? b : a, sizeof a);
            memcpy(e[ne].p[1], swap ? a : b, sizeof a);
            ne++;
        }
    qsort(e, ne, sizeof e[0], edge_cmp);
    size_t i = 0, odd = 0;
    while (i < ne) {
        size_t j = i;
        while (j < ne && !edge_cmp(&e[i], &e[j]))
            j++;
        odd += (j - i) != 2;
        i = j;
    }
    print_message("%zu edges, %zu not shared by exactly two triangles\n", ne, odd);
    assert_int_equal(odd, 0);
}

static void test_overflow(void **state)
{
    (void)state;
    hol_mesh m;
    make_pieces(&m);
    uint32_t n0 = m.ni;
    m.cap_v = m.nv + 10; /* room for a few polygons only */
    hol_mesh_slice_y(&m, 0, n0, ys, 3);
    assert_true(m.overflow);
    assert_true(m.nv <= m.cap_v);
    assert_int_equal((m.ni - n0) % 3, 0);
    for (uint32_t i = n0; i < m.ni; i++)
        assert_true(m.idx[i] < m.nv);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bands),
        cmocka_unit_test(test_closed),
        cmocka_unit_test(test_overflow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
