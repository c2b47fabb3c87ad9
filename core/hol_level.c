/* hol_level.c - level files' ground (see hol_level.h, hol_level_impl.h):
 * errors set and formatted, names, and the parser's helpers every line
 * kind uses (its one way to fail, numbers, words and addresses). It calls
 * no other level file. */
#include "hol_level_impl.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hol_tile.h"

hol_err hol_level_err_vset(hol_level_err *e, hol_err code, long line, long other,
                           const char *fmt, va_list ap)
{
    if (e) {
        memset(e, 0, sizeof *e);
        e->code = code;
        e->line = line;
        e->other = other;
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    }
    return code;
}

hol_err hol__lfail(hol__lp *p, hol_err code, long line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    hol_level_err_vset(p->err, code, line, 0, fmt, ap);
    va_end(ap);
    return code;
}

/* A conflict with another line: "... (line M)", or "... on line M". */
hol_err hol__lv_conflict(hol__lp *p, long line, long other, int on, const char *what,
                             const char *addr)
{
    if (on)
        hol__lfail(p, HOL_EARG, line, "%.30s is already placed", addr);
    else
        hol__lfail(p, HOL_EARG, line, "the placement on %.30s conflicts with %s", addr, what);
    if (p->err) {
        p->err->other = other;
        p->err->other_on = on;
    }
    return HOL_EARG;
}

/* ---- numbers and words ------------------------------------------------------ */


/* A positive decimal count (digits only, at most 2^40); 0 when it is not. */
uint64_t hol__lv_count(const char *s)
{
    uint64_t v = 0;
    if (!*s)
        return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9' || v > (UINT64_C(1) << 40))
            return 0;
        v = v * 10 + (uint64_t)(*s - '0');
    }
    return v <= (UINT64_C(1) << 40) ? v : 0;
}

/* An unsigned 64-bit number, decimal or 0x hex (a leading 0 is not octal;
 * no sign, no blanks): 1 ok. */
int hol__lv_u64(const char *s, uint64_t *out)
{
    int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    const char *d = hex ? s + 2 : s;
    uint64_t v = 0, base = hex ? 16 : 10;
    if (!*d)
        return 0;
    for (; *d; d++) {
        int c = *d;
        int k = c >= '0' && c <= '9' ? c - '0'
                : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                              : -1;
        if (k < 0 || v > (UINT64_MAX - (uint64_t)k) / base)
            return 0;
        v = v * base + (uint64_t)k;
    }
    *out = v;
    return 1;
}

/* Index of word in names[n], or -1. */
int hol__lv_word(const char *word, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(word, names[i]))
            return i;
    return -1;
}

/* "MIN [MAX]" of a distance key from field first: 1 <= MIN <= MAX <= 10. */
int hol__lv_range(char **f, int nf, int first, int *lo, int *hi)
{
    uint64_t a = hol__lv_count(f[first]);
    uint64_t b = nf > first + 1 ? hol__lv_count(f[first + 1]) : a;
    if (!a || !b || a > HOL_LEVEL_MAX_DIST || b > HOL_LEVEL_MAX_DIST || a > b)
        return 1;
    *lo = (int)a;
    *hi = (int)b;
    return 0;
}

hol_err hol__lv_one_of(hol__lp *p, char **f, const char *const *names, int n, const char *list,
                       int *out)
{
    int m = hol__lv_word(f[1], names, n);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "%s '%.20s' is not %s", f[0], f[1], list);
    *out = m;
    return HOL_OK;
}

/* ---- addresses -------------------------------------------------------------- */

/* The level's tiling Q (the geometry lines are read first). */
int hol__lv_q(const hol__lp *p)
{
    return p->L.tiling_q ? p->L.tiling_q : HOL_TILING_DEFAULT_Q;
}

/* An address of the level's tiling at s into *t: 0, or the failure
 * reported for what ("'ADDR'", "key 'ADDR'"). A tile must lie inside the
 * reach of tile words with its neighbours (its distance below
 * hol_tile_reach: 59 letters in {4,6} and {4,7} was exit 1 at start). */
hol_err hol__lv_addr(hol__lp *p, const char *s, const char *what, hol_tile *t)
{
    int q = hol__lv_q(p), reach = hol_tile_reach(q);
    if (hol_tile_parse_q(q, s, -1, t))
        return hol__lfail(p, HOL_EPARSE, p->line, "%s'%.30s' is not a canonical address of {4,%d}",
                          what, s, q);
    if (hol_tile_dist(hol_tile_origin_q(q), *t) >= reach)
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "%s'%.30s...' lies %d steps from O; a level's tile lies at most %d "
                          "in {4,%d}", what, s, hol_tile_dist(hol_tile_origin_q(q), *t),
                          reach - 1, q);
    return HOL_OK;
}


/* A UTF-8 byte order mark at the start of a text (some editors write
 * one) is skipped: the text begins after it. */
void hol__lv_skip_bom(const char **text, size_t *len)
{
    if (*len >= 3 && !memcmp(*text, "\xef\xbb\xbf", 3))
        *text += 3, *len -= 3;
}

/* ---- errors formatted, names ------------------------------------------------ */

char *hol_level_err_format(const hol_level_err *err, long first, char *out, size_t cap)
{
    int n = err->line > 0 ? snprintf(out, cap, "line %ld: %s", first + err->line - 1, err->msg)
                          : snprintf(out, cap, "%s", err->msg);
    if (err->other > 0 && n >= 0 && (size_t)n < cap)
        snprintf(out + n, cap - (size_t)n, err->other_on ? " on line %ld" : " (line %ld)",
                 first + err->other - 1);
    return out;
}

int hol_level_name_ok(const char *name, size_t len)
{
    return len > 0 && len < HOL_LEVEL_NAME_MAX && !memchr(name, 0, len) &&
           !memchr(name, '\n', len) && !memchr(name, '\r', len);
}

/* ---- cell values read and written ------------------------------------------ */

hol_err hol_level_parse_cell(const char *s, size_t len, double *out_m)
{
    long v = 0;
    size_t i = 0, digits = 0, decimals = 0;
    for (; i < len && s[i] >= '0' && s[i] <= '9' && digits < 4; i++, digits++)
        v = v * 10 + (s[i] - '0');
    if (!digits)
        return HOL_EPARSE;
    if (i < len && s[i] == '.') {
        for (i++; i < len && s[i] >= '0' && s[i] <= '9' && decimals < 3; i++, decimals++)
            v = v * 10 + (s[i] - '0');
        if (!decimals)
            return HOL_EPARSE;
    }
    if (i != len)
        return i < len && s[i] >= '0' && s[i] <= '9' ? HOL_ERANGE : HOL_EPARSE;
    for (; decimals < 3; decimals++)
        v *= 10;
    if (v < 500 || v > 1500)
        return HOL_ERANGE;
    *out_m = (double)v / 1000.0; /* the nearest double, as strtod gives */
    return HOL_OK;
}

char *hol_level_format_cell(double m, char out[16])
{
    if (!(m > 0))
        m = 1.0;
    snprintf(out, 16, "%.3f", m);
    char *e = out + strlen(out);
    while (e > out && e[-1] == '0')
        *--e = 0;
    if (e > out && e[-1] == '.')
        *--e = 0;
    return out;
}
