/* play_prov.h - the provenance files of a log folder: provenance.csv (which
 * build wrote the session), order.csv (a study participant's order) and
 * codebook.csv (every column of every file; docs/logs.md, "Provenance").
 *
 * Contract
 * - play_prov_write is called by play_session_open once the session is
 *   open on a --log folder (play, replay, xr): it appends provenance.csv's
 *   row (PLAY_PROV_COLUMNS: the session, its participant, this build's
 *   version, commit and date: build_info.h; the header when the file is
 *   new), appends the held order rows (play_prov_hold_order) to order.csv
 *   (PLAY_ORDER_COLUMNS, each prefixed with the session; the header when
 *   new) and writes codebook.csv (codebook.h) whole, as codebook.csv.new
 *   renamed. Every write goes through the folder's sink and is flushed
 *   durably. Returns 0, or 1 when one failed (the session goes on: these
 *   files are never a reason to lose a participant's play).
 * - play_prov_failed(cmd), at the session's end (play_session_end, after
 *   the session's own failure if any): 0 when play_prov_write wrote all,
 *   else 1 after one line naming the file and why (cli_error_end: not
 *   said when a failure was said before, the disk full twice).
 * - play_prov_hold_order(rows, levels, n) keeps rows (CSV lines after the
 *   session column and before level_sha256, one per level of levels, each
 *   ending in LF) for the next play_prov_write, which writes and forgets
 *   them; play_prov_order_hash(levels, n), given the same array once the
 *   levels' texts are final (play_geometry_apply calls it), adds each
 *   level's hash: rows never given their hashes are not written.
 *   play_study_levels holds its order.
 * - Every field is escaped for a terminal and quoted per RFC 4180 as the
 *   logs' names are (core/hol_text.h); play_prov_field appends one.
 * - The logs the session writes are not changed: these are new files.
 */
#ifndef PLAY_PROV_H
#define PLAY_PROV_H

#include <stddef.h>

#include "../../core/hol_level.h"
#include "../../core/hol_rec.h"
#include "../../core/hol_sink.h"

#define PLAY_PROV_COLUMNS "session,participant,version,commit,build_date"
#define PLAY_ORDER_COLUMNS \
    "session,participant,study,position,condition,level,level_file,level_sha256"

int play_prov_write(const hol_sink *log, const hol_rec_meta *meta);
int play_prov_failed(const char *cmd);
void play_prov_hold_order(const char *rows, const hol_level *levels, int n);
void play_prov_order_hash(const hol_level *levels, int n);
/* Appends ",FIELD" (first: "FIELD") to out (cap bytes); 1 when it does
 * not fit (out is then left as it was). */
int play_prov_field(char *out, size_t cap, const char *s, int first);

#endif
