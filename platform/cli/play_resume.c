/* play_resume.c - `play --resume` / `xr --resume`: a participant's study
 * continued where their logs say it stopped (see play_study.h). */
#include "play_study.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../../core/hol_ask.h"
#include "../../core/hol_report.h"
#include "../../core/hol_session.h"
#include "../../core/hol_sha256.h"
#include "../file/hol_lines.h"
#include "cli.h"
#include "summary_read.h"

#define RESUME_MAX_DONE 1024 /* done or timeout attempts of one participant */

/* A `done` or `timeout` attempt of theirs: which level of the order it
 * played (the first of its condition, position and text) and whether its
 * pointing answer is in points.csv. */
typedef struct resume_done {
    char session[HOL_REC_ID_MAX];
    long attempt;
    int level, pointed;
} resume_done;

/* What the folder holds of one participant in one study. */
typedef struct resume_rows {
    long rows;     /* summary rows and unfinished attempts of theirs */
    int ndone;
    resume_done d[RESUME_MAX_DONE];
    /* the attempt (index into d) marking each level of the order, -1 none:
     * each attempt whose level is over (done, timeout, its pointing
     * answered) marks the first unmarked level of its condition, position
     * and text (a condition may play one level file twice) */
    int by[HOL_SESSION_MAX_LEVELS];
    /* the marked level's items answered (answers.csv), counted over its
     * questionnaires in order */
    unsigned char answered[HOL_SESSION_MAX_LEVELS][HOL_APP_MAX_QUESTIONS];
    char bad[256]; /* a row the study given cannot have played ("" none) */
} resume_rows;

/* 1 when an attempt that ended so has its level over: the level's own
 * rules ended it (`done`, or `timeout` at its time limit). */
static int resume_finished(const char *end)
{
    return !strcmp(end, "done") || !strcmp(end, "timeout");
}

/* The first level of the order (the whole order) of this condition,
 * position and text; -1 when none. */
static int resume_level(const hol_level *levels, int n, const hol_report_attempt *a)
{
    for (int i = 0; i < n; i++) {
        char hex[HOL_SHA256_HEX];
        hol_sha256_hex(levels[i].sha256, hex);
        if (!strcmp(levels[i].condition, a->condition) && levels[i].position == a->position &&
            !strcmp(hex, a->level_sha256))
            return i;
    }
    return -1;
}

static void resume_add(resume_rows *r, const hol_level *levels, int n,
                       const hol_report_attempt *a, int is_row)
{
    r->rows++;
    int lv = resume_level(levels, n, a);
    if (!r->bad[0] && lv < 0)
        snprintf(r->bad, sizeof r->bad, "attempt %ld (condition %.60s, position %ld, level %.60s)",
                 a->attempt, a->condition, a->position, a->level);
    if (lv < 0 || !is_row || !resume_finished(a->end))
        return;
    if (r->ndone == RESUME_MAX_DONE) {
        r->ndone++; /* too many: refused */
        return;
    }
    if (r->ndone < RESUME_MAX_DONE) {
        resume_done *d = &r->d[r->ndone++];
        snprintf(d->session, sizeof d->session, "%.63s", a->session);
        d->attempt = a->attempt;
        d->level = lv;
        d->pointed = 0;
    }
}

/* What one reader of the rows looks for. */
typedef struct resume_ctx {
    const char *study, *participant;
    const hol_level *levels;
    int n, is_summary;
    resume_rows *r;
} resume_ctx;

/* A row of theirs added (summary_read's fn). */
static int resume_row(void *ctx, const hol_report_attempt *a, long line)
{
    resume_ctx *c = ctx;
    (void)line;
    if (!strcmp(a->study, c->study) && play_study_same_participant(a->participant, c->participant))
        resume_add(c->r, c->levels, c->n, a, c->is_summary);
    return 0;
}

/* An attempt-NNN.live: the summary header is given, then its one row (a
 * file the session wrote; one it could not finish is the recovery's). */
static int resume_live(const char *cmd, const char *path, resume_ctx *c)
{
    static const char header[] = HOL_SESSION_SUMMARY_COLUMNS;
    hol_lines l;
    int rc = cli_open_lines(cmd, "attempt", path, 65536, &l);
    if (rc)
        return rc;
    hol_report_header h;
    static hol_report_attempt a; /* 2.5 KB of text fields */
    char err[HOL_REPORT_ERR];
    int have_h = !hol_report_summary_header(header, sizeof header - 1, &h, err);
    char *s;
    size_t len;
    while (have_h && hol_lines_next(&l, &s, &len) > 0)
        if (!hol_report_summary_row(&h, s, len, &a, err))
            resume_row(c, &a, l.lineno);
    hol_lines_close(&l);
    return 0;
}

/* summary.csv (read as `report` reads it: summary_read.h), then the
 * attempts a killed session left (attempt-NNN.live: unfinished, whatever
 * the recovery will call them). */
static int resume_scan(const char *cmd, const char *dir, const char *study,
                       const char *participant, const hol_level *levels, int n, resume_rows *r)
{
    char path[4096];
    resume_ctx c = {study, participant, levels, n, 1, r};
    long cut = 0;
    int rc = snprintf(path, sizeof path, "%s/summary.csv", dir) < (int)sizeof path
                 ? summary_read(cmd, path, SUMMARY_NONE_OK, resume_row, &c, &cut)
                 : 0;
    c.is_summary = 0;
    DIR *d = rc ? NULL : opendir(dir);
    struct dirent *e;
    while (d && !rc && (e = readdir(d)) != NULL) {
        size_t k = strlen(e->d_name);
        if (strncmp(e->d_name, "attempt-", 8) || k < 13 || strcmp(e->d_name + k - 5, ".live") ||
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= (int)sizeof path)
            continue;
        rc = resume_live(cmd, path, &c);
    }
    if (d)
        closedir(d);
    return rc;
}

/* ---- points.csv and answers.csv: what was answered ---- */

enum { RC_SESSION, RC_PART, RC_ATTEMPT, RC_Q, RC_WHEN, RC_ITEM, RC_N };

/* The attempt of theirs (index into r->d) that session and attempt name;
 * -1 none. */
static int resume_find(const resume_rows *r, const char *session, const char *attempt)
{
    char *end;
    long a = strtol(attempt, &end, 10);
    if (!*attempt || *end)
        return -1;
    int nd = r->ndone < RESUME_MAX_DONE ? r->ndone : RESUME_MAX_DONE;
    for (int k = nd - 1; k >= 0; k--)
        if (r->d[k].attempt == a && !strcmp(r->d[k].session, session))
            return k;
    return -1;
}

/* An answers.csv row of attempt k: its item marked on the level k marks. */
static void resume_answer(resume_rows *r, const hol_level *levels, int n, int k,
                          const char *const *f)
{
    for (int i = 0; i < n; i++) {
        if (r->by[i] != k)
            continue;
        const hol_app_level *L = &levels[i].lvl;
        for (int q = 0, item = 0; q < L->nasks; q++)
            for (int j = 0; j < L->asks[q].n; j++, item++) {
                int w = L->asks[q].when;
                if (!strcmp(L->asks[q].name, f[RC_Q]) &&
                    !strcmp(hol_ask_when_name(w), f[RC_WHEN]) &&
                    !strcmp(L->questions[L->asks[q].first + j].id, f[RC_ITEM]) &&
                    item < HOL_APP_MAX_QUESTIONS)
                    r->answered[i][item] = 1;
            }
    }
}

/* The rows of points.csv (answers 0) or answers.csv (1) of this
 * participant: a pointing answer marks its attempt pointed, an answer its
 * item. A file not there has none; a row that cannot be read is not one
 * (report names it). */
static int resume_answers(const char *cmd, const char *dir, int answers, const char *participant,
                          const hol_level *levels, int n, resume_rows *r)
{
    static const char *const names[RC_N] = {"session", "participant", "attempt",
                                            "questionnaire", "when", "item"};
    char path[4096];
    struct stat st;
    if (snprintf(path, sizeof path, "%s/%s", dir, answers ? "answers.csv" : "points.csv") >=
            (int)sizeof path ||
        stat(path, &st) != 0)
        return 0;
    hol_lines l;
    int rc = cli_open_lines(cmd, "log", path, 65536, &l);
    if (rc)
        return rc;
    static char buf[65536];
    const char *f[64], *g[RC_N];
    int col[RC_N], nf, line = 0, ncol = answers ? RC_N : RC_Q;
    char err[HOL_REPORT_ERR], *s;
    size_t len;
    while (hol_lines_next(&l, &s, &len) > 0) {
        if (!line && len >= 3 && !memcmp(s, "\xef\xbb\xbf", 3)) { /* a byte order mark */
            s += 3;
            len -= 3;
        }
        if (hol_report_csv_split(s, len, buf, sizeof buf, f, 64, &nf, err))
            nf = 0; /* a row that cannot be read is none (report names it) */
        if (++line == 1) {
            for (int c = 0; c < ncol; c++) {
                col[c] = -1;
                for (int i = 0; i < nf; i++)
                    if (!strcmp(f[i], names[c]) && col[c] < 0)
                        col[c] = i;
            }
            continue;
        }
        int ok = 1;
        for (int c = 0; c < ncol; c++) {
            ok &= col[c] >= 0 && col[c] < nf;
            g[c] = ok ? f[col[c]] : "";
        }
        int k = ok && play_study_same_participant(g[RC_PART], participant)
                    ? resume_find(r, g[RC_SESSION], g[RC_ATTEMPT])
                    : -1;
        if (k >= 0 && !answers)
            r->d[k].pointed = 1;
        else if (k >= 0)
            resume_answer(r, levels, n, k, g);
    }
    hol_lines_close(&l);
    return 0;
}

/* Each level marked by the first attempt of its condition, position and
 * text whose level is over: done or timeout, and its pointing question (a
 * level with `point`) answered; a lost pointing answer leaves the level to
 * be played again (the question is about the walk just made). */
static void resume_mark(const hol_level *levels, int n, resume_rows *r)
{
    for (int i = 0; i < n; i++)
        r->by[i] = -1;
    for (int k = 0; k < r->ndone; k++) {
        const resume_done *d = &r->d[k];
        if (levels[d->level].lvl.point && !d->pointed)
            continue;
        const hol_level *m = &levels[d->level];
        for (int i = d->level; i < n; i++)
            if (r->by[i] < 0 && !strcmp(levels[i].condition, m->condition) &&
                levels[i].position == m->position &&
                !memcmp(levels[i].sha256, m->sha256, sizeof m->sha256)) {
                r->by[i] = k;
                break;
            }
    }
}

/* The first unanswered item of level i (0-based over its
 * questionnaires) but a `before` one's (its level is played: too late
 * for a baseline), or -1 when every one is answered. */
static int resume_unanswered(const hol_level *levels, int i, const resume_rows *r)
{
    const hol_app_level *L = &levels[i].lvl;
    for (int q = 0, item = 0; q < L->nasks; q++)
        for (int j = 0; j < L->asks[q].n; j++, item++)
            if (item < HOL_APP_MAX_QUESTIONS && !r->answered[i][item] &&
                !hol_ask_before(L->asks[q].when)) /* a baseline is not asked after its level */
                return item;
    return -1;
}

/* The first level of the order not finished: no attempt marks it, or its
 * questions are not all answered (*out_item: the first unanswered, else
 * -1). */
static int resume_first(const hol_level *levels, int n, const resume_rows *r, int *out_item)
{
    *out_item = -1;
    for (int i = 0; i < n; i++) {
        if (r->by[i] < 0)
            return i;
        if ((*out_item = resume_unanswered(levels, i, r)) >= 0)
            return i;
    }
    return n;
}

static char resume_note[256];
static hol_rec_meta resume_ask; /* ask_session, ask_attempt, ask_item */

/* Refusals before the levels are looked at: 2, else 0. */
static int resume_refused(const char *cmd, const char *log_dir, const char *study,
                          const char *participant, const resume_rows *r)
{
    if (!r->rows) {
        cli_error(cmd, 0, "participant %s has no data for study %s in '%s': nothing to resume "
                          "(start them without --resume)",
                  participant, study, log_dir);
        return CLI_EXIT_USAGE;
    }
    if (r->bad[0]) {
        cli_error(cmd, 0, "the study given is not the one participant %s played in '%s': their "
                          "%s is not in it; give that study file, or --restart-participant",
                  participant, log_dir, r->bad);
        return CLI_EXIT_USAGE;
    }
    if (r->ndone > RESUME_MAX_DONE) {
        cli_error(cmd, 0, "participant %s has more than %d finished attempts of study %s in "
                          "'%s': --restart-participant in another folder",
                  participant, RESUME_MAX_DONE, study, log_dir);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

int play_study_resume(const char *cmd, const char *log_dir, const char *study,
                      const char *participant, hol_level *levels, int *nlevels)
{
    static resume_rows r;
    memset(&r, 0, sizeof r);
    memset(&resume_ask, 0, sizeof resume_ask);
    resume_note[0] = 0;
    int n = *nlevels, rc = resume_scan(cmd, log_dir, study, participant, levels, n, &r);
    if (!rc)
        rc = resume_refused(cmd, log_dir, study, participant, &r);
    if (!rc)
        rc = resume_answers(cmd, log_dir, 0, participant, levels, n, &r);
    if (rc)
        return rc;
    resume_mark(levels, n, &r);
    if ((rc = resume_answers(cmd, log_dir, 1, participant, levels, n, &r)))
        return rc;
    int item, first = resume_first(levels, n, &r, &item);
    if (first == n) {
        cli_error(cmd, 0, "participant %s has finished study %s in '%s': nothing to resume",
                  participant, study, log_dir);
        return CLI_EXIT_USAGE;
    }
    if (item >= 0) {
        const resume_done *d = &r.d[r.by[first]];
        snprintf(resume_ask.ask_session, sizeof resume_ask.ask_session, "%s", d->session);
        resume_ask.ask_attempt = (int)d->attempt;
        resume_ask.ask_item = item + 1;
    }
    snprintf(resume_note, sizeof resume_note, "; resumed at %.60s (position %d), level %d of %d%s",
             levels[first].condition, levels[first].position, first + 1, n,
             item >= 0 ? ", its questions" : "");
    if (item >= 0)
        snprintf(resume_note + strlen(resume_note), sizeof resume_note - strlen(resume_note),
                 " from item %d (attempt %d)", item + 1, resume_ask.ask_attempt);
    if (first)
        memmove(levels, levels + first, (size_t)(n - first) * sizeof *levels);
    *nlevels = n - first;
    return 0;
}

const char *play_study_resume_note(void)
{
    return resume_note;
}

void play_study_resume_meta(hol_rec_meta *m)
{
    snprintf(m->ask_session, sizeof m->ask_session, "%s", resume_ask.ask_session);
    m->ask_attempt = resume_ask.ask_attempt;
    m->ask_item = resume_ask.ask_item;
    m->ready = resume_ask.ask_item == 0; /* a level played: the ready screen first */
}
