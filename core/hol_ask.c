/* hol_ask.c - questionnaires (see hol_ask.h): the presets' one table (each
 * preset's name, scale, items and scores), which the level parser, the
 * study, the app (through the level's items), the SSQ scoring and the
 * report read, and an item's ID and when; a new preset is a row here
 * (docs/hacking.md, "Adding a questionnaire preset"). The question line is
 * hol_ask_question.c's. */
#include "hol_ask.h"

#include <stdio.h>
#include <string.h>

#define HOL__VLO "Very low"
#define HOL__VHI "Very high"

/* The SSQ's subscales: nausea (bit 0), oculomotor (1), disorientation (2),
 * Kennedy et al. 1993, table 4; its scores: the subscales' raw sums
 * weighted, the total their sum x 3.74. The TLX: the six scales' mean. */
#define HOL__N 1u
#define HOL__O 2u
#define HOL__D 4u

/* Presets a build adds after the standard ones (a test's example row). */
#ifndef HOL_ASK_MORE_PRESETS
#define HOL_ASK_MORE_PRESETS
#endif

static const hol_ask_preset_def hol__presets[] = {
    {"ssq", 0, 3, 1, "none", "severe", 16,
     {{"general_discomfort", "General discomfort", 0, 0, HOL__N | HOL__O},
      {"fatigue", "Fatigue", 0, 0, HOL__O},
      {"headache", "Headache", 0, 0, HOL__O},
      {"eye_strain", "Eye strain", 0, 0, HOL__O},
      {"difficulty_focusing", "Difficulty focusing", 0, 0, HOL__O | HOL__D},
      {"salivation_increasing", "Salivation increasing", 0, 0, HOL__N},
      {"sweating", "Sweating", 0, 0, HOL__N},
      {"nausea", "Nausea", 0, 0, HOL__N | HOL__D},
      {"difficulty_concentrating", "Difficulty concentrating", 0, 0, HOL__N | HOL__O},
      {"fullness_of_head", "Fullness of the head", 0, 0, HOL__D},
      {"blurred_vision", "Blurred vision", 0, 0, HOL__O | HOL__D},
      {"dizziness_eyes_open", "Dizziness with eyes open", 0, 0, HOL__D},
      {"dizziness_eyes_closed", "Dizziness with eyes closed", 0, 0, HOL__D},
      {"vertigo", "Vertigo", 0, 0, HOL__D},
      {"stomach_awareness", "Stomach awareness", 0, 0, HOL__N},
      {"burping", "Burping", 0, 0, HOL__N}},
     4,
     {{"total", HOL__N | HOL__O | HOL__D, 3.74, 1},
      {"nausea", HOL__N, 9.54, 1},
      {"oculomotor", HOL__O, 7.58, 1},
      {"disorientation", HOL__D, 13.92, 1}}},
    {"tlx", 0, 100, 5, HOL__VLO, HOL__VHI, 6,
     {{"mental", "Mental demand: how mentally demanding was the task?", 0, 0, 1},
      {"physical", "Physical demand: how physically demanding was the task?", 0, 0, 1},
      {"temporal", "Temporal demand: how hurried or rushed was the pace of the task?", 0, 0, 1},
      {"performance", "Performance: how successful were you in doing what you were asked to do?",
       "Perfect", "Failure", 1},
      {"effort", "Effort: how hard did you have to work to reach your level of performance?", 0,
       0, 1},
      {"frustration", "Frustration: how insecure, discouraged, irritated, stressed and annoyed "
                      "were you?", 0, 0, 1}},
     1,
     {{"raw", 1, 1, 6}}},
    HOL_ASK_MORE_PRESETS
};

#define HOL__NPRESETS ((int)(sizeof hol__presets / sizeof hol__presets[0]))
_Static_assert(sizeof hol__presets / sizeof hol__presets[0] <= HOL_ASK_MAX_PRESETS,
               "more presets than HOL_ASK_MAX_PRESETS");

int hol_ask_npresets(void)
{
    return HOL__NPRESETS;
}

const hol_ask_preset_def *hol_ask_preset_at(int i)
{
    return i >= 0 && i < HOL__NPRESETS ? &hol__presets[i] : NULL;
}

int hol_ask_preset_index(const char *name, size_t n)
{
    for (int i = 0; i < HOL__NPRESETS; i++)
        if (strlen(hol__presets[i].name) == n && !memcmp(hol__presets[i].name, name, n))
            return i;
    return -1;
}

int hol_ask_preset_item(const hol_ask_preset_def *p, const char *id)
{
    for (int k = 0; p && k < p->nitems; k++)
        if (!strcmp(p->items[k].id, id))
            return k;
    return -1;
}

int hol_ask_preset(const char *name, size_t n, hol_app_question *out, int max)
{
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index(name, n));
    int count = p ? p->nitems : 0;
    for (int k = 0; k < count && k < max; k++) {
        const hol_ask_item_def *it = &p->items[k];
        hol_app_question *q = &out[k];
        memset(q, 0, sizeof *q);
        q->kind = HOL_APP_LIKERT;
        snprintf(q->id, sizeof q->id, "%s", it->id);
        snprintf(q->text, sizeof q->text, "%s", it->text);
        q->lo = p->lo, q->hi = p->hi, q->step = p->step;
        snprintf(q->low, sizeof q->low, "%s", it->low ? it->low : p->low);
        snprintf(q->high, sizeof q->high, "%s", it->high ? it->high : p->high);
    }
    return count;
}

void hol_ask_score(const hol_ask_preset_def *p, const double *v, double *out)
{
    double raw[HOL_ASK_PRESET_SCALES] = {0};
    for (int i = 0; i < p->nitems; i++)
        for (int j = 0; j < HOL_ASK_PRESET_SCALES; j++)
            raw[j] += (p->items[i].scales >> j & 1u) ? v[i] : 0;
    for (int k = 0; k < p->nscores; k++) {
        const hol_ask_score_def *sc = &p->scores[k];
        double sum = 0;
        for (int j = 0; j < HOL_ASK_PRESET_SCALES; j++)
            sum += (sc->scales >> j & 1u) ? raw[j] : 0;
        out[k] = sum * sc->weight / sc->div;
    }
}

void hol_ask_preset_names(const char *conj, char *out, size_t cap)
{
    size_t len = 0;
    out[0] = 0;
    for (int i = 0; i < HOL__NPRESETS && len < cap; i++) {
        const char *sep = i == 0 ? "" : i == HOL__NPRESETS - 1 ? " " : ", ";
        int k = snprintf(out + len, cap - len, "%s%s%s%s", sep,
                         i && i == HOL__NPRESETS - 1 ? conj : "",
                         i && i == HOL__NPRESETS - 1 ? " " : "", hol__presets[i].name);
        len += k > 0 ? (size_t)k : 0;
    }
}

unsigned hol_ask_ssq_subscales(int k)
{
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index("ssq", 3));
    return p && k >= 0 && k < p->nitems ? p->items[k].scales : 0;
}

/* ---- IDs and when -------------------------------------------------------------- */

int hol_ask_id_ok(const char *id, size_t n)
{
    if (n == 0 || n >= HOL_APP_ID_MAX)
        return 0;
    for (size_t i = 0; i < n; i++) {
        char c = id[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '-' || c == '.'))
            return 0;
    }
    return 1;
}

static int hol__is(const char *w, size_t n, const char *word)
{
    return strlen(word) == n && !memcmp(w, word, n);
}

static const char *const hol__whens[HOL_APP_ASK_WHENS] = {
    "level", "condition", "study", "before_level", "before_condition", "before_study"};

int hol_ask_when(const char *w, size_t n)
{
    for (int k = 0; k < HOL_APP_ASK_WHENS; k++)
        if (hol__is(w, n, hol__whens[k]))
            return k;
    return -1;
}

const char *hol_ask_when_name(int when)
{
    return when >= 0 && when < HOL_APP_ASK_WHENS ? hol__whens[when] : "level";
}

int hol_ask_before(int when)
{
    return when >= HOL_APP_BEFORE_LEVEL && when < HOL_APP_ASK_WHENS;
}
