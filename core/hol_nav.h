/* hol_nav.h - guidance: fewest room steps to a tile, keys-and-chest tours,
 * the hot-cold field and direction arrows of the minimap.
 *
 * Contract
 * - A walk is an array of room directions (HOL_DIR_N 0, W 1, S 2, E 3), the
 *   same codes as hol_room_step. Every walk returned stays inside the room.
 * - hol_nav_create makes the one allocation of the module (through the
 *   desc's hooks, malloc/free when zero): the cost table and the search
 *   arena. Queries never allocate; the arena is reset per query.
 * - The cost table uses the homogeneity of the tiling: the fewest steps from
 *   a room state (tile, orientation, cell) to a target depend only on the
 *   user's tile and room north as seen from the target, plus the cell. It
 *   holds, for every tile within desc.radius of a target, every orientation
 *   and cell, the fewest steps of walks that stay within that radius. For
 *   targets within the trusted radius (radius - 2, 12 by default) the table
 *   gives the answer without search (result.exact = 1). "Trusted": a table
 *   one tile larger gives the same costs there (checked by the tests for
 *   every radius 4..14), and so do brute-force BFS runs to distance 8; the
 *   costs are not proved exact beyond what hol_nav_table.c proves.
 * - hol_nav_create also reserves a state-to-state leg table for exact tours
 *   (about 5 MB, built on the first hol_nav_tour call).
 * - Farther targets: anytime best-first search guided by the table, at most
 *   `budget` nodes (the arena bounds it, so no query hangs); it returns the
 *   best complete walk found (result.exact = 0), or failing that a chain of
 *   exact legs to waypoints on the geodesic. HOL_EBUDGET is never returned.
 * - hol_nav_field and hol_nav_direction do not need a hol_nav: they are pure
 *   functions of tiles (no allocation, caller buffers).
 * - A hol_nav is not thread safe (one arena); use one per thread.
 * - Geometry: a navigator serves one tiling {4,Q} and one room size C x R
 *   (desc.tiling_q, room_cols, room_rows; zero: {4,5}, 3 x 3). Room states
 *   and tiles of another tiling or room size are HOL_EARG. Radii: without
 *   desc.radius, the largest table radius up to 14 whose navigator keeps
 *   within HOL_NAV_BUDGET (tables, leg table, arena; the leg table up to
 *   radius 10 and HOL_NAV_LEG_BUDGET): radius 14 for {4,5} 3 x 3, as it
 *   always was; hol_nav_table_exact_radius and hol_nav_tour_exact_radius
 *   tell what a navigator got (the README lists every configuration). The
 *   numbers above are those of {4,5} 3 x 3.
 * - The flat grid {4,4}: no holonomy, so a room reaches exactly its own
 *   C x R tiles; the tables cover them whole (exact to their radius), and
 *   a target or key off them is HOL_EUNREACH.
 */
#ifndef HOL_NAV_H
#define HOL_NAV_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_room.h"
#include "hol_tile.h"

/* Defaults of hol_nav_desc (zero fields take these). */
#define HOL_NAV_DEFAULT_RADIUS 14
#define HOL_NAV_MAX_RADIUS 15
#define HOL_NAV_DEFAULT_NODES (1u << 18)
#define HOL_NAV_DEFAULT_MARGIN 16
/* Longest walk any query writes; out_walk buffers of this size always fit. */
#define HOL_NAV_WALK_MAX 4096
#define HOL_NAV_TOUR_MAX_KEYS 5
#define HOL_NAV_TOUR_EXACT_RADIUS 7 /* {4,5} 3 x 3 (hol_nav_tour_exact_radius) */
/* Memory the default radii keep within, and the most an explicit radius
 * may take. */
#define HOL_NAV_BUDGET ((size_t)60 << 20)
#define HOL_NAV_LEG_BUDGET ((size_t)16 << 20)
#define HOL_NAV_MAX_BYTES ((size_t)512 << 20)

typedef struct hol_nav_desc {
    int radius;        /* cost table radius in tiles (3..15); 0: the largest
                        * up to 14 within HOL_NAV_BUDGET (14 in {4,5} 3 x 3) */
    size_t max_nodes;  /* search arena capacity in nodes (1024..2^26); 0: 2^18 */
    int anytime_margin; /* anytime search explores f up to best + this
                         * (steps, 1..255); 0: 16 */
    /* allocator hooks (both or neither); zero: malloc/free */
    void *(*alloc_fn)(size_t size, void *user);
    void (*free_fn)(void *ptr, void *user);
    void *user;
    int tiling_q;      /* the tiling {4,Q}, 4..8; 0: 5 */
    int room_cols;     /* the room's columns and rows, 3..5; 0: 3 */
    int room_rows;
    int lazy;          /* 1 (tools, short runs): the cost table is built
                        * by parts, as queries need it: a find within the
                        * trusted radius runs the table's BFS only up to
                        * its start's cost (a few ms for a target 5 tiles
                        * away), anything else (far finds, tours) first
                        * finishes it; and the search arena's pages are
                        * not touched at create (its hash is cleared at the
                        * first search instead; the first far query pays
                        * its page faults, about 8 ms). 0: the table whole
                        * and the arena touched at create. The answers are
                        * the same. */
} hol_nav_desc;

typedef struct hol_nav hol_nav; /* opaque */

/* Build the cost table (about 0.1-0.3 s of CPU; by parts with desc.lazy;
 * 30 MB in all at the defaults: table 11 MB, leg table 5 MB, arena 32
 * bytes a node plus 16 of hash and queue, at least the table's build
 * scratch). Errors:
 * HOL_EARG (radius out of range, a bad tiling or room size, an explicit
 * radius over HOL_NAV_MAX_BYTES), HOL_ENOMEM (the allocation failed). */
hol_err hol_nav_create(const hol_nav_desc *desc, hol_nav **out_nav);
void hol_nav_destroy(hol_nav *nav);

/* Bytes held by the navigator (tables + arena); hol_nav_memory_for: what
 * hol_nav_create(desc) would allocate (0 for a bad desc). */
size_t hol_nav_memory(const hol_nav *nav);
size_t hol_nav_memory_for(const hol_nav_desc *desc);
/* The navigator's tiling Q and room size (any output may be NULL). */
void hol_nav_geometry(const hol_nav *nav, int *out_q, int *out_cols, int *out_rows);
/* The cost table's radius; the tours' trusted radius (legs between keys
 * within it are exact: 7 in {4,5} 3 x 3). */
int hol_nav_table_radius(const hol_nav *nav);
int hol_nav_tour_exact_radius(const hol_nav *nav);
/* The trusted radius, the table's radius - 2 (12 by default; the radius
 * itself in {4,4}): targets within it are answered from the table alone
 * (no search) and flagged exact (see the contract above for what backs
 * that). */
int hol_nav_table_exact_radius(const hol_nav *nav);

typedef struct hol_nav_result {
    int len;      /* steps written to out_walk */
    int exact;    /* 1: len is the fewest (trusted table); 0: best found */
    size_t nodes; /* search nodes expanded (0 when the table alone answered) */
} hol_nav_result;

/* Fewest further steps from *start (staying in the room) after which the
 * user stands on `target`, and such a walk in out_walk (cap entries).
 * Within the trusted radius the answer is exact and budget is ignored.
 * Beyond: budget is the node budget of the anytime search (0: the arena
 * capacity); the best walk found is returned with exact = 0.
 * Errors: HOL_EARG (bad arguments, another tiling or room size),
 * HOL_ENOMEM (cap too small for the walk), HOL_ERANGE (a tile beyond the
 * reach of tile words on the way), HOL_EUNREACH (no walk inside the room
 * reaches the target: only in {4,4}, off the room's tiles). */
hol_err hol_nav_find(hol_nav *nav, const hol_room *start, hol_tile target,
                     size_t budget, uint8_t *out_walk, size_t cap,
                     hol_nav_result *out_result);

/* Keys and chest: the fewest steps from *start to stand on every key (in any
 * order; a key counts when the user stands on its tile) and after that on
 * the chest, and the walk. Up to HOL_NAV_TOUR_MAX_KEYS keys.
 * - First a dynamic program over key subsets x the 36 room states
 *   (orientation, cell) on each key, run twice over the same legs: over
 *   walks (a valid tour, an upper bound) and over lower bounds of the legs
 *   (a lower bound on the optimum). Legs come from a second,
 *   state-to-state table (built at hol_nav_prepare_tours, memory reserved
 *   at create): exact within its trusted radius (7 tiles); farther, through
 *   the sphere of that radius around the key (hol_nav_legs.c). When the two
 *   programs meet, the tour is exact with no search (result.nodes = 0):
 *   always when the keys lie within 7 tiles of each other and of the start
 *   and the chest within 12 of every key, and mostly for 5 keys within 8
 *   tiles of the start (about 70-75 % of them in the benches).
 * - Otherwise A* over room state x collected-key set, pruned by the upper
 *   bound, with an admissible heuristic (a backward program over key sets
 *   on the legs' lower bounds), within budget (0: arena capacity). It is
 *   exact when the A* reaches the chest or runs dry below the bound;
 *   otherwise the bound's tour (exact = 0), or without one, keys nearest
 *   first with hol_nav_find legs (exact = 0).
 * A key under the start counts as collected. nkeys = 0 is hol_nav_find.
 * Errors: as hol_nav_find (HOL_EUNREACH: a key or the chest that no walk
 * reaches); HOL_EARG for nkeys outside 0..5. */
/* Build the state-to-state leg table of exact tours now (about 80 ms once)
 * instead of in the first hol_nav_tour call, so no tour pays for it; the
 * app calls it at create. Idempotent. */
void hol_nav_prepare_tours(hol_nav *nav);

hol_err hol_nav_tour(hol_nav *nav, const hol_room *start, const hol_tile *keys,
                     int nkeys, hol_tile chest, size_t budget,
                     uint8_t *out_walk, size_t cap, hol_nav_result *out_result);

/* Hot-cold field (minimap). One entry per tile within `radius` tiles of the
 * user's tile. */
typedef struct hol_nav_cell {
    hol_tile tile; /* absolute tile */
    hol_tile rel;  /* its address seen from the user (room north as N) */
    int16_t user_dist; /* tiles from the user's tile (rel's length) */
    int16_t hot;       /* tile distance to the nearest objective; -1 if none */
} hol_nav_cell;

/* Entries hol_nav_field writes for a radius (0..8): 1, 5, 17, 45, 109, ...
 * in {4,5}; hol_nav_field_count_q in {4,q}. */
size_t hol_nav_field_count(int radius);
size_t hol_nav_field_count_q(int q, int radius);

/* Fill out_cells (cap entries) with the field around user (tile and room
 * orientation); objectives: n tiles (n may be 0: every hot is -1). Entries
 * come ordered by user_dist, the user's tile first. *out_n receives the
 * number written. Errors: HOL_EARG (radius outside 0..8), HOL_ENOMEM (cap
 * below hol_nav_field_count(radius)), HOL_ERANGE (a tile beyond reach). */
hol_err hol_nav_field(const hol_room *user, int radius, const hol_tile *objectives,
                      size_t n, hol_nav_cell *out_cells, size_t cap,
                      size_t *out_n);

/* Direction arrow: angle in radians counter-clockwise from room north (the
 * room's -z axis seen from above; west is +pi/2) from the centre of the
 * user's tile to the objective's centre, and the hyperbolic distance between
 * the centres (curvature radius units). Correct for every pair of tiles in
 * reach (precision depends only on their distance). The angle is 0 when the
 * objective is the user's tile. Either output may be NULL. In {4,4} the
 * distance is in tile sides. */
hol_err hol_nav_direction(const hol_room *user, hol_tile objective,
                          double *out_angle, double *out_dist);

#endif
