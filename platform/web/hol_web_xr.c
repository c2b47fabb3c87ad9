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

/* The hands' pinches (hol_web_xr.h: a tap on its end, back when held
 * long) into *held and *pressed; clears the hands' buttons in pad. */
static void hand_pinches(hol_web_xr_state *st, hol_web_xr_pad pad[2], double t, int focused,
                         uint32_t *held, uint32_t *pressed)
{
    for (int h = 0; h < 2; h++) {
        hol_web_xr_pad *p = &pad[h];
        if (!(p->present > 0 && p->hand > 0)) {
            st->pinch_on[h] = 0;
            continue;
        }
        int pinch = p->button[B_TRIGGER] > 0.5f;
        p->button[B_TRIGGER] = p->button[B_SQUEEZE] = 0;
        if (pinch && !st->pinch_on[h]) {
            st->pinch_on[h] = 1;
            st->pinch_t0[h] = t;
            st->pinch_spent[h] = !focused;
        } else if (!pinch && st->pinch_on[h]) {
            st->pinch_on[h] = 0;
            if (!st->pinch_spent[h] && focused)
                *pressed |= h == HOL_HAND_RIGHT ? HOL_BTN_CONFIRM : HOL_BTN_MENU;
            continue;
        }
        if (!pinch)
            continue;
        if (!focused) {
            st->pinch_spent[h] = 1;
        } else if (t - st->pinch_t0[h] >= HOL_WEB_XR_LONG_PINCH_S && !st->pinch_spent[h]) {
            st->pinch_spent[h] = 2; /* long: back, held until it ends */
            *pressed |= HOL_BTN_BACK;
        }
        if (st->pinch_spent[h] == 2)
            *held |= HOL_BTN_BACK;
    }
}

/* The glue's joints of each hand (reference space) into raw; none for a
 * hand without all of them. */
static void hand_joints(const hol_web_xr_frame *f, hol_hand_joints raw[2])
{
    memset(raw, 0, 2 * sizeof raw[0]);
    for (int h = 0; h < 2; h++) {
        const hol_web_xr_pad *p = &f->pad[h];
        if (!(p->present > 0 && p->hand > 0 && p->joints_valid > 0))
            continue;
        for (int i = 0; i < HOL_HAND_JOINTS; i++) {
            memcpy(raw[h].pos[i], p->joint[i], sizeof raw[h].pos[i]);
            raw[h].radius[i] = p->joint[i][3] >= 0 && p->joint[i][3] < 1 ? p->joint[i][3] : 0;
        }
        /* a hand the browser lost: none (the glue's joints_valid: all located) */
        raw[h].tracked = (uint32_t)hol_hand_joints_usable(raw[h].pos, HOL_HAND_LOCATED_ALL);
    }
}

void hol_web_xr_input(hol_web_xr_state *st, const hol_web_xr_frame *f, double t,
                      hol_input *out)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t > st->last_t ? t : st->last_t;
    st->last_t = in.time_s;
    /* the headset's state: the core decides whether the head walks */
    in.flags |= HOL_INPUT_HEADSET | HOL_INPUT_WAY_BACK; /* and it shows the way back in */
    if (f->visibility == HOL_WEB_XR_VISIBLE)
        in.flags |= HOL_INPUT_FOCUSED;
    if (f->visibility < HOL_WEB_XR_BLURRED)
        in.flags |= HOL_INPUT_HEADSET_OFF;
    double rw = st->room_w > 0 ? st->room_w : 3.0, rd = st->room_d > 0 ? st->room_d : 3.0;
    st->calib.half_w = rw / 2;
    st->calib.half_d = rd / 2;
    if (f->bounds[0] > 0 && f->bounds[1] > 0 && !hol_xr_bounds_hold(f->bounds[0], f->bounds[1], rw, rd))
        in.flags |= HOL_INPUT_BOUNDS_SMALL;
    /* held while the session is not focused (a system menu over it) counts
     * neither then nor as a press when it comes back */
    hol_web_xr_pad pad[2] = {f->pad[0], f->pad[1]};
    int focused = (in.flags & HOL_INPUT_FOCUSED) != 0;
    uint32_t hand_held = 0, hand_taps = 0;
    uint32_t dev = HOL_DEVICE_NONE;
    hol_web_xr_buttons(pad, &dev);
    if (dev != HOL_DEVICE_WEBXR_TOUCH)
        hand_pinches(st, pad, in.time_s, focused, &hand_held, &hand_taps);
    for (int h = 0; h < 2; h++)
        if (dev != HOL_DEVICE_WEBXR_TOUCH && pad[h].present > 0 && pad[h].hand > 0)
            dev = HOL_DEVICE_WEBXR_HAND;
    in.device = dev;
    /* the hands-only recentre: palms up is the same in the reference space
     * as in the room (the room only turns about the vertical) */
    hol_hand_joints raw[2], none[2];
    hand_joints(f, raw);
    st->hands = 0;
    for (int h = 0; h < 2; h++)
        st->hands |= (raw[h].tracked ? 1 << h : 0) | (hol_gesture_palm_up(&raw[h], h) ? 4 << h : 0);
    memset(none, 0, sizeof none);
    uint32_t gesture = hol_gesture_step(&st->gesture, focused ? raw : none, in.time_s);
    uint32_t held = hol_web_xr_buttons(pad, NULL) | hand_held;
    if (focused) {
        in.buttons = held;
        in.pressed = (held & ~st->prev_buttons) | hand_taps | gesture;
    }
    st->prev_buttons = held;
    if (f->head_valid > 0) {
        if (in.pressed & HOL_BTN_RECENTRE)
            hol_xr_recentre(&st->calib, f->head_pos, f->head_quat);
        hol_xr_to_room(&st->calib, f->head_pos, f->head_quat, &in.head);
        in.flags |= HOL_INPUT_HEAD_VALID | (f->head_valid > 1.5f ? HOL_INPUT_POS_EMULATED : 0u);
    }
    for (int h = 0; h < 2; h++) {
        const hol_web_xr_pad *p = &f->pad[h];
        if (p->present > 0 && p->grip_valid > 0) {
            hol_xr_to_room(&st->calib, p->grip_pos, p->grip_quat, &in.hand[h]);
            in.flags |= h ? HOL_INPUT_HAND_R_VALID : HOL_INPUT_HAND_L_VALID;
        }
        if (!raw[h].tracked)
            continue;
        in.joints[h] = raw[h]; /* into the room (after a recentre's placing) */
        for (int i = 0; i < HOL_HAND_JOINTS; i++) {
            static const float one[4] = {0, 0, 0, 1};
            hol_pose j;
            hol_xr_to_room(&st->calib, raw[h].pos[i], one, &j);
            memcpy(in.joints[h].pos[i], j.pos, sizeof j.pos);
        }
    }
    if (st->seated && focused) { /* a pinch and flick: one room step */
        int pinch[2];
        for (int h = 0; h < 2; h++)
            pinch[h] = dev == HOL_DEVICE_WEBXR_HAND && f->pad[h].present > 0 && f->pad[h].hand > 0 &&
                       f->pad[h].button[B_TRIGGER] > 0.5f;
        in.pressed |= hol_flick_step(&st->flick, &in, pinch);
        for (int h = 0; h < 2; h++)
            if (st->flick.stepped[h] && st->pinch_on[h] && !st->pinch_spent[h])
                st->pinch_spent[h] = 1; /* used up: no tap, no back */
    } else {
        memset(&st->flick, 0, sizeof st->flick);
    }
    *out = in;
}
