/* hol_xr_app.h - what the headset layer is given: the app it runs
 * (hol_xr_app_fns) and the run's options (hol_xr_desc). Types only; the
 * entries are hol_xr_run (hol_xr.h) and hol_xr_run_session
 * (hol_xr_session.h), whose contracts say how they are used.
 */
#ifndef HOL_XR_APP_H
#define HOL_XR_APP_H

#include "../../core/hol_app.h"
#include "../../core/hol_fit.h"
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
     * activity's looper; a signal on the desktop). Returns 0 to go on, 1
     * when the platform wants to leave (the session then ends properly,
     * through STOPPING; 1 may come again while it does), 2 to leave at
     * once without waiting for the runtime (a second Ctrl-C). */
    int (*poll_platform)(void *user);
    /* Optional: the play area's fit (core/hol_fit.h: the room and cell
     * size the stage bounds hold; NULL when the runtime gives no bounds or
     * the room's space is LOCAL), called once after the stage bounds are
     * read and before the first world() or step(): the platform plays it
     * in every level that names neither a room nor a cell, unless its own
     * options name them (and may create its session here). Returns 0 to go
     * on, else the run ends with status 1 (the platform said why). A new
     * play area later (a reference space change) is told ("xr: ..."), not
     * applied: the room in play stays. */
    int (*fit)(void *user, const hol_fit *f);
    /* Optional: the view now (before the first step too), so the room in
     * play is placed in the stage from the first frame; NULL: the 3 x 3 m
     * room until the first step. */
    const hol_app_view *(*view)(void *user);
    /* Optional: the controllers' pulses of the last step (the app's
     * events.haptic, core/hol_haptic.h), played with xrApplyHapticFeedback;
     * NULL: none (holonomy xr --no-haptics). */
    const hol_haptic *(*haptic)(void *user);
    /* Optional: what the headset's side is (for the platform's records:
     * holonomy xr's environment.csv), called once just before fit with the
     * runtime's name and version, the GL renderer and eye 0's image size;
     * the strings live only during the call. */
    void (*host)(void *user, const char *runtime, const char *gl_renderer, int eye_w,
                 int eye_h);
    /* Optional: what is known only once frames run, called once: the
     * controller (the hands' interaction profile as the input's device
     * name, hol_input_device_name: "xr-simple", "xr-touch", ...; "xr" for
     * a profile not in hol_xr_bind.h's list; "" none) and the display's
     * refresh rate in Hz (XR_FB_display_refresh_rate's where the runtime
     * lists the extension, how "runtime"; else 1e9 over the mean
     * predictedDisplayPeriod of xrWaitFrame's first HOL_XR_REFRESH_FRAMES
     * frames, how "measured"; 0 and "" when no frame ran). Called at the
     * first frame where the rate is known and a hand's profile is (or
     * HOL_XR_PROFILE_WAIT frames have passed without one), else when the
     * run ends. */
    void (*environment)(void *user, const char *controller, double refresh_hz,
                        const char *how);
    /* Optional: at every change of the session's state, 1 when the new
     * state is FOCUSED, else 0 (VISIBLE, SYNCHRONIZED, STOPPING, lost,
     * ...): what the game's own pause does not stop follows it (the
     * sound is held). The steps tell it too (HOL_INPUT_FOCUSED), but none
     * runs once the session stops. */
    void (*focus)(void *user, int focused);
} hol_xr_app_fns;

#define HOL_XR_REFRESH_FRAMES 60
#define HOL_XR_PROFILE_WAIT 600

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
    int space;               /* 0: STAGE when the runtime has it, else LOCAL;
                                HOL_XR_SPACE_LOCAL (hol_xr_pick.h): LOCAL */
    int panel;               /* the world panel (hol_xr_quad.h):
                                HOL_XR_PANEL_QUAD (0) an OpenXR quad layer
                                where the runtime makes its swapchain, else
                                in the scene; HOL_XR_PANEL_SCENE in the
                                scene */
    int seated;              /* 1: seated play (core/hol_input.h
                                HOL_INPUT_SEATED): the head walks nothing,
                                either thumbstick's (trackpad's) push is
                                one room step (hol_xr_stick_path) */
    float play_area[2];      /* > 0: the play area's width and depth in
                                metres, given by hand: used instead of the
                                runtime's stage bounds (a runtime without
                                them, or a smaller area than it draws) */
    /* Android only: the JavaVM and the activity object (jobject), for
     * xrInitializeLoaderKHR and XR_KHR_android_create_instance. */
    void *android_vm, *android_activity;
} hol_xr_desc;

#endif
