/* hol_nav_tour.c - keys and chest: the fewest steps to stand on every key,
 * then on the chest (hol_nav_tour; contract in hol_nav.h).
 *
 * A dynamic program over key subsets x room states on the keys
 * (hol__tour_dp): with the keys close together its legs are exact
 * state-to-state costs and so is the tour. Otherwise (legs up to the
 * tables' radii, or through a midway tile) its tour is an upper bound that
 * prunes an A* over room state x collected keys (admissible heuristic
 * hol__tour_h from a backward program over key sets, hol__tour_suf; nodes
 * may be reopened), which is exact when it completes.
 */
#include "hol_nav.h"

#include <string.h>

#include "hol_nav_impl.h"

#define HOL__NK HOL_NAV_TOUR_MAX_KEYS

/* ---- tours ---- */

/* Least leg from any room state on each tile of the sphere at the leg
 * table's trusted radius (relative index off[rho] + x) to each goal state
 * s2: the same for every destination, as the leg table is relative. */
static void hol__far_e(const hol_nav *nav, uint8_t (*e)[36])
{
    int rho = nav->leg_trust;
    uint32_t lo = nav->tab.off[rho], n = nav->tab.off[rho + 1] - lo;
    for (uint32_t x = 0; x < n; x++)
        for (int s2 = 0; s2 < 36; s2++) {
            int m = 255;
            for (int o = 0; o < 4; o++)
                for (int cell = 0; cell < 9; cell++) {
                    int v = hol_navtab_leg(nav->leg, lo + x, o, cell, s2 / 9, s2 % 9);
                    if (v < m)
                        m = v;
                }
            e[x][s2] = (uint8_t)m;
        }
}

void hol_nav_prepare_tours(hol_nav *nav)
{
    if (!nav->leg_ready) {
        hol_navtab_build_legs(&nav->tab, nav->leg_radius, nav->leg, nav->nodes);
        nav->leg_ready = 1;
        nav->hash_dirty = 1; /* the build's scratch was the arena */
        if (nav->tab.off[nav->leg_trust + 1] - nav->tab.off[nav->leg_trust] <= HOL__SPHERE_MAX)
            hol__far_e(nav, (uint8_t (*)[36])(void *)nav->far_e);
    }
}

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
    /* suf[m][k][s]: a lower bound on the steps from key k in room state s
     * (orientation s / 9 relative to the tile's heading, cell s % 9) with
     * the keys in m held (k in m) to collect the others and stand on the
     * chest; sufmin[m][k] its least over s (hol__tour_suf) */
    uint16_t suf[1 << HOL_NAV_TOUR_MAX_KEYS][HOL_NAV_TOUR_MAX_KEYS][36];
    int sufmin[1 << HOL_NAV_TOUR_MAX_KEYS][HOL_NAV_TOUR_MAX_KEYS];
} hol__tour;

static unsigned hol__keys_on(const hol__tour *t, hol_tile tile)
{
    unsigned m = 0;
    for (int i = 0; i < t->nkeys; i++)
        if (hol_tile_eq(t->keys[i], tile))
            m |= 1u << i;
    return m;
}

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
    int h = hol__lb(nav, n->u.t, n->o, n->cell, t->chest), nearest = INT32_MAX, best = INT32_MAX;
    unsigned mask = n->flags & HOL__MASK;
    if (mask == t->full)
        return h;
    for (int i = 0; i < t->nkeys; i++) {
        if (mask & (1u << i))
            continue;
        unsigned m2 = mask | (1u << i);
        hol__rel r;
        int c = hol__lb(nav, n->u.t, n->o, n->cell, t->keys[i]), v;
        if (c < nearest)
            nearest = c;
        if (nav->leg_ready && hol__rel_of(nav, n->u.t, t->keys[i], nav->leg_trust, &r)) {
            int o = (r.facing + n->o) & 3;
            v = INT32_MAX;
            for (int s2 = 0; s2 < 36; s2++) {
                int l = hol_navtab_leg(nav->leg, r.idx, o, n->cell, s2 / 9, s2 % 9);
                if (l < 255 && l + t->suf[m2][i][s2] < v)
                    v = l + t->suf[m2][i][s2];
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

/* Fill t->suf (see hol__tour) backwards over key sets: the chest's cost
 * from the main table with every key held; between keys the exact leg
 * within the leg table's trusted radius, else the larger of the two tiles'
 * costs to each other from the main table (steps are reversible, so a leg
 * costs at least both). Needs the leg table (hol_nav_prepare_tours). */
/* For keys farther apart than the leg table's trusted radius rho: every
 * walk from a state on src to state s2 on dst is last at distance rho from
 * dst on some tile x, and from there stays within rho, so it costs at
 * least (src state to x's tile, main table) + (least over x's room states
 * of the leg to s2). out[s][s2] = the least of that over the sphere. */
/* e: hol__far_e (the same for every pair: the leg table is relative to the
 * destination); c, order: scratch of the sphere's size. */
static void hol__far_lb(const hol_nav *nav, hol_tile src, hol_tile dst, uint8_t out[36][36],
                        const uint8_t (*e)[36], uint8_t (*c)[36], uint16_t *order)
{
    int rho = nav->leg_trust;
    uint32_t lo = nav->tab.off[rho], n = nav->tab.off[rho + 1] - lo;
    uint16_t cnt[512];
    int key[HOL__SPHERE_MAX];
    memset(cnt, 0, sizeof cnt);
    for (uint32_t x = 0; x < n; x++) {
        /* x's tile: its address seen from dst, walked from dst */
        hol_tile u = hol_navtab_unrank(&nav->tab, lo + x);
        hol_heading_tile f = {dst, 0};
        int ok = 1;
        for (int i = 0; i < rho && ok; i++)
            ok = !hol_heading_tile_step(f, hol_tile_letter(u, i), &f);
        /* as hol__lb(src state, x), the relative address found once */
        hol_tile rx;
        int facing, d = -1;
        if (ok && !hol_tile_relative(f.tile, 0, src, &rx, &facing))
            d = hol_tile_dist0(rx);
        uint32_t ri = d >= 0 && d <= nav->trust ? hol_navtab_rank(&nav->tab, rx) : 0;
        int cmin = 255, emin = 255;
        for (int s = 0; s < 36; s++) {
            int v;
            if (d < 0)
                v = 0;
            else if (d <= nav->trust)
                v = hol_navtab_cost(&nav->tab, ri, (facing + s / 9) & 3, s % 9);
            else
                v = nav->tab.min_at[nav->trust] + d - nav->trust;
            c[x][s] = (uint8_t)(v < 255 ? v : 255);
            if (c[x][s] < cmin)
                cmin = c[x][s];
            if (e[x][s] < emin)
                emin = e[x][s];
        }
        key[x] = cmin + emin;
        cnt[key[x]]++;
    }
    /* tiles by cmin + emin ascending (counting sort): once that exceeds
     * every entry found, no later tile can lower one */
    uint32_t start[512], acc = 0;
    for (int k = 0; k < 512; k++) {
        start[k] = acc;
        acc += cnt[k];
    }
    for (uint32_t x = 0; x < n; x++)
        order[start[key[x]]++] = (uint16_t)x;
    memset(out, 255, 36 * 36);
    int worst = 255;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t x = order[i];
        if (key[x] >= worst)
            break;
        int w = 0;
        for (int s = 0; s < 36; s++)
            for (int s2 = 0; s2 < 36; s2++) {
                int v = c[x][s] + e[x][s2];
                if (v < out[s][s2])
                    out[s][s2] = (uint8_t)v;
                if (out[s][s2] > w)
                    w = out[s][s2];
            }
        worst = w;
    }
}

static void hol__tour_suf(hol_nav *nav, hol__tour *t)
{
    int nk = t->nkeys;
    hol__rel rel[HOL__NK][HOL__NK];
    int near[HOL__NK][HOL__NK];
    uint8_t lbk[HOL__NK][HOL__NK][36]; /* key j state s to key k's tile */
    /* scratch in the arena (the A* has not started) */
    uint8_t (*far)[HOL__NK][36][36] = (uint8_t (*)[HOL__NK][36][36])(void *)nav->nodes;
    const uint8_t (*e)[36] = (const uint8_t (*)[36])(const void *)nav->far_e;
    uint32_t nsph = nav->tab.off[nav->leg_trust + 1] - nav->tab.off[nav->leg_trust];
    uint8_t (*c)[36] = (uint8_t (*)[36])(void *)((char *)nav->nodes +
                                                  sizeof(uint8_t[HOL__NK][HOL__NK][36][36]));
    uint16_t *order = (uint16_t *)(void *)(c + nsph);
    nav->hash_dirty = 1;
    for (int j = 0; j < nk; j++)
        for (int k = 0; k < nk; k++) {
            if (j == k)
                continue;
            near[j][k] = hol__rel_of(nav, t->keys[j], t->keys[k], nav->leg_trust, &rel[j][k]);
            for (int s = 0; s < 36; s++) {
                int cst = hol__lb(nav, t->keys[j], s / 9, s % 9, t->keys[k]);
                lbk[j][k][s] = (uint8_t)(cst < 255 ? cst : 255);
            }
            if (!near[j][k] && nsph <= HOL__SPHERE_MAX) {
                hol__far_lb(nav, t->keys[j], t->keys[k], far[j][k], e, c, order);
            } else if (!near[j][k]) {
                memset(far[j][k], 0, sizeof far[j][k]);
            }
        }
    for (unsigned m = t->full; m >= 1; m--)
        for (int k = 0; k < nk; k++) {
            if (!(m & (1u << k)))
                continue;
            int mn = INT32_MAX;
            for (int s = 0; s < 36; s++) {
                int v = INT32_MAX;
                if (m == t->full) {
                    v = hol__lb(nav, t->keys[k], s / 9, s % 9, t->chest);
                } else {
                    for (int k2 = 0; k2 < nk; k2++) {
                        if (m & (1u << k2))
                            continue;
                        unsigned m2 = m | (1u << k2);
                        const hol__rel *r = &rel[k][k2];
                        int o = (r->facing + s / 9) & 3;
                        for (int s2 = 0; s2 < 36; s2++) {
                            int l;
                            if (near[k][k2]) {
                                l = hol_navtab_leg(nav->leg, r->idx, o, s % 9, s2 / 9, s2 % 9);
                                if (l == 255)
                                    continue;
                            } else {
                                l = lbk[k][k2][s] > lbk[k2][k][s2] ? lbk[k][k2][s]
                                                                    : lbk[k2][k][s2];
                                if (far[k][k2][s][s2] > l)
                                    l = far[k][k2][s][s2];
                            }
                            if (l + t->suf[m2][k2][s2] < v)
                                v = l + t->suf[m2][k2][s2];
                        }
                    }
                }
                if (v > 0xfff0)
                    v = 0xfff0;
                t->suf[m][k][s] = (uint16_t)v;
                if (v < mn)
                    mn = v;
            }
            t->sufmin[m][k] = mn;
        }
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


/* Descend the leg table from (idx, o, cell) to the goal state (ob, cb). */
static void hol__leg_descend(const hol_nav *nav, uint32_t idx, int o, int cell, int ob,
                             int cb, hol__walk *w)
{
    uint32_t n = nav->tab.off[nav->leg_radius + 1];
    int v = hol_navtab_leg(nav->leg, idx, o, cell, ob, cb);
    while (v > 0 && v < 255) {
        int moved = 0;
        for (int d = 0; d < 4 && !moved; d++) {
            int c2 = hol__nav_cell_step(cell, d);
            if (c2 < 0)
                continue;
            uint32_t e = nav->tab.nb[4 * (size_t)idx + (size_t)((o + d) & 3)];
            if (e == HOL_NAVTAB_NONE || (e >> 2) >= n)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            if (hol_navtab_leg(nav->leg, e >> 2, o2, c2, ob, cb) == v - 1) {
                hol__nav_emit(w, d);
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

/* Legs from every room state on a source tile to every room state on a
 * key: state-to-state costs of walks, straight from the leg table when the
 * tiles lie within its radius, else through a room state on the tile
 * midway along a geodesic (both halves from the leg table; the walk is
 * valid, its cost an upper bound). */
typedef struct hol__legm {
    uint8_t c[36][36];   /* c[s][s2]: source state s to key state s2 */
    uint8_t via[36][36]; /* the midway state (through a midpoint) */
    hol__rel r1, r2;     /* direct: r1; midway: r1 to the midpoint, r2 on */
    int mid;
} hol__legm;

/* The chest from every room state on a key: the main table directly, or
 * through the midway tile as above (leg, then the main table). */
typedef struct hol__chestv {
    uint8_t c[36];
    uint8_t via[36];
    hol__rel r1, r2;
    int mid;
} hol__chestv;

typedef struct hol__dp {
    uint16_t cost[1 << HOL__NK][HOL__NK][36];
    int8_t pj[1 << HOL__NK][HOL__NK][36]; /* previous key, -1: the start */
    uint8_t ps[1 << HOL__NK][HOL__NK][36]; /* previous state */
    hol__legm leg[HOL__NK + 1][HOL__NK];   /* from key j (or the start, nk) to key k */
    hol__chestv chest[HOL__NK];
} hol__dp;

/* The tile halfway along a geodesic from a to b. */
static int hol__midway(hol_tile a, hol_tile b, hol_tile *out)
{
    uint8_t let[HOL_TILE_REL_MAX];
    int n = hol_tile_relative_letters(a, 0, b, let, NULL);
    if (n < 0)
        return 0;
    hol_heading_tile f = {a, 0};
    for (int i = 0; i < (n + 1) / 2; i++)
        if (hol_heading_tile_step(f, let[i], &f))
            return 0;
    *out = f.tile;
    return 1;
}

static int hol__leg_at(const hol_nav *nav, const hol__rel *r, int s, int s2)
{
    return hol_navtab_leg(nav->leg, r->idx, (r->facing + s / 9) & 3, s % 9, s2 / 9, s2 % 9);
}

static int hol__legm_fill(const hol_nav *nav, hol_tile a, hol_tile b, hol__legm *L)
{
    hol_tile x;
    if (hol__rel_of(nav, a, b, nav->leg_radius, &L->r1)) {
        L->mid = 0;
        for (int s = 0; s < 36; s++)
            for (int s2 = 0; s2 < 36; s2++)
                L->c[s][s2] = (uint8_t)hol__leg_at(nav, &L->r1, s, s2);
        return 1;
    }
    if (!hol__midway(a, b, &x) || !hol__rel_of(nav, a, x, nav->leg_radius, &L->r1) ||
        !hol__rel_of(nav, x, b, nav->leg_radius, &L->r2))
        return 0;
    L->mid = 1;
    uint8_t h2[36][36];
    for (int u = 0; u < 36; u++)
        for (int s2 = 0; s2 < 36; s2++)
            h2[u][s2] = (uint8_t)hol__leg_at(nav, &L->r2, u, s2);
    for (int s = 0; s < 36; s++) {
        int h1[36];
        for (int u = 0; u < 36; u++)
            h1[u] = hol__leg_at(nav, &L->r1, s, u);
        for (int s2 = 0; s2 < 36; s2++) {
            int best = 255, bu = 0;
            for (int u = 0; u < 36; u++)
                if (h1[u] + h2[u][s2] < best) {
                    best = h1[u] + h2[u][s2];
                    bu = u;
                }
            L->c[s][s2] = (uint8_t)best;
            L->via[s][s2] = (uint8_t)bu;
        }
    }
    return 1;
}

static int hol__chestv_fill(const hol_nav *nav, hol_tile key, hol_tile chest,
                            hol__chestv *C)
{
    hol_tile x;
    if (hol__rel_of(nav, key, chest, nav->tab.radius, &C->r1)) {
        C->mid = 0;
        for (int s = 0; s < 36; s++)
            C->c[s] = (uint8_t)hol_navtab_cost(&nav->tab, C->r1.idx,
                                               (C->r1.facing + s / 9) & 3, s % 9);
        return 1;
    }
    if (!hol__midway(key, chest, &x) || !hol__rel_of(nav, key, x, nav->leg_radius, &C->r1) ||
        !hol__rel_of(nav, x, chest, nav->tab.radius, &C->r2))
        return 0;
    C->mid = 1;
    int h2[36];
    for (int u = 0; u < 36; u++)
        h2[u] = hol_navtab_cost(&nav->tab, C->r2.idx, (C->r2.facing + u / 9) & 3, u % 9);
    for (int s = 0; s < 36; s++) {
        int best = 255, bu = 0;
        for (int u = 0; u < 36; u++) {
            int v = hol__leg_at(nav, &C->r1, s, u) + h2[u];
            if (v < best) {
                best = v;
                bu = u;
            }
        }
        C->c[s] = (uint8_t)best;
        C->via[s] = (uint8_t)bu;
    }
    return 1;
}

/* The walk of leg L from state s (orientation s / 9, cell s % 9) to s2. */
static void hol__legm_walk(const hol_nav *nav, const hol__legm *L, int s, int s2, hol__walk *w)
{
    if (!L->mid) {
        hol__leg_descend(nav, L->r1.idx, (L->r1.facing + s / 9) & 3, s % 9, s2 / 9, s2 % 9, w);
        return;
    }
    int u = L->via[s][s2];
    hol__leg_descend(nav, L->r1.idx, (L->r1.facing + s / 9) & 3, s % 9, u / 9, u % 9, w);
    hol__leg_descend(nav, L->r2.idx, (L->r2.facing + u / 9) & 3, u % 9, s2 / 9, s2 % 9, w);
}

/* The dynamic program over key subsets x room states on the keys with the
 * legs above. *out_proved: every leg within the trusted radii (keys within
 * the leg table's trusted radius of each other and of the start, the chest
 * within the main table's of every key), so the tour is the optimum;
 * otherwise it is a valid tour, an upper bound. HOL_ERANGE when some tiles
 * lie too far apart even for the midway legs. */
static hol_err hol__tour_dp(hol_nav *nav, const hol_room *start, const hol__tour *t,
                            hol__walk *w, hol_nav_result *res, int *out_proved)
{
    int nk = t->nkeys, proved = 1;
    hol_nav_prepare_tours(nav);
    /* the table lives in the arena (nodes are not used by this path) */
    hol__dp *dp = (hol__dp *)nav->nodes;
    nav->hash_dirty = 1; /* the nodes no longer match the hash */
    for (int k = 0; k < nk; k++) {
        if (!hol__legm_fill(nav, start->tile, t->keys[k], &dp->leg[nk][k]) ||
            !hol__chestv_fill(nav, t->keys[k], t->chest, &dp->chest[k]))
            return HOL_ERANGE;
        proved &= hol_tile_dist(start->tile, t->keys[k]) <= nav->leg_trust &&
                  hol_tile_dist(t->keys[k], t->chest) <= nav->trust;
        for (int j = 0; j < nk; j++)
            if (j != k) {
                if (!hol__legm_fill(nav, t->keys[j], t->keys[k], &dp->leg[j][k]))
                    return HOL_ERANGE;
                proved &= hol_tile_dist(t->keys[j], t->keys[k]) <= nav->leg_trust;
            }
    }
    memset(dp->cost, 0xff, sizeof dp->cost);
    int ss = 9 * start->orient + start->col + 3 * start->row;
    for (int k = 0; k < nk; k++)
        for (int s = 0; s < 36; s++) {
            int v = dp->leg[nk][k].c[ss][s];
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
                    const uint8_t *row = dp->leg[j][k].c[s];
                    for (int s2 = 0; s2 < 36; s2++) {
                        int v = row[s2];
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
            int v = dp->chest[j].c[s];
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
        if (i == n - 1)
            hol__legm_walk(nav, &dp->leg[nk][oj[i]], ss, os[i], w);
        else
            hol__legm_walk(nav, &dp->leg[oj[i + 1]][oj[i]], os[i + 1], os[i], w);
    }
    const hol__chestv *C = &dp->chest[bj];
    if (!C->mid) {
        hol__nav_descend(&nav->tab, C->r1.idx, (C->r1.facing + bs / 9) & 3, bs % 9, w);
    } else {
        int u = C->via[bs];
        hol__leg_descend(nav, C->r1.idx, (C->r1.facing + bs / 9) & 3, bs % 9, u / 9, u % 9, w);
        hol__nav_descend(&nav->tab, C->r2.idx, (C->r2.facing + u / 9) & 3, u % 9, w);
    }
    if (w->overflow)
        return HOL_ENOMEM;
    if ((int)w->n != best)
        return HOL_ERANGE; /* a leg could not be walked as costed (does not happen) */
    res->exact = proved;
    res->nodes = 0;
    *out_proved = proved;
    return HOL_OK;
}

size_t hol__nav_tour_scratch(void)
{
    size_t far = sizeof(uint8_t[HOL__NK][HOL__NK][36][36]) + HOL__SPHERE_MAX * (2 * 36 + 2);
    return sizeof(hol__dp) > far ? sizeof(hol__dp) : far;
}

hol_err hol_nav_tour(hol_nav *nav, const hol_room *start, const hol_tile *keys,
                     int nkeys, hol_tile chest, size_t budget,
                     uint8_t *out_walk, size_t cap, hol_nav_result *out_result)
{
    if (!nav || !hol__nav_room_ok(start) || !out_walk || !out_result ||
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
    /* The program's tour: the optimum when every leg lies within the
     * trusted radii; otherwise a valid tour whose length bounds the A*
     * below (if the A* runs dry below it, this walk is the optimum). */
    int proved = 0, ub = INT32_MAX;
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
    hol__tour_suf(nav, &t);

    hol__nav_reset(nav);
    hol__node root;
    memset(&root, 0, sizeof root);
    root.u.t = start->tile;
    root.o = start->orient;
    root.cell = (uint8_t)(start->col + 3 * start->row);
    root.flags = (uint8_t)hol__keys_on(&t, start->tile);
    root.parent = HOL__NIL;
    int h = hol__tour_h(nav, &t, &root), isnew;
    root.f = (uint16_t)(h < HOL__FMAX ? h : HOL__FMAX - 1);
    uint32_t id = hol__nav_intern(nav, &root, &isnew);
    hol__nav_push(nav, id);
    uint32_t goal = HOL__NIL;
    size_t expanded = 0;
    int full_arena = 0, dry = 0;
    for (;;) {
        if (expanded >= budget || full_arena)
            break;
        if ((id = hol__nav_pop(nav)) == HOL__NIL) {
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
            int c2 = hol__nav_cell_step(cur.cell, d), arr;
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
            uint32_t nid = hol__nav_relax(nav, &nx, id, d, g, &full_arena);
            if (full_arena)
                break;
            if (nid == HOL__NIL)
                continue;
            hol__node *q = &nav->nodes[nid];
            int f = g + hol__tour_h(nav, &t, q);
            q->f = (uint16_t)(f < HOL__FMAX ? f : HOL__FMAX - 1);
            if (f >= ub)
                continue; /* cannot beat the upper bound */
            if (!hol__nav_push(nav, nid)) {
                full_arena = 1;
                break;
            }
        }
    }
    res.nodes = expanded;
    hol_err err = HOL_OK;
    if (goal != HOL__NIL) {
        w.n = 0;
        hol__nav_emit_path(nav, goal, &w);
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
