/* test_font.c - the text face (core/hol_face.h) and its CPU rasteriser
 * (render/hol_face_draw.h):
 * - UTF-8: every code point U+0000..U+00FF round-trips, the glyph set maps
 *   to its own glyph and everything else to the box; malformed input
 *   (stray continuation, overlong, surrogate, beyond U+10FFFF, truncated)
 *   gives one malformed byte at a time and is counted as a box;
 * - every glyph of the set draws ink (but the two blanks) and none draws
 *   the missing box; lower case differs from upper case, an accented
 *   letter from its base letter;
 * - widths are proportional, advances positive, kerning sorted and applied,
 *   the drawn width equals hol_face_width;
 * - wrapping by measured width: no line wider than the width, no word
 *   split unless it alone is wider, blanks at breaks dropped, '\n'.
 * - the packed texels (the web build's, hol_face_unpack) decode to the
 *   atlas byte for byte; a cut or damaged stream stays in the atlas.
 * HOL_FONT_SHEET=file.png also writes a sample sheet of every glyph at
 * three sizes, to look at.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_face.h"
#include "../platform/file/hol_file.h"
#include "../render/hol_face_draw.h"
#include "../render/hol_png.h"

#define CELL 40

/* Writes code point c as UTF-8 into out (at least 5 bytes); returns its length. */
static size_t utf8(uint32_t c, char *out)
{
    size_t n;
    if (c < 0x80) {
        out[0] = (char)c;
        n = 1;
    } else if (c < 0x800) {
        out[0] = (char)(0xC0 | (c >> 6));
        out[1] = (char)(0x80 | (c & 0x3F));
        n = 2;
    } else if (c < 0x10000) {
        out[0] = (char)(0xE0 | (c >> 12));
        out[1] = (char)(0x80 | ((c >> 6) & 0x3F));
        out[2] = (char)(0x80 | (c & 0x3F));
        n = 3;
    } else {
        out[0] = (char)(0xF0 | (c >> 18));
        out[1] = (char)(0x80 | ((c >> 12) & 0x3F));
        out[2] = (char)(0x80 | ((c >> 6) & 0x3F));
        out[3] = (char)(0x80 | (c & 0x3F));
        n = 4;
    }
    out[n] = 0;
    return n;
}

static int in_set(uint32_t c)
{
    return (c >= 0x20 && c <= 0x7E) || (c >= 0xA0 && c <= 0xFF);
}

/* Draws code point c (or the text s when c is 0) black on white into a
 * CELL x CELL grey picture; returns the number of inked pixels. */
static int draw_cell(uint32_t c, uint8_t grey[CELL * CELL])
{
    static uint8_t rgba[CELL * CELL * 4];
    memset(rgba, 255, sizeof rgba);
    char s[8];
    size_t n = utf8(c, s);
    hol_face_canvas cv = {rgba, CELL, CELL, 0};
    hol_face_draw_desc d = {.x = 6, .y = 30, .size = 28};
    hol_face_draw(&cv, &d, s, n, NULL);
    int ink = 0;
    for (int i = 0; i < CELL * CELL; i++) {
        grey[i] = rgba[i * 4];
        ink += grey[i] < 128;
    }
    return ink;
}

/* Pixels that differ by more than half the range. */
static int differ(const uint8_t *a, const uint8_t *b)
{
    int n = 0;
    for (int i = 0; i < CELL * CELL; i++)
        n += abs((int)a[i] - (int)b[i]) > 128;
    return n;
}

static void test_decode_latin1(void **state)
{
    (void)state;
    for (uint32_t c = 0; c <= 0xFF; c++) {
        char s[8];
        size_t n = utf8(c, s), pos = 0;
        if (c == 0)
            n = 1;
        assert_int_equal(hol_face_decode(s, n, &pos), c);
        assert_int_equal(pos, n);
        int g = hol_face_index(c);
        if (in_set(c)) {
            assert_true(g > 0 && g < HOL_FACE_NGLYPH);
            assert_int_equal(hol_face_glyph_at(g).code, c);
        } else {
            assert_int_equal(g, 0);
        }
    }
    assert_int_equal(hol_face_index(0x20AC), 0); /* the euro sign is not Latin-1 */
    assert_int_equal(hol_face_glyph_at(-1).code, 0);
    assert_int_equal(hol_face_glyph_at(HOL_FACE_NGLYPH).code, 0);
}

static void test_decode_malformed(void **state)
{
    (void)state;
    static const struct {
        const char *s;
        size_t len;
        uint32_t first;
        size_t used;
    } cases[] = {
        {"\x80" "A", 2, HOL_FACE_MALFORMED, 1},       /* stray continuation */
        {"\xC0\x80", 2, HOL_FACE_MALFORMED, 1},       /* overlong NUL */
        {"\xC1\xBF", 2, HOL_FACE_MALFORMED, 1},       /* overlong DEL */
        {"\xE0\x80\x80", 3, HOL_FACE_MALFORMED, 1},   /* overlong 3 bytes */
        {"\xF0\x80\x80\x80", 4, HOL_FACE_MALFORMED, 1},
        {"\xED\xA0\x80", 3, HOL_FACE_MALFORMED, 1},   /* a surrogate */
        {"\xF4\x90\x80\x80", 4, HOL_FACE_MALFORMED, 1}, /* beyond U+10FFFF */
        {"\xF5\x80\x80\x80", 4, HOL_FACE_MALFORMED, 1},
        {"\xFF", 1, HOL_FACE_MALFORMED, 1},
        {"\xC3", 1, HOL_FACE_MALFORMED, 1},           /* truncated at the end */
        {"\xC3" "A", 2, HOL_FACE_MALFORMED, 1},       /* truncated by a letter */
        {"\xE2\x82", 2, HOL_FACE_MALFORMED, 1},
        {"\xE2\x82\xAC", 3, 0x20AC, 3},               /* the euro sign */
        {"\xF0\x9F\x98\x80", 4, 0x1F600, 4},
        {"\xEF\xBF\xBF", 3, 0xFFFF, 3},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t pos = 0;
        assert_int_equal(hol_face_decode(cases[i].s, cases[i].len, &pos), cases[i].first);
        assert_int_equal(pos, cases[i].used);
        assert_int_equal(hol_face_index(cases[i].first), 0);
    }
    /* every malformed byte and every code point outside the set is a box */
    int missing = 0;
    const char *t = "a\x80" "b\xC3\xA4\xE2\x82\xAC\xC3";
    long units = hol_face_units(t, strlen(t), &missing);
    assert_int_equal(missing, 3);
    long want = hol_face_units("a", 1, NULL) + hol_face_units("b", 1, NULL) +
                hol_face_units("\xC3\xA4", 2, NULL) + 3 * (long)hol_face_glyph_at(0).advance;
    assert_true(labs(units - want) < 200); /* only kerning between them differs */
}

static void test_every_glyph_inks_and_is_not_the_box(void **state)
{
    (void)state;
    uint8_t box[CELL * CELL], cell[CELL * CELL];
    assert_true(draw_cell(0x01, box) > 40); /* a control draws the box */
    for (uint32_t c = 0x20; c <= 0xFF; c++) {
        if (!in_set(c))
            continue;
        int ink = draw_cell(c, cell);
        if (c == 0x20 || c == 0xA0) { /* space, no-break space */
            assert_int_equal(ink, 0);
            continue;
        }
        if (ink == 0)
            fail_msg("U+%04X draws no ink", (unsigned)c);
        if (differ(cell, box) < 20)
            fail_msg("U+%04X draws the missing box", (unsigned)c);
    }
}

static void test_packed_texels_are_the_atlas(void **state)
{
    (void)state;
    int w, h;
    hol_face_atlas(NULL, &w, &h);
    size_t n = (size_t)w * (size_t)h;
    uint8_t *want = malloc(n), *got = malloc(n + 1);
    assert_non_null(want);
    assert_non_null(got);
    hol_face_atlas(want, &w, &h);
    hol_face_packed p;
    hol_face_get_packed(&p);
    assert_true(p.n > 0 && p.n < n / 4);
    memset(got, 1, n); /* HOL_FACE_CLEAR: the texels outside every glyph */
    assert_int_equal(hol_face_unpack(&p, got), 0);
    assert_memory_equal(got, want, n);
    /* a cut stream and damaged bytes: never a write outside the atlas */
    uint8_t *bad = malloc(p.n);
    assert_non_null(bad);
    for (int k = 0; k < 64; k++) {
        memcpy(bad, p.bytes, p.n);
        hol_face_packed q = p;
        q.bytes = bad;
        q.n = (size_t)k * p.n / 64;
        bad[(size_t)k * 97 % p.n] ^= (uint8_t)(1 + k);
        got[n] = 0xA5;
        (void)hol_face_unpack(&q, got);
        assert_int_equal(got[n], 0xA5);
    }
    free(bad);
    free(want);
    free(got);
}

static void test_cases_and_accents_differ(void **state)
{
    (void)state;
    uint8_t a[CELL * CELL], b[CELL * CELL];
    for (uint32_t c = 'A'; c <= 'Z'; c++) {
        draw_cell(c, a);
        draw_cell(c + 32, b);
        if (differ(a, b) < 6)
            fail_msg("%c looks like %c", (char)c, (char)(c + 32));
    }
    static const uint32_t pairs[][2] = {
        {0xC4, 'A'}, {0xD6, 'O'}, {0xDC, 'U'}, {0xE4, 'a'}, {0xF6, 'o'}, {0xFC, 'u'}, {0xDF, 'B'},
        {0xE9, 'e'}, {0xE8, 'e'}, {0xEA, 'e'}, {0xEB, 'e'}, {0xE0, 'a'}, {0xE2, 'a'}, {0xE7, 'c'},
        {0xEE, 'i'}, {0xEF, 'i'}, {0xF4, 'o'}, {0xFB, 'u'}, {0xF9, 'u'}, {0xFF, 'y'}, {0xF1, 'n'},
        {0xE9, 0xE8}, {0xC4, 0xC5},
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
        draw_cell(pairs[i][0], a);
        draw_cell(pairs[i][1], b);
        if (differ(a, b) < 6)
            fail_msg("U+%04X looks like U+%04X", (unsigned)pairs[i][0], (unsigned)pairs[i][1]);
    }
}

static void test_widths_and_kerning(void **state)
{
    (void)state;
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    assert_true(m.units_per_em > 0 && m.ascent > m.cap_height && m.cap_height > m.x_height);
    assert_true(m.x_height > 0 && m.descent < 0 && m.line_gap >= 0);
    assert_true(hol_face_width("i", 10) < hol_face_width("W", 10) * 0.5f);
    assert_true(hol_face_width("l", 10) < hol_face_width("m", 10));
    float w = hol_face_width("Hello", 20);
    assert_true(w > 0 && hol_face_width("Hello", 40) == 2 * w);
    for (int g = 0; g < HOL_FACE_NGLYPH; g++)
        assert_true(hol_face_glyph_at(g).advance > 0);
    /* kerning: "AV" and "To" draw tighter than their letters apart */
    assert_true(hol_face_kerning(hol_face_index('A'), hol_face_index('V')) < 0);
    assert_true(hol_face_width("AV", 20) < hol_face_width("A", 20) + hol_face_width("V", 20));
    assert_int_equal(hol_face_kerning(0, hol_face_index('V')), 0);
    assert_int_equal(hol_face_kerning(hol_face_index('A'), -1), 0);
    int pairs = 0, prev = -1;
    for (int a = 1; a < HOL_FACE_NGLYPH; a++)
        for (int b = 1; b < HOL_FACE_NGLYPH; b++) {
            int k = hol_face_kerning(a, b);
            if (k == 0)
                continue;
            pairs++;
            assert_true(a * 256 + b > prev);
            prev = a * 256 + b;
            /* a kerned pair still advances */
            assert_true(hol_face_glyph_at(a).advance + k > 0);
        }
    assert_true(pairs > 100);
    /* the rasteriser's pen moves as hol_face_width measures */
    static uint8_t rgba[64 * 16 * 4];
    hol_face_canvas cv = {rgba, 64, 16, 0};
    const char *s = "Wave, AVAT\xC3\x96l!";
    hol_face_draw_desc d = {.x = 0, .y = 12, .size = 13};
    assert_true(hol_face_draw(&cv, &d, s, strlen(s), NULL) == hol_face_width(s, 13));
    float em_cap = hol_face_em_per_cap();
    assert_true(em_cap > 1.3f && em_cap < 1.45f);
}

static void expect_lines(const char *text, float width, const char *const *want, int n)
{
    hol_face_line lines[16];
    int got = hol_face_wrap(text, 10, width, lines, 16);
    assert_int_equal(got, n);
    assert_int_equal(hol_face_wrap(text, 10, width, NULL, 0), n);
    for (int i = 0; i < n; i++) {
        char buf[128];
        memcpy(buf, text + lines[i].start, lines[i].len);
        buf[lines[i].len] = 0;
        assert_string_equal(buf, want[i]);
    }
}

static void test_wrap(void **state)
{
    (void)state;
    float w = hol_face_width("the quick", 10), w2 = hol_face_width("brown fox", 10);
    w = w > w2 ? w : w2;
    expect_lines("the quick brown fox", w, (const char *const[]){"the quick", "brown fox"}, 2);
    float wq = hol_face_width("quick", 10), wb = hol_face_width("brown", 10);
    expect_lines("the quick brown fox", wq > wb ? wq : wb, (const char *const[]){"the", "quick", "brown", "fox"}, 4);
    expect_lines("  the   quick  ", 100, (const char *const[]){"the   quick"}, 1);
    expect_lines("the\n\nquick", 100, (const char *const[]){"the", "", "quick"}, 3);
    expect_lines("", 100, NULL, 0);
    expect_lines("   ", 100, NULL, 0);
    /* a word wider than the width alone is split, at least one code point a line */
    float wm = hol_face_width("mm", 10);
    expect_lines("mmmmm a", wm, (const char *const[]){"mm", "mm", "m a"}, 3);
    expect_lines("\xC3\x9C\xC3\x9C", 0, (const char *const[]){"\xC3\x9C", "\xC3\x9C"}, 2);
    /* a long German sentence: every line fits, words are whole, nothing lost */
    const char *t = "Zeigen Sie bitte auf den Baum, den Sie zuletzt gesehen haben: "
                    "die \xC3\x9C" "bung ist zu Ende, gro\xC3\x9F" "artig! Dank f\xC3\xBC" "r Ihre Geduld.";
    hol_face_line lines[32];
    float width = hol_face_width("Zeigen Sie bitte auf", 10);
    int n = hol_face_wrap(t, 10, width, lines, 32);
    assert_true(n >= 5 && n <= 32);
    size_t words = 0;
    for (int i = 0; i < n; i++) {
        assert_true(hol_face_units(t + lines[i].start, lines[i].len, NULL) * 10.0 / 2048.0 <= width + 1e-4);
        for (size_t j = 0; j < lines[i].len; j++)
            words += t[lines[i].start + j] != ' ' && (j == 0 || t[lines[i].start + j - 1] == ' ');
        size_t end = lines[i].start + lines[i].len;
        assert_true(t[end] == 0 || t[end] == ' '); /* ends at a word's end */
        assert_true(t[lines[i].start] != ' ');
    }
    assert_int_equal(words, 21);
    /* max caps what is written, not the count */
    assert_int_equal(hol_face_wrap(t, 10, width, lines, 2), n);
}

/* The lines of hol_face_wrap_pairs (pairs 1) or hol_face_wrap (0) as one
 * string, " / " between lines. */
static const char *wrapped(const char *text, float width, int pairs)
{
    static char out[256];
    hol_face_line lines[16];
    int n = (pairs ? hol_face_wrap_pairs : hol_face_wrap)(text, 10, width, lines, 16);
    size_t k = 0;
    for (int i = 0; i < n && i < 16; i++) {
        k += (size_t)snprintf(out + k, sizeof out - k, "%s%.*s", i ? " / " : "",
                              (int)lines[i].len, text + lines[i].start);
    }
    out[k] = 0;
    return out;
}

/* A prompt's "KEY: action" pairs stay whole (issue 36: the panel showed
 * "Y:" at a line's end and "menu" on the next, and "3 x 3" / "m: mind the
 * edges"), where plain wrapping split them. */
static void test_wrap_pairs(void **state)
{
    (void)state;
    const char *p = "A: confirm, Y / MENU: menu";
    float w = hol_face_width("A: confirm, Y / MENU: men", 10);
    assert_string_equal(wrapped(p, w, 0), "A: confirm, Y / MENU: / menu");
    assert_string_equal(wrapped(p, w, 1), "A: confirm, / Y / MENU: menu");
    /* inside an action before inside a key or between key and action */
    const char *q = "B: back to the menu";
    w = hol_face_width("B: back to the", 10);
    assert_string_equal(wrapped(q, w, 1), "B: back to the / menu");
    w = hol_face_width("B: bac", 10);
    assert_string_equal(wrapped(q, w, 1), "B: / back / to the / menu"); /* no other choice */
    /* a number with its unit, the key with its action */
    const char *e = "Play area under 3 x 3 m: mind the edges";
    w = hol_face_width("Play area under 3 x 3 m: mi", 10);
    assert_string_equal(wrapped(e, w, 0), "Play area under 3 x 3 m: / mind the edges");
    w = hol_face_width("Play area under 3 x 3 m", 10);
    assert_string_equal(wrapped(e, w, 0), "Play area under 3 x 3 / m: mind the edges");
    assert_string_equal(wrapped(e, w, 1), "Play area under / 3 x 3 m: mind the / edges");
    /* a text without pairs wraps as plain text would where it has no comma */
    w = hol_face_width("the quick brown", 10) - 1;
    assert_string_equal(wrapped("the quick brown fox", w, 1), "the quick / brown fox");
}

/* The sample sheet: every glyph at three sizes, and a sentence. */
static void write_sheet(const char *path)
{
    enum { W = 720, H = 370 };
    uint8_t *rgba = malloc((size_t)W * H * 4);
    assert_non_null(rgba);
    memset(rgba, 255, (size_t)W * H * 4);
    hol_face_canvas cv = {rgba, W, H, 0};
    char ascii[200], latin[400];
    size_t na = 0, nl = 0;
    for (uint32_t c = 0x21; c <= 0x7E; c++)
        na += utf8(c, ascii + na);
    for (uint32_t c = 0xA1; c <= 0xFF; c++)
        nl += utf8(c, latin + nl);
    ascii[na] = latin[nl] = 0;
    const char *sample = "Pointing? 50% <ready> \"quote\" Gr\xC3\xB6\xC3\x9F" "e \xC3\x9C" "bung caf\xC3\xA9 \xC2\xAB" "12\xC2\xB0\xC2\xBB";
    static const float sizes[] = {11, 15, 24};
    float y = 4;
    for (int s = 0; s < 3; s++) {
        float lh = sizes[s] * 1.2f;
        const char *texts[] = {ascii, latin, sample};
        for (int t = 0; t < 3; t++) {
            hol_face_line lines[8];
            int n = hol_face_wrap(texts[t], sizes[s], W - 16, lines, 8);
            for (int i = 0; i < n && i < 8; i++) {
                y += lh;
                hol_face_draw_desc d = {.x = 8, .y = y, .size = sizes[s], .ink = 0x202020FFu};
                hol_face_draw(&cv, &d, texts[t] + lines[i].start, lines[i].len, NULL);
            }
        }
        y += lh * 0.5f;
    }
    hol_face_draw_desc d = {.x = 8, .y = H - 10, .size = 14, .ink = 0x202020FFu};
    const char *box = "missing: \x01 \xE2\x82\xAC \x80";
    hol_face_draw(&cv, &d, box, strlen(box), NULL);
    /* grey only, so level 8 writes a palette: a small file to keep */
    uint8_t *png = NULL;
    size_t size = 0;
    assert_int_equal(hol_png_encode_level(rgba, W, H, 0, 8, &png, &size), HOL_OK);
    assert_int_equal(hol_file_write_atomic(path, png, size), HOL_OK);
    free(png);
    free(rgba);
}

static void test_sheet(void **state)
{
    (void)state;
    const char *path = getenv("HOL_FONT_SHEET");
    if (path && *path)
        write_sheet(path);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decode_latin1),
        cmocka_unit_test(test_decode_malformed),
        cmocka_unit_test(test_every_glyph_inks_and_is_not_the_box),
        cmocka_unit_test(test_packed_texels_are_the_atlas),
        cmocka_unit_test(test_cases_and_accents_differ),
        cmocka_unit_test(test_widths_and_kerning),
        cmocka_unit_test(test_wrap),
        cmocka_unit_test(test_wrap_pairs),
        cmocka_unit_test(test_sheet),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
