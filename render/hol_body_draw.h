/* hol_body_draw.h - the body's meshes: controllers, tracked hands and the
 * pointing ray (core/hol_body.h) in room coordinates.
 *
 * Contract
 * - hol_body_build appends the body of a frame (hol_frame_desc.body) to a
 *   mesh, its vertices in room coordinates (the frame's room pass draws
 *   them with the identity model, depth-tested and written like the
 *   room's trees): each controller's model placed by its grip pose, each
 *   tracked hand's joints as spheres of their radii and its bones as
 *   cylinders between them, the ray as a thin box along the grip's -z.
 *   Nothing is moved by a tile's transform: the body stands where the
 *   record says in every tile.
 * - A controller's model (hol_body_model) is a few boxes and discs in the
 *   grip's frame (x right, y up, -z ahead); hol_body_grip_box gives its
 *   grip, the box tests project (tests/test_render_body.c).
 * - No GL: the renderer uploads the mesh with the frame's dynamic geometry.
 */
#ifndef HOL_BODY_DRAW_H
#define HOL_BODY_DRAW_H

#include "../core/hol_body.h"
#include "hol_mesh.h"

/* The grip box of a controller model, in the grip's frame (metres). */
void hol_body_grip_box(int model, float lo[3], float hi[3]);

/* Append the body b to m (overflow: m->overflow, the part dropped whole). */
void hol_body_build(hol_mesh *m, const hol_body *b);

#endif
