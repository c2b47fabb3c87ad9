/* hol_view.h - what the user sees: camera maths and the portal view
 * branches of a room of C x R cells (SPEC sections 1, 2 and 7). Pure CPU
 * code, no GL.
 *
 * Contract
 * - Room coordinates in metres: x east, y up, z south; cell (c,r) spans
 *   x in [c*M,(c+1)*M], z in [r*M,(r+1)*M] for cells of M metres (the
 *   camera works in metres; hol_view_build takes the eye in cells, i.e.
 *   metres / M, since the branches do not depend on M). The room's size
 *   and the tiling are the user state's (hol_room_cols/rows, the tile
 *   word's hol_tile_q). yaw 0 looks north (-z), positive yaw turns
 *   west (counter-clockwise from above), positive pitch looks up; vertical
 *   field of view fovy, square pixels.
 * - A floor point shows the tile reached by walking, from the eye's cell,
 *   the cells that the eye-to-point segment crosses (projected on the
 *   floor), with hol_room_step semantics on the user's state. All floor
 *   points inside the room with the same crossing sequence form one *branch*.
 * - The floor-projected direction of a pixel's ray fixes the whole sequence
 *   of cells along it up to and including the step that leaves the room:
 *   the *leaf*. Leaves are the angular wedges between the directions from
 *   the eye to the (C+1)(R+1) room vertices (segments through a vertex are
 *   hidden by the trunk standing there). In the 3 x 3 room each leaf gets
 *   a 7-bit stencil code; a
 *   branch (any in-room prefix of a leaf) is drawn where
 *   (stencil & mask) == ref, so each branch costs one stencil-tested draw
 *   and the whole stencil is written by one polygon per leaf:
 *     bits 0-1: the first step (room direction N 0, W 1, S 2, E 3);
 *     bit 2:    the side the sequence turns to (1: first step + 1, i.e.
 *               to the left), if it turns at all;
 *     bit 1+i:  step i (i = 2..5) differs from the first step.
 *   A straight half-line only ever steps in its first direction or in one
 *   fixed side direction, so the code is a prefix code of the sequence.
 * - Larger rooms (a sequence of up to 9 steps does not fit 7 bits): the
 *   view has `wedges` set, no branch has a stencil test (ref = mask = 0)
 *   and each branch carries its wedge instead: the floor directions w0,
 *   w1 from the eye such that a point p belongs to the branch's leaves
 *   when cross(w0, p - eye) >= 0 and cross(p - eye, w1) >= 0 on the floor
 *   (x, z); the leaves of a branch are contiguous in angle, and the
 *   renderer discards fragments outside the wedge. Every branch (3 x 3
 *   too) gets its wedge; branch 0 (the eye's cell) has none (all zero).
 * - Floor outside the room is not shown (the boundary hedges hide it; see
 *   render/hol_render.h); the exit step only makes the codes prefix-free.
 * - Euclidean mode (baseline): one branch per cell, the tile reached by the
 *   room walk columns first then rows, no stencil.
 */
#ifndef HOL_VIEW_H
#define HOL_VIEW_H

#include <stdint.h>

#include "../core/hol_room.h"

/* (C+1)(R+1) vertex directions in a 5 x 5 room; up to 9 steps and the one
 * leaving the room; branches: every in-room prefix of every leaf. */
#define HOL_VIEW_MAX_LEAVES 36
#define HOL_VIEW_MAX_STEPS 10
#define HOL_VIEW_MAX_BRANCHES 128
#define HOL_VIEW_STENCIL_CLEAR 0x80 /* matches no branch */

typedef struct hol_camera {
    double eye[3];    /* room coordinates */
    double yaw_deg;
    double pitch_deg; /* -90..90 */
    double fovy_deg;  /* 0 means 90 */
    int width, height;
    double znear, zfar; /* 0 means 0.05 and 60 */
    /* Headset form (what OpenXR gives per eye): when has_pose is set, the
     * orientation is the unit quaternion (x, y, z, w) taking view space
     * (x right, y up, looking down -z) to room space, roll included, and
     * the four tangents of the half-angles give an asymmetric field of
     * view (tan_left and tan_down negative); yaw, pitch and fovy are then
     * ignored. */
    int has_pose;
    double orient[4];
    double tan_left, tan_right, tan_down, tan_up;
} hol_camera;

typedef struct hol_view_leaf {
    double u0[2], u1[2];  /* floor directions (x,z) bounding the wedge */
    uint8_t code;         /* stencil value */
    uint8_t nsteps;       /* steps including the one leaving the room */
    uint8_t steps[HOL_VIEW_MAX_STEPS];
} hol_view_leaf;

typedef struct hol_view_branch {
    hol_room state;       /* tile, orientation; col,row = the cell */
    uint8_t nsteps;
    uint8_t steps[HOL_VIEW_MAX_STEPS];
    uint8_t ref, mask;    /* stencil test; mask 0: no test */
    double w0[2], w1[2];  /* the wedge of the branch's leaves (x, z) */
    hol_err err;          /* HOL_ERANGE: beyond the reach, not drawn */
} hol_view_branch;

typedef struct hol_view {
    int euclidean;
    int wedges;           /* 1: branches are told apart by wedges, not
                             stencil codes (rooms other than 3 x 3) */
    int nleaves;
    hol_view_leaf leaves[HOL_VIEW_MAX_LEAVES];
    int nbranches;        /* branches[0] is the eye's cell */
    hol_view_branch branches[HOL_VIEW_MAX_BRANCHES];
} hol_view;

/* Tangents of the frustum's half-angles (left and down negative). */
void hol_camera_tangents(const hol_camera *cam, double *out_l, double *out_r,
                         double *out_d, double *out_u);
/* Basis of the camera: right, up, back (world vectors). */
void hol_camera_basis(const hol_camera *cam, double out_r[3], double out_u[3],
                      double out_b[3]);
/* Column-major 4x4 view and projection matrices (float, for GL). */
void hol_camera_matrices(const hol_camera *cam, float out_view[16],
                         float out_proj[16]);
/* The ray direction (world) through normalized device coordinates. */
void hol_camera_ray(const hol_camera *cam, double ndc_x, double ndc_y,
                    double out_dir[3]);

/* Step code of a sequence of room directions (see above). */
uint8_t hol_view_code(const uint8_t *steps, int n);
/* Mask testing the first n steps of a sequence (n >= 1). */
uint8_t hol_view_mask(const uint8_t *steps, int n);

/* Build the leaves and branches for a user state and an eye position in
 * cells (x, z in metres divided by the cell size; strictly inside the
 * user's cell). Errors: HOL_EARG (eye not inside the cell, a room size
 * outside 3..5). Branches beyond the reach of tile words get err =
 * HOL_ERANGE. */
hol_err hol_view_build(const hol_room *user, double ex, double ez, int euclidean,
                       hol_view *out);

/* The screen region of a leaf: a convex polygon in normalized device
 * coordinates (the wedge clipped to [-1,1]^2). Returns the vertex count
 * (0 when the wedge is off screen); out holds up to 8 points. */
int hol_view_leaf_ndc(const hol_camera *cam, const hol_view_leaf *leaf,
                      float out_xy[8][2]);

#endif
