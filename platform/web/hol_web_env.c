/* hol_web_env.c - environment.csv on the web (hol_web.h; docs/research.md,
 * "Session metadata"): one row when the page's session starts (platform
 * `web`, once its display rate is measured) and one at every Enter VR
 * (platform `webxr`, once the rate and the hands' device are known), in the
 * page's log folder, with the desktop's header (play_env.h) and fields
 * escaped and quoted as play_env.c does (hol_text_escape, hol_text_csv).
 */
#include <emscripten.h>
#include <emscripten/html5.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_text.h"
#include "../cli/play_env.h"
#include "hol_web.h"
#include "hol_web_sink.h"

/* hol_web_lib.js: 0 os, 1 runtime (the browser), 2 the GL renderer, 3 the
 * controller (XR: the right, else left, input source's profiles[0]; else
 * the first standard gamepad's id), 4 options (the query string), 5 the
 * XR session's frameRate ("" where undefined) */
extern void hol_web_js_env(int what, char *buf, int cap);

#define ENV__SKIP 10   /* frames before the rate's count (the first are slow) */
#define ENV__COUNT 60  /* frames the rate is measured over */
#define ENV__WAIT 600  /* XR frames waited for the hands' device */

static struct {
    char gl[256];
    int done[2];     /* the web row; the XR session's row */
    long n[2];       /* frames seen (pancake; this XR session) */
    double t0[2], hz[2];
    int w, h;        /* the XR eye */
    uint32_t device; /* the XR session's last device */
} env;

void hol_web_env_init(void)
{
    hol_web_js_env(2, env.gl, sizeof env.gl);
}

/* field s, escaped and quoted, after a comma unless first; 1 if over cap */
static int env_field(char *row, size_t cap, size_t *at, const char *s)
{
    char esc[1024], csv[2100];
    size_t e = hol_text_escape(s, strlen(s), esc, sizeof esc);
    size_t c = e < sizeof esc ? hol_text_csv(esc, e, csv, sizeof csv) : sizeof csv;
    int w = c < sizeof csv ? snprintf(row + *at, cap - *at, "%s%s", *at ? "," : "", csv) : -1;
    if (w < 0 || (size_t)w >= cap - *at)
        return 1;
    *at += (size_t)w;
    return 0;
}

static void env_write(int xr, double hz, int w, int h)
{
    const hol_rec_meta *m = hol_web_game_meta();
    if (!m)
        return;
    static char row[8192];
    char os[512], rt[256], ctl[256], opt[1024], num[3][32] = {"", "", ""};
    hol_web_js_env(0, os, sizeof os);
    hol_web_js_env(1, rt, sizeof rt);
    hol_web_js_env(3, ctl, sizeof ctl);
    hol_web_js_env(4, opt, sizeof opt);
    if (xr && env.device != HOL_DEVICE_NONE) /* the recording's d= name */
        snprintf(ctl, sizeof ctl, "%s", hol_input_device_name(env.device));
    if (hz > 0)
        snprintf(num[0], sizeof num[0], "%.3f", hz);
    if (w > 0 && h > 0)
        snprintf(num[1], sizeof num[1], "%d", w), snprintf(num[2], sizeof num[2], "%d", h);
    const char *f[] = {m->session, m->participant, "", "", xr ? "webxr" : "web", os, rt,
                       env.gl, ctl, num[0], num[1], num[2], "", opt};
    size_t at = 0;
    int over = 0;
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
        over |= env_field(row, sizeof row - 1, &at, f[i]);
    row[at++] = '\n';
    const hol_sink *s = hol_web_sink();
    char b;
    size_t got = 0;
    int new_file = s->read(NULL, "environment.csv", 0, &b, 1, &got) || !got, hd = -1;
    if (over || s->open(NULL, "environment.csv", 1, &hd) ||
        (new_file && s->write(NULL, hd, PLAY_ENV_COLUMNS "\n", sizeof PLAY_ENV_COLUMNS)) ||
        s->write(NULL, hd, row, at) || s->close(NULL, hd))
        printf("web: environment.csv not written: %s\n", over ? "the row is too long"
                                                                : s->why(NULL));
    else
        printf("web: environment %s %s Hz, %sx%s, controller '%s'\n", xr ? "webxr" : "web",
               num[0], num[1], num[2], ctl);
}

/* A frame at t_ms; the rate known over ENV__COUNT frames. 1 when known. */
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
    env_write(0, env.hz[0], cw, ch);
}

void hol_web_env_xr(int on)
{
    if (on) {
        memset(env.n, 0, sizeof env.n); /* the pancake count starts again after */
        env.done[1] = 0, env.hz[1] = 0, env.w = env.h = 0, env.device = HOL_DEVICE_NONE;
        return;
    }
    if (!env.done[1] && env.n[1] > 0) /* ended before all was known */
        env_write(1, env.hz[1], env.w, env.h);
    env.done[1] = 1;
}

void hol_web_env_xr_frame(double t_ms, uint32_t device)
{
    const hol_web_xr_frame *f = &hol_web_g.xf;
    if (env.done[1])
        return;
    if (f->nviews > 0)
        env.w = (int)f->view[0].vp[2], env.h = (int)f->view[0].vp[3];
    if (device != HOL_DEVICE_NONE)
        env.device = device;
    char s[32]; /* XRSession.frameRate where the browser has it */
    hol_web_js_env(5, s, sizeof s);
    double rate = s[0] ? strtod(s, NULL) : 0;
    if (rate > 0)
        env.hz[1] = rate;
    int counted = env_count(1, t_ms);
    int hands = f->pad[0].present > 0 || f->pad[1].present > 0;
    if ((counted || rate > 0) && (env.device != HOL_DEVICE_NONE || hands || env.n[1] >= ENV__WAIT)) {
        env.done[1] = 1;
        env_write(1, env.hz[1], env.w, env.h);
    }
}
