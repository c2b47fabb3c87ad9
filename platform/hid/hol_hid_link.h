/* hol_hid_link.h - a game controller joined to the keyboard and mouse in
 * the desktop frame loop: what `holonomy play` does with each poll.
 *
 * Contract
 * - Each frame the platform polls the controller (hol_hid_dev_poll into a
 *   zeroed hol_input) and calls hol_hid_link_merge with the poll's result,
 *   whether the device was lost, the pad's input and whether the keyboard
 *   or mouse did anything this frame. The merge writes into the frame's
 *   input (already filled from the keyboard and mouse):
 *   - a connected pad: axes are added and clamped to [-1, 1], buttons and
 *     pressed buttons are OR-ed; so keyboard and pad both work at once;
 *   - the device in use (io->device, HOL_DEVICE_*): the pad from a frame
 *     where it was used (a button, or an axis off centre) until the
 *     keyboard or mouse is used (then io->device as the keyboard filled
 *     it); so the prompts name the buttons of what the player holds;
 *   - a pad that went away (unplugged): HOL_INPUT_DEVICE_LOST, so the app
 *     pauses, until the pad comes back (hot-plug) or the player uses the
 *     keyboard or mouse, which resumes the game without the pad (a pad
 *     plugged in later joins again);
 *   - no pad ever seen: the input is left as the keyboard made it.
 * - Pure: no I/O, no allocation, no clock.
 */
#ifndef HOL_HID_LINK_H
#define HOL_HID_LINK_H

#include "../../core/hol_err.h"
#include "../../core/hol_input.h"

typedef struct hol_hid_link {
    int connected; /* the pad answered the last poll */
    int lost;      /* a pad went away and the game waits for it */
    int pad_in_use; /* the pad was used more recently than the keyboard */
} hol_hid_link;

/* poll_err: hol_hid_dev_poll's result; dev_lost: the device's lost flag
 * (a pad was open and a read failed); pad: what the poll wrote;
 * key_activity: a key or the mouse was used this frame. */
void hol_hid_link_merge(hol_hid_link *l, hol_err poll_err, int dev_lost, const hol_input *pad,
                        int key_activity, hol_input *io);

#endif
