/* test_render_lazy.c - a renderer without hol_render_desc.all_programs
 * (the default; the web's first frame, docs/performance.md): a renderer
 * that compiles only the day program at create draws every frame as the one that compiles all 79 at
 * create, pixel for pixel, compiling the others when a frame first needs
 * them or when hol_render_prepare is called.
 *
 * - test_lazy_frames_equal_eager: day, dusk and night with lanterns and
 *   fireflies (the lit programs, their night and firefly variants), in
 *   both orders of the two renderers on one OSMesa context: the same
 *   bytes; the frames draw without a GL error (desc.debug).
 * - test_prepare_counts_down: hol_render_prepare compiles one program a
 *   call and says how many are left: HOL_PROG_SLOTS - 1 programs after
 *   the day one (the lit tiles' have variants without shadows and with
 *   the tile's shadow mask), then 0
 *   and 0 again; the frames after it are the eager renderer's.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../render/hol_program.h"
#include "render_fixture.h"

#define W 96
#define H 72

static render_fixture fx;   /* its renderer made again with all_programs */
static hol_render *lazy;
static uint8_t img_a[W * H * 4], img_b[W * H * 4];

static hol_render *make_lazy(void)
{
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = fx.world;
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1;
    hol_render *r = NULL;
    assert_int_equal(hol_render_create(&rd, &r), HOL_OK);
    return r;
}

static int setup(void **state)
{
    (void)state;
    if (render_fixture_make(&fx, W, H, 7))
        return -1;
    /* the fixture's renderer again, compiling every program at create */
    hol_render_destroy(fx.rnd);
    fx.rnd = NULL;
    return render_fixture_eager(&fx, &fx.rnd);
}

static int teardown(void **state)
{
    (void)state;
    render_fixture_destroy(&fx);
    return 0;
}

static hol_frame_desc frame(int lighting)
{
    hol_frame_desc f = render_fixture_frame(W, H, -25);
    f.flags = HOL_RENDER_MINIMAP;
    f.lighting = lighting;
    f.time_s = 3.0;
    if (lighting) {
        f.nlanterns = 1;
        f.lanterns[0] = f.user.tile;
        f.fireflies = 1;
    }
    return f;
}

static void render(hol_render *r, const hol_frame_desc *f, uint8_t *out)
{
    render_fixture_draw(r, f, W, H, out);
}

static void test_lazy_frames_equal_eager(void **state)
{
    (void)state;
    lazy = make_lazy();
    for (int pass = 0; pass < 2; pass++)
        for (int l = 0; l <= 2; l++) {
            hol_frame_desc f = frame(l);
            render(pass ? fx.rnd : lazy, &f, img_a);
            render(pass ? lazy : fx.rnd, &f, img_b);
            assert_memory_equal(img_a, img_b, sizeof img_a);
        }
    hol_render_destroy(lazy);
}

static void test_prepare_counts_down(void **state)
{
    (void)state;
    lazy = make_lazy();
    for (int left = HOL_PROG_SLOTS - 2; left >= 0; left--)
        assert_int_equal(hol_render_prepare(lazy), left);
    assert_int_equal(hol_render_prepare(lazy), 0);
    for (int l = 0; l <= 2; l++) {
        hol_frame_desc f = frame(l);
        render(lazy, &f, img_a);
        render(fx.rnd, &f, img_b);
        assert_memory_equal(img_a, img_b, sizeof img_a);
    }
    hol_render_destroy(lazy);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lazy_frames_equal_eager),
        cmocka_unit_test(test_prepare_counts_down),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
