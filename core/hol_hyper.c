#include "hol_hyper.h"

#include <math.h>

#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

/* cos(pi/q) / sin(pi/4): the edge of {4,q} (q >= 5) is 2 acosh(c) */
static double hol__edge_c(int q)
{
    return hol_cos(HOL__PI / q) / hol_sin(HOL__PI / 4.0);
}

double hol_hyper_edge(void) { return hol_hyper_edge_q(5); }

double hol_hyper_edge_q(int q)
{
    if (q == 4)
        return 1.0;
    if (q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q)
        return 0.0;
    return 2.0 * hol_acosh(hol__edge_c(q));
}

/* The translation by one edge along +y: [[1, 0, 0], [0, t0, t1], [0, t2, t3]]
 * (a boost in the hyperbolic plane, a shift in the flat one). */
static void hol__edge_move(int q, double t[4])
{
    if (q == 4) {
        t[0] = 1, t[1] = 1, t[2] = 0, t[3] = 1;
    } else {
        /* cosh and sinh of the edge 2 acosh(c): 2c^2 - 1 and 2c sqrt(c^2 - 1) */
        double c = hol__edge_c(q);
        t[0] = t[3] = 2.0 * c * c - 1.0;
        t[1] = t[2] = 2.0 * c * sqrt(c * c - 1.0);
    }
}

/* m = m * R(turn quarter turns counter-clockwise) * T (t as hol__edge_move) */
static void hol__apply(double m[9], int turn, const double t[4])
{
    static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    double c = cs[turn & 3][0], s = cs[turn & 3][1];
    /* R * T = [[c, -s t0, -s t1], [s, c t0, c t1], [0, t2, t3]] */
    double rt[9] = {c, -s * t[0], -s * t[1], s, c * t[0], c * t[1], 0, t[2], t[3]};
    double r[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[3 * i + j] = m[3 * i] * rt[j] + m[3 * i + 1] * rt[3 + j] +
                           m[3 * i + 2] * rt[6 + j];
    for (int i = 0; i < 9; i++)
        m[i] = r[i];
}

hol_err hol_hyper_frame(hol_tile a, int a_north, hol_tile b, double out_m[9])
{
    uint8_t rel[HOL_TILE_REL_MAX];
    int facing;
    int n = hol_tile_relative_letters(a, a_north, b, rel, &facing);
    if (n < 0)
        return HOL_EARG;
    double t[4], id[4] = {1, 0, 0, 1};
    hol__edge_move(hol_tile_q(a), t);
    double m[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int i = 0; i < n; i++)
        hol__apply(m, rel[i], t);
    hol__apply(m, facing, id);
    for (int i = 0; i < 9; i++)
        out_m[i] = m[i];
    return HOL_OK;
}

void hol_hyper_frame_step(int q, const double m[9], int turn, int arrive, double out_m[9])
{
    double t[4], id[4] = {1, 0, 0, 1}, r[9];
    hol__edge_move(q, t);
    for (int i = 0; i < 9; i++)
        r[i] = m[i];
    hol__apply(r, turn, t);
    hol__apply(r, -arrive, id);
    for (int i = 0; i < 9; i++)
        out_m[i] = r[i];
}

hol_err hol_hyper_pos(hol_tile a, int a_north, hol_tile b, double out_p[3],
                      double *out_angle, double *out_dist)
{
    double m[9];
    hol_err err = hol_hyper_frame(a, a_north, b, m);
    if (err)
        return err;
    double x = m[2], y = m[5], w = m[8];
    if (out_p) {
        out_p[0] = x;
        out_p[1] = y;
        out_p[2] = w;
    }
    if (out_angle)
        *out_angle = hol_atan2(-x, y);
    if (out_dist)
        *out_dist = hol_tile_q(a) == 4 ? sqrt(x * x + y * y) : hol_acosh(w < 1.0 ? 1.0 : w);
    return HOL_OK;
}

void hol_hyper_to_disk(const double p[3], double out_xy[2])
{
    out_xy[0] = p[0] / (1.0 + p[2]);
    out_xy[1] = p[1] / (1.0 + p[2]);
}

void hol_hyper_from_klein(double kx, double ky, int flat, double out_p[3])
{
    if (flat) {
        out_p[0] = kx, out_p[1] = ky, out_p[2] = 1;
        return;
    }
    double r2 = kx * kx + ky * ky;
    double s = 1 / sqrt(r2 < 0.999999 ? 1 - r2 : 1e-6);
    out_p[0] = kx * s, out_p[1] = ky * s, out_p[2] = s;
}

double hol_hyper_chord(const double p[3], const double q[3], int flat)
{
    double dx = p[0] - q[0], dy = p[1] - q[1], dw = p[2] - q[2];
    double c2 = dx * dx + dy * dy - (flat ? 0 : dw * dw);
    return sqrt(c2 > 0 ? c2 : 0);
}

double hol_hyper_dist(const double p[3], const double q[3], int flat)
{
    double c = hol_hyper_chord(p, q, flat);
    return flat ? c : 2 * hol_asinh(c / 2);
}
