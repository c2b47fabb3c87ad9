/* hol_xr_frame.c - one headset frame (see hol_xr_state.h): xrWaitFrame,
 * xrBeginFrame, the views, the input record (head, hands, buttons), the
 * app step, both eyes drawn into their swapchains, xrEndFrame. Every xr*
 * result is checked: a failure ends the run with its one line. */
#define _GNU_SOURCE
#include "hol_xr_state.h"

#include "../../core/hol_input_io.h"
#include "../shell/hol_shell_seat.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

static double hol__thread_cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

/* A space's pose in the room's space at time t: 1 located (position and
 * orientation valid), 2 located with the position not tracked (emulated:
 * XR_SPACE_LOCATION_POSITION_TRACKED_BIT clear), 0 not located now, -1 a
 * failure (reported). */
static int hol__locate(hol__xr *x, XrSpace space, XrTime t, float pos[3], float quat[4])
{
    XrSpaceLocation loc = {XR_TYPE_SPACE_LOCATION};
    XrResult r = xrLocateSpace(space, x->stage, t, &loc);
    if (XR_FAILED(r))
        return -hol__xr_fail(x, "locate the head and hands", r);
    if (!(loc.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) ||
        !(loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT))
        return 0;
    hol__pose_in(&loc.pose, pos, quat);
    return loc.locationFlags & XR_SPACE_LOCATION_POSITION_TRACKED_BIT ? 1 : 2;
}

/* The buttons (hol_xr_buttons: the layer of the app's menu) and both grips. */
static int hol__hands(hol__xr *x, XrTime t, hol_input *in)
{
    XrActiveActionSet as = {x->set, XR_NULL_PATH};
    XrActionsSyncInfo sy = {XR_TYPE_ACTIONS_SYNC_INFO};
    sy.countActiveActionSets = 1;
    sy.activeActionSets = &as;
    HOL__XR(x, "read the controllers", xrSyncActions(x->session, &sy));
    int held[HOL_XR_ACT_COUNT];
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        if (hol__xr_bool(x, a, &held[a]))
            return 1;
    in->buttons |= hol_xr_buttons(&x->keys, held, x->in_menu);
    for (int h = 0; h < 2; h++) {
        float gp[3], gq[4];
        int got = hol__locate(x, x->grip[h], t, gp, gq);
        if (got < 0)
            return 1;
        if (!got)
            continue;
        hol_xr_to_room(&x->calib, gp, gq, &in->hand[h]);
        in->flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
        if (!x->grips_located[h]++)
            hol__xr_say(x, "xr: grip %s located", h ? "right" : "left");
    }
    return 0;
}

/* The device in use, for the prompts (HOL_DEVICE_*): the right hand's
 * profile (it holds confirm), else the left's; none known: any XR
 * controller, or none at all. */
static uint32_t hol__device(const hol__xr *x)
{
    int p = x->profile[1] >= 0 ? x->profile[1] : x->profile[0];
    if (p >= 0)
        return hol_xr_profile_device(p);
    return x->any_profile ? HOL_DEVICE_XR : HOL_DEVICE_NONE;
}

/* The room in play (v: the app's view; NULL keeps the last): its size
 * places it in the stage (centred on the calibration's origin), sizes the
 * safety fade, and says whether the stage bounds hold it. */
static void hol__room_size(hol__xr *x, const hol_app_view *v)
{
    if (v) {
        double m = v->cell_m > 0 ? v->cell_m : 1.0;
        x->room_w = hol_room_cols(&v->user) * m;
        x->room_d = hol_room_rows(&v->user) * m;
    }
    if (x->room_w <= 0)
        x->room_w = x->room_d = 3.0;
    x->calib.half_w = x->room_w / 2;
    x->calib.half_d = x->room_d / 2;
    x->bounds_small = x->have_bounds && (x->fit.too_small ||
                                         !hol_xr_bounds_hold(x->bounds_w, x->bounds_d,
                                                             x->room_w, x->room_d));
}

/* While the fit is told (the first HOL__FIT_NOTE_S seconds): the view with
 * its two HUD lines (hol_xr_fit_note). */
static const hol_app_view *hol__noted(hol__xr *x, const hol_app_view *v, double t)
{
    if (!x->have_bounds || t >= HOL__FIT_NOTE_S || !v || !hol_xr_fit_note(&x->fit, 0, v, &x->note))
        return v;
    return &x->note;
}

/* The input record of this frame; shift: what the scripted head motion
 * moved the head by (room coordinates), for the eyes. */
static int hol__input(hol__xr *x, const XrFrameState *fs, hol_input *in, float shift[3])
{
    memset(in, 0, sizeof *in);
    double t = (double)(fs->predictedDisplayTime - x->t0) * 1e-9;
    in->time_s = t > x->last_t ? t : x->last_t;
    x->last_t = in->time_s;
    /* the headset's state (worn, focused), the session's: the core
     * decides from it whether the head walks (core/hol_input.h) */
    in->flags |= hol_xr_life_state(&x->life);
    hol__room_size(x, x->fns->view ? x->fns->view(x->fns->user) : NULL);
    if (x->bounds_small)
        in->flags |= HOL_INPUT_BOUNDS_SMALL;
    /* the head where the runtime has none: standing in the room's middle */
    float hp[3] = {0, (float)HOL_XR_EYE_HEIGHT, 0}, hq[4] = {0, 0, 0, 1};
    int head = hol__locate(x, x->view_space, fs->predictedDisplayTime, hp, hq);
    if (head < 0)
        return 1;
    if (head)
        in->flags |= HOL_INPUT_HEAD_VALID | (head == 2 ? HOL_INPUT_POS_EMULATED : 0u);
    /* the runtime's recentre: told once with a head */
    in->flags |= hol_xr_life_take(&x->life, head);
    if (x->life.focused && hol__hands(x, fs->predictedDisplayTime, in))
        return 1;
    /* the tracked hands' joints, and their recentre (both palms up, held:
     * a press, placed from the head as the control's is) */
    if (hol__xr_hands_locate(x, fs->predictedDisplayTime))
        return 1;
    uint32_t gesture = hol__xr_hands_gesture(x, x->life.focused, in->time_s);
    if (((in->buttons & HOL_BTN_RECENTRE) && !(x->prev_buttons & HOL_BTN_RECENTRE)) || gesture)
        if (head)
            hol_xr_recentre(&x->calib, hp, hq);
    in->pressed = (in->buttons & ~x->prev_buttons) | gesture; /* the runtime keeps no taps */
    x->prev_buttons = in->buttons;
    in->device = hol__device(x);
    hol_xr_to_room(&x->calib, hp, hq, &in->head);
    hol__xr_hands_room(x, in->joints);
    /* scripted head motion (the simulated headset does not move): the
     * recorded record's head pose, in room coordinates */
    shift[0] = shift[1] = shift[2] = 0;
    if (x->d->nscript > 0) {
        const hol_input *s = &x->d->script[x->submitted % x->d->nscript];
        if (s->flags & HOL_INPUT_HEAD_VALID) {
            for (int k = 0; k < 3; k++)
                shift[k] = s->head.pos[k] - in->head.pos[k];
            in->head = s->head;
            in->flags = (in->flags & ~(uint32_t)HOL_INPUT_POS_EMULATED) | HOL_INPUT_HEAD_VALID;
        }
        /* and the headset's state the line gives (off, untracked) */
        in->flags |= s->flags & (HOL_INPUT_HEADSET_OFF | HOL_INPUT_POS_EMULATED);
        in->buttons |= s->buttons;
        in->pressed |= s->pressed;
    }
    if (x->d->seated) { /* either stick's push: one room step */
        for (int h = 0; x->life.focused && h < 2; h++) {
            float s[2];
            if (hol__xr_stick(x, h, s))
                return 1;
            for (int k = 0; k < 2; k++)
                in->move[k] += s[k];
        }
        for (int k = 0; k < 2; k++)
            in->move[k] = in->move[k] > 1 ? 1 : in->move[k] < -1 ? -1 : in->move[k];
        hol_shell_seat(&x->seat_latch, in);
    }
    return 0;
}

/* The app step; a quit (the app's, or desc.frames reached) asks the runtime
 * to end the session. */
static int hol__step(hol__xr *x, const hol_input *in, const hol_app_view **out_v)
{
    double s0 = hol__thread_cpu_ms();
    int st = x->fns->step(x->fns->user, in, out_v);
    x->step_now = hol__thread_cpu_ms() - s0;
    if (st < 0)
        return hol__xr_error(x, "the app step failed");
    x->in_menu = *out_v && (*out_v)->paused && x->life.focused;
    hol__room_size(x, *out_v);
    /* the panel's prompt line, said when it changes (the first seconds
     * name the menu's control: "xr: prompt MENU: menu") */
    if (*out_v && strcmp((*out_v)->hud.hint, x->prompt)) {
        snprintf(x->prompt, sizeof x->prompt, "%s", (*out_v)->hud.hint);
        hol__xr_say(x, "xr: prompt %s", x->prompt[0] ? x->prompt : "(none)");
    }
    if (x->fns->level_started(x->fns->user))
        hol_render_invalidate(x->rnd);
    if ((st > 0 || (x->d->frames > 0 && x->submitted + 1 >= x->d->frames)) &&
        hol_xr_life_quit(&x->life) == HOL_XR_QUIT_REQUEST_EXIT) {
        HOL__XR(x, "end the session", xrRequestExitSession(x->session));
        hol__xr_say(x, "xr: exit requested after %ld frames", x->submitted + 1);
    }
    return 0;
}

/* One eye: drawn where it is (eroom, its room pose), with the view's own
 * asymmetric field of view, into the swapchain's next image; its room
 * state (the cell it sees from) is seat's (the eye, or outside the room
 * the point hol_xr_outside_eyes moved it to). */
static int hol__draw_eye(hol__xr *x, int e, const hol_app_view *v, const hol_input *in,
                         const hol_pose *eroom, const double seat[3], double fade,
                         XrCompositionLayerProjectionView *pv)
{
    hol__eye *ey = &x->eye[e];
    const XrView *view = &x->views[e];
    uint32_t idx;
    if (hol__xr_chain_acquire(x, ey->swapchain, ey->nimages, "draw the next frame", &idx))
        return 1;
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->samples > 1 ? ey->msaa_fbo : ey->fbo[idx]);
    x->gl.Viewport(0, 0, ey->w, ey->h);
    hol_frame_desc fd;
    hol_app_frame_desc(v, e, ey->w, ey->h, 0, &fd);
    hol_app_frame_panel(v, &fd); /* the HUD on a panel in the world */
    if (x->quad_on && !x->quad_covered) /* the panel is the quad layer's */
        fd.flags |= HOL_RENDER_PANEL_LAYER;
    for (int k = 0; k < 3; k++)
        fd.cam.eye[k] = eroom->pos[k];
    fd.cam.has_pose = 1;
    for (int k = 0; k < 4; k++)
        fd.cam.orient[k] = eroom->quat[k];
    fd.cam.tan_left = tan(view->fov.angleLeft);
    fd.cam.tan_right = tan(view->fov.angleRight);
    fd.cam.tan_down = tan(view->fov.angleDown);
    fd.cam.tan_up = tan(view->fov.angleUp);
    if (in->flags & HOL_INPUT_HAND_L_VALID && (fd.flags & HOL_RENDER_MINIMAP_HAND)) {
        memcpy(fd.hand_pos, in->hand[0].pos, sizeof fd.hand_pos);
        memcpy(fd.hand_orient, in->hand[0].quat, sizeof fd.hand_orient);
    }
    /* the eye's own room state: the cell its seat lies in; none (beyond
     * the safety fade's margin, inside): the boundary colour alone */
    int inside = fade < 1 && hol_motion_eye_state(&v->user, v->head, seat, &fd.user) == HOL_OK;
    fd.fade = inside ? fade : 1;
    hol_render_stats rs;
    memset(&rs, 0, sizeof rs);
    if (hol_render_frame(x->rnd, &fd, &rs)) {
        fd.fade = 1; /* never a stale image */
        hol_render_frame(x->rnd, &fd, &rs);
    }
    x->faded += (fd.fade > 0 || fd.outside) && e == 0; /* faded, or dimmed outside */
    if (fade == 0) { /* the figures of a full view */
        x->draws[e] = rs.draw_calls;
        x->tris[e] = rs.triangles;
    }
    if (ey->samples > 1) { /* the multisampled eye resolved into the image */
        x->gl.BindFramebuffer(HOL__GL_READ_FRAMEBUFFER, ey->msaa_fbo);
        x->gl.BindFramebuffer(HOL__GL_DRAW_FRAMEBUFFER, ey->fbo[idx]);
        x->gl.BlitFramebuffer(0, 0, ey->w, ey->h, 0, 0, ey->w, ey->h, HOL__GL_COLOR_BUFFER_BIT,
                              HOL__GL_NEAREST);
    }
#ifndef __ANDROID__
    if (x->d->check_dir && x->submitted == x->d->check_frame && inside && fd.fade == 0)
        hol__xr_check_eye(x, e, &fd, ey->fbo[idx], ey->w, ey->h);
#endif
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    XrSwapchainImageReleaseInfo ri = {XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    HOL__XR(x, "draw the next frame", xrReleaseSwapchainImage(ey->swapchain, &ri));
    pv->type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
    pv->pose = view->pose;
    pv->fov = view->fov;
    pv->subImage.swapchain = ey->swapchain;
    pv->subImage.imageRect.extent.width = ey->w;
    pv->subImage.imageRect.extent.height = ey->h;
    return 0;
}

/* Both eyes where they are (the world never moves), and the safety fade
 * from how far they are beyond where the app's head may go. *out_rendered:
 * 1 drawn, 2 drawn faded (cheaper; not in the CPU figures). */
static int hol__eyes(hol__xr *x, const hol_app_view *v, const hol_input *in,
                     const float shift[3], XrCompositionLayerProjectionView pv[2],
                     int *out_rendered)
{
    hol_pose eroom[2];
    double eyes[2][3];
    for (int e = 0; e < 2; e++) {
        float ep[3], eq[4];
        hol__pose_in(&x->views[e].pose, ep, eq);
        hol_xr_to_room(&x->calib, ep, eq, &eroom[e]);
        for (int k = 0; k < 3; k++)
            eyes[e][k] = eroom[e].pos[k] += shift[k];
    }
    double fade = hol_xr_fade_room(eyes, HOL__MARGIN, x->room_w, x->room_d);
    /* outside: drawn from the head where it is, dimmed, the room's cells
     * seen from the nearest (the seats inside) */
    double seat[2][3];
    memcpy(seat, eyes, sizeof seat);
    if (hol_xr_outside_eyes(v, in, seat))
        fade = 0;
    hol__xr_quad_covered(x, v); /* scenery nearer than the panel: in the eyes */
    for (int e = 0; e < 2; e++)
        if (hol__draw_eye(x, e, v, in, &eroom[e], seat[e], fade, &pv[e]))
            return 1;
    *out_rendered = fade > 0 ? 2 : 1;
    x->fade_now = fade;
    return 0;
}

/* The views at the predicted display time: 1 both located, 0 not (no
 * layer this frame), -1 a failure. */
static int hol__locate_views(hol__xr *x, XrTime t)
{
    XrViewLocateInfo li = {XR_TYPE_VIEW_LOCATE_INFO};
    li.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    li.displayTime = t;
    li.space = x->stage;
    XrViewState vs = {XR_TYPE_VIEW_STATE};
    uint32_t n = 0;
    for (uint32_t e = 0; e < x->nviews; e++) {
        x->views[e].type = XR_TYPE_VIEW;
        x->views[e].next = NULL;
    }
    XrResult r = xrLocateViews(x->session, &li, &vs, x->nviews, &n, x->views);
    if (XR_FAILED(r))
        return -hol__xr_fail(x, "locate the eyes", r);
    return n == 2 && (vs.viewStateFlags & XR_VIEW_STATE_POSITION_VALID_BIT) &&
           (vs.viewStateFlags & XR_VIEW_STATE_ORIENTATION_VALID_BIT);
}

void hol__xr_tell_env(hol__xr *x, int last)
{
    if (x->env_told || !x->fns->environment)
        return;
    int p = x->profile[1] >= 0 ? x->profile[1] : x->profile[0];
    int rate = x->refresh_fb > 0 || x->periods >= HOL_XR_REFRESH_FRAMES;
    if (!last && !(rate && (p >= 0 || x->any_profile || x->submitted >= HOL_XR_PROFILE_WAIT)))
        return;
    x->env_told = 1;
    double hz = x->refresh_fb > 0 ? x->refresh_fb
                : x->periods      ? 1e9 / (x->period_ns / (double)x->periods)
                                  : 0;
    const char *how = x->refresh_fb > 0 ? "runtime" : x->periods ? "measured" : "";
    const char *ctl = p >= 0 ? hol_input_device_name(hol_xr_profile_device(p))
                      : x->any_profile ? "xr"
                                       : "";
    if (hz > 0)
        hol__xr_say(x, "xr: display refresh %.3f Hz (%s%s)", hz, how,
                    x->refresh_fb > 0 ? ": XR_FB_display_refresh_rate"
                                   : ": the mean predictedDisplayPeriod of the first frames");
    x->fns->environment(x->fns->user, ctl ? ctl : "", hz, how);
}

int hol__xr_frame(hol__xr *x)
{
    XrFrameWaitInfo wi = {XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState fs = {XR_TYPE_FRAME_STATE};
    HOL__XR(x, "wait for the next frame", xrWaitFrame(x->session, &wi, &fs));
    if (x->periods < HOL_XR_REFRESH_FRAMES && fs.predictedDisplayPeriod > 0) {
        x->period_ns += (double)fs.predictedDisplayPeriod;
        x->periods++;
    }
    hol__xr_tell_env(x, 0);
    double c0 = hol__thread_cpu_ms();
    XrFrameBeginInfo bi = {XR_TYPE_FRAME_BEGIN_INFO};
    HOL__XR(x, "begin the next frame", xrBeginFrame(x->session, &bi));
    if (!x->t0)
        x->t0 = fs.predictedDisplayTime;
    int views_ok = hol__locate_views(x, fs.predictedDisplayTime);
    hol_input in;
    float shift[3];
    const hol_app_view *v = NULL;
    if (views_ok < 0 || hol__input(x, &fs, &in, shift) || hol__step(x, &in, &v) ||
        hol__xr_haptics(x))
        return 1;
    v = hol__noted(x, v, in.time_s);
    XrCompositionLayerProjectionView pv[2];
    memset(pv, 0, sizeof pv);
    int rendered = 0;
    if (fs.shouldRender && views_ok && v && hol__eyes(x, v, &in, shift, pv, &rendered))
        return 1;
    XrCompositionLayerProjection layer = {XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    layer.space = x->stage;
    layer.viewCount = 2;
    layer.views = pv;
    /* the panel's quad after the projection layer (over it), unless the
     * view is faded out entirely */
    XrCompositionLayerQuad quad = {XR_TYPE_COMPOSITION_LAYER_QUAD};
    int with_quad = 0;
    if (rendered && x->fade_now < 1 && hol__xr_quad_layer(x, v, shift, &quad, &with_quad))
        return 1;
    const XrCompositionLayerBaseHeader *layers[2] = {(const XrCompositionLayerBaseHeader *)&layer,
                                                     (const XrCompositionLayerBaseHeader *)&quad};
    XrFrameEndInfo ei = {XR_TYPE_FRAME_END_INFO};
    ei.displayTime = fs.predictedDisplayTime;
    ei.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ei.layerCount = rendered ? 1 + (uint32_t)with_quad : 0;
    ei.layers = layers;
    HOL__XR(x, "show the frame", xrEndFrame(x->session, &ei));
    x->submitted++;
    /* the check frame's OSMesa reference is not the app's time */
    if (rendered == 1 && x->submitted - 1 != x->d->check_frame &&
        x->ncpu < (long)(sizeof x->cpu_ms / sizeof x->cpu_ms[0])) {
        x->step_ms[x->ncpu] = x->step_now;
        x->cpu_ms[x->ncpu++] = hol__thread_cpu_ms() - c0;
    }
    return 0;
}
