/* hol_web_main.c - the browser platform (emscripten): a WebGL 2 context with
 * a stencil buffer on the page's canvas, the renderer, the session, and
 * the pancake loop (keyboard, pointer-lock mouse, the Gamepad API, touch)
 * on the window's animation frames. While a WebXR session runs, its frames
 * drive the app instead (hol_web_lib.js calls hol_web_xr_step).
 *
 * Like every platform's loop: poll, fill the input record, step the
 * session, render. The page (index.html, page.js) and the WebXR glue
 * (hol_web_lib.js) call the functions marked EMSCRIPTEN_KEEPALIVE.
 */
#include <emscripten.h>
#include <emscripten/html5.h>
#include <GLES3/gl3.h>
#include <stdio.h>
#include <string.h>

#include "../../render/hol_app_frame.h"
#include "../../render/hol_gl.h"
#include "../../core/hol_str.h"
#include "hol_web.h"

hol_web hol_web_g;

/* the page's state and config (hol_web_lib.js) */
extern int hol_web_js_focused(void);
extern void hol_web_js_event(const char *kind, const char *text);
extern void hol_web_js_config(const char *key, char *buf, int cap);
extern void hol_web_js_mark(const char *name);

/* ?snap=DEG: a divisor of 360 in 1..180, as play's --snap-turn; 0 none.
 * -1 when it is not one. */
static int config_snap(void)
{
    char s[16];
    hol_web_js_config("snap", s, sizeof s);
    if (!s[0])
        return 0;
    int v = 0;
    for (const char *p = s; *p; p++) {
        if (*p < '0' || *p > '9' || v > 1000)
            return -1;
        v = v * 10 + (*p - '0');
    }
    return v >= 1 && v <= 180 && 360 % v == 0 ? v : -1;
}

/* ---- devices ---------------------------------------------------------------- */

static EM_BOOL on_key(int type, const EmscriptenKeyboardEvent *e, void *user)
{
    (void)user;
    int k = hol_web_key_from_code(e->code);
    if (k < 0 || e->ctrlKey || e->altKey || e->metaKey)
        return EM_FALSE; /* the browser's own keys stay the browser's */
    if (k == HOL_WEB_K_STATS) { /* F2: the frame time on the view, as the desktop's */
        if (type == EMSCRIPTEN_EVENT_KEYDOWN && !e->repeat)
            hol_web_g.overlay = !hol_web_g.overlay;
        return EM_TRUE;
    }
    hol_web_key(&hol_web_g.pan, k, type == EMSCRIPTEN_EVENT_KEYDOWN, e->repeat);
    return EM_TRUE;
}

static EM_BOOL on_mouse(int type, const EmscriptenMouseEvent *e, void *user)
{
    (void)user;
    hol_web_pancake *p = &hol_web_g.pan;
    if (type == EMSCRIPTEN_EVENT_MOUSEDOWN && e->button == 0 && !p->pointer_locked &&
        !hol_web_g.xr_active)
        emscripten_request_pointerlock("#canvas", 1);
    if (type == EMSCRIPTEN_EVENT_MOUSEMOVE && (p->pointer_locked || (e->buttons & 1))) {
        p->mouse_dx += e->movementX;
        p->mouse_dy += e->movementY;
    }
    return EM_FALSE;
}

static EM_BOOL on_pointerlock(int type, const EmscriptenPointerlockChangeEvent *e, void *user)
{
    (void)type, (void)user;
    hol_web_g.pan.pointer_locked = e->isActive;
    return EM_FALSE;
}

static EM_BOOL on_blur(int type, const EmscriptenFocusEvent *e, void *user)
{
    (void)type, (void)e, (void)user;
    /* keys released while the page had no focus never come up */
    memset(hol_web_g.pan.held, 0, sizeof hol_web_g.pan.held);
    hol_web_g.pan.touch_buttons = 0;
    return EM_FALSE;
}

/* Touch: a finger landing on the left half is the walking stick, one on
 * the right half drags the look. */
static struct {
    long stick_id, look_id;
    double sx, sy, lx, ly;
} touch = {-1, -1, 0, 0, 0, 0};

static EM_BOOL on_touch(int type, const EmscriptenTouchEvent *e, void *user)
{
    (void)user;
    hol_web_pancake *p = &hol_web_g.pan;
    double cw = 0, ch = 0;
    emscripten_get_element_css_size("#canvas", &cw, &ch);
    double radius = (cw < ch ? cw : ch) * 0.12 + 1;
    for (int i = 0; i < e->numTouches; i++) {
        const EmscriptenTouchPoint *t = &e->touches[i];
        if (!t->isChanged)
            continue;
        p->touch_used = 1;
        if (type == EMSCRIPTEN_EVENT_TOUCHSTART) {
            if (t->targetX < cw / 2 && touch.stick_id < 0)
                touch.stick_id = t->identifier, touch.sx = t->targetX, touch.sy = t->targetY;
            else if (touch.look_id < 0)
                touch.look_id = t->identifier, touch.lx = t->targetX, touch.ly = t->targetY;
        } else if (type == EMSCRIPTEN_EVENT_TOUCHMOVE) {
            if (t->identifier == touch.stick_id) {
                double x = (t->targetX - touch.sx) / radius, y = -(t->targetY - touch.sy) / radius;
                double m = x * x + y * y > 1 ? 1 / __builtin_sqrt(x * x + y * y) : 1;
                p->touch_move[0] = (float)(x * m);
                p->touch_move[1] = (float)(y * m);
            } else if (t->identifier == touch.look_id) {
                p->touch_dx += t->targetX - touch.lx;
                p->touch_dy += t->targetY - touch.ly;
                touch.lx = t->targetX, touch.ly = t->targetY;
            }
        } else { /* end, cancel */
            if (t->identifier == touch.stick_id) {
                touch.stick_id = -1;
                p->touch_move[0] = p->touch_move[1] = 0;
            } else if (t->identifier == touch.look_id) {
                touch.look_id = -1;
            }
        }
    }
    return EM_TRUE;
}

/* The on-screen buttons (page.js): HOL_BTN_* bit held or released. */
EMSCRIPTEN_KEEPALIVE void hol_web_touch_button(int bit, int down)
{
    hol_web_pancake *p = &hol_web_g.pan;
    uint32_t b = (uint32_t)bit & HOL_BTN_ALL;
    if (down) {
        p->touch_taps |= b & ~p->touch_buttons;
        p->touch_buttons |= b;
    } else {
        p->touch_buttons &= ~b;
    }
    p->touch_used = 1;
}

/* The first connected gamepad with the standard mapping, sampled. */
static void poll_gamepad(hol_web_pancake *p)
{
    p->pad_connected = 0;
    if (emscripten_sample_gamepad_data() != EMSCRIPTEN_RESULT_SUCCESS)
        return;
    int n = emscripten_get_num_gamepads();
    for (int i = 0; i < n; i++) {
        EmscriptenGamepadEvent g;
        if (emscripten_get_gamepad_status(i, &g) != EMSCRIPTEN_RESULT_SUCCESS || !g.connected ||
            strcmp(g.mapping, "standard"))
            continue;
        p->pad_connected = 1;
        p->pad_standard = 1;
        for (int a = 0; a < 4; a++)
            p->pad_axes[a] = a < g.numAxes ? (float)g.axis[a] : 0.0f;
        for (int b = 0; b < HOL_WEB_PAD_BUTTONS; b++)
            p->pad_button[b] = b < g.numButtons && g.digitalButton[b];
        return;
    }
}

/* What the page and the tests may ask (numbers, so no strings cross):
 * 0 app steps, 1 XR frames, 2 XR frames with two views, 3 XR frames
 * focused, 4 the app state (hol_app_state), 5 paused, 6 room steps in the
 * level, 7 the session is over, 8 failed, 9 head x, 10 head z, 11 cell
 * column, 12 cell row, 13 the level clock, 14 yaw, 15 the device the
 * prompts name (HOL_DEVICE_*), 16 the looping sound sources playing
 * (0 before the first gesture, with ?sound=0, or without WebAudio), 17
 * the head outside the room (hol_app_view.outside.on), 18 the floor
 * arrow's yaw, 19 and 20 the room's columns and rows, 21 its cell (m),
 * 22 the next room step of the walk to the objective (hol_app_walk:
 * 'N', 'E', 'S', 'W' as a number; 0 none), 23
 * the tracked hands at the last XR frame (bits: 1, 2 the left's and the
 * right's joints; 4, 8 their palms up and open: hol_web_xr.h), 24 the
 * body parts drawn (controllers and hands: hol_app_view.body), 25 the
 * questionnaire item's value chosen now (hud.ask_value: likert the
 * number, choice its index). */
EMSCRIPTEN_KEEPALIVE double hol_web_state(int what)
{
    hol_web *w = &hol_web_g;
    const hol_app_view *v = hol_web_game_app() ? hol_app_get_view(hol_web_game_app()) : NULL;
    switch (what) {
    case 0: return (double)w->frames;
    case 1: return (double)w->xr_frames;
    case 2: return (double)w->xr_two_views;
    case 3: return (double)w->xr_focused;
    case 7: return w->over;
    case 8: return w->failed;
    case 16: return hol_web_sound_active();
    case 23: return w->xr.hands;
    default: break;
    }
    if (!v)
        return -1;
    switch (what) {
    case 4: return v->state;
    case 5: return v->paused;
    case 6: return v->hud.steps;
    case 9: return v->head[0];
    case 10: return v->head[2];
    case 11: return v->user.col;
    case 12: return v->user.row;
    case 13: return v->hud.elapsed_s;
    case 14: return v->yaw_deg;
    case 15: return v->hud.device;
    case 17: return v->outside.on;
    case 18: return v->outside.arrow_yaw_deg;
    case 19: return hol_room_cols(&v->user);
    case 20: return hol_room_rows(&v->user);
    case 21: return v->cell_m;
    case 22: {
        uint8_t walk[1];
        return hol_app_walk(hol_web_game_app(), walk, 1) > 0 ? hol_dir_to_char(walk[0]) : 0;
    }
    case 24: return (v->body.hand[0].kind != 0) + (v->body.hand[1].kind != 0);
    case 25: return v->hud.ask_value;
    default: return -1;
    }
}

/* ---- the loop ------------------------------------------------------------- */

void hol_web_stats_add(double c0)
{
    hol_web *w = &hol_web_g;
    double now = emscripten_get_now();
    w->cpu_total_ms += now - c0;
    w->cpu_total_frames++;
    w->stats_ms += now - c0;
    w->stats_frames++;
    if (w->stats_t0 <= 0 || now < w->stats_t0) {
        w->stats_t0 = now;
        w->stats_ms = 0;
        w->stats_frames = 0;
        snprintf(w->overlay_text, sizeof w->overlay_text, "FPS - CPU - MS");
    } else if (now - w->stats_t0 >= 1000) {
        snprintf(w->overlay_text, sizeof w->overlay_text, "FPS %.1f CPU %.1f MS",
                 w->stats_frames * 1000.0 / (now - w->stats_t0), w->stats_ms / w->stats_frames);
        w->stats_t0 = now;
        w->stats_ms = 0;
        w->stats_frames = 0;
    }
}

/* The mean main-thread ms of the frames (pancake and XR: step, and the GL
 * calls issued) since the last reset; reset: start again. -1: no frame. */
EMSCRIPTEN_KEEPALIVE double hol_web_cpu_mean_ms(int reset)
{
    hol_web *w = &hol_web_g;
    double m = w->cpu_total_frames ? w->cpu_total_ms / w->cpu_total_frames : -1;
    if (reset)
        w->cpu_total_ms = 0, w->cpu_total_frames = 0;
    return m;
}

/* F2's line while it is on (the tests read it), else NULL. */
EMSCRIPTEN_KEEPALIVE const char *hol_web_overlay(void)
{
    return hol_web_g.overlay ? hol_web_g.overlay_text : NULL;
}

/* The prompt line the HUD shows (on the world panel in VR: "LEFT PINCH:
 * menu" in a session's first seconds with hands), for the tests. */
EMSCRIPTEN_KEEPALIVE const char *hol_web_hint(void)
{
    return hol_web_game_app() ? hol_app_get_view(hol_web_game_app())->hud.hint : "";
}

/* Where the first frame's time goes (performance.now() at: main's start,
 * after the GL context, after the game - the navigator's table, the
 * world, the level -, after the renderer), told with the first frame. */
static double boot_ms[4];

#define HOL_WEB_UNTOLD "?"

/* Why the game is paused now (NULL: it is not), for the page's status. */
static const char *pause_reason(const hol_input *in, const hol_app_view *v)
{
    hol_web *w = &hol_web_g;
    int l = hol_web_game_lang();
    if (!v->paused)
        return NULL;
    if (!(in->flags & HOL_INPUT_FOCUSED) || (in->flags & HOL_INPUT_HEADSET_OFF)) {
        if (!w->xr_active)
            return hol_str(l, HOL_S_PAUSE_UNFOCUSED);
        return w->xf.visibility < 0.5f || (in->flags & HOL_INPUT_HEADSET_OFF)
                   ? hol_str(l, HOL_S_PAUSE_HEADSET_OFF)
                   : hol_str(l, HOL_S_PAUSE_SYSTEM_MENU);
    }
    if (in->flags & HOL_INPUT_DEVICE_LOST)
        return hol_str(l, HOL_S_PAUSE_PAD_GONE);
    return hol_str(l, HOL_S_PAUSE_MENU);
}

/* The page's visibilitychange (XR): the next step tells its reason anew;
 * hidden (off: the headset taken off, a session that runs no frames then),
 * the next XR record says the headset was off (core/hol_input.h). */
EMSCRIPTEN_KEEPALIVE void hol_web_pause_retell(int off)
{
    hol_web_g.pause_told = HOL_WEB_UNTOLD;
    hol_web_g.xr_off |= off;
}

static void tell_pause(const hol_input *in)
{
    hol_web *w = &hol_web_g;
    const char *why = pause_reason(in, hol_app_get_view(hol_web_game_app()));
    if (why == w->pause_told)
        return;
    w->pause_told = why;
    hol_web_js_event(why ? "pause" : "resume", why ? why : "");
}

/* Time since the start, never going back. */
static double now_s(double t_ms)
{
    double t = (t_ms - hol_web_g.t0_ms) / 1000.0;
    if (t < hol_web_g.last_t)
        t = hol_web_g.last_t;
    hol_web_g.last_t = t;
    return t;
}

int hol_web_step(const hol_input *in)
{
    hol_web *w = &hol_web_g;
    int rc = hol_web_game_step(in);
    w->frames++;
    if (rc < 0) {
        w->failed = w->over = 1;
        hol_web_js_event("failed", "the session failed (see the console)");
        return 1;
    }
    if (hol_app_get_events(hol_web_game_app())->level_started)
        hol_render_invalidate(w->rnd);
    hol_web_sound_step(rc != 0);
    if (rc == 0)
        tell_pause(in);
    if (rc > 0) {
        w->over = 1;
        hol_web_game_print_end();
        hol_web_game_finish();
        hol_web_js_event("over", "");
        return 1;
    }
    return 0;
}

static EM_BOOL pancake_frame(double t_ms, void *user)
{
    (void)user;
    hol_web *w = &hol_web_g;
    if (!w->xr_active && !w->failed)
        hol_web_env_pancake(t_ms);
    if (w->xr_active || w->failed || (w->over && w->drawn_over))
        return EM_TRUE; /* the XR session draws, or nothing is left to do */
    double c0 = emscripten_get_now();
    if (!w->over) {
        double t = now_s(t_ms), dt = t - w->last_frame_t;
        w->last_frame_t = t;
        hol_web_pancake *p = &w->pan;
        p->focused = hol_web_js_focused();
        poll_gamepad(p);
        hol_input in;
        hol_web_pancake_input(p, t, dt, hol_app_get_view(hol_web_game_app())->yaw_deg, &in);
        hol_web_step(&in);
    }
    /* once over, the last view is drawn once more (under the page's logs) */
    w->drawn_over = w->over;
    int cw = 0, ch = 0;
    emscripten_get_canvas_element_size("#canvas", &cw, &ch);
    if (cw < 16 || ch < 16)
        return EM_TRUE;
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(hol_web_game_app()), -1, cw, ch, 0, &fd);
    fd.overlay = hol_web_overlay();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    hol_err err = hol_render_frame(w->rnd, &fd, NULL);
    if (!err && (cw != w->drawn_w || ch != w->drawn_h)) {
        w->drawn_w = cw; /* the first frame, or a resize: one error check
                            (glGetError waits for the GL: never per frame) */
        w->drawn_h = ch;
        err = hol_render_check(w->rnd);
    }
    if (err) {
        printf("web: rendering failed\n");
        w->failed = w->over = 1;
        hol_web_js_event("failed", "rendering failed");
    } else if (w->drawn_first && w->progs_left > 0) {
        /* the programs the first frame did not need, all in the frame after
         * it (their status queries wait for the GL: never later in play) */
        while ((w->progs_left = hol_render_prepare(w->rnd)) > 0)
            ;
        if (w->progs_left < 0)
            printf("web: a shader program did not compile (a frame that needs it fails)\n");
    } else if (!w->drawn_first) {
        w->drawn_first = 1; /* performance.now(): since the page's navigation began */
        double now = emscripten_performance_now();
        hol_web_js_mark("holonomy-first-frame");
        printf("web: first frame %.0f ms after the page began loading: main at %.0f ms (the "
               "page, the wasm's download and compile), GL context %.0f ms, the game (the "
               "navigator's table, the world) %.0f ms, the renderer %.0f ms, the first frame "
               "%.0f ms\n",
               now, boot_ms[0], boot_ms[1] - boot_ms[0], boot_ms[2] - boot_ms[1],
               boot_ms[3] - boot_ms[2], now - boot_ms[3]);
    }
    hol_web_stats_add(c0);
    return EM_TRUE;
}

/* The renderer's GL functions (render/hol_gl.h's list), linked by name:
 * emscripten_webgl_get_proc_address would link every WebGL function
 * emscripten has (57 KB of JS, a 4 KB table in the wasm; docs/web.md). */
static hol_render_proc gl_getproc(const char *name)
{
    static const struct {
        const char *name;
        hol_render_proc fn;
    } fns[] = {
#define GL_FN(type, fn, str) {str, (hol_render_proc)gl##fn},
        HOL_GL_FUNCS(GL_FN)
#undef GL_FN
    };
    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++)
        if (!strcmp(fns[i].name, name))
            return fns[i].fn;
    return NULL;
}

/* The WebGL 2 context: depth, 8 stencil bits, no antialiasing (the
 * stencil portals' edges are the renderer's business). */
static int make_gl(void)
{
    EmscriptenWebGLContextAttributes a;
    emscripten_webgl_init_context_attributes(&a);
    a.majorVersion = 2;
    a.minorVersion = 0;
    a.depth = EM_TRUE;
    a.stencil = EM_TRUE;
    a.antialias = EM_FALSE;
    a.alpha = EM_FALSE;
    a.premultipliedAlpha = EM_FALSE;
    a.powerPreference = EM_WEBGL_POWER_PREFERENCE_HIGH_PERFORMANCE;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE ctx = emscripten_webgl_create_context("#canvas", &a);
    if (ctx <= 0 || emscripten_webgl_make_context_current(ctx) != EMSCRIPTEN_RESULT_SUCCESS)
        return 1;
    hol_web_g.gl = (int)ctx;
    GLint stencil = 0;
    glGetIntegerv(GL_STENCIL_BITS, &stencil);
    printf("web: WebGL 2 context: %s, %d stencil bits\n",
           (const char *)glGetString(GL_RENDERER), (int)stencil);
    return stencil < 8;
}

static void listen(void)
{
    const char *win = EMSCRIPTEN_EVENT_TARGET_WINDOW;
    emscripten_set_keydown_callback(win, NULL, 1, on_key);
    emscripten_set_keyup_callback(win, NULL, 1, on_key);
    emscripten_set_mousedown_callback("#canvas", NULL, 1, on_mouse);
    emscripten_set_mousemove_callback(win, NULL, 1, on_mouse);
    emscripten_set_pointerlockchange_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, NULL, 1,
                                              on_pointerlock);
    emscripten_set_blur_callback(win, NULL, 1, on_blur);
    emscripten_set_touchstart_callback("#canvas", NULL, 1, on_touch);
    emscripten_set_touchmove_callback("#canvas", NULL, 1, on_touch);
    emscripten_set_touchend_callback("#canvas", NULL, 1, on_touch);
    emscripten_set_touchcancel_callback("#canvas", NULL, 1, on_touch);
}

int main(void)
{
    hol_web *w = &hol_web_g;
    w->check_frame = -1;
    w->pause_told = HOL_WEB_UNTOLD;
    char msg[256] = "";
    boot_ms[0] = emscripten_performance_now();
    hol_web_js_mark("holonomy-main");
    if (make_gl()) {
        hol_web_js_event("failed", "this browser has no WebGL 2 with a stencil buffer");
        return 1;
    }
    hol_web_env_init();
    boot_ms[1] = emscripten_performance_now();
    hol_web_js_mark("holonomy-gl");
    w->pan.snap_deg = config_snap();
    char seated[4];
    hol_web_js_config("seated", seated, sizeof seated);
    w->pan.seated = !strcmp(seated, "1"); /* ?seated=1 */
    if (w->pan.snap_deg < 0) {
        hol_web_js_event("failed", "snap is not a divisor of 360 in 1..180");
        return 1;
    }
    if (hol_web_sound_config()) {
        hol_web_js_event("failed", "sound is not 0 or 1");
        return 1;
    }
    if (hol_web_game_open(msg, sizeof msg)) {
        printf("web: %s\n", msg);
        hol_web_js_event("failed", msg);
        return 1;
    }
    boot_ms[2] = emscripten_performance_now();
    hol_web_js_mark("holonomy-game");
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = gl_getproc;
    char dbg[8];
    hol_web_js_config("gldebug", dbg, sizeof dbg); /* ?gldebug=1: check every frame */
    rd.debug = dbg[0] && strcmp(dbg, "0");
    rd.world = hol_app_world(hol_web_game_app());
    /* the day program now, the others in the second frame (prepare) */
    w->progs_left = 1;
    if (hol_render_create(&rd, &w->rnd)) {
        hol_web_js_event("failed", "cannot initialise the renderer on this WebGL context");
        return 1;
    }
    w->t0_ms = boot_ms[3] = emscripten_performance_now();
    hol_web_js_mark("holonomy-renderer");
    listen();
    emscripten_request_animation_frame_loop(pancake_frame, NULL);
    hol_web_js_event("ready", "");
    return 0;
}
