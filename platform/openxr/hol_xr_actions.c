/* hol_xr_actions.c - the headset's actions, suggested bindings and spaces
 * (see hol_xr_impl.h; the bindings themselves are hol_xr_bind.h). */
#define _GNU_SOURCE
#include "hol_xr_impl.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- actions -------------------------------------------------------------- */

static XrPath hol__path(hol__xr *x, const char *s)
{
    XrPath p = XR_NULL_PATH;
    xrStringToPath(x->instance, s, &p);
    return p;
}

static int hol__action(hol__xr *x, XrAction *out, const char *name, const char *local,
                       XrActionType type, int hands)
{
    XrActionCreateInfo ai = {XR_TYPE_ACTION_CREATE_INFO};
    snprintf(ai.actionName, sizeof ai.actionName, "%s", name);
    snprintf(ai.localizedActionName, sizeof ai.localizedActionName, "%s", local);
    ai.actionType = type;
    if (hands) {
        ai.countSubactionPaths = 2;
        ai.subactionPaths = x->hand_path;
    }
    HOL__XR(x, xrCreateAction(x->set, &ai, out));
    return 0;
}

int hol__actions(hol__xr *x)
{
    XrActionSetCreateInfo si = {XR_TYPE_ACTION_SET_CREATE_INFO};
    snprintf(si.actionSetName, sizeof si.actionSetName, "game");
    snprintf(si.localizedActionSetName, sizeof si.localizedActionSetName, "Game");
    HOL__XR(x, xrCreateActionSet(x->instance, &si, &x->set));
    x->hand_path[0] = hol__path(x, "/user/hand/left");
    x->hand_path[1] = hol__path(x, "/user/hand/right");
    if (hol__action(x, &x->grip_action, "grip", "Hand pose", XR_ACTION_TYPE_POSE_INPUT, 1))
        return 1;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        if (hol__action(x, &x->act[a], hol_xr_action_name(a), hol_xr_action_label(a),
                        XR_ACTION_TYPE_BOOLEAN_INPUT, 0))
            return 1;
    /* the suggested bindings (hol_xr_bind.h): every one must be accepted */
    const hol_xr_profile *binds = hol_xr_profiles();
    for (int i = 0; i < HOL_XR_NPROFILES; i++) {
        XrActionSuggestedBinding sb[HOL_XR_ACT_COUNT + 2];
        uint32_t n = 0;
        for (int h = 0; h < 2; h++) {
            sb[n].action = x->grip_action;
            sb[n++].binding = hol__path(x, hol_xr_grip_path(h));
        }
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
            sb[n].action = x->act[a];
            sb[n++].binding = hol__path(x, binds[i].path[a]);
        }
        XrInteractionProfileSuggestedBinding ps = {
            XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        ps.interactionProfile = hol__path(x, binds[i].profile);
        ps.countSuggestedBindings = n;
        ps.suggestedBindings = sb;
        XrResult r = xrSuggestInteractionProfileBindings(x->instance, &ps);
        if (XR_FAILED(r))
            return hol__fail(x, binds[i].profile, r);
        printf("xr: bindings accepted %s\n", binds[i].profile + 22);
    }
    return 0;
}

int hol__spaces(hol__xr *x)
{
    XrSessionActionSetsAttachInfo at = {XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    at.countActionSets = 1;
    at.actionSets = &x->set;
    HOL__XR(x, xrAttachSessionActionSets(x->session, &at));
    for (int h = 0; h < 2; h++) {
        XrActionSpaceCreateInfo ai = {XR_TYPE_ACTION_SPACE_CREATE_INFO};
        ai.action = x->grip_action;
        ai.subactionPath = x->hand_path[h];
        ai.poseInActionSpace.orientation.w = 1;
        HOL__XR(x, xrCreateActionSpace(x->session, &ai, &x->grip[h]));
    }
    uint32_t n = 0;
    XrReferenceSpaceType types[16];
    HOL__XR(x, xrEnumerateReferenceSpaces(x->session, 16, &n, types));
    x->is_stage = 0;
    for (uint32_t i = 0; i < n; i++)
        x->is_stage |= types[i] == XR_REFERENCE_SPACE_TYPE_STAGE;
    XrReferenceSpaceCreateInfo ri = {XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    ri.referenceSpaceType = x->is_stage ? XR_REFERENCE_SPACE_TYPE_STAGE
                                        : XR_REFERENCE_SPACE_TYPE_LOCAL;
    ri.poseInReferenceSpace.orientation.w = 1;
    HOL__XR(x, xrCreateReferenceSpace(x->session, &ri, &x->stage));
    ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    HOL__XR(x, xrCreateReferenceSpace(x->session, &ri, &x->view_space));
    printf("xr: reference space %s\n", x->is_stage ? "STAGE" : "LOCAL");
    if (x->is_stage) {
        XrExtent2Df b = {0, 0};
        XrResult r = xrGetReferenceSpaceBoundsRect(x->session, XR_REFERENCE_SPACE_TYPE_STAGE, &b);
        if (r == XR_SUCCESS) {
            x->bounds_small = !hol_xr_bounds_hold_room(b.width, b.height);
            printf("xr: stage bounds %.2f x %.2f m%s\n", b.width, b.height,
                   x->bounds_small ? " (smaller than the 3 x 3 m room)" : "");
        } else {
            printf("xr: stage bounds not given by the runtime\n");
        }
    }
    return 0;
}

int hol__bool(hol__xr *x, int a)
{
    XrActionStateGetInfo gi = {XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = x->act[a];
    XrActionStateBoolean st = {XR_TYPE_ACTION_STATE_BOOLEAN};
    if (XR_FAILED(xrGetActionStateBoolean(x->session, &gi, &st)))
        return 0;
    return st.isActive && st.currentState;
}
