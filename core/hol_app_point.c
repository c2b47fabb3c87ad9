/* hol_app_point.c - the pointing question of a level (`point`, SPEC 8;
 * see hol_app.h, hol_app_point): the level's walk as hol_bearing counts
 * it, the question at the level's end and its answer. */
#include <math.h>
#include <string.h>

#include "hol_app_impl.h"

/* The target tile of the level's question. */
static hol_tile hol__point_target(const hol_app *app)
{
    const hol_app_level *L = &app->level;
    if (L->point == HOL_APP_POINT_OBJECTIVE)
        return L->mode == HOL_APP_KEYS ? L->chest : L->flag;
    return app->start_room.tile;
}

void hol__point_begin(hol_app *app)
{
    const hol_app_level *L = &app->level;
    app->bw_ok = 0;
    if (!L->point)
        return;
    hol_tile target = hol__point_target(app);
    if (hol_bearing_begin(&app->bw, target))
        return;
    for (int i = 0; i < L->nstart; i++)
        if (hol_bearing_step(&app->bw, L->start[i]))
            return;
    /* the flat vector counts from where the level begins: the start walk's
     * own visits are not the participant's */
    app->bw.x = app->bw.y = 0;
    app->bw.tx = app->bw.ty = 0;
    app->bw.steps = 0;
    app->bw.seen = hol_tile_eq(app->bw.at, target);
    app->bw_ok = hol_tile_eq(app->bw.at, app->start_room.tile) &&
                 app->bw.orient == app->start_room.orient;
}

void hol__point_step(hol_app *app, int dir)
{
    if (app->bw_ok && hol_bearing_step(&app->bw, dir))
        app->bw_ok = 0;
}

/* The room was placed anew around the head (no room step): the walk stands
 * where the room says, with the room's north. */
void hol__point_sync(hol_app *app)
{
    if (!app->bw_ok)
        return;
    int was = hol_tile_eq(app->bw.at, app->mo.user.tile);
    app->bw.orient = app->mo.user.orient;
    if (!was)
        app->bw_ok = 0; /* cannot happen: a re-placing keeps the tile */
}

/* Degrees wrapped to (-180, 180]. */
static double hol__wrap180(double d)
{
    d = fmod(d, 360.0);
    if (d > 180)
        d -= 360;
    if (d <= -180)
        d += 360;
    return d;
}

/* A yaw (SPEC 1: 0 north, positive towards the west) as a bearing. */
static double hol__bearing_of_yaw(double yaw)
{
    double b = fmod(-yaw, 360.0);
    if (b < 0)
        b += 360;
    return b >= 360 ? 0 : b;
}

/* The direction the user points now (hol_app_point). */
double hol__pointed_yaw(const hol_app *app, const hol_input *in)
{
    if (in && (in->flags & HOL_INPUT_HEAD_VALID) &&
        (in->flags & (HOL_INPUT_HAND_R_VALID | HOL_INPUT_HAND_L_VALID))) {
        int h = (in->flags & HOL_INPUT_HAND_R_VALID) ? HOL_HAND_RIGHT : HOL_HAND_LEFT;
        double yaw = app->mo.yaw_deg, pitch = 0;
        hol__yaw_pitch_from_quat(in->hand[h].quat, &yaw, &pitch);
        return yaw;
    }
    return app->mo.yaw_deg;
}

int hol__point_can_ask(const hol_app *app)
{
    return app->level.point && app->bw_ok;
}

/* The answer at confirm: the event's row. */
void hol__point_answer(hol_app *app, const hol_input *in)
{
    hol_app_point *p = &app->ev.point;
    memset(p, 0, sizeof *p);
    p->target = app->level.point;
    p->t = app->level_t;
    p->asked_s = app->asked_s;
    p->time_s = in->time_s - app->asked_s;
    p->at_s = in->time_s;
    p->pointed_deg = hol__bearing_of_yaw(hol__pointed_yaw(app, in));
    hol_bearing b;
    if (!hol_bearing_end(&app->bw, &b)) {
        p->has_true = b.has_true;
        p->has_flat = b.has_flat;
        p->true_deg = b.true_deg;
        p->flat_deg = b.flat_deg;
    }
    if (p->has_true)
        p->error_true = hol__wrap180(p->pointed_deg - p->true_deg);
    if (p->has_flat)
        p->error_flat = hol__wrap180(p->pointed_deg - p->flat_deg);
    app->ev.pointed = 1;
}
