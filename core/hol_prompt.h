/* hol_prompt.h - the words a prompt uses for a button: the name of the
 * button bound to an action on the device in use.
 *
 * Contract
 * - hol_prompt_button(device, btn) names the control that gives HOL_BTN_*
 *   bit btn on device (HOL_DEVICE_*, core/hol_input.h), in capitals as the
 *   HUD draws them: the keyboard's keys ("ENTER", "P", "R", "ESC", "M",
 *   "F3"), a game controller's buttons in the Xbox layout the Linux gamepad
 *   order follows ("A" south, "B" east, "X" west, "Y" north, "START"), and
 *   for each OpenXR interaction profile the control its suggested binding
 *   uses (platform/openxr/hol_xr_bind.c: "TRIGGER", "A", "MENU", "LEFT
 *   TRACKPAD", ...; a left-hand control is "LEFT ..." where the right hand
 *   has one of that name too; quit is bound in the pause menu only, and
 *   restart has no control of its own: in the menu the confirm control
 *   restarts, as on every device). NULL: no control gives it on that
 *   device.
 *   HOL_DEVICE_NONE names the action itself ("CONFIRM", "MENU", ...), the
 *   hands their gestures ("PINCH", "LEFT GRASP", ...) and
 *   HOL_DEVICE_SCREEN (the web page's touch screen) the on-screen buttons
 *   as the page labels them ("OK", "BACK", "MENU", "MAP");
 *   hol_prompt_button_in(device, btn, lang) says those in lang (the
 *   string table's HOL_S_BTN_*, HOL_S_HAND_*, HOL_S_SCREEN_*; a device's
 *   controls as above); hol_prompt_button gives the English.
 * - hol_prompt_move(device, lang) says how one walks with it ("W/S/A/D:
 *   WALK"), in lang (core/hol_str.h); NULL for HOL_DEVICE_NONE. The
 *   controls' names above (not the gestures' nor the on-screen buttons')
 *   are the names printed on them, in every language. hol_prompt_seated(device, lang) names seated play and its
 *   step controls in lang (the string table's HOL_S_SEATED_*).
 * - The tables must follow the bindings: tests/test_xr_bind.c derives each
 *   XR word from the profile's binding path and compares.
 * - Pure data: static strings, no state.
 */
#ifndef HOL_PROMPT_H
#define HOL_PROMPT_H

#include <stdint.h>

const char *hol_prompt_button(uint32_t device, uint32_t btn);
const char *hol_prompt_button_in(uint32_t device, uint32_t btn, int lang);
const char *hol_prompt_move(uint32_t device, int lang);
/* Seated play (HOL_INPUT_SEATED): the panel's line naming the mode and
 * how one steps with the device ("SEATED: W/A/S/D OR UP/DOWN: ONE STEP");
 * never NULL. */
const char *hol_prompt_seated(uint32_t device, int lang);

#endif
