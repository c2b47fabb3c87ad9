/* hol_nav_impl.h - internals shared by hol_nav.c (navigator, arena, fewest
 * steps), hol_nav_tour.c (keys and chest) and hol_nav_field.c (minimap).
 *
 * Contract: not a public header; names are hol__nav_*. The navigator is one
 * block from hol_nav_create: the cost table, the tour leg table and the
 * search arena (nodes, hash of states, bucket queue of open entries). The
 * arena is reset per query; nothing here allocates.
 */
#ifndef HOL_NAV_IMPL_H
#define HOL_NAV_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "hol_nav.h"
#include "hol_nav_table.h"

#define HOL__FMAX 8192
#define HOL__LEG_RADIUS 10 /* tour legs exact between tiles within 7 */
#define HOL__NIL UINT32_MAX
#define HOL__SPHERE_MAX 1024 /* tiles at the leg table's trusted radius (780 at 7) */
#define HOL__INSIDE 0x80u
#define HOL__MASK 0x3fu

typedef struct hol__node {
    union {
        hol_tile t;   /* relative (nav, outside the table) or absolute (tour) */
        uint32_t idx; /* table index (nav, inside the table) */
    } u;
    uint32_t parent, spare;
    uint16_t g, f;
    uint8_t o, cell, dir, flags; /* flags: HOL__INSIDE | key mask */
} hol__node;

struct hol_nav {
    hol_navtab tab;
    int trust;          /* table costs within it are exact */
    int far_base16;     /* extrapolation: 16 x mean cost at trust */
    int far_slope16;    /* 16 x mean cost per tile */
    int margin;         /* anytime: explore f up to best + margin */
    hol__node *nodes;
    uint32_t cap, count;
    uint32_t *hash; /* node index + 1; 0 empty */
    uint32_t hash_mask;
    uint32_t *bucket; /* HOL__FMAX heads of open-entry lists */
    uint32_t *ent;    /* open entries: node id, next entry (pairs) */
    uint32_t ent_cap, ent_n;
    uint32_t fmin;
    int hash_dirty;     /* 1: the hash may hold anything (the arena served as
                         * scratch or as the tour's table): clear it whole */
    uint8_t *leg;       /* tour leg table (state to state), built lazily */
    int leg_radius, leg_trust, leg_ready;
    uint8_t *far_e;     /* HOL__SPHERE_MAX x 36: least leg from a tile on the
                         * leg table's trusted sphere to each goal state,
                         * filled with the leg table (hol_nav_tour.c) */
    size_t bytes;
    void *block;
    void (*free_fn)(void *ptr, void *user);
    void *user;
};

/* Output buffer of a walk. */
typedef struct hol__walk {
    uint8_t *dirs;
    size_t cap, n;
    int overflow;
} hol__walk;

/* Shared internals (hol_nav.c), used by hol_nav_tour.c and hol_nav_field.c. */
void hol__nav_reset(hol_nav *nav);
/* Find the node equal to *n, or add it; HOL__NIL when the arena is full. */
uint32_t hol__nav_intern(hol_nav *nav, const hol__node *n, int *out_new);
/* Relax the step d from node `parent` to the state *nx at cost g: intern
 * it and, when g improves on its cost, record g, parent and step and
 * return its index. HOL__NIL: nothing improved (g too large, or known at
 * least as cheap), or the arena is full (then *out_full = 1). */
uint32_t hol__nav_relax(hol_nav *nav, const hol__node *nx, uint32_t parent, int d,
                        int g, int *out_full);
/* Queue node id under its f; 0 when the entry pool is full. */
int hol__nav_push(hol_nav *nav, uint32_t id);
/* The newest node of the lowest f (stale entries skipped), or HOL__NIL. */
uint32_t hol__nav_pop(hol_nav *nav);
/* Cell (col + 3 * row) after a room step, -1 outside the room. */
int hol__nav_cell_step(int cell, int dir);
int hol__nav_room_ok(const hol_room *r);
void hol__nav_emit(hol__walk *w, int dir);
/* Descend the tile table from (idx, o, cell) to cost 0; returns the steps. */
int hol__nav_descend(const hol_navtab *tab, uint32_t idx, int o, int cell, hol__walk *w);
/* Bytes of arena the tours use as scratch (hol_nav_tour.c): the dynamic
 * program's table, then the far keys' bounds. */
size_t hol__nav_tour_scratch(void);
/* Room steps from the search root to node id, appended to w. */
void hol__nav_emit_path(hol_nav *nav, uint32_t id, hol__walk *w);

#endif
