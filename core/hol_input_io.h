/* hol_input_io.h - input records as text lines, for recordings and scripts.
 *
 * Contract
 * - One hol_input (core/hol_input.h) is one line (format version
 *   HOL_INPUT_TEXT_VERSION):
 *
 *     TIME [f=FLAGS] [b=BUTTONS] [m=X,Y] [t=X,Y] [h=POSE] [l=POSE] [r=POSE]
 *
 *   TIME seconds (decimal, >= 0); FLAGS and BUTTONS hex bit sets of
 *   HOL_INPUT_* and HOL_BTN_* (no unknown bits); m the move axes (right,
 *   forward), t the turn axes (left, up), each in [-1, 1]; h, l, r the head,
 *   left and right hand poses: seven numbers px,py,pz,qx,qy,qz,qw. A field
 *   left out is zero (an omitted pose is all zero). Fields are separated by
 *   single spaces, each at most once, in any order. Numbers are finite
 *   decimals (strtod syntax without hex, inf or nan).
 * - hol_input_format writes the canonical line: fields in the order above,
 *   fields whose bytes are all zero left out (a -0 is written), floats with 9
 *   significant digits and the time with 17, so parsing the line gives back
 *   the record bit for bit. A recording of lines therefore
 *   replays exactly the records that were stepped.
 * - Pure: no allocation, no globals, no OS; the caller gives the buffers.
 */
#ifndef HOL_INPUT_IO_H
#define HOL_INPUT_IO_H

#include <stddef.h>

#include "hol_err.h"
#include "hol_input.h"

#define HOL_INPUT_TEXT_VERSION 1
/* The longest canonical line, without its NUL. */
#define HOL_INPUT_LINE_MAX 480

/* Write the canonical line of *in (no newline) and a NUL into out (cap
 * bytes; HOL_INPUT_LINE_MAX + 1 always fit). Returns the length, or 0 when
 * the record is not valid (see hol_input_valid) or cap is too small. */
size_t hol_input_format(const hol_input *in, char *out, size_t cap);

/* Parse one line (len bytes, no newline; NULs are bad input) into *out.
 * Errors: HOL_EPARSE, with the 0-based byte offset of the offending field in
 * *out_bad (may be NULL). On error *out is unchanged. */
hol_err hol_input_parse(const char *s, size_t len, hol_input *out, size_t *out_bad);

/* 1 when every number is finite, time >= 0, axes in [-1, 1] and no unknown
 * flag or button bit is set. */
int hol_input_valid(const hol_input *in);

#endif
