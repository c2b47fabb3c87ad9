/* test_input_io.c - input record lines (core/hol_input_io.h): random records
 * round-trip bit for bit through the canonical line; hand-written script
 * lines; bad lines are refused with the offending field's offset.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_input_io.h"

static uint64_t rng_next(uint64_t *s)
{
    *s += UINT64_C(0x9E3779B97F4A7C15);
    uint64_t z = *s;
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

/* A float from random bits, kept finite and (for axes) in [-1, 1]. */
static float rnd_float(uint64_t *s, int axis)
{
    uint32_t b = (uint32_t)rng_next(s);
    float f;
    memcpy(&f, &b, sizeof f);
    if (!isfinite(f))
        f = 0;
    if (axis && !(f >= -1 && f <= 1))
        f = (float)((double)(b % 2001) / 1000.0 - 1.0);
    if (rng_next(s) % 4 == 0)
        f = 0; /* zero fields are left out */
    return f;
}

static void test_round_trip(void **state)
{
    (void)state;
    uint64_t s = 3;
    char line[HOL_INPUT_LINE_MAX + 1];
    size_t longest = 0;
    for (int k = 0; k < 20000; k++) {
        hol_input in, out;
        memset(&in, 0, sizeof in);
        memset(&out, 0xff, sizeof out);
        uint64_t tb = rng_next(&s) >> 2; /* positive doubles */
        memcpy(&in.time_s, &tb, sizeof tb);
        if (!isfinite(in.time_s))
            in.time_s = 1.25;
        in.flags = (uint32_t)rng_next(&s) & HOL_INPUT_FLAGS_ALL;
        in.buttons = (uint32_t)rng_next(&s) & HOL_BTN_ALL;
        in.pressed = (uint32_t)rng_next(&s) & HOL_BTN_ALL;
        in.device = (uint32_t)(rng_next(&s) % HOL_DEVICE_COUNT);
        in.snap_yaw_deg = rng_next(&s) % 3 ? 0.0f : (float)(rng_next(&s) % 360000) / 1000.0f;
        for (int i = 0; i < 2; i++) {
            in.move[i] = rnd_float(&s, 1);
            in.turn[i] = rnd_float(&s, 1);
        }
        hol_pose *p[3] = {&in.head, &in.hand[0], &in.hand[1]};
        for (int j = 0; j < 3; j++) {
            if (rng_next(&s) % 3 == 0)
                continue;
            for (int i = 0; i < 3; i++)
                p[j]->pos[i] = rnd_float(&s, 0);
            for (int i = 0; i < 4; i++)
                p[j]->quat[i] = rnd_float(&s, 0);
        }
        size_t n = hol_input_format(&in, line, sizeof line);
        assert_true(n > 0);
        if (n > longest)
            longest = n;
        assert_int_equal(hol_input_parse(line, n, &out, NULL), HOL_OK);
        assert_memory_equal(&in.time_s, &out.time_s, sizeof in.time_s);
        assert_int_equal(in.flags, out.flags);
        assert_int_equal(in.buttons, out.buttons);
        assert_int_equal(in.pressed, out.pressed);
        assert_int_equal(in.device, out.device);
        assert_memory_equal(&in.snap_yaw_deg, &out.snap_yaw_deg, sizeof in.snap_yaw_deg);
        assert_memory_equal(&in.head, &out.head, sizeof in.head);
        assert_memory_equal(in.hand, out.hand, sizeof in.hand);
        assert_memory_equal(in.move, out.move, sizeof in.move);
        assert_memory_equal(in.turn, out.turn, sizeof in.turn);
    }
    assert_true(longest <= HOL_INPUT_LINE_MAX);
    /* the worst case: every field at its longest */
    hol_input w;
    memset(&w, 0, sizeof w);
    w.time_s = -0x1.fffffffffffffp+1023 * -1;
    w.flags = HOL_INPUT_FLAGS_ALL;
    w.buttons = w.pressed = HOL_BTN_ALL;
    w.device = HOL_DEVICE_XR_SIMPLE; /* the longest name */
    w.snap_yaw_deg = 1.17549435e-38f;
    for (int i = 0; i < 2; i++)
        w.move[i] = w.turn[i] = -0.123456791f;
    hol_pose *p[3] = {&w.head, &w.hand[0], &w.hand[1]};
    for (int j = 0; j < 3; j++) {
        for (int i = 0; i < 3; i++)
            p[j]->pos[i] = -1.17549435e-38f;
        for (int i = 0; i < 4; i++)
            p[j]->quat[i] = -1.17549435e-38f;
    }
    assert_true(hol_input_format(&w, line, sizeof line) > 0);
}

static void test_script_lines(void **state)
{
    (void)state;
    hol_input in;
    const char *l = "0.5 m=0,1 f=8";
    assert_int_equal(hol_input_parse(l, strlen(l), &in, NULL), HOL_OK);
    assert_true(in.time_s == 0.5 && in.flags == HOL_INPUT_FOCUSED && in.move[1] == 1.0f &&
                in.move[0] == 0 && in.buttons == 0 && in.head.quat[3] == 0);
    char line[HOL_INPUT_LINE_MAX + 1];
    assert_int_equal(hol_input_format(&in, line, sizeof line), strlen("0.5 f=8 m=0,1"));
    assert_string_equal(line, "0.5 f=8 m=0,1");
    l = "2 b=41 h=1.5,1.6,1.5,0,0,0,1";
    assert_int_equal(hol_input_parse(l, strlen(l), &in, NULL), HOL_OK);
    assert_true(in.buttons == (HOL_BTN_CONFIRM | HOL_BTN_QUIT) && in.head.pos[1] == 1.6f &&
                in.head.quat[3] == 1.0f);
    /* an invalid record is not formatted */
    in.move[0] = 2;
    assert_int_equal(hol_input_format(&in, line, sizeof line), 0);
    /* version 2: pressed buttons, a snap turn, the device */
    l = "1.5 d=gamepad p=1 f=48 y=90";
    assert_int_equal(hol_input_parse(l, strlen(l), &in, NULL), HOL_OK);
    assert_true(in.pressed == HOL_BTN_CONFIRM && in.buttons == 0 &&
                in.device == HOL_DEVICE_GAMEPAD && in.snap_yaw_deg == 90.0f &&
                in.flags == (HOL_INPUT_FOCUSED | HOL_INPUT_SNAP_YAW));
    assert_true(hol_input_format(&in, line, sizeof line) > 0);
    assert_string_equal(line, "1.5 f=48 p=1 y=90 d=gamepad");
    static const char *const names[HOL_DEVICE_COUNT] = {
        "", "keyboard", "gamepad", "xr-simple", "xr-touch", "xr-vive", "xr-index", "xr-wmr", "xr",
        "webxr-touch", "webxr-hand", "xr-hand", "touchscreen"};
    for (uint32_t d = 0; d < HOL_DEVICE_COUNT; d++)
        assert_string_equal(hol_input_device_name(d), names[d]);
    assert_null(hol_input_device_name(HOL_DEVICE_COUNT));
}

/* Lines written before version 2 (no p, y or d) read as they did: the
 * same record, nothing pressed, no device, no snap. */
static void test_version1_lines(void **state)
{
    (void)state;
    static const char *const v1[] = {
        "0 f=8 m=0,1",
        "0.016666666666666666 f=8 m=0,1 t=0.5,0",
        "2 f=9 b=41 h=1.5,1.75,1.5,0,0,0,1 l=1,1,1,0,0,0,1 r=2,1,2,0,0,0,1",
        "3.25 f=18 b=7f",
    };
    for (size_t i = 0; i < sizeof v1 / sizeof v1[0]; i++) {
        hol_input in;
        memset(&in, 0x55, sizeof in);
        assert_int_equal(hol_input_parse(v1[i], strlen(v1[i]), &in, NULL), HOL_OK);
        assert_int_equal(in.pressed, 0);
        assert_int_equal(in.device, HOL_DEVICE_NONE);
        assert_true(in.snap_yaw_deg == 0.0f && !(in.flags & HOL_INPUT_SNAP_YAW));
        char line[HOL_INPUT_LINE_MAX + 1];
        assert_true(hol_input_format(&in, line, sizeof line) > 0);
        assert_string_equal(line, v1[i]);
    }
}

static void test_bad_lines(void **state)
{
    (void)state;
    static const struct {
        const char *line;
        size_t bad;
    } cases[] = {
        {"", 0},         {"x", 0},           {"-1", 0},          {"nan", 0},
        {"inf", 0},      {"0x10", 0},        {" 1", 0},          {"1 ", 2},
        {"1  f=8", 2},   {"1 f=8 f=8", 6},   {"1 q=1", 2},       {"1 f=", 2},
        {"1 f=g", 2},    {"1 f=2000", 0},    {"1 b=1000", 0},    {"1 m=0", 2},
        {"1 m=0,1,2", 2}, {"1 m=2,0", 0},    {"1 m=0,nan", 2},   {"1 h=1,2,3", 2},
        {"1 t=1e99,0", 2}, {"1 f=123456789", 2}, {"1 m=,1", 2},
        {"1 f=2880", 0}, {"1 f=3fff", 0},     {"1 p=1000", 0},    {"1 p=", 2},
        {"1 p=1 p=1", 6}, {"1 d=mouse", 2},  {"1 d=", 2},        {"1 d=Keyboard", 2},
        {"1 y=360", 0},  {"1 y=-1", 0},      {"1 y=1,2", 2},     {"1 y=nan", 2},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        hol_input in;
        memset(&in, 0x33, sizeof in);
        size_t bad = 999;
        hol_err e = hol_input_parse(cases[i].line, strlen(cases[i].line), &in, &bad);
        if (e != HOL_EPARSE || bad != cases[i].bad)
            fail_msg("line '%s': err %d offset %zu, want offset %zu", cases[i].line, (int)e,
                     bad, cases[i].bad);
        unsigned char *b = (unsigned char *)&in;
        for (size_t k = 0; k < sizeof in; k++)
            assert_int_equal(b[k], 0x33);
    }
    char nul[] = "1 f=8";
    nul[1] = 0;
    hol_input in;
    assert_int_equal(hol_input_parse(nul, 5, &in, NULL), HOL_EPARSE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_script_lines),
        cmocka_unit_test(test_bad_lines),
        cmocka_unit_test(test_version1_lines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
