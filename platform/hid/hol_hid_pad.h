/* hol_hid_pad.h - game controller input reports to the app's hol_input.
 *
 * Contract
 * - Pure C11, caller memory (hol_hid_pad_init), no allocation, no OS calls;
 *   decoding a report is bounded (the pad keeps at most
 *   HOL_HID_PAD_MAX_BUTTONS buttons, four axes and one hat).
 * - Roles from the field map (hol_hid_desc.h): Generic Desktop X, Y are
 *   the left stick (walk: hol_input.move); the right stick (turn and look:
 *   hol_input.turn) is Z, Rz, else Rx, Ry, else Simulation rudder,
 *   throttle. Axes are normalised from the logical range to [-1, 1] (the
 *   range's middle is 0), then a radial dead zone (default 0.15) per stick
 *   is removed and the rest rescaled to reach 1. HID's y grows downwards:
 *   move[1] = -left y (forward +), turn[0] = -right x (turn left +),
 *   turn[1] = -right y (look up +).
 * - Buttons (Button page usage N = button N) and the hat give HOL_BTN_*:
 *   generic pads follow the Linux gamepad order (1 south: CONFIRM, 2 east:
 *   BACK, 4 north: RECENTRE, 5 west: MINIMAP, 11 select: MINIMAP,
 *   12 start: MENU, 13 mode: MENU); hat up: RECENTRE, hat down: MINIMAP.
 *   The hat's direction is (v - min) * 8 / (max - min + 1) eighths from
 *   north, as Linux reads it; a value outside the logical range (null
 *   state) is centred.
 * - A small table of known pads by VID:PID (hol_hid_known_find) gives the
 *   button roles where the descriptor's button numbers mislead (Sony), the
 *   report a pad needs before it sends input, and a fixed layout where the
 *   descriptor does not describe the report (Switch Pro report 0x30).
 * - Decoding keeps the last value of every field, so pads that split their
 *   state over several reports work; a report that is too short for a
 *   field leaves that field unchanged; unknown report IDs are ignored.
 */
#ifndef HOL_HID_PAD_H
#define HOL_HID_PAD_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_err.h"
#include "../../core/hol_input.h"
#include "hol_hid_desc.h"

#define HOL_HID_PAD_MAX_BUTTONS 32

enum { HOL_HID_LX, HOL_HID_LY, HOL_HID_RX, HOL_HID_RY, HOL_HID_AXES };

/* how a known pad must be started (hol_hid_known.start_kind) */
enum {
    HOL_HID_START_NONE = 0,
    HOL_HID_START_FEATURE, /* read feature report start[0] (start_len bytes) */
    HOL_HID_START_OUTPUT   /* write the output reports in start[] */
};
/* report layouts */
enum { HOL_HID_LAYOUT_DESCRIPTOR = 0, HOL_HID_LAYOUT_SWITCH_PRO };

typedef struct hol_hid_known {
    uint16_t vid, pid;
    const char *name;
    uint8_t layout;                /* HOL_HID_LAYOUT_* */
    uint8_t start_kind;            /* HOL_HID_START_* */
    uint8_t start_len;             /* feature length, or bytes per output report */
    uint8_t start_count;           /* output reports in start */
    const uint8_t *start;          /* start_count reports of start_len bytes */
    const uint32_t *button_roles;  /* HOL_BTN_* for buttons 1..32, or NULL */
} hol_hid_known;

/* The table entry of a pad, or NULL (generic). */
const hol_hid_known *hol_hid_known_find(uint16_t vid, uint16_t pid);

typedef struct hol_hid_pad_desc {
    float dead_zone; /* radial, of the unit stick; 0: 0.15 */
} hol_hid_pad_desc;

typedef struct hol_hid_pad {
    const hol_hid_known *known;
    int has_ids;
    float dead_zone;
    hol_hid_field axis[HOL_HID_AXES];
    uint8_t has_axis[HOL_HID_AXES];
    hol_hid_field hat;
    uint8_t has_hat;
    int n_buttons;
    hol_hid_field button[HOL_HID_PAD_MAX_BUTTONS];
    uint32_t button_role[HOL_HID_PAD_MAX_BUTTONS];
    /* state */
    float raw[HOL_HID_AXES]; /* normalised, before the dead zone */
    int hat_dir;             /* 0..7 from north clockwise, -1 centred */
    uint32_t pressed;        /* bit i: button[i] held */
} hol_hid_pad;

/* Set the pad up from a field map; vid:pid picks a known-pad entry.
 * HOL_EUNSUPPORTED when the map has no stick, hat or button. */
hol_err hol_hid_pad_init(hol_hid_pad *pad, const hol_hid_field *fields,
                         size_t n, int has_ids, uint16_t vid, uint16_t pid,
                         const hol_hid_pad_desc *desc);

/* Decode one input report as read from the device (with its ID byte when
 * the descriptor declares IDs) and write buttons, move and turn of *io
 * (other fields untouched). Returns 1 when the report was the pad's. */
int hol_hid_pad_decode(hol_hid_pad *pad, const uint8_t *report, size_t len,
                       hol_input *io);

/* The pad's current state into *io (buttons, move, turn). */
void hol_hid_pad_state(const hol_hid_pad *pad, hol_input *io);

#endif
