/* hol_xr_bind.h - the headset's actions and their suggested bindings, as
 * pure data and functions (no OpenXR headers): what the session layer
 * hands to xrSuggestInteractionProfileBindings and how the boolean action
 * states become the input record's buttons. Tested without a runtime
 * (tests/test_xr_bind.c checks every path against the OpenXR 1.0
 * specification's list for its interaction profile).
 *
 * Contract
 * - Actions: a grip pose per hand (/user/hand/{left,right}/input/grip/pose,
 *   the hand-held minimap follows the left one) and four boolean actions,
 *   HOL_XR_ACT_*: confirm (next level; the right hand's main button or
 *   trigger), menu (the pause menu: resume, restart, recentre by its
 *   hint), recentre (place the room from the head), minimap (HUD, hand,
 *   off).
 * - Profiles: khr/simple_controller, oculus/touch_controller,
 *   htc/vive_controller, valve/index_controller,
 *   microsoft/motion_controller; each binds every action to a distinct
 *   input path of that profile. A runtime that refuses one is an error of
 *   the session (the suggested bindings must all be accepted).
 * - hol_xr_buttons maps the held actions to HOL_BTN_* bits.
 */
#ifndef HOL_XR_BIND_H
#define HOL_XR_BIND_H

#include <stdint.h>

enum {
    HOL_XR_ACT_CONFIRM = 0,
    HOL_XR_ACT_MENU,
    HOL_XR_ACT_RECENTRE,
    HOL_XR_ACT_MINIMAP,
    HOL_XR_ACT_COUNT
};

typedef struct hol_xr_profile {
    const char *profile;                 /* /interaction_profiles/... */
    const char *path[HOL_XR_ACT_COUNT];  /* per HOL_XR_ACT_* */
} hol_xr_profile;

#define HOL_XR_NPROFILES 5

/* The profiles (HOL_XR_NPROFILES of them), static data. */
const hol_xr_profile *hol_xr_profiles(void);
/* The action's name and localized name for xrCreateAction. */
const char *hol_xr_action_name(int act);
const char *hol_xr_action_label(int act);
/* The grip pose path of hand 0 (left) or 1 (right). */
const char *hol_xr_grip_path(int hand);
/* held[a] nonzero: action a is held. Returns the HOL_BTN_* bits. */
uint32_t hol_xr_buttons(const int held[HOL_XR_ACT_COUNT]);

#endif
