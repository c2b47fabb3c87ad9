/* test_motion.c - room following (core/hol_motion.h) against an independent
 * check: the head moved in 0.1 mm sub-steps, a room step each time the
 * floor cell under it changes; eye states for stereo; hedges; pancake axes.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_motion.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"

static uint64_t rng_next(uint64_t *s)
{
    *s += UINT64_C(0x9E3779B97F4A7C15);
    uint64_t z = *s;
    z = (z ^ (z >> 30)) * UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27)) * UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

static double rng_unit(uint64_t *s)
{
    return (double)(rng_next(s) >> 11) * (1.0 / 9007199254740992.0);
}

static hol_room state_of(const char *walk)
{
    uint8_t d[64];
    size_t n = 0;
    hol_room r = hol_room_start();
    assert_int_equal(hol_walk_parse(walk, strlen(walk), d, sizeof d, &n, NULL), HOL_OK);
    assert_int_equal(hol_room_walk(&r, d, n, NULL), HOL_OK);
    return r;
}

static void assert_same_room(const hol_room *a, const hol_room *b)
{
    assert_true(hol_tile_eq(a->tile, b->tile));
    assert_int_equal(a->orient, b->orient);
    assert_int_equal(a->col, b->col);
    assert_int_equal(a->row, b->row);
}

/* The independent check: walk the segment in tiny sub-steps; whenever the
 * cell under the point changes, step the room that way (a change of both
 * column and row in one sub-step is a vertex: returns 0, no verdict). */
static int reference_walk(hol_room *u, double x0, double z0, double x1, double z1)
{
    int n = (int)(fmax(fabs(x1 - x0), fabs(z1 - z0)) / 1e-4) + 1;
    int col = (int)floor(x0), row = (int)floor(z0);
    for (int i = 1; i <= n; i++) {
        double t = (double)i / n;
        int c = (int)floor(x0 + (x1 - x0) * t), r = (int)floor(z0 + (z1 - z0) * t);
        if (c != col && r != row)
            return 0;
        if (c != col)
            assert_int_equal(hol_room_step(u, c > col ? HOL_DIR_E : HOL_DIR_W), HOL_OK);
        if (r != row)
            assert_int_equal(hol_room_step(u, r > row ? HOL_DIR_S : HOL_DIR_N), HOL_OK);
        col = c;
        row = r;
    }
    return 1;
}

/* Random moves (within the margin so no clamping) against the reference;
 * the steps listed replay to the same state and the head stays in its
 * cell. */
static void test_move_against_reference(void **state)
{
    (void)state;
    uint64_t s = 42;
    hol_motion m;
    hol_room start = hol_room_start();
    hol_motion_init(&m, &start, NULL);
    int checked = 0, crossings = 0;
    for (int k = 0; k < 3000; k++) {
        double len = 0.02 + 1.3 * rng_unit(&s), ang = 2 * M_PI * rng_unit(&s);
        double to[3] = {m.head[0] + len * cos(ang), 1.6, m.head[2] + len * sin(ang)};
        if (to[0] < 0.2 || to[0] > 2.8 || to[2] < 0.2 || to[2] > 2.8)
            continue;
        hol_room ref = m.user, before = m.user;
        int ok = reference_walk(&ref, m.head[0], m.head[2], to[0], to[2]);
        hol_motion_steps st;
        long steps0 = m.steps;
        assert_int_equal(hol_motion_move_to(&m, to, &st), HOL_OK);
        assert_int_equal(m.steps - steps0, st.n);
        assert_true(m.head[0] > m.user.col && m.head[0] < m.user.col + 1);
        assert_true(m.head[2] > m.user.row && m.head[2] < m.user.row + 1);
        hol_room replay = before;
        for (int i = 0; i < st.n; i++) {
            assert_int_equal(hol_room_step(&replay, st.dir[i]), HOL_OK);
            assert_same_room(&replay, &st.after[i]);
        }
        assert_same_room(&replay, &m.user);
        if (ok) {
            assert_same_room(&ref, &m.user);
            checked++;
            crossings += st.n;
        }
    }
    assert_true(checked > 1000);
    assert_true(crossings > 1000);
}

/* Hedges stop you: pushing far outside leaves the head at the margin, in
 * the border cell, with the room steps of the way there. */
static void test_hedges(void **state)
{
    (void)state;
    hol_motion m;
    hol_room start = hol_room_start();
    hol_motion_desc d;
    memset(&d, 0, sizeof d);
    d.margin = 0.2;
    hol_motion_init(&m, &start, &d);
    double far_north[3] = {1.5, 1.6, -5};
    hol_motion_steps st;
    assert_int_equal(hol_motion_move_to(&m, far_north, &st), HOL_OK);
    assert_int_equal(st.n, 1);
    assert_int_equal(st.dir[0], HOL_DIR_N);
    assert_true(fabs(m.head[2] - 0.2) < 1e-9);
    assert_int_equal(m.user.row, 0);
    assert_same_room(&m.user, &st.after[0]);
    hol_room want = state_of("N");
    assert_same_room(&m.user, &want);
    /* pushing on into the hedge: nothing changes */
    assert_int_equal(hol_motion_move_to(&m, far_north, &st), HOL_OK);
    assert_int_equal(st.n, 0);
    assert_same_room(&m.user, &want);
    /* a grid line is never stood on */
    double on_line[3] = {1.0, 1.6, 1.0};
    assert_int_equal(hol_motion_move_to(&m, on_line, &st), HOL_OK);
    assert_true(m.head[0] != 1.0 && m.head[2] != 1.0);
    assert_true(m.head[0] > m.user.col && m.head[0] < m.user.col + 1);
    assert_true(m.head[2] > m.user.row && m.head[2] < m.user.row + 1);
}

/* Pancake: forward at yaw 0 goes north, yaw 90 goes west; turning rates;
 * speed; pitch limits; a NaN axis is no motion. */
static void test_pancake(void **state)
{
    (void)state;
    hol_motion m;
    hol_room start = hol_room_start();
    hol_motion_init(&m, &start, NULL);
    float fwd[2] = {0, 1}, none[2] = {0, 0}, left[2] = {1, 0}, up[2] = {0, 1};
    hol_motion_steps st;
    /* 0.5 s forward at 1.4 m/s: 0.7 m north, across z = 1 */
    assert_int_equal(hol_motion_pancake(&m, fwd, none, 0.5, &st), HOL_OK);
    assert_true(fabs(m.head[2] - (1.5 - 0.7)) < 1e-9);
    assert_true(fabs(m.head[0] - 1.5) < 1e-9);
    assert_int_equal(st.n, 1);
    assert_int_equal(st.dir[0], HOL_DIR_N);
    /* turn left (west) 90 degrees in 0.75 s at 120 deg/s, then walk */
    assert_int_equal(hol_motion_pancake(&m, none, left, 0.75, &st), HOL_OK);
    assert_true(fabs(m.yaw_deg - 90) < 1e-9);
    assert_int_equal(hol_motion_pancake(&m, fwd, none, 0.5, &st), HOL_OK);
    assert_true(fabs(m.head[0] - 0.8) < 1e-9);
    assert_int_equal(st.n, 1);
    assert_int_equal(st.dir[0], HOL_DIR_W);
    hol_room want = state_of("NW");
    assert_same_room(&m.user, &want);
    /* look up: held at 89 */
    assert_int_equal(hol_motion_pancake(&m, none, up, 10, &st), HOL_OK);
    assert_true(fabs(m.pitch_deg - 89) < 1e-9);
    float nan2[2] = {NAN, NAN};
    double head[3];
    memcpy(head, m.head, sizeof head);
    assert_int_equal(hol_motion_pancake(&m, nan2, nan2, 0.1, &st), HOL_OK);
    assert_memory_equal(head, m.head, sizeof head);
    assert_int_equal(hol_motion_pancake(&m, fwd, none, -1, &st), HOL_EARG);
    assert_int_equal(hol_motion_pancake(&m, fwd, none, INFINITY, &st), HOL_EARG);
}

/* Stereo: the state an eye sees from is the user's state walked along the
 * head-to-eye segment. */
static void test_eye_state(void **state)
{
    (void)state;
    hol_room u = state_of("NE"), got, want;
    double head[3] = {2.95, 1.6, 0.5};
    double same[3] = {2.9, 1.6, 0.45};
    assert_int_equal(hol_motion_eye_state(&u, head, same, &got), HOL_OK);
    assert_same_room(&got, &u);
    /* leaning south over the edge z = 1 */
    head[0] = 2.5;
    head[2] = 0.98;
    double south[3] = {2.5, 1.6, 1.02};
    assert_int_equal(hol_motion_eye_state(&u, head, south, &got), HOL_OK);
    want = u;
    assert_int_equal(hol_room_step(&want, HOL_DIR_S), HOL_OK);
    assert_same_room(&got, &want);
    /* across a corner: the segment crosses x = 2 first, then z = 1 */
    head[0] = 2.01;
    head[2] = 0.97;
    double diag[3] = {1.97, 1.6, 1.02};
    assert_int_equal(hol_motion_eye_state(&u, head, diag, &got), HOL_OK);
    want = u;
    assert_int_equal(hol_room_step(&want, HOL_DIR_W), HOL_OK);
    assert_int_equal(hol_room_step(&want, HOL_DIR_S), HOL_OK);
    assert_same_room(&got, &want);
    /* the eye state agrees with the reference walk on random segments */
    uint64_t s = 7;
    for (int k = 0; k < 500; k++) {
        hol_room r = state_of("NE");
        double h[3] = {r.col + 0.01 + 0.98 * rng_unit(&s), 1.6, r.row + 0.01 + 0.98 * rng_unit(&s)};
        double e[3] = {0.01 + 2.98 * rng_unit(&s), 1.6, 0.01 + 2.98 * rng_unit(&s)};
        hol_room ref = r;
        if (!reference_walk(&ref, h[0], h[2], e[0], e[2]))
            continue;
        assert_int_equal(hol_motion_eye_state(&r, h, e, &got), HOL_OK);
        assert_same_room(&got, &ref);
    }
    /* errors */
    double out_room[3] = {3.01, 1.6, 0.5};
    head[0] = 2.99;
    head[2] = 0.5;
    assert_int_equal(hol_motion_eye_state(&u, head, out_room, &got), HOL_EROOM);
    double bad_head[3] = {1.5, 1.6, 1.5};
    assert_int_equal(hol_motion_eye_state(&u, bad_head, same, &got), HOL_EARG);
}

/* Snap turn: each snap goes to the next multiple of the step in its
 * direction (the first aligns the look), and wraps into [0, 360). */
static void test_snap_yaw(void **state)
{
    (void)state;
    static const struct {
        double yaw, step;
        int turns;
        double want;
    } c[] = {
        {0, 90, 1, 90},        {0, 90, -1, 270},      {37.3, 90, 1, 90},   {37.3, 90, -1, 0},
        {90, 90, 1, 180},      {90, 90, -1, 0},       {270, 90, 1, 0},     {10, 90, 2, 180},
        {10, 90, -2, 270},     {89.9999999, 90, 1, 180}, {90.0000001, 90, -1, 0},
        {359.5, 45, 1, 0},     {359.5, 45, -1, 315},  {100, 30, 1, 120},   {100, 30, -1, 90},
        {180, 180, 1, 0},      {200, 180, -3, 180},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        double got = hol_motion_snap_yaw(c[i].yaw, c[i].step, c[i].turns);
        if (got != c[i].want)
            fail_msg("snap %g by %g x %d: %.9f, want %g", c[i].yaw, c[i].step, c[i].turns, got,
                     c[i].want);
    }
}

/* Rooms of other sizes (SPEC 7): the move area is C x R cells, a move
 * across the whole room crosses every inner grid line, the hedges clamp at
 * C and R, and the eye may lean anywhere in the room. */
static void test_room_sizes(void **state)
{
    (void)state;
    hol_room start;
    assert_int_equal(hol_room_start_in(6, 5, 4, &start), HOL_OK);
    hol_motion m;
    hol_motion_init(&m, &start, NULL);
    assert_true(m.head[0] > 2 && m.head[0] < 3 && m.head[2] > 2 && m.head[2] < 3);
    hol_motion_steps st;
    double west[3] = {0.5, 1.6, 2.5}, corner[3] = {0.5, 1.6, 0.5};
    assert_int_equal(hol_motion_move_to(&m, west, &st), HOL_OK);
    assert_int_equal(st.n, 2);
    assert_int_equal(m.user.col, 0);
    assert_int_equal(hol_motion_move_to(&m, corner, &st), HOL_OK);
    assert_int_equal(st.n, 2);
    assert_int_equal(m.user.row, 0);
    double far[3] = {10.0, 1.6, 10.0}; /* clamped to 5 and 4 less the margin */
    assert_int_equal(hol_motion_move_to(&m, far, &st), HOL_OK);
    assert_int_equal(st.n, 7); /* 4 x lines and 3 z lines: HOL_MOTION_MAX_STEPS fits them */
    assert_true(st.n <= HOL_MOTION_MAX_STEPS);
    assert_int_equal(m.user.col, 4);
    assert_int_equal(m.user.row, 3);
    assert_true(fabs(m.head[0] - (5 - 0.15)) < 1e-9 && fabs(m.head[2] - (4 - 0.15)) < 1e-9);
    hol_room eye;
    double head[3] = {4.5, 1.6, 3.5}, lean[3] = {3.5, 1.6, 3.5}, out[3] = {5.5, 1.6, 3.5};
    assert_int_equal(hol_motion_eye_state(&m.user, head, lean, &eye), HOL_OK);
    assert_int_equal(eye.col, 3);
    assert_int_equal(hol_motion_eye_state(&m.user, head, out, &eye), HOL_EROOM);
}

/* A re-place (recentre) takes no step: the tile stays, the cell is the
 * head's, the head where it was put (clamped); the room's north turns by
 * the quarter turns nearest to the change of look, checked against the
 * world: the step in the direction the user faces reaches the same tile
 * before and after, in {4,5} 3 x 3 and {4,6} 5 x 4. */
static void test_replace(void **state)
{
    (void)state;
    hol_room starts[2];
    starts[0] = state_of("ENSW");
    assert_int_equal(hol_room_start_in(6, 5, 4, &starts[1]), HOL_OK);
    static const double looks[][2] = {{0, 0},   {90, 0},   {100, 5},  {180, 0}, {0, 270},
                                      {350, 10}, {44, 0},  {46, 0},   {271, 1}, {135.5, 0}};
    for (int si = 0; si < 2; si++) {
        for (size_t k = 0; k < sizeof looks / sizeof looks[0]; k++) {
            hol_motion m;
            hol_motion_init(&m, &starts[si], NULL);
            m.yaw_deg = looks[k][1];
            hol_room was = m.user;
            double pos[3] = {1.5, 1.7, 2.5};
            hol_motion_replace(&m, pos, looks[k][0]);
            assert_true(hol_tile_eq(m.user.tile, was.tile));
            assert_int_equal(m.user.col, 1);
            assert_int_equal(m.user.row, 2);
            assert_int_equal(m.steps, 0);
            assert_true(m.head[0] == 1.5 && m.head[1] == 1.7 && m.head[2] == 2.5);
            /* the world direction faced: the room direction nearest the
             * look (N 0, W 1, S 2, E 3, as yaw turns west), stepped */
            int before = (int)floor(looks[k][0] / 90 + 0.5) & 3;
            int after = (int)floor(looks[k][1] / 90 + 0.5) & 3;
            double turn = (looks[k][0] - looks[k][1]) / 90;
            if (fabs(turn - floor(turn) - 0.5) < 0.1 ||
                fabs(looks[k][0] / 90 - floor(looks[k][0] / 90) - 0.5) < 0.1)
                continue; /* near 45 degrees: no nearest direction to compare */
            hol_room a = was, b = m.user;
            a.col = b.col = 1;
            a.row = b.row = 1;
            assert_int_equal(hol_room_step(&a, before), HOL_OK);
            assert_int_equal(hol_room_step(&b, after), HOL_OK);
            assert_true(hol_tile_eq(a.tile, b.tile));
        }
    }
    /* clamped like a move, off the grid lines */
    hol_motion m;
    hol_room r = hol_room_start();
    hol_motion_init(&m, &r, NULL);
    double far[3] = {-4, 1.6, 3.0};
    hol_motion_replace(&m, far, 0);
    assert_int_equal(m.user.col, 0);
    assert_int_equal(m.user.row, 2);
    assert_true(fabs(m.head[0] - 0.15) < 1e-9 && fabs(m.head[2] - 2.85) < 1e-9);
    assert_int_equal(m.user.orient, r.orient);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_snap_yaw),
        cmocka_unit_test(test_move_against_reference),
        cmocka_unit_test(test_hedges),
        cmocka_unit_test(test_pancake),
        cmocka_unit_test(test_eye_state),
        cmocka_unit_test(test_room_sizes),
        cmocka_unit_test(test_replace),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
