/* hol_libm_web.h - the web build's libm for the renderer and the platform:
 * the core's own functions (core/hol_math.h) and a small exp family, in
 * place of musl's (the transfer size, docs/web.md).
 *
 * Contract
 * - The Makefile force-includes this header (-include) into the web build's
 *   render/ and platform/ objects only: the native builds and the core are
 *   untouched (the core calls hol_math.h itself and no libm transcendental).
 * - sin, cos, atan2, acosh, asinh are the core's hol_* (fdlibm's, under 1
 *   ulp, 2 for acosh and asinh); tan is hol_sin / hol_cos (within 4 ulp);
 *   sinf and cosf the float of hol_sin and hol_cos of the double; hypot is
 *   sqrt(a^2 + b^2) (the renderer's lengths are far from overflow); sinh,
 *   cosh, tanh are hol_sinh, hol_cosh, hol_tanh (core/hol_math_exp.h, within
 *   4 ulp of glibc's: tests/test_web_libm.c); powf(x, y) is the float of
 *   hol_exp(y hol_log(x)) (the renderer's sRGB curve, x in (0, 1]).
 * - Why: musl's sin, cos and tan carry the huge-argument reduction and its
 *   table of 2/pi, exp its 2 KB table, and the rest their own kernels: about
 *   10.5 KB of the gzip'ed wasm, which the core's functions already in it
 *   replace. The web's pixels were never the native bits (glibc's libm is
 *   not musl's either; web-test compares the eyes with a tolerance), and
 *   nothing a replay recomputes depends on them: the core computes with
 *   hol_math.h, and what the platform computes (the room placed from the
 *   head, hol_xr_room.c) enters the recording as input.
 * - Pure functions: no state, no errno. NaN in, NaN out.
 */
#ifndef HOL_LIBM_WEB_H
#define HOL_LIBM_WEB_H

#include <math.h>

#include "../core/hol_math.h"
#include "../core/hol_math_exp.h"

#ifdef HOL_WEB_LIBM_MACROS
#define sin(x) hol_sin(x)
#define cos(x) hol_cos(x)
#define tan(x) hol__web_tan(x)
#define sinf(x) ((float)hol_sin((double)(x)))
#define cosf(x) ((float)hol_cos((double)(x)))
#define atan2(y, x) hol_atan2(y, x)
#define acosh(x) hol_acosh(x)
#define asinh(x) hol_asinh(x)
#define hypot(a, b) hol__web_hypot(a, b)
#define sinh(x) hol_sinh(x)
#define cosh(x) hol_cosh(x)
#define tanh(x) hol_tanh(x)
#define powf(x, y) ((float)hol_exp((double)(y) * hol_log((double)(x))))
static inline double hol__web_tan(double x)
{
    return hol_sin(x) / hol_cos(x);
}
static inline double hol__web_hypot(double a, double b)
{
    return sqrt(a * a + b * b);
}
#endif

#endif
