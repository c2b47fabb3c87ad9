/* hol_shell_prov.h - the provenance files of a log folder, one for every
 * platform (play, replay and xr on the desktop, the web page, the
 * headset): provenance.csv (which build wrote the session), order.csv (a
 * study participant's order) and codebook.csv (every column of every
 * file; docs/logs.md, "Provenance and codebook").
 *
 * Contract
 * - HOL_SHELL_PROV_COLUMNS and HOL_SHELL_ORDER_COLUMNS: the files'
 *   headers, made from their tables (HOL_LOG_PROV_TABLE,
 *   HOL_LOG_ORDER_TABLE: core/hol_log_cols.h).
 * - hol_shell_prov_write(log, meta, order) is called once the session is
 *   open on a log folder: it appends provenance.csv's row (the session,
 *   its participant, this build's version, commit and date:
 *   hol_shell_build.h; the header when the file is new), appends order
 *   (rows of order.csv after the session column, each ending in LF; NULL
 *   or "": none) to order.csv, each prefixed with the session (the header
 *   when new), and writes codebook.csv (hol_shell_codebook_logs) whole, as
 *   codebook.csv.new renamed. Every write goes through the folder's sink
 *   and is flushed durably. Returns NULL, or the name of the first file
 *   that failed (the platform says so; the session goes on: these files
 *   are never a reason to lose a participant's play).
 * - hol_shell_order_rows(study, participant, lv, levels, n, out, cap):
 *   the order's rows without their session and level_sha256 (participant,
 *   study, position, condition, level, level_file; lv and levels as
 *   hol_study_session made them) into out; hol_shell_order_hash(rows,
 *   levels, n, out, cap) adds each level's hash (levels' texts final).
 *   Both return 0, or 1 when out is too small (out then "").
 * - hol_shell_prov_field appends ",FIELD" (first: "FIELD") to out (cap
 *   bytes), escaped for a terminal and quoted per RFC 4180 as the logs'
 *   names are (core/hol_text.h); 1 when it does not fit (out then as it
 *   was).
 * - The logs the session writes are not changed: these are other files.
 */
#ifndef HOL_SHELL_PROV_H
#define HOL_SHELL_PROV_H

#include <stddef.h>

#include "../../core/hol_level.h"
#include "../../core/hol_rec.h"
#include "../../core/hol_log_cols.h"
#include "../../core/hol_sink.h"
#include "../../core/hol_study.h"

#define HOL_SHELL_PROV_COLUMNS HOL_LOG_PROV_TABLE(HOL_COL_NAME, ",")
#define HOL_SHELL_ORDER_COLUMNS HOL_LOG_ORDER_TABLE(HOL_COL_NAME, ",")

const char *hol_shell_prov_write(const hol_sink *log, const hol_rec_meta *meta, const char *order);
int hol_shell_order_rows(const hol_study *study, const char *participant, const int *lv,
                         const hol_level *levels, int n, char *out, size_t cap);
int hol_shell_order_hash(const char *rows, const hol_level *levels, int n, char *out, size_t cap);
int hol_shell_prov_field(char *out, size_t cap, const char *s, int first);

#endif
