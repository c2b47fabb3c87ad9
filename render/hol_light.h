/* hol_light.h - lights in the world's geometry (issue 27): where every
 * drawn point lies on the hyperboloid, which lanterns light each drawn
 * tile, and the falloff. Pure CPU data prep for the renderer's shader (no
 * GL); the tests model the same formulas independently.
 *
 * Contract
 * - The frame near the user: the user's tile U with +y room north (the
 *   hyperboloid frame of hol_hyper_frame(U, user.orient, .)); every point
 *   and light of a frame is in it, so the numbers a frame uses stay small
 *   near the user (lights farther than the radius are never used).
 * - The map of a tile: a point of a tile mesh at (x, z) metres in the
 *   tile's own frame (the square [-M/2, M/2]^2, heading -z; M the cell
 *   side) has Klein coordinates K = (x, -z) * a / (M/2) in the tile's
 *   hyperbolic frame (+y its heading), a = tanh(r_in) the Klein radius of
 *   an edge's midpoint (r_in the inradius: cosh r_in = cos(pi/Q)/sin(pi/4)).
 *   The Klein model keeps geodesics straight, so the mesh's square is the
 *   true tile and neighbouring tiles meet exactly on their shared edge. Its
 *   hyperboloid point is (K, 1)/sqrt(1 - |K|^2), then the tile's frame
 *   (hol_light_tile) takes it to the user's frame. In the flat {4,4} the
 *   point is (x/M, -z/M, 1) (tile sides) and frames are rigid motions.
 * - Distances: the floor distance of two hyperboloid points is
 *   2 asinh(|p - q|_L / 2) (|.|_L the Lorentz norm of the chord: exact and
 *   without acosh's cancellation near 0), |p - q| in {4,4}; in metres times
 *   metres_per_unit = M / e (e the centre distance of neighbours,
 *   hol_hyper_edge_q: a step is one cell). The true distance in H^2 x E is
 *   sqrt(floor^2 + dh^2), dh the height difference in metres.
 * - Falloff (hol_light_falloff): F(d) = W(d) (1 - B + B s) / (1 + (d/D0)^2)
 *   with W(d) = (1 - (d/R)^2)^2 for d < R and 0 beyond (R =
 *   HOL_LIGHT_RADIUS_M: a light reaches no farther, which keeps the choice
 *   per tile exact), s = x / sinh(x) for the floor distance x in curvature
 *   units (1 in {4,4}): the physical spreading of H^2 (a circle's length
 *   grows as sinh) blended by B = HOL_LIGHT_PHYS into the softened inverse
 *   square of the ray-marchers' default, so the forest stays readable.
 * - A surface at height h with normal n lit by a lantern at height L gets
 *   F(d) (0.3 + 0.7 max(n_y, 0) max(L - h, 0) / d); the shader sums the
 *   tile's lights (render/hol_render_tiles.c), and maps the lanterns'
 *   sum S by the tone curve T(S) = S K / (K + S) (Reinhard's, white level
 *   K = HOL_LIGHT_TONE_K = 1/4: the lanterns' colour times K is (0.44,
 *   0.25, 0.085) in linear light, so they light a surface to at most about
 *   3/4 of its sRGB value in red).
 *   It gets them in the tile's own
 *   frame (the renderer applies the inverse of hol_light_tile's frame), so
 *   for the fragment's Klein point K, cosh x = (l_z - K.l_xy) /
 *   sqrt(1 - |K|^2), the first factor affine in the mesh (the vertex
 *   shader's); sinh x = sqrt(cosh^2 x - 1) by the chord, x = log(cosh x +
 *   sinh x), the window and inverse square from d^2: the same numbers.
 * - A lantern hangs HOL_LIGHT_HEIGHT_M over its tile's centre. A carried
 *   lantern (f->carried) is a round lantern at f->carried_pos: its room
 *   offset from the user's cell centre is a point of the user's tile (as
 *   the eye's), at that height; it follows the lanterns (before the
 *   fireflies), so every tile within reach takes it, through portals;
 *   at a height other than HOL_LIGHT_HEIGHT_M, fx is at least 1 (the
 *   programs that take each light's height).
 * - Which lights: hol_light_tile gives a tile up to HOL_LIGHT_PER_TILE
 *   lights, among those whose floor distance to its centre is under R plus
 *   the tile's circumradius, the lanterns first, then the fireflies, each
 *   nearest to its centre first (so every light that reaches some point of
 *   the tile is chosen while at most 4 do; hol_light_budget keeps every
 *   drawn tile to at most 4 lanterns).
 * - Fireflies (f->fireflies, at dusk and night): over every creek, spring,
 *   pool and flower tile within HOL_LIGHT_FF_STEPS steps of the user's
 *   (the nearest HOL_LIGHT_MAX_FF), one small light; its place in the
 *   tile's own frame comes from the tile's address (hol_tile_hash), as the
 *   world's other fixed choices (hol_light_firefly): an offset of up to
 *   0.3 cell from the centre, 0.45..0.75 m up, circling 0.08 m around it
 *   (period 5..9 s by f->time_s; time 0 is the resting place). A firefly
 *   is a light like a lantern (the same falloff, distance and choice of
 *   four a tile) with its own height and a weight HOL_LIGHT_FF_WEIGHT in
 *   its own colour (yellow-green, the shader's u_fcol). The renderer
 *   draws each one as a small glowing sprite at its place too, in the
 *   tile's mesh coordinates (HOL_FF_SPRITE_*; not in HOL_RENDER_BARE).
 * - Spots (f->lantern_spot[k] != 0): the lantern's light only in a cone
 *   around its direction, given in the lantern tile's own frame: 1..4 its
 *   heading turned k - 1 quarter turns clockwise and tilted
 *   HOL_LIGHT_SPOT_TILT_DEG below the horizon, 5 straight down. The frame
 *   takes that tangent to the user's frame (pos's tangent sd, metres per
 *   unit folded in), the tile's frame to the drawing tile's. For a point P
 *   at true distance d, floor distance x, height difference dh below the
 *   light: cos(angle) = (x_m <u, t> + sin(tilt) dh) / d, t the unit
 *   tangent at the light of the geodesic towards P (= (P + <P,L> L) /
 *   sinh x on the hyperboloid, (P - L)/|P - L| flat), u the direction's
 *   horizontal part (|u| = cos tilt): the geodesic direction from the
 *   light in the light's frame, the same numbers as the distance. The
 *   light is then multiplied by smoothstep(cos OUTER, cos INNER, cos
 *   angle) (HOL_LIGHT_SPOT_*_DEG).
 * - Trunk shadows (issue 27): a trunk of radius HOL_SHADOW_TRUNK_M stands on
 *   every vertex of the tiling, taller (2.7 m and more) than any light, so
 *   a point P under its top is in its shadow from light L exactly when the
 *   floor geodesic segment from P to L's foot passes within the radius r
 *   of the trunk's axis T (H2 x E is a product). Outside the trunk's own
 *   disc that is where P lies beyond the geodesic through T perpendicular
 *   to LT and between the two geodesics from L tangent to T's circle:
 *   three half-planes, each affine in the drawing tile's Klein point k
 *   (geodesics are straight in Klein; hol_light_wedge). With d the signed
 *   distance from P into each (positive inside), the trunk's occlusion is
 *   o = clamp(1/2 + min(sinh d) m / (2 e), 0, 1) (m metres per unit, e =
 *   HOL_SHADOW_EDGE_M; flat: d in sides): a linear soft edge 2 e = 4 cm
 *   wide across the tangent geodesics, centred on them. The light is
 *   multiplied by max(0, 1 - the sum of the occlusions of its pairs).
 * - Which trunks cast (issue 38): every trunk casts the shadow of every
 *   lantern of a tile's four lights (the carried one included; not the
 *   fireflies) within R of it, so both sides of a tile edge agree
 *   wherever the budget keeps every lantern that reaches them.
 *   hol_light_shadows gives a tile up to HOL_SHADOW_PAIRS such pairs
 *   whose shadow reaches it beyond r + e from the trunk (the tile's Klein
 *   square clipped by the three half-planes), among the corners of the
 *   tiles whose centre lies within 2 rho + r of the segment from one of
 *   its lanterns to its centre (rho the circumradius) that lie within r of
 *   the convex hull of that lantern and the tile, nearest their light
 *   first. The renderer rasters a tile's pairs into its shadow mask
 *   (core/hol_shadow.h), which the shader samples once a fragment.
 * - Hedges (issue 38): the room's hedges, 2 m high, stand all round the
 *   room's cells, higher than any lantern; hol_light_budget drops every
 *   lantern (the fireflies are left) whose foot lies in none of the view's
 *   drawn tiles: outside the hedges, every floor geodesic from it to a
 *   point of the room crosses them.
 */
#ifndef HOL_LIGHT_H
#define HOL_LIGHT_H

#include "../core/hol_err.h"
#include "../core/hol_room.h"
#include "../core/hol_world.h"
#include "hol_render_types.h"

#define HOL_LIGHT_PER_TILE 4
#define HOL_LIGHT_RADIUS_M 3.0
#define HOL_LIGHT_HEIGHT_M 1.3
#define HOL_LIGHT_D0_M 1.0
#define HOL_LIGHT_PHYS 0.5
#define HOL_LIGHT_TONE_K 0.25 /* the lanterns' sum's white level */
/* The sRGB encode of linear light c (docs/lighting.md#linear-light), by
 * square roots: A sqrt(c) + B sqrt(sqrt(c)) + C c + D from c = 0.0031308
 * up, 12.92 c below; within 0.1 of a code of the sRGB formula (a minimax
 * fit; tests/test_render_light.c checks it at every code) */
#define HOL_SRGB_A 0.8337578
#define HOL_SRGB_B 0.2981037
#define HOL_SRGB_C -0.0553181
#define HOL_SRGB_D -0.0769025
#define HOL_LIGHT_MAX_FF 16
#define HOL_LIGHT_MAX (HOL_RENDER_MAX_LANTERNS + 1 + HOL_LIGHT_MAX_FF)
#define HOL_LIGHT_FF_STEPS 3
#define HOL_LIGHT_FF_WEIGHT 0.15
/* A firefly's sprite: an octahedron of this radius (metres) at its place,
 * drawn unlit (as a lantern's glass: 1.5 times this colour in linear
 * light) and fogged;
 * its luma stays under 200, the glass's (make xr-test finds the glass so) */
#define HOL_FF_SPRITE_M 0.04f
#define HOL_FF_SPRITE_RGB 150, 190, 80
#define HOL_LIGHT_SPOT_TILT_DEG 45.0
#define HOL_LIGHT_SPOT_OUTER_DEG 35.0
#define HOL_LIGHT_SPOT_INNER_DEG 25.0
#define HOL_SHADOW_PAIRS 32
/* the renderer's texture of shadow masks: columns and rows of masks */
#define HOL_SHADOW_ATLAS_COLS 16
#define HOL_SHADOW_ATLAS_ROWS 8
#define HOL_SHADOW_TRUNK_M 0.09
#define HOL_SHADOW_EDGE_M 0.02

struct hol_world;
struct hol_view;

typedef struct hol_light_frame {
    int flat;                 /* {4,4} */
    int q;
    hol_room user;
    double cell_m;
    double klein;             /* Klein coordinate per metre: a / (M/2);
                                 {4,4}: 1/M */
    double metres_per_unit;   /* M / e; {4,4}: M */
    double circum_m;          /* a tile's circumradius in metres */
    double eye[3];            /* the eye's point (user frame) */
    double eye_h;             /* its height, metres */
    int n;                    /* lights placed (lanterns, then fireflies) */
    double pos[HOL_LIGHT_MAX][3]; /* their points, user frame */
    double h[HOL_LIGHT_MAX];      /* their heights, metres */
    double wt[HOL_LIGHT_MAX];     /* their weights: 1, or lanterns merged
                                     into one (hol_light_budget) */
    uint8_t ff[HOL_LIGHT_MAX];    /* 1: a firefly */
    int nff;                      /* the fireflies' tiles and places (x, z,
                                     height in metres in the tile's own
                                     frame, hol_light_firefly), in the
                                     order placed: the renderer draws
                                     each one's sprite there */
    hol_tile ff_tile[HOL_LIGHT_MAX_FF];
    double ff_xzh[HOL_LIGHT_MAX_FF][3];
    double sd[HOL_LIGHT_MAX][3];  /* a spot's horizontal direction, a tangent
                                     at pos (user frame) of length
                                     cos(tilt) * metres_per_unit; 0 for
                                     down or no spot */
    double ssin[HOL_LIGHT_MAX];   /* a spot's sin(tilt); -2: no spot */
    int fx;                       /* 2: a spot is placed, 1: fireflies but
                                     no spot, 0: neither (the most of the
                                     renderer's HOL_FX programs; each
                                     tile takes the one its slots need) */
    /* trunk shadows, in a tile's own frame (curvature units; flat: sides) */
    double corner[4][3];          /* its corners: the trunks' axes */
    double refl[4][9];            /* the reflections in its four edges */
    double rho;                   /* its circumradius */
    double trunk_r;               /* HOL_SHADOW_TRUNK_M */
    double reach;                 /* HOL_LIGHT_RADIUS_M */
} hol_light_frame;

/* A tile's trunk shadow pairs (hol_light_shadows), in the tile's own
 * frame: each a trunk and the light that casts its shadow. */
typedef struct hol_shadow_set {
    int n;                                /* pairs, 0..HOL_SHADOW_PAIRS */
    int slot[HOL_SHADOW_PAIRS];           /* each pair's light: its index
                                             in lp */
    double trunk[HOL_SHADOW_PAIRS][3];    /* the trunks' points */
} hol_shadow_set;

/* The frame's lights from f (the user, the cell, the eye, the lanterns and
 * their spots; with f->fireflies and a world, the fireflies of its tiles).
 * A light whose tile is too far from the user's for a frame
 * (hol_hyper_frame fails) is dropped. HOL_EARG: a cell outside 0.5..1.5. */
hol_err hol_light_prepare(const hol_frame_desc *f, const struct hol_world *w,
                          hol_light_frame *out);

/* The hedges (see the contract): the lanterns whose foot lies in no drawn
 * tile of view v leave lf. Then the budget (no seams past four lanterns):
 * while some tile of view v has
 * more than HOL_LIGHT_PER_TILE of lf's lanterns (not fireflies) within
 * reach (hol_light_tile's rule), one step on the first such tile: its two
 * nearest round lanterns become one (the weighted mean of the two points
 * on the hyperboloid, the mean height, the summed weight: every lit
 * tile's program takes the weights), else (spots) its lantern farthest from
 * the user leaves. A decision for the whole frame, so every tile takes
 * every lantern that reaches it (hol_light_tile takes lanterns before
 * fireflies) and the lanterns' light is continuous across every tile edge;
 * fireflies fill the slots left, nearest first, so theirs may still step
 * where lanterns fill a tile (docs/lighting.md). */
void hol_light_budget(hol_light_frame *lf, const struct hol_view *v);

/* The index into lf->ff_tile of tile t's firefly, or -1 (none placed). */
int hol_light_ff_of(const hol_light_frame *lf, hol_tile t);

/* Tile t's firefly at time_s: 1 and its place (x, z metres in the tile's
 * own frame, as the tile meshes; height in metres) when content c has one
 * (creek, spring, pool or flowers), else 0. */
int hol_light_firefly(hol_tile t, const hol_tile_content *c, double cell_m, double time_s,
                      double out_xzh[3]);

/* Tile t's frame in the user's frame (row-major 3x3) and its lights
 * (indices into lf->pos, nearest first); returns how many (0..4), or -1
 * when t is too far for a frame. */
int hol_light_tile(const hol_light_frame *lf, hol_tile t, double out_frame[9],
                   int out_idx[HOL_LIGHT_PER_TILE]);

/* The trunk shadow pairs of a tile (see the contract): fr its frame
 * (hol_light_tile; not needed since every lantern casts, kept for the
 * callers), lp[0..nl-1] its lights' points in its own frame (hyperboloid;
 * flat (x, y, 1)), lidx[i] their indices in lf (a firefly casts none).
 * Deterministic; no allocation. */
void hol_light_shadows(const hol_light_frame *lf, const double fr[9], const double lp[][3],
                       const int *lidx, int nl, hol_shadow_set *out);

/* The shadow of trunk t from light l (both in a tile's own frame) as three
 * affine functions of the tile's Klein point k: out[j] = (a, b, c), value
 * a k_x + b k_y + c. g value (g = 1/sqrt(1 - |k|^2); flat: 1) is
 * sinh d m / (2 HOL_SHADOW_EDGE_M), d the signed floor distance (curvature
 * units; flat: sides, no sinh) from the point to geodesic j, positive on
 * the shadow's side, m metres per unit: j 0 and 1 the geodesics from l
 * tangent to the trunk's circle, 2 the one through t perpendicular to lt
 * (beyond t). */
void hol_light_wedge(const hol_light_frame *lf, const double l[3], const double t[3],
                     double out[3][3]);

/* The distance (curvature units; flat: tile sides) from point t to the
 * geodesic segment from a to b. */
double hol_light_seg_dist(const double t[3], const double a[3], const double b[3], int flat);

/* The point of the tile map: (x, z) metres in a tile's own frame to its
 * hyperboloid point in that tile's frame (see the contract). */
void hol_light_point(const hol_light_frame *lf, double x, double z, double out_p[3]);

/* Floor distance of two points in metres. */
double hol_light_floor_m(const hol_light_frame *lf, const double p[3], const double l[3]);

/* F(d): d the true distance in metres, x the floor distance in curvature
 * units (ignored in {4,4}: pass 0). */
double hol_light_falloff(double d_m, double x_units, int flat);

#endif
