/* hol_face_draw.c - the text face on the CPU (contract in hol_face_draw.h). */
#include "hol_face_draw.h"

#include <math.h>

#include "../core/hol_face.h"

static float hol__clampf(float v, float lo, float hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* The atlas's value at (u, v) inside glyph index gi's rectangle g,
 * bilinear, texel centres at half pixels, clamped to the rectangle. */
static float hol__sample(int gi, const hol_face_glyph *g, float u, float v)
{
    const uint8_t *texels = hol_face_texels(gi);
    float fx = hol__clampf(u - 0.5f, 0.0f, (float)(g->w - 1));
    float fy = hol__clampf(v - 0.5f, 0.0f, (float)(g->h - 1));
    int x0 = (int)fx, y0 = (int)fy;
    int x1 = x0 + 1 < g->w ? x0 + 1 : x0, y1 = y0 + 1 < g->h ? y0 + 1 : y0;
    float tx = fx - (float)x0, ty = fy - (float)y0;
    const uint8_t *r0 = texels + (size_t)y0 * g->w;
    const uint8_t *r1 = texels + (size_t)y1 * g->w;
    float top = r0[x0] + (r0[x1] - r0[x0]) * tx;
    float bot = r1[x0] + (r1[x1] - r1[x0]) * tx;
    return top + (bot - top) * ty;
}

float hol_face_coverage(int g, float u, float v, float edge)
{
    const hol_face_glyph gv = hol_face_glyph_at(g), *gl = &gv;
    if (gl->w == 0 || gl->h == 0)
        return 0.0f;
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    float d = (hol__sample(g, gl, u, v) - 128.0f) * (float)m.spread / 128.0f;
    float e = edge > 1e-6f ? edge : 1e-6f;
    float t = hol__clampf(d / e + 0.5f, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

static void hol__blend(uint8_t *p, const float ink[4], float cov)
{
    float a = ink[3] * cov;
    if (a <= 0.0f)
        return;
    float da = p[3] / 255.0f, oa = a + da * (1.0f - a);
    for (int c = 0; c < 3; c++) {
        float o = (ink[c] * a + p[c] / 255.0f * da * (1.0f - a)) / oa;
        p[c] = (uint8_t)(o * 255.0f + 0.5f);
    }
    p[3] = (uint8_t)(oa * 255.0f + 0.5f);
}

/* One glyph, its quad's top-left at (x0, y0) picture pixels, k picture
 * pixels per atlas pixel. */
static void hol__glyph(const hol_face_canvas *c, int g, float x0, float y0, float k, const float ink[4],
                       float edge)
{
    const hol_face_glyph gv = hol_face_glyph_at(g), *gl = &gv;
    size_t stride = c->stride ? c->stride : (size_t)c->w * 4;
    int px0 = (int)floorf(x0), py0 = (int)floorf(y0);
    int px1 = (int)ceilf(x0 + gl->w * k), py1 = (int)ceilf(y0 + gl->h * k);
    px0 = px0 < 0 ? 0 : px0;
    py0 = py0 < 0 ? 0 : py0;
    px1 = px1 > c->w ? c->w : px1;
    py1 = py1 > c->h ? c->h : py1;
    for (int py = py0; py < py1; py++)
        for (int px = px0; px < px1; px++) {
            float u = ((float)px + 0.5f - x0) / k, v = ((float)py + 0.5f - y0) / k;
            float cov = hol_face_coverage(g, u, v, edge / k);
            hol__blend(c->rgba + (size_t)py * stride + (size_t)px * 4, ink, cov);
        }
}

float hol_face_draw(const hol_face_canvas *canvas, const hol_face_draw_desc *desc, const char *text,
                    size_t len, int *out_missing)
{
    hol_face_metrics m;
    hol_face_get_metrics(&m);
    float size = desc->size > 0 ? desc->size : 16.0f;
    float edge = desc->edge > 0 ? desc->edge : 1.0f;
    uint32_t ink32 = desc->ink ? desc->ink : 0x000000FFu;
    float ink[4];
    for (int i = 0; i < 4; i++)
        ink[i] = (float)((ink32 >> (24 - 8 * i)) & 0xFFu) / 255.0f;
    float k = size / (float)m.bake_em, per_unit = size / (float)m.units_per_em;
    long units = 0;
    int prev = -1, missing = 0;
    for (size_t pos = 0; pos < len;) {
        int g = hol_face_index(hol_face_decode(text, len, &pos));
        missing += g == 0;
        units += hol_face_kerning(prev, g);
        const hol_face_glyph gv = hol_face_glyph_at(g), *gl = &gv;
        float pen = desc->x + (float)((double)units * per_unit);
        if (gl->w > 0)
            hol__glyph(canvas, g, pen + gl->qx * k, desc->y + gl->qy * k, k, ink, edge);
        units += gl->advance;
        prev = g;
    }
    if (out_missing)
        *out_missing += missing;
    return (float)((double)units * per_unit);
}
