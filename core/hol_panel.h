/* hol_panel.h - where the headset's UI panel stands: a lazy follower of
 * the head.
 *
 * Contract
 * - Pure state, no OS, no clock, no allocation: the app step drives it
 *   with the head's position, yaw and the frame's time (hol_app_view.panel
 *   holds it; a platform that draws for a headset's eyes places the HUD
 *   there: render/hol_app_frame.h, hol_app_frame_panel).
 * - The panel stands HOL_PANEL_DISTANCE metres from its anchor (a head
 *   position), HOL_PANEL_DROP_DEG below eye level, along the anchor's yaw,
 *   facing the anchor (tilted back by the drop). Room coordinates (SPEC 1:
 *   yaw 0 looks north, towards -z; positive yaw turns west).
 * - Lazy: the anchor stays put while the head stays within
 *   HOL_PANEL_TURN_DEG of its yaw and HOL_PANEL_MOVE_M of its position.
 *   Once the head goes beyond either, the panel re-centres: the anchor
 *   eases to the head (time constant HOL_PANEL_EASE_S, the head followed
 *   while it moves) and stops when it has reached it (within 0.5 degrees
 *   and 1 cm). The first update places it at once; so does a time that
 *   goes backwards. A long frame (a stall, a gap of seconds) glides too:
 *   the ease takes at most 0.1 s of time per update (a bounded catch-up,
 *   about 45 % of the way), so the panel never jumps. A new session or a
 *   re-placed room places it at once (hol_panel_place, the app's view).
 */
#ifndef HOL_PANEL_H
#define HOL_PANEL_H

#define HOL_PANEL_DISTANCE 1.5 /* metres from the eyes */
#define HOL_PANEL_DROP_DEG 10.0 /* below eye level */
#define HOL_PANEL_TURN_DEG 20.0 /* the head's turn that re-centres it */
#define HOL_PANEL_MOVE_M 0.5 /* the head's move that re-centres it */
#define HOL_PANEL_EASE_S 0.12 /* the re-centring's time constant */

typedef struct hol_panel {
    int placed;         /* 0: never updated */
    int moving;         /* 1: re-centring */
    double anchor[3];   /* the head position it is placed for */
    double yaw_deg;     /* the yaw it is placed for, in (-180, 180] */
    double t;           /* the time of the last update, seconds */
    double pos[3];      /* the panel's centre, room coordinates */
    double orient[4];   /* x, y, z, w: unturned the panel faces +z, up +y */
    int recentres;      /* re-centrings so far (placing included) */
} hol_panel;

/* Update the panel for a head at head[3] looking along yaw_deg at time
 * t_s (seconds, the frame's). */
void hol_panel_follow(hol_panel *p, const double head[3], double yaw_deg, double t_s);

/* The panel placed straight for this head, at once (a recentre). */
void hol_panel_place(hol_panel *p, const double head[3], double yaw_deg, double t_s);

#endif
