/* hol_app_geom.c - the app's lowest helpers, used by its view, its
 * pointing question and its questionnaires (hol_app_view.c,
 * hol_app_point.c, hol_app_ask.c) and by the level's checks: a head or
 * hand's yaw and pitch from its quaternion, and text wrapped to the HUD's
 * columns (hol_app_wrap, see hol_app.h). It calls no other app file. */
#include <math.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_math.h"

#define HOL__PI 3.14159265358979323846

void hol__yaw_pitch_from_quat(const float qf[4], double *yaw, double *pitch)
{
    double x = qf[0], y = qf[1], z = qf[2], w = qf[3];
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (!(n > 0))
        return;
    x /= n, y /= n, z /= n, w /= n;
    double fx = -2 * (x * z + w * y), fy = -2 * (y * z - w * x),
           fz = -(1 - 2 * (x * x + y * y));
    fy = fy < -1 ? -1 : fy > 1 ? 1 : fy;
    *pitch = hol_asin(fy) * 180 / HOL__PI;
    *yaw = hol_atan2(-fx, -fz) * 180 / HOL__PI;
}

void hol__utf8_cut(char *s, size_t max)
{
    if (strlen(s) <= max)
        return;
    while (max > 0 && ((unsigned char)s[max] & 0xc0) == 0x80)
        max--;
    s[max] = 0;
}

int hol_app_wrap(const char *text, int cols, char (*out)[HOL_APP_TEXT_MAX], int max)
{
    if (cols < 1)
        cols = 1;
    if (cols > HOL_APP_TEXT_MAX - 1)
        cols = HOL_APP_TEXT_MAX - 1;
    int n = 0;
    size_t len = strlen(text), at = 0;
    while (at < len && text[at] == ' ')
        at++;
    while (at < len) {
        /* fit: the bytes of the first cols characters (a UTF-8 sequence
         * whole) within a line's bytes; ASCII: cols bytes */
        size_t fit = 0;
        for (int c = 0; c < cols && at + fit < len; c++) {
            size_t k = 1;
            while (at + fit + k < len && ((unsigned char)text[at + fit + k] & 0xc0) == 0x80)
                k++;
            if (fit + k > HOL_APP_TEXT_MAX - 1)
                break;
            fit += k;
        }
        size_t take = len - at;
        if (take > fit) {
            size_t sp = fit; /* the last space at or before the fit's end */
            while (sp > 0 && text[at + sp] != ' ')
                sp--;
            take = sp > 0 ? sp : fit;
        }
        size_t keep = take;
        while (keep > 0 && text[at + keep - 1] == ' ')
            keep--;
        if (out && n < max) {
            memcpy(out[n], text + at, keep);
            out[n][keep] = 0;
        }
        n++;
        at += take;
        while (at < len && text[at] == ' ')
            at++;
    }
    return n;
}
