/* hol_shadow.h - a tile's shadow mask (issue 38): every shadow that falls
 * on a tile, from every light of it, as one small image per tile that the
 * renderer samples once a fragment, so a tile pays the same for one
 * shadow as for thirty.
 *
 * Contract
 * - A shadow is a wedge: three half-planes, each affine in the tile's
 *   Klein point k, (a, b, c) with value a k_x + b k_y + c; times g (g =
 *   1/sqrt(1 - |k|^2), flat 1) it is sinh d m / (2 e), d the signed
 *   floor distance into the half-plane, m metres per unit, e the soft
 *   edge's half width (render/hol_light.h's hol_light_wedge: a trunk's
 *   shadow, or a hedge's). Its occlusion is o = clamp(1/2 + u, 0, 1), u =
 *   g min_j(value_j); a light's occlusion is min(1, the sum of its
 *   wedges' o), the light is multiplied by 1 minus that.
 * - The mask: HOL_SHADOW_MASK_N x HOL_SHADOW_MASK_N texels of four bytes,
 *   one per light slot of the tile, row j and column i at the Klein point
 *   k = A (2 i / (N - 1) - 1, 2 j / (N - 1) - 1), A the tile's Klein half
 *   side (texel centres on the tile's edges and corners, so both tiles of
 *   an edge sample the same points on it). A byte b holds a value u' with
 *   u' = (2 b / 255 - 1) HOL_SHADOW_MASK_RANGE, and the slot's occlusion
 *   is clamp(1/2 + u', 0, 1) of the bilinear mix of the four nearest
 *   texels: u' = u of the one wedge where one acts (so a wedge's edge,
 *   affine in k but for g, is interpolated almost exactly), the summed
 *   occlusion minus 1/2 where several overlap in their soft edges, and
 *   continued beyond 0 and 1 by the strongest wedge, within the range.
 * - Pure: no allocation, no GL, no state; the same wedges give the same
 *   bytes.
 */
#ifndef HOL_SHADOW_H
#define HOL_SHADOW_H

#include <stdint.h>

#define HOL_SHADOW_MASK_N 64
#define HOL_SHADOW_MASK_RANGE 2.0
#define HOL_SHADOW_MASK_BYTES (HOL_SHADOW_MASK_N * HOL_SHADOW_MASK_N * 4)

typedef struct hol_shadow_mask_desc {
    int flat;                   /* {4,4}: g = 1 */
    double half;                /* A, the tile's Klein half side */
    int n;                      /* wedges */
    const double (*wedge)[3][3]; /* each one's three half-planes */
    const int *slot;            /* each one's light slot, 0..3 */
} hol_shadow_mask_desc;

/* The mask of d's wedges into out (HOL_SHADOW_MASK_BYTES bytes, rows of
 * N texels of four slot bytes). */
void hol_shadow_mask(const hol_shadow_mask_desc *d, uint8_t *out);

#endif
