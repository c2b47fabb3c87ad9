/* hol_render.c - the renderer's API: create, a frame, the panel's image,
 * read back (render/hol_render_int.h: which file does what). */
#include "hol_render.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../core/hol_face.h"
#include "hol_hud.h"
#include "hol_render_int.h"

/* The text face's atlas (core/hol_face.h) as one R8 texture: linear,
 * clamped, rows of one byte aligned to 1 (WebGL 2's default is 4). Its
 * bytes are written into the vertex store, which holds nothing yet (every
 * mesh is written before it is drawn). */
static void hol__make_atlas(hol_render *r)
{
    int w, h;
    uint8_t *px = (uint8_t *)r->verts;
    hol_face_atlas(NULL, &w, &h);
    if ((size_t)w * (size_t)h > (HOL__DYN_V + HOL__ROOM_V) * sizeof *r->verts)
        return; /* never: the atlas is 60 KB, the store megabytes */
    hol_face_atlas(px, &w, &h);
    r->gl.GenTextures(1, &r->atlas);
    r->gl.ActiveTexture(GL_TEXTURE0);
    r->gl.BindTexture(GL_TEXTURE_2D, r->atlas);
    r->gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    r->gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R8, w, h, 0, GL_RED, GL_UNSIGNED_BYTE, px);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    r->gl.BindTexture(GL_TEXTURE_2D, 0);
}

/* Compile the program of slot k (render/hol_program.h); 0 ok. */
static int hol__make_slot(hol_render *r, int k)
{
    hol_prog_key key = hol_prog_key_of_slot(k);
    return hol_prog_make(&r->gl, &key, &r->progs[k]);
}

int hol_render_prepare(hol_render *r)
{
    int left = 0, made = 0;
    for (int k = 0; k < HOL_PROG_SLOTS; k++) {
        if (r->progs[k].prog)
            continue;
        if (!made) {
            made = 1;
            if (hol__make_slot(r, k))
                return -1;
            continue;
        }
        left++;
    }
    return left;
}

hol_err hol_render_create(const hol_render_desc *desc, hol_render **out)
{
    hol_render_desc d;
    memset(&d, 0, sizeof d);
    if (desc)
        d = *desc;
    hol_render *r = hol_alloc_mem(&d.alloc, sizeof *r);
    if (!r)
        return HOL_ENOMEM;
    memset(r, 0, sizeof *r);
    r->desc = d;
    /* the CPU-side stores: dynamic + scratch */
    r->verts = hol_alloc_mem(&d.alloc, (HOL__DYN_V + HOL__ROOM_V) * sizeof *r->verts);
    r->idx = hol_alloc_mem(&d.alloc, (HOL__DYN_I + HOL__ROOM_I) * sizeof *r->idx);
    if (!r->verts || !r->idx || hol_scene_create(&d.alloc, &r->scene)) {
        hol_alloc_release(&d.alloc, r->verts);
        hol_alloc_release(&d.alloc, r->idx);
        hol_alloc_release(&d.alloc, r);
        return HOL_ENOMEM;
    }
    hol_mesh_init(&r->dyn, r->verts, HOL__DYN_V, r->idx, HOL__DYN_I);
    hol_mesh_init(&r->scratch, r->verts + HOL__DYN_V, HOL__ROOM_V, r->idx + HOL__DYN_I,
                  HOL__ROOM_I);
    hol_mesh_init(&r->body, r->body_v, HOL__BODY_V, r->body_i, HOL__BODY_I);
    hol_err gerr = hol_gl_load(&r->gl, r->desc.getproc);
    if (gerr) {
        hol_alloc_release(&d.alloc, r->verts);
        hol_alloc_release(&d.alloc, r->idx);
        hol_scene_destroy(&d.alloc, r->scene);
        hol_alloc_release(&d.alloc, r);
        return gerr;
    }
    /* the day program now (it proves the GL compiles the shaders); the
     * others when a frame first uses one (hol__use_progs), or all now
     * (desc.all_programs), or by hol_render_prepare */
    int bad = hol__make_slot(r, 0); /* day, no wedge */
    for (int k = 1; k < HOL_PROG_SLOTS && d.all_programs; k++)
        bad = bad || hol__make_slot(r, k);
    if (bad) {
        hol_render_destroy(r);
        return HOL_EUNSUPPORTED;
    }
    r->pg = &r->progs[0];
    r->gl.GenVertexArrays(2, r->vao);
    r->gl.GenBuffers(1, &r->vbo[1]);
    r->gl.GenBuffers(1, &r->ibo[1]);
    r->gl.BindVertexArray(r->vao[1]);
    r->gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo[1]);
    hol__vao_attribs(r, 1);
    hol__static_grow(r, d.all_programs ? HOL__SLOTS : HOL__SLOTS_FIRST);
    hol__make_atlas(r);
    if (r->gl.GetError() != GL_NO_ERROR) {
        hol_render_destroy(r);
        return HOL_EUNSUPPORTED;
    }
    *out = r;
    return HOL_OK;
}

void hol_render_destroy(hol_render *r)
{
    if (!r)
        return;
    for (int k = 0; k < HOL_PROG_SLOTS; k++)
        if (r->progs[k].prog)
            r->gl.DeleteProgram(r->progs[k].prog);
    if (r->vao[0])
        r->gl.DeleteVertexArrays(2, r->vao);
    if (r->atlas)
        r->gl.DeleteTextures(1, &r->atlas);
    if (r->shm)
        r->gl.DeleteTextures(1, &r->shm);
    if (r->vbo[0])
        r->gl.DeleteBuffers(2, r->vbo);
    if (r->ibo[0])
        r->gl.DeleteBuffers(2, r->ibo);
    hol_alloc d = r->desc.alloc;
    hol_scene_destroy(&d, r->scene);
    hol_alloc_release(&d, r->verts);
    hol_alloc_release(&d, r->idx);
    hol_alloc_release(&d, r);
}

void hol_render_set_world(hol_render *r, struct hol_world *world)
{
    r->desc.world = world;
    hol_render_invalidate(r);
}

void hol_render_invalidate(hol_render *r)
{
    for (int i = 0; i < HOL__SLOTS; i++)
        r->slots[i].used = 0;
    r->room_valid = 0;
    r->hud_valid = 0;
    r->body_valid = 0;
}

const hol_view *hol_render_last_view(const hol_render *r)
{
    return &r->view;
}

static int hol__cmp_item(const void *a, const void *b)
{
    const hol__item *x = *(const hol__item *const *)a, *y = *(const hol__item *const *)b;
    return x->key < y->key ? -1 : x->key > y->key;
}

static double hol__now(clockid_t id)
{
    struct timespec ts = {0, 0}; /* stays zero where the clock is missing (wasm) */
    clock_gettime(id, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

hol_err hol_render_frame(hol_render *r, const hol_frame_desc *f,
                         hol_render_stats *out_stats)
{
    double c0 = hol__now(CLOCK_PROCESS_CPUTIME_ID), w0 = hol__now(CLOCK_MONOTONIC);
    int maxw = r->desc.max_width > 0 ? r->desc.max_width : 4096;
    int maxh = r->desc.max_height > 0 ? r->desc.max_height : 4096;
    if (f->cam.width <= 0 || f->cam.height <= 0 || f->cam.width > maxw ||
        f->cam.height > maxh)
        return HOL_EARG;
    hol_render_stats st;
    memset(&st, 0, sizeof st);
    if (f->fade >= 1 && !(f->flags & HOL_RENDER_IDS)) {
        hol__frame_faded(r, f);
        hol_err err = r->desc.debug ? hol_render_check(r) : HOL_OK;
        if (f->flags & HOL_RENDER_WAIT)
            r->gl.Finish();
        st.cpu_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
        st.wall_ms = hol__now(CLOCK_MONOTONIC) - w0;
        if (out_stats)
            *out_stats = st;
        return err;
    }
    hol_err err = hol__build(r, f);
    if (!err)
        err = hol__use_progs(r, f);
    if (err)
        return err;
    for (int i = 0; i < r->nitems; i++)
        r->sorted[i] = &r->items[i];
    qsort(r->sorted, (size_t)r->nitems, sizeof r->sorted[0], hol__cmp_item);
    st.build_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    float vp[16];
    hol__frame_begin(r, f, vp);
    st.state_changes += 2;
    hol__execute(r, f, vp, &st);
    r->gl.Disable(GL_BLEND);
    r->gl.BindVertexArray(0);
    r->gl.Disable(GL_SCISSOR_TEST);
    if (f->flags & HOL_RENDER_WAIT)
        r->gl.Finish(); /* the figures include the GPU's time */
    st.cpu_ms = hol__now(CLOCK_PROCESS_CPUTIME_ID) - c0;
    st.uploaded_bytes = r->uploaded;
    st.tiles_built = r->tiles_built;
    st.wall_ms = hol__now(CLOCK_MONOTONIC) - w0;
    if (r->desc.debug && hol_render_check(r))
        return HOL_EUNSUPPORTED;
    if (out_stats)
        *out_stats = st;
    return HOL_OK;
}

/* The panel alone (hol_render_panel_key, _image): g is f with the panel
 * at the origin, unturned, the map beside the text or none (a map in the
 * hand is not the panel's), queued into the dynamic mesh. */
static hol_err hol__queue_panel_only(hol_render *r, const hol_frame_desc *f, hol_frame_desc *g)
{
    *g = *f;
    uint32_t keep = HOL_RENDER_MINIMAP | HOL_RENDER_NO_HOT_COLD | HOL_RENDER_NO_ARROW;
    g->flags = (f->flags & keep) | HOL_RENDER_PANEL;
    if (f->flags & HOL_RENDER_MINIMAP_HAND)
        g->flags &= ~(uint32_t)HOL_RENDER_MINIMAP;
    memset(g->panel_pos, 0, sizeof g->panel_pos);
    /* the image is the box whatever its size in metres: a panel nearer in
     * front of a hedge (scaled, core/hol_panel.h) keeps its key and image */
    g->panel_px = 0;
    static const double unturned[4] = {0, 0, 0, 1};
    memcpy(g->panel_orient, unturned, sizeof unturned);
    g->lighting = 0;
    g->fade = 0;
    hol_mesh_clear(&r->dyn);
    r->nitems = 0;
    hol_err err = hol__queue_hud(r, g);
    return err ? err : r->dyn.overflow ? HOL_ENOMEM : HOL_OK;
}

uint64_t hol_render_panel_key(hol_render *r, const hol_frame_desc *f)
{
    hol_frame_desc g;
    uint64_t key = 0xcbf29ce484222325ull;
    if (hol__queue_panel_only(r, f, &g))
        return key; /* an overflow draws nothing: never equal to a drawn key */
    key = hol__fnv(key, &g.flags, sizeof g.flags);
    key = hol__fnv(key, &g.panel_px, sizeof g.panel_px);
    key = hol__fnv(key, r->dyn.v, r->dyn.nv * sizeof r->dyn.v[0]);
    key = hol__fnv(key, r->dyn.idx, r->dyn.ni * sizeof r->dyn.idx[0]);
    for (int i = 0; i < r->nitems; i++) {
        key = hol__fnv(key, r->items[i].model, sizeof r->items[i].model);
        key = hol__fnv(key, &r->items[i].count, sizeof r->items[i].count);
    }
    if (g.flags & HOL_RENDER_MINIMAP)
        key = hol__fnv(key, &r->hud_key, sizeof r->hud_key);
    return key ^ 1; /* never the overflow's */
}

hol_err hol_render_panel_image(hol_render *r, const hol_frame_desc *f, int w, int h)
{
    int maxw = r->desc.max_width > 0 ? r->desc.max_width : 4096;
    int maxh = r->desc.max_height > 0 ? r->desc.max_height : 4096;
    if (w <= 0 || h <= 0 || w > maxw || h > maxh)
        return HOL_EARG;
    hol_frame_desc g;
    hol_err err = hol__queue_panel_only(r, f, &g);
    if (!err)
        err = hol__use_progs(r, &g);
    if (err)
        return err;
    for (int i = 0; i < r->nitems; i++)
        r->sorted[i] = &r->items[i];
    qsort(r->sorted, (size_t)r->nitems, sizeof r->sorted[0], hol__cmp_item);
    g.cam.width = w;
    g.cam.height = h;
    g.vp_x = g.vp_y = 0;
    float vp[16];
    hol__frame_begin(r, &g, vp); /* uploads the text; clears to the sky */
    r->gl.ClearColor(0, 0, 0, 0);
    r->gl.Clear(GL_COLOR_BUFFER_BIT);
    /* the box (panel plane, metres) onto the whole image */
    double box[4];
    hol_hud_panel_box((g.flags & HOL_RENDER_MINIMAP) != 0, g.panel_px, box);
    memset(vp, 0, sizeof vp);
    vp[0] = (float)(2 / box[0]);
    vp[5] = (float)(2 / box[1]);
    vp[10] = 1;
    vp[12] = (float)(-2 * box[2] / box[0]);
    vp[13] = (float)(-2 * box[3] / box[1]);
    vp[15] = 1;
    hol_render_stats st;
    memset(&st, 0, sizeof st);
    hol__execute(r, &g, vp, &st);
    r->gl.Disable(GL_BLEND);
    r->gl.BindVertexArray(0);
    r->gl.Disable(GL_SCISSOR_TEST);
    return r->desc.debug ? hol_render_check(r) : HOL_OK;
}

void hol_render_read_rgba(hol_render *r, int w, int h, uint8_t *out_rgba)
{
    r->gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    r->gl.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, out_rgba);
    size_t row = (size_t)w * 4;
    uint8_t tmp[4 * 1024];
    for (int y = 0; y < h / 2; y++) {
        uint8_t *a = out_rgba + (size_t)y * row, *b = out_rgba + (size_t)(h - 1 - y) * row;
        for (size_t o = 0; o < row; o += sizeof tmp) {
            size_t n = row - o < sizeof tmp ? row - o : sizeof tmp;
            memcpy(tmp, a + o, n);
            memcpy(a + o, b + o, n);
            memcpy(b + o, tmp, n);
        }
    }
}

int hol_render_decode_id(const uint8_t rgba[4])
{
    return (int)rgba[0] + 256 * (int)rgba[1] - 1;
}

hol_err hol_render_check(hol_render *r)
{
    int bad = 0;
    /* every error flag the GL holds (at most a few: one per kind) */
    for (int i = 0; i < 8 && r->gl.GetError() != GL_NO_ERROR; i++)
        bad = 1;
    return bad ? HOL_EUNSUPPORTED : HOL_OK;
}
