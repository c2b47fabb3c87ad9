/* hol_nav_impl.h - internals shared by the guidance files.
 *
 * Contract: not a public header; names are hol__*. The navigator is one
 * block from hol_nav_create: the cost table, the tour leg table and the
 * search arena (nodes, hash of states, bucket queue of open entries). The
 * arena is reset per query; nothing here allocates.
 *
 * The files, lowest first (each calls only the ones above it, never one
 * below): hol_nav_table.c (tables), hol_nav_arena.c (the arena, walks,
 * descents; hol_nav_arena.h: it knows the tables, not the navigator),
 * hol_nav_legs.c (tour legs), hol_nav.c (the navigator and
 * hol_nav_find), hol_nav_tour.c (tours), hol_nav_field.c (minimap field
 * and arrows: pure functions of tiles). hol_nav.c sizes the tours' scratch
 * from the struct below, without calling into hol_nav_tour.c.
 *
 * Room states: s = ncell * o + cell (o the room's north relative to the
 * tile's heading, cell = col + cols * row), nst = 4 * ncell of them on a
 * tile (36 in a 3 x 3 room, at most HOL__MAXST).
 */
#ifndef HOL_NAV_IMPL_H
#define HOL_NAV_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "hol_nav.h"
#include "hol_nav_arena.h"
#include "hol_nav_table.h"

#define HOL__MAXST HOL_NAVTAB_MAX_NST /* room states a tile, at most */
#define HOL__LEG_RADIUS 10 /* tour legs exact between tiles within 7 */
#define HOL__SPHERE_MAX 2048 /* tiles at the leg table's trusted radius (780 at 7; 1508 in {4,6}) */
#define HOL__SPH_CACHE 8 /* spheres kept (hol_nav_legs.c), > HOL_NAV_TOUR_MAX_KEYS */

struct hol_nav {
    hol_navtab tab; /* and the configuration: tab.q, tab.cols, tab.rows */
    uint8_t par[HOL__MAXST]; /* (o + col + row) mod 2 of each room state */
    int trust;          /* table costs within it are exact */
    int partial;        /* 1: some room states reach some tiles within the
                         * trusted radius never ({4,4}, {4,8}) */
    int far_base16;     /* extrapolation: 16 x mean cost at trust */
    int far_slope16;    /* 16 x mean cost per tile */
    int margin;         /* anytime: explore f up to best + margin */
    int tabled;         /* the table finished and the fields above set
                         * (hol__nav_complete): lazy navigators at the
                         * first query that needs more than a descent */
    hol__arena ar;      /* the search arena (hol_nav_arena.h); its nodes
                         * also serve as the tours' and leg build's scratch */
    uint8_t *leg;       /* tour leg table (state to state), built lazily */
    int leg_radius, leg_trust, leg_ready;
    uint8_t *far_e;     /* HOL__SPHERE_MAX x nst: least leg from a tile on the
                         * leg table's trusted sphere to each goal state,
                         * filled with the leg table (hol__far_e_fill) */
    struct hol__sph *sph; /* HOL__SPH_CACHE spheres around recent keys */
    hol_tile sph_tile[HOL__SPH_CACHE];
    uint32_t sph_stamp[HOL__SPH_CACHE]; /* last use, 0: empty */
    uint32_t sph_clock;
    size_t bytes;
    void *block;
    void (*free_fn)(void *ptr, void *user);
    void *user;
};

/* Finish the table (its build's scratch spans the leg table and the
 * arena) and set the fields that come from it (far_base16, far_slope16,
 * partial): before any use of those, the arena, the leg table or a table
 * cost other than through hol_navtab_need. Idempotent. */
void hol__nav_complete(hol_nav *nav);

/* ---- tour legs (hol_nav_legs.c) ---- */

#define HOL__VIA_DIRECT 0xffffu /* the leg table (or main table) directly */
#define HOL__VIA_MID 0xfffeu    /* through the tile midway along a geodesic */
#define HOL__KEY_MAX 511        /* cheap bounds are clamped to this */

/* A source tile seen from a destination: its table index and heading. */
typedef struct hol__rel {
    uint32_t idx;
    int facing;
} hol__rel;

/* 1 and *out when `from` lies within `trust` of `to`. */
int hol__rel_of(const hol_nav *nav, hol_tile from, hol_tile to, int trust, hol__rel *out);

/* Lower bound (the main table, exact within its trusted radius) on the
 * steps from room state (tile, o, cell) to stand on target. */
int hol__lb_state(const hol_nav *nav, hol_tile tile, int o, int cell, hol_tile target);
/* The same in two parts: `from` seen from `to` (ranked within the main
 * table's radius), returning their distance (HOL_TILE_MAX_DIST + 1 beyond
 * reach); then the bound from room state s = 9 * o + cell on `from`. */
int hol__rel_ranked(const hol_nav *nav, hol_tile from, hol_tile to, hol__rel *out);
int hol__lb_rel(const hol_nav *nav, const hol__rel *r, int d, int s);

/* The sphere of radius leg_trust around a key: tile x (absolute) is
 * nav->tab.off[leg_trust] + x seen from the key. n = 0: none (the leg
 * table is not built, too small, or the sphere leaves the reach). */
typedef struct hol__sph {
    uint32_t n;
    hol_tile tile[HOL__SPHERE_MAX];
    hol__rel from_key[HOL__SPHERE_MAX]; /* hol__rel_of(tile[x], key) */
} hol__sph;

/* A leg from every source state in src to every state on a key: lb a
 * lower bound on the fewest steps, ub the steps of a walk (255: none
 * found), that walk through (vt[vx], vm) or HOL__VIA_*. ub == lb: exact.
 * The tables are nst x nst, row s (a source state) at s * nst
 * (HOL__LX(L, s, s2)), so a 3 x 3 room's fill a compact corner. */
typedef struct hol__legb {
    int nst;
    uint8_t ub[HOL__MAXST * HOL__MAXST], lb[HOL__MAXST * HOL__MAXST];
    uint16_t vx[HOL__MAXST * HOL__MAXST];
    uint8_t vm[HOL__MAXST * HOL__MAXST];
    const hol_tile *vt;
    hol_tile mid;
} hol__legb;
#define HOL__LX(L, s, s2) ((size_t)(s) * (size_t)(L)->nst + (size_t)(s2))

/* The same from every room state on a key to stand on the chest's tile. */
typedef struct hol__chestb {
    uint8_t ub[HOL__MAXST], lb[HOL__MAXST];
    uint16_t vx[HOL__MAXST];
    uint8_t vm[HOL__MAXST];
    const hol_tile *vt;
    hol_tile mid;
} hol__chestb;

/* Scratch of the sphere passes. */
typedef struct hol__legx {
    hol__rel r;
    uint8_t d, c1[HOL__MAXST], u2[HOL__MAXST];
} hol__legx;
typedef struct hol__legscr {
    hol__legx x[HOL__SPHERE_MAX];
    uint16_t key[HOL__SPHERE_MAX], order[HOL__SPHERE_MAX];
    /* a sphere tile's legs to the key (hol_nav_legs.c's hol__fan) */
    struct hol__fanbuf {
        uint8_t p2[HOL__MAXST][HOL__MAXST], z2[HOL__MAXST][HOL__MAXST];
        int nz[HOL__MAXST];
    } fan;
    uint8_t c2[HOL__MAXST];
} hol__legscr;

/* nav->far_e, once the leg table is built (hol_nav_prepare_tours). */
void hol__far_e_fill(hol_nav *nav);
/* Needs the leg table (hol_nav_prepare_tours). */
void hol__sph_fill(const hol_nav *nav, hol_tile key, hol__sph *out_sph);
/* The sphere around key from the navigator's cache (filled on a miss,
 * replacing the least recently used): the keys of a level stay the same
 * while the tour is planned again at every room step. Valid until
 * HOL__SPH_CACHE - 1 further calls. */
const hol__sph *hol__sph_get(hol_nav *nav, hol_tile key);
/* Leg bounds from states src[0..nsrc) on tile a to key b (sphere sb). */
void hol__legb_fill(const hol_nav *nav, hol_tile a, hol_tile b, const hol__sph *sb,
                    const int *src, int nsrc, hol__legb *out_leg, hol__legscr *scr);
/* The leg from b to a, from L's from a to b (with every source state):
 * steps reverse, so the bounds are the same and the walk goes through the
 * same room state on the same tile. */
void hol__legb_reverse(const hol__legb *L, hol__legb *out_rev);
/* From key a (sphere sa) to the chest's tile. */
void hol__chestb_fill(const hol_nav *nav, hol_tile a, hol_tile chest, const hol__sph *sa,
                      hol__chestb *out_leg, hol__legscr *scr);

/* ---- the navigator's configuration ---- */
/* A valid room state of the navigator's configuration (tiling, size). */
static inline int hol__nav_room_ok(const hol_nav *nav, const hol_room *r)
{
    return hol_room_ok(r) && hol_tile_q(r->tile) == nav->tab.q &&
           hol_room_cols(r) == nav->tab.cols && hol_room_rows(r) == nav->tab.rows;
}
/* Its room state s = ncell * orient + col + cols * row. */
static inline int hol__nav_state(const hol_nav *nav, const hol_room *r)
{
    return nav->tab.ncell * r->orient + r->col + nav->tab.cols * r->row;
}
/* A tile of the navigator's tiling within the reach. */
static inline int hol__nav_tile_ok(const hol_nav *nav, hol_tile t)
{
    return hol_tile_q(t) == nav->tab.q;
}

/* The walk of leg L from state s on tile a to s2 on b (its ub steps),
 * appended to w; and of C from s on key a to the chest. */
void hol__legb_walk(const hol_nav *nav, const hol__legb *L, hol_tile a, int s, hol_tile b,
                    int s2, hol__walk *w);
void hol__chestb_walk(const hol_nav *nav, const hol__chestb *C, hol_tile a, int s,
                      hol_tile chest, hol__walk *w);

/* ---- tours (hol_nav_tour.c): the dynamic program, in the arena ----
 * cost, lower, pj, ps: [mask][key j][state s] at HOL__DPX(nst, m, j, s):
 * F[mask][j][s], the fewest steps from the start to stand on key j in room
 * state s having first visited the keys in mask, j last (cost: over the
 * legs' walks; lower: over their lower bounds); pj the previous key (-1:
 * the start), ps its state. Here so that hol_nav.c sizes the arena without
 * calling into the tours. */
#define HOL__NK HOL_NAV_TOUR_MAX_KEYS
#define HOL__DPX(nst, m, j, s) (((size_t)(m) * HOL__NK + (size_t)(j)) * (size_t)(nst) + (size_t)(s))
typedef struct hol__dp {
    uint16_t cost[(1 << HOL__NK) * HOL__NK * HOL__MAXST];
    uint16_t lower[(1 << HOL__NK) * HOL__NK * HOL__MAXST];
    int8_t pj[(1 << HOL__NK) * HOL__NK * HOL__MAXST];
    uint8_t ps[(1 << HOL__NK) * HOL__NK * HOL__MAXST];
    hol__legb leg[HOL__NK + 1][HOL__NK]; /* from key j (or the start, nk) to key k */
    hol__chestb chest[HOL__NK];
    const hol__sph *sph[HOL__NK]; /* the navigator's cache, or none */
    hol__sph none;                /* n = 0 */
    hol__legscr scr;
} hol__dp;

#endif
