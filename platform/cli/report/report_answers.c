/* report_answers.c - the report's instruments read back (report_stats.h,
 * report_stats_impl.h): points.csv and answers.csv of every LOGDIR, by
 * column name, each row checked against its header and its documented
 * ranges, the questionnaires grouped and scored, the Likert items kept. */
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
    int cond, att;
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
    k->att = g->att;
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
typedef struct rs_at { /* what a score is of */
    const char *key;
    int cond, att;
} rs_at;
static void add_score(report_stats *s, rs_at g, const char *sub, double v, int has, int complete)
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
    snprintf(o->key, sizeof o->key, "%s", g.key);
    o->cond = g.cond;
    o->att = g.att;
    snprintf(o->sub, sizeof o->sub, "%s", sub);
    o->v = v;
    o->has = has;
    o->complete = complete;
}

/* Preset p's rows of scores.csv: its scores (empty when answered in
 * part), and for a preset of one score (tlx: raw) each item's answer. */
static void preset_scores(report_stats *s, rs_at g, const hol_ask_preset_def *p,
                          const double *v, unsigned have)
{
    int complete = have == (1u << p->nitems) - 1;
    double sc[HOL_ASK_PRESET_SCORES] = {0};
    if (complete)
        hol_ask_score(p, v, sc);
    for (int k = 0; k < p->nscores; k++)
        add_score(s, g, p->scores[k].name, sc[k], complete, complete);
    for (int j = 0; p->nscores == 1 && j < p->nitems; j++)
        add_score(s, g, p->items[j].id, v[j], (have >> j) & 1, complete);
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
            preset_scores(s, (rs_at){g->key, g->cond, g->att}, p, g->v[i], g->have[i]);
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
                preset_scores(s, (rs_at){pt->g[i].key, pt->g[i].cond, pt->g[i].att},
                              hol_ask_preset_at(p), pt->g[i].v[p], pt->g[i].have[p]);
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
    char key[sizeof g->key], part[HOL_REC_ID_MAX];
    const char *q = field(c, A_Q), *item = field(c, A_ITEM), *who = field(c, A_PART);
    if (hol_study_participant_id(who, part, sizeof part) == HOL_STUDY_ID_RENAMED)
        who = part; /* in its one spelling, as the summary's (report_ids_read) */
    snprintf(key, sizeof key, "%s\x1f%s\x1f%ld\x1f%s\x1f%s", field(c, A_SESSION), who, att, q,
             field(c, A_WHEN));
    if (strcmp(key, g->key)) {
        flush_group(s, g, pt);
        memcpy(g->key, key, sizeof key);
        g->att = find_att(r, c->dir, field(c, A_SESSION), att);
        g->cond = rs_when_cond(s, g->att < 0 ? s->none : s->att_cond[g->att], field(c, A_WHEN));
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
        add_score(s, (rs_at){g->key, g->cond, g->att}, item, v, 1, 1);
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


int rs_read_instruments(report_run *r)
{
    rs_csv *c = malloc(sizeof *c);
    int st = c ? 0 : CLI_EXIT_FAIL;
    for (int d = 0; !st && d < r->ndirs; d++) {
        st = read_instrument(r, d, c, "points.csv");
        if (!st)
            st = read_instrument(r, d, c, "answers.csv");
    }
    free(c);
    return st;
}

int report_stats_read(report_run *r)
{
    int st = rs_read_trials(r);
    return st ? st : rs_read_done(r, rs_read_instruments(r));
}
