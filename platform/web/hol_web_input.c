/* hol_web_input.c - the page's pancake devices as an input record (see
 * hol_web_input.h). */
#include "hol_web_input.h"

#include <math.h>
#include <string.h>

#include "../../core/hol_motion.h"
#include "../shell/hol_shell_seat.h"
#include "../shell/hol_shell_stick.h"

int hol_web_key_from_code(const char *code)
{
    static const struct {
        const char *code;
        int key;
    } map[] = {
        {"KeyW", HOL_WEB_K_FORWARD},      {"ArrowUp", HOL_WEB_K_FORWARD},
        {"KeyS", HOL_WEB_K_BACK},         {"ArrowDown", HOL_WEB_K_BACK},
        {"KeyA", HOL_WEB_K_STRAFE_L},     {"KeyD", HOL_WEB_K_STRAFE_R},
        {"ArrowLeft", HOL_WEB_K_TURN_L},  {"ArrowRight", HOL_WEB_K_TURN_R},
        {"PageUp", HOL_WEB_K_LOOK_UP},    {"PageDown", HOL_WEB_K_LOOK_DOWN},
        {"Enter", HOL_WEB_K_CONFIRM},     {"NumpadEnter", HOL_WEB_K_CONFIRM},
        {"Space", HOL_WEB_K_CONFIRM},     {"KeyP", HOL_WEB_K_MENU},
        {"KeyR", HOL_WEB_K_RESTART},      {"KeyM", HOL_WEB_K_MINIMAP},
        {"F3", HOL_WEB_K_DEBUG},          {"KeyQ", HOL_WEB_K_QUIT},
        {"Escape", HOL_WEB_K_ESCAPE},     {"F2", HOL_WEB_K_STATS},
    };
    for (size_t i = 0; code && i < sizeof map / sizeof map[0]; i++)
        if (!strcmp(code, map[i].code))
            return map[i].key;
    return -1;
}

void hol_web_key(hol_web_pancake *p, int key, int down, int repeat)
{
    if (key < 0 || key >= HOL_WEB_K_COUNT || repeat)
        return;
    if (down && !p->held[key])
        p->taps[key] = 1;
    p->held[key] = (uint8_t)(down != 0);
    p->device = HOL_DEVICE_KEYBOARD;
}

static float clamp1(double v)
{
    return (float)(v < -1 ? -1 : v > 1 ? 1 : v);
}

/* The pad's sticks and buttons (standard mapping) into in; 1 if used. */
static int pad_input(const hol_web_pancake *p, hol_input *in)
{
    static const uint32_t role[HOL_WEB_PAD_BUTTONS] = {
        [0] = HOL_BTN_CONFIRM,  [1] = HOL_BTN_BACK,    [2] = HOL_BTN_MINIMAP,
        [3] = HOL_BTN_RECENTRE, [8] = HOL_BTN_MINIMAP, [9] = HOL_BTN_MENU,
        [12] = HOL_BTN_RECENTRE, [13] = HOL_BTN_MINIMAP, [16] = HOL_BTN_MENU,
    };
    if (!p->pad_connected || !p->pad_standard)
        return 0;
    float l[2], r[2];
    hol_shell_stick(HOL_WEB_DEAD_ZONE, p->pad_axes[0], p->pad_axes[1], l);
    hol_shell_stick(HOL_WEB_DEAD_ZONE, p->pad_axes[2], p->pad_axes[3], r);
    in->move[0] = clamp1(in->move[0] + l[0]);
    in->move[1] = clamp1(in->move[1] - l[1]);
    in->turn[0] = clamp1(in->turn[0] - r[0]);
    in->turn[1] = clamp1(in->turn[1] - r[1]);
    uint32_t b = 0;
    for (int i = 0; i < HOL_WEB_PAD_BUTTONS; i++)
        b |= p->pad_button[i] ? role[i] : 0;
    in->buttons |= b;
    return b || l[0] != 0 || l[1] != 0 || r[0] != 0 || r[1] != 0;
}

static int on(const hol_web_pancake *p, int k)
{
    return p->held[k] || p->taps[k];
}

void hol_web_pancake_input(hol_web_pancake *p, double t, double dt, double yaw_deg,
                           hol_input *out)
{
    static const struct {
        int key;
        uint32_t btn;
    } btns[] = {{HOL_WEB_K_CONFIRM, HOL_BTN_CONFIRM}, {HOL_WEB_K_MENU, HOL_BTN_MENU},
                {HOL_WEB_K_RESTART, HOL_BTN_RESTART}, {HOL_WEB_K_MINIMAP, HOL_BTN_MINIMAP},
                {HOL_WEB_K_DEBUG, HOL_BTN_DEBUG},     {HOL_WEB_K_QUIT, HOL_BTN_QUIT}};
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = p->focused ? HOL_INPUT_FOCUSED : 0;
    double rate = dt > 1e-3 ? dt : 1e-3;
    in.move[0] = (float)(on(p, HOL_WEB_K_STRAFE_R) - on(p, HOL_WEB_K_STRAFE_L));
    in.move[1] = (float)(on(p, HOL_WEB_K_FORWARD) - on(p, HOL_WEB_K_BACK));
    int snap = p->snap_deg > 0 ? p->snap_deg : p->seated ? 90 : 0;
    int turn_keys = snap > 0 ? 0 : on(p, HOL_WEB_K_TURN_L) - on(p, HOL_WEB_K_TURN_R);
    /* mouse 0.2 and touch drag 0.3 degrees a pixel, as turn rates over
     * this frame (120 deg/s turn, 90 deg/s look at full deflection) */
    double dx = p->mouse_dx * 0.2 + p->touch_dx * 0.3, dy = p->mouse_dy * 0.2 + p->touch_dy * 0.3;
    in.turn[0] = clamp1(turn_keys - dx / (120 * rate));
    in.turn[1] = clamp1(on(p, HOL_WEB_K_LOOK_UP) - on(p, HOL_WEB_K_LOOK_DOWN) - dy / (90 * rate));
    in.move[0] = clamp1(in.move[0] + p->touch_move[0]);
    in.move[1] = clamp1(in.move[1] + p->touch_move[1]);
    for (size_t i = 0; i < sizeof btns / sizeof btns[0]; i++) {
        in.buttons |= p->held[btns[i].key] ? btns[i].btn : 0;
        in.pressed |= p->taps[btns[i].key] ? btns[i].btn : 0;
    }
    if (p->taps[HOL_WEB_K_ESCAPE] && !p->pointer_locked)
        in.pressed |= HOL_BTN_QUIT;
    in.buttons |= p->touch_buttons;
    in.pressed |= p->touch_taps;
    int keys_used = p->mouse_dx != 0 || p->mouse_dy != 0;
    for (int k = 0; k < HOL_WEB_K_COUNT; k++)
        keys_used |= p->held[k] | p->taps[k];
    if (keys_used)
        p->device = HOL_DEVICE_KEYBOARD;
    if (p->touch_used || p->touch_buttons) /* the prompts name the on-screen buttons */
        p->device = HOL_DEVICE_SCREEN;
    if (pad_input(p, &in))
        p->device = HOL_DEVICE_GAMEPAD;
    if (p->device == HOL_DEVICE_GAMEPAD && !p->pad_connected)
        in.flags |= HOL_INPUT_DEVICE_LOST;
    in.device = (uint32_t)p->device;
    /* snap turn: Left and Right turn by snaps, one a press */
    int turns = p->taps[HOL_WEB_K_TURN_L] - p->taps[HOL_WEB_K_TURN_R];
    if (snap > 0 && turns) {
        in.flags |= HOL_INPUT_SNAP_YAW;
        in.snap_yaw_deg = (float)hol_motion_snap_yaw(yaw_deg, snap, turns);
    }
    if (p->seated) /* one room step a push */
        hol_shell_seat(&p->seat_latch, &in);
    memset(p->taps, 0, sizeof p->taps);
    p->mouse_dx = p->mouse_dy = p->touch_dx = p->touch_dy = 0;
    p->touch_taps = 0;
    p->touch_used = 0;
    *out = in;
}
