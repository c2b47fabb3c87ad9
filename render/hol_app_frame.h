/* hol_app_frame.h - what the app step's view (core/hol_app.h) asks the
 * renderer to draw, as one eye's frame description.
 *
 * Contract
 * - Pure translation, no GL and no state: every platform (desktop window,
 *   replay, headset) calls it after hol_app_step, so they all draw the
 *   same things from the same view. The renderer decides nothing: which
 *   objectives have markers and poles, whether the chest is open, the HUD
 *   lines and the minimap placement all come from the view.
 * - eye -1: the head (a single view, as on the desktop); 0 or 1: the left
 *   or right eye (hol_app_view.eye_user and .eye), looking along the head.
 * - The returned description points into v (the HUD lines): keep v alive
 *   and unchanged until the frame is drawn.
 * - Minimap in the hand: on the desktop there are no hands, so the map (20
 *   cm) is held low in a left hand: 28 cm ahead of the eye, 52 cm below it
 *   and 12 cm to its left, tilted back to face it; at the usual pitch (30
 *   degrees down) it sits in the lower part of the view, out of its middle,
 *   where a glance down finds it. A platform with tracked hands overwrites
 *   hand_pos and hand_orient with the hand's pose.
 * - The body (hol_app_view.body: controllers, tracked hands, the pointing
 *   ray) goes to every eye's frame as the view has it (fd->body points
 *   into v; NULL when it has none): the renderer draws it in the room.
 * - A headset's eyes: hol_app_frame_panel moves the HUD text (and the
 *   minimap, unless it is in the hand) onto the panel in the world where
 *   the app step placed it (hol_app_view.panel, core/hol_panel.h), its
 *   font pixel scaled by the panel's scale (nearer: smaller alike). Every
 *   platform that draws for a headset (OpenXR, WebXR) calls it for each
 *   eye; desktop, pancake and replays keep the screen layout. Outside the
 *   room (hol_app_view.outside) it also sets the frame's `outside` and its
 *   floor arrow: the view dimmed, the panel over all, the arrow (the
 *   platform draws the eyes where the head is, their cells the seats'
 *   inside: platform/shell/hol_xr_room.h, hol_xr_outside_eyes).
 */
#ifndef HOL_APP_FRAME_H
#define HOL_APP_FRAME_H

#include "../core/hol_app.h"
#include "hol_render.h"

/* Fill *out for one eye of w x h pixels, vertical field of view fovy_deg
 * (0: 90). */
void hol_app_frame_desc(const hol_app_view *v, int eye, int w, int h, double fovy_deg,
                        hol_frame_desc *out);

/* Draw the HUD of *out on the view's world panel (HOL_RENDER_PANEL). */
void hol_app_frame_panel(const hol_app_view *v, hol_frame_desc *out);

#endif
