/* hol_font.h - the built-in 5x7 bitmap font, shared by the HUD and the
 * report's pictures.
 *
 * Contract
 * - hol_font_glyph(c) gives the 7 rows of c's glyph; bit 4 (0x10) of a row
 *   is its leftmost column. Pure, no GL, thread safe.
 * - The font has digits, upper-case letters, the lower-case f, l and r
 *   (the minimap's step letters), and : . - / , ! ( ) and space. Other
 *   lower-case letters are drawn upper-case; any other byte (and 0) gets a
 *   hollow box, so a missing glyph shows instead of vanishing.
 */
#ifndef HOL_FONT_H
#define HOL_FONT_H

#include <stdint.h>

const uint8_t *hol_font_glyph(int c);

#endif
