/* count_alloc.h - allocator hooks (core/hol_alloc.h) that count, for the
 * suites that check "one allocation at create, none after": pass
 * count_alloc_hooks() in a desc and compare count_allocs / count_frees. */
#ifndef HOL_TEST_COUNT_ALLOC_H
#define HOL_TEST_COUNT_ALLOC_H

#include <stdlib.h>

#include "../core/hol_alloc.h"

static long count_allocs, count_frees;

static void *count_alloc_fn(size_t n, void *user)
{
    (void)user;
    count_allocs++;
    return malloc(n);
}

static void count_free_fn(void *p, void *user)
{
    (void)user;
    count_frees += p != NULL;
    free(p);
}

static inline hol_alloc count_alloc_hooks(void)
{
    hol_alloc a = {count_alloc_fn, count_free_fn, NULL};
    return a;
}

#endif
