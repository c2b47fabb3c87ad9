/* app_fixture.h - the fixture the app's core tests share (test_app.c,
 * test_screens.c, test_point.c, test_ask.c, test_finish.c,
 * test_conditions.c, test_audio.c; test_session_study.c takes its navigator
 * and tracked head): one navigator, an app on it, a tracked head's input
 * record, a step that must succeed.
 *
 * Contract
 * - Include it after <cmocka.h> (its functions assert) and
 *   core/hol_app.h; it includes <math.h>, <string.h>, core/hol_level.h
 *   and core/hol_nav.h.
 * - One {4,5} 3 x 3 navigator for the whole group, g_nav: made by setup,
 *   freed by teardown (cmocka_run_group_tests(tests, setup, teardown));
 *   a test may use it (hol_nav_find) but never frees it.
 * - make_app(): an app with a zero desc but for the shared navigator
 *   (hol_app_create must succeed); the test destroys it.
 * - app_head(t, col, row, yaw_deg, device, pressed): a focused input
 *   record at time t of a tracked head standing at cell (col, row)'s
 *   centre, 1.6 m up, looking level at yaw_deg (SPEC 1: 0 north, positive
 *   towards the west), from device (HOL_DEVICE_*; 0 none) with the
 *   buttons pressed; tracked_at(t, col, row) is the same looking north,
 *   with no device and nothing pressed.
 * - step(app, in): one hol_app_step that must succeed; the step's events.
 * - parse_level(text, L, e): hol_level_parse of a C string into L (zeroed
 *   first), its error in e.
 * - Every function is static inline: a file that calls only some pays
 *   nothing for the others and gets no warning.
 */
#ifndef HOL_TEST_APP_FIXTURE_H
#define HOL_TEST_APP_FIXTURE_H

#include <math.h>
#include <string.h>

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"

static hol_nav *g_nav;

static inline int setup(void **state)
{
    (void)state;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    return hol_nav_create(&nd, &g_nav) != HOL_OK;
}

static inline int teardown(void **state)
{
    (void)state;
    hol_nav_destroy(g_nav);
    g_nav = NULL;
    return 0;
}

static inline hol_app *make_app(void)
{
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = g_nav;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    return app;
}

static inline hol_input app_head(double t, int col, int row, double yaw_deg, uint32_t device,
                                 uint32_t pressed)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
    in.head.pos[0] = (float)col + 0.5f;
    in.head.pos[1] = 1.6f;
    in.head.pos[2] = (float)row + 0.5f;
    double h = yaw_deg * acos(-1.0) / 360;
    in.head.quat[1] = (float)sin(h);
    in.head.quat[3] = (float)cos(h);
    in.device = device;
    in.pressed = pressed;
    return in;
}

static inline hol_input tracked_at(double t, int col, int row)
{
    return app_head(t, col, row, 0, 0, 0);
}

static inline const hol_app_events *step(hol_app *app, hol_input in)
{
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    return hol_app_get_events(app);
}

static inline hol_err parse_level(const char *text, hol_app_level *L, hol_level_err *e)
{
    memset(L, 0, sizeof *L);
    return hol_level_parse(text, strlen(text), L, e);
}

#endif
