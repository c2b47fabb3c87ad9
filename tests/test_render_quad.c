/* test_render_quad.c - the headset's world panel as a composition layer's
 * image (render/hol_render.h: HOL_RENDER_PANEL_LAYER,
 * hol_render_panel_key, hol_render_panel_image), headless (OSMesa):
 * - an eye drawn with HOL_RENDER_PANEL_LAYER is the eye without the panel,
 *   pixel for pixel (the runtime shows it instead);
 * - the image: against the panel's documented layout (render/hol_hud.h:
 *   the text block 136 font pixels wide, 9 a line + 4 high, its top at the
 *   box's top; the map square, 64 a side, 6 to its right, tops level; the
 *   box 93 high; 4 texels a font pixel): the block's texels opaque, the
 *   rest of the box transparent (0, 0, 0, 0);
 * - the content key: equal for the same content wherever the panel
 *   stands; different when its text or its map changes (so the image is
 *   drawn again exactly then).
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
#include "../render/hol_app_frame.h"
#include "panel_view.h"
#include "../core/hol_face.h"
#include "render_fixture.h"

#define K 4 /* texels a font pixel */
#define IW ((136 + 6 + 64) * K)
#define IH (93 * K)

static void make_view(hol_app_view *v, int map_place)
{
    static const char *const lines[] = {"FIND THE FLAG", "STEPS 3"};
    panel_view(v, map_place, 0, lines, 2, "MENU: MENU");
}

static void eye_desc(const hol_app_view *v, hol_frame_desc *fd)
{
    hol_app_frame_desc(v, 0, 320, 240, 90, fd);
    hol_app_frame_panel(v, fd);
}

static void test_eye_leaves_it_out(void **state)
{
    render_fixture *fx = *state;
    size_t n = 320 * 240 * 4;
    uint8_t *a = malloc(n), *b = malloc(n), *c = malloc(n);
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    for (int map = 0; map < 2; map++) {
        hol_app_view v;
        make_view(&v, map ? HOL_MINIMAP_HUD : HOL_MINIMAP_OFF);
        hol_frame_desc fd;
        eye_desc(&v, &fd);
        render_fixture_draw(fx->rnd, &fd, 320, 240, c); /* with the panel */
        fd.flags |= HOL_RENDER_PANEL_LAYER;
        render_fixture_draw(fx->rnd, &fd, 320, 240, a);
        fd.flags = (fd.flags & ~(uint32_t)HOL_RENDER_PANEL_LAYER) | HOL_RENDER_NO_HUD;
        render_fixture_draw(fx->rnd, &fd, 320, 240, b);
        assert_memory_equal(a, b, n);
        assert_true(memcmp(a, c, n) != 0); /* the control: the panel shows */
    }
    free(a);
    free(b);
    free(c);
}

/* texel (x, y from the top) of an image w wide */
static const uint8_t *at(const uint8_t *img, int w, int x, int y)
{
    return img + 4 * ((size_t)y * (size_t)w + (size_t)x);
}

static void test_image_layout(void **state)
{
    render_fixture *fx = *state;
    uint8_t *img = malloc((size_t)IW * IH * 4);
    assert_non_null(img);
    for (int map = 0; map < 2; map++) {
        hol_app_view v;
        make_view(&v, map ? HOL_MINIMAP_HUD : HOL_MINIMAP_OFF);
        hol_frame_desc fd;
        eye_desc(&v, &fd);
        int w = map ? IW : 136 * K;
        assert_int_equal(hol_render_panel_image(fx->rnd, &fd, w, IH), HOL_OK);
        hol_render_read_rgba(fx->rnd, w, IH, img);
        /* the text block: the rows from the top that are opaque across the
         * block's whole width; a line of the text face (a cap height of 7
         * font pixels) each + 4 (3 lines, nothing wraps) */
        int rows = 0;
        while (rows < IH && at(img, w, 0, rows)[3] == 255 && at(img, w, 136 * K - 1, rows)[3] == 255)
            rows++;
        hol_face_metrics fm;
        hol_face_get_metrics(&fm);
        double lh = (double)(fm.ascent - fm.descent) / fm.units_per_em * 7 * hol_face_em_per_cap();
        assert_true(fabs(rows - (lh * 3 + 4) * K) <= 1);
        long opaque = 0, clear = 0, other = 0;
        for (int y = 0; y < IH; y++)
            for (int x = 0; x < w; x++) {
                const uint8_t *p = at(img, w, x, y);
                int in_text = x < 136 * K && y < rows;
                int in_map = map && x >= (136 + 6) * K && y < 64 * K;
                if (in_text) {
                    opaque += p[3] == 255;
                    other += p[3] != 255;
                } else if (!in_map) {
                    clear += !p[0] && !p[1] && !p[2] && !p[3];
                    other += p[0] || p[1] || p[2] || p[3];
                }
            }
        assert_int_equal(other, 0);
        assert_true(opaque == (long)136 * K * rows);
        assert_true(clear > 0);
        if (map) { /* the map square: opaque texels at its centre */
            const uint8_t *c = at(img, w, (136 + 6 + 32) * K, 32 * K);
            assert_int_equal(c[3], 255);
        }
    }
    free(img);
    hol_frame_desc fd;
    hol_app_view v;
    make_view(&v, HOL_MINIMAP_OFF);
    eye_desc(&v, &fd);
    assert_int_equal(hol_render_panel_image(fx->rnd, &fd, 0, IH), HOL_EARG);
}

static void test_key(void **state)
{
    render_fixture *fx = *state;
    hol_app_view v;
    hol_frame_desc fd;
    make_view(&v, HOL_MINIMAP_HUD);
    eye_desc(&v, &fd);
    uint64_t k0 = hol_render_panel_key(fx->rnd, &fd);
    assert_true(hol_render_panel_key(fx->rnd, &fd) == k0);
    /* the panel elsewhere (the head turned and moved): the same content */
    const double head[3] = {0.9, 1.5, 2.1};
    hol_panel_place(&v.panel, head, 75, 1);
    eye_desc(&v, &fd);
    assert_true(hol_render_panel_key(fx->rnd, &fd) == k0);
    /* nearer in front of a hedge, scaled (core/hol_panel.h): the same image */
    fd.panel_px = HOL_RENDER_PANEL_PX * 0.4;
    assert_true(hol_render_panel_key(fx->rnd, &fd) == k0);
    eye_desc(&v, &fd);
    /* a drawn frame between (the eye's queue) changes nothing */
    assert_int_equal(hol_render_frame(fx->rnd, &fd, NULL), HOL_OK);
    assert_true(hol_render_panel_key(fx->rnd, &fd) == k0);
    /* its text */
    snprintf(v.hud.lines[1], sizeof v.hud.lines[1], "STEPS 4");
    eye_desc(&v, &fd);
    uint64_t k1 = hol_render_panel_key(fx->rnd, &fd);
    assert_true(k1 != k0);
    snprintf(v.hud.hint, sizeof v.hud.hint, "TRIGGER: NEXT");
    eye_desc(&v, &fd);
    uint64_t k2 = hol_render_panel_key(fx->rnd, &fd);
    assert_true(k2 != k1 && k2 != k0);
    /* its map: the objective elsewhere */
    assert_int_equal(hol_tile_parse("Wr", 2, &v.map.objectives[0]), HOL_OK);
    eye_desc(&v, &fd);
    assert_true(hol_render_panel_key(fx->rnd, &fd) != k2);
    /* the map off the panel (in the hand): not the panel's content */
    make_view(&v, HOL_MINIMAP_OFF);
    eye_desc(&v, &fd);
    uint64_t off = hol_render_panel_key(fx->rnd, &fd);
    assert_true(off != k0);
}

static int setup(void **state)
{
    static render_fixture fx;
    if (render_fixture_make(&fx, IW, IH < 240 ? 240 : IH, 5))
        return -1;
    *state = &fx;
    return 0;
}

static int teardown(void **state)
{
    render_fixture_destroy(*state);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_eye_leaves_it_out),
        cmocka_unit_test(test_image_layout),
        cmocka_unit_test(test_key),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
