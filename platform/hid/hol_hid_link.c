/* hol_hid_link.c - a game controller joined to the keyboard (see
 * hol_hid_link.h). */
#include "hol_hid_link.h"

static float hol__clamp1(float v)
{
    return v < -1.0f ? -1.0f : v > 1.0f ? 1.0f : v;
}

void hol_hid_link_merge(hol_hid_link *l, hol_err poll_err, int dev_lost, const hol_input *pad,
                        int key_activity, hol_input *io)
{
    if (poll_err == HOL_OK) {
        l->connected = 1;
        l->lost = 0;
        int used = pad->buttons || pad->pressed;
        for (int k = 0; k < 2; k++) {
            used |= pad->move[k] != 0 || pad->turn[k] != 0;
            io->move[k] = hol__clamp1(io->move[k] + pad->move[k]);
            io->turn[k] = hol__clamp1(io->turn[k] + pad->turn[k]);
        }
        io->buttons |= pad->buttons;
        io->pressed |= pad->pressed;
        if (key_activity)
            l->pad_in_use = 0;
        else if (used)
            l->pad_in_use = 1;
        if (l->pad_in_use)
            io->device = HOL_DEVICE_GAMEPAD;
        return;
    }
    l->pad_in_use = 0;
    if (l->connected && dev_lost)
        l->lost = 1; /* it was there and went away */
    l->connected = 0;
    if (l->lost && key_activity)
        l->lost = 0; /* the keyboard takes over */
    if (l->lost)
        io->flags |= HOL_INPUT_DEVICE_LOST;
}
