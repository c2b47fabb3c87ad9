/* report_stats.c - the report's statistics (report_stats.h): conditions,
 * points.csv and answers.csv read back, learning curves and the
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
    return s->ncond++;
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

/* The attempt (an index in r->att) of (dir, session, attempt), -1 none. */
static int find_att(const report_run *r, int dir, const char *session, long attempt)
{
    const report_stats *s = r->stats;
    int lo = 0, hi = r->natt;
    while (lo < hi) {
        int m = (lo + hi) / 2;
        const report_att *t = &r->att[s->order[m]];
        int c = t->dir != dir ? (t->dir < dir ? -1 : 1) : strcmp(t->a.session, session);
        if (!c)
            c = t->a.attempt < attempt ? -1 : t->a.attempt > attempt;
        if (!c)
            return s->order[m];
        if (c < 0)
            lo = m + 1;
        else
            hi = m;
    }
    return -1;
}

/* ---- CSV files of the instruments, read by column name ---- */

typedef struct rs_csv {
    const report_run *r;
    int dir;
    char path[4200];
    hol_lines l;
    int col[16];
    int ncol;
    int nhead; /* the header's fields: every row has as many */
    const char *f[HOL_REPORT_MAX_COLS];
    int nf;
    char buf[REPORT_LINE_MAX + 8];
    char err[HOL_REPORT_ERR];
} rs_csv;

static int bad(rs_csv *c, const char *msg)
{
    cli_error(c->r->cmd, 0, "%.300s: line %ld: %s", c->path, c->l.lineno, msg);
    return CLI_EXIT_USAGE;
}

/* Next data row into c->f (0 at the end, 1 a row, else -exit status);
 * the header's columns (names; the first nreq required, the rest -1 when
 * absent) found first; a row of another field count than the header's
 * (a torn row, the next one glued on) is refused. */
static int next_row(rs_csv *c, const char *const *names, int nnames, int nreq)
{
    char *s;
    size_t n;
    int got;
    while ((got = hol_lines_next(&c->l, &s, &n)) > 0) {
        if (c->l.lineno == 1 && n >= 3 && !memcmp(s, "\xef\xbb\xbf", 3))
            s += 3, n -= 3;
        if (n == strspn(s, " \t"))
            continue;
        if (hol_report_csv_split(s, n, c->buf, sizeof c->buf, c->f, HOL_REPORT_MAX_COLS, &c->nf,
                                 c->err))
            return -bad(c, c->err);
        if (c->ncol && c->nf != c->nhead) {
            snprintf(c->err, sizeof c->err, "%d fields where the header has %d", c->nf, c->nhead);
            return -bad(c, c->err);
        }
        if (c->ncol)
            return 1;
        c->nhead = c->nf;
        for (int k = 0; k < nnames; k++) {
            c->col[k] = -1;
            for (int i = 0; i < c->nf; i++)
                if (!strcmp(c->f[i], names[k]))
                    c->col[k] = i;
            if (c->col[k] < 0 && k < nreq) {
                snprintf(c->err, sizeof c->err, "no column '%s'", names[k]);
                return -bad(c, c->err);
            }
        }
        c->ncol = nnames;
    }
    return got < 0 ? -cli_lines_failed(c->r->cmd, "log", c->path, &c->l) : 0;
}

static const char *field(const rs_csv *c, int k)
{
    return c->col[k] >= 0 && c->col[k] < c->nf ? c->f[c->col[k]] : "";
}

/* An optional column's field, NULL when the file lacks the column. */
static const char *field_or_null(const rs_csv *c, int k)
{
    return c->col[k] >= 0 ? field(c, k) : NULL;
}

/* The attempt column: a whole number, 0 (before any) or more. */
static int attempt_of(rs_csv *c, int k, long *out)
{
    return report_instr_whole(field(c, k), 0, LONG_MAX, out);
}

static int open_csv(rs_csv *c, const report_run *r, int d, const char *name)
{
    struct stat sb;
    memset(c, 0, sizeof *c - sizeof c->buf);
    c->r = r;
    c->dir = d;
    snprintf(c->path, sizeof c->path, "%s/%s", r->dirs[d], name);
    if (lstat(c->path, &sb))
        return 1; /* not there: nothing to read */
    return cli_open_lines(r->cmd, "log", c->path, REPORT_LINE_MAX, &c->l) ? -1 : 0;
}

enum { P_SESSION, P_ATTEMPT, P_ETRUE, P_EFLAT, P_POINTED, P_TRUE, P_FLAT };

/* points.csv's rows (the file open in c->l): 0, or the exit status. */
static int points_rows(report_run *r, rs_csv *c)
{
    static const char *const names[] = {"session", "attempt", "error_true", "error_flat",
                                        "pointed", "true", "flat"}; /* the last 3 optional */
    report_stats *s = r->stats;
    int got;
    while ((got = next_row(c, names, 7, 4)) > 0) {
        long att;
        int has[2];
        double e[2];
        const char *bear[3] = {field_or_null(c, P_POINTED), field_or_null(c, P_TRUE),
                               field_or_null(c, P_FLAT)};
        if (!attempt_of(c, P_ATTEMPT, &att)) {
            got = -bad(c, "attempt is not a whole number (0 or more)");
            break;
        }
        if (report_instr_point(field(c, P_ETRUE), field(c, P_EFLAT), bear, has, e, c->err)) {
            got = -bad(c, c->err);
            break;
        }
        int ai = find_att(r, c->dir, field(c, P_SESSION), att);
        int ci = ai < 0 ? s->none : s->att_cond[ai];
        for (int k = 0; k < 2; k++)
            if (has[k]) {
                hol_stats_add(&s->fix[ci * RS_NFIX + RS_ERR_TRUE + k], e[k] < 0 ? -e[k] : e[k]);
                if (ai >= 0) /* the attempt's answers (report_pstats.c) */
                    hol_stats_add(&s->tpt[2 * ai + k], e[k] < 0 ? -e[k] : e[k]);
            }
    }
    return got < 0 ? -got : 0;
}

/* ---- answers.csv: questionnaires grouped, scored, likert means ---- */

enum { A_SESSION, A_PART, A_ATTEMPT, A_Q, A_WHEN, A_ITEM, A_KIND, A_VALUE };

typedef struct rs_group {
    char key[4 * HOL_REPORT_TEXT];
    int cond;
    double v[HOL_ASK_MAX_PRESETS][HOL_ASK_PRESET_ITEMS]; /* by the presets' table */
    unsigned have[HOL_ASK_MAX_PRESETS];
    report_instr_items items; /* the questionnaire's so far: none twice */
    int att;                  /* its attempt (r->att), -1 none */
    int level_dir, level_ok;  /* the level in r->level: its folder, parsed */
    char level_sha[HOL_REPORT_TEXT]; /* and name ("" none read) */
} rs_group;

/* A preset's answers seen in part so far (a session killed in it, the rest
 * asked by a resumed session, maybe after other participants' rows: issue
 * 39), kept until the rest come: RS_PARTS of them in a folder. */
#define RS_PARTS 64
typedef struct rs_part {
    char key[4 * HOL_REPORT_TEXT];
    int cond;
    double v[HOL_ASK_MAX_PRESETS][HOL_ASK_PRESET_ITEMS];
    unsigned have[HOL_ASK_MAX_PRESETS];
} rs_part;
typedef struct rs_parts {
    rs_part g[RS_PARTS];
    int n;
    long lost; /* partial beyond RS_PARTS: not scored */
} rs_parts;

/* 1 when the group holds a preset answered in part. */
static int group_partial(const rs_group *g)
{
    for (int i = 0; i < hol_ask_npresets(); i++)
        if (g->have[i] && g->have[i] != (1u << hol_ask_preset_at(i)->nitems) - 1)
            return 1;
    return 0;
}

/* A group answered in part is kept in pt (its scores wait for the rest);
 * told in pt->lost when there is no room. */
static void keep_partial(rs_parts *pt, const rs_group *g)
{
    if (pt->n == RS_PARTS) {
        pt->lost++;
        return;
    }
    rs_part *k = &pt->g[pt->n++];
    memcpy(k->key, g->key, sizeof k->key);
    k->cond = g->cond;
    memcpy(k->v, g->v, sizeof k->v);
    memcpy(k->have, g->have, sizeof k->have);
}

/* The rest of a group kept in part: its answers back into g. */
static void take_partial(rs_parts *pt, rs_group *g)
{
    for (int i = 0; i < pt->n; i++)
        if (!strcmp(pt->g[i].key, g->key)) {
            memcpy(g->v, pt->g[i].v, sizeof g->v);
            memcpy(g->have, pt->g[i].have, sizeof g->have);
            pt->g[i] = pt->g[--pt->n];
            return;
        }
}

/* A row of scores.csv (s->score grown as needed; s->score_oom when it
 * cannot be). */
static void add_score(report_stats *s, const char *key, int cond, const char *sub, double v,
                      int has, int complete)
{
    if (s->nscore == s->capscore) {
        long cap = s->capscore ? 2 * s->capscore : 256;
        rs_score *n = realloc(s->score, sizeof *n * (size_t)cap);
        if (!n) {
            s->score_oom = 1;
            return;
        }
        s->score = n;
        s->capscore = cap;
    }
    rs_score *o = &s->score[s->nscore++];
    snprintf(o->key, sizeof o->key, "%s", key);
    o->cond = cond;
    snprintf(o->sub, sizeof o->sub, "%s", sub);
    o->v = v;
    o->has = has;
    o->complete = complete;
}

/* Preset p's rows of scores.csv: its scores (empty when answered in
 * part), and for a preset of one score (tlx: raw) each item's answer. */
static void preset_scores(report_stats *s, const char *key, int cond,
                          const hol_ask_preset_def *p, const double *v, unsigned have)
{
    int complete = have == (1u << p->nitems) - 1;
    double sc[HOL_ASK_PRESET_SCORES] = {0};
    if (complete)
        hol_ask_score(p, v, sc);
    for (int k = 0; k < p->nscores; k++)
        add_score(s, key, cond, p->scores[k].name, sc[k], complete, complete);
    for (int j = 0; p->nscores == 1 && j < p->nitems; j++)
        add_score(s, key, cond, p->items[j].id, v[j], (have >> j) & 1, complete);
}

/* Each preset answered in full: its scores into the measures from RS_SSQ_T
 * on, in the table's order (ssq's four, tlx's raw); one answered in part
 * waits in pt. */
static void flush_group(report_stats *s, rs_group *g, rs_parts *pt)
{
    if (g->key[0] && group_partial(g))
        keep_partial(pt, g);
    hol_stats *f = &s->fix[g->cond * RS_NFIX];
    for (int i = 0, col = RS_SSQ_T; i < hol_ask_npresets(); i++) {
        const hol_ask_preset_def *p = hol_ask_preset_at(i);
        double sc[HOL_ASK_PRESET_SCORES];
        if (g->have[i] == (1u << p->nitems) - 1) {
            hol_ask_score(p, g->v[i], sc);
            preset_scores(s, g->key, g->cond, p, g->v[i], g->have[i]);
        }
        for (int k = 0; k < p->nscores; k++, col++)
            if (g->have[i] == (1u << p->nitems) - 1 && col < RS_NFIX)
                hol_stats_add(&f[col], sc[k]);
        g->have[i] = 0;
    }
}

/* The groups still in part at a folder's end: counted, the first named. */
static void parts_end(report_stats *s, const char *dir, rs_parts *pt)
{
    for (int i = 0; i < pt->n; i++) {
        for (int p = 0; p < hol_ask_npresets(); p++)
            if (pt->g[i].have[p])
                preset_scores(s, pt->g[i].key, pt->g[i].cond, hol_ask_preset_at(p),
                              pt->g[i].v[p], pt->g[i].have[p]);
        if (!s->partial++) {
            char k[sizeof pt->g[i].key];
            memcpy(k, pt->g[i].key, sizeof k);
            for (char *c = k; *c; c++)
                *c = *c == '\x1f' ? ' ' : *c;
            snprintf(s->partial_first, sizeof s->partial_first, "%.60s: %.90s", dir, k);
        }
    }
    s->partial += pt->lost;
    pt->n = 0;
    pt->lost = 0;
}

/* The Likert items by (condition, questionnaire, item): an open-addressed
 * table of RS_LIK_SLOTS (twice the items it may hold), O(1) a row. */
static unsigned lik_hash(int cond, const char *q, const char *item)
{
    unsigned h = 2166136261u ^ (unsigned)cond;
    for (const char *p = q; *p; p++)
        h = (h ^ (unsigned char)*p) * 16777619u;
    h = (h ^ 0x1f) * 16777619u;
    for (const char *p = item; *p; p++)
        h = (h ^ (unsigned char)*p) * 16777619u;
    return h;
}

static void add_likert(report_stats *s, int cond, const char *q, const char *item, double v)
{
    unsigned h = lik_hash(cond, q, item) % RS_LIK_SLOTS;
    int i;
    while ((i = s->slot[h]) >= 0) {
        const rs_likert *l = &s->lik[i];
        if (l->cond == cond && !strncmp(l->q, q, sizeof l->q - 1) &&
            !strncmp(l->item, item, sizeof l->item - 1))
            break;
        h = (h + 1) % RS_LIK_SLOTS;
    }
    if (i < 0) {
        if (s->nlik == s->caplik) {
            s->lik_dropped++; /* bounded: a warning names it */
            return;
        }
        i = s->slot[h] = s->nlik++;
        rs_likert *l = &s->lik[i];
        l->cond = cond;
        snprintf(l->q, sizeof l->q, "%s", q);
        snprintf(l->item, sizeof l->item, "%s", item);
        hol_stats_init(&l->s);
    }
    hol_stats_add(&s->lik[i].s, v);
}

/* The item of questionnaire q its attempt's level asks (level-HASH.txt
 * in the row's folder, read once for the rows that follow), NULL when
 * that level or the item is not at hand. */
static const hol_app_question *asked(report_run *r, rs_group *g, int dir, const char *q,
                                     const char *item)
{
    const char *sha = g->att >= 0 ? r->att[g->att].a.level_sha256 : "";
    if (!sha[0] || strchr(sha, '/') || !r->dirs)
        return NULL;
    if (g->level_dir != dir || strcmp(g->level_sha, sha)) {
        char path[4400];
        struct stat sb;
        uint8_t *data = NULL;
        size_t size = 0;
        hol_level_err le;
        g->level_dir = dir;
        snprintf(g->level_sha, sizeof g->level_sha, "%s", sha);
        snprintf(path, sizeof path, "%s/level-%s.txt", r->dirs[dir], sha);
        g->level_ok = !lstat(path, &sb) && S_ISREG(sb.st_mode) &&
                      !hol_file_read_all(path, HOL_LEVEL_TEXT_MAX + 1, &data, &size) &&
                      !hol_level_parse((const char *)data, size, &r->level.lvl, &le);
        free(data);
    }
    const hol_app_level *L = &r->level.lvl;
    for (int k = 0; g->level_ok && k < L->nasks; k++)
        for (int i = L->asks[k].first; !strcmp(L->asks[k].name, q) &&
                                        i < L->asks[k].first + L->asks[k].n; i++)
            if (i >= 0 && i < L->nquestions && !strcmp(L->questions[i].id, item))
                return &L->questions[i];
    return NULL;
}

/* A row of a questionnaire of the study's own against the item its level
 * asks (when at hand): the same kind, a Likert value on its marks. 0, or
 * -1 and c->err. */
static int level_item(report_run *r, rs_csv *c, rs_group *g, int likert, double v)
{
    const char *q = field(c, A_Q), *item = field(c, A_ITEM);
    if (hol_ask_preset_index(q, strlen(q)) >= 0)
        return 0; /* a preset's marks are its table's (report_instr_answer) */
    const hol_app_question *it = asked(r, g, c->dir, q, item);
    if (!it)
        return 0;
    if (likert != (it->kind == HOL_APP_LIKERT)) {
        snprintf(c->err, sizeof c->err, "column kind: its level asks %.40s's %.40s as a %s", q,
                 item, likert ? "choice" : "likert");
        return -1;
    }
    if (!likert || (v >= it->lo && v <= it->hi && ((long)v - it->lo) % it->step == 0))
        return 0;
    snprintf(c->err, sizeof c->err, "column value: '%.0f' is not one of %.40s's marks %d..%d "
             "(its level's question)", v, item, it->lo, it->hi);
    return -1;
}

/* A checked row (report_instr_answer) into its questionnaire: 0, or -1
 * and c->err when the questionnaire has its item already or its level
 * asks the item otherwise. */
static int answer_row(report_run *r, rs_csv *c, rs_group *g, rs_parts *pt, long att, int likert,
                      double v)
{
    report_stats *s = r->stats;
    char key[sizeof g->key];
    const char *q = field(c, A_Q), *item = field(c, A_ITEM);
    snprintf(key, sizeof key, "%s\x1f%s\x1f%ld\x1f%s\x1f%s", field(c, A_SESSION),
             field(c, A_PART), att, q, field(c, A_WHEN));
    if (strcmp(key, g->key)) {
        flush_group(s, g, pt);
        memcpy(g->key, key, sizeof key);
        g->att = find_att(r, c->dir, field(c, A_SESSION), att);
        g->cond = g->att < 0 ? s->none : s->att_cond[g->att];
        g->items.n = 0;
        take_partial(pt, g);
    }
    if (report_instr_item_new(&g->items, q, item, c->err) || level_item(r, c, g, likert, v))
        return -1;
    if (!likert)
        return 0;
    add_likert(s, g->cond, q, item, v);
    int p = hol_ask_preset_index(q, strlen(q));
    if (p < 0)
        add_score(s, g->key, g->cond, item, v, 1, 1);
    int k = hol_ask_preset_item(hol_ask_preset_at(p), item);
    if (k >= 0) {
        g->v[p][k] = v;
        g->have[p] |= 1u << k;
    }
    return 0;
}

/* answers.csv's rows (the file open in c->l): 0, or the exit status;
 * questionnaires answered in part wait in pt (parts_end). */
static int answers_rows(report_run *r, rs_csv *c, rs_parts *pt)
{
    static const char *const names[] = {"session", "participant", "attempt", "questionnaire",
                                        "when", "item", "kind", "value"};
    rs_group g;
    int got;
    memset(&g, 0, sizeof g);
    g.level_dir = -1;
    while ((got = next_row(c, names, 8, 8)) > 0) {
        long att;
        double v;
        if (!attempt_of(c, A_ATTEMPT, &att)) {
            got = -bad(c, "attempt is not a whole number (0 or more)");
            break;
        }
        if (report_instr_answer(field(c, A_Q), field(c, A_WHEN), field(c, A_ITEM),
                                field(c, A_KIND), field(c, A_VALUE), &v, c->err) ||
            answer_row(r, c, &g, pt, att, !strcmp(field(c, A_KIND), "likert"), v)) {
            got = -bad(c, c->err);
            break;
        }
    }
    flush_group(r->stats, &g, pt);
    parts_end(r->stats, r->dirs ? r->dirs[c->dir] : c->path, pt);
    return got < 0 ? -got : 0;
}

/* An instrument file open in c->l read (answers 1: answers.csv, else
 * points.csv), then closed. */
static int instrument(report_run *r, rs_csv *c, int answers)
{
    rs_parts *pt = answers ? calloc(1, sizeof *pt) : NULL;
    int st = !answers ? points_rows(r, c) : pt ? answers_rows(r, c, pt) : CLI_EXIT_FAIL;
    free(pt);
    hol_lines_close(&c->l);
    return st;
}

static int read_instrument(report_run *r, int d, rs_csv *c, const char *name)
{
    int o = open_csv(c, r, d, name);
    if (o)
        return o > 0 ? 0 : CLI_EXIT_USAGE;
    return instrument(r, c, !strcmp(name, "answers.csv"));
}

int report_stats_instrument(report_run *r, int d, const char *path, hol_lines *l)
{
    rs_csv *c = malloc(sizeof *c);
    if (!c) {
        hol_lines_close(l);
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    memset(c, 0, sizeof *c - sizeof c->buf);
    c->r = r;
    c->dir = d;
    c->l = *l;
    snprintf(c->path, sizeof c->path, "%s", path);
    const char *base = strrchr(path, '/');
    int st = instrument(r, c, !strcmp(base ? base + 1 : path, "answers.csv"));
    free(c);
    return st;
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
    int c = strcmp(a->participant, b->participant);
    if (!c)
        c = rs_cmp(a->cond, b->cond);
    return c ? c : rs_cmp(a->i, b->i);
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
        k[c].klass = !s->cond[c].study[0] ? 0 : s->cond[c].practice ? 0 : 2;
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
    size_t n = (size_t)r->natt + 1;
    if (!s || !(s->cond = malloc(sizeof *s->cond * n)) ||
        !(s->att_cond = malloc(sizeof *s->att_cond * n)) ||
        !(s->order = malloc(sizeof *s->order * n)) ||
        !(s->tpt = calloc(2 * n, sizeof *s->tpt)) ||
        !(s->fix = calloc(n * RS_NFIX, sizeof *s->fix)) ||
        !(s->lik = malloc(sizeof *s->lik * RS_LIK_MAX)) ||
        !(s->slot = malloc(sizeof *s->slot * RS_LIK_SLOTS)) ||
        !(s->pts = malloc(sizeof *s->pts * n)) || !(s->used = calloc(n, sizeof *s->used)) ||
        !(s->nrange = calloc(2 * n, sizeof *s->nrange))) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    s->caplik = RS_LIK_MAX;
    for (int i = 0; i < RS_LIK_SLOTS; i++)
        s->slot[i] = -1;
    return 0;
}

int report_stats_read(report_run *r)
{
    int st = alloc_stats(r);
    report_stats *s = r->stats;
    for (int i = 0; !st && i < r->natt; i++) {
        s->att_cond[i] = cond_of(s, &r->att[i].a);
        s->order[i] = i;
    }
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
    rs_csv *c = malloc(sizeof *c);
    st = c ? 0 : CLI_EXIT_FAIL;
    for (int d = 0; !st && d < r->ndirs; d++) {
        st = read_instrument(r, d, c, "points.csv");
        if (!st)
            st = read_instrument(r, d, c, "answers.csv");
    }
    free(c);
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
    fputs("study,condition,measure,item,n,mean,sd,ci_low,ci_high\n", f);
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
    const report_stats *s = r->stats;
    (void)ctx;
    fputs("study,condition,position,n,mean_efficiency,sd,ci_low,ci_high\n", f);
    for (int i = 0; i < s->nlearn; i++) {
        const rs_learn *l = &s->learn[i];
        report_csv(f, s->cond[l->cond].study, 0);
        report_csv(f, s->cond[l->cond].condition, 0);
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
    fputs("participant,study,condition,attempts,done,mean_steps,mean_efficiency,mean_time\n",
          f);
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

/* scores.csv: a row's key split (session, participant, attempt,
 * questionnaire, when); `after study` and `before study` under the
 * condition `study`. */
static int scores_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_stats *s = r->stats;
    (void)ctx;
    fputs("participant,session,attempt,study,condition,placement,scope,instrument,subscale,"
          "score,complete\n", f);
    for (long i = 0; i < s->nscore; i++) {
        const rs_score *o = &s->score[i];
        char k[sizeof o->key], *part[5] = {k, "", "", "", ""};
        memcpy(k, o->key, sizeof k);
        for (int j = 1; j < 5; j++) {
            char *sep = strchr(part[j - 1], '\x1f');
            if (!sep)
                break;
            *sep = 0;
            part[j] = sep + 1;
        }
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
        fprintf(f, ",%d\n", o->complete);
    }
    return 0;
}

int report_stats_write(const report_run *r)
{
    int st = report_write_file(r, "stats.csv", stats_csv, NULL);
    if (!st)
        st = report_write_file(r, "scores.csv", scores_csv, NULL);
    if (!st)
        st = report_write_file(r, "learning.csv", learning_csv, NULL);
    if (!st)
        st = report_write_file(r, "participants.csv", participants_csv, NULL);
    return st;
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
