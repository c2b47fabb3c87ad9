/* hol_xr_room.h - the 3 x 3 m room in an OpenXR stage, and the session
 * lifecycle, as pure functions (no OpenXR headers, no GL): what the headset
 * layer decides, testable without a runtime (tests/test_xr_room.c).
 *
 * Contract
 * - Stage space (OpenXR): +x right, +y up, looking down -z. Room
 *   coordinates (SPEC sections 1, 7): x east, y up, z south, move area x in
 *   [0, W], z in [0, D] (W = C*M, D = R*M: the room's cells times the cell
 *   size; 3 x 3 m by default). By default the room is centred on the stage
 *   origin with north along stage -z: room = stage + (W/2, 0, D/2) (the
 *   calibration's half_w, half_d; zero: 1.5, the 3 x 3 m room).
 * - Recentre places the room from the head: the head's floor position
 *   becomes the room's centre (W/2, D/2) and the direction it faces
 *   (its forward vector projected on the floor) becomes room north; height
 *   is kept. A head looking straight up or down keeps the previous heading.
 * - Stage bounds (xrGetReferenceSpaceBoundsRect, full width and depth):
 *   the room and cell size are fitted to them (core/hol_fit.h); a room in
 *   play larger than them in either direction is a warning; none is not an
 *   error.
 * - Safety: hol_xr_fade says how far the view fades to the boundary.
 * - Lifecycle: hol_xr_lifecycle maps each session state (the XrSessionState
 *   values, mirrored below) to what the platform must do: READY begins the
 *   session, STOPPING ends it, EXITING and LOSS_PENDING tear it down; the
 *   game runs unpaused only while FOCUSED.
 */
#ifndef HOL_XR_ROOM_H
#define HOL_XR_ROOM_H

#include "../../core/hol_app.h"
#include "../../core/hol_fit.h"
#include "../../core/hol_input.h"

typedef struct hol_xr_calib {
    double yaw;    /* radians: the room's north is stage -z turned by yaw
                      about +y (positive towards -x, as the app's yaw) */
    double ox, oz; /* stage floor point at the room's centre */
    double half_w, half_d; /* the room's half width and depth, metres;
                              0: 1.5 (the 3 x 3 m room) */
} hol_xr_calib;   /* all zero: the default placement */

/* Stage pose -> room pose. */
void hol_xr_to_room(const hol_xr_calib *c, const float stage_pos[3], const float stage_quat[4],
                    hol_pose *out);
/* Room -> stage (for the projection layer and tests). */
void hol_xr_to_stage(const hol_xr_calib *c, const hol_pose *room, float out_pos[3],
                     float out_quat[4]);
/* Place the room from the head's stage pose (see the contract). */
void hol_xr_recentre(hol_xr_calib *c, const float head_pos[3], const float head_quat[4]);

/* 1 when the stage bounds (metres) hold the 3 x 3 m room, 0 when smaller
 * (warn); hol_xr_bounds_hold: the room of room_w x room_d metres. */
int hol_xr_bounds_hold_room(float width, float depth);
int hol_xr_bounds_hold(float width, float depth, double room_w, double room_d);

/* The safety fade of the view (hol_frame_desc.fade) for the tracked,
 * unclamped eyes' room positions: 0 while every eye's floor point lies in
 * the square `margin` metres inside the hedges (where the app's head moves
 * freely; the motion's margin), rising linearly with the distance beyond it
 * to 1 at HOL_XR_FADE_FULL metres inside the boundary, and 1 beyond: the
 * view is gone before an eye leaves the room, and the world never moves
 * (the eyes are drawn where they are; the app's head stays clamped). One
 * value for both eyes, the larger. */
#define HOL_XR_FADE_FULL 0.05
double hol_xr_fade(const double eye[2][3], double margin);
/* The same in a room of room_w x room_d metres (hol_xr_fade: 3 x 3). */
double hol_xr_fade_room(const double eye[2][3], double margin, double room_w, double room_d);
/* Outside the room (v->outside.on, core/hol_app.h): the eyes are drawn
 * where they are (the real head: never a view held still while the head
 * moves), and eye[] is turned into their seats, the points whose room
 * state (cell) they see from: moved by the view's head less the tracked
 * head (in's, on the floor; the motion keeps the view's inside the
 * hedges); the renderer builds its view from the seat's cell
 * (hol_frame_desc.outside). The fade is then 0 (the renderer dims the
 * view). Returns 1 when it moved them, 0 (nothing done) inside the room. */
int hol_xr_outside_eyes(const hol_app_view *v, const hol_input *in, double eye[2][3]);

/* The fit told on the HUD (the headset and the web, for their first
 * seconds): *out = *v with two more short lines, in capitals: "ROOM C X R
 * OF M M" and "FITS YOUR W X D M AREA" when the room in play is the fit;
 * else, with `offered` (the web offers the fit as a link), "C X R OF M
 * FITS: RELOAD"; else the room marked "(ASKED)" (a level or the options
 * named it) or ": TOO BIG" (too small an area) and "YOUR AREA: W X D M".
 * 0 when the HUD has no room for two more lines (*out untouched). */
int hol_xr_fit_note(const hol_fit *f, int offered, const hol_app_view *v, hol_app_view *out);

/* XrSessionState values (OpenXR 1.0, section 10.3). */
enum {
    HOL_XR_STATE_IDLE = 1,
    HOL_XR_STATE_READY = 2,
    HOL_XR_STATE_SYNCHRONIZED = 3,
    HOL_XR_STATE_VISIBLE = 4,
    HOL_XR_STATE_FOCUSED = 5,
    HOL_XR_STATE_STOPPING = 6,
    HOL_XR_STATE_LOSS_PENDING = 7,
    HOL_XR_STATE_EXITING = 8
};

typedef enum hol_xr_do {
    HOL_XR_DO_NOTHING = 0,
    HOL_XR_DO_BEGIN,     /* xrBeginSession, then run frames */
    HOL_XR_DO_END,       /* xrEndSession, stop frames */
    HOL_XR_DO_TEAR_DOWN  /* destroy the session (and leave, or recreate) */
} hol_xr_do;

/* What to do on entering `state`; *out_running says whether frames run
 * (xrWaitFrame/xrBeginFrame/xrEndFrame) and *out_focused whether the game
 * has the input (not paused). */
hol_xr_do hol_xr_lifecycle(int state, int *out_running, int *out_focused);

/* The whole session lifecycle as a state machine fed by events (zero it
 * to start):
 * - hol_xr_life_event(l, state) on each session state change: the action
 *   (hol_xr_lifecycle's), and l->done once the session must be destroyed
 *   and the platform leave (EXITING, LOSS_PENDING). A STOPPING the app did
 *   not ask for (the headset taken off, the app sent to the background)
 *   ends the session and waits: READY begins it again.
 * - hol_xr_life_quit(l) when the app or the platform wants to leave:
 *   HOL_XR_QUIT_REQUEST_EXIT (call xrRequestExitSession; then STOPPING,
 *   EXITING come as events) while the session runs, HOL_XR_QUIT_LEAVE
 *   (l->done: destroy it now) while it does not, HOL_XR_QUIT_NONE when
 *   already asked.
 * - The headset's state in every record (core/hol_input.h: steps only
 *   from a worn, focused, tracked headset; the rule is the core's):
 *   hol_xr_life_state(l) gives HOL_INPUT_HEADSET, HOL_INPUT_WAY_BACK (it
 *   shows the way back into the room), HOL_INPUT_FOCUSED while
 *   FOCUSED, and HOL_INPUT_HEADSET_OFF unless the session is VISIBLE or
 *   FOCUSED (SYNCHRONIZED: the headset is off, its view hidden).
 * - Re-entering walks nothing: a session begun again (READY after a
 *   STOPPING: the headset taken off and put on, the app sent to the
 *   background and back) sets l->off, and the next hol_xr_life_state
 *   gives HOL_INPUT_HEADSET_OFF (and clears it): the frames the stopped
 *   session never ran were the headset off, so the app re-bases the room
 *   around the head where it is now (the `relocated` event when it is in
 *   another cell) and where it went is no walk, no room step is logged.
 * - The runtime's own recentre (hol_xr_life_recentred: the platform calls
 *   it on XrEventDataReferenceSpaceChangePending) sets l->recentre;
 *   hol_xr_life_take(l, head) gives HOL_INPUT_RECENTRED for the first
 *   record with a tracked head after it (and clears it), so the app
 *   re-places the room around the head (a recentre: no walk, no event). */
typedef struct hol_xr_life {
    int state;          /* the last session state (0: none yet) */
    int running;        /* frames run */
    int focused;        /* the game has the input */
    int quit_requested; /* xrRequestExitSession was called */
    int done;           /* destroy the session and leave */
    int begins;         /* sessions begun (READY) so far */
    int recentre;       /* the next record with a head re-places the room */
    int off;            /* begun again: the next record says the headset
                           was off */
} hol_xr_life;

typedef enum hol_xr_quit {
    HOL_XR_QUIT_NONE = 0,
    HOL_XR_QUIT_REQUEST_EXIT,
    HOL_XR_QUIT_LEAVE
} hol_xr_quit;

hol_xr_do hol_xr_life_event(hol_xr_life *l, int state);
hol_xr_quit hol_xr_life_quit(hol_xr_life *l);
void hol_xr_life_recentred(hol_xr_life *l);
uint32_t hol_xr_life_take(hol_xr_life *l, int head_valid);
uint32_t hol_xr_life_state(hol_xr_life *l);

#endif
