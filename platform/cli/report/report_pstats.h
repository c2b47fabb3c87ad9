/* report_pstats.h - the participant-level statistics of `holonomy report`
 * (docs/report.md "Participant-level statistics"): trials.csv (one row per
 * attempt with the reason it is left out, if it is), participants_stats.csv
 * (per condition and measure over the participants' means, the between-
 * and the within-subjects 95 % CI) and paired.csv (each pair of a study's
 * conditions: the paired difference, its CI and Cohen's d_z), and the
 * page's section of them. Internal to the command.
 *
 * Contract
 * - report_pstats_compute (after report_stats_read, which reads each
 *   attempt's pointing answers): each attempt's exclusion (practice, its
 *   end when not done, duplicate, restarted; report_pstats_excluded), its
 *   trial number within the participant, and the statistics. A
 *   participant's value in a condition is the mean over their included
 *   trials; the statistics are over participants. 0, or CLI_EXIT_FAIL out
 *   of memory (one line said).
 * - The 95 % intervals use report_t975 (Student's t quantile computed
 *   with the C library to 1e-12 relative, 1e-15 below 50 degrees of
 *   freedom, so R's qt agrees to 1e-9).
 * - report_pstats_write writes the three CSVs and effects.csv (the main
 *   effects of a study's factors, report_effects.c) atomically (numbers
 *   with 15 significant digits); report_pstats_html the page's section.
 *   O(n log n) in the attempts, plus the pairs of a study's conditions
 *   (at most REPORT_PAIR_MAX conditions a study have pairs).
 */
#ifndef REPORT_PSTATS_H
#define REPORT_PSTATS_H

#include <stdio.h>

#include "report.h"

#define REPORT_PAIR_MAX 32

int report_pstats_compute(report_run *r);
int report_pstats_write(const report_run *r);
void report_pstats_html(FILE *f, const report_run *r);
void report_pstats_free(report_run *r);
/* The reason attempt i is left out of the participant-level statistics
 * ("practice", its end, "duplicate", "restarted"), "" when it is in. */
const char *report_pstats_excluded(const report_run *r, int i);
/* The 0.975 quantile of Student's t with df >= 1 degrees of freedom. */
double report_t975(long df);

#endif
