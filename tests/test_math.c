/* test_math.c - core/hol_math.h against an independent reference: the C
 * library's long double functions (64-bit mantissa on x86-64, 113-bit on
 * arm64), rounded errors measured in ulps of the double result; special
 * values per C99 Annex F; the same bits as every other platform
 * (math_golden.h).
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_math.h"
#include "math_golden.h"

static uint64_t rng(uint64_t *s)
{
    *s += UINT64_C(0x9E3779B97F4A7C15);
    uint64_t z = *s;
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static double unit(uint64_t *s)
{
    return (double)(rng(s) >> 11) * (1.0 / 9007199254740992.0);
}

/* |got - ref| in units of the last place of the double nearest ref */
static double ulps(double got, long double ref)
{
    double r = (double)ref;
    if (isnan(got) || isnan(r))
        return isnan(got) && isnan(r) ? 0 : 1e9;
    if (isinf(r))
        return got == r ? 0 : 1e9;
    double a = fabs(r);
    double ulp = a < DBL_MIN ? DBL_TRUE_MIN : nextafter(a, INFINITY) - a;
    /* at a power of two the lower neighbour is closer: use the smaller ulp */
    double below = a - nextafter(a, 0);
    if (below > 0 && below < ulp)
        ulp = below;
    return (double)(fabsl((long double)got - ref) / ulp);
}

typedef double (*fn1)(double);
typedef long double (*ref1)(long double);

/* The largest error over n arguments lo + (hi - lo) u, u uniform (or
 * log-uniform between lo and hi when logscale). */
static double worst1(fn1 f, ref1 r, double lo, double hi, int logscale, int n, double *at)
{
    uint64_t s = 12345;
    double w = 0;
    for (int i = 0; i < n; i++) {
        double u = unit(&s);
        double x = logscale ? lo * pow(hi / lo, u) : lo + (hi - lo) * u;
        double e = ulps(f(x), r(x));
        if (e > w) {
            w = e;
            *at = x;
        }
    }
    return w;
}

static void expect_under(const char *name, double lo, double hi, double w, double at,
                         double bound)
{
    if (w >= bound)
        fprintf(stderr, "%s on [%g, %g]: %.3f ulp at %.17g (bound %.1f)\n", name, lo, hi, w, at,
                bound);
    assert_true(w < bound);
}

#define N 10000

static void check1(const char *name, fn1 f, ref1 r, double lo, double hi, int logscale,
                   double bound)
{
    double at = 0, w = worst1(f, r, lo, hi, logscale, N, &at);
    expect_under(name, lo, hi, w, at, bound);
}

static void test_sin_cos(void **state)
{
    (void)state;
    static const double ranges[][3] = {{-0.8, 0.8, 0}, {-7, 7, 0}, {-100, 100, 0},
                                       {1e-9, 1e5, 1}, {1e5, 1.6e6, 0}};
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; i++) {
        check1("hol_sin", hol_sin, sinl, ranges[i][0], ranges[i][1], (int)ranges[i][2], 1.0);
        check1("hol_cos", hol_cos, cosl, ranges[i][0], ranges[i][1], (int)ranges[i][2], 1.0);
    }
    /* near multiples of pi/2, where the reduction cancels most */
    uint64_t s = 7;
    double w = 0, at = 0;
    for (int k = -2000; k <= 2000; k++) {
        for (int j = 0; j < 4; j++) {
            double x = k * 1.5707963267948966 + (unit(&s) - 0.5) * 1e-9 * j;
            double e1 = ulps(hol_sin(x), sinl(x)), e2 = ulps(hol_cos(x), cosl(x));
            if (e1 > w || e2 > w) {
                w = e1 > e2 ? e1 : e2;
                at = x;
            }
        }
    }
    expect_under("hol_sin/hol_cos near k pi/2", -3142, 3142, w, at, 1.0);
}

static void test_atan_asin(void **state)
{
    (void)state;
    check1("hol_atan", hol_atan, atanl, -3, 3, 0, 1.0);
    check1("hol_atan", hol_atan, atanl, 1e-10, 1e20, 1, 1.0);
    check1("hol_atan", hol_atan, atanl, -100, -1e-3, 0, 1.0);
    check1("hol_asin", hol_asin, asinl, -1, 1, 0, 1.0);
    check1("hol_asin", hol_asin, asinl, 0.97, 1, 0, 1.0);
    check1("hol_asin", hol_asin, asinl, 1e-12, 0.5, 1, 1.0);
    /* atan2 over all four quadrants and magnitudes */
    uint64_t s = 99;
    double w = 0, aty = 0, atx = 0;
    for (int i = 0; i < 4 * N; i++) {
        double y = (unit(&s) - 0.5) * pow(10, 8 * unit(&s) - 4);
        double x = (unit(&s) - 0.5) * pow(10, 8 * unit(&s) - 4);
        double e = ulps(hol_atan2(y, x), atan2l(y, x));
        if (e > w) {
            w = e;
            aty = y;
            atx = x;
        }
    }
    /* the rounding of y / x adds up to half an ulp to atan's */
    if (w >= 2.0)
        fprintf(stderr, "hol_atan2: %.3f ulp at (%.17g, %.17g)\n", w, aty, atx);
    assert_true(w < 2.0);
}

static void test_log_acosh(void **state)
{
    (void)state;
    check1("hol_log", hol_log, logl, 1e-300, 1e300, 1, 1.0);
    check1("hol_log", hol_log, logl, 0.5, 2, 0, 1.0);
    check1("hol_log", hol_log, logl, 4.9e-324, 2e-308, 1, 1.0); /* subnormal */
    check1("hol_log1p", hol_log1p, log1pl, -0.999, 3, 0, 1.0);
    check1("hol_log1p", hol_log1p, log1pl, 1e-20, 1e300, 1, 1.0);
    check1("hol_acosh", hol_acosh, acoshl, 1, 2, 0, 2.0);
    check1("hol_acosh", hol_acosh, acoshl, 1, 1e300, 1, 2.0);
    check1("hol_acosh", hol_acosh, acoshl, 2, 100, 0, 2.0);
    check1("hol_asinh", hol_asinh, asinhl, 1e-20, 1e300, 1, 2.0);
    check1("hol_asinh", hol_asinh, asinhl, 0, 3, 0, 2.0);
    check1("hol_asinh", hol_asinh, asinhl, -3, 0, 0, 2.0);
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

static void test_special_values(void **state)
{
    (void)state;
    double inf = INFINITY, nan_ = NAN;
    assert_true(same_bits(hol_sin(0.0), 0.0) && same_bits(hol_sin(-0.0), -0.0));
    assert_true(hol_cos(0.0) == 1.0 && hol_cos(-0.0) == 1.0);
    assert_true(isnan(hol_sin(inf)) && isnan(hol_cos(-inf)) && isnan(hol_sin(nan_)));
    assert_true(isnan(hol_sin(1e9)) && isnan(hol_cos(-3e8))); /* beyond 2^28: documented */
    assert_true(!isnan(hol_sin(2.6e8)));
    assert_true(same_bits(hol_atan(-0.0), -0.0) && hol_atan(inf) == (double)atanl(INFINITY));
    assert_true(isnan(hol_atan(nan_)));
    /* atan2's signed zeros and infinities (C99 F.9.1.4) */
    const double pi = 3.14159265358979323846;
    assert_true(same_bits(hol_atan2(0.0, 1.0), 0.0) && same_bits(hol_atan2(-0.0, 1.0), -0.0));
    assert_true(hol_atan2(0.0, -1.0) == pi && hol_atan2(-0.0, -1.0) == -pi);
    assert_true(hol_atan2(0.0, -0.0) == pi && hol_atan2(-0.0, -0.0) == -pi);
    assert_true(same_bits(hol_atan2(0.0, 0.0), 0.0) && same_bits(hol_atan2(-0.0, 0.0), -0.0));
    assert_true(hol_atan2(1.0, 0.0) == pi / 2 && hol_atan2(-1.0, -0.0) == -pi / 2);
    assert_true(hol_atan2(inf, inf) == pi / 4 && hol_atan2(-inf, -inf) == -3 * pi / 4);
    assert_true(hol_atan2(1.0, -inf) == pi && same_bits(hol_atan2(-1.0, inf), -0.0));
    assert_true(hol_atan2(inf, 5.0) == pi / 2 && isnan(hol_atan2(nan_, 1.0)));
    assert_true(hol_asin(1.0) == pi / 2 && hol_asin(-1.0) == -pi / 2);
    assert_true(isnan(hol_asin(1.0000000000000002)) && isnan(hol_asin(-2)));
    assert_true(same_bits(hol_asin(-0.0), -0.0));
    assert_true(hol_log(1.0) == 0 && hol_log(0.0) == -inf && hol_log(-0.0) == -inf);
    assert_true(isnan(hol_log(-1.0)) && hol_log(inf) == inf && isnan(hol_log(nan_)));
    assert_true(hol_log1p(-1.0) == -inf && isnan(hol_log1p(-1.5)) && hol_log1p(inf) == inf);
    assert_true(same_bits(hol_log1p(-0.0), -0.0) && hol_log1p(1e-300) == 1e-300);
    assert_true(hol_acosh(1.0) == 0 && hol_acosh(inf) == inf);
    assert_true(isnan(hol_acosh(0.5)) && isnan(hol_acosh(-3)) && isnan(hol_acosh(-1e30)));
}

/* The same bits everywhere: the hash of math_golden.h. */
static void test_golden_bits(void **state)
{
    (void)state;
    uint64_t h = math_golden_hash();
    if (h != MATH_GOLDEN_HASH)
        fprintf(stderr, "math golden hash %016llx, expected %016llx\n", (unsigned long long)h,
                (unsigned long long)MATH_GOLDEN_HASH);
    assert_true(h == MATH_GOLDEN_HASH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sin_cos),
        cmocka_unit_test(test_atan_asin),
        cmocka_unit_test(test_log_acosh),
        cmocka_unit_test(test_special_values),
        cmocka_unit_test(test_golden_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
