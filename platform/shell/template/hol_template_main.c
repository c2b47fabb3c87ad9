/* hol_template_main.c - a new platform's starting point (docs/hacking.md,
 * "Adding a platform"), in the manner of raylib's rcore_template.c: one
 * loop that polls the platform, fills the input record, steps the app,
 * renders and presents. Copy it to platform/NAME/, rename the template_*
 * functions' bodies to the platform's calls, and keep the loop.
 *
 * Contract
 * - `hol_template [--frames N] [--size WxH]` (N 1..1000, default 3; sides
 *   16..4096, default 64x48): opens a headless GL context (OSMesa here;
 *   a window, EGL or a browser canvas on a real platform), creates the app
 *   (core/hol_app.h) and the renderer (render/hol_render.h), starts a flag
 *   level, and for N frames: polls, fills a hol_input, hol_app_step,
 *   hol_app_frame_desc, hol_render_frame, presents. Then it prints the
 *   frames drawn and environment.csv's header and row (the shell's
 *   platform/shell/hol_shell_env.h), and exits 0; 1 on a failure
 *   (reported on stderr), 2 on a bad option (the shell's clash table,
 *   platform/shell/hol_shell_opts.h, checks the options that go together).
 * - make test builds and runs it (make template-run), so it cannot rot.
 * - It includes only core/, render/, platform/shell/ and the GL context's
 *   helper (platform/osmesa/): a platform never includes another.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../../core/hol_app.h"
#include "../../../core/hol_input.h"
#include "../../../core/hol_tile.h"
#include "../../../render/hol_app_frame.h"
#include "../../../render/hol_render.h"
#include "../../osmesa/hol_osmesa.h"
#include "../hol_shell_env.h"
#include "../hol_shell_opts.h"

/* ---- the platform's part: replace these on a real platform ---------------- */

typedef struct template_platform {
    hol_osmesa gl; /* a window and its GL context on a real platform */
    int w, h;
    long frame;
} template_platform;

/* Open the display and make a GL context current: 0 ok, else 1 reported. */
static int template_open(template_platform *p, int w, int h)
{
    char msg[256];
    p->w = w, p->h = h, p->frame = 0;
    if (hol_osmesa_create(&p->gl, w, h, msg, sizeof msg)) {
        fprintf(stderr, "template: %s\n", msg);
        return 1;
    }
    return 0;
}

/* Read the platform's events and devices into one input record: here a
 * fixed clock of 1/60 s a frame, focus, and a slow walk forward. A real
 * platform reads its keys, pads or tracked hands (core/hol_input.h). */
static void template_poll(template_platform *p, hol_input *in)
{
    memset(in, 0, sizeof *in);
    in->time_s = (double)p->frame / 60.0;
    in->flags = HOL_INPUT_FOCUSED;
    in->device = HOL_DEVICE_KEYBOARD;
    in->move[1] = 0.5f;
}

/* Show the frame: a buffer swap on a real platform (eglSwapBuffers, the
 * browser's next animation frame, xrEndFrame). OSMesa draws into memory. */
static void template_present(template_platform *p)
{
    p->frame++;
}

static void template_close(template_platform *p)
{
    hol_osmesa_destroy(&p->gl);
}

/* ---- the loop: the same on every platform ---------------------------------- */

typedef struct template_run {
    hol_app *app;
    hol_render *rnd;
} template_run;

static int template_start(template_run *t)
{
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    if (hol_app_create(&ad, &t->app))
        return 1;
    hol_app_level level;
    memset(&level, 0, sizeof level);
    level.mode = HOL_APP_FLAG;
    level.seed = 3;
    level.cues = HOL_CUE_ALL;
    level.minimap = HOL_MINIMAP_HUD;
    if (hol_tile_resolve("N", -1, &level.flag) || hol_app_start_level(t->app, &level))
        return 1;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = hol_osmesa_getproc;
    rd.world = hol_app_world(t->app);
    return hol_render_create(&rd, &t->rnd) != HOL_OK;
}

static int template_loop(template_platform *p, template_run *t, long frames)
{
    for (long i = 0; i < frames; i++) {
        hol_input in;
        template_poll(p, &in);
        if (hol_app_step(t->app, &in))
            return 1;
        hol_frame_desc fd;
        hol_app_frame_desc(hol_app_get_view(t->app), -1, p->w, p->h, 0, &fd);
        if (hol_render_frame(t->rnd, &fd, NULL))
            return 1;
        template_present(p);
    }
    return 0;
}

/* environment.csv's row as every platform writes it (the shell's). */
static void template_env(const template_platform *p)
{
    char row[4096];
    size_t n;
    const hol_shell_env_fields f = {.session = "template", .platform = "template",
                                    .width = p->w, .height = p->h, .options = "--frames"};
    if (!hol_shell_env_row(&f, 0, row, sizeof row, &n))
        printf("%s\n%.*s\n", HOL_SHELL_ENV_COLUMNS, (int)n, row);
}

static int template_options(int argc, char **argv, long *frames, int *w, int *h)
{
    unsigned char given[HOL_SHELL_OPT_COUNT] = {0};
    for (int i = 1; i < argc; i++) {
        const char *v = i + 1 < argc ? argv[i + 1] : "";
        if (!strcmp(argv[i], "--frames") && (*frames = atol(v)) >= 1 && *frames <= 1000)
            i++;
        else if (!strcmp(argv[i], "--size") && sscanf(v, "%dx%d", w, h) == 2 && *w >= 16 &&
                 *w <= 4096 && *h >= 16 && *h <= 4096)
            i++;
        else {
            fprintf(stderr, "template: '%.40s' is not --frames N (1..1000) or --size WxH\n",
                    argv[i]);
            return 2;
        }
    }
    char clash[200]; /* a platform's options checked against the shell's table */
    if (hol_shell_clash(given, clash, sizeof clash)) {
        fprintf(stderr, "template: %s\n", clash);
        return 2;
    }
    return 0;
}

int main(int argc, char **argv)
{
    long frames = 3;
    int w = 64, h = 48;
    int st = template_options(argc, argv, &frames, &w, &h);
    if (st)
        return st;
    template_platform p;
    template_run t = {0};
    if (template_open(&p, w, h))
        return 1;
    st = template_start(&t) || template_loop(&p, &t, frames);
    if (st)
        fprintf(stderr, "template: the app or the renderer failed\n");
    else
        printf("template: %ld frames of %dx%d drawn\n", p.frame, w, h);
    if (!st)
        template_env(&p);
    hol_render_destroy(t.rnd);
    hol_app_destroy(t.app);
    template_close(&p);
    return st;
}
