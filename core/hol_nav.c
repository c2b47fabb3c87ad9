/* hol_nav.c - the navigator (one block: tables and arena), the search
 * arena, and the fewest room steps to a tile (hol_nav_find). Tours are in
 * hol_nav_tour.c, the minimap's field and arrows in hol_nav_field.c.
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
 */
#include "hol_nav.h"

#include <stdlib.h>
#include <string.h>

#include "hol_nav_impl.h"

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
    if (arena < hol__nav_tour_scratch())
        arena = hol__align(hol__nav_tour_scratch());
    size_t far_e = hol__align(HOL__SPHERE_MAX * 36);
    size_t sph = hol__align(HOL__SPH_CACHE * sizeof(hol__sph));
    size_t total = hol__align(sizeof(hol_nav)) + table + legs + far_e + sph + arena;
    char *block = (char *)d.alloc_fn(total, d.user);
    if (!block)
        return HOL_ENOMEM;
    hol_nav *nav = (hol_nav *)block;
    memset(nav, 0, sizeof *nav);
    char *p = block + hol__align(sizeof(hol_nav));
    char *arena_p = p + table + legs + far_e + sph;
    hol_err err = hol_navtab_build(&nav->tab, d.radius, p, p + table);
    if (err) {
        d.free_fn(block, d.user);
        return err;
    }
    /* touch the arena once here (the table build used only part of it as
     * scratch): the first far query paid about 8 ms of page faults */
    memset(arena_p, 0, arena);
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
    nav->far_e = (uint8_t *)(p + table + legs);
    nav->sph = (hol__sph *)(void *)(p + table + legs + far_e);
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

static uint64_t hol__node_hash(const hol__node *n);

/* Clearing the whole hash (2 MB at the defaults) cost more than a small
 * query; after a search only the slots of its nodes are cleared (found by
 * rehashing each node and probing for its id). */
void hol__nav_reset(hol_nav *nav)
{
    if (nav->hash_dirty) {
        memset(nav->hash, 0, ((size_t)nav->hash_mask + 1) * sizeof(uint32_t));
        nav->hash_dirty = 0;
    } else {
        for (uint32_t i = 0; i < nav->count; i++) {
            uint32_t h = (uint32_t)hol__node_hash(&nav->nodes[i]) & nav->hash_mask;
            while (nav->hash[h] != i + 1)
                h = (h + 1) & nav->hash_mask;
            nav->hash[h] = 0;
        }
    }
    nav->count = 0;
    nav->ent_n = 0;
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
uint32_t hol__nav_intern(hol_nav *nav, const hol__node *n, int *out_new)
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

uint32_t hol__nav_relax(hol_nav *nav, const hol__node *nx, uint32_t parent, int d,
                        int g, int *out_full)
{
    int isnew;
    if (g >= HOL__FMAX / 2)
        return HOL__NIL;
    uint32_t nid = hol__nav_intern(nav, nx, &isnew);
    if (nid == HOL__NIL) {
        *out_full = 1;
        return HOL__NIL;
    }
    hol__node *q = &nav->nodes[nid];
    if (!isnew && q->g <= g)
        return HOL__NIL;
    q->g = (uint16_t)g;
    q->parent = parent;
    q->dir = (uint8_t)d;
    return nid;
}

/* Queue node id under its f; 0 when the entry pool is full. */
int hol__nav_push(hol_nav *nav, uint32_t id)
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
uint32_t hol__nav_pop(hol_nav *nav)
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

int hol__nav_cell_step(int cell, int dir)
{
    static const int8_t dc[4] = {0, -1, 0, 1}, dr[4] = {-1, 0, 1, 0};
    int c = cell % 3 + dc[dir], r = cell / 3 + dr[dir];
    if (c < 0 || c > 2 || r < 0 || r > 2)
        return -1;
    return c + 3 * r;
}

int hol__nav_room_ok(const hol_room *r)
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


void hol__nav_emit(hol__walk *w, int dir)
{
    if (w->n < w->cap)
        w->dirs[w->n++] = (uint8_t)dir;
    else
        w->overflow = 1;
}

static int hol__tab_cost(const void *tab, uint32_t idx, int o, int cell)
{
    return hol_navtab_cost((const hol_navtab *)tab, idx, o, cell);
}

/* Descend the table from (idx, o, cell) to cost 0; returns the steps taken
 * (the table cost). */
int hol__nav_descend(const hol_navtab *tab, uint32_t idx, int o, int cell,
                        hol__walk *w)
{
    return hol__descend(tab, UINT32_MAX, hol__tab_cost, tab, idx, o, cell, w);
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
            hol_heading_tile f = {room->tile, room->orient};
            for (int i = 0; i < k; i++) {
                hol_err err = hol_heading_tile_step(f, letters[i], &f);
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
        hol__nav_descend(&nav->tab, idx, o, room->col + 3 * room->row, w);
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
void hol__nav_emit_path(hol_nav *nav, uint32_t id, hol__walk *w)
{
    size_t start = w->n;
    for (uint32_t x = id; nav->nodes[x].parent != HOL__NIL; x = nav->nodes[x].parent)
        hol__nav_emit(w, nav->nodes[x].dir);
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
    int c2 = hol__nav_cell_step(n->cell, d);
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
    hol__nav_reset(nav);
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
    uint32_t rid = hol__nav_intern(nav, &root, &isnew);
    hol__nav_push(nav, rid);
    uint32_t best = HOL__NIL;
    int best_cost = 1 << 20;
    if (v < 255) {
        best = rid;
        best_cost = v;
    }
    size_t expanded = 0;
    uint32_t id;
    int full = 0;
    while (!full && expanded < budget && (id = hol__nav_pop(nav)) != HOL__NIL) {
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
            uint32_t nid = hol__nav_relax(nav, &nx, id, d, g, &full);
            if (full)
                break; /* arena full: stop */
            if (nid == HOL__NIL)
                continue;
            hol__node *q = &nav->nodes[nid];
            int c;
            int hh = hol__nav_h(nav, q, &c);
            int f = g + hh;
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (c < 255 && g + c < best_cost) {
                best_cost = g + c;
                best = nid;
            }
            if (!hol__nav_push(nav, nid)) {
                full = 1;
                break;
            }
        }
    }
    res->nodes = expanded;
    if (best != HOL__NIL) {
        hol__nav_emit_path(nav, best, w);
        const hol__node *b = &nav->nodes[best];
        hol__nav_descend(&nav->tab, b->u.idx, b->o, b->cell, w);
        return w->overflow ? HOL_ENOMEM : HOL_OK;
    }
    return HOL_EBUDGET; /* nothing inside the table: caller chains */
}

hol_err hol_nav_find(hol_nav *nav, const hol_room *start, hol_tile target,
                     size_t budget, uint8_t *out_walk, size_t cap,
                     hol_nav_result *out_result)
{
    if (!nav || !hol__nav_room_ok(start) || !out_walk || !out_result ||
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
        hol__nav_descend(&nav->tab, idx, o, start->col + 3 * start->row, &w);
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
