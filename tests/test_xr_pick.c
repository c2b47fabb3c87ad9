/* test_xr_pick.c - the reference space and the swapchain format the
 * headset layer picks (platform/openxr/hol_xr_pick.h), without a runtime;
 * the mirrored enum values against openxr.h and GL's. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <openxr/openxr.h>

#include "../platform/shell/hol_xr_pick.h"

static void test_mirrored_values(void **state)
{
    (void)state;
    assert_int_equal(HOL_XR_SPACE_VIEW, XR_REFERENCE_SPACE_TYPE_VIEW);
    assert_int_equal(HOL_XR_SPACE_LOCAL, XR_REFERENCE_SPACE_TYPE_LOCAL);
    assert_int_equal(HOL_XR_SPACE_STAGE, XR_REFERENCE_SPACE_TYPE_STAGE);
    /* GL_RGBA8 and GL_SRGB8_ALPHA8 (glcorearb.h, gl3.h) */
    assert_int_equal(HOL_XR_GL_RGBA8, 0x8058);
    assert_int_equal(HOL_XR_GL_SRGB8_ALPHA8, 0x8C43);
}

/* Issue 19: the LOCAL fallback puts the eye at standing height. */
static void test_space(void **state)
{
    (void)state;
    double y = 99;
    const int both[] = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL,
                        XR_REFERENCE_SPACE_TYPE_STAGE};
    assert_int_equal(hol_xr_pick_space(both, 3, 0, &y), HOL_XR_SPACE_STAGE);
    assert_true(y == 0);
    const int local[] = {XR_REFERENCE_SPACE_TYPE_VIEW, XR_REFERENCE_SPACE_TYPE_LOCAL};
    assert_int_equal(hol_xr_pick_space(local, 2, 0, &y), HOL_XR_SPACE_LOCAL);
    /* LOCAL's origin is the head's start: the room's floor 1.6 m below it,
     * so a head at LOCAL y = 0 stands at room y = 1.6 */
    assert_true(y == -1.6);
    assert_true(0 - y == HOL_XR_EYE_HEIGHT);
    /* LOCAL asked for: LOCAL with its floor offset, though STAGE is there */
    y = 99;
    assert_int_equal(hol_xr_pick_space(both, 3, HOL_XR_SPACE_LOCAL, &y), HOL_XR_SPACE_LOCAL);
    assert_true(y == -1.6);
    const int view[] = {XR_REFERENCE_SPACE_TYPE_VIEW};
    assert_int_equal(hol_xr_pick_space(view, 1, 0, &y), 0);
    assert_int_equal(hol_xr_pick_space(NULL, 0, 0, &y), 0);
}

/* Issue 18: an sRGB swapchain when offered, whatever the runtime's order. */
static void test_format(void **state)
{
    (void)state;
    int srgb = -1;
    const int64_t monado[] = {0x8C43, 0x8058, 0x881A, 0x81A6, 0x88F0};
    assert_int_equal(hol_xr_pick_format(monado, 5, &srgb), 0x8C43);
    assert_int_equal(srgb, 1);
    const int64_t linear_first[] = {0x8058, 0x8C43};
    assert_int_equal(hol_xr_pick_format(linear_first, 2, &srgb), 0x8C43);
    assert_int_equal(srgb, 1);
    const int64_t only_linear[] = {0x881A, 0x8058};
    assert_int_equal(hol_xr_pick_format(only_linear, 2, &srgb), 0x8058);
    assert_int_equal(srgb, 0);
    const int64_t none[] = {0x881A, 0x88F0};
    assert_int_equal(hol_xr_pick_format(none, 2, &srgb), 0);
    assert_int_equal(hol_xr_pick_format(NULL, 0, &srgb), 0);
}

/* The eyes' samples: the runtime's recommendation within its maximum and
 * HOL_XR_MAX_SAMPLES (Monado recommends 1: no multisampled framebuffer;
 * a Quest-like 4 of 4: four, resolved). */
static void test_samples(void **state)
{
    (void)state;
    assert_int_equal(hol_xr_pick_samples(1, 1), 1);
    assert_int_equal(hol_xr_pick_samples(1, 8), 1);
    assert_int_equal(hol_xr_pick_samples(4, 4), 4);
    assert_int_equal(hol_xr_pick_samples(4, 2), 2);
    assert_int_equal(hol_xr_pick_samples(0, 4), 1);
    assert_int_equal(hol_xr_pick_samples(16, 0), HOL_XR_MAX_SAMPLES);
    assert_int_equal(hol_xr_pick_samples(16, 32), HOL_XR_MAX_SAMPLES);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mirrored_values),
        cmocka_unit_test(test_space),
        cmocka_unit_test(test_samples),
        cmocka_unit_test(test_format),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
