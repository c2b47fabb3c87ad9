/* light_probe.c - `make xr-test`'s look at a lit eye (tests/xr/lighting.sh).
 *
 *   light_probe EYE.png --point X,Y,Z RENDER-ARGS...
 *
 * RENDER-ARGS are the eye's `holonomy render` arguments as `holonomy xr
 * --check-frame` prints them ("xr: check eye E render --eye X,Y,Z --orient
 * X,Y,Z,W --tan L,R,D,U --size WxH --fireflies T"; the frame's time T
 * places the fireflies: taken and ignored here). The point (room
 * coordinates, metres: a lantern's glass) is projected through that eye
 * by a pinhole of its pose and tangents (the model, independent of the
 * renderer), and the picture is measured. Prints one line:
 *
 *   mean M at PX,PY disc D bright N centroid CX
 *
 * M the mean luma (0..255, Rec. 601 weights) of the whole picture; PX,PY
 * the point's pixel (x from the left, y from the top); D the mean luma of
 * the pixels within 3 px of it; N the number of pixels within 16 px of it
 * with luma at least 200 (the glass glows), CX their mean x (-1 if none).
 * Exit status: 0 ok, 1 the point is behind the eye, 2 bad arguments or a
 * file that cannot be read. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../platform/image/hol_png_file.h"

static int nums(const char *s, double *v, int n)
{
    for (int i = 0; i < n; i++) {
        char *end;
        v[i] = strtod(s, &end);
        if (end == s || (i < n - 1 && *end != ',') || (i == n - 1 && *end))
            return -1;
        s = end + 1;
    }
    return 0;
}

/* v turned by the inverse of the unit quaternion q (x, y, z, w) */
static void unturn(const double q[4], const double v[3], double out[3])
{
    double x = -q[0], y = -q[1], z = -q[2], w = q[3];
    double t[3] = {2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]),
                   2 * (x * v[1] - y * v[0])};
    out[0] = v[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = v[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = v[2] + w * t[2] + (x * t[1] - y * t[0]);
}

static double luma(const uint8_t *p)
{
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

int main(int argc, char **argv)
{
    double eye[3] = {0}, q[4] = {0, 0, 0, 1}, tan[4] = {0}, pt[3] = {0}, ff_t = 0;
    int got = 0, sw = 0, sh = 0;
    for (int i = 2; i + 1 < argc; i += 2) {
        const char *a = argv[i], *v = argv[i + 1];
        int bad = 0;
        if (!strcmp(a, "--eye"))
            bad = nums(v, eye, 3), got |= 1;
        else if (!strcmp(a, "--orient"))
            bad = nums(v, q, 4), got |= 2;
        else if (!strcmp(a, "--tan"))
            bad = nums(v, tan, 4), got |= 4;
        else if (!strcmp(a, "--point"))
            bad = nums(v, pt, 3), got |= 8;
        else if (!strcmp(a, "--size"))
            bad = sscanf(v, "%dx%d", &sw, &sh) != 2;
        else if (!strcmp(a, "--fireflies"))
            bad = nums(v, &ff_t, 1) || ff_t < 0;
        else
            bad = 1;
        if (bad) {
            fprintf(stderr, "light_probe: bad argument %s %s\n", a, v);
            return 2;
        }
    }
    uint8_t *img = NULL;
    int w, h;
    if (argc < 2 || argc % 2 || got != 15) {
        fprintf(stderr, "usage: light_probe EYE.png --point X,Y,Z --eye X,Y,Z --orient "
                        "X,Y,Z,W --tan L,R,D,U [--size WxH] [--fireflies T]\n");
        return 2;
    }
    if (hol_png_read_file(argv[1], &img, &w, &h) || (sw && (sw != w || sh != h))) {
        fprintf(stderr, "light_probe: cannot read '%s' (or not of --size)\n", argv[1]);
        return 2;
    }
    double d[3] = {pt[0] - eye[0], pt[1] - eye[1], pt[2] - eye[2]}, c[3];
    unturn(q, d, c);
    if (c[2] >= 0) {
        printf("behind\n");
        return 1;
    }
    double px = (c[0] / -c[2] - tan[0]) / (tan[1] - tan[0]) * w;
    double py = (tan[3] - c[1] / -c[2]) / (tan[3] - tan[2]) * h;
    double sum = 0, disc = 0, cx = 0;
    long nd = 0, nb = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double l = luma(img + 4 * ((size_t)y * (size_t)w + (size_t)x));
            double r = hypot(x + 0.5 - px, y + 0.5 - py);
            sum += l;
            if (r <= 3)
                disc += l, nd++;
            if (r <= 16 && l >= 200)
                cx += x + 0.5, nb++;
        }
    printf("mean %.2f at %.2f,%.2f disc %.2f bright %ld centroid %.2f\n", sum / ((double)w * h),
           px, py, nd ? disc / (double)nd : 0.0, nb, nb ? cx / (double)nb : -1.0);
    free(img);
    return 0;
}
