/* hol_math.h - the core's own elementary functions: the same bits on every
 * platform.
 *
 * Contract
 * - The core's results (motion, the app step's yaw and pitch, hyperbolic
 *   positions) must not depend on the C library's libm: glibc and the musl
 *   that emscripten builds into wasm disagree in the last bit for about 3 %
 *   of sin and cos arguments and 15 % of atan2's, and a recording made in a
 *   browser replays on the desktop to the same steps only if both run the
 *   same arithmetic. tests/check_core_purity.sh keeps libm's transcendental
 *   functions out of core/.
 * - These functions use only IEEE 754 double +, -, *, / and sqrt (correctly
 *   rounded everywhere) in a fixed order, so they give the same bits on
 *   x86-64, arm64 and wasm32 when the compiler does not contract a*b+c into
 *   a fused multiply-add (C11 mode gcc does not; clang builds of the core
 *   for arm64 need -ffp-contract=off; wasm has no fused multiply-add).
 * - The algorithms are fdlibm's (Sun Microsystems, freely distributable; see
 *   hol_math.c), as musl carries them. Accuracy, measured in
 *   tests/test_math.c against the 64-bit-mantissa long double libm over
 *   random and special arguments: under 1 ulp for hol_sin and hol_cos
 *   (|x| < 2^20 pi/2, 1.6e6), hol_atan, hol_atan2, hol_asin, hol_log and
 *   hol_log1p; under 2 ulp for hol_acosh and hol_asinh.
 * - Special values follow C99 Annex F: NaN in, NaN out; hol_sin and
 *   hol_cos of an infinity, hol_asin beyond [-1, 1], hol_log of a negative
 *   number, hol_acosh below 1: NaN. Beyond |x| >= 2^28 hol_sin and hol_cos
 *   give NaN too (the core never asks: its angles are below 2 pi; the
 *   argument reduction of fdlibm's huge case is not carried).
 * - Pure functions: no state, no errno, no allocation.
 */
#ifndef HOL_MATH_H
#define HOL_MATH_H

double hol_sin(double x);
double hol_cos(double x);
double hol_atan(double x);
double hol_atan2(double y, double x);
double hol_asin(double x);
double hol_log(double x);
double hol_log1p(double x);
double hol_acosh(double x);
/* asinh by log1p (odd; for the hyperbolic distances of hol_hyper_dist):
 * log1p(|x| + x^2 / (1 + sqrt(1 + x^2))), within 2 ulp. */
double hol_asinh(double x);

#endif
