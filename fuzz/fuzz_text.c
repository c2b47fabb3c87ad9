/* fuzz_text.c - libFuzzer harness for core/hol_text.h: any bytes (names
 * from level files, recordings, device names, paths).
 *
 * Checks, against the independent models of tests/text_model.h: the
 * escaped text is safe for a terminal and reads back to the input; the CSV
 * field reads back (RFC 4180) to the input; both return the length they
 * need, and a result cut by a small buffer is a prefix of the whole one,
 * cut between pieces (it still reads back to a prefix of the input).
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_text.h"
#include "../tests/text_model.h"

#include "fuzz_check.h"

typedef size_t (*text_fn)(const char *s, size_t len, char *out, size_t cap);

static void check_one(text_fn fn, int csv, const char *s, size_t n, size_t small)
{
    size_t cap = 4 * n + 3;
    char *full = malloc(cap), *cut = malloc(small + 1), *back = malloc(cap);
    CHECK(full && cut && back);
    size_t need = fn(s, n, full, cap);
    CHECK(need < cap && strlen(full) == need);
    CHECK(fn(s, n, NULL, 0) == need);
    long b = csv ? model_csv_read(full, need, back) : model_unescape(full, need, back);
    CHECK(b == (long)n && memcmp(back, s, n) == 0);
    if (!csv)
        CHECK(model_terminal_safe(full, need));
    /* cut: a prefix, between pieces */
    CHECK(fn(s, n, cut, small + 1) == need);
    size_t got = strlen(cut);
    CHECK(got <= small && memcmp(cut, full, got) == 0);
    if (!csv) {
        b = model_unescape(cut, got, back);
        CHECK(b >= 0 && memcmp(back, s, (size_t)b) == 0);
    }
    free(full);
    free(cut);
    free(back);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0 || size > 4096)
        return 0;
    size_t small = data[0] % 32;
    const char *s = (const char *)data + 1;
    /* the input may hold NUL bytes: the output never does before its end */
    check_one(hol_text_escape, 0, s, size - 1, small);
    if (!memchr(s, 0, size - 1))
        check_one(hol_text_csv, 1, s, size - 1, small);
    return 0;
}
