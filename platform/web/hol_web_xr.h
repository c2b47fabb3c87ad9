/* hol_web_xr.h - one WebXR frame as the app's input record and each eye's
 * camera. Pure (no browser, no GL): the glue (hol_web_lib.js) copies the
 * XRFrame's numbers into a hol_web_xr_frame, the loop (hol_web_main.c)
 * calls these; tests/test_web_xr.c runs them natively.
 *
 * Contract
 * - Reference space: `local-floor` (origin on the floor where the session
 *   began, the user looking down -z) or `bounded-floor` (origin near the
 *   middle of the play area): both are OpenXR's STAGE convention, so the
 *   room sits in them exactly as in the headset build
 *   (platform/shell/hol_xr_room.h: centred on the origin, north along -z;
 *   recentre places it from the head).
 * - Views: each view's viewport in the layer's framebuffer, its projection
 *   matrix (column-major, as XRView.projectionMatrix) and its transform
 *   (XRView.transform: position and orientation in the reference space).
 *   hol_web_xr_camera gives the renderer's headset camera: the eye in room
 *   coordinates, the orientation taking view space to room space, the four
 *   tangents of the field of view read from the matrix (an asymmetric
 *   frustum: tan_right = (1 + m8) / m0, tan_left = (m8 - 1) / m0,
 *   tan_up = (1 + m9) / m5, tan_down = (m9 - 1) / m5), the viewport's size.
 * - Controllers: the WebXR Gamepads Module's "xr-standard" layout (buttons
 *   0 trigger, 1 squeeze, 2 touchpad, 3 thumbstick press, 4 A or X, 5 B or
 *   Y; axes 2, 3 the thumbstick; missing entries are zero - the arrays the
 *   browser gives may hold nulls). With A/B and X/Y (Meta Quest Touch,
 *   HOL_DEVICE_WEBXR_TOUCH): right trigger or A confirm, B back, Y menu,
 *   X minimap, left thumbstick press recentre; in the app's pause menu
 *   confirm restarts and back quits (core/hol_app.h). Another xr-standard
 *   controller (HOL_DEVICE_NONE: the prompts name actions, not inputs):
 *   right trigger confirm, right squeeze back,
 *   left trigger menu, left squeeze minimap, left thumbstick press
 *   recentre. The thumbsticks' axes move nothing: the player walks.
 *   WebXR's select and squeeze (a hand's pinch, which has no gamepad on
 *   every browser) are written by the glue as that hand's trigger and
 *   squeeze held (present set).
 * - Hands (a tracked hand, XRInputSource.hand; the glue sets `hand` and
 *   `present` for it whether or not it has a gamepad): with no controller
 *   of the A/B, X/Y layout, HOL_DEVICE_WEBXR_HAND, and a hand's pinch
 *   (its select, or its gamepad's button 0) is a gesture of its own rather
 *   than a held trigger: a pinch let go within HOL_WEB_XR_LONG_PINCH_S is
 *   a tap, pressed when it ends (right hand: confirm; left hand: the menu,
 *   opened and closed); a pinch held HOL_WEB_XR_LONG_PINCH_S is back,
 *   pressed then and held until it ends, its end pressing nothing (in the
 *   menu back quits: hands alone open the menu, resume, restart and
 *   quit). A pinch going on while the session is not focused counts
 *   neither then nor at its end. A hand's squeeze does nothing.
 * - A tracked hand's joints (the glue fills `joint` from XRHand's 25
 *   joint spaces, positions in the reference space and radii, and sets
 *   joints_valid when every one has a pose) go to the record in room
 *   coordinates (hol_input.joints: drawn, core/hol_body.h) when usable
 *   (hol_hand_joints_usable: all located, finite, within reach), and both
 *   hands' make the hands-only recentre: both palms up and open, held
 *   HOL_GESTURE_HOLD_S while focused (hol_gesture_step) press
 *   HOL_BTN_RECENTRE, which places the room from the head as the
 *   thumbstick's press does.
 * - Seated play (state.seated, ?seated=1): with hands, a pinch dragged
 *   HOL_FLICK_M across the floor within HOL_FLICK_S takes one room step
 *   in the direction the hand went, relative to the look (core/hol_body.h
 *   hol_flick_step: its step bit in pressed); that pinch is then used up,
 *   its end pressing nothing and never a long pinch. A pinch that did not
 *   step is a tap or a long pinch as above.
 * - hol_web_xr_input fills the frame's record: time, the headset's state
 *   (core/hol_input.h: HOL_INPUT_HEADSET; HOL_INPUT_FOCUSED while the
 *   session is `visible`, not `visible-blurred` or `hidden`;
 *   HOL_INPUT_HEADSET_OFF while `hidden`; HOL_INPUT_POS_EMULATED for a
 *   viewer pose with emulatedPosition, head_valid 2), the head (the viewer
 *   pose) and both grips in room coordinates, buttons,
 *   pressed (held now, not at the previous frame; nothing is held or
 *   pressed while the session is not focused, and an input held through
 *   that is not pressed when focus comes back), device, and
 *   HOL_INPUT_BOUNDS_SMALL when the bounded-floor area cannot hold the
 *   room in play (state.room_w x room_d metres; 0: 3 x 3 m, which also
 *   centres it: calib.half_w, half_d). A recentre press places the room
 *   from the head before the head is converted (as the headset does).
 */
#ifndef HOL_WEB_XR_H
#define HOL_WEB_XR_H

#include <stdint.h>

#include "../../core/hol_body.h"
#include "../../core/hol_input.h"
#include "../../render/hol_view.h"
#include "../shell/hol_xr_room.h"

#define HOL_WEB_XR_BUTTONS 8
#define HOL_WEB_XR_AXES 4
#define HOL_WEB_XR_LONG_PINCH_S 1.0 /* a hand's pinch held this long: back */

enum { HOL_WEB_XR_HIDDEN = 0, HOL_WEB_XR_BLURRED = 1, HOL_WEB_XR_VISIBLE = 2 };

typedef struct hol_web_xr_view {
    float vp[4];      /* viewport x, y, width, height (pixels, from the bottom left) */
    float proj[16];   /* projection matrix, column-major */
    float pos[3];     /* eye position in the reference space, metres */
    float quat[4];    /* eye orientation x, y, z, w */
} hol_web_xr_view;

typedef struct hol_web_xr_pad {
    float present;                      /* 1: a controller with a gamepad */
    float touch_layout;                 /* 1: A/B or X/Y buttons (4, 5) */
    float grip_valid;                   /* 1: grip pose below */
    float grip_pos[3], grip_quat[4];
    float button[HOL_WEB_XR_BUTTONS];   /* 1 pressed, 0 not (or missing) */
    float axes[HOL_WEB_XR_AXES];
    float hand;                         /* 1: a tracked hand (XRInputSource.hand) */
    float joints_valid;                 /* 1: joint below holds all 25 */
    float joint[HOL_HAND_JOINTS][4];    /* x, y, z (reference space), radius */
} hol_web_xr_pad;

/* Everything the glue copies per XRFrame: floats only, so the page writes
 * it with one Float32Array view (hol_web_lib.js names the offsets). */
typedef struct hol_web_xr_frame {
    float nviews;
    float visibility;                   /* HOL_WEB_XR_* */
    float head_valid;                   /* 0 none, 1 tracked, 2 position emulated */
    float head_pos[3], head_quat[4];
    float bounds[2];                    /* bounded-floor width, depth (0: none) */
    hol_web_xr_view view[2];
    hol_web_xr_pad pad[2];              /* HOL_HAND_LEFT, HOL_HAND_RIGHT */
} hol_web_xr_frame;

/* What the loop keeps between frames. Zero it when a session begins. */
typedef struct hol_web_xr_state {
    hol_xr_calib calib;
    double room_w, room_d;  /* the room in play, metres (the loop sets it
                               from the view; 0: 3 x 3 m) */
    uint32_t prev_buttons;
    double last_t;
    /* each hand's pinch: going on (1), since pinch_t0; spent (1: long, or
     * begun unfocused: its end presses nothing) */
    int pinch_on[2], pinch_spent[2];
    double pinch_t0[2];
    hol_gesture gesture;    /* the hands-only recentre (core/hol_body.h) */
    int seated;             /* seated play (the loop sets it): a hand's
                               pinch and flick is a room step */
    hol_flick flick;        /* its state (core/hol_body.h) */
    int hands;              /* the last frame's hands (bits: 1, 2 joints of
                               the left, right; 4, 8 their palms up, open) */
} hol_web_xr_state;

/* The room camera of one view (viewport size as the camera's size). */
void hol_web_xr_camera(const hol_xr_calib *c, const hol_web_xr_view *v, hol_camera *out);

/* The buttons held (HOL_BTN_*) and the device of the controllers. */
uint32_t hol_web_xr_buttons(const hol_web_xr_pad pad[2], uint32_t *out_device);

/* The frame's input record at time t (seconds; never before the last). */
void hol_web_xr_input(hol_web_xr_state *st, const hol_web_xr_frame *f, double t,
                      hol_input *out);

#endif
