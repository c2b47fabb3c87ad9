/* hol_light.c - lights in the world's geometry (see hol_light.h). */
#include "hol_light.h"

#include <math.h>
#include <string.h>

#include "../core/hol_hyper.h"
#include "hol_view.h"

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
static void hol__light_put(hol_light_frame *o, const double fr[9], double x, double z, double h)
{
    double p[3];
    hol_light_point(o, x, z, p);
    for (int r = 0; r < 3; r++)
        o->pos[o->n][r] = fr[3 * r] * p[0] + fr[3 * r + 1] * p[1] + fr[3 * r + 2] * p[2];
    o->h[o->n] = h;
    o->wt[o->n] = 1;
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
        hol__light_put(o, fr, xzh[0], xzh[1], xzh[2]);
        o->ff_tile[o->nff] = t;
        memcpy(o->ff_xzh[o->nff++], xzh, sizeof xzh);
        o->ff[o->n++] = 1;
        o->fx = o->fx ? o->fx : 1;
        nff++;
    }
}

/* The tile-frame constants of trunk shadows (corners, edge reflections,
 * circumradius, the trunk's radius and soft edge in curvature units). */
static void hol__shadow_frame(hol_light_frame *o)
{
    double A = o->klein * o->cell_m / 2; /* Klein coordinate of an edge */
    for (int k = 0; k < 4; k++)
        hol_hyper_from_klein(k & 1 ? A : -A, k & 2 ? A : -A, o->flat, o->corner[k]);
    for (int e = 0; e < 4; e++) {
        /* edge e: x = +-A (e 0, 1) or y = +-A (e 2, 3); its plane's normal
         * n = (1, 0, sA) (or (0, 1, sA)), reflection v - 2 <v,n>/<n,n> n */
        double sg = e & 1 ? -1 : 1, *M = o->refl[e];
        int ax = e < 2 ? 0 : 1;
        memset(M, 0, 9 * sizeof *M);
        M[0] = M[4] = M[8] = 1;
        if (o->flat) {
            M[4 * ax] = -1;
            M[3 * ax + 2] = sg; /* x -> sg - x: the line x = sg/2 */
            continue;
        }
        double n[3] = {0, 0, sg * A}, jn[3];
        n[ax] = 1;
        jn[0] = n[0], jn[1] = n[1], jn[2] = -n[2];
        double nn = 1 - A * A;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                M[3 * i + j] -= 2 * n[i] * jn[j] / nn;
    }
    double c[3] = {0, 0, 1};
    o->rho = hol_hyper_dist(c, o->corner[0], o->flat);
    o->trunk_r = HOL_SHADOW_TRUNK_M / o->metres_per_unit;
    o->reach = HOL_LIGHT_RADIUS_M / o->metres_per_unit;
}

static double hol__lor(const double a[3], const double b[3], int flat)
{
    return a[0] * b[0] + a[1] * b[1] - (flat ? 0 : a[2] * b[2]);
}

double hol_light_seg_dist(const double t[3], const double a[3], const double b[3], int flat)
{
    double det = t[0] * (a[1] * b[2] - a[2] * b[1]) - t[1] * (a[0] * b[2] - a[2] * b[0]) +
                 t[2] * (a[0] * b[1] - a[1] * b[0]);
    double at = hol_hyper_dist(a, t, flat), bt = hol_hyper_dist(b, t, flat);
    double ab = hol_hyper_dist(a, b, flat);
    if (flat) {
        double u[2] = {b[0] - a[0], b[1] - a[1]}, v[2] = {t[0] - a[0], t[1] - a[1]};
        double w[2] = {t[0] - b[0], t[1] - b[1]};
        if (ab < 1e-12 || u[0] * v[0] + u[1] * v[1] <= 0)
            return at;
        if (u[0] * w[0] + u[1] * w[1] >= 0)
            return bt;
        return fabs(det) / ab;
    }
    double cab = -hol__lor(a, b, 0), cat = -hol__lor(a, t, 0), cbt = -hol__lor(b, t, 0);
    if (ab < 1e-12 || cab * cat <= cbt)
        return at;
    if (cab * cbt <= cat)
        return bt;
    return asinh(fabs(det) / sinh(ab));
}

static void hol__mul3(const double A[9], const double B[9], double out[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* The same point (coordinates within eps: a cheap test, no acosh)? */
static int hol__same(const double a[3], const double b[3], double eps)
{
    return fabs(a[0] - b[0]) < eps && fabs(a[1] - b[1]) < eps && fabs(a[2] - b[2]) < eps;
}

/* Is point c within dmax of the segment from one of the used lights to the
 * tile's centre? */
static int hol__near_segs(const hol_light_frame *lf, const double c[3], const double lp[][3],
                          const uint8_t *use, int nl, double dmax)
{
    static const double o[3] = {0, 0, 1};
    for (int i = 0; i < nl; i++)
        if (use[i] && hol_light_seg_dist(c, lp[i], o, lf->flat) < dmax)
            return 1;
    return 0;
}

/* The trunks that may shadow a tile: the corners of the tiles whose centre
 * lies within 2 rho + r of a light's segment (breadth first over edge
 * reflections from the tile itself); returns how many. */
static int hol__shadow_trunks(const hol_light_frame *lf, const double lp[][3],
                              const uint8_t *use, int nl, double (*vt)[3], int maxv)
{
    enum { NT = 160 };
    double fr[NT][9], cen[NT][3];
    int n = 1, nv = 0;
    memset(fr[0], 0, sizeof fr[0]);
    fr[0][0] = fr[0][4] = fr[0][8] = 1;
    cen[0][0] = cen[0][1] = 0;
    cen[0][2] = 1;
    double wide = 2 * lf->rho + lf->trunk_r, eps = 1e-6;
    for (int h = 0; h < n; h++) {
        for (int k = 0; k < 4; k++) {
            double v[3];
            for (int r = 0; r < 3; r++)
                v[r] = fr[h][3 * r] * lf->corner[k][0] + fr[h][3 * r + 1] * lf->corner[k][1] +
                       fr[h][3 * r + 2] * lf->corner[k][2];
            int dup = 0;
            for (int i = 0; i < nv && !dup; i++)
                dup = hol__same(vt[i], v, eps);
            if (!dup && nv < maxv)
                memcpy(vt[nv++], v, sizeof v);
        }
        for (int e = 0; e < 4 && n < NT; e++) {
            hol__mul3(fr[h], lf->refl[e], fr[n]);
            double *c = cen[n];
            for (int r = 0; r < 3; r++)
                c[r] = fr[n][3 * r + 2];
            int dup = 0;
            for (int i = 0; i < n && !dup; i++)
                dup = hol__same(cen[i], c, eps);
            if (!dup && hol__near_segs(lf, c, lp, use, nl, wide))
                n++;
        }
    }
    return nv;
}

/* Klein point k in triangle (a, b, c) (straight in Klein; either winding) */
static int hol__in_tri(const double k[2], const double a[2], const double b[2], const double c[2])
{
    double d0 = (b[0] - a[0]) * (k[1] - a[1]) - (b[1] - a[1]) * (k[0] - a[0]);
    double d1 = (c[0] - b[0]) * (k[1] - b[1]) - (c[1] - b[1]) * (k[0] - b[0]);
    double d2 = (a[0] - c[0]) * (k[1] - c[1]) - (a[1] - c[1]) * (k[0] - c[0]);
    return (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
}

/* Can trunk t shadow some point of the tile from light l? It must lie
 * within r of the convex hull of l and the tile (the tile and the
 * triangles from l over its edges; straight in Klein): inside, or within
 * r of an edge or of a segment from l to a corner. */
static int hol__may_shadow(const hol_light_frame *lf, const double t[3], const double l[3])
{
    static const int cyc[5] = {0, 1, 3, 2, 0};
    double A = lf->klein * lf->cell_m / 2, r = lf->trunk_r;
    double tk[2] = {t[0] / t[2], t[1] / t[2]}, lk[2] = {l[0] / l[2], l[1] / l[2]};
    if (fabs(tk[0]) <= A && fabs(tk[1]) <= A)
        return 1;
    for (int e = 0; e < 4; e++) {
        const double *a = lf->corner[cyc[e]], *b = lf->corner[cyc[e + 1]];
        double ak[2] = {a[0] / a[2], a[1] / a[2]}, bk[2] = {b[0] / b[2], b[1] / b[2]};
        if (hol__in_tri(tk, lk, ak, bk) || hol_light_seg_dist(t, l, a, lf->flat) < r ||
            hol_light_seg_dist(t, a, b, lf->flat) < r)
            return 1;
    }
    return 0;
}

/* Does trunk t's shadow from light l (its half-planes h, hol_light_wedge)
 * reach a point of the tile farther than r + e from t (nearer, the trunk
 * hides the floor)? The tile (the Klein square) clipped by the three
 * half-planes widened by the soft edge (g >= 1, so value >= -0.5 holds
 * wherever the occlusion is not 0); distance from t is convex along the
 * clipped polygon's straight (geodesic) edges, so its corners decide. */
static int hol__wedge_reaches(const hol_light_frame *lf, const double t[3], double h[3][3])
{
    enum { NP = 12 };
    double A = lf->klein * lf->cell_m / 2, poly[2][NP][2];
    static const double sq[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    int n = 4, cur = 0;
    for (int i = 0; i < 4; i++)
        poly[0][i][0] = sq[i][0] * A, poly[0][i][1] = sq[i][1] * A;
    for (int j = 0; j < 3 && n > 0; j++) {
        int m = 0;
        for (int i = 0; i < n && m < NP - 1; i++) {
            const double *a = poly[cur][i], *b = poly[cur][(i + 1) % n];
            double va = h[j][0] * a[0] + h[j][1] * a[1] + h[j][2] + 0.5;
            double vb = h[j][0] * b[0] + h[j][1] * b[1] + h[j][2] + 0.5;
            if (va >= 0)
                memcpy(poly[!cur][m++], a, sizeof poly[0][0]);
            if ((va >= 0) != (vb >= 0)) {
                double u = va / (va - vb);
                poly[!cur][m][0] = a[0] + u * (b[0] - a[0]);
                poly[!cur][m++][1] = a[1] + u * (b[1] - a[1]);
            }
        }
        n = m;
        cur = !cur;
    }
    double far = lf->trunk_r + HOL_SHADOW_EDGE_M / lf->metres_per_unit;
    for (int i = 0; i < n; i++) {
        double p[3];
        hol_hyper_from_klein(poly[cur][i][0], poly[cur][i][1], lf->flat, p);
        if (hol_hyper_dist(p, t, lf->flat) > far)
            return 1;
    }
    return 0;
}

void hol_light_shadows(const hol_light_frame *lf, const double fr[9], const double lp[][3],
                       const int *lidx, int nl, hol_shadow_set *out)
{
    enum { NV = 400 };
    double vt[NV][3], key[HOL_SHADOW_PAIRS];
    (void)fr;
    out->n = 0;
    uint8_t use[HOL_LIGHT_PER_TILE] = {0};
    int any = 0;
    for (int k = 0; k < nl; k++)
        any |= use[k] = !lf->ff[lidx[k]];
    if (!any)
        return;
    int nv = hol__shadow_trunks(lf, lp, use, nl, vt, NV);
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < nl; k++) { /* every trunk, every lantern */
            if (!use[k])
                continue;
            double d = hol_hyper_dist(lp[k], vt[i], lf->flat);
            if (d >= lf->reach || d <= 2 * lf->trunk_r || !hol__may_shadow(lf, vt[i], lp[k]))
                continue;
            double h[3][3];
            hol_light_wedge(lf, lp[k], vt[i], h);
            if (!hol__wedge_reaches(lf, vt[i], h))
                continue;
            /* insert by distance to its light (ties: the one found first) */
            int j = out->n < HOL_SHADOW_PAIRS ? out->n++ : HOL_SHADOW_PAIRS;
            while (j > 0 && key[j - 1] > d) {
                if (j < HOL_SHADOW_PAIRS) {
                    key[j] = key[j - 1];
                    out->slot[j] = out->slot[j - 1];
                    memcpy(out->trunk[j], out->trunk[j - 1], sizeof out->trunk[0]);
                }
                j--;
            }
            if (j < HOL_SHADOW_PAIRS) {
                key[j] = d;
                out->slot[j] = k;
                memcpy(out->trunk[j], vt[i], sizeof vt[0]);
            }
        }
}

void hol_light_wedge(const hol_light_frame *lf, const double l[3], const double t[3],
                     double out[3][3])
{
    double sc = lf->metres_per_unit / (2 * HOL_SHADOW_EDGE_M), n[3][3];
    if (lf->flat) {
        double w[2] = {t[0] - l[0], t[1] - l[1]}, D = hypot(w[0], w[1]);
        w[0] /= D, w[1] /= D;
        double m[2] = {-w[1], w[0]}, sa = lf->trunk_r / D, ca = sqrt(1 - sa * sa);
        for (int i = 0; i < 2; i++) {
            n[0][i] = sa * w[i] - ca * m[i];
            n[1][i] = sa * w[i] + ca * m[i];
            n[2][i] = w[i];
        }
        for (int j = 0; j < 3; j++) {
            const double *at = j == 2 ? t : l;
            out[j][0] = n[j][0] * sc;
            out[j][1] = n[j][1] * sc;
            out[j][2] = -(n[j][0] * at[0] + n[j][1] * at[1]) * sc;
        }
        return;
    }
    double cD = -hol__lor(l, t, 0), sD = sqrt(cD * cD - 1);
    double c[3] = {l[1] * t[2] - l[2] * t[1], l[2] * t[0] - l[0] * t[2],
                   l[0] * t[1] - l[1] * t[0]};
    double mm[3] = {c[0], c[1], -c[2]}, nm = sqrt(hol__lor(mm, mm, 0));
    double sa = sinh(lf->trunk_r) / sD, ca = sqrt(1 - sa * sa);
    for (int i = 0; i < 3; i++) {
        double w = (t[i] - cD * l[i]) / sD, v = (l[i] - cD * t[i]) / sD, m = mm[i] / nm;
        n[0][i] = sa * w - ca * m;
        n[1][i] = sa * w + ca * m;
        n[2][i] = -v;
    }
    for (int j = 0; j < 3; j++) { /* <n, P> = g (n_x k_x + n_y k_y - n_z) */
        out[j][0] = n[j][0] * sc;
        out[j][1] = n[j][1] * sc;
        out[j][2] = -n[j][2] * sc;
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
    hol__shadow_frame(out);
    double dx = f->cam.eye[0] - (f->user.col + 0.5) * m;
    double dz = f->cam.eye[2] - (f->user.row + 0.5) * m;
    hol_light_point(out, dx, dz, out->eye);
    out->eye_h = f->cam.eye[1];
    int nl = f->nlanterns < HOL_RENDER_MAX_LANTERNS ? f->nlanterns : HOL_RENDER_MAX_LANTERNS;
    for (int i = 0; i < nl; i++) {
        double fr[9];
        if (hol_hyper_frame(f->user.tile, f->user.orient, f->lanterns[i], fr))
            continue;
        hol__light_put(out, fr, 0, 0, HOL_LIGHT_HEIGHT_M);
        hol__spot(out, fr, f->lantern_spot[i]);
        if (out->ssin[out->n] > -1.5)
            out->fx = 2;
        out->n++;
    }
    if (f->carried) { /* in the user's tile: the user frame itself */
        static const double id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        hol__light_put(out, id, f->carried_pos[0] - (f->user.col + 0.5) * m,
                       f->carried_pos[2] - (f->user.row + 0.5) * m, f->carried_pos[1]);
        out->n++;
        if (f->carried_pos[1] != HOL_LIGHT_HEIGHT_M && !out->fx)
            out->fx = 1; /* a height of its own: the programs with heights */
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
        if (lf->ff[i]) /* the lanterns first (hol_light_budget), then fireflies */
            d += 1e6;
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

/* Light i out of the frame (the later ones move down one). */
static void hol__light_drop(hol_light_frame *lf, int i)
{
    for (int j = i; j + 1 < lf->n; j++) {
        memcpy(lf->pos[j], lf->pos[j + 1], sizeof lf->pos[0]);
        memcpy(lf->sd[j], lf->sd[j + 1], sizeof lf->sd[0]);
        lf->h[j] = lf->h[j + 1];
        lf->wt[j] = lf->wt[j + 1];
        lf->ff[j] = lf->ff[j + 1];
        lf->ssin[j] = lf->ssin[j + 1];
    }
    lf->n--;
}

/* Lights a and b (round lanterns, a < b) as one at their weighted mean
 * (on the hyperboloid: the weighted sum of the points scaled back onto it;
 * flat: the mean), its height the weighted mean, its weight the sum. */
static void hol__light_merge(hol_light_frame *lf, int a, int b)
{
    double wa = lf->wt[a], wb = lf->wt[b], p[3];
    for (int r = 0; r < 3; r++)
        p[r] = (wa * lf->pos[a][r] + wb * lf->pos[b][r]) / (wa + wb);
    double k = lf->flat ? 1 / p[2] : 1 / sqrt(-hol__lor(p, p, 0));
    for (int r = 0; r < 3; r++)
        lf->pos[a][r] = p[r] * k;
    lf->h[a] = (wa * lf->h[a] + wb * lf->h[b]) / (wa + wb);
    lf->wt[a] = wa + wb;
    hol__light_drop(lf, b);
}

/* The lanterns of the first drawn tile (centres c[0..nt-1]) that more
 * than HOL_LIGHT_PER_TILE reach (into idx; their count), or 0: none. A light
 * reaches a tile when its floor distance to the centre is under R plus the
 * circumradius (hol_light_tile's rule), here by the Lorentz product. */
static int hol__over_full(const hol_light_frame *lf, const double (*c)[3], int nt,
                          int idx[HOL_LIGHT_MAX])
{
    double u = (HOL_LIGHT_RADIUS_M + lf->circum_m) / lf->metres_per_unit;
    double lim = lf->flat ? u * u : cosh(u);
    for (int t = 0; t < nt; t++) {
        int n = 0;
        for (int i = 0; i < lf->n; i++) {
            if (lf->ff[i])
                continue;
            double dx = c[t][0] - lf->pos[i][0], dy = c[t][1] - lf->pos[i][1];
            double v = lf->flat ? dx * dx + dy * dy : -hol__lor(c[t], lf->pos[i], 0);
            if (v < lim)
                idx[n++] = i;
        }
        if (n > HOL_LIGHT_PER_TILE)
            return n;
    }
    return 0;
}

/* One step towards the budget on an over-full tile's lanterns
 * idx[0..n-1]: merge its two nearest round lanterns, else (spots) drop its
 * lantern farthest from the user. */
static void hol__budget_step(hol_light_frame *lf, const int *idx, int n)
{
    int ba = -1, bb = -1;
    double best = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++) {
            int a = idx[i], b = idx[j];
            if (lf->ssin[a] > -1.5 || lf->ssin[b] > -1.5)
                continue;
            double d = hol_hyper_dist(lf->pos[a], lf->pos[b], lf->flat);
            if (ba < 0 || d < best)
                ba = a, bb = b, best = d;
        }
    if (ba >= 0) {
        hol__light_merge(lf, ba, bb);
        return;
    }
    static const double o[3] = {0, 0, 1};
    int far = idx[0];
    for (int k = 1; k < n; k++)
        if (hol_hyper_dist(lf->pos[idx[k]], o, lf->flat) > hol_hyper_dist(lf->pos[far], o, lf->flat))
            far = idx[k];
    hol__light_drop(lf, far);
}

/* Does the foot of point p (user frame) lie in the tile of frame fr (its
 * Klein square, with a margin of 1e-9)? */
static int hol__in_tile(const hol_light_frame *lf, const double fr[9], const double p[3])
{
    double q[3];
    if (lf->flat) {
        double dx = p[0] - fr[2], dy = p[1] - fr[5];
        q[0] = fr[0] * dx + fr[3] * dy;
        q[1] = fr[1] * dx + fr[4] * dy;
        q[2] = 1;
    } else /* the inverse: Lorentz J F^T J */
        for (int i = 0; i < 3; i++)
            q[i] = fr[i] * p[0] * (i == 2 ? -1 : 1) + fr[3 + i] * p[1] * (i == 2 ? -1 : 1) +
                   fr[6 + i] * p[2] * (i == 2 ? 1 : -1);
    double a = lf->klein * lf->cell_m / 2 + 1e-9;
    return fabs(q[0]) <= a * q[2] && fabs(q[1]) <= a * q[2];
}

void hol_light_budget(hol_light_frame *lf, const hol_view *v)
{
    double c[HOL_VIEW_MAX_BRANCHES][3], fr[HOL_VIEW_MAX_BRANCHES][9];
    int nt = 0, idx[HOL_LIGHT_MAX], n;
    for (int k = 0; k < v->nbranches; k++) {
        if (v->branches[k].err ||
            hol_hyper_frame(lf->user.tile, lf->user.orient, v->branches[k].state.tile, fr[nt]))
            continue;
        c[nt][0] = fr[nt][2], c[nt][1] = fr[nt][5], c[nt][2] = fr[nt][8];
        nt++;
    }
    /* the hedges: a lantern whose foot lies in no drawn tile is outside
     * them, and they stand between it and every floor point of the room
     * (fireflies are left: docs/lighting.md) */
    for (int i = lf->n - 1; i >= 0 && nt > 0; i--) {
        int in = lf->ff[i];
        for (int t = 0; t < nt && !in; t++)
            in = hol__in_tile(lf, fr[t], lf->pos[i]);
        if (!in)
            hol__light_drop(lf, i);
    }
    if (lf->n <= HOL_LIGHT_PER_TILE)
        return;
    while ((n = hol__over_full(lf, (const double(*)[3])c, nt, idx)) > 0)
        hol__budget_step(lf, idx, n);
}
