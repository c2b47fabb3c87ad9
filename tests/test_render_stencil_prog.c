/* test_render_stencil_prog.c - the stencil pass (pass 0: the leaves'
 * polygons, colour writes off) draws with the day's program at every sky
 * (render/hol_render_gpu.c's hol__set_pass). It writes no colour, but
 * SwiftShader (the web) runs the bound program's fragment shader for
 * every pixel of every draw, before its stencil test and whatever the
 * colour mask; at night the program bound before was the lit tiles' with
 * shadow masks, the dearest, and it cost the web's night frame about
 * 20 ms (docs/web-night.md).
 *
 * The referee is GL itself: the renderer's entry points are wrapped
 * (desc.getproc), so the test sees which program object each draw uses
 * and the colour mask it draws under.
 * - test_stencil_pass_day_program: a day frame's colour-masked draws (its
 *   stencil polygons: at least one) all use one program; dusk, night and
 *   the sky between them (with lanterns, a spot, fireflies and a carried
 *   lantern: the lit tiles' dearest programs in use) draw their stencil
 *   polygons with that same program, and draw with other programs after
 *   it (the frame is lit).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "render_fixture.h"

#define W 96
#define H 72

typedef void (*use_fn)(unsigned);
typedef void (*mask_fn)(unsigned char, unsigned char, unsigned char, unsigned char);
typedef void (*elems_fn)(unsigned, int, unsigned, const void *);
typedef void (*arrays_fn)(unsigned, int, int);

/* The wrapped entry points' real ones (getproc), by WRAP_*. */
enum { WRAP_USE, WRAP_MASK, WRAP_ELEMS, WRAP_ARRAYS, WRAP_COUNT };
static hol_osmesa_proc real[WRAP_COUNT];

/* What the wrappers saw since the last reset. */
static struct {
    unsigned prog;     /* the program in use */
    int colour;        /* 1: some colour channel written */
    int masked_draws;  /* draws with every colour channel off */
    unsigned masked[8]; /* the distinct programs of those (0: none) */
    int nmasked;
    int lit_draws;     /* draws with colour on, another program than masked[0] */
} seen;

static void reset(void)
{
    unsigned prog = seen.prog;
    int colour = seen.colour;
    memset(&seen, 0, sizeof seen);
    seen.prog = prog;
    seen.colour = colour;
}

static void note_draw(void)
{
    if (seen.colour) {
        seen.lit_draws += seen.nmasked && seen.prog != seen.masked[0];
        return;
    }
    seen.masked_draws++;
    for (int i = 0; i < seen.nmasked; i++)
        if (seen.masked[i] == seen.prog)
            return;
    if (seen.nmasked < 8)
        seen.masked[seen.nmasked++] = seen.prog;
}

static void w_use(unsigned p)
{
    seen.prog = p;
    ((use_fn)real[WRAP_USE])(p);
}

static void w_mask(unsigned char r, unsigned char g, unsigned char b, unsigned char a)
{
    seen.colour = r || g || b || a;
    ((mask_fn)real[WRAP_MASK])(r, g, b, a);
}

static void w_elems(unsigned mode, int n, unsigned type, const void *idx)
{
    note_draw();
    ((elems_fn)real[WRAP_ELEMS])(mode, n, type, idx);
}

static void w_arrays(unsigned mode, int first, int n)
{
    note_draw();
    ((arrays_fn)real[WRAP_ARRAYS])(mode, first, n);
}

/* The renderer's loader: the four entry points above wrapped, by name. */
static hol_osmesa_proc getproc(const char *name)
{
    static const struct {
        const char *name;
        hol_osmesa_proc wrap;
    } wraps[WRAP_COUNT] = {[WRAP_USE] = {"glUseProgram", (hol_osmesa_proc)w_use},
                           [WRAP_MASK] = {"glColorMask", (hol_osmesa_proc)w_mask},
                           [WRAP_ELEMS] = {"glDrawElements", (hol_osmesa_proc)w_elems},
                           [WRAP_ARRAYS] = {"glDrawArrays", (hol_osmesa_proc)w_arrays}};
    hol_osmesa_proc p = hol_osmesa_getproc(name);
    for (int i = 0; i < WRAP_COUNT; i++)
        if (!strcmp(name, wraps[i].name)) {
            real[i] = p;
            return wraps[i].wrap;
        }
    return p;
}

static render_fixture fx;
static hol_render *rnd;
static uint8_t img[W * H * 4];

static int setup(void **state)
{
    (void)state;
    if (render_fixture_make(&fx, W, H, 7))
        return -1;
    seen.colour = 1; /* GL's initial colour mask */
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = fx.world;
    rd.getproc = getproc;
    rd.debug = 1;
    return hol_render_create(&rd, &rnd) ? -1 : 0;
}

static int teardown(void **state)
{
    (void)state;
    hol_render_destroy(rnd);
    render_fixture_destroy(&fx);
    return 0;
}

/* A frame of the fixture's start looking 25 degrees down at lighting l;
 * lit ones with the user's tile's lantern a spot, the tile north's round,
 * fireflies and a carried lantern beside the eye; cycle 1: between dusk
 * and night. */
static hol_frame_desc frame(int l, int cycle)
{
    hol_frame_desc f = render_fixture_frame(W, H, -25);
    f.lighting = l;
    f.time_s = 3.0;
    if (l) {
        f.nlanterns = 2;
        f.lanterns[0] = f.user.tile;
        f.lantern_spot[0] = 5;
        hol_tile_step(f.user.tile, 0, &f.lanterns[1], NULL);
        f.fireflies = 1;
        f.carried = 1;
        f.carried_pos[0] = 1.3;
        f.carried_pos[1] = 1.2;
        f.carried_pos[2] = 1.4;
        f.cycle = cycle;
        f.night = 0.5;
    }
    return f;
}

static void test_stencil_pass_day_program(void **state)
{
    (void)state;
    hol_frame_desc day = frame(HOL_LIGHT_DAY, 0);
    reset();
    render_fixture_draw(rnd, &day, W, H, img);
    print_message("day: %d stencil draws, %d programs\n", seen.masked_draws, seen.nmasked);
    assert_true(seen.masked_draws >= 1);
    assert_int_equal(seen.nmasked, 1);
    unsigned day_prog = seen.masked[0];
    assert_true(day_prog != 0);
    static const int skies[][2] = {{HOL_LIGHT_DUSK, 0}, {HOL_LIGHT_NIGHT, 0}, {HOL_LIGHT_NIGHT, 1}};
    for (size_t k = 0; k < sizeof skies / sizeof skies[0]; k++) {
        hol_frame_desc f = frame(skies[k][0], skies[k][1]);
        reset();
        render_fixture_draw(rnd, &f, W, H, img);
        print_message("lighting %d cycle %d: %d stencil draws, %d programs (day's: %s), "
                      "%d draws with other programs after\n",
                      skies[k][0], skies[k][1], seen.masked_draws, seen.nmasked,
                      seen.nmasked == 1 && seen.masked[0] == day_prog ? "yes" : "no",
                      seen.lit_draws);
        assert_true(seen.masked_draws >= 1);
        assert_int_equal(seen.nmasked, 1);
        assert_int_equal(seen.masked[0], day_prog);
        assert_true(seen.lit_draws >= 1);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stencil_pass_day_program),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
