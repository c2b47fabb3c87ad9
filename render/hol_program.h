/* hol_program.h - the renderer's shader programs as data: a key names a
 * variant, one slot holds it.
 *
 * Contract
 * - Every program is the same two shaders (render/shaders/scene.vert.glsl
 *   and scene.frag.glsl, made into C strings at build time by
 *   render/shaders/glsl_c.sh) after a preamble of defines written from its
 *   key (hol_prog_preamble), as sokol-shdc's variants are: no shader text
 *   is chosen by arithmetic.
 * - A key (hol_prog_key) says what varies: the lighting (core's
 *   hol_app_lighting), the lit room's meshes or the lit tiles, the flat
 *   {4,4} grid, the wedge's discard, the lights' effects (fireflies,
 *   spots), the shadow mask read, the lit room's lamps (its
 *   trees and hedges lantern-lit, or its backdrop on the cheaper path)
 *   and the lit tiles' per-vertex light (vlit: their small props).
 *   The day program has only the wedge; the lit room's the lighting, the
 *   lamps and the wedge; the lit tiles' the rest but the lamps.
 *   The text program (text = 1, every other field 0) draws the overlays
 *   (the HUD, the hand's map, the headset's panel): flat colours and the
 *   text face's glyphs from its signed-distance atlas (core/hol_face.h),
 *   read from attribute 3 (render/hol_mesh.h's HOL_MESH_GLYPH), with an
 *   alpha for blending.
 * - hol_prog_slot and hol_prog_key_of_slot are the one encoding between
 *   keys and the HOL_PROG_SLOTS slots of a program table (dense: every
 *   slot is a program): slot -> key -> slot is the identity, and a key no
 *   program has (day at night, a room with spots, ...) has slot -1.
 *   Nothing else computes with slot numbers. The encoding is a table
 *   (hol_program.c): the families of programs, each a base key and the
 *   dimensions it varies; a new dimension is a row, not arithmetic.
 * - hol_prog_make compiles and links a key's program through the loaded
 *   GL (render/hol_gl.h) and finds its uniforms (-1: not in it). It waits
 *   for the GL (compile and link status).
 */
#ifndef HOL_PROGRAM_H
#define HOL_PROGRAM_H

#include <stddef.h>

#include "hol_gl.h"

/* hol_prog_key.fx: what the lit tiles' lights do beyond lanterns (the
 * shaders' HOL_FX): each lit tile's own (what its four slots hold: the
 * renderer's hol__item.fx), at most the frame's hol_light_frame.fx, so a
 * tile lit only by round lanterns takes the plain program even in a
 * frame with fireflies or spots. A new kind of light
 * that needs code of its own takes the next value before
 * HOL_PROG_FX_COUNT (docs/hacking.md#adding-a-light-type). */
enum {
    HOL_PROG_FX_NONE = 0,
    HOL_PROG_FX_FIREFLIES = 1, /* per-light heights and weights */
    HOL_PROG_FX_SPOTS = 2,     /* and the spots' cones */
    HOL_PROG_FX_COUNT
};

typedef struct hol_prog_key {
    int lighting;     /* HOL_LIGHT_DAY, _DUSK, _NIGHT (core/hol_app.h), or
                       * HOL_PROG_CYCLE: a sky between dusk and night, its
                       * ambient and sun light uniforms (a lighting cycle) */
    int room;         /* lit: 1 the room's own meshes (no tile code) */
    int flat;         /* lit tiles: the flat {4,4} grid */
    int wedge;        /* discard outside a branch's wedge (hol_view.h) */
    int fx;           /* lit tiles: HOL_PROG_FX_* */
    int shadow;       /* lit tiles: 1 its shadow mask read (core/hol_shadow.h) */
    int text;         /* the overlays' program (every other field 0) */
    int lamps;        /* lit room: 1 its trees and hedges, lantern-lit with
                       * a Lambert term; 0 its backdrop and outer ground
                       * (ambient and sun only, the cheaper path) */
    int vlit;         /* lit tiles: 1 lit per vertex (a tile's small props:
                       * the vertex shader lights, fogs and tone maps, the
                       * fragment only writes; fx below spots) */
    int floor;        /* lit tiles: 1 a tile's ground (its normal straight
                       * up: none to turn to the eye, no Lambert term's
                       * horizontal part; no wedge) */
} hol_prog_key;

/* Rows of per-light values a lit tile gives its shaders (u_tx, four
 * lights a row: render/hol_render_tiles.c's hol__item_lights; the shaders'
 * HOL_TX_ROWS). */
#define HOL_PROG_TX_ROWS 7

/* The key's lighting between dusk and night (after HOL_LIGHT_NIGHT). */
#define HOL_PROG_CYCLE 3

/* day 2 (wedge), lit room 3 x 2 x 2 (lighting, lamps, wedge), lit tiles
 * 3 x 2 x 2 (lighting, flat, wedge) x HOL_PROG_FX_COUNT x 2 (shadow
 * mask), their small props the same with the effects below spots
 * (vlit), their ground 3 x 2 (lighting, flat) x HOL_PROG_FX_COUNT x 2
 * (floor), text 1: 171 (render/hol_program.c's table of families) */
#define HOL_PROG_SLOTS \
    (2 + 12 + 12 * HOL_PROG_FX_COUNT * 2 + 12 * HOL_PROG_FX_SPOTS * 2 + 6 * HOL_PROG_FX_COUNT * 2 + 1)
/* The text program's slot (the last). */
#define HOL_PROG_TEXT_SLOT (HOL_PROG_SLOTS - 1)

/* The slot of key, or -1 when no program has that key. */
int hol_prog_slot(const hol_prog_key *key);
/* The key of slot (0 <= slot < HOL_PROG_SLOTS). */
hol_prog_key hol_prog_key_of_slot(int slot);

/* The preamble of key's shaders ("#version 300 es" and the defines) into
 * out (n bytes, NUL-terminated); the length, or -1 when it did not fit. */
int hol_prog_preamble(const hol_prog_key *key, char *out, size_t n);

/* A program and its uniforms (-1: not in this program). */
typedef struct hol_prog {
    GLuint prog;
    GLint u_vp, u_model, u_mode, u_id, u_eye, u_fog, u_fogd, u_lin, u_wedge, u_wmode;
    GLint u_light, u_klein, u_mpu2, u_tl, u_eyeh, u_lonly, u_tx, u_shr, u_shm, u_atlas, u_amb,
        u_sun;
} hol_prog;

/* Compile and link key's program into out: 0, or 1 when the GL refused it
 * (nothing left half-made: out->prog stays 0). */
int hol_prog_make(const hol_gl *gl, const hol_prog_key *key, hol_prog *out);

#endif
