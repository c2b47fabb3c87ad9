/* test_render_golden.c - rendered views against reviewed golden PNGs.
 *
 * Each view is rendered at 160 x 120 and compared with tests/golden/NAME.png
 * pixel by pixel: a pixel differs when a channel is off by more than
 * TOL (8 of 255); a view fails when more than 0.5 % of its pixels differ
 * (llvmpipe versions may round a few edge pixels differently). On failure
 * the actual image and a diff image (differing pixels red over a darkened
 * copy of the golden) are written to GOLDEN_OUT (default: the folder of
 * this binary, golden-out/) and named in the message.
 *
 * Updating (only on request): HOL_GOLDEN_UPDATE=1 writes every view as the
 * new golden instead of comparing; then look at each changed PNG (git diff
 * --stat tests/golden; open them) before committing. See README "Golden
 * images".
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"
#include "../core/hol_world.h"
#include "../platform/egl/hol_egl.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../platform/file/hol_file.h"
#include "../platform/image/hol_png_file.h"
#include "../render/hol_png.h"
#include "../render/hol_render.h"
#include "golden_compare.h"
#include "hand_fixture.h"
#include "render_fixture.h"

#define W 160
#define H 120
#define TOL GOLDEN_TOL

typedef struct golden_view {
    const char *name, *walk;
    double eye[3], yaw, pitch, fov;
    int flags;
    /* geometry (SPEC 7): tiling Q, room C x R, cell M metres; 0: {4,5},
     * 3 x 3, 1 m. Each tiling gets a world of its own (same seed). */
    int q, cols, rows;
    double cell;
    /* dusk and night (docs/lighting.md): the sky, and lanterns
     * on the tiles that these room walks from the user's state reach */
    int lighting;
    const char *lanterns[4];
    /* fireflies and spots (render/hol_light.h): hol_frame_desc.fireflies
     * and each lantern's lantern_spot */
    int fireflies;
    int spot[4];
    /* the HUD's text instead of the frame's fields (a questionnaire
     * item: the text face's lower case and punctuation), and its prompt */
    const char *hud[3];
    const char *prompt;
    /* the body (core/hol_body.h): 1 two Touch controllers and the
     * pointing ray from the right, 2 two tracked hands (tests/
     * hand_fixture.h), held below the eye (golden_body) */
    int body;
    /* the carried lantern (render/hol_light.h): 1 at the eye's x and z,
     * HOL_APP_CARRIED_DROP_M below it; a lighting cycle: cycle 1 and
     * night the sky between dusk (0) and night (1) */
    int carried, cycle;
    double night;
} golden_view;

/* the day views leave lighting and lanterns out (zero: day, none) */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
static const golden_view views[] = {
    {"centre_north", "-", {1.5, 1.6, 1.5}, 0, -30, 90, 0, 0, 0, 0, 0},
    {"centre_down", "-", {1.45, 1.6, 1.55}, 20, -89, 100, 0, 0, 0, 0, 0},
    {"centre_bare", "-", {1.5, 1.6, 1.5}, 0, -35, 90, HOL_RENDER_BARE, 0, 0, 0, 0},
    {"corner_across_vertices", "NW", {0.3, 1.6, 0.3}, -135, -30, 90, 0, 0, 0, 0, 0},
    {"corner_se", "SE", {2.7, 1.6, 2.7}, 45, -25, 90, 0, 0, 0, 0, 0},
    {"edge_north", "N", {1.5, 1.6, 0.4}, 180, -30, 90, 0, 0, 0, 0, 0},
    {"along_edge", "E", {2.5, 1.6, 1.03}, 90, -15, 90, 0, 0, 0, 0, 0},
    {"along_edge_bare", "E", {2.5, 1.6, 1.03}, 90, -15, 90, HOL_RENDER_BARE, 0, 0, 0, 0},
    {"deep_tile", "NWSSEEN", {2.3, 1.7, 1.6}, 120, -30, 90, 0, 0, 0, 0, 0},
    {"low_eye", "S", {1.6, 0.8, 2.4}, 10, -10, 90, 0, 0, 0, 0, 0},
    {"wide_west", "W", {0.7, 1.6, 1.3}, -70, -35, 120, 0, 0, 0, 0, 0},
    {"euclidean_centre", "-", {1.5, 1.6, 1.5}, 0, -30, 90, HOL_RENDER_EUCLIDEAN, 0, 0, 0, 0},
    {"minimap", "NE", {2.4, 1.6, 0.6}, 135, -30, 90, HOL_RENDER_MINIMAP, 0, 0, 0, 0},
    {"minimap_hand", "NE", {2.4, 1.6, 0.6}, 135, -30, 90,
     HOL_RENDER_MINIMAP | HOL_RENDER_MINIMAP_HAND, 0, 0, 0, 0},
    /* other geometries: the same corner view in {4,4} (a flat grid: the
     * map a plain top view, captioned), {4,6} and {4,8}; a 5 x 5 room;
     * a 4 x 4 room of 0.7 m cells in {4,6}; the flat map in the hand */
    {"q4_corner", "NE", {2.4, 1.6, 0.6}, 135, -30, 90, HOL_RENDER_MINIMAP, 4, 0, 0, 0},
    {"q6_corner", "NE", {2.4, 1.6, 0.6}, 135, -30, 90, HOL_RENDER_MINIMAP, 6, 0, 0, 0},
    {"q8_corner", "NE", {2.4, 1.6, 0.6}, 135, -30, 90, HOL_RENDER_MINIMAP, 8, 0, 0, 0},
    {"q4_hand", "NE", {2.4, 1.6, 0.6}, 135, -30, 90,
     HOL_RENDER_MINIMAP | HOL_RENDER_MINIMAP_HAND, 4, 0, 0, 0},
    {"room5x5", "NW", {1.3, 1.6, 1.2}, -135, -25, 100, HOL_RENDER_MINIMAP, 5, 5, 5, 0},
    {"cell07_q6_room4x4", "E", {2.2, 1.6, 1.6}, 100, -30, 90, HOL_RENDER_MINIMAP, 6, 4, 4, 0.7},
    /* dusk and night with lanterns: on the user's tile, and on the two
     * tiles of the middle cell (reached west-then-south and south-then-
     * west: two tiles in {4,5} and {4,6}, holonomy), one more south */
    {"q5_dusk", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 5, 0, 0, 0, HOL_LIGHT_DUSK,
     {"-", "WS", "SW", "SSW"}},
    {"q5_night", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 5, 0, 0, 0, HOL_LIGHT_NIGHT,
     {"-", "WS", "SW", "SSW"}},
    {"q6_dusk", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 6, 0, 0, 0, HOL_LIGHT_DUSK,
     {"-", "WS", "SW", "SSW"}},
    {"q6_night", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 6, 0, 0, 0, HOL_LIGHT_NIGHT,
     {"-", "WS", "SW", "SSW"}},
    /* the same with fireflies, the middle cell's lanterns spots (straight
     * down; towards their tiles' heading turned a quarter) and the far one
     * a spot towards its heading */
    {"q5_dusk_fx", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 5, 0, 0, 0, HOL_LIGHT_DUSK,
     {"-", "WS", "SW", "SSW"}, 1, {0, 5, 2, 1}},
    {"q5_night_fx", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 5, 0, 0, 0, HOL_LIGHT_NIGHT,
     {"-", "WS", "SW", "SSW"}, 1, {0, 5, 2, 1}},
    {"q6_dusk_fx", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 6, 0, 0, 0, HOL_LIGHT_DUSK,
     {"-", "WS", "SW", "SSW"}, 1, {0, 5, 2, 1}},
    {"q6_night_fx", "NE", {2.4, 1.6, 0.6}, 135, -25, 90, 0, 6, 0, 0, 0, HOL_LIGHT_NIGHT,
     {"-", "WS", "SW", "SSW"}, 1, {0, 5, 2, 1}},
    /* a carried lantern at night (no lantern placed): its light on the
     * user's tile and through the portals on the tiles beyond; the same
     * in {4,4}; a lighting cycle half-way from dusk to night, the lanterns
     * of q5_dusk */
    {.name = "q5_night_carried", .walk = "NE", .eye = {2.4, 1.6, 0.6}, .yaw = 135, .pitch = -50,
     .fov = 90, .q = 5, .lighting = HOL_LIGHT_NIGHT, .carried = 1},
    {.name = "q4_night_carried", .walk = "NE", .eye = {2.4, 1.6, 0.6}, .yaw = 135, .pitch = -50,
     .fov = 90, .q = 4, .lighting = HOL_LIGHT_NIGHT, .carried = 1},
    {.name = "q5_cycle_half", .walk = "NE", .eye = {2.4, 1.6, 0.6}, .yaw = 135, .pitch = -25,
     .fov = 90, .q = 5, .lighting = HOL_LIGHT_DUSK, .lanterns = {"-", "WS", "SW", "SSW"},
     .cycle = 1, .night = 0.5},
    /* a questionnaire item on the HUD (the map off): ? % < " ' and lower
     * case in the text face */
    {"ask_item", "-", {1.5, 1.6, 1.5}, 0, -30, 90, HOL_RENDER_HUD_TEXT, 0, 0, 0, 0, 0, {0}, 0,
     {0},
     {"How \"hurried\" was the pace?", "0 % = very low, 100 % =", "very high; < 50 % is 'low'"},
     "Left/right: -5 %, enter: OK"},
    /* the body, in a tile two steps away (its poses are the room's: the
     * walk does not move them) */
    {.name = "body_controllers", .walk = "WS", .eye = {0.5, 1.6, 2.4}, .yaw = -30, .pitch = -35,
     .fov = 90, .body = 1},
    {.name = "body_hands", .walk = "WS", .eye = {0.5, 1.6, 2.4}, .yaw = -40, .pitch = -35,
     .fov = 90, .body = 2},
};

static render_fixture fx;
static char out_dir[512];
static struct hol_world *qworlds[9]; /* tilings other than {4,5}, by Q */

/* The world of tiling {4,q}: the fixture's for {4,5}, else one of the
 * same seed made on first use. */
static struct hol_world *geometry_world(int q)
{
    if (q == 5)
        return fx.world;
    if (!qworlds[q]) {
        hol_world_desc wd;
        memset(&wd, 0, sizeof wd);
        wd.seed = 2;
        wd.capacity = 1u << 14;
        wd.tiling_q = q;
        assert_int_equal(hol_world_make(&wd, &qworlds[q]), HOL_OK);
    }
    return qworlds[q];
}

static int setup(void **state)
{
    (void)state;
    return render_fixture_make(&fx, W, H, 2);
}

static int teardown(void **state)
{
    (void)state;
    for (int q = 0; q < 9; q++)
        hol_world_destroy(qworlds[q]);
    render_fixture_destroy(&fx);
    return 0;
}

/* The view's body (g->body): the hands 0.3 m ahead of the eye along its
 * yaw, 0.3 m below it and 0.15 m to each side; the controllers' tips up
 * 15 degrees. */
static void golden_body(const golden_view *g, hol_body *out)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.flags = HOL_INPUT_HEAD_VALID;
    in.device = g->body == 1 ? HOL_DEVICE_XR_TOUCH : HOL_DEVICE_WEBXR_HAND;
    double y = g->yaw * 3.14159265358979323846 / 180;
    for (int h = 0; h < 2; h++) {
        double side = h ? 0.15 : -0.15, w[3];
        w[0] = g->eye[0] + side * cos(y) - 0.3 * sin(y);
        w[1] = g->eye[1] - 0.3;
        w[2] = g->eye[2] - side * sin(y) - 0.3 * cos(y);
        if (g->body == 2) {
            hand_fixture(h, w, g->yaw + (h ? 15 : -15), 0, h == 0, &in.joints[h]);
            continue;
        }
        in.flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
        double a = 7.5 * 3.14159265358979323846 / 180, b = y / 2; /* yaw * tip up */
        in.hand[h].quat[0] = (float)(cos(b) * sin(a));
        in.hand[h].quat[1] = (float)(sin(b) * cos(a));
        in.hand[h].quat[2] = (float)(-sin(b) * sin(a));
        in.hand[h].quat[3] = (float)(cos(b) * cos(a));
        for (int k = 0; k < 3; k++)
            in.hand[h].pos[k] = (float)w[k];
    }
    hol_body_from_input(&in, g->body == 1, out);
}

static void render_with(hol_render *rr, const golden_view *g, uint8_t *rgba)
{
    hol_frame_desc f;
    memset(&f, 0, sizeof f);
    int q = g->q ? g->q : 5;
    assert_int_equal(hol_room_start_in(q, g->cols, g->rows, &f.user), HOL_OK);
    f.cell_m = g->cell;
    struct hol_world *world = geometry_world(q);
    hol_render_set_world(rr, world);
    for (const char *p = g->walk; *p && *p != '-'; p++)
        assert_int_equal(hol_room_step(&f.user, hol_dir_from_char(*p)), HOL_OK);
    f.lighting = g->lighting;
    for (int k = 0; k < 4 && g->lanterns[k]; k++) {
        hol_room u = f.user;
        for (const char *p = g->lanterns[k]; *p && *p != '-'; p++)
            assert_int_equal(hol_room_step(&u, hol_dir_from_char(*p)), HOL_OK);
        f.lantern_spot[f.nlanterns] = (uint8_t)g->spot[k];
        f.lanterns[f.nlanterns++] = u.tile;
    }
    f.fireflies = g->fireflies;
    f.cycle = g->cycle;
    f.night = g->night;
    f.carried = g->carried;
    f.carried_pos[0] = g->eye[0];
    f.carried_pos[1] = g->eye[1] - HOL_APP_CARRIED_DROP_M;
    f.carried_pos[2] = g->eye[2];
    memcpy(f.cam.eye, g->eye, sizeof f.cam.eye);
    f.cam.yaw_deg = g->yaw;
    f.cam.pitch_deg = g->pitch;
    f.cam.fovy_deg = g->fov;
    f.cam.width = W;
    f.cam.height = H;
    f.flags = g->flags;
    if (!(g->flags & (HOL_RENDER_MINIMAP | HOL_RENDER_HUD_TEXT)))
        f.flags |= HOL_RENDER_NO_HUD;
    for (int k = 0; k < 3 && g->hud[k]; k++)
        f.hud_lines[f.nhud_lines++] = g->hud[k];
    f.prompt = g->prompt;
    if (g->flags & HOL_RENDER_MINIMAP_HAND) {
        /* held low in front of the eye, turned 135 degrees about the
         * vertical so that it faces the eye (north-east of it) */
        f.hand_pos[0] = 2.2;
        f.hand_pos[1] = 1.3;
        f.hand_pos[2] = 0.8;
        f.hand_orient[1] = sin(135.0 / 2 * 3.14159265358979323846 / 180);
        f.hand_orient[3] = cos(135.0 / 2 * 3.14159265358979323846 / 180);
        f.hand_size = 0.3;
    }
    f.nobjectives = 2;
    assert_int_equal(hol_tile_resolve_q(q, "Nrfl", -1, &f.objectives[0]), HOL_OK);
    assert_int_equal(hol_tile_resolve_q(q, "Wlffr", -1, &f.objectives[1]), HOL_OK);
    f.objective_text = "find the key";
    static const uint8_t path[] = {HOL_DIR_W, HOL_DIR_W, HOL_DIR_S, HOL_DIR_S};
    f.path = path;
    f.npath = 4;
    assert_int_equal(hol_world_update(world, &f.user), HOL_OK);
    f.steps_taken = 2;
    f.time_s = 83;
    static hol_body body;
    if (g->body) {
        golden_body(g, &body);
        f.body = &body;
    }
    render_fixture_draw(rr, &f, W, H, rgba);
    hol_render_set_world(rr, fx.world);
}

static void render_view(const golden_view *g, uint8_t *rgba)
{
    render_with(fx.rnd, g, rgba);
}

/* Compare img with the golden NAME (tests/golden_compare.h). */
static int compare(const char *name, const uint8_t *img, const char *tag)
{
    return golden_compare(name, img, W, H, tag, out_dir);
}

static void test_goldens(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    int update = golden_update_requested();
    int failed = 0;
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
        const golden_view *g = &views[i];
        char path[600];
        snprintf(path, sizeof path, "tests/golden/%s.png", g->name);
        render_view(g, img);
        if (update) {
            assert_int_equal(hol_png_write_file(path, img, W, H, 0), HOL_OK);
            printf("golden: wrote %s (review it before committing)\n", path);
            continue;
        }
        failed += compare(g->name, img, "");
    }
    assert_int_equal(failed, 0);
}

/* The comparison has teeth: a one-degree turn changes a view beyond the
 * tolerance, and the PNG round trip is exact. */
static void test_comparison_detects_change(void **state)
{
    (void)state;
    static uint8_t a[W * H * 4], b[W * H * 4];
    golden_view g = views[0];
    render_view(&g, a);
    g.yaw += 1.0;
    render_view(&g, b);
    int bad = 0;
    for (int p = 0; p < W * H; p++)
        for (int k = 0; k < 3; k++)
            if (abs((int)a[4 * p + k] - (int)b[4 * p + k]) > TOL) {
                bad++;
                break;
            }
    assert_true(bad * 200 > W * H);
    uint8_t *data, *back;
    size_t n;
    int w, h;
    assert_int_equal(hol_png_encode(a, W, H, 1, &data, &n), HOL_OK);
    assert_int_equal(hol_png_decode(data, n, &back, &w, &h), HOL_OK);
    assert_int_equal(w, W);
    assert_int_equal(h, H);
    assert_memory_equal(a, back, sizeof a);
    /* damage: a flipped byte in the data is caught by the CRC */
    data[n / 2] ^= 0x40;
    uint8_t *bad_img = NULL;
    assert_int_equal(hol_png_decode(data, n, &bad_img, &w, &h), HOL_ECORRUPT);
    assert_int_equal(hol_png_decode(data, 7, &bad_img, &w, &h), HOL_ECORRUPT);
    free(data);
    free(back);
}

/* The same code on OpenGL ES 3 (EGL surfaceless, Mesa) draws the same
 * pictures as on OSMesa's desktop core profile: every golden view is
 * rendered through EGL and compared with the same goldens. Skipped (with a
 * message) where the machine has no EGL surfaceless platform. */
static void test_egl_gles_matches_goldens(void **state)
{
    (void)state;
    if (golden_update_requested())
        skip(); /* goldens are written from OSMesa; compare on the next run */
    hol_egl egl;
    char msg[256];
    if (hol_egl_create(&egl, W, H, msg, sizeof msg)) {
        printf("egl: %s: skipped\n", msg);
        OSMesaMakeCurrent(fx.gl.ctx, fx.gl.buf, GL_UNSIGNED_BYTE, W, H);
        skip();
    }
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = fx.world;
    rd.getproc = hol_egl_getproc;
    rd.debug = 1; /* a test build: every GL error reported */
    hol_render *er = NULL;
    assert_int_equal(hol_render_create(&rd, &er), HOL_OK);
    static uint8_t img[W * H * 4];
    int failed = 0;
    for (size_t i = 0; i < sizeof views / sizeof views[0]; i++) {
        render_with(er, &views[i], img);
        failed += compare(views[i].name, img, ".egl");
    }
    hol_render_destroy(er);
    hol_egl_destroy(&egl);
    OSMesaMakeCurrent(fx.gl.ctx, fx.gl.buf, GL_UNSIGNED_BYTE, W, H);
    assert_int_equal(failed, 0);
}

/* Per-eye budgets that do not depend on timing (those are in make bench):
 * at most 150 draw calls and 300k triangles, one stencil polygon per
 * visible leaf (at most 16), none in the euclidean baseline; checked over
 * the golden views and a sweep of eye positions in all nine cells with the
 * forest, HUD and minimap on. */
static void test_stats_within_budget(void **state)
{
    (void)state;
    static const char *walks[9] = {"NW", "N", "NE", "W", "-", "E", "SW", "S", "SE"};
    int frames = 0, max_dc = 0, skipped = 0;
    long max_tri = 0;
    for (int k = 0; k < 9 * 8 + (int)(sizeof views / sizeof views[0]); k++) {
        golden_view g;
        if (k < 72) {
            hol_room u = hol_room_start();
            for (const char *p = walks[k / 8]; *p && *p != '-'; p++)
                hol_room_step(&u, hol_dir_from_char(*p));
            g = (golden_view){"sweep", walks[k / 8],
                              {u.col + 0.1 + 0.1 * (k % 8), 1.6, u.row + 0.85 - 0.1 * (k % 8)},
                              45.0 * (k % 8), -30, 100, HOL_RENDER_MINIMAP, 0, 0, 0, 0};
        } else {
            g = views[k - 72];
        }
        for (int eu = 0; eu < 2; eu++) {
            hol_frame_desc f;
            memset(&f, 0, sizeof f);
            int q = g.q ? g.q : 5;
            assert_int_equal(hol_room_start_in(q, g.cols, g.rows, &f.user), HOL_OK);
            f.cell_m = g.cell;
            for (const char *p = g.walk; *p && *p != '-'; p++)
                hol_room_step(&f.user, hol_dir_from_char(*p));
            hol_render_set_world(fx.rnd, geometry_world(q));
            assert_int_equal(hol_world_update(geometry_world(q), &f.user), HOL_OK);
            memcpy(f.cam.eye, g.eye, sizeof f.cam.eye);
            f.cam.yaw_deg = g.yaw;
            f.cam.pitch_deg = g.pitch;
            f.cam.fovy_deg = g.fov;
            f.cam.width = W;
            f.cam.height = H;
            f.flags = (g.flags & ~HOL_RENDER_EUCLIDEAN) | HOL_RENDER_MINIMAP |
                      (eu ? HOL_RENDER_EUCLIDEAN : 0);
            hol_render_stats st;
            assert_int_equal(hol_render_frame(fx.rnd, &f, &st), HOL_OK);
            assert_true(st.draw_calls <= 150);
            assert_true(st.triangles <= 300000);
            hol_render_set_world(fx.rnd, fx.world);
            if (eu || hol_render_last_view(fx.rnd)->wedges)
                assert_int_equal(st.stencil_passes, 0);
            else
                assert_true(st.stencil_passes >= 1 && st.stencil_passes <= HOL_VIEW_MAX_LEAVES);
            /* every branch of the view drawn but those with no leaf on
             * screen (hol__branch_box): some views skip some */
            int nb = hol_render_last_view(fx.rnd)->nbranches;
            assert_true(nb >= 9);
            assert_true(st.branches >= 1 && st.branches <= nb);
            skipped += nb - st.branches;
            max_dc = st.draw_calls > max_dc ? st.draw_calls : max_dc;
            max_tri = st.triangles > max_tri ? st.triangles : max_tri;
            frames++;
        }
    }
    printf("budget: %d frames, max %d draw calls, max %ld triangles, %d branches off screen\n",
           frames, max_dc, max_tri, skipped);
    assert_true(skipped > 0);
}

/* Meshes stay resident: an unchanged second frame builds no tile mesh,
 * uploads only the leaf polygons and HUD, and draws the same image; a tile
 * whose content changes (a key placed on it) is rebuilt on the next frame. */
static void test_resident_meshes(void **state)
{
    (void)state;
    static uint8_t a[W * H * 4], b[W * H * 4];
    golden_view g = views[0]; /* centre_north */
    hol_frame_desc f;
    memset(&f, 0, sizeof f);
    f.user = hol_room_start();
    assert_int_equal(hol_world_update(fx.world, &f.user), HOL_OK);
    memcpy(f.cam.eye, g.eye, sizeof f.cam.eye);
    f.cam.yaw_deg = g.yaw;
    f.cam.pitch_deg = g.pitch;
    f.cam.fovy_deg = g.fov;
    f.cam.width = W;
    f.cam.height = H;
    f.flags = HOL_RENDER_MINIMAP;
    hol_render_stats s1, s2, s3;
    hol_render_invalidate(fx.rnd);
    assert_int_equal(hol_render_frame(fx.rnd, &f, &s1), HOL_OK);
    hol_render_read_rgba(fx.rnd, W, H, a);
    assert_true(s1.tiles_built >= 3 && s1.tiles_built <= s1.branches);
    assert_int_equal(hol_render_frame(fx.rnd, &f, &s2), HOL_OK);
    hol_render_read_rgba(fx.rnd, W, H, b);
    printf("resident: first frame %ld bytes, %d tiles; second %ld bytes\n",
           s1.uploaded_bytes, s1.tiles_built, s2.uploaded_bytes);
    assert_int_equal(s2.tiles_built, 0);
    assert_true(s2.uploaded_bytes < 64 * 1024);
    assert_true(s2.uploaded_bytes * 4 < s1.uploaded_bytes);
    assert_memory_equal(a, b, sizeof a);
    /* the tile north of the user gets a key: rebuilt, and it shows */
    hol_tile n, got;
    assert_int_equal(hol_tile_resolve("N", -1, &n), HOL_OK);
    hol_tile_content c;
    assert_int_equal(hol_world_get(fx.world, n, &c), HOL_OK);
    if (hol_world_reserve(fx.world, n, 0, HOL_OBJ_KEY, &got) != HOL_OK)
        skip(); /* the tile is not free in this world: nothing to show */
    assert_int_equal(hol_render_frame(fx.rnd, &f, &s3), HOL_OK);
    hol_render_read_rgba(fx.rnd, W, H, b);
    assert_true(s3.tiles_built >= 1);
    assert_memory_not_equal(a, b, sizeof a);
    assert_int_equal(hol_world_release(fx.world, got), HOL_OK);
}

/* Rewrite every chunk CRC so mutations reach the inflate and unfilter code
 * instead of stopping at the checksum. */
static void fix_crcs(uint8_t *d, size_t n)
{
    size_t pos = 8;
    while (pos + 12 <= n) {
        uint32_t len = (uint32_t)d[pos] << 24 | (uint32_t)d[pos + 1] << 16 |
                       (uint32_t)d[pos + 2] << 8 | d[pos + 3];
        if (len > n - pos - 12)
            return;
        uint32_t c = 0xffffffffu;
        for (size_t i = pos + 4; i < pos + 8 + len; i++) {
            c ^= d[i];
            for (int k = 0; k < 8; k++)
                c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1)));
        }
        c ^= 0xffffffffu;
        uint8_t *q = d + pos + 8 + len;
        q[0] = (uint8_t)(c >> 24);
        q[1] = (uint8_t)(c >> 16);
        q[2] = (uint8_t)(c >> 8);
        q[3] = (uint8_t)c;
        pos += 12 + len;
    }
}

/* The reader never crashes or over-reads on damaged files: thousands of
 * mutated and truncated images either decode to the stated size or fail
 * with an error. (render/ is outside the libFuzzer harnesses, which link the
 * core only; this is its fuzz-style test.) */
static void test_png_reader_survives_damage(void **state)
{
    (void)state;
    static uint8_t img[32 * 24 * 4];
    for (size_t i = 0; i < sizeof img; i++)
        img[i] = (uint8_t)(i * 7 + (i >> 5));
    uint8_t *good;
    size_t n;
    assert_int_equal(hol_png_encode(img, 32, 24, 1, &good, &n), HOL_OK);
    uint8_t *buf = malloc(n);
    assert_non_null(buf);
    uint64_t rng = 99;
    int ok = 0, errors = 0;
    for (int it = 0; it < 4000; it++) {
        memcpy(buf, good, n);
        size_t len = n;
        int muts = 1 + it % 4;
        for (int m = 0; m < muts; m++) {
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            size_t at = (size_t)(rng >> 33) % n;
            buf[at] ^= (uint8_t)(1u << ((rng >> 20) & 7));
        }
        if (it % 5 == 0) {
            rng = rng * 6364136223846793005ull + 1442695040888963407ull;
            len = (size_t)(rng >> 33) % n;
        }
        if (it % 2 == 0)
            fix_crcs(buf, len);
        uint8_t *out = NULL;
        int w = 0, h = 0;
        hol_err e = hol_png_decode(buf, len, &out, &w, &h);
        if (e == HOL_OK) {
            assert_true(w > 0 && h > 0 && w <= HOL_PNG_MAX_DIM && h <= HOL_PNG_MAX_DIM);
            volatile uint8_t last = out[(size_t)w * (size_t)h * 4 - 1];
            (void)last;
            free(out);
            ok++;
        } else {
            assert_true(e == HOL_ECORRUPT || e == HOL_EUNSUPPORTED || e == HOL_ENOMEM);
            errors++;
        }
    }
    assert_true(errors > 1000);
    free(buf);
    free(good);
    (void)ok;
}

int main(int argc, char **argv)
{
    (void)argc;
    golden_out_dir(out_dir, sizeof out_dir, argv[0]);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_comparison_detects_change),
        cmocka_unit_test(test_png_reader_survives_damage),
        cmocka_unit_test(test_stats_within_budget),
        cmocka_unit_test(test_resident_meshes),
        cmocka_unit_test(test_egl_gles_matches_goldens),
        cmocka_unit_test(test_goldens),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
