/* hol_render_gpu.c - the renderer's GL side: buffers, a frame's programs,
 * clear and uniforms, the passes' state, the sorted queue executed. */
#include "hol_render_int.h"

#include <math.h>
#include <string.h>

/* The vertex layout of vao[k] (bound), read from vbo[k]. */
void hol__vao_attribs(hol_render *r, int k)
{
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[k]);
    r->gl.EnableVertexAttribArray(0);
    r->gl.EnableVertexAttribArray(1);
    r->gl.EnableVertexAttribArray(2);
    r->gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, pos));
    r->gl.VertexAttribPointer(1, 3, GL_BYTE, GL_TRUE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, nrm));
    r->gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, rgba));
    /* a glyph's atlas point in the normal's bytes (the text program's) */
    r->gl.EnableVertexAttribArray(3);
    r->gl.VertexAttribPointer(3, 2, GL_UNSIGNED_SHORT, GL_TRUE, sizeof(hol_vertex),
                              (const void *)offsetof(hol_vertex, nrm));
}

/* A new buffer of new_bytes for target (bound first to it: WebGL 2 fixes a
 * buffer's type at its first binding, and one first bound to a copy
 * target can never be an element array), old's first old_bytes copied in
 * (old 0: none), old deleted. Leaves target unbound. */
static GLuint hol__buffer_grown(hol_render *r, GLenum target, GLuint old, size_t old_bytes,
                                size_t new_bytes)
{
    GLuint b = 0;
    r->gl.GenBuffers(1, &b);
    r->gl.BindBuffer(target, b);
    r->gl.BufferData(target, (GLsizeiptr)new_bytes, NULL, GL_DYNAMIC_DRAW);
    if (old) {
        r->gl.BindBuffer(GL_COPY_READ_BUFFER, old);
        r->gl.CopyBufferSubData(GL_COPY_READ_BUFFER, target, 0, 0, (GLsizeiptr)old_bytes);
        r->gl.BindBuffer(GL_COPY_READ_BUFFER, 0);
        r->gl.DeleteBuffers(1, &old);
    }
    r->gl.BindBuffer(target, 0);
    return b;
}

/* The static buffers (the room, the minimap, then the tile slots) made
 * for cap slots: new ones, what the old ones held copied in, vao[0]
 * pointed at them. Leaves no vertex array bound. */
void hol__static_grow(hol_render *r, int cap)
{
    r->gl.BindVertexArray(0); /* the element binding below is vertex array 0's */
    r->vbo[0] = hol__buffer_grown(r, GL_ARRAY_BUFFER, r->vbo[0],
                                  HOL__SLOT_VBASE(r->slot_cap) * sizeof(hol_vertex),
                                  HOL__SLOT_VBASE(cap) * sizeof(hol_vertex));
    r->ibo[0] = hol__buffer_grown(r, GL_ELEMENT_ARRAY_BUFFER, r->ibo[0],
                                  HOL__SLOT_IBASE(r->slot_cap) * sizeof(uint32_t),
                                  HOL__SLOT_IBASE(cap) * sizeof(uint32_t));
    r->slot_cap = cap;
    r->gl.BindVertexArray(r->vao[0]);
    r->gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, r->ibo[0]);
    hol__vao_attribs(r, 0);
    r->gl.BindVertexArray(0);
}

/* Upload the scratch mesh to the static buffers at (vbase, ibase), its
 * indices shifted by vbase. */
void hol__upload_scratch(hol_render *r, uint32_t vbase, uint32_t ibase)
{
    hol_mesh *m = &r->scratch;
    for (uint32_t i = 0; i < m->ni; i++)
        m->idx[i] += vbase;
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[0]);
    r->gl.BufferSubData(GL_ARRAY_BUFFER, (GLintptr)(vbase * sizeof(hol_vertex)),
                        (GLsizeiptr)(m->nv * sizeof(hol_vertex)), m->v);
    r->gl.BindVertexArray(r->vao[0]);
    r->gl.BufferSubData(GL_ELEMENT_ARRAY_BUFFER, (GLintptr)(ibase * sizeof(uint32_t)),
                        (GLsizeiptr)(m->ni * sizeof(uint32_t)), m->idx);
    r->gl.BindVertexArray(0);
    r->uploaded += (long)(m->nv * sizeof(hol_vertex) + m->ni * sizeof(uint32_t));
}

/* An sRGB-authored colour's linear light (the sRGB formula). */
static float hol__srgb_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

/* glClearColor of an sRGB-authored colour: with desc.srgb the GL encodes
 * what is written, so the colour is given linear (as the shader does). */
static void hol__clear_colour(hol_render *r, float red, float green, float blue)
{
    float c[3] = {red, green, blue};
    for (int k = 0; k < 3 && r->desc.srgb; k++)
        c[k] = hol__srgb_linear(c[k]);
    r->gl.ClearColor(c[0], c[1], c[2], 1);
}

void hol__fade_rgb(const hol_frame_desc *f, uint8_t out[3])
{
    static const uint8_t def[3] = HOL_RENDER_FADE_RGB, dim[3] = HOL_RENDER_OUTSIDE_RGB;
    int set = f->fade_rgb[0] || f->fade_rgb[1] || f->fade_rgb[2];
    memcpy(out, f->outside ? dim : set ? f->fade_rgb : def, 3);
}

/* The frame's rectangle: viewport, and the scissor its clear keeps to. */
static void hol__viewport(hol_render *r, const hol_frame_desc *f)
{
    r->gl.Viewport(f->vp_x, f->vp_y, f->cam.width, f->cam.height);
    r->gl.Enable(GL_SCISSOR_TEST);
    r->gl.Scissor(f->vp_x, f->vp_y, f->cam.width, f->cam.height);
}

/* Fully faded: the boundary colour alone, no view. */
void hol__frame_faded(hol_render *r, const hol_frame_desc *f)
{
    uint8_t rgb[3];
    hol__fade_rgb(f, rgb);
    hol__viewport(r, f);
    r->gl.DepthMask(GL_TRUE);
    r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    r->gl.StencilMask(0xff);
    hol__clear_colour(r, rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f);
    r->gl.ClearDepthf(1.0f);
    r->gl.ClearStencil(HOL_VIEW_STENCIL_CLEAR);
    r->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    r->gl.Disable(GL_SCISSOR_TEST);
}

/* A lit frame's sky between dusk (0) and night (1). */
static float hol__night(const hol_frame_desc *f)
{
    if (!f->cycle)
        return f->lighting == HOL_LIGHT_NIGHT ? 1.0f : 0.0f;
    return f->night <= 0 ? 0.0f : f->night >= 1 ? 1.0f : (float)f->night;
}

/* The programs' lighting: day, dusk or night, or between them (a cycle's
 * 0 and 1 take dusk's and night's own programs). */
static int hol__sky_key(const hol_frame_desc *f)
{
    if (!f->lighting || !f->cycle)
        return f->lighting;
    float u = hol__night(f);
    return u <= 0 ? HOL_LIGHT_DUSK : u >= 1 ? HOL_LIGHT_NIGHT : HOL_PROG_CYCLE;
}

/* The sky of a frame's lighting (day: hol_scene_sky) and its fog density
 * per metre. */
static float hol__sky(const hol_frame_desc *f, float rgb[3])
{
    static const float skies[3][3] = {{0, 0, 0}, {0.46f, 0.36f, 0.44f}, {0.03f, 0.04f, 0.08f}};
    if (f->lighting == HOL_LIGHT_DUSK || f->lighting == HOL_LIGHT_NIGHT) {
        /* a * (1 - u) + b * u: exactly a at 0 and b at 1 */
        float u = hol__night(f);
        for (int i = 0; i < 3; i++)
            rgb[i] = skies[1][i] * (1 - u) + skies[2][i] * u;
        return 0.10f * (1 - u) + 0.15f * u;
    }
    hol_scene_sky(rgb);
    return 0.06f;
}

/* The per-frame uniforms of dusk and night (hol_light.h). */
static void hol__frame_lights(hol_render *r, const hol_frame_desc *f)
{
    const hol_light_frame *lf = &r->lights;
    r->gl.Uniform1i(r->pg->u_lonly, (f->flags & HOL_RENDER_LIGHT_ONLY) != 0);
    r->gl.Uniform1f(r->pg->u_klein, (float)lf->klein);
    r->gl.Uniform1f(r->pg->u_mpu2, (float)(lf->metres_per_unit * lf->metres_per_unit));
    r->gl.Uniform1f(r->pg->u_eyeh, (float)lf->eye_h);
    /* the sky's ambient and sun light (linear: scene.frag.glsl's), dusk's
     * and night's mixed */
    static const float amb[2][3] = {{0.0980f, 0.0772f, 0.0873f}, {0.0129f, 0.0151f, 0.0276f}};
    static const float sun[2][3] = {{0.2174f, 0.1039f, 0.0661f}, {0.0117f, 0.0151f, 0.0347f}};
    float u = hol__night(f), a[3], s[3];
    for (int i = 0; i < 3; i++) {
        a[i] = amb[0][i] * (1 - u) + amb[1][i] * u;
        s[i] = sun[0][i] * (1 - u) + sun[1][i] * u;
    }
    r->gl.Uniform3f(r->pg->u_amb, a[0], a[1], a[2]);
    r->gl.Uniform3f(r->pg->u_sun, s[0], s[1], s[2]);
}

/* The room's meshes (trees, hedges) take the lanterns of the room's cells
 * (u_tl: the cells' centres' x, z in room metres, the lights' heights,
 * their weights; up to four): a lantern's cell is the one whose tile, by
 * the room walk columns first then rows (as the vertex trees are chosen:
 * render/hol_scene.c), is the lantern's tile. The shader measures a point
 * in the Klein frame of that cell's tile (docs/lighting.md). */
static void hol__room_lights(hol_render *r, const hol_frame_desc *f)
{
    float tl[4][4] = {{1e4f, 1e4f, 1e4f, 1e4f}, {1e4f, 1e4f, 1e4f, 1e4f}, {0}, {0}};
    double m = f->cell_m > 0 ? f->cell_m : 1.0;
    int n = 0, cols = hol_room_cols(&f->user), rows = hol_room_rows(&f->user);
    for (int c = 0; c < cols && n < 4; c++)
        for (int w = 0; w < rows && n < 4; w++) {
            hol_room st = f->user;
            int ok = 1;
            while (ok && st.col != c)
                ok = hol_room_step(&st, st.col < c ? HOL_DIR_E : HOL_DIR_W) == HOL_OK;
            while (ok && st.row != w)
                ok = hol_room_step(&st, st.row < w ? HOL_DIR_S : HOL_DIR_N) == HOL_OK;
            for (int o = 0; ok && o < f->nlanterns && o < HOL_RENDER_MAX_LANTERNS && n < 4; o++)
                if (hol_tile_eq(f->lanterns[o], st.tile)) {
                    tl[0][n] = (float)((c + 0.5) * m);
                    tl[1][n] = (float)((w + 0.5) * m);
                    tl[2][n] = (float)HOL_LIGHT_HEIGHT_M;
                    tl[3][n++] = 1;
                    break;
                }
        }
    if (f->carried && n < 4) { /* the carried lantern, where it is */
        tl[0][n] = (float)f->carried_pos[0];
        tl[1][n] = (float)f->carried_pos[2];
        tl[2][n] = (float)f->carried_pos[1];
        tl[3][n++] = 1;
    }
    r->gl.Uniform4fv(r->pg->u_tl, 4, &tl[0][0]);
}

/* The masks' texture (HOL__SHM_COLS x HOL__SHM_ROWS masks of RGBA8,
 * linear, clamped): made when a frame first has a shadow. */
static void hol__shm_texture(hol_render *r)
{
    r->gl.GenTextures(1, &r->shm);
    r->gl.ActiveTexture(GL_TEXTURE1);
    r->gl.BindTexture(GL_TEXTURE_2D, r->shm);
    r->gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, HOL__SHM_COLS * HOL_SHADOW_MASK_N,
                     HOL__SHM_ROWS * HOL_SHADOW_MASK_N, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    r->gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    r->gl.ActiveTexture(GL_TEXTURE0);
}

/* The slot of the shadow mask with key (nonzero): kept from an earlier
 * frame; else, with d, rastered (core/hol_shadow.h) into a free slot or
 * the least recently used one not used by this frame. -1: not kept (d
 * NULL) or every slot is this frame's; -2: d has no wedge (kept so, no
 * texture: the tile takes the program without shadows). */
int hol__shadow_mask(hol_render *r, uint64_t key, const hol_shadow_mask_desc *d)
{
    int lru = -1;
    for (int k = 0; k < HOL__SHM_SLOTS; k++) {
        if (r->shm_slot[k].key == key) {
            r->shm_slot[k].last_frame = r->frame;
            return r->shm_slot[k].empty ? -2 : k;
        }
        if (!r->shm_slot[k].key) {
            if (lru < 0 || r->shm_slot[lru].key)
                lru = k;
        } else if (r->shm_slot[k].last_frame != r->frame &&
                   (lru < 0 || (r->shm_slot[lru].key &&
                                r->shm_slot[k].last_frame < r->shm_slot[lru].last_frame)))
            lru = k;
    }
    if (!d || lru < 0)
        return -1;
    r->shm_slot[lru].key = key;
    r->shm_slot[lru].last_frame = r->frame;
    r->shm_slot[lru].empty = d->n == 0;
    if (d->n == 0)
        return -2;
    if (!r->shm)
        hol__shm_texture(r);
    hol_shadow_mask(d, r->shm_px);
    r->shm_made++;
    r->gl.ActiveTexture(GL_TEXTURE1);
    r->gl.BindTexture(GL_TEXTURE_2D, r->shm);
    r->gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    r->gl.TexSubImage2D(GL_TEXTURE_2D, 0, lru % HOL__SHM_COLS * HOL_SHADOW_MASK_N,
                        lru / HOL__SHM_COLS * HOL_SHADOW_MASK_N, HOL_SHADOW_MASK_N,
                        HOL_SHADOW_MASK_N, GL_RGBA, GL_UNSIGNED_BYTE, r->shm_px);
    r->gl.ActiveTexture(GL_TEXTURE0);
    return lru;
}

/* The effects' levels (HOL_PROG_FX_*) the lit tiles of this frame take,
 * a bit each: a tile's own (hol__item.fx: what its slots hold), so a tile
 * whose slots hold only round lanterns takes the cheapest program even in
 * a frame with fireflies or spots; bit HOL__VLIT_BIT + fx: a tile of that
 * level draws its small props per vertex (hol__item.props); bit
 * HOL__FLOOR_BIT + fx: its ground apart (hol__item.ground). */
#define HOL__VLIT_BIT 8
#define HOL__FLOOR_BIT 16
static unsigned hol__tile_fx_used(const hol_render *r)
{
    unsigned m = 0;
    for (int i = 0; i < r->nitems; i++)
        if (r->items[i].pass == HOL__PASS_TILE) {
            m |= 1u << r->items[i].fx;
            if (r->items[i].props)
                m |= 1u << (HOL__VLIT_BIT + r->items[i].fx);
            if (r->items[i].ground)
                m |= 1u << (HOL__FLOOR_BIT + r->items[i].fx);
        }
    return m;
}

/* The programs frame f uses, n of them, in the order their per-frame
 * uniforms are set: day's one; or at dusk and night day's too (the
 * stencil pass's: hol__set_pass), the tiles' of the lower effects'
 * levels that a tile takes, then the tiles' without shadows, the room's,
 * and the tiles' with shadow masks (current at the end). */
static int hol__frame_uses(const hol_render *r, const hol_frame_desc *f, hol__use out[])
{
    if (!f->lighting) {
        out[0] = (hol__use){HOL__USE_DAY, 0};
        return 1;
    }
    int n = 0, top = r->lights.fx;
    unsigned m = hol__tile_fx_used(r);
    out[n++] = (hol__use){HOL__USE_DAY, 0}; /* the stencil pass's */
    for (int fx = 0; fx <= top; fx++) {
        if (m >> (HOL__VLIT_BIT + fx) & 1) {
            out[n++] = (hol__use){HOL__USE_VLIT0, fx};
            out[n++] = (hol__use){HOL__USE_VLITM, fx};
        }
        if (m >> (HOL__FLOOR_BIT + fx) & 1) {
            out[n++] = (hol__use){HOL__USE_FLOOR0, fx};
            out[n++] = (hol__use){HOL__USE_FLOORM, fx};
        }
    }
    for (int fx = 0; fx < top; fx++)
        if (m >> fx & 1) {
            out[n++] = (hol__use){HOL__USE_TILES0, fx};
            out[n++] = (hol__use){HOL__USE_TILESM, fx};
        }
    out[n++] = (hol__use){HOL__USE_TILES0, top};
    out[n++] = (hol__use){HOL__USE_BACK, 0};
    out[n++] = (hol__use){HOL__USE_ROOM, 0};
    out[n++] = (hol__use){HOL__USE_TILESM, top};
    return n;
}

/* This frame's program for a use (HOL__USE_*): its key from the frame (the
 * lighting, the tiling's flatness, the view's wedges) and, for the tiles,
 * the effects' level fx (HOL_PROG_FX_*, at most the frame's). */
hol_prog *hol__use_prog(hol_render *r, const hol_frame_desc *f, int use, int fx)
{
    hol_prog_key k;
    memset(&k, 0, sizeof k);
    if (use == HOL__USE_TEXT)
        return &r->progs[HOL_PROG_TEXT_SLOT];
    k.wedge = r->view.wedges != 0;
    if (use != HOL__USE_DAY) {
        k.lighting = hol__sky_key(f);
        k.room = use == HOL__USE_ROOM || use == HOL__USE_BACK;
        k.lamps = use == HOL__USE_ROOM;
    }
    if (use >= HOL__USE_TILES0) {
        k.flat = r->lights.flat != 0;
        k.fx = fx;
        k.shadow = use == HOL__USE_TILESM || use == HOL__USE_VLITM || use == HOL__USE_FLOORM;
        k.vlit = use == HOL__USE_VLIT0 || use == HOL__USE_VLITM;
        k.floor = use == HOL__USE_FLOOR0 || use == HOL__USE_FLOORM;
        k.wedge = k.wedge && !k.floor;
    }
    return &r->progs[hol_prog_slot(&k)];
}

/* The frame's program for a use, the tiles' at the frame's effects. */
hol_prog *hol__frame_prog(hol_render *r, const hol_frame_desc *f, int use)
{
    return hol__use_prog(r, f, use, r->lights.fx);
}

/* Compile, if not yet, the programs this frame uses: a command that draws
 * only the day compiles 1 or 2 programs of the HOL_PROG_SLOTS (each costs
 * llvmpipe about 8 ms of CPU). HOL_EUNSUPPORTED if one does not compile. */
hol_err hol__use_progs(hol_render *r, const hol_frame_desc *f)
{
    int n, over = 0;
    for (int i = 0; i < r->nitems && !over; i++)
        over = r->items[i].pass >= HOL__PASS_HAND;
    hol_prog *tp = &r->progs[HOL_PROG_TEXT_SLOT];
    hol_prog_key tk = hol_prog_key_of_slot(HOL_PROG_TEXT_SLOT);
    if (over && !tp->prog && hol_prog_make(&r->gl, &tk, tp))
        return HOL_EUNSUPPORTED;
    hol__use uses[HOL__MAX_USES];
    n = hol__frame_uses(r, f, uses);
    for (int i = 0; i < n; i++) {
        hol_prog *pg = hol__use_prog(r, f, uses[i].use, uses[i].fx);
        hol_prog_key k = hol_prog_key_of_slot((int)(pg - r->progs));
        if (!pg->prog && hol_prog_make(&r->gl, &k, pg))
            return HOL_EUNSUPPORTED;
    }
    return HOL_OK;
}

/* Clear the frame (sky, or black for IDs), upload this frame's dynamic
 * geometry, and set the program's per-frame uniforms; vp receives the
 * view-projection matrix. */
void hol__frame_begin(hol_render *r, const hol_frame_desc *f, float vp[16])
{
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    float sky[3];
    float fogd = hol__sky(f, sky);
    hol__viewport(r, f);
    r->gl.Disable(GL_CULL_FACE);
    r->gl.Disable(GL_BLEND);
    r->gl.Disable(GL_DITHER);
    r->gl.DepthMask(GL_TRUE);
    r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    r->gl.StencilMask(0xff);
    if (ids)
        r->gl.ClearColor(0, 0, 0, 1);
    else
        hol__clear_colour(r, sky[0], sky[1], sky[2]);
    r->gl.ClearDepthf(1.0f);
    r->gl.ClearStencil(HOL_VIEW_STENCIL_CLEAR);
    r->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    r->gl.BindVertexArray(r->vao[1]);
    r->gl.BindBuffer(GL_ARRAY_BUFFER, r->vbo[1]);
    r->gl.BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(r->dyn.nv * sizeof(hol_vertex)), r->dyn.v,
                     GL_STREAM_DRAW);
    r->gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(r->dyn.ni * sizeof(uint32_t)),
                     r->dyn.idx, GL_STREAM_DRAW);
    r->uploaded += (long)(r->dyn.nv * sizeof(hol_vertex) + r->dyn.ni * sizeof(uint32_t));
    float view[16], proj[16];
    hol_camera_matrices(&f->cam, view, proj);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float s = 0;
            for (int k = 0; k < 4; k++)
                s += proj[4 * k + j] * view[4 * i + k];
            vp[4 * i + j] = s;
        }
    /* the per-frame uniforms of every program the frame uses: day's, or
     * at dusk and night the room's then the tiles' (current at the end) */
    hol__use uses[HOL__MAX_USES];
    int n = hol__frame_uses(r, f, uses);
    for (int i = 0; i < n; i++) {
        r->pg = hol__use_prog(r, f, uses[i].use, uses[i].fx);
        r->gl.UseProgram(r->pg->prog);
        r->gl.Uniform3f(r->pg->u_eye, (float)r->view_at[0], (float)r->view_at[1],
                        (float)r->view_at[2]);
        /* the fog: the sky's colour in linear light, as the light it mixes */
        r->gl.Uniform3f(r->pg->u_fog, hol__srgb_linear(sky[0]), hol__srgb_linear(sky[1]),
                        hol__srgb_linear(sky[2]));
        r->gl.Uniform1f(r->pg->u_fogd, fogd);
        r->gl.Uniform1i(r->pg->u_lin, r->desc.srgb != 0);
        r->gl.Uniform1i(r->pg->u_wmode, 0);
        r->gl.Uniform1i(r->pg->u_shm, 1); /* the shadow masks' unit */
        int room = uses[i].use == HOL__USE_ROOM || uses[i].use == HOL__USE_BACK;
        r->gl.Uniform1i(r->pg->u_light, room ? 2 + r->lights.flat : 0);
        if (f->lighting)
            hol__frame_lights(r, f);
        if (uses[i].use == HOL__USE_ROOM)
            hol__room_lights(r, f);
    }
}

/* The passes over the scene (the panel, the fade, the HUD): no depth test
 * or writes, no stencil; vp the view-projection (NULL: the identity, and
 * the model's too). */
static void hol__set_overlay(hol_render *r, const float vp[16], int mode)
{
    float ident[16];
    hol__identity(ident);
    r->gl.Disable(GL_DEPTH_TEST);
    r->gl.DepthMask(GL_FALSE);
    r->gl.Disable(GL_STENCIL_TEST);
    r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp ? vp : ident);
    if (!vp)
        r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
    r->gl.Uniform1i(r->pg->u_mode, mode);
}

/* The GL state of a pass (vp: the view-projection, for the passes in the
 * world). */
static void hol__set_pass_as(hol_render *r, const hol_frame_desc *f, int pass, const float vp[16],
                             hol_prog *want)
{
    int ids = (f->flags & HOL_RENDER_IDS) != 0;
    float ident[16];
    hol__identity(ident);
    if (want) { /* the room's meshes: the program without tile code */
        if (want != r->pg) {
            r->pg = want;
            r->gl.UseProgram(want->prog);
        }
    }
    r->gl.Uniform1i(r->pg->u_wmode, 0); /* the tile pass sets it per branch */
    switch (pass) {
    case HOL__PASS_STENCIL:
        r->gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        r->gl.Disable(GL_DEPTH_TEST);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Enable(GL_STENCIL_TEST);
        r->gl.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, ident);
        r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        break;
    case HOL__PASS_ROOM:
    case HOL__PASS_TILE:
        r->gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        r->gl.Enable(GL_DEPTH_TEST);
        r->gl.DepthFunc(GL_LESS);
        r->gl.DepthMask(GL_TRUE);
        r->gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        if (pass == HOL__PASS_ROOM)
            r->gl.Disable(GL_STENCIL_TEST);
        else
            r->gl.Enable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_LIT);
        r->gl.Uniform4f(r->pg->u_id, 0, 0, 0, 1);
        if (pass == HOL__PASS_ROOM)
            r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, ident);
        if (f->lighting) /* the tile pass sets it per tile; 3: a flat room */
            r->gl.Uniform1i(r->pg->u_light, 2 + (pass == HOL__PASS_ROOM && r->lights.flat));
        break;
    case HOL__PASS_HAND:
        /* in the world: hidden where the scene is nearer; its coplanar
         * layers are painted in order (no depth writes) */
        r->gl.Enable(GL_DEPTH_TEST);
        r->gl.DepthFunc(GL_LEQUAL);
        r->gl.DepthMask(GL_FALSE);
        r->gl.Disable(GL_STENCIL_TEST);
        r->gl.UniformMatrix4fv(r->pg->u_vp, 1, GL_FALSE, vp);
        r->gl.Uniform1i(r->pg->u_mode, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        break;
    case HOL__PASS_PANEL:
        /* in the world, drawn last, hidden where the scene is nearer (no
         * depth writes: its layers painted in order). The app places it in
         * front of the nearest hedge or trunk in its direction, down to
         * 0.5 m (core/hol_panel.h); a trunk nearer than that covers it as
         * it would cover a real sign, never the other way round. */
        hol__set_overlay(r, vp, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        if (!f->outside) { /* outside the room: over all, readable */
            r->gl.Enable(GL_DEPTH_TEST);
            r->gl.DepthFunc(GL_LEQUAL);
        }
        break;
    case HOL__PASS_FADE:
        hol__set_overlay(r, NULL, HOL__MODE_FLAT);
        r->gl.Enable(GL_BLEND);
        r->gl.BlendColor(0, 0, 0, (float)(f->outside && f->fade < HOL_RENDER_OUTSIDE_DIM
                                              ? HOL_RENDER_OUTSIDE_DIM
                                              : f->fade));
        r->gl.BlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
        break;
    default: /* the HUD */
        hol__set_overlay(r, NULL, ids ? HOL__MODE_ID : HOL__MODE_FLAT);
        break;
    }
}

/* The overlays' program current, its texture bound and the blending of
 * its glyphs' edges (straight alpha; the destination's alpha kept opaque
 * over opaque, for a panel's layer image); not for IDs. */
static void hol__text_prog(hol_render *r, const hol_frame_desc *f)
{
    hol_prog *tp = &r->progs[HOL_PROG_TEXT_SLOT];
    if (r->pg != tp) {
        r->pg = tp;
        r->gl.UseProgram(tp->prog);
        r->gl.Uniform1i(tp->u_lin, r->desc.srgb != 0);
        r->gl.Uniform1i(tp->u_atlas, 0);
        r->gl.ActiveTexture(GL_TEXTURE0);
        r->gl.BindTexture(GL_TEXTURE_2D, r->atlas);
    }
    if (f->flags & HOL_RENDER_IDS)
        return;
    r->gl.Enable(GL_BLEND);
    r->gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

/* The GL state of a pass: at dusk and night the room's meshes take the
 * programs without tile code (its trees and hedges lantern-lit, its
 * backdrop on the cheaper path: both get the pass's state), and the tile
 * pass's state goes to both tile programs (with the shadow masks' texture
 * on unit 1, current at the end, and without); the overlays take the text
 * program. The stencil pass draws with the day's program at every sky:
 * it writes no colour, but a renderer that shades every fragment before
 * its stencil test and whatever the colour mask (SwiftShader: the web)
 * pays the program's fragment shader over every leaf polygon's pixels,
 * and the lit tiles' with shadow masks (the one current before) cost the
 * web's night frame about 20 ms (docs/web-night.md). */
static void hol__set_pass(hol_render *r, const hol_frame_desc *f, int pass, const float vp[16])
{
    if (pass >= HOL__PASS_HAND && r->progs[HOL_PROG_TEXT_SLOT].prog) {
        hol__text_prog(r, f);
        hol__set_pass_as(r, f, pass, vp, NULL);
        return;
    }
    if (f->lighting && pass == HOL__PASS_TILE) {
        /* every tile program the frame uses (hol__frame_uses: the last of
         * them, current after the pass's set, the tiles' with shadows at
         * the frame's effects) */
        hol__use uses[HOL__MAX_USES];
        int n = hol__frame_uses(r, f, uses);
        for (int i = 0; i < n; i++)
            if (uses[i].use >= HOL__USE_TILES0)
                hol__set_pass_as(r, f, pass, vp, hol__use_prog(r, f, uses[i].use, uses[i].fx));
        r->gl.ActiveTexture(GL_TEXTURE1); /* the shadow masks (u_shm) */
        r->gl.BindTexture(GL_TEXTURE_2D, r->shm);
        r->gl.ActiveTexture(GL_TEXTURE0);
        return;
    }
    if (f->lighting && pass == HOL__PASS_ROOM)
        hol__set_pass_as(r, f, pass, vp, hol__frame_prog(r, f, HOL__USE_BACK));
    int last = pass == HOL__PASS_ROOM ? HOL__USE_ROOM : HOL__USE_DAY;
    hol__set_pass_as(r, f, pass, vp, f->lighting ? hol__frame_prog(r, f, last) : NULL);
}

/* A lit tile's frame and lights (a tile without a frame: as the room). */
static void hol__item_uniforms(hol_render *r, const hol__item *it)
{
    r->gl.Uniform1i(r->pg->u_light, it->nl < 0 ? 2 : 1);
    if (it->nl < 0)
        return;
    r->gl.Uniform4fv(r->pg->u_tl, 4, &it->tl[0][0]);
    r->gl.Uniform4fv(r->pg->u_tx, HOL_PROG_TX_ROWS, &it->tx[0][0]);
    if (it->nsh)
        r->gl.Uniform4fv(r->pg->u_shr, 1, it->shr);
}

/* Draw count indices from first of the bound buffers. */
static void hol__draw(hol_render *r, uint32_t first, uint32_t count, hol_render_stats *st)
{
    r->gl.DrawElements(GL_TRIANGLES, (GLsizei)count, GL_UNSIGNED_INT,
                       (const void *)(uintptr_t)(first * sizeof(uint32_t)));
    st->draw_calls++;
    st->triangles += count / 3;
}

/* A tile item's program (at dusk and night: its effects' level, its
 * shadow mask or none, its part: HOL__PART_*) and uniforms. */
enum { HOL__PART_REST, HOL__PART_PROPS, HOL__PART_GROUND };
static void hol__tile_state(hol_render *r, const hol_frame_desc *f, const hol__item *it,
                            int part, hol_render_stats *st)
{
    if (f->lighting) { /* a tile with no shadow: the program without */
        static const int uses[3][2] = {{HOL__USE_TILES0, HOL__USE_TILESM},
                                       {HOL__USE_VLIT0, HOL__USE_VLITM},
                                       {HOL__USE_FLOOR0, HOL__USE_FLOORM}};
        int use = uses[part][it->nl >= 0 && it->nsh];
        hol_prog *want = hol__use_prog(r, f, use, it->fx);
        if (want != r->pg) {
            r->pg = want;
            r->gl.UseProgram(want->prog);
            st->state_changes++;
        }
    }
    r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, it->model);
    if (f->lighting)
        hol__item_uniforms(r, it);
    if (r->view.wedges) {
        r->gl.Uniform1i(r->pg->u_wmode, it->branch > 0);
        r->gl.Uniform4f(r->pg->u_wedge, it->wedge[0], it->wedge[1], it->wedge[2], it->wedge[3]);
    }
    if (f->flags & HOL_RENDER_IDS) {
        int id = it->branch + 1;
        r->gl.Uniform4f(r->pg->u_id, (float)(id & 255) / 255.0f, (float)(id >> 8) / 255.0f, 0, 1);
    }
}

/* An item's indices drawn with its pass's program: all but a lit tile's
 * small props and ground (hol__item.props, .ground), each drawn apart. */
static uint32_t hol__rest(const hol__item *it)
{
    return it->count - it->props - it->ground;
}

/* The vertex array vao (0 the static buffers, 1 the dynamic) bound, when
 * *cur (the one bound) differs. */
static void hol__bind_vao(hol_render *r, int vao, int *cur, hol_render_stats *st)
{
    if (vao == *cur)
        return;
    *cur = vao;
    r->gl.BindVertexArray(r->vao[vao]);
    st->state_changes++;
}

/* The scissor: box (hol__item.box; NULL or w 0: the viewport) when cur
 * (the one set) differs. */
static void hol__scissor(hol_render *r, const hol_frame_desc *f, const int32_t *box,
                         int32_t cur[4])
{
    static const int32_t whole[4] = {0, 0, 0, 0};
    if (!box || !box[2])
        box = whole;
    if (!memcmp(box, cur, 4 * sizeof cur[0]))
        return;
    memcpy(cur, box, 4 * sizeof cur[0]);
    if (box[2])
        r->gl.Scissor(box[0], box[1], box[2], box[3]);
    else
        r->gl.Scissor(f->vp_x, f->vp_y, f->cam.width, f->cam.height);
}

/* Back faces culled (on) or not, when *cur (the state set) differs. The
 * room's and the tiles' resident meshes are closed or seen from their
 * normal's side only, each triangle wound counter-clockwise seen from
 * that side (tests/test_render_cull.c), so culling their back faces
 * changes no pixel but a few on silhouettes (where a back face had won a
 * shared edge's pixel); it halves what the rasteriser shades of them, which
 * SwiftShader shades before its depth and stencil tests (docs/web.md,
 * docs/performance.md).
 * The dynamic meshes (the body, the fireflies' sprites) are drawn whole,
 * and so is everything when the eye is outside the room (f->outside: it
 * may stand inside a hedge, whose inside it sees). */
static void hol__cull(hol_render *r, int on, int *cur)
{
    if (on == *cur)
        return;
    *cur = on;
    if (on)
        r->gl.Enable(GL_CULL_FACE);
    else
        r->gl.Disable(GL_CULL_FACE);
}

/* Execute the sorted queue, skipping redundant state changes. */
void hol__execute(hol_render *r, const hol_frame_desc *f, const float vp[16],
                         hol_render_stats *st)
{
    int cur_vao = 1, cur_pass = -1, cur_ref = -1, cur_mask = -1;
    int32_t cur_box[4] = {0, 0, 0, 0}; /* the scissor: the viewport */
    int cur_cull = 0;
    for (int i = 0; i < r->nitems; i++) {
        const hol__item *it = r->sorted[i];
        if (it->pass != cur_pass) {
            cur_pass = it->pass;
            cur_ref = cur_mask = -1;
            st->state_changes++;
            hol__set_pass(r, f, cur_pass, vp);
        }
        hol__scissor(r, f, cur_pass == HOL__PASS_TILE ? it->box : NULL, cur_box);
        hol__cull(r, (cur_pass == HOL__PASS_ROOM || cur_pass == HOL__PASS_TILE) && !it->dyn &&
                         !f->outside,
                  &cur_cull);
        if (cur_pass == HOL__PASS_STENCIL) {
            r->gl.StencilFunc(GL_ALWAYS, it->ref, 0xff);
            st->state_changes++;
            st->stencil_passes++;
        } else if (cur_pass == HOL__PASS_TILE) {
            if (it->ref != cur_ref || it->mask != cur_mask) {
                r->gl.StencilFunc(GL_EQUAL, it->ref, it->mask);
                cur_ref = it->ref;
                cur_mask = it->mask;
                st->state_changes++;
            }
            if (it->props) { /* its small props first, lit per vertex */
                hol__bind_vao(r, it->dyn, &cur_vao, st);
                hol__tile_state(r, f, it, HOL__PART_PROPS, st);
                hol__draw(r, it->first + it->count - it->props, it->props, st);
            }
            if (it->ground) { /* its ground, then the rest */
                hol__bind_vao(r, it->dyn, &cur_vao, st);
                hol__tile_state(r, f, it, HOL__PART_GROUND, st);
                hol__draw(r, it->first, it->ground, st);
            }
            if (hol__rest(it)) /* a ground alone has no rest */
                hol__tile_state(r, f, it, HOL__PART_REST, st);
            st->branches += !it->dyn; /* a firefly's sprite is no branch */
        } else if (cur_pass == HOL__PASS_ROOM && f->lighting) {
            hol_prog *want = hol__frame_prog(r, f, it->lamps ? HOL__USE_ROOM : HOL__USE_BACK);
            if (want != r->pg) {
                r->pg = want;
                r->gl.UseProgram(want->prog);
                st->state_changes++;
            }
        } else if (cur_pass == HOL__PASS_HAND || cur_pass == HOL__PASS_PANEL) {
            r->gl.UniformMatrix4fv(r->pg->u_model, 1, GL_FALSE, it->model);
        }
        hol__bind_vao(r, it->dyn, &cur_vao, st);
        if (hol__rest(it))
            hol__draw(r, it->first + it->ground, hol__rest(it), st);
    }
    hol__scissor(r, f, NULL, cur_box);
    hol__cull(r, 0, &cur_cull);
}
