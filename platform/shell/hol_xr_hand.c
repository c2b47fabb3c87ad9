/* hol_xr_hand.c - an OpenXR hand's joints as the record's (see
 * hol_xr_hand.h). */
#include "hol_xr_hand.h"

#include <string.h>

#include "../../core/hol_body.h"

int hol_xr_hand_joints(const hol_xr_calib *c, int active,
                       const float pos[HOL_XR_HAND_JOINTS][3],
                       const float radius[HOL_XR_HAND_JOINTS],
                       const unsigned flags[HOL_XR_HAND_JOINTS], hol_hand_joints *out)
{
    static const float one[4] = {0, 0, 0, 1};
    memset(out, 0, sizeof *out);
    if (!active)
        return 0;
    uint32_t located = 0;
    for (int i = 0; i < HOL_HAND_JOINTS; i++)
        located |= flags[i + 1] & HOL_XR_HAND_POS_VALID ? 1u << i : 0u;
    if (!hol_hand_joints_usable(pos + 1, located)) /* the palm (0) dropped */
        return 0;
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        hol_pose j;
        hol_xr_to_room(c, pos[i + 1], one, &j);
        memcpy(out->pos[i], j.pos, sizeof j.pos);
        float r = radius[i + 1];
        out->radius[i] = r > 0 && r < 1 ? r : 0;
    }
    out->tracked = 1;
    return 1;
}
