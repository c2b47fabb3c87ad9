/* hol_haptic.h - the controllers' pulses: which controller, which pulse, a
 * frame at a time (issue 25, "the body in the room"). The app step decides
 * (hol_app_events.haptic); a platform only plays them (OpenXR
 * xrApplyHapticFeedback).
 *
 * Contract
 * - Contact: a tracked hand (grip pose, room coordinates) is in a hedge
 *   when it is beyond the room's boundary (x outside 0..C*M or z outside
 *   0..R*M) below the hedge's top (HOL_HAPTIC_HEDGE_TOP_M), and in a
 *   trunk when it is within HOL_HAPTIC_TRUNK_M of a vertex of the room's
 *   grid horizontally (core/hol_props.h: the trunks stand on the (C+1)(R+1)
 *   vertices) below the trunk's top (HOL_HAPTIC_TRUNK_TOP_M), above the
 *   floor in both cases.
 * - A hand that goes into a hedge or a trunk gets one short pulse
 *   (HOL_HAPTIC_HIT_*), that hand only; it gets another only after it has
 *   come out by HOL_HAPTIC_CLEAR_M (no buzz while it stays in, no chatter
 *   on the surface). A hand that is not tracked this frame keeps its state.
 * - Each room step of the frame gives both tracked hands a gentle pulse
 *   (HOL_HAPTIC_STEP_*) unless a contact pulse plays on that hand.
 * - enabled 0 (the off switch: holonomy xr --no-haptics, or paused): no
 *   pulse; the contacts are still followed, so switching on mid-contact
 *   does not pulse.
 * - Pure: no allocation, no I/O; the state zeroed is the start.
 */
#ifndef HOL_HAPTIC_H
#define HOL_HAPTIC_H

#include <stdint.h>

#include "hol_input.h"

#define HOL_HAPTIC_TRUNK_M 0.11      /* the widest trunk's base radius */
#define HOL_HAPTIC_TRUNK_TOP_M 3.2
#define HOL_HAPTIC_HEDGE_TOP_M 2.0
#define HOL_HAPTIC_CLEAR_M 0.02      /* out by this much before another pulse */
#define HOL_HAPTIC_HIT_AMP 0.8f
#define HOL_HAPTIC_HIT_MS 40
#define HOL_HAPTIC_STEP_AMP 0.25f
#define HOL_HAPTIC_STEP_MS 15

enum { HOL_HAPTIC_NONE = 0, HOL_HAPTIC_HEDGE = 1, HOL_HAPTIC_TRUNK = 2, HOL_HAPTIC_STEP = 3 };

typedef struct hol_haptic_pulse {
    float amplitude; /* 0..1; 0: no pulse */
    int duration_ms;
    int why;         /* HOL_HAPTIC_* */
} hol_haptic_pulse;

/* This frame's pulses, per hand (HOL_HAND_LEFT, HOL_HAND_RIGHT). */
typedef struct hol_haptic {
    hol_haptic_pulse hand[2];
} hol_haptic;

typedef struct hol_haptic_state {
    uint8_t inside[2]; /* the hand is in a hedge or a trunk */
} hol_haptic_state;

/* What a point of room coordinates touches in a room of cols x rows cells
 * of cell_m metres, with the surfaces moved out by grow metres:
 * HOL_HAPTIC_HEDGE, HOL_HAPTIC_TRUNK or HOL_HAPTIC_NONE. */
int hol_haptic_contact(const float pos[3], int cols, int rows, double cell_m, double grow);

/* One frame: in (its hands and their HOL_INPUT_HAND_*_VALID flags), the
 * room, the room steps taken in this frame, enabled. Fills *out. */
void hol_haptic_step(hol_haptic_state *s, const hol_input *in, int cols, int rows, double cell_m,
                     int room_steps, int enabled, hol_haptic *out);

#endif
