/* hol_ask.c - questionnaires (see hol_ask.h): the presets' one table (each
 * preset's name, scale, items and scores), which the level parser, the
 * study, the app (through the level's items), the SSQ scoring and the
 * report read, and an item's ID and when; a new preset is a row here
 * (docs/hacking.md, "Adding a questionnaire preset"). The question line is
 * hol_ask_question.c's. */
#include "hol_ask.h"

#include <stdio.h>
#include <string.h>

#include "hol_str.h"

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
    {"ssq", 0, 3, 1, NULL, NULL, 16,
     {{"general_discomfort", NULL, NULL, NULL, HOL__N | HOL__O},
      {"fatigue", NULL, NULL, NULL, HOL__O},
      {"headache", NULL, NULL, NULL, HOL__O},
      {"eye_strain", NULL, NULL, NULL, HOL__O},
      {"difficulty_focusing", NULL, NULL, NULL, HOL__O | HOL__D},
      {"salivation_increasing", NULL, NULL, NULL, HOL__N},
      {"sweating", NULL, NULL, NULL, HOL__N},
      {"nausea", NULL, NULL, NULL, HOL__N | HOL__D},
      {"difficulty_concentrating", NULL, NULL, NULL, HOL__N | HOL__O},
      {"fullness_of_head", NULL, NULL, NULL, HOL__D},
      {"blurred_vision", NULL, NULL, NULL, HOL__O | HOL__D},
      {"dizziness_eyes_open", NULL, NULL, NULL, HOL__D},
      {"dizziness_eyes_closed", NULL, NULL, NULL, HOL__D},
      {"vertigo", NULL, NULL, NULL, HOL__D},
      {"stomach_awareness", NULL, NULL, NULL, HOL__N},
      {"burping", NULL, NULL, NULL, HOL__N}},
     4,
     {{"total", HOL__N | HOL__O | HOL__D, 3.74, 1},
      {"nausea", HOL__N, 9.54, 1},
      {"oculomotor", HOL__O, 7.58, 1},
      {"disorientation", HOL__D, 13.92, 1}}},
    {"tlx", 0, 100, 5, NULL, NULL, 6,
     {{"mental", NULL, NULL, NULL, 1},
      {"physical", NULL, NULL, NULL, 1},
      {"temporal", NULL, NULL, NULL, 1},
      {"performance", NULL, NULL, NULL, 1},
      {"effort", NULL, NULL, NULL, 1},
      {"frustration", NULL, NULL, NULL, 1}},
     1,
     {{"raw", 1, 1, 6}}},
    HOL_ASK_MORE_PRESETS
};

/* The standard rows' words (their strings NULL above), ids of the string
 * table in its order: row i's item k says first + k; its anchors low,
 * high; item own (-1: none) its own anchors. */
static const struct {
    hol_str_id first, low, high;
    int own;
    hol_str_id own_low, own_high;
} hol__says[] = {
    {HOL_S_SSQ_GENERAL_DISCOMFORT, HOL_S_SSQ_NONE, HOL_S_SSQ_SEVERE, -1, 0, 0},
    {HOL_S_TLX_MENTAL, HOL_S_TLX_VERY_LOW, HOL_S_TLX_VERY_HIGH, 3, HOL_S_TLX_PERFECT,
     HOL_S_TLX_FAILURE},
};
_Static_assert(HOL_S_SSQ_BURPING - HOL_S_SSQ_GENERAL_DISCOMFORT + 1 == HOL_ASK_SSQ_ITEMS &&
                   HOL_S_TLX_FRUSTRATION - HOL_S_TLX_MENTAL + 1 == HOL_ASK_TLX_ITEMS,
               "the string table holds each standard row's items in its order");
#define HOL__NSAYS ((int)(sizeof hol__says / sizeof hol__says[0]))

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

hol_err hol_ask_preset_item_in(const hol_ask_preset_def *p, int k, int lang,
                               hol_app_question *out)
{
    if (!p || k < 0 || k >= p->nitems || !out)
        return HOL_EARG;
    int i = 0;
    while (i < HOL__NSAYS && p != &hol__presets[i])
        i++;
    const hol_ask_item_def *it = &p->items[k];
    const char *text = it->text, *low = it->low ? it->low : p->low;
    const char *high = it->high ? it->high : p->high;
    if (i >= 0 && i < HOL__NSAYS) { /* a standard row: the string table's */
        int own = k == hol__says[i].own;
        text = hol_str(lang, (hol_str_id)(hol__says[i].first + k));
        low = hol_str(lang, own ? hol__says[i].own_low : hol__says[i].low);
        high = hol_str(lang, own ? hol__says[i].own_high : hol__says[i].high);
    }
    memset(out, 0, sizeof *out);
    out->kind = HOL_APP_LIKERT;
    snprintf(out->id, sizeof out->id, "%s", it->id);
    snprintf(out->text, sizeof out->text, "%s", text);
    out->lo = p->lo, out->hi = p->hi, out->step = p->step;
    snprintf(out->low, sizeof out->low, "%s", low);
    snprintf(out->high, sizeof out->high, "%s", high);
    return HOL_OK;
}

int hol_ask_preset(const char *name, size_t n, hol_app_question *out, int max)
{
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index(name, n));
    int count = p ? p->nitems : 0;
    for (int k = 0; k < count && k < max; k++)
        hol_ask_preset_item_in(p, k, HOL_LANG_EN, &out[k]);
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
