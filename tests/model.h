/* model.h - an independent geometric model of the tilings {4,Q}, for tests.
 *
 * Contract: written only for the tests and shares no code with core/. Tiles
 * are 3x3 Lorentz matrices (hyperboloid model, double precision): a frame
 * whose origin is the tile centre and whose +y axis is a heading. A step in
 * direction k (quarter turns counter-clockwise, 0 = +y) is
 * M * R(k) * T(d) * R(-k) with d = 2 acosh(cos(pi/Q) / sin(pi/4)), which
 * carries the frame across the edge (parallel transport). A breadth-first
 * search from the origin identifies tiles by their centre points and gives
 * each tile's true distance. Good to about distance 14 in {4,5} (the
 * coordinates grow like cosh(d * edge), faster for larger Q: 11 in {4,8}).
 * For Q = 4, the flat grid: plain integer coordinates, the same matrices as
 * rigid motions of the plane (exact in double precision), T a unit
 * translation. model_use_tiling(Q) selects the tiling ({4,5} by default).
 *
 * Header-only; include it once per test program.
 */
#ifndef HOL_TEST_MODEL_H
#define HOL_TEST_MODEL_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef struct model_mat {
    double m[9];
} model_mat;

static model_mat model_mul(model_mat a, model_mat b)
{
    model_mat r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.m[3 * i + j] = a.m[3 * i] * b.m[j] + a.m[3 * i + 1] * b.m[3 + j] +
                             a.m[3 * i + 2] * b.m[6 + j];
    return r;
}

static model_mat model_identity(void)
{
    model_mat r = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
    return r;
}

/* Rotation by k quarter turns counter-clockwise (x right, y forward).
 * Each of the four is computed once and kept (the model's steps and
 * distances are most of some tests' time; kept values are the same
 * doubles, so every result is the same too). */
static model_mat model_rot(int k)
{
    static model_mat kept[4];
    static int have[4];
    if (!have[k & 3]) {
        double a = (k & 3) * acos(-1.0) / 2.0;
        double c = round(cos(a)), s = round(sin(a));
        model_mat r = {{c, -s, 0, s, c, 0, 0, 0, 1}};
        kept[k & 3] = r;
        have[k & 3] = 1;
    }
    return kept[k & 3];
}

static int model_q = 5;

static void model_use_tiling(int q) { model_q = q; }

/* The edge length d of model_q's tiling, computed once a tiling and kept
 * (as model_rot's rotations). */
static double model_edge(void)
{
    static double kept[16];
    if (model_q == 4)
        return 1.0;
    if (model_q < 0 || model_q >= 16)
        return 2.0 * acosh(cos(acos(-1.0) / model_q) / sin(acos(-1.0) / 4.0));
    if (kept[model_q] == 0)
        kept[model_q] = 2.0 * acosh(cos(acos(-1.0) / model_q) / sin(acos(-1.0) / 4.0));
    return kept[model_q];
}

/* Translation along +y by the edge length. */
static model_mat model_fwd(void)
{
    if (model_q == 4) {
        model_mat e = {{1, 0, 0, 0, 1, 1, 0, 0, 1}};
        return e;
    }
    static model_mat kept[16];
    static int have[16];
    if (model_q >= 0 && model_q < 16 && have[model_q])
        return kept[model_q];
    double d = model_edge();
    model_mat r = {{1, 0, 0, 0, cosh(d), sinh(d), 0, sinh(d), cosh(d)}};
    if (model_q >= 0 && model_q < 16) {
        kept[model_q] = r;
        have[model_q] = 1;
    }
    return r;
}

static model_mat model_step(model_mat m, int k)
{
    return model_mul(model_mul(model_mul(m, model_rot(k)), model_fwd()),
                     model_rot(-k));
}

/* Inverse of a Lorentz matrix: J M^T J with J = diag(1, 1, -1); of a
 * rigid motion of the flat plane: [R^T, -R^T t]. */
static model_mat model_inv(model_mat a)
{
    model_mat r;
    if (model_q == 4) {
        model_mat e = {{a.m[0], a.m[3], 0, a.m[1], a.m[4], 0, 0, 0, 1}};
        e.m[2] = -(a.m[0] * a.m[2] + a.m[3] * a.m[5]);
        e.m[5] = -(a.m[1] * a.m[2] + a.m[4] * a.m[5]);
        return e;
    }
    static const double j[3] = {1, 1, -1};
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            r.m[3 * i + k] = j[i] * a.m[3 * k + i] * j[k];
    return r;
}

/* Whether two frames have the same centre, to a tolerance relative to the
 * size of the coordinates (acosh of a Minkowski product loses half the
 * digits near zero distance, so positions are compared directly). */
static int model_same_point(model_mat a, model_mat b)
{
    double scale = 1.0 + fabs(a.m[8]) + fabs(b.m[8]);
    return fabs(a.m[2] - b.m[2]) + fabs(a.m[5] - b.m[5]) + fabs(a.m[8] - b.m[8]) <
           1e-6 * scale;
}

/* Rotation (0..3) r with a * R(r) == b, or -1 if the frames differ. */
static int model_frame_diff(model_mat a, model_mat b)
{
    double scale = fabs(a.m[8]) + 1.0;
    for (int k = 0; k < 4; k++) {
        model_mat x = model_mul(a, model_rot(k));
        double e = 0;
        for (int i = 0; i < 9; i++)
            e += fabs(x.m[i] - b.m[i]);
        if (e < 1e-6 * scale)
            return k;
    }
    return -1;
}

/* ---- breadth-first search from the origin ---- */

typedef struct model_tile {
    double x, y; /* centre on the hyperboloid */
    int dist;
} model_tile;

typedef struct model_bfs {
    model_tile *tiles;
    int count, cap;
    int *slots; /* hash table of tile indices, -1 empty */
    uint32_t nslots;
    int max_dist;
    int per_dist[32];
} model_bfs;

static uint32_t model__hash(double x, double y)
{
    int64_t a = llround(x * 8.0), b = llround(y * 8.0);
    uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15u ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Fu;
    h ^= h >> 29;
    return (uint32_t)h;
}

/* Index of the tile centred at (x, y), or -1. Centres of distinct tiles are
 * far apart, so the test is a generous tolerance on the coordinates
 * (relative to their size: rounding errors are about 1e-15 of it, while two
 * tiles far out can differ by as little as one unit in one coordinate). */
static int model_find(const model_bfs *b, double x, double y)
{
    double tol = 1e-9 * (1.0 + fabs(x) + fabs(y));
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++) {
            double qx = x + dx * 0.0625, qy = y + dy * 0.0625;
            uint32_t h = model__hash(qx, qy) & (b->nslots - 1);
            for (;;) {
                int i = b->slots[h];
                if (i < 0)
                    break;
                if (fabs(b->tiles[i].x - x) < tol && fabs(b->tiles[i].y - y) < tol)
                    return i;
                h = (h + 1) & (b->nslots - 1);
            }
        }
    return -1;
}

static int model__add(model_bfs *b, double x, double y, int dist)
{
    int i = b->count++;
    b->tiles[i].x = x;
    b->tiles[i].y = y;
    b->tiles[i].dist = dist;
    uint32_t h = model__hash(x, y) & (b->nslots - 1);
    while (b->slots[h] >= 0)
        h = (h + 1) & (b->nslots - 1);
    b->slots[h] = i;
    b->per_dist[dist]++;
    return i;
}

/* All tiles to max_dist with their distances. Frames of the search are kept
 * only for the current and next layer. Returns 0 on success. */
static int model_bfs_run(model_bfs *b, int max_dist)
{
    memset(b, 0, sizeof *b);
    b->max_dist = max_dist;
    b->cap = 1;
    for (int d = 1, n = 4; d <= max_dist && b->cap < 4000000; d++, n *= 3)
        b->cap += n; /* 4 * 3^(d - 1) at distance d: a bound */
    if (b->cap > 4000000)
        b->cap = 4000000;
    if (model_q == 4)
        b->cap = 2 * (max_dist + 1) * (max_dist + 2) + 1; /* 1 + 2d(d + 1) */
    if (max_dist > 31)
        return -1; /* per_dist */
    b->nslots = 1;
    while (b->nslots < (uint32_t)b->cap * 2)
        b->nslots <<= 1;
    b->tiles = malloc(sizeof *b->tiles * (size_t)b->cap);
    b->slots = malloc(sizeof *b->slots * b->nslots);
    model_mat *layer = malloc(sizeof *layer * (size_t)b->cap);
    model_mat *next = malloc(sizeof *next * (size_t)b->cap);
    if (!b->tiles || !b->slots || !layer || !next)
        return -1;
    memset(b->slots, 0xff, sizeof *b->slots * b->nslots);
    layer[0] = model_identity();
    int nlayer = 1;
    model__add(b, 0, 0, 0);
    for (int d = 1; d <= max_dist; d++) {
        int nnext = 0;
        for (int i = 0; i < nlayer; i++)
            for (int k = 0; k < 4; k++) {
                model_mat m = model_step(layer[i], k);
                if (model_find(b, m.m[2], m.m[5]) >= 0)
                    continue;
                if (b->count >= b->cap)
                    return -1;
                model__add(b, m.m[2], m.m[5], d);
                next[nnext++] = m;
            }
        model_mat *t = layer;
        layer = next;
        next = t;
        nlayer = nnext;
    }
    free(layer);
    free(next);
    return 0;
}

static void model_bfs_free(model_bfs *b)
{
    free(b->tiles);
    free(b->slots);
}

/* Distance from the origin of the tile centred where frame m is; -1 if the
 * tile is beyond the search. */
static int model_dist0(const model_bfs *b, model_mat m)
{
    int i = model_find(b, m.m[2], m.m[5]);
    return i < 0 ? -1 : b->tiles[i].dist;
}

/* Frame reached from the origin (heading N = +y) by an address given as
 * letter codes: the branch (0 N, 1 W, 2 S, 3 E, a turn from +y) and then
 * turns (0 f, 1 l, 3 r) relative to the current heading. The frame's +y is
 * the heading of the last step. */
static model_mat model_walk_letters(const int *codes, int n)
{
    model_mat m = model_identity();
    int heading = 0;
    for (int i = 0; i < n; i++) {
        heading = (heading + codes[i]) & 3;
        m = model_step(m, heading);
    }
    /* rotate the frame so that +y is the final heading */
    return model_mul(m, model_rot(heading));
}

#endif
