/* math_check.c - core/hol_math.h in wasm (emcc, run under node by make
 * web-test): the hash of tests/math_golden.h must be the native one, so a
 * browser's motion and geometry give the desktop's bits. */
#include <stdio.h>

#include "../math_golden.h"

int main(void)
{
    uint64_t h = math_golden_hash();
    printf("math golden hash %016llx (%s)\n", (unsigned long long)h,
           h == MATH_GOLDEN_HASH ? "the native one" : "NOT the native one");
    return h != MATH_GOLDEN_HASH;
}
