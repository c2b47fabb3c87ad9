/* hol_web_input.h - the page's pancake devices (keyboard, pointer-lock
 * mouse, the Gamepad API, touch) as one input record per frame. Pure: the
 * browser loop (hol_web_main.c) fills a hol_web_pancake from its events,
 * this turns it into a hol_input; tests/test_web_input.c runs it natively.
 *
 * Contract
 * - Keys are KeyboardEvent.code values (layout independent), mapped as the
 *   desktop's `holonomy play`: W/S or Up/Down walk, A/D step sideways,
 *   Left/Right turn (with a snap angle: snap, one turn a press), PgUp/PgDn
 *   look, Enter/Space confirm, P menu, R restart, M minimap, F3 debug,
 *   F2 the frame time (the loop's toggle: no button), Q quit; Escape quits only while the pointer is not locked (with the
 *   pointer locked the browser takes Escape to release it).
 * - A key counts while held or when it went down since the last frame (a
 *   tap between two frames: `taps`), and its button's `pressed` bit is set
 *   for the tap; hol_web_pancake_input clears the taps and the mouse motion
 *   it used.
 * - Mouse: 0.2 degrees a pixel of pointer-lock motion, as the desktop.
 * - Gamepad (the Gamepad API's "standard" mapping): left stick walks, right
 *   stick turns and looks (radial dead zone 0.15, as the desktop's pads),
 *   A/south confirms, B/east backs, X/west, select and d-pad down cycle the
 *   minimap, Y/north and d-pad up recentre, start and home open the menu;
 *   axes add to the keys' (clamped), buttons OR with them.
 * - Touch: a finger that lands on the left half of the canvas is a stick
 *   (its offset from where it landed over touch_radius pixels, clamped to
 *   the unit disc: walk), one on the right half drags the look (0.3 degrees
 *   a pixel); on-screen buttons hold HOL_BTN_* bits (touch_buttons,
 *   touch_taps).
 * - device: the one used last (HOL_DEVICE_KEYBOARD for keys and mouse,
 *   HOL_DEVICE_SCREEN for touch and the on-screen buttons, so the prompts
 *   name those: "OK: NEXT LEVEL"; HOL_DEVICE_GAMEPAD for the pad). A gamepad in use that goes away
 *   sets HOL_INPUT_DEVICE_LOST (the game pauses) until it is back or a key,
 *   the mouse or a touch is used.
 * - HOL_INPUT_FOCUSED while the page is visible and has the focus.
 * - Seated play (`seated`, the page's ?seated=1): the move axes the keys,
 *   the touch stick (a swipe on the left half) and the pad give take one
 *   room step a push (platform/shell/hol_shell_seat.h), the on-screen
 *   arrows hold HOL_BTN_STEP_* bits, Left/Right snap by 90 degrees unless
 *   snap_deg says otherwise.
 */
#ifndef HOL_WEB_INPUT_H
#define HOL_WEB_INPUT_H

#include <stdint.h>

#include "../../core/hol_input.h"

enum {
    HOL_WEB_K_FORWARD = 0,
    HOL_WEB_K_BACK,
    HOL_WEB_K_STRAFE_L,
    HOL_WEB_K_STRAFE_R,
    HOL_WEB_K_TURN_L,
    HOL_WEB_K_TURN_R,
    HOL_WEB_K_LOOK_UP,
    HOL_WEB_K_LOOK_DOWN,
    HOL_WEB_K_CONFIRM,
    HOL_WEB_K_MENU,
    HOL_WEB_K_RESTART,
    HOL_WEB_K_MINIMAP,
    HOL_WEB_K_DEBUG,
    HOL_WEB_K_QUIT,
    HOL_WEB_K_ESCAPE, /* quit unless the pointer is locked */
    HOL_WEB_K_STATS,  /* F2: the frame time on the view (the loop's, no button) */
    HOL_WEB_K_COUNT
};

#define HOL_WEB_PAD_BUTTONS 17 /* the standard mapping's */
#define HOL_WEB_DEAD_ZONE 0.15f

typedef struct hol_web_pancake {
    uint8_t held[HOL_WEB_K_COUNT];
    uint8_t taps[HOL_WEB_K_COUNT];  /* went down since the last frame */
    double mouse_dx, mouse_dy;      /* pointer-lock motion since the last frame, px */
    int pointer_locked;
    /* touch */
    float touch_move[2];            /* the left stick: right +, forward + (unit disc) */
    double touch_dx, touch_dy;      /* look drag since the last frame, px */
    uint32_t touch_buttons;         /* HOL_BTN_* held on screen */
    uint32_t touch_taps;            /* HOL_BTN_* pressed since the last frame */
    int touch_used;                 /* a touch since the last frame */
    /* gamepad */
    int pad_connected;
    int pad_standard;               /* mapping "standard" */
    float pad_axes[4];
    uint8_t pad_button[HOL_WEB_PAD_BUTTONS]; /* pressed at the last sample (the
                                       API is polled: its edges are the app's) */
    /* the page */
    int focused;
    int snap_deg;                   /* > 0: Left/Right snap by this many degrees */
    int seated;                     /* seated play (see the contract) */
    int seat_latch;                 /* hol_shell_seat's, kept between frames */
    /* kept between frames */
    int device;                     /* HOL_DEVICE_* used last */
} hol_web_pancake;

/* KeyboardEvent.code -> HOL_WEB_K_*, or -1 for a key the game ignores. */
int hol_web_key_from_code(const char *code);

/* Record a key going down (repeat: an auto-repeat, ignored) or up. */
void hol_web_key(hol_web_pancake *p, int key, int down, int repeat);

/* This frame's record at time t (seconds), dt since the last frame, the
 * look's yaw (for the snap). Clears the taps and motions it used. */
void hol_web_pancake_input(hol_web_pancake *p, double t, double dt, double yaw_deg,
                           hol_input *out);

#endif
