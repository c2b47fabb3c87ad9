/* hol_quiz.h - a class's pre-test and post-test (issue 37): the same four
 * concepts as the lessons (a square walk closes or not, the squares at a
 * corner and a square's angle sum, the tiles at a distance, the fewest
 * steps home), with other numbers before and after; docs/teaching.md
 * says how a class uses them and `holonomy report --class` sums them up.
 *
 * Contract
 * - Phase HOL_QUIZ_PRE or HOL_QUIZ_POST; item k of 0..HOL_QUIZ_ITEMS-1
 *   (concepts square, corner, growth, home). hol_quiz_item_of gives an
 *   item's question in the tiling {4,q} (4..8): its id ("CONCEPT_qQ", so
 *   an answer names its own key), its text, choices or scale, and the
 *   right answer (a choice's label, or a number) computed from the core
 *   alone (room steps walked from the start of a 3 x 3 room, the tiles'
 *   counts of SPEC 9), never typed into a text.
 * - hol_quiz_item_in: the same item with its words (text, choices,
 *   anchors) in lang (core/hol_str.h), as the app shows it; its id and
 *   right answer are the English item's (the logs keep English).
 * - hol_quiz_fill makes the test a level (the level line `quiz pre|post`,
 *   docs/levels.md): mode explore, its four items asked before the level
 *   as questionnaire "pretest" or "posttest" (answers.csv), then a level
 *   of HOL_QUIZ_LEVEL_S seconds (it ends at its time limit: the test takes
 *   no walk) and a closing screen saying it is done.
 * - hol_quiz_key(questionnaire, item, right, cap): the right answer's text
 *   (a choice's label or a number in decimal) of an answer logged under
 *   that questionnaire and item id, and its concept's index; -1 when the
 *   pair is not a quiz's item. A value is right when it equals that text.
 * - Pure: no allocation, no I/O, no globals but constant tables; the
 *   items in one table (hol_quiz.c), their words the string table's.
 */
#ifndef HOL_QUIZ_H
#define HOL_QUIZ_H

#include <stddef.h>

#include "hol_app.h"
#include "hol_err.h"

#define HOL_QUIZ_ITEMS 4
#define HOL_QUIZ_LEVEL_S 0.5
enum { HOL_QUIZ_PRE = 0, HOL_QUIZ_POST = 1 };

typedef struct hol_quiz_item {
    hol_app_question question;          /* id, text, choices or scale */
    char right[HOL_APP_LABEL_MAX];      /* the right answer as logged */
    int concept;                        /* 0..HOL_QUIZ_ITEMS-1 */
} hol_quiz_item;

/* The concepts' names (k 0..HOL_QUIZ_ITEMS-1), or NULL. */
const char *hol_quiz_concept(int k);
/* The questionnaire's name of a phase: "pretest", "posttest"; NULL else. */
const char *hol_quiz_name(int phase);
/* Errors: HOL_EARG (phase, k or q out of range). */
hol_err hol_quiz_item_in(int phase, int k, int q, int lang, hol_quiz_item *out);
hol_err hol_quiz_item_of(int phase, int k, int q, hol_quiz_item *out);
/* Errors: HOL_EARG, HOL_ERANGE (a text does not fit). */
hol_err hol_quiz_fill(int phase, int q, hol_app_level *L);
int hol_quiz_key(const char *questionnaire, const char *item, char *right, size_t cap);

#endif
