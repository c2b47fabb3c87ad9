/* hol_nav_line.h - parsing of guidance input: `PREFIX TARGET` lines of
 * `holonomy nav`, and the PREFIX / address arguments of `holonomy tour`.
 *
 * Contract
 * - PREFIX is a walk of room steps N/E/S/W from the start (cell (1,1) of O,
 *   SPEC section 1), "-" for none; it must stay inside the room. TARGET is a
 *   canonical tile address (SPEC section 3). The _in forms start from any
 *   start state (hol_room_start_in: another tiling or room size, SPEC 7)
 *   and read addresses in its tiling.
 * - On failure a one-line, printable, lower-case message (no line number,
 *   no trailing newline) is written to msg (msg_cap bytes, NUL-terminated,
 *   truncated if needed) and nothing else is written. Input may hold any
 *   bytes, NUL included; the message never echoes unprintable ones.
 * - No allocation, no globals; thread safe.
 */
#ifndef HOL_NAV_LINE_H
#define HOL_NAV_LINE_H

#include <stddef.h>

#include "hol_err.h"
#include "hol_room.h"
#include "hol_tile.h"

/* Longest PREFIX accepted, in steps. */
#define HOL_NAV_PREFIX_MAX 65536

/* Apply PREFIX (s, len) from the start: *out_room is the state reached.
 * Errors: HOL_EPARSE (a character that is no step), HOL_EROOM (a step leaves
 * the room), HOL_ERANGE (longer than HOL_NAV_PREFIX_MAX or beyond reach). */
hol_err hol_nav_parse_prefix(const char *s, size_t len, hol_room *out_room,
                             char *msg, size_t msg_cap);
hol_err hol_nav_parse_prefix_in(const hol_room *start, const char *s, size_t len,
                                hol_room *out_room, char *msg, size_t msg_cap);

/* Parse a canonical address. Errors: HOL_EPARSE, HOL_ENOTCANON (the message
 * names the canonical address of that walk), HOL_ERANGE. */
hol_err hol_nav_parse_target(const char *s, size_t len, hol_tile *out_tile,
                             char *msg, size_t msg_cap);
hol_err hol_nav_parse_target_q(int q, const char *s, size_t len, hol_tile *out_tile,
                               char *msg, size_t msg_cap);

/* A whole `PREFIX TARGET` line (fields separated by spaces or tabs; leading
 * and trailing blanks ignored). Errors as above, HOL_EPARSE also for a wrong
 * number of fields or a NUL byte. */
hol_err hol_nav_parse_line(const char *s, size_t len, hol_room *out_room,
                           hol_tile *out_target, char *msg, size_t msg_cap);
hol_err hol_nav_parse_line_in(const hol_room *start, const char *s, size_t len,
                              hol_room *out_room, hol_tile *out_target, char *msg,
                              size_t msg_cap);

#endif
