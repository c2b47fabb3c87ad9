/* hol_render.h - the renderer: one render queue per eye, stencil portals.
 *
 * Contract
 * - Platform independent GLES 3.0 (shaders are `#version 300 es`; under
 *   OSMesa's desktop GL core profile the same code runs, and EGL's GLES 3
 *   draws the same pixels). GL entry points are loaded through
 *   desc.getproc (render/hol_gl.h); nothing links gl* symbols. The caller
 *   makes a GL context current (8 stencil bits, a depth buffer) before
 *   hol_render_create and keeps it current for every call.
 * - hol_render_create makes the GL objects and the CPU stores once (fixed
 *   sizes); frames allocate nothing on the CPU. Shader programs other than
 *   the day's are compiled the first time a frame uses one, unless
 *   desc.all_programs (then all at create). Meshes stay resident on the GPU: the
 *   room's (rebuilt when the user steps) and a pool of tile meshes (LRU,
 *   rebuilt when a tile's content changes); per frame only the leaf
 *   polygons and the HUD are uploaded (a few KB).
 * - A frame is one eye: hol_view_build gives the leaves and branches; the
 *   queue holds one stencil polygon per visible leaf (pass 0, colour and
 *   depth writes off; rooms other than 3 x 3 tell branches apart by their
 *   wedges instead, tested in the fragment shader: hol_view.h), the room's
 *   own meshes (trees on all (C+1)(R+1) vertices,
 *   hedges on the boundary, a backdrop forest beyond them; pass 1, no
 *   stencil test), one draw per branch of its tile's mesh placed in the
 *   branch's cell and tested against the branch's stencil ref/mask (pass 2,
 *   nearest cells first for early depth rejection), the HUD (pass 3: the
 *   resident minimap and the live arrow and text; for a headset's eye a
 *   panel in the world instead, the last pass: HOL_RENDER_PANEL). One program for all;
 *   the queue is sorted by (pass, buffer, depth) and executed with
 *   redundant state changes skipped. No scene pass per portal, no
 *   render-to-texture.
 * - Geometry: the tiling is the user's tile word's (hol_tile_q: {4,4} the
 *   flat grid .. {4,8}), the room the user state's C x R cells, the cell
 *   side f->cell_m metres (0: 1). Room coordinates are metres (SPEC 7):
 *   a tile's ground, creeks and the places of its props scale with the
 *   cell; props, trees and hedges keep their size in metres.
 * - Floor outside the room is not drawn: hedges 2 m high stand on the room
 *   boundary (the move area ends there), and over them one sees sky/fog.
 *   Floor pixels are those showing the ground of a tile inside the room.
 * - ID mode renders the same queue but writes, for floor pixels, the index
 *   + 1 of the branch drawn there and 0 elsewhere (props, trees, sky): the
 *   tile under every pixel, as the portals decided it.
 * - Lighting (f->lighting, docs/rendering.md#lighting): day draws exactly
 *   the picture without lights. At dusk and night every tile fragment gets
 *   its point on the hyperboloid (render/hol_light.h: the tile's frame in
 *   the user's tile, the Klein map of the square), up to 4 lanterns chosen
 *   per tile on the CPU light it by the true distance in H^2 x E, and fog
 *   follows the true distance from the eye; the room's own meshes get the
 *   sky's ambient light and fog by room distance. A lantern tile shows a
 *   lantern (its glass drawn unlit). Fireflies (f->fireflies) and spots
 *   (f->lantern_spot) join the same choice (render/hol_light.h).
 *   HOL_RENDER_LIGHT_ONLY (tests) writes a tile fragment as (the lanterns'
 *   sum, the fog factor, the fireflies' sum).
 * - World content: with desc.world the tiles' content (biome, objects,
 *   creeks, logs, trees) comes from hol_world_get; without it, a plain
 *   biome-tinted floor from hol_tile_hash.
 */
#ifndef HOL_RENDER_H
#define HOL_RENDER_H

#include <stddef.h>
#include <stdint.h>

#include "../core/hol_alloc.h"
#include "../core/hol_room.h"
#include "hol_view.h"

struct hol_world;

/* The platform's get-proc-address (OSMesaGetProcAddress,
 * eglGetProcAddress, ...), cast to this type. */
typedef void (*hol_render_proc)(void);
typedef hol_render_proc (*hol_render_getproc)(const char *name);

typedef struct hol_render_desc {
    hol_render_getproc getproc; /* required: GL is loaded through it */
    int max_width, max_height;  /* 0: 4096 */
    struct hol_world *world;   /* optional; not owned */
    hol_alloc alloc;           /* hooks for the CPU stores (core/hol_alloc.h);
                                  zero: malloc/free */
    int srgb;                  /* the colour buffer is sRGB and the GL encodes
                                  what is written (GLES always; desktop GL with
                                  GL_FRAMEBUFFER_SRGB enabled by the caller):
                                  colours (authored in sRGB) are written as
                                  linear values, so the stored bytes are those
                                  of a plain RGBA8 buffer. 0: written as they
                                  are (OSMesa, EGL, a linear swapchain) */
    int debug;                 /* 1: hol_render_frame asks the GL for errors
                                  after every frame (glGetError: a round trip
                                  that waits for the GL's queue; a WebGL
                                  frame spent 284 of 285 ms in it). 0 (normal
                                  running): no glGet*, glGetError, glFinish or
                                  glReadPixels in a frame; errors are checked
                                  at create and by hol_render_check (after a
                                  resize). Tools and tests set it. */
    int all_programs;          /* 1: compile every shader program at create
                                  and size the tile meshes' buffers for all
                                  their slots (a headset: no compile and no
                                  buffer growth in a frame). 0:
                                  the day program at create, each other
                                  the first time a frame uses it (that
                                  frame's CPU time includes it; one that
                                  does not compile fails the frame with
                                  HOL_EUNSUPPORTED) */
} hol_render_desc;

typedef struct hol_render hol_render;

enum {
    HOL_RENDER_EUCLIDEAN = 1, /* flat room baseline: no portals */
    HOL_RENDER_BARE = 2,      /* floors only: no trees, hedges or props */
    HOL_RENDER_IDS = 4,       /* ID mode (see above) */
    HOL_RENDER_NO_HUD = 8,
    HOL_RENDER_MINIMAP = 16,  /* draw the minimap and HUD text */
    HOL_RENDER_MINIMAP_HAND = 32, /* with MINIMAP: the map on a quad in the
                                     hand (hand_* below), the text on screen */
    HOL_RENDER_NO_POLES = 64,     /* no guide poles over the objectives */
    HOL_RENDER_NO_HOT_COLD = 128, /* minimap tiles grey, not hot-cold */
    HOL_RENDER_NO_ARROW = 256,    /* no rim arrows towards far objectives */
    HOL_RENDER_WAIT = 512,        /* wait for the GL to finish the frame
                                     (glFinish), so out_stats' times include
                                     the GPU's: benches and --frames timings
                                     only, never in a frame loop */
    HOL_RENDER_HUD_TEXT = 1024,   /* the HUD text, with or without the minimap
                                     (MINIMAP implies it): a map that is off
                                     never takes the objective, steps, time,
                                     result or prompt with it */
    HOL_RENDER_LIGHT_ONLY = 4096, /* tests, at dusk and night: a tile's
                                     pixel is (lanterns' sum, fog factor,
                                     fireflies' sum)
                                     (docs/rendering.md#lighting) */
    HOL_RENDER_PANEL = 2048,      /* a headset's eye: the HUD text (and the
                                     minimap unless in the hand) on a panel
                                     in the world (panel_* below), not on
                                     the screen */
    HOL_RENDER_PANEL_LAYER = 8192 /* with PANEL: the panel is shown by the
                                     runtime (a composition layer drawn by
                                     hol_render_panel_image): the eye leaves
                                     it out (a map in the hand stays) */
};

#define HOL_RENDER_MAX_OBJECTIVES 8
#define HOL_RENDER_HUD_LINES 6
#define HOL_RENDER_MAX_MARKS 2
/* Lanterns a frame may name (a level's 8 placed, one per objective). */
#define HOL_RENDER_MAX_LANTERNS 16

/* hol_frame_desc.lighting (the same numbers as core's hol_app_lighting). */
enum { HOL_RENDER_DAY = 0, HOL_RENDER_DUSK = 1, HOL_RENDER_NIGHT = 2 };

/* Game object kinds (hol_frame_desc.object_kinds). */
enum {
    HOL_RENDER_OBJ_NONE = 0,
    HOL_RENDER_OBJ_FLAG,
    HOL_RENDER_OBJ_KEY,
    HOL_RENDER_OBJ_CHEST,      /* closed */
    HOL_RENDER_OBJ_CHEST_OPEN, /* every key held */
    HOL_RENDER_OBJ_MARKER      /* a tutorial lesson's marker: a glowing
                                  violet ring on the ground round a violet
                                  post with a glowing orb (no cloth: not a
                                  flag) */
};

typedef struct hol_frame_desc {
    hol_room user;     /* tile (its tiling), orientation, cell, room size */
    double cell_m;     /* a cell's side in metres, 0.5..1.5; 0: 1 */
    hol_camera cam;
    int flags;
    /* HUD / minimap (optional) */
    int nobjectives;   /* minimap markers and guide poles */
    hol_tile objectives[HOL_RENDER_MAX_OBJECTIVES];
    /* Game objects to draw (the app says which; the world's reserved game
     * objects are not drawn from its content): a tile and a HOL_RENDER_OBJ_*
     * kind each, at the tile's centre. */
    int nobjects;
    hol_tile object_tiles[HOL_RENDER_MAX_OBJECTIVES];
    uint8_t object_kinds[HOL_RENDER_MAX_OBJECTIVES];
    /* A marked tree (the tutorial's tree to walk round): tree_marked 1
     * puts two glowing violet bands round the trunk on room vertex
     * (tree_vertex[0], tree_vertex[1]), at x = tree_vertex[0] * cell_m,
     * z = tree_vertex[1] * cell_m, and the marker's ring round its foot. */
    int tree_marked;
    int tree_vertex[2];
    const char *objective_text; /* e.g. "find the key"; NULL: none */
    int steps_taken;
    double time_s;
    const uint8_t *path; /* shortest-path overlay: room steps from the user */
    int npath;
    /* The HUD text as the app filled it at its step (hol_app_hud.lines):
     * when nhud_lines > 0, these lines are drawn as given instead of the
     * objective/steps/tile/time lines composed from the fields above. */
    const char *hud_lines[HOL_RENDER_HUD_LINES];
    int nhud_lines;
    /* The prompt (what the buttons do now, hol_app_hud.hint): drawn under
     * the text in yellow; NULL or "": none. */
    const char *prompt;
    /* A platform's overlay (e.g. "FPS 20.1 CPU 31.5 MS"): small, at the top
     * right; NULL or "": none. */
    const char *overlay;
    /* Tiles marked on the minimap (cyan rings), e.g. a tutorial lesson's
     * two tiles of one cell. */
    int nmarks;
    hol_tile marks[HOL_RENDER_MAX_MARKS];
    /* The minimap in the hand (HOL_RENDER_MINIMAP_HAND): a square of side
     * hand_size metres (0: 0.25) centred at hand_pos (room coordinates),
     * turned by the unit quaternion hand_orient (x, y, z, w; all zero:
     * identity). Unturned, the map faces +z (south) with room north up
     * (+y); the quad is drawn over the scene wherever the scene is farther. */
    double hand_pos[3];
    double hand_orient[4];
    double hand_size;
    /* Fade (the headset's safety boundary): the view is blended towards
     * fade_rgb by `fade` in [0, 1] (0: no fade), the HUD text stays on top.
     * At fade >= 1 the frame is fade_rgb alone: no view is built, so the eye
     * may lie anywhere, even outside the room. fade_rgb all zero: the hedge
     * green HOL_RENDER_FADE_RGB. */
    double fade;
    uint8_t fade_rgb[3];
    /* Where the frame goes in the framebuffer: its lower-left corner, in
     * pixels from the left and bottom (zero: the origin). A headset layer
     * that holds both eyes side by side (WebXR's XRWebGLLayer) gives each
     * eye's viewport here; the frame clears and draws only its own
     * cam.width x cam.height rectangle (scissor). */
    int vp_x, vp_y;
    /* The sky and its lights (docs/rendering.md#lighting): lighting 0 day
     * (the picture without lights, exactly as before), 1 dusk, 2 night
     * (hol_app_lighting); lanterns: tiles with a lantern over their centre
     * (lit at dusk and night). */
    int lighting;
    int nlanterns;
    hol_tile lanterns[HOL_RENDER_MAX_LANTERNS];
    /* A lantern's spot (render/hol_light.h): 0 a round lantern, 1..4 a spot
     * towards its tile's heading turned k - 1 quarter turns clockwise and
     * tilted 45 degrees down, 5 a spot straight down. */
    uint8_t lantern_spot[HOL_RENDER_MAX_LANTERNS];
    /* 1: fireflies over the creek and flower tiles near the user at dusk
     * and night (with desc.world; they circle with time_s), each a light
     * and a small glowing sprite at its place (not with HOL_RENDER_BARE). */
    int fireflies;
    /* The headset's panel (HOL_RENDER_PANEL): its centre panel_pos (room
     * coordinates), turned by the unit quaternion panel_orient (x, y, z, w;
     * unturned it faces +z, up +y), one font pixel panel_px metres (0:
     * HOL_RENDER_PANEL_PX). The text block and the map square beside it
     * (render/hol_hud.h) are drawn with the eye's view and projection,
     * after the scene and over it (no depth test): always readable, even
     * where a hedge or a trunk comes nearer than the panel. */
    double panel_pos[3];
    double panel_orient[4];
    double panel_px;
} hol_frame_desc;

/* 4.3 mm: a capital (7 font pixels) 30 mm high, 1.15 degrees at 1.5 m */
#define HOL_RENDER_PANEL_PX 0.0043

#define HOL_RENDER_FADE_RGB {56, 117, 61}

typedef struct hol_render_stats {
    int draw_calls;
    long triangles;
    int stencil_passes;   /* stencil-writing draws (leaves) */
    int branches;         /* branches drawn */
    int state_changes;    /* program/stencil/depth/mask changes issued */
    int tiles_built;      /* tile meshes (re)built this frame */
    long uploaded_bytes;  /* vertex + index bytes sent to GL this frame */
    double build_ms;      /* CPU time building and sorting the queue */
    double cpu_ms;        /* process CPU time of the frame incl. glFinish */
    double wall_ms;
} hol_render_stats;

/* Errors: HOL_EARG (no getproc), HOL_EUNSUPPORTED (a GL function or the
 * shaders are missing), HOL_ENOMEM. */
hol_err hol_render_create(const hol_render_desc *desc, hol_render **out);
void hol_render_destroy(hol_render *r);
/* Switch the world the content comes from (NULL: placeholder content). */
void hol_render_set_world(hol_render *r, struct hol_world *world);
/* Drop every resident mesh (they are rebuilt on use). Not needed when only
 * tile content changes: a tile's mesh is rebuilt when hol_world_get reports
 * other content than it was built from. */
void hol_render_invalidate(hol_render *r);

/* Render one eye into the current framebuffer (viewport: cam size at
 * vp_x, vp_y). The frame is queued: nothing in it waits for the GL (no
 * glGet*, glGetError, glFinish, glReadPixels), unless f->flags has
 * HOL_RENDER_WAIT (glFinish at the end: out_stats' times then include the
 * GPU's) or desc.debug is set (glGetError at the end: a GL error is
 * HOL_EUNSUPPORTED). out_stats' counts are filled either way.
 * Errors: HOL_EARG (eye not inside the user's cell unless fade >= 1, bad
 * size, a cell size outside 0.5..1.5),
 * HOL_ENOMEM (the fixed stores overflowed). */
hol_err hol_render_frame(hol_render *r, const hol_frame_desc *f,
                         hol_render_stats *out_stats);

/* The headset panel's content alone, for a composition layer (an OpenXR
 * quad layer, a WebXR XRQuadLayer): f as for an eye with HOL_RENDER_PANEL
 * (its text, flags, map; the camera and the panel's pose are not used).
 * hol_render_panel_key: a hash of everything the image shows (the text
 * block's vertices and size, the map's inputs), computed on the CPU (it
 * may upload a changed resident map, as a frame would): equal keys, equal
 * images, so the caller redraws only when the key changes.
 * hol_render_panel_image: draws the image into the current framebuffer at
 * (0, 0), w x h pixels: the panel's box (hol_hud_panel_box in
 * render/hol_hud.h) fills it, x right and y up as GL's (row 0 at the
 * bottom), the rest of the box cleared to transparent (0, 0, 0, 0), the
 * panel's own pixels opaque. Errors: HOL_EARG (a size outside 1..the
 * renderer's maximum), HOL_ENOMEM. */
uint64_t hol_render_panel_key(hol_render *r, const hol_frame_desc *f);
hol_err hol_render_panel_image(hol_render *r, const hol_frame_desc *f, int w, int h);

/* With desc.lazy_programs: compile one more of the programs not compiled
 * yet. Returns how
 * many are left, 0 when all are made, or -1 when this one failed (its
 * first frame would fail the same way). Each compile waits for the GL
 * (its status): the web compiles them all in the frame after its first. */
int hol_render_prepare(hol_render *r);

/* Ask the GL for errors now (one glGetError round trip): HOL_OK, or
 * HOL_EUNSUPPORTED when the GL reported one since the last check. For
 * init and after a resize; not per frame (see desc.debug). */
hol_err hol_render_check(hol_render *r);

/* The room state an eye sees from (stereo) is the core's business:
 * hol_motion_eye_state (core/hol_motion.h). */

/* The view of the last frame (branches, for decoding ID images). */
const hol_view *hol_render_last_view(const hol_render *r);

/* Read the framebuffer (w x h RGBA, rows top to bottom). */
void hol_render_read_rgba(hol_render *r, int w, int h, uint8_t *out_rgba);

/* Decode an ID-mode pixel: -1 for no floor, else the branch index. */
int hol_render_decode_id(const uint8_t rgba[4]);

#endif
