/* report_stats.c - the report's statistics (report_stats.h): conditions,
 * learning curves and the
 * per-participant table computed, stats.csv, learning.csv and
 * participants.csv written. */
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../../../core/hol_ask.h"
#include "../../../core/hol_study.h"
#include "../../../core/hol_text.h"
#include "../../file/hol_file.h"
#include "../../file/hol_lines.h"
#include "../cli.h"
#include "report_escape.h"
#include "report_instr.h"
#include "report_pstats_impl.h"
#include "report_stats_impl.h"

const char *const rs_measure[RS_NFIX] = {
    "steps",    "efficiency", "time",       "error_true",         "error_flat",
    "ssq_total", "ssq_nausea", "ssq_oculomotor", "ssq_disorientation", "tlx_raw"};

int rs_included(const report_run *r, int i)
{
    const report_stats *s = r->stats;
    return !strcmp(r->att[i].a.end, "done") && !s->cond[s->att_cond[i]].practice;
}

static int cond_of(report_stats *s, const hol_report_attempt *a)
{
    const char *c = a->study[0] ? a->condition : a->level;
    for (int i = 0; i < s->ncond; i++)
        if (!strcmp(s->cond[i].study, a->study) && !strcmp(s->cond[i].condition, c))
            return i;
    rs_cond *n = &s->cond[s->ncond];
    memcpy(n->study, a->study, sizeof n->study);
    snprintf(n->condition, sizeof n->condition, "%s", c);
    n->practice = a->study[0] && (!strcmp(c, HOL_STUDY_PRACTICE) || a->position == 0);
    n->whole = 0;
    return s->ncond++;
}

/* Each study's "study" (rs_cond.whole), after the conditions of the
 * attempts (so that the first-seen order of those stays s->seen's). */
static void add_wholes(report_stats *s)
{
    int n = s->ncond;
    for (int c = 0; c < n; c++) {
        int first = s->cond[c].study[0] != 0;
        for (int d = 0; first && d < c; d++)
            first = strcmp(s->cond[d].study, s->cond[c].study) != 0;
        if (!first)
            continue;
        rs_cond *w = &s->cond[s->ncond++];
        memset(w, 0, sizeof *w);
        memcpy(w->study, s->cond[c].study, sizeof w->study);
        snprintf(w->condition, sizeof w->condition, "study");
        w->whole = 1;
    }
}

int rs_when_cond(const report_stats *s, int c, const char *when)
{
    if (strcmp(when, "study") || c == s->none)
        return c;
    for (int w = 0; w < s->ncond; w++)
        if (s->cond[w].whole && !strcmp(s->cond[w].study, s->cond[c].study))
            return w;
    return c;
}

/* Attempts (pointers into r->att) by (dir, session, attempt), then where
 * they stand: a total order that needs no context. */
static int by_key(const void *pa, const void *pb)
{
    const report_att *a = *(const report_att *const *)pa, *b = *(const report_att *const *)pb;
    int c = rs_cmp(a->dir, b->dir);
    if (!c)
        c = strcmp(a->a.session, b->a.session);
    if (!c)
        c = rs_cmp(a->a.attempt, b->a.attempt);
    return c ? c : (a > b) - (a < b);
}

/* s->order: the attempts by by_key. 0, or -1 out of memory. */
static int order_attempts(const report_run *r, report_stats *s)
{
    const report_att **p = malloc(sizeof *p * (size_t)(r->natt + 1));
    if (!p)
        return -1;
    for (int i = 0; i < r->natt; i++)
        p[i] = &r->att[i];
    qsort(p, (size_t)r->natt, sizeof *p, by_key);
    for (int i = 0; i < r->natt; i++)
        s->order[i] = (int)(p[i] - r->att);
    free(p);
    return 0;
}

/* ---- learning curves and the per-participant table ---- */

typedef struct rs_lentry {
    int cond;
    long pos;
    double eff;
} rs_lentry;

static int by_cond_pos(const void *pa, const void *pb)
{
    const rs_lentry *a = pa, *b = pb;
    int c = rs_cmp(a->cond, b->cond);
    return c ? c : rs_cmp(a->pos, b->pos);
}

/* Position in the participant's order; outside a study the attempt. */
static long position(const hol_report_attempt *a)
{
    return a->position >= 1 ? a->position : a->attempt;
}

static int learning(const report_run *r, report_stats *s)
{
    rs_lentry *e = malloc(sizeof *e * (size_t)(r->natt + 1));
    s->learn = malloc(sizeof *s->learn * (size_t)(r->natt + 1));
    if (!e || !s->learn) {
        free(e);
        return -1;
    }
    int n = 0;
    for (int i = 0; i < r->natt; i++) {
        double eff = hol_report_efficiency(&r->att[i].a);
        if (rs_included(r, i) && eff >= 0)
            e[n++] = (rs_lentry){s->att_cond[i], position(&r->att[i].a), eff};
    }
    qsort(e, (size_t)n, sizeof *e, by_cond_pos);
    for (int i = 0; i < n;) {
        hol_stats st;
        hol_stats_init(&st);
        int j = i;
        for (; j < n && e[j].cond == e[i].cond && e[j].pos == e[i].pos; j++)
            hol_stats_add(&st, e[j].eff);
        rs_learn *l = &s->learn[s->nlearn++];
        l->cond = e[i].cond;
        l->pos = e[i].pos;
        hol_stats_summarize(&st, &l->m);
        i = j;
    }
    free(e);
    return 0;
}

typedef struct rs_pkey { /* an attempt as participants() sorts it */
    const char *participant;
    int cond, i;
} rs_pkey;

static int by_part_cond(const void *pa, const void *pb)
{
    const rs_pkey *a = pa, *b = pb;
    return rs_first(strcmp(a->participant, b->participant), rs_cmp(a->cond, b->cond),
                    rs_cmp(a->i, b->i));
}

static int participants(const report_run *r, report_stats *s)
{
    int *ix = malloc(sizeof *ix * (size_t)(r->natt + 1));
    rs_pkey *k = malloc(sizeof *k * (size_t)(r->natt + 1));
    s->prow = malloc(sizeof *s->prow * (size_t)(r->natt + 1));
    if (!ix || !k || !s->prow) {
        free(ix);
        free(k);
        return -1;
    }
    for (int i = 0; i < r->natt; i++)
        k[i] = (rs_pkey){r->att[i].a.participant, s->att_cond[i], i};
    qsort(k, (size_t)r->natt, sizeof *k, by_part_cond);
    for (int i = 0; i < r->natt; i++)
        ix[i] = k[i].i;
    free(k);
    for (int i = 0; i < r->natt;) {
        rs_prow *p = &s->prow[s->nprow++];
        memset(p, 0, sizeof *p);
        p->att = ix[i];
        p->cond = s->att_cond[ix[i]];
        int j = i;
        for (; j < r->natt && s->att_cond[ix[j]] == p->cond &&
               !strcmp(r->att[ix[j]].a.participant, r->att[ix[i]].a.participant); j++) {
            const hol_report_attempt *a = &r->att[ix[j]].a;
            double eff = hol_report_efficiency(a);
            p->n++;
            if (strcmp(a->end, "done"))
                continue;
            p->done++;
            hol_stats_add(&p->steps, (double)a->steps);
            hol_stats_add(&p->time, a->time_s);
            if (eff >= 0)
                hol_stats_add(&p->eff, eff);
        }
        i = j;
    }
    free(ix);
    return 0;
}

/* ---- the conditions' order: the study file's (docs/research.md) ---- */

typedef struct rs_rank {
    int group;  /* the study's first condition in first-seen order */
    int klass;  /* 0 practice, 1 in a study file, 2 not in one */
    int index;  /* in the study file; outside a study: first seen */
    int cond;   /* the condition (first seen) */
    const char *name; /* its name */
} rs_rank;

/* Each LOGDIR's study-HASH.txt files (by name) give their study's
 * conditions in the file's order; the first file naming a condition wins. */
static void rank_from_files(const report_run *r, rs_rank *k, hol_study *st)
{
    const report_stats *s = r->stats;
    for (int d = 0; d < r->ndirs; d++) {
        struct dirent **e = NULL;
        int n = scandir(r->dirs[d], &e, NULL, alphasort);
        for (int i = 0; i < n; i++) {
            const char *nm = e[i]->d_name;
            size_t len = strlen(nm);
            char path[4200];
            struct stat sb;
            uint8_t *data = NULL;
            size_t size = 0;
            hol_level_err err;
            snprintf(path, sizeof path, "%s/%s", r->dirs[d], nm);
            if (len > 10 && !strncmp(nm, "study-", 6) && !strcmp(nm + len - 4, ".txt") &&
                !lstat(path, &sb) && S_ISREG(sb.st_mode) &&
                !hol_file_read_all(path, HOL_STUDY_TEXT_MAX, &data, &size) &&
                !hol_study_parse((const char *)data, size, st, &err))
                for (int c = 0; c < s->ncond; c++)
                    for (int j = 0; k[c].klass == 2 && j < st->nconditions; j++)
                        if (!strcmp(s->cond[c].study, st->name) &&
                            !strcmp(s->cond[c].condition, st->conditions[j].name))
                            k[c].klass = 1, k[c].index = j;
            free(data);
            free(e[i]);
        }
        free(e);
    }
}

/* Names as a person sorts them: runs of digits by their value (c2 before
 * c10; leading zeros decide a tie), the rest byte by byte. */
static int name_cmp(const char *a, const char *b)
{
    while (*a && *b) {
        if (*a >= '0' && *a <= '9' && *b >= '0' && *b <= '9') {
            const char *za = a, *zb = b;
            while (*za == '0')
                za++;
            while (*zb == '0')
                zb++;
            size_t na = strspn(za, "0123456789"), nb = strspn(zb, "0123456789");
            if (na != nb)
                return na < nb ? -1 : 1;
            int c = memcmp(za, zb, na);
            if (c)
                return c;
            if (za - a != zb - b)
                return za - a < zb - b ? -1 : 1;
            a = za + na;
            b = zb + nb;
            continue;
        }
        if (*a != *b)
            return (unsigned char)*a < (unsigned char)*b ? -1 : 1;
        a++, b++;
    }
    return *a ? 1 : *b ? -1 : 0;
}

static int by_rank(const void *pa, const void *pb)
{
    const rs_rank *x = pa, *y = pb;
    int c = rs_cmp(x->group, y->group);
    if (!c)
        c = rs_cmp(x->klass, y->klass);
    if (!c && x->klass != 2)
        c = rs_cmp(x->index, y->index);
    if (!c)
        c = name_cmp(x->name, y->name);
    if (!c)
        c = strcmp(x->name, y->name);
    return c ? c : rs_cmp(x->cond, y->cond);
}

/* Conditions (not yet "none") reordered: by study in first-seen order;
 * in a study practice first, then the study file's order, then those no
 * study file names by name; outside a study the order first seen. */
static int order_conditions(report_run *r)
{
    report_stats *s = r->stats;
    int n = s->ncond;
    rs_rank *k = malloc(sizeof *k * (size_t)(n + 1));
    int *ix = malloc(sizeof *ix * (size_t)(n + 1)), *to = malloc(sizeof *to * (size_t)(n + 1));
    rs_cond *old = malloc(sizeof *old * (size_t)(n + 1));
    hol_study *st = malloc(sizeof *st);
    int ok = k && ix && to && old && st;
    for (int c = 0; ok && c < n; c++) {
        k[c].group = c;
        for (int g = 0; g < c; g++)
            if (!strcmp(s->cond[g].study, s->cond[c].study)) {
                k[c].group = k[g].group;
                break;
            }
        k[c].klass = !s->cond[c].study[0]   ? 0
                     : s->cond[c].practice ? 0
                     : s->cond[c].whole    ? 3
                                           : 2;
        k[c].index = c;
        k[c].cond = c;
        k[c].name = s->cond[c].condition;
    }
    if (ok) {
        rank_from_files(r, k, st);
        qsort(k, (size_t)n, sizeof *k, by_rank);
        for (int c = 0; c < n; c++)
            ix[c] = k[c].cond;
        memcpy(old, s->cond, sizeof *old * (size_t)n);
        for (int c = 0; c < n; c++) {
            s->cond[c] = old[ix[c]];
            to[ix[c]] = c;
        }
        for (int i = 0; i < r->natt; i++)
            s->att_cond[i] = to[s->att_cond[i]];
        s->seen = to; /* first seen -> listed (report_stats_order_agg) */
        s->nseen = n;
        to = NULL;
    }
    free(k);
    free(ix);
    free(to);
    free(old);
    free(st);
    return ok ? 0 : CLI_EXIT_FAIL;
}

typedef struct rs_aggkey {
    int rank, i;
} rs_aggkey;

static int by_aggkey(const void *pa, const void *pb)
{
    const rs_aggkey *a = pa, *b = pb;
    int c = rs_cmp(a->rank, b->rank);
    return c ? c : rs_cmp(a->i, b->i);
}

/* The conditions of g (first seen, as report_stats_read's were) in the
 * same order as stats.csv's. */
int report_stats_order_agg(const report_run *r, hol_report_agg *g)
{
    const report_stats *s = r->stats;
    if (!s || !g->c || g->n < 2)
        return 0;
    rs_aggkey *k = malloc(sizeof *k * (size_t)g->n);
    hol_report_cond *old = malloc(sizeof *old * (size_t)g->n);
    if (!k || !old) {
        free(k);
        free(old);
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    for (int i = 0; i < g->n; i++) {
        const hol_report_cond *c = &g->c[i];
        int at = i < s->nseen ? s->seen[i] : -1;
        if (at < 0 || strcmp(s->cond[at].study, c->study) ||
            strcmp(s->cond[at].condition, c->condition))
            for (at = 0; at < s->ncond; at++) /* not expected: looked up */
                if (!strcmp(s->cond[at].study, c->study) &&
                    !strcmp(s->cond[at].condition, c->condition))
                    break;
        k[i] = (rs_aggkey){at, i};
    }
    qsort(k, (size_t)g->n, sizeof *k, by_aggkey);
    memcpy(old, g->c, sizeof *old * (size_t)g->n);
    for (int i = 0; i < g->n; i++)
        g->c[i] = old[k[i].i];
    free(k);
    free(old);
    return 0;
}

/* ---- reading it all ---- */

static int alloc_stats(report_run *r)
{
    report_stats *s = r->stats = calloc(1, sizeof *r->stats);
    size_t n = (size_t)r->natt + 1, nc = 2 * n; /* conditions: rs_cond */
    if (!s || !(s->cond = malloc(sizeof *s->cond * nc)) ||
        !(s->att_cond = malloc(sizeof *s->att_cond * n)) ||
        !(s->order = malloc(sizeof *s->order * n)) ||
        !(s->tpt = calloc(2 * n, sizeof *s->tpt)) ||
        !(s->fix = calloc(nc * RS_NFIX, sizeof *s->fix)) ||
        !(s->lik = malloc(sizeof *s->lik * RS_LIK_MAX)) ||
        !(s->slot = malloc(sizeof *s->slot * RS_LIK_SLOTS)) ||
        !(s->pts = malloc(sizeof *s->pts * n)) || !(s->used = calloc(nc, sizeof *s->used)) ||
        !(s->nrange = calloc(2 * nc, sizeof *s->nrange))) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    s->caplik = RS_LIK_MAX;
    for (int i = 0; i < RS_LIK_SLOTS; i++)
        s->slot[i] = -1;
    return 0;
}

/* report_stats_read's first part (report_answers.c runs the three): the
 * trials' figures. */
int rs_read_trials(report_run *r)
{
    int st = alloc_stats(r);
    report_stats *s = r->stats;
    for (int i = 0; !st && i < r->natt; i++) {
        s->att_cond[i] = cond_of(s, &r->att[i].a);
        s->order[i] = i;
    }
    if (!st)
        add_wholes(s);
    if (!st && order_conditions(r)) {
        cli_error(r->cmd, 0, "out of memory");
        st = CLI_EXIT_FAIL;
    }
    if (st)
        return st;
    s->none = s->ncond++;
    memset(&s->cond[s->none], 0, sizeof s->cond[0]);
    snprintf(s->cond[s->none].condition, sizeof s->cond[0].condition, "none");
    if (order_attempts(r, s)) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    for (int i = 0; i < r->natt; i++) {
        hol_stats *f = &s->fix[s->att_cond[i] * RS_NFIX];
        double eff = hol_report_efficiency(&r->att[i].a);
        if (!rs_included(r, i))
            continue;
        hol_stats_add(&f[RS_STEPS], (double)r->att[i].a.steps);
        hol_stats_add(&f[RS_TIME], r->att[i].a.time_s);
        if (eff >= 0)
            hol_stats_add(&f[RS_EFF], eff);
    }
    return 0;
}

/* report_stats_read's last part, after the questionnaires and pointing
 * were read with status st: the warnings, learning and participants. */
int rs_read_done(report_run *r, int st)
{
    report_stats *s = r->stats;
    if (!st && s->lik_dropped)
        fprintf(stderr, "holonomy %s: warning: more than %d Likert items and conditions: "
                        "%ld answers not in stats.csv\n", r->cmd, RS_LIK_MAX, s->lik_dropped);
    if (!st && s->partial)
        fprintf(stderr, "holonomy %s: warning: %ld questionnaire(s) answered in part, not "
                        "scored (the first: %s)\n", r->cmd, s->partial, s->partial_first);
    if (!st && (s->score_oom || learning(r, s) || participants(r, s)))
        st = CLI_EXIT_FAIL;
    if (st == CLI_EXIT_FAIL)
        cli_error(r->cmd, 0, "out of memory");
    return st;
}

void report_stats_free(report_run *r)
{
    report_stats *s = r->stats;
    if (!s)
        return;
    void *own[] = {s->cond, s->att_cond, s->order, s->tpt, s->fix, s->lik, s->slot, s->learn,
                   s->prow, s->seen, s->pts, s->used, s->nrange, s->score, s};
    for (size_t i = 0; i < sizeof own / sizeof own[0]; i++)
        free(own[i]);
    r->stats = NULL;
}

/* ---- the CSV files ---- */

/* n,mean,sd,ci_low,ci_high (empty where not defined) */
static void summary(FILE *f, const hol_stats *st)
{
    hol_stats_summary m;
    hol_stats_summarize(st, &m);
    fprintf(f, "%ld,", m.n);
    if (m.has_mean)
        fprintf(f, "%.4f", m.mean);
    if (m.has_sd)
        fprintf(f, ",%.4f,%.4f,%.4f\n", m.sd, m.lo, m.hi);
    else
        fputs(",,,\n", f);
}

static int stats_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_stats *s = r->stats;
    (void)ctx;
    report_header(f, "stats.csv");
    for (int c = 0; c < s->ncond; c++) {
        for (int m = 0; m < RS_NFIX; m++) {
            if (!s->fix[c * RS_NFIX + m].n)
                continue;
            report_csv(f, s->cond[c].study, 0);
            report_csv(f, s->cond[c].condition, 0);
            fprintf(f, "%s,,", rs_measure[m]);
            summary(f, &s->fix[c * RS_NFIX + m]);
        }
        for (int i = 0; i < s->nlik; i++) {
            char item[160];
            if (s->lik[i].cond != c)
                continue;
            snprintf(item, sizeof item, "%s/%s", s->lik[i].q, s->lik[i].item);
            report_csv(f, s->cond[c].study, 0);
            report_csv(f, s->cond[c].condition, 0);
            fputs("likert,", f);
            report_csv(f, item, 0);
            summary(f, &s->lik[i].s);
        }
    }
    return 0;
}

static int learning_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)ctx;
    report_header(f, "learning.csv");
    for (int i = 0; i < r->stats->nlearn; i++) {
        const rs_learn *l = &r->stats->learn[i];
        const rs_cond *c = &r->stats->cond[l->cond];
        report_csv(f, c->study, 0);
        report_csv(f, c->condition, 0);
        fprintf(f, "%ld,%ld,%.4f,", l->pos, l->m.n, l->m.mean);
        if (l->m.has_sd)
            fprintf(f, "%.4f,%.4f,%.4f\n", l->m.sd, l->m.lo, l->m.hi);
        else
            fputs(",,\n", f);
    }
    return 0;
}

static void mean_or_empty(FILE *f, const hol_stats *st, int last)
{
    if (st->n)
        fprintf(f, "%.4f", st->mean);
    fputc(last ? '\n' : ',', f);
}

static int participants_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_stats *s = r->stats;
    (void)ctx;
    report_header(f, "participants.csv");
    for (int i = 0; i < s->nprow; i++) {
        const rs_prow *p = &s->prow[i];
        report_csv(f, r->att[p->att].a.participant, 0);
        report_csv(f, s->cond[p->cond].study, 0);
        report_csv(f, s->cond[p->cond].condition, 0);
        fprintf(f, "%ld,%ld,", p->n, p->done);
        mean_or_empty(f, &p->steps, 0);
        mean_or_empty(f, &p->eff, 0);
        mean_or_empty(f, &p->time, 1);
    }
    return 0;
}

const char *rs_score_excluded(const report_run *r, const rs_score *o)
{
    const report_pstats *p = r->pstats;
    if (!p || o->att < 0 || o->att >= r->natt)
        return "";
    int run = p->run[o->att];
    return run == PX_DUPLICATE ? "duplicate" : run == PX_RESTARTED ? "restarted" : "";
}

int rs_score_fields(const rs_score *o, char k[sizeof o->key], char *part[5])
{
    memcpy(k, o->key, sizeof o->key);
    part[0] = k;
    for (int j = 1; j < 5; j++) {
        char *sep = strchr(part[j - 1], '\x1f');
        for (int l = j; !sep && l < 5; l++)
            part[l] = "";
        if (!sep)
            return j;
        *sep = 0;
        part[j] = sep + 1;
    }
    return 5;
}

/* scores.csv: a row's key split (session, participant, attempt,
 * questionnaire, when); `after study` and `before study` under the
 * condition `study`. */
static int scores_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_stats *s = r->stats;
    char k[sizeof s->score->key], *part[5];
    (void)ctx;
    report_header(f, "scores.csv");
    for (long i = 0; i < s->nscore; i++) {
        const rs_score *o = &s->score[i];
        rs_score_fields(o, k, part);
        const char *when = part[4], *scope = strchr(when, '_') ? strchr(when, '_') + 1 : when;
        int before = !strncmp(when, "before_", 7);
        report_csv(f, part[1], 0);
        report_csv(f, part[0], 0);
        report_csv(f, part[2], 0);
        report_csv(f, s->cond[o->cond].study, 0);
        report_csv(f, !strcmp(scope, "study") ? "study" : s->cond[o->cond].condition, 0);
        fprintf(f, "%s,", before ? "before" : "after");
        report_csv(f, scope, 0);
        report_csv(f, part[3], 0);
        report_csv(f, o->sub, 0);
        if (o->has)
            fprintf(f, "%.4f", o->v);
        fprintf(f, ",%d,", o->complete);
        report_csv(f, rs_score_excluded(r, o), 1);
    }
    return 0;
}

int report_stats_write(const report_run *r)
{
    static const report_file_job jobs[] = {
        {"stats.csv", stats_csv}, {"scores.csv", scores_csv}, {"learning.csv", learning_csv},
        {"participants.csv", participants_csv}};
    return report_write_files(r, jobs, (int)(sizeof jobs / sizeof jobs[0]));
}

/* ---- a log folder named from the report's folder ---- */

void report_rel_dir(const report_run *r, int d, char *out, size_t cap)
{
    char from[4096], to[4096];
    out[0] = 0;
    if (!realpath(r->out, from) || !realpath(r->dirs[d], to))
        return;
    size_t common = 0, i = 0;
    for (;; i++) { /* the last '/' (or end) where both agree */
        int ef = !from[i] || from[i] == '/', et = !to[i] || to[i] == '/';
        if (ef && et)
            common = i;
        if (!from[i] || !to[i] || from[i] != to[i])
            break;
    }
    if (!strcmp(from, "/"))
        common = 0;
    size_t n = 0;
    for (const char *p = from + common; *p; p++)
        if (*p == '/' && n + 4 < cap)
            n += (size_t)snprintf(out + n, cap - n, "../");
    const char *rest = to + common + (to[common] == '/');
    if (!*rest && n)
        out[n - 1] = 0; /* "../.." */
    else if (!*rest)
        snprintf(out, cap, ".");
    else
        snprintf(out + n, cap - n, "%s", rest);
}
