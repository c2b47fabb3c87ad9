/* test_body.c - the body a headset shows (core/hol_body.h): which hands
 * are drawn as what, the pointing ray, and the hands-only recentre
 * gesture with scripted joints, down to the app's recentre (issue 36),
 * and when a runtime's joints make a usable hand.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_body.h"
#include "../core/hol_input_io.h"
#include "app_fixture.h"
#include "hand_fixture.h"

static void both(hol_hand_joints j[2], int up_l, int up_r, int pinch)
{
    const double cl[3] = {1.3, 1.0, 1.2}, cr[3] = {1.7, 1.0, 1.2};
    hand_fixture(HOL_HAND_LEFT, cl, 0, up_l, pinch, &j[0]);
    hand_fixture(HOL_HAND_RIGHT, cr, 0, up_r, pinch, &j[1]);
}

/* Controllers by profile, tracked hands by their joints, poses bit for
 * bit; nothing untracked; the ray only while pointing with a head. */
static void test_body_from_input(void **state)
{
    (void)state;
    hol_body b;
    hol_body_from_input(NULL, 1, &b);
    assert_int_equal(b.hand[0].kind, HOL_BODY_NONE);
    assert_int_equal(b.ray_hand, -1);
    hol_input in = app_head(1, 1, 1, 0, HOL_DEVICE_XR_TOUCH, 0);
    in.flags |= HOL_INPUT_HAND_R_VALID;
    in.hand[1].pos[0] = 1.234567f;
    in.hand[1].quat[1] = 0.6f;
    in.hand[1].quat[3] = 0.8f;
    hol_body_from_input(&in, 0, &b);
    assert_int_equal(b.hand[0].kind, HOL_BODY_NONE);
    assert_int_equal(b.hand[1].kind, HOL_BODY_CONTROLLER);
    assert_int_equal(b.hand[1].model, HOL_BODY_MODEL_TOUCH);
    assert_memory_equal(&b.hand[1].pose, &in.hand[1], sizeof in.hand[1]);
    assert_int_equal(b.ray_hand, -1);
    hol_body_from_input(&in, 1, &b);
    assert_int_equal(b.ray_hand, HOL_HAND_RIGHT);
    assert_true(b.ray_m == HOL_BODY_RAY_M);
    in.flags &= ~(uint32_t)HOL_INPUT_HEAD_VALID; /* pancake: no ray */
    hol_body_from_input(&in, 1, &b);
    assert_int_equal(b.ray_hand, -1);
    assert_int_equal(hol_body_model_of(HOL_DEVICE_XR_VIVE), HOL_BODY_MODEL_WAND);
    assert_int_equal(hol_body_model_of(HOL_DEVICE_XR_INDEX), HOL_BODY_MODEL_INDEX);
    assert_int_equal(hol_body_model_of(HOL_DEVICE_XR_SIMPLE), HOL_BODY_MODEL_PLAIN);
    /* a tracked hand: its joints, the grip as its pose (or the wrist) */
    in = app_head(1, 1, 1, 0, HOL_DEVICE_WEBXR_HAND, 0);
    both(in.joints, 1, 0, 0);
    hol_body_from_input(&in, 1, &b);
    assert_int_equal(b.hand[0].kind, HOL_BODY_HAND);
    assert_int_equal(b.hand[1].kind, HOL_BODY_HAND);
    assert_memory_equal(&b.hand[0].joints, &in.joints[0], sizeof in.joints[0]);
    assert_true(b.hand[0].pose.pos[0] == in.joints[0].pos[HOL_JOINT_WRIST][0]);
    assert_true(b.hand[0].pose.quat[3] == 1);
    assert_int_equal(b.ray_hand, -1); /* no grip to point with */
    assert_int_equal(hol_input_valid(&in), 1);
    /* the line format keeps no joints: a line read back has none, the
     * rest bit for bit */
    char line[HOL_INPUT_LINE_MAX + 1];
    size_t n = hol_input_format(&in, line, sizeof line);
    assert_true(n > 0);
    hol_input back;
    assert_int_equal(hol_input_parse(line, n, &back, NULL), HOL_OK);
    assert_int_equal(back.joints[0].tracked, 0);
    hol_input want = in;
    memset(want.joints, 0, sizeof want.joints);
    assert_memory_equal(&back, &want, sizeof want);
    in.joints[1].pos[3][1] = NAN; /* a tracked joint must be finite */
    assert_int_equal(hol_input_valid(&in), 0);
}

/* Seated play's step by hand (a pinch and flick): the pinch point moved
 * 12 cm level within 0.8 s is one step in the look's nearest direction;
 * one a pinch; a tap, a slow drag, a lift and a record with no head are
 * none; a hand without joints flicks with its grip. */
static hol_input flick_rec(double t, double yaw, const double at[3], int joints)
{
    hol_input in = app_head(t, 1, 1, yaw, HOL_DEVICE_WEBXR_HAND, 0);
    in.flags |= HOL_INPUT_HEADSET | HOL_INPUT_SEATED;
    const double w[3] = {at[0], at[1], at[2] + 0.1}; /* the tips ~10 cm ahead */
    if (joints) {
        hand_fixture(HOL_HAND_RIGHT, w, 0, 0, 1, &in.joints[HOL_HAND_RIGHT]);
        double p[3];
        assert_true(hol_flick_point(&in, HOL_HAND_RIGHT, p));
        for (int k = 0; k < 3; k++) /* the whole hand moved so that p is at */
            for (int i = 0; i < HOL_HAND_JOINTS; i++)
                in.joints[HOL_HAND_RIGHT].pos[i][k] += (float)(at[k] - p[k]);
    } else {
        in.flags |= HOL_INPUT_HAND_R_VALID;
        for (int k = 0; k < 3; k++)
            in.hand[HOL_HAND_RIGHT].pos[k] = (float)at[k];
    }
    return in;
}

/* A right-hand pinch from (1.7, 1, 1.2) moved by (dx, dy, dz) over n
 * records of 0.05 s (the last at t0 + 0.05 n), looking at yaw: the steps
 * given, or'ed; *out_stepped the state's stepped at its end. */
static uint32_t flick(double yaw, double dx, double dy, double dz, int n, int joints,
                      int *out_stepped)
{
    hol_flick g;
    memset(&g, 0, sizeof g);
    const int on[2] = {0, 1};
    uint32_t got = 0;
    for (int i = 0; i <= n; i++) {
        double f = (double)i / n, at[3] = {1.7 + dx * f, 1.0 + dy * f, 1.2 + dz * f};
        hol_input in = flick_rec(2.0 + 0.05 * i, yaw, at, joints);
        uint32_t b = hol_flick_step(&g, &in, on);
        assert_true(b == 0 || !(got & b)); /* one a pinch */
        assert_true((b & ~(uint32_t)HOL_BTN_STEPS) == 0);
        got |= b;
    }
    *out_stepped = g.stepped[HOL_HAND_RIGHT];
    return got;
}

static void test_flick(void **state)
{
    (void)state;
    int st;
    /* looking north: north ahead, east right */
    assert_int_equal(flick(0, 0, 0, -0.2, 4, 1, &st), HOL_BTN_STEP_FWD);
    assert_int_equal(st, 1);
    assert_int_equal(flick(0, 0, 0, 0.2, 4, 1, &st), HOL_BTN_STEP_BACK);
    assert_int_equal(flick(0, 0.2, 0, 0.05, 4, 1, &st), HOL_BTN_STEP_RIGHT);
    assert_int_equal(flick(0, -0.2, 0, 0.05, 4, 1, &st), HOL_BTN_STEP_LEFT);
    /* looking west: west ahead, north right, south left, east back */
    assert_int_equal(flick(90, -0.15, 0, 0, 3, 1, &st), HOL_BTN_STEP_FWD);
    assert_int_equal(flick(90, 0, 0, -0.15, 3, 1, &st), HOL_BTN_STEP_RIGHT);
    assert_int_equal(flick(90, 0, 0, 0.15, 3, 1, &st), HOL_BTN_STEP_LEFT);
    assert_int_equal(flick(90, 0.15, 0, 0, 3, 1, &st), HOL_BTN_STEP_BACK);
    /* 30 degrees west of north: a move north-west (the look) is ahead */
    assert_int_equal(flick(30, -0.1, 0, -0.1732, 3, 1, &st), HOL_BTN_STEP_FWD);
    /* with the grip alone */
    assert_int_equal(flick(0, 0.2, 0, 0, 4, 0, &st), HOL_BTN_STEP_RIGHT);
    /* a tap (a pinch that moved 5 cm), a lift of 30 cm, a drag of 12 cm
     * that took 1.0 s: no step, the pinch the platform's */
    assert_int_equal(flick(0, 0.05, 0, 0, 4, 1, &st), 0);
    assert_int_equal(st, 0);
    assert_int_equal(flick(0, 0, 0.3, 0, 4, 1, &st), 0);
    assert_int_equal(flick(0, 0, 0, -0.13, 20, 1, &st), 0);
    assert_int_equal(st, 0);
    /* just within: 12.5 cm in 0.8 s */
    assert_int_equal(flick(0, 0, 0, -0.125, 16, 1, &st), HOL_BTN_STEP_FWD);
    /* no head, no pinch, no hand: nothing; a new pinch steps again */
    hol_flick g;
    memset(&g, 0, sizeof g);
    const int on[2] = {0, 1}, off[2] = {0, 0};
    const double a0[3] = {1.7, 1, 1.2}, a1[3] = {1.7, 1, 1.0};
    hol_input in = flick_rec(1.0, 0, a0, 1);
    assert_int_equal(hol_flick_step(&g, &in, on), 0);
    in = flick_rec(1.1, 0, a1, 1);
    in.flags &= ~(uint32_t)HOL_INPUT_HEAD_VALID;
    assert_int_equal(hol_flick_step(&g, &in, on), 0);
    in.flags |= HOL_INPUT_HEAD_VALID;
    assert_int_equal(hol_flick_step(&g, &in, off), 0); /* let go */
    assert_int_equal(hol_flick_step(&g, &in, on), 0);  /* pinched again here */
    in = flick_rec(1.3, 0, a0, 1);
    assert_int_equal(hol_flick_step(&g, &in, on), HOL_BTN_STEP_BACK);
    in = flick_rec(1.4, 0, a1, 1);
    assert_int_equal(hol_flick_step(&g, &in, on), 0); /* the same pinch */
    memset(&in.joints, 0, sizeof in.joints);
    assert_int_equal(hol_flick_step(&g, &in, on), 0); /* the hand lost */
    assert_int_equal(g.on[HOL_HAND_RIGHT], 0);
}

/* Palms: up and open, down, pinching; one hand alone never fires. */
static void test_palm_up(void **state)
{
    (void)state;
    hol_hand_joints j[2];
    both(j, 1, 1, 0);
    assert_true(hol_gesture_palm_up(&j[0], HOL_HAND_LEFT));
    assert_true(hol_gesture_palm_up(&j[1], HOL_HAND_RIGHT));
    /* the other hand's rule: a left hand read as a right is palm down */
    assert_false(hol_gesture_palm_up(&j[0], HOL_HAND_RIGHT));
    both(j, 0, 0, 0);
    assert_false(hol_gesture_palm_up(&j[0], HOL_HAND_LEFT));
    assert_false(hol_gesture_palm_up(&j[1], HOL_HAND_RIGHT));
    both(j, 1, 1, 1); /* a pinch is not an open hand */
    assert_false(hol_gesture_palm_up(&j[1], HOL_HAND_RIGHT));
    j[1].tracked = 0;
    assert_false(hol_gesture_palm_up(&j[1], HOL_HAND_RIGHT));
}

/* A hand's joints as a runtime gives them: usable whole (every joint
 * located, finite and within reach), else not at all. */
static void test_hand_usable(void **state)
{
    (void)state;
    const double at[3] = {0.2, 1.1, -0.3};
    hol_hand_joints j;
    hand_fixture(HOL_HAND_RIGHT, at, 30, 1, 0, &j);
    assert_true(hol_hand_joints_usable(j.pos, HOL_HAND_LOCATED_ALL));
    assert_true(hol_hand_joints_usable(j.pos, 0xffffffffu)); /* bits past 25: unread */
    /* a missing joint: any one, the first and the last included */
    for (int i = 0; i < HOL_HAND_JOINTS; i++)
        assert_false(hol_hand_joints_usable(j.pos, HOL_HAND_LOCATED_ALL & ~(1u << i)));
    assert_false(hol_hand_joints_usable(j.pos, 0));
    /* one coordinate NaN or infinite, of the wrist or the little tip */
    const float bad[3] = {NAN, INFINITY, -INFINITY};
    for (int b = 0; b < 3; b++)
        for (int k = 0; k < 3; k++) {
            hol_hand_joints t = j;
            t.pos[b == 0 ? HOL_JOINT_WRIST : HOL_HAND_JOINTS - 1][k] = bad[b];
            assert_false(hol_hand_joints_usable(t.pos, HOL_HAND_LOCATED_ALL));
        }
    /* out of reach: 1e4 m or further either way; just under it is a hand */
    hol_hand_joints t = j;
    t.pos[HOL_JOINT_INDEX_TIP][1] = HOL_HAND_REACH_M;
    assert_false(hol_hand_joints_usable(t.pos, HOL_HAND_LOCATED_ALL));
    t.pos[HOL_JOINT_INDEX_TIP][1] = -HOL_HAND_REACH_M;
    assert_false(hol_hand_joints_usable(t.pos, HOL_HAND_LOCATED_ALL));
    t.pos[HOL_JOINT_INDEX_TIP][1] = nextafterf(HOL_HAND_REACH_M, 0);
    assert_true(hol_hand_joints_usable(t.pos, HOL_HAND_LOCATED_ALL));
    t.pos[HOL_JOINT_INDEX_TIP][1] = -nextafterf(HOL_HAND_REACH_M, 0);
    assert_true(hol_hand_joints_usable(t.pos, HOL_HAND_LOCATED_ALL));
}

/* Held 1 s: one recentre at the record that reaches it, none after while
 * held, none for one palm or a pinch, again after a palm went down. */
static void test_gesture_hold(void **state)
{
    (void)state;
    hol_gesture g;
    memset(&g, 0, sizeof g);
    hol_hand_joints up[2], down[2], one[2], pinch[2];
    both(up, 1, 1, 0);
    both(down, 0, 0, 0);
    both(one, 1, 0, 0);
    both(pinch, 1, 1, 1);
    int fired = 0;
    double at = -1;
    for (int i = 0; i <= 40; i++) { /* 2 s at 20 Hz */
        double t = 10 + i * 0.05;
        uint32_t b = hol_gesture_step(&g, up, t);
        if (b) {
            assert_int_equal(b, HOL_BTN_RECENTRE);
            fired++;
            at = t;
        }
    }
    assert_int_equal(fired, 1);
    assert_true(fabs(at - 11.0) < 1e-9);
    assert_int_equal(hol_gesture_step(&g, down, 12.1), 0);
    for (int i = 0; i < 30; i++) {
        assert_int_equal(hol_gesture_step(&g, one, 13 + i * 0.1), 0);
    }
    for (int i = 0; i < 30; i++)
        assert_int_equal(hol_gesture_step(&g, pinch, 17 + i * 0.1), 0);
    /* a hold broken at 0.9 s starts again */
    for (int i = 0; i <= 9; i++)
        assert_int_equal(hol_gesture_step(&g, up, 21 + i * 0.1), 0);
    assert_int_equal(hol_gesture_step(&g, down, 22.0), 0);
    assert_int_equal(hol_gesture_step(&g, up, 22.1), 0);
    assert_int_equal(hol_gesture_step(&g, up, 23.05), 0);
    assert_int_equal(hol_gesture_step(&g, up, 23.1), HOL_BTN_RECENTRE);
}

/* The hands-only recentre does what the controller's does: two apps get
 * the same headset records (a walk west turned west, then the platform's
 * room placed from the head), one with the recentre button pressed, the
 * other with scripted hands held palms up, the button coming only from
 * hol_gesture_step as a platform puts it in. Their rooms, heads, panels
 * and steps agree at every record, and the recentre happened (no step,
 * the cell the head's, the panel re-centred). */
static void test_hands_recentre(void **state)
{
    (void)state;
    hol_app *a = make_app(), *b = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 5;
    assert_int_equal(hol_tile_parse("Wrfl", -1, &L.flag), HOL_OK);
    L.cues = HOL_CUE_ALL;
    assert_int_equal(hol_app_start_level(a, &L), HOL_OK);
    assert_int_equal(hol_app_start_level(b, &L), HOL_OK);
    const hol_app_view *va = hol_app_get_view(a), *vb = hol_app_get_view(b);
    hol_gesture g;
    memset(&g, 0, sizeof g);
    int pressed_at = -1, recentres0 = 0;
    hol_room walked;
    memset(&walked, 0, sizeof walked);
    for (int i = 0; i < 50; i++) {
        double t = i * 0.05;
        /* 0..0.5 s in the middle; then west, turned west; from the press
         * (2.0 s: palms up from 1.0 s) the platform's room placed from
         * the head: the middle, north */
        int west = i >= 10 && i < 40;
        hol_input in = app_head(t, west ? 0 : 1, 1, west ? 90 : 0, HOL_DEVICE_WEBXR_HAND, 0);
        in.flags |= HOL_INPUT_HEADSET;
        hol_input hb = in;
        both(hb.joints, i >= 20, i >= 20, 0); /* palms down, then up from 1.0 s */
        uint32_t gest = (hb.flags & HOL_INPUT_FOCUSED) ? hol_gesture_step(&g, hb.joints, t) : 0;
        hb.pressed |= gest;
        hb.buttons |= gest;
        if (gest) {
            assert_int_equal(pressed_at, -1);
            pressed_at = i;
            in.pressed = in.buttons = HOL_BTN_RECENTRE;
            walked = va->user;
            recentres0 = va->panel.recentres;
        }
        const hol_app_events *ea = step(a, in);
        int na = ea->nsteps;
        const hol_app_events *eb = step(b, hb);
        assert_int_equal(na, eb->nsteps);
        assert_memory_equal(&va->user, &vb->user, sizeof va->user);
        assert_memory_equal(va->head, vb->head, sizeof va->head);
        assert_true(va->yaw_deg == vb->yaw_deg);
        assert_memory_equal(&va->panel, &vb->panel, sizeof va->panel);
        assert_int_equal(va->hud.steps, vb->hud.steps);
        assert_int_equal(vb->body.hand[0].kind, HOL_BODY_HAND);
        assert_int_equal(va->body.hand[0].kind, HOL_BODY_NONE);
        if (i == pressed_at) {
            assert_int_equal(eb->nsteps, 0);
            assert_true(hol_tile_eq(vb->user.tile, walked.tile));
            assert_int_equal(vb->user.col, 1);
            assert_int_equal(vb->user.orient, (walked.orient + 1) & 3);
            assert_true(vb->panel.recentres > recentres0);
        }
    }
    assert_int_equal(pressed_at, 40);
    assert_int_equal(vb->hud.steps, 1);
    hol_app_destroy(a);
    hol_app_destroy(b);
}

/* With the minimap in the hand the left controller is not drawn (the map
 * is drawn at its grip); the right one is, and a tracked left hand too. */
static void test_map_in_hand(void **state)
{
    (void)state;
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_EXPLORE;
    L.minimap = HOL_MINIMAP_HAND;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    hol_input in = app_head(0, 1, 1, 0, HOL_DEVICE_XR_TOUCH, 0);
    in.flags |= HOL_INPUT_HAND_L_VALID | HOL_INPUT_HAND_R_VALID;
    in.hand[0].quat[3] = in.hand[1].quat[3] = 1;
    step(app, in);
    assert_int_equal(v->map.place, HOL_MINIMAP_HAND);
    assert_int_equal(v->body.hand[0].kind, HOL_BODY_NONE);
    assert_int_equal(v->body.hand[1].kind, HOL_BODY_CONTROLLER);
    in = app_head(0.1, 1, 1, 0, HOL_DEVICE_XR_TOUCH, HOL_BTN_MINIMAP); /* the map off */
    in.flags |= HOL_INPUT_HAND_L_VALID | HOL_INPUT_HAND_R_VALID;
    in.hand[0].quat[3] = in.hand[1].quat[3] = 1;
    step(app, in);
    assert_int_equal(v->map.place, HOL_MINIMAP_OFF);
    assert_int_equal(v->body.hand[0].kind, HOL_BODY_CONTROLLER);
    in = app_head(0.2, 1, 1, 0, HOL_DEVICE_WEBXR_HAND, HOL_BTN_MINIMAP); /* hands, the map back */
    both(in.joints, 0, 0, 0);
    step(app, in);
    assert_int_equal(v->map.place, HOL_MINIMAP_HUD);
    in = app_head(0.3, 1, 1, 0, HOL_DEVICE_WEBXR_HAND, HOL_BTN_MINIMAP);
    both(in.joints, 0, 0, 0);
    step(app, in);
    assert_int_equal(v->map.place, HOL_MINIMAP_HAND);
    assert_int_equal(v->body.hand[0].kind, HOL_BODY_HAND);
    hol_app_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_body_from_input),
        cmocka_unit_test(test_palm_up),
        cmocka_unit_test(test_hand_usable),
        cmocka_unit_test(test_flick),
        cmocka_unit_test(test_gesture_hold),
        cmocka_unit_test(test_hands_recentre),
        cmocka_unit_test(test_map_in_hand),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
