/* hol_xr_state.c - how the headset layer reports (see hol_xr_state.h):
 * progress lines and the one failure line, on stdout and stderr on the
 * desktop and through logcat on Android (where stdout goes nowhere). */
#define _GNU_SOURCE
#include "hol_xr_state.h"

#include <stdarg.h>
#ifdef __ANDROID__
#include <android/log.h>
#endif

void hol__xr_say(hol__xr *x, const char *fmt, ...)
{
    (void)x;
    va_list ap;
    va_start(ap, fmt);
#ifdef __ANDROID__
    __android_log_vprint(ANDROID_LOG_INFO, "holonomy", fmt, ap);
#else
    vprintf(fmt, ap);
    putchar('\n');
#endif
    va_end(ap);
}

int hol__xr_error(hol__xr *x, const char *fmt, ...)
{
    if (x && x->failed) /* the first failure is the one line */
        return 1;
    if (x)
        x->failed = 1;
    char line[768];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
#ifdef __ANDROID__
    __android_log_print(ANDROID_LOG_ERROR, "holonomy", "%s", line);
#else
    fflush(stdout);
    fprintf(stderr, "holonomy xr: %s\n", line);
#endif
    return 1;
}

int hol__xr_fail(hol__xr *x, const char *doing, XrResult r)
{
    char line[640];
#ifdef __ANDROID__
    hol_xr_message(doing, (int)r, 1, line, sizeof line);
#else
    hol_xr_message(doing, (int)r, 0, line, sizeof line);
#endif
    if (x)
        x->lost |= hol_xr_result_is_loss((int)r);
    return hol__xr_error(x, "%s", line);
}

void hol__xr_gone(hol__xr *x, const char *doing, XrResult r)
{
    if (XR_FAILED(r) && !x->lost)
        hol__xr_fail(x, doing, r);
}
