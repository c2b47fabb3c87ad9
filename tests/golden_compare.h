/* golden_compare.h - compare a rendered image with a reviewed golden PNG.
 *
 * A pixel differs when a channel is off by more than GOLDEN_TOL (8 of 255);
 * an image fails when more than 0.5 % of its pixels differ (llvmpipe
 * versions may round a few edge pixels differently). On failure the actual
 * image and a diff image (differing pixels red over a darkened copy of the
 * golden) are written to out_dir and named in the message.
 * Header-only; include it once per test program. */
#ifndef HOL_TEST_GOLDEN_COMPARE_H
#define HOL_TEST_GOLDEN_COMPARE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../platform/image/hol_png_file.h"

#define GOLDEN_TOL 8

/* 1 when HOL_GOLDEN_UPDATE=1 asks to write goldens instead of comparing. */
static int golden_update_requested(void)
{
    const char *e = getenv("HOL_GOLDEN_UPDATE");
    return e && e[0] == '1';
}

/* Where failures are written: GOLDEN_OUT, else golden-out beside the test
 * program (argv0's folder), else ./golden-out. */
static void golden_out_dir(char *out, size_t cap, const char *argv0)
{
    const char *env = getenv("GOLDEN_OUT");
    const char *slash = argv0 ? strrchr(argv0, '/') : NULL;
    if (env && *env)
        snprintf(out, cap, "%s", env);
    else if (slash)
        snprintf(out, cap, "%.*s/golden-out", (int)(slash - argv0), argv0);
    else
        snprintf(out, cap, "golden-out");
}

/* Compare img (w x h RGBA) with tests/golden/NAME.png; on failure write
 * out_dir/NAME+tag.actual.png and .diff.png and return 1; 0 when equal
 * within the tolerance. */
static int golden_compare(const char *name, const uint8_t *img, int w, int h, const char *tag,
                          const char *out_dir)
{
    char path[600], apath[600], dpath[600];
    snprintf(path, sizeof path, "tests/golden/%s.png", name);
    uint8_t *ref = NULL;
    int rw = 0, rh = 0;
    hol_err err = hol_png_read_file(path, &ref, &rw, &rh);
    if (err) {
        printf("golden: %s: cannot read (%s); run with HOL_GOLDEN_UPDATE=1 "
               "and review\n", path, hol_err_str(err));
        return 1;
    }
    if (rw != w || rh != h) {
        printf("golden: %s is %dx%d, expected %dx%d\n", path, rw, rh, w, h);
        free(ref);
        return 1;
    }
    uint8_t *diff = malloc((size_t)w * (size_t)h * 4);
    if (!diff) {
        free(ref);
        printf("golden: %s: out of memory\n", path);
        return 1;
    }
    int bad = 0, worst = 0;
    for (int p = 0; p < w * h; p++) {
        int d = 0;
        for (int k = 0; k < 3; k++) {
            int e = abs((int)img[4 * p + k] - (int)ref[4 * p + k]);
            d = e > d ? e : d;
        }
        worst = d > worst ? d : worst;
        uint8_t *o = diff + 4 * p;
        if (d > GOLDEN_TOL) {
            bad++;
            o[0] = 255;
            o[1] = o[2] = 0;
        } else {
            o[0] = ref[4 * p] / 3;
            o[1] = ref[4 * p + 1] / 3;
            o[2] = ref[4 * p + 2] / 3;
        }
        o[3] = 255;
    }
    free(ref);
    if (bad * 200 <= w * h) {
        free(diff);
        return 0;
    }
    mkdir(out_dir, 0777);
    snprintf(apath, sizeof apath, "%s/%s%s.actual.png", out_dir, name, tag);
    snprintf(dpath, sizeof dpath, "%s/%s%s.diff.png", out_dir, name, tag);
    hol_png_write_file(apath, img, w, h, 0);
    hol_png_write_file(dpath, diff, w, h, 0);
    free(diff);
    printf("golden: %s%s: %d pixels differ (max channel diff %d); see %s and %s\n", name,
           tag, bad, worst, apath, dpath);
    return 1;
}

#endif
