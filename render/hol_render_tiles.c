/* hol_render_tiles.c - the tile pass: one draw per branch of its tile's
 * resident mesh, a lit tile's lights and shadow mask in its own frame,
 * the fireflies' sprites. */
#include "hol_render_int.h"

#include <math.h>
#include <string.h>

#include "../core/hol_world.h"

/* A tile's resident index range: first, count, the last props of them its
 * small props and the first ground its ground (hol_scene_tile's). */
typedef struct hol__range {
    uint32_t first, count, props, ground;
} hol__range;

/* The resident mesh of tile t: reused while the tile's content is the
 * same, else (re)built into the least recently used slot. */
static int hol__tile_range(hol_render *r, hol_tile t, int bare, int pole, int kind,
                           double cell_m, hol__range *out)
{
    hol_tile_content c;
    memset(&c, 0, sizeof c);
    int have = r->desc.world && hol_world_get(r->desc.world, t, &c) == HOL_OK;
    int free_slot = -1, lru = -1;
    for (int i = 0; i < HOL__SLOTS; i++) {
        hol__slot *sl = &r->slots[i];
        if (!sl->used) {
            if (free_slot < 0)
                free_slot = i;
            continue;
        }
        if (hol_tile_eq(sl->tile, t) && sl->bare == bare && sl->pole == pole && sl->kind == kind &&
            sl->have == have && sl->cell_m == cell_m &&
            (!have || !memcmp(&sl->content, &c, sizeof c))) {
            sl->last_frame = r->frame;
            *out = (hol__range){HOL__SLOT_IBASE(i), sl->nidx, sl->nprops, sl->nground};
            return 1;
        }
        if (sl->last_frame != r->frame &&
            (lru < 0 || sl->last_frame < r->slots[lru].last_frame))
            lru = i;
    }
    int k = free_slot >= 0 ? free_slot : lru;
    if (k < 0)
        return 0;
    hol_mesh_clear(&r->scratch);
    r->scratch.cap_v = HOL__SLOT_V;
    r->scratch.cap_i = HOL__SLOT_I;
    uint32_t p0 = 0, g = 0;
    hol_scene_tile(r->scene, &r->scratch, t, r->desc.world, bare, pole, kind, cell_m, &p0, &g);
    r->scratch.cap_v = HOL__ROOM_V;
    r->scratch.cap_i = HOL__ROOM_I;
    if (r->scratch.overflow)
        return 0;
    if (k >= r->slot_cap)
        hol__static_grow(r, k < HOL__SLOTS_MID ? HOL__SLOTS_MID : HOL__SLOTS);
    uint32_t vbase = HOL__SLOT_VBASE(k);
    uint32_t ibase = HOL__SLOT_IBASE(k);
    hol__upload_scratch(r, vbase, ibase);
    hol__slot *sl = &r->slots[k];
    sl->used = 1;
    sl->tile = t;
    sl->bare = bare;
    sl->pole = pole;
    sl->kind = kind;
    sl->have = have;
    sl->cell_m = cell_m;
    sl->content = c;
    sl->last_frame = r->frame;
    sl->nidx = r->scratch.ni;
    sl->nprops = r->scratch.ni - p0;
    sl->nground = g;
    r->tiles_built++;
    *out = (hol__range){ibase, sl->nidx, sl->nprops, sl->nground};
    return 1;
}

/* The guide pole (objective index, or -1) and the game object kind on
 * tile t. */
static void hol__tile_marks(const hol_frame_desc *f, hol_tile t, int *pole, int *kind)
{
    *pole = -1;
    *kind = 0;
    for (int o = 0; o < f->nobjectives && o < HOL_RENDER_MAX_OBJECTIVES &&
                    !(f->flags & HOL_RENDER_NO_POLES); o++)
        if (hol_tile_eq(f->objectives[o], t)) {
            *pole = o;
            break;
        }
    for (int o = 0; o < f->nobjects && o < HOL_RENDER_MAX_OBJECTIVES; o++)
        if (hol_tile_eq(f->object_tiles[o], t)) {
            *kind = f->object_kinds[o];
            break;
        }
    for (int o = 0; f->lighting && o < f->nlanterns && o < HOL_RENDER_MAX_LANTERNS; o++)
        if (hol_tile_eq(f->lanterns[o], t)) {
            *kind |= HOL_SCENE_LANTERN; /* shown at dusk and night */
            break;
        }
}

/* A point of the user's frame in the tile's own frame (inv: the inverse of
 * the tile's frame), as the shader's slot takes it: x, y and z (hyperbolic)
 * or |p|^2/2 (flat, where z is 1). */
static void hol__tile_slot(const double inv[9], const double p[3], int flat, float out[3])
{
    double q[3];
    for (int i = 0; i < 3; i++)
        q[i] = inv[3 * i] * p[0] + inv[3 * i + 1] * p[1] + inv[3 * i + 2] * p[2];
    out[0] = (float)q[0];
    out[1] = (float)q[1];
    out[2] = (float)(flat ? (q[0] * q[0] + q[1] * q[1]) / 2 : q[2]);
}

/* A spot's tangent u at light point l (user frame) in the tile's own frame
 * (the vertex shader's U = u.xy k - u.z): u itself (its z the Lorentz
 * part) on the hyperboloid; flat, u.z = u.xy . l, so U = u . (k - l). */
static void hol__tile_tangent(const double inv[9], const double u[3], const double l[3],
                              int flat, float out[3])
{
    double a[3], b[3];
    for (int i = 0; i < 3; i++) {
        a[i] = inv[3 * i] * u[0] + inv[3 * i + 1] * u[1] + (flat ? 0 : inv[3 * i + 2] * u[2]);
        b[i] = inv[3 * i] * l[0] + inv[3 * i + 1] * l[1] + inv[3 * i + 2] * l[2];
    }
    out[0] = (float)a[0];
    out[1] = (float)a[1];
    out[2] = (float)(flat ? a[0] * b[0] + a[1] * b[1] : a[2]);
}

/* A lit tile's shadows (hol_light.h; the shader's hol_shadow): its pairs'
 * wedges (hol_light_wedge) rastered into its shadow mask (core/hol_shadow.h),
 * kept while the tile, the frame's geometry and its lanterns in its own
 * frame are the same (hol__shadow_mask; a firefly's slot counts, not its
 * place: it casts no shadow), so a still scene, fireflies circling or not,
 * chooses no pairs and rasters nothing; u_shr: 1 / (2 A) (A the tile's Klein half side)
 * and the mask's first texel centre in the masks' texture coordinates. */
static void hol__item_shadows(hol_render *r, hol__item *it, hol_tile t, const double fr[9],
                              const double inv[9], const int idx[], int n)
{
    const hol_light_frame *lf = &r->lights;
    double lp[HOL_LIGHT_PER_TILE][3];
    uint8_t ff[HOL_LIGHT_PER_TILE];
    for (int k = 0; k < n; k++) {
        const double *p = lf->pos[idx[k]];
        for (int i = 0; i < 3; i++)
            lp[k][i] = inv[3 * i] * p[0] + inv[3 * i + 1] * p[1] + inv[3 * i + 2] * p[2];
        ff[k] = lf->ff[idx[k]];
    }
    double geo[3] = {lf->cell_m, lf->klein, lf->metres_per_unit};
    uint64_t key = hol__fnv(0xcbf29ce484222325ull, &t, sizeof t);
    key = hol__fnv(key, geo, sizeof geo);
    for (int k = 0; k < n; k++) /* a firefly casts no shadow: only its slot is in the key */
        key = hol__fnv(key, ff[k] ? (const double *)geo : lp[k], sizeof lp[0]);
    key = hol__fnv(key, ff, (size_t)n) | 1;
    it->nsh = 0;
    int k = hol__shadow_mask(r, key, NULL);
    if (k == -1) { /* not kept: choose the pairs, raster their mask */
        hol_shadow_set ss;
        hol_light_shadows(lf, fr, (const double(*)[3])lp, idx, n, &ss);
        double wedge[HOL_SHADOW_PAIRS][3][3];
        for (int m = 0; m < ss.n; m++)
            hol_light_wedge(lf, lp[ss.slot[m]], ss.trunk[m], wedge[m]);
        hol_shadow_mask_desc md = {lf->flat, lf->klein * lf->cell_m / 2, ss.n,
                                   (const double(*)[3][3])wedge, ss.slot};
        k = hol__shadow_mask(r, key, &md);
    }
    if (k < 0)
        return; /* no shadow, or more masks in one frame than slots */
    it->nsh = 1;
    it->shr[0] = (float)(1 / (lf->klein * lf->cell_m));
    it->shr[1] = (float)((k % HOL__SHM_COLS * HOL_SHADOW_MASK_N + 0.5) /
                         (HOL__SHM_COLS * HOL_SHADOW_MASK_N));
    it->shr[2] = (float)((k / HOL__SHM_COLS * HOL_SHADOW_MASK_N + 0.5) /
                         (HOL__SHM_ROWS * HOL_SHADOW_MASK_N));
    it->shr[3] = 0;
}

/* A lit tile's lights and the eye in the tile's own frame (u_tl: the
 * lights' x, y, z as four-slot vectors, then the eye's point; an empty
 * slot lies far beyond the radius), so the shader needs no matrix. */
static void hol__item_lights(hol_render *r, hol__item *it, hol_tile t, int shadows)
{
    double fr[9], inv[9];
    int idx[HOL_LIGHT_PER_TILE];
    int n = hol_light_tile(&r->lights, t, fr, idx);
    it->nl = (int8_t)n;
    it->nsh = 0;
    if (n < 0)
        return;
    /* the inverse of the frame: Lorentz J F^T J (flat: the rigid motion's) */
    int flat = r->lights.flat;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            inv[3 * i + j] = fr[3 * j + i] * (!flat && (i == 2) != (j == 2) ? -1 : 1);
    if (flat) {
        for (int i = 0; i < 2; i++)
            inv[3 * i + 2] = -(fr[i] * fr[2] + fr[3 + i] * fr[5]);
        inv[6] = inv[7] = 0;
        inv[8] = 1;
    }
    const hol_light_frame *lf = &r->lights;
    for (int k = 0; k < HOL_LIGHT_PER_TILE; k++) {
        float v[3] = {0, 0, 1e4f}, u[3] = {0, 0, 0};
        int i = k < n ? idx[k] : -1;
        if (i >= 0) {
            hol__tile_slot(inv, lf->pos[i], flat, v);
            hol__tile_tangent(inv, lf->sd[i], lf->pos[i], flat, u);
        }
        for (int j = 0; j < 3; j++) {
            it->tl[j][k] = v[j];
            it->tx[j][k] = u[j];
        }
        it->tx[3][k] = i >= 0 ? (float)lf->ssin[i] : -2.0f;
        it->tx[4][k] = i >= 0 ? (float)lf->h[i] : (float)HOL_LIGHT_HEIGHT_M;
        it->tx[5][k] = i >= 0 && !lf->ff[i] ? (float)lf->wt[i] : 0.0f;
        it->tx[6][k] = i >= 0 && lf->ff[i] ? (float)(HOL_LIGHT_FF_WEIGHT * lf->wt[i]) : 0.0f;
        /* the effects this tile's slots need: its program's (hol__item.fx) */
        int fx = it->tx[3][k] > -1.5f ? HOL_PROG_FX_SPOTS
                 : i >= 0 && (lf->ff[i] || it->tx[4][k] != (float)HOL_LIGHT_HEIGHT_M)
                     ? HOL_PROG_FX_FIREFLIES
                     : HOL_PROG_FX_NONE;
        it->fx = (int8_t)(fx > it->fx ? fx : it->fx);
    }
    hol__tile_slot(inv, r->lights.eye, flat, it->tl[3]);
    it->tl[3][3] = 0;
    if (shadows)
        hol__item_shadows(r, it, t, fr, inv, idx, n);
}

/* A firefly's sprite (render/hol_light.h): when tile t has one of the
 * frame's fireflies, a small glowing blob at its place in the tile's own
 * frame, drawn like the tile's item (its stencil, wedge, matrix and
 * lights) from the dynamic buffer after every tile; nonzero: out of
 * room. */
static int hol__queue_firefly(hol_render *r, const hol__item *tile_it, hol_tile t)
{
    int i = hol_light_ff_of(&r->lights, t);
    if (i < 0)
        return 0;
    static const uint8_t glow[3] = {HOL_FF_SPRITE_RGB};
    const double *p = r->lights.ff_xzh[i];
    float c[3] = {(float)p[0], (float)p[2], (float)p[1]};
    uint32_t v0 = r->dyn.nv, i0 = r->dyn.ni;
    hol_mesh_blob(&r->dyn, c, HOL_FF_SPRITE_M, HOL_FF_SPRITE_M, HOL_FF_SPRITE_M, glow);
    if (r->dyn.overflow)
        return 1;
    for (uint32_t v = v0; v < r->dyn.nv; v++)
        r->dyn.v[v].rgba[3] = HOL_MESH_GLOW; /* unlit, as a lantern's glass */
    hol__item *it = hol__queue_push(r, HOL__PASS_TILE, i0, r->dyn.ni - i0);
    if (!it)
        return 1;
    *it = *tile_it;
    it->first = i0;
    it->count = r->dyn.ni - i0;
    it->dyn = 1;
    it->props = 0;
    it->ground = 0;
    it->fx = HOL_PROG_FX_NONE; /* unlit: the cheapest of the tiles' programs */
    it->nsh = 0;
    it->key = 2u << 24 | 0xffu << 16 | (uint32_t)(uint16_t)tile_it->branch;
    return 0;
}

/* The window's pixels where branch br's stencil test can pass: the
 * bounding box of the leaves it is drawn on ((code & mask) == ref; their
 * NDC boxes from hol__queue_leaves), a pixel wider on every side than
 * the leaves' polygons, within the viewport; out w 0 with a return of 1
 * for the whole viewport (a branch with no stencil test: the wedges'
 * views), 0 when no leaf of it is on screen (nothing of it is drawn). */
static int hol__branch_box(const hol_render *r, const hol_frame_desc *f,
                           const hol_view_branch *br, int32_t out[4])
{
    memset(out, 0, 4 * sizeof out[0]);
    if (!br->mask)
        return 1;
    float b[4] = {1, 1, -1, -1};
    for (int k = 0; k < r->view.nleaves; k++) {
        const float *lb = r->leaf_box[k];
        if ((r->view.leaves[k].code & br->mask) != br->ref || lb[0] > lb[2])
            continue;
        hol__box_add(b, lb[0], lb[1]);
        hol__box_add(b, lb[2], lb[3]);
    }
    if (b[0] > b[2])
        return 0;
    const int size[2] = {f->cam.width, f->cam.height};
    for (int j = 0; j < 2; j++) {
        double lo = floor((b[j] + 1) * 0.5 * size[j]) - 1, hi = ceil((b[2 + j] + 1) * 0.5 * size[j]) + 1;
        lo = lo < 0 ? 0 : lo;
        hi = hi > size[j] ? size[j] : hi;
        out[j] = (int32_t)lo + (j ? f->vp_y : f->vp_x);
        out[2 + j] = (int32_t)(hi - lo);
    }
    return out[2] > 0 && out[3] > 0;
}

/* Pass 2: one draw per branch of its tile's resident mesh, placed in the
 * branch's cell, nearest cells first. */
hol_err hol__queue_tiles(hol_render *r, const hol_frame_desc *f, int bare,
                                double cell_m)
{
    const hol_view *v = &r->view;
    for (int k = 0; k < v->nbranches; k++) {
        const hol_view_branch *br = &v->branches[k];
        int32_t box[4];
        if (br->err || !hol__branch_box(r, f, br, box))
            continue;
        hol__range rg;
        int pole, kind;
        hol__tile_marks(f, br->state.tile, &pole, &kind);
        if (!hol__tile_range(r, br->state.tile, bare, pole, kind, cell_m, &rg))
            return HOL_ENOMEM;
        hol__item *it = hol__queue_push(r, HOL__PASS_TILE, rg.first, rg.count);
        if (!it)
            return HOL_ENOMEM;
        it->ref = br->ref;
        it->mask = br->mask;
        it->branch = (int16_t)k;
        memcpy(it->box, box, sizeof box);
        for (int j = 0; j < 2; j++) {
            it->wedge[j] = (float)br->w0[j];
            it->wedge[2 + j] = (float)br->w1[j];
        }
        it->key = 2u << 24 | (uint32_t)br->nsteps << 16 | (uint32_t)k;
        if (f->lighting)
            hol__item_lights(r, it, br->state.tile, !(f->flags & HOL_RENDER_NO_SHADOWS));
        /* its small props apart, lit per vertex: a lit tile with a frame
         * and no spot in its slots, not the IDs' frame */
        int apart = f->lighting && !(f->flags & HOL_RENDER_IDS) && it->nl >= 0;
        it->props = apart && it->fx < HOL_PROG_FX_SPOTS ? rg.props : 0;
        /* and its ground, with the floor's program (not with wedges) */
        it->ground = apart && !r->view.wedges ? rg.ground : 0;
        /* tile frame -> room: the tile's heading is room north turned
         * clockwise by orient quarter turns */
        double a = -(double)br->state.orient * 1.5707963267948966;
        float c = (float)cos(a), s = (float)sin(a);
        c = fabsf(c) < 1e-6f ? 0.0f : c;
        s = fabsf(s) < 1e-6f ? 0.0f : s;
        /* x' = x c + z s, z' = -x s + z c (counter-clockwise by a) */
        float *m = it->model;
        m[0] = c;
        m[2] = -s;
        m[8] = s;
        m[10] = c;
        m[12] = (float)((br->state.col + 0.5) * cell_m);
        m[14] = (float)((br->state.row + 0.5) * cell_m);
        if (f->lighting && !bare && hol__queue_firefly(r, it, br->state.tile))
            return HOL_ENOMEM;
    }
    return HOL_OK;
}
