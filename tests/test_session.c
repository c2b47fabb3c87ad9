/* test_session.c - the session every platform runs (core/hol_session.h)
 * against a model of a sink: a folder in memory whose streams keep only
 * what was flushed when the "process" is killed, so a kill is
 * hol_session_destroy without finish, then every stream cut to its
 * flushed bytes. And the POSIX sink (platform/file/hol_sink_posix.h) on a
 * temporary folder.
 *
 * Checked: a folder holding logs is refused without append, numbered on
 * with it; rows reach a flush within a second of input time; a killed
 * attempt is finished by the next session as `killed` (rows cut to whole
 * lines, no duplicate row when the kill came after its summary row); torn
 * append-only logs cut, a cut summary row's files removed with it; an
 * attempt's files appear with its row; head rows fall on exact 10 Hz
 * times, interpolated between frames against a linear walk; visible cues;
 * aborted; the recording reads back to the same levels and replays to the
 * same logs byte for byte; no allocation after create. A resumed level's
 * questions alone (issue 39): no attempt, answers on the attempt named,
 * from the item named, then the next level; the recording says so.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "../core/hol_input_io.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_rec.h"
#include "../core/hol_session.h"
#include "../core/hol_sha256.h"
#include "../platform/file/hol_sink_posix.h"
#include "count_alloc.h"

#include "mem_sink.h" /* a folder in memory */

/* ---- sessions --------------------------------------------------------------------- */

static hol_nav *g_nav;
static hol_level g_flag; /* mode flag, seed 5, flag Wrf: 8 steps by WNESWNEE */
static const char *const g_walk = "WNESWNEE";

static int setup(void **state)
{
    (void)state;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    const char *t = "mode flag\nseed 5\nflag Wrf\n";
    return hol_nav_create(&nd, &g_nav) != HOL_OK ||
           hol_level_make("lv", 2, t, strlen(t), &g_flag, NULL) != HOL_OK;
}

static int teardown(void **state)
{
    (void)state;
    hol_nav_destroy(g_nav);
    return 0;
}

static hol_session *make(const hol_level *levels, int n, mem_sink *log, mem_sink *rec, int append)
{
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = levels;
    d.nlevels = n;
    d.app.nav = g_nav;
    d.log = log ? &log->sink : NULL;
    d.append = append;
    d.rec = rec ? &rec->sink : NULL;
    d.rec_name = "s.rec";
    snprintf(d.meta.session, sizeof d.meta.session, "20260101T000000Z-00000001");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    snprintf(d.meta.participant, sizeof d.meta.participant, "P1");
    hol_session *s = NULL;
    char msg[256];
    hol_err e = hol_session_create(&d, &s, msg, sizeof msg);
    if (e)
        fail_msg("create: %s", msg);
    return s;
}

/* A tracked head standing at cell (c, r)'s centre at time t. */
static hol_input head_at(double t, double x, double z)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
    in.head.pos[0] = (float)x;
    in.head.pos[1] = 1.6f;
    in.head.pos[2] = (float)z;
    in.head.quat[3] = 1;
    return in;
}

/* Step the walk from cell (1,1), a step every 0.25 s from t0; the record
 * of every frame is kept in ins (when not NULL). Returns the last time. */
static double walk(hol_session *s, const char *w, double t0, hol_input *ins, int *nin)
{
    int c = 1, r = 1, over = 0;
    double t = t0;
    hol_input in = head_at(t, c + 0.5, r + 0.5);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    if (ins)
        ins[(*nin)++] = in;
    for (const char *p = w; *p; p++) {
        c += *p == 'E' ? 1 : *p == 'W' ? -1 : 0;
        r += *p == 'S' ? 1 : *p == 'N' ? -1 : 0;
        t += 0.25;
        in = head_at(t, c + 0.5, r + 0.5);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        if (ins)
            ins[(*nin)++] = in;
    }
    return t;
}

/* ---- the tests ---------------------------------------------------------------------- */

static void test_folder_refused_or_appended(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    mem_make(&m, "steps-007.csv");
    mem_make(&m, "notes.txt");
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = &g_flag;
    d.nlevels = 1;
    d.app.nav = g_nav;
    d.log = &m.sink;
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EARG);
    assert_non_null(strstr(msg, "holds earlier logs"));
    assert_null(mem_find(&m, "summary.csv")); /* nothing written */
    /* append: numbered on from the folder's highest attempt */
    s = make(&g_flag, 1, &m, NULL, 1);
    walk(s, g_walk, 0, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_non_null(mem_find(&m, "steps-008.csv"));
    assert_non_null(mem_find(&m, "head-008.csv"));
    const char *sum = mem_text(&m, "summary.csv");
    assert_non_null(strstr(sum, HOL_SESSION_SUMMARY_COLUMNS "\n"));
    assert_non_null(strstr(sum, ",8,,,,lv,")); /* no study: empty labels */
    assert_non_null(strstr(sum, ",done,,,\n"));
    /* other columns in summary.csv: refused even with append */
    mem_stream *x = mem_find(&m, "summary.csv");
    x->data[0] = 'X';
    d.append = 1;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EVERSION);
    mem_free(&m);
}

/* Every row made at input time T has been flushed by input time T + 1 s. */
static void test_rows_flushed_each_second(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&g_flag, 1, &m, NULL, 0);
    int over = 0;
    for (int k = 0; k <= 600; k++) { /* 10 s at 60 Hz, walking east and back */
        double t = k / 60.0, x = 1.5 + 0.9 * sin(t);
        hol_input in = head_at(t, x, 1.5);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        mem_stream *h = mem_find(&m, "head-001.csv.live");
        assert_non_null(h);
        int kept = 0;
        for (size_t i = 0; i < h->kept; i++)
            kept += h->data[i] == '\n';
        /* the header and a row per 0.1 s up to t - 1 at least */
        if (t >= 1.0)
            assert_true(kept - 1 >= (int)((t - 1.0) * 10) + 1);
    }
    hol_session_destroy(s);
    mem_free(&m);
}

static void kill_midway(mem_sink *m)
{
    hol_session *s = make(&g_flag, 1, m, NULL, 0);
    int over = 0;
    double t = walk(s, g_walk, 0, NULL, NULL); /* attempt 1: done */
    hol_input in = head_at(t + 0.5, 2.5, 1.5);
    in.pressed = HOL_BTN_CONFIRM; /* the end screen: the same level again? no: over */
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(over, 1);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    /* a second session: attempt 2 walks 3 steps in 3 s, then is killed */
    s = make(&g_flag, 1, m, NULL, 1);
    t = 10;
    const char *w = "WNE";
    int c = 1, r = 1;
    for (int k = 0; k <= 300; k++) {
        double tt = t + k / 100.0;
        int i = k / 100;
        if (k % 100 == 0 && k && w[i - 1]) {
            c += w[i - 1] == 'E' ? 1 : w[i - 1] == 'W' ? -1 : 0;
            r += w[i - 1] == 'N' ? -1 : 0;
        }
        hol_input hi = head_at(tt, c + 0.5, r + 0.5);
        assert_int_equal(hol_session_step(s, &hi, &over), HOL_OK);
    }
    hol_session_destroy(s); /* closes; writes nothing */
    mem_kill(m);
}

static void test_killed_attempt_recovered(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    kill_midway(&m);
    /* after the kill: attempt 1 whole, attempt 2 only as live files */
    assert_non_null(mem_find(&m, "steps-001.csv"));
    assert_non_null(mem_find(&m, "head-001.csv"));
    assert_null(mem_find(&m, "steps-002.csv"));
    assert_non_null(mem_find(&m, "attempt-002.live"));
    const char *live = mem_text(&m, "steps-002.csv.live");
    assert_non_null(live);
    int kept_steps = count_lines(live) - 1;
    assert_true(kept_steps >= 2); /* steps at 11 s and 12 s: flushed by 13 s */
    live = mem_text(&m, "head-002.csv.live");
    int kept_head = count_lines(live) - 1;
    assert_true(kept_head >= 20); /* at least 2 s of the 3 s */
    /* a row cut by the kill: its bytes dropped by the recovery */
    mem_stream *h = mem_find(&m, "head-002.csv.live");
    mem_open(&m, "head-002.csv.live", 1, &(int){0});
    mem_write(&m, 0, "20260101T000000Z-00000001,2,lv,9.9,9.", 36);
    m.open[0] = 0;
    h->kept = h->len;
    /* the next session (append) finishes it as killed */
    hol_session *s = make(&g_flag, 1, &m, NULL, 1);
    assert_int_equal(hol_session_recovered(s), 1);
    assert_null(mem_find(&m, "steps-002.csv.live"));
    assert_null(mem_find(&m, "attempt-002.live"));
    assert_int_equal(count_lines(mem_text(&m, "steps-002.csv")) - 1, kept_steps);
    const char *hd = mem_text(&m, "head-002.csv");
    assert_int_equal(count_lines(hd) - 1, kept_head);
    assert_int_equal(hd[strlen(hd) - 1], '\n');
    const char *sum = mem_text(&m, "summary.csv");
    char want[64];
    snprintf(want, sizeof want, ",2,,,,lv,");
    const char *row = strstr(sum, want);
    assert_non_null(row);
    assert_non_null(strstr(row, ",killed,,,\n"));
    char steps[32];
    snprintf(steps, sizeof steps, ",%d,8,", kept_steps);
    assert_non_null(strstr(row, steps));
    /* and it goes on at attempt 3 */
    walk(s, "W", 0, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_non_null(mem_find(&m, "steps-003.csv"));
    assert_int_equal(count_lines(mem_text(&m, "summary.csv")), 4);
    mem_free(&m);
}

/* Killed right after the attempt began: only its attempt-NNN.live. The
 * next session gives it its row and both files (headers only). */
static void test_killed_at_begin(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&g_flag, 1, &m, NULL, 0);
    hol_session_destroy(s); /* no frame: no attempt yet */
    char row[512];
    snprintf(row, sizeof row,
             "x,,2026-01-01T00:00:00Z,0.1.0,5,lv,%064d,flag,5,15,3.0000,0,8,0.0000,killed\n", 0);
    int h;
    mem_open(&m, "attempt-005.live", 0, &h);
    mem_write(&m, h, row, strlen(row));
    mem_flush(&m, h, 1);
    mem_close(&m, h);
    s = make(&g_flag, 1, &m, NULL, 1);
    assert_int_equal(hol_session_recovered(s), 1);
    hol_session_destroy(s);
    assert_non_null(strstr(mem_text(&m, "summary.csv"), ",5,lv,"));
    assert_string_equal(mem_text(&m, "steps-005.csv"), HOL_SESSION_STEP_COLUMNS "\n");
    assert_string_equal(mem_text(&m, "head-005.csv"), HOL_SESSION_HEAD_COLUMNS "\n");
    assert_null(mem_find(&m, "attempt-005.live"));
    mem_free(&m);
}

/* A torn last row in every append-only log (issue 39, findings 7 and 14):
 * each cut to its whole rows before the next session appends, and the
 * files of the attempt whose summary row was cut removed with it; said in
 * hol_session_repaired. */
static void test_torn_logs_cut(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    for (int k = 0; k < 2; k++) {
        hol_session *s = make(&g_flag, 1, &m, NULL, k);
        assert_string_equal(hol_session_repaired(s), "");
        walk(s, "W", 0, NULL, NULL);
        assert_int_equal(hol_session_finish(s), HOL_OK);
        hol_session_destroy(s);
    }
    assert_non_null(mem_find(&m, "steps-002.csv"));
    mem_stream *sum = mem_find(&m, "summary.csv");
    sum->len -= 20; /* attempt 2's row cut */
    sum->kept = sum->len;
    static const char torn[] = HOL_SESSION_ANSWER_COLUMNS "\nS,P1,1,q,level,a,likert,3,1.0\nS,P1";
    int h;
    mem_open(&m, "answers.csv", 0, &h);
    mem_write(&m, h, torn, sizeof torn - 1);
    mem_flush(&m, h, 1);
    mem_close(&m, h);
    hol_session *s = make(&g_flag, 1, &m, NULL, 1);
    assert_non_null(s);
    const char *said = hol_session_repaired(s);
    assert_non_null(strstr(said, "(summary.csv, answers.csv)"));
    assert_non_null(strstr(said, "steps-002.csv"));
    assert_null(mem_find(&m, "steps-002.csv"));
    assert_null(mem_find(&m, "head-002.csv"));
    assert_null(mem_find(&m, "track-002.csv"));
    assert_non_null(mem_find(&m, "steps-001.csv"));
    assert_int_equal(count_lines(mem_text(&m, "summary.csv")), 2);
    assert_int_equal(count_lines(mem_text(&m, "answers.csv")), 2);
    const char *a = mem_text(&m, "answers.csv");
    assert_int_equal(a[strlen(a) - 1], '\n');
    walk(s, "W", 0, NULL, NULL); /* numbered on past the removed attempt */
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_non_null(mem_find(&m, "steps-003.csv"));
    mem_free(&m);
}

/* A kill between the summary row and the renames: the next session renames
 * and adds no second row. */
static void test_no_double_row(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&g_flag, 1, &m, NULL, 0);
    m.fail_rename = 1; /* the first rename (steps live -> steps) fails */
    int over = 0;
    int c = 1, r = 1;
    double t = 0;
    hol_input in = head_at(t, c + 0.5, r + 0.5);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    for (const char *p = g_walk; *p; p++) {
        c += *p == 'E' ? 1 : *p == 'W' ? -1 : 0;
        r += *p == 'S' ? 1 : *p == 'N' ? -1 : 0;
        in = head_at(t += 0.25, c + 0.5, r + 0.5);
        hol_err e = hol_session_step(s, &in, &over);
        assert_true(e == HOL_OK || e == HOL_EIO);
    }
    assert_int_equal(hol_session_finish(s), HOL_EIO);
    assert_non_null(strstr(hol_session_message(s), "rename"));
    hol_session_destroy(s);
    mem_kill(&m);
    assert_int_equal(count_lines(mem_text(&m, "summary.csv")), 2);
    assert_null(mem_find(&m, "steps-001.csv"));
    s = make(&g_flag, 1, &m, NULL, 1);
    assert_int_equal(hol_session_recovered(s), 1);
    hol_session_destroy(s);
    assert_int_equal(count_lines(mem_text(&m, "summary.csv")), 2);
    assert_non_null(mem_find(&m, "steps-001.csv"));
    assert_non_null(mem_find(&m, "head-001.csv"));
    assert_null(mem_find(&m, "attempt-001.live"));
    mem_free(&m);
}

/* Head rows at k/10 s exactly, interpolated between irregular frames of a
 * head moving east at 0.5 m/s (x = 1.5 + 0.5 t): x, frame_t. */
static void test_head_rows_interpolated(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&g_flag, 1, &m, NULL, 0);
    static const double ts[] = {0, 0.07, 0.31, 0.33, 0.52, 0.9, 1.0, 1.27};
    int over = 0;
    for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++) {
        hol_input in = head_at(ts[i], 1.5 + 0.5 * ts[i], 1.5);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *hd = mem_text(&m, "head-001.csv");
    assert_non_null(hd);
    assert_int_equal(count_lines(hd) - 1, 13); /* 0.0 .. 1.2 */
    const char *p = strchr(hd, '\n') + 1;
    for (int k = 0; k <= 12; k++) {
        double t, ft, x;
        char tail[256];
        assert_int_equal(sscanf(p, "20260101T000000Z-00000001,1,lv,%lf,%lf,%lf,%255s", &t, &ft,
                                &x, tail),
                         4);
        assert_true(t == k / 10.0 || fabs(t - k / 10.0) < 1e-9);
        double later = 0;
        for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++)
            if (ts[i] >= k / 10.0 - 1e-12) {
                later = ts[i];
                break;
            }
        assert_true(fabs(ft - later) < 1e-4);
        assert_true(fabs(x - (1.5 + 0.05 * k)) < 2e-4);
        p = strchr(p, '\n') + 1;
    }
    mem_free(&m);
}

/* Cues drawn, not only in force. */
static void test_visible_cues(void **state)
{
    (void)state;
    hol_app_view v;
    memset(&v, 0, sizeof v);
    v.user = hol_room_start();
    v.map.cues = HOL_CUE_ALL;
    v.map.place = HOL_MINIMAP_HUD;
    assert_int_equal(hol_session_cues_visible(&v), 0); /* no objective left */
    hol_tile near, far;
    assert_int_equal(hol_tile_parse("Nf", -1, &near), HOL_OK);
    assert_int_equal(hol_tile_parse("Nfffff", -1, &far), HOL_OK);
    v.map.nobjectives = 1;
    v.map.objectives[0] = near;
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_HOT_COLD | HOL_CUE_POLES);
    v.map.objectives[0] = far; /* beyond the minimap's 4 tiles: its arrow */
    assert_int_equal(hol_session_cues_visible(&v),
                     HOL_CUE_HOT_COLD | HOL_CUE_POLES | HOL_CUE_ARROW);
    v.map.npath = 3;
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_ALL);
    v.map.place = HOL_MINIMAP_OFF; /* in force, not shown */
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_POLES);
    v.map.cues = HOL_CUE_POLES | HOL_CUE_LANTERN; /* lanterns: lit at dusk and night */
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_POLES);
    v.lighting = HOL_LIGHT_DUSK;
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_POLES | HOL_CUE_LANTERN);
    v.map.cues = HOL_CUE_PATH;
    v.map.place = HOL_MINIMAP_HAND;
    assert_int_equal(hol_session_cues_visible(&v), HOL_CUE_PATH);
    /* in the rows: a level with `cues none` shows none */
    static hol_level none;
    const char *t = "mode flag\nseed 5\nflag Wrf\ncues none\n";
    assert_int_equal(hol_level_make("n", 1, t, strlen(t), &none, NULL), HOL_OK);
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&g_flag, 1, &m, NULL, 0);
    walk(s, "W", 0, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *rows = mem_text(&m, "steps-001.csv");
    if (!strstr(rows, ",15,5\n"))
        fail_msg("%s", rows); /* in force all; drawn hot-cold, poles */
    mem_free(&m);
    mem_init(&m);
    s = make(&none, 1, &m, NULL, 0);
    walk(s, "W", 0, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    rows = mem_text(&m, "steps-001.csv");
    assert_non_null(strstr(rows, ",0,0\n"));
    mem_free(&m);
}

/* Aborted: the attempt in play ends `aborted`, the files are renamed. */
static void test_abort(void **state)
{
    (void)state;
    static mem_sink m, r;
    mem_init(&m);
    mem_init(&r);
    hol_session *s = make(&g_flag, 1, &m, &r, 0);
    walk(s, "WN", 0, NULL, NULL);
    assert_non_null(mem_find(&r, "s.rec.live"));
    assert_int_equal(hol_session_abort(s), HOL_OK);
    assert_int_equal(hol_session_abort(s), HOL_OK); /* once */
    hol_session_destroy(s);
    assert_non_null(strstr(mem_text(&m, "summary.csv"), ",2,8,0.5000,aborted,,,\n"));
    assert_non_null(mem_find(&m, "steps-001.csv"));
    assert_null(mem_find(&r, "s.rec.live"));
    assert_non_null(mem_find(&r, "s.rec"));
    /* a killed session's recording in the way: refused at create */
    mem_make(&r, "s.rec.live");
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = &g_flag;
    d.nlevels = 1;
    d.app.nav = g_nav;
    d.rec = &r.sink;
    d.rec_name = "s.rec";
    snprintf(d.meta.session, sizeof d.meta.session, "x");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EARG);
    assert_non_null(strstr(msg, "did not end"));
    mem_free(&m);
    mem_free(&r);
}

/* The recording reads back to the same levels and metadata, and its input
 * lines replayed through a new session give the same logs, byte for byte. */
static void test_recording_replays(void **state)
{
    (void)state;
    static mem_sink m1, m2, r;
    static hol_input ins[64];
    int nin = 0;
    mem_init(&m1);
    mem_init(&m2);
    mem_init(&r);
    hol_session *s = make(&g_flag, 1, &m1, &r, 0);
    walk(s, "SN", 0, ins, &nin);
    hol_input rs = head_at(1, 1.5, 1.5);
    rs.pressed = HOL_BTN_RESTART;
    int over;
    assert_int_equal(hol_session_step(s, &rs, &over), HOL_OK);
    walk(s, g_walk, 2, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    /* read it back a line at a time */
    const char *rec = mem_text(&r, "s.rec");
    assert_non_null(rec);
    static char copy[1 << 16];
    snprintf(copy, sizeof copy, "%s", rec);
    static hol_level levels[HOL_REC_MAX_LEVELS];
    static hol_rec_reader rd;
    hol_rec_reader_init(&rd, levels);
    char *line = copy, *nl;
    int done = 0;
    while (!done && (nl = strchr(line, '\n'))) {
        *nl = 0;
        assert_int_equal(hol_rec_read_line(&rd, line, strlen(line), &done), HOL_OK);
        if (!done)
            line = nl + 1;
    }
    assert_int_equal(rd.nlevels, 1);
    assert_int_equal(rd.version, 2);
    assert_string_equal(rd.meta.participant, "P1");
    assert_string_equal(levels[0].text, g_flag.text);
    assert_memory_equal(levels[0].sha256, g_flag.sha256, 32);
    /* replay: the same session id and start from the recording */
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = levels;
    d.nlevels = rd.nlevels;
    d.app.nav = g_nav;
    d.log = &m2.sink;
    d.meta = rd.meta;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    for (;;) {
        hol_input in;
        assert_int_equal(hol_input_parse(line, strlen(line), &in, NULL), HOL_OK);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        line += strlen(line) + 1;
        if (!*line)
            break;
        nl = strchr(line, '\n');
        *nl = 0;
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    static const char *const files[] = {"summary.csv", "steps-001.csv", "head-001.csv",
                                        "steps-002.csv", "head-002.csv"};
    for (int i = 0; i < 5; i++) {
        mem_stream *a = mem_find(&m1, files[i]), *b = mem_find(&m2, files[i]);
        assert_non_null(a);
        assert_non_null(b);
        assert_int_equal(a->len, b->len);
        assert_memory_equal(a->data, b->data, a->len);
    }
    assert_non_null(strstr(mem_text(&m1, "summary.csv"), ",restart,,,\n"));
    mem_free(&m1);
    mem_free(&m2);
    mem_free(&r);
}

/* A study's session: the summary's study, condition and position from the
 * levels' labels and the study's name; every level's text in
 * level-HASH.txt; a version 3 recording that reads back to the same labels
 * and replays to the same summary. */
static void test_study_labels(void **state)
{
    (void)state;
    static mem_sink m1, m2, r;
    static hol_level lv[2], back[HOL_REC_MAX_LEVELS];
    mem_init(&m1);
    mem_init(&m2);
    mem_init(&r);
    lv[0] = g_flag;
    const char *t2 = "mode flag\nseed 6\nflag Nf\nminimap hand\n";
    assert_int_equal(hol_level_make("lv2", 3, t2, strlen(t2), &lv[1], NULL), HOL_OK);
    assert_string_equal(lv[1].condition, ""); /* made without labels */
    snprintf(lv[0].condition, sizeof lv[0].condition, "hand");
    lv[0].position = 1;
    snprintf(lv[1].condition, sizeof lv[1].condition, "hud");
    lv[1].position = 2;
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = lv;
    d.nlevels = 2;
    d.app.nav = g_nav;
    d.log = &m1.sink;
    d.rec = &r.sink;
    d.rec_name = "s.rec";
    snprintf(d.meta.session, sizeof d.meta.session, "20260101T000000Z-00000002");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    snprintf(d.meta.participant, sizeof d.meta.participant, "P2");
    snprintf(d.meta.study, sizeof d.meta.study, "s1");
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    double t = walk(s, g_walk, 0, NULL, NULL);
    hol_input in = head_at(t + 0.5, 1.5, 1.5);
    in.pressed = HOL_BTN_CONFIRM;
    int over;
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    assert_int_equal(hol_session_level_index(s), 1);
    walk(s, "N", t + 1, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    static char sum[4096];
    snprintf(sum, sizeof sum, "%s", mem_text(&m1, "summary.csv"));
    assert_non_null(strstr(sum, ",P2,2026-01-01T00:00:00Z,"));
    assert_non_null(strstr(sum, ",1,s1,hand,1,lv,"));
    assert_non_null(strstr(sum, ",2,s1,hud,2,lv2,"));
    for (int i = 0; i < 2; i++) {
        char hex[HOL_SHA256_HEX], name[96];
        hol_sha256_hex(lv[i].sha256, hex);
        snprintf(name, sizeof name, "level-%s.txt", hex);
        assert_string_equal(mem_text(&m1, name), lv[i].text);
        assert_non_null(strstr(sum, hex));
        snprintf(name, sizeof name, "level-%s.txt.live", hex);
        assert_null(mem_find(&m1, name));
    }
    /* the recording: version 3, read back with the labels */
    static char copy[1 << 16];
    snprintf(copy, sizeof copy, "%s", mem_text(&r, "s.rec"));
    assert_true(!strncmp(copy, "holonomy-rec 3\nsession ", 23));
    assert_non_null(strstr(copy, "\nstudy s1\nlevel lv\ncondition hand 1\nL mode flag\n"));
    static hol_rec_reader rd;
    hol_rec_reader_init(&rd, back);
    char *line = copy, *nl;
    int done = 0;
    while (!done && (nl = strchr(line, '\n'))) {
        *nl = 0;
        assert_int_equal(hol_rec_read_line(&rd, line, strlen(line), &done), HOL_OK);
        if (!done)
            line = nl + 1;
    }
    assert_int_equal(rd.version, 3);
    assert_string_equal(rd.meta.study, "s1");
    assert_int_equal(rd.nlevels, 2);
    assert_string_equal(back[1].condition, "hud");
    assert_int_equal(back[1].position, 2);
    assert_string_equal(back[1].text, lv[1].text);
    /* replayed: the same summary */
    d.levels = back;
    d.log = &m2.sink;
    d.rec = NULL;
    d.meta = rd.meta;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    for (;;) {
        assert_int_equal(hol_input_parse(line, strlen(line), &in, NULL), HOL_OK);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        line += strlen(line) + 1;
        if (!*line)
            break;
        *strchr(line, '\n') = 0;
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_string_equal(mem_text(&m2, "summary.csv"), sum);
    mem_free(&m1);
    mem_free(&m2);
    mem_free(&r);
}

/* Every allocation at create (the session's and the app's hooks); none in
 * a thousand frames with logs and a recording. */
/* meta.ask_item: the first level is not played; its questions are asked
 * from item 3 (ssq's second: item 1 is `mine`'s), the rows on session
 * OLD's attempt 7; then level 2 plays as attempt 1; the recording's header
 * carries the ask line and reads back to it. */
static void test_resumed_questions(void **state)
{
    (void)state;
    static mem_sink log, r;
    static hol_level lv[2], back[HOL_REC_MAX_LEVELS];
    mem_init(&log);
    mem_init(&r);
    const char *t = "mode flag\nseed 5\nflag Wrf\n"
                    "question h choice \"Which hand?\" \"left\" \"right\"\n"
                    "ask mine level h\nask ssq condition\n";
    assert_int_equal(hol_level_make("q", 1, t, strlen(t), &lv[0], NULL), HOL_OK);
    lv[1] = g_flag;
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = lv;
    d.nlevels = 2;
    d.app.nav = g_nav;
    d.log = &log.sink;
    d.rec = &r.sink;
    d.rec_name = "s.rec";
    snprintf(d.meta.session, sizeof d.meta.session, "20260102T000000Z-00000002");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-02T00:00:00Z");
    snprintf(d.meta.participant, sizeof d.meta.participant, "P1");
    snprintf(d.meta.ask_session, sizeof d.meta.ask_session, "OLD");
    d.meta.ask_attempt = 7;
    d.meta.ask_item = 18; /* 17 items: none */
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_EARG);
    assert_non_null(strstr(msg, "has no question 18"));
    d.meta.ask_item = 3;
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    assert_string_equal(hol_session_end_name(s), "done");
    int over = 0;
    double tt = 0;
    hol_input in = head_at(tt, 1.5, 1.5);
    assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    const hol_app_view *v = hol_app_get_view(hol_session_app(s));
    assert_int_equal(v->state, HOL_APP_ASK);
    assert_int_equal(v->hud.ask_item, 1);
    for (int k = 1; k < 16; k++) {
        in = head_at(tt += 0.5, 1.5, 1.5);
        in.pressed = HOL_BTN_CONFIRM;
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        assert_int_equal(hol_app_get_events(hol_session_app(s))->answered, 1);
        assert_true(fabs(hol_app_get_events(hol_session_app(s))->answer.time_s - 0.5) < 1e-9);
    }
    assert_int_equal(hol_session_level_index(s), 1); /* the last answer goes on */
    walk(s, g_walk, tt + 0.5, NULL, NULL);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *a = mem_text(&log, "answers.csv");
    assert_non_null(a);
    assert_int_equal(strncmp(a, HOL_SESSION_ANSWER_COLUMNS "\nOLD,P1,7,ssq,condition,fatigue,"
                                "likert,1,0.5000,0,500\n", sizeof HOL_SESSION_ANSWER_COLUMNS + 53),
                     0);
    int rows = 0;
    for (const char *p = a; (p = strchr(p, '\n')); p++)
        rows++;
    assert_int_equal(rows, 16); /* the header and ssq's items 2..16 */
    const char *sum = mem_text(&log, "summary.csv");
    assert_non_null(sum);
    assert_non_null(strstr(sum, ",P1,2026-01-02T00:00:00Z,"));
    assert_null(strstr(sum, ",q,")); /* no attempt of the asked level */
    assert_non_null(strstr(sum, ",1,,,,lv,"));
    /* the recording's header */
    static char copy[1 << 16];
    snprintf(copy, sizeof copy, "%s", mem_text(&r, "s.rec"));
    assert_non_null(strstr(copy, "\nask OLD 7 3\nlevel q\n"));
    static hol_rec_reader rd;
    hol_rec_reader_init(&rd, back);
    int done = 0;
    for (char *line = copy, *nl; !done && (nl = strchr(line, '\n')); line = nl + 1) {
        *nl = 0;
        assert_int_equal(hol_rec_read_line(&rd, line, strlen(line), &done), HOL_OK);
    }
    assert_string_equal(rd.meta.ask_session, "OLD");
    assert_int_equal(rd.meta.ask_attempt, 7);
    assert_int_equal(rd.meta.ask_item, 3);
    /* a bad ask line is refused */
    hol_rec_reader_init(&rd, back);
    const char *bad[] = {"holonomy-rec 4", "session S", "start 2026-01-02T00:00:00Z",
                         "version 1", "ask OLD 0 3"};
    hol_err e = HOL_OK;
    for (int i = 0; i < 5 && !e; i++)
        e = hol_rec_read_line(&rd, bad[i], strlen(bad[i]), &done);
    assert_int_equal(e, HOL_EPARSE);
}

static void test_no_allocation_after_create(void **state)
{
    (void)state;
    static mem_sink m, r;
    mem_init(&m);
    mem_init(&r);
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = &g_flag;
    d.nlevels = 1;
    d.app.nav = g_nav;
    d.app.alloc = count_alloc_hooks();
    d.alloc = count_alloc_hooks();
    d.log = &m.sink;
    d.rec = &r.sink;
    d.rec_name = "a.rec";
    snprintf(d.meta.session, sizeof d.meta.session, "x");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    hol_session *s = NULL;
    char msg[256];
    assert_int_equal(hol_session_create(&d, &s, msg, sizeof msg), HOL_OK);
    long before = count_allocs;
    int over;
    for (int k = 0; k < 1000; k++) {
        hol_input in = head_at(k / 60.0, 1.5 + 0.9 * sin(k / 60.0), 1.5);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    assert_int_equal(count_allocs, before);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    assert_int_equal(count_allocs, count_frees);
    mem_free(&m);
    mem_free(&r);
}

/* The POSIX sink on a temporary folder: the sink contract's calls, a FIFO
 * refused without blocking, the folder made when its parent exists. */
static void test_posix_sink(void **state)
{
    (void)state;
    char dir[] = "/tmp/holonomy-sink-XXXXXX", path[256];
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/logs", dir);
    assert_int_equal(hol_sink_posix_make_dir(path), HOL_OK);
    assert_int_equal(hol_sink_posix_make_dir(path), HOL_OK);
    hol_sink_posix p;
    assert_int_equal(hol_sink_posix_init(&p, path), HOL_OK);
    hol_sink *k = &p.sink;
    int h;
    assert_int_equal(k->open(k->user, "a.txt", 0, &h), HOL_OK);
    assert_int_equal(k->write(k->user, h, "hello\n", 6), HOL_OK);
    assert_int_equal(k->flush(k->user, h, 1), HOL_OK);
    assert_int_equal(k->close(k->user, h), HOL_OK);
    assert_int_equal(k->open(k->user, "a.txt", 1, &h), HOL_OK);
    assert_int_equal(k->write(k->user, h, "more\n", 5), HOL_OK);
    assert_int_equal(k->close(k->user, h), HOL_OK);
    char buf[32];
    size_t got;
    assert_int_equal(k->read(k->user, "a.txt", 6, buf, sizeof buf, &got), HOL_OK);
    assert_int_equal(got, 5);
    assert_memory_equal(buf, "more\n", 5);
    assert_int_equal(k->rename(k->user, "a.txt", "b.txt"), HOL_OK);
    assert_int_equal(k->read(k->user, "a.txt", 0, buf, sizeof buf, &got), HOL_EOPEN);
    assert_int_equal(k->remove(k->user, "b.txt"), HOL_OK);
    assert_int_equal(k->remove(k->user, "b.txt"), HOL_OK);
    char fifo[300];
    snprintf(fifo, sizeof fifo, "%s/f", path);
    assert_int_equal(mkfifo(fifo, 0600), 0);
    assert_int_equal(k->open(k->user, "f", 0, &h), HOL_EOPEN);
    assert_int_equal(k->read(k->user, "f", 0, buf, 1, &got), HOL_EIO);
    assert_non_null(k->why(k->user));
    hol_sink_posix_fini(&p);
    unlink(fifo);
    rmdir(path);
    snprintf(path, sizeof path, "%s/no/such", dir);
    assert_int_equal(hol_sink_posix_make_dir(path), HOL_EOPEN);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_folder_refused_or_appended),
        cmocka_unit_test(test_rows_flushed_each_second),
        cmocka_unit_test(test_killed_attempt_recovered),
        cmocka_unit_test(test_killed_at_begin),
        cmocka_unit_test(test_no_double_row),
        cmocka_unit_test(test_torn_logs_cut),
        cmocka_unit_test(test_head_rows_interpolated),
        cmocka_unit_test(test_visible_cues),
        cmocka_unit_test(test_abort),
        cmocka_unit_test(test_recording_replays),
        cmocka_unit_test(test_study_labels),
        cmocka_unit_test(test_resumed_questions),
        cmocka_unit_test(test_no_allocation_after_create),
        cmocka_unit_test(test_posix_sink),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
