/* hol_math_exp.c - e^x and the hyperbolic functions (contract: hol_math_exp.h).
 * e^r - 1 for |r| <= ln 2 / 2 by its Taylor series to r^14 (the rest below
 * 1e-17), e^x as 2^k (1 + that) with x = k ln 2 + r (ln 2 in two parts, as
 * fdlibm splits it), the hyperbolic functions from those. */
#include "hol_math_exp.h"

#include <math.h>

#include <stdint.h>
#include <string.h>

#define HOL__LN2_HI 6.93147180369123816490e-01
#define HOL__LN2_LO 1.90821492927058770002e-10
#define HOL__INV_LN2 1.44269504088896338700e+00

/* e^r - 1 for |r| <= 0.35: r (1 + r/2 (1 + r/3 (1 + ... (1 + r/14)))) */
static double hol__em1(double r)
{
    double s = 1;
    for (int n = 14; n >= 2; n--)
        s = 1 + r / n * s;
    return r * s;
}

/* 2^k for -1022 <= k <= 1023 */
static double hol__pow2(int k)
{
    uint64_t u = (uint64_t)(k + 1023) << 52;
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

double hol_exp(double x)
{
    if (x != x)
        return x;
    if (x > 709.782712893384)
        return HUGE_VAL;
    if (x < -745.2)
        return 0;
    int k = (int)floor(x * HOL__INV_LN2 + 0.5);
    double r = (x - k * HOL__LN2_HI) - k * HOL__LN2_LO;
    /* 2^k in two halves, each a normal number, so that the ends of the
     * range neither overflow early nor lose the subnormals outright */
    return (1 + hol__em1(r)) * hol__pow2(k / 2) * hol__pow2(k - k / 2);
}

double hol_expm1(double x)
{
    if (fabs(x) <= 0.3465) /* no cancellation: the series itself */
        return hol__em1(x);
    return hol_exp(x) - 1;
}

double hol_sinh(double x)
{
    double a = fabs(x), h = copysign(0.5, x);
    if (a < 22) {
        double t = hol_expm1(a);
        return h * (t + t / (t + 1));
    }
    return h * hol_exp(a); /* e^-a is below an ulp of e^a */
}

double hol_cosh(double x)
{
    double a = fabs(x);
    if (a < 22) {
        double t = hol_exp(a);
        return 0.5 * t + 0.5 / t;
    }
    return 0.5 * hol_exp(a);
}

double hol_tanh(double x)
{
    double a = fabs(x);
    if (x != x)
        return x;
    double t = 1;
    if (a <= 22) {
        double e = hol_expm1(2 * a);
        t = e / (e + 2);
    }
    return copysign(t, x);
}
