/* hol_quiz.c - the class's pre-test and post-test (see hol_quiz.h). */
#include "hol_quiz.h"

#include <stdio.h>
#include <string.h>

#include "hol_room.h"
#include "hol_str.h"
#include "hol_tile.h"

/* Per phase and concept: the question, the route it walks ("" none), the
 * scale lo, hi, step (0, 0, 0: a choice), then the choices or anchors
 * (0: none); the words are the string table's (core/hol_str.h), the
 * level's and the logs' in English. */
static const struct {
    hol_str_id text;
    const char *route;
    int lo, hi, step;
    hol_str_id label[3];
} hol__items[2][HOL_QUIZ_ITEMS] = {
    {{HOL_S_QUIZ_PRE_SQUARE, "NESW", 0, 0, 0, {HOL_S_YES, HOL_S_NO}},
     {HOL_S_QUIZ_PRE_CORNER, "", 3, 9, 1, {HOL_S_FEWER, HOL_S_MORE}},
     {HOL_S_QUIZ_PRE_GROWTH, "", 0, 20, 1, {HOL_S_FEWER, HOL_S_MORE}},
     {HOL_S_QUIZ_PRE_HOME, "NESS", 0, 10, 1, {HOL_S_FEWER, HOL_S_MORE}}},
    {{HOL_S_QUIZ_POST_SQUARE, "ENWS", 0, 0, 0, {HOL_S_YES, HOL_S_NO}},
     {HOL_S_QUIZ_POST_CORNER, "", 0, 0, 0, {HOL_S_DEG_360, HOL_S_LESS_360, HOL_S_MORE_360}},
     {HOL_S_QUIZ_POST_GROWTH, "", 4, 44, 4, {HOL_S_FEWER, HOL_S_MORE}},
     {HOL_S_QUIZ_POST_HOME, "WSEE", 0, 10, 1, {HOL_S_FEWER, HOL_S_MORE}}}};

static const char *const hol__concepts[HOL_QUIZ_ITEMS] = {"square", "corner", "growth", "home"};
static const char *const hol__names[2] = {"pretest", "posttest"};

const char *hol_quiz_concept(int k)
{
    return k >= 0 && k < HOL_QUIZ_ITEMS ? hol__concepts[k] : NULL;
}

const char *hol_quiz_name(int phase)
{
    return phase == HOL_QUIZ_PRE || phase == HOL_QUIZ_POST ? hol__names[phase] : NULL;
}

/* The tile a route of room steps from the start of a 3 x 3 room ends on. */
static hol_err hol__walk(int q, const char *route, hol_tile *out)
{
    hol_room r;
    hol_err e = hol_room_start_in(q, 3, 3, &r);
    for (size_t i = 0; !e && route[i]; i++)
        e = hol_room_step(&r, hol_dir_from_char((unsigned char)route[i]));
    *out = r.tile;
    return e;
}

/* The right answer of item k of a phase in {4,q}. */
static hol_err hol__right(int phase, int k, int q, char *out, size_t cap)
{
    hol_tile end;
    hol_err e = HOL_OK;
    switch (k) {
    case 0: /* the square closes only on the flat grid */
        if (!(e = hol__walk(q, hol__items[phase][k].route, &end)))
            snprintf(out, cap, "%s",
                     hol_str(HOL_LANG_EN, hol__items[phase][k].label[hol_tile_dist0(end) ? 1 : 0]));
        break;
    case 1: /* q squares at a corner; their angles sum to 4 x 360 / q */
        if (phase == HOL_QUIZ_PRE)
            snprintf(out, cap, "%d", q);
        else
            snprintf(out, cap, "%s",
                     hol_str(HOL_LANG_EN, hol__items[phase][k].label[4 * 360 == 360 * q ? 0 : 1]));
        break;
    case 2: snprintf(out, cap, "%llu", (unsigned long long)hol_tile_count_at(q, 2 + phase)); break;
    default:
        if (!(e = hol__walk(q, hol__items[phase][k].route, &end)))
            snprintf(out, cap, "%d", hol_tile_dist0(end));
        break;
    }
    return e;
}

hol_err hol_quiz_item_in(int phase, int k, int q, int lang, hol_quiz_item *out)
{
    if (!out || !hol_quiz_name(phase) || !hol_quiz_concept(k) || q < HOL_TILING_MIN_Q ||
        q > HOL_TILING_MAX_Q)
        return HOL_EARG;
    hol_quiz_item it;
    memset(&it, 0, sizeof it);
    it.concept = k;
    hol_app_question *qn = &it.question;
    const hol_str_id *label = hol__items[phase][k].label;
    snprintf(qn->id, sizeof qn->id, "%s_q%d", hol__concepts[k], q);
    snprintf(qn->text, sizeof qn->text, "%s", hol_str(lang, hol__items[phase][k].text));
    if (hol__items[phase][k].step) {
        qn->kind = HOL_APP_LIKERT;
        qn->lo = hol__items[phase][k].lo;
        qn->hi = hol__items[phase][k].hi;
        qn->step = hol__items[phase][k].step;
        snprintf(qn->low, sizeof qn->low, "%s", hol_str(lang, label[0]));
        snprintf(qn->high, sizeof qn->high, "%s", hol_str(lang, label[1]));
    } else {
        qn->kind = HOL_APP_CHOICE;
        for (int c = 0; c < 3 && label[c]; c++)
            snprintf(qn->choices[qn->nchoices++], HOL_APP_LABEL_MAX, "%s", hol_str(lang, label[c]));
    }
    hol_err e = hol__right(phase, k, q, it.right, sizeof it.right);
    if (e)
        return e;
    *out = it;
    return HOL_OK;
}

hol_err hol_quiz_item_of(int phase, int k, int q, hol_quiz_item *out)
{
    return hol_quiz_item_in(phase, k, q, HOL_LANG_EN, out);
}

hol_err hol_quiz_fill(int phase, int q, hol_app_level *L)
{
    if (!L || !hol_quiz_name(phase))
        return HOL_EARG;
    for (int k = 0; k < HOL_QUIZ_ITEMS; k++) {
        hol_quiz_item it;
        hol_err e = hol_quiz_item_of(phase, k, q, &it);
        if (e)
            return e;
        L->questions[k] = it.question;
    }
    L->mode = HOL_APP_EXPLORE;
    L->nquestions = HOL_QUIZ_ITEMS;
    L->nasks = 1;
    memset(&L->asks[0], 0, sizeof L->asks[0]);
    snprintf(L->asks[0].name, sizeof L->asks[0].name, "%s", hol__names[phase]);
    L->asks[0].when = HOL_APP_BEFORE_LEVEL;
    L->asks[0].n = HOL_QUIZ_ITEMS;
    snprintf(L->closing, sizeof L->closing, "%s", hol_str(HOL_LANG_EN, HOL_S_QUIZ_DONE));
    L->time_limit_s = HOL_QUIZ_LEVEL_S;
    return HOL_OK;
}

int hol_quiz_key(const char *questionnaire, const char *item, char *right, size_t cap)
{
    int phase = -1;
    for (int p = 0; p < 2; p++)
        if (questionnaire && !strcmp(questionnaire, hol__names[p]))
            phase = p;
    if (phase < 0 || !item)
        return -1;
    for (int k = 0; k < HOL_QUIZ_ITEMS; k++) {
        size_t n = strlen(hol__concepts[k]);
        if (strncmp(item, hol__concepts[k], n) || item[n] != '_' || item[n + 1] != 'q')
            continue;
        const char *d = item + n + 2;
        if (d[0] < '4' || d[0] > '8' || d[1])
            return -1;
        hol_quiz_item it;
        if (hol_quiz_item_of(phase, k, d[0] - '0', &it))
            return -1;
        snprintf(right, cap, "%s", it.right);
        return k;
    }
    return -1;
}
