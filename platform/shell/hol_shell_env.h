/* hol_shell_env.h - environment.csv's row, one for every platform (the
 * desktop's play and xr, the web page, the headset): its header and its
 * fields' formatting (docs/research.md, "Session metadata").
 *
 * Contract
 * - HOL_SHELL_ENV_COLUMNS: the file's header line (without its newline),
 *   made from its table of columns (HOL_LOG_ENV_TABLE, core/hol_log_cols.h:
 *   codebook.csv's rows are made from it too); every platform writes it
 *   when it makes the file.
 * - hol_shell_env_row writes one row, without its newline, into out (cap
 *   bytes, NUL-terminated): the fourteen fields in the header's order, each
 *   escaped for a terminal (hol_text_escape) and then quoted as one RFC
 *   4180 field (hol_text_csv), comma-separated. Numbers: session_no,
 *   width and height "%d" ("" when 0), refresh_hz "%.3f" ("" when not
 *   above 0). A NULL string is "". field_max (0: HOL_SHELL_ENV_FIELD_MAX,
 *   at most that) bounds one field once escaped.
 * - Returns 0 with *out_len the row's length, or 1 when a field or the
 *   row does not fit (the caller writes no row).
 * - Pure: no I/O, no allocation, no globals (core/hol_text.h only).
 */
#ifndef HOL_SHELL_ENV_H
#define HOL_SHELL_ENV_H

#include <stddef.h>

#include "../../core/hol_log_cols.h"

#define HOL_SHELL_ENV_COLUMNS HOL_LOG_ENV_TABLE(HOL_COL_NAME, ",")
/* A field's bound once escaped: above a recording's whole meta text (16
 * values of 200 bytes, each escaped to at most 800: HOL_REC_META_TEXT), so
 * that valid --meta always has its row (issue 39). */
#define HOL_SHELL_ENV_FIELD_MAX 16384
/* The longest row (with its NUL): every field escaped just under the
 * bound, then quoted with each byte a doubled quote, and the commas. */
#define HOL_SHELL_ENV_ROW_MAX (14 * (2 * HOL_SHELL_ENV_FIELD_MAX + 3))

typedef struct hol_shell_env_fields {
    const char *session, *participant;
    int session_no; /* 0: none */
    const char *study_sha256, *platform, *os, *runtime, *gl_renderer, *controller;
    double refresh_hz; /* 0: unknown */
    int width, height; /* 0: unknown */
    const char *meta, *options;
} hol_shell_env_fields;

int hol_shell_env_row(const hol_shell_env_fields *f, size_t field_max, char *out, size_t cap,
                      size_t *out_len);

#endif
