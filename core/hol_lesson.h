/* hol_lesson.h - lessons for a class (issue 37): six lessons, each in three
 * beats, predict (a question answered before walking), walk (a route of
 * room steps) and check (the answer and why), in any tiling {4,Q}; {4,4}
 * is the flat comparison. docs/teaching.md says how a class uses them.
 *
 * Contract
 * - hol_lesson_facts computes what lesson n (1..HOL_LESSONS) states in the
 *   tiling {4,q} (4..8), from the core alone (no number is typed into a
 *   text): its route (room steps from the start cell of a room of at least
 *   3 x 3, staying within one cell of it), the tile it ends on and that
 *   tile's distance from O (the fewest steps home: the address's length,
 *   which the navigator's fewest steps inside a 3 x 3 room equal for these
 *   routes; tests/test_lesson.c checks both), the flat grid's steps home
 *   (the room cells between the route's end and its start), the squares at
 *   a corner (q) and a corner's angle (360 / q degrees; a square's four
 *   corners 4 x that), the true bearing from the route's end to O (SPEC 8),
 *   the tiles at distance 1..3 here and in {4,4} and {4,5} (SPEC 9), how
 *   often the square N, E, S, W is walked until it ends on O again
 *   (q / gcd(4, q)), and the predict question's right answer (a choice's
 *   index, or a number).
 * - hol_lesson_fill makes the lesson a level (the level line `lesson N`,
 *   docs/levels.md): mode explore with the route as its task
 *   (hol_app_level.route), the predict question asked before the level
 *   (questionnaire "predict", item "lessonN": the study's answers.csv),
 *   the walk's instructions, lesson 3's pointing question (point start),
 *   and the check as the closing screen. Every text fits its screen
 *   (HOL_APP_SCREEN_LINES lines of HOL_APP_SCREEN_COLS).
 *   The level holds the English texts (the logged choice is the English
 *   label, as every log is English); the app shows them in its language
 *   (hol_lesson_question, hol_lesson_text with hol_app's language).
 * - hol_lesson_text expands a lesson's text in a language (HOL_LANG_*,
 *   core/hol_str.h; hol_lesson_text.c: every text a lesson shows, one
 *   table with English, German and Dutch side by side; a build without
 *   Dutch and a lang out of range read English) with its facts: {name}
 *   places a fact (hol_lesson_text.c lists them). Every language's text
 *   fits where the English one does (tests/test_str.c).
 * - Pure: no allocation, no I/O, no globals but constant tables.
 */
#ifndef HOL_LESSON_H
#define HOL_LESSON_H

#include <stddef.h>
#include <stdint.h>

#include "hol_app.h"
#include "hol_err.h"
#include "hol_tile.h"

#define HOL_LESSONS 6
#define HOL_LESSON_TEXT_MAX HOL_APP_SCREEN_TEXT

/* The predict question: a choice (answer the choice's index) or a number
 * (a scale lo..hi in step; answer the number). */
typedef struct hol_lesson_facts {
    int lesson, q;
    uint8_t route[HOL_APP_ROUTE_MAX];
    int nroute;
    hol_tile end;           /* the route's last tile */
    int home;               /* its distance from O: the fewest steps home */
    int flat_home;          /* the room cells between the end and the start */
    double corner_deg;      /* 360 / q */
    double square_deg;      /* 4 x corner_deg */
    int has_bearing;        /* 0: the route ends on O */
    double bearing_deg;     /* the true bearing from the end to O */
    uint64_t count[4], flat_count[4], curved_count[4]; /* tiles at 0..3: here, {4,4}, {4,5} */
    int repeats;            /* the square N, E, S, W walked this often ends on O */
    int choice;             /* 1: a choice question; 0: a number */
    int answer;             /* the right choice's index, or the number */
} hol_lesson_facts;

/* Errors: HOL_EARG (n not 1..HOL_LESSONS, q not 4..8). */
hol_err hol_lesson_facts_of(int n, int q, hol_lesson_facts *out);

/* The lesson's texts (the string table's columns). */
enum hol_lesson_part {
    HOL_LESSON_TITLE = 0,  /* "Corners" */
    HOL_LESSON_GOAL,       /* what a pupil should take away */
    HOL_LESSON_QUESTION,   /* the predict question */
    HOL_LESSON_WALK,       /* the walk's instructions */
    HOL_LESSON_CHECK,      /* the answer and why */
    HOL_LESSON_HINT,       /* a hint (the worksheet's, the puzzle's) */
    HOL_LESSON_PARTS
};

/* Part `part` of lesson f->lesson, expanded with f into out (cap bytes,
 * NUL-terminated): its length, or -1 when it does not fit. */
int hol_lesson_text(const hol_lesson_facts *f, int lang, int part, char *out, size_t cap);
/* The predict question's choices (f->choice) or the scale's anchors in
 * lang: the k-th label (k from 0), or NULL past the last. */
const char *hol_lesson_label(const hol_lesson_facts *f, int lang, int k);
/* The table's raw entry k of lesson n in lang, for tests/test_str.c: k
 * below HOL_LESSON_PARTS + HOL_APP_MAX_CHOICES a part or a label, then
 * (with n 1) the words facts are said in; NULL for none (or a language
 * the build leaves out). */
const char *hol_lesson_entry(int n, int lang, int k);
/* The predict question of f's lesson in lang as a level's item (id
 * "lessonN", its text, choices or scale). Errors: HOL_ERANGE (a text does
 * not fit the item). */
hol_err hol_lesson_question(const hol_lesson_facts *f, int lang, hol_app_question *qn);
/* The scale of a number question: lo, hi, step. */
void hol_lesson_scale(const hol_lesson_facts *f, int *lo, int *hi, int *step);

/* Lesson n in {4,q} as a level's fields (see the contract), in English:
 * writes mode, route, questions, asks, instructions, closing and point of
 * *L, nothing else. Errors: HOL_EARG. */
hol_err hol_lesson_fill(int n, int q, hol_app_level *L);

#endif
