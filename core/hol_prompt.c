/* hol_prompt.c - button words per device (see hol_prompt.h). */
#include "hol_prompt.h"

#include <stddef.h>

#include "hol_input.h"
#include "hol_str.h"

#define HOL__NBTN 8 /* HOL_BTN_* bits 0..7 */

/* Per device, per button bit: confirm, back, menu, recentre, minimap,
 * restart, quit, debug. */
static const char *const hol__words[HOL_DEVICE_COUNT][HOL__NBTN] = {
    [HOL_DEVICE_NONE] = {"CONFIRM", "BACK", "MENU", "RECENTRE", "MINIMAP", "RESTART", "QUIT",
                         "DEBUG"},
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
    /* the web build's hands (platform/web/hol_web_xr.h): a right pinch
     * confirms, a left pinch opens the menu, a pinch held a second backs
     * (in the menu it quits) */
    [HOL_DEVICE_WEBXR_HAND] = {"PINCH", "LONG PINCH", "LEFT PINCH", NULL, NULL, NULL, NULL, NULL},
    /* OpenXR's hands (ext/hand_interaction_ext): right pinch confirm, left
     * pinch menu, left grasp recentre, right grasp minimap (in the menu:
     * quit) */
    [HOL_DEVICE_XR_HAND] = {"PINCH", NULL, "LEFT PINCH", "LEFT GRASP", "GRASP", NULL, "GRASP",
                            NULL},
};

const char *hol_prompt_button(uint32_t device, uint32_t btn)
{
    if (device >= HOL_DEVICE_COUNT || !btn || (btn & (btn - 1)))
        return NULL;
    for (int k = 0; k < HOL__NBTN; k++)
        if (btn == 1u << k)
            return hol__words[device][k];
    return NULL;
}

const char *hol_prompt_move(uint32_t device, int lang)
{
    switch (device) {
    case HOL_DEVICE_NONE: return NULL;
    case HOL_DEVICE_KEYBOARD: return hol_str(lang, HOL_S_MOVE_KEYBOARD);
    case HOL_DEVICE_GAMEPAD: return hol_str(lang, HOL_S_MOVE_GAMEPAD);
    default: return hol_str(lang, HOL_S_MOVE_ROOM);
    }
}

const char *hol_prompt_seated(uint32_t device, int lang)
{
    switch (device) {
    case HOL_DEVICE_KEYBOARD: return "SEATED: W/A/S/D OR UP/DOWN: ONE STEP";
    case HOL_DEVICE_GAMEPAD: return "SEATED: LEFT STICK OR D-PAD: ONE STEP";
    case HOL_DEVICE_NONE: return "SEATED: SWIPE OR ARROWS: ONE STEP";
    case HOL_DEVICE_WEBXR_HAND: /* a pinch and flick (core/hol_body.h) */
    case HOL_DEVICE_XR_HAND: return hol_str(lang, HOL_S_SEATED_HANDS);
    default: return "SEATED: THUMBSTICK: ONE STEP";
    }
}
