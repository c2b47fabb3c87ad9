/* bench_util.h - helpers of the benchmarks: thread CPU time (what the code
 * costs on the shared build machine, without preemption spikes) and a
 * comparison of doubles for qsort (medians, percentiles). */
#ifndef HOL_BENCH_UTIL_H
#define HOL_BENCH_UTIL_H

#include <time.h>

static inline double bench_cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static inline int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#endif
