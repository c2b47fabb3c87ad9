/* bench_app.c - `make bench` figures for the app step (core/hol_app.h),
 * without GL: the CPU time of hol_app_step per frame while a pancake user
 * walks (random walk and turn at 72 Hz), over all frames and over the
 * frames with a room step (world update, objectives, guidance replan);
 * and the level start (placement and exact optimum).
 * Times are thread CPU time (CLOCK_THREAD_CPUTIME_ID).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_app.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_tile.h"
#include "bench_util.h"

static uint64_t rng = 0x2545F4914F6CDD1D;
static uint32_t rnd(uint32_t n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)((rng >> 11) % n);
}

/* A random tile at distance d from O (a random canonical address). */
static hol_tile tile_at(int d)
{
    for (;;) {
        hol_tile t = hol_tile_origin();
        int ok = 1;
        for (int i = 0; i < d && ok; i++) {
            static const int letters[3] = {0, 1, 3};
            hol_tile c;
            ok = !hol_tile_child(t, i == 0 ? (int)rnd(4) : letters[rnd(3)], &c);
            t = c;
        }
        if (ok)
            return t;
    }
}

#define FRAMES 30000
static double g_time; /* input time never goes back across levels */

/* The frames' figures (ms): every frame's median and p99, a stepping
 * frame's median and p99. */
typedef struct frame_figs {
    int n, nstep;
    double med, p99, max, step_med, step_p99;
} frame_figs;

static frame_figs run_frames(hol_app *app, int count)
{
    static double all[FRAMES], stepped[FRAMES];
    int nall = 0, nstep = 0;
    float fwd = 1, turn = 0;
    for (int f = 0; f < count; f++) {
        if (f % 36 == 0) {
            fwd = rnd(5) ? 1.0f : -1.0f;
            turn = (float)rnd(3) - 1;
        }
        hol_input in;
        memset(&in, 0, sizeof in);
        g_time += 1 / 72.0;
        in.time_s = g_time;
        in.flags = HOL_INPUT_FOCUSED;
        in.move[1] = fwd;
        in.turn[0] = turn;
        double t0 = bench_cpu_now();
        hol_err err = hol_app_step(app, &in);
        double dt = (bench_cpu_now() - t0) * 1e3;
        if (err) {
            fprintf(stderr, "bench_app: step failed: %s\n", hol_err_str(err));
            exit(1);
        }
        all[nall++] = dt;
        if (hol_app_get_events(app)->nsteps)
            stepped[nstep++] = dt;
    }
    qsort(all, (size_t)nall, sizeof *all, bench_cmp_double);
    qsort(stepped, (size_t)nstep, sizeof *stepped, bench_cmp_double);
    frame_figs g = {nall, nstep, all[nall / 2], all[nall * 99 / 100], all[nall - 1], 0, 0};
    if (nstep) {
        g.step_med = stepped[nstep / 2];
        g.step_p99 = stepped[nstep * 99 / 100];
    }
    return g;
}

static void frames(hol_app *app, const char *what)
{
    frame_figs g = run_frames(app, FRAMES);
    printf("%s: %d frames, %d with a room step\n", what, g.n, g.nstep);
    printf("  every frame: median %.4f ms, p99 %.4f ms, max %.3f ms (targets < 0.2 / < 1 ms)\n",
           g.med, g.p99, g.max);
    if (g.nstep)
        printf("  frames with a room step: median %.4f ms, p99 %.4f ms\n", g.step_med,
               g.step_p99);
}

/* The app step in every shipped geometry (issue 20: under 1 ms p99 in
 * every configuration): a flag level 3..6 tiles out (1..2 in the flat
 * {4,4} 3 x 3, whose room reaches only its nine tiles; seeds whose flag
 * {4,8} cannot reach are skipped), 10000 frames of the random pancake
 * walk, the navigator made beforehand (hol_app_prepare). */
static void geometries(hol_app *app)
{
    static const struct { int q, c, r; double m; } cf[] = {
        {4, 3, 3, 1}, {5, 3, 3, 1}, {6, 3, 3, 1}, {7, 3, 3, 1}, {8, 3, 3, 1},
        {5, 4, 4, 1}, {5, 5, 5, 1}, {6, 4, 4, 0.75}, {4, 5, 5, 1}, {7, 5, 5, 0.5},
    };
    printf("app step per geometry (10000 frames each, flag level; ms):\n");
    printf("  %-18s %8s %8s %8s %10s %10s\n", "geometry", "median", "p99", "max", "step med",
           "step p99");
    for (size_t i = 0; i < sizeof cf / sizeof cf[0]; i++) {
        char text[160], cell[16];
        hol_app_level L;
        hol_err err = HOL_EARG;
        if (hol_app_prepare(app, cf[i].q, cf[i].c, cf[i].r))
            continue;
        for (int seed = 1; seed < 40 && err; seed++) {
            snprintf(text, sizeof text, "tiling 4 %d\nroom %d %d\ncell %s\nmode flag\nseed %d\n"
                     "flag-distance %s\n", cf[i].q, cf[i].c, cf[i].r,
                     hol_level_format_cell(cf[i].m, cell), seed, cf[i].q == 4 ? "1 2" : "3 6");
            if (!hol_level_parse(text, strlen(text), &L, NULL))
                err = hol_app_start_level(app, &L);
        }
        if (err) {
            printf("  {4,%d} %dx%d: no level started\n", cf[i].q, cf[i].c, cf[i].r);
            continue;
        }
        frame_figs g = run_frames(app, 10000);
        char name[32];
        snprintf(name, sizeof name, "{4,%d} %dx%d %s m", cf[i].q, cf[i].c, cf[i].r, cell);
        printf("  %-18s %8.4f %8.4f %8.3f %10.4f %10.4f\n", name, g.med, g.p99, g.max, g.step_med,
               g.step_p99);
    }
}

int main(void)
{
    printf("== app step (hol_app): CPU per frame without GL\n");
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    hol_nav *nav;
    if (hol_nav_create(&nd, &nav)) {
        fprintf(stderr, "bench_app: cannot create the navigator\n");
        return 1;
    }
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = nav;
    hol_app *app;
    if (hol_app_create(&d, &app)) {
        fprintf(stderr, "bench_app: cannot create the app\n");
        return 1;
    }
    /* level start: a flag at distance 10; 5 keys within 6 tiles */
    static double starts[2][40];
    int nok[2] = {0, 0};
    hol_app_level L;
    for (int k = 0; k < 40; k++) {
        memset(&L, 0, sizeof L);
        L.mode = HOL_APP_FLAG;
        L.seed = (uint64_t)k;
        L.flag = tile_at(10);
        L.cues = HOL_CUE_ALL;
        double t0 = bench_cpu_now();
        hol_err err = hol_app_start_level(app, &L);
        if (!err)
            starts[0][nok[0]++] = (bench_cpu_now() - t0) * 1e3;
        memset(&L, 0, sizeof L);
        L.mode = HOL_APP_KEYS;
        L.seed = (uint64_t)k;
        L.nkeys = 5;
        for (int i = 0; i < 5; i++)
            L.keys[i] = tile_at(1 + (int)rnd(3)); /* within 6 tiles of each other */
        L.chest = tile_at(1 + (int)rnd(3));
        L.cues = HOL_CUE_ALL;
        t0 = bench_cpu_now();
        err = hol_app_start_level(app, &L);
        if (!err)
            starts[1][nok[1]++] = (bench_cpu_now() - t0) * 1e3;
    }
    for (int m = 0; m < 2; m++) {
        qsort(starts[m], (size_t)nok[m], sizeof starts[m][0], bench_cmp_double);
        if (nok[m])
            printf("level start, %s: %d levels, median %.2f ms, max %.2f ms (target < 50 ms)\n",
                   m ? "5 keys and a chest within 3 tiles of the start" : "flag at distance 10",
                   nok[m], starts[m][nok[m] / 2], starts[m][nok[m] - 1]);
    }
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 2;
    L.flag = tile_at(8);
    L.cues = HOL_CUE_ALL;
    if (!hol_app_start_level(app, &L))
        frames(app, "flag level (distance 8), random pancake walk");
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_KEYS;
    L.seed = 4;
    L.nkeys = 3;
    for (int i = 0; i < 3; i++)
        L.keys[i] = tile_at(2);
    L.chest = tile_at(3);
    L.cues = HOL_CUE_ALL;
    if (!hol_app_start_level(app, &L))
        frames(app, "keys level (3 keys, replan a tour per step), random pancake walk");
    /* exact tours at level start over wider spreads (issue 11: every level
     * exact or refused, 5 keys within 8 tiles under 100 ms at p99); after
     * the frames so their random walks stay those of earlier figures */
    for (int m = 0; m < 2; m++) {
        static const int spread[2] = {6, 8};
        static double wide[300];
        int n = 300, refused = 0;
        for (int k = 0; k < n; k++) {
            memset(&L, 0, sizeof L);
            L.mode = HOL_APP_KEYS;
            L.seed = (uint64_t)k;
            L.cues = HOL_CUE_ALL;
            L.nkeys = 5;
            for (int i = 0; i < 5; i++)
                L.keys[i] = tile_at(1 + (int)rnd((uint32_t)spread[m]));
            L.chest = tile_at(1 + (int)rnd((uint32_t)spread[m]));
            double t0 = bench_cpu_now();
            hol_err err = hol_app_start_level(app, &L);
            wide[k] = (bench_cpu_now() - t0) * 1e3;
            refused += err == HOL_EBUDGET;
        }
        qsort(wide, (size_t)n, sizeof wide[0], bench_cmp_double);
        printf("level start, 5 keys and a chest 1..%d tiles from the start: %d levels, %d "
               "refused (optimum not proved exact); median %.2f ms, p99 %.2f ms, max %.2f ms "
               "(refusals included)\n", spread[m], n, refused, wide[n / 2],
               wide[n * 99 / 100], wide[n - 1]);
    }
    geometries(app);
    hol_app_destroy(app);
    hol_nav_destroy(nav);
    return 0;
}
