/* test_panel.c - the headset UI panel's place and its lazy follow
 * (core/hol_panel.h), against plain trigonometry written here: 1.5 m
 * ahead along the anchor's yaw, 10 degrees below eye level, facing the
 * eyes; it stays while the head turns up to 20 degrees or moves up to
 * 0.5 m, re-centres (easing, not in one frame) beyond, and then stops. The
 * app step drives it: a level start places it before the head. In a room
 * it comes in front of the nearest hedge or trunk ahead, down to 0.5 m,
 * scaled alike (the distances worked out by hand here).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_nav.h"
#include "../core/hol_panel.h"

#define PI 3.14159265358979323846

static double g_dist = 1.5; /* the distance the panel must stand at */

/* where the panel must stand for a head at h looking along yaw (degrees) */
static void expect_place(const double h[3], double yaw, double out[3])
{
    double y = yaw * PI / 180, d = 10 * PI / 180;
    out[0] = h[0] - g_dist * cos(d) * sin(y);
    out[1] = h[1] - g_dist * sin(d);
    out[2] = h[2] - g_dist * cos(d) * cos(y);
}

/* v turned by the unit quaternion q (x, y, z, w) */
static void turn(const double q[4], const double v[3], double out[3])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double t[3] = {2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]),
                   2 * (x * v[1] - y * v[0])};
    out[0] = v[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = v[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = v[2] + w * t[2] + (x * t[1] - y * t[0]);
}

static void assert_at(const hol_panel *p, const double h[3], double yaw)
{
    double e[3];
    expect_place(h, yaw, e);
    for (int i = 0; i < 3; i++)
        assert_true(fabs(p->pos[i] - e[i]) < 1e-9);
    /* its face (+z unturned) looks straight at the head, its up (+y) has no
     * sideways part, its right (+x) is level */
    static const double ez[3] = {0, 0, 1}, ex[3] = {1, 0, 0};
    double n[3], r[3], to[3], len = 0;
    turn(p->orient, ez, n);
    turn(p->orient, ex, r);
    for (int i = 0; i < 3; i++) {
        to[i] = h[i] - p->pos[i];
        len += to[i] * to[i];
    }
    len = sqrt(len);
    assert_true(fabs(len - g_dist) < 1e-9);
    assert_true(fabs(p->scale - g_dist / 1.5) < 1e-12);
    for (int i = 0; i < 3; i++)
        assert_true(fabs(n[i] - to[i] / len) < 1e-9);
    assert_true(fabs(r[1]) < 1e-9);
}

static void test_place(void **state)
{
    (void)state;
    hol_panel p;
    memset(&p, 0, sizeof p);
    double h[3] = {1.5, 1.6, 1.5};
    hol_panel_follow(&p, h, 0, 0); /* the first update places it */
    assert_int_equal(p.placed, 1);
    assert_int_equal(p.moving, 0);
    assert_at(&p, h, 0);
    double h2[3] = {0.7, 1.5, 2.2};
    for (int a = -180; a < 180; a += 15) {
        hol_panel_place(&p, h2, a, 1);
        assert_at(&p, h2, a);
    }
    /* the central 20 degrees: the panel's centre is 10 degrees below the
     * horizon of its anchor */
    hol_panel_place(&p, h, 0, 1);
    double down = atan2(h[1] - p.pos[1], h[2] - p.pos[2]) * 180 / PI;
    assert_true(fabs(down - 10) < 1e-9);
}

static void test_lazy(void **state)
{
    (void)state;
    hol_panel p;
    memset(&p, 0, sizeof p);
    double h[3] = {1.5, 1.6, 1.5};
    hol_panel_follow(&p, h, 0, 0);
    int placed = p.recentres;
    /* turning up to 20 degrees and moving up to 0.5 m: it stays */
    double t = 0;
    for (int i = 0; i <= 19; i++) {
        double hh[3] = {1.5 + 0.02 * i, 1.6, 1.5 - 0.01 * i};
        hol_panel_follow(&p, hh, i, t += 1.0 / 72);
        assert_int_equal(p.moving, 0);
        assert_at(&p, h, 0);
    }
    hol_panel_follow(&p, h, -19.9, t += 1.0 / 72);
    assert_at(&p, h, 0);
    assert_int_equal(p.recentres, placed);
    /* 30 degrees: it re-centres, easing (not at once), and stops */
    hol_panel_follow(&p, h, 30, t += 1.0 / 72);
    assert_int_equal(p.moving, 1);
    assert_int_equal(p.recentres, placed + 1);
    assert_true(p.yaw_deg > 0 && p.yaw_deg < 30);
    double prev = p.yaw_deg;
    int frames = 1;
    while (p.moving && frames < 1000) {
        hol_panel_follow(&p, h, 30, t += 1.0 / 72);
        assert_true(p.yaw_deg >= prev && p.yaw_deg <= 30); /* never overshoots */
        prev = p.yaw_deg;
        frames++;
    }
    assert_int_equal(p.moving, 0);
    assert_true(frames > 10 && frames < 72); /* a glide under a second */
    assert_at(&p, h, 30);
    assert_int_equal(p.recentres, placed + 1);
    /* across +-180 it turns the short way */
    hol_panel_place(&p, h, 170, t);
    hol_panel_follow(&p, h, -160, t += 1.0 / 72);
    assert_int_equal(p.moving, 1);
    assert_true(p.yaw_deg > 170 || p.yaw_deg < -160);
    /* a move of more than 0.5 m re-centres too */
    hol_panel_place(&p, h, 0, t);
    double far[3] = {2.1, 1.6, 1.5};
    hol_panel_follow(&p, far, 0, t += 1.0 / 72);
    assert_int_equal(p.moving, 1);
    for (int i = 0; i < 200; i++)
        hol_panel_follow(&p, far, 0, t += 1.0 / 72);
    assert_int_equal(p.moving, 0);
    assert_at(&p, far, 0);
    /* a frame 5 s after the last (a stall) glides: the bounded catch-up
     * moves it part of the way, never all of it, then on to the head */
    double y0 = p.yaw_deg;
    hol_panel_follow(&p, h, 90, t += 5);
    assert_int_equal(p.moving, 1);
    assert_true(p.yaw_deg > y0 + 20 && p.yaw_deg < y0 + 60);
    frames = 0;
    while (p.moving && frames < 200) {
        double was = p.yaw_deg;
        hol_panel_follow(&p, h, 90, t += 1.0 / 72);
        assert_true(p.yaw_deg >= was && p.yaw_deg <= 90); /* no overshoot */
        frames++;
    }
    assert_true(frames > 10 && frames < 72);
    assert_at(&p, h, 90);
    /* time going backwards (a new session) places it at once */
    hol_panel_follow(&p, h, 0, t - 1);
    assert_int_equal(p.moving, 0);
    assert_at(&p, h, 0);
}

/* a tracked head at (x, 1.6, z) turned yaw degrees */
static hol_input head_at(double t, double x, double z, double yaw)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
    in.head.pos[0] = (float)x;
    in.head.pos[1] = 1.6f;
    in.head.pos[2] = (float)z;
    in.head.quat[1] = (float)sin(yaw * PI / 360);
    in.head.quat[3] = (float)cos(yaw * PI / 360);
    return in;
}

/* The app step drives it from the tracked head: placed at the level's
 * start, kept through a small turn, re-centred after a large one. */
static void test_app_drives_it(void **state)
{
    (void)state;
    hol_nav *nav = NULL;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    assert_int_equal(hol_nav_create(&nd, &nav), HOL_OK);
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = nav;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.seed = 9;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    double t = 0;
    hol_input in = head_at(t, 1.5, 1.5, 0);
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->panel.placed, 1);
    /* the middle of the 3 x 3 room looking north: the trunks at (1, 0) and
     * (2, 0) stand 18.43 degrees aside, just beyond the 18 degrees looked
     * along: the edge ray meets the trunk (radius 0.12) at t; 5 cm before
     * that depth, 10 degrees down */
    double e18 = 18 * PI / 180, cx = 0.5, cz = 1.5, c2 = cx * cx + cz * cz;
    double b = cx * sin(e18) + cz * cos(e18);
    double t18 = b - sqrt(0.12 * 0.12 - (c2 - b * b));
    g_dist = (t18 * cos(e18) - 0.05) / cos(10 * PI / 180);
    assert_at(&v->panel, v->head, 0);
    double h0[3] = {v->head[0], v->head[1], v->head[2]};
    for (int f = 1; f <= 30; f++) { /* a 15 degree look aside */
        in = head_at(t += 1.0 / 72, 1.5, 1.5, 15);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        assert_int_equal(v->panel.moving, 0);
    }
    assert_at(&v->panel, h0, 0);
    for (int f = 1; f <= 72; f++) { /* a 40 degree turn, held a second */
        in = head_at(t += 1.0 / 72, 1.5, 1.5, 40);
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        if (f == 1)
            assert_int_equal(v->panel.moving, 1);
    }
    assert_int_equal(v->panel.moving, 0);
    assert_true(fabs(v->yaw_deg - 40) < 1e-3);
    g_dist = v->panel.dist; /* the rule's own: test_room has it */
    assert_true(g_dist >= 0.5 && g_dist <= 1.5);
    assert_at(&v->panel, v->head, v->panel.yaw_deg);
    assert_true(fabs(v->panel.yaw_deg - v->yaw_deg) < 0.5);
    g_dist = 1.5;
    hol_app_destroy(app);
    hol_nav_destroy(nav);
}

/* In front of the nearest hedge or trunk, down to 0.5 m, the same angular
 * size; outside the room or without one, 1.5 m. */
static void test_room(void **state)
{
    (void)state;
    hol_panel p;
    memset(&p, 0, sizeof p);
    hol_panel_room(&p, 3, 3, 1);
    double far[3] = {1.5, 1.6, 2.2}, near[3] = {1.5, 1.6, 0.7}, wall[3] = {1.5, 1.6, 0.4};
    /* looking south from z 2.2: the hedge at z 3 is 0.8 m ahead, the
     * trunks at (1, 3) and (2, 3) 32 degrees aside (beyond 18 + 8.6) */
    hol_panel_place(&p, far, 180, 0);
    g_dist = (0.8 - 0.05) / cos(10 * PI / 180);
    assert_at(&p, far, 180);
    /* north from z 0.7: the hedge 0.7 m ahead, the trunks at (1, 0) and
     * (2, 0) 35.5 degrees aside (their edge rays pass 0.27 m off them) */
    hol_panel_place(&p, near, 0, 0);
    g_dist = (0.7 - 0.05) / cos(10 * PI / 180);
    assert_at(&p, near, 0);
    assert_false(p.covered);
    hol_panel_place(&p, wall, 0, 0); /* 0.4 m from the hedge: the floor */
    g_dist = 0.5;
    assert_at(&p, wall, 0);
    assert_true(p.covered); /* a quad layer would show over the hedge */
    double out[3] = {1.5, 1.6, -0.5}; /* outside the room: as ever */
    hol_panel_place(&p, out, 0, 0);
    g_dist = 1.5;
    assert_at(&p, out, 0);
    hol_panel_room(&p, 0, 0, 0); /* no room: as ever */
    hol_panel_place(&p, near, 0, 0);
    assert_at(&p, near, 0);
    /* a trunk straight ahead: (1, 1) from (1, 1.6 m, 1.7), 0.7 - 0.12 */
    hol_panel_room(&p, 3, 3, 1);
    double tr[3] = {1, 1.6, 1.7};
    hol_panel_place(&p, tr, 0, 0);
    g_dist = (0.7 - 0.12 - 0.05) / cos(10 * PI / 180);
    assert_at(&p, tr, 0);
    assert_false(p.covered);
    double touch[3] = {1, 1.6, 1.3}; /* 0.18 m from the trunk's bark */
    hol_panel_place(&p, touch, 0, 0);
    g_dist = 0.5;
    assert_at(&p, touch, 0);
    assert_true(p.covered);
    hol_panel_place(&p, tr, 0, 0); /* back: uncovered */
    assert_false(p.covered);
    g_dist = 1.5;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_place),
        cmocka_unit_test(test_lazy),
        cmocka_unit_test(test_app_drives_it),
        cmocka_unit_test(test_room),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
