/* test_tutorial.c - the tutorial's lessons as issue 35 asks (core/hol_app.h,
 * core/hol_app_tutorial.c): each lesson begins facing what it names (its
 * marker or flag on the side the look is nearest to, lesson 2's tree the
 * cell's corner nearest the look, a pancake view turned to it); one idea
 * at a time (a lesson's feedback alone on the HUD, no objective, no
 * prompt); M is not taught where a study holds the minimap; a row per
 * lesson (hol_app_events.lessons). With desc.flow_v4 (a recording of
 * version 1 to 4 replayed) the lessons are as they were.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_str.h"
#include "../core/hol_app.h"
#include "../core/hol_bearing.h"
#include "../core/hol_nav.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"

static hol_tile tile(const char *a)
{
    hol_tile t;
    assert_int_equal(hol_tile_parse(a, -1, &t), HOL_OK);
    return t;
}

static hol_app_level tutorial(unsigned stages)
{
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_TUTORIAL;
    L.seed = 8;
    L.cues = HOL_CUE_ALL;
    L.stages = stages;
    return L;
}

static hol_app *app_v4(int flow_v4)
{
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = g_nav;
    d.flow_v4 = flow_v4;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    return app;
}

/* The angle, 0..180, between a yaw (SPEC 1) and a bearing. */
static double off(double yaw, double bearing)
{
    double d = fabs(fmod(-yaw - bearing, 360.0));
    d = d > 180 ? 360 - d : d;
    return d;
}

/* Lesson 1 for a head looking north, west, south or east: its marker is
 * the tile one step that way (before: always north, behind a head looking
 * south); with desc.flow_v4 north. */
static void test_lesson1_where_the_head_looks(void **state)
{
    (void)state;
    static const char *const want[4] = {"N", "W", "S", "E"};
    for (int v4 = 0; v4 < 2; v4++)
        for (int k = 0; k < 4; k++) {
            hol_app *app = app_v4(v4);
            hol_app_level L = tutorial(0);
            assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
            step(app, app_head(0, 1, 1, 90.0 * k, 0, 0));
            const hol_app_view *v = hol_app_get_view(app);
            assert_int_equal(v->map.nobjectives, 1);
            assert_true(hol_tile_eq(v->map.objectives[0], tile(v4 ? "N" : want[k])));
            assert_int_equal(v->hud.stage_optimum, 1);
            hol_app_destroy(app);
        }
}

/* Lesson 2 from the north row: of the cell's two inner corners (both
 * behind a head looking north) the one nearest the look is marked: east
 * for a head looking east, west for one looking west. */
static void test_lesson2_tree_in_view(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        hol_app *app = make_app();
        hol_app_level L = tutorial(1u << 1 | 1u << 2);
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        step(app, app_head(0, 1, 0, k ? 270 : 90, 0, 0)); /* east, west */
        const hol_app_view *v = hol_app_get_view(app);
        assert_int_equal(v->tree_marked, 1);
        assert_int_equal(v->tree_vertex[0], k ? 2 : 1);
        assert_int_equal(v->tree_vertex[1], 1);
        assert_int_equal(v->hud.stage_optimum, 4);
        hol_app_destroy(app);
    }
}

/* Pancake frames at 60 Hz from time *t, forward (1) or standing (0). */
static void pancake(hol_app *app, double *t, int frames, float fwd)
{
    for (int f = 0; f < frames; f++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = *t;
        in.flags = HOL_INPUT_FOCUSED;
        in.move[1] = fwd;
        step(app, in);
        *t += 1 / 60.0;
    }
}

/* A pancake player (no head to turn) faces each lesson's thing when it
 * begins: lesson 2's tree after the first step north (behind the player
 * before, by the north hedge), lesson 3's marker and lesson 4's flag in a
 * level that begins with them. */
static void test_pancake_faces_each_lesson(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L = tutorial(0);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    double t = 0;
    for (int f = 0; f < 60 && v->hud.stage == 0; f++)
        pancake(app, &t, 1, 1); /* forward to the step north */
    assert_int_equal(v->hud.stage, 1);
    assert_int_equal(v->user.row, 0);
    pancake(app, &t, 1, 0);
    hol_room u = v->user;
    double b = hol_bearing_of_vector(v->tree_vertex[0] - (u.col + 0.5),
                                     (u.row + 0.5) - v->tree_vertex[1]);
        assert_true(off(v->yaw_deg, b) < 0.01);
    assert_true(off(v->yaw_deg, 0) > 90); /* it was behind */
    hol_app_destroy(app);
    for (int k = 2; k < 4; k++) {
        app = make_app();
        L = tutorial(1u << k);
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        v = hol_app_get_view(app);
        t = 0;
        pancake(app, &t, 2, 0);
        assert_int_equal(v->map.nobjectives, 1);
        assert_int_equal(hol_bearing_true(v->user.tile, v->user.orient, v->map.objectives[0], &b),
                         HOL_OK);
        assert_true(off(v->yaw_deg, b) < 0.01);
        hol_app_destroy(app);
    }
}

/* Walk (room directions) through tracked heads looking north from time
 * *t; the lessons done on the way appended to rows (at most 4). */
static void walk(hol_app *app, const uint8_t *dirs, int n, double *t, hol_app_lesson *rows,
                 int *nrows)
{
    const hol_app_view *v = hol_app_get_view(app);
    int col = v->user.col, row = v->user.row;
    for (int i = 0; i < n; i++) {
        int dc, dr;
        hol_dir_delta(dirs[i], &dc, &dr);
        col += dc, row += dr;
        *t += 0.25;
        const hol_app_events *ev = step(app, app_head(*t, col, row, 0, HOL_DEVICE_KEYBOARD, 0));
        for (int k = 0; k < ev->nlessons && *nrows < 4; k++)
            rows[(*nrows)++] = ev->lessons[k];
    }
}

/* One idea at a time: a lesson's feedback alone (lesson 2's with the
 * rings' note), no objective and no prompt, for its 6 s; then the next
 * lesson's objective and prompt (lesson 3's M). One row per lesson: its
 * number, start, steps and optimum. */
static void test_one_idea_and_a_row_per_lesson(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L = tutorial(0);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    hol_app_lesson rows[4];
    int nrows = 0;
    double t = 0;
    step(app, app_head(t, 1, 1, 0, HOL_DEVICE_KEYBOARD, 0));
    uint8_t north = HOL_DIR_N;
    walk(app, &north, 1, &t, rows, &nrows);
    assert_int_equal(v->hud.nlines, 1);
    assert_string_equal(v->hud.lines[0], "Well done: one step, one new tile");
    uint8_t loop[4];
    int east = v->tree_vertex[0] > v->user.col;
    loop[0] = east ? HOL_DIR_E : HOL_DIR_W;
    loop[1] = HOL_DIR_S, loop[2] = (uint8_t)((loop[0] + 2) % 4), loop[3] = HOL_DIR_N;
    walk(app, loop, 4, &t, rows, &nrows);
    assert_int_equal(v->hud.stage, 2);
    assert_int_equal(v->hud.nlines, 2);
    assert_string_equal(v->hud.lines[1], hol_str(HOL_LANG_EN, HOL_S_RINGS));
    assert_string_equal(v->hud.hint, "");
    t += 6.1;
    step(app, app_head(t, v->user.col, v->user.row, 0, HOL_DEVICE_KEYBOARD, 0));
    assert_true(strstr(v->hud.lines[0], "3/4") != NULL);
    assert_true(strstr(v->hud.hint, "map on the HUD") != NULL);
    for (int k = 2; k < 4; k++) {
        uint8_t nav[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        hol_room here = v->user;
        assert_int_equal(hol_nav_find(g_nav, &here, v->map.objectives[0], 0, nav, sizeof nav,
                                      &res), HOL_OK);
        walk(app, nav, res.len, &t, rows, &nrows);
    }
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_int_equal(nrows, 4);
    int want_steps[4] = {1, 4, rows[2].optimum, rows[3].optimum};
    for (int k = 0; k < 4; k++) {
        assert_int_equal(rows[k].lesson, k + 1);
        assert_int_equal(rows[k].steps, want_steps[k]);
        assert_int_equal(rows[k].optimum, want_steps[k]);
        assert_true(rows[k].t > rows[k].started);
        assert_true(k == 0 || fabs(rows[k].started - rows[k - 1].t) < 1e-9);
    }
    assert_true(rows[0].started == 0);
    hol_app_destroy(app);
}

/* Lesson 3 where a study holds the minimap: M is not taught (no prompt);
 * held off, the objective does not send the player to the map. */
static void test_held_map_not_taught(void **state)
{
    (void)state;
    for (int held = 0; held < 3; held++) {
        hol_app *app = make_app();
        hol_app_level L = tutorial(1u << 2);
        L.minimap_fixed = held > 0;
        L.minimap = held == 2 ? HOL_MINIMAP_OFF : HOL_MINIMAP_HUD;
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        step(app, app_head(0, 1, 1, 0, HOL_DEVICE_KEYBOARD, 0));
        const hol_app_view *v = hol_app_get_view(app);
        assert_int_equal(v->hud.stage, 2);
        if (held)
            assert_null(strstr(v->hud.hint, "map"));
        else
            assert_non_null(strstr(v->hud.hint, "map on the HUD"));
        assert_string_equal(v->hud.objective, held == 2 ? "3/4 Reach the marker"
                                                        : "3/4 Use the map: reach the marker");
        hol_app_destroy(app);
    }
}

/* Lesson 2's end where a study holds the map off: its feedback without
 * the rings' line (no map shows them); with the map, the line. */
static void test_held_off_map_no_rings_line(void **state)
{
    (void)state;
    for (int held = 0; held < 2; held++) {
        hol_app *app = make_app();
        hol_app_level L = tutorial(0);
        L.minimap_fixed = held;
        L.minimap = held ? HOL_MINIMAP_OFF : HOL_MINIMAP_HUD;
        assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
        const hol_app_view *v = hol_app_get_view(app);
        hol_app_lesson rows[4];
        int nrows = 0;
        double t = 0;
        step(app, app_head(t, 1, 1, 0, HOL_DEVICE_KEYBOARD, 0));
        uint8_t north = HOL_DIR_N;
        walk(app, &north, 1, &t, rows, &nrows);
        uint8_t loop[4];
        int east = v->tree_vertex[0] > v->user.col;
        loop[0] = east ? HOL_DIR_E : HOL_DIR_W;
        loop[1] = HOL_DIR_S, loop[2] = (uint8_t)((loop[0] + 2) % 4), loop[3] = HOL_DIR_N;
        walk(app, loop, 4, &t, rows, &nrows);
        assert_int_equal(v->hud.stage, 2);
        assert_int_equal(v->hud.nlines, held ? 1 : 2);
        assert_string_equal(v->hud.note, held ? "" : hol_str(HOL_LANG_EN, HOL_S_RINGS));
        for (int k = 0; k < v->hud.nlines && held; k++)
            assert_null(strstr(v->hud.lines[k], "Rings"));
        hol_app_destroy(app);
    }
}

/* desc.flow_v4: the lessons as before: the feedback over the next
 * objective, no rows, a pancake view not turned. */
static void test_flow_v4(void **state)
{
    (void)state;
    hol_app *app = app_v4(1);
    hol_app_level L = tutorial(0);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    double t = 0;
    pancake(app, &t, 30, 1);
    const hol_app_events *ev = hol_app_get_events(app);
    assert_int_equal(v->hud.stage, 1);
    assert_int_equal(ev->nlessons, 0);
    pancake(app, &t, 1, 0);
    assert_true(off(v->yaw_deg, 0) < 1e-9);
    assert_string_equal(v->hud.lines[0], "Well done: one step, one new tile");
    assert_true(strstr(v->hud.lines[1], "2/4") != NULL);
    hol_app_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lesson1_where_the_head_looks),
        cmocka_unit_test(test_lesson2_tree_in_view),
        cmocka_unit_test(test_pancake_faces_each_lesson),
        cmocka_unit_test(test_one_idea_and_a_row_per_lesson),
        cmocka_unit_test(test_held_map_not_taught),
        cmocka_unit_test(test_held_off_map_no_rings_line),
        cmocka_unit_test(test_flow_v4),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
