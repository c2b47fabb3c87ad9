/* hol_input_io.h - input records as text lines, for recordings and scripts.
 *
 * Contract
 * - One hol_input (core/hol_input.h) is one line (format version
 *   HOL_INPUT_TEXT_VERSION):
 *
 *     TIME [f=FLAGS] [b=BUTTONS] [p=PRESSED] [m=X,Y] [t=X,Y] [y=YAW]
 *          [h=POSE] [l=POSE] [r=POSE] [d=DEVICE]
 *
 *   TIME seconds (decimal, >= 0); FLAGS, BUTTONS and PRESSED hex bit sets
 *   of HOL_INPUT_* and HOL_BTN_* (no unknown bits; PRESSED: the buttons
 *   pressed since the previous record); m the move axes (right, forward),
 *   t the turn axes (left, up), each in [-1, 1]; y the snap turn's yaw in
 *   degrees, [0, 360); h, l, r the head, left and right hand poses: seven
 *   numbers px,py,pz,qx,qy,qz,qw; DEVICE the device in use, one of
 *   keyboard, gamepad, xr-simple, xr-touch, xr-vive, xr-index, xr-wmr, xr,
 *   webxr-touch, webxr-hand, xr-hand, touchscreen
 *   (hol_input_device_name). A field left out is zero (an omitted pose is
 *   all zero, an omitted device HOL_DEVICE_NONE). Fields are separated by
 *   single spaces, each at most once, in any order. Numbers are finite
 *   decimals (strtod syntax without hex, inf or nan).
 * - Version 2 added p, y and d (and the HOL_BTN_DEBUG and
 *   HOL_INPUT_SNAP_YAW bits); every version 1 line parses as it did. The
 *   HOL_INPUT_RECENTRED bit (80) joined version 2 later, and so did the
 *   headset's state (HOL_INPUT_HEADSET 100, HOL_INPUT_HEADSET_OFF 200,
 *   HOL_INPUT_POS_EMULATED 400), the way back (HOL_INPUT_WAY_BACK 800),
 *   and seated play (HOL_INPUT_SEATED 1000, the buttons HOL_BTN_STEP_*
 *   100..800), and the device touchscreen (the web page's touch screen,
 *   which was keyboard before): builds before them refuse a line
 *   that has one; a line without them reads and replays as it always did.
 * - hol_input_format writes the canonical line: fields in the order above,
 *   fields whose bytes are all zero left out (a -0 is written), floats with 9
 *   significant digits and the time with 17, so parsing the line gives back
 *   the record bit for bit. A recording of lines therefore
 *   replays exactly the records that were stepped. A tracked hand's
 *   joints (hol_input.joints) are not written (core/hol_input.h): a line
 *   read back has none.
 * - Pure: no allocation, no globals, no OS; the caller gives the buffers.
 */
#ifndef HOL_INPUT_IO_H
#define HOL_INPUT_IO_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"
#include "hol_input.h"

#define HOL_INPUT_TEXT_VERSION 2
/* The longest canonical line, without its NUL. */
#define HOL_INPUT_LINE_MAX 540

/* Write the canonical line of *in (no newline) and a NUL into out (cap
 * bytes; HOL_INPUT_LINE_MAX + 1 always fit). Returns the length, or 0 when
 * the record is not valid (see hol_input_valid) or cap is too small. */
size_t hol_input_format(const hol_input *in, char *out, size_t cap);

/* Parse one line (len bytes, no newline; NULs are bad input) into *out.
 * Errors: HOL_EPARSE, with the 0-based byte offset of the offending field in
 * *out_bad (may be NULL). On error *out is unchanged. */
hol_err hol_input_parse(const char *s, size_t len, hol_input *out, size_t *out_bad);

/* 1 when every number is finite, time >= 0, axes in [-1, 1], the snap yaw
 * in [0, 360), the device known, no unknown flag or button bit is set and
 * a tracked hand's joints are finite with radii in [0, 1). */
int hol_input_valid(const hol_input *in);

/* The line format's name of a HOL_DEVICE_* value ("" for NONE, NULL for an
 * unknown value). */
const char *hol_input_device_name(uint32_t device);

#endif
