/* hol_view.c - camera maths and portal branches (see hol_view.h). */
#include "hol_view.h"

#include <math.h>
#include <string.h>

#define HOL__PI 3.14159265358979323846

static double hol__fovy(const hol_camera *cam)
{
    return (cam->fovy_deg > 0 ? cam->fovy_deg : 90.0) * HOL__PI / 180.0;
}

void hol_camera_tangents(const hol_camera *cam, double *out_l, double *out_r,
                         double *out_d, double *out_u)
{
    if (cam->has_pose) {
        *out_l = cam->tan_left;
        *out_r = cam->tan_right;
        *out_d = cam->tan_down;
        *out_u = cam->tan_up;
        return;
    }
    double ay = tan(hol__fovy(cam) / 2), ax = ay * cam->width / cam->height;
    *out_l = -ax;
    *out_r = ax;
    *out_d = -ay;
    *out_u = ay;
}

/* v rotated by the unit quaternion q = (x, y, z, w) */
static void hol__qrot(const double q[4], const double v[3], double out[3])
{
    double x = q[0], y = q[1], z = q[2], w = q[3];
    /* t = 2 q.xyz x v; out = v + w t + q.xyz x t */
    double tx = 2 * (y * v[2] - z * v[1]), ty = 2 * (z * v[0] - x * v[2]),
           tz = 2 * (x * v[1] - y * v[0]);
    out[0] = v[0] + w * tx + (y * tz - z * ty);
    out[1] = v[1] + w * ty + (z * tx - x * tz);
    out[2] = v[2] + w * tz + (x * ty - y * tx);
}

void hol_camera_basis(const hol_camera *cam, double out_r[3], double out_u[3],
                      double out_b[3])
{
    if (cam->has_pose) {
        const double *q = cam->orient;
        double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        double qn[4] = {0, 0, 0, 1};
        if (n > 0)
            for (int i = 0; i < 4; i++)
                qn[i] = q[i] / n;
        static const double ex[3] = {1, 0, 0}, ey[3] = {0, 1, 0}, ez[3] = {0, 0, 1};
        hol__qrot(qn, ex, out_r);
        hol__qrot(qn, ey, out_u);
        hol__qrot(qn, ez, out_b);
        return;
    }
    double y = cam->yaw_deg * HOL__PI / 180.0, p = cam->pitch_deg * HOL__PI / 180.0;
    double cy = cos(y), sy = sin(y), cp = cos(p), sp = sin(p);
    /* R = Ry(yaw) * Rx(pitch); columns are right, up, back */
    out_r[0] = cy;
    out_r[1] = 0;
    out_r[2] = -sy;
    out_u[0] = sy * sp;
    out_u[1] = cp;
    out_u[2] = cy * sp;
    out_b[0] = sy * cp;
    out_b[1] = -sp;
    out_b[2] = cy * cp;
}

void hol_camera_matrices(const hol_camera *cam, float out_view[16],
                         float out_proj[16])
{
    double r[3], u[3], b[3];
    hol_camera_basis(cam, r, u, b);
    const double *e = cam->eye;
    double v[16] = {0};
    for (int i = 0; i < 3; i++) {
        v[4 * i + 0] = r[i];
        v[4 * i + 1] = u[i];
        v[4 * i + 2] = b[i];
    }
    v[12] = -(r[0] * e[0] + r[1] * e[1] + r[2] * e[2]);
    v[13] = -(u[0] * e[0] + u[1] * e[1] + u[2] * e[2]);
    v[14] = -(b[0] * e[0] + b[1] * e[1] + b[2] * e[2]);
    v[15] = 1;
    for (int i = 0; i < 16; i++)
        out_view[i] = (float)v[i];
    double n = cam->znear > 0 ? cam->znear : 0.05;
    double f = cam->zfar > 0 ? cam->zfar : 60.0;
    double l, rt, d, up;
    hol_camera_tangents(cam, &l, &rt, &d, &up);
    memset(out_proj, 0, 16 * sizeof(float));
    /* off-centre frustum in tangent units */
    out_proj[0] = (float)(2 / (rt - l));
    out_proj[5] = (float)(2 / (up - d));
    out_proj[8] = (float)((rt + l) / (rt - l));
    out_proj[9] = (float)((up + d) / (up - d));
    out_proj[10] = (float)((f + n) / (n - f));
    out_proj[11] = -1.0f;
    out_proj[14] = (float)(2 * f * n / (n - f));
}

void hol_camera_ray(const hol_camera *cam, double ndc_x, double ndc_y,
                    double out_dir[3])
{
    double r[3], u[3], b[3];
    hol_camera_basis(cam, r, u, b);
    double l, rt, d, up;
    hol_camera_tangents(cam, &l, &rt, &d, &up);
    double tx = l + (ndc_x + 1) / 2 * (rt - l), ty = d + (ndc_y + 1) / 2 * (up - d);
    for (int i = 0; i < 3; i++)
        out_dir[i] = tx * r[i] + ty * u[i] - b[i];
}

uint8_t hol_view_code(const uint8_t *steps, int n)
{
    if (n <= 0)
        return 0;
    int d1 = steps[0] & 3;
    unsigned code = (unsigned)d1;
    for (int i = 1; i < n; i++) {
        int d = steps[i] & 3;
        if (d != d1) {
            code |= 1u << (i + 2);
            if (((d - d1) & 3) == 1)
                code |= 4u;
        }
    }
    return (uint8_t)code;
}

uint8_t hol_view_mask(const uint8_t *steps, int n)
{
    unsigned mask = 3;
    for (int i = 1; i < n; i++) {
        mask |= 1u << (i + 2);
        if ((steps[i] & 3) != (steps[0] & 3))
            mask |= 4u;
    }
    return (uint8_t)mask;
}

/* Trace the half-line from (ex,ez) in direction (dx,dz) through the cells
 * of a cols x rows room: room steps up to and including the one that
 * leaves the room. */
static int hol__trace(double ex, double ez, double dx, double dz, int cols, int rows,
                      uint8_t steps[HOL_VIEW_MAX_STEPS])
{
    int c = (int)floor(ex), r = (int)floor(ez), n = 0;
    while (n < HOL_VIEW_MAX_STEPS) {
        double tx = dx > 0 ? (c + 1 - ex) / dx : dx < 0 ? (c - ex) / dx : INFINITY;
        double tz = dz > 0 ? (r + 1 - ez) / dz : dz < 0 ? (r - ez) / dz : INFINITY;
        int d;
        if (tx < tz) {
            d = dx > 0 ? HOL_DIR_E : HOL_DIR_W;
            c += dx > 0 ? 1 : -1;
        } else {
            d = dz > 0 ? HOL_DIR_S : HOL_DIR_N;
            r += dz > 0 ? 1 : -1;
        }
        steps[n++] = (uint8_t)d;
        if (c < 0 || c >= cols || r < 0 || r >= rows)
            break;
    }
    return n;
}

static double hol__cross(const double a[2], const double b[2])
{
    return a[0] * b[1] - a[1] * b[0];
}

static void hol__add_branch(hol_view *v, const hol_room *user, const uint8_t *steps,
                            int n, int stencil)
{
    for (int i = 0; i < v->nbranches; i++) {
        const hol_view_branch *b = &v->branches[i];
        if (b->nsteps == n && (n == 0 || !memcmp(b->steps, steps, (size_t)n)))
            return;
    }
    if (v->nbranches >= HOL_VIEW_MAX_BRANCHES)
        return; /* cannot happen (at most ~40 in 3 x 3; test_render_tiles
                   counts the 5 x 5 room's) */
    hol_view_branch *b = &v->branches[v->nbranches++];
    memset(b, 0, sizeof *b);
    b->state = *user;
    b->nsteps = (uint8_t)n;
    if (n > 0)
        memcpy(b->steps, steps, (size_t)n);
    b->err = hol_room_walk(&b->state, steps, (size_t)n, NULL);
    if (stencil && n > 0 && !v->wedges) {
        b->ref = hol_view_code(steps, n);
        b->mask = hol_view_mask(steps, n);
    }
}

/* The Euclidean baseline: one branch per cell, columns first, then rows. */
static void hol__build_flat(hol_view *out, const hol_room *user, int cols, int rows)
{
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            uint8_t steps[2 * HOL_ROOM_MAX_SIDE];
            int n = 0;
            for (int k = user->col; k < c; k++)
                steps[n++] = HOL_DIR_E;
            for (int k = user->col; k > c; k--)
                steps[n++] = HOL_DIR_W;
            for (int k = user->row; k < r; k++)
                steps[n++] = HOL_DIR_S;
            for (int k = user->row; k > r; k--)
                steps[n++] = HOL_DIR_N;
            hol__add_branch(out, user, steps, n, 0);
        }
}

/* The directions from the eye to the room's vertices, sorted by angle,
 * collinear ones merged; returns their number. */
static int hol__vertex_dirs(double ex, double ez, int cols, int rows,
                            double dirs[HOL_VIEW_MAX_LEAVES][2])
{
    double ang[HOL_VIEW_MAX_LEAVES];
    int nd = 0;
    for (int j = 0; j <= rows; j++)
        for (int i = 0; i <= cols; i++) {
            double dx = i - ex, dz = j - ez, l = sqrt(dx * dx + dz * dz);
            double u[2] = {dx / l, dz / l};
            int dup = 0;
            for (int k = 0; k < nd && !dup; k++)
                dup = fabs(hol__cross(u, dirs[k])) < 1e-12 &&
                      u[0] * dirs[k][0] + u[1] * dirs[k][1] > 0;
            if (dup)
                continue;
            double a = atan2(u[1], u[0]);
            int k = nd++;
            while (k > 0 && ang[k - 1] > a) {
                ang[k] = ang[k - 1];
                dirs[k][0] = dirs[k - 1][0];
                dirs[k][1] = dirs[k - 1][1];
                k--;
            }
            ang[k] = a;
            dirs[k][0] = u[0];
            dirs[k][1] = u[1];
        }
    return nd;
}

/* 1 when leaf lf continues branch b (b's steps are a proper prefix). */
static int hol__leaf_has(const hol_view_leaf *lf, const hol_view_branch *b)
{
    return lf->nsteps > b->nsteps && !memcmp(lf->steps, b->steps, b->nsteps);
}

/* Each branch's wedge: its leaves are contiguous in angle (cyclically):
 * from the first's u0 to the last's u1. */
static void hol__wedges(hol_view *v)
{
    int nl = v->nleaves;
    for (int i = 1; i < v->nbranches; i++) {
        hol_view_branch *b = &v->branches[i];
        for (int k = 0; k < nl; k++) {
            if (!hol__leaf_has(&v->leaves[k], b) ||
                hol__leaf_has(&v->leaves[(k + nl - 1) % nl], b))
                continue;
            int e = k;
            while (hol__leaf_has(&v->leaves[(e + 1) % nl], b) && (e + 1) % nl != k)
                e = (e + 1) % nl;
            memcpy(b->w0, v->leaves[k].u0, sizeof b->w0);
            memcpy(b->w1, v->leaves[e].u1, sizeof b->w1);
            break;
        }
    }
}

hol_err hol_view_build(const hol_room *user, double ex, double ez, int euclidean,
                       hol_view *out)
{
    int cols = hol_room_cols(user), rows = hol_room_rows(user);
    if (cols > HOL_ROOM_MAX_SIDE || rows > HOL_ROOM_MAX_SIDE)
        return HOL_EARG;
    if (!(ex > user->col && ex < user->col + 1 && ez > user->row &&
          ez < user->row + 1))
        return HOL_EARG;
    memset(out, 0, sizeof *out);
    out->euclidean = euclidean ? 1 : 0;
    out->wedges = !euclidean && (cols != HOL_ROOM_SIZE || rows != HOL_ROOM_SIZE);
    hol__add_branch(out, user, NULL, 0, 0);
    if (euclidean) {
        hol__build_flat(out, user, cols, rows);
        return HOL_OK;
    }
    double dirs[HOL_VIEW_MAX_LEAVES][2];
    int nd = hol__vertex_dirs(ex, ez, cols, rows, dirs);
    for (int k = 0; k < nd; k++) {
        const double *u0 = dirs[k], *u1 = dirs[(k + 1) % nd];
        double mx = u0[0] + u1[0], mz = u0[1] + u1[1];
        hol_view_leaf *lf = &out->leaves[out->nleaves++];
        lf->u0[0] = u0[0];
        lf->u0[1] = u0[1];
        lf->u1[0] = u1[0];
        lf->u1[1] = u1[1];
        lf->nsteps = (uint8_t)hol__trace(ex, ez, mx, mz, cols, rows, lf->steps);
        lf->code = out->wedges ? 0 : hol_view_code(lf->steps, lf->nsteps);
        for (int n = 1; n < lf->nsteps; n++)
            hol__add_branch(out, user, lf->steps, n, 1);
    }
    hol__wedges(out);
    return HOL_OK;
}

/* Clip a convex polygon by a*x + b*y + c >= 0. */
static int hol__clip(double in[][2], int n, double a, double b, double c,
                     double out[][2])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *p = in[i], *q = in[(i + 1) % n];
        double dp = a * p[0] + b * p[1] + c, dq = a * q[0] + b * q[1] + c;
        if (dp >= 0) {
            out[m][0] = p[0];
            out[m][1] = p[1];
            m++;
        }
        if ((dp >= 0) != (dq >= 0)) {
            double t = dp / (dp - dq);
            out[m][0] = p[0] + t * (q[0] - p[0]);
            out[m][1] = p[1] + t * (q[1] - p[1]);
            m++;
        }
    }
    return m;
}

int hol_view_leaf_ndc(const hol_camera *cam, const hol_view_leaf *leaf,
                      float out_xy[8][2])
{
    double r[3], u[3], b[3];
    hol_camera_basis(cam, r, u, b);
    double l, rt, d, up;
    hol_camera_tangents(cam, &l, &rt, &d, &up);
    /* the ray through (x,y) is x*ax*r + y*ay*u + o with the half extents
     * ax, ay and the offset o = cx*r + cy*u - b of an off-centre frustum */
    double ax = (rt - l) / 2, ay = (up - d) / 2, cx = (rt + l) / 2, cy = (up + d) / 2;
    double o[3];
    for (int i = 0; i < 3; i++)
        o[i] = cx * r[i] + cy * u[i] - b[i];
    double poly[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, tmp[8][2];
    int n = 4;
    /* cross(u0, v) >= 0 and cross(v, u1) >= 0 */
    const double *u0 = leaf->u0, *u1 = leaf->u1;
    double a0 = ax * (u0[0] * r[2] - u0[1] * r[0]);
    double b0 = ay * (u0[0] * u[2] - u0[1] * u[0]);
    double c0 = u0[0] * o[2] - u0[1] * o[0];
    double a1 = -ax * (u1[0] * r[2] - u1[1] * r[0]);
    double b1 = -ay * (u1[0] * u[2] - u1[1] * u[0]);
    double c1 = -(u1[0] * o[2] - u1[1] * o[0]);
    n = hol__clip(poly, n, a0, b0, c0, tmp);
    n = hol__clip(tmp, n, a1, b1, c1, poly);
    for (int i = 0; i < n; i++) {
        out_xy[i][0] = (float)poly[i][0];
        out_xy[i][1] = (float)poly[i][1];
    }
    return n;
}
