#include "hol_bearing.h"

#include <math.h>

#include "hol_hyper.h"
#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

double hol_bearing_of_vector(double east, double north)
{
    if (east == 0.0 && north == 0.0)
        return 0.0;
    double d = hol_atan2(east, north) * (180.0 / HOL__PI);
    d = fmod(d, 360.0);
    if (d < 0.0)
        d += 360.0;
    if (d >= 360.0)
        d -= 360.0;
    return d;
}

int hol_bearing_format(double deg, char buf[HOL_BEARING_TEXT])
{
    if (!(deg > -1e9 && deg < 1e9))
        deg = 0.0; /* NaN or absurd: never undefined behaviour */
    double r = floor(fmod(deg, 360.0) * 10.0 + 0.5);
    long tenths = (long)r;
    tenths %= 3600;
    if (tenths < 0)
        tenths += 3600;
    char tmp[HOL_BEARING_TEXT];
    int n = 0;
    long v = tenths / 10;
    do {
        tmp[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    int len = 0;
    while (n)
        buf[len++] = tmp[--n];
    buf[len++] = '.';
    buf[len++] = (char)('0' + tenths % 10);
    buf[len] = '\0';
    return len;
}

hol_err hol_bearing_true(hol_tile u, int u_north, hol_tile t, double *out_deg)
{
    if (hol_tile_q(u) == 0 || hol_tile_q(u) != hol_tile_q(t) || hol_tile_eq(u, t))
        return HOL_EARG;
    double p[3];
    hol_err err = hol_hyper_pos(u, u_north & 3, t, p, NULL, NULL);
    if (err)
        return err;
    /* p in u's frame: +y room north, +x room east. On the hyperboloid the
     * geodesic from the centre (0, 0, 1) to p starts along (x, y); in the
     * flat grid the segment does. */
    *out_deg = hol_bearing_of_vector(p[0], p[1]);
    return HOL_OK;
}

hol_err hol_bearing_begin(hol_bearing_walk *w, hol_tile target)
{
    int q = hol_tile_q(target);
    if (q == 0)
        return HOL_EARG;
    hol_bearing_walk z = {0};
    z.target = target;
    z.at = hol_tile_origin_q(q);
    if (hol_tile_eq(z.at, target))
        z.seen = 1;
    *w = z;
    return HOL_OK;
}

hol_err hol_bearing_step(hol_bearing_walk *w, int dir)
{
    static const int dx[4] = {0, -1, 0, 1}, dy[4] = {1, 0, -1, 0};
    if (dir < 0 || dir > 3)
        return HOL_EARG;
    hol_tile next;
    int arrive;
    hol_err err = hol_tile_step(w->at, (w->orient + dir) & 3, &next, &arrive);
    if (err)
        return err;
    w->at = next;
    w->orient = (arrive - dir) & 3;
    w->x += dx[dir];
    w->y += dy[dir];
    w->steps++;
    if (!w->seen && hol_tile_eq(next, w->target)) {
        w->seen = 1;
        w->tx = w->x;
        w->ty = w->y;
    }
    return HOL_OK;
}

hol_err hol_bearing_end(const hol_bearing_walk *w, hol_bearing *out)
{
    hol_bearing b = {0};
    if (!hol_tile_eq(w->at, w->target)) {
        hol_err err = hol_bearing_true(w->at, w->orient, w->target, &b.true_deg);
        if (err)
            return err;
        b.has_true = 1;
    }
    if (w->seen && (w->tx != w->x || w->ty != w->y)) {
        b.has_flat = 1;
        b.flat_deg = hol_bearing_of_vector((double)(w->tx - w->x), (double)(w->ty - w->y));
    }
    *out = b;
    return HOL_OK;
}
