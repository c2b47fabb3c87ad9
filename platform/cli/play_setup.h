/* play_setup.h - what `holonomy play` and `holonomy xr` share before their
 * loops: the level list and recorded input lines.
 *
 * Contract
 * - play_levels fills levels (SESSION_MAX_LEVELS) from a LEVEL file, or a
 *   --mode level made from the seed (flag 5 steps out; 3 keys 2..3 out and
 *   the chest at 5), or with neither the default campaign (the tutorial,
 *   flags at distance 3, 5 and 7, keys and chest with 2 and 3 keys). It
 *   reports a problem as one line and returns the exit status (0 ok).
 * - read_lines reads a whole file as lines (NUL-terminated in place, CR LF
 *   accepted); parse_input_line parses line k as an input record
 *   (core/hol_input_io.h) whose time may not go back; both report errors
 *   as one line naming the line.
 * - play_load_pad_script reads a scripted game controller
 *   (--gamepad-replay, hol_hid_script.h) into *sc, reporting a bad line
 *   as one line naming it.
 */
#ifndef HOL_PLAY_SETUP_H
#define HOL_PLAY_SETUP_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_input.h"
#include "../hid/hol_hid_script.h"
#include "session.h"

int play_levels(const char *cmd, const char *level_path, const char *mode, uint64_t seed,
                session_level *levels, int *nlevels);

typedef struct file_lines {
    uint8_t *data;
    char **line;
    size_t *len;
    long n;
} file_lines;

/* 0 ok, else the exit status (reported). */
int read_lines(const char *cmd, const char *path, file_lines *fl);
void free_lines(file_lines *fl);
/* read_lines, then, when the file is a recording, its header skipped:
 * *out_first is the first input line. 0 ok, else the exit status (reported;
 * fl freed). */
int read_input_lines(const char *cmd, const char *path, file_lines *fl, long *out_first);
/* 0 ok, 1 reported (bad record, or time going back from *prev_t). */
int parse_input_line(const char *cmd, const file_lines *fl, long k, hol_input *in,
                     double *prev_t);

/* 0 ok, else the exit status (reported). */
int play_load_pad_script(const char *cmd, const char *path, hol_hid_script *sc);

#endif
