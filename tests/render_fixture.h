/* render_fixture.h - the headless renderer the render suites share: an
 * OSMesa context of w x h, a small seeded world and a renderer on top.
 * Header-only; include it once per test program after cmocka.h. */
#ifndef HOL_TEST_RENDER_FIXTURE_H
#define HOL_TEST_RENDER_FIXTURE_H

#include <stdio.h>
#include <string.h>

#include "../core/hol_world.h"
#include "../platform/osmesa/hol_osmesa.h"
#include "../render/hol_render.h"

typedef struct render_fixture {
    hol_osmesa gl;
    hol_world *world;
    hol_render *rnd;
} render_fixture;

/* 0 on success; on failure says why on stderr and returns -1. */
static int render_fixture_make(render_fixture *f, int w, int h, uint64_t seed)
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

static void render_fixture_destroy(render_fixture *f)
{
    hol_render_destroy(f->rnd);
    hol_world_destroy(f->world);
    hol_osmesa_destroy(&f->gl);
}

#endif
