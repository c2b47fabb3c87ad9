/* hol_xr_actions.c - the headset's actions, suggested bindings, reference
 * spaces and stage bounds (see hol_xr_state.h; the bindings themselves are
 * hol_xr_bind.h, the choice of space hol_xr_pick.h). */
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- actions -------------------------------------------------------------- */

static int hol__path(hol__xr *x, const char *s, XrPath *out)
{
    char doing[160];
    snprintf(doing, sizeof doing, "name the path %.120s", s);
    HOL__XR(x, doing, xrStringToPath(x->instance, s, out));
    return 0;
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
    HOL__XR(x, "create the controller actions", xrCreateAction(x->set, &ai, out));
    return 0;
}

/* The suggested bindings of profile i (hol_xr_bind.h): all must be accepted. */
static int hol__suggest(hol__xr *x, const hol_xr_profile *p)
{
    XrActionSuggestedBinding sb[HOL_XR_ACT_COUNT + 6];
    uint32_t n = 0;
    for (int h = 0; h < 2; h++) {
        sb[n].action = x->grip_action;
        if (hol__path(x, hol_xr_grip_path(h), &sb[n++].binding))
            return 1;
        if (p->no_haptic)
            continue;
        sb[n].action = x->haptic_action;
        if (hol__path(x, hol_xr_haptic_path(h), &sb[n++].binding))
            return 1;
    }
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
        sb[n].action = x->act[a];
        if (hol__path(x, p->path[a], &sb[n++].binding))
            return 1;
    }
    for (int h = 0; x->d->seated && h < 2; h++) { /* seated: the sticks */
        const char *s = hol_xr_stick_path((int)(p - hol_xr_profiles()), h);
        sb[n].action = x->stick_action;
        if (s && hol__path(x, s, &sb[n++].binding))
            return 1;
    }
    XrInteractionProfileSuggestedBinding ps = {XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    if (hol__path(x, p->profile, &ps.interactionProfile))
        return 1;
    ps.countSuggestedBindings = n;
    ps.suggestedBindings = sb;
    char doing[160];
    snprintf(doing, sizeof doing, "bind the %s controllers", p->name);
    HOL__XR(x, doing, xrSuggestInteractionProfileBindings(x->instance, &ps));
    hol__xr_say(x, "xr: bindings accepted %s", p->name);
    return 0;
}

int hol__xr_actions(hol__xr *x)
{
    XrActionSetCreateInfo si = {XR_TYPE_ACTION_SET_CREATE_INFO};
    snprintf(si.actionSetName, sizeof si.actionSetName, "game");
    snprintf(si.localizedActionSetName, sizeof si.localizedActionSetName, "Game");
    HOL__XR(x, "create the controller actions", xrCreateActionSet(x->instance, &si, &x->set));
    if (hol__path(x, "/user/hand/left", &x->hand_path[0]) ||
        hol__path(x, "/user/hand/right", &x->hand_path[1]) ||
        hol__action(x, &x->grip_action, "grip", "Hand pose", XR_ACTION_TYPE_POSE_INPUT, 1) ||
        hol__action(x, &x->haptic_action, "haptic", "Pulse", XR_ACTION_TYPE_VIBRATION_OUTPUT, 1) ||
        (x->d->seated && hol__action(x, &x->stick_action, "step", "Seated step",
                                     XR_ACTION_TYPE_VECTOR2F_INPUT, 1)))
        return 1;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        if (hol__action(x, &x->act[a], hol_xr_action_name(a), hol_xr_action_label(a),
                        XR_ACTION_TYPE_BOOLEAN_INPUT, 0))
            return 1;
    const hol_xr_profile *binds = hol_xr_profiles();
    for (int i = 0; i < HOL_XR_NPROFILES; i++)
        if ((!binds[i].extension || x->hand_interaction) && hol__suggest(x, &binds[i]))
            return 1;
    x->profile[0] = x->profile[1] = -1;
    return 0;
}

/* ---- spaces --------------------------------------------------------------- */

/* The runtime's reference spaces (two-call idiom) and the room's space
 * (hol_xr_pick_space: STAGE, else LOCAL with its floor 1.6 m down). */
static int hol__room_space(hol__xr *x)
{
    uint32_t n = 0;
    HOL__XR(x, "list the reference spaces", xrEnumerateReferenceSpaces(x->session, 0, &n, NULL));
    XrReferenceSpaceType *types = calloc(n ? n : 1, sizeof *types);
    int *ints = calloc(n ? n : 1, sizeof *ints);
    XrResult r = types && ints ? xrEnumerateReferenceSpaces(x->session, n, &n, types)
                               : XR_ERROR_OUT_OF_MEMORY;
    for (uint32_t i = 0; XR_SUCCEEDED(r) && i < n; i++)
        ints[i] = (int)types[i];
    x->space_type = XR_SUCCEEDED(r) ? hol_xr_pick_space(ints, n, x->d->space, &x->origin_y) : 0;
    free(types);
    free(ints);
    if (XR_FAILED(r))
        return hol__xr_fail(x, "list the reference spaces", r);
    if (!x->space_type)
        return hol__xr_error(x, "the OpenXR runtime offers neither a STAGE nor a LOCAL "
                             "reference space (OpenXR requires LOCAL): the runtime is broken");
    XrReferenceSpaceCreateInfo ri = {XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    ri.referenceSpaceType = (XrReferenceSpaceType)x->space_type;
    ri.poseInReferenceSpace.orientation.w = 1;
    ri.poseInReferenceSpace.position.y = (float)x->origin_y;
    HOL__XR(x, "create the room's reference space",
            xrCreateReferenceSpace(x->session, &ri, &x->stage));
    if (x->space_type == HOL_XR_SPACE_STAGE)
        hol__xr_say(x, "xr: reference space STAGE");
    else
        hol__xr_say(x, "xr: reference space LOCAL (%s): the floor taken %.2f m below the head's "
                    "start",
                    x->d->space == HOL_XR_SPACE_LOCAL ? "asked for" : "no STAGE", -x->origin_y);
    return 0;
}

int hol__xr_spaces(hol__xr *x)
{
    XrSessionActionSetsAttachInfo at = {XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    at.countActionSets = 1;
    at.actionSets = &x->set;
    HOL__XR(x, "attach the controller actions", xrAttachSessionActionSets(x->session, &at));
    for (int h = 0; h < 2; h++) {
        XrActionSpaceCreateInfo ai = {XR_TYPE_ACTION_SPACE_CREATE_INFO};
        ai.action = x->grip_action;
        ai.subactionPath = x->hand_path[h];
        ai.poseInActionSpace.orientation.w = 1;
        HOL__XR(x, "create the hands' spaces", xrCreateActionSpace(x->session, &ai, &x->grip[h]));
    }
    if (hol__room_space(x))
        return 1;
    XrReferenceSpaceCreateInfo ri = {XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    ri.poseInReferenceSpace.orientation.w = 1;
    HOL__XR(x, "create the head's space", xrCreateReferenceSpace(x->session, &ri, &x->view_space));
    return hol__xr_bounds(x);
}

/* The stage bounds (the play area) and the room and cell that fit them
 * (core/hol_fit.h), told in one line; a runtime without them (Monado's
 * null compositor) is not an error. */
int hol__xr_bounds(hol__xr *x)
{
    x->have_bounds = x->bounds_small = 0;
    x->fit_text[0] = 0;
    if (x->space_type != HOL_XR_SPACE_STAGE)
        return 0;
    XrExtent2Df b = {0, 0};
    XrResult r = xrGetReferenceSpaceBoundsRect(x->session, XR_REFERENCE_SPACE_TYPE_STAGE, &b);
    if (XR_FAILED(r))
        return hol__xr_fail(x, "read the play area's bounds", r);
    if (x->d->play_area[0] > 0 && x->d->play_area[1] > 0) { /* given by hand */
        hol__xr_say(x, "xr: play area %.2f x %.2f m given (the runtime's bounds: %s)",
                    x->d->play_area[0], x->d->play_area[1],
                    r == XR_SPACE_BOUNDS_UNAVAILABLE || b.width <= 0 ? "none" : "not used");
        b.width = x->d->play_area[0];
        b.height = x->d->play_area[1];
        r = XR_SUCCESS;
    }
    if (r == XR_SPACE_BOUNDS_UNAVAILABLE || b.width <= 0 || b.height <= 0 ||
        hol_fit_rect(b.width, b.height, -1, &x->fit) != HOL_OK) {
        hol__xr_say(x, "xr: stage bounds not given by the runtime: the room is not fitted to "
                    "the play area");
        return 0;
    }
    x->have_bounds = 1;
    x->bounds_w = b.width;
    x->bounds_d = b.height;
    x->bounds_small = x->fit.too_small;
    hol_fit_text(&x->fit, -1, x->fit_text, sizeof x->fit_text);
    hol__xr_say(x, "xr: stage bounds %.2f x %.2f m", b.width, b.height);
    hol__xr_say(x, "xr: %s", x->fit_text);
    return 0;
}

/* ---- haptics --------------------------------------------------------------- */

/* The pulses of the last step (core/hol_haptic.h, through fns->haptic),
 * played on their hands. A failed pulse is said once and never ends the
 * run, unless the session or the instance is gone. */
int hol__xr_haptics(hol__xr *x)
{
    const hol_haptic *hp = x->fns->haptic ? x->fns->haptic(x->fns->user) : NULL;
    for (int h = 0; hp && h < 2; h++) {
        if (!(hp->hand[h].amplitude > 0))
            continue;
        XrHapticVibration v = {XR_TYPE_HAPTIC_VIBRATION};
        v.duration = (XrDuration)hp->hand[h].duration_ms * 1000000;
        v.frequency = XR_FREQUENCY_UNSPECIFIED;
        v.amplitude = hp->hand[h].amplitude;
        XrHapticActionInfo hi = {XR_TYPE_HAPTIC_ACTION_INFO};
        hi.action = x->haptic_action;
        hi.subactionPath = x->hand_path[h];
        XrResult r = xrApplyHapticFeedback(x->session, &hi, (const XrHapticBaseHeader *)&v);
        if (XR_FAILED(r) && hol_xr_result_is_loss((int)r))
            return hol__xr_fail(x, "pulse a controller", r);
        if (XR_SUCCEEDED(r)) {
            x->pulses++;
            x->pulses_hit += hp->hand[h].why != HOL_HAPTIC_STEP;
        }
        if (XR_FAILED(r) && !x->haptic_failed) {
            x->haptic_failed = 1;
            hol__xr_say(x, "xr: cannot pulse the %s controller: %s; the run goes on without",
                        h ? "right" : "left", hol_xr_result_words((int)r));
        }
    }
    return 0;
}

/* ---- state ---------------------------------------------------------------- */

int hol__xr_stick(hol__xr *x, int h, float out[2])
{
    XrActionStateGetInfo gi = {XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = x->stick_action;
    gi.subactionPath = x->hand_path[h];
    XrActionStateVector2f st = {XR_TYPE_ACTION_STATE_VECTOR2F};
    HOL__XR(x, "read the thumbsticks", xrGetActionStateVector2f(x->session, &gi, &st));
    out[0] = st.isActive && isfinite(st.currentState.x) ? st.currentState.x : 0;
    out[1] = st.isActive && isfinite(st.currentState.y) ? st.currentState.y : 0;
    return 0;
}

int hol__xr_bool(hol__xr *x, int a, int *out_held)
{
    XrActionStateGetInfo gi = {XR_TYPE_ACTION_STATE_GET_INFO};
    gi.action = x->act[a];
    XrActionStateBoolean st = {XR_TYPE_ACTION_STATE_BOOLEAN};
    HOL__XR(x, "read the controller buttons", xrGetActionStateBoolean(x->session, &gi, &st));
    *out_held = st.isActive && st.currentState;
    return 0;
}

/* The hands' interaction profiles now (after an interaction profile
 * changed event): x->profile[h], one line each that changed. Only for the
 * prompts: a failed read keeps the old ones (one line), unless the session
 * or the instance is gone. */
int hol__xr_profiles_now(hol__xr *x)
{
    int any = 0;
    for (int h = 0; h < 2; h++) {
        XrInteractionProfileState st = {XR_TYPE_INTERACTION_PROFILE_STATE};
        char path[XR_MAX_PATH_LENGTH] = "";
        uint32_t len = 0;
        XrResult r = xrGetCurrentInteractionProfile(x->session, x->hand_path[h], &st);
        if (XR_SUCCEEDED(r) && st.interactionProfile != XR_NULL_PATH)
            r = xrPathToString(x->instance, st.interactionProfile, sizeof path, &len, path);
        if (XR_FAILED(r)) {
            if (hol_xr_result_is_loss((int)r))
                return hol__xr_fail(x, "read the controllers' profile", r);
            hol__xr_say(x, "xr: cannot read the controllers' profile: %s (%s); the prompts keep "
                        "the last one",
                        hol_xr_result_words((int)r), hol_xr_result_name((int)r)
                                                      ? hol_xr_result_name((int)r)
                                                      : "an extension's result");
            return 0;
        }
        int p = st.interactionProfile == XR_NULL_PATH ? -1 : hol_xr_profile_find(path);
        if (p != x->profile[h])
            hol__xr_say(x, "xr: %s hand: %s", h ? "right" : "left",
                        st.interactionProfile == XR_NULL_PATH ? "no controller"
                        : p >= 0                              ? hol_xr_profiles()[p].name
                                                           : path);
        x->profile[h] = p;
        any |= st.interactionProfile != XR_NULL_PATH && p < 0;
    }
    x->any_profile = any;
    return 0;
}
