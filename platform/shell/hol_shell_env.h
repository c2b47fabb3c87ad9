/* hol_shell_env.h - environment.csv's row, one for every platform (the
 * desktop's play and xr, the web page, the headset): its header and its
 * fields' formatting (docs/research.md, "Session metadata").
 *
 * Contract
 * - HOL_SHELL_ENV_TABLE: the file's columns (name, type, unit, allowed
 *   values, meaning), from which HOL_SHELL_ENV_COLUMNS, the file's header
 *   line (without its newline), and its rows of codebook.csv are made
 *   (hol_shell_codebook.h); every platform writes the header when it makes
 *   the file.
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

#include "../../core/hol_session_cols.h"

/* environment.csv's columns (a table as core/hol_session_cols.h's) */
#define HOL_SHELL_ENV_TABLE(X, S) \
    HOL_COL_SESSION(X) S \
    HOL_COL_PARTICIPANT(X) S \
    X("session_no", "integer", "", "1..999; empty: none", "the session number (--session N)") S \
    X("study_sha256", "hex", "", "64 lowercase hex digits; empty outside a study", "SHA-256 of the study file") S \
    X("platform", "string", "", "desktop, openxr, web, webxr", "the platform") S \
    X("os", "string", "", "", "uname -srm") S \
    X("runtime", "string", "", "empty on the desktop", "the OpenXR runtime's name and version") S \
    X("gl_renderer", "string", "", "", "GL_RENDERER") S \
    X("controller", "string", "", "", "the game controller or interaction profile") S \
    X("refresh_hz", "number", "Hz", "empty: unknown", "the display's refresh rate") S \
    X("width", "integer", "px", "", "the window's or eye image's width") S \
    X("height", "integer", "px", "", "the window's or eye image's height") S \
    X("meta", "string", "", "KEY=VALUE joined with ;", "the --meta options") S \
    X("options", "string", "", "", "the command line as given")
#define HOL_SHELL_ENV_COLUMNS HOL_SHELL_ENV_TABLE(HOL_COL_NAME, ",")
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
