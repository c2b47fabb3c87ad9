/* hol_room.h - the user's state in the 3 x 3 room and walks of room steps.
 *
 * Contract
 * - The room has nine 1 m cells (col, row), col 0..2 west to east, row 0..2
 *   north to south; the user starts on cell (1,1) of the origin tile with the
 *   room's directions equal to the origin's (SPEC section 1 and 2).
 * - The state is (tile, orientation, cell). orient is the room's north given
 *   as a turn (0..3, counter-clockwise quarter turns) relative to the tile's
 *   canonical heading. A step crosses one cell edge and one tile edge; the
 *   room frame is carried across the edge.
 * - A step that would leave the room is refused (HOL_EROOM) and the state is
 *   unchanged. No allocation, no globals.
 */
#ifndef HOL_ROOM_H
#define HOL_ROOM_H

#include <stddef.h>
#include <stdint.h>

#include "hol_tile.h"

#define HOL_ROOM_SIZE 3

typedef struct hol_room {
    hol_tile tile;
    uint8_t orient; /* 0..3 */
    uint8_t col, row; /* 0..2 */
} hol_room;

/* The start: origin tile, orientation 0, cell (1,1). */
hol_room hol_room_start(void);

/* Room direction letter ('N','E','S','W') to code (N 0, W 1, S 2, E 3);
 * -1 for any other character. */
int hol_dir_from_char(int c);
char hol_dir_to_char(int dir);

/* Cell change of a room direction. */
void hol_dir_delta(int dir, int *out_dcol, int *out_drow);

/* One step inside the room. Errors: HOL_EROOM (would leave the room),
 * HOL_ERANGE (tile beyond the reach), HOL_EARG (dir not 0..3). */
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

#endif
