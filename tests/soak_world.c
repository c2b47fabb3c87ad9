/* soak_world.c - `make soak` (not CI): a million room steps of a random
 * walk that wanders and comes back, in a world whose store (2^16 tiles)
 * evicts all the time. Every tile within the radius after every step is
 * compared with what it was the first time the user saw it, against the
 * soak's own record (an independent table). Prints the tiles seen, the
 * revisits compared, the changed tiles (must be 0), the store's counters,
 * and the resident memory at the start and the end (must stay flat: the
 * world allocates once). Exit 1 on any changed tile or memory growth. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"

typedef struct rec {
    hol_tile tile;
    hol_tile_content c;
    int used;
} rec;

static uint64_t rng_next(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static long rss_kb(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long pages = 0, res = 0;
    if (f) {
        if (fscanf(f, "%ld %ld", &pages, &res) != 2)
            res = 0;
        fclose(f);
    }
    return res * 4;
}

/* tiles within r of t: breadth first with a small hash set */
static size_t ball(hol_tile t, int r, hol_tile *out, int *dist)
{
    enum { SET = 1024 };
    static hol_tile set[SET];
    static unsigned char used[SET];
    memset(used, 0, sizeof used);
    size_t n = 0;
    out[n] = t;
    dist[n++] = 0;
    used[hol_tile_hash(t) & (SET - 1)] = 1;
    set[hol_tile_hash(t) & (SET - 1)] = t;
    for (size_t q = 0; q < n; q++) {
        if (dist[q] >= r)
            continue;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            if (hol_tile_step(out[q], d, &nt, NULL))
                continue;
            size_t h = hol_tile_hash(nt) & (SET - 1);
            while (used[h] && !hol_tile_eq(set[h], nt))
                h = (h + 1) & (SET - 1);
            if (used[h])
                continue;
            used[h] = 1;
            set[h] = nt;
            out[n] = nt;
            dist[n++] = dist[q] + 1;
        }
    }
    return n;
}

int main(int argc, char **argv)
{
    long steps = argc > 1 ? atol(argv[1]) : 1000000;
    const size_t mask = (1u << 22) - 1;
    rec *tab = calloc(mask + 1, sizeof *tab);
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.seed = 2026;
    d.capacity = 1u << 16;
    d.keep_capacity = 1u << 21; /* 2 M seen tiles remembered: 48 MB */
    hol_world *w;
    if (!tab || hol_world_make(&d, &w)) {
        fprintf(stderr, "soak: cannot allocate\n");
        return 1;
    }
    /* touch the soak's own record now (a volatile write per page: not
     * elided), so the resident memory from here on shows the world */
    for (size_t off = 0; off < (mask + 1) * sizeof *tab; off += 4096)
        ((volatile unsigned char *)tab)[off] = 0;
    hol_room room = hol_room_start();
    hol_world_update(w, &room);
    long rss0 = rss_kb();
    uint64_t rng = 7;
    size_t seen = 0, compared = 0, changed = 0;
    static hol_tile b[1024];
    static int bd[1024];
    clock_t c0 = clock();
    for (long i = 0; i <= steps; i++) {
        size_t n = ball(room.tile, hol_world_radius(w), b, bd);
        for (size_t k = 0; k < n; k++) {
            hol_tile_content c;
            if (hol_world_peek(w, b[k], &c))
                continue;
            size_t h = hol_tile_hash(b[k]) & mask;
            while (tab[h].used && !hol_tile_eq(tab[h].tile, b[k]))
                h = (h + 1) & mask;
            if (!tab[h].used) {
                if (seen >= mask / 2) {
                    fprintf(stderr, "soak: the soak's own record is full\n");
                    return 1;
                }
                tab[h].used = 1;
                tab[h].tile = b[k];
                tab[h].c = c;
                seen++;
            } else {
                compared++;
                changed += memcmp(&tab[h].c, &c, sizeof c) != 0;
            }
        }
        if (i == steps)
            break;
        /* a random step; now and then towards the origin, so the walk
         * comes back over what it saw */
        for (int tries = 0; tries < 64; tries++) {
            uint64_t r = rng_next(&rng);
            int dir = (int)(r & 3);
            if ((r >> 8) % 1000 < 300)
                for (int dd = 0; dd < 4; dd++) {
                    hol_room t = room;
                    if (!hol_room_step(&t, dd) && hol_tile_dist0(t.tile) < hol_tile_dist0(room.tile))
                        dir = dd;
                }
            hol_room t = room;
            if (hol_room_step(&t, dir))
                continue;
            room = t;
            if (hol_world_update(w, &room)) {
                fprintf(stderr, "soak: update failed at step %ld\n", i);
                return 1;
            }
            break;
        }
    }
    long rss1 = rss_kb();
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    printf("soak: %ld steps in %.0f s: %zu tiles seen, %zu revisits compared, %zu changed\n",
           steps, (double)(clock() - c0) / CLOCKS_PER_SEC, seen, compared, changed);
    printf("soak: store %u tiles (capacity %u), %llu evicted, %u seen tiles remembered "
           "outside it (of %u), %llu lost\n",
           st.count, st.capacity, (unsigned long long)st.evicted, st.kept, st.keep_capacity,
           (unsigned long long)st.keep_lost);
    printf("soak: resident memory %ld KB after the first update, %ld KB at the end "
           "(world %.1f MB, fixed; the soak's own record %zu KB)\n",
           rss0, rss1, st.bytes / 1048576.0, (size_t)((mask + 1) * sizeof *tab / 1024));
    int ok = changed == 0 && rss1 <= rss0 + 1024;
    hol_world_destroy(w);
    free(tab);
    return ok ? 0 : 1;
}
