/* hol_props.h - where real props stand in the room: the plan that
 * `holonomy props` prints (docs/headset.md, "Props").
 *
 * Contract
 * - The room (SPEC 1 and 7): C x R cells of M metres, x east 0..C*M, z
 *   south 0..R*M, the north-west corner at (0, 0). Every tile of the
 *   forest maps onto the same room, so the room's own trees and hedges
 *   are the same wherever the player is: a few real props stand in for
 *   every virtual hedge and trunk (haptic retargeting).
 * - Trees: a trunk stands on every vertex of the room's grid, (C+1)(R+1)
 *   of them at (i*M, j*M), i 0..C, j 0..R: `inner` (0 < i < C and
 *   0 < j < R: free-standing in the walking area), `corner` (the room's
 *   four corners) and `side` (the others on the edges, in the hedge
 *   line). Listed row by row from the north (j), west to east (i).
 *   HOL_PROPS_TRUNK_M is the largest virtual trunk's base radius.
 * - Hedges: one piece along every cell edge of the room's boundary,
 *   2(C + R) of them: the north side west to east, then the east side
 *   north to south, the south side east to west, the west side south to
 *   north.
 * - A play area (optional, width x depth metres) is centred on the room
 *   (hol_fit.h: the room is centred on the play area's origin).
 * - The page: the plan at 1:N on the first of A4 portrait, A4 landscape,
 *   A3 portrait, A3 landscape where it fits with its margins (header,
 *   measurements, the list of trees). scale 0 takes the first of 20, 25,
 *   50, 100 that fits; a scale asked for that fits no page is HOL_ERANGE.
 *   Page coordinates are millimetres from the page's top-left corner,
 *   north up (page y grows with z).
 * - Pure: no allocation, no I/O.
 */
#ifndef HOL_PROPS_H
#define HOL_PROPS_H

#include "hol_err.h"
#include "hol_haptic.h"

#define HOL_PROPS_TRUNK_M HOL_HAPTIC_TRUNK_M /* the widest virtual trunk's base radius */
#define HOL_PROPS_MAX_TREES 36     /* (5+1)(5+1) */
#define HOL_PROPS_MAX_HEDGES 20    /* 2(5+5) */
#define HOL_PROPS_SCALE_MIN 5
#define HOL_PROPS_SCALE_MAX 200
#define HOL_PROPS_AREA_MAX 20.0    /* metres a side of a play area */
/* Page margins and the room's surroundings, millimetres. */
#define HOL_PROPS_MARGIN_MM 15.0
#define HOL_PROPS_HEAD_MM 30.0     /* title, scale, the scale bar */
#define HOL_PROPS_DIM_MM 14.0      /* a dimension line's room (top and left) */
#define HOL_PROPS_RIGHT_MM 6.0
#define HOL_PROPS_FOOT_MM 50.0     /* the list of trees, the notes */

enum { HOL_PROPS_INNER = 0, HOL_PROPS_SIDE = 1, HOL_PROPS_CORNER = 2 };

typedef struct hol_props_desc {
    int cols, rows;        /* 3..5 */
    double cell_m;         /* 0.5..1.5 */
    int scale;             /* N of 1:N, HOL_PROPS_SCALE_MIN..MAX; 0: automatic */
    double area_w, area_d; /* a play area's metres, 0 for none (then both 0) */
} hol_props_desc;

typedef struct hol_props_tree {
    double x, z; /* metres, room coordinates */
    int i, j;    /* the vertex: column line 0..C, row line 0..R */
    int kind;    /* HOL_PROPS_INNER, _SIDE or _CORNER */
} hol_props_tree;

typedef struct hol_props_hedge {
    double x0, z0, x1, z1; /* metres */
} hol_props_hedge;

typedef struct hol_props {
    int cols, rows;
    double cell_m, room_w, room_d; /* room_w = cols * cell_m */
    int ntrees, ninner, nhedges;
    hol_props_tree trees[HOL_PROPS_MAX_TREES];
    hol_props_hedge hedges[HOL_PROPS_MAX_HEDGES];
    int has_area;
    double area_x0, area_z0, area_w, area_d; /* the play area, room coordinates */
    /* the page */
    int scale;            /* N of 1:N */
    const char *page;     /* "A4 portrait", ... */
    double page_w, page_h; /* mm */
    double ox, oy;         /* mm: where the room's (0, 0) lies on the page */
} hol_props;

/* The plan of d. Errors: HOL_EARG (a side outside 3..5, a cell outside
 * 0.5..1.5 m, a scale outside its bounds, a play area side not finite or
 * outside (0, HOL_PROPS_AREA_MAX], or only one of its sides),
 * HOL_ERANGE (the scale asked for fits no page). *out is untouched on
 * error. */
hol_err hol_props_plan(const hol_props_desc *d, hol_props *out);

/* Room metres to page millimetres. */
static inline double hol_props_px(const hol_props *p, double x) { return p->ox + x * 1000.0 / p->scale; }
static inline double hol_props_py(const hol_props *p, double z) { return p->oy + z * 1000.0 / p->scale; }

#endif
