/* hol_ask.h - questionnaire items: the `question` line, the presets ssq and
 * tlx, and their scoring's tables (docs/research.md "Questionnaires").
 *
 * Contract
 * - A question line (a level's or a study's):
 *     question ID likert LO HI "TEXT" "LOW" "HIGH"
 *     question ID choice "TEXT" "A" "B" ...
 *   ID: 1..31 letters, digits, '_', '-', '.' (hol_ask_id_ok), not a preset's
 *   name; likert: integers LO < HI in 0..100, at most HOL_APP_MAX_SCALE marks
 *   (step 1); choice: 2..HOL_APP_MAX_CHOICES choices. Quoted fields: any
 *   printable ASCII but '"' (no escapes), TEXT 1..95 bytes, an anchor or a
 *   choice 1..23; fields separated by blanks. hol_ask_parse_question fills
 *   *q or returns HOL_EPARSE / HOL_ERANGE with a message (msg, cap).
 * - Presets (hol_ask_preset): `ssq`, the 16 items of the Simulator Sickness
 *   Questionnaire (Kennedy, Lane, Berbaum and Lilienthal 1993), each 0..3
 *   (none, slight, moderate, severe), IDs in HOL_ASK_SSQ_IDS order; `tlx`,
 *   the six raw NASA-TLX scales (Hart and Staveland 1988) mental, physical,
 *   temporal, performance, effort, frustration, 0..100 in steps of 5 (21
 *   marks). hol_ask_ssq_weight gives an SSQ item's subscales (bit 0 nausea,
 *   1 oculomotor, 2 disorientation).
 * - Pure data and parsing: no allocation, no globals but constant tables.
 */
#ifndef HOL_ASK_H
#define HOL_ASK_H

#include <stddef.h>

#include "hol_app.h"
#include "hol_err.h"

#define HOL_ASK_SSQ_ITEMS 16
#define HOL_ASK_TLX_ITEMS 6

int hol_ask_id_ok(const char *id, size_t n);
hol_err hol_ask_parse_question(const char *line, size_t n, hol_app_question *q, char *msg,
                               size_t cap);
/* The preset's items into out (max of them): their count, 0 for a name
 * that is no preset. */
int hol_ask_preset(const char *name, size_t n, hol_app_question *out, int max);
/* "level", "condition", "study": the hol_app_ask_when; -1 for another. */
int hol_ask_when(const char *w, size_t n);
const char *hol_ask_when_name(int when);
/* The subscales of SSQ item k (0..15): bit 0 nausea, 1 oculomotor, 2
 * disorientation (Kennedy et al. 1993, table 4). */
unsigned hol_ask_ssq_subscales(int k);

#endif
