/* hol_nav_table.h - the exact cost table behind hol_nav (internal module).
 *
 * Contract
 * - Tiles within `radius` of O are numbered densely (O = 0, then by address
 *   length, then lexicographically by letter code) with an exact rank and
 *   unrank through the canonical-address automaton (a copy of the one
 *   documented in hol_tile.c; the tests check both agree).
 * - nb[4 * i + t] is the neighbour of tile i across the edge in turn t
 *   (relative to its canonical heading): (index << 2) | arrive, where arrive
 *   is the direction of travel on arrival relative to the neighbour's
 *   heading; HOL_NAVTAB_NONE when the neighbour lies beyond the radius.
 * - cost[9 * i + cell] is, for a user whose tile seen from the target is
 *   tile i with room north equal to i's canonical heading, standing on
 *   `cell` (col + 3 * row), the fewest room steps to stand on the target
 *   (tile O) among walks whose tiles all stay within the radius. Other room
 *   orientations o map to it by rotating the cell: hol_navtab_cost below.
 *   255 means unreachable inside the radius (does not happen for r >= 2).
 * - The table is filled once (hol_navtab_build) in caller memory; lookups
 *   are pure and thread safe.
 */
#ifndef HOL_NAV_TABLE_H
#define HOL_NAV_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_tile.h"

#define HOL_NAVTAB_NONE UINT32_MAX
#define HOL_NAVTAB_MAX_RADIUS 17

typedef struct hol_navtab {
    int radius;
    uint32_t count;                        /* tiles within the radius */
    uint32_t off[HOL_NAVTAB_MAX_RADIUS + 2];  /* first index of each length */
    uint32_t cnt[HOL_TILE_STATES][HOL_NAVTAB_MAX_RADIUS + 1]; /* suffix counts per state */
    int8_t next[HOL_TILE_STATES][4]; /* hol_tile_automaton, cached */
    uint32_t *nb;   /* 4 * count */
    uint8_t *cost;  /* 9 * count */
    int min_at_radius; /* least cost over states at exactly `radius` */
    int proved_radius; /* costs within it are proved exact by the bound */
    int min_at[HOL_NAVTAB_MAX_RADIUS + 1];  /* least cost at each distance */
    int mean16_at[HOL_NAVTAB_MAX_RADIUS + 1]; /* 16 x mean finite cost */
} hol_navtab;

/* Tiles within radius r of a tile (r <= HOL_NAVTAB_MAX_RADIUS). */
uint32_t hol_navtab_count(int radius);
/* Bytes hol_navtab_build needs: table memory and scratch memory. */
size_t hol_navtab_table_bytes(int radius);
size_t hol_navtab_scratch_bytes(int radius);

/* Fill only the numbering (off, cnt, count) for radius 0..15: enough for
 * rank and unrank, no memory needed. */
hol_err hol_navtab_init_index(hol_navtab *tab, int radius);

/* Build in `mem` (hol_navtab_table_bytes) using `scratch` (overwritten). */
hol_err hol_navtab_build(hol_navtab *tab, int radius, void *mem, void *scratch);

/* Index of tile t, or HOL_NAVTAB_NONE if it lies beyond the radius. */
uint32_t hol_navtab_rank(const hol_navtab *tab, hol_tile t);
hol_tile hol_navtab_unrank(const hol_navtab *tab, uint32_t idx);
int hol_navtab_len(const hol_navtab *tab, uint32_t idx);

/* ---- leg table: state-to-state costs for tours ----
 * leg[36 * (9 * i + cell) + 9 * ob + cb] is, for a user on tile i (seen
 * from the target as above, room north = i's heading, so o = 0) on `cell`,
 * the fewest steps to stand on the target with room north ob (relative to
 * the target's heading) on cell cb, among walks within leg_radius. Only
 * tiles i < hol_navtab_count(leg_radius) are covered; the neighbour table
 * of `tab` (radius >= leg_radius) is reused. Costs within leg_radius - 3
 * equal those of every larger leg table (the tests check r against r + 1;
 * one tile less than the tile table, as a given final room state may need
 * one more tile of room to turn into). */
size_t hol_navtab_leg_bytes(int leg_radius);
size_t hol_navtab_leg_scratch_bytes(int leg_radius);
hol_err hol_navtab_build_legs(const hol_navtab *tab, int leg_radius, uint8_t *out_leg,
                              void *scratch);

/* Cell index (col + 3 * row) after rotating the room by o quarter turns
 * counter-clockwise. */
int hol_navtab_rot_cell(int o, int cell);

/* Table cost (within the radius) of tile index idx, orientation o, cell. */
static inline int hol_navtab_cost(const hol_navtab *tab, uint32_t idx, int o,
                                  int cell)
{
    return tab->cost[9 * (size_t)idx + (size_t)hol_navtab_rot_cell(o, cell)];
}

/* Leg cost for a user (tile index i, room north o, cell) to stand on the
 * target with room north ob on cell cb (see above). */
static inline int hol_navtab_leg(const uint8_t *leg, uint32_t idx, int o, int cell,
                                 int ob, int cb)
{
    return leg[36 * (9 * (size_t)idx + (size_t)hol_navtab_rot_cell(o, cell)) +
               (size_t)(9 * ((ob - o) & 3) + hol_navtab_rot_cell(o, cb))];
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
