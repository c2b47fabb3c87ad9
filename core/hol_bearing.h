/* hol_bearing.h - bearings for pointing tasks (SPEC section 8).
 *
 * Contract
 * - A bearing is a direction in the room's frame in degrees clockwise from
 *   room north: N 0, E 90, S 180, W 270, in [0, 360).
 * - The true bearing from tile U to tile T: at U's centre, the initial
 *   direction of the geodesic to T's centre, in the frame the walk to U
 *   carried (room north in U is where a step N from U goes). It is computed
 *   from T's address relative to U (hol_hyper_pos), so its precision
 *   depends only on the distance between U and T.
 * - The flat bearing of T after a walk: the direction from where the walk
 *   ends to where it first stood on T, in a flat square grid where every
 *   step is one unit in its room direction (the homing vector of path
 *   integration when T is the start). It has no value when the walk never
 *   stood on T or when that flat vector is zero.
 * - A walk is fed a step at a time (hol_bearing_begin, _step, _end), so a
 *   walk of any length needs no buffer; the state is a plain value.
 * - Pure: no allocation, no globals, no OS; libm's transcendentals are
 *   replaced by core/hol_math.h.
 */
#ifndef HOL_BEARING_H
#define HOL_BEARING_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_tile.h"

/* A walk in progress from the start (O, room north = N). */
typedef struct hol_bearing_walk {
    hol_tile target; /* T */
    hol_tile at;     /* the tile the walk stands on */
    int orient;      /* room north in `at`, relative to its canonical heading */
    int64_t x, y;    /* flat position: x east, y north, in steps */
    int seen;        /* 1 once the walk stood on T (the start counts) */
    int64_t tx, ty;  /* the flat position where it first did */
    uint64_t steps;  /* steps taken */
} hol_bearing_walk;

/* The two bearings of a walk's end. has_true 0: the walk ends on T;
 * has_flat 0: it never stood on T, or the flat vector is zero. */
typedef struct hol_bearing {
    int has_true, has_flat;
    double true_deg, flat_deg; /* in [0, 360) when present */
} hol_bearing;

/* Starts a walk from O of target's tiling. HOL_EARG for a target that is
 * no tile word. */
hol_err hol_bearing_begin(hol_bearing_walk *w, hol_tile target);
/* One room step (HOL_DIR_N, W, S or E). HOL_EARG for another dir,
 * HOL_ERANGE when the step goes beyond the reach of tile words; on error
 * the walk is unchanged. */
hol_err hol_bearing_step(hol_bearing_walk *w, int dir);
/* The bearings where the walk stands now. */
hol_err hol_bearing_end(const hol_bearing_walk *w, hol_bearing *out);

/* The true bearing from u (room north = u_north, a turn relative to u's
 * canonical heading) to t. HOL_EARG for tiles of two tilings or invalid
 * words, and for t == u (no direction). */
hol_err hol_bearing_true(hol_tile u, int u_north, hol_tile t, double *out_deg);

/* Degrees of the direction (east, north) clockwise from north, in
 * [0, 360); 0 for the zero vector. */
double hol_bearing_of_vector(double east, double north);

/* Writes a bearing with one decimal ("0.0" .. "359.9"; a value that rounds
 * to 360.0 is written "0.0") and a NUL; returns its length. */
#define HOL_BEARING_TEXT 8
int hol_bearing_format(double deg, char buf[HOL_BEARING_TEXT]);

#endif
