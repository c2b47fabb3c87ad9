/* bench_ratio.c - {4,5} in the 3 x 3 room, today's build against the build
 * before the tilings {4,Q} and room sizes came (make bench builds this file
 * twice: against core/ and against core/ of the pinned commit
 * BENCH_BASE_COMMIT, see the Makefile; tests/bench_ratio.sh runs the two in
 * turns and prints medians and ratios).
 *
 * Only functions both builds have: tile steps, room steps, distances, the
 * navigator's build, fewest steps (exact and anytime), tours, the world's
 * update. Prints one line per figure, "NAME SECONDS" (thread CPU time of
 * the whole figure's loop). Asserts nothing about time.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_nav.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "bench_util.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static uint64_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

static hol_tile random_tile(int n)
{
    hol_tile t = hol_tile_origin();
    while (hol_tile_dist0(t) < n) {
        hol_tile c;
        if (hol_tile_child(t, (int)(rng() % 4), &c) == HOL_OK)
            t = c;
    }
    return t;
}

/* A tile at distance d from the user's tile, through random letters. */
static hol_tile target_at(const hol_room *u, int d)
{
    hol_tile rel = random_tile(d);
    hol_heading_tile f = {u->tile, u->orient};
    for (int i = 0; i < d; i++)
        hol_heading_tile_step(f, hol_tile_letter(rel, i), &f);
    return f.tile;
}

static hol_room random_room(int steps)
{
    hol_room r = hol_room_start();
    for (int i = 0; i < steps; i++)
        hol_room_step(&r, (int)(rng() % 4));
    return r;
}

#define NT 4096
static hol_tile tiles[NT], others[NT];
static uint8_t dirs[NT];
static volatile uint64_t sink;

static void figure(const char *name, double t0)
{
    printf("%s %.6f\n", name, bench_cpu_now() - t0);
    fflush(stdout);
}

static void bench_tiles(void)
{
    for (int i = 0; i < NT; i++) {
        tiles[i] = random_tile(20);
        others[i] = random_tile(20);
        dirs[i] = (uint8_t)(rng() % 4);
    }
    double t0 = bench_cpu_now();
    for (long i = 0; i < 3000000; i++) {
        hol_tile nb;
        int arr;
        unsigned k = (unsigned)(i & (NT - 1));
        if (!hol_tile_step(tiles[k], dirs[(k * 7 + (unsigned)(i >> 12)) & (NT - 1)], &nb, &arr))
            sink += nb.bits[0] + (uint64_t)arr;
    }
    figure("tile_step_3M", t0);
    hol_room r = hol_room_start();
    t0 = bench_cpu_now();
    for (long i = 0; i < 3000000; i++) {
        hol_room_step(&r, dirs[i & (NT - 1)] ^ (int)((i >> 12) & 3));
        sink += r.col;
    }
    figure("room_step_3M", t0);
    t0 = bench_cpu_now();
    for (long i = 0; i < 100000; i++)
        sink += (uint64_t)hol_tile_dist(tiles[i & (NT - 1)], others[i & (NT - 1)]);
    figure("tile_dist_100k", t0);
}

static void bench_nav(void)
{
    double t0 = bench_cpu_now();
    hol_nav *nav;
    if (hol_nav_create(NULL, &nav)) {
        fprintf(stderr, "bench_ratio: no navigator\n");
        exit(1);
    }
    figure("nav_create", t0);
    t0 = bench_cpu_now();
    hol_nav_prepare_tours(nav);
    figure("nav_prepare_tours", t0);
    static uint8_t walk[HOL_NAV_WALK_MAX];
    hol_nav_result res;
    t0 = bench_cpu_now();
    for (int q = 0; q < 20000; q++) {
        hol_room s = random_room(30);
        hol_tile t = target_at(&s, 1 + q % 12);
        hol_nav_find(nav, &s, t, 0, walk, sizeof walk, &res);
        sink += (uint64_t)res.len;
    }
    figure("nav_exact_20k", t0);
    t0 = bench_cpu_now();
    for (int q = 0; q < 100; q++) {
        hol_room s = random_room(30);
        hol_tile t = target_at(&s, 13 + q % 2);
        hol_nav_find(nav, &s, t, 4000, walk, sizeof walk, &res);
        sink += (uint64_t)res.len;
    }
    figure("nav_anytime_100", t0);
    t0 = bench_cpu_now();
    for (int q = 0; q < 60; q++) {
        hol_room s = random_room(20);
        hol_tile keys[3] = {target_at(&s, 1 + q % 5), target_at(&s, 1 + (q + 2) % 5),
                            target_at(&s, 1 + (q + 4) % 5)};
        hol_tile chest = target_at(&s, 1 + (q + 1) % 5);
        hol_nav_tour(nav, &s, keys, 3, chest, 0, walk, sizeof walk, &res);
        sink += (uint64_t)res.len;
    }
    figure("tour_3keys_60", t0);
    hol_nav_destroy(nav);
}

static void bench_world(void)
{
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.seed = 7;
    d.capacity = 1u << 16;
    hol_world *w;
    if (hol_world_make(&d, &w)) {
        fprintf(stderr, "bench_ratio: no world\n");
        exit(1);
    }
    hol_room r = hol_room_start();
    double t0 = bench_cpu_now();
    for (int i = 0; i < 20000; i++) {
        hol_room n = r;
        int dir = (int)(rng() % 4);
        /* drift home now and then, so the walk stays near O */
        if (rng() % 4 == 0)
            for (int k = 0; k < 4; k++) {
                hol_room m = r;
                if (!hol_room_step(&m, k) && hol_tile_dist0(m.tile) < hol_tile_dist0(r.tile))
                    dir = k;
            }
        if (hol_room_step(&n, dir))
            continue;
        r = n;
        hol_world_update(w, &r);
    }
    figure("world_update_20k_steps", t0);
    hol_world_destroy(w);
}

int main(void)
{
    bench_tiles();
    bench_nav();
    bench_world();
    return (int)(sink & 0);
}
