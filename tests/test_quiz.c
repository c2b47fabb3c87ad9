/* test_quiz.c - the class's pre-test and post-test (core/hol_quiz.h, issue
 * 37): every item's right answer in {4,4}..{4,8} against the model of
 * tests/model.h (the square walk closes or not, the fewest steps home by a
 * breadth-first search, the tiles at 2 and 3 steps counted by it, the
 * corner's squares and their angle sum); the key read back from an
 * answer's questionnaire and item id; the pre-test and post-test differ in
 * their numbers; `quiz pre|post` levels parse and ask the four items.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_level.h"
#include "../core/hol_quiz.h"
#include "../core/hol_room.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "model.h"
#pragma GCC diagnostic pop

static model_mat route(const char *s)
{
    model_mat m = model_identity();
    for (; *s; s++)
        m = model_step(m, hol_dir_from_char((unsigned char)*s));
    return m;
}

/* The model's squares round a corner: N, W, S, E, ... until home. */
static int corner_squares(void)
{
    static const char round[] = "NWSE";
    model_mat m = model_identity(), o = model_identity();
    for (int k = 1; k <= 16; k++) {
        m = model_step(m, hol_dir_from_char(round[(k - 1) % 4]));
        if (model_same_point(m, o))
            return k;
    }
    return -1;
}

static void test_keys_against_the_model(void **state)
{
    (void)state;
    static const char *const routes[2][2] = {{"NESW", "NESS"}, {"ENWS", "WSEE"}};
    for (int q = 4; q <= 8; q++) {
        model_use_tiling(q);
        model_bfs b;
        assert_int_equal(model_bfs_run(&b, 7), 0);
        for (int ph = 0; ph < 2; ph++) {
            hol_quiz_item it[HOL_QUIZ_ITEMS];
            for (int k = 0; k < HOL_QUIZ_ITEMS; k++)
                assert_int_equal(hol_quiz_item_of(ph, k, q, &it[k]), HOL_OK);
            char want[32];
            int closes = model_same_point(route(routes[ph][0]), model_identity());
            assert_string_equal(it[0].right, closes ? "Yes" : "No");
            assert_int_equal(closes, q == 4);
            int squares = corner_squares();
            assert_int_equal(squares, q);
            if (ph == 0) {
                snprintf(want, sizeof want, "%d", squares);
            } else {
                double sum = 4 * 360.0 / squares;
                snprintf(want, sizeof want, "%s",
                         fabs(sum - 360) < 1e-9 ? "360 degrees" : sum < 360 ? "less than 360"
                                                                           : "more than 360");
            }
            assert_string_equal(it[1].right, want);
            snprintf(want, sizeof want, "%d", b.per_dist[2 + ph]);
            assert_string_equal(it[2].right, want);
            snprintf(want, sizeof want, "%d", model_dist0(&b, route(routes[ph][1])));
            assert_string_equal(it[3].right, want);
            /* a number answer lies on its scale */
            for (int k = 1; k < HOL_QUIZ_ITEMS; k++) {
                const hol_app_question *qn = &it[k].question;
                if (qn->kind != HOL_APP_LIKERT)
                    continue;
                int v = atoi(it[k].right);
                assert_true(v >= qn->lo && v <= qn->hi && (v - qn->lo) % qn->step == 0);
                assert_true((qn->hi - qn->lo) / qn->step + 1 <= HOL_APP_MAX_SCALE);
            }
            /* the key read back from the logged names */
            for (int k = 0; k < HOL_QUIZ_ITEMS; k++) {
                char right[32];
                assert_int_equal(hol_quiz_key(hol_quiz_name(ph), it[k].question.id, right,
                                              sizeof right), k);
                assert_string_equal(right, it[k].right);
            }
        }
        model_bfs_free(&b);
    }
    char r[32];
    assert_int_equal(hol_quiz_key("pretest", "home_q9", r, sizeof r), -1);
    assert_int_equal(hol_quiz_key("predict", "home_q5", r, sizeof r), -1);
    assert_int_equal(hol_quiz_key("posttest", "homes_q5", r, sizeof r), -1);
    assert_int_equal(hol_quiz_key("posttest", "home_q55", r, sizeof r), -1);
}

/* The same concepts with other numbers: each item's text differs between
 * the tests, and so do the answers of the growth and corner items. */
static void test_pre_and_post_differ(void **state)
{
    (void)state;
    for (int k = 0; k < HOL_QUIZ_ITEMS; k++) {
        hol_quiz_item a, b;
        assert_int_equal(hol_quiz_item_of(HOL_QUIZ_PRE, k, 5, &a), HOL_OK);
        assert_int_equal(hol_quiz_item_of(HOL_QUIZ_POST, k, 5, &b), HOL_OK);
        assert_string_not_equal(a.question.text, b.question.text);
        assert_string_equal(a.question.id, b.question.id);
    }
    hol_quiz_item x;
    assert_int_equal(hol_quiz_item_of(2, 0, 5, &x), HOL_EARG);
    assert_int_equal(hol_quiz_item_of(0, 4, 5, &x), HOL_EARG);
    assert_int_equal(hol_quiz_item_of(0, 0, 9, &x), HOL_EARG);
}

static void test_quiz_levels(void **state)
{
    (void)state;
    static const char *const text[2] = {"tiling 4 6\nquiz pre\n", "quiz post\n"};
    for (int ph = 0; ph < 2; ph++) {
        hol_app_level L;
        hol_level_err e;
        assert_int_equal(hol_level_parse(text[ph], strlen(text[ph]), &L, &e), HOL_OK);
        assert_int_equal(L.mode, HOL_APP_EXPLORE);
        assert_int_equal(L.nasks, 1);
        assert_string_equal(L.asks[0].name, hol_quiz_name(ph));
        assert_int_equal(L.asks[0].when, HOL_APP_BEFORE_LEVEL);
        assert_int_equal(L.nquestions, HOL_QUIZ_ITEMS);
        assert_string_equal(L.questions[2].id, ph ? "growth_q5" : "growth_q6");
        assert_true(L.time_limit_s > 0);
    }
    hol_app_level L;
    hol_level_err e;
    assert_int_equal(hol_level_parse("quiz mid\n", 9, &L, &e), HOL_EPARSE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_keys_against_the_model),
        cmocka_unit_test(test_pre_and_post_differ),
        cmocka_unit_test(test_quiz_levels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
