/* report_stats.h - the statistics of `holonomy report` (docs/research.md
 * "Report"): stats.csv, learning.csv, participants.csv and the page's
 * statistics section, from the attempts and, when a log folder has them,
 * points.csv and answers.csv. Internal to the command.
 *
 * Contract
 * - report_stats_read (after report_read_summaries, before anything is
 *   written): each attempt's condition (a study's condition; outside a
 *   study the level), and every LOGDIR's points.csv and answers.csv when
 *   present (a missing one is no error; a malformed one is refused naming
 *   its file and line: exit 2, one line). The row's condition is its
 *   attempt's (session, attempt) in that folder's summary.csv; attempt 0
 *   or an attempt not in the summary: the condition "none". A row has
 *   the header's field count, and its values their documented ranges
 *   (report_instr.h); a questionnaire (its consecutive rows of one
 *   session, participant, attempt, name and when) no item twice; an item
 *   of the study's own as its attempt's level (level-HASH.txt, when
 *   there) asks it: the same kind, a Likert value on its marks.
 * - Means are over COMPLETED attempts (end "done") outside practice only
 *   (core/hol_stats.h: SD, 95 % t interval, n). Pointing errors: |error|
 *   in degrees, every answer with a bearing. SSQ and TLX: one score per
 *   complete questionnaire (all 16, all 6 items). Likert: every answer.
 * - Conditions are listed (every CSV, the page) by study in the order
 *   first seen; in a study practice first, then the order of the study
 *   file (a LOGDIR's study-HASH.txt naming the condition), then by name;
 *   outside a study in the order first seen; "none" last.
 * - report_stats_write writes the three CSVs atomically; report_stats_html
 *   writes the page's section into f. O(n log n) in the attempts.
 */
#ifndef REPORT_STATS_H
#define REPORT_STATS_H

#include <stddef.h>
#include <stdio.h>

#include "../../file/hol_lines.h"
#include "report.h"

int report_stats_read(report_run *r);
/* One instrument file (path ending in answers.csv, else points.csv),
 * open in *l, read into r->stats as report_stats_read reads LOGDIR d's
 * (report_stats_read has made r->stats); *l is closed. 0, or the exit
 * status after one line (fuzz/fuzz_report_instr.c). */
int report_stats_instrument(report_run *r, int d, const char *path, hol_lines *l);
int report_stats_write(const report_run *r);
void report_stats_html(FILE *f, const report_run *r);
void report_stats_free(report_run *r);
/* Sort g's conditions (as hol_report_agg_add finds them: first seen) into
 * the order of stats.csv (docs/research.md "Report": a study's practice,
 * its conditions in the study file's order, then the rest by name). 0, or
 * CLI_EXIT_FAIL out of memory (one line said). */
int report_stats_order_agg(const report_run *r, hol_report_agg *g);
/* LOGDIR d named from DIR (both resolved: "../logs"); "" when either
 * cannot be resolved. */
void report_rel_dir(const report_run *r, int d, char *out, size_t cap);

#endif
