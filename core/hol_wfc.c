/* hol_wfc.c - the tile set and wave function collapse with backtracking.
 *
 * Tile set: 29 states (object + connectors on the four edges):
 *    0..5   plain: none, grass, flowers, rock, mushroom, pond (no connectors)
 *    6..9   log half, log connector on edge d = state - 6
 *   10..13  spring, creek on edge d;   14..17  end pool, creek on edge d
 *   18..19  straight creek {r, r+2};   20..23  bend {r, r+1}
 *   24..27  tee {r, r+1, r+2};         28      cross (all four edges)
 * For every demand vector a generator can produce - each edge free or fixed
 * to none/creek/log, at most one log, never log and creek together - some
 * state matches exactly (plain, log, spring, creek with 2..4 edges), and a
 * collapse only chooses connectors that keep every neighbour's demands in
 * that set (forward check against the neighbour's domain). So no collapsed
 * neighbourhood is ever unresolvable; tests/test_world.c checks all 4^4
 * demand vectors exhaustively, and hol_world_check verifies for every open
 * tile in the store that its fixed neighbours leave it a completion.
 *
 * Weights: a free choice draws by biome weight (hol__base) times a factor
 * for the creek edges it opens towards open neighbours: a tile no creek
 * reaches may start one only as a spring (x12; creek shapes x0), a creek
 * that arrives continues with one new edge (x100) far more often than it
 * ends (spring/pool x100 but small bases) or forks (2 new edges x3).
 *
 * A batch (hol__generate) takes the tiles within `radius` of a centre (the
 * ball) plus the ring at radius + 1, derives each uncollapsed domain from the
 * collapsed neighbours in the store, runs arc-consistency propagation, then
 * repeatedly collapses the ball tile of lowest entropy (fewest states left;
 * ties by hash(seed, tile)) to a state drawn by biome weight from
 * hash(seed, tile, attempt). A domain that becomes empty undoes the last
 * decision through a trail and bans its state (backtracking). Only tiles of
 * the running batch change; a failed batch restores everything.
 */
#include "hol_world_impl.h"

#include <string.h>

enum {
    HOL__C_NONE, HOL__C_GRASS, HOL__C_FLOWERS, HOL__C_ROCK, HOL__C_MUSHROOM,
    HOL__C_POND, HOL__C_LOG, HOL__C_SPRING, HOL__C_POOLEND, HOL__C_STRAIGHT,
    HOL__C_BEND, HOL__C_TEE, HOL__C_CROSS, HOL__C_COUNT
};

#define CR(m) ((((m) & 1) ? 1 : 0) | (((m) & 2) ? 4 : 0) | (((m) & 4) ? 16 : 0) | \
               (((m) & 8) ? 64 : 0))
#define LG(d) (2 << (2 * (d)))

typedef struct hol__state_def {
    uint8_t obj, cls;
    int8_t rot;
    uint8_t conn; /* 2 bits per edge */
} hol__state_def;

static const hol__state_def hol__states[HOL__NSTATES] = {
    {HOL_OBJ_NONE, HOL__C_NONE, -1, 0},
    {HOL_OBJ_GRASS, HOL__C_GRASS, -1, 0},
    {HOL_OBJ_FLOWERS, HOL__C_FLOWERS, -1, 0},
    {HOL_OBJ_ROCK, HOL__C_ROCK, -1, 0},
    {HOL_OBJ_MUSHROOM, HOL__C_MUSHROOM, -1, 0},
    {HOL_OBJ_POOL, HOL__C_POND, -1, 0},
    {HOL_OBJ_LOG, HOL__C_LOG, 0, LG(0)},
    {HOL_OBJ_LOG, HOL__C_LOG, 1, LG(1)},
    {HOL_OBJ_LOG, HOL__C_LOG, 2, LG(2)},
    {HOL_OBJ_LOG, HOL__C_LOG, 3, LG(3)},
    {HOL_OBJ_SPRING, HOL__C_SPRING, 0, CR(1)},
    {HOL_OBJ_SPRING, HOL__C_SPRING, 1, CR(2)},
    {HOL_OBJ_SPRING, HOL__C_SPRING, 2, CR(4)},
    {HOL_OBJ_SPRING, HOL__C_SPRING, 3, CR(8)},
    {HOL_OBJ_POOL, HOL__C_POOLEND, 0, CR(1)},
    {HOL_OBJ_POOL, HOL__C_POOLEND, 1, CR(2)},
    {HOL_OBJ_POOL, HOL__C_POOLEND, 2, CR(4)},
    {HOL_OBJ_POOL, HOL__C_POOLEND, 3, CR(8)},
    {HOL_OBJ_CREEK, HOL__C_STRAIGHT, 0, CR(5)},
    {HOL_OBJ_CREEK, HOL__C_STRAIGHT, 1, CR(10)},
    {HOL_OBJ_CREEK, HOL__C_BEND, 0, CR(3)},
    {HOL_OBJ_CREEK, HOL__C_BEND, 1, CR(6)},
    {HOL_OBJ_CREEK, HOL__C_BEND, 2, CR(12)},
    {HOL_OBJ_CREEK, HOL__C_BEND, 3, CR(9)},
    {HOL_OBJ_CREEK, HOL__C_TEE, 0, CR(7)},
    {HOL_OBJ_CREEK, HOL__C_TEE, 1, CR(14)},
    {HOL_OBJ_CREEK, HOL__C_TEE, 2, CR(13)},
    {HOL_OBJ_CREEK, HOL__C_TEE, 3, CR(11)},
    {HOL_OBJ_CREEK, HOL__C_CROSS, 0, CR(15)},
};

/* Base weights of a free choice per biome and class; 0 = never chosen
 * freely (the biome's restriction). */
static const uint16_t hol__base[HOL_BIOME_COUNT][HOL__C_COUNT] = {
    /*           none grass flow rock mush pond log spr pend str bend tee x */
    /* meadow */ {10, 40, 25, 5, 0, 2, 0, 1, 3, 30, 30, 1, 1},
    /* pine   */ {30, 15, 0, 10, 12, 0, 1, 1, 2, 30, 30, 1, 1},
    /* wetland*/ {5, 30, 8, 2, 3, 8, 0, 4, 6, 40, 40, 4, 1},
    /* autumn */ {25, 10, 5, 8, 10, 1, 1, 1, 2, 30, 30, 1, 1},
};

int hol__state_obj(int s) { return hol__states[s].obj; }
int hol__state_rot(int s) { return hol__states[s].rot; }
int hol__state_conn(int s, int edge)
{
    return (hol__states[s].conn >> (2 * (edge & 3))) & 3;
}

uint32_t hol__compat(int edge, int conn)
{
    uint32_t m = 0;
    for (int s = 0; s < HOL__NSTATES; s++)
        if (hol__state_conn(s, edge) == conn)
            m |= UINT32_C(1) << s;
    return m;
}

uint32_t hol__weight(int biome, int s)
{
    if (biome < 0 || biome >= HOL_BIOME_COUNT)
        return 0;
    return hol__base[biome][hol__states[s].cls];
}

static int hol__popcount(uint32_t x)
{
#if defined(__GNUC__)
    return __builtin_popcount(x);
#else
    int n = 0;
    for (; x; x &= x - 1)
        n++;
    return n;
#endif
}

/* The open list: ball slots not collapsed, for the lowest-entropy pick. */
static void hol__open_add(hol_world *w, uint32_t slot)
{
    w->slots[slot].open_pos = w->nopen;
    w->open[w->nopen++] = slot;
}

static void hol__open_remove(hol_world *w, uint32_t slot)
{
    uint32_t pos = w->slots[slot].open_pos;
    uint32_t last = w->open[--w->nopen];
    w->open[pos] = last;
    w->slots[last].open_pos = pos;
    w->slots[slot].open_pos = UINT32_MAX;
}

/* Connectors the states of dom allow on edge e, as a 3-bit set. */
static unsigned hol__support(uint32_t dom, int e, const uint32_t compat[4][3])
{
    unsigned set = 0;
    for (int c = 0; c < HOL_CONN_COUNT; c++)
        if (dom & compat[e][c])
            set |= 1u << c;
    return set;
}

typedef struct hol__batch {
    hol_world *w;
    uint32_t compat[4][3];
    uint32_t nqueue;
    uint64_t batch_backtracks;
    int failed; /* trail or queue overflow */
} hol__batch;

static void hol__trail_push(hol__batch *b, uint32_t slot)
{
    hol_world *w = b->w;
    if (w->ntrail >= w->max_trail) {
        b->failed = 1;
        return;
    }
    hol__entry *e = &w->entries[w->slots[slot].entry];
    hol__trail *t = &w->trail[w->ntrail++];
    t->slot = slot;
    t->dom = w->slots[slot].dom;
    t->state = e->state;
    t->biome = e->biome;
    t->depth = e->depth;
    t->pad = 0;
}

static void hol__undo(hol__batch *b, uint32_t pos)
{
    hol_world *w = b->w;
    while (w->ntrail > pos) {
        hol__trail *t = &w->trail[--w->ntrail];
        hol__entry *e = &w->entries[w->slots[t->slot].entry];
        w->slots[t->slot].dom = t->dom;
        if (t->state == HOL__UNSET && e->state != HOL__UNSET)
            hol__open_add(w, t->slot);
        e->state = t->state;
        e->biome = t->biome;
        e->depth = t->depth;
    }
}

/* Restrict slot n (whose edge en faces slot s's edge es) to what s allows.
 * Returns 0 on a contradiction. */
static int hol__narrow(hol__batch *b, uint32_t n, int en, uint32_t dom_s, int es)
{
    hol_world *w = b->w;
    unsigned sup = hol__support(dom_s, es, b->compat);
    uint32_t allowed = 0;
    for (int c = 0; c < HOL_CONN_COUNT; c++)
        if (sup & (1u << c))
            allowed |= b->compat[en][c];
    hol__slot *sn = &w->slots[n];
    uint32_t nd = sn->dom & allowed;
    if (nd == sn->dom)
        return 1;
    hol__trail_push(b, n);
    sn->dom = nd;
    if (!nd)
        return 0;
    if (!sn->ring) {
        if (b->nqueue >= w->max_trail) {
            b->failed = 1;
            return 0;
        }
        w->queue[b->nqueue++] = n;
    }
    return 1;
}

static int hol__propagate(hol__batch *b)
{
    hol_world *w = b->w;
    while (b->nqueue > 0) {
        uint32_t s = w->queue[--b->nqueue];
        hol__slot *ss = &w->slots[s];
        for (int d = 0; d < 4; d++) {
            if (ss->nb[d] < 0)
                continue;
            if (!hol__narrow(b, (uint32_t)ss->nb[d], ss->nbe[d], ss->dom, d)) {
                b->nqueue = 0;
                return 0;
            }
        }
    }
    return !b->failed;
}

/* ---- the ball ------------------------------------------------------------ */

static int64_t hol__slot_of(hol_world *w, uint32_t entry)
{
    uint32_t i = (uint32_t)hol__mix(entry, 1) & w->map_mask;
    while (w->map_key[i]) {
        if (w->map_key[i] == entry + 1)
            return w->map_val[i];
        i = (i + 1) & w->map_mask;
    }
    return -1;
}

static hol_err hol__add_slot(hol_world *w, uint32_t entry, int dist, int ring,
                             uint32_t *out_slot)
{
    if (w->nslots >= w->max_slots)
        return HOL_ENOMEM; /* cannot happen: the ball size is exact */
    uint32_t i = (uint32_t)hol__mix(entry, 1) & w->map_mask;
    while (w->map_key[i])
        i = (i + 1) & w->map_mask;
    w->map_key[i] = entry + 1;
    w->map_val[i] = w->nslots;
    hol__slot *s = &w->slots[w->nslots];
    memset(s, 0, sizeof *s);
    s->entry = entry;
    s->hash = hol__tile_hash(w->seed, w->entries[entry].tile);
    s->dist = (uint8_t)dist;
    s->ring = (uint8_t)ring;
    for (int d = 0; d < 4; d++)
        s->nb[d] = -2;
    w->entries[entry].stamp = w->stamp;
    *out_slot = w->nslots++;
    return HOL_OK;
}

static hol_err hol__build_ball(hol_world *w, hol_tile centre, int radius)
{
    memset(w->map_key, 0, (size_t)(w->map_mask + 1) * sizeof(uint32_t));
    w->nslots = 0;
    int64_t idx = hol__insert(w, centre);
    if (idx < 0)
        return HOL_ENOMEM;
    uint32_t slot;
    hol_err err = hol__add_slot(w, (uint32_t)idx, 0, radius == -1, &slot);
    if (err)
        return err;
    for (uint32_t q = 0; q < w->nslots; q++) {
        if (w->slots[q].ring)
            continue;
        hol_tile t = w->entries[w->slots[q].entry].tile;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            int arr;
            if (hol_tile_step(t, d, &nt, &arr)) {
                w->slots[q].nb[d] = -1; /* beyond the reach: the world ends */
                continue;
            }
            idx = hol__insert(w, nt);
            if (idx < 0)
                return HOL_ENOMEM;
            int64_t ns = hol__slot_of(w, (uint32_t)idx);
            if (ns < 0) {
                int nd = w->slots[q].dist + 1;
                err = hol__add_slot(w, (uint32_t)idx, nd, nd > radius, &slot);
                if (err)
                    return err;
                ns = slot;
            }
            w->slots[q].nb[d] = (int32_t)ns;
            w->slots[q].nbe[d] = (uint8_t)((arr + 2) & 3);
        }
    }
    return HOL_OK;
}

/* Initial domains: exact demands of the collapsed neighbours. */
/* The states a designer placement allows: its object, any rotation, no
 * connector (a pond, not a creek's end). */
static uint32_t hol__place_mask(int obj)
{
    uint32_t m = 0;
    for (int st = 0; st < HOL__NSTATES; st++) {
        int conn = 0;
        for (int d = 0; d < 4; d++)
            conn |= hol__state_conn(st, d);
        if (hol__state_obj(st) == obj && !conn)
            m |= UINT32_C(1) << st;
    }
    return m;
}

static hol_err hol__init_domains(hol__batch *b)
{
    hol_world *w = b->w;
    for (uint32_t i = 0; i < w->nslots; i++) {
        hol__slot *s = &w->slots[i];
        const hol__entry *e = &w->entries[s->entry];
        s->dom = e->state == HOL__UNSET ? HOL__ALL_STATES : UINT32_C(1) << e->state;
        s->pad[0] = 0; /* relevant ring slot */
        if (e->state == HOL__UNSET)
            for (uint32_t k = 0; k < w->nplaces; k++)
                if (hol_tile_eq(w->places[k].tile, e->tile))
                    s->dom &= hol__place_mask(w->places[k].object);
    }
    for (uint32_t i = 0; i < w->nslots; i++) {
        hol__slot *s = &w->slots[i];
        if (s->ring || w->entries[s->entry].state != HOL__UNSET)
            continue;
        for (int d = 0; d < 4; d++) {
            if (s->nb[d] == -1) {
                s->dom &= b->compat[d][HOL_CONN_NONE];
                continue;
            }
            hol__slot *n = &w->slots[s->nb[d]];
            int ns = w->entries[n->entry].state;
            if (ns != HOL__UNSET)
                s->dom &= b->compat[d][hol__state_conn(ns, s->nbe[d])];
            else if (n->ring)
                n->pad[0] = 1;
        }
        if (!s->dom)
            return HOL_ECORRUPT;
    }
    /* ring tiles next to open ball tiles: look at their outer neighbours */
    for (uint32_t i = 0; i < w->nslots; i++) {
        hol__slot *s = &w->slots[i];
        if (!s->pad[0])
            continue;
        hol_tile t = w->entries[s->entry].tile;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            int arr;
            if (hol_tile_step(t, d, &nt, &arr)) {
                s->dom &= b->compat[d][HOL_CONN_NONE];
                continue;
            }
            int64_t idx = hol__find(w, nt);
            int ns;
            if (idx >= 0) {
                ns = w->entries[idx].state;
            } else {
                /* not in the store: a seen tile keeps constraining */
                const hol__kept *k = hol__kept_find(w, nt);
                if (!k)
                    continue;
                ns = k->state;
            }
            if (ns != HOL__UNSET)
                s->dom &= b->compat[d][hol__state_conn(ns, (arr + 2) & 3)];
        }
        if (!s->dom)
            return HOL_ECORRUPT;
    }
    w->nopen = 0;
    for (uint32_t i = 0; i < w->nslots; i++) {
        w->slots[i].open_pos = UINT32_MAX;
        if (!w->slots[i].ring && w->entries[w->slots[i].entry].state == HOL__UNSET)
            hol__open_add(w, i);
    }
    /* arc consistency from every ball tile */
    b->nqueue = 0;
    for (uint32_t i = 0; i < w->nslots; i++)
        if (!w->slots[i].ring)
            w->queue[b->nqueue++] = i;
    if (!hol__propagate(b))
        return HOL_ECORRUPT;
    return HOL_OK;
}

/* ---- one collapse --------------------------------------------------------- */

static void hol__assign_biome(hol__batch *b, uint32_t slot)
{
    hol_world *w = b->w;
    hol__slot *s = &w->slots[slot];
    hol__entry *e = &w->entries[s->entry];
    if (e->biome == HOL_BIOME_NONE) {
        uint64_t h = hol__mix(s->hash, 0xB10E);
        hol__trail_push(b, slot);
        e->biome = (uint8_t)(h % HOL_BIOME_COUNT);
        e->depth = (uint8_t)(2 + (h >> 16) % (HOL__MAX_DEPTH - 1));
    }
    if (e->depth == 0)
        return;
    for (int d = 0; d < 4; d++) {
        if (s->nb[d] < 0)
            continue;
        hol__entry *n = &w->entries[w->slots[s->nb[d]].entry];
        if (n->biome != HOL_BIOME_NONE)
            continue;
        hol__trail_push(b, (uint32_t)s->nb[d]);
        n->biome = e->biome;
        n->depth = (uint8_t)(e->depth - 1);
    }
}

/* Choose a state for slot: -1 if no candidate is left. */
static int hol__choose(hol__batch *b, uint32_t slot)
{
    hol_world *w = b->w;
    hol__slot *s = &w->slots[slot];
    const hol__entry *e = &w->entries[s->entry];
    uint32_t weight[HOL__NSTATES];
    uint64_t total = 0;
    uint32_t zero_ok = 0;
    int placed = 0; /* a designer's object: allowed whatever the biome */
    for (uint32_t k = 0; k < w->nplaces; k++)
        placed |= hol_tile_eq(w->places[k].tile, e->tile);
    for (int st = 0; st < HOL__NSTATES; st++) {
        weight[st] = 0;
        if (!(s->dom & (UINT32_C(1) << st)))
            continue;
        int ok = 1, fresh = 0, kept = 0;
        for (int d = 0; d < 4 && ok; d++) {
            int c = hol__state_conn(st, d);
            if (s->nb[d] == -1) {
                ok = c == HOL_CONN_NONE;
                continue;
            }
            const hol__slot *n = &w->slots[s->nb[d]];
            if (!(hol__support(n->dom, s->nbe[d], b->compat) & (1u << c)))
                ok = 0;
            else if (c == HOL_CONN_CREEK) {
                if (w->entries[n->entry].state == HOL__UNSET)
                    fresh++;
                else
                    kept++;
            }
        }
        if (!ok)
            continue;
        uint32_t base = hol__weight(e->biome, st);
        if (placed && base == 0)
            base = 1;
        uint32_t mult;
        int cls = hol__states[st].cls;
        if (kept == 0 && cls >= HOL__C_STRAIGHT)
            mult = 0; /* creeks begin at springs */
        else if (kept == 0 && cls == HOL__C_SPRING)
            mult = 12;
        else if (kept == 0 && cls == HOL__C_POOLEND)
            mult = 0;
        else
            mult = fresh <= 1 ? 100 : fresh == 2 ? 3 : 1;
        weight[st] = base * mult;
        total += weight[st];
        if (cls >= HOL__C_LOG)
            zero_ok |= UINT32_C(1) << st;
    }
    uint64_t r = hol__mix(s->hash, 0xC401CE + (uint64_t)s->pad[1]);
    s->pad[1]++;
    if (total == 0) {
        /* only forced continuations left: pick uniformly among them */
        int n = hol__popcount(zero_ok);
        if (n == 0)
            return -1;
        int pick = (int)(r % (uint64_t)n);
        for (int st = 0; st < HOL__NSTATES; st++)
            if ((zero_ok >> st) & 1)
                if (pick-- == 0)
                    return st;
        return -1;
    }
    uint64_t x = r % total;
    for (int st = 0; st < HOL__NSTATES; st++) {
        if (x < weight[st])
            return st;
        x -= weight[st];
    }
    return -1;
}

/* Lowest entropy first: fewest states left, ties by hash. */
static int64_t hol__pick(hol_world *w)
{
    int64_t best = -1;
    int best_n = 99;
    uint64_t best_h = 0;
    for (uint32_t k = 0; k < w->nopen; k++) {
        uint32_t i = w->open[k];
        const hol__slot *s = &w->slots[i];
        int n = hol__popcount(s->dom);
        if (n < best_n || (n == best_n && s->hash < best_h)) {
            best = i;
            best_n = n;
            best_h = s->hash;
        }
    }
    return best;
}

#define HOL__BACKTRACK_BUDGET 20000

/* Undo decisions until one can be banned without a contradiction. */
static int hol__backtrack(hol__batch *b)
{
    hol_world *w = b->w;
    while (w->ndec > 0 && !b->failed) {
        hol__decision dd = w->dec[--w->ndec];
        hol__undo(b, dd.trail_pos);
        b->batch_backtracks++;
        if (b->batch_backtracks > HOL__BACKTRACK_BUDGET)
            return 0;
        hol__trail_push(b, dd.slot);
        w->slots[dd.slot].dom &= ~(UINT32_C(1) << dd.state);
        if (!w->slots[dd.slot].dom)
            continue;
        b->nqueue = 0;
        w->queue[b->nqueue++] = dd.slot;
        if (hol__propagate(b))
            return 1;
    }
    return 0;
}

hol_err hol__generate(hol_world *w, hol_tile centre, int radius, int mark_seen)
{
    hol__batch b;
    memset(&b, 0, sizeof b);
    b.w = w;
    for (int d = 0; d < 4; d++)
        for (int c = 0; c < HOL_CONN_COUNT; c++)
            b.compat[d][c] = hol__compat(d, c);
    hol_err err = hol__build_ball(w, centre, radius);
    if (err)
        return err;
    w->ntrail = 0;
    w->ndec = 0;
    err = hol__init_domains(&b);
    if (err) {
        hol__undo(&b, 0);
        return err;
    }
    for (;;) {
        int64_t pick = hol__pick(w);
        if (pick < 0)
            break;
        uint32_t slot = (uint32_t)pick;
        uint32_t pos = w->ntrail;
        hol__assign_biome(&b, slot);
        int st = b.failed ? -1 : hol__choose(&b, slot);
        int ok = st >= 0;
        if (ok) {
            hol__decision *dd = &w->dec[w->ndec++];
            dd->trail_pos = pos;
            dd->slot = slot;
            dd->state = (uint32_t)st;
            dd->choices = (uint32_t)hol__popcount(w->slots[slot].dom);
            hol__trail_push(&b, slot);
            w->slots[slot].dom = UINT32_C(1) << st;
            w->entries[w->slots[slot].entry].state = (uint8_t)st;
            hol__open_remove(w, slot);
            b.nqueue = 0;
            w->queue[b.nqueue++] = slot;
            ok = hol__propagate(&b);
            /* testing: declare a contradiction at random, but only where
             * backtracking can absorb it (a ban leaves this domain, or the
             * previous decision's, non-empty), so the batch stays
             * satisfiable and the rejections exercise one or two levels */
            if (ok && w->reject_per_mille &&
                (dd->choices >= 2 ||
                 (w->ndec >= 2 && w->dec[w->ndec - 2].choices >= 2)) &&
                hol__mix(w->slots[slot].hash, ++w->choice_counter) % 1000 <
                    w->reject_per_mille)
                ok = 0;
        } else {
            hol__undo(&b, pos);
        }
        if (!ok && !hol__backtrack(&b)) {
            w->backtracks += b.batch_backtracks;
            hol__undo(&b, 0);
            w->ndec = 0;
            return HOL_EBUDGET;
        }
    }
    w->backtracks += b.batch_backtracks;
    w->collapsed += w->ndec;
    for (uint32_t i = 0; i < w->nslots; i++)
        if (!w->slots[i].ring && mark_seen)
            w->entries[w->slots[i].entry].flags |= HOL__F_SEEN;
    for (uint32_t i = 0; i < w->nslots && w->nplaces; i++) {
        hol__entry *e = &w->entries[w->slots[i].entry];
        for (uint32_t k = 0; k < w->nplaces; k++)
            if (e->state != HOL__UNSET && hol_tile_eq(w->places[k].tile, e->tile))
                e->flags |= HOL__F_PLACED;
    }
    w->ntrail = 0;
    w->ndec = 0;
    return HOL_OK;
}

/* The content of a collapsed entry: the tile set (here) and the trees
 * (hol_world_tree.c, which does not use the tile set). */
void hol__fill_content(const hol_world *w, const hol__entry *e,
                       hol_tile_content *out)
{
    int s = e->state;
    out->biome = e->biome < HOL_BIOME_COUNT ? e->biome : HOL_BIOME_MEADOW;
    out->object = (uint8_t)(e->game ? e->game : hol__state_obj(s));
    int rot = hol__state_rot(s);
    if (rot < 0)
        rot = (int)(hol__tile_hash(w->seed ^ 0x5070, e->tile) & 3);
    out->rotation = (uint8_t)rot;
    out->log_partner = -1;
    for (int d = 0; d < 4; d++) {
        out->conn[d] = (uint8_t)hol__state_conn(s, d);
        if (out->conn[d] == HOL_CONN_LOG)
            out->log_partner = (int8_t)d;
    }
    uint16_t p = (e->flags & HOL__F_TREES) ? e->trees
                                           : hol__trees_packed(w->seed, e->tile);
    for (int c = 0; c < 4; c++) {
        out->tree[c].kind = (uint8_t)((p >> (4 * c)) & 3);
        out->tree[c].size = (uint8_t)((p >> (4 * c + 2)) & 3);
    }
}

/* ---- public entry points ---------------------------------------------------- */

hol_err hol_world_update(hol_world *w, const hol_room *room)
{
    if (!w || !hol_room_ok(room) || hol_tile_q(room->tile) != w->q)
        return HOL_EARG;
    if (w->ready && hol_tile_eq(room->tile, w->user.tile)) {
        w->user = *room; /* same tile: its ball is already collapsed */
        return HOL_OK;
    }
    w->stamp++;
    hol__maybe_evict(w);
    hol_err err = hol__generate(w, room->tile, w->radius, 1);
    if (err)
        return err;
    w->user = *room;
    w->ready = 1;
    w->updates++;
    return HOL_OK;
}

hol_err hol_world_get(hol_world *w, hol_tile t, hol_tile_content *out)
{
    if (!w || !out || hol_tile_q(t) != w->q)
        return HOL_EARG;
    int64_t idx = hol__find(w, t);
    if (idx < 0 || w->entries[idx].state == HOL__UNSET) {
        hol__maybe_evict(w);
        hol_err err = hol__generate(w, t, 0, 1);
        if (err)
            return err;
        idx = hol__find(w, t);
        if (idx < 0)
            return HOL_ENOMEM;
    }
    hol__entry *e = &w->entries[idx];
    e->stamp = w->stamp;
    if (!(e->flags & HOL__F_TREES)) {
        e->trees = hol__trees_packed(w->seed, t);
        e->flags |= HOL__F_TREES;
    }
    hol__fill_content(w, e, out);
    return HOL_OK;
}

hol_err hol_world_peek(const hol_world *w, hol_tile t, hol_tile_content *out)
{
    if (!w || !out)
        return HOL_EARG;
    int64_t idx = hol__find(w, t);
    if (idx < 0 || w->entries[idx].state == HOL__UNSET)
        return HOL_EARG;
    hol__fill_content(w, &w->entries[idx], out);
    return HOL_OK;
}

static int hol__free_for_game(const hol__entry *e)
{
    if (e->state == HOL__UNSET || e->game != HOL_OBJ_NONE)
        return 0;
    int o = hol__states[e->state].obj;
    return hol__states[e->state].conn == 0 &&
           (o == HOL_OBJ_NONE || o == HOL_OBJ_GRASS || o == HOL_OBJ_FLOWERS ||
            o == HOL_OBJ_MUSHROOM);
}

hol_err hol_world_reserve(hol_world *w, hol_tile t, int max_dist,
                          hol_object obj, hol_tile *out_tile)
{
    if (!w || !out_tile || max_dist < 0 ||
        (obj != HOL_OBJ_FLAG && obj != HOL_OBJ_KEY && obj != HOL_OBJ_CHEST) ||
        hol_tile_q(t) != w->q)
        return HOL_EARG;
    if (max_dist > w->radius)
        max_dist = w->radius;
    uint32_t n = 1, lvl_end = 1;
    int dist = 0;
    w->reserve_tiles[0] = t;
    for (uint32_t q = 0; q < n; q++) {
        if (q == lvl_end) {
            dist++;
            lvl_end = n;
        }
        hol_tile_content c;
        hol_err err = hol_world_get(w, w->reserve_tiles[q], &c);
        if (err == HOL_ENOMEM || err == HOL_EBUDGET)
            return err;
        if (!err) {
            int64_t idx = hol__find(w, w->reserve_tiles[q]);
            if (idx >= 0 && hol__free_for_game(&w->entries[idx])) {
                w->entries[idx].game = (uint8_t)obj;
                *out_tile = w->reserve_tiles[q];
                return HOL_OK;
            }
        }
        if (dist >= max_dist)
            continue;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            if (hol_tile_step(w->reserve_tiles[q], d, &nt, NULL))
                continue;
            int seen = 0;
            for (uint32_t i = 0; i < n && !seen; i++)
                seen = hol_tile_eq(w->reserve_tiles[i], nt);
            if (!seen && n < w->max_reserve)
                w->reserve_tiles[n++] = nt;
        }
    }
    return HOL_ENOMEM;
}

hol_err hol_world_release(hol_world *w, hol_tile t)
{
    if (!w)
        return HOL_EARG;
    int64_t idx = hol__find(w, t);
    if (idx < 0 || w->entries[idx].game == HOL_OBJ_NONE)
        return HOL_EARG;
    w->entries[idx].game = HOL_OBJ_NONE;
    return HOL_OK;
}
