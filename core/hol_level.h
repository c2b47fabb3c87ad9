/* hol_level.h - level files (SPEC section 5): the one parser every platform
 * uses (game, play, replay, xr, Android, the web), and a level as a session
 * carries it: its name, its text and the parsed level.
 *
 * Contract
 * - hol_level_parse reads a level file's text into a hol_app_level: one
 *   `KEY VALUE...` per line, `#` starts a comment, blank lines are ignored,
 *   a line may end in CR LF. Keys: SPEC section 5 and the added ones (README
 *   "Level files"). Bounds: at most HOL_LEVEL_TEXT_MAX bytes (a last line end
 *   added if missing: the text as kept), lines of at
 *   most HOL_LEVEL_LINE_MAX bytes, no NUL byte.
 * - On bad input it returns a typed error and fills *err: the 1-based line
 *   of the text, the other line a conflict names (0: none) and a message
 *   without line numbers; hol_level_err_format makes the one line
 *   "line N: MESSAGE" (a conflict: "... (line M)" or "... on line M"),
 *   numbering lines from `first` (a recording's level starts later in its
 *   file). Errors: HOL_EPARSE (not the grammar: an unknown key, a wrong
 *   value count, a bad word or address), HOL_ERANGE (a number out of its
 *   range), HOL_EARG (the level does not hold together: no mode, a start
 *   walk leaving the room, a placement on an objective, no free tile for a
 *   drawn objective), HOL_ENOMEM (too long: the text, a line, the
 *   placements). *out is untouched on error.
 * - Objectives by distance are drawn from the seed after the last line:
 *   the same text always gives the same level.
 * - hol_level_make makes a session's level from a name and a file's text:
 *   the name must survive a recording's "level NAME" line (1 to
 *   HOL_LEVEL_NAME_MAX - 1 bytes, no NUL, CR or LF: else HOL_EARG with
 *   line 0); the text is kept with LF line ends (CR LF read as LF, a last
 *   line without its newline given one), which is exactly what a recording
 *   carries and replays, and its SHA-256 (hol_sha256.h) is kept: the
 *   `sha256sum` of a file with LF line ends. The hash covers the text up
 *   to a line HOL_LEVEL_LAST_MARK (hashed bytes; all without one), so a
 *   study's level has one hash whether or not it is the participant's
 *   last (issue 35), and skips the lines from HOL_LEVEL_FIRST_MARK to
 *   HOL_LEVEL_FIRST_END (both included: the participant's first level's),
 *   so it has one hash at every position too. hol_level_hashed_text writes
 *   the hashed bytes (what `sha256sum` of level-HASH.txt reads). A study's
 *   labels start empty.
 * - Pure: no allocation, no I/O, no globals.
 */
#ifndef HOL_LEVEL_H
#define HOL_LEVEL_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include "hol_app.h"
#include "hol_err.h"

#define HOL_LEVEL_TEXT_MAX 4095 /* bytes of a level file */
#define HOL_LEVEL_LINE_MAX 511  /* bytes of one line, without its newline */
#define HOL_LEVEL_NAME_MAX 64   /* with the NUL */
#define HOL_LEVEL_MAX_DIST 10   /* objectives by distance: 1..10 tiles */
/* The line before a study's lines for a participant's last level (its
 * closing, its questionnaires `after study`): the hash stops there. */
#define HOL_LEVEL_LAST_MARK "# the participant's last level (not in level_sha256):"
/* The lines around a study's lines for a participant's first level (its
 * questionnaires `before study`, when it has no practice): the hash skips
 * them, marks included. */
#define HOL_LEVEL_FIRST_MARK "# the participant's first level (not in level_sha256):"
#define HOL_LEVEL_FIRST_END "# the participant's first level: end"

typedef struct hol_level_err {
    hol_err code;
    long line;    /* 1-based line of the text; 0: the name or the whole text */
    long other;   /* the line a conflict names, or 0 */
    int other_on; /* 1: "... on line M", 0: "... (line M)" */
    char msg[192];
} hol_level_err;

typedef struct hol_level {
    char name[HOL_LEVEL_NAME_MAX];
    char text[HOL_LEVEL_TEXT_MAX + 2]; /* LF line ends, NUL-terminated */
    size_t len;
    uint8_t sha256[32];
    size_t hashed; /* text's bytes up to the last level's mark (see above) */
    size_t cut_from, cut_to; /* text's bytes [cut_from, cut_to) the hash
                                skips (the first level's lines); 0, 0 */
    hol_app_level lvl;
    /* a study's labels (core/hol_study.h): the condition it is played
     * under and its position in the participant's order; "" and 0 outside
     * a study (hol_level_make clears them) */
    char condition[HOL_LEVEL_NAME_MAX];
    int position;
    int added; /* lines hol_level_set_geometry put before the file's first */
} hol_level;

hol_err hol_level_parse(const char *text, size_t len, hol_app_level *out,
                        hol_level_err *err);

/* One line of a level file checked on its own (a study's set line): its
 * key, value count and values as hol_level_parse reads them; what needs
 * the other lines (a mode's objectives, conflicts) is not checked; an
 * address may be of any tiling {4,4}..{4,8} (the level's tiling line may
 * be another line). Errors as hol_level_parse's, with line 1. */
hol_err hol_level_line_check(const char *s, size_t n, hol_level_err *err);

/* The line of the level's file (lv->text less the lines the geometry
 * options added) that gives its first objective: `flag` or
 * `flag-distance` in mode flag, `keys`, `keys-distance`, `chest` or
 * `chest-distance` in mode keys; 0 when there is none. A level that cannot
 * start (no walk inside its room reaches an objective, or its optimum
 * cannot be proved exact) is refused naming it. */
long hol_level_objective_line(const hol_level *lv);

/* Writes "line N: MESSAGE..." (N counted from first for line 1; just the
 * message when err->line is 0) into out; returns out. */
char *hol_level_err_format(const hol_level_err *err, long first, char *out, size_t cap);
/* *e (when e is not NULL) cleared and set: code, line, other, the message
 * fmt with ap; returns code (the level's and the study's parsers fail
 * through it). */
hol_err hol_level_err_vset(hol_level_err *e, hol_err code, long line, long other,
                           const char *fmt, va_list ap);

/* 1 when name (len bytes) can be a level's name: see the contract. */
int hol_level_name_ok(const char *name, size_t len);

hol_err hol_level_make(const char *name, size_t name_len, const char *text, size_t len,
                       hol_level *out, hol_level_err *err);

/* ---- geometry (SPEC 7; docs/levels.md) ----
 * A level's lines `tiling 4 Q`, `room C R` and `cell M` set
 * hol_app_level.tiling_q, room_cols/rows and cell_m (0 when the line is
 * absent: {4,5}, 3 x 3, 1 m). The geometry lines are read before the
 * others, so addresses anywhere in the file are of the level's tiling. In
 * the flat {4,4} an objective off the room's own tiles is bad input
 * (HOL_EARG naming its line) and objectives by distance are drawn among
 * the room's tiles; in {4,5}..{4,8} the app's navigator decides the reach
 * (hol_app_start_level: HOL_EUNREACH; only {4,8} has tiles out of reach).
 * A tutorial is refused in {4,4} and {4,8} (its lessons need walks that
 * those rooms do not have).
 *
 * hol_level_parse_cell: "D[.DDD]" metres (at most 3 decimals), 0.5..1.5:
 * HOL_EPARSE (not that form), HOL_ERANGE (out of range); the value is the
 * double nearest the decimal. The same rule for the level line and --cell.
 * hol_level_format_cell: the shortest text of m with at most 3 decimals
 * ("1", "0.75", "1.25"); what logs and recordings write.
 * hol_level_set_geometry: the options a command was given (0: not given)
 * applied to a made level: a level without the line gets it (the line
 * prepended to its text, which is what logs and recordings keep, so a
 * replay needs no options; the level parsed again); a level whose own line
 * says otherwise is refused (HOL_EARG, line 0: "its own line 'tiling 4 5'
 * differs from the {4,6} asked for"); errors of the new text as
 * hol_level_make's (HOL_ENOMEM: too long with the lines). A tutorial
 * level takes only the cell size (the player's space): its lessons are
 * made for {4,5} 3 x 3, so it keeps them unless its own lines say
 * otherwise (q, cols and rows are ignored for it), on every platform. */
hol_err hol_level_parse_cell(const char *s, size_t len, double *out_m);
char *hol_level_format_cell(double m, char out[16]);
/* The bytes lv's SHA-256 covers (see above) into out; their count. */
size_t hol_level_hashed_text(const hol_level *lv, char out[HOL_LEVEL_TEXT_MAX + 2]);

hol_err hol_level_set_geometry(hol_level *lv, int q, int cols, int rows, double cell_m,
                               hol_level_err *err);

#endif
