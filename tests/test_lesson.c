/* test_lesson.c - the lessons' facts (core/hol_lesson.h, issue 37) against
 * the independent model of tests/model.h in every tiling {4,4}..{4,8}: each
 * route's end tile and its distance from O (the model's breadth-first
 * search), lesson 5's fewest steps home inside a 3 x 3 room (the navigator), the
 * squares round a corner (the model's walk round a vertex until it closes)
 * and the corner's angle (the model's angle between two edges at a vertex),
 * lesson 3's true bearing (the model's direction of O in the carried
 * frame), the tiles at 1..3 steps (the search's counts), how often the
 * square N, E, S, W is walked until it closes; each lesson's texts expand
 * every fact and fit their screens, and `lesson N` parses into the level.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_lesson.h"
#include "../core/hol_level.h"
#include "../core/hol_str.h"
#include "../core/hol_nav.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" /* the frames' difference is not used here */
#include "model.h"
#pragma GCC diagnostic pop

static double ang_diff(double a, double b)
{
    double d = fmod(fabs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

/* The model's frame at the end of room steps from the origin. */
static model_mat model_route(const uint8_t *dirs, int n)
{
    model_mat m = model_identity();
    for (int i = 0; i < n; i++)
        m = model_step(m, dirs[i]);
    return m;
}

/* Room steps of the model round the vertex north-west of the start cell
 * (N, W, S, E, ...) until the frame stands on the origin again. */
static int model_corner_squares(void)
{
    static const int round[4] = {0, 1, 2, 3};
    model_mat m = model_identity(), o = model_identity();
    for (int k = 1; k <= 16; k++) {
        m = model_step(m, round[(k - 1) % 4]);
        if (model_same_point(m, o))
            return k;
    }
    return -1;
}

/* The angle (degrees) of a square's corner, from the model alone: the
 * centres of the tiles round the corner north-west of O's centre (O, N,
 * and on round it) lie evenly round it, so the corner is their normalised
 * mean (on the hyperboloid; in the flat grid the plain mean), and the angle
 * there between the geodesics to two neighbouring centres is the corner's. */
static double model_corner_angle(int q)
{
    /* the centres of the tiles round the corner: O, N, NW, ... */
    model_mat m = model_identity();
    double pts[16][3];
    static const int round[4] = {0, 1, 2, 3};
    for (int k = 0; k < q; k++) {
        pts[k][0] = m.m[2];
        pts[k][1] = m.m[5];
        pts[k][2] = m.m[8];
        m = model_step(m, round[k % 4]);
    }
    /* the corner: the normalised mean of the centres (hyperboloid); the
     * angle between the tangents towards two neighbouring centres */
    double c[3] = {0, 0, 0};
    for (int k = 0; k < q; k++)
        for (int j = 0; j < 3; j++)
            c[j] += pts[k][j];
    double flat = q == 4;
    double norm = flat ? (double)q : sqrt(c[2] * c[2] - c[0] * c[0] - c[1] * c[1]);
    for (int j = 0; j < 3; j++)
        c[j] /= norm;
    double t[2][3];
    for (int s = 0; s < 2; s++) {
        const double *p = pts[s];
        if (flat) {
            for (int j = 0; j < 3; j++)
                t[s][j] = p[j] - c[j];
        } else { /* p minus its part along c: <p,c> = -(p2 c2 - p0 c0 - p1 c1) */
            double ip = p[0] * c[0] + p[1] * c[1] - p[2] * c[2];
            for (int j = 0; j < 3; j++)
                t[s][j] = p[j] + ip * c[j];
        }
    }
    double dot = t[0][0] * t[1][0] + t[0][1] * t[1][1] - (flat ? 0 : t[0][2] * t[1][2]);
    double n0 = sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1] - (flat ? 0 : t[0][2] * t[0][2]));
    double n1 = sqrt(t[1][0] * t[1][0] + t[1][1] * t[1][1] - (flat ? 0 : t[1][2] * t[1][2]));
    /* neighbouring centres round the corner are one corner angle apart */
    return acos(dot / (n0 * n1)) * 180.0 / acos(-1.0);
}

static void test_facts_against_model(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++) {
        model_use_tiling(q);
        model_bfs b;
        assert_int_equal(model_bfs_run(&b, 9), 0);
        hol_nav_desc nd;
        memset(&nd, 0, sizeof nd);
        nd.tiling_q = q;
        nd.lazy = 1;
        hol_nav *nav;
        assert_int_equal(hol_nav_create(&nd, &nav), HOL_OK);
        int corner = model_corner_squares();
        assert_int_equal(corner, q);
        double angle = model_corner_angle(q);
        for (int n = 1; n <= HOL_LESSONS; n++) {
            hol_lesson_facts f;
            assert_int_equal(hol_lesson_facts_of(n, q, &f), HOL_OK);
            model_mat m = model_route(f.route, f.nroute);
            /* the end tile, and its distance: the model's */
            int codes[HOL_TILE_MAX_DIST], len = hol_tile_dist0(f.end);
            for (int i = 0; i < len; i++)
                codes[i] = hol_tile_letter(f.end, i);
            assert_true(model_same_point(model_walk_letters(codes, len), m));
            assert_int_equal(model_dist0(&b, m), f.home);
            /* the fewest steps home inside the 3 x 3 room: the navigator's */
            hol_room r;
            assert_int_equal(hol_room_start_in(q, 3, 3, &r), HOL_OK);
            for (int i = 0; i < f.nroute; i++)
                assert_int_equal(hol_room_step(&r, f.route[i]), HOL_OK);
            uint8_t walk[64];
            hol_nav_result res;
            assert_int_equal(
                hol_nav_find(nav, &r, hol_tile_origin_q(q), 0, walk, sizeof walk, &res), HOL_OK);
            assert_true(res.exact);
            if (n == 5) /* the lesson that states it: the room takes no more */
                assert_int_equal(res.len, f.home);
            else
                assert_true(res.len >= f.home);
            /* corners and angles */
            assert_true(fabs(f.corner_deg - angle) < 1e-6);
            assert_true(fabs(f.square_deg - 4 * angle) < 1e-6);
            /* tiles at 1..3 steps: the search's */
            for (int d = 0; d < 4; d++) {
                assert_int_equal(f.count[d], (uint64_t)b.per_dist[d]);
                assert_int_equal(f.flat_count[d], d ? 4u * (unsigned)d : 1u);
            }
            /* the bearing to O from the route's end: the model's */
            model_mat rel = model_mul(model_inv(m), model_identity());
            int on_o = model_same_point(m, model_identity());
            assert_int_equal(f.has_bearing, !on_o);
            if (!on_o) {
                double want = atan2(rel.m[2], rel.m[5]) * 180.0 / acos(-1.0);
                assert_true(ang_diff(f.bearing_deg, want < 0 ? want + 360 : want) < 1e-4);
            }
            /* the square walked until it closes */
            static const uint8_t sq[4] = {HOL_DIR_N, HOL_DIR_E, HOL_DIR_S, HOL_DIR_W};
            model_mat s = model_identity();
            int times = 0;
            do {
                s = model_mul(s, model_route(sq, 4));
                times++;
            } while (!model_same_point(s, model_identity()) && times < 16);
            assert_int_equal(f.repeats, times);
            /* the right answers */
            switch (n) {
            case 1: assert_int_equal(f.answer, on_o ? 0 : 1); break;
            case 2: assert_int_equal(f.answer, corner); break;
            case 4: assert_int_equal(f.answer, b.per_dist[3]); break;
            case 5: assert_int_equal(f.answer, model_dist0(&b, m)); break;
            case 6: assert_int_equal(f.answer, times); break;
            default: assert_int_equal(f.answer, on_o ? 0 : 1); break; /* north, or here */
            }
            if (n == 6 || n == 2 || n == 1)
                assert_int_equal(on_o, n != 1 || q == 4);
        }
        hol_nav_destroy(nav);
        model_bfs_free(&b);
    }
}

/* Every text expands every fact (a '{' left only in "{4,Q}") and fits its
 * screen. */
static void test_texts_fit(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++)
        for (int n = 1; n <= HOL_LESSONS; n++) {
            hol_lesson_facts f;
            assert_int_equal(hol_lesson_facts_of(n, q, &f), HOL_OK);
            for (int part = 0; part < HOL_LESSON_PARTS; part++) {
                char s[HOL_LESSON_TEXT_MAX];
                int len = hol_lesson_text(&f, HOL_LANG_EN, part, s, sizeof s);
                assert_true(len > 0);
                for (const char *b = strchr(s, '{'); b; b = strchr(b + 1, '{'))
                    assert_true(b[1] == '4' && b[2] == ',');
                for (const char *c = s; *c; c++)
                    assert_true(*c >= 32 && *c < 127);
                if (part == HOL_LESSON_WALK || part == HOL_LESSON_CHECK)
                    assert_true(hol_app_wrap(s, HOL_APP_SCREEN_COLS, NULL, 0) <=
                                HOL_APP_SCREEN_LINES);
                if (part == HOL_LESSON_QUESTION)
                    assert_true(len < HOL_APP_QTEXT_MAX);
            }
        }
}

static void test_level_line(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++)
        for (int n = 1; n <= HOL_LESSONS; n++) {
            char text[64];
            snprintf(text, sizeof text, "tiling 4 %d\nlesson %d\n", q, n);
            hol_app_level L;
            hol_level_err e;
            assert_int_equal(hol_level_parse(text, strlen(text), &L, &e), HOL_OK);
            hol_lesson_facts f;
            assert_int_equal(hol_lesson_facts_of(n, q, &f), HOL_OK);
            assert_int_equal(L.lesson, n);
            assert_int_equal(L.mode, HOL_APP_EXPLORE);
            assert_int_equal(L.nroute, f.nroute);
            assert_memory_equal(L.route, f.route, (size_t)f.nroute);
            assert_int_equal(L.nasks, 1);
            assert_int_equal(L.asks[0].when, HOL_APP_BEFORE_LEVEL);
            assert_string_equal(L.asks[0].name, "predict");
            assert_int_equal(L.questions[0].kind, f.choice ? HOL_APP_CHOICE : HOL_APP_LIKERT);
            if (!f.choice) /* the right number is on the scale */
                assert_true(f.answer >= L.questions[0].lo && f.answer <= L.questions[0].hi &&
                            (f.answer - L.questions[0].lo) % L.questions[0].step == 0);
            else
                assert_true(f.answer < L.questions[0].nchoices);
            assert_int_equal(L.point, n == 3 ? HOL_APP_POINT_START : HOL_APP_POINT_NONE);
            assert_true(L.instructions[0] && L.closing[0]);
        }
    static const char *const bad[] = {"lesson 0\n", "lesson 7\n", "lesson 1\nmode flag\n",
                                      "lesson 1\npoint start\n", "lesson 2\nlesson 3\n",
                                      "lesson 1\nstart N\n", "lesson x\n"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        hol_app_level L;
        hol_level_err e;
        assert_int_not_equal(hol_level_parse(bad[i], strlen(bad[i]), &L, &e), HOL_OK);
    }
    hol_lesson_facts f;
    assert_int_equal(hol_lesson_facts_of(0, 5, &f), HOL_EARG);
    assert_int_equal(hol_lesson_facts_of(1, 9, &f), HOL_EARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_facts_against_model),
        cmocka_unit_test(test_texts_fit),
        cmocka_unit_test(test_level_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
