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
 * and other orientations rotate the cell.
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
 * proof, beyond proved_radius.
 */
#include "hol_nav_table.h"

#include <string.h>

static void hol__counts(uint32_t cnt[HOL_TILE_STATES][HOL_NAVTAB_MAX_RADIUS + 1], int r)
{
    for (int s = 0; s < HOL_TILE_STATES; s++)
        cnt[s][0] = 1;
    for (int k = 1; k <= r; k++)
        for (int s = 0; s < HOL_TILE_STATES; s++) {
            uint32_t n = 0;
            for (int c = 0; c < 4; c++)
                if (hol_tile_automaton(s, c) >= 0)
                    n += cnt[hol_tile_automaton(s, c)][k - 1];
            cnt[s][k] = n;
        }
}

uint32_t hol_navtab_count(int radius)
{
    uint32_t cnt[HOL_TILE_STATES][HOL_NAVTAB_MAX_RADIUS + 1];
    if (radius < 0 || radius > HOL_NAVTAB_MAX_RADIUS)
        return 0;
    hol__counts(cnt, radius);
    uint32_t n = 1;
    for (int k = 1; k <= radius; k++)
        n += 4 * cnt[0][k - 1];
    return n;
}

size_t hol_navtab_table_bytes(int radius)
{
    size_t n = hol_navtab_count(radius);
    return n * 4 * sizeof(uint32_t) + n * 9;
}

size_t hol_navtab_scratch_bytes(int radius)
{
    return (size_t)hol_navtab_count(radius) * 9 * sizeof(uint32_t);
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
    hol_tile t = hol_tile_origin();
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

hol_err hol_navtab_init_index(hol_navtab *tab, int radius)
{
    if (radius < 0 || radius > HOL_NAVTAB_MAX_RADIUS)
        return HOL_EARG;
    memset(tab, 0, sizeof *tab);
    tab->radius = radius;
    for (int st = 0; st < HOL_TILE_STATES; st++)
        for (int c = 0; c < 4; c++)
            tab->next[st][c] = (int8_t)hol_tile_automaton(st, c);
    hol__counts(tab->cnt, radius);
    tab->off[0] = 0;
    tab->off[1] = 1;
    for (int k = 1; k <= radius; k++)
        tab->off[k + 1] = tab->off[k] + 4 * tab->cnt[0][k - 1];
    tab->count = tab->off[radius + 1];
    return HOL_OK;
}

hol_err hol_navtab_build(hol_navtab *tab, int radius, void *mem, void *scratch)
{
    if (radius < 1 || radius > HOL_NAVTAB_MAX_RADIUS)
        return HOL_EARG;
    hol_navtab_init_index(tab, radius);
    uint32_t n = tab->count;
    tab->nb = (uint32_t *)mem;
    tab->cost = (uint8_t *)(tab->nb + 4 * (size_t)n);

    /* neighbours */
    for (uint32_t i = 0; i < n; i++) {
        hol_tile t = hol_navtab_unrank(tab, i);
        for (int turn = 0; turn < 4; turn++) {
            hol_tile u;
            int arr;
            uint32_t v = HOL_NAVTAB_NONE;
            if (!hol_tile_step(t, turn, &u, &arr)) {
                uint32_t j = hol_navtab_rank(tab, u);
                if (j != HOL_NAVTAB_NONE)
                    v = (j << 2) | (uint32_t)arr;
            }
            tab->nb[4 * (size_t)i + (size_t)turn] = v;
        }
    }

    /* BFS from the goal (tile O, every cell) over (tile, cell), o = 0 */
    uint32_t *queue = (uint32_t *)scratch;
    size_t head = 0, tail = 0;
    memset(tab->cost, 255, 9 * (size_t)n);
    for (int c = 0; c < 9; c++) {
        tab->cost[c] = 0;
        queue[tail++] = (uint32_t)c;
    }
    static const int8_t dcol[4] = {0, -1, 0, 1}, drow[4] = {-1, 0, 1, 0};
    while (head < tail) {
        uint32_t st = queue[head++];
        uint32_t i = st / 9;
        int cell = (int)(st % 9), col = cell % 3, row = cell / 3;
        int v = tab->cost[st];
        for (int d = 0; d < 4; d++) {
            int c2 = col + dcol[d], r2 = row + drow[d];
            if (c2 < 0 || c2 > 2 || r2 < 0 || r2 > 2)
                continue;
            uint32_t e = tab->nb[4 * (size_t)i + (size_t)d];
            if (e == HOL_NAVTAB_NONE)
                continue;
            int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
            uint32_t s2 = 9 * (e >> 2) + (uint32_t)hol_navtab_rot_cell(o2, c2 + 3 * r2);
            if (tab->cost[s2] == 255) {
                tab->cost[s2] = (uint8_t)(v + 1);
                queue[tail++] = s2;
            }
        }
    }

    /* certification */
    int m = 255;
    for (size_t s = 9 * (size_t)tab->off[radius]; s < 9 * (size_t)n; s++)
        if (tab->cost[s] < m)
            m = tab->cost[s];
    tab->min_at_radius = m;
    tab->proved_radius = radius;
    for (int k = 0; k <= radius; k++) {
        int bound = hol_navtab_exit_bound(tab, k), mn = 255;
        uint64_t sum = 0, cnt = 0;
        for (size_t s = 9 * (size_t)tab->off[k]; s < 9 * (size_t)tab->off[k + 1]; s++) {
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
    return HOL_OK;
}

size_t hol_navtab_leg_bytes(int leg_radius)
{
    return (size_t)hol_navtab_count(leg_radius) * 9 * 36;
}

size_t hol_navtab_leg_scratch_bytes(int leg_radius)
{
    return (size_t)hol_navtab_count(leg_radius) * 36 * (sizeof(uint32_t) + 1);
}

/* One BFS per goal state (36): from (O, ob, cb) over full states
 * (tile, o, cell) of the tiles within leg_radius; steps are reversible, so
 * these are the distances to the goal. */
hol_err hol_navtab_build_legs(const hol_navtab *tab, int leg_radius, uint8_t *out_leg,
                              void *scratch)
{
    if (leg_radius < 1 || leg_radius > tab->radius)
        return HOL_EARG;
    uint32_t n = hol_navtab_count(leg_radius);
    size_t nst = 36 * (size_t)n;
    uint32_t *queue = (uint32_t *)scratch;
    uint8_t *dist = (uint8_t *)(queue + nst);
    static const int8_t dcol[4] = {0, -1, 0, 1}, drow[4] = {-1, 0, 1, 0};
    for (int g = 0; g < 36; g++) {
        int ob = g / 9, cb = g % 9;
        memset(dist, 255, nst);
        size_t head = 0, tail = 0;
        uint32_t s0 = (uint32_t)(ob * 9 + cb); /* tile 0 */
        dist[s0] = 0;
        queue[tail++] = s0;
        while (head < tail) {
            uint32_t st = queue[head++];
            uint32_t i = st / 36;
            int o = (int)(st / 9 % 4), cell = (int)(st % 9);
            int col = cell % 3, row = cell / 3, v = dist[st];
            for (int d = 0; d < 4; d++) {
                int c2 = col + dcol[d], r2 = row + drow[d];
                if (c2 < 0 || c2 > 2 || r2 < 0 || r2 > 2)
                    continue;
                uint32_t e = tab->nb[4 * (size_t)i + (size_t)((o + d) & 3)];
                if (e == HOL_NAVTAB_NONE || (e >> 2) >= n)
                    continue;
                int o2 = (int)((e & 3u) - (uint32_t)d) & 3;
                uint32_t s2 = 36 * (e >> 2) + (uint32_t)(9 * o2 + c2 + 3 * r2);
                if (dist[s2] == 255) {
                    dist[s2] = (uint8_t)(v + 1);
                    queue[tail++] = s2;
                }
            }
        }
        for (uint32_t i = 0; i < n; i++)
            for (int c = 0; c < 9; c++)
                out_leg[36 * (9 * (size_t)i + (size_t)c) + (size_t)g] = dist[36 * (size_t)i + (size_t)c];
    }
    return HOL_OK;
}
