/* hol_hyper.h - floating-point geometry relative to a tile (minimap, arrows).
 *
 * Contract
 * - Points of the hyperbolic plane are on the hyperboloid x^2 + y^2 - w^2 = -1,
 *   w > 0, stored as (x, y, w). A frame is a 3x3 Lorentz matrix, row-major.
 * - In the flat grid {4,4} (tiles with hol_tile_q 4) points are (x, y, 1) in
 *   units of the tile's side and a frame is a rigid motion of the plane in
 *   the same homogeneous form; every function below works for both, taking
 *   the tiling from its tiles.
 * - Coordinates of tile b are computed from b's address relative to tile a
 *   (hol_tile_relative), so their precision depends only on the distance
 *   between a and b, never on how far both are from the origin.
 * - In a's frame, +y is the direction a_north (a turn relative to a's
 *   canonical heading; pass the room orientation to get room north) and +x is
 *   90 degrees clockwise of it (room east).
 * - Pure functions; no allocation, no globals.
 */
#ifndef HOL_HYPER_H
#define HOL_HYPER_H

#include "hol_tile.h"

/* Centre-to-centre distance of neighbouring tiles of {4,5},
 * 2 acosh(cos(pi/5) / sin(pi/4)) ~= 1.0612750619. */
double hol_hyper_edge(void);
/* The same in {4,q}: 2 acosh(cos(pi/q) / sin(pi/4)), and 1 in the flat
 * {4,4} (there in tile sides, not curvature radii); 0 for a bad q. */
double hol_hyper_edge_q(int q);

/* Frame of b (its centre, +y its canonical heading) in a's frame.
 * HOL_EARG for invalid tiles or tiles of two tilings. */
hol_err hol_hyper_frame(hol_tile a, int a_north, hol_tile b, double out_m[9]);

/* The frame of t's neighbour across the edge in direction turn (as
 * hol_tile_step, which gives arrive) from t's frame m, in {4,q}: m times
 * the quarter turns, one edge, and the arrival undone (what
 * hol_hyper_frame gives for the neighbour, to rounding; for walks that
 * visit many tiles: one matrix product a step, no address). */
void hol_hyper_frame_step(int q, const double m[9], int turn, int arrive, double out_m[9]);

/* Centre of b in a's frame, and its direction and distance as seen from a's
 * centre: angle in radians counter-clockwise from +y (a_north), distance in
 * units of the plane's curvature radius (tile sides in {4,4}). Either
 * output may be NULL. */
hol_err hol_hyper_pos(hol_tile a, int a_north, hol_tile b, double out_p[3],
                      double *out_angle, double *out_dist);

/* The hyperboloid point (x, y, w) of the Klein point (kx, ky) (|k| < 1;
 * clamped just inside the disk), or (kx, ky, 1) when flat ({4,4}). */
void hol_hyper_from_klein(double kx, double ky, int flat, double out_p[3]);

/* The chord |p - q|_L (Lorentz norm of p - q: exact near 0, no acosh
 * cancellation; the Euclidean |p - q| when flat) and the distance on the
 * plane, 2 asinh(chord / 2) (the chord itself when flat), in curvature
 * units (tile sides when flat). */
double hol_hyper_chord(const double p[3], const double q[3], int flat);
double hol_hyper_dist(const double p[3], const double q[3], int flat);

/* Poincare-disk point (|z| < 1) of a hyperboloid point (not for {4,4}). */
void hol_hyper_to_disk(const double p[3], double out_xy[2]);

#endif
