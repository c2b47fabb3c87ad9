/* hol_render_types.h - the types the renderer's parts share: a frame's
 * description (hol_frame_desc), its flags and limits, the frame's figures.
 *
 * Contract
 * - Plain data, no functions: render/hol_render.h (the renderer's API)
 *   and the parts it calls (hol_hud.h, hol_scene.h, hol_light.h, the
 *   renderer's own files through hol_render_int.h) include this header, so
 *   the renderer's arrows run one way: hol_render.c down to its parts,
 *   every part down to these types. The renderer's desc and its opaque
 *   handle are here too (its files below hol_render.c use them).
 * - Lighting is core's enum (hol_app_lighting in core/hol_app.h:
 *   HOL_LIGHT_DAY, _DUSK, _NIGHT); render has no copy of it.
 * - What the fields mean for the picture: render/hol_render.h's contract.
 */
#ifndef HOL_RENDER_TYPES_H
#define HOL_RENDER_TYPES_H

#include <stdint.h>

#include "../core/hol_alloc.h"
#include "../core/hol_app.h"
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
                                     (docs/lighting.md) */
    HOL_RENDER_PANEL = 2048,      /* a headset's eye: the HUD text (and the
                                     minimap unless in the hand) on a panel
                                     in the world (panel_* below), not on
                                     the screen */
    HOL_RENDER_PANEL_LAYER = 8192, /* with PANEL: the panel is shown by the
                                     runtime (a composition layer drawn by
                                     hol_render_panel_image): the eye leaves
                                     it out (a map in the hand stays) */
    HOL_RENDER_NO_SHADOWS = 16384 /* tests, at dusk and night: the lights
                                     without the trunks' and hedges'
                                     shadows */
};

#define HOL_RENDER_MAX_OBJECTIVES 8
#define HOL_RENDER_HUD_LINES 6
#define HOL_RENDER_MAX_MARKS 2
/* Lanterns a frame may name (a level's 8 placed, one per objective). */
#define HOL_RENDER_MAX_LANTERNS 16

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
    /* The language of the lines composed from the fields (hol_lang,
     * core/hol_str.h; 0: English); the app's lines come in its own. */
    int lang;
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
    /* The sky and its lights (docs/lighting.md): lighting is
     * core's hol_app_lighting: HOL_LIGHT_DAY (the picture without lights,
     * exactly as before), HOL_LIGHT_DUSK, HOL_LIGHT_NIGHT; lanterns: tiles with a lantern over their centre
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
    /* The sky between dusk and night (core's hol_app_view.night): with
     * cycle 1, night in 0..1 (0 dusk, 1 night) mixes the two skies (their
     * colour, fog, ambient and sun; lighting a lit one); cycle 0: the
     * lighting's own sky. */
    int cycle;
    double night;
    /* 1: a carried lantern at carried_pos (room metres: its x, height and
     * z), lit at dusk and night like a placed one, in the room and every
     * tile through the portals (render/hol_light.h). */
    int carried;
    double carried_pos[3];
    /* The headset's panel (HOL_RENDER_PANEL): its centre panel_pos (room
     * coordinates), turned by the unit quaternion panel_orient (x, y, z, w;
     * unturned it faces +z, up +y), one font pixel panel_px metres (0:
     * HOL_RENDER_PANEL_PX). The text block and the map square beside it
     * (render/hol_hud.h) are drawn with the eye's view and projection,
     * after the scene, depth-tested (no depth writes): hidden where the
     * scene is nearer, never drawn over it. The app places it in front of
     * the nearest hedge or trunk (core/hol_panel.h), scaled by panel_px. */
    double panel_pos[3];
    double panel_orient[4];
    double panel_px;
    /* The body (core/hol_body.h: controllers, tracked hands, the pointing
     * ray; NULL: none): drawn in room coordinates in the room's pass
     * (render/hol_body_draw.h), depth-tested and written, with the room's
     * light, in every tile the same: never moved by a tile's transform.
     * Not with HOL_RENDER_BARE. */
    const hol_body *body;
    /* Outside the room (core's hol_app_view.outside; a headset's eyes,
     * drawn where the head is: the eye may stand outside the room, the
     * view is then built from the eye's nearest point in user's cell, a
     * millimetre inside, which is also the programs' eye): the view dimmed
     * towards HOL_RENDER_OUTSIDE_RGB by at least HOL_RENDER_OUTSIDE_DIM
     * (the fade pass; a larger `fade` wins), the panel over everything (no
     * depth test: readable wherever it stands), and a flat arrow on the
     * floor, HOL_RENDER_ARROW_M long, its centre at outside_arrow (room
     * coordinates), pointing along outside_yaw_deg (SPEC 1's yaw), drawn
     * over everything. 0: none. */
    int outside;
    double outside_arrow[3];
    double outside_yaw_deg;
} hol_frame_desc;

#define HOL_RENDER_OUTSIDE_DIM 0.6
#define HOL_RENDER_OUTSIDE_RGB {4, 8, 5}
#define HOL_RENDER_ARROW_M 0.6
#define HOL_RENDER_ARROW_RGB {255, 215, 60} /* the prompt's yellow */

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

#endif
