/* hol_nav_arena.c - the search arena (nodes, a hash of states, a bucket
 * queue on f), walks and table descents: the lowest layer of guidance
 * above the tables (hol_nav_arena.h; hol_nav_impl.h lists the files and
 * their order). It knows the table, never the navigator.
 */
#include <string.h>

#include "hol_nav_arena.h"

/* ---- arena: nodes, hash of states, bucket queue on f ---- */

static uint64_t hol__node_hash(const hol__node *n);

/* Clearing the whole hash (2 MB at the defaults) cost more than a small
 * query; after a search only the slots of its nodes are cleared (found by
 * rehashing each node and probing for its id). */
void hol__arena_reset(hol__arena *ar)
{
    if (ar->hash_dirty) {
        memset(ar->hash, 0, ((size_t)ar->hash_mask + 1) * sizeof(uint32_t));
        ar->hash_dirty = 0;
    } else {
        for (uint32_t i = 0; i < ar->count; i++) {
            uint32_t h = (uint32_t)hol__node_hash(&ar->nodes[i]) & ar->hash_mask;
            while (ar->hash[h] != i + 1)
                h = (h + 1) & ar->hash_mask;
            ar->hash[h] = 0;
        }
    }
    ar->count = 0;
    ar->ent_n = 0;
    for (int i = 0; i < HOL__FMAX; i++)
        ar->bucket[i] = HOL__NIL;
    ar->fmin = HOL__FMAX;
}

static uint64_t hol__node_hash(const hol__node *n)
{
    uint64_t h;
    if (n->flags & HOL__INSIDE)
        h = (uint64_t)n->u.idx * UINT64_C(0x9E3779B97F4A7C15);
    else
        h = hol_tile_hash(n->u.t);
    h ^= (uint64_t)(n->o | n->cell << 2 | (n->flags & HOL__MASK) << 6) *
         UINT64_C(0xD6E8FEB86659FD93);
    h ^= h >> 29;
    return h;
}

static int hol__node_same(const hol__node *a, const hol__node *b)
{
    if (a->o != b->o || a->cell != b->cell || a->flags != b->flags)
        return 0;
    if (a->flags & HOL__INSIDE)
        return a->u.idx == b->u.idx;
    return hol_tile_eq(a->u.t, b->u.t);
}

/* Find the node equal to *n, or add it. *out_new tells which. HOL__NIL when
 * the arena is full. */
uint32_t hol__arena_intern(hol__arena *ar, const hol__node *n, int *out_new)
{
    uint32_t h = (uint32_t)hol__node_hash(n) & ar->hash_mask;
    for (;;) {
        uint32_t e = ar->hash[h];
        if (e == 0)
            break;
        if (hol__node_same(&ar->nodes[e - 1], n)) {
            *out_new = 0;
            return e - 1;
        }
        h = (h + 1) & ar->hash_mask;
    }
    if (ar->count >= ar->cap)
        return HOL__NIL;
    uint32_t id = ar->count++;
    ar->nodes[id] = *n;
    ar->hash[h] = id + 1;
    *out_new = 1;
    return id;
}

uint32_t hol__arena_relax(hol__arena *ar, const hol__node *nx, uint32_t parent, int d,
                          int g, int *out_full)
{
    int isnew;
    if (g >= HOL__FMAX / 2)
        return HOL__NIL;
    uint32_t nid = hol__arena_intern(ar, nx, &isnew);
    if (nid == HOL__NIL) {
        *out_full = 1;
        return HOL__NIL;
    }
    hol__node *q = &ar->nodes[nid];
    if (!isnew && q->g <= g)
        return HOL__NIL;
    q->g = (uint16_t)g;
    q->parent = parent;
    q->dir = (uint8_t)d;
    return nid;
}

/* Queue node id under its f; 0 when the entry pool is full. */
int hol__arena_push(hol__arena *ar, uint32_t id)
{
    if (ar->ent_n >= ar->ent_cap)
        return 0;
    uint32_t f = ar->nodes[id].f, e = ar->ent_n++;
    ar->ent[2 * e] = id;
    ar->ent[2 * e + 1] = ar->bucket[f];
    ar->bucket[f] = e;
    if (f < ar->fmin)
        ar->fmin = f;
    return 1;
}

/* Pop the newest node of the lowest f; skips entries made stale by a
 * later improvement (the node's f no longer matches its bucket). */
uint32_t hol__arena_pop(hol__arena *ar)
{
    while (ar->fmin < HOL__FMAX) {
        uint32_t e = ar->bucket[ar->fmin];
        if (e == HOL__NIL) {
            ar->fmin++;
            continue;
        }
        uint32_t id = ar->ent[2 * e];
        ar->bucket[ar->fmin] = ar->ent[2 * e + 1];
        if (ar->nodes[id].f == ar->fmin)
            return id;
    }
    return HOL__NIL;
}

void hol__nav_emit(hol__walk *w, int dir)
{
    if (w->n < w->cap)
        w->dirs[w->n++] = (uint8_t)dir;
    else
        w->overflow = 1;
}

static int hol__tab_cost(const void *tab, uint32_t idx, int o, int cell)
{
    return hol_navtab_cost((const hol_navtab *)tab, idx, o, cell);
}

/* Descend the table from (idx, o, cell) to cost 0; returns the steps taken
 * (the table cost). */
int hol__nav_descend(const hol_navtab *tab, uint32_t idx, int o, int cell, hol__walk *w)
{
    return hol__descend(tab, UINT32_MAX, hol__tab_cost, tab, idx, o, cell, w);
}

/* Path of room steps from the search root to node id, appended to w. */
void hol__arena_path(const hol__arena *ar, uint32_t id, hol__walk *w)
{
    size_t start = w->n;
    for (uint32_t x = id; ar->nodes[x].parent != HOL__NIL; x = ar->nodes[x].parent)
        hol__nav_emit(w, ar->nodes[x].dir);
    if (w->overflow)
        return;
    for (size_t i = start, j = w->n; i + 1 < j; i++, j--) {
        uint8_t t = w->dirs[i];
        w->dirs[i] = w->dirs[j - 1];
        w->dirs[j - 1] = t;
    }
}

