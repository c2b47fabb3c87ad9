/* test_ask.c - questionnaires (issue 26 item 7): the presets against the
 * published instruments (SSQ: Kennedy et al. 1993's 16 items, 0..3, their
 * subscale membership as table 4 gives it; raw TLX: six scales 0..100 in
 * steps of 5), the question line's grammar, and the app step answering the
 * SSQ after a level's end screen with keys (left/right from the axes, and
 * snap turns), a choice item, and a headset's controller ray; every answer's
 * event (questionnaire, when, item, kind, value, time taken); then the next
 * level. And a study placing questionnaires on the right levels.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_ask.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_study.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"

/* Kennedy et al. (1993), table 4: the items of each subscale, written out
 * here by name (N nausea, O oculomotor, D disorientation). */
static void test_presets(void **state)
{
    (void)state;
    static const char *const ids[16] = {
        "general_discomfort", "fatigue", "headache", "eye_strain", "difficulty_focusing",
        "salivation_increasing", "sweating", "nausea", "difficulty_concentrating",
        "fullness_of_head", "blurred_vision", "dizziness_eyes_open", "dizziness_eyes_closed",
        "vertigo", "stomach_awareness", "burping"};
    static const char *const N[] = {"general_discomfort", "salivation_increasing", "sweating",
                                    "nausea", "difficulty_concentrating", "stomach_awareness",
                                    "burping"};
    static const char *const O[] = {"general_discomfort", "fatigue", "headache", "eye_strain",
                                    "difficulty_focusing", "difficulty_concentrating",
                                    "blurred_vision"};
    static const char *const D[] = {"difficulty_focusing", "nausea", "fullness_of_head",
                                    "blurred_vision", "dizziness_eyes_open",
                                    "dizziness_eyes_closed", "vertigo"};
    hol_app_question q[40];
    assert_int_equal(hol_ask_preset("ssq", 3, q, 40), 16);
    int count[3] = {0, 0, 0};
    for (int k = 0; k < 16; k++) {
        assert_string_equal(q[k].id, ids[k]);
        assert_int_equal(q[k].kind, HOL_APP_LIKERT);
        assert_int_equal(q[k].lo, 0);
        assert_int_equal(q[k].hi, 3);
        unsigned want = 0;
        for (int j = 0; j < 7; j++) {
            want |= !strcmp(N[j], ids[k]) ? 1u : 0u;
            want |= !strcmp(O[j], ids[k]) ? 2u : 0u;
            want |= !strcmp(D[j], ids[k]) ? 4u : 0u;
        }
        assert_int_equal(hol_ask_ssq_subscales(k), want);
        for (int b = 0; b < 3; b++)
            count[b] += (int)(want >> b & 1);
    }
    assert_int_equal(count[0], 7);
    assert_int_equal(count[1], 7);
    assert_int_equal(count[2], 7);
    assert_int_equal(hol_ask_preset("tlx", 3, q, 40), 6);
    static const char *const tlx[6] = {"mental", "physical", "temporal", "performance", "effort",
                                       "frustration"};
    for (int k = 0; k < 6; k++) {
        assert_string_equal(q[k].id, tlx[k]);
        assert_int_equal(q[k].lo, 0);
        assert_int_equal(q[k].hi, 100);
        assert_int_equal(q[k].step, 5);
        assert_true(strlen(q[k].text) < HOL_APP_QTEXT_MAX);
        assert_true(hol_app_wrap(q[k].text, HOL_APP_SCREEN_COLS, NULL, 0) <= 3);
    }
    assert_int_equal(hol_ask_preset("sus", 3, q, 40), 0);
}

static hol_err qline(const char *s, hol_app_question *q)
{
    char msg[160];
    return hol_ask_parse_question(s, strlen(s), q, msg, sizeof msg);
}

static void test_question_line(void **state)
{
    (void)state;
    hol_app_question q;
    assert_int_equal(qline("question fun likert 1 7 \"How much fun?\" \"none\" \"a lot\"", &q),
                     HOL_OK);
    assert_string_equal(q.id, "fun");
    assert_int_equal(q.lo, 1);
    assert_int_equal(q.hi, 7);
    assert_string_equal(q.text, "How much fun?");
    assert_string_equal(q.high, "a lot");
    assert_int_equal(qline("question c choice \"Which?\" \"a b\" \"c\"", &q), HOL_OK);
    assert_int_equal(q.nchoices, 2);
    assert_string_equal(q.choices[0], "a b");
    assert_int_equal(qline("question c choice \"Which?\" \"a\"", &q), HOL_EPARSE);
    assert_int_equal(qline("question c likert 7 1 \"T\" \"l\" \"h\"", &q), HOL_ERANGE);
    assert_int_equal(qline("question c likert 0 100 \"T\" \"l\" \"h\"", &q), HOL_ERANGE);
    assert_int_equal(qline("question c likert 1 7 \"T \"l\" \"h\"", &q), HOL_EPARSE);
    assert_int_equal(qline("question ssq likert 1 7 \"T\" \"l\" \"h\"", &q), HOL_EPARSE);
    assert_int_equal(qline("question c likert 1 7 T \"l\" \"h\"", &q), HOL_EPARSE);
    assert_int_equal(qline("question c choice \"T\" \"1\" \"2\" \"3\" \"4\" \"5\" \"6\" \"7\"", &q),
                     HOL_EPARSE);
    hol_app_level L;
    hol_level_err e;
    static const char lvl[] = "mode flag\nflag N\nask x level nope\n";
    assert_int_equal(hol_level_parse(lvl, sizeof lvl - 1, &L, &e), HOL_EARG);
    assert_int_equal(e.line, 3);
    static const char lvl2[] = "mode flag\nflag N\nask ssq later\n";
    assert_int_equal(hol_level_parse(lvl2, sizeof lvl2 - 1, &L, &e), HOL_EPARSE);
}

static hol_input key_in(double t, uint32_t pressed, float move_x, float turn_x)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED;
    in.pressed = pressed;
    in.move[0] = move_x;
    in.turn[0] = turn_x;
    in.device = HOL_DEVICE_KEYBOARD;
    return in;
}

/* A level ended by its time limit at t = 1 whose text asks (lines). */
static hol_app *ended_level(const char *text)
{
    hol_app *app = make_app();
    hol_app_level L;
    hol_level_err e;
    assert_int_equal(hol_level_parse(text, strlen(text), &L, &e), HOL_OK);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    for (int i = 0; i <= 60; i++)
        step(app, key_in(i / 60.0, 0, 0, 0));
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_DONE);
    return app;
}

/* The presets and the class test in German (issue 37): the items shown in
 * the view's language (the level's `lang`), the answers logged as before
 * (item ids, English choices). */
static void test_app_said(void **state)
{
    (void)state;
    hol_app *app = ended_level("lang de\nmode flag\nflag N\ntime-limit 1\nask tlx condition\n");
    const hol_app_view *v = hol_app_get_view(app);
    const hol_app_events *ev = step(app, key_in(1.5, HOL_BTN_CONFIRM, 0, 0));
    assert_int_equal(v->state, HOL_APP_ASK);
    assert_string_equal(v->hud.lines[0], "Geistige Anforderung: Wie geistig");
    assert_string_equal(v->hud.lines[1], "anspruchsvoll war die Aufgabe?");
    assert_string_equal(v->hud.lines[3], "0 Sehr gering, 100 Sehr hoch");
    assert_string_equal(v->hud.hint, "ENTER: antworten, ESC: aufhören");
    ev = step(app, key_in(2.0, HOL_BTN_CONFIRM, 0, 0));
    assert_int_equal(ev->answered, 1);
    assert_string_equal(ev->answer.questionnaire, "tlx");
    assert_string_equal(ev->answer.item, "mental");
    hol_app_destroy(app);
    app = make_app();
    hol_app_level L;
    hol_level_err e;
    static const char quiz[] = "lang de\nquiz pre\n";
    assert_int_equal(hol_level_parse(quiz, sizeof quiz - 1, &L, &e), HOL_OK);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    v = hol_app_get_view(app);
    step(app, key_in(0, 0, 0, 0));
    assert_int_equal(v->state, HOL_APP_ASK);
    assert_string_equal(v->hud.lines[0], "Geh N, O, S, W. Stehst du wieder auf deiner");
    assert_string_equal(v->hud.lines[2], "  Ja >   Vortest 1/4");
    ev = step(app, key_in(0.5, HOL_BTN_CONFIRM, 0, 0));
    assert_int_equal(ev->answered, 1);
    assert_string_equal(ev->answer.questionnaire, "pretest");
    assert_string_equal(ev->answer.item, "square_q5");
    assert_string_equal(ev->answer.choice, "Yes");
    hol_app_destroy(app);
}

/* The SSQ with keys: item k answered k mod 4 (from the middle, 1: right
 * presses raise, left lower, a held key counts once, a snap turn counts). */
static void test_app_ssq(void **state)
{
    (void)state;
    hol_app *app = ended_level("mode flag\nflag N\ntime-limit 1\nask ssq condition\n");
    const hol_app_view *v = hol_app_get_view(app);
    double t = 1.5;
    const hol_app_events *ev = step(app, key_in(t, HOL_BTN_CONFIRM, 0, 0));
    assert_int_equal(ev->next_level, 0);
    assert_int_equal(v->state, HOL_APP_ASK);
    assert_string_equal(v->hud.lines[0], "General discomfort");
    assert_string_equal(v->hud.lines[1], "< 1 >   ssq 1/16"); /* from the middle */
    assert_string_equal(v->hud.lines[2], "0 none, 3 severe");
    assert_string_equal(v->hud.hint, "ENTER: answer, ESC: quit");
    hol_app_question q[16];
    hol_ask_preset("ssq", 3, q, 16);
    for (int k = 0; k < 16; k++) {
        int want = k % 4, at = 1;
        assert_int_equal(v->hud.ask_item, k);
        assert_int_equal(v->hud.ask_items, 16);
        while (at != want) {
            int right = want > at;
            t += 0.1;
            if (k == 5 && !right) { /* a snap turn to the left: one lower */
                hol_input in = key_in(t, 0, 0, 0);
                in.flags |= HOL_INPUT_SNAP_YAW;
                in.snap_yaw_deg = 45;
                step(app, in);
            } else {
                step(app, key_in(t, 0, right ? 1.0f : 0, right ? 0 : 1.0f));
                t += 0.1;
                step(app, key_in(t, 0, right ? 1.0f : 0, right ? 0 : 1.0f)); /* held */
                t += 0.1;
                step(app, key_in(t, 0, 0, 0));
            }
            at += right ? 1 : -1;
            assert_int_equal(v->hud.ask_value, at);
        }
        t += 0.25;
        double shown = t;
        (void)shown;
        ev = step(app, key_in(t, HOL_BTN_CONFIRM, 0, 0));
        assert_int_equal(ev->answered, 1);
        assert_string_equal(ev->answer.questionnaire, "ssq");
        assert_int_equal(ev->answer.when, HOL_APP_AFTER_CONDITION);
        assert_string_equal(ev->answer.item, q[k].id);
        assert_int_equal(ev->answer.kind, HOL_APP_LIKERT);
        assert_int_equal(ev->answer.value, want);
        assert_true(ev->answer.time_s > 0.2);
        if (k < 15) {
            assert_int_equal(ev->next_level, 0);
            assert_int_equal(v->state, HOL_APP_ASK);
        }
    }
    assert_int_equal(ev->next_level, 1); /* the last answer goes on */
    hol_app_destroy(app);
}

/* A choice and a 0..100 scale by 5 (tlx's first), the time taken, quit. */
static void test_app_choice_time(void **state)
{
    (void)state;
    hol_app *app = ended_level("mode flag\nflag N\ntime-limit 1\n"
                               "question h choice \"Which hand?\" \"left\" \"right\" \"both\"\n"
                               "ask mine level h\nask tlx study\n");
    const hol_app_view *v = hol_app_get_view(app);
    step(app, key_in(2, HOL_BTN_CONFIRM, 0, 0));
    assert_string_equal(v->hud.lines[1], "< right >   mine 1/1");
    step(app, key_in(2.5, 0, 1, 0));
    assert_string_equal(v->hud.lines[1], "< both     mine 1/1");
    const hol_app_events *ev = step(app, key_in(4.5, HOL_BTN_CONFIRM, 0, 0));
    assert_int_equal(ev->answered, 1);
    assert_int_equal(ev->answer.kind, HOL_APP_CHOICE);
    assert_string_equal(ev->answer.choice, "both");
    assert_true(fabs(ev->answer.time_s - 2.5) < 1e-9);
    assert_int_equal(v->hud.ask_value, 50); /* tlx from the middle of 0..100 */
    step(app, key_in(5, 0, 0, 1));
    assert_int_equal(v->hud.ask_value, 45);
    ev = step(app, key_in(6, HOL_BTN_CONFIRM, 0, 0));
    assert_string_equal(ev->answer.item, "mental");
    assert_int_equal(ev->answer.value, 45);
    assert_int_equal(ev->answer.when, HOL_APP_AFTER_STUDY);
    assert_true(fabs(ev->answer.time_s - 1.5) < 1e-9); /* shown at 4.5 */
    ev = step(app, key_in(7, HOL_BTN_QUIT, 0, 0));
    assert_int_equal(v->state, HOL_APP_QUIT);
    assert_int_equal(ev->answered, 0);
    hol_app_destroy(app);
}

/* A headset: the controller's ray picks the mark, 60 degrees across the
 * scale centred on the look when the item came up. */
static void test_app_ray(void **state)
{
    (void)state;
    hol_app *app = ended_level("mode flag\nflag N\ntime-limit 1\n"
                               "question f likert 1 7 \"Fun?\" \"no\" \"yes\"\nask m level f\n");
    const hol_app_view *v = hol_app_get_view(app);
    hol_input in = key_in(1.5, HOL_BTN_CONFIRM, 0, 0);
    in.flags |= HOL_INPUT_HEAD_VALID;
    in.head.quat[3] = 1;
    in.head.pos[0] = in.head.pos[2] = 1.5f;
    in.head.pos[1] = 1.6f;
    step(app, in);
    assert_int_equal(v->state, HOL_APP_ASK);
    static const struct { double right_deg; int mark; } cases[] = {
        {-40, 1}, {-29, 1}, {-21, 2}, {0, 4}, {9, 5}, {21, 6}, {27, 7}, {80, 7}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        in.time_s += 0.1;
        in.pressed = 0;
        in.flags |= HOL_INPUT_HAND_R_VALID;
        double h = -cases[k].right_deg * acos(-1.0) / 360; /* right: negative yaw */
        in.hand[HOL_HAND_RIGHT].quat[1] = (float)sin(h);
        in.hand[HOL_HAND_RIGHT].quat[3] = (float)cos(h);
        step(app, in);
        assert_int_equal(v->hud.ask_value, cases[k].mark);
    }
    in.time_s += 0.1;
    in.pressed = HOL_BTN_CONFIRM;
    const hol_app_events *ev = step(app, in);
    assert_int_equal(ev->answer.value, 7);
    hol_app_destroy(app);
}

static hol_study g_study;

static int asks_of(int i, int position, char *names)
{
    static const char file[] = "mode flag\nflag N\n";
    hol_level lv;
    hol_level_err e;
    int in_study;
    assert_int_equal(hol_study_make_level(&g_study, i, position, file, sizeof file - 1, NULL, &lv,
                                          &e, &in_study),
                     HOL_OK);
    names[0] = 0;
    for (int k = 0; k < lv.lvl.nasks; k++)
        sprintf(names + strlen(names), "%s%s:%d", k ? " " : "", lv.lvl.asks[k].name,
                lv.lvl.asks[k].n);
    return lv.lvl.nasks;
}

static void test_study_placement(void **state)
{
    (void)state;
    static const char text[] =
        "study s\ncounterbalance fixed\npractice p.lvl\n"
        "question fun likert 1 7 \"Fun?\" \"no\" \"yes\"\n"
        "question h choice \"Hand?\" \"l\" \"r\"\n"
        "questionnaire mine fun h\n"
        "questionnaire tlx after study\nquestionnaire ssq after condition\n"
        "questionnaire mine after level\n"
        "condition a\nlevel x.lvl\nlevel x.lvl\ncondition b\nlevel x.lvl\n";
    hol_level_err e;
    assert_int_equal(hol_study_parse(text, sizeof text - 1, &g_study, &e), HOL_OK);
    char names[256];
    assert_int_equal(asks_of(0, 0, names), 0); /* practice: none */
    asks_of(1, 1, names);
    assert_string_equal(names, "mine:2");
    asks_of(2, 1, names);
    assert_string_equal(names, "mine:2 ssq:16");
    asks_of(3, 2, names);
    assert_string_equal(names, "mine:2 ssq:16 tlx:6");
    asks_of(2, 2, names); /* a's last played last */
    assert_string_equal(names, "mine:2 ssq:16 tlx:6");
    static const char *const bad[][2] = {
        {"study s\nquestionnaire sus after level\ncondition a\nset mode explore\n",
         "line 2: questionnaire sus is neither given"},
        {"study s\nquestionnaire m fun\ncondition a\nset mode explore\n",
         "line 2: questionnaire m: no question 'fun' before it"},
        {"study s\nquestionnaire ssq after lunch\ncondition a\nset mode explore\n",
         "line 2: questionnaire ssq after 'lunch'"},
        {"study s\ncondition a\nset mode explore\nquestionnaire ssq after level\n",
         "line 4: 'questionnaire' comes before the first condition"},
        {"study s\nquestion q likert 1 7 \"a\" \"b\"\ncondition a\nset mode explore\n",
         "line 2: question q likert needs"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        assert_int_not_equal(hol_study_parse(bad[k][0], strlen(bad[k][0]), &g_study, &e), HOL_OK);
        char msg[256];
        hol_level_err_format(&e, 1, msg, sizeof msg);
        if (strncmp(msg, bad[k][1], strlen(bad[k][1]))) {
            print_error("%zu: got '%s', want '%s'\n", k, msg, bad[k][1]);
            fail();
        }
    }
}

/* Level i's asks as NAME:WHEN, in order. */
static void whens_of(int i, int position, char *names)
{
    static const char file[] = "mode flag\nflag N\n";
    hol_level lv;
    hol_level_err e;
    int in_study;
    assert_int_equal(hol_study_make_level(&g_study, i, position, file, sizeof file - 1, NULL, &lv,
                                          &e, &in_study),
                     HOL_OK);
    names[0] = 0;
    for (int k = 0; k < lv.lvl.nasks; k++)
        sprintf(names + strlen(names), "%s%s:%s", k ? " " : "", lv.lvl.asks[k].name,
                hol_ask_when_name(lv.lvl.asks[k].when));
}

/* `before` placements (issue 35): before study on the participant's first
 * level (the practice's when there is one), before condition on each
 * condition's first, before level on each; before ones ahead of after
 * ones; a level line `ask NAME during` refused. */
static void test_study_before(void **state)
{
    (void)state;
    static const char text[] =
        "study s\ncounterbalance fixed\npractice p.lvl\n"
        "question fun likert 1 7 \"Fun?\" \"no\" \"yes\"\n"
        "questionnaire mine fun\n"
        "questionnaire tlx after condition\nquestionnaire mine before level\n"
        "questionnaire tlx before condition\nquestionnaire ssq before study\n"
        "condition a\nlevel x.lvl\nlevel x.lvl\ncondition b\nlevel x.lvl\n";
    hol_level_err e;
    assert_int_equal(hol_study_parse(text, sizeof text - 1, &g_study, &e), HOL_OK);
    char names[256];
    whens_of(0, 0, names);
    assert_string_equal(names, "ssq:before_study");
    whens_of(1, 1, names);
    assert_string_equal(names, "tlx:before_condition mine:before_level");
    whens_of(2, 1, names);
    assert_string_equal(names, "mine:before_level tlx:condition");
    whens_of(3, 2, names);
    assert_string_equal(names, "tlx:before_condition mine:before_level tlx:condition");
    static const char plain[] = "study s\ncounterbalance fixed\nquestionnaire ssq before study\n"
                                "condition a\nlevel x.lvl\nlevel x.lvl\ncondition b\nlevel x.lvl\n";
    assert_int_equal(hol_study_parse(plain, sizeof plain - 1, &g_study, &e), HOL_OK);
    whens_of(0, 1, names);
    assert_string_equal(names, "ssq:before_study");
    whens_of(1, 1, names);
    assert_string_equal(names, "");
    whens_of(2, 1, names); /* b played first */
    assert_string_equal(names, "ssq:before_study");
    whens_of(2, 2, names);
    assert_string_equal(names, "");
    hol_level lv;
    static const char bad[] = "mode flag\nflag N\nask ssq during\n";
    assert_int_not_equal(hol_level_parse(bad, sizeof bad - 1, &lv.lvl, &e), HOL_OK);
    char msg[256];
    hol_level_err_format(&e, 1, msg, sizeof msg);
    assert_non_null(strstr(msg, "ask ssq: 'during' is not level, condition, study, before_level, "
                                "before_condition or before_study"));
    static const char good[] = "mode flag\nflag N\nask ssq before_level\n";
    assert_int_equal(hol_level_parse(good, sizeof good - 1, &lv.lvl, &e), HOL_OK);
    assert_int_equal(lv.lvl.asks[0].when, HOL_APP_BEFORE_LEVEL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_presets),       cmocka_unit_test(test_question_line),
        cmocka_unit_test(test_app_said),
        cmocka_unit_test(test_app_ssq),       cmocka_unit_test(test_app_choice_time),
        cmocka_unit_test(test_app_ray),       cmocka_unit_test(test_study_placement),
        cmocka_unit_test(test_study_before),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
