/* bench_nav.c - `make bench` figures for guidance (hol_nav).
 *
 * Per tile distance 2..16 between the user's tile and the target (random
 * starts: random walks in the room; random targets at exactly that distance):
 * median and 99th-percentile time per query, mean nodes expanded, mean walk
 * length, share of exact answers. Then the anytime mode's quality: how often
 * its first steps are a prefix of an optimal walk, measured where the truth
 * is known (a radius-10 navigator, trusted to 8, answering targets at 9..12
 * in anytime mode, against the default navigator's exact answers; and the
 * default navigator at distance 13 against a radius-15 one). Last, tours:
 * time, share answered by the dynamic program, share exact.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../core/hol_nav.h"
#include "../core/hol_nav_table.h"
#include "bench_util.h"
#include "plain_astar.h"

static uint64_t rng = 0x9E3779B97F4A7C15ull;

static uint32_t rnd(uint32_t n)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (uint32_t)((rng >> 11) % n);
}

/* wall-clock time (the tables also print the thread CPU time: what the code
 * costs without the time other processes held the core) */
static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static hol_room random_start(void)
{
    hol_room r = hol_room_start();
    int n = (int)rnd(60);
    for (int i = 0; i < n; i++)
        hol_room_step(&r, (int)rnd(4));
    return r;
}

static hol_tile random_target(const hol_room *u, int d)
{
    hol_tile rel = hol_tile_origin(), c;
    hol_tile_child(rel, (int)rnd(4), &rel);
    while (hol_tile_dist0(rel) < d) {
        static const int letters[3] = {0, 1, 3};
        if (!hol_tile_child(rel, letters[rnd(3)], &c))
            rel = c;
    }
    hol_heading_tile f = {u->tile, u->orient};
    for (int i = 0; i < d; i++)
        hol_heading_tile_step(f, hol_tile_letter(rel, i), &f);
    return f.tile;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#define QUERIES 400

static void bench_distances(hol_nav *nav, size_t budget, const char *label)
{
    static double t[QUERIES];
    static uint8_t walk[HOL_NAV_WALK_MAX];
    printf("\n%s\n", label);
    printf("  dist  median_ms  p99_ms   max_ms  max_cpu_ms  nodes_mean  nodes_max  len_mean  "
           "exact\n");
    for (int d = 2; d <= 16; d++) {
        double nodes = 0, len = 0, cpu_max = 0;
        size_t nodes_max = 0;
        int exact = 0;
        for (int q = 0; q < QUERIES; q++) {
            hol_room s = random_start();
            hol_tile target = random_target(&s, d);
            hol_nav_result res;
            double c0 = (1e3 * bench_cpu_now()), t0 = now_ms();
            hol_err err = hol_nav_find(nav, &s, target, budget, walk, sizeof walk, &res);
            t[q] = now_ms() - t0;
            double c = (1e3 * bench_cpu_now()) - c0;
            if (c > cpu_max)
                cpu_max = c;
            if (res.nodes > nodes_max)
                nodes_max = res.nodes;
            if (err) {
                printf("  error %s at distance %d\n", hol_err_str(err), d);
                exit(1);
            }
            nodes += (double)res.nodes;
            len += res.len;
            exact += res.exact;
        }
        qsort(t, QUERIES, sizeof t[0], cmp_double);
        printf("  %4d  %9.4f  %6.3f  %7.3f  %10.3f  %10.0f  %9zu  %8.2f  %4d%%\n", d,
               t[QUERIES / 2], t[QUERIES * 99 / 100], t[QUERIES - 1], cpu_max, nodes / QUERIES,
               nodes_max, len / QUERIES, 100 * exact / QUERIES);
    }
}

/* Anytime answers of `any` against the exact answers of `exact`. */
static void bench_prefix(hol_nav *any, hol_nav *exact, int dlo, int dhi, size_t budget)
{
    static uint8_t walk[HOL_NAV_WALK_MAX], best[HOL_NAV_WALK_MAX];
    for (int d = dlo; d <= dhi; d++) {
        int n = 200, same = 0, p1 = 0, p3 = 0, p5 = 0, extra = 0;
        double tsum = 0, tmax = 0;
        for (int q = 0; q < n; q++) {
            hol_room s = random_start();
            hol_tile target = random_target(&s, d);
            hol_nav_result res, opt, rest;
            double t0 = now_ms();
            hol_nav_find(any, &s, target, budget, walk, sizeof walk, &res);
            double dt = now_ms() - t0;
            tsum += dt;
            if (dt > tmax)
                tmax = dt;
            hol_nav_find(exact, &s, target, 0, best, sizeof best, &opt);
            same += res.len == opt.len;
            extra += res.len - opt.len;
            int ks[3] = {1, 3, 5}, *hits[3] = {&p1, &p3, &p5};
            for (int j = 0; j < 3; j++) {
                int k = ks[j] < res.len ? ks[j] : res.len;
                hol_room r = s;
                for (int i = 0; i < k; i++)
                    hol_room_step(&r, walk[i]);
                hol_nav_find(exact, &r, target, 0, best, sizeof best, &rest);
                *hits[j] += rest.len + k == opt.len;
            }
        }
        printf("  %4d  %6zu  %5.1f%%  %5.1f%%  %5.1f%%  %5.1f%%  %6.2f  %7.3f  %7.3f\n", d,
               budget, 100.0 * p1 / n, 100.0 * p3 / n, 100.0 * p5 / n, 100.0 * same / n,
               (double)extra / n, tsum / n, tmax);
    }
}

/* Optional (NAV_BENCH_VERIFY=1; about 4 s and 270 MB): the default
 * navigator's anytime answers at 13..15 against a radius-17 table (trusted
 * to 15), and the default table against it within 12. */
static hol_navtab nav_tab_default; /* the default table's numbering, for its size */

static void bench_verify(hol_nav *nav)
{
    static uint8_t walk[HOL_NAV_WALK_MAX];
    hol_navtab big, small;
    hol_navtab_init_index(&big, 17);
    hol_navtab_init_index(&small, 14);
    void *mb = malloc(hol_navtab_table_bytes(&big)), *ms = malloc(hol_navtab_table_bytes(&small));
    void *s = malloc(hol_navtab_scratch_bytes(&big));
    if (!mb || !ms || !s) {
        printf("verify: out of memory\n");
        return;
    }
    hol_navtab_build(&big, mb, s);
    hol_navtab_build(&small, ms, s);
    free(s);
    int first = -1;
    for (int k = 0; k <= 14 && first < 0; k++)
        for (size_t q = 9 * (size_t)small.off[k]; q < 9 * (size_t)small.off[k + 1]; q++)
            if (small.cost[q] != big.cost[q]) {
                first = k;
                break;
            }
    printf("\nverify: the radius-14 table equals a radius-17 table (%u tiles) up to "
           "distance %d\n", big.count, first - 1);
    printf("  dist  optimal  first5_on_optimal  extra\n");
    for (int d = 13; d <= 15; d++) {
        int n = 400, same = 0, p5 = 0;
        long extra = 0;
        for (int q = 0; q < n; q++) {
            hol_room st = random_start();
            hol_tile target = random_target(&st, d);
            hol_nav_result r;
            hol_nav_find(nav, &st, target, 0, walk, sizeof walk, &r);
            hol_tile u;
            int fac;
            hol_tile_relative(target, 0, st.tile, &u, &fac);
            int opt = hol_navtab_cost(&big, hol_navtab_rank(&big, u), (fac + st.orient) & 3,
                                      st.col + 3 * st.row);
            same += r.len == opt;
            extra += r.len - opt;
            hol_room r5 = st;
            int k = r.len < 5 ? r.len : 5;
            for (int i = 0; i < k; i++)
                hol_room_step(&r5, walk[i]);
            hol_tile_relative(target, 0, r5.tile, &u, &fac);
            int rest = hol_navtab_cost(&big, hol_navtab_rank(&big, u), (fac + r5.orient) & 3,
                                       r5.col + 3 * r5.row);
            p5 += rest + k == opt;
        }
        printf("  %4d  %6.1f%%  %16.1f%%  %5.2f\n", d, 100.0 * same / n, 100.0 * p5 / n,
               (double)extra / n);
    }
    free(mb);
    free(ms);
}

static void bench_tours(hol_nav *nav, int dmax, size_t budget, const char *label)
{
    static uint8_t walk[HOL_NAV_WALK_MAX];
    printf("\ntours: %s\n", label);
    printf("  keys  median_ms  max_ms  by_dp  exact  nodes_mean  len_mean\n");
    for (int nk = 1; nk <= 5; nk++) {
        int n = 40, exact = 0, dp = 0;
        double t[40], nodes = 0, len = 0;
        for (int q = 0; q < n; q++) {
            hol_room s = random_start();
            hol_tile keys[5], chest;
            for (int i = 0; i < nk; i++)
                keys[i] = random_target(&s, 1 + (int)rnd((uint32_t)dmax));
            chest = random_target(&s, 1 + (int)rnd((uint32_t)dmax));
            hol_nav_result res;
            double t0 = 1e3 * bench_cpu_now(); /* thread CPU time */
            hol_nav_tour(nav, &s, keys, nk, chest, budget, walk, sizeof walk, &res);
            t[q] = 1e3 * bench_cpu_now() - t0;
            nodes += (double)res.nodes;
            len += res.len;
            exact += res.exact;
            dp += res.exact && res.nodes == 0;
        }
        qsort(t, (size_t)n, sizeof t[0], cmp_double);
        printf("  %4d  %9.3f  %6.1f  %4d%%  %4d%%  %10.0f  %8.2f\n", nk, t[n / 2], t[n - 1],
               100 * dp / n, 100 * exact / n, nodes / n, len / n);
    }
}

/* The side-by-side figure: the original's guidance method (plain A* over
 * room states with the tile-distance heuristic, tests/plain_astar.h) and
 * ours on the same queries; both must give the same fewest steps. */
static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void bench_side_by_side(hol_nav *nav)
{
    plain_astar pa;
    if (pa_init(&pa, 22)) {
        printf("cannot allocate the plain A*\n");
        return;
    }
    printf("\nside by side: plain A* over (tile, room orientation, cell) with the tile\n"
           "distance heuristic (the original's method) vs hol_nav, the same queries\n");
    printf("  dist  queries  A* nodes (mean)  A* ms (median / p99)  ours nodes  ours ms "
           "(median / p99)  speed-up (median)  same length\n");
    static const int dists[3] = {4, 8, 12};
    for (int k = 0; k < 3; k++) {
        int d = dists[k], nq = 40, same = 0;
        double ta[40], tb[40], na = 0, nb = 0;
        static uint8_t walk[HOL_NAV_WALK_MAX];
        for (int q = 0; q < nq; q++) {
            hol_room s = random_start();
            hol_tile t = random_target(&s, d);
            size_t ex = 0;
            double t0 = now_ms();
            int len = pa_find(&pa, &s, t, &ex);
            ta[q] = now_ms() - t0;
            na += (double)ex;
            hol_nav_result res;
            t0 = now_ms();
            hol_err err = hol_nav_find(nav, &s, t, 0, walk, sizeof walk, &res);
            tb[q] = now_ms() - t0;
            nb += (double)res.nodes;
            same += !err && len == res.len;
        }
        qsort(ta, (size_t)nq, sizeof ta[0], cmp_d);
        qsort(tb, (size_t)nq, sizeof tb[0], cmp_d);
        printf("  %4d  %7d  %15.0f  %9.3f / %8.3f  %10.0f  %7.4f / %7.4f  %17.0fx  %d/%d\n", d,
               nq, na / nq, ta[nq / 2], ta[nq * 99 / 100], nb / nq, tb[nq / 2],
               tb[nq * 99 / 100], tb[nq / 2] > 0 ? ta[nq / 2] / tb[nq / 2] : 0, same, nq);
    }
    pa_fini(&pa);
}

int main(void)
{
    printf("== bench_nav: fewest room steps (hol_nav)\n");
    double t0 = now_ms();
    hol_nav *nav;
    if (hol_nav_create(NULL, &nav)) {
        printf("cannot create navigator\n");
        return 1;
    }
    hol_navtab_init_index(&nav_tab_default, HOL_NAV_DEFAULT_RADIUS);
    printf("table radius %d (trusted/exact within %d): built in %.0f ms, "
           "%.1f MB in all (table %.1f MB, search arena %u nodes)\n",
           HOL_NAV_DEFAULT_RADIUS, hol_nav_table_exact_radius(nav), now_ms() - t0,
           (double)hol_nav_memory(nav) / 1048576.0,
           (double)hol_navtab_table_bytes(&nav_tab_default) / 1048576.0,
           HOL_NAV_DEFAULT_NODES);

    bench_side_by_side(nav);
    bench_distances(nav, 0, "per tile distance, default budget (arena, 262144 nodes); "
                            "<= 12 exact from the table, beyond anytime");
    bench_distances(nav, 8000, "per tile distance, --budget 8000 (anytime beyond 12)");

    printf("\nanytime quality: share of answers whose first 1/3/5 steps lie on an "
           "optimal walk, share of optimal length, mean extra steps, time\n");
    printf("  radius-10 navigator (trusted 8) vs the exact default navigator\n");
    printf("  dist  budget  first1  first3  first5  optlen  extra  mean_ms   max_ms\n");
    hol_nav_desc sd = {0};
    sd.radius = 10;
    hol_nav *small;
    if (hol_nav_create(&sd, &small)) {
        printf("cannot create navigator\n");
        return 1;
    }
    bench_prefix(small, nav, 9, 12, 1000);
    bench_prefix(small, nav, 9, 12, 8000);
    hol_nav_destroy(small);
    printf("  default navigator (trusted 12) vs a radius-15 navigator (trusted 13)\n");
    hol_nav_desc bd = {0};
    bd.radius = 15;
    hol_nav *big;
    if (hol_nav_create(&bd, &big)) {
        printf("cannot create the radius-15 navigator\n");
    } else {
        bench_prefix(nav, big, 13, 13, 8000);
        hol_nav_destroy(big);
    }

    {
        /* the first tour builds the leg table */
        static uint8_t walk[HOL_NAV_WALK_MAX];
        hol_room s = hol_room_start();
        hol_tile key = random_target(&s, 2);
        hol_nav_result res;
        double tl = now_ms();
        hol_nav_tour(nav, &s, &key, 1, key, 0, walk, sizeof walk, &res);
        printf("\ntour leg table (state to state, radius 10, exact within %d): built "
               "on the first tour in %.0f ms\n", HOL_NAV_TOUR_EXACT_RADIUS, now_ms() - tl);
    }
    bench_tours(nav, 3, 0, "keys and chest at tile distance 1..3 from the start");
    bench_tours(nav, 5, 0, "keys and chest at tile distance 1..5 from the start");
    bench_tours(nav, 7, 20000, "keys and chest at tile distance 1..7, --budget 20000");
    bench_tours(nav, 7, 0, "keys and chest at tile distance 1..7, default budget (as the app)");
    bench_tours(nav, 8, 0, "keys and chest at tile distance 1..8, default budget (as the app)");
    if (getenv("NAV_BENCH_VERIFY"))
        bench_verify(nav);
    else
        printf("\n(NAV_BENCH_VERIFY=1 make bench adds a check of the anytime answers at "
               "13..15 against a radius-17 table)\n");
    hol_nav_destroy(nav);
    return 0;
}
