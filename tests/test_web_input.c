/* test_web_input.c - the web page's pancake devices as input records
 * (platform/web/hol_web_input.h): keys by KeyboardEvent.code, taps between
 * frames, auto-repeat, Escape and the pointer lock, the mouse's turn rate,
 * the standard-mapping gamepad (dead zone, roles, device switch, loss),
 * touch, snap turn, focus.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../platform/web/hol_web_input.h"

static hol_input frame(hol_web_pancake *p)
{
    hol_input in;
    hol_web_pancake_input(p, 1.0, 1.0 / 60, 0.0, &in);
    return in;
}

static void test_key_codes(void **state)
{
    (void)state;
    assert_int_equal(hol_web_key_from_code("KeyW"), HOL_WEB_K_FORWARD);
    assert_int_equal(hol_web_key_from_code("ArrowUp"), HOL_WEB_K_FORWARD);
    assert_int_equal(hol_web_key_from_code("KeyS"), HOL_WEB_K_BACK);
    assert_int_equal(hol_web_key_from_code("KeyA"), HOL_WEB_K_STRAFE_L);
    assert_int_equal(hol_web_key_from_code("KeyD"), HOL_WEB_K_STRAFE_R);
    assert_int_equal(hol_web_key_from_code("ArrowLeft"), HOL_WEB_K_TURN_L);
    assert_int_equal(hol_web_key_from_code("PageDown"), HOL_WEB_K_LOOK_DOWN);
    assert_int_equal(hol_web_key_from_code("Space"), HOL_WEB_K_CONFIRM);
    assert_int_equal(hol_web_key_from_code("NumpadEnter"), HOL_WEB_K_CONFIRM);
    assert_int_equal(hol_web_key_from_code("KeyP"), HOL_WEB_K_MENU);
    assert_int_equal(hol_web_key_from_code("KeyM"), HOL_WEB_K_MINIMAP);
    assert_int_equal(hol_web_key_from_code("KeyR"), HOL_WEB_K_RESTART);
    assert_int_equal(hol_web_key_from_code("KeyQ"), HOL_WEB_K_QUIT);
    assert_int_equal(hol_web_key_from_code("F3"), HOL_WEB_K_DEBUG);
    assert_int_equal(hol_web_key_from_code("Escape"), HOL_WEB_K_ESCAPE);
    assert_int_equal(hol_web_key_from_code("KeyZ"), -1);
    assert_int_equal(hol_web_key_from_code("keyw"), -1); /* codes are exact */
    assert_int_equal(hol_web_key_from_code(""), -1);
    assert_int_equal(hol_web_key_from_code(NULL), -1);
}

static void test_held_and_tapped(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    p.focused = 1;
    hol_web_key(&p, HOL_WEB_K_FORWARD, 1, 0);
    hol_input in = frame(&p);
    assert_true(in.move[1] == 1.0f && in.move[0] == 0.0f);
    assert_true(in.flags == HOL_INPUT_FOCUSED && in.device == HOL_DEVICE_KEYBOARD);
    in = frame(&p); /* still held */
    assert_true(in.move[1] == 1.0f);
    hol_web_key(&p, HOL_WEB_K_FORWARD, 0, 0);
    in = frame(&p);
    assert_true(in.move[1] == 0.0f);
    /* a tap between two frames still moves one frame and presses once */
    hol_web_key(&p, HOL_WEB_K_STRAFE_L, 1, 0);
    hol_web_key(&p, HOL_WEB_K_STRAFE_L, 0, 0);
    hol_web_key(&p, HOL_WEB_K_MINIMAP, 1, 0);
    hol_web_key(&p, HOL_WEB_K_MINIMAP, 0, 0);
    in = frame(&p);
    assert_true(in.move[0] == -1.0f);
    assert_int_equal(in.pressed, HOL_BTN_MINIMAP);
    assert_int_equal(in.buttons, 0);
    in = frame(&p);
    assert_true(in.move[0] == 0.0f && in.pressed == 0);
    /* held: buttons; the tap that began it: pressed, once */
    hol_web_key(&p, HOL_WEB_K_CONFIRM, 1, 0);
    in = frame(&p);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    hol_web_key(&p, HOL_WEB_K_CONFIRM, 1, 1); /* auto-repeat: no new press */
    in = frame(&p);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, 0);
    hol_web_key(&p, HOL_WEB_K_CONFIRM, 0, 0);
    /* every button key */
    static const struct {
        int key;
        uint32_t btn;
    } keys[] = {{HOL_WEB_K_MENU, HOL_BTN_MENU},   {HOL_WEB_K_RESTART, HOL_BTN_RESTART},
                {HOL_WEB_K_DEBUG, HOL_BTN_DEBUG}, {HOL_WEB_K_QUIT, HOL_BTN_QUIT}};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        hol_web_key(&p, keys[i].key, 1, 0);
        in = frame(&p);
        assert_int_equal(in.pressed, keys[i].btn);
        hol_web_key(&p, keys[i].key, 0, 0);
    }
    /* unfocused: no FOCUSED flag (the app pauses) */
    p.focused = 0;
    in = frame(&p);
    assert_int_equal(in.flags & HOL_INPUT_FOCUSED, 0);
}

static void test_escape_and_pointer_lock(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    p.pointer_locked = 1;
    hol_web_key(&p, HOL_WEB_K_ESCAPE, 1, 0);
    hol_input in = frame(&p);
    assert_int_equal(in.pressed & HOL_BTN_QUIT, 0); /* the browser's: unlock */
    hol_web_key(&p, HOL_WEB_K_ESCAPE, 0, 0);
    p.pointer_locked = 0;
    hol_web_key(&p, HOL_WEB_K_ESCAPE, 1, 0);
    in = frame(&p);
    assert_int_equal(in.pressed & HOL_BTN_QUIT, HOL_BTN_QUIT);
}

static void test_mouse_turns(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    /* 0.2 degrees a pixel as a rate over the frame: 5 px in 1/60 s is 60
     * deg/s, half of the 120 deg/s turn; right is a negative (clockwise) turn */
    p.mouse_dx = 5;
    p.mouse_dy = -3; /* up: 36 deg/s of the 90 deg/s look */
    hol_input in = frame(&p);
    assert_true(fabsf(in.turn[0] + 0.5f) < 1e-6f);
    assert_true(fabsf(in.turn[1] - 0.4f) < 1e-6f);
    in = frame(&p); /* the motion was used */
    assert_true(in.turn[0] == 0.0f && in.turn[1] == 0.0f);
    p.mouse_dx = -1000; /* clamped */
    in = frame(&p);
    assert_true(in.turn[0] == 1.0f);
}

static void test_gamepad(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    p.focused = 1;
    p.pad_connected = 1;
    p.pad_standard = 1;
    p.pad_axes[1] = -1.0f; /* left stick up: forward */
    p.pad_axes[2] = 0.1f;  /* right stick inside the dead zone */
    hol_input in = frame(&p);
    assert_true(in.move[1] == 1.0f && in.move[0] == 0.0f);
    assert_true(in.turn[0] == 0.0f);
    assert_int_equal(in.device, HOL_DEVICE_GAMEPAD);
    /* the dead zone is radial and rescaled: 0.575 is half way */
    p.pad_axes[1] = 0;
    p.pad_axes[2] = -0.575f; /* right stick left: turn left (+) */
    in = frame(&p);
    assert_true(fabsf(in.turn[0] - 0.5f) < 1e-5f);
    p.pad_axes[2] = 0;
    static const struct {
        int b;
        uint32_t btn;
    } roles[] = {{0, HOL_BTN_CONFIRM},  {1, HOL_BTN_BACK},    {2, HOL_BTN_MINIMAP},
                 {3, HOL_BTN_RECENTRE}, {8, HOL_BTN_MINIMAP}, {9, HOL_BTN_MENU},
                 {12, HOL_BTN_RECENTRE}, {13, HOL_BTN_MINIMAP}, {16, HOL_BTN_MENU}};
    for (size_t i = 0; i < sizeof roles / sizeof roles[0]; i++) {
        memset(p.pad_button, 0, sizeof p.pad_button);
        p.pad_button[roles[i].b] = 1;
        in = frame(&p);
        assert_int_equal(in.buttons, roles[i].btn);
    }
    memset(p.pad_button, 0, sizeof p.pad_button);
    /* keys and pad add, clamped */
    p.pad_axes[0] = 1.0f;
    hol_web_key(&p, HOL_WEB_K_STRAFE_R, 1, 0);
    in = frame(&p);
    assert_true(in.move[0] == 1.0f);
    hol_web_key(&p, HOL_WEB_K_STRAFE_R, 0, 0);
    p.pad_axes[0] = 0;
    in = frame(&p); /* the pad was used last */
    /* the pad in use goes away: device lost until it is back or a key is used */
    p.pad_axes[1] = -1.0f;
    in = frame(&p);
    assert_int_equal(in.device, HOL_DEVICE_GAMEPAD);
    p.pad_connected = 0;
    in = frame(&p);
    assert_int_equal(in.flags & HOL_INPUT_DEVICE_LOST, HOL_INPUT_DEVICE_LOST);
    assert_true(in.move[1] == 0.0f);
    hol_web_key(&p, HOL_WEB_K_FORWARD, 1, 0);
    in = frame(&p);
    assert_int_equal(in.flags & HOL_INPUT_DEVICE_LOST, 0);
    assert_int_equal(in.device, HOL_DEVICE_KEYBOARD);
    hol_web_key(&p, HOL_WEB_K_FORWARD, 0, 0);
    /* a pad without the standard mapping is not read */
    p.pad_connected = 1;
    p.pad_standard = 0;
    p.pad_axes[1] = -1.0f;
    in = frame(&p);
    assert_true(in.move[1] == 0.0f && in.device == HOL_DEVICE_KEYBOARD);
}

static void test_touch_and_snap(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    p.touch_move[1] = 0.5f;
    p.touch_dx = -10; /* drag left: 3 degrees in 1/60 s, 180 deg/s: clamped */
    p.touch_used = 1;
    p.touch_buttons = HOL_BTN_MENU;
    p.touch_taps = HOL_BTN_MENU;
    hol_input in = frame(&p);
    assert_true(in.move[1] == 0.5f && in.turn[0] == 1.0f);
    assert_int_equal(in.buttons, HOL_BTN_MENU);
    assert_int_equal(in.pressed, HOL_BTN_MENU);
    assert_int_equal(in.device, HOL_DEVICE_SCREEN); /* prompts name the on-screen buttons */
    in = frame(&p);
    assert_int_equal(in.pressed, 0); /* taps used */
    assert_int_equal(in.buttons, HOL_BTN_MENU);
    assert_int_equal(in.device, HOL_DEVICE_SCREEN);
    p.touch_buttons = 0; /* a key after the touch: the keyboard again */
    hol_web_key(&p, HOL_WEB_K_CONFIRM, 1, 0);
    in = frame(&p);
    assert_int_equal(in.device, HOL_DEVICE_KEYBOARD);
    hol_web_key(&p, HOL_WEB_K_CONFIRM, 0, 0);
    p.touch_used = 1; /* and a swipe: the touch screen */
    in = frame(&p);
    assert_int_equal(in.device, HOL_DEVICE_SCREEN);
    /* snap turn: Left snaps to the next multiple of 90 degrees and does not turn */
    memset(&p, 0, sizeof p);
    p.snap_deg = 90;
    hol_web_key(&p, HOL_WEB_K_TURN_L, 1, 0);
    hol_web_pancake_input(&p, 1.0, 1.0 / 60, 10.0, &in);
    assert_int_equal(in.flags & HOL_INPUT_SNAP_YAW, HOL_INPUT_SNAP_YAW);
    assert_true(in.turn[0] == 0.0f);
    assert_true(fabsf(in.snap_yaw_deg - 90.0f) < 1e-6f);
    hol_web_pancake_input(&p, 1.1, 0.1, 90.0, &in); /* held: one snap a press */
    assert_int_equal(in.flags & HOL_INPUT_SNAP_YAW, 0);
    hol_web_key(&p, HOL_WEB_K_TURN_L, 0, 0);
    hol_web_key(&p, HOL_WEB_K_TURN_R, 1, 0);
    hol_web_pancake_input(&p, 1.2, 0.1, 90.0, &in);
    assert_true(fabsf(in.snap_yaw_deg - 0.0f) < 1e-6f);
}

/* Seated play (?seated=1): a key held is one step, released and pressed
 * again the next; the touch stick's swipe steps too; the record is
 * seated; Left snaps by 90 degrees though no snap was asked. */
static void test_seated(void **state)
{
    (void)state;
    hol_web_pancake p;
    memset(&p, 0, sizeof p);
    p.seated = 1;
    hol_web_key(&p, HOL_WEB_K_FORWARD, 1, 0);
    hol_input in = frame(&p);
    assert_int_equal(in.flags & HOL_INPUT_SEATED, HOL_INPUT_SEATED);
    assert_int_equal(in.pressed & HOL_BTN_STEPS, HOL_BTN_STEP_FWD);
    in = frame(&p); /* held: no second step */
    assert_int_equal(in.pressed & HOL_BTN_STEPS, 0);
    hol_web_key(&p, HOL_WEB_K_FORWARD, 0, 0);
    in = frame(&p);
    assert_int_equal(in.pressed & HOL_BTN_STEPS, 0);
    hol_web_key(&p, HOL_WEB_K_STRAFE_L, 1, 0);
    assert_int_equal(frame(&p).pressed & HOL_BTN_STEPS, HOL_BTN_STEP_LEFT);
    hol_web_key(&p, HOL_WEB_K_STRAFE_L, 0, 0);
    frame(&p);
    p.touch_move[1] = -0.9f; /* a swipe down on the left half */
    p.touch_used = 1;
    assert_int_equal(frame(&p).pressed & HOL_BTN_STEPS, HOL_BTN_STEP_BACK);
    p.touch_move[1] = 0;
    frame(&p);
    /* the on-screen arrows hold the step buttons themselves */
    p.touch_buttons = p.touch_taps = HOL_BTN_STEP_RIGHT;
    in = frame(&p);
    assert_int_equal(in.pressed & HOL_BTN_STEPS, HOL_BTN_STEP_RIGHT);
    p.touch_buttons = 0;
    hol_web_key(&p, HOL_WEB_K_TURN_L, 1, 0);
    hol_web_pancake_input(&p, 2.0, 1.0 / 60, 0.0, &in);
    assert_int_equal(in.flags & HOL_INPUT_SNAP_YAW, HOL_INPUT_SNAP_YAW);
    assert_true(fabsf(in.snap_yaw_deg - 90.0f) < 1e-6f);
    assert_true(in.turn[0] == 0.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_key_codes),     cmocka_unit_test(test_held_and_tapped),
        cmocka_unit_test(test_escape_and_pointer_lock), cmocka_unit_test(test_mouse_turns),
        cmocka_unit_test(test_gamepad),       cmocka_unit_test(test_touch_and_snap),
        cmocka_unit_test(test_seated),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
