/* test_study.c - study designs (core/hol_study.h): the counterbalancing
 * squares proved by counting (participants 1..R: each condition equally
 * often in each position; Williams: each ordered pair of conditions
 * adjacent equally often), the study file's grammar and every refusal with
 * its line, and a condition's level (set lines replacing the file's lines
 * of their key, errors named in the right file).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_sha256.h"
#include "../core/hol_study.h"
#include "../core/hol_tile.h"

static hol_study study; /* 16 KB of text: not on the stack */

static int parse(const char *text, char *msg)
{
    hol_level_err e;
    if (hol_study_parse(text, strlen(text), &study, &e) == HOL_OK)
        return 0;
    hol_level_err_format(&e, 1, msg, 256);
    return 1;
}

/* Rows 0..R-1 of a square: every row a permutation; each condition `per`
 * times in each position; with adj > 0, each ordered pair (a, b), a != b,
 * adjacent (b right after a) exactly adj times. */
static void check_square(hol_study_rule rule, int n, int per, int adj)
{
    uint64_t rows = hol_study_rows(rule, n);
    int pos[16][16] = {{0}}, pair[16][16] = {{0}};
    for (uint64_t r = 0; r < rows; r++) {
        int row[16], seen[16] = {0};
        assert_int_equal(hol_study_square(rule, n, r, row), HOL_OK);
        for (int k = 0; k < n; k++) {
            assert_true(row[k] >= 0 && row[k] < n);
            assert_int_equal(seen[row[k]]++, 0);
            pos[row[k]][k]++;
            if (k > 0)
                pair[row[k - 1]][row[k]]++;
        }
    }
    for (int a = 0; a < n; a++)
        for (int k = 0; k < n; k++)
            assert_int_equal(pos[a][k], per);
    for (int a = 0; adj && a < n; a++)
        for (int b = 0; b < n; b++)
            assert_int_equal(pair[a][b], a == b ? 0 : adj);
    int row[16];
    assert_int_equal(hol_study_square(rule, n, rows, row), HOL_EARG);
}

static void test_williams(void **state)
{
    (void)state;
    for (int n = 2; n <= 16; n += 2) {
        assert_int_equal(hol_study_rows(HOL_STUDY_WILLIAMS, n), n);
        check_square(HOL_STUDY_WILLIAMS, n, 1, 1);
    }
    /* odd: the square and its mirror, 2n rows, everything twice */
    for (int n = 3; n <= 15; n += 2) {
        assert_int_equal(hol_study_rows(HOL_STUDY_WILLIAMS, n), 2 * n);
        check_square(HOL_STUDY_WILLIAMS, n, 2, 2);
    }
    assert_int_equal(hol_study_rows(HOL_STUDY_WILLIAMS, 1), 1);
    check_square(HOL_STUDY_WILLIAMS, 1, 1, 0);
    /* the textbook square of four: A B D C, B C A D, C D B A, D A C B */
    static const int want[4][4] = {{0, 1, 3, 2}, {1, 2, 0, 3}, {2, 3, 1, 0}, {3, 0, 2, 1}};
    for (int r = 0; r < 4; r++) {
        int row[4];
        assert_int_equal(hol_study_square(HOL_STUDY_WILLIAMS, 4, (uint64_t)r, row), HOL_OK);
        assert_memory_equal(row, want[r], sizeof row);
    }
}

static void test_other_rules(void **state)
{
    (void)state;
    for (int n = 1; n <= 16; n++) {
        check_square(HOL_STUDY_LATIN, n, 1, 0);
        assert_int_equal(hol_study_rows(HOL_STUDY_FIXED, n), 1);
        int row[16];
        assert_int_equal(hol_study_square(HOL_STUDY_FIXED, n, 0, row), HOL_OK);
        for (int k = 0; k < n; k++)
            assert_int_equal(row[k], k);
    }
    /* complete: n! distinct orders, in lexicographic order */
    uint64_t fact = 1;
    for (int n = 1; n <= 6; n++) {
        fact *= (uint64_t)n;
        assert_int_equal(hol_study_rows(HOL_STUDY_COMPLETE, n), fact);
        check_square(HOL_STUDY_COMPLETE, n, (int)(fact / (uint64_t)n), 0);
        int prev[16] = {0}, row[16];
        for (uint64_t r = 0; r < fact; r++) {
            hol_study_square(HOL_STUDY_COMPLETE, n, r, row);
            int k = 0;
            while (r && k < n && prev[k] == row[k])
                k++;
            assert_true(r == 0 || (k < n && prev[k] < row[k]));
            memcpy(prev, row, sizeof row);
        }
    }
    assert_int_equal(hol_study_rows(HOL_STUDY_COMPLETE, 16), 20922789888000ull);
    assert_int_equal(hol_study_rows(HOL_STUDY_LATIN, 0), 0);
    assert_int_equal(hol_study_rows(HOL_STUDY_LATIN, 17), 0);
}

/* Participants 1..n of a parsed study get a balanced square; participant
 * n + 1 starts it again. */
static void test_participants(void **state)
{
    (void)state;
    char text[2048], msg[256];
    for (int n = 2; n <= 8; n++) {
        int len = snprintf(text, sizeof text, "study s\nset mode explore\n");
        for (int c = 0; c < n; c++)
            len += snprintf(text + len, sizeof text - (size_t)len, "condition c%d\nset seed %d\n",
                            c, c);
        assert_int_equal(parse(text, msg), 0);
        assert_int_equal(study.rule, HOL_STUDY_WILLIAMS);
        int rows = n % 2 ? 2 * n : n, pos[8][8] = {{0}}, pair[8][8] = {{0}};
        for (int p = 1; p <= rows; p++) {
            int order[16], again[16];
            assert_int_equal(hol_study_order(&study, (uint64_t)p, order), HOL_OK);
            assert_int_equal(hol_study_order(&study, (uint64_t)(p + rows), again), HOL_OK);
            assert_memory_equal(order, again, sizeof(int) * (size_t)n);
            for (int k = 0; k < n; k++) {
                pos[order[k]][k]++;
                if (k)
                    pair[order[k - 1]][order[k]]++;
            }
            /* the session: each condition's one level at its position */
            int lv[16], cond[16], at[16];
            assert_int_equal(hol_study_session(&study, order, lv, cond, at), n);
            for (int k = 0; k < n; k++) {
                assert_int_equal(cond[k], order[k]);
                assert_int_equal(at[k], k + 1);
                assert_int_equal(hol_study_level_condition(&study, lv[k]), order[k]);
            }
        }
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++) {
                assert_int_equal(pos[a][b], n % 2 ? 2 : 1);
                assert_int_equal(pair[a][b], a == b ? 0 : n % 2 ? 2 : 1);
            }
        int order[16];
        assert_int_equal(hol_study_order(&study, 0, order), HOL_EARG);
    }
    assert_int_equal(hol_study_participant_number("P07"), 7);
    assert_int_equal(hol_study_participant_number("12"), 12);
    assert_int_equal(hol_study_participant_number("s2-p031"), 31);
    assert_int_equal(hol_study_participant_number("P"), 0);
    assert_int_equal(hol_study_participant_number("P0"), 0);
    /* issue 24 finding 16: a sign, an exponent or hex are not numbers */
    assert_int_equal(hol_study_participant_number("-1"), 0);
    assert_int_equal(hol_study_participant_number("1e3"), 0);
    assert_int_equal(hol_study_participant_number("0x10"), 0);
    assert_int_equal(hol_study_participant_number("_7"), 0);
    assert_int_equal(hol_study_participant_number("007"), 7);
    assert_int_equal(hol_study_participant_number("P1000000000"), 1000000000);
    assert_int_equal(hol_study_participant_number("P1000000001"), 0);
    assert_int_equal(hol_study_participant_number("P99999999999999999999999"), 0);
}

/* Participant ids in their one spelling (issue 35): P02, 002 and p2 are
 * one participant; a number spelled otherwise is refused, not guessed. */
static void test_participant_ids(void **state)
{
    (void)state;
    static const struct {
        const char *id, *want;
        int kind;
    } cases[] = {
        {"P02", "P02", HOL_STUDY_ID_SAME},      {"002", "P02", HOL_STUDY_ID_RENAMED},
        {"p2", "P02", HOL_STUDY_ID_RENAMED},    {"2", "P02", HOL_STUDY_ID_RENAMED},
        {"P2", "P02", HOL_STUDY_ID_RENAMED},    {"P0002", "P02", HOL_STUDY_ID_RENAMED},
        {"P123", "P123", HOL_STUDY_ID_SAME},    {"0123", "P123", HOL_STUDY_ID_RENAMED},
        {"P10", "P10", HOL_STUDY_ID_SAME},      {"P0", "P00", HOL_STUDY_ID_RENAMED},
        {"s2-p031", "s2-p031", HOL_STUDY_ID_SAME}, {"Pam", "Pam", HOL_STUDY_ID_SAME},
        {"KM07", "KM07", HOL_STUDY_ID_SAME},    {"", "", HOL_STUDY_ID_SAME},
        {"P-02", "P02", HOL_STUDY_ID_AMBIGUOUS}, {"p_2", "P02", HOL_STUDY_ID_AMBIGUOUS},
        {"0.2", "P02", HOL_STUDY_ID_AMBIGUOUS}, {"P.1.2", "P12", HOL_STUDY_ID_AMBIGUOUS},
        {"-A1", "-A1", HOL_STUDY_ID_SAME},      {"PP2", "PP2", HOL_STUDY_ID_SAME},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char out[HOL_REC_ID_MAX];
        assert_int_equal(hol_study_participant_id(cases[i].id, out, sizeof out), cases[i].kind);
        assert_string_equal(out, cases[i].want);
        /* its spelling is a fixed point, and the number is kept */
        char again[HOL_REC_ID_MAX];
        if (cases[i].kind != HOL_STUDY_ID_AMBIGUOUS) {
            assert_int_equal(hol_study_participant_id(out, again, sizeof again),
                             HOL_STUDY_ID_SAME);
            assert_int_equal(hol_study_participant_number(out),
                             hol_study_participant_number(cases[i].id));
        }
    }
    /* in place, and a spelling that does not fit is no spelling */
    char buf[HOL_REC_ID_MAX] = "p7";
    assert_int_equal(hol_study_participant_id(buf, buf, sizeof buf), HOL_STUDY_ID_RENAMED);
    assert_string_equal(buf, "P07");
    char small[3];
    assert_int_equal(hol_study_participant_id("7", small, sizeof small), HOL_STUDY_ID_AMBIGUOUS);
    char digits[HOL_REC_ID_MAX];
    memset(digits, '9', 63);
    digits[63] = 0;
    char out[HOL_REC_ID_MAX];
    assert_int_equal(hol_study_participant_id(digits, out, sizeof out), HOL_STUDY_ID_AMBIGUOUS);
    assert_string_equal(out, digits);
}

static const char full[] =
    "# a study of the minimap's place\n"
    "study minimap-place\n"
    "counterbalance latin   # one row each\n"
    "practice tutorial.lvl\n"
    "set time-limit 300\n"
    "set cues hot-cold path poles arrow\n"
    "\n"
    "condition hud\r\n"
    "level flag-a.lvl\n"
    "level flag-b.lvl\n"
    "set minimap hud\n"
    "condition hand\n"
    "  level   flag-a.lvl\n"
    "  set minimap hand\n"
    "  set cues hot-cold   path\n"
    "condition none\n"
    "set mode flag\n"
    "set flag-distance 3\n"
    "set minimap off\n";

static void test_grammar(void **state)
{
    (void)state;
    char msg[256] = "", path[HOL_STUDY_PATH_MAX];
    if (parse(full, msg))
        fail_msg("%s", msg);
    assert_string_equal(study.name, "minimap-place");
    assert_int_equal(study.rule, HOL_STUDY_LATIN);
    assert_int_equal(study.npractice, 1);
    assert_int_equal(study.nconditions, 3);
    assert_int_equal(study.nlevels, 5);
    assert_int_equal(study.nglobal, 2);
    assert_int_equal(study.nsets, 8);
    const char *names[3] = {"hud", "hand", "none"};
    const int first[3] = {1, 3, 4}, nl[3] = {2, 1, 1}, ns[3] = {1, 2, 3};
    for (int c = 0; c < 3; c++) {
        assert_string_equal(study.conditions[c].name, names[c]);
        assert_int_equal(study.conditions[c].first_level, first[c]);
        assert_int_equal(study.conditions[c].nlevels, nl[c]);
        assert_int_equal(study.conditions[c].nsets, ns[c]);
    }
    assert_int_equal(study.conditions[1].line, 12);
    hol_study_level_path(&study, 0, path);
    assert_string_equal(path, "tutorial.lvl");
    hol_study_level_path(&study, 3, path);
    assert_string_equal(path, "flag-a.lvl");
    hol_study_level_path(&study, 4, path);
    assert_string_equal(path, "");
    assert_int_equal(hol_study_level_condition(&study, 0), -1);
    assert_int_equal(hol_study_level_condition(&study, 2), 0);
    /* the practice level first, then each condition's levels */
    int order[3] = {2, 0, 1}, lv[16], cond[16], at[16];
    assert_int_equal(hol_study_session(&study, order, lv, cond, at), 5);
    static const int wlv[5] = {0, 4, 1, 2, 3}, wc[5] = {-1, 2, 0, 0, 1}, wat[5] = {0, 1, 2, 2, 3};
    assert_memory_equal(lv, wlv, sizeof wlv);
    assert_memory_equal(cond, wc, sizeof wc);
    assert_memory_equal(at, wat, sizeof wat);
    for (int p = 1; p <= 3; p++) { /* latin: rows 0, 1, 2 */
        int o[3];
        hol_study_order(&study, (uint64_t)p, o);
        for (int k = 0; k < 3; k++)
            assert_int_equal(o[k], (k + p - 1) % 3);
    }
}

static void test_refusals(void **state)
{
    (void)state;
    static const struct {
        const char *text, *msg;
    } bad[] = {
        {"condition a\n", "no 'study NAME' line"},
        {"study s\n", "no 'condition NAME' line"},
        {"study s\nstudy t\ncondition a\n", "line 2: a second 'study' line (line 1)"},
        {"study s s\ncondition a\n", "line 1: 'study' takes one value"},
        {"study\ncondition a\n", "line 1: 'study' needs a value"},
        {"study a/b\n", "line 1: study 'a/b' is not 1..63 letters, digits, '.', '_', '-'"},
        {"study s\ncounterbalance balanced\n",
         "line 2: counterbalance 'balanced' is not williams, latin, complete or fixed"},
        {"study s\ncondition a\ncounterbalance latin\n",
         "line 3: 'counterbalance' comes before the first condition"},
        {"study s\ncondition a\nstudy t\n", "line 3: 'study' comes before the first condition"},
        {"study s\nlevel x.lvl\n",
         "line 2: 'level' belongs to a condition (before the first: 'practice')"},
        {"study s\ncondition a\npractice t.lvl\n",
         "line 3: 'practice' comes before the first condition"},
        {"study s\ncondition a\ncondition a\n", "line 3: condition 'a' is given twice (line 2)"},
        {"study s\ncondition practice\n",
         "line 2: 'practice' names the practice levels, not a condition"},
        {"study s\ncondition a,b\n",
         "line 2: condition 'a,b' is not 1..63 letters, digits, '.', '_', '-'"},
        {"study s\nconditions a\n",
         "line 2: unknown key 'conditions' (study, counterbalance, practice, condition, level, "
         "set, allow, instructions, closing, question, questionnaire)"},
        {"study s\nallow minimap\ncondition a\n",
         "line 2: allow 'minimap' is not minimap-toggle"},
        {"study s\ncondition a\nallow minimap-toggle\n",
         "line 3: 'allow' comes before the first condition"},
        {"study s\nallow\ncondition a\n", "line 2: 'allow' needs a value"},
        {"study s\ncondition a\nset\n", "line 3: 'set' needs a level line (KEY VALUE...)"},
        {"study s\ncondition a\nset minimap wrist\n",
         "line 3: set: minimap 'wrist' is not hud, hand or off"},
        {"study s\nset colour red\ncondition a\n",
         "line 2: set: unknown key or wrong value count: 'colour'"},
        {"study s\ncondition a\nset time-limit 0\n",
         "line 3: set: time-limit '0' is not seconds in 1..86400"},
        {"study s\ncondition a\nset cues # none\n", "line 3: set: 'cues' needs a value"},
        {"study s\ncondition a\nlevel a\0b\n", "line 3: a NUL byte"},
    };
    char msg[256];
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        size_t len = strlen(bad[i].text);
        if (strstr(bad[i].text, "level a"))
            len = sizeof "study s\ncondition a\nlevel a\0b\n" - 1;
        hol_level_err e;
        hol_err r = hol_study_parse(bad[i].text, len, &study, &e);
        assert_int_not_equal(r, HOL_OK);
        hol_level_err_format(&e, 1, msg, sizeof msg);
        if (strcmp(msg, bad[i].msg))
            fail_msg("%zu: got '%s', want '%s'", i, msg, bad[i].msg);
        assert_int_equal(study.nconditions, 0); /* nothing kept */
    }
    /* bounds: the file, a line, levels, conditions, set lines */
    static char big[HOL_STUDY_TEXT_MAX + 2];
    memset(big, '#', sizeof big - 1);
    assert_int_equal(parse(big, msg), 1);
    assert_string_equal(msg, "longer than 16383 bytes");
    char line[700];
    snprintf(line, sizeof line, "study s\ncondition a\nlevel %0600d\n", 0);
    assert_int_equal(parse(line, msg), 1);
    assert_string_equal(msg, "line 3: longer than 511 bytes");
    char text[4096];
    int n = snprintf(text, sizeof text, "study s\ncondition a\n");
    for (int k = 0; k < 17; k++)
        n += snprintf(text + n, sizeof text - (size_t)n, "level l%d\n", k);
    assert_int_equal(parse(text, msg), 1);
    assert_string_equal(msg, "line 19: more than 16 levels in all (a recording holds 16)");
    n = snprintf(text, sizeof text, "study s\npractice p\n");
    for (int k = 0; k < 16; k++)
        n += snprintf(text + n, sizeof text - (size_t)n, "condition c%d\nset mode explore\n", k);
    assert_int_equal(parse(text, msg), 1);
    assert_string_equal(msg, "line 33: more than 16 levels in all");
    /* 65 set lines: five keys in each of 13 conditions (a key set twice
     * in one condition is refused by itself) */
    static const char *const sets5[5] = {"seed 1", "cues none", "minimap hud", "time-limit 5",
                                         "start N"};
    n = snprintf(text, sizeof text, "study s\n");
    for (int k = 0; k < 65; k++) {
        if (k % 5 == 0)
            n += snprintf(text + n, sizeof text - (size_t)n, "condition c%d\n", k / 5);
        n += snprintf(text + n, sizeof text - (size_t)n, "set %s\n", sets5[k % 5]);
    }
    assert_int_equal(parse(text, msg), 1);
    assert_string_equal(msg, "line 79: more than 64 set lines");
    /* issue 24 finding 9: a key set twice in one place, naming both lines;
     * a condition's set line over the study's is no repeat */
    assert_int_equal(parse("study s\nset seed 1\nset seed 2\ncondition a\nset mode explore\n", msg), 1);
    assert_string_equal(msg, "line 3: set seed is given twice in the study (line 2)");
    assert_int_equal(parse("study s\ncondition a\nset mode flag\nset flag Nf\nset mode keys\n", msg), 1);
    assert_string_equal(msg, "line 5: set mode is given twice in this condition (line 3)");
    assert_int_equal(parse("study s\nset seed 1\ncondition a\nset mode explore\nset seed 2\n", msg), 0);
    /* a UTF-8 byte order mark before the first line is not part of it */
    assert_int_equal(parse("\xef\xbb\xbfstudy s\ncondition a\nset mode explore\n", msg), 0);
    /* 16 conditions, one level each, fit */
    n = snprintf(text, sizeof text, "study s\n");
    for (int k = 0; k < 16; k++)
        n += snprintf(text + n, sizeof text - (size_t)n, "condition c%d\nset mode explore\n", k);
    assert_int_equal(parse(text, msg), 0);
    assert_int_equal(study.nlevels, 16);
}

static int make(int i, int position, const char *file, hol_level *out, char *msg,
                int *in_study)
{
    hol_level_err e;
    if (!hol_study_make_level(&study, i, position, file, file ? strlen(file) : 0, NULL, out, &e,
                              in_study))
        return 0;
    hol_level_err_format(&e, 1, msg, 256);
    return 1;
}

/* Tiling, room and cell size as conditions: set lines replace the file's
 * geometry lines, the addresses of the file are read in the condition's
 * tiling, and a condition whose objective its room cannot reach is
 * refused naming the file's line. */
static void test_geometry_conditions(void **state)
{
    (void)state;
    char msg[256];
    int in_study = -1;
    static hol_level L;
    assert_int_equal(parse("study geo\ncounterbalance latin\nset seed 4\n"
                           "condition flat\nlevel a.lvl\nset tiling 4 4\n"
                           "condition curved\nlevel a.lvl\nset tiling 4 6\nset room 4 4\n"
                           "set cell 0.75\n"
                           "condition plain\nlevel a.lvl\n", msg), 0);
    const char *file = "mode flag\nflag Nr\ntiling 4 5\n";
    assert_int_equal(make(0, 1, file, &L, msg, &in_study), 0);
    assert_int_equal(L.lvl.tiling_q, 4);
    assert_int_equal(L.lvl.room_cols, 0);
    assert_int_equal(hol_tile_q(L.lvl.flag), 4);
    assert_string_equal(L.text, "mode flag\nflag Nr\n# study geo, condition flat:\nseed 4\n"
                                "tiling 4 4\n");
    assert_int_equal(make(1, 2, file, &L, msg, &in_study), 0);
    assert_int_equal(L.lvl.tiling_q, 6);
    assert_int_equal(L.lvl.room_cols, 4);
    assert_int_equal(L.lvl.room_rows, 4);
    assert_true(L.lvl.cell_m == 0.75);
    assert_int_equal(hol_tile_q(L.lvl.flag), 6);
    assert_string_equal(L.condition, "curved");
    assert_int_equal(make(2, 3, file, &L, msg, &in_study), 0);
    assert_int_equal(L.lvl.tiling_q, 5); /* the file's own line */
    /* the flat condition cannot reach a flag two tiles ahead */
    assert_int_equal(make(0, 1, "mode flag\nflag Nf\n", &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 2: no walk inside the room reaches the flag's tile Nf (in the "
                             "flat {4,4} a 3x3 room reaches only its own 9 tiles)");
    assert_int_equal(in_study, 0);
    /* a set line with an address of another tiling ({4,8}'s Nrr) */
    assert_int_equal(parse("study geo\ncondition a\nlevel a.lvl\nset tiling 4 8\n"
                           "set flag Nrr\n", msg), 0);
    assert_int_equal(make(0, 1, "mode flag\nflag N\n", &L, msg, &in_study), 0);
    assert_int_equal(hol_tile_q(L.lvl.flag), 8);
    assert_int_equal(parse("study geo\ncondition a\nlevel a.lvl\nset flag Nrrrrrrr\n", msg), 1);
    /* a bad set line: the study's line */
    assert_int_equal(parse("study geo\ncondition a\nset mode explore\nset room 3 6\n", msg), 1);
    assert_string_equal(msg, "line 4: set: room needs C R with C and R from 3 to 5 (cells), not '3 6'");
}

/* Light per condition (issue 27): `set lighting` and `set cues ...
 * lantern` make the conditions; the file's own lighting line is replaced. */
static void test_lighting_conditions(void **state)
{
    (void)state;
    char msg[256];
    int in_study = -1;
    static hol_level L;
    assert_int_equal(parse("study sky\ncounterbalance latin\n"
                           "condition lanterns\nlevel a.lvl\nset lighting night\n"
                           "set cues poles lantern\n"
                           "condition day\nlevel a.lvl\nset lighting day\n", msg), 0);
    const char *file = "mode flag\nflag Nr\nlighting dusk\nplace lantern E\n";
    assert_int_equal(make(0, 1, file, &L, msg, &in_study), 0);
    assert_int_equal(L.lvl.lighting, HOL_LIGHT_NIGHT);
    assert_int_equal(L.lvl.cues, HOL_CUE_POLES | HOL_CUE_LANTERN);
    assert_int_equal(L.lvl.nlanterns, 1);
    assert_int_equal(make(1, 2, file, &L, msg, &in_study), 0);
    assert_int_equal(L.lvl.lighting, HOL_LIGHT_DAY);
    assert_int_equal(L.lvl.cues, HOL_CUE_ALL);
    assert_int_equal(parse("study sky\ncondition a\nset lighting noon\n", msg), 1);
    assert_string_equal(msg, "line 3: set: lighting 'noon' is not day, dusk or night");
}

static void test_levels(void **state)
{
    (void)state;
    char msg[256];
    int in_study = -1;
    static hol_level L;
    assert_int_equal(parse(full, msg), 0);
    const char *flag = "mode flag\r\nseed 7 # the world\nflag Nf\nminimap hand\ncues none\n"
                       "time-limit 60\nplace rock Ef\nplace pond Wf\n";
    /* practice: the file as it is, labelled practice 0 */
    assert_int_equal(make(0, 5, "mode tutorial\nstages 1 2", &L, msg, &in_study), 0);
    assert_string_equal(L.text, "mode tutorial\nstages 1 2\n");
    assert_string_equal(L.condition, "practice");
    assert_int_equal(L.position, 0);
    assert_string_equal(L.name, "practice");
    /* hud: the file's minimap, cues and time-limit lines replaced */
    assert_int_equal(make(1, 2, flag, &L, msg, &in_study), 0);
    assert_string_equal(L.text, "mode flag\nseed 7 # the world\nflag Nf\nplace rock Ef\n"
                                "place pond Wf\n# study minimap-place, condition hud:\n"
                                "time-limit 300\ncues hot-cold path poles arrow\nminimap hud\n"
                                "fixed minimap\n");
    assert_string_equal(L.condition, "hud");
    assert_int_equal(L.position, 2);
    assert_int_equal(L.lvl.minimap, HOL_MINIMAP_HUD);
    assert_int_equal(L.lvl.minimap_fixed, 1); /* the condition's minimap holds */
    assert_int_equal(L.lvl.cues, HOL_CUE_ALL);
    assert_true(L.lvl.time_limit_s == 300);
    assert_int_equal(L.lvl.nplaces, 2);
    /* hand: its cues line in force, the study's not */
    assert_int_equal(make(3, 1, flag, &L, msg, &in_study), 0);
    assert_string_equal(L.text, "mode flag\nseed 7 # the world\nflag Nf\nplace rock Ef\n"
                                "place pond Wf\n# study minimap-place, condition hand:\n"
                                "time-limit 300\nminimap hand\ncues hot-cold   path\n"
                                "fixed minimap\n");
    assert_int_equal(L.lvl.cues, HOL_CUE_HOT_COLD | HOL_CUE_PATH);
    /* none: no file; named after the condition */
    assert_int_equal(make(4, 3, NULL, &L, msg, &in_study), 0);
    assert_string_equal(L.name, "none");
    assert_int_equal(L.lvl.mode, HOL_APP_FLAG);
    assert_int_equal(L.lvl.minimap, HOL_MINIMAP_OFF);
    /* errors: a file's line, a conflict between the file and a set line */
    assert_int_equal(make(1, 1, "mode flag\nflag Nf\nseed x\n", &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 3: seed 'x' is not an unsigned 64-bit number");
    assert_int_equal(in_study, 0);
    assert_int_equal(make(1, 1, "mode keys\nseed 1\n", &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 1: mode keys needs a 'keys' or 'keys-distance' line");
    assert_int_equal(in_study, 0);
    assert_int_equal(parse("study s\ncondition a\nlevel f.lvl\nset place rock Nf\n", msg), 0);
    assert_int_equal(make(0, 1, "mode flag\nflag Nf\n", &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 4: set: the placement on Nf conflicts with the flag");
    assert_int_equal(in_study, 1);
    /* a condition of set lines without a mode: its condition line */
    assert_int_equal(parse("study s\ncondition a\nset seed 3\ncondition b\nset mode explore\n", msg),
                     1);
    assert_string_equal(msg, "line 2: condition a has neither a 'level' nor a 'set mode' line");
    assert_int_equal(parse("study s\nset mode explore\ncondition a\nset seed 3\n", msg), 0);
    assert_int_equal(make(0, 1, NULL, &L, msg, &in_study), 0);
    /* a conflict the level finds after its last line: the set line */
    assert_int_equal(parse("study s\ncondition a\nset mode flag\n", msg), 0);
    assert_int_equal(make(0, 1, NULL, &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 3: set: mode flag needs a 'flag' or 'flag-distance' line");
    assert_int_equal(in_study, 1);
    /* without set lines the file is unchanged: the same SHA-256 */
    assert_int_equal(parse("study s\ncondition a\nlevel f.lvl\n", msg), 0);
    assert_int_equal(make(0, 1, "mode flag\r\nflag Nf", &L, msg, &in_study), 0);
    uint8_t h[32];
    hol_sha256("mode flag\nflag Nf\n", 18, h);
    assert_memory_equal(L.sha256, h, 32);
    /* too long with the set lines: the condition's line */
    char text[HOL_LEVEL_TEXT_MAX + 1];
    memset(text, '#', sizeof text - 1);
    memcpy(text, "mode explore\n", 13);
    text[HOL_LEVEL_TEXT_MAX - 10] = '\n';
    text[HOL_LEVEL_TEXT_MAX - 9] = 0;
    assert_int_equal(parse("study s\ncondition a\nlevel f\nset seed 12345678\n", msg), 0);
    assert_int_equal(make(0, 1, text, &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 2: condition a: its level with the set lines is longer than "
                             "4095 bytes");
    assert_int_equal(in_study, 1);
    /* issue 39: the closing makes a's level too long only where a is the
     * last; the participant playing it first is refused as well (the bounds
     * are every participant's), naming the closing and the position */
    for (int k = 99; k < HOL_LEVEL_TEXT_MAX - 150; k += 100)
        text[k] = '\n'; /* comment lines of 99 bytes */
    text[HOL_LEVEL_TEXT_MAX - 150] = '\n';
    text[HOL_LEVEL_TEXT_MAX - 149] = 0;
    assert_int_equal(parse("study s\ncounterbalance latin\nclosing Thank you, this is a "
                           "closing line long enough to be over the level's bound when it is "
                           "added to the level text of condition a, which is nearly full by "
                           "itself.\ncondition a\nlevel f\ncondition b\nset mode explore\n",
                           msg), 0);
    assert_int_equal(make(0, 1, text, &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 4: condition a: its level with the closing is longer than "
                             "4095 bytes (at position 2 of 2, the last)");
    assert_int_equal(make(0, 2, text, &L, msg, &in_study), 1);
    assert_string_equal(msg, "line 4: condition a: its level with the closing is longer than "
                             "4095 bytes");
    assert_int_equal(make(1, 1, NULL, &L, msg, &in_study), 0);
    /* fixed: a is always first and never carries the closing */
    assert_int_equal(parse("study s\ncounterbalance fixed\nclosing Thank you, this is a "
                           "closing line long enough to be over the level's bound when it is "
                           "added to the level text of condition a, which is nearly full by "
                           "itself.\ncondition a\nlevel f\ncondition b\nset mode explore\n",
                           msg), 0);
    assert_int_equal(make(0, 1, text, &L, msg, &in_study), 0);
    assert_int_equal(L.position, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_williams),   cmocka_unit_test(test_other_rules),
        cmocka_unit_test(test_participants), cmocka_unit_test(test_participant_ids),
        cmocka_unit_test(test_grammar),
        cmocka_unit_test(test_refusals),   cmocka_unit_test(test_levels),
        cmocka_unit_test(test_geometry_conditions),
        cmocka_unit_test(test_lighting_conditions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
