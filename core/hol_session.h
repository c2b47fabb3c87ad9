/* hol_session.h - a play session, the same on every platform: the level
 * sequence, the app step, attempts, the research logs and the recording.
 * `holonomy play`, `replay`, `xr`, the Quest app and the web page all run
 * it, so a replay runs exactly the code the play ran.
 *
 * Contract
 * - Pure: no I/O, no clock, no globals. Files go through sinks
 *   (hol_sink.h) the platform gives; wall-clock values (the start time,
 *   the session id) come in the desc. Memory: hol_session_create makes
 *   every allocation through desc.alloc (the app's own through desc.app);
 *   stepping allocates nothing.
 * - hol_session_create copies the levels, creates the app, starts the first
 *   level and opens the outputs: the recording (desc.rec, desc.rec_name)
 *   with its header (hol_rec.h), and the log folder (desc.log).
 * - hol_session_step: one frame. The app steps with the input, the input
 *   line goes to the recording, the attempt's rows to its files, and the
 *   next level starts when the app asks. Rows and recording lines are kept
 *   in fixed buffers and handed to the sinks (write, then flush) whenever
 *   desc.flush_s (default 1 s) of input time has passed since the last
 *   flush, or a buffer is full: a process killed at any moment loses at most
 *   that much. *out_over is 1 when the session is over (the app quit, or
 *   the last level done and confirmed).
 * - Attempts: a level start or restart begins attempt NNN (001, 002, ...;
 *   numbered on from the folder's earlier attempts with desc.append). An
 *   attempt ends done, timeout, restart, quit (the app), open (the session
 *   finished in its middle: hol_session_finish), aborted (a signal, a
 *   closed window: hol_session_abort) or killed (found unfinished by a later
 *   session: see recovery).
 * - Log folder, while attempt NNN runs: attempt-NNN.live (its summary row
 *   as known at its start), steps-NNN.csv.live and head-NNN.csv.live (its
 *   rows, streamed). When it ends: the live files are flushed durably, its
 *   row is appended to summary.csv (durably), then the live files are
 *   renamed to head-NNN.csv and, last, steps-NNN.csv, and attempt-NNN.live
 *   is removed. So steps-NNN.csv never exists without head-NNN.csv and its
 *   row (a kill before its rename leaves the rest for the next append
 *   session to rename), and rows of a finished attempt are never lost.
 * - Recovery (desc.append): live files of attempts a killed session left
 *   are finished first: each gets its summary row (end killed; steps: its
 *   step rows; time: its last row's level time) unless summary.csv has it
 *   already, then the renames; a live file without a whole header line is
 *   made again with its header. An attempt with no row and no whole
 *   attempt-NNN.live (killed before it reached the disk) is dropped: its
 *   files removed (hol_session_dropped). A summary.csv holding only a first
 *   part of its header is made again; one whose last row the kill cut is
 *   cut to its whole rows, and the files of the attempts that row would
 *   have kept (finished files above the highest attempt of its whole rows,
 *   with no live file) are removed: an attempt's files stay only with its
 *   row. Every other append-only log (events.csv, points.csv, answers.csv,
 *   the platform's environment.csv, each finished steps-NNN.csv) is cut
 *   to its whole rows too, before anything is added to it
 *   (hol_session_repaired says what). A summary.csv another program saved
 *   (a UTF-8 byte order mark, CR LF line ends) is read as the logs' own.
 *   So recovery always leaves a folder `report`
 *   and `replay --append` accept. Without desc.append a folder that holds any
 *   log file (summary.csv, steps-*, head-*, attempt-*.live) is refused
 *   (HOL_EARG): a session never mixes its files into another's unasked.
 *   With desc.append, summary.csv must have this version's columns, or
 *   the previous version's (HOL_SESSION_SUMMARY_COLUMNS_OLD): then the
 *   session's rows (and recovered ones) have those columns only.
 * - The summary's session_no, study_sha256 and meta are desc.meta's (the
 *   same in every row of the session: empty, or the number, the hash and
 *   the escaped meta text, CSV-quoted when it needs it), so a replay of
 *   the recording (which carries them, hol_rec.h version 4) writes the
 *   same rows.
 * - Levels: at create, each level's text (as played and recorded) goes to
 *   level-HASH.txt in the log folder (HASH its SHA-256 in hex, the
 *   summary's level_sha256), written as level-HASH.txt.live and renamed:
 *   a log folder holds every level its rows name (`holonomy report` draws
 *   the optimal walks from them). Another session's file of the same hash
 *   holds the same bytes and is replaced by them.
 * - Resumed questions (meta.ask_item > 0, issue 39): the first level is
 *   started but not played (hol_app_ask_from): no attempt, no steps; its
 *   questions are asked from item meta.ask_item, their answers.csv rows
 *   on the attempt that played it (session meta.ask_session, attempt
 *   meta.ask_attempt: the rows a report groups with the first answers);
 *   then the session goes on as after its last item. The recording says
 *   so (hol_rec.h `ask`), so a replay does the same.
 * - A resumed session's first level (meta.ready, issue 35) begins on the
 *   ready screen (hol_app_ready): its clock starts at the confirm. The
 *   recording says so (hol_rec.h `ready`).
 * - Studies: a level's labels (hol_level: condition, position) and the
 *   study's name (meta.study) fill the summary's study, condition and
 *   position; all three are empty for a level without a condition.
 *   At create, desc.study_text (the study file's bytes, as the platform
 *   read them) goes to study-HASH.txt in the log folder (HASH: the
 *   summary's study_sha256, meta.study_sha256, which must be the text's
 *   SHA-256: HOL_EARG otherwise), written as study-HASH.txt.live and
 *   renamed, as a level's text: once a session, whatever its attempts.
 *   Only a live session has the text: a replay (whose recording carries
 *   the hash, not the text) writes none, so a replay's folder lacks it.
 * - Recording: written as REC.live (REC = desc.rec_name) and renamed to REC
 *   by hol_session_finish (or abort); a REC.live already there (a killed
 *   session's recording) is refused at create (HOL_EARG).
 * - Columns (CSV per RFC 4180; names via hol_text_csv):
 *   summary.csv HOL_SESSION_SUMMARY_COLUMNS, steps HOL_SESSION_STEP_COLUMNS,
 *   head HOL_SESSION_HEAD_COLUMNS; events.csv HOL_SESSION_EVENT_COLUMNS (a
 *   row, appended durably as it happens, for each change of the minimap's
 *   place during play, `minimap`, each refused one, `minimap-fixed`, and
 *   each re-basing of the room into another cell, `relocated` (value the
 *   distance in metres, 3 decimals: hol_app_events.relocated), and a
 *   tracked head leaving the room, `outside` (value its distance beyond
 *   the hedges), and coming back, `inside` (value the seconds it was
 *   out), from records with HOL_INPUT_WAY_BACK;
 *   the header when the file is new; a folder holding it holds logs);
 *   points.csv HOL_SESSION_POINT_COLUMNS, answers.csv
 *   HOL_SESSION_ANSWER_COLUMNS and tutorial.csv HOL_SESSION_LESSON_COLUMNS
 *   (likewise); docs/logs.md documents
 *   each. Head rows fall on exact 10 Hz level times, interpolated between
 *   the frames around them (position linear, yaw the short way round;
 *   cell and tile from the nearer frame), frame_t the later frame's time.
 *   Over a gap (HOL_SESSION_GAP_S) one row stands for the samples it hides:
 *   t the first of them, frame_t the frame after the gap, x..row empty,
 *   tile "gap". Every writer is bounded a frame: one recording line, at
 *   most HOL_APP_MAX_STEP_EVENTS step rows, HOL_SESSION_GAP_ROWS head
 *   rows and HOL_SESSION_GAP_S * track_hz + 1 track rows, so the logs grow
 *   with the input, never with its time.
 * - Track rows (track-NNN.csv, HOL_SESSION_TRACK_COLUMNS; live, renamed
 *   and recovered as head-NNN.csv, renamed between head and steps): the
 *   head (the view's, as head rows) and both hands (the input's grip
 *   poses, HOL_INPUT_HAND_*_VALID) at samples k = 0, 1, 2, ... of level
 *   time k / track_hz, computed as k / hz in doubles (no sum that drifts);
 *   sample k, t with 4 decimals. Between the frames around a sample a pose
 *   is interpolated (position linear, quaternion normalized linear the short
 *   way), tracked as in the nearer frame (its seven fields empty when not),
 *   device the nearer frame's (hol_input_device_name). A gap as for head
 *   rows: one row, device "gap", sample and t the first sample it hides,
 *   every pose field empty.
 *   A step row's visible says which cues were drawn after the step
 *   (hol_session_cues_visible), cues which were in force.
 * - Errors: hol_err, with a one-line reason in hol_session_message (naming
 *   the stream and the sink's why). After a sink failure the session keeps
 *   stepping but writes nothing more; finish reports the failure.
 */
#ifndef HOL_SESSION_H
#define HOL_SESSION_H

#include <stddef.h>
#include <stdint.h>

#include "hol_alloc.h"
#include "hol_app.h"
#include "hol_err.h"
#include "hol_level.h"
#include "hol_rec.h"
#include "hol_log_cols.h"
#include "hol_sink.h"

#define HOL_SESSION_MAX_LEVELS HOL_REC_MAX_LEVELS
/* The closing screen of a study's session whose study gives no `closing`
 * line: shown after the last level's end screen (a level labelled with a
 * condition: hol_level.condition), its confirm ends the session. */
#define HOL_SESSION_CLOSING "Thank you: the study is over."
/* Head rows are interpolated over frames at most HOL_SESSION_GAP_S of level
 * time apart; a longer gap (a stall, a laptop asleep, a recording whose
 * time jumps) is one `gap` row. A frame writes at most HOL_SESSION_GAP_ROWS
 * head rows (20 samples of a 2 s gap, and the one at its end). */
#define HOL_SESSION_GAP_S 2.0
#define HOL_SESSION_GAP_ROWS 21
/* Track rows (track-NNN.csv): desc.track_hz samples a second of level time,
 * HOL_SESSION_TRACK_HZ_MIN..MAX, default HOL_SESSION_TRACK_HZ; over a gap
 * as head rows (HOL_SESSION_GAP_S), so a frame writes at most
 * HOL_SESSION_GAP_S * hz + 1 track rows (181 at 90 Hz). */
#define HOL_SESSION_TRACK_HZ 10
#define HOL_SESSION_TRACK_HZ_MIN 10
#define HOL_SESSION_TRACK_HZ_MAX 90

/* The files' columns (hol_log_cols.h): HOL_SESSION_SUMMARY_COLUMNS;
 * a folder whose summary.csv has the columns of the build before
 * session_no, study_sha256 and meta (HOL_SESSION_SUMMARY_COLUMNS_OLD) is
 * appended to in those columns. */
/* points.csv: a row per pointing answer (level line `point`, SPEC 8;
 * hol_app_point), appended durably as it happens, the header when the file
 * is new. attempt: the attempt just ended (the level asked about); t its
 * level time at the question; pointed, true, flat: bearings with one
 * decimal (true, flat empty when undefined); error_true, error_flat:
 * pointed minus them wrapped to (-180, 180], one decimal, empty with
 * theirs; time: seconds taken to answer; shown_ms, answered_ms: the input
 * time (the session's clock, in the recording) in whole milliseconds when
 * it was asked and at its confirm. A points.csv whose header is an earlier
 * build's, without those two (HOL_SESSION_POINT_COLUMNS_OLD), is appended
 * to in its columns. */
/* answers.csv: a row per questionnaire item answered (hol_app_answer),
 * appended durably as it happens, the header when the file is new.
 * attempt: the last attempt before the questionnaire (a resumed level's
 * questions, meta.ask_item: session and attempt are meta.ask_session's
 * and meta.ask_attempt, the attempt that played it); questionnaire its
 * name, when level|condition|study (after the level) or before_level|
 * before_condition|before_study (before it: attempt the one its level
 * begins next), item the item's ID, kind
 * likert|choice, value the number (likert) or the choice's text (CSV
 * quoted when it needs it), time the seconds taken, shown_ms and
 * answered_ms the input time in whole milliseconds when the item appeared
 * and at its confirm (likewise; HOL_SESSION_ANSWER_COLUMNS_OLD). */
/* tutorial.csv: a row per tutorial lesson done (issue 35; hol_app_lesson,
 * not in a replay of a recording of version 1 to 4), appended durably as
 * it happens, the header when the file is new. lesson 1..4; started and
 * t the level times it began and was done; steps its room steps, optimum
 * its fewest from where it began; time t - started (the columns:
 * core/hol_log_cols.h). */

typedef struct hol_session_desc {
    const hol_level *levels; /* 1..HOL_SESSION_MAX_LEVELS, copied */
    int nlevels;
    hol_app_desc app;        /* the app's desc */
    hol_alloc alloc;         /* the session's buffers; zero: malloc */
    const hol_sink *log;     /* the log folder; NULL: no logs */
    int append;              /* 1: add to a folder's earlier logs */
    const hol_sink *rec;     /* the recording's folder; NULL: none */
    const char *rec_name;    /* its name there */
    hol_rec_meta meta;       /* session id, participant, start, version:
                                "" version: HOL_VERSION; required ids
                                checked (hol_rec_id_ok, hol_rec_time_ok)
                                when there are logs or a recording;
                                session_no, study_sha256 and meta checked
                                (hol_rec_meta_ok) always */
    double flush_s;          /* 0: 1 s */
    int track_hz;            /* track rows a second, 10..90; 0: 10 */
    const char *study_text;  /* a live study session's study file, kept as
                                study-HASH.txt (see Studies); NULL: none
                                (a replay: its recording has only the hash) */
    size_t study_len;        /* its bytes */
} hol_session_desc;

typedef struct hol_session hol_session;

/* Errors: HOL_EARG (a bad desc, a folder with logs and no append, a killed
 * recording in the way, a level that cannot start), HOL_EVERSION
 * (summary.csv of other columns), HOL_EBUDGET (a level's optimum cannot be
 * proved), HOL_ENOMEM, HOL_EIO / HOL_EOPEN (a sink). msg (cap bytes) gets
 * the one-line reason. */
hol_err hol_session_create(const hol_session_desc *desc, hol_session **out, char *msg,
                           size_t cap);
/* Errors: HOL_EARG (a bad record: nothing happened), HOL_ENOMEM (the world
 * store), HOL_EIO (a sink, once; the frame happened). */
hol_err hol_session_step(hol_session *s, const hol_input *in, int *out_over);
/* End now: the attempt in play ends `aborted`; then as finish. */
hol_err hol_session_abort(hol_session *s);
/* End: the attempt in play ends `open`, every file is committed. Later
 * calls do nothing. */
hol_err hol_session_finish(hol_session *s);
/* End as a kill at this frame, then the next --append session's recovery,
 * would have (a replay of a killed session's REC.live, issue 26): the
 * attempt in play's rows are flushed and it is finished as recovery
 * finishes a killed attempt (its summary row with end `killed`, `steps`
 * the steps rows, `time` the last row's; its live files renamed), so the
 * replay's summary equals the play's recovered one byte for byte; then as
 * finish. */
hol_err hol_session_end_killed(hol_session *s);
/* Frees everything; writes nothing (call finish first to keep the files:
 * unfinished live files stay, for the next session's recovery). NULL ok. */
void hol_session_destroy(hol_session *s);

hol_app *hol_session_app(hol_session *s);
/* The level in play (index into the desc's levels) and its level. */
int hol_session_level_index(const hol_session *s);
const hol_level *hol_session_level(const hol_session *s);
/* How the level in play's attempt ended (hol_app_end: done, timeout,
 * restart, quit) once it has, while its pointing question, end screen,
 * questionnaires or closing screen follow; HOL_APP_END_DONE for a
 * resumed level's questions (meta.ask_item); 0 while it plays or waits
 * for its instructions. What a platform prints at the end is this, not
 * the app's state: a quit in a questionnaire leaves an attempt `done`. */
int hol_session_level_end(const hol_session *s);
/* The word a platform prints for the level in play at the end ("level NAME
 * WORD steps ..."): timeout when its time ran out, else the end its
 * attempt was logged with once it ended (done, restart, quit: a quit in its
 * pointing question, end screen or questionnaire leaves it done), else the
 * app's (hol_app_end_word). */
const char *hol_session_end_name(hol_session *s);
long hol_session_frames(const hol_session *s);
/* Attempts of a killed session finished by recovery at create; those it
 * dropped (killed before their attempt-NNN.live reached the disk). */
int hol_session_recovered(const hol_session *s);
int hol_session_dropped(const hol_session *s);
/* What recovery repaired at create, as one line's text ("" nothing): the
 * logs it cut to their whole rows (summary.csv, events.csv, points.csv,
 * answers.csv, environment.csv, finished steps-NNN.csv) and the files it
 * removed with a summary row it cut. The platform prints it. */
const char *hol_session_repaired(hol_session *s);
const char *hol_session_message(const hol_session *s);

/* 1 when name is one of a log folder's files (summary.csv, steps-NNN.csv,
 * head-NNN.csv, or a live file of an attempt): a folder holding one is
 * refused without append. Platforms check before they open anything. */
int hol_session_is_log_name(const char *name);

/* The cues drawn in a view: hot-cold (the minimap shows, an objective is
 * left), path (the minimap shows its strayed path), poles (an objective
 * stands), arrow (the minimap shows and an objective lies beyond its
 * HOL_APP_MINIMAP_RADIUS tiles), lantern (an objective stands and the sky
 * is dusk or night: its lantern is lit) - each only where the level has
 * it. */
unsigned hol_session_cues_visible(const hol_app_view *v);

#endif
