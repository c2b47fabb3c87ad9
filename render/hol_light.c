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

hol_err hol_light_prepare(const hol_frame_desc *f, hol_light_frame *out)
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
        out->pos[out->n][0] = fr[2];
        out->pos[out->n][1] = fr[5];
        out->pos[out->n][2] = fr[8];
        out->n++;
    }
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
