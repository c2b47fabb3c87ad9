/* hol_nav_table.c - dense tile numbering and the exact cost table.
 *
 * Why the table is exact
 * ----------------------
 * The tiling is homogeneous, so the fewest room steps from a room state to
 * a target depend only on where the user stands as seen from the target:
 * the user's tile U in the target's frame, the room's north o as a turn
 * relative to U's heading, and the cell. A room step in direction d moves U
 * to its neighbour across the edge in turn o + d and carries o along, so the
 * costs are breadth-first distances from the goal set {U = O} in the graph
 * of these relative states. Steps are reversible (step d then d + 2 returns
 * to the same state), so that BFS runs forward from the goal. Rotating the
 * whole room by a quarter turn maps walks to walks, so only o = 0 is stored
 * and other orientations rotate the cell (an oblong room only turns by a
 * half: o = 0 and 1 are stored, 2 and 3 turn the room a half).
 *
 * The BFS is truncated to tiles within the radius R, which gives the fewest
 * steps among walks that stay inside, an upper bound on the truth. A walk
 * that leaves the ball: let E be the least true cost of a state outside.
 * Follow an optimal walk from such a state to its last entry into the
 * ball, at a state S at distance R; from S on it stays inside, so the true
 * cost of S equals its table cost, which is at least m = min table cost at
 * distance R. Hence E >= m + 1. A walk from distance d that leaves needs
 * at least R + 1 - d steps to get out, so it costs at least
 * R + 2 - d + m (hol_navtab_exit_bound). Where the table cost does not
 * exceed that bound it is exact; everywhere min(table, bound) is an
 * admissible and consistent heuristic (both change by at most one a step).
 *
 * That bound proves the costs only to distance 7 at radius 14
 * (proved_radius): the least cost at the radius (about 1.5 steps a tile,
 * walking straight) is far below the typical cost (about 3 a tile). The
 * navigator therefore trusts the table to radius - 2: for every radius
 * 4..14 the table of radius r + 1 (and r + 2 where checked) gives the same
 * costs within r - 2 and differs only at r - 1 and r, so no optimal walk
 * gains by straying more than two tiles beyond its start's distance; the
 * tests repeat that check and match the answers against brute-force BFS;
 * the radius-14 table also equals a radius-17 one (5.6 million tiles) to
 * distance 12 (NAV_BENCH_VERIFY=1 make bench). This is evidence, not a
 * proof, beyond proved_radius. Every tiling and room size has its own
 * table by the same rules; tests/test_nav.c repeats the r against r + 1
 * check for each, and hol_nav.c says which radius each gets.
 */
#include "hol_nav_table.h"

#include <string.h>

static int hol__counts(uint32_t cnt[HOL_TILE_MAX_STATES][HOL_NAVTAB_MAX_RADIUS + 1], int q,
                       int r)
{
    int ns = hol_tile_states(q);
    for (int s = 0; s < ns; s++)
        cnt[s][0] = 1;
    for (int k = 1; k <= r; k++)
        for (int s = 0; s < ns; s++) {
            uint64_t n = 0;
            for (int c = 0; c < 4; c++) {
                int t = hol_tile_automaton_q(q, s, c);
                if (t >= 0)
                    n += cnt[t][k - 1];
            }
            if (n > UINT32_MAX / 8)
                return 0;
            cnt[s][k] = (uint32_t)n;
        }
    return 1;
}

uint32_t hol_navtab_count_q(int q, int radius)
{
    uint32_t cnt[HOL_TILE_MAX_STATES][HOL_NAVTAB_MAX_RADIUS + 1];
    if (radius < 0 || radius > HOL_NAVTAB_MAX_RADIUS || !hol_tile_states(q) ||
        !hol__counts(cnt, q, radius))
        return 0;
    uint64_t n = 1;
    for (int k = 1; k <= radius; k++)
        n += 4 * (uint64_t)cnt[0][k - 1];
    return n > UINT32_MAX / 2 ? 0 : (uint32_t)n;
}

uint32_t hol_navtab_count(int radius) { return hol_navtab_count_q(5, radius); }

size_t hol_navtab_table_bytes(const hol_navtab *tab)
{
    return (size_t)tab->count * (4 * sizeof(uint32_t) + (size_t)tab->per);
}

size_t hol_navtab_scratch_bytes(const hol_navtab *tab)
{
    return (size_t)tab->count * (sizeof(hol_tile) + 1); /* hol__neighbours */
}

int hol_navtab_rot_cell(int o, int cell)
{
    /* (col, row) -> (row, 2 - col): one quarter turn counter-clockwise */
    static const uint8_t rot[4][9] = {
        {0, 1, 2, 3, 4, 5, 6, 7, 8},
        {6, 3, 0, 7, 4, 1, 8, 5, 2},
        {8, 7, 6, 5, 4, 3, 2, 1, 0},
        {2, 5, 8, 1, 4, 7, 0, 3, 6},
    };
    return rot[o & 3][cell];
}

/* The room's tables: cells turned, stored states, steps between cells. */
static void hol__room_tables(hol_navtab *tab)
{
    int C = tab->cols, R = tab->rows, square = C == R;
    static const int8_t dc[4] = {0, -1, 0, 1}, dr[4] = {-1, 0, 1, 0};
    for (int cell = 0; cell < tab->ncell; cell++) {
        int c = cell % C, r = cell / C;
        /* a quarter turn counter-clockwise: (col, row) -> (row, C - 1 - col) */
        tab->rotc[0][cell] = (uint8_t)cell;
        tab->rotc[2][cell] = (uint8_t)((C - 1 - c) + C * (R - 1 - r));
        tab->rotc[1][cell] = (uint8_t)(square ? r + C * (C - 1 - c) : cell);
        tab->rotc[3][cell] = (uint8_t)(square ? (C - 1 - r) + C * c : cell);
        for (int d = 0; d < 4; d++) {
            int c2 = c + dc[d], r2 = r + dr[d];
            tab->cellnb[cell][d] =
                (int8_t)(c2 < 0 || c2 >= C || r2 < 0 || r2 >= R ? -1 : c2 + C * r2);
        }
    }
    for (int o = 0; o < 4; o++) {
        int g = square ? o : o & 2; /* turns that bring o to a stored one */
        tab->turn[o] = (uint8_t)g;
        for (int cell = 0; cell < tab->ncell; cell++)
            tab->rot[o][cell] = (uint8_t)(tab->ncell * ((o - g) & 3) + tab->rotc[g][cell]);
    }
    for (int k = 0; k < tab->per; k++) {
        tab->so[k] = (uint8_t)(k / tab->ncell);
        tab->sc[k] = (uint8_t)(k % tab->ncell);
    }
}

uint32_t hol_navtab_rank(const hol_navtab *tab, hol_tile t)
{
    int n = hol_tile_dist0(t);
    if (n > tab->radius)
        return HOL_NAVTAB_NONE;
    if (n == 0)
        return 0;
    uint32_t r = tab->off[n] + (uint32_t)hol_tile_letter(t, 0) * tab->cnt[0][n - 1];
    int s = 0;
    for (int i = 1; i < n; i++) {
        int c = hol_tile_letter(t, i);
        for (int c2 = 0; c2 < c; c2++)
            if (tab->next[s][c2] >= 0)
                r += tab->cnt[tab->next[s][c2]][n - 1 - i];
        s = tab->next[s][c];
    }
    return r;
}

int hol_navtab_len(const hol_navtab *tab, uint32_t idx)
{
    int n = 0;
    while (n < tab->radius && idx >= tab->off[n + 1])
        n++;
    return n;
}

hol_tile hol_navtab_unrank(const hol_navtab *tab, uint32_t idx)
{
    hol_tile t = hol_tile_origin_q(tab->q);
    int n = hol_navtab_len(tab, idx);
    if (n == 0)
        return t;
    uint32_t r = idx - tab->off[n];
    int b = (int)(r / tab->cnt[0][n - 1]);
    r -= (uint32_t)b * tab->cnt[0][n - 1];
    hol_tile_child(t, b, &t);
    int s = 0;
    for (int i = 1; i < n; i++) {
        int c = 0;
        for (;; c++) {
            if (tab->next[s][c] < 0)
                continue;
            uint32_t k = tab->cnt[tab->next[s][c]][n - 1 - i];
            if (r < k)
                break;
            r -= k;
        }
        hol_tile_child(t, c, &t);
        s = tab->next[s][c];
    }
    return t;
}

hol_err hol_navtab_init(hol_navtab *tab, int q, int cols, int rows, int radius)
{
    hol_room probe;
    if (radius < 0 || radius > HOL_NAVTAB_MAX_RADIUS || hol_room_start_in(q, cols, rows, &probe))
        return HOL_EARG;
    memset(tab, 0, sizeof *tab);
    tab->radius = radius;
    tab->q = hol_tile_q(probe.tile);
    tab->cols = hol_room_cols(&probe);
    tab->rows = hol_room_rows(&probe);
    tab->ncell = tab->cols * tab->rows;
    tab->per = tab->cols == tab->rows ? tab->ncell : 2 * tab->ncell;
    tab->nst = 4 * tab->ncell;
    tab->nstates = hol_tile_states(tab->q);
    for (int st = 0; st < tab->nstates; st++)
        for (int c = 0; c < 4; c++)
            tab->next[st][c] = (int8_t)hol_tile_automaton_q(tab->q, st, c);
    if (!hol__counts(tab->cnt, tab->q, radius))
        return HOL_EARG;
    tab->off[0] = 0;
    tab->off[1] = 1;
    for (int k = 1; k <= radius; k++) {
        if ((uint64_t)tab->off[k] + 4 * (uint64_t)tab->cnt[0][k - 1] > UINT32_MAX / 8)
            return HOL_EARG;
        tab->off[k + 1] = tab->off[k] + 4 * tab->cnt[0][k - 1];
    }
    tab->count = tab->off[radius + 1];
    hol__room_tables(tab);
    return HOL_OK;
}

hol_err hol_navtab_init_index(hol_navtab *tab, int radius)
{
    return hol_navtab_init(tab, 5, 3, 3, radius);
}

/* nb: every tile's neighbours within the radius. The tiles are made in
 * index order from their parents (a tile's children, its canonical
 * extensions, come in letter order, so they are the next indices of the
 * level below): the edges to a child (arriving straight on, arrive 0) and
 * back to the parent cost nothing. Only the other edges (about one a tile)
 * take a hol_tile_step and a rank, and each of those is stepped once: the
 * edge read backwards is the neighbour's edge in turn arrive + 2, arriving
 * in turn + 2. `scratch` holds the tiles and their automaton states
 * (17 bytes a tile: hol_navtab_scratch_bytes).
 *
 * A build by parts makes a tile's neighbours when the BFS first expands
 * one of its states (hol__nb_of: the tile unranked, its unset edges
 * stepped, the same entries), and the rest in index order at the end
 * (hol__nb_upto, which skips the edges already made). A level's entries
 * (nb unset, cost 255) are written before anything can write to them
 * (hol__levels_upto): a tile's edges lead at most one level down. */
#define HOL__NB_UNSET (UINT32_MAX - 1)
static void hol__levels_upto(hol_navtab *tab, int len)
{
    size_t per = (size_t)tab->per;
    len = len > tab->radius ? tab->radius : len;
    for (; tab->init_len < len; tab->init_len++) {
        size_t a = tab->off[tab->init_len + 1], b = tab->off[tab->init_len + 2];
        for (size_t k = 4 * a; k < 4 * b; k++)
            tab->nb[k] = HOL__NB_UNSET;
        memset(tab->cost + per * a, 255, per * (b - a));
    }
}

/* The unset edges of tile i (the tile t), each with its edge read
 * backwards. */
static void hol__nb_edges(hol_navtab *tab, uint32_t i, hol_tile t)
{
    uint32_t *nb = tab->nb + 4 * (size_t)i;
    for (int turn = 0; turn < 4; turn++) {
        if (nb[turn] != HOL__NB_UNSET)
            continue;
        hol_tile u;
        int arr;
        uint32_t j = HOL_NAVTAB_NONE;
        if (!hol_tile_step(t, turn, &u, &arr))
            j = hol_navtab_rank(tab, u);
        nb[turn] = j == HOL_NAVTAB_NONE ? j : (j << 2) | (uint32_t)arr;
        if (j != HOL_NAVTAB_NONE)
            tab->nb[4 * (size_t)j + (size_t)((arr + 2) & 3)] =
                (i << 2) | (uint32_t)((turn + 2) & 3);
    }
}

/* The neighbours of tile i (its children made), i the next tile. */
static void hol__nb_tile(hol_navtab *tab, uint32_t i, int len)
{
    hol_tile *tile = tab->nbt;
    uint8_t *state = tab->nbs;
    uint32_t *nb = tab->nb + 4 * (size_t)i;
    for (int c = 0; c < 4; c++) {
        int s2 = len == 0 ? 0 : tab->next[state[i]][c];
        if (s2 < 0)
            continue;
        if (len == tab->radius) {
            nb[c] = HOL_NAVTAB_NONE;
            continue;
        }
        uint32_t kid = tab->nb_kids++;
        hol_tile_child(tile[i], c, &tile[kid]);
        state[kid] = (uint8_t)s2;
        nb[c] = kid << 2;
        tab->nb[4 * (size_t)kid + HOL_TURN_B] = (i << 2) | (uint32_t)((c + 2) & 3);
    }
    hol__nb_edges(tab, i, tile[i]);
}

/* The neighbours of every tile before `end` (at most count). */
static void hol__nb_upto(hol_navtab *tab, uint32_t end)
{
    if (end > tab->count)
        end = tab->count;
    for (uint32_t i = tab->nb_done; i < end; i++) {
        if (i == tab->off[tab->nb_len + 1])
            tab->nb_len++;
        hol__levels_upto(tab, tab->nb_len + 1);
        hol__nb_tile(tab, i, tab->nb_len);
        tab->nb_done = i + 1;
    }
}

/* The neighbours of tile i, made now if any is missing (its level's
 * entries set first, and the next level's, where its edges write). */
static inline void hol__nb_of(hol_navtab *tab, uint32_t i)
{
    const uint32_t *nb = tab->nb + 4 * (size_t)i;
    if (i < tab->nb_done)
        return;
    if (i >= tab->off[tab->init_len + 1])
        hol__levels_upto(tab, hol_navtab_len(tab, i) + 1);
    if (nb[0] != HOL__NB_UNSET && nb[1] != HOL__NB_UNSET && nb[2] != HOL__NB_UNSET &&
        nb[3] != HOL__NB_UNSET)
        return;
    hol__levels_upto(tab, hol_navtab_len(tab, i) + 1);
    hol__nb_edges(tab, i, hol_navtab_unrank(tab, i));
}

/* The least and mean costs by distance, and how far the bound proves. */
static void hol__certify(hol_navtab *tab)
{
    int m = 255, radius = tab->radius;
    size_t per = (size_t)tab->per;
    for (size_t s = per * tab->off[radius]; s < per * tab->count; s++)
        if (tab->cost[s] < m)
            m = tab->cost[s];
    tab->min_at_radius = m;
    tab->proved_radius = radius;
    for (int k = 0; k <= radius; k++) {
        int bound = hol_navtab_exit_bound(tab, k), mn = 255;
        uint64_t sum = 0, cnt = 0;
        for (size_t s = per * tab->off[k]; s < per * tab->off[k + 1]; s++) {
            int v = tab->cost[s];
            if (v > bound && tab->proved_radius >= k)
                tab->proved_radius = k - 1;
            if (v < mn)
                mn = v;
            if (v < 255) {
                sum += (uint64_t)v;
                cnt++;
            }
        }
        tab->min_at[k] = mn;
        tab->mean16_at[k] = cnt ? (int)(16 * sum / cnt) : 0;
    }
}

/* Expand stored state st (cost v): its unvisited neighbours get v + 1;
 * [*lo, *hi) grows to cover them. */
static inline void hol__expand(hol_navtab *tab, uint32_t st, int v, size_t *lo, size_t *hi)
{
    uint32_t per = (uint32_t)tab->per, i = st / per, k = st - i * per;
    int o = tab->so[k], cell = tab->sc[k];
    hol__nb_of(tab, i);
    for (int d = 0; d < 4; d++) {
        int c2 = tab->cellnb[cell][d];
        if (c2 < 0)
            continue;
        uint32_t e = tab->nb[4 * (size_t)i + (size_t)((o + d) & 3)];
        if (e == HOL_NAVTAB_NONE)
            continue;
        int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
        size_t s2 = (size_t)per * (e >> 2) + tab->rot[o2][c2];
        if (tab->cost[s2] == 255) {
            tab->cost[s2] = (uint8_t)(v + 1);
            if (s2 < *lo)
                *lo = s2;
            if (s2 >= *hi)
                *hi = s2 + 1;
        }
    }
}

/* One level of the BFS from the goal (tile O, every room state) over
 * stored states: the states of cost v are found by scanning the cost
 * array over the span where the level before wrote them (no queue, and
 * the neighbour table is read in order); their tiles' neighbours are made
 * first. 0 when the BFS has ended (no state of cost v). */
static int hol__bfs_level(hol_navtab *tab)
{
    if (tab->bfs_lo >= tab->bfs_hi || tab->bfs_v >= 254)
        return 0;
    uint32_t per = (uint32_t)tab->per;
    int v = tab->bfs_v;
    size_t nlo = per * (size_t)tab->count, nhi = 0;
    const uint8_t *p = tab->cost + tab->bfs_lo, *end = tab->cost + tab->bfs_hi;
    while (p < end && (p = (const uint8_t *)memchr(p, v, (size_t)(end - p))) != NULL) {
        hol__expand(tab, (uint32_t)(p - tab->cost), v, &nlo, &nhi);
        p++;
    }
    tab->bfs_lo = nlo;
    tab->bfs_hi = nhi;
    tab->bfs_v = v + 1;
    return 1;
}

hol_err hol_navtab_begin(hol_navtab *tab, void *mem, void *scratch)
{
    if (tab->radius < 1 || !tab->count)
        return HOL_EARG;
    tab->nb = (uint32_t *)mem;
    tab->cost = (uint8_t *)(tab->nb + 4 * (size_t)tab->count);
    tab->nbt = (hol_tile *)scratch;
    tab->nbs = (uint8_t *)(tab->nbt + tab->count);
    tab->nbt[0] = hol_tile_origin_q(tab->q);
    tab->nbs[0] = 0;
    tab->nb_done = 0;
    tab->nb_kids = 1;
    tab->nb_len = 0;
    for (size_t k = 0; k < 4; k++)
        tab->nb[k] = HOL__NB_UNSET; /* level 0; the others when first reached */
    memset(tab->cost, 0, (size_t)tab->per); /* the goal */
    tab->init_len = 0;
    hol__levels_upto(tab, 1);
    tab->bfs_v = 0;
    tab->bfs_lo = 0;
    tab->bfs_hi = (size_t)tab->per;
    tab->complete = 0;
    return HOL_OK;
}

int hol_navtab_need(hol_navtab *tab, uint32_t idx, int o, int cell)
{
    if (!tab->complete) {
        hol__nb_of(tab, idx); /* the descent's first step */
        while (hol_navtab_cost(tab, idx, o, cell) == 255 && hol__bfs_level(tab))
            ;
    }
    return hol_navtab_cost(tab, idx, o, cell);
}

void hol_navtab_finish(hol_navtab *tab)
{
    if (tab->complete)
        return;
    hol__nb_upto(tab, tab->count); /* in index order: no tile unranked */
    while (hol__bfs_level(tab))
        ;
    hol__certify(tab);
    tab->nbt = NULL; /* the scratch is free */
    tab->nbs = NULL;
    tab->complete = 1;
}

hol_err hol_navtab_build(hol_navtab *tab, void *mem, void *scratch)
{
    hol_err err = hol_navtab_begin(tab, mem, scratch);
    if (!err)
        hol_navtab_finish(tab);
    return err;
}

size_t hol_navtab_leg_bytes(const hol_navtab *tab, int leg_radius)
{
    return (size_t)hol_navtab_count_q(tab->q, leg_radius) * (size_t)tab->per * (size_t)tab->nst;
}

size_t hol_navtab_leg_scratch_bytes(const hol_navtab *tab, int leg_radius)
{
    return (size_t)hol_navtab_count_q(tab->q, leg_radius) * (size_t)tab->nst *
           (sizeof(uint32_t) + 1);
}

/* One BFS per stored goal state (per of the nst): from (O, ob, cb) over
 * full states (tile, o, cell) of the tiles within leg_radius; steps are
 * reversible, so these are the distances to the goal. Turning the whole
 * room (the turns of hol_navtab_cost) maps walks to walks, so the goal G
 * whose stored state is k has the distances of goal k read at the turned
 * states: dist_G(i, s) = dist_k(i, s turned like G). */
static void hol__leg_bfs(const hol_navtab *tab, uint32_t n, uint32_t g, uint32_t *queue,
                         uint8_t *dist)
{
    uint32_t nst = (uint32_t)tab->nst, nc = (uint32_t)tab->ncell;
    memset(dist, 255, nst * (size_t)n);
    size_t head = 0, tail = 0;
    dist[g] = 0; /* tile 0, state g */
    queue[tail++] = g;
    while (head < tail) {
        uint32_t st = queue[head++];
        uint32_t i = st / nst, s = st - i * nst;
        int o = (int)(s / nc), cell = (int)(s % nc), v = dist[st];
        for (int d = 0; d < 4; d++) {
            int c2 = tab->cellnb[cell][d];
            if (c2 < 0)
                continue;
            uint32_t e = tab->nb[4 * (size_t)i + (size_t)((o + d) & 3)];
            if (e == HOL_NAVTAB_NONE || (e >> 2) >= n)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            uint32_t s2 = nst * (e >> 2) + nc * (uint32_t)o2 + (uint32_t)c2;
            if (dist[s2] == 255) {
                dist[s2] = (uint8_t)(v + 1);
                queue[tail++] = s2;
            }
        }
    }
}

hol_err hol_navtab_build_legs(const hol_navtab *tab, int leg_radius, uint8_t *out_leg,
                              void *scratch)
{
    if (leg_radius < 1 || leg_radius > tab->radius)
        return HOL_EARG;
    uint32_t n = hol_navtab_count_q(tab->q, leg_radius), nst = (uint32_t)tab->nst;
    uint32_t nc = (uint32_t)tab->ncell, per = (uint32_t)tab->per;
    uint32_t *queue = (uint32_t *)scratch;
    uint8_t *dist = (uint8_t *)(queue + nst * (size_t)n);
    for (uint32_t k = 0; k < per; k++) {
        hol__leg_bfs(tab, n, nc * tab->so[k] + tab->sc[k], queue, dist);
        for (uint32_t G = 0; G < nst; G++) {
            int og = (int)(G / nc), g = tab->turn[og];
            if (tab->rot[og][G % nc] != k)
                continue;
            uint32_t at[HOL_NAVTAB_MAX_NST]; /* stored state k2, turned like G */
            for (uint32_t k2 = 0; k2 < per; k2++)
                at[k2] = nc * (uint32_t)((tab->so[k2] - g) & 3) + tab->rotc[g][tab->sc[k2]];
            for (uint32_t i = 0; i < n; i++)
                for (uint32_t k2 = 0; k2 < per; k2++)
                    out_leg[nst * (per * (size_t)i + k2) + G] = dist[nst * (size_t)i + at[k2]];
        }
    }
    return HOL_OK;
}
