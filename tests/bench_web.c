/* bench_web.c - the same work natively and in wasm (make bench runs this
 * binary and its emcc build under node, tests/web/bench.mjs compares): the
 * navigator's table build, then the app step while a pancake user walks a
 * flag level (a fixed script at 72 Hz: forward, turns, back), per frame.
 * The mean per frame is process CPU time over a whole walk, the least of
 * five (natively
 * CLOCK_PROCESS_CPUTIME_ID, in node process.cpuUsage(): both without the
 * time other processes hold the shared cores); the 99th percentile and the
 * worst frame are wall-clock (wasm has no per-thread CPU clock), so they
 * carry the machine's preemptions. The last line's hash of
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

#ifdef __EMSCRIPTEN__
EM_JS(double, cpu_ms, (void), {
    var u = process.cpuUsage();
    return (u.user + u.system) / 1000;
});
static double now_ms(void)
{
    return emscripten_get_now();
}
#else
static double clock_ms(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}
static double now_ms(void)
{
    return clock_ms(CLOCK_MONOTONIC);
}
static double cpu_ms(void)
{
    return clock_ms(CLOCK_PROCESS_CPUTIME_ID);
}
#endif

#define FRAMES 10000

static uint64_t mix(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * UINT64_C(0x100000001b3);
    return h;
}

/* One walk of the level from its start. timed: each frame's wall-clock
 * time (p99, worst) is printed with prefix; untimed: the mean's process CPU
 * time per frame, with no clock read in the loop (a read from wasm is a
 * call out to JavaScript, a tenth of a microsecond or more). */
static int walk(hol_app *app, const hol_app_level *lvl, const char *prefix, int timed)
{
    static double dt[FRAMES];
    int nsteps = 0;
    if (hol_app_start_level(app, lvl))
        return 1;
    static double t_base; /* input time never goes back across walks */
    double base = t_base, cpu0 = cpu_ms();
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
        double a = timed ? now_ms() : 0;
        hol_err err = hol_app_step(app, &in);
        dt[f] = timed ? now_ms() - a : 0;
        if (err) {
            fprintf(stderr, "bench_web: step %d failed: %s\n", f, hol_err_str(err));
            return 1;
        }
        nsteps += hol_app_get_events(app)->nsteps;
    }
    double cpu = cpu_ms() - cpu0;
    qsort(dt, FRAMES, sizeof dt[0], bench_cmp_double);
    if (!timed) {
        static double best = -1;
        if (best < 0 || cpu < best)
            best = cpu;
        if (prefix) {
            printf("%sframes %d\n%sroom_steps %d\n", prefix, FRAMES, prefix, nsteps);
            printf("%sstep_cpu_mean_us %.3f\n", prefix, best / FRAMES * 1e3);
        }
    } else {
        printf("%sstep_p99_us %.2f\n%sstep_max_us %.2f\n", prefix, dt[FRAMES * 99 / 100] * 1e3,
               prefix, dt[FRAMES - 1] * 1e3);
    }
    return 0;
}

int main(void)
{
    double t0 = cpu_ms();
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    hol_nav *nav;
    if (hol_nav_create(&nd, &nav)) {
        fprintf(stderr, "bench_web: cannot create the navigator\n");
        return 1;
    }
    printf("nav_build_ms %.1f\n", cpu_ms() - t0); /* process CPU */
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    ad.nav = nav;
    hol_app *app;
    hol_level lv;
    if (hol_app_create(&ad, &app) || hol_campaign_mode_level("flag", 7, NULL, &lv)) {
        fprintf(stderr, "bench_web: cannot start the level\n");
        return 1;
    }
    /* the first walk warms up (wasm compiles in tiers as code runs), the
     * second is the figure */
    /* the mean: the least of five untimed walks (the same work each time) */
    if (walk(app, &lv.lvl, "cold_", 1) || walk(app, &lv.lvl, NULL, 0) ||
        walk(app, &lv.lvl, NULL, 0) || walk(app, &lv.lvl, NULL, 0) ||
        walk(app, &lv.lvl, NULL, 0) || walk(app, &lv.lvl, "", 0) || walk(app, &lv.lvl, "", 1))
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
