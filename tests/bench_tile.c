/* bench_tile.c - speed of the tiling core (make bench). Prints figures;
 * asserts nothing about time. Targets on a 2-core machine: a step under
 * 50 ns; a distance between tiles 20 apart under 2 us. */
#include <stdint.h>
#include <stdio.h>
#include <time.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static uint64_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e9 + ts.tv_nsec;
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

#define NT 4096
static hol_tile tiles[NT], others[NT];
static char texts[NT][HOL_TILE_ADDR_MAX];
static volatile uint64_t sink;

static uint8_t dirs[NT];

/* hol_tile_step on random tiles at `dist` from O in random directions (all
 * four, so a quarter of the steps go back towards O). */
static void bench_step(int dist)
{
    for (int i = 0; i < NT; i++) {
        tiles[i] = random_tile(dist);
        dirs[i] = (uint8_t)(rng() % 4);
    }
    long n = 4000000;
    uint64_t acc = 0;
    double t0 = now_ns();
    for (long i = 0; i < n; i++) {
        hol_tile nb;
        int arr;
        unsigned k = (unsigned)(i & (NT - 1));
        if (hol_tile_step(tiles[k], dirs[(k * 7 + (unsigned)(i >> 12)) & (NT - 1)], &nb,
                          &arr) == HOL_OK)
            acc += nb.bits[0] + (uint64_t)arr;
    }
    double t1 = now_ns();
    sink = acc;
    printf("  neighbour step at distance %2d:        %7.1f ns\n", dist, (t1 - t0) / n);
}

/* Room steps: a random walk inside the room (the app's hot path). */
static void bench_room(void)
{
    hol_room room = hol_room_start();
    long n = 4000000, done = 0;
    for (int i = 0; i < NT; i++)
        dirs[i] = (uint8_t)(rng() % 4);
    double t0 = now_ns();
    for (long i = 0; i < n; i++) {
        if (hol_room_step(&room, dirs[i & (NT - 1)] ^ (int)((i >> 12) & 3)) == HOL_OK)
            done++;
        if (hol_tile_dist0(room.tile) > 40)
            room = hol_room_start();
    }
    double t1 = now_ns();
    sink = (uint64_t)done + room.tile.bits[0];
    printf("  room step (random walk in the room):  %7.1f ns per attempt\n",
           (t1 - t0) / n);
}

static void bench_parse(int dist)
{
    for (int i = 0; i < NT; i++)
        hol_tile_print(random_tile(dist), texts[i]);
    long n = 2000000;
    uint64_t acc = 0;
    double t0 = now_ns();
    for (long i = 0; i < n; i++) {
        hol_tile t;
        if (hol_tile_parse(texts[i & (NT - 1)], dist, &t) == HOL_OK)
            acc += t.bits[0];
    }
    double t1 = now_ns();
    sink = acc;
    printf("  address parse, %2d letters:            %7.1f ns\n", dist, (t1 - t0) / n);
}

static void bench_dist(int from_o, int apart)
{
    for (int i = 0; i < NT; i++) {
        for (;;) {
            hol_tile a = random_tile(from_o), b = a;
            for (int s = 0; s < 4 * apart && hol_tile_dist(a, b) < apart; s++) {
                hol_tile nb;
                if (hol_tile_step(b, (int)(rng() % 4), &nb, NULL) == HOL_OK &&
                    hol_tile_dist(a, nb) >= hol_tile_dist(a, b))
                    b = nb;
            }
            if (hol_tile_dist(a, b) == apart) {
                tiles[i] = a;
                others[i] = b;
                break;
            }
        }
    }
    long n = 200000;
    uint64_t acc = 0;
    double t0 = now_ns();
    for (long i = 0; i < n; i++)
        acc += (uint64_t)hol_tile_dist(tiles[i & (NT - 1)], others[i & (NT - 1)]);
    double t1 = now_ns();
    sink = acc;
    printf("  distance, tiles %d apart, %2d from O:  %7.1f ns\n", apart, from_o,
           (t1 - t0) / n);
}

int main(void)
{
    printf("bench_tile (tiling core, one core)\n");
    bench_step(10);
    bench_step(20);
    bench_step(40);
    bench_step(58);
    bench_room();
    bench_parse(20);
    bench_parse(60);
    bench_dist(20, 20);
    bench_dist(40, 20);
    return 0;
}
