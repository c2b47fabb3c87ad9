/* hol_nav_arena.h - the search arena of guidance: nodes, a hash of states,
 * a bucket queue on f; walks (room steps out) and descents of a table.
 *
 * Contract: not a public header; names are hol__*. The lowest layer of
 * guidance above the tables (hol_nav_impl.h lists the files): it knows
 * the table (hol_nav_table.h) and tiles, never the navigator. The arena's
 * memory is the caller's (hol_nav_create carves it from the navigator's
 * block); hol__arena_reset empties it per query; nothing here allocates.
 */
#ifndef HOL_NAV_ARENA_H
#define HOL_NAV_ARENA_H

#include <stddef.h>
#include <stdint.h>

#include "hol_nav_table.h"
#include "hol_tile.h"

#define HOL__FMAX 8192 /* f values of the bucket queue: 0 .. HOL__FMAX - 1 */
#define HOL__NIL UINT32_MAX
#define HOL__INSIDE 0x80u /* node flag: u.idx is a table index */
#define HOL__MASK 0x3fu   /* node flags: the keys' mask (tours) */

/* A search state: a tile (or table index), the room's orientation o and
 * cell, its cost g, f = g + h, and the step dir from its parent. */
typedef struct hol__node {
    union {
        hol_tile t;   /* relative (nav, outside the table) or absolute (tour) */
        uint32_t idx; /* table index (nav, inside the table) */
    } u;
    uint32_t parent, spare;
    uint16_t g, f;
    uint8_t o, cell, dir, flags; /* flags: HOL__INSIDE | key mask */
} hol__node;

/* The arena: nodes, the hash of their states, open entries by f. */
typedef struct hol__arena {
    hol__node *nodes;
    uint32_t cap, count;
    uint32_t *hash; /* node index + 1; 0 empty */
    uint32_t hash_mask;
    uint32_t *bucket; /* HOL__FMAX heads of open-entry lists */
    uint32_t *ent;    /* open entries: node id, next entry (pairs) */
    uint32_t ent_cap, ent_n;
    uint32_t fmin;
    int hash_dirty;     /* 1: the hash may hold anything (the nodes served
                         * as scratch or as the tour's table): clear it whole */
} hol__arena;

/* Empty the arena for a new search. */
void hol__arena_reset(hol__arena *ar);
/* Find the node equal to *n, or add it (*out_new tells which); HOL__NIL
 * when the arena is full. */
uint32_t hol__arena_intern(hol__arena *ar, const hol__node *n, int *out_new);
/* Relax the step d from node `parent` to the state *nx at cost g: intern
 * it and, when g improves on its cost, record g, parent and step and
 * return its index. HOL__NIL: nothing improved (g too large, or known at
 * least as cheap), or the arena is full (then *out_full = 1). */
uint32_t hol__arena_relax(hol__arena *ar, const hol__node *nx, uint32_t parent, int d,
                          int g, int *out_full);
/* Queue node id under its f; 0 when the entry pool is full. */
int hol__arena_push(hol__arena *ar, uint32_t id);
/* The newest node of the lowest f (stale entries skipped), or HOL__NIL. */
uint32_t hol__arena_pop(hol__arena *ar);

/* Output buffer of a walk. */
typedef struct hol__walk {
    uint8_t *dirs;
    size_t cap, n;
    int overflow;
} hol__walk;
void hol__nav_emit(hol__walk *w, int dir);
/* Room steps from the search root to node id, appended to w. */
void hol__arena_path(const hol__arena *ar, uint32_t id, hol__walk *w);

/* Cell after a room step, -1 outside the room. */
static inline int hol__nav_cell_step(const hol_navtab *tab, int cell, int dir)
{
    return tab->cellnb[cell][dir & 3];
}
/* Descend the tile table from (idx, o, cell) to cost 0; returns the steps. */
int hol__nav_descend(const hol_navtab *tab, uint32_t idx, int o, int cell, hol__walk *w);

/* The descent both tables share: from (idx, o, cell), step to a neighbour
 * (tile index below n) whose cost(ctx, idx, o, cell) is one less, until 0;
 * returns the steps. Inline so that each caller's cost is inlined too. */
typedef int (*hol__cost_fn)(const void *ctx, uint32_t idx, int o, int cell);
static inline int hol__descend(const hol_navtab *tab, uint32_t n, hol__cost_fn cost,
                               const void *ctx, uint32_t idx, int o, int cell, hol__walk *w)
{
    int v = cost(ctx, idx, o, cell), steps = 0;
    while (v > 0 && v < 255) {
        int moved = 0;
        for (int d = 0; d < 4 && !moved; d++) {
            int c2 = hol__nav_cell_step(tab, cell, d);
            if (c2 < 0)
                continue;
            uint32_t e = tab->nb[4 * (size_t)idx + (size_t)((o + d) & 3)];
            if (e == HOL_NAVTAB_NONE || (e >> 2) >= n)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            if (cost(ctx, e >> 2, o2, c2) == v - 1) {
                hol__nav_emit(w, d);
                idx = e >> 2;
                o = o2;
                cell = c2;
                v--;
                steps++;
                moved = 1;
            }
        }
        if (!moved)
            break; /* cannot happen for a BFS table */
    }
    return steps;
}

#endif
