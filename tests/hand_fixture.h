/* hand_fixture.h - a scripted tracked hand (25 joints, WebXR's order:
 * core/hol_input.h) for the body's tests (test_body.c,
 * test_render_body.c, test_render_golden.c).
 *
 * Contract
 * - hand_fixture(h, wrist, yaw_deg, palm_up, pinch, out): hand h
 *   (HOL_HAND_*) with its wrist at `wrist` (room coordinates), the fingers
 *   ahead along the look of yaw_deg (SPEC 1: 0 north, positive towards
 *   the west), flat and a little spread, the palm up or down; the thumb
 *   beside the index, or with pinch its tip 1 cm above the index's. Radii
 *   12 mm at the wrist down to 7 mm at the fingertips. Every joint
 *   tracked.
 * - Header-only, static inline; include after core/hol_input.h.
 */
#ifndef HOL_TEST_HAND_FIXTURE_H
#define HOL_TEST_HAND_FIXTURE_H

#include <math.h>
#include <string.h>

#include "../core/hol_input.h"

static inline void hand_fixture(int h, const double wrist[3], double yaw_deg, int palm_up,
                                int pinch, hol_hand_joints *out)
{
    memset(out, 0, sizeof *out);
    out->tracked = 1;
    /* the thumb's side: a right palm up and a left palm down have it on
     * the right (+x before the turn), so index x pinky is the palm's side */
    double s = (h == HOL_HAND_RIGHT ? 1.0 : -1.0) * (palm_up ? 1.0 : -1.0);
    double yr = yaw_deg * 3.14159265358979323846 / 180, cy = cos(yr), sy = sin(yr);
    for (int i = 0; i < HOL_HAND_JOINTS; i++) {
        double x = 0, y = 0, z = 0, r = 0.012;
        if (i >= HOL_JOINT_THUMB_METACARPAL && i <= HOL_JOINT_THUMB_TIP) {
            int k = i - HOL_JOINT_THUMB_METACARPAL;
            x = s * (0.03 + 0.014 * k);
            z = -0.018 * (k + 1);
            y = 0.006 * k;
            r = 0.010 - 0.001 * k;
        } else if (i >= HOL_JOINT_INDEX_METACARPAL) {
            int f = (i - HOL_JOINT_INDEX_METACARPAL) / 5, k = (i - HOL_JOINT_INDEX_METACARPAL) % 5;
            x = s * (0.024 - 0.017 * f - 0.005 * f * k + 0.004 * k);
            z = -0.03 - 0.024 * k;
            r = 0.0095 - 0.0006 * k;
        }
        out->pos[i][0] = (float)(wrist[0] + x * cy + z * sy);
        out->pos[i][1] = (float)(wrist[1] + y);
        out->pos[i][2] = (float)(wrist[2] - x * sy + z * cy);
        out->radius[i] = (float)r;
    }
    if (pinch)
        for (int k = 0; k < 3; k++)
            out->pos[HOL_JOINT_THUMB_TIP][k] =
                out->pos[HOL_JOINT_INDEX_TIP][k] + (k == 1 ? 0.01f : 0.0f);
}

#endif
