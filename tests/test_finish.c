/* test_finish.c - the last level says "finish" (issue 26): its end screen's
 * prompt names confirm as "finish", not "next level", on every device's
 * prompt (core/hol_prompt.h), because confirm there ends the session; every
 * other level still says "next level". Through the app (hol_app_level.last)
 * and through the session, which sets it on its last level only (a campaign
 * of two levels: the first says next level, the second finish, and confirm
 * on it ends the session).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_session.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"

/* A tracked head standing at cell (c, r)'s centre at time t. */
static hol_input head_at(double t, int c, int r, uint32_t device, uint32_t pressed)
{
    return app_head(t, c, r, 0, device, pressed);
}

/* The end screen's prompt of a flag level one step north, for a device. */
static void end_prompt(uint32_t device, int last, char *out)
{
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 5;
    L.cues = HOL_CUE_ALL;
    L.last = last;
    assert_int_equal(hol_tile_parse("N", -1, &L.flag), HOL_OK);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    hol_input in = head_at(0, 1, 1, device, 0);
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    in = head_at(0.25, 1, 0, device, 0);
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_DONE);
    strcpy(out, v->hud.hint);
    hol_app_destroy(app);
}

static void test_every_device(void **state)
{
    (void)state;
    for (uint32_t dev = 0; dev < HOL_DEVICE_COUNT; dev++) {
        char next[HOL_APP_TEXT_MAX], fin[HOL_APP_TEXT_MAX], want[HOL_APP_TEXT_MAX + 16];
        end_prompt(dev, 0, next);
        end_prompt(dev, 1, fin);
        const char *at = strstr(next, "next level");
        if (!at)
            fail_msg("device %u: '%s' has no 'next level'", (unsigned)dev, next);
        assert_null(strstr(fin, "next level"));
        /* the same prompt with the one word changed */
        snprintf(want, sizeof want, "%.*sfinish%s", (int)(at - next), next,
                 at + strlen("next level"));
        assert_string_equal(fin, want);
    }
    char k[HOL_APP_TEXT_MAX];
    end_prompt(HOL_DEVICE_KEYBOARD, 1, k);
    assert_string_equal(k, "ENTER: finish, R: again");
}

/* Two levels in a session: the first's end says next level, the second's
 * finish, and confirm there ends the session. */
static void test_session_last(void **state)
{
    (void)state;
    static hol_level lv[2];
    const char *txt = "mode flag\nseed 5\nflag N\n";
    assert_int_equal(hol_level_make("a", 1, txt, strlen(txt), &lv[0], NULL), HOL_OK);
    txt = "mode flag\nseed 6\nflag S\n";
    assert_int_equal(hol_level_make("b", 1, txt, strlen(txt), &lv[1], NULL), HOL_OK);
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = lv;
    d.nlevels = 2;
    d.app.nav = g_nav;
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    const hol_app_view *v = hol_app_get_view(hol_session_app(s));
    int over = 0;
    uint32_t kb = HOL_DEVICE_KEYBOARD;
    hol_input in = head_at(0, 1, 1, kb, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    in = head_at(0.25, 1, 0, kb, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_string_equal(v->hud.hint, "ENTER: next level, R: again");
    in = head_at(0.5, 1, 0, kb, HOL_BTN_CONFIRM);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(hol_session_level_index(s), 1);
    assert_int_equal(over, 0);
    /* a level start places the room round the head (a recentre): one
     * metre south from where the head stands is one step south */
    in = head_at(0.6, 1, 0, kb, 0); /* the new level's first frame */
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    in = head_at(0.75, 1, 1, kb, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_string_equal(v->hud.hint, "ENTER: finish, R: again");
    /* restarting the last level keeps it the last */
    in = head_at(1.0, 1, 1, kb, HOL_BTN_RESTART);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    in = head_at(1.1, 1, 1, kb, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(v->state, HOL_APP_PLAYING);
    in = head_at(1.25, 1, 2, kb, 0);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_string_equal(v->hud.hint, "ENTER: finish, R: again");
    in = head_at(1.5, 1, 2, kb, HOL_BTN_CONFIRM);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(over, 1);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_device),
        cmocka_unit_test(test_session_last),
    };
    return cmocka_run_group_tests_name("finish", tests, setup, teardown);
}
