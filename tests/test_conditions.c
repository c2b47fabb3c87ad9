/* test_conditions.c - conditions that hold (issue 26): a study condition's
 * `set minimap` fixes the minimap during its levels (the composed level
 * says `fixed minimap`), the minimap key then moves nothing and the HUD
 * says "Minimap fixed in this study" for 3 s, unless the study says
 * `allow minimap-toggle`; practice levels and conditions without a minimap
 * line stay free. Every move of the minimap during play, and every refused
 * one, is a row of events.csv in the log folder (a sink that keeps only
 * flushed bytes, as in test_session.c), through the session, so a replay
 * writes the same rows.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_session.h"
#include "../core/hol_study.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"

#define MEM_TEXT_MAX (1 << 16)
#include "mem_sink.h" /* a sink in memory (test_session.c's) */

/* ---- the tests ---- */

static hol_study study;

/* A tracked head at cell (c, r) looking north, keys pressed. */
static hol_input head_at(double t, int c, int r, uint32_t pressed)
{
    return app_head(t, c, r, 0, HOL_DEVICE_KEYBOARD, pressed);
}

static const char *const g_file = "mode flag\nseed 5\nflag N\nminimap hud\n";

/* Level i of the study text, made from g_file. */
static void make_level(const char *text, int i, hol_level *out)
{
    hol_level_err e;
    int in_study;
    assert_int_equal(hol_study_parse(text, strlen(text), &study, &e), HOL_OK);
    assert_int_equal(hol_study_make_level(&study, i, 1, g_file, strlen(g_file), NULL, out, &e,
                                          &in_study),
                     HOL_OK);
}

static const char *const g_study = "study s\npractice p.lvl\nset cues none\n"
                                   "condition hand\nlevel a.lvl\nset minimap hand\n"
                                   "condition free\nlevel a.lvl\n";

/* The study fixes what its conditions set; allow minimap-toggle and
 * practice do not. */
static void test_study_fixes(void **state)
{
    (void)state;
    static hol_level L;
    make_level(g_study, 0, &L); /* practice: the file as it is */
    assert_int_equal(L.lvl.minimap_fixed, 0);
    make_level(g_study, 1, &L); /* hand: set minimap */
    assert_int_equal(L.lvl.minimap, HOL_MINIMAP_HAND);
    assert_int_equal(L.lvl.minimap_fixed, 1);
    assert_non_null(strstr(L.text, "\nminimap hand\nfixed minimap\n"));
    make_level(g_study, 2, &L); /* free: no minimap line of its own */
    assert_int_equal(L.lvl.minimap_fixed, 0);
    assert_int_equal(L.lvl.cues, 0); /* the study's cues: set, and no key changes them */
    char allow[512];
    snprintf(allow, sizeof allow, "allow minimap-toggle\n%s", g_study);
    make_level(allow, 1, &L);
    assert_int_equal(L.lvl.minimap, HOL_MINIMAP_HAND);
    assert_int_equal(L.lvl.minimap_fixed, 0);
    assert_null(strstr(L.text, "fixed"));
    /* the level line itself */
    hol_app_level A;
    hol_level_err e;
    const char *t = "mode explore\nfixed minimap\n";
    assert_int_equal(hol_level_parse(t, strlen(t), &A, &e), HOL_OK);
    assert_int_equal(A.minimap_fixed, 1);
    t = "mode explore\nfixed cues\n";
    assert_int_equal(hol_level_parse(t, strlen(t), &A, &e), HOL_EPARSE);
    assert_int_equal(e.line, 2);
}

/* The app: M on a fixed level moves nothing and says so for 3 s. */
static void test_app_refuses(void **state)
{
    (void)state;
    for (int fixed = 0; fixed <= 1; fixed++) {
        hol_app *app = make_app();
        hol_app_level L;
        memset(&L, 0, sizeof L);
        L.mode = HOL_APP_EXPLORE;
        L.minimap = HOL_MINIMAP_HAND;
        L.minimap_fixed = fixed;
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        const hol_app_view *v = hol_app_get_view(app);
        const hol_app_events *ev = hol_app_get_events(app);
        hol_input in = head_at(0, 1, 1, 0);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        in = head_at(1, 1, 1, HOL_BTN_MINIMAP);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        assert_int_equal(v->map.place, fixed ? HOL_MINIMAP_HAND : HOL_MINIMAP_OFF);
        assert_int_equal(ev->minimap_moved, !fixed);
        assert_int_equal(ev->minimap_refused, fixed);
        assert_string_equal(v->hud.feedback, fixed ? "Minimap fixed in this study" : "");
        int shown = 0;
        for (int i = 0; i < v->hud.nlines; i++)
            shown |= !strcmp(v->hud.lines[i], "Minimap fixed in this study");
        assert_int_equal(shown, fixed);
        in = head_at(3.9, 1, 1, 0);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        assert_int_equal(ev->minimap_refused, 0);
        assert_string_equal(v->hud.feedback, fixed ? "Minimap fixed in this study" : "");
        in = head_at(4.1, 1, 1, 0);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        assert_string_equal(v->hud.feedback, "");
        hol_app_destroy(app);
    }
}

/* Through a session with logs: practice (free) then the hand condition
 * (fixed): events.csv holds one row per move and per refusal. */
static void test_session_events(void **state)
{
    (void)state;
    static hol_level lv[2];
    static mem_sink log;
    make_level(g_study, 0, &lv[0]);
    make_level(g_study, 1, &lv[1]);
    mem_init(&log);
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = lv;
    d.nlevels = 2;
    d.app.nav = g_nav;
    d.log = &log.sink;
    snprintf(d.meta.session, sizeof d.meta.session, "S1");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    snprintf(d.meta.participant, sizeof d.meta.participant, "P1");
    snprintf(d.meta.study, sizeof d.meta.study, "s");
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    const hol_app_view *v = hol_app_get_view(hol_session_app(s));
    int over = 0;
    static const struct {
        double t;
        int c, r;
        uint32_t pressed;
    } frames[] = {
        {0, 1, 1, 0},
        {0.5, 1, 1, HOL_BTN_MINIMAP},   /* practice: hud -> hand */
        {0.75, 1, 1, HOL_BTN_MINIMAP},  /* hand -> off */
        {1.0, 1, 0, 0},                 /* onto the flag */
        {1.25, 1, 0, HOL_BTN_CONFIRM},  /* the hand condition */
        {1.5, 1, 0, 0},
        {2.0, 1, 0, HOL_BTN_MINIMAP},   /* refused */
    };
    for (size_t i = 0; i < sizeof frames / sizeof frames[0]; i++) {
        hol_input in = head_at(frames[i].t, frames[i].c, frames[i].r, frames[i].pressed);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    assert_int_equal(hol_session_level_index(s), 1);
    assert_int_equal(v->map.place, HOL_MINIMAP_HAND);
    assert_string_equal(v->hud.feedback, "Minimap fixed in this study");
    /* written as they happen, before the session ends */
    const char *ev = mem_text(&log, "events.csv");
    assert_non_null(ev);
    assert_string_equal(ev, HOL_SESSION_EVENT_COLUMNS "\n"
                            "S1,1,practice,0.5000,minimap,hand\n"
                            "S1,1,practice,0.7500,minimap,off\n"
                            "S1,2,hand,0.5000,minimap-fixed,hand\n");
    assert_int_equal(log.s[mem_find(&log, "events.csv") - log.s].kept,
                     log.s[mem_find(&log, "events.csv") - log.s].len);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    /* a folder holding events.csv holds logs: refused without append */
    assert_true(hol_session_is_log_name("events.csv"));
    d.append = 0;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EARG);
    /* appended to: no second header */
    d.append = 1;
    snprintf(d.meta.session, sizeof d.meta.session, "S2");
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    hol_input in = head_at(10, 1, 1, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    in = head_at(10.5, 1, 1, HOL_BTN_MINIMAP);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    ev = mem_text(&log, "events.csv");
    assert_non_null(strstr(ev, "minimap-fixed,hand\nS2,3,practice,0.5000,minimap,hand\n"));
    const char *second = strstr(ev + 1, "session,attempt");
    assert_null(second);
    mem_free(&log);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_study_fixes),
        cmocka_unit_test(test_app_refuses),
        cmocka_unit_test(test_session_events),
    };
    return cmocka_run_group_tests_name("conditions", tests, setup, teardown);
}
