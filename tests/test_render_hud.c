/* test_render_hud.c - the HUD text does not hang on the minimap (issue 26):
 * with the map off (a level's `minimap off`, or M), the objective, steps,
 * time, the end screen's result and its prompt are still drawn; only the
 * map's corner stays empty. The app's view goes the way every platform's
 * does (core/hol_app.h, render/hol_app_frame.h, the renderer on OSMesa at
 * 320 x 240), and the pixels are read back: the HUD panel's colour top
 * left, the prompt's yellow (its glyphs' edges blended over the panel),
 * nothing drawn in the map's rectangle.
 *
 * test_every_glyph: every glyph of the text face (core/hol_face.h: printable
 * ASCII and Latin-1) drawn alone on the HUD through the GL path (the text
 * program and its atlas) differs from the missing-glyph box drawn the same
 * way (more than 3 pixels of the text's corner differ), and every glyph
 * with ink changes the picture from a blank's.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_face.h"
#include "../core/hol_tile.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_app_frame.h"
#include "../render/hol_hud.h"
#include "../render/hol_render.h"
#include "render_fixture.h"

#define W 320
#define H 240

static hol_osmesa gl;
static hol_app *app;
static hol_render *rnd;
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

static void step(int frames, float fwd)
{
    for (int i = 0; i < frames; i++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = now;
        in.flags = HOL_INPUT_FOCUSED;
        in.device = HOL_DEVICE_KEYBOARD;
        in.move[1] = fwd;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        now += 1.0 / 60;
    }
}

static void start_flag(int minimap)
{
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_FLAG;
    L.seed = 7;
    L.cues = HOL_CUE_ALL;
    L.minimap = minimap;
    assert_int_equal(hol_tile_resolve("N", -1, &L.flag), HOL_OK);
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    hol_render_set_world(rnd, hol_app_world(app));
    step(1, 0);
}

typedef struct counts {
    int changed;     /* pixels the HUD changes */
    int in_map;      /* of them, inside the minimap's rectangle */
    int panel;       /* pixels of the text panel's colour, top left */
    int yellow;      /* pixels of the prompt's yellow */
} counts;

/* The app's view drawn with and without the HUD (HOL_RENDER_NO_HUD). */
static counts draw(void)
{
    static uint8_t with[W * H * 4], without[W * H * 4];
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(app), -1, W, H, 0, &fd);
    render_fixture_draw_hud(rnd, &fd, W, H, with, without);
    float r[4];
    hol_hud_map_rect(W, H, r);
    counts c = {0, 0, 0, 0};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const uint8_t *a = with + 4 * (y * W + x), *b = without + 4 * (y * W + x);
            if (memcmp(a, b, 3) == 0)
                continue;
            c.changed++;
            int ty = y; /* rows top to bottom, as the map's rectangle */
            c.in_map += x >= r[0] && x < r[2] && ty >= r[1] && ty < r[3];
            c.panel += x < W / 2 && ty < H / 2 && a[0] == 24 && a[1] == 28 && a[2] == 34;
            /* the prompt's yellow, its glyphs' edges blended */
            c.yellow += a[0] > 120 && a[1] > 100 && a[2] + 60 < a[1];
        }
    return c;
}

/* Map on the HUD: the control (text and map). */
static void test_map_on(void **state)
{
    (void)state;
    start_flag(HOL_MINIMAP_HUD);
    counts c = draw();
    print_message("    map on: %d changed, %d in the map, %d panel\n", c.changed, c.in_map,
                  c.panel);
    assert_true(c.in_map > 1000);
    assert_true(c.panel > 300);
}

/* Map off: the text stays, the map's corner is the world's. Then the end
 * screen: the result and the prompt (yellow) stay too. */
static void test_map_off_keeps_text(void **state)
{
    (void)state;
    start_flag(HOL_MINIMAP_OFF);
    const hol_app_view *v = hol_app_get_view(app);
    assert_int_equal(v->map.place, HOL_MINIMAP_OFF);
    counts c = draw();
    print_message("    map off: %d changed, %d in the map, %d panel\n", c.changed,
                  c.in_map, c.panel);
    assert_int_equal(c.in_map, 0);
    assert_true(c.panel > 300);
    step(40, 1); /* 0.93 m north: onto the flag */
    assert_int_equal(hol_app_get_view(app)->state, HOL_APP_DONE);
    c = draw();
    print_message("    end screen, map off: %d panel, %d yellow\n", c.panel, c.yellow);
    assert_int_equal(c.in_map, 0);
    assert_true(c.panel > 300);
    assert_true(c.yellow > 20); /* an 8-pixel em at 240 rows: thin strokes */
}

/* The HUD's text corner (40 x 24 pixels) of a frame whose one line is s. */
static void glyph_shot(const char *s, uint8_t out[24][40][4])
{
    static uint8_t img[W * H * 4];
    hol_frame_desc f = render_fixture_frame(W, H, 30);
    f.flags = HOL_RENDER_HUD_TEXT | HOL_RENDER_BARE;
    f.hud_lines[0] = s;
    f.nhud_lines = 1;
    render_fixture_draw(rnd, &f, W, H, img);
    for (int y = 0; y < 24; y++)
        memcpy(out[y], img + 4 * (y * W), 40 * 4);
}

static int differing(uint8_t a[24][40][4], uint8_t b[24][40][4])
{
    int n = 0;
    for (int y = 0; y < 24; y++)
        for (int x = 0; x < 40; x++)
            for (int c = 0; c < 3; c++)
                if (abs(a[y][x][c] - b[y][x][c]) > 24) {
                    n++;
                    break;
                }
    return n;
}

static void test_every_glyph(void **state)
{
    (void)state;
    static uint8_t box[24][40][4], blank[24][40][4], g[24][40][4];
    glyph_shot("\x01", box); /* a control: the box */
    glyph_shot(" ", blank);
    assert_true(differing(box, blank) > 10);
    int drawn = 0;
    for (int i = 1; i < HOL_FACE_NGLYPH; i++) {
        uint32_t c = hol_face_glyph_at(i).code;
        char s[3] = {(char)c, 0, 0};
        if (c >= 0x80) { /* two bytes of UTF-8 */
            s[0] = (char)(0xC0 | (c >> 6));
            s[1] = (char)(0x80 | (c & 0x3F));
        }
        assert_int_equal(hol_face_index(c), i);
        glyph_shot(s, g);
        int vs_box = differing(g, box), vs_blank = differing(g, blank);
        if (vs_box <= 3)
            fail_msg("U+%04X draws as the missing box (%d pixels differ)", (unsigned)c, vs_box);
        int ink = hol_face_glyph_at(i).w > 0;
        if (ink && vs_blank == 0)
            fail_msg("U+%04X draws nothing", (unsigned)c);
        drawn += ink;
    }
    print_message("    %d glyphs with ink, none the box\n", drawn);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_map_on),
        cmocka_unit_test(test_map_off_keeps_text),
        cmocka_unit_test(test_every_glyph),
    };
    return cmocka_run_group_tests_name("render_hud", tests, setup, teardown);
}
