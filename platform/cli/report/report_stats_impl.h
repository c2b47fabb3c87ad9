/* report_stats_impl.h - report_stats.c's tables, shared with
 * report_stats_html.c. Internal. */
#ifndef REPORT_STATS_IMPL_H
#define REPORT_STATS_IMPL_H

#include "../../../core/hol_stats.h"
#include "report_stats.h"

enum { RS_STEPS, RS_EFF, RS_TIME, RS_ERR_TRUE, RS_ERR_FLAT, RS_SSQ_T, RS_SSQ_N, RS_SSQ_O,
       RS_SSQ_D, RS_TLX, RS_NFIX };
extern const char *const rs_measure[RS_NFIX];

typedef struct rs_cond {
    char study[HOL_REPORT_TEXT], condition[HOL_REPORT_TEXT];
    int practice;
    int whole; /* 1: the study as a whole ("study"): its `after study`
                  questionnaires, no attempt (listed after its conditions) */
} rs_cond;

#define RS_LIK_MAX 4096   /* Likert items x conditions counted */
#define RS_LIK_SLOTS 8192

typedef struct rs_likert {
    int cond;
    char q[64], item[64];
    hol_stats s;
} rs_likert;

typedef struct rs_learn { /* one point of a learning curve */
    int cond;
    long pos;
    hol_stats_summary m;
} rs_learn;

typedef struct rs_prow { /* one participant x condition */
    int att, cond; /* att: an attempt of it (its participant) */
    long n, done;
    hol_stats steps, eff, time;
} rs_prow;

/* A point of the steps-against-optimum plot: the attempts of one condition
 * with the same optimum and steps (n of them). */
typedef struct rs_pt {
    long opt, steps;
    int cond, n;
} rs_pt;

/* A row of scores.csv: a questionnaire's score, subscale or item (key:
 * session, participant, attempt, questionnaire, when; \x1f between). */
typedef struct rs_score {
    char key[4 * HOL_REPORT_TEXT];
    int cond;
    char sub[64];
    double v;
    int has, complete; /* has: v is a value (a partial's scores have none) */
    int att;           /* the attempt answered at (r->att), -1 none */
} rs_score;

typedef struct report_stats {
    int ncond, none; /* none: the condition "none" */
    rs_cond *cond;  /* 2 natt + 1: the attempts', a "study" a study, "none" */
    int *att_cond;  /* per attempt */
    int *order;     /* attempts by (dir, session, attempt) */
    hol_stats *tpt; /* per attempt: its |error_true|, |error_flat| (2 each) */
    hol_stats *fix; /* ncond x RS_NFIX */
    rs_likert *lik;
    int nlik, caplik;
    int *slot; /* RS_LIK_SLOTS: an index in lik, -1 empty */
    long lik_dropped; /* answers beyond RS_LIK_MAX items */
    long partial;     /* questionnaires (presets) answered in part: unscored */
    char partial_first[160]; /* the first: its folder and group */
    rs_score *score; /* scores.csv's rows, as read */
    long nscore, capscore;
    int score_oom;
    rs_learn *learn;
    int nlearn;
    rs_prow *prow;
    int nprow;
    int *seen; /* a condition first seen i-th is listed seen[i]-th */
    int nseen;
    rs_pt *pts;    /* natt + 1: the plot's points (report_stats_html) */
    int *used;     /* per condition: in a plot (report_stats_html) */
    long *nrange;  /* per condition: its n's range in a plot (2 each) */
} report_stats;

int rs_included(const report_run *r, int i); /* done, not practice */
/* Score o's key split into part[0..4] (session, participant, attempt,
 * questionnaire, when; "" for those missing) in k, a copy of it: the
 * number of fields it has. */
/* scores.csv's excluded of score o: "duplicate" or "restarted" when the
 * run of the attempt it was answered at is (trials.csv's reason, whether
 * that attempt itself is practice or ended otherwise than done; from
 * r->pstats: report_stats.c), "" else (none, or no pstats). */
const char *rs_score_excluded(const report_run *r, const rs_score *o);
int rs_score_fields(const rs_score *o, char k[sizeof o->key], char *part[5]);
/* The condition a questionnaire of when (answers.csv's) at an attempt of
 * condition c is counted in: its study's "study" for `after study`, else c. */
int rs_when_cond(const report_stats *s, int c, const char *when);
/* The condition as the page names it ("study / condition"), HTML. */
void rs_cond_name(FILE *f, const rs_cond *c);

/* -1, 0 or 1 as a is below, equal to or above b (the sorts' comparators). */
static inline int rs_cmp(long a, long b)
{
    return (a > b) - (a < b);
}

/* The first of three comparisons that is not 0: a sort by three keys. */
static inline int rs_first(int c1, int c2, int c3)
{
    return c1 ? c1 : c2 ? c2 : c3;
}

/* report_answers.c: every LOGDIR's points.csv and answers.csv read into
 * r->stats (0, or an exit status after one line). */
int rs_read_instruments(report_run *r);
/* report_stats_read in parts (report_stats.c): the trials' figures, then,
 * after rs_read_instruments, the rest with its status. */
int rs_read_trials(report_run *r);
int rs_read_done(report_run *r, int st);

#endif
