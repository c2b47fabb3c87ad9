/* hol_xr_hands.c - the tracked hands (XR_EXT_hand_tracking; see
 * hol_xr_state.h): the extension enabled where the runtime lists it, two
 * hand trackers where the system tracks hands, their 26 joints located
 * each frame in the room's space and given to the record as its 25
 * (platform/shell/hol_xr_hand.h), and the hands-only recentre read from
 * them (core/hol_body.h). A runtime without them, or a tracker that cannot
 * be made, is said in one line and the controllers are drawn as before:
 * never a failure of the run. */
#define _GNU_SOURCE
#include "hol_xr_state.h"

#include "../../core/hol_body.h"
#include "../shell/hol_xr_hand.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

/* The system's answer (XrSystemHandTrackingPropertiesEXT): 1 it tracks
 * hands. */
static int hol__hands_supported(hol__xr *x)
{
    XrSystemHandTrackingPropertiesEXT ht = {XR_TYPE_SYSTEM_HAND_TRACKING_PROPERTIES_EXT};
    XrSystemProperties sp = {XR_TYPE_SYSTEM_PROPERTIES};
    sp.next = &ht;
    XrResult r = xrGetSystemProperties(x->instance, x->system, &sp);
    return XR_SUCCEEDED(r) && ht.supportsHandTracking;
}

int hol__xr_hands_setup(hol__xr *x)
{
    const char *why = NULL;
    if (!x->hand_ext)
        why = "not listed by the runtime: the controllers are drawn";
    else if (!hol__hands_supported(x))
        why = "listed, but the system tracks no hands: the controllers are drawn";
    else if (XR_FAILED(xrGetInstanceProcAddr(x->instance, "xrCreateHandTrackerEXT",
                                             (PFN_xrVoidFunction *)&x->hand_create)) ||
             XR_FAILED(xrGetInstanceProcAddr(x->instance, "xrLocateHandJointsEXT",
                                             (PFN_xrVoidFunction *)&x->hand_locate)) ||
             XR_FAILED(xrGetInstanceProcAddr(x->instance, "xrDestroyHandTrackerEXT",
                                             (PFN_xrVoidFunction *)&x->hand_destroy)) ||
             !x->hand_create || !x->hand_locate || !x->hand_destroy)
        why = "listed, but its functions were not found: the controllers are drawn";
    for (int h = 0; h < 2 && !why; h++) {
        XrHandTrackerCreateInfoEXT ci = {XR_TYPE_HAND_TRACKER_CREATE_INFO_EXT};
        ci.hand = h ? XR_HAND_RIGHT_EXT : XR_HAND_LEFT_EXT;
        ci.handJointSet = XR_HAND_JOINT_SET_DEFAULT_EXT;
        XrResult r = x->hand_create(x->session, &ci, &x->hand_tracker[h]);
        if (XR_FAILED(r)) {
            x->hand_tracker[h] = XR_NULL_HANDLE;
            why = "listed, but a hand tracker could not be made: the controllers are drawn";
        }
    }
    if (why) {
        hol__xr_hands_free(x);
        hol__xr_say(x, "xr: %s %s", XR_EXT_HAND_TRACKING_EXTENSION_NAME, why);
        return 0;
    }
    x->hands_on = 1;
    hol__xr_say(x, "xr: %s enabled: tracked hands are drawn as their 25 joints",
                XR_EXT_HAND_TRACKING_EXTENSION_NAME);
    return 0;
}

void hol__xr_hands_free(hol__xr *x)
{
    for (int h = 0; h < 2; h++)
        if (x->hand_tracker[h] != XR_NULL_HANDLE) {
            hol__xr_gone(x, "destroy the hand trackers", x->hand_destroy(x->hand_tracker[h]));
            x->hand_tracker[h] = XR_NULL_HANDLE;
        }
    x->hands_on = 0;
}

/* One hand's joints at time t in the room's space, kept as OpenXR gives
 * them (x->hand_raw[h]). 1 a failure (reported). */
static int hol__hand_locate(hol__xr *x, int h, XrTime t)
{
    XrHandJointLocationEXT loc[HOL_XR_HAND_JOINTS];
    XrHandJointLocationsEXT ls = {XR_TYPE_HAND_JOINT_LOCATIONS_EXT};
    ls.jointCount = HOL_XR_HAND_JOINTS;
    ls.jointLocations = loc;
    XrHandJointsLocateInfoEXT li = {XR_TYPE_HAND_JOINTS_LOCATE_INFO_EXT};
    li.baseSpace = x->stage;
    li.time = t;
    HOL__XR(x, "locate the hands' joints", x->hand_locate(x->hand_tracker[h], &li, &ls));
    hol__xr_hand_raw *r = &x->hand_raw[h];
    r->active = ls.isActive != XR_FALSE;
    for (int i = 0; i < HOL_XR_HAND_JOINTS; i++) {
        float q[4];
        hol__pose_in(&loc[i].pose, r->pos[i], q);
        r->radius[i] = loc[i].radius;
        r->flags[i] = (unsigned)loc[i].locationFlags;
    }
    return 0;
}

int hol__xr_hands_locate(hol__xr *x, XrTime t)
{
    memset(x->hand_raw, 0, sizeof x->hand_raw);
    for (int h = 0; h < 2 && x->hands_on; h++)
        if (hol__hand_locate(x, h, t))
            return 1;
    return 0;
}

uint32_t hol__xr_hands_gesture(hol__xr *x, int focused, double t)
{
    /* palms up is the same in the stage as in the room (the room only
     * turns about the vertical): the default placement will do */
    hol_xr_calib stage;
    memset(&stage, 0, sizeof stage);
    hol_hand_joints j[2];
    memset(j, 0, sizeof j);
    for (int h = 0; h < 2 && focused; h++) {
        const hol__xr_hand_raw *r = &x->hand_raw[h];
        hol_xr_hand_joints(&stage, r->active, r->pos, r->radius, r->flags, &j[h]);
    }
    return hol_gesture_step(&x->gesture, j, t);
}

void hol__xr_hands_room(hol__xr *x, hol_hand_joints out[2])
{
    for (int h = 0; h < 2; h++) {
        const hol__xr_hand_raw *r = &x->hand_raw[h];
        if (hol_xr_hand_joints(&x->calib, r->active, r->pos, r->radius, r->flags, &out[h]) &&
            !x->hands_located[h]++)
            hol__xr_say(x, "xr: hand %s located (25 joints)", h ? "right" : "left");
    }
}
