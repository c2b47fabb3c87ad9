/* hol_level_parse.c - level files read (see hol_level.h): the table of
 * keys, a line read and handed to its key, the two passes over a text, a
 * line checked alone and an objective's line found (the parser's files:
 * hol_level_impl.h). */
#include "hol_level_impl.h"

#include <stdio.h>
#include <string.h>

/* ---- the keys ---------------------------------------------------------------- */

/* Keys a build adds after the standard ones (a test's example row,
 * docs/hacking.md). */
#ifndef HOL_LEVEL_MORE_KEYS
#define HOL_LEVEL_MORE_KEYS
#endif

/* A key's columns: HOL__REPEAT, given on many lines (each other key once:
 * a second line is refused naming both); HOL__GEO, read in a first pass
 * (addresses need the tiling). */
#define HOL__REPEAT 1u
#define HOL__GEO 2u

/* Every key, with its least and most fields (the key included), its
 * columns and its function (hol_level_keys.c, hol_level_ask.c). */
static const struct {
    const char *key;
    int min, max;
    unsigned flags;
    hol_err (*fn)(hol__lp *p, char **f, int nf);
} hol__keys[] = {
    {"mode", 2, 2, 0, hol__key_mode},
    {"seed", 2, 2, 0, hol__key_seed},
    {"start", 2, 2, 0, hol__key_start},
    {"flag", 2, 2, 0, hol__key_tile},
    {"chest", 2, 2, 0, hol__key_tile},
    {"keys", 2, 1 + HOL_APP_MAX_KEYS, 0, hol__key_keys},
    {"flag-distance", 2, 3, 0, hol__key_dist},
    {"chest-distance", 2, 3, 0, hol__key_dist},
    {"keys-distance", 3, 4, 0, hol__key_keys_dist},
    {"time-limit", 2, 2, 0, hol__key_time_limit},
    {"stages", 2, HOL__FIELDS + 1, 0, hol__key_stages},
    {"place", 3, 5, HOL__REPEAT, hol__key_place},
    {"cues", 2, HOL__FIELDS + 1, 0, hol__key_cues},
    {"minimap", 2, 2, 0, hol__key_minimap},
    {"fixed", 2, 2, 0, hol__key_fixed},
    {"lighting", 2, 3, 0, hol__key_lighting},
    {"lantern", 2, 2, 0, hol__key_carried},
    {"sound", 2, 2, 0, hol__key_sound},
    {"lang", 2, 2, 0, hol__key_lang},
    {"point", 2, 2, 0, hol__key_point},
    {"instructions", 2, HOL__FIELDS + 1, 0, hol__key_text},
    {"closing", 2, HOL__FIELDS + 1, 0, hol__key_text},
    {"question", 3, HOL__FIELDS + 1, HOL__REPEAT, hol__key_question},
    {"ask", 3, HOL__FIELDS + 1, HOL__REPEAT, hol__key_ask},
    {"tiling", 3, 3, HOL__GEO, hol__key_tiling},
    {"room", 3, 3, HOL__GEO, hol__key_room},
    {"cell", 2, 2, HOL__GEO, hol__key_cell},
    {"lesson", 2, 2, 0, hol__key_lesson},
    {"quiz", 2, 2, 0, hol__key_quiz},
    HOL_LEVEL_MORE_KEYS
};
_Static_assert(sizeof hol__keys / sizeof hol__keys[0] <= 32, "hol__lp.key_line holds every key");

/* The columns of the key named key (0: no such key). */
static unsigned hol__key_flags(const char *key)
{
    for (size_t k = 0; k < sizeof hol__keys / sizeof hol__keys[0]; k++)
        if (!strcmp(key, hol__keys[k].key))
            return hol__keys[k].flags;
    return 0;
}

/* ---- lines -------------------------------------------------------------------- */

/* Split line (NUL-terminated, comment removed) at spaces and tabs into at
 * most HOL__FIELDS NUL-terminated fields; returns the count, or
 * HOL__FIELDS + 1 when there are more. */
static int hol__split(char *line, char **f)
{
    int n = 0;
    char *s = line;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            return n;
        if (n == HOL__FIELDS)
            return n + 1;
        f[n++] = s;
        while (*s && *s != ' ' && *s != '\t')
            s++;
        if (*s)
            *s++ = 0;
    }
}

/* One line (n bytes at s, without its LF): comment, fields, its key. */
static hol_err hol__line(hol__lp *p, const char *s, size_t n)
{
    char line[HOL_LEVEL_LINE_MAX + 1];
    while (n && s[n - 1] == '\r')
        n--;
    if (n > HOL_LEVEL_LINE_MAX)
        return hol__lfail(p, HOL_ENOMEM, p->line, "longer than %d bytes", HOL_LEVEL_LINE_MAX);
    if (memchr(s, 0, n))
        return hol__lfail(p, HOL_EPARSE, p->line, "a NUL byte");
    memcpy(line, s, n);
    line[n] = 0;
    char *hash = strchr(line, '#');
    if (hash)
        *hash = 0;
    memcpy(p->raw, line, strlen(line) + 1);
    char *f[HOL__FIELDS];
    int nf = hol__split(line, f);
    if (nf == 0)
        return HOL_OK;
    if (nf < 2)
        return hol__lfail(p, HOL_EPARSE, p->line, "'%.20s' needs a value", f[0]);
    if (p->geo_only && !(hol__key_flags(f[0]) & HOL__GEO))
        return HOL_OK;
    for (size_t k = 0; k < sizeof hol__keys / sizeof hol__keys[0]; k++)
        if (!strcmp(f[0], hol__keys[k].key) && nf >= hol__keys[k].min &&
            nf <= hol__keys[k].max) {
            /* a key given twice is refused, naming both lines (no silent
             * last-wins) unless the table marks it HOL__REPEAT */
            if (p->key_line[k] && !(hol__keys[k].flags & HOL__REPEAT)) {
                hol_level_err *quiet = p->err;
                p->err = p->loud;
                p->repeated = 1;
                hol__lfail(p, HOL_EARG, p->line, "'%s' is given twice; give each key once",
                           f[0]);
                if (p->err)
                    p->err->other = p->key_line[k];
                p->err = quiet;
                return HOL_EARG;
            }
            p->key_line[k] = p->line;
            return hol__keys[k].fn(p, f, nf);
        }
    return hol__lfail(p, HOL_EPARSE, p->line, "unknown key or wrong value count: '%.20s'", f[0]);
}

/* A lesson level (`lesson N`) sets its mode, route, questions, screens and
 * pointing itself: a line that would set them too is refused, naming the
 * lesson's line. */
static hol_err hol__lesson_alone(hol__lp *p)
{
    static const char *const own[] = {"mode",         "start",         "flag",     "chest",
                                      "keys",         "flag-distance", "keys-distance",
                                      "chest-distance", "stages",      "point",    "instructions",
                                      "closing",      "question",      "ask"};
    long lesson = 0;
    for (size_t k = 0; k < sizeof hol__keys / sizeof hol__keys[0]; k++)
        if (!strcmp(hol__keys[k].key, "lesson"))
            lesson = p->key_line[k];
    if (!lesson)
        return HOL_OK;
    for (size_t k = 0; k < sizeof hol__keys / sizeof hol__keys[0]; k++)
        for (size_t j = 0; j < sizeof own / sizeof own[0]; j++)
            if (p->key_line[k] && !strcmp(hol__keys[k].key, own[j])) {
                hol__lfail(p, HOL_EARG, p->key_line[k],
                           "a lesson level sets its own '%s': drop this line", own[j]);
                if (p->err)
                    p->err->other = lesson;
                return HOL_EARG;
            }
    return HOL_OK;
}

/* ---- the API ------------------------------------------------------------------ */

hol_err hol_level_parse(const char *text, size_t len, hol_app_level *out, hol_level_err *err)
{
    hol__lv_skip_bom(&text, &len);
    static const hol__lp zero;
    hol__lp p = zero;
    p.L.cues = HOL_CUE_ALL;
    p.err = err;
    p.loud = err;
    /* the bound is on the text as a session keeps it (hol_level_make adds
     * a last line end), so what parses is kept whole and parses again */
    size_t kept = len + (len && text[len - 1] != '\n');
    if (kept > HOL_LEVEL_TEXT_MAX)
        return hol__lfail(&p, HOL_ENOMEM, 0, "longer than %d bytes (its last line end counted)",
                          HOL_LEVEL_TEXT_MAX);
    /* two passes: the geometry lines first (quietly: the second pass
     * reports every line's error in order), then every line in the
     * level's tiling */
    for (int pass = 0; pass < 2; pass++) {
        p.geo_only = !pass;
        p.err = pass ? err : NULL;
        p.line = 0;
        memset(p.key_line, 0, sizeof p.key_line);
        const char *s = text, *end = text + len;
        while (s < end) {
            const char *nl = memchr(s, '\n', (size_t)(end - s));
            const char *le = nl ? nl : end;
            p.line++;
            hol_err e = hol__line(&p, s, (size_t)(le - s));
            if (e && pass)
                return e;
            /* a repeated geometry line is refused before any address is
             * read in a tiling that a later line changes */
            if (e && p.repeated)
                return e;
            s = nl ? nl + 1 : end;
        }
    }
    hol_err e = hol__lesson_alone(&p);
    if (!e)
        e = hol__lv_finish(&p);
    if (e)
        return e;
    *out = p.L;
    return HOL_OK;
}

hol_err hol_level_line_check(const char *s, size_t n, hol_level_err *err)
{
    /* an address may be one of any tiling (the level's own tiling line may
     * come from elsewhere): the line is good when some tiling reads it;
     * the error is {4,5}'s */
    static const int qs[5] = {5, 4, 6, 7, 8};
    hol_err first = HOL_OK;
    for (int i = 0; i < 5; i++) {
        static const hol__lp zero;
        hol__lp p = zero;
        p.L.cues = HOL_CUE_ALL;
        p.L.tiling_q = qs[i];
        p.err = i ? NULL : err;
        p.line = 1;
        hol_err e = hol__line(&p, s, n);
        if (!e)
            return HOL_OK;
        if (!i)
            first = e;
    }
    return first;
}

long hol_level_objective_line(const hol_level *lv)
{
    static const char *const keys[] = {"flag", "flag-distance", "keys", "keys-distance",
                                       "chest", "chest-distance"};
    int mode = lv->lvl.mode, from = mode == HOL_APP_FLAG ? 0 : 2, to = mode == HOL_APP_FLAG ? 2 : 6;
    if (mode != HOL_APP_FLAG && mode != HOL_APP_KEYS)
        return 0;
    long line = 0;
    for (const char *s = lv->text, *end = lv->text + lv->len; s < end;) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        const char *le = nl ? nl : end;
        line++;
        while (s < le && (*s == ' ' || *s == '\t'))
            s++;
        size_t n = 0;
        while (s + n < le && s[n] != ' ' && s[n] != '\t' && s[n] != '#')
            n++;
        for (int k = from; k < to; k++)
            if (strlen(keys[k]) == n && !memcmp(s, keys[k], n))
                return line > lv->added ? line - lv->added : 0;
        s = nl ? nl + 1 : end;
    }
    return 0;
}
