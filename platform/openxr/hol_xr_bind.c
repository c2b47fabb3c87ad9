/* hol_xr_bind.c - actions and suggested bindings (see hol_xr_bind.h). */
#include "hol_xr_bind.h"

#include <string.h>

#include "../../core/hol_input.h"

#define HOL__L "/user/hand/left/input/"
#define HOL__R "/user/hand/right/input/"

static const hol_xr_profile hol__profiles[HOL_XR_NPROFILES] = {
    /* confirm, menu, recentre, minimap | restart, quit (the menu's layer) */
    {"/interaction_profiles/khr/simple_controller", "khr/simple_controller",
     {HOL__R "select/click", HOL__R "menu/click", HOL__L "menu/click", HOL__L "select/click",
      HOL__R "select/click", HOL__L "menu/click"},
     {"right select", "right menu", "left menu", "left select", "right select", "left menu"},
     NULL, 0},
    {"/interaction_profiles/oculus/touch_controller", "oculus/touch_controller",
     /* as the web build's Touch (platform/web/hol_web_xr.h): Y menu, left
      * thumbstick press recentre - WebXR gives pages no menu button */
     {HOL__R "a/click", HOL__L "y/click", HOL__L "thumbstick/click", HOL__L "x/click",
      HOL__R "a/click", HOL__R "b/click"},
     {"A", "Y", "left thumbstick", "X", "A", "B"},
     NULL, 0},
    {"/interaction_profiles/htc/vive_controller", "htc/vive_controller",
     {HOL__R "trigger/click", HOL__R "menu/click", HOL__L "menu/click",
      HOL__L "trackpad/click", HOL__R "trigger/click", HOL__R "trackpad/click"},
     {"right trigger", "right menu", "left menu", "left trackpad", "right trigger",
      "right trackpad"},
     NULL, 0},
    {"/interaction_profiles/valve/index_controller", "valve/index_controller",
     {HOL__R "a/click", HOL__R "b/click", HOL__L "b/click", HOL__L "a/click", HOL__R "a/click",
      HOL__L "trigger/click"},
     {"right A", "right B", "left B", "left A", "right A", "left trigger"},
     NULL, 0},
    {"/interaction_profiles/microsoft/motion_controller", "microsoft/motion_controller",
     {HOL__R "trigger/value", HOL__R "menu/click", HOL__L "menu/click",
      HOL__L "trackpad/click", HOL__R "trigger/value", HOL__R "trackpad/click"},
     {"right trigger", "right menu", "left menu", "left trackpad", "right trigger",
      "right trackpad"},
     NULL, 0},
    /* hands alone (XR_EXT_hand_interaction): a pinch as a button (the
     * boolean action on the float value: the runtime's threshold) */
    {"/interaction_profiles/ext/hand_interaction_ext", "ext/hand_interaction_ext",
     {HOL__R "pinch_ext/value", HOL__L "pinch_ext/value", HOL__L "grasp_ext/value",
      HOL__R "grasp_ext/value", HOL__R "pinch_ext/value", HOL__R "grasp_ext/value"},
     {"right pinch", "left pinch", "left grasp", "right grasp", "right pinch", "right grasp"},
     HOL_XR_EXT_HAND_INTERACTION, 1},
};

const char *hol_xr_stick_path(int profile, int hand)
{
    static const char *const stick[HOL_XR_NPROFILES][2] = {
        {NULL, NULL},
        {HOL__L "thumbstick", HOL__R "thumbstick"},
        {HOL__L "trackpad", HOL__R "trackpad"},
        {HOL__L "thumbstick", HOL__R "thumbstick"},
        {HOL__L "thumbstick", HOL__R "thumbstick"},
        {NULL, NULL},
    };
    return profile >= 0 && profile < HOL_XR_NPROFILES && (hand == 0 || hand == 1)
               ? stick[profile][hand]
               : NULL;
}

const hol_xr_profile *hol_xr_profiles(void)
{
    return hol__profiles;
}

int hol_xr_profile_find(const char *path)
{
    for (int i = 0; path && i < HOL_XR_NPROFILES; i++)
        if (!strcmp(hol__profiles[i].profile, path))
            return i;
    return -1;
}

uint32_t hol_xr_profile_device(int profile)
{
    static const uint32_t dev[HOL_XR_NPROFILES] = {HOL_DEVICE_XR_SIMPLE, HOL_DEVICE_XR_TOUCH,
                                                    HOL_DEVICE_XR_VIVE, HOL_DEVICE_XR_INDEX,
                                                    HOL_DEVICE_XR_WMR, HOL_DEVICE_XR_HAND};
    return profile >= 0 && profile < HOL_XR_NPROFILES ? dev[profile] : HOL_DEVICE_XR;
}

const char *hol_xr_input_label(int profile, int act)
{
    if (profile < 0 || profile >= HOL_XR_NPROFILES || act < 0 || act >= HOL_XR_ACT_COUNT)
        return "";
    return hol__profiles[profile].label[act];
}

const char *hol_xr_action_name(int act)
{
    static const char *const n[HOL_XR_ACT_COUNT] = {"confirm", "menu",    "recentre",
                                                     "minimap", "restart", "quit"};
    return act >= 0 && act < HOL_XR_ACT_COUNT ? n[act] : "";
}

const char *hol_xr_action_label(int act)
{
    static const char *const n[HOL_XR_ACT_COUNT] = {
        "Confirm", "Menu", "Recentre the room", "Minimap", "Restart the level (menu)",
        "Quit (menu)"};
    return act >= 0 && act < HOL_XR_ACT_COUNT ? n[act] : "";
}

int hol_xr_action_in_layer(int act, int in_menu)
{
    switch (act) {
    case HOL_XR_ACT_MENU:
        return 1;
    case HOL_XR_ACT_CONFIRM:
    case HOL_XR_ACT_RECENTRE:
    case HOL_XR_ACT_MINIMAP:
        return !in_menu;
    case HOL_XR_ACT_RESTART:
    case HOL_XR_ACT_QUIT:
        return in_menu;
    default:
        return 0;
    }
}

const char *hol_xr_grip_path(int hand)
{
    return hand ? "/user/hand/right/input/grip/pose" : "/user/hand/left/input/grip/pose";
}

const char *hol_xr_haptic_path(int hand)
{
    return hand ? "/user/hand/right/output/haptic" : "/user/hand/left/output/haptic";
}

uint32_t hol_xr_buttons(hol_xr_keys *k, const int held[HOL_XR_ACT_COUNT], int in_menu)
{
    static const uint32_t bit[HOL_XR_ACT_COUNT] = {HOL_BTN_CONFIRM,  HOL_BTN_MENU,
                                                    HOL_BTN_RECENTRE, HOL_BTN_MINIMAP,
                                                    HOL_BTN_RESTART,  HOL_BTN_QUIT};
    unsigned now = 0;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        now |= held[a] ? 1u << a : 0;
    in_menu = in_menu != 0;
    if (in_menu != k->in_menu) {
        k->suppressed |= now; /* held across the change: wait for a release */
        k->in_menu = in_menu;
    }
    k->suppressed &= now;
    uint32_t b = 0;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        if ((now & ~k->suppressed) >> a & 1 && hol_xr_action_in_layer(a, in_menu))
            b |= bit[a];
    return b;
}
