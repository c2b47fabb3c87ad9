/* hol_mesh.c - low-poly primitives into caller-sized stores. */
#include "hol_mesh.h"

#include <math.h>
#include <string.h>

void hol_mesh_init(hol_mesh *m, hol_vertex *v, uint32_t cap_v, uint32_t *idx,
                   uint32_t cap_i)
{
    m->v = v;
    m->idx = idx;
    m->cap_v = cap_v;
    m->cap_i = cap_i;
    m->nv = m->ni = 0;
    m->overflow = 0;
}

void hol_mesh_clear(hol_mesh *m)
{
    m->nv = m->ni = 0;
    m->overflow = 0;
}

int64_t hol_mesh_reserve(hol_mesh *m, uint32_t nv, uint32_t ni)
{
    if (m->nv + nv > m->cap_v || m->ni + ni > m->cap_i) {
        m->overflow = 1;
        return -1;
    }
    return m->nv;
}

static int8_t hol__snorm(float f)
{
    float s = f * 127.0f;
    if (s > 127.0f)
        s = 127.0f;
    if (s < -127.0f)
        s = -127.0f;
    return (int8_t)lrintf(s);
}

static void hol__vtx(hol_mesh *m, float x, float y, float z, float nx, float ny,
                     float nz, const uint8_t rgb[3], uint8_t a)
{
    hol_vertex *v = &m->v[m->nv++];
    float l = sqrtf(nx * nx + ny * ny + nz * nz);
    if (l <= 0)
        l = 1;
    v->pos[0] = x;
    v->pos[1] = y;
    v->pos[2] = z;
    v->nrm[0] = hol__snorm(nx / l);
    v->nrm[1] = hol__snorm(ny / l);
    v->nrm[2] = hol__snorm(nz / l);
    v->nrm[3] = 0;
    v->rgba[0] = rgb[0];
    v->rgba[1] = rgb[1];
    v->rgba[2] = rgb[2];
    v->rgba[3] = a;
}

static void hol__tri(hol_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
    m->idx[m->ni++] = a;
    m->idx[m->ni++] = b;
    m->idx[m->ni++] = c;
}

static void hol__append(hol_mesh *m, const hol_mesh *src, hol_place p,
                        const uint8_t *tint)
{
    int64_t base = hol_mesh_reserve(m, src->nv, src->ni);
    if (base < 0)
        return;
    float c = cosf(p.yaw), s = sinf(p.yaw), k = p.scale > 0 ? p.scale : 1.0f;
    for (uint32_t i = 0; i < src->nv; i++) {
        hol_vertex v = src->v[i];
        /* counter-clockwise from above: x' = x c + z s, z' = -x s + z c */
        float x = v.pos[0] * k, z = v.pos[2] * k;
        v.pos[0] = p.x + x * c + z * s;
        v.pos[1] = p.y + v.pos[1] * k;
        v.pos[2] = p.z - x * s + z * c;
        float nx = v.nrm[0], nz = v.nrm[2];
        v.nrm[0] = hol__snorm((nx * c + nz * s) / 127.0f);
        v.nrm[2] = hol__snorm((-nx * s + nz * c) / 127.0f);
        if (tint)
            for (int j = 0; j < 3; j++)
                v.rgba[j] = (uint8_t)((v.rgba[j] * tint[j] + 127) / 255);
        m->v[m->nv++] = v;
    }
    for (uint32_t i = 0; i < src->ni; i++)
        m->idx[m->ni++] = (uint32_t)base + src->idx[i];
}

void hol_mesh_append(hol_mesh *m, const hol_mesh *src, hol_place p)
{
    hol__append(m, src, p, NULL);
}

void hol_mesh_append_tinted(hol_mesh *m, const hol_mesh *src, hol_place p,
                            const uint8_t tint[3])
{
    hol__append(m, src, p, tint);
}

void hol_mesh_quad_y(hol_mesh *m, float x0, float z0, float x1, float z1, float y,
                     const uint8_t rgb[3], uint8_t kind)
{
    int64_t b = hol_mesh_reserve(m, 4, 6);
    if (b < 0)
        return;
    hol__vtx(m, x0, y, z0, 0, 1, 0, rgb, kind);
    hol__vtx(m, x0, y, z1, 0, 1, 0, rgb, kind);
    hol__vtx(m, x1, y, z1, 0, 1, 0, rgb, kind);
    hol__vtx(m, x1, y, z0, 0, 1, 0, rgb, kind);
    uint32_t u = (uint32_t)b;
    hol__tri(m, u, u + 1, u + 2);
    hol__tri(m, u, u + 2, u + 3);
}

void hol_mesh_box(hol_mesh *m, const float lo[3], const float hi[3],
                  const uint8_t rgb[3])
{
    int64_t b = hol_mesh_reserve(m, 24, 36);
    if (b < 0)
        return;
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int f = 0; f < 6; f++) {
        /* two tangent axes of face f */
        int ax = f < 2 ? 0 : f < 4 ? 1 : 2;
        int t1 = (ax + 1) % 3, t2 = (ax + 2) % 3;
        float sgn = n[f][ax];
        uint32_t base = m->nv;
        for (int k = 0; k < 4; k++) {
            float p[3];
            p[ax] = sgn > 0 ? hi[ax] : lo[ax];
            int a = (k == 1 || k == 2), c = (k >= 2);
            p[t1] = a ? hi[t1] : lo[t1];
            p[t2] = c ? hi[t2] : lo[t2];
            hol__vtx(m, p[0], p[1], p[2], n[f][0], n[f][1], n[f][2], rgb,
                     HOL_MESH_PROP);
        }
        /* (t1,t2) order makes (lo,lo),(hi,lo),(hi,hi),(lo,hi) CCW around
         * +ax; flip for the negative faces */
        if (sgn > 0) {
            hol__tri(m, base, base + 1, base + 2);
            hol__tri(m, base, base + 2, base + 3);
        } else {
            hol__tri(m, base, base + 2, base + 1);
            hol__tri(m, base, base + 3, base + 2);
        }
    }
}

void hol_mesh_frustum(hol_mesh *m, int n, float r0, float y0, float r1, float y1,
                      const uint8_t rgb[3])
{
    if (n < 3)
        n = 3;
    if (n > 32)
        n = 32;
    int cap = r1 > 0, cone = r1 <= 0; /* a cone: one triangle a side */
    int inside = y0 > 0; /* an open bottom above the ground: seen into */
    uint32_t side_v = cone ? 3u : 4u, side_i = cone ? 3u : 6u;
    int64_t b = hol_mesh_reserve(m, (uint32_t)n * side_v + (uint32_t)(cap ? n : 0),
                                 (uint32_t)n * side_i * (inside ? 2u : 1u) +
                                     (uint32_t)(cap ? 3 * (n - 2) : 0));
    if (b < 0)
        return;
    float h = y1 - y0, slope = (r0 - r1) / (h != 0 ? h : 1);
    for (int i = 0; i < n; i++) {
        float a0 = 6.2831853f * i / n, a1 = 6.2831853f * (i + 1) / n;
        float am = 0.5f * (a0 + a1);
        float nx = cosf(am), nz = -sinf(am);
        uint32_t base = m->nv;
        hol__vtx(m, r0 * cosf(a0), y0, -r0 * sinf(a0), nx, slope, nz, rgb, HOL_MESH_PROP);
        hol__vtx(m, r0 * cosf(a1), y0, -r0 * sinf(a1), nx, slope, nz, rgb, HOL_MESH_PROP);
        hol__vtx(m, r1 * cosf(a1), y1, -r1 * sinf(a1), nx, slope, nz, rgb, HOL_MESH_PROP);
        hol__tri(m, base, base + 1, base + 2);
        if (!cone) { /* a cone's second triangle would have no area */
            hol__vtx(m, r1 * cosf(a0), y1, -r1 * sinf(a0), nx, slope, nz, rgb, HOL_MESH_PROP);
            hol__tri(m, base, base + 2, base + 3);
        }
    }
    if (cap) {
        uint32_t base = m->nv;
        for (int i = 0; i < n; i++) {
            float a = 6.2831853f * i / n;
            hol__vtx(m, r1 * cosf(a), y1, -r1 * sinf(a), 0, 1, 0, rgb, HOL_MESH_PROP);
        }
        for (int i = 1; i + 1 < n; i++)
            hol__tri(m, base, base + (uint32_t)i, base + (uint32_t)i + 1);
    }
    /* seen from below through its open bottom (a pine's crown from under
     * it): the sides' inner faces, the same triangles wound the other way
     * (the room and tile passes cull back faces) */
    for (int i = 0; i < n && inside; i++) {
        uint32_t base = (uint32_t)b + (uint32_t)i * side_v;
        hol__tri(m, base, base + 2, base + 1);
        if (!cone)
            hol__tri(m, base, base + 3, base + 2);
    }
}

void hol_mesh_blob(hol_mesh *m, const float c[3], float sx, float sy, float sz,
                   const uint8_t rgb[3])
{
    int64_t b = hol_mesh_reserve(m, 24, 24);
    if (b < 0)
        return;
    /* eight faces of an octahedron, flat shaded */
    for (int f = 0; f < 8; f++) {
        float px = (f & 1) ? 1.0f : -1.0f, py = (f & 2) ? 1.0f : -1.0f,
              pz = (f & 4) ? 1.0f : -1.0f;
        float va[3][3] = {{px, 0, 0}, {0, py, 0}, {0, 0, pz}};
        uint32_t base = m->nv;
        for (int k = 0; k < 3; k++)
            hol__vtx(m, c[0] + va[k][0] * sx, c[1] + va[k][1] * sy,
                     c[2] + va[k][2] * sz, px / sx, py / sy, pz / sz, rgb,
                     HOL_MESH_PROP);
        /* orientation: outward normal (px,py,pz); x->y->z is CCW when the
         * product of signs is positive */
        if (px * py * pz > 0)
            hol__tri(m, base, base + 1, base + 2);
        else
            hol__tri(m, base, base + 2, base + 1);
    }
}
