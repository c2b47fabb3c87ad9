/* fuzz_cli.c - libFuzzer harness for the command line's own parsers
 * (platform/cli): option values and level files, as the commands take them.
 *
 * Input: the first byte picks the parser, the rest is its text.
 * - 0: an option value (NUL-terminated at the first NUL): cli_parse_u64
 *   (seeds; decimal or 0x hex), hol_level_parse_cell (--cell),
 *   cli_parse_count and cli_parse_doubles (lists
 *   of numbers). Checks: accepted text is all digits (or 0x and hex digits)
 *   and prints back to the same value; a list is accepted only with as many
 *   values as it has commas plus one, all finite; refused text leaves
 *   nothing half-parsed.
 * - 1: a level file (core/hol_level.h, hol_level_parse and hol_level_make).
 *   Checks: accepted, the level's fields are in range (mode, 1..5 keys,
 *   time limit, stages, at most 32 placements, the geometry: tiling 4..8,
 *   room 3..5 a side, a cell 0.5..1.5 m that prints back to itself, a
 *   `point` question only in a mode with its target), the
 *   kept text (LF line
 *   ends) parses to the same level and its hash is its text's; refused,
 *   the typed error names a line of the file (and a conflict another).
 * - 2: a message with any bytes (cli_error into a memory stream). Checks:
 *   one line, no control byte.
 */
#define _GNU_SOURCE
#include <ctype.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../platform/cli/cli.h"
#include "../core/hol_level.h"
#include "../core/hol_sha256.h"

#include "fuzz_check.h"

static void check_number(const char *s)
{
    uint64_t v = 0;
    if (cli_parse_u64(s, &v)) {
        char back[32];
        int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
        snprintf(back, sizeof back, hex ? "%" PRIx64 : "%" PRIu64, v);
        const char *digits = hex ? s + 2 : s;
        while (digits[0] == '0' && digits[1])
            digits++; /* leading zeros */
        CHECK(strcasecmp(back, digits) == 0);
    }
    /* --cell M (hol_level_parse_cell): accepted, a value in 0.5..1.5 of
     * digits and at most 3 decimals that prints back to the same value;
     * refused, the output untouched */
    double m = -7;
    if (hol_level_parse_cell(s, strlen(s), &m) == HOL_OK) {
        char back[16];
        double again_m = 0;
        CHECK(m >= 0.5 && m <= 1.5);
        hol_level_format_cell(m, back);
        CHECK(hol_level_parse_cell(back, strlen(back), &again_m) == HOL_OK && again_m == m);
        for (const char *p = s; *p; p++)
            CHECK(isdigit((unsigned char)*p) || *p == '.');
    } else {
        CHECK(m == -7);
    }
    size_t c = cli_parse_count(s);
    if (c) {
        for (const char *p = s; *p; p++)
            CHECK(isdigit((unsigned char)*p));
    }
    /* lists of numbers (--eye X,Y,Z, --orient, --tan): accepted for at
     * most one n, the number of commas plus one, every value finite; a
     * refusal leaves out untouched */
    int commas = 0;
    for (const char *p = s; *p; p++)
        commas += *p == ',';
    for (int n = 1; n <= 5; n++) {
        double out[5];
        for (int i = 0; i < 5; i++)
            out[i] = -1234.5;
        if (cli_parse_doubles(s, out, n)) {
            CHECK(commas == n - 1);
            for (int i = 0; i < n; i++)
                CHECK(isfinite(out[i]));
        } else {
            for (int i = 0; i < 5; i++)
                CHECK(out[i] == -1234.5);
        }
    }
}

static void check_level(const char *text, size_t len)
{
    hol_app_level L;
    hol_level_err err;
    memset(&err, 0, sizeof err);
    if (hol_level_parse(text, len, &L, &err) == HOL_OK) {
        CHECK(L.mode >= 0 && L.mode <= 3);
        CHECK(L.nkeys >= 0 && L.nkeys <= HOL_APP_MAX_KEYS);
        CHECK(L.time_limit_s >= 0 && L.time_limit_s <= 86400);
        CHECK(L.stages < (1u << HOL_APP_TUTORIAL_STAGES));
        CHECK(L.nplaces >= 0 && L.nplaces <= HOL_WORLD_MAX_PLACES);
        CHECK(L.nstart >= 0 && L.nstart <= (int)sizeof L.start);
        CHECK(L.tiling_q == 0 || (L.tiling_q >= 4 && L.tiling_q <= 8));
        CHECK((L.room_cols == 0) == (L.room_rows == 0));
        CHECK(L.room_cols == 0 || (L.room_cols >= 3 && L.room_cols <= 5 && L.room_rows >= 3 &&
                                   L.room_rows <= 5));
        CHECK(L.cell_m == 0 || (L.cell_m >= 0.5 && L.cell_m <= 1.5));
        /* a pointing question only where it has a target */
        CHECK(L.point >= 0 && L.point <= HOL_APP_POINT_OBJECTIVE);
        CHECK(!L.point || L.mode != HOL_APP_TUTORIAL);
        CHECK(L.point != HOL_APP_POINT_OBJECTIVE || L.mode == HOL_APP_FLAG ||
              L.mode == HOL_APP_KEYS);
        /* questionnaires: asks within the items, items well formed; screens
         * of printable text */
        CHECK(L.nasks >= 0 && L.nasks <= HOL_APP_MAX_ASKS);
        CHECK(L.nquestions >= 0 && L.nquestions <= HOL_APP_MAX_QUESTIONS);
        for (int k = 0; k < L.nasks; k++)
            CHECK(L.asks[k].n > 0 && L.asks[k].first >= 0 &&
                  L.asks[k].first + L.asks[k].n <= L.nquestions && L.asks[k].when >= 0 &&
                  L.asks[k].when < HOL_APP_ASK_WHENS);
        for (int k = 0; k < L.nquestions; k++) {
            const hol_app_question *q = &L.questions[k];
            CHECK(q->id[0] && q->text[0]);
            if (q->kind == HOL_APP_LIKERT)
                CHECK(q->lo < q->hi && q->hi <= 100 && q->step >= 1 &&
                      (q->hi - q->lo) / q->step + 1 <= HOL_APP_MAX_SCALE);
            else
                CHECK(q->kind == HOL_APP_CHOICE && q->nchoices >= 2 &&
                      q->nchoices <= HOL_APP_MAX_CHOICES);
        }
        CHECK(hol_app_wrap(L.instructions, HOL_APP_SCREEN_COLS, NULL, 0) <= HOL_APP_SCREEN_LINES);
        CHECK(hol_app_wrap(L.closing, HOL_APP_SCREEN_COLS, NULL, 0) <= HOL_APP_SCREEN_LINES);
        if (L.cell_m > 0) { /* the cell size prints back to itself */
            char c[16];
            double again_m = 0;
            hol_level_format_cell(L.cell_m, c);
            CHECK(hol_level_parse_cell(c, strlen(c), &again_m) == HOL_OK && again_m == L.cell_m);
        }
        static hol_level lv;
        hol_app_level again;
        CHECK(hol_level_make("x", 1, text, len, &lv, NULL) == HOL_OK);
        CHECK(hol_level_parse(lv.text, lv.len, &again, NULL) == HOL_OK);
        CHECK(!memcmp(&again, &L, sizeof L));
        CHECK(lv.len == 0 || lv.text[lv.len - 1] == '\n');
        uint8_t h[32];
        hol_sha256(lv.text, lv.len, h);
        CHECK(!memcmp(h, lv.sha256, 32));
    } else {
        CHECK(err.code != HOL_OK && strlen(err.msg) < sizeof err.msg);
        long lines = 1;
        for (size_t i = 0; i < len; i++)
            lines += text[i] == '\n';
        CHECK(err.line >= 0 && err.line <= lines);
        size_t kept = len + (len && text[len - 1] != '\n'); /* a last LF added */
        CHECK(err.line > 0 || kept > HOL_LEVEL_TEXT_MAX);
        CHECK(err.other >= 0 && err.other <= lines);
        char line[300];
        hol_level_err_format(&err, 1, line, sizeof line);
        CHECK(err.line == 0 || !strncmp(line, "line ", 5));
    }
}

static void check_message(const char *s)
{
    char *out = NULL;
    size_t n = 0;
    FILE *mem = open_memstream(&out, &n);
    CHECK(mem != NULL);
    FILE *saved = stderr;
    stderr = mem;
    cli_error("fuzz", 0, "value '%s'", s);
    stderr = saved;
    fclose(mem);
    CHECK(n > 0 && out[n - 1] == '\n');
    for (size_t i = 0; i + 1 < n; i++)
        CHECK((unsigned char)out[i] >= 0x20 && out[i] != 0x7f);
    free(out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 8192)
        return 0;
    char *buf = malloc(size);
    if (!buf)
        abort();
    memcpy(buf, data + 1, size - 1);
    buf[size - 1] = 0;
    switch (data[0] % 3) {
    case 0: check_number(buf); break;
    case 1: check_level(buf, size - 1); break;
    default: check_message(buf); break;
    }
    free(buf);
    return 0;
}
