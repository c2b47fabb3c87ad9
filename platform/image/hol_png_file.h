/* hol_png_file.h - PNG files for the desktop tools: render/hol_png.h's
 * in-memory encoder and decoder over platform/file's whole-file reads and
 * atomic writes.
 *
 * Contract
 * - hol_png_write_file encodes RGBA pixels (rows top to bottom) and writes
 *   the file atomically (never half-written); alpha 0 writes RGB.
 * - hol_png_read_file reads a PNG (at most 1 GiB) into a malloc'ed RGBA
 *   buffer (free it with free()). Errors are hol_err, as the encoder,
 *   decoder and hol_file_* give them; errno holds an I/O error's cause.
 */
#ifndef HOL_PNG_FILE_H
#define HOL_PNG_FILE_H

#include <stdint.h>

#include "../../core/hol_err.h"

hol_err hol_png_write_file(const char *path, const uint8_t *rgba, int w, int h,
                           int alpha);
hol_err hol_png_read_file(const char *path, uint8_t **out_rgba, int *out_w,
                          int *out_h);

#endif
