/* play_study.c - a study's levels for play and xr (see play_study.h). */
#include "play_study.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_report.h"
#include "../../core/hol_study.h"
#include "../shell/hol_shell_prov.h"
#include "cli.h"
#include "play_prov.h"
#include "summary_read.h"

/* The participant's number, or 0 after the message. */
static uint64_t study_number(const char *cmd, const char *participant)
{
    uint64_t p = participant ? hol_study_participant_number(participant) : 0;
    if (!p)
        cli_error(cmd, 0, "--study needs --participant ID ending in the participant's number "
                          "(P07, 12: 1..1000000000)");
    return p;
}

/* PATH of a level, relative to the study file's folder unless absolute. */
static int study_path(const char *study, const char *level, char *out, size_t cap)
{
    const char *slash = strrchr(study, '/');
    int n = level[0] == '/' || !slash
                ? snprintf(out, cap, "%s", level)
                : snprintf(out, cap, "%.*s/%s", (int)(slash - study), study, level);
    return n < 0 || (size_t)n >= cap;
}

/* Level i of the study, labelled with position pos, into *out. */
static int study_level(const char *cmd, const char *spath, const hol_study *s, int i, int pos,
                       const cli_outs *outs, hol_level *out)
{
    char rel[HOL_STUDY_PATH_MAX], path[4096], name[64] = "", msg[256];
    uint8_t *data = NULL;
    size_t size = 0;
    hol_study_level_path(s, i, rel);
    if (rel[0]) {
        if (study_path(spath, rel, path, sizeof path)) {
            cli_error(cmd, 0, "%.200s: line %ld: the level's path is too long", spath,
                      s->levels[i].line);
            return CLI_EXIT_USAGE;
        }
        const cli_path in = {"the study's level", path};
        int rs = cli_check_reads(cmd, &in, 1, outs);
        if (!rs)
            rs = cli_read_file(cmd, "level", path, HOL_LEVEL_TEXT_MAX, &data, &size);
        if (rs)
            return rs;
        const char *base = strrchr(path, '/');
        base = base ? base + 1 : path;
        size_t bl = strcspn(base, ".");
        snprintf(name, sizeof name, "%.*s", (int)(bl ? (bl < 60 ? bl : 60) : 60), base);
    }
    hol_level_err le;
    int in_study = 0;
    hol_err e = hol_study_make_level(s, i, pos, (const char *)data, size, name[0] ? name : NULL,
                                     out, &le, &in_study);
    free(data);
    if (e) {
        int c = hol_study_level_condition(s, i);
        hol_level_err_format(&le, 1, msg, sizeof msg);
        if (in_study || !rel[0])
            cli_error(cmd, 0, "%.200s: %s", spath, msg);
        else
            cli_error(cmd, 0, "%.200s: %s (condition %s of %.100s)", path, msg,
                      c < 0 ? HOL_STUDY_PRACTICE : s->conditions[c].name, spath);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

/* The order line, held until play_study_announce ("" when none). */
static char study_line[2048];

/* "hud, hand, none" */
static void study_tell(const char *cmd, const hol_study *s, const char *participant,
                       uint64_t p, const int *order)
{
    uint64_t rows = hol_study_rows(s->rule, s->nconditions);
    size_t cap = sizeof study_line, n;
    snprintf(study_line, cap, "holonomy %s: study %s, participant %s (number %llu, order %llu of %llu):",
             cmd, s->name, participant, (unsigned long long)p,
             (unsigned long long)((p - 1) % rows + 1), (unsigned long long)rows);
    if (s->npractice && (n = strlen(study_line)) < cap)
        snprintf(study_line + n, cap - n, " practice,");
    for (int k = 0; k < s->nconditions; k++)
        if ((n = strlen(study_line)) < cap)
            snprintf(study_line + n, cap - n, " %s%s", s->conditions[order[k]].name,
                     k + 1 < s->nconditions ? "," : "");
}

void play_study_announce(void)
{
    if (study_line[0])
        fprintf(stderr, "%s%s\n", study_line, play_study_resume_note());
    study_line[0] = 0;
}

/* order.csv's rows for the session (play_prov.h): the whole order, every
 * position with its condition and level file (the played text's hash is
 * added once the geometry options made the text: play_geometry_apply). */
static void study_hold_order(const hol_study *s, const char *participant, const int *lv,
                             const hol_level *levels, int n)
{
    static char rows[64 * 1024];
    if (!hol_shell_order_rows(s, participant, lv, levels, n, rows, sizeof rows))
        play_prov_hold_order(rows, levels, n);
}

int play_study_levels(const char *cmd, const char *path, const char *participant,
                      const char *fresh_in, const cli_outs *outs, hol_level *levels,
                      int *nlevels, char study_name[HOL_REC_ID_MAX])
{
    static hol_study s;
    *nlevels = 0;
    study_line[0] = 0;
    uint64_t p = study_number(cmd, participant);
    if (!p)
        return CLI_EXIT_USAGE;
    uint8_t *data = NULL;
    size_t size = 0;
    int st = cli_read_file(cmd, "study", path, HOL_STUDY_TEXT_MAX, &data, &size);
    if (st)
        return st;
    hol_level_err le;
    hol_err e = hol_study_parse((const char *)data, size, &s, &le);
    free(data);
    if (e) {
        char msg[256];
        cli_error(cmd, 0, "%.200s: %s", path, hol_level_err_format(&le, 1, msg, sizeof msg));
        return CLI_EXIT_USAGE;
    }
    int order[HOL_STUDY_MAX_CONDITIONS], lv[HOL_STUDY_MAX_LEVELS], cond[HOL_STUDY_MAX_LEVELS],
        pos[HOL_STUDY_MAX_LEVELS];
    hol_study_order(&s, p, order);
    int n = hol_study_session(&s, order, lv, cond, pos);
    for (int i = 0; i < n; i++)
        if ((st = study_level(cmd, path, &s, lv[i], pos[i], outs, &levels[i])))
            return st;
    if (fresh_in && (st = play_study_participant_new(cmd, fresh_in, s.name, participant)))
        return st;
    *nlevels = n;
    snprintf(study_name, HOL_REC_ID_MAX, "%s", s.name);
    study_tell(cmd, &s, participant, p, order);
    study_hold_order(&s, participant, lv, levels, n);
    return 0;
}

int play_study_same_participant(const char *logged, const char *id)
{
    char spelled[HOL_REC_ID_MAX];
    if (!strcmp(logged, id))
        return 1;
    return hol_study_participant_id(logged, spelled, sizeof spelled) == HOL_STUDY_ID_RENAMED &&
           !strcmp(spelled, id);
}

/* A row of the study and participant counted (summary_read's fn). */
typedef struct study_rows {
    const char *study, *participant;
    long rows;
} study_rows;

static int study_row(void *ctx, const hol_report_attempt *a, long line)
{
    study_rows *c = ctx;
    (void)line;
    c->rows += !strcmp(a->study, c->study) && play_study_same_participant(a->participant, c->participant);
    return 0;
}

int play_study_participant_new(const char *cmd, const char *log_dir, const char *study_name,
                               const char *participant)
{
    char path[4096];
    if (!log_dir || !participant ||
        snprintf(path, sizeof path, "%s/summary.csv", log_dir) >= (int)sizeof path)
        return 0;
    /* read as `report` and --resume read it (summary_read.h) */
    study_rows c = {study_name, participant, 0};
    long cut = 0;
    int rc = summary_read(cmd, path, SUMMARY_NONE_OK, study_row, &c, &cut);
    if (rc)
        return rc;
    long rows = c.rows;
    if (!rows)
        return 0;
    cli_error(cmd, 0,
              "participant %s already has data for study %s in '%s' (%ld attempt%s); "
              "--restart-participant plays their order again from the start, --resume "
              "continues it",
              participant, study_name, log_dir, rows, rows == 1 ? "" : "s");
    return CLI_EXIT_USAGE;
}
