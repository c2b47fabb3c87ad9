/* hol_web_xr_loop.c - the WebXR frames: the glue (hol_web_lib.js) copies
 * each XRFrame into hol_web_g.xf and calls hol_web_xr_step, which steps the
 * session with the frame's record and draws both eyes into the layer's
 * framebuffer, each in its viewport, as the headset build draws its
 * swapchains (platform/openxr: the eyes where they are, the safety fade,
 * each eye's own cell, the hand map on the left grip).
 */
#include <emscripten.h>
#include <GLES3/gl3.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_motion.h"
#include "../../render/hol_app_frame.h"
#include "../shell/hol_shell_seat.h"
#include "../shell/hol_xr_quad.h"
#include "hol_web.h"

extern void hol_web_js_event(const char *kind, const char *text);
extern void hol_web_js_config(const char *key, char *buf, int cap);
extern int hol_web_js_pulse(int hand, double amplitude, int duration_ms);

#define HOL__MARGIN 0.15 /* the motion's default hedge margin */
#define HOL__FIT_NOTE_S 12.0 /* seconds the fit stays on the HUD */

/* Offsets (in floats) of hol_web_xr_frame's fields, for the glue. */
enum {
    HOL__OFF_FRAME_FLOATS = 0, HOL__OFF_NVIEWS, HOL__OFF_VISIBILITY, HOL__OFF_HEAD_VALID,
    HOL__OFF_HEAD_POS, HOL__OFF_HEAD_QUAT, HOL__OFF_BOUNDS, HOL__OFF_VIEW, HOL__OFF_VIEW_FLOATS,
    HOL__OFF_VIEW_VP, HOL__OFF_VIEW_PROJ, HOL__OFF_VIEW_POS, HOL__OFF_VIEW_QUAT, HOL__OFF_PAD,
    HOL__OFF_PAD_FLOATS, HOL__OFF_PAD_PRESENT, HOL__OFF_PAD_TOUCH, HOL__OFF_PAD_GRIP_VALID,
    HOL__OFF_PAD_GRIP_POS, HOL__OFF_PAD_GRIP_QUAT, HOL__OFF_PAD_BUTTON, HOL__OFF_PAD_AXES,
    HOL__OFF_PAD_HAND, HOL__OFF_PAD_JOINTS_VALID, HOL__OFF_PAD_JOINT
};

EMSCRIPTEN_KEEPALIVE int hol_web_xr_offset(int what)
{
#define F(x) (int)((x) / sizeof(float))
    static const int off[] = {
        F(sizeof(hol_web_xr_frame)),
        F(offsetof(hol_web_xr_frame, nviews)),
        F(offsetof(hol_web_xr_frame, visibility)),
        F(offsetof(hol_web_xr_frame, head_valid)),
        F(offsetof(hol_web_xr_frame, head_pos)),
        F(offsetof(hol_web_xr_frame, head_quat)),
        F(offsetof(hol_web_xr_frame, bounds)),
        F(offsetof(hol_web_xr_frame, view)),
        F(sizeof(hol_web_xr_view)),
        F(offsetof(hol_web_xr_view, vp)),
        F(offsetof(hol_web_xr_view, proj)),
        F(offsetof(hol_web_xr_view, pos)),
        F(offsetof(hol_web_xr_view, quat)),
        F(offsetof(hol_web_xr_frame, pad)),
        F(sizeof(hol_web_xr_pad)),
        F(offsetof(hol_web_xr_pad, present)),
        F(offsetof(hol_web_xr_pad, touch_layout)),
        F(offsetof(hol_web_xr_pad, grip_valid)),
        F(offsetof(hol_web_xr_pad, grip_pos)),
        F(offsetof(hol_web_xr_pad, grip_quat)),
        F(offsetof(hol_web_xr_pad, button)),
        F(offsetof(hol_web_xr_pad, axes)),
        F(offsetof(hol_web_xr_pad, hand)),
        F(offsetof(hol_web_xr_pad, joints_valid)),
        F(offsetof(hol_web_xr_pad, joint)),
    };
#undef F
    return what >= 0 && what < (int)(sizeof off / sizeof off[0]) ? off[what] : -1;
}

EMSCRIPTEN_KEEPALIVE float *hol_web_xr_frame_buffer(void)
{
    return (float *)&hol_web_g.xf;
}

/* The session began (1) or ended (0). */
EMSCRIPTEN_KEEPALIVE void hol_web_xr_active(int on)
{
    hol_web *w = &hol_web_g;
    w->xr_active = on;
    w->drawn_over = 0;
    w->xr_checked = 0;
    /* every session's first frame with a head re-places the room around it,
     * as a recentre does: the head's place in the new reference space is
     * not a walk from where the pancake view (or the last session) stood */
    w->xr_recentred = on;
    w->xr_off = 0; /* a hidden of the last session is not this one's */
    if (on) {
        memset(&w->xr, 0, sizeof w->xr);
        w->xr.last_t = w->last_t;
        hol_render_invalidate(w->rnd);
    }
    hol_web_env_xr(on);
    printf("web: xr session %s after %ld XR frames\n", on ? "started" : "ended", w->xr_frames);
}

/* Read both eyes back at XR frame `frame` (make web-test). */
EMSCRIPTEN_KEEPALIVE void hol_web_check_request(int frame)
{
    hol_web_g.check_frame = frame;
}

EMSCRIPTEN_KEEPALIVE uint8_t *hol_web_check_pixels(int eye)
{
    return eye >= 0 && eye < 4 ? hol_web_g.check_px[eye] : NULL;
}

/* Read the eye's viewport back into check slot k (rows bottom to top). */
static void check_read(int k, const hol_frame_desc *fd)
{
    hol_web *w = &hol_web_g;
    int ew = fd->cam.width, eh = fd->cam.height;
    free(w->check_px[k]);
    w->check_px[k] = malloc((size_t)ew * (size_t)eh * 4);
    if (!w->check_px[k])
        return;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(fd->vp_x, fd->vp_y, ew, eh, GL_RGBA, GL_UNSIGNED_BYTE, w->check_px[k]);
    w->check_w[k] = ew;
    w->check_h[k] = eh;
}

/* The eye's read back (rows bottom to top, as GL gives them), and the
 * camera that drew it, for the test to render the same eye with OSMesa. */
static void check_eye(int e, const hol_frame_desc *fd)
{
    hol_web *w = &hol_web_g;
    int ew = fd->cam.width, eh = fd->cam.height;
    check_read(e, fd);
    if (!w->check_px[e])
        return;
    const hol_camera *c = &fd->cam;
    printf("web: check eye %d frame %ld render --fireflies %.17g --eye %.9g,%.9g,%.9g "
           "--orient %.9g,%.9g,%.9g,%.9g --tan %.17g,%.17g,%.17g,%.17g --size %dx%d cell %d,%d\n",
           e, w->xr_frames, fd->fireflies ? fd->time_s : 0.0, c->eye[0], c->eye[1], c->eye[2], c->orient[0], c->orient[1],
           c->orient[2], c->orient[3], c->tan_left, c->tan_right, c->tan_down, c->tan_up, ew, eh,
           fd->user.col, fd->user.row);
}

/* The world panel as a WebXR quad layer (XRQuadLayer, where the glue
 * got one: hol_web_lib.js, HolXR.quadSetup): the eyes leave it out, and
 * after each step the glue asks for its place (hol_web_xr_panel_place)
 * and, when its content changed, draws it (hol_web_xr_panel_draw). */
static struct {
    int on;
    hol_xr_quad_cache cache;
    float out[10]; /* pos 3, quat 4, width, height, map */
    const hol_app_view *v;
    float fade;
    int covered; /* the last frame's panel.covered */
} quad;

EMSCRIPTEN_KEEPALIVE void hol_web_xr_panel_quad(int on)
{
    quad.on = on;
    hol_xr_quad_forget(&quad.cache);
}

EMSCRIPTEN_KEEPALIVE float *hol_web_xr_panel_buffer(void)
{
    return quad.out;
}

/* The panel of the last step, in the reference space (out): 0 none this
 * frame (no panel, the view faded out, or scenery nearer than the panel
 * can come: the eyes draw it, depth-tested, core/hol_panel.h), 1
 * unchanged, 2 its content changed (draw it). force: a new texture (the
 * layer's needsRedraw). */
EMSCRIPTEN_KEEPALIVE int hol_web_xr_panel_place(int force)
{
    const hol_app_view *v = quad.v;
    if (!quad.on || !v || quad.fade >= 1 || v->panel.covered)
        return 0;
    hol_frame_desc fd;
    hol_app_frame_desc(v, 0, 16, 16, 0, &fd);
    hol_app_frame_panel(v, &fd);
    if (fd.flags & HOL_RENDER_NO_HUD)
        return 0;
    int map = (fd.flags & HOL_RENDER_MINIMAP) && !(fd.flags & HOL_RENDER_MINIMAP_HAND);
    hol_xr_quad q;
    hol_xr_quad_place(&hol_web_g.xr.calib, fd.panel_pos, fd.panel_orient, map, fd.panel_px,
                      NULL, &q);
    memcpy(quad.out, q.pos, sizeof q.pos);
    memcpy(quad.out + 3, q.quat, sizeof q.quat);
    quad.out[7] = q.size[0];
    quad.out[8] = q.size[1];
    quad.out[9] = (float)map;
    if (force)
        hol_xr_quad_forget(&quad.cache);
    return hol_xr_quad_stale(&quad.cache, hol_render_panel_key(hol_web_g.rnd, &fd)) ? 2 : 1;
}

/* Draw the panel into fb (the layer's texture, w x h: the whole texture
 * holds the panel's box). 0 ok. */
EMSCRIPTEN_KEEPALIVE int hol_web_xr_panel_draw(int fb, int w, int h)
{
    if (!quad.v)
        return 1;
    hol_frame_desc fd;
    hol_app_frame_desc(quad.v, 0, 16, 16, 0, &fd);
    hol_app_frame_panel(quad.v, &fd);
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fb);
    int r = hol_render_panel_image(hol_web_g.rnd, &fd, w, h) != HOL_OK;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return r;
}

/* Line i of the panel as the last XR frame drew it (the fit's note
 * included), "" past its last: for tests. */
EMSCRIPTEN_KEEPALIVE const char *hol_web_xr_panel_line(int i)
{
    const hol_app_view *v = quad.v;
    return v && i >= 0 && i < v->hud.nlines ? v->hud.lines[i] : "";
}

EMSCRIPTEN_KEEPALIVE long hol_web_xr_panel_redraws(void)
{
    return quad.cache.redraws;
}

static void xr_render(const hol_app_view *v, const hol_input *in, int fb)
{
    hol_web *w = &hol_web_g;
    int n = w->xf.nviews > 1.5f ? 2 : 1;
    hol_camera cam[2];
    double eyes[2][3];
    for (int e = 0; e < 2; e++) {
        hol_web_xr_camera(&w->xr.calib, &w->xf.view[e < n ? e : 0], &cam[e]);
        memcpy(eyes[e], cam[e].eye, sizeof eyes[e]);
    }
    double fade = hol_xr_fade_room(eyes, HOL__MARGIN, w->xr.room_w, w->xr.room_d);
    /* outside: drawn from the head where it is, dimmed, the room's cells
     * seen from the nearest (eyes: the seats inside) */
    if (hol_xr_outside_eyes(v, in, eyes))
        fade = 0;
    quad.v = v;
    quad.fade = (float)fade;
    if (quad.on && v->panel.covered != quad.covered)
        printf("web: xr frame %ld: panel %s\n", w->xr_frames,
               v->panel.covered ? "in the scene (depth-tested): scenery too near for the quad"
                                : "as the quad layer again");
    quad.covered = v->panel.covered;
    glBindFramebuffer(GL_FRAMEBUFFER, (GLuint)fb);
    int checking = w->check_frame == w->xr_frames;
    for (int e = 0; e < n; e++) {
        const hol_web_xr_view *vw = &w->xf.view[e];
        if (cam[e].width < 1 || cam[e].height < 1)
            continue;
        hol_frame_desc fd;
        hol_app_frame_desc(v, n == 2 ? e : -1, cam[e].width, cam[e].height, 0, &fd);
        fd.overlay = hol_web_overlay();
        hol_app_frame_panel(v, &fd); /* the HUD on a panel in the world */
        if (quad.on && !v->panel.covered) /* the quad layer's; else depth-tested here */
            fd.flags |= HOL_RENDER_PANEL_LAYER;
        fd.cam = cam[e];
        fd.vp_x = (int)vw->vp[0];
        fd.vp_y = (int)vw->vp[1];
        if ((in->flags & HOL_INPUT_HAND_L_VALID) && (fd.flags & HOL_RENDER_MINIMAP_HAND)) {
            for (int k = 0; k < 3; k++)
                fd.hand_pos[k] = in->hand[0].pos[k];
            for (int k = 0; k < 4; k++)
                fd.hand_orient[k] = in->hand[0].quat[k];
        }
        /* the eye's own cell (its seat's); none: the boundary colour */
        int inside = fade < 1 && hol_motion_eye_state(&v->user, v->head, eyes[e], &fd.user) == HOL_OK;
        fd.fade = inside ? fade : 1;
        if (hol_render_frame(w->rnd, &fd, NULL)) {
            fd.fade = 1; /* never a stale image */
            hol_render_frame(w->rnd, &fd, NULL);
        }
        if (!w->xr_checked) { /* the session's first frame: one error check */
            w->xr_checked = 1;
            if (hol_render_check(w->rnd))
                printf("web: the GL reported an error at the XR session's first frame\n");
        }
        if (checking) {
            /* the check compares the world with `holonomy render` (no
             * HUD, no body: it draws none): it reads back a draw without
             * the UI panel, then one with it (the panel's pixels differ),
             * then the eye is drawn again as shown */
            hol_frame_desc bare = fd, shown = fd;
            bare.flags |= HOL_RENDER_NO_HUD;
            bare.body = shown.body = NULL;
            hol_render_frame(w->rnd, &bare, NULL);
            w->check_user[e] = fd.user;
            w->check_cam[e] = fd.cam;
            check_eye(e, &bare);
            hol_render_frame(w->rnd, &shown, NULL);
            check_read(2 + e, &shown);
            hol_render_frame(w->rnd, &fd, NULL);
            printf("web: check panel eye %d frame %ld pos %.9g,%.9g,%.9g orient "
                   "%.9g,%.9g,%.9g,%.9g px %.9g map %d\n",
                   e, w->xr_frames, fd.panel_pos[0], fd.panel_pos[1], fd.panel_pos[2],
                   fd.panel_orient[0], fd.panel_orient[1], fd.panel_orient[2],
                   fd.panel_orient[3], fd.panel_px > 0 ? fd.panel_px : HOL_RENDER_PANEL_PX,
                   (fd.flags & HOL_RENDER_MINIMAP) && !(fd.flags & HOL_RENDER_MINIMAP_HAND));
        }
    }
    w->xr_two_views += n == 2;
}

/* The bounded-floor polygon (n points x, z in fit_xz; the glue's boundsGeometry, at
 * the session's start and when the space is reset): the room and cell
 * that fit it (core/hol_fit.h), told on the console, to the page and on
 * the panel for 12 s, and played at once (fit on entry:
 * hol_web_game_refit, a new session in the fitted room while the first
 * level is in play and no study runs); else offered as a link (the page
 * again with it). The page's ?room= or ?cell= win: the fit is then only
 * told. */
static float fit_xz[2 * HOL_FIT_MAX_POINTS]; /* the glue writes the polygon here */

EMSCRIPTEN_KEEPALIVE float *hol_web_xr_fit_buffer(void)
{
    return fit_xz;
}

EMSCRIPTEN_KEEPALIVE void hol_web_xr_fit(int n)
{
    hol_web *w = &hol_web_g;
    if (n > HOL_FIT_MAX_POINTS || hol_fit_polygon(fit_xz, n, -1, &w->fit) != HOL_OK) {
        printf("web: the bounded-floor polygon (%d points) gives no play area\n", n);
        return;
    }
    w->have_fit = 1;
    w->fit_t = w->last_t;
    char line[256], offer[64];
    hol_fit_text(&w->fit, -1, line, sizeof line);
    printf("web: %s\n", line);
    hol_fit_say(&w->fit, -1, hol_web_game_lang(), line, sizeof line); /* the page's status */
    const hol_app_view *v = hol_app_get_view(hol_web_game_app());
    double m = v->cell_m > 0 ? v->cell_m : 1.0;
    int same = hol_room_cols(&v->user) == w->fit.cols && hol_room_rows(&v->user) == w->fit.rows &&
               fabs(m - w->fit.cell_m) < 1e-9;
    if (w->geo_named)
        printf("web: the page names the room or cell: the fit is not offered\n");
    char cm[16];
    snprintf(offer, sizeof offer, "room=%dx%d&cell=%s", w->fit.cols, w->fit.rows,
             hol_level_format_cell(w->fit.cell_m, cm));
    hol_web_js_event("fit", line);
    if (same || w->fit.too_small)
        return;
    /* fit on entry: the room fitted at once where the page allows it, else
     * offered as a link (the page again with it) */
    char msg[256];
    char room[16];
    snprintf(room, sizeof room, "%dx%d", w->fit.cols, w->fit.rows);
    int r = hol_web_game_refit(room, cm, msg, sizeof msg);
    if (r > 0) {
        hol_render_set_world(w->rnd, hol_app_world(hol_web_game_app()));
        hol_render_invalidate(w->rnd);
        quad.v = NULL; /* the old session's view: gone */
        printf("web: the room fitted to the play area (%s of %s m): a new session plays it\n",
               room, cm);
    } else if (r < 0) {
        printf("web: %s\n", msg);
    }
    if (r <= 0 && !w->geo_named)
        hol_web_js_event("fit-offer", offer);
}

/* While the fit is told: the view with its two HUD lines. */
static const hol_app_view *xr_noted(const hol_app_view *v)
{
    hol_web *w = &hol_web_g;
    if (!w->have_fit || w->last_t - w->fit_t >= HOL__FIT_NOTE_S)
        return v;
    return hol_xr_fit_note(&w->fit, !w->geo_named, v, &w->note) ? &w->note : v;
}

/* The reference space's 'reset' event (the browser's or the system's
 * recentre): the next record with a head carries HOL_INPUT_RECENTRED, so
 * the app re-places the room instead of walking the jump (docs/play.md). */
EMSCRIPTEN_KEEPALIVE void hol_web_xr_recentred(void)
{
    hol_web_g.xr_recentred = 1;
}

/* The step's controller pulses (core/hol_haptic.h: a hand into a hedge or
 * a trunk, a gentle one on each room step), played on that hand's
 * gamepad's first haptic actuator (the glue: GamepadHapticActuator.pulse;
 * a hand without one is skipped). Off with the page's haptics=0 (as
 * holonomy xr --no-haptics). */
static void xr_pulses(void)
{
    static int off = -1;
    if (off < 0) {
        char s[8];
        hol_web_js_config("haptics", s, sizeof s);
        off = !strcmp(s, "0") || !strcmp(s, "off");
        printf("web: haptics %s\n", off ? "off (haptics=0)" : "on");
    }
    const hol_haptic *hp = &hol_app_get_events(hol_web_game_app())->haptic;
    for (int h = 0; !off && h < 2; h++)
        if (hp->hand[h].amplitude > 0)
            hol_web_js_pulse(h, hp->hand[h].amplitude, hp->hand[h].duration_ms);
}

/* One XRFrame (t_ms: its time, performance.now()'s origin; fb: the layer's
 * framebuffer, 0 for the default one). Returns 0 to go on, 1 when the
 * session is over (the glue ends the XR session). */
EMSCRIPTEN_KEEPALIVE int hol_web_xr_step(double t_ms, int fb)
{
    hol_web *w = &hol_web_g;
    if (w->over)
        return 1;
    double c0 = emscripten_get_now();
    double t = (t_ms - w->t0_ms) / 1000.0;
    hol_input in;
    const hol_app_view *now = hol_app_get_view(hol_web_game_app());
    double m = now->cell_m > 0 ? now->cell_m : 1.0;
    w->xr.room_w = hol_room_cols(&now->user) * m; /* the room in play, in the stage */
    w->xr.room_d = hol_room_rows(&now->user) * m;
    w->xr.seated = w->pan.seated; /* a hand's pinch and flick steps */
    hol_web_xr_input(&w->xr, &w->xf, t > w->last_t ? t : w->last_t, &in);
    w->last_t = in.time_s;
    if (w->xr_off) /* hidden since the last frame (hol_web_pause_retell) */
        in.flags |= HOL_INPUT_HEADSET_OFF;
    w->xr_off = 0;
    if (w->xr_recentred && (in.flags & HOL_INPUT_HEAD_VALID)) {
        in.flags |= HOL_INPUT_RECENTRED;
        w->xr_recentred = 0;
    }
    if (w->pan.seated) { /* seated: either thumbstick's push is one step
                            (a hand's flick is in in.pressed already) */
        for (int h = 0; h < 2; h++) {
            float x = w->xf.pad[h].axes[2], y = w->xf.pad[h].axes[3];
            in.move[0] += isfinite(x) ? x : 0;
            in.move[1] -= isfinite(y) ? y : 0;
        }
        for (int a = 0; a < 2; a++)
            in.move[a] = in.move[a] > 1 ? 1 : in.move[a] < -1 ? -1 : in.move[a];
        hol_shell_seat(&w->xr_seat_latch, &in);
    }
    w->xr_focused += (in.flags & HOL_INPUT_FOCUSED) != 0;
    hol_web_env_xr_frame(t_ms, in.device);
    if (hol_web_step(&in))
        return 1;
    xr_pulses();
    xr_render(xr_noted(hol_app_get_view(hol_web_game_app())), &in, fb);
    if (w->xr_ncpu < (int)(sizeof w->xr_cpu_ms / sizeof w->xr_cpu_ms[0]))
        w->xr_cpu_ms[w->xr_ncpu++] = emscripten_get_now() - c0;
    hol_web_stats_add(c0);
    w->xr_frames++;
    return 0;
}

/* Median and 99th percentile of the XR frames' CPU ms (step and both
 * eyes' draw calls issued), for make bench; out[0] frames. */
static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

EMSCRIPTEN_KEEPALIVE double hol_web_xr_cpu_ms(int which)
{
    hol_web *w = &hol_web_g;
    if (!w->xr_ncpu)
        return -1;
    static double s[sizeof w->xr_cpu_ms / sizeof w->xr_cpu_ms[0]];
    memcpy(s, w->xr_cpu_ms, (size_t)w->xr_ncpu * sizeof s[0]);
    qsort(s, (size_t)w->xr_ncpu, sizeof s[0], cmp_d);
    return which == 0 ? w->xr_ncpu : which == 1 ? s[w->xr_ncpu / 2] : s[w->xr_ncpu * 99 / 100];
}

EMSCRIPTEN_KEEPALIVE void hol_web_xr_cpu_reset(void)
{
    hol_web_g.xr_ncpu = 0;
}

EMSCRIPTEN_KEEPALIVE long hol_web_xr_frames(int two_views)
{
    return two_views ? hol_web_g.xr_two_views : hol_web_g.xr_frames;
}
