/* test_route_preset.c - docs/hacking.md's route "Adding a questionnaire
 * preset", walked: the page's example row (the Fast Motion sickness Scale,
 * Keshavarz and Hecht 2011: one item, 0..20) added to the presets' table
 * the way the page says, then a level that asks it parsed, a study that
 * places it parsed, the app asking it after a level's end screen, its
 * answer scored; the standard presets and the SSQ's scores unchanged.
 *
 * The row is added by building core/hol_ask.c into this test with
 * HOL_ASK_MORE_PRESETS (the table's hook for a build's own rows): this
 * file then defines every name of that file, so the core library's copy is
 * not linked, and the level parser, the study and the app read this table.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

/* The page's example row, as docs/hacking.md shows it. */
#define HOL_ASK_MORE_PRESETS                                                                  \
    {"fms", 0, 20, 1, "no sickness", "frank sickness", 1,                                     \
     {{"fms", "Motion sickness right now: 0 none to 20 frank sickness", NULL, NULL, 1}}, 1,  \
     {{"score", 1, 1, 1}}},
#include "../core/hol_ask.c"

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_stats.h"
#include "../core/hol_study.h"
#include "app_fixture.h"

static hol_input key_in(double t, uint32_t pressed)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED;
    in.pressed = pressed;
    in.device = HOL_DEVICE_KEYBOARD;
    return in;
}

/* The table: the new row after the standard ones, named in messages. */
static void test_table(void **state)
{
    (void)state;
    assert_int_equal(hol_ask_npresets(), 3);
    int i = hol_ask_preset_index("fms", 3);
    assert_int_equal(i, 2);
    const hol_ask_preset_def *p = hol_ask_preset_at(i);
    assert_int_equal(hol_ask_preset_item(p, "fms"), 0);
    char names[HOL_ASK_NAMES_MAX];
    hol_ask_preset_names("or", names, sizeof names);
    assert_string_equal(names, "ssq, tlx or fms");
    hol_app_question q[2];
    assert_int_equal(hol_ask_preset("fms", 3, q, 2), 1);
    assert_string_equal(q[0].id, "fms");
    assert_int_equal(q[0].lo, 0);
    assert_int_equal(q[0].hi, 20);
    assert_int_equal(q[0].step, 1);
    assert_string_equal(q[0].low, "no sickness");
    assert_string_equal(q[0].high, "frank sickness");
    /* the standard rows and the SSQ's scores as before */
    assert_int_equal(hol_ask_preset("ssq", 3, q, 0), 16);
    assert_int_equal(hol_ask_preset("tlx", 3, q, 0), 6);
    double v[HOL_STATS_SSQ_NITEMS];
    for (int k = 0; k < HOL_STATS_SSQ_NITEMS; k++)
        v[k] = 1;
    hol_stats_ssq_score s;
    hol_stats_ssq(v, &s);
    assert_true(fabs(s.nausea - 7 * 9.54) < 1e-9);
    assert_true(fabs(s.total - 21 * 3.74) < 1e-9);
}

/* A level asks it by name (no IDs); a question may not take its name; a
 * study places it like ssq and tlx. */
static void test_level_and_study(void **state)
{
    (void)state;
    hol_app_level L;
    hol_level_err e;
    static const char lvl[] = "mode flag\nflag N\nask fms level\n";
    assert_int_equal(hol_level_parse(lvl, sizeof lvl - 1, &L, &e), HOL_OK);
    assert_int_equal(L.nasks, 1);
    assert_int_equal(L.asks[0].n, 1);
    assert_string_equal(L.questions[L.asks[0].first].id, "fms");
    static const char bad[] = "mode flag\nflag N\nquestion fms likert 1 7 \"T\" \"l\" \"h\"\n";
    assert_int_equal(hol_level_parse(bad, sizeof bad - 1, &L, &e), HOL_EPARSE);
    assert_non_null(strstr(e.msg, "(and not ssq, tlx or fms)"));
    static const char none[] = "mode flag\nflag N\nask sus level\n";
    assert_int_equal(hol_level_parse(none, sizeof none - 1, &L, &e), HOL_EPARSE);
    assert_non_null(strstr(e.msg, "ssq, tlx and fms need none"));
    static hol_study st;
    static const char study[] = "study s\ncounterbalance fixed\n"
                                "questionnaire fms after level\n"
                                "condition a\nset mode explore\n";
    assert_int_equal(hol_study_parse(study, sizeof study - 1, &st, &e), HOL_OK);
}

/* The app asks it after the end screen; the answer is scored. */
static void test_app_asks_and_scores(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L;
    hol_level_err e;
    static const char lvl[] = "mode flag\nflag N\ntime-limit 1\nask fms level\n";
    assert_int_equal(hol_level_parse(lvl, sizeof lvl - 1, &L, &e), HOL_OK);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    for (int i = 0; i <= 60; i++)
        step(app, key_in(i / 60.0, 0));
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_DONE);
    step(app, key_in(1.5, HOL_BTN_CONFIRM));
    assert_int_equal(v->state, HOL_APP_ASK);
    assert_int_equal(v->hud.ask_items, 1);
    int shown = v->hud.ask_value; /* from the middle of 0..20 */
    const hol_app_events *ev = step(app, key_in(2.0, HOL_BTN_CONFIRM));
    assert_int_equal(ev->answered, 1);
    assert_string_equal(ev->answer.questionnaire, "fms");
    assert_string_equal(ev->answer.item, "fms");
    assert_int_equal(ev->answer.value, shown);
    assert_true(ev->answer.value >= 0 && ev->answer.value <= 20);
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index("fms", 3));
    double answers[1] = {ev->answer.value}, score[HOL_ASK_PRESET_SCORES];
    hol_ask_score(p, answers, score);
    assert_true(score[0] == ev->answer.value);
    hol_app_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_level_and_study),
        cmocka_unit_test(test_app_asks_and_scores),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
