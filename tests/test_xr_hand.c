/* test_xr_hand.c - an OpenXR hand (XR_EXT_hand_tracking's 26 joints) as
 * the record's 25 (platform/shell/hol_xr_hand.h), without a runtime: the
 * joints' order (the palm dropped, WebXR's names), room coordinates by
 * the calibration, radii, and a hand half located or not finite is no
 * hand. A palm-up hand converted is palm up for the hands-only recentre
 * (core/hol_body.h), in the default placement and after a recentre. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_body.h"
#include "../platform/shell/hol_xr_hand.h"

/* A hand as OpenXR gives it: the wrist at w, fingers along stage -z, the
 * thumb's side towards +x * side (palm down for the right hand at side
 * -1, for the left at +1; the other side turns it up). Joint 0 the palm. */
static void xr_hand(const float w[3], float side, float pos[26][3], float radius[26],
                    unsigned flags[26])
{
    memset(pos, 0, 26 * sizeof pos[0]);
    pos[0][0] = w[0];
    pos[0][1] = w[1];
    pos[0][2] = w[2] - 0.05f; /* the palm */
    pos[1][0] = w[0];
    pos[1][1] = w[1];
    pos[1][2] = w[2];
    for (int j = 0; j < 4; j++) { /* thumb: 2..5 */
        pos[2 + j][0] = w[0] + side * (0.03f + 0.01f * (float)j);
        pos[2 + j][1] = w[1];
        pos[2 + j][2] = w[2] - 0.02f - 0.015f * (float)j;
    }
    for (int f = 0; f < 4; f++) /* index .. little: 6.., 5 each */
        for (int j = 0; j < 5; j++) {
            float *p = pos[6 + 5 * f + j];
            p[0] = w[0] + side * (0.02f - 0.017f * (float)f);
            p[1] = w[1];
            p[2] = w[2] - 0.05f - 0.025f * (float)j;
        }
    for (int i = 0; i < 26; i++) {
        radius[i] = 0.005f + 0.0001f * (float)i;
        flags[i] = 0xfu; /* position and orientation valid and tracked */
    }
}

static void test_order_and_room(void **state)
{
    (void)state;
    float pos[26][3], radius[26], w[3] = {0.2f, 1.3f, -0.4f};
    unsigned flags[26];
    xr_hand(w, -1, pos, radius, flags);
    hol_xr_calib c;
    memset(&c, 0, sizeof c); /* the default: room = stage + (1.5, 0, 1.5) */
    hol_hand_joints j;
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 1);
    assert_int_equal(j.tracked, 1);
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        assert_true(fabs(j.pos[i][0] - (pos[i + 1][0] + 1.5)) < 1e-6);
        assert_true(fabs(j.pos[i][1] - pos[i + 1][1]) < 1e-6);
        assert_true(fabs(j.pos[i][2] - (pos[i + 1][2] + 1.5)) < 1e-6);
        assert_true(j.radius[i] == radius[i + 1]);
    }
    /* the names the app reads: OpenXR's wrist 1, thumb tip 5, index
     * metacarpal 6, index tip 10, little metacarpal 21 */
    static const int named[][2] = {{HOL_JOINT_WRIST, 1}, {HOL_JOINT_THUMB_METACARPAL, 2},
                                   {HOL_JOINT_THUMB_TIP, 5}, {HOL_JOINT_INDEX_METACARPAL, 6},
                                   {HOL_JOINT_INDEX_TIP, 10}, {HOL_JOINT_PINKY_METACARPAL, 21}};
    for (size_t n = 0; n < sizeof named / sizeof named[0]; n++)
        assert_true(fabs(j.pos[named[n][0]][2] - (pos[named[n][1]][2] + 1.5)) < 1e-6 &&
                    fabs(j.pos[named[n][0]][0] - (pos[named[n][1]][0] + 1.5)) < 1e-6);
    /* a recentred room: each joint is hol_xr_to_room of its OpenXR joint */
    static const float head[3] = {0.4f, 1.6f, -0.3f}, turned[4] = {0, 0.38268343f, 0, 0.92387953f};
    hol_xr_recentre(&c, head, turned);
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 1);
    static const float one[4] = {0, 0, 0, 1};
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        hol_pose p;
        hol_xr_to_room(&c, pos[i + 1], one, &p);
        for (int k = 0; k < 3; k++)
            assert_true(j.pos[i][k] == p.pos[k]);
    }
}

static void test_no_hand_unless_whole(void **state)
{
    (void)state;
    float pos[26][3], radius[26], w[3] = {-0.2f, 1.3f, -0.4f};
    unsigned flags[26];
    xr_hand(w, 1, pos, radius, flags);
    hol_xr_calib c;
    memset(&c, 0, sizeof c);
    hol_hand_joints j, zero;
    memset(&zero, 0, sizeof zero);
    assert_int_equal(hol_xr_hand_joints(&c, 0, pos, radius, flags, &j), 0); /* not active */
    assert_memory_equal(&j, &zero, sizeof j);
    flags[0] = 0; /* the palm is not read */
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 1);
    flags[25] = 0x1u; /* the little tip's position not valid */
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 0);
    assert_memory_equal(&j, &zero, sizeof j);
    flags[25] = 0xfu;
    pos[13][1] = NAN;
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 0);
    assert_memory_equal(&j, &zero, sizeof j);
    pos[13][1] = 2e4f;
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 0);
    pos[13][1] = 1.3f;
    radius[3] = 0; /* no radius, or a wrong one: 0 (the renderer's default) */
    radius[4] = 2;
    radius[5] = NAN;
    assert_int_equal(hol_xr_hand_joints(&c, 1, pos, radius, flags, &j), 1);
    assert_true(j.radius[2] == 0 && j.radius[3] == 0 && j.radius[4] == 0);
}

/* Palms down, then up (the thumbs' sides swapped), both open: the
 * gesture's test holds in the room, also with the room turned. */
static void test_palms_up_in_the_room(void **state)
{
    (void)state;
    float pos[2][26][3], radius[26];
    unsigned flags[26];
    static const float wl[3] = {-0.2f, 1.3f, -0.4f}, wr[3] = {0.2f, 1.3f, -0.4f};
    static const float head[3] = {0.1f, 1.6f, 0.2f}, turned[4] = {0, 0.7071068f, 0, 0.7071068f};
    for (int recentred = 0; recentred < 2; recentred++)
        for (int up = 0; up < 2; up++) {
            hol_xr_calib c;
            memset(&c, 0, sizeof c);
            if (recentred)
                hol_xr_recentre(&c, head, turned);
            float s = up ? -1.0f : 1.0f;
            xr_hand(wl, s, pos[0], radius, flags);
            xr_hand(wr, -s, pos[1], radius, flags);
            hol_hand_joints j[2];
            for (int h = 0; h < 2; h++)
                assert_int_equal(hol_xr_hand_joints(&c, 1, pos[h], radius, flags, &j[h]), 1);
            assert_int_equal(hol_gesture_palm_up(&j[0], HOL_HAND_LEFT), up);
            assert_int_equal(hol_gesture_palm_up(&j[1], HOL_HAND_RIGHT), up);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_order_and_room),
        cmocka_unit_test(test_no_hand_unless_whole),
        cmocka_unit_test(test_palms_up_in_the_room),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
