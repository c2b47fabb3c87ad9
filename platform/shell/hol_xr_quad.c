/* hol_xr_quad.c - the world panel as a quad layer (see hol_xr_quad.h). */
#include "hol_xr_quad.h"

#include <math.h>
#include <string.h>

#include "../../render/hol_hud.h"

void hol_xr_quad_place(const hol_xr_calib *c, const double panel_pos[3],
                       const double panel_orient[4], int map, double px, const float shift[3],
                       hol_xr_quad *out)
{
    double box[4];
    hol_hud_panel_box(map, px, box);
    double x = panel_orient[0], y = panel_orient[1], z = panel_orient[2], w = panel_orient[3];
    double n = sqrt(x * x + y * y + z * z + w * w);
    if (n < 1e-12) {
        x = y = z = 0;
        w = n = 1;
    }
    x /= n, y /= n, z /= n, w /= n;
    /* the panel's right and up axes: the rotation's first two columns */
    double right[3] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)};
    double up[3] = {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)};
    hol_pose room;
    for (int k = 0; k < 3; k++)
        room.pos[k] = (float)(panel_pos[k] + right[k] * box[2] + up[k] * box[3] -
                              (shift ? shift[k] : 0));
    room.quat[0] = (float)x;
    room.quat[1] = (float)y;
    room.quat[2] = (float)z;
    room.quat[3] = (float)w;
    hol_xr_to_stage(c, &room, out->pos, out->quat);
    out->size[0] = (float)box[0];
    out->size[1] = (float)box[1];
    double k = px > 0 ? px : HOL_RENDER_PANEL_PX;
    out->rect[0] = (int)lround(box[0] / k * HOL_XR_QUAD_TEXELS);
    out->rect[1] = (int)lround(box[1] / k * HOL_XR_QUAD_TEXELS);
}

void hol_xr_quad_image(int *out_w, int *out_h)
{
    double box[4];
    hol_hud_panel_box(1, 1, box); /* in font pixels */
    *out_w = (int)lround(box[0] * HOL_XR_QUAD_TEXELS);
    *out_h = (int)lround(box[1] * HOL_XR_QUAD_TEXELS);
}

int hol_xr_quad_stale(hol_xr_quad_cache *c, uint64_t key)
{
    if (c->drawn && c->key == key)
        return 0;
    c->drawn = 1;
    c->key = key;
    c->redraws++;
    return 1;
}

void hol_xr_quad_forget(hol_xr_quad_cache *c)
{
    c->drawn = 0;
}
