/* report_draw.h - an attempt's picture for `holonomy report`: the walked
 * path and the optimal one on the Poincare disk (the flat grid {4,4}: a
 * plain top view), centred on the tile where the level begins, room north
 * up, over the tiling's edges.
 *
 * Contract
 * - report_draw fills rgba (size * size * 4 bytes, rows top to bottom):
 *   the disk, the tiles' edges within a few steps of the start (grey), the
 *   optimal walk (REPORT_RGB_OPTIMAL, 7 px wide) under the walked one
 *   (REPORT_RGB_WALKED, 3 px), both through tile centres along geodesics;
 *   the start (green), the objectives (red; keys gold, the chest brown) and
 *   the walk's last tile (an orange ring). Colours are exact (no blending)
 *   so tests can count them.
 * - Tiles are of one tiling (the start's); others are HOL_EARG. size is
 *   64..2048. No allocation. After a signal (cli_caught_signal) a path
 *   stops within 1,024 tiles and report_draw gives HOL_EBUDGET (a walk of a
 *   million steps takes seconds to draw).
 * - report_draw_background draws the disk and the edges alone for a
 *   hyperbolic {4,q} (q 5..8; they are the same for every start): given as
 *   background (same size and q), report_draw copies it instead of drawing
 *   them again (many pictures: `holonomy report`). The flat {4,4} grid
 *   depends on the walks' extent and is always drawn.
 */
#ifndef REPORT_DRAW_H
#define REPORT_DRAW_H

#include <stdint.h>

#include "../../core/hol_err.h"
#include "../../core/hol_room.h"

#define REPORT_RGB_WALKED 0xdc5014u  /* orange */
#define REPORT_RGB_OPTIMAL 0x78aaf0u /* light blue */

typedef struct report_picture {
    hol_room start;           /* the level's beginning */
    const hol_tile *walked;   /* tiles entered, in order (without the start) */
    int nwalked;
    const hol_tile *optimal;  /* the optimal walk's tiles (without the start) */
    int noptimal;
    const hol_tile *goals;    /* objectives */
    int ngoals;
    int chest_last;           /* 1: the last goal is the chest (keys level) */
    const uint8_t *background; /* NULL, or report_draw_background's of this q */
} report_picture;

hol_err report_draw(const report_picture *p, uint8_t *rgba, int size);
hol_err report_draw_background(int q, uint8_t *rgba, int size);

#endif
