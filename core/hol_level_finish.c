/* hol_level_finish.c - a level after its last line (see
 * hol_level_impl.h): placements against objectives, the start walk, the
 * room's reach, and the objectives drawn by distance from the seed. */
#include "hol_level_impl.h"

#include <string.h>

#include "hol_room.h"
#include "hol_tile.h"

/* A placement may not stand where an objective is given. */
static hol_err hol__check_places(hol__lp *p)
{
    const hol_app_level *L = &p->L;
    for (int k = 0; k < L->nplaces; k++) {
        hol_tile t = L->places[k].tile;
        const char *what = NULL;
        long at = 0;
        if (L->mode == HOL_APP_FLAG && p->flag_line && !p->flag_lo && hol_tile_eq(t, L->flag))
            what = "the flag", at = p->flag_line;
        for (int j = 0; L->mode == HOL_APP_KEYS && !p->keys_n && j < L->nkeys; j++)
            if (hol_tile_eq(t, L->keys[j]))
                what = "a key", at = p->keys_line;
        if (L->mode == HOL_APP_KEYS && p->chest_line && !p->chest_lo && hol_tile_eq(t, L->chest))
            what = "the chest", at = p->chest_line;
        if (what) {
            char a[HOL_TILE_ADDR_MAX];
            hol_tile_print(t, a);
            return hol__lv_conflict(p, p->place_line[k], at, 0, what, a);
        }
    }
    return HOL_OK;
}

static uint64_t hol__mix(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A tile at distance d from `from`, drawn from rng: each step goes to a
 * neighbour one further away (in the {4,5} tiling every tile has one). */
static hol_tile hol__tile_at(hol_tile from, int d, uint64_t *rng)
{
    hol_tile t = from;
    for (int i = 1; i <= d; i++) {
        hol_tile cand[4];
        int n = 0;
        for (int e = 0; e < 4; e++) {
            hol_tile nb;
            int arr;
            if (!hol_tile_step(t, e, &nb, &arr) && hol_tile_dist(from, nb) == i)
                cand[n++] = nb;
        }
        if (n == 0)
            break;
        t = cand[hol__mix(rng) % (uint64_t)n];
    }
    return t;
}

/* Is t taken: the start tile, an objective or a placement? */
static int hol__taken(const hol_app_level *L, hol_tile start, hol_tile t)
{
    if (hol_tile_eq(t, start))
        return 1;
    if (L->mode == HOL_APP_FLAG && hol_tile_eq(t, L->flag))
        return 1;
    if (L->mode == HOL_APP_KEYS) {
        for (int k = 0; k < L->nkeys; k++)
            if (hol_tile_eq(t, L->keys[k]))
                return 1;
        if (hol_tile_eq(t, L->chest))
            return 1;
    }
    for (int k = 0; k < L->nplaces; k++)
        if (hol_tile_eq(t, L->places[k].tile))
            return 1;
    return 0;
}

/* The tiles a walk inside the room reaches, in the flat {4,4} (where a
 * room reaches exactly its own C x R tiles); n 0 in the other tilings,
 * whose reach the navigator decides (HOL_EUNREACH at the app's start). */
typedef struct hol__reach {
    int n;
    hol_tile tiles[HOL_ROOM_MAX_CELLS];
} hol__reach;

static void hol__reach_init(const hol_app_level *L, hol__reach *rc)
{
    rc->n = 0;
    hol_room s;
    if (L->tiling_q != 4 || hol_room_start_in(4, L->room_cols, L->room_rows, &s))
        return;
    int cols = hol_room_cols(&s), rows = hol_room_rows(&s);
    for (int c = 0; c < cols; c++)
        for (int r = 0; r < rows; r++) {
            hol_room u = s;
            while (u.col != c)
                (void)hol_room_step(&u, u.col < c ? HOL_DIR_E : HOL_DIR_W);
            while (u.row != r)
                (void)hol_room_step(&u, u.row < r ? HOL_DIR_S : HOL_DIR_N);
            rc->tiles[rc->n++] = u.tile;
        }
}

static int hol__reached(const hol__reach *rc, hol_tile t)
{
    if (!rc->n)
        return 1;
    for (int i = 0; i < rc->n; i++)
        if (hol_tile_eq(rc->tiles[i], t))
            return 1;
    return 0;
}

/* A free tile at a distance in [lo, hi] from start that a walk reaches; 1
 * if none was found in 256 draws. */
static int hol__draw(const hol_app_level *L, const hol__reach *rc, hol_tile start, int lo,
                     int hi, uint64_t *rng, hol_tile *out)
{
    for (int tries = 0; tries < 256; tries++) {
        int d = lo + (int)(hol__mix(rng) % (uint64_t)(hi - lo + 1));
        hol_tile t = hol__tile_at(start, d, rng);
        if (hol_tile_dist(start, t) == d && !hol__taken(L, start, t) && hol__reached(rc, t)) {
            *out = t;
            return 0;
        }
    }
    return 1;
}

/* Objectives by distance from the start tile, drawn from the seed. */
static hol_err hol__draw_objectives(hol__lp *p, const hol__reach *rc, hol_tile start)
{
    hol_app_level *L = &p->L;
    uint64_t rng = L->seed ^ 0x6c6576656cull;
    const char *none = rc->n ? "that a walk inside the room reaches" : "";
    if (L->mode == HOL_APP_FLAG && p->flag_lo &&
        hol__draw(L, rc, start, p->flag_lo, p->flag_hi, &rng, &L->flag))
        return hol__lfail(p, HOL_EARG, p->flag_line, "no free tile for the flag at that distance%s%s",
                          *none ? " " : "", none);
    if (L->mode == HOL_APP_KEYS && p->chest_lo &&
        hol__draw(L, rc, start, p->chest_lo, p->chest_hi, &rng, &L->chest))
        return hol__lfail(p, HOL_EARG, p->chest_line,
                          "no free tile for the chest at that distance%s%s", *none ? " " : "", none);
    if (L->mode == HOL_APP_KEYS && p->keys_n) {
        L->nkeys = 0;
        for (int k = 0; k < p->keys_n; k++) {
            hol_tile t;
            if (hol__draw(L, rc, start, p->keys_lo, p->keys_hi, &rng, &t))
                return hol__lfail(p, HOL_EARG, p->keys_line,
                                  "no free tile for key %d at that distance%s%s", k + 1,
                                  *none ? " " : "", none);
            L->keys[L->nkeys++] = t;
        }
    }
    return HOL_OK;
}

/* Objectives given by address that no walk inside the room reaches (the
 * flat {4,4}: off the room's own tiles) are bad input naming their line. */
static hol_err hol__check_reach(hol__lp *p, const hol__reach *rc)
{
    const hol_app_level *L = &p->L;
    hol_tile t;
    long at = 0;
    const char *what = NULL;
    if (L->mode == HOL_APP_FLAG && !p->flag_lo && !hol__reached(rc, L->flag))
        t = L->flag, at = p->flag_line, what = "the flag";
    for (int k = 0; !what && L->mode == HOL_APP_KEYS && !p->keys_n && k < L->nkeys; k++)
        if (!hol__reached(rc, L->keys[k]))
            t = L->keys[k], at = p->keys_line, what = "a key";
    if (!what && L->mode == HOL_APP_KEYS && !p->chest_lo && !hol__reached(rc, L->chest))
        t = L->chest, at = p->chest_line, what = "the chest";
    if (!what)
        return HOL_OK;
    char a[HOL_TILE_ADDR_MAX];
    hol_tile_print(t, a);
    return hol__lfail(p, HOL_EARG, at,
                      "no walk inside the room reaches %s's tile %.30s (in the flat {4,4} a "
                      "%dx%d room reaches only its own %d tiles)",
                      what, a, L->room_cols ? L->room_cols : 3, L->room_rows ? L->room_rows : 3,
                      rc->n);
}

hol_err hol__lv_finish(hol__lp *p)
{
    if (!p->have_mode)
        return hol__lfail(p, HOL_EARG, p->line ? p->line : 1, "no 'mode' line%s",
                         p->line ? "" : " (the level is empty)");
    /* a missing objective is bad input naming the mode's line (it was
     * left on tile O, where the level begins) */
    const char *missing = p->L.mode == HOL_APP_FLAG && !p->flag_line    ? "flag"
                          : p->L.mode == HOL_APP_KEYS && !p->keys_line  ? "keys"
                          : p->L.mode == HOL_APP_KEYS && !p->chest_line ? "chest"
                                                                        : NULL;
    if (missing)
        return hol__lfail(p, HOL_EARG, p->have_mode, "mode %s needs a '%s' or '%s-distance' line",
                          p->L.mode == HOL_APP_FLAG ? "flag" : "keys", missing, missing);
    const hol_app_level *L = &p->L;
    int q = hol__lv_q(p);
    if (L->mode == HOL_APP_TUTORIAL && (q == 4 || q == 8))
        return hol__lfail(p, HOL_EARG, p->tiling_line ? p->tiling_line : p->have_mode,
                          "the tutorial needs the tiling {4,5}, {4,6} or {4,7}: its lessons have "
                          "no walk inside the room in {4,%d}", q);
    if (L->point && (L->mode == HOL_APP_TUTORIAL ||
                     (L->point == HOL_APP_POINT_OBJECTIVE && L->mode == HOL_APP_EXPLORE)))
        return hol__lfail(p, HOL_EARG, p->point_line,
                          "point %s needs a mode with an objective (flag or keys%s)",
                          L->point == HOL_APP_POINT_START ? "start" : "objective",
                          L->point == HOL_APP_POINT_START ? ", or explore" : "");
    hol_room r0;
    (void)hol_room_start_in(q, L->room_cols, L->room_rows, &r0);
    for (int i = 0; i < L->nstart; i++)
        if (hol_room_step(&r0, L->start[i]))
            return hol__lfail(p, HOL_EARG, p->line, "the start walk leaves the room");
    hol__reach rc;
    hol__reach_init(L, &rc);
    hol_err e = hol__check_places(p);
    if (!e)
        e = hol__check_reach(p, &rc);
    return e ? e : hol__draw_objectives(p, &rc, r0.tile);
}
