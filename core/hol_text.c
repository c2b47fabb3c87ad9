/* hol_text.c - terminal escaping and CSV fields (see hol_text.h). */
#include "hol_text.h"

/* The output: pieces are written whole or not at all (a piece that does
 * not fit stops the writing; the count goes on). */
typedef struct hol__out {
    char *p;
    size_t cap;
    size_t n;       /* the whole result's length */
    size_t written; /* bytes in p (before the first piece that did not fit) */
} hol__out;

static void hol__put(hol__out *o, const char *s, size_t k)
{
    if (o->written == o->n && o->n + k < o->cap) {
        for (size_t i = 0; i < k; i++)
            o->p[o->n + i] = s[i];
        o->written += k;
    }
    o->n += k;
}

static size_t hol__end(hol__out *o)
{
    if (o->cap > 0)
        o->p[o->written] = 0;
    return o->n;
}

/* The valid UTF-8 sequence at s (n bytes left): its length and code point,
 * or 0 when it is not valid (overlong, surrogate, beyond U+10FFFF, short). */
static size_t hol__utf8(const unsigned char *s, size_t n, unsigned long *cp)
{
    unsigned long v, min;
    size_t k;
    if (s[0] < 0x80) {
        *cp = s[0];
        return 1;
    }
    if (s[0] >= 0xc2 && s[0] <= 0xdf)
        k = 2, v = s[0] & 0x1fu, min = 0x80;
    else if (s[0] >= 0xe0 && s[0] <= 0xef)
        k = 3, v = s[0] & 0x0fu, min = 0x800;
    else if (s[0] >= 0xf0 && s[0] <= 0xf4)
        k = 4, v = s[0] & 0x07u, min = 0x10000;
    else
        return 0;
    if (n < k)
        return 0;
    for (size_t i = 1; i < k; i++) {
        if ((s[i] & 0xc0) != 0x80)
            return 0;
        v = v << 6 | (s[i] & 0x3fu);
    }
    if (v < min || v > 0x10ffff || (v >= 0xd800 && v <= 0xdfff))
        return 0;
    *cp = v;
    return k;
}

/* A code point a terminal may act on (see the contract). */
static int hol__acts(unsigned long cp)
{
    return cp < 0x20 || cp == 0x7f || (cp >= 0x80 && cp <= 0x9f) || cp == 0x2028 ||
           cp == 0x2029 || (cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069);
}

size_t hol_text_escape(const char *s, size_t len, char *out, size_t cap)
{
    static const char hex[] = "0123456789abcdef";
    hol__out o = {out, cap, 0, 0};
    const unsigned char *u = (const unsigned char *)s;
    size_t i = 0;
    while (i < len) {
        unsigned long cp = 0;
        size_t k = hol__utf8(u + i, len - i, &cp);
        if (k && !hol__acts(cp)) {
            hol__put(&o, cp == '\\' ? "\\\\" : s + i, cp == '\\' ? 2 : k);
            i += k;
            continue;
        }
        /* escaped byte by byte: the whole sequence, or the one bad byte */
        for (size_t j = 0; j < (k ? k : 1); j++) {
            char e[4] = {'\\', 'x', hex[u[i + j] >> 4], hex[u[i + j] & 15]};
            hol__put(&o, e, 4);
        }
        i += k ? k : 1;
    }
    return hol__end(&o);
}

size_t hol_text_csv(const char *s, size_t len, char *out, size_t cap)
{
    hol__out o = {out, cap, 0, 0};
    int quote = len > 0 && (s[0] == ' ' || s[len - 1] == ' ');
    for (size_t i = 0; i < len && !quote; i++)
        quote = s[i] == ',' || s[i] == '"' || s[i] == '\r' || s[i] == '\n';
    if (quote)
        hol__put(&o, "\"", 1);
    for (size_t i = 0; i < len; i++)
        hol__put(&o, s[i] == '"' ? "\"\"" : s + i, s[i] == '"' ? 2 : 1);
    if (quote)
        hol__put(&o, "\"", 1);
    return hol__end(&o);
}
