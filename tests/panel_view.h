/* panel_view.h - the playing view the headset panel's render tests share
 * (test_render_panel.c, test_render_quad.c).
 *
 * Contract
 * - Include it after <cmocka.h> (it asserts) and core/hol_app.h; it
 *   includes <stdio.h> and <string.h>.
 * - panel_view(v, map_place, ipd, lines, nlines, hint): a zeroed view,
 *   playing, at the room's start, 1 m cells; the head standing at
 *   (1.5, 1.6, 1.62) looking north (the identity quaternion); the eyes
 *   ipd apart along x about the head (0: both at the head), each in the
 *   head's tile; the HUD's nlines lines (at most HOL_APP_HUD_LINES) and hint;
 *   the minimap at map_place with one objective, the tile Nf; the panel
 *   placed by its follower at once (hol_panel_follow, no easing).
 */
#ifndef HOL_TEST_PANEL_VIEW_H
#define HOL_TEST_PANEL_VIEW_H

#include <stdio.h>
#include <string.h>

static void panel_view(hol_app_view *v, int map_place, double ipd, const char *const *lines,
                       int nlines, const char *hint)
{
    memset(v, 0, sizeof *v);
    v->state = HOL_APP_PLAYING;
    v->user = hol_room_start();
    v->cell_m = 1;
    v->head[0] = 1.5;
    v->head[1] = 1.6;
    v->head[2] = 1.62;
    v->head_quat[3] = 1;
    for (int e = 0; e < 2; e++) {
        memcpy(v->eye[e], v->head, sizeof v->head);
        v->eye[e][0] += e ? ipd / 2 : -ipd / 2;
        v->eye_user[e] = v->user;
    }
    for (int i = 0; i < nlines; i++)
        snprintf(v->hud.lines[i], sizeof v->hud.lines[i], "%s", lines[i]);
    v->hud.nlines = nlines;
    snprintf(v->hud.hint, sizeof v->hud.hint, "%s", hint);
    v->map.place = map_place;
    assert_int_equal(hol_tile_parse("Nf", 2, &v->map.objectives[0]), HOL_OK);
    v->map.nobjectives = 1;
    hol_panel_follow(&v->panel, v->head, v->yaw_deg, 0);
}

#endif
