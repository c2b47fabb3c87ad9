/* play_env.h - a session's environment and metadata (issue 26 item 5):
 * `--session N` and repeatable `--meta KEY=VALUE` of play (and xr), the
 * study file's text and hash, and one row per session start in the log
 * folder's environment.csv (docs/research.md).
 *
 * Contract (problems reported as one line on stderr, as cli_error does)
 * - play_env_value takes one option: 1 taken, 0 not one of these, -1 a bad
 *   value reported. --session N: 1..999. --meta KEY=VALUE: KEY [a-z0-9_]
 *   1..32 bytes, VALUE at most 200 bytes without';' (the separator), at most PLAY_ENV_META_MAX, a key
 *   given twice refused.
 * - play_env_check: exit status 0, or 2 after reporting --session/--meta
 *   without --log, or a DIR/environment.csv there that is not a regular
 *   file (hol_file_check_out: a FIFO, a folder), before anything opens;
 *   with --log, a command line (e->argv) over HOL_SHELL_ENV_FIELD_MAX - 1
 *   bytes once escaped is refused too (environment.csv's options column
 *   would not hold it: never cut). A row of valid options always fits
 *   (HOL_SHELL_ENV_ROW_MAX), so play_env_write fails only on the disk.
 * - play_env_write (after the session opened on DIR): one row appended to
 *   DIR/environment.csv (made with its header HOL_SHELL_ENV_COLUMNS; the row
 *   written with one write(2) and fsync'ed), study_sha256 its column ("":
 *   none). The row: platform/shell/hol_shell_env.h. Returns 0
 *   or 1 (reported).
 * - play_env_meta (before the session opens): the session's metadata for
 *   summary.csv and the recording (hol_rec_meta's session_no,
 *   study_sha256: the study file's SHA-256, read now; meta: the --meta
 *   options joined with ';', escaped by hol_text_escape), and the study's
 *   text as read (*out_study, malloc'ed, the caller frees it even on
 *   failure; NULL without study_path): the session keeps it as
 *   DIR/study-HASH.txt (hol_session_desc's study_text). 0, or 1 reported
 *   (the study cannot be read again).
 * - Replay writes no environment row: the environment is the live one.
 * - play_opts_check (play and xr): the first clash of the options given
 *   (platform/shell/hol_shell_opts.h's table), then play_env_check and
 *   play_track_check (play_track.h); 0 none, else 1 (reported).
 */
#ifndef HOL_PLAY_ENV_H
#define HOL_PLAY_ENV_H

#include <stddef.h>

#include "../shell/hol_shell_opts.h"

#define PLAY_ENV_META_MAX 16
#define PLAY_ENV_OPTIONS "--session", "--meta"
#define PLAY_ENV_USAGE                                                                   \
    "  --session N     the participant's session number, 1..999 (day 1, day 2),\n"      \
    "                  in summary.csv and environment.csv (needs --log)\n"              \
    "  --meta KEY=VALUE  a note for summary.csv and environment.csv (needs --log;\n"    \
    "                  repeatable, up to 16; KEY 1..32 of a-z, 0-9, '_')\n"

typedef struct play_env {
    int argc;       /* the command line, for the options column */
    char **argv;
    int session_no; /* 0: not given */
    int nmeta;
    const char *meta[PLAY_ENV_META_MAX];
} play_env;

/* What the platform knows of itself ("" or 0 when it does not). */
typedef struct play_env_host {
    const char *platform, *runtime, *gl_renderer, *controller;
    double refresh_hz;
    int width, height;
} play_env_host;

int play_env_value(const char *cmd, const char *opt, const char *val, play_env *e);
int play_env_check(const char *cmd, const play_env *e, const char *log_dir);
struct hol_rec_meta;
int play_env_meta(const char *cmd, const play_env *e, const char *study_path,
                  struct hol_rec_meta *m, char **out_study, size_t *out_len);
int play_env_write(const char *cmd, const char *log_dir, const play_env *e, const char *session,
                   const char *participant, const char *study_sha256, const play_env_host *h,
                   int argc, char **argv);

int play_opts_check(const char *cmd, const unsigned char given[HOL_SHELL_OPT_COUNT],
                    const play_env *e, const char *log_dir, int track_hz);

#endif
