/* hol_shadow.c - a tile's shadow mask (core/hol_shadow.h). */
#include "hol_shadow.h"

#include <math.h>

/* The stored value of one slot from its wedges' u (n of them). */
static double hol__mask_value(const double *u, int n)
{
    double s = 0, top = -HOL_SHADOW_MASK_RANGE;
    for (int p = 0; p < n; p++) {
        double o = 0.5 + u[p];
        s += o < 0 ? 0 : o > 1 ? 1 : o;
        top = u[p] > top ? u[p] : top;
    }
    if (s <= 0)
        return top;
    if (s >= 1)
        return 0.5 + (s - 1) + (top > 0.5 ? top - 0.5 : 0);
    return s - 0.5;
}

void hol_shadow_mask(const hol_shadow_mask_desc *d, uint8_t *out)
{
    enum { N = HOL_SHADOW_MASK_N, MAXW = 64 };
    const double R = HOL_SHADOW_MASK_RANGE;
    for (int j = 0; j < N; j++) {
        double ky = d->half * (2.0 * j / (N - 1) - 1);
        for (int i = 0; i < N; i++) {
            double kx = d->half * (2.0 * i / (N - 1) - 1), kk = kx * kx + ky * ky;
            double g = d->flat ? 1 : 1 / sqrt(kk < 0.999999 ? 1 - kk : 1e-6);
            double u[4][MAXW];
            int nu[4] = {0, 0, 0, 0};
            for (int p = 0; p < d->n; p++) {
                const double(*h)[3] = d->wedge[p];
                double v = h[0][0] * kx + h[0][1] * ky + h[0][2];
                for (int q = 1; q < 3; q++) {
                    double w = h[q][0] * kx + h[q][1] * ky + h[q][2];
                    v = w < v ? w : v;
                }
                int s = d->slot[p] & 3;
                if (nu[s] < MAXW)
                    u[s][nu[s]++] = g * v;
            }
            uint8_t *px = out + 4 * (j * N + i);
            for (int s = 0; s < 4; s++) {
                double v = nu[s] ? hol__mask_value(u[s], nu[s]) : -R;
                v = v < -R ? -R : v > R ? R : v;
                px[s] = (uint8_t)floor((v / R + 1) * 127.5 + 0.5);
            }
        }
    }
}
