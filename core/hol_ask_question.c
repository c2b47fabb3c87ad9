/* hol_ask_question.c - the question line (see hol_ask.h): a level's or a
 * study's questionnaire item, parsed. */
#include "hol_ask.h"

#include <stdio.h>
#include <string.h>

#include "hol_face.h"

static int hol__word_is(const char *w, size_t n, const char *word)
{
    return strlen(word) == n && !memcmp(w, word, n);
}

/* The next field of [*s, end): a word, or a quoted string (without its
 * quotes); 0 at the end, -1 for an unclosed quote. */
static int hol__tok(const char **s, const char *end, const char **out, size_t *n)
{
    const char *p = *s;
    while (p < end && (*p == ' ' || *p == '\t'))
        p++;
    if (p == end)
        return 0;
    if (*p == '"') {
        const char *q = memchr(p + 1, '"', (size_t)(end - p - 1));
        if (!q)
            return -1;
        *out = p + 1, *n = (size_t)(q - p - 1), *s = q + 1;
        if (*s < end && **s != ' ' && **s != '\t')
            return -1;
        return 2;
    }
    *out = p;
    while (p < end && *p != ' ' && *p != '\t')
        p++;
    *n = (size_t)(p - *out), *s = p;
    return 1;
}

/* A quoted field into out (cap with the NUL): 0 ok. */
static int hol__text(int kind, const char *w, size_t n, char *out, size_t cap)
{
    if (kind != 2 || n == 0 || n >= cap)
        return 1;
    if (hol_face_text_bad(w, n, NULL) < n) /* printable ASCII and Latin-1 only */
        return 1;
    memcpy(out, w, n);
    out[n] = 0;
    return 0;
}

static int hol__int(const char *w, size_t n, int *out)
{
    if (n == 0 || n > 3)
        return 1;
    int v = 0;
    for (size_t i = 0; i < n; i++) {
        if (w[i] < '0' || w[i] > '9')
            return 1;
        v = v * 10 + (w[i] - '0');
    }
    *out = v;
    return 0;
}

#define HOL__BAD(code, ...) (snprintf(msg, cap, __VA_ARGS__), (code))

hol_err hol_ask_parse_question(const char *line, size_t len, hol_app_question *q, char *msg,
                               size_t cap)
{
    const char *s = line, *end = line + len, *w[3 + HOL_APP_MAX_CHOICES + 2];
    size_t n[3 + HOL_APP_MAX_CHOICES + 2];
    int kind[3 + HOL_APP_MAX_CHOICES + 2], nf = 0, k;
    while (nf < (int)(sizeof w / sizeof w[0]) && (k = hol__tok(&s, end, &w[nf], &n[nf])) > 0)
        kind[nf++] = k;
    if (k < 0)
        return HOL__BAD(HOL_EPARSE, "question: a quoted field is not closed, or not followed "
                                    "by a blank");
    if (nf == (int)(sizeof w / sizeof w[0]) && hol__tok(&s, end, &w[0], &n[0]))
        return HOL__BAD(HOL_EPARSE, "question: more than %d choices", HOL_APP_MAX_CHOICES);
    memset(q, 0, sizeof *q);
    if (nf < 3 || !hol__word_is(w[0], n[0], "question") || kind[1] != 1)
        return HOL__BAD(HOL_EPARSE, "question needs ID likert|choice ...");
    char presets[HOL_ASK_NAMES_MAX];
    hol_ask_preset_names("or", presets, sizeof presets);
    if (!hol_ask_id_ok(w[1], n[1]) || hol_ask_preset(w[1], n[1], NULL, 0))
        return HOL__BAD(HOL_EPARSE, "question: the ID '%.*s' is not 1..31 letters, digits, "
                                    "'_', '-', '.' (and not %s)",
                        (int)(n[1] < 40 ? n[1] : 40), w[1], presets);
    memcpy(q->id, w[1], n[1]);
    if (hol__word_is(w[2], n[2], "likert")) {
        q->kind = HOL_APP_LIKERT;
        q->step = 1;
        if (nf != 8 || kind[3] != 1 || kind[4] != 1 || hol__int(w[3], n[3], &q->lo) ||
            hol__int(w[4], n[4], &q->hi) || hol__text(kind[5], w[5], n[5], q->text, sizeof q->text) ||
            hol__text(kind[6], w[6], n[6], q->low, sizeof q->low) ||
            hol__text(kind[7], w[7], n[7], q->high, sizeof q->high))
            return HOL__BAD(HOL_EPARSE, "question %s likert needs LO HI \"TEXT\" \"LOW\" "
                                        "\"HIGH\" (TEXT 1..95 characters, LOW and HIGH 1..23)",
                            q->id);
        if (q->lo >= q->hi || q->hi > 100 || q->hi - q->lo + 1 > HOL_APP_MAX_SCALE)
            return HOL__BAD(HOL_ERANGE, "question %s: LO below HI, both 0..100, at most %d marks",
                            q->id, HOL_APP_MAX_SCALE);
        return HOL_OK;
    }
    if (!hol__word_is(w[2], n[2], "choice"))
        return HOL__BAD(HOL_EPARSE, "question %s: '%.*s' is not likert or choice", q->id,
                        (int)(n[2] < 20 ? n[2] : 20), w[2]);
    q->kind = HOL_APP_CHOICE;
    if (nf < 6 || nf - 4 > HOL_APP_MAX_CHOICES ||
        hol__text(kind[3], w[3], n[3], q->text, sizeof q->text))
        return HOL__BAD(HOL_EPARSE, "question %s choice needs \"TEXT\" and 2..%d \"CHOICE\"s "
                                    "(TEXT 1..95 characters, a choice 1..23)",
                        q->id, HOL_APP_MAX_CHOICES);
    for (int i = 4; i < nf; i++) {
        if (hol__text(kind[i], w[i], n[i], q->choices[q->nchoices++], HOL_APP_LABEL_MAX))
            return HOL__BAD(HOL_EPARSE, "question %s: choice %d is not a quoted 1..23 "
                                        "characters", q->id, i - 3);
        for (int j = 0; j + 1 < q->nchoices; j++)
            if (!strcmp(q->choices[j], q->choices[q->nchoices - 1]))
                return HOL__BAD(HOL_EARG, "question %s: choice %d is choice %d again ('%s')",
                                q->id, i - 3, j + 1, q->choices[j]);
    }
    return HOL_OK;
}
