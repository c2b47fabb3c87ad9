/* hol_xr_hand.h - a tracked hand of OpenXR's XR_EXT_hand_tracking as the
 * input record's joints (core/hol_input.h), as a pure function (no OpenXR
 * headers): what the headset layer (platform/openxr/hol_xr_hands.c) does
 * with xrLocateHandJointsEXT's answer, testable without a runtime
 * (tests/test_xr_hand.c).
 *
 * Contract
 * - OpenXR's default joint set has HOL_XR_HAND_JOINTS (26) joints: the
 *   palm first (XR_HAND_JOINT_PALM_EXT, 0), then the wrist (1), the
 *   thumb's four (metacarpal, proximal, distal, tip: 2..5) and five of
 *   each finger (metacarpal, proximal, intermediate, distal, tip: index
 *   6..10, middle 11..15, ring 16..20, little 21..25). The record's 25
 *   (WebXR's XRHand order, HOL_JOINT_*) are the same without the palm:
 *   joint i is OpenXR's i + 1. The palm is dropped.
 * - hol_xr_hand_joints: joint positions in the stage space (the app's
 *   reference space) go into room coordinates by the calibration
 *   (hol_xr_to_room, core/hol_input.h's frame), radii are kept (a radius
 *   not in (0, 1) m: 0, the renderer's default); `tracked` is 1 only when
 *   the hand is active and its 25 are usable (core/hol_body.h's
 *   hol_hand_joints_usable: a joint is located when its flags[i + 1] has
 *   HOL_XR_HAND_POS_VALID, XR_SPACE_LOCATION_POSITION_VALID_BIT; finite
 *   stage coordinates under HOL_HAND_REACH_M, 1e4 m); else the whole
 *   record is zero (a hand half located is not drawn: its grip's
 *   controller is, as for a hand the runtime lost).
 */
#ifndef HOL_XR_HAND_H
#define HOL_XR_HAND_H

#include "../../core/hol_input.h"
#include "hol_xr_room.h"

#define HOL_XR_HAND_JOINTS 26   /* XR_HAND_JOINT_COUNT_EXT */
#define HOL_XR_HAND_POS_VALID 0x2u /* XR_SPACE_LOCATION_POSITION_VALID_BIT */

/* One hand: active (the runtime's isActive), the 26 joints' stage
 * positions, radii and location flags; *out its record (see above).
 * Returns out->tracked. */
int hol_xr_hand_joints(const hol_xr_calib *c, int active,
                       const float pos[HOL_XR_HAND_JOINTS][3],
                       const float radius[HOL_XR_HAND_JOINTS],
                       const unsigned flags[HOL_XR_HAND_JOINTS], hol_hand_joints *out);

#endif
