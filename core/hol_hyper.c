#include "hol_hyper.h"

#include <math.h>

#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

/* cos(pi/5) / sin(pi/4): the edge is 2 acosh(c) */
static double hol__edge_c(void)
{
    return hol_cos(HOL__PI / 5.0) / hol_sin(HOL__PI / 4.0);
}

double hol_hyper_edge(void)
{
    return 2.0 * hol_acosh(hol__edge_c());
}

/* m = m * R(turn quarter turns counter-clockwise) * T(+y by d) */
static void hol__apply(double m[9], int turn, double ch, double sh)
{
    static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    double c = cs[turn & 3][0], s = cs[turn & 3][1];
    /* R * T = [[c, -s ch, -s sh], [s, c ch, c sh], [0, sh, ch]] */
    double rt[9] = {c, -s * ch, -s * sh, s, c * ch, c * sh, 0, sh, ch};
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
    /* cosh and sinh of the edge 2 acosh(c): 2c^2 - 1 and 2c sqrt(c^2 - 1) */
    double c = hol__edge_c(), ch = 2.0 * c * c - 1.0, sh = 2.0 * c * sqrt(c * c - 1.0);
    double m[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int i = 0; i < n; i++)
        hol__apply(m, rel[i], ch, sh);
    hol__apply(m, facing, 1.0, 0.0);
    for (int i = 0; i < 9; i++)
        out_m[i] = m[i];
    return HOL_OK;
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
        *out_dist = hol_acosh(w < 1.0 ? 1.0 : w);
    return HOL_OK;
}

void hol_hyper_to_disk(const double p[3], double out_xy[2])
{
    out_xy[0] = p[0] / (1.0 + p[2]);
    out_xy[1] = p[1] / (1.0 + p[2]);
}
