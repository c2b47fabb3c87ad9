/* hol_xr_bind.h - the headset's actions and their suggested bindings, as
 * pure data and functions (no OpenXR headers): what the session layer
 * hands to xrSuggestInteractionProfileBindings and how the boolean action
 * states become the input record's buttons. Tested without a runtime
 * (tests/test_xr_bind.c checks every path against the OpenXR 1.0
 * specification's list for its interaction profile).
 *
 * Contract
 * - Actions: a grip pose per hand (/user/hand/{left,right}/input/grip/pose,
 *   the hand-held minimap follows the left one) and six boolean actions,
 *   HOL_XR_ACT_*: confirm (next level; the right hand's main button or
 *   trigger), menu (the pause menu), recentre (place the room from the
 *   head), minimap (HUD, hand, off), restart (the level again) and quit
 *   (leave the app).
 * - Two layers: while the game runs, confirm, menu, recentre and minimap
 *   count; while the pause menu is open, menu (resume), restart and quit.
 *   So restart and quit are never one accidental press away, and a
 *   controller with four inputs (khr/simple_controller) binds all six.
 *   Restart is always on confirm's input (the prompts name it so: in the
 *   menu, "confirm" restarts on every device, core/hol_app.c). Within a
 *   layer every action has an input of its own.
 * - Profiles: khr/simple_controller, oculus/touch_controller,
 *   htc/vive_controller, valve/index_controller,
 *   microsoft/motion_controller; each binds every action to an input path
 *   of that profile. A runtime that refuses one is an error of the session
 *   (the suggested bindings must all be accepted). And the hands of
 *   XR_EXT_hand_interaction (ext/hand_interaction_ext: its `extension`
 *   names the extension, suggested only where the runtime lists it and it
 *   is enabled; it has no haptic output, `haptic` 0): right pinch
 *   confirm (and restart), left pinch menu, left grasp recentre, right
 *   grasp minimap and, in the menu, quit.
 * - hol_xr_buttons maps the held actions of the current layer to HOL_BTN_*
 *   bits. An input held while the layer changes (the press that opened the
 *   menu, a restart held while the menu closes) counts in the new layer
 *   only once it has been released: one press never acts in both.
 * - hol_xr_profile_find names the profile of an interaction profile path
 *   (xrGetCurrentInteractionProfile), hol_xr_profile_device its device in
 *   the input record (hol_input.device: the prompts name its buttons), and
 *   hol_xr_input_label the input an action is bound to in it, in words a
 *   prompt can show ("A", "left menu").
 */
#ifndef HOL_XR_BIND_H
#define HOL_XR_BIND_H

#include <stdint.h>

enum {
    HOL_XR_ACT_CONFIRM = 0,
    HOL_XR_ACT_MENU,
    HOL_XR_ACT_RECENTRE,
    HOL_XR_ACT_MINIMAP,
    HOL_XR_ACT_RESTART,
    HOL_XR_ACT_QUIT,
    HOL_XR_ACT_COUNT
};

typedef struct hol_xr_profile {
    const char *profile;                 /* /interaction_profiles/... */
    const char *name;                    /* short: "oculus/touch_controller" */
    const char *path[HOL_XR_ACT_COUNT];  /* per HOL_XR_ACT_* */
    const char *label[HOL_XR_ACT_COUNT]; /* the input in words: "A" */
    const char *extension;               /* NULL: core OpenXR; else the
                                            extension that defines it */
    int no_haptic;                       /* 1: no output/haptic paths */
} hol_xr_profile;

#define HOL_XR_NPROFILES 6
#define HOL_XR_EXT_HAND_INTERACTION "XR_EXT_hand_interaction"

/* The profiles (HOL_XR_NPROFILES of them), static data. */
const hol_xr_profile *hol_xr_profiles(void);
/* The index of the profile whose path is `path`, or -1. */
int hol_xr_profile_find(const char *path);
/* The hol_input device (HOL_DEVICE_XR_*) of profile `profile` (an index);
 * HOL_DEVICE_XR for any other. */
uint32_t hol_xr_profile_device(int profile);
/* The input action `act` is bound to in profile `profile` (an index), in
 * words; "" for a bad index. */
const char *hol_xr_input_label(int profile, int act);
/* The action's name and localized name for xrCreateAction. */
const char *hol_xr_action_name(int act);
const char *hol_xr_action_label(int act);
/* 1 when action act counts in the layer (in_menu: the pause menu's). */
int hol_xr_action_in_layer(int act, int in_menu);
/* The grip pose path of hand 0 (left) or 1 (right). */
const char *hol_xr_grip_path(int hand);
/* The haptic output path of hand 0 (left) or 1 (right): every profile
 * above has /user/hand/{left,right}/output/haptic, bound to one vibration
 * output action with the hands as its subaction paths; the app step's
 * pulses (core/hol_haptic.h) are played on it. */
const char *hol_xr_haptic_path(int hand);

/* Seated play's stick (holonomy xr --seated, issue 37): the thumbstick of
 * hand 0 (left) or 1 (right) in profile `profile` (an index), the Vive's
 * trackpad, as a vector2f input path (its /x and /y in the profile's
 * list); NULL where the profile has none (the simple controller, the
 * hands). Either stick's push is one room step (platform/shell/
 * hol_shell_seat.h), as on the web. */
const char *hol_xr_stick_path(int profile, int hand);

/* The layer state of hol_xr_buttons; zero it at the session's start. */
typedef struct hol_xr_keys {
    int in_menu;         /* the layer of the last call */
    unsigned suppressed; /* actions held across a layer change (bits 1 << act) */
} hol_xr_keys;

/* held[a] nonzero: action a is held; in_menu: the pause menu is open.
 * Returns the HOL_BTN_* bits (see the contract). */
uint32_t hol_xr_buttons(hol_xr_keys *k, const int held[HOL_XR_ACT_COUNT], int in_menu);

#endif
