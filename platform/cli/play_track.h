/* play_track.h - `--track-hz N` of play, xr and replay: the rate of the
 * tracker rows (track-NNN.csv, core/hol_session.h) in the log folder.
 *
 * Contract
 * - play_track_value: N a whole number in HOL_SESSION_TRACK_HZ_MIN..MAX
 *   (10..90, decimal digits only) into *out_hz, 0; else one line on stderr
 *   (cli_error) and 1 (the caller exits 2).
 * - play_track_check: --track-hz without --log is refused the same way
 *   (no file would hold the rows).
 * - The option reaches environment.csv's options column with the rest of
 *   the command line; a replay reproduces the play's track rows only at
 *   the play's rate (give it the same --track-hz).
 */
#ifndef HOL_PLAY_TRACK_H
#define HOL_PLAY_TRACK_H

#define PLAY_TRACK_USAGE                                                                 \
    "  --track-hz N    tracker rows (head and hands: DIR/track-NNN.csv) N times a\n"    \
    "                  second of level time, 10..90 (default 10; needs --log)\n"

int play_track_value(const char *cmd, const char *val, int *out_hz);
int play_track_check(const char *cmd, int hz, const char *log_dir);

#endif
