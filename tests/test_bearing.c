/* test_bearing.c - bearings for pointing (core/hol_bearing.h, SPEC 8)
 * against the independent hyperboloid model of tests/model.h, in every
 * tiling {4,4}..{4,8}: random free walks and targets (tiles the walk stood
 * on, and others), the true bearing as the model's direction of the target's
 * centre in the walk's carried frame, the flat bearing from integer grid
 * positions and the model's own identification of tiles; in {4,4} the two
 * agree wherever the flat one exists; SPEC's example; formatting; errors and
 * far walks.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_bearing.h"
#include "../core/hol_tile.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" /* the search is not used here */
#include "model.h"
#pragma GCC diagnostic pop

static uint64_t rng = 0x9E3779B97F4A7C15u;
static unsigned rnd(unsigned n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (unsigned)(rng % n);
}

/* Circular difference of two angles in degrees. */
static double ang_diff(double a, double b)
{
    double d = fmod(fabs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

/* The model's bearing of vector (east, north), written independently. */
static double model_bearing(double east, double north)
{
    double d = atan2(east, north) * 180.0 / acos(-1.0);
    return d < 0 ? d + 360.0 : d;
}

/* The model's frame of tile t from its address letters alone. */
static model_mat frame_of(hol_tile t)
{
    int codes[HOL_TILE_MAX_DIST];
    int n = hol_tile_dist0(t);
    for (int i = 0; i < n; i++)
        codes[i] = hol_tile_letter(t, i);
    return model_walk_letters(codes, n);
}

/* One walk (room dirs 0 N, 1 W, 2 S, 3 E) and a target, checked against the
 * model. Returns 1 when the walk had a flat bearing. */
static int check_one(int q, const int *dirs, int n, hol_tile target)
{
    static const int dx[4] = {0, -1, 0, 1}, dy[4] = {1, 0, -1, 0};
    model_mat p = frame_of(target), m = model_identity();
    int seen = model_same_point(m, p), x = 0, y = 0, tx = 0, ty = 0;
    hol_bearing_walk w;
    assert_int_equal(hol_bearing_begin(&w, target), HOL_OK);
    for (int i = 0; i < n; i++) {
        assert_int_equal(hol_bearing_step(&w, dirs[i]), HOL_OK);
        m = model_step(m, dirs[i]); /* the room frame carried: +y stays north */
        x += dx[dirs[i]];
        y += dy[dirs[i]];
        if (!seen && model_same_point(m, p)) {
            seen = 1;
            tx = x;
            ty = y;
        }
    }
    hol_bearing b;
    assert_int_equal(hol_bearing_end(&w, &b), HOL_OK);
    (void)q;
    model_mat rel = model_mul(model_inv(m), p);
    if (model_same_point(m, p)) {
        assert_int_equal(b.has_true, 0);
    } else {
        assert_int_equal(b.has_true, 1);
        double want = model_bearing(rel.m[2], rel.m[5]);
        assert_true(b.true_deg >= 0.0 && b.true_deg < 360.0);
        if (ang_diff(b.true_deg, want) > 1e-4) {
            print_error("{4,%d} n=%d true %.9f model %.9f\n", q, n, b.true_deg, want);
            fail();
        }
        /* the printed text, away from a rounding boundary */
        double frac = want * 10.0 - floor(want * 10.0);
        if (fabs(frac - 0.5) > 1e-3) {
            char got[HOL_BEARING_TEXT], exp[32];
            hol_bearing_format(b.true_deg, got);
            long t = (long)floor(want * 10.0 + 0.5) % 3600;
            snprintf(exp, sizeof exp, "%ld.%ld", t / 10, t % 10);
            assert_string_equal(got, exp);
        }
    }
    int flat = seen && (tx != x || ty != y);
    assert_int_equal(b.has_flat, flat);
    if (flat)
        assert_true(ang_diff(b.flat_deg, model_bearing(tx - x, ty - y)) < 1e-9);
    if (q == 4 && flat) { /* SPEC 8: in {4,4} the two agree */
        assert_int_equal(b.has_true, 1);
        assert_true(ang_diff(b.true_deg, b.flat_deg) < 1e-9);
    }
    return flat;
}

static hol_tile tile_of_walk(int q, const int *dirs, int n)
{
    uint8_t d[64];
    hol_tile t;
    for (int i = 0; i < n; i++)
        d[i] = (uint8_t)dirs[i];
    assert_int_equal(hol_tile_from_walk_q(q, d, (size_t)n, &t, NULL), HOL_OK);
    return t;
}

static void test_model_every_tiling(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++) {
        model_use_tiling(q);
        int flats = 0, trues = 0;
        for (int k = 0; k < 3000; k++) {
            int dirs[16], n = (int)rnd(8), other[8], m = (int)rnd(6);
            for (int i = 0; i < n; i++)
                dirs[i] = (int)rnd(4);
            for (int i = 0; i < m; i++)
                other[i] = (int)rnd(4);
            /* a tile the walk stood on (a prefix), or another tile */
            hol_tile t = k % 2 ? tile_of_walk(q, dirs, (int)rnd((unsigned)n + 1))
                               : tile_of_walk(q, other, m);
            flats += check_one(q, dirs, n, t);
            trues++;
        }
        assert_true(flats > 500);
        (void)trues;
    }
    model_use_tiling(5);
}

/* {4,4}: every walk up to 6 steps, every tile it stood on. */
static void test_flat_grid_agrees(void **state)
{
    (void)state;
    model_use_tiling(4);
    int dirs[6];
    for (int n = 0; n <= 6; n++)
        for (int code = 0; code < (1 << (2 * n)); code++) {
            for (int i = 0; i < n; i++)
                dirs[i] = (code >> (2 * i)) & 3;
            for (int pre = 0; pre <= n; pre += 2)
                check_one(4, dirs, n, tile_of_walk(4, dirs, pre));
        }
    model_use_tiling(5);
}

static void bearing_text(int q, const char *walk, const char *target, char *out)
{
    hol_tile t;
    hol_bearing_walk w;
    hol_bearing b;
    assert_int_equal(hol_tile_parse_q(q, target, -1, &t), HOL_OK);
    assert_int_equal(hol_bearing_begin(&w, t), HOL_OK);
    for (const char *c = walk; *c; c++)
        assert_int_equal(hol_bearing_step(&w, (int)(strchr("NWSE", *c) - "NWSE")), HOL_OK);
    assert_int_equal(hol_bearing_end(&w, &b), HOL_OK);
    char a[HOL_BEARING_TEXT] = "-", f[HOL_BEARING_TEXT] = "-";
    if (b.has_true)
        hol_bearing_format(b.true_deg, a);
    if (b.has_flat)
        hol_bearing_format(b.flat_deg, f);
    sprintf(out, "%s %s", a, f);
}

static void test_spec_examples(void **state)
{
    (void)state;
    char s[32];
    bearing_text(5, "NESW", "O", s);
    assert_string_equal(s, "0.0 -"); /* SPEC 8 */
    bearing_text(4, "NESW", "O", s);
    assert_string_equal(s, "- -"); /* the loop closes in the flat grid */
    bearing_text(5, "", "O", s);
    assert_string_equal(s, "- -");
    bearing_text(5, "N", "O", s);
    assert_string_equal(s, "180.0 180.0");
    bearing_text(5, "", "E", s);
    assert_string_equal(s, "90.0 -");
    bearing_text(6, "W", "O", s);
    assert_string_equal(s, "90.0 90.0");
    bearing_text(4, "NE", "O", s);
    assert_string_equal(s, "225.0 225.0");
    /* a straight walk is a geodesic through the centres: the start lies
     * due south however far it goes */
    char far[64];
    memset(far, 'N', 55);
    far[55] = '\0';
    for (int q = 4; q <= 8; q++) {
        bearing_text(q, far, "O", s);
        assert_string_equal(s, "180.0 180.0");
    }
}

static void test_format(void **state)
{
    (void)state;
    char b[HOL_BEARING_TEXT];
    static const struct { double v; const char *s; } cases[] = {
        {0.0, "0.0"},     {-0.0, "0.0"},     {359.96, "0.0"}, {359.94, "359.9"},
        {90.0, "90.0"},   {180.04, "180.0"}, {7.26, "7.3"},   {360.0, "0.0"},
        {-0.04, "0.0"},   {-90.0, "270.0"},  {NAN, "0.0"},    {1e300, "0.0"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        int n = hol_bearing_format(cases[i].v, b);
        assert_string_equal(b, cases[i].s);
        assert_int_equal(n, (int)strlen(cases[i].s));
    }
    assert_true(fabs(hol_bearing_of_vector(1, 0) - 90.0) < 1e-12);
    assert_true(fabs(hol_bearing_of_vector(0, -1) - 180.0) < 1e-12);
    assert_true(fabs(hol_bearing_of_vector(-1, 0) - 270.0) < 1e-12);
    assert_true(hol_bearing_of_vector(0, 0) == 0.0);
}

static void test_errors(void **state)
{
    (void)state;
    hol_tile bad = {{0, ~(uint64_t)0}}, o = hol_tile_origin_q(6), t;
    hol_bearing_walk w, before;
    double deg = -1;
    assert_int_equal(hol_bearing_begin(&w, bad), HOL_EARG);
    assert_int_equal(hol_bearing_begin(&w, o), HOL_OK);
    before = w;
    assert_int_equal(hol_bearing_step(&w, 4), HOL_EARG);
    assert_int_equal(hol_bearing_step(&w, -1), HOL_EARG);
    assert_memory_equal(&w, &before, sizeof w);
    /* beyond the reach: refused, the walk unchanged */
    for (int i = 0; i < hol_tile_reach(6); i++)
        assert_int_equal(hol_bearing_step(&w, 0), HOL_OK);
    before = w;
    assert_int_equal(hol_bearing_step(&w, 0), HOL_ERANGE);
    assert_memory_equal(&w, &before, sizeof w);
    assert_int_equal(hol_bearing_step(&w, 2), HOL_OK);
    /* tiles of two tilings, or no direction */
    assert_int_equal(hol_tile_parse_q(5, "N", -1, &t), HOL_OK);
    assert_int_equal(hol_bearing_true(o, 0, t, &deg), HOL_EARG);
    assert_int_equal(hol_bearing_true(t, 0, t, &deg), HOL_EARG);
    assert_true(deg == -1);
    /* the frame is an argument: room north turned a quarter left */
    assert_int_equal(hol_bearing_true(hol_tile_origin_q(5), 1, t, &deg), HOL_OK);
    assert_true(fabs(deg - 90.0) < 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_model_every_tiling),
        cmocka_unit_test(test_flat_grid_agrees),
        cmocka_unit_test(test_spec_examples),
        cmocka_unit_test(test_format),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("bearing", tests, NULL, NULL);
}
