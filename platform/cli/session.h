/* session.h - a play session on the desktop: the app step, the level list,
 * the research logs and the recording; shared by `holonomy play` (window)
 * and `holonomy replay` (headless), so a replay runs exactly the code the
 * play ran.
 *
 * Contract
 * - session_open creates the app (core/hol_app.h), starts the first level
 *   and, with a recording path, opens the recording (written to a temporary
 *   file, renamed into place at session_close).
 * - session_step steps the app with one input record, appends the record to
 *   the recording, keeps the research log rows in fixed ring buffers (no
 *   allocation, no file I/O in a frame), writes the level's log files
 *   atomically when a level attempt ends, and starts the next level when the
 *   app asks for it.
 * - Logs (DIR given): per level attempt NNN, DIR/steps-NNN.csv (one row per
 *   room step) and DIR/head-NNN.csv (the head at 10 Hz); DIR/summary.csv
 *   one row per attempt, rewritten at every attempt's end. Columns in the
 *   README. A ring that overflows drops its oldest rows and the summary
 *   row says how many.
 * - Recording (text): "holonomy-rec 1", then each level as "level NAME",
 *   its file's lines prefixed "L ", "end"; then one input line
 *   (core/hol_input_io.h) per frame.
 */
#ifndef HOL_SESSION_H
#define HOL_SESSION_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_app.h"
#include "../../render/hol_render.h"
#include "../file/hol_file.h"

/* The recording's header version (the session's); its input lines are
 * read in any version of the line format up to HOL_INPUT_TEXT_VERSION
 * (core/hol_input_io.h: version 2 only added fields). */
#define SESSION_REC_VERSION 1
#define SESSION_MAX_LEVELS 16
#define SESSION_LEVEL_TEXT 4096
#define SESSION_NAME_MAX 64
#define SESSION_STEP_ROWS 65536
#define SESSION_HEAD_ROWS 36000 /* an hour at 10 Hz */
#define SESSION_MAX_ATTEMPTS 1024

typedef struct session_level {
    char name[SESSION_NAME_MAX];
    char text[SESSION_LEVEL_TEXT]; /* the level file */
    size_t len;
    hol_app_level lvl;             /* parsed */
} session_level;

typedef struct session_head_row {
    double t;
    double pos[3];
    double yaw, pitch;
    hol_room room;
} session_head_row;

typedef struct session_summary_row {
    int attempt, level;
    hol_app_summary s;
    long dropped;
} session_summary_row;

typedef struct session {
    const char *cmd;
    hol_app *app;
    session_level *levels; /* nlevels, owned by the caller */
    int nlevels, cur;
    const char *log_dir;   /* NULL: no logs */
    int attempt;           /* 1-based, session wide; 0 before the first */
    int attempt_open;
    hol_app_step_event *step_ring;
    long step_head, step_n, step_dropped;
    session_head_row *head_ring;
    long head_head, head_n, head_dropped;
    session_summary_row *summary;
    int nsummary;
    hol_file_atomic rec;
    int recording;
    int finished;          /* quit, or the last level done and confirmed */
    long frame;
} session;

/* Parse a level file's text into lvl; on bad input 1 with "line N: ..."
 * in err. */
int session_parse_level(const char *text, size_t len, hol_app_level *lvl, char *err,
                        size_t err_cap);

/* Open: 0 ok; else an exit status with the error reported. */
int session_open(session *s, const char *cmd, session_level *levels, int nlevels,
                 const char *log_dir, const char *record_path);
/* One frame: 0 go on, 1 the session is over (quit, or the campaign done),
 * -1 a failure (reported; exit status 1). */
int session_step(session *s, const hol_input *in);
/* Write the open level's logs (end "open"), commit the recording, free. */
int session_close(session *s);


/* Read a recording's header (levels) from text lines; returns the line
 * number where the input lines begin (1-based), or 0 with err set. */
long session_read_header(char *const *lines, const size_t *lens, long nlines,
                         session_level *levels, int *nlevels, char *err, size_t err_cap);

#endif
