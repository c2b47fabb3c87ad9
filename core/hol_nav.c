/* hol_nav.c - fewest room steps, anytime search, tours, field, direction.
 *
 * Near targets (tile distance <= the table's trusted radius, radius - 2)
 * are answered by descending the exact cost table: from the start, take a
 * step whose successor costs one less, until the cost is 0. No search.
 *
 * Farther targets use a best-first search over relative room states
 * (user tile seen from the target, room north, cell) with nodes in the
 * arena: f = g + H, H the table cost where the state lies within the table
 * and an extrapolation (the mean table cost at the trusted radius plus the
 * mean cost per tile) beyond. Every node inside the table offers a complete
 * walk (its path plus the table descent); the best one is kept. A node
 * within the trusted radius is not expanded (no walk through it beats
 * g + its exact cost), nor one whose admissible bound (it must cross the
 * trusted sphere) cannot beat the best. The search stops at the node
 * budget, or when the least f exceeds the best by the margin (H is only an
 * estimate, so a margin of 16 steps finds the optimum in every case the
 * bench can check). With nothing inside the table within the budget,
 * waypoints on the geodesic to the target chain exact legs. These answers
 * are flagged exact = 0.
 *
 * Tours: with start, keys and chest close together (the leg table's
 * trusted radius), a dynamic program over key subsets x room states on the
 * keys (see hol__tour_dp). Otherwise A* over room state x collected-key set
 * with an admissible heuristic (hol__tour_h) built from C, the table cost
 * (a lower bound beyond the table: the walk must cross the trusted
 * sphere), and C*(a, b), the least cost from any room state on a to b.
 * Nodes may be reopened, so the answer is exact once the search completes
 * within the budget. The program run with legs up to the tables' radii
 * (valid walks, not proved shortest) gives an upper bound that prunes the
 * A* and is the answer if the budget runs out; without it, keys nearest
 * first with hol_nav_find legs.
 */
#include "hol_nav.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hol_hyper.h"
#include "hol_nav_table.h"

#define HOL__FMAX 8192
#define HOL__LEG_RADIUS 10 /* tour legs exact between tiles within 7 */
#define HOL__NIL UINT32_MAX
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
    uint8_t *leg;       /* tour leg table (state to state), built lazily */
    int leg_radius, leg_trust, leg_ready;
    size_t bytes;
    void *block;
    void (*free_fn)(void *ptr, void *user);
    void *user;
};

static void *hol__malloc(size_t size, void *user)
{
    (void)user;
    return malloc(size);
}

static void hol__free(void *ptr, void *user)
{
    (void)user;
    free(ptr);
}

static size_t hol__align(size_t n) { return (n + 63) & ~(size_t)63; }

hol_err hol_nav_create(const hol_nav_desc *desc, hol_nav **out_nav)
{
    hol_nav_desc d;
    if (desc)
        d = *desc;
    else
        memset(&d, 0, sizeof d);
    if (d.radius == 0)
        d.radius = HOL_NAV_DEFAULT_RADIUS;
    if (d.max_nodes == 0)
        d.max_nodes = HOL_NAV_DEFAULT_NODES;
    if (d.anytime_margin == 0)
        d.anytime_margin = HOL_NAV_DEFAULT_MARGIN;
    if (d.radius < 3 || d.radius > HOL_NAV_MAX_RADIUS || d.max_nodes < 1024 ||
        d.max_nodes > (1u << 26) || d.anytime_margin < 0 ||
        d.anytime_margin > 255 || (!d.alloc_fn) != (!d.free_fn))
        return HOL_EARG;
    if (!d.alloc_fn) {
        d.alloc_fn = hol__malloc;
        d.free_fn = hol__free;
    }
    uint32_t cap = (uint32_t)d.max_nodes;
    uint32_t hsize = 16;
    while (hsize < 2 * cap)
        hsize <<= 1;
    size_t table = hol__align(hol_navtab_table_bytes(d.radius));
    size_t arena = hol__align((size_t)cap * sizeof(hol__node)) +
                   hol__align((size_t)hsize * sizeof(uint32_t)) +
                   hol__align(HOL__FMAX * sizeof(uint32_t)) +
                   hol__align((size_t)cap * 4 * sizeof(uint32_t));
    /* the table's build scratch spans the leg table and the arena (both
     * unused then); the leg table's build scratch is the arena */
    int leg_radius = d.radius < HOL__LEG_RADIUS ? d.radius : HOL__LEG_RADIUS;
    size_t legs = hol__align(hol_navtab_leg_bytes(leg_radius));
    size_t scratch = hol_navtab_scratch_bytes(d.radius);
    if (arena + legs < scratch)
        arena = scratch - legs;
    if (arena < hol_navtab_leg_scratch_bytes(leg_radius))
        arena = hol_navtab_leg_scratch_bytes(leg_radius);
    size_t total = hol__align(sizeof(hol_nav)) + table + legs + arena;
    char *block = (char *)d.alloc_fn(total, d.user);
    if (!block)
        return HOL_ENOMEM;
    hol_nav *nav = (hol_nav *)block;
    memset(nav, 0, sizeof *nav);
    char *p = block + hol__align(sizeof(hol_nav));
    char *arena_p = p + table + legs;
    hol_err err = hol_navtab_build(&nav->tab, d.radius, p, p + table);
    if (err) {
        d.free_fn(block, d.user);
        return err;
    }
    nav->nodes = (hol__node *)arena_p;
    nav->hash = (uint32_t *)(arena_p + hol__align((size_t)cap * sizeof(hol__node)));
    nav->bucket = (uint32_t *)((char *)nav->hash +
                               hol__align((size_t)hsize * sizeof(uint32_t)));
    nav->ent = (uint32_t *)((char *)nav->bucket +
                            hol__align(HOL__FMAX * sizeof(uint32_t)));
    nav->ent_cap = 2 * cap;
    nav->cap = cap;
    nav->hash_mask = hsize - 1;
    nav->trust = d.radius - 2;
    nav->leg = (uint8_t *)(p + table);
    nav->leg_radius = leg_radius;
    nav->leg_trust = leg_radius - 3;
    nav->margin = d.anytime_margin;
    nav->far_base16 = nav->tab.mean16_at[nav->trust];
    nav->far_slope16 = nav->tab.mean16_at[nav->trust] - nav->tab.mean16_at[nav->trust - 1];
    nav->bytes = total;
    nav->block = block;
    nav->free_fn = d.free_fn;
    nav->user = d.user;
    *out_nav = nav;
    return HOL_OK;
}

void hol_nav_destroy(hol_nav *nav)
{
    if (nav)
        nav->free_fn(nav->block, nav->user);
}

size_t hol_nav_memory(const hol_nav *nav) { return nav->bytes; }

int hol_nav_table_exact_radius(const hol_nav *nav) { return nav->trust; }

/* ---- arena: nodes, hash of states, bucket queue on f ---- */

static void hol__reset(hol_nav *nav)
{
    nav->count = 0;
    nav->ent_n = 0;
    memset(nav->hash, 0, ((size_t)nav->hash_mask + 1) * sizeof(uint32_t));
    for (int i = 0; i < HOL__FMAX; i++)
        nav->bucket[i] = HOL__NIL;
    nav->fmin = HOL__FMAX;
}

static uint64_t hol__node_hash(const hol__node *n)
{
    uint64_t h;
    if (n->flags & HOL__INSIDE)
        h = (uint64_t)n->u.idx * UINT64_C(0x9E3779B97F4A7C15);
    else
        h = hol_tile_hash(n->u.t);
    h ^= (uint64_t)(n->o | n->cell << 2 | (n->flags & HOL__MASK) << 6) *
         UINT64_C(0xD6E8FEB86659FD93);
    h ^= h >> 29;
    return h;
}

static int hol__node_same(const hol__node *a, const hol__node *b)
{
    if (a->o != b->o || a->cell != b->cell || a->flags != b->flags)
        return 0;
    if (a->flags & HOL__INSIDE)
        return a->u.idx == b->u.idx;
    return hol_tile_eq(a->u.t, b->u.t);
}

/* Find the node equal to *n, or add it. *out_new tells which. HOL__NIL when
 * the arena is full. */
static uint32_t hol__intern(hol_nav *nav, const hol__node *n, int *out_new)
{
    uint32_t h = (uint32_t)hol__node_hash(n) & nav->hash_mask;
    for (;;) {
        uint32_t e = nav->hash[h];
        if (e == 0)
            break;
        if (hol__node_same(&nav->nodes[e - 1], n)) {
            *out_new = 0;
            return e - 1;
        }
        h = (h + 1) & nav->hash_mask;
    }
    if (nav->count >= nav->cap)
        return HOL__NIL;
    uint32_t id = nav->count++;
    nav->nodes[id] = *n;
    nav->hash[h] = id + 1;
    *out_new = 1;
    return id;
}

/* Queue node id under its f; 0 when the entry pool is full. */
static int hol__push(hol_nav *nav, uint32_t id)
{
    if (nav->ent_n >= nav->ent_cap)
        return 0;
    uint32_t f = nav->nodes[id].f, e = nav->ent_n++;
    nav->ent[2 * e] = id;
    nav->ent[2 * e + 1] = nav->bucket[f];
    nav->bucket[f] = e;
    if (f < nav->fmin)
        nav->fmin = f;
    return 1;
}

/* Pop the newest node of the lowest f; skips entries made stale by a
 * later improvement (the node's f no longer matches its bucket). */
static uint32_t hol__pop(hol_nav *nav)
{
    while (nav->fmin < HOL__FMAX) {
        uint32_t e = nav->bucket[nav->fmin];
        if (e == HOL__NIL) {
            nav->fmin++;
            continue;
        }
        uint32_t id = nav->ent[2 * e];
        nav->bucket[nav->fmin] = nav->ent[2 * e + 1];
        if (nav->nodes[id].f == nav->fmin)
            return id;
    }
    return HOL__NIL;
}

static int hol__cell_step(int cell, int dir)
{
    static const int8_t dc[4] = {0, -1, 0, 1}, dr[4] = {-1, 0, 1, 0};
    int c = cell % 3 + dc[dir], r = cell / 3 + dr[dir];
    if (c < 0 || c > 2 || r < 0 || r > 2)
        return -1;
    return c + 3 * r;
}

static int hol__room_ok(const hol_room *r)
{
    return r && r->orient < 4 && r->col < 3 && r->row < 3 &&
           hol_tile_dist0(r->tile) <= HOL_TILE_MAX_DIST;
}

/* The user's relative state: tile seen from `target` (target heading = N)
 * and room north as a turn relative to that tile's heading. */
static hol_err hol__relate(const hol_room *user, hol_tile target, hol_tile *out_u,
                           int *out_o)
{
    int facing;
    hol_err err = hol_tile_relative(target, 0, user->tile, out_u, &facing);
    if (err)
        return err;
    *out_o = (facing + user->orient) & 3;
    return HOL_OK;
}

/* Output buffer of a walk. */
typedef struct hol__walk {
    uint8_t *dirs;
    size_t cap, n;
    int overflow;
} hol__walk;

static void hol__emit(hol__walk *w, int dir)
{
    if (w->n < w->cap)
        w->dirs[w->n++] = (uint8_t)dir;
    else
        w->overflow = 1;
}

/* Descend the table from (idx, o, cell) to cost 0; returns the steps taken
 * (the table cost) and updates the state. */
static int hol__descend(const hol_navtab *tab, uint32_t idx, int o, int cell,
                        hol__walk *w)
{
    int v = hol_navtab_cost(tab, idx, o, cell), steps = 0;
    while (v > 0 && v < 255) {
        int moved = 0;
        for (int d = 0; d < 4 && !moved; d++) {
            int c2 = hol__cell_step(cell, d);
            if (c2 < 0)
                continue;
            uint32_t e = tab->nb[4 * (size_t)idx + (size_t)((o + d) & 3)];
            if (e == HOL_NAVTAB_NONE)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            if (hol_navtab_cost(tab, e >> 2, o2, c2) == v - 1) {
                hol__emit(w, d);
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

/* Admissible lower bound for a node outside the trusted radius: it must
 * first cross the trusted sphere. */
static int hol__lb_far(const hol_nav *nav, const hol__node *n)
{
    int d = (n->flags & HOL__INSIDE) ? hol_navtab_len(&nav->tab, n->u.idx)
                                     : hol_tile_dist0(n->u.t);
    return d - nav->trust + nav->tab.min_at[nav->trust];
}

/* Heuristic of the anytime search: table cost, or the extrapolation. */
static int hol__far(const hol_nav *nav, int d)
{
    int h = (nav->far_base16 + nav->far_slope16 * (d - nav->trust)) / 16;
    return h < 0 ? 0 : h;
}

/* Waypoint chain from *room (absolute) to target; exact legs from the
 * table. Updates *room. */
static hol_err hol__chain(hol_nav *nav, hol_room *room, hol_tile target,
                          hol__walk *w)
{
    for (int guard = 0; guard < 4096; guard++) {
        uint8_t letters[HOL_TILE_REL_MAX];
        int n = hol_tile_relative_letters(room->tile, room->orient, target,
                                          letters, NULL);
        if (n < 0)
            return HOL_EARG;
        if (n == 0)
            return HOL_OK;
        hol_tile goal = target;
        if (n > nav->trust) {
            int k = n - nav->trust;
            if (k > nav->trust)
                k = nav->trust;
            hol_flag f = {room->tile, room->orient};
            for (int i = 0; i < k; i++) {
                hol_err err = hol_flag_step(f, letters[i], &f);
                if (err)
                    return err;
            }
            goal = f.tile;
        }
        hol_tile u;
        int o;
        hol_err err = hol__relate(room, goal, &u, &o);
        if (err)
            return err;
        uint32_t idx = hol_navtab_rank(&nav->tab, u);
        if (idx == HOL_NAVTAB_NONE)
            return HOL_EARG;
        size_t before = w->n;
        hol__descend(&nav->tab, idx, o, room->col + 3 * room->row, w);
        if (w->overflow)
            return HOL_ENOMEM;
        for (size_t i = before; i < w->n; i++) {
            err = hol_room_step(room, w->dirs[i]);
            if (err)
                return err;
        }
    }
    return HOL_ENOMEM;
}

/* Path of room steps from the search root to node id, appended to w. */
static void hol__emit_path(hol_nav *nav, uint32_t id, hol__walk *w)
{
    size_t start = w->n;
    for (uint32_t x = id; nav->nodes[x].parent != HOL__NIL; x = nav->nodes[x].parent)
        hol__emit(w, nav->nodes[x].dir);
    if (w->overflow)
        return;
    for (size_t i = start, j = w->n; i + 1 < j; i++, j--) {
        uint8_t t = w->dirs[i];
        w->dirs[i] = w->dirs[j - 1];
        w->dirs[j - 1] = t;
    }
}

/* Successor of a nav node in room direction d (relative tile stepping). */
static int hol__nav_succ(const hol_nav *nav, const hol__node *n, int d,
                         hol__node *out)
{
    int c2 = hol__cell_step(n->cell, d);
    if (c2 < 0)
        return 0;
    int turn = (n->o + d) & 3, arr;
    hol_tile t;
    if (n->flags & HOL__INSIDE) {
        uint32_t e = nav->tab.nb[4 * (size_t)n->u.idx + (size_t)turn];
        if (e != HOL_NAVTAB_NONE) {
            memset(out, 0, sizeof *out);
            out->u.idx = e >> 2;
            out->flags = HOL__INSIDE;
            out->o = (uint8_t)(((int)(e & 3u) - d) & 3);
            out->cell = (uint8_t)c2;
            return 1;
        }
        t = hol_navtab_unrank(&nav->tab, n->u.idx);
    } else {
        t = n->u.t;
    }
    hol_tile t2;
    if (hol_tile_step(t, turn, &t2, &arr))
        return 0;
    memset(out, 0, sizeof *out);
    uint32_t idx = hol_navtab_rank(&nav->tab, t2);
    if (idx != HOL_NAVTAB_NONE) {
        out->u.idx = idx;
        out->flags = HOL__INSIDE;
    } else {
        out->u.t = t2;
    }
    out->o = (uint8_t)((arr - d) & 3);
    out->cell = (uint8_t)c2;
    return 1;
}

/* H of a nav node; *out_cost receives the table cost (255 if none). */
static int hol__nav_h(const hol_nav *nav, const hol__node *n, int *out_cost)
{
    *out_cost = 255;
    if (n->flags & HOL__INSIDE) {
        int v = hol_navtab_cost(&nav->tab, n->u.idx, n->o, n->cell);
        *out_cost = v;
        if (v < 255)
            return v;
        return hol__far(nav, hol_navtab_len(&nav->tab, n->u.idx));
    }
    return hol__far(nav, hol_tile_dist0(n->u.t));
}

static hol_err hol__anytime(hol_nav *nav, const hol_room *start, hol_tile u, int o,
                            size_t budget, hol__walk *w, hol_nav_result *res)
{
    hol__reset(nav);
    hol__node root;
    memset(&root, 0, sizeof root);
    uint32_t idx = hol_navtab_rank(&nav->tab, u);
    if (idx != HOL_NAVTAB_NONE) {
        root.u.idx = idx;
        root.flags = HOL__INSIDE;
    } else {
        root.u.t = u;
    }
    root.o = (uint8_t)o;
    root.cell = (uint8_t)(start->col + 3 * start->row);
    root.parent = HOL__NIL;
    int v, isnew;
    int h = hol__nav_h(nav, &root, &v);
    root.f = (uint16_t)(h < HOL__FMAX ? h : HOL__FMAX - 1);
    uint32_t rid = hol__intern(nav, &root, &isnew);
    hol__push(nav, rid);
    uint32_t best = HOL__NIL;
    int best_cost = 1 << 20;
    if (v < 255) {
        best = rid;
        best_cost = v;
    }
    size_t expanded = 0;
    uint32_t id;
    int full = 0;
    while (!full && expanded < budget && (id = hol__pop(nav)) != HOL__NIL) {
        hol__node cur = nav->nodes[id];
        if ((int)cur.f >= best_cost + nav->margin)
            break;
        /* A node within the trusted radius is a finished candidate: every
         * walk through it costs at least g + its exact table cost. */
        if ((cur.flags & HOL__INSIDE) &&
            hol_navtab_len(&nav->tab, cur.u.idx) <= nav->trust)
            continue;
        if (cur.g + hol__lb_far(nav, &cur) >= best_cost)
            continue;
        expanded++;
        for (int d = 0; d < 4; d++) {
            hol__node nx;
            if (!hol__nav_succ(nav, &cur, d, &nx))
                continue;
            int g = cur.g + 1;
            if (g >= HOL__FMAX / 2)
                continue;
            uint32_t nid = hol__intern(nav, &nx, &isnew);
            if (nid == HOL__NIL) {
                full = 1; /* arena full: stop */
                break;
            }
            hol__node *q = &nav->nodes[nid];
            if (!isnew && q->g <= g)
                continue;
            q->g = (uint16_t)g;
            q->parent = id;
            q->dir = (uint8_t)d;
            int c;
            int hh = hol__nav_h(nav, q, &c);
            int f = g + hh;
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (c < 255 && g + c < best_cost) {
                best_cost = g + c;
                best = nid;
            }
            if (!hol__push(nav, nid)) {
                full = 1;
                break;
            }
        }
    }
    res->nodes = expanded;
    if (best != HOL__NIL) {
        hol__emit_path(nav, best, w);
        const hol__node *b = &nav->nodes[best];
        hol__descend(&nav->tab, b->u.idx, b->o, b->cell, w);
        return w->overflow ? HOL_ENOMEM : HOL_OK;
    }
    return HOL_EBUDGET; /* nothing inside the table: caller chains */
}

hol_err hol_nav_find(hol_nav *nav, const hol_room *start, hol_tile target,
                     size_t budget, uint8_t *out_walk, size_t cap,
                     hol_nav_result *out_result)
{
    if (!nav || !hol__room_ok(start) || !out_walk || !out_result ||
        hol_tile_dist0(target) > HOL_TILE_MAX_DIST)
        return HOL_EARG;
    hol__walk w = {out_walk, cap, 0, 0};
    hol_nav_result res = {0, 0, 0};
    hol_tile u;
    int o;
    hol_err err = hol__relate(start, target, &u, &o);
    if (err == HOL_ERANGE) {
        /* farther than a tile word reaches: waypoints only */
        hol_room room = *start;
        err = hol__chain(nav, &room, target, &w);
    } else if (!err && hol_tile_dist0(u) <= nav->trust) {
        uint32_t idx = hol_navtab_rank(&nav->tab, u);
        hol__descend(&nav->tab, idx, o, start->col + 3 * start->row, &w);
        res.exact = 1;
        err = w.overflow ? HOL_ENOMEM : HOL_OK;
    } else if (!err) {
        if (budget == 0 || budget > nav->cap)
            budget = nav->cap;
        err = hol__anytime(nav, start, u, o, budget, &w, &res);
        if (err == HOL_EBUDGET) {
            /* no table node: chain waypoints on absolute tiles */
            hol_room room = *start;
            w.n = 0;
            w.overflow = 0;
            err = hol__chain(nav, &room, target, &w);
        }
    }
    if (err)
        return err;
    res.len = (int)w.n;
    *out_result = res;
    return HOL_OK;
}

/* ---- tours ---- */

/* Lower bound (exact within the trusted radius) on the steps from room
 * state (tile, o, cell) to stand on target. */
static int hol__lb(const hol_nav *nav, hol_tile tile, int o, int cell, hol_tile target)
{
    hol_tile u;
    int facing;
    if (hol_tile_relative(target, 0, tile, &u, &facing))
        return nav->tab.min_at[nav->trust] + HOL_TILE_MAX_DIST - nav->trust;
    int d = hol_tile_dist0(u);
    if (d <= nav->trust)
        return hol_navtab_cost(&nav->tab, hol_navtab_rank(&nav->tab, u),
                               (facing + o) & 3, cell);
    return nav->tab.min_at[nav->trust] + d - nav->trust;
}

/* Least cost from any room state on tile a to stand on b. */
static int hol__lb_any(const hol_nav *nav, hol_tile a, hol_tile b)
{
    hol_tile u;
    if (hol_tile_relative(b, 0, a, &u, NULL))
        return nav->tab.min_at[nav->trust];
    int d = hol_tile_dist0(u);
    if (d <= nav->trust) {
        uint32_t idx = hol_navtab_rank(&nav->tab, u);
        int m = 255;
        for (int c = 0; c < 9; c++)
            if (nav->tab.cost[9 * (size_t)idx + (size_t)c] < m)
                m = nav->tab.cost[9 * (size_t)idx + (size_t)c];
        return m;
    }
    return nav->tab.min_at[nav->trust] + d - nav->trust;
}

typedef struct hol__tour {
    const hol_tile *keys;
    int nkeys;
    hol_tile chest;
    int key_chest[HOL_NAV_TOUR_MAX_KEYS];
    /* mst[mask]: minimum spanning tree over the chest and the keys NOT in
     * mask, edges the least cost between two tiles from any room state */
    int mst[1 << HOL_NAV_TOUR_MAX_KEYS];
    unsigned full;
} hol__tour;

static unsigned hol__keys_on(const hol__tour *t, hol_tile tile)
{
    unsigned m = 0;
    for (int i = 0; i < t->nkeys; i++)
        if (hol_tile_eq(t->keys[i], tile))
            m |= 1u << i;
    return m;
}

/* Admissible: the walk still has to reach every key left and then the
 * chest, so it costs at least (a) the cost to the chest, (b) for each key
 * left, the cost to it plus the least cost from it to the chest, and (c)
 * the cost to the nearest key left plus a spanning tree over the keys left
 * and the chest (the rest of the walk joins them all). */
static int hol__tour_h(const hol_nav *nav, const hol__tour *t, const hol__node *n)
{
    int h = hol__lb(nav, n->u.t, n->o, n->cell, t->chest), nearest = INT32_MAX;
    unsigned mask = n->flags & HOL__MASK;
    for (int i = 0; i < t->nkeys; i++) {
        if (mask & (1u << i))
            continue;
        int c = hol__lb(nav, n->u.t, n->o, n->cell, t->keys[i]);
        if (c < nearest)
            nearest = c;
        if (c + t->key_chest[i] > h)
            h = c + t->key_chest[i];
    }
    if (nearest != INT32_MAX && nearest + t->mst[mask] > h)
        h = nearest + t->mst[mask];
    return h;
}

/* Prim over the chest and the keys not in mask. */
static int hol__tour_mst(const int w[HOL_NAV_TOUR_MAX_KEYS + 1][HOL_NAV_TOUR_MAX_KEYS + 1],
                         int nkeys, unsigned mask)
{
    int in[HOL_NAV_TOUR_MAX_KEYS + 1] = {0}, best[HOL_NAV_TOUR_MAX_KEYS + 1];
    int total = 0, chest = nkeys;
    for (int i = 0; i <= nkeys; i++)
        best[i] = w[chest][i];
    in[chest] = 1;
    for (;;) {
        int pick = -1;
        for (int i = 0; i < nkeys; i++)
            if (!in[i] && !(mask & (1u << i)) && (pick < 0 || best[i] < best[pick]))
                pick = i;
        if (pick < 0)
            return total;
        in[pick] = 1;
        total += best[pick];
        for (int i = 0; i < nkeys; i++)
            if (w[pick][i] < best[i])
                best[i] = w[pick][i];
    }
}

/* Greedy fallback: nearest key by tile distance, exact-or-anytime legs. */
static hol_err hol__tour_greedy(hol_nav *nav, const hol_room *start,
                                const hol__tour *t, size_t budget, hol__walk *w)
{
    hol_room room = *start;
    unsigned mask = hol__keys_on(t, room.tile);
    for (;;) {
        hol_tile goal = t->chest;
        if (mask != t->full) {
            int bestd = INT32_MAX;
            for (int i = 0; i < t->nkeys; i++) {
                if (mask & (1u << i))
                    continue;
                int dd = hol_tile_dist(room.tile, t->keys[i]);
                if (dd < bestd) {
                    bestd = dd;
                    goal = t->keys[i];
                }
            }
        }
        hol_nav_result r;
        if (w->n >= w->cap)
            return HOL_ENOMEM;
        hol_err err = hol_nav_find(nav, &room, goal, budget, w->dirs + w->n,
                                   w->cap - w->n, &r);
        if (err)
            return err;
        for (int i = 0; i < r.len; i++) {
            err = hol_room_step(&room, w->dirs[w->n + (size_t)i]);
            if (err)
                return err;
            mask |= hol__keys_on(t, room.tile);
        }
        w->n += (size_t)r.len;
        if (mask == t->full && hol_tile_eq(room.tile, t->chest))
            return HOL_OK;
    }
}


/* ---- exact tours by dynamic programming over room states at the keys ----
 *
 * F[mask][j][s]: fewest steps from the start to stand on key j in room
 * state s (orientation, cell: 36 states) having first visited the keys in
 * mask, j last. Legs between room states come from the leg table, exact
 * when the tiles lie within its trusted radius; the last leg to the chest
 * (any state) from the main table. The optimal walk visits the keys first
 * in some order; each leg between consecutive first visits costs at least
 * the state-to-state distance, so the minimum over the DP is the optimum,
 * and it is achieved by the concatenated legs. */

typedef struct hol__rel {
    uint32_t idx; /* tile index of the source seen from the destination */
    int facing;   /* source heading in that frame */
} hol__rel;

static int hol__rel_of(const hol_nav *nav, hol_tile from, hol_tile to, int trust,
                       hol__rel *out)
{
    hol_tile u;
    if (hol_tile_relative(to, 0, from, &u, &out->facing) || hol_tile_dist0(u) > trust)
        return 0;
    out->idx = hol_navtab_rank(&nav->tab, u);
    return 1;
}

/* Descend the leg table from (idx, o, cell) to the goal state (ob, cb). */
static void hol__leg_descend(const hol_nav *nav, uint32_t idx, int o, int cell, int ob,
                             int cb, hol__walk *w)
{
    uint32_t n = nav->tab.off[nav->leg_radius + 1];
    int v = hol_navtab_leg(nav->leg, idx, o, cell, ob, cb);
    while (v > 0 && v < 255) {
        int moved = 0;
        for (int d = 0; d < 4 && !moved; d++) {
            int c2 = hol__cell_step(cell, d);
            if (c2 < 0)
                continue;
            uint32_t e = nav->tab.nb[4 * (size_t)idx + (size_t)((o + d) & 3)];
            if (e == HOL_NAVTAB_NONE || (e >> 2) >= n)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            if (hol_navtab_leg(nav->leg, e >> 2, o2, c2, ob, cb) == v - 1) {
                hol__emit(w, d);
                idx = e >> 2;
                o = o2;
                cell = c2;
                v--;
                moved = 1;
            }
        }
        if (!moved)
            break;
    }
}

#define HOL__NK HOL_NAV_TOUR_MAX_KEYS
typedef struct hol__dp {
    uint16_t cost[1 << HOL__NK][HOL__NK][36];
    int8_t pj[1 << HOL__NK][HOL__NK][36]; /* previous key, -1: the start */
    uint8_t ps[1 << HOL__NK][HOL__NK][36]; /* previous state */
} hol__dp;

/* HOL_ERANGE when some tiles lie too far apart for the leg table. */
/* lt: the farthest key-to-key (and start-to-key) distance allowed, ct: the
 * farthest key-to-chest; within the trusted radii the result is exact,
 * beyond (up to the tables' radii) the legs are walks that stay inside the
 * tables, so the tour is valid but only an upper bound. */
static hol_err hol__tour_dp(hol_nav *nav, const hol_room *start, const hol__tour *t,
                            int lt, int ct, hol__walk *w, hol_nav_result *res)
{
    int nk = t->nkeys;
    hol__rel from_start[HOL__NK], pair[HOL__NK][HOL__NK], to_chest[HOL__NK];
    for (int k = 0; k < nk; k++) {
        if (!hol__rel_of(nav, start->tile, t->keys[k], lt, &from_start[k]) ||
            !hol__rel_of(nav, t->keys[k], t->chest, ct, &to_chest[k]))
            return HOL_ERANGE;
        for (int j = 0; j < nk; j++)
            if (j != k && !hol__rel_of(nav, t->keys[j], t->keys[k], lt, &pair[j][k]))
                return HOL_ERANGE;
    }
    if (!nav->leg_ready) {
        hol_navtab_build_legs(&nav->tab, nav->leg_radius, nav->leg, nav->nodes);
        nav->leg_ready = 1;
    }
    /* the table lives in the arena (nodes are not used by this path) */
    hol__dp *dp = (hol__dp *)nav->nodes;
    memset(dp->cost, 0xff, sizeof dp->cost);
    int sc = start->col + 3 * start->row;
    for (int k = 0; k < nk; k++)
        for (int s = 0; s < 36; s++) {
            const hol__rel *r = &from_start[k];
            int v = hol_navtab_leg(nav->leg, r->idx, (r->facing + start->orient) & 3, sc,
                                   s / 9, s % 9);
            if (v < 255) {
                dp->cost[1u << k][k][s] = (uint16_t)v;
                dp->pj[1u << k][k][s] = -1;
            }
        }
    for (unsigned m = 1; m < (1u << nk); m++)
        for (int j = 0; j < nk; j++) {
            if (!(m & (1u << j)))
                continue;
            for (int s = 0; s < 36; s++) {
                int base = dp->cost[m][j][s];
                if (base == 0xffff)
                    continue;
                for (int k = 0; k < nk; k++) {
                    if (m & (1u << k))
                        continue;
                    unsigned m2 = m | (1u << k);
                    const hol__rel *r = &pair[j][k];
                    int o = (r->facing + s / 9) & 3;
                    for (int s2 = 0; s2 < 36; s2++) {
                        int v = hol_navtab_leg(nav->leg, r->idx, o, s % 9, s2 / 9, s2 % 9);
                        if (v < 255 && base + v < dp->cost[m2][k][s2]) {
                            dp->cost[m2][k][s2] = (uint16_t)(base + v);
                            dp->pj[m2][k][s2] = (int8_t)j;
                            dp->ps[m2][k][s2] = (uint8_t)s;
                        }
                    }
                }
            }
        }
    unsigned full = t->full;
    int best = INT32_MAX, bj = -1, bs = -1;
    for (int j = 0; j < nk; j++)
        for (int s = 0; s < 36; s++) {
            if (dp->cost[full][j][s] == 0xffff)
                continue;
            const hol__rel *r = &to_chest[j];
            int v = hol_navtab_cost(&nav->tab, r->idx, (r->facing + s / 9) & 3, s % 9);
            if (v < 255 && dp->cost[full][j][s] + v < best) {
                best = dp->cost[full][j][s] + v;
                bj = j;
                bs = s;
            }
        }
    if (bj < 0)
        return HOL_ERANGE;
    /* the order of first visits, back to front */
    int oj[HOL__NK], os[HOL__NK], n = 0;
    unsigned m = full;
    for (int j = bj, s = bs; j >= 0;) {
        oj[n] = j;
        os[n] = s;
        n++;
        int pj = dp->pj[m][j][s], ps = dp->ps[m][j][s];
        m &= ~(1u << j);
        j = pj;
        s = ps;
    }
    /* legs, front to back */
    for (int i = n - 1; i >= 0; i--) {
        int k = oj[i], s2 = os[i];
        if (i == n - 1) {
            const hol__rel *r = &from_start[k];
            hol__leg_descend(nav, r->idx, (r->facing + start->orient) & 3, sc, s2 / 9,
                             s2 % 9, w);
        } else {
            int j = oj[i + 1], s = os[i + 1];
            const hol__rel *r = &pair[j][k];
            hol__leg_descend(nav, r->idx, (r->facing + s / 9) & 3, s % 9, s2 / 9, s2 % 9, w);
        }
    }
    const hol__rel *r = &to_chest[bj];
    hol__descend(&nav->tab, r->idx, (r->facing + bs / 9) & 3, bs % 9, w);
    if (w->overflow)
        return HOL_ENOMEM;
    res->exact = 1;
    res->nodes = 0;
    (void)best;
    return HOL_OK;
}

hol_err hol_nav_tour(hol_nav *nav, const hol_room *start, const hol_tile *keys,
                     int nkeys, hol_tile chest, size_t budget,
                     uint8_t *out_walk, size_t cap, hol_nav_result *out_result)
{
    if (!nav || !hol__room_ok(start) || !out_walk || !out_result ||
        nkeys < 0 || nkeys > HOL_NAV_TOUR_MAX_KEYS || (nkeys && !keys) ||
        hol_tile_dist0(chest) > HOL_TILE_MAX_DIST)
        return HOL_EARG;
    for (int i = 0; i < nkeys; i++)
        if (hol_tile_dist0(keys[i]) > HOL_TILE_MAX_DIST)
            return HOL_EARG;
    hol__tour t;
    t.keys = keys;
    t.nkeys = nkeys;
    t.chest = chest;
    t.full = (1u << nkeys) - 1;
    int wt[HOL_NAV_TOUR_MAX_KEYS + 1][HOL_NAV_TOUR_MAX_KEYS + 1];
    for (int i = 0; i <= nkeys; i++)
        for (int j = 0; j <= nkeys; j++)
            wt[i][j] = i == j ? 0
                             : hol__lb_any(nav, i < nkeys ? keys[i] : chest,
                                           j < nkeys ? keys[j] : chest);
    for (int i = 0; i < nkeys; i++)
        t.key_chest[i] = wt[i][nkeys];
    for (unsigned m = 0; m < (1u << nkeys); m++)
        t.mst[m] = hol__tour_mst((const int(*)[HOL_NAV_TOUR_MAX_KEYS + 1])wt, nkeys, m);
    if (budget == 0 || budget > nav->cap)
        budget = nav->cap;
    hol__walk w = {out_walk, cap, 0, 0};
    hol_nav_result res = {0, 0, 0};
    if (nkeys == 0) {
        return hol_nav_find(nav, start, chest, budget, out_walk, cap, out_result);
    }
    hol_err dperr = hol__tour_dp(nav, start, &t, nav->leg_trust, nav->trust, &w, &res);
    if (dperr != HOL_ERANGE) {
        if (dperr)
            return dperr;
        res.len = (int)w.n;
        *out_result = res;
        return HOL_OK;
    }
    /* An upper bound: the same program with legs up to the tables' radii
     * (walks inside the tables, not proved shortest). The A* below prunes
     * with it; if the A* runs dry below it, this walk is the optimum. */
    w.n = 0;
    w.overflow = 0;
    int ub = INT32_MAX;
    dperr = hol__tour_dp(nav, start, &t, nav->leg_radius, nav->tab.radius, &w, &res);
    if (dperr == HOL_OK)
        ub = (int)w.n;
    else if (dperr != HOL_ERANGE)
        return dperr;
    else
        w.n = 0;
    w.overflow = 0;
    res.exact = 0;

    hol__reset(nav);
    hol__node root;
    memset(&root, 0, sizeof root);
    root.u.t = start->tile;
    root.o = start->orient;
    root.cell = (uint8_t)(start->col + 3 * start->row);
    root.flags = (uint8_t)hol__keys_on(&t, start->tile);
    root.parent = HOL__NIL;
    int h = hol__tour_h(nav, &t, &root), isnew;
    root.f = (uint16_t)(h < HOL__FMAX ? h : HOL__FMAX - 1);
    uint32_t id = hol__intern(nav, &root, &isnew);
    hol__push(nav, id);
    uint32_t goal = HOL__NIL;
    size_t expanded = 0;
    int full_arena = 0, dry = 0;
    for (;;) {
        if (expanded >= budget || full_arena)
            break;
        if ((id = hol__pop(nav)) == HOL__NIL) {
            dry = 1;
            break;
        }
        hol__node cur = nav->nodes[id];
        if ((int)cur.f >= ub) {
            dry = 1; /* nothing left below the bound */
            break;
        }
        if ((cur.flags & HOL__MASK) == t.full && hol_tile_eq(cur.u.t, chest)) {
            goal = id;
            break;
        }
        expanded++;
        for (int d = 0; d < 4; d++) {
            int c2 = hol__cell_step(cur.cell, d), arr;
            if (c2 < 0)
                continue;
            hol__node nx;
            memset(&nx, 0, sizeof nx);
            if (hol_tile_step(cur.u.t, cur.o + d, &nx.u.t, &arr))
                continue;
            nx.o = (uint8_t)((arr - d) & 3);
            nx.cell = (uint8_t)c2;
            nx.flags = (uint8_t)((cur.flags & HOL__MASK) | hol__keys_on(&t, nx.u.t));
            int g = cur.g + 1;
            if (g >= HOL__FMAX / 2)
                continue;
            uint32_t nid = hol__intern(nav, &nx, &isnew);
            if (nid == HOL__NIL) {
                full_arena = 1;
                break;
            }
            hol__node *q = &nav->nodes[nid];
            if (!isnew && q->g <= g)
                continue;
            q->g = (uint16_t)g;
            q->parent = id;
            q->dir = (uint8_t)d;
            int f = g + hol__tour_h(nav, &t, q);
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (f >= ub)
                continue; /* cannot beat the upper bound */
            if (!hol__push(nav, nid)) {
                full_arena = 1;
                break;
            }
        }
    }
    res.nodes = expanded;
    hol_err err = HOL_OK;
    if (goal != HOL__NIL) {
        w.n = 0;
        hol__emit_path(nav, goal, &w);
        res.exact = 1;
        err = w.overflow ? HOL_ENOMEM : HOL_OK;
    } else if (ub != INT32_MAX) {
        res.exact = dry; /* the bound's walk, proved optimal if A* ran dry */
    } else {
        err = hol__tour_greedy(nav, start, &t, budget, &w);
    }
    if (err)
        return err;
    res.len = (int)w.n;
    *out_result = res;
    return HOL_OK;
}

/* ---- hot-cold field and direction ---- */

#define HOL__FIELD_MAX_RADIUS 8

size_t hol_nav_field_count(int radius)
{
    if (radius < 0 || radius > HOL__FIELD_MAX_RADIUS)
        return 0;
    return hol_navtab_count(radius);
}

hol_err hol_nav_field(const hol_room *user, int radius, const hol_tile *objectives,
                      size_t n, hol_nav_cell *out_cells, size_t cap,
                      size_t *out_n)
{
    if (!hol__room_ok(user) || radius < 0 || radius > HOL__FIELD_MAX_RADIUS ||
        (n && !objectives) || !out_cells || !out_n)
        return HOL_EARG;
    hol_navtab ix;
    hol_navtab_init_index(&ix, radius);
    if (cap < ix.count)
        return HOL_ENOMEM;
    for (uint32_t i = 0; i < ix.count; i++) {
        hol_tile rel = hol_navtab_unrank(&ix, i);
        int len = hol_tile_dist0(rel);
        hol_flag f = {user->tile, user->orient};
        for (int k = 0; k < len; k++) {
            hol_err err = hol_flag_step(f, hol_tile_letter(rel, k), &f);
            if (err)
                return err;
        }
        hol_nav_cell *c = &out_cells[i];
        c->tile = f.tile;
        c->rel = rel;
        c->user_dist = (int16_t)len;
        c->hot = -1;
        for (size_t j = 0; j < n; j++) {
            int dd = hol_tile_dist(f.tile, objectives[j]);
            if (dd >= 0 && (c->hot < 0 || dd < c->hot))
                c->hot = (int16_t)(dd > INT16_MAX ? INT16_MAX : dd);
        }
    }
    *out_n = ix.count;
    return HOL_OK;
}

hol_err hol_nav_direction(const hol_room *user, hol_tile objective,
                          double *out_angle, double *out_dist)
{
    if (!hol__room_ok(user) || hol_tile_dist0(objective) > HOL_TILE_MAX_DIST)
        return HOL_EARG;
    double angle, dist;
    hol_err err = hol_hyper_pos(user->tile, user->orient, objective, NULL, &angle,
                                &dist);
    if (err)
        return err;
    if (hol_tile_eq(user->tile, objective)) {
        angle = 0.0;
        dist = 0.0;
    }
    if (out_angle)
        *out_angle = angle;
    if (out_dist)
        *out_dist = dist;
    return HOL_OK;
}
