/* hol_tile.c - canonical addresses and exact neighbours in {4,5}.
 *
 * Why the canonical words are what they are
 * -----------------------------------------
 * Walk on the tiles with a heading. Around every vertex five tiles meet, so
 * with F = step forward (heading carried across the edge) and L = turn left
 * a quarter, the flag (tile, heading) obeys L^4 = 1 and (F L)^5 = 1: five
 * times "step, turn left" goes round a vertex and returns the same flag.
 * Consequences for a shortest walk, written as letters f/l/r (turn, step):
 *   - "ll" never appears: three tiles of a vertex's five, the other two are
 *     shorter. "rr" likewise.
 *   - ties exist: "a lfl b" and "a' rfr b'" can reach the same tile (two
 *     mirror walks about a diagonal through a vertex).
 * The canonical address is the unique shortest walk that avoids "lfl". It is
 * the leftmost of the shortest walks, and it agrees with the rules published
 * with the original system wherever those give a shortest walk. The set of
 * canonical suffixes (after the branch letter) is accepted by this automaton:
 *
 *   state  f  l  r     state 0 = straight (start after the branch)
 *     0    0  2  1           1 = after r        2 = after l
 *     1    3  2  -           3 = after "rf"     4 = after "lf"
 *     2    4  -  1           5 = after "rfr"
 *     3    0  2  5
 *     4    0  -  1
 *     5    1  2  -
 *
 * The tests check this language against an independent hyperboloid model:
 * each tile to distance 12 has exactly one accepted word, and it is shortest.
 *
 * Neighbours
 * ----------
 * Stepping from tile w in direction t: back is the parent; a direction whose
 * letter the automaton accepts gives the child w+letter. Otherwise the
 * neighbour is reached the other way round the vertex between w, its parent
 * and that neighbour: from (F L)^5 = 1 follows
 *     L F = L L F R F R F R F L     and     R F = R R F L F L F L F R,
 * that is: go back to the parent, then three steps round the vertex. The
 * three steps recurse on tiles no farther than w from O (at most one step
 * farther for the last one), and the recursion ends: the worst case is about
 * 2n calls for a word of length n, the mean under two.
 */
#include "hol_tile.h"

#include "hol_hash.h"

#include <string.h>

#define HOL__CAP 127 /* letters a working word can hold */
#define HOL__SINK 6

/* hol__dfa[state][letter code]; code 2 (back) is never a letter. */
static const uint8_t hol__dfa[7][4] = {
    {0, 2, HOL__SINK, 1},
    {3, 2, HOL__SINK, HOL__SINK},
    {4, HOL__SINK, HOL__SINK, 1},
    {0, 2, HOL__SINK, 5},
    {0, HOL__SINK, HOL__SINK, 1},
    {1, 2, HOL__SINK, HOL__SINK},
    {HOL__SINK, HOL__SINK, HOL__SINK, HOL__SINK},
};

/* Working word: like hol_tile but twice as long, so relative addresses
 * between any two tiles in reach (up to 2 * HOL_TILE_MAX_DIST) fit. */
typedef struct hol__word {
    uint64_t b[4];
    int len;
} hol__word;

/* Letter i of a bit array (a hol__word's b or a hol_tile's bits: letters
 * of a valid tile never reach the length field). */
static int hol__at(const uint64_t *b, int i)
{
    return (int)((b[i >> 5] >> (2 * (i & 31))) & 3u);
}

static int hol__get(const hol__word *w, int i) { return hol__at(w->b, i); }

static void hol__push(hol__word *w, int c)
{
    w->b[w->len >> 5] |= (uint64_t)c << (2 * (w->len & 31));
    w->len++;
}

static void hol__pop(hol__word *w)
{
    if (w->len == 0)
        return;
    w->len--;
    w->b[w->len >> 5] &= ~(UINT64_C(3) << (2 * (w->len & 31)));
}

/* Automaton state after the whole word (length >= 1). The automaton
 * synchronises: after an "l" it is always in state 2 and after "fff" always
 * in state 0, so only the letters after the last such mark are run. */
static int hol__state_of(const uint64_t *b, int len)
{
    int i = len - 1, run = 0, s = 0;
    for (; i >= 1; i--) {
        int c = hol__at(b, i);
        if (c == HOL_TURN_L) {
            s = 2;
            break;
        }
        run = c == HOL_TURN_F ? run + 1 : 0;
        if (run == 3) {
            s = 0;
            i += 2;
            break;
        }
    }
    if (i < 1)
        i = 0;
    for (i++; i < len; i++)
        s = hol__dfa[s][hol__at(b, i)];
    return s;
}

static int hol__state(const hol__word *w) { return hol__state_of(w->b, w->len); }

static hol__word hol__widen(hol_tile t)
{
    hol__word w;
    w.b[0] = t.bits[0];
    w.b[1] = t.bits[1] & ~(UINT64_C(63) << 58);
    w.b[2] = w.b[3] = 0;
    w.len = (int)(t.bits[1] >> 58);
    return w;
}

/* Caller ensures w.len <= HOL_TILE_MAX_DIST. */
static hol_tile hol__narrow(const hol__word *w)
{
    hol_tile t;
    t.bits[0] = w->b[0];
    t.bits[1] = w->b[1] | ((uint64_t)w->len << 58);
    return t;
}

static int hol__len(hol_tile t) { return (int)(t.bits[1] >> 58); }

hol_tile hol_tile_origin(void)
{
    hol_tile t;
    t.bits[0] = t.bits[1] = 0;
    return t;
}

int hol_tile_dist0(hol_tile t) { return hol__len(t); }

int hol_tile_eq(hol_tile a, hol_tile b)
{
    return a.bits[0] == b.bits[0] && a.bits[1] == b.bits[1];
}

uint64_t hol_tile_hash(hol_tile t)
{
    return hol_mix64(t.bits[0] ^ (t.bits[1] * UINT64_C(0x9E3779B97F4A7C15)));
}

int hol_tile_letter(hol_tile t, int i)
{
    if (i < 0 || i >= hol__len(t))
        return -1;
    return hol__at(t.bits, i);
}

int hol_tile_automaton(int state, int letter)
{
    if (state < 0 || state >= HOL_TILE_STATES || letter < 0 || letter > 3)
        return -1;
    int next = hol__dfa[state][letter];
    return next == HOL__SINK ? -1 : next;
}

int hol_tile_state(hol_tile t)
{
    int n = hol__len(t);
    if (n == 0 || n > HOL_TILE_MAX_DIST)
        return -1;
    return hol__state_of(t.bits, n);
}

static const char hol__branch_ch[4] = {'N', 'W', 'S', 'E'};
static const char hol__turn_ch[4] = {'f', 'l', '?', 'r'};

/* Letter code + 1 of each character after the branch (0: not a letter). */
static const uint8_t hol__turn_code[256] = {
    ['f'] = HOL_TURN_F + 1, ['l'] = HOL_TURN_L + 1, ['r'] = HOL_TURN_R + 1};

/* Letter code of character c at position i, or -1. */
static int hol__code(char c, ptrdiff_t i)
{
    if (i == 0) {
        switch (c) {
        case 'N': return 0;
        case 'W': return 1;
        case 'S': return 2;
        case 'E': return 3;
        default: return -1;
        }
    }
    return hol__turn_code[(unsigned char)c] - 1;
}

hol_err hol_tile_parse(const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    if (len < 0)
        len = (ptrdiff_t)strlen(s);
    if (len == 0)
        return HOL_EPARSE;
    if (len == 1 && s[0] == 'O') {
        *out_tile = hol_tile_origin();
        return HOL_OK;
    }
    hol__word w = {{0, 0, 0, 0}, 0};
    int state = 0;
    hol_err err = HOL_OK;
    for (ptrdiff_t i = 0; i < len; i++) {
        int c = hol__code(s[i], i);
        if (c < 0)
            return HOL_EPARSE;
        if (i > 0) {
            state = hol__dfa[state][c];
            if (state == HOL__SINK && !err)
                err = HOL_ENOTCANON; /* keep scanning for syntax errors */
        }
        if (i >= HOL_TILE_MAX_DIST) {
            if (!err)
                err = HOL_ERANGE;
        } else {
            hol__push(&w, c);
        }
    }
    if (err)
        return err;
    *out_tile = hol__narrow(&w);
    return HOL_OK;
}

int hol_tile_print(hol_tile t, char *buf)
{
    hol__word w = hol__widen(t);
    if (w.len == 0) {
        buf[0] = 'O';
        buf[1] = '\0';
        return 1;
    }
    buf[0] = hol__branch_ch[hol__get(&w, 0)];
    for (int i = 1; i < w.len; i++)
        buf[i] = hol__turn_ch[hol__get(&w, i)];
    buf[w.len] = '\0';
    return w.len;
}

hol_tile hol_tile_parent(hol_tile t)
{
    hol__word w = hol__widen(t);
    hol__pop(&w);
    return hol__narrow(&w);
}

/* Append letter code c to a tile short of the reach. */
static hol_tile hol__tile_push(hol_tile t, int n, int c)
{
    t.bits[n >> 5] |= (uint64_t)c << (2 * (n & 31));
    t.bits[1] += UINT64_C(1) << 58;
    return t;
}

hol_err hol_tile_child(hol_tile t, int letter, hol_tile *out_tile)
{
    int n = hol__len(t);
    if (letter < 0 || letter > 3 || n > HOL_TILE_MAX_DIST)
        return HOL_EARG;
    if (n > 0 && hol__dfa[hol__state_of(t.bits, n)][letter] == HOL__SINK)
        return HOL_ENOTCANON;
    if (n == HOL_TILE_MAX_DIST)
        return HOL_ERANGE;
    *out_tile = hol__tile_push(t, n, letter);
    return HOL_OK;
}

/* The recursion described at the top, on working words. */
static hol_err hol__step(hol__word *w, int t, int *arr)
{
    t &= 3;
    if (w->len == 0) {
        hol__push(w, t);
        *arr = 0;
        return HOL_OK;
    }
    if (t == HOL_TURN_B) {
        *arr = (hol__get(w, w->len - 1) + 2) & 3;
        hol__pop(w);
        return HOL_OK;
    }
    if (hol__dfa[hol__state(w)][t] != HOL__SINK) {
        if (w->len >= HOL__CAP)
            return HOL_ERANGE;
        hol__push(w, t);
        *arr = 0;
        return HOL_OK;
    }
    /* Not a child: back to the parent, then three steps round the vertex,
     * turning right each time for a left neighbour and left for a right. */
    int s = t == HOL_TURN_L ? -1 : 1;
    int th = (hol__get(w, w->len - 1) + 2) & 3;
    hol__word q = *w;
    hol__pop(&q);
    for (int i = 0; i < 3; i++) {
        hol_err err = hol__step(&q, th + s, &th);
        if (err)
            return err;
    }
    *w = q;
    *arr = (th - s) & 3;
    return HOL_OK;
}

static int hol__valid(hol_tile t)
{
    return hol__len(t) <= HOL_TILE_MAX_DIST;
}

hol_err hol_tile_step(hol_tile t, int turn, hol_tile *out_tile, int *out_arrive)
{
    int arr, n = hol__len(t);
    turn &= 3;
    if (n > HOL_TILE_MAX_DIST)
        return HOL_EARG;
    /* fast path: the parent */
    if (n > 0 && turn == HOL_TURN_B) {
        int last = hol__at(t.bits, n - 1);
        t.bits[(n - 1) >> 5] &= ~(UINT64_C(3) << (2 * ((n - 1) & 31)));
        t.bits[1] -= UINT64_C(1) << 58;
        *out_tile = t;
        if (out_arrive)
            *out_arrive = (last + 2) & 3;
        return HOL_OK;
    }
    /* a child of a tile short of the reach */
    if (n > 0 && n < HOL_TILE_MAX_DIST &&
        hol__dfa[hol__state_of(t.bits, n)][turn] != HOL__SINK) {
        *out_tile = hol__tile_push(t, n, turn);
        if (out_arrive)
            *out_arrive = 0;
        return HOL_OK;
    }
    hol__word w = hol__widen(t);
    hol_err err = hol__step(&w, turn, &arr);
    if (!err && w.len > HOL_TILE_MAX_DIST)
        err = HOL_ERANGE;
    if (err)
        return err;
    *out_tile = hol__narrow(&w);
    if (out_arrive)
        *out_arrive = arr;
    return HOL_OK;
}

hol_err hol_heading_tile_step(hol_heading_tile f, int turn, hol_heading_tile *out_ht)
{
    hol_heading_tile r;
    hol_err err = hol_tile_step(f.tile, f.facing + turn, &r.tile, &r.facing);
    if (err)
        return err;
    *out_ht = r;
    return HOL_OK;
}

hol_err hol_tile_from_walk(const uint8_t *dirs, size_t n, hol_tile *out_tile,
                           int *out_orient)
{
    hol_tile t = hol_tile_origin();
    int orient = 0; /* room N relative to the tile's canonical heading */
    for (size_t i = 0; i < n; i++) {
        int arr;
        if (dirs[i] > 3)
            return HOL_EARG;
        hol_err err = hol_tile_step(t, orient + dirs[i], &t, &arr);
        if (err)
            return err;
        orient = (arr - dirs[i]) & 3;
    }
    *out_tile = t;
    if (out_orient)
        *out_orient = orient;
    return HOL_OK;
}

hol_err hol_tile_resolve(const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    /* parse checks the whole syntax before it reports a non-canonical or
     * too long word; only those are walked */
    hol_err err = hol_tile_parse(s, len, out_tile);
    if (err != HOL_ENOTCANON && err != HOL_ERANGE)
        return err;
    if (len < 0)
        len = (ptrdiff_t)strlen(s);
    hol_heading_tile f = {hol_tile_origin(), 0};
    for (ptrdiff_t i = 0; i < len; i++) {
        err = hol_heading_tile_step(f, hol__code(s[i], i), &f);
        if (err)
            return err;
    }
    *out_tile = f.tile;
    return HOL_OK;
}

/* The walk a -> longest common prefix -> b, replayed from a's point of view
 * on a working word. theta: the walker's facing relative to the real tile's
 * heading; v, phi: the same walk seen from a. */
static hol_err hol__relative(hol_tile a, int a_north, hol_tile b, hol__word *v,
                             int *out_facing)
{
    if (!hol__valid(a) || !hol__valid(b))
        return HOL_EARG;
    hol__word wa = hol__widen(a), wb = hol__widen(b);
    int k = 0;
    while (k < wa.len && k < wb.len && hol__get(&wa, k) == hol__get(&wb, k))
        k++;
    int theta = a_north & 3, phi = 0;
    *v = (hol__word){{0, 0, 0, 0}, 0};
    for (int i = wa.len - 1; i >= k; i--) {
        hol_err err = hol__step(v, phi + HOL_TURN_B - theta, &phi);
        if (err)
            return err;
        theta = (hol__get(&wa, i) + 2) & 3;
    }
    for (int i = k; i < wb.len; i++) {
        hol_err err = hol__step(v, phi + hol__get(&wb, i) - theta, &phi);
        if (err)
            return err;
        theta = 0;
    }
    *out_facing = (phi - theta) & 3;
    return HOL_OK;
}

hol_err hol_tile_relative(hol_tile a, int a_north, hol_tile b, hol_tile *out_rel,
                          int *out_facing)
{
    hol__word v;
    int facing;
    hol_err err = hol__relative(a, a_north, b, &v, &facing);
    if (!err && v.len > HOL_TILE_MAX_DIST)
        err = HOL_ERANGE;
    if (err)
        return err;
    *out_rel = hol__narrow(&v);
    if (out_facing)
        *out_facing = facing;
    return HOL_OK;
}

int hol_tile_relative_letters(hol_tile a, int a_north, hol_tile b,
                              uint8_t out_letters[HOL_TILE_REL_MAX],
                              int *out_facing)
{
    hol__word v;
    int facing;
    if (hol__relative(a, a_north, b, &v, &facing))
        return -1;
    for (int i = 0; i < v.len; i++)
        out_letters[i] = (uint8_t)hol__get(&v, i);
    if (out_facing)
        *out_facing = facing;
    return v.len;
}

int hol_tile_dist(hol_tile a, hol_tile b)
{
    hol__word v;
    int facing;
    if (hol__relative(a, 0, b, &v, &facing))
        return -1;
    return v.len;
}
