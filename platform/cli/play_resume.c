/* play_resume.c - `play --resume` / `xr --resume`: a participant's study
 * continued where their logs say it stopped (see play_study.h). */
#include "play_study.h"

#include <dirent.h>
#include <stdio.h>
#include <string.h>

#include "../../core/hol_report.h"
#include "../../core/hol_session.h"
#include "../../core/hol_sha256.h"
#include "../file/hol_lines.h"
#include "cli.h"
#include "summary_read.h"

/* What the folder holds of one participant in one study. */
typedef struct resume_rows {
    long rows;     /* summary rows and unfinished attempts of theirs */
    /* levels of the order with a finished attempt (done, timeout): each
     * finished attempt marks the first unmarked level of its condition,
     * position and text (a condition may play one level file twice) */
    int done[HOL_SESSION_MAX_LEVELS];
    char bad[256]; /* a row the study given cannot have played ("" none) */
} resume_rows;

/* 1 when an attempt that ended so has its level finished: the level's own
 * rules ended it (`done`, or `timeout` at its time limit). */
static int resume_finished(const char *end)
{
    return !strcmp(end, "done") || !strcmp(end, "timeout");
}

/* The first level of the order (the whole order) of this condition,
 * position and text not yet marked in done
 * (done NULL: any); -1 when none. */
static int resume_level(const hol_level *levels, int n, const hol_report_attempt *a,
                        const int *done)
{
    for (int i = 0; i < n; i++) {
        char hex[HOL_SHA256_HEX];
        hol_sha256_hex(levels[i].sha256, hex);
        if ((!done || !done[i]) && !strcmp(levels[i].condition, a->condition) &&
            levels[i].position == a->position && !strcmp(hex, a->level_sha256))
            return i;
    }
    return -1;
}

static void resume_add(resume_rows *r, const hol_level *levels, int n,
                       const hol_report_attempt *a, int is_row)
{
    r->rows++;
    if (!r->bad[0] && resume_level(levels, n, a, NULL) < 0)
        snprintf(r->bad, sizeof r->bad, "attempt %ld (condition %.60s, position %ld, level %.60s)",
                 a->attempt, a->condition, a->position, a->level);
    int i = is_row && resume_finished(a->end) ? resume_level(levels, n, a, r->done) : -1;
    if (i >= 0)
        r->done[i] = 1;
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
    if (!strcmp(a->study, c->study) && !strcmp(a->participant, c->participant))
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

/* The first level of the order without a finished attempt. */
static int resume_first(int n, const resume_rows *r)
{
    int i = 0;
    while (i < n && r->done[i])
        i++;
    return i;
}

static char resume_note[256];

int play_study_resume(const char *cmd, const char *log_dir, const char *study,
                      const char *participant, hol_level *levels, int *nlevels)
{
    static resume_rows r;
    memset(&r, 0, sizeof r);
    resume_note[0] = 0;
    int n = *nlevels, rc = resume_scan(cmd, log_dir, study, participant, levels, n, &r);
    if (rc)
        return rc;
    if (!r.rows) {
        cli_error(cmd, 0, "participant %s has no data for study %s in '%s': nothing to resume "
                          "(start them without --resume)",
                  participant, study, log_dir);
        return CLI_EXIT_USAGE;
    }
    if (r.bad[0]) {
        cli_error(cmd, 0, "the study given is not the one participant %s played in '%s': their "
                          "%s is not in it; give that study file, or --restart-participant",
                  participant, log_dir, r.bad);
        return CLI_EXIT_USAGE;
    }
    int first = resume_first(n, &r);
    if (first == n) {
        cli_error(cmd, 0, "participant %s has finished study %s in '%s': nothing to resume",
                  participant, study, log_dir);
        return CLI_EXIT_USAGE;
    }
    snprintf(resume_note, sizeof resume_note,
             "; resumed at %.60s (position %d), level %d of %d", levels[first].condition,
             levels[first].position, first + 1, n);
    if (first)
        memmove(levels, levels + first, (size_t)(n - first) * sizeof *levels);
    *nlevels = n - first;
    return 0;
}

const char *play_study_resume_note(void)
{
    return resume_note;
}
