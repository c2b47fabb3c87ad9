/* codebook.h - codebook.csv: every column of every file a log folder and a
 * report hold, with its type, unit, allowed values and meaning (docs/logs.md,
 * "Provenance"; docs/report.md).
 *
 * Contract
 * - The rows are one table (codebook_table.h), in each file's column order.
 *   tests/test_codebook.c checks that each file's columns, joined with
 *   commas, are that file's header as its writer writes it (the session's
 *   HOL_SESSION_*_COLUMNS, HOL_SHELL_ENV_COLUMNS, PLAY_PROV_COLUMNS, ...);
 *   tests/cli_codebook.sh that every column of every file written in a log
 *   folder and a report is in the codebook.csv written there.
 * - codebook_csv(which, out, cap) writes the codebook's text (its header
 *   CODEBOOK_COLUMNS, then one row per column; fields quoted per RFC 4180
 *   where they need it) into out: which CODEBOOK_LOGS the log folder's
 *   files, CODEBOOK_REPORT the report's (named without "report:"). A
 *   report column with an empty meaning takes the log column of the same
 *   name's. Returns its length, or 0 when cap is too small.
 * - codebook_header(file, out, cap): the file's columns joined with commas
 *   (file as in the table: "steps-NNN.csv", "report:stats.csv"); returns
 *   the number of columns, 0 for a file not in the table.
 * - Pure: no I/O, no allocation.
 */
#ifndef CODEBOOK_H
#define CODEBOOK_H

#include <stddef.h>

typedef struct codebook_row {
    const char *file, *column, *type, *unit, *allowed, *meaning;
} codebook_row;

#define CODEBOOK_COLUMNS "file,column,type,unit,allowed,meaning"
#define CODEBOOK_TEXT_MAX (64 * 1024)
enum { CODEBOOK_LOGS, CODEBOOK_REPORT };

size_t codebook_csv(int which, char *out, size_t cap);
int codebook_header(const char *file, char *out, size_t cap);

#endif
