/* test_report_escape.c - the report's one CSV field writer and one HTML
 * text writer (platform/cli/report/report_escape.h), against their rules written
 * out by hand:
 * - CSV: a plain field as it is; a comma, a double quote, CR, LF, a leading
 *   or trailing space quoted, the quote doubled; ',' after, '\n' when last;
 * - HTML: & < > " ' as entities, every other byte as it is;
 * - both clean first: a control byte, DEL, a C1 control, a bidi control and
 *   bad UTF-8 as \xHH per byte, a backslash kept, valid UTF-8 kept;
 * - a field of the logs (HOL_REPORT_TEXT - 1 bytes, all control bytes) is
 *   not cut; a longer text is cut at REPORT_ESCAPE_MAX bytes cleaned,
 *   never inside an escape;
 * - spreadsheet safety (issue 39 finding 13): a text that starts with
 *   = + - @ (a tab or CR are \x09, \x0d once cleaned) and is no number is
 *   written quoted with a ' before it; a number (-12.5) as it is; the page
 *   never gets the quote.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../platform/cli/report/report_escape.h"

/* What report_csv (last 0 or 1) or report_html (last -1) writes for s. */
static char *written(const char *s, int last)
{
    char *buf = NULL;
    size_t n = 0;
    FILE *f = open_memstream(&buf, &n);
    assert_non_null(f);
    if (last < 0)
        report_html(f, s);
    else
        report_csv(f, s, last);
    assert_int_equal(fclose(f), 0);
    return buf;
}

static char *csv_of(const char *s, int last)
{
    return written(s, last);
}

static char *html_of(const char *s)
{
    return written(s, -1);
}

static void csv_is(const char *s, int last, const char *want)
{
    char *got = csv_of(s, last);
    assert_string_equal(got, want);
    free(got);
}

static void html_is(const char *s, const char *want)
{
    char *got = html_of(s);
    assert_string_equal(got, want);
    free(got);
}

static void test_csv_quoting(void **state)
{
    (void)state;
    csv_is("P01", 0, "P01,");
    csv_is("P01", 1, "P01\n");
    csv_is("", 0, ",");
    csv_is("a,b", 0, "\"a,b\",");
    csv_is("say \"hi\"", 1, "\"say \"\"hi\"\"\"\n");
    csv_is(" lead", 0, "\" lead\",");
    csv_is("trail ", 0, "\"trail \",");
    csv_is("in side", 0, "in side,");
    csv_is("<&>'", 0, "<&>',"); /* no HTML rule in a CSV */
}

static void test_html_entities(void **state)
{
    (void)state;
    html_is("plain", "plain");
    html_is("", "");
    html_is("a&b<c>d\"e'f", "a&amp;b&lt;c&gt;d&quot;e&#39;f");
    html_is("&amp;", "&amp;amp;"); /* text, not markup: escaped again */
    html_is("a,b \"", "a,b &quot;");
}

static void test_both_clean_first(void **state)
{
    (void)state;
    /* a line break is cleaned (\x0a), so the CSV field needs no quotes */
    csv_is("a\nb", 0, "a\\x0ab,");
    csv_is("a\rb", 0, "a\\x0db,");
    html_is("a\nb", "a\\x0ab");
    csv_is("\x1b[31mred", 1, "\\x1b[31mred\n");
    html_is("\x1b<", "\\x1b&lt;");
    csv_is("del\x7f", 0, "del\\x7f,");
    csv_is("c1\xc2\x9b", 0, "c1\\xc2\\x9b,");      /* U+009B, a CSI */
    html_is("bidi\xe2\x80\xae", "bidi\\xe2\\x80\\xae"); /* U+202E */
    csv_is("bad\xff", 0, "bad\\xff,");
    html_is("cut\xc3", "cut\\xc3");
    csv_is("a\\b", 0, "a\\b,"); /* a backslash kept, not doubled */
    html_is("a\\\\b", "a\\\\b");
    csv_is("caf\xc3\xa9", 0, "caf\xc3\xa9,");
    html_is("\xe2\x86\x92 <", "\xe2\x86\x92 &lt;");
}

static void test_cut(void **state)
{
    (void)state;
    char field[HOL_REPORT_TEXT], want[4 * HOL_REPORT_TEXT + 2];
    memset(field, 1, sizeof field - 1);
    field[sizeof field - 1] = 0;
    want[0] = 0;
    for (size_t i = 0; i + 1 < sizeof field; i++)
        strcat(want, "\\x01");
    char *got = html_of(field);
    assert_string_equal(got, want); /* a whole field, not cut */
    free(got);
    strcat(want, ",");
    csv_is(field, 0, want);

    char *big = malloc(3 * REPORT_ESCAPE_MAX);
    memset(big, 'a', 3 * REPORT_ESCAPE_MAX - 1);
    big[3 * REPORT_ESCAPE_MAX - 1] = 0;
    got = csv_of(big, 1);
    assert_int_equal(strlen(got), REPORT_ESCAPE_MAX + 1);
    assert_int_equal(got[REPORT_ESCAPE_MAX], '\n');
    free(got);
    memset(big, 2, 3 * REPORT_ESCAPE_MAX - 1); /* cut at a whole escape */
    got = html_of(big);
    assert_int_equal(strlen(got), REPORT_ESCAPE_MAX / 4 * 4);
    assert_memory_equal(got + strlen(got) - 4, "\\x02", 4);
    free(got);
    free(big);
}

static void test_csv_formula(void **state)
{
    (void)state;
    csv_is("=1+1.lvl", 0, "\"'=1+1.lvl\",");
    csv_is("@SUM(A1).lvl", 0, "\"'@SUM(A1).lvl\",");
    csv_is("-h.lvl", 1, "\"'-h.lvl\"\n");
    csv_is("-A1", 0, "\"'-A1\",");
    csv_is("+x", 0, "\"'+x\",");
    csv_is("-", 0, "\"'-\",");
    csv_is("=cmd|' /C calc'!A0", 0, "\"'=cmd|' /C calc'!A0\",");
    csv_is("=a\"b,c", 0, "\"'=a\"\"b,c\",");
    csv_is("-12.5", 0, "-12.5,");
    csv_is("+3", 0, "+3,");
    csv_is("-.5", 0, "-.5,");
    csv_is("-1e-3", 0, "-1e-3,");
    csv_is("-1e", 0, "\"'-1e\",");
    csv_is("-inf", 0, "\"'-inf\",");
    csv_is("-0x10", 0, "\"'-0x10\",");
    csv_is("\t=x", 0, "\\x09=x,"); /* cleaned first: no longer a formula */
    csv_is("a=b", 0, "a=b,");
    csv_is("P-1", 0, "P-1,");
    html_is("=1+1", "=1+1");
    assert_true(report_csv_number("12") && report_csv_number("-12.5") && report_csv_number("5."));
    assert_false(report_csv_number("") || report_csv_number("-") || report_csv_number(".") ||
                 report_csv_number("1.2.3") || report_csv_number("1 "));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_csv_quoting),
        cmocka_unit_test(test_html_entities),
        cmocka_unit_test(test_both_clean_first),
        cmocka_unit_test(test_cut),
        cmocka_unit_test(test_csv_formula),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
