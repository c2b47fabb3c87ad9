/* hol_world_tree.c - vertices, trees and the content of a tile.
 *
 * Corner c of tile t is the vertex between its edges c and c + 1 (counted
 * counter-clockwise from the canonical heading). Going round that vertex:
 * step across edge c to (n, arrive); the shared edge is (arrive + 2) & 3 in
 * n, and orientation flips across an edge, so the vertex is corner
 * (arrive + 1) & 3 of n. Q such moves return to (t, c) (five in {4,5}: Q
 * of the tile's tiling). The canonical name of the vertex is the least
 * (tile word, corner) of the Q, ordering
 * tile words by length first (so the tile nearest O wins); near the reach of
 * tile words the walk round goes both ways and uses the tiles that exist.
 */
#include "hol_world_impl.h"

static int hol__tile_less(hol_tile a, int ca, hol_tile b, int cb)
{
    if (a.bits[1] != b.bits[1])
        return a.bits[1] < b.bits[1];
    if (a.bits[0] != b.bits[0])
        return a.bits[0] < b.bits[0];
    return ca < cb;
}

hol_err hol_world_vertex_canon(hol_tile t, int corner, hol_tile *out_tile,
                               int *out_corner)
{
    int q = hol_tile_q(t);
    if (!q || !out_tile || !out_corner)
        return HOL_EARG;
    corner &= 3;
    hol_tile best = t;
    int best_c = corner;
    /* counter-clockwise round the vertex */
    hol_tile cur = t;
    int c = corner, i = 0;
    for (; i < q - 1; i++) {
        hol_tile n;
        int arr;
        if (hol_tile_step(cur, c, &n, &arr))
            break;
        cur = n;
        c = (arr + 1) & 3;
        if (hol__tile_less(cur, c, best, best_c)) {
            best = cur;
            best_c = c;
        }
    }
    if (i < q - 1) {
        /* the other way: across edge c + 1, the vertex is corner arrive + 2 */
        cur = t;
        c = corner;
        for (int j = 0; j < q - 1 - i; j++) {
            hol_tile n;
            int arr;
            if (hol_tile_step(cur, c + 1, &n, &arr))
                break;
            cur = n;
            c = (arr + 2) & 3;
            if (hol__tile_less(cur, c, best, best_c)) {
                best = cur;
                best_c = c;
            }
        }
    }
    *out_tile = best;
    *out_corner = best_c;
    return HOL_OK;
}

static hol_tree hol__tree_of(uint64_t seed, hol_tile vt, int vc)
{
    uint64_t h = hol__mix(hol__tile_hash(seed ^ UINT64_C(0x7EE5), vt),
                          (uint64_t)vc);
    hol_tree tr;
    tr.kind = (uint8_t)(h % HOL_TREE_COUNT);
    tr.size = (uint8_t)((h >> 8) & 3);
    return tr;
}

hol_err hol_world_tree(uint64_t seed, hol_tile t, int corner, hol_tree *out)
{
    hol_tile vt;
    int vc;
    if (!out)
        return HOL_EARG;
    hol_err err = hol_world_vertex_canon(t, corner, &vt, &vc);
    if (err)
        return err;
    *out = hol__tree_of(seed, vt, vc);
    return HOL_OK;
}

uint16_t hol__trees_packed(uint64_t seed, hol_tile t)
{
    uint16_t p = 0;
    for (int c = 0; c < 4; c++) {
        hol_tree tr;
        if (hol_world_tree(seed, t, c, &tr))
            tr.kind = tr.size = 0;
        p |= (uint16_t)((tr.kind | tr.size << 2) << (4 * c));
    }
    return p;
}
