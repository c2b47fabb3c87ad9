/* hol_hud.c - HUD text and the Poincare minimap. */
#include "hol_hud.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../core/hol_face.h"
#include "../core/hol_hyper.h"
#include "../core/hol_nav.h"
#include "../core/hol_str.h"

#define HOL__PI 3.14159265358979323846

/* The HUD's em in pixels on a screen h pixels high: 24 at 720p, at
 * least 8 (a line of 9.3 pixels, the 5x7 font's 9 at 1x). */
static float hol__hud_size(int h)
{
    float s = (float)h / 30.0f;
    return s < 8 ? 8 : s;
}


typedef struct hol__px {
    hol_mesh *m;
    int w, h;
    int hand; /* lay the minimap out to fill the square (in the hand) */
} hol__px;

static void hol__v(hol__px *p, float x, float y, const uint8_t rgb[3])
{
    hol_vertex *v = &p->m->v[p->m->nv++];
    memset(v, 0, sizeof *v);
    v->pos[0] = 2.0f * x / (float)p->w - 1.0f;
    v->pos[1] = 1.0f - 2.0f * y / (float)p->h;
    v->rgba[0] = rgb[0];
    v->rgba[1] = rgb[1];
    v->rgba[2] = rgb[2];
    v->rgba[3] = HOL_MESH_PROP;
}

static void hol__rect(hol__px *p, float x0, float y0, float x1, float y1,
                      const uint8_t rgb[3])
{
    int64_t b = hol_mesh_reserve(p->m, 4, 6);
    if (b < 0)
        return;
    hol__v(p, x0, y0, rgb);
    hol__v(p, x1, y0, rgb);
    hol__v(p, x1, y1, rgb);
    hol__v(p, x0, y1, rgb);
    uint32_t u = (uint32_t)b, t[6] = {u, u + 1, u + 2, u, u + 2, u + 3};
    memcpy(p->m->idx + p->m->ni, t, sizeof t);
    p->m->ni += 6;
}

/* A convex polygon (pixel coordinates) as a fan. */
static void hol__poly(hol__px *p, const float (*xy)[2], int n, const uint8_t rgb[3])
{
    if (n < 3)
        return;
    int64_t b = hol_mesh_reserve(p->m, (uint32_t)n, (uint32_t)(3 * (n - 2)));
    if (b < 0)
        return;
    for (int i = 0; i < n; i++)
        hol__v(p, xy[i][0], xy[i][1], rgb);
    for (int i = 1; i + 1 < n; i++) {
        p->m->idx[p->m->ni++] = (uint32_t)b;
        p->m->idx[p->m->ni++] = (uint32_t)b + (uint32_t)i;
        p->m->idx[p->m->ni++] = (uint32_t)b + (uint32_t)i + 1;
    }
}

static void hol__segment(hol__px *p, float x0, float y0, float x1, float y1, float th,
                         const uint8_t rgb[3])
{
    float dx = x1 - x0, dy = y1 - y0, l = sqrtf(dx * dx + dy * dy);
    if (l <= 0)
        return;
    float nx = -dy / l * th / 2, ny = dx / l * th / 2;
    float q[4][2] = {{x0 + nx, y0 + ny}, {x1 + nx, y1 + ny}, {x1 - nx, y1 - ny},
                     {x0 - nx, y0 - ny}};
    hol__poly(p, (const float(*)[2])q, 4, rgb);
}

/* The text face's scale: font units and atlas pixels to the caller's. */
typedef struct hol__face {
    hol_face_metrics m;
    float aw, ah; /* the atlas's size */
} hol__face;

static hol__face hol__face_get(void)
{
    hol__face f;
    int w, h;
    hol_face_get_metrics(&f.m);
    hol_face_atlas(NULL, &w, &h);
    f.aw = (float)w;
    f.ah = (float)h;
    return f;
}

/* One glyph's quad: its atlas rectangle scaled by k from the pen (x, y). */
static void hol__glyph(hol__px *p, const hol__face *fc, const hol_face_glyph *g, float x, float y,
                       float k, const uint8_t rgb[3])
{
    int64_t b = hol_mesh_reserve(p->m, 4, 6);
    if (b < 0)
        return;
    float x0 = x + (float)g->qx * k, y0 = y + (float)g->qy * k;
    float x1 = x0 + (float)g->w * k, y1 = y0 + (float)g->h * k;
    float u0 = (float)g->x / fc->aw, v0 = (float)g->y / fc->ah;
    float u1 = (float)(g->x + g->w) / fc->aw, v1 = (float)(g->y + g->h) / fc->ah;
    const float c[4][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
    for (int i = 0; i < 4; i++) {
        hol__v(p, c[i][0], c[i][1], rgb);
        hol_vertex *v = &p->m->v[p->m->nv - 1];
        v->rgba[3] = HOL_MESH_GLYPH;
        hol_mesh_set_uv(v, c[i][2], c[i][3]);
    }
    uint32_t u = (uint32_t)b, t[6] = {u, u + 1, u + 2, u, u + 2, u + 3};
    memcpy(p->m->idx + p->m->ni, t, sizeof t);
    p->m->ni += 6;
}

/* The first len bytes of s from the pen (x, y on the baseline) at size;
 * the advance. */
static float hol__text(hol__px *p, const char *s, size_t len, float x, float y, float size,
                       const uint8_t rgb[3])
{
    hol__face fc = hol__face_get();
    float k = size / (float)fc.m.bake_em, per = size / (float)fc.m.units_per_em;
    long pen = 0;
    int prev = -1;
    for (size_t at = 0; at < len;) {
        int gi = hol_face_index(hol_face_decode(s, len, &at));
        if (prev >= 0)
            pen += hol_face_kerning(prev, gi);
        const hol_face_glyph gv = hol_face_glyph_at(gi), *g = &gv;
        if (g->w && g->h)
            hol__glyph(p, &fc, g, x + (float)pen * per, y, k, rgb);
        pen += g->advance;
        prev = gi;
    }
    return (float)pen * per;
}

float hol_hud_text(hol_mesh *out, const char *s, float x, float y, float size,
                   const uint8_t rgb[3], int w, int h)
{
    hol__px p = {out, w, h, 0};
    return hol__text(&p, s, strlen(s), x, y, size, rgb);
}

/* A size's ascent and line height (pixels). */
static float hol__ascent(float size)
{
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    return (float)m.ascent * size / (float)m.units_per_em;
}

static float hol__line_h(float size)
{
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    return (float)(m.ascent - m.descent) * size / (float)m.units_per_em;
}

/* Hot-cold colour: red at the objective, through yellow, to blue far. */
static void hol__hot(int hot, uint8_t rgb[3])
{
    if (hot < 0) {
        rgb[0] = 90;
        rgb[1] = 130;
        rgb[2] = 90;
        return;
    }
    float t = hot >= 6 ? 1.0f : (float)hot / 6.0f;
    float r = t < 0.5f ? 1.0f : 2.0f * (1.0f - t);
    float gch = t < 0.5f ? 0.3f + 1.2f * t : 0.9f - 1.2f * (t - 0.5f);
    float b = t < 0.5f ? 0.15f : 0.15f + 1.7f * (t - 0.5f);
    rgb[0] = (uint8_t)(40 + 200 * r);
    rgb[1] = (uint8_t)(40 + 180 * (gch < 0 ? 0 : gch));
    rgb[2] = (uint8_t)(40 + 200 * (b > 1 ? 1 : b));
}

/* The flat grid's top view shows this many tile sides from the centre to
 * the rim: the tiles within HOL_HUD_MAP_RADIUS steps (a diamond whose
 * farthest corners lie sqrt(4.5^2 + 0.5^2) ~ 4.53 sides out) fit. */
#define HOL__FLAT_SPAN (HOL_HUD_MAP_RADIUS + 0.75)

/* A point of the user's tile's frame to the map's unit disk: the Poincare
 * disk of a hyperboloid point ({4,Q}, Q >= 5), or a plain top view scaled
 * by HOL__FLAT_SPAN in the flat grid ({4,4}: (x, y, 1) in tile sides). */
static void hol__to_map(int q, const double p[3], double out[2])
{
    if (q == 4) {
        out[0] = p[0] / p[2] / HOL__FLAT_SPAN;
        out[1] = p[1] / p[2] / HOL__FLAT_SPAN;
        return;
    }
    hol_hyper_to_disk(p, out);
}

/* Point of tile-local coordinates (x, y, w) under frame m, to minimap
 * pixels. */
static void hol__map(int q, const double m[9], const double pt[3], float cx, float cy,
                     float rad, float out[2])
{
    double p[3];
    for (int i = 0; i < 3; i++)
        p[i] = m[3 * i] * pt[0] + m[3 * i + 1] * pt[1] + m[3 * i + 2] * pt[2];
    double d[2];
    hol__to_map(q, p, d);
    out[0] = cx + (float)(d[0] * rad);
    out[1] = cy - (float)(d[1] * rad);
}

/* The corners of a tile in its own frame: geodesic squares with corners at
 * circumradius acosh(cot(pi/Q)) in {4,Q}; the unit square in {4,4}. */
static void hol__tile_corners(int q, double corner[4][3])
{
    double rho = q == 4 ? 0 : acosh(1.0 / tan(HOL__PI / q)), shr = sinh(rho), chr = cosh(rho);
    for (int k = 0; k < 4; k++) {
        double a = HOL__PI / 4 + k * HOL__PI / 2;
        corner[k][0] = q == 4 ? sqrt(0.5) * cos(a) : shr * cos(a);
        corner[k][1] = q == 4 ? sqrt(0.5) * sin(a) : shr * sin(a);
        corner[k][2] = q == 4 ? 1 : chr;
    }
}

/* The HUD minimap: in the bottom right corner, a margin of 3 % of the
 * short side from the edges; its radius 16 % of the short side, less where
 * the map with its rim arrows (1.1 radii) would reach into the middle 40 %
 * of the view both ways (so that it never hides what lies ahead). */
static void hol__hud_layout(int w, int h, float *rad, float *cx, float *cy)
{
    float sh = (float)(w < h ? w : h), lg = (float)(w < h ? h : w), m = 0.03f * sh;
    float r = 0.16f * sh, cap = (0.3f * lg - m) / 2.2f - 1.0f;
    *rad = r < cap ? r : cap;
    *cx = (float)w - m - 1.1f * *rad;
    *cy = (float)h - m - 1.1f * *rad;
}

void hol_hud_map_rect(int w, int h, float out[4])
{
    float rad, cx, cy;
    hol__hud_layout(w, h, &rad, &cx, &cy);
    out[0] = cx - 1.1f * rad;
    out[1] = cy - 1.1f * rad;
    out[2] = cx + 1.1f * rad;
    out[3] = cy + 1.1f * rad;
}

static void hol__layout(const hol__px *p, float *rad, float *cx, float *cy)
{
    int w = p->w, h = p->h;
    if (p->hand) { /* centred, leaving room for the rim arrows */
        *rad = 0.42f * (float)(w < h ? w : h);
        *cx = 0.5f * (float)w;
        *cy = 0.5f * (float)h;
        return;
    }
    hol__hud_layout(w, h, rad, cx, cy);
}

/* The disk: a dark rim and a light ground. */
static void hol__map_disk(hol__px *p, float rad, float cx, float cy)
{
    static const uint8_t rim[3] = {20, 24, 30}, bg[3] = {200, 205, 210};
    float disk[48][2];
    for (int i = 0; i < 48; i++) {
        double a = 2 * HOL__PI * i / 48;
        disk[i][0] = cx + (rad + 2) * (float)cos(a);
        disk[i][1] = cy + (rad + 2) * (float)sin(a);
    }
    hol__poly(p, (const float(*)[2])disk, 48, rim);
    for (int i = 0; i < 48; i++) {
        double a = 2 * HOL__PI * i / 48;
        disk[i][0] = cx + rad * (float)cos(a);
        disk[i][1] = cy + rad * (float)sin(a);
    }
    hol__poly(p, (const float(*)[2])disk, 48, bg);
}

static void hol__map_tiles(hol__px *p, const hol_frame_desc *f, float rad, float cx, float cy)
{
    /* geodesic squares (hol__tile_corners), edges subdivided so they bend
     * like the disk's geodesics */
    hol_nav_cell cells[512];
    int q = hol_tile_q(f->user.tile);
    size_t n = 0;
    int nobj = f->nobjectives < HOL_RENDER_MAX_OBJECTIVES ? f->nobjectives : HOL_RENDER_MAX_OBJECTIVES;
    if (hol_nav_field(&f->user, HOL_HUD_MAP_RADIUS, f->objectives, (size_t)(nobj > 0 ? nobj : 0),
                      cells, sizeof cells / sizeof cells[0], &n))
        n = 0;
    double corner[4][3];
    hol__tile_corners(q, corner);
    for (size_t i = 0; i < n; i++) {
        double m[9];
        if (hol_hyper_frame(f->user.tile, f->user.orient, cells[i].tile, m))
            continue;
        uint8_t col[3];
        hol__hot((f->flags & HOL_RENDER_NO_HOT_COLD) ? -1 : cells[i].hot, col);
        float poly[16][2];
        int nq = 0;
        for (int k = 0; k < 4; k++)
            for (int s = 0; s < 4; s++) {
                /* point s/4 along the geodesic corner k -> k+1 */
                double t = s / 4.0, pt[3];
                for (int j = 0; j < 3; j++)
                    pt[j] = (1 - t) * corner[k][j] + t * corner[(k + 1) & 3][j];
                double nn = q == 4 ? 1 : sqrt(pt[2] * pt[2] - pt[0] * pt[0] - pt[1] * pt[1]);
                for (int j = 0; j < 3; j++)
                    pt[j] /= nn;
                hol__map(q, m, pt, cx, cy, rad * 0.985f, poly[nq++]);
            }
        /* shrink slightly towards the centre for visible seams */
        float mx = 0, my = 0;
        for (int k = 0; k < nq; k++) {
            mx += poly[k][0] / nq;
            my += poly[k][1] / nq;
        }
        for (int k = 0; k < nq; k++) {
            poly[k][0] = mx + 0.9f * (poly[k][0] - mx);
            poly[k][1] = my + 0.9f * (poly[k][1] - my);
        }
        hol__poly(p, (const float(*)[2])poly, nq, col);
    }
}

/* The shortest-path overlay: tile centres along the room walk. */
static void hol__map_path(hol__px *p, const hol_frame_desc *f, float rad, float cx, float cy)
{
    static const double origin[3] = {0, 0, 1};
    hol_room st = f->user;
    float prev[2] = {cx, cy};
    static const uint8_t pathc[3] = {250, 250, 250};
    for (int i = 0; i < f->npath && f->path; i++) {
        if (hol_room_step(&st, f->path[i]))
            break;
        double m[9];
        if (hol_hyper_frame(f->user.tile, f->user.orient, st.tile, m))
            break;
        float c[2];
        hol__map(hol_tile_q(st.tile), m, origin, cx, cy, rad * 0.985f, c);
        hol__segment(p, prev[0], prev[1], c[0], c[1], rad * 0.035f + 1, pathc);
        prev[0] = c[0];
        prev[1] = c[1];
    }
}

static void hol__map_marks(hol__px *p, const hol_frame_desc *f, float rad, float cx, float cy)
{
    /* marks: cyan rings round the tile centres (on the map only) */
    static const uint8_t markc[3] = {60, 230, 255};
    for (int k = 0; k < f->nmarks && k < HOL_RENDER_MAX_MARKS; k++) {
        double m[9], d[2];
        if (hol_tile_dist(f->user.tile, f->marks[k]) > HOL_HUD_MAP_RADIUS ||
            hol_hyper_frame(f->user.tile, f->user.orient, f->marks[k], m))
            continue;
        double pc[3] = {m[2], m[5], m[8]};
        hol__to_map(hol_tile_q(f->user.tile), pc, d);
        float c[2] = {cx + (float)(d[0] * rad * 0.985), cy - (float)(d[1] * rad * 0.985)};
        float rr = rad * 0.11f + 2, th = rad * 0.03f + 1;
        for (int i = 0; i < 16; i++) {
            double a0 = 2 * HOL__PI * i / 16, a1 = 2 * HOL__PI * (i + 1) / 16;
            hol__segment(p, c[0] + rr * (float)cos(a0), c[1] + rr * (float)sin(a0),
                         c[0] + rr * (float)cos(a1), c[1] + rr * (float)sin(a1), th, markc);
        }
    }
}

static void hol__map_objectives(hol__px *p, const hol_frame_desc *f, float rad, float cx, float cy)
{
    static const uint8_t rim[3] = {20, 24, 30};
    int nobj = f->nobjectives < HOL_RENDER_MAX_OBJECTIVES ? f->nobjectives : HOL_RENDER_MAX_OBJECTIVES;
    /* objectives: diamonds on the map, arrows on the rim when off it */
    static const uint8_t objc[3] = {255, 220, 40};
    for (int o = 0; o < nobj; o++) {
        double m[9], ang = 0, dist = 0;
        int on = 0;
        float c[2] = {cx, cy};
        if (!hol_hyper_frame(f->user.tile, f->user.orient, f->objectives[o], m)) {
            double pc[3] = {m[2], m[5], m[8]}, d[2];
            hol__to_map(hol_tile_q(f->user.tile), pc, d);
            on = hol_tile_dist(f->user.tile, f->objectives[o]) <= HOL_HUD_MAP_RADIUS;
            c[0] = cx + (float)(d[0] * rad * 0.985);
            c[1] = cy - (float)(d[1] * rad * 0.985);
        }
        if (on) {
            float s = rad * 0.07f + 1.5f;
            float dq[4][2] = {{c[0], c[1] - s}, {c[0] + s, c[1]}, {c[0], c[1] + s}, {c[0] - s, c[1]}};
            hol__poly(p, (const float(*)[2])dq, 4, rim);
            float s2 = s * 0.65f;
            float dq2[4][2] = {{c[0], c[1] - s2}, {c[0] + s2, c[1]}, {c[0], c[1] + s2}, {c[0] - s2, c[1]}};
            hol__poly(p, (const float(*)[2])dq2, 4, objc);
        } else if (!(f->flags & HOL_RENDER_NO_ARROW) &&
                   !hol_nav_direction(&f->user, f->objectives[o], &ang, &dist)) {
            /* angle counter-clockwise from room north: map direction (-sin, cos) */
            float ux = -(float)sin(ang), uy = -(float)cos(ang); /* pixel y down */
            float tipx = cx + ux * (rad + 0.10f * rad), tipy = cy + uy * (rad + 0.10f * rad);
            float bx = cx + ux * (rad - 0.06f * rad), by = cy + uy * (rad - 0.06f * rad);
            float s = 0.09f * rad + 1;
            float tri[3][2] = {{tipx, tipy}, {bx - uy * s, by + ux * s}, {bx + uy * s, by - ux * s}};
            hol__poly(p, (const float(*)[2])tri, 3, objc);
        }
    }}

/* The flat grid's map is no Poincare disk: a caption over it says so (on
 * the HUD right-aligned above the map, in the hand along its top). */
static void hol__map_caption(hol__px *p, float rad, float cx, float cy)
{
    static const char text[] = HOL_HUD_FLAT_CAPTION;
    static const uint8_t panel[3] = {24, 28, 34}, ink[3] = {240, 240, 230};
    float size = p->hand ? 24 : hol__hud_size(p->h), pad = 0.25f * size;
    float tw = hol_face_width(text, size), lh = hol__line_h(size), x, y;
    if (p->hand) {
        x = cx - tw / 2;
        y = pad;
    } else {
        x = cx + 1.1f * rad - tw;
        x = x < 2 * pad ? 2 * pad : x;
        y = cy - 1.1f * rad - lh - 2 * pad;
    }
    hol__rect(p, x - pad, y - pad / 2, x + tw + pad, y + lh + pad / 2, panel);
    hol__text(p, text, sizeof text - 1, x, y + hol__ascent(size), size, ink);
}

static void hol__minimap(hol__px *p, const hol_frame_desc *f)
{
    float rad, cx, cy;
    hol__layout(p, &rad, &cx, &cy);
    hol__map_disk(p, rad, cx, cy);
    hol__map_tiles(p, f, rad, cx, cy);
    hol__map_path(p, f, rad, cx, cy);
    hol__map_marks(p, f, rad, cx, cy);
    hol__map_objectives(p, f, rad, cx, cy);
    if (hol_tile_q(f->user.tile) == 4)
        hol__map_caption(p, rad, cx, cy);
}

static void hol__user_arrow(hol__px *p, const hol_frame_desc *f)
{
    float rad, cx, cy;
    hol__layout(p, &rad, &cx, &cy);
    /* the user: an arrow where the eye stands in the tile (the cell's
     * offset scaled so that a cell edge maps to the tile edge), pointing
     * along the view yaw */
    double cm = f->cell_m > 0 ? f->cell_m : 1.0;
    double ox = f->cam.eye[0] / cm - f->user.col - 0.5, on = -(f->cam.eye[2] / cm - f->user.row - 0.5);
    double ol = sqrt(ox * ox + on * on);
    int tq = hol_tile_q(f->user.tile);
    if (ol > 1e-9 && ol < 1) {
        double rr = ol * hol_hyper_edge_q(tq), d[2];
        double q[3] = {sinh(rr) * ox / ol, sinh(rr) * on / ol, cosh(rr)};
        if (tq == 4) {
            q[0] = ox;
            q[1] = on;
            q[2] = 1;
        }
        hol__to_map(tq, q, d);
        cx += (float)(d[0] * rad * 0.985);
        cy -= (float)(d[1] * rad * 0.985);
    }
    /* the view direction seen from above (works for headset poses too) */
    double br[3], bu[3], bb[3];
    hol_camera_basis(&f->cam, br, bu, bb);
    double yaw = (bb[0] * bb[0] + bb[2] * bb[2] > 1e-12) ? atan2(bb[0], bb[2])
                                                        : f->cam.yaw_deg * HOL__PI / 180;
    float ux = -(float)sin(yaw), uy = -(float)cos(yaw), s = 0.12f * rad + 2;
    float arrow[4][2] = {{cx + ux * s, cy + uy * s},
                         {cx - ux * s * 0.6f - uy * s * 0.6f, cy - uy * s * 0.6f + ux * s * 0.6f},
                         {cx - ux * s * 0.25f, cy - uy * s * 0.25f},
                         {cx - ux * s * 0.6f + uy * s * 0.6f, cy - uy * s * 0.6f - ux * s * 0.6f}};
    static const uint8_t userc[3] = {20, 20, 20};
    float t1[3][2] = {{arrow[0][0], arrow[0][1]}, {arrow[1][0], arrow[1][1]}, {arrow[2][0], arrow[2][1]}};
    float t2[3][2] = {{arrow[0][0], arrow[0][1]}, {arrow[2][0], arrow[2][1]}, {arrow[3][0], arrow[3][1]}};
    hol__poly(p, (const float(*)[2])t1, 3, userc);
    hol__poly(p, (const float(*)[2])t2, 3, userc);
}

void hol_hud_build_map(hol_mesh *out, const hol_frame_desc *f, int w, int h)
{
    hol__px p = {out, w, h, 0};
    hol__minimap(&p, f);
}

/* The hand's map lives in a square; its units do not matter (the renderer
 * scales the [-1, 1] square to the quad), only the proportions. */
#define HOL__HAND_PX 512

void hol_hud_build_hand_map(hol_mesh *out, const hol_frame_desc *f)
{
    hol__px p = {out, HOL__HAND_PX, HOL__HAND_PX, 1};
    hol__minimap(&p, f);
}

void hol_hud_build_hand_arrow(hol_mesh *out, const hol_frame_desc *f)
{
    hol__px p = {out, HOL__HAND_PX, HOL__HAND_PX, 1};
    hol__user_arrow(&p, f);
}

void hol_hud_build(hol_mesh *out, const hol_frame_desc *f, int w, int h)
{
    hol_hud_build_map(out, f, w, h);
    hol_hud_build_live(out, f, w, h);
}

void hol_hud_build_live(hol_mesh *out, const hol_frame_desc *f, int w, int h)
{
    hol__px p = {out, w, h, 0};
    hol__user_arrow(&p, f);
    hol_hud_build_text(out, f, w, h);
}

/* The lines to draw: the app's, or composed from the frame's fields. */
static int hol__text_lines(const hol_frame_desc *f, char lines[][96])
{
    int nl = 0;
    if (f->nhud_lines > 0) {
        for (int i = 0; i < f->nhud_lines && i < HOL_RENDER_HUD_LINES; i++)
            snprintf(lines[nl++], 96, "%.60s", f->hud_lines[i] ? f->hud_lines[i] : "");
    } else {
        char addr[HOL_TILE_ADDR_MAX];
        if (f->objective_text)
            snprintf(lines[nl++], 96, "%.40s", f->objective_text);
        hol_tile_print(f->user.tile, addr);
        snprintf(lines[nl++], 96, hol_str(f->lang, HOL_S_STEPS_FMT), f->steps_taken);
        snprintf(lines[nl++], 96, hol_str(f->lang, HOL_S_TILE_FMT), addr);
        long t = (long)(f->time_s > 0 ? f->time_s : 0);
        snprintf(lines[nl++], 96, hol_str(f->lang, HOL_S_TIME_FMT), t / 60 % 100000, t % 60);
    }
    if (f->prompt && f->prompt[0])
        snprintf(lines[nl++], 96, "%.60s", f->prompt);
    return nl;
}

/* The text: a panel at the top left (over the sky: the view's top is sky
 * at the usual pitch), the lines in white and the prompt last in yellow,
 * in the text face at hol__hud_size. The overlay is at the top right, a
 * size smaller. */
void hol_hud_build_text(hol_mesh *out, const hol_frame_desc *f, int w, int h)
{
    hol__px p = {out, w, h, 0};
    float size = hol__hud_size(h), lh = hol__line_h(size), pad = 0.25f * size;
    char lines[HOL_RENDER_HUD_LINES + 1][96];
    int nl = hol__text_lines(f, lines);
    int prompt = f->prompt && f->prompt[0];
    float longest = 0;
    for (int i = 0; i < nl; i++) {
        float lw = hol_face_width(lines[i], size);
        longest = lw > longest ? lw : longest;
    }
    static const uint8_t panel[3] = {24, 28, 34}, text[3] = {240, 240, 230},
                         yellow[3] = {255, 215, 60};
    float m = 1.5f * pad;
    if (nl > 0)
        hol__rect(&p, m, m, m + longest + 2 * pad, m + lh * (float)nl + pad, panel);
    for (int i = 0; i < nl; i++)
        hol__text(&p, lines[i], strlen(lines[i]), m + pad,
                  m + pad / 2 + hol__ascent(size) + lh * (float)i, size,
                  prompt && i == nl - 1 ? yellow : text);
    if (f->overlay && f->overlay[0]) {
        char o[64];
        snprintf(o, sizeof o, "%.60s", f->overlay);
        float so = 0.8f * size, po = 0.25f * so, ow = hol_face_width(o, so) + 2 * po;
        hol__rect(&p, (float)w - m - ow, m, (float)w - m, m + hol__line_h(so) + po, panel);
        hol__text(&p, o, strlen(o), (float)w - m - ow + po, m + po / 2 + hol__ascent(so), so,
                  text);
    }
}

/* The panel's em at glyph scale k (font pixels): a cap height of 7 font
 * pixels at k = 1 (the 5x7 font's, 1.15 degrees at the usual distance). */
static float hol__panel_size(float k)
{
    return 7.0f * k * hol_face_em_per_cap();
}

/* The wrapped lines of the panel at glyph scale k: one entry a screen
 * line, colours per line (0 text, 1 prompt). */
static int hol__panel_lines(const hol_frame_desc *f, float k, char out[][96], uint8_t *kind,
                            int max)
{
    char lines[HOL_RENDER_HUD_LINES + 2][96];
    int nl = hol__text_lines(f, lines), prompt = f->prompt && f->prompt[0], n = 0;
    int last = prompt ? nl - 1 : -1; /* the prompt's line */
    if (f->overlay && f->overlay[0] && nl < HOL_RENDER_HUD_LINES + 2)
        snprintf(lines[nl++], 96, "%.60s", f->overlay);
    float size = hol__panel_size(k);
    for (int i = 0; i < nl && n < max; i++) {
        hol_face_line fl[48];
        int m = (i == last ? hol_face_wrap_pairs : hol_face_wrap)(lines[i], size,
                                                                  HOL_HUD_PANEL_W - 4, fl, max - n);
        m = m < max - n ? m : max - n;
        for (int j = 0; j < m; j++) {
            size_t len = fl[j].len < 95 ? fl[j].len : 95;
            memcpy(out[n + j], lines[i] + fl[j].start, len);
            out[n + j][len] = 0;
            kind[n + j] = (uint8_t)(i == last);
        }
        n += m;
    }
    return n;
}

void hol_hud_build_panel_text(hol_mesh *out, const hol_frame_desc *f, float out_wh[2])
{
    char lines[48][96];
    uint8_t kind[48];
    float k = 1;
    int n = hol__panel_lines(f, k, lines, kind, 48);
    /* shrink until every line fits the block's height (nothing is cut) */
    while (k > 0.3f && hol__line_h(hol__panel_size(k)) * (float)n + 4 > HOL_HUD_PANEL_HMAX) {
        k *= 0.9f;
        n = hol__panel_lines(f, k, lines, kind, 48);
    }
    float size = hol__panel_size(k), lh = hol__line_h(size);
    float wpx = HOL_HUD_PANEL_W, hpx = lh * (float)n + 4;
    if (n == 0) {
        out_wh[0] = out_wh[1] = 0;
        return;
    }
    /* 8 units a font pixel: the block is (8 wpx) x (8 hpx) units, laid out
     * in [-1, 1]^2 for the renderer to scale to wpx x hpx font pixels */
    hol__px p = {out, (int)(8 * wpx + 0.5f), (int)(8 * hpx + 0.5f), 0};
    static const uint8_t panel[3] = {24, 28, 34}, text[3] = {240, 240, 230},
                         yellow[3] = {255, 215, 60};
    hol__rect(&p, 0, 0, (float)p.w, (float)p.h, panel);
    for (int i = 0; i < n; i++)
        hol__text(&p, lines[i], strlen(lines[i]), 2 * 8,
                  8 * (2 + hol__ascent(size) + lh * (float)i), 8 * size,
                  kind[i] ? yellow : text);
    out_wh[0] = wpx;
    out_wh[1] = hpx;
}
