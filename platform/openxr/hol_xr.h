/* hol_xr.h - the headset: an OpenXR session that feeds the app step and
 * draws its view into the runtime's swapchains.
 *
 * Contract
 * - hol_xr_run owns the whole session: instance (XR_KHR_opengl_enable with
 *   an Xlib/GLX binding on Linux; XR_KHR_opengl_es_enable with EGL on
 *   Android, after xrInitializeLoaderKHR on a thread attached to the Java
 *   VM), system (HMD), GL context, session, reference spaces (STAGE when
 *   the runtime has it, else LOCAL with its floor 1.6 m below the head's
 *   start: hol_xr_pick.h), per-eye swapchains (sRGB when offered; two
 *   passes: llvmpipe and most runtimes here have no multiview), actions
 *   and suggested bindings for khr/simple_controller,
 *   oculus/touch_controller, htc/vive_controller, valve/index_controller
 *   and microsoft/motion_controller (hol_xr_bind.h; every suggestion must
 *   be accepted). Every list the runtime sizes is read with the two-call
 *   idiom; the stereo configuration must have two views.
 * - Every frame: xrWaitFrame, xrBeginFrame, xrLocateViews at the predicted
 *   display time, the head and both grip poses located and turned into
 *   room coordinates (hol_xr_room.h), the input record filled and handed
 *   to the app (fns->step), each eye rendered into its swapchain image with
 *   the view's own pose and asymmetric field of view, xrEndFrame with one
 *   projection layer. The game is paused unless the session is FOCUSED.
 * - Lifecycle as hol_xr_life says (hol_xr_room.h): READY begins the
 *   session, STOPPING ends it, EXITING tears it down and returns; a
 *   STOPPING the app did not ask for (headset off, app in the background)
 *   waits for READY again; the session begun again re-places the room
 *   around the head at its first tracked frame (HOL_INPUT_RECENTRED: the
 *   head's way while stopped is no walk). Quitting (the app's quit, desc.frames reached,
 *   or fns->poll_platform) calls xrRequestExitSession and goes on until
 *   STOPPING (xrEndSession) and EXITING, then destroys everything; without
 *   a running session it leaves at once.
 * - Events: a reference space change of the room's space (the runtime
 *   recentred, or a new play area) places the room on the new origin and
 *   reads the stage bounds again; an interaction profile change reads the
 *   hands' profiles again (printed).
 * - Failures: every xr* result is checked. Any failure, and the loss of
 *   the session (LOSS_PENDING, XR_ERROR_SESSION_LOST) or of the instance
 *   (instance loss pending, XR_ERROR_INSTANCE_LOST: the runtime's service
 *   went away), ends the run with status 1 and one line in words saying
 *   what could not be done, why, and what to do (hol_xr_text.h; never the
 *   C call, never a bare number).
 * - Safety: an eye outside the room sees only the boundary colour (the
 *   world is not drawn and never moves); the HUD status warns.
 * - Everything is allocated before the first frame; frames allocate
 *   nothing. Progress and results are "xr: ..." lines on stdout (the test
 *   reads them), the failure one line on stderr; on Android both go to
 *   logcat (tag "holonomy").
 */
#ifndef HOL_XR_H
#define HOL_XR_H

#include "hol_xr_app.h"

/* 0 ok, 1 failure or loss (one line on stderr). A platform that makes its own
 * instance and GL context runs the same loop with hol_xr_run_session
 * (hol_xr_session.h). */
int hol_xr_run(const hol_xr_desc *desc, const hol_xr_app_fns *fns);

#endif
