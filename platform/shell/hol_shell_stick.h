/* hol_shell_stick.h - a thumbstick's radial dead zone, the same for every
 * platform that reads sticks (platform/hid's gamepads, the web's Gamepad
 * API).
 *
 * Contract
 * - hol_shell_stick(dead, x, y, out): (x, y) of the unit stick (-1..1
 *   each) with its length at most dead (or not a number) is (0, 0);
 *   beyond, the length is mapped from dead..1 onto 0..1 (at most 1),
 *   keeping the direction. All in float, as both callers had it.
 * - Header-only (static inline): the hid layer's tests, fuzzers and benches
 *   link no shell source for it.
 */
#ifndef HOL_SHELL_STICK_H
#define HOL_SHELL_STICK_H

#include <math.h>

static inline void hol_shell_stick(float dead, float x, float y, float out[2])
{
    float m = sqrtf(x * x + y * y);
    if (!(m > dead)) {
        out[0] = out[1] = 0.0f;
        return;
    }
    float s = (m > 1.0f ? 1.0f : m);
    s = (s - dead) / (1.0f - dead) / m;
    out[0] = x * s;
    out[1] = y * s;
}

#endif
