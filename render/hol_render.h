/* hol_render.h - the renderer: one render queue per eye, stencil portals.
 *
 * Contract
 * - Platform independent GLES 3.0 (shaders are `#version 300 es`; under
 *   OSMesa's desktop GL core profile the same code runs, and EGL's GLES 3
 *   draws the same pixels). GL entry points are loaded through
 *   desc.getproc (render/hol_gl.h); nothing links gl* symbols. The caller
 *   makes a GL context current (8 stencil bits, a depth buffer) before
 *   hol_render_create and keeps it current for every call.
 * - hol_render_create makes the GL objects and the CPU stores once (fixed
 *   sizes); frames allocate nothing on the CPU. Shader programs other than
 *   the day's are compiled the first time a frame uses one, unless
 *   desc.all_programs (then all at create). Meshes stay resident on the GPU: the
 *   room's (rebuilt when the user steps) and a pool of tile meshes (LRU,
 *   rebuilt when a tile's content changes); per frame only the leaf
 *   polygons and the HUD are uploaded (a few KB).
 * - A frame is one eye: hol_view_build gives the leaves and branches; the
 *   queue holds one stencil polygon per visible leaf (pass 0, colour and
 *   depth writes off, drawn with the day's program at every sky, the
 *   cheapest; rooms other than 3 x 3 tell branches apart by their
 *   wedges instead, tested in the fragment shader: hol_view.h), the room's
 *   own meshes (trees on all (C+1)(R+1) vertices,
 *   hedges on the boundary, a backdrop forest beyond them; pass 1, no
 *   stencil test), one draw per branch of its tile's mesh placed in the
 *   branch's cell and tested against the branch's stencil ref/mask (pass 2,
 *   nearest cells first for early depth rejection), the HUD (pass 3: the
 *   resident minimap and the live arrow and text; for a headset's eye a
 *   panel in the world instead, the last pass: HOL_RENDER_PANEL). One pair
 *   of shaders for all, its variants keyed (render/hol_program.h); the
 *   queue is sorted by (pass, buffer, depth) and executed with
 *   redundant state changes skipped. No scene pass per portal, no
 *   render-to-texture.
 * - Geometry: the tiling is the user's tile word's (hol_tile_q: {4,4} the
 *   flat grid .. {4,8}), the room the user state's C x R cells, the cell
 *   side f->cell_m metres (0: 1). Room coordinates are metres (SPEC 7):
 *   a tile's ground, creeks and the places of its props scale with the
 *   cell; props, trees and hedges keep their size in metres.
 * - Floor outside the room is not drawn: hedges 2 m high stand on the room
 *   boundary (the move area ends there), and over them one sees sky/fog.
 *   Floor pixels are those showing the ground of a tile inside the room.
 * - ID mode renders the same queue but writes, for floor pixels, the index
 *   + 1 of the branch drawn there and 0 elsewhere (props, trees, sky): the
 *   tile under every pixel, as the portals decided it.
 * - Lighting (f->lighting, docs/lighting.md): day draws exactly
 *   the picture without lights. At dusk and night every tile fragment gets
 *   its point on the hyperboloid (render/hol_light.h: the tile's frame in
 *   the user's tile, the Klein map of the square), up to 4 lanterns chosen
 *   per tile on the CPU light it by the true distance in H^2 x E, and fog
 *   follows the true distance from the eye; the room's own meshes get the
 *   sky's ambient light and fog by room distance. A lantern tile shows a
 *   lantern (its glass drawn unlit). Fireflies (f->fireflies) and spots
 *   (f->lantern_spot) join the same choice (render/hol_light.h).
 *   HOL_RENDER_LIGHT_ONLY (tests) writes a tile fragment as (the lanterns'
 *   sum, the fog factor, the fireflies' sum).
 * - World content: with desc.world the tiles' content (biome, objects,
 *   creeks, logs, trees) comes from hol_world_get; without it, a plain
 *   biome-tinted floor from hol_tile_hash.
 */
#ifndef HOL_RENDER_H
#define HOL_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "hol_render_types.h"

/* Errors: HOL_EARG (no getproc), HOL_EUNSUPPORTED (a GL function or the
 * shaders are missing), HOL_ENOMEM. */
hol_err hol_render_create(const hol_render_desc *desc, hol_render **out);
void hol_render_destroy(hol_render *r);
/* Switch the world the content comes from (NULL: placeholder content). */
void hol_render_set_world(hol_render *r, struct hol_world *world);
/* Drop every resident mesh (they are rebuilt on use). Not needed when only
 * tile content changes: a tile's mesh is rebuilt when hol_world_get reports
 * other content than it was built from. */
void hol_render_invalidate(hol_render *r);

/* Render one eye into the current framebuffer (viewport: cam size at
 * vp_x, vp_y). The frame is queued: nothing in it waits for the GL (no
 * glGet*, glGetError, glFinish, glReadPixels), unless f->flags has
 * HOL_RENDER_WAIT (glFinish at the end: out_stats' times then include the
 * GPU's) or desc.debug is set (glGetError at the end: a GL error is
 * HOL_EUNSUPPORTED). out_stats' counts are filled either way.
 * Errors: HOL_EARG (eye not inside the user's cell unless fade >= 1, bad
 * size, a cell size outside 0.5..1.5),
 * HOL_ENOMEM (the fixed stores overflowed). */
hol_err hol_render_frame(hol_render *r, const hol_frame_desc *f,
                         hol_render_stats *out_stats);

/* The headset panel's content alone, for a composition layer (an OpenXR
 * quad layer, a WebXR XRQuadLayer): f as for an eye with HOL_RENDER_PANEL
 * (its text, flags, map; the camera and the panel's pose are not used).
 * hol_render_panel_key: a hash of everything the image shows (the text
 * block's vertices and size, the map's inputs), computed on the CPU (it
 * may upload a changed resident map, as a frame would): equal keys, equal
 * images, so the caller redraws only when the key changes.
 * hol_render_panel_image: draws the image into the current framebuffer at
 * (0, 0), w x h pixels: the panel's box (hol_hud_panel_box in
 * render/hol_hud.h) fills it, x right and y up as GL's (row 0 at the
 * bottom), the rest of the box cleared to transparent (0, 0, 0, 0), the
 * panel's own pixels opaque. Errors: HOL_EARG (a size outside 1..the
 * renderer's maximum), HOL_ENOMEM. */
uint64_t hol_render_panel_key(hol_render *r, const hol_frame_desc *f);
hol_err hol_render_panel_image(hol_render *r, const hol_frame_desc *f, int w, int h);

/* With desc.lazy_programs: compile one more of the programs not compiled
 * yet. Returns how
 * many are left, 0 when all are made, or -1 when this one failed (its
 * first frame would fail the same way). Each compile waits for the GL
 * (its status): the web compiles them all in the frame after its first. */
int hol_render_prepare(hol_render *r);

/* Ask the GL for errors now (one glGetError round trip): HOL_OK, or
 * HOL_EUNSUPPORTED when the GL reported one since the last check. For
 * init and after a resize; not per frame (see desc.debug). */
hol_err hol_render_check(hol_render *r);

/* The room state an eye sees from (stereo) is the core's business:
 * hol_motion_eye_state (core/hol_motion.h). */

/* The view of the last frame (branches, for decoding ID images). */
const hol_view *hol_render_last_view(const hol_render *r);

/* Read the framebuffer (w x h RGBA, rows top to bottom). */
void hol_render_read_rgba(hol_render *r, int w, int h, uint8_t *out_rgba);

/* Decode an ID-mode pixel: -1 for no floor, else the branch index. */
int hol_render_decode_id(const uint8_t rgba[4]);

#endif
