/* hol_xr.c - the OpenXR session: instance, swapchains, the frame loop,
 * lifecycle events, teardown (see hol_xr.h, hol_xr_session.h). */
#define _GNU_SOURCE

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hol_xr_impl.h"

int hol__fail(hol__xr *x, const char *what, XrResult r)
{
    char name[XR_MAX_RESULT_STRING_SIZE] = "";
    if (x->instance != XR_NULL_HANDLE)
        xrResultToString(x->instance, r, name);
    if (r == XR_ERROR_RUNTIME_UNAVAILABLE) /* no instance yet to name it */
        fprintf(stderr, "holonomy xr: no OpenXR runtime (XR_ERROR_RUNTIME_UNAVAILABLE from "
                        "%s): start one, e.g. monado-service, or set XR_RUNTIME_JSON\n", what);
    else if (r == XR_ERROR_FORM_FACTOR_UNAVAILABLE)
        fprintf(stderr, "holonomy xr: the OpenXR runtime has no headset connected "
                        "(XR_ERROR_FORM_FACTOR_UNAVAILABLE)\n");
    else
        fprintf(stderr, "holonomy xr: %s failed: %s (%d)\n", what, name[0] ? name : "?", (int)r);
    return 1;
}


static double hol__thread_cpu_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static const char *hol__state_name(int s)
{
    static const char *const n[] = {"UNKNOWN", "IDLE", "READY", "SYNCHRONIZED", "VISIBLE",
                                    "FOCUSED", "STOPPING", "LOSS_PENDING", "EXITING"};
    return s >= 0 && s <= 8 ? n[s] : "?";
}

/* ---- swapchains ----------------------------------------------------------- */

static int hol__swapchains(hol__xr *x)
{
    XrViewConfigurationView vc[2] = {{XR_TYPE_VIEW_CONFIGURATION_VIEW},
                                     {XR_TYPE_VIEW_CONFIGURATION_VIEW}};
    uint32_t n = 0;
    HOL__XR(x, xrEnumerateViewConfigurationViews(x->instance, x->system,
                                                 XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2,
                                                 &n, vc));
    int64_t formats[64];
    uint32_t nf = 0;
    HOL__XR(x, xrEnumerateSwapchainFormats(x->session, 64, &nf, formats));
    int64_t fmt = nf ? formats[0] : HOL__GL_RGBA8;
    for (uint32_t i = 0; i < nf; i++)
        if (formats[i] == HOL__GL_RGBA8)
            fmt = formats[i]; /* the same bytes as the OSMesa reference */
    for (int e = 0; e < 2; e++) {
        hol__eye *ey = &x->eye[e];
        XrSwapchainCreateInfo ci = {XR_TYPE_SWAPCHAIN_CREATE_INFO};
        ci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
        ci.format = fmt;
        ci.sampleCount = 1;
        ci.width = vc[e].recommendedImageRectWidth;
        ci.height = vc[e].recommendedImageRectHeight;
        ci.faceCount = 1;
        ci.arraySize = 1;
        ci.mipCount = 1;
        HOL__XR(x, xrCreateSwapchain(x->session, &ci, &ey->swapchain));
        ey->w = (int32_t)ci.width;
        ey->h = (int32_t)ci.height;
        uint32_t ni = 0;
        for (int k = 0; k < HOL__MAX_IMAGES; k++) {
#ifdef __ANDROID__
            ey->images[k].type = XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_ES_KHR;
#else
            ey->images[k].type = XR_TYPE_SWAPCHAIN_IMAGE_OPENGL_KHR;
#endif
            ey->images[k].next = NULL;
        }
        HOL__XR(x, xrEnumerateSwapchainImages(ey->swapchain, HOL__MAX_IMAGES, &ni,
                                              (XrSwapchainImageBaseHeader *)ey->images));
        ey->nimages = ni;
        x->gl.GenRenderbuffers(1, &ey->depth);
        x->gl.BindRenderbuffer(HOL__GL_RENDERBUFFER, ey->depth);
        x->gl.RenderbufferStorage(HOL__GL_RENDERBUFFER, HOL__GL_DEPTH24_STENCIL8, ey->w, ey->h);
        x->gl.GenFramebuffers((hol__GLsizei)ni, ey->fbo);
        for (uint32_t k = 0; k < ni; k++) {
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->fbo[k]);
            x->gl.FramebufferTexture2D(HOL__GL_FRAMEBUFFER, HOL__GL_COLOR_ATTACHMENT0,
                                       HOL__GL_TEXTURE_2D, ey->images[k].image, 0);
            x->gl.FramebufferRenderbuffer(HOL__GL_FRAMEBUFFER, HOL__GL_DEPTH_STENCIL_ATTACHMENT,
                                          HOL__GL_RENDERBUFFER, ey->depth);
            if (x->gl.CheckFramebufferStatus(HOL__GL_FRAMEBUFFER) != HOL__GL_FRAMEBUFFER_COMPLETE) {
                fprintf(stderr, "holonomy xr: swapchain framebuffer incomplete\n");
                return 1;
            }
        }
        x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    }
    printf("xr: swapchains %dx%d per eye, format 0x%llx, %u images, two passes\n", x->eye[0].w,
           x->eye[0].h, (unsigned long long)fmt, x->eye[0].nimages);
    return 0;
}

/* ---- the frame ------------------------------------------------------------ */
static int hol__frame(hol__xr *x)
{
    XrFrameWaitInfo wi = {XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState fs = {XR_TYPE_FRAME_STATE};
    HOL__XR(x, xrWaitFrame(x->session, &wi, &fs));
    double c0 = hol__thread_cpu_ms();
    XrFrameBeginInfo bi = {XR_TYPE_FRAME_BEGIN_INFO};
    HOL__XR(x, xrBeginFrame(x->session, &bi));
    if (!x->t0)
        x->t0 = fs.predictedDisplayTime;
    XrViewLocateInfo li = {XR_TYPE_VIEW_LOCATE_INFO};
    li.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    li.displayTime = fs.predictedDisplayTime;
    li.space = x->stage;
    XrViewState vs = {XR_TYPE_VIEW_STATE};
    XrView views[2] = {{XR_TYPE_VIEW}, {XR_TYPE_VIEW}};
    uint32_t nv = 0;
    HOL__XR(x, xrLocateViews(x->session, &li, &vs, 2, &nv, views));
    int views_ok = nv == 2 && (vs.viewStateFlags & XR_VIEW_STATE_POSITION_VALID_BIT) &&
                   (vs.viewStateFlags & XR_VIEW_STATE_ORIENTATION_VALID_BIT);
    /* the input record */
    hol_input in;
    memset(&in, 0, sizeof in);
    double t = (double)(fs.predictedDisplayTime - x->t0) * 1e-9;
    in.time_s = t > x->last_t ? t : x->last_t;
    x->last_t = in.time_s;
    if (x->life.focused)
        in.flags |= HOL_INPUT_FOCUSED;
    if (x->bounds_small)
        in.flags |= HOL_INPUT_BOUNDS_SMALL;
    XrSpaceLocation loc = {XR_TYPE_SPACE_LOCATION};
    float hp[3] = {0, 1.6f, 0}, hq[4] = {0, 0, 0, 1};
    if (XR_SUCCEEDED(xrLocateSpace(x->view_space, x->stage, fs.predictedDisplayTime, &loc)) &&
        (loc.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT) &&
        (loc.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT)) {
        hol__pose_in(&loc.pose, hp, hq);
        in.flags |= HOL_INPUT_HEAD_VALID;
    }
    if (x->life.focused) {
        XrActiveActionSet as = {x->set, XR_NULL_PATH};
        XrActionsSyncInfo sy = {XR_TYPE_ACTIONS_SYNC_INFO};
        sy.countActiveActionSets = 1;
        sy.activeActionSets = &as;
        HOL__XR(x, xrSyncActions(x->session, &sy));
        int held[HOL_XR_ACT_COUNT];
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
            held[a] = hol__bool(x, a);
        in.buttons |= hol_xr_buttons(held);
        for (int h = 0; h < 2; h++) {
            XrSpaceLocation gl = {XR_TYPE_SPACE_LOCATION};
            if (XR_SUCCEEDED(xrLocateSpace(x->grip[h], x->stage, fs.predictedDisplayTime, &gl)) &&
                (gl.locationFlags & XR_SPACE_LOCATION_POSITION_VALID_BIT)) {
                float gp[3], gq[4];
                hol__pose_in(&gl.pose, gp, gq);
                hol_xr_to_room(&x->calib, gp, gq, &in.hand[h]);
                in.flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
                if (!x->grips_located[h]++)
                    printf("xr: grip %s located\n", h ? "right" : "left");
            }
        }
    }
    if ((in.buttons & HOL_BTN_RECENTRE) && !(x->prev_buttons & HOL_BTN_RECENTRE) &&
        (in.flags & HOL_INPUT_HEAD_VALID))
        hol_xr_recentre(&x->calib, hp, hq);
    x->prev_buttons = in.buttons;
    hol_xr_to_room(&x->calib, hp, hq, &in.head);
    /* scripted head motion (the simulated headset does not move): the
     * recorded record's head pose, in room coordinates */
    float room_from_stage_shift[3] = {0, 0, 0};
    if (x->d->nscript > 0) {
        const hol_input *s = &x->d->script[x->submitted % x->d->nscript];
        if (s->flags & HOL_INPUT_HEAD_VALID) {
            for (int k = 0; k < 3; k++)
                room_from_stage_shift[k] = s->head.pos[k] - in.head.pos[k];
            in.head = s->head;
            in.flags |= HOL_INPUT_HEAD_VALID;
        }
        in.buttons |= s->buttons;
    }
    const hol_app_view *v = NULL;
    double s0 = hol__thread_cpu_ms();
    int st = x->fns->step(x->fns->user, &in, &v);
    x->step_now = hol__thread_cpu_ms() - s0;
    if (st < 0)
        return 1;
    if (x->fns->level_started(x->fns->user))
        hol_render_invalidate(x->rnd);
    if (st > 0 || (x->d->frames > 0 && x->submitted + 1 >= x->d->frames)) {
        if (hol_xr_life_quit(&x->life) == HOL_XR_QUIT_REQUEST_EXIT) {
            HOL__XR(x, xrRequestExitSession(x->session));
            printf("xr: exit requested after %ld frames\n", x->submitted + 1);
        }
    }
    /* render each eye */
    XrCompositionLayerProjectionView pv[2];
    memset(pv, 0, sizeof pv);
    int rendered = 0;
    if (fs.shouldRender && views_ok && v) {
        /* both eyes where they are (the world never moves), and the safety
         * fade from how far they are beyond where the app's head may go */
        hol_pose eroom[2];
        double eyes[2][3];
        for (int e = 0; e < 2; e++) {
            float ep[3], eq[4];
            hol__pose_in(&views[e].pose, ep, eq);
            hol_xr_to_room(&x->calib, ep, eq, &eroom[e]);
            for (int k = 0; k < 3; k++)
                eyes[e][k] = eroom[e].pos[k] += room_from_stage_shift[k];
        }
        double fade = hol_xr_fade(eyes, HOL__MARGIN);
        for (int e = 0; e < 2; e++) {
            hol__eye *ey = &x->eye[e];
            uint32_t idx = 0;
            XrSwapchainImageAcquireInfo ai = {XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
            HOL__XR(x, xrAcquireSwapchainImage(ey->swapchain, &ai, &idx));
            XrSwapchainImageWaitInfo wi2 = {XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
            wi2.timeout = XR_INFINITE_DURATION;
            HOL__XR(x, xrWaitSwapchainImage(ey->swapchain, &wi2));
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->fbo[idx]);
            x->gl.Viewport(0, 0, ey->w, ey->h);
            hol_frame_desc fd;
            hol_app_frame_desc(v, e, ey->w, ey->h, 0, &fd);
            for (int k = 0; k < 3; k++)
                fd.cam.eye[k] = eroom[e].pos[k];
            fd.cam.has_pose = 1;
            for (int k = 0; k < 4; k++)
                fd.cam.orient[k] = eroom[e].quat[k];
            fd.cam.tan_left = tan(views[e].fov.angleLeft);
            fd.cam.tan_right = tan(views[e].fov.angleRight);
            fd.cam.tan_down = tan(views[e].fov.angleDown);
            fd.cam.tan_up = tan(views[e].fov.angleUp);
            if (in.flags & HOL_INPUT_HAND_L_VALID && (fd.flags & HOL_RENDER_MINIMAP_HAND)) {
                for (int k = 0; k < 3; k++)
                    fd.hand_pos[k] = in.hand[0].pos[k];
                for (int k = 0; k < 4; k++)
                    fd.hand_orient[k] = in.hand[0].quat[k];
            }
            /* the eye's own room state: the cell its position lies in;
             * none (outside the room): the boundary colour alone */
            int inside = fade < 1 &&
                         hol_motion_eye_state(&v->user, v->head, fd.cam.eye, &fd.user) == HOL_OK;
            fd.fade = inside ? fade : 1;
            hol_render_stats rs;
            memset(&rs, 0, sizeof rs);
            if (hol_render_frame(x->rnd, &fd, &rs)) {
                fd.fade = 1; /* never a stale image */
                hol_render_frame(x->rnd, &fd, &rs);
            }
            x->faded += fd.fade > 0 && e == 0;
            if (fade == 0) { /* the figures of a full view */
                x->draws[e] = rs.draw_calls;
                x->tris[e] = rs.triangles;
            }
#ifndef __ANDROID__
            if (e == 0 && x->d->check_dir && x->submitted == x->d->check_frame && inside &&
                fd.fade == 0)
                hol__check(x, &fd, ey->w, ey->h);
#endif
            x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
            XrSwapchainImageReleaseInfo ri = {XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
            HOL__XR(x, xrReleaseSwapchainImage(ey->swapchain, &ri));
            pv[e].type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
            pv[e].pose = views[e].pose;
            pv[e].fov = views[e].fov;
            pv[e].subImage.swapchain = ey->swapchain;
            pv[e].subImage.imageRect.extent.width = ey->w;
            pv[e].subImage.imageRect.extent.height = ey->h;
        }
        rendered = fade > 0 ? 2 : 1; /* 2: faded (cheaper; not in the CPU figures) */
    }
    XrCompositionLayerProjection layer = {XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    layer.space = x->stage;
    layer.viewCount = 2;
    layer.views = pv;
    const XrCompositionLayerBaseHeader *layers[1] = {(const XrCompositionLayerBaseHeader *)&layer};
    XrFrameEndInfo ei = {XR_TYPE_FRAME_END_INFO};
    ei.displayTime = fs.predictedDisplayTime;
    ei.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ei.layerCount = rendered ? 1 : 0;
    ei.layers = layers;
    HOL__XR(x, xrEndFrame(x->session, &ei));
    x->submitted++;
    /* the check frame's OSMesa reference is not the app's time */
    if (rendered == 1 && x->submitted - 1 != x->d->check_frame &&
        x->ncpu < (long)(sizeof x->cpu_ms / sizeof x->cpu_ms[0])) {
        x->step_ms[x->ncpu] = x->step_now;
        x->cpu_ms[x->ncpu++] = hol__thread_cpu_ms() - c0;
    }
    return 0;
}

static void hol__events(hol__xr *x)
{
    XrEventDataBuffer ev = {XR_TYPE_EVENT_DATA_BUFFER};
    XrResult pr;
    while ((pr = xrPollEvent(x->instance, &ev)) == XR_SUCCESS) {
        if (ev.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
            const XrEventDataSessionStateChanged *e = (const XrEventDataSessionStateChanged *)&ev;
            int state = (int)e->state;
            printf("xr: state %s\n", hol__state_name(state));
            x->reached_focused |= state == HOL_XR_STATE_FOCUSED;
            hol_xr_do d = hol_xr_life_event(&x->life, state);
            if (d == HOL_XR_DO_BEGIN) {
                XrSessionBeginInfo sb = {XR_TYPE_SESSION_BEGIN_INFO};
                sb.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
                XrResult r = xrBeginSession(x->session, &sb);
                if (XR_FAILED(r)) {
                    hol__fail(x, "xrBeginSession", r);
                    x->failed = x->life.done = 1;
                }
            } else if (d == HOL_XR_DO_END) {
                XrResult r = xrEndSession(x->session);
                if (XR_FAILED(r)) {
                    hol__fail(x, "xrEndSession", r);
                    x->failed = x->life.done = 1;
                } else {
                    printf("xr: session ended after STOPPING%s\n",
                           x->life.quit_requested ? "" : " (by the runtime: waiting for READY)");
                }
            }
        } else if (ev.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
            printf("xr: instance loss pending\n");
            x->life.done = 1;
        }
        ev.type = XR_TYPE_EVENT_DATA_BUFFER;
        ev.next = NULL;
    }
    if (XR_FAILED(pr)) { /* the runtime went away */
        hol__fail(x, "xrPollEvent", pr);
        x->failed = x->life.done = 1;
    }
}

static int hol__cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The instance and system (hol_xr_run; hol_xr_run_session is given them). */
static int hol__instance(hol__xr *x)
{
    XrInstanceCreateInfo ic = {XR_TYPE_INSTANCE_CREATE_INFO};
#ifdef __ANDROID__
    /* the Android loader needs the VM and the activity before anything */
    PFN_xrInitializeLoaderKHR init_loader = NULL;
    HOL__XR(x, xrGetInstanceProcAddr(XR_NULL_HANDLE, "xrInitializeLoaderKHR",
                                     (PFN_xrVoidFunction *)&init_loader));
    XrLoaderInitInfoAndroidKHR li = {XR_TYPE_LOADER_INIT_INFO_ANDROID_KHR};
    li.applicationVM = x->d->android_vm;
    li.applicationContext = x->d->android_activity;
    HOL__XR(x, init_loader((const XrLoaderInitInfoBaseHeaderKHR *)&li));
    XrInstanceCreateInfoAndroidKHR ai = {XR_TYPE_INSTANCE_CREATE_INFO_ANDROID_KHR};
    ai.applicationVM = x->d->android_vm;
    ai.applicationActivity = x->d->android_activity;
    ic.next = &ai;
    const char *ext[] = {XR_KHR_OPENGL_ES_ENABLE_EXTENSION_NAME,
                         XR_KHR_ANDROID_CREATE_INSTANCE_EXTENSION_NAME};
    ic.enabledExtensionCount = 2;
#else
    const char *ext[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
    ic.enabledExtensionCount = 1;
#endif
    ic.enabledExtensionNames = ext;
    snprintf(ic.applicationInfo.applicationName, sizeof ic.applicationInfo.applicationName, "%s",
             x->d->app_name ? x->d->app_name : "Holonomy");
    ic.applicationInfo.applicationVersion = 1;
    snprintf(ic.applicationInfo.engineName, sizeof ic.applicationInfo.engineName, "holonomy");
    ic.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    HOL__XR(x, xrCreateInstance(&ic, &x->instance));
    XrInstanceProperties ip = {XR_TYPE_INSTANCE_PROPERTIES};
    if (XR_SUCCEEDED(xrGetInstanceProperties(x->instance, &ip)))
        printf("xr: runtime %s %u.%u.%u\n", ip.runtimeName, XR_VERSION_MAJOR(ip.runtimeVersion),
               XR_VERSION_MINOR(ip.runtimeVersion), XR_VERSION_PATCH(ip.runtimeVersion));
    XrSystemGetInfo sg = {XR_TYPE_SYSTEM_GET_INFO};
    sg.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    HOL__XR(x, xrGetSystem(x->instance, &sg, &x->system));
    return 0;
}

/* The session on x's instance, system and current GL context (binding: the
 * graphics binding for xrCreateSession), its loop until it ends. */
static int hol__run(hol__xr *x, const void *binding)
{
    if (hol__load_gl(x) || hol__actions(x))
        return 1;
    XrSessionCreateInfo sc = {XR_TYPE_SESSION_CREATE_INFO};
    sc.next = binding;
    sc.systemId = x->system;
    HOL__XR(x, xrCreateSession(x->instance, &sc, &x->session));
    if (hol__spaces(x) || hol__swapchains(x))
        return 1;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = x->getproc;
    rd.world = x->fns->world(x->fns->user);
    if (hol_render_create(&rd, &x->rnd)) {
        fprintf(stderr, "holonomy xr: cannot initialise the renderer on this GL context\n");
        return 1;
    }
    while (!x->life.done) {
        if (x->fns->poll_platform && x->fns->poll_platform(x->fns->user) &&
            hol_xr_life_quit(&x->life) == HOL_XR_QUIT_REQUEST_EXIT)
            HOL__XR(x, xrRequestExitSession(x->session));
        hol__events(x);
        if (x->life.done)
            break;
        if (x->life.running) {
            if (hol__frame(x))
                return 1;
        } else {
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
        }
    }
    printf("xr: frames submitted %ld, reached FOCUSED %s, faded at the boundary %ld\n",
           x->submitted, x->reached_focused ? "yes" : "no", x->faded);
    if (x->ncpu) {
        qsort(x->cpu_ms, (size_t)x->ncpu, sizeof x->cpu_ms[0], hol__cmp);
        qsort(x->step_ms, (size_t)x->ncpu, sizeof x->step_ms[0], hol__cmp);
        printf("xr: app thread CPU per stereo frame (step, both eyes, submit; without "
               "xrWaitFrame; unfaded frames): median %.2f ms, p99 %.2f ms over %ld frames; "
               "of it the app step median %.3f ms, p99 %.3f ms\n",
               x->cpu_ms[x->ncpu / 2], x->cpu_ms[x->ncpu * 99 / 100], x->ncpu,
               x->step_ms[x->ncpu / 2], x->step_ms[x->ncpu * 99 / 100]);
        printf("xr: per eye: %ld / %ld draw calls, %ld / %ld triangles (left / right)\n",
               x->draws[0], x->draws[1], x->tris[0], x->tris[1]);
    }
    return x->failed;
}

static void hol__destroy(hol__xr *x)
{
    hol_render_destroy(x->rnd);
    for (int e = 0; e < 2; e++) {
        if (x->eye[e].nimages && x->gl.DeleteFramebuffers) {
            x->gl.DeleteFramebuffers((hol__GLsizei)x->eye[e].nimages, x->eye[e].fbo);
            x->gl.DeleteRenderbuffers(1, &x->eye[e].depth);
        }
        if (x->eye[e].swapchain != XR_NULL_HANDLE)
            xrDestroySwapchain(x->eye[e].swapchain);
    }
    for (int h = 0; h < 2; h++)
        if (x->grip[h] != XR_NULL_HANDLE)
            xrDestroySpace(x->grip[h]);
    if (x->view_space != XR_NULL_HANDLE)
        xrDestroySpace(x->view_space);
    if (x->stage != XR_NULL_HANDLE)
        xrDestroySpace(x->stage);
    if (x->session != XR_NULL_HANDLE)
        xrDestroySession(x->session);
    if (x->set != XR_NULL_HANDLE)
        xrDestroyActionSet(x->set);
    if (x->external) /* the instance and the GL context are the caller's */
        return;
    if (x->instance != XR_NULL_HANDLE)
        xrDestroyInstance(x->instance);
#ifdef __ANDROID__
    if (x->edpy != EGL_NO_DISPLAY) {
        eglMakeCurrent(x->edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglTerminate(x->edpy);
    }
#else
    if (x->dpy) {
        glXMakeCurrent(x->dpy, None, NULL);
        if (x->ctx)
            glXDestroyContext(x->dpy, x->ctx);
        if (x->win)
            XDestroyWindow(x->dpy, x->win);
        if (x->cmap)
            XFreeColormap(x->dpy, x->cmap);
        XCloseDisplay(x->dpy);
    }
#endif
}

/* Both entries: the one allocation, the run (own instance and context, or
 * the caller's in ext), teardown of what was made. */
static int hol__main(const hol_xr_desc *desc, const hol_xr_app_fns *fns,
                     const hol_xr_external *ext)
{
    hol__xr *x = calloc(1, sizeof *x); /* the platform's one allocation */
    if (!x) {
        fprintf(stderr, "holonomy xr: out of memory\n");
        return 1;
    }
    x->d = desc;
    x->fns = fns;
#ifdef __ANDROID__
    x->edpy = EGL_NO_DISPLAY;
#endif
    int rc;
    if (ext) {
        x->external = 1;
        x->instance = ext->instance;
        x->system = ext->system;
        x->getproc = ext->getproc;
        rc = hol__run(x, ext->graphics_binding);
    } else {
        hol__binding binding;
        rc = hol__instance(x) || hol__graphics(x, &binding) || hol__run(x, &binding);
    }
    hol__destroy(x);
    free(x);
    fflush(stdout);
    return rc;
}

int hol_xr_run(const hol_xr_desc *desc, const hol_xr_app_fns *fns)
{
    return hol__main(desc, fns, NULL);
}

int hol_xr_run_session(const hol_xr_desc *desc, const hol_xr_app_fns *fns,
                       const hol_xr_external *ext)
{
    if (!ext || ext->instance == XR_NULL_HANDLE || !ext->graphics_binding || !ext->getproc) {
        fprintf(stderr, "holonomy xr: no instance, graphics binding or getproc given\n");
        return 1;
    }
    return hol__main(desc, fns, ext);
}
