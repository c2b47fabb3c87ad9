/* hol_nav.c - the navigator (one block: tables and arena; the radii of
 * each tiling and room size) and the fewest room steps to a tile
 * (hol_nav_find). The arena is in hol_nav_arena.c, tours in
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

/* The one block of a navigator: sizes of its parts. */
typedef struct hol__plan {
    hol_navtab tab; /* configuration and numbering */
    int leg_radius;
    uint32_t cap, hsize;
    size_t table, legs, far_e, sph, arena, total;
} hol__plan;

/* Plan a navigator of table radius r and leg radius lr (the desc checked). */
static hol_err hol__plan_sizes(const hol_nav_desc *d, int r, int lr, hol__plan *p)
{
    if (hol_navtab_init(&p->tab, d->tiling_q, d->room_cols, d->room_rows, r))
        return HOL_EARG;
    p->leg_radius = lr;
    p->cap = (uint32_t)d->max_nodes;
    p->hsize = 16;
    while (p->hsize < 2 * p->cap)
        p->hsize <<= 1;
    p->table = hol__align(hol_navtab_table_bytes(&p->tab));
    p->arena = hol__align((size_t)p->cap * sizeof(hol__node)) +
               hol__align((size_t)p->hsize * sizeof(uint32_t)) +
               hol__align(HOL__FMAX * sizeof(uint32_t)) +
               hol__align((size_t)p->cap * 4 * sizeof(uint32_t));
    /* the table's build scratch spans the leg table and the arena (both
     * unused then); the leg table's build scratch is the arena, and so is
     * the tours' dynamic program */
    p->legs = hol__align(hol_navtab_leg_bytes(&p->tab, lr));
    /* what the table's build once took as its queue (4 bytes a stored
     * state): the radii within HOL_NAV_BUDGET were chosen with it, so the
     * plan still reserves it and every configuration keeps its radius (the
     * build itself needs hol_navtab_scratch_bytes, far less) */
    size_t scratch = (size_t)p->tab.count * (size_t)p->tab.per * sizeof(uint32_t);
    if (scratch < hol_navtab_scratch_bytes(&p->tab))
        scratch = hol_navtab_scratch_bytes(&p->tab);
    if (p->arena + p->legs < scratch)
        p->arena = hol__align(scratch - p->legs);
    if (p->arena < hol_navtab_leg_scratch_bytes(&p->tab, lr))
        p->arena = hol__align(hol_navtab_leg_scratch_bytes(&p->tab, lr));
    if (p->arena < sizeof(hol__dp))
        p->arena = hol__align(sizeof(hol__dp));
    p->far_e = hol__align(HOL__SPHERE_MAX * (size_t)p->tab.nst);
    p->sph = hol__align(HOL__SPH_CACHE * sizeof(hol__sph));
    p->total = hol__align(sizeof(hol_nav)) + p->table + p->legs + p->far_e + p->sph + p->arena;
    return HOL_OK;
}

/* The leg radius for table radius r: the largest up to HOL__LEG_RADIUS (and
 * r) whose leg table keeps within HOL_NAV_LEG_BUDGET; 0 if none. */
static int hol__leg_radius(const hol_nav_desc *d, int r)
{
    hol_navtab t;
    if (hol_navtab_init(&t, d->tiling_q, d->room_cols, d->room_rows, 0))
        return 0;
    for (int lr = r < HOL__LEG_RADIUS ? r : HOL__LEG_RADIUS; lr >= 1; lr--)
        if (hol_navtab_leg_bytes(&t, lr) <= HOL_NAV_LEG_BUDGET)
            return lr;
    return 0;
}

static const uint8_t *hol__gap(const hol_navtab *tab);

/* The plan of desc: its radius, or else the largest radius up to the
 * default whose navigator keeps within HOL_NAV_BUDGET. */
static hol_err hol__plan_desc(const hol_nav_desc *d, hol__plan *p)
{
    if (d->radius) {
        int lr = hol__leg_radius(d, d->radius);
        hol_err err = lr ? hol__plan_sizes(d, d->radius, lr, p) : HOL_EARG;
        if (!err && (p->total > HOL_NAV_MAX_BYTES || d->radius - hol__gap(&p->tab)[0] < 1))
            err = HOL_EARG; /* too large, or too small to trust any distance */
        return err;
    }
    for (int r = HOL_NAV_DEFAULT_RADIUS; r >= 3; r--) {
        int lr = hol__leg_radius(d, r);
        if (lr && !hol__plan_sizes(d, r, lr, p) && p->total <= HOL_NAV_BUDGET)
            return HOL_OK;
    }
    return HOL_EARG;
}

/* The desc with its defaults, checked. */
static hol_err hol__desc(const hol_nav_desc *desc, hol_nav_desc *out)
{
    hol_nav_desc d;
    if (desc)
        d = *desc;
    else
        memset(&d, 0, sizeof d);
    if (d.max_nodes == 0)
        d.max_nodes = HOL_NAV_DEFAULT_NODES;
    if (d.anytime_margin == 0)
        d.anytime_margin = HOL_NAV_DEFAULT_MARGIN;
    hol_room probe;
    if ((d.radius && (d.radius < 3 || d.radius > HOL_NAV_MAX_RADIUS)) || d.max_nodes < 1024 ||
        d.max_nodes > (1u << 26) || d.anytime_margin < 0 || d.anytime_margin > 255 ||
        (!d.alloc_fn) != (!d.free_fn) ||
        hol_room_start_in(d.tiling_q, d.room_cols, d.room_rows, &probe))
        return HOL_EARG;
    if (!d.alloc_fn) {
        d.alloc_fn = hol__malloc;
        d.free_fn = hol__free;
    }
    *out = d;
    return HOL_OK;
}

/* How far beyond a target's distance optimal walks stray, by tiling and
 * room (the smaller side, then the larger): the main table is trusted to
 * its radius minus the first, the leg table to its radius minus the second.
 * Measured at each configuration's radius against a table one tile larger
 * (make bench repeats it, NAV_BENCH_VERIFY=1; tests/test_nav.c at smaller
 * radii); the gaps grow a little with the radius, so a smaller table than
 * the default is trusted less than it could be, never more. {4,5} 3 x 3:
 * 2 and 3, as always. {4,8} (like the flat grid) never strays: its tables
 * agree with larger ones everywhere. */
static const uint8_t hol__gaps[5][6][2] = {
    /* 3x3    4x4     5x5     3x4     3x5     4x5 */
    {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}, /* {4,4} */
    {{2, 3}, {3, 4}, {4, 5}, {4, 4}, {3, 4}, {4, 5}}, /* {4,5} */
    {{3, 3}, {3, 4}, {4, 5}, {4, 4}, {4, 4}, {4, 5}}, /* {4,6} */
    {{3, 4}, {4, 5}, {4, 6}, {4, 4}, {4, 5}, {5, 6}}, /* {4,7} */
    {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}, /* {4,8} */
};

static const uint8_t *hol__gap(const hol_navtab *tab)
{
    int a = tab->cols < tab->rows ? tab->cols : tab->rows;
    int b = tab->cols < tab->rows ? tab->rows : tab->cols;
    static const int8_t idx[3][3] = {{0, 3, 4}, {-1, 1, 5}, {-1, -1, 2}};
    return hol__gaps[tab->q - 4][idx[a - 3][b - 3]];
}

/* The navigator's fields over its block (the table built). */
static void hol__nav_init(hol_nav *nav, const hol_nav_desc *d, const hol__plan *pl, char *p)
{
    char *arena_p = p + pl->table + pl->legs + pl->far_e + pl->sph;
    /* touch the arena once here (the table build used only part of it as
     * scratch): the first far query paid about 8 ms of page faults; lazy:
     * only the hash is cleared, at the first search (14 MB at the
     * defaults, most of a short tool's navigator) */
    if (d->lazy)
        nav->ar.hash_dirty = 1;
    else
        memset(arena_p, 0, pl->arena);
    nav->ar.nodes = (hol__node *)(void *)arena_p;
    nav->ar.hash = (uint32_t *)(void *)(arena_p + hol__align((size_t)pl->cap * sizeof(hol__node)));
    nav->ar.bucket = (uint32_t *)(void *)((char *)nav->ar.hash +
                                       hol__align((size_t)pl->hsize * sizeof(uint32_t)));
    nav->ar.ent = (uint32_t *)(void *)((char *)nav->ar.bucket + hol__align(HOL__FMAX * sizeof(uint32_t)));
    nav->ar.ent_cap = 2 * pl->cap;
    nav->ar.cap = pl->cap;
    nav->ar.hash_mask = pl->hsize - 1;
    /* in the flat grid every walk stays on the room's tiles, all within
     * (cols - 1) + (rows - 1) <= 8 of each other: the tables are exact to
     * their radii (gaps 0) */
    const uint8_t *gap = hol__gap(&nav->tab);
    nav->trust = nav->tab.radius - gap[0]; /* at least 1 (hol__plan_desc) */
    nav->leg = (uint8_t *)(p + pl->table);
    nav->far_e = (uint8_t *)(p + pl->table + pl->legs);
    nav->sph = (hol__sph *)(void *)(p + pl->table + pl->legs + pl->far_e);
    nav->leg_radius = pl->leg_radius;
    nav->leg_trust = pl->leg_radius - gap[1];
    nav->margin = d->anytime_margin;
    for (int s = 0; s < nav->tab.nst; s++) {
        int cell = s % nav->tab.ncell;
        nav->par[s] = (uint8_t)((s / nav->tab.ncell + cell % nav->tab.cols + cell / nav->tab.cols) & 1);
    }
    nav->bytes = pl->total;
}

void hol__nav_complete(hol_nav *nav)
{
    if (nav->tabled)
        return;
    hol_navtab_finish(&nav->tab);
    nav->tabled = 1;
    int t = nav->trust < nav->tab.radius ? nav->trust : nav->tab.radius - 1;
    t = t < 1 ? 1 : t;
    nav->far_base16 = nav->tab.mean16_at[t];
    nav->far_slope16 = nav->tab.mean16_at[t] - nav->tab.mean16_at[t - 1];
    for (size_t i = 0; i < (size_t)nav->tab.per * nav->tab.off[nav->trust + 1]; i++)
        nav->partial |= nav->tab.cost[i] == 255;
}

hol_err hol_nav_create(const hol_nav_desc *desc, hol_nav **out_nav)
{
    hol_nav_desc d;
    hol__plan pl;
    hol_err err = hol__desc(desc, &d);
    if (!err)
        err = hol__plan_desc(&d, &pl);
    if (err)
        return err;
    char *block = (char *)d.alloc_fn(pl.total, d.user);
    if (!block)
        return HOL_ENOMEM;
    hol_nav *nav = (hol_nav *)(void *)block;
    memset(nav, 0, sizeof *nav);
    char *p = block + hol__align(sizeof(hol_nav));
    nav->tab = pl.tab;
    /* lazy: the table's build by parts (near finds run it as far as they
     * need; anything else finishes it first) */
    err = hol_navtab_begin(&nav->tab, p, p + pl.table);
    if (err) {
        d.free_fn(block, d.user);
        return err;
    }
    if (!d.lazy)
        hol_navtab_finish(&nav->tab); /* before the arena, its scratch, is cleared */
    hol__nav_init(nav, &d, &pl, p);
    if (!d.lazy)
        hol__nav_complete(nav);
    nav->block = block;
    nav->free_fn = d.free_fn;
    nav->user = d.user;
    *out_nav = nav;
    return HOL_OK;
}

size_t hol_nav_memory_for(const hol_nav_desc *desc)
{
    hol_nav_desc d;
    hol__plan pl;
    if (hol__desc(desc, &d) || hol__plan_desc(&d, &pl))
        return 0;
    return pl.total;
}

void hol_nav_destroy(hol_nav *nav)
{
    if (nav)
        nav->free_fn(nav->block, nav->user);
}

size_t hol_nav_memory(const hol_nav *nav) { return nav->bytes; }

int hol_nav_table_exact_radius(const hol_nav *nav) { return nav->trust; }

int hol_nav_table_radius(const hol_nav *nav) { return nav->tab.radius; }

int hol_nav_tour_exact_radius(const hol_nav *nav) { return nav->leg_trust; }

void hol_nav_geometry(const hol_nav *nav, int *out_q, int *out_cols, int *out_rows)
{
    if (out_q)
        *out_q = nav->tab.q;
    if (out_cols)
        *out_cols = nav->tab.cols;
    if (out_rows)
        *out_rows = nav->tab.rows;
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
        if (hol_navtab_cost(&nav->tab, idx, o, room->col + nav->tab.cols * room->row) == 255)
            return HOL_EUNREACH; /* {4,8}: a waypoint off the room's reach */
        size_t before = w->n;
        hol__nav_descend(&nav->tab, idx, o, room->col + nav->tab.cols * room->row, w);
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

/* Successor of a nav node in room direction d (relative tile stepping). */
static int hol__nav_succ(const hol_nav *nav, const hol__node *n, int d,
                         hol__node *out)
{
    int c2 = hol__nav_cell_step(&nav->tab, n->cell, d);
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
    hol__arena_reset(&nav->ar);
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
    root.cell = (uint8_t)(start->col + nav->tab.cols * start->row);
    root.parent = HOL__NIL;
    int v, isnew;
    int h = hol__nav_h(nav, &root, &v);
    root.f = (uint16_t)(h < HOL__FMAX ? h : HOL__FMAX - 1);
    uint32_t rid = hol__arena_intern(&nav->ar, &root, &isnew);
    hol__arena_push(&nav->ar, rid);
    uint32_t best = HOL__NIL;
    int best_cost = 1 << 20;
    if (v < 255) {
        best = rid;
        best_cost = v;
    }
    size_t expanded = 0;
    uint32_t id;
    int full = 0;
    while (!full && expanded < budget && (id = hol__arena_pop(&nav->ar)) != HOL__NIL) {
        hol__node cur = nav->ar.nodes[id];
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
            uint32_t nid = hol__arena_relax(&nav->ar, &nx, id, d, g, &full);
            if (full)
                break; /* arena full: stop */
            if (nid == HOL__NIL)
                continue;
            hol__node *q = &nav->ar.nodes[nid];
            int c;
            int hh = hol__nav_h(nav, q, &c);
            int f = g + hh;
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (c < 255 && g + c < best_cost) {
                best_cost = g + c;
                best = nid;
            }
            if (!hol__arena_push(&nav->ar, nid)) {
                full = 1;
                break;
            }
        }
    }
    res->nodes = expanded;
    if (best != HOL__NIL) {
        hol__arena_path(&nav->ar, best, w);
        const hol__node *b = &nav->ar.nodes[best];
        hol__nav_descend(&nav->tab, b->u.idx, b->o, b->cell, w);
        return w->overflow ? HOL_ENOMEM : HOL_OK;
    }
    return HOL_EBUDGET; /* nothing inside the table: caller chains */
}

hol_err hol_nav_find(hol_nav *nav, const hol_room *start, hol_tile target,
                     size_t budget, uint8_t *out_walk, size_t cap,
                     hol_nav_result *out_result)
{
    if (!nav || !hol__nav_room_ok(nav, start) || !out_walk || !out_result ||
        !hol__nav_tile_ok(nav, target))
        return HOL_EARG;
    hol__walk w = {out_walk, cap, 0, 0};
    hol_nav_result res = {0, 0, 0};
    hol_tile u;
    int o;
    hol_err err = hol__relate(start, target, &u, &o);
    int flat = nav->tab.q == 4;
    if (err == HOL_ERANGE) {
        /* farther than a tile word reaches: waypoints only (none in the
         * flat grid, whose rooms reach their own tiles only) */
        hol_room room = *start;
        if (!flat)
            hol__nav_complete(nav);
        err = flat ? HOL_EUNREACH : hol__chain(nav, &room, target, &w);
    } else if (!err && hol_tile_dist0(u) <= nav->trust) {
        uint32_t idx = hol_navtab_rank(&nav->tab, u);
        int cell = start->col + nav->tab.cols * start->row;
        /* the table as far as this state's cost (all of it, eager) */
        if (hol_navtab_need(&nav->tab, idx, o, cell) == 255)
            return HOL_EUNREACH; /* {4,4} and {4,8}: no walk in the room reaches it */
        hol__nav_descend(&nav->tab, idx, o, cell, &w);
        res.exact = 1;
        err = w.overflow ? HOL_ENOMEM : HOL_OK;
    } else if (!err && flat) {
        err = HOL_EUNREACH; /* beyond the room's span */
    } else if (!err) {
        hol__nav_complete(nav);
        if (budget == 0 || budget > nav->ar.cap)
            budget = nav->ar.cap;
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
