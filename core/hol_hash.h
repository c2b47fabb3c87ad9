/* hol_hash.h - the one 64-bit mixing function of the core.
 *
 * Contract: hol_mix64 is the splitmix64 finaliser, a bijection of 64-bit
 * values with good avalanche; tile hashing and the world's seeded hashing
 * are built on it. Pure, header-only. */
#ifndef HOL_HASH_H
#define HOL_HASH_H

#include <stdint.h>

static inline uint64_t hol_mix64(uint64_t x)
{
    x ^= x >> 30;
    x *= UINT64_C(0xBF58476D1CE4E5B9);
    x ^= x >> 27;
    x *= UINT64_C(0x94D049BB133111EB);
    x ^= x >> 31;
    return x;
}

#endif
