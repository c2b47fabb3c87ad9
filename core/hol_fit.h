/* hol_fit.h - the room and cell size that fit a play area: what the
 * headset (OpenXR stage bounds) and the web (WebXR bounded-floor) offer
 * the player when the runtime says how large the play area is.
 *
 * Contract
 * - Choices (SPEC 7): a room of C x R cells, C and R from 3 to 5, cells of
 *   M metres, M from 0.5 to 1.5 in steps of HOL_FIT_STEP_CM centimetres
 *   (a size a player can read and a log can name exactly). Columns run
 *   along the play area's width (stage x), rows along its depth (stage z).
 * - Fits: the room, with `margin` metres kept clear on every side, lies
 *   inside the play area: (C*M + 2 margin) x (R*M + 2 margin). For a
 *   polygon (WebXR boundsGeometry) the room is centred on the origin of
 *   the bounded space, axis-aligned, and must lie inside the polygon.
 * - The rule, in order:
 *   1. the most cells (C*R) among the rooms whose cells are at least
 *      HOL_FIT_COMFORT_CM (a step a player takes without shuffling), then
 *      the largest cell, then more columns;
 *   2. when no room fits with cells that large: 3 x 3 with the largest
 *      cell that fits (small cells rather than fewer: a 2 x 2 room is
 *      useless, issue 20);
 *   3. when not even 3 x 3 cells of 0.5 m fit: 3 x 3 of 0.5 m and
 *      too_small set: the platform raises HOL_INPUT_BOUNDS_SMALL and says
 *      the play area is too small.
 *   So a 3.2 x 3.2 m area (margin 0.1: 3.0 m usable) gets 5 x 5 cells of
 *   0.6 m, 2.6 x 2.6 m gets 4 x 4 of 0.6 m, 2.0 x 2.0 m 3 x 3 of 0.6 m.
 * - Who wins: the platform fits only what neither the level file nor the
 *   command line / URL names (a level's `room`/`cell` lines and --room /
 *   --cell / ?room= / ?cell= are kept as given); without bounds from the
 *   runtime nothing is fitted (the default 3 x 3 of 1 m).
 * - Pure: no allocation, no I/O.
 */
#ifndef HOL_FIT_H
#define HOL_FIT_H

#include <stddef.h>

#include "hol_err.h"
#include "hol_level.h"

#define HOL_FIT_MARGIN 0.1      /* metres clear on every side (default) */
#define HOL_FIT_STEP_CM 5       /* cell sizes are multiples of 5 cm */
#define HOL_FIT_MIN_CM 50
#define HOL_FIT_MAX_CM 150
#define HOL_FIT_COMFORT_CM 60   /* smallest cell for a room beyond 3 x 3 */
#define HOL_FIT_MAX_POINTS 64   /* polygon vertices read */

typedef struct hol_fit {
    int cols, rows;      /* 3..5 */
    int cell_cm;         /* 50..150, a multiple of HOL_FIT_STEP_CM */
    double cell_m;       /* cell_cm / 100 */
    int too_small;       /* 1: not even 3 x 3 of 0.5 m fits (rule 3) */
    double area_w, area_d; /* the play area's width and depth (a polygon's
                              bounding box), metres */
} hol_fit;

/* A width x depth metres rectangle (OpenXR xrGetReferenceSpaceBoundsRect,
 * centred on the stage origin). margin < 0: HOL_FIT_MARGIN. Errors:
 * HOL_EARG (a size not finite or not above 0). */
hol_err hol_fit_rect(double width, double depth, double margin, hol_fit *out);

/* A polygon of n points (x, z pairs, metres, in order round the area;
 * 3 <= n <= HOL_FIT_MAX_POINTS): WebXR's boundsGeometry. Errors: HOL_EARG
 * (too few or too many points, a coordinate not finite). */
hol_err hol_fit_polygon(const float *xz, int n, double margin, hol_fit *out);

/* 1 when the room of cols x rows cells of cell_cm, with the margin, lies
 * inside the polygon centred on its origin (the test rule 1-3 use). */
int hol_fit_polygon_holds(const float *xz, int n, double margin, int cols, int rows,
                          int cell_cm);

/* The line that tells the user: "Room 4 x 4 cells of 0.6 m fits your
 * 2.6 x 2.6 m play area", or for too_small "Your 1.2 x 1.4 m play area is
 * smaller than the smallest room (3 x 3 cells of 0.5 m and 0.1 m clear):
 * playing 3 x 3 cells of 0.5 m, keep to the middle". Returns the length
 * (snprintf's). */
int hol_fit_text(const hol_fit *f, double margin, char *buf, size_t cap);
/* The same line in lang (hol_lang, core/hol_str.h) for the player (the web
 * page's status); hol_fit_text is its English, for the tools' lines. */
int hol_fit_say(const hol_fit *f, double margin, int lang, char *buf, size_t cap);

/* Plays the fit in a level that names neither a room nor a cell (its
 * lvl.room_cols and lvl.cell_m are 0): hol_level_set_geometry, the
 * lines "room C R" and "cell M" added to the level's text, which is made
 * again (so its hash, the logs and the recording name the room and a
 * replay plays it). Returns HOL_OK with *out_changed 1, or 0 when the
 * level names its own geometry (kept as it is); an error of
 * hol_level_set_geometry (the text too long, the room refusing the level)
 * leaves the level unchanged. */
hol_err hol_fit_level(hol_level *lv, const hol_fit *f, int *out_changed);

#endif
