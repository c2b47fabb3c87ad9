/* test_render_grow.c - the renderer's static buffers grown as frames need
 * more tile slots (16 at create, then 48, then all 96: llvmpipe clears
 * every buffer it allocates, so a short run allocates few) against a
 * renderer that holds all 96 from create (hol_render_desc.all_programs).
 *
 * - test_grown_frames_equal: a walk of room steps through the forest, each
 *   room state drawn by both renderers: the same bytes every frame, while
 *   the first renderer's buffers grow twice (over 96 tile meshes built, so
 *   the slots are reused after); then the first frames again, whose tiles
 *   (built before the buffers grew, copied over) must still draw the same.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "render_fixture.h"

#define W 96
#define H 72

static render_fixture fx; /* its renderer: 16 slots at create */
static hol_render *full;  /* all 96 at create */
static uint8_t img_a[W * H * 4], img_b[W * H * 4];

static int setup(void **state)
{
    (void)state;
    if (render_fixture_make(&fx, W, H, 11))
        return -1;
    return render_fixture_eager(&fx, &full);
}

static int teardown(void **state)
{
    (void)state;
    hol_render_destroy(full);
    render_fixture_destroy(&fx);
    return 0;
}

/* A frame of room state u from its cell's centre, looking across the room
 * (yaw turning with k, so corners and edges are seen). */
static hol_frame_desc frame(const hol_room *u, int k)
{
    hol_frame_desc f;
    memset(&f, 0, sizeof f);
    f.user = *u;
    f.cam.eye[0] = u->col + 0.5;
    f.cam.eye[1] = 1.6;
    f.cam.eye[2] = u->row + 0.5;
    f.cam.yaw_deg = 45.0 * k;
    f.cam.pitch_deg = -20;
    f.cam.width = W;
    f.cam.height = H;
    f.flags = HOL_RENDER_MINIMAP;
    return f;
}

/* Both renderers draw f: the same bytes; returns the tiles the first built. */
static int both(const hol_frame_desc *f)
{
    hol_render_stats s;
    memset(&s, 0, sizeof s);
    assert_int_equal(hol_render_frame(fx.rnd, f, &s), HOL_OK);
    hol_render_read_rgba(fx.rnd, W, H, img_a);
    assert_int_equal(hol_render_frame(full, f, NULL), HOL_OK);
    hol_render_read_rgba(full, W, H, img_b);
    assert_memory_equal(img_a, img_b, sizeof img_a);
    return (int)s.tiles_built;
}

static void test_grown_frames_equal(void **state)
{
    (void)state;
    hol_room u = hol_room_start();
    hol_room first[3];
    int built = 0, k = 0;
    /* laps round the room's outer ring: each lap ends on other tiles
     * (holonomy), so the walk keeps meeting new ones */
    static const char ring[] = "ESSWWNNE";
    for (; k < 160 && built <= 120; k++) {
        assert_int_equal(hol_world_update(fx.world, &u), HOL_OK);
        if (k < 3)
            first[k] = u;
        hol_frame_desc f = frame(&u, k);
        built += both(&f);
        char c = k == 0 ? 'N' : ring[(k - 1) % 8];
        int d = c == 'N' ? HOL_DIR_N : c == 'E' ? HOL_DIR_E : c == 'S' ? HOL_DIR_S : HOL_DIR_W;
        assert_int_equal(hol_room_step(&u, d), HOL_OK);
    }
    print_message("tile meshes built: %d\n", built);
    assert_true(built > 96); /* grown to 48, to 96, and slots reused */
    for (int i = 0; i < 3; i++) {
        hol_frame_desc f = frame(&first[i], i);
        both(&f);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grown_frames_equal),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
