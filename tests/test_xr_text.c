/* test_xr_text.c - OpenXR results in words (platform/openxr/hol_xr_text.h),
 * without a runtime. The model: openxr.h's own list of results
 * (openxr_reflection.h's XR_LIST_ENUM_XrResult): every core result has its
 * name and words; the mirrored codes equal openxr.h's. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#include <openxr/openxr.h>
#include <openxr/openxr_reflection.h>

#include "../platform/openxr/hol_xr_text.h"

typedef struct spec_result {
    const char *name;
    int code;
} spec_result;

#define SPEC_RESULT(name, value) {#name, value},
static const spec_result spec[] = {XR_LIST_ENUM_XrResult(SPEC_RESULT)};
#define NSPEC (sizeof spec / sizeof spec[0])

/* OpenXR 1.0's core results lie in -100..100; extensions' far beyond */
static int core(int code)
{
    return code > -100 && code < 100;
}

static void test_every_core_result_named(void **state)
{
    (void)state;
    int ncore = 0;
    for (size_t i = 0; i < NSPEC; i++) {
        if (!core(spec[i].code))
            continue;
        ncore++;
        const char *n = hol_xr_result_name(spec[i].code);
        if (!n)
            fail_msg("%s (%d) has no name", spec[i].name, spec[i].code);
        assert_string_equal(n, spec[i].name);
        const char *w = hol_xr_result_words(spec[i].code);
        assert_true(strlen(w) > 8);
        assert_null(strchr(w, '?'));
        assert_null(strstr(w, "XR_"));
    }
    assert_true(ncore >= 50);
    /* an extension's code: no name, still words */
    assert_null(hol_xr_result_name(XR_ERROR_ANDROID_THREAD_SETTINGS_FAILURE_KHR));
    assert_string_equal(hol_xr_result_words(XR_ERROR_ANDROID_THREAD_SETTINGS_FAILURE_KHR),
                        "an OpenXR error");
}

static void test_mirrored_codes(void **state)
{
    (void)state;
    assert_int_equal(HOL_XR_SUCCESS, XR_SUCCESS);
    assert_int_equal(HOL_XR_SPACE_BOUNDS_UNAVAILABLE, XR_SPACE_BOUNDS_UNAVAILABLE);
    assert_int_equal(HOL_XR_ERROR_RUNTIME_FAILURE, XR_ERROR_RUNTIME_FAILURE);
    assert_int_equal(HOL_XR_ERROR_INSTANCE_LOST, XR_ERROR_INSTANCE_LOST);
    assert_int_equal(HOL_XR_ERROR_SESSION_LOST, XR_ERROR_SESSION_LOST);
    assert_int_equal(HOL_XR_ERROR_FORM_FACTOR_UNAVAILABLE, XR_ERROR_FORM_FACTOR_UNAVAILABLE);
    assert_int_equal(HOL_XR_ERROR_RUNTIME_UNAVAILABLE, XR_ERROR_RUNTIME_UNAVAILABLE);
}

static void message(int code, int android, char *out, size_t cap)
{
    hol_xr_message("start the OpenXR instance", code, android, out, cap);
}

/* Issue 18/19: the service down says so and how to start it; never "? (-2)". */
static void test_the_service_down_in_words(void **state)
{
    (void)state;
    char m[512];
    static const int down[] = {XR_ERROR_RUNTIME_FAILURE, XR_ERROR_RUNTIME_UNAVAILABLE,
                               XR_ERROR_FORM_FACTOR_UNAVAILABLE};
    for (size_t i = 0; i < sizeof down / sizeof down[0]; i++) {
        message(down[i], 0, m, sizeof m);
        assert_non_null(strstr(m, "cannot start the OpenXR instance: "));
        assert_non_null(strstr(m, "service"));
        assert_non_null(strstr(m, "monado-service"));
        assert_non_null(strstr(m, hol_xr_result_name(down[i])));
        assert_null(strchr(m, '?'));
        assert_null(strstr(m, "(-"));
        assert_null(strchr(m, '\n'));
        message(down[i], 1, m, sizeof m);
        assert_null(strstr(m, "monado")); /* on the headset: its own remedy */
        assert_non_null(strstr(m, "Holonomy"));
    }
    message(XR_ERROR_RUNTIME_FAILURE, 0, m, sizeof m);
    assert_non_null(strstr(m, "not running"));
    message(XR_ERROR_INSTANCE_LOST, 0, m, sizeof m);
    assert_non_null(strstr(m, "went away"));
    message(XR_ERROR_SESSION_LOST, 0, m, sizeof m);
    assert_non_null(strstr(m, "reconnect the headset"));
    /* an unknown code: its number, no "?" */
    message(-1000999999, 0, m, sizeof m);
    assert_non_null(strstr(m, "an OpenXR error (code -1000999999)"));
    /* cut to cap, terminated */
    message(XR_ERROR_RUNTIME_FAILURE, 0, m, 12);
    assert_int_equal(strlen(m), 11);
    assert_true(hol_xr_result_is_loss(XR_ERROR_SESSION_LOST));
    assert_true(hol_xr_result_is_loss(XR_ERROR_INSTANCE_LOST));
    assert_false(hol_xr_result_is_loss(XR_ERROR_RUNTIME_FAILURE));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_core_result_named),
        cmocka_unit_test(test_mirrored_codes),
        cmocka_unit_test(test_the_service_down_in_words),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
