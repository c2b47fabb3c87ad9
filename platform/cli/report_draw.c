/* report_draw.c - an attempt's walks on the Poincare disk (report_draw.h). */
#include "report_draw.h"

#include <math.h>
#include <string.h>

#include "../../core/hol_hyper.h"
#include "cli.h"

typedef struct canvas {
    uint8_t *px;
    int size;
    double cx, cy, r; /* the disk's centre and radius in pixels */
    int flat;         /* {4,4}: plane coordinates scaled by 1 / extent */
    int clip;         /* 1: pixels outside the disk are left alone */
    double extent;
    hol_room start;
} canvas;

static void put(canvas *c, int x, int y, uint32_t rgb)
{
    if (x < 0 || y < 0 || x >= c->size || y >= c->size)
        return;
    double dx = x + 0.5 - c->cx, dy = y + 0.5 - c->cy;
    if (c->clip && dx * dx + dy * dy > (c->r - 1.5) * (c->r - 1.5))
        return;
    uint8_t *p = c->px + ((size_t)y * (size_t)c->size + (size_t)x) * 4;
    p[0] = (uint8_t)(rgb >> 16);
    p[1] = (uint8_t)(rgb >> 8);
    p[2] = (uint8_t)rgb;
    p[3] = 255;
}

/* Pixels a..b of row j (put's checks, made once for the row). */
static void span(canvas *c, int a, int b, int j, uint32_t rgb)
{
    if (j < 0 || j >= c->size || c->clip) {
        for (int i = a; i <= b; i++)
            put(c, i, j, rgb);
        return;
    }
    a = a < 0 ? 0 : a;
    b = b >= c->size ? c->size - 1 : b;
    uint8_t px[4] = {(uint8_t)(rgb >> 16), (uint8_t)(rgb >> 8), (uint8_t)rgb, 255};
    uint8_t *p = c->px + ((size_t)j * (size_t)c->size + (size_t)(a < 0 ? 0 : a)) * 4;
    for (int i = a; i <= b; i++, p += 4)
        memcpy(p, px, 4);
}

/* Pixel (i, j)'s centre within rad of (x, y): the one test dot makes. */
static int in_disc(int i, int j, double x, double y, double rad)
{
    double dx = i + 0.5 - x, dy = j + 0.5 - y;
    return dx * dx + dy * dy <= rad * rad;
}

/* The pixels whose centres are within rad of (x, y), a row at a time: the
 * row's span from one square root, its ends settled by in_disc (so the
 * pixels are exactly those the test picks; on a row they are contiguous). */
static void dot(canvas *c, double x, double y, double rad, uint32_t rgb)
{
    int i0 = (int)floor(x - rad), i1 = (int)ceil(x + rad);
    for (int j = (int)floor(y - rad); j <= (int)ceil(y + rad); j++) {
        double dy = j + 0.5 - y, s2 = rad * rad - dy * dy;
        if (s2 < 0)
            s2 = 0;
        double s = sqrt(s2);
        int a = (int)floor(x - s - 0.5), b = (int)ceil(x + s - 0.5);
        a = a < i0 ? i0 : a;
        b = b > i1 ? i1 : b;
        while (a > i0 && in_disc(a - 1, j, x, y, rad))
            a--;
        while (a <= b && !in_disc(a, j, x, y, rad))
            a++;
        while (b < i1 && in_disc(b + 1, j, x, y, rad))
            b++;
        while (b >= a && !in_disc(b, j, x, y, rad))
            b--;
        span(c, a, b, j, rgb);
    }
}

static void ring(canvas *c, double x, double y, double rad, double w, uint32_t rgb)
{
    for (int j = (int)floor(y - rad); j <= (int)ceil(y + rad); j++)
        for (int i = (int)floor(x - rad); i <= (int)ceil(x + rad); i++) {
            double dx = i + 0.5 - x, dy = j + 0.5 - y, d = sqrt(dx * dx + dy * dy);
            if (d <= rad && d >= rad - w)
                put(c, i, j, rgb);
        }
}

/* Discs every half pixel from a to b; from the second when first is 0 (a
 * piece continuing another, whose last disc is the same). */
static void line(canvas *c, const double a[2], const double b[2], double w, uint32_t rgb,
                 int first)
{
    double dx = b[0] - a[0], dy = b[1] - a[1];
    int n = (int)(sqrt(dx * dx + dy * dy) * 2) + 1;
    for (int k = first ? 0 : 1; k <= n; k++)
        dot(c, a[0] + dx * k / n, a[1] + dy * k / n, w / 2, rgb);
}

/* A point of the plane (hyperboloid, or (x, y, 1) in the flat grid) in pixels. */
static void to_px(const canvas *c, const double p[3], double out[2])
{
    double d[2];
    if (c->flat) {
        d[0] = p[0] / c->extent;
        d[1] = p[1] / c->extent;
    } else {
        hol_hyper_to_disk(p, d);
    }
    out[0] = c->cx + d[0] * c->r;
    out[1] = c->cy - d[1] * c->r;
}

/* The geodesic from a to b in pieces. */
static void geodesic(canvas *c, const double a[3], const double b[3], double w, uint32_t rgb)
{
    double prev[2], cur[2];
    to_px(c, a, prev);
    for (int k = 1; k <= 24; k++) {
        double t = k / 24.0, p[3];
        for (int i = 0; i < 3; i++)
            p[i] = a[i] * (1 - t) + b[i] * t;
        if (!c->flat) {
            double n = sqrt(p[2] * p[2] - p[0] * p[0] - p[1] * p[1]);
            for (int i = 0; i < 3; i++)
                p[i] /= n;
        }
        to_px(c, p, cur);
        line(c, prev, cur, w, rgb, k == 1);
        prev[0] = cur[0];
        prev[1] = cur[1];
    }
}

static hol_err centre(const canvas *c, hol_tile t, double out[3])
{
    return hol_hyper_pos(c->start.tile, c->start.orient, t, out, NULL, NULL);
}

/* Tile b's four edges (b seen from O of its tiling: the grid around the
 * start looks the same, up to a quarter turn that maps it onto itself). */
static void tile_edges(canvas *c, hol_tile o, hol_tile b, double corner_r)
{
    double m[9], pts[4][3];
    if (hol_hyper_frame(o, 0, b, m))
        return;
    for (int k = 0; k < 4; k++) {
        double sx = k == 0 || k == 3 ? 1 : -1, sy = k < 2 ? 1 : -1, l[3];
        if (c->flat) {
            l[0] = sx * 0.5, l[1] = sy * 0.5, l[2] = 1;
        } else {
            double s = sinh(corner_r) * sqrt(0.5);
            l[0] = sx * s, l[1] = sy * s, l[2] = cosh(corner_r);
        }
        for (int i = 0; i < 3; i++)
            pts[k][i] = m[3 * i] * l[0] + m[3 * i + 1] * l[1] + m[3 * i + 2] * l[2];
    }
    for (int k = 0; k < 4; k++)
        geodesic(c, pts[k], pts[(k + 1) % 4], 1, 0xb4b9aa);
}

/* Every tile within depth steps of O, by its canonical address. */
static void grid(canvas *c, hol_tile o, hol_tile t, int depth, double corner_r)
{
    tile_edges(c, o, t, corner_r);
    if (!depth)
        return;
    int is_o = hol_tile_dist0(t) == 0;
    for (int l = 0; l < 4; l++) {
        hol_tile ch;
        if (!is_o && l == 2)
            continue;
        if (!hol_tile_child(t, l, &ch))
            grid(c, o, ch, depth - 1, corner_r);
    }
}

static hol_err path(canvas *c, const hol_tile *tiles, int n, double w, uint32_t rgb)
{
    double a[3], b[3];
    hol_err err = centre(c, c->start.tile, a);
    for (int i = 0; !err && i < n; i++) {
        if (!(i & 1023) && cli_caught_signal())
            return HOL_EBUDGET; /* a walk of a million steps: stopped (report_draw.h) */
        if ((err = centre(c, tiles[i], b)))
            break;
        geodesic(c, a, b, w, rgb);
        memcpy(a, b, sizeof a);
    }
    return err;
}

static double flat_extent(const report_picture *p)
{
    double e = 2.5, q[3];
    const hol_tile *lists[3] = {p->walked, p->optimal, p->goals};
    int ns[3] = {p->nwalked, p->noptimal, p->ngoals};
    for (int l = 0; l < 3; l++)
        for (int i = 0; i < ns[l]; i++)
            if (!hol_hyper_pos(p->start.tile, p->start.orient, lists[l][i], q, NULL, NULL))
                e = fmax(e, fmax(fabs(q[0]), fabs(q[1])) + 1);
    return e;
}

static void marks(canvas *c, const report_picture *p)
{
    double q[3], x[2];
    for (int i = 0; i < p->ngoals; i++)
        if (!centre(c, p->goals[i], q)) {
            to_px(c, q, x);
            uint32_t rgb = p->chest_last && i == p->ngoals - 1 ? 0x8b5a2b
                           : p->chest_last                  ? 0xe6b400 : 0xd21e1e;
            dot(c, x[0], x[1], c->size / 60.0 + 2, rgb);
        }
    if (!centre(c, p->start.tile, q)) {
        to_px(c, q, x);
        dot(c, x[0], x[1], c->size / 80.0 + 2, 0x1e9b3c);
    }
    if (p->nwalked > 0 && !centre(c, p->walked[p->nwalked - 1], q)) {
        to_px(c, q, x);
        ring(c, x[0], x[1], c->size / 50.0 + 3, 2, 0xdc5014);
    }
}

/* The disk and the tiling's edges (they do not depend on the start: the
 * grid around it looks the same, see tile_edges). */
static void background(canvas *c, int q)
{
    for (int i = 0; i < c->size * c->size; i++)
        memcpy(c->px + 4 * (size_t)i, "\xff\xff\xff\xff", 4);
    dot(c, c->cx, c->cy, c->r, 0xf4f3ec);
    ring(c, c->cx, c->cy, c->r, 1.5, 0x82877a);
    double corner_r = q == 4 ? 0 : acosh(1 / tan(M_PI / q));
    int depth = q == 5 ? 6 : 5;
    if (c->flat)
        depth = (int)fmin(2 * c->extent + 2, 40);
    c->clip = 1; /* the flat grid's lines end at the disk */
    grid(c, hol_tile_origin_q(q), hol_tile_origin_q(q), depth, corner_r);
    c->clip = 0;
}

hol_err report_draw_background(int q, uint8_t *rgba, int size)
{
    if (size < 64 || size > 2048 || q < 5 || q > 8)
        return HOL_EARG;
    canvas c = {.px = rgba, .size = size, .cx = size / 2.0, .cy = size / 2.0,
                .r = size / 2.0 - 4, .extent = 1};
    background(&c, q);
    return HOL_OK;
}

hol_err report_draw(const report_picture *p, uint8_t *rgba, int size)
{
    if (size < 64 || size > 2048 || !hol_room_ok(&p->start))
        return HOL_EARG;
    int q = hol_tile_q(p->start.tile);
    canvas c = {rgba, size, size / 2.0, size / 2.0, size / 2.0 - 4, q == 4, 0, 1, p->start};
    if (c.flat)
        c.extent = flat_extent(p);
    if (p->background && !c.flat)
        memcpy(rgba, p->background, (size_t)size * (size_t)size * 4);
    else
        background(&c, q);
    hol_err err = path(&c, p->optimal, p->noptimal, size / 50.0 + 3, REPORT_RGB_OPTIMAL);
    if (!err)
        err = path(&c, p->walked, p->nwalked, size / 120.0 + 1.5, REPORT_RGB_WALKED);
    if (!err)
        marks(&c, p);
    return err;
}
