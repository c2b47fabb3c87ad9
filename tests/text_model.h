/* text_model.h - independent models of core/hol_text.h for the tests and
 * the fuzz harness: reading an escaped text back, reading one RFC 4180 CSV
 * field back, and what a terminal must never receive.
 */
#ifndef HOL_TEXT_MODEL_H
#define HOL_TEXT_MODEL_H

#include <stddef.h>
#include <stdint.h>

static int model_hex(int c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

/* Unescape e (\\ and \xHH): the byte count, or -1 when e is not a
 * complete escaped text. */
static long model_unescape(const char *e, size_t n, char *out)
{
    size_t o = 0;
    for (size_t i = 0; i < n; i++) {
        if (e[i] != '\\') {
            out[o++] = e[i];
            continue;
        }
        if (i + 1 < n && e[i + 1] == '\\') {
            out[o++] = '\\';
            i++;
            continue;
        }
        if (i + 3 >= n || e[i + 1] != 'x' || model_hex(e[i + 2]) < 0 || model_hex(e[i + 3]) < 0)
            return -1;
        out[o++] = (char)(model_hex(e[i + 2]) << 4 | model_hex(e[i + 3]));
        i += 3;
    }
    return (long)o;
}

/* 1 when e is safe for a terminal: valid UTF-8 (decoded the long way, bit
 * by bit) with no C0/C1 control, DEL, line separator or bidi control. */
static int model_terminal_safe(const char *e, size_t n)
{
    const uint8_t *u = (const uint8_t *)e;
    for (size_t i = 0; i < n;) {
        int k = u[i] < 0x80 ? 1 : (u[i] >> 5) == 6 ? 2 : (u[i] >> 4) == 14 ? 3 : (u[i] >> 3) == 30 ? 4 : 0;
        if (!k || i + (size_t)k > n)
            return 0;
        uint32_t cp = k == 1 ? u[i] : (uint32_t)(u[i] & (0x7f >> k));
        for (int j = 1; j < k; j++) {
            if ((u[i + j] >> 6) != 2)
                return 0;
            cp = cp << 6 | (u[i + j] & 0x3f);
        }
        static const uint32_t least[5] = {0, 0, 0x80, 0x800, 0x10000};
        if (cp < least[k] || cp > 0x10ffff || (cp >= 0xd800 && cp < 0xe000))
            return 0;
        if (cp < 0x20 || (cp >= 0x7f && cp < 0xa0) || cp == 0x2028 || cp == 0x2029 ||
            (cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069))
            return 0;
        i += (size_t)k;
    }
    return 1;
}

/* Read one RFC 4180 field that spans all of f: the byte count, or -1 when
 * f is not exactly one field (a stray quote, a bare comma or line break). */
static long model_csv_read(const char *f, size_t n, char *out)
{
    size_t o = 0;
    if (n == 0 || f[0] != '"') {
        for (size_t i = 0; i < n; i++) {
            if (f[i] == '"' || f[i] == ',' || f[i] == '\r' || f[i] == '\n')
                return -1;
            out[o++] = f[i];
        }
        return (long)o;
    }
    for (size_t i = 1; i < n; i++) {
        if (f[i] != '"') {
            out[o++] = f[i];
            continue;
        }
        if (i == n - 1)
            return (long)o;
        if (f[i + 1] != '"')
            return -1;
        out[o++] = '"';
        i++;
    }
    return -1; /* no closing quote */
}

#endif
