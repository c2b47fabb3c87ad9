/* plain_astar.h - the original system's guidance method, as a reference:
 * plain A* over room states (tile, room orientation, cell) with the tile
 * distance to the target as the heuristic (admissible: a room step moves
 * to a neighbouring tile or stays on the tile). Used by bench_nav for the
 * side-by-side figure and by test_nav to check that it and hol_nav agree
 * on the fewest steps. Header-only, allocates (test code); not the app's.
 */
#ifndef HOL_TEST_PLAIN_ASTAR_H
#define HOL_TEST_PLAIN_ASTAR_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_hash.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"

typedef struct pa_node {
    hol_room r;
    int g;
    int used;
} pa_node;

typedef struct pa_heap_item {
    int f, g;
    uint32_t node;
} pa_heap_item;

typedef struct plain_astar {
    pa_node *nodes; /* open addressing on the room state */
    uint32_t mask;
    uint32_t *touched; /* slots used by the last query (cleared next time) */
    size_t ntouched;
    pa_heap_item *heap;
    size_t nheap, cap_heap;
} plain_astar;

static int pa_init(plain_astar *a, uint32_t log2_cap)
{
    memset(a, 0, sizeof *a);
    a->mask = (1u << log2_cap) - 1;
    a->nodes = calloc((size_t)a->mask + 1, sizeof *a->nodes);
    a->cap_heap = (size_t)a->mask + 1;
    a->heap = malloc(a->cap_heap * sizeof *a->heap);
    a->touched = malloc(((size_t)a->mask + 1) * sizeof *a->touched);
    return a->nodes && a->heap && a->touched ? 0 : -1;
}

static void pa_fini(plain_astar *a)
{
    free(a->nodes);
    free(a->heap);
    free(a->touched);
}

static uint32_t pa_slot(const plain_astar *a, const hol_room *r)
{
    uint64_t h = hol_tile_hash(r->tile) ^ ((uint64_t)r->orient * 0x9E3779B97F4A7C15ull) ^
                 ((uint64_t)(r->col * 3 + r->row + 1) * 0xC2B2AE3D27D4EB4Full);
    uint32_t i = (uint32_t)(h ^ (h >> 29)) & a->mask;
    while (a->nodes[i].used &&
           !(hol_tile_eq(a->nodes[i].r.tile, r->tile) && a->nodes[i].r.orient == r->orient &&
             a->nodes[i].r.col == r->col && a->nodes[i].r.row == r->row))
        i = (i + 1) & a->mask;
    return i;
}

static void pa_push(plain_astar *a, pa_heap_item it)
{
    size_t i = a->nheap++;
    while (i > 0) {
        size_t p = (i - 1) / 2;
        if (a->heap[p].f < it.f || (a->heap[p].f == it.f && a->heap[p].g >= it.g))
            break;
        a->heap[i] = a->heap[p];
        i = p;
    }
    a->heap[i] = it;
}

static pa_heap_item pa_pop(plain_astar *a)
{
    pa_heap_item top = a->heap[0], last = a->heap[--a->nheap];
    size_t i = 0;
    for (;;) {
        size_t c = 2 * i + 1;
        if (c >= a->nheap)
            break;
        if (c + 1 < a->nheap &&
            (a->heap[c + 1].f < a->heap[c].f ||
             (a->heap[c + 1].f == a->heap[c].f && a->heap[c + 1].g > a->heap[c].g)))
            c++;
        if (last.f < a->heap[c].f || (last.f == a->heap[c].f && last.g >= a->heap[c].g))
            break;
        a->heap[i] = a->heap[c];
        i = c;
    }
    a->heap[i] = last;
    return top;
}

/* Fewest room steps from start until standing on target; *out_expanded
 * counts expanded nodes. -1 when the table filled up. */
static int pa_find(plain_astar *a, const hol_room *start, hol_tile target, size_t *out_expanded)
{
    for (size_t i = 0; i < a->ntouched; i++)
        a->nodes[a->touched[i]].used = 0;
    a->ntouched = 0;
    a->nheap = 0;
    size_t expanded = 0, used = 0;
    uint32_t s = pa_slot(a, start);
    a->nodes[s] = (pa_node){*start, 0, 1};
    a->touched[a->ntouched++] = s;
    used++;
    pa_push(a, (pa_heap_item){hol_tile_dist(start->tile, target), 0, s});
    int result = -1;
    while (a->nheap) {
        pa_heap_item it = pa_pop(a);
        pa_node *n = &a->nodes[it.node];
        if (it.g > n->g)
            continue; /* stale */
        expanded++;
        if (hol_tile_eq(n->r.tile, target)) {
            result = n->g;
            break;
        }
        for (int d = 0; d < 4; d++) {
            hol_room nr = n->r;
            if (hol_room_step(&nr, d) != HOL_OK)
                continue;
            uint32_t k = pa_slot(a, &nr);
            int g = it.g + 1;
            if (a->nodes[k].used && a->nodes[k].g <= g)
                continue;
            if (!a->nodes[k].used) {
                if (++used > (size_t)a->mask * 3 / 4 || a->nheap + 1 >= a->cap_heap)
                    goto out;
                a->touched[a->ntouched++] = k;
            }
            a->nodes[k] = (pa_node){nr, g, 1};
            pa_push(a, (pa_heap_item){g + hol_tile_dist(nr.tile, target), g, k});
        }
    }
out:
    *out_expanded = expanded;
    return result;
}

#endif
