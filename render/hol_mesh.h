/* hol_mesh.h - CPU mesh building: vertices, indices, low-poly primitives.
 *
 * Contract
 * - A hol_mesh is a caller-sized vertex and index store (no allocation
 *   here: the caller passes arrays and capacities). Appending past the
 *   capacity sets `overflow` and drops the primitive whole, never half.
 * - Vertices: position in metres (float), normal as signed bytes, colour
 *   RGBA8. Alpha marks the surface kind: HOL_MESH_FLOOR (255) for the ground
 *   of a tile (what --tile-ids calls floor), HOL_MESH_PROP (0) for anything
 *   else. Indices are 32-bit triangles, counter-clockwise seen from outside.
 * - A glyph of the text face (the overlays: render/hol_hud.c) has alpha
 *   HOL_MESH_GLYPH and no normal: its four normal bytes hold its atlas
 *   point (u, v in 0..1 of the atlas) as two unsigned 16-bit numbers
 *   (u * 65535, native byte order; hol_mesh_set_uv), which the renderer
 *   reads as attribute 3 for the text program (render/hol_program.h).
 * - Primitives take a placement: translation (x, y, z), a yaw (radians,
 *   counter-clockwise seen from above) and a scale.
 */
#ifndef HOL_MESH_H
#define HOL_MESH_H

#include <stdint.h>
#include <string.h>

#define HOL_MESH_FLOOR 255
#define HOL_MESH_PROP 0
#define HOL_MESH_GLYPH 64

typedef struct hol_vertex {
    float pos[3];
    int8_t nrm[4];
    uint8_t rgba[4];
} hol_vertex;

typedef struct hol_mesh {
    hol_vertex *v;
    uint32_t *idx;
    uint32_t nv, cap_v, ni, cap_i;
    int overflow;
} hol_mesh;

typedef struct hol_place {
    float x, y, z, yaw, scale;
} hol_place;

/* A glyph vertex's atlas point (u, v in 0..1) into its normal bytes. */
static inline void hol_mesh_set_uv(hol_vertex *v, float u, float w)
{
    uint16_t uv[2] = {(uint16_t)(u * 65535.0f + 0.5f), (uint16_t)(w * 65535.0f + 0.5f)};
    memcpy(v->nrm, uv, sizeof uv);
}

void hol_mesh_init(hol_mesh *m, hol_vertex *v, uint32_t cap_v, uint32_t *idx,
                   uint32_t cap_i);
void hol_mesh_clear(hol_mesh *m);
/* Reserve room for nv vertices and ni indices; returns the first vertex
 * index, or -1 (and sets overflow) when it does not fit. */
int64_t hol_mesh_reserve(hol_mesh *m, uint32_t nv, uint32_t ni);
/* Append a copy of src placed by p (normals rotated by the yaw). */
void hol_mesh_append(hol_mesh *m, const hol_mesh *src, hol_place p);
/* Same, with every colour multiplied by tint (0..255 per channel). */
void hol_mesh_append_tinted(hol_mesh *m, const hol_mesh *src, hol_place p,
                            const uint8_t tint[3]);

/* Primitives in local coordinates (before placement); colour rgb, kind as
 * the alpha. */
void hol_mesh_quad_y(hol_mesh *m, float x0, float z0, float x1, float z1, float y,
                     const uint8_t rgb[3], uint8_t kind);
/* An axis-aligned box from (x0,y0,z0) to (x1,y1,z1). */
void hol_mesh_box(hol_mesh *m, const float lo[3], const float hi[3],
                  const uint8_t rgb[3]);
/* A prism/frustum around the y axis: n sides, radius r0 at y0, r1 at y1
 * (r1 = 0: a cone, one triangle a side), with a cap on top when r1 > 0;
 * every triangle wound counter-clockwise seen from outside, and with y0
 * above the ground (an open bottom one can look into) the sides' inner
 * faces too, wound the other way. */
void hol_mesh_frustum(hol_mesh *m, int n, float r0, float y0, float r1, float y1,
                      const uint8_t rgb[3]);
/* A low-poly blob (octahedron stretched by sx, sy, sz) centred at c. */
void hol_mesh_blob(hol_mesh *m, const float c[3], float sx, float sy, float sz,
                   const uint8_t rgb[3]);

#endif
