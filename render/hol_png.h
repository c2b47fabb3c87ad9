/* hol_png.h - minimal PNG encoder and decoder, in memory, for rendered images and goldens.
 *
 * Contract
 * - Images are 8-bit RGBA, rows top to bottom, tightly packed (4 * w bytes
 *   per row). Writing produces a non-interlaced 8-bit RGB or RGBA PNG
 *   compressed with zlib.
 * - In memory only: files are the platform's (platform/image/hol_png_file.h has
 *   hol_png_write_file, atomic, and hol_png_read_file).
 * - The reader accepts what the writer produces and the common subset of
 *   other encoders: 8-bit grey, grey+alpha, RGB, RGBA, non-interlaced, all
 *   five filter types. Anything else is HOL_EUNSUPPORTED; structural damage
 *   (bad signature, CRC, sizes, truncated data) is HOL_ECORRUPT. It never
 *   reads past its input and caps images at HOL_PNG_MAX_DIM per side.
 * - The reader allocates the output with malloc; free it with free().
 */
#ifndef HOL_PNG_H
#define HOL_PNG_H

#include <stddef.h>
#include <stdint.h>

#include "../core/hol_err.h"

#define HOL_PNG_MAX_DIM 16384

/* Encode to a malloc'ed buffer. alpha = 0 drops the alpha channel. */
hol_err hol_png_encode(const uint8_t *rgba, int w, int h, int alpha,
                       uint8_t **out_data, size_t *out_size);

/* The same with zlib's level 1..9 (hol_png_encode is level 9). Below 9 the
 * rows are all filtered "up" instead of the best of four per row, and a
 * picture without alpha of at most 256 colours is written with a palette
 * (colour type 3, one byte a pixel): at level 1 many times faster (many
 * pictures: `holonomy report`); the pixels are the same. */
hol_err hol_png_encode_level(const uint8_t *rgba, int w, int h, int alpha, int level,
                             uint8_t **out_data, size_t *out_size);

/* An indexed image (one byte a pixel, each below npal, rows top to
 * bottom) with its palette (npal 1..256 colours, 3 bytes each) as a PNG of
 * colour type 3, rows filtered "up", deflated in one block of the fixed
 * codes with only literals and runs of the byte before (no search: many
 * times faster than zlib's level 1 on pictures of flat colours, about as
 * small; `holonomy report`'s pictures). */
hol_err hol_png_encode_indexed(const uint8_t *idx, int w, int h, const uint8_t *plte,
                               int npal, uint8_t **out_data, size_t *out_size);

/* Decode PNG bytes to malloc'ed RGBA (opaque alpha for formats without):
 * 8-bit grey, grey+alpha, RGB, RGBA or palette (an index beyond the
 * palette is HOL_ECORRUPT). */
hol_err hol_png_decode(const uint8_t *data, size_t size, uint8_t **out_rgba,
                       int *out_w, int *out_h);

#endif
