/* hol_scene.h - procedural content: prop templates built once, the room's
 * own meshes (trees on the vertices, boundary hedges) and tile meshes.
 *
 * Contract
 * - hol_scene_create builds every template mesh in code (no asset files)
 *   into one allocation; nothing else allocates.
 * - Tile meshes are in the tile's frame: the tile is the square
 *   x, z in [-M/2, M/2] centred at the origin (M the cell side in metres,
 *   cell_m; 0: 1): its ground and the places of its props scale with M,
 *   the props' sizes do not (they are metres), its canonical heading is -z
 *   (edge d of hol_tile_step lies towards heading + d quarter turns
 *   counter-clockwise). The ground is HOL_MESH_FLOOR, everything else
 *   HOL_MESH_PROP.
 * - Content comes from the world when one is given (hol_world_get), else a
 *   deterministic placeholder from hol_tile_hash (a biome-tinted floor).
 * - Room meshes are in room coordinates (metres: x east, z south, 0..C*M
 *   and 0..R*M).
 */
#ifndef HOL_SCENE_H
#define HOL_SCENE_H

#include "../core/hol_alloc.h"
#include "../core/hol_tile.h"
#include "hol_mesh.h"
#include "hol_render_types.h"
#include "hol_view.h"

struct hol_world;
typedef struct hol_scene hol_scene;

/* One allocation through a (NULL: malloc). */
hol_err hol_scene_create(const hol_alloc *a, hol_scene **out);
void hol_scene_destroy(const hol_alloc *a, hol_scene *s);

/* Trees on the (C+1)(R+1) room vertices, the boundary hedges and the
 * backdrop forest, for the user's C x R room of cell_m metres (0: 1). The tree kinds come from the world when given: each room vertex
 * as a corner of the adjacent cell nearest the user's cell, reached by the
 * room walk columns first (a function of the user's state only).
 * out_backdrop (NULL: not wanted) receives the index range [first, end)
 * of the outer ground and the backdrop forest (lit by no lantern: the
 * renderer draws it on the cheaper path at dusk and night). */
void hol_scene_room(const hol_scene *s, hol_mesh *out, const hol_room *user,
                    struct hol_world *world, double cell_m, uint32_t out_backdrop[2]);

/* The mark of the tree on room vertex (vx, vz) (hol_frame_desc.tree_marked):
 * two glowing bands round its trunk and a glowing ring round its foot, in
 * room coordinates (x = vx * cell_m, z = vz * cell_m; cell_m 0: 1). */
void hol_scene_tree_mark(const hol_scene *s, hol_mesh *out, int vx, int vz, double cell_m);

/* The mesh of tile t in its own frame; bare: the ground only. pole >= 0
 * adds a tall guide pole of colour pole (objective index). Game objects
 * are drawn as the app says, not from the world's content: kind is a
 * HOL_RENDER_OBJ_* (0: none) drawn at the tile's centre, or'd with
 * HOL_SCENE_LANTERN for a lantern over the centre (HOL_LIGHT_HEIGHT_M) on
 * a post beside it; the lantern's glass has alpha HOL_MESH_GLOW (the
 * shader draws it unlit, glowing). Its small props (grass tufts, flowers,
 * mushrooms) come last: out_props receives the index (of out's) where
 * they begin (out's end when there are none), so the renderer can draw
 * them apart (lit per vertex at dusk and night: docs/lighting.md).
 * Its ground (the floor and its water, every vertex's normal straight up)
 * comes first: out_ground (NULL: not wanted) receives its number of
 * indices, so the renderer can draw it with the floor's program. */
#define HOL_SCENE_LANTERN 0x100
#define HOL_MESH_GLOW 100
void hol_scene_tile(const hol_scene *s, hol_mesh *out, hol_tile t,
                    struct hol_world *world, int bare, int pole, int kind, double cell_m,
                    uint32_t *out_props, uint32_t *out_ground);

/* Sky / fog colour (linear 0..1). */
void hol_scene_sky(float out_rgb[3]);

#endif
