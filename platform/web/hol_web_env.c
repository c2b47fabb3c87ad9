/* hol_web_env.c - environment.csv on the web (hol_web.h; docs/research.md,
 * "Session metadata"): one row when the page's session starts (platform
 * `web`, once its display rate is measured) and one at every Enter VR
 * (platform `webxr`, once the rate is known, the hands' device with it), in the
 * page's log folder, the row the desktop writes (platform/shell/hol_shell_env.h:
 * its header, its fields escaped and quoted).
 */
#include <emscripten.h>
#include <emscripten/html5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_rec.h"
#include "../shell/hol_shell_env.h"
#include "hol_web.h"

/* hol_web_lib.js: 0 os, 1 runtime (the browser), 2 the controller (XR:
 * the right, else left, input source's profiles[0]; else the first
 * standard gamepad's id), 3 options (the query string), 4 the GL renderer,
 * 5 the XR session's frameRate (returned too; "" and 0 where undefined);
 * the page's store (hol_web_sink.c) */
extern double hol_web_js_env(int what, char *buf, int cap);
extern int hol_web_js_store_open(const char *name, int append);
extern int hol_web_js_store_write(int h, const void *data, int n);
extern int hol_web_js_store_close(int h);
extern int hol_web_js_store_read(const char *name, double off, void *buf, int n);

#define ENV__SKIP 10   /* frames before the rate's count (the first are slow) */
#define ENV__COUNT 60  /* frames the rate is measured over */
#define ENV__ROW 8192
#define ENV__FIELD 1024 /* one field, escaped */

static struct {
    char gl[256];
    int done[2];     /* the web row; the XR session's row */
    long n[2];       /* frames seen (pancake; this XR session) */
    double t0[2], hz[2];
} env;

void hol_web_env_init(void)
{
    hol_web_js_env(4, env.gl, sizeof env.gl);
}

static void env_write(int xr, double hz, int w, int h, uint32_t device)
{
    const hol_rec_meta *m = hol_web_game_meta();
    if (!m)
        return;
    static char row[ENV__ROW + 64], str[4][1024];
    for (int k = 0; k < 4; k++) /* os, runtime, controller, options */
        hol_web_js_env(k, str[k], sizeof str[k]);
    const char *ctl = device ? hol_input_device_name(device) : str[2];
    const hol_shell_env_fields f = {m->session, m->participant, 0, m->study_sha256,
                                    xr ? "webxr" : "web", str[0], str[1], env.gl, ctl, hz,
                                    w > 0 && h > 0 ? w : 0, w > 0 && h > 0 ? h : 0, "", str[3]};
    size_t at = 0;
    int over = hol_shell_env_row(&f, ENV__FIELD, row, ENV__ROW, &at);
    row[at++] = '\n';
    char b; /* the header when the file is new */
    int new_file = hol_web_js_store_read("environment.csv", 0, &b, 1) <= 0;
    int hd = over ? -1 : hol_web_js_store_open("environment.csv", 1);
    int bad = hd < 0 ||
              (new_file && hol_web_js_store_write(hd, HOL_SHELL_ENV_COLUMNS "\n",
                                                  sizeof HOL_SHELL_ENV_COLUMNS)) ||
              hol_web_js_store_write(hd, row, (int)at) | hol_web_js_store_close(hd);
    char hzs[32] = "";
    if (hz > 0)
        snprintf(hzs, sizeof hzs, "%.3f", hz);
    printf("web: environment %s %s Hz%s\n", f.platform, hzs, bad ? ": not written" : "");
}

/* A frame at t_ms; the rate measured over ENV__COUNT frames (unless known).
 * 1 once counted. */
static int env_count(int k, double t_ms)
{
    long n = env.n[k]++;
    if (n == ENV__SKIP)
        env.t0[k] = t_ms;
    else if (n == ENV__SKIP + ENV__COUNT && t_ms > env.t0[k] && env.hz[k] <= 0)
        env.hz[k] = ENV__COUNT * 1000.0 / (t_ms - env.t0[k]);
    return n >= ENV__SKIP + ENV__COUNT;
}

void hol_web_env_pancake(double t_ms)
{
    if (env.done[0] || !env_count(0, t_ms))
        return;
    int cw = 0, ch = 0;
    emscripten_get_canvas_element_size("#canvas", &cw, &ch);
    env.done[0] = 1;
    env_write(0, env.hz[0], cw, ch, 0);
}

void hol_web_env_xr(int on)
{
    if (on) { /* the pancake count starts again after it */
        memset(env.n, 0, sizeof env.n);
        env.done[1] = 0, env.hz[1] = 0;
    }
}

void hol_web_env_xr_frame(double t_ms, uint32_t device)
{
    const hol_web_xr_frame *f = &hol_web_g.xf;
    if (env.done[1])
        return;
    char s[32]; /* XRSession.frameRate where the browser has it */
    double rate = hol_web_js_env(5, s, sizeof s);
    if (rate > 0)
        env.hz[1] = rate;
    /* with frameRate, once an input source is there; else after the count */
    int hands = f->pad[0].present > 0 || f->pad[1].present > 0;
    if (env_count(1, t_ms) || (rate > 0 && hands)) {
        env.done[1] = 1;
        env_write(1, env.hz[1], (int)f->view[0].vp[2], (int)f->view[0].vp[3], device);
    }
}
