/* hol_math.c - elementary functions in plain IEEE arithmetic (see
 * hol_math.h).
 *
 * The algorithms and coefficients are fdlibm's, as carried by musl:
 *
 *   Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
 *   Developed at SunPro, a Sun Microsystems, Inc. business.
 *   Permission to use, copy, modify, and distribute this
 *   software is freely granted, provided that this notice
 *   is preserved.
 */
#include "hol_math.h"

/* No fused multiply-add here, whatever the flags: the same bits on every
 * CPU (hol_math.h). */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <math.h> /* sqrt only: correctly rounded everywhere (IEEE 754) */
#include <stdint.h>
#include <string.h>

static uint64_t hol__bits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static double hol__from_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

static uint32_t hol__hi(double x)
{
    return (uint32_t)(hol__bits(x) >> 32);
}

static double hol__fabs(double x)
{
    return hol__from_bits(hol__bits(x) & 0x7fffffffffffffffull);
}

static int hol__isnan(double x)
{
    return (hol__bits(x) & 0x7fffffffffffffffull) > 0x7ff0000000000000ull;
}

/* NaN without dividing by zero at run time (no trap, same bits anywhere) */
static double hol__nan(void)
{
    return hol__from_bits(0x7ff8000000000000ull);
}

/* ---- sin, cos ------------------------------------------------------------ */

static const double
    hol__S1 = -1.66666666666666324348e-01, /* 0xBFC55555, 0x55555549 */
    hol__S2 = 8.33333333332248946124e-03,  /* 0x3F811111, 0x1110F8A6 */
    hol__S3 = -1.98412698298579493134e-04, /* 0xBF2A01A0, 0x19C161D5 */
    hol__S4 = 2.75573137070700676789e-06,  /* 0x3EC71DE3, 0x57B1FE7D */
    hol__S5 = -2.50507602534068634195e-08, /* 0xBE5AE5E6, 0x8A2B9CEB */
    hol__S6 = 1.58969099521155010221e-10,  /* 0x3DE5D93A, 0x5ACFD57C */
    hol__C1 = 4.16666666666666019037e-02,  /* 0x3FA55555, 0x5555554C */
    hol__C2 = -1.38888888888741095749e-03, /* 0xBF56C16C, 0x16C15177 */
    hol__C3 = 2.48015872894767294178e-05,  /* 0x3EFA01A0, 0x19CB1590 */
    hol__C4 = -2.75573143513906633035e-07, /* 0xBE927E4F, 0x809C52AD */
    hol__C5 = 2.08757232129817482790e-09,  /* 0x3E21EE9E, 0xBDB4B1C4 */
    hol__C6 = -1.13596475577881948265e-11; /* 0xBDA8FAE9, 0xBE8838D4 */

/* sin(x + y) for |x + y| <= pi/4, y the tail of x (iy 0: y is zero) */
static double hol__ksin(double x, double y, int iy)
{
    double z = x * x, w = z * z;
    double r = hol__S2 + z * (hol__S3 + z * hol__S4) + z * w * (hol__S5 + z * hol__S6);
    double v = z * x;
    if (iy == 0)
        return x + v * (hol__S1 + z * r);
    return x - ((z * (0.5 * y - v * r) - y) - v * hol__S1);
}

/* cos(x + y) for |x + y| <= pi/4 */
static double hol__kcos(double x, double y)
{
    double z = x * x, w = z * z;
    double r = z * (hol__C1 + z * (hol__C2 + z * hol__C3)) +
               w * w * (hol__C4 + z * (hol__C5 + z * hol__C6));
    double hz = 0.5 * z;
    w = 1.0 - hz;
    return w + (((1.0 - w) - hz) + (z * r - x * y));
}

static const double
    hol__invpio2 = 6.36619772367581382433e-01, /* 0x3FE45F30, 0x6DC9C883 */
    hol__pio2_1 = 1.57079632673412561417e+00,  /* 0x3FF921FB, 0x54400000 */
    hol__pio2_1t = 6.07710050650619224932e-11, /* 0x3DD0B461, 0x1A626331 */
    hol__pio2_2 = 6.07710050630396597660e-11,  /* 0x3DD0B461, 0x1A600000 */
    hol__pio2_2t = 2.02226624879595063154e-21, /* 0x3BA3198A, 0x2E037073 */
    hol__pio2_3 = 2.02226624871116645580e-21,  /* 0x3BA3198A, 0x2E000000 */
    hol__pio2_3t = 8.47842766036889956997e-32; /* 0x397B839A, 0x252049C1 */

/* x = n pi/2 + y[0] + y[1] with |y[0] + y[1]| <= pi/4 (about), for
 * |x| < 2^28: Cody and Waite's reduction with pi/2 in three 33-bit parts,
 * a second and third part only where cancellation needs them (exact to
 * 151 bits for |x| < 2^20 pi/2). Returns n. */
static int hol__rem_pio2(double x, double y[2])
{
    const double toint = 1.5 / 2.220446049250313080847e-16; /* 1.5 / DBL_EPSILON */
    double fn = x * hol__invpio2 + toint - toint; /* round to nearest */
    int n = (int)fn;
    double r = x - fn * hol__pio2_1;
    double w = fn * hol__pio2_1t; /* 1st round, good to 85 bits */
    y[0] = r - w;
    int ex = (int)(hol__hi(x) >> 20 & 0x7ff);
    int ey = (int)(hol__hi(y[0]) >> 20 & 0x7ff);
    if (ex - ey > 16) { /* 2nd round, good to 118 bits */
        double t = r;
        w = fn * hol__pio2_2;
        r = t - w;
        w = fn * hol__pio2_2t - ((t - r) - w);
        y[0] = r - w;
        ey = (int)(hol__hi(y[0]) >> 20 & 0x7ff);
        if (ex - ey > 49) { /* 3rd round, good to 151 bits */
            t = r;
            w = fn * hol__pio2_3;
            r = t - w;
            w = fn * hol__pio2_3t - ((t - r) - w);
            y[0] = r - w;
        }
    }
    y[1] = (r - y[0]) - w;
    return n;
}

double hol_sin(double x)
{
    uint32_t ix = hol__hi(x) & 0x7fffffff;
    if (ix <= 0x3fe921fb) {     /* |x| ~<= pi/4 */
        if (ix < 0x3e500000)    /* |x| < 2^-26 */
            return x;
        return hol__ksin(x, 0.0, 0);
    }
    if (ix >= 0x41b00000)       /* |x| >= 2^28, inf or NaN */
        return hol__isnan(x) ? x : hol__nan();
    double y[2];
    int n = hol__rem_pio2(x, y);
    switch (n & 3) {
    case 0: return hol__ksin(y[0], y[1], 1);
    case 1: return hol__kcos(y[0], y[1]);
    case 2: return -hol__ksin(y[0], y[1], 1);
    default: return -hol__kcos(y[0], y[1]);
    }
}

double hol_cos(double x)
{
    uint32_t ix = hol__hi(x) & 0x7fffffff;
    if (ix <= 0x3fe921fb) {     /* |x| ~<= pi/4 */
        if (ix < 0x3e46a09e)    /* |x| < 2^-27 sqrt(2) */
            return 1.0;
        return hol__kcos(x, 0.0);
    }
    if (ix >= 0x41b00000)
        return hol__isnan(x) ? x : hol__nan();
    double y[2];
    int n = hol__rem_pio2(x, y);
    switch (n & 3) {
    case 0: return hol__kcos(y[0], y[1]);
    case 1: return -hol__ksin(y[0], y[1], 1);
    case 2: return -hol__kcos(y[0], y[1]);
    default: return hol__ksin(y[0], y[1], 1);
    }
}

/* ---- atan, atan2 ----------------------------------------------------------- */

static const double hol__atanhi[] = {
    4.63647609000806093515e-01, /* atan(0.5)hi 0x3FDDAC67, 0x0561BB4F */
    7.85398163397448278999e-01, /* atan(1.0)hi 0x3FE921FB, 0x54442D18 */
    9.82793723247329054082e-01, /* atan(1.5)hi 0x3FEF730B, 0xD281F69B */
    1.57079632679489655800e+00, /* atan(inf)hi 0x3FF921FB, 0x54442D18 */
};

static const double hol__atanlo[] = {
    2.26987774529616870924e-17, /* atan(0.5)lo 0x3C7A2B7F, 0x222F65E2 */
    3.06161699786838301793e-17, /* atan(1.0)lo 0x3C81A626, 0x33145C07 */
    1.39033110312309984516e-17, /* atan(1.5)lo 0x3C700788, 0x7AF0CBBD */
    6.12323399573676603587e-17, /* atan(inf)lo 0x3C91A626, 0x33145C07 */
};

static const double hol__aT[] = {
    3.33333333333329318027e-01,  /* 0x3FD55555, 0x5555550D */
    -1.99999999998764832476e-01, /* 0xBFC99999, 0x9998EBC4 */
    1.42857142725034663711e-01,  /* 0x3FC24924, 0x920083FF */
    -1.11111104054623557880e-01, /* 0xBFBC71C6, 0xFE231671 */
    9.09088713343650656196e-02,  /* 0x3FB745CD, 0xC54C206E */
    -7.69187620504482999495e-02, /* 0xBFB3B0F2, 0xAF749A6D */
    6.66107313738753120669e-02,  /* 0x3FB10D66, 0xA0D03D51 */
    -5.83357013379057348645e-02, /* 0xBFADDE2D, 0x52DEFD9A */
    4.97687799461593236017e-02,  /* 0x3FA97B4B, 0x24760DEB */
    -3.65315727442169155270e-02, /* 0xBFA2B444, 0x2C6A6C2F */
    1.62858201153657823623e-02,  /* 0x3F90AD3A, 0xE322DA11 */
};

double hol_atan(double x)
{
    uint32_t ix = hol__hi(x);
    int sign = (int)(ix >> 31), id;
    ix &= 0x7fffffff;
    if (ix >= 0x44100000) { /* |x| >= 2^66, inf or NaN */
        if (hol__isnan(x))
            return x;
        return sign ? -hol__atanhi[3] : hol__atanhi[3];
    }
    if (ix < 0x3fdc0000) {  /* |x| < 0.4375 */
        if (ix < 0x3e400000) /* |x| < 2^-27 */
            return x;
        id = -1;
    } else {
        x = hol__fabs(x);
        if (ix < 0x3ff30000) {        /* |x| < 1.1875 */
            if (ix < 0x3fe60000) {    /* 7/16 <= |x| < 11/16 */
                id = 0;
                x = (2.0 * x - 1.0) / (2.0 + x);
            } else {                  /* 11/16 <= |x| < 19/16 */
                id = 1;
                x = (x - 1.0) / (x + 1.0);
            }
        } else if (ix < 0x40038000) { /* |x| < 2.4375 */
            id = 2;
            x = (x - 1.5) / (1.0 + 1.5 * x);
        } else {                      /* 2.4375 <= |x| < 2^66 */
            id = 3;
            x = -1.0 / x;
        }
    }
    double z = x * x, w = z * z;
    const double *a = hol__aT;
    double s1 = z * (a[0] + w * (a[2] + w * (a[4] + w * (a[6] + w * (a[8] + w * a[10])))));
    double s2 = w * (a[1] + w * (a[3] + w * (a[5] + w * (a[7] + w * a[9]))));
    if (id < 0)
        return x - x * (s1 + s2);
    z = hol__atanhi[id] - ((x * (s1 + s2) - hol__atanlo[id]) - x);
    return sign ? -z : z;
}

static const double hol__pi = 3.1415926535897931160e+00, /* 0x400921FB, 0x54442D18 */
    hol__pi_lo = 1.2246467991473531772e-16;                /* 0x3CA1A626, 0x33145C07 */

double hol_atan2(double y, double x)
{
    if (hol__isnan(x) || hol__isnan(y))
        return x + y;
    uint64_t bx = hol__bits(x), by = hol__bits(y);
    if (bx == 0x3ff0000000000000ull) /* x = 1 */
        return hol_atan(y);
    int m = (int)(by >> 63) | (int)(bx >> 62 & 2); /* 2 sign(x) + sign(y) */
    uint32_t ix = (uint32_t)(bx >> 32) & 0x7fffffff, iy = (uint32_t)(by >> 32) & 0x7fffffff;
    if ((by << 1) == 0) /* y = +-0 */
        return m == 2 ? hol__pi : m == 3 ? -hol__pi : y;
    if ((bx << 1) == 0) /* x = +-0 */
        return m & 1 ? -hol__pi / 2 : hol__pi / 2;
    if (ix == 0x7ff00000) { /* x infinite */
        if (iy == 0x7ff00000) /* both infinite: +-pi/4, +-3 pi/4 */
            return (m & 1 ? -1 : 1) * (m & 2 ? 3 * hol__pi / 4 : hol__pi / 4);
        return m == 0 ? 0.0 : m == 1 ? -0.0 : m == 2 ? hol__pi : -hol__pi;
    }
    if (ix + (64u << 20) < iy || iy == 0x7ff00000) /* |y/x| > 2^64 */
        return m & 1 ? -hol__pi / 2 : hol__pi / 2;
    double z;
    if ((m & 2) && iy + (64u << 20) < ix) /* |y/x| < 2^-64, x < 0 */
        z = 0;
    else
        z = hol_atan(hol__fabs(y / x));
    switch (m) {
    case 0: return z;
    case 1: return -z;
    case 2: return hol__pi - (z - hol__pi_lo);
    default: return (z - hol__pi_lo) - hol__pi;
    }
}

/* ---- asin ----------------------------------------------------------------- */

static const double
    hol__pio2_hi = 1.57079632679489655800e+00, /* 0x3FF921FB, 0x54442D18 */
    hol__pio2_lo = 6.12323399573676603587e-17, /* 0x3C91A626, 0x33145C07 */
    hol__pS0 = 1.66666666666666657415e-01,     /* 0x3FC55555, 0x55555555 */
    hol__pS1 = -3.25565818622400915405e-01,    /* 0xBFD4D612, 0x03EB6F7D */
    hol__pS2 = 2.01212532134862925881e-01,     /* 0x3FC9C155, 0x0E884455 */
    hol__pS3 = -4.00555345006794114027e-02,    /* 0xBFA48228, 0xB5688F3B */
    hol__pS4 = 7.91534994289814532176e-04,     /* 0x3F49EFE0, 0x7501B288 */
    hol__pS5 = 3.47933107596021167570e-05,     /* 0x3F023DE1, 0x0DFDF709 */
    hol__qS1 = -2.40339491173441421878e+00,    /* 0xC0033A27, 0x1C8A2D4B */
    hol__qS2 = 2.02094576023350569471e+00,     /* 0x40002AE5, 0x9C598AC8 */
    hol__qS3 = -6.88283971605453293030e-01,    /* 0xBFE6066C, 0x1B8D0159 */
    hol__qS4 = 7.70381505559019352791e-02;     /* 0x3FB3B8C5, 0xB12E9282 */

static double hol__asin_r(double z)
{
    double p = z * (hol__pS0 +
                    z * (hol__pS1 + z * (hol__pS2 + z * (hol__pS3 + z * (hol__pS4 + z * hol__pS5)))));
    double q = 1.0 + z * (hol__qS1 + z * (hol__qS2 + z * (hol__qS3 + z * hol__qS4)));
    return p / q;
}

double hol_asin(double x)
{
    uint32_t hx = hol__hi(x), ix = hx & 0x7fffffff;
    if (ix >= 0x3ff00000) { /* |x| >= 1 or NaN */
        if ((hol__bits(x) & 0x7fffffffffffffffull) == 0x3ff0000000000000ull)
            return x * hol__pio2_hi; /* +-pi/2 */
        return hol__isnan(x) ? x : hol__nan();
    }
    if (ix < 0x3fe00000) { /* |x| < 0.5 */
        if (ix < 0x3e500000) /* |x| < 2^-26 */
            return x;
        return x + x * hol__asin_r(x * x);
    }
    double z = (1 - hol__fabs(x)) * 0.5, s = sqrt(z), r = hol__asin_r(z);
    if (ix >= 0x3fef3333) { /* |x| > 0.975 */
        x = hol__pio2_hi - (2 * (s + s * r) - hol__pio2_lo);
    } else {
        double f = hol__from_bits(hol__bits(s) & 0xffffffff00000000ull); /* f + c = sqrt(z) */
        double c = (z - f * f) / (s + f);
        x = 0.5 * hol__pio2_hi - (2 * s * r - (hol__pio2_lo - 2 * c) - (0.5 * hol__pio2_hi - 2 * f));
    }
    return hx >> 31 ? -x : x;
}

/* ---- log, log1p, acosh ------------------------------------------------------- */

static const double
    hol__ln2_hi = 6.93147180369123816490e-01, /* 0x3FE62E42, 0xFEE00000 */
    hol__ln2_lo = 1.90821492927058770002e-10, /* 0x3DEA39EF, 0x35793C76 */
    hol__Lg1 = 6.666666666666735130e-01,      /* 0x3FE55555, 0x55555593 */
    hol__Lg2 = 3.999999999940941908e-01,      /* 0x3FD99999, 0x9997FA04 */
    hol__Lg3 = 2.857142874366239149e-01,      /* 0x3FD24924, 0x94229359 */
    hol__Lg4 = 2.222219843214978396e-01,      /* 0x3FCC71C5, 0x1D8E78AF */
    hol__Lg5 = 1.818357216161805012e-01,      /* 0x3FC74664, 0x96CB03DE */
    hol__Lg6 = 1.531383769920937332e-01,      /* 0x3FC39A09, 0xD078C69F */
    hol__Lg7 = 1.479819860511658591e-01;      /* 0x3FC2F112, 0xDF3E5244 */

/* log(1 + f) + k ln 2 + c for f in [sqrt(2)/2 - 1, sqrt(2) - 1] */
static double hol__klog(double f, int k, double c)
{
    double hfsq = 0.5 * f * f, s = f / (2.0 + f), z = s * s, w = z * z;
    double t1 = w * (hol__Lg2 + w * (hol__Lg4 + w * hol__Lg6));
    double t2 = z * (hol__Lg1 + w * (hol__Lg3 + w * (hol__Lg5 + w * hol__Lg7)));
    double r = t2 + t1, dk = k;
    return s * (hfsq + r) + (dk * hol__ln2_lo + c) - hfsq + f + dk * hol__ln2_hi;
}

double hol_log(double x)
{
    uint64_t u = hol__bits(x);
    uint32_t hx = (uint32_t)(u >> 32);
    int k = 0;
    if (hx < 0x00100000 || hx >> 31) {
        if (u << 1 == 0)
            return -hol__from_bits(0x7ff0000000000000ull); /* log(+-0) = -inf */
        if (hx >> 31)
            return hol__isnan(x) ? x : hol__nan(); /* log(-x) = NaN */
        k -= 54; /* subnormal: scale up */
        x *= 18014398509481984.0; /* 2^54 */
        u = hol__bits(x);
        hx = (uint32_t)(u >> 32);
    } else if (hx >= 0x7ff00000) {
        return x;
    } else if (hx == 0x3ff00000 && u << 32 == 0) {
        return 0;
    }
    /* reduce x into [sqrt(2)/2, sqrt(2)] */
    hx += 0x3ff00000 - 0x3fe6a09e;
    k += (int)(hx >> 20) - 0x3ff;
    hx = (hx & 0x000fffff) + 0x3fe6a09e;
    x = hol__from_bits((uint64_t)hx << 32 | (u & 0xffffffff));
    return hol__klog(x - 1.0, k, 0.0);
}

double hol_log1p(double x)
{
    uint32_t hx = hol__hi(x);
    int k = 1;
    double f = 0, c = 0;
    if (hx < 0x3fda827a || hx >> 31) { /* 1 + x < sqrt(2)+ */
        if (hx >= 0xbff00000) {        /* x <= -1 or -NaN */
            if (x == -1)
                return -hol__from_bits(0x7ff0000000000000ull);
            return hol__isnan(x) ? x : hol__nan();
        }
        if (hx << 1 < 0x3ca00000u << 1) /* |x| < 2^-53 */
            return x;
        if (hx <= 0xbfd2bec4) {         /* sqrt(2)/2- <= 1 + x < sqrt(2)+ */
            k = 0;
            f = x;
        }
    } else if (hx >= 0x7ff00000) {
        return x;
    }
    if (k) {
        double uf = 1 + x;
        uint64_t u = hol__bits(uf);
        uint32_t hu = (uint32_t)(u >> 32) + (0x3ff00000 - 0x3fe6a09e);
        k = (int)(hu >> 20) - 0x3ff;
        if (k < 54) { /* correction: log(1 + x) - log(uf) */
            c = k >= 2 ? 1 - (uf - x) : x - (uf - 1);
            c /= uf;
        }
        hu = (hu & 0x000fffff) + 0x3fe6a09e;
        f = hol__from_bits((uint64_t)hu << 32 | (u & 0xffffffff)) - 1;
    }
    return hol__klog(f, k, c);
}

double hol_acosh(double x)
{
    unsigned e = (unsigned)(hol__bits(x) >> 52 & 0x7ff);
    if (e < 0x3ff + 1) /* |x| < 2 (below 1: NaN from the square root or log1p) */
        return hol_log1p(x - 1 + sqrt((x - 1) * (x - 1) + 2 * (x - 1)));
    if (e < 0x3ff + 26) /* |x| < 2^26 */
        return hol_log(2 * x - 1 / (x + sqrt(x * x - 1)));
    if (hol__bits(x) >> 63) /* x <= -2^26 */
        return hol__nan();
    return hol_log(x) + 0.693147180559945309417232121458176568; /* big, inf or NaN */
}

double hol_asinh(double x)
{
    double a = x < 0 ? -x : x;
    if (a > 1e150) /* x^2 would overflow: asinh(a) = log(2a) to double precision */
        return (x < 0 ? -1 : 1) * (hol_log(a) + 0.693147180559945309417232121458176568);
    double r = hol_log1p(a + a * a / (1 + sqrt(1 + a * a)));
    return x < 0 ? -r : r;
}
