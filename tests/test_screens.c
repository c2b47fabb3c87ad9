/* test_screens.c - the session flow's screens (issue 26 item 3): the level
 * lines `instructions TEXT` and `closing TEXT` (parsed whole, checked:
 * printable ASCII, at most HOL_APP_SCREEN_LINES lines when wrapped), the
 * wrap itself against a plain model of it, the app step (the instructions
 * before the level begins: no attempt, no clock, no step until confirm;
 * not again on a restart; the closing screen after the last level's end
 * screen, whose confirm ends), and a study's lines placed on the right
 * levels (the first of the practice and of a condition, the participant's
 * last).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_face.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_study.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"

static void test_level_lines(void **state)
{
    (void)state;
    hol_app_level L;
    hol_level_err e;
    assert_int_equal(parse_level("mode flag\nflag N\ninstructions  Walk to the flag, then   wait.  \n"
                           "closing Thanks! # a comment\n",
                           &L, &e),
                     HOL_OK);
    assert_string_equal(L.instructions, "Walk to the flag, then   wait.");
    assert_string_equal(L.closing, "Thanks!");
    assert_int_equal(parse_level("mode flag\nflag N\n", &L, &e), HOL_OK);
    assert_string_equal(L.instructions, "");
    assert_string_equal(L.closing, "");
    assert_int_equal(parse_level("mode flag\nflag N\ninstructions\n", &L, &e), HOL_EPARSE);
    /* Latin-1 letters in UTF-8 (the face's); nothing else */
    assert_int_equal(parse_level("mode flag\nflag N\ninstructions Gr\xc3\xbc\xc3\x9f dich, caf\xc3\xa9\n",
                                 &L, &e),
                     HOL_OK);
    assert_string_equal(L.instructions, "Gr\xc3\xbc\xc3\x9f dich, caf\xc3\xa9");
    assert_int_equal(parse_level("mode flag\nflag N\ninstructions 5 \xe2\x82\xac\n", &L, &e), HOL_EPARSE);
    assert_int_equal(e.line, 3);
    assert_non_null(strstr(e.msg, "printable ASCII"));
    assert_non_null(strstr(e.msg, "not U+20AC"));
    static const char *const bad[] = {"caf\xe9", "a\xc2\x85\x62" /* a, U+0085, b */, "\xc3", "a\tb", "\xc0\xa9",
                                      "\xf0\x9f\x98\x80"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char t[64];
        snprintf(t, sizeof t, "mode flag\nflag N\nclosing %s\n", bad[i]);
        assert_int_equal(parse_level(t, &L, &e), HOL_EPARSE);
        assert_non_null(strstr(e.msg, "Latin-1"));
    }
    /* a question's quoted fields likewise */
    assert_int_equal(parse_level("mode flag\nflag N\nquestion q1 choice \"Gef\xc3\xa4llt es dir?\" "
                                 "\"Ja\" \"Nein, \xc3\xbc" "berhaupt nicht\"\nask a level q1\n",
                                 &L, &e),
                     HOL_OK);
    assert_string_equal(L.questions[0].choices[1], "Nein, \xc3\xbc" "berhaupt nicht");
    assert_int_equal(parse_level("mode flag\nflag N\nquestion q1 choice \"caf\xe9\" \"a\" \"b\"\n", &L, &e),
                     HOL_EPARSE);
    /* wrapped by characters, never inside one, and a line within its bytes */
    char w[8][HOL_APP_TEXT_MAX], t[400] = "";
    for (int i = 0; i < 30; i++)
        strcat(t, "\xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f ");
    /* five words a line: 24 characters, 44 bytes (a sixth: 53) */
    assert_int_equal(hol_app_wrap(t, HOL_APP_SCREEN_COLS, w, 8), 6);
    for (int i = 0; i < 6; i++) {
        assert_true(strlen(w[i]) <= HOL_APP_TEXT_MAX - 1);
        int missing = 0;
        hol_face_units(w[i], strlen(w[i]), &missing);
        assert_int_equal(missing, 0);
    }
    assert_string_equal(w[0], "\xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f \xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f \xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f \xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f \xc3\xa4\xc3\xb6\xc3\xbc\xc3\x9f");
    char one[HOL_APP_SCREEN_COLS * 2 + 1] = ""; /* one word of 46 umlauts: cut at 23 */
    for (int i = 0; i < HOL_APP_SCREEN_COLS; i++)
        strcat(one, "\xc3\xbc");
    assert_int_equal(hol_app_wrap(one, HOL_APP_SCREEN_COLS, w, 8), 2);
    assert_int_equal(strlen(w[0]), 46);
    assert_int_equal(parse_level("mode flag\nflag N\ninstructions a\ninstructions b\n", &L, &e),
                     HOL_EARG);
    /* six lines of 46 fit; a seventh is refused, naming the count */
    char text[1024] = "mode flag\nflag N\ninstructions ";
    for (int i = 0; i < 6; i++)
        strcat(text, "aaaaaaaaaa bbbbbbbbbb cccccccccc dddddddddd ee ");
    strcat(text, "\n");
    assert_int_equal(parse_level(text, &L, &e), HOL_OK);
    assert_int_equal(hol_app_wrap(L.instructions, HOL_APP_SCREEN_COLS, NULL, 0), 6);
    text[strlen(text) - 1] = 0;
    strcat(text, "x\n");
    assert_int_equal(parse_level(text, &L, &e), HOL_ERANGE);
    assert_non_null(strstr(e.msg, "wraps into 7 lines"));
    assert_int_equal(hol_level_line_check("closing Bye.", 12, &e), HOL_OK);
}

/* The wrap: no line longer than cols, no word cut that fits a line, and
 * the words in order. */
static void test_wrap(void **state)
{
    (void)state;
    char out[8][HOL_APP_TEXT_MAX];
    int n = hol_app_wrap("one two three four five six", 9, out, 8);
    assert_int_equal(n, 4);
    assert_string_equal(out[0], "one two");
    assert_string_equal(out[1], "three");
    assert_string_equal(out[2], "four five");
    assert_string_equal(out[3], "six");
    n = hol_app_wrap("  abcdefghijkl   x ", 5, out, 8);
    assert_int_equal(n, 4);
    assert_string_equal(out[0], "abcde");
    assert_string_equal(out[1], "fghij");
    assert_string_equal(out[2], "kl");
    assert_string_equal(out[3], "x");
    n = hol_app_wrap("kl  x", 5, out, 8); /* spaces inside a line stay */
    assert_int_equal(n, 1);
    assert_string_equal(out[0], "kl  x");
    assert_int_equal(hol_app_wrap("", 10, out, 8), 0);
    assert_int_equal(hol_app_wrap("a b c d e f g h i j", 1, out, 3), 10); /* counts beyond max */
    assert_string_equal(out[2], "c");
}

/* A tracked head at cell (c, r) looking north, keys pressed. */
static hol_input head_at(double t, int c, int r, uint32_t pressed)
{
    return app_head(t, c, r, 0, HOL_DEVICE_KEYBOARD, pressed);
}

static void test_app_instructions(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 3;
    L.cues = HOL_CUE_ALL;
    assert_int_equal(hol_tile_parse("N", -1, &L.flag), HOL_OK);
    snprintf(L.instructions, sizeof L.instructions,
             "Find the flag. It stands one step to the north of where you begin.");
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_SCREEN);
    const hol_app_events *ev = step(app, head_at(0, 1, 1, 0));
    assert_int_equal(ev->level_started, 0);
    assert_int_equal(v->hud.screen, HOL_APP_SCREEN_INSTRUCTIONS);
    assert_int_equal(v->hud.nlines, 2);
    assert_string_equal(v->hud.lines[0], "Find the flag. It stands one step to the north");
    assert_string_equal(v->hud.lines[1], "of where you begin.");
    assert_string_equal(v->hud.hint, "ENTER: begin, ESC: quit");
    /* walking onto the flag now is no step: the level has not begun */
    ev = step(app, head_at(1, 1, 0, 0));
    assert_int_equal(ev->nsteps, 0);
    assert_int_equal(v->state, HOL_APP_SCREEN);
    /* no minimap, no objective, no flag before the clock starts */
    assert_int_equal(v->map.place, HOL_MINIMAP_OFF);
    assert_int_equal(v->map.nobjectives, 0);
    assert_int_equal(v->nobjects, 0);
    ev = step(app, head_at(2, 1, 1, HOL_BTN_CONFIRM));
    assert_int_equal(ev->level_started, 0);
    assert_int_equal(ev->next_level, 0);
    /* then the ready screen: the clock waits for its confirm */
    assert_int_equal(v->state, HOL_APP_SCREEN);
    assert_int_equal(v->hud.screen, HOL_APP_SCREEN_READY);
    assert_string_equal(v->hud.lines[0], HOL_APP_READY_TEXT);
    assert_int_equal(v->map.place, HOL_MINIMAP_OFF);
    ev = step(app, head_at(2.5, 1, 1, HOL_BTN_CONFIRM));
    assert_int_equal(ev->level_started, 0);
    ev = step(app, head_at(3, 1, 1, 0)); /* the level begins here, its clock at 0 */
    assert_int_equal(ev->level_started, 1);
    assert_int_equal(v->state, HOL_APP_PLAYING);
    assert_int_equal(v->hud.screen, 0);
    assert_true(v->hud.elapsed_s == 0);
    assert_int_equal(v->map.place, HOL_MINIMAP_HUD);
    assert_int_equal(v->map.nobjectives, 1);
    assert_int_equal(v->nobjects, 1);
    ev = step(app, head_at(3.5, 1, 0, 0));
    assert_int_equal(ev->nsteps, 1);
    assert_int_equal(ev->level_ended, HOL_APP_END_DONE);
    assert_true(ev->summary.time_s > 0.49 && ev->summary.time_s < 0.51);
    /* a restart plays again without the instructions */
    ev = step(app, head_at(4, 1, 1, HOL_BTN_RESTART));
    assert_int_equal(ev->level_started, 1);
    assert_int_equal(v->state, HOL_APP_PLAYING);
    /* quit on the instructions quits, with no attempt */
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    ev = step(app, head_at(5, 1, 1, HOL_BTN_QUIT));
    assert_int_equal(v->state, HOL_APP_QUIT);
    assert_int_equal(ev->level_ended, HOL_APP_END_NONE);
    assert_int_equal(ev->level_started, 0);
    hol_app_destroy(app);
}

/* The menu's hint (a headset's first 10 s of play) waits for the
 * instructions: read for 20 s, they do not use it up. */
static void test_app_instructions_menu_hint(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 3;
    L.cues = HOL_CUE_ALL;
    assert_int_equal(hol_tile_parse("N", -1, &L.flag), HOL_OK);
    snprintf(L.instructions, sizeof L.instructions, "Find the flag.");
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    hol_input in = head_at(0, 1, 1, 0);
    in.device = HOL_DEVICE_XR_TOUCH;
    step(app, in);
    assert_int_equal(v->state, HOL_APP_SCREEN);
    assert_null(strstr(v->hud.hint, "Y: menu"));
    in = head_at(20, 1, 1, HOL_BTN_CONFIRM);
    in.device = HOL_DEVICE_XR_TOUCH;
    step(app, in);
    in = head_at(20.5, 1, 1, HOL_BTN_CONFIRM); /* the ready screen */
    in.device = HOL_DEVICE_XR_TOUCH;
    step(app, in);
    in = head_at(21, 1, 1, 0);
    in.device = HOL_DEVICE_XR_TOUCH;
    step(app, in);
    assert_int_equal(v->state, HOL_APP_PLAYING);
    assert_non_null(strstr(v->hud.hint, "Y: menu"));
    in.time_s = 21 + HOL_APP_MENU_HINT_S - 0.1;
    step(app, in);
    assert_non_null(strstr(v->hud.hint, "Y: menu"));
    in.time_s = 21 + HOL_APP_MENU_HINT_S;
    step(app, in);
    assert_null(strstr(v->hud.hint, "Y: menu"));
    hol_app_destroy(app);
}

static void test_app_closing(void **state)
{
    (void)state;
    for (int last = 0; last < 2; last++) {
        hol_app *app = make_app();
        hol_app_level L;
        memset(&L, 0, sizeof L);
        L.mode = HOL_APP_FLAG;
        L.seed = 3;
        L.cues = HOL_CUE_ALL;
        L.last = last;
        assert_int_equal(hol_tile_parse("N", -1, &L.flag), HOL_OK);
        snprintf(L.closing, sizeof L.closing, "Thank you.");
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        const hol_app_view *v = hol_app_get_view(app);
        step(app, head_at(0, 1, 1, 0));
        step(app, head_at(0.5, 1, 0, 0));
        assert_int_equal(v->state, HOL_APP_DONE);
        const hol_app_events *ev = step(app, head_at(1, 1, 0, HOL_BTN_CONFIRM));
        if (!last) { /* not the last level: the closing waits */
            assert_int_equal(ev->next_level, 1);
            hol_app_destroy(app);
            continue;
        }
        assert_int_equal(ev->next_level, 0);
        assert_int_equal(v->state, HOL_APP_SCREEN);
        assert_int_equal(v->hud.screen, HOL_APP_SCREEN_CLOSING);
        assert_int_equal(v->hud.nlines, 1);
        assert_string_equal(v->hud.lines[0], "Thank you.");
        assert_string_equal(v->hud.hint, "ENTER: finish");
        ev = step(app, head_at(1.5, 1, 0, HOL_BTN_RESTART)); /* nothing else acts */
        assert_int_equal(ev->level_started, 0);
        assert_int_equal(ev->next_level, 0);
        ev = step(app, head_at(2, 1, 0, HOL_BTN_CONFIRM));
        assert_int_equal(ev->next_level, 1);
        hol_app_destroy(app);
    }
}

static hol_study g_study;

/* Level i of participant 1's session (fixed order) made from a flag
 * level's text; its instructions and closing. */
static void made(int i, int position, char *instr, char *closing)
{
    static const char file[] = "mode flag\nflag N\ninstructions the file's own\n";
    hol_level lv;
    hol_level_err e;
    int in_study;
    assert_int_equal(hol_study_make_level(&g_study, i, position, file, sizeof file - 1, NULL, &lv,
                                          &e, &in_study),
                     HOL_OK);
    strcpy(instr, lv.lvl.instructions);
    strcpy(closing, lv.lvl.closing);
}

static void test_study_lines(void **state)
{
    (void)state;
    static const char text[] = "study s\ncounterbalance fixed\npractice p.lvl\npractice p.lvl\n"
                               "instructions First some practice.\n"
                               "closing All done, thank you.\n"
                               "condition a\ninstructions Condition A now.\nlevel x.lvl\n"
                               "level x.lvl\n"
                               "condition b\nlevel x.lvl\nlevel x.lvl\n";
    hol_level_err e;
    assert_int_equal(hol_study_parse(text, sizeof text - 1, &g_study, &e), HOL_OK);
    char in[HOL_APP_SCREEN_TEXT], cl[HOL_APP_SCREEN_TEXT];
    made(0, 0, in, cl);
    assert_string_equal(in, "First some practice.");
    assert_string_equal(cl, "");
    made(1, 0, in, cl); /* the second practice level: the file as it is */
    assert_string_equal(in, "the file's own");
    made(2, 1, in, cl);
    assert_string_equal(in, "Condition A now.");
    assert_string_equal(cl, "");
    made(3, 1, in, cl);
    assert_string_equal(in, "the file's own");
    made(4, 2, in, cl); /* b has no instructions: its file's own */
    assert_string_equal(in, "the file's own");
    assert_string_equal(cl, "");
    made(5, 2, in, cl); /* the participant's last level */
    assert_string_equal(cl, "All done, thank you.");
    made(3, 2, in, cl); /* a's last, played last (another order) */
    assert_string_equal(cl, "All done, thank you.");
    /* refusals */
    static const char *const bad[][2] = {
        {"study s\ninstructions a\ninstructions b\ncondition a\nset mode explore\n",
         "line 3: a second 'instructions' line for the practice (line 2)"},
        {"study s\ncondition a\nset mode explore\ninstructions a\ninstructions b\n",
         "line 5: a second 'instructions' line in this condition (line 4)"},
        {"study s\ncondition a\nset mode explore\nclosing bye\n",
         "line 4: 'closing' comes before the first condition"},
        {"study s\nclosing\ncondition a\nset mode explore\n", "line 2: "},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        hol_err r = hol_study_parse(bad[k][0], strlen(bad[k][0]), &g_study, &e);
        assert_int_not_equal(r, HOL_OK);
        char msg[256];
        hol_level_err_format(&e, 1, msg, sizeof msg);
        if (strncmp(msg, bad[k][1], strlen(bad[k][1]))) {
            print_error("%zu: got '%s', want '%s'\n", k, msg, bad[k][1]);
            fail();
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_level_lines),
        cmocka_unit_test(test_wrap),
        cmocka_unit_test(test_app_instructions),
        cmocka_unit_test(test_app_instructions_menu_hint),
        cmocka_unit_test(test_app_closing),
        cmocka_unit_test(test_study_lines),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
