/* hol_world_check.c - every constraint of the world, checked tile by tile.
 *
 * hol__check_rec works on any lookup (the live store, or a saved image that
 * hol_world_load has not accepted yet), so saved files are held to exactly
 * the rules the generator keeps.
 */
#include "hol_world_impl.h"

#include <stdio.h>

static hol_err hol__fail(char *msg, size_t cap, hol_tile t, const char *what,
                         int a, int b)
{
    if (msg && cap) {
        char addr[HOL_TILE_ADDR_MAX];
        if (hol_tile_dist0(t) <= HOL_TILE_MAX_DIST)
            hol_tile_print(t, addr);
        else
            snprintf(addr, sizeof addr, "(invalid tile word)");
        snprintf(msg, cap, "tile %s: %s", addr, what);
        char tail[64];
        if (a >= 0) {
            snprintf(tail, sizeof tail, " (edge %d, value %d)", a, b);
            size_t n = 0;
            while (n < cap && msg[n])
                n++;
            snprintf(msg + n, cap - n, "%s", tail);
        }
    }
    return HOL_ECORRUPT;
}

static int hol__plain_class(int s) { return hol__state_rot(s) < 0; }

hol_err hol__check_rec(const hol__rec *r, hol__lookup_fn look, const void *ctx,
                       char *msg, size_t cap)
{
    if (!hol__tile_valid(r->tile))
        return hol__fail(msg, cap, r->tile, "not a canonical tile word", -1, 0);
    int s = r->state;
    int collapsed = s != HOL__UNSET;
    if (collapsed && s >= HOL__NSTATES)
        return hol__fail(msg, cap, r->tile, "unknown state", -1, 0);
    if (r->biome >= HOL_BIOME_COUNT && r->biome != HOL_BIOME_NONE)
        return hol__fail(msg, cap, r->tile, "unknown biome", -1, 0);
    if (r->depth > HOL__MAX_DEPTH)
        return hol__fail(msg, cap, r->tile, "biome depth out of range", -1, 0);
    if (r->flags & ~HOL__F_KNOWN)
        return hol__fail(msg, cap, r->tile, "unknown flags", -1, 0);
    if ((r->flags & HOL__F_KEPT) && (!collapsed || r->game != HOL_OBJ_NONE))
        return hol__fail(msg, cap, r->tile, "a remembered seen tile that is not collapsed",
                         -1, 0);
    if (r->game != HOL_OBJ_NONE) {
        if (r->game != HOL_OBJ_FLAG && r->game != HOL_OBJ_KEY &&
            r->game != HOL_OBJ_CHEST)
            return hol__fail(msg, cap, r->tile, "unknown game object", -1, 0);
        if (!collapsed || !hol__plain_class(s) || hol__state_obj(s) == HOL_OBJ_ROCK ||
            hol__state_obj(s) == HOL_OBJ_POOL)
            return hol__fail(msg, cap, r->tile, "game object on a tile that is not free",
                             -1, 0);
    }
    if (collapsed && r->biome == HOL_BIOME_NONE)
        return hol__fail(msg, cap, r->tile, "collapsed without a biome", -1, 0);
    if (collapsed && hol__plain_class(s) && hol__weight(r->biome, s) == 0 &&
        !(r->flags & HOL__F_PLACED))
        return hol__fail(msg, cap, r->tile, "object not allowed in its biome", -1, 0);
    uint32_t dom = HOL__ALL_STATES;
    for (int d = 0; d < 4; d++) {
        hol_tile nt;
        int arr;
        int want = -1; /* the neighbour's demand on this edge */
        hol__rec nr;
        if (hol_tile_step(r->tile, d, &nt, &arr)) {
            want = HOL_CONN_NONE;
        } else if (look(ctx, nt, &nr) && nr.state != HOL__UNSET &&
                   nr.state < HOL__NSTATES) {
            want = hol__state_conn(nr.state, (arr + 2) & 3);
            /* (a seen half may come back from memory beside a partner
             * regenerated in another biome: the rule is for new pairs) */
            if (collapsed && want == HOL_CONN_LOG && nr.biome < HOL_BIOME_COUNT &&
                r->biome < HOL_BIOME_COUNT && !(r->flags & HOL__F_SEEN) &&
                !(nr.flags & HOL__F_SEEN) &&
                hol__weight(r->biome, s) == 0 && hol__weight(nr.biome, nr.state) == 0)
                return hol__fail(msg, cap, r->tile,
                                 "log where neither biome allows logs", d, 0);
        }
        if (want < 0)
            continue;
        if (collapsed && hol__state_conn(s, d) != want)
            return hol__fail(msg, cap, r->tile,
                             "connector does not match the neighbour's", d,
                             hol__state_conn(s, d));
        dom &= hol__compat(d, want);
    }
    if (!collapsed && !dom)
        return hol__fail(msg, cap, r->tile,
                         "open tile whose fixed neighbours have no completion", -1, 0);
    return HOL_OK;
}

static void hol__to_rec(const hol__entry *e, hol__rec *out)
{
    out->tile = e->tile;
    out->stamp = e->stamp;
    out->state = e->state;
    out->biome = e->biome;
    out->depth = e->depth;
    out->flags = e->flags & (uint8_t)~HOL__F_USED;
    out->game = e->game;
}

static int hol__store_lookup(const void *ctx, hol_tile t, hol__rec *out)
{
    const hol_world *w = ctx;
    int64_t i = hol__find(w, t);
    if (i < 0)
        return 0;
    hol__to_rec(&w->entries[i], out);
    return 1;
}

hol_err hol_world_check(const hol_world *w, char *msg, size_t msg_cap)
{
    if (msg && msg_cap)
        msg[0] = 0;
    uint32_t used = 0;
    for (uint32_t i = 0; i < w->cap; i++) {
        const hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED))
            continue;
        used++;
        if (hol__find(w, e->tile) != (int64_t)i)
            return hol__fail(msg, msg_cap, e->tile,
                             "store entry not reachable from its hash home", -1, 0);
        hol__rec r;
        hol__to_rec(e, &r);
        hol_err err = hol__check_rec(&r, hol__store_lookup, w, msg, msg_cap);
        if (err)
            return err;
    }
    if (used != w->count) {
        if (msg && msg_cap)
            snprintf(msg, msg_cap, "store holds %u tiles but counts %u", used,
                     w->count);
        return HOL_ECORRUPT;
    }
    return HOL_OK;
}
