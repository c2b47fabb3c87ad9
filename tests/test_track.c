/* test_track.c - the tracker rows of track-NNN.csv (core/hol_session.h,
 * core/hol_session_track.c) against a sink in memory (the same model as
 * tests/test_session.c: streams keep what was flushed when "killed").
 *
 * Checked: at 10, 45 and 90 Hz over irregular frames the rows are the
 * samples k = 0..K, each once and in order, K counted by brute force
 * (the largest k with k / hz <= the last frame's level time), t printed
 * from k / hz; poses against an independent linear model of a head and
 * hands moving at constant speed; a hand not tracked gives empty fields
 * exactly at the samples nearer a frame that does not track it; a gap of
 * more than 2 s is one row at 90 Hz too, and no frame writes more than
 * 2 * hz + 1 rows; rates outside 10..90 are refused at create; a killed
 * attempt's track file is recovered (renamed, header made when missing)
 * by the next --append session; replaying the same records gives the
 * same bytes.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_input_io.h"
#include "../core/hol_level.h"
#include "../core/hol_nav.h"
#include "../core/hol_session.h"

#include "mem_sink.h" /* a folder in memory */

/* ---- sessions ------------------------------------------------------------------- */

static hol_nav *g_nav;
static hol_level g_flag; /* mode flag, seed 5, flag Wrf: nothing here walks to it */

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

static hol_err make_hz(mem_sink *log, int append, int hz, hol_session **out)
{
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = &g_flag;
    d.nlevels = 1;
    d.app.nav = g_nav;
    d.log = log ? &log->sink : NULL;
    d.append = append;
    d.track_hz = hz;
    snprintf(d.meta.session, sizeof d.meta.session, "20260101T000000Z-00000001");
    snprintf(d.meta.start, sizeof d.meta.start, "2026-01-01T00:00:00Z");
    char msg[256];
    *out = NULL;
    return hol_session_create(&d, out, msg, sizeof msg);
}

static hol_session *make(mem_sink *log, int append, int hz)
{
    hol_session *s = NULL;
    if (make_hz(log, append, hz, &s))
        fail_msg("create at %d Hz", hz);
    return s;
}

/* The model: a head walking east at 0.1 m/s from the middle cell's
 * centre; the left hand 0.3 m west of it and lower; the right hand turning
 * about +y at 0.2 rad/s (quaternion (0, sin(a/2), 0, cos(a/2))). */
static void model(double t, double head[3], double left[3], double right_q[4])
{
    head[0] = 1.5 + 0.1 * t, head[1] = 1.6, head[2] = 1.5;
    left[0] = 1.2 + 0.1 * t, left[1] = 1.0, left[2] = 1.4;
    double a = 0.2 * t;
    right_q[0] = 0, right_q[1] = sin(a / 2), right_q[2] = 0, right_q[3] = cos(a / 2);
}

static hol_input record(double t, uint32_t hands)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    double h[3], l[3], q[4];
    model(t, h, l, q);
    in.time_s = t;
    in.flags = HOL_INPUT_HEAD_VALID | HOL_INPUT_FOCUSED | hands;
    in.device = HOL_DEVICE_XR_TOUCH;
    for (int i = 0; i < 3; i++) {
        in.head.pos[i] = (float)h[i];
        in.hand[0].pos[i] = (float)l[i];
        in.hand[1].pos[i] = (float)(h[i] + (i == 1 ? -0.5 : 0.2));
    }
    in.head.quat[3] = in.hand[0].quat[3] = 1;
    for (int i = 0; i < 4; i++)
        in.hand[1].quat[i] = (float)q[i];
    return in;
}

/* The fields of one CSV line (no quoting in these rows), 28 at most. */
static int split(const char *line, char f[28][32])
{
    int n = 0;
    const char *p = line;
    for (;;) {
        const char *e = p;
        while (*e && *e != ',' && *e != '\n')
            e++;
        assert_true(n < 28 && (size_t)(e - p) < 32);
        memcpy(f[n], p, (size_t)(e - p));
        f[n][e - p] = 0;
        n++;
        if (*e != ',')
            return n;
        p = e + 1;
    }
}

/* The line after the i-th LF of text (0: the first line). */
static const char *line_at(const char *text, int i)
{
    for (; i > 0 && text; i--) {
        text = strchr(text, '\n');
        text = text ? text + 1 : NULL;
    }
    return text;
}

/* Irregular frames (about 72 Hz with jitter, and one on the second's
 * mark) to 3 s: every sample once, in order, against the brute-force count
 * and the model. */
static void check_rate(int hz)
{
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&m, 0, hz);
    int over = 0;
    double t = 0, last = 0;
    for (int i = 0; t < 3.0; i++) {
        t = i == 72 ? 1.0 : i / 72.0 + 0.004 * sin(i * 1.7) * (i > 0);
        hol_input in = record(t, HOL_INPUT_HAND_L_VALID | HOL_INPUT_HAND_R_VALID);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        last = t;
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    long K = 0; /* brute force: the largest k with k / hz <= last */
    while ((double)(K + 1) / hz <= last)
        K++;
    const char *text = mem_text(&m, "track-001.csv");
    assert_non_null(text);
    assert_int_equal(strncmp(text, HOL_SESSION_TRACK_COLUMNS "\n",
                             sizeof HOL_SESSION_TRACK_COLUMNS),
                     0);
    assert_int_equal(count_lines(text) - 1, K + 1);
    for (long k = 0; k <= K; k++) {
        char f[28][32], want[32];
        assert_int_equal(split(line_at(text, (int)k + 1), f), 28);
        assert_int_equal(atol(f[3]), k);
        snprintf(want, sizeof want, "%.4f", (double)k / hz);
        assert_string_equal(f[4], want);
        assert_string_equal(f[6], "xr-touch");
        double ts = (double)k / hz, h[3], l[3], q[4];
        model(ts, h, l, q);
        for (int i = 0; i < 3; i++) {
            assert_true(fabs(atof(f[7 + i]) - h[i]) < 2e-4);
            assert_true(fabs(atof(f[14 + i]) - l[i]) < 2e-4);
        }
        assert_true(fabs(atof(f[13]) - 1) < 1e-5 && fabs(atof(f[20]) - 1) < 1e-5);
        for (int i = 0; i < 4; i++)
            assert_true(fabs(atof(f[24 + i]) - q[i]) < 2e-5);
    }
    mem_free(&m);
}

static void test_rate_10(void **state)
{
    (void)state;
    check_rate(10);
}

static void test_rate_45(void **state)
{
    (void)state;
    check_rate(45);
}

static void test_rate_90(void **state)
{
    (void)state;
    check_rate(90);
}

/* Frames every 0.25 s; the left hand tracked at 0, 0.25 and 1 s only, the
 * right never: at 10 Hz a sample's left fields are empty exactly when its
 * nearer frame does not track it; next to an untracked frame the tracked
 * one's pose is kept as it is. The device is the nearer frame's. */
static void test_hands_valid_invalid(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&m, 0, 0); /* 0: the default, 10 Hz */
    static const int left_ok[5] = {1, 1, 0, 0, 1};
    int over = 0;
    for (int i = 0; i < 5; i++) {
        hol_input in = record(i * 0.25, left_ok[i] ? HOL_INPUT_HAND_L_VALID : 0);
        in.device = i < 2 ? HOL_DEVICE_XR_TOUCH : HOL_DEVICE_WEBXR_HAND;
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *text = mem_text(&m, "track-001.csv");
    assert_int_equal(count_lines(text) - 1, 11);
    for (int k = 0; k <= 10; k++) {
        char f[28][32];
        assert_int_equal(split(line_at(text, k + 1), f), 28);
        /* the frames around sample k / 10 and the nearer one */
        int j = k == 0 ? 0 : (k * 4 - 1) / 10 + 1; /* the frame at or after it */
        double a = k == 0 ? 1 : (k / 10.0 - (j - 1) * 0.25) / 0.25;
        int near = a >= 0.5 ? j : j - 1;
        assert_string_equal(f[6], near < 2 ? "xr-touch" : "webxr-hand");
        for (int i = 14; i < 28; i++)
            if (i >= 21 || !left_ok[near])
                assert_string_equal(f[i], "");
        if (left_ok[near]) {
            double h[3], l[3], q[4];
            int both = left_ok[j] && left_ok[j > 0 ? j - 1 : 0];
            model(both ? k / 10.0 : near * 0.25, h, l, q);
            assert_true(fabs(atof(f[14]) - l[0]) < 2e-4);
        }
        assert_true(f[7][0] != 0); /* the head: always */
    }
    mem_free(&m);
}

/* The largest k with k / hz <= t, counted (from 0, or from a few below
 * t * hz for times beyond a minute). */
static long brute_last(double t, int hz)
{
    long k = t > 60 ? (long)(t * hz) - 3 : 0;
    assert_true((double)k / hz <= t);
    while ((double)(k + 1) / hz <= t)
        k++;
    return k;
}

/* At 90 Hz: 1.875 s interpolated (168 rows in one frame), 2.625 s a single
 * gap row, rows going on after it; exactly 2 s: 180 rows; a jump of 1e9 s
 * one row, rows going on after it. No frame writes more than 2 * 90 + 1
 * rows. */
static void test_gap_90(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = make(&m, 0, 90);
    static const double ts[] = {0, 1.875, 4.5, 4.625, 6.625, 1e9, 1e9 + 0.0625};
    static const int want_rows[] = {1, 168, 1, 11, 180, 1, 5}; /* by hand */
    static const int gap[] = {0, 0, 1, 0, 0, 1, 0};
    int over = 0;
    for (int i = 0; i < 7; i++) {
        hol_input in = record(ts[i] < 10 ? ts[i] : 0, HOL_INPUT_HAND_L_VALID);
        in.time_s = ts[i];
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    const char *text = mem_text(&m, "track-001.csv");
    int n = count_lines(text) - 1, r = 0;
    long next = 0;
    for (int i = 0; i < 7; i++) {
        char ft[32];
        snprintf(ft, sizeof ft, "%.4f", ts[i]);
        long last = brute_last(ts[i], 90);
        int rows = 0;
        for (; r < n; r++, rows++) {
            char f[28][32];
            assert_int_equal(split(line_at(text, r + 1), f), 28);
            if (strcmp(f[5], ft))
                break;
            assert_int_equal(atol(f[3]), next + (gap[i] ? 0 : rows));
            assert_string_equal(f[6], gap[i] ? "gap" : "xr-touch");
            for (int k = 7; gap[i] && k < 28; k++)
                assert_string_equal(f[k], "");
        }
        assert_int_equal(rows, want_rows[i]);
        assert_true(rows <= 2 * 90 + 1);
        assert_int_equal(gap[i] ? 1 : last - next + 1, rows);
        next = last + 1;
    }
    assert_int_equal(r, n);
    mem_free(&m);
}

/* Rates outside 10..90 are refused at create, the ends taken. */
static void test_rate_bounds(void **state)
{
    (void)state;
    static mem_sink m;
    mem_init(&m);
    hol_session *s = NULL;
    assert_int_equal(make_hz(&m, 0, 9, &s), HOL_EARG);
    assert_int_equal(make_hz(&m, 0, 91, &s), HOL_EARG);
    assert_int_equal(make_hz(&m, 0, -10, &s), HOL_EARG);
    assert_null(mem_find(&m, "track-001.csv.live"));
    for (int hz = 10; hz <= 90; hz += 80) {
        mem_free(&m);
        mem_init(&m);
        assert_int_equal(make_hz(&m, 0, hz, &s), HOL_OK);
        hol_input in = record(0, 0);
        int over = 0;
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
        assert_int_equal(hol_session_finish(s), HOL_OK);
        hol_session_destroy(s);
        assert_non_null(mem_find(&m, "track-001.csv"));
    }
    mem_free(&m);
}

/* A kill at 2.5 s (rows flushed each second): the next --append session
 * renames the track file with the rows that reached the "disk", whole; a
 * track live file the kill left unmade gets its header. The same records
 * played again give the same bytes. */
static void play_to(mem_sink *m, int hz, double end)
{
    hol_session *s = make(m, 0, hz);
    int over = 0;
    for (int i = 0; i / 60.0 <= end; i++) {
        hol_input in = record(i / 60.0, HOL_INPUT_HAND_R_VALID);
        assert_int_equal(hol_session_step(s, &in, &over), HOL_OK);
    }
    hol_session_destroy(s); /* no finish: a kill */
    mem_kill(m);
}

static void test_killed_recovered(void **state)
{
    (void)state;
    static mem_sink m, m2;
    mem_init(&m);
    play_to(&m, 90, 2.5);
    const char *live = mem_text(&m, "track-001.csv.live");
    assert_non_null(live);
    int kept = count_lines(live) - 1;
    assert_true(kept >= 2 * 90 && kept <= 2.5 * 90 + 1);
    char *copy = strdup(live);
    hol_session *s = make(&m, 1, 90);
    assert_int_equal(hol_session_recovered(s), 1);
    assert_null(mem_find(&m, "track-001.csv.live"));
    assert_string_equal(mem_text(&m, "track-001.csv"), copy);
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    /* determinism: the same records, the same bytes */
    mem_init(&m2);
    play_to(&m2, 90, 2.5);
    assert_string_equal(mem_text(&m2, "track-001.csv.live"), copy);
    free(copy);
    /* a kill before the track file was made (or a folder of an older build) */
    mem_remove(&m2, "track-001.csv.live");
    s = make(&m2, 1, 90);
    assert_int_equal(hol_session_recovered(s), 1);
    assert_string_equal(mem_text(&m2, "track-001.csv"), HOL_SESSION_TRACK_COLUMNS "\n");
    assert_int_equal(hol_session_finish(s), HOL_OK);
    hol_session_destroy(s);
    mem_free(&m);
    mem_free(&m2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rate_10),
        cmocka_unit_test(test_rate_45),
        cmocka_unit_test(test_rate_90),
        cmocka_unit_test(test_hands_valid_invalid),
        cmocka_unit_test(test_gap_90),
        cmocka_unit_test(test_rate_bounds),
        cmocka_unit_test(test_killed_recovered),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
