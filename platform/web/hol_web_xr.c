/* hol_web_xr.c - a WebXR frame as the input record and eye cameras (see
 * hol_web_xr.h). */
#include "hol_web_xr.h"

#include <string.h>

void hol_web_xr_camera(const hol_xr_calib *c, const hol_web_xr_view *v, hol_camera *out)
{
    hol_pose room;
    hol_xr_to_room(c, v->pos, v->quat, &room);
    memset(out, 0, sizeof *out);
    for (int k = 0; k < 3; k++)
        out->eye[k] = room.pos[k];
    for (int k = 0; k < 4; k++)
        out->orient[k] = room.quat[k];
    out->has_pose = 1;
    const float *m = v->proj;
    out->tan_right = (1.0 + m[8]) / m[0];
    out->tan_left = (m[8] - 1.0) / m[0];
    out->tan_up = (1.0 + m[9]) / m[5];
    out->tan_down = (m[9] - 1.0) / m[5];
    out->width = (int)v->vp[2];
    out->height = (int)v->vp[3];
}

enum { B_TRIGGER = 0, B_SQUEEZE = 1, B_STICK = 3, B_AX = 4, B_BY = 5 };

uint32_t hol_web_xr_buttons(const hol_web_xr_pad pad[2], uint32_t *out_device)
{
    const hol_web_xr_pad *l = &pad[HOL_HAND_LEFT], *r = &pad[HOL_HAND_RIGHT];
    int touch = (l->present > 0 && l->touch_layout > 0) || (r->present > 0 && r->touch_layout > 0);
#define HELD(p, i) ((p)->present > 0 && (p)->button[i] > 0.5f)
    uint32_t b = 0;
    b |= HELD(r, B_TRIGGER) ? HOL_BTN_CONFIRM : 0;
    b |= HELD(l, B_STICK) ? HOL_BTN_RECENTRE : 0;
    if (touch) {
        b |= HELD(r, B_AX) ? HOL_BTN_CONFIRM : 0;
        b |= HELD(r, B_BY) ? HOL_BTN_BACK : 0;
        b |= HELD(l, B_BY) ? HOL_BTN_MENU : 0;
        b |= HELD(l, B_AX) ? HOL_BTN_MINIMAP : 0;
    } else {
        b |= HELD(r, B_SQUEEZE) ? HOL_BTN_BACK : 0;
        b |= HELD(l, B_TRIGGER) ? HOL_BTN_MENU : 0;
        b |= HELD(l, B_SQUEEZE) ? HOL_BTN_MINIMAP : 0;
    }
#undef HELD
    if (out_device)
        *out_device = l->present > 0 || r->present > 0
                          ? (touch ? HOL_DEVICE_WEBXR_TOUCH : HOL_DEVICE_NONE)
                          : HOL_DEVICE_NONE;
    return b;
}

void hol_web_xr_input(hol_web_xr_state *st, const hol_web_xr_frame *f, double t,
                      hol_input *out)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t > st->last_t ? t : st->last_t;
    st->last_t = in.time_s;
    if (f->visibility == HOL_WEB_XR_VISIBLE)
        in.flags |= HOL_INPUT_FOCUSED;
    double rw = st->room_w > 0 ? st->room_w : 3.0, rd = st->room_d > 0 ? st->room_d : 3.0;
    st->calib.half_w = rw / 2;
    st->calib.half_d = rd / 2;
    if (f->bounds[0] > 0 && f->bounds[1] > 0 && !hol_xr_bounds_hold(f->bounds[0], f->bounds[1], rw, rd))
        in.flags |= HOL_INPUT_BOUNDS_SMALL;
    /* held while the session is not focused (a system menu over it) counts
     * neither then nor as a press when it comes back */
    uint32_t held = hol_web_xr_buttons(f->pad, &in.device);
    if (in.flags & HOL_INPUT_FOCUSED) {
        in.buttons = held;
        in.pressed = held & ~st->prev_buttons;
    }
    st->prev_buttons = held;
    if (f->head_valid > 0) {
        if (in.pressed & HOL_BTN_RECENTRE)
            hol_xr_recentre(&st->calib, f->head_pos, f->head_quat);
        hol_xr_to_room(&st->calib, f->head_pos, f->head_quat, &in.head);
        in.flags |= HOL_INPUT_HEAD_VALID;
    }
    for (int h = 0; h < 2; h++) {
        const hol_web_xr_pad *p = &f->pad[h];
        if (p->present > 0 && p->grip_valid > 0) {
            hol_xr_to_room(&st->calib, p->grip_pos, p->grip_quat, &in.hand[h]);
            in.flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
        }
    }
    *out = in;
}
