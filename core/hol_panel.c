/* hol_panel.c - the headset UI panel's lazy follow (see hol_panel.h). */
#include "hol_panel.h"

#include <math.h>

#include "hol_math.h"

#define HOL__PI 3.14159265358979323846
#define HOL__CATCH_S 0.1 /* the longest step of time the glide takes at
                            once: after a long frame it glides on */

/* a - b in (-180, 180] */
static double hol__ddeg(double a, double b)
{
    double d = fmod(a - b, 360.0);
    if (d > 180)
        d -= 360;
    else if (d <= -180)
        d += 360;
    return d;
}

#define HOL__FAR 1e9
#define HOL__RAY_STEP_DEG 0.5

void hol_panel_room(hol_panel *p, int cols, int rows, double cell_m)
{
    p->cols = cols > 0 && rows > 0 && cell_m > 0 ? cols : 0;
    p->rows = p->cols ? rows : 0;
    p->cell_m = p->cols ? cell_m : 0;
}

/* The nearest hedge's depth along yaw y (radians) over the sector's rays,
 * from (x, z) inside the w x d room. */
static double hol__hedge_depth(double x, double z, double w, double d, double y)
{
    double best = HOL__FAR;
    int n = (int)(HOL_PANEL_HALF_DEG / HOL__RAY_STEP_DEG);
    for (int k = -n; k <= n; k++) {
        double phi = k * HOL__RAY_STEP_DEG * HOL__PI / 180;
        double dx = -hol_sin(y + phi), dz = -hol_cos(y + phi);
        double tx = dx < 0 ? -x / dx : dx > 0 ? (w - x) / dx : HOL__FAR;
        double tz = dz < 0 ? -z / dz : dz > 0 ? (d - z) / dz : HOL__FAR;
        double t = (tx < tz ? tx : tz) * hol_cos(phi);
        best = t < best ? t : best;
    }
    return best;
}

/* The nearest depth along yaw y of the trunk of radius r at (cx, cz) from
 * the head, over the directions within half of y (radians); HOL__FAR when
 * it is out of them. */
static double hol__trunk_depth(double cx, double cz, double y, double half, double r)
{
    double c2 = cx * cx + cz * cz;
    if (c2 <= r * r) /* inside the trunk */
        return 0;
    double fx = -hol_sin(y), fz = -hol_cos(y);
    double along = cx * fx + cz * fz, side = cx * fz - cz * fx;
    if (along > 0 && fabs(hol_atan2(side, along)) <= half)
        return along - r; /* its nearest point, straight ahead of it */
    double best = HOL__FAR;
    for (int s = -1; s <= 1; s += 2) { /* else where the sector's edges meet it */
        double ux = -hol_sin(y + s * half), uz = -hol_cos(y + s * half);
        double b = cx * ux + cz * uz, disc = r * r - (c2 - b * b);
        if (disc < 0 || b <= 0)
            continue;
        double t = (b - sqrt(disc)) * hol_cos(half);
        best = t < best ? t : best;
    }
    return best;
}

double hol_panel_clear_depth(const hol_panel *p, const double head[3], double yaw_deg)
{
    double m = p->cell_m, w = p->cols * m, d = p->rows * m, x = head[0], z = head[2];
    if (!p->cols || !(x >= 0 && x <= w && z >= 0 && z <= d))
        return HOL__FAR;
    double y = yaw_deg * HOL__PI / 180;
    double best = hol__hedge_depth(x, z, w, d, y), r = HOL_PANEL_TRUNK_M;
    double half = HOL_PANEL_HALF_DEG * HOL__PI / 180;
    for (int i = 0; i <= p->cols; i++)
        for (int j = 0; j <= p->rows; j++) {
            double t = hol__trunk_depth(i * m - x, j * m - z, y, half, r);
            best = t < best ? t : best;
        }
    return best;
}

/* The panel's pose from its anchor and yaw. */
static void hol__pose(hol_panel *p)
{
    double y = p->yaw_deg * HOL__PI / 180, a = HOL_PANEL_DROP_DEG * HOL__PI / 180;
    double sy = hol_sin(y), cy = hol_cos(y), ca = hol_cos(a), sa = hol_sin(a);
    double dist = HOL_PANEL_DISTANCE;
    p->covered = 0;
    if (p->cols) {
        double h = (hol_panel_clear_depth(p, p->anchor, p->yaw_deg) - HOL_PANEL_CLEAR_M) / ca;
        dist = h < dist ? h : dist;
        p->covered = dist < HOL_PANEL_NEAR_M;
        dist = p->covered ? HOL_PANEL_NEAR_M : dist;
    }
    p->dist = dist;
    p->scale = dist / HOL_PANEL_DISTANCE;
    /* forward at yaw y is (-sin y, 0, -cos y) */
    p->pos[0] = p->anchor[0] - dist * ca * sy;
    p->pos[1] = p->anchor[1] - dist * sa;
    p->pos[2] = p->anchor[2] - dist * ca * cy;
    /* q_yaw(y) * q_x(-a): turned to the anchor's yaw, tilted back by the
     * drop so that its face looks up at the eyes */
    double sy2 = hol_sin(y / 2), cy2 = hol_cos(y / 2), sa2 = hol_sin(-a / 2),
           ca2 = hol_cos(-a / 2);
    p->orient[0] = cy2 * sa2;
    p->orient[1] = sy2 * ca2;
    p->orient[2] = -sy2 * sa2;
    p->orient[3] = cy2 * ca2;
}

void hol_panel_place(hol_panel *p, const double head[3], double yaw_deg, double t_s)
{
    for (int i = 0; i < 3; i++)
        p->anchor[i] = head[i];
    p->yaw_deg = hol__ddeg(yaw_deg, 0);
    p->t = t_s;
    p->placed = 1;
    p->moving = 0;
    p->recentres++;
    hol__pose(p);
}

void hol_panel_follow(hol_panel *p, const double head[3], double yaw_deg, double t_s)
{
    double dt = t_s - p->t;
    if (!p->placed || !(dt >= 0)) {
        hol_panel_place(p, head, yaw_deg, t_s);
        return;
    }
    p->t = t_s;
    double dyaw = hol__ddeg(yaw_deg, p->yaw_deg), d2 = 0;
    for (int i = 0; i < 3; i++)
        d2 += (head[i] - p->anchor[i]) * (head[i] - p->anchor[i]);
    if (!p->moving && (fabs(dyaw) > HOL_PANEL_TURN_DEG || d2 > HOL_PANEL_MOVE_M * HOL_PANEL_MOVE_M)) {
        p->moving = 1;
        p->recentres++;
    }
    if (!p->moving)
        return;
    if (fabs(dyaw) < 0.5 && d2 < 0.01 * 0.01) {
        p->yaw_deg = hol__ddeg(yaw_deg, 0);
        for (int i = 0; i < 3; i++)
            p->anchor[i] = head[i];
        p->moving = 0;
    } else {
        /* implicit Euler of d/dt x = (target - x) / tau: never overshoots */
        double c = dt < HOL__CATCH_S ? dt : HOL__CATCH_S;
        double k = c / (HOL_PANEL_EASE_S + c);
        p->yaw_deg = hol__ddeg(p->yaw_deg + k * dyaw, 0);
        for (int i = 0; i < 3; i++)
            p->anchor[i] += k * (head[i] - p->anchor[i]);
    }
    hol__pose(p);
}
