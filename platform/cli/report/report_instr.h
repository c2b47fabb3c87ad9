/* report_instr.h - the values of points.csv and answers.csv as `holonomy
 * report` takes them (docs/report.md "Statistics"): the documented ranges
 * and nothing else; report_stats.c reads the files and asks these, and
 * fuzz/fuzz_report_instr.c reaches both through report_stats_instrument.
 *
 * Contract
 * - report_instr_whole: s is a whole number in decimal (an optional '-',
 *   1..18 digits, nothing else) within lo..hi: 1 and *out; else 0.
 * - report_instr_point: a points.csv row's error_true and error_flat (each
 *   empty, or a decimal number, [-]D[.D], in (-180, 180]: has[k] 0 or 1,
 *   e[k]) and its bearings pointed, true and flat (each NULL for a column
 *   the file lacks, empty, or a decimal number in [0, 360)): 0, else -1
 *   with a message naming the column in err (HOL_REPORT_ERR bytes).
 * - report_instr_answer: an answers.csv row: questionnaire and item IDs
 *   (hol_ask_id_ok), when `level`, `condition`, `study` or one of them
 *   with `before_` (hol_ask_when), kind `likert`
 *   or `choice`; a preset's (ssq, tlx: core/hol_ask.h) item is one of its
 *   own and a likert whose value is one of its marks (lo..hi in its
 *   step); another likert's value a whole number in 0..100 (where every
 *   scale's marks lie). 0 (*out_v the likert's value), else -1 and err.
 * - report_instr_items: one questionnaire's items as its rows come (a
 *   set, REPORT_INSTR_ITEMS of them): report_instr_item_new adds item,
 *   0; -1 and err when the questionnaire has it already or is full.
 * - Pure: no I/O, no allocation, no globals.
 */
#ifndef REPORT_INSTR_H
#define REPORT_INSTR_H

#include "../../../core/hol_app.h"

#define REPORT_INSTR_ITEMS HOL_APP_MAX_QUESTIONS /* a questionnaire's, at most */

int report_instr_whole(const char *s, long lo, long hi, long *out);
int report_instr_point(const char *err_true, const char *err_flat, const char *const bear[3],
                       int has[2], double e[2], char *err);
int report_instr_answer(const char *q, const char *when, const char *item, const char *kind,
                        const char *value, double *out_v, char *err);

typedef struct report_instr_items {
    int n;
    char id[REPORT_INSTR_ITEMS][HOL_APP_ID_MAX];
} report_instr_items;

int report_instr_item_new(report_instr_items *s, const char *q, const char *item, char *err);

#endif
