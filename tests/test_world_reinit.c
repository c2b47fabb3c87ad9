/* test_world_reinit.c - a world whose store is not cleared (zeroed memory,
 * hol_world_reinit of an empty store) against one cleared as before.
 *
 * - test_zeroed_same: a world on calloc'd memory said to hold zeros
 *   (desc.mem_zeroed) walks to the same store, byte for byte in its saved
 *   image, as a world on memory full of garbage that init clears.
 * - test_reinit_clears_only_tiles: white box: a store that holds tiles is
 *   cleared by hol_world_reinit (a mark left in an unused entry is gone),
 *   an empty one is not (the mark stays: its pages untouched); either way
 *   the next walk gives the image of a fresh world, also for another seed,
 *   another tiling (the store moves: cleared), a failed reinit before, and
 *   a hol_world_make'd world (still destroyable).
 * - test_app_lazy_world_same: an app with lazy_world (calloc'd world, not
 *   cleared at create nor at its first level) plays two levels (the second
 *   clears the first's tiles) to the same events, views and world images
 *   as an eager app.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_world_impl.h" /* white box: the store's entries */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include "app_fixture.h"
#pragma GCC diagnostic pop

/* The world's saved image (malloc'd; *n its length). */
static uint8_t *image(const hol_world *w, size_t *n)
{
    size_t cap = hol_world_save_size(w);
    uint8_t *buf = malloc(cap);
    assert_non_null(buf);
    assert_int_equal(hol_world_save(w, buf, cap, n), HOL_OK);
    return buf;
}

/* A walk of 40 room steps (fixed pseudo-random directions) with updates. */
static void walk(hol_world *w, int q)
{
    hol_room r;
    assert_int_equal(hol_room_start_in(q, 0, 0, &r), HOL_OK);
    assert_int_equal(hol_world_update(w, &r), HOL_OK);
    uint32_t x = 12345;
    for (int i = 0; i < 40; i++) {
        x = x * 1103515245u + 12345u;
        if (hol_room_step(&r, (int)(x >> 16) & 3) == HOL_OK)
            assert_int_equal(hol_world_update(w, &r), HOL_OK);
    }
}

static void assert_same_image(const hol_world *a, const hol_world *b)
{
    size_t na, nb;
    uint8_t *ia = image(a, &na), *ib = image(b, &nb);
    assert_int_equal(na, nb);
    assert_memory_equal(ia, ib, na);
    free(ia);
    free(ib);
}

static hol_world_desc desc_of(uint64_t seed, int q)
{
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.seed = seed;
    d.tiling_q = q;
    d.capacity = 1u << 14;
    d.keep_capacity = 1u << 12;
    return d;
}

static void test_zeroed_same(void **state)
{
    (void)state;
    hol_world_desc d = desc_of(7, 5);
    size_t size = hol_world_mem_size(&d);
    void *garbage = malloc(size), *zeros = calloc(1, size);
    assert_non_null(garbage);
    assert_non_null(zeros);
    memset(garbage, 0xa5, size);
    hol_world *a, *b;
    assert_int_equal(hol_world_init(garbage, size, &d, &a), HOL_OK);
    d.mem_zeroed = 1;
    assert_int_equal(hol_world_init(zeros, size, &d, &b), HOL_OK);
    walk(a, 5);
    walk(b, 5);
    assert_int_equal(hol_world_check(b, NULL, 0), HOL_OK);
    assert_same_image(a, b);
    free(garbage);
    free(zeros);
}

/* An unused entry of the store (flags without USED) marked, white box. */
static uint32_t mark_unused(hol_world *w)
{
    for (uint32_t i = 0; i < w->cap; i++)
        if (!(w->entries[i].flags & HOL__F_USED)) {
            w->entries[i].pad = 0x5a;
            return i;
        }
    fail();
    return 0;
}

/* A fresh world of d, walked, compared with w walked. */
static void same_as_fresh(hol_world *w, const hol_world_desc *d)
{
    size_t size = hol_world_mem_size(d);
    void *mem = malloc(size);
    assert_non_null(mem);
    hol_world *fresh;
    assert_int_equal(hol_world_init(mem, size, d, &fresh), HOL_OK);
    walk(fresh, d->tiling_q);
    walk(w, d->tiling_q);
    assert_same_image(fresh, w);
    free(mem);
}

static void test_reinit_clears_only_tiles(void **state)
{
    (void)state;
    hol_world_desc d5 = desc_of(3, 5), d6 = desc_of(3, 6);
    size_t size = hol_world_mem_size(&d5);
    if (hol_world_mem_size(&d6) > size)
        size = hol_world_mem_size(&d6);
    void *mem = malloc(size);
    assert_non_null(mem);
    hol_world *w;
    assert_int_equal(hol_world_init(mem, size, &d5, &w), HOL_OK);
    /* empty: not cleared */
    uint32_t i = mark_unused(w);
    assert_int_equal(hol_world_reinit(mem, size, &d5, &w), HOL_OK);
    assert_int_equal(w->entries[i].pad, 0x5a);
    same_as_fresh(w, &d5);
    /* tiles in it: cleared, the next walk as a fresh world's (another
     * seed too) */
    i = mark_unused(w);
    hol_world_desc d9 = desc_of(9, 5);
    assert_int_equal(hol_world_reinit(mem, size, &d9, &w), HOL_OK);
    assert_int_equal(w->entries[i].pad, 0);
    same_as_fresh(w, &d9);
    /* another tiling: the store elsewhere (cleared), even when empty */
    assert_int_equal(hol_world_reinit(mem, size, &d5, &w), HOL_OK);
    i = mark_unused(w);
    assert_int_equal(hol_world_reinit(mem, size, &d6, &w), HOL_OK);
    same_as_fresh(w, &d6);
    /* a failed reinit (a bad placement), then a good one: cleared */
    hol_world_place bad = {hol_tile_origin_q(5), HOL_OBJ_FLAG};
    hol_world_desc dbad = d5;
    dbad.places = &bad;
    dbad.nplaces = 1;
    assert_int_equal(hol_world_reinit(mem, size, &dbad, &w), HOL_EARG);
    assert_int_equal(hol_world_reinit(mem, size, &d5, &w), HOL_OK);
    same_as_fresh(w, &d5);
    free(mem);
    /* a made world: reinit in its own memory, destroyed after */
    hol_world *m;
    assert_int_equal(hol_world_make(&d5, &m), HOL_OK);
    i = mark_unused(m);
    hol_world *m2;
    assert_int_equal(hol_world_reinit(m, m->bytes, &d5, &m2), HOL_OK);
    assert_ptr_equal(m, m2);
    assert_int_equal(m2->entries[i].pad, 0x5a);
    same_as_fresh(m2, &d5);
    hol_world_destroy(m2);
}

static hol_app *app_of(int lazy)
{
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = g_nav;
    d.lazy_world = lazy;
    d.lazy_nav = lazy;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    return app;
}

/* Steps through the room (cells' centres) for both apps: the same events
 * and views each frame. */
static void play_both(hol_app *a, hol_app *b, double *t)
{
    static const int cells[][2] = {{1, 1}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2},
                                   {0, 2}, {0, 1}, {0, 0}, {1, 0}, {1, 1}};
    for (size_t k = 0; k < sizeof cells / sizeof cells[0]; k++) {
        for (int f = 0; f < 3; f++) {
            *t += 1.0 / 72;
            hol_input in = tracked_at(*t, cells[k][0], cells[k][1]);
            step(a, in);
            step(b, in);
            assert_memory_equal(hol_app_get_events(a), hol_app_get_events(b),
                                sizeof(hol_app_events));
            assert_memory_equal(hol_app_get_view(a), hol_app_get_view(b),
                                sizeof(hol_app_view));
        }
    }
    assert_same_image(hol_app_world(a), hol_app_world(b));
}

static void test_app_lazy_world_same(void **state)
{
    (void)state;
    hol_app *eager = app_of(0), *lazy = app_of(1);
    const char *levels[2] = {"mode flag\nseed 5\nflag Wrf\n", "mode flag\nseed 11\nflag Nfl\n"};
    double t = 0;
    for (int k = 0; k < 2; k++) {
        hol_app_level L;
        hol_level_err e;
        assert_int_equal(parse_level(levels[k], &L, &e), HOL_OK);
        assert_int_equal(hol_app_start_level(eager, &L), HOL_OK);
        assert_int_equal(hol_app_start_level(lazy, &L), HOL_OK);
        assert_same_image(hol_app_world(eager), hol_app_world(lazy));
        play_both(eager, lazy, &t);
    }
    hol_app_destroy(eager);
    hol_app_destroy(lazy);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_zeroed_same),
        cmocka_unit_test(test_reinit_clears_only_tiles),
        cmocka_unit_test(test_app_lazy_world_same),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
