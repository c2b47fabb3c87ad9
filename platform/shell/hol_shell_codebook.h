/* hol_shell_codebook.h - codebook.csv: every column of every file a log
 * folder holds, with its type, unit, allowed values and meaning, made from
 * the tables the writers make their headers from (core/hol_log_cols.h:
 * the session's HOL_SESSION_*_COLUMNS, hol_shell_env.h's and
 * hol_shell_prov.h's), so no column is written that the codebook lacks (docs/logs.md, "Provenance and codebook").
 *
 * Contract
 * - hol_codebook_col: a table's row; HOL_CODEBOOK_COL(...) makes one (X of
 *   a table: TABLE(HOL_CODEBOOK_COL, ) is an initializer's rows).
 * - hol_shell_codebook_logs(&n): the log folder's files in codebook.csv's
 *   order, each its name ("steps-NNN.csv" for an attempt's) and table; n
 *   their count.
 * - hol_shell_codebook_put(file, col, out, cap, &at) appends one row of
 *   codebook.csv at out + at: file, column, type and unit as they are,
 *   allowed and meaning always in double quotes (a quote in them doubled),
 *   LF; 1 when it does not fit.
 * - hol_shell_codebook_csv(out, cap): the log folder's codebook.csv (its
 *   header HOL_SHELL_CODEBOOK_COLUMNS, then every file's rows, as
 *   hol_shell_codebook_put writes them); its length, or 0 when cap is too
 *   small. The text is one string literal the preprocessor makes from the
 *   tables (HOL_LOG_FILES): no table of pointers in a build
 *   that only writes it (the web's transfer size). So no field of a table
 *   holds a double quote, a comma in file, column, type or unit, or a line
 *   break (tests/test_codebook.c).
 * - hol_shell_codebook_header(file, out, cap): a log file's columns
 *   joined with commas; the number of columns, 0 for a file not listed.
 * - Pure: no I/O, no allocation, no mutable state.
 */
#ifndef HOL_SHELL_CODEBOOK_H
#define HOL_SHELL_CODEBOOK_H

#include <stddef.h>

#include "../../core/hol_log_cols.h"

typedef struct hol_codebook_col {
    const char *column, *type, *unit, *allowed, *meaning;
} hol_codebook_col;

typedef struct hol_codebook_file {
    const char *name;
    const hol_codebook_col *cols;
    int n;
} hol_codebook_file;

#define HOL_CODEBOOK_COL(name, type, unit, allowed, meaning) {name, type, unit, allowed, meaning},

#define HOL_SHELL_CODEBOOK_COLUMNS HOL_LOG_CODEBOOK_TABLE(HOL_COL_NAME, ",")

#define HOL_SHELL_CODEBOOK_TEXT_MAX (64 * 1024)

const hol_codebook_file *hol_shell_codebook_logs(int *out_n);
int hol_shell_codebook_put(const char *file, const hol_codebook_col *col, char *out, size_t cap,
                           size_t *at);
size_t hol_shell_codebook_csv(char *out, size_t cap);
int hol_shell_codebook_header(const char *file, char *out, size_t cap);

#endif
