/* hol_study.h - study designs: a study file names conditions (levels and
 * the level lines that make them differ) and a counterbalancing rule; a
 * participant's number gives the order in which they play the conditions.
 * `holonomy play --study`, `xr --study` and the web page's study= run it.
 *
 * Contract
 * - The file: one `KEY VALUE...` per line, `#` starts a comment, blank
 *   lines are ignored, CR LF is read as LF. At most HOL_STUDY_TEXT_MAX
 *   bytes, lines of at most HOL_STUDY_LINE_MAX bytes, no NUL byte.
 *     study NAME              once, before the first condition (required)
 *     counterbalance RULE     once, before the first condition: williams
 *                             (the default), latin, complete or fixed
 *     practice LEVEL          before the first condition, any number:
 *                             levels everyone plays first, in this order
 *                             (condition "practice", position 0)
 *     set KEY VALUE...        before the first condition: a level line for
 *                             every level of every condition
 *     condition NAME          starts a condition (1..HOL_STUDY_MAX_CONDITIONS)
 *     level LEVEL             in a condition: one of its levels (trials), in
 *                             order; none: the condition's level is made of
 *                             its set lines alone and named after it
 *     set KEY VALUE...        in a condition: a level line for its levels
 *     allow minimap-toggle    before the first condition: a condition's
 *                             `set minimap` is where its levels start, and
 *                             the minimap key still moves it
 *     instructions TEXT       once before the first condition (the
 *                             practice's) and once in a condition (its):
 *                             shown before the first level of the practice
 *                             or the condition until confirm (a level line,
 *                             hol_app_level.instructions: the rest of the
 *                             line, printable ASCII and Latin-1 in UTF-8,
 *                             at most 6 lines of 46
 *                             characters when wrapped; checked as a level
 *                             line)
 *     question ID ...         before the first condition: a questionnaire
 *                             item (core/hol_ask.h: likert or choice)
 *     questionnaire NAME ITEM...  before the first condition: a
 *                             questionnaire of those items (question IDs)
 *     questionnaire NAME before level|condition|study  before the first
 *                             condition: asked when every level of the
 *                             conditions starts, a condition's first
 *                             level, or the participant's first level (the
 *                             first practice level, if any), before its
 *                             instructions: `ask NAME before_WHEN` lines
 *     questionnaire NAME after level|condition|study  before the first
 *                             condition: asked after every level of the
 *                             conditions, after each condition's last
 *                             level, or after the participant's last
 *                             level (NAME: one defined, or the presets
 *                             ssq and tlx; at most HOL_APP_MAX_ASKS);
 *                             the level carries it as `question` and
 *                             `ask NAME WHEN ID...` level lines (after the
 *                             set lines), so logs and recordings hold it
 *     closing TEXT            once, before the first condition: the closing
 *                             screen after the participant's last level
 *                             (default: HOL_SESSION_CLOSING, which the
 *                             session shows)
 *   NAME: 1..63 letters, digits, '.', '_', '-' (hol_rec_id_ok); condition
 *   names are unique and not "practice". LEVEL: a level file's path (one
 *   field, 1..255 bytes), relative to the study file's folder; the
 *   platform reads it. A set line is a level line (core/hol_level.h) and is
 *   checked as one here (hol_level_line_check): any level key, so a key the
 *   level format gains (tiling, room, ...) is a condition without a change
 *   to this format.
 * - A condition's level (hol_study_make_level): the level file's text
 *   without its lines of a key that a set line gives (a set line replaces
 *   every line of its key: `set place ...` replaces all placements), then
 *   a comment line naming the study and condition, then the study's set
 *   lines (those of a key the condition also sets left out), then the
 *   condition's, then `fixed minimap` when a set line in force gives
 *   `minimap` and the study has no `allow minimap-toggle` (the condition's
 *   minimap holds: the key says "fixed in this study"). Then, on the
 *   first level of the practice or of a condition with an `instructions`
 *   line, that line (the file's own `instructions` lines left out), and on
 *   the participant's last level (position = the number of conditions, the
 *   condition's last level) the line HOL_LEVEL_LAST_MARK, then the
 *   questionnaires `after study` and the study's `closing` line (the
 *   file's own left out): the level's hash stops at the mark, so a level
 *   has one SHA-256 at every position (issue 35). The questionnaires
 *   `before study` on a condition's level (the participant's first, no
 *   practice) are between HOL_LEVEL_FIRST_MARK and HOL_LEVEL_FIRST_END,
 *   which the hash skips, where they were (before the other
 *   questionnaires); a question they share with another questionnaire of
 *   the level comes before the first mark at every position. With none of these the text is the file's, unchanged (the same
 *   SHA-256); practice levels are the files as they are but for their
 *   instructions and the first one's `before study` questionnaires.
 * - Counterbalancing (hol_study_order, hol_study_square): participant
 *   number P (1, 2, ...) plays row (P - 1) mod R of the rule's square of
 *   the n conditions, R = hol_study_rows:
 *   - williams: a balanced Latin square (Williams 1949): row r is the first
 *     row 0, 1, n-1, 2, n-2, ... with r added to every entry (mod n). Each
 *     condition stands once in each position, and for even n each ordered
 *     pair of conditions is adjacent (A right before B) in exactly one row
 *     (R = n). For odd n no n-row square can do that: the rows are followed
 *     by their mirror images (R = 2n), so each condition stands twice in
 *     each position and each ordered pair is adjacent in exactly two rows.
 *   - latin: the cyclic Latin square, row r = r, r+1, ... (mod n): each
 *     condition once in each position, carry-over not balanced (R = n).
 *   - complete: every order, in lexicographic order (R = n!).
 *   - fixed: the file's order for everyone (R = 1).
 * - A participant's session: the practice levels, then each condition's
 *   levels in the participant's order (hol_study_session), at most
 *   HOL_STUDY_MAX_LEVELS in all (HOL_REC_MAX_LEVELS: a recording holds
 *   them).
 * - Errors (hol_level_err, formatted with hol_level_err_format): HOL_EPARSE
 *   (not the grammar), HOL_EARG (a name twice, a line out of place, no
 *   study or condition line, "practice" as a condition), HOL_ENOMEM (too
 *   long; too many conditions, levels or set lines), with the 1-based line
 *   of the study file (0: the whole file).
 * - Pure: no allocation, no I/O, no globals.
 */
#ifndef HOL_STUDY_H
#define HOL_STUDY_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_level.h"
#include "hol_rec.h"

#define HOL_STUDY_TEXT_MAX 16383
#define HOL_STUDY_LINE_MAX 511
#define HOL_STUDY_PATH_MAX 256 /* with the NUL */
#define HOL_STUDY_MAX_LEVELS HOL_REC_MAX_LEVELS
#define HOL_STUDY_MAX_CONDITIONS HOL_STUDY_MAX_LEVELS
#define HOL_STUDY_MAX_SETS 64
#define HOL_STUDY_PRACTICE "practice"

typedef enum hol_study_rule {
    HOL_STUDY_WILLIAMS = 0,
    HOL_STUDY_LATIN,
    HOL_STUDY_COMPLETE,
    HOL_STUDY_FIXED
} hol_study_rule;

/* A piece of the study's text (hol_study.text): off, len; its line. */
typedef struct hol_study_span {
    uint16_t off, len;
    long line;
} hol_study_span;

typedef struct hol_study_condition {
    char name[HOL_REC_ID_MAX];
    long line;
    int first_level, nlevels; /* into hol_study.levels */
    int first_set, nsets;     /* into hol_study.sets */
    hol_study_span instructions; /* its `instructions TEXT` line (len 0: none) */
} hol_study_condition;

/* Questionnaires of a study (docs/research.md "Questionnaires"). */
#define HOL_STUDY_MAX_QUESTIONS HOL_APP_MAX_QUESTIONS
#define HOL_STUDY_MAX_QUESTIONNAIRES 8

typedef struct hol_study_questionnaire {
    char name[HOL_APP_ID_MAX];
    hol_study_span items;     /* its item IDs, blank separated */
} hol_study_questionnaire;

typedef struct hol_study_ask {
    char name[HOL_APP_ID_MAX]; /* a questionnaire's, or ssq, tlx */
    int when;                  /* hol_app_ask_when */
    long line;
} hol_study_ask;

typedef struct hol_study {
    char name[HOL_REC_ID_MAX];
    hol_study_rule rule;
    int npractice;                          /* levels[0..npractice-1] */
    int nconditions;
    hol_study_condition conditions[HOL_STUDY_MAX_CONDITIONS];
    int nlevels;                            /* practice and conditions' */
    hol_study_span levels[HOL_STUDY_MAX_LEVELS]; /* LEVEL paths (len 0: a
                                               condition without a file) */
    int allow_minimap_toggle;               /* `allow minimap-toggle` */
    hol_study_span practice_instructions;   /* `instructions TEXT` before the
                                               first condition (len 0: none) */
    hol_study_span closing;                 /* `closing TEXT` (len 0: none) */
    int nquestions;                         /* `question` lines */
    hol_study_span questions[HOL_STUDY_MAX_QUESTIONS];
    char question_ids[HOL_STUDY_MAX_QUESTIONS][HOL_APP_ID_MAX];
    int nquestionnaires;                    /* `questionnaire NAME ITEM...` */
    hol_study_questionnaire questionnaires[HOL_STUDY_MAX_QUESTIONNAIRES];
    int nasks;                              /* `questionnaire NAME after WHEN` */
    hol_study_ask asks[HOL_APP_MAX_ASKS];
    int nglobal;                            /* sets[0..nglobal-1]: the study's */
    int nsets;
    hol_study_span sets[HOL_STUDY_MAX_SETS]; /* "KEY VALUE..." */
    char text[HOL_STUDY_TEXT_MAX + 1];      /* the file, NUL-terminated */
} hol_study;

hol_err hol_study_parse(const char *text, size_t len, hol_study *out, hol_level_err *err);

/* The number of rows of rule's square of n conditions (see the contract);
 * 0 for n outside 1..HOL_STUDY_MAX_CONDITIONS. */
uint64_t hol_study_rows(hol_study_rule rule, int n);

/* Row `row` (0 <= row < hol_study_rows) of the square: out[k] the
 * condition (0..n-1) at position k. HOL_EARG for a bad rule, n or row. */
hol_err hol_study_square(hol_study_rule rule, int n, uint64_t row, int *out);

/* The order of participant number participant (>= 1) in s: out[k] the
 * condition at position k (k < s->nconditions). HOL_EARG for 0. */
hol_err hol_study_order(const hol_study *s, uint64_t participant, int *out);

/* A participant's levels, in play order: out[i] the index into s->levels
 * of the i-th level, out_cond[i] its condition (-1: practice) and
 * out_pos[i] its position (1-based; 0: practice). Returns the count. */
int hol_study_session(const hol_study *s, const int *order, int *out, int *out_cond,
                      int *out_pos);

/* The path of level i (NUL-terminated into path, HOL_STUDY_PATH_MAX
 * bytes), or "" for a condition without a level file. */
void hol_study_level_path(const hol_study *s, int i, char path[HOL_STUDY_PATH_MAX]);

/* The participant's number in an id: its trailing decimal digits ("P07":
 * 7, "12": 12, "s2-p031": 31), or 0 when it has none, they are 0 or above
 * 10^9, or the id is not all digits and does not begin with a letter
 * ("-1", "1e3", "0x10": 0, refused, not 1, 3 and 10). */
uint64_t hol_study_participant_number(const char *id);

/* A participant id in its one spelling (docs/studies.md "Participant
 * ids"), so that "P02", "002" and "p2" are not three people: an id that is
 * a number, alone or after one 'P' or 'p', is written 'P' and the number
 * without leading zeros, at least two digits ("2", "002", "p2", "P002":
 * "P02"; "P123" stays); any other id stays as given. Writes at most cap
 * bytes with the NUL into out (out may be id) and returns
 * HOL_STUDY_ID_SAME (the id is in its spelling), HOL_STUDY_ID_RENAMED (out
 * differs from id), or HOL_STUDY_ID_AMBIGUOUS when the id is a number in
 * another spelling that a reader might take for that participant (out:
 * the spelling it might mean): with its case ignored and its '.', '_' and
 * '-' left out it is such a number ("P-02", "p_2", "0.2"), or its
 * spelling is longer than cap - 1 bytes. Pure; O(length). */
enum { HOL_STUDY_ID_SAME, HOL_STUDY_ID_RENAMED, HOL_STUDY_ID_AMBIGUOUS };
int hol_study_participant_id(const char *id, char *out, size_t cap);

/* Level i of the study made for a session (hol_level_make): from the level
 * file's text (file, len; NULL for a condition without a file), its set
 * lines as in the contract, named name (NULL: the condition's name),
 * labelled with the condition's name and position (practice:
 * HOL_STUDY_PRACTICE, and position 0 whatever is given). On error *err names a
 * line of the level file (*out_in_study 0) or of the study (1: a set line,
 * or the condition's line when the composed level is too long or
 * lacks a line), as hol_level_make's errors do; a level too long names
 * what made it so (its set lines, the questions asked after it, the
 * instructions or the closing). A condition's level is checked at every
 * position its condition can take (issue 39: what it carries, the closing
 * and the asks `after study`, depends on being the last), so a study is
 * refused for every participant or for none: an error at another position
 * than the one given ends " (at position P of N, the last)" or "(..., not
 * the last)". out is the level at the position given. */
hol_err hol_study_make_level(const hol_study *s, int i, int position, const char *file,
                             size_t len, const char *name, hol_level *out, hol_level_err *err,
                             int *out_in_study);

/* The condition of level i (-1: a practice level). */
int hol_study_level_condition(const hol_study *s, int i);

#endif
