/* hol_world.c - the world's lifecycle and its fixed-capacity tile store.
 *
 * The store is an open-addressing table (linear probing, power-of-two
 * capacity, backward-shift deletion) of hol__entry keyed by the tile word.
 * Full-store policy (see hol_world.h): at the start of an update (or of a
 * get that must generate), a store over 3/4 full starts evicting the
 * entries with the oldest stamps (the update counter when last used), whole
 * stamp buckets at a time, until at most 1/2 remains; entries stamped by the
 * last or the running update and entries holding a game object are never
 * evicted. The sweep is incremental: three passes over the table, cap/256
 * slots per call (at most about 0.1 ms per update at 2^20 tiles, not one
 * pause of tens of milliseconds); over 7/8 full it finishes at once.
 */
#include "hol_world_impl.h"
#include "hol_hash.h"

#include <stdlib.h>
#include <string.h>

/* Tiles within distance r of a tile of {4,q}: 1 + 4 + 12 + 28 + ... in
 * {4,5} (SPEC 3 and 7). */
uint32_t hol__ball_size(int q, int radius)
{
    uint64_t n = 0;
    for (int d = 0; d <= (radius > 9 ? 9 : radius); d++)
        n += hol_tile_count_at(q, d);
    return (uint32_t)n;
}

uint64_t hol__mix(uint64_t a, uint64_t b)
{
    return hol_mix64(a ^ (b + UINT64_C(0x9E3779B97F4A7C15) + (a << 6) + (a >> 2)));
}

uint64_t hol__tile_hash(uint64_t seed, hol_tile t)
{
    return hol__mix(hol__mix(seed, t.bits[0]), t.bits[1]);
}

int hol__tile_valid(hol_tile t)
{
    int len = hol_tile_dist0(t);
    int q = hol_tile_q(t);
    if (!q || len > HOL_TILE_MAX_DIST)
        return 0;
    char buf[HOL_TILE_ADDR_MAX];
    hol_tile back;
    hol_tile_print(t, buf);
    if (hol_tile_parse_q(q, buf, -1, &back))
        return 0;
    return hol_tile_eq(back, t); /* also rejects stray high bits */
}

/* ---- layout ------------------------------------------------------------ */

typedef struct hol__layout {
    uint32_t cap, max_slots, map_size, max_trail, max_reserve, kept_size, kept_max;
    size_t off_entries, off_slots, off_map_key, off_map_val, off_trail, off_dec,
        off_queue, off_open, off_reserve, off_kept, total;
} hol__layout;

static size_t hol__align(size_t n) { return (n + 15) & ~(size_t)15; }

/* The next part of the block: its offset, *off moved past its bytes
 * (aligned to 16). */
static size_t hol__take(size_t *off, size_t bytes)
{
    size_t at = *off;
    *off += hol__align(bytes);
    return at;
}

static int hol__plan(const hol_world_desc *desc, hol__layout *l)
{
    int radius = desc->radius ? desc->radius : HOL_WORLD_DEFAULT_RADIUS;
    int q = desc->tiling_q ? desc->tiling_q : HOL_TILING_DEFAULT_Q;
    if (radius < 1 || radius > HOL_WORLD_MAX_RADIUS || q < HOL_TILING_MIN_Q ||
        q > HOL_TILING_MAX_Q)
        return 0;
    uint64_t want = desc->capacity ? desc->capacity : HOL_WORLD_DEFAULT_CAPACITY;
    if (want > (UINT64_C(1) << 31))
        return 0;
    uint64_t minimum = (uint64_t)8 * hol__ball_size(q, radius + 1);
    if (want < minimum)
        want = minimum;
    if (want < HOL_WORLD_MIN_CAPACITY)
        want = HOL_WORLD_MIN_CAPACITY;
    uint64_t cap = 1;
    while (cap < want)
        cap <<= 1;
    l->cap = (uint32_t)cap;
    l->max_slots = hol__ball_size(q, radius + 1);
    l->map_size = 1;
    while (l->map_size < 2 * l->max_slots)
        l->map_size <<= 1;
    l->max_trail = 32 * l->max_slots + 64;
    l->max_reserve = hol__ball_size(q, radius);
    size_t off = hol__align(sizeof(hol_world));
    l->off_entries = hol__take(&off, (size_t)l->cap * sizeof(hol__entry));
    l->off_slots = hol__take(&off, (size_t)l->max_slots * sizeof(hol__slot));
    l->off_map_key = hol__take(&off, (size_t)l->map_size * sizeof(uint32_t));
    l->off_map_val = hol__take(&off, (size_t)l->map_size * sizeof(uint32_t));
    l->off_trail = hol__take(&off, (size_t)l->max_trail * sizeof(hol__trail));
    l->off_dec = hol__take(&off, (size_t)(l->max_slots + 1) * sizeof(hol__decision));
    l->off_queue = hol__take(&off, (size_t)l->max_trail * sizeof(uint32_t));
    l->off_open = hol__take(&off, (size_t)l->max_slots * sizeof(uint32_t));
    l->off_reserve = hol__take(&off, (size_t)l->max_reserve * sizeof(hol_tile));
    /* the memory of seen tiles: a table at most 3/4 full */
    uint64_t keep = desc->keep_capacity ? desc->keep_capacity : l->cap;
    if (keep > (UINT64_C(1) << 30))
        return 0;
    uint64_t ks = 16;
    while (ks * 3 / 4 < keep)
        ks <<= 1;
    l->kept_size = (uint32_t)ks;
    l->kept_max = (uint32_t)keep;
    l->off_kept = hol__take(&off, (size_t)ks * sizeof(hol__kept));
    l->total = off;
    return 1;
}

uint32_t hol_world_capacity_of(const hol_world_desc *desc)
{
    hol__layout l;
    if (!desc || !hol__plan(desc, &l))
        return 0;
    return l.cap;
}

size_t hol_world_mem_size(const hol_world_desc *desc)
{
    hol__layout l;
    if (!desc || !hol__plan(desc, &l))
        return 0;
    return l.total;
}

/* hol_world_init; zeroed: the store and the table of seen tiles hold no
 * used entry (mem holds zeros: calloc; or an empty world's store), so
 * they are not cleared (the world command's store is over 100 MB: its
 * clear was nearly all of a short run's time; the app's 14 MB, a fifth of
 * a short play's start). The struct itself is always cleared. */
static hol_err hol__world_init(void *mem, size_t size, const hol_world_desc *desc,
                               hol_world **out_world, int zeroed)
{
    hol__layout l;
    if (!mem || !desc || !out_world || ((uintptr_t)mem & 15) ||
        !hol__plan(desc, &l))
        return HOL_EARG;
    if (size < l.total)
        return HOL_ENOMEM;
    char *base = mem;
    memset(base, 0, zeroed ? l.off_entries : l.off_slots); /* struct (and store) */
    hol_world *w = mem;
    if (desc->nplaces > HOL_WORLD_MAX_PLACES || (desc->nplaces && !desc->places))
        return HOL_EARG;
    for (uint32_t i = 0; i < desc->nplaces; i++) {
        int o = desc->places[i].object;
        if (o != HOL_OBJ_NONE && o != HOL_OBJ_GRASS && o != HOL_OBJ_FLOWERS &&
            o != HOL_OBJ_ROCK && o != HOL_OBJ_MUSHROOM && o != HOL_OBJ_POOL)
            return HOL_EARG;
        for (uint32_t j = 0; j < i; j++)
            if (hol_tile_eq(desc->places[i].tile, desc->places[j].tile))
                return HOL_EARG;
        int pq = desc->tiling_q ? desc->tiling_q : HOL_TILING_DEFAULT_Q;
        if (hol_tile_q(desc->places[i].tile) != pq)
            return HOL_EARG;
    }
    w->seed = desc->seed;
    w->nplaces = desc->nplaces;
    if (desc->nplaces)
        memcpy(w->places, desc->places, desc->nplaces * sizeof w->places[0]);
    w->radius = desc->radius ? desc->radius : HOL_WORLD_DEFAULT_RADIUS;
    w->cap = l.cap;
    w->mask = l.cap - 1;
    w->reject_per_mille = desc->test_reject_per_mille > 1000
                              ? 1000
                              : desc->test_reject_per_mille;
    w->q = desc->tiling_q ? desc->tiling_q : HOL_TILING_DEFAULT_Q;
    hol_room_start_in(w->q, 0, 0, &w->user);
    w->entries = (hol__entry *)(void *)(base + l.off_entries);
    w->slots = (hol__slot *)(void *)(base + l.off_slots);
    w->max_slots = l.max_slots;
    w->map_key = (uint32_t *)(void *)(base + l.off_map_key);
    w->map_val = (uint32_t *)(void *)(base + l.off_map_val);
    w->map_mask = l.map_size - 1;
    w->trail = (hol__trail *)(void *)(base + l.off_trail);
    w->max_trail = l.max_trail;
    w->dec = (hol__decision *)(void *)(base + l.off_dec);
    w->queue = (uint32_t *)(void *)(base + l.off_queue);
    w->open = (uint32_t *)(void *)(base + l.off_open);
    w->reserve_tiles = (hol_tile *)(void *)(base + l.off_reserve);
    w->max_reserve = l.max_reserve;
    w->kept = (hol__kept *)(void *)(base + l.off_kept);
    if (!zeroed)
        memset(w->kept, 0, (size_t)l.kept_size * sizeof(hol__kept));
    w->kept_mask = l.kept_size - 1;
    w->kept_max = l.kept_max;
    w->bytes = l.total;
    *out_world = w;
    return HOL_OK;
}

hol_err hol_world_init(void *mem, size_t size, const hol_world_desc *desc,
                       hol_world **out_world)
{
    return hol__world_init(mem, size, desc, out_world, desc && desc->mem_zeroed);
}

hol_err hol_world_reinit(void *mem, size_t size, const hol_world_desc *desc,
                         hol_world **out_world)
{
    hol__layout l;
    if (!mem || !desc || !out_world || ((uintptr_t)mem & 15) || !hol__plan(desc, &l))
        return HOL_EARG;
    /* an empty store (every entry removed is zeroed; nothing remembered)
     * at the same place and size as desc's: no entry is in use (a failed
     * init left cap 0: cleared then) */
    hol_world *w = mem;
    int empty = w->count == 0 && w->kept_count == 0 && w->cap == l.cap &&
                (size_t)w->kept_mask + 1 == l.kept_size &&
                (char *)w->kept == (char *)mem + l.off_kept;
    void (*free_fn)(void *, void *) = w->free_fn;
    void *free_user = w->free_user;
    hol_err err = hol__world_init(mem, size, desc, out_world, empty);
    w->free_fn = free_fn; /* still the caller's to destroy, if made */
    w->free_user = free_user;
    return err;
}

static void *hol__default_alloc(size_t size, void *user)
{
    (void)user;
    return calloc(1, size); /* zero pages, mapped when first written */
}

static void hol__default_free(void *ptr, void *user)
{
    (void)user;
    free(ptr);
}

hol_err hol_world_make(const hol_world_desc *desc, hol_world **out_world)
{
    size_t size = hol_world_mem_size(desc);
    if (!size || !out_world)
        return HOL_EARG;
    void *(*alloc)(size_t, void *) = desc->allocator.alloc;
    void (*free_fn)(void *, void *) = desc->allocator.free;
    if (!alloc || !free_fn) {
        alloc = hol__default_alloc;
        free_fn = hol__default_free;
    }
    void *mem = alloc(size, desc->allocator.user);
    if (!mem)
        return HOL_ENOMEM;
    hol_world *w;
    hol_err err = hol__world_init(mem, size, desc, &w, alloc == hol__default_alloc);
    if (err) {
        free_fn(mem, desc->allocator.user);
        return err;
    }
    w->free_fn = free_fn;
    w->free_user = desc->allocator.user;
    *out_world = w;
    return HOL_OK;
}

void hol_world_destroy(hol_world *w)
{
    if (w && w->free_fn)
        w->free_fn(w, w->free_user);
}

uint64_t hol_world_seed(const hol_world *w) { return w->seed; }
int hol_world_tiling(const hol_world *w) { return w->q; }
int hol_world_radius(const hol_world *w) { return w->radius; }
hol_room hol_world_user(const hol_world *w) { return w->user; }

void hol_world_get_stats(const hol_world *w, hol_world_stats *out)
{
    memset(out, 0, sizeof *out);
    out->tiles_collapsed = w->collapsed;
    out->backtracks = w->backtracks;
    out->updates = w->updates;
    out->evicted = w->evicted;
    out->count = w->count;
    out->kept = w->kept_count;
    out->keep_capacity = w->kept_max;
    out->keep_lost = w->kept_lost;
    out->capacity = w->cap;
    out->bytes = w->bytes;
}

/* ---- the table ---------------------------------------------------------- */

static uint32_t hol__home(const hol_world *w, hol_tile t)
{
    return (uint32_t)hol_tile_hash(t) & w->mask;
}

int64_t hol__find(const hol_world *w, hol_tile t)
{
    uint32_t i = hol__home(w, t);
    for (uint32_t n = 0; n < w->cap; n++, i = (i + 1) & w->mask) {
        const hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED))
            return -1;
        if (hol_tile_eq(e->tile, t))
            return i;
    }
    return -1;
}

/* ---- the memory of seen tiles -------------------------------------------- */

static uint32_t hol__kept_home(const hol_world *w, hol_tile t)
{
    uint64_t h = hol_tile_hash(t);
    return (uint32_t)(h ^ (h >> 32)) & w->kept_mask;
}

const hol__kept *hol__kept_find(const hol_world *w, hol_tile t)
{
    if (!w->kept_count)
        return NULL;
    for (uint32_t i = hol__kept_home(w, t);; i = (i + 1) & w->kept_mask) {
        const hol__kept *k = &w->kept[i];
        if (!k->used)
            return NULL;
        if (hol_tile_eq(k->tile, t))
            return k;
    }
}

/* Remember a seen tile leaving the store (its state is final). */
void hol__keep(hol_world *w, const hol__entry *e)
{
    uint32_t i = hol__kept_home(w, e->tile);
    for (;; i = (i + 1) & w->kept_mask) {
        hol__kept *k = &w->kept[i];
        if (k->used && hol_tile_eq(k->tile, e->tile))
            return; /* already remembered, and it never changes */
        if (!k->used)
            break;
    }
    if (w->kept_count >= w->kept_max) {
        w->kept_lost++;
        return;
    }
    hol__kept *k = &w->kept[i];
    k->tile = e->tile;
    k->state = e->state;
    k->biome = e->biome;
    k->depth = e->depth;
    k->used = (uint8_t)(1 | ((e->flags & HOL__F_PLACED) ? 2 : 0));
    w->kept_count++;
}

int64_t hol__insert(hol_world *w, hol_tile t)
{
    uint32_t i = hol__home(w, t);
    for (uint32_t n = 0; n < w->cap; n++, i = (i + 1) & w->mask) {
        hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED)) {
            if (w->count + 1 >= w->cap)
                return -1; /* always keep one empty slot */
            memset(e, 0, sizeof *e);
            e->tile = t;
            e->state = HOL__UNSET;
            e->biome = HOL_BIOME_NONE;
            e->flags = HOL__F_USED;
            e->stamp = w->stamp;
            /* a seen tile coming back: exactly as it was */
            const hol__kept *k = hol__kept_find(w, t);
            if (k) {
                e->state = k->state;
                e->biome = k->biome;
                e->depth = k->depth;
                e->flags |= (uint8_t)(HOL__F_SEEN | ((k->used & 2) ? HOL__F_PLACED : 0));
            }
            w->count++;
            return i;
        }
        if (hol_tile_eq(e->tile, t))
            return i;
    }
    return -1;
}

/* Backward-shift deletion of slot i. */
static void hol__delete(hol_world *w, uint32_t i)
{
    uint32_t j = i;
    for (;;) {
        j = (j + 1) & w->mask;
        hol__entry *e = &w->entries[j];
        if (!(e->flags & HOL__F_USED))
            break;
        uint32_t k = hol__home(w, e->tile);
        /* may e move into the hole at i? only if its home is not in (i, j] */
        int between = i <= j ? (k > i && k <= j) : (k > i || k <= j);
        if (!between) {
            w->entries[i] = *e;
            i = j;
        }
    }
    memset(&w->entries[i], 0, sizeof w->entries[i]);
    w->count--;
}

static int hol__evictable(const hol_world *w, const hol__entry *e)
{
    return (e->flags & HOL__F_USED) && e->game == HOL_OBJ_NONE &&
           e->stamp + 1 < w->stamp;
}

/* One bounded step of the sweep: at most `budget` table slots. The sweep
 * has three passes - stamp range, stamp histogram (256 buckets), eviction
 * of the stamps below the bucket where at least count - cap/2 entries are
 * reached - and may span many calls: between calls the table stays valid,
 * and deleting only at the cursor keeps unvisited entries ahead of it. */
static void hol__sweep_step(hol_world *w, uint32_t budget)
{
    uint32_t end = w->sweep_pos + budget;
    if (end > w->cap || end < w->sweep_pos)
        end = w->cap;
    uint32_t i = w->sweep_pos;
    if (w->sweep_phase == 1) {
        for (; i < end; i++) {
            const hol__entry *e = &w->entries[i];
            if (!hol__evictable(w, e))
                continue;
            w->sweep_n++;
            if (e->stamp < w->sweep_lo)
                w->sweep_lo = e->stamp;
            if (e->stamp > w->sweep_hi)
                w->sweep_hi = e->stamp;
        }
        if (i == w->cap) {
            w->sweep_phase = w->sweep_n ? 2 : 0;
            i = 0;
            memset(w->sweep_hist, 0, sizeof w->sweep_hist);
        }
    } else if (w->sweep_phase == 2) {
        uint64_t width = ((uint64_t)w->sweep_hi - w->sweep_lo) / 256 + 1;
        for (; i < end; i++) {
            const hol__entry *e = &w->entries[i];
            if (hol__evictable(w, e) && e->stamp >= w->sweep_lo &&
                e->stamp <= w->sweep_hi)
                w->sweep_hist[(e->stamp - w->sweep_lo) / width]++;
        }
        if (i == w->cap) {
            uint32_t need = w->count > w->cap / 2 ? w->count - w->cap / 2 : 0;
            uint32_t sum = 0, b = 0;
            for (; b < 255; b++) {
                sum += w->sweep_hist[b];
                if (sum >= need)
                    break;
            }
            uint64_t limit = w->sweep_lo + (uint64_t)(b + 1) * width;
            w->sweep_limit = limit > UINT32_MAX ? UINT32_MAX : (uint32_t)limit;
            w->sweep_phase = 3;
            i = 0;
        }
    } else if (w->sweep_phase == 3) {
        for (; i < end; i++) {
            while (hol__evictable(w, &w->entries[i]) &&
                   w->entries[i].stamp < w->sweep_limit) {
                if ((w->entries[i].flags & HOL__F_SEEN) && w->entries[i].state != HOL__UNSET)
                    hol__keep(w, &w->entries[i]);
                hol__delete(w, i);
                w->evicted++;
            }
        }
        if (i == w->cap)
            w->sweep_phase = 0;
    }
    w->sweep_pos = i;
}

void hol__maybe_evict(hol_world *w)
{
    if (w->sweep_phase == 0) {
        if (w->count <= w->cap - w->cap / 4)
            return;
        w->sweep_phase = 1;
        w->sweep_pos = 0;
        w->sweep_lo = UINT32_MAX;
        w->sweep_hi = 0;
        w->sweep_n = 0;
    }
    if (w->count > w->cap - w->cap / 8) {
        /* growing faster than the sweep: finish it now */
        while (w->sweep_phase != 0)
            hol__sweep_step(w, w->cap);
        return;
    }
    uint32_t budget = w->cap / 256 > 4096 ? w->cap / 256 : 4096;
    hol__sweep_step(w, budget);
}

/* ---- names -------------------------------------------------------------- */

const char *hol_biome_name(int biome)
{
    static const char *const n[] = {"meadow", "pine", "wetland", "autumn"};
    return biome >= 0 && biome < HOL_BIOME_COUNT ? n[biome] : "?";
}

const char *hol_object_name(int object)
{
    static const char *const n[] = {"none",  "grass",    "flowers", "log",
                                    "creek", "spring",   "pool",    "rock",
                                    "mushroom", "flag",  "key",     "chest"};
    return object >= 0 && object < HOL_OBJ_COUNT ? n[object] : "?";
}

const char *hol_conn_name(int conn)
{
    static const char *const n[] = {"-", "creek", "log"};
    return conn >= 0 && conn < HOL_CONN_COUNT ? n[conn] : "?";
}

char hol_conn_char(int conn)
{
    return conn >= 0 && conn < HOL_CONN_COUNT ? "-cl"[conn] : '?';
}
