/* test_render_game.c - the game as players see it, against reviewed golden
 * PNGs: the flag, a key, the chest closed and open, the level-end screen
 * and the tutorial (its first prompt and marker, lesson 2's marked tree,
 * lesson 2's end with the rings' line).
 *
 * Each picture goes the whole way a platform goes: a level started in the
 * app (core/hol_app.h), input records stepped, the view turned into a
 * frame description (render/hol_app_frame.h) and drawn by the renderer
 * (OSMesa, 320 x 240). So a golden also checks that the app puts the
 * objects in the world, opens the chest, hides collected keys and writes
 * the HUD lines. Compared as in test_render_golden.c
 * (tests/golden_compare.h); HOL_GOLDEN_UPDATE=1 writes them for review.
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

#include "../core/hol_app.h"
#include "../core/hol_str.h"
#include "../core/hol_tile.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_app_frame.h"
#include "../render/hol_hud.h"
#include "../render/hol_render.h"
#include "golden_compare.h"
#include "render_fixture.h"

#define W 320
#define H 240

static hol_osmesa gl;
static hol_app *app;
static hol_render *rnd;
static char out_dir[512];
static double now;

static int setup(void **state)
{
    (void)state;
    char msg[256];
    if (hol_osmesa_create(&gl, W, H, msg, sizeof msg)) {
        fprintf(stderr, "%s\n", msg);
        return -1;
    }
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    if (hol_app_create(&ad, &app))
        return -1;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1; /* a test build: every GL error reported */
    rd.world = hol_app_world(app);
    return hol_render_create(&rd, &rnd) ? -1 : 0;
}

static int teardown(void **state)
{
    (void)state;
    hol_render_destroy(rnd);
    hol_app_destroy(app);
    hol_osmesa_destroy(&gl);
    return 0;
}

static hol_tile tile(const char *addr)
{
    hol_tile t;
    assert_int_equal(hol_tile_resolve(addr, -1, &t), HOL_OK);
    return t;
}

static void start(const hol_app_level *L)
{
    assert_int_equal(hol_app_start_level(app, L), HOL_OK);
    hol_render_set_world(rnd, hol_app_world(app));

}

/* Step the app for `frames` frames of 1/60 s with pancake axes: move
 * (right, forward) and turn (left, up). */
static void step(int frames, float right, float fwd, float turn_left, float look_up)
{
    for (int i = 0; i < frames; i++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = now;
        in.flags = HOL_INPUT_FOCUSED;
        in.device = HOL_DEVICE_KEYBOARD; /* the prompts name keys */
        in.move[0] = right;
        in.move[1] = fwd;
        in.turn[0] = turn_left;
        in.turn[1] = look_up;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        now += 1.0 / 60;
    }
}

/* Draw the app's view as the desktop does (the head's view), without the
 * HUD when hud is 0, and compare it with golden NAME. */
static void draw(const hol_frame_desc *fd, uint8_t *img)
{
    render_fixture_draw(rnd, fd, W, H, img);
}

static int shot(const char *name, int hud, uint8_t *img)
{
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(app), -1, W, H, 0, &fd);
    if (!hud)
        fd.flags |= HOL_RENDER_NO_HUD;
    draw(&fd, img);
    if (golden_update_requested()) {
        char path[600];
        snprintf(path, sizeof path, "tests/golden/%s.png", name);
        assert_int_equal(hol_png_write_file(path, img, W, H, 0), HOL_OK);
        printf("golden: wrote %s (review it before committing)\n", path);
        return 0;
    }
    return golden_compare(name, img, W, H, "", out_dir);
}

static hol_app_level level(int mode)
{
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = mode;
    L.seed = 3;
    L.cues = HOL_CUE_ALL;
    L.minimap = HOL_MINIMAP_HUD;
    return L;
}

/* The flag one tile north of the start, seen from the middle cell. */
static void test_flag(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_level L = level(HOL_APP_FLAG);
    L.flag = tile("N");
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->nobjects, 1);
    assert_int_equal(v->objects[0].kind, HOL_APP_OBJ_FLAG);
    assert_int_equal(shot("game_flag", 0, img), 0);
    /* the same level with the poles cue off: the flag stands, the guide
     * pole over it is gone (and only a pole's worth of pixels changes) */
    static uint8_t img2[W * H * 4];
    L.cues = HOL_CUE_ALL & ~HOL_CUE_POLES;
    start(&L);
    step(1, 0, 0, 0, 0);
    assert_int_equal(v->nobjects, 1);
    assert_int_equal(shot("game_flag_no_pole", 0, img2), 0);
    int differ = 0;
    for (int i = 0; i < W * H; i++)
        differ += memcmp(img + 4 * i, img2 + 4 * i, 3) != 0;
    printf("    poles cue off: %d of %d pixels change\n", differ, W * H);
    assert_true(differ > 300 && differ < W * H / 10);
}

/* The flag one tile north in other geometries, as the app plays them: the
 * flat {4,4} (3 x 3: the map a plain top view with its caption) and {4,6}
 * in a 4 x 4 room of 0.8 m cells (the view's cell size reaches the frame:
 * the eye at the start cell's centre, 1.6 m up). */
static void test_flag_geometries(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    static const struct { int q, cols, rows; double cell; const char *name; } g[] = {
        {4, 3, 3, 1.0, "game_flag_q4"},
        {6, 4, 4, 0.8, "game_flag_q6_room4x4_cell08"},
    };
    int failed = 0;
    for (int i = 0; i < 2; i++) {
        hol_app_level L = level(HOL_APP_FLAG);
        L.tiling_q = g[i].q;
        L.room_cols = g[i].cols;
        L.room_rows = g[i].rows;
        L.cell_m = g[i].cell;
        assert_int_equal(hol_tile_resolve_q(g[i].q, "N", -1, &L.flag), HOL_OK);
        start(&L);
        step(1, 0, 0, 0, 0);
        const hol_app_view *v = hol_app_get_view(app);
        assert_int_equal(v->nobjects, 1);
        assert_true(fabs(v->cell_m - g[i].cell) < 1e-12);
        hol_frame_desc fd;
        hol_app_frame_desc(v, -1, W, H, 0, &fd);
        assert_true(fabs(fd.cell_m - g[i].cell) < 1e-12);
        assert_int_equal(hol_tile_q(fd.user.tile), g[i].q);
        assert_int_equal(hol_room_cols(&fd.user), g[i].cols);
        failed += shot(g[i].name, 1, img);
    }
    assert_int_equal(failed, 0);
}

/* Two keys (north and east) and the chest (south): looking north shows a
 * key; turned round, the closed chest. */
static void test_key_and_chest(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_level L = level(HOL_APP_KEYS);
    L.nkeys = 2;
    L.keys[0] = tile("N");
    L.keys[1] = tile("E");
    L.chest = tile("S");
    start(&L);
    step(1, 0, 0, 0, 0);
    int failed = shot("game_key", 0, img);
    step(90, 0, 0, 1, 0); /* 120 degrees/s for 1.5 s: facing south */
    const hol_app_view *v = hol_app_get_view(app);
    assert_true(v->yaw_deg > 179 && v->yaw_deg < 181);
    assert_int_equal(v->objects[v->nobjects - 1].kind, HOL_APP_OBJ_CHEST);
    failed += shot("game_chest", 0, img);
    assert_int_equal(failed, 0);
}

/* One key east, the chest north: step east onto the key and back; the key
 * is gone and the chest, looked at from the middle cell, stands open. */
static void test_chest_open(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_level L = level(HOL_APP_KEYS);
    L.nkeys = 1;
    L.keys[0] = tile("E");
    L.chest = tile("N");
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->nobjects, 2);
    step(45, 1, 0, 0, 0);  /* 1.4 m/s: 1.05 m east, into the key's tile */
    assert_int_equal(v->hud.keys_held, 1);
    step(45, -1, 0, 0, 0); /* and back into the middle cell */
    assert_int_equal(v->user.col, 1);
    assert_int_equal(v->nobjects, 1);
    assert_int_equal(v->objects[0].kind, HOL_APP_OBJ_CHEST_OPEN);
    assert_int_equal(shot("game_chest_open", 0, img), 0);
}

/* The level-end screen: walk north onto the flag; the HUD says done, the
 * steps against the best and the time, and what confirm does. */
static void test_level_end(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_level L = level(HOL_APP_FLAG);
    L.flag = tile("N");
    start(&L);
    step(1, 0, 0, 0, 0);
    step(40, 0, 1, 0, 0); /* 0.93 m north: across z = 1 */
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_int_equal(v->hud.steps, 1);
    assert_int_equal(shot("game_level_end", 1, img), 0);
}

/* Issue 37: the same screens in German (the app's language set, nothing
 * else changed): the tutorial's first prompt, the pause menu and a level's
 * end, each with umlauts on the HUD; every glyph is the face's own
 * (tests/test_str.c), and the English goldens above stay as they were. */
static void test_german(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_set_lang(app, HOL_LANG_DE);
    hol_app_level L = level(HOL_APP_TUTORIAL);
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    assert_string_equal(v->hud.lines[0], "1/4 Tritt auf die markierte Kachel vor dir");
    assert_int_equal(shot("game_tutorial_prompt_de", 1, img), 0);
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = now;
    in.flags = HOL_INPUT_FOCUSED;
    in.device = HOL_DEVICE_KEYBOARD;
    in.pressed = HOL_BTN_MENU;
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    now += 1.0 / 60;
    assert_string_equal(v->hud.hint, "P: weiter, ENTER: von vorn, ESC: aufhören");
    assert_int_equal(shot("game_menu_de", 1, img), 0);
    L = level(HOL_APP_FLAG);
    L.flag = tile("N");
    start(&L);
    step(1, 0, 0, 0, 0);
    step(40, 0, 1, 0, 0); /* 0.93 m north: across z = 1 */
    assert_int_equal(v->state, HOL_APP_DONE);
    assert_string_equal(v->hud.hint, "ENTER: nächstes Level, R: nochmal");
    assert_int_equal(shot("game_level_end_de", 1, img), 0);
    hol_app_set_lang(app, HOL_LANG_EN);
}

/* Pixels of img that differ from other and are red like the flag's
 * cloth: red well over green and blue. */
static int red_pixels(const uint8_t *img, const uint8_t *other)
{
    int n = 0;
    for (int i = 0; i < W * H; i++) {
        const uint8_t *p = img + 4 * i;
        n += memcmp(p, other + 4 * i, 3) && p[0] > 140 && p[1] < 90 && p[2] < 90;
    }
    return n;
}

/* The tutorial's first prompt with its marker one tile ahead: a violet
 * ring and post, unlike the flag (the same frame with a flag there shows
 * the flag's red cloth where the two differ; the marker's no red at all;
 * the red guide pole beside it is the same in both). */
static void test_tutorial_prompt(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4], flag[W * H * 4];
    hol_app_level L = level(HOL_APP_TUTORIAL);
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->hud.stage, 0);
    assert_int_equal(shot("game_tutorial_prompt", 1, img), 0);
    hol_frame_desc fd;
    hol_app_frame_desc(v, -1, W, H, 0, &fd);
    fd.flags |= HOL_RENDER_NO_HUD;
    assert_int_equal(fd.nobjects, 1);
    assert_int_equal(fd.object_kinds[0], HOL_RENDER_OBJ_MARKER);
    draw(&fd, img);
    fd.object_kinds[0] = HOL_RENDER_OBJ_FLAG;
    draw(&fd, flag);
    printf("    red pixels where they differ: marker %d, flag %d\n", red_pixels(img, flag),
           red_pixels(flag, img));
    assert_int_equal(red_pixels(img, flag), 0);
    assert_true(red_pixels(flag, img) > 50);
}

/* Lesson 2 (a tutorial of that lesson alone, from the middle cell): the
 * tree to walk round is marked, violet bands on its trunk and a ring at
 * its foot, at the room vertex the app names, and the view faces it; the
 * same frame without the mark differs only round that trunk (a few per
 * cent of the pixels, in the middle of the frame). */
static void test_tutorial_tree(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4], plain[W * H * 4];
    hol_app_level L = level(HOL_APP_TUTORIAL);
    L.stages = 1u << 1;
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->hud.stage, 1);
    assert_int_equal(v->tree_marked, 1);
    assert_int_equal(shot("game_tutorial_tree", 1, img), 0);
    hol_frame_desc fd;
    hol_app_frame_desc(v, -1, W, H, 0, &fd);
    fd.flags |= HOL_RENDER_NO_HUD;
    assert_int_equal(fd.tree_marked, 1);
    draw(&fd, img);
    fd.tree_marked = 0;
    draw(&fd, plain);
    /* the lesson begins facing its tree (issue 35: the view turned to it):
     * the changed pixels lie in the middle half of the frame */
    int differ = 0, middle = 0;
    for (int i = 0; i < W * H; i++)
        if (memcmp(img + 4 * i, plain + 4 * i, 3)) {
            differ++;
            middle += i % W >= W / 4 && i % W < W * 3 / 4;
        }
    printf("    tree mark: %d of %d pixels change, %d in the middle half\n", differ, W * H,
           middle);
    assert_true(differ > 300 && differ < W * H / 10);
    assert_true(middle > differ * 9 / 10);
}

/* Lesson 2 done: the head walked round the marked tree (tracked, a
 * quarter second a cell) and is back in the middle cell on another tile;
 * the HUD says holonomy, the next line what the minimap's cyan rings
 * mean, and the map rings the cell's two tiles. */
static void test_tutorial_rings(void **state)
{
    (void)state;
    static uint8_t img[W * H * 4];
    hol_app_level L = level(HOL_APP_TUTORIAL);
    L.stages = 1u << 1 | 1u << 2;
    start(&L);
    step(1, 0, 0, 0, 0);
    const hol_app_view *v = hol_app_get_view(app);
    int c = v->user.col, r = v->user.row;
    int dx = v->tree_vertex[0] == c + 1 ? 1 : -1, dz = v->tree_vertex[1] == r + 1 ? 1 : -1;
    const int cells[4][2] = {{c + dx, r}, {c + dx, r + dz}, {c, r + dz}, {c, r}};
    for (int i = 0; i < 4; i++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = now;
        in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
        in.device = HOL_DEVICE_KEYBOARD;
        in.head.pos[0] = (float)cells[i][0] + 0.5f;
        in.head.pos[1] = 1.6f;
        in.head.pos[2] = (float)cells[i][1] + 0.5f;
        in.head.quat[3] = 1;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        now += 0.25;
    }
    assert_int_equal(v->hud.stage, 2);
    assert_int_equal(v->map.nmarks, 2);
    assert_string_equal(v->hud.note, hol_str(HOL_LANG_EN, HOL_S_RINGS));
    assert_int_equal(shot("game_tutorial_rings", 1, img), 0);
}

/* The HUD minimap sits in the bottom right corner, scaled to the window,
 * and never reaches into the middle 40 % of the view both ways, at any
 * window shape; at 320 x 240 no pixel the HUD changes lies in that middle
 * box (the map, its rim arrows, the text). */
static void test_map_corner(void **state)
{
    (void)state;
    static const int size[][2] = {{320, 240}, {640, 480}, {960, 720}, {1920, 1080}, {720, 720},
                                  {1280, 400}, {400, 900}, {64, 48}, {16, 16}, {4096, 300}};
    for (size_t i = 0; i < sizeof size / sizeof size[0]; i++) {
        int w = size[i][0], h = size[i][1];
        float r[4];
        hol_hud_map_rect(w, h, r);
        float shortest = (float)(w < h ? w : h);
        if (!(r[0] >= 0 && r[1] >= 0 && r[2] <= w && r[3] <= h))
            fail_msg("%dx%d: the map %.0f,%.0f..%.0f,%.0f leaves the window", w, h, r[0], r[1],
                     r[2], r[3]);
        int clear_x = r[0] >= 0.7f * w, clear_y = r[1] >= 0.7f * h;
        if (!clear_x && !clear_y)
            fail_msg("%dx%d: the map %.0f,%.0f..%.0f,%.0f reaches the middle of the view", w, h,
                     r[0], r[1], r[2], r[3]);
        /* in the corner, and not too small to read: a side of 18 % of the
         * short side at least */
        assert_true(w - r[2] < 0.05f * shortest + 1 && h - r[3] < 0.05f * shortest + 1);
        assert_true(r[2] - r[0] >= 0.18f * shortest || shortest < 48);
    }
    /* the pixels: every pixel the HUD changes lies outside the middle */
    static uint8_t with[W * H * 4], without[W * H * 4];
    hol_app_level L = level(HOL_APP_FLAG);
    L.flag = tile("Wrf");
    start(&L);
    step(1, 0, 0, 0, 0);
    step(60, 0, 0, 0.5f, 0);
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(app), -1, W, H, 0, &fd);
    render_fixture_draw_hud(rnd, &fd, W, H, with, without);
    int changed = 0, middle = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int d = memcmp(with + 4 * (y * W + x), without + 4 * (y * W + x), 3) != 0;
            changed += d;
            middle += d && x >= 0.3 * W && x < 0.7 * W && y >= 0.3 * H && y < 0.7 * H;
        }
    printf("    the HUD changes %d pixels, %d in the middle\n", changed, middle);
    assert_true(changed > 2000);
    assert_int_equal(middle, 0);
}

/* The desktop's hand minimap sits low: at the usual pitch (30 degrees
 * down) its quad projects into the lower part of the view, out of the
 * middle box, and mostly on screen. */
static void test_hand_map_low(void **state)
{
    (void)state;
    hol_app_level L = level(HOL_APP_FLAG);
    L.flag = tile("Wrf");
    L.minimap = HOL_MINIMAP_HAND;
    start(&L);
    step(1, 0, 0, 0, 0);
    step(30, 0, 0, 1, 0); /* any yaw: the hand turns with the look */
    static const int size[][2] = {{320, 240}, {960, 720}, {1920, 1080}, {720, 720}};
    for (size_t i = 0; i < sizeof size / sizeof size[0]; i++) {
        int w = size[i][0], h = size[i][1];
        hol_frame_desc fd;
        hol_app_frame_desc(hol_app_get_view(app), -1, w, h, 0, &fd);
        assert_true(fd.flags & HOL_RENDER_MINIMAP_HAND);
        assert_true(fabs(fd.cam.pitch_deg + 30) < 1e-9);
        float view[16], proj[16];
        hol_camera_matrices(&fd.cam, view, proj);
        /* the quad's corners: hand_pos + R (±s/2, ±s/2, 0) */
        double x = fd.hand_orient[0], y = fd.hand_orient[1], z = fd.hand_orient[2],
               q = fd.hand_orient[3], hs = fd.hand_size / 2;
        double rx[3] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * q), 2 * (x * z - y * q)};
        double ry[3] = {2 * (x * y - z * q), 1 - 2 * (x * x + z * z), 2 * (y * z + x * q)};
        double top = 1e9, bottom = -1e9, cy = 0;
        for (int c = 0; c < 4; c++) {
            double u = (c & 1) ? hs : -hs, v = (c & 2) ? hs : -hs, pw[4] = {0, 0, 0, 1}, pe[4],
                   pc[4];
            for (int k = 0; k < 3; k++)
                pw[k] = fd.hand_pos[k] + u * rx[k] + v * ry[k];
            for (int r = 0; r < 4; r++) {
                pe[r] = 0;
                for (int k = 0; k < 4; k++)
                    pe[r] += view[4 * k + r] * pw[k];
            }
            for (int r = 0; r < 4; r++) {
                pc[r] = 0;
                for (int k = 0; k < 4; k++)
                    pc[r] += proj[4 * k + r] * pe[k];
            }
            assert_true(pc[3] > 0); /* in front of the eye */
            double py = (1 - pc[1] / pc[3]) / 2 * h;
            top = py < top ? py : top;
            bottom = py > bottom ? py : bottom;
            cy += py / 4;
        }
        printf("    %dx%d: the hand map spans y %.0f..%.0f\n", w, h, top, bottom);
        assert_true(top > 0.7 * h);       /* below the middle */
        assert_true(cy < 0.95 * h);       /* and its middle on screen */
    }
}

int main(int argc, char **argv)
{
    (void)argc;
    golden_out_dir(out_dir, sizeof out_dir, argv[0]);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_flag),
        cmocka_unit_test(test_flag_geometries),
        cmocka_unit_test(test_key_and_chest),
        cmocka_unit_test(test_chest_open),
        cmocka_unit_test(test_level_end),
        cmocka_unit_test(test_tutorial_prompt),
        cmocka_unit_test(test_tutorial_tree),
        cmocka_unit_test(test_tutorial_rings),
        cmocka_unit_test(test_map_corner),
        cmocka_unit_test(test_hand_map_low),
        cmocka_unit_test(test_german),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
