/* hol_shell_seat.h - seated play's steps from a platform's move axes (a
 * stick, the W/S/A/D keys, a swipe), the same for every platform that
 * offers seated play (issue 37; core/hol_input.h HOL_INPUT_SEATED).
 *
 * Contract
 * - hol_shell_seat(latch, in): marks *in seated (HOL_INPUT_SEATED) and
 *   turns its move axes into at most one step button edge: when the
 *   larger axis passes HOL_SHELL_SEAT_ON (0.6) and the latch is open, the
 *   edge of HOL_BTN_STEP_FWD / BACK (move[1] + / -) or STEP_RIGHT / LEFT
 *   (move[0] + / -) is added to in->pressed and the latch closes; it opens
 *   again once both axes are below HOL_SHELL_SEAT_OFF (0.3). So a key held
 *   or a stick pushed takes one step; releasing and pressing again takes
 *   the next. The axes stay in the record (the core ignores them seated).
 * - Header-only (static inline), pure: the latch is the caller's.
 */
#ifndef HOL_SHELL_SEAT_H
#define HOL_SHELL_SEAT_H

#include <math.h>

#include "../../core/hol_input.h"

#define HOL_SHELL_SEAT_ON 0.6f
#define HOL_SHELL_SEAT_OFF 0.3f

static inline void hol_shell_seat(int *latch, hol_input *in)
{
    float x = in->move[0], y = in->move[1], ax = fabsf(x), ay = fabsf(y);
    in->flags |= HOL_INPUT_SEATED;
    if (ax < HOL_SHELL_SEAT_OFF && ay < HOL_SHELL_SEAT_OFF) {
        *latch = 0;
        return;
    }
    if (*latch || (ax < HOL_SHELL_SEAT_ON && ay < HOL_SHELL_SEAT_ON))
        return;
    *latch = 1;
    if (ay >= ax)
        in->pressed |= y > 0 ? HOL_BTN_STEP_FWD : HOL_BTN_STEP_BACK;
    else
        in->pressed |= x > 0 ? HOL_BTN_STEP_RIGHT : HOL_BTN_STEP_LEFT;
}

#endif
