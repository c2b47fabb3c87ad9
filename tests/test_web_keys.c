/* test_web_keys.c - every level type completed with the keyboard alone and
 * one key at a time (issue 37, accessibility: keys only, one hand). The
 * keys go through the page's key mapping (platform/web/hol_web_input.h:
 * KeyboardEvent codes, the same keys as `holonomy play`) into the app, a
 * frame at 60 Hz; the player never turns to walk: W, S, A and D walk the
 * room's north, south, west and east with the look kept north, and at no
 * frame is more than one key held (no chord, no mouse, no second hand).
 * The walks are the navigator's fewest steps to the objective on the map
 * (tutorial lessons 1, 3 and 4, flags, keys and the chest) and, for the
 * tutorial's lesson 2, the four cells round its marked tree. Each level
 * type: the tutorial, flag, keys (each to its end screen and Enter's next
 * level), a flag level with an instructions screen, the pointing question
 * (turned with the arrow keys) and a questionnaire item (chosen with the
 * arrows), and explore (walked, then Q quits).
 */
#include <math.h>
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
#include "../core/hol_room.h"
#include "../platform/web/hol_web_input.h"

static hol_nav *nav;

static int setup(void **state)
{
    (void)state;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    return hol_nav_create(&nd, &nav) != HOL_OK;
}

static int teardown(void **state)
{
    (void)state;
    hol_nav_destroy(nav);
    return 0;
}

typedef struct kb {
    hol_app *app;
    hol_web_pancake p;
    double t;
    int next_level, answered, pointed, frames;
} kb;

static void frame(kb *k)
{
    int held = 0;
    for (int i = 0; i < HOL_WEB_K_COUNT; i++)
        held += k->p.held[i];
    assert_true(held <= 1); /* one key at a time */
    hol_input in;
    hol_web_pancake_input(&k->p, k->t, 1.0 / 60, hol_app_get_view(k->app)->yaw_deg, &in);
    assert_int_equal(hol_app_step(k->app, &in), HOL_OK);
    const hol_app_events *ev = hol_app_get_events(k->app);
    k->next_level += ev->next_level;
    k->answered += ev->answered;
    k->pointed += ev->pointed;
    k->t += 1.0 / 60;
    assert_true(++k->frames < 100000);
}

static void key(kb *k, const char *code, int down)
{
    int id = hol_web_key_from_code(code);
    assert_true(id >= 0);
    hol_web_key(&k->p, id, down, 0);
}

/* Press and release: a tap. */
static void tap(kb *k, const char *code)
{
    key(k, code, 1);
    frame(k);
    key(k, code, 0);
    frame(k);
}

/* The look turned back north with the arrow keys (a lesson of the
 * tutorial turns a pancake view to what it names), within a degree. */
static void look_north(kb *k)
{
    const hol_app_view *v = hol_app_get_view(k->app);
    for (int i = 0; i < 4; i++) {
        double y = fmod(v->yaw_deg + 540.0, 360.0) - 180.0; /* (-180, 180] */
        if (fabs(y) < 1.0)
            return;
        const char *turn = y > 0 ? "ArrowRight" : "ArrowLeft"; /* positive yaw: west */
        key(k, turn, 1);
        for (int f = 0; f < 600; f++) {
            frame(k);
            double z = fmod(v->yaw_deg + 540.0, 360.0) - 180.0;
            if (fabs(z) < 1.0 || (z > 0) != (y > 0))
                break;
        }
        key(k, turn, 0);
        frame(k);
    }
}

/* One room step in dir, the look north first: W, S, A or D held until the head
 * is at the next cell's centre. */
static void walk_step(kb *k, int dir)
{
    static const char *const code[4] = {[HOL_DIR_N] = "KeyW", [HOL_DIR_S] = "KeyS",
                                        [HOL_DIR_W] = "KeyA", [HOL_DIR_E] = "KeyD"};
    const hol_app_view *v = hol_app_get_view(k->app);
    look_north(k);
    int dc, dr;
    hol_dir_delta(dir, &dc, &dr);
    double cell = v->cell_m;
    double goal[2] = {(v->user.col + dc + 0.5) * cell, (v->user.row + dr + 0.5) * cell};
    int axis = dc ? 0 : 1;
    double sign = dc ? dc : dr;
    key(k, code[dir], 1);
    for (int i = 0; i < 600; i++) {
        frame(k);
        if (v->state != HOL_APP_PLAYING)
            break;
        double pos = v->head[axis ? 2 : 0];
        if ((goal[axis] - pos) * sign < 0.02)
            break;
    }
    key(k, code[dir], 0);
    frame(k);
}

/* Lesson 2: round the marked tree's four cells, back to this one. */
static void round_the_tree(kb *k)
{
    const hol_app_view *v = hol_app_get_view(k->app);
    int vc = v->tree_vertex[0], vr = v->tree_vertex[1];
    const int ring[4][2] = {{vc - 1, vr - 1}, {vc, vr - 1}, {vc, vr}, {vc - 1, vr}};
    int i = 4;
    for (int n = 0; n < 8 && i == 4; n++) {
        for (i = 0; i < 4 && (ring[i][0] != v->user.col || ring[i][1] != v->user.row); i++)
            ;
        if (i == 4) { /* the tree is ahead, not beside: walk to its nearest cell */
            int dc = ring[0][0] - v->user.col, dr = ring[0][1] - v->user.row;
            for (int j = 1; j < 4; j++) {
                int c = ring[j][0] - v->user.col, r = ring[j][1] - v->user.row;
                if (abs(c) + abs(r) < abs(dc) + abs(dr))
                    dc = c, dr = r;
            }
            walk_step(k, dr < 0 ? HOL_DIR_N : dr > 0 ? HOL_DIR_S : dc > 0 ? HOL_DIR_E : HOL_DIR_W);
        }
    }
    assert_true(i < 4); /* in one of the tree's cells */
    for (int s = 1; s <= 4 && v->state == HOL_APP_PLAYING && v->hud.stage == 1; s++) {
        const int *to = ring[(i + s) % 4];
        int dc = to[0] - v->user.col, dr = to[1] - v->user.row;
        walk_step(k, dc > 0 ? HOL_DIR_E : dc < 0 ? HOL_DIR_W : dr > 0 ? HOL_DIR_S : HOL_DIR_N);
    }
}

/* Plays the level to its end (state DONE, or the pointing question). */
static void play_to_end(kb *k)
{
    const hol_app_view *v = hol_app_get_view(k->app);
    for (int guard = 0; v->state == HOL_APP_PLAYING; guard++) {
        assert_true(guard < 200);
        if (v->hud.stage == 1 && v->tree_marked) {
            round_the_tree(k);
            continue;
        }
        assert_true(v->map.nobjectives > 0);
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        hol_room here = v->user;
        assert_int_equal(hol_nav_find(nav, &here, v->map.objectives[0], 0, walk, sizeof walk,
                                      &res), HOL_OK);
        assert_true(res.len > 0);
        walk_step(k, walk[0]);
    }
}

static void start(kb *k, const char *text)
{
    hol_app_level L;
    hol_level_err e;
    memset(&L, 0, sizeof L);
    assert_int_equal(hol_level_parse(text, strlen(text), &L, &e), HOL_OK);
    assert_int_equal(hol_app_start_level(k->app, &L), HOL_OK);
    frame(k);
}

static void test_keys_only(void **state)
{
    (void)state;
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = nav;
    kb k;
    memset(&k, 0, sizeof k);
    assert_int_equal(hol_app_create(&d, &k.app), HOL_OK);
    k.p.focused = 1;
    const hol_app_view *v = hol_app_get_view(k.app);
    static const char *const ended[] = {"mode tutorial\nseed 3\n", "mode flag\nseed 4\nflag Wrfl\n",
                                        "mode keys\nseed 5\nkeys Nf Wr\nchest Sf\n"};
    for (int i = 0; i < 3; i++) {
        start(&k, ended[i]);
        play_to_end(&k);
        assert_int_equal(v->state, HOL_APP_DONE);
        assert_false(v->hud.timed_out);
        int before = k.next_level;
        tap(&k, "Enter");
        assert_int_equal(k.next_level, before + 1);
        printf("    %s level done with keys alone, %d steps\n", i == 0 ? "tutorial"
                                                               : i == 1 ? "flag" : "keys",
               v->hud.steps);
    }
    /* a screen, the pointing question and a questionnaire item */
    start(&k, "mode flag\nseed 6\nflag Nff\ninstructions Walk to the flag.\npoint start\n"
              "question hard likert 1 5 \"How hard was it?\" \"easy\" \"hard\"\n"
              "ask q level hard\n");
    assert_int_equal(v->state, HOL_APP_SCREEN);
    tap(&k, "Enter");
    assert_int_equal(v->state, HOL_APP_SCREEN); /* the ready screen */
    tap(&k, "Enter");
    play_to_end(&k);
    assert_int_equal(v->state, HOL_APP_POINT);
    key(&k, "ArrowLeft", 1); /* turn to face where the start may be */
    for (int i = 0; i < 30; i++)
        frame(&k);
    key(&k, "ArrowLeft", 0);
    tap(&k, "Enter");
    assert_int_equal(k.pointed, 1);
    assert_int_equal(v->state, HOL_APP_DONE);
    tap(&k, "Enter");
    assert_int_equal(v->state, HOL_APP_ASK);
    int mark = v->hud.ask_value;
    tap(&k, "ArrowRight");
    assert_int_equal(v->hud.ask_value, mark + 1);
    tap(&k, "Enter");
    assert_int_equal(k.answered, 1);
    /* explore: walked, then Q quits */
    start(&k, "mode explore\nseed 7\n");
    walk_step(&k, HOL_DIR_N);
    walk_step(&k, HOL_DIR_E);
    assert_int_equal(v->hud.steps, 2);
    tap(&k, "KeyQ");
    assert_int_equal(v->state, HOL_APP_QUIT);
    hol_app_destroy(k.app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_keys_only),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
