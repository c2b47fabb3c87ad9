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
 * - Buttons are bits of HOL_BTN_*, set while held; edges (pressed this
 *   frame) are the app step's business, from the previous record.
 * - Axes are in [-1, 1] after the platform's dead zone; zero is at rest.
 *   The app step turns them into motion (pancake mode); a headset sends
 *   zero axes and a tracked head.
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

/* buttons (held) */
#define HOL_BTN_CONFIRM  (1u << 0) /* confirm / next level */
#define HOL_BTN_BACK     (1u << 1) /* back / cancel */
#define HOL_BTN_MENU     (1u << 2) /* pause menu */
#define HOL_BTN_RECENTRE (1u << 3) /* place the room from the head pose */
#define HOL_BTN_MINIMAP  (1u << 4) /* cycle minimap: HUD, hand, off */
#define HOL_BTN_RESTART  (1u << 5) /* restart the level */
#define HOL_BTN_QUIT     (1u << 6) /* leave the app */
#define HOL_BTN_ALL      0x7fu

enum { HOL_HAND_LEFT = 0, HOL_HAND_RIGHT = 1 };

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
} hol_input;

#endif
