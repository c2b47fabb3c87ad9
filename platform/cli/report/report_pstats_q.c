/* report_pstats_q.c - the questionnaires' scores at participant level
 * (report_pstats.h): participants_stats.csv's rows of the presets' scores
 * (ssq_total, ssq_nausea, ssq_oculomotor, ssq_disorientation, tlx_raw;
 * with "_before" for a `before` placement), from scores.csv's rows as it
 * writes them (4 decimals, so that a reader of scores.csv gets the same
 * figures): per study, condition (or "study") and measure, the mean of
 * the participants' means (each the mean of their complete scores there),
 * and where the study has two or more conditions with the measure the
 * within-subjects interval over the participants with a score in each. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../../core/hol_ask.h"
#include "../cli.h"
#include "report_escape.h"
#include "report_pstats_impl.h"

typedef struct pq_key { /* one complete score */
    const char *study, *condition;
    char participant[HOL_REPORT_TEXT];
    int sorder, corder; /* the study's first condition, the condition's (study: ncond) */
    int m;              /* (preset x HOL_ASK_PRESET_SCORES + score) x 2 + before */
    double v;
} pq_key;

static int by_q(const void *pa, const void *pb)
{
    const pq_key *a = pa, *b = pb;
    int c = rs_first(rs_cmp(a->sorder, b->sorder), rs_cmp(a->m, b->m),
                     rs_cmp(a->corder, b->corder));
    return c ? c : strcmp(a->participant, b->participant);
}

/* Score o as a key: 1, 0 when it is no preset's complete score. */
static int q_key(const report_run *r, const rs_score *o, pq_key *k)
{
    const report_stats *s = r->stats;
    if (*rs_score_excluded(r, o) && !r->include_restarted)
        return 0; /* scores.csv's excluded */
    char key[sizeof o->key], *part[5];
    int p = rs_score_fields(o, key, part) == 5 ? hol_ask_preset_index(part[3], strlen(part[3]))
                                               : -1;
    if (!o->has || !o->complete || p < 0 || o->cond == s->none)
        return 0;
    const hol_ask_preset_def *d = hol_ask_preset_at(p);
    int sc = 0;
    while (sc < d->nscores && strcmp(d->scores[sc].name, o->sub))
        sc++;
    if (sc == d->nscores)
        return 0;
    const char *when = part[4], *scope = strchr(when, '_') ? strchr(when, '_') + 1 : when;
    int whole = !strcmp(scope, "study");
    const rs_cond *c = &s->cond[o->cond];
    k->study = c->study;
    k->condition = whole ? "study" : c->condition;
    k->sorder = 0;
    while (k->sorder < s->ncond && strcmp(s->cond[k->sorder].study, c->study))
        k->sorder++;
    k->corder = whole ? s->ncond : o->cond;
    k->m = (p * HOL_ASK_PRESET_SCORES + sc) * 2 + !strncmp(when, "before_", 7);
    snprintf(k->participant, sizeof k->participant, "%s", part[1]);
    char cell[32];
    snprintf(cell, sizeof cell, "%.4f", o->v); /* as scores.csv has it */
    k->v = strtod(cell, NULL);
    return 1;
}

/* The participants' means of keys [lo, hi) (one condition and measure):
 * into out (one per participant), their count; *trials the scores. */
static int part_means(const pq_key *k, int lo, int hi, double *out, long *trials)
{
    int n = 0;
    *trials = hi - lo;
    for (int i = lo, j; i < hi; i = j) {
        double sum = 0;
        for (j = i; j < hi && !strcmp(k[j].participant, k[i].participant); j++)
            sum += k[j].v;
        out[n++] = sum / (double)(j - i);
    }
    return n;
}

/* The participant p's mean in condition [lo, hi) of k, 1; 0 when none. */
static int mean_of(const pq_key *k, int lo, int hi, const char *p, double *out)
{
    double sum = 0;
    int n = 0;
    for (int i = lo; i < hi; i++)
        if (!strcmp(k[i].participant, p))
            sum += k[i].v, n++;
    if (n)
        *out = sum / n;
    return n > 0;
}

/* The within-subjects values of condition c of the J conditions [at[0],
 * at[1]), [at[1], at[2]), ... of k (one study and measure): each
 * participant with a mean in all J, their value less their mean plus the
 * grand mean. */
static void within_q(const pq_key *k, const int *at, int J, int c, hol_stats *w)
{
    double grand = 0, v[REPORT_PAIR_MAX];
    long np = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = at[0]; i < at[1]; i++) {
            if (i > at[0] && !strcmp(k[i].participant, k[i - 1].participant))
                continue;
            double sum = 0;
            int have = 1;
            for (int j = 0; j < J && have; j++)
                have = mean_of(k, at[j], at[j + 1], k[i].participant, &v[j]), sum += v[j];
            if (have && !pass)
                grand += sum, np++;
            else if (have && np)
                hol_stats_add(w, v[c] - sum / J + grand / ((double)np * J));
        }
}

/* One study's measure (keys [lo, hi), by condition, "study" last: its
 * order whole): its rows. -1 out of memory. */
static int q_rows(FILE *f, const pq_key *k, int lo, int hi, int whole_order)
{
    int *at = malloc(sizeof *at * (size_t)(hi - lo + 2)), n = 0;
    double *pm = malloc(sizeof *pm * (size_t)(hi - lo + 1));
    if (!at || !pm) {
        free(at);
        free(pm);
        return -1;
    }
    for (int i = lo; i < hi; i++)
        if (i == lo || k[i].corder != k[i - 1].corder)
            at[n++] = i;
    at[n] = hi;
    int J = n - (k[at[n - 1]].corder == whole_order);
    const hol_ask_preset_def *d = hol_ask_preset_at(k[lo].m / 2 / HOL_ASK_PRESET_SCORES);
    for (int c = 0; c < n; c++) {
        long trials;
        int np = part_means(k, at[c], at[c + 1], pm, &trials), whole = c >= J;
        hol_stats b, w;
        hol_stats_init(&b);
        hol_stats_init(&w);
        for (int i = 0; i < np; i++)
            hol_stats_add(&b, pm[i]);
        if (!whole && J >= 2 && J <= REPORT_PAIR_MAX)
            within_q(k, at, J, c, &w);
        report_csv(f, k[lo].study, 0);
        report_csv(f, k[at[c]].condition, 0);
        fprintf(f, "%s_%s%s,%d,%ld,", d->name, d->scores[k[lo].m / 2 % HOL_ASK_PRESET_SCORES].name,
                k[lo].m % 2 ? "_before" : "", np, trials);
        ps_summary(f, &b, 1, 1, 0);
        fprintf(f, "%d,%ld,", whole ? 0 : J, w.n);
        ps_summary(f, &w, J >= 2 ? sqrt((double)J / (J - 1)) : 0, 0, 1);
    }
    free(at);
    free(pm);
    return 0;
}

/* Each study's measure of the complete scores (keys [lo, hi) of k, by
 * condition, "study" last) through fn (0, -1 out of memory): 0, or
 * CLI_EXIT_FAIL out of memory (one line said). */
typedef int (*q_fn)(FILE *f, const report_run *r, const pq_key *k, int lo, int hi);
static int q_each(FILE *f, const report_run *r, q_fn fn)
{
    const report_stats *s = r->stats;
    pq_key *k = malloc(sizeof *k * (size_t)(s->nscore + 1));
    int n = 0, st = !k;
    for (long i = 0; k && i < s->nscore; i++)
        n += q_key(r, &s->score[i], &k[n]);
    if (k)
        qsort(k, (size_t)n, sizeof *k, by_q);
    for (int i = 0, j; i < n && !st; i = j) {
        for (j = i; j < n && k[j].sorder == k[i].sorder && k[j].m == k[i].m; j++)
            ;
        st = fn(f, r, k, i, j);
    }
    free(k);
    if (st)
        cli_error(r->cmd, 0, "out of memory");
    return st ? CLI_EXIT_FAIL : 0;
}

static int q_rows_of(FILE *f, const report_run *r, const pq_key *k, int lo, int hi)
{
    return q_rows(f, k, lo, hi, r->stats->ncond);
}

int report_pstats_q_rows(FILE *f, const report_run *r)
{
    return q_each(f, r, q_rows_of);
}

/* The study's conditions of keys [lo, hi) (not "study"): their bounds
 * into at (J + 1), J; 0 when under 2 or over REPORT_PAIR_MAX. */
static int q_conds(const pq_key *k, int lo, int hi, int whole_order, int *at)
{
    int n = 0;
    for (int i = lo; i < hi && k[i].corder != whole_order; i++)
        if (i == lo || k[i].corder != k[i - 1].corder) {
            if (n == REPORT_PAIR_MAX)
                return 0;
            at[n++] = i;
        }
    int end = n ? at[n - 1] : hi;
    while (end < hi && k[end].corder != whole_order)
        end++;
    at[n] = end;
    return n >= 2 ? n : 0;
}

/* The measure's name and study as the rows' first cells. */
static void q_lead(FILE *f, const pq_key *k)
{
    const hol_ask_preset_def *d = hol_ask_preset_at(k->m / 2 / HOL_ASK_PRESET_SCORES);
    report_csv(f, k->study, 0);
    fprintf(f, "%s_%s%s,", d->name, d->scores[k->m / 2 % HOL_ASK_PRESET_SCORES].name,
            k->m % 2 ? "_before" : "");
}

/* paired.csv's rows of one study's measure: each pair of its conditions,
 * A - B over the participants with a score in both. */
static int q_pairs(FILE *f, const report_run *r, const pq_key *k, int lo, int hi)
{
    int at[REPORT_PAIR_MAX + 1], J = q_conds(k, lo, hi, r->stats->ncond, at);
    for (int a = 0; a < J; a++)
        for (int b = a + 1; b < J; b++) {
            hol_stats d;
            double va, vb;
            hol_stats_init(&d);
            for (int i = at[a]; i < at[a + 1]; i++)
                if ((i == at[a] || strcmp(k[i].participant, k[i - 1].participant)) &&
                    mean_of(k, at[a], at[a + 1], k[i].participant, &va) &&
                    mean_of(k, at[b], at[b + 1], k[i].participant, &vb))
                    hol_stats_add(&d, va - vb);
            if (!d.n)
                continue;
            q_lead(f, &k[lo]);
            report_csv(f, k[at[a]].condition, 0);
            report_csv(f, k[at[b]].condition, 0);
            ps_differ(f, r, k[at[a]].corder, k[at[b]].corder, ",");
            ps_diff_cells(f, &d);
        }
    return 0;
}

int report_pstats_q_pairs(FILE *f, const report_run *r)
{
    return q_each(f, r, q_pairs);
}

/* effects.csv's rows of one study's measure and factor x: the levels of
 * its conditions (their first included trials'), each complete
 * participant's level means, each pair of levels. */
static void q_effect(FILE *f, const report_run *r, const pq_key *k, const int *at, int J, int x)
{
    char text[REPORT_PAIR_MAX][24];
    int of[REPORT_PAIR_MAX], nl = 0;
    for (int c = 0; c < J; c++) {
        int i = r->pstats->first[k[at[c]].corder];
        of[c] = -1;
        if (i < 0)
            continue;
        char t[24];
        ps_factor_text(&r->att[i], x, t, sizeof t);
        for (of[c] = 0; of[c] < nl && strcmp(text[of[c]], t); of[c]++)
            ;
        if (of[c] == nl)
            memcpy(text[nl++], t, sizeof t);
    }
    if (nl < 2)
        return;
    hol_stats d[REPORT_PAIR_MAX * REPORT_PAIR_MAX];
    memset(d, 0, sizeof d);
    for (int i = at[0]; i < at[1]; i++) {
        double v, ls[REPORT_PAIR_MAX] = {0};
        int ln[REPORT_PAIR_MAX] = {0}, have = 1;
        if (i > at[0] && !strcmp(k[i].participant, k[i - 1].participant))
            continue;
        for (int c = 0; c < J && have; c++)
            if ((have = mean_of(k, at[c], at[c + 1], k[i].participant, &v)) && of[c] >= 0)
                ls[of[c]] += v, ln[of[c]]++;
        for (int a = 0; have && a < nl; a++)
            for (int b = a + 1; b < nl; b++)
                if (ln[a] && ln[b])
                    hol_stats_add(&d[a * nl + b], ls[a] / ln[a] - ls[b] / ln[b]);
    }
    for (int a = 0; a < nl; a++)
        for (int b = a + 1; b < nl; b++)
            if (d[a * nl + b].n) {
                q_lead(f, &k[at[0]]);
                fprintf(f, "%s,", ps_factor[x]);
                report_csv(f, text[a], 0);
                report_csv(f, text[b], 0);
                ps_diff_cells(f, &d[a * nl + b]);
            }
}

static int q_effects(FILE *f, const report_run *r, const pq_key *k, int lo, int hi)
{
    int at[REPORT_PAIR_MAX + 1], J = q_conds(k, lo, hi, r->stats->ncond, at);
    for (int x = 0; J && x < PS_NF; x++)
        q_effect(f, r, k, at, J, x);
    return 0;
}

int report_pstats_q_effects(FILE *f, const report_run *r)
{
    return q_each(f, r, q_effects);
}
