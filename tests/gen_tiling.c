/* gen_tiling.c - derives the automaton of canonical addresses of every
 * tiling {4,Q}, Q = 4..8, from the geometry, and prints core/hol_tile_dfa.h.
 *
 *   make gen-tiling            rewrite core/hol_tile_dfa.h
 *   build/tests/gen_tiling     print it (make test compares the two)
 *
 * Method
 * 1. The ball of radius D around the origin tile, breadth first, in a
 *    geometric model of its own (not tests/model.h, not core/): for Q >= 5
 *    3x3 Lorentz frames in double precision on the hyperboloid, a step in
 *    direction k being M R(k) T R(-k), T the translation by the
 *    centre-to-centre distance 2 acosh(cos(pi/Q) / sin(pi/4)); tiles are
 *    told apart by their centres. For Q = 4, exact integer positions.
 * 2. The canonical address of each tile: its leftmost shortest walk from O.
 *    A tile at distance n is entered from tiles at distance n - 1; a prefix
 *    of a leftmost shortest walk is the leftmost shortest walk of its tile,
 *    so the address is the least of (address of p) + (letter from p's
 *    heading) over those p, where "least" turns further left where two
 *    walks part: l before f before r, and of two neighbouring branches the
 *    one a quarter turn to the left (W before N, S before W, E before S, N
 *    before E; only the flat grid has such ties).
 * 3. The automaton (Myhill-Nerode): two addresses are in one state when the
 *    same suffixes of up to K letters extend both to addresses. K grows
 *    until the number of states stops growing and the transitions are
 *    deterministic on every address of the ball short enough to tell.
 * 4. Synchronising letters, for the core's fast state lookup: a letter
 *    that leads every state to one state, and letters whose runs of k lead
 *    every state to one state.
 * The ball is finite, so the automaton is a derivation, not a proof: the
 * proof is tests/test_tile.c, which checks the printed automata against an
 * independent model (every tile to some distance has exactly one accepted
 * word, a shortest walk; neighbours and frames; the SPEC counts).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAXST 32

typedef double real;

typedef struct tile {
    int32_t parent;
    uint8_t letter, dist;
    real x, y; /* centre (hyperboloid x, y; or integers for Q = 4) */
} tile;

typedef struct ball {
    int q, depth;
    tile *t;
    int n, cap;
    int32_t *slot;
    uint32_t nslot;
    real (*frame)[9]; /* frames of the last layer, by tile index - layer start */
} ball;

static real g_ch, g_sh;

static void mul(const real *a, const real *b, real *r)
{
    real t[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    memcpy(r, t, sizeof t);
}

static void rot(int k, real *r)
{
    static const int cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    int c = cs[k & 3][0], s = cs[k & 3][1];
    real m[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    memcpy(r, m, sizeof m);
}

/* frame m stepped in direction k (relative to its +y), turned to face it */
static void step(int q, const real *m, int k, real *out)
{
    real r[9], t[9];
    rot(k, r);
    mul(m, r, out);
    if (q == 4) {
        real tt[9] = {1, 0, 0, 0, 1, 1, 0, 0, 1};
        memcpy(t, tt, sizeof t);
    } else {
        real tt[9] = {1, 0, 0, 0, g_ch, g_sh, 0, g_sh, g_ch};
        memcpy(t, tt, sizeof t);
    }
    mul(out, t, out);
}

static uint32_t hash2(real x, real y)
{
    int64_t a = llround(x * 8), b = llround(y * 8);
    uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15u ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Fu;
    h ^= h >> 29;
    return (uint32_t)h;
}

static int find(const ball *b, real x, real y)
{
    real tol = 1e-9 * (1 + fabs(x) + fabs(y));
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++) {
            uint32_t h = hash2(x + dx * 0.0625, y + dy * 0.0625) & (b->nslot - 1);
            for (int i; (i = b->slot[h]) >= 0; h = (h + 1) & (b->nslot - 1))
                if (fabs(b->t[i].x - x) < tol && fabs(b->t[i].y - y) < tol)
                    return i;
        }
    return -1;
}

static int add(ball *b, real x, real y, int parent, int letter, int dist)
{
    if (b->n >= b->cap) {
        fprintf(stderr, "gen_tiling: ball too large\n");
        exit(1);
    }
    int i = b->n++;
    tile *t = &b->t[i];
    t->x = x;
    t->y = y;
    t->parent = parent;
    t->letter = (uint8_t)letter;
    t->dist = (uint8_t)dist;
    uint32_t h = hash2(x, y) & (b->nslot - 1);
    while (b->slot[h] >= 0)
        h = (h + 1) & (b->nslot - 1);
    b->slot[h] = i;
    return i;
}

/* Order of letters from the left: l, f, r (codes 1, 0, 3). */
static int rank_letter(int c) { return c == 1 ? 0 : c == 0 ? 1 : 2; }

/* 1 when the address of tile i + letter ci is left of tile j + letter cj
 * (both tiles at the same distance). */
static int lefter(const ball *b, int i, int ci, int j, int cj)
{
    int pi[64], pj[64], n = b->t[i].dist;
    for (int k = n, x = i; k >= 1; k--, x = b->t[x].parent)
        pi[k - 1] = b->t[x].letter;
    for (int k = n, x = j; k >= 1; k--, x = b->t[x].parent)
        pj[k - 1] = b->t[x].letter;
    pi[n] = ci;
    pj[n] = cj;
    if (pi[0] != pj[0]) {
        if (((pi[0] - pj[0]) & 3) == 1)
            return 1;
        if (((pj[0] - pi[0]) & 3) == 1)
            return 0;
        fprintf(stderr, "gen_tiling: a tie between opposite branches\n");
        exit(1);
    }
    for (int k = 1; k <= n; k++)
        if (pi[k] != pj[k])
            return rank_letter(pi[k]) < rank_letter(pj[k]);
    return 0;
}

typedef struct cand {
    int from, letter;
    real f[9];
} cand;

static void grow(ball *b)
{
    int q = b->q;
    b->cap = 4000000;
    b->t = malloc(sizeof *b->t * (size_t)b->cap);
    b->nslot = 1u << 23;
    b->slot = malloc(sizeof *b->slot * b->nslot);
    cand *c = malloc(sizeof *c * (size_t)b->cap);
    real(*layer)[9] = malloc(sizeof *layer * (size_t)b->cap);
    real(*next)[9] = malloc(sizeof *next * (size_t)b->cap);
    if (!b->t || !b->slot || !c || !layer || !next) {
        fprintf(stderr, "gen_tiling: out of memory\n");
        exit(1);
    }
    memset(b->slot, 0xff, sizeof *b->slot * b->nslot);
    real id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    memcpy(layer[0], id, sizeof id);
    add(b, 0, 0, -1, 0, 0);
    int lo = 0, hi = 1;
    for (int d = 1; d <= b->depth; d++) {
        /* candidates: every tile of the last layer, every letter */
        int nc = 0;
        for (int i = lo; i < hi; i++)
            for (int k = 0; k < 4; k++) {
                if (d > 1 && k == 2)
                    continue;
                cand *x = &c[nc];
                step(q, layer[i - lo], k, x->f);
                if (find(b, x->f[2], x->f[5]) >= 0)
                    continue; /* nearer: in the ball already */
                x->from = i;
                x->letter = k;
                nc++;
            }
        /* one tile per centre: the leftmost candidate */
        int start = b->n;
        for (int k = 0; k < nc; k++) {
            cand *x = &c[k];
            int j = find(b, x->f[2], x->f[5]);
            if (j < start) {
                j = add(b, x->f[2], x->f[5], x->from, x->letter, d);
                memcpy(next[j - start], x->f, sizeof x->f);
            } else if (lefter(b, x->from, x->letter, b->t[j].parent, b->t[j].letter)) {
                b->t[j].parent = x->from;
                b->t[j].letter = (uint8_t)x->letter;
                memcpy(next[j - start], x->f, sizeof x->f);
            }
        }
        lo = start;
        hi = b->n;
        real(*tmp)[9] = layer;
        layer = next;
        next = tmp;
    }
    free(c);
    free(layer);
    free(next);
}

/* ---- the automaton ---- */

typedef struct dfa {
    int n, k;
    int8_t next[MAXST][4]; /* -1: no such address */
} dfa;

/* child[4 * i + c]: the tile whose address is i's + letter c, or -1 */
static int32_t *children(const ball *b)
{
    int32_t *ch = malloc(sizeof *ch * 4 * (size_t)b->n);
    memset(ch, 0xff, sizeof *ch * 4 * (size_t)b->n);
    for (int i = 1; i < b->n; i++)
        ch[4 * b->t[i].parent + b->t[i].letter] = i;
    return ch;
}

/* Interned signatures: sig[i] at depth k = id of (sig of each child at
 * k - 1, or none). Tiles farther than depth - k get -1. */
typedef struct intern {
    int32_t (*key)[3];
    int n, cap;
} intern;

static int intern_id(intern *in, const int32_t key[3])
{
    for (int i = 0; i < in->n; i++) /* few distinct signatures */
        if (!memcmp(in->key[i], key, sizeof(int32_t) * 3))
            return i;
    if (in->n == in->cap) {
        in->cap = in->cap ? 2 * in->cap : 256;
        in->key = realloc(in->key, sizeof *in->key * (size_t)in->cap);
    }
    memcpy(in->key[in->n], key, sizeof(int32_t) * 3);
    return in->n++;
}

static const int letters[3] = {0, 3, 1}; /* f, r, l: the order states are numbered in */

/* States at suffix depth k; 0 if the classes are not yet a congruence. */
static int derive(const ball *b, const int32_t *ch, int k, dfa *out)
{
    int32_t *sig = malloc(sizeof *sig * (size_t)b->n), *prev = malloc(sizeof *prev * (size_t)b->n);
    int nclass = 1;
    for (int i = 0; i < b->n; i++)
        prev[i] = 0; /* depth 0: one class */
    for (int j = 1; j <= k; j++) {
        intern in = {0};
        for (int i = 0; i < b->n; i++) {
            sig[i] = -1;
            if (b->t[i].dist > b->depth - j)
                continue;
            int32_t key[3];
            for (int l = 0; l < 3; l++) {
                int c = ch[4 * i + letters[l]];
                key[l] = c < 0 ? -1 : prev[c];
            }
            sig[i] = intern_id(&in, key);
        }
        nclass = in.n;
        free(in.key);
        int32_t *t = prev;
        prev = sig;
        sig = t;
    }
    /* prev: classes at depth k. Transitions from the tiles at distance
     * 1..depth - k - 1 (whose children are classified too). */
    int32_t (*tr)[3] = malloc(sizeof *tr * (size_t)nclass);
    for (int c = 0; c < nclass; c++)
        tr[c][0] = tr[c][1] = tr[c][2] = -2;
    int ok = 1;
    for (int i = 1; i < b->n && ok; i++) {
        if (b->t[i].dist > b->depth - k - 1)
            continue;
        for (int l = 0; l < 3; l++) {
            int c = ch[4 * i + letters[l]], t = c < 0 ? -1 : prev[c];
            if (tr[prev[i]][l] == -2)
                tr[prev[i]][l] = t;
            else if (tr[prev[i]][l] != t)
                ok = 0; /* not a congruence yet */
        }
    }
    int first = prev[1];
    for (int i = 1; i <= 4; i++)
        if (prev[i] != first)
            ok = 0; /* the branches differ */
    /* number the classes reachable from the branches' class */
    int *map = malloc(sizeof *map * (size_t)nclass), queue[MAXST], head = 0;
    for (int c = 0; c < nclass; c++)
        map[c] = -1;
    memset(out, 0, sizeof *out);
    memset(out->next, 0xff, sizeof out->next);
    out->k = k;
    map[first] = out->n++;
    queue[0] = first;
    while (ok && head < out->n) {
        int cls = queue[head++], s = map[cls];
        for (int l = 0; l < 3 && ok; l++) {
            int t = tr[cls][l];
            if (t == -2) {
                ok = 0; /* a class seen only too far out */
                if (getenv("GEN_DEBUG"))
                    fprintf(stderr, "  k %d: state %d letter %d unseen\n", k, s, letters[l]);
            } else if (t >= 0) {
                if (map[t] < 0) {
                    if (out->n == MAXST) {
                        ok = 0;
                        break;
                    }
                    map[t] = out->n;
                    queue[out->n++] = t;
                }
                out->next[s][letters[l]] = (int8_t)map[t];
            }
        }
    }
    free(map);
    free(tr);
    free(sig);
    free(prev);
    return ok ? out->n : 0;
}

/* A letter that leads every state to one state (or none), else -1. */
static int sync1(const dfa *a, int c)
{
    int to = -1;
    for (int s = 0; s < a->n; s++) {
        int t = a->next[s][c];
        if (t < 0)
            continue;
        if (to >= 0 && t != to)
            return -1;
        to = t;
    }
    return to;
}

/* Least k <= 6 such that k letters c lead every state to one state; the
 * state in *out; 0 if none. */
static int sync_run(const dfa *a, int c, int *out)
{
    for (int k = 1; k <= 6; k++) {
        int to = -1, ok = 1;
        for (int s = 0; s < a->n && ok; s++) {
            int t = s;
            for (int i = 0; i < k && t >= 0; i++)
                t = a->next[t][c];
            if (t < 0)
                continue;
            if (to >= 0 && t != to)
                ok = 0;
            to = t;
        }
        if (ok && to >= 0) {
            *out = to;
            return k;
        }
    }
    return 0;
}

static void print_dfa(int q, const dfa *a, int depth, const int *counts)
{
    printf("/* {4,%d}: %d states (suffixes of up to %d letters told apart, ball of\n"
           " * radius %d; tiles at distance 0..%d: ", q, a->n, a->k, depth, depth < 8 ? depth : 8);
    for (int d = 0; d <= 8 && d <= depth; d++)
        printf("%d%s", counts[d], d < 8 && d < depth ? ", " : ")");
    printf(" */\nstatic const uint8_t hol__dfa%d[%d][4] = {\n", q, a->n + 1);
    for (int s = 0; s <= a->n; s++) {
        printf("    {");
        for (int c = 0; c < 4; c++) {
            int t = s < a->n ? a->next[s][c] : -1;
            printf("%d%s", t < 0 ? a->n : t, c < 3 ? ", " : "");
        }
        printf("},\n");
    }
    printf("};\n");
    int st[4], run[4];
    for (int c = 0; c < 4; c++) {
        run[c] = c == 2 ? 0 : sync_run(a, c, &st[c]);
        if (!run[c])
            st[c] = 0;
    }
    (void)sync1;
    printf("/* letters f, l, -, r: a run of this many leads every state to the\n"
           " * state below (0: never) */\n");
    printf("static const uint8_t hol__sync_run%d[4] = {%d, %d, %d, %d};\n", q, run[0], run[1],
           run[2], run[3]);
    printf("static const uint8_t hol__sync_state%d[4] = {%d, %d, %d, %d};\n\n", q, st[0], st[1],
           st[2], st[3]);
}

int main(int argc, char **argv)
{
    (void)argv;
    static const int depth[9] = {0, 0, 0, 0, 40, 12, 11, 13, 11};
    printf("/* hol_tile_dfa.h - generated by tests/gen_tiling.c (make gen-tiling): the\n"
           " * automata of canonical addresses of the tilings {4,Q}, derived from the\n"
           " * geometry. Do not edit. Included by hol_tile.c only. Codes: f 0, l 1,\n"
           " * r 3 (2 is never a letter); state 0 follows the branch; the last row is\n"
           " * the sink (no address continues that way). */\n"
           "#ifndef HOL_TILE_DFA_H\n#define HOL_TILE_DFA_H\n\n#include <stdint.h>\n\n");
    for (int q = 4; q <= 8; q++) {
        ball b = {0};
        b.q = q;
        b.depth = depth[q];
        if (q > 4) {
            double d = 2 * acosh(cos(acos(-1) / q) / sin(acos(-1) / 4));
            g_ch = cosh(d);
            g_sh = sinh(d);
        }
        grow(&b);
        int counts[64] = {0};
        for (int i = 0; i < b.n; i++)
            counts[b.t[i].dist]++;
        int32_t *ch = children(&b);
        /* K grows while the ball tells the states apart; the automaton is
         * taken when two successive K agree */
        dfa a, best = {0};
        int last = 0, settled = 0;
        for (int k = 1; k <= b.depth - 3 && k <= 12; k++) {
            int n = derive(&b, ch, k, &a);
            if (argc > 1)
                fprintf(stderr, "{4,%d} K %d: %d states\n", q, k, n);
            if (n && n == last) {
                best = a;
                settled = 1;
            } else if (!n && settled) {
                break; /* the ball is too small for larger K */
            }
            last = n;
        }
        if (!settled) {
            fprintf(stderr, "gen_tiling: {4,%d}: the automaton did not settle\n", q);
            return 1;
        }
        print_dfa(q, &best, b.depth, counts);
        free(ch);
        free(b.t);
        free(b.slot);
    }
    printf("#endif\n");
    return 0;
}
