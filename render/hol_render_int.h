/* hol_render_int.h - the renderer's insides, shared by its files (not an
 * API: nothing outside render/hol_render*.c includes it).
 *
 * Contract
 * - struct hol_render and its queue's items; the GPU buffers' layout.
 * - The files, each one job: hol_render.c the API (create, frame, panel
 *   image, read back), hol_render_queue.c a frame's queue (leaves, room,
 *   fade, HUD and panel), hol_render_tiles.c the tile pass (resident tile
 *   meshes, a lit tile's lights and shadows, fireflies), hol_render_gpu.c
 *   the GL side (buffers, the frame's programs and uniforms, the passes'
 *   state, executing the sorted queue). Programs: render/hol_program.h.
 * - Calls run one way: hol_render.c -> hol_render_queue.c ->
 *   hol_render_tiles.c -> hol_render_gpu.c (and hol_render.c to the last
 *   two); none calls back up. Single-threaded, as the renderer.
 */
#ifndef HOL_RENDER_INT_H
#define HOL_RENDER_INT_H

#include <stdint.h>
#include <string.h>

#include "../core/hol_shadow.h"
#include "hol_gl.h"
#include "hol_light.h"
#include "hol_mesh.h"
#include "hol_program.h"
#include "hol_render_types.h"
#include "hol_scene.h"

/* GPU memory layout. The static buffers hold the room meshes and a pool of
 * tile meshes that stay resident across frames; the dynamic buffers get the
 * per-frame leaf polygons and HUD (a few KB). */
#define HOL__ROOM_V (1u << 16)
#define HOL__ROOM_I (1u << 17)
/* Tile meshes resident at once: a frame shows at most ~40 tiles in the
 * 3 x 3 room and 65 in a 5 x 5 one (test_render_tiles counts them). The
 * static buffers hold HOL__SLOTS_FIRST slots at create, HOL__SLOTS_MID
 * from the first frame that needs more, all of them from the first that
 * needs more again (hol__static_grow): llvmpipe clears a buffer it
 * allocates, 24 MB for all the slots, about 0.1 s of a picture's
 * start-up, 6 MB with the first 16 (a picture from the room's middle cell
 * builds about 14 tiles). */
#define HOL__SLOTS 96
#define HOL__SLOTS_FIRST 16
#define HOL__SLOTS_MID 48
#define HOL__SLOT_V 8192u
#define HOL__SLOT_I 16384u
#define HOL__HUD_V (1u << 14) /* the resident minimap, after the room */
#define HOL__HUD_I (1u << 15)
#define HOL__HUD_VBASE HOL__ROOM_V
#define HOL__HUD_IBASE HOL__ROOM_I
#define HOL__SLOT_VBASE(k) (HOL__ROOM_V + HOL__HUD_V + (uint32_t)(k) * HOL__SLOT_V)
#define HOL__SLOT_IBASE(k) (HOL__ROOM_I + HOL__HUD_I + (uint32_t)(k) * HOL__SLOT_I)
#define HOL__DYN_V (1u << 16)
#define HOL__DYN_I (1u << 17)
#define HOL__MAX_ITEMS 1024
/* Shadow masks (core/hol_shadow.h) resident at once, in one texture of
 * HOL__SHM_COLS x HOL__SHM_ROWS masks (render/hol_light.h; 1024 x 512
 * texels, 2 MB): more than the lit tiles of any frame (65), kept while
 * their tile's wedges are the same, so a still scene rasters none. */
#define HOL__SHM_COLS HOL_SHADOW_ATLAS_COLS
#define HOL__SHM_ROWS HOL_SHADOW_ATLAS_ROWS
#define HOL__SHM_SLOTS (HOL__SHM_COLS * HOL__SHM_ROWS)
/* The body's mesh (render/hol_body_draw.h: two tracked hands are 5,526
 * vertices and 25,728 indices), built once for both eyes. */
#define HOL__BODY_V 6144u
#define HOL__BODY_I 27648u

typedef struct hol__slot {
    int used;
    hol_tile tile;
    int bare, pole, kind, have; /* have: content came from the world */
    double cell_m;
    hol_tile_content content;
    uint64_t last_frame;
    uint32_t nidx;
    uint32_t nprops; /* its small props: the last nprops of its indices */
    uint32_t nground; /* its ground: the first nground of its indices */
} hol__slot;

enum {
    HOL__PASS_STENCIL = 0,
    HOL__PASS_ROOM = 1,
    HOL__PASS_TILE = 2,
    HOL__PASS_HAND = 3, /* the minimap on a quad in the hand (world space) */
    HOL__PASS_FADE = 4, /* the safety fade over the scene (blended) */
    HOL__PASS_HUD = 5,
    HOL__PASS_PANEL = 6 /* a headset's UI panel in the world, over all */
};
enum { HOL__MODE_LIT = 0, HOL__MODE_ID = 1, HOL__MODE_FLAT = 2 };

typedef struct hol__item {
    uint32_t key;
    uint8_t pass;
    uint8_t dyn; /* 1: dynamic buffers */
    uint8_t ref, mask;
    int16_t branch;
    float wedge[4]; /* w0, w1 (x, z) when the view has wedges */
    int8_t nl;      /* lit tiles: lights (-1: no hyperbolic frame) */
    float tl[4][4]; /* u_tl: its lights and the eye in the tile's own frame */
    /* u_tx: the spots' tangents (3) and sines, heights, lantern and
     * firefly weights (hol__item_lights) */
    float tx[HOL_PROG_TX_ROWS][4];
    float shr[4];    /* u_shr: its shadow mask's place (hol__item_shadows) */
    int8_t nsh;      /* 1: it has one (0: the programs without shadows) */
    int8_t fx;       /* lit tiles: the effects its slots need (HOL_PROG_FX_*:
                      * 0 only round lanterns at their height, 1 a firefly
                      * or a height of its own, 2 a spot), at most the
                      * frame's; its program's (hol__use_prog) */
    uint8_t lamps;   /* the lit room: 1 trees and hedges, 0 the backdrop */
    uint32_t first, count; /* index range */
    /* a lit tile (dusk, night) with no spot in its slots: the last
     * props of its count are its small props, drawn first and lit per
     * vertex (the programs with vlit: hol__use_prog's HOL__USE_VLIT*);
     * 0 day, IDs and every other item: one draw */
    uint32_t props;
    /* a lit tile (dusk, night) with a frame, not the IDs' frame, no
     * wedges: the first ground of its count are its ground (the floor and
     * its water, normal straight up), drawn first with the floor's
     * programs (HOL__USE_FLOOR*: no normal to turn, no Lambert term's
     * horizontal part); 0: drawn with the rest */
    uint32_t ground;
    /* the tile pass: the window's pixels its stencil can pass (x, y, w,
     * h; w 0: the whole viewport), the bounding box of its branch's
     * leaves (hol__branch_box): SwiftShader shades a fragment before its
     * stencil test, so the scissor, not the stencil, keeps a branch's
     * mesh from costing a whole screen's shading */
    int32_t box[4];
    float model[16];
} hol__item;

struct hol_render {
    hol_render_desc desc;
    hol_gl gl;
    hol_scene *scene;
    GLuint vao[2], vbo[2], ibo[2]; /* [0] static, [1] dynamic */
    GLuint atlas;                  /* the text face's (core/hol_face.h) */
    GLuint shm;                    /* the shadow masks' (made when first used) */
    struct {
        uint64_t key;              /* its tile, geometry and lights (0: free) */
        uint64_t last_frame;
        int empty;                 /* 1: no shadow falls on that tile */
    } shm_slot[HOL__SHM_SLOTS];
    uint8_t shm_px[HOL_SHADOW_MASK_BYTES]; /* one mask before upload */
    long shm_made;                 /* masks rastered (tests, the bench) */
    /* the programs by slot (render/hol_program.h), each compiled when
     * first used: variants, not uniforms, since a uniform costs llvmpipe
     * a load per pixel and a discard makes it shade before the depth test
     * (only the wedge's programs discard); only the tiles whose slots
     * hold a firefly or a spot pay for their code (hol__item.fx) */
    hol_prog progs[HOL_PROG_SLOTS];
    hol_prog *pg;       /* the current one */
    hol_light_frame lights; /* this frame's (at dusk and night) */
    hol_mesh dyn;     /* per-frame geometry */
    hol_mesh scratch; /* one room or tile mesh before upload */
    hol_vertex *verts;
    uint32_t *idx;
    hol__item items[HOL__MAX_ITEMS];
    int nitems;
    hol__item *sorted[HOL__MAX_ITEMS];
    hol_view view;
    /* each leaf's polygon's bounding box in NDC (x0, y0, x1, y1; x0 > x1:
     * off screen), from hol__queue_leaves */
    float leaf_box[HOL_VIEW_MAX_LEAVES][4];
    double view_at[3]; /* where the view was built from (room coordinates):
                          the eye, or outside the room (hol_frame_desc.outside)
                          its nearest point in the user's cell; the
                          programs' u_eye (fog, light, the wedges' origin) */
    /* resident meshes */
    hol__slot slots[HOL__SLOTS];
    int slot_cap; /* slots the static buffers hold now */
    uint64_t frame;
    int room_valid, room_bare;
    int room_tree[3];  /* the marked tree the room mesh has (marked, vx, vz) */
    hol_room room_user;
    double room_cell;
    struct hol_world *room_world;
    uint32_t room_nidx;
    uint32_t room_back[2]; /* its backdrop's index range (hol_scene_room) */
    int hud_valid;
    uint64_t hud_key;
    uint32_t hud_nidx;
    /* the body (hol_frame_desc.body) as built, in room coordinates: kept
     * while the body is the same (body_key), so a frame's second eye
     * copies it into the dynamic buffer instead of building it again */
    hol_mesh body;
    hol_vertex body_v[HOL__BODY_V];
    uint32_t body_i[HOL__BODY_I];
    int body_valid;
    uint64_t body_key;
    /* this frame's counters */
    long uploaded;
    int tiles_built;
};

/* The programs a frame uses (hol__frame_prog): the day's; at dusk and
 * night the room's and the tiles' (with their shadow mask or without). */
enum {
    HOL__USE_DAY = 0,
    HOL__USE_ROOM,   /* the room's trees and hedges, lantern-lit */
    HOL__USE_BACK,   /* its backdrop and outer ground: ambient and sun */
    HOL__USE_TILES0, /* lit tiles without shadows */
    HOL__USE_TILESM, /* with their shadow mask */
    HOL__USE_VLIT0,  /* lit tiles' small props, lit per vertex: no shadows */
    HOL__USE_VLITM,  /* with their shadow mask */
    HOL__USE_FLOOR0, /* lit tiles' ground: no shadows */
    HOL__USE_FLOORM, /* with their shadow mask */
    HOL__USE_TEXT    /* the overlays (hand, fade, HUD, panel): text's */
};
/* A program's use in a frame and, for the tiles', its effects' level
 * (HOL_PROG_FX_*); a frame has at most HOL__MAX_USES. */
typedef struct hol__use {
    int use, fx;
} hol__use;
#define HOL__MAX_USES (5 + 6 * HOL_PROG_FX_COUNT)

/* m = the identity (column-major). */
static inline void hol__identity(float m[16])
{
    memset(m, 0, 16 * sizeof(float));
    m[0] = m[5] = m[10] = m[15] = 1;
}

/* A new item of the queue in pass over the index range (first, count),
 * no branch, the identity for its model; NULL when the queue is full or
 * count is 0. */
static inline hol__item *hol__queue_push(hol_render *r, int pass, uint32_t first, uint32_t count)
{
    if (r->nitems >= HOL__MAX_ITEMS || count == 0)
        return NULL;
    hol__item *it = &r->items[r->nitems++];
    memset(it, 0, sizeof *it);
    it->pass = (uint8_t)pass;
    it->first = first;
    it->count = count;
    it->branch = -1;
    hol__identity(it->model);
    return it;
}

/* Box b (x0, y0, x1, y1; x0 > x1: empty) grown to hold the point (x, y). */
static inline void hol__box_add(float b[4], float x, float y)
{
    b[0] = x < b[0] ? x : b[0];
    b[1] = y < b[1] ? y : b[1];
    b[2] = x > b[2] ? x : b[2];
    b[3] = y > b[3] ? y : b[3];
}

/* FNV-1a over n bytes from h: the keys of kept draws and kept shadow masks */
static inline uint64_t hol__fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

/* hol_render_queue.c */
void hol__quad_matrix(const double pos[3], const double q[4], double sx, double sy,
                      double ox, double oy, float m[16]);
hol_err hol__queue_hud(hol_render *r, const hol_frame_desc *f);
hol_err hol__build(hol_render *r, const hol_frame_desc *f);

/* hol_render_tiles.c */
hol_err hol__queue_tiles(hol_render *r, const hol_frame_desc *f, int bare, double cell_m);

/* hol_render_gpu.c */
void hol__vao_attribs(hol_render *r, int k);
int hol__shadow_mask(hol_render *r, uint64_t key, const hol_shadow_mask_desc *d);
void hol__static_grow(hol_render *r, int cap);
void hol__upload_scratch(hol_render *r, uint32_t vbase, uint32_t ibase);
void hol__fade_rgb(const hol_frame_desc *f, uint8_t out[3]);
hol_prog *hol__frame_prog(hol_render *r, const hol_frame_desc *f, int use);
hol_prog *hol__use_prog(hol_render *r, const hol_frame_desc *f, int use, int fx);
hol_err hol__use_progs(hol_render *r, const hol_frame_desc *f);
void hol__frame_faded(hol_render *r, const hol_frame_desc *f);
void hol__frame_begin(hol_render *r, const hol_frame_desc *f, float vp[16]);
void hol__execute(hol_render *r, const hol_frame_desc *f, const float vp[16],
                  hol_render_stats *st);

#endif
