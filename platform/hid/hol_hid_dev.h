/* hol_hid_dev.h - game controllers through hidapi (hidraw backend, or
 * libusb with `make HID=libusb`).
 *
 * Contract
 * - hol_hid_dev_open_first finds the first game controller (a top-level
 *   collection Generic Desktop Joystick 0x04, Gamepad 0x05 or Multi-axis
 *   Controller 0x08), reads its report descriptor, builds the field map
 *   and the decoder (hol_hid_pad.h), sends a known pad's start report, and
 *   sets the device non-blocking. The field map, decoder and buffers live
 *   in the hol_hid_dev struct (caller memory). While a controller is
 *   connected, polling allocates nothing; re-enumeration (hidapi's
 *   hid_enumerate and hid_open_path, which allocate) happens only while
 *   no controller is open. With hidapi 0.13 (Debian 12) the descriptor is
 *   read from sysfs (hidraw backend only); hidapi >= 0.14 reads it itself.
 * - hol_hid_dev_poll(dev, io) never blocks: it drains the reports waiting
 *   and writes buttons, move and turn of *io, and ORs into io->pressed
 *   every button that went down in any of those reports (a press and
 *   release between two polls is not lost). When the device goes away
 *   (a read error) it sets HOL_INPUT_DEVICE_LOST in io->flags, zeroes the
 *   axes and buttons, closes the handle and returns HOL_EIO; later polls
 *   try to reopen a controller (hot-plug), at most once every
 *   HOL_HID_REENUM_S seconds of io->time_s.
 * - No device: HOL_EOPEN (never a crash). hol_hid_dev_list prints nothing;
 *   it calls fn for every controller found.
 * - Backends: hidapi by default. hol_hid_dev_open_backend makes the same
 *   device layer (enumeration, descriptor, decoder, drain, unplug,
 *   re-enumeration) read from another source instead: a recorded script
 *   (hol_hid_script.h) for tests and `play --gamepad-replay`. A backend
 *   pad gets no start report (known pads' output reports are hidapi only).
 */
#ifndef HOL_HID_DEV_H
#define HOL_HID_DEV_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_err.h"
#include "../../core/hol_input.h"
#include "hol_hid_desc.h"
#include "hol_hid_pad.h"

#define HOL_HID_DEV_MAX_FIELDS 1024
#define HOL_HID_DESC_MAX 4096
#define HOL_HID_REENUM_S 1.0

typedef struct hol_hid_dev_info {
    uint16_t vid, pid;
    uint16_t usage_page, usage;
    char path[256];
    char name[128];
} hol_hid_dev_info;

/* A device source other than hidapi. now_s is the poll's io->time_s. */
typedef struct hol_hid_backend {
    /* The first game controller present: its info and report descriptor
     * (at most cap bytes, length in *out_len). HOL_EOPEN when none. */
    hol_err (*open_first)(void *ctx, double now_s, hol_hid_dev_info *out_info, uint8_t *desc,
                          size_t cap, size_t *out_len);
    /* Never blocks: the next waiting report's length (at most cap bytes),
     * 0 when none is waiting, < 0 when the device went away. */
    int (*read)(void *ctx, double now_s, uint8_t *buf, size_t cap);
    void (*close)(void *ctx);
    void *ctx;
} hol_hid_backend;

typedef struct hol_hid_dev {
    void *handle; /* hid_device * (or the backend), NULL when closed */
    const hol_hid_backend *be; /* NULL: hidapi */
    hol_hid_dev_info info;
    hol_hid_field fields[HOL_HID_DEV_MAX_FIELDS];
    size_t n_fields;
    int has_ids;
    hol_hid_pad pad;
    double last_try_s; /* io->time_s of the last (re)open attempt */
    int tried;
    int lost;          /* the controller went away (HOL_INPUT_DEVICE_LOST) */
} hol_hid_dev;

/* Open the first game controller into *dev. HOL_EOPEN: none found. */
hol_err hol_hid_dev_open_first(hol_hid_dev *dev);
/* Non-blocking; see the contract. io->time_s is the clock for the
 * re-enumeration interval. A dev that failed hol_hid_dev_open_first may be
 * polled too: it keeps looking for a controller (plug it in later). */
hol_err hol_hid_dev_poll(hol_hid_dev *dev, hol_input *io);
/* As hol_hid_dev_open_first, on backend be (kept for the re-opens of
 * later polls) at time now_s. */
hol_err hol_hid_dev_open_backend(hol_hid_dev *dev, const hol_hid_backend *be, double now_s);
void hol_hid_dev_close(hol_hid_dev *dev);

/* Call fn for every game controller; returns how many were found. The
 * field map of each (when its descriptor could be read) is passed too. */
typedef void (*hol_hid_dev_list_fn)(void *ctx, const hol_hid_dev_info *info,
                                    const hol_hid_field *fields, size_t n,
                                    hol_err desc_err);
int hol_hid_dev_list(hol_hid_dev_list_fn fn, void *ctx);

/* hidapi backend name of this build ("hidraw" or "libusb"). */
const char *hol_hid_dev_backend(void);

#endif
