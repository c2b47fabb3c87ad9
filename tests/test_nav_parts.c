/* test_nav_parts.c - the cost table built by parts (a lazy navigator's)
 * against the table built whole.
 *
 * - test_parts_same_table: in six tilings and room sizes, a table built by
 *   parts answers every hol_navtab_need as the whole table does (the cost,
 *   and the descent from that state step for step), near states first
 *   (while most of the table is not built), then any; finished, it equals
 *   the whole table byte for byte (neighbours, costs) and in its
 *   certificate (least and mean costs by distance, the proved radius).
 * - test_lazy_nav_near_first: a lazy navigator answers near finds from a
 *   table it has built only in part (checked: not finished, few tiles'
 *   neighbours made), the same walks as an eager navigator; then far finds,
 *   tours and near finds again, still the same; {4,4}'s unreachable tiles
 *   the same HOL_EUNREACH (the BFS run to its end).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_nav.h"
#include "../core/hol_nav_impl.h" /* white box: the navigator's table */
#include "../core/hol_nav_table.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static uint32_t rnd(uint32_t n)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (uint32_t)((rng_state >> 11) % n);
}

typedef struct built {
    hol_navtab tab;
    void *mem, *scratch;
} built;

static void make_tab(built *b, int q, int cols, int rows, int radius)
{
    assert_int_equal(hol_navtab_init(&b->tab, q, cols, rows, radius), HOL_OK);
    b->mem = malloc(hol_navtab_table_bytes(&b->tab));
    b->scratch = malloc(hol_navtab_scratch_bytes(&b->tab));
    assert_non_null(b->mem);
    assert_non_null(b->scratch);
}

static void free_tab(built *b)
{
    free(b->mem);
    free(b->scratch);
}

/* The descent from (idx, o, cell) in tab: its steps in out (cap 512). */
static int descend(const hol_navtab *tab, uint32_t idx, int o, int cell, uint8_t *out)
{
    hol__walk w = {out, 512, 0, 0};
    int n = hol__nav_descend(tab, idx, o, cell, &w);
    assert_false(w.overflow);
    assert_int_equal(n, (int)w.n);
    return n;
}

/* One need on the table by parts, checked against the whole table. */
static void need_same(hol_navtab *parts, const hol_navtab *whole, uint32_t idx, int o,
                      int cell)
{
    int v = hol_navtab_need(parts, idx, o, cell);
    assert_int_equal(v, hol_navtab_cost(whole, idx, o, cell));
    if (v == 255)
        return;
    uint8_t w1[512], w2[512];
    int n1 = descend(whole, idx, o, cell, w1), n2 = descend(parts, idx, o, cell, w2);
    assert_int_equal(n1, v);
    assert_int_equal(n2, v);
    assert_memory_equal(w1, w2, (size_t)v);
}

/* Tiles whose neighbours the table by parts has made so far (white box:
 * the levels set up, their entries not unset). */
static uint32_t tiles_made(const hol_navtab *tab)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i < tab->off[tab->init_len + 1]; i++) {
        int all = 1;
        for (int t = 0; t < 4; t++)
            all &= tab->nb[4 * (size_t)i + (size_t)t] != UINT32_MAX - 1;
        n += (uint32_t)all;
    }
    return n;
}

static void parts_same(int q, int cols, int rows, int radius)
{
    built whole, parts;
    make_tab(&whole, q, cols, rows, radius);
    make_tab(&parts, q, cols, rows, radius);
    assert_int_equal(hol_navtab_build(&whole.tab, whole.mem, whole.scratch), HOL_OK);
    assert_int_equal(hol_navtab_begin(&parts.tab, parts.mem, parts.scratch), HOL_OK);
    hol_navtab *p = &parts.tab;
    const hol_navtab *w = &whole.tab;
    /* near states first: tiles within 2, then within 4, then any but the
     * outermost two levels (the navigator's trusted radius) */
    static const int reach[3] = {2, 4, 0};
    for (int pass = 0; pass < 3; pass++) {
        int r = reach[pass] ? reach[pass] : radius - 2;
        r = r > radius ? radius : r;
        for (int k = 0; k < 150; k++) {
            uint32_t idx = rnd(w->off[r + 1]);
            need_same(p, w, idx, (int)rnd(4), (int)rnd((uint32_t)w->ncell));
        }
        if (pass == 0 && radius >= 10) /* built in part only (4 % in {4,5} r10) */
            assert_true(tiles_made(p) < w->count / 10);
    }
    assert_int_equal(p->complete, 0);
    hol_navtab_finish(p);
    assert_int_equal(p->complete, 1);
    assert_memory_equal(p->nb, w->nb, 4 * sizeof(uint32_t) * (size_t)w->count);
    assert_memory_equal(p->cost, w->cost, (size_t)w->per * w->count);
    assert_int_equal(p->min_at_radius, w->min_at_radius);
    assert_int_equal(p->proved_radius, w->proved_radius);
    assert_memory_equal(p->min_at, w->min_at, sizeof w->min_at);
    assert_memory_equal(p->mean16_at, w->mean16_at, sizeof w->mean16_at);
    /* and every state of the finished table reads the same */
    for (int k = 0; k < 200; k++)
        need_same(p, w, rnd(w->count), (int)rnd(4), (int)rnd((uint32_t)w->ncell));
    free_tab(&whole);
    free_tab(&parts);
}

static void test_parts_same_table(void **state)
{
    (void)state;
    parts_same(5, 3, 3, 10);
    parts_same(4, 3, 3, 6); /* the flat grid: most states never reached */
    parts_same(8, 3, 3, 6);
    parts_same(6, 4, 4, 7);
    parts_same(5, 3, 4, 8); /* oblong: two orientations stored */
    parts_same(7, 5, 5, 5);
}

/* A room state: a random walk of up to n steps from the start of {4,q}
 * cols x rows. */
static hol_room random_room(int q, int cols, int rows, int n)
{
    hol_room r;
    assert_int_equal(hol_room_start_in(q, cols, rows, &r), HOL_OK);
    for (int i = (int)rnd((uint32_t)n + 1); i > 0; i--)
        hol_room_step(&r, (int)rnd(4)); /* refused steps leave r unchanged */
    return r;
}

/* A tile d steps from t on a random walk of tiles (its distance at most d). */
static hol_tile random_tile_near(hol_tile t, int d)
{
    hol_heading_tile f = {t, 0};
    for (int i = 0; i < d; i++)
        assert_int_equal(hol_heading_tile_step(f, (int)rnd(4), &f), HOL_OK);
    return f.tile;
}

/* The same answer from both navigators (find, or a tour of nkeys keys). */
static void same_answer(hol_nav *eager, hol_nav *lazy, const hol_room *s, const hol_tile *keys,
                        int nkeys, hol_tile target, size_t budget)
{
    uint8_t w1[HOL_NAV_WALK_MAX], w2[HOL_NAV_WALK_MAX];
    hol_nav_result r1, r2;
    hol_err e1, e2;
    if (nkeys) {
        e1 = hol_nav_tour(eager, s, keys, nkeys, target, budget, w1, sizeof w1, &r1);
        e2 = hol_nav_tour(lazy, s, keys, nkeys, target, budget, w2, sizeof w2, &r2);
    } else {
        e1 = hol_nav_find(eager, s, target, budget, w1, sizeof w1, &r1);
        e2 = hol_nav_find(lazy, s, target, budget, w2, sizeof w2, &r2);
    }
    assert_int_equal(e1, e2);
    if (e1)
        return;
    assert_int_equal(r1.len, r2.len);
    assert_int_equal(r1.exact, r2.exact);
    assert_int_equal(r1.nodes, r2.nodes);
    assert_memory_equal(w1, w2, (size_t)r1.len);
}

static void lazy_near_first(int q, int cols, int rows, int radius)
{
    hol_nav_desc desc = {0};
    desc.radius = radius;
    desc.max_nodes = 1u << 15;
    desc.tiling_q = q;
    desc.room_cols = cols;
    desc.room_rows = rows;
    hol_nav *eager, *lazy;
    assert_int_equal(hol_nav_create(&desc, &eager), HOL_OK);
    desc.lazy = 1;
    assert_int_equal(hol_nav_create(&desc, &lazy), HOL_OK);
    assert_int_equal(lazy->tab.complete, 0);
    int trust = hol_nav_table_exact_radius(lazy);
    /* near finds: the table in part */
    for (int k = 0; k < 40; k++) {
        hol_room s = random_room(q, cols, rows, 12);
        same_answer(eager, lazy, &s, NULL, 0, random_tile_near(s.tile, 1 + k % 3), 0);
    }
    assert_int_equal(lazy->tab.complete, 0);
    if (radius >= 10)
        assert_true(tiles_made(&lazy->tab) < lazy->tab.count / 10);
    /* then anything: near to the trusted radius, far (the table finished
     * first), tours (the leg table), near again */
    for (int k = 0; k < 30; k++) {
        hol_room s = random_room(q, cols, rows, 12);
        hol_tile keys[2] = {random_tile_near(s.tile, 1 + (int)rnd(3)),
                            random_tile_near(s.tile, 1 + (int)rnd(3))};
        int d = k % 3 == 1 ? trust + 1 + (int)rnd(2) : 1 + (int)rnd((uint32_t)trust);
        hol_tile t = random_tile_near(s.tile, d);
        same_answer(eager, lazy, &s, keys, k % 3 == 2 ? 1 + k % 2 : 0, t, 400);
    }
    hol_nav_destroy(eager);
    hol_nav_destroy(lazy);
}

static void test_lazy_nav_near_first(void **state)
{
    (void)state;
    lazy_near_first(5, 3, 3, 10);
    lazy_near_first(6, 4, 4, 7);
    lazy_near_first(5, 3, 4, 8);
    lazy_near_first(4, 3, 3, 6); /* tiles off the room's own: HOL_EUNREACH */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parts_same_table),
        cmocka_unit_test(test_lazy_nav_near_first),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
