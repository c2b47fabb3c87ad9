/* hol_xr.h - the headset: an OpenXR session that feeds the app step and
 * draws its view into the runtime's swapchains.
 *
 * Contract
 * - hol_xr_run owns the whole session: instance (XR_KHR_opengl_enable with
 *   an Xlib/GLX binding on Linux; XR_KHR_opengl_es_enable with EGL on
 *   Android), system (HMD), GL context, session, reference spaces (STAGE
 *   when the runtime has it, else LOCAL), per-eye swapchains (two passes:
 *   llvmpipe and most runtimes here have no multiview), actions and
 *   suggested bindings for khr/simple_controller, oculus/touch_controller,
 *   htc/vive_controller, valve/index_controller and
 *   microsoft/motion_controller (every suggestion must be accepted).
 * - Every frame: xrWaitFrame, xrBeginFrame, xrLocateViews at the predicted
 *   display time, the head and both grip poses located and turned into
 *   room coordinates (hol_xr_room.h), the input record filled and handed
 *   to the app (fns->step), each eye rendered into its swapchain image with
 *   the view's own pose and asymmetric field of view, xrEndFrame with one
 *   projection layer. The game is paused unless the session is FOCUSED.
 * - Lifecycle as hol_xr_life says (hol_xr_room.h): READY begins the
 *   session, STOPPING ends it, EXITING and LOSS_PENDING tear it down and
 *   return; a STOPPING the app did not ask for (headset off, app in the
 *   background) waits for READY again. Quitting (the app's quit,
 *   desc.frames reached, or fns->poll_platform) calls
 *   xrRequestExitSession and goes on until STOPPING (xrEndSession) and
 *   EXITING, then destroys everything; without a running session it
 *   leaves at once. A runtime that goes away (xrPollEvent fails) is a
 *   failure.
 * - Safety: an eye outside the room sees only the boundary colour (the
 *   world is not drawn and never moves); the HUD status warns.
 * - Everything is allocated before the first frame; frames allocate
 *   nothing. Progress and results are printed as "xr: ..." lines on
 *   stdout (the test reads them); errors as one line on stderr.
 */
#ifndef HOL_XR_H
#define HOL_XR_H

#include "../../core/hol_app.h"
#include "../../core/hol_input.h"

struct hol_world;

typedef struct hol_xr_app_fns {
    void *user;
    /* One app step with the input; *out_view is what to draw. Returns 0 to
     * go on, 1 when the app asks to quit, -1 on failure. */
    int (*step)(void *user, const hol_input *in, const hol_app_view **out_view);
    struct hol_world *(*world)(void *user);
    /* A level (re)started in the last step: resident meshes are stale. */
    int (*level_started)(void *user);
    /* Optional: the platform's own events once per loop (Android: the
     * activity's looper; pause, resume, window). Returns 1 when the
     * platform wants to leave (the session then exits properly). */
    int (*poll_platform)(void *user);
} hol_xr_app_fns;

typedef struct hol_xr_desc {
    const char *app_name;    /* NULL: "Holonomy" */
    long frames;             /* > 0: quit after this many submitted frames */
    long check_frame;        /* >= 0 with check_dir: read eye 0 of this frame
                                back and compare it with an OSMesa render of
                                the same eye (desktop only) */
    const char *check_dir;
    const hol_input *script; /* optional recorded head motion: frame k uses
                                script[k % nscript]'s head pose (in room
                                coordinates) instead of the runtime's (the
                                simulated headset does not move) */
    long nscript;
    /* Android only: the JavaVM and the activity object (jobject), for
     * xrInitializeLoaderKHR and XR_KHR_android_create_instance. */
    void *android_vm, *android_activity;
} hol_xr_desc;

/* 0 ok, 1 failure (one line on stderr). A platform that makes its own
 * instance and GL context runs the same loop with hol_xr_run_session
 * (hol_xr_session.h). */
int hol_xr_run(const hol_xr_desc *desc, const hol_xr_app_fns *fns);

#endif
