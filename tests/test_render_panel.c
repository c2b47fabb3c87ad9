/* test_render_panel.c - the headset's UI panel in true stereo.
 *
 * A stereo pair as a headset draws it: two eyes 64 mm apart, each frame
 * described by hol_app_frame_desc for its eye and put on the world panel by
 * hol_app_frame_panel (what OpenXR and WebXR do), the panel where the app's
 * lazy follower placed it (core/hol_panel.h). The panel's pixels are those
 * that change when the HUD is drawn (the same frame with
 * HOL_RENDER_NO_HUD is the reference). Against an independent pinhole model
 * written here (the panel's rectangle from its documented layout: 1.5 m
 * ahead, 10 degrees down, facing the eyes, 4.3 mm a font pixel, a text block
 * 136 font pixels wide, 9 a line + 4, the map 64 a side 6 to its right, the
 * tops level), in each eye:
 * - the text block's edges lie where its corners project, within 1 px;
 * - its horizontal offset between the eyes is the one its depth predicts
 *   (about 10 px here), within 1 px, and so is the map's;
 * - every panel pixel lies within 20 degrees of the eye's axis both ways;
 * - a capital is at least 1 degree high; a line longer than the block
 *   wraps (nothing is cut off).
 * The same checks on the screen-space HUD (the same frames without the
 * panel: what the headsets drew before) fail: no disparity, in the corners.
 * With HOL_PANEL_SHOT=FILE.png the pair is written side by side (the
 * screenshot in docs/headset.md).
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
#include "../platform/image/hol_png_file.h"
#include "../render/hol_app_frame.h"
#include "panel_view.h"
#include "../core/hol_face.h"
#include "render_fixture.h"

static int W = 480, H = 480; /* HOL_PANEL_SIZE=N: N x N an eye */
#define PI 3.14159265358979323846
#define FOCAL (H / 2.0) /* 90 degrees vertical, square pixels */
#define PX 0.0043

typedef struct box {
    int x0, y0, x1, y1; /* pixels, inclusive; x0 > x1: empty */
    long n;
} box;

typedef struct eye_shot {
    uint8_t *img;   /* with the HUD */
    uint8_t *mask;  /* 1 where the HUD changed the picture */
    box all, text, map;
} eye_shot;

static const char *const lines[] = {"Find the flag", "STEPS 3", "TIME 0:42"};
static const char *hint = "Trigger: the next level, B: this one again";

/* The shared view (tests/panel_view.h), the eyes 64 mm apart, and a flag
 * two tiles ahead, on the map and in the world, with its cues. */
static void make_view(hol_app_view *v, int map_place)
{
    panel_view(v, map_place, 0.064, lines, 3, hint);
    v->objects[0].tile = v->map.objectives[0];
    v->objects[0].kind = HOL_APP_OBJ_FLAG;
    v->nobjects = 1;
    v->map.cues = HOL_CUE_POLES | HOL_CUE_HOT_COLD;
}

static void bound(box *b, int x, int y)
{
    if (b->n++ == 0) {
        b->x0 = b->x1 = x;
        b->y0 = b->y1 = y;
        return;
    }
    b->x0 = x < b->x0 ? x : b->x0;
    b->x1 = x > b->x1 ? x : b->x1;
    b->y0 = y < b->y0 ? y : b->y0;
    b->y1 = y > b->y1 ? y : b->y1;
}

/* One eye with and without its HUD; the mask, its box, and the text block
 * and map split at the first empty column after the text starts. */
static void shoot(render_fixture *fx, const hol_app_view *v, int e, int panel, eye_shot *s)
{
    hol_frame_desc fd;
    hol_app_frame_desc(v, e, W, H, 90, &fd);
    if (panel)
        hol_app_frame_panel(v, &fd);
    uint8_t *ref = malloc((size_t)W * H * 4);
    s->img = malloc((size_t)W * H * 4);
    s->mask = calloc((size_t)W * H, 1);
    assert_non_null(ref);
    assert_non_null(s->img);
    assert_non_null(s->mask);
    render_fixture_draw_hud(fx->rnd, &fd, W, H, s->img, ref);
    memset(&s->all, 0, sizeof s->all);
    int *cols = calloc(W, sizeof *cols);
    assert_non_null(cols);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t i = (size_t)y * W + x;
            if (memcmp(s->img + 4 * i, ref + 4 * i, 3) != 0) {
                s->mask[i] = 1;
                bound(&s->all, x, y);
                cols[x]++;
            }
        }
    int split = W;
    for (int x = s->all.x0; s->all.n && x <= s->all.x1; x++)
        if (!cols[x]) {
            split = x;
            break;
        }
    memset(&s->text, 0, sizeof s->text);
    memset(&s->map, 0, sizeof s->map);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (s->mask[(size_t)y * W + x])
                bound(x < split ? &s->text : &s->map, x, y);
    free(cols);
    free(ref);
}

/* The independent model: a point of the panel's plane (font pixels from its
 * centre, x right, y up) in the room, for a panel placed for head h at yaw
 * 0: 1.5 m ahead (-z), 10 degrees down, facing the head. */
static void panel_point(const double h[3], double u, double w, double out[3])
{
    double d = 10 * PI / 180;
    double c[3] = {h[0], h[1] - 1.5 * sin(d), h[2] - 1.5 * cos(d)};
    double up[3] = {0, cos(d), -sin(d)}; /* tilted back: its top farther */
    out[0] = c[0] + u * PX;
    out[1] = c[1] + w * PX * up[1];
    out[2] = c[2] + w * PX * up[2];
}

/* pinhole projection for an eye at e looking north (-z): pixel x from the
 * left, y from the top (continuous; pixel i spans [i, i + 1]) */
static void project(const double e[3], const double p[3], double *x, double *y)
{
    double z = e[2] - p[2];
    *x = W / 2.0 + FOCAL * (p[0] - e[0]) / z;
    *y = H / 2.0 - FOCAL * (p[1] - e[1]) / z;
}

/* the projected bounding box of a rectangle of the panel (font pixels) */
static void predict(const hol_app_view *v, int e, double u0, double u1, double w0, double w1,
                    double out[4])
{
    out[0] = out[1] = 1e9;
    out[2] = out[3] = -1e9;
    for (int k = 0; k < 4; k++) {
        double p[3], x, y;
        panel_point(v->head, k & 1 ? u1 : u0, k & 2 ? w1 : w0, p);
        project(v->eye[e], p, &x, &y);
        out[0] = x < out[0] ? x : out[0];
        out[1] = y < out[1] ? y : out[1];
        out[2] = x > out[2] ? x : out[2];
        out[3] = y > out[3] ? y : out[3];
    }
}

/* every pixel of the mask within deg degrees of the axis, both ways */
static int central(const eye_shot *s, double deg)
{
    double lim = FOCAL * tan(deg * PI / 180);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (s->mask[(size_t)y * W + x] &&
                (fabs(x + 0.5 - W / 2.0) > lim || fabs(y + 0.5 - H / 2.0) > lim))
                return 0;
    return 1;
}

/* The text block's rectangle in font pixels: map beside it or not, n lines. */
static void text_rect(int map, int n, double r[4])
{
    /* a line of the text face at a cap height of 7 font pixels */
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    double lh = (double)(m.ascent - m.descent) / m.units_per_em * 7 * hol_face_em_per_cap();
    double wide = 136 + (map ? 6 + 64 : 0);
    r[0] = -wide / 2;
    r[1] = -wide / 2 + 136;
    r[2] = 32 - (lh * n + 4);
    r[3] = 32;
}

static int near1(double a, double b)
{
    return fabs(a - b) <= 1.0;
}

/* The checks of the panel on a pair; returns the number that failed (and
 * says which unless quiet). */
static int check_pair(const hol_app_view *v, eye_shot s[2], int map, int nlines, int quiet)
{
    int bad = 0;
    double r[4];
    text_rect(map, nlines, r);
    double pt[2][4], pm[2][4];
    for (int e = 0; e < 2; e++) {
        predict(v, e, r[0], r[1], r[2], r[3], pt[e]);
        double mx0 = r[1] + 6, half = 32;
        predict(v, e, mx0, mx0 + 2 * half, -half, half, pm[e]);
        const box *t = &s[e].text;
        /* the text block's edges where its corners project */
        if (!t->n || !near1(t->x0, pt[e][0]) || !near1(t->x1 + 1, pt[e][2]) ||
            !near1(t->y0, pt[e][1]) || !near1(t->y1 + 1, pt[e][3])) {
            bad++;
            if (!quiet)
                print_error("eye %d text block [%d %d %d %d], predicted [%.1f %.1f %.1f %.1f]\n", e,
                            t->x0, t->y0, t->x1 + 1, t->y1 + 1, pt[e][0], pt[e][1], pt[e][2],
                            pt[e][3]);
        }
        if (!central(&s[e], 20)) {
            bad++;
            if (!quiet)
                print_error("eye %d: panel pixels outside the central 20 degrees\n", e);
        }
    }
    /* the offset between the eyes: the one the depth predicts */
    double dl = s[0].text.x0 - s[1].text.x0, dr = s[0].text.x1 - s[1].text.x1;
    double want = pt[0][0] - pt[1][0];
    if (!(want > 5) || !near1(dl, want) || !near1(dr, pt[0][2] - pt[1][2])) {
        bad++;
        if (!quiet)
            print_error("text disparity %.0f / %.0f px, predicted %.2f\n", dl, dr, want);
    }
    if (map) {
        /* the map is a disk inside its square: its centre's offset */
        double cl = (s[0].map.x0 + s[0].map.x1 + 1) / 2.0, cr = (s[1].map.x0 + s[1].map.x1 + 1) / 2.0;
        double wm = (pm[0][0] + pm[0][2]) / 2 - (pm[1][0] + pm[1][2]) / 2;
        if (!s[0].map.n || !s[1].map.n || !near1(cl - cr, wm)) {
            bad++;
            if (!quiet)
                print_error("map disparity %.1f px, predicted %.2f\n", cl - cr, wm);
        }
    }
    return bad;
}

static void shot_png(eye_shot s[2])
{
    const char *path = getenv("HOL_PANEL_SHOT");
    if (!path || !path[0])
        return;
    int gap = 8, fw = 2 * W + gap;
    uint8_t *both = calloc((size_t)fw * H * 4, 1);
    assert_non_null(both);
    for (int y = 0; y < H; y++)
        for (int e = 0; e < 2; e++)
            memcpy(both + 4 * ((size_t)y * fw + (size_t)e * (W + gap)),
                   s[e].img + 4 * (size_t)y * W, 4 * (size_t)W);
    for (size_t i = 0; i < (size_t)fw * H; i++)
        both[4 * i + 3] = 255;
    assert_int_equal(hol_png_write_file(path, both, fw, H, 0), HOL_OK);
    free(both);
}

/* The panel's cost in one eye: draws and triangles over the same frame
 * without it. */
static void panel_cost(render_fixture *fx, const hol_app_view *v, int *draws, long *tris)
{
    hol_frame_desc fd;
    hol_app_frame_desc(v, 0, W, H, 90, &fd);
    hol_app_frame_panel(v, &fd);
    hol_render_stats with, without;
    assert_int_equal(hol_render_frame(fx->rnd, &fd, &with), HOL_OK);
    fd.flags |= HOL_RENDER_NO_HUD;
    assert_int_equal(hol_render_frame(fx->rnd, &fd, &without), HOL_OK);
    *draws = with.draw_calls - without.draw_calls;
    *tris = with.triangles - without.triangles;
}

static void free_pair(eye_shot s[2])
{
    for (int e = 0; e < 2; e++) {
        free(s[e].img);
        free(s[e].mask);
    }
}

static void test_panel_stereo(void **state)
{
    (void)state;
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, W, H, 7), 0);
    hol_app_view v;
    /* the map beside the text */
    make_view(&v, HOL_MINIMAP_HUD);
    eye_shot s[2];
    for (int e = 0; e < 2; e++)
        shoot(&fx, &v, e, 1, &s[e]);
    /* 3 lines + the prompt, which wraps (wider than the block) */
    assert_int_equal(check_pair(&v, s, 1, 5, 0), 0);
    print_message("text block: left eye x %d..%d, right eye x %d..%d (disparity %d px); "
                  "y %d..%d; map x %d..%d / %d..%d\n",
                  s[0].text.x0, s[0].text.x1, s[1].text.x0, s[1].text.x1,
                  s[0].text.x0 - s[1].text.x0, s[0].text.y0, s[0].text.y1, s[0].map.x0,
                  s[0].map.x1, s[1].map.x0, s[1].map.x1);
    shot_png(s);
    int draws;
    long tris;
    panel_cost(&fx, &v, &draws, &tris);
    print_message("panel cost an eye: %d draws, %ld triangles\n", draws, tris);
    assert_int_equal(draws, 3); /* the text, the resident map, the arrow */
    assert_true(tris > 0 && tris < 4000);
    /* a capital: 7 font pixels of 4.3 mm at about 1.5 m */
    double cap = atan(7 * PX / 1.5) * 180 / PI;
    assert_true(cap >= 1.0);
    free_pair(s);
    /* the map in the hand: the text alone on the panel, centred */
    make_view(&v, HOL_MINIMAP_HAND);
    for (int e = 0; e < 2; e++)
        shoot(&fx, &v, e, 1, &s[e]);
    /* the hand's map is not on the panel (held low, out of this view) */
    assert_int_equal(check_pair(&v, s, 0, 5, 0), 0);
    free_pair(s);
    make_view(&v, HOL_MINIMAP_OFF);
    for (int e = 0; e < 2; e++)
        shoot(&fx, &v, e, 1, &s[e]);
    assert_int_equal(check_pair(&v, s, 0, 5, 0), 0);
    free_pair(s);
    render_fixture_destroy(&fx);
}

/* The control: the screen-space HUD (no panel) fails the same checks. */
static void test_screen_hud_fails(void **state)
{
    (void)state;
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, W, H, 7), 0);
    hol_app_view v;
    make_view(&v, HOL_MINIMAP_HUD);
    eye_shot s[2];
    for (int e = 0; e < 2; e++)
        shoot(&fx, &v, e, 0, &s[e]);
    assert_true(s[0].all.n > 0);
    assert_true(check_pair(&v, s, 1, 5, 1) >= 3);
    /* the same pixels in both eyes: no disparity at all */
    assert_int_equal(s[0].all.x0, s[1].all.x0);
    assert_int_equal(s[0].all.x1, s[1].all.x1);
    assert_false(central(&s[0], 20));
    free_pair(s);
    render_fixture_destroy(&fx);
}

/* A long line wraps into the block; many lines shrink the glyphs until
 * every one fits: the block keeps its width and height bounds. */
static void test_panel_wraps(void **state)
{
    (void)state;
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, W, H, 7), 0);
    hol_app_view v;
    make_view(&v, HOL_MINIMAP_OFF);
    snprintf(v.hud.lines[0], sizeof v.hud.lines[0],
             "FIND THE MARKED TILE AHEAD, THEN THE NEXT ONE");
    for (int i = 1; i < 6; i++)
        snprintf(v.hud.lines[i], sizeof v.hud.lines[i], "LINE %d OF A LONG END SCREEN", i);
    v.hud.nlines = 6;
    eye_shot s[2];
    for (int e = 0; e < 2; e++)
        shoot(&fx, &v, e, 1, &s[e]);
    double r[4], p[4];
    text_rect(0, 1, r);
    predict(&v, 0, r[0], r[1], -61, 32, p); /* the block's most: 93 high */
    assert_true(s[0].text.x0 >= p[0] - 1 && s[0].text.x1 + 1 <= p[2] + 1);
    assert_true(s[0].text.y0 >= p[1] - 1 && s[0].text.y1 + 1 <= p[3] + 1);
    assert_true(central(&s[0], 20) && central(&s[1], 20));
    free_pair(s);
    render_fixture_destroy(&fx);
}

int main(void)
{
    const char *size = getenv("HOL_PANEL_SIZE");
    if (size && atoi(size) >= 240 && atoi(size) <= 2048)
        W = H = atoi(size);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_panel_stereo),
        cmocka_unit_test(test_screen_hud_fails),
        cmocka_unit_test(test_panel_wraps),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
