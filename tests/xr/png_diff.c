/* png_diff.c - `make xr-test`'s comparison of the swapchain read back in the
 * Monado chroot with the host build's `holonomy render` of the same eye.
 *
 *   png_diff A.png B.png   prints "N of M pixels differ by more than 8/255
 *                          (P %), largest difference D"; exit 0 when P is
 *                          at most 0.5, 1 when more, 2 on a bad file
 *
 * The tolerance is the render goldens' (tests/golden_compare.h): a pixel
 * differs when a colour channel is off by more than 8 of 255, and at most
 * 0.5 % of the pixels may differ. The two images come from two Mesa
 * releases (trixie's in the chroot, the host's) through two GL front ends
 * (GLX on Xvfb, OSMesa): llvmpipe rasterises both, but a shader compiler's
 * rounding may move a channel by a step or two and a triangle edge by a
 * pixel; a wrong pose, field of view, cell or world moves far more. */
#include <stdio.h>
#include <stdlib.h>

#include "../../platform/image/hol_png_file.h"

#define TOL 8
#define MAX_PCT 0.5

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: png_diff A.png B.png\n");
        return 2;
    }
    uint8_t *img[2] = {NULL, NULL};
    int w[2], h[2];
    for (int i = 0; i < 2; i++)
        if (hol_png_read_file(argv[1 + i], &img[i], &w[i], &h[i])) {
            fprintf(stderr, "png_diff: cannot read '%s'\n", argv[1 + i]);
            return 2;
        }
    if (w[0] != w[1] || h[0] != h[1]) {
        printf("sizes differ: %dx%d and %dx%d\n", w[0], h[0], w[1], h[1]);
        return 1;
    }
    long n = (long)w[0] * h[0], bad = 0;
    int worst = 0;
    for (long p = 0; p < n; p++) {
        int d = 0;
        for (int k = 0; k < 3; k++) {
            int c = abs((int)img[0][4 * p + k] - (int)img[1][4 * p + k]);
            d = c > d ? c : d;
        }
        worst = d > worst ? d : worst;
        bad += d > TOL;
    }
    double pct = 100.0 * (double)bad / (double)n;
    printf("%ld of %ld pixels differ by more than %d/255 (%.3f %%), largest difference %d\n",
           bad, n, TOL, pct, worst);
    free(img[0]);
    free(img[1]);
    return pct <= MAX_PCT ? 0 : 1;
}
