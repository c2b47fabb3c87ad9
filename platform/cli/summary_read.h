/* summary_read.h - a log folder's summary.csv read back the one way every
 * reader of it reads it: `holonomy report` (report/report_read.c),
 * `play --resume` and `xr --resume` (play_resume.c) and the participant
 * check of --append (play_study.c), so that a damaged summary gets the same
 * answer from each (issue 39, finding 15).
 *
 * Contract
 * - summary_read(cmd, path, flags, fn, ctx, &cut) reads path (DIR/summary.csv)
 *   a line at a time (at most SUMMARY_LINE_MAX bytes a line; one CR
 *   before a line's LF dropped, platform/file/hol_lines.h): a UTF-8 byte
 *   order mark at the file's start is skipped, and so is a blank line
 *   (empty, or only spaces and tabs) wherever it stands; the first other
 *   line is the header (core/hol_report.h), every line after it a row,
 *   given in order to fn(ctx, row, line): fn returns 0 to go on, or an
 *   exit status after its own one line on stderr, which ends the read.
 * - A last line without its LF is a row a kill cut (the next --append
 *   session's recovery removes it): it is left out, and *out_cut gets its
 *   line number (0: none), for the caller to say so.
 * - Refused with one line on stderr naming the file (and the line) and
 *   exit 2: a symbolic link (even to a regular file: it is neither
 *   followed nor written through), a name that is not a regular file, a
 *   file with no header, a header or row that is not the logs' (not RFC
 *   4180, a missing column, a bad number, a NUL byte, a field count other
 *   than the header's), a line longer than SUMMARY_LINE_MAX. A read failure
 *   is exit 1 after one line.
 * - flags SUMMARY_NONE_OK: a missing file, or one with no whole line (a
 *   first session killed before its header reached the disk), is 0 with
 *   no rows; without it they are refused (exit 2).
 * - No state of its own: one hol_lines reader open during the call.
 */
#ifndef HOL_SUMMARY_READ_H
#define HOL_SUMMARY_READ_H

#include "../../core/hol_report.h"
#include "../file/hol_lines.h"

#define SUMMARY_LINE_MAX 65536
#define SUMMARY_NONE_OK 1

typedef int (*summary_row_fn)(void *ctx, const hol_report_attempt *row, long line);

/* The log readers' line rules, for the report's other CSV readers too:
 * summary_csv_line drops a byte order mark at the file's start from *s
 * and returns 0 for a blank line (empty or only spaces and tabs);
 * summary_bad_line says "PATH: line N: MSG" in one line and returns 2. */
int summary_csv_line(const hol_lines *l, char **s, size_t *n);
int summary_bad_line(const char *cmd, const char *path, long line, const char *msg);

int summary_read(const char *cmd, const char *path, int flags, summary_row_fn fn, void *ctx,
                 long *out_cut);

#endif
