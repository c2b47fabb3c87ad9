/* report_draw.c - an attempt's walks on the Poincare disk, re-centred and
 * zoomed on the walk, with step order and a legend (report_draw.h). */
#include "report_draw.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../../core/hol_hyper.h"
#include "../../../core/hol_face.h"
#include "../../../render/hol_face_draw.h"
#include "../cli.h"

#define RGB_WHITE 0xffffffu
#define RGB_TEXT 0x202020u
#define RGB_START 0x1e9b3cu
#define RGB_GOAL 0xd21e1eu
#define RGB_KEY 0xe6b400u
#define RGB_CHEST 0x8b5a2bu
#define RGB_EDGE 0xb4b9aau
#define RGB_RAMP_MID 0xc23c8cu
#define RGB_DISK 0xf4f3ecu
#define RGB_RIM 0x82877au

typedef struct canvas {
    uint8_t *px;
    int size;
    double cx, cy, r; /* the view's centre and radius in pixels */
    double zs;        /* the disk's magnification */
    int flat;         /* {4,4}: plane coordinates, v->flat */
    int clip;         /* 1: pixels outside the disk are left alone */
    const report_view *v;
    hol_room start;
    uint32_t ink_rgb; /* the last colour asked for and its index */
    uint8_t ink;
} canvas;

/* Every colour of a picture, the palette's order: these, then the ramp. */
static const uint32_t fixed_rgb[] = {RGB_WHITE, RGB_DISK, RGB_RIM, RGB_EDGE, REPORT_RGB_OPTIMAL,
                                     RGB_TEXT, RGB_START, RGB_GOAL, RGB_KEY, RGB_CHEST};
#define NFIXED (int)(sizeof fixed_rgb / sizeof fixed_rgb[0])

/* The ramp's colour at level l of REPORT_RAMP_LEVELS (0: the first step):
 * indigo to magenta to orange. */
static uint32_t ramp_level(int l)
{
    double t = l / (double)(REPORT_RAMP_LEVELS - 1) * 2;
    uint32_t a = t <= 1 ? REPORT_RGB_RAMP0 : RGB_RAMP_MID;
    uint32_t b = t <= 1 ? RGB_RAMP_MID : REPORT_RGB_RAMP1, rgb = 0;
    t = t <= 1 ? t : t - 1;
    for (int s = 16; s >= 0; s -= 8)
        rgb |= (uint32_t)lround(((a >> s) & 255) * (1 - t) + ((b >> s) & 255) * t) << s;
    return rgb;
}

int report_palette(uint8_t plte[3 * 256])
{
    for (int i = 0; i < NFIXED + REPORT_RAMP_LEVELS; i++) {
        uint32_t c = i < NFIXED ? fixed_rgb[i] : ramp_level(i - NFIXED);
        plte[3 * i] = (uint8_t)(c >> 16);
        plte[3 * i + 1] = (uint8_t)(c >> 8);
        plte[3 * i + 2] = (uint8_t)c;
    }
    return NFIXED + REPORT_RAMP_LEVELS;
}

/* rgb's palette index (one of the picture's colours; else the text's). */
static uint8_t colour_index(uint32_t rgb)
{
    for (int i = 0; i < NFIXED; i++)
        if (fixed_rgb[i] == rgb)
            return (uint8_t)i;
    for (int l = 0; l < REPORT_RAMP_LEVELS; l++)
        if (ramp_level(l) == rgb)
            return (uint8_t)(NFIXED + l);
    return 5;
}

static uint8_t ink(canvas *c, uint32_t rgb)
{
    if (rgb != c->ink_rgb) {
        c->ink_rgb = rgb;
        c->ink = colour_index(rgb);
    }
    return c->ink;
}

static void put(canvas *c, int x, int y, uint32_t rgb)
{
    if (x < 0 || y < 0 || x >= c->size || y >= c->size)
        return;
    double dx = x + 0.5 - c->cx, dy = y + 0.5 - c->cy, rr = c->r * c->zs - 1.5;
    if (c->clip && dx * dx + dy * dy > rr * rr)
        return;
    c->px[(size_t)y * (size_t)c->size + (size_t)x] = ink(c, rgb);
}

/* Pixels a..b of row j (put's checks, made once for the row). */
static void span(canvas *c, int a, int b, int j, uint32_t rgb)
{
    if (j < 0 || j >= c->size)
        return;
    a = a < 0 ? 0 : a;
    b = b >= c->size ? c->size - 1 : b;
    if (c->clip) {
        for (int i = a; i <= b; i++)
            put(c, i, j, rgb);
        return;
    }
    if (a <= b)
        memset(c->px + (size_t)j * (size_t)c->size + (size_t)a, ink(c, rgb),
               (size_t)(b - a + 1));
}

static void rect(canvas *c, int x0, int y0, int x1, int y1, uint32_t rgb)
{
    for (int j = y0; j < y1; j++)
        span(c, x0, x1 - 1, j, rgb);
}

/* The pixels whose centres are within rad of (x, y), a row at a time. */
static void dot(canvas *c, double x, double y, double rad, uint32_t rgb)
{
    int j0 = (int)floor(y - rad), j1 = (int)ceil(y + rad);
    j0 = j0 < 0 ? 0 : j0;
    j1 = j1 >= c->size ? c->size - 1 : j1;
    for (int j = j0; j <= j1; j++) {
        double dy = j + 0.5 - y, s2 = rad * rad - dy * dy;
        if (s2 < 0)
            continue;
        double s = sqrt(s2);
        span(c, (int)ceil(x - s - 0.5), (int)floor(x + s - 0.5), j, rgb);
    }
}

static void ring(canvas *c, double x, double y, double rad, double w, uint32_t rgb)
{
    int j0 = (int)fmax(floor(y - rad), 0), j1 = (int)fmin(ceil(y + rad), c->size - 1);
    int i0 = (int)fmax(floor(x - rad), 0), i1 = (int)fmin(ceil(x + rad), c->size - 1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            double dx = i + 0.5 - x, dy = j + 0.5 - y, d = sqrt(dx * dx + dy * dy);
            if (d <= rad && d >= rad - w)
                put(c, i, j, rgb);
        }
}

/* x with lo <= k x + m <= hi, intersected into [*a, *b]. */
static void solve(double k, double m, double lo, double hi, double *a, double *b)
{
    if (k == 0) {
        if (m < lo || m > hi)
            *a = INFINITY, *b = -INFINITY;
        return;
    }
    double u = (lo - m) / k, w = (hi - m) / k;
    *a = fmax(*a, fmin(u, w));
    *b = fmin(*b, fmax(u, w));
}

/* The pixels whose centres are within rad of the segment a-b (a capsule:
 * convex, so a row's pixels are one span, the union of its three parts'). */
static void line(canvas *c, const double a[2], const double b[2], double w, uint32_t rgb)
{
    double rad = w / 2, dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double l = sqrt(l2);
    int j0 = (int)floor(fmin(a[1], b[1]) - rad), j1 = (int)ceil(fmax(a[1], b[1]) + rad);
    j0 = j0 < 0 ? 0 : j0;
    j1 = j1 >= c->size ? c->size - 1 : j1;
    for (int j = j0; j <= j1; j++) {
        double y = j + 0.5, lo = INFINITY, hi = -INFINITY;
        for (int e = 0; e < 2; e++) {
            const double *p = e ? b : a;
            double s2 = rad * rad - (y - p[1]) * (y - p[1]);
            if (s2 >= 0) {
                double s = sqrt(s2);
                lo = fmin(lo, p[0] - s);
                hi = fmax(hi, p[0] + s);
            }
        }
        if (l > 0) {
            double u = -INFINITY, v = INFINITY; /* 0 <= t <= 1, |distance| <= rad */
            solve(dx / l2, (-a[0] * dx + (y - a[1]) * dy) / l2, 0, 1, &u, &v);
            solve(dy / l, (-a[0] * dy - (y - a[1]) * dx) / l, -rad, rad, &u, &v);
            if (u <= v) {
                lo = fmin(lo, u);
                hi = fmax(hi, v);
            }
        }
        if (lo <= hi)
            span(c, (int)ceil(lo - 0.5), (int)floor(hi - 0.5), j, rgb);
    }
}

static double zoom_scale(int zoom)
{
    return pow(2, zoom / 4.0);
}

int report_legend_height(int size)
{
    int k = size >= 400 ? 2 : 1;
    return 2 * (7 * k + 6) + 6;
}

static void view_geometry(int size, double *cx, double *cy, double *r)
{
    double h = size - report_legend_height(size);
    *cx = size / 2.0;
    *cy = h / 2.0;
    *r = h / 2.0 - 4;
}

static void mat_vec(const double m[9], const double p[3], double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = m[3 * i] * p[0] + m[3 * i + 1] * p[1] + m[3 * i + 2] * p[2];
}

void report_view_px(const report_view *v, int flat, int size, const double p[3],
                    double out[2])
{
    double cx, cy, r, d[2];
    view_geometry(size, &cx, &cy, &r);
    if (flat) {
        d[0] = (p[0] - v->flat[0]) / v->flat[2];
        d[1] = (p[1] - v->flat[1]) / v->flat[2];
    } else {
        double q[3], zs = zoom_scale(v->zoom);
        mat_vec(v->m, p, q);
        d[0] = q[0] / (1 + q[2]) * zs;
        d[1] = q[1] / (1 + q[2]) * zs;
    }
    out[0] = cx + d[0] * r;
    out[1] = cy - d[1] * r;
}

static void to_px(const canvas *c, const double p[3], double out[2])
{
    report_view_px(c->v, c->flat, c->size, p, out);
}

/* The geodesic from a to b (start frame) in pieces, offset off pixels to
 * the right of its direction. */
static void geodesic(canvas *c, const double a[3], const double b[3], double w, uint32_t rgb,
                     double off)
{
    double pa[2], pb[2], o[2] = {0, 0};
    to_px(c, a, pa);
    to_px(c, b, pb);
    double dx = pb[0] - pa[0], dy = pb[1] - pa[1], l = sqrt(dx * dx + dy * dy);
    off = fmin(off, l / 3); /* no wider than the step is long (near the rim) */
    if (off > 0)
        o[0] = -dy / l * off, o[1] = dx / l * off; /* right of the direction, y down */
    int n = c->flat ? 1 : 1 + (int)fmin(l / 6, 23);
    double prev[2] = {pa[0] + o[0], pa[1] + o[1]}, cur[2];
    for (int k = 1; k <= n; k++) {
        double t = k / (double)n, p[3];
        for (int i = 0; i < 3; i++)
            p[i] = a[i] * (1 - t) + b[i] * t;
        if (!c->flat) {
            double s = sqrt(p[2] * p[2] - p[0] * p[0] - p[1] * p[1]);
            for (int i = 0; i < 3; i++)
                p[i] /= s;
        }
        to_px(c, p, cur);
        cur[0] += o[0];
        cur[1] += o[1];
        line(c, prev, cur, w, rgb);
        prev[0] = cur[0];
        prev[1] = cur[1];
    }
}

static hol_err centre(const canvas *c, hol_tile t, double out[3])
{
    return hol_hyper_pos(c->start.tile, c->start.orient, t, out, NULL, NULL);
}

/* Tile b's four edges (b seen from O of its tiling: the grid around the
 * view's centre tile looks the same, up to a quarter turn that maps it
 * onto itself). The background's view is the identity. */
static void tile_edges(canvas *c, hol_tile o, hol_tile b, double corner_r)
{
    double m[9], pts[4][3];
    if (hol_hyper_frame(o, 0, b, m))
        return;
    for (int k = 0; k < 4; k++) {
        double sx = k == 0 || k == 3 ? 1 : -1, sy = k < 2 ? 1 : -1, s = sinh(corner_r) * sqrt(0.5);
        double l[3] = {sx * s, sy * s, cosh(corner_r)};
        mat_vec(m, l, pts[k]);
    }
    for (int k = 0; k < 4; k++)
        geodesic(c, pts[k], pts[(k + 1) % 4], 1, RGB_EDGE, 0);
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

/* The flat grid: lines between the tiles (half-integer coordinates of the
 * start's frame) across the view. */
static void flat_grid(canvas *c)
{
    const double *f = c->v->flat;
    for (int axis = 0; axis < 2; axis++)
        for (double k = floor(f[axis] - f[2]) - 0.5; k <= f[axis] + f[2] + 1; k++) {
            double a[3] = {0, 0, 1}, b[3] = {0, 0, 1}, pa[2], pb[2];
            a[axis] = b[axis] = k;
            a[1 - axis] = f[1 - axis] - f[2] - 1;
            b[1 - axis] = f[1 - axis] + f[2] + 1;
            to_px(c, a, pa);
            to_px(c, b, pb);
            line(c, pa, pb, 1, RGB_EDGE);
        }
}

/* The view's disk and the tiling's edges. */
static void background(canvas *c, int q)
{
    memset(c->px, ink(c, RGB_WHITE), (size_t)c->size * (size_t)c->size);
    dot(c, c->cx, c->cy, c->r * c->zs, RGB_DISK);
    ring(c, c->cx, c->cy, c->r * c->zs, 1.5, RGB_RIM);
    c->clip = 1; /* the lines end at the disk */
    if (c->flat)
        flat_grid(c);
    else
        grid(c, hol_tile_origin_q(q), hol_tile_origin_q(q), q == 5 ? 6 : 5,
             acosh(1 / tan(M_PI / q)));
    c->clip = 0;
}

static void canvas_init(canvas *c, uint8_t *px, int size, const report_view *v, int flat,
                        hol_room start)
{
    memset(c, 0, sizeof *c);
    c->px = px;
    c->size = size;
    c->v = v;
    c->flat = flat;
    c->start = start;
    view_geometry(size, &c->cx, &c->cy, &c->r);
    c->ink_rgb = RGB_WHITE;
    c->ink = 0;
    c->zs = flat ? 1 : zoom_scale(v->zoom);
}

hol_err report_draw_background(int q, int zoom, uint8_t *px, int size)
{
    if (size < 64 || size > 2048 || q < 5 || q > 8 || zoom < 0 || zoom > REPORT_ZOOM_MAX)
        return HOL_EARG;
    report_view v;
    memset(&v, 0, sizeof v);
    v.m[0] = v.m[4] = v.m[8] = 1;
    v.zoom = zoom;
    canvas c;
    canvas_init(&c, px, size, &v, 0, (hol_room){0});
    background(&c, q);
    return HOL_OK;
}

/* Points of the picture: k = 0 the start, then the walked tiles, the
 * optimal walk's, the objectives. */
static hol_tile point_tile(const report_picture *p, long k)
{
    if (k == 0)
        return p->start.tile;
    if (--k < p->nwalked)
        return p->walked[k];
    if ((k -= p->nwalked) < p->noptimal)
        return p->optimal[k];
    return p->goals[k - p->noptimal];
}

/* The Minkowski centroid C of the walk's points (the start and the walked
 * tiles: k < nc), the flat bounding box of all n. */
static hol_err fit_centre(const report_picture *p, long nc, long n, int flat, report_view *v)
{
    double s[3] = {0, 0, 0}, lo[2] = {0, 0}, hi[2] = {0, 0}, q[3];
    for (long k = 0; k < n; k++) {
        if (!(k & 1023) && k && cli_caught_signal())
            return HOL_EBUDGET;
        hol_err err = hol_hyper_pos(p->start.tile, p->start.orient, point_tile(p, k), q, NULL,
                                    NULL);
        if (err)
            return err;
        for (int i = 0; k < nc && i < 3; i++)
            s[i] += q[i];
        for (int i = 0; i < 2; i++)
            lo[i] = fmin(lo[i], q[i]), hi[i] = fmax(hi[i], q[i]);
    }
    if (flat) {
        v->flat[0] = (lo[0] + hi[0]) / 2;
        v->flat[1] = (lo[1] + hi[1]) / 2;
        v->flat[2] = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]) / 2 + 1, 1.5);
        return HOL_OK;
    }
    double norm = sqrt(s[2] * s[2] - s[0] * s[0] - s[1] * s[1]);
    for (int i = 0; i < 3; i++)
        v->centre[i] = s[i] / norm;
    return HOL_OK;
}

/* T, the walk's point nearest C (the least -<q, C> = cosh d; k < n). */
static hol_err fit_tile(const report_picture *p, long n, report_view *v)
{
    double best = INFINITY, q[3];
    const double *c = v->centre;
    for (long k = 0; k < n; k++) {
        if (!(k & 1023) && k && cli_caught_signal())
            return HOL_EBUDGET;
        hol_tile t = point_tile(p, k);
        hol_err err = hol_hyper_pos(p->start.tile, p->start.orient, t, q, NULL, NULL);
        if (err)
            return err;
        double ch = q[2] * c[2] - q[0] * c[0] - q[1] * c[1];
        if (ch < best - 1e-12)
            best = ch, v->tile = t;
    }
    return HOL_OK;
}

/* v->m: T's frame inverted (J F^T J, J = diag(1, 1, -1)), then the quarter
 * turn nearest to the pure translation taking T's centre to the origin. */
static hol_err fit_matrix(const report_picture *p, report_view *v)
{
    double f[9], inv[9], b[9], r[9];
    hol_err err = hol_hyper_frame(p->start.tile, p->start.orient, v->tile, f);
    if (err)
        return err;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            inv[3 * i + j] = f[3 * j + i] * (i == 2 ? -1 : 1) * (j == 2 ? -1 : 1);
    double cx = f[2], cy = f[5], cz = f[8], w = 1 + cz; /* the boost from O to T's centre */
    double boost[9] = {1 + cx * cx / w, cx * cy / w, cx, cx * cy / w, 1 + cy * cy / w, cy,
                       cx, cy, cz};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            b[3 * i + j] = inv[3 * i] * boost[j] + inv[3 * i + 1] * boost[3 + j] +
                           inv[3 * i + 2] * boost[6 + j];
    int k = ((int)lround(atan2(b[3], b[0]) / (M_PI / 2)) % 4 + 4) % 4; /* b: a rotation */
    static const double cs[4][2] = {{1, 0}, {0, -1}, {-1, 0}, {0, 1}}; /* by -k quarter turns */
    double rot[9] = {cs[k][0], -cs[k][1], 0, cs[k][1], cs[k][0], 0, 0, 0, 1};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * i + j] = rot[3 * i] * inv[j] + rot[3 * i + 1] * inv[3 + j] +
                           rot[3 * i + 2] * inv[6 + j];
    memcpy(v->m, r, sizeof r);
    return HOL_OK;
}

/* The largest zoom that keeps the walk and the objectives within 0.85 of
 * the view. */
static hol_err fit_zoom(const report_picture *p, long n, report_view *v)
{
    double rho = 0, q[3], u[3];
    for (long k = 0; k < n; k++) {
        if (!(k & 1023) && k && cli_caught_signal())
            return HOL_EBUDGET;
        if (k > p->nwalked && k <= (long)p->nwalked + p->noptimal)
            continue; /* the optimal walk may leave the view */
        hol_err err = hol_hyper_pos(p->start.tile, p->start.orient, point_tile(p, k), q, NULL,
                                    NULL);
        if (err)
            return err;
        mat_vec(v->m, q, u);
        rho = fmax(rho, sqrt(u[0] * u[0] + u[1] * u[1]) / (1 + u[2]));
    }
    int z = rho > 0 ? (int)floor(4 * log2(0.85 / rho)) : REPORT_ZOOM_MAX;
    v->zoom = z < 0 ? 0 : z > REPORT_ZOOM_MAX ? REPORT_ZOOM_MAX : z;
    return HOL_OK;
}

hol_err report_view_fit(const report_picture *p, report_view *v)
{
    memset(v, 0, sizeof *v);
    v->m[0] = v->m[4] = v->m[8] = 1;
    if (!hol_room_ok(&p->start))
        return HOL_EARG;
    v->tile = p->start.tile;
    int flat = hol_tile_q(p->start.tile) == 4;
    long n = 1L + p->nwalked + p->noptimal + p->ngoals;
    hol_err err = fit_centre(p, 1L + p->nwalked, n, flat, v);
    if (err || flat)
        return err;
    if (!(err = fit_tile(p, 1L + p->nwalked, v)) && !(err = fit_matrix(p, v)))
        err = fit_zoom(p, n, v);
    return err;
}


static uint32_t ramp(long i, long n)
{
    return ramp_level(n > 1 ? (int)(i * (REPORT_RAMP_LEVELS - 1) / (n - 1)) : REPORT_RAMP_LEVELS - 1);
}

static int tile_less(hol_tile a, hol_tile b)
{
    return a.bits[1] != b.bits[1] ? a.bits[1] < b.bits[1] : a.bits[0] < b.bits[0];
}

/* Earlier passes of the edge a-b (0 when untracked), counting this one. */
static int edge_pass(report_edges *tab, hol_tile a, hol_tile b)
{
    if (tile_less(b, a)) {
        hol_tile t = a;
        a = b;
        b = t;
    }
    uint64_t k[4] = {a.bits[0], a.bits[1], b.bits[0], b.bits[1]}, h = 0x9e3779b97f4a7c15u;
    for (int i = 0; i < 4; i++)
        h = (h ^ k[i]) * 0x100000001b3u, h ^= h >> 29;
    for (uint32_t i = (uint32_t)h % (2 * REPORT_EDGE_SLOTS);; i = (i + 1) % (2 * REPORT_EDGE_SLOTS)) {
        report_edge_slot *e = &tab->tab[i];
        if (e->stamp == tab->stamp && !memcmp(e->k, k, sizeof k))
            return (int)e->count++;
        if (e->stamp != tab->stamp) {
            if (tab->used >= REPORT_EDGE_SLOTS)
                return 0;
            tab->used++;
            memcpy(e->k, k, sizeof k);
            e->stamp = tab->stamp;
            e->count = 1;
            return 0;
        }
    }
}

/* The table emptied for a new picture (a stamp marks this picture's slots). */
static void edges_reset(report_edges *t)
{
    if (++t->stamp == 0) { /* wrapped: every slot is old */
        memset(t->tab, 0, sizeof t->tab);
        t->stamp = 1;
    }
    t->used = 0;
}

static double walked_width(int size)
{
    return size / 120.0 + 2;
}

/* The optimal walk: one colour, wide, under the walked path. */
static hol_err optimal_path(canvas *c, const report_picture *p)
{
    double a[3], b[3];
    hol_err err = centre(c, c->start.tile, a);
    for (int i = 0; !err && i < p->noptimal; i++) {
        if ((err = centre(c, p->optimal[i], b)))
            break;
        geodesic(c, a, b, c->size / 50.0 + 3, REPORT_RGB_OPTIMAL, 0);
        memcpy(a, b, sizeof a);
    }
    return err;
}

/* The walked path: each step in its ramp colour, an edge walked again
 * beside its earlier passes (at most 3 widths out, and a third of the
 * step's length on the screen). */
static hol_err walked_path(canvas *c, const report_picture *p, report_edges *edges)
{
    double a[3], b[3], w = walked_width(c->size);
    hol_tile prev = c->start.tile;
    hol_err err = centre(c, prev, a);
    edges_reset(edges);
    for (long i = 0; !err && i < p->nwalked; i++) {
        if (!(i & 1023) && cli_caught_signal())
            return HOL_EBUDGET; /* a walk of a million steps: stopped (report_draw.h) */
        if ((err = centre(c, p->walked[i], b)))
            break;
        int pass = edge_pass(edges, prev, p->walked[i]);
        geodesic(c, a, b, w, ramp(i, p->nwalked), (pass > 3 ? 3 : pass) * (w + 2));
        memcpy(a, b, sizeof a);
        prev = p->walked[i];
    }
    return err;
}

/* The text face's em for a cap height of 7 k pixels (the old 5x7 font's
 * at k). */
static float text_size(int k)
{
    return 7.0f * (float)k * hol_face_em_per_cap();
}

/* The width of s at k (pixels, rounded up). */
static int text_width(const char *s, int k)
{
    return (int)ceilf(hol_face_width(s, text_size(k)));
}

/* Text at (x, y) (the top of its capitals; the baseline 7 k below) in the
 * text face (render/hol_face_draw.h), drawn into an RGBA strip and its
 * pixels of coverage at least a half put in rgb (the picture is
 * paletted: no blending); the advance. */
static int text(canvas *c, const char *s, int x, int y, int k, uint32_t rgb)
{
    enum { TW = 768, TH = 64 };
    static const uint8_t none[4] = {0, 0, 0, 0};
    uint8_t strip[TW * TH * 4];
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    float size = text_size(k);
    int asc = (int)ceilf((float)m.ascent * size / (float)m.units_per_em) + 1;
    int h = asc + (int)ceilf((float)-m.descent * size / (float)m.units_per_em) + 1;
    h = h < TH ? h : TH;
    for (size_t i = 0; i < (size_t)TW * (size_t)h * 4; i += 4)
        memcpy(strip + i, none, 4);
    hol_face_canvas fc = {strip, TW, h, 0};
    hol_face_draw_desc d = {1, (float)asc, size, 0xffffffffu, 1};
    float adv = hol_face_draw(&fc, &d, s, strlen(s), NULL);
    int top = y + 7 * k - asc;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < TW && i < (int)adv + 3; i++)
            if (strip[4 * (j * TW + i) + 3] >= 128)
                put(c, x - 1 + i, top + j, rgb);
    return (int)ceilf(adv);
}

/* Text with a white outline (readable over the lines). */
static void text_halo(canvas *c, const char *s, int x, int y, int k, uint32_t rgb)
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++)
            if (dx || dy)
                text(c, s, x + dx * k, y + dy * k, k, RGB_WHITE);
    text(c, s, x, y, k, rgb);
}

static uint32_t goal_rgb(const report_picture *p, int i)
{
    return p->chest_last && i == p->ngoals - 1 ? RGB_CHEST : p->chest_last ? RGB_KEY : RGB_GOAL;
}

/* The marks' radii (pixels) at size. */
static double goal_radius(int size)
{
    return size / 60.0 + 2;
}

static double start_radius(int size)
{
    return size / 80.0 + 2;
}

static double end_radius(int size)
{
    return size / 50.0 + 3;
}

static int mark_count(const report_picture *p)
{
    return 1 + p->ngoals + (p->nwalked > 0);
}

/* Mark i's centre and radius: 0 the start, then the objectives, then the
 * end ring; 0, or -1 when its tile has no place. */
static int mark_at(const canvas *c, const report_picture *p, int i, double x[2], double *rad)
{
    double q[3];
    hol_tile t = i == 0 ? p->start.tile : i <= p->ngoals ? p->goals[i - 1]
                                                         : p->walked[p->nwalked - 1];
    if (centre(c, t, q))
        return -1;
    to_px(c, q, x);
    *rad = i == 0 ? start_radius(c->size) : i <= p->ngoals ? goal_radius(c->size)
                                                           : end_radius(c->size);
    return 0;
}

static void marks(canvas *c, const report_picture *p)
{
    double x[2], rad;
    for (int i = 1; i <= p->ngoals; i++)
        if (!mark_at(c, p, i, x, &rad))
            dot(c, x[0], x[1], rad, goal_rgb(p, i - 1));
    if (!mark_at(c, p, 0, x, &rad))
        dot(c, x[0], x[1], rad, RGB_START);
    if (p->nwalked > 0 && !mark_at(c, p, 1 + p->ngoals, x, &rad))
        ring(c, x[0], x[1], rad, 2, REPORT_RGB_RAMP1);
}

/* The square of pixels around a mark (its disk or ring, and a pixel). */
static report_box mark_box(const double x[2], double rad)
{
    return (report_box){(int)floor(x[0] - rad) - 1, (int)floor(x[1] - rad) - 1,
                        (int)ceil(x[0] + rad) + 1, (int)ceil(x[1] + rad) + 1};
}

static int box_meets(const report_box *a, const report_box *b)
{
    return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

/* The steps numbered, in the order they are placed: the last, the first,
 * then every few (1, 2, 5, 10, 20, 50 ... steps apart, at most 12), none
 * nearer the first or the last than half that; how many. */
static int numbered_steps(long n, long out[REPORT_LABELS_MAX])
{
    static const int digit[3] = {1, 2, 5};
    long every = 1;
    int k = 0;
    for (long base = 1, m = 0; n / every > 12; m++, base *= m % 3 ? 1 : 10)
        every = digit[m % 3] * base;
    if (n < 1)
        return 0;
    out[k++] = n;
    if (n > 1)
        out[k++] = 1;
    for (long s = every; s < n && k < REPORT_LABELS_MAX; s += every)
        if (s > 1 && s - 1 >= every / 2 && n - s >= every / 2)
            out[k++] = s;
    return k;
}

/* A free place for a number w x h pixels (its halo included) near (x, y):
 * the first of 8 directions (up right first) at 3 distances whose box lies
 * in the view above the legend and meets no mark and no number placed (nor
 * comes within 2 font pixels of one). */
static int label_place(const canvas *c, const report_picture *p, double x, double y, int w,
                       int h, const report_label *done, int ndone, report_box *out)
{
    static const int dir[8][2] = {{1, -1}, {-1, -1}, {1, 1}, {-1, 1},
                                  {1, 0},  {-1, 0},  {0, -1}, {0, 1}};
    int k = c->size >= 400 ? 2 : 1, bottom = c->size - report_legend_height(c->size);
    for (int r = 0; r < 3; r++)
        for (int d = 0; d < 8; d++) {
            double gap = (2 + 5 * r) * k + 2;
            int x0 = (int)lround(dir[d][0] > 0 ? x + gap : dir[d][0] < 0 ? x - gap - w
                                                                          : x - w / 2.0);
            int y0 = (int)lround(dir[d][1] > 0 ? y + gap : dir[d][1] < 0 ? y - gap - h
                                                                          : y - h / 2.0);
            report_box b = {x0, y0, x0 + w, y0 + h};
            int free = b.x0 >= 0 && b.y0 >= 0 && b.x1 <= c->size && b.y1 <= bottom;
            report_box apart = {b.x0 - 2 * k, b.y0 - 2 * k, b.x1 + 2 * k, b.y1 + 2 * k};
            for (int i = 0; free && i < ndone; i++) /* a gap between numbers: "14 2", not "142" */
                free = !box_meets(&apart, &done[i].box);
            double mx[2], rad;
            for (int i = 0; free && i < mark_count(p); i++)
                if (!mark_at(c, p, i, mx, &rad)) {
                    report_box m = mark_box(mx, rad);
                    free = !box_meets(&b, &m);
                }
            if (free) {
                *out = b;
                return 1;
            }
        }
    return 0;
}

static int layout(const canvas *c, const report_picture *p, report_label out[REPORT_LABELS_MAX])
{
    long steps[REPORT_LABELS_MAX];
    int k = c->size >= 400 ? 2 : 1, n = numbered_steps(p->nwalked, steps), m = 0;
    for (int i = 0; i < n; i++) {
        double q[3], x[2];
        report_label *l = &out[m];
        if (centre(c, p->walked[steps[i] - 1], q))
            continue;
        to_px(c, q, x);
        l->step = steps[i];
        snprintf(l->text, sizeof l->text, "%ld", steps[i]);
        int w = text_width(l->text, k) + 2 * k, h = 9 * k; /* the glyphs and the halo */
        m += label_place(c, p, x[0], x[1], w, h, out, m, &l->box);
    }
    return m;
}

int report_mark_boxes(const report_picture *p, const report_view *v, int size,
                      report_box *out, int max)
{
    canvas c;
    double x[2], rad;
    int n = 0;
    canvas_init(&c, NULL, size, v, hol_tile_q(p->start.tile) == 4, p->start);
    for (int i = 0; i < mark_count(p); i++)
        if (!mark_at(&c, p, i, x, &rad) && n < max)
            out[n++] = mark_box(x, rad);
    return n;
}

int report_step_labels(const report_picture *p, const report_view *v, int size,
                       report_label out[REPORT_LABELS_MAX])
{
    canvas c;
    canvas_init(&c, NULL, size, v, hol_tile_q(p->start.tile) == 4, p->start);
    return layout(&c, p, out);
}

/* The numbers where layout placed them: over the lines, beside the marks. */
static void step_numbers(canvas *c, const report_picture *p)
{
    report_label l[REPORT_LABELS_MAX];
    int k = c->size >= 400 ? 2 : 1, n = layout(c, p, l);
    for (int i = 0; i < n; i++)
        text_halo(c, l[i].text, l[i].box.x0 + k, l[i].box.y0 + k, k, RGB_TEXT);
}

/* A legend entry: its mark, then its name; the x after it. */
static int legend_item(canvas *c, int x, int y, int k, int kind, uint32_t rgb, const char *name)
{
    double h = 7 * k, mx = x + h / 2, my = y + h / 2;
    if (kind == 0)
        dot(c, mx, my, h / 2, rgb);
    else if (kind == 1)
        line(c, (double[2]){x, my}, (double[2]){x + 3 * h, my}, h * 0.8, rgb), mx += 2.5 * h;
    else
        ring(c, mx, my, h / 2 + 1, 2, rgb);
    return x + (int)(mx - x + h) + text(c, name, (int)(mx + h), y, k, RGB_TEXT) + 5 * k;
}

/* The legend band at the bottom: the ramp of the steps, then the marks. */
static void legend(canvas *c, const report_picture *p)
{
    int band = report_legend_height(c->size), k = c->size >= 400 ? 2 : 1, y0 = c->size - band;
    rect(c, 0, y0, c->size, c->size, RGB_WHITE);
    rect(c, 0, y0, c->size, y0 + 1, RGB_RIM);
    int x = 4 * k, y = y0 + 3 + 3 * k;
    char num[32];
    if (p->nwalked > 0) {
        x += text(c, "STEP 1", x, y, k, RGB_TEXT) + 2 * k;
        int bw = c->size * 2 / 5;
        for (int l = 0; l < REPORT_RAMP_LEVELS; l++)
            rect(c, x + bw * l / REPORT_RAMP_LEVELS, y, x + bw * (l + 1) / REPORT_RAMP_LEVELS,
                 y + 7 * k, ramp_level(l));
        snprintf(num, sizeof num, "%d", p->nwalked);
        text(c, num, x + bw + 3 * k, y, k, RGB_TEXT);
    } else {
        text(c, "NO STEPS WALKED", x, y, k, RGB_TEXT);
    }
    x = 4 * k;
    y += 7 * k + 6;
    x = legend_item(c, x, y, k, 0, RGB_START, "START");
    if (p->chest_last) {
        x = legend_item(c, x, y, k, 0, RGB_KEY, "KEY");
        x = legend_item(c, x, y, k, 0, RGB_CHEST, "CHEST");
    } else if (p->ngoals > 0) {
        x = legend_item(c, x, y, k, 0, RGB_GOAL, "GOAL");
    }
    if (p->noptimal > 0)
        x = legend_item(c, x, y, k, 1, REPORT_RGB_OPTIMAL, "OPTIMAL");
    if (p->nwalked > 0)
        legend_item(c, x, y, k, 2, REPORT_RGB_RAMP1, "END");
}

/* report_draw without the caller's edge table: one of its own, zeroed. */
static hol_err draw_own_edges(const report_picture *p, uint8_t *px, int size)
{
    report_edges edges;
    memset(&edges, 0, sizeof edges);
    report_picture own = *p;
    own.edges = &edges;
    return report_draw(&own, px, size);
}

hol_err report_draw(const report_picture *p, uint8_t *px, int size)
{
    if (size < 64 || size > 2048 || !hol_room_ok(&p->start))
        return HOL_EARG;
    if (!p->edges)
        return draw_own_edges(p, px, size);
    report_view fit;
    const report_view *v = p->view;
    hol_err err = HOL_OK;
    if (!v && (err = report_view_fit(p, &fit)))
        return err;
    v = v ? v : &fit;
    int q = hol_tile_q(p->start.tile);
    canvas c;
    canvas_init(&c, px, size, v, q == 4, p->start);
    if (p->background && !c.flat)
        memcpy(px, p->background, (size_t)size * (size_t)size);
    else
        background(&c, q);
    if (!(err = optimal_path(&c, p)) && !(err = walked_path(&c, p, p->edges))) {
        marks(&c, p);
        step_numbers(&c, p);
        legend(&c, p);
    }
    return err;
}
