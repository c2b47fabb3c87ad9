/* hol_report.h - reading research logs back (docs/research.md: summary.csv
 * and steps-NNN.csv) for `holonomy report`: one CSV line at a time, by
 * column name, into fixed structs; and per-condition means.
 *
 * Contract
 * - Lines come from the platform's bounded line reader (no LF, no CR; at
 *   most HOL_REPORT_LINE_MAX bytes, longer is HOL_ENOMEM); a
 *   line is one record (the logs never hold a raw newline in a field: names
 *   are escaped before they are quoted). Fields follow RFC 4180: a field is
 *   either bare (no double quote in it) or enclosed in double quotes with
 *   inner quotes doubled; anything else is bad input.
 * - A header line names the columns; columns are found by name, so added
 *   columns (any order) are ignored and missing optional ones take their
 *   defaults: participant, study, condition, position, cues, session_no
 *   empty; tiling 4,5,
 *   room 3x3, cell 1 (the geometry columns come from newer logs).
 *   Required: summary session, attempt, level, mode, steps, optimum, time,
 *   end; steps session, attempt, step, col, row, dir, tile, orient.
 * - Errors: HOL_EPARSE (not CSV, a missing required column, a bad number
 *   or word), HOL_ENOMEM (a field longer than its struct holds, more than
 *   HOL_REPORT_MAX_COLS fields); *err gets a message naming the column.
 *   Outputs are untouched on error.
 * - Pure: no I/O, no allocation, no globals.
 */
#ifndef HOL_REPORT_H
#define HOL_REPORT_H

#include <stddef.h>

#include "hol_err.h"

#define HOL_REPORT_MAX_COLS 256
#define HOL_REPORT_LINE_MAX 65536 /* bytes of one line (docs/research.md) */
#define HOL_REPORT_TEXT 256   /* a text field with its NUL */
#define HOL_REPORT_ERR 160

/* Column positions by name: -1 when absent. */
typedef struct hol_report_header {
    int ncols;
    int col[24];
} hol_report_header;

/* One summary row. */
typedef struct hol_report_attempt {
    char session[HOL_REPORT_TEXT], participant[HOL_REPORT_TEXT];
    char study[HOL_REPORT_TEXT], condition[HOL_REPORT_TEXT];
    char level[HOL_REPORT_TEXT], level_sha256[HOL_REPORT_TEXT];
    char mode[HOL_REPORT_TEXT], end[HOL_REPORT_TEXT];
    long attempt;
    long position;     /* -1: empty (outside a study) */
    long cues;         /* column `cues` (bits, 0..65535); -1: absent or empty */
    long session_no;   /* column `session_no` (1..999); -1: absent or empty */
    long steps, optimum; /* optimum -1: not scored */
    double time_s;
    int tiling_q;      /* 4..8 (column `tiling`, "4,Q"; default 5) */
    int room_cols, room_rows; /* column `room`, "CxR"; default 3x3 */
    double cell_m;     /* column `cell`; default 1 */
} hol_report_attempt;

/* One steps row. */
typedef struct hol_report_step {
    char session[HOL_REPORT_TEXT];
    long attempt, step;
    int col, row, dir;  /* dir: HOL_DIR_* */
    char tile[HOL_REPORT_TEXT];
    int orient;
} hol_report_step;

/* Split one CSV line into at most max fields, unquoted into buf (cap
 * bytes; each field NUL-terminated there): *out_n fields at f[i]. */
hol_err hol_report_csv_split(const char *s, size_t len, char *buf, size_t cap,
                             const char **f, int max, int *out_n, char *err);

hol_err hol_report_summary_header(const char *s, size_t len, hol_report_header *out,
                                  char *err);
hol_err hol_report_summary_row(const hol_report_header *h, const char *s, size_t len,
                               hol_report_attempt *out, char *err);
hol_err hol_report_steps_header(const char *s, size_t len, hol_report_header *out,
                                char *err);
hol_err hol_report_step_row(const hol_report_header *h, const char *s, size_t len,
                            hol_report_step *out, char *err);

/* optimum / steps for a completed scored attempt (end "done", optimum >= 0,
 * steps > 0; 1 when both are 0); -1 otherwise (not defined). */
double hol_report_efficiency(const hol_report_attempt *a);

/* A text field read from a log made safe for a CSV a person may `cat` and
 * for a page, as the app's writers make names (core/hol_text.h): what a
 * terminal acts on (C0, DEL, C1, U+2028/9, bidi controls) and bad UTF-8 as
 * \xHH per byte. A backslash is kept as it is: the logs' texts are already
 * escaped (a name's backslash is there as \\), so escaping it again would
 * double it. Same return and cut rules as hol_text_escape: the length the
 * whole result needs; out always NUL-terminated when cap > 0. */
size_t hol_report_clean(const char *s, char *out, size_t cap);

/* Per-condition means: conditions are (study, condition) pairs; outside a
 * study the condition is the level's name. The table is the caller's
 * (hol_report_agg_init: cap entries); a condition beyond it is counted in
 * overflow, never dropped silently (the caller refuses: one line). */
typedef struct hol_report_cond {
    char study[HOL_REPORT_TEXT], condition[HOL_REPORT_TEXT];
    long n, done;        /* attempts, completed ones */
    long neff;           /* attempts with an efficiency */
    double steps, eff, time_s; /* sums: steps and time over all, eff over neff */
} hol_report_cond;

typedef struct hol_report_agg {
    int n, cap;
    long overflow;       /* attempts of conditions beyond the table */
    hol_report_cond *c;
} hol_report_agg;

void hol_report_agg_init(hol_report_agg *g, hol_report_cond *conds, int cap);
void hol_report_agg_add(hol_report_agg *g, const hol_report_attempt *a);

#endif
