/* hol_hud.h - HUD text (the text face, core/hol_face.h) and the Poincare
 * minimap.
 *
 * Contract
 * - Builds flat 2D geometry straight in normalized device coordinates
 *   (z = 0) into a hol_mesh, for one draw with the renderer's text
 *   program (render/hol_program.h). Vertices are HOL_MESH_PROP (never
 *   floor), a glyph's HOL_MESH_GLYPH with its atlas point (hol_mesh.h):
 *   one quad a glyph. Nothing allocates.
 * - Minimap: a Poincare disk centred on the user's tile (room north up,
 *   room east right) showing every tile within HOL_HUD_MAP_RADIUS steps as
 *   its geodesic square (the tiling is the user's tile's, {4,5}..{4,8});
 *   in the flat grid {4,4} a plain top view instead (squares, no disk
 *   distortion, HOL_HUD_MAP_RADIUS + 0.75 tile sides from the centre to
 *   the rim) with the caption HOL_HUD_FLAT_CAPTION over it. Tiles are
 *   coloured hot-cold by the tile distance to the nearest objective (red near, blue far; grey-green without objectives),
 *   the shortest-path overlay (tile centres of the given room walk), the
 *   objectives (yellow diamonds), the user's arrow (view yaw), and for each
 *   objective off the map an arrow on the rim pointing towards it.
 * - Placement on the screen: the minimap in the bottom right corner,
 *   scaled to the window and kept out of the middle 40 % of the view both
 *   ways (hol_hud_map_rect); the text top left (the app's lines, the
 *   prompt last in yellow), an overlay (frame time) top right. Tiles in
 *   f->marks get cyan rings on the map.
 * - In the hand: the same minimap laid out to fill the square [-1, 1]^2
 *   (x right, y up, z = 0), for the renderer to place on a quad at the
 *   hand's pose; the text stays on the screen.
 * - On a headset's panel (hol_hud_build_panel_text): the text wrapped into
 *   a block of a fixed width, for the renderer to place in the world.
 */
#ifndef HOL_HUD_H
#define HOL_HUD_H

#include "../core/hol_app.h"
#include "hol_mesh.h"
#include "hol_render_types.h"

#define HOL_HUD_MAP_RADIUS HOL_APP_MINIMAP_RADIUS
/* The caption over the flat grid's map (Q = 4): a plain top view. */
#define HOL_HUD_FLAT_CAPTION "Map: flat top view {4,4}"

/* Append the HUD of frame f (viewport w x h pixels) to out: the map part
 * (disk, tiles, path, objectives, rim arrows: a function of the user's
 * state, objectives, path and viewport only, so it can stay resident) and
 * the live part (the user's arrow and the text). hol_hud_build does both. */
void hol_hud_build(hol_mesh *out, const hol_frame_desc *f, int w, int h);
void hol_hud_build_map(hol_mesh *out, const hol_frame_desc *f, int w, int h);
void hol_hud_build_live(hol_mesh *out, const hol_frame_desc *f, int w, int h);
void hol_hud_build_text(hol_mesh *out, const hol_frame_desc *f, int w, int h);

/* The minimap in the hand: the map part (resident) and the user's arrow
 * (live), in the square [-1, 1]^2. */
void hol_hud_build_hand_map(hol_mesh *out, const hol_frame_desc *f);
void hol_hud_build_hand_arrow(hol_mesh *out, const hol_frame_desc *f);

/* The headset's panel (HOL_RENDER_PANEL), in font pixels (the renderer
 * makes one font pixel f->panel_px metres): the text block is
 * HOL_HUD_PANEL_W wide and at most HOL_HUD_PANEL_HMAX high, its lines
 * wrapped at blanks to fit the width (the prompt in yellow, the overlay
 * last); when more lines than fit the height, the glyphs shrink until all
 * fit: no line is cut off. The map square (HOL_HUD_PANEL_MAP a side, the
 * hand's layout) stands HOL_HUD_PANEL_GAP to its right, their tops level.
 * Builds the block into the square [-1, 1]^2 (x right, y up, z = 0) and
 * gives its size in font pixels in out_wh ({0, 0}: no text). */
#define HOL_HUD_PANEL_W 136.0f
#define HOL_HUD_PANEL_HMAX 93.0f
#define HOL_HUD_PANEL_MAP 64.0f
#define HOL_HUD_PANEL_GAP 6.0f
void hol_hud_build_panel_text(hol_mesh *out, const hol_frame_desc *f, float out_wh[2]);

/* The panel's whole box in its own plane (x right, y up, metres; the
 * panel's centre, panel_pos, at 0, 0): what a composition layer shows
 * (HOL_RENDER_PANEL_LAYER). map: the map square stands beside the text
 * (HOL_RENDER_MINIMAP without HOL_RENDER_MINIMAP_HAND); px: metres per
 * font pixel (0: HOL_RENDER_PANEL_PX). The box is the text block's
 * widest and tallest (HOL_HUD_PANEL_HMAX: a block of fewer lines leaves
 * its lower part empty): out = width, height, centre x, centre y. */
static inline void hol_hud_panel_box(int map, double px, double out[4])
{
    double k = px > 0 ? px : HOL_RENDER_PANEL_PX;
    double wide = HOL_HUD_PANEL_W + (map ? HOL_HUD_PANEL_GAP + HOL_HUD_PANEL_MAP : 0);
    double top = HOL_HUD_PANEL_MAP / 2, bottom = top - HOL_HUD_PANEL_HMAX;
    out[0] = wide * k;
    out[1] = (top - bottom) * k;
    out[2] = 0;
    out[3] = (top + bottom) / 2 * k;
}

/* The HUD minimap's square, rim arrows included, on a w x h screen:
 * out = x0, y0, x1, y1 in pixels (y down). */
void hol_hud_map_rect(int w, int h, float out[4]);

/* UTF-8 text in the text face from the pen at pixel (x, y) on the
 * baseline (y down), size pixels to the em, on a w x h screen; returns the
 * advance in pixels (hol_face_width's). A code point the face lacks, or a
 * malformed byte, draws the missing box (core/hol_face.h). */
float hol_hud_text(hol_mesh *out, const char *s, float x, float y, float size,
                   const uint8_t rgb[3], int w, int h);

#endif
