/* hol_xr_quad.h - the world panel as an OpenXR quad layer
 * (XrCompositionLayerQuad), as pure functions (no OpenXR or GL headers):
 * where the quad stands and how large it is, its image's size, and when
 * its image is drawn again. tests/test_xr_quad.c checks them without a
 * runtime.
 *
 * Contract
 * - The panel's pose comes from core (hol_app_view.panel, core/hol_panel.h:
 *   its centre and turn in room coordinates; unturned it faces +z, up +y,
 *   as a quad layer does). The layer shows the panel's whole box
 *   (hol_hud_panel_box, render/hol_hud.h): the text block's widest and
 *   tallest, and the map square beside it when the map is on the panel.
 *   hol_xr_quad_place gives the box's centre (the panel's centre moved
 *   within its plane by the box's offset) and the panel's turn in the
 *   room's OpenXR space (hol_xr_to_stage of the calibration), minus
 *   `shift` (room metres: the scripted head's offset, which moves the
 *   app's eyes but not the runtime's; zero on a real headset), its size in
 *   metres, and the part of the image it uses (the texels from the
 *   image's lower left corner).
 * - The image: HOL_XR_QUAD_TEXELS texels per font pixel, the box of the
 *   widest panel (with the map): hol_xr_quad_image; created once, its
 *   lower left part used when the map is not on the panel.
 * - Redraw on change: hol_xr_quad_stale(c, key) is 1 the first time and
 *   whenever the panel's content key (hol_render_panel_key) differs from
 *   the last drawn one, then remembers it; 0 otherwise (the runtime keeps
 *   showing the image released last). hol_xr_quad_forget: the image must
 *   be drawn again (a new swapchain).
 */
#ifndef HOL_XR_QUAD_H
#define HOL_XR_QUAD_H

#include <stdint.h>

#include "hol_xr_room.h"

/* texels per font pixel: a capital (7 font pixels, 30 mm at 1.5 m) 28
 * texels high */
#define HOL_XR_QUAD_TEXELS 4

/* What holonomy xr --panel chose (hol_xr_desc.panel). */
enum { HOL_XR_PANEL_QUAD = 0, HOL_XR_PANEL_SCENE = 1 };

typedef struct hol_xr_quad {
    float pos[3];  /* the box's centre in the room's OpenXR space */
    float quat[4]; /* x, y, z, w: the panel's turn in that space */
    float size[2]; /* width, height in metres */
    int rect[2];   /* the image's texels used, from (0, 0): width, height */
} hol_xr_quad;

/* map: the map square on the panel; px: metres per font pixel (0: the
 * renderer's HOL_RENDER_PANEL_PX); shift may be NULL (none). */
void hol_xr_quad_place(const hol_xr_calib *c, const double panel_pos[3],
                       const double panel_orient[4], int map, double px, const float shift[3],
                       hol_xr_quad *out);
/* The image's size in texels (the widest box). */
void hol_xr_quad_image(int *out_w, int *out_h);

typedef struct hol_xr_quad_cache {
    int drawn;    /* an image was drawn */
    uint64_t key; /* its content key */
    long redraws; /* images drawn so far */
} hol_xr_quad_cache;

int hol_xr_quad_stale(hol_xr_quad_cache *c, uint64_t key);
void hol_xr_quad_forget(hol_xr_quad_cache *c);

#endif
