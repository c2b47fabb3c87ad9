/* hol_body.c - the body a headset shows and the hands-only recentre (see
 * hol_body.h). */
#include "hol_body.h"

#include <math.h>
#include <string.h>

#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

int hol_body_model_of(uint32_t device)
{
    switch (device) {
    case HOL_DEVICE_XR_TOUCH:
    case HOL_DEVICE_WEBXR_TOUCH:
        return HOL_BODY_MODEL_TOUCH;
    case HOL_DEVICE_XR_VIVE:
        return HOL_BODY_MODEL_WAND;
    case HOL_DEVICE_XR_INDEX:
        return HOL_BODY_MODEL_INDEX;
    default:
        return HOL_BODY_MODEL_PLAIN;
    }
}

void hol_body_from_input(const hol_input *in, int pointing, hol_body *out)
{
    memset(out, 0, sizeof *out);
    out->ray_hand = -1;
    if (!in)
        return;
    static const uint32_t valid[2] = {HOL_INPUT_HAND_L_VALID, HOL_INPUT_HAND_R_VALID};
    for (int h = 0; h < 2; h++) {
        hol_body_part *p = &out->hand[h];
        int grip = (in->flags & valid[h]) != 0;
        if (in->joints[h].tracked) {
            p->kind = HOL_BODY_HAND;
            p->joints = in->joints[h];
            if (grip) {
                p->pose = in->hand[h];
            } else {
                memcpy(p->pose.pos, in->joints[h].pos[HOL_JOINT_WRIST], sizeof p->pose.pos);
                p->pose.quat[3] = 1;
            }
        } else if (grip) {
            p->kind = HOL_BODY_CONTROLLER;
            p->model = hol_body_model_of(in->device);
            p->pose = in->hand[h];
        }
    }
    /* the pointing question's ray: the hand hol_app_point reads */
    if (pointing && (in->flags & HOL_INPUT_HEAD_VALID)) {
        if (in->flags & HOL_INPUT_HAND_R_VALID)
            out->ray_hand = HOL_HAND_RIGHT;
        else if (in->flags & HOL_INPUT_HAND_L_VALID)
            out->ray_hand = HOL_HAND_LEFT;
        out->ray_m = out->ray_hand >= 0 ? HOL_BODY_RAY_M : 0;
    }
}

int hol_hand_joints_usable(const float pos[HOL_HAND_JOINTS][3], uint32_t located)
{
    if ((located & HOL_HAND_LOCATED_ALL) != HOL_HAND_LOCATED_ALL)
        return 0;
    for (int i = 0; i < HOL_HAND_JOINTS; i++)
        for (int k = 0; k < 3; k++)
            if (!(isfinite(pos[i][k]) && fabsf(pos[i][k]) < HOL_HAND_REACH_M))
                return 0;
    return 1;
}

int hol_gesture_palm_up(const hol_hand_joints *j, int h)
{
    if (!j->tracked)
        return 0;
    const float *w = j->pos[HOL_JOINT_WRIST], *ix = j->pos[HOL_JOINT_INDEX_METACARPAL];
    const float *pk = j->pos[HOL_JOINT_PINKY_METACARPAL];
    double a[3], b[3], n[3];
    for (int k = 0; k < 3; k++) {
        a[k] = (double)ix[k] - w[k];
        b[k] = (double)pk[k] - w[k];
    }
    /* index x pinky points out of the right palm; the left's is mirrored */
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 1e-9))
        return 0;
    double up = (h == HOL_HAND_RIGHT ? n[1] : -n[1]) / len;
    if (!(up >= hol_cos(HOL_GESTURE_PALM_DEG * HOL__PI / 180)))
        return 0;
    const float *t = j->pos[HOL_JOINT_THUMB_TIP], *i = j->pos[HOL_JOINT_INDEX_TIP];
    double d2 = 0;
    for (int k = 0; k < 3; k++)
        d2 += ((double)t[k] - i[k]) * ((double)t[k] - i[k]);
    return d2 > HOL_GESTURE_OPEN_M * HOL_GESTURE_OPEN_M;
}

uint32_t hol_gesture_step(hol_gesture *g, const hol_hand_joints joints[2], double t)
{
    int up = hol_gesture_palm_up(&joints[HOL_HAND_LEFT], HOL_HAND_LEFT) &&
             hol_gesture_palm_up(&joints[HOL_HAND_RIGHT], HOL_HAND_RIGHT);
    if (!up) {
        g->up = g->spent = 0;
        return 0;
    }
    if (!g->up) {
        g->up = 1;
        g->t0 = t;
    }
    if (g->spent || t - g->t0 < HOL_GESTURE_HOLD_S)
        return 0;
    g->spent = 1;
    return HOL_BTN_RECENTRE;
}

int hol_flick_point(const hol_input *in, int h, double out[3])
{
    const hol_hand_joints *j = &in->joints[h];
    if (j->tracked) {
        for (int k = 0; k < 3; k++)
            out[k] = ((double)j->pos[HOL_JOINT_THUMB_TIP][k] + j->pos[HOL_JOINT_INDEX_TIP][k]) / 2;
        return 1;
    }
    if (!(in->flags & (h == HOL_HAND_RIGHT ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID)))
        return 0;
    for (int k = 0; k < 3; k++)
        out[k] = in->hand[h].pos[k];
    return 1;
}

/* The step of a level move (dx, dz) against the look's forward (fx, fz,
 * unit): the nearest of ahead, back, left, right. */
static uint32_t hol__flick_dir(double dx, double dz, double fx, double fz)
{
    double ahead = dx * fx + dz * fz, right = -dx * fz + dz * fx; /* right of (fx, fz): (-fz, fx) */
    if (fabs(ahead) >= fabs(right))
        return ahead >= 0 ? HOL_BTN_STEP_FWD : HOL_BTN_STEP_BACK;
    return right >= 0 ? HOL_BTN_STEP_RIGHT : HOL_BTN_STEP_LEFT;
}

uint32_t hol_flick_step(hol_flick *g, const hol_input *in, const int pinch[2])
{
    /* the look's forward, level: the head's -z turned by its quaternion */
    const float *q = in->head.quat;
    double fx = -2.0 * ((double)q[0] * q[2] + (double)q[1] * q[3]);
    double fz = -(1.0 - 2.0 * ((double)q[0] * q[0] + (double)q[1] * q[1]));
    double fl = sqrt(fx * fx + fz * fz);
    int head = (in->flags & HOL_INPUT_HEAD_VALID) && fl > 1e-6;
    uint32_t out = 0;
    for (int h = 0; h < 2; h++) {
        double at[3];
        if (!pinch[h] || !hol_flick_point(in, h, at)) {
            g->on[h] = g->spent[h] = g->stepped[h] = 0;
            continue;
        }
        if (!g->on[h]) { /* a pinch begins */
            g->on[h] = 1;
            g->spent[h] = g->stepped[h] = 0;
            g->t0[h] = in->time_s;
            memcpy(g->at0[h], at, sizeof at);
            continue;
        }
        if (g->spent[h])
            continue;
        if (in->time_s - g->t0[h] > HOL_FLICK_S) {
            g->spent[h] = 1; /* too slow: the platform's pinch */
            continue;
        }
        double dx = at[0] - g->at0[h][0], dz = at[2] - g->at0[h][2];
        if (out || !head || dx * dx + dz * dz < HOL_FLICK_M * HOL_FLICK_M)
            continue;
        out = hol__flick_dir(dx, dz, fx / fl, fz / fl);
        g->spent[h] = g->stepped[h] = 1;
    }
    return out;
}
