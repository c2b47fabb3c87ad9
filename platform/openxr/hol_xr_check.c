/* hol_xr_check.c - the desktop's read-back check of `holonomy xr
 * --check-frame` (see hol_xr_state.h): eye 0 read back from the swapchain
 * image against an OSMesa render of the same frame desc. Not on Android. */
#ifndef __ANDROID__
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../image/hol_png_file.h"
#include "../osmesa/hol_osmesa.h"

/* The OSMesa render of the same eye, in a child process (it must not share
 * this process's GLX state), against the swapchain's read back. */
void hol__xr_check(hol__xr *x, const hol_frame_desc *fd, int w, int h)
{
    size_t bytes = (size_t)w * (size_t)h * 4;
    uint8_t *got = malloc(bytes), *ref = malloc(bytes);
    if (!got || !ref) {
        free(got);
        free(ref);
        return;
    }
    hol_render_read_rgba(x->rnd, w, h, got);
    char path[600];
    snprintf(path, sizeof path, "%s/xr-eye0.png", x->d->check_dir);
    hol_png_write_file(path, got, w, h, 0);
    snprintf(path, sizeof path, "%s/osmesa-eye0.png", x->d->check_dir);
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        hol_osmesa o;
        char msg[256];
        hol_render *r = NULL;
        hol_render_desc rd;
        memset(&rd, 0, sizeof rd);
        rd.getproc = (hol_render_getproc)hol_osmesa_getproc;
        rd.world = x->fns->world(x->fns->user);
        if (hol_osmesa_create(&o, w, h, msg, sizeof msg) || hol_render_create(&rd, &r) ||
            hol_render_frame(r, fd, NULL))
            _exit(1);
        hol_render_read_rgba(r, w, h, ref);
        _exit(hol_png_write_file(path, ref, w, h, 0) ? 1 : 0);
    }
    int st = 1;
    if (pid > 0)
        waitpid(pid, &st, 0);
    uint8_t *ref2 = NULL;
    int rw = 0, rh = 0;
    if (pid < 0 || st != 0 || hol_png_read_file(path, &ref2, &rw, &rh) || rw != w || rh != h) {
        hol__xr_say(x, "xr: check: the OSMesa reference render failed");
    } else {
        long bad = 0;
        int worst = 0;
        for (size_t p = 0; p < (size_t)w * (size_t)h; p++) {
            int dmax = 0;
            for (int k = 0; k < 3; k++) {
                int dd = abs((int)got[4 * p + k] - (int)ref2[4 * p + k]);
                dmax = dd > dmax ? dd : dmax;
            }
            worst = dmax > worst ? dmax : worst;
            bad += dmax > 8;
        }
        hol__xr_say(x, "xr: check frame %ld eye 0 %dx%d (%s swapchain): %ld pixels differ by more "
                    "than 8/255 (%.3f %%), largest difference %d",
                    x->d->check_frame, w, h, x->srgb ? "sRGB" : "linear", bad,
                    100.0 * (double)bad / ((double)w * h), worst);
    }
    free(ref2);
    free(got);
    free(ref);
}
#endif

#ifndef __ANDROID__
/* v turned by the unit quaternion q (x, y, z, w); conj: by its inverse */
static void hol__turn(const double q[4], int conj, const double v[3], double out[3])
{
    double x = conj ? -q[0] : q[0], y = conj ? -q[1] : q[1], z = conj ? -q[2] : q[2], w = q[3];
    double t[3] = {2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]),
                   2 * (x * v[1] - y * v[0])};
    out[0] = v[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = v[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = v[2] + w * t[2] + (x * t[1] - y * t[0]);
}

/* Where the text block's top-left corner projects in the eye (pixels from
 * the left): the panel's documented layout (docs/headset.md: the block 136
 * font pixels wide, the map 6 + 64 beside it, the tops 32 above the
 * centre) and a pinhole of the eye's pose and tangents. -1: behind. */
static double hol__panel_corner(const hol_frame_desc *fd, int w)
{
    int map = (fd->flags & HOL_RENDER_MINIMAP) && !(fd->flags & HOL_RENDER_MINIMAP_HAND);
    double px = fd->panel_px > 0 ? fd->panel_px : HOL_RENDER_PANEL_PX;
    double u = -(136.0 + (map ? 70 : 0)) / 2 * px, v = 32 * px;
    static const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    double r[3], up[3], d[3], c[3];
    hol__turn(fd->panel_orient, 0, ex, r);
    hol__turn(fd->panel_orient, 0, ey, up);
    for (int k = 0; k < 3; k++)
        d[k] = fd->panel_pos[k] + u * r[k] + v * up[k] - fd->cam.eye[k];
    hol__turn(fd->cam.orient, 1, d, c);
    if (c[2] >= 0)
        return -1;
    double t = c[0] / -c[2];
    return (t - fd->cam.tan_left) / (fd->cam.tan_right - fd->cam.tan_left) * w;
}

static void hol__measure_panel(hol__xr *x, int e, const hol_frame_desc *fd, const uint8_t *bare,
                               const uint8_t *shown, int w, int h)
{
    const hol_camera *c = &fd->cam;
    long n = 0;
    int y0 = -1, left = w;
    double worst = 0;
    for (int y = 0; y < h; y++)
        for (int i = 0; i < w; i++) {
            size_t p = 4 * ((size_t)y * (size_t)w + (size_t)i);
            if (!memcmp(bare + p, shown + p, 3))
                continue;
            n++;
            y0 = y0 < 0 ? y : y0;
            if (y <= y0 + 3 && i < left)
                left = i; /* the block's first rows, whole pixels across: the
                           * first glyph's leftmost column (a T has it only
                           * in its top row) */
            double tx = c->tan_left + (i + 0.5) / w * (c->tan_right - c->tan_left);
            double ty = c->tan_up - (y + 0.5) / h * (c->tan_up - c->tan_down);
            double a = fabs(atan(tx)) > fabs(atan(ty)) ? fabs(atan(tx)) : fabs(atan(ty));
            worst = a > worst ? a : worst;
        }
    x->panel_left[e] = n ? left : -1;
    x->panel_pred[e] = hol__panel_corner(fd, w);
    hol__xr_say(x, "xr: check panel eye %d: %ld pixels, left edge %d px (predicted %.2f), at most "
                "%.1f degrees from the eye's axis",
                e, n, n ? left : -1, x->panel_pred[e], worst * 180 / 3.14159265358979323846);
    if (e == 1)
        hol__xr_say(x, "xr: check panel disparity %.0f px (predicted %.2f)",
                    x->panel_left[0] - x->panel_left[1], x->panel_pred[0] - x->panel_pred[1]);
}

/* The body's pixels in eye e: where the world drawn with it and without
 * it differ; "xr: check body eye E: N pixels (left K, right K)", K the
 * part drawn (hand: its joints, controller, none). */
static void hol__measure_body(hol__xr *x, int e, const hol_body *body, const uint8_t *without,
                              const uint8_t *with, int w, int h)
{
    static const char *kind[] = {"none", "controller", "hand"};
    long n = 0;
    for (long p = 0; p < (long)w * h; p++)
        n += memcmp(without + 4 * p, with + 4 * p, 3) != 0;
    int l = body->hand[HOL_HAND_LEFT].kind, r = body->hand[HOL_HAND_RIGHT].kind;
    hol__xr_say(x, "xr: check body eye %d: %ld pixels (left %s, right %s)", e, n,
                kind[l >= 0 && l <= 2 ? l : 0], kind[r >= 0 && r <= 2 ? r : 0]);
}

void hol__xr_check_eye(hol__xr *x, int e, const hol_frame_desc *fd, unsigned fbo, int w, int h)
{
    size_t bytes = (size_t)w * (size_t)h * 4;
    uint8_t *bare = malloc(bytes), *shown = malloc(bytes);
    /* the world: no HUD, and no body (the controllers are not the world's:
     * `holonomy render` draws none) */
    hol_frame_desc b = *fd;
    b.flags |= HOL_RENDER_NO_HUD;
    b.body = NULL;
    if (!bare || !shown || hol_render_frame(x->rnd, &b, NULL) != HOL_OK) {
        free(bare);
        free(shown);
        return;
    }
    hol_render_read_rgba(x->rnd, w, h, bare);
    /* the eye's world (no HUD) as a PNG, and the eye for `holonomy render`
     * (make xr-test's host half renders both eyes again from these lines) */
    char path[600];
    snprintf(path, sizeof path, "%s/xr-world-eye%d.png", x->d->check_dir, e);
    hol_png_write_file(path, bare, w, h, 0);
    const hol_camera *c = &b.cam;
    hol__xr_say(x, "xr: check eye %d render --eye %.9g,%.9g,%.9g --orient %.9g,%.9g,%.9g,%.9g "
                "--tan %.17g,%.17g,%.17g,%.17g --size %dx%d --fireflies %.17g",
                e, c->eye[0], c->eye[1], c->eye[2], c->orient[0], c->orient[1], c->orient[2],
                c->orient[3], c->tan_left, c->tan_right, c->tan_down, c->tan_up, w, h,
                b.fireflies ? b.time_s : 0.0);
    if (e == 0) /* the world against the renders without a HUD */
        hol__xr_check(x, &b, w, h);
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, fbo);
    if (fd->body) { /* the panel's pixels: as shown against the same without the HUD */
        b.body = fd->body;
        if (hol_render_frame(x->rnd, &b, NULL) == HOL_OK) {
            hol_render_read_rgba(x->rnd, w, h, shown);
            hol__measure_body(x, e, fd->body, bare, shown, w, h);
            memcpy(bare, shown, bytes);
        }
    }
    if (hol_render_frame(x->rnd, fd, NULL) == HOL_OK) {
        hol_render_read_rgba(x->rnd, w, h, shown);
        snprintf(path, sizeof path, "%s/xr-shown-eye%d.png", x->d->check_dir, e);
        hol_png_write_file(path, shown, w, h, 0);
        hol__measure_panel(x, e, fd, bare, shown, w, h);
    }
    free(bare);
    free(shown);
}
#endif
