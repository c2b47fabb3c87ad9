/* play_prov.h - the provenance files of a `play`, `replay` or `xr` log
 * folder: provenance.csv, order.csv and codebook.csv, written by the
 * shell's hol_shell_prov_write (platform/shell/hol_shell_prov.h) as on
 * every platform; here the order held until the session is open, and the
 * failure said at the session's end.
 *
 * Contract
 * - play_prov_write is called by play_session_open once the session is
 *   open on a --log folder (play, replay, xr): hol_shell_prov_write with
 *   the held order rows (play_prov_hold_order), which it forgets. Returns
 *   0, or 1 when a file failed (the session goes on: these files are never
 *   a reason to lose a participant's play).
 * - play_prov_failed(cmd), at the session's end (play_session_end, after
 *   the session's own failure if any): 0 when play_prov_write wrote all,
 *   else 1 after one line naming the file and why (cli_error_end: not
 *   said when a failure was said before, the disk full twice).
 * - play_prov_hold_order(rows, levels, n) keeps rows (hol_shell_order_rows:
 *   one per level of levels) for the next play_prov_write;
 *   play_prov_order_hash(levels, n), given the same array once the levels'
 *   texts are final (play_geometry_apply calls it), adds each level's hash
 *   (hol_shell_order_hash): rows never given their hashes are not written.
 *   play_study_levels holds its order.
 */
#ifndef PLAY_PROV_H
#define PLAY_PROV_H

#include "../../core/hol_level.h"
#include "../../core/hol_rec.h"
#include "../../core/hol_sink.h"

int play_prov_write(const hol_sink *log, const hol_rec_meta *meta);
int play_prov_failed(const char *cmd);
void play_prov_hold_order(const char *rows, const hol_level *levels, int n);
void play_prov_order_hash(const hol_level *levels, int n);

#endif
