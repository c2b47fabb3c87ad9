/* test_xr_quad.c - the world panel as an OpenXR quad layer
 * (platform/openxr/hol_xr_quad.h), without a runtime: the quad's pose and
 * size from the panel core places, against an independent model (the
 * panel's axes from its yaw and drop as plain vectors, the stage from the
 * calibration as a matrix; the in-scene panel's corner as the renderer
 * lays it out), and the redraw-on-change rule. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_panel.h"
#include "../platform/shell/hol_xr_quad.h"
#include "quat_model.h"

#define PI 3.14159265358979323846
#define PX 0.0043 /* HOL_RENDER_PANEL_PX */

/* room -> stage of a calibration (model: a yaw matrix about +y) */
static void to_stage(const hol_xr_calib *c, const double room[3], double out[3])
{
    double hw = c->half_w > 0 ? c->half_w : 1.5, hd = c->half_d > 0 ? c->half_d : 1.5;
    double x = room[0] - hw, z = room[2] - hd, cy = cos(c->yaw), sy = sin(c->yaw);
    out[0] = cy * x + sy * z + c->ox;
    out[1] = room[1];
    out[2] = -sy * x + cy * z + c->oz;
}

/* The panel's corners against the model: the in-scene text block's top
 * left corner (renderer: left = -wide / 2, top = HOL_HUD_PANEL_MAP / 2 font
 * pixels from the panel's centre, along its right and up axes) is the
 * quad's top left, and its right and up axes are the panel's. */
static void check_place(const hol_xr_calib *c, double yaw_deg, int map, const float *shift)
{
    hol_panel p;
    memset(&p, 0, sizeof p);
    const double head[3] = {1.2, 1.65, 1.7};
    hol_panel_place(&p, head, yaw_deg, 0);
    hol_xr_quad q;
    hol_xr_quad_place(c, p.pos, p.orient, map, 0, shift, &q);
    double wide = map ? 136 + 6 + 64 : 136;
    assert_true(fabs(q.size[0] - wide * PX) < 1e-6);
    assert_true(fabs(q.size[1] - 93 * PX) < 1e-6);
    assert_int_equal(q.rect[0], (int)wide * HOL_XR_QUAD_TEXELS);
    assert_int_equal(q.rect[1], 93 * HOL_XR_QUAD_TEXELS);
    /* the model's axes: yaw y, drop a (10 degrees): right (cos y, 0,
     * -sin y); the face looks up at the eyes, up tilted back */
    double y = yaw_deg * PI / 180, a = 10 * PI / 180;
    double right[3] = {cos(y), 0, -sin(y)};
    double up[3] = {-sin(y) * sin(a), cos(a), -cos(y) * sin(a)};
    double corner_room[3];
    for (int k = 0; k < 3; k++)
        corner_room[k] = p.pos[k] + right[k] * (-wide / 2 * PX) + up[k] * (32 * PX) -
                         (shift ? shift[k] : 0);
    double corner[3];
    to_stage(c, corner_room, corner);
    /* the quad's own top left corner and axes, from its pose */
    const double l[3] = {-q.size[0] / 2, q.size[1] / 2, 0}, ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0};
    double d[3], qr[3], qu[3];
    quat_model_rotate(q.quat, l, d);
    quat_model_rotate(q.quat, ex, qr);
    quat_model_rotate(q.quat, ey, qu);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(q.pos[k] + d[k] - corner[k]) < 1e-5);
    /* the panel's axes carried into the stage: differences of points */
    const double base[3] = {1.5, 0, 1.5};
    double rr[3], uu[3], sr[3], su[3], s0[3];
    for (int k = 0; k < 3; k++) {
        rr[k] = base[k] + right[k];
        uu[k] = base[k] + up[k];
    }
    to_stage(c, rr, sr);
    to_stage(c, uu, su);
    to_stage(c, base, s0);
    for (int k = 0; k < 3; k++) {
        assert_true(fabs(qr[k] - (sr[k] - s0[k])) < 1e-5);
        assert_true(fabs(qu[k] - (su[k] - s0[k])) < 1e-5);
    }
    assert_true(fabs(hypot(hypot(q.quat[0], q.quat[1]), hypot(q.quat[2], q.quat[3])) - 1) < 1e-5);
}

static void test_place(void **state)
{
    (void)state;
    hol_xr_calib c0;
    memset(&c0, 0, sizeof c0);
    hol_xr_calib c1 = {0.3, 0.2, -0.1, 1.2, 1.8};
    const float shift[3] = {0.05f, -0.02f, 0.4f};
    for (int map = 0; map < 2; map++)
        for (double yaw = -170; yaw <= 180; yaw += 35) {
            check_place(&c0, yaw, map, NULL);
            check_place(&c1, yaw, map, NULL);
            check_place(&c1, yaw, map, shift);
        }
}

/* The default: the 3 x 3 m room on the stage origin, yaw 0: the quad
 * faces the head (its +z towards it), below eye level. */
static void test_place_default(void **state)
{
    (void)state;
    hol_panel p;
    memset(&p, 0, sizeof p);
    const double head[3] = {1.5, 1.6, 1.5};
    hol_panel_place(&p, head, 0, 0);
    hol_xr_calib c;
    memset(&c, 0, sizeof c);
    hol_xr_quad q;
    hol_xr_quad_place(&c, p.pos, p.orient, 0, 0, NULL, &q);
    assert_true(fabs(q.pos[0]) < 1e-6);
    assert_true(q.pos[2] < -1.3 && q.pos[2] > -1.6); /* north: stage -z */
    assert_true(q.pos[1] < 1.6);
    const double ez[3] = {0, 0, 1};
    double n[3];
    quat_model_rotate(q.quat, ez, n);
    assert_true(n[2] > 0.9 && n[1] > 0.1); /* towards the head, up at the eyes */
}

/* The image holds the widest box; every rectangle used fits it. */
static void test_image(void **state)
{
    (void)state;
    int w = 0, h = 0;
    hol_xr_quad_image(&w, &h);
    assert_int_equal(w, (136 + 6 + 64) * HOL_XR_QUAD_TEXELS);
    assert_int_equal(h, 93 * HOL_XR_QUAD_TEXELS);
    hol_panel p;
    memset(&p, 0, sizeof p);
    const double head[3] = {1.5, 1.6, 1.5};
    hol_panel_place(&p, head, 40, 0);
    hol_xr_calib c;
    memset(&c, 0, sizeof c);
    for (int map = 0; map < 2; map++) {
        hol_xr_quad q;
        hol_xr_quad_place(&c, p.pos, p.orient, map, 0, NULL, &q);
        assert_true(q.rect[0] > 0 && q.rect[0] <= w && q.rect[1] > 0 && q.rect[1] <= h);
        /* texels per metre the same both ways: square texels */
        assert_true(fabs(q.rect[0] / q.size[0] - q.rect[1] / q.size[1]) < 1e-3 * q.rect[0]);
    }
}

/* Redraw on change: the first time, then only when the key changes. */
static void test_stale(void **state)
{
    (void)state;
    hol_xr_quad_cache c;
    memset(&c, 0, sizeof c);
    assert_int_equal(hol_xr_quad_stale(&c, 0), 1); /* never drawn: even key 0 */
    assert_int_equal(hol_xr_quad_stale(&c, 0), 0);
    for (int i = 0; i < 100; i++)
        assert_int_equal(hol_xr_quad_stale(&c, 0), 0);
    assert_int_equal(hol_xr_quad_stale(&c, 42), 1);
    assert_int_equal(hol_xr_quad_stale(&c, 42), 0);
    assert_int_equal(hol_xr_quad_stale(&c, 0), 1); /* back: drawn again */
    assert_int_equal(c.redraws, 3);
    hol_xr_quad_forget(&c); /* a new swapchain */
    assert_int_equal(hol_xr_quad_stale(&c, 0), 1);
    assert_int_equal(hol_xr_quad_stale(&c, 0), 0);
    assert_int_equal(c.redraws, 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_place),
        cmocka_unit_test(test_place_default),
        cmocka_unit_test(test_image),
        cmocka_unit_test(test_stale),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
