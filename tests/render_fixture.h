/* render_fixture.h - the headless renderer the render suites share: an
 * OSMesa context of w x h, a small seeded world and a renderer on top;
 * and the frames the suites draw on any renderer.
 * Header-only; include it once per test program after cmocka.h (its
 * drawing functions assert).
 *
 * Contract
 * - render_fixture_make / render_fixture_destroy: the context, world and
 *   renderer (0, or -1 said on stderr).
 * - render_fixture_eager(f, out): a second renderer on f's world that
 *   compiles every shader program at create (desc.all_programs), as the
 *   headset's; 0, or -1 (the caller destroys *out).
 * - render_fixture_frame(w, h, pitch_deg): a frame description of w x h
 *   at the start (hol_room_start: the middle cell of {4,5} 3 x 3), the eye
 *   at the cell's centre (1.5, 1.6, 1.5) looking north, pitch_deg up
 *   (negative: down), the default field of view; every other field zero.
 * - render_fixture_draw(r, f, w, h, rgba): f drawn by r (HOL_OK asserted)
 *   and its w x h pixels read into rgba (top row first).
 * - render_fixture_draw_hud(r, f, w, h, with, without): f drawn as given,
 *   then with HOL_RENDER_NO_HUD added (f itself unchanged).
 * - Every function is static inline: a file that calls only some (the
 *   suites with a renderer of their own draw with it) pays nothing for the
 *   others and gets no warning.
 */
#ifndef HOL_TEST_RENDER_FIXTURE_H
#define HOL_TEST_RENDER_FIXTURE_H

#include <stdio.h>
#include <string.h>

#include "../core/hol_room.h"
#include "../core/hol_world.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_render.h"

typedef struct render_fixture {
    hol_osmesa gl;
    hol_world *world;
    hol_render *rnd;
} render_fixture;

/* 0 on success; on failure says why on stderr and returns -1. */
static inline int render_fixture_make(render_fixture *f, int w, int h, uint64_t seed)
{
    char msg[256];
    memset(f, 0, sizeof *f);
    if (hol_osmesa_create(&f->gl, w, h, msg, sizeof msg)) {
        fprintf(stderr, "%s\n", msg);
        return -1;
    }
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = seed;
    wd.capacity = 1u << 14;
    if (hol_world_make(&wd, &f->world)) {
        fprintf(stderr, "render fixture: cannot make the world\n");
        return -1;
    }
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = f->world;
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1; /* a test build: every GL error reported */
    if (hol_render_create(&rd, &f->rnd)) {
        fprintf(stderr, "render fixture: cannot create the renderer\n");
        return -1;
    }
    return 0;
}

static inline int render_fixture_eager(const render_fixture *f, hol_render **out)
{
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.world = f->world;
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1;
    rd.all_programs = 1;
    return hol_render_create(&rd, out) ? -1 : 0;
}

static inline void render_fixture_destroy(render_fixture *f)
{
    hol_render_destroy(f->rnd);
    hol_world_destroy(f->world);
    hol_osmesa_destroy(&f->gl);
}

static inline hol_frame_desc render_fixture_frame(int w, int h, double pitch_deg)
{
    hol_frame_desc f;
    memset(&f, 0, sizeof f);
    f.user = hol_room_start();
    f.cam.eye[0] = 1.5;
    f.cam.eye[1] = 1.6;
    f.cam.eye[2] = 1.5;
    f.cam.pitch_deg = pitch_deg;
    f.cam.width = w;
    f.cam.height = h;
    return f;
}

static inline void render_fixture_draw(hol_render *r, const hol_frame_desc *f, int w, int h,
                                       uint8_t *rgba)
{
    assert_int_equal(hol_render_frame(r, f, NULL), HOL_OK);
    hol_render_read_rgba(r, w, h, rgba);
}

static inline void render_fixture_draw_hud(hol_render *r, const hol_frame_desc *f, int w, int h,
                                           uint8_t *with, uint8_t *without)
{
    render_fixture_draw(r, f, w, h, with);
    hol_frame_desc bare = *f;
    bare.flags |= HOL_RENDER_NO_HUD;
    render_fixture_draw(r, &bare, w, h, without);
}

#endif
