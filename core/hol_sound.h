/* hol_sound.h - the forest you hear (issue 27): which sound sources play
 * around the listener, where they are and how loud, chosen once in core;
 * a platform (platform/audio) only carries the list out. Also the
 * procedural synthesis of every sound (no asset files).
 *
 * Contract
 * - Sources (hol_sound_kind):
 *   ambience (level line `sound all` only): birdsong from every tile with a
 *   tree of size >= 2 whose tile word hashes to 0 mod 3 (one tree in three
 *   sings), at the tile's centre 3 m up; water from every creek, spring or
 *   pool tile, at its centre on the floor; wind in the room's four hedges,
 *   at the middle of each room side 1 m up (the hedges are the room's own,
 *   so their place is the room's, not the world's);
 *   effects (`all` and `cues`): a footstep on every room step, by the
 *   surface of the tile stepped onto (water for creek, spring and pool
 *   tiles, grass for grass and flower tiles, earth otherwise), at the feet;
 *   a chime when a key is collected, the chest opens, the flag is reached
 *   and the level starts, at the listener;
 *   beacons (`all` and `cues`, and the level's cues include `sound`): one
 *   on each objective still to reach, at its tile's centre 1.5 m up.
 * - Geometry (H^2 x E, as render/hol_light.h): the listener is the head's
 *   point: its offset from its cell's centre mapped to the user tile's
 *   Klein square (K = (x, -z) tanh(r_in) / (M/2)), lifted to the
 *   hyperboloid; a tile's centre comes from hol_hyper_frame(user tile,
 *   room orientation, tile). The floor distance is 2 asinh(c/2) (c the
 *   Lorentz norm of the chord) in curvature units, times M / e metres
 *   (e = hol_hyper_edge_q: a step is one cell); |chord| in {4,4}. The
 *   true distance is d = sqrt(floor^2 + dh^2).
 * - Falloff: G(d) = W(d) sqrt(s) / (1 + d / D0), with s = x / sinh x
 *   (x the floor distance in curvature units; 1 in {4,4}) the spreading of
 *   H^2 (a circle's length grows as sinh: the intensity falls as s / d^2,
 *   so the amplitude as sqrt(s) / d), an inverse distance softened within
 *   D0 = 1 m (1 / (1 + d) for 1 / d: the one departure from the physics,
 *   so that a source at the ear is not infinitely loud), and
 *   W(d) = (1 - (d/R)^2)^2 below R, 0 beyond, for ambience (so a source
 *   fades in and out without a pop); R = hol_sound_radius_m
 *   (HOL_SOUND_RADIUS_M, or less in {4,q>4}: HOL_SOUND_HORIZON curvature
 *   radii; the tiles within a radius grow as e^r: the horizon bounds the
 *   work), cut to the world's generated radius (no nearer than the
 *   nearest tile more than hol_world_radius steps from the user's, less a
 *   tile's circumradius: no source appears as a tile collapses; the
 *   listener's hol_sound.radius); the hedges' wind has
 *   R = HOL_SOUND_RADIUS_M (room space).
 *   Beacons have no window (W = 1) and are heard from any distance a frame
 *   reaches. Effects at the listener have gain 1 (footsteps 0.6).
 * - Direction: the initial direction of the geodesic from the listener to
 *   the source: the tangent S + <P,S> P at the listener's point P, boosted
 *   to the origin (the floor part, room east and north), the height
 *   difference as the vertical part, weighted by the floor distance in
 *   metres; then turned into the head's frame (view.head_quat: x right,
 *   y up, -z ahead, OpenAL's listener axes). What the player hears
 *   follows the world's geodesics, not the room's portals: a source seen
 *   through a portal in one cell may be heard from another direction (that
 *   is holonomy made audible; docs/sound.md).
 * - Which: by true distance, not by steps: beacons first, then every
 *   ambient source whose gain is above 0 (every tile whose centre is
 *   within R, found breadth first through the tiles whose centre lies
 *   within R plus a tile's circumradius) and the wind. When more than fit
 *   (HOL_SOUND_MAX_SOURCES), the loudest that fit play, each less the gain
 *   of the loudest left out: a source enters and leaves the list at gain 0
 *   (a continuous cross-fade at the cap; the window is the cross-fade at
 *   the radius). Each with a stable id (kind and tile) so a platform keeps
 *   the same voice playing from frame to frame. Effects of the step come
 *   as shots (played once).
 * - Pure: no allocation, no OS, no libm (core/hol_math.h); the same view,
 *   events and world give the same list, bit for bit.
 * - Synthesis (hol_sound_synth): every kind's buffer, mono 16-bit at the
 *   given rate, from a fixed seed per kind (a xorshift generator, sines
 *   and one-pole filters): loops of 2 s (birds, water, wind, beacon),
 *   shots of 0.12 s (footsteps) and 1.2 s (chimes).
 */
#ifndef HOL_SOUND_H
#define HOL_SOUND_H

#include <stdint.h>

#include "hol_app.h"
#include "hol_err.h"

#define HOL_SOUND_MAX_SOURCES 32
#define HOL_SOUND_MAX_SHOTS 8
#define HOL_SOUND_RADIUS_M 4.0
#define HOL_SOUND_D0_M 1.0
#define HOL_SOUND_HORIZON 3.5
#define HOL_SOUND_RATE 48000

typedef enum hol_sound_kind {
    HOL_SND_BIRDS = 0,
    HOL_SND_WATER,
    HOL_SND_WIND,
    HOL_SND_BEACON,
    HOL_SND_STEP_EARTH,
    HOL_SND_STEP_GRASS,
    HOL_SND_STEP_WATER,
    HOL_SND_CHIME_KEY,
    HOL_SND_CHIME_CHEST,
    HOL_SND_CHIME_FLAG,
    HOL_SND_CHIME_START,
    HOL_SND_KINDS
} hol_sound_kind;

typedef struct hol_sound_src {
    int kind;          /* hol_sound_kind */
    uint32_t id;       /* stable per (kind, tile / hedge) for loops */
    double gain;       /* 0..1: THE gain (no other rolloff) */
    double dir[3];     /* unit, head frame: x right, y up, -z ahead */
    double dist_m;     /* true distance (0 for effects) */
} hol_sound_src;

typedef struct hol_sound_list {
    int n;                                   /* loops playing this frame */
    hol_sound_src src[HOL_SOUND_MAX_SOURCES];
    int nshots;                              /* effects starting now */
    hol_sound_src shot[HOL_SOUND_MAX_SHOTS];
    int beacons;                             /* beacons in src[] */
} hol_sound_list;

/* One ambient source of the cache: its tile's centre (user frame). */
typedef struct hol_sound_amb {
    double S[3];
    double h;          /* metres up */
    int kind;
    uint32_t id;
} hol_sound_amb;

#define HOL_SOUND_MAX_AMB 256

/* What one listener remembers between frames: to see a key collected, and
 * the ambient sources around the user's tile (a cache: rebuilt whenever
 * the user's tile, its orientation, the cell size or the world's tiles
 * change, so the list is the same as without it). */
typedef struct hol_sound {
    int keys_held;
    int state;
    int valid;                 /* 1: the cache below holds */
    hol_room user;
    double cell_m;
    const struct hol_world *world;
    uint64_t world_key[5];     /* collapses, backtracks, evictions, count,
                                  seed */
    double radius;             /* the ambience's window R, metres */
    int namb;
    hol_sound_amb amb[HOL_SOUND_MAX_AMB];
} hol_sound;

void hol_sound_init(hol_sound *s);

/* The sources of this frame, from the app's view and events and the world
 * (tiles read with hol_world_peek: only collapsed tiles sound). The level's
 * sound line is view->sound (hol_app_sound); HOL_SOUND_OFF gives an empty
 * list. Errors: HOL_EARG (a NULL argument). */
hol_err hol_sound_update(hol_sound *s, const hol_app_view *v, const hol_app_events *ev,
                         const struct hol_world *w, hol_sound_list *out);

/* The documented falloff: d_m the true distance in metres, chord the
 * Lorentz norm of the floor chord (the floor distance in curvature units is
 * x = 2 asinh(chord/2), and sinh x = chord sqrt(1 + chord^2/4): no exp in
 * core), flat 1 in {4,4} (s = 1), radius_m the window's R (0: none). */
double hol_sound_falloff(double d_m, double chord, int flat, double radius_m);
/* The ambience's window R in metres in {4,q} with cells of cell_m (0: 1). */
double hol_sound_radius_m(int q, double cell_m);

/* Samples of a kind's buffer at `rate` Hz (0 for a bad kind). */
int hol_sound_length(int kind, int rate);
/* 1: the kind loops (ambience and beacons); 0: played once. */
int hol_sound_loops(int kind);
/* Fill out[0..n) with the kind's sound (n from hol_sound_length). */
hol_err hol_sound_synth(int kind, int rate, int16_t *out, int n);
const char *hol_sound_kind_name(int kind);

#endif
