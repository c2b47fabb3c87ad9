/* hol_level_ask.c - a level's questionnaire lines (see hol_level_impl.h,
 * core/hol_ask.h): question (an item), ask (a questionnaire after the end
 * screen: a preset of hol_ask.c's table, or questions named). */
#include "hol_level_impl.h"

#include <stdio.h>
#include <string.h>

#include "hol_ask.h"

/* question ID likert|choice ... (core/hol_ask.h): an item `ask` lines
 * may name (after it). */
hol_err hol__key_question(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (p->ndefs >= HOL_APP_MAX_QUESTIONS)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d questions",
                          HOL_APP_MAX_QUESTIONS);
    char msg[160];
    hol_app_question *q = &p->defs[p->ndefs];
    hol_err e = hol_ask_parse_question(p->raw, strlen(p->raw), q, msg, sizeof msg);
    if (e)
        return hol__lfail(p, e, p->line, "%s", msg);
    for (int i = 0; i < p->ndefs; i++)
        if (!strcmp(p->defs[i].id, q->id))
            return hol__lfail(p, HOL_EARG, p->line, "question %s is given twice", q->id);
    p->ndefs++;
    (void)f;
    return HOL_OK;
}

/* An ask's items: the preset's (NAME a preset's, no IDs) or the questions
 * named (given before), copied after the level's questions. */
static hol_err hol__ask_items(hol__lp *p, hol_app_ask *a, const char *ids)
{
    hol_app_level *L = &p->L;
    a->first = L->nquestions;
    int room = HOL_APP_MAX_QUESTIONS - L->nquestions;
    if (!*ids) {
        int n = hol_ask_preset(a->name, strlen(a->name), L->questions + L->nquestions, room);
        char presets[HOL_ASK_NAMES_MAX];
        hol_ask_preset_names("and", presets, sizeof presets);
        if (!n)
            return hol__lfail(p, HOL_EPARSE, p->line,
                              "ask %s names no items (IDs of questions; %s need none)", a->name,
                              presets);
        if (n > room)
            return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d items to ask",
                              HOL_APP_MAX_QUESTIONS);
        a->n = n;
        L->nquestions += n;
        return HOL_OK;
    }
    for (const char *s = ids; *s;) {
        size_t n = strcspn(s, " \t");
        int k = 0;
        while (k < p->ndefs && !(strlen(p->defs[k].id) == n && !memcmp(p->defs[k].id, s, n)))
            k++;
        if (k == p->ndefs)
            return hol__lfail(p, HOL_EARG, p->line, "ask %s: no question '%.*s' before it",
                              a->name, (int)(n < 32 ? n : 32), s);
        for (int j = a->first; j < L->nquestions; j++)
            if (!strcmp(L->questions[j].id, p->defs[k].id))
                return hol__lfail(p, HOL_EARG, p->line, "ask %s lists '%s' twice", a->name,
                                  p->defs[k].id);
        if (L->nquestions >= HOL_APP_MAX_QUESTIONS)
            return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d items to ask",
                              HOL_APP_MAX_QUESTIONS);
        L->questions[L->nquestions++] = p->defs[k];
        a->n++;
        s += n;
        s += strspn(s, " \t");
    }
    return HOL_OK;
}

/* ask NAME WHEN [ID...]: a questionnaire after the end screen (WHEN
 * level|condition|study) or when the level starts, before its instructions
 * (before_level|before_condition|before_study), in the order of the lines. */
hol_err hol__key_ask(hol__lp *p, char **f, int nf)
{
    (void)nf;
    hol_app_level *L = &p->L;
    if (L->nasks >= HOL_APP_MAX_ASKS)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d ask lines", HOL_APP_MAX_ASKS);
    hol_app_ask *a = &L->asks[L->nasks];
    memset(a, 0, sizeof *a);
    if (!hol_ask_id_ok(f[1], strlen(f[1])))
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "ask: '%.31s' is not 1..31 letters, digits, '_', '-', '.'", f[1]);
    snprintf(a->name, sizeof a->name, "%s", f[1]);
    a->when = hol_ask_when(f[2], strlen(f[2]));
    if (a->when < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "ask %s: '%.20s' is not level, condition, "
                          "study, before_level, before_condition or before_study", a->name, f[2]);
    for (int k = 0; k < L->nasks; k++) /* asked once a time (issue 39) */
        if (L->asks[k].when == a->when && !strcmp(L->asks[k].name, a->name))
            return hol__lfail(p, HOL_EARG, p->line, "ask %s %s is given twice", a->name,
                              hol_ask_when_name(a->when));
    /* the IDs: the raw line after the key, NAME and WHEN */
    const char *r = p->raw;
    for (int k = 0; k < 3; k++) {
        r += strspn(r, " \t");
        r += strcspn(r, " \t");
    }
    r += strspn(r, " \t");
    char ids[HOL_LEVEL_LINE_MAX + 1];
    snprintf(ids, sizeof ids, "%s", r);
    size_t n = strlen(ids);
    while (n && (ids[n - 1] == ' ' || ids[n - 1] == '\t'))
        ids[--n] = 0;
    hol_err e = hol__ask_items(p, a, ids);
    if (!e)
        L->nasks++;
    return e;
}
