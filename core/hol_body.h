/* hol_body.h - the user's body as a headset shows it: the controllers and
 * the tracked hands at their room poses, the pointing task's ray, and the
 * hands-only recentre gesture.
 *
 * Contract
 * - hol_body_from_input fills the view's body (hol_app_view.body) from the
 *   step's record: a hand with tracked joints (hol_input.joints) is drawn
 *   as its joints (HOL_BODY_HAND), else a tracked grip
 *   (HOL_INPUT_HAND_*_VALID) as the controller model of the device in use
 *   (HOL_BODY_CONTROLLER, model by profile: hol_body_model), else nothing.
 *   Poses are the record's, in room coordinates, copied bit for bit: the
 *   body is drawn in the room (the eye's frame), never moved by a tile's
 *   transform, so after any loop of room steps the hands are drawn where
 *   the real hands are (holonomy turns the world, not the room).
 * - The app (hol_app_view.body) leaves the left controller out while the
 *   minimap is in the hand (HOL_MINIMAP_HAND): the platforms draw the map
 *   at that grip, so the map is what it holds (a tracked hand stays).
 * - The ray: while the pointing question is asked with a tracked head
 *   (state HOL_APP_POINT) from the hand that points (hol_app_point: the
 *   right grip when tracked, else the left), along the grip's -z axis,
 *   HOL_BODY_RAY_M long; ray_hand -1 otherwise.
 * - The hands-only recentre (a documented gesture, docs/headset.md): both
 *   palms up, hands open (no pinch), held HOL_GESTURE_HOLD_S. A palm is up
 *   when the normal of the triangle wrist, index metacarpal, pinky
 *   metacarpal (towards the palm) is within HOL_GESTURE_PALM_DEG of +y;
 *   open when the thumb's and index's tips are more than
 *   HOL_GESTURE_OPEN_M apart. hol_gesture_step gives HOL_BTN_RECENTRE once
 *   when the hold is reached; the next needs a palm down (or a hand lost)
 *   first. A platform calls it on each focused record and puts the
 *   button in the record's pressed bits, placing its room from the head as
 *   for its recentre control, so the app recentres exactly as for the
 *   controller's (the record, and a recording, carry the button).
 * - The seated step by hand (issue 37; docs/teaching.md, "Seated play"):
 *   in seated play (HOL_INPUT_SEATED) a pinch dragged across the floor
 *   (a "pinch and flick") takes one room step in the direction the hand
 *   went, relative to the look: the pinch point (the middle of the thumb's
 *   and the index's tips of a tracked hand, else the hand's grip) moved
 *   HOL_FLICK_M or more horizontally from where the pinch began, within
 *   HOL_FLICK_S of its beginning, gives the edge of HOL_BTN_STEP_FWD,
 *   BACK, LEFT or RIGHT, whichever of the look's four directions (the
 *   head's forward, level) the move is nearest (a tie: ahead or back).
 *   One step a pinch: the next needs the pinch let go and made anew. A
 *   pinch that took a step is used up (hol_flick.stepped): the platform
 *   makes its end press nothing and never a long pinch of it (so it is
 *   never a confirm, a menu or a back); a pinch that did not is the
 *   platform's as before (a tap moves less than HOL_FLICK_M, a long pinch
 *   is back only after HOL_FLICK_S has passed). The palms-up recentre
 *   needs open hands, never a pinch. hol_flick_step reads the record's
 *   head (tracked: HOL_INPUT_HEAD_VALID), the joints or grips (room
 *   coordinates) and the platform's pinches (each hand's select, held,
 *   while focused); it returns at most one step bit, which the platform
 *   puts in the record's pressed bits (a recording carries it; the core
 *   steps as for a thumbstick's push: core/hol_input.h).
 * - A tracked hand's joints as a runtime gives them (OpenXR's
 *   XR_EXT_hand_tracking, WebXR's XRHand) are usable only whole:
 *   hol_hand_joints_usable is 1 when every one of the HOL_HAND_JOINTS is
 *   located (bit i of `located` set for joint i; HOL_HAND_LOCATED_ALL:
 *   all) and each of its coordinates is finite and under
 *   HOL_HAND_REACH_M in magnitude (checked in the runtime's own space,
 *   before any calibration); else 0, and the platform draws no hand (its
 *   grip's controller instead, as for a hand the runtime lost). Both
 *   headset platforms (platform/shell/hol_xr_hand.c,
 *   platform/web/hol_web_xr.c) decide by it.
 * - Pure: no allocation, no globals, no clock (times come in).
 */
#ifndef HOL_BODY_H
#define HOL_BODY_H

#include <stdint.h>

#include "hol_input.h"

#define HOL_BODY_RAY_M 3.0      /* the pointing ray's length, metres */
#define HOL_GESTURE_HOLD_S 1.0  /* both palms up this long: recentre */
#define HOL_GESTURE_PALM_DEG 35.0
#define HOL_GESTURE_OPEN_M 0.04

enum hol_body_kind { HOL_BODY_NONE = 0, HOL_BODY_CONTROLLER = 1, HOL_BODY_HAND = 2 };

/* The controller's model by interaction profile (render/hol_body_draw.c
 * holds their shapes). */
enum hol_body_model {
    HOL_BODY_MODEL_PLAIN = 0, /* a grip and a pointer tip (simple, others) */
    HOL_BODY_MODEL_TOUCH = 1, /* Quest Touch: a grip and a tracking ring */
    HOL_BODY_MODEL_WAND = 2,  /* Vive wand: a long grip and a head */
    HOL_BODY_MODEL_INDEX = 3, /* Index knuckles: a grip and a strap */
    HOL_BODY_MODEL_COUNT = 4
};

typedef struct hol_body_part {
    int kind;               /* hol_body_kind */
    int model;              /* HOL_BODY_CONTROLLER: hol_body_model */
    hol_pose pose;          /* the grip's pose (HAND: the grip if tracked,
                               else the wrist's position, no turn) */
    hol_hand_joints joints; /* HOL_BODY_HAND: the joints */
} hol_body_part;

typedef struct hol_body {
    hol_body_part hand[2];  /* HOL_HAND_LEFT, HOL_HAND_RIGHT */
    int ray_hand;           /* -1: no ray; else the hand it starts from */
    double ray_m;           /* its length */
} hol_body;

/* The body of record in (NULL: none); pointing 1 while the pointing
 * question is asked. */
void hol_body_from_input(const hol_input *in, int pointing, hol_body *out);

/* The model drawn for a device (HOL_DEVICE_*). */
int hol_body_model_of(uint32_t device);

#define HOL_HAND_REACH_M 1e4f /* a joint this far (metres) or further: no hand */
#define HOL_HAND_LOCATED_ALL ((1u << HOL_HAND_JOINTS) - 1u)

/* 1 when the HOL_HAND_JOINTS positions pos (the runtime's space, metres)
 * with the joints located (bit i: joint i) make a usable hand (see
 * above), else 0. */
int hol_hand_joints_usable(const float pos[HOL_HAND_JOINTS][3], uint32_t located);

/* 1 when hand h (HOL_HAND_*) is tracked, its palm up and open. */
int hol_gesture_palm_up(const hol_hand_joints *j, int h);

typedef struct hol_gesture {
    int up;                 /* both palms up since t0 */
    int spent;              /* fired in this hold */
    double t0;
} hol_gesture;

/* One record's joints at time t (seconds, never decreasing): HOL_BTN_RECENTRE
 * at the record where both palms have been up HOL_GESTURE_HOLD_S, else 0.
 * Zero the state to begin. */
uint32_t hol_gesture_step(hol_gesture *g, const hol_hand_joints joints[2], double t);

#define HOL_FLICK_M 0.12 /* a pinch dragged this far (metres, level): a step */
#define HOL_FLICK_S 0.8  /* within this long of its beginning (seconds; a
                            long pinch, back, is 1 s) */

typedef struct hol_flick {
    int on[2];          /* hand h pinches (with a pinch point) since t0[h] */
    int spent[2];       /* its step is taken, or its time is up */
    int stepped[2];     /* 1: this pinch took a step (used up) */
    double t0[2];
    double at0[2][3];   /* where its pinch point began (room) */
} hol_flick;

/* The pinch point of hand h of in (room coordinates) into out; 0 when
 * the hand has neither joints nor a grip. */
int hol_flick_point(const hol_input *in, int h, double out[3]);

/* One record in (its time, head, joints, grips) with pinch[h] 1 while
 * hand h pinches: the step's button (HOL_BTN_STEP_*) or 0. Zero the
 * state to begin. */
uint32_t hol_flick_step(hol_flick *g, const hol_input *in, const int pinch[2]);

#endif
