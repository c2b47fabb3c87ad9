/* hol_haptic.c - the controllers' pulses (hol_haptic.h). */
#include "hol_haptic.h"

#include <math.h>
#include <string.h>

int hol_haptic_contact(const float pos[3], int cols, int rows, double cell_m, double grow)
{
    double x = pos[0], y = pos[1], z = pos[2];
    double w = cols * cell_m, d = rows * cell_m;
    if (y < 0)
        return HOL_HAPTIC_NONE;
    /* the hedge: beyond the boundary (its surface moved in by grow) */
    if (y < HOL_HAPTIC_HEDGE_TOP_M + grow &&
        (x < grow || x > w - grow || z < grow || z > d - grow))
        return HOL_HAPTIC_HEDGE;
    if (y >= HOL_HAPTIC_TRUNK_TOP_M + grow)
        return HOL_HAPTIC_NONE;
    double i = floor(x / cell_m + 0.5), j = floor(z / cell_m + 0.5);
    if (i < 0 || i > cols || j < 0 || j > rows)
        return HOL_HAPTIC_NONE;
    double dx = x - i * cell_m, dz = z - j * cell_m;
    double r = HOL_HAPTIC_TRUNK_M + grow;
    return dx * dx + dz * dz < r * r ? HOL_HAPTIC_TRUNK : HOL_HAPTIC_NONE;
}

void hol_haptic_step(hol_haptic_state *s, const hol_input *in, int cols, int rows, double cell_m,
                     int room_steps, int enabled, hol_haptic *out)
{
    static const uint32_t valid[2] = {HOL_INPUT_HAND_L_VALID, HOL_INPUT_HAND_R_VALID};
    memset(out, 0, sizeof *out);
    for (int h = 0; h < 2; h++) {
        if (!(in->flags & valid[h]))
            continue;
        int now = hol_haptic_contact(in->hand[h].pos, cols, rows, cell_m, 0);
        if (now && !s->inside[h]) {
            s->inside[h] = 1;
            if (enabled)
                out->hand[h] = (hol_haptic_pulse){HOL_HAPTIC_HIT_AMP, HOL_HAPTIC_HIT_MS, now};
        } else if (!now && s->inside[h] &&
                   !hol_haptic_contact(in->hand[h].pos, cols, rows, cell_m, HOL_HAPTIC_CLEAR_M)) {
            s->inside[h] = 0;
        }
        if (enabled && room_steps > 0 && out->hand[h].amplitude == 0)
            out->hand[h] = (hol_haptic_pulse){HOL_HAPTIC_STEP_AMP, HOL_HAPTIC_STEP_MS,
                                              HOL_HAPTIC_STEP};
    }
}
