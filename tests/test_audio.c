/* test_audio.c - the sound player's hold (platform/audio/hol_audio.h:
 * hol_audio_pause and the feed every platform uses, hol_audio_feed), on
 * OpenAL Soft's loopback device: a beacon sounds; held, every voice stops
 * and the rendered output is silence, and applying a list changes nothing;
 * let go, the next list plays again. Through the feed: an app's beacon
 * (a flag level with the sound cue) plays, is held (silence) and plays
 * again. The WAV's pan (HRTF off): the equal-power law. No loop of a 60 s
 * walk pops in the rendered sound ({4,5}, {4,8}). Skipped where
 * libopenal.so.1 cannot be loaded (the arm64 run under qemu has none).
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

#include "../core/hol_app.h"
#include "../platform/audio/hol_audio.h"
#include "app_fixture.h" /* the group's navigator, make_app */

#define N 4800 /* 0.1 s at 48 kHz */

static int16_t g_pcm[2 * N];

static hol_audio *open_loopback(void)
{
    hol_audio *a = NULL;
    char msg[160];
    if (hol_audio_open(1, 1.0, &a, msg, sizeof msg)) {
        fprintf(stderr, "test_audio: skipped: %s\n", msg);
        return NULL;
    }
    return a;
}

/* the largest sample of 0.1 s rendered now */
static int peak(hol_audio *a)
{
    assert_int_equal(hol_audio_render(a, g_pcm, N), 0);
    int m = 0;
    for (int i = 0; i < 2 * N; i++)
        m = abs(g_pcm[i]) > m ? abs(g_pcm[i]) : m;
    return m;
}

/* a list of one water loop (noise: never silent for 0.1 s) at gain g,
 * azimuth az radians right of ahead */
static void water(hol_sound_list *l, double g, double az)
{
    memset(l, 0, sizeof *l);
    l->n = 1;
    l->src[0].kind = HOL_SND_WATER;
    l->src[0].id = 7;
    l->src[0].gain = g;
    l->src[0].dir[0] = sin(az);
    l->src[0].dir[2] = -cos(az);
}

static void test_pause_stops_and_resumes(void **state)
{
    (void)state;
    hol_audio *a = open_loopback();
    if (!a)
        skip();
    hol_sound_list l;
    water(&l, 1.0, 0); /* ahead */
    hol_audio_apply(a, &l);
    assert_int_equal(hol_audio_active(a), 1);
    assert_true(peak(a) > 100);

    hol_audio_pause(a, 1);
    assert_true(hol_audio_paused(a));
    assert_int_equal(hol_audio_active(a), 0);
    assert_int_equal(peak(a), 0);
    hol_audio_apply(a, &l); /* held: nothing starts */
    assert_int_equal(hol_audio_active(a), 0);
    assert_int_equal(peak(a), 0);
    hol_audio_pause(a, 1); /* idempotent */
    assert_int_equal(peak(a), 0);

    hol_audio_pause(a, 0);
    assert_false(hol_audio_paused(a));
    assert_int_equal(peak(a), 0); /* the loop was released: silent until applied */
    hol_audio_apply(a, &l);
    assert_int_equal(hol_audio_active(a), 1);
    assert_true(peak(a) > 100);
    hol_audio_close(a);
    hol_audio_pause(NULL, 1); /* NULL ok */
    assert_false(hol_audio_paused(NULL));
}

static void test_feed_holds(void **state)
{
    (void)state;
    hol_audio *a = open_loopback();
    if (!a)
        skip();
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.seed = 5;
    L.mode = HOL_APP_FLAG;
    assert_int_equal(hol_tile_resolve("Ef", -1, &L.flag), HOL_OK);
    L.cues = HOL_CUE_SOUND;
    L.sound = HOL_SOUND_CUES;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);

    hol_audio_feed f;
    memset(&f, 0, sizeof f);
    hol_sound_init(&f.snd);
    f.au = a; /* as hol_audio_feed_open leaves it, on the loopback device */
    hol_audio_feed_step(&f, app);
    assert_int_equal(hol_audio_active(a), 1); /* the flag's beacon */
    assert_true(peak(a) > 0);

    hol_audio_feed_hold(&f, 1); /* the focus lost, the activity paused */
    assert_int_equal(hol_audio_active(a), 0);
    hol_audio_feed_step(&f, app);
    hol_audio_feed_step(&f, app);
    assert_int_equal(hol_audio_active(a), 0);
    assert_int_equal(peak(a), 0);

    hol_audio_feed_hold(&f, 0); /* focused again */
    hol_audio_feed_step(&f, app);
    assert_int_equal(hol_audio_active(a), 1);
    assert_true(peak(a) > 0);

    hol_audio_feed_close(&f);
    assert_null(f.au);
    hol_audio_feed_step(&f, app); /* silent feed: nothing */
    hol_audio_feed_hold(&f, 1);
    assert_int_equal(f.held, 1); /* remembered for a later open */
    hol_app_destroy(app);
}

/* The WAV's pan with HRTF off (the loopback device) no harder than the
 * equal-power law (issue 38): a source at azimuth a (right of ahead)
 * gives the right ear sin^2(pi/4 + a/2) of the power, within 0.01, and
 * the total power does not change with a (within 2 %). */
static void test_pan_equal_power(void **state)
{
    (void)state;
    double total0 = 0;
    for (int az = 0; az <= 90; az += 15) {
        hol_audio *a = open_loopback();
        if (!a)
            skip();
        hol_sound_list l;
        double t = az * 3.14159265358979 / 180;
        water(&l, 0.5, t);
        hol_audio_apply(a, &l);
        assert_int_equal(hol_audio_render(a, g_pcm, N), 0); /* settle */
        assert_int_equal(hol_audio_render(a, g_pcm, N), 0);
        double L = 0, R = 0;
        for (int i = 0; i < N; i++) {
            L += (double)g_pcm[2 * i] * g_pcm[2 * i];
            R += (double)g_pcm[2 * i + 1] * g_pcm[2 * i + 1];
        }
        double want = pow(sin(3.14159265358979 / 4 + t / 2), 2), got = R / (L + R);
        if (fabs(got - want) > 0.01)
            print_message("azimuth %d: right share %.4f, equal power %.4f\n", az, got, want);
        assert_true(fabs(got - want) <= 0.01);
        if (az == 0)
            total0 = L + R;
        assert_true(fabs((L + R) / total0 - 1) < 0.02);
        hol_audio_close(a);
    }
}

/* The 60 s walk of tests/test_sound.c (90 Hz, `sound all`, the head
 * swaying through the room, crossing cells, turning; the flag far) in
 * {4,q}: each frame's loops, into lists[0..WALK). */
#define WALK 5400
static void walk_lists(int q, hol_sound_list *lists)
{
    hol_app *app = make_app();
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.seed = 5;
    L.mode = HOL_APP_FLAG;
    L.tiling_q = q;
    assert_int_equal(hol_tile_resolve_q(q, "Nrrf", -1, &L.flag), HOL_OK);
    L.cues = HOL_CUE_POLES;
    L.sound = HOL_SOUND_ALL;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    static hol_sound snd;
    hol_sound_init(&snd);
    for (int f = 0; f < WALK; f++) {
        double t = f / 90.0, yaw = 40 * sin(t * 0.2) * M_PI / 360;
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = t;
        in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
        in.head.pos[0] = (float)(1.5 + 1.2 * sin(t * 0.71));
        in.head.pos[1] = 1.6f;
        in.head.pos[2] = (float)(1.5 + 1.2 * sin(t * 0.53));
        in.head.quat[1] = (float)sin(yaw);
        in.head.quat[3] = (float)cos(yaw);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        hol_sound_update(&snd, hol_app_get_view(app), hol_app_get_events(app), hol_app_world(app),
                         &lists[f]);
        lists[f].nshots = 0; /* the loops only */
    }
    hol_app_destroy(app);
}

/* Loops that pop, counted on the rendered sound: each loop of the walk
 * rendered alone through the player on the loopback device (its gain and
 * direction frame by frame, 533 samples a frame); a pop is a loop whose
 * first frame after silence, or last frame before it, peaks above
 * -50 dBFS (104 of 32767). A lower bound (a bird between chirps is silent
 * at any gain), so none must be found. */
static int wav_pops(hol_audio *a, const hol_sound_list *lists, double *out_loudest)
{
    static uint32_t ids[1024];
    static int16_t pcm[2 * 533];
    int nids = 0, pops = 0;
    for (int f = 0; f < WALK; f++)
        for (int i = 0; i < lists[f].n; i++) {
            int k = 0;
            while (k < nids && ids[k] != lists[f].src[i].id)
                k++;
            if (k == nids && nids < 1024)
                ids[nids++] = lists[f].src[i].id;
        }
    *out_loudest = 0;
    for (int k = 0; k < nids; k++) {
        int was = 0, last_peak = 0;
        for (int f = 0; f < WALK; f++) {
            hol_sound_list one;
            memset(&one, 0, sizeof one);
            for (int i = 0; i < lists[f].n; i++)
                if (lists[f].src[i].id == ids[k])
                    one.src[one.n++] = lists[f].src[i];
            hol_audio_apply(a, &one);
            assert_int_equal(hol_audio_render(a, pcm, 533), 0);
            int peak = 0;
            for (int i = 0; i < 2 * 533; i++)
                peak = abs(pcm[i]) > peak ? abs(pcm[i]) : peak;
            int jump = (one.n && !was && f > 0) ? peak : (!one.n && was) ? last_peak : 0;
            if (jump > 104) {
                pops++;
                *out_loudest = jump / 32767.0 > *out_loudest ? jump / 32767.0 : *out_loudest;
            }
            was = one.n > 0, last_peak = peak;
        }
    }
    return pops;
}

/* Sounds by true distance (issue 38): in a 60 s walk no loop appears or
 * vanishes above -50 dBFS in the rendered sound, in {4,5} and {4,8}. */
static void test_no_pops_in_the_wav(void **state)
{
    (void)state;
    hol_audio *a = open_loopback();
    if (!a)
        skip();
    hol_sound_list *lists = malloc(WALK * sizeof *lists);
    assert_non_null(lists);
    const int qs[] = {5, 8};
    for (int i = 0; i < 2; i++) {
        walk_lists(qs[i], lists);
        double loud;
        int pops = wav_pops(a, lists, &loud);
        if (pops)
            print_message("{4,%d}: %d loops pop in the WAV, the loudest %.4f\n", qs[i], pops, loud);
        assert_int_equal(pops, 0);
    }
    free(lists);
    hol_audio_close(a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pause_stops_and_resumes),
        cmocka_unit_test(test_feed_holds),
        cmocka_unit_test(test_pan_equal_power),
        cmocka_unit_test(test_no_pops_in_the_wav),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
