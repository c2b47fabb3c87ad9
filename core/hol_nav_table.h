/* hol_nav_table.h - the exact cost table behind hol_nav (internal module).
 *
 * Contract
 * - A table serves one configuration: the tiling {4,q} and a room of
 *   cols x rows cells (cell index col + cols * row). hol_navtab_init sets
 *   it and the numbering; the build fills caller memory.
 * - Tiles within `radius` of O are numbered densely (O = 0, then by address
 *   length, then lexicographically by letter code) with an exact rank and
 *   unrank through the tiling's canonical-address automaton (a copy of
 *   hol_tile_automaton_q; the tests check both agree).
 * - nb[4 * i + t] is the neighbour of tile i across the edge in turn t
 *   (relative to its canonical heading): (index << 2) | arrive, where arrive
 *   is the direction of travel on arrival relative to the neighbour's
 *   heading; HOL_NAVTAB_NONE when the neighbour lies beyond the radius.
 * - Room states on a tile: (o, cell), o the room's north relative to the
 *   tile's heading: 4 * cells of them (nst). Turning the whole room maps
 *   walks to walks, so the table stores only `per` of them a tile: a square
 *   room turned a quarter is itself (per = cells, o = 0 stored, other
 *   orientations turn the cell); an oblong one only turned a half (per =
 *   2 * cells, o = 0 and 1 stored). rot[o][cell] is the stored index of a
 *   state (hol_navtab_cost).
 * - cost[per * i + k] is, for a user whose tile seen from the target is
 *   tile i in stored state k, the fewest room steps to stand on the target
 *   (tile O) among walks whose tiles all stay within the radius. 255 means
 *   unreachable inside the radius (in {4,4} every tile off the room's own
 *   C x R; never in the other tilings for r >= 2).
 * - The table is filled once (hol_navtab_build) in caller memory; lookups
 *   are pure and thread safe. Or by parts (hol_navtab_begin, then
 *   hol_navtab_need for each state read, hol_navtab_finish for the rest):
 *   the BFS a level of cost at a time, the neighbours a tile at a time in
 *   index order, so a near query pays for the states nearer the goal than
 *   its own (see hol_navtab_need for what may be read meanwhile). The
 *   finished table is the same, byte for byte, however it was reached.
 */
#ifndef HOL_NAV_TABLE_H
#define HOL_NAV_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_room.h"
#include "hol_tile.h"

#define HOL_NAVTAB_NONE UINT32_MAX
#define HOL_NAVTAB_MAX_RADIUS 17
#define HOL_NAVTAB_MAX_NST (4 * HOL_ROOM_MAX_CELLS) /* room states a tile, 100 */

typedef struct hol_navtab {
    int radius;
    int q, cols, rows, ncell;
    int per; /* stored room states a tile: ncell (square room) or 2 * ncell */
    int nst; /* room states a tile: 4 * ncell */
    int nstates; /* automaton states */
    uint32_t count;                        /* tiles within the radius */
    uint32_t off[HOL_NAVTAB_MAX_RADIUS + 2];  /* first index of each length */
    uint32_t cnt[HOL_TILE_MAX_STATES][HOL_NAVTAB_MAX_RADIUS + 1]; /* suffix counts per state */
    int8_t next[HOL_TILE_MAX_STATES][4]; /* hol_tile_automaton_q, cached */
    uint8_t rot[4][HOL_ROOM_MAX_CELLS];  /* stored index of state (o, cell) */
    uint8_t turn[4];                     /* g: the quarter turns that bring o to a stored one */
    uint8_t rotc[4][HOL_ROOM_MAX_CELLS]; /* a cell after turning the room g quarter turns */
    uint8_t so[HOL_NAVTAB_MAX_NST];      /* stored index k: its orientation */
    uint8_t sc[HOL_NAVTAB_MAX_NST];      /* and its cell */
    int8_t cellnb[HOL_ROOM_MAX_CELLS][4]; /* cell after a room step, -1 outside */
    uint32_t *nb;   /* 4 * count */
    uint8_t *cost;  /* per * count */
    int min_at_radius; /* least cost over states at exactly `radius` */
    int proved_radius; /* costs within it are proved exact by the bound */
    int min_at[HOL_NAVTAB_MAX_RADIUS + 1];  /* least cost at each distance */
    int mean16_at[HOL_NAVTAB_MAX_RADIUS + 1]; /* 16 x mean finite cost */
    /* the build by parts: min_at_radius .. mean16_at are set at its end */
    int complete;       /* 1: built whole (hol_navtab_finish) */
    hol_tile *nbt;      /* scratch: the tiles made so far, and */
    uint8_t *nbs;       /* their automaton states */
    uint32_t nb_done;   /* tiles before it have all their neighbours */
    uint32_t nb_kids;   /* tiles made (nbt) */
    int nb_len;         /* length of the last tile done */
    int init_len;       /* levels 0..init_len have their entries set */
    int bfs_v;          /* the next BFS level to expand */
    size_t bfs_lo, bfs_hi; /* the span of its states */
} hol_navtab;

/* Tiles within radius r of a tile of {4,q} (r <= HOL_NAVTAB_MAX_RADIUS);
 * hol_navtab_count is {4,5}. 0 for bad arguments or more than 2^32. */
uint32_t hol_navtab_count_q(int q, int radius);
uint32_t hol_navtab_count(int radius);

/* Set the configuration ({4,q}, cols x rows; zero: 5, 3, 3) and the
 * numbering (off, cnt, count) for radius 0..HOL_NAVTAB_MAX_RADIUS: enough
 * for rank and unrank, no memory needed. HOL_EARG for bad values.
 * hol_navtab_init_index is the same for {4,5} and 3 x 3. */
hol_err hol_navtab_init(hol_navtab *tab, int q, int cols, int rows, int radius);
hol_err hol_navtab_init_index(hol_navtab *tab, int radius);

/* Bytes hol_navtab_build needs for an initialised tab: table memory and
 * scratch memory. */
size_t hol_navtab_table_bytes(const hol_navtab *tab);
size_t hol_navtab_scratch_bytes(const hol_navtab *tab);

/* Build the initialised tab (radius >= 1) in `mem` (hol_navtab_table_bytes)
 * using `scratch` (overwritten). */
hol_err hol_navtab_build(hol_navtab *tab, void *mem, void *scratch);

/* The same by parts. hol_navtab_begin: the goal's states only (scratch
 * must stay the table's until hol_navtab_finish). hol_navtab_need: the
 * cost of state (idx, o, cell), the BFS run until it is known (255: none
 * reaches it, the BFS ended); then it, every state of a lower cost and
 * the neighbours of tile idx and of the tiles of those states are as in
 * the whole table, so a descent from it (hol__nav_descend) takes the same
 * steps. Nothing else of the table may be read before hol_navtab_finish
 * (which completes it and certifies it: min_at_radius .. mean16_at). */
hol_err hol_navtab_begin(hol_navtab *tab, void *mem, void *scratch);
int hol_navtab_need(hol_navtab *tab, uint32_t idx, int o, int cell);
void hol_navtab_finish(hol_navtab *tab);

/* Index of tile t (of the table's tiling), or HOL_NAVTAB_NONE if it lies
 * beyond the radius. */
uint32_t hol_navtab_rank(const hol_navtab *tab, hol_tile t);
hol_tile hol_navtab_unrank(const hol_navtab *tab, uint32_t idx);
int hol_navtab_len(const hol_navtab *tab, uint32_t idx);

/* ---- leg table: state-to-state costs for tours ----
 * leg[nst * (per * i + k) + s2] is, for a user on tile i (seen from the
 * target as above) in stored state k, the fewest steps to stand on the
 * target in room state s2 = ncell * ob + cb (ob relative to the target's
 * heading, cell cb), among walks within leg_radius. Only tiles
 * i < hol_navtab_count_q(q, leg_radius) are covered; the neighbour table
 * of `tab` (radius >= leg_radius) is reused. In {4,5} 3 x 3, costs within
 * leg_radius - 3 equal those of every larger leg table (the tests check r
 * against r + 1; one tile less than the tile table, as a given final room
 * state may need one more tile of room to turn into). */
size_t hol_navtab_leg_bytes(const hol_navtab *tab, int leg_radius);
size_t hol_navtab_leg_scratch_bytes(const hol_navtab *tab, int leg_radius);
hol_err hol_navtab_build_legs(const hol_navtab *tab, int leg_radius, uint8_t *out_leg,
                              void *scratch);

/* Cell index after rotating a square room by o quarter turns
 * counter-clockwise ({4,5} 3 x 3 cells; the tables use rot and rotc). */
int hol_navtab_rot_cell(int o, int cell);

/* Table cost (within the radius) of tile index idx, orientation o, cell. */
static inline int hol_navtab_cost(const hol_navtab *tab, uint32_t idx, int o, int cell)
{
    return tab->cost[(size_t)tab->per * idx + tab->rot[o & 3][cell]];
}

/* Leg cost for a user (tile index i, room north o, cell) to stand on the
 * target with room north ob on cell cb (see above): the room turned by g
 * (tab->turn[o]) brings the user to a stored state, and the goal with it. */
static inline int hol_navtab_leg(const hol_navtab *tab, const uint8_t *leg, uint32_t idx,
                                 int o, int cell, int ob, int cb)
{
    int g = tab->turn[o & 3];
    return leg[(size_t)tab->nst * ((size_t)tab->per * idx + tab->rot[o & 3][cell]) +
               (size_t)(tab->ncell * ((ob - g) & 3) + tab->rotc[g][cb])];
}

/* A lower bound on the true fewest steps (walks may leave the radius) for a
 * user at tile distance d from the target: exact (= table cost) where the
 * table cost does not exceed hol_navtab_exit_bound(d). */
static inline int hol_navtab_exit_bound(const hol_navtab *tab, int d)
{
    /* Leaving the ball takes radius + 1 - d steps and costs at least
     * min_at_radius + 1 from outside (see hol_nav_table.c). */
    if (d <= tab->radius)
        return tab->radius + 2 - d + tab->min_at_radius;
    return d - tab->radius + tab->min_at_radius;
}

#endif
