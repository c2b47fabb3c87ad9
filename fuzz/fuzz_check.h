/* fuzz_check.h - the harnesses' assertion: a failed property aborts, which
 * libFuzzer reports as a crash with the input saved (and the gcc replay
 * build turns into a failed `make test`). */
#ifndef HOL_FUZZ_CHECK_H
#define HOL_FUZZ_CHECK_H

#include <stdlib.h>

#define CHECK(c)                                                                \
    do {                                                                       \
        if (!(c))                                                              \
            abort();                                                           \
    } while (0)

#endif
