/* quick.h - the lighter sizes of the brute-force unit tests.
 *
 * Contract
 * - test_quick() is 1 when the environment has HOL_TEST_QUICK set to
 *   anything but "" or "0", else 0. test_tile, test_world and test_nav
 *   then run their exhaustive and random checks at a smaller depth or count
 *   (each names what it lowers); every check still runs and can fail.
 * - make test runs them in full. CI sets HOL_TEST_QUICK=1 where the same
 *   code runs again slower: under qemu (make cross-test: the arm64 build
 *   behaves like the host's) and under ASan + UBSan (make san, san-all).
 * - Include after <stdlib.h> and <string.h>; a static function, so each
 *   program has its own copy.
 */
#ifndef TESTS_QUICK_H
#define TESTS_QUICK_H

static __attribute__((unused)) int test_quick(void)
{
    const char *s = getenv("HOL_TEST_QUICK");
    return s && *s && strcmp(s, "0") != 0;
}

#endif
