/* report.h - the parts of `holonomy report`, the report module of the tool
 * (this folder; cmd_report.c, the command, runs them). Each file has one job:
 *   report_read.c        log folders read back (summaries, steps, levels)
 *   report_write.c       the report's files: attempts.csv, conditions.csv,
 *                        index.html
 *   report_file.c        report_write_file: every file of the report
 *                        written atomically (the writers are its bodies)
 *   report_stats*.c      the statistics (report_stats.h): stats.csv,
 *                        learning.csv, participants.csv, the page's section
 *   report_draw.c        an attempt's picture (report_draw.h)
 *   report_escape.c      the one CSV field and HTML text writer
 *                        (report_escape.h; test_report_escape)
 *   report_bids.c        --bids DIR: the tracks as BIDS-Motion
 *                        (report_bids.h; tests/cli_report_bids.sh)
 *   report_ids.c         participant ids read in their one spelling
 * The module keeps no file-scope mutable state: what a run holds is in its
 * report_run (and the command's buffers), passed down. Internal to the
 * command.
 *
 * Contract
 * - report_read_summaries reads every LOGDIR's summary.csv (streamed,
 *   bounded lines; the reader --resume uses, ../summary_read.h) into r->att; report_walk reads one attempt's
 *   steps-NNN.csv into tiles; report_optimal re-parses the attempt's level
 *   (level-HASH.txt) and gives the optimal walk's tiles from its start.
 *   Each returns 0 or the exit status after one line on stderr naming the
 *   file and line (bad input 2, failure 1); a missing steps or level file
 *   is not an error: a warning line, and the attempt has no walk (has_* 0).
 * - report_write_* write DIR's files atomically (platform/file), each
 *   through report_write_file: DIR/name written by body (its 0, or an exit
 *   status after one line: the file is then left out), committed; 0, or
 *   CLI_EXIT_FAIL after one line when it cannot be opened or written.
 * - report_ids_read (after report_read_summaries): every attempt's
 *   participant in its one spelling (hol_study_participant_id: "2", "002"
 *   and "p2" are "P02"), the logs' spelling kept (report_id_logged).
 *   report_ids_tell (once every log file is checked) says one line on
 *   stderr for each participant spelled two or more ways (a merge) and one
 *   for the ids only respelled; 0, or CLI_EXIT_FAIL.
 */
#ifndef REPORT_H
#define REPORT_H

#include <stddef.h>
#include <stdio.h>

#include "../../../core/hol_level.h"
#include "../../../core/hol_nav.h"
#include "../../../core/hol_rec.h"
#include "../../../core/hol_report.h"
#include "../../../core/hol_room.h"

#define REPORT_MAX_ATTEMPTS 10000
#define REPORT_MAX_STEPS 1000000 /* rows of one steps file */
#define REPORT_LINE_MAX 65536
#define REPORT_PNG_SIZE 480

typedef struct report_att {
    hol_report_attempt a;
    int dir;          /* index of its LOGDIR */
    int has_walk;     /* its steps file was read */
    int has_optimal;  /* its level gave an optimal walk */
    int optimal_len;
    int minimap;      /* its level's minimap place (hol_app_minimap_place), -1: unknown */
    char png[32];     /* its picture's name in DIR, "" for none */
    char spelled[HOL_REC_ID_MAX]; /* the participant as logged when a.participant
                                     is its respelling (report_ids_read), else "" */
} report_att;

/* A level's objectives and optimal walk in one geometry, computed once
 * (report_optimal; REPORT_OPT_CACHE of them, the oldest replaced). */
#define REPORT_OPT_CACHE 16
typedef struct report_opt {
    char sha[HOL_REPORT_TEXT]; /* "" for none */
    int q, cols, rows;
    hol_room start;
    hol_tile goals[HOL_APP_MAX_OBJECTIVES];
    int ngoals, chest_last;
    int minimap;               /* the level's minimap place, -1: unread */
    int has_optimal, optimal_len;
    int nwalk;
    hol_tile walk[HOL_NAV_WALK_MAX]; /* last: not cleared */
} report_opt;

typedef struct report_run {
    const char *cmd;
    char **dirs;
    int ndirs;
    const char *out;
    const char *bids;  /* --bids DIR, NULL without */
    report_att *att;
    int natt;
    /* navigators by geometry, made on first use */
    hol_nav *nav[6];
    int nav_key[6];
    int nnav;
    hol_level level;   /* scratch */
    report_opt *opt;   /* REPORT_OPT_CACHE entries, made on first use */
    int nopt, nopt_next;
    int quiet;         /* 1: warnings were given (the second pass) */
    int include_restarted; /* --include-restarted: duplicate and restarted
                              trials count in the participant-level statistics */
    struct report_stats *stats; /* report_stats.h */
    struct report_pstats *pstats; /* report_pstats.h */
} report_run;

int report_read_summaries(report_run *r);
/* tiles: REPORT_MAX_STEPS entries (NULL: only check the file). */
int report_walk(report_run *r, report_att *t, hol_tile *tiles, int *out_n);
/* 0, or after SIGINT, SIGTERM or SIGHUP (cli_catch_signals) 128+N with one
 * line on stderr: every loop of the command asks, so it stops within 1 s. */
int report_stopped(const report_run *r);
/* The level's start state and objectives, and the optimal walk's tiles
 * (walk: HOL_NAV_WALK_MAX entries). */
int report_optimal(report_run *r, report_att *t, hol_room *out_start, hol_tile *goals,
                   int *ngoals, int *chest_last, hol_tile *walk, int *nwalk);
void report_free(report_run *r);
void report_ids_read(report_run *r);
int report_ids_tell(const report_run *r);
/* The participant of attempt t as its log spells it. */
const char *report_id_logged(const report_att *t);

typedef int (*report_body)(FILE *f, const report_run *r, const void *ctx);
int report_write_file(const report_run *r, const char *name, report_body body, const void *ctx);
/* Files written in turn by report_write_file (no ctx) until one fails. */
typedef struct report_file_job {
    const char *name;
    report_body body;
} report_file_job;
int report_write_files(const report_run *r, const report_file_job *jobs, int n);
/* The header of the report's file NAME (its codebook rows' columns,
 * codebook_table.h: the codebook and the file say the same columns). */
void report_header(FILE *f, const char *name);
/* The same into dir/name (name may hold folders that exist: --bids). */
int report_write_in(const report_run *r, const char *dir, const char *name, report_body body,
                    const void *ctx);

int report_write_csv(const report_run *r);
/* `holonomy report --class DIR --out OUT` (report_class.c): argv[1] is
 * "--class". */
int report_class_main(const char *cmd, int argc, char **argv);
/* build.csv (which build wrote the report: program, version, commit,
 * build_date) and codebook.csv (every column of the report's files:
 * ../codebook.h). */
int report_write_provenance(const report_run *r);
int report_write_conditions(const report_run *r, const hol_report_agg *g);
int report_write_html(const report_run *r, const hol_report_agg *g);

#endif
