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
void hol__check(hol__xr *x, const hol_frame_desc *fd, int w, int h)
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
    /* the same eye for `holonomy render` (the host's check in make xr-test) */
    const hol_camera *c = &fd->cam;
    hol__say(x, "xr: check eye 0 render --eye %.9g,%.9g,%.9g --orient %.9g,%.9g,%.9g,%.9g "
                "--tan %.17g,%.17g,%.17g,%.17g --size %dx%d",
             c->eye[0], c->eye[1], c->eye[2], c->orient[0], c->orient[1], c->orient[2],
             c->orient[3], c->tan_left, c->tan_right, c->tan_down, c->tan_up, w, h);
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
        hol__say(x, "xr: check: the OSMesa reference render failed");
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
        hol__say(x, "xr: check frame %ld eye 0 %dx%d (%s swapchain): %ld pixels differ by more "
                    "than 8/255 (%.3f %%), largest difference %d",
                 x->d->check_frame, w, h, x->srgb ? "sRGB" : "linear", bad,
                 100.0 * (double)bad / ((double)w * h), worst);
    }
    free(ref2);
    free(got);
    free(ref);
}
#endif
