/* hol_log_cols.h - the columns of every CSV file of a log folder: the
 * session's (summary, steps, head, track, events, points, answers, tutorial;
 * hol_session.h) and the platform shell's (environment, provenance, order,
 * codebook; platform/shell/): one table a file, each column's name, type,
 * unit, allowed values and meaning.
 *
 * Contract
 * - Each table is a macro TABLE(X, S): X(name, type, unit, allowed,
 *   meaning) for each column in the file's order, S between two columns.
 *   HOL_COL_NAME and "," make the file's header (HOL_SESSION_*_COLUMNS,
 *   a string literal: the writers write it, so no column is written that
 *   the table lacks); the platform's codebook (platform/shell/
 *   hol_shell_codebook.h) makes codebook.csv's rows from the same tables,
 *   the files in HOL_LOG_FILES's order.
 * - type is string, integer, number, hex, id or timestamp; unit empty, or
 *   s, ms, m, deg, Hz, px, count, cell, bits, quarter turns; allowed empty
 *   (any of the type) or the values allowed; meaning never empty. No field
 *   starts with = + - @ (a spreadsheet's formula).
 * - A table named _OLD is the columns of an earlier build's file, which a
 *   session appending to it keeps (hol_session.h).
 * - Macros only: no code, no data.
 */
#ifndef HOL_LOG_COLS_H
#define HOL_LOG_COLS_H

/* A column's name (X for a header: TABLE(HOL_COL_NAME, ",")). */
#define HOL_COL_NAME(name, type, unit, allowed, meaning) name

/* summary.csv before session_no, study_sha256 and meta */
#define HOL_SESSION_SUMMARY_OLD_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("session_start", "timestamp", "", "ISO 8601 UTC", "the session's start") S \
    X("version", "string", "", "", "the app version that played") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("study", "string", "", "empty outside a study", "the study's name (--study)") S \
    X("condition", "string", "", "a condition's name, practice; empty outside a study", "the condition the level was played under") S \
    X("position", "integer", "", "0 practice, 1..; empty outside a study", "the level's position in the participant's order") S \
    X("level", "string", "", "", "the level's name") S \
    X("level_sha256", "hex", "", "64 lowercase hex digits", "SHA-256 of the level's text as played (level-HASH.txt)") S \
    X("mode", "string", "", "flag, keys, explore, tutorial, ...", "the level's mode") S \
    X("seed", "integer", "", "", "the level's seed") S \
    X("cues", "integer", "bits", "1 hot-cold, 2 path, 4 poles, 8 arrow, 16 lanterns", "the cues the level has in force") S \
    X("tiling", "string", "", "4,Q with Q 4..8", "the tiling {4,Q}") S \
    X("room", "string", "", "CxR, C and R 3..5", "the room's size in cells") S \
    X("cell", "number", "m", "0.5..1.5", "the side of a room cell") S \
    X("started", "number", "s", "0..", "seconds since the session's start when the attempt began") S \
    X("steps", "integer", "count", "0..", "room steps") S \
    X("optimum", "integer", "count", "0.., or -1: none", "the fewest room steps that complete the level") S \
    X("time", "number", "s", "0..", "the level clock at the attempt's end") S \
    X("end", "string", "", "done, timeout, restart, quit, open, aborted, killed", "how the attempt ended")

/* summary.csv */
#define HOL_SESSION_SUMMARY_TABLE(X, S) \
    HOL_SESSION_SUMMARY_OLD_TABLE(X, S) S \
    X("session_no", "integer", "", "1..999; empty: none", "the session number (--session N)") S \
    X("study_sha256", "hex", "", "64 lowercase hex digits; empty outside a study", "SHA-256 of the study file (study-HASH.txt)") S \
    X("meta", "string", "", "KEY=VALUE joined with ;", "the --meta options")

/* steps-NNN.csv */
#define HOL_SESSION_STEP_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name") S \
    X("t", "number", "s", "0..", "the level clock at the step") S \
    X("step", "integer", "count", "1..", "the step's number in the attempt") S \
    X("col", "integer", "cell", "0..", "the room column after the step") S \
    X("row", "integer", "cell", "0..", "the room row after the step") S \
    X("dir", "string", "", "N, E, S, W", "the room direction of the step") S \
    X("yaw", "number", "deg", "0..360, 0 north, positive west", "the look direction in the room") S \
    X("tile", "string", "", "", "the tile address reached") S \
    X("orient", "integer", "quarter turns", "0..3", "the room's north relative to the tile's canonical heading") S \
    X("remaining", "integer", "count", "0.., or -1: none", "the optimal steps left from there") S \
    X("cues", "integer", "bits", "as summary.csv", "the cues in force") S \
    X("visible", "integer", "bits", "as cues, 32 sound", "the cues drawn after the step")

/* head-NNN.csv */
#define HOL_SESSION_HEAD_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name") S \
    X("t", "number", "s", "multiples of 0.1", "the sample's level time") S \
    X("frame_t", "number", "s", "0..", "the level time of the frame after the sample") S \
    X("x", "number", "m", "empty in a gap row", "head position east in the room") S \
    X("y", "number", "m", "empty in a gap row", "head height") S \
    X("z", "number", "m", "empty in a gap row", "head position south in the room") S \
    X("yaw", "number", "deg", "0..360; empty in a gap row", "head yaw, 0 north, positive west") S \
    X("pitch", "number", "deg", "empty in a gap row", "head pitch") S \
    X("col", "integer", "cell", "empty in a gap row", "the room column") S \
    X("row", "integer", "cell", "empty in a gap row", "the room row") S \
    X("tile", "string", "", "an address, or gap", "the tile address, or gap for samples a gap hides")

/* A tracked pose's seven columns (track-NNN.csv): position and unit
 * quaternion, prefix "head_", "left_" or "right_". */
#define HOL__COL_POSE(X, S, prefix, who) \
    X(prefix "x", "number", "m", "empty when not tracked", who " position east") S \
    X(prefix "y", "number", "m", "empty when not tracked", who " position up") S \
    X(prefix "z", "number", "m", "empty when not tracked", who " position south") S \
    X(prefix "qx", "number", "", "from -1 to 1; empty when not tracked", who " orientation, unit quaternion x") S \
    X(prefix "qy", "number", "", "from -1 to 1; empty when not tracked", who " orientation, unit quaternion y") S \
    X(prefix "qz", "number", "", "from -1 to 1; empty when not tracked", who " orientation, unit quaternion z") S \
    X(prefix "qw", "number", "", "from -1 to 1; empty when not tracked", who " orientation, unit quaternion w")

/* track-NNN.csv */
#define HOL_SESSION_TRACK_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name") S \
    X("sample", "integer", "", "0..", "the sample's index k (t = k / hz)") S \
    X("t", "number", "s", "k / hz", "the sample's level time") S \
    X("frame_t", "number", "s", "0..", "the level time of the frame after the sample") S \
    X("device", "string", "", "keyboard, gamepad, xr-touch, webxr-touch, webxr-hand, xr-hand, ..., gap; empty unknown", "the input device at the nearer frame") S \
    HOL__COL_POSE(X, S, "head_", "the head") S \
    HOL__COL_POSE(X, S, "left_", "the left hand's grip") S \
    HOL__COL_POSE(X, S, "right_", "the right hand's grip")

/* events.csv */
#define HOL_SESSION_EVENT_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name") S \
    X("t", "number", "s", "0..", "the attempt's level time (paused time does not count)") S \
    X("event", "string", "", "minimap, minimap-fixed, relocated", "what happened") S \
    X("value", "string", "", "hud, hand, off; relocated: metres, 3 decimals", "the minimap's new (or kept) place; relocated: the distance the room moved")

/* points.csv before the timestamps */
#define HOL_SESSION_POINT_OLD_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name") S \
    X("t", "number", "s", "0..", "the attempt's level time (paused time does not count)") S \
    X("target", "string", "", "", "the pointing target's name") S \
    X("pointed", "number", "deg", "0..360", "the direction pointed") S \
    X("true", "number", "deg", "0..360", "the target's true direction") S \
    X("flat", "number", "deg", "0..360", "the target's direction in the flat (Euclidean) reading") S \
    X("error_true", "number", "deg", "from -180 to 180", "pointed minus true") S \
    X("error_flat", "number", "deg", "from -180 to 180", "pointed minus flat") S \
    X("time", "number", "s", "0..", "the answer's time since the question appeared")

/* answers.csv before the timestamps */
#define HOL_SESSION_ANSWER_OLD_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("questionnaire", "string", "", "ssq, tlx, a study's name", "the questionnaire") S \
    X("when", "string", "", "level, condition, study, before_level, before_condition, before_study", "its placement (after its level, condition or study, or before it)") S \
    X("item", "string", "", "", "the item's name") S \
    X("kind", "string", "", "likert, scale, choice, ...", "the item's kind") S \
    X("value", "number", "", "the item's range", "the answer") S \
    X("time", "number", "s", "0..", "seconds from the item's screen to its confirm")

/* points.csv and answers.csv: the build before the timestamps' columns,
 * then them (input time: the session's clock, which the recording keeps,
 * so a replay writes the same values). */

/* points.csv */
#define HOL_SESSION_POINT_TABLE(X, S) \
    HOL_SESSION_POINT_OLD_TABLE(X, S) S \
    X("shown_ms", "integer", "ms", "0..", "the session's clock (its input time) when the question appeared") S \
    X("answered_ms", "integer", "ms", "0..", "the session's clock (its input time) at the answer's confirm")

/* answers.csv */
#define HOL_SESSION_ANSWER_TABLE(X, S) \
    HOL_SESSION_ANSWER_OLD_TABLE(X, S) S \
    X("shown_ms", "integer", "ms", "0..", "the session's clock (its input time) when the item appeared") S \
    X("answered_ms", "integer", "ms", "0..", "the session's clock (its input time) at the answer's confirm")

/* The platform shell's files. */

/* environment.csv (hol_shell_env.h) */
#define HOL_LOG_ENV_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
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

/* provenance.csv (hol_shell_prov.h) */
#define HOL_LOG_PROV_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("version", "string", "", "", "the release version (core/hol_version.h)") S \
    X("commit", "string", "", "git describe --always --dirty, or unknown", "the source commit built") S \
    X("build_date", "timestamp", "", "ISO 8601 UTC, or unknown", "the build's date (SOURCE_DATE_EPOCH, else the commit's)")

/* order.csv (hol_shell_prov.h) */
#define HOL_LOG_ORDER_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("study", "string", "", "", "the study's name") S \
    X("position", "integer", "", "0 practice, 1..", "the position in the participant's order") S \
    X("condition", "string", "", "a condition's name, practice", "the condition") S \
    X("level", "string", "", "", "the level's name") S \
    X("level_file", "string", "", "a path relative to the study file; empty: a generated level", "the level file the study names") S \
    X("level_sha256", "hex", "", "64 lowercase hex digits", "SHA-256 of the level's text as the session plays it")

/* tutorial.csv (a row per tutorial lesson done) */
#define HOL_SESSION_LESSON_TABLE(X, S) \
    X("session", "id", "", "YYYYMMDDTHHMMSSZ-XXXXXXXX", "the session's id: its start (UTC) and 8 random hex digits") S \
    X("participant", "string", "", "1..63 of A-Z a-z 0-9 . _ -; empty: none", "the participant's id (--participant ID)") S \
    X("attempt", "integer", "", "1..9999", "the attempt's number NNN in the log folder") S \
    X("level", "string", "", "", "the level's name (a tutorial)") S \
    X("lesson", "integer", "", "1..4", "the tutorial's lesson done") S \
    X("started", "number", "s", "0..", "the attempt's level time the lesson began") S \
    X("steps", "integer", "", "1..", "the room steps the lesson took") S \
    X("optimum", "integer", "", "1..", "the fewest room steps from where the lesson began") S \
    X("time", "number", "s", "0..", "the lesson's time: from started to its last step")

/* codebook.csv (hol_shell_codebook.h) */
#define HOL_LOG_CODEBOOK_TABLE(X, S) \
    X("file", "string", "", "a file name, NNN for an attempt's number", "the file the column is in") S \
    X("column", "string", "", "", "the column's name in the file's header") S \
    X("type", "string", "", "string, integer, number, hex, id, timestamp", "the column's type") S \
    X("unit", "string", "", "empty: none", "the unit of a number") S \
    X("allowed", "string", "", "", "the values allowed; empty: any of the type") S \
    X("meaning", "string", "", "", "what the column holds")

/* Every file of a log folder, F(name, TABLE), in codebook.csv's order. */
#define HOL_LOG_FILES(F)                                                                 \
    F("summary.csv", HOL_SESSION_SUMMARY_TABLE) F("steps-NNN.csv", HOL_SESSION_STEP_TABLE)  \
    F("head-NNN.csv", HOL_SESSION_HEAD_TABLE) F("track-NNN.csv", HOL_SESSION_TRACK_TABLE)   \
    F("events.csv", HOL_SESSION_EVENT_TABLE) F("points.csv", HOL_SESSION_POINT_TABLE)       \
    F("answers.csv", HOL_SESSION_ANSWER_TABLE) F("tutorial.csv", HOL_SESSION_LESSON_TABLE)  \
    F("environment.csv", HOL_LOG_ENV_TABLE)                                              \
    F("provenance.csv", HOL_LOG_PROV_TABLE) F("order.csv", HOL_LOG_ORDER_TABLE)             \
    F("codebook.csv", HOL_LOG_CODEBOOK_TABLE)

/* The session's headers. */
#define HOL_SESSION_SUMMARY_COLUMNS_OLD HOL_SESSION_SUMMARY_OLD_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_SUMMARY_COLUMNS HOL_SESSION_SUMMARY_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_STEP_COLUMNS HOL_SESSION_STEP_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_HEAD_COLUMNS HOL_SESSION_HEAD_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_TRACK_COLUMNS HOL_SESSION_TRACK_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_EVENT_COLUMNS HOL_SESSION_EVENT_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_POINT_COLUMNS_OLD HOL_SESSION_POINT_OLD_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_POINT_COLUMNS HOL_SESSION_POINT_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_ANSWER_COLUMNS_OLD HOL_SESSION_ANSWER_OLD_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_ANSWER_COLUMNS HOL_SESSION_ANSWER_TABLE(HOL_COL_NAME, ",")
#define HOL_SESSION_LESSON_COLUMNS HOL_SESSION_LESSON_TABLE(HOL_COL_NAME, ",")

#endif
