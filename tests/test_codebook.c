/* test_codebook.c - the codebook's table (platform/cli/codebook.h) against
 * the headers the writers write:
 * - each log file's columns in the table, joined with commas, are its
 *   writer's header byte for byte: the session's HOL_SESSION_*_COLUMNS
 *   (summary, steps, head, track, events, points, answers), the shell's
 *   HOL_SHELL_ENV_COLUMNS (environment.csv), PLAY_PROV_COLUMNS,
 *   PLAY_ORDER_COLUMNS, CODEBOOK_COLUMNS; the report's build.csv and
 *   codebook.csv likewise (its other files' headers are string literals in
 *   its writers: tests/cli_codebook.sh parses them from the files);
 * - every row has a type of the listed ones and a meaning, no column is
 *   listed twice for a file, and no field starts with = + - @ (a
 *   spreadsheet's formula);
 * - both codebooks fit CODEBOOK_TEXT_MAX, start with their header, and a
 *   report's names no "report:" file.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_session.h"
#include "../platform/cli/codebook.h"
#include "../platform/cli/codebook_table.h"
#include "../platform/cli/play_prov.h"
#include "../platform/cli/report/report.h"
#include "../platform/shell/hol_shell_env.h"

static void header_is(const char *file, const char *want)
{
    char got[4096];
    int n = codebook_header(file, got, sizeof got);
    if (n == 0 || strcmp(got, want)) {
        print_error("%s: codebook columns\n  %s\nwriter's header\n  %s\n", file, got, want);
        fail();
    }
}

static void headers_match(void **state)
{
    (void)state;
    header_is("summary.csv", HOL_SESSION_SUMMARY_COLUMNS);
    header_is("steps-NNN.csv", HOL_SESSION_STEP_COLUMNS);
    header_is("head-NNN.csv", HOL_SESSION_HEAD_COLUMNS);
    header_is("track-NNN.csv", HOL_SESSION_TRACK_COLUMNS);
    header_is("events.csv", HOL_SESSION_EVENT_COLUMNS);
    header_is("points.csv", HOL_SESSION_POINT_COLUMNS);
    header_is("answers.csv", HOL_SESSION_ANSWER_COLUMNS);
    header_is("environment.csv", HOL_SHELL_ENV_COLUMNS);
    header_is("provenance.csv", PLAY_PROV_COLUMNS);
    header_is("order.csv", PLAY_ORDER_COLUMNS);
    header_is("codebook.csv", CODEBOOK_COLUMNS);
    header_is("report:codebook.csv", CODEBOOK_COLUMNS);
    header_is("report:build.csv", REPORT_BUILD_COLUMNS);
    char none[8];
    assert_int_equal(codebook_header("nothing.csv", none, sizeof none), 0);
}

static int formula(const char *s) { return s[0] && strchr("=+-@", s[0]) != NULL; }

static void rows_complete(void **state)
{
    (void)state;
    static const char *const types[] = {"string", "integer", "number", "hex", "id", "timestamp"};
    size_t n = sizeof codebook_rows / sizeof codebook_rows[0];
    for (size_t i = 0; i < n; i++) {
        const codebook_row *r = &codebook_rows[i];
        int typed = 0;
        for (size_t k = 0; k < sizeof types / sizeof types[0]; k++)
            typed |= !strcmp(r->type, types[k]);
        if (!typed || !r->column[0] || formula(r->unit) || formula(r->allowed) ||
            formula(r->meaning)) {
            print_error("row %zu (%s %s) incomplete or a formula\n", i, r->file, r->column);
            fail();
        }
        for (size_t j = 0; j < i; j++)
            if (!strcmp(codebook_rows[j].file, r->file) &&
                !strcmp(codebook_rows[j].column, r->column)) {
                print_error("%s %s listed twice\n", r->file, r->column);
                fail();
            }
    }
}

static void texts(void **state)
{
    (void)state;
    static char text[CODEBOOK_TEXT_MAX];
    for (int which = CODEBOOK_LOGS; which <= CODEBOOK_REPORT; which++) {
        size_t n = codebook_csv(which, text, sizeof text);
        assert_true(n > 0 && n == strlen(text) && text[n - 1] == '\n');
        assert_memory_equal(text, CODEBOOK_COLUMNS "\n", sizeof CODEBOOK_COLUMNS);
        assert_null(strstr(text, "report:"));
        /* every meaning filled (a report's from the log column's) */
        assert_null(strstr(text, ",\n"));
    }
    assert_non_null(strstr(text, "\nattempts.csv,steps,"));
    assert_int_equal(codebook_csv(CODEBOOK_LOGS, text, 100), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(headers_match),
        cmocka_unit_test(rows_complete),
        cmocka_unit_test(texts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
