/* hol_tile.h - exact tiles of the hyperbolic square tiling {4,5}.
 *
 * Contract
 * - A tile is a 16-byte value (hol_tile) holding its canonical address: the
 *   branch N/W/S/E (the first step from the origin O) followed by f/l/r
 *   letters (straight, turn left then step, turn right then step).
 * - The canonical address of a tile is its unique shortest walk from O that
 *   contains no "lfl" after the branch. Equivalently it is the *leftmost*
 *   shortest walk: where two shortest walks part, the canonical one turns
 *   further left. The canonical words are exactly the words accepted by a
 *   six-state automaton (hol_tile.c documents it and why it is right).
 * - Everything here is integer work: no floating point, no allocation, no
 *   global state. Every function is thread safe.
 * - Reach: addresses up to HOL_TILE_MAX_DIST letters. An operation whose
 *   result would lie farther from O returns HOL_ERANGE and leaves its outputs
 *   untouched; it never wraps silently.
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

#define HOL_TILE_MAX_DIST 60
/* Longest text of an address including the terminating NUL. */
#define HOL_TILE_ADDR_MAX (HOL_TILE_MAX_DIST + 1)

enum { HOL_DIR_N = 0, HOL_DIR_W = 1, HOL_DIR_S = 2, HOL_DIR_E = 3 };
enum { HOL_TURN_F = 0, HOL_TURN_L = 1, HOL_TURN_B = 2, HOL_TURN_R = 3 };

/* Bit layout: letter i (i = 0 is the branch) in bits 2i..2i+1 of the 128-bit
 * value bits[0] | bits[1] << 64, coded as its turn index (f=0, l=1, r=3;
 * branch N=0, W=1, S=2, E=3); the length (0..61) in the top six bits. Unused
 * letter bits are zero, so equal tiles have equal bits. */
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

hol_tile hol_tile_origin(void);
int hol_tile_dist0(hol_tile t); /* distance from O = address length */
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
int hol_tile_state(hol_tile t);

/* Parse an address ("O", "N", "Nrfl", ...). len < 0 means NUL-terminated.
 * Errors: HOL_EPARSE (a character that is no address letter, or empty),
 * HOL_ENOTCANON (a valid walk that is not the canonical address; the walk
 * may still be turned into its tile with hol_tile_from_turns), HOL_ERANGE. */
hol_err hol_tile_parse(const char *s, ptrdiff_t len, hol_tile *out_tile);
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

/* The tile reached by any walk written like an address (branch, then f/l/r
 * letters), canonical or not: "Nrr" gives El. Errors as hol_tile_parse,
 * without HOL_ENOTCANON. */
hol_err hol_tile_resolve(const char *s, ptrdiff_t len, hol_tile *out_tile);

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
 * an invalid tile word. */
int hol_tile_dist(hol_tile a, hol_tile b);

/* The parent (address minus its last letter); O is its own parent. */
hol_tile hol_tile_parent(hol_tile t);

/* Child by a letter code (0 f, 1 l, 3 r; for O the branch 0..3). Fails with
 * HOL_ENOTCANON when the child address is not canonical (the neighbour in
 * that direction has another address: use hol_tile_step). */
hol_err hol_tile_child(hol_tile t, int letter, hol_tile *out_tile);

#endif
