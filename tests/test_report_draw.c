/* test_report_draw.c - the report's per-attempt pictures
 * (platform/cli/report/report_draw.h) and their PNG writer (hol_png_encode_indexed):
 * - the view's map against an independent model: the Poincare disk's Mobius
 *   maps z -> e^{ia} (z - t) / (1 - conj(t) z) in complex numbers, and
 *   hyperbolic distances 2 atanh |(z - w) / (1 - conj(w) z)| kept;
 * - the centre tile is the walk's tile nearest its centroid (by disk
 *   distances), and it lands on the view's centre;
 * - a straight walk of 8 tiles is no longer squeezed into a thin rim;
 * - pixels: the first step in the ramp's first colour, the last in its
 *   last, the start green, an edge walked back drawn beside the first pass,
 *   the legend's ramp and marks in the bottom band;
 * - the step numbers of a walk back and forth through the start and a goal:
 *   no number's box meets a mark's or comes within 2 font pixels of another
 *   number's, the first and the
 *   last are shown, the text is drawn only in the boxes, the marks whole;
 * - the indexed PNG decodes (render/hol_png.c and zlib) to the same pixels.
 */
#include <complex.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <zlib.h>

#include "../core/hol_hyper.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../platform/cli/report/report_draw.h"
#include "../render/hol_png.h"

int cli_caught_signal(void); /* report_draw's one use of the CLI: no signal here */
int cli_caught_signal(void)
{
    return 0;
}

#define SIZE 480
static uint8_t px[SIZE * SIZE];

static hol_tile tile(const char *s)
{
    hol_tile t;
    assert_int_equal(hol_tile_parse(s, (ptrdiff_t)strlen(s), &t), HOL_OK);
    return t;
}

static hol_room start(void)
{
    hol_room r;
    assert_int_equal(hol_room_start_in(5, 3, 3, &r), HOL_OK);
    return r;
}

/* A tile's Poincare-disk point seen from the start (no view). */
static double complex disk(hol_room s, hol_tile t)
{
    double p[3];
    assert_int_equal(hol_hyper_pos(s.tile, s.orient, t, p, NULL, NULL), HOL_OK);
    return p[0] / (1 + p[2]) + I * (p[1] / (1 + p[2]));
}

static double dist(double complex z, double complex w)
{
    return 2 * atanh(cabs((z - w) / (1 - conj(w) * z)));
}

/* The view's disk point of t (report_view_px without the zoom). */
static double complex view_disk(const report_view *v, hol_room s, hol_tile t)
{
    double p[3], o[2], c[2], zero[3] = {0, 0, 1};
    report_view w = *v;
    assert_int_equal(hol_hyper_pos(s.tile, s.orient, t, p, NULL, NULL), HOL_OK);
    w.zoom = 0;
    report_view_px(&w, 0, SIZE, p, o);
    memset(w.m, 0, sizeof w.m);
    w.m[0] = w.m[4] = w.m[8] = 1;
    report_view_px(&w, 0, SIZE, zero, c); /* the view's centre, in pixels */
    double r = (SIZE - report_legend_height(SIZE)) / 2.0 - 4;
    return (o[0] - c[0]) / r - I * (o[1] - c[1]) / r;
}

static const char *const wander[] = {"N", "Nf", "Nfl", "Nflf", "Nflfr", "Nflf", "Nfl", "Nflr"};

static void test_view_is_a_mobius_map(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[8];
    for (int i = 0; i < 8; i++)
        w[i] = tile(wander[i]);
    report_picture p = {.start = s, .walked = w, .nwalked = 8};
    report_view v;
    assert_int_equal(report_view_fit(&p, &v), HOL_OK);
    /* the centre tile: the walk's tile nearest its centroid, found here by
     * disk distances to the centroid's disk point */
    double complex c = v.centre[0] / (1 + v.centre[2]) + I * (v.centre[1] / (1 + v.centre[2]));
    hol_tile pts[9] = {s.tile};
    memcpy(pts + 1, w, sizeof w);
    int best = 0;
    for (int i = 1; i < 9; i++)
        if (dist(disk(s, pts[i]), c) < dist(disk(s, pts[best]), c) - 1e-9)
            best = i;
    assert_true(hol_tile_eq(v.tile, pts[best]));
    double complex t = disk(s, v.tile);
    assert_true(cabs(view_disk(&v, s, v.tile)) < 1e-9);
    /* every point: the Mobius map taking t to 0, up to one rotation */
    double complex rot = 0;
    for (int i = 0; i < 9; i++) {
        double complex z = disk(s, pts[i]), m = (z - t) / (1 - conj(t) * z);
        double complex got = view_disk(&v, s, pts[i]);
        assert_true(fabs(cabs(got) - cabs(m)) < 1e-9);
        if (cabs(m) > 0.1 && rot == 0)
            rot = got / m;
        else if (cabs(m) > 0.1)
            assert_true(cabs(got / m - rot) < 1e-9);
        for (int j = 0; j < i; j++) /* distances kept */
            assert_true(fabs(dist(got, view_disk(&v, s, pts[j])) -
                             dist(z, disk(s, pts[j]))) < 1e-9);
    }
    assert_true(fabs(cabs(rot) - 1) < 1e-9);
    /* the centroid lands as far from the centre as it is from T */
    double q[3], o[2];
    report_view z0 = v;
    z0.zoom = 0;
    report_view_px(&z0, 0, SIZE, v.centre, o);
    (void)q;
    double r = (SIZE - report_legend_height(SIZE)) / 2.0 - 4;
    double complex cv = (o[0] - SIZE / 2.0) / r - I * (o[1] - (r + 4)) / r;
    assert_true(fabs(dist(cv, 0) - dist(c, t)) < 1e-9);

}

/* A straight walk N, Nf, ... Nfffffff: its tiles' radii in the view. */
static void test_long_walk_not_in_the_rim(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[8];
    char a[16] = "N";
    for (int i = 0; i < 8; i++) {
        w[i] = tile(a);
        strcat(a, "f");
    }
    report_picture p = {.start = s, .walked = w, .nwalked = 8};
    report_view v;
    assert_int_equal(report_view_fit(&p, &v), HOL_OK);
    /* each step's length on the screen (in view radii), centred on the
     * start (the pictures before) and on the walk */
    double minstep_old = 1, minstep_new = 1, far = 0, sum = 0;
    for (int i = 1; i < 8; i++) {
        minstep_old = fmin(minstep_old, cabs(disk(s, w[i]) - disk(s, w[i - 1])));
        minstep_new = fmin(minstep_new, cabs(view_disk(&v, s, w[i]) - view_disk(&v, s, w[i - 1])));
    }
    for (int i = 0; i < 8; i++) {
        far = fmax(far, cabs(view_disk(&v, s, w[i])));
        sum += cabs(view_disk(&v, s, w[i]));
    }
    assert_true(minstep_old < 0.002); /* under half a pixel of 480: the rim */
    assert_true(minstep_new > 0.02);  /* over 4 pixels */
    assert_true(far < 0.975);
    assert_true(sum / 8 < 0.7);
}

static uint32_t rgb_at(int x, int y)
{
    uint8_t plte[768];
    int n = report_palette(plte);
    int i = px[(size_t)y * SIZE + (size_t)x];
    assert_true(i < n);
    return (uint32_t)plte[3 * i] << 16 | (uint32_t)plte[3 * i + 1] << 8 | plte[3 * i + 2];
}

/* The pixel of the geodesic midpoint between tiles a and b. */
static void mid_px(const report_view *v, hol_room s, hol_tile a, hol_tile b, double out[2])
{
    double p[3], q[3], m[3];
    hol_hyper_pos(s.tile, s.orient, a, p, NULL, NULL);
    hol_hyper_pos(s.tile, s.orient, b, q, NULL, NULL);
    for (int i = 0; i < 3; i++)
        m[i] = p[i] + q[i];
    double n = sqrt(m[2] * m[2] - m[0] * m[0] - m[1] * m[1]);
    for (int i = 0; i < 3; i++)
        m[i] /= n;
    report_view_px(v, 0, SIZE, m, out);
}

static void test_pixels_of_a_small_walk(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[4] = {tile("N"), tile("Nf"), tile("Nfl"), tile("Nflf")};
    hol_tile goal = tile("Nflff");
    report_picture p = {.start = s, .walked = w, .nwalked = 4, .goals = &goal, .ngoals = 1};
    report_view v;
    assert_int_equal(report_view_fit(&p, &v), HOL_OK);
    assert_int_equal(report_draw(&p, px, SIZE), HOL_OK);
    double m[2], o[3], x[2];
    mid_px(&v, s, s.tile, w[0], m);
    assert_int_equal(rgb_at((int)m[0], (int)m[1]), REPORT_RGB_RAMP0);
    mid_px(&v, s, w[2], w[3], m);
    assert_int_equal(rgb_at((int)m[0], (int)m[1]), REPORT_RGB_RAMP1);
    hol_hyper_pos(s.tile, s.orient, s.tile, o, NULL, NULL);
    report_view_px(&v, 0, SIZE, o, x);
    assert_int_equal(rgb_at((int)x[0], (int)x[1]), 0x1e9b3c); /* the start */
    /* the legend band: every ramp colour, the start and the goal */
    int band = report_legend_height(SIZE), seen[4] = {0, 0, 0, 0};
    for (int y = SIZE - band; y < SIZE; y++)
        for (int i = 0; i < SIZE; i++) {
            uint32_t c = rgb_at(i, y);
            seen[0] |= c == REPORT_RGB_RAMP0;
            seen[1] |= c == REPORT_RGB_RAMP1;
            seen[2] |= c == 0x1e9b3c;
            seen[3] |= c == 0xd21e1e;
        }
    assert_true(seen[0] && seen[1] && seen[2] && seen[3]);
}

/* N, then back: the way back is drawn beside the way there. */
static void test_walked_back_beside(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[2] = {tile("N"), s.tile};
    report_picture p = {.start = s, .walked = w, .nwalked = 2};
    report_view v;
    assert_int_equal(report_view_fit(&p, &v), HOL_OK);
    assert_int_equal(report_draw(&p, px, SIZE), HOL_OK);
    double m[2];
    mid_px(&v, s, s.tile, w[0], m);
    int there = 0, back = 0;
    for (int d = -30; d <= 30; d++) { /* across the edge (vertical on the screen) */
        for (int e = -30; e <= 30; e++) {
            int xx = (int)m[0] + d, yy = (int)m[1] + e;
            uint32_t c = rgb_at(xx, yy);
            there += c == REPORT_RGB_RAMP0;
            back += c == REPORT_RGB_RAMP1;
        }
    }
    assert_true(there > 50);
    assert_true(back > 50);
}

static int meets(const report_box *a, const report_box *b)
{
    return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

/* The pixels within rad - 1 of the tile's centre are all of colour rgb (a
 * mark no number covers). */
static void assert_disk(const report_view *v, hol_room s, hol_tile t, int size, double rad,
                        uint32_t rgb)
{
    double o[3], x[2];
    uint8_t plte[768];
    report_palette(plte);
    assert_int_equal(hol_hyper_pos(s.tile, s.orient, t, o, NULL, NULL), HOL_OK);
    report_view_px(v, 0, size, o, x);
    for (int j = (int)(x[1] - rad); j <= (int)(x[1] + rad); j++)
        for (int i = (int)(x[0] - rad); i <= (int)(x[0] + rad); i++) {
            double dx = i + 0.5 - x[0], dy = j + 0.5 - x[1];
            if (dx * dx + dy * dy > (rad - 1) * (rad - 1))
                continue;
            const uint8_t *c = plte + 3 * px[(size_t)j * (size_t)size + (size_t)i];
            if (((uint32_t)c[0] << 16 | (uint32_t)c[1] << 8 | c[2]) != rgb)
                fail_msg("a mark's pixel %d,%d is %02x%02x%02x, not %06x", i, j, c[0], c[1],
                         c[2], rgb);
        }
}

/* Back and forth through the start and a goal: every number's box lies in
 * the view, meets no mark's box and no other number's; the first and the
 * last are there; the drawn text is only in the boxes; the marks' disks
 * stay whole. At 480 (font pixels 2 x 2) and 160 (1 x 1). */
static void test_numbers_beside_the_marks(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[13] = {tile("N"),  s.tile, tile("E"), s.tile, tile("N"), s.tile, tile("W"),
                      s.tile,     tile("S"), s.tile, tile("N"), tile("Nf"), tile("N")};
    hol_tile goals[2] = {tile("Nf"), tile("E")};
    report_picture p = {.start = s, .walked = w, .nwalked = 13, .goals = goals, .ngoals = 2};
    static const int sizes[2] = {480, 160};
    for (int z = 0; z < 2; z++) {
        int size = sizes[z], bottom = size - report_legend_height(size);
        report_view v;
        report_label l[REPORT_LABELS_MAX];
        report_box m[8];
        assert_int_equal(report_view_fit(&p, &v), HOL_OK);
        int nl = report_step_labels(&p, &v, size, l), nm = report_mark_boxes(&p, &v, size, m, 8);
        assert_int_equal(nm, 4); /* the start, two goals, the end */
        /* the marks' boxes hold their disks: the start's radius size/80 + 2 */
        double o[3], x[2];
        assert_int_equal(hol_hyper_pos(s.tile, s.orient, s.tile, o, NULL, NULL), HOL_OK);
        report_view_px(&v, 0, size, o, x);
        double rs = size / 80.0 + 2;
        assert_true(m[0].x0 <= x[0] - rs && m[0].x1 >= x[0] + rs && m[0].y0 <= x[1] - rs &&
                    m[0].y1 >= x[1] + rs);
        int first = 0, last = 0;
        for (int i = 0; i < nl; i++) {
            first |= l[i].step == 1;
            last |= l[i].step == 13;
            assert_true(l[i].box.x0 >= 0 && l[i].box.y0 >= 0 && l[i].box.x1 <= size &&
                        l[i].box.y1 <= bottom);
            for (int j = 0; j < nm; j++)
                if (meets(&l[i].box, &m[j]))
                    fail_msg("size %d: step %ld's number meets mark %d", size, l[i].step, j);
            int g = size >= 400 ? 4 : 2; /* 2 font pixels apart */
            report_box near = {l[i].box.x0 - g, l[i].box.y0 - g, l[i].box.x1 + g,
                               l[i].box.y1 + g};
            for (int j = 0; j < i; j++)
                if (meets(&near, &l[j].box))
                    fail_msg("size %d: steps %ld and %ld's numbers meet", size, l[i].step,
                             l[j].step);
        }
        assert_true(first && last);
        assert_true(nl >= 8); /* most of the 13 find a place: around the start */
        /* the picture: dark text pixels only in the numbers' boxes */
        assert_int_equal(report_draw(&p, px, size), HOL_OK);
        uint8_t plte[768];
        report_palette(plte);
        for (int y = 0; y < bottom; y++)
            for (int i = 0; i < size; i++) {
                const uint8_t *c = plte + 3 * px[(size_t)y * (size_t)size + (size_t)i];
                if (c[0] != 0x20 || c[1] != 0x20 || c[2] != 0x20)
                    continue;
                int in = 0;
                for (int j = 0; !in && j < nl; j++)
                    in = i >= l[j].box.x0 && i < l[j].box.x1 && y >= l[j].box.y0 &&
                         y < l[j].box.y1;
                if (!in)
                    fail_msg("size %d: text at %d,%d outside the numbers' boxes", size, i, y);
            }
        assert_disk(&v, s, s.tile, size, size / 80.0 + 2, 0x1e9b3c);
        assert_disk(&v, s, goals[0], size, size / 60.0 + 2, 0xd21e1e);
        assert_disk(&v, s, goals[1], size, size / 60.0 + 2, 0xd21e1e);
    }
}

/* The indexed PNG: zlib and render/hol_png.c decode it to the same pixels. */
static void test_indexed_png_round_trip(void **state)
{
    (void)state;
    hol_room s = start();
    hol_tile w[3] = {tile("N"), tile("Nf"), tile("N")};
    report_picture p = {.start = s, .walked = w, .nwalked = 3};
    assert_int_equal(report_draw(&p, px, SIZE), HOL_OK);
    for (int i = 0; i < 2000; i++) /* and noise: literals, not only runs */
        px[(size_t)i * 97 % (SIZE * SIZE)] = (uint8_t)(i % 30);
    uint8_t plte[768], *data, *rgba;
    int n = report_palette(plte), w2, h2;
    size_t size;
    assert_int_equal(hol_png_encode_indexed(px, SIZE, SIZE, plte, n, &data, &size), HOL_OK);
    assert_int_equal(hol_png_decode(data, size, &rgba, &w2, &h2), HOL_OK);
    assert_int_equal(w2, SIZE);
    assert_int_equal(h2, SIZE);
    for (int i = 0; i < SIZE * SIZE; i++)
        assert_memory_equal(rgba + 4 * i, plte + 3 * px[i], 3);
    free(rgba);
    /* zlib's own inflate: the filtered rows, "up" */
    size_t at = 8 + 25 + 12 + 3 * (size_t)n;
    uint32_t zn = (uint32_t)data[at] << 24 | (uint32_t)data[at + 1] << 16 |
                  (uint32_t)data[at + 2] << 8 | data[at + 3];
    assert_memory_equal(data + at + 4, "IDAT", 4);
    uLongf rawn = (uLongf)(SIZE + 1) * SIZE;
    uint8_t *raw = malloc(rawn);
    assert_int_equal(uncompress(raw, &rawn, data + at + 8, zn), Z_OK);
    assert_int_equal(rawn, (SIZE + 1) * SIZE);
    assert_int_equal(raw[0], 2);
    assert_int_equal(raw[SIZE + 2], (uint8_t)(px[SIZE] - px[0]));
    free(raw);
    free(data);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_view_is_a_mobius_map),
        cmocka_unit_test(test_long_walk_not_in_the_rim),
        cmocka_unit_test(test_pixels_of_a_small_walk),
        cmocka_unit_test(test_walked_back_beside),
        cmocka_unit_test(test_numbers_beside_the_marks),
        cmocka_unit_test(test_indexed_png_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
