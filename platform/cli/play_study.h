/* play_study.h - a study file (core/hol_study.h) on this machine, for
 * `holonomy play --study` and `xr --study`: the file and its level files
 * read, the participant's order made from their number, the session's
 * levels labelled.
 *
 * Contract
 * - play_study_levels reads the study file (at most HOL_STUDY_TEXT_MAX
 *   bytes) and each level file it names (paths relative to the study
 *   file's folder, unless absolute), takes the participant's number from
 *   the trailing digits of participant (--participant, required: "P07" is
 *   7), and fills levels[0..*nlevels-1] in the participant's order, each
 *   named as play_read_level names a level file (a condition without a
 *   file: the condition's name) and labelled with its condition and
 *   position; study_name gets the study's name (for the session's
 *   metadata). play_study_announce then prints one line on stderr naming
 *   the order played: the caller calls it once every other check has
 *   passed (its session open), so that a refusal is its one line alone.
 *   fresh_in (NULL: no check): a log folder the session appends to; a
 *   participant with data there is refused (play_study_participant_new).
 *   outs: the command's outputs; a level file that is one of them (or a
 *   file of its --log folder) is refused before it is read
 *   (cli_check_reads, issue 39): "the study's level 'PATH' is ...".
 * - Every problem is one line on stderr naming the file and line (a bad
 *   study line, a level file's bad line with the condition it serves), and
 *   the exit status is returned: 2 bad input, 1 failure; 0 ok.
 */
#ifndef HOL_PLAY_STUDY_H
#define HOL_PLAY_STUDY_H

#include "../../core/hol_level.h"
#include "../../core/hol_rec.h"
#include "cli.h"

int play_study_levels(const char *cmd, const char *path, const char *participant,
                      const char *fresh_in, const cli_outs *outs, hol_level *levels, int *nlevels,
                      char study_name[HOL_REC_ID_MAX]);
void play_study_announce(void);


/* A participant who already has data is not started again unasked (issue
 * 26): with --append, when log_dir's summary.csv has a row of this study
 * and participant, one line on stderr ("participant P07 already has data
 * for study four in 'DIR' (3 attempts); --restart-participant plays their
 * order again from the start, --resume continues it") and 2. 0 when the folder has no
 * summary.csv or no such row; summary.csv is read as `report` and --resume
 * read it (summary_read.h: a damaged one refused alike, one line). */
int play_study_participant_new(const char *cmd, const char *log_dir, const char *study_name,
                               const char *participant);

/* --resume (issue 26): a participant's study continued where the log
 * folder says it stopped. levels[0..*nlevels-1] is the participant's whole
 * order (play_study_levels, with the geometry options applied); the rows
 * of this study and participant in log_dir (summary.csv, and the
 * attempt-NNN.live files a killed session left) say which levels are
 * finished: a level is finished when one of its attempts ended `done` or
 * `timeout` (its own rules ended it) and its questions are answered (issue
 * 39): its pointing answer in points.csv (a level with `point`; without
 * it the attempt does not count and the level is played again), every
 * item of its questionnaires in answers.csv (by that attempt's session
 * and attempt); `restart`, `quit`, `open`, `aborted`, `killed` leave it
 * unfinished. Attempts are matched to the order's levels by condition,
 * position and level_sha256 (one attempt per level, in order); the list
 * is cut to start at the first level not finished (a practice block
 * already done is not played again), the levels keeping their condition
 * and position. When that level's attempt counts but items are missing,
 * play_study_resume_meta gives the questions to ask (from the first
 * unanswered item) instead of its play. Refused with one line
 * and 2: no rows of theirs (nothing to resume), every level finished, or
 * a row the study given cannot have played (its condition, position and
 * level text are in none of the order's levels: another study file, or
 * another version of it), or more than 1024 `done`/`timeout` attempts of
 * theirs. 0 ok; summary.csv is read as `report` reads it (summary_read.h:
 * a symbolic link, a NUL byte, a row that is not the logs', a line too
 * long refused alike, one line; a byte order mark and CR LF read; a last
 * row without its newline left out); points.csv and answers.csv that
 * cannot be opened as cli_open_lines says (a row that cannot be read is
 * none: report names it). play_study_announce then adds where it resumed. */
int play_study_resume(const char *cmd, const char *log_dir, const char *study,
                      const char *participant, hol_level *levels, int *nlevels);
const char *play_study_resume_note(void);
/* The last play_study_resume's questions to ask (issue 39) into m's
 * ask_session, ask_attempt, ask_item (0, "" when it plays its first level:
 * see core/hol_rec.h). */
void play_study_resume_meta(hol_rec_meta *m);

#endif
