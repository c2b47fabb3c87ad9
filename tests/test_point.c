/* test_point.c - the pointing question (issue 26 item 7, SPEC 8; level line
 * `point start|objective`): driven through the app step. At the level's
 * end (here its time limit) the app asks (state HOL_APP_POINT, the level
 * over: its summary given at that frame), the user turns and confirms, and
 * the answer's bearings are checked against the independent hyperboloid
 * model of tests/model.h (the true bearing: the target's centre in the
 * walk's carried frame) and integer grid positions (the flat one), for the
 * walk the app's own step events report. The pointed direction: the head's
 * yaw, the right controller's when tracked, the view's in pancake play
 * (where the axes turn but never walk). Also: no question without the line,
 * restart and quit during it, the parser's checks.
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
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_tile.h"
#include "app_fixture.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "model.h"
#pragma GCC diagnostic pop

static double ang_diff(double a, double b)
{
    double d = fmod(fabs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

/* Written independently of core: degrees clockwise from north. */
static double model_bearing(double east, double north)
{
    double d = atan2(east, north) * 180.0 / acos(-1.0);
    return d < 0 ? d + 360.0 : d;
}

static double wrap180(double d)
{
    while (d > 180)
        d -= 360;
    while (d <= -180)
        d += 360;
    return d;
}

/* A tracked head at cell (c, r)'s centre looking at yaw (SPEC 1: 0 north,
 * positive towards the west). */
static hol_input head_at(double t, int c, int r, double yaw, uint32_t pressed)
{
    return app_head(t, c, r, yaw, HOL_DEVICE_XR_TOUCH, pressed);
}

static hol_app_level flag_level_q(int q, const char *flag, int point, double limit)
{
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 11;
    L.cues = HOL_CUE_ALL;
    L.time_limit_s = limit;
    L.point = point;
    L.tiling_q = q;
    assert_int_equal(hol_tile_parse_q(q, flag, -1, &L.flag), HOL_OK);
    return L;
}

static hol_app_level flag_level(const char *flag, int point, double limit)
{
    return flag_level_q(5, flag, point, limit);
}

/* The walk the app took, for the model: room dirs and the flat grid. */
typedef struct walk_rec {
    int dirs[64], n;
} walk_rec;

static void step_rec(hol_app *app, const hol_input *in, walk_rec *w)
{
    assert_int_equal(hol_app_step(app, in), HOL_OK);
    const hol_app_events *ev = hol_app_get_events(app);
    for (int i = 0; i < ev->nsteps; i++)
        w->dirs[w->n++] = ev->steps[i].dir;
}

/* Walks the head through cells (c, r) pairs, a quarter second each. */
static void walk_cells(hol_app *app, const int *cells, int n, walk_rec *w, double *t)
{
    for (int i = 0; i < n; i++) {
        hol_input in = head_at(*t, cells[2 * i], cells[2 * i + 1], 0, 0);
        step_rec(app, &in, w);
        *t += 0.25;
    }
}

/* Expected bearings of target (start: the identity) after walk w. */
static void model_expect(const walk_rec *w, const hol_tile *target, int *has_true,
                         double *true_deg, int *has_flat, double *flat_deg)
{
    static const int dx[4] = {0, -1, 0, 1}, dy[4] = {1, 0, -1, 0};
    model_mat p = model_identity(), m = model_identity();
    if (target) {
        int codes[HOL_TILE_MAX_DIST], n = hol_tile_dist0(*target);
        for (int i = 0; i < n; i++)
            codes[i] = hol_tile_letter(*target, i);
        p = model_walk_letters(codes, n);
    }
    int seen = model_same_point(m, p), x = 0, y = 0, tx = 0, ty = 0;
    for (int i = 0; i < w->n; i++) {
        m = model_step(m, w->dirs[i]);
        x += dx[w->dirs[i]];
        y += dy[w->dirs[i]];
        if (!seen && model_same_point(m, p))
            seen = 1, tx = x, ty = y;
    }
    model_mat rel = model_mul(model_inv(m), p);
    *has_true = !model_same_point(m, p);
    *true_deg = *has_true ? model_bearing(rel.m[2], rel.m[5]) : 0;
    *has_flat = seen && (tx != x || ty != y);
    *flat_deg = *has_flat ? model_bearing(tx - x, ty - y) : 0;
}

/* Point to the start after a walk E N W W S, the level ended by its time
 * limit; the head turned to yaw 100 (bearing 260) confirms half a second
 * later. */
static void test_point_start_head(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L = flag_level("Nff", HOL_APP_POINT_START, 2.0);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    static const int cells[] = {1, 1, 2, 1, 2, 0, 1, 0, 0, 0, 0, 1};
    walk_rec w = {{0}, 0};
    double t = 0;
    walk_cells(app, cells, 6, &w, &t);
    assert_int_equal(w.n, 5);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_PLAYING);
    hol_input in = head_at(2.0, 0, 1, 100, 0);
    step_rec(app, &in, &w);
    const hol_app_events *ev = hol_app_get_events(app);
    assert_int_equal(ev->level_ended, HOL_APP_END_TIMEOUT); /* the summary as before */
    assert_int_equal(v->state, HOL_APP_POINT);
    assert_int_equal(ev->pointed, 0);
    assert_non_null(strstr(v->hud.status, "the start"));
    assert_string_equal(v->hud.hint, "A: confirm"); /* Touch: A confirms */
    /* looking round: no step, the clock stands */
    in = head_at(2.2, 0, 1, 30, 0);
    step_rec(app, &in, &w);
    assert_int_equal(w.n, 5);
    assert_int_equal(v->state, HOL_APP_POINT);
    assert_true(fabs(v->hud.elapsed_s - 2.0) < 1e-9);
    in = head_at(2.5, 0, 1, 100, HOL_BTN_CONFIRM);
    step_rec(app, &in, &w);
    assert_int_equal(ev->pointed, 1);
    assert_int_equal(ev->next_level, 0); /* the confirm answered, nothing more */
    assert_int_equal(v->state, HOL_APP_DONE);
    const hol_app_point *p = &ev->point;
    assert_int_equal(p->target, HOL_APP_POINT_START);
    assert_true(fabs(p->t - 2.0) < 1e-9);
    assert_true(fabs(p->time_s - 0.5) < 1e-9);
    assert_true(ang_diff(p->pointed_deg, 260) < 1e-4);
    int ht, hf;
    double td, fd;
    model_expect(&w, NULL, &ht, &td, &hf, &fd);
    assert_int_equal(p->has_true, 1);
    assert_int_equal(ht, 1);
    assert_true(ang_diff(p->true_deg, td) < 1e-4);
    assert_int_equal(p->has_flat, 1);
    assert_int_equal(hf, 1);
    assert_true(ang_diff(p->flat_deg, 90) < 1e-9); /* from (-1, 0) home to (0, 0) */
    assert_true(ang_diff(p->flat_deg, fd) < 1e-9);
    assert_true(fabs(p->error_true - wrap180(260 - td)) < 1e-4);
    assert_true(fabs(p->error_flat - 170) < 1e-4);
    /* then the end screen's confirm goes on */
    in = head_at(2.6, 0, 1, 100, HOL_BTN_CONFIRM);
    step_rec(app, &in, &w);
    assert_int_equal(ev->next_level, 1);
    assert_int_equal(ev->pointed, 0);
    hol_app_destroy(app);
}

/* Point to the objective (the flag, never reached) with the right
 * controller, in another tiling too: the controller's yaw, not the head's. */
static void point_objective_hand(int q, const char *flag)
{
    model_use_tiling(q);
    hol_app *app = make_app();
    hol_app_level L = flag_level_q(q, flag, HOL_APP_POINT_OBJECTIVE, 1.5);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    static const int cells[] = {1, 1, 1, 2, 2, 2, 2, 1};
    walk_rec w = {{0}, 0};
    double t = 0;
    walk_cells(app, cells, 4, &w, &t);
    hol_input in = head_at(1.5, 2, 1, 0, 0);
    step_rec(app, &in, &w);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_POINT);
    in = head_at(1.9, 2, 1, 10, HOL_BTN_CONFIRM);
    in.flags |= HOL_INPUT_HAND_R_VALID;
    double h = -45 * acos(-1.0) / 360; /* the ray at yaw -45: bearing 45 */
    in.hand[HOL_HAND_RIGHT].quat[1] = (float)sin(h);
    in.hand[HOL_HAND_RIGHT].quat[3] = (float)cos(h);
    step_rec(app, &in, &w);
    const hol_app_point *p = &hol_app_get_events(app)->point;
    assert_int_equal(hol_app_get_events(app)->pointed, 1);
    assert_int_equal(p->target, HOL_APP_POINT_OBJECTIVE);
    assert_true(ang_diff(p->pointed_deg, 45) < 1e-4);
    int ht, hf;
    double td, fd;
    hol_tile ft = L.flag;
    model_expect(&w, &ft, &ht, &td, &hf, &fd);
    assert_int_equal(p->has_true, 1);
    assert_true(ang_diff(p->true_deg, td) < 1e-4);
    assert_int_equal(p->has_flat, 0); /* never stood on the flag */
    assert_int_equal(hf, 0);
    assert_true(fabs(p->error_true - wrap180(45 - td)) < 1e-4);
    hol_app_destroy(app);
    model_use_tiling(5);
}

static void test_point_objective_hand(void **state)
{
    (void)state;
    point_objective_hand(5, "Nfl");
    point_objective_hand(6, "Nfr");
    point_objective_hand(4, "N");
}

/* Pancake: the axes turn the view and never walk; the view's yaw is the
 * answer. At the start tile: no bearing at all (empty fields). */
static void test_point_pancake(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L = flag_level("Nf", HOL_APP_POINT_START, 0.5);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    hol_input in;
    memset(&in, 0, sizeof in);
    in.flags = HOL_INPUT_FOCUSED;
    in.device = HOL_DEVICE_KEYBOARD;
    for (int i = 0; i <= 30; i++) {
        in.time_s = i / 60.0;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
    }
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_POINT);
    assert_non_null(strstr(v->hud.status, "Turn to face the start"));
    assert_non_null(strstr(v->hud.hint, "ENTER"));
    hol_room before = v->user;
    double yaw0 = v->yaw_deg;
    in.move[1] = 1; /* walking is ignored */
    in.turn[0] = 1; /* turning left is not */
    for (int i = 31; i <= 90; i++) {
        in.time_s = i / 60.0;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        assert_int_equal(hol_app_get_events(app)->nsteps, 0);
    }
    assert_int_equal(v->user.col, before.col);
    assert_int_equal(v->user.row, before.row);
    assert_true(fabs(v->head[2] - 1.5) < 1e-9);
    assert_true(ang_diff(v->yaw_deg, yaw0) > 10);
    assert_int_equal(v->hud.steps, 0);
    double yaw = v->yaw_deg;
    in.move[1] = in.turn[0] = 0;
    in.time_s = 91 / 60.0;
    in.pressed = HOL_BTN_CONFIRM;
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    const hol_app_events *ev = hol_app_get_events(app);
    assert_int_equal(ev->pointed, 1);
    assert_true(ang_diff(ev->point.pointed_deg, 360 - yaw) < 1e-9);
    assert_true(ev->point.pointed_deg >= 0 && ev->point.pointed_deg < 360);
    assert_int_equal(ev->point.has_true, 0); /* standing on the start */
    assert_int_equal(ev->point.has_flat, 0);
    assert_true(fabs(ev->point.time_s - (91 - 30) / 60.0) < 1e-9);
    assert_int_equal(v->state, HOL_APP_DONE);
    hol_app_destroy(app);
}

/* Without the line the end screen comes at once; restart and quit leave
 * the question unanswered. */
static void test_point_none_restart_quit(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L = flag_level("N", 0, 0);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    walk_rec w = {{0}, 0};
    double t = 0;
    static const int cells[] = {1, 1, 1, 0};
    walk_cells(app, cells, 2, &w, &t);
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_DONE);
    L.point = HOL_APP_POINT_OBJECTIVE;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    walk_cells(app, cells, 2, &w, &t);
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_POINT);
    hol_input in = head_at(t, 1, 1, 0, HOL_BTN_RESTART); /* back in the start cell */
    step_rec(app, &in, &w);
    assert_int_equal(hol_app_get_events(app)->pointed, 0);
    assert_int_equal(hol_app_get_events(app)->level_started, 1);
    assert_int_equal(hol_app_get_events(app)->level_ended, HOL_APP_END_NONE);
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_PLAYING);
    t += 0.25;
    walk_cells(app, cells, 2, &w, &t);
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_POINT);
    in = head_at(t, 1, 0, 0, HOL_BTN_QUIT);
    step_rec(app, &in, &w);
    assert_int_equal(hol_app_get_events(app)->pointed, 0);
    assert_int_equal(hol_app_get_events(app)->level_ended, HOL_APP_END_NONE);
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_QUIT);
    hol_app_destroy(app);
}

static void test_point_parse(void **state)
{
    (void)state;
    hol_app_level L;
    hol_level_err e;
    assert_int_equal(parse_level("mode flag\nflag Nf\npoint start\n", &L, &e), HOL_OK);
    assert_int_equal(L.point, HOL_APP_POINT_START);
    assert_int_equal(parse_level("mode keys\nkeys N E\nchest S\npoint objective\n", &L, &e), HOL_OK);
    assert_int_equal(L.point, HOL_APP_POINT_OBJECTIVE);
    assert_int_equal(parse_level("mode explore\npoint start\n", &L, &e), HOL_OK);
    assert_int_equal(parse_level("mode flag\nflag Nf\n", &L, &e), HOL_OK);
    assert_int_equal(L.point, 0);
    assert_int_equal(parse_level("mode flag\nflag Nf\npoint north\n", &L, &e), HOL_EPARSE);
    assert_int_equal(e.line, 3);
    assert_int_equal(parse_level("mode flag\nflag Nf\npoint\n", &L, &e), HOL_EPARSE);
    assert_int_equal(parse_level("mode flag\nflag Nf\npoint start start\n", &L, &e), HOL_EPARSE);
    assert_int_equal(parse_level("mode explore\npoint objective\n", &L, &e), HOL_EARG);
    assert_int_equal(e.line, 2);
    assert_int_equal(parse_level("mode tutorial\npoint start\n", &L, &e), HOL_EARG);
    assert_int_equal(parse_level("mode flag\npoint start\nflag N\npoint objective\n", &L, &e),
                     HOL_EARG); /* a key twice */
    assert_int_equal(hol_level_line_check("point objective", 15, &e), HOL_OK);
    assert_int_equal(hol_level_line_check("point east", 10, &e), HOL_EPARSE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_point_start_head),
        cmocka_unit_test(test_point_objective_hand),
        cmocka_unit_test(test_point_pancake),
        cmocka_unit_test(test_point_none_restart_quit),
        cmocka_unit_test(test_point_parse),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
