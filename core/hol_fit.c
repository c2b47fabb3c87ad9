/* hol_fit.c - the room and cell size that fit a play area (see hol_fit.h). */
#include "hol_fit.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_str.h"

#define HOL__EPS 1e-6 /* metres: touching the boundary still fits */

/* The largest cell (cm, a multiple of the step, at most the maximum) of a
 * side of n cells in `cm` usable centimetres; 0 when even the smallest
 * does not fit. */
static int hol__side_cm(long usable_cm, int n)
{
    long c = usable_cm / n;
    c -= c % HOL_FIT_STEP_CM;
    if (c > HOL_FIT_MAX_CM)
        c = HOL_FIT_MAX_CM;
    return c >= HOL_FIT_MIN_CM ? (int)c : 0;
}

/* best[] = (cols, rows, cm) of the rule's order: more cells, larger cell,
 * more columns. 1 when (c, r, cm) beats it. */
static int hol__better(int c, int r, int cm, const int best[3])
{
    if (!best[0])
        return 1;
    if (c * r != best[0] * best[1])
        return c * r > best[0] * best[1];
    if (cm != best[2])
        return cm > best[2];
    return c > best[0];
}

static void hol__fit_out(const int best[3], int too_small, double w, double d, hol_fit *out)
{
    memset(out, 0, sizeof *out);
    out->cols = best[0];
    out->rows = best[1];
    out->cell_cm = best[2];
    out->cell_m = best[2] / 100.0;
    out->too_small = too_small;
    out->area_w = w;
    out->area_d = d;
}

/* Rules 1-3 over a "largest cell of (c, r)" function: cm_of(ctx, c, r) is
 * 0 when the room does not fit with the smallest cell. */
typedef int (*hol__cm_fn)(const void *ctx, int c, int r);

static void hol__choose(hol__cm_fn cm_of, const void *ctx, double w, double d, hol_fit *out)
{
    int best[3] = {0, 0, 0};
    for (int c = 3; c <= 5; c++)
        for (int r = 3; r <= 5; r++) {
            int cm = cm_of(ctx, c, r);
            if (cm >= HOL_FIT_COMFORT_CM && hol__better(c, r, cm, best))
                best[0] = c, best[1] = r, best[2] = cm;
        }
    if (best[0]) {
        hol__fit_out(best, 0, w, d, out);
        return;
    }
    int cm = cm_of(ctx, 3, 3);
    int small[3] = {3, 3, cm ? cm : HOL_FIT_MIN_CM};
    hol__fit_out(small, cm == 0, w, d, out);
}

typedef struct hol__rect {
    long w_cm, d_cm;
} hol__rect;

static int hol__rect_cm(const void *ctx, int c, int r)
{
    const hol__rect *q = ctx;
    int a = hol__side_cm(q->w_cm, c), b = hol__side_cm(q->d_cm, r);
    return a < b ? a : b;
}

static double hol__margin(double margin)
{
    return margin < 0 || !isfinite(margin) ? HOL_FIT_MARGIN : margin;
}

hol_err hol_fit_rect(double width, double depth, double margin, hol_fit *out)
{
    if (!out || !isfinite(width) || !isfinite(depth) || width <= 0 || depth <= 0 ||
        width > 1e6 || depth > 1e6)
        return HOL_EARG;
    margin = hol__margin(margin);
    /* usable centimetres, touching allowed (HOL__EPS, as the polygon's) */
    double uw = (width - 2 * margin) * 100 + HOL__EPS * 100;
    double ud = (depth - 2 * margin) * 100 + HOL__EPS * 100;
    hol__rect q = {uw > 0 ? (long)floor(uw) : 0, ud > 0 ? (long)floor(ud) : 0};
    hol__choose(hol__rect_cm, &q, width, depth, out);
    return HOL_OK;
}

/* ---- polygons ------------------------------------------------------------ */

/* Distance from (px, pz) to the segment a-b. */
static double hol__seg_dist(double px, double pz, double ax, double az, double bx, double bz)
{
    double dx = bx - ax, dz = bz - az, l = dx * dx + dz * dz;
    double t = l > 0 ? ((px - ax) * dx + (pz - az) * dz) / l : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = ax + t * dx - px, ez = az + t * dz - pz;
    return sqrt(ex * ex + ez * ez);
}

/* Inside or on the boundary (within HOL__EPS). */
static int hol__inside(const float *p, int n, double x, double z)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        double xi = p[2 * i], zi = p[2 * i + 1], xj = p[2 * j], zj = p[2 * j + 1];
        if (hol__seg_dist(x, z, xi, zi, xj, zj) <= HOL__EPS)
            return 1;
        if ((zi > z) != (zj > z) && x < (xj - xi) * (z - zi) / (zj - zi) + xi)
            in = !in;
    }
    return in;
}

/* 1 when the segment a-b passes through the open box |x| < a, |z| < b
 * (Liang-Barsky clipping; the clipped part's middle strictly inside). */
static int hol__crosses(double ax, double az, double bx, double bz, double a, double b)
{
    double t0 = 0, t1 = 1, dx = bx - ax, dz = bz - az;
    double p[4] = {-dx, dx, -dz, dz}, q[4] = {ax + a, a - ax, az + b, b - az};
    for (int k = 0; k < 4; k++) {
        if (p[k] == 0) {
            if (q[k] < 0)
                return 0;
            continue;
        }
        double t = q[k] / p[k];
        if (p[k] < 0)
            t0 = t > t0 ? t : t0;
        else
            t1 = t < t1 ? t : t1;
    }
    if (t0 > t1)
        return 0;
    double tm = (t0 + t1) / 2, mx = ax + tm * dx, mz = az + tm * dz;
    return fabs(mx) < a - HOL__EPS && fabs(mz) < b - HOL__EPS;
}

int hol_fit_polygon_holds(const float *xz, int n, double margin, int cols, int rows,
                          int cell_cm)
{
    margin = hol__margin(margin);
    double a = cols * cell_cm / 200.0 + margin, b = rows * cell_cm / 200.0 + margin;
    for (int k = 0; k < 4; k++)
        if (!hol__inside(xz, n, k & 1 ? a : -a, k & 2 ? b : -b))
            return 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if (hol__crosses(xz[2 * j], xz[2 * j + 1], xz[2 * i], xz[2 * i + 1], a, b))
            return 0;
    return 1;
}

typedef struct hol__poly {
    const float *xz;
    int n;
    double margin;
} hol__poly;

static int hol__poly_cm(const void *ctx, int c, int r)
{
    const hol__poly *q = ctx;
    for (int cm = HOL_FIT_MAX_CM; cm >= HOL_FIT_MIN_CM; cm -= HOL_FIT_STEP_CM)
        if (hol_fit_polygon_holds(q->xz, q->n, q->margin, c, r, cm))
            return cm;
    return 0;
}

hol_err hol_fit_polygon(const float *xz, int n, double margin, hol_fit *out)
{
    if (!out || !xz || n < 3 || n > HOL_FIT_MAX_POINTS)
        return HOL_EARG;
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < 2 * n; i++) {
        if (!isfinite(xz[i]) || fabs(xz[i]) > 1e6)
            return HOL_EARG;
        lo[i & 1] = xz[i] < lo[i & 1] ? xz[i] : lo[i & 1];
        hi[i & 1] = xz[i] > hi[i & 1] ? xz[i] : hi[i & 1];
    }
    hol__poly q = {xz, n, hol__margin(margin)};
    hol__choose(hol__poly_cm, &q, hi[0] - lo[0], hi[1] - lo[1], out);
    return HOL_OK;
}

/* "2.6", "0.55": metres with the digits they need (at most 2). */
static void hol__metres(double m, char *buf, size_t cap)
{
    long cm = (long)floor(m * 100 + 0.5);
    if (cm % 10 == 0)
        snprintf(buf, cap, "%ld.%ld", cm / 100, cm / 10 % 10);
    else
        snprintf(buf, cap, "%ld.%02ld", cm / 100, cm % 100);
}

hol_err hol_fit_level(hol_level *lv, const hol_fit *f, int *out_changed)
{
    *out_changed = 0;
    if (lv->lvl.room_cols || lv->lvl.room_rows || lv->lvl.cell_m > 0)
        return HOL_OK;
    hol_level_err le;
    hol_err e = hol_level_set_geometry(lv, 0, f->cols, f->rows, f->cell_m, &le);
    *out_changed = e == HOL_OK;
    return e;
}

int hol_fit_text(const hol_fit *f, double margin, char *buf, size_t cap)
{
    return hol_fit_say(f, margin, HOL_LANG_EN, buf, cap);
}

int hol_fit_say(const hol_fit *f, double margin, int lang, char *buf, size_t cap)
{
    char w[32], d[32], c[32], m[32];
    hol__metres(f->area_w, w, sizeof w);
    hol__metres(f->area_d, d, sizeof d);
    hol__metres(f->cell_m, c, sizeof c);
    hol__metres(hol__margin(margin), m, sizeof m);
    if (f->too_small)
        return snprintf(buf, cap, hol_str(lang, HOL_S_FIT_SMALL_FMT), w, d, m);
    return snprintf(buf, cap, hol_str(lang, HOL_S_FIT_FMT), f->cols, f->rows, c, w, d);
}
