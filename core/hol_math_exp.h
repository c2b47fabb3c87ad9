/* hol_math_exp.h - e^x and the hyperbolic functions, the core's own.
 *
 * Contract
 * - hol_expm1(x) = e^x - 1, hol_exp(x) = e^x, and hol_sinh, hol_cosh,
 *   hol_tanh from them: within 4 ulp of glibc's (tests/test_web_libm.c).
 *   Pure: no state, no errno; NaN in, NaN out.
 * - Used by the web build's libm (render/hol_libm_web.h) in place of
 *   musl's exp family and its 2 KB table (the transfer size, docs/web.md);
 *   the native builds do not call them.
 */
#ifndef HOL_MATH_EXP_H
#define HOL_MATH_EXP_H

double hol_expm1(double x);
double hol_exp(double x);
double hol_sinh(double x);
double hol_cosh(double x);
double hol_tanh(double x);

#endif
