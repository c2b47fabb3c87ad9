/* report_pstats_impl.h - report_pstats.c's tables, shared with
 * report_pstats_write.c (the CSVs and the page). Internal. */
#ifndef REPORT_PSTATS_IMPL_H
#define REPORT_PSTATS_IMPL_H

#include <stddef.h>
#include <stdio.h>

#include "report_pstats.h"
#include "report_stats_impl.h"

/* The measures of a trial (the first five of stats.csv's). */
enum { PM_STEPS, PM_EFF, PM_TIME, PM_ERR_TRUE, PM_ERR_FLAT, PS_NM };
extern const char *const ps_measure[PS_NM];

/* Why an attempt is left out (PX_END: its end, not done). */
enum { PX_IN, PX_PRACTICE, PX_END, PX_DUPLICATE, PX_RESTARTED };

typedef struct ps_key { /* an attempt as the sorts see it */
    const char *study, *participant;
    int i, cond, group;
} ps_key;

typedef struct ps_cell { /* one participant in one condition */
    const char *participant;
    int cond, group;
    long n[PS_NM];   /* included trials with a value */
    double sum[PS_NM], mean[PS_NM];
} ps_cell;

typedef struct ps_row { /* one condition and measure */
    hol_stats between; /* over the participants' means */
    hol_stats within;  /* the normalised means of the complete participants */
    long trials;
    int J;             /* the study's conditions with this measure */
} ps_row;

typedef struct ps_pairs { /* the pairs of one study's conditions */
    int group, first, n;
    size_t off; /* in pair: n x n x PS_NM, [a][b][m] for a < b */
} ps_pairs;

typedef struct report_pstats {
    int *excl;   /* per attempt: PX_* */
    int *run;    /* per attempt: PX_DUPLICATE, PX_RESTARTED or PX_IN (its run's,
                    whatever the attempt's own end: its questionnaires') */
    int *trial;  /* per attempt: its number within the study's participant */
    int *group;  /* per condition: its study's first condition; -1 none */
    int *first;  /* per condition: its first included attempt, -1 none */
    ps_row *row; /* ncond x PS_NM */
    ps_cell *cell;
    int ncell;
    ps_pairs *pg;
    int npg;
    hol_stats *pair;
    size_t npair;
} report_pstats;

int ps_value(const report_run *r, int i, int m, double *v);
/* 1 when attempt i counts in the statistics: not excluded, or excluded as
 * duplicate or restarted under --include-restarted. */
int ps_counts(const report_run *r, const report_pstats *p, int i);
/* The end of the participant's cells from cell i (one group's), and the
 * number and sum of their values of measure m. */
int ps_part_end(const report_pstats *p, int i, int m, int *have, double *sum);
/* The study's conditions (a group) of measure m that have values: J. */
int ps_group_conds(const report_pstats *p, int g, int m, int ncond);
/* mean[,sd],ci_low,ci_high of st (with_sd: the sd too; the t interval's
 * half widened by k), each followed by ',' (the last by '\n' when last);
 * what is not defined empty. */
void ps_summary(FILE *f, const hol_stats *st, double k, int with_sd, int last);
/* d_z: the mean difference over the SD of the differences: 1 and *out,
 * 0 when it is not defined (n under 2, no spread: an SD of 0 or under
 * 1e-9 of the mean's magnitude, equal differences but for rounding). */
int ps_dz(const hol_stats *d, double *out);
/* A difference's last cells: n, its summary (ps_summary, with SD), d_z and
 * the row's newline. */
void ps_diff_cells(FILE *f, const hol_stats *d);
/* participants_stats.csv's rows of the questionnaires' scores
 * (report_pstats_q.c), after the trials' measures: 0, CLI_EXIT_FAIL out of
 * memory (one line said). */
int report_pstats_q_rows(FILE *f, const report_run *r);
/* paired.csv's and effects.csv's rows of the questionnaires' scores
 * (report_pstats_q.c), after the trials' measures: as report_pstats_q_rows. */
int report_pstats_q_pairs(FILE *f, const report_run *r);
int report_pstats_q_effects(FILE *f, const report_run *r);
/* The factor columns of trials.csv (report_effects.c). */
enum { PS_NF = 5 };
extern const char *const ps_factor[PS_NF];
/* Factor k of attempt t as trials.csv writes it ("" when it has none). */
void ps_factor_text(const report_att *t, int k, char *out, size_t cap);
/* The factors in which conditions ca and cb differ (their first included
 * trials'), space-separated, then end (report_pstats_write.c). */
void ps_differ(FILE *f, const report_run *r, int ca, int cb, const char *end);
/* effects.csv (report_effects.c) */
int report_effects_write(const report_run *r);

#endif
