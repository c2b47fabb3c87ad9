/* hol_xr_bind.c - actions and suggested bindings (see hol_xr_bind.h). */
#include "hol_xr_bind.h"

#include "../../core/hol_input.h"

static const hol_xr_profile hol__profiles[HOL_XR_NPROFILES] = {
    /* confirm, menu, recentre, minimap */
    {"/interaction_profiles/khr/simple_controller",
     {"/user/hand/right/input/select/click", "/user/hand/right/input/menu/click",
      "/user/hand/left/input/menu/click", "/user/hand/left/input/select/click"}},
    {"/interaction_profiles/oculus/touch_controller",
     {"/user/hand/right/input/a/click", "/user/hand/left/input/menu/click",
      "/user/hand/left/input/y/click", "/user/hand/left/input/x/click"}},
    {"/interaction_profiles/htc/vive_controller",
     {"/user/hand/right/input/trigger/click", "/user/hand/right/input/menu/click",
      "/user/hand/left/input/menu/click", "/user/hand/left/input/trackpad/click"}},
    {"/interaction_profiles/valve/index_controller",
     {"/user/hand/right/input/a/click", "/user/hand/right/input/b/click",
      "/user/hand/left/input/b/click", "/user/hand/left/input/a/click"}},
    {"/interaction_profiles/microsoft/motion_controller",
     {"/user/hand/right/input/trigger/value", "/user/hand/right/input/menu/click",
      "/user/hand/left/input/menu/click", "/user/hand/left/input/trackpad/click"}},
};

const hol_xr_profile *hol_xr_profiles(void)
{
    return hol__profiles;
}

const char *hol_xr_action_name(int act)
{
    static const char *const n[HOL_XR_ACT_COUNT] = {"confirm", "menu", "recentre", "minimap"};
    return act >= 0 && act < HOL_XR_ACT_COUNT ? n[act] : "";
}

const char *hol_xr_action_label(int act)
{
    static const char *const n[HOL_XR_ACT_COUNT] = {"Confirm", "Menu", "Recentre the room",
                                                     "Minimap"};
    return act >= 0 && act < HOL_XR_ACT_COUNT ? n[act] : "";
}

const char *hol_xr_grip_path(int hand)
{
    return hand ? "/user/hand/right/input/grip/pose" : "/user/hand/left/input/grip/pose";
}

uint32_t hol_xr_buttons(const int held[HOL_XR_ACT_COUNT])
{
    static const uint32_t bit[HOL_XR_ACT_COUNT] = {HOL_BTN_CONFIRM, HOL_BTN_MENU,
                                                    HOL_BTN_RECENTRE, HOL_BTN_MINIMAP};
    uint32_t b = 0;
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        b |= held[a] ? bit[a] : 0;
    return b;
}
