/* hol_input.h - the device-neutral input record of one app step.
 *
 * Contract
 * - One hol_input is everything a platform tells the app about one frame:
 *   the time, the head and both hands in room coordinates, the buttons held,
 *   and the pancake (screen play) move and turn axes. Every platform fills
 *   it (desktop keyboard and mouse, gamepad, OpenXR, a recording) and the
 *   app step (core) reads nothing else, so a recorded stream of records
 *   replays a session exactly.
 * - Room coordinates (SPEC section 1): metres, x east, y up, z south; the
 *   move area is x, z in [0, 3]. Orientations are unit quaternions
 *   (x, y, z, w) in the same frame; the identity looks north (-z), up +y.
 * - A pose whose HOL_INPUT_*_VALID flag is clear is not tracked this frame
 *   and its values mean nothing.
 * - Buttons are bits of HOL_BTN_*: `buttons` those held at the record's
 *   time, `pressed` those pressed at least once since the previous record
 *   (a tap between two frames is in `pressed` though no longer held). The
 *   app step acts on edges: `pressed`, and any held button the previous
 *   record did not hold (so records without `pressed`, as in recordings
 *   older than the field, still give their edges).
 * - `device` names the device in use (HOL_DEVICE_*): the app words its
 *   prompts with that device's bindings ("ENTER: NEXT LEVEL", "A: NEXT
 *   LEVEL", "TRIGGER: NEXT LEVEL"); HOL_DEVICE_NONE words them by action.
 * - Snap turn (pancake): with HOL_INPUT_SNAP_YAW the look turns to
 *   snap_yaw_deg (degrees, yaw as in SPEC section 1) at this step, before
 *   the axes apply; the platform chooses the angle (a multiple of its snap
 *   so the room's axes stay aligned), the record carries it for replays.
 * - Recentre: a record with HOL_BTN_RECENTRE in its edges (the platform
 *   placed the room from the head for that button) or with
 *   HOL_INPUT_RECENTRED (the runtime moved its origin) and a tracked head
 *   re-places the room around the head: the head's jump in room
 *   coordinates is not walked, no room step is taken or logged, the user
 *   keeps the tile and (within 45 degrees) the look's direction in the
 *   world (hol_motion_replace).
 * - Steps only from a worn, tracked, focused headset: a record with
 *   HOL_INPUT_HEADSET (every OpenXR and WebXR frame) carries the headset's
 *   state, and the head walks (room steps) only while that state is worn
 *   (no HOL_INPUT_HEADSET_OFF), focused (HOL_INPUT_FOCUSED: no system menu
 *   over the app; WebXR `visible`, OpenXR FOCUSED) and tracked
 *   (HOL_INPUT_HEAD_VALID without HOL_INPUT_POS_EMULATED). While it is
 *   not, the head does not move the user (the look follows a tracked
 *   orientation); at the first record that is again, the room is re-based
 *   around the head (hol_motion_replace with no turn: the user keeps the
 *   tile and the room its north, the cell becomes the one under the head)
 *   instead of walking the head's jump, and when that changed the cell
 *   the step's events say `relocated` with the floor distance (core/
 *   hol_app.h). Records without HOL_INPUT_HEADSET (pancake, scripts,
 *   recordings made before the bit) walk every tracked head as before.
 *   A platform that missed frames while the headset was off (a stopped
 *   OpenXR session, a hidden WebXR session) sets HOL_INPUT_HEADSET_OFF on
 *   the first record after them.
 * - Seated play (HOL_INPUT_SEATED, issue 37: a desk or a chair, no room
 *   walking): the head's position walks nothing (a tracked head gives the
 *   look only; the pancake move axes are ignored, its turn axes and snap
 *   turns still turn); an edge of a HOL_BTN_STEP_* button moves the user
 *   from the centre of the cell to the centre of its neighbour in the room
 *   direction nearest the look's (ahead, back, left or right), which
 *   crosses one cell edge: the same room step a walk across that edge
 *   takes (hol_motion_move_to). One step a record (the first of ahead,
 *   back, left, right); a step into the hedge is not taken. Records
 *   without the flag (every recording made before it) play as before.
 * - Axes are in [-1, 1] after the platform's dead zone; zero is at rest.
 *   The app step turns them into motion (pancake mode); a headset sends
 *   zero axes and a tracked head.
 * - Tracked hands (WebXR's XRHand, OpenXR's hand tracking): `joints[h]`
 *   holds the 25 joints of hand h in room coordinates (WebXR's order:
 *   HOL_JOINT_*), each a position and a radius, when joints[h].tracked is
 *   1. They are drawn (the view's body, core/hol_body.h) and the platform
 *   may read a gesture from them (hol_gesture_step: the hands-only
 *   recentre, which it gives the app as HOL_BTN_RECENTRE); the app step
 *   decides nothing else from them. They are not in the line format
 *   (core/hol_input_io.h): a recording keeps the grips and the buttons
 *   the joints gave, and its replay draws a tracked hand as its grip's
 *   controller model.
 * - Plain data with fixed-size fields; no pointers, no allocation.
 */
#ifndef HOL_INPUT_H
#define HOL_INPUT_H

#include <stdint.h>

/* flags */
#define HOL_INPUT_HEAD_VALID   (1u << 0)
#define HOL_INPUT_HAND_L_VALID (1u << 1)
#define HOL_INPUT_HAND_R_VALID (1u << 2)
#define HOL_INPUT_FOCUSED      (1u << 3) /* the app has focus (unfocused: pause) */
#define HOL_INPUT_DEVICE_LOST  (1u << 4) /* the active controller went away */
#define HOL_INPUT_BOUNDS_SMALL (1u << 5) /* the play area is smaller than the
                                            3 x 3 m room: the HUD warns */
#define HOL_INPUT_SNAP_YAW     (1u << 6) /* turn the look to snap_yaw_deg */
#define HOL_INPUT_RECENTRED    (1u << 7) /* the runtime placed the room anew
                                            since the previous record (its
                                            recentre): the head's jump is
                                            no walk (see below) */
#define HOL_INPUT_HEADSET      (1u << 8) /* a headset's record: its state is in
                                            HOL_INPUT_FOCUSED and the two
                                            bits below (see above) */
#define HOL_INPUT_HEADSET_OFF  (1u << 9) /* the headset is off (not worn, its
                                            view hidden), or was since the
                                            previous record */
#define HOL_INPUT_POS_EMULATED (1u << 10) /* the head's position is not
                                             tracked (emulated, or lost):
                                             its orientation is */
#define HOL_INPUT_WAY_BACK     (1u << 11) /* the platform shows the way back
                                             in when the head is outside
                                             the room (hol_app_view.outside):
                                             the step logs `outside` and
                                             `inside` events (recordings
                                             made before it have none) */
#define HOL_INPUT_SEATED       (1u << 12) /* seated play: the head's position
                                             walks nothing, the step buttons
                                             take one room step each (below) */
#define HOL_INPUT_FLAGS_ALL    0x1fffu

/* buttons (held) */
#define HOL_BTN_CONFIRM  (1u << 0) /* confirm / next level */
#define HOL_BTN_BACK     (1u << 1) /* back / cancel */
#define HOL_BTN_MENU     (1u << 2) /* pause menu */
#define HOL_BTN_RECENTRE (1u << 3) /* place the room from the head pose */
#define HOL_BTN_MINIMAP  (1u << 4) /* cycle minimap: HUD, hand, off */
#define HOL_BTN_RESTART  (1u << 5) /* restart the level */
#define HOL_BTN_QUIT     (1u << 6) /* leave the app */
#define HOL_BTN_DEBUG    (1u << 7) /* show or hide the debug text (tile, cell) */
#define HOL_BTN_STEP_FWD   (1u << 8)  /* seated: one room step ahead */
#define HOL_BTN_STEP_BACK  (1u << 9)  /* seated: one room step back */
#define HOL_BTN_STEP_LEFT  (1u << 10) /* seated: one room step to the left */
#define HOL_BTN_STEP_RIGHT (1u << 11) /* seated: one room step to the right */
#define HOL_BTN_STEPS      0xf00u
#define HOL_BTN_ALL        0xfffu

/* The device in use (hol_input.device). The XR values are the OpenXR
 * interaction profiles the headset binds (platform/openxr/hol_xr_bind.h);
 * HOL_DEVICE_XR is any other XR controller; HOL_DEVICE_WEBXR_TOUCH the
 * web build's WebXR controllers with A/B and X/Y buttons (Meta Quest Touch,
 * the WebXR Gamepads Module's xr-standard layout: platform/web/hol_web_xr.h;
 * the Quest's menu button is not given to web pages, so its bindings differ
 * from OpenXR's touch_controller); HOL_DEVICE_WEBXR_HAND the web build's
 * tracked hands without controllers (pinches); HOL_DEVICE_SCREEN the web
 * page's touch screen (its prompts name the on-screen buttons the pupil
 * taps: platform/web/index.html). Names in the input line format
 * (core/hol_input_io.h): hol_input_device_name. */
enum hol_input_device {
    HOL_DEVICE_NONE = 0,      /* unknown: prompts name actions */
    HOL_DEVICE_KEYBOARD = 1,  /* keyboard and mouse */
    HOL_DEVICE_GAMEPAD = 2,   /* a game controller (Linux gamepad order) */
    HOL_DEVICE_XR_SIMPLE = 3, /* khr/simple_controller */
    HOL_DEVICE_XR_TOUCH = 4,  /* oculus/touch_controller */
    HOL_DEVICE_XR_VIVE = 5,   /* htc/vive_controller */
    HOL_DEVICE_XR_INDEX = 6,  /* valve/index_controller */
    HOL_DEVICE_XR_WMR = 7,    /* microsoft/motion_controller */
    HOL_DEVICE_XR = 8,        /* another XR controller */
    HOL_DEVICE_WEBXR_TOUCH = 9, /* WebXR, xr-standard with A/B, X/Y (Quest) */
    HOL_DEVICE_WEBXR_HAND = 10, /* WebXR hand tracking, no controller: a
                                   right pinch confirms, a left pinch opens
                                   the menu, a long pinch (either hand) backs
                                   and in the menu quits
                                   (platform/web/hol_web_xr.h) */
    HOL_DEVICE_XR_HAND = 11,    /* OpenXR hands (XR_EXT_hand_interaction):
                                   pinches and grasps
                                   (platform/openxr/hol_xr_bind.h) */
    HOL_DEVICE_SCREEN = 12,     /* the web page's touch screen: its
                                   on-screen buttons (OK, Back, Menu, Map,
                                   the arrows) and swipes */
    HOL_DEVICE_COUNT = 13
};

enum { HOL_HAND_LEFT = 0, HOL_HAND_RIGHT = 1 };

/* A tracked hand's joints, in WebXR's order (XRHand): the wrist, then
 * four of the thumb (metacarpal, proximal, distal, tip) and five of each
 * finger (metacarpal, proximal, intermediate, distal, tip). */
#define HOL_HAND_JOINTS 25
enum { /* the joints the app reads (a finger's: its metacarpal + 0..4) */
    HOL_JOINT_WRIST = 0, HOL_JOINT_THUMB_METACARPAL = 1, HOL_JOINT_THUMB_TIP = 4,
    HOL_JOINT_INDEX_METACARPAL = 5, HOL_JOINT_INDEX_TIP = 9, HOL_JOINT_PINKY_METACARPAL = 20
};

typedef struct hol_hand_joints {
    uint32_t tracked;                 /* 1: every joint below is tracked */
    float pos[HOL_HAND_JOINTS][3];    /* metres, room coordinates */
    float radius[HOL_HAND_JOINTS];    /* metres (WebXR's radius; 0: 8 mm) */
} hol_hand_joints;

typedef struct hol_pose {
    float pos[3];  /* metres, room coordinates */
    float quat[4]; /* x, y, z, w; identity: looking north, up +y */
} hol_pose;

typedef struct hol_input {
    double time_s;     /* seconds since the session began; never decreases */
    uint32_t flags;    /* HOL_INPUT_* */
    uint32_t buttons;  /* HOL_BTN_* held */
    hol_pose head;     /* head (centre eye) */
    hol_pose hand[2];  /* grip poses, HOL_HAND_LEFT / HOL_HAND_RIGHT */
    float move[2];     /* pancake walk: [0] right +, [1] forward + */
    float turn[2];     /* pancake look: [0] turn left + (yaw), [1] look up + */
    uint32_t pressed;  /* HOL_BTN_* pressed since the previous record */
    uint32_t device;   /* HOL_DEVICE_* in use */
    float snap_yaw_deg; /* with HOL_INPUT_SNAP_YAW: the look's new yaw */
    hol_hand_joints joints[2]; /* tracked hands (see above; not recorded) */
} hol_input;

#endif
