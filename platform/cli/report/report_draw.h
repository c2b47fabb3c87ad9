/* report_draw.h - an attempt's picture for `holonomy report`: the walked
 * path and the optimal one on the Poincare disk (the flat grid {4,4}: a
 * plain top view), re-centred and zoomed on the walk, over the tiling's
 * edges, with a legend in a band at the bottom.
 *
 * Contract
 * - report_view_fit chooses the view: the centre C of the walk (the start
 *   and the walked tiles) is their mean on the hyperboloid, normalised (the
 *   Minkowski centroid); the walk's tile T nearest C is moved to the disk's
 *   centre by an
 *   isometry of the tiling (a Mobius map of the disk: T's frame inverted,
 *   then the quarter turn that leaves the room's north within 45 degrees of
 *   up, as seen along the geodesic from T's centre), and the disk is
 *   magnified by 2^(zoom/4), zoom 0..REPORT_ZOOM_MAX, the largest that keeps
 *   the walk and the objectives within 0.85 of the view's radius (the
 *   optimal walk may leave the view). Centring on a tile, not on
 *   C itself, keeps the tiling's picture the same for every attempt of a
 *   zoom (drawn once: report_draw_background). {4,4}: the points' bounding
 *   box centred, its half-width plus a tile the view's radius (zoom 0).
 * - report_draw fills px (size * size bytes, rows top to bottom, one
 *   index of report_palette's colours a pixel: a PNG's colour type 3): the
 *   view (the disk, the tiles' edges grey), the optimal walk
 *   (REPORT_RGB_OPTIMAL, a wide line) under the walked one, through tile
 *   centres along geodesics. The walked path's steps go from
 *   REPORT_RGB_RAMP0 (the first) to REPORT_RGB_RAMP1 (the last) through
 *   REPORT_RAMP_LEVELS colours; an edge walked again is drawn beside the
 *   earlier passes (offset to the right of its direction, a line's width
 *   and a gap per earlier pass; the first REPORT_EDGE_SLOTS distinct edges
 *   of a walk are tracked); the start (green), the objectives (red; keys
 *   gold, the chest brown), the walk's last tile (a ring of the ramp's
 *   end); the step numbers where report_step_labels places them. The bottom
 *   report_legend_height(size) rows are the legend: the ramp with its first
 *   and last step numbers, and the marks and lines named. Colours are exact
 *   (no blending) so tests can count them.
 * - Tiles are of one tiling (the start's); others are HOL_EARG. size is
 *   64..2048. No allocation, no globals: the walk's edges are counted in
 *   p->edges (the caller's, kept between pictures) or, NULL, in a table on
 *   report_draw's stack. After a signal (cli_caught_signal) a path
 *   stops within 1,024 tiles and report_draw gives HOL_EBUDGET (a walk of a
 *   million steps takes seconds to draw).
 * - report_step_labels places the step numbers (dark, in a white halo): the
 *   last step's and the first's, then every few steps' (1, 2, 5, 10, 20, ...
 *   apart, at most 12; none nearer the first or the last than half that),
 *   each beside the tile it reached, in the first of 8 directions (up right
 *   first) at 3 distances where its box (the glyphs and the halo) lies in
 *   the view above the legend and meets no mark's box and no number placed
 *   before (nor comes within 2 font pixels of one); a number with no such place is left out (so a tile revisited
 *   has its numbers around it, none over another). report_mark_boxes gives
 *   the marks' boxes: the squares around the start's disk, the objectives'
 *   and the end ring, a pixel wider. Both for tests; report_draw draws the
 *   same numbers.
 * - report_draw_background draws the view's disk and edges alone for a
 *   hyperbolic {4,q} (q 5..8) at a zoom: given as background (same size, q
 *   and zoom), report_draw copies it instead of drawing them again (many
 *   pictures: `holonomy report`). The flat {4,4} grid depends on the walks'
 *   extent and is always drawn.
 */
#ifndef REPORT_DRAW_H
#define REPORT_DRAW_H

#include <stdint.h>

#include "../../../core/hol_err.h"
#include "../../../core/hol_room.h"

#define REPORT_RGB_RAMP0 0x3c28b4u   /* the first step: indigo */
#define REPORT_RGB_RAMP1 0xdc5014u   /* the last step: orange */
#define REPORT_RGB_WALKED REPORT_RGB_RAMP1
#define REPORT_RGB_OPTIMAL 0x78aaf0u /* light blue */
#define REPORT_RAMP_LEVELS 24
#define REPORT_ZOOM_MAX 12
#define REPORT_EDGE_SLOTS 4096

/* The edges of the walk being drawn (unordered pairs of tiles) and how
 * often each was walked: report_draw's work space, kept by a caller that
 * draws many pictures (a stamp empties it for each, not a clear of its
 * 320 KB). Zero is ready. */
typedef struct report_edge_slot {
    uint64_t k[4];
    uint32_t stamp, count;
} report_edge_slot;

typedef struct report_edges {
    report_edge_slot tab[2 * REPORT_EDGE_SLOTS];
    uint32_t stamp;
    int used;
} report_edges;

typedef struct report_picture {
    hol_room start;           /* the level's beginning */
    const hol_tile *walked;   /* tiles entered, in order (without the start) */
    int nwalked;
    const hol_tile *optimal;  /* the optimal walk's tiles (without the start) */
    int noptimal;
    const hol_tile *goals;    /* objectives */
    int ngoals;
    int chest_last;           /* 1: the last goal is the chest (keys level) */
    const uint8_t *background; /* NULL, or report_draw_background's of this q and zoom */
    const struct report_view *view; /* NULL, or report_view_fit's of this picture */
    report_edges *edges;      /* NULL: report_draw's own (zeroed on its stack) */
} report_picture;

typedef struct report_view {
    double m[9];     /* a start-frame hyperboloid point to the view's (row-major) */
    double centre[3]; /* C, the points' centroid (start frame) */
    hol_tile tile;   /* T, moved to the disk's centre */
    int zoom;        /* the disk magnified 2^(zoom/4) */
    double flat[3];  /* {4,4}: the centre x, y and the half-width shown */
} report_view;

typedef struct report_box { /* pixels x0 <= x < x1, y0 <= y < y1 */
    int x0, y0, x1, y1;
} report_box;

#define REPORT_LABELS_MAX 32

typedef struct report_label {
    long step;      /* 1: the first step */
    char text[24];  /* its number */
    report_box box; /* the glyphs and their halo */
} report_label;

hol_err report_view_fit(const report_picture *p, report_view *out);
/* A start-frame point to pixels of a size x size picture of view v. */
void report_view_px(const report_view *v, int flat, int size, const double p[3],
                    double out[2]);
int report_legend_height(int size);
/* The numbers' places in a size x size picture of view v: how many. */
int report_step_labels(const report_picture *p, const report_view *v, int size,
                       report_label out[REPORT_LABELS_MAX]);
/* The marks' boxes (the start, the objectives, the end): how many (<= max). */
int report_mark_boxes(const report_picture *p, const report_view *v, int size,
                      report_box *out, int max);
hol_err report_draw(const report_picture *p, uint8_t *px, int size);
hol_err report_draw_background(int q, int zoom, uint8_t *px, int size);
/* The pictures' colours (3 bytes each, plte: 768 bytes): how many. */
int report_palette(uint8_t plte[3 * 256]);

#endif
