/* hol_room.h - the user's state in the room and walks of room steps.
 *
 * Contract
 * - The room has C x R cells (col, row), col 0..C-1 west to east, row
 *   0..R-1 north to south, C and R from 3 to 5 (SPEC section 1 and 7); the
 *   default is 3 x 3. The user starts on cell (C/2, R/2) of the origin tile
 *   with the room's directions equal to the origin's.
 * - The state is (tile, orientation, cell) and the room's size. orient is
 *   the room's north given as a turn (0..3, counter-clockwise quarter
 *   turns) relative to the tile's canonical heading. The tiling is the
 *   tile's (hol_tile_q). A step crosses one cell edge and one tile edge; the
 *   room frame is carried across the edge.
 * - The size is stored as columns and rows beyond three (more_cols,
 *   more_rows, 0..2), so a zeroed field is the 3 x 3 room and a {4,5}
 *   3 x 3 state is what it was before rooms had sizes.
 * - A step that would leave the room is refused (HOL_EROOM) and the state is
 *   unchanged. No allocation, no globals.
 */
#ifndef HOL_ROOM_H
#define HOL_ROOM_H

#include <stddef.h>
#include <stdint.h>

#include "hol_tile.h"

/* The default room's side, and the range of sides. */
#define HOL_ROOM_SIZE 3
#define HOL_ROOM_MIN_SIDE 3
#define HOL_ROOM_MAX_SIDE 5
/* Most cells of any room (5 x 5). */
#define HOL_ROOM_MAX_CELLS (HOL_ROOM_MAX_SIDE * HOL_ROOM_MAX_SIDE)

typedef struct hol_room {
    hol_tile tile;
    uint8_t orient;     /* 0..3 */
    uint8_t col, row;   /* 0..cols-1, 0..rows-1 */
    uint8_t more_cols;  /* columns beyond 3 (0..2) */
    uint8_t more_rows;  /* rows beyond 3 (0..2) */
} hol_room;

static inline int hol_room_cols(const hol_room *r) { return HOL_ROOM_MIN_SIDE + r->more_cols; }
static inline int hol_room_rows(const hol_room *r) { return HOL_ROOM_MIN_SIDE + r->more_rows; }

/* The start: origin tile of {4,5}, orientation 0, cell (1,1) of 3 x 3. */
hol_room hol_room_start(void);
/* The start of a room of cols x rows cells in {4,q}: O, orientation 0,
 * cell (cols/2, rows/2). A zero argument takes the default (5, 3, 3).
 * Errors: HOL_EARG (q outside 4..8, a side outside 3..5). */
hol_err hol_room_start_in(int q, int cols, int rows, hol_room *out_room);
/* 1 when r is a state a step can start from: a tile word in reach, an
 * orientation 0..3, a size 3..5 a side and the cell inside it. */
int hol_room_ok(const hol_room *r);

/* Room direction letter ('N','E','S','W') to code (N 0, W 1, S 2, E 3);
 * -1 for any other character. */
int hol_dir_from_char(int c);
char hol_dir_to_char(int dir);

/* Cell change of a room direction. */
void hol_dir_delta(int dir, int *out_dcol, int *out_drow);

/* One step inside the room. Errors: HOL_EROOM (would leave the room),
 * HOL_ERANGE (tile beyond the reach), HOL_EARG (dir not 0..3, or a room
 * size outside 3..5). */
hol_err hol_room_step(hol_room *room, int dir);

/* Parse a walk: letters N/E/S/W, or "-" (or empty) for none. On success
 * writes at most cap codes and *out_n; HOL_EPARSE names the first bad
 * character's offset in *out_bad (may be NULL); HOL_ENOMEM if over cap. */
hol_err hol_walk_parse(const char *s, size_t len, uint8_t *out_dirs, size_t cap,
                       size_t *out_n, size_t *out_bad);

/* Apply a walk inside the room from *room. On error *out_done (may be NULL)
 * receives how many steps were applied and *room holds that state. */
hol_err hol_room_walk(hol_room *room, const uint8_t *dirs, size_t n,
                      size_t *out_done);

/* ---- option text (SPEC 7), for command lines and files ----
 * hol_room_parse_tiling: "4,Q" (or "{4,Q}") with Q 4..8 into *out_q.
 * hol_room_parse_size: "CxR" (x or X) with C and R 3..5.
 * Errors: HOL_EPARSE (not of that form), HOL_EARG (a number out of
 * range); outputs untouched on error. len is the text's length (any bytes,
 * NUL included, are refused as text). */
hol_err hol_room_parse_tiling(const char *s, size_t len, int *out_q);
hol_err hol_room_parse_size(const char *s, size_t len, int *out_cols, int *out_rows);

#endif
