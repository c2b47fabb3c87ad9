/* hol_study.c - study files, counterbalancing squares and a condition's
 * levels (see hol_study.h). */
#include "hol_study.h"

#include "hol_ask.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- errors ------------------------------------------------------------------ */

static hol_err hol__fail(hol_level_err *e, hol_err code, long line, long other,
                         const char *fmt, ...) __attribute__((format(printf, 5, 6)));

static hol_err hol__fail(hol_level_err *e, hol_err code, long line, long other,
                         const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hol_level_err_vset(e, code, line, other, fmt, ap);
    va_end(ap);
    return code;
}

/* ---- lines ------------------------------------------------------------------- */

static int hol__set_key(const hol_study *s, int c, const char *k, size_t kn);

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
static size_t hol__field(const char **p, const char *end, const char **out)
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

static int hol__is(const char *w, size_t n, const char *word)
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
    size_t n = hol__field(&rest, end, out);
    const char *more;
    if (n == 0)
        return hol__fail(p->err, HOL_EPARSE, p->line, 0, "'%s' needs a value", key), -1;
    if (hol__field(&rest, end, &more))
        return hol__fail(p->err, HOL_EPARSE, p->line, 0, "'%s' takes one value", key), -1;
    return (long)n;
}

static hol_err hol__add_level(hol__sp *p, const char *w, size_t n)
{
    hol_study *s = p->s;
    if (s->nlevels >= HOL_STUDY_MAX_LEVELS)
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0,
                         "more than %d levels in all (a recording holds %d)",
                         HOL_STUDY_MAX_LEVELS, HOL_STUDY_MAX_LEVELS);
    if (n >= HOL_STUDY_PATH_MAX)
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "a level's path is longer than %d bytes",
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

static size_t hol__key(const char *b, const char *e, const char **out);
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
        return hol__fail(p->err, HOL_EPARSE, p->line, 0, "'set' needs a level line (KEY VALUE...)");
    hol_level_err le;
    if (hol_level_line_check(rest, (size_t)(end - rest), &le))
        return hol__fail(p->err, le.code, p->line, 0, "set: %s", le.msg);
    if (s->nsets >= HOL_STUDY_MAX_SETS)
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d set lines",
                         HOL_STUDY_MAX_SETS);
    hol_study_span *sp = &s->sets[s->nsets++];
    sp->off = (uint16_t)(rest - s->text);
    sp->len = (uint16_t)(end - rest);
    sp->line = p->line;
    /* a key set twice in one place (the study's, or a condition's) is
     * refused naming both lines, as a level's repeated key is */
    int first = p->cur >= 0 ? s->conditions[p->cur].first_set : 0;
    const char *key;
    size_t kn = hol__key(rest, end, &key);
    for (int i = first; i < s->nsets - 1; i++)
        if (hol__same_key(s, i, s->nsets - 1) && !(kn == 5 && !memcmp(key, "place", 5))) {
            s->nsets--;
            return hol__fail(p->err, HOL_EARG, p->line, s->sets[i].line,
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
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d conditions",
                         HOL_STUDY_MAX_CONDITIONS);
    hol_study_condition *c = &s->conditions[s->nconditions];
    memset(c, 0, sizeof *c);
    if (!hol__name(w, n, c->name))
        return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                         "condition '%.*s' is not 1..63 letters, digits, '.', '_', '-'",
                         (int)(n < 40 ? n : 40), w);
    if (!strcmp(c->name, HOL_STUDY_PRACTICE))
        return hol__fail(p->err, HOL_EARG, p->line, 0,
                         "'practice' names the practice levels, not a condition");
    for (int k = 0; k < s->nconditions; k++)
        if (!strcmp(s->conditions[k].name, c->name))
            return hol__fail(p->err, HOL_EARG, p->line, s->conditions[k].line,
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
        return hol__fail(p->err, HOL_EARG, p->line, 0, "'%s' comes before the first condition",
                         key);
    if (*seen)
        return hol__fail(p->err, HOL_EARG, p->line, *seen, "a second '%s' line", key);
    *seen = p->line;
    if (is_study) {
        if (!hol__name(w, n, p->s->name))
            return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                             "study '%.*s' is not 1..63 letters, digits, '.', '_', '-'",
                             (int)(n < 40 ? n : 40), w);
        return HOL_OK;
    }
    for (int r = 0; r < 4; r++)
        if (hol__is(w, n, rules[r])) {
            p->s->rule = (hol_study_rule)r;
            return HOL_OK;
        }
    return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                     "counterbalance '%.*s' is not williams, latin, complete or fixed",
                     (int)(n < 30 ? n : 30), w);
}

/* allow minimap-toggle: before the first condition; the conditions'
 * minimap is not fixed (M moves it, and the logs say so). */
static hol_err hol__allow(hol__sp *p, const char *w, size_t n)
{
    if (p->cur >= 0)
        return hol__fail(p->err, HOL_EARG, p->line, 0, "'allow' comes before the first condition");
    if (!hol__is(w, n, "minimap-toggle"))
        return hol__fail(p->err, HOL_EPARSE, p->line, 0, "allow '%.*s' is not minimap-toggle",
                         (int)(n < 30 ? n : 30), w);
    if (p->allow_line)
        return hol__fail(p->err, HOL_EARG, p->line, p->allow_line,
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
        return hol__fail(p->err, HOL_EARG, p->line, 0, "'closing' comes before the first condition");
    hol_study_span *sp = closing ? &s->closing
                         : p->cur >= 0 ? &s->conditions[p->cur].instructions
                                       : &s->practice_instructions;
    if (sp->len)
        return hol__fail(p->err, HOL_EARG, p->line, sp->line, "a second '%s' line %s", key,
                         closing ? "in the study" : p->cur >= 0 ? "in this condition"
                                                                : "for the practice");
    hol_level_err le;
    if (hol_level_line_check(b, (size_t)(end - b), &le))
        return hol__fail(p->err, le.code, p->line, 0, "%s", le.msg);
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
        return hol__fail(p->err, HOL_EARG, p->line, 0, "'question' comes before the first condition");
    if (s->nquestions >= HOL_STUDY_MAX_QUESTIONS)
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questions",
                         HOL_STUDY_MAX_QUESTIONS);
    hol_app_question q;
    char msg[160];
    hol_err e = hol_ask_parse_question(b, (size_t)(end - b), &q, msg, sizeof msg);
    if (e)
        return hol__fail(p->err, e, p->line, 0, "%s", msg);
    for (int i = 0; i < s->nquestions; i++)
        if (!strcmp(s->question_ids[i], q.id))
            return hol__fail(p->err, HOL_EARG, p->line, s->questions[i].line,
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
    size_t n = hol__field(&rest, end, &w), n2 = hol__field(&rest, end, &w2);
    const char *items = rest;
    size_t n3 = hol__field(&rest, end, &w3), n4 = hol__field(&rest, end, &more);
    if (p->cur >= 0)
        return hol__fail(p->err, HOL_EARG, p->line, 0,
                         "'questionnaire' comes before the first condition");
    if (!hol_ask_id_ok(w, n) || n2 == 0)
        return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                         "questionnaire needs NAME ITEM... or NAME after|before "
                         "level|condition|study "
                         "(NAME 1..31 letters, digits, '_', '-', '.')");
    char name[HOL_APP_ID_MAX];
    memcpy(name, w, n);
    name[n] = 0;
    int before = hol__is(w2, n2, "before");
    if ((before || hol__is(w2, n2, "after")) && n3 && !n4) {
        int when = hol_ask_when(w3, n3);
        if (when < 0 || hol_ask_before(when))
            return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                             "questionnaire %s %s '%.*s': level, condition or study", name,
                             before ? "before" : "after", (int)(n3 < 20 ? n3 : 20), w3);
        when += before ? HOL_APP_BEFORE_LEVEL : 0;
        for (int k = 0; k < s->nasks; k++)
            if (s->asks[k].when == when && !strcmp(s->asks[k].name, name))
                return hol__fail(p->err, HOL_EARG, p->line, s->asks[k].line,
                                 "questionnaire %s %s %s is given twice", name,
                                 before ? "before" : "after",
                                 hol_ask_when_name(when - (before ? HOL_APP_BEFORE_LEVEL : 0)));
        if (s->nasks >= HOL_APP_MAX_ASKS)
            return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questionnaires asked",
                             HOL_APP_MAX_ASKS);
        hol_study_ask *a = &s->asks[s->nasks++];
        snprintf(a->name, sizeof a->name, "%s", name);
        a->when = when;
        a->line = p->line;
        return HOL_OK;
    }
    if (n3 && !n4 && hol_ask_when(w3, n3) >= 0)
        return hol__fail(p->err, HOL_EPARSE, p->line, 0,
                         "questionnaire %s %.*s %.*s: a questionnaire is placed with "
                         "'after|before level|condition|study'", name, (int)(n2 < 20 ? n2 : 20), w2,
                         (int)n3, w3);
    if (hol_ask_preset(w, n, NULL, 0))
        return hol__fail(p->err, HOL_EARG, p->line, 0, "questionnaire %s is a preset: it has its "
                         "items", name);
    for (int i = 0; i < s->nquestionnaires; i++)
        if (!strcmp(s->questionnaires[i].name, name))
            return hol__fail(p->err, HOL_EARG, p->line, 0, "questionnaire %s is given twice",
                             name);
    if (s->nquestionnaires >= HOL_STUDY_MAX_QUESTIONNAIRES)
        return hol__fail(p->err, HOL_ENOMEM, p->line, 0, "more than %d questionnaires",
                         HOL_STUDY_MAX_QUESTIONNAIRES);
    /* every item a question given before */
    const char *it = w2;
    while (end > it && hol__blank(end[-1]))
        end--;
    for (const char *q = it; q < end;) {
        const char *id;
        size_t k = hol__field(&q, end, &id), j = 0;
        if (!k)
            break;
        while (j < (size_t)s->nquestions && !hol__is(id, k, s->question_ids[j]))
            j++;
        if (j == (size_t)s->nquestions)
            return hol__fail(p->err, HOL_EARG, p->line, 0,
                             "questionnaire %s: no question '%.*s' before it", name,
                             (int)(k < 32 ? k : 32), id);
        const char *q2 = it, *id2;
        size_t k2;
        while ((k2 = hol__field(&q2, end, &id2)) > 0 && id2 < id)
            if (k2 == k && !memcmp(id2, id, k))
                return hol__fail(p->err, HOL_EARG, p->line, 0,
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
    size_t kn = hol__field(&rest, end, &key);
    if (kn == 0)
        return HOL_OK;
    if (hol__is(key, kn, "set"))
        return hol__add_set(p, rest, end);
    if (hol__is(key, kn, "instructions") || hol__is(key, kn, "closing"))
        return hol__screen(p, hol__is(key, kn, "closing"), b, end);
    if (hol__is(key, kn, "question"))
        return hol__question(p, b, end);
    if (hol__is(key, kn, "questionnaire"))
        return hol__questionnaire(p, rest, end);
    static const char *const keys[6] = {"study", "counterbalance", "practice", "condition",
                                        "level", "allow"};
    int k = 0;
    while (k < 6 && !hol__is(key, kn, keys[k]))
        k++;
    if (k == 6)
        return hol__fail(p->err, HOL_EPARSE, p->line, 0,
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
        return hol__fail(p->err, HOL_EARG, p->line, 0,
                         "'practice' comes before the first condition");
    if (k == 4 && p->cur < 0)
        return hol__fail(p->err, HOL_EARG, p->line, 0,
                         "'level' belongs to a condition (before the first: 'practice')");
    return hol__add_level(p, w, (size_t)n);
}

/* After the last line: a name, a condition, and a level for each. */
static hol_err hol__finish(hol__sp *p)
{
    hol_study *s = p->s;
    if (!p->study_line)
        return hol__fail(p->err, HOL_EARG, 0, 0, "no 'study NAME' line");
    if (s->nconditions == 0)
        return hol__fail(p->err, HOL_EARG, 0, 0, "no 'condition NAME' line");
    for (int k = 0; k < s->nasks; k++) {
        const char *nm = s->asks[k].name;
        int known = hol_ask_preset(nm, strlen(nm), NULL, 0) > 0;
        for (int i = 0; i < s->nquestionnaires && !known; i++)
            known = !strcmp(s->questionnaires[i].name, nm);
        char presets[HOL_ASK_NAMES_MAX];
        hol_ask_preset_names("or", presets, sizeof presets);
        if (!known)
            return hol__fail(p->err, HOL_EARG, s->asks[k].line, 0,
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
            return hol__fail(p->err, HOL_ENOMEM, s->conditions[c].line, 0,
                             "more than %d levels in all", HOL_STUDY_MAX_LEVELS);
        if (!hol__set_key(s, c, "mode", 4))
            return hol__fail(p->err, HOL_EARG, s->conditions[c].line, 0,
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
        return hol__fail(err, HOL_ENOMEM, 0, 0, "longer than %d bytes", HOL_STUDY_TEXT_MAX);
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
            e = hol__fail(err, HOL_ENOMEM, p.line, 0, "longer than %d bytes", HOL_STUDY_LINE_MAX);
        else if (memchr(s, 0, (size_t)(le - s)))
            e = hol__fail(err, HOL_EPARSE, p.line, 0, "a NUL byte");
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

/* ---- a condition's level ---------------------------------------------------------- */

/* The key of a level line [b, e): its first field before any comment. */
static size_t hol__key(const char *b, const char *e, const char **out)
{
    const char *hash = memchr(b, '#', (size_t)(e - b));
    return hol__field(&b, hash ? hash : e, out);
}

static int hol__same_key(const hol_study *s, int a, int b)
{
    const char *k, *k2;
    const hol_study_span *x = &s->sets[a], *y = &s->sets[b];
    size_t n = hol__key(s->text + x->off, s->text + x->off + x->len, &k);
    size_t n2 = hol__key(s->text + y->off, s->text + y->off + y->len, &k2);
    return n == n2 && !memcmp(k, k2, n);
}

/* Is set line j in force for condition c: the condition's own, or the
 * study's when the condition does not set the same key? */
static int hol__in_force(const hol_study *s, int c, int j)
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
static int hol__set_key(const hol_study *s, int c, const char *k, size_t kn)
{
    for (int j = 0; j < s->nsets; j++) {
        const char *k2;
        const hol_study_span *o = &s->sets[j];
        size_t n = hol__key(s->text + o->off, s->text + o->off + o->len, &k2);
        if (hol__in_force(s, c, j) && n == kn && !memcmp(k, k2, n))
            return 1;
    }
    return 0;
}

/* A condition's level text being composed: out (cap bytes), origin[k] the
 * line that composed line k + 1 came from (> 0 the file's, < 0 the
 * study's). */
typedef struct hol__compose {
    char *out;
    size_t n, cap;
    long *origin;
    long nlines, max_lines;
    const char *stage; /* what is being added: the overflow's cause */
} hol__compose;

static int hol__put_line(hol__compose *c, const char *s, size_t n, long origin)
{
    if (c->n + n + 1 > c->cap || c->nlines >= c->max_lines)
        return 1;
    memcpy(c->out + c->n, s, n);
    c->n += n;
    c->out[c->n++] = '\n';
    c->origin[c->nlines++] = origin;
    return 0;
}

/* The study's screen lines level i carries (see hol_study.h): its
 * instructions (the first level of the practice or of its condition) and
 * the closing (the participant's last level); NULL when none. */
static const hol_study_span *hol__instr_of(const hol_study *s, int c, int i)
{
    const hol_study_span *sp = c < 0 ? &s->practice_instructions : &s->conditions[c].instructions;
    int first = c < 0 ? 0 : s->conditions[c].first_level;
    return sp->len && i == first ? sp : NULL;
}

static const hol_study_span *hol__closing_of(const hol_study *s, int c, int i, int position)
{
    const hol_study_condition *cd = c >= 0 ? &s->conditions[c] : NULL;
    return s->closing.len && cd && position == s->nconditions &&
                   i == cd->first_level + cd->nlevels - 1
               ? &s->closing
               : NULL;
}

/* Does the study give level i's line of key [k, k+kn) (a screen line)? */
static int hol__screen_key(const hol_study *s, int c, int i, int position, const char *k,
                           size_t kn)
{
    return (kn == 12 && !memcmp(k, "instructions", 12) && hol__instr_of(s, c, i)) ||
           (kn == 7 && !memcmp(k, "closing", 7) && hol__closing_of(s, c, i, position));
}

/* Is the study's ask k due with level i (condition c, position): after
 * it, or before it (a baseline: `before study` before the participant's
 * first level, the practice's when there is one)? */
static int hol__ask_due(const hol_study *s, int k, int c, int i, int position)
{
    if (s->asks[k].when == HOL_APP_BEFORE_STUDY)
        return s->npractice > 0 ? c < 0 && i == 0
                                : c >= 0 && position == 1 && i == s->conditions[c].first_level;
    if (c < 0)
        return 0; /* practice levels ask nothing else */
    const hol_study_condition *cd = &s->conditions[c];
    int last_of_cond = i == cd->first_level + cd->nlevels - 1;
    switch (s->asks[k].when) {
    case HOL_APP_AFTER_LEVEL:
    case HOL_APP_BEFORE_LEVEL: return 1;
    case HOL_APP_AFTER_CONDITION: return last_of_cond;
    case HOL_APP_BEFORE_CONDITION: return i == cd->first_level;
    default: return last_of_cond && position == s->nconditions;
    }
}

/* The question line of ID [id, id+n) once into the level. 1 when it does
 * not fit. */
static int hol__put_question(const hol_study *s, const char *id, size_t n, hol__compose *cp,
                             unsigned char *put)
{
    for (int j = 0; j < s->nquestions; j++)
        if (hol__is(id, n, s->question_ids[j]) && !put[j]) {
            put[j] = 1;
            return hol__put_line(cp, s->text + s->questions[j].off, s->questions[j].len,
                                 -s->questions[j].line);
        }
    return 0;
}

/* The study's questionnaire NAME (its items), NULL for a preset. */
static const hol_study_questionnaire *hol__qn(const hol_study *s, const char *name)
{
    for (int j = 0; j < s->nquestionnaires; j++)
        if (!strcmp(s->questionnaires[j].name, name))
            return &s->questionnaires[j];
    return NULL;
}

/* The order questionnaires are put in: before study, condition, level;
 * then after level, condition, study. */
static const int hol__whens[HOL_APP_ASK_WHENS] = {
    HOL_APP_BEFORE_STUDY, HOL_APP_BEFORE_CONDITION, HOL_APP_BEFORE_LEVEL,
    HOL_APP_AFTER_LEVEL,  HOL_APP_AFTER_CONDITION,  HOL_APP_AFTER_STUDY};

/* The questionnaires due with level i whose when is hol__whens[from..to):
 * their questions (each once: put), then `ask NAME WHEN ID...`, by when,
 * in the file's order. */
static int hol__put_asks(const hol_study *s, int c, int i, int position, hol__compose *cp,
                         int from, int to, unsigned char *put)
{
    for (int w = from; w < to; w++)
        for (int k = 0; k < s->nasks; k++) {
            const hol_study_ask *a = &s->asks[k];
            int when = hol__whens[w];
            if (a->when != when || !hol__ask_due(s, k, c, i, position))
                continue;
            const hol_study_questionnaire *d = hol__qn(s, a->name);
            char line[HOL_STUDY_LINE_MAX + 64];
            int n = snprintf(line, sizeof line, "ask %s %s", a->name, hol_ask_when_name(when));
            if (d) {
                const char *q = s->text + d->items.off, *end = q + d->items.len, *id;
                size_t kn;
                while ((kn = hol__field(&q, end, &id)) > 0)
                    if (hol__put_question(s, id, kn, cp, put))
                        return 1;
                n += snprintf(line + n, sizeof line - (size_t)n, " %.*s", (int)d->items.len,
                              s->text + d->items.off);
            }
            if (n < 0 || (size_t)n >= sizeof line || hol__put_line(cp, line, (size_t)n, -a->line))
                return 1;
        }
    return 0;
}

/* Is question ID [id, id+n) an item of a questionnaire `before study`? */
static int hol__baseline_item(const hol_study *s, const char *id, size_t n)
{
    for (int k = 0; k < s->nasks; k++) {
        const hol_study_questionnaire *d = hol__qn(s, s->asks[k].name);
        const char *q = d ? s->text + d->items.off : NULL, *end = d ? q + d->items.len : NULL, *f;
        size_t kn;
        while (d && s->asks[k].when == HOL_APP_BEFORE_STUDY && (kn = hol__field(&q, end, &f)) > 0)
            if (kn == n && !memcmp(f, id, n))
                return 1;
    }
    return 0;
}

/* A condition's level without a practice: the questions the questionnaires
 * `before study` share with those due with level i but at the study's
 * ends (before or after its condition or itself), put before the first
 * level's own lines at every position, so that what follows the first
 * level's mark adds only lines (its hash the other positions'). 1 when
 * they do not fit. */
static int hol__put_shared(const hol_study *s, int c, int i, int position, hol__compose *cp,
                           unsigned char *put)
{
    for (int w = 1; w < HOL_APP_ASK_WHENS - 1 && c >= 0 && !s->npractice; w++)
        for (int k = 0; k < s->nasks; k++) {
            const hol_study_questionnaire *d = hol__qn(s, s->asks[k].name);
            if (!d || s->asks[k].when != hol__whens[w] || !hol__ask_due(s, k, c, i, position))
                continue;
            const char *q = s->text + d->items.off, *end = q + d->items.len, *id;
            size_t kn;
            while ((kn = hol__field(&q, end, &id)) > 0)
                if (hol__baseline_item(s, id, kn) && hol__put_question(s, id, kn, cp, put))
                    return 1;
        }
    return 0;
}

/* The questionnaires `before study` due with a condition's level i
 * between HOL_LEVEL_FIRST_MARK and HOL_LEVEL_FIRST_END (outside the
 * level's hash); a practice's level has them as they are (every
 * participant's first). 1 when they do not fit. */
static int hol__put_baseline(const hol_study *s, int c, int i, int position, hol__compose *cp,
                             unsigned char *put)
{
    int due = 0;
    for (int k = 0; k < s->nasks; k++)
        due |= s->asks[k].when == HOL_APP_BEFORE_STUDY && hol__ask_due(s, k, c, i, position);
    long at = c >= 0 ? -s->conditions[c].line : 0;
    if (due && c >= 0 && hol__put_line(cp, HOL_LEVEL_FIRST_MARK, sizeof HOL_LEVEL_FIRST_MARK - 1, at))
        return 1;
    if (hol__put_asks(s, c, i, position, cp, 0, 1, put))
        return 1;
    return due && c >= 0 && hol__put_line(cp, HOL_LEVEL_FIRST_END, sizeof HOL_LEVEL_FIRST_END - 1, at);
}

/* Is a questionnaire `after study` due after level i? */
static int hol__study_ask_due(const hol_study *s, int c, int i, int position)
{
    for (int k = 0; k < s->nasks; k++)
        if (s->asks[k].when == HOL_APP_AFTER_STUDY && hol__ask_due(s, k, c, i, position))
            return 1;
    return 0;
}

/* The screen lines of level i after its text: its questionnaires (but
 * those after the study; those before it, on a condition's level, between
 * the first level's marks), its instructions, then what only the
 * participant's last level carries (the questionnaires `after study`, the
 * closing) after HOL_LEVEL_LAST_MARK, outside the level's hash. 1 when
 * they do not fit. */
static int hol__put_screens(const hol_study *s, int c, int i, int position, hol__compose *cp)
{
    unsigned char put[HOL_STUDY_MAX_QUESTIONS] = {0};
    cp->stage = "questions asked after it";
    if (hol__put_shared(s, c, i, position, cp, put) ||
        hol__put_baseline(s, c, i, position, cp, put) ||
        hol__put_asks(s, c, i, position, cp, 1, HOL_APP_ASK_WHENS - 1, put))
        return 1;
    const hol_study_span *a = hol__instr_of(s, c, i), *b = hol__closing_of(s, c, i, position);
    cp->stage = "instructions";
    if (a && hol__put_line(cp, s->text + a->off, a->len, -a->line))
        return 1;
    int last = b || hol__study_ask_due(s, c, i, position);
    if (last && hol__put_line(cp, HOL_LEVEL_LAST_MARK, sizeof HOL_LEVEL_LAST_MARK - 1,
                              c >= 0 ? -s->conditions[c].line : 0))
        return 1;
    cp->stage = "questions asked after it";
    if (hol__put_asks(s, c, i, position, cp, HOL_APP_ASK_WHENS - 1, HOL_APP_ASK_WHENS, put))
        return 1;
    cp->stage = "closing";
    return b && hol__put_line(cp, s->text + b->off, b->len, -b->line);
}

/* The level file's lines but those a set line (or a screen line of the
 * study's) replaces, the note, the set lines in force, the screens. 1 when
 * it does not fit. c -1: a practice level (no set lines). */
static int hol__compose_text(const hol_study *s, int c, int i, int position, const char *file,
                             size_t len, hol__compose *cp)
{
    const hol_study_condition *cd = c >= 0 ? &s->conditions[c] : NULL;
    long fl = 0;
    for (const char *p = file, *end = file ? file + len : NULL; p && p < end;) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *le = nl ? nl : end, *k;
        fl++;
        size_t n = (size_t)(le - p);
        while (n && p[n - 1] == '\r')
            n--;
        size_t kn = hol__key(p, p + n, &k);
        int replaced = kn && ((c >= 0 && hol__set_key(s, c, k, kn)) ||
                              hol__screen_key(s, c, i, position, k, kn));
        if (!replaced && hol__put_line(cp, p, n, fl))
            return 1;
        p = nl ? nl + 1 : end;
    }
    if (c < 0)
        return hol__put_screens(s, c, i, position, cp);
    int used = 0;
    cp->stage = "set lines";
    for (int j = 0; j < s->nsets; j++)
        used += hol__in_force(s, c, j);
    if (used) {
        char note[160];
        int n = snprintf(note, sizeof note, "# study %s, condition %s:", s->name, cd->name);
        if (hol__put_line(cp, note, (size_t)n, -cd->line))
            return 1;
    }
    for (int j = 0; j < s->nsets; j++)
        if (hol__in_force(s, c, j) &&
            hol__put_line(cp, s->text + s->sets[j].off, s->sets[j].len, -s->sets[j].line))
            return 1;
    /* a condition's minimap holds during its levels (issue 26) */
    if (hol__set_key(s, c, "minimap", 7) && !s->allow_minimap_toggle &&
        hol__put_line(cp, "fixed minimap", 13, -cd->line))
        return 1;
    return hol__put_screens(s, c, i, position, cp);
}

/* A level error's lines, of the composed text, as the file's or the
 * study's. */
static void hol__map_err(const hol__compose *cp, long cond_line, hol_level_err *err,
                         int *in_study)
{
    long o = err->line > 0 && err->line <= cp->nlines ? cp->origin[err->line - 1]
             : err->line > 0                           ? -cond_line
                                                       : 0;
    *in_study = o < 0;
    err->line = o < 0 ? -o : o;
    if (err->other > 0 && err->other <= cp->nlines) {
        long m = cp->origin[err->other - 1];
        err->other = (m < 0) == *in_study ? (m < 0 ? -m : m) : 0;
    }
}

/* An error on a study's set line says "set: " as the line's own check
 * does (issue 39: `set place lantern` errors found once composed). */
static void hol__set_prefix(const hol_study *s, int in_study, hol_level_err *err)
{
    int on_set = 0;
    for (int j = 0; in_study && j < s->nsets; j++)
        on_set |= s->sets[j].line == err->line;
    if (!on_set || !strncmp(err->msg, "set", 3))
        return;
    size_t n = strlen(err->msg);
    if (n > sizeof err->msg - 6)
        n = sizeof err->msg - 6;
    memmove(err->msg + 5, err->msg, n);
    memcpy(err->msg, "set: ", 5);
    err->msg[n + 5] = 0;
}

static hol_err hol__make_at(const hol_study *s, int i, int position, const char *file,
                           size_t len, const char *name, hol_level *out, hol_level_err *err,
                           int *out_in_study)
{
    char buf[HOL_LEVEL_TEXT_MAX + 1];
    long origin[HOL_LEVEL_TEXT_MAX / 2 + 2];
    *out_in_study = 0;
    if (i < 0 || i >= s->nlevels)
        return hol__fail(err, HOL_EARG, 0, 0, "no level %d in the study", i);
    int c = hol_study_level_condition(s, i);
    const char *cname = c < 0 ? HOL_STUDY_PRACTICE : s->conditions[c].name;
    if (!name)
        name = cname;
    hol__compose cp = {buf, 0, sizeof buf, origin, 0, (long)(sizeof origin / sizeof origin[0]),
                       "level file's lines"};
    /* a practice level is the file as it is, unless it carries the
     * practice's instructions or a questionnaire before the study */
    int composed = c >= 0 || hol__instr_of(s, c, i);
    for (int k = 0; k < s->nasks && !composed; k++)
        composed = hol__ask_due(s, k, c, i, position);
    long at = c >= 0 ? s->conditions[c].line : s->practice_instructions.line;
    if (composed && hol__compose_text(s, c, i, position, file, len, &cp)) {
        *out_in_study = 1;
        return hol__fail(err, HOL_ENOMEM, at, 0,
                         "%s %s: its level with the %s is longer than %d bytes",
                         c >= 0 ? "condition" : "the", cname, cp.stage, HOL_LEVEL_TEXT_MAX);
    }
    const char *t = composed ? buf : file ? file : "";
    size_t tl = composed ? cp.n : file ? len : 0;
    hol_err e = hol_level_make(name, strlen(name), t, tl, out, err);
    if (e) {
        if (composed)
            hol__map_err(&cp, at, err, out_in_study);
        hol__set_prefix(s, *out_in_study, err);
        return e;
    }
    snprintf(out->condition, sizeof out->condition, "%s", cname);
    out->position = c < 0 ? 0 : position;
    return HOL_OK;
}

/* What a condition's level carries depends on its position only through
 * being the last (the closing, the asks `after study`): the positions
 * condition c can take, one not the last and the last (fixed: its own). */
static int hol__positions(const hol_study *s, int c, int out[2])
{
    int n = s->nconditions;
    if (s->rule == HOL_STUDY_FIXED || n < 2) {
        out[0] = s->rule == HOL_STUDY_FIXED ? c + 1 : n;
        return 1;
    }
    out[0] = 1, out[1] = n;
    return 2;
}

hol_err hol_study_make_level(const hol_study *s, int i, int position, const char *file,
                             size_t len, const char *name, hol_level *out, hol_level_err *err,
                             int *out_in_study)
{
    int c = i >= 0 && i < s->nlevels ? hol_study_level_condition(s, i) : -1, at[2];
    int n = c >= 0 ? hol__positions(s, c, at) : 0, last = s->nconditions;
    for (int k = 0; k < n; k++) {
        if ((at[k] == last) == (position == last))
            continue; /* the participant's own position is made last, below */
        hol_err e = hol__make_at(s, i, at[k], file, len, name, out, err, out_in_study);
        hol_level_err mine;
        int mine_in = 0;
        /* an error at the position given too is its own, unmarked */
        hol_err e2 = e ? hol__make_at(s, i, position, file, len, name, out, &mine, &mine_in)
                       : HOL_OK;
        if (e2) {
            *err = mine, *out_in_study = mine_in;
            return e2;
        }
        if (e) {
            size_t m = strlen(err->msg);
            snprintf(err->msg + m, sizeof err->msg - m, " (at position %d of %d, %s)", at[k],
                     last, at[k] == last ? "the last" : "not the last");
            return e;
        }
    }
    return hol__make_at(s, i, position, file, len, name, out, err, out_in_study);
}
