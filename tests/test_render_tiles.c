/* test_render_tiles.c - the portals against an independent ray walk.
 *
 * For every pixel of a set of views, the test computes in double precision
 * (its own camera maths from SPEC section 1, not the renderer's) where the
 * pixel-centre ray meets the floor, walks the cells that the eye-to-point
 * segment crosses (sorted crossings of the grid lines, not the renderer's
 * angular leaves or stencil codes) with hol_room_step on the user's state,
 * and compares with the tile the renderer drew there (ID mode: the branch
 * whose stencil-tested floor covered the pixel). Pixels are skipped only
 * when the answer is ambiguous: a sample 0.05 px away gives another answer
 * (the point is within a hair of a cell edge, the room boundary, or the
 * segment passes within a hair of a vertex).
 * - bare views (floors only): the floor pixels must be exactly the expected
 *   ones, every one with the expected tile;
 * - full views (trees, hedges, props): every floor pixel must be expected
 *   floor with the expected tile (props may hide floor, never add it).
 * The test was checked against deliberate bugs (stencil masks cut to the
 * first step, leaf wedges shifted by 0.02): each makes it fail.
 * Geometry cases (SPEC 7): the tilings {4,4}..{4,8}, rooms of 3..5 cells a
 * side (larger rooms tell branches apart by wedges, not stencil codes)
 * and cells of M metres (the ray walk crosses the lines x = k*M, z = k*M).
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

#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_render.h"
#include "count_alloc.h"
#include "render_fixture.h"

#define W 128
#define H 96
#define PI 3.14159265358979323846

typedef struct view_case {
    const char *walk;
    double eye[3], yaw, pitch, fov;
    int flags;
    /* headset form: roll and an asymmetric frustum (tangents) */
    int pose;
    double roll, tl, tr, td, tu;
    /* geometry: tiling Q, room C x R, cell M metres (0: 5, 3, 3, 1) */
    int q, cols, rows;
    double cell;
} view_case;

#define GEOM_CASES 9

static const view_case cases[] = {
    {"-", {1.5, 1.6, 1.5}, 0, -45, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* centre cell */
    {"-", {1.2, 1.6, 1.7}, 90, -30, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* centre, looking west */
    {"N", {1.5, 1.6, 0.3}, 180, -40, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* edge cell, looking south */
    {"NW", {0.2, 1.6, 0.2}, -135, -35, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* corner, across the room */
    {"SE", {2.8, 1.7, 2.9}, 45, -30, 100, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* other corner */
    {"E", {2.5, 1.5, 1.02}, 90, -20, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* along the edge z = 1 */
    {"NW", {0.5, 1.6, 0.5}, -135, -40, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* across the diagonal vertices */
    {"-", {1.37, 1.6, 1.61}, 33, -90, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* straight down */
    {"NWSSEEN", {2.3, 1.8, 1.6}, 200, -25, 120, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* deeper tile, wide view */
    {"S", {1.6, 0.5, 2.4}, 10, -10, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, /* low eye, grazing */
    {"W", {0.7, 1.6, 1.3}, -70, -35, 90, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {"-", {1.5, 1.6, 1.5}, 0, -45, 90, HOL_RENDER_EUCLIDEAN, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {"NW", {0.2, 1.6, 0.2}, -135, -35, 90, HOL_RENDER_EUCLIDEAN, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    /* headset poses: roll and asymmetric per-eye frusta as OpenXR gives */
    {"-", {1.47, 1.62, 1.55}, 20, -30, 0, 0, 1, 12, -1.05, 0.88, -1.12, 0.84, 0, 0, 0, 0},
    {"SE", {2.6, 1.7, 2.7}, 50, -45, 0, 0, 1, -25, -0.9, 1.02, -1.2, 0.9, 0, 0, 0, 0},
    {"N", {1.3, 1.5, 0.6}, 170, -60, 0, 0, 1, 40, -1.3, 0.7, -0.8, 1.1, 0, 0, 0, 0},
    {"W", {0.5, 1.6, 1.5}, -80, -20, 0, HOL_RENDER_EUCLIDEAN, 1, 8, -1.0, 1.0, -1.1, 0.8, 0, 0, 0, 0},
    /* geometries (GEOM_CASES, last): tilings, rooms, cells */
    {"NE", {2.4, 1.6, 0.6}, 135, -30, 90, 0, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0},
    {"NE", {2.4, 1.6, 0.6}, 135, -30, 90, 0, 0, 0, 0, 0, 0, 0, 6, 0, 0, 0},
    {"SW", {0.3, 1.6, 2.8}, -45, -35, 100, 0, 0, 0, 0, 0, 0, 0, 8, 0, 0, 0},
    {"NW", {1.3, 1.6, 1.2}, -135, -30, 100, 0, 0, 0, 0, 0, 0, 0, 5, 5, 5, 0},
    {"-", {2.45, 1.6, 2.6}, 20, -35, 100, 0, 0, 0, 0, 0, 0, 0, 7, 5, 5, 0},
    {"E", {2.2, 1.6, 1.6}, 100, -30, 90, 0, 0, 0, 0, 0, 0, 0, 6, 4, 4, 0.7},
    {"S", {3.0, 1.5, 2.9}, 200, -40, 90, 0, 0, 0, 0, 0, 0, 0, 5, 5, 3, 1.3},
    {"N", {0.8, 1.6, 0.6}, 170, -45, 90, 0, 0, 0, 0, 0, 0, 0, 4, 3, 4, 0.5},
    {"NW", {1.3, 1.6, 1.2}, -135, -30, 100, HOL_RENDER_EUCLIDEAN, 0, 0, 0, 0, 0, 0, 5, 5, 5, 0},
};

/* The renderer's camera for a case: yaw/pitch/fov, or the headset form
 * with the orientation as a quaternion qyaw * qpitch * qroll. */
static void fill_cam(const view_case *c, hol_camera *cam)
{
    memset(cam, 0, sizeof *cam);
    memcpy(cam->eye, c->eye, sizeof cam->eye);
    cam->yaw_deg = c->yaw;
    cam->pitch_deg = c->pitch;
    cam->fovy_deg = c->fov;
    cam->width = W;
    cam->height = H;
    if (!c->pose)
        return;
    double y = c->yaw * PI / 360, p = c->pitch * PI / 360, r = c->roll * PI / 360;
    double qy[4] = {0, sin(y), 0, cos(y)}, qx[4] = {sin(p), 0, 0, cos(p)},
           qz[4] = {0, 0, sin(r), cos(r)}, t[4], q[4];
    /* Hamilton products (x, y, z, w) */
#define QMUL(a, b, o)                                                          \
    do {                                                                       \
        o[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];          \
        o[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];          \
        o[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];          \
        o[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];          \
    } while (0)
    QMUL(qy, qx, t);
    QMUL(t, qz, q);
#undef QMUL
    cam->has_pose = 1;
    memcpy(cam->orient, q, sizeof q);
    cam->tan_left = c->tl;
    cam->tan_right = c->tr;
    cam->tan_down = c->td;
    cam->tan_up = c->tu;
}

static render_fixture fx;

static int setup(void **state)
{
    (void)state;
    return render_fixture_make(&fx, W, H, 7);
}

static int teardown(void **state)
{
    (void)state;
    render_fixture_destroy(&fx);
    return 0;
}

static hol_room state_of(const char *walk)
{
    hol_room u = hol_room_start();
    for (const char *p = walk; *p && *p != '-'; p++)
        assert_int_equal(hol_room_step(&u, hol_dir_from_char(*p)), HOL_OK);
    return u;
}

/* A case's state: its walk from the start of its room in its tiling. */
static hol_room case_state(const view_case *c)
{
    hol_room u;
    assert_int_equal(hol_room_start_in(c->q, c->cols, c->rows, &u), HOL_OK);
    for (const char *p = c->walk; *p && *p != '-'; p++)
        assert_int_equal(hol_room_step(&u, hol_dir_from_char(*p)), HOL_OK);
    return u;
}

static double case_cell(const view_case *c)
{
    return c->cell > 0 ? c->cell : 1.0;
}

/* The floor point of pixel (px, py) (fractional, pixel centres at .5). */
static int floor_point(const view_case *c, double px, double py, double out[2])
{
    double yaw = c->yaw * PI / 180, pitch = c->pitch * PI / 180;
    double ty = tan(c->fov * PI / 360), tx = ty * W / H;
    double nx = 2 * px / W - 1, ny = 1 - 2 * py / H;
    /* view space ray (nx tx, ny ty, -1); pitch about x, then yaw about y */
    double vx = nx * tx, vy = ny * ty, vz = -1;
    if (c->pose) {
        /* asymmetric frustum, then roll about z (rotation matrices, not
         * the renderer's quaternion code) */
        double ax = c->tl + (px / W) * (c->tr - c->tl);
        double ay = c->tu - (py / H) * (c->tu - c->td);
        double ro = c->roll * PI / 180;
        vx = ax * cos(ro) - ay * sin(ro);
        vy = ax * sin(ro) + ay * cos(ro);
    }
    double y1 = vy * cos(pitch) - vz * sin(pitch);
    double z1 = vy * sin(pitch) + vz * cos(pitch);
    double x2 = vx * cos(yaw) + z1 * sin(yaw);
    double z2 = -vx * sin(yaw) + z1 * cos(yaw);
    if (y1 >= 0)
        return 0;
    double t = -c->eye[1] / y1;
    out[0] = c->eye[0] + t * x2;
    out[1] = c->eye[2] + t * z2;
    return 1;
}

typedef struct cross {
    double t;
    int dir;
} cross;

static int cmp_cross(const void *a, const void *b)
{
    double x = ((const cross *)a)->t, y = ((const cross *)b)->t;
    return x < y ? -1 : x > y;
}

/* Expected tile at pixel (px,py): 1 floor with *out, 0 no floor, -1 the
 * segment passes through a vertex (hidden by a trunk). */
static int expected(const view_case *c, double px, double py, hol_tile *out)
{
    double p[2];
    if (!floor_point(c, px, py, p))
        return 0;
    hol_room u = case_state(c);
    const double m = case_cell(c);
    const int cols = hol_room_cols(&u), rows = hol_room_rows(&u);
    if (p[0] <= 0 || p[0] >= cols * m || p[1] <= 0 || p[1] >= rows * m)
        return 0;
    double ex = c->eye[0], ez = c->eye[2];
    if (c->flags & HOL_RENDER_EUCLIDEAN) {
        int col = (int)floor(p[0] / m), row = (int)floor(p[1] / m);
        while (u.col != col)
            assert_int_equal(hol_room_step(&u, u.col < col ? HOL_DIR_E : HOL_DIR_W), 0);
        while (u.row != row)
            assert_int_equal(hol_room_step(&u, u.row < row ? HOL_DIR_S : HOL_DIR_N), 0);
        *out = u.tile;
        return 1;
    }
    cross cs[2 * HOL_ROOM_MAX_SIDE];
    int n = 0;
    for (int k = 1; k < cols; k++)
        if ((ex < k * m) != (p[0] < k * m))
            cs[n++] = (cross){(k * m - ex) / (p[0] - ex), p[0] > ex ? HOL_DIR_E : HOL_DIR_W};
    for (int k = 1; k < rows; k++)
        if ((ez < k * m) != (p[1] < k * m))
            cs[n++] = (cross){(k * m - ez) / (p[1] - ez), p[1] > ez ? HOL_DIR_S : HOL_DIR_N};
    qsort(cs, (size_t)n, sizeof cs[0], cmp_cross);
    double len = hypot(p[0] - ex, p[1] - ez);
    for (int i = 0; i + 1 < n; i++)
        if ((cs[i + 1].t - cs[i].t) * len < 1e-9)
            return -1;
    for (int i = 0; i < n; i++)
        assert_int_equal(hol_room_step(&u, cs[i].dir), HOL_OK);
    *out = u.tile;
    return 1;
}

static void check_case(const view_case *c, int flags, int *out_checked)
{
    hol_frame_desc f;
    memset(&f, 0, sizeof f);
    f.user = case_state(c);
    f.cell_m = c->cell;
    fill_cam(c, &f.cam);
    f.flags = c->flags | flags | HOL_RENDER_IDS | HOL_RENDER_NO_HUD;
    static uint8_t px[W * H * 4];
    render_fixture_draw(fx.rnd, &f, W, H, px);
    const hol_view *v = hol_render_last_view(fx.rnd);
    int bare = (flags & HOL_RENDER_BARE) != 0;
    int checked = 0, skipped = 0, drawn = 0, exp_floor = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int id = hol_render_decode_id(px + (y * W + x) * 4);
            assert_true(id >= -1 && id < v->nbranches);
            drawn += id >= 0;
            hol_tile t0, t1;
            int e0 = expected(c, x + 0.5, y + 0.5, &t0);
            static const double d[4][2] = {{0.05, 0}, {-0.05, 0}, {0, 0.05}, {0, -0.05}};
            int ambiguous = e0 < 0;
            for (int k = 0; k < 4 && !ambiguous; k++) {
                int e1 = expected(c, x + 0.5 + d[k][0], y + 0.5 + d[k][1], &t1);
                ambiguous = e1 != e0 || (e0 == 1 && !hol_tile_eq(t0, t1));
            }
            if (ambiguous) {
                skipped++;
                continue;
            }
            exp_floor += e0;
            if (e0 == 0 && id >= 0)
                fail_msg("case %s yaw %g: pixel %d,%d shows floor where the ray "
                         "walk finds none", c->walk, c->yaw, x, y);
            if (e0 == 1 && id < 0) {
                if (bare)
                    fail_msg("case %s yaw %g: pixel %d,%d shows no floor in a bare "
                             "view", c->walk, c->yaw, x, y);
                continue;
            }
            if (e0 == 1) {
                if (!hol_tile_eq(v->branches[id].state.tile, t0)) {
                    char a[HOL_TILE_ADDR_MAX], b[HOL_TILE_ADDR_MAX];
                    hol_tile_print(v->branches[id].state.tile, a);
                    hol_tile_print(t0, b);
                    fail_msg("case %s eye %g,%g yaw %g: pixel %d,%d shows %s, the ray "
                             "walk reaches %s", c->walk, c->eye[0], c->eye[2], c->yaw,
                             x, y, a, b);
                }
                checked++;
            }
        }
    /* the comparison must have teeth: most pixels are decided */
    assert_true(skipped < W * H / 10);
    if (bare)
        assert_true(checked >= exp_floor);
    *out_checked += checked;
    (void)drawn;
}

static void test_bare_views_match_ray_walk(void **state)
{
    (void)state;
    int checked = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_case(&cases[i], HOL_RENDER_BARE, &checked);
    assert_true(checked > 30000);
}

static void test_full_views_match_ray_walk(void **state)
{
    (void)state;
    int checked = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        check_case(&cases[i], 0, &checked);
    assert_true(checked > 10000);
}

/* Every reachable view branch: a sweep of eye positions over all nine
 * cells and yaws, checked pixel by pixel at a small size. */
static void test_sweep_all_cells(void **state)
{
    (void)state;
    static const char *walks[9] = {"NW", "N", "NE", "W", "-", "E", "SW", "S", "SE"};
    int checked = 0;
    for (int k = 0; k < 9; k++) {
        hol_room u = state_of(walks[k]);
        for (int j = 0; j < 8; j++) {
            view_case c;
            memset(&c, 0, sizeof c);
            c.walk = walks[k];
            c.eye[0] = u.col + 0.15 + 0.7 * ((j * 37) % 8) / 7.0;
            c.eye[1] = 1.6;
            c.eye[2] = u.row + 0.15 + 0.7 * ((j * 53) % 8) / 7.0;
            c.yaw = j * 45 + 10;
            c.pitch = -35;
            c.fov = 100;
            check_case(&c, HOL_RENDER_BARE, &checked);
        }
    }
    assert_true(checked > 100000);
}

/* Trunks hide the seams: no floor pixel's sight line passes within 5 cm of
 * a vertex (the trunks are at least 6 cm thick up to above the eye). */
static void test_trunks_hide_seams(void **state)
{
    (void)state;
    int checked = 0;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const view_case *c = &cases[i];
        hol_frame_desc f;
        memset(&f, 0, sizeof f);
        f.user = case_state(c);
        f.cell_m = c->cell;
        fill_cam(c, &f.cam);
        f.flags = c->flags | HOL_RENDER_IDS | HOL_RENDER_NO_HUD;
        static uint8_t px[W * H * 4];
        render_fixture_draw(fx.rnd, &f, W, H, px);
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                if (hol_render_decode_id(px + (y * W + x) * 4) < 0)
                    continue;
                double p[2];
                if (!floor_point(c, x + 0.5, y + 0.5, p))
                    fail_msg("pixel %d,%d shows floor above the horizon", x, y);
                double ex = c->eye[0], ez = c->eye[2], dx = p[0] - ex, dz = p[1] - ez;
                double l2 = dx * dx + dz * dz, m = case_cell(c);
                hol_room u = case_state(c);
                for (int vj = 0; vj <= hol_room_rows(&u); vj++)
                    for (int vi = 0; vi <= hol_room_cols(&u); vi++) {
                        double t = ((vi * m - ex) * dx + (vj * m - ez) * dz) / l2;
                        t = t < 0 ? 0 : t > 1 ? 1 : t;
                        double d = hypot(ex + t * dx - vi * m, ez + t * dz - vj * m);
                        if (d < 0.05)
                            fail_msg("case %s yaw %g: pixel %d,%d shows floor %.3f m "
                                     "from the trunk axis at vertex (%d,%d)",
                                     c->walk, c->yaw, x, y, d, vi, vj);
                    }
                checked++;
            }
    }
    assert_true(checked > 20000);
}

/* Project a floor point to pixel coordinates with the test's own camera. */
static int project(const view_case *c, double x, double z, double out[2])
{
    double yaw = c->yaw * PI / 180, pitch = c->pitch * PI / 180;
    double ty = tan(c->fov * PI / 360), tx = ty * W / H;
    double vx = x - c->eye[0], vy = -c->eye[1], vz = z - c->eye[2];
    /* undo yaw (about y), then pitch (about x) */
    double x1 = vx * cos(yaw) - vz * sin(yaw), z1 = vx * sin(yaw) + vz * cos(yaw);
    double y2 = vy * cos(pitch) + z1 * sin(pitch), z2 = -vy * sin(pitch) + z1 * cos(pitch);
    if (z2 >= -1e-6)
        return 0;
    out[0] = (x1 / -z2 / tx + 1) * W / 2;
    out[1] = (1 - y2 / -z2 / ty) * H / 2;
    return out[0] >= 0 && out[0] < W && out[1] >= 0 && out[1] < H;
}

static int is_water(const uint8_t *p)
{
    return p[2] > p[1] + 20 && p[2] > p[0] + 60;
}

/* Creeks continue across every cell edge: the tiles on both sides of an
 * edge, each drawn in its own branch's frame, agree on whether a creek
 * crosses the edge's midpoint. A wrong rotation of tile frames breaks it. */
static void test_creeks_continue_across_edges(void **state)
{
    (void)state;
    int checked = 0, water = 0;
    uint64_t rng = 12345;
    for (uint64_t seed = 1; seed <= 12; seed++) {
        hol_world *w;
        hol_world_desc wd;
        memset(&wd, 0, sizeof wd);
        wd.seed = seed;
        wd.capacity = 1u << 14;
        assert_int_equal(hol_world_make(&wd, &w), HOL_OK);
        hol_render_set_world(fx.rnd, w);
        for (int k = 0; k < 24; k++) {
            /* a random walk in the room back to the centre cell */
            char walk[40];
            int n = 0;
            hol_room u = hol_room_start();
            int len = 2 + (int)(rng % 10);
            while (n < len) {
                rng = rng * 6364136223846793005ull + 1442695040888963407ull;
                int d = (int)(rng >> 62);
                if (hol_room_step(&u, d) == HOL_OK)
                    walk[n++] = hol_dir_to_char(d);
            }
            while (u.col != 1 || u.row != 1) {
                int d = u.col < 1 ? HOL_DIR_E : u.col > 1 ? HOL_DIR_W
                        : u.row < 1 ? HOL_DIR_S : HOL_DIR_N;
                assert_int_equal(hol_room_step(&u, d), HOL_OK);
                walk[n++] = hol_dir_to_char(d);
            }
            walk[n] = 0;
            if (hol_world_update(w, &u))
                continue;
            view_case c = {walk, {1.5, 1.6, 1.5}, (double)(k * 90), -90, 110,
                           HOL_RENDER_BARE, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
            hol_frame_desc f;
            memset(&f, 0, sizeof f);
            f.user = u;
            memcpy(f.cam.eye, c.eye, sizeof f.cam.eye);
            f.cam.yaw_deg = c.yaw;
            f.cam.pitch_deg = c.pitch;
            f.cam.fovy_deg = c.fov;
            f.cam.width = W;
            f.cam.height = H;
            f.flags = HOL_RENDER_BARE | HOL_RENDER_NO_HUD;
            static uint8_t px[W * H * 4];
            render_fixture_draw(fx.rnd, &f, W, H, px);
            /* the 12 interior edges: vertical x = 1, 2 and horizontal z = 1, 2 */
            for (int e = 0; e < 12; e++) {
                int vert = e < 6, line = 1 + (e % 6) / 3, seg = e % 3;
                double mx = vert ? line : seg + 0.5, mz = vert ? seg + 0.5 : line;
                double ox = vert ? 0.05 : 0, oz = vert ? 0 : 0.05;
                double a[2], b[2];
                if (!project(&c, mx - ox, mz - oz, a) || !project(&c, mx + ox, mz + oz, b))
                    continue;
                const uint8_t *pa = px + ((int)a[1] * W + (int)a[0]) * 4;
                const uint8_t *pb = px + ((int)b[1] * W + (int)b[0]) * 4;
                if (is_water(pa) != is_water(pb))
                    fail_msg("seed %d walk %s: a creek ends at the edge midpoint "
                             "(%.1f,%.1f): pixel %d,%d vs %d,%d", (int)seed, walk, mx,
                             mz, (int)a[0], (int)a[1], (int)b[0], (int)b[1]);
                checked++;
                water += is_water(pa);
            }
        }
        hol_render_set_world(fx.rnd, fx.world);
        hol_world_destroy(w);
    }
    printf("creeks: %d edges checked, %d with water\n", checked, water);
    /* the check must have met creeks, or it proves nothing */
    assert_true(checked > 500);
    assert_true(water >= 12);
}

/* The stencil code is a prefix code: over many eye positions, a branch's
 * (ref, mask) accepts a leaf exactly when the branch's steps are a prefix
 * of the leaf's, for any two branches reaching the same cell. */
static void test_stencil_codes_are_prefix_codes(void **state)
{
    (void)state;
    uint64_t rng = 7;
    int pairs = 0;
    static const char *walks[9] = {"NW", "N", "NE", "W", "-", "E", "SW", "S", "SE"};
    for (int it = 0; it < 2000; it++) {
        hol_room u = state_of(walks[it % 9]);
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        double ex = u.col + 0.01 + 0.98 * (double)(rng >> 11) / 9007199254740992.0;
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        double ez = u.row + 0.01 + 0.98 * (double)(rng >> 11) / 9007199254740992.0;
        static hol_view v;
        assert_int_equal(hol_view_build(&u, ex, ez, 0, &v), HOL_OK);
        assert_true(v.nleaves >= 4 && v.nleaves <= HOL_VIEW_MAX_LEAVES);
        for (int b = 1; b < v.nbranches; b++) {
            const hol_view_branch *br = &v.branches[b];
            for (int l = 0; l < v.nleaves; l++) {
                const hol_view_leaf *lf = &v.leaves[l];
                int prefix = lf->nsteps > br->nsteps &&
                             !memcmp(lf->steps, br->steps, br->nsteps);
                int accepts = (lf->code & br->mask) == br->ref;
                if (prefix)
                    assert_true(accepts);
                /* a leaf through another branch to the same cell is refused */
                for (int o = 1; o < v.nbranches && accepts && !prefix; o++) {
                    const hol_view_branch *ot = &v.branches[o];
                    if (o == b || ot->state.col != br->state.col ||
                        ot->state.row != br->state.row)
                        continue;
                    if (lf->nsteps > ot->nsteps && !memcmp(lf->steps, ot->steps, ot->nsteps))
                        fail_msg("eye %.3f,%.3f: two branches to cell %d,%d accept one leaf",
                                 ex, ez, br->state.col, br->state.row);
                    pairs++;
                }
            }
        }
        /* the wedges cover the full turn once */
        double total = 0;
        for (int l = 0; l < v.nleaves; l++) {
            const double *a = v.leaves[l].u0, *c = v.leaves[l].u1;
            total += atan2(a[0] * c[1] - a[1] * c[0], a[0] * c[0] + a[1] * c[1]);
        }
        assert_true(fabs(total - 2 * PI) < 1e-9);
    }
    (void)pairs;
}

/* Larger rooms: branches are told apart by wedges. Over many eye
 * positions in 5 x 5 rooms ({4,5} and {4,8}): the branches fit
 * HOL_VIEW_MAX_BRANCHES with room to spare, the distinct tiles fit the
 * renderer's 96 resident meshes (hol_render_tiles.c), and a branch's wedge holds exactly the
 * leaves its steps are a prefix of (each leaf's middle direction). */
static void test_wedges_in_large_rooms(void **state)
{
    (void)state;
    uint64_t rng = 11;
    int most = 0, most_tiles = 0;
    for (int it = 0; it < 600; it++) {
        hol_room u;
        assert_int_equal(hol_room_start_in(it % 2 ? 8 : 5, 5, 5, &u), HOL_OK);
        static const char *walks[] = {"NW", "NN", "NNWW", "-", "SSEE", "E", "WWS"};
        for (const char *p = walks[it % 7]; *p && *p != '-'; p++)
            assert_int_equal(hol_room_step(&u, hol_dir_from_char(*p)), HOL_OK);
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        double ex = u.col + 0.01 + 0.98 * (double)(rng >> 11) / 9007199254740992.0;
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        double ez = u.row + 0.01 + 0.98 * (double)(rng >> 11) / 9007199254740992.0;
        static hol_view v;
        assert_int_equal(hol_view_build(&u, ex, ez, 0, &v), HOL_OK);
        assert_int_equal(v.wedges, 1);
        assert_true(v.nbranches < HOL_VIEW_MAX_BRANCHES);
        most = v.nbranches > most ? v.nbranches : most;
        int ntiles = 0;
        for (int b = 0; b < v.nbranches; b++) {
            int seen = 0;
            for (int o = 0; o < b && !seen; o++)
                seen = hol_tile_eq(v.branches[o].state.tile, v.branches[b].state.tile);
            ntiles += !seen;
        }
        most_tiles = ntiles > most_tiles ? ntiles : most_tiles;
        for (int b = 1; b < v.nbranches; b++) {
            const hol_view_branch *br = &v.branches[b];
            assert_int_equal(br->mask, 0);
            for (int l = 0; l < v.nleaves; l++) {
                const hol_view_leaf *lf = &v.leaves[l];
                double m[2] = {lf->u0[0] + lf->u1[0], lf->u0[1] + lf->u1[1]};
                int in = br->w0[0] * m[1] - br->w0[1] * m[0] > 0 &&
                         m[0] * br->w1[1] - m[1] * br->w1[0] > 0;
                int prefix = lf->nsteps > br->nsteps &&
                             !memcmp(lf->steps, br->steps, br->nsteps);
                if (in != prefix)
                    fail_msg("eye %.3f,%.3f: branch %d's wedge %s leaf %d", ex, ez, b,
                             in ? "holds" : "misses", l);
            }
        }
    }
    printf("5 x 5 rooms: at most %d branches, %d distinct tiles\n", most, most_tiles);
    assert_true(most_tiles <= 96);
}

static void test_ids_decode(void **state)
{
    (void)state;
    uint8_t none[4] = {0, 0, 0, 255}, one[4] = {1, 0, 0, 255}, big[4] = {45, 1, 0, 255};
    assert_int_equal(hol_render_decode_id(none), -1);
    assert_int_equal(hol_render_decode_id(one), 0);
    assert_int_equal(hol_render_decode_id(big), 300);
}

/* The renderer's CPU stores come through the allocator hooks
 * (core/hol_alloc.h), all at create; a frame allocates nothing. */
static void test_allocator_hooks(void **state)
{
    (void)state;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = fx.world;
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1; /* a test build: every GL error reported */
    rd.alloc = count_alloc_hooks();
    hol_render *r = NULL;
    assert_int_equal(hol_render_create(&rd, &r), HOL_OK);
    long made = count_allocs;
    assert_true(made >= 2);
    hol_frame_desc f = render_fixture_frame(W, H, -30);
    f.flags = HOL_RENDER_MINIMAP;
    for (int k = 0; k < 3; k++)
        assert_int_equal(hol_render_frame(r, &f, NULL), HOL_OK);
    assert_int_equal(count_allocs, made);
    hol_render_destroy(r);
    assert_int_equal(count_frees, made);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_wedges_in_large_rooms),
        cmocka_unit_test(test_ids_decode),
        cmocka_unit_test(test_stencil_codes_are_prefix_codes),
        cmocka_unit_test(test_bare_views_match_ray_walk),
        cmocka_unit_test(test_full_views_match_ray_walk),
        cmocka_unit_test(test_sweep_all_cells),
        cmocka_unit_test(test_trunks_hide_seams),
        cmocka_unit_test(test_creeks_continue_across_edges),
        cmocka_unit_test(test_allocator_hooks),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
