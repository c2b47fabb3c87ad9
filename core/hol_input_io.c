/* hol_input_io.c - input records as text lines (see hol_input_io.h). */
#include "hol_input_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int hol__pose_valid(const hol_pose *p)
{
    for (int i = 0; i < 3; i++)
        if (!isfinite(p->pos[i]))
            return 0;
    for (int i = 0; i < 4; i++)
        if (!isfinite(p->quat[i]))
            return 0;
    return 1;
}

/* A tracked hand's joints: finite, radii >= 0 (untracked: not read). */
static int hol__joints_valid(const hol_hand_joints *j)
{
    if (!j->tracked)
        return 1;
    if (j->tracked != 1)
        return 0;
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        for (int k = 0; k < 3; k++)
            if (!isfinite(j->pos[i][k]))
                return 0;
        if (!(j->radius[i] >= 0 && j->radius[i] < 1))
            return 0;
    }
    return 1;
}

static int hol__axis_ok(float v)
{
    return v >= -1.0f && v <= 1.0f;
}

static const char *const hol__device_names[HOL_DEVICE_COUNT] = {
    "", "keyboard", "gamepad", "xr-simple", "xr-touch", "xr-vive", "xr-index", "xr-wmr", "xr",
    "webxr-touch", "webxr-hand", "xr-hand", "touchscreen"};

const char *hol_input_device_name(uint32_t device)
{
    return device < HOL_DEVICE_COUNT ? hol__device_names[device] : NULL;
}

int hol_input_valid(const hol_input *in)
{
    if (!(isfinite(in->time_s) && in->time_s >= 0))
        return 0;
    if ((in->flags & ~(uint32_t)HOL_INPUT_FLAGS_ALL) || (in->buttons & ~(uint32_t)HOL_BTN_ALL) ||
        (in->pressed & ~(uint32_t)HOL_BTN_ALL) || in->device >= HOL_DEVICE_COUNT)
        return 0;
    if (!(in->snap_yaw_deg >= 0 && in->snap_yaw_deg < 360))
        return 0;
    for (int i = 0; i < 2; i++)
        if (!hol__axis_ok(in->move[i]) || !hol__axis_ok(in->turn[i]))
            return 0;
    return hol__pose_valid(&in->head) && hol__pose_valid(&in->hand[0]) &&
           hol__pose_valid(&in->hand[1]) && hol__joints_valid(&in->joints[0]) &&
           hol__joints_valid(&in->joints[1]);
}

static int hol__all_zero(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++)
        if (b[i])
            return 0;
    return 1;
}

/* Append to out at *len; 1 on overflow. */
static int hol__put(char *out, size_t cap, size_t *len, const char *fmt, double v)
{
    int n = snprintf(out + *len, cap - *len, fmt, v);
    if (n < 0 || (size_t)n >= cap - *len)
        return 1;
    *len += (size_t)n;
    return 0;
}

static int hol__put_hex(char *out, size_t cap, size_t *len, const char *fmt, uint32_t v)
{
    int n = snprintf(out + *len, cap - *len, fmt, (unsigned)v);
    if (n < 0 || (size_t)n >= cap - *len)
        return 1;
    *len += (size_t)n;
    return 0;
}

static int hol__put_floats(char *out, size_t cap, size_t *len, const char *key,
                           const float *v, int n)
{
    size_t kl = strlen(key);
    if (cap - *len <= kl)
        return 1;
    memcpy(out + *len, key, kl + 1);
    *len += kl;
    for (int i = 0; i < n; i++)
        if (hol__put(out, cap, len, i ? ",%.9g" : "%.9g", v[i]))
            return 1;
    return 0;
}

size_t hol_input_format(const hol_input *in, char *out, size_t cap)
{
    if (!cap || !hol_input_valid(in))
        return 0;
    size_t len = 0;
    out[0] = 0;
    if (hol__put(out, cap, &len, "%.17g", in->time_s))
        return 0;
    if (in->flags && hol__put_hex(out, cap, &len, " f=%x", in->flags))
        return 0;
    if (in->buttons && hol__put_hex(out, cap, &len, " b=%x", in->buttons))
        return 0;
    if (in->pressed && hol__put_hex(out, cap, &len, " p=%x", in->pressed))
        return 0;
    if (!hol__all_zero(in->move, sizeof in->move) &&
        hol__put_floats(out, cap, &len, " m=", in->move, 2))
        return 0;
    if (!hol__all_zero(in->turn, sizeof in->turn) &&
        hol__put_floats(out, cap, &len, " t=", in->turn, 2))
        return 0;
    if (!hol__all_zero(&in->snap_yaw_deg, sizeof in->snap_yaw_deg) &&
        hol__put_floats(out, cap, &len, " y=", &in->snap_yaw_deg, 1))
        return 0;
    static const char *const pkey[3] = {" h=", " l=", " r="};
    const hol_pose *poses[3] = {&in->head, &in->hand[0], &in->hand[1]};
    for (int p = 0; p < 3; p++) {
        if (hol__all_zero(poses[p], sizeof *poses[p]))
            continue;
        float v[7];
        memcpy(v, poses[p]->pos, sizeof poses[p]->pos);
        memcpy(v + 3, poses[p]->quat, sizeof poses[p]->quat);
        if (hol__put_floats(out, cap, &len, pkey[p], v, 7))
            return 0;
    }
    if (in->device) {
        const char *dn = hol__device_names[in->device];
        size_t dl = strlen(dn);
        if (cap - len <= dl + 3)
            return 0;
        memcpy(out + len, " d=", 3);
        memcpy(out + len + 3, dn, dl + 1);
        len += dl + 3;
    }
    return len;
}

/* A decimal number token [s, e): digits, sign, point, exponent only. */
static int hol__num_chars(const char *s, const char *e)
{
    if (s == e)
        return 0;
    for (const char *p = s; p < e; p++)
        if (!((*p >= '0' && *p <= '9') || *p == '-' || *p == '+' || *p == '.' ||
              *p == 'e' || *p == 'E'))
            return 0;
    return 1;
}

/* Parse n comma-separated floats in [s, e). */
static int hol__parse_floats(const char *s, const char *e, float *out, int n)
{
    char buf[64];
    for (int i = 0; i < n; i++) {
        const char *c = memchr(s, ',', (size_t)(e - s));
        const char *te = i == n - 1 ? e : c;
        if (!te || (i == n - 1 && c) || !hol__num_chars(s, te) ||
            (size_t)(te - s) >= sizeof buf)
            return 1;
        memcpy(buf, s, (size_t)(te - s));
        buf[te - s] = 0;
        char *end;
        float v = strtof(buf, &end);
        if (*end || !isfinite(v))
            return 1;
        out[i] = v;
        s = te + 1;
    }
    return 0;
}

static int hol__parse_hex(const char *s, const char *e, uint32_t *out)
{
    if (s == e || e - s > 8)
        return 1;
    uint32_t v = 0;
    for (const char *p = s; p < e; p++) {
        int d = *p >= '0' && *p <= '9' ? *p - '0' : *p >= 'a' && *p <= 'f' ? *p - 'a' + 10 : -1;
        if (d < 0)
            return 1;
        v = v << 4 | (uint32_t)d;
    }
    *out = v;
    return 0;
}

static int hol__parse_device(const char *s, const char *e, uint32_t *out)
{
    for (uint32_t d = 1; d < HOL_DEVICE_COUNT; d++) {
        size_t n = strlen(hol__device_names[d]);
        if ((size_t)(e - s) == n && !memcmp(s, hol__device_names[d], n)) {
            *out = d;
            return 0;
        }
    }
    return 1;
}

hol_err hol_input_parse(const char *s, size_t len, hol_input *out, size_t *out_bad)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    size_t bad = 0;
    const char *end = s + len, *p = s;
    if (len == 0 || memchr(s, 0, len))
        goto fail;
    /* the time */
    const char *te = memchr(p, ' ', len);
    if (!te)
        te = end;
    char buf[64];
    if (!hol__num_chars(p, te) || (size_t)(te - p) >= sizeof buf)
        goto fail;
    memcpy(buf, p, (size_t)(te - p));
    buf[te - p] = 0;
    char *nend;
    in.time_s = strtod(buf, &nend);
    if (*nend || !isfinite(in.time_s) || in.time_s < 0)
        goto fail;
    unsigned seen = 0;
    p = te;
    while (p < end) {
        /* p at a separating space */
        p++;
        bad = (size_t)(p - s);
        const char *fe = memchr(p, ' ', (size_t)(end - p));
        if (!fe)
            fe = end;
        if (fe - p < 3 || p[1] != '=')
            goto fail;
        const char *keys = "fbmthlrpyd", *k = memchr(keys, p[0], 10);
        if (!k)
            goto fail;
        unsigned bit = 1u << (k - keys);
        if (seen & bit)
            goto fail;
        seen |= bit;
        const char *v = p + 2;
        int err = 0;
        switch (p[0]) {
        case 'f': err = hol__parse_hex(v, fe, &in.flags); break;
        case 'b': err = hol__parse_hex(v, fe, &in.buttons); break;
        case 'm': err = hol__parse_floats(v, fe, in.move, 2); break;
        case 't': err = hol__parse_floats(v, fe, in.turn, 2); break;
        case 'p': err = hol__parse_hex(v, fe, &in.pressed); break;
        case 'y': err = hol__parse_floats(v, fe, &in.snap_yaw_deg, 1); break;
        case 'd': err = hol__parse_device(v, fe, &in.device); break;
        default: {
            hol_pose *pose = p[0] == 'h' ? &in.head : p[0] == 'l' ? &in.hand[0] : &in.hand[1];
            float f7[7];
            err = hol__parse_floats(v, fe, f7, 7);
            if (!err) {
                memcpy(pose->pos, f7, sizeof pose->pos);
                memcpy(pose->quat, f7 + 3, sizeof pose->quat);
            }
        }
        }
        if (err)
            goto fail;
        p = fe;
    }
    if (!hol_input_valid(&in)) {
        bad = 0;
        goto fail;
    }
    *out = in;
    return HOL_OK;
fail:
    if (out_bad)
        *out_bad = bad;
    return HOL_EPARSE;
}
