/* bench_geometry.c - every tiling {4,Q} and room size (issue 20, SPEC 7):
 * per configuration the navigator's build time, memory and exact radii,
 * fewest-steps answers by distance (median and p99), and per tiling the
 * world's update after a room step; then, per configuration, what one room
 * step costs the guidance: the world's update plus a new plan to a flag 8
 * tiles away (the app step's share of geometry work; the app itself takes
 * only {4,5} 3 x 3 until the platforms take the options).
 * Thread CPU time (the shared machine's preemption left out). Prints
 * figures; asserts nothing about time. BENCH_GEOMETRY_QUICK=1: two
 * configurations only.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_nav.h"
#include "../core/hol_nav_table.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "bench_util.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static uint32_t rnd(uint32_t n)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (uint32_t)((rng_state >> 11) % n);
}

static hol_room random_room(const hol_room *s0, int steps)
{
    hol_room r = *s0;
    for (int i = 0; i < steps; i++)
        hol_room_step(&r, (int)rnd(4));
    return r;
}

/* A tile at distance d from the user's tile (random canonical letters). */
static hol_tile target_at(const hol_room *u, int d)
{
    int q = hol_tile_q(u->tile);
    hol_tile rel = hol_tile_origin_q(q), c;
    while (hol_tile_dist0(rel) < d)
        if (!hol_tile_child(rel, (int)rnd(4), &c))
            rel = c;
    hol_heading_tile f = {u->tile, u->orient};
    for (int i = 0; i < d; i++)
        hol_heading_tile_step(f, hol_tile_letter(rel, i), &f);
    return f.tile;
}

static double pct(double *v, int n, double p)
{
    qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
    int i = (int)(p * (n - 1) + 0.5);
    return v[i];
}

#define NQ 200
static uint8_t walk[HOL_NAV_WALK_MAX];

/* Fewest steps at distance 1..trust + 2: median and p99 in microseconds,
 * one cell per distance "d:median/p99" (a '*' where answers were anytime,
 * 'u' counts targets out of reach). */
static void nav_by_distance(hol_nav *nav, const hol_room *s0, int trust)
{
    static double t[NQ];
    printf("   nav by distance, median/p99 us:");
    for (int d = 1; d <= trust + 2 && d <= 16; d++) {
        int n = 0, anytime = 0, unreach = 0;
        for (int k = 0; k < NQ; k++) {
            hol_room s = random_room(s0, 30);
            hol_tile goal = target_at(&s, d);
            hol_nav_result res;
            double t0 = bench_cpu_now();
            hol_err err = hol_nav_find(nav, &s, goal, 4000, walk, sizeof walk, &res);
            double dt = bench_cpu_now() - t0;
            if (err == HOL_EUNREACH) {
                unreach++;
                continue;
            }
            t[n++] = dt * 1e6;
            anytime += !res.exact;
        }
        if (d % 6 == 1)
            printf("\n     ");
        if (!n) {
            printf(" %d:-", d);
            continue;
        }
        printf(" %d:%.1f/%.1f%s", d, pct(t, n, 0.5), pct(t, n, 0.99), anytime ? "*" : "");
        if (unreach)
            printf("(%du)", unreach);
    }
    printf("\n");
}

/* A flag d tiles from the user that a walk in the room reaches. */
static hol_tile reachable_flag(hol_nav *nav, const hol_room *r, int d)
{
    for (;;) {
        hol_tile t = target_at(r, d);
        hol_nav_result res;
        if (hol_nav_find(nav, r, t, 0, walk, sizeof walk, &res) == HOL_OK)
            return t;
        d = d > 1 ? d - 1 : 1; /* {4,4}, {4,8}: nearer, until one is in reach */
    }
}

/* What a room step costs the guidance, as a player walks to flags: the
 * world's update and a new plan, over 4000 steps, two in three along the
 * plan, one in three anywhere; a new flag 8 tiles away once one is
 * reached (the app's flag levels). */
static void step_cost(hol_nav *nav, const hol_room *s0)
{
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = 3;
    wd.capacity = 1u << 16;
    wd.tiling_q = hol_tile_q(s0->tile);
    hol_world *w;
    if (hol_world_make(&wd, &w))
        return;
    hol_room r = *s0;
    hol_world_update(w, &r);
    hol_tile flag = reachable_flag(nav, &r, 8);
    static double t[4000];
    int n = 0, next = -1;
    hol_nav_result res;
    for (int i = 0; i < 4000; i++) {
        hol_room nx = r;
        if (hol_room_step(&nx, next >= 0 && rnd(3) ? next : (int)rnd(4)))
            continue;
        r = nx;
        double t0 = bench_cpu_now();
        hol_world_update(w, &r);
        hol_err err = hol_nav_find(nav, &r, flag, 0, walk, sizeof walk, &res);
        t[n++] = (bench_cpu_now() - t0) * 1e3;
        next = !err && res.len ? walk[0] : -1;
        if (hol_tile_eq(r.tile, flag) || err)
            flag = reachable_flag(nav, &r, 8);
    }
    double med = pct(t, n, 0.5), p99 = pct(t, n, 0.99);
    printf("   room step (world update + plan to a flag): median %.3f ms, p99 %.3f ms, max %.3f ms\n",
           med, p99, t[n - 1]);
    hol_world_destroy(w);
}

static void config(int q, int C, int R)
{
    hol_nav_desc d = {0};
    d.tiling_q = q;
    d.room_cols = C;
    d.room_rows = R;
    hol_nav *nav;
    double t0 = bench_cpu_now();
    if (hol_nav_create(&d, &nav)) {
        printf("{4,%d} %dx%d: no navigator\n", q, C, R);
        return;
    }
    double build = bench_cpu_now() - t0;
    t0 = bench_cpu_now();
    hol_nav_prepare_tours(nav);
    double legs = bench_cpu_now() - t0;
    hol_room s0;
    hol_room_start_in(q, C, R, &s0);
    int trust = hol_nav_table_exact_radius(nav);
    printf("{4,%d} %dx%d: table radius %d, exact to %d tiles, tours exact to %d; build %.2f s "
           "+ legs %.2f s; %.1f MB\n",
           q, C, R, hol_nav_table_radius(nav), trust, hol_nav_tour_exact_radius(nav), build, legs,
           hol_nav_memory(nav) / 1048576.0);
    nav_by_distance(nav, &s0, trust);
    step_cost(nav, &s0);
    fflush(stdout);
    hol_nav_destroy(nav);
}

/* The world alone: updates after each room step of a walk near O. */
static void world_cost(int q)
{
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = 5;
    wd.tiling_q = q;
    hol_world *w;
    if (hol_world_make(&wd, &w))
        return;
    hol_room r;
    hol_room_start_in(q, 3, 3, &r);
    static double t[20000];
    int n = 0;
    for (int i = 0; i < 20000; i++) {
        hol_room nx = r;
        int dir = (int)rnd(4);
        if (rnd(3) == 0)
            for (int k = 0; k < 4; k++) {
                hol_room m = r;
                if (!hol_room_step(&m, k) && hol_tile_dist0(m.tile) < hol_tile_dist0(r.tile))
                    dir = k;
            }
        if (hol_room_step(&nx, dir))
            continue;
        r = nx;
        double t0 = bench_cpu_now();
        hol_world_update(w, &r);
        t[n++] = (bench_cpu_now() - t0) * 1e6;
    }
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    double med = pct(t, n, 0.5), p99 = pct(t, n, 0.99);
    printf("{4,%d} world update after a room step: median %.1f us, p99 %.1f us, max %.1f us "
           "(%llu tiles collapsed, %.0f MB)\n",
           q, med, p99, t[n - 1], (unsigned long long)st.tiles_collapsed, st.bytes / 1048576.0);
    hol_world_destroy(w);
}

int main(void)
{
    static const int rooms[6][2] = {{3, 3}, {4, 4}, {5, 5}, {3, 4}, {3, 5}, {4, 5}};
    int quick = getenv("BENCH_GEOMETRY_QUICK") != NULL;
    printf("== bench_geometry: every tiling and room size (thread CPU time; %d queries a "
           "distance, anytime budget 4000)\n", NQ);
    for (int q = 4; q <= 8; q++)
        if (!quick || q == 5)
            world_cost(q);
    for (int q = 4; q <= 8; q++)
        for (int z = 0; z < 6; z++)
            if (!quick || (z < 2 && q == 5))
                config(q, rooms[z][0], rooms[z][1]);
    return 0;
}
