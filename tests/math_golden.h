/* math_golden.h - the bits of core/hol_math.h's functions over a fixed set
 * of arguments, folded into one 64-bit hash: every platform must give
 * MATH_GOLDEN_HASH (tests/test_math.c natively and under qemu on arm64;
 * tests/web/math_check.c in wasm under node, in make web-test).
 */
#ifndef MATH_GOLDEN_H
#define MATH_GOLDEN_H

#include <stdint.h>
#include <string.h>

#include "../core/hol_math.h"

/* Computed on x86-64 (glibc) when the functions were written; arm64 and
 * wasm32 give the same. */
#define MATH_GOLDEN_HASH UINT64_C(0x9baa4313f72d3709)

static uint64_t math_golden_mix(uint64_t h, double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    h ^= b;
    h *= UINT64_C(0x100000001b3);
    return h ^ (h >> 29);
}

/* 8 functions x 4096 arguments from a fixed sequence (angles up to 4 pi,
 * slopes, unit values, distances up to 1e3). */
static uint64_t math_golden_hash(void)
{
    uint64_t h = UINT64_C(0xcbf29ce484222325), s = 1;
    for (int i = 0; i < 4096; i++) {
        s = s * UINT64_C(6364136223846793005) + UINT64_C(1442695040888963407);
        double u = (double)(s >> 11) * (1.0 / 9007199254740992.0); /* [0, 1) */
        double a = (u - 0.5) * 8 * 3.14159265358979323846;
        h = math_golden_mix(h, hol_sin(a));
        h = math_golden_mix(h, hol_cos(a));
        h = math_golden_mix(h, hol_atan((u - 0.5) * 20));
        h = math_golden_mix(h, hol_atan2(u - 0.3, 0.6 - u * u));
        h = math_golden_mix(h, hol_asin(2 * u - 1));
        h = math_golden_mix(h, hol_log(u * 1e3 + 1e-3));
        h = math_golden_mix(h, hol_log1p(u * 4 - 0.9));
        h = math_golden_mix(h, hol_acosh(1 + u * u * 1e3));
    }
    return h;
}

#endif
