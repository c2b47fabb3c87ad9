/* play_setup.h - what `holonomy play`, `replay`, `xr` and `game` share
 * around the session (core/hol_session.h): levels from files, recorded
 * input read a line at a time, the session's outputs on this machine, and
 * its start and end.
 *
 * Contract (every function reports a problem as one line on stderr, as
 * cli_error does, and returns the exit status: 0 ok, 1 failure, 2 bad
 * input)
 * - play_read_level reads a level file (core/hol_level.h) named after the
 *   file (its base name up to the first '.'; the whole base name when that
 *   is empty; at most 60 bytes); a name a recording cannot carry (a newline
 *   in the file's name) is refused. play_levels: a LEVEL file, a --mode
 *   level, or the default campaign (core/hol_campaign.h), made for g's
 *   tiling and room (g may be NULL: the defaults).
 * - play_input reads input records (core/hol_input_io.h) from a file a line
 *   at a time (platform/file/hol_lines.h, lines of at most HOL_REC_LINE_MAX
 *   bytes): a recording's header (core/hol_rec.h) is read first when the
 *   file starts with one (required with want_header; its levels and
 *   metadata are kept in the play_input); each record's time may not go
 *   back. A record is taken only whole: a last line without its LF (a file
 *   cut in a record) is dropped with one warning line on stderr, as the
 *   end. A recording's last line "end aborted" (core/hol_rec.h) ends the
 *   records with pi->aborted set: the caller aborts its session as the
 *   recorded one was. play_input_next: 1 a record, 0 the end, else -status.
 * - play_out_open checks the outputs before any play: --log DIR (made when
 *   missing and its parent exists; else bad input; one that holds logs is
 *   refused unless append) and --record FILE (FILE and FILE.live a regular
 *   file or a new name in an existing folder, cli_check_output; a FILE.live
 *   a killed session left is refused; with append, a log file in DIR that
 *   is not a regular file, a folder or a FIFO, is refused). A DIR it made
 *   is removed again by play_out_close when no session opened on it (a
 *   refused study, a window that failed): no empty folder is left.
 *   play_session_open
 *   then creates the session on them (with po's study_text, which the
 *   session keeps as DIR/study-HASH.txt; its navigator and world lazy,
 *   hol_app_desc's lazy_nav and lazy_world, except for "xr": a headset's
 *   level start and frames never pay); play_session_end finishes it (or
 *   aborts it: the attempt in play ends `aborted`) and frees it.
 * - play_print_end prints "level NAME STATE steps S optimum O tile A cell
 *   C,R" with NAME escaped for the terminal (core/hol_text.h).
 * - play_load_pad_script reads a scripted game controller (--gamepad-replay,
 *   hol_hid_script.h).
 */
#ifndef HOL_PLAY_SETUP_H
#define HOL_PLAY_SETUP_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_input.h"
#include "../../core/hol_level.h"
#include "../../core/hol_rec.h"
#include "../../core/hol_session.h"
#include "../file/hol_lines.h"
#include "../file/hol_sink_posix.h"
#include "../hid/hol_hid_script.h"

int play_read_level(const char *cmd, const char *path, hol_level *out);

/* The geometry options of play, xr, replay and game (SPEC 7): --tiling 4,Q,
 * --room CxR, --cell M (0: not given). play_geometry_value takes one
 * (opt its name, val its value): 1 taken, 0 not one of them, -1 a bad value
 * reported as one line. play_geometry_apply gives each level the options
 * as its default (hol_level_set_geometry: the missing lines added to its
 * text; a level whose own line differs is refused naming the level); a
 * tutorial level takes only --cell (its lessons are made for {4,5} 3x3:
 * its own lines may say otherwise). */
typedef struct play_geometry {
    int q, cols, rows;
    double cell_m;
} play_geometry;
#define PLAY_GEOMETRY_OPTIONS "--tiling", "--room", "--cell"
#define PLAY_GEOMETRY_USAGE                                                            \
    "  --tiling 4,Q    the tiling {4,Q}, Q from 4 to 8 (default 4,5; SPEC 7)\n"         \
    "  --room CxR      a room of C x R cells, 3 to 5 each (default 3x3)\n"              \
    "  --cell M        the side of a cell in metres, 0.5 to 1.5 (default 1)\n"          \
    "                  These are the default of levels without a 'tiling', 'room'\n"   \
    "                  or 'cell' line (the line is added to the level's text, so\n"     \
    "                  logs and recordings carry it); a level whose own line\n"         \
    "                  differs is refused (docs/levels.md). The tutorial takes\n"   \
    "                  only --cell: it stays {4,5} 3x3 unless its own lines say\n"  \
    "                  otherwise\n"
int play_geometry_value(const char *cmd, const char *opt, const char *val, play_geometry *g);
int play_geometry_apply(const char *cmd, const play_geometry *g, hol_level *levels, int n);
/* --lesson N (1..HOL_LESSONS): 0 ok, else 1 with one line. */
int play_lesson_value(const char *cmd, const char *val, int *out);
/* The level 'lesson N' named lesson-N (core/hol_lesson.h). */
int play_lesson_level(const char *cmd, int n, hol_level *levels, int *nlevels);
int play_levels(const char *cmd, const char *level_path, const char *mode, uint64_t seed,
                const play_geometry *g, hol_level *levels, int *nlevels);

typedef struct play_input {
    const char *cmd, *path;
    hol_lines lines;
    double prev_t;
    int have_first;                   /* first: read with the header */
    char first[HOL_REC_LINE_MAX + 1];
    size_t first_len;
    int first_cut;                    /* first had no LF (the file's end) */
    int aborted;                      /* ended by the "end aborted" line */
    int recording;                    /* the file has a recording's header */
    hol_rec_reader rec;               /* its levels and metadata */
    hol_level levels[HOL_REC_MAX_LEVELS];
} play_input;

int play_input_open(const char *cmd, const char *path, int want_header, play_input *pi);
int play_input_next(play_input *pi, hol_input *in);
void play_input_close(play_input *pi);

typedef struct play_out {
    hol_sink_posix log, rec;
    int has_log, has_rec;
    char rec_name[HOL_SINK_NAME_MAX];
    char made_dir[4096]; /* --log DIR when play_out_open made it */
    int opened;          /* a session opened on them */
    int track_hz;        /* --track-hz, set after play_out_open; 0: 10 */
    int lang;            /* --lang, set after play_out_open: the app's
                            (hol_app_desc.lang); 0: English */
    char *study_text;    /* --study's text for the session to keep (set
                            after play_out_open, play_env_meta; freed by
                            play_out_close); NULL: none */
    size_t study_len;
} play_out;

int play_out_open(const char *cmd, const char *log_dir, int append, const char *rec_path,
                  play_out *po);
void play_out_close(play_out *po);
/* --participant ID: 0 when ID is one (hol_rec_id_ok) that does not start
 * with '-' (a spreadsheet's formula: docs/report.md) and is no participant
 * number in an ambiguous spelling, with its one spelling in out
 * (hol_study_participant_id: "p2" and "002" are "P02"); else reported, 1. */
int play_participant(const char *cmd, const char *id, char out[HOL_REC_ID_MAX]);
int play_session_open(const char *cmd, play_out *po, const hol_level *levels, int nlevels,
                      const hol_rec_meta *meta, int append, hol_session **out);
/* abort: 0 finish, 1 abort, PLAY_END_KILLED as a kill and its recovery
 * (hol_session_end_killed: the replay of a killed session's REC.live). */
#define PLAY_END_KILLED 2
int play_session_end(const char *cmd, hol_session *s, int abort);

void play_print_end(hol_session *s);

int play_load_pad_script(const char *cmd, const char *path, hol_hid_script *sc);

#endif
