/* hol_study_level.c - a condition's level (hol_study_make_level, see
 * hol_study.h): the level file's lines, the study's set lines in force,
 * its questionnaires and screens, composed into one level text and made. */
#include "hol_study.h"
#include "hol_study_impl.h"

#include "hol_ask.h"

#include <stdio.h>
#include <string.h>

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
        if (hol__study_is(id, n, s->question_ids[j]) && !put[j]) {
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
                while ((kn = hol__study_field(&q, end, &id)) > 0)
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
        while (d && s->asks[k].when == HOL_APP_BEFORE_STUDY && (kn = hol__study_field(&q, end, &f)) > 0)
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
            while ((kn = hol__study_field(&q, end, &id)) > 0)
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
        size_t kn = hol__study_key(p, p + n, &k);
        int replaced = kn && ((c >= 0 && hol__study_set_key(s, c, k, kn)) ||
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
        used += hol__study_in_force(s, c, j);
    if (used) {
        char note[160];
        int n = snprintf(note, sizeof note, "# study %s, condition %s:", s->name, cd->name);
        if (hol__put_line(cp, note, (size_t)n, -cd->line))
            return 1;
    }
    for (int j = 0; j < s->nsets; j++)
        if (hol__study_in_force(s, c, j) &&
            hol__put_line(cp, s->text + s->sets[j].off, s->sets[j].len, -s->sets[j].line))
            return 1;
    /* a condition's minimap holds during its levels (issue 26) */
    if (hol__study_set_key(s, c, "minimap", 7) && !s->allow_minimap_toggle &&
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
        return hol__study_fail(err, HOL_EARG, 0, 0, "no level %d in the study", i);
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
        return hol__study_fail(err, HOL_ENOMEM, at, 0,
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
