/* hol_body_draw.c - the body's meshes (see hol_body_draw.h). */
#include "hol_body_draw.h"

#include <math.h>
#include <string.h>

#define HOL__JOINT_R 0.008f /* a joint's radius when the runtime gives none */

/* Per model: the grip box (lo, hi), the part that tells it apart (a tip,
 * a ring, a head, a strap: lo, hi) and whether that part is a disc. */
static const struct {
    float grip[2][3];
    float part[2][3];
    int disc;
} hol__models[HOL_BODY_MODEL_COUNT] = {
    [HOL_BODY_MODEL_PLAIN] = {{{-0.018f, -0.022f, -0.05f}, {0.018f, 0.022f, 0.06f}},
                              {{-0.007f, -0.007f, -0.09f}, {0.007f, 0.007f, -0.05f}}, 0},
    [HOL_BODY_MODEL_TOUCH] = {{{-0.018f, -0.022f, -0.04f}, {0.018f, 0.022f, 0.06f}},
                              {{-0.045f, 0.03f, -0.085f}, {0.045f, 0.04f, 0.005f}}, 1},
    [HOL_BODY_MODEL_WAND] = {{{-0.016f, -0.02f, -0.03f}, {0.016f, 0.02f, 0.12f}},
                             {{-0.04f, -0.015f, -0.11f}, {0.04f, 0.025f, -0.03f}}, 1},
    [HOL_BODY_MODEL_INDEX] = {{{-0.017f, -0.022f, -0.04f}, {0.017f, 0.022f, 0.07f}},
                              {{0.017f, -0.03f, -0.035f}, {0.027f, 0.03f, 0.065f}}, 0},
};

static const uint8_t hol__grip_rgb[3] = {58, 60, 68}, hol__part_rgb[3] = {200, 204, 214},
                     hol__skin_rgb[3] = {226, 196, 172}, hol__bone_rgb[3] = {204, 170, 146},
                     hol__ray_rgb[3] = {255, 226, 96};

void hol_body_grip_box(int model, float lo[3], float hi[3])
{
    int k = model >= 0 && model < HOL_BODY_MODEL_COUNT ? model : 0;
    memcpy(lo, hol__models[k].grip[0], 3 * sizeof(float));
    memcpy(hi, hol__models[k].grip[1], 3 * sizeof(float));
}

/* The rotation matrix (row-major) of a quaternion (x, y, z, w; all zero:
 * the identity). */
static void hol__rot(const float q[4], double rot[9])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (!(n > 1e-12))
        x = y = z = 0, w = n = 1;
    x /= n, y /= n, z /= n, w /= n;
    double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
                   2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                   2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    memcpy(rot, r, sizeof r);
}

static int8_t hol__snorm(double f)
{
    double s = f * 127.0;
    return (int8_t)lrint(s > 127 ? 127 : s < -127 ? -127 : s);
}

/* The vertices from v0 on turned by rot and moved by t. */
static void hol__place(hol_mesh *m, uint32_t v0, const double rot[9], const double t[3])
{
    for (uint32_t i = v0; i < m->nv; i++) {
        hol_vertex *v = &m->v[i];
        double p[3] = {v->pos[0], v->pos[1], v->pos[2]}, n[3] = {v->nrm[0], v->nrm[1], v->nrm[2]};
        for (int r = 0; r < 3; r++) {
            v->pos[r] = (float)(t[r] + rot[3 * r] * p[0] + rot[3 * r + 1] * p[1] +
                                rot[3 * r + 2] * p[2]);
            v->nrm[r] = hol__snorm((rot[3 * r] * n[0] + rot[3 * r + 1] * n[1] +
                                    rot[3 * r + 2] * n[2]) / 127.0);
        }
    }
}

/* A controller of model k at pose p. */
static void hol__controller(hol_mesh *m, int k, const hol_pose *p)
{
    if (k < 0 || k >= HOL_BODY_MODEL_COUNT)
        k = 0;
    uint32_t v0 = m->nv;
    hol_mesh_box(m, hol__models[k].grip[0], hol__models[k].grip[1], hol__grip_rgb);
    const float *lo = hol__models[k].part[0], *hi = hol__models[k].part[1];
    if (hol__models[k].disc) { /* a disc round the y axis, moved to its box */
        uint32_t d0 = m->nv;
        float r = 0.5f * (hi[0] - lo[0]);
        hol_mesh_frustum(m, 12, r, lo[1], r, hi[1], hol__part_rgb);
        for (uint32_t i = d0; i < m->nv; i++) {
            m->v[i].pos[0] += 0.5f * (lo[0] + hi[0]);
            m->v[i].pos[2] += 0.5f * (lo[2] + hi[2]);
        }
    } else {
        hol_mesh_box(m, lo, hi, hol__part_rgb);
    }
    double rot[9], t[3] = {p->pos[0], p->pos[1], p->pos[2]};
    hol__rot(p->quat, rot);
    hol__place(m, v0, rot, t);
}

/* The unit sphere of the joints (10 slices, 8 stacks: its facets lie at
 * most 5 % of the radius inside it), made once per body: its points, which
 * are its normals, and those as the vertices' bytes. */
enum { HOL__SL = 10, HOL__ST = 8, HOL__SV = (HOL__SL + 1) * (HOL__ST + 1) };
typedef struct hol__unit_sphere {
    float p[HOL__SV][3];
    int8_t n[HOL__SV][3];
} hol__unit_sphere;

static void hol__unit(hol__unit_sphere *u)
{
    double st[HOL__ST + 1], ct[HOL__ST + 1], sp[HOL__SL + 1], cp[HOL__SL + 1];
    for (int i = 0; i <= HOL__ST; i++) {
        st[i] = sin(3.14159265358979 * i / HOL__ST);
        ct[i] = cos(3.14159265358979 * i / HOL__ST);
    }
    for (int j = 0; j <= HOL__SL; j++) {
        sp[j] = sin(6.28318530717959 * j / HOL__SL);
        cp[j] = cos(6.28318530717959 * j / HOL__SL);
    }
    for (int i = 0, k = 0; i <= HOL__ST; i++)
        for (int j = 0; j <= HOL__SL; j++, k++) {
            double n[3] = {st[i] * cp[j], ct[i], -st[i] * sp[j]};
            for (int c = 0; c < 3; c++) {
                u->p[k][c] = (float)n[c];
                u->n[k][c] = hol__snorm(n[c]);
            }
        }
}

/* A sphere of radius r at c (the unit sphere u scaled and moved). */
static void hol__sphere(hol_mesh *m, const hol__unit_sphere *u, const float c[3], float r,
                        const uint8_t rgb[3])
{
    int64_t b = hol_mesh_reserve(m, HOL__SV, 6 * HOL__SL * HOL__ST);
    if (b < 0)
        return;
    for (int k = 0; k < HOL__SV; k++) {
        hol_vertex *v = &m->v[m->nv++];
        for (int i = 0; i < 3; i++) {
            v->pos[i] = c[i] + r * u->p[k][i];
            v->nrm[i] = u->n[k][i];
        }
        v->nrm[3] = 0;
        memcpy(v->rgba, rgb, 3);
        v->rgba[3] = HOL_MESH_PROP;
    }
    for (int i = 0; i < HOL__ST; i++)
        for (int j = 0; j < HOL__SL; j++) {
            uint32_t a = (uint32_t)b + (uint32_t)(i * (HOL__SL + 1) + j), d = a + HOL__SL + 1;
            uint32_t tri[6] = {a, d, a + 1, a + 1, d, d + 1};
            for (int k = 0; k < 6; k++)
                m->idx[m->ni++] = tri[k];
        }
}

/* A cylinder of radius r from a to b: 6 sides, smooth, no caps (the
 * joints' spheres cover its ends). */
static void hol__bone(hol_mesh *m, const float a[3], const float b[3], float r,
                      const uint8_t rgb[3])
{
    double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(len > 1e-6))
        return;
    for (int k = 0; k < 3; k++)
        d[k] /= len;
    /* u, w across the bone */
    double u[3] = {d[1], -d[0], 0};
    if (fabs(d[2]) > 0.9)
        u[0] = 0, u[1] = d[2], u[2] = -d[1];
    double un = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int k = 0; k < 3; k++)
        u[k] /= un;
    double w[3] = {u[1] * d[2] - u[2] * d[1], u[2] * d[0] - u[0] * d[2], u[0] * d[1] - u[1] * d[0]};
    int64_t base = hol_mesh_reserve(m, 12, 36);
    if (base < 0)
        return;
    static const double cs[6][2] = {{1, 0}, {0.5, 0.8660254037844386}, {-0.5, 0.8660254037844386},
                                    {-1, 0}, {-0.5, -0.8660254037844386}, {0.5, -0.8660254037844386}};
    for (int end = 0; end < 2; end++)
        for (int i = 0; i < 6; i++) {
            hol_vertex *v = &m->v[m->nv++];
            for (int k = 0; k < 3; k++) {
                double n = cs[i][0] * u[k] + cs[i][1] * w[k];
                v->pos[k] = (end ? b[k] : a[k]) + (float)(r * n);
                v->nrm[k] = hol__snorm(n);
            }
            v->nrm[3] = 0;
            memcpy(v->rgba, rgb, 3);
            v->rgba[3] = HOL_MESH_PROP;
        }
    for (uint32_t i = 0; i < 6; i++) {
        uint32_t j = (i + 1) % 6, a0 = (uint32_t)base + i, a1 = (uint32_t)base + j;
        uint32_t tri[6] = {a0, a1, a1 + 6, a0, a1 + 6, a0 + 6};
        for (int k = 0; k < 6; k++)
            m->idx[m->ni++] = tri[k];
    }
}

/* A tracked hand: its joints' spheres and the bones between them (each
 * joint after the wrist joins the one before it in its finger; each
 * finger's first joins the wrist). */
static void hol__hand(hol_mesh *m, const hol__unit_sphere *u, const hol_hand_joints *j)
{
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        float r = j->radius[i] > 0 ? j->radius[i] : HOL__JOINT_R;
        hol__sphere(m, u, j->pos[i], r, hol__skin_rgb);
    }
    for (int i = 1; i < HOL_HAND_JOINTS; i++) {
        int first = i == HOL_JOINT_THUMB_METACARPAL || (i >= HOL_JOINT_INDEX_METACARPAL &&
                                                        (i - HOL_JOINT_INDEX_METACARPAL) % 5 == 0);
        int from = first ? HOL_JOINT_WRIST : i - 1;
        float ra = j->radius[from] > 0 ? j->radius[from] : HOL__JOINT_R;
        float rb = j->radius[i] > 0 ? j->radius[i] : HOL__JOINT_R;
        hol__bone(m, j->pos[from], j->pos[i], 0.7f * (ra < rb ? ra : rb), hol__bone_rgb);
    }
}

void hol_body_build(hol_mesh *m, const hol_body *b)
{
    hol__unit_sphere u;
    if (b->hand[0].kind == HOL_BODY_HAND || b->hand[1].kind == HOL_BODY_HAND)
        hol__unit(&u);
    for (int h = 0; h < 2; h++) {
        const hol_body_part *p = &b->hand[h];
        if (p->kind == HOL_BODY_CONTROLLER)
            hol__controller(m, p->model, &p->pose);
        else if (p->kind == HOL_BODY_HAND)
            hol__hand(m, &u, &p->joints);
    }
    if (b->ray_hand < 0 || b->ray_hand > 1 || !(b->ray_m > 0))
        return;
    const hol_pose *p = &b->hand[b->ray_hand].pose;
    uint32_t v0 = m->nv;
    float lo[3] = {-0.002f, -0.002f, -(float)b->ray_m}, hi[3] = {0.002f, 0.002f, -0.05f};
    hol_mesh_box(m, lo, hi, hol__ray_rgb);
    double rot[9], t[3] = {p->pos[0], p->pos[1], p->pos[2]};
    hol__rot(p->quat, rot);
    hol__place(m, v0, rot, t);
}
