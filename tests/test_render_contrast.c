/* test_render_contrast.c - the text's contrast measured on rendered pixels
 * (issue 37; WCAG 2's 4.5:1 for text, which the W3C XR Accessibility User
 * Requirements take over). The HUD is drawn by the renderer on OSMesa as
 * every platform draws it (the lines, a caption, the prompt, the overlay),
 * in every language of core/hol_str.h, over the forest by day and by night
 * and over a bright sky; the pixels are read back and the HUD's pixels
 * found as those that differ from the same frame without it. The panel
 * behind the text is the pixels of the panel's colour (within 6 a channel)
 * in the HUD's box; the text is every other pixel of the box, split into
 * the white lines and the yellow prompt by hue. The text's luminance is
 * the 90th percentile of its pixels' (the glyphs' cores; their edges are
 * blended into the panel), the panel's the 95th of its own (its brightest),
 * by WCAG's relative luminance (sRGB decoded); each ratio
 * (L1 + 0.05) / (L2 + 0.05) must be at least 4.5.
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

#include "../core/hol_str.h"
#include "render_fixture.h"

#define W 640
#define H 480

static render_fixture fx;
static uint8_t with[W * H * 4], without[W * H * 4];

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

static double lin(int c)
{
    double s = c / 255.0;
    return s <= 0.04045 ? s / 12.92 : pow((s + 0.055) / 1.055, 2.4);
}

static double luminance(const uint8_t *p)
{
    return 0.2126 * lin(p[0]) + 0.7152 * lin(p[1]) + 0.0722 * lin(p[2]);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double percentile(double *v, int n, double q)
{
    assert_true(n > 0);
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return v[(int)(q * (n - 1))];
}

/* The contrast of the text of class k (0 white, 1 yellow) against the
 * panel in the HUD's box at the top left; the pixels counted go to
 * *out_n. */
static double contrast(int k, int *out_n)
{
    static const uint8_t panel[3] = {24, 28, 34};
    static double text[W * H], back[W * H];
    int x1 = 0, y1 = 0, nt = 0, nb = 0;
    /* the box: the panel-coloured HUD pixels in the left half's top third */
    for (int y = 0; y < H / 3; y++)
        for (int x = 0; x < W / 2; x++) {
            const uint8_t *p = with + 4 * (y * W + x);
            if (!memcmp(p, without + 4 * (y * W + x), 3))
                continue;
            if (abs(p[0] - panel[0]) <= 6 && abs(p[1] - panel[1]) <= 6 &&
                abs(p[2] - panel[2]) <= 6) {
                x1 = x > x1 ? x : x1;
                y1 = y > y1 ? y : y1;
            }
        }
    for (int y = 0; y <= y1; y++)
        for (int x = 0; x <= x1; x++) {
            const uint8_t *p = with + 4 * (y * W + x);
            if (!memcmp(p, without + 4 * (y * W + x), 3))
                continue; /* not the HUD's */
            int d = abs(p[0] - panel[0]) + abs(p[1] - panel[1]) + abs(p[2] - panel[2]);
            if (d <= 18) {
                back[nb++] = luminance(p);
                continue;
            }
            int yellow = p[2] * 2 < p[0];
            if (yellow == k)
                text[nt++] = luminance(p);
        }
    *out_n = nt;
    if (!nt)
        return 0;
    return (percentile(text, nt, 0.90) + 0.05) / (percentile(back, nb, 0.95) + 0.05);
}

static void check_frame(const char *what, hol_frame_desc *f, int prompt)
{
    render_fixture_draw_hud(fx.rnd, f, W, H, with, without);
    for (int k = 0; k < 1 + prompt; k++) {
        int n;
        double c = contrast(k, &n);
        printf("    %-28s %-6s %5d pixels, contrast %.1f:1\n", what, k ? "prompt" : "lines",
               n, c);
        if (n < 100)
            fail_msg("%s: only %d pixels of text found", what, n);
        if (c < 4.5)
            fail_msg("%s: the %s's contrast is %.2f:1, under 4.5:1", what,
                     k ? "prompt" : "lines", c);
    }
}

/* Every language's longest texts on the HUD, with a caption and a prompt,
 * by day, at night and looking up into the sky. */
static void test_hud_contrast(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int lighting;
        double pitch;
    } scene[3] = {{"day", 0, 0}, {"night", 2, 0}, {"sky", 0, 60}};
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (int s = 0; s < 3; s++) {
            hol_frame_desc f = render_fixture_frame(W, H, scene[s].pitch);
            f.lighting = scene[s].lighting;
            f.flags = HOL_RENDER_HUD_TEXT | HOL_RENDER_MINIMAP;
            char steps[64];
            snprintf(steps, sizeof steps, hol_str(l, HOL_S_STEPS_FMT), 12);
            f.hud_lines[0] = hol_str(l, HOL_S_LESSON_2_DONE);
            f.hud_lines[1] = hol_str(l, HOL_S_POINT_CTRL_START);
            f.hud_lines[2] = steps;
            f.hud_lines[3] = hol_str(l, HOL_S_CAP_KEY);
            f.nhud_lines = 4;
            f.prompt = hol_str(l, HOL_S_MOVE_GAMEPAD);
            f.lang = l;
            char what[64];
            snprintf(what, sizeof what, "%s, %s", hol_lang_code(l), scene[s].name);
            check_frame(what, &f, 1);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hud_contrast),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
