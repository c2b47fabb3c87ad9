/* hol_xr_text.c - OpenXR results in words (see hol_xr_text.h). */
#include "hol_xr_text.h"

#include <stdio.h>

typedef struct hol__result {
    int code;
    const char *name, *words;
} hol__result;

/* OpenXR 1.0's core results (openxr.h, enum XrResult), in its order. */
static const hol__result hol__results[] = {
    {0, "XR_SUCCESS", "the call succeeded"},
    {1, "XR_TIMEOUT_EXPIRED", "the runtime's wait timed out"},
    {3, "XR_SESSION_LOSS_PENDING", "the session is about to be lost"},
    {4, "XR_EVENT_UNAVAILABLE", "no event was waiting"},
    {7, "XR_SPACE_BOUNDS_UNAVAILABLE", "the runtime knows no bounds for the play area"},
    {8, "XR_SESSION_NOT_FOCUSED", "the session does not have the input focus"},
    {9, "XR_FRAME_DISCARDED", "the runtime discarded the frame"},
    {-1, "XR_ERROR_VALIDATION_FAILURE", "the runtime refused a request as invalid"},
    {-2, "XR_ERROR_RUNTIME_FAILURE", "the OpenXR runtime failed"},
    {-3, "XR_ERROR_OUT_OF_MEMORY", "the runtime ran out of memory"},
    {-4, "XR_ERROR_API_VERSION_UNSUPPORTED", "the runtime does not support OpenXR 1.0"},
    {-6, "XR_ERROR_INITIALIZATION_FAILED", "the runtime could not initialise"},
    {-7, "XR_ERROR_FUNCTION_UNSUPPORTED", "the runtime lacks a function the app needs"},
    {-8, "XR_ERROR_FEATURE_UNSUPPORTED", "the runtime lacks a feature the app needs"},
    {-9, "XR_ERROR_EXTENSION_NOT_PRESENT",
     "the runtime lacks an extension the app needs (OpenGL or OpenGL ES binding)"},
    {-10, "XR_ERROR_LIMIT_REACHED", "the runtime reached one of its limits"},
    {-11, "XR_ERROR_SIZE_INSUFFICIENT", "a buffer given to the runtime was too small"},
    {-12, "XR_ERROR_HANDLE_INVALID", "the runtime was given a handle it does not know"},
    {-13, "XR_ERROR_INSTANCE_LOST",
     "the OpenXR runtime went away (its service stopped or crashed)"},
    {-14, "XR_ERROR_SESSION_RUNNING", "the session is already running"},
    {-16, "XR_ERROR_SESSION_NOT_RUNNING", "the session is not running"},
    {-17, "XR_ERROR_SESSION_LOST",
     "the headset session was lost (the headset was disconnected or the runtime failed)"},
    {-18, "XR_ERROR_SYSTEM_INVALID", "the headset the runtime offered is no longer valid"},
    {-19, "XR_ERROR_PATH_INVALID", "the runtime was given an unknown path"},
    {-20, "XR_ERROR_PATH_COUNT_EXCEEDED", "the runtime has no room for more paths"},
    {-21, "XR_ERROR_PATH_FORMAT_INVALID", "the runtime was given a malformed path"},
    {-22, "XR_ERROR_PATH_UNSUPPORTED",
     "the runtime does not support a controller input the app binds"},
    {-23, "XR_ERROR_LAYER_INVALID", "the runtime refused a composition layer"},
    {-24, "XR_ERROR_LAYER_LIMIT_EXCEEDED", "too many composition layers for the runtime"},
    {-25, "XR_ERROR_SWAPCHAIN_RECT_INVALID", "the runtime refused an image rectangle"},
    {-26, "XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED",
     "the runtime does not support the image format"},
    {-27, "XR_ERROR_ACTION_TYPE_MISMATCH", "an action was read as the wrong type"},
    {-28, "XR_ERROR_SESSION_NOT_READY", "the session was begun before it was ready"},
    {-29, "XR_ERROR_SESSION_NOT_STOPPING", "the session was ended before it was stopping"},
    {-30, "XR_ERROR_TIME_INVALID", "the runtime was given a time it does not accept"},
    {-31, "XR_ERROR_REFERENCE_SPACE_UNSUPPORTED",
     "the runtime does not support the reference space"},
    {-32, "XR_ERROR_FILE_ACCESS_ERROR", "the runtime could not read one of its files"},
    {-33, "XR_ERROR_FILE_CONTENTS_INVALID", "one of the runtime's files is invalid"},
    {-34, "XR_ERROR_FORM_FACTOR_UNSUPPORTED", "the runtime does not drive headsets"},
    {-35, "XR_ERROR_FORM_FACTOR_UNAVAILABLE", "the OpenXR runtime sees no headset"},
    {-36, "XR_ERROR_API_LAYER_NOT_PRESENT", "an API layer that was asked for is not installed"},
    {-37, "XR_ERROR_CALL_ORDER_INVALID", "the runtime was called out of order"},
    {-38, "XR_ERROR_GRAPHICS_DEVICE_INVALID",
     "the runtime cannot use this GL context (another GPU or display)"},
    {-39, "XR_ERROR_POSE_INVALID", "the runtime was given an invalid pose"},
    {-40, "XR_ERROR_INDEX_OUT_OF_RANGE", "the runtime was given an index out of range"},
    {-41, "XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED",
     "the runtime has no stereo view configuration"},
    {-42, "XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED",
     "the runtime does not support opaque display"},
    {-44, "XR_ERROR_NAME_DUPLICATED", "an action name was used twice"},
    {-45, "XR_ERROR_NAME_INVALID", "the runtime refused an action name"},
    {-46, "XR_ERROR_ACTIONSET_NOT_ATTACHED", "the actions were not attached to the session"},
    {-47, "XR_ERROR_ACTIONSETS_ALREADY_ATTACHED", "the actions were attached twice"},
    {-48, "XR_ERROR_LOCALIZED_NAME_DUPLICATED", "an action label was used twice"},
    {-49, "XR_ERROR_LOCALIZED_NAME_INVALID", "the runtime refused an action label"},
    {-50, "XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING",
     "the graphics requirements were not asked for first"},
    {-51, "XR_ERROR_RUNTIME_UNAVAILABLE", "no OpenXR runtime is installed or active"},
};
#define HOL__NRESULTS (sizeof hol__results / sizeof hol__results[0])

static const hol__result *hol__find(int result)
{
    for (size_t i = 0; i < HOL__NRESULTS; i++)
        if (hol__results[i].code == result)
            return &hol__results[i];
    return NULL;
}

const char *hol_xr_result_name(int result)
{
    const hol__result *r = hol__find(result);
    return r ? r->name : NULL;
}

const char *hol_xr_result_words(int result)
{
    const hol__result *r = hol__find(result);
    return r ? r->words : "an OpenXR error";
}

int hol_xr_result_is_loss(int result)
{
    return result == HOL_XR_ERROR_SESSION_LOST || result == HOL_XR_ERROR_INSTANCE_LOST;
}

/* What the user can do about it, or NULL. */
static const char *hol__remedy(int result, int android)
{
    switch (result) {
    case HOL_XR_ERROR_RUNTIME_UNAVAILABLE:
        return android ? "the headset's OpenXR runtime was not found: update the headset's "
                         "system software, then start Holonomy again"
                       : "install one (Debian: apt-get install monado-service) and start its "
                         "service (monado-service), or point XR_RUNTIME_JSON at a runtime's "
                         "manifest";
    case HOL_XR_ERROR_RUNTIME_FAILURE:
        return android ? "restart the headset and start Holonomy again"
                       : "its service is probably not running: start it (Monado: "
                         "monado-service; SteamVR: start SteamVR) and try again";
    case HOL_XR_ERROR_FORM_FACTOR_UNAVAILABLE:
        return android ? "put the headset on and start Holonomy again"
                       : "connect the headset and switch it on, and make sure the runtime's "
                         "service is running (Monado: monado-service; with no headset, "
                         "SIMULATED_ENABLE=1 monado-service)";
    case HOL_XR_ERROR_INSTANCE_LOST:
        return android ? "start Holonomy again" : "start the service again, then Holonomy";
    case HOL_XR_ERROR_SESSION_LOST:
        return "reconnect the headset, then start Holonomy again";
    default:
        return NULL;
    }
}

void hol_xr_message(const char *doing, int result, int android, char *out, size_t cap)
{
    if (!out || !cap)
        return;
    const char *name = hol_xr_result_name(result), *remedy = hol__remedy(result, android);
    char code[32];
    if (!name) {
        snprintf(code, sizeof code, "code %d", result);
        name = code;
    }
    snprintf(out, cap, "cannot %s: %s%s%s (%s)", doing ? doing : "go on",
             hol_xr_result_words(result), remedy ? "; " : "", remedy ? remedy : "", name);
}
