/* test_nav.c - guidance against brute force.
 *
 * The brute force is a breadth-first search over absolute room states
 * (tile, orientation, cell) with hol_room_step, written here and sharing no
 * code with core/hol_nav*.c: it knows nothing of relative positions, cost
 * tables or symmetry. Checked: fewest steps and walk validity for random
 * starts and targets to tile distance 8; the tile numbering against the
 * SPEC counts; the table against a larger table (the trust argument); the
 * anytime mode against exact answers (prefix rate measured); tours against
 * every key order with BFS legs; the hot-cold field against
 * hol_tile_dist; the direction against the room's axes; input parsing.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "plain_astar.h"

#include "../core/hol_nav.h"
#include "../core/hol_nav_impl.h" /* tour legs, white box */
#include "../core/hol_nav_line.h"
#include "../core/hol_nav_table.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function" /* model.h helpers not used here */
#include "model.h"
#include "quick.h"
#pragma GCC diagnostic pop

#ifndef FAR_BFS
#define FAR_BFS 4
#endif
#ifndef FAR_BFS_DEPTH
#define FAR_BFS_DEPTH 36
#endif

static hol_nav *g_nav; /* default navigator (radius 14, trusted 12) */

static int setup(void **state)
{
    (void)state;
    return hol_nav_create(NULL, &g_nav) != HOL_OK;
}

static int teardown(void **state)
{
    (void)state;
    hol_nav_destroy(g_nav);
    return 0;
}

/* ---- deterministic random numbers ---- */

static uint64_t rng_state = 0x1234567887654321ull;

static uint32_t rnd(uint32_t n)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return (uint32_t)((rng_state >> 11) % n);
}

/* ---- brute force: BFS over absolute room states ---- */

typedef struct bf_state {
    hol_room room;
    int32_t parent; /* index in the state array, -1 for the root */
    uint8_t dir;
    uint8_t stage; /* tour: index of the next key in the order */
} bf_state;

/* The index of states is an open-addressed table of at most hmax slots
 * (twice the states' capacity, so never over half full). A search starts
 * it at BF_HASH0 slots and doubles it as the states grow past half of it,
 * so a small search clears and probes a small table (the cache's), not
 * the whole of it (32 MB: clearing it was most of a short search). */
#define BF_HASH0 4096u

/* A slot: the state's index (-1: empty) and the high half of its hash, so
 * a probe reads the state itself only when the halves agree. */
typedef struct bf_slot_ent {
    int32_t i;
    uint32_t tag;
} bf_slot_ent;

typedef struct bf {
    bf_state *st;
    size_t n, cap;
    bf_slot_ent *hash;
    size_t hmask, hmax;
} bf;

static void bf_init(bf *b, size_t cap)
{
    b->cap = cap;
    b->st = malloc(cap * sizeof *b->st);
    size_t h = BF_HASH0;
    while (h < 2 * cap)
        h <<= 1;
    b->hash = malloc(h * sizeof *b->hash);
    b->hmax = h;
    b->hmask = BF_HASH0 - 1;
    assert_non_null(b->st);
    assert_non_null(b->hash);
}

static void bf_free(bf *b)
{
    free(b->st);
    free(b->hash);
}

static uint64_t bf_hash(const hol_room *r, int stage)
{
    uint64_t h = hol_tile_hash(r->tile) ^
                 ((uint64_t)(r->orient + 4 * (r->col + 3 * r->row) + 64 * stage) *
                  0x9E3779B97F4A7C15ull);
    return h ^ (h >> 31);
}

/* The table twice as large, every state indexed again. */
static void bf_grow(bf *b)
{
    assert_true(2 * (b->hmask + 1) <= b->hmax);
    b->hmask = 2 * (b->hmask + 1) - 1;
    memset(b->hash, 0xff, (b->hmask + 1) * sizeof *b->hash);
    for (size_t i = 0; i < b->n; i++) {
        uint64_t h = bf_hash(&b->st[i].room, b->st[i].stage);
        size_t s = (size_t)h & b->hmask;
        while (b->hash[s].i >= 0)
            s = (s + 1) & b->hmask;
        b->hash[s] = (bf_slot_ent){(int32_t)i, (uint32_t)(h >> 32)};
    }
}

/* No state, the table at its first size. */
static void bf_reset(bf *b)
{
    b->n = 0;
    b->hmask = BF_HASH0 - 1;
    memset(b->hash, 0xff, (b->hmask + 1) * sizeof *b->hash);
}

/* Index of the state or -1 after inserting it (new). */
static int bf_add(bf *b, const hol_room *r, int stage, int32_t parent, int dir)
{
    if (2 * (b->n + 1) > b->hmask + 1)
        bf_grow(b);
    uint64_t h = bf_hash(r, stage);
    uint32_t tag = (uint32_t)(h >> 32);
    size_t s = (size_t)h & b->hmask;
    while (b->hash[s].i >= 0) {
        const bf_state *o = &b->st[b->hash[s].i];
        if (b->hash[s].tag == tag && o->stage == stage && o->room.orient == r->orient &&
            o->room.col == r->col && o->room.row == r->row &&
            hol_tile_eq(o->room.tile, r->tile))
            return b->hash[s].i;
        s = (s + 1) & b->hmask;
    }
    assert_true(b->n < b->cap);
    b->hash[s] = (bf_slot_ent){(int32_t)b->n, tag};
    bf_state *n = &b->st[b->n++];
    n->room = *r;
    n->parent = parent;
    n->dir = (uint8_t)dir;
    n->stage = (uint8_t)stage;
    return -1;
}

/* BFS over (absolute room state, stage): next(ctx, stage, tile) is the
 * stage after entering tile; the search ends when it reaches `goal`.
 * Returns the fewest steps, or -1 if not within max_depth. */
typedef int (*bf_next_fn)(const void *ctx, int stage, hol_tile tile);

static int bf_search(bf *b, const hol_room *start, bf_next_fn next, const void *ctx,
                     int goal, int max_depth)
{
    bf_reset(b);
    int stage = next(ctx, 0, start->tile);
    if (stage == goal)
        return 0;
    bf_add(b, start, stage, -1, 0);
    size_t head = 0;
    for (int depth = 0; depth < max_depth; depth++) {
        size_t end = b->n;
        for (; head < end; head++) {
            for (int d = 0; d < 4; d++) {
                hol_room r = b->st[head].room;
                if (hol_room_step(&r, d))
                    continue;
                int s = next(ctx, b->st[head].stage, r.tile);
                if (s == goal)
                    return depth + 1;
                bf_add(b, &r, s, (int32_t)head, d);
            }
        }
    }
    return -1;
}

typedef struct bf_goals {
    const hol_tile *goals;
    int n;
} bf_goals;

static int bf_next_in_order(const void *ctx, int stage, hol_tile tile)
{
    const bf_goals *g = ctx;
    while (stage < g->n && hol_tile_eq(tile, g->goals[stage]))
        stage++;
    return stage;
}

/* Fewest steps from start to stand on the tiles goals[0], goals[1], ... in
 * this order (a tile passed early counts when it is the next in order).
 * Returns -1 if not found within max_depth. */
static int bf_order(bf *b, const hol_room *start, const hol_tile *goals, int ngoals,
                    int max_depth)
{
    bf_goals g = {goals, ngoals};
    return bf_search(b, start, bf_next_in_order, &g, ngoals, max_depth);
}

static int bf_cost(bf *b, const hol_room *start, hol_tile target, int max_depth)
{
    return bf_order(b, start, &target, 1, max_depth);
}

/* ---- helpers ---- */

/* Random start: a random walk inside the room from `from`. */
static hol_room random_start_from(hol_room r, int max_steps)
{
    int n = (int)rnd((uint32_t)max_steps + 1);
    for (int i = 0; i < n; i++)
        hol_room_step(&r, (int)rnd(4)); /* refused steps leave r unchanged */
    return r;
}

/* Random start: a random walk inside the room from the start state. */
static hol_room random_start(int max_steps)
{
    hol_room r = hol_room_start();
    int n = (int)rnd((uint32_t)max_steps + 1);
    for (int i = 0; i < n; i++)
        hol_room_step(&r, (int)rnd(4)); /* refused steps leave r unchanged */
    return r;
}

/* A random tile at exactly distance d from the user's tile. */
static hol_tile random_target(const hol_room *user, int d)
{
    int q = hol_tile_q(user->tile);
    if (d > HOL_NAVTAB_MAX_RADIUS) {
        /* random canonical word, letter by letter */
        hol_tile rel = hol_tile_origin_q(q), c;
        assert_int_equal(hol_tile_child(rel, (int)rnd(4), &rel), HOL_OK);
        while (hol_tile_dist0(rel) < d) {
            static const int letters[3] = {0, 1, 3};
            if (!hol_tile_child(rel, letters[rnd(3)], &c))
                rel = c;
        }
        hol_heading_tile f = {user->tile, user->orient};
        for (int i = 0; i < d; i++)
            assert_int_equal(hol_heading_tile_step(f, hol_tile_letter(rel, i), &f), HOL_OK);
        assert_int_equal(hol_tile_dist(user->tile, f.tile), d);
        return f.tile;
    }
    hol_navtab ix;
    hol_navtab_init(&ix, q, 0, 0, d);
    uint32_t lo = ix.off[d], hi = ix.off[d + 1];
    hol_tile rel = hol_navtab_unrank(&ix, lo + rnd(hi - lo));
    hol_heading_tile f = {user->tile, user->orient};
    for (int i = 0; i < d; i++)
        assert_int_equal(hol_heading_tile_step(f, hol_tile_letter(rel, i), &f), HOL_OK);
    assert_int_equal(hol_tile_dist(user->tile, f.tile), d);
    return f.tile;
}

/* The walk stays in the room and ends on target. */
static void check_walk(const hol_room *start, const uint8_t *walk, int n,
                       hol_tile target)
{
    hol_room r = *start;
    for (int i = 0; i < n; i++)
        assert_int_equal(hol_room_step(&r, walk[i]), HOL_OK);
    assert_true(hol_tile_eq(r.tile, target));
}

/* ---- tile numbering ---- */

static void test_index(void **state)
{
    (void)state;
    static const uint32_t spec[13] = {1,    4,    12,   28,    64,    148,  340,
                                      780,  1792, 4116, 9452, 21708, 49856};
    hol_navtab ix;
    assert_int_equal(hol_navtab_init_index(&ix, 12), HOL_OK);
    for (int d = 0; d <= 12; d++)
        assert_int_equal(ix.off[d + 1] - ix.off[d], spec[d]);
    hol_tile prev = hol_tile_origin();
    for (uint32_t i = 0; i < ix.off[10]; i++) {
        hol_tile t = hol_navtab_unrank(&ix, i);
        char buf[HOL_TILE_ADDR_MAX];
        hol_tile back;
        hol_tile_print(t, buf);
        /* every word is a canonical address, ranks are dense and ordered */
        assert_int_equal(hol_tile_parse(buf, -1, &back), HOL_OK);
        assert_true(hol_tile_eq(back, t));
        assert_int_equal(hol_navtab_rank(&ix, t), i);
        assert_int_equal(hol_navtab_len(&ix, i), hol_tile_dist0(t));
        if (i > 0)
            assert_false(hol_tile_eq(prev, t));
        prev = t;
    }
    hol_tile far;
    assert_int_equal(hol_tile_parse("Nffffffffffff", -1, &far), HOL_OK);
    assert_int_equal(hol_navtab_rank(&ix, far), HOL_NAVTAB_NONE);
}

/* The neighbour table (built from parents and children, each other edge
 * stepped once) is hol_tile_step and rank, edge by edge, in every tiling. */
static void test_neighbours_are_steps(void **state)
{
    (void)state;
    for (int q = HOL_TILING_MIN_Q; q <= HOL_TILING_MAX_Q; q++) {
        hol_navtab tab;
        int r = q == 4 ? 6 : 9 - q / 2; /* a few thousand tiles each */
        assert_int_equal(hol_navtab_init(&tab, q, 3, 4, r), HOL_OK);
        void *m = malloc(hol_navtab_table_bytes(&tab)), *s = malloc(hol_navtab_scratch_bytes(&tab));
        assert_non_null(m);
        assert_non_null(s);
        assert_int_equal(hol_navtab_build(&tab, m, s), HOL_OK);
        for (uint32_t i = 0; i < tab.count; i++) {
            hol_tile t = hol_navtab_unrank(&tab, i), u;
            for (int turn = 0; turn < 4; turn++) {
                int arr;
                uint32_t want = HOL_NAVTAB_NONE;
                assert_int_equal(hol_tile_step(t, turn, &u, &arr), HOL_OK);
                uint32_t j = hol_navtab_rank(&tab, u);
                if (j != HOL_NAVTAB_NONE)
                    want = (j << 2) | (uint32_t)arr;
                if (tab.nb[4 * i + (uint32_t)turn] != want)
                    fail_msg("{4,%d} radius %d: tile %u turn %d: nb %x, step %x", q, r, i, turn,
                             tab.nb[4 * i + (uint32_t)turn], want);
            }
        }
        free(m);
        free(s);
    }
}

/* ---- the table: radius r agrees with radius r + 1 within r - 2 ---- */

/* Tables of radius r and r + more of one configuration agree within
 * r - 2 (r - trust_gap) and differ beyond (the check has teeth). */
static void check_converged_in(int q, int cols, int rows, int r, int more, int gap)
{
    hol_navtab a, b;
    assert_int_equal(hol_navtab_init(&a, q, cols, rows, r), HOL_OK);
    assert_int_equal(hol_navtab_init(&b, q, cols, rows, r + more), HOL_OK);
    void *ma = malloc(hol_navtab_table_bytes(&a)), *mb = malloc(hol_navtab_table_bytes(&b));
    void *s = malloc(hol_navtab_scratch_bytes(&b));
    assert_non_null(ma);
    assert_non_null(mb);
    assert_non_null(s);
    assert_int_equal(hol_navtab_build(&a, ma, s), HOL_OK);
    assert_int_equal(hol_navtab_build(&b, mb, s), HOL_OK);
    size_t n = (size_t)a.per * a.off[r - gap + 1];
    if (memcmp(a.cost, b.cost, n))
        fail_msg("{4,%d} %dx%d: the radius-%d table differs from radius %d within %d", q, cols,
                 rows, r, r + more, r - gap);
    /* and it does differ at the edge, so the check has teeth ({4,8} never
     * strays: its tables agree everywhere) */
    if (gap)
        assert_true(memcmp(a.cost, b.cost, (size_t)a.per * a.count) != 0);
    free(ma);
    free(mb);
    free(s);
}

static void check_converged(int r, int more)
{
    check_converged_in(5, 3, 3, r, more, 2);
}

static void test_table_converges(void **state)
{
    (void)state;
    for (int r = 4; r <= 12; r++)
        check_converged(r, 1);
    for (int r = 4; r <= 11; r++)
        check_converged(r, 2);
}

/* The default radius (14 against 15): the claim behind "exact within 12".
 * About 1 s and 80 MB. */
static void test_table_converges_default(void **state)
{
    (void)state;
    check_converged(HOL_NAV_DEFAULT_RADIUS, 1);
}

/* The tour leg table (state to state): radius r agrees with r + 1 within
 * r - 3 (one tile less than the tile table: reaching a given room state
 * may use one more tile of room), up to the default leg radius 10
 * (trusted 7). */
static void test_legs_converge(void **state)
{
    (void)state;
    hol_navtab tab;
    assert_int_equal(hol_navtab_init_index(&tab, 11), HOL_OK);
    void *m = malloc(hol_navtab_table_bytes(&tab));
    void *s = malloc(hol_navtab_scratch_bytes(&tab) > hol_navtab_leg_scratch_bytes(&tab, 11)
                         ? hol_navtab_scratch_bytes(&tab)
                         : hol_navtab_leg_scratch_bytes(&tab, 11));
    uint8_t *a = malloc(hol_navtab_leg_bytes(&tab, 11)), *b = malloc(hol_navtab_leg_bytes(&tab, 11));
    assert_non_null(m);
    assert_non_null(s);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(hol_navtab_build(&tab, m, s), HOL_OK);
    assert_int_equal(hol_navtab_build_legs(&tab, 5, a, s), HOL_OK);
    for (int r = 5; r <= 10; r++) {
        assert_int_equal(hol_navtab_build_legs(&tab, r + 1, b, s), HOL_OK);
        assert_memory_equal(a, b, 36 * 9 * (size_t)tab.off[r - 2]);
        assert_true(memcmp(a, b, hol_navtab_leg_bytes(&tab, r)) != 0);
        uint8_t *t = a;
        a = b;
        b = t;
    }
    /* the parity classes (hol_nav_legs.c): with p one bit per tile,
     * (col + row + o + p) mod 2 never changes, so every finite leg from a
     * tile joins states whose parities differ by one bit per tile */
    for (uint32_t i = 0; i < tab.off[9]; i++) {
        int cls = -1;
        for (int c = 0; c < 9; c++)
            for (int g = 0; g < 36; g++) {
                int v = hol_navtab_leg(&tab, a, i, 0, c, g / 9, g % 9);
                int par = (c % 3 + c / 3 + g / 9 + g % 9 % 3 + g % 9 / 3) & 1;
                if (v == 255)
                    continue;
                if (cls < 0)
                    cls = par;
                assert_int_equal(par, cls);
            }
        assert_true(cls >= 0);
    }
    /* leg costs to any arrival state agree with the tile table */
    for (uint32_t i = 0; i < tab.off[9]; i += 7)
        for (int o = 0; o < 4; o++)
            for (int c = 0; c < 9; c++) {
                int mn = 255;
                for (int g = 0; g < 36; g++) {
                    int v = hol_navtab_leg(&tab, a, i, o, c, g / 9, g % 9);
                    if (v < mn)
                        mn = v;
                }
                assert_int_equal(mn, hol_navtab_cost(&tab, i, o, c));
            }
    free(m);
    free(s);
    free(a);
    free(b);
}

static void test_table_small(void **state)
{
    (void)state;
    /* hand-checked costs from the start state (cell (1,1), orientation 0) */
    static const struct {
        const char *target;
        int cost;
    } cases[] = {{"O", 0}, {"N", 1}, {"W", 1}, {"Nr", 2}, {"Nf", 5}, {"Nff", 7},
                 {"Nffff", 11}, {"Nfffffff", 17}, {"Sfrlf", 12}};
    bf b;
    bf_init(&b, 1u << 21);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        hol_tile t;
        assert_int_equal(hol_tile_parse(cases[i].target, -1, &t), HOL_OK);
        hol_room s = hol_room_start();
        uint8_t walk[64];
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &s, t, 0, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.len, cases[i].cost);
        assert_int_equal(res.exact, 1);
        check_walk(&s, walk, res.len, t);
        assert_int_equal(bf_cost(&b, &s, t, res.len), res.len);
    }
    bf_free(&b);
}

/* ---- optimality against brute force ---- */

static void test_optimal_vs_bfs(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 21);
    int checked = 0, hist[9] = {0};
    /* quick (tests/quick.h): 160 queries, not 400, and 2 far ones, not 4 */
    int nq = test_quick() ? 160 : 400, nfar = test_quick() ? 2 : FAR_BFS;
    for (int q = 0; q < nq; q++) {
        hol_room s = random_start(40);
        int d = 1 + (int)rnd(q < nq / 2 ? 6 : 8);
        hol_tile t = random_target(&s, d);
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &s, t, 0, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.exact, 1);
        check_walk(&s, walk, res.len, t);
        /* the brute force finds nothing shorter, and finds this length */
        if (res.len > 33)
            continue; /* beyond the brute force's reach in test time */
        int c = bf_cost(&b, &s, t, res.len);
        assert_int_equal(c, res.len);
        checked++;
        hist[d]++;
    }
    /* a few far ones, from the start state (a BFS to depth ~36 is ~1 s) */
    int far_checked = 0;
    for (int q = 0; q < 200 && far_checked < nfar; q++) {
        hol_room s = hol_room_start();
        hol_tile t = random_target(&s, 10 + q % 3);
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &s, t, 0, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.exact, 1);
        check_walk(&s, walk, res.len, t);
        if (res.len > FAR_BFS_DEPTH)
            continue;
        assert_int_equal(bf_cost(&b, &s, t, res.len), res.len);
        far_checked++;
    }
    print_message("optimal vs BFS: %d far queries (distance 10..12)\n", far_checked);
    print_message("optimal vs BFS: %d queries (by distance 1..8: %d %d %d %d %d %d %d %d)\n",
                  checked, hist[1], hist[2], hist[3], hist[4], hist[5], hist[6],
                  hist[7], hist[8]);
    assert_true(hist[8] >= 5);
    bf_free(&b);
}

/* ---- anytime mode ---- */

/* A small navigator (radius 8, trusted 6) answers targets at distance 7 to
 * 10 in anytime mode; the default navigator gives the exact answers. */
static void test_anytime(void **state)
{
    (void)state;
    hol_nav_desc desc = {0};
    desc.radius = 8;
    desc.max_nodes = 1u << 16;
    hol_nav *small;
    assert_int_equal(hol_nav_create(&desc, &small), HOL_OK);
    assert_int_equal(hol_nav_table_exact_radius(small), 6);
    int n = 0, equal = 0, prefix = 0;
    for (int q = 0; q < 120; q++) {
        hol_room s = random_start(30);
        int d = 7 + (int)rnd(4);
        hol_tile t = random_target(&s, d);
        uint8_t walk[HOL_NAV_WALK_MAX], best[HOL_NAV_WALK_MAX];
        hol_nav_result res, opt;
        size_t budget = q % 2 ? 200 : 5000;
        assert_int_equal(hol_nav_find(small, &s, t, budget, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.exact, 0);
        assert_true(res.nodes <= budget);
        check_walk(&s, walk, res.len, t);
        assert_int_equal(hol_nav_find(g_nav, &s, t, 0, best, sizeof best, &opt), HOL_OK);
        assert_int_equal(opt.exact, 1);
        assert_true(res.len >= opt.len);
        n++;
        equal += res.len == opt.len;
        /* first 3 steps a prefix of an optimal walk: the remaining exact
         * cost after them is opt - 3 */
        hol_room r = s;
        int k = res.len < 3 ? res.len : 3;
        for (int i = 0; i < k; i++)
            hol_room_step(&r, walk[i]);
        hol_nav_result rest;
        assert_int_equal(hol_nav_find(g_nav, &r, t, 0, best, sizeof best, &rest), HOL_OK);
        prefix += rest.len + k == opt.len;
    }
    print_message("anytime (radius 8, targets 7..10): %d/%d optimal length, "
                  "%d/%d first 3 steps on an optimal walk\n", equal, n, prefix, n);
    assert_true(equal * 10 >= 9 * n); /* measured 100% with the default margin */
    assert_true(prefix * 10 >= 9 * n);
    hol_nav_destroy(small);
}

/* A lazy navigator (its arena untouched at create, hash cleared at the
 * first search) answers as an eager one, query for query: anytime finds
 * (the arena's nodes and hash), tours (the leg table built in the first,
 * on the arena as scratch), finds again after them. */
static void test_lazy_same(void **state)
{
    (void)state;
    hol_nav_desc desc = {0};
    desc.radius = 8;
    desc.max_nodes = 1u << 16;
    hol_nav *eager, *lazy;
    assert_int_equal(hol_nav_create(&desc, &eager), HOL_OK);
    hol_nav_prepare_tours(eager); /* as the app did at create */
    desc.lazy = 1;
    assert_int_equal(hol_nav_create(&desc, &lazy), HOL_OK);
    for (int q = 0; q < 60; q++) {
        hol_room s = random_start(20);
        uint8_t w1[HOL_NAV_WALK_MAX], w2[HOL_NAV_WALK_MAX];
        hol_nav_result r1, r2;
        hol_err e1, e2;
        if (q % 3 == 2) {
            hol_tile keys[3], chest = random_target(&s, 1 + (int)rnd(4));
            for (int i = 0; i < 3; i++)
                keys[i] = random_target(&s, 2 + (int)rnd(5));
            e1 = hol_nav_tour(eager, &s, keys, 1 + q % 3, chest, 0, w1, sizeof w1, &r1);
            e2 = hol_nav_tour(lazy, &s, keys, 1 + q % 3, chest, 0, w2, sizeof w2, &r2);
        } else {
            hol_tile t = random_target(&s, 3 + (int)rnd(9));
            size_t budget = q % 2 ? 300 : 0;
            e1 = hol_nav_find(eager, &s, t, budget, w1, sizeof w1, &r1);
            e2 = hol_nav_find(lazy, &s, t, budget, w2, sizeof w2, &r2);
        }
        assert_int_equal(e1, e2);
        if (e1)
            continue;
        assert_int_equal(r1.len, r2.len);
        assert_int_equal(r1.exact, r2.exact);
        assert_int_equal(r1.nodes, r2.nodes);
        assert_memory_equal(w1, w2, (size_t)r1.len);
    }
    hol_nav_destroy(eager);
    hol_nav_destroy(lazy);
}

/* Far targets: complete, valid walks, never exact, bounded work. */
static void test_far(void **state)
{
    (void)state;
    for (int q = 0; q < 6; q++) {
        hol_room s = random_start(20);
        int d = 13 + 4 * q;
        hol_tile t = random_target(&s, d);
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &s, t, 2000, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.exact, 0);
        check_walk(&s, walk, res.len, t);
        assert_true(res.len >= d);
        assert_true(res.len <= 4 * d + 8);
    }
    /* user and target on opposite sides of O, 90 tiles apart: farther than
     * a relative address reaches, so the waypoint chain alone answers */
    {
        hol_room u = hol_room_start();
        hol_tile t;
        assert_int_equal(hol_tile_parse("Sffffffffffffffffffffffffffffffffffffffff", -1, &u.tile),
                         HOL_OK);
        assert_int_equal(
            hol_tile_parse("Nfffffffffffffffffffffffffffffffffffffffffffffffff", -1, &t),
            HOL_OK);
        u.orient = 2;
        u.col = 0;
        u.row = 2;
        assert_int_equal(hol_tile_dist(u.tile, t), 91);
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &u, t, 100, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.exact, 0);
        check_walk(&u, walk, res.len, t);
        assert_true(res.len >= 91 && res.len <= 4 * 91);
        /* bad states are refused */
        u.col = 3;
        assert_int_equal(hol_nav_find(g_nav, &u, t, 100, walk, sizeof walk, &res), HOL_EARG);
    }
    /* a buffer too small is an error, not a truncated walk */
    hol_room s = hol_room_start();
    hol_tile t;
    assert_int_equal(hol_tile_parse("Nffffff", -1, &t), HOL_OK);
    uint8_t tiny[4];
    hol_nav_result res;
    assert_int_equal(hol_nav_find(g_nav, &s, t, 0, tiny, sizeof tiny, &res), HOL_ENOMEM);
}

/* Small and odd configurations still give valid walks. */
static void test_small_radius(void **state)
{
    (void)state;
    for (int r = 3; r <= 5; r++) {
        hol_nav_desc desc = {0};
        desc.radius = r;
        desc.max_nodes = 1024;
        hol_nav *nav;
        assert_int_equal(hol_nav_create(&desc, &nav), HOL_OK);
        assert_int_equal(hol_nav_table_exact_radius(nav), r - 2);
        for (int q = 0; q < 10; q++) {
            hol_room s = random_start(20);
            hol_tile t = random_target(&s, 1 + (int)rnd(9));
            uint8_t walk[HOL_NAV_WALK_MAX];
            hol_nav_result res;
            assert_int_equal(hol_nav_find(nav, &s, t, 0, walk, sizeof walk, &res), HOL_OK);
            check_walk(&s, walk, res.len, t);
            hol_tile keys[2] = {random_target(&s, 2), random_target(&s, 3)};
            assert_int_equal(hol_nav_tour(nav, &s, keys, 2, t, 0, walk, sizeof walk, &res),
                             HOL_OK);
            check_walk(&s, walk, res.len, t);
        }
        hol_nav_destroy(nav);
    }
    hol_nav_desc bad = {0};
    hol_nav *nav;
    bad.radius = 2;
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
    bad.radius = 16;
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
    bad.radius = 0;
    bad.max_nodes = 100;
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
}

/* ---- tours ---- */

static int perm_next(int *a, int n)
{
    int i = n - 2;
    while (i >= 0 && a[i] >= a[i + 1])
        i--;
    if (i < 0)
        return 0;
    int j = n - 1;
    while (a[j] <= a[i])
        j--;
    int t = a[i];
    a[i] = a[j];
    a[j] = t;
    for (int l = i + 1, r = n - 1; l < r; l++, r--) {
        t = a[l];
        a[l] = a[r];
        a[r] = t;
    }
    return 1;
}

static void test_tour_vs_bruteforce(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 21);
    for (int q = 0; q < 14; q++) {
        hol_room s = random_start(20);
        int nk = 1 + q % 3;
        hol_tile keys[5], chest;
        for (int i = 0; i < nk; i++)
            keys[i] = random_target(&s, 1 + (int)rnd(2));
        chest = random_target(&s, 1 + (int)rnd(2));
        if (q == 5)
            keys[1] = keys[0]; /* duplicate keys */
        if (q == 7)
            chest = s.tile; /* chest under the user */
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_tour(g_nav, &s, keys, nk, chest, 0, walk, sizeof walk, &res),
                         HOL_OK);
        assert_int_equal(res.exact, 1);
        /* the walk visits every key, then the chest */
        hol_room r = s;
        unsigned got = 0;
        for (int k = 0; k < nk; k++)
            if (hol_tile_eq(r.tile, keys[k]))
                got |= 1u << k;
        int chest_after = nk == 0 && hol_tile_eq(r.tile, chest);
        for (int i = 0; i < res.len; i++) {
            assert_int_equal(hol_room_step(&r, walk[i]), HOL_OK);
            for (int k = 0; k < nk; k++)
                if (hol_tile_eq(r.tile, keys[k]))
                    got |= 1u << k;
            if (got == (1u << nk) - 1 && hol_tile_eq(r.tile, chest))
                chest_after = 1;
        }
        assert_int_equal(got, (1u << nk) - 1);
        assert_true(chest_after);
        assert_true(hol_tile_eq(r.tile, chest));
        /* brute force: every order of the keys, BFS in (state, stage) */
        int order[5] = {0, 1, 2, 3, 4}, best = -1;
        do {
            hol_tile goals[6];
            for (int i = 0; i < nk; i++)
                goals[i] = keys[order[i]];
            goals[nk] = chest;
            int c = bf_order(&b, &s, goals, nk + 1, res.len);
            if (c >= 0 && (best < 0 || c < best))
                best = c;
        } while (perm_next(order, nk));
        assert_int_equal(best, res.len);
    }
    /* no keys: a plain walk to the chest */
    hol_room s = hol_room_start();
    hol_tile chest;
    assert_int_equal(hol_tile_parse("Nff", -1, &chest), HOL_OK);
    uint8_t walk[64];
    hol_nav_result res;
    assert_int_equal(hol_nav_tour(g_nav, &s, NULL, 0, chest, 0, walk, sizeof walk, &res),
                     HOL_OK);
    assert_int_equal(res.len, 7);
    assert_int_equal(hol_nav_tour(g_nav, &s, NULL, 6, chest, 0, walk, sizeof walk, &res),
                     HOL_EARG);
    bf_free(&b);
}

/* Tour legs beyond the leg table's trusted radius (hol_nav_legs.c,
 * through the sphere around the key): for a random room state and a key 8
 * tiles away, a BFS over absolute room states gives the fewest steps to
 * every room state on the key. The leg's lower bound may not exceed it,
 * its walk may not be shorter and must arrive in that state, where the two
 * meet (an exact leg) they equal it, and every state the bound calls
 * unreachable (the parity classes) is never reached. */
static void test_leg_bounds_vs_bfs(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 22);
    hol_nav_prepare_tours(g_nav);
    static hol__sph sph;
    static hol__legb L;
    static hol__legscr scr;
    int exact = 0, reach = 0, never = 0;
    for (int q = 0; q < 3; q++) {
        hol_room s = random_start(20);
        hol_tile key = random_target(&s, 8);
        hol__sph_fill(g_nav, key, &sph);
        assert_true(sph.n > 0);
        int ss = 9 * s.orient + s.col + 3 * s.row, maxub = 0;
        hol__legb_fill(g_nav, s.tile, key, &sph, &ss, 1, &L, &scr);
        for (int s2 = 0; s2 < 36; s2++)
            if (L.ub[HOL__LX(&L, ss, s2)] != 255 && L.ub[HOL__LX(&L, ss, s2)] > maxub)
                maxub = L.ub[HOL__LX(&L, ss, s2)];
        /* BFS to depth maxub: first arrival in each state on the key */
        int got[36];
        for (int s2 = 0; s2 < 36; s2++)
            got[s2] = -1;
        bf_reset(&b);
        bf_add(&b, &s, 0, -1, 0);
        if (hol_tile_eq(s.tile, key))
            got[ss] = 0;
        size_t head = 0;
        for (int depth = 1; depth <= maxub; depth++) {
            size_t end = b.n;
            for (; head < end; head++)
                for (int d = 0; d < 4; d++) {
                    hol_room r = b.st[head].room;
                    if (hol_room_step(&r, d) || bf_add(&b, &r, 0, (int32_t)head, d) >= 0)
                        continue;
                    int s2 = 9 * r.orient + r.col + 3 * r.row;
                    if (hol_tile_eq(r.tile, key) && got[s2] < 0)
                        got[s2] = depth;
                }
        }
        for (int s2 = 0; s2 < 36; s2++) {
            int lb = L.lb[HOL__LX(&L, ss, s2)], ub = L.ub[HOL__LX(&L, ss, s2)];
            if (got[s2] < 0) {
                assert_int_equal(ub, 255); /* a walk of ub steps would be found */
                never += lb == 255;
                continue;
            }
            reach++;
            assert_true(lb <= got[s2]);
            assert_true(ub >= got[s2]);
            if (lb == ub) {
                assert_int_equal(ub, got[s2]);
                exact++;
            }
            if (ub == 255)
                continue;
            uint8_t buf[256];
            hol__walk w = {buf, sizeof buf, 0, 0};
            hol__legb_walk(g_nav, &L, s.tile, ss, key, s2, &w);
            assert_int_equal((int)w.n, ub);
            hol_room r = s;
            for (size_t i = 0; i < w.n; i++)
                assert_int_equal(hol_room_step(&r, buf[i]), HOL_OK);
            assert_true(hol_tile_eq(r.tile, key));
            assert_int_equal(9 * r.orient + r.col + 3 * r.row, s2);
        }
    }
    print_message("legs 8 tiles beyond the start: %d states reached, %d exact legs agree, "
                  "%d proved unreachable (never reached)\n", reach, exact, never);
    assert_true(exact > reach / 2);
    assert_int_equal(never, 3 * 36 - reach); /* half the states, by parity */

    /* legs to the chest's tile beyond the main table's trusted radius
     * (first exit from the key's sphere): a radius-7 navigator (trusted 5,
     * legs trusted 4) and chests 6..8 tiles away, against bf_cost */
    hol_nav_desc desc = {0};
    desc.radius = 7;
    hol_nav *small;
    assert_int_equal(hol_nav_create(&desc, &small), HOL_OK);
    hol_nav_prepare_tours(small);
    static hol__chestb C;
    int cexact = 0, cn = 0;
    for (int q = 0; q < 24; q++) {
        hol_room s = random_start(20);
        hol_tile chest = random_target(&s, 6 + q % 3);
        hol__sph_fill(small, s.tile, &sph);
        assert_true(sph.n > 0);
        hol__chestb_fill(small, s.tile, chest, &sph, &C, &scr);
        int ss = 9 * s.orient + s.col + 3 * s.row;
        int best = bf_cost(&b, &s, chest, 40);
        assert_true(best >= 0);
        assert_true(C.lb[ss] <= best);
        assert_true(C.ub[ss] >= best);
        cn++;
        if (C.lb[ss] == C.ub[ss]) {
            assert_int_equal(C.ub[ss], best);
            cexact++;
        }
        uint8_t buf[256];
        hol__walk w = {buf, sizeof buf, 0, 0};
        hol__chestb_walk(small, &C, s.tile, ss, chest, &w);
        assert_int_equal((int)w.n, C.ub[ss]);
        hol_room r = s;
        for (size_t i = 0; i < w.n; i++)
            assert_int_equal(hol_room_step(&r, buf[i]), HOL_OK);
        assert_true(hol_tile_eq(r.tile, chest));
    }
    print_message("chest legs 6..8 tiles (radius-7 navigator): %d of %d exact, all agree\n",
                  cexact, cn);
    assert_true(cexact >= cn / 4); /* a small table proves less */
    hol_nav_destroy(small);
    bf_free(&b);
}

/* Fewest steps to hold every key and then stand on the chest: BFS over
 * (absolute room state, keys held), an independent model of the game's
 * rule (a key counts on entering its tile, the chest only once every key
 * is held). -1 if not within max_depth. */
typedef struct bf_level {
    const hol_tile *keys;
    int nk;
    hol_tile chest;
} bf_level;

#define BF_DONE 64 /* stage: the level is complete */

static int bf_next_held(const void *ctx, int stage, hol_tile tile)
{
    const bf_level *L = ctx;
    for (int k = 0; k < L->nk; k++)
        if (hol_tile_eq(tile, L->keys[k]))
            stage |= 1 << k;
    return stage == (1 << L->nk) - 1 && hol_tile_eq(tile, L->chest) ? BF_DONE : stage;
}

static int bf_tour(bf *b, const hol_room *start, const hol_tile *keys, int nk, hol_tile chest,
                   int max_depth)
{
    bf_level L = {keys, nk, chest};
    return bf_search(b, start, bf_next_held, &L, BF_DONE, max_depth);
}

/* Tours of 4 and 5 keys against bf_tour: the default navigator (dynamic
 * program) and small ones whose tables force the other paths (legs through
 * a midway tile, the A* with its heuristic). Every answer flagged exact
 * must equal the brute force; the others may not be shorter. */
static void test_tour_product_bfs(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 21);
    static const int radii[3] = {0, 5, 3};
    for (int v = 0; v < 3; v++) {
        hol_nav *nav = g_nav;
        if (radii[v]) {
            hol_nav_desc desc = {0};
            desc.radius = radii[v];
            assert_int_equal(hol_nav_create(&desc, &nav), HOL_OK);
        }
        int exact = 0, n = 10;
        for (int q = 0; q < n; q++) {
            hol_room s = random_start(20);
            int nk = 4 + q % 2;
            hol_tile keys[5], chest;
            int spread = v == 2 ? 3 : 2; /* radius 3: keys up to 6 apart, beyond its legs */
            for (int i = 0; i < nk; i++)
                keys[i] = random_target(&s, 1 + (int)rnd((uint32_t)spread));
            chest = random_target(&s, 1 + (int)rnd((uint32_t)spread));
            uint8_t walk[HOL_NAV_WALK_MAX];
            hol_nav_result res;
            assert_int_equal(hol_nav_tour(nav, &s, keys, nk, chest, 0, walk, sizeof walk, &res),
                             HOL_OK);
            /* the walk itself completes the level */
            hol_room r = s;
            unsigned got = 0;
            int done = 0;
            for (int i = 0; i <= res.len; i++) {
                if (i > 0)
                    assert_int_equal(hol_room_step(&r, walk[i - 1]), HOL_OK);
                for (int k = 0; k < nk; k++)
                    if (hol_tile_eq(r.tile, keys[k]))
                        got |= 1u << k;
                if (got == (1u << nk) - 1 && hol_tile_eq(r.tile, chest))
                    done = 1;
            }
            assert_true(done);
            int best = bf_tour(&b, &s, keys, nk, chest, res.len);
            assert_true(best >= 0 && best <= res.len);
            if (res.exact) {
                assert_int_equal(best, res.len);
                exact++;
            }
        }
        print_message("tours vs product BFS, radius %d: %d of %d exact, all agree\n",
                      radii[v] ? radii[v] : HOL_NAV_DEFAULT_RADIUS, exact, n);
        if (!radii[v])
            assert_int_equal(exact, n);
        else
            hol_nav_destroy(nav);
    }
    bf_free(&b);
}

/* The two exact tour methods agree: the default navigator's dynamic
 * program (keys within 7 tiles of each other, exact legs) against a
 * radius-7 navigator, whose leg table only covers 4 tiles: its legs go
 * through spheres (hol_nav_legs.c) and, where their bounds do not meet,
 * its A*. (The radius-3 navigator of test_tour_product_bfs has no sphere:
 * A* only.) */
static void test_tour_dp_vs_astar(void **state)
{
    (void)state;
    hol_nav_desc desc = {0};
    desc.radius = 7;
    hol_nav *small;
    assert_int_equal(hol_nav_create(&desc, &small), HOL_OK);
    int compared = 0, astar = 0, farc = 0;
    for (int q = 0; q < 24; q++) {
        hol_room s = random_start(20);
        int nk = 2 + q % 3;
        hol_tile keys[5], chest;
        for (int i = 0; i < nk; i++)
            keys[i] = random_target(&s, 2 + (int)rnd(2));
        chest = random_target(&s, 1 + (int)rnd(3));
        int far = 0;
        for (int i = 0; i < nk; i++)
            for (int j = 0; j < nk; j++)
                far |= hol_tile_dist(keys[i], keys[j]) > 4;
        uint8_t w1[HOL_NAV_WALK_MAX], w2[HOL_NAV_WALK_MAX];
        hol_nav_result r1, r2;
        assert_int_equal(hol_nav_tour(g_nav, &s, keys, nk, chest, 0, w1, sizeof w1, &r1),
                         HOL_OK);
        assert_int_equal(r1.exact, 1);
        assert_int_equal(r1.nodes, 0); /* the dynamic program */
        assert_int_equal(hol_nav_tour(small, &s, keys, nk, chest, 0, w2, sizeof w2, &r2),
                         HOL_OK);
        if (!r2.exact)
            continue;
        compared++;
        farc += far;
        astar += far && r2.nodes > 0;
        assert_int_equal(r1.len, r2.len);
    }
    print_message("tours: dynamic program vs small navigator: %d compared, %d with keys "
                  "beyond its leg table (%d by A*)\n", compared, farc, astar);
    assert_true(farc >= 8);
    hol_nav_destroy(small);
}

/* Five keys and a chest 1..8 tiles from the start (issue 11's levels):
 * every tour is exact at the default budget and its walk completes the
 * level. */
static void test_tour_spread8(void **state)
{
    (void)state;
    int nosearch = 0;
    for (int q = 0; q < 8; q++) {
        hol_room s = random_start(20);
        hol_tile keys[5], chest;
        for (int i = 0; i < 5; i++)
            keys[i] = random_target(&s, 1 + (int)rnd(8));
        chest = random_target(&s, 1 + (int)rnd(8));
        uint8_t walk[HOL_NAV_WALK_MAX];
        hol_nav_result res;
        assert_int_equal(hol_nav_tour(g_nav, &s, keys, 5, chest, 0, walk, sizeof walk, &res),
                         HOL_OK);
        assert_int_equal(res.exact, 1);
        nosearch += res.nodes == 0;
        hol_room r = s;
        unsigned got = 0;
        for (int i = 0; i <= res.len; i++) {
            if (i > 0)
                assert_int_equal(hol_room_step(&r, walk[i - 1]), HOL_OK);
            for (int k = 0; k < 5; k++)
                if (hol_tile_eq(r.tile, keys[k]))
                    got |= 1u << k;
        }
        assert_int_equal(got, 31u);
        assert_true(hol_tile_eq(r.tile, chest));
    }
    print_message("5 keys within 8 tiles: 8 of 8 exact, %d with no search\n", nosearch);
}

/* Budget exhausted: the greedy tour is still complete and valid. */
static void test_tour_budget(void **state)
{
    (void)state;
    hol_room s = hol_room_start();
    hol_tile keys[5], chest;
    static const char *const far[5] = {"Nfffffff", "Sfffffff", "Wfffffff", "Efffffff", "Nlffffff"};
    for (int i = 0; i < 5; i++)
        assert_int_equal(hol_tile_parse(far[i], -1, &keys[i]), HOL_OK);
    chest = random_target(&s, 4);
    uint8_t walk[HOL_NAV_WALK_MAX];
    hol_nav_result res;
    assert_int_equal(hol_nav_tour(g_nav, &s, keys, 5, chest, 50, walk, sizeof walk, &res),
                     HOL_OK);
    assert_int_equal(res.exact, 0);
    hol_room r = s;
    unsigned got = 0;
    for (int i = 0; i < res.len; i++) {
        assert_int_equal(hol_room_step(&r, walk[i]), HOL_OK);
        for (int k = 0; k < 5; k++)
            if (hol_tile_eq(r.tile, keys[k]))
                got |= 1u << k;
    }
    assert_int_equal(got, 31u);
    assert_true(hol_tile_eq(r.tile, chest));
}

/* ---- hot-cold field and direction ---- */

static void test_field(void **state)
{
    (void)state;
    assert_int_equal(hol_nav_field_count(0), 1);
    assert_int_equal(hol_nav_field_count(1), 5);
    assert_int_equal(hol_nav_field_count(4), 109);
    assert_int_equal(hol_nav_field_count(9), 0);
    for (int q = 0; q < 10; q++) {
        hol_room u = random_start(30);
        hol_tile obj[3];
        size_t nobj = (size_t)(q % 4);
        for (size_t i = 0; i < nobj; i++)
            obj[i] = random_target(&u, 1 + (int)rnd(9));
        hol_nav_cell cells[109];
        size_t n;
        assert_int_equal(hol_nav_field(&u, 4, obj, nobj, cells, 108, &n), HOL_ENOMEM);
        assert_int_equal(hol_nav_field(&u, 4, obj, nobj, cells, 109, &n), HOL_OK);
        assert_int_equal(n, 109);
        assert_true(hol_tile_eq(cells[0].tile, u.tile));
        for (size_t i = 0; i < n; i++) {
            assert_int_equal(cells[i].user_dist, hol_tile_dist(u.tile, cells[i].tile));
            assert_int_equal(cells[i].user_dist, hol_tile_dist0(cells[i].rel));
            if (i)
                assert_true(cells[i].user_dist >= cells[i - 1].user_dist);
            int hot = -1;
            for (size_t j = 0; j < nobj; j++) {
                int dd = hol_tile_dist(cells[i].tile, obj[j]);
                if (hot < 0 || dd < hot)
                    hot = dd;
            }
            assert_int_equal(cells[i].hot, hot);
            /* the relative address is the tile seen from the user */
            hol_tile rel;
            assert_int_equal(hol_tile_relative(u.tile, u.orient, cells[i].tile, &rel, NULL),
                             HOL_OK);
            assert_true(hol_tile_eq(rel, cells[i].rel));
            for (size_t j = 0; j < i; j++)
                assert_false(hol_tile_eq(cells[j].tile, cells[i].tile));
        }
    }
}

static void test_direction(void **state)
{
    (void)state;
    const double pi = 3.14159265358979323846;
    hol_room s = hol_room_start();
    /* the room's neighbours: N ahead (0), W left (+pi/2), E right (-pi/2) */
    static const struct {
        int dir;
        double angle;
    } cases[] = {{HOL_DIR_N, 0.0}, {HOL_DIR_W, pi / 2}, {HOL_DIR_E, -pi / 2}};
    for (int k = 0; k < 3; k++) {
        hol_room r = s;
        assert_int_equal(hol_room_step(&r, cases[k].dir), HOL_OK);
        double a, dist;
        assert_int_equal(hol_nav_direction(&s, r.tile, &a, &dist), HOL_OK);
        assert_true(fabs(a - cases[k].angle) < 1e-9);
        assert_true(fabs(dist - 1.0612750619) < 1e-9);
        /* and back: the room frame is carried, so from the neighbour the
         * start lies in the opposite room direction */
        double back;
        assert_int_equal(hol_nav_direction(&r, s.tile, &back, NULL), HOL_OK);
        assert_true(fabs(remainder(back - a - pi, 2 * pi)) < 1e-9);
    }
    /* a far tile straight ahead along room north stays at angle 0 from
     * every state that walked north and back south (a room-frame check) */
    hol_tile far;
    assert_int_equal(hol_tile_parse("Nffffffffffffffffffff", -1, &far), HOL_OK);
    double a, dist;
    assert_int_equal(hol_nav_direction(&s, far, &a, &dist), HOL_OK);
    assert_true(fabs(a) < 1e-9);
    assert_true(dist > 20.0);
    assert_int_equal(hol_nav_direction(&s, s.tile, &a, &dist), HOL_OK);
    assert_true(a == 0.0 && dist == 0.0);
    /* rotating the room turns the arrow: random states, the angle to a tile
     * equals that of the tile seen in the rotated frame */
    for (int q = 0; q < 20; q++) {
        hol_room u = random_start(30);
        hol_tile t = random_target(&u, 1 + (int)rnd(12));
        double a0, a1;
        assert_int_equal(hol_nav_direction(&u, t, &a0, NULL), HOL_OK);
        hol_room v = u;
        v.orient = (uint8_t)((u.orient + 1) & 3); /* room turned a quarter left */
        assert_int_equal(hol_nav_direction(&v, t, &a1, NULL), HOL_OK);
        double diff = remainder(a0 - a1 - pi / 2, 2 * pi);
        assert_true(fabs(diff) < 1e-6);
    }
}

/* Against the independent hyperboloid model (tests/model.h): the user's
 * frame is the product of the carried room steps, the objective's frame the
 * product along its address; the arrow is the angle of the objective's
 * centre in the user's frame. Objectives up to 24 tiles away. */
static void test_direction_model(void **state)
{
    (void)state;
    double worst = 0;
    for (int q = 0; q < 60; q++) {
        hol_room u = hol_room_start();
        model_mat mu = model_identity();
        int n = (int)rnd(16);
        for (int i = 0; i < n; i++) {
            int d = (int)rnd(4);
            if (hol_room_step(&u, d) == HOL_OK)
                mu = model_step(mu, d);
        }
        int dist = 1 + (int)rnd(24);
        hol_tile t = random_target(&u, dist);
        int codes[HOL_TILE_MAX_DIST];
        int len = hol_tile_dist0(t);
        for (int i = 0; i < len; i++)
            codes[i] = hol_tile_letter(t, i);
        model_mat rel = model_mul(model_inv(mu), model_walk_letters(codes, len));
        double x = rel.m[2], y = rel.m[5], w = rel.m[8];
        double want = atan2(-x, y), want_dist = acosh(w);
        double a, dd;
        assert_int_equal(hol_nav_direction(&u, t, &a, &dd), HOL_OK);
        double err = fabs(remainder(a - want, 2 * 3.14159265358979323846));
        if (err > worst)
            worst = err;
        assert_true(err < 1e-6);
        assert_true(fabs(dd - want_dist) < 1e-6 * (1 + want_dist));
    }
    print_message("direction vs hyperboloid model: worst angle error %.2e rad\n", worst);
}

/* ---- input lines ---- */

static void test_parse(void **state)
{
    (void)state;
    hol_room r;
    hol_tile t;
    char msg[128];
    assert_int_equal(hol_nav_parse_line("- O", 3, &r, &t, msg, sizeof msg), HOL_OK);
    assert_true(hol_tile_eq(t, hol_tile_origin()));
    assert_int_equal(r.col, 1);
    assert_int_equal(hol_nav_parse_line(" \tNE  Nr\t", 9, &r, &t, msg, sizeof msg), HOL_OK);
    assert_int_equal(r.col, 2);
    assert_int_equal(r.row, 0);
    assert_int_equal(hol_nav_parse_line("NN O", 4, &r, &t, msg, sizeof msg), HOL_EROOM);
    assert_non_null(strstr(msg, "step 2"));
    assert_int_equal(hol_nav_parse_line("NX O", 4, &r, &t, msg, sizeof msg), HOL_EPARSE);
    assert_non_null(strstr(msg, "character 2"));
    assert_int_equal(hol_nav_parse_line("- Nrr", 5, &r, &t, msg, sizeof msg), HOL_ENOTCANON);
    assert_non_null(strstr(msg, "El"));
    assert_int_equal(hol_nav_parse_line("- Q", 3, &r, &t, msg, sizeof msg), HOL_EPARSE);
    assert_int_equal(hol_nav_parse_line("-", 1, &r, &t, msg, sizeof msg), HOL_EPARSE);
    assert_int_equal(hol_nav_parse_line("", 0, &r, &t, msg, sizeof msg), HOL_EPARSE);
    assert_int_equal(hol_nav_parse_line("- O O", 5, &r, &t, msg, sizeof msg), HOL_EPARSE);
    assert_int_equal(hol_nav_parse_line("- O\0", 4, &r, &t, msg, sizeof msg), HOL_EPARSE);
    char tiny[8];
    assert_int_equal(hol_nav_parse_line("- Nrr", 5, &r, &t, tiny, sizeof tiny), HOL_ENOTCANON);
    assert_int_equal(strlen(tiny), 7);
}

/* The original's method (plain A*, tests/plain_astar.h) and hol_nav agree
 * on the fewest steps: 120 random queries at tile distance 1..9. */
static void test_plain_astar_agrees(void **state)
{
    (void)state;
    plain_astar pa;
    assert_int_equal(pa_init(&pa, 20), 0);
    static uint8_t walk[HOL_NAV_WALK_MAX];
    for (int q = 0; q < 120; q++) {
        hol_room s = random_start(30);
        int d = 1 + q % 9;
        hol_tile t = random_target(&s, d);
        size_t ex = 0;
        int len = pa_find(&pa, &s, t, &ex);
        assert_true(len >= 0);
        hol_nav_result res;
        assert_int_equal(hol_nav_find(g_nav, &s, t, 0, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.len, len);
        assert_true(ex > 0);
    }
    pa_fini(&pa);
}

/* ---- every tiling {4,Q} and room size (SPEC 7) ---- */

static const int room_sizes[][2] = {{3, 3}, {4, 4}, {5, 5}, {3, 4}, {4, 3}, {3, 5}, {5, 3},
                                    {4, 5}, {5, 4}};
#define NROOMS (int)(sizeof room_sizes / sizeof room_sizes[0])

/* The gaps the navigator claims (hol_nav.c): its tables are trusted to
 * their radius minus the first, its leg table minus the second. */
static void claimed_gaps(int q, int C, int R, int *gap, int *leg_gap)
{
    static const int g[5][6][2] = {
        {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}, {{2, 3}, {3, 4}, {4, 5}, {4, 4}, {3, 4}, {4, 5}},
        {{3, 3}, {3, 4}, {4, 5}, {4, 4}, {4, 4}, {4, 5}}, {{3, 4}, {4, 5}, {4, 6}, {4, 4}, {4, 5}, {5, 6}},
        {{0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {0, 0}}};
    static const int idx[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    *gap = g[q - 4][idx[C - 3][R - 3]][0];
    *leg_gap = g[q - 4][idx[C - 3][R - 3]][1];
}

/* The trust claim of every configuration: the table of radius r + 1 gives
 * the same costs within r - 2 (the leg table: within r - 3), at radii
 * small enough for the test's time; make bench checks the shipped radii. */
static void test_configs_converge(void **state)
{
    (void)state;
    static const int top[9] = {0, 0, 0, 0, 0, 9, 8, 8, 7};
    for (int q = 5; q <= 8; q++)
        for (int z = 0; z < NROOMS; z++) {
            int C = room_sizes[z][0], R = room_sizes[z][1], gap, lgap;
            claimed_gaps(q, C, R, &gap, &lgap);
            check_converged_in(q, C, R, top[q], 1, gap);
        }
    /* legs: 3 x 3, 4 x 4, 5 x 5 and an oblong room, at radius 7 */
    for (int q = 5; q <= 8; q++)
        for (int z = 0; z < 4; z++) {
            int C = room_sizes[z == 3 ? 5 : z][0], R = room_sizes[z == 3 ? 5 : z][1], gap, lgap;
            claimed_gaps(q, C, R, &gap, &lgap);
            hol_navtab tab;
            assert_int_equal(hol_navtab_init(&tab, q, C, R, 8), HOL_OK);
            size_t sb = hol_navtab_scratch_bytes(&tab), lb = hol_navtab_leg_bytes(&tab, 8);
            size_t ls = hol_navtab_leg_scratch_bytes(&tab, 8);
            void *m = malloc(hol_navtab_table_bytes(&tab)), *sc = malloc(sb > ls ? sb : ls);
            uint8_t *a = malloc(lb), *b = malloc(lb);
            assert_true(m && sc && a && b);
            assert_int_equal(hol_navtab_build(&tab, m, sc), HOL_OK);
            for (int r = 7; r <= 7; r++) {
                assert_int_equal(hol_navtab_build_legs(&tab, r, a, sc), HOL_OK);
                assert_int_equal(hol_navtab_build_legs(&tab, r + 1, b, sc), HOL_OK);
                size_t n = (size_t)tab.nst * (size_t)tab.per * tab.off[r - lgap + 1];
                if (memcmp(a, b, n))
                    fail_msg("{4,%d} %dx%d: legs of radius %d and %d differ within %d", q, C, R, r,
                             r + 1, r - lgap);
            }
            free(m);
            free(sc);
            free(a);
            free(b);
        }
}

static hol_nav *make_nav(int q, int C, int R, int radius)
{
    hol_nav_desc d = {0};
    hol_nav *nav;
    d.tiling_q = q;
    d.room_cols = C;
    d.room_rows = R;
    d.radius = radius;
    d.max_nodes = 1u << 16;
    assert_int_equal(hol_nav_create(&d, &nav), HOL_OK);
    return nav;
}

/* Optimal walks against BFS over absolute room states (which knows only
 * hol_room_step), in 3 x 3, 4 x 4, 5 x 5 and oblong rooms of every hyperbolic
 * tiling: radius-8 navigators, targets 1..6 tiles from random states. */
static void test_configs_optimal_vs_bfs(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 22);
    static const int rooms[4] = {0, 1, 2, 5};
    int checked = 0, unreach = 0;
    int per = test_quick() ? 4 : 10; /* quick (tests/quick.h): 4 queries a geometry, not 10 */
    for (int q = 5; q <= 8; q++)
        for (int z = 0; z < 4; z++) {
            int C = room_sizes[rooms[z]][0], R = room_sizes[rooms[z]][1], gap, lgap;
            claimed_gaps(q, C, R, &gap, &lgap);
            hol_nav *nav = make_nav(q, C, R, 9);
            int trust = hol_nav_table_exact_radius(nav);
            assert_int_equal(trust, 9 - gap);
            assert_true(hol_nav_tour_exact_radius(nav) <= 9 - lgap); /* leg radius 9 or less */
            int gq, gc, gr;
            hol_nav_geometry(nav, &gq, &gc, &gr);
            assert_true(gq == q && gc == C && gr == R);
            hol_room s0;
            assert_int_equal(hol_room_start_in(q, C, R, &s0), HOL_OK);
            for (int k = 0; k < per; k++) {
                hol_room s = random_start_from(s0, 30);
                hol_tile t = random_target(&s, 1 + (int)rnd((uint32_t)(trust < 6 ? trust : 6)));
                uint8_t walk[HOL_NAV_WALK_MAX];
                hol_nav_result res;
                hol_err err = hol_nav_find(nav, &s, t, 0, walk, sizeof walk, &res);
                if (err == HOL_EUNREACH) {
                    /* {4,8}: no walk reaches it; none to 16 steps, at least */
                    assert_int_equal(q, 8);
                    assert_int_equal(bf_cost(&b, &s, t, 16), -1);
                    unreach++;
                    continue;
                }
                assert_int_equal(err, HOL_OK);
                assert_int_equal(res.exact, 1);
                check_walk(&s, walk, res.len, t);
                if (res.len > 20)
                    continue; /* beyond the brute force in test time */
                assert_int_equal(bf_cost(&b, &s, t, res.len), res.len);
                checked++;
            }
            /* a room state of another size or tiling is refused */
            hol_room other;
            uint8_t walk[8];
            hol_nav_result res;
            hol_room_start_in(q == 5 ? 6 : 5, C, R, &other);
            assert_int_equal(hol_nav_find(nav, &other, other.tile, 0, walk, 8, &res), HOL_EARG);
            hol_room_start_in(q, C == 3 ? 4 : 3, R, &other);
            assert_int_equal(hol_nav_find(nav, &other, s0.tile, 0, walk, 8, &res), HOL_EARG);
            hol_nav_destroy(nav);
        }
    print_message("every tiling, rooms 3x3 4x4 5x5 3x5: %d walks equal to BFS, %d out of "
                  "reach in {4,8} (BFS: none to 16 steps)\n", checked, unreach);
    assert_true(checked > 10 * per);
    bf_free(&b);
}

/* Tours of 2 to 4 keys in larger rooms against the product BFS. */
static void test_configs_tours(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 22);
    static const int cfg[4][3] = {{6, 4, 4}, {8, 5, 5}, {5, 3, 5}, {7, 4, 5}};
    int exact = 0, n = 0, unreach = 0;
    for (int c = 0; c < 4; c++) {
        hol_nav *nav = make_nav(cfg[c][0], cfg[c][1], cfg[c][2], 9);
        hol_room s0;
        assert_int_equal(hol_room_start_in(cfg[c][0], cfg[c][1], cfg[c][2], &s0), HOL_OK);
        for (int k = 0; k < 4; k++) {
            hol_room s = random_start_from(s0, 20);
            int nk = 2 + k % 3;
            hol_tile keys[5], chest;
            for (int i = 0; i < nk; i++)
                keys[i] = random_target(&s, 1 + (int)rnd(2));
            chest = random_target(&s, 1 + (int)rnd(2));
            uint8_t walk[HOL_NAV_WALK_MAX];
            hol_nav_result res;
            hol_err err = hol_nav_tour(nav, &s, keys, nk, chest, 0, walk, sizeof walk, &res);
            if (err == HOL_EUNREACH) {
                /* {4,8}: a key or the chest out of the room's reach */
                assert_int_equal(cfg[c][0], 8);
                assert_int_equal(bf_tour(&b, &s, keys, nk, chest, 14), -1);
                unreach++;
                continue;
            }
            assert_int_equal(err, HOL_OK);
            hol_room r = s;
            unsigned got = 0;
            for (int i = 0; i <= res.len; i++) {
                if (i > 0)
                    assert_int_equal(hol_room_step(&r, walk[i - 1]), HOL_OK);
                for (int j = 0; j < nk; j++)
                    if (hol_tile_eq(r.tile, keys[j]))
                        got |= 1u << j;
            }
            assert_int_equal(got, (1u << nk) - 1);
            assert_true(hol_tile_eq(r.tile, chest));
            int best = bf_tour(&b, &s, keys, nk, chest, res.len);
            assert_true(best >= 0 && best <= res.len);
            if (res.exact)
                assert_int_equal(best, res.len);
            exact += res.exact;
            n++;
        }
        hol_nav_destroy(nav);
    }
    print_message("tours in 4x4, 5x5, 3x5, 4x5 rooms: %d of %d exact, all agree; %d out of reach "
                  "in {4,8}\n", exact, n, unreach);
    assert_int_equal(exact, n);
    bf_free(&b);
}

/* The flat grid: a room reaches exactly its own tiles; the navigator
 * answers those exactly (against BFS) and refuses the others. */
static void test_flat(void **state)
{
    (void)state;
    bf b;
    bf_init(&b, 1u << 16);
    for (int z = 0; z < NROOMS; z++) {
        int C = room_sizes[z][0], R = room_sizes[z][1];
        hol_nav *nav = make_nav(4, C, R, 0);
        assert_int_equal(hol_nav_table_exact_radius(nav), hol_nav_table_radius(nav));
        hol_room s0;
        assert_int_equal(hol_room_start_in(4, C, R, &s0), HOL_OK);
        for (int k = 0; k < 12; k++) {
            hol_room s = random_start_from(s0, 20);
            hol_tile t = random_target(&s, 1 + (int)rnd(10));
            uint8_t walk[HOL_NAV_WALK_MAX];
            hol_nav_result res;
            hol_err err = hol_nav_find(nav, &s, t, 0, walk, sizeof walk, &res);
            int c = bf_cost(&b, &s, t, 40);
            if (c < 0) {
                assert_int_equal(err, HOL_EUNREACH);
                continue;
            }
            assert_int_equal(err, HOL_OK);
            assert_int_equal(res.exact, 1);
            assert_int_equal(res.len, c);
            check_walk(&s, walk, res.len, t);
        }
        /* the room's far corner is reached, one tile beyond it is not */
        uint8_t walk[HOL_NAV_WALK_MAX], steps[16];
        int n = 0;
        for (int i = C / 2; i < C - 1; i++)
            steps[n++] = HOL_DIR_E;
        for (int i = R / 2; i < R - 1; i++)
            steps[n++] = HOL_DIR_S;
        hol_tile corner, beyond;
        assert_int_equal(hol_tile_from_walk_q(4, steps, (size_t)n, &corner, NULL), HOL_OK);
        steps[n++] = HOL_DIR_E;
        assert_int_equal(hol_tile_from_walk_q(4, steps, (size_t)n, &beyond, NULL), HOL_OK);
        hol_nav_result res;
        assert_int_equal(hol_nav_find(nav, &s0, corner, 0, walk, sizeof walk, &res), HOL_OK);
        assert_int_equal(res.len, n - 1);
        assert_int_equal(hol_nav_find(nav, &s0, beyond, 0, walk, sizeof walk, &res), HOL_EUNREACH);
        hol_tile keys[2] = {corner, s0.tile};
        assert_int_equal(hol_nav_tour(nav, &s0, keys, 2, s0.tile, 0, walk, sizeof walk, &res),
                         HOL_OK);
        assert_int_equal(res.len, 2 * (n - 1));
        assert_int_equal(res.exact, 1);
        keys[1] = beyond;
        assert_int_equal(hol_nav_tour(nav, &s0, keys, 2, s0.tile, 0, walk, sizeof walk, &res),
                         HOL_EUNREACH);
        hol_nav_destroy(nav);
    }
    bf_free(&b);
}

/* Every configuration's navigator keeps within the budget (60 MB; all
 * guidance memory under 64 MB), and {4,5} 3 x 3 keeps today's radii. */
static void test_configs_memory(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++)
        for (int z = 0; z < NROOMS; z++) {
            hol_nav_desc d = {0};
            d.tiling_q = q;
            d.room_cols = room_sizes[z][0];
            d.room_rows = room_sizes[z][1];
            size_t bytes = hol_nav_memory_for(&d);
            assert_true(bytes > 0 && bytes <= HOL_NAV_BUDGET);
        }
    assert_int_equal(hol_nav_table_exact_radius(g_nav), 12);
    assert_int_equal(hol_nav_table_radius(g_nav), 14);
    assert_int_equal(hol_nav_tour_exact_radius(g_nav), HOL_NAV_TOUR_EXACT_RADIUS);
    assert_int_equal(hol_nav_memory(g_nav), hol_nav_memory_for(NULL));
    hol_nav_desc bad = {0};
    bad.tiling_q = 9;
    assert_int_equal(hol_nav_memory_for(&bad), 0);
    hol_nav *nav;
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
    bad.tiling_q = 8;
    bad.room_cols = 6;
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
    bad.room_cols = 5;
    bad.room_rows = 5;
    bad.radius = 15; /* {4,8} 5 x 5 at radius 15: far over HOL_NAV_MAX_BYTES */
    assert_int_equal(hol_nav_create(&bad, &nav), HOL_EARG);
}

/* The field and the arrows in every tiling: the field against
 * hol_tile_dist, the arrows against the model of that tiling. */
static void test_configs_field_direction(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++) {
        hol_room u0;
        assert_int_equal(hol_room_start_in(q, 4, 5, &u0), HOL_OK);
        hol_room u = random_start_from(u0, 20);
        hol_tile obj[2] = {random_target(&u, 3), random_target(&u, 5)};
        size_t cnt = hol_nav_field_count_q(q, 3), n;
        assert_int_equal(cnt, hol_tile_count_at(q, 0) + hol_tile_count_at(q, 1) +
                                  hol_tile_count_at(q, 2) + hol_tile_count_at(q, 3));
        hol_nav_cell cells[200];
        assert_true(cnt <= 200);
        assert_int_equal(hol_nav_field(&u, 3, obj, 2, cells, cnt, &n), HOL_OK);
        assert_int_equal(n, cnt);
        for (size_t i = 0; i < n; i++) {
            assert_int_equal(hol_tile_q(cells[i].tile), q);
            assert_int_equal(cells[i].user_dist, hol_tile_dist(u.tile, cells[i].tile));
            int h0 = hol_tile_dist(cells[i].tile, obj[0]), h1 = hol_tile_dist(cells[i].tile, obj[1]);
            assert_int_equal(cells[i].hot, h0 < h1 ? h0 : h1);
        }
        hol_tile other = hol_tile_origin_q(q == 5 ? 6 : 5);
        assert_int_equal(hol_nav_field(&u, 3, &other, 1, cells, cnt, &n), HOL_EARG);
        /* arrows against the model */
        model_use_tiling(q);
        for (int k = 0; k < 20; k++) {
            hol_room v = u0;
            model_mat mu = model_identity();
            for (int i = 0; i < 12; i++) {
                int d = (int)rnd(4);
                if (hol_room_step(&v, d) == HOL_OK)
                    mu = model_step(mu, d);
            }
            hol_tile t = random_target(&v, 1 + (int)rnd(8));
            int codes[HOL_TILE_MAX_DIST], len = hol_tile_dist0(t);
            for (int i = 0; i < len; i++)
                codes[i] = hol_tile_letter(t, i);
            model_mat rel = model_mul(model_inv(mu), model_walk_letters(codes, len));
            double x = rel.m[2], y = rel.m[5], a, dd;
            assert_int_equal(hol_nav_direction(&v, t, &a, &dd), HOL_OK);
            if (hol_tile_eq(v.tile, t))
                continue;
            assert_true(fabs(remainder(a - atan2(-x, y), 2 * 3.14159265358979323846)) < 1e-6);
            double want = q == 4 ? sqrt(x * x + y * y) : acosh(rel.m[8]);
            assert_true(fabs(dd - want) < 1e-6 * (1 + want));
        }
        assert_int_equal(hol_nav_direction(&u, other, NULL, NULL), HOL_EARG);
    }
    model_use_tiling(5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_index),
        cmocka_unit_test(test_neighbours_are_steps),
        cmocka_unit_test(test_plain_astar_agrees),
        cmocka_unit_test(test_table_converges),
        cmocka_unit_test(test_table_converges_default),
        cmocka_unit_test(test_legs_converge),
        cmocka_unit_test(test_leg_bounds_vs_bfs),
        cmocka_unit_test(test_tour_spread8),
        cmocka_unit_test(test_table_small),
        cmocka_unit_test(test_optimal_vs_bfs),
        cmocka_unit_test(test_anytime),
        cmocka_unit_test(test_far),
        cmocka_unit_test(test_small_radius),
        cmocka_unit_test(test_tour_vs_bruteforce),
        cmocka_unit_test(test_tour_product_bfs),
        cmocka_unit_test(test_tour_dp_vs_astar),
        cmocka_unit_test(test_tour_budget),
        cmocka_unit_test(test_field),
        cmocka_unit_test(test_direction),
        cmocka_unit_test(test_direction_model),
        cmocka_unit_test(test_parse),
        cmocka_unit_test(test_configs_memory),
        cmocka_unit_test(test_configs_converge),
        cmocka_unit_test(test_configs_optimal_vs_bfs),
        cmocka_unit_test(test_configs_tours),
        cmocka_unit_test(test_flat),
        cmocka_unit_test(test_lazy_same),
        cmocka_unit_test(test_configs_field_direction),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
