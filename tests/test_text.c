/* test_text.c - core/hol_text.h: terminal escaping and CSV fields, by hand
 * (the names of issue 19: a terminal title sequence, a comma, a quote) and
 * on random bytes against the independent models of text_model.h.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_text.h"
#include "text_model.h"

static void expect_escape(const char *in, size_t n, const char *want)
{
    char out[256];
    size_t need = hol_text_escape(in, n, out, sizeof out);
    assert_string_equal(out, want);
    assert_int_equal(need, strlen(want));
}

static void test_escape(void **state)
{
    (void)state;
    expect_escape("plain name", 10, "plain name");
    /* the title sequence of issue 19 */
    expect_escape("\033]0;pwned\007", 10, "\\x1b]0;pwned\\x07");
    expect_escape("a\nb\tc\rd\x7f", 8, "a\\x0ab\\x09c\\x0dd\\x7f");
    expect_escape("nul\0byte", 8, "nul\\x00byte");
    expect_escape("back\\slash", 10, "back\\\\slash");
    /* UTF-8 passes; C1 (U+009B, a CSI), bidi and line separators do not */
    expect_escape("\xc3\xa9t\xc3\xa9", 5, "\xc3\xa9t\xc3\xa9");
    expect_escape("\xf0\x9f\x8c\xb2", 4, "\xf0\x9f\x8c\xb2");
    expect_escape("\xc2\x9b" "31m", 5, "\\xc2\\x9b31m");
    expect_escape("\xe2\x80\xae" "evil", 7, "\\xe2\\x80\\xaeevil");
    expect_escape("\xe2\x80\xa8", 3, "\\xe2\\x80\\xa8");
    expect_escape("\xe2\x81\xa6", 3, "\\xe2\\x81\\xa6");
    /* not UTF-8: a lone byte, overlong, surrogate, beyond U+10FFFF, cut */
    expect_escape("\x9b", 1, "\\x9b");
    expect_escape("\xc0\xaf", 2, "\\xc0\\xaf");
    expect_escape("\xed\xa0\x80", 3, "\\xed\\xa0\\x80");
    expect_escape("\xf4\x90\x80\x80", 4, "\\xf4\\x90\\x80\\x80");
    expect_escape("\xe2\x80", 2, "\\xe2\\x80");
    expect_escape("\xe2\x80" "a", 3, "\\xe2\\x80a");
}

static void test_cut(void **state)
{
    (void)state;
    char out[8];
    /* never inside an escape or a character; the need is the whole */
    assert_int_equal(hol_text_escape("ab\033cd", 5, out, 5), 8);
    assert_string_equal(out, "ab");
    assert_int_equal(hol_text_escape("a\xc3\xa9", 3, out, 3), 3);
    assert_string_equal(out, "a");
    assert_int_equal(hol_text_escape("abc", 3, NULL, 0), 3);
    assert_int_equal(hol_text_csv("a\"b", 3, out, 4), 6);
    assert_string_equal(out, "\"a");
}

static void expect_csv(const char *in, const char *want)
{
    char out[256];
    size_t need = hol_text_csv(in, strlen(in), out, sizeof out);
    assert_string_equal(out, want);
    assert_int_equal(need, strlen(want));
}

static void test_csv(void **state)
{
    (void)state;
    expect_csv("flag-1", "flag-1");
    expect_csv("", "");
    expect_csv("a,b", "\"a,b\"");
    expect_csv("say \"hi\"", "\"say \"\"hi\"\"\"");
    expect_csv("two\nlines", "\"two\nlines\"");
    expect_csv("cr\r", "\"cr\r\"");
    expect_csv(" lead", "\" lead\"");
    expect_csv("trail ", "\"trail \"");
    expect_csv("in side", "in side");
    /* escaped first, then quoted: what a CSV of outside names holds */
    char esc[64], field[128];
    hol_text_escape("\033]0;x,\"y\"\007", 10, esc, sizeof esc);
    hol_text_csv(esc, strlen(esc), field, sizeof field);
    assert_string_equal(field, "\"\\x1b]0;x,\"\"y\"\"\\x07\"");
}

static uint64_t rng(uint64_t *s)
{
    *s = *s * 6364136223846793005u + 1442695040888963407u;
    return *s >> 33;
}

/* Random bytes (biased towards the interesting ones) round-trip through
 * both, and the escaped text is safe for a terminal. */
static void test_random_models(void **state)
{
    (void)state;
    static const uint8_t pick[] = {0, '\033', '\n', '\r', '"', ',', ' ', '\\', 'x', 0x7f,
                                   0x80, 0x9b, 0xc2, 0xc3, 0xe2, 0x80, 0xae, 0xed, 0xf0,
                                   0xf4, 0x90, 0xbf, 0xff, 'a'};
    uint64_t s = 19;
    char in[64], out[300], back[300];
    for (int k = 0; k < 200000; k++) {
        size_t n = rng(&s) % sizeof in;
        for (size_t i = 0; i < n; i++)
            in[i] = (char)(rng(&s) % 3 ? pick[rng(&s) % sizeof pick] : rng(&s) & 0xff);
        size_t need = hol_text_escape(in, n, out, sizeof out);
        assert_true(need < sizeof out);
        assert_true(model_terminal_safe(out, need));
        assert_int_equal(model_unescape(out, need, back), (long)n);
        assert_memory_equal(back, in, n);
        if (memchr(in, 0, n))
            continue;
        need = hol_text_csv(in, n, out, sizeof out);
        assert_int_equal(model_csv_read(out, need, back), (long)n);
        assert_memory_equal(back, in, n);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_escape),
        cmocka_unit_test(test_cut),
        cmocka_unit_test(test_csv),
        cmocka_unit_test(test_random_models),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
