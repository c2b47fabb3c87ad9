/* hol_motion.c - room following (see hol_motion.h). */
#include "hol_motion.h"

#include <math.h>
#include <string.h>

#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

/* Crossings of the grid lines x = k and z = k by the floor segment from
 * (hx, hz) to (ex, ez), in order along it (ties: x first): the room
 * directions in out_dir and the segment parameters in out_t. */
static int hol__crossings(double hx, double hz, double ex, double ez, const hol_room *u,
                          double m, uint8_t out_dir[HOL_MOTION_MAX_STEPS],
                          double out_t[HOL_MOTION_MAX_STEPS])
{
    int n = 0;
    for (int k = 1; k < hol_room_cols(u); k++) {
        double g = k * m; /* the grid line x = k cells */
        if ((hx < g) != (ex < g)) {
            out_t[n] = (g - hx) / (ex - hx);
            out_dir[n++] = ex > hx ? HOL_DIR_E : HOL_DIR_W;
        }
    }
    for (int k = 1; k < hol_room_rows(u); k++) {
        double g = k * m;
        if ((hz < g) != (ez < g)) {
            out_t[n] = (g - hz) / (ez - hz);
            out_dir[n++] = ez > hz ? HOL_DIR_S : HOL_DIR_N;
        }
    }
    for (int i = 1; i < n; i++) /* stable insertion sort by t */
        for (int j = i; j > 0 && out_t[j] < out_t[j - 1]; j--) {
            double tt = out_t[j];
            out_t[j] = out_t[j - 1];
            out_t[j - 1] = tt;
            uint8_t dd = out_dir[j];
            out_dir[j] = out_dir[j - 1];
            out_dir[j - 1] = dd;
        }
    return n;
}

static int hol__inside_cell(const hol_room *u, double m, double x, double z)
{
    return x > u->col * m && x < (u->col + 1) * m && z > u->row * m && z < (u->row + 1) * m;
}

static double hol__cell_m(double cell_m)
{
    return cell_m >= HOL_MOTION_MIN_CELL && cell_m <= HOL_MOTION_MAX_CELL ? cell_m : 1.0;
}

hol_err hol_motion_eye_state(const hol_room *user, const double head[3],
                             const double eye[3], hol_room *out_state)
{
    return hol_motion_eye_state_m(user, 1.0, head, eye, out_state);
}

hol_err hol_motion_eye_state_m(const hol_room *user, double cell_m, const double head[3],
                               const double eye[3], hol_room *out_state)
{
    double hx = head[0], hz = head[2], ex = eye[0], ez = eye[2], m = hol__cell_m(cell_m);
    if (!hol__inside_cell(user, m, hx, hz))
        return HOL_EARG;
    if (!(ex > 0 && ex < hol_room_cols(user) * m && ez > 0 && ez < hol_room_rows(user) * m))
        return HOL_EROOM;
    uint8_t dir[HOL_MOTION_MAX_STEPS];
    double t[HOL_MOTION_MAX_STEPS];
    int n = hol__crossings(hx, hz, ex, ez, user, m, dir, t);
    hol_room st = *user;
    for (int i = 0; i < n; i++) {
        hol_err err = hol_room_step(&st, dir[i]);
        if (err)
            return err;
    }
    *out_state = st;
    return HOL_OK;
}

void hol_motion_init(hol_motion *m, const hol_room *user, const hol_motion_desc *desc)
{
    memset(m, 0, sizeof *m);
    if (desc)
        m->d = *desc;
    if (!(m->d.speed > 0))
        m->d.speed = 1.4;
    if (!(m->d.turn_rate > 0))
        m->d.turn_rate = 120;
    if (!(m->d.pitch_rate > 0))
        m->d.pitch_rate = 90;
    if (!(m->d.margin > 0))
        m->d.margin = 0.15;
    if (m->d.margin < 1e-3)
        m->d.margin = 1e-3;
    if (m->d.margin > 0.45)
        m->d.margin = 0.45;
    if (!(m->d.eye_height > 0))
        m->d.eye_height = 1.6;
    m->d.cell_m = hol__cell_m(m->d.cell_m);
    m->user = *user;
    m->head[0] = (user->col + 0.5) * m->d.cell_m;
    m->head[1] = m->d.eye_height;
    m->head[2] = (user->row + 0.5) * m->d.cell_m;
    m->pitch_deg = -30;
}

/* Clamp to the move area (0..size cells of m metres) less the margin; off
 * the grid lines. */
static double hol__clamp_axis(double v, double margin, int size, double m)
{
    double w = size * m;
    if (!(v == v))
        v = 0.5 * w;
    if (v < margin)
        v = margin;
    if (v > w - margin)
        v = w - margin;
    if (v / m == floor(v / m))
        v += 1e-6;
    return v;
}

hol_err hol_motion_move_to(hol_motion *m, const double pos[3],
                           hol_motion_steps *out_steps)
{
    hol_motion_steps local;
    hol_motion_steps *s = out_steps ? out_steps : &local;
    s->n = 0;
    double cm = m->d.cell_m;
    double x = hol__clamp_axis(pos[0], m->d.margin, hol_room_cols(&m->user), cm);
    double z = hol__clamp_axis(pos[2], m->d.margin, hol_room_rows(&m->user), cm);
    uint8_t dir[HOL_MOTION_MAX_STEPS];
    double t[HOL_MOTION_MAX_STEPS];
    double hx = m->head[0], hz = m->head[2];
    int n = hol__crossings(hx, hz, x, z, &m->user, cm, dir, t);
    for (int i = 0; i < n; i++) {
        hol_room next = m->user;
        hol_err err = hol_room_step(&next, dir[i]);
        if (err) {
            /* stop just before this edge, inside the current cell */
            double tt = t[i];
            double cx = hx + (x - hx) * tt, cz = hz + (z - hz) * tt;
            double lo_x = m->user.col * cm + 1e-6, hi_x = (m->user.col + 1) * cm - 1e-6;
            double lo_z = m->user.row * cm + 1e-6, hi_z = (m->user.row + 1) * cm - 1e-6;
            m->head[0] = cx < lo_x ? lo_x : cx > hi_x ? hi_x : cx;
            m->head[2] = cz < lo_z ? lo_z : cz > hi_z ? hi_z : cz;
            m->head[1] = pos[1];
            return err;
        }
        m->user = next;
        m->steps++;
        s->dir[s->n] = dir[i];
        s->after[s->n++] = next;
    }
    m->head[0] = x;
    m->head[1] = pos[1];
    m->head[2] = z;
    return HOL_OK;
}

void hol_motion_replace(hol_motion *m, const double pos[3], double yaw_was_deg)
{
    int cols = hol_room_cols(&m->user), rows = hol_room_rows(&m->user);
    double cm = m->d.cell_m;
    double x = hol__clamp_axis(pos[0], m->d.margin, cols, cm);
    double z = hol__clamp_axis(pos[2], m->d.margin, rows, cm);
    double turn = isfinite(yaw_was_deg - m->yaw_deg) ? (yaw_was_deg - m->yaw_deg) / 90 : 0;
    int q = (int)fmod(floor(turn + 0.5), 4.0);
    m->user.orient = (uint8_t)((m->user.orient + q + 4) & 3);
    m->user.col = (uint8_t)(x / cm);
    m->user.row = (uint8_t)(z / cm);
    m->head[0] = x;
    m->head[1] = pos[1];
    m->head[2] = z;
}

static double hol__clamp1(float v)
{
    return !(v == v) ? 0 : v < -1 ? -1 : v > 1 ? 1 : v;
}

hol_err hol_motion_pancake(hol_motion *m, const float move[2], const float turn[2],
                           double dt, hol_motion_steps *out_steps)
{
    if (!(dt >= 0) || !isfinite(dt)) {
        if (out_steps)
            out_steps->n = 0;
        return HOL_EARG;
    }
    m->yaw_deg += hol__clamp1(turn[0]) * m->d.turn_rate * dt;
    m->yaw_deg = fmod(m->yaw_deg, 360.0);
    if (m->yaw_deg < 0)
        m->yaw_deg += 360.0;
    m->pitch_deg += hol__clamp1(turn[1]) * m->d.pitch_rate * dt;
    m->pitch_deg = m->pitch_deg < -89 ? -89 : m->pitch_deg > 89 ? 89 : m->pitch_deg;
    double yr = m->yaw_deg * HOL__PI / 180;
    double fwd = hol__clamp1(move[1]) * m->d.speed * dt;
    double side = hol__clamp1(move[0]) * m->d.speed * dt;
    double sy = hol_sin(yr), cy = hol_cos(yr);
    double pos[3] = {m->head[0] - fwd * sy + side * cy, m->head[1],
                     m->head[2] - fwd * cy - side * sy};
    if (fwd == 0 && side == 0) {
        if (out_steps)
            out_steps->n = 0;
        return HOL_OK;
    }
    return hol_motion_move_to(m, pos, out_steps);
}

double hol_motion_snap_yaw(double yaw_deg, double step_deg, int turns)
{
    if (!(step_deg > 0) || !isfinite(yaw_deg))
        return 0;
    /* the multiple k * step at or just beyond the yaw, within 1e-6 of a step */
    double k = yaw_deg / step_deg;
    double m = turns > 0 ? floor(k + 1e-6) + turns : ceil(k - 1e-6) + turns;
    if (turns == 0)
        m = k;
    double y = fmod(m * step_deg, 360.0);
    if (y < 0)
        y += 360.0;
    return y >= 360.0 ? 0 : y;
}
