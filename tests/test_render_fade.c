/* test_render_fade.c - the safety fade of hol_frame_desc (the headset's
 * boundary): each pixel of a faded frame is the unfaded pixel blended
 * towards the fade colour by exactly `fade` (the model: a*(1-f) + c*f per
 * channel, within 1/255 of rounding); a full fade is the colour alone and
 * needs no view, so an eye outside the room renders; the HUD text stays on
 * top of the fade. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "golden_compare.h"
#include "render_fixture.h"

#define W 96
#define H 72

static render_fixture fx;
static uint8_t img_a[W * H * 4], img_b[W * H * 4];

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

static hol_frame_desc frame(double fade, int flags)
{
    hol_frame_desc f = render_fixture_frame(W, H, -20);
    f.flags = flags;
    f.fade = fade;
    return f;
}

static void render(const hol_frame_desc *f, uint8_t *out)
{
    render_fixture_draw(fx.rnd, f, W, H, out);
}

static void test_partial_fade_blends_every_pixel(void **state)
{
    (void)state;
    static const uint8_t c[3] = HOL_RENDER_FADE_RGB;
    hol_frame_desc f0 = frame(0, HOL_RENDER_NO_HUD);
    render(&f0, img_a);
    const double fades[3] = {0.25, 0.5, 0.8};
    for (int k = 0; k < 3; k++) {
        hol_frame_desc f = frame(fades[k], HOL_RENDER_NO_HUD);
        render(&f, img_b);
        int worst = 0;
        long changed = 0;
        for (int p = 0; p < W * H; p++)
            for (int ch = 0; ch < 3; ch++) {
                double want = img_a[4 * p + ch] * (1 - fades[k]) + c[ch] * fades[k];
                int d = abs(img_b[4 * p + ch] - (int)(want + 0.5));
                worst = d > worst ? d : worst;
                changed += img_b[4 * p + ch] != img_a[4 * p + ch];
            }
        assert_true(worst <= 1);
        assert_true(changed > W * H); /* the fade did something */
    }
}

static void test_full_fade_is_the_colour_anywhere(void **state)
{
    (void)state;
    static const uint8_t def[3] = HOL_RENDER_FADE_RGB;
    hol_frame_desc f = frame(1, 0);
    f.cam.eye[0] = -0.7; /* outside the room: no view could be built */
    f.cam.eye[2] = 3.4;
    /* without the fade the renderer refuses that eye */
    hol_frame_desc g = f;
    g.fade = 0;
    assert_int_equal(hol_render_frame(fx.rnd, &g, NULL), HOL_EARG);
    hol_render_stats st;
    assert_int_equal(hol_render_frame(fx.rnd, &f, &st), HOL_OK);
    assert_int_equal(st.draw_calls, 0);
    hol_render_read_rgba(fx.rnd, W, H, img_a);
    for (int p = 0; p < W * H; p++)
        for (int ch = 0; ch < 3; ch++)
            assert_int_equal(img_a[4 * p + ch], def[ch]);
    f.fade_rgb[0] = 200;
    f.fade_rgb[1] = 10;
    f.fade_rgb[2] = 30;
    render(&f, img_a);
    for (int p = 0; p < W * H; p++)
        for (int ch = 0; ch < 3; ch++)
            assert_int_equal(img_a[4 * p + ch], f.fade_rgb[ch]);
}

static void test_hud_text_stays_over_the_fade(void **state)
{
    (void)state;
    hol_frame_desc f = frame(0.9, HOL_RENDER_MINIMAP);
    render(&f, img_a);
    f.hud_lines[0] = "STEP BACK INTO THE ROOM";
    f.nhud_lines = 1;
    render(&f, img_b);
    /* the text's pixels are not faded: some differ from the faded frame
     * by far more than the 10 % of the scene left under the fade */
    long text = 0;
    for (int p = 0; p < W * H; p++) {
        int d = 0;
        for (int ch = 0; ch < 3; ch++)
            d += abs(img_b[4 * p + ch] - img_a[4 * p + ch]);
        text += d > 150;
    }
    assert_true(text > 20);
}

/* Outside the room (issue 36; hol_frame_desc.outside): every pixel of the
 * view blended towards HOL_RENDER_OUTSIDE_RGB by HOL_RENDER_OUTSIDE_DIM
 * (the forest dimmed, not hidden), but the arrow's, which are its yellow;
 * the panel drawn over a hedge that stands between it and the eye (inside
 * the room the hedge hides it); an eye outside the room drawn where it
 * is, the panel and the arrow over the hedge it stands behind; and that
 * picture as reviewed (tests/golden/outside_way_back.png). */
static void test_outside_dims_shows_arrow_and_panel(void **state)
{
    (void)state;
    static const uint8_t dim[3] = HOL_RENDER_OUTSIDE_RGB, arrow[3] = HOL_RENDER_ARROW_RGB;
    hol_frame_desc f0 = frame(0, HOL_RENDER_NO_HUD);
    render(&f0, img_a);
    hol_frame_desc f = f0;
    f.outside = 1;
    f.outside_arrow[0] = 1.5; /* 1.1 m ahead on the floor, pointing south-east */
    f.outside_arrow[2] = 0.4;
    f.outside_yaw_deg = -135;
    render(&f, img_b);
    long yellow = 0, off = 0;
    for (int p = 0; p < W * H; p++) {
        int ay = 1, ok = 1;
        for (int ch = 0; ch < 3; ch++) {
            double want = img_a[4 * p + ch] * (1 - HOL_RENDER_OUTSIDE_DIM) +
                          dim[ch] * HOL_RENDER_OUTSIDE_DIM;
            ok &= abs(img_b[4 * p + ch] - (int)(want + 0.5)) <= 1;
            ay &= abs(img_b[4 * p + ch] - arrow[ch]) <= 2;
        }
        yellow += ay;
        off += !ok && !ay;
    }
    assert_true(yellow > 40);
    /* inside the room back faces are culled, outside not (the eye may
     * stand in a hedge): a silhouette's edge pixel may differ */
    assert_true(off <= W * H / 1000);
    /* the panel 2.5 m ahead, beyond the north hedge (z 0), facing the eye */
    hol_frame_desc g = frame(0, HOL_RENDER_PANEL | HOL_RENDER_HUD_TEXT);
    g.cam.pitch_deg = -25; /* the panel and the arrow in view */
    g.hud_lines[0] = "OUTSIDE THE ROOM";
    g.nhud_lines = 1;
    g.panel_pos[0] = 1.5;
    g.panel_pos[1] = 1.5;
    g.panel_pos[2] = -1.0;
    g.panel_orient[3] = 1;
    g.panel_px = 0.02;
    long shown[2];
    for (int out = 0; out < 2; out++) {
        g.outside = out;
        g.outside_yaw_deg = 180;
        g.outside_arrow[0] = 1.5;
        g.outside_arrow[2] = 0.4;
        render_fixture_draw_hud(fx.rnd, &g, W, H, img_a, img_b);
        shown[out] = 0;
        for (int p = 0; p < 4 * W * H; p++)
            shown[out] += img_a[p] != img_b[p];
    }
    assert_int_equal(shown[0], 0); /* behind the hedge: hidden */
    assert_true(shown[1] > 400);   /* outside: over it */
    /* From the head where it is (issue 36): the eye 0.3 m beyond the
     * north hedge, looking back south at the room, the north-middle cell
     * the one it sees from (its nearest); the panel 1.5 m ahead, beyond
     * the hedge, over it; the arrow on the floor inside, pointing south, 1.8 m ahead of the
     * view's head
     * (the picture reviewed: the hedge's back dimmed, the panel, the
     * arrow). */
    hol_frame_desc o = g;
    hol_room_step(&o.user, HOL_DIR_N);
    o.cam.eye[2] = -0.3;
    o.cam.yaw_deg = 180;
    o.panel_pos[2] = 1.2;
    o.panel_orient[1] = 1; /* turned to face north, towards the eye */
    o.panel_orient[3] = 0;
    o.outside = 1;
    o.outside_arrow[2] = 1.95; /* 1.8 m ahead of the view's head (z 0.15) */
    render_fixture_draw_hud(fx.rnd, &o, W, H, img_a, img_b);
    long panel = 0;
    yellow = 0;
    for (int p = 0; p < W * H; p++) {
        int ay = 1;
        for (int ch = 0; ch < 3; ch++)
            ay &= abs(img_a[4 * p + ch] - arrow[ch]) <= 2;
        yellow += ay;
        panel += memcmp(img_a + 4 * p, img_b + 4 * p, 3) != 0;
    }
    assert_true(panel > 400);
    assert_true(yellow > 5);
    char dir[512];
    golden_out_dir(dir, sizeof dir, NULL);
    if (golden_update_requested())
        assert_int_equal(hol_png_write_file("tests/golden/outside_way_back.png", img_a, W, H, 0),
                         HOL_OK);
    else
        assert_int_equal(golden_compare("outside_way_back", img_a, W, H, "", dir), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_partial_fade_blends_every_pixel),
        cmocka_unit_test(test_full_fade_is_the_colour_anywhere),
        cmocka_unit_test(test_hud_text_stays_over_the_fade),
        cmocka_unit_test(test_outside_dims_shows_arrow_and_panel),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
