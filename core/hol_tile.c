/* hol_tile.c - canonical addresses and exact neighbours in {4,Q}.
 *
 * Why the canonical words are what they are
 * -----------------------------------------
 * Walk on the tiles with a heading. Around every vertex Q tiles meet, so
 * with F = step forward (heading carried across the edge) and L = turn left
 * a quarter, the flag (tile, heading) obeys L^4 = 1 and (F L)^Q = 1: Q
 * times "step, turn left" goes round a vertex and returns the same flag.
 * In {4,5}, consequences for a shortest walk, written as letters f/l/r
 * (turn, step):
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
 * Every tiling {4,Q} has such an automaton of leftmost shortest words
 * (hol_tile_dfa.h: 2 states in the flat {4,4}, where words are a straight
 * run, one right turn, a straight run; 4 in {4,6}, 10 in {4,7}, 6 in
 * {4,8}), derived from the geometry by tests/gen_tiling.c. The tests check
 * each against an independent model (a hyperboloid model for Q >= 5,
 * integer coordinates for Q = 4): each tile to some distance has exactly
 * one accepted word, and it is shortest.
 *
 * Neighbours
 * ----------
 * Stepping from tile w in direction t: back is the parent; a direction whose
 * letter the automaton accepts gives the child w+letter (straight on is
 * always accepted, in every tiling). Otherwise the neighbour is reached the
 * other way round the vertex between w, its parent and that neighbour: from
 * (F L)^Q = 1 follows, for Q = 5,
 *     L F = L L F R F R F R F L     and     R F = R R F L F L F L F R,
 * that is: go back to the parent, then Q - 2 steps round the vertex. The
 * steps recurse on tiles no farther than w from O (at most one step
 * farther for the last one), and the recursion ends: the worst case is
 * about 2n calls for a word of length n in {4,5}, the mean under two (the
 * tests walk every neighbour of every tile to some distance in each tiling,
 * and random words to the reach).
 */
#include "hol_tile.h"

#include "hol_hash.h"
#include "hol_tile_dfa.h"

#include <string.h>

#define HOL__CAP 127 /* letters a working word can hold */

/* Inlined into each caller, so that a {4,5} caller's copy knows its
 * automaton at compile time (the core's hottest paths). */
#if defined(__GNUC__)
#define HOL__HOT static inline __attribute__((always_inline))
#define HOL__COLD static __attribute__((noinline))
#else
#define HOL__HOT static inline
#define HOL__COLD static
#endif

/* A tiling: its automaton (dfa[state][letter code], code 2 (back) is never
 * a letter; `sink` is the state of no address), the synchronising runs
 * (hol__state_of), the reach and the tiling bits of its words. */
typedef struct hol__tiling {
    int q, reach, nstates, sink;
    const uint8_t (*dfa)[4];
    const uint8_t *sync_run, *sync_state;
    uint64_t qbits; /* or-ed into bits[1] */
} hol__tiling;

#define HOL__N(Q) ((int)(sizeof hol__dfa##Q / sizeof hol__dfa##Q[0]) - 1)
#define HOL__T(Q, REACH, QB)                                                           \
    {Q, REACH, HOL__N(Q), HOL__N(Q), hol__dfa##Q, hol__sync_run##Q, hol__sync_state##Q, QB}
static const hol__tiling hol__tilings[5] = {
    HOL__T(4, 59, UINT64_C(4) << 54),
    HOL__T(5, 60, 0),
    HOL__T(6, 59, UINT64_C(6) << 54),
    HOL__T(7, 59, UINT64_C(7) << 54),
    HOL__T(8, 59, UINT64_C(8) << 54),
};
_Static_assert(HOL__N(4) <= HOL_TILE_MAX_STATES && HOL__N(5) == HOL_TILE_STATES &&
                   HOL__N(6) <= HOL_TILE_MAX_STATES && HOL__N(7) <= HOL_TILE_MAX_STATES &&
                   HOL__N(8) <= HOL_TILE_MAX_STATES,
               "an automaton larger than HOL_TILE_MAX_STATES");
#define HOL__T45 (&hol__tilings[1])

/* The tiling of a word (NULL: an unknown tiling code). */
static inline const hol__tiling *hol__tiling_of(hol_tile t)
{
    if (!((t.bits[1] >> 56) & 3u))
        return HOL__T45;
    unsigned q = (unsigned)(t.bits[1] >> 54) & 15u;
    return q == 4 || (q >= 6 && q <= 8) ? &hol__tilings[q - 4] : NULL;
}

static const hol__tiling *hol__tiling_q(int q)
{
    return q >= HOL_TILING_MIN_Q && q <= HOL_TILING_MAX_Q ? &hol__tilings[q - 4] : NULL;
}

/* Working word: like hol_tile but twice as long, so relative addresses
 * between any two tiles in reach (up to 2 * HOL_TILE_MAX_DIST) fit. It holds
 * letters only; its tiling travels beside it. */
typedef struct hol__word {
    uint64_t b[4];
    int len;
} hol__word;

/* Letter i of a bit array (a hol__word's b or a hol_tile's bits: letters
 * of a valid tile never reach the tiling or length fields). */
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

/* Automaton state after the whole word (length >= 1). The automata
 * synchronise: a run of sync_run[c] letters c leads every state to
 * sync_state[c], so only the letters after the last such run are run. */
static int hol__state_gen(const hol__tiling *T, const uint64_t *b, int len)
{
    int i = len - 1, run = 0, prev = -1, s = 0;
    for (; i >= 1; i--) {
        int c = hol__at(b, i);
        run = c == prev ? run + 1 : 1;
        prev = c;
        if (T->sync_run[c] && run == T->sync_run[c]) {
            s = T->sync_state[c];
            i += run - 1;
            break;
        }
    }
    if (i < 1)
        i = 0;
    for (i++; i < len; i++)
        s = T->dfa[s][hol__at(b, i)];
    return s;
}

/* The same for {4,5}, written out (the core's hottest path): after an "l"
 * always state 2, after "fff" always state 0 (hol__sync_run5). A bit-mask
 * search for the last such run cost more than this scan, which mostly
 * stops within a few letters. */
static int hol__state45(const uint64_t *b, int len)
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
        s = hol__dfa5[s][hol__at(b, i)];
    return s;
}

HOL__HOT int hol__state_of(const hol__tiling *T, const uint64_t *b, int len)
{
    return T == HOL__T45 ? hol__state45(b, len) : hol__state_gen(T, b, len);
}

static int hol__state(const hol__tiling *T, const hol__word *w)
{
    return hol__state_of(T, w->b, w->len);
}

#define HOL__LEN_SHIFT 58
#define HOL__HIGH_MASK (~(UINT64_C(0) ) << 54) /* tiling and length fields */

/* The letters of a tile word of tiling T (its tiling and length fields
 * cleared: {4,5} has no tiling field, so its 60th letter may fill bits
 * 118..119). */
HOL__HOT hol__word hol__widen_in(const hol__tiling *T, hol_tile t)
{
    hol__word w;
    w.b[0] = t.bits[0];
    w.b[1] = t.bits[1] & ~(T == HOL__T45 ? UINT64_C(63) << HOL__LEN_SHIFT : HOL__HIGH_MASK);
    w.b[2] = w.b[3] = 0;
    w.len = (int)(t.bits[1] >> HOL__LEN_SHIFT);
    return w;
}

/* Any word, its tiling unknown (printing). */
static hol__word hol__widen(hol_tile t)
{
    const hol__tiling *T = hol__tiling_of(t);
    return hol__widen_in(T ? T : HOL__T45, t);
}

/* Caller ensures w.len <= T->reach. */
static hol_tile hol__narrow(const hol__tiling *T, const hol__word *w)
{
    hol_tile t;
    t.bits[0] = w->b[0];
    t.bits[1] = w->b[1] | T->qbits | ((uint64_t)w->len << HOL__LEN_SHIFT);
    return t;
}

static int hol__len(hol_tile t) { return (int)(t.bits[1] >> HOL__LEN_SHIFT); }

/* The tiling of a valid tile word (length within its reach), else NULL. */
static inline const hol__tiling *hol__valid_of(hol_tile t)
{
    const hol__tiling *T = hol__tiling_of(t);
    return T && hol__len(t) <= T->reach ? T : NULL;
}

hol_tile hol_tile_origin(void)
{
    hol_tile t;
    t.bits[0] = t.bits[1] = 0;
    return t;
}

hol_tile hol_tile_origin_q(int q)
{
    const hol__tiling *T = hol__tiling_q(q);
    hol_tile t;
    t.bits[0] = 0;
    /* a bad q: a length no tiling reaches */
    t.bits[1] = T ? T->qbits : UINT64_C(63) << HOL__LEN_SHIFT;
    return t;
}

int hol_tile_q(hol_tile t)
{
    const hol__tiling *T = hol__valid_of(t);
    return T ? T->q : 0;
}

int hol_tile_reach(int q)
{
    const hol__tiling *T = hol__tiling_q(q);
    return T ? T->reach : 0;
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

int hol_tile_states(int q)
{
    const hol__tiling *T = hol__tiling_q(q);
    return T ? T->nstates : 0;
}

int hol_tile_automaton_q(int q, int state, int letter)
{
    const hol__tiling *T = hol__tiling_q(q);
    if (!T || state < 0 || state >= T->nstates || letter < 0 || letter > 3)
        return -1;
    int next = T->dfa[state][letter];
    return next == T->sink ? -1 : next;
}

int hol_tile_automaton(int state, int letter)
{
    return hol_tile_automaton_q(5, state, letter);
}

int hol_tile_state(hol_tile t)
{
    const hol__tiling *T = hol__valid_of(t);
    int n = hol__len(t);
    if (!T || n == 0)
        return -1;
    return hol__state_of(T, t.bits, n);
}

uint64_t hol_tile_count_at(int q, int d)
{
    const hol__tiling *T = hol__tiling_q(q);
    if (!T || d < 0)
        return 0;
    if (d == 0)
        return 1;
    /* words of d - 1 letters after the branch, from state 0 */
    uint64_t cnt[HOL_TILE_MAX_STATES], nx[HOL_TILE_MAX_STATES];
    for (int s = 0; s < T->nstates; s++)
        cnt[s] = 1;
    for (int k = 1; k < d; k++) {
        for (int s = 0; s < T->nstates; s++) {
            uint64_t n = 0;
            for (int c = 0; c < 4; c++)
                if (T->dfa[s][c] != T->sink)
                    n += cnt[T->dfa[s][c]];
            nx[s] = n;
        }
        for (int s = 0; s < T->nstates; s++) {
            if (nx[s] > (UINT64_C(1) << 61))
                return 0;
            cnt[s] = nx[s];
        }
    }
    return 4 * cnt[0];
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

static hol_err hol__parse(const hol__tiling *T, const char *s, ptrdiff_t len,
                          hol_tile *out_tile)
{
    if (len < 0)
        len = (ptrdiff_t)strlen(s);
    if (len == 0)
        return HOL_EPARSE;
    if (len == 1 && s[0] == 'O') {
        hol__word o = {{0, 0, 0, 0}, 0};
        *out_tile = hol__narrow(T, &o);
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
            state = T->dfa[state][c];
            if (state == T->sink && !err)
                err = HOL_ENOTCANON; /* keep scanning for syntax errors */
        }
        if (i >= T->reach) {
            if (!err)
                err = HOL_ERANGE;
        } else {
            hol__push(&w, c);
        }
    }
    if (err)
        return err;
    *out_tile = hol__narrow(T, &w);
    return HOL_OK;
}

hol_err hol_tile_parse(const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    return hol__parse(HOL__T45, s, len, out_tile);
}

hol_err hol_tile_parse_q(int q, const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    const hol__tiling *T = hol__tiling_q(q);
    return T ? hol__parse(T, s, len, out_tile) : HOL_EARG;
}

int hol_tile_print(hol_tile t, char *buf)
{
    hol__word w = hol__widen(t);
    if (w.len > HOL_TILE_MAX_DIST)
        w.len = HOL_TILE_MAX_DIST; /* an invalid word: print what fits */
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
    int n = hol__len(t);
    if (n == 0 || n > HOL_TILE_MAX_DIST)
        return t;
    t.bits[(n - 1) >> 5] &= ~(UINT64_C(3) << (2 * ((n - 1) & 31)));
    t.bits[1] -= UINT64_C(1) << HOL__LEN_SHIFT;
    return t;
}

/* Append letter code c to a tile short of the reach. */
static hol_tile hol__tile_push(hol_tile t, int n, int c)
{
    t.bits[n >> 5] |= (uint64_t)c << (2 * (n & 31));
    t.bits[1] += UINT64_C(1) << HOL__LEN_SHIFT;
    return t;
}

HOL__HOT hol_err hol__child(const hol__tiling *T, hol_tile t, int letter, hol_tile *out_tile)
{
    int n = hol__len(t);
    if (letter < 0 || letter > 3)
        return HOL_EARG;
    if (n > 0 && T->dfa[hol__state_of(T, t.bits, n)][letter] == T->sink)
        return HOL_ENOTCANON;
    if (n == T->reach)
        return HOL_ERANGE;
    *out_tile = hol__tile_push(t, n, letter);
    return HOL_OK;
}

/* The tilings other than {4,5}, out of the {4,5} path's way. */
HOL__COLD hol_err hol__child_q(hol_tile t, int letter, hol_tile *out_tile)
{
    const hol__tiling *T = hol__valid_of(t);
    return T && T != HOL__T45 ? hol__child(T, t, letter, out_tile) : HOL_EARG;
}

hol_err hol_tile_child(hol_tile t, int letter, hol_tile *out_tile)
{
    if ((t.bits[1] >> 56) <= (HOL_TILE_MAX_DIST << 2) && !((t.bits[1] >> 56) & 3u))
        return hol__child(HOL__T45, t, letter, out_tile); /* {4,5} within its reach */
    return hol__child_q(t, letter, out_tile);
}

/* The recursion described at the top, on working words; `self` is the
 * function to recurse with (hol__step45 or hol__stepq: inlined into each,
 * so the {4,5} copy knows its automaton at compile time). */
typedef hol_err (*hol__step_fn)(const hol__tiling *T, hol__word *w, int t, int *arr);

static inline hol_err hol__step_in(const hol__tiling *T, hol__word *w, int t, int *arr,
                                   hol__step_fn self)
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
    if (T->dfa[hol__state(T, w)][t] != T->sink) {
        if (w->len >= HOL__CAP)
            return HOL_ERANGE;
        hol__push(w, t);
        *arr = 0;
        return HOL_OK;
    }
    /* Not a child: back to the parent, then Q - 2 steps round the vertex,
     * turning right each time for a left neighbour and left for a right. */
    int s = t == HOL_TURN_L ? -1 : 1;
    int th = (hol__get(w, w->len - 1) + 2) & 3;
    hol__word q = *w;
    hol__pop(&q);
    for (int i = 0; i < T->q - 2; i++) {
        hol_err err = self(T, &q, th + s, &th);
        if (err)
            return err;
    }
    *w = q;
    *arr = (th - s) & 3;
    return HOL_OK;
}

static hol_err hol__step45(const hol__tiling *T, hol__word *w, int t, int *arr)
{
    (void)T;
    return hol__step_in(HOL__T45, w, t, arr, hol__step45);
}

static hol_err hol__stepq(const hol__tiling *T, hol__word *w, int t, int *arr)
{
    return hol__step_in(T, w, t, arr, hol__stepq);
}

static hol__step_fn hol__stepper(const hol__tiling *T)
{
    return T == HOL__T45 ? hol__step45 : hol__stepq;
}

/* The neighbour that is neither the parent nor a child: the recursion on a
 * working word (out of the fast paths' way, so that they stay lean). */
HOL__COLD hol_err hol__tile_step_far(const hol__tiling *T, hol_tile t, int turn,
                                      hol_tile *out_tile, int *out_arrive)
{
    int arr;
    hol__word w = hol__widen_in(T, t);
    hol_err err = hol__stepper(T)(T, &w, turn, &arr);
    if (!err && w.len > T->reach)
        err = HOL_ERANGE;
    if (err)
        return err;
    *out_tile = hol__narrow(T, &w);
    if (out_arrive)
        *out_arrive = arr;
    return HOL_OK;
}

/* hol_tile_step for a valid tile of tiling T (inlined twice, so that the
 * {4,5} copy knows its automaton at compile time). */
HOL__HOT hol_err hol__tile_step(const hol__tiling *T, hol_tile t, int turn, hol_tile *out_tile,
                                int *out_arrive)
{
    int n = hol__len(t);
    /* fast path: the parent */
    if (n > 0 && turn == HOL_TURN_B) {
        int last = hol__at(t.bits, n - 1);
        t.bits[(n - 1) >> 5] &= ~(UINT64_C(3) << (2 * ((n - 1) & 31)));
        t.bits[1] -= UINT64_C(1) << HOL__LEN_SHIFT;
        *out_tile = t;
        if (out_arrive)
            *out_arrive = (last + 2) & 3;
        return HOL_OK;
    }
    /* a child of a tile short of the reach */
    if (n > 0 && n < T->reach && T->dfa[hol__state_of(T, t.bits, n)][turn] != T->sink) {
        *out_tile = hol__tile_push(t, n, turn);
        if (out_arrive)
            *out_arrive = 0;
        return HOL_OK;
    }
    return hol__tile_step_far(T, t, turn, out_tile, out_arrive);
}

/* The tilings other than {4,5}, out of the {4,5} path's way. */
HOL__COLD hol_err hol__tile_step_q(hol_tile t, int turn, hol_tile *out_tile, int *out_arrive)
{
    const hol__tiling *T = hol__valid_of(t);
    if (!T || T == HOL__T45)
        return HOL_EARG; /* an unknown tiling, or {4,5} beyond its reach */
    return hol__tile_step(T, t, turn, out_tile, out_arrive);
}

hol_err hol_tile_step(hol_tile t, int turn, hol_tile *out_tile, int *out_arrive)
{
    turn &= 3;
    /* {4,5} with a length within its reach: tiling bits 56..57 zero and the
     * top byte (length << 2) at most 60 << 2 */
    if ((t.bits[1] >> 56) <= (HOL_TILE_MAX_DIST << 2) && !((t.bits[1] >> 56) & 3u))
        return hol__tile_step(HOL__T45, t, turn, out_tile, out_arrive);
    return hol__tile_step_q(t, turn, out_tile, out_arrive);
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

hol_err hol_tile_from_walk_q(int q, const uint8_t *dirs, size_t n, hol_tile *out_tile,
                             int *out_orient)
{
    if (!hol__tiling_q(q))
        return HOL_EARG;
    hol_tile t = hol_tile_origin_q(q);
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

hol_err hol_tile_from_walk(const uint8_t *dirs, size_t n, hol_tile *out_tile,
                           int *out_orient)
{
    return hol_tile_from_walk_q(5, dirs, n, out_tile, out_orient);
}

hol_err hol_tile_resolve_q(int q, const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    /* parse checks the whole syntax before it reports a non-canonical or
     * too long word; only those are walked */
    hol_err err = hol_tile_parse_q(q, s, len, out_tile);
    if (err != HOL_ENOTCANON && err != HOL_ERANGE)
        return err;
    if (len < 0)
        len = (ptrdiff_t)strlen(s);
    hol_heading_tile f = {hol_tile_origin_q(q), 0};
    for (ptrdiff_t i = 0; i < len; i++) {
        err = hol_heading_tile_step(f, hol__code(s[i], i), &f);
        if (err)
            return err;
    }
    *out_tile = f.tile;
    return HOL_OK;
}

hol_err hol_tile_resolve(const char *s, ptrdiff_t len, hol_tile *out_tile)
{
    return hol_tile_resolve_q(5, s, len, out_tile);
}

/* The walk a -> longest common prefix -> b, replayed from a's point of view
 * on a working word. theta: the walker's facing relative to the real tile's
 * heading; v, phi: the same walk seen from a. *out_t: the tiling. */
static hol_err hol__relative(hol_tile a, int a_north, hol_tile b, hol__word *v,
                             int *out_facing, const hol__tiling **out_t)
{
    const hol__tiling *T = hol__valid_of(a);
    if (!T || hol__valid_of(b) != T)
        return HOL_EARG;
    hol__step_fn step = hol__stepper(T);
    hol__word wa = hol__widen_in(T, a), wb = hol__widen_in(T, b);
    int k = 0;
    while (k < wa.len && k < wb.len && hol__get(&wa, k) == hol__get(&wb, k))
        k++;
    int theta = a_north & 3, phi = 0;
    *v = (hol__word){{0, 0, 0, 0}, 0};
    for (int i = wa.len - 1; i >= k; i--) {
        hol_err err = step(T, v, phi + HOL_TURN_B - theta, &phi);
        if (err)
            return err;
        theta = (hol__get(&wa, i) + 2) & 3;
    }
    for (int i = k; i < wb.len; i++) {
        hol_err err = step(T, v, phi + hol__get(&wb, i) - theta, &phi);
        if (err)
            return err;
        theta = 0;
    }
    *out_facing = (phi - theta) & 3;
    *out_t = T;
    return HOL_OK;
}

hol_err hol_tile_relative(hol_tile a, int a_north, hol_tile b, hol_tile *out_rel,
                          int *out_facing)
{
    hol__word v;
    int facing;
    const hol__tiling *T;
    hol_err err = hol__relative(a, a_north, b, &v, &facing, &T);
    if (!err && v.len > T->reach)
        err = HOL_ERANGE;
    if (err)
        return err;
    *out_rel = hol__narrow(T, &v);
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
    const hol__tiling *T;
    if (hol__relative(a, a_north, b, &v, &facing, &T))
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
    const hol__tiling *T;
    if (hol__relative(a, 0, b, &v, &facing, &T))
        return -1;
    return v.len;
}
