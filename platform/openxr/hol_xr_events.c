/* hol_xr_events.c - the runtime's events (see hol_xr_state.h): the session
 * lifecycle (hol_xr_life, hol_xr_room.h), the loss of the session or the
 * instance (the run fails with one line, exit status 1), a reference space
 * changed (the runtime recentred, or the play area was redrawn: the room
 * is placed on the new origin and the bounds are read again), and the
 * hands' interaction profiles changed (read again, for the prompts). */
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

static const char *hol__state_name(int s)
{
    static const char *const n[] = {"UNKNOWN", "IDLE", "READY", "SYNCHRONIZED", "VISIBLE",
                                    "FOCUSED", "STOPPING", "LOSS_PENDING", "EXITING"};
    return s >= 0 && s <= 8 ? n[s] : "?";
}

static void hol__state_changed(hol__xr *x, const XrEventDataSessionStateChanged *e)
{
    int state = (int)e->state;
    hol__xr_say(x, "xr: state %s", hol__state_name(state));
    x->reached_focused |= state == HOL_XR_STATE_FOCUSED;
    hol_xr_do d = hol_xr_life_event(&x->life, state);
    if (x->fns->focus)
        x->fns->focus(x->fns->user, x->life.focused);
    if (state == HOL_XR_STATE_LOSS_PENDING) {
        x->lost = 1;
        hol__xr_error(x, "the headset session was lost (the headset was disconnected or the "
                      "runtime failed): reconnect the headset, then start Holonomy again");
    } else if (d == HOL_XR_DO_BEGIN) {
        XrSessionBeginInfo sb = {XR_TYPE_SESSION_BEGIN_INFO};
        sb.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        XrResult r = xrBeginSession(x->session, &sb);
        if (XR_FAILED(r)) {
            hol__xr_fail(x, "begin the session", r);
            x->life.done = 1;
        }
    } else if (d == HOL_XR_DO_END) {
        XrResult r = xrEndSession(x->session);
        if (XR_FAILED(r)) {
            hol__xr_fail(x, "end the session", r);
            x->life.done = 1;
        } else {
            hol__xr_say(x, "xr: session ended after STOPPING%s",
                        x->life.quit_requested ? "" : " (by the runtime: waiting for READY)");
        }
    }
}

/* The runtime moved the origin of a reference space: a recentre from its
 * menu (LOCAL, STAGE) or a new play area (STAGE). The room follows the
 * runtime: placed on the new origin as at the start (an earlier recentre
 * action is dropped), the bounds read again. */
static void hol__space_changed(hol__xr *x, const XrEventDataReferenceSpaceChangePending *e)
{
    if (e->session != x->session || (int)e->referenceSpaceType != x->space_type)
        return;
    memset(&x->calib, 0, sizeof x->calib);
    hol_xr_life_recentred(&x->life); /* the app re-places the room: the head's jump is no walk */
    hol__xr_say(x, "xr: reference space %s changed (%s): the room is placed on its new origin",
                x->space_type == HOL_XR_SPACE_STAGE ? "STAGE" : "LOCAL",
                x->space_type == HOL_XR_SPACE_STAGE ? "recentred, or a new play area"
                                                 : "recentred");
    if (hol__xr_bounds(x))
        x->life.done = 1;
    else if (x->have_bounds)
        hol__xr_say(x, "xr: the room in play stays as it is; Holonomy started again plays the "
                    "new fit");
}

static void hol__event(hol__xr *x, const XrEventDataBuffer *ev)
{
    switch (ev->type) {
    case XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED:
        hol__state_changed(x, (const XrEventDataSessionStateChanged *)ev);
        break;
    case XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING:
        x->lost = 1;
        x->life.done = 1;
        hol__xr_error(x, "the OpenXR runtime is shutting down (instance loss pending): start its "
                      "service again, then Holonomy");
        break;
    case XR_TYPE_EVENT_DATA_REFERENCE_SPACE_CHANGE_PENDING:
        hol__space_changed(x, (const XrEventDataReferenceSpaceChangePending *)ev);
        break;
    case XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED:
        if (hol__xr_profiles_now(x))
            x->life.done = 1;
        break;
    case XR_TYPE_EVENT_DATA_EVENTS_LOST:
        hol__xr_say(x, "xr: the runtime lost %u events",
                    ((const XrEventDataEventsLost *)ev)->lostEventCount);
        break;
    default:
        break;
    }
}

void hol__xr_events(hol__xr *x)
{
    for (;;) {
        XrEventDataBuffer ev = {XR_TYPE_EVENT_DATA_BUFFER};
        XrResult r = xrPollEvent(x->instance, &ev);
        if (r == XR_EVENT_UNAVAILABLE)
            return;
        if (XR_FAILED(r)) { /* the runtime went away */
            hol__xr_fail(x, "read the runtime's events", r);
            x->life.done = 1;
            return;
        }
        hol__event(x, &ev);
        if (x->life.done)
            return;
    }
}
