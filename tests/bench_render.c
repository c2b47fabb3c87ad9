/* bench_render.c - renderer budgets (make bench).
 *
 * Per eye at most 150 draw calls and 300k triangles; the hyperbolic view at
 * most 1.25x the CPU time of the euclidean baseline (same nine cells, no
 * portals) at 1440 x 1584 under llvmpipe, measured side by side in one run
 * (interleaved frames, median of each). Prints the figures; exits 1 when a
 * budget is exceeded.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_room.h"
#include "../core/hol_world.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_render.h"

#define BW 1440
#define BH 1584
#define FRAMES 7

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
        f.flags = HOL_RENDER_MINIMAP;
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
    hol_render_destroy(r);
    hol_world_destroy(world);
    hol_osmesa_destroy(&gl);
    return over ? 1 : 0;
}
