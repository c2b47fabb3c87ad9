/* test_xr_room.c - the room in an OpenXR stage and the session lifecycle
 * (platform/openxr/hol_xr_room.h), without a runtime. Rotations are
 * checked against an independent model: 3x3 matrices built from the
 * quaternion and the yaw, not the module's quaternion product. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_nav.h"
#include "../platform/shell/hol_xr_room.h"
#include "quat_model.h"

static double frand(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static void random_quat(uint64_t *s, float q[4])
{
    double a[4], n = 0;
    for (int k = 0; k < 4; k++) {
        a[k] = frand(s) * 2 - 1;
        n += a[k] * a[k];
    }
    n = sqrt(n);
    for (int k = 0; k < 4; k++)
        q[k] = (float)(a[k] / n);
}

static void test_default_placement(void **state)
{
    (void)state;
    hol_xr_calib c = {0, 0, 0, 0, 0};
    float p[3] = {0, 1.7f, 0}, q[4] = {0, 0, 0, 1};
    hol_pose r;
    hol_xr_to_room(&c, p, q, &r);
    assert_true(fabsf(r.pos[0] - 1.5f) < 1e-6f && fabsf(r.pos[2] - 1.5f) < 1e-6f);
    assert_true(fabsf(r.pos[1] - 1.7f) < 1e-6f);
    assert_true(fabsf(r.quat[3] - 1) < 1e-6f);
    /* one metre ahead in the stage (-z) is one metre north in the room */
    float p2[3] = {0.25f, 1.7f, -1};
    hol_xr_to_room(&c, p2, q, &r);
    assert_true(fabsf(r.pos[0] - 1.75f) < 1e-6f && fabsf(r.pos[2] - 0.5f) < 1e-6f);
}

/* Recentre from 2000 random head poses: the head lands on the middle
 * cell's centre, its floor-projected forward becomes room north, and
 * room <-> stage round-trips. */
static void test_recentre(void **state)
{
    (void)state;
    uint64_t s = 7;
    for (int i = 0; i < 2000; i++) {
        hol_xr_calib c = {frand(&s) * 6, frand(&s) * 4 - 2, frand(&s) * 4 - 2, 0, 0};
        float p[3] = {(float)(frand(&s) * 6 - 3), (float)(1 + frand(&s)),
                      (float)(frand(&s) * 6 - 3)}, q[4];
        random_quat(&s, q);
        double fwd[3], nz[3] = {0, 0, -1};
        quat_model_rotate(q, nz, fwd);
        if (fwd[0] * fwd[0] + fwd[2] * fwd[2] < 1e-3)
            continue; /* looking straight up or down */
        hol_xr_recentre(&c, p, q);
        hol_pose r;
        hol_xr_to_room(&c, p, q, &r);
        assert_true(fabsf(r.pos[0] - 1.5f) < 1e-4f && fabsf(r.pos[2] - 1.5f) < 1e-4f);
        assert_true(fabsf(r.pos[1] - p[1]) < 1e-6f);
        double rf[3];
        quat_model_rotate(r.quat, nz, rf);
        double h = sqrt(rf[0] * rf[0] + rf[2] * rf[2]);
        assert_true(fabs(rf[0] / h) < 1e-4 && rf[2] / h < -0.9999);
        /* the vertical is kept: the pitch of the forward vector */
        assert_true(fabs(rf[1] - fwd[1]) < 1e-4);
        /* round trip */
        float p3[3] = {(float)(frand(&s) * 4 - 2), 1.6f, (float)(frand(&s) * 4 - 2)}, q3[4];
        random_quat(&s, q3);
        hol_xr_to_room(&c, p3, q3, &r);
        float bp[3], bq[4];
        hol_xr_to_stage(&c, &r, bp, bq);
        for (int k = 0; k < 3; k++)
            assert_true(fabsf(bp[k] - p3[k]) < 1e-4f);
        double dot = 0;
        for (int k = 0; k < 4; k++)
            dot += (double)bq[k] * q3[k];
        assert_true(fabs(fabs(dot) - 1) < 1e-5);
    }
}

static void test_bounds(void **state)
{
    (void)state;
    assert_true(hol_xr_bounds_hold_room(3, 3));
    assert_true(hol_xr_bounds_hold_room(4, 3.5f));
    assert_false(hol_xr_bounds_hold_room(2.9f, 4));
    assert_false(hol_xr_bounds_hold_room(4, 2.5f));
}

/* the fade's model: the floor distance beyond the inner square, by
 * brute force over the square's edges, against hol_xr_fade */
static double beyond(double x, double z, double m)
{
    double cx = x < m ? m : x > 3 - m ? 3 - m : x, cz = z < m ? m : z > 3 - m ? 3 - m : z;
    double dx = x - cx, dz = z - cz;
    return fabs(dx) > fabs(dz) ? fabs(dx) : fabs(dz); /* square distance */
}

static void test_fade(void **state)
{
    (void)state;
    const double m = 0.15;
    /* inside the inner square: no fade, anywhere, at any height */
    for (double x = m; x <= 3 - m; x += 0.05)
        for (double z = m; z <= 3 - m; z += 0.05) {
            double e[2][3] = {{x, 1.7, z}, {x, 0.2, z}};
            assert_true(hol_xr_fade(e, m) == 0);
        }
    /* beyond it: linear, complete HOL_XR_FADE_FULL inside the boundary */
    uint64_t s = 3;
    for (int i = 0; i < 2000; i++) {
        double x = frand(&s) * 3.6 - 0.3, z = frand(&s) * 3.6 - 0.3;
        double e[2][3] = {{x, 1.6, z}, {1.5, 1.6, 1.5}};
        double want = beyond(x, z, m) / (m - HOL_XR_FADE_FULL);
        want = want > 1 ? 1 : want;
        assert_true(fabs(hol_xr_fade(e, m) - want) < 1e-9);
        /* the larger of the two eyes, whichever eye it is */
        double f[2][3] = {{1.5, 1.6, 1.5}, {x, 1.6, z}};
        assert_true(fabs(hol_xr_fade(f, m) - want) < 1e-9);
        /* an eye outside the room is fully faded */
        if (x <= 0 || x >= 3 || z <= 0 || z >= 3)
            assert_true(hol_xr_fade(e, m) == 1);
    }
    double edge[2][3] = {{HOL_XR_FADE_FULL, 1.6, 1.5}, {1.5, 1.6, 1.5}};
    assert_true(hol_xr_fade(edge, m) == 1);
    double half[2][3] = {{1.5, 1.6, 3 - (m + HOL_XR_FADE_FULL) / 2}, {1.5, 1.6, 1.5}};
    assert_true(fabs(hol_xr_fade(half, m) - 0.5) < 1e-9);
    double nan_eye[2][3] = {{NAN, 1.6, 1.5}, {1.5, 1.6, 1.5}};
    assert_true(hol_xr_fade(nan_eye, m) == 1);
}

/* Issue 20: a room of W x D metres (C*M by R*M) is centred on the stage
 * origin (and on the head at a recentre), round-trips, and fades at its
 * own hedges; the stage bounds hold it or not by its own size. */
static void test_room_of_any_size(void **state)
{
    (void)state;
    static const double size[][2] = {{2.4, 2.4}, {3.0, 1.8}, {7.5, 6.0}, {1.5, 1.5}};
    uint64_t s = 11;
    for (size_t k = 0; k < sizeof size / sizeof size[0]; k++) {
        double w = size[k][0], d = size[k][1];
        hol_xr_calib c = {0, 0, 0, w / 2, d / 2};
        float p[3] = {0, 1.6f, 0}, q[4] = {0, 0, 0, 1};
        hol_pose r;
        hol_xr_to_room(&c, p, q, &r);
        assert_true(fabs(r.pos[0] - w / 2) < 1e-6 && fabs(r.pos[2] - d / 2) < 1e-6);
        /* the room's north-west corner is half the room west and north */
        float nw[3] = {(float)(-w / 2), 1.6f, (float)(-d / 2)};
        hol_xr_to_room(&c, nw, q, &r);
        assert_true(fabs(r.pos[0]) < 1e-5 && fabs(r.pos[2]) < 1e-5);
        /* recentre: the head becomes the room's centre; stage <-> room */
        float hp[3] = {(float)(frand(&s) - 0.5), 1.7f, (float)(frand(&s) - 0.5)}, hq[4];
        random_quat(&s, hq);
        hol_xr_recentre(&c, hp, hq);
        hol_xr_to_room(&c, hp, hq, &r);
        assert_true(fabs(r.pos[0] - w / 2) < 1e-5 && fabs(r.pos[2] - d / 2) < 1e-5);
        float back[3], bq[4];
        hol_xr_to_stage(&c, &r, back, bq);
        for (int i = 0; i < 3; i++)
            assert_true(fabsf(back[i] - hp[i]) < 1e-5f);
        /* the fade: none in the middle, full at and beyond the hedges */
        double mid[2][3] = {{w / 2, 1.6, d / 2}, {w / 2, 1.6, d / 2}};
        assert_true(hol_xr_fade_room(mid, 0.15, w, d) == 0);
        double east[2][3] = {{w - 0.01, 1.6, d / 2}, {w / 2, 1.6, d / 2}};
        assert_true(hol_xr_fade_room(east, 0.15, w, d) == 1);
        double in_east[2][3] = {{w - 0.15, 1.6, d / 2}, {w / 2, 1.6, d / 2}};
        assert_true(hol_xr_fade_room(in_east, 0.15, w, d) == 0);
        double south[2][3] = {{w / 2, 1.6, d + 0.2}, {w / 2, 1.6, d / 2}};
        assert_true(hol_xr_fade_room(south, 0.15, w, d) == 1);
        /* bounds: the room's own size */
        assert_true(hol_xr_bounds_hold((float)w, (float)d, w, d));
        assert_false(hol_xr_bounds_hold((float)(w - 0.01), (float)d, w, d));
        assert_false(hol_xr_bounds_hold((float)w, (float)(d - 0.01), w, d));
    }
    /* zero half sizes: the 3 x 3 m room, as before rooms had sizes */
    double e[2][3] = {{2.9, 1.6, 1.5}, {1.5, 1.6, 1.5}};
    assert_true(hol_xr_fade_room(e, 0.15, 3, 3) == hol_xr_fade(e, 0.15));
}

/* The fit told on the HUD: two lines, in capitals, the room in play and the
 * play area; the room in play named "(ASKED)" when it is not the fit. */
static void test_fit_note(void **state)
{
    (void)state;
    hol_fit f;
    assert_int_equal(hol_fit_rect(2.6, 2.6, -1, &f), HOL_OK);
    hol_app_view v, out;
    memset(&v, 0, sizeof v);
    v.user.more_cols = v.user.more_rows = 1; /* 4 x 4 */
    v.cell_m = 0.6;
    v.hud.nlines = 2;
    assert_int_equal(hol_xr_fit_note(&f, 0, &v, &out), 1);
    assert_int_equal(out.hud.nlines, 4);
    assert_string_equal(out.hud.lines[2], "ROOM 4 X 4 OF 0.6 M");
    assert_string_equal(out.hud.lines[3], "FITS YOUR 2.6 X 2.6 M AREA");
    memset(&v.user, 0, sizeof v.user); /* 3 x 3 of 1 m: a level named it */
    v.cell_m = 0;
    assert_int_equal(hol_xr_fit_note(&f, 0, &v, &out), 1);
    assert_string_equal(out.hud.lines[2], "ROOM 3 X 3 OF 1.0 M (ASKED)");
    assert_string_equal(out.hud.lines[3], "YOUR AREA: 2.6 X 2.6 M");
    assert_int_equal(hol_xr_fit_note(&f, 1, &v, &out), 1);
    assert_string_equal(out.hud.lines[2], "ROOM 3 X 3 OF 1.0 M");
    assert_string_equal(out.hud.lines[3], "4 X 4 OF 0.6 FITS: RELOAD");
    assert_int_equal(hol_fit_rect(1.2, 1.2, -1, &f), HOL_OK);
    v.cell_m = 0.5;
    assert_int_equal(hol_xr_fit_note(&f, 0, &v, &out), 1);
    assert_string_equal(out.hud.lines[2], "ROOM 3 X 3 OF 0.5 M: TOO BIG");
    assert_string_equal(out.hud.lines[3], "YOUR AREA: 1.2 X 1.2 M");
    v.hud.nlines = HOL_APP_HUD_LINES - 1; /* no room for two lines */
    assert_int_equal(hol_xr_fit_note(&f, 0, &v, &out), 0);
}

static void test_lifecycle(void **state)
{
    (void)state;
    static const struct {
        int st, act, running, focused;
    } t[] = {
        {HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING, 0, 0},
        {HOL_XR_STATE_READY, HOL_XR_DO_BEGIN, 1, 0},
        {HOL_XR_STATE_SYNCHRONIZED, HOL_XR_DO_NOTHING, 1, 0},
        {HOL_XR_STATE_VISIBLE, HOL_XR_DO_NOTHING, 1, 0},
        {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING, 1, 1},
        {HOL_XR_STATE_STOPPING, HOL_XR_DO_END, 0, 0},
        {HOL_XR_STATE_LOSS_PENDING, HOL_XR_DO_TEAR_DOWN, 0, 0},
        {HOL_XR_STATE_EXITING, HOL_XR_DO_TEAR_DOWN, 0, 0},
        {0, HOL_XR_DO_NOTHING, 0, 0},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
        int running = -1, focused = -1;
        assert_int_equal(hol_xr_lifecycle(t[i].st, &running, &focused), t[i].act);
        assert_int_equal(running, t[i].running);
        assert_int_equal(focused, t[i].focused);
    }
}

/* a session's events through the state machine: (state, action) pairs,
 * then what quitting does */
static void run_events(hol_xr_life *l, const int (*ev)[2], int n)
{
    for (int i = 0; i < n; i++) {
        assert_false(l->done);
        assert_int_equal(hol_xr_life_event(l, ev[i][0]), ev[i][1]);
    }
}

static void test_life_quit_by_the_app(void **state)
{
    (void)state;
    hol_xr_life l;
    memset(&l, 0, sizeof l);
    static const int up[][2] = {{HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_READY, HOL_XR_DO_BEGIN},
                                {HOL_XR_STATE_SYNCHRONIZED, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_VISIBLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING}};
    run_events(&l, up, 5);
    assert_true(l.running && l.focused);
    /* quitting while running asks the runtime, once */
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_REQUEST_EXIT);
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_NONE);
    assert_false(l.done);
    static const int down[][2] = {{HOL_XR_STATE_VISIBLE, HOL_XR_DO_NOTHING},
                                  {HOL_XR_STATE_SYNCHRONIZED, HOL_XR_DO_NOTHING},
                                  {HOL_XR_STATE_STOPPING, HOL_XR_DO_END},
                                  {HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING},
                                  {HOL_XR_STATE_EXITING, HOL_XR_DO_TEAR_DOWN}};
    run_events(&l, down, 5);
    assert_true(l.done);
    assert_false(l.running || l.focused);
}

static void test_life_stopped_by_the_runtime(void **state)
{
    (void)state;
    hol_xr_life l;
    memset(&l, 0, sizeof l);
    /* the headset taken off: STOPPING unasked ends the session and waits;
     * READY begins it again (the app must not leave) */
    static const int ev[][2] = {{HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_READY, HOL_XR_DO_BEGIN},
                                {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_VISIBLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_STOPPING, HOL_XR_DO_END},
                                {HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_READY, HOL_XR_DO_BEGIN},
                                {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING}};
    run_events(&l, ev, 8);
    assert_false(l.done);
    assert_true(l.running && l.focused);
    /* stopped again, then the user quits while idle: leave at once (no
     * xrRequestExitSession without a running session) */
    static const int ev2[][2] = {{HOL_XR_STATE_STOPPING, HOL_XR_DO_END},
                                 {HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING}};
    run_events(&l, ev2, 2);
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_LEAVE);
    assert_true(l.done);
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_NONE);
}

/* The app's frames around a lifecycle (as the platform's: the record's
 * headset state from hol_xr_life_state, RECENTRED from hol_xr_life_take),
 * the head walked from `from` to `to`
 * in 2 cm strides at 60 Hz; returns the room steps the app took. */
static int walk_head(hol_app *app, hol_xr_life *l, double *t, const float from[3],
                     const float to[3])
{
    int steps = 0;
    double d = hypot(to[0] - from[0], to[2] - from[2]);
    int n = (int)ceil(d / 0.02);
    for (int i = 0; i <= n; i++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = *t += 1.0 / 60;
        in.flags = HOL_INPUT_HEAD_VALID | hol_xr_life_state(l);
        in.flags |= hol_xr_life_take(l, 1);
        for (int k = 0; k < 3; k++)
            in.head.pos[k] = (float)(from[k] + (to[k] - from[k]) * (n ? (double)i / n : 1));
        in.head.quat[3] = 1;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        steps += hol_app_get_events(app)->nsteps;
    }
    return steps;
}

/* Entering, leaving and entering the session again (the headset taken
 * off: STOPPING, IDLE; put on again: READY) walks nothing: the head's way
 * while the session was stopped is no room step, the steps walked in
 * either session are, each once. */
static void test_life_reenter_walks_nothing(void **state)
{
    (void)state;
    hol_nav *nav = NULL;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    assert_int_equal(hol_nav_create(&nd, &nav), HOL_OK);
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = nav;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_EXPLORE;
    L.seed = 5;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    hol_xr_life l;
    memset(&l, 0, sizeof l);
    static const int on[][2] = {{HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_READY, HOL_XR_DO_BEGIN},
                                {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING}};
    static const int off[][2] = {{HOL_XR_STATE_VISIBLE, HOL_XR_DO_NOTHING},
                                 {HOL_XR_STATE_STOPPING, HOL_XR_DO_END},
                                 {HOL_XR_STATE_IDLE, HOL_XR_DO_NOTHING}};
    double t = 0;
    const float mid[3] = {1.5f, 1.6f, 1.5f}, north[3] = {1.5f, 1.6f, 0.6f},
                south[3] = {1.4f, 1.6f, 2.6f}, east[3] = {2.5f, 1.6f, 2.6f};
    run_events(&l, on, 3);
    assert_false(l.off || l.recentre); /* the first session: placed at the level's start */
    assert_int_equal(walk_head(app, &l, &t, mid, mid), 0);
    assert_int_equal(walk_head(app, &l, &t, mid, north), 1); /* one step north */
    run_events(&l, off, 3);
    /* the headset off, its wearer walks two cells south: nothing is run */
    run_events(&l, on, 3);
    assert_true(l.off && !l.recentre);
    assert_int_equal(walk_head(app, &l, &t, south, south), 0); /* re-based */
    assert_false(l.off);
    assert_int_equal(walk_head(app, &l, &t, south, east), 1); /* one step east */
    /* once more: off, on where it was left: still nothing */
    run_events(&l, off, 3);
    run_events(&l, on, 3);
    assert_int_equal(walk_head(app, &l, &t, east, east), 0);
    assert_int_equal(hol_app_get_view(app)->hud.steps, 2);
    assert_int_equal(l.begins, 3);
    /* no head yet: the recentre waits for one */
    hol_xr_life_recentred(&l);
    assert_int_equal(hol_xr_life_take(&l, 0), 0);
    assert_int_equal(hol_xr_life_take(&l, 1), HOL_INPUT_RECENTRED);
    assert_int_equal(hol_xr_life_take(&l, 1), 0);
    hol_app_destroy(app);
    hol_nav_destroy(nav);
}

static void test_life_loss(void **state)
{
    (void)state;
    hol_xr_life l;
    memset(&l, 0, sizeof l);
    static const int ev[][2] = {{HOL_XR_STATE_READY, HOL_XR_DO_BEGIN},
                                {HOL_XR_STATE_FOCUSED, HOL_XR_DO_NOTHING},
                                {HOL_XR_STATE_LOSS_PENDING, HOL_XR_DO_TEAR_DOWN}};
    run_events(&l, ev, 3);
    assert_true(l.done);
    assert_false(l.running);
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_NONE);
    /* quitting before the session ever ran leaves at once */
    memset(&l, 0, sizeof l);
    assert_int_equal(hol_xr_life_event(&l, HOL_XR_STATE_IDLE), HOL_XR_DO_NOTHING);
    assert_int_equal(hol_xr_life_quit(&l), HOL_XR_QUIT_LEAVE);
    assert_true(l.done);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_placement),
        cmocka_unit_test(test_recentre),
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_fade),
        cmocka_unit_test(test_room_of_any_size),
        cmocka_unit_test(test_fit_note),
        cmocka_unit_test(test_lifecycle),
        cmocka_unit_test(test_life_quit_by_the_app),
        cmocka_unit_test(test_life_stopped_by_the_runtime),
        cmocka_unit_test(test_life_loss),
        cmocka_unit_test(test_life_reenter_walks_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
