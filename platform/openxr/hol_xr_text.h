/* hol_xr_text.h - OpenXR results in words: the one line a headset failure
 * prints. Pure (no OpenXR headers: the result codes of OpenXR 1.0 are
 * mirrored as plain ints; tests/test_xr_text.c checks every one against
 * openxr.h's own list).
 *
 * Contract
 * - hol_xr_result_name(r): the enumerant's name ("XR_ERROR_RUNTIME_FAILURE")
 *   for every result of OpenXR 1.0's core; NULL for any other code (an
 *   extension's).
 * - hol_xr_result_words(r): what it means, in words, for every code
 *   (never "?"): a known one says what happened; another says "an OpenXR
 *   error (code N)".
 * - hol_xr_message(doing, r, android, out, cap): the whole line after
 *   "holonomy xr: ", e.g. "cannot start the OpenXR instance: the OpenXR
 *   runtime did not answer; its service is probably not running: start it
 *   (Monado: monado-service; SteamVR: start SteamVR) and try again
 *   (XR_ERROR_RUNTIME_FAILURE)". `doing` is what the app was doing, in
 *   words ("start the OpenXR instance"), never a C call. Where the result
 *   has a remedy (no runtime, its service down, no headset, the runtime or
 *   the headset gone), the line says it; `android` nonzero gives the
 *   headset's remedies instead of the desktop's. Always NUL-terminated,
 *   cut to cap.
 * - hol_xr_result_is_loss(r): 1 for the results that mean the session or
 *   the instance is gone (XR_ERROR_SESSION_LOST, XR_ERROR_INSTANCE_LOST).
 */
#ifndef HOL_XR_TEXT_H
#define HOL_XR_TEXT_H

#include <stddef.h>

/* The XrResult values the layer itself tests (OpenXR 1.0). */
enum {
    HOL_XR_SUCCESS = 0,
    HOL_XR_SPACE_BOUNDS_UNAVAILABLE = 7,
    HOL_XR_ERROR_RUNTIME_FAILURE = -2,
    HOL_XR_ERROR_INSTANCE_LOST = -13,
    HOL_XR_ERROR_SESSION_LOST = -17,
    HOL_XR_ERROR_FORM_FACTOR_UNAVAILABLE = -35,
    HOL_XR_ERROR_RUNTIME_UNAVAILABLE = -51
};

const char *hol_xr_result_name(int result);
const char *hol_xr_result_words(int result);
void hol_xr_message(const char *doing, int result, int android, char *out, size_t cap);
int hol_xr_result_is_loss(int result);

#endif
