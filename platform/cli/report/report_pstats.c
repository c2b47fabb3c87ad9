/* report_pstats.c - the participant-level statistics (report_pstats.h):
 * each attempt's exclusion and trial number, the participants' means per
 * condition, the between- and within-subjects intervals (Cousineau 2005
 * with Morey's 2008 correction), the paired differences and d_z. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../cli.h"
#include "report_pstats.h"
#include "report_pstats_impl.h"

const char *const ps_measure[PS_NM] = {"steps", "efficiency", "time", "error_true",
                                       "error_flat"};

/* ---- Student's t, to 1e-12 (relative; 1e-15 below 50 degrees of freedom) ---- */

/* The continued fraction of the regularized incomplete beta (Lentz). */
static double beta_cf(double a, double b, double x)
{
    const double tiny = 1e-300;
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    d = 1 / (fabs(d) < tiny ? tiny : d);
    double h = d;
    for (int m = 1; m <= 1000; m++) {
        double m2 = 2.0 * m, aa = m * (b - m) * x / ((a + m2 - 1) * (a + m2));
        for (int k = 0; k < 2; k++) {
            d = 1 + aa * d;
            d = 1 / (fabs(d) < tiny ? tiny : d);
            c = 1 + aa / c;
            c = fabs(c) < tiny ? tiny : c;
            h *= d * c;
            aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1));
        }
        if (fabs(d * c - 1) < 1e-16)
            break;
    }
    return h;
}

/* I_x(a, b) */
static double beta_inc(double a, double b, double x)
{
    if (x <= 0 || x >= 1)
        return x <= 0 ? 0 : 1;
    double lf = lgamma(a + b) - lgamma(a) - lgamma(b) + a * log(x) + b * log1p(-x);
    if (x < (a + 1) / (a + b + 2))
        return exp(lf) * beta_cf(a, b, x) / a;
    return 1 - exp(lf) * beta_cf(b, a, 1 - x) / b;
}

double report_t975(long df)
{
    if (df < 1)
        return 0;
    const double v = (double)df;
    double t = df == 1 ? 12.706204736174698 : df == 2 ? 4.302652729749464 : hol_stats_t975(df);
    for (int it = 0; df > 2 && it < 50; it++) { /* Newton on the upper tail */
        double tail = 0.5 * beta_inc(v / 2, 0.5, v / (v + t * t));
        double pdf = exp(lgamma((v + 1) / 2) - lgamma(v / 2) - (v + 1) / 2 * log1p(t * t / v)) /
                     sqrt(v * M_PI);
        double step = (tail - 0.025) / pdf;
        t += step;
        if (fabs(step) < 1e-15 * t)
            break;
    }
    return t;
}

/* ---- exclusions and trial numbers ---- */

static int by_part(const void *pa, const void *pb)
{
    const ps_key *a = pa, *b = pb;
    return rs_first(strcmp(a->study, b->study), strcmp(a->participant, b->participant),
                    rs_cmp(a->i, b->i));
}

/* 1 when attempts t and u are one level of the order played by two
 * sessions of one folder (u the other). */
static int same_level(const report_att *t, const report_att *u)
{
    return u->dir == t->dir && strcmp(u->a.session, t->a.session) &&
           u->a.position == t->a.position && !strcmp(u->a.level_sha256, t->a.level_sha256);
}

/* 1 when a later session (its attempt t) of the participant whose earlier
 * session logged u may have been started as theirs: the same spelling of
 * the id, or its one spelling, which a build that has the rule logs, and
 * which such a build starts again only with --restart-participant or
 * --resume (a session that logged "2", then one that logged "P02"). */
static int same_person(const report_att *u, const report_att *t)
{
    return !t->spelled[0] || !strcmp(report_id_logged(u), report_id_logged(t));
}

/* Attempt k[j] of a second run of the participant (k[lo, j) before it):
 * in another folder than their first, or in theirs under another old
 * spelling of their id (logs made before ids had one: "002", then "p2")
 * replaying a level an earlier session completed. */
static int second_run(const report_run *r, const ps_key *k, int lo, int j)
{
    const report_att *t = &r->att[k[j].i];
    if (t->dir != r->att[k[lo].i].dir)
        return 1;
    for (int l = lo; l < j; l++) {
        const report_att *u = &r->att[k[l].i];
        if (same_level(t, u) && !strcmp(u->a.end, "done") && !same_person(u, t))
            return 1;
    }
    return 0;
}

/* The line naming a participant's second run: its first trial k[j]. */
static void tell_duplicate(const report_run *r, const ps_key *k, int lo, int j, long n)
{
    const report_att *a = &r->att[k[lo].i], *b = &r->att[k[j].i];
    const char *in[8] = {a->a.participant, a->a.study, r->dirs[a->dir], a->a.session,
                         report_id_logged(a), r->dirs[b->dir], b->a.session, report_id_logged(b)};
    char e[8][160];
    for (int x = 0; x < 8; x++)
        cli_escape(in[x], e[x], sizeof e[x]);
    fprintf(stderr, "holonomy %s: participant %s of study %s ran twice ('%s' session %s as %s, "
                    "then '%s' session %s as %s): %ld trial(s) of the second run are excluded "
                    "as duplicate (--include-restarted counts them)\n", r->cmd, e[0], e[1], e[2],
            e[3], e[4], e[5], e[6], e[7], n);
}

/* Attempts [lo, hi) of k: one study's participant, in the order read. */
static void one_participant(const report_run *r, report_pstats *p, const ps_key *k, int lo,
                            int hi)
{
    const report_stats *s = r->stats;
    int first_dup = -1;
    long ndup = 0;
    for (int j = lo; j < hi; j++) {
        int i = k[j].i;
        const hol_report_attempt *a = &r->att[i].a;
        int run = a->study[0] && second_run(r, k, lo, j) ? PX_DUPLICATE : PX_IN;
        p->trial[i] = j - lo + 1;
        for (int l = j + 1; !run && a->study[0] && l < hi; l++) {
            const report_att *b = &r->att[k[l].i];
            if (same_level(&r->att[i], b) && same_person(&r->att[i], b))
                run = PX_RESTARTED; /* played again by a later session */
        }
        p->run[i] = run;
        p->excl[i] = s->cond[s->att_cond[i]].practice ? PX_PRACTICE
                     : strcmp(a->end, "done")         ? PX_END
                                                      : run;
        if (p->excl[i] == PX_DUPLICATE && !ndup++)
            first_dup = j;
    }
    if (ndup && !r->quiet)
        tell_duplicate(r, k, lo, first_dup, ndup);
}

static int exclusions(const report_run *r, report_pstats *p)
{
    ps_key *k = malloc(sizeof *k * (size_t)(r->natt + 1));
    if (!k)
        return -1;
    for (int i = 0; i < r->natt; i++)
        k[i] = (ps_key){.study = r->att[i].a.study, .participant = r->att[i].a.participant, .i = i};
    qsort(k, (size_t)r->natt, sizeof *k, by_part);
    for (int i = 0; i < r->natt;) {
        int j = i + 1;
        while (j < r->natt && !strcmp(k[j].study, k[i].study) &&
               !strcmp(k[j].participant, k[i].participant))
            j++;
        one_participant(r, p, k, i, j);
        i = j;
    }
    free(k);
    return 0;
}

const char *report_pstats_excluded(const report_run *r, int i)
{
    static const char *const why[] = {"", "practice", "", "duplicate", "restarted"};
    const report_pstats *p = r->pstats;
    if (!p)
        return "";
    return p->excl[i] == PX_END ? r->att[i].a.end : why[p->excl[i]];
}

int ps_counts(const report_run *r, const report_pstats *p, int i)
{
    return !p->excl[i] || (r->include_restarted &&
                           (p->excl[i] == PX_DUPLICATE || p->excl[i] == PX_RESTARTED));
}

/* Attempt i's value of measure m: 1 and *v, 0 when it has none. */
int ps_value(const report_run *r, int i, int m, double *v)
{
    const hol_report_attempt *a = &r->att[i].a;
    const hol_stats *pt = &r->stats->tpt[2 * i];
    switch (m) {
    case PM_STEPS: *v = (double)a->steps; return 1;
    case PM_EFF: *v = hol_report_efficiency(a); return *v >= 0;
    case PM_TIME: *v = a->time_s; return 1;
    default: *v = pt[m - PM_ERR_TRUE].mean; return pt[m - PM_ERR_TRUE].n > 0;
    }
}

/* ---- the participants' means: one cell per (participant, condition) ---- */

/* Included attempts by (condition's study, participant, condition). */
static int by_cell(const void *pa, const void *pb)
{
    const ps_key *a = pa, *b = pb;
    int c = rs_cmp(a->group, b->group);
    if (!c)
        c = strcmp(a->participant, b->participant);
    if (!c)
        c = rs_cmp(a->cond, b->cond);
    return c ? c : rs_cmp(a->i, b->i);
}

static int make_cells(const report_run *r, report_pstats *p)
{
    const report_stats *s = r->stats;
    ps_key *k = malloc(sizeof *k * (size_t)(r->natt + 1));
    p->cell = malloc(sizeof *p->cell * (size_t)(r->natt + 1));
    if (!k || !p->cell) {
        free(k);
        return -1;
    }
    int n = 0;
    for (int c = 0; c < s->ncond; c++)
        p->first[c] = -1;
    for (int i = 0; i < r->natt; i++)
        if (ps_counts(r, p, i) && p->first[s->att_cond[i]] < 0)
            p->first[s->att_cond[i]] = i;
    for (int i = 0; i < r->natt; i++)
        if (ps_counts(r, p, i))
            k[n++] = (ps_key){NULL, r->att[i].a.participant, i, s->att_cond[i],
                              p->group[s->att_cond[i]]};
    qsort(k, (size_t)n, sizeof *k, by_cell);
    for (int i = 0; i < n;) {
        ps_cell *c = &p->cell[p->ncell++];
        memset(c, 0, sizeof *c);
        c->participant = k[i].participant;
        c->cond = k[i].cond;
        c->group = k[i].group;
        int j = i;
        for (; j < n && k[j].cond == k[i].cond && !strcmp(k[j].participant, k[i].participant);
             j++)
            for (int m = 0; m < PS_NM; m++) {
                double v;
                if (ps_value(r, k[j].i, m, &v))
                    c->sum[m] += v, c->n[m]++;
            }
        for (int m = 0; m < PS_NM; m++)
            if (c->n[m])
                c->mean[m] = c->sum[m] / (double)c->n[m];
        i = j;
    }
    free(k);
    return 0;
}

/* Between: per condition and measure over the cells (participants). */
static void between(report_pstats *p)
{
    for (int i = 0; i < p->ncell; i++)
        for (int m = 0; m < PS_NM; m++) {
            const ps_cell *c = &p->cell[i];
            ps_row *w = &p->row[c->cond * PS_NM + m];
            if (!c->n[m])
                continue;
            hol_stats_add(&w->between, c->mean[m]);
            w->trials += c->n[m];
        }
}

int ps_group_conds(const report_pstats *p, int g, int m, int ncond)
{
    int j = 0;
    for (int c = 0; c < ncond; c++)
        if (p->group[c] == g && p->row[c * PS_NM + m].between.n)
            j++;
    return j;
}

int ps_part_end(const report_pstats *p, int i, int m, int *have, double *sum)
{
    int j = i;
    *have = 0;
    *sum = 0;
    for (; j < p->ncell && p->cell[j].group == p->cell[i].group &&
           !strcmp(p->cell[j].participant, p->cell[i].participant);
         j++)
        if (p->cell[j].n[m])
            ++*have, *sum += p->cell[j].mean[m];
    return j;
}

/* Within (Cousineau-Morey) for group g and measure m: the participants
 * with a value in each of its J conditions; each value less the
 * participant's mean plus the grand mean (the interval is widened by
 * sqrt(J / (J - 1)) when written). */
static void within(report_pstats *p, int g, int m, int ncond)
{
    int J = ps_group_conds(p, g, m, ncond), have;
    double grand = 0, sum;
    long np = 0;
    if (J < 2)
        return;
    for (int i = 0, j; i < p->ncell; i = j) {
        j = ps_part_end(p, i, m, &have, &sum);
        if (p->cell[i].group == g && have == J)
            grand += sum, np++;
    }
    if (!np)
        return;
    grand /= (double)np * J;
    for (int i = 0, j; i < p->ncell; i = j) {
        j = ps_part_end(p, i, m, &have, &sum);
        for (int l = i; p->cell[i].group == g && have == J && l < j; l++)
            if (p->cell[l].n[m])
                hol_stats_add(&p->row[p->cell[l].cond * PS_NM + m].within,
                              p->cell[l].mean[m] - sum / J + grand);
    }
    for (int c = 0; c < ncond; c++)
        if (p->group[c] == g)
            p->row[c * PS_NM + m].J = J;
}

/* Pairs of the conditions of pg's group: each participant's differences. */
static void pairs(report_pstats *p, const ps_pairs *pg)
{
    hol_stats *pair = p->pair + pg->off;
    int have;
    double sum;
    for (int i = 0, j; i < p->ncell; i = j) {
        j = ps_part_end(p, i, 0, &have, &sum);
        for (int a = i; p->cell[i].group == pg->group && a < j; a++)
            for (int b = a + 1; b < j; b++)
                for (int m = 0; m < PS_NM; m++) {
                    const ps_cell *ca = &p->cell[a], *cb = &p->cell[b];
                    size_t ia = (size_t)(ca->cond - pg->first), ib = (size_t)(cb->cond - pg->first);
                    if (ca->n[m] && cb->n[m] && ib < (size_t)pg->n) /* ia < ib */
                        hol_stats_add(&pair[(ia * (size_t)pg->n + ib) * PS_NM + m],
                                      ca->mean[m] - cb->mean[m]);
                }
    }
}

/* Each condition's group: the first condition of its study (a study's
 * conditions are contiguous, practice first); practice and "none": -1. */
static void assign_groups(const report_run *r, report_pstats *p)
{
    const report_stats *s = r->stats;
    for (int c = 0; c < s->ncond; c++) {
        p->group[c] = c;
        for (int d = 0; d < c; d++)
            if (p->group[d] >= 0 && !strcmp(s->cond[d].study, s->cond[c].study)) {
                p->group[c] = p->group[d];
                break;
            }
        if (s->cond[c].practice || s->cond[c].whole || c == s->none)
            p->group[c] = -1;
    }
}

/* The within intervals of every group, then its pairs (a group of
 * 2..REPORT_PAIR_MAX conditions). */
static int design(const report_run *r, report_pstats *p)
{
    int ncond = r->stats->ncond;
    for (int g = 0; g < ncond; g++) {
        if (p->group[g] != g)
            continue;
        int gc = 0;
        for (int c = g; c < ncond; c++)
            gc += p->group[c] == g;
        for (int m = 0; m < PS_NM; m++)
            within(p, g, m, ncond);
        if (gc < 2 || gc > REPORT_PAIR_MAX)
            continue;
        p->pg[p->npg++] = (ps_pairs){g, g, gc, p->npair};
        p->npair += (size_t)gc * (size_t)gc * PS_NM;
    }
    if (!(p->pair = calloc(p->npair + 1, sizeof *p->pair)))
        return -1;
    for (int i = 0; i < p->npg; i++)
        pairs(p, &p->pg[i]);
    return 0;
}

int report_pstats_compute(report_run *r)
{
    const report_stats *s = r->stats;
    report_pstats *p = r->pstats = calloc(1, sizeof *p);
    size_t n = (size_t)r->natt + 1, nc = (size_t)s->ncond + 1;
    int ok = p && (p->excl = calloc(n, sizeof *p->excl)) &&
             (p->run = calloc(n, sizeof *p->run)) &&
             (p->trial = calloc(n, sizeof *p->trial)) &&
             (p->group = calloc(nc, sizeof *p->group)) &&
             (p->first = calloc(nc, sizeof *p->first)) &&
             (p->row = calloc(nc * PS_NM, sizeof *p->row)) &&
             (p->pg = calloc(nc, sizeof *p->pg)) && !exclusions(r, p);
    if (ok)
        assign_groups(r, p);
    if (ok && make_cells(r, p))
        ok = 0;
    if (ok)
        between(p);
    if (ok && design(r, p))
        ok = 0;
    if (!ok)
        cli_error(r->cmd, 0, "out of memory");
    return ok ? 0 : CLI_EXIT_FAIL;
}

void report_pstats_free(report_run *r)
{
    report_pstats *p = r->pstats;
    if (!p)
        return;
    void *own[] = {p->excl, p->run, p->trial, p->group, p->first, p->row, p->pg, p->cell, p->pair, p};
    for (size_t i = 0; i < sizeof own / sizeof own[0]; i++)
        free(own[i]);
    r->pstats = NULL;
}
