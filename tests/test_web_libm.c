/* test_web_libm.c - the web build's libm (render/hol_libm_web.h, core/hol_math_exp.h):
 * its exp family within 4 ulp of the C library's over the ranges the
 * renderer uses and beyond, special values, and the macros the web build
 * force-includes into render/ and platform/ giving the functions they
 * replace to within a few ulp.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include "../render/hol_libm_web.h"

/* |a - b| in units of b's last place */
static double ulps(double a, double b)
{
    if (a == b)
        return 0;
    return fabs(a - b) / fabs(nextafter(b, INFINITY) - b);
}

/* a fixed sequence of arguments: x in [-r, r] (a 64-bit LCG) */
static double arg(uint64_t *s, double r)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(*s >> 11) / 9007199254740992.0 * 2 - 1) * r;
}

static void test_exp_family(void **state)
{
    (void)state;
    static const double ranges[] = {1e-9, 1e-3, 0.35, 1, 5, 30, 700};
    uint64_t s = 1;
    double worst[5] = {0};
    for (size_t k = 0; k < sizeof ranges / sizeof ranges[0]; k++)
        for (int i = 0; i < 20000; i++) {
            double x = arg(&s, ranges[k]);
            double e[5] = {ulps(hol_exp(x), exp(x)), ulps(hol_expm1(x), expm1(x)),
                           ulps(hol_sinh(x), sinh(x)), ulps(hol_cosh(x), cosh(x)),
                           ulps(hol_tanh(x), tanh(x))};
            for (int j = 0; j < 5; j++)
                worst[j] = e[j] > worst[j] ? e[j] : worst[j];
        }
    for (int j = 0; j < 5; j++) {
        print_message("hol_web exp family %d: worst %.2f ulp\n", j, worst[j]);
        assert_true(worst[j] <= 4);
    }
}

static void test_special(void **state)
{
    (void)state;
    assert_true(isnan(hol_exp(NAN)) && isnan(hol_sinh(NAN)) && isnan(hol_cosh(NAN)) &&
                isnan(hol_tanh(NAN)) && isnan(hol_expm1(NAN)));
    assert_true(hol_exp(800) == INFINITY && hol_exp(-800) == 0);
    assert_true(hol_exp(0) == 1 && hol_expm1(0) == 0 && hol_cosh(0) == 1);
    assert_true(signbit(hol_tanh(-0.0)) && hol_tanh(-50) == -1 && hol_tanh(50) == 1);
    assert_true(signbit(hol_sinh(-0.0)) && hol_sinh(-1) == -hol_sinh(1));
}

/* what render/ and platform/ call, through the macros */
#define HOL_WEB_LIBM_MACROS
#undef HOL_LIBM_WEB_H
#include "../render/hol_libm_web.h"
static double lib_sin(double x) { return (sin)(x); }
static double lib_tan(double x) { return (tan)(x); }
static double lib_atan2(double y, double x) { return (atan2)(y, x); }
static float lib_powf(float x, float y) { return (powf)(x, y); }

static void test_macros(void **state)
{
    (void)state;
    uint64_t s = 7;
    for (int i = 0; i < 20000; i++) {
        double x = arg(&s, 10), y = arg(&s, 10);
        assert_true(ulps(sin(x), lib_sin(x)) <= 1);
        assert_true(ulps(tan(x), lib_tan(x)) <= 4 || fabs(tan(x)) > 1e6);
        assert_true(ulps(atan2(y, x), lib_atan2(y, x)) <= 1);
        assert_true(fabsf(sinf((float)x) - (float)lib_sin(x)) <= 1e-6f);
        float c = (float)fabs(arg(&s, 1));
        assert_true(fabsf(powf(c, 2.4f) - lib_powf(c, 2.4f)) <= 2 * (nextafterf(lib_powf(c, 2.4f), 2) - lib_powf(c, 2.4f)));
        assert_true(ulps(hypot(x, y), sqrt(x * x + y * y)) == 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exp_family),
        cmocka_unit_test(test_special),
        cmocka_unit_test(test_macros),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
