/* hol_level_write.c - named levels (see hol_level.h): the text as a
 * recording carries it, its hash, and the geometry lines a session adds
 * before the file's first. */
#include "hol_level_impl.h"

#include <stdio.h>
#include <string.h>

#include "hol_sha256.h"

/* The start of text's line that is exactly mark m (from byte from on),
 * its end in *out_end; len when none. */
static size_t hol__level_line(const char *text, size_t len, size_t from, const char *m,
                              size_t *out_end)
{
    size_t mn = strlen(m);
    for (size_t o = from; o < len;) {
        const char *nl = memchr(text + o, '\n', len - o);
        size_t n = (size_t)((nl ? nl : text + len) - (text + o));
        if (n == mn && !memcmp(text + o, m, mn)) {
            *out_end = o + n + (nl != NULL);
            return o;
        }
        o += n + 1;
    }
    *out_end = len;
    return len;
}

/* The bytes of text the hash covers: up to the line HOL_LEVEL_LAST_MARK
 * (a study's lines for a participant's last level), else all, but the
 * lines from HOL_LEVEL_FIRST_MARK to HOL_LEVEL_FIRST_END (a participant's
 * first level's) before it. */
static void hol__level_hashed(hol_level *lv)
{
    size_t e;
    lv->hashed = hol__level_line(lv->text, lv->len, 0, HOL_LEVEL_LAST_MARK, &e);
    size_t a = hol__level_line(lv->text, lv->hashed, 0, HOL_LEVEL_FIRST_MARK, &e);
    size_t b = a < lv->hashed ? hol__level_line(lv->text, lv->hashed, e, HOL_LEVEL_FIRST_END, &e)
                              : lv->hashed;
    lv->cut_from = lv->cut_to = 0;
    if (b < lv->hashed)
        lv->cut_from = a, lv->cut_to = e;
}

size_t hol_level_hashed_text(const hol_level *lv, char out[HOL_LEVEL_TEXT_MAX + 2])
{
    size_t n = lv->cut_to > lv->cut_from ? lv->cut_from : lv->hashed;
    memcpy(out, lv->text, n);
    if (lv->cut_to > lv->cut_from) {
        memcpy(out + n, lv->text + lv->cut_to, lv->hashed - lv->cut_to);
        n += lv->hashed - lv->cut_to;
    }
    return n;
}

hol_err hol_level_make(const char *name, size_t name_len, const char *text, size_t len,
                       hol_level *out, hol_level_err *err)
{
    hol__lp p;
    memset(&p, 0, sizeof p);
    p.err = err;
    if (!hol_level_name_ok(name, name_len))
        return hol__lfail(&p, HOL_EARG, 0,
                         name_len == 0 ? "an empty level name"
                         : name_len >= HOL_LEVEL_NAME_MAX
                             ? "a level name longer than 63 bytes"
                             : "a level name with a NUL, CR or LF byte, which a recording "
                               "cannot carry");
    hol__lv_skip_bom(&text, &len); /* not kept: the text may gain lines before it */
    hol_err e = hol_level_parse(text, len, &out->lvl, err);
    if (e)
        return e;
    /* the parse skips a BOM of its own: keep what it read, so that the kept
     * text parses and hashes the same when a recording carries it again */
    hol__lv_skip_bom(&text, &len);
    /* the text as a recording carries it: LF line ends (CRs before them
     * dropped), the last line's too */
    size_t o = 0;
    for (const char *s = text, *end = text + len; s < end;) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        size_t n = (size_t)((nl ? nl : end) - s);
        while (n && s[n - 1] == '\r')
            n--;
        memcpy(out->text + o, s, n);
        o += n;
        out->text[o++] = '\n';
        s = nl ? nl + 1 : end;
    }
    out->text[o] = 0;
    out->len = o;
    memcpy(out->name, name, name_len);
    out->name[name_len] = 0;
    out->condition[0] = 0;
    out->position = 0;
    out->added = 0;
    hol__level_hashed(out);
    char hashed[HOL_LEVEL_TEXT_MAX + 2];
    hol_sha256(hashed, hol_level_hashed_text(out, hashed), out->sha256);
    return HOL_OK;
}

/* ---- the geometry lines a session adds -------------------------------------- */

hol_err hol_level_set_geometry(hol_level *lv, int q, int cols, int rows, double cell_m,
                               hol_level_err *err)
{
    hol__lp p;
    memset(&p, 0, sizeof p);
    p.err = err;
    const hol_app_level *L = &lv->lvl;
    char add[96], had[32], want[32];
    size_t n = 0;
    had[0] = want[0] = 0;
    if (L->mode == HOL_APP_TUTORIAL) /* its lessons are made for {4,5} 3 x 3 */
        q = cols = rows = 0;
    if (q && L->tiling_q && L->tiling_q != q)
        snprintf(had, sizeof had, "tiling 4 %d", L->tiling_q),
            snprintf(want, sizeof want, "{4,%d}", q);
    else if (cols && L->room_cols && (L->room_cols != cols || L->room_rows != rows))
        snprintf(had, sizeof had, "room %d %d", L->room_cols, L->room_rows),
            snprintf(want, sizeof want, "%dx%d", cols, rows);
    else if (cell_m > 0 && L->cell_m > 0 && L->cell_m != cell_m) {
        char a[16], b[16];
        snprintf(had, sizeof had, "cell %s", hol_level_format_cell(L->cell_m, a));
        snprintf(want, sizeof want, "%s m", hol_level_format_cell(cell_m, b));
    }
    if (had[0])
        return hol__lfail(&p, HOL_EARG, 0,
                          "its own line '%s' differs from the %s asked for", had, want);
    if (q && !L->tiling_q)
        n += (size_t)snprintf(add + n, sizeof add - n, "tiling 4 %d\n", q);
    if (cols && !L->room_cols)
        n += (size_t)snprintf(add + n, sizeof add - n, "room %d %d\n", cols, rows);
    if (cell_m > 0 && !(L->cell_m > 0)) {
        char c[16];
        n += (size_t)snprintf(add + n, sizeof add - n, "cell %s\n", hol_level_format_cell(cell_m, c));
    }
    if (!n)
        return HOL_OK;
    if (n + lv->len > HOL_LEVEL_TEXT_MAX)
        return hol__lfail(&p, HOL_ENOMEM, 0, "longer than %d bytes with the geometry lines",
                          HOL_LEVEL_TEXT_MAX);
    static const hol_level zero;
    hol_level nl = zero;
    char text[HOL_LEVEL_TEXT_MAX + 2];
    memcpy(text, add, n);
    memcpy(text + n, lv->text, lv->len);
    hol_err e = hol_level_make(lv->name, strlen(lv->name), text, n + lv->len, &nl, err);
    if (e && err) {
        /* lines of the file as it was (an added line itself: no line) */
        long added = 0;
        for (size_t i = 0; i < n; i++)
            added += add[i] == '\n';
        err->line = err->line > added ? err->line - added : 0;
        err->other = err->other > added ? err->other - added : 0;
    }
    if (e)
        return e;
    memcpy(nl.condition, lv->condition, sizeof nl.condition);
    nl.position = lv->position;
    for (size_t i = 0; i < n; i++)
        nl.added += add[i] == '\n';
    nl.added += lv->added;
    *lv = nl;
    return HOL_OK;
}
