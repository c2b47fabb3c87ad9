/* bench_world.c - `make bench` figures for the world (hol_world).
 *
 * 1. Fill after each step: a random room walk (drifting home 30% of the
 *    time so it stays inside the reach of tile words) calls
 *    hol_world_update after every step, as the app does; per-step time to
 *    have radius 4 collapsed: mean, median, 99th percentile, max.
 * 2. Microseconds per generated tile over that walk, and a radius-8 ball
 *    generated from scratch.
 * 3. Backtracks per 1,000 tiles: the real tile set, and with the testing
 *    hook rejecting 10% of the choices (to show the cost of backtracking).
 * Times are thread CPU time (CLOCK_THREAD_CPUTIME_ID), not wall time.
 * 4. Memory: the world's single block (store + batch scratch) at the default
 *    capacity; then the store filled to the eviction threshold and the cost
 *    per update while the incremental eviction sweep runs.
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <sys/resource.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"

/* CPU time of this thread: on the shared 2-core build machine, wall time
 * per update is dominated by preemption spikes; CPU time is what the code
 * costs. */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static uint64_t rng = 0x1234567;
static uint32_t rnd(uint32_t n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)((rng >> 11) % n);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* malloc'd, so hol_world_init clears (touches) the store as the app's
 * world is: no update below takes a page fault (the default allocator's
 * calloc maps the store's pages when first written) */
static void *bench_alloc(size_t n, void *user)
{
    (void)user;
    return malloc(n);
}

static void bench_free(void *p, void *user)
{
    (void)user;
    free(p);
}

static hol_world *make(uint64_t seed, uint32_t cap, uint32_t reject)
{
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.allocator.alloc = bench_alloc;
    d.allocator.free = bench_free;
    d.seed = seed;
    d.capacity = cap;
    d.test_reject_per_mille = reject;
    hol_world *w;
    if (hol_world_make(&d, &w)) {
        fprintf(stderr, "bench_world: cannot make a world\n");
        exit(1);
    }
    return w;
}

/* One step in the room, towards O with probability home/1000. */
static void step(hol_room *room, int home)
{
    for (;;) {
        int dir = (int)rnd(4);
        if ((int)rnd(1000) < home) {
            for (int d = 0; d < 4; d++) {
                hol_room n = *room;
                if (!hol_room_step(&n, d) &&
                    hol_tile_dist0(n.tile) < hol_tile_dist0(room->tile))
                    dir = d;
            }
        }
        hol_room n = *room;
        if (!hol_room_step(&n, dir)) {
            *room = n;
            return;
        }
    }
}

/* The timer's own noise on this machine: a fixed computation (about 20 us,
 * no memory beyond the cache, no system call) timed the same way as the
 * updates, as often. Its maximum is what the machine adds (a virtual CPU
 * descheduled by the host counts as running time), not the code. */
static void control_noise(int n)
{
    static double c[50000];
    volatile uint64_t sink = 0;
    for (int i = 0; i < n; i++) {
        double a = now();
        uint64_t x = (uint64_t)i + 1;
        for (int k = 0; k < 6000; k++)
            x = x * 6364136223846793005ull + 1442695040888963407ull;
        sink += x;
        c[i] = (now() - a) * 1e6;
    }
    (void)sink;
    qsort(c, (size_t)n, sizeof c[0], cmp_double);
    printf("timer noise (control): a fixed %.1f us computation timed %d times: p99 %.1f us, "
           "max %.1f us\n", c[n / 2], n, c[n * 99 / 100], c[n - 1]);
}

int main(void)
{
    enum { STEPS = 50000 };
    static double t[STEPS];
    printf("== world (hol_world): WFC population, radius 4, default capacity\n");
    control_noise(STEPS);

    /* 1 + 2: fill after each step, for a walk that stays near O (home 30%)
     * and one that explores outwards (home 10%) */
    int homes[2] = {300, 100};
    for (int h = 0; h < 2; h++) {
        hol_world *w = make(1, 0, 0);
        hol_room room = hol_room_start();
        hol_world_update(w, &room);
        hol_world_stats s0, s1;
        hol_world_get_stats(w, &s0);
        double total = 0, worst = 0, worst_per_tile = 0, worst_clean = 0;
        long worst_faults = 0, worst_switches = 0;
        int maxd = 0, worst_tiles = 0, max_tiles = 0;
        long sum_d = 0;
        for (int i = 0; i < STEPS; i++) {
            step(&room, homes[h]);
            hol_world_stats sa, sb;
            hol_world_get_stats(w, &sa);
            struct rusage ra, rb;
            getrusage(RUSAGE_THREAD, &ra);
            double a = now();
            hol_err err = hol_world_update(w, &room);
            double b = now();
            getrusage(RUSAGE_THREAD, &rb);
            hol_world_get_stats(w, &sb);
            long faults = (rb.ru_minflt - ra.ru_minflt) + (rb.ru_majflt - ra.ru_majflt);
            long switches = (rb.ru_nivcsw - ra.ru_nivcsw) + (rb.ru_nvcsw - ra.ru_nvcsw);
            int nt = (int)(sb.tiles_collapsed - sa.tiles_collapsed);
            double us = (b - a) * 1e6;
            if (us > worst) {
                worst = us;
                worst_tiles = nt;
                worst_faults = faults;
                worst_switches = switches;
            }
            if (faults == 0 && switches == 0 && us > worst_clean)
                worst_clean = us;
            if (nt > max_tiles)
                max_tiles = nt;
            if (nt >= 8 && us / nt > worst_per_tile)
                worst_per_tile = us / nt;
            if (err) {
                fprintf(stderr, "bench_world: update failed: %s\n", hol_err_str(err));
                return 1;
            }
            t[i] = (b - a) * 1e6;
            total += b - a;
            int d = hol_tile_dist0(room.tile);
            sum_d += d;
            if (d > maxd)
                maxd = d;
        }
        hol_world_get_stats(w, &s1);
        uint64_t tiles = s1.tiles_collapsed - s0.tiles_collapsed;
        qsort(t, STEPS, sizeof t[0], cmp_double);
        printf("fill radius 4 after a step: %d steps, home %d%%, user at mean distance "
               "%.1f (max %d) from O:\n",
               STEPS, homes[h] / 10, (double)sum_d / STEPS, maxd);
        printf("  mean %.1f us, median %.1f us, p99 %.1f us, max %.1f us (target < 500 us)\n",
               total / STEPS * 1e6, t[STEPS / 2], t[STEPS * 99 / 100], t[STEPS - 1]);
        printf("  %.2f new tiles per step; %.2f us per generated tile (all update time / tiles)\n",
               (double)tiles / STEPS, total * 1e6 / (double)tiles);
        printf("  the slowest update generated %d tiles (%.1f us, %ld page faults, %ld context "
               "switches during it); the most tiles one step generated: %d; the dearest tile "
               "of an update with 8 or more: %.1f us\n",
               worst_tiles, worst, worst_faults, worst_switches, max_tiles, worst_per_tile);
        printf("  the slowest update without a page fault or a context switch: %.1f us "
               "(target < 500 us)\n", worst_clean);
        printf("  backtracks per 1000 tiles: %.3f (%llu in %llu tiles); store %u tiles\n",
               tiles ? 1000.0 * (double)(s1.backtracks - s0.backtracks) / (double)tiles : 0.0,
               (unsigned long long)(s1.backtracks - s0.backtracks),
               (unsigned long long)tiles, s1.count);
        hol_world_destroy(w);
    }
    hol_world *w;
    hol_room room;
    hol_world_stats s1;

    /* 2b: a radius-8 ball from scratch */
    {
        hol_world_desc d;
        memset(&d, 0, sizeof d);
        d.seed = 2;
        d.radius = 8;
        hol_world *w8;
        if (hol_world_make(&d, &w8) == HOL_OK) {
            room = hol_room_start();
            double a = now();
            hol_world_update(w8, &room);
            double b = now();
            hol_world_get_stats(w8, &s1);
            printf("radius-8 ball from scratch: %llu tiles in %.2f ms, %.2f us per tile\n",
                   (unsigned long long)s1.tiles_collapsed, (b - a) * 1e3,
                   (b - a) * 1e6 / (double)s1.tiles_collapsed);
            hol_world_destroy(w8);
        }
    }

    /* 3: backtracking cost with the testing hook */
    w = make(3, 0, 100);
    room = hol_room_start();
    hol_world_update(w, &room);
    double a = now();
    for (int i = 0; i < 10000; i++) {
        step(&room, 300);
        if (hol_world_update(w, &room)) {
            fprintf(stderr, "bench_world: update with rejections failed\n");
            break;
        }
    }
    double b = now();
    hol_world_get_stats(w, &s1);
    printf("with 10%% of choices rejected (test hook): %.1f backtracks per 1000 tiles, "
           "%.1f us per step\n",
           1000.0 * (double)s1.backtracks / (double)s1.tiles_collapsed,
           (b - a) * 1e6 / 10000);
    hol_world_destroy(w);

    /* 4: memory and one eviction sweep at the default capacity */
    w = make(4, 0, 0);
    hol_world_get_stats(w, &s1);
    printf("memory: one block of %zu bytes (%.1f MiB) for %u tiles "
           "(%zu bytes per tile incl. scratch); never grows\n",
           s1.bytes, (double)s1.bytes / 1048576.0, s1.capacity,
           s1.bytes / s1.capacity);
    room = hol_room_start();
    hol_world_update(w, &room);
    /* fill to the eviction threshold with far tiles collapsed on demand */
    hol_tile t0 = hol_tile_origin();
    hol_world_stats fill0;
    hol_world_get_stats(w, &fill0);
    a = now();
    while (1) {
        hol_world_get_stats(w, &s1);
        if (s1.count > s1.capacity / 4 * 3 + 8)
            break;
        hol_tile tt = t0;
        for (int k = 0; k < 24; k++) {
            hol_tile n;
            if (hol_tile_step(tt, (int)rnd(4), &n, NULL) == HOL_OK)
                tt = n;
        }
        hol_tile_content c;
        hol_world_get(w, tt, &c);
    }
    b = now();
    printf("filled the store to %u tiles with lone collapses (hol_world_get of far tiles) "
           "in %.2f s: %.2f us per generated tile\n",
           s1.count, b - a,
           (b - a) * 1e6 / (double)(s1.tiles_collapsed - fill0.tiles_collapsed));
    hol_world_stats before;
    hol_world_get_stats(w, &before);
    /* step back and forth until the incremental sweep has run through */
    double worst = 0, sum = 0;
    int n_upd = 0;
    room = hol_room_start();
    for (; n_upd < 2000; n_upd++) {
        hol_room next = room;
        hol_room_step(&next, n_upd & 1 ? HOL_DIR_S : HOL_DIR_N);
        room = next;
        a = now();
        hol_world_update(w, &room);
        b = now();
        sum += b - a;
        if (b - a > worst)
            worst = b - a;
        t[n_upd] = (b - a) * 1e6;
        hol_world_get_stats(w, &s1);
        if (s1.count <= s1.capacity / 2)
            break;
    }
    int nu = n_upd < 2000 ? n_upd + 1 : 2000;
    qsort(t, (size_t)nu, sizeof t[0], cmp_double);
    printf("eviction: %llu tiles evicted, store %u -> %u over %d updates (incremental "
           "sweep); update during the sweep: mean %.1f us, median %.1f us, p99 %.1f us, "
           "max %.1f us\n",
           (unsigned long long)(s1.evicted - before.evicted), before.count, s1.count,
           nu, sum / nu * 1e6, t[nu / 2], t[nu * 99 / 100], worst * 1e6);
    hol_world_destroy(w);
    return 0;
}
