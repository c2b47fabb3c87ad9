/* hol_ask.h - questionnaire items: the `question` line (hol_ask_question.c),
 * the presets ssq and tlx as one table (hol_ask.c: items, scale, anchors,
 * scores) that the level parser, the study and the report read (docs/research.md
 * "Questionnaires"; docs/hacking.md "Adding a questionnaire preset").
 *
 * Contract
 * - A question line (a level's or a study's):
 *     question ID likert LO HI "TEXT" "LOW" "HIGH"
 *     question ID choice "TEXT" "A" "B" ...
 *   ID: 1..31 letters, digits, '_', '-', '.' (hol_ask_id_ok), not a preset's
 *   name; likert: integers LO < HI in 0..100, at most HOL_APP_MAX_SCALE marks
 *   (step 1); choice: 2..HOL_APP_MAX_CHOICES choices. Quoted fields: any
 *   printable ASCII but '"' and Latin-1 in UTF-8 (hol_face_text_bad; no
 *   escapes), TEXT 1..95 bytes, an anchor or a
 *   choice 1..23; fields separated by blanks. hol_ask_parse_question fills
 *   *q or returns HOL_EPARSE / HOL_ERANGE with a message (msg, cap).
 * - Presets (hol_ask_preset): `ssq`, the 16 items of the Simulator Sickness
 *   Questionnaire (Kennedy, Lane, Berbaum and Lilienthal 1993), each 0..3
 *   (none, slight, moderate, severe), IDs in the table's order; `tlx`,
 *   the six raw NASA-TLX scales (Hart and Staveland 1988) mental, physical,
 *   temporal, performance, effort, frustration, 0..100 in steps of 5 (21
 *   marks). hol_ask_ssq_weight gives an SSQ item's subscales (bit 0 nausea,
 *   1 oculomotor, 2 disorientation).
 * - The standard rows' words (items' texts, anchors) are the string
 *   table's (core/hol_str.h: HOL_S_SSQ_*, HOL_S_TLX_*, every language),
 *   and their strings in the row are NULL; a row a build adds writes its
 *   English in place.
 * - The table (hol_ask_preset_at, 0..hol_ask_npresets() - 1): a preset's
 *   NAME (an ask names it, a question ID may not), its items' scale LO..HI
 *   in STEP, anchors (an item's own, else the preset's), and scores: score
 *   k = (the sum of the raw sums of the scales in scores[k].scales) x
 *   weight / div, where scale j's raw sum adds the answers of the items
 *   with bit j; hol_ask_score computes them in that order (ssq: total,
 *   nausea, oculomotor, disorientation; tlx: raw). The report's columns
 *   are NAME_SCORE, in table order. A build may add rows after the
 *   standard ones by defining HOL_ASK_MORE_PRESETS (a test does).
 * - Pure data and parsing: no allocation, no globals but constant tables.
 */
#ifndef HOL_ASK_H
#define HOL_ASK_H

#include <stddef.h>

#include "hol_app.h"
#include "hol_err.h"

#define HOL_ASK_SSQ_ITEMS 16
#define HOL_ASK_TLX_ITEMS 6

#define HOL_ASK_MAX_PRESETS 8    /* the table's rows, at most */
#define HOL_ASK_PRESET_ITEMS 16  /* a preset's items, at most */
#define HOL_ASK_PRESET_SCALES 8  /* its scales (bits of an item's scales) */
#define HOL_ASK_PRESET_SCORES 4  /* its scores */
#define HOL_ASK_NAMES_MAX 96     /* "ssq or tlx" and its NUL */

typedef struct hol_ask_item_def {
    const char *id, *text;
    const char *low, *high; /* NULL: the preset's anchors */
    unsigned scales;        /* bit j: weighs in scale j */
} hol_ask_item_def;

typedef struct hol_ask_score_def {
    const char *name;   /* the report's column NAME_name */
    unsigned scales;    /* the scales whose raw sums it adds */
    double weight, div; /* sum x weight / div */
} hol_ask_score_def;

typedef struct hol_ask_preset_def {
    const char *name;
    int lo, hi, step;       /* every item's scale */
    const char *low, *high; /* the anchors of items without their own */
    int nitems;
    hol_ask_item_def items[HOL_ASK_PRESET_ITEMS];
    int nscores;
    hol_ask_score_def scores[HOL_ASK_PRESET_SCORES];
} hol_ask_preset_def;

int hol_ask_npresets(void);
/* Row i of the table, NULL outside it. */
const hol_ask_preset_def *hol_ask_preset_at(int i);
/* The row of a preset's name, -1 for another. */
int hol_ask_preset_index(const char *name, size_t n);
/* The index of item id in p, -1 when it is none (or p NULL). */
int hol_ask_preset_item(const hol_ask_preset_def *p, const char *id);
/* p's scores (out[p->nscores]) from its items' answers v[p->nitems]. */
void hol_ask_score(const hol_ask_preset_def *p, const double *v, double *out);
/* The presets' names for a message: "ssq or tlx" (conj "or"). */
void hol_ask_preset_names(const char *conj, char *out, size_t cap);

int hol_ask_id_ok(const char *id, size_t n);
hol_err hol_ask_parse_question(const char *line, size_t n, hol_app_question *q, char *msg,
                               size_t cap);
/* The preset's items into out (max of them): their count, 0 for a name
 * that is no preset. In English (the level's and the logs' words). */
int hol_ask_preset(const char *name, size_t n, hol_app_question *out, int max);
/* Item k of p as a question in lang (core/hol_str.h; a row a build adds
 * with its own English words stays English); HOL_EARG for no such item. */
hol_err hol_ask_preset_item_in(const hol_ask_preset_def *p, int k, int lang,
                               hol_app_question *out);
/* "level", "condition", "study", "before_level", "before_condition",
 * "before_study": the hol_app_ask_when; -1 for another. hol_ask_when_name:
 * its name ("level" outside them); hol_ask_before: 1 for a before one. */
int hol_ask_when(const char *w, size_t n);
const char *hol_ask_when_name(int when);
int hol_ask_before(int when);
/* The subscales of SSQ item k (0..15): bit 0 nausea, 1 oculomotor, 2
 * disorientation (Kennedy et al. 1993, table 4). */
unsigned hol_ask_ssq_subscales(int k);

#endif
