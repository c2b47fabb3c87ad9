/* test_fit.c - the room and cell that fit a play area (core/hol_fit.h),
 * against brute force: every allowed room and cell (3..5 x 3..5, 0.5 to
 * 1.5 m in 5 cm steps) tried on the area, the rule applied by sorting the
 * ones that fit, for thousands of random areas; polygons against a grid
 * of sample points. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_fit.h"
#include "../core/hol_str.h"

static double frand(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* The model: every candidate that fits (a room of c*cm + 2 margin
 * centimetres by r*cm + 2 margin inside w x d), then the rule by a key. */
static void brute_rect(double w, double d, double margin, int out[4])
{
    long best = -1;
    int small = 0;
    for (int c = 3; c <= 5; c++)
        for (int r = 3; r <= 5; r++)
            for (int cm = 50; cm <= 150; cm += 5) {
                int fits = c * cm / 100.0 + 2 * margin <= w + 1e-9 &&
                           r * cm / 100.0 + 2 * margin <= d + 1e-9;
                if (!fits)
                    continue;
                if (c == 3 && r == 3 && cm > small)
                    small = cm;
                long key = cm >= 60 ? (long)c * r * 100000 + cm * 10 + c : -1;
                if (key > best) {
                    best = key;
                    out[0] = c, out[1] = r, out[2] = cm, out[3] = 0;
                }
            }
    if (best < 0) {
        out[0] = out[1] = 3;
        out[2] = small ? small : 50;
        out[3] = !small;
    }
}

static void check_rect(double w, double d, double margin)
{
    int want[4];
    brute_rect(w, d, margin < 0 ? 0.1 : margin, want);
    hol_fit f;
    assert_int_equal(hol_fit_rect(w, d, margin, &f), HOL_OK);
    if (f.cols != want[0] || f.rows != want[1] || f.cell_cm != want[2] ||
        f.too_small != want[3])
        fail_msg("%.4f x %.4f margin %.3f: got %dx%d %d cm small %d, want %dx%d %d cm small %d",
                 w, d, margin, f.cols, f.rows, f.cell_cm, f.too_small, want[0], want[1],
                 want[2], want[3]);
    assert_true(fabs(f.cell_m - f.cell_cm / 100.0) < 1e-12);
    assert_true(f.area_w == w && f.area_d == d);
}

static void test_rect_brute_force(void **state)
{
    (void)state;
    uint64_t s = 20;
    for (int i = 0; i < 20000; i++) {
        double w = 0.5 + frand(&s) * 9, d = i % 3 ? 0.5 + frand(&s) * 9 : w;
        check_rect(w, d, i % 4 ? -1 : frand(&s) * 0.4);
    }
    /* every area on a 1 cm grid up to 9 m square (exact edges included) */
    for (int w = 100; w <= 900; w += 7)
        for (int d = 100; d <= 900; d += 11)
            check_rect(w / 100.0 + 1e-12, d / 100.0 + 1e-12, 0.1);
}

static void test_rect_examples(void **state)
{
    (void)state;
    static const struct {
        double w, d;
        int c, r, cm, small;
    } ex[] = {
        {3.2, 3.2, 5, 5, 60, 0},  {2.6, 2.6, 4, 4, 60, 0}, {2.0, 2.0, 3, 3, 60, 0},
        {3.2, 2.0, 5, 3, 60, 0},  {1.8, 1.8, 3, 3, 50, 0}, {1.7, 1.7, 3, 3, 50, 0}, {1.6, 1.7, 3, 3, 50, 1},
        {1.69, 1.69, 3, 3, 50, 1}, {9, 9, 5, 5, 150, 0},   {3.2, 4.4, 5, 5, 60, 0},
        {5.2, 5.2, 5, 5, 100, 0}, {3.5, 3.5, 5, 5, 65, 0},
    };
    for (size_t i = 0; i < sizeof ex / sizeof ex[0]; i++) {
        hol_fit f;
        assert_int_equal(hol_fit_rect(ex[i].w, ex[i].d, -1, &f), HOL_OK);
        if (f.cols != ex[i].c || f.rows != ex[i].r || f.cell_cm != ex[i].cm ||
            f.too_small != ex[i].small)
            fail_msg("%.2f x %.2f: %dx%d %d cm %d", ex[i].w, ex[i].d, f.cols, f.rows,
                     f.cell_cm, f.too_small);
    }
}

static void test_rect_bad(void **state)
{
    (void)state;
    hol_fit f;
    assert_int_equal(hol_fit_rect(0, 3, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_rect(3, -1, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_rect(NAN, 3, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_rect(3, INFINITY, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_rect(3, 3, -1, NULL), HOL_EARG);
    /* a margin that eats the area: too small, not an error */
    assert_int_equal(hol_fit_rect(3, 3, 5, &f), HOL_OK);
    assert_int_equal(f.too_small, 1);
}

/* ---- polygons ---------------------------------------------------------- */

/* The model of "the centred room lies inside": points on a fine grid over
 * the room (edges included) all inside the polygon by a winding count
 * (points within 1e-5 m of an edge count as inside). */
static int model_inside_point(const float *p, int n, double x, double z)
{
    double wind = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double ax = p[2 * i] - x, az = p[2 * i + 1] - z, bx = p[2 * j] - x,
               bz = p[2 * j + 1] - z;
        double ex = bx - ax, ez = bz - az, l = ex * ex + ez * ez;
        double t = l > 0 ? -(ax * ex + az * ez) / l : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        double dx = ax + t * ex, dz = az + t * ez;
        if (dx * dx + dz * dz < 1e-10)
            return 1;
        wind += atan2(ax * bz - az * bx, ax * bx + az * bz);
    }
    return fabs(wind) > 3;
}

static int model_holds(const float *p, int n, double margin, int c, int r, int cm)
{
    double a = c * cm / 200.0 + margin, b = r * cm / 200.0 + margin;
    for (int i = 0; i <= 60; i++)
        for (int j = 0; j <= 60; j++)
            if ((i == 0 || i == 60 || j == 0 || j == 60 || (i % 6 == 0 && j % 6 == 0)) &&
                !model_inside_point(p, n, -a + 2 * a * i / 60, -b + 2 * b * j / 60))
                return 0;
    return 1;
}

static void test_polygon_rect_equals_rect(void **state)
{
    (void)state;
    uint64_t s = 7;
    for (int i = 0; i < 400; i++) {
        float w = (float)(1 + frand(&s) * 6), d = (float)(1 + frand(&s) * 6);
        float p[8] = {-w / 2, -d / 2, w / 2, -d / 2, w / 2, d / 2, -w / 2, d / 2};
        hol_fit a, b;
        assert_int_equal(hol_fit_rect(w, d, -1, &a), HOL_OK);
        assert_int_equal(hol_fit_polygon(p, 4, -1, &b), HOL_OK);
        assert_int_equal(a.cols, b.cols);
        assert_int_equal(a.rows, b.rows);
        assert_int_equal(a.cell_cm, b.cell_cm);
        assert_int_equal(a.too_small, b.too_small);
        assert_true(fabs(b.area_w - w) < 1e-6 && fabs(b.area_d - d) < 1e-6);
    }
}

static void test_polygon_against_model(void **state)
{
    (void)state;
    /* an L (a corner cut off the north-east), a diamond, an irregular
     * octagon, and a rectangle off the origin */
    static const float L[] = {-1.6f, -0.4f, 0.4f, -0.4f, 0.4f, -1.6f, 1.6f, -1.6f,
                              1.6f,  1.6f,  -1.6f, 1.6f};
    static const float diamond[] = {0, -2.5f, 2.5f, 0, 0, 2.5f, -2.5f, 0};
    static const float oct[] = {-1.0f, -1.9f, 1.2f, -1.8f, 1.9f, -0.9f, 1.8f, 1.1f,
                                0.9f,  1.7f,  -1.1f, 1.8f, -1.8f, 0.8f, -1.7f, -1.2f};
    static const float off[] = {-1.0f, -1.0f, 2.0f, -1.0f, 2.0f, 1.0f, -1.0f, 1.0f};
    const float *polys[] = {L, diamond, oct, off};
    int ns[] = {6, 4, 8, 4};
    for (int k = 0; k < 4; k++)
        for (int c = 3; c <= 5; c++)
            for (int r = 3; r <= 5; r++)
                for (int cm = 50; cm <= 150; cm += 5) {
                    int got = hol_fit_polygon_holds(polys[k], ns[k], 0.1, c, r, cm);
                    int want = model_holds(polys[k], ns[k], 0.1, c, r, cm);
                    if (got != want)
                        fail_msg("polygon %d room %dx%d %d cm: %d, model %d", k, c, r, cm, got,
                                 want);
                }
    /* the L's notch (x < 0.4, z < -0.4) leaves a centred room 0.8 m deep
     * at most (0.6 m of cells and 0.1 m margins): too small; in the diamond
     * (|x| + |z| <= 2.5) (c + r) cells of cm fit when (c + r) cm <= 460:
     * 4 x 3 of 0.65 m (12 cells; more columns of the two) */
    hol_fit f;
    assert_int_equal(hol_fit_polygon(L, 6, -1, &f), HOL_OK);
    assert_int_equal(f.too_small, 1);
    assert_int_equal(hol_fit_polygon(diamond, 4, -1, &f), HOL_OK);
    assert_int_equal(f.cols, 4);
    assert_int_equal(f.rows, 3);
    assert_int_equal(f.cell_cm, 65);
    /* x in [-1, 2]: the centred room is 2 m wide at most, 3 x 3 of 0.6 m */
    assert_int_equal(hol_fit_polygon(off, 4, -1, &f), HOL_OK);
    assert_int_equal(f.too_small, 0);
    assert_int_equal(f.cell_cm, 60);
    assert_int_equal(f.rows, 3);
    assert_int_equal(f.cols, 3);
    assert_true(fabs(f.area_w - 3) < 1e-6 && fabs(f.area_d - 2) < 1e-6);
}

static void test_polygon_bad(void **state)
{
    (void)state;
    float p[2 * (HOL_FIT_MAX_POINTS + 1)] = {0};
    hol_fit f;
    assert_int_equal(hol_fit_polygon(p, 2, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_polygon(p, HOL_FIT_MAX_POINTS + 1, -1, &f), HOL_EARG);
    assert_int_equal(hol_fit_polygon(NULL, 4, -1, &f), HOL_EARG);
    float q[8] = {-1, -1, 1, -1, NAN, 1, -1, 1};
    assert_int_equal(hol_fit_polygon(q, 4, -1, &f), HOL_EARG);
    float z[8] = {0}; /* degenerate: nothing fits */
    assert_int_equal(hol_fit_polygon(z, 4, -1, &f), HOL_OK);
    assert_int_equal(f.too_small, 1);
}

static void test_text(void **state)
{
    (void)state;
    char buf[200];
    hol_fit f;
    hol_fit_rect(2.6, 2.6, -1, &f);
    hol_fit_text(&f, -1, buf, sizeof buf);
    assert_string_equal(buf, "Room 4 x 4 cells of 0.6 m fits your 2.6 x 2.6 m play area");
    hol_fit_rect(3.5, 3.57, -1, &f);
    hol_fit_text(&f, -1, buf, sizeof buf);
    assert_string_equal(buf, "Room 5 x 5 cells of 0.65 m fits your 3.5 x 3.57 m play area");
    hol_fit_rect(1.2, 1.4, -1, &f);
    hol_fit_text(&f, -1, buf, sizeof buf);
    assert_string_equal(buf, "Your 1.2 x 1.4 m play area is smaller than the smallest room "
                             "(3 x 3 cells of 0.5 m and 0.1 m clear): playing 3 x 3 cells "
                             "of 0.5 m, keep to the middle");
    /* the player's line in German (issue 37: the web page's status) */
    hol_fit_say(&f, -1, HOL_LANG_DE, buf, sizeof buf);
    assert_string_equal(buf, "Deine 1.2 x 1.4 m Spielfläche ist zu klein für 3 x 3 Zellen zu "
                             "0.5 m und 0.1 m Rand: bleib in der Mitte");
    hol_fit_rect(10, 12, -1, &f);
    hol_fit_text(&f, -1, buf, sizeof buf);
    assert_string_equal(buf, "Room 5 x 5 cells of 1.5 m fits your 10.0 x 12.0 m play area");
}

/* The fit played in a level: the lines added to its text (so logs and
 * recordings name them), the level made again; a level naming its room
 * or cell keeps it. */
static void test_fit_level(void **state)
{
    (void)state;
    hol_fit f;
    assert_int_equal(hol_fit_rect(2.6, 2.6, -1, &f), HOL_OK);
    static hol_level lv;
    hol_level_err le;
    const char *t = "mode explore\nseed 3\n";
    assert_int_equal(hol_level_make("a", 1, t, strlen(t), &lv, &le), HOL_OK);
    int changed = -1;
    assert_int_equal(hol_fit_level(&lv, &f, &changed), HOL_OK);
    assert_int_equal(changed, 1);
    assert_int_equal(lv.lvl.room_cols, 4);
    assert_int_equal(lv.lvl.room_rows, 4);
    assert_true(fabs(lv.lvl.cell_m - 0.6) < 1e-12);
    assert_non_null(strstr(lv.text, "room 4 4\n"));
    assert_non_null(strstr(lv.text, "cell 0.6\n"));
    assert_string_equal(lv.name, "a");
    static const char *const own[] = {"mode explore\nseed 3\nroom 3 3\n",
                                      "mode explore\nseed 3\ncell 1\n"};
    for (int i = 0; i < 2; i++) {
        assert_int_equal(hol_level_make("b", 1, own[i], strlen(own[i]), &lv, &le), HOL_OK);
        char before[sizeof lv.text];
        memcpy(before, lv.text, sizeof before);
        assert_int_equal(hol_fit_level(&lv, &f, &changed), HOL_OK);
        assert_int_equal(changed, 0);
        assert_string_equal(lv.text, before);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rect_brute_force),   cmocka_unit_test(test_rect_examples),
        cmocka_unit_test(test_rect_bad),           cmocka_unit_test(test_polygon_rect_equals_rect),
        cmocka_unit_test(test_polygon_against_model), cmocka_unit_test(test_polygon_bad),
        cmocka_unit_test(test_text),
        cmocka_unit_test(test_fit_level),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
