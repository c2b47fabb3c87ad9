/* test_tile.c - the tiling core against an independent hyperboloid model.
 *
 * Every check compares core/ with tests/model.h, which shares no code with
 * it: addresses (one per tile, shortest, SPEC counts), neighbours and the
 * carried frame, relative addresses, distances between arbitrary pairs, the
 * room state, hyperboloid coordinates, parsing, printing and the reach.
 * The language check also runs against the rules published with the
 * original system and must reject them (SPEC section 3). The same proofs
 * run for every other tiling {4,Q} (each against its own model: the
 * hyperboloid of {4,Q}, integer coordinates for the flat {4,4}), with rooms
 * of every size and the options' text (SPEC section 7).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_hyper.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "model.h"
#include "quick.h"

/* Checked exhaustively to this distance; SPEC gives counts to 12. A deeper
 * run: make BUILD=build/deep CFLAGS=-DHOL_TEST_MAXLEN=14 unit */
#ifndef HOL_TEST_MAXLEN
#define HOL_TEST_MAXLEN 12
#endif
#define MAXLEN HOL_TEST_MAXLEN
#define SPEC_MAXLEN 12

static const int spec_counts[13] = {1,    4,    12,   28,    64,    148,  340,
                                    780,  1792, 4116, 9452, 21708, 49856};

static model_bfs bfs;

static int setup(void **state)
{
    (void)state;
    return model_bfs_run(&bfs, MAXLEN + 1);
}

static int teardown(void **state)
{
    (void)state;
    model_bfs_free(&bfs);
    return 0;
}

/* ---- helpers ---- */

static void codes_to_text(const int *codes, int n, char *out)
{
    if (n == 0) {
        strcpy(out, "O");
        return;
    }
    for (int i = 0; i < n; i++)
        out[i] = i == 0 ? "NWSE"[codes[i]] : "fl?r"[codes[i]];
    out[n] = '\0';
}

static int tile_codes(hol_tile t, int *codes)
{
    int n = hol_tile_dist0(t);
    for (int i = 0; i < n; i++)
        codes[i] = hol_tile_letter(t, i);
    return n;
}

static model_mat tile_frame(hol_tile t)
{
    int codes[HOL_TILE_MAX_DIST];
    int n = tile_codes(t, codes);
    return model_walk_letters(codes, n);
}

static hol_tile parse_ok(const char *s)
{
    hol_tile t;
    hol_err err = hol_tile_parse(s, -1, &t);
    if (err)
        fail_msg("parse '%s': %s", s, hol_err_str(err));
    return t;
}

/* ---- the address language ---- */

typedef int (*acceptor_fn)(const int *codes, int n);

static int g_q = 5; /* the tiling accept_core parses in */

static int accept_core(const int *codes, int n)
{
    char s[64];
    hol_tile t;
    codes_to_text(codes, n, s);
    return hol_tile_parse_q(g_q, s, -1, &t) == HOL_OK;
}

/* The validity rules published with the original system: no two right turns
 * in a row; no two left turns without a right turn between them. */
static int accept_published(const int *codes, int n)
{
    int last_turn_left = 0;
    for (int i = 1; i < n; i++) {
        if (codes[i] == 3 && codes[i - 1] == 3 && i > 1)
            return 0;
        if (codes[i] == 1) {
            if (last_turn_left)
                return 0;
            last_turn_left = 1;
        } else if (codes[i] == 3) {
            last_turn_left = 0;
        }
    }
    return 1;
}

#define LANG_MAX 31 /* longest words a language check takes */

typedef struct lang_check {
    acceptor_fn accepts;
    const model_bfs *bfs;
    int maxlen;
    const int *spec; /* tiles by distance, spec[0..nspec) */
    int nspec;
    int *owner; /* per model tile: index of the word that addresses it */
    char (*words)[LANG_MAX + 2];
    int nwords;
    int per_len[LANG_MAX + 1];
    char problem[256];
} lang_check;

static void lang_note(lang_check *c, const char *fmt, ...)
{
    if (c->problem[0])
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->problem, sizeof c->problem, fmt, ap);
    va_end(ap);
}

/* Both acceptors are prefix-closed (a word with a rejected prefix is
 * rejected), so the search stops at a rejected word: it visits every
 * accepted word to maxlen. */
static void lang_dfs(lang_check *c, int *codes, int n, model_mat m, int heading)
{
    if (n > 0 && !c->accepts(codes, n))
        return;
    char s[LANG_MAX + 2];
    codes_to_text(codes, n, s);
    int i = model_find(c->bfs, m.m[2], m.m[5]);
    if (i < 0 || c->bfs->tiles[i].dist != n)
        lang_note(c, "accepts %s, which is not a shortest walk", s);
    else if (c->owner[i] >= 0)
        lang_note(c, "%s and %s address the same tile", c->words[c->owner[i]], s);
    else {
        c->owner[i] = c->nwords;
        strcpy(c->words[c->nwords++], s);
        c->per_len[n]++;
    }
    if (n == c->maxlen || c->problem[0])
        return;
    for (int k = 0; k < 4; k++) {
        if (n > 0 && k == 2)
            continue; /* no letter turns back */
        int h = n == 0 ? k : (heading + k) & 3;
        codes[n] = k;
        lang_dfs(c, codes, n + 1, model_step(m, h), h);
    }
}

/* 0 if `accepts` gives every tile of b to maxlen exactly one shortest
 * address and the SPEC counts (spec[0..nspec)); otherwise 1 and
 * c->problem says why. */
static int lang_run_in(lang_check *c, acceptor_fn accepts, const model_bfs *b, int maxlen,
                       const int *spec, int nspec)
{
    memset(c, 0, sizeof *c);
    assert_true(maxlen <= LANG_MAX && maxlen < b->max_dist + 1);
    c->accepts = accepts;
    c->bfs = b;
    c->maxlen = maxlen;
    c->spec = spec;
    c->nspec = nspec;
    c->owner = malloc(sizeof *c->owner * (size_t)b->count);
    c->words = malloc(sizeof *c->words * (size_t)b->count);
    assert_non_null(c->owner);
    assert_non_null(c->words);
    for (int i = 0; i < b->count; i++)
        c->owner[i] = -1;
    int codes[LANG_MAX + 1];
    lang_dfs(c, codes, 0, model_identity(), 0);
    for (int i = 0; i < b->count && !c->problem[0]; i++)
        if (b->tiles[i].dist <= maxlen && c->owner[i] < 0)
            lang_note(c, "a tile at distance %d has no address", b->tiles[i].dist);
    for (int d = 0; d <= maxlen && !c->problem[0]; d++)
        if (c->per_len[d] != b->per_dist[d] || (d < nspec && b->per_dist[d] != spec[d]))
            lang_note(c, "distance %d: %d addresses, %d tiles, SPEC says %d", d,
                      c->per_len[d], b->per_dist[d], d < nspec ? spec[d] : -1);
    return c->problem[0] != 0;
}

static int lang_run(lang_check *c, acceptor_fn accepts)
{
    return lang_run_in(c, accepts, &bfs, MAXLEN, spec_counts, SPEC_MAXLEN + 1);
}

static void lang_free(lang_check *c)
{
    free(c->owner);
    free(c->words);
}

static void test_model_counts(void **state)
{
    (void)state;
    for (int d = 0; d <= SPEC_MAXLEN && d <= MAXLEN; d++)
        assert_int_equal(bfs.per_dist[d], spec_counts[d]);
}

static void test_addresses_one_per_tile_shortest(void **state)
{
    (void)state;
    lang_check c;
    if (lang_run(&c, accept_core))
        fail_msg("core addresses: %s", c.problem);
    lang_free(&c);
}

static void test_published_rules_are_rejected(void **state)
{
    (void)state;
    lang_check c;
    assert_int_equal(lang_run(&c, accept_published), 1);
    print_message("published rules rejected: %s\n", c.problem);
    lang_free(&c);
    /* and the two counterexamples SPEC names */
    int lffl[5] = {0, 1, 0, 0, 1}, rfrfr[6] = {0, 3, 0, 3, 0, 3};
    assert_false(accept_published(lffl, 5));
    assert_true(accept_core(lffl, 5));
    assert_true(accept_published(rfrfr, 6));
    assert_false(accept_core(rfrfr, 6));
}

static void enum_words(hol_tile t, int maxlen, void (*fn)(hol_tile))
{
    fn(t);
    if (hol_tile_dist0(t) == maxlen)
        return;
    for (int k = 0; k < 4; k++) {
        hol_tile c;
        if (hol_tile_child(t, k, &c) == HOL_OK)
            enum_words(c, maxlen, fn);
    }
}

/* The automaton API agrees with parsing: a child is canonical exactly when
 * the automaton accepts its letter. */
static void check_automaton(hol_tile t)
{
    int n = hol_tile_dist0(t), st = hol_tile_state(t);
    if (n == 0) {
        assert_int_equal(st, -1);
        return;
    }
    int q = hol_tile_q(t);
    assert_true(st >= 0 && st < hol_tile_states(q) && st < HOL_TILE_MAX_STATES);
    for (int c = 0; c < 4; c++) {
        hol_tile ch;
        int next = hol_tile_automaton_q(q, st, c);
        if (q == 5)
            assert_int_equal(next, hol_tile_automaton(st, c));
        assert_int_equal(next >= 0, hol_tile_child(t, c, &ch) == HOL_OK);
        if (next >= 0 && hol_tile_dist0(ch) < HOL_TILE_MAX_DIST)
            assert_int_equal(hol_tile_state(ch), next);
    }
}

static void test_automaton_api(void **state)
{
    (void)state;
    enum_words(hol_tile_origin(), 8, check_automaton);
    assert_int_equal(hol_tile_automaton(-1, 0), -1);
    assert_int_equal(hol_tile_automaton(HOL_TILE_STATES, 0), -1);
    assert_int_equal(hol_tile_automaton(0, 2), -1);
}

/* ---- neighbours, frames, relative addresses, distances ---- */

static void check_step(hol_tile t)
{
    model_mat c = tile_frame(t);
    for (int k = 0; k < 4; k++) {
        hol_tile nb;
        int arr;
        char s[HOL_TILE_ADDR_MAX], sn[HOL_TILE_ADDR_MAX];
        hol_tile_print(t, s);
        if (k == 2 && hol_tile_dist0(t) == 0) {
            /* O: direction S is the branch S */
        }
        assert_int_equal(hol_tile_step(t, k, &nb, &arr), HOL_OK);
        hol_tile_print(nb, sn);
        /* the frame carried across edge k, facing the direction of travel */
        model_mat moved = model_mul(model_mul(c, model_rot(k)), model_fwd());
        model_mat cn = tile_frame(nb);
        if (!model_same_point(cn, moved))
            fail_msg("step %s dir %d gave %s, which is not the neighbour", s, k, sn);
        if (model_frame_diff(cn, moved) != arr)
            fail_msg("step %s dir %d: arrival %d, model %d", s, k, arr,
                     model_frame_diff(cn, moved));
        /* and back again */
        hol_tile back;
        int arr2;
        assert_int_equal(hol_tile_step(nb, arr + 2, &back, &arr2), HOL_OK);
        assert_true(hol_tile_eq(back, t));
        assert_int_equal((arr2 + 2) & 3, k & 3);
    }
}

static void test_neighbours_and_frames(void **state)
{
    (void)state;
    /* HOL_TEST_QUICK (tests/quick.h): to distance 9, 5 times fewer tiles */
    int depth = test_quick() ? MAXLEN - 3 : MAXLEN - 1;
    enum_words(hol_tile_origin(), depth, check_step);
    print_message("neighbours of every tile to distance %d checked\n", depth);
}

static uint64_t rng_state = 0x1234567887654321u;
static uint64_t rng(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

/* A uniformly random canonical word of length n, through the core's child
 * rule (its acceptance is checked against the model above). */
static hol_tile random_tile(int n)
{
    hol_tile t = hol_tile_origin();
    while (hol_tile_dist0(t) < n) {
        hol_tile c;
        int k = (int)(rng() % 4);
        if (hol_tile_child(t, k, &c) == HOL_OK)
            t = c;
    }
    return t;
}

static void test_relative_and_distance(void **state)
{
    (void)state;
    int checked = 0, iters = test_quick() ? 10000 : 40000; /* tests/quick.h */
    for (int iter = 0; iter < iters; iter++) {
        hol_tile a = random_tile((int)(rng() % 9));
        hol_tile b = random_tile((int)(rng() % 9));
        int north = (int)(rng() % 4);
        model_mat ca = model_mul(tile_frame(a), model_rot(north));
        model_mat rel = model_mul(model_inv(ca), tile_frame(b));
        int d = model_dist0(&bfs, rel);
        if (d < 0)
            continue; /* beyond the model */
        hol_tile r;
        int facing;
        char sa[HOL_TILE_ADDR_MAX], sb[HOL_TILE_ADDR_MAX];
        hol_tile_print(a, sa);
        hol_tile_print(b, sb);
        assert_int_equal(hol_tile_relative(a, north, b, &r, &facing), HOL_OK);
        if (hol_tile_dist0(r) != d)
            fail_msg("relative %s -> %s: length %d, model distance %d", sa, sb,
                     hol_tile_dist0(r), d);
        if (model_frame_diff(tile_frame(r), rel) != facing)
            fail_msg("relative %s -> %s (north %d): wrong tile or frame", sa, sb,
                     north);
        if (north == 0) {
            assert_int_equal(hol_tile_dist(a, b), d);
            assert_int_equal(hol_tile_dist(b, a), d);
        }
        checked++;
    }
    print_message("%d pairs checked\n", checked);
    assert_true(checked > iters / 2);
}

/* ---- the room ---- */

static void test_room_walks_match_model(void **state)
{
    (void)state;
    for (int w = 0; w < 2000; w++) {
        hol_room room = hol_room_start();
        model_mat frame = model_identity(); /* +y = room north */
        int col = 1, row = 1;
        for (int s = 0; s < 12; s++) {
            int dir = (int)(rng() % 4), dc, dr;
            hol_dir_delta(dir, &dc, &dr);
            hol_room before = room;
            hol_err err = hol_room_step(&room, dir);
            int inside = col + dc >= 0 && col + dc < 3 && row + dr >= 0 && row + dr < 3;
            if (!inside) {
                assert_int_equal(err, HOL_EROOM);
                assert_memory_equal(&room, &before, sizeof room);
                continue;
            }
            assert_int_equal(err, HOL_OK);
            col += dc;
            row += dr;
            frame = model_step(frame, dir);
            assert_int_equal(room.col, col);
            assert_int_equal(room.row, row);
            model_mat c = tile_frame(room.tile);
            assert_true(model_same_point(c, frame));
            assert_int_equal(model_frame_diff(c, frame), room.orient);
        }
    }
}

static void test_holonomy(void **state)
{
    (void)state;
    hol_room room = hol_room_start();
    const char *walk = "NESW";
    for (const char *p = walk; *p; p++)
        assert_int_equal(hol_room_step(&room, hol_dir_from_char(*p)), HOL_OK);
    /* back on cell (1,1), but not on the origin: one step away, on E */
    assert_int_equal(room.col, 1);
    assert_int_equal(room.row, 1);
    assert_false(hol_tile_eq(room.tile, hol_tile_origin()));
    assert_true(hol_tile_eq(room.tile, parse_ok("E")));
    /* five steps "forward, turn left" close a loop, with the frame turned */
    uint8_t five[5] = {HOL_DIR_N, HOL_DIR_W, HOL_DIR_S, HOL_DIR_E, HOL_DIR_N};
    hol_tile t;
    int orient;
    assert_int_equal(hol_tile_from_walk(five, 5, &t, &orient), HOL_OK);
    assert_true(hol_tile_eq(t, hol_tile_origin()));
    assert_int_not_equal(orient, 0);
    /* SPEC example: NE reaches Nr */
    uint8_t ne[2] = {HOL_DIR_N, HOL_DIR_E};
    assert_int_equal(hol_tile_from_walk(ne, 2, &t, NULL), HOL_OK);
    assert_true(hol_tile_eq(t, parse_ok("Nr")));
}

static void test_walk_parse(void **state)
{
    (void)state;
    uint8_t d[8];
    size_t n, bad = 99;
    assert_int_equal(hol_walk_parse("NESW", 4, d, 8, &n, &bad), HOL_OK);
    assert_int_equal(n, 4);
    assert_int_equal(d[1], HOL_DIR_E);
    assert_int_equal(hol_walk_parse("-", 1, d, 8, &n, &bad), HOL_OK);
    assert_int_equal(n, 0);
    assert_int_equal(hol_walk_parse("", 0, d, 8, &n, &bad), HOL_OK);
    assert_int_equal(n, 0);
    assert_int_equal(hol_walk_parse("NEx", 3, d, 8, &n, &bad), HOL_EPARSE);
    assert_int_equal(bad, 2);
    assert_int_equal(hol_walk_parse("NNNNNNNNN", 9, d, 8, &n, &bad), HOL_ENOMEM);
}

/* ---- text ---- */

static void check_print_parse(hol_tile t)
{
    char s[HOL_TILE_ADDR_MAX];
    hol_tile u;
    int n = hol_tile_print(t, s);
    assert_int_equal((int)strlen(s), n);
    assert_int_equal(hol_tile_parse(s, -1, &u), HOL_OK);
    assert_true(hol_tile_eq(t, u));
    assert_int_equal(hol_tile_hash(t), hol_tile_hash(u));
}

static void test_parse_print(void **state)
{
    (void)state;
    enum_words(hol_tile_origin(), 8, check_print_parse);
    hol_tile t, keep = parse_ok("Nr");
    t = keep;
    assert_int_equal(hol_tile_parse("", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("X", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("Nx", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("NF", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("OO", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("fN", -1, &t), HOL_EPARSE);
    assert_int_equal(hol_tile_parse("Nrr", -1, &t), HOL_ENOTCANON);
    assert_int_equal(hol_tile_parse("Nll", -1, &t), HOL_ENOTCANON);
    assert_int_equal(hol_tile_parse("Nlfl", -1, &t), HOL_ENOTCANON);
    assert_int_equal(hol_tile_parse("Nrfrfr", -1, &t), HOL_ENOTCANON);
    assert_int_equal(hol_tile_parse("Nrrx", -1, &t), HOL_EPARSE);
    assert_true(hol_tile_eq(t, keep)); /* failures leave the output alone */
    assert_int_equal(hol_tile_parse("Nlffl", -1, &t), HOL_OK);
    /* non-canonical walks resolve to their tile */
    assert_int_equal(hol_tile_resolve("Nrr", -1, &t), HOL_OK);
    assert_true(hol_tile_eq(t, parse_ok("El")));
    assert_int_equal(hol_tile_resolve("Wrfr", -1, &t), HOL_OK);
    assert_true(hol_tile_eq(t, parse_ok("Wrfr")));
    assert_int_equal(hol_tile_resolve("Nlfl", -1, &t), HOL_OK);
    assert_true(hol_tile_eq(t, parse_ok("Wrfr")));
}

/* ---- the reach ---- */

static void test_reach(void **state)
{
    (void)state;
    char s[HOL_TILE_MAX_DIST + 2];
    hol_tile t, far, keep = parse_ok("S");
    s[0] = 'N';
    memset(s + 1, 'f', HOL_TILE_MAX_DIST - 1);
    s[HOL_TILE_MAX_DIST] = '\0';
    far = parse_ok(s);
    assert_int_equal(hol_tile_dist0(far), HOL_TILE_MAX_DIST);
    s[HOL_TILE_MAX_DIST] = 'f';
    s[HOL_TILE_MAX_DIST + 1] = '\0';
    t = keep;
    assert_int_equal(hol_tile_parse(s, -1, &t), HOL_ERANGE);
    assert_true(hol_tile_eq(t, keep));
    /* stepping outward past the reach fails and changes nothing */
    int arr = 7;
    t = keep;
    assert_int_equal(hol_tile_step(far, HOL_TURN_F, &t, &arr), HOL_ERANGE);
    assert_true(hol_tile_eq(t, keep));
    assert_int_equal(arr, 7);
    assert_int_equal(hol_tile_child(far, HOL_TURN_F, &t), HOL_ERANGE);
    /* sideways along the rim stays in reach or fails cleanly */
    for (int k = 0; k < 4; k++) {
        hol_err err = hol_tile_step(far, k, &t, &arr);
        assert_true(err == HOL_OK || err == HOL_ERANGE);
        if (!err)
            assert_true(hol_tile_dist0(t) <= HOL_TILE_MAX_DIST);
    }
    /* the room refuses a step beyond the reach and keeps its state */
    hol_room room = {far, 0, 1, 1, 0, 0};
    hol_room before = room;
    assert_int_equal(hol_room_step(&room, HOL_DIR_N), HOL_ERANGE);
    assert_memory_equal(&room, &before, sizeof room);
    /* distances work between any two tiles in reach, up to 120 */
    s[0] = 'S';
    s[HOL_TILE_MAX_DIST] = '\0';
    hol_tile opposite = parse_ok(s);
    assert_int_equal(hol_tile_dist(far, opposite), 2 * HOL_TILE_MAX_DIST);
    assert_int_equal(hol_tile_relative(far, 0, opposite, &t, NULL), HOL_ERANGE);
    uint8_t letters[HOL_TILE_REL_MAX];
    assert_int_equal(hol_tile_relative_letters(far, 0, opposite, letters, NULL),
                     2 * HOL_TILE_MAX_DIST);
    /* invalid words are refused */
    hol_tile bad = far;
    bad.bits[1] |= UINT64_C(63) << 58;
    assert_int_equal(hol_tile_step(bad, 0, &t, &arr), HOL_EARG);
    assert_int_equal(hol_tile_dist(bad, far), -1);
}

/* Long words: neighbour-and-back, the vertex relation and the triangle
 * inequality, where the model cannot reach. */
static void test_far_consistency(void **state)
{
    (void)state;
    for (int iter = 0; iter < 3000; iter++) {
        hol_tile t = random_tile(40 + (int)(rng() % 20));
        /* five times "step, turn left" returns the same flag */
        hol_heading_tile f = {t, (int)(rng() % 4)}, g = f;
        int ok = 1;
        for (int i = 0; i < 5 && ok; i++) {
            if (hol_heading_tile_step(g, 0, &g)) {
                ok = 0;
                break;
            }
            g.facing = (g.facing + 1) & 3;
        }
        if (ok) {
            assert_true(hol_tile_eq(g.tile, f.tile));
            assert_int_equal(g.facing, f.facing);
        }
        hol_tile u = random_tile(40 + (int)(rng() % 20));
        hol_tile v = random_tile(40 + (int)(rng() % 20));
        int duv = hol_tile_dist(u, v), dvu = hol_tile_dist(v, u);
        int dtu = hol_tile_dist(t, u), dtv = hol_tile_dist(t, v);
        assert_int_equal(duv, dvu);
        assert_true(dtv <= dtu + duv);
        assert_true(hol_tile_dist(t, t) == 0);
        /* a neighbour is at distance 1 */
        hol_tile nb;
        if (hol_tile_step(t, (int)(rng() % 4), &nb, NULL) == HOL_OK)
            assert_int_equal(hol_tile_dist(t, nb), 1);
    }
}

/* ---- hyperboloid coordinates ---- */

static void test_hyperboloid(void **state)
{
    (void)state;
    assert_true(fabs(hol_hyper_edge() - model_edge()) < 1e-15);
    for (int iter = 0; iter < 2000; iter++) {
        hol_tile a = random_tile((int)(rng() % 7));
        hol_tile b = random_tile((int)(rng() % 7));
        int north = (int)(rng() % 4);
        double m[9], p[3], ang, dist;
        assert_int_equal(hol_hyper_frame(a, north, b, m), HOL_OK);
        model_mat want = model_mul(model_inv(model_mul(tile_frame(a), model_rot(north))),
                                   tile_frame(b));
        for (int i = 0; i < 9; i++)
            assert_true(fabs(m[i] - want.m[i]) < 1e-9 * (1 + fabs(want.m[8])));
        assert_int_equal(hol_hyper_pos(a, north, b, p, &ang, &dist), HOL_OK);
        assert_true(fabs(cosh(dist) - want.m[8]) < 1e-9 * want.m[8]);
        if (dist > 1e-9) {
            double wa = atan2(-want.m[2], want.m[5]);
            assert_true(fabs(remainder(ang - wa, 2 * acos(-1.0))) < 1e-9);
        }
        double z[2];
        hol_hyper_to_disk(p, z);
        assert_true(z[0] * z[0] + z[1] * z[1] < 1.0);
    }
    /* far from O, precision depends only on the relative distance */
    hol_tile far = random_tile(58), nb;
    int arr;
    assert_int_equal(hol_tile_step(far, HOL_TURN_L, &nb, &arr), HOL_OK);
    double p[3], ang, dist;
    assert_int_equal(hol_hyper_pos(far, 0, nb, p, &ang, &dist), HOL_OK);
    assert_true(fabs(dist - model_edge()) < 1e-12);
    assert_true(fabs(ang - acos(-1.0) / 2) < 1e-12); /* to the left */
}

/* ---- every tiling {4,Q} ----
 * The same proofs for Q = 4, 6, 7, 8 ({4,5} above), each against its own
 * model: the hyperboloid of {4,Q}, or for Q = 4 integer coordinates. */

typedef struct tiling_case {
    int q, maxlen; /* the proofs run to maxlen */
    int nspec;
    int spec[16]; /* SPEC 7 counts by distance */
} tiling_case;

/* Deeper (a minute, 2 GB): make BUILD=build/deep CFLAGS=-DHOL_TEST_DEEP unit */
#ifdef HOL_TEST_DEEP
#define DEEPER 2
#else
#define DEEPER 0
#endif
static const tiling_case tilings[] = {
    {4, 24 + DEEPER, 0, {0}}, /* 4d, checked below */
    {6, 11 + DEEPER, 8, {1, 4, 12, 32, 84, 220, 576, 1508}},
    {7, 10 + DEEPER, 7, {1, 4, 12, 36, 100, 284, 800}},
    {8, 10 + DEEPER, 7, {1, 4, 12, 36, 104, 300, 868}},
};
#define NTILINGS (int)(sizeof tilings / sizeof tilings[0])

/* The depth the proofs of a tiling run to: 2 less with HOL_TEST_QUICK
 * (tests/quick.h), still past every SPEC count of the tiling. */
static int tiling_maxlen(const tiling_case *tc)
{
    return tc->maxlen - (test_quick() ? 2 : 0);
}

/* A uniformly random letter, then canonical children: a random tile of
 * {4,q} at distance n. */
static hol_tile random_tile_q(int q, int n)
{
    hol_tile t = hol_tile_origin_q(q);
    while (hol_tile_dist0(t) < n) {
        hol_tile c;
        int k = (int)(rng() % 4);
        if (hol_tile_child(t, k, &c) == HOL_OK)
            t = c;
    }
    return t;
}

static void test_tilings_addresses(void **state)
{
    (void)state;
    for (int i = 0; i < NTILINGS; i++) {
        const tiling_case *tc = &tilings[i];
        model_bfs b;
        int maxlen = tiling_maxlen(tc);
        model_use_tiling(tc->q);
        g_q = tc->q;
        assert_int_equal(model_bfs_run(&b, maxlen + 1), 0);
        int flat[LANG_MAX + 1];
        for (int d = 0; d <= LANG_MAX; d++)
            flat[d] = d ? 4 * d : 1;
        const int *spec = tc->q == 4 ? flat : tc->spec;
        int nspec = tc->q == 4 ? maxlen + 1 : tc->nspec;
        lang_check c;
        if (lang_run_in(&c, accept_core, &b, maxlen, spec, nspec))
            fail_msg("{4,%d} addresses: %s", tc->q, c.problem);
        for (int d = 0; d <= maxlen; d++)
            assert_int_equal(hol_tile_count_at(tc->q, d), (uint64_t)b.per_dist[d]);
        print_message("{4,%d}: every tile to distance %d has one address, a shortest walk "
                      "(%d words)\n", tc->q, maxlen, c.nwords);
        lang_free(&c);
        model_bfs_free(&b);
    }
    model_use_tiling(5);
    g_q = 5;
}

static void test_tilings_neighbours(void **state)
{
    (void)state;
    for (int i = 0; i < NTILINGS; i++) {
        const tiling_case *tc = &tilings[i];
        model_use_tiling(tc->q);
        int depth = tiling_maxlen(tc) - 2 < 9 ? tiling_maxlen(tc) - 2 : 9;
        enum_words(hol_tile_origin_q(tc->q), depth, check_step);
        enum_words(hol_tile_origin_q(tc->q), depth, check_automaton);
        print_message("{4,%d}: neighbours and frames of every tile to distance %d\n", tc->q,
                      depth);
    }
    model_use_tiling(5);
}

static void test_tilings_relative(void **state)
{
    (void)state;
    for (int i = 0; i < NTILINGS; i++) {
        const tiling_case *tc = &tilings[i];
        model_bfs b;
        model_use_tiling(tc->q);
        assert_int_equal(model_bfs_run(&b, tiling_maxlen(tc)), 0);
        int checked = 0, half = tiling_maxlen(tc) / 2;
        for (int iter = 0; iter < 6000; iter++) {
            hol_tile a = random_tile_q(tc->q, (int)(rng() % (unsigned)(half + 1)));
            hol_tile t = random_tile_q(tc->q, (int)(rng() % (unsigned)(half + 1)));
            int north = (int)(rng() % 4), facing;
            model_mat rel = model_mul(model_inv(model_mul(tile_frame(a), model_rot(north))),
                                      tile_frame(t));
            int d = model_dist0(&b, rel);
            if (d < 0)
                continue;
            hol_tile r;
            assert_int_equal(hol_tile_relative(a, north, t, &r, &facing), HOL_OK);
            assert_int_equal(hol_tile_q(r), tc->q);
            assert_int_equal(hol_tile_dist0(r), d);
            assert_int_equal(model_frame_diff(tile_frame(r), rel), facing);
            assert_int_equal(hol_tile_dist(a, t), hol_tile_dist(t, a));
            if (north == 0)
                assert_int_equal(hol_tile_dist(a, t), d);
            checked++;
        }
        assert_true(checked > 3000);
        model_bfs_free(&b);
    }
    model_use_tiling(5);
}

/* Far from O, where no model reaches: Q times "step, turn left" closes
 * the loop round a vertex, neighbours are at distance 1 and back, and
 * distances are symmetric and obey the triangle inequality. In {4,4} the
 * address is a plain coordinate: its distance is |x| + |y|. */
static void test_tilings_far(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++) {
        int reach = hol_tile_reach(q);
        for (int iter = 0; iter < 600; iter++) {
            hol_tile t = random_tile_q(q, reach - 20 + (int)(rng() % 21));
            hol_heading_tile f = {t, (int)(rng() % 4)}, g = f;
            int ok = 1;
            for (int i = 0; i < q && ok; i++) {
                ok = hol_heading_tile_step(g, 0, &g) == HOL_OK;
                g.facing = (g.facing + 1) & 3;
            }
            if (ok) {
                assert_true(hol_tile_eq(g.tile, f.tile));
                assert_int_equal(g.facing, f.facing);
            }
            hol_tile u = random_tile_q(q, reach - 20 + (int)(rng() % 21)), nb, back;
            int duv = hol_tile_dist(t, u);
            assert_int_equal(duv, hol_tile_dist(u, t));
            hol_tile v = random_tile_q(q, (int)(rng() % (unsigned)reach));
            assert_true(hol_tile_dist(t, v) <= duv + hol_tile_dist(u, v));
            int k = (int)(rng() % 4), arr, arr2;
            if (hol_tile_step(t, k, &nb, &arr) == HOL_OK) {
                assert_int_equal(hol_tile_dist(t, nb), 1);
                assert_int_equal(hol_tile_step(nb, arr + 2, &back, &arr2), HOL_OK);
                assert_true(hol_tile_eq(back, t));
            }
        }
    }
    /* {4,4}: (x, y) of a tile from its walk */
    for (int iter = 0; iter < 2000; iter++) {
        hol_tile t = random_tile_q(4, (int)(rng() % 59)), u = random_tile_q(4, (int)(rng() % 59));
        int xy[2][2];
        for (int w = 0; w < 2; w++) {
            hol_tile x = w ? u : t;
            int h = 0;
            xy[w][0] = xy[w][1] = 0;
            for (int i = 0; i < hol_tile_dist0(x); i++) {
                static const int dx[4] = {0, -1, 0, 1}, dy[4] = {1, 0, -1, 0};
                h = (h + hol_tile_letter(x, i)) & 3;
                xy[w][0] += dx[h];
                xy[w][1] += dy[h];
            }
            assert_int_equal(hol_tile_dist0(x), abs(xy[w][0]) + abs(xy[w][1]));
        }
        assert_int_equal(hol_tile_dist(t, u), abs(xy[0][0] - xy[1][0]) + abs(xy[0][1] - xy[1][1]));
    }
}

static int room_same(const hol_room *a, const hol_room *b)
{
    return hol_tile_eq(a->tile, b->tile) && a->orient == b->orient && a->col == b->col &&
           a->row == b->row && a->more_cols == b->more_cols && a->more_rows == b->more_rows;
}

/* Rooms of every size in every tiling: random walks against the model,
 * refused steps at the room's bounds, the start cell. */
static void test_rooms_sizes(void **state)
{
    (void)state;
    static const int sizes[6][2] = {{3, 3}, {4, 4}, {5, 5}, {3, 5}, {5, 3}, {4, 5}};
    for (int q = 4; q <= 8; q++)
        for (int z = 0; z < 6; z++) {
            int C = sizes[z][0], R = sizes[z][1];
            model_use_tiling(q);
            hol_room start;
            assert_int_equal(hol_room_start_in(q, C, R, &start), HOL_OK);
            assert_int_equal(hol_room_cols(&start), C);
            assert_int_equal(hol_room_rows(&start), R);
            assert_int_equal(start.col, C / 2);
            assert_int_equal(start.row, R / 2);
            assert_true(hol_room_ok(&start));
            for (int w = 0; w < 60; w++) {
                hol_room room = start;
                model_mat frame = model_identity();
                int col = C / 2, row = R / 2;
                for (int k = 0; k < 16; k++) {
                    int dir = (int)(rng() % 4), dc, dr;
                    hol_dir_delta(dir, &dc, &dr);
                    hol_room before = room;
                    hol_err err = hol_room_step(&room, dir);
                    if (col + dc < 0 || col + dc >= C || row + dr < 0 || row + dr >= R) {
                        assert_int_equal(err, HOL_EROOM);
                        assert_true(room_same(&room, &before));
                        continue;
                    }
                    assert_int_equal(err, HOL_OK);
                    col += dc;
                    row += dr;
                    frame = model_step(frame, dir);
                    assert_int_equal(room.col, col);
                    assert_int_equal(room.row, row);
                    assert_int_equal(hol_room_cols(&room), C);
                    model_mat c = tile_frame(room.tile);
                    assert_true(model_same_point(c, frame));
                    assert_int_equal(model_frame_diff(c, frame), room.orient);
                }
            }
        }
    model_use_tiling(5);
    hol_room r = hol_room_start(), d;
    assert_int_equal(hol_room_start_in(0, 0, 0, &d), HOL_OK);
    assert_true(room_same(&r, &d)); /* the defaults are today's start */
    assert_int_equal(hol_room_start_in(9, 3, 3, &d), HOL_EARG);
    assert_int_equal(hol_room_start_in(5, 2, 3, &d), HOL_EARG);
    assert_int_equal(hol_room_start_in(5, 3, 6, &d), HOL_EARG);
    r.more_cols = 3; /* a 6-column room does not exist */
    assert_false(hol_room_ok(&r));
    assert_int_equal(hol_room_step(&r, HOL_DIR_E), HOL_EARG);
}

/* The flat grid has no holonomy: every walk of a C x R room in {4,4}
 * stays on its C x R tiles, each cell always on the same tile (SPEC 7).
 * A breadth-first search over every room state the start reaches. */
static void test_flat_room_stays(void **state)
{
    (void)state;
    for (int C = 3; C <= 5; C++)
        for (int R = 3; R <= 5; R++) {
            hol_room st[4 * 25 * 25];
            int n = 1, head = 0;
            assert_int_equal(hol_room_start_in(4, C, R, &st[0]), HOL_OK);
            hol_tile seen[25];
            int nseen = 1;
            seen[0] = st[0].tile;
            while (head < n) {
                for (int d = 0; d < 4; d++) {
                    hol_room r = st[head];
                    if (hol_room_step(&r, d))
                        continue;
                    int known = 0;
                    for (int i = 0; i < n && !known; i++)
                        known = room_same(&st[i], &r);
                    if (known)
                        continue;
                    assert_true(n < 4 * 25 * 25);
                    st[n++] = r;
                    /* the tile is the cell's: its offset from the start */
                    uint8_t walk[16];
                    int k = 0;
                    for (int c = C / 2; c < r.col; c++)
                        walk[k++] = HOL_DIR_E;
                    for (int c = C / 2; c > r.col; c--)
                        walk[k++] = HOL_DIR_W;
                    for (int w = R / 2; w < r.row; w++)
                        walk[k++] = HOL_DIR_S;
                    for (int w = R / 2; w > r.row; w--)
                        walk[k++] = HOL_DIR_N;
                    hol_tile want;
                    assert_int_equal(hol_tile_from_walk_q(4, walk, (size_t)k, &want, NULL), HOL_OK);
                    assert_true(hol_tile_eq(r.tile, want));
                    int fresh = 1;
                    for (int i = 0; i < nseen; i++)
                        fresh &= !hol_tile_eq(seen[i], r.tile);
                    if (fresh)
                        seen[nseen++] = r.tile;
                }
                head++;
            }
            assert_int_equal(nseen, C * R);
        }
}

static void test_option_text(void **state)
{
    (void)state;
    int q = 0, c = 0, r = 0;
    assert_int_equal(hol_room_parse_tiling("4,6", 3, &q), HOL_OK);
    assert_int_equal(q, 6);
    assert_int_equal(hol_room_parse_tiling("{4,8}", 5, &q), HOL_OK);
    assert_int_equal(q, 8);
    static const char *const bad_syntax[] = {"", "4", "4,", ",5", "4,5,", "4;5", "{4,5", "4,5}",
                                             " 4,5", "4,5 ", "4,0005", "4,x", "4,5\n"};
    for (size_t i = 0; i < sizeof bad_syntax / sizeof *bad_syntax; i++)
        assert_int_equal(hol_room_parse_tiling(bad_syntax[i], strlen(bad_syntax[i]), &q),
                         HOL_EPARSE);
    static const char *const bad_range[] = {"4,3", "4,9", "3,5", "5,4", "4,10", "4,0"};
    for (size_t i = 0; i < sizeof bad_range / sizeof *bad_range; i++)
        assert_int_equal(hol_room_parse_tiling(bad_range[i], strlen(bad_range[i]), &q), HOL_EARG);
    assert_int_equal(hol_room_parse_tiling("4,5\0", 4, &q), HOL_EPARSE);
    assert_int_equal(q, 8);
    assert_int_equal(hol_room_parse_size("4x5", 3, &c, &r), HOL_OK);
    assert_int_equal(c, 4);
    assert_int_equal(r, 5);
    assert_int_equal(hol_room_parse_size("3X3", 3, &c, &r), HOL_OK);
    assert_int_equal(hol_room_parse_size("2x2", 3, &c, &r), HOL_EARG);
    assert_int_equal(hol_room_parse_size("6x3", 3, &c, &r), HOL_EARG);
    assert_int_equal(hol_room_parse_size("3x", 2, &c, &r), HOL_EPARSE);
    assert_int_equal(hol_room_parse_size("3*3", 3, &c, &r), HOL_EPARSE);
    assert_int_equal(hol_room_parse_size("3x3x3", 5, &c, &r), HOL_EPARSE);
    assert_int_equal(c, 3);
}

/* Coordinates of every tiling against its model: frames, positions,
 * angles and distances (Euclidean in {4,4}). */
static void test_tilings_hyper(void **state)
{
    (void)state;
    for (int q = 4; q <= 8; q++) {
        model_use_tiling(q);
        assert_true(fabs(hol_hyper_edge_q(q) - model_edge()) < 1e-15);
        for (int iter = 0; iter < 500; iter++) {
            hol_tile a = random_tile_q(q, (int)(rng() % 6));
            hol_tile b = random_tile_q(q, (int)(rng() % 6));
            int north = (int)(rng() % 4);
            double m[9], p[3], ang, dist;
            assert_int_equal(hol_hyper_frame(a, north, b, m), HOL_OK);
            model_mat want = model_mul(model_inv(model_mul(tile_frame(a), model_rot(north))),
                                       tile_frame(b));
            for (int i = 0; i < 9; i++)
                assert_true(fabs(m[i] - want.m[i]) < 1e-9 * (1 + fabs(want.m[8])));
            assert_int_equal(hol_hyper_pos(a, north, b, p, &ang, &dist), HOL_OK);
            double x = want.m[2], y = want.m[5];
            if (q == 4)
                assert_true(fabs(dist - sqrt(x * x + y * y)) < 1e-9);
            else
                assert_true(fabs(cosh(dist) - want.m[8]) < 1e-9 * want.m[8]);
            if (dist > 1e-9)
                assert_true(fabs(remainder(ang - atan2(-x, y), 2 * acos(-1.0))) < 1e-9);
        }
    }
    model_use_tiling(5);
    assert_true(hol_hyper_edge_q(3) == 0.0);
    double m[9];
    assert_int_equal(hol_hyper_frame(hol_tile_origin_q(6), 0, hol_tile_origin(), m), HOL_EARG);
}

/* The tiling is part of the word: {4,5} words are as before, the others
 * carry Q, tiles of two tilings never meet, and the reach is 59. */
static void test_tilings_words(void **state)
{
    (void)state;
    hol_tile o5 = hol_tile_origin_q(5), t, u;
    assert_true(hol_tile_eq(o5, hol_tile_origin()));
    assert_int_equal(o5.bits[0] | o5.bits[1], 0);
    assert_int_equal(hol_tile_q(o5), 5);
    assert_int_equal(hol_tile_reach(5), HOL_TILE_MAX_DIST);
    for (int q = 4; q <= 8; q++) {
        hol_tile o = hol_tile_origin_q(q);
        assert_int_equal(hol_tile_q(o), q);
        assert_int_equal(hol_tile_dist0(o), 0);
        assert_int_equal(hol_tile_reach(q), q == 5 ? 60 : 59);
        assert_int_equal(hol_tile_parse_q(q, "Nf", -1, &t), HOL_OK);
        assert_int_equal(hol_tile_q(t), q);
        char buf[HOL_TILE_ADDR_MAX];
        hol_tile_print(t, buf);
        assert_string_equal(buf, "Nf");
        assert_int_equal(hol_tile_count_at(q, 1), 4);
        assert_int_equal(hol_tile_count_at(q, 2), q == 4 ? 8 : 12);
        if (q == 5)
            continue;
        assert_false(hol_tile_eq(o, o5));
        assert_int_equal(hol_tile_dist(o, o5), -1);
        assert_int_equal(hol_tile_relative(o, 0, o5, &u, NULL), HOL_EARG);
        /* the longest address, and one letter more */
        char s[64];
        s[0] = 'N';
        memset(s + 1, 'f', 58);
        s[59] = '\0';
        assert_int_equal(hol_tile_parse_q(q, s, -1, &t), HOL_OK);
        assert_int_equal(hol_tile_q(t), q);
        assert_int_equal(hol_tile_dist0(t), 59);
        assert_int_equal(hol_tile_step(t, HOL_TURN_F, &u, NULL), HOL_ERANGE);
        assert_int_equal(hol_tile_step(t, HOL_TURN_B, &u, NULL), HOL_OK);
        assert_int_equal(hol_tile_dist0(u), 58);
        assert_int_equal(hol_tile_q(u), q);
        s[59] = 'f';
        s[60] = '\0';
        assert_int_equal(hol_tile_parse_q(q, s, -1, &t), HOL_ERANGE);
    }
    assert_int_equal(hol_tile_parse_q(3, "O", -1, &t), HOL_EARG);
    assert_int_equal(hol_tile_parse_q(9, "O", -1, &t), HOL_EARG);
    hol_tile bad = hol_tile_origin_q(9);
    assert_int_equal(hol_tile_q(bad), 0);
    assert_int_equal(hol_tile_step(bad, 0, &t, NULL), HOL_EARG);
    /* an unknown tiling code is no tile */
    bad = hol_tile_origin();
    bad.bits[1] |= UINT64_C(5) << 54; /* Q = 5 written as a code */
    assert_int_equal(hol_tile_q(bad), 0);
    assert_int_equal(hol_tile_step(bad, 0, &t, NULL), HOL_EARG);
    /* walks: NESW closes in the flat grid, not in {4,6} */
    uint8_t nesw[4] = {HOL_DIR_N, HOL_DIR_E, HOL_DIR_S, HOL_DIR_W};
    int orient;
    assert_int_equal(hol_tile_from_walk_q(4, nesw, 4, &t, &orient), HOL_OK);
    assert_true(hol_tile_eq(t, hol_tile_origin_q(4)));
    assert_int_equal(hol_tile_from_walk_q(6, nesw, 4, &t, &orient), HOL_OK);
    assert_int_equal(hol_tile_dist0(t), 2); /* 4 of the 6 tiles round a vertex */
    /* and the flat grid's ties between branches go to the left one */
    assert_int_equal(hol_tile_resolve_q(4, "Nl", -1, &t), HOL_OK);
    assert_int_equal(hol_tile_parse_q(4, "Wr", -1, &u), HOL_OK);
    assert_true(hol_tile_eq(t, u));
    assert_int_equal(hol_tile_parse_q(4, "Nl", -1, &t), HOL_ENOTCANON);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_model_counts),
        cmocka_unit_test(test_addresses_one_per_tile_shortest),
        cmocka_unit_test(test_published_rules_are_rejected),
        cmocka_unit_test(test_automaton_api),
        cmocka_unit_test(test_neighbours_and_frames),
        cmocka_unit_test(test_relative_and_distance),
        cmocka_unit_test(test_room_walks_match_model),
        cmocka_unit_test(test_holonomy),
        cmocka_unit_test(test_walk_parse),
        cmocka_unit_test(test_parse_print),
        cmocka_unit_test(test_reach),
        cmocka_unit_test(test_far_consistency),
        cmocka_unit_test(test_hyperboloid),
        cmocka_unit_test(test_tilings_words),
        cmocka_unit_test(test_tilings_addresses),
        cmocka_unit_test(test_tilings_neighbours),
        cmocka_unit_test(test_tilings_relative),
        cmocka_unit_test(test_tilings_far),
        cmocka_unit_test(test_tilings_hyper),
        cmocka_unit_test(test_rooms_sizes),
        cmocka_unit_test(test_flat_room_stays),
        cmocka_unit_test(test_option_text),
    };
    return cmocka_run_group_tests_name("tile", tests, setup, teardown);
}
