/* test_report.c - core/hol_report.h: the log reader of `holonomy report`.
 * CSV fields by hand (RFC 4180 quoting, refusals) and on random fields
 * written by hol_text_csv (the logs' own writer); headers by column name
 * (added columns, any order, missing required ones); summary and steps
 * rows (defaults and geometry columns, bounds); efficiency; per-condition
 * means.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_report.h"
#include "../core/hol_room.h"
#include "../core/hol_text.h"

static int split(const char *s, const char **f, char *buf, size_t cap)
{
    int n = -1;
    char err[HOL_REPORT_ERR];
    if (hol_report_csv_split(s, strlen(s), buf, cap, f, HOL_REPORT_MAX_COLS, &n, err))
        return -1;
    return n;
}

static void test_split(void **state)
{
    (void)state;
    const char *f[HOL_REPORT_MAX_COLS];
    char buf[256];
    assert_int_equal(split("a,,\"b,c\",\"d\"\"e\",", f, buf, sizeof buf), 5);
    assert_string_equal(f[0], "a");
    assert_string_equal(f[1], "");
    assert_string_equal(f[2], "b,c");
    assert_string_equal(f[3], "d\"e");
    assert_string_equal(f[4], "");
    assert_int_equal(split("", f, buf, sizeof buf), 1);
    assert_int_equal(split("\"\"", f, buf, sizeof buf), 1);
    assert_string_equal(f[0], "");
    /* refused: an open quote, text after a closing one, a bare quote */
    assert_int_equal(split("a,\"b", f, buf, sizeof buf), -1);
    assert_int_equal(split("\"a\"b", f, buf, sizeof buf), -1);
    assert_int_equal(split("a\"b", f, buf, sizeof buf), -1);
    assert_int_equal(split("abcdef", f, buf, 4), -1); /* longer than the buffer */
    char many[HOL_REPORT_MAX_COLS + 1], big[4 * sizeof many];
    memset(many, ',', sizeof many);
    many[HOL_REPORT_MAX_COLS - 1] = 0; /* HOL_REPORT_MAX_COLS fields */
    assert_int_equal(split(many, f, big, sizeof big), HOL_REPORT_MAX_COLS);
    many[HOL_REPORT_MAX_COLS - 1] = ',';
    many[HOL_REPORT_MAX_COLS] = 0; /* one more */
    assert_int_equal(split(many, f, big, sizeof big), -1); /* more than the report reads */
}

/* Random fields through the logs' writer read back the same. */
static void test_split_random(void **state)
{
    (void)state;
    uint64_t x = 88172645463325252ull;
    for (int round = 0; round < 3000; round++) {
        char fields[6][16], line[512], buf[512];
        size_t o = 0;
        int n = 1 + round % 6;
        for (int i = 0; i < n; i++) {
            int len = (int)((x >> 7) % 12);
            for (int k = 0; k < len; k++) {
                x ^= x << 13, x ^= x >> 7, x ^= x << 17;
                fields[i][k] = " ,\"ab\r\n"[x % 7];
            }
            fields[i][len] = 0;
            o += hol_text_csv(fields[i], (size_t)len, line + o, sizeof line - o);
            line[o++] = ',';
        }
        line[--o] = 0;
        const char *f[HOL_REPORT_MAX_COLS];
        int got = -1;
        assert_int_equal(hol_report_csv_split(line, o, buf, sizeof buf, f, HOL_REPORT_MAX_COLS,
                                              &got, NULL), HOL_OK);
        assert_int_equal(got, n);
        for (int i = 0; i < n; i++)
            assert_string_equal(f[i], fields[i]);
    }
}

static const char summary_head[] =
    "session,participant,session_start,version,attempt,study,condition,position,level,"
    "level_sha256,mode,seed,cues,tiling,room,cell,started,steps,optimum,time,end";

static hol_err row(const hol_report_header *h, const char *s, hol_report_attempt *a, char *err)
{
    return hol_report_summary_row(h, s, strlen(s), a, err);
}

static void test_summary(void **state)
{
    (void)state;
    hol_report_header h;
    hol_report_attempt a;
    char err[HOL_REPORT_ERR];
    assert_int_equal(hol_report_summary_header(summary_head, strlen(summary_head), &h, err), 0);
    assert_int_equal(row(&h, "S1,P07,2026-01-31T14:05:09Z,0.1.0,3,cues,hand,2,\"a,b\",ff,flag,5,15,"
                             "\"4,6\",4x5,0.75,1.5,12,9,20.2500,done", &a, err), 0);
    assert_string_equal(a.session, "S1");
    assert_string_equal(a.participant, "P07");
    assert_string_equal(a.condition, "hand");
    assert_string_equal(a.level, "a,b");
    assert_int_equal(a.attempt, 3);
    assert_int_equal(a.position, 2);
    assert_int_equal(a.steps, 12);
    assert_int_equal(a.optimum, 9);
    assert_true(a.time_s == 20.25);
    assert_int_equal(a.tiling_q, 6);
    assert_int_equal(a.room_cols, 4);
    assert_int_equal(a.room_rows, 5);
    assert_true(a.cell_m == 0.75);
    assert_true(hol_report_efficiency(&a) == 0.75);
    /* refusals name their column; the attempt is untouched */
    a.steps = 77;
    assert_int_equal(row(&h, "S1,,x,v,3,,,,l,ff,flag,5,15,\"4,9\",3x3,1,0,1,1,1.0,done", &a, err),
                     HOL_EPARSE);
    assert_non_null(strstr(err, "tiling"));
    assert_int_equal(a.steps, 77);
    assert_int_equal(row(&h, "S1,,x,v,3,,,,l,ff,flag,5,15,,,,0,-1,1,1.0,done", &a, err), HOL_EPARSE);
    assert_non_null(strstr(err, "steps"));
    assert_int_equal(row(&h, "S1,,x,v,3,,,,l,ff,flag,5,15,,,,0,1,1,1e3,done", &a, err), HOL_EPARSE);
    assert_non_null(strstr(err, "time"));
    assert_int_equal(row(&h, "S1,,x,v,3,,,,l,ff,flag,5,15,,,,0,1,1,1.0", &a, err), HOL_EPARSE);
    assert_non_null(strstr(err, "fields"));
    /* an older log: no geometry columns, no study columns */
    static const char old[] = "session,attempt,level,mode,steps,optimum,time,end";
    assert_int_equal(hol_report_summary_header(old, strlen(old), &h, err), 0);
    assert_int_equal(row(&h, "S2,1,f,flag,4,5,2.0,killed", &a, err), 0);
    assert_int_equal(a.tiling_q, 5);
    assert_int_equal(a.room_cols, 3);
    assert_true(a.cell_m == 1);
    assert_int_equal(a.position, -1);
    assert_true(hol_report_efficiency(&a) == -1); /* not done */
    /* a missing required column */
    static const char bad[] = "session,attempt,level,mode,steps,time,end";
    assert_int_equal(hol_report_summary_header(bad, strlen(bad), &h, err), HOL_EPARSE);
    assert_non_null(strstr(err, "optimum"));
}

static void test_steps(void **state)
{
    (void)state;
    static const char head[] =
        "session,attempt,level,t,step,col,row,dir,yaw,tile,orient,remaining,cues,visible";
    hol_report_header h;
    hol_report_step s;
    char err[HOL_REPORT_ERR];
    assert_int_equal(hol_report_steps_header(head, strlen(head), &h, err), 0);
    const char *ok = "S,1,f,1.0,2,0,1,W,0.00,Wr,3,6,15,5";
    assert_int_equal(hol_report_step_row(&h, ok, strlen(ok), &s, err), 0);
    assert_int_equal(s.step, 2);
    assert_int_equal(s.col, 0);
    assert_int_equal(s.row, 1);
    assert_int_equal(s.dir, HOL_DIR_W);
    assert_string_equal(s.tile, "Wr");
    assert_int_equal(s.orient, 3);
    const char *bad[] = {"S,1,f,1.0,2,0,1,X,0.00,Wr,3,6,15,5", "S,1,f,1.0,2,5,1,W,0.00,Wr,3,6,15,5",
                         "S,1,f,1.0,0,0,1,W,0.00,Wr,3,6,15,5", "S,1,f,1.0,2,0,1,W,0.00,Wr,4,6,15,5"};
    for (int i = 0; i < 4; i++)
        assert_int_equal(hol_report_step_row(&h, bad[i], strlen(bad[i]), &s, err), HOL_EPARSE);
}

static void test_agg(void **state)
{
    (void)state;
    static hol_report_cond conds[80];
    hol_report_agg g;
    hol_report_attempt a;
    hol_report_agg_init(&g, conds, 80);
    memset(&a, 0, sizeof a);
    strcpy(a.end, "done");
    strcpy(a.level, "f");
    a.steps = 10, a.optimum = 5, a.time_s = 4;
    hol_report_agg_add(&g, &a); /* outside a study: by level */
    strcpy(a.study, "s"), strcpy(a.condition, "hud");
    hol_report_agg_add(&g, &a);
    a.steps = 5, a.time_s = 2;
    hol_report_agg_add(&g, &a);
    strcpy(a.end, "killed");
    hol_report_agg_add(&g, &a);
    assert_int_equal(g.n, 2);
    assert_string_equal(g.c[0].condition, "f");
    assert_string_equal(g.c[1].condition, "hud");
    assert_int_equal(g.c[1].n, 3);
    assert_int_equal(g.c[1].done, 2);
    assert_int_equal(g.c[1].neff, 2);
    assert_true(g.c[1].eff / (double)g.c[1].neff == 0.75);
    assert_true(g.c[1].steps == 20 && g.c[1].time_s == 8);
    /* 70 more levels (the old table held 64 and dropped the rest): all in
     * a table of 80; beyond the caller's table, counted, never silent */
    for (int i = 0; i < 70; i++) {
        a.level[0] = (char)('A' + i % 60), a.level[1] = (char)('0' + i / 60), a.level[2] = 0;
        a.study[0] = 0;
        hol_report_agg_add(&g, &a);
    }
    assert_int_equal(g.n, 72);
    assert_int_equal(g.overflow, 0);
    assert_string_equal(g.c[71].condition, "J1");
    for (int i = 0; i < 10; i++) {
        a.level[0] = (char)('k' + i), a.level[1] = 0;
        hol_report_agg_add(&g, &a);
    }
    assert_int_equal(g.n, 80);
    assert_int_equal(g.overflow, 2);
}

/* Texts from logs: what a terminal acts on and bad UTF-8 as \xHH, valid
 * UTF-8 and backslashes (the logs' own escapes) kept; cut between pieces. */
static void test_clean(void **state)
{
    (void)state;
    char out[128];
    const char *in = "a\\b\\x1b \x1b]0;T\x07\x7f\xc2\x9b\xe2\x80\xae\xff\xc3\xa9z";
    const char *want = "a\\b\\x1b \\x1b]0;T\\x07\\x7f\\xc2\\x9b\\xe2\\x80\\xae\\xff\xc3\xa9z";
    size_t n = hol_report_clean(in, out, sizeof out);
    assert_string_equal(out, want);
    assert_int_equal(n, strlen(want));
    assert_int_equal(hol_report_clean(in, NULL, 0), n);
    for (size_t cap = 1; cap <= n; cap++) {
        char cut[128];
        memset(cut, 'Z', sizeof cut);
        assert_int_equal(hol_report_clean(in, cut, cap), n);
        assert_true(strlen(cut) < cap && strlen(cut) + 4 >= cap);
        assert_memory_equal(cut, want, strlen(cut));
    }
    assert_int_equal(hol_report_clean("", out, sizeof out), 0);
    assert_string_equal(out, "");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_split),
        cmocka_unit_test(test_split_random),
        cmocka_unit_test(test_summary),
        cmocka_unit_test(test_steps),
        cmocka_unit_test(test_agg),
        cmocka_unit_test(test_clean),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
