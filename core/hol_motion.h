/* hol_motion.h - room following: the user's continuous head position in the
 * room, turned into room steps.
 *
 * Contract
 * - The user is a room state (hol_room: tile, room north, cell) plus a head
 *   position in room coordinates (SPEC section 1: metres, x east, y up, z
 *   south, move area x, z in [0, 3]; in [0, C*M] and [0, R*M] for a room
 *   of C x R cells (hol_room_cols and rows of the state) of M metres
 *   (desc.cell_m, SPEC 7)) and a look direction (yaw 0 north,
 *   positive turns west; pitch positive up). The head always lies strictly
 *   inside the state's cell.
 * - Moving the head from one position to another walks the cells that the
 *   floor projection of the segment crosses, in order along it: crossing a
 *   cell edge is one room step (hol_room_step), and the world follows.
 * - Hedges stop you: a target position is first clamped to the move area
 *   less a margin (desc.margin), so the room never refuses a step. A head
 *   never stands exactly on a grid line (it is nudged by 1e-6 m), so the
 *   cell is always defined. Two crossings at the same point of the segment
 *   (through a vertex, where a trunk stands) go x first, then z.
 * - Pancake mode (hol_motion_pancake): the input's move axes walk along the
 *   look direction at desc.speed, its turn axes turn at desc.turn_rate and
 *   tilt at desc.pitch_rate; pitch is held in [-89, 89] degrees.
 * - Pure: doubles and integer tile work only; no allocation, no globals, no
 *   clock (the caller passes dt).
 */
#ifndef HOL_MOTION_H
#define HOL_MOTION_H

#include <stdint.h>

#include "hol_err.h"
#include "hol_room.h"

/* Most room steps one move can take: every inner grid line of the largest
 * room, four x and four z (two of each in a 3 x 3 room). */
#define HOL_MOTION_MAX_STEPS 8

typedef struct hol_motion_desc {
    double speed;      /* m/s at full move axis; 0: 1.4 */
    double turn_rate;  /* degrees/s at full turn axis; 0: 120 */
    double pitch_rate; /* degrees/s at full look axis; 0: 90 */
    double margin;     /* metres kept from the hedges; 0: 0.15 */
    double eye_height; /* metres, the pancake head's y; 0: 1.6 */
    double cell_m;     /* a cell's side in metres (SPEC 7: cell (c,r) spans
                          x in [c*M, (c+1)*M]); 0 or outside 0.5..1.5: 1 */
} hol_motion_desc;

#define HOL_MOTION_MIN_CELL 0.5
#define HOL_MOTION_MAX_CELL 1.5

typedef struct hol_motion {
    hol_room user;     /* the room state; the head is inside its cell */
    double head[3];    /* room coordinates */
    double yaw_deg;    /* look direction (pancake; tracked heads set it) */
    double pitch_deg;
    long steps;        /* room steps taken since init */
    hol_motion_desc d; /* with defaults filled in */
} hol_motion;

/* The steps one call took, in order (room directions HOL_DIR_*), and the
 * state after each. */
typedef struct hol_motion_steps {
    int n;
    uint8_t dir[HOL_MOTION_MAX_STEPS];
    hol_room after[HOL_MOTION_MAX_STEPS];
} hol_motion_steps;

/* Start at room state `user`, the head at its cell's centre at eye height,
 * looking north and 30 degrees down. desc may be NULL (defaults). */
void hol_motion_init(hol_motion *m, const hol_room *user, const hol_motion_desc *desc);

/* Move the head to pos (x and z clamped to the move area less the margin;
 * y taken as given). out_steps (may be NULL) lists the room steps taken.
 * Errors: HOL_ERANGE (a step would go beyond the reach of tile words: the
 * head stops at the last cell edge before it, steps up to there are kept
 * and listed). */
hol_err hol_motion_move_to(hol_motion *m, const double pos[3],
                           hol_motion_steps *out_steps);

/* Re-place the room around the head (a recentre: the room was placed anew
 * in tracking space, so the head's room position jumped without the user
 * walking): the head goes to pos (x and z clamped as in
 * hol_motion_move_to) with no room step. The user keeps the tile; the
 * cell becomes the one under the head; the room's north turns by the
 * quarter turns nearest to (yaw_was_deg - m->yaw_deg), so the look keeps
 * its direction in the world within 45 degrees (m->yaw_deg is the look in
 * the new room, yaw_was_deg the look before). steps is unchanged. */
void hol_motion_replace(hol_motion *m, const double pos[3], double yaw_was_deg);

/* Pancake: turn and tilt by turn[0] (left +) and turn[1] (up +), then walk
 * move[1] forward and move[0] right for dt seconds (axes in [-1, 1], larger
 * values are clamped). Errors as hol_motion_move_to; HOL_EARG for a dt
 * that is negative or not finite. */
hol_err hol_motion_pancake(hol_motion *m, const float move[2], const float turn[2],
                           double dt, hol_motion_steps *out_steps);

/* Snap turn: the yaw (degrees, [0, 360)) after `turns` snaps of step_deg
 * from yaw_deg (positive turns: left, as yaw grows). Each snap goes to the
 * next multiple of step_deg in its direction, so the first aligns the look
 * with the multiples (with 90: the room's axes) and the rest keep it. */
double hol_motion_snap_yaw(double yaw_deg, double step_deg, int turns);

/* The room state an eye sees from (stereo): `user` walked across the cells
 * that the floor projection of the segment from `head` (inside the user's
 * cell) to `eye` crosses, so an eye that leans over a cell edge sees
 * exactly what a sight line from the head through it would. Errors:
 * HOL_EARG (head not inside the user's cell), HOL_EROOM (eye outside the
 * room), HOL_ERANGE. */
hol_err hol_motion_eye_state(const hol_room *user, const double head[3],
                             const double eye[3], hol_room *out_state);
/* The same in a room of cells of cell_m metres (0: 1 m); the app's view
 * has it in hol_app_view.cell_m. hol_motion_eye_state is cell_m 1. */
hol_err hol_motion_eye_state_m(const hol_room *user, double cell_m, const double head[3],
                               const double eye[3], hol_room *out_state);

#endif
