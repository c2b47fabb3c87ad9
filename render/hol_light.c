/* hol_light.c - lights in the world's geometry (see hol_light.h). */
#include "hol_light.h"

#include <math.h>
#include <string.h>

#include "../core/hol_hyper.h"

#define HOL__PI 3.14159265358979323846

void hol_light_point(const hol_light_frame *lf, double x, double z, double out_p[3])
{
    hol_hyper_from_klein(x * lf->klein, -z * lf->klein, lf->flat, out_p);
}

double hol_light_floor_m(const hol_light_frame *lf, const double p[3], const double l[3])
{
    return hol_hyper_dist(p, l, lf->flat) * lf->metres_per_unit;
}

double hol_light_falloff(double d_m, double x_units, int flat)
{
    if (d_m >= HOL_LIGHT_RADIUS_M)
        return 0;
    double u = d_m / HOL_LIGHT_RADIUS_M, w = (1 - u * u) * (1 - u * u);
    double s = flat || x_units < 1e-6 ? 1 : x_units / sinh(x_units);
    double e = d_m / HOL_LIGHT_D0_M;
    return w * (1 - HOL_LIGHT_PHYS + HOL_LIGHT_PHYS * s) / (1 + e * e);
}

int hol_light_firefly(hol_tile t, const hol_tile_content *c, double cell_m, double time_s,
                      double out_xzh[3])
{
    if (c->object != HOL_OBJ_CREEK && c->object != HOL_OBJ_SPRING &&
        c->object != HOL_OBJ_POOL && c->object != HOL_OBJ_FLOWERS)
        return 0;
    uint64_t h = hol_tile_hash(t) * 0x9e3779b97f4a7c15ull;
    double u[5];
    for (int i = 0; i < 5; i++)
        u[i] = (double)((h >> (12 * i)) & 0xfff) / 4095.0;
    double period = 5 + 4 * u[3], ph = 2 * HOL__PI * u[4];
    double a = 2 * HOL__PI * time_s / period + ph;
    out_xzh[0] = (u[0] - 0.5) * 0.6 * cell_m + 0.08 * (cos(a) - cos(ph));
    out_xzh[1] = (u[1] - 0.5) * 0.6 * cell_m + 0.08 * (sin(a) - sin(ph));
    out_xzh[2] = 0.45 + 0.3 * u[2] + 0.05 * sin(2 * a);
    return 1;
}

int hol_light_ff_of(const hol_light_frame *lf, hol_tile t)
{
    for (int i = 0; i < lf->nff; i++)
        if (hol_tile_eq(lf->ff_tile[i], t))
            return i;
    return -1;
}

/* Light i at the point of (x, z) metres, h up, in the frame fr of a tile. */
static void hol__put(hol_light_frame *o, const double fr[9], double x, double z, double h)
{
    double p[3];
    hol_light_point(o, x, z, p);
    for (int r = 0; r < 3; r++)
        o->pos[o->n][r] = fr[3 * r] * p[0] + fr[3 * r + 1] * p[1] + fr[3 * r + 2] * p[2];
    o->h[o->n] = h;
    o->ssin[o->n] = -2;
    memset(o->sd[o->n], 0, sizeof o->sd[0]);
}

/* A lantern's spot: its direction in its tile's frame fr (see the contract). */
static void hol__spot(hol_light_frame *o, const double fr[9], int spot)
{
    if (spot < 1 || spot > 5)
        return;
    double tilt = (spot == 5 ? 90 : HOL_LIGHT_SPOT_TILT_DEG) * HOL__PI / 180;
    o->ssin[o->n] = sin(tilt);
    if (spot == 5)
        return;
    /* heading +y turned clockwise (towards +x) by spot - 1 quarter turns */
    static const double dx[4] = {0, 1, 0, -1}, dy[4] = {1, 0, -1, 0};
    double k = cos(tilt) * o->metres_per_unit;
    for (int r = 0; r < 3; r++)
        o->sd[o->n][r] = k * (fr[3 * r] * dx[spot - 1] + fr[3 * r + 1] * dy[spot - 1]);
}

/* The fireflies of the world's tiles within HOL_LIGHT_FF_STEPS steps of
 * the user's (breadth first: the nearest first, up to HOL_LIGHT_MAX_FF). */
static void hol__fireflies(const hol_frame_desc *f, const struct hol_world *w,
                           hol_light_frame *o)
{
    enum { NT = 256 };
    hol_tile seen[NT];
    int n = 0, head = 0, level_end = 1, depth = 0, nff = 0;
    seen[n++] = f->user.tile;
    while (head < n && nff < HOL_LIGHT_MAX_FF) {
        if (head == level_end) {
            if (++depth > HOL_LIGHT_FF_STEPS)
                break;
            level_end = n;
        }
        hol_tile t = seen[head++];
        for (int e = 0; e < 4 && depth < HOL_LIGHT_FF_STEPS; e++) {
            hol_tile nb;
            int dup = 0;
            if (hol_tile_step(t, e, &nb, NULL) || n >= NT)
                continue;
            for (int i = 0; i < n && !dup; i++)
                dup = hol_tile_eq(seen[i], nb);
            if (!dup)
                seen[n++] = nb;
        }
        hol_tile_content c;
        double xzh[3], fr[9];
        if (hol_world_peek(w, t, &c) || !hol_light_firefly(t, &c, o->cell_m, f->time_s, xzh) ||
            hol_hyper_frame(f->user.tile, f->user.orient, t, fr))
            continue;
        hol__put(o, fr, xzh[0], xzh[1], xzh[2]);
        o->ff_tile[o->nff] = t;
        memcpy(o->ff_xzh[o->nff++], xzh, sizeof xzh);
        o->ff[o->n++] = 1;
        o->fx = o->fx ? o->fx : 1;
        nff++;
    }
}

hol_err hol_light_prepare(const hol_frame_desc *f, const struct hol_world *w,
                          hol_light_frame *out)
{
    memset(out, 0, sizeof *out);
    double m = f->cell_m > 0 ? f->cell_m : 1.0;
    if (!(m >= 0.5 && m <= 1.5))
        return HOL_EARG;
    int q = hol_tile_q(f->user.tile);
    out->q = q;
    out->flat = q == 4;
    out->user = f->user;
    out->cell_m = m;
    if (out->flat) {
        out->klein = 1 / m;
        out->metres_per_unit = m;
        out->circum_m = m * sqrt(0.5);
    } else {
        double rin = hol_hyper_edge_q(q) / 2;
        out->klein = tanh(rin) / (m / 2);
        out->metres_per_unit = m / hol_hyper_edge_q(q);
        out->circum_m = acosh(1 / tan(HOL__PI / q)) * out->metres_per_unit;
    }
    double dx = f->cam.eye[0] - (f->user.col + 0.5) * m;
    double dz = f->cam.eye[2] - (f->user.row + 0.5) * m;
    hol_light_point(out, dx, dz, out->eye);
    out->eye_h = f->cam.eye[1];
    int nl = f->nlanterns < HOL_RENDER_MAX_LANTERNS ? f->nlanterns : HOL_RENDER_MAX_LANTERNS;
    for (int i = 0; i < nl; i++) {
        double fr[9];
        if (hol_hyper_frame(f->user.tile, f->user.orient, f->lanterns[i], fr))
            continue;
        hol__put(out, fr, 0, 0, HOL_LIGHT_HEIGHT_M);
        hol__spot(out, fr, f->lantern_spot[i]);
        if (out->ssin[out->n] > -1.5)
            out->fx = 2;
        out->n++;
    }
    if (f->fireflies && w)
        hol__fireflies(f, w, out);
    return HOL_OK;
}

int hol_light_tile(const hol_light_frame *lf, hol_tile t, double out_frame[9],
                   int out_idx[HOL_LIGHT_PER_TILE])
{
    if (hol_hyper_frame(lf->user.tile, lf->user.orient, t, out_frame))
        return -1;
    double c[3] = {out_frame[2], out_frame[5], out_frame[8]};
    double dist[HOL_LIGHT_PER_TILE];
    int n = 0;
    for (int i = 0; i < lf->n; i++) {
        double d = hol_light_floor_m(lf, c, lf->pos[i]);
        if (d >= HOL_LIGHT_RADIUS_M + lf->circum_m)
            continue;
        /* insert by distance (ties: the lantern named first) */
        int k = n < HOL_LIGHT_PER_TILE ? n++ : HOL_LIGHT_PER_TILE;
        while (k > 0 && dist[k - 1] > d) {
            if (k < HOL_LIGHT_PER_TILE) {
                dist[k] = dist[k - 1];
                out_idx[k] = out_idx[k - 1];
            }
            k--;
        }
        if (k < HOL_LIGHT_PER_TILE) {
            dist[k] = d;
            out_idx[k] = i;
        }
    }
    return n;
}
