/* hol_xr_room.c - the room in the stage, the lifecycle (see hol_xr_room.h). */
#include "hol_xr_room.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* q = a * b (x, y, z, w) */
static void hol__qmul(const double a[4], const double b[4], double q[4])
{
    q[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    q[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    q[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    q[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
}

/* rotation about +y by angle a, applied to (x, z) */
static void hol__roty(double a, double x, double z, double *ox, double *oz)
{
    double c = cos(a), s = sin(a);
    *ox = x * c + z * s;
    *oz = -x * s + z * c;
}

static double hol__half(double h)
{
    return h > 0 ? h : 1.5;
}

void hol_xr_to_room(const hol_xr_calib *c, const float stage_pos[3], const float stage_quat[4],
                    hol_pose *out)
{
    double x, z;
    hol__roty(-c->yaw, stage_pos[0] - c->ox, stage_pos[2] - c->oz, &x, &z);
    out->pos[0] = (float)(x + hol__half(c->half_w));
    out->pos[1] = stage_pos[1];
    out->pos[2] = (float)(z + hol__half(c->half_d));
    double r[4] = {0, sin(-c->yaw / 2), 0, cos(-c->yaw / 2)};
    double q[4] = {stage_quat[0], stage_quat[1], stage_quat[2], stage_quat[3]}, o[4];
    hol__qmul(r, q, o);
    for (int k = 0; k < 4; k++)
        out->quat[k] = (float)o[k];
}

void hol_xr_to_stage(const hol_xr_calib *c, const hol_pose *room, float out_pos[3],
                     float out_quat[4])
{
    double x, z;
    hol__roty(c->yaw, room->pos[0] - hol__half(c->half_w), room->pos[2] - hol__half(c->half_d),
              &x, &z);
    out_pos[0] = (float)(x + c->ox);
    out_pos[1] = room->pos[1];
    out_pos[2] = (float)(z + c->oz);
    double r[4] = {0, sin(c->yaw / 2), 0, cos(c->yaw / 2)};
    double q[4] = {room->quat[0], room->quat[1], room->quat[2], room->quat[3]}, o[4];
    hol__qmul(r, q, o);
    for (int k = 0; k < 4; k++)
        out_quat[k] = (float)o[k];
}

void hol_xr_recentre(hol_xr_calib *c, const float head_pos[3], const float head_quat[4])
{
    /* forward = q (0, 0, -1) */
    double x = head_quat[0], y = head_quat[1], z = head_quat[2], w = head_quat[3];
    double fx = -(2 * (x * z + w * y)), fz = -(1 - 2 * (x * x + y * y));
    if (fx * fx + fz * fz > 1e-6)
        c->yaw = atan2(-fx, -fz);
    c->ox = head_pos[0];
    c->oz = head_pos[2];
}

int hol_xr_bounds_hold_room(float width, float depth)
{
    return hol_xr_bounds_hold(width, depth, 3.0, 3.0);
}

int hol_xr_bounds_hold(float width, float depth, double room_w, double room_d)
{
    return width >= room_w - 1e-4 && depth >= room_d - 1e-4;
}

double hol_xr_fade(const double eye[2][3], double margin)
{
    return hol_xr_fade_room(eye, margin, 3.0, 3.0);
}

double hol_xr_fade_room(const double eye[2][3], double margin, double room_w, double room_d)
{
    double size[3] = {room_w, 0, room_d};
    double ramp = margin - HOL_XR_FADE_FULL, f = 0;
    for (int e = 0; e < 2; e++) {
        if (!isfinite(eye[e][0]) || !isfinite(eye[e][2]))
            return 1; /* not a position: nothing safe to show */
        double d = 0;
        for (int k = 0; k <= 2; k += 2) {
            double lo = margin - eye[e][k], hi = eye[e][k] - (size[k] - margin);
            d = lo > d ? lo : d;
            d = hi > d ? hi : d;
        }
        double fe = ramp > 0 ? d / ramp : (d > 0 ? 1 : 0);
        f = fe > f ? fe : f;
    }
    return f > 1 ? 1 : f;
}

int hol_xr_outside_eyes(const hol_app_view *v, const hol_input *in, double eye[2][3])
{
    if (!v || !in || !v->outside.on)
        return 0;
    for (int e = 0; e < 2; e++)
        for (int k = 0; k <= 2; k += 2)
            eye[e][k] += v->head[k] - in->head.pos[k];
    return 1;
}

/* "0.6", "1.0", "0.55": metres from centimetres */
static void hol__m(int cm, char out[16])
{
    if (cm % 10)
        snprintf(out, 16, "%d.%02d", cm / 100 % 100, cm % 100);
    else
        snprintf(out, 16, "%d.%d", cm / 100 % 100, cm / 10 % 10);
}

int hol_xr_fit_note(const hol_fit *f, int offered, const hol_app_view *v, hol_app_view *out)
{
    if (v->hud.nlines + 2 > HOL_APP_HUD_LINES)
        return 0;
    *out = *v;
    hol_app_hud *h = &out->hud;
    double m = v->cell_m > 0 ? v->cell_m : 1.0;
    int c = hol_room_cols(&v->user), r = hol_room_rows(&v->user);
    int fitted = c == f->cols && r == f->rows && fabs(m - f->cell_m) < 1e-9 && !f->too_small;
    char cell[16], fcell[16], w[16], d[16];
    int aw = (int)floor(f->area_w * 10 + 0.5), ad = (int)floor(f->area_d * 10 + 0.5);
    hol__m((int)floor(m * 100 + 0.5), cell);
    hol__m(f->cell_cm, fcell);
    hol__m((aw > 9999 ? 9999 : aw) * 10, w);
    hol__m((ad > 9999 ? 9999 : ad) * 10, d);
    char tmp[2][96]; /* short lines: an eye's HUD is narrow */
    snprintf(tmp[0], sizeof tmp[0], "ROOM %d X %d OF %s M%s", c, r, cell,
             fitted || offered ? "" : f->too_small ? ": TOO BIG" : " (ASKED)");
    if (fitted)
        snprintf(tmp[1], sizeof tmp[1], "FITS YOUR %s X %s M AREA", w, d);
    else if (offered && !f->too_small)
        snprintf(tmp[1], sizeof tmp[1], "%d X %d OF %s FITS: RELOAD", f->cols, f->rows, fcell);
    else
        snprintf(tmp[1], sizeof tmp[1], "YOUR AREA: %s X %s M", w, d);
    for (int k = 0; k < 2; k++) {
        size_t n = strlen(tmp[k]);
        n = n < HOL_APP_TEXT_MAX - 1 ? n : HOL_APP_TEXT_MAX - 1;
        memcpy(h->lines[h->nlines], tmp[k], n);
        h->lines[h->nlines++][n] = 0;
    }
    return 1;
}

hol_xr_do hol_xr_lifecycle(int state, int *out_running, int *out_focused)
{
    *out_focused = state == HOL_XR_STATE_FOCUSED;
    switch (state) {
    case HOL_XR_STATE_READY:
        *out_running = 1;
        return HOL_XR_DO_BEGIN;
    case HOL_XR_STATE_SYNCHRONIZED:
    case HOL_XR_STATE_VISIBLE:
    case HOL_XR_STATE_FOCUSED:
        *out_running = 1;
        return HOL_XR_DO_NOTHING;
    case HOL_XR_STATE_STOPPING:
        *out_running = 0;
        return HOL_XR_DO_END;
    case HOL_XR_STATE_EXITING:
    case HOL_XR_STATE_LOSS_PENDING:
        *out_running = 0;
        return HOL_XR_DO_TEAR_DOWN;
    default:
        *out_running = 0;
        return HOL_XR_DO_NOTHING;
    }
}

hol_xr_do hol_xr_life_event(hol_xr_life *l, int state)
{
    l->state = state;
    hol_xr_do d = hol_xr_lifecycle(state, &l->running, &l->focused);
    if (d == HOL_XR_DO_TEAR_DOWN)
        l->done = 1;
    if (d == HOL_XR_DO_BEGIN && ++l->begins > 1)
        l->off = 1; /* begun again: the frames it missed were the headset off */
    return d;
}

void hol_xr_life_recentred(hol_xr_life *l)
{
    l->recentre = 1;
}

uint32_t hol_xr_life_take(hol_xr_life *l, int head_valid)
{
    if (!head_valid || !l->recentre)
        return 0;
    l->recentre = 0;
    return HOL_INPUT_RECENTRED;
}

uint32_t hol_xr_life_state(hol_xr_life *l)
{
    int worn = !l->off && (l->state == HOL_XR_STATE_VISIBLE || l->state == HOL_XR_STATE_FOCUSED);
    l->off = 0;
    return HOL_INPUT_HEADSET | HOL_INPUT_WAY_BACK | (l->focused ? HOL_INPUT_FOCUSED : 0u) |
           (worn ? 0u : HOL_INPUT_HEADSET_OFF);
}

hol_xr_quit hol_xr_life_quit(hol_xr_life *l)
{
    if (l->quit_requested || l->done)
        return HOL_XR_QUIT_NONE;
    l->quit_requested = 1;
    if (l->running)
        return HOL_XR_QUIT_REQUEST_EXIT;
    l->done = 1;
    return HOL_XR_QUIT_LEAVE;
}
