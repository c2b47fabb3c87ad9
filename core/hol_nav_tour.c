/* hol_nav_tour.c - keys and chest: the fewest steps to stand on every key,
 * then on the chest (hol_nav_tour; contract in hol_nav.h).
 *
 * A dynamic program over key subsets x room states on the keys
 * (hol__tour_dp), over the legs of hol_nav_legs.c twice: their walks give
 * a tour, their lower bounds a bound on the optimum; where the two meet
 * the tour is exact. Otherwise the tour prunes an A* over room state x
 * collected keys (admissible heuristic hol__tour_h from a backward program
 * over key sets on the legs' lower bounds, hol__tour_suf; nodes may be
 * reopened), which is exact when it completes.
 */
#include "hol_nav.h"

#include <string.h>

#include "hol_nav_impl.h"

/* ---- tours ---- */

void hol_nav_prepare_tours(hol_nav *nav)
{
    hol__nav_complete(nav); /* the leg table's build overwrites its scratch */
    if (!nav->leg_ready) {
        hol_navtab_build_legs(&nav->tab, nav->leg_radius, nav->leg, nav->ar.nodes);
        nav->leg_ready = 1;
        nav->ar.hash_dirty = 1; /* the build's scratch was the arena */
        hol__far_e_fill(nav);
    }
}

/* Least cost from any room state on tile a to stand on b. */
static int hol__lb_any(const hol_nav *nav, hol_tile a, hol_tile b)
{
    hol__rel r;
    int d = hol__rel_ranked(nav, a, b, &r), m = 255;
    for (int s = 0; s < nav->tab.nst; s++) {
        int v = hol__lb_rel(nav, &r, d, s);
        if (v < m)
            m = v;
    }
    return m;
}

typedef struct hol__tour {
    const hol_tile *keys;
    int nkeys;
    hol_tile chest;
    /* mst[mask]: minimum spanning tree over the chest and the keys NOT in
     * mask, edges the least cost between two tiles from any room state */
    int mst[1 << HOL__NK];
    unsigned full;
    /* suf at HOL__DPX(nst, m, k, s): a lower bound on the steps from key k
     * in room state s with the keys in m held (k in m) to collect the
     * others and stand on the chest; sufmin[m][k] its least over s
     * (hol__tour_suf) */
    uint16_t suf[(1 << HOL__NK) * HOL__NK * HOL__MAXST];
    int sufmin[1 << HOL__NK][HOL__NK];
} hol__tour;

static unsigned hol__keys_on(const hol__tour *t, hol_tile tile)
{
    unsigned m = 0;
    for (int i = 0; i < t->nkeys; i++)
        if (hol_tile_eq(t->keys[i], tile))
            m |= 1u << i;
    return m;
}

/* Admissible: the walk still has to reach the keys left, first visits in
 * some order, then the chest. From the node to the next key k: the exact
 * state-to-state leg when k is within the leg table's trusted radius (then
 * the rest is suf of the state it arrives in), else the cost to k's tile
 * from the main table (then the least suf over k's states). With every key
 * held: the cost to the chest. Also at least (a) the cost to the chest and
 * (c) the cost to the nearest key left plus a spanning tree over the keys
 * left and the chest. */
static int hol__tour_h(const hol_nav *nav, const hol__tour *t, const hol__node *n)
{
    int h = hol__lb_state(nav, n->u.t, n->o, n->cell, t->chest), nearest = INT32_MAX, best = INT32_MAX;
    int nst = nav->tab.nst, nc = nav->tab.ncell;
    unsigned mask = n->flags & HOL__MASK;
    if (mask == t->full)
        return h;
    for (int i = 0; i < t->nkeys; i++) {
        if (mask & (1u << i))
            continue;
        unsigned m2 = mask | (1u << i);
        hol__rel r;
        int d = hol__rel_ranked(nav, n->u.t, t->keys[i], &r), v;
        int c = hol__lb_rel(nav, &r, d, nc * n->o + n->cell);
        if (c < nearest)
            nearest = c;
        if (nav->leg_ready && d <= nav->leg_trust) {
            int o = (r.facing + n->o) & 3;
            const uint16_t *suf = &t->suf[HOL__DPX(nst, m2, i, 0)];
            v = INT32_MAX;
            for (int s2 = 0; s2 < nst; s2++) {
                int l = hol_navtab_leg(&nav->tab, nav->leg, r.idx, o, n->cell, s2 / nc, s2 % nc);
                if (l < 255 && l + suf[s2] < v)
                    v = l + suf[s2];
            }
        } else {
            v = c + t->sufmin[m2][i];
        }
        if (v < best)
            best = v;
    }
    if (best > h)
        h = best;
    if (nearest != INT32_MAX && nearest + t->mst[mask] > h)
        h = nearest + t->mst[mask];
    return h;
}

/* Prim over the chest and the keys not in mask. */
static int hol__tour_mst(const int w[HOL__NK + 1][HOL__NK + 1], int nkeys, unsigned mask)
{
    int in[HOL__NK + 1] = {0}, best[HOL__NK + 1];
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
 * F[mask][j][s] (hol__dp in hol_nav_impl.h): fewest steps from the start to
 * stand on key j in room state s (orientation, cell: nst states) having
 * first visited the keys in mask, j last. The optimal walk visits the keys
 * first in some order; each leg between consecutive first visits costs at
 * least the state-to-state distance, and the last leg to the chest at
 * least the state-to-tile one. So the program over the legs' lower bounds
 * (hol_nav_legs.c) bounds the optimum from below, and the program over
 * their walks gives a tour; when the two meet, that tour is the optimum. */

/* One step of the program: F[m2][k][.] from F[m][j][s] over leg row. */
static void hol__dp_relax(int nst, uint16_t *to, const uint8_t *row, int base, int8_t *pj,
                          uint8_t *ps, int j, int s)
{
    for (int s2 = 0; s2 < nst; s2++) {
        int v = row[s2];
        if (v < 255 && base + v < to[s2]) {
            to[s2] = (uint16_t)(base + v);
            if (pj) {
                pj[s2] = (int8_t)j;
                ps[s2] = (uint8_t)s;
            }
        }
    }
}

/* The legs (bounds and walks) of the tour from the start over t's keys. */
static void hol__dp_legs(hol_nav *nav, hol__dp *dp, const hol_room *start, const hol__tour *t,
                         int ss)
{
    int nk = t->nkeys, all[HOL__MAXST];
    for (int s = 0; s < nav->tab.nst; s++)
        all[s] = s;
    /* a key's sphere only where a leg from the start or another key to it,
     * or from it to the chest, lies beyond the trusted radii */
    for (int k = 0; k < nk; k++) {
        int need = hol_tile_dist(start->tile, t->keys[k]) > nav->leg_trust ||
                   hol_tile_dist(t->keys[k], t->chest) > nav->trust;
        for (int j = 0; j < k && !need; j++)
            need = hol_tile_dist(t->keys[j], t->keys[k]) > nav->leg_trust;
        dp->none.n = 0;
        dp->sph[k] = need ? hol__sph_get(nav, t->keys[k]) : &dp->none;
    }
    for (int k = 0; k < nk; k++) {
        hol__legb_fill(nav, start->tile, t->keys[k], dp->sph[k], &ss, 1, &dp->leg[nk][k],
                       &dp->scr);
        hol__chestb_fill(nav, t->keys[k], t->chest, dp->sph[k], &dp->chest[k], &dp->scr);
        for (int j = 0; j < k; j++) {
            hol__legb_fill(nav, t->keys[j], t->keys[k], dp->sph[k], all, nav->tab.nst,
                           &dp->leg[j][k], &dp->scr);
            hol__legb_reverse(&dp->leg[j][k], &dp->leg[k][j]);
        }
    }
}

/* Both programs forwards over the key sets (dp's legs filled). */
static void hol__dp_run(const hol_nav *nav, hol__dp *dp, const hol__tour *t, int ss)
{
    int nk = t->nkeys, nst = nav->tab.nst;
    size_t cells = (size_t)(1u << nk) * HOL__NK * (size_t)nst;
    memset(dp->cost, 0xff, cells * sizeof dp->cost[0]);
    memset(dp->lower, 0xff, cells * sizeof dp->lower[0]);
    for (int k = 0; k < nk; k++) {
        size_t x = HOL__DPX(nst, 1u << k, k, 0), r = HOL__LX(&dp->leg[nk][k], ss, 0);
        hol__dp_relax(nst, &dp->cost[x], &dp->leg[nk][k].ub[r], 0, &dp->pj[x], &dp->ps[x], -1, 0);
        hol__dp_relax(nst, &dp->lower[x], &dp->leg[nk][k].lb[r], 0, NULL, NULL, 0, 0);
    }
    for (unsigned m = 1; m < (1u << nk); m++)
        for (int j = 0; j < nk; j++) {
            if (!(m & (1u << j)))
                continue;
            for (int s = 0; s < nst; s++)
                for (int k = 0; k < nk; k++) {
                    if (m & (1u << k))
                        continue;
                    size_t from = HOL__DPX(nst, m, j, s), to = HOL__DPX(nst, m | (1u << k), k, 0);
                    size_t r = HOL__LX(&dp->leg[j][k], s, 0);
                    if (dp->cost[from] != 0xffff)
                        hol__dp_relax(nst, &dp->cost[to], &dp->leg[j][k].ub[r], dp->cost[from],
                                      &dp->pj[to], &dp->ps[to], j, s);
                    if (dp->lower[from] != 0xffff)
                        hol__dp_relax(nst, &dp->lower[to], &dp->leg[j][k].lb[r], dp->lower[from],
                                      NULL, NULL, 0, 0);
                }
        }
}

/* The tour's walk: the order of first visits back to front from (bj, bs),
 * then its legs front to back and the leg to the chest. */
static void hol__dp_walk(const hol_nav *nav, const hol__dp *dp, const hol_room *start,
                         const hol__tour *t, int ss, int bj, int bs, hol__walk *w)
{
    int oj[HOL__NK], os[HOL__NK], n = 0, nk = t->nkeys, nst = nav->tab.nst;
    unsigned m = t->full;
    for (int j = bj, s = bs; j >= 0;) {
        oj[n] = j;
        os[n] = s;
        n++;
        size_t x = HOL__DPX(nst, m, j, s);
        m &= ~(1u << j);
        j = dp->pj[x];
        s = dp->ps[x];
    }
    for (int i = n - 1; i >= 0; i--) {
        if (i == n - 1)
            hol__legb_walk(nav, &dp->leg[nk][oj[i]], start->tile, ss, t->keys[oj[i]], os[i], w);
        else
            hol__legb_walk(nav, &dp->leg[oj[i + 1]][oj[i]], t->keys[oj[i + 1]], os[i + 1],
                           t->keys[oj[i]], os[i], w);
    }
    hol__chestb_walk(nav, &dp->chest[bj], t->keys[bj], bs, t->chest, w);
}

/* The dynamic program over key subsets x room states on the keys, over
 * the legs' walks and their lower bounds. *out_proved: the two meet, the
 * tour is the optimum; otherwise it is a valid tour, an upper bound.
 * HOL_ERANGE when no tour was found (tiles too far apart). */
static hol_err hol__tour_dp(hol_nav *nav, const hol_room *start, const hol__tour *t,
                            hol__walk *w, hol_nav_result *res, int *out_proved)
{
    int nk = t->nkeys, nst = nav->tab.nst;
    hol_nav_prepare_tours(nav);
    /* the program lives in the arena (nodes are not used by this path) */
    hol__dp *dp = (hol__dp *)(void *)nav->ar.nodes;
    nav->ar.hash_dirty = 1; /* the nodes no longer match the hash */
    int ss = hol__nav_state(nav, start);
    hol__dp_legs(nav, dp, start, t, ss);
    hol__dp_run(nav, dp, t, ss);
    int best = INT32_MAX, bj = -1, bs = -1, low = INT32_MAX;
    for (int j = 0; j < nk; j++)
        for (int s = 0; s < nst; s++) {
            size_t x = HOL__DPX(nst, t->full, j, s);
            int v = dp->chest[j].ub[s], lv = dp->chest[j].lb[s];
            if (dp->cost[x] != 0xffff && v < 255 && dp->cost[x] + v < best) {
                best = dp->cost[x] + v;
                bj = j;
                bs = s;
            }
            if (dp->lower[x] != 0xffff && dp->lower[x] + lv < low)
                low = dp->lower[x] + lv;
        }
    if (bj < 0)
        return HOL_ERANGE;
    hol__dp_walk(nav, dp, start, t, ss, bj, bs, w);
    if (w->overflow)
        return HOL_ENOMEM;
    if ((int)w->n != best)
        return HOL_ERANGE; /* a leg could not be walked as costed (does not happen) */
    int proved = low >= best;
    res->exact = proved;
    res->nodes = 0;
    *out_proved = proved;
    return HOL_OK;
}

/* Fill t->suf (see hol__tour) backwards over key sets from the legs' lower
 * bounds (the program's, still in the arena). */
static void hol__tour_suf(const hol_nav *nav, hol__tour *t)
{
    const hol__dp *dp = (const hol__dp *)(const void *)nav->ar.nodes;
    int nk = t->nkeys, nst = nav->tab.nst;
    for (unsigned m = t->full; m >= 1; m--)
        for (int k = 0; k < nk; k++) {
            if (!(m & (1u << k)))
                continue;
            int mn = INT32_MAX;
            for (int s = 0; s < nst; s++) {
                int v = INT32_MAX;
                if (m == t->full) {
                    v = dp->chest[k].lb[s];
                } else {
                    for (int k2 = 0; k2 < nk; k2++) {
                        if (m & (1u << k2))
                            continue;
                        const uint16_t *suf = &t->suf[HOL__DPX(nst, m | (1u << k2), k2, 0)];
                        const uint8_t *row = &dp->leg[k][k2].lb[HOL__LX(&dp->leg[k][k2], s, 0)];
                        for (int s2 = 0; s2 < nst; s2++)
                            if (row[s2] + suf[s2] < v)
                                v = row[s2] + suf[s2];
                    }
                }
                if (v > 0xfff0)
                    v = 0xfff0;
                t->suf[HOL__DPX(nst, m, k, s)] = (uint16_t)v;
                if (v < mn)
                    mn = v;
            }
            t->sufmin[m][k] = mn;
        }
}

/* The A* over room state x collected keys, pruned by ub (the program's
 * tour, INT32_MAX: none), within budget. *out_goal: the node on the chest
 * with every key (HOL__NIL: none); *out_dry: nothing is left below ub. */
static void hol__tour_astar(hol_nav *nav, const hol_room *start, const hol__tour *t, int ub,
                            size_t budget, uint32_t *out_goal, int *out_dry, size_t *out_nodes)
{
    hol__arena_reset(&nav->ar);
    hol__node root;
    memset(&root, 0, sizeof root);
    root.u.t = start->tile;
    root.o = start->orient;
    root.cell = (uint8_t)(start->col + nav->tab.cols * start->row);
    root.flags = (uint8_t)hol__keys_on(t, start->tile);
    root.parent = HOL__NIL;
    int h = hol__tour_h(nav, t, &root), isnew, full_arena = 0;
    root.f = (uint16_t)(h < HOL__FMAX ? h : HOL__FMAX - 1);
    uint32_t id = hol__arena_intern(&nav->ar, &root, &isnew);
    hol__arena_push(&nav->ar, id);
    size_t expanded = 0;
    *out_goal = HOL__NIL;
    *out_dry = 0;
    while (expanded < budget && !full_arena) {
        if ((id = hol__arena_pop(&nav->ar)) == HOL__NIL) {
            *out_dry = 1;
            break;
        }
        hol__node cur = nav->ar.nodes[id];
        if ((int)cur.f >= ub) {
            *out_dry = 1; /* nothing left below the bound */
            break;
        }
        if ((cur.flags & HOL__MASK) == t->full && hol_tile_eq(cur.u.t, t->chest)) {
            *out_goal = id;
            break;
        }
        expanded++;
        for (int d = 0; d < 4; d++) {
            int c2 = hol__nav_cell_step(&nav->tab, cur.cell, d), arr;
            if (c2 < 0)
                continue;
            hol__node nx;
            memset(&nx, 0, sizeof nx);
            if (hol_tile_step(cur.u.t, cur.o + d, &nx.u.t, &arr))
                continue;
            nx.o = (uint8_t)((arr - d) & 3);
            nx.cell = (uint8_t)c2;
            nx.flags = (uint8_t)((cur.flags & HOL__MASK) | hol__keys_on(t, nx.u.t));
            int g = cur.g + 1;
            uint32_t nid = hol__arena_relax(&nav->ar, &nx, id, d, g, &full_arena);
            if (full_arena)
                break;
            if (nid == HOL__NIL)
                continue;
            hol__node *q = &nav->ar.nodes[nid];
            int f = g + hol__tour_h(nav, t, q);
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (f >= ub)
                continue; /* cannot beat the upper bound */
            if (!hol__arena_push(&nav->ar, nid)) {
                full_arena = 1;
                break;
            }
        }
    }
    *out_nodes = expanded;
}

/* The tour's keys and chest, with the spanning trees of hol__tour_h. */
static void hol__tour_init(const hol_nav *nav, hol__tour *t, const hol_tile *keys, int nkeys,
                           hol_tile chest)
{
    t->keys = keys;
    t->nkeys = nkeys;
    t->chest = chest;
    t->full = (1u << nkeys) - 1;
    int wt[HOL__NK + 1][HOL__NK + 1];
    for (int i = 0; i <= nkeys; i++)
        for (int j = 0; j <= nkeys; j++)
            wt[i][j] = i == j ? 0
                             : hol__lb_any(nav, i < nkeys ? keys[i] : chest,
                                           j < nkeys ? keys[j] : chest);
    for (unsigned m = 0; m < (1u << nkeys); m++)
        t->mst[m] = hol__tour_mst((const int(*)[HOL__NK + 1])wt, nkeys, m);
}

/* Where some tiles are out of some room states' reach ({4,4}, {4,8}):
 * HOL_EUNREACH when a key or the chest is (no walk reaches it; the keys
 * one reaches, it reaches in any order, steps being reversible). */
static hol_err hol__tour_reach(hol_nav *nav, const hol_room *start, const hol_tile *keys,
                               int nkeys, hol_tile chest)
{
    uint8_t walk[64];
    hol_nav_result r;
    for (int i = 0; i <= nkeys; i++) {
        hol_err err = hol_nav_find(nav, start, i < nkeys ? keys[i] : chest, 0, walk,
                                   sizeof walk, &r);
        if (err)
            return err;
    }
    return HOL_OK;
}

hol_err hol_nav_tour(hol_nav *nav, const hol_room *start, const hol_tile *keys,
                     int nkeys, hol_tile chest, size_t budget,
                     uint8_t *out_walk, size_t cap, hol_nav_result *out_result)
{
    if (!nav || !hol__nav_room_ok(nav, start) || !out_walk || !out_result ||
        nkeys < 0 || nkeys > HOL_NAV_TOUR_MAX_KEYS || (nkeys && !keys) ||
        !hol__nav_tile_ok(nav, chest))
        return HOL_EARG;
    for (int i = 0; i < nkeys; i++)
        if (!hol__nav_tile_ok(nav, keys[i]))
            return HOL_EARG;
    if (nkeys == 0)
        return hol_nav_find(nav, start, chest, budget, out_walk, cap, out_result);
    hol__nav_complete(nav);
    hol_err err = nav->partial ? hol__tour_reach(nav, start, keys, nkeys, chest) : HOL_OK;
    if (err)
        return err;
    hol__tour t;
    hol__tour_init(nav, &t, keys, nkeys, chest);
    if (budget == 0 || budget > nav->ar.cap)
        budget = nav->ar.cap;
    hol__walk w = {out_walk, cap, 0, 0};
    hol_nav_result res = {0, 0, 0};
    /* The program's tour: the optimum when every leg lies within the
     * trusted radii; otherwise a valid tour whose length bounds the A*
     * below (if the A* runs dry below it, this walk is the optimum). */
    int proved = 0, ub = INT32_MAX, dry;
    hol_err dperr = hol__tour_dp(nav, start, &t, &w, &res, &proved);
    if (dperr == HOL_OK && proved) {
        res.len = (int)w.n;
        *out_result = res;
        return HOL_OK;
    }
    if (dperr == HOL_OK)
        ub = (int)w.n;
    else if (dperr != HOL_ERANGE)
        return dperr;
    else
        w.n = 0;
    w.overflow = 0;
    res.exact = 0;
    hol__tour_suf(nav, &t); /* before the search takes the arena */
    uint32_t goal;
    hol__tour_astar(nav, start, &t, ub, budget, &goal, &dry, &res.nodes);
    if (goal != HOL__NIL) {
        w.n = 0;
        hol__arena_path(&nav->ar, goal, &w);
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
