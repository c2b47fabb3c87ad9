/* hol_nav_legs.c - the legs of a keys-and-chest tour: for every room state
 * on a source tile and every room state on a key (or the chest's tile), a
 * lower bound on the fewest steps and a valid walk (contract in
 * hol_nav_impl.h, hol__legb_*, hol__chestb_*).
 *
 * Within the leg table's trusted radius rho (7) a leg is exact: the table.
 * Farther, through the sphere S of radius rho around the key:
 * - every walk from a tile farther than rho to a room state s2 on key b is
 *   last at distance rho from b on some tile x of S, in some room state m,
 *   and stays inside the sphere afterwards, so it costs at least
 *   D(s, m) + leg(m, s2), the second term exact from the leg table;
 * - every walk from a room state s on key a to a tile farther than rho
 *   first reaches distance rho from a on some x of S (a's sphere), so it
 *   costs at least leg(s, m) + D(m, target).
 * D(s, m) is the leg table's exact cost when x lies within rho of the
 * other end; otherwise the main table's cost to x's tile (any room state)
 * bounds it from below, and the leg table within its radius gives a walk.
 * The least over x and m is then both the lower bound and, where every
 * term was exact, a walk of that cost: the leg is exact. Tiles x go in
 * order of a cheap bound, until it reaches every entry found.
 */
#include <string.h>

#include "hol_nav_impl.h"

int hol__rel_of(const hol_nav *nav, hol_tile from, hol_tile to, int trust, hol__rel *out)
{
    return hol__rel_ranked(nav, from, to, out) <= trust; /* trust <= the radius */
}

static int hol__leg_at(const hol_nav *nav, const hol__rel *r, int s, int s2)
{
    int nc = nav->tab.ncell;
    return hol_navtab_leg(&nav->tab, nav->leg, r->idx, (r->facing + s / nc) & 3, s % nc,
                          s2 / nc, s2 % nc);
}

/* Main table: steps from room state s on the source of r to stand on its
 * destination tile. */
static int hol__cost_at(const hol_nav *nav, const hol__rel *r, int s)
{
    int nc = nav->tab.ncell;
    return hol_navtab_cost(&nav->tab, r->idx, (r->facing + s / nc) & 3, s % nc);
}

/* A lower bound on the steps from a tile at distance d of a target (any
 * room state) to stand on it, beyond the main table's radius: leaving the
 * table's ball (hol_navtab_exit_bound). */
static int hol__crude(const hol_nav *nav, int d)
{
    return hol_navtab_exit_bound(&nav->tab, d);
}

/* The same from room state s on the source of r (ranked when d is within
 * the table's radius): exact within the trusted radius; between it and
 * the radius a walk stays in the ball (the table's cost) or leaves it. */
int hol__lb_rel(const hol_nav *nav, const hol__rel *r, int d, int s)
{
    if (d > nav->tab.radius)
        return hol__crude(nav, d);
    int v = hol__cost_at(nav, r, s);
    if (d <= nav->trust)
        return v;
    int e = hol_navtab_exit_bound(&nav->tab, d);
    return v < e ? v : e;
}

int hol__rel_ranked(const hol_nav *nav, hol_tile from, hol_tile to, hol__rel *out)
{
    hol_tile u;
    out->idx = 0;
    out->facing = 0;
    if (hol_tile_relative(to, 0, from, &u, &out->facing))
        return HOL_TILE_MAX_DIST + 1;
    int d = hol_tile_dist0(u);
    if (d <= nav->tab.radius)
        out->idx = hol_navtab_rank(&nav->tab, u);
    return d;
}

int hol__lb_state(const hol_nav *nav, hol_tile tile, int o, int cell, hol_tile target)
{
    hol__rel r;
    int d = hol__rel_ranked(nav, tile, target, &r);
    return hol__lb_rel(nav, &r, d, nav->tab.ncell * o + cell);
}

void hol__sph_fill(const hol_nav *nav, hol_tile key, hol__sph *S)
{
    int rho = nav->leg_trust;
    S->n = 0;
    if (rho < 1 || !nav->leg_ready)
        return;
    uint32_t lo = nav->tab.off[rho], n = nav->tab.off[rho + 1] - lo;
    if (n > HOL__SPHERE_MAX)
        return;
    for (uint32_t x = 0; x < n; x++) {
        /* x's tile: its address seen from the key, walked from the key */
        hol_tile u = hol_navtab_unrank(&nav->tab, lo + x);
        hol_heading_tile f = {key, 0};
        for (int i = 0; i < rho; i++)
            if (hol_heading_tile_step(f, hol_tile_letter(u, i), &f))
                return; /* beyond reach: no sphere, S->n = 0 */
        if (!hol__rel_of(nav, f.tile, key, rho, &S->from_key[x]) ||
            S->from_key[x].idx != lo + x)
            return;
        S->tile[x] = f.tile;
    }
    S->n = n;
}

const hol__sph *hol__sph_get(hol_nav *nav, hol_tile key)
{
    int slot = 0;
    for (int i = 0; i < HOL__SPH_CACHE; i++) {
        if (nav->sph_stamp[i] && hol_tile_eq(nav->sph_tile[i], key)) {
            nav->sph_stamp[i] = ++nav->sph_clock;
            return &nav->sph[i];
        }
        if (nav->sph_stamp[i] < nav->sph_stamp[slot])
            slot = i;
    }
    hol__sph_fill(nav, key, &nav->sph[slot]);
    nav->sph_tile[slot] = key;
    nav->sph_stamp[slot] = ++nav->sph_clock;
    return &nav->sph[slot];
}

/* Least leg from any room state on each tile of the sphere at the leg
 * table's trusted radius (relative index off[rho] + x) to each goal state
 * s2: the same for every destination, as the leg table is relative. */
void hol__far_e_fill(hol_nav *nav)
{
    int rho = nav->leg_trust;
    uint32_t lo = nav->tab.off[rho], n = nav->tab.off[rho + 1] - lo;
    int nst = nav->tab.nst, nc = nav->tab.ncell;
    if (n > HOL__SPHERE_MAX)
        return; /* no spheres either (hol__sph_fill) */
    for (uint32_t x = 0; x < n; x++)
        for (int s2 = 0; s2 < nst; s2++) {
            int m = 255;
            for (int o = 0; o < 4; o++)
                for (int cell = 0; cell < nc; cell++) {
                    int v = hol_navtab_leg(&nav->tab, nav->leg, lo + x, o, cell, s2 / nc, s2 % nc);
                    if (v < m)
                        m = v;
                }
            nav->far_e[(size_t)x * (size_t)nst + (size_t)s2] = (uint8_t)m;
        }
}

/* Tiles of the sphere by cheap bound, ascending (counting sort). */
static void hol__by_key(const uint16_t *key, uint32_t n, uint16_t *order)
{
    uint32_t cnt[HOL__KEY_MAX + 1], acc = 0;
    memset(cnt, 0, sizeof cnt);
    for (uint32_t x = 0; x < n; x++)
        cnt[key[x]]++;
    for (int k = 0; k <= HOL__KEY_MAX; k++) {
        uint32_t c = cnt[k];
        cnt[k] = acc;
        acc += c;
    }
    for (uint32_t x = 0; x < n; x++)
        order[cnt[key[x]]++] = (uint16_t)x;
}

static uint16_t hol__key(int v)
{
    return (uint16_t)(v < HOL__KEY_MAX ? v : HOL__KEY_MAX);
}

/* Upper bounds through the tile midway along a geodesic, where nothing
 * else gave a walk (tiles farther apart than the sphere reaches). */
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

static void hol__legb_midway(const hol_nav *nav, hol_tile a, hol_tile b, const int *src,
                             int nsrc, hol__legb *L)
{
    hol__rel r1, r2;
    int nst = nav->tab.nst;
    if (!hol__midway(a, b, &L->mid) || !hol__rel_of(nav, a, L->mid, nav->leg_radius, &r1) ||
        !hol__rel_of(nav, L->mid, b, nav->leg_radius, &r2))
        return;
    for (int i = 0; i < nsrc; i++) {
        int s = src[i];
        for (int m = 0; m < nst; m++) {
            int p = hol__leg_at(nav, &r1, s, m);
            if (p == 255)
                continue;
            for (int s2 = 0; s2 < nst; s2++) {
                int v = p + hol__leg_at(nav, &r2, m, s2);
                size_t x = HOL__LX(L, s, s2);
                if (v < L->ub[x]) {
                    L->ub[x] = (uint8_t)v;
                    L->vx[x] = HOL__VIA_MID;
                    L->vm[x] = (uint8_t)m;
                }
            }
        }
    }
}

/* Half the room states cannot reach the other half: with p(T) one bit per
 * tile, (col + row + o + p(T)) mod 2 never changes (nav->par holds
 * (col + row + o) mod 2). (A step flips the cell's colour and changes o by
 * the arrival edge's index minus the departure edge's, so p must change
 * by 1 + arr - dep mod 2 across each edge; around a vertex of the tiling,
 * Q tiles each entered and left through adjacent edges, those changes add
 * up to an even number, and the plane being simply connected, p exists.)
 * So one walk from s0 to s2_0 tells which pairs (s, s2) can be joined at
 * all: lower bounds of the others are 255 (never). */

/* par(s) ^ par(s2) of the pairs a walk can join, from a walk found; -1:
 * none found yet. */
static int hol__class(const hol_nav *nav, const hol__legb *L, const int *src, int nsrc)
{
    for (int i = 0; i < nsrc; i++)
        for (int s2 = 0; s2 < L->nst; s2++)
            if (L->ub[HOL__LX(L, src[i], s2)] != 255)
                return nav->par[src[i]] ^ nav->par[s2];
    return -1;
}

static void hol__unreachable(const hol_nav *nav, hol__legb *L, const int *src, int nsrc)
{
    int want = hol__class(nav, L, src, nsrc);
    if (want < 0)
        return;
    for (int i = 0; i < nsrc; i++)
        for (int s2 = 0; s2 < L->nst; s2++)
            if ((nav->par[src[i]] ^ nav->par[s2]) != want)
                L->lb[HOL__LX(L, src[i], s2)] = 255;
}

/* Steps reverse, so a leg costs at least each end's cost to the other
 * end's tile (main table): raise the lower bounds to that. */
static void hol__lb_ends(const hol_nav *nav, hol_tile a, hol_tile b, const int *src, int nsrc,
                         hol__legb *L)
{
    int ca[HOL__MAXST], cb[HOL__MAXST], nst = nav->tab.nst, nc = nav->tab.ncell;
    for (int s = 0; s < nst; s++) {
        ca[s] = hol__lb_state(nav, a, s / nc, s % nc, b);
        cb[s] = hol__lb_state(nav, b, s / nc, s % nc, a);
    }
    for (int i = 0; i < nsrc; i++) {
        uint8_t *lb = &L->lb[HOL__LX(L, src[i], 0)];
        for (int s2 = 0; s2 < nst; s2++) {
            int v = ca[src[i]] > cb[s2] ? ca[src[i]] : cb[s2];
            if (v > lb[s2])
                lb[s2] = (uint8_t)(v < 255 ? v : 255);
        }
    }
}

/* A leg without a sphere (or within the leg table): the leg table where
 * it reaches, else bounds from the ends and walks through a midway tile.
 * Returns 1 when that is the whole leg. */
static int hol__legb_near(const hol_nav *nav, hol_tile a, hol_tile b, const hol__sph *sb,
                          const int *src, int nsrc, hol__legb *L)
{
    int nst = nav->tab.nst;
    hol__rel r;
    if (hol__rel_of(nav, a, b, nav->leg_radius, &r)) {
        for (int i = 0; i < nsrc; i++)
            for (int s2 = 0; s2 < nst; s2++) {
                size_t x = HOL__LX(L, src[i], s2);
                L->ub[x] = (uint8_t)hol__leg_at(nav, &r, src[i], s2);
                L->vx[x] = HOL__VIA_DIRECT;
            }
        if (hol_tile_dist(a, b) <= nav->leg_trust) {
            memcpy(L->lb, L->ub, (size_t)nst * (size_t)nst);
            return 1;
        }
    }
    if (sb->n)
        return 0;
    for (int i = 0; i < nsrc; i++)
        memset(&L->lb[HOL__LX(L, src[i], 0)], 0, (size_t)nst);
    hol__lb_ends(nav, a, b, src, nsrc, L);
    hol__legb_midway(nav, a, b, src, nsrc, L);
    hol__unreachable(nav, L, src, nsrc);
    return 1;
}

/* The cheap bound of each sphere tile x around key b (scr->key[x]): the
 * least main-table cost from a source state on a to x's tile plus the
 * least leg from x to the key; then the tiles in its order. */
static void hol__legb_keys(const hol_nav *nav, hol_tile a, const hol__sph *sb, const int *src,
                           int nsrc, hol__legscr *scr)
{
    int nst = nav->tab.nst;
    uint32_t lo = nav->tab.off[nav->leg_trust];
    for (uint32_t x = 0; x < sb->n; x++) {
        hol__legx *X = &scr->x[x];
        X->d = (uint8_t)hol__rel_ranked(nav, a, sb->tile[x], &X->r);
        int c1 = 255, e2 = 255;
        for (int i = 0; i < nsrc; i++) {
            int s = src[i];
            int v = hol__lb_rel(nav, &X->r, X->d, s);
            X->c1[s] = (uint8_t)(v < 255 ? v : 255);
            if (X->c1[s] < c1)
                c1 = X->c1[s];
        }
        const uint8_t *ex = nav->far_e + (size_t)(sb->from_key[x].idx - lo) * (size_t)nst;
        for (int s2 = 0; s2 < nst; s2++)
            if (ex[s2] < e2)
                e2 = ex[s2];
        scr->key[x] = hol__key(c1 + e2);
    }
    hol__by_key(scr->key, sb->n, scr->order);
}

/* The finite legs from each state m on sphere tile x to the key: p2[m][i]
 * the leg to state z2[m][i], nz[m] of them (in the scratch). */
typedef struct hol__fanbuf hol__fan;

static void hol__fan_fill(const hol_nav *nav, const hol__rel *from_key, hol__fan *F)
{
    int nst = nav->tab.nst;
    for (int m = 0; m < nst; m++) {
        F->nz[m] = 0;
        for (int s2 = 0; s2 < nst; s2++) {
            int v = hol__leg_at(nav, from_key, m, s2);
            if (v != 255) {
                F->z2[m][F->nz[m]] = (uint8_t)s2;
                F->p2[m][F->nz[m]++] = (uint8_t)v;
            }
        }
    }
}

/* One sphere tile x of the pass: what the legs through it add to the
 * source row s (bounds, and walks where x is in the leg table's reach). */
typedef struct hol__via {
    const hol__legx *X;
    const uint8_t *ex; /* far_e of x */
    const hol__fan *F;
    const uint8_t *c2; /* main-table cost from each state on x back to a */
    int exact, walk, coupled, want;
    uint32_t x;
} hol__via;

static void hol__via_row(const hol_nav *nav, const hol__via *V, int s, hol__legb *L)
{
    int nst = nav->tab.nst;
    const hol__legx *X = V->X;
    uint8_t *lb = &L->lb[HOL__LX(L, s, 0)], *ub = &L->ub[HOL__LX(L, s, 0)];
    if (V->coupled) {
        for (int m = 0; m < nst; m++) {
            if (V->want >= 0 && (nav->par[s] ^ nav->par[m]) != V->want)
                continue;
            int base = X->c1[s] > V->c2[m] ? X->c1[s] : V->c2[m];
            for (int i2 = 0; i2 < V->F->nz[m]; i2++) {
                int s2 = V->F->z2[m][i2], v = base + V->F->p2[m][i2];
                if (v < lb[s2])
                    lb[s2] = (uint8_t)v;
            }
        }
    } else if (!V->exact) {
        for (int s2 = 0; s2 < nst; s2++) {
            int v = X->c1[s] + V->ex[s2];
            if (v < lb[s2])
                lb[s2] = (uint8_t)v;
        }
    }
    if (!V->walk)
        return;
    for (int m = 0; m < nst; m++) {
        int p = hol__leg_at(nav, &X->r, s, m);
        if (p == 255)
            continue;
        for (int i2 = 0; i2 < V->F->nz[m]; i2++) {
            int s2 = V->F->z2[m][i2], v = p + V->F->p2[m][i2];
            if (v < ub[s2]) {
                ub[s2] = (uint8_t)v;
                L->vx[HOL__LX(L, s, s2)] = (uint16_t)V->x;
                L->vm[HOL__LX(L, s, s2)] = (uint8_t)m;
            }
            if (V->exact && v < lb[s2])
                lb[s2] = (uint8_t)v;
        }
    }
}

/* The greatest lower bound of the leg still open (the pass stops when the
 * next tile's cheap bound reaches it); pairs no walk can join (the parity
 * classes) do not hold the pass up. */
static int hol__legb_worst(const hol_nav *nav, const hol__legb *L, const int *src, int nsrc,
                           int cls)
{
    int worst = 0;
    for (int k = 0; k < nsrc; k++)
        for (int s2 = 0; s2 < L->nst; s2++) {
            int v = L->lb[HOL__LX(L, src[k], s2)];
            if (v > worst && (cls < 0 || (nav->par[src[k]] ^ nav->par[s2]) == cls))
                worst = v;
        }
    return worst;
}

void hol__legb_fill(const hol_nav *nav, hol_tile a, hol_tile b, const hol__sph *sb,
                    const int *src, int nsrc, hol__legb *L, hol__legscr *scr)
{
    int rho = nav->leg_trust, nst = nav->tab.nst;
    L->nst = nst;
    memset(L->ub, 255, (size_t)nst * (size_t)nst);
    memset(L->lb, 255, (size_t)nst * (size_t)nst);
    L->vt = sb->tile;
    if (hol__legb_near(nav, a, b, sb, src, nsrc, L))
        return;
    hol__legb_keys(nav, a, sb, src, nsrc, scr);
    uint32_t lo = nav->tab.off[rho];
    int worst = 255, cls = hol__class(nav, L, src, nsrc);
    for (uint32_t i = 0; i < sb->n; i++) {
        uint32_t x = scr->order[i];
        if (scr->key[x] >= worst)
            break;
        hol__via V = {&scr->x[x], nav->far_e + (size_t)(sb->from_key[x].idx - lo) * (size_t)nst,
                      &scr->fan, scr->c2, 0, 0, 0, -1, x};
        V.exact = V.X->d <= rho;
        V.walk = V.X->d <= nav->leg_radius;
        /* coupled: D(s, m) >= max(main(s to x), main(m to a)), as steps
         * reverse; m only in s's class (hol__unreachable) when a walk from
         * a to x tells it */
        V.coupled = !V.exact && V.X->d <= nav->trust;
        if (V.walk || V.coupled)
            hol__fan_fill(nav, &sb->from_key[x], &scr->fan);
        if (V.coupled) {
            hol__rel back;
            if (hol__rel_of(nav, sb->tile[x], a, nav->trust, &back))
                for (int m = 0; m < nst; m++)
                    scr->c2[m] = (uint8_t)hol__cost_at(nav, &back, m);
            else
                V.coupled = 0;
            for (int m = 0; m < nst && V.walk && V.want < 0; m++)
                if (hol__leg_at(nav, &V.X->r, src[0], m) != 255)
                    V.want = nav->par[src[0]] ^ nav->par[m];
        }
        for (int k = 0; k < nsrc; k++)
            hol__via_row(nav, &V, src[k], L);
        if (cls < 0)
            cls = hol__class(nav, L, src, nsrc);
        worst = hol__legb_worst(nav, L, src, nsrc, cls);
    }
    hol__lb_ends(nav, a, b, src, nsrc, L);
    hol__unreachable(nav, L, src, nsrc);
    int missing = 0;
    for (int k = 0; k < nsrc; k++)
        for (int s2 = 0; s2 < nst; s2++)
            missing |= L->ub[HOL__LX(L, src[k], s2)] == 255 && L->lb[HOL__LX(L, src[k], s2)] != 255;
    if (missing) {
        hol__legb_midway(nav, a, b, src, nsrc, L);
        hol__unreachable(nav, L, src, nsrc);
    }
}

/* Where no walk was found: through the tile midway (leg, then the main
 * table). */
static void hol__chestb_midway(const hol_nav *nav, hol_tile a, hol_tile chest,
                               hol__chestb *C)
{
    int missing = 0, nst = nav->tab.nst;
    for (int s = 0; s < nst; s++)
        missing |= C->ub[s] == 255;
    hol__rel r1, r2;
    if (!missing || !hol__midway(a, chest, &C->mid) ||
        !hol__rel_of(nav, a, C->mid, nav->leg_radius, &r1) ||
        !hol__rel_of(nav, C->mid, chest, nav->tab.radius, &r2))
        return;
    for (int s = 0; s < nst; s++)
        for (int m = 0; m < nst; m++) {
            int v = hol__leg_at(nav, &r1, s, m) + hol__cost_at(nav, &r2, m);
            if (v < C->ub[s]) {
                C->ub[s] = (uint8_t)v;
                C->vx[s] = HOL__VIA_MID;
                C->vm[s] = (uint8_t)m;
            }
        }
}

/* The first exit from a's sphere: the cheap bound of each tile x (the
 * least leg from a to x plus the least cost from x to the chest), then
 * the tiles in its order. */
static void hol__chestb_keys(const hol_nav *nav, hol_tile chest, const hol__sph *sa,
                             hol__legscr *scr)
{
    int nst = nav->tab.nst;
    uint32_t lo = nav->tab.off[nav->leg_trust];
    for (uint32_t x = 0; x < sa->n; x++) {
        hol__legx *X = &scr->x[x];
        int l2 = 255, e1 = 255;
        X->d = (uint8_t)hol__rel_ranked(nav, sa->tile[x], chest, &X->r);
        for (int m = 0; m < nst; m++) {
            int lv = hol__lb_rel(nav, &X->r, X->d, m), uv = 255;
            if (X->d <= nav->tab.radius)
                uv = hol__cost_at(nav, &X->r, m);
            X->c1[m] = (uint8_t)(lv < 255 ? lv : 255);
            X->u2[m] = (uint8_t)(uv < 255 ? uv : 255);
            if (X->c1[m] < l2)
                l2 = X->c1[m];
        }
        const uint8_t *ex = nav->far_e + (size_t)(sa->from_key[x].idx - lo) * (size_t)nst;
        for (int s = 0; s < nst; s++)
            if (ex[s] < e1)
                e1 = ex[s];
        scr->key[x] = hol__key(e1 + l2);
    }
    hol__by_key(scr->key, sa->n, scr->order);
}

void hol__chestb_fill(const hol_nav *nav, hol_tile a, hol_tile chest, const hol__sph *sa,
                      hol__chestb *C, hol__legscr *scr)
{
    int nst = nav->tab.nst, nc = nav->tab.ncell;
    memset(C->ub, 255, sizeof C->ub);
    memset(C->lb, 255, sizeof C->lb);
    C->vt = sa->tile;
    hol__rel r;
    int d = hol_tile_dist(a, chest);
    if (hol__rel_of(nav, a, chest, nav->tab.radius, &r)) {
        for (int s = 0; s < nst; s++) {
            C->ub[s] = (uint8_t)hol__cost_at(nav, &r, s);
            C->vx[s] = HOL__VIA_DIRECT;
        }
        if (d <= nav->trust) {
            memcpy(C->lb, C->ub, sizeof C->lb);
            return;
        }
    }
    if (sa->n == 0 || d <= nav->leg_trust) {
        for (int s = 0; s < nst; s++) {
            int v = hol__lb_state(nav, a, s / nc, s % nc, chest);
            C->lb[s] = (uint8_t)(v < 255 ? v : 255);
        }
        hol__chestb_midway(nav, a, chest, C);
        return;
    }
    hol__chestb_keys(nav, chest, sa, scr);
    int worst = 255;
    for (uint32_t i = 0; i < sa->n; i++) {
        uint32_t x = scr->order[i];
        if (scr->key[x] >= worst)
            break;
        const hol__legx *X = &scr->x[x];
        for (int s = 0; s < nst; s++)
            for (int m = 0; m < nst; m++) {
                /* steps reverse: the leg from s on a to m on x is the leg
                 * from m on x to s on a */
                int p = hol__leg_at(nav, &sa->from_key[x], m, s);
                if (p == 255)
                    continue;
                if (p + X->c1[m] < C->lb[s])
                    C->lb[s] = (uint8_t)(p + X->c1[m]);
                if (p + X->u2[m] < C->ub[s]) {
                    C->ub[s] = (uint8_t)(p + X->u2[m]);
                    C->vx[s] = (uint16_t)x;
                    C->vm[s] = (uint8_t)m;
                }
            }
        worst = 0;
        for (int s = 0; s < nst; s++)
            if (C->lb[s] > worst)
                worst = C->lb[s];
    }
    hol__chestb_midway(nav, a, chest, C);
}

void hol__legb_reverse(const hol__legb *L, hol__legb *out_rev)
{
    out_rev->nst = L->nst;
    for (int s = 0; s < L->nst; s++)
        for (int s2 = 0; s2 < L->nst; s2++) {
            size_t x = HOL__LX(L, s, s2), y = HOL__LX(L, s2, s);
            out_rev->ub[y] = L->ub[x];
            out_rev->lb[y] = L->lb[x];
            out_rev->vx[y] = L->vx[x];
            out_rev->vm[y] = L->vm[x];
        }
    out_rev->vt = L->vt;
    out_rev->mid = L->mid;
}

/* Descend the leg table from (idx, o, cell) to the goal state (ob, cb). */
typedef struct hol__leg_goal {
    const hol_navtab *tab;
    const uint8_t *leg;
    int ob, cb;
} hol__leg_goal;

static int hol__leg_cost(const void *ctx, uint32_t idx, int o, int cell)
{
    const hol__leg_goal *g = ctx;
    return hol_navtab_leg(g->tab, g->leg, idx, o, cell, g->ob, g->cb);
}

static void hol__leg_descend(const hol_nav *nav, uint32_t idx, int o, int cell, int ob,
                             int cb, hol__walk *w)
{
    hol__leg_goal g = {&nav->tab, nav->leg, ob, cb};
    hol__descend(&nav->tab, nav->tab.off[nav->leg_radius + 1], hol__leg_cost, &g, idx, o,
                 cell, w);
}

/* The leg table's walk from room state s on tile a to s2 on tile b. */
static void hol__leg_walk(const hol_nav *nav, hol_tile a, int s, hol_tile b, int s2,
                          hol__walk *w)
{
    hol__rel r;
    int nc = nav->tab.ncell;
    if (!hol__rel_of(nav, a, b, nav->leg_radius, &r))
        return; /* cannot happen: the leg was costed this way (the caller
                 * checks the walk's length against its cost) */
    hol__leg_descend(nav, r.idx, (r.facing + s / nc) & 3, s % nc, s2 / nc, s2 % nc, w);
}

void hol__legb_walk(const hol_nav *nav, const hol__legb *L, hol_tile a, int s, hol_tile b,
                    int s2, hol__walk *w)
{
    unsigned vx = L->vx[HOL__LX(L, s, s2)];
    if (vx == HOL__VIA_DIRECT) {
        hol__leg_walk(nav, a, s, b, s2, w);
        return;
    }
    hol_tile x = vx == HOL__VIA_MID ? L->mid : L->vt[vx];
    hol__leg_walk(nav, a, s, x, L->vm[HOL__LX(L, s, s2)], w);
    hol__leg_walk(nav, x, L->vm[HOL__LX(L, s, s2)], b, s2, w);
}

void hol__chestb_walk(const hol_nav *nav, const hol__chestb *C, hol_tile a, int s,
                      hol_tile chest, hol__walk *w)
{
    hol_tile from = a;
    hol__rel r;
    int nc = nav->tab.ncell;
    if (C->vx[s] != HOL__VIA_DIRECT) {
        from = C->vx[s] == HOL__VIA_MID ? C->mid : C->vt[C->vx[s]];
        hol__leg_walk(nav, a, s, from, C->vm[s], w);
        s = C->vm[s];
    }
    if (!hol__rel_of(nav, from, chest, nav->tab.radius, &r))
        return; /* as above */
    hol__nav_descend(&nav->tab, r.idx, (r.facing + s / nc) & 3, s % nc, w);
}
