/* test_render_depth.c - the headset's panel is never drawn over geometry
 * nearer than itself (issue 36, item 2).
 *
 * A sweep of SWEEP positions and headings in the 3 x 3 room of 1 m cells
 * ({4,5}, from its start): the head at 1.6 m anywhere the motion lets it
 * stand (0.15 m from a hedge), looking anywhere; the app's panel placed for
 * it by core/hol_panel.h's rule (in front of the nearest hedge or trunk in
 * its direction, down to 0.5 m, the same angular size); both eyes 64 mm
 * apart drawn by the desktop renderer at 64 x 64 with the panel
 * (hol_app_frame_panel, as OpenXR and WebXR). The scene's depth is read
 * back from the frame drawn without the panel. Two checks, in both eyes:
 * - the placement: every pixel of the panel's box (hol_hud_panel_box: what
 *   a quad layer shows, composited over the scene without depth) has the
 *   panel's depth along its ray (the ray met with the panel's plane) at
 *   most the scene's there (1 cm of slack), wherever the rule is above its
 *   0.5 m floor (a hedge or trunk 0.55 m ahead or nearer: counted, and
 *   there the in-scene panel is hidden by it);
 * - the drawing: every pixel the panel changes in the scene, anywhere, has
 *   the panel's depth at most the scene's (it is never painted over nearer
 *   geometry).
 * The same sweep with the placement before the rule (no room given: 1.5 m
 * always) fails the first check in most positions (and, drawn without the
 * depth test as before, the second). With HOL_DEPTH_SHOT=FILE.png both
 * eyes near a hedge are written side by side (docs/headset.md).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_motion.h"
#include "../core/hol_panel.h"
#include "../render/hol_app_frame.h"
#include "../render/hol_gl.h"
#include "../render/hol_hud.h"
#include "../render/hol_view.h"
#include "../platform/image/hol_png_file.h"
#include "panel_view.h"
#include "render_fixture.h"

#define S 64 /* pixels a side, an eye */
#define SWEEP 1000
#define PI 3.14159265358979323846

static const char *const lines[] = {"Find the flag", "STEPS 3", "TIME 0:42"};
static const char *hint = "Trigger: the next level, B: this one again";

typedef struct sweep_out {
    int judged, floored, bad_pos, floor_bad;
    long panel_px, bad_px, bad_drawn;
} sweep_out;

/* a small LCG: the sweep is the same every run */
static double rnd01(uint64_t *s)
{
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* The view for a head at (x, 1.6, z) looking along yaw: the room's state
 * there (and at each eye) from its start; the panel placed by the rule when
 * room is set, else at 1.5 m (today's). */
static void place(hol_app_view *v, double x, double z, double yaw, int room)
{
    panel_view(v, HOL_MINIMAP_HUD, 0.064, lines, 3, hint);
    double start[3] = {v->head[0], v->head[1], v->head[2]};
    v->head[0] = x;
    v->head[2] = z;
    v->yaw_deg = yaw;
    double y = yaw * PI / 180;
    v->head_quat[1] = sin(y / 2);
    v->head_quat[3] = cos(y / 2);
    hol_room st = v->user;
    assert_int_equal(hol_motion_eye_state_m(&st, 1, start, v->head, &v->user), HOL_OK);
    for (int e = 0; e < 2; e++) {
        double s = (e ? 0.032 : -0.032);
        v->eye[e][0] = x + s * cos(y);
        v->eye[e][1] = v->head[1];
        v->eye[e][2] = z - s * sin(y);
        assert_int_equal(hol_motion_eye_state_m(&st, 1, start, v->eye[e], &v->eye_user[e]),
                         HOL_OK);
    }
    memset(&v->panel, 0, sizeof v->panel);
    if (room)
        hol_panel_room(&v->panel, 3, 3, 1);
    hol_panel_place(&v->panel, v->head, yaw, 0);
}

/* q's turn of a (x, y, z, w) */
static void turn(const double q[4], const double a[3], double out[3])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double t[3] = {2 * (y * a[2] - z * a[1]), 2 * (z * a[0] - x * a[2]), 2 * (x * a[1] - y * a[0])};
    out[0] = a[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = a[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = a[2] + w * t[2] + (x * t[1] - y * t[0]);
}

/* One eye: the pixels of the panel's box (what a quad layer shows over the
 * scene) whose panel depth exceeds the scene's; *npanel and *bad_drawn
 * count the panel pixels drawn in the scene and those of them behind it. */
static long eye_conflicts(render_fixture *fx, hol_gl *gl, const hol_app_view *v, int e,
                          long *npanel, long *bad_drawn)
{
    static uint8_t with[S * S * 4], without[S * S * 4];
    static float depth[S * S];
    hol_frame_desc fd;
    hol_app_frame_desc(v, e, S, S, 90, &fd);
    hol_app_frame_panel(v, &fd);
    render_fixture_draw(fx->rnd, &fd, S, S, with);
    hol_frame_desc bare = fd;
    bare.flags |= HOL_RENDER_NO_HUD;
    render_fixture_draw(fx->rnd, &bare, S, S, without);
    gl->ReadPixels(0, 0, S, S, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    double n = 0.05, f = 60, nrm[3], fwd[3] = {-sin(v->yaw_deg * PI / 180), 0,
                                                -cos(v->yaw_deg * PI / 180)};
    turn(v->panel.orient, (double[3]){0, 0, 1}, nrm);
    double box[4], ax[3], ay[3];
    hol_hud_panel_box((fd.flags & HOL_RENDER_MINIMAP) != 0, fd.panel_px, box);
    turn(v->panel.orient, (double[3]){1, 0, 0}, ax);
    turn(v->panel.orient, (double[3]){0, 1, 0}, ay);
    long bad = 0;
    for (int py = 0; py < S; py++)
        for (int px = 0; px < S; px++) {
            size_t i = (size_t)py * S + px;
            int drawn = memcmp(with + 4 * i, without + 4 * i, 3) != 0;
            double dir[3], num = 0, den = 0, lx = 0, ly = 0;
            hol_camera_ray(&fd.cam, (px + 0.5) / S * 2 - 1, 1 - (py + 0.5) / S * 2, dir);
            for (int k = 0; k < 3; k++) {
                num += nrm[k] * (v->panel.pos[k] - fd.cam.eye[k]);
                den += nrm[k] * dir[k];
            }
            double t = num / den, pz = 0;
            for (int k = 0; k < 3; k++) {
                double hit = fd.cam.eye[k] + t * dir[k] - v->panel.pos[k];
                pz += t * dir[k] * fwd[k];
                lx += hit * ax[k];
                ly += hit * ay[k];
            }
            int in_box = t > 0 && fabs(lx - box[2]) <= box[0] / 2 && fabs(ly - box[3]) <= box[1] / 2;
            double d = depth[(size_t)(S - 1 - py) * S + px] * 2 - 1;
            double sz = 2 * f * n / ((f + n) - d * (f - n));
            int behind = pz > sz + 0.01;
            *npanel += drawn;
            *bad_drawn += drawn && behind;
            bad += in_box && behind;
        }
    return bad;
}

static void sweep(int room, int count, sweep_out *o)
{
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, S, S, 7), 0);
    hol_gl gl;
    assert_int_equal(hol_gl_load(&gl, (hol_gl_getproc)hol_osmesa_getproc), HOL_OK);
    memset(o, 0, sizeof *o);
    uint64_t seed = 36;
    static hol_app_view v;
    for (int k = 0; k < count; k++) {
        double x = 0.15 + 2.7 * rnd01(&seed), z = 0.15 + 2.7 * rnd01(&seed);
        double yaw = 360 * rnd01(&seed) - 180;
        place(&v, x, z, yaw, room);
        hol_panel probe = v.panel;
        hol_panel_room(&probe, 3, 3, 1);
        double clear = hol_panel_clear_depth(&probe, v.head, yaw);
        int floor = room && clear < HOL_PANEL_NEAR_M + HOL_PANEL_CLEAR_M;
        long bad = 0;
        for (int e = 0; e < 2; e++)
            bad += eye_conflicts(&fx, &gl, &v, e, &o->panel_px, &o->bad_drawn);
        if (floor) {
            o->floored++;
            o->floor_bad += bad > 0;
            continue;
        }
        o->judged++;
        o->bad_px += bad;
        o->bad_pos += bad > 0;
    }
    render_fixture_destroy(&fx);
}

static void test_panel_in_front(void **state)
{
    (void)state;
    sweep_out o;
    sweep(1, SWEEP, &o);
    printf("rule: %d positions judged, %d at the 0.5 m floor (%d of them with the scene over "
           "part of the box), %ld panel pixels drawn, %ld box pixels behind the scene, %ld drawn "
           "pixels behind it\n",
           o.judged, o.floored, o.floor_bad, o.panel_px, o.bad_px, o.bad_drawn);
    assert_true(o.judged + o.floored == SWEEP);
    assert_true(o.judged * 2 > SWEEP);
    assert_true(o.panel_px > (long)SWEEP * 2 * 50); /* the panel was drawn */
    assert_int_equal(o.bad_px, 0);    /* the rule: its whole box in front */
    assert_int_equal(o.bad_drawn, 0); /* the drawing: never over nearer geometry */
}

/* Today's placement (1.5 m always): its box is behind a hedge or a trunk in
 * most positions (a quad layer or the panel drawn over everything shows
 * it there). */
static void test_fixed_distance_fails(void **state)
{
    (void)state;
    sweep_out o;
    sweep(0, SWEEP / 5, &o);
    printf("at 1.5 m always: %d of %d positions with box pixels behind the scene (%ld px)\n",
           o.bad_pos, o.judged, o.bad_px);
    assert_true(o.bad_pos * 2 > o.judged); /* half and more */
}

/* HOL_DEPTH_SHOT=FILE.png: both eyes (400 px each, side by side) 0.9 m
 * from the north hedge looking at it, the panel in front of it (the
 * screenshot in docs/headset.md); else nothing. */
static void test_shot(void **state)
{
    (void)state;
    const char *path = getenv("HOL_DEPTH_SHOT");
    if (!path || !path[0])
        return;
    enum { W = 400, GAP = 8 };
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, W, W, 7), 0);
    static hol_app_view v;
    place(&v, 1.5, 0.9, 0, 1);
    uint8_t *eye = malloc((size_t)W * W * 4), *both = calloc((size_t)(2 * W + GAP) * W * 4, 1);
    assert_non_null(eye);
    assert_non_null(both);
    for (int e = 0; e < 2; e++) {
        hol_frame_desc fd;
        hol_app_frame_desc(&v, e, W, W, 90, &fd);
        hol_app_frame_panel(&v, &fd);
        render_fixture_draw(fx.rnd, &fd, W, W, eye);
        for (int y = 0; y < W; y++)
            memcpy(both + 4 * ((size_t)y * (2 * W + GAP) + (size_t)e * (W + GAP)),
                   eye + 4 * (size_t)y * W, 4 * (size_t)W);
    }
    for (size_t i = 0; i < (size_t)(2 * W + GAP) * W; i++)
        both[4 * i + 3] = 255;
    assert_int_equal(hol_png_write_file(path, both, 2 * W + GAP, W, 0), HOL_OK);
    printf("the panel %.3f m ahead (scale %.3f)\n", v.panel.dist, v.panel.scale);
    free(eye);
    free(both);
    render_fixture_destroy(&fx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_panel_in_front),
        cmocka_unit_test(test_fixed_distance_fails),
        cmocka_unit_test(test_shot),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
