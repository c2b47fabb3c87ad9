/* hol_campaign.c - a mode's level from a seed and the default campaign
 * (see hol_campaign.h). */
#include "hol_campaign.h"

#include <stdio.h>
#include <string.h>

#include "hol_room.h"
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

/* The geometry, its defaults filled in (q 5, a 3 x 3 room). */
typedef struct hol__geo {
    int q, cols, rows;
} hol__geo;

static int hol__avoided(hol_tile t, const hol_tile *avoid, int navoid)
{
    for (int i = 0; i < navoid; i++)
        if (hol_tile_eq(t, avoid[i]))
            return 1;
    return 0;
}

/* Room steps a walked tile may take (enough to find every tile of a 5 x 5
 * flat room many times over). */
#define HOL__WALK_MAX 4096

/* A tile d steps from O that a walk inside the room reaches, and not in
 * avoid: a seeded walk of room steps from the room's start (a step out of
 * the room is tried in the next direction), stopped on the first such tile
 * at distance d; failing that within HOL__WALK_MAX steps, the farthest one
 * within d seen. O when the walk meets no such tile at all. */
static hol_tile hol__walked_tile(const hol__geo *g, uint64_t *rng, int d, const hol_tile *avoid,
                                 int navoid)
{
    hol_room r;
    if (hol_room_start_in(g->q, g->cols, g->rows, &r))
        return hol_tile_origin_q(g->q);
    hol_tile best = r.tile;
    int best_d = 0;
    for (int i = 0; i < HOL__WALK_MAX; i++) {
        int first = (int)(hol__splitmix(rng) % 4);
        for (int k = 0; k < 4 && hol_room_step(&r, (first + k) % 4) != HOL_OK; k++)
            ;
        int dist = hol_tile_dist0(r.tile);
        if (dist <= best_d || dist > d || hol__avoided(r.tile, avoid, navoid))
            continue;
        best = r.tile;
        best_d = dist;
        if (dist == d)
            break;
    }
    return best;
}

/* An objective about d steps out, not in avoid: {4,5}'s canonical address
 * (drawn again while in avoid, as before geometries came), or a walked
 * tile. HOL_ERANGE when none is found. */
static hol_err hol__objective(const hol__geo *g, uint64_t *rng, int d, const hol_tile *avoid,
                              int navoid, hol_tile *out)
{
    if (g->q == 5) {
        *out = hol__seeded_tile(rng, d);
        return HOL_OK;
    }
    *out = hol__walked_tile(g, rng, d, avoid, navoid);
    return hol_tile_dist0(*out) > 0 ? HOL_OK : HOL_ERANGE;
}

/* "keys K1 K2 ...\nchest C\n": nkeys keys 2..3 out, none on the chest. */
static hol_err hol__keys_text(const hol__geo *g, uint64_t *rng, int dist, int nkeys, char *out,
                              size_t cap, int *out_n)
{
    char a[HOL_TILE_ADDR_MAX];
    hol_tile used[HOL_APP_MAX_KEYS + 1];
    hol_err e = hol__objective(g, rng, dist, NULL, 0, &used[0]);
    int n = snprintf(out, cap, "keys");
    for (int k = 0; k < nkeys && !e; k++) {
        int tries = 0;
        do {
            int d = 2 + (int)(hol__splitmix(rng) % 2);
            e = hol__objective(g, rng, d, used, k + 1, &used[k + 1]);
        } while (!e && hol__avoided(used[k + 1], used, k + 1) && ++tries < 1000);
        e = e ? e : tries < 1000 ? HOL_OK : HOL_ERANGE;
        hol_tile_print(used[k + 1], a);
        n += snprintf(out + n, cap - (size_t)n, " %s", a);
    }
    hol_tile_print(used[0], a);
    n += snprintf(out + n, cap - (size_t)n, "\nchest %s\n", a);
    *out_n = n;
    return e;
}

/* The level's first lines: "mode M\n", beyond {4,5} the tiling and a room
 * other than 3 x 3 (the objectives were found in it), "seed S\n". */
static int hol__head(const hol__geo *g, const char *mode, uint64_t seed, char *out, size_t cap)
{
    int n = snprintf(out, cap, "mode %s\n", mode);
    if (g->q != 5 && strcmp(mode, "tutorial"))
        n += snprintf(out + n, cap - (size_t)n, "tiling 4 %d\n", g->q);
    if (g->q != 5 && strcmp(mode, "tutorial") && (g->cols != 3 || g->rows != 3))
        n += snprintf(out + n, cap - (size_t)n, "room %d %d\n", g->cols, g->rows);
    return n + snprintf(out + n, cap - (size_t)n, "seed %llu\n", (unsigned long long)seed);
}

/* A level of a mode: the flag at distance dist; or nkeys keys 2..3 out and
 * the chest at dist. */
static hol_err hol__mode_level(const hol__geo *g, const char *mode, uint64_t seed, int dist,
                               int nkeys, const char *name, hol_level *out)
{
    char text[512], a[HOL_TILE_ADDR_MAX];
    uint64_t rng = seed;
    static const char *const modes[] = {"explore", "tutorial", "flag", "keys"};
    int m = 0;
    while (m < 4 && strcmp(mode, modes[m]))
        m++;
    if (m == 4)
        return HOL_EARG;
    int n = hol__head(g, mode, seed, text, sizeof text), more = 0;
    hol_err e = HOL_OK;
    if (m == 2) {
        hol_tile flag;
        e = hol__objective(g, &rng, dist, NULL, 0, &flag);
        hol_tile_print(flag, a);
        more = snprintf(text + n, sizeof text - (size_t)n, "flag %s\n", a);
    } else if (m == 3) {
        e = hol__keys_text(g, &rng, dist, nkeys, text + n, sizeof text - (size_t)n, &more);
    }
    if (e)
        return e;
    n += more;
    char nm[HOL_LEVEL_NAME_MAX];
    if (!name) {
        snprintf(nm, sizeof nm, "%s-%llu", mode, (unsigned long long)seed);
        name = nm;
    }
    return hol_level_make(name, strlen(name), text, (size_t)n, out, NULL);
}

static hol_err hol__geo_of(const hol_campaign_geo *geo, hol__geo *out)
{
    out->q = geo && geo->q ? geo->q : 5;
    out->cols = geo && geo->cols ? geo->cols : HOL_ROOM_SIZE;
    out->rows = geo && geo->rows ? geo->rows : HOL_ROOM_SIZE;
    hol_room r;
    return hol_room_start_in(out->q, out->cols, out->rows, &r);
}

hol_err hol_campaign_mode_level(const char *mode, uint64_t seed, const hol_campaign_geo *geo,
                                hol_level *out)
{
    hol__geo g;
    hol_err e = hol__geo_of(geo, &g);
    return e ? e : hol__mode_level(&g, mode, seed, 5, 3, NULL, out);
}

hol_err hol_campaign_default(uint64_t seed, const hol_campaign_geo *geo,
                             hol_level levels[HOL_CAMPAIGN_LEVELS])
{
    static const int flag_dist[3] = {3, 5, 7};
    char name[32];
    hol__geo g;
    hol_err e = hol__geo_of(geo, &g);
    if (!e)
        e = hol__mode_level(&g, "tutorial", seed, 0, 0, "tutorial", &levels[0]);
    for (int i = 0; i < 3 && !e; i++) {
        snprintf(name, sizeof name, "flag-%d", i + 1);
        e = hol__mode_level(&g, "flag", seed + (uint64_t)i, flag_dist[i], 0, name,
                            &levels[1 + i]);
    }
    for (int i = 0; i < 2 && !e; i++) {
        snprintf(name, sizeof name, "keys-%d", i + 1);
        e = hol__mode_level(&g, "keys", seed + 3 + (uint64_t)i, 3 + i, 2 + i, name,
                            &levels[4 + i]);
    }
    return e;
}
