/* hol_study.c - study files and counterbalancing squares (see hol_study.h);
 * a condition's level is composed in hol_study_level.c, from the helpers
 * on a level line's key here (hol_study_impl.h). */
#include "hol_study.h"
#include "hol_study_impl.h"

#include "hol_ask.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- errors ------------------------------------------------------------------ */

hol_err hol__study_fail(hol_level_err *e, hol_err code, long line, long other,
                         const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hol_level_err_vset(e, code, line, other, fmt, ap);
    va_end(ap);
    return code;
}

/* ---- lines ------------------------------------------------------------------- */

/* The parser's state. */
typedef struct hol__sp {
    hol_study *s;
    hol_level_err *err;
    long line, study_line, rule_line;
    long allow_line; /* `allow minimap-toggle`'s line, 0: none yet */
    int cur; /* the condition being read, -1 before the first */
} hol__sp;

static int hol__blank(char c)
{
    return c == ' ' || c == '\t';
}

/* The next field of [*p, end): its start and length (0 at the end). */
size_t hol__study_field(const char **p, const char *end, const char **out)
{
    const char *s = *p;
    while (s < end && hol__blank(*s))
        s++;
    *out = s;
    while (s < end && !hol__blank(*s))
        s++;
    *p = s;
    return (size_t)(s - *out);
}

int hol__study_is(const char *w, size_t n, const char *word)
{
    return strlen(word) == n && !memcmp(w, word, n);
}

/* A NAME field into out: 1 ok. */
static int hol__name(const char *w, size_t n, char out[HOL_REC_ID_MAX])
{
    if (n == 0 || n >= HOL_REC_ID_MAX)
        return 0;
    memcpy(out, w, n);
    out[n] = 0;
    return hol_rec_id_ok(out);
}

/* A line's one value (after its key): its start and length, or -1 after
 * reporting a missing or second value. */
static long hol__one(hol__sp *p, const char *key, const char *rest, const char *end,
                     const char **out)
{
    size_t n = hol__study_field(&rest, end, out);
    const char *more;
    if (n == 0)
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0, "'%s' needs a value", key), -1;
    if (hol__study_field(&rest, end, &more))
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0, "'%s' takes one value", key), -1;
    return (long)n;
}

static hol_err hol__add_level(hol__sp *p, const char *w, size_t n)
{
    hol_study *s = p->s;
    if (s->nlevels >= HOL_STUDY_MAX_LEVELS)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0,
                         "more than %d levels in all (a recording holds %d)",
                         HOL_STUDY_MAX_LEVELS, HOL_STUDY_MAX_LEVELS);
    if (n >= HOL_STUDY_PATH_MAX)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "a level's path is longer than %d bytes",
                         HOL_STUDY_PATH_MAX - 1);
    hol_study_span *sp = &s->levels[s->nlevels++];
    sp->off = (uint16_t)(w - s->text);
    sp->len = (uint16_t)n;
    sp->line = p->line;
    if (p->cur >= 0)
        s->conditions[p->cur].nlevels++;
    else
        s->npractice++;
    return HOL_OK;
}

static int hol__same_key(const hol_study *s, int a, int b);

/* set KEY VALUE...: checked as a level line. */
static hol_err hol__add_set(hol__sp *p, const char *rest, const char *end)
{
    hol_study *s = p->s;
    while (rest < end && hol__blank(*rest))
        rest++;
    while (end > rest && hol__blank(end[-1]))
        end--;
    if (rest == end)
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0, "'set' needs a level line (KEY VALUE...)");
    hol_level_err le;
    if (hol_level_line_check(rest, (size_t)(end - rest), &le))
        return hol__study_fail(p->err, le.code, p->line, 0, "set: %s", le.msg);
    if (s->nsets >= HOL_STUDY_MAX_SETS)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d set lines",
                         HOL_STUDY_MAX_SETS);
    hol_study_span *sp = &s->sets[s->nsets++];
    sp->off = (uint16_t)(rest - s->text);
    sp->len = (uint16_t)(end - rest);
    sp->line = p->line;
    /* a key set twice in one place (the study's, or a condition's) is
     * refused naming both lines, as a level's repeated key is */
    int first = p->cur >= 0 ? s->conditions[p->cur].first_set : 0;
    const char *key;
    size_t kn = hol__study_key(rest, end, &key);
    for (int i = first; i < s->nsets - 1; i++)
        if (hol__same_key(s, i, s->nsets - 1) && !(kn == 5 && !memcmp(key, "place", 5))) {
            s->nsets--;
            return hol__study_fail(p->err, HOL_EARG, p->line, s->sets[i].line,
                             "set %.*s is given twice in %s", (int)(kn < 20 ? kn : 20), key,
                             p->cur >= 0 ? "this condition" : "the study");
        }
    if (p->cur >= 0)
        s->conditions[p->cur].nsets++;
    else
        s->nglobal++;
    return HOL_OK;
}

static hol_err hol__condition(hol__sp *p, const char *w, size_t n)
{
    hol_study *s = p->s;
    if (s->nconditions >= HOL_STUDY_MAX_CONDITIONS)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d conditions",
                         HOL_STUDY_MAX_CONDITIONS);
    hol_study_condition *c = &s->conditions[s->nconditions];
    memset(c, 0, sizeof *c);
    if (!hol__name(w, n, c->name))
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                         "condition '%.*s' is not 1..63 letters, digits, '.', '_', '-'",
                         (int)(n < 40 ? n : 40), w);
    if (!strcmp(c->name, HOL_STUDY_PRACTICE))
        return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                         "'practice' names the practice levels, not a condition");
    for (int k = 0; k < s->nconditions; k++)
        if (!strcmp(s->conditions[k].name, c->name))
            return hol__study_fail(p->err, HOL_EARG, p->line, s->conditions[k].line,
                             "condition '%s' is given twice", c->name);
    c->line = p->line;
    c->first_level = s->nlevels;
    c->first_set = s->nsets;
    p->cur = s->nconditions++;
    return HOL_OK;
}

/* study NAME, counterbalance RULE: once, before the first condition. */
static hol_err hol__header(hol__sp *p, int is_study, const char *w, size_t n)
{
    static const char *const rules[4] = {"williams", "latin", "complete", "fixed"};
    const char *key = is_study ? "study" : "counterbalance";
    long *seen = is_study ? &p->study_line : &p->rule_line;
    if (p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0, "'%s' comes before the first condition",
                         key);
    if (*seen)
        return hol__study_fail(p->err, HOL_EARG, p->line, *seen, "a second '%s' line", key);
    *seen = p->line;
    if (is_study) {
        if (!hol__name(w, n, p->s->name))
            return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                             "study '%.*s' is not 1..63 letters, digits, '.', '_', '-'",
                             (int)(n < 40 ? n : 40), w);
        return HOL_OK;
    }
    for (int r = 0; r < 4; r++)
        if (hol__study_is(w, n, rules[r])) {
            p->s->rule = (hol_study_rule)r;
            return HOL_OK;
        }
    return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                     "counterbalance '%.*s' is not williams, latin, complete or fixed",
                     (int)(n < 30 ? n : 30), w);
}

/* allow minimap-toggle: before the first condition; the conditions'
 * minimap is not fixed (M moves it, and the logs say so). */
static hol_err hol__allow(hol__sp *p, const char *w, size_t n)
{
    if (p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0, "'allow' comes before the first condition");
    if (!hol__study_is(w, n, "minimap-toggle"))
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0, "allow '%.*s' is not minimap-toggle",
                         (int)(n < 30 ? n : 30), w);
    if (p->allow_line)
        return hol__study_fail(p->err, HOL_EARG, p->line, p->allow_line,
                         "allow minimap-toggle is given twice");
    p->allow_line = p->line;
    p->s->allow_minimap_toggle = 1;
    return HOL_OK;
}

/* instructions TEXT (the practice's before the first condition, else the
 * condition's), closing TEXT (before the first condition): once each,
 * checked as the level line they become. */
static hol_err hol__screen(hol__sp *p, int closing, const char *b, const char *end)
{
    hol_study *s = p->s;
    const char *key = closing ? "closing" : "instructions";
    while (b < end && hol__blank(*b))
        b++;
    while (end > b && hol__blank(end[-1]))
        end--;
    if (closing && p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0, "'closing' comes before the first condition");
    hol_study_span *sp = closing ? &s->closing
                         : p->cur >= 0 ? &s->conditions[p->cur].instructions
                                       : &s->practice_instructions;
    if (sp->len)
        return hol__study_fail(p->err, HOL_EARG, p->line, sp->line, "a second '%s' line %s", key,
                         closing ? "in the study" : p->cur >= 0 ? "in this condition"
                                                                : "for the practice");
    hol_level_err le;
    if (hol_level_line_check(b, (size_t)(end - b), &le))
        return hol__study_fail(p->err, le.code, p->line, 0, "%s", le.msg);
    sp->off = (uint16_t)(b - s->text);
    sp->len = (uint16_t)(end - b);
    sp->line = p->line;
    return HOL_OK;
}

/* question ID ...: before the first condition, checked as a level line. */
static hol_err hol__question(hol__sp *p, const char *b, const char *end)
{
    hol_study *s = p->s;
    while (end > b && hol__blank(end[-1]))
        end--;
    while (b < end && hol__blank(*b))
        b++;
    if (p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0, "'question' comes before the first condition");
    if (s->nquestions >= HOL_STUDY_MAX_QUESTIONS)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questions",
                         HOL_STUDY_MAX_QUESTIONS);
    hol_app_question q;
    char msg[160];
    hol_err e = hol_ask_parse_question(b, (size_t)(end - b), &q, msg, sizeof msg);
    if (e)
        return hol__study_fail(p->err, e, p->line, 0, "%s", msg);
    for (int i = 0; i < s->nquestions; i++)
        if (!strcmp(s->question_ids[i], q.id))
            return hol__study_fail(p->err, HOL_EARG, p->line, s->questions[i].line,
                             "question %s is given twice", q.id);
    snprintf(s->question_ids[s->nquestions], HOL_APP_ID_MAX, "%s", q.id);
    s->questions[s->nquestions++] = (hol_study_span){(uint16_t)(b - s->text),
                                                     (uint16_t)(end - b), p->line};
    return HOL_OK;
}

/* questionnaire NAME ITEM... | questionnaire NAME after|before WHEN. */
static hol_err hol__questionnaire(hol__sp *p, const char *rest, const char *end)
{
    hol_study *s = p->s;
    const char *w, *w2, *w3, *more;
    size_t n = hol__study_field(&rest, end, &w), n2 = hol__study_field(&rest, end, &w2);
    const char *items = rest;
    size_t n3 = hol__study_field(&rest, end, &w3), n4 = hol__study_field(&rest, end, &more);
    if (p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                         "'questionnaire' comes before the first condition");
    if (!hol_ask_id_ok(w, n) || n2 == 0)
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                         "questionnaire needs NAME ITEM... or NAME after|before "
                         "level|condition|study "
                         "(NAME 1..31 letters, digits, '_', '-', '.')");
    char name[HOL_APP_ID_MAX];
    memcpy(name, w, n);
    name[n] = 0;
    int before = hol__study_is(w2, n2, "before");
    if ((before || hol__study_is(w2, n2, "after")) && n3 && !n4) {
        int when = hol_ask_when(w3, n3);
        if (when < 0 || hol_ask_before(when))
            return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                             "questionnaire %s %s '%.*s': level, condition or study", name,
                             before ? "before" : "after", (int)(n3 < 20 ? n3 : 20), w3);
        when += before ? HOL_APP_BEFORE_LEVEL : 0;
        for (int k = 0; k < s->nasks; k++)
            if (s->asks[k].when == when && !strcmp(s->asks[k].name, name))
                return hol__study_fail(p->err, HOL_EARG, p->line, s->asks[k].line,
                                 "questionnaire %s %s %s is given twice", name,
                                 before ? "before" : "after",
                                 hol_ask_when_name(when - (before ? HOL_APP_BEFORE_LEVEL : 0)));
        if (s->nasks >= HOL_APP_MAX_ASKS)
            return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questionnaires asked",
                             HOL_APP_MAX_ASKS);
        hol_study_ask *a = &s->asks[s->nasks++];
        snprintf(a->name, sizeof a->name, "%s", name);
        a->when = when;
        a->line = p->line;
        return HOL_OK;
    }
    if (n3 && !n4 && hol_ask_when(w3, n3) >= 0)
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                         "questionnaire %s %.*s %.*s: a questionnaire is placed with "
                         "'after|before level|condition|study'", name, (int)(n2 < 20 ? n2 : 20), w2,
                         (int)n3, w3);
    if (hol_ask_preset(w, n, NULL, 0))
        return hol__study_fail(p->err, HOL_EARG, p->line, 0, "questionnaire %s is a preset: it has its "
                         "items", name);
    for (int i = 0; i < s->nquestionnaires; i++)
        if (!strcmp(s->questionnaires[i].name, name))
            return hol__study_fail(p->err, HOL_EARG, p->line, 0, "questionnaire %s is given twice",
                             name);
    if (s->nquestionnaires >= HOL_STUDY_MAX_QUESTIONNAIRES)
        return hol__study_fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questionnaires",
                         HOL_STUDY_MAX_QUESTIONNAIRES);
    /* every item a question given before */
    const char *it = w2;
    while (end > it && hol__blank(end[-1]))
        end--;
    for (const char *q = it; q < end;) {
        const char *id;
        size_t k = hol__study_field(&q, end, &id), j = 0;
        if (!k)
            break;
        while (j < (size_t)s->nquestions && !hol__study_is(id, k, s->question_ids[j]))
            j++;
        if (j == (size_t)s->nquestions)
            return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                             "questionnaire %s: no question '%.*s' before it", name,
                             (int)(k < 32 ? k : 32), id);
        const char *q2 = it, *id2;
        size_t k2;
        while ((k2 = hol__study_field(&q2, end, &id2)) > 0 && id2 < id)
            if (k2 == k && !memcmp(id2, id, k))
                return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                                 "questionnaire %s lists '%.*s' twice", name,
                                 (int)(k < 32 ? k : 32), id);
    }
    (void)items;
    hol_study_questionnaire *d = &s->questionnaires[s->nquestionnaires++];
    snprintf(d->name, sizeof d->name, "%s", name);
    d->items = (hol_study_span){(uint16_t)(it - s->text), (uint16_t)(end - it), p->line};
    return HOL_OK;
}

/* One line [b, end) (no LF, CR dropped, no comment). */
static hol_err hol__line(hol__sp *p, const char *b, const char *end)
{
    const char *rest = b, *key, *w;
    size_t kn = hol__study_field(&rest, end, &key);
    if (kn == 0)
        return HOL_OK;
    if (hol__study_is(key, kn, "set"))
        return hol__add_set(p, rest, end);
    if (hol__study_is(key, kn, "instructions") || hol__study_is(key, kn, "closing"))
        return hol__screen(p, hol__study_is(key, kn, "closing"), b, end);
    if (hol__study_is(key, kn, "question"))
        return hol__question(p, b, end);
    if (hol__study_is(key, kn, "questionnaire"))
        return hol__questionnaire(p, rest, end);
    static const char *const keys[6] = {"study", "counterbalance", "practice", "condition",
                                        "level", "allow"};
    int k = 0;
    while (k < 6 && !hol__study_is(key, kn, keys[k]))
        k++;
    if (k == 6)
        return hol__study_fail(p->err, HOL_EPARSE, p->line, 0,
                         "unknown key '%.*s' (study, counterbalance, practice, condition, level, "
                         "set, allow, instructions, closing, question, questionnaire)", (int)(kn < 20 ? kn : 20), key);
    long n = hol__one(p, keys[k], rest, end, &w);
    if (n < 0)
        return p->err ? p->err->code : HOL_EPARSE;
    if (k == 5)
        return hol__allow(p, w, (size_t)n);
    if (k <= 1)
        return hol__header(p, k == 0, w, (size_t)n);
    if (k == 3)
        return hol__condition(p, w, (size_t)n);
    if (k == 2 && p->cur >= 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                         "'practice' comes before the first condition");
    if (k == 4 && p->cur < 0)
        return hol__study_fail(p->err, HOL_EARG, p->line, 0,
                         "'level' belongs to a condition (before the first: 'practice')");
    return hol__add_level(p, w, (size_t)n);
}

/* After the last line: a name, a condition, and a level for each. */
static hol_err hol__finish(hol__sp *p)
{
    hol_study *s = p->s;
    if (!p->study_line)
        return hol__study_fail(p->err, HOL_EARG, 0, 0, "no 'study NAME' line");
    if (s->nconditions == 0)
        return hol__study_fail(p->err, HOL_EARG, 0, 0, "no 'condition NAME' line");
    for (int k = 0; k < s->nasks; k++) {
        const char *nm = s->asks[k].name;
        int known = hol_ask_preset(nm, strlen(nm), NULL, 0) > 0;
        for (int i = 0; i < s->nquestionnaires && !known; i++)
            known = !strcmp(s->questionnaires[i].name, nm);
        char presets[HOL_ASK_NAMES_MAX];
        hol_ask_preset_names("or", presets, sizeof presets);
        if (!known)
            return hol__study_fail(p->err, HOL_EARG, s->asks[k].line, 0,
                             "questionnaire %s is neither given (questionnaire %s ITEM...) nor "
                             "%s", nm, nm, presets);
    }
    /* a condition without a level file plays one level of its set lines:
     * the levels in all, counted in file order, must fit */
    int total = s->nlevels;
    for (int c = 0; c < s->nconditions; c++) {
        if (s->conditions[c].nlevels)
            continue;
        if (++total > HOL_STUDY_MAX_LEVELS)
            return hol__study_fail(p->err, HOL_ENOMEM, s->conditions[c].line, 0,
                             "more than %d levels in all", HOL_STUDY_MAX_LEVELS);
        if (!hol__study_set_key(s, c, "mode", 4))
            return hol__study_fail(p->err, HOL_EARG, s->conditions[c].line, 0,
                             "condition %s has neither a 'level' nor a 'set mode' line",
                             s->conditions[c].name);
    }
    /* its entry (an empty path) keeps the levels in file order */
    for (int c = s->nconditions - 1; c >= 0; c--) {
        hol_study_condition *cd = &s->conditions[c];
        if (cd->nlevels)
            continue;
        int at = cd->first_level;
        memmove(&s->levels[at + 1], &s->levels[at],
                (size_t)(s->nlevels - at) * sizeof s->levels[0]);
        s->nlevels++;
        s->levels[at] = (hol_study_span){0, 0, cd->line};
        cd->nlevels = 1;
        for (int j = c + 1; j < s->nconditions; j++)
            s->conditions[j].first_level++;
    }
    return HOL_OK;
}

hol_err hol_study_parse(const char *text, size_t len, hol_study *out, hol_level_err *err)
{
    static const hol_study zero;
    if (len > HOL_STUDY_TEXT_MAX)
        return hol__study_fail(err, HOL_ENOMEM, 0, 0, "longer than %d bytes", HOL_STUDY_TEXT_MAX);
    *out = zero;
    memcpy(out->text, text, len);
    hol__sp p = {out, err, 0, 0, 0, 0, -1};
    const char *s = out->text, *end = out->text + len;
    hol_err e = HOL_OK;
    if (len >= 3 && !memcmp(s, "\xef\xbb\xbf", 3))
        s += 3; /* a UTF-8 byte order mark, as some editors write */
    while (!e && s < end) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        const char *le = nl ? nl : end;
        p.line++;
        while (le > s && le[-1] == '\r')
            le--;
        const char *hash = memchr(s, '#', (size_t)(le - s));
        if ((size_t)(le - s) > HOL_STUDY_LINE_MAX)
            e = hol__study_fail(err, HOL_ENOMEM, p.line, 0, "longer than %d bytes", HOL_STUDY_LINE_MAX);
        else if (memchr(s, 0, (size_t)(le - s)))
            e = hol__study_fail(err, HOL_EPARSE, p.line, 0, "a NUL byte");
        else
            e = hol__line(&p, s, hash ? hash : le);
        s = nl ? nl + 1 : end;
    }
    if (!e)
        e = hol__finish(&p);
    if (e)
        *out = zero;
    return e;
}

/* ---- squares ------------------------------------------------------------------ */

uint64_t hol_study_rows(hol_study_rule rule, int n)
{
    if (n < 1 || n > HOL_STUDY_MAX_CONDITIONS)
        return 0;
    switch (rule) {
    case HOL_STUDY_WILLIAMS: return n == 1 ? 1 : n % 2 ? 2 * (uint64_t)n : (uint64_t)n;
    case HOL_STUDY_LATIN: return (uint64_t)n;
    case HOL_STUDY_COMPLETE: {
        uint64_t f = 1;
        for (int k = 2; k <= n; k++)
            f *= (uint64_t)k;
        return f;
    }
    case HOL_STUDY_FIXED: return 1;
    }
    return 0;
}

/* Row `row` of every order, lexicographic (the factorial number system). */
static void hol__permutation(int n, uint64_t row, int *out)
{
    int left[HOL_STUDY_MAX_CONDITIONS];
    uint64_t f = 1;
    for (int k = 0; k < n; k++)
        left[k] = k;
    for (int k = 2; k < n; k++)
        f *= (uint64_t)k; /* (n-1)! */
    for (int pos = 0; pos < n; pos++) {
        int m = n - pos; /* conditions left */
        uint64_t pick = m > 1 ? row / f : 0;
        row = m > 1 ? row % f : 0;
        out[pos] = left[pick];
        memmove(&left[pick], &left[pick + 1], (size_t)(m - 1 - (int)pick) * sizeof left[0]);
        if (m > 1)
            f /= (uint64_t)(m - 1 > 0 ? m - 1 : 1);
    }
}

hol_err hol_study_square(hol_study_rule rule, int n, uint64_t row, int *out)
{
    uint64_t rows = hol_study_rows(rule, n);
    if (!rows || row >= rows)
        return HOL_EARG;
    if (rule == HOL_STUDY_COMPLETE) {
        hol__permutation(n, row, out);
        return HOL_OK;
    }
    int r = (int)(row % (uint64_t)n), mirror = row >= (uint64_t)n;
    for (int j = 0; j < n; j++) {
        int first = j; /* latin and fixed: 0, 1, ..., n-1 */
        if (rule == HOL_STUDY_WILLIAMS)
            first = j == 0 ? 0 : j % 2 ? (j + 1) / 2 : n - j / 2;
        int v = rule == HOL_STUDY_FIXED ? first : (first + r) % n;
        out[mirror ? n - 1 - j : j] = v;
    }
    return HOL_OK;
}

hol_err hol_study_order(const hol_study *s, uint64_t participant, int *out)
{
    uint64_t rows = hol_study_rows(s->rule, s->nconditions);
    if (participant == 0 || rows == 0)
        return HOL_EARG;
    return hol_study_square(s->rule, s->nconditions, (participant - 1) % rows, out);
}

int hol_study_session(const hol_study *s, const int *order, int *out, int *out_cond,
                      int *out_pos)
{
    int n = 0;
    for (int i = 0; i < s->npractice; i++, n++)
        out[n] = i, out_cond[n] = -1, out_pos[n] = 0;
    for (int k = 0; k < s->nconditions; k++) {
        const hol_study_condition *c = &s->conditions[order[k]];
        for (int i = 0; i < c->nlevels; i++, n++)
            out[n] = c->first_level + i, out_cond[n] = order[k], out_pos[n] = k + 1;
    }
    return n;
}

void hol_study_level_path(const hol_study *s, int i, char path[HOL_STUDY_PATH_MAX])
{
    const hol_study_span *sp = &s->levels[i];
    memcpy(path, s->text + sp->off, sp->len);
    path[sp->len] = 0;
}

int hol_study_level_condition(const hol_study *s, int i)
{
    for (int c = 0; c < s->nconditions; c++)
        if (i >= s->conditions[c].first_level &&
            i < s->conditions[c].first_level + s->conditions[c].nlevels)
            return c;
    return -1;
}

/* ---- a level line's key ---------------------------------------------------- */

/* The key of a level line [b, e): its first field before any comment. */
size_t hol__study_key(const char *b, const char *e, const char **out)
{
    const char *hash = memchr(b, '#', (size_t)(e - b));
    return hol__study_field(&b, hash ? hash : e, out);
}

static int hol__same_key(const hol_study *s, int a, int b)
{
    const char *k, *k2;
    const hol_study_span *x = &s->sets[a], *y = &s->sets[b];
    size_t n = hol__study_key(s->text + x->off, s->text + x->off + x->len, &k);
    size_t n2 = hol__study_key(s->text + y->off, s->text + y->off + y->len, &k2);
    return n == n2 && !memcmp(k, k2, n);
}

/* Is set line j in force for condition c: the condition's own, or the
 * study's when the condition does not set the same key? */
int hol__study_in_force(const hol_study *s, int c, int j)
{
    const hol_study_condition *cd = &s->conditions[c];
    if (j >= cd->first_set && j < cd->first_set + cd->nsets)
        return 1;
    if (j >= s->nglobal)
        return 0;
    for (int i = cd->first_set; i < cd->first_set + cd->nsets; i++)
        if (hol__same_key(s, i, j))
            return 0;
    return 1;
}

/* Does a set line in force for condition c give key [k, k+kn)? */
int hol__study_set_key(const hol_study *s, int c, const char *k, size_t kn)
{
    for (int j = 0; j < s->nsets; j++) {
        const char *k2;
        const hol_study_span *o = &s->sets[j];
        size_t n = hol__study_key(s->text + o->off, s->text + o->off + o->len, &k2);
        if (hol__study_in_force(s, c, j) && n == kn && !memcmp(k, k2, n))
            return 1;
    }
    return 0;
}
