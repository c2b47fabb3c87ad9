/* hol_tile.h - exact tiles of the square tilings {4,Q}, Q = 4..8 ({4,5} by
 * default; {4,4} is the flat grid).
 *
 * Contract
 * - A tile is a 16-byte value (hol_tile) holding its tiling and its
 *   canonical address: the branch N/W/S/E (the first step from the origin
 *   O) followed by f/l/r letters (straight, turn left then step, turn right
 *   then step).
 * - The tiling is part of the word (the bit layout below): a tile knows its
 *   tiling, tiles of two tilings are never equal, and every function here
 *   takes its tiling from its tile arguments (two tiles of different
 *   tilings are HOL_EARG, or -1 for hol_tile_dist). The functions without a
 *   Q argument that make a tile from nothing (hol_tile_origin,
 *   hol_tile_parse, hol_tile_resolve, hol_tile_from_walk) are {4,5}; their
 *   _q variants take Q. A zero hol_tile is O of {4,5}, and every {4,5} word
 *   is bit for bit what it was before the other tilings came.
 * - The canonical address of a tile is its *leftmost* shortest walk from
 *   O: where two shortest walks part, the canonical one turns further left
 *   (l before f before r; in the flat grid, of two neighbouring branches
 *   the one a quarter turn to the left). In {4,5} that is the shortest walk
 *   with no "lfl" after the branch. The canonical words of each tiling are
 *   exactly the words accepted by a small automaton (hol_tile_dfa.h,
 *   derived from the geometry by tests/gen_tiling.c; hol_tile.c says why
 *   the neighbour rule is right).
 * - Everything here is integer work: no floating point, no allocation, no
 *   global state. Every function is thread safe.
 * - Reach: addresses up to hol_tile_reach(Q) letters (HOL_TILE_MAX_DIST =
 *   60 in {4,5}, 59 in the others: their tiling code takes the bits of the
 *   60th letter). An operation whose result would lie farther from O
 *   returns HOL_ERANGE and leaves its outputs untouched; it never wraps
 *   silently.
 *
 * Directions and turns are small integers counted counter-clockwise (seen
 * from above) in quarter turns: 0 = forward, 1 = left, 2 = back, 3 = right.
 * Every tile has a canonical heading: the direction of the last step of its
 * address (for O: the direction of branch N). Room directions use the same
 * numbering relative to the room: HOL_DIR_N = 0, W = 1, S = 2, E = 3.
 */
#ifndef HOL_TILE_H
#define HOL_TILE_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"

/* The reach of {4,5}, the longest of any tiling. */
#define HOL_TILE_MAX_DIST 60
/* Longest text of an address including the terminating NUL. */
#define HOL_TILE_ADDR_MAX (HOL_TILE_MAX_DIST + 1)

/* The tilings {4,Q}. */
#define HOL_TILING_MIN_Q 4
#define HOL_TILING_MAX_Q 8
#define HOL_TILING_DEFAULT_Q 5

enum { HOL_DIR_N = 0, HOL_DIR_W = 1, HOL_DIR_S = 2, HOL_DIR_E = 3 };
enum { HOL_TURN_F = 0, HOL_TURN_L = 1, HOL_TURN_B = 2, HOL_TURN_R = 3 };

/* Bit layout: letter i (i = 0 is the branch) in bits 2i..2i+1 of the 128-bit
 * value bits[0] | bits[1] << 64, coded as its turn index (f=0, l=1, r=3;
 * branch N=0, W=1, S=2, E=3); the length (0..60) in the top six bits
 * (122..127). The tiling: bits 120..121 zero for {4,5}; for the others
 * bits 118..121 hold Q (4, 6, 7 or 8, so 120..121 are never both zero).
 * Unused letter bits are zero, so equal tiles have equal bits. */
typedef struct hol_tile {
    uint64_t bits[2];
} hol_tile;

/* A tile together with a facing: the step (or room) direction, given as a
 * turn relative to the tile's canonical heading. (Named so that it is not
 * taken for the game's flag.) */
typedef struct hol_heading_tile {
    hol_tile tile;
    int facing; /* 0..3 */
} hol_heading_tile;

hol_tile hol_tile_origin(void); /* O of {4,5} (all bits zero) */
int hol_tile_dist0(hol_tile t); /* distance from O = address length */

/* ---- tilings ---- */
/* Q of t's tiling (4..8); 0 when t is not a tile word (an unknown tiling
 * code or a length beyond the reach). */
int hol_tile_q(hol_tile t);
/* The reach of {4,q}: 60 for q = 5, 59 for the others, 0 for a bad q. */
int hol_tile_reach(int q);
/* O of {4,q}; for a q outside 4..8 a word that every function refuses. */
hol_tile hol_tile_origin_q(int q);
/* Tiles at distance exactly d from any tile of {4,q} (SPEC 7: 1, 4, 12,
 * 28, ... in {4,5}; 4d in {4,4}); 0 for a bad q, d < 0 or a count beyond
 * 2^63. */
uint64_t hol_tile_count_at(int q, int d);
int hol_tile_eq(hol_tile a, hol_tile b);
uint64_t hol_tile_hash(hol_tile t);
/* Letter i of the address as its code (see the bit layout); i < length. */
int hol_tile_letter(hol_tile t, int i);

/* The automaton of canonical addresses (hol_tile.c shows its table): states
 * 0..HOL_TILE_STATES-1 over the letters after the branch, state 0 right
 * after the branch. hol_tile_automaton gives the state after `letter` (0 f,
 * 1 l, 3 r) or -1 when no canonical address continues with it;
 * hol_tile_state the state after t's address (0 for a branch, -1 for O).
 * With them, canonical words can be counted, ranked and enumerated. */
#define HOL_TILE_STATES 6
int hol_tile_automaton(int state, int letter);
int hol_tile_state(hol_tile t); /* any tiling: t's own automaton */
/* The same for {4,q}: hol_tile_states(q) states (at most
 * HOL_TILE_MAX_STATES; 0 for a bad q). */
#define HOL_TILE_MAX_STATES 10
int hol_tile_states(int q);
int hol_tile_automaton_q(int q, int state, int letter);

/* Parse an address ("O", "N", "Nrfl", ...). len < 0 means NUL-terminated.
 * Errors: HOL_EPARSE (a character that is no address letter, or empty),
 * HOL_ENOTCANON (a valid walk that is not the canonical address; the walk
 * may still be turned into its tile with hol_tile_from_turns), HOL_ERANGE. */
hol_err hol_tile_parse(const char *s, ptrdiff_t len, hol_tile *out_tile);
/* The same in {4,q} (HOL_EARG for a q outside 4..8). */
hol_err hol_tile_parse_q(int q, const char *s, ptrdiff_t len, hol_tile *out_tile);
/* Writes the address and a NUL; returns its length. buf holds at least
 * HOL_TILE_ADDR_MAX bytes. */
int hol_tile_print(hol_tile t, char *buf);

/* The neighbour across the edge that lies in direction `turn` (0..3,
 * relative to t's canonical heading). out_arrive (may be NULL) receives the
 * direction of travel on arrival, relative to the neighbour's canonical
 * heading, so a frame carried across the edge stays exact. */
hol_err hol_tile_step(hol_tile t, int turn, hol_tile *out_tile, int *out_arrive);

/* Heading-tile form of the above: turn by `turn` relative to the facing, step, and
 * face the direction of travel. */
hol_err hol_heading_tile_step(hol_heading_tile f, int turn, hol_heading_tile *out_ht);

/* The tile reached from O by a walk of room directions (0..3 each, a free
 * walk with the room frame carried), and the room's north on arrival as a
 * turn relative to that tile's canonical heading (may be NULL). */
hol_err hol_tile_from_walk(const uint8_t *dirs, size_t n, hol_tile *out_tile,
                           int *out_orient);
hol_err hol_tile_from_walk_q(int q, const uint8_t *dirs, size_t n, hol_tile *out_tile,
                             int *out_orient);

/* The tile reached by any walk written like an address (branch, then f/l/r
 * letters), canonical or not: "Nrr" gives El. Errors as hol_tile_parse,
 * without HOL_ENOTCANON. */
hol_err hol_tile_resolve(const char *s, ptrdiff_t len, hol_tile *out_tile);
hol_err hol_tile_resolve_q(int q, const char *s, ptrdiff_t len, hol_tile *out_tile);

/* Address of b as seen from a: the tile that b is when a is taken as the
 * origin and direction `a_north` (relative to a's canonical heading) as N.
 * out_facing (may be NULL) receives b's canonical heading expressed in the
 * same relative frame (relative to the relative tile's canonical heading).
 * Errors: HOL_ERANGE when the relative address is longer than the reach. */
hol_err hol_tile_relative(hol_tile a, int a_north, hol_tile b, hol_tile *out_rel,
                          int *out_facing);

/* The same relative address as letter codes (branch first), which works for
 * every pair of tiles in reach (up to 2 * HOL_TILE_MAX_DIST letters).
 * Returns the length, or -1 for an invalid tile. */
#define HOL_TILE_REL_MAX (2 * HOL_TILE_MAX_DIST)
int hol_tile_relative_letters(hol_tile a, int a_north, hol_tile b,
                              uint8_t out_letters[HOL_TILE_REL_MAX],
                              int *out_facing);

/* Fewest steps between a and b (exact for every pair in reach); -1 only for
 * an invalid tile word or tiles of two tilings. */
int hol_tile_dist(hol_tile a, hol_tile b);

/* The parent (address minus its last letter); O is its own parent. */
hol_tile hol_tile_parent(hol_tile t);

/* Child by a letter code (0 f, 1 l, 3 r; for O the branch 0..3). Fails with
 * HOL_ENOTCANON when the child address is not canonical (the neighbour in
 * that direction has another address: use hol_tile_step). */
hol_err hol_tile_child(hol_tile t, int letter, hol_tile *out_tile);

#endif
