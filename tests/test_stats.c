/* test_stats.c - core/hol_stats.h: mean, SD and the 95 % t interval against
 * values computed by hand (and Python's statistics module); Welford's
 * running update against a brute-force two-pass computation on random
 * data; t(0.975, df) against published quantiles on both sides of the
 * table's end; SSQ scores with Kennedy et al.'s weights.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_stats.h"

static void near(double got, double want, double tol)
{
    if (fabs(got - want) > tol)
        fail_msg("got %.10f, want %.10f (tol %g)", got, want, tol);
}

static hol_stats_summary of(const double *x, int n)
{
    hol_stats s;
    hol_stats_summary m;
    hol_stats_init(&s);
    for (int i = 0; i < n; i++)
        hol_stats_add(&s, x[i]);
    hol_stats_summarize(&s, &m);
    return m;
}

static void test_by_hand(void **state)
{
    (void)state;
    /* mean 5; squared deviations 9+1+1+1+0+0+4+16 = 32, sd = sqrt(32/7);
     * half-width t(.975,7) * sd / sqrt(8) = 2.364624252 * 2.13809 / 2.82843 */
    const double x[] = {2, 4, 4, 4, 5, 5, 7, 9};
    hol_stats_summary m = of(x, 8);
    assert_int_equal(m.n, 8);
    assert_true(m.has_mean && m.has_sd);
    near(m.mean, 5, 1e-12);
    near(m.sd, 2.138089935299395, 1e-12);
    near(m.lo, 3.212512081455964, 1e-8);
    near(m.hi, 6.787487918544036, 1e-8);
    /* two values: df 1, t = 12.706 */
    const double y[] = {1.0, 0.5};
    m = of(y, 2);
    near(m.mean, 0.75, 1e-12);
    near(m.sd, 0.3535533905932738, 1e-12);
    near(m.lo, -2.426551184, 1e-8);
    near(m.hi, 3.926551184, 1e-8);
}

static void test_small_n(void **state)
{
    (void)state;
    hol_stats_summary m = of(NULL, 0);
    assert_int_equal(m.n, 0);
    assert_false(m.has_mean);
    assert_false(m.has_sd);
    const double one[] = {3.5};
    m = of(one, 1);
    assert_int_equal(m.n, 1);
    assert_true(m.has_mean);
    assert_false(m.has_sd);
    near(m.mean, 3.5, 0);
    const double same[] = {7, 7, 7};
    m = of(same, 3);
    near(m.sd, 0, 0);
    near(m.lo, 7, 0);
    near(m.hi, 7, 0);
}

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* Welford against two passes, on sets of 2..400 values around large offsets. */
static void test_brute_force(void **state)
{
    (void)state;
    static double x[400];
    for (int trial = 0; trial < 500; trial++) {
        int n = 2 + (int)(uniform() * 399);
        double off = trial % 2 ? 1e4 : 0, scale = 1 + uniform() * 100;
        double sum = 0, ss = 0;
        for (int i = 0; i < n; i++)
            sum += x[i] = off + scale * uniform();
        double mean = sum / n;
        for (int i = 0; i < n; i++)
            ss += (x[i] - mean) * (x[i] - mean);
        double sd = sqrt(ss / (n - 1)), h = hol_stats_t975(n - 1) * sd / sqrt((double)n);
        hol_stats_summary m = of(x, n);
        assert_int_equal(m.n, n);
        near(m.mean, mean, 1e-9 * (off + scale));
        near(m.sd, sd, 1e-9 * scale);
        near(m.lo, mean - h, 1e-8 * (off + scale));
        near(m.hi, mean + h, 1e-8 * (off + scale));
    }
}

static void test_t975(void **state)
{
    (void)state;
    near(hol_stats_t975(1), 12.706204736, 1e-9);
    near(hol_stats_t975(5), 2.570581836, 1e-9);
    near(hol_stats_t975(30), 2.042272456, 1e-9);
    /* beyond the table (published quantiles) */
    near(hol_stats_t975(31), 2.039513446, 1e-6);
    near(hol_stats_t975(40), 2.021075390, 1e-6);
    near(hol_stats_t975(60), 2.000297822, 1e-6);
    near(hol_stats_t975(120), 1.979930405, 1e-6);
    near(hol_stats_t975(100000), 1.959986, 1e-5);
    /* the expansion continues the table */
    near(hol_stats_t975(31), hol_stats_t975(30), 0.003);
    for (long df = 1; df < 5000; df++)
        assert_true(hol_stats_t975(df + 1) < hol_stats_t975(df));
    assert_true(hol_stats_t975(0) == 0);
}

static void test_ssq(void **state)
{
    (void)state;
    double v[HOL_STATS_SSQ_NITEMS];
    hol_stats_ssq_score s;
    for (int i = 0; i < HOL_STATS_SSQ_NITEMS; i++)
        v[i] = 1;
    hol_stats_ssq(v, &s); /* 7 items in each subscale */
    near(s.nausea, 7 * 9.54, 1e-9);
    near(s.oculomotor, 7 * 7.58, 1e-9);
    near(s.disorientation, 7 * 13.92, 1e-9);
    near(s.total, 21 * 3.74, 1e-9);
    memset(v, 0, sizeof v);
    v[hol_stats_ssq_index("nausea")] = 3; /* N and D */
    v[hol_stats_ssq_index("difficulty_focusing")] = 2; /* O and D */
    v[hol_stats_ssq_index("burping")] = 1; /* N */
    hol_stats_ssq(v, &s);
    near(s.nausea, 4 * 9.54, 1e-9);
    near(s.oculomotor, 2 * 7.58, 1e-9);
    near(s.disorientation, 5 * 13.92, 1e-9);
    near(s.total, 11 * 3.74, 1e-9);
    /* the maximum (3 on every item): the published 235.62, 200.34, 159.18, 292.32 */
    for (int i = 0; i < HOL_STATS_SSQ_NITEMS; i++)
        v[i] = 3;
    hol_stats_ssq(v, &s);
    near(s.total, 235.62, 1e-9);
    near(s.nausea, 200.34, 1e-9);
    near(s.oculomotor, 159.18, 1e-9);
    near(s.disorientation, 292.32, 1e-9);
    assert_int_equal(hol_stats_ssq_index("general_discomfort"), 0);
    assert_int_equal(hol_stats_ssq_index("burping"), 15);
    assert_int_equal(hol_stats_ssq_index("mental"), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_by_hand),  cmocka_unit_test(test_small_n),
        cmocka_unit_test(test_brute_force), cmocka_unit_test(test_t975),
        cmocka_unit_test(test_ssq),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
