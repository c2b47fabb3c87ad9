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
 * - Never through a hedge or a trunk (once it knows the room:
 *   hol_panel_room). Drawn over the scene, it must be nearer than whatever
 *   it covers, so it comes in front of the nearest hedge or trunk in its
 *   direction: over the directions within HOL_PANEL_HALF_DEG of its yaw
 *   (the panel's whole width, 16.4 degrees each way with the map, and
 *   the eyes' offset), the nearest point of the
 *   room's four hedges (the room's sides, 0..C*M x 0..R*M) or of a trunk
 *   (a vertex of the grid, radius HOL_PANEL_TRUNK_M) from the anchor, along
 *   the panel's yaw, less HOL_PANEL_CLEAR_M, sets its depth, down to
 *   HOL_PANEL_NEAR_M and up to HOL_PANEL_DISTANCE (dist). It keeps its
 *   angular size: it is scaled by dist / HOL_PANEL_DISTANCE (scale; the
 *   renderer's font pixel is scaled alike, render/hol_app_frame.c). Nearer
 *   than HOL_PANEL_NEAR_M + HOL_PANEL_CLEAR_M to a hedge or trunk (the
 *   motion keeps the head 0.15 m from a hedge; a trunk can be touched) the
 *   panel stays at HOL_PANEL_NEAR_M and may be covered: `covered` says so
 *   (1 while the nearest hedge or trunk is nearer than that), and a
 *   platform that composites the panel over the scene without depth (a
 *   quad layer) draws it in the scene, depth-tested, for those frames
 *   instead (platform/openxr/hol_xr_panel.c, platform/web). An anchor
 *   outside the room keeps HOL_PANEL_DISTANCE.
 */
#ifndef HOL_PANEL_H
#define HOL_PANEL_H

#define HOL_PANEL_DISTANCE 1.5 /* metres from the eyes */
#define HOL_PANEL_DROP_DEG 10.0 /* below eye level */
#define HOL_PANEL_TURN_DEG 20.0 /* the head's turn that re-centres it */
#define HOL_PANEL_MOVE_M 0.5 /* the head's move that re-centres it */
#define HOL_PANEL_EASE_S 0.12 /* the re-centring's time constant */
#define HOL_PANEL_NEAR_M 0.5 /* the nearest it comes, in front of a hedge */
#define HOL_PANEL_CLEAR_M 0.05 /* kept from the hedge or trunk behind it */
#define HOL_PANEL_HALF_DEG 18.0 /* the directions looked along, each way */
#define HOL_PANEL_TRUNK_M 0.12 /* a trunk's radius (the widest is 0.11) */

typedef struct hol_panel {
    int placed;         /* 0: never updated */
    int moving;         /* 1: re-centring */
    double anchor[3];   /* the head position it is placed for */
    double yaw_deg;     /* the yaw it is placed for, in (-180, 180] */
    double t;           /* the time of the last update, seconds */
    double pos[3];      /* the panel's centre, room coordinates */
    double orient[4];   /* x, y, z, w: unturned the panel faces +z, up +y */
    int recentres;      /* re-centrings so far (placing included) */
    int cols, rows;     /* the room in cells (hol_panel_room); 0: none */
    double cell_m;      /* a cell's side, metres */
    double dist;        /* its distance from the anchor, metres */
    double scale;       /* dist / HOL_PANEL_DISTANCE: its size's factor */
    int covered;        /* 1: at HOL_PANEL_NEAR_M with scenery nearer still */
} hol_panel;

/* The room it stands in: cols x rows cells of cell_m metres, hedges on its
 * sides, trunks on its grid's vertices (room coordinates, 0..cols*cell_m x
 * 0..rows*cell_m). 0 cols: no room (always HOL_PANEL_DISTANCE). Takes
 * effect at the next placement or follow. */
void hol_panel_room(hol_panel *p, int cols, int rows, double cell_m);

/* The depth (metres, along yaw_deg, horizontal) of the nearest hedge or
 * trunk within HOL_PANEL_HALF_DEG of yaw_deg from head in that room; a
 * large number when none or when head is outside the room. */
double hol_panel_clear_depth(const hol_panel *p, const double head[3], double yaw_deg);

/* Update the panel for a head at head[3] looking along yaw_deg at time
 * t_s (seconds, the frame's). */
void hol_panel_follow(hol_panel *p, const double head[3], double yaw_deg, double t_s);

/* The panel placed straight for this head, at once (a recentre). */
void hol_panel_place(hol_panel *p, const double head[3], double yaw_deg, double t_s);

#endif
