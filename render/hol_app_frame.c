/* hol_app_frame.c - an app view as one eye's frame description. */
#include "hol_app_frame.h"

#include <math.h>
#include <string.h>

#define HOL__PI 3.14159265358979323846
#define HOL__HAND_AHEAD 0.28
#define HOL__HAND_BELOW 0.52
#define HOL__HAND_LEFT 0.12
#define HOL__HAND_SIZE 0.2

void hol_app_frame_desc(const hol_app_view *v, int eye, int w, int h, double fovy_deg,
                        hol_frame_desc *out)
{
    hol_frame_desc *fd = out;
    memset(fd, 0, sizeof *fd);
    /* the HUD text the app filled at its step */
    int nl = v->hud.nlines < HOL_RENDER_HUD_LINES ? v->hud.nlines : HOL_RENDER_HUD_LINES;
    for (int i = 0; i < nl; i++)
        fd->hud_lines[i] = v->hud.lines[i];
    fd->nhud_lines = nl;
    fd->prompt = v->hud.hint;
    int nm = v->map.nmarks < HOL_RENDER_MAX_MARKS ? v->map.nmarks : HOL_RENDER_MAX_MARKS;
    fd->nmarks = nm > 0 ? nm : 0;
    memcpy(fd->marks, v->map.marks, (size_t)fd->nmarks * sizeof fd->marks[0]);
    if (eye == 0 || eye == 1) {
        fd->user = v->eye_user[eye];
        memcpy(fd->cam.eye, v->eye[eye], sizeof fd->cam.eye);
    } else {
        fd->user = v->user;
        memcpy(fd->cam.eye, v->head, sizeof fd->cam.eye);
    }
    fd->cell_m = v->cell_m; /* the room's cells, for the view and the map */
    if (v->seat_fade > 0) { /* seated: a step's short fade to near black */
        static const uint8_t dark[3] = {1, 1, 1};
        fd->fade = 0.9 * v->seat_fade;
        memcpy(fd->fade_rgb, dark, sizeof dark);
    }
    fd->cam.yaw_deg = v->yaw_deg;
    fd->cam.pitch_deg = v->pitch_deg;
    fd->cam.fovy_deg = fovy_deg > 0 ? fovy_deg : 90;
    fd->cam.width = w;
    fd->cam.height = h;
    fd->flags = HOL_RENDER_HUD_TEXT | (v->map.place == HOL_MINIMAP_OFF ? 0 : HOL_RENDER_MINIMAP);
    if (!(v->map.cues & HOL_CUE_POLES))
        fd->flags |= HOL_RENDER_NO_POLES;
    if (!(v->map.cues & HOL_CUE_HOT_COLD))
        fd->flags |= HOL_RENDER_NO_HOT_COLD;
    if (!(v->map.cues & HOL_CUE_ARROW))
        fd->flags |= HOL_RENDER_NO_ARROW;
    if (v->map.place == HOL_MINIMAP_HAND) {
        /* a left hand held low: HOL__HAND_AHEAD ahead of the eye,
         * HOL__HAND_BELOW below it and HOL__HAND_LEFT to its left, the
         * map tilted back to face the eye */
        double y = v->yaw_deg * HOL__PI / 180, a = -atan2(HOL__HAND_BELOW, HOL__HAND_AHEAD);
        fd->hand_pos[0] = fd->cam.eye[0] - HOL__HAND_AHEAD * sin(y) - HOL__HAND_LEFT * cos(y);
        fd->hand_pos[1] = fd->cam.eye[1] - HOL__HAND_BELOW;
        fd->hand_pos[2] = fd->cam.eye[2] - HOL__HAND_AHEAD * cos(y) + HOL__HAND_LEFT * sin(y);
        double sy = sin(y / 2), cy = cos(y / 2), sa = sin(a / 2), ca = cos(a / 2);
        fd->hand_orient[0] = cy * sa; /* q_yaw * q_tilt */
        fd->hand_orient[1] = sy * ca;
        fd->hand_orient[2] = -sy * sa;
        fd->hand_orient[3] = cy * ca;
        fd->hand_size = HOL__HAND_SIZE;
        fd->flags |= HOL_RENDER_MINIMAP_HAND;
    }
    int n = v->map.nobjectives < HOL_RENDER_MAX_OBJECTIVES ? v->map.nobjectives
                                                           : HOL_RENDER_MAX_OBJECTIVES;
    fd->nobjectives = n;
    memcpy(fd->objectives, v->map.objectives, (size_t)n * sizeof fd->objectives[0]);
    int no = v->nobjects < HOL_RENDER_MAX_OBJECTIVES ? v->nobjects : HOL_RENDER_MAX_OBJECTIVES;
    fd->nobjects = no;
    for (int i = 0; i < no; i++) {
        static const uint8_t kinds[] = {HOL_RENDER_OBJ_NONE, HOL_RENDER_OBJ_FLAG,
                                        HOL_RENDER_OBJ_KEY, HOL_RENDER_OBJ_CHEST,
                                        HOL_RENDER_OBJ_CHEST_OPEN, HOL_RENDER_OBJ_MARKER};
        int k = v->objects[i].kind;
        fd->object_tiles[i] = v->objects[i].tile;
        fd->object_kinds[i] = k >= 0 && k < (int)sizeof kinds ? kinds[k] : 0;
    }
    fd->tree_marked = v->tree_marked != 0;
    fd->tree_vertex[0] = v->tree_vertex[0];
    fd->tree_vertex[1] = v->tree_vertex[1];
    fd->objective_text = v->hud.status[0] ? v->hud.status : v->hud.objective;
    fd->steps_taken = v->hud.steps;
    fd->time_s = v->hud.elapsed_s;
    fd->path = v->map.npath ? v->map.path : NULL;
    fd->lighting = v->lighting;
    /* fireflies at dusk and night, circling with the level's clock (time_s;
     * `holonomy render --fireflies T` draws the same frame) */
    fd->fireflies = 1;
    int nlan = v->nlanterns < HOL_RENDER_MAX_LANTERNS ? v->nlanterns : HOL_RENDER_MAX_LANTERNS;
    fd->nlanterns = nlan > 0 ? nlan : 0;
    memcpy(fd->lanterns, v->lanterns, (size_t)fd->nlanterns * sizeof fd->lanterns[0]);
    memcpy(fd->lantern_spot, v->lantern_spot, (size_t)fd->nlanterns);
    fd->cycle = 1;
    fd->night = v->night;
    fd->carried = v->carried;
    memcpy(fd->carried_pos, v->carried_pos, sizeof fd->carried_pos);
    fd->npath = v->map.npath;
    /* the controllers and hands at their room poses (core/hol_body.h) */
    const hol_body *b = &v->body;
    if (b->hand[0].kind || b->hand[1].kind || b->ray_hand >= 0)
        fd->body = b;
}

void hol_app_frame_panel(const hol_app_view *v, hol_frame_desc *out)
{
    out->flags |= HOL_RENDER_PANEL;
    memcpy(out->panel_pos, v->panel.pos, sizeof out->panel_pos);
    memcpy(out->panel_orient, v->panel.orient, sizeof out->panel_orient);
    /* nearer than HOL_PANEL_DISTANCE in front of a hedge: smaller alike,
     * the same angular size (core/hol_panel.h) */
    double k = v->panel.scale;
    out->panel_px = k > 0 && k != 1 ? HOL_RENDER_PANEL_PX * k : 0;
    if (v->outside.on) { /* the way back in (core/hol_app.h) */
        out->outside = 1;
        memcpy(out->outside_arrow, v->outside.arrow, sizeof out->outside_arrow);
        out->outside_yaw_deg = v->outside.arrow_yaw_deg;
    }
}
