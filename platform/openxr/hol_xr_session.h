/* hol_xr_session.h - the headset's session loop on an instance and a GL
 * context the caller made: for a platform entry that owns them (an Android
 * NativeActivity that initialises the loader, creates the instance with
 * XR_KHR_android_create_instance and its own EGL context, then hands them
 * over). Includes the OpenXR headers; hol_xr.h does not.
 *
 * Contract
 * - hol_xr_run_session does everything hol_xr_run does after the instance
 *   and the GL context exist: actions and suggested bindings (on the given
 *   instance), the session (its next chain is graphics_binding, e.g. an
 *   XrGraphicsBindingOpenGLESAndroidKHR or XrGraphicsBindingOpenGLXlibKHR
 *   for the GL context current on the calling thread), spaces, swapchains,
 *   the renderer, the frame loop and the whole lifecycle (hol_xr.h), and
 *   tears down what it made: session, spaces, swapchains, action set,
 *   renderer. It never destroys the instance or the GL context, so the
 *   caller may run another session on them (after a loss or a resume).
 * - The instance must have the graphics extension of the binding enabled
 *   (XR_KHR_opengl_es_enable on Android, XR_KHR_opengl_enable on Linux)
 *   and the runtime's graphics requirements must have been queried
 *   (xrGet*GraphicsRequirementsKHR) before, as OpenXR demands.
 * - 0 ok, 1 failure (one line on stderr).
 */
#ifndef HOL_XR_SESSION_H
#define HOL_XR_SESSION_H

#include <openxr/openxr.h>

#include "../../render/hol_render.h"
#include "hol_xr_app.h"

typedef struct hol_xr_external {
    XrInstance instance;
    XrSystemId system;
    const void *graphics_binding; /* the XrGraphicsBinding*KHR struct */
    hol_render_getproc getproc;   /* the GL context's get-proc-address */
} hol_xr_external;

int hol_xr_run_session(const hol_xr_desc *desc, const hol_xr_app_fns *fns,
                       const hol_xr_external *ext);

#endif
