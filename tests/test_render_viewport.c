/* test_render_viewport.c - a frame drawn at a viewport origin (vp_x, vp_y:
 * one eye of a side-by-side XR layer) is the same picture as at the
 * origin (within a code: the sRGB encode's rounding), and the rest of the framebuffer is untouched (its clear keeps to
 * the frame's rectangle).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_room.h"
#include "../render/hol_gl.h"
#include "render_fixture.h"

#define EW 160 /* one eye */
#define EH 120
#define FW (2 * EW + 8)
#define FH (EH + 6)

static void view(hol_frame_desc *f, double yaw)
{
    *f = render_fixture_frame(EW, EH, -25);
    f->cam.eye[0] = 1.45; /* off the cell's centre */
    f->cam.yaw_deg = yaw;
}

/* the framebuffer, rows bottom to top as GL gives them */
static void read_all(const hol_gl *gl, uint8_t *px)
{
    gl->PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, px);
}

static void magenta(const hol_gl *gl)
{
    gl->Disable(GL_SCISSOR_TEST);
    gl->ClearColor(1, 0, 1, 1);
    gl->Clear(GL_COLOR_BUFFER_BIT);
}

static void test_viewport_origin(void **state)
{
    (void)state;
    render_fixture fx;
    assert_int_equal(render_fixture_make(&fx, FW, FH, 7), 0);
    hol_gl gl;
    assert_int_equal(hol_gl_load(&gl, (hol_gl_getproc)hol_osmesa_getproc), HOL_OK);
    size_t n = (size_t)FW * FH * 4;
    uint8_t *ref = malloc(n), *got = malloc(n);
    assert_non_null(ref);
    assert_non_null(got);
    hol_frame_desc left, right;
    view(&left, 10);
    view(&right, -35);
    /* the right eye's picture at the origin */
    magenta(&gl);
    assert_int_equal(hol_render_frame(fx.rnd, &right, NULL), HOL_OK);
    read_all(&gl, ref);
    /* both eyes side by side, the right one at (EW + 8, 6) */
    magenta(&gl);
    assert_int_equal(hol_render_frame(fx.rnd, &left, NULL), HOL_OK);
    right.vp_x = EW + 8;
    right.vp_y = 6;
    assert_int_equal(hol_render_frame(fx.rnd, &right, NULL), HOL_OK);
    read_all(&gl, got);
    long other = 0, same = 0, near = 0, gap = 0;
    for (int y = 0; y < FH; y++)
        for (int x = 0; x < FW; x++) {
            const uint8_t *p = got + 4 * ((size_t)y * FW + x);
            int in_left = x < EW && y < EH, in_right = x >= EW + 8 && y >= 6;
            if (in_right) {
                const uint8_t *q = ref + 4 * ((size_t)(y - 6) * FW + (x - EW - 8));
                int d = 0;
                for (int k = 0; k < 4; k++)
                    d = abs(p[k] - q[k]) > d ? abs(p[k] - q[k]) : d;
                same += d == 0;
                near += d <= 1;
                other++;
            } else if (!in_left) {
                gap += p[0] == 255 && p[1] == 0 && p[2] == 255; /* still magenta */
            }
        }
    /* the right eye equals its render at the origin: every pixel within
     * a code, all but 1 in 1000 the same. The sRGB encode (linear light:
     * docs/lighting.md#linear-light) is steep in the dark (12.92 at 0),
     * so a varying interpolated a last bit differently at another window
     * position may round a pixel to the next code */
    printf("viewport: %ld of %ld pixels the same, %ld within a code\n", same, other, near);
    assert_int_equal(near, other);
    assert_true(same * 1000 >= other * 999);
    assert_int_equal(other, (long)EW * EH);
    /* outside both eyes nothing was cleared or drawn */
    assert_int_equal(gap, (long)FW * FH - 2L * EW * EH);
    /* and the left eye differs from the right (they look different ways) */
    long differ = 0;
    for (int y = 0; y < EH; y++)
        differ += memcmp(got + 4 * (size_t)y * FW, ref + 4 * (size_t)y * FW, 4 * EW) != 0;
    assert_true(differ > EH / 2);
    free(ref);
    free(got);
    render_fixture_destroy(&fx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_viewport_origin),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
