/* bench_web.c - the same work natively and in wasm (make bench runs this
 * binary and its emcc build under node, tests/web/bench.mjs compares): the
 * navigator's table build, then the app step while a pancake user walks a
 * flag level (a fixed script at 72 Hz: forward, turns, back), per frame.
 * Times are wall-clock monotonic in both (wasm has no thread CPU clock):
 * the mean per frame over the whole walk, the 99th percentile and the
 * worst frame (a room step: world update and guidance replan). The last line's hash of
 * the final view proves both ran the same frames to the same bits.
 *
 * Output, one figure a line: "KEY VALUE".
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

#include "../core/hol_app.h"
#include "../core/hol_campaign.h"
#include "../core/hol_nav.h"
#include "bench_util.h"

static double now_ms(void)
{
#ifdef __EMSCRIPTEN__
    return emscripten_get_now();
#else
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
#endif
}

#define FRAMES 10000

static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * UINT64_C(0x100000001b3);
    return h;
}

/* One walk of the level from its start; prints the figures with prefix. */
static int walk(hol_app *app, const hol_app_level *lvl, const char *prefix)
{
    static double dt[FRAMES];
    int nsteps = 0;
    double total = 0;
    if (hol_app_start_level(app, lvl))
        return 1;
    static double t_base; /* input time never goes back across walks */
    double base = t_base;
    for (int f = 0; f < FRAMES; f++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = base + f / 72.0;
        t_base = in.time_s;
        in.flags = HOL_INPUT_FOCUSED;
        int phase = f / 144 % 5; /* 2 s each: forward, turn, forward, back, strafe */
        in.move[1] = phase == 0 || phase == 2 ? 1.0f : phase == 3 ? -1.0f : 0.0f;
        in.move[0] = phase == 4 ? 1.0f : 0.0f;
        in.turn[0] = phase == 1 ? 0.6f : 0.0f;
        double a = now_ms();
        hol_err err = hol_app_step(app, &in);
        dt[f] = now_ms() - a;
        total += dt[f];
        if (err) {
            fprintf(stderr, "bench_web: step %d failed: %s\n", f, hol_err_str(err));
            return 1;
        }
        nsteps += hol_app_get_events(app)->nsteps;
    }
    qsort(dt, FRAMES, sizeof dt[0], bench_cmp_double);
    printf("%sframes %d\n%sroom_steps %d\n", prefix, FRAMES, prefix, nsteps);
    printf("%sstep_mean_us %.2f\n%sstep_p99_us %.2f\n%sstep_max_us %.2f\n", prefix,
           total / FRAMES * 1e3, prefix, dt[FRAMES * 99 / 100] * 1e3, prefix,
           dt[FRAMES - 1] * 1e3);
    return 0;
}

int main(void)
{
    double t0 = now_ms();
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    hol_nav *nav;
    if (hol_nav_create(&nd, &nav)) {
        fprintf(stderr, "bench_web: cannot create the navigator\n");
        return 1;
    }
    printf("nav_build_ms %.1f\n", now_ms() - t0);
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    ad.nav = nav;
    hol_app *app;
    hol_level lv;
    if (hol_app_create(&ad, &app) || hol_campaign_mode_level("flag", 7, &lv)) {
        fprintf(stderr, "bench_web: cannot start the level\n");
        return 1;
    }
    /* the first walk warms up (wasm compiles in tiers as code runs), the
     * second is the figure */
    if (walk(app, &lv.lvl, "cold_") || walk(app, &lv.lvl, ""))
        return 1;
    const hol_app_view *v = hol_app_get_view(app);
    uint64_t h = UINT64_C(0xcbf29ce484222325);
    h = mix(h, v->head, sizeof v->head);
    h = mix(h, &v->yaw_deg, sizeof v->yaw_deg);
    h = mix(h, &v->hud.steps, sizeof v->hud.steps);
    h = mix(h, v->hud.address, strlen(v->hud.address));
    printf("view_hash %016llx\n", (unsigned long long)h);
    hol_app_destroy(app);
    hol_nav_destroy(nav);
    return 0;
}
