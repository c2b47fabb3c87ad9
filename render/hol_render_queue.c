/* hol_render_queue.c - a frame's queue: the view, the leaves' stencil
 * polygons, the room's meshes, the fade, the HUD, the hand's map and the
 * headset's panel (the tiles: hol_render_tiles.c). */
#include "hol_render_int.h"

#include <math.h>
#include <string.h>

#include "hol_body_draw.h"
#include "hol_hud.h"

/* Column-major model matrix of a quad in the world: the square [-1, 1]^2
 * (z = 0) scaled to sx x sy (half sides, metres) and moved by (ox, oy) in
 * its own plane, turned by the quaternion q (all zero: identity), moved to
 * pos. */
void hol__quad_matrix(const double pos[3], const double q[4], double sx, double sy,
                             double ox, double oy, float m[16])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (n < 1e-12) {
        x = y = z = 0;
        w = 1;
    } else {
        x /= n, y /= n, z /= n, w /= n;
    }
    double rot[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                     2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                     2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    hol__identity(m);
    for (int r = 0; r < 3; r++) {
        m[r] = (float)(rot[3 * r] * sx);
        m[4 + r] = (float)(rot[3 * r + 1] * sy);
        m[8 + r] = (float)rot[3 * r + 2];
        m[12 + r] = (float)(pos[r] + rot[3 * r] * ox + rot[3 * r + 1] * oy);
    }
}

/* The hand's minimap quad: hand_size a side, at hand_pos, hand_orient. */
static void hol__hand_matrix(const hol_frame_desc *f, float m[16])
{
    double half = (f->hand_size > 0 ? f->hand_size : 0.25) / 2;
    hol__quad_matrix(f->hand_pos, f->hand_orient, half, half, 0, 0, m);
}

/* An item of this frame's dynamic geometry, from index i0 to the end: in
 * pass, its key's low bits sub, model (NULL: the identity). */
static void hol__queue_push_dyn(hol_render *r, int pass, uint32_t i0, uint32_t sub,
                                const float model[16])
{
    hol__item *it = hol__queue_push(r, pass, i0, r->dyn.ni - i0);
    if (!it)
        return;
    it->key = (uint32_t)pass << 24 | sub;
    it->dyn = 1;
    if (model)
        memcpy(it->model, model, sizeof it->model);
}

/* Pass 0 of the queue: one stencil polygon per leaf, in NDC. */
static hol_err hol__queue_leaves(hol_render *r, const hol_frame_desc *f)
{
    const hol_view *v = &r->view;
    for (int k = 0; k < v->nleaves; k++) {
        float xy[8][2], *box = r->leaf_box[k];
        int n = hol_view_leaf_ndc(&f->cam, &v->leaves[k], xy);
        box[0] = box[1] = 1; /* empty: off screen */
        box[2] = box[3] = -1;
        if (n < 3)
            continue;
        for (int i = 0; i < n; i++)
            hol__box_add(box, xy[i][0], xy[i][1]);
        int64_t b = hol_mesh_reserve(&r->dyn, (uint32_t)n, (uint32_t)(3 * (n - 2)));
        if (b < 0)
            return HOL_ENOMEM;
        uint32_t i0 = r->dyn.ni;
        for (int i = 0; i < n; i++) {
            hol_vertex *vx = &r->dyn.v[r->dyn.nv++];
            memset(vx, 0, sizeof *vx);
            vx->pos[0] = xy[i][0];
            vx->pos[1] = xy[i][1];
        }
        for (int i = 1; i + 1 < n; i++) {
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b;
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b + (uint32_t)i;
            r->dyn.idx[r->dyn.ni++] = (uint32_t)b + (uint32_t)i + 1;
        }
        hol__item *it = hol__queue_push(r, HOL__PASS_STENCIL, i0, r->dyn.ni - i0);
        if (!it)
            return HOL_ENOMEM;
        it->dyn = 1;
        it->ref = v->leaves[k].code;
        it->mask = 0xff;
        it->key = (uint32_t)k;
    }
    return HOL_OK;
}

/* Pass 1: the room's own meshes, resident while the user's state and the
 * world stay the same. */
static hol_err hol__queue_room(hol_render *r, const hol_frame_desc *f, double cell_m)
{
    int tree[3] = {f->tree_marked != 0, f->tree_marked ? f->tree_vertex[0] : 0,
                   f->tree_marked ? f->tree_vertex[1] : 0};
    if (!r->room_valid || r->room_world != r->desc.world || r->room_cell != cell_m ||
        memcmp(&r->room_user, &f->user, sizeof f->user) || memcmp(r->room_tree, tree, sizeof tree)) {
        hol_mesh_clear(&r->scratch);
        hol_scene_room(r->scene, &r->scratch, &f->user, r->desc.world, cell_m, r->room_back);
        if (tree[0])
            hol_scene_tree_mark(r->scene, &r->scratch, tree[1], tree[2], cell_m);
        memcpy(r->room_tree, tree, sizeof tree);
        if (r->scratch.overflow)
            return HOL_ENOMEM;
        hol__upload_scratch(r, 0, 0);
        r->room_nidx = r->scratch.ni;
        r->room_user = f->user;
        r->room_cell = cell_m;
        r->room_world = r->desc.world;
        r->room_valid = 1;
    }
    if (!f->lighting) { /* day: one draw */
        hol__item *it = hol__queue_push(r, HOL__PASS_ROOM, 0, r->room_nidx);
        if (it)
            it->key = 1u << 24;
        return HOL_OK;
    }
    /* dusk and night: the trees and hedges lantern-lit (per vertex at
     * knot heights: scene.vert.glsl), then the backdrop and outer ground
     * on the cheaper program, behind the hedges: the depth test spares
     * llvmpipe shading what the hedges hide */
    const uint32_t cut[3][2] = {{0, r->room_back[0]},
                                {r->room_back[1], r->room_nidx},
                                {r->room_back[0], r->room_back[1]}};
    for (int k = 0; k < 3; k++) {
        hol__item *it = hol__queue_push(r, HOL__PASS_ROOM, cut[k][0], cut[k][1] - cut[k][0]);
        if (it) {
            it->key = 1u << 24 | (uint32_t)k;
            it->lamps = k != 2;
        }
    }
    return HOL_OK;
}

/* The body (hol_frame_desc.body): built in room coordinates (once while
 * it stays the same: both eyes of a frame share it), copied into the
 * frame's dynamic geometry, drawn in the room's pass after its meshes. */
static hol_err hol__queue_body(hol_render *r, const hol_frame_desc *f)
{
    uint64_t key = hol__fnv(0xcbf29ce484222325ull, f->body, sizeof *f->body);
    if (!r->body_valid || r->body_key != key) {
        hol_mesh_clear(&r->body);
        hol_body_build(&r->body, f->body);
        r->body_valid = !r->body.overflow;
        r->body_key = key;
        if (r->body.overflow)
            return HOL_ENOMEM;
    }
    int64_t b = hol_mesh_reserve(&r->dyn, r->body.nv, r->body.ni);
    if (b < 0)
        return HOL_ENOMEM;
    uint32_t i0 = r->dyn.ni;
    memcpy(r->dyn.v + b, r->body.v, r->body.nv * sizeof r->body.v[0]);
    r->dyn.nv += r->body.nv;
    for (uint32_t i = 0; i < r->body.ni; i++)
        r->dyn.idx[r->dyn.ni++] = (uint32_t)b + r->body.idx[i];
    hol__queue_push_dyn(r, HOL__PASS_ROOM, i0, 1, NULL);
    return HOL_OK;
}

/* The fade: one screen quad, blended by the constant alpha f->fade. */
static hol_err hol__queue_fade(hol_render *r, const hol_frame_desc *f)
{
    uint8_t rgb[3];
    hol__fade_rgb(f, rgb);
    int64_t b = hol_mesh_reserve(&r->dyn, 4, 6);
    if (b < 0)
        return HOL_ENOMEM;
    uint32_t i0 = r->dyn.ni;
    static const float q[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; i++) {
        hol_vertex *vx = &r->dyn.v[r->dyn.nv++];
        memset(vx, 0, sizeof *vx);
        vx->pos[0] = q[i][0];
        vx->pos[1] = q[i][1];
        memcpy(vx->rgba, rgb, 3);
        vx->rgba[3] = 255;
    }
    static const uint32_t tri[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++)
        r->dyn.idx[r->dyn.ni++] = (uint32_t)b + tri[i];
    hol__item *it = hol__queue_push(r, HOL__PASS_FADE, i0, 6);
    if (!it)
        return HOL_ENOMEM;
    it->key = (uint32_t)HOL__PASS_FADE << 24;
    it->dyn = 1;
    return HOL_OK;
}

/* Outside the room: a flat arrow on the floor (hol_frame_desc.outside),
 * in the panel's pass (over all): a shaft and a head, in room metres. */
static hol_err hol__queue_floor_arrow(hol_render *r, const hol_frame_desc *f)
{
    static const uint8_t rgb[3] = HOL_RENDER_ARROW_RGB;
    /* along the arrow (a) and across it (c), from its centre */
    static const float pts[7][2] = {{-0.5f, -0.09f}, {0.1f, -0.09f}, {0.1f, -0.25f},
                                    {0.5f, 0},       {0.1f, 0.25f},  {0.1f, 0.09f},
                                    {-0.5f, 0.09f}};
    static const uint32_t tri[9] = {0, 1, 5, 0, 5, 6, 2, 3, 4};
    int64_t b = hol_mesh_reserve(&r->dyn, 7, 9);
    if (b < 0)
        return HOL_ENOMEM;
    uint32_t i0 = r->dyn.ni;
    double y = f->outside_yaw_deg * 3.14159265358979323846 / 180, len = HOL_RENDER_ARROW_M;
    double ax = -sin(y), az = -cos(y), cx = -az, cz = ax; /* forward, right */
    for (int i = 0; i < 7; i++) {
        hol_vertex *vx = &r->dyn.v[r->dyn.nv++];
        memset(vx, 0, sizeof *vx);
        vx->pos[0] = (float)(f->outside_arrow[0] + len * (pts[i][0] * ax + pts[i][1] * cx));
        vx->pos[1] = (float)(f->outside_arrow[1] + 0.02);
        vx->pos[2] = (float)(f->outside_arrow[2] + len * (pts[i][0] * az + pts[i][1] * cz));
        memcpy(vx->rgba, rgb, 3); /* alpha 0: opaque, no glyph (HOL_MESH_GLYPH) */
    }
    for (int i = 0; i < 9; i++)
        r->dyn.idx[r->dyn.ni++] = (uint32_t)b + tri[i];
    hol__queue_push_dyn(r, HOL__PASS_PANEL, i0, 0, NULL);
    return HOL_OK;
}

/* What the resident minimap is a function of: the user's state, the
 * objectives, the path, the marks, where it is (hand or HUD) and the HUD's
 * size. */
static uint64_t hol__map_key(const hol_frame_desc *f, int hand)
{
    uint64_t key = 0xcbf29ce484222325ull;
    int nobj = f->nobjectives < 0 ? 0 : f->nobjectives > HOL_RENDER_MAX_OBJECTIVES
                                            ? HOL_RENDER_MAX_OBJECTIVES : f->nobjectives;
    key = hol__fnv(key, &f->user, sizeof f->user);
    key = hol__fnv(key, &nobj, sizeof nobj);
    key = hol__fnv(key, f->objectives, (size_t)nobj * sizeof f->objectives[0]);
    key = hol__fnv(key, &f->npath, sizeof f->npath);
    if (f->path && f->npath > 0)
        key = hol__fnv(key, f->path, (size_t)f->npath);
    key = hol__fnv(key, &hand, sizeof hand);
    int nm = f->nmarks < 0 ? 0 : f->nmarks > HOL_RENDER_MAX_MARKS ? HOL_RENDER_MAX_MARKS
                                                                  : f->nmarks;
    key = hol__fnv(key, &nm, sizeof nm);
    key = hol__fnv(key, f->marks, (size_t)nm * sizeof f->marks[0]);
    if (!hand) {
        key = hol__fnv(key, &f->cam.width, sizeof f->cam.width);
        key = hol__fnv(key, &f->cam.height, sizeof f->cam.height);
    }
    return key;
}

/* The minimap (on the HUD or in the hand; resident while its inputs stay
 * the same) and the live part: the user's arrow and the text. */
/* The headset's panel: the text block and, unless the map is in the hand,
 * the resident map (the hand's square layout) and the user's arrow beside
 * it, each a quad placed in the panel's plane (render/hol_hud.h). */
static hol_err hol__queue_panel(hol_render *r, const hol_frame_desc *f)
{
    if (f->flags & HOL_RENDER_PANEL_LAYER)
        return HOL_OK; /* the runtime shows it (hol_render_panel_image) */
    int map = (f->flags & HOL_RENDER_MINIMAP) && !(f->flags & HOL_RENDER_MINIMAP_HAND);
    double px = f->panel_px > 0 ? f->panel_px : HOL_RENDER_PANEL_PX;
    double wide = HOL_HUD_PANEL_W + (map ? HOL_HUD_PANEL_GAP + HOL_HUD_PANEL_MAP : 0);
    double left = -wide / 2, top = HOL_HUD_PANEL_MAP / 2;
    uint32_t i0 = r->dyn.ni;
    float wh[2];
    hol_hud_build_panel_text(&r->dyn, f, wh);
    float tm[16];
    hol__quad_matrix(f->panel_pos, f->panel_orient, wh[0] / 2 * px, wh[1] / 2 * px,
                     (left + wh[0] / 2) * px, (top - wh[1] / 2) * px, tm);
    hol__queue_push_dyn(r, HOL__PASS_PANEL, i0, 2, tm);
    if (!map)
        return HOL_OK;
    float m[16];
    double half = HOL_HUD_PANEL_MAP / 2;
    hol__quad_matrix(f->panel_pos, f->panel_orient, half * px, half * px,
                     (left + HOL_HUD_PANEL_W + HOL_HUD_PANEL_GAP + half) * px, 0, m);
    hol__item *mi = hol__queue_push(r, HOL__PASS_PANEL, HOL__HUD_IBASE, r->hud_nidx);
    if (mi) {
        mi->key = (uint32_t)HOL__PASS_PANEL << 24;
        memcpy(mi->model, m, sizeof m);
    }
    i0 = r->dyn.ni;
    hol_hud_build_hand_arrow(&r->dyn, f);
    hol__queue_push_dyn(r, HOL__PASS_PANEL, i0, 1, m);
    return HOL_OK;
}

/* The HUD text alone (the minimap off). */
static hol_err hol__queue_text(hol_render *r, const hol_frame_desc *f)
{
    uint32_t i0 = r->dyn.ni;
    hol_hud_build_text(&r->dyn, f, f->cam.width, f->cam.height);
    hol__queue_push_dyn(r, HOL__PASS_HUD, i0, 1, NULL);
    return HOL_OK;
}

hol_err hol__queue_hud(hol_render *r, const hol_frame_desc *f)
{
    int panel = (f->flags & HOL_RENDER_PANEL) != 0;
    /* the map's square layout: in the hand, or on the headset's panel */
    if (panel && !(f->flags & HOL_RENDER_MINIMAP))
        return hol__queue_panel(r, f); /* the text alone */
    int hand = (f->flags & HOL_RENDER_MINIMAP_HAND) != 0 || panel;
    uint64_t key = hol__map_key(f, hand);
    if (!r->hud_valid || r->hud_key != key) {
        hol_mesh_clear(&r->scratch);
        r->scratch.cap_v = HOL__HUD_V;
        r->scratch.cap_i = HOL__HUD_I;
        if (hand)
            hol_hud_build_hand_map(&r->scratch, f);
        else
            hol_hud_build_map(&r->scratch, f, f->cam.width, f->cam.height);
        r->scratch.cap_v = HOL__ROOM_V;
        r->scratch.cap_i = HOL__ROOM_I;
        if (r->scratch.overflow)
            return HOL_ENOMEM;
        hol__upload_scratch(r, HOL__HUD_VBASE, HOL__HUD_IBASE);
        r->hud_nidx = r->scratch.ni;
        r->hud_key = key;
        r->hud_valid = 1;
    }
    if (panel && !(f->flags & HOL_RENDER_MINIMAP_HAND))
        return hol__queue_panel(r, f);
    int map_pass = hand ? HOL__PASS_HAND : HOL__PASS_HUD;
    float hand_m[16];
    if (hand)
        hol__hand_matrix(f, hand_m);
    hol__item *map = hol__queue_push(r, map_pass, HOL__HUD_IBASE, r->hud_nidx);
    if (map) {
        map->key = (uint32_t)map_pass << 24;
        if (hand)
            memcpy(map->model, hand_m, sizeof hand_m);
    }
    uint32_t i0 = r->dyn.ni;
    if (hand) {
        hol_hud_build_hand_arrow(&r->dyn, f);
        hol__queue_push_dyn(r, HOL__PASS_HAND, i0, 1, hand_m);
        if (panel) /* the map in the hand, the text on the panel */
            return hol__queue_panel(r, f);
        return hol__queue_text(r, f);
    }
    hol_hud_build_live(&r->dyn, f, f->cam.width, f->cam.height);
    hol__queue_push_dyn(r, HOL__PASS_HUD, i0, 1, NULL);
    return HOL_OK;
}

/* Build the queue of a frame: the view, then each pass's items. */
hol_err hol__build(hol_render *r, const hol_frame_desc *f)
{
    int eu = (f->flags & HOL_RENDER_EUCLIDEAN) != 0;
    int bare = (f->flags & HOL_RENDER_BARE) != 0;
    double m = f->cell_m > 0 ? f->cell_m : 1.0;
    if (!(m >= 0.5 && m <= 1.5))
        return HOL_EARG;
    /* the view from the eye; an eye outside the room (f->outside) from
     * its nearest point in the user's cell, a hair inside it */
    memcpy(r->view_at, f->cam.eye, sizeof r->view_at);
    if (f->outside) {
        const double in = 1e-3, lo[2] = {f->user.col + in, f->user.row + in};
        for (int k = 0; k < 2; k++) {
            double v = f->cam.eye[2 * k] / m;
            v = v < lo[k] ? lo[k] : v > lo[k] + 1 - 2 * in ? lo[k] + 1 - 2 * in : v;
            r->view_at[2 * k] = v * m;
        }
    }
    hol_err err = hol_view_build(&f->user, r->view_at[0] / m, r->view_at[2] / m, eu, &r->view);
    if (err)
        return err;
    if (f->lighting && (err = hol_light_prepare(f, r->desc.world, &r->lights)))
        return err;
    if (f->lighting)
        hol_light_budget(&r->lights, &r->view);
    hol_mesh_clear(&r->dyn);
    r->nitems = 0;
    r->frame++;
    r->uploaded = 0;
    r->tiles_built = 0;
    if (!r->view.wedges && (err = hol__queue_leaves(r, f)))
        return err;
    if (!bare && (err = hol__queue_room(r, f, m)))
        return err;
    if (!bare && f->body && (err = hol__queue_body(r, f)))
        return err;
    if ((err = hol__queue_tiles(r, f, bare, m)))
        return err;
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    if ((f->fade > 0 || f->outside) && !ids && (err = hol__queue_fade(r, f)))
        return err;
    if (f->outside && !ids && (err = hol__queue_floor_arrow(r, f)))
        return err;
    if (!(f->flags & HOL_RENDER_NO_HUD)) {
        if (f->flags & (HOL_RENDER_MINIMAP | HOL_RENDER_PANEL))
            err = hol__queue_hud(r, f);
        else if (f->flags & HOL_RENDER_HUD_TEXT)
            err = hol__queue_text(r, f);
        if (err)
            return err;
    }
    return r->dyn.overflow ? HOL_ENOMEM : HOL_OK;
}
