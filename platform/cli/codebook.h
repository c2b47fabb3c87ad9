/* codebook.h - codebook.csv: every column of every file a log folder and a
 * report hold, with its type, unit, allowed values and meaning (docs/logs.md,
 * "Provenance"; docs/report.md).
 *
 * Contract
 * - The log folder's files are the writers' own tables (core/
 *   hol_log_cols.h: each writer's header is made from its table, the
 *   codebook's text by platform/shell/hol_shell_codebook.h);
 *   the report's are a table of rows here (codebook_table.h), in each
 *   file's column order, from which the report's writers print their
 *   headers (codebook_header, report_header). tests/test_codebook.c checks that the report's
 *   build.csv's and codebook.csv's columns are their headers, and every
 *   table's rows complete; tests/cli_codebook.sh that every column of
 *   every file written in a log folder and a report is in the
 *   codebook.csv written there.
 * - codebook_csv(which, out, cap) writes the codebook's text (its header
 *   CODEBOOK_COLUMNS, then one row per column; fields quoted per RFC 4180
 *   where they need it) into out: which CODEBOOK_LOGS the log folder's
 *   files (hol_shell_codebook_csv), CODEBOOK_REPORT the report's (named
 *   without "report:"). A report column with an empty meaning takes the
 *   log column of the same name's. Returns its length, or 0 when cap is
 *   too small.
 * - codebook_header(file, out, cap): the file's columns joined with commas
 *   (file as in the tables: "steps-NNN.csv", "report:stats.csv"); returns
 *   the number of columns, 0 for a file not in them.
 * - Pure: no I/O, no allocation.
 */
#ifndef CODEBOOK_H
#define CODEBOOK_H

#include <stddef.h>

#include "../shell/hol_shell_codebook.h"

typedef struct codebook_row {
    const char *file, *column, *type, *unit, *allowed, *meaning;
} codebook_row;

#define CODEBOOK_COLUMNS HOL_SHELL_CODEBOOK_COLUMNS
#define CODEBOOK_TEXT_MAX HOL_SHELL_CODEBOOK_TEXT_MAX
enum { CODEBOOK_LOGS, CODEBOOK_REPORT };

size_t codebook_csv(int which, char *out, size_t cap);
int codebook_header(const char *file, char *out, size_t cap);

#endif
