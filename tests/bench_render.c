/* bench_render.c - renderer budgets (make bench).
 *
 * Per eye at most 150 draw calls and 300k triangles; the hyperbolic view at
 * most 1.25x the CPU time of the euclidean baseline (same nine cells, no
 * portals) at 1440 x 1584 under llvmpipe, measured side by side in one run
 * (interleaved frames, median of each). Then the frame time per geometry
 * (SPEC 7): the tilings {4,4}..{4,8} in the 3 x 3 room, 5 x 5 rooms and a
 * 4 x 4 room of 0.7 m cells, from the room's south-west corner looking
 * across it (each tiling its own world, seed 2); the draw-call and
 * triangle budgets hold there too. Then dusk and night (issue 27): the
 * frame at night with 16 lanterns on the tiles in view (most drawn tiles
 * get the 4 they may have) against the same frame at day, interleaved in
 * the same run (target: at most 1.3x), in {4,5} and {4,6}, and the CPU
 * time of choosing every drawn tile's lights and trunk shadows
 * (hol_light_prepare, hol_light_tile and hol_light_shadows). Prints the figures; exits 1 when a budget is exceeded.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../core/hol_room.h"
#include "../core/hol_world.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_light.h"
#include "../render/hol_render.h"

#define BW 1440
#define BH 1584
#define FRAMES 7
#define LFRAMES 15 /* the lighting table's ratio: more frames, a steadier median */

typedef struct bview {
    const char *name, *walk;
    double eye[3], yaw, pitch;
} bview;

static const bview views[] = {
    {"centre", "-", {1.5, 1.6, 1.5}, 0, -30},
    {"corner", "NW", {0.2, 1.6, 0.2}, -135, -30},
    {"edge", "E", {2.5, 1.6, 1.05}, 90, -20},
    {"deep", "NWSSEEN", {2.3, 1.7, 1.6}, 200, -25},
};

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

typedef struct bgeom {
    int q, cols, rows;
    double cell;
} bgeom;

static const bgeom geoms[] = {
    {4, 3, 3, 1}, {5, 3, 3, 1}, {6, 3, 3, 1}, {7, 3, 3, 1}, {8, 3, 3, 1},
    {5, 5, 5, 1}, {8, 5, 5, 1}, {6, 4, 4, 0.7},
};

/* The frame time per geometry: 1 when a budget is exceeded. */
static int bench_geometries(hol_render *r)
{
    int over = 0;
    printf("  per geometry, from the south-west corner cell looking across the room:\n");
    printf("  %-14s %8s %9s %8s %8s %6s %9s\n", "geometry", "ms", "draws", "tris", "stencil",
           "branch", "queue ms");
    for (size_t i = 0; i < sizeof geoms / sizeof geoms[0]; i++) {
        const bgeom *g = &geoms[i];
        hol_world *world;
        hol_world_desc wd;
        memset(&wd, 0, sizeof wd);
        wd.seed = 2;
        wd.capacity = 1u << 14;
        wd.tiling_q = g->q;
        hol_frame_desc f;
        memset(&f, 0, sizeof f);
        if (hol_world_make(&wd, &world) ||
            hol_room_start_in(g->q, g->cols, g->rows, &f.user))
            return 1;
        while (f.user.col > 0)
            hol_room_step(&f.user, HOL_DIR_W);
        while (f.user.row < g->rows - 1)
            hol_room_step(&f.user, HOL_DIR_S);
        if (hol_world_update(world, &f.user))
            return 1;
        hol_render_set_world(r, world);
        f.cell_m = g->cell;
        f.cam.eye[0] = 0.15 * g->cell;
        f.cam.eye[1] = 1.6;
        f.cam.eye[2] = (g->rows - 0.15) * g->cell;
        f.cam.yaw_deg = -30;
        f.cam.pitch_deg = -22;
        f.cam.width = BW;
        f.cam.height = BH;
        f.flags = HOL_RENDER_MINIMAP | HOL_RENDER_WAIT; /* times incl. the GPU's */
        double t[FRAMES];
        hol_render_stats st;
        hol_render_frame(r, &f, &st); /* warm up */
        for (int k = 0; k < FRAMES; k++) {
            if (hol_render_frame(r, &f, &st))
                return 1;
            t[k] = st.cpu_ms;
        }
        qsort(t, FRAMES, sizeof t[0], cmp_d);
        char name[32];
        snprintf(name, sizeof name, "{4,%d} %dx%d %gm", g->q, g->cols, g->rows, g->cell);
        printf("  %-14s %8.2f %9d %8ld %8d %6d %9.3f\n", name, t[FRAMES / 2], st.draw_calls,
               st.triangles, st.stencil_passes, st.branches, st.build_ms);
        over |= st.draw_calls > 150 || st.triangles > 300000;
        hol_render_set_world(r, NULL);
        hol_world_destroy(world);
    }
    return over;
}

static double thread_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* The lights of every drawn tile of the last frame's view, chosen n times:
 * ms per frame; *out_mean the mean lights a tile, *out_four the tiles
 * with 4. */
static int pairs; /* the shadow pairs of the view's tiles (light_choice_ms) */

static double light_choice_ms(hol_render *r, const hol_frame_desc *f, int n, double *out_mean,
                              int *out_four, int *out_tiles)
{
    const hol_view *v = hol_render_last_view(r);
    static hol_light_frame lf;
    int sum = 0, four = 0, tiles = 0;
    pairs = 0;
    double t0 = thread_ms();
    for (int k = 0; k < n; k++) {
        hol_light_prepare(f, NULL, &lf);
        for (int b = 0; b < v->nbranches; b++) {
            double fr[9];
            int idx[HOL_LIGHT_PER_TILE];
            int nl = v->branches[b].err ? -1 : hol_light_tile(&lf, v->branches[b].state.tile,
                                                              fr, idx);
            if (nl > 0) { /* and its trunk shadows (hol_light_shadows), as the
                             renderer does: the lights in the tile's frame */
                double lp[HOL_LIGHT_PER_TILE][3];
                for (int j = 0; j < nl; j++) {
                    const double *p = lf.pos[idx[j]];
                    for (int i = 0; i < 3; i++) /* J F^T J: the inverse (hyperbolic) */
                        lp[j][i] = (i == 2 ? -1 : 1) * (fr[i] * p[0] + fr[3 + i] * p[1] -
                                                        fr[6 + i] * p[2]);
                }
                hol_shadow_set ss;
                hol_light_shadows(&lf, fr, (const double(*)[3])lp, idx, nl, &ss);
                if (k == 0) {
                    pairs += ss.n;
                    if (getenv("BENCH_PAIRS"))
                        printf("    branch %d (%d steps): %d pairs\n", b,
                               v->branches[b].nsteps, ss.n);
                }
            }
            if (k == 0 && nl >= 0) {
                sum += nl;
                four += nl == HOL_LIGHT_PER_TILE;
                tiles++;
            }
        }
    }
    double ms = (thread_ms() - t0) / n;
    *out_mean = tiles ? (double)sum / tiles : 0;
    *out_four = four;
    *out_tiles = tiles;
    return ms;
}

/* Night with lanterns against day, interleaved: 1 when over 1.3x. */
static int bench_lighting(hol_render *r)
{
    int over = 0;
    printf("  dusk and night: 16 lanterns on the tiles in view, the corner view, night / day\n");
    printf("  (ff: the same night with fireflies, as the app draws it; spot: and every\n"
           "  other lantern a spot, all in view)\n");
    printf("  %-8s %8s %8s %6s %10s %12s %14s %8s %6s %8s %6s\n", "tiling", "day ms",
           "night ms", "ratio", "dusk ms", "lights/tile", "choice ms", "ff ms", "ratio",
           "spot ms", "ratio");
    static const int qs[2] = {5, 6};
    for (int i = 0; i < 2; i++) {
        hol_world *world;
        hol_world_desc wd;
        memset(&wd, 0, sizeof wd);
        wd.seed = 2;
        wd.capacity = 1u << 14;
        wd.tiling_q = qs[i];
        hol_frame_desc f;
        memset(&f, 0, sizeof f);
        if (hol_world_make(&wd, &world) || hol_room_start_in(qs[i], 3, 3, &f.user))
            return 1;
        hol_room_step(&f.user, HOL_DIR_S);
        hol_room_step(&f.user, HOL_DIR_W);
        if (hol_world_update(world, &f.user))
            return 1;
        hol_render_set_world(r, world);
        f.cam.eye[0] = 0.15;
        f.cam.eye[1] = 1.6;
        f.cam.eye[2] = 2.85;
        f.cam.yaw_deg = -30;
        f.cam.pitch_deg = -22;
        f.cam.width = BW;
        f.cam.height = BH;
        f.flags = HOL_RENDER_MINIMAP | HOL_RENDER_WAIT; /* times incl. the GPU's */
        hol_render_stats st;
        hol_render_frame(r, &f, &st);
        const hol_view *v = hol_render_last_view(r);
        for (int b = 0; b < v->nbranches && f.nlanterns < HOL_RENDER_MAX_LANTERNS; b++) {
            int dup = v->branches[b].err != 0;
            for (int k = 0; k < f.nlanterns; k++)
                dup |= hol_tile_eq(f.lanterns[k], v->branches[b].state.tile);
            if (!dup)
                f.lanterns[f.nlanterns++] = v->branches[b].state.tile;
        }
        double td[LFRAMES], tn[LFRAMES], tk[LFRAMES], tf[LFRAMES], ts[LFRAMES];
        for (int w = 0; w < 2; w++) /* warm up */
            for (int l = 0; l < 3; l++) {
                f.lighting = l;
                hol_render_frame(r, &f, &st);
            }
        for (int k = 0; k < LFRAMES; k++) {
            f.lighting = HOL_LIGHT_DAY;
            if (hol_render_frame(r, &f, &st))
                return 1;
            td[k] = st.cpu_ms;
            f.lighting = HOL_LIGHT_NIGHT;
            if (hol_render_frame(r, &f, &st))
                return 1;
            tn[k] = st.cpu_ms;
            f.lighting = HOL_LIGHT_DUSK;
            if (hol_render_frame(r, &f, &st))
                return 1;
            tk[k] = st.cpu_ms;
            f.lighting = HOL_LIGHT_NIGHT;
            f.fireflies = 1;
            if (hol_render_frame(r, &f, &st))
                return 1;
            tf[k] = st.cpu_ms;
            for (int j = 0; j < f.nlanterns; j += 2)
                f.lantern_spot[j] = (uint8_t)(j % 3 ? 5 : 1 + j % 4);
            int e = hol_render_frame(r, &f, &st);
            f.fireflies = 0;
            memset(f.lantern_spot, 0, sizeof f.lantern_spot);
            if (e)
                return 1;
            ts[k] = st.cpu_ms;
        }
        qsort(td, LFRAMES, sizeof td[0], cmp_d);
        qsort(tn, LFRAMES, sizeof tn[0], cmp_d);
        qsort(tk, LFRAMES, sizeof tk[0], cmp_d);
        qsort(tf, LFRAMES, sizeof tf[0], cmp_d);
        qsort(ts, LFRAMES, sizeof ts[0], cmp_d);
        double mean;
        int four, tiles;
        double choice = light_choice_ms(r, &f, 1000, &mean, &four, &tiles);
        double ratio = tn[LFRAMES / 2] / td[LFRAMES / 2];
        char name[16], per[32];
        snprintf(name, sizeof name, "{4,%d}", qs[i]);
        snprintf(per, sizeof per, "%.2f (%d/%d: 4)", mean, four, tiles);
        printf("  (%s: %d trunk shadow pairs on the %d tiles)\n", qs[i] == 5 ? "{4,5}" : "{4,6}",
               pairs, tiles);
        double fratio = tf[LFRAMES / 2] / td[LFRAMES / 2];
        double sratio = ts[LFRAMES / 2] / td[LFRAMES / 2];
        printf("  %-8s %8.2f %8.2f %6.3f %10.2f %12s %14.4f %8.2f %6.3f %8.2f %6.3f\n", name,
               td[LFRAMES / 2], tn[LFRAMES / 2], ratio, tk[LFRAMES / 2], per, choice,
               tf[LFRAMES / 2], fratio, ts[LFRAMES / 2], sratio);
        over |= ratio > 1.3 || fratio > 1.3;
        hol_render_set_world(r, NULL);
        hol_world_destroy(world);
    }
    /* reported, not a failure of make bench: the target is not met
     * on llvmpipe (docs/performance.md#lighting) */
    printf("  night / day: target at most 1.3 %s\n", over ? "NOT MET" : "ok");
    return 0;
}

int main(void)
{
    hol_osmesa gl;
    char msg[256];
    if (hol_osmesa_create(&gl, BW, BH, msg, sizeof msg)) {
        fprintf(stderr, "bench_render: %s\n", msg);
        return 1;
    }
    hol_world *world;
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = 2;
    wd.capacity = 1u << 14;
    if (hol_world_make(&wd, &world)) {
        fprintf(stderr, "bench_render: cannot make the world\n");
        return 1;
    }
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = world;
    rd.getproc = hol_osmesa_getproc;
    hol_render *r;
    if (hol_render_create(&rd, &r)) {
        fprintf(stderr, "bench_render: cannot create the renderer\n");
        return 1;
    }
    int over = 0, max_dc = 0;
    long max_tri = 0;
    double sum_h = 0, sum_e = 0;
    if (getenv("BENCH_LIGHT_ONLY")) { /* the lighting table alone (quick runs) */
        over = bench_lighting(r);
        hol_render_destroy(r);
        hol_world_destroy(world);
        hol_osmesa_destroy(&gl);
        return over;
    }
    printf("bench_render: %dx%d, llvmpipe via OSMesa, world seed 2, HUD and minimap on,\n"
           "  median of %d interleaved frames (CPU ms: process time incl. llvmpipe threads)\n",
           BW, BH, FRAMES);
    printf("  %-8s %10s %10s %6s %9s %8s %8s %6s %9s\n", "view", "hyp ms", "eucl ms", "ratio",
           "draws", "tris", "stencil", "branch", "queue ms");
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
        const bview *bv = &views[i];
        hol_frame_desc f;
        memset(&f, 0, sizeof f);
        f.user = hol_room_start();
        for (const char *p = bv->walk; *p && *p != '-'; p++)
            hol_room_step(&f.user, hol_dir_from_char(*p));
        if (hol_world_update(world, &f.user))
            return 1;
        memcpy(f.cam.eye, bv->eye, sizeof f.cam.eye);
        f.cam.yaw_deg = bv->yaw;
        f.cam.pitch_deg = bv->pitch;
        f.cam.width = BW;
        f.cam.height = BH;
        f.flags = HOL_RENDER_MINIMAP | HOL_RENDER_WAIT; /* times incl. the GPU's */
        f.nobjectives = 1;
        hol_tile_resolve("Nrfl", -1, &f.objectives[0]);
        double th[FRAMES], te[FRAMES];
        hol_render_stats sh, se;
        /* warm up both (shader compilation, first-use costs) */
        hol_render_frame(r, &f, &sh);
        f.flags |= HOL_RENDER_EUCLIDEAN;
        hol_render_frame(r, &f, &se);
        for (int k = 0; k < FRAMES; k++) {
            f.flags &= ~HOL_RENDER_EUCLIDEAN;
            if (hol_render_frame(r, &f, &sh))
                return 1;
            th[k] = sh.cpu_ms;
            f.flags |= HOL_RENDER_EUCLIDEAN;
            if (hol_render_frame(r, &f, &se))
                return 1;
            te[k] = se.cpu_ms;
        }
        qsort(th, FRAMES, sizeof th[0], cmp_d);
        qsort(te, FRAMES, sizeof te[0], cmp_d);
        double mh = th[FRAMES / 2], me = te[FRAMES / 2];
        sum_h += mh;
        sum_e += me;
        printf("  %-8s %10.2f %10.2f %6.3f %9d %8ld %8d %6d %9.3f\n", bv->name, mh, me,
               mh / me, sh.draw_calls, sh.triangles, sh.stencil_passes, sh.branches,
               sh.build_ms);
        if (sh.draw_calls > max_dc)
            max_dc = sh.draw_calls;
        if (sh.triangles > max_tri)
            max_tri = sh.triangles;
    }
    double ratio = sum_h / sum_e;
    printf("  draw calls per eye: max %d (budget 150) %s\n", max_dc,
           max_dc <= 150 ? "ok" : "OVER BUDGET");
    printf("  triangles per eye:  max %ld (budget 300000) %s\n", max_tri,
           max_tri <= 300000 ? "ok" : "OVER BUDGET");
    printf("  CPU hyperbolic / euclidean: %.3f (budget 1.25) %s\n", ratio,
           ratio <= 1.25 ? "ok" : "OVER BUDGET");
    over = max_dc > 150 || max_tri > 300000 || ratio > 1.25;
    if (bench_geometries(r)) {
        printf("  a geometry is OVER BUDGET (150 draw calls, 300000 triangles)\n");
        over = 1;
    }
    over |= bench_lighting(r);
    hol_render_destroy(r);
    hol_world_destroy(world);
    hol_osmesa_destroy(&gl);
    return over ? 1 : 0;
}
