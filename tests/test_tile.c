/* test_tile.c - the tiling core against an independent hyperboloid model.
 *
 * Every check compares core/ with tests/model.h, which shares no code with
 * it: addresses (one per tile, shortest, SPEC counts), neighbours and the
 * carried frame, relative addresses, distances between arbitrary pairs, the
 * room state, hyperboloid coordinates, parsing, printing and the reach.
 * The language check also runs against the rules published with the
 * original system and must reject them (SPEC section 3).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include <cmocka.h>

#include "../core/hol_hyper.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "model.h"

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

static int accept_core(const int *codes, int n)
{
    char s[64];
    hol_tile t;
    codes_to_text(codes, n, s);
    return hol_tile_parse(s, -1, &t) == HOL_OK;
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

typedef struct lang_check {
    acceptor_fn accepts;
    int *owner; /* per model tile: index of the word that addresses it */
    char (*words)[MAXLEN + 2];
    int nwords;
    int per_len[MAXLEN + 1];
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

static void lang_dfs(lang_check *c, int *codes, int n, model_mat m, int heading)
{
    if (c->accepts(codes, n)) {
        char s[MAXLEN + 2];
        codes_to_text(codes, n, s);
        int i = model_find(&bfs, m.m[2], m.m[5]);
        if (i < 0 || bfs.tiles[i].dist != n)
            lang_note(c, "accepts %s, which is not a shortest walk", s);
        else if (c->owner[i] >= 0)
            lang_note(c, "%s and %s address the same tile", c->words[c->owner[i]], s);
        else {
            c->owner[i] = c->nwords;
            strcpy(c->words[c->nwords++], s);
            c->per_len[n]++;
        }
    }
    if (n == MAXLEN)
        return;
    for (int k = 0; k < 4; k++) {
        if (n > 0 && k == 2)
            continue; /* no letter turns back */
        int h = n == 0 ? k : (heading + k) & 3;
        codes[n] = k;
        lang_dfs(c, codes, n + 1, model_step(m, h), h);
    }
}

/* 0 if `accepts` gives every tile to MAXLEN exactly one shortest address
 * and the SPEC counts; otherwise 1 and c->problem says why. */
static int lang_run(lang_check *c, acceptor_fn accepts)
{
    memset(c, 0, sizeof *c);
    c->accepts = accepts;
    c->owner = malloc(sizeof *c->owner * (size_t)bfs.count);
    c->words = malloc(sizeof *c->words * (size_t)bfs.count);
    assert_non_null(c->owner);
    assert_non_null(c->words);
    for (int i = 0; i < bfs.count; i++)
        c->owner[i] = -1;
    int codes[MAXLEN + 1];
    lang_dfs(c, codes, 0, model_identity(), 0);
    for (int i = 0; i < bfs.count && !c->problem[0]; i++)
        if (bfs.tiles[i].dist <= MAXLEN && c->owner[i] < 0)
            lang_note(c, "a tile at distance %d has no address", bfs.tiles[i].dist);
    for (int d = 0; d <= MAXLEN && !c->problem[0]; d++)
        if (c->per_len[d] != bfs.per_dist[d] ||
            (d <= SPEC_MAXLEN && bfs.per_dist[d] != spec_counts[d]))
            lang_note(c, "distance %d: %d addresses, %d tiles, SPEC says %d", d,
                      c->per_len[d], bfs.per_dist[d], spec_counts[d]);
    return c->problem[0] != 0;
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
    assert_true(st >= 0 && st < HOL_TILE_STATES);
    for (int c = 0; c < 4; c++) {
        hol_tile ch;
        int next = hol_tile_automaton(st, c);
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
    enum_words(hol_tile_origin(), MAXLEN - 1, check_step);
    print_message("neighbours of every tile to distance %d checked\n", MAXLEN - 1);
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
    int checked = 0;
    for (int iter = 0; iter < 40000; iter++) {
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
    assert_true(checked > 20000);
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
    hol_room room = {far, 0, 1, 1};
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
    };
    return cmocka_run_group_tests_name("tile", tests, setup, teardown);
}
