/* hol_face_draw.h - draws text in the text face (core/hol_face.h) into an
 * RGBA picture on the CPU, from the signed-distance atlas: the report's
 * pictures and the tests' sheets; the GPU path samples the same atlas.
 *
 * Contract
 * - Pure: writes only the caller's pixels; no allocation, no globals.
 * - Each glyph is its quad of the atlas scaled by size / HOL_FACE_BAKE_EM,
 *   the pen starting at (x, y) on the baseline (pixels, y down) and moving
 *   by advances plus kerning, computed in font units as hol_face_units, so
 *   the drawn width is hol_face_width's. A pixel samples the atlas at its
 *   centre with bilinear filtering (never outside the glyph's rectangle);
 *   its coverage is smoothstep(-s/2, s/2, d), d the distance to the
 *   outline in picture pixels (positive inside) and s the edge width.
 * - The ink is blended over the picture (source over, straight alpha);
 *   pixels outside the picture are clipped. Text is UTF-8; missing and
 *   malformed code points draw the box (hol_face.h), counted.
 */
#ifndef HOL_FACE_DRAW_H
#define HOL_FACE_DRAW_H

#include <stddef.h>
#include <stdint.h>

/* An RGBA picture, rows top to bottom; stride in bytes (0: 4 * w). */
typedef struct hol_face_canvas {
    uint8_t *rgba;
    int w, h;
    size_t stride;
} hol_face_canvas;

typedef struct hol_face_draw_desc {
    float x, y;    /* the pen's start on the baseline, pixels */
    float size;    /* pixels per em; 0: 16 */
    uint32_t ink;  /* 0xRRGGBBAA; 0: opaque black */
    float edge;    /* width of the edge's ramp in pixels; 0: 1 */
} hol_face_draw_desc;

/* Draws the first len bytes of text; returns the pen's advance in pixels;
 * adds the boxes drawn for missing or malformed code points to
 * *out_missing when not NULL. */
float hol_face_draw(const hol_face_canvas *canvas, const hol_face_draw_desc *desc, const char *text,
                    size_t len, int *out_missing);

/* The coverage (0..1) of glyph index g at atlas point (u, v), atlas pixels
 * from its rectangle's top-left, for an edge ramp of `edge` atlas pixels:
 * the sampling both hol_face_draw and the shader do. */
float hol_face_coverage(int g, float u, float v, float edge);

#endif
