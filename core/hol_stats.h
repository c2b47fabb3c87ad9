/* hol_stats.h - descriptive statistics for `holonomy report`: mean, sample
 * standard deviation and a 95 % confidence interval of the mean from
 * Student's t distribution; SSQ scoring (Kennedy et al. 1993).
 *
 * Contract
 * - hol_stats accumulates values one at a time (Welford's update: stable
 *   for times of hours and efficiencies near 1 alike), O(1) per value.
 * - hol_stats_summary: n; mean when n >= 1; sd (n - 1 in the denominator)
 *   and the interval mean -/+ t(0.975, n - 1) * sd / sqrt(n) when n >= 2.
 *   What is not defined is flagged (has_mean, has_sd), never NaN.
 * - hol_stats_t975(df): the 0.975 quantile of Student's t with df degrees
 *   of freedom (df >= 1): a table for df <= 30 (to 1e-9), beyond it the
 *   Cornish-Fisher expansion in 1/df to the fourth order (error below
 *   1e-6 for df > 30); only + - * / (core purity: no libm transcendental).
 * - hol_stats_ssq: the 16 items of the Simulator Sickness Questionnaire
 *   (0..3 each, in the order of hol_ask.h's preset ssq) into the raw subscale sums and
 *   the weighted scores: nausea x 9.54, oculomotor x 7.58, disorientation x
 *   13.92, total = (N + O + D raw sums) x 3.74.
 * - Pure: no I/O, no allocation, no globals written.
 */
#ifndef HOL_STATS_H
#define HOL_STATS_H

typedef struct hol_stats {
    long n;
    double mean, m2; /* running mean, sum of squared deviations */
} hol_stats;

typedef struct hol_stats_summary {
    long n;
    int has_mean, has_sd;
    double mean, sd, lo, hi; /* lo, hi: the 95 % CI of the mean */
} hol_stats_summary;

void hol_stats_init(hol_stats *s);
void hol_stats_add(hol_stats *s, double x);
void hol_stats_summarize(const hol_stats *s, hol_stats_summary *out);
double hol_stats_t975(long df);

/* The items (answers.csv `item`) are hol_ask.h's preset ssq's, in
 * Kennedy et al.'s order. */
#define HOL_STATS_SSQ_NITEMS 16

typedef struct hol_stats_ssq_score {
    double nausea, oculomotor, disorientation, total;
} hol_stats_ssq_score;

/* The index of an SSQ item ID, -1 when it is none. */
int hol_stats_ssq_index(const char *id);
/* Scores of one questionnaire (v[i]: item i's answer, 0..3). */
void hol_stats_ssq(const double v[HOL_STATS_SSQ_NITEMS], hol_stats_ssq_score *out);

#endif
