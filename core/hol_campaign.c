/* hol_campaign.c - a mode's level from a seed and the default campaign
 * (see hol_campaign.h). */
#include "hol_campaign.h"

#include <stdio.h>
#include <string.h>

#include "hol_tile.h"

static uint64_t hol__splitmix(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A tile at distance d from O: a random canonical address (the branch,
 * then f, l or r wherever the address stays canonical). */
static hol_tile hol__seeded_tile(uint64_t *rng, int d)
{
    static const int letters[3] = {0, 1, 3};
    hol_tile t = hol_tile_origin();
    for (int i = 0; i < d; i++) {
        hol_tile c;
        int first = (int)(hol__splitmix(rng) % (i ? 3 : 4));
        for (int k = 0; k < 3; k++)
            if (!hol_tile_child(t, i ? letters[(first + k) % 3] : first, &c))
                break;
        t = c;
    }
    return t;
}

/* "keys K1 K2 ...\nchest C\n": nkeys keys 2..3 out, none on the chest. */
static int hol__keys_text(uint64_t *rng, int dist, int nkeys, char *out, size_t cap)
{
    char a[HOL_TILE_ADDR_MAX];
    hol_tile keys[HOL_APP_MAX_KEYS], chest = hol__seeded_tile(rng, dist);
    int n = snprintf(out, cap, "keys");
    for (int k = 0; k < nkeys; k++) {
        int fresh;
        do {
            keys[k] = hol__seeded_tile(rng, 2 + (int)(hol__splitmix(rng) % 2));
            fresh = !hol_tile_eq(keys[k], chest);
            for (int j = 0; j < k; j++)
                fresh &= !hol_tile_eq(keys[k], keys[j]);
        } while (!fresh);
        hol_tile_print(keys[k], a);
        n += snprintf(out + n, cap - (size_t)n, " %s", a);
    }
    hol_tile_print(chest, a);
    n += snprintf(out + n, cap - (size_t)n, "\nchest %s\n", a);
    return n;
}

/* A level of a mode: the flag at distance dist; or nkeys keys 2..3 out and
 * the chest at dist. */
static hol_err hol__mode_level(const char *mode, uint64_t seed, int dist, int nkeys,
                               const char *name, hol_level *out)
{
    char text[512], a[HOL_TILE_ADDR_MAX];
    uint64_t rng = seed;
    unsigned long long s = (unsigned long long)seed;
    int n;
    if (!strcmp(mode, "explore") || !strcmp(mode, "tutorial")) {
        n = snprintf(text, sizeof text, "mode %s\nseed %llu\n", mode, s);
    } else if (!strcmp(mode, "flag")) {
        hol_tile_print(hol__seeded_tile(&rng, dist), a);
        n = snprintf(text, sizeof text, "mode flag\nseed %llu\nflag %s\n", s, a);
    } else if (!strcmp(mode, "keys")) {
        n = snprintf(text, sizeof text, "mode keys\nseed %llu\n", s);
        n += hol__keys_text(&rng, dist, nkeys, text + n, sizeof text - (size_t)n);
    } else {
        return HOL_EARG;
    }
    char nm[HOL_LEVEL_NAME_MAX];
    if (!name) {
        snprintf(nm, sizeof nm, "%s-%llu", mode, s);
        name = nm;
    }
    return hol_level_make(name, strlen(name), text, (size_t)n, out, NULL);
}

hol_err hol_campaign_mode_level(const char *mode, uint64_t seed, hol_level *out)
{
    return hol__mode_level(mode, seed, 5, 3, NULL, out);
}

hol_err hol_campaign_default(uint64_t seed, hol_level levels[HOL_CAMPAIGN_LEVELS])
{
    static const int flag_dist[3] = {3, 5, 7};
    char name[32];
    hol_err e = hol__mode_level("tutorial", seed, 0, 0, "tutorial", &levels[0]);
    for (int i = 0; i < 3 && !e; i++) {
        snprintf(name, sizeof name, "flag-%d", i + 1);
        e = hol__mode_level("flag", seed + (uint64_t)i, flag_dist[i], 0, name, &levels[1 + i]);
    }
    for (int i = 0; i < 2 && !e; i++) {
        snprintf(name, sizeof name, "keys-%d", i + 1);
        e = hol__mode_level("keys", seed + 3 + (uint64_t)i, 3 + i, 2 + i, name, &levels[4 + i]);
    }
    return e;
}
