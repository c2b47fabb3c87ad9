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

/* The panel's pose from its anchor and yaw. */
static void hol__pose(hol_panel *p)
{
    double y = p->yaw_deg * HOL__PI / 180, a = HOL_PANEL_DROP_DEG * HOL__PI / 180;
    double sy = hol_sin(y), cy = hol_cos(y), ca = hol_cos(a), sa = hol_sin(a);
    /* forward at yaw y is (-sin y, 0, -cos y) */
    p->pos[0] = p->anchor[0] - HOL_PANEL_DISTANCE * ca * sy;
    p->pos[1] = p->anchor[1] - HOL_PANEL_DISTANCE * sa;
    p->pos[2] = p->anchor[2] - HOL_PANEL_DISTANCE * ca * cy;
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
