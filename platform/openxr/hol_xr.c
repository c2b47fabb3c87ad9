/* hol_xr.c - the headset's entries (see hol_xr.h, hol_xr_session.h): the
 * instance and system, the session and its loop until it ends, teardown.
 * The top of platform/openxr: it calls the files below it (the list in
 * hol_xr_state.h) and none of them calls it. */
#define _GNU_SOURCE

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hol_xr.h"
#include "hol_xr_session.h"
#include "hol_xr_state.h"

static int hol__cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

#ifdef __ANDROID__
/* The Android loader needs the VM and the activity before anything, on a
 * thread attached to the VM (the loader and the runtime call Java).
 * *out_attached: this call attached it (hol__main detaches it again). */
static int hol__android_loader(hol__xr *x, int *out_attached)
{
    JavaVM *vm = x->d->android_vm;
    JNIEnv *env = NULL;
    if (!vm || !x->d->android_activity)
        return hol__xr_error(x, "no Java VM or activity given for the OpenXR loader");
    if ((*vm)->GetEnv(vm, (void **)&env, JNI_VERSION_1_6) == JNI_EDETACHED) {
        if ((*vm)->AttachCurrentThread(vm, &env, NULL) != JNI_OK)
            return hol__xr_error(x, "cannot attach the headset thread to the Java VM");
        *out_attached = 1;
    }
    PFN_xrInitializeLoaderKHR init_loader = NULL;
    HOL__XR(x, "find the OpenXR loader's Android start",
            xrGetInstanceProcAddr(XR_NULL_HANDLE, "xrInitializeLoaderKHR",
                                  (PFN_xrVoidFunction *)&init_loader));
    XrLoaderInitInfoAndroidKHR li = {XR_TYPE_LOADER_INIT_INFO_ANDROID_KHR};
    li.applicationVM = vm;
    li.applicationContext = x->d->android_activity;
    HOL__XR(x, "start the OpenXR loader", init_loader((const XrLoaderInitInfoBaseHeaderKHR *)&li));
    return 0;
}
#endif

/* 1 when the runtime lists extension `name` (xrEnumerateInstanceExtensionProperties;
 * a failure lists nothing). */
static int hol__has_extension(const char *name)
{
    uint32_t n = 0;
    if (XR_FAILED(xrEnumerateInstanceExtensionProperties(NULL, 0, &n, NULL)) || !n)
        return 0;
    XrExtensionProperties *p = calloc(n, sizeof *p);
    if (!p)
        return 0;
    for (uint32_t i = 0; i < n; i++)
        p[i].type = XR_TYPE_EXTENSION_PROPERTIES;
    int found = 0;
    if (XR_SUCCEEDED(xrEnumerateInstanceExtensionProperties(NULL, n, &n, p)))
        for (uint32_t i = 0; i < n && !found; i++)
            found = !strcmp(p[i].extensionName, name);
    free(p);
    return found;
}

/* The instance and system (hol_xr_run; hol_xr_run_session is given them);
 * XR_EXT_hand_interaction enabled where the runtime lists it (the hands'
 * bindings, hol_xr_bind.h), and XR_EXT_hand_tracking (their joints,
 * hol_xr_hands.c). */
static int hol__instance(hol__xr *x)
{
    XrInstanceCreateInfo ic = {XR_TYPE_INSTANCE_CREATE_INFO};
#ifdef __ANDROID__
    XrInstanceCreateInfoAndroidKHR ai = {XR_TYPE_INSTANCE_CREATE_INFO_ANDROID_KHR};
    ai.applicationVM = x->d->android_vm;
    ai.applicationActivity = x->d->android_activity;
    ic.next = &ai;
    const char *ext[5] = {XR_KHR_OPENGL_ES_ENABLE_EXTENSION_NAME,
                          XR_KHR_ANDROID_CREATE_INSTANCE_EXTENSION_NAME};
    ic.enabledExtensionCount = 2;
#else
    const char *ext[5] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
    ic.enabledExtensionCount = 1;
#endif
    x->hand_interaction = hol__has_extension(HOL_XR_EXT_HAND_INTERACTION);
    if (x->hand_interaction)
        ext[ic.enabledExtensionCount++] = HOL_XR_EXT_HAND_INTERACTION;
    x->fb_refresh = hol__has_extension(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME);
    if (x->fb_refresh)
        ext[ic.enabledExtensionCount++] = XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME;
    x->hand_ext = hol__has_extension(XR_EXT_HAND_TRACKING_EXTENSION_NAME);
    if (x->hand_ext)
        ext[ic.enabledExtensionCount++] = XR_EXT_HAND_TRACKING_EXTENSION_NAME;
    ic.enabledExtensionNames = ext;
    snprintf(ic.applicationInfo.applicationName, sizeof ic.applicationInfo.applicationName, "%s",
             x->d->app_name ? x->d->app_name : "Holonomy");
    ic.applicationInfo.applicationVersion = 1;
    snprintf(ic.applicationInfo.engineName, sizeof ic.applicationInfo.engineName, "holonomy");
    ic.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
    HOL__XR(x, "start the OpenXR instance", xrCreateInstance(&ic, &x->instance));
    XrInstanceProperties ip = {XR_TYPE_INSTANCE_PROPERTIES};
    HOL__XR(x, "read the runtime's name", xrGetInstanceProperties(x->instance, &ip));
    snprintf(x->runtime, sizeof x->runtime, "%s %u.%u.%u", ip.runtimeName,
             XR_VERSION_MAJOR(ip.runtimeVersion), XR_VERSION_MINOR(ip.runtimeVersion),
             XR_VERSION_PATCH(ip.runtimeVersion));
    hol__xr_say(x, "xr: runtime %s %u.%u.%u", ip.runtimeName, XR_VERSION_MAJOR(ip.runtimeVersion),
                XR_VERSION_MINOR(ip.runtimeVersion), XR_VERSION_PATCH(ip.runtimeVersion));
    hol__xr_say(x, "xr: %s %s", HOL_XR_EXT_HAND_INTERACTION,
                x->hand_interaction ? "enabled: the hands are bound (pinches and grasps)"
                                 : "not listed by the runtime: no hand bindings");
    XrSystemGetInfo sg = {XR_TYPE_SYSTEM_GET_INFO};
    sg.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    HOL__XR(x, "find the headset", xrGetSystem(x->instance, &sg, &x->system));
    return 0;
}

/* The display's refresh rate from XR_FB_display_refresh_rate, where the
 * runtime lists it (x->refresh_fb; a failure leaves it 0: measured). */
static void hol__refresh_fb(hol__xr *x)
{
    PFN_xrGetDisplayRefreshRateFB get = NULL;
    float hz = 0;
    if (x->fb_refresh &&
        XR_SUCCEEDED(xrGetInstanceProcAddr(x->instance, "xrGetDisplayRefreshRateFB",
                                           (PFN_xrVoidFunction *)&get)) &&
        get && XR_SUCCEEDED(get(x->session, &hz)) && hz > 0)
        x->refresh_fb = hz;
    hol__xr_say(x, "xr: %s %s", XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME,
                x->refresh_fb > 0 ? "gives the display's refresh rate"
                : x->fb_refresh   ? "gave no rate: it is measured (predictedDisplayPeriod)"
                               : "not listed by the runtime: the refresh rate is measured "
                                 "(predictedDisplayPeriod)");
}

/* The session and everything on it, before the first frame. */
static int hol__setup(hol__xr *x, const void *binding)
{
    if (hol__xr_load_gl(x) || hol__xr_actions(x) || hol__xr_views(x))
        return 1;
    XrSessionCreateInfo sc = {XR_TYPE_SESSION_CREATE_INFO};
    sc.next = binding;
    sc.systemId = x->system;
    HOL__XR(x, "create the headset session", xrCreateSession(x->instance, &sc, &x->session));
    if (hol__xr_spaces(x) || hol__xr_swapchains(x) || hol__xr_quad_setup(x) ||
        hol__xr_hands_setup(x))
        return 1;
    hol__refresh_fb(x);
    if (x->fns->host) {
        typedef const unsigned char *(*get_string_fn)(unsigned);
        get_string_fn gs = (get_string_fn)x->getproc("glGetString");
        const unsigned char *gl = gs ? gs(0x1F01 /* GL_RENDERER */) : NULL;
        x->fns->host(x->fns->user, x->runtime, gl ? (const char *)gl : "", (int)x->eye[0].w,
                     (int)x->eye[0].h);
    }
    /* the platform plays the fit (or not) before its world is asked for */
    if (x->fns->fit && x->fns->fit(x->fns->user, x->have_bounds ? &x->fit : NULL)) {
        x->failed = 1;
        return 1;
    }
#ifndef __ANDROID__
    /* desktop GL encodes sRGB images only when asked (GLES always does) */
    if (x->srgb)
        x->gl.Enable(HOL__GL_FRAMEBUFFER_SRGB);
#endif
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = x->getproc;
    rd.world = x->fns->world(x->fns->user);
    rd.srgb = x->srgb;
    rd.all_programs = 1; /* no shader compiled in a frame the headset waits for */
    if (hol_render_create(&rd, &x->rnd))
        return hol__xr_error(x, "cannot initialise the renderer on this GL context");
    return 0;
}

static void hol__figures(hol__xr *x)
{
    hol__xr_say(x, "xr: frames submitted %ld, reached FOCUSED %s, faded at the boundary %ld",
                x->submitted, x->reached_focused ? "yes" : "no", x->faded);
    if (x->quad_on)
        hol__xr_say(x, "xr: panel quad layer submitted in %ld frames, its image drawn %ld times "
                    "(when its content changed); in the scene behind nearer scenery in %ld",
                    x->quad_frames, x->quad_cache.redraws, x->quad_covered_frames);
    hol__xr_say(x, "xr: controller pulses %ld (%ld into a hedge or a trunk, %ld room steps)%s",
                x->pulses, x->pulses_hit, x->pulses - x->pulses_hit,
                x->fns->haptic ? "" : ": off (--no-haptics)");
    if (!x->ncpu)
        return;
    qsort(x->cpu_ms, (size_t)x->ncpu, sizeof x->cpu_ms[0], hol__cmp);
    qsort(x->step_ms, (size_t)x->ncpu, sizeof x->step_ms[0], hol__cmp);
    hol__xr_say(x, "xr: app thread CPU per stereo frame (step, both eyes, submit; without "
                "xrWaitFrame; unfaded frames): median %.2f ms, p99 %.2f ms over %ld frames; "
                "of it the app step median %.3f ms, p99 %.3f ms",
                x->cpu_ms[x->ncpu / 2], x->cpu_ms[x->ncpu * 99 / 100], x->ncpu,
                x->step_ms[x->ncpu / 2], x->step_ms[x->ncpu * 99 / 100]);
    hol__xr_say(x, "xr: per eye: %ld / %ld draw calls, %ld / %ld triangles (left / right)",
                x->draws[0], x->draws[1], x->tris[0], x->tris[1]);
}

/* The session on x's instance, system and current GL context (binding: the
 * graphics binding for xrCreateSession), its loop until it ends. */
static int hol__run(hol__xr *x, const void *binding)
{
    if (hol__setup(x, binding))
        return 1;
    while (!x->life.done) {
        int leave = x->fns->poll_platform ? x->fns->poll_platform(x->fns->user) : 0;
        if (leave == 2) { /* at once: the platform cannot wait for the runtime */
            hol__xr_say(x, "xr: leaving at once, without ending the session");
            break;
        }
        if (leave && hol_xr_life_quit(&x->life) == HOL_XR_QUIT_REQUEST_EXIT) {
            HOL__XR(x, "end the session", xrRequestExitSession(x->session));
            hol__xr_say(x, "xr: exit requested by the platform");
        }
        hol__xr_events(x);
        if (x->life.done)
            break;
        if (x->life.running) {
            if (hol__xr_frame(x))
                return 1;
        } else {
            struct timespec ts = {0, 10 * 1000 * 1000};
            nanosleep(&ts, NULL);
        }
    }
    hol__xr_tell_env(x, 1);
    hol__figures(x);
    return x->failed;
}

static void hol__destroy(hol__xr *x)
{
    hol_render_destroy(x->rnd);
    hol__xr_quad_free(x);
    hol__xr_hands_free(x);
    hol__xr_views_free(x);
    for (int h = 0; h < 2; h++)
        if (x->grip[h] != XR_NULL_HANDLE)
            hol__xr_gone(x, "destroy the hands' spaces", xrDestroySpace(x->grip[h]));
    if (x->view_space != XR_NULL_HANDLE)
        hol__xr_gone(x, "destroy the head's space", xrDestroySpace(x->view_space));
    if (x->stage != XR_NULL_HANDLE)
        hol__xr_gone(x, "destroy the room's space", xrDestroySpace(x->stage));
    if (x->session != XR_NULL_HANDLE)
        hol__xr_gone(x, "destroy the session", xrDestroySession(x->session));
    if (x->set != XR_NULL_HANDLE)
        hol__xr_gone(x, "destroy the controller actions", xrDestroyActionSet(x->set));
    if (x->external) /* the instance and the GL context are the caller's */
        return;
    if (x->instance != XR_NULL_HANDLE)
        hol__xr_gone(x, "close the OpenXR instance", xrDestroyInstance(x->instance));
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
    if (!x)
        return hol__xr_error(NULL, "out of memory");
    x->d = desc;
    x->fns = fns;
    x->profile[0] = x->profile[1] = -1;
#ifdef __ANDROID__
    x->edpy = EGL_NO_DISPLAY;
    int attached = 0;
#endif
    if (ext) {
        x->external = 1;
        x->instance = ext->instance;
        x->system = ext->system;
        x->getproc = ext->getproc;
        hol__run(x, ext->graphics_binding);
    } else {
        hol__binding binding;
#ifdef __ANDROID__
        if (!hol__android_loader(x, &attached))
#endif
            if (!hol__instance(x) && !hol__xr_graphics(x, &binding))
                hol__run(x, &binding);
    }
    hol__destroy(x);
#ifdef __ANDROID__
    if (attached)
        (*(JavaVM *)desc->android_vm)->DetachCurrentThread((JavaVM *)desc->android_vm);
#endif
    int rc = x->failed;
    free(x);
#ifndef __ANDROID__
    fflush(stdout);
#endif
    return rc;
}

int hol_xr_run(const hol_xr_desc *desc, const hol_xr_app_fns *fns)
{
    return hol__main(desc, fns, NULL);
}

int hol_xr_run_session(const hol_xr_desc *desc, const hol_xr_app_fns *fns,
                       const hol_xr_external *ext)
{
    if (!ext || ext->instance == XR_NULL_HANDLE || !ext->graphics_binding || !ext->getproc)
        return hol__xr_error(NULL, "no instance, graphics binding or getproc given");
    return hol__main(desc, fns, ext);
}
