/* test_web_xr.c - WebXR frames as input records and eye cameras
 * (platform/web/hol_web_xr.h): the field of view read back from projection
 * matrices built as browsers build them, eyes and head placed in the room as
 * the headset build places them, the xr-standard bindings, focus from the
 * visibility state, press edges, recentre, the play-area warning.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_input_io.h"
#include "../platform/web/hol_web_xr.h"
#include "hand_fixture.h"

/* A perspective matrix from the four half-angle tangents (left and down
 * negative), near n and far f, column-major: what XRView.projectionMatrix
 * holds. */
static void frustum(double l, double r, double d, double u, double n, double f, float m[16])
{
    memset(m, 0, 16 * sizeof m[0]);
    m[0] = (float)(2 / (r - l));
    m[5] = (float)(2 / (u - d));
    m[8] = (float)((r + l) / (r - l));
    m[9] = (float)((u + d) / (u - d));
    m[10] = (float)(-(f + n) / (f - n));
    m[11] = -1;
    m[14] = (float)(-2 * f * n / (f - n));
}

static void test_camera(void **state)
{
    (void)state;
    /* Quest-like asymmetric eyes */
    static const double fov[2][4] = {{-1.0, 0.85, -1.05, 0.95}, {-0.85, 1.0, -1.05, 0.95}};
    for (int e = 0; e < 2; e++) {
        hol_web_xr_view v;
        memset(&v, 0, sizeof v);
        frustum(fov[e][0], fov[e][1], fov[e][2], fov[e][3], 0.1, 1000, v.proj);
        v.vp[0] = (float)(e * 400);
        v.vp[2] = 400;
        v.vp[3] = 600;
        v.pos[0] = e ? 0.032f : -0.032f;
        v.pos[1] = 1.6f;
        v.quat[3] = 1;
        hol_xr_calib c;
        memset(&c, 0, sizeof c);
        hol_camera cam;
        hol_web_xr_camera(&c, &v, &cam);
        assert_true(cam.has_pose);
        assert_true(fabs(cam.tan_left - fov[e][0]) < 1e-6 && fabs(cam.tan_right - fov[e][1]) < 1e-6);
        assert_true(fabs(cam.tan_down - fov[e][2]) < 1e-6 && fabs(cam.tan_up - fov[e][3]) < 1e-6);
        assert_int_equal(cam.width, 400);
        assert_int_equal(cam.height, 600);
        /* the room is centred on the reference space's origin, north along -z */
        assert_true(fabs(cam.eye[0] - (1.5 + v.pos[0])) < 1e-6);
        assert_true(fabs(cam.eye[1] - 1.6) < 1e-6 && fabs(cam.eye[2] - 1.5) < 1e-6);
        assert_true(fabs(cam.orient[3] - 1) < 1e-6);
    }
    /* turned 90 degrees to the left (west) about +y: the same turn in the room */
    hol_web_xr_view v;
    memset(&v, 0, sizeof v);
    frustum(-1, 1, -1, 1, 0.1, 100, v.proj);
    v.quat[1] = (float)sin(M_PI / 4);
    v.quat[3] = (float)cos(M_PI / 4);
    v.pos[2] = -1.0f; /* a metre north of the origin */
    hol_xr_calib c;
    memset(&c, 0, sizeof c);
    hol_camera cam;
    hol_web_xr_camera(&c, &v, &cam);
    assert_true(fabs(cam.eye[2] - 0.5) < 1e-6);
    assert_true(fabs(cam.orient[1] - sin(M_PI / 4)) < 1e-6 && fabs(cam.orient[3] - cos(M_PI / 4)) < 1e-6);
}

static hol_web_xr_frame touch_frame(void)
{
    hol_web_xr_frame f;
    memset(&f, 0, sizeof f);
    f.visibility = HOL_WEB_XR_VISIBLE;
    f.head_valid = 1;
    f.head_pos[1] = 1.6f;
    f.head_quat[3] = 1;
    for (int h = 0; h < 2; h++) {
        f.pad[h].present = 1;
        f.pad[h].touch_layout = 1;
    }
    return f;
}

/* Hands alone (iwer's hand mode, a Quest without controllers): a zeroed
 * state *st and touch_frame's focused frame and head, both sources hands
 * (no gamepad layout, no grip, no joints). */
static hol_web_xr_frame hands_frame(hol_web_xr_state *st)
{
    memset(st, 0, sizeof *st);
    hol_web_xr_frame f = touch_frame();
    for (int h = 0; h < 2; h++) {
        f.pad[h].touch_layout = 0;
        f.pad[h].hand = 1;
    }
    return f;
}

/* Both hands' joints as the glue writes them (reference space, the radius
 * in [3], joints_valid): hand_fixture's, palms up or down, the wrists
 * 1.2 m up, 0.3 m north, at x 0.85 and 1.15. */
static void hands_joints(hol_web_xr_frame *f, int palm_up)
{
    for (int h = 0; h < 2; h++) {
        double w[3] = {h ? 1.15 : 0.85, 1.2, -0.3};
        hol_hand_joints j;
        hand_fixture(h, w, 0, palm_up, 0, &j);
        f->pad[h].joints_valid = 1;
        for (int i = 0; i < HOL_HAND_JOINTS; i++) {
            memcpy(f->pad[h].joint[i], j.pos[i], 3 * sizeof(float));
            f->pad[h].joint[i][3] = j.radius[i];
        }
    }
}

static void test_buttons(void **state)
{
    (void)state;
    hol_web_xr_frame f = touch_frame();
    uint32_t dev = 99;
    assert_int_equal(hol_web_xr_buttons(f.pad, &dev), 0);
    assert_int_equal(dev, HOL_DEVICE_WEBXR_TOUCH);
    /* right: trigger 0, A 4 confirm, B 5 back; left: Y 5 menu, X 4 minimap,
     * thumbstick 3 recentre */
    static const struct {
        int hand, b;
        uint32_t btn;
    } touch[] = {{1, 0, HOL_BTN_CONFIRM}, {1, 4, HOL_BTN_CONFIRM}, {1, 5, HOL_BTN_BACK},
                 {0, 5, HOL_BTN_MENU},    {0, 4, HOL_BTN_MINIMAP}, {0, 3, HOL_BTN_RECENTRE},
                 {0, 0, 0},               {0, 1, 0},               {1, 1, 0}, {1, 3, 0}};
    for (size_t i = 0; i < sizeof touch / sizeof touch[0]; i++) {
        hol_web_xr_frame g = touch_frame();
        g.pad[touch[i].hand].button[touch[i].b] = 1;
        assert_int_equal(hol_web_xr_buttons(g.pad, NULL), touch[i].btn);
    }
    /* another xr-standard controller: no A/B, X/Y */
    static const struct {
        int hand, b;
        uint32_t btn;
    } generic[] = {{1, 0, HOL_BTN_CONFIRM}, {1, 1, HOL_BTN_BACK}, {0, 0, HOL_BTN_MENU},
                   {0, 1, HOL_BTN_MINIMAP}, {0, 3, HOL_BTN_RECENTRE}, {1, 4, 0}};
    for (size_t i = 0; i < sizeof generic / sizeof generic[0]; i++) {
        hol_web_xr_frame g = touch_frame();
        g.pad[0].touch_layout = g.pad[1].touch_layout = 0;
        g.pad[generic[i].hand].button[generic[i].b] = 1;
        assert_int_equal(hol_web_xr_buttons(g.pad, &dev), generic[i].btn);
        assert_int_equal(dev, HOL_DEVICE_NONE);
    }
    /* a controller without a gamepad presses nothing */
    hol_web_xr_frame g = touch_frame();
    g.pad[1].present = 0;
    g.pad[1].button[0] = 1;
    assert_int_equal(hol_web_xr_buttons(g.pad, &dev), 0);
    g.pad[0].present = 0;
    hol_web_xr_buttons(g.pad, &dev);
    assert_int_equal(dev, HOL_DEVICE_NONE);
}

static void test_input(void **state)
{
    (void)state;
    hol_web_xr_state st;
    memset(&st, 0, sizeof st);
    hol_web_xr_frame f = touch_frame();
    f.head_pos[0] = 0.25f;
    f.head_pos[2] = -0.5f;
    f.pad[0].grip_valid = 1;
    f.pad[0].grip_pos[1] = 1.0f;
    f.pad[0].grip_quat[3] = 1;
    f.pad[1].button[0] = 1; /* trigger held */
    hol_input in;
    hol_web_xr_input(&st, &f, 2.0, &in);
    assert_true(in.time_s == 2.0);
    assert_int_equal(in.flags, HOL_INPUT_HEADSET | HOL_INPUT_WAY_BACK | HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID |
                                   HOL_INPUT_HAND_L_VALID);
    assert_true(fabsf(in.head.pos[0] - 1.75f) < 1e-6f && fabsf(in.head.pos[2] - 1.0f) < 1e-6f);
    assert_true(fabsf(in.hand[0].pos[0] - 1.5f) < 1e-6f && fabsf(in.hand[0].pos[1] - 1.0f) < 1e-6f);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    assert_int_equal(in.device, HOL_DEVICE_WEBXR_TOUCH);
    /* held on: no new press; time never goes back */
    hol_web_xr_input(&st, &f, 1.5, &in);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, 0);
    assert_true(in.time_s == 2.0);
    /* blurred (a system menu over the session): not focused, no buttons */
    f.visibility = HOL_WEB_XR_BLURRED;
    hol_web_xr_input(&st, &f, 2.1, &in);
    assert_int_equal(in.flags & (HOL_INPUT_FOCUSED | HOL_INPUT_HEADSET_OFF), 0);
    assert_int_equal(in.buttons, 0);
    /* hidden (the headset off): not focused, off */
    f.visibility = HOL_WEB_XR_HIDDEN;
    hol_web_xr_input(&st, &f, 2.15, &in);
    assert_int_equal(in.flags & (HOL_INPUT_FOCUSED | HOL_INPUT_HEADSET_OFF), HOL_INPUT_HEADSET_OFF);
    f.visibility = HOL_WEB_XR_VISIBLE;
    hol_web_xr_input(&st, &f, 2.2, &in); /* back: held, but no new press */
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, 0);
    /* recentre (left thumbstick press): the head becomes the middle cell's
     * centre, facing north */
    f.pad[1].button[0] = 0;
    f.pad[0].button[3] = 1;
    f.head_quat[1] = (float)sin(0.3);
    f.head_quat[3] = (float)cos(0.3);
    hol_web_xr_input(&st, &f, 2.3, &in);
    assert_int_equal(in.pressed, HOL_BTN_RECENTRE);
    assert_true(fabsf(in.head.pos[0] - 1.5f) < 1e-5f && fabsf(in.head.pos[2] - 1.5f) < 1e-5f);
    assert_true(fabsf(in.head.quat[1]) < 1e-5f && fabsf(in.head.quat[3] - 1) < 1e-5f);
    /* an emulated position (tracking lost): the head, its position untracked */
    f.head_valid = 2;
    hol_web_xr_input(&st, &f, 2.35, &in);
    assert_int_equal(in.flags & (HOL_INPUT_HEAD_VALID | HOL_INPUT_POS_EMULATED),
                     HOL_INPUT_HEAD_VALID | HOL_INPUT_POS_EMULATED);
    /* no viewer pose: no head */
    f.head_valid = 0;
    hol_web_xr_input(&st, &f, 2.4, &in);
    assert_int_equal(in.flags & HOL_INPUT_HEAD_VALID, 0);
}

/* Hands alone (iwer's hand mode, a Quest without controllers): the device
 * is the hands'; a right pinch let go is confirm, a left one the menu
 * (both pressed at the pinch's end); a pinch held a second is back (held
 * until let go, its end pressing nothing); a pinch begun while not
 * focused counts neither then nor at its end. */
static void test_hands(void **state)
{
    (void)state;
    hol_web_xr_state st;
    hol_web_xr_frame f = hands_frame(&st);
    hol_input in;
    double t = 1.0;
    hol_web_xr_input(&st, &f, t, &in);
    assert_int_equal(in.device, HOL_DEVICE_WEBXR_HAND);
    assert_int_equal(in.buttons | in.pressed, 0);
    /* a short right pinch: nothing while held, confirm when let go */
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    hol_web_xr_input(&st, &f, t += 0.5, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    f.pad[1].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    assert_int_equal(in.buttons, 0);
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.pressed, 0);
    /* a short left pinch (select and squeeze as the glue writes them):
     * the menu */
    f.pad[0].button[0] = f.pad[0].button[1] = 1;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    f.pad[0].button[0] = f.pad[0].button[1] = 0;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.pressed, HOL_BTN_MENU);
    /* a long pinch (either hand): back once it has lasted a second, held
     * on, nothing when let go */
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    double t0 = t;
    hol_web_xr_input(&st, &f, t = t0 + HOL_WEB_XR_LONG_PINCH_S - 0.01, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    hol_web_xr_input(&st, &f, t = t0 + HOL_WEB_XR_LONG_PINCH_S, &in);
    assert_int_equal(in.pressed, HOL_BTN_BACK);
    assert_int_equal(in.buttons, HOL_BTN_BACK);
    hol_web_xr_input(&st, &f, t += 0.5, &in);
    assert_int_equal(in.pressed, 0);
    assert_int_equal(in.buttons, HOL_BTN_BACK);
    f.pad[1].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    /* begun under a system menu: nothing then, nothing at its end */
    f.visibility = HOL_WEB_XR_BLURRED;
    f.pad[0].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    f.visibility = HOL_WEB_XR_VISIBLE;
    hol_web_xr_input(&st, &f, t += 2.0, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    f.pad[0].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.buttons | in.pressed, 0);
    /* a controller with A/B, X/Y beside a hand: the controller's layout,
     * the trigger held as a trigger */
    f.pad[1].hand = 0;
    f.pad[1].touch_layout = 1;
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.1, &in);
    assert_int_equal(in.device, HOL_DEVICE_WEBXR_TOUCH);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
}

/* Seated with hands (?seated=1): a right pinch dragged 15 cm ahead is one
 * step ahead when it has gone 12 cm, its end pressing nothing and no
 * long pinch however long it is held; a pinch that stays is a tap
 * (confirm) as before; standing, the same drag is a tap. */
static void test_hands_seated(void **state)
{
    (void)state;
    hol_web_xr_state st;
    hol_web_xr_frame f = hands_frame(&st);
    f.head_pos[1] = 1.2f;
    for (int h = 0; h < 2; h++) {
        f.pad[h].grip_valid = 1;
        f.pad[h].grip_pos[0] = h ? 0.2f : -0.2f;
        f.pad[h].grip_pos[1] = 1.0f;
        f.pad[h].grip_pos[2] = -0.3f;
        f.pad[h].grip_quat[3] = 1;
    }
    hol_input in;
    double t = 1.0;
    st.seated = 1;
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.05, &in);
    assert_int_equal(in.pressed, 0);
    for (int k = 1; k <= 5; k++) { /* 3.2 cm a frame ahead (north, -z) */
        f.pad[1].grip_pos[2] = -0.3f - 0.032f * (float)k;
        hol_web_xr_input(&st, &f, t += 0.05, &in);
        assert_int_equal(in.pressed, k == 4 ? HOL_BTN_STEP_FWD : 0);
    }
    hol_web_xr_input(&st, &f, t += 1.5, &in); /* held on: no back */
    assert_int_equal(in.pressed | in.buttons, 0);
    f.pad[1].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.05, &in); /* let go: nothing */
    assert_int_equal(in.pressed | in.buttons, 0);
    /* a pinch that stays: a tap, as standing */
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.05, &in);
    hol_web_xr_input(&st, &f, t += 0.2, &in);
    f.pad[1].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.05, &in);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    st.seated = 0;
    /* standing: a short drag is a tap (confirm), the same as before */
    f.pad[1].grip_pos[2] = -0.3f;
    f.pad[1].button[0] = 1;
    hol_web_xr_input(&st, &f, t += 0.05, &in);
    f.pad[1].grip_pos[2] = -0.45f;
    hol_web_xr_input(&st, &f, t += 0.2, &in);
    assert_int_equal(in.pressed, 0);
    f.pad[1].button[0] = 0;
    hol_web_xr_input(&st, &f, t += 0.05, &in);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
}

/* The glue's joints (reference space) reach the record in room
 * coordinates; both palms up and open for 1 s, focused, press the
 * recentre once, which places the room from the head (the head, a metre
 * east of the origin and turned west, is then in the middle looking
 * north); under a system menu nothing. */
static void test_hands_recentre(void **state)
{
    (void)state;
    hol_web_xr_state st;
    hol_web_xr_frame f = hands_frame(&st);
    f.head_pos[0] = 1.0f;
    f.head_quat[1] = (float)sin(M_PI / 4);
    f.head_quat[3] = (float)cos(M_PI / 4);
    hands_joints(&f, 1);
    hol_input in;
    hol_web_xr_input(&st, &f, 1.0, &in);
    assert_int_equal(in.device, HOL_DEVICE_WEBXR_HAND);
    for (int h = 0; h < 2; h++) {
        assert_int_equal(in.joints[h].tracked, 1);
        hol_pose room;
        static const float one[4] = {0, 0, 0, 1};
        hol_xr_to_room(&st.calib, f.pad[h].joint[7], one, &room);
        assert_memory_equal(in.joints[h].pos[7], room.pos, sizeof room.pos);
        assert_true(in.joints[h].radius[7] == f.pad[h].joint[7][3]);
    }
    assert_true(fabs(in.head.pos[0] - 2.5) < 1e-6); /* not placed yet */
    /* under a system menu: nothing, and the hold starts again after it */
    f.visibility = HOL_WEB_XR_BLURRED;
    for (int k = 1; k <= 100; k++) {
        hol_web_xr_input(&st, &f, 1.0 + k / 72.0, &in);
        assert_int_equal(in.pressed, 0);
    }
    f.visibility = HOL_WEB_XR_VISIBLE;
    int presses = 0;
    double t0 = 1.0 + 101 / 72.0, at = -1;
    for (int k = 0; k < 144; k++) { /* 2 s at 72 Hz */
        hol_web_xr_input(&st, &f, t0 + k / 72.0, &in);
        if (in.pressed & HOL_BTN_RECENTRE) {
            presses++;
            at = k / 72.0;
            /* placed from the head: in the middle, looking north */
            assert_true(fabs(in.head.pos[0] - 1.5) < 1e-5 && fabs(in.head.pos[2] - 1.5) < 1e-5);
            assert_true(fabs(fabs(in.head.quat[3]) - 1) < 1e-5);
        }
    }
    assert_int_equal(presses, 1);
    assert_true(at >= HOL_GESTURE_HOLD_S && at < HOL_GESTURE_HOLD_S + 1.5 / 72);
    /* palms down: no press however long */
    memset(&st.gesture, 0, sizeof st.gesture);
    hands_joints(&f, 0);
    for (int k = 0; k < 144; k++) {
        hol_web_xr_input(&st, &f, 10 + k / 72.0, &in);
        assert_int_equal(in.pressed & HOL_BTN_RECENTRE, 0);
    }
    /* a joint the browser lost (NaN): that hand has none, the record stays
     * valid */
    f.pad[1].joint[12][1] = NAN;
    hol_web_xr_input(&st, &f, 20, &in);
    assert_int_equal(in.joints[0].tracked, 1);
    assert_int_equal(in.joints[1].tracked, 0);
    assert_true(hol_input_valid(&in));
}

static void test_bounds(void **state)
{
    (void)state;
    static const struct {
        float w, d;
        int small;
    } cases[] = {{0, 0, 0}, {3.5f, 3.2f, 0}, {3.0f, 3.0f, 0}, {2.5f, 4.0f, 1}, {4.0f, 2.9f, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        hol_web_xr_state st;
        memset(&st, 0, sizeof st);
        hol_web_xr_frame f = touch_frame();
        f.bounds[0] = cases[i].w;
        f.bounds[1] = cases[i].d;
        hol_input in;
        hol_web_xr_input(&st, &f, 0, &in);
        assert_int_equal((in.flags & HOL_INPUT_BOUNDS_SMALL) != 0, cases[i].small);
    }
}

/* Issue 20: a room of another size (4 x 4 cells of 0.6 m: 2.4 m) is
 * centred on the origin and checked against the bounds by its own size. */
static void test_room_of_another_size(void **state)
{
    (void)state;
    hol_web_xr_state st;
    memset(&st, 0, sizeof st);
    st.room_w = st.room_d = 2.4;
    hol_web_xr_frame f = touch_frame();
    f.head_valid = 1;
    f.head_pos[0] = 0, f.head_pos[1] = 1.6f, f.head_pos[2] = 0;
    f.head_quat[0] = f.head_quat[1] = f.head_quat[2] = 0, f.head_quat[3] = 1;
    f.bounds[0] = 2.5f, f.bounds[1] = 2.5f;
    hol_input in;
    hol_web_xr_input(&st, &f, 0, &in);
    assert_true(fabsf(in.head.pos[0] - 1.2f) < 1e-5f && fabsf(in.head.pos[2] - 1.2f) < 1e-5f);
    assert_int_equal(in.flags & HOL_INPUT_BOUNDS_SMALL, 0); /* 2.5 m holds 2.4 m */
    f.bounds[0] = 2.3f;
    hol_web_xr_input(&st, &f, 0.1, &in);
    assert_true(in.flags & HOL_INPUT_BOUNDS_SMALL);
    /* the 3 x 3 m room does not fit in 2.5 m: small, centred on 1.5 */
    memset(&st, 0, sizeof st);
    f.bounds[0] = 2.5f;
    hol_web_xr_input(&st, &f, 0, &in);
    assert_true(in.flags & HOL_INPUT_BOUNDS_SMALL);
    assert_true(fabsf(in.head.pos[0] - 1.5f) < 1e-5f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera),
        cmocka_unit_test(test_buttons),
        cmocka_unit_test(test_input),
        cmocka_unit_test(test_hands),
        cmocka_unit_test(test_hands_recentre),
        cmocka_unit_test(test_hands_seated),
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_room_of_another_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
