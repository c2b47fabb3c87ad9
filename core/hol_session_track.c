/* hol_session_track.c - the tracker rows of track-NNN.csv: the head and
 * both hands (controllers or tracked hands) at exact samples k / hz of level
 * time, interpolated between the frames around them (see hol_session.h). */
#include "hol_session_impl.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_input_io.h"

/* The index of the last sample k / hz at or before level time t (a whole
 * number as a double: exact below 2^53, and no cast that can overflow). */
double hol__last_sample_hz(double t, int hz)
{
    double k = floor(t * hz);
    if ((k + 1) / hz <= t)
        k += 1;
    else if (k / hz > t)
        k -= 1;
    return k;
}

static void hol__track_frame_of(hol__track_frame *f, const hol_app_view *v,
                                const hol_input *in)
{
    static const uint32_t valid[2] = {HOL_INPUT_HAND_L_VALID, HOL_INPUT_HAND_R_VALID};
    memset(f, 0, sizeof *f);
    f->valid = 1;
    f->t = v->hud.elapsed_s;
    f->device = in ? in->device : 0;
    for (int i = 0; i < 3; i++)
        f->pose[0][i] = v->head[i];
    for (int i = 0; i < 4; i++)
        f->pose[0][3 + i] = v->head_quat[i];
    f->ok[0] = 1;
    for (int h = 0; in && h < 2; h++) {
        if (!(in->flags & valid[h]))
            continue;
        f->ok[1 + h] = 1;
        for (int i = 0; i < 3; i++)
            f->pose[1 + h][i] = in->hand[h].pos[i];
        for (int i = 0; i < 4; i++)
            f->pose[1 + h][3 + i] = in->hand[h].quat[i];
    }
}

/* Pose a of the way from p to c: position linear, orientation normalized
 * linear the short way round (the ends exact). */
static void hol__pose_mix(const double p[7], const double c[7], double a, double out[7])
{
    if (a <= 0 || a >= 1) {
        memcpy(out, a <= 0 ? p : c, 7 * sizeof *out);
        return;
    }
    double dot = 0, n = 0;
    for (int i = 3; i < 7; i++)
        dot += p[i] * c[i];
    double sign = dot < 0 ? -1 : 1;
    for (int i = 0; i < 3; i++)
        out[i] = p[i] + a * (c[i] - p[i]);
    for (int i = 3; i < 7; i++) {
        out[i] = (1 - a) * p[i] + a * sign * c[i];
        n += out[i] * out[i];
    }
    n = sqrt(n);
    for (int i = 3; i < 7 && n > 1e-12; i++)
        out[i] /= n;
}

/* A pose's seven fields (",x,y,z,qx,qy,qz,qw"), or seven empty ones. */
static size_t hol__pose_fields(char *out, size_t cap, int ok, const double v[7])
{
    int n = ok ? snprintf(out, cap, ",%.4f,%.4f,%.4f,%.5f,%.5f,%.5f,%.5f", v[0], v[1], v[2],
                          v[3], v[4], v[5], v[6])
               : snprintf(out, cap, ",,,,,,,");
    return n > 0 && (size_t)n < cap ? (size_t)n : 0;
}

/* One row: sample k at time k / hz, between frames p and c (a the share
 * of c); each pose tracked as in the nearer frame, mixed when both track
 * it. */
static void hol__track_row(hol_session *s, const char *name, double k,
                           const hol__track_frame *p, const hol__track_frame *c, double a)
{
    const hol__track_frame *near = a >= 0.5 ? c : p;
    const char *dev = hol_input_device_name(near->device);
    char row[1024];
    int n = snprintf(row, sizeof row, "%s,%d,%s,%.0f,%.4f,%.4f,%s", s->meta.session,
                     s->attempt, name, k, k / s->track_hz, c->t, dev ? dev : "");
    if (n <= 0 || (size_t)n >= sizeof row)
        return;
    size_t len = (size_t)n;
    for (int j = 0; j < 3; j++) {
        double pose[7];
        int ok = near->ok[j];
        if (ok && p->ok[j] && c->ok[j])
            hol__pose_mix(p->pose[j], c->pose[j], a, pose);
        else if (ok)
            memcpy(pose, near->pose[j], sizeof pose);
        size_t w = hol__pose_fields(row + len, sizeof row - len, ok, pose);
        if (!w)
            return;
        len += w;
    }
    if (len + 1 >= sizeof row)
        return;
    row[len++] = '\n';
    hol__out_put(s, &s->track, row, len);
}

void hol__track_rows(hol_session *s, const hol_app_view *v, const hol_input *in,
                     const char *name)
{
    hol__track_frame cur;
    hol__track_frame_of(&cur, v, in);
    const hol__track_frame prev = s->track_prev.valid ? s->track_prev : cur, *p = &prev;
    s->track_prev = cur;
    int hz = s->track_hz;
    double last = hol__last_sample_hz(cur.t, hz), due = last - s->track_next + 1;
    if (due < 1)
        return;
    if (cur.t - p->t > HOL_SESSION_GAP_S || due > HOL_SESSION_GAP_S * hz + 1) {
        /* one gap row for the samples it hides: pose fields empty */
        hol__out_printf(s, &s->track, "%s,%d,%s,%.0f,%.4f,%.4f,gap%s\n", s->meta.session,
                        s->attempt, name, s->track_next, s->track_next / hz, cur.t,
                        ",,,,,,,,,,,,,,,,,,,,,");
        s->track_next = last + 1;
        return;
    }
    for (; s->track_next <= last; s->track_next++) {
        double span = cur.t - p->t, t = s->track_next / hz;
        double a = span > 0 ? (t - p->t) / span : 1;
        a = a < 0 ? 0 : a > 1 ? 1 : a;
        hol__track_row(s, name, s->track_next, p, &cur, a);
    }
}
