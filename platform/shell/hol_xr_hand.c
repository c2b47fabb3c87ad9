/* hol_xr_hand.c - an OpenXR hand's joints as the record's (see
 * hol_xr_hand.h). */
#include "hol_xr_hand.h"

#include <math.h>
#include <string.h>

int hol_xr_hand_joints(const hol_xr_calib *c, int active,
                       const float pos[HOL_XR_HAND_JOINTS][3],
                       const float radius[HOL_XR_HAND_JOINTS],
                       const unsigned flags[HOL_XR_HAND_JOINTS], hol_hand_joints *out)
{
    static const float one[4] = {0, 0, 0, 1};
    memset(out, 0, sizeof *out);
    if (!active)
        return 0;
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        const float *p = pos[i + 1];
        if (!(flags[i + 1] & HOL_XR_HAND_POS_VALID))
            break;
        int finite = 1;
        for (int k = 0; k < 3; k++)
            finite &= isfinite(p[k]) && fabsf(p[k]) < 1e4f;
        if (!finite)
            break;
        hol_pose j;
        hol_xr_to_room(c, p, one, &j);
        memcpy(out->pos[i], j.pos, sizeof j.pos);
        float r = radius[i + 1];
        out->radius[i] = r > 0 && r < 1 ? r : 0;
        if (i == HOL_HAND_JOINTS - 1)
            out->tracked = 1;
    }
    if (!out->tracked)
        memset(out, 0, sizeof *out);
    return (int)out->tracked;
}
