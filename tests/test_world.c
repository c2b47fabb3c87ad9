/* test_world.c - the world: tile set completions, vertices and trees, the
 * constraints after long random walks, determinism, save/load, corrupt and
 * truncated images, capacity exhaustion, backtracking, game objects.
 *
 * The long walk takes HOL_TEST_WORLD_STEPS room steps (default 100000). Set
 * it lower for a quick run:
 *   make BUILD=build/quick CFLAGS=-DHOL_TEST_WORLD_STEPS=5000 unit
 * With HOL_TEST_QUICK=1 in the environment (tests/quick.h: CI's runs under
 * qemu and under the sanitizers) the long walk takes 30000 steps at most in
 * a store of 2^14 tiles (not 2^16), and the walk of seen tiles 10000 steps
 * instead of 30000.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "../core/hol_world_impl.h" /* white box: the tile set, checksum */
#include "quick.h"

#ifndef HOL_TEST_WORLD_STEPS
#define HOL_TEST_WORLD_STEPS 100000
#endif

/* ---- helpers ---------------------------------------------------------------- */

static uint64_t rng_next(uint64_t *s)
{
    *s += UINT64_C(0x9E3779B97F4A7C15);
    uint64_t z = *s;
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static hol_world *make_world(uint64_t seed, uint32_t cap, uint32_t reject)
{
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.seed = seed;
    d.capacity = cap;
    d.test_reject_per_mille = reject;
    hol_world *w = NULL;
    assert_int_equal(hol_world_make(&d, &w), HOL_OK);
    return w;
}

/* ball's table of the tiles it holds: slot -> index in out, a slot of
 * an earlier call told apart by its stamp (nothing to clear a call). */
enum { BALL_MAX = 4096, BALL_SLOTS = 8192 };
static uint32_t ball_stamp[BALL_SLOTS], ball_now;
static uint16_t ball_at[BALL_SLOTS];

/* The slot of tile t in ball's table: the one holding it, or the empty
 * one where it goes. */
static size_t ball_slot(const hol_tile *out, hol_tile t)
{
    size_t s = (size_t)hol_tile_hash(t) & (BALL_SLOTS - 1);
    while (ball_stamp[s] == ball_now && !hol_tile_eq(out[ball_at[s]], t))
        s = (s + 1) & (BALL_SLOTS - 1);
    return s;
}

/* Tiles within r of t (breadth first), at most cap. A tile found is
 * looked up in a table of those held (it was compared with every one:
 * the walks call this at every step). */
static size_t ball(hol_tile t, int r, hol_tile *out, size_t cap)
{
    size_t n = 1;
    int dist[BALL_MAX];
    if (++ball_now == 0) {
        memset(ball_stamp, 0, sizeof ball_stamp);
        ball_now = 1;
    }
    out[0] = t;
    dist[0] = 0;
    size_t s0 = ball_slot(out, t);
    ball_stamp[s0] = ball_now;
    ball_at[s0] = 0;
    for (size_t q = 0; q < n; q++) {
        if (dist[q] >= r)
            continue;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            if (hol_tile_step(out[q], d, &nt, NULL))
                continue;
            size_t s = ball_slot(out, nt);
            int seen = ball_stamp[s] == ball_now;
            if (!seen && n < cap && n < BALL_MAX) {
                out[n] = nt;
                dist[n] = dist[q] + 1;
                ball_stamp[s] = ball_now;
                ball_at[s] = (uint16_t)n;
                n++;
            }
        }
    }
    return n;
}

static void assert_check(const hol_world *w)
{
    char msg[256];
    hol_err err = hol_world_check(w, msg, sizeof msg);
    if (err)
        fail_msg("world check: %s", msg);
}

static uint8_t *save_image(const hol_world *w, size_t *out_len)
{
    size_t need = hol_world_save_size(w);
    uint8_t *buf = malloc(need);
    assert_non_null(buf);
    assert_int_equal(hol_world_save(w, buf, need, out_len), HOL_OK);
    assert_int_equal(*out_len, need);
    return buf;
}

static int same_image(const hol_world *a, const hol_world *b)
{
    size_t la, lb;
    uint8_t *ia = save_image(a, &la), *ib = save_image(b, &lb);
    int same = la == lb && memcmp(ia, ib, la) == 0;
    free(ia);
    free(ib);
    return same;
}

/* One random room step that stays in the room and in reach; `home` in
 * per mille: the chance to take a step towards O when there is one. */
static void random_step(hol_world *w, hol_room *room, uint64_t *rng, int home)
{
    for (int tries = 0; tries < 64; tries++) {
        uint64_t r = rng_next(rng);
        int dir = (int)(r & 3);
        if ((int)((r >> 8) % 1000) < home) {
            int best = -1;
            for (int d = 0; d < 4; d++) {
                hol_room n = *room;
                if (!hol_room_step(&n, d) &&
                    hol_tile_dist0(n.tile) < hol_tile_dist0(room->tile))
                    best = d;
            }
            if (best >= 0)
                dir = best;
        }
        hol_room n = *room;
        if (hol_room_step(&n, dir))
            continue;
        *room = n;
        assert_int_equal(hol_world_update(w, room), HOL_OK);
        return;
    }
    fail_msg("no step possible");
}

/* ---- the tile set ------------------------------------------------------------- */

/* Every demand vector (each edge free, or fixed to none / creek / log) has
 * a matching state exactly when it has at most one log and not a log and a
 * creek together - and those are the only vectors the generator can make
 * (hol_world_check verifies, for every open tile, that its fixed
 * neighbours have a completion). */
static void test_tile_set_completions(void **state)
{
    (void)state;
    int completable = 0;
    for (int v = 0; v < 256; v++) {
        int dem[4], logs = 0, creeks = 0;
        uint32_t dom = HOL__ALL_STATES;
        for (int e = 0; e < 4; e++) {
            dem[e] = ((v >> (2 * e)) & 3) - 1; /* -1 free, else a conn */
            if (dem[e] < 0)
                continue;
            logs += dem[e] == HOL_CONN_LOG;
            creeks += dem[e] == HOL_CONN_CREEK;
            dom &= hol__compat(e, dem[e]);
        }
        int expect = logs <= 1 && !(logs && creeks);
        assert_int_equal(dom != 0, expect);
        completable += expect;
        /* the completion with 'none' on every free edge exists too */
        if (expect) {
            uint32_t minimal = HOL__ALL_STATES;
            for (int e = 0; e < 4; e++)
                minimal &= hol__compat(e, dem[e] < 0 ? HOL_CONN_NONE : dem[e]);
            assert_int_not_equal(minimal, 0);
        }
    }
    assert_int_equal(completable, 81 + 4 * 8); /* no log: 3^4; one log: 4 * 2^3 */
}

/* Shapes: logs one log edge, creeks 2..4 creek edges, springs 1, pools 0/1,
 * everything else none; each rotation of a shape exists exactly once. */
static void test_tile_set_shapes(void **state)
{
    (void)state;
    int seen[HOL_OBJ_COUNT][256];
    memset(seen, 0, sizeof seen);
    for (int s = 0; s < HOL__NSTATES; s++) {
        int c = 0, l = 0, pattern = 0;
        for (int e = 0; e < 4; e++) {
            int k = hol__state_conn(s, e);
            c += k == HOL_CONN_CREEK;
            l += k == HOL_CONN_LOG;
            pattern |= k << (2 * e);
        }
        int o = hol__state_obj(s);
        assert_int_equal(seen[o][pattern]++, 0);
        switch (o) {
        case HOL_OBJ_LOG:
            assert_int_equal(l, 1);
            assert_int_equal(c, 0);
            assert_int_equal(hol__state_conn(s, hol__state_rot(s)), HOL_CONN_LOG);
            break;
        case HOL_OBJ_CREEK:
            assert_true(c >= 2 && l == 0);
            break;
        case HOL_OBJ_SPRING:
            assert_true(c == 1 && l == 0);
            assert_int_equal(hol__state_conn(s, hol__state_rot(s)), HOL_CONN_CREEK);
            break;
        case HOL_OBJ_POOL:
            assert_true(c <= 1 && l == 0);
            break;
        default:
            assert_true(c == 0 && l == 0);
        }
    }
    /* every biome has a positive free choice without connectors */
    for (int b = 0; b < HOL_BIOME_COUNT; b++)
        assert_true(hol__weight(b, 0) + hol__weight(b, 1) > 0);
}

/* ---- vertices and trees -------------------------------------------------------- */

static void test_vertices(void **state)
{
    (void)state;
    hol_tile tiles[400];
    size_t n = ball(hol_tile_origin(), 5, tiles, 400);
    hol_tile far;
    assert_int_equal(hol_tile_resolve("Nrfflrflrfff", -1, &far), HOL_OK);
    size_t m = ball(far, 2, tiles + n, 400 - n);
    n += m;
    int kinds[HOL_TREE_COUNT] = {0};
    for (size_t i = 0; i < n; i++) {
        for (int c = 0; c < 4; c++) {
            hol_tile ct, t = tiles[i];
            int cc, corner = c;
            assert_int_equal(hol_world_vertex_canon(t, c, &ct, &cc), HOL_OK);
            hol_tree tree;
            assert_int_equal(hol_world_tree(7, t, c, &tree), HOL_OK);
            kinds[tree.kind]++;
            /* five moves round the vertex return to (t, c); every one of
             * the five names the same vertex and the same tree */
            for (int k = 0; k < 5; k++) {
                hol_tile nt;
                int arr;
                assert_int_equal(hol_tile_step(t, corner, &nt, &arr), HOL_OK);
                t = nt;
                corner = (arr + 1) & 3;
                hol_tile ct2;
                int cc2;
                hol_tree tree2;
                assert_int_equal(hol_world_vertex_canon(t, corner, &ct2, &cc2), HOL_OK);
                assert_true(hol_tile_eq(ct, ct2));
                assert_int_equal(cc, cc2);
                assert_int_equal(hol_world_tree(7, t, corner, &tree2), HOL_OK);
                assert_int_equal(tree.kind, tree2.kind);
                assert_int_equal(tree.size, tree2.size);
                if (k < 4)
                    assert_false(hol_tile_eq(t, tiles[i]) && corner == c);
            }
            assert_true(hol_tile_eq(t, tiles[i]));
            assert_int_equal(corner, c);
        }
    }
    for (int k = 0; k < HOL_TREE_COUNT; k++)
        assert_true(kinds[k] > 0);
    /* a tile has four distinct corners */
    hol_tile a, b;
    int ca, cb;
    hol_world_vertex_canon(hol_tile_origin(), 0, &a, &ca);
    hol_world_vertex_canon(hol_tile_origin(), 1, &b, &cb);
    assert_false(hol_tile_eq(a, b) && ca == cb);
}

/* ---- the long walk ----------------------------------------------------------------- */

/* Constraints everywhere after HOL_TEST_WORLD_STEPS random room steps,
 * half drifting home (revisits, eviction) and half free (the walk runs to
 * the reach of tile words). Every tile within the radius is collapsed after
 * each update, and a tile seen in one update is unchanged in the next. */
static void test_long_walk(void **state)
{
    (void)state;
    /* quick (tests/quick.h): a quarter of the store, so the shorter walk
     * evicts too */
    hol_world *w = make_world(2024, test_quick() ? 1u << 14 : 1u << 16, 0);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    uint64_t rng = 99;
    static hol_tile prev[128], cur[128];
    static hol_tile_content prevc[128], curc[128];
    size_t nprev = 0, compared = 0;
    long steps = HOL_TEST_WORLD_STEPS;
    if (test_quick() && steps > 30000)
        steps = 30000;
    for (long i = 0; i < steps; i++) {
        random_step(w, &room, &rng, i < steps / 2 ? 450 : 0);
        /* snapshots at steps 16k and 16k + 1: a tile seen in both balls
         * must not have changed */
        if (i % 16 <= 1 || i == steps - 1) {
            size_t n = ball(room.tile, 4, cur, 128);
            for (size_t k = 0; k < n; k++) {
                assert_int_equal(hol_world_peek(w, cur[k], &curc[k]), HOL_OK);
                for (size_t j = 0; j < nprev; j++)
                    if (hol_tile_eq(prev[j], cur[k]))
                        assert_memory_equal(&prevc[j], &curc[k], sizeof curc[k]);
            }
            memcpy(prev, cur, n * sizeof cur[0]);
            memcpy(prevc, curc, n * sizeof curc[0]);
            nprev = n;
            if (i % 16 == 1)
                compared += n;
        } else {
            nprev = 0;
        }
        if (i % 25000 == 24999)
            assert_check(w);
    }
    assert_check(w);
    assert_true(compared > (size_t)steps / 16 * 50);
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    assert_true(st.count < st.capacity);
    if (steps >= 20000)
        assert_true(st.evicted > 0);
    assert_int_equal(st.backtracks, 0); /* the tile set never contradicts */
    print_message("    %ld steps: %llu tiles collapsed, %llu evicted, %u in store\n",
                  steps, (unsigned long long)st.tiles_collapsed,
                  (unsigned long long)st.evicted, st.count);
    hol_world_destroy(w);
}

/* The biome layer: every collapsed tile has one; neighbours mostly agree
 * (spreading), and more than one biome appears. */
static void test_biomes(void **state)
{
    (void)state;
    hol_world *w = make_world(5, 0, 0);
    static hol_tile tiles[4096];
    size_t n = ball(hol_tile_origin(), 7, tiles, 4096);
    int used[HOL_BIOME_COUNT] = {0}, same = 0, pairs = 0;
    for (size_t i = 0; i < n; i++) {
        hol_tile_content c, nc;
        assert_int_equal(hol_world_get(w, tiles[i], &c), HOL_OK);
        assert_true(c.biome < HOL_BIOME_COUNT);
        used[c.biome]++;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            if (hol_tile_step(tiles[i], d, &nt, NULL))
                continue;
            if (hol_world_peek(w, nt, &nc))
                continue;
            pairs++;
            same += nc.biome == c.biome;
        }
    }
    int kinds = 0;
    for (int b = 0; b < HOL_BIOME_COUNT; b++)
        kinds += used[b] > 0;
    assert_true(kinds >= 3);
    assert_true(same * 2 > pairs);
    /* the rule: a fresh biome has depth 2..5; depth 0 or 1 can only come
     * from a neighbour of the same biome with depth one more (nothing was
     * evicted here, so that neighbour is in the store) */
    int spread = 0;
    for (uint32_t i = 0; i < w->cap; i++) {
        const hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED) || e->biome == HOL_BIOME_NONE)
            continue;
        assert_true(e->depth <= HOL__MAX_DEPTH);
        if (e->depth >= 2)
            continue;
        int found = 0;
        for (int d = 0; d < 4 && !found; d++) {
            hol_tile nt;
            if (hol_tile_step(e->tile, d, &nt, NULL))
                continue;
            int64_t j = hol__find(w, nt);
            found = j >= 0 && w->entries[j].biome == e->biome &&
                    w->entries[j].depth == e->depth + 1 &&
                    w->entries[j].state != HOL__UNSET;
        }
        assert_true(found);
        spread++;
    }
    assert_true(spread > 100);
    assert_check(w);
    hol_world_destroy(w);
}

/* ---- determinism ---------------------------------------------------------------------- */

static hol_world *walk_world(uint64_t seed, long steps, uint32_t cap, uint32_t reject)
{
    hol_world *w = make_world(seed, cap, reject);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    uint64_t rng = 1234;
    for (long i = 0; i < steps; i++)
        random_step(w, &room, &rng, 300);
    return w;
}

static void test_determinism(void **state)
{
    (void)state;
    hol_world *a = walk_world(77, 3000, 1u << 14, 0);
    hol_world *b = walk_world(77, 3000, 1u << 14, 0);
    hol_world *c = walk_world(78, 3000, 1u << 14, 0);
    assert_true(same_image(a, b));
    assert_false(same_image(a, c));
    /* another seed gives another world: many tiles near O differ */
    hol_tile tiles[128];
    size_t n = ball(hol_tile_origin(), 3, tiles, 128);
    int differ = 0;
    hol_world *fa = make_world(77, 0, 0), *fc = make_world(78, 0, 0);
    for (size_t i = 0; i < n; i++) {
        hol_tile_content x, y;
        assert_int_equal(hol_world_get(fa, tiles[i], &x), HOL_OK);
        assert_int_equal(hol_world_get(fc, tiles[i], &y), HOL_OK);
        differ += memcmp(&x, &y, sizeof x) != 0;
    }
    assert_true(differ > (int)n / 2);
    hol_world_destroy(fa);
    hol_world_destroy(fc);
    hol_world_destroy(a);
    hol_world_destroy(b);
    hol_world_destroy(c);
}

/* ---- backtracking ----------------------------------------------------------------------- */

static void test_backtracking(void **state)
{
    (void)state;
    /* with rejections, tiles in the ball before a step are unchanged after */
    hol_world *v = make_world(13, 1u << 14, 150);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(v, &room), HOL_OK);
    uint64_t rng = 8;
    static hol_tile before[128], after[128];
    static hol_tile_content bc[128], ac[128];
    size_t compared = 0;
    for (int i = 0; i < 400; i++) {
        size_t nb = ball(room.tile, 4, before, 128);
        for (size_t k = 0; k < nb; k++)
            assert_int_equal(hol_world_peek(v, before[k], &bc[k]), HOL_OK);
        random_step(v, &room, &rng, 300);
        size_t na = ball(room.tile, 4, after, 128);
        for (size_t k = 0; k < na; k++) {
            assert_int_equal(hol_world_peek(v, after[k], &ac[k]), HOL_OK);
            for (size_t j = 0; j < nb; j++)
                if (hol_tile_eq(before[j], after[k])) {
                    assert_memory_equal(&bc[j], &ac[k], sizeof ac[k]);
                    compared++;
                }
        }
    }
    hol_world_stats vs;
    hol_world_get_stats(v, &vs);
    assert_true(vs.backtracks > 50);
    assert_true(compared > 400 * 40);
    assert_check(v);
    hol_world_destroy(v);

    hol_world *a = walk_world(11, 1500, 1u << 14, 100);
    hol_world *b = walk_world(11, 1500, 1u << 14, 100);
    hol_world_stats st;
    hol_world_get_stats(a, &st);
    assert_true(st.backtracks > 100);
    assert_check(a);
    assert_true(same_image(a, b));
    hol_world_destroy(a);
    hol_world_destroy(b);
}

/* ---- save and load ------------------------------------------------------------------------- */

static void test_save_load(void **state)
{
    (void)state;
    hol_world *a = walk_world(3, 2000, 1u << 15, 0);
    hol_tile_content c;
    hol_tile key;
    assert_int_equal(hol_world_reserve(a, hol_world_user(a).tile, 3, HOL_OBJ_KEY, &key),
                     HOL_OK);
    size_t len;
    uint8_t *img = save_image(a, &len);
    hol_world_desc d;
    char msg[200];
    assert_int_equal(hol_world_image_desc(img, len, &d, msg, sizeof msg), HOL_OK);
    assert_int_equal(d.seed, 3);
    assert_int_equal(d.radius, 4);
    d.capacity = 1u << 15;
    hol_world *b;
    assert_int_equal(hol_world_make(&d, &b), HOL_OK);
    assert_int_equal(hol_world_load(b, img, len, msg, sizeof msg), HOL_OK);
    assert_true(same_image(a, b));
    assert_check(b);
    assert_int_equal(hol_world_peek(b, key, &c), HOL_OK);
    assert_int_equal(c.object, HOL_OBJ_KEY);
    hol_room ra = hol_world_user(a), rb = hol_world_user(b);
    assert_true(hol_tile_eq(ra.tile, rb.tile));
    assert_int_equal(ra.orient, rb.orient);
    assert_int_equal(ra.col, rb.col);
    assert_int_equal(ra.row, rb.row);
    /* both continue identically */
    uint64_t r1 = 5, r2 = 5;
    for (int i = 0; i < 500; i++) {
        random_step(a, &ra, &r1, 0);
        random_step(b, &rb, &r2, 0);
    }
    assert_true(same_image(a, b));
    free(img);
    hol_world_destroy(a);
    hol_world_destroy(b);
}

/* Load img into w and expect err; w must be unchanged. */
static void expect_rejected(hol_world *w, const uint8_t *img, size_t len, hol_err err)
{
    size_t l0;
    uint8_t *before = save_image(w, &l0);
    char msg[200];
    hol_err got = hol_world_load(w, img, len, msg, sizeof msg);
    if (got != err)
        fail_msg("load gave %d (%s), want %d", got, msg, err);
    assert_true(msg[0] != 0);
    assert_null(strchr(msg, '\n'));
    size_t l1;
    uint8_t *after = save_image(w, &l1);
    assert_int_equal(l0, l1);
    assert_memory_equal(before, after, l0);
    free(before);
    free(after);
}

static void reseal(uint8_t *img, size_t len)
{
    uint64_t h = hol__image_checksum(img, len - 8);
    for (int i = 0; i < 8; i++)
        img[len - 8 + i] = (uint8_t)(h >> (8 * i));
}

static void test_corrupt_images(void **state)
{
    (void)state;
    hol_world *a = walk_world(9, 300, 1u << 14, 0);
    hol_world *w = walk_world(10, 50, 1u << 14, 0); /* the victim */
    size_t len;
    uint8_t *img = save_image(a, &len);
    uint8_t *bad = malloc(len);
    /* truncated anywhere */
    size_t cuts[] = {0, 1, 8, 11, 12, 40, 63, 64, 71, 72, 100, len / 2, len - 9, len - 1};
    for (size_t i = 0; i < sizeof cuts / sizeof cuts[0]; i++)
        expect_rejected(w, img, cuts[i], HOL_ECORRUPT);
    /* one flipped bit anywhere (sampled) */
    for (size_t pos = 0; pos < len; pos += (pos < 80 ? 1 : 97)) {
        memcpy(bad, img, len);
        bad[pos] ^= 0x10;
        expect_rejected(w, bad, len, pos >= 8 && pos < 12 ? HOL_EVERSION : HOL_ECORRUPT);
    }
    /* trailing garbage */
    uint8_t *longer = malloc(len + 3);
    memcpy(longer, img, len);
    memset(longer + len, 0, 3);
    expect_rejected(w, longer, len + 3, HOL_ECORRUPT);
    free(longer);
    /* another version, correctly sealed */
    memcpy(bad, img, len);
    bad[8] = 2;
    reseal(bad, len);
    expect_rejected(w, bad, len, HOL_EVERSION);
    /* sealed images that break a rule: a tile with a creek or log towards
     * a collapsed neighbour turned into grass */
    uint32_t count = (uint32_t)((len - 72) / 24);
    int forged = 0;
    for (uint32_t r = 0; r < count && forged < 40; r++) {
        uint8_t *rec = img + 64 + (size_t)r * 24;
        if (rec[20] == 0xff)
            continue;
        hol_tile t;
        memcpy(&t.bits[0], rec, 8); /* little-endian host assumed here */
        memcpy(&t.bits[1], rec + 8, 8);
        int linked = 0;
        for (int e = 0; e < 4; e++) {
            hol_tile nt;
            hol_tile_content nc;
            if (hol__state_conn(rec[20], e) != HOL_CONN_NONE &&
                !hol_tile_step(t, e, &nt, NULL) && !hol_world_peek(a, nt, &nc))
                linked = 1;
        }
        if (!linked)
            continue;
        memcpy(bad, img, len);
        bad[64 + (size_t)r * 24 + 20] = 1; /* grass */
        reseal(bad, len);
        expect_rejected(w, bad, len, HOL_ECORRUPT);
        forged++;
    }
    assert_true(forged > 0);
    memcpy(bad, img, len);
    bad[64 + 20] = 200; /* unknown state */
    reseal(bad, len);
    expect_rejected(w, bad, len, HOL_ECORRUPT);
    memcpy(bad, img, len); /* swap two records: order */
    uint8_t tmp[24];
    memcpy(tmp, bad + 64, 24);
    memcpy(bad + 64, bad + 88, 24);
    memcpy(bad + 88, tmp, 24);
    reseal(bad, len);
    expect_rejected(w, bad, len, HOL_ECORRUPT);
    memcpy(bad, img, len); /* a tile word that is not canonical */
    bad[64 + 15] |= 0x03;
    reseal(bad, len);
    expect_rejected(w, bad, len, HOL_ECORRUPT);
    /* more tiles than the capacity allows */
    hol_world *small = make_world(1, HOL_WORLD_MIN_CAPACITY, 0);
    hol_world_stats st;
    hol_world_get_stats(small, &st);
    hol_world *big = walk_world(9, 3000, 1u << 15, 0);
    size_t blen;
    uint8_t *bimg = save_image(big, &blen);
    assert_true((blen - 72) / 24 > st.capacity * 3 / 4);
    expect_rejected(small, bimg, blen, HOL_ENOMEM);
    free(bimg);
    hol_world_destroy(big);
    hol_world_destroy(small);
    /* the untouched original still loads */
    char msg[200];
    assert_int_equal(hol_world_load(w, img, len, msg, sizeof msg), HOL_OK);
    assert_true(same_image(a, w));
    free(bad);
    free(img);
    hol_world_destroy(a);
    hol_world_destroy(w);
}

/* ---- fixed memory ---------------------------------------------------------------------------- */

static void test_capacity_exhaustion(void **state)
{
    (void)state;
    hol_world *w = make_world(8, HOL_WORLD_MIN_CAPACITY, 0);
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    uint32_t cap = st.capacity;
    size_t bytes = st.bytes;
    assert_true(cap >= HOL_WORLD_MIN_CAPACITY && cap <= 8192);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    hol_tile flag;
    assert_int_equal(hol_world_reserve(w, room.tile, 2, HOL_OBJ_FLAG, &flag), HOL_OK);
    uint64_t rng = 42;
    uint32_t peak = 0;
    for (int i = 0; i < 20000; i++) {
        random_step(w, &room, &rng, 400);
        hol_world_get_stats(w, &st);
        if (st.count > peak)
            peak = st.count;
        assert_true(st.count < cap);
        assert_int_equal(st.bytes, bytes);
        if (i % 4000 == 0)
            assert_check(w);
    }
    assert_check(w);
    assert_true(st.evicted > 2 * (uint64_t)cap);
    assert_true(peak <= cap - cap / 8);
    /* the game object was never evicted */
    hol_tile_content c;
    assert_int_equal(hol_world_peek(w, flag, &c), HOL_OK);
    assert_int_equal(c.object, HOL_OBJ_FLAG);
    hol_world_destroy(w);
}

/* A store full of tiles it may not evict (game objects) refuses new tiles
 * with HOL_ENOMEM, never crashes, and stays valid. */
static void test_store_full_of_pins(void **state)
{
    (void)state;
    hol_world *w = make_world(12, HOL_WORLD_MIN_CAPACITY, 0);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    uint64_t rng = 77;
    int pins = 0, refusals = 0;
    hol_world_stats st;
    for (int i = 0; i < 100000 && refusals < 50; i++) {
        hol_tile t = hol_tile_origin();
        for (int k = 0; k < 14; k++) {
            hol_tile n;
            if (!hol_tile_step(t, (int)(rng_next(&rng) & 3), &n, NULL))
                t = n;
        }
        hol_tile got;
        hol_err err = hol_world_reserve(w, t, 0, HOL_OBJ_KEY, &got);
        assert_true(err == HOL_OK || err == HOL_ENOMEM);
        /* the user steps to and fro, so unpinned tiles age and may go */
        hol_room next = room;
        assert_int_equal(hol_room_step(&next, i & 1 ? HOL_DIR_S : HOL_DIR_N), HOL_OK);
        hol_err uerr = hol_world_update(w, &next);
        assert_true(uerr == HOL_OK || uerr == HOL_ENOMEM);
        if (!uerr)
            room = next;
        hol_world_get_stats(w, &st);
        assert_true(st.count < st.capacity);
        pins += err == HOL_OK;
        hol_tile_content c;
        if (err == HOL_ENOMEM && hol_world_peek(w, t, &c) != HOL_OK)
            refusals++; /* the store could not even take t */
    }
    assert_true(refusals >= 50);
    assert_true(pins > (int)st.capacity / 2);
    /* walking on either works (evicting what it may) or is refused with
     * HOL_ENOMEM; the store stays valid and within its capacity */
    int refused = 0;
    for (int i = 0; i < 2000; i++) {
        hol_room next = room;
        if (hol_room_step(&next, (int)(rng_next(&rng) & 3)))
            continue;
        hol_err err = hol_world_update(w, &next);
        assert_true(err == HOL_OK || err == HOL_ENOMEM);
        if (err == HOL_OK)
            room = next;
        else
            refused++;
        hol_world_get_stats(w, &st);
        assert_true(st.count < st.capacity);
    }
    print_message("    store of %u: %d game objects, %u tiles, %d steps refused\n",
                  st.capacity, pins, st.count, refused);
    assert_true(refused > 0);
    assert_check(w);
    hol_world_destroy(w);
}

/* ---- what the user has seen stays ------------------------------------------------------------ */

/* The test's own record of every tile seen: an open-addressing table of
 * (tile, content), independent of the world's store and archive. */
typedef struct seen_rec {
    hol_tile tile;
    hol_tile_content c;
    int used;
} seen_rec;

static seen_rec *seen_slot(seen_rec *tab, size_t mask, hol_tile t)
{
    size_t i = (size_t)hol_tile_hash(t) & mask;
    while (tab[i].used && !hol_tile_eq(tab[i].tile, t))
        i = (i + 1) & mask;
    return &tab[i];
}

/* A small store (evicting all the time) and a walk that keeps coming back:
 * every tile within the radius after every update is compared with what it
 * was the first time the user saw it. Then the world is saved and loaded
 * into a fresh one, and the walk goes on: still the same. */
static void test_seen_tiles_stay(void **state)
{
    (void)state;
    const int STEPS = test_quick() ? 10000 : 30000;
    const size_t mask = (1u << 17) - 1;
    seen_rec *tab = calloc(mask + 1, sizeof *tab);
    assert_non_null(tab);
    static hol_tile b[256];
    hol_world_desc kd;
    memset(&kd, 0, sizeof kd);
    kd.seed = 21;
    kd.capacity = HOL_WORLD_MIN_CAPACITY;
    kd.keep_capacity = 1u << 16; /* a small store that remembers many seen tiles */
    hol_world *w = NULL;
    assert_int_equal(hol_world_make(&kd, &w), HOL_OK);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    uint64_t rng = 99;
    size_t nseen = 0, compared = 0, changed = 0;
    for (int i = 0; i <= STEPS; i++) {
        if (i == STEPS / 2) {
            /* through a save image into another world */
            size_t len;
            uint8_t *img = save_image(w, &len);
            hol_world *w2 = NULL;
            assert_int_equal(hol_world_make(&kd, &w2), HOL_OK);
            assert_int_equal(hol_world_load(w2, img, len, NULL, 0), HOL_OK);
            free(img);
            hol_world_destroy(w);
            w = w2;
            assert_int_equal(hol_world_update(w, &room), HOL_OK);
        }
        size_t n = ball(room.tile, hol_world_radius(w), b, 256);
        for (size_t k = 0; k < n; k++) {
            hol_tile_content c;
            assert_int_equal(hol_world_peek(w, b[k], &c), HOL_OK);
            seen_rec *r = seen_slot(tab, mask, b[k]);
            if (!r->used) {
                assert_true(nseen < mask / 2);
                r->used = 1;
                r->tile = b[k];
                r->c = c;
                nseen++;
            } else {
                compared++;
                changed += memcmp(&r->c, &c, sizeof c) != 0;
            }
        }
        if (i < STEPS)
            random_step(w, &room, &rng, 300);
    }
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    print_message("    %zu tiles seen, %zu revisits compared, %zu changed; store %u, "
                  "evicted %llu\n",
                  nseen, compared, changed, st.capacity,
                  (unsigned long long)st.evicted);
    /* the walk saw far more tiles than the store holds, so it evicted and
     * came back to evicted tiles */
    assert_true(nseen > 2 * (size_t)st.capacity);
    assert_true(st.evicted > (uint64_t)st.capacity);
    assert_int_equal(changed, 0);
    assert_check(w);
    hol_world_destroy(w);
    free(tab);
}


/* ---- lifecycle, game objects, errors ---------------------------------------------------------- */

static int allocs, frees;
static void *count_alloc(size_t size, void *user)
{
    (void)user;
    allocs++;
    return malloc(size);
}
static void count_free(void *p, void *user)
{
    (void)user;
    frees++;
    free(p);
}

static void test_lifecycle(void **state)
{
    (void)state;
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.capacity = 5000;
    d.allocator.alloc = count_alloc;
    d.allocator.free = count_free;
    hol_world *w;
    assert_int_equal(hol_world_make(&d, &w), HOL_OK);
    hol_room room = hol_room_start();
    uint64_t rng = 3;
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    for (int i = 0; i < 3000; i++)
        random_step(w, &room, &rng, 0);
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    assert_int_equal(st.capacity, 8192);
    hol_world_destroy(w);
    assert_int_equal(allocs, 1);
    assert_int_equal(frees, 1);

    /* over caller memory, same results as make */
    memset(&d, 0, sizeof d);
    d.seed = 17;
    size_t size = hol_world_mem_size(&d);
    assert_true(size > (size_t)HOL_WORLD_DEFAULT_CAPACITY * sizeof(hol__entry));
    void *mem = aligned_alloc(16, (size + 15) & ~(size_t)15);
    hol_world *wi, *wm;
    assert_int_equal(hol_world_init(mem, size - 1, &d, &wi), HOL_ENOMEM);
    assert_int_equal(hol_world_init(mem, size, &d, &wi), HOL_OK);
    assert_int_equal(hol_world_make(&d, &wm), HOL_OK);
    room = hol_room_start();
    assert_int_equal(hol_world_update(wi, &room), HOL_OK);
    assert_int_equal(hol_world_update(wm, &room), HOL_OK);
    assert_true(same_image(wi, wm));
    hol_world_destroy(wm);
    free(mem);

    /* bad descs and arguments */
    memset(&d, 0, sizeof d);
    d.radius = HOL_WORLD_MAX_RADIUS + 1;
    assert_int_equal(hol_world_mem_size(&d), 0);
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
    d.radius = -1;
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
    w = make_world(1, 0, 0);
    /* an update on the tile of the last one is free (every frame is fine) */
    room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    hol_world_get_stats(w, &st);
    assert_int_equal(st.updates, 1);
    hol_room bad = hol_room_start();
    bad.col = 3;
    assert_int_equal(hol_world_update(w, &bad), HOL_EARG);
    hol_tile_content c;
    hol_tile far;
    assert_int_equal(hol_tile_parse("Wrfflfrfl", -1, &far), HOL_OK);
    assert_int_equal(hol_world_peek(w, far, &c), HOL_EARG);
    assert_int_equal(hol_world_get(w, far, &c), HOL_OK); /* alone, far away */
    hol_tile_content c2;
    assert_int_equal(hol_world_peek(w, far, &c2), HOL_OK);
    assert_memory_equal(&c, &c2, sizeof c);
    assert_check(w);
    hol_world_destroy(w);
}

static void test_reserve(void **state)
{
    (void)state;
    hol_world *w = make_world(21, 0, 0);
    hol_room room = hol_room_start();
    assert_int_equal(hol_world_update(w, &room), HOL_OK);
    hol_tile got[12];
    for (int i = 0; i < 12; i++) {
        int obj = i == 11 ? HOL_OBJ_CHEST : HOL_OBJ_KEY;
        assert_int_equal(hol_world_reserve(w, hol_tile_origin(), 3, obj, &got[i]),
                         HOL_OK);
        for (int j = 0; j < i; j++)
            assert_false(hol_tile_eq(got[i], got[j]));
        hol_tile_content c;
        assert_int_equal(hol_world_peek(w, got[i], &c), HOL_OK);
        assert_int_equal(c.object, obj);
        for (int e = 0; e < 4; e++)
            assert_int_equal(c.conn[e], HOL_CONN_NONE);
    }
    assert_check(w);
    hol_tile t;
    assert_int_equal(hol_world_reserve(w, got[0], 0, HOL_OBJ_FLAG, &t), HOL_ENOMEM);
    assert_int_equal(hol_world_reserve(w, got[0], 0, HOL_OBJ_ROCK, &t), HOL_EARG);
    assert_int_equal(hol_world_release(w, got[0]), HOL_OK);
    assert_int_equal(hol_world_release(w, got[0]), HOL_EARG);
    assert_int_equal(hol_world_reserve(w, got[0], 0, HOL_OBJ_FLAG, &t), HOL_OK);
    assert_true(hol_tile_eq(t, got[0]));
    hol_world_destroy(w);
}

/* hol_world_check can fail: break the store in several ways. */
static void test_check_detects(void **state)
{
    (void)state;
    hol_world *w = walk_world(31, 400, 1u << 14, 0);
    assert_check(w);
    char msg[256];
    int broken = 0;
    for (uint32_t i = 0; i < w->cap && broken < 20; i++) {
        hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED) || e->state == HOL__UNSET)
            continue;
        int linked = 0;
        for (int d = 0; d < 4; d++) {
            hol_tile nt;
            hol_tile_content nc;
            if (hol__state_conn(e->state, d) != HOL_CONN_NONE &&
                !hol_tile_step(e->tile, d, &nt, NULL) && !hol_world_peek(w, nt, &nc))
                linked = 1;
        }
        if (!linked)
            continue;
        uint8_t keep = e->state;
        e->state = 1; /* grass: a creek or log now ends at this edge */
        assert_int_equal(hol_world_check(w, msg, sizeof msg), HOL_ECORRUPT);
        assert_non_null(strstr(msg, "connector"));
        e->state = keep;
        broken++;
    }
    assert_true(broken > 0);
    assert_check(w);
    /* an object the biome does not allow */
    for (uint32_t i = 0; i < w->cap; i++) {
        hol__entry *e = &w->entries[i];
        if ((e->flags & HOL__F_USED) && e->state == 0 /* none */) {
            uint8_t b = e->biome;
            e->state = 2;               /* flowers ... */
            e->biome = HOL_BIOME_PINE;  /* ... are not in pine forests */
            assert_int_equal(hol_world_check(w, msg, sizeof msg), HOL_ECORRUPT);
            e->state = 0;
            e->biome = b;
            break;
        }
    }
    /* a collapsed tile without a biome */
    for (uint32_t i = 0; i < w->cap; i++) {
        hol__entry *e = &w->entries[i];
        if ((e->flags & HOL__F_USED) && e->state != HOL__UNSET) {
            uint8_t b = e->biome;
            e->biome = HOL_BIOME_NONE;
            assert_int_equal(hol_world_check(w, msg, sizeof msg), HOL_ECORRUPT);
            e->biome = b;
            break;
        }
    }
    /* the table: a wrong count */
    w->count++;
    assert_int_equal(hol_world_check(w, msg, sizeof msg), HOL_ECORRUPT);
    w->count--;
    assert_check(w);
    hol_world_destroy(w);
}

/* Designer placements: every placed tile is generated with its object (no
 * connectors), whatever the biome, over many seeds and with forced
 * backtracking; the world's constraints still hold everywhere; after the
 * store evicts them, regenerated they carry the object again. Bad
 * placements are refused. */
static void test_designer_places(void **state)
{
    (void)state;
    static const char *const addr[] = {"N", "Ef", "Srl", "Wlf", "Nff", "Elr", "Sff", "Wr"};
    static const int objs[] = {HOL_OBJ_ROCK, HOL_OBJ_POOL, HOL_OBJ_FLOWERS, HOL_OBJ_MUSHROOM,
                               HOL_OBJ_NONE, HOL_OBJ_GRASS, HOL_OBJ_ROCK, HOL_OBJ_POOL};
    hol_world_place pl[8];
    for (int i = 0; i < 8; i++) {
        assert_int_equal(hol_tile_parse(addr[i], -1, &pl[i].tile), HOL_OK);
        pl[i].object = objs[i];
    }
    for (uint64_t seed = 1; seed <= 40; seed++) {
        hol_world_desc d;
        memset(&d, 0, sizeof d);
        d.seed = seed;
        d.capacity = HOL_WORLD_MIN_CAPACITY;
        d.test_reject_per_mille = seed % 2 ? 0 : 150;
        d.places = pl;
        d.nplaces = 8;
        hol_world *w = NULL;
        assert_int_equal(hol_world_make(&d, &w), HOL_OK);
        hol_room r = hol_room_start();
        /* walk out and back far enough that the small store evicts */
        static const char walk[] = "NNSSEEWWSSNNWWEE";
        for (int lap = 0; lap < (seed == 1 ? 30 : 1); lap++)
            for (const char *c = walk; *c; c++) {
                hol_room n = r;
                if (hol_room_step(&n, hol_dir_from_char(*c)) == HOL_OK)
                    r = n;
                assert_int_equal(hol_world_update(w, &r), HOL_OK);
                for (int i = 0; i < 8; i++) {
                    hol_tile_content c2;
                    if (hol_world_peek(w, pl[i].tile, &c2))
                        continue; /* not generated (or evicted) now */
                    assert_int_equal(c2.object, objs[i]);
                    for (int e = 0; e < 4; e++)
                        assert_int_equal(c2.conn[e], HOL_CONN_NONE);
                }
            }
        for (int i = 0; i < 8; i++) {
            hol_tile_content c2;
            assert_int_equal(hol_world_get(w, pl[i].tile, &c2), HOL_OK);
            assert_int_equal(c2.object, objs[i]);
        }
        assert_check(w);
        if (seed == 1) {
            hol_world_stats st;
            hol_world_get_stats(w, &st);
            assert_true(st.evicted > 0); /* the placements were regenerated */
        }
        hol_world_destroy(w);
    }
    /* refused: a tile placed twice, an object with connectors, too many */
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    hol_world *w = NULL;
    hol_world_place two[2] = {pl[0], pl[0]};
    two[1].object = HOL_OBJ_GRASS;
    d.places = two;
    d.nplaces = 2;
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
    hol_world_place bad = {pl[0].tile, HOL_OBJ_CREEK};
    d.places = &bad;
    d.nplaces = 1;
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
    bad.object = HOL_OBJ_FLAG;
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
    d.nplaces = HOL_WORLD_MAX_PLACES + 1;
    assert_int_equal(hol_world_make(&d, &w), HOL_EARG);
}

/* ---- every tiling {4,Q} ---- */

/* Trees on vertices with Q tiles round them, creeks and logs across edges
 * (hol_world_check), in every tiling and room size: random walks, every
 * tile within the radius collapsed after each step, the trees of the Q
 * tiles round each vertex the same, save and load of a {4,Q} world in a
 * C x R room, and no tile or image of another tiling accepted. */
static void test_tilings(void **state)
{
    (void)state;
    static const int rooms[5][2] = {{3, 3}, {4, 4}, {5, 5}, {3, 5}, {4, 3}};
    for (int q = 4; q <= 8; q++) {
        hol_world_desc d;
        memset(&d, 0, sizeof d);
        d.seed = 100 + (uint64_t)q;
        d.capacity = 1u << 14;
        d.tiling_q = q;
        hol_world *w = NULL;
        assert_int_equal(hol_world_make(&d, &w), HOL_OK);
        assert_int_equal(hol_world_tiling(w), q);
        assert_int_equal(hol_tile_q(hol_world_user(w).tile), q);
        hol_room room;
        int C = rooms[q - 4][0], R = rooms[q - 4][1];
        assert_int_equal(hol_room_start_in(q, C, R, &room), HOL_OK);
        assert_int_equal(hol_world_update(w, &room), HOL_OK);
        uint64_t rng = (uint64_t)q;
        for (int i = 0; i < 300; i++) {
            random_step(w, &room, &rng, q == 4 ? 0 : 300);
            hol_tile_content c;
            hol_tile around[64];
            size_t n = ball(room.tile, 2, around, 64);
            for (size_t k = 0; k < n; k++)
                assert_int_equal(hol_world_peek(w, around[k], &c), HOL_OK);
        }
        assert_check(w);
        /* the Q tiles round a vertex name one vertex and one tree */
        for (int c = 0; c < 4; c++) {
            hol_tile t = room.tile, ct, ct2;
            int corner = c, cc, cc2;
            hol_tree tree, tree2;
            assert_int_equal(hol_world_vertex_canon(t, corner, &ct, &cc), HOL_OK);
            assert_int_equal(hol_world_tree(d.seed, t, corner, &tree), HOL_OK);
            for (int k = 0; k < q; k++) {
                hol_tile nt;
                int arr;
                assert_int_equal(hol_tile_step(t, corner, &nt, &arr), HOL_OK);
                t = nt;
                corner = (arr + 1) & 3;
                assert_int_equal(hol_world_vertex_canon(t, corner, &ct2, &cc2), HOL_OK);
                assert_true(hol_tile_eq(ct, ct2) && cc == cc2);
                assert_int_equal(hol_world_tree(d.seed, t, corner, &tree2), HOL_OK);
                assert_true(tree.kind == tree2.kind && tree.size == tree2.size);
                if (k < q - 1)
                    assert_false(hol_tile_eq(t, room.tile) && corner == c);
            }
            assert_true(hol_tile_eq(t, room.tile) && corner == c);
        }
        /* save and load: the tiling and the room's size come back */
        size_t len;
        uint8_t *img = save_image(w, &len);
        hol_world_desc d2;
        char msg[200];
        assert_int_equal(hol_world_image_desc(img, len, &d2, msg, sizeof msg), HOL_OK);
        assert_int_equal(d2.tiling_q, q);
        hol_world *w2 = NULL;
        assert_int_equal(hol_world_make(&d2, &w2), HOL_OK);
        assert_int_equal(hol_world_load(w2, img, len, msg, sizeof msg), HOL_OK);
        hol_room u = hol_world_user(w2);
        assert_true(hol_tile_eq(u.tile, room.tile) && hol_room_cols(&u) == C &&
                    hol_room_rows(&u) == R && u.col == room.col && u.row == room.row);
        assert_true(same_image(w, w2));
        /* another tiling's world refuses the image, tiles and rooms */
        hol_world_desc d3 = d2;
        d3.tiling_q = q == 5 ? 6 : 5;
        hol_world *w3 = NULL;
        assert_int_equal(hol_world_make(&d3, &w3), HOL_OK);
        assert_int_equal(hol_world_load(w3, img, len, msg, sizeof msg), HOL_EARG);
        assert_non_null(strstr(msg, "tiling"));
        hol_tile_content c;
        assert_int_equal(hol_world_get(w3, room.tile, &c), HOL_EARG);
        assert_int_equal(hol_world_update(w3, &room), HOL_EARG);
        hol_tile got;
        assert_int_equal(hol_world_reserve(w3, room.tile, 2, HOL_OBJ_FLAG, &got), HOL_EARG);
        assert_int_equal(hol_world_reserve(w, room.tile, 2, HOL_OBJ_FLAG, &got), HOL_OK);
        assert_int_equal(hol_tile_q(got), q);
        free(img);
        hol_world_destroy(w);
        hol_world_destroy(w2);
        hol_world_destroy(w3);
    }
    hol_world_desc bad;
    memset(&bad, 0, sizeof bad);
    bad.tiling_q = 9;
    hol_world *w = NULL;
    assert_int_equal(hol_world_make(&bad, &w), HOL_EARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tile_set_completions),
        cmocka_unit_test(test_tile_set_shapes),
        cmocka_unit_test(test_vertices),
        cmocka_unit_test(test_biomes),
        cmocka_unit_test(test_determinism),
        cmocka_unit_test(test_backtracking),
        cmocka_unit_test(test_save_load),
        cmocka_unit_test(test_corrupt_images),
        cmocka_unit_test(test_capacity_exhaustion),
        cmocka_unit_test(test_seen_tiles_stay),
        cmocka_unit_test(test_store_full_of_pins),
        cmocka_unit_test(test_designer_places),
        cmocka_unit_test(test_lifecycle),
        cmocka_unit_test(test_reserve),
        cmocka_unit_test(test_check_detects),
        cmocka_unit_test(test_long_walk),
        cmocka_unit_test(test_tilings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
