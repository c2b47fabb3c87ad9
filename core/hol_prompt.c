/* hol_prompt.c - button words per device (see hol_prompt.h). */
#include "hol_prompt.h"

#include <stddef.h>

#include "hol_input.h"
#include "hol_str.h"

#define HOL__NBTN 8 /* HOL_BTN_* bits 0..7 */

/* Per device, per button bit: confirm, back, menu, recentre, minimap,
 * restart, quit, debug. */
static const char *const hol__words[HOL_DEVICE_COUNT][HOL__NBTN] = {
    /* HOL_DEVICE_NONE names actions (hol__said below) */
    [HOL_DEVICE_KEYBOARD] = {"ENTER", NULL, "P", NULL, "M", "R", "ESC", "F3"},
    [HOL_DEVICE_GAMEPAD] = {"A", "B", "START", "Y", "X", NULL, NULL, NULL},
    /* XR: quit is the pause menu's own input; restart has none outside the
     * menu, and in it the confirm input restarts (platform/openxr/hol_xr_bind.h) */
    [HOL_DEVICE_XR_SIMPLE] = {"SELECT", NULL, "MENU", "LEFT MENU", "LEFT SELECT", NULL,
                              "LEFT MENU", NULL},
    /* Touch: the same buttons as the web build's (below): Y menu, left
     * thumbstick press recentre */
    [HOL_DEVICE_XR_TOUCH] = {"A", NULL, "Y", "LEFT THUMBSTICK", "X", NULL, "B", NULL},
    [HOL_DEVICE_XR_VIVE] = {"TRIGGER", NULL, "MENU", "LEFT MENU", "LEFT TRACKPAD", NULL,
                            "TRACKPAD", NULL},
    [HOL_DEVICE_XR_INDEX] = {"A", NULL, "B", "LEFT B", "LEFT A", NULL, "LEFT TRIGGER", NULL},
    [HOL_DEVICE_XR_WMR] = {"TRIGGER", NULL, "MENU", "LEFT MENU", "LEFT TRACKPAD", NULL,
                           "TRACKPAD", NULL},
    [HOL_DEVICE_XR] = {"TRIGGER", NULL, "MENU", NULL, NULL, NULL, NULL, NULL},
    /* the web build's (platform/web/hol_web_xr.h): right trigger or A
     * confirm, B back, Y menu, left thumbstick press recentre, X minimap:
     * the native Touch's buttons (in the menu B quits on both) */
    [HOL_DEVICE_WEBXR_TOUCH] = {"A", "B", "Y", "LEFT THUMBSTICK", "X", NULL, NULL, NULL},
    /* the hands' and the touch screen's words are the string table's
     * (hol__said below): they have no names printed on them */
};

/* The devices whose words are the player's language's (hol_str): per
 * button bit the string id, 0 none. */
static const unsigned short hol__said[HOL_DEVICE_COUNT][HOL__NBTN] = {
    [HOL_DEVICE_NONE] = {HOL_S_BTN_CONFIRM, HOL_S_BTN_BACK, HOL_S_BTN_MENU, HOL_S_BTN_RECENTRE,
                         HOL_S_BTN_MINIMAP, HOL_S_BTN_RESTART, HOL_S_BTN_QUIT, HOL_S_BTN_DEBUG},
    /* the web build's hands (platform/web/hol_web_xr.h): a right pinch
     * confirms, a left pinch opens the menu, a pinch held a second backs
     * (in the menu it quits) */
    [HOL_DEVICE_WEBXR_HAND] = {HOL_S_HAND_PINCH, HOL_S_HAND_LONG_PINCH, HOL_S_HAND_LEFT_PINCH},
    /* OpenXR's hands (ext/hand_interaction_ext): right pinch confirm, left
     * pinch menu, left grasp recentre, right grasp minimap (in the menu:
     * quit) */
    [HOL_DEVICE_XR_HAND] = {HOL_S_HAND_PINCH, 0, HOL_S_HAND_LEFT_PINCH, HOL_S_HAND_LEFT_GRASP,
                            HOL_S_HAND_GRASP, 0, HOL_S_HAND_GRASP, 0},
    /* the web page's on-screen buttons (platform/web/index.html: OK, Back,
     * Menu, Map; no restart nor quit: in the menu Back quits) */
    [HOL_DEVICE_SCREEN] = {HOL_S_SCREEN_OK, HOL_S_SCREEN_BACK, HOL_S_SCREEN_MENU, 0,
                           HOL_S_SCREEN_MAP, 0, 0, 0},
};

const char *hol_prompt_button(uint32_t device, uint32_t btn)
{
    return hol_prompt_button_in(device, btn, HOL_LANG_EN);
}

const char *hol_prompt_button_in(uint32_t device, uint32_t btn, int lang)
{
    if (device >= HOL_DEVICE_COUNT || !btn || (btn & (btn - 1)))
        return NULL;
    for (int k = 0; k < HOL__NBTN; k++)
        if (btn == 1u << k)
            return hol__said[device][k] ? hol_str(lang, (hol_str_id)hol__said[device][k])
                                        : hol__words[device][k];
    return NULL;
}

const char *hol_prompt_move(uint32_t device, int lang)
{
    switch (device) {
    case HOL_DEVICE_NONE: return NULL;
    case HOL_DEVICE_KEYBOARD: return hol_str(lang, HOL_S_MOVE_KEYBOARD);
    case HOL_DEVICE_GAMEPAD: return hol_str(lang, HOL_S_MOVE_GAMEPAD);
    case HOL_DEVICE_SCREEN: return hol_str(lang, HOL_S_MOVE_SCREEN);
    default: return hol_str(lang, HOL_S_MOVE_ROOM);
    }
}

const char *hol_prompt_seated(uint32_t device, int lang)
{
    switch (device) {
    case HOL_DEVICE_KEYBOARD: return hol_str(lang, HOL_S_SEATED_KEYBOARD);
    case HOL_DEVICE_GAMEPAD: return hol_str(lang, HOL_S_SEATED_GAMEPAD);
    case HOL_DEVICE_NONE:
    case HOL_DEVICE_SCREEN: return hol_str(lang, HOL_S_SEATED_TOUCH);
    case HOL_DEVICE_WEBXR_HAND:
    case HOL_DEVICE_XR_HAND: return hol_str(lang, HOL_S_SEATED_HANDS);
    default: return hol_str(lang, HOL_S_SEATED_STICK);
    }
}
