/* hol_app_view.c - the view an app step fills (see hol_app.h and
 * hol_app_impl.h): eyes, HUD text and prompts, minimap model, objects. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_math.h"
#include "hol_prompt.h"

#define HOL__PI 3.14159265358979323846

static void hol__quat_from_yaw_pitch(double yaw_deg, double pitch_deg, double q[4])
{
    double y = yaw_deg * HOL__PI / 360, p = pitch_deg * HOL__PI / 360;
    double sy = hol_sin(y), cy = hol_cos(y), sp = hol_sin(p), cp = hol_cos(p);
    q[0] = cy * sp;
    q[1] = sy * cp;
    q[2] = -sy * sp;
    q[3] = cy * cp;
}

/* The head's look and each eye: head +- ipd/2 along the head's right axis,
 * in the floor plane, and the room state it sees from. */
static void hol__fill_eyes(hol_app *app, const hol_input *in)
{
    hol_app_view *v = &app->view;
    v->user = app->mo.user;
    v->cell_m = app->mo.d.cell_m;
    memcpy(v->head, app->mo.head, sizeof v->head);
    v->yaw_deg = app->mo.yaw_deg;
    v->pitch_deg = app->mo.pitch_deg;
    if (in && (in->flags & HOL_INPUT_HEAD_VALID)) {
        for (int i = 0; i < 4; i++)
            v->head_quat[i] = in->head.quat[i];
    } else {
        hol__quat_from_yaw_pitch(v->yaw_deg, v->pitch_deg, v->head_quat);
    }
    double x = v->head_quat[0], y = v->head_quat[1], z = v->head_quat[2], w = v->head_quat[3];
    double rx = 1 - 2 * (y * y + z * z), rz = 2 * (x * z - w * y);
    double rn = sqrt(rx * rx + rz * rz);
    if (!(rn > 1e-9))
        rx = 1, rz = 0, rn = 1;
    for (int e = 0; e < 2; e++) {
        double s = (e ? 0.5 : -0.5) * app->d.ipd / rn;
        v->eye[e][0] = v->head[0] + s * rx;
        v->eye[e][1] = v->head[1];
        v->eye[e][2] = v->head[2] + s * rz;
        if (hol_motion_eye_state_m(&v->user, app->mo.d.cell_m, v->head, v->eye[e],
                                   &v->eye_user[e]))
            v->eye_user[e] = v->user;
    }
    /* the headset's UI panel: placed ahead at once when a level starts or
     * the room is re-placed around the head, else lazily following */
    double t = in ? in->time_s : v->panel.t;
    hol_panel_room(&v->panel, hol_room_cols(&v->user), hol_room_rows(&v->user), app->mo.d.cell_m);
    if (app->ev.level_started || app->place_panel || (in && (in->flags & HOL_INPUT_RECENTRED)))
        hol_panel_place(&v->panel, v->head, v->yaw_deg, t);
    else
        hol_panel_follow(&v->panel, v->head, v->yaw_deg, t);
    if (in)
        app->place_panel = 0;
}

static void hol__fill_objective(const hol_app *app, hol_app_hud *h)
{
    static const char *const lesson[HOL_APP_TUTORIAL_STAGES] = {
        "1/4 Step onto the marked tile ahead", "2/4 Walk round the marked tree to this cell",
        "3/4 Use the map: reach the marker", "4/4 Find the flag, every cue on"};
    switch (app->level.mode) {
    case HOL_APP_FLAG: snprintf(h->objective, sizeof h->objective, "Find the flag"); break;
    case HOL_APP_KEYS:
        if (h->keys_held < h->keys_total)
            snprintf(h->objective, sizeof h->objective, "Keys %d/%d", h->keys_held,
                     h->keys_total);
        else
            snprintf(h->objective, sizeof h->objective, "Bring the keys to the chest");
        break;
    case HOL_APP_TUTORIAL:
        snprintf(h->objective, sizeof h->objective, "%s", lesson[app->stage]);
        break;
    default:
        if (app->level.nroute)
            snprintf(h->objective, sizeof h->objective, HOL_APP_ROUTE_TEXT,
                     app->route_k + (app->route_k < app->level.nroute), app->level.nroute);
        else
            snprintf(h->objective, sizeof h->objective, "Explore");
        break;
    }
}

/* The prompt: "BUTTON: WHAT" for each pair whose action has a control on
 * the device (the first bound of each pair's alternatives), comma
 * separated. */
typedef struct hol__ask {
    uint32_t btn, alt; /* HOL_BTN_*; alt: the control to name when btn has none */
    const char *what;
} hol__ask;

static void hol__prompt(hol_app_hud *h, uint32_t device, const hol__ask *ask, int n)
{
    size_t len = 0;
    h->hint[0] = 0;
    for (int i = 0; i < n; i++) {
        const char *b = hol_prompt_button(device, ask[i].btn);
        if (!b && ask[i].alt)
            b = hol_prompt_button(device, ask[i].alt);
        if (!b)
            continue;
        int k = snprintf(h->hint + len, sizeof h->hint - len, "%s%s: %s", len ? ", " : "", b,
                         ask[i].what);
        if (k < 0 || (size_t)k >= sizeof h->hint - len) {
            h->hint[len] = 0; /* what does not fit is left out */
            break;
        }
        len += (size_t)k;
    }
}

/* A headset's first seconds with its device: the control that opens the
 * menu ("Y: menu"), after the prompt shown if it fits (hol_app.h:
 * HOL_APP_MENU_HINT_S). Only while a level is played: not in the menu,
 * nor on the end screen, a pointing question, a questionnaire or a screen
 * of text, whose prompts name what acts there. */
static void hol__menu_hint(const hol_app *app, const hol_input *in, hol_app_hud *h)
{
    const char *b = hol_prompt_button(app->device, HOL_BTN_MENU);
    if (!in || !b || app->device < HOL_DEVICE_XR_SIMPLE || app->menu ||
        app->view.state != HOL_APP_PLAYING || !(in->time_s - app->device_t < HOL_APP_MENU_HINT_S))
        return;
    size_t len = strlen(h->hint);
    int k = snprintf(h->hint + len, sizeof h->hint - len, "%s%s: menu", len ? ", " : "", b);
    if (k < 0 || (size_t)k >= sizeof h->hint - len)
        h->hint[len] = 0; /* no room: the prompt alone */
}

const char *hol_app_end_word(const hol_app_view *v)
{
    static const char *const word[] = {
        [HOL_APP_IDLE] = "idle", [HOL_APP_PLAYING] = "playing", [HOL_APP_DONE] = "done",
        [HOL_APP_QUIT] = "quit", [HOL_APP_POINT] = "done",      [HOL_APP_SCREEN] = "playing",
        [HOL_APP_ASK] = "done"};
    _Static_assert(sizeof word / sizeof word[0] == HOL_APP_STATE_COUNT, "one word per state");
    if (v->hud.timed_out)
        return "timeout";
    if (v->state == HOL_APP_SCREEN && v->hud.screen == HOL_APP_SCREEN_CLOSING)
        return "done";
    if (v->state == HOL_APP_ASK && v->hud.ask_before)
        return "playing"; /* a baseline: the level has not begun */
    unsigned s = (unsigned)v->state;
    return s < HOL_APP_STATE_COUNT && word[s] ? word[s] : "playing";
}

/* A screen of text (state HOL_APP_SCREEN): its prompt. */
static void hol__screen_status(const hol_app *app, hol_app_hud *h)
{
    const hol__ask ask[2] = {{HOL_BTN_CONFIRM, 0,
                              app->screen == HOL_APP_SCREEN_CLOSING ? "finish" : "begin"},
                             {HOL_BTN_QUIT, 0, "quit"}};
    hol__prompt(h, app->device, ask, app->screen == HOL_APP_SCREEN_CLOSING ? 1 : 2);
}

/* The pointing question (state HOL_APP_POINT): what to point at, and how
 * (a headset: the controller; else the view). */
static void hol__point_status(const hol_app *app, const hol_input *in, hol_app_hud *h)
{
    const hol_app_level *L = &app->level;
    const char *what = L->point == HOL_APP_POINT_START ? "the start"
                       : L->mode == HOL_APP_KEYS       ? "the chest"
                                                       : "the flag";
    if (in && (in->flags & HOL_INPUT_HEAD_VALID) &&
        (in->flags & (HOL_INPUT_HAND_R_VALID | HOL_INPUT_HAND_L_VALID)))
        snprintf(h->status, sizeof h->status, "Point the controller at %s", what);
    else
        snprintf(h->status, sizeof h->status, "Turn to face %s", what);
    const hol__ask ask[1] = {{HOL_BTN_CONFIRM, 0, "confirm"}};
    hol__prompt(h, app->device, ask, 1);
}

/* Status (end screen, pause, safety) and the prompt of what the buttons do
 * now, worded for the device in use. */
static void hol__fill_status(hol_app *app, const hol_input *in, hol_app_hud *h)
{
    const hol_app_view *v = &app->view;
    uint32_t dev = app->device;
    long secs = (long)app->level_t;
    h->hint[0] = 0;
    h->status[0] = 0;
    if (app->menu) {
        snprintf(h->status, sizeof h->status, "Paused");
        const hol__ask ask[3] = {{HOL_BTN_MENU, 0, "resume"},
                                 {HOL_BTN_CONFIRM, 0, "restart"},
                                 {HOL_BTN_QUIT, HOL_BTN_BACK, "quit"}};
        hol__prompt(h, dev, ask, 3);
    } else if (v->state == HOL_APP_SCREEN) {
        hol__screen_status(app, h);
    } else if (v->state == HOL_APP_ASK) {
        const hol__ask ask[2] = {{HOL_BTN_CONFIRM, 0, "answer"}, {HOL_BTN_QUIT, 0, "quit"}};
        hol__prompt(h, dev, ask, 2);
    } else if (v->state == HOL_APP_POINT) {
        hol__point_status(app, in, h);
    } else if (v->state == HOL_APP_DONE) {
        if (app->timed_out)
            snprintf(h->status, sizeof h->status, "Time up: %d steps, best %d, %ld:%02ld",
                     app->steps, app->optimum, secs / 60 % 100000, secs % 60);
        else if (app->level.mode == HOL_APP_TUTORIAL)
            snprintf(h->status, sizeof h->status, "Tutorial done: %d steps, %ld:%02ld",
                     app->steps, secs / 60 % 100000, secs % 60);
        else
            snprintf(h->status, sizeof h->status, "Done: %d steps, best %d, %ld:%02ld",
                     app->steps, app->optimum, secs / 60 % 100000, secs % 60);
        const hol__ask ask[2] = {{HOL_BTN_CONFIRM, 0, app->level.last ? "finish" : "next level"},
                                 {HOL_BTN_RESTART, 0, "again"}};
        hol__prompt(h, dev, ask, 2);
    } else if (v->paused && in && (in->flags & HOL_INPUT_DEVICE_LOST)) {
        snprintf(h->status, sizeof h->status, "Controller lost");
        snprintf(h->hint, sizeof h->hint, "Plug it back in, or press a key");
    } else if (v->paused) {
        snprintf(h->status, sizeof h->status, "Paused");
    } else if (app->level.mode == HOL_APP_TUTORIAL && app->stage == 0 && hol_prompt_move(dev)) {
        snprintf(h->hint, sizeof h->hint, "%s", hol_prompt_move(dev));
    } else if (app->level.mode == HOL_APP_TUTORIAL && app->stage == 2) {
        const hol__ask ask[1] = {{HOL_BTN_MINIMAP, 0, "map on the HUD, in the hand, off"}};
        hol__prompt(h, dev, ask, 1);
    }
    hol__menu_hint(app, in, h);
    /* safety: a tracked head beyond the hedges; a play area too small */
    double w = hol_room_cols(&v->user) * app->mo.d.cell_m,
           d = hol_room_rows(&v->user) * app->mo.d.cell_m;
    if (in && (in->flags & HOL_INPUT_HEAD_VALID) &&
        (in->head.pos[0] < 0 || in->head.pos[0] > w || in->head.pos[2] < 0 ||
         in->head.pos[2] > d))
        snprintf(h->status, sizeof h->status, "Outside the room: step back in");
    if (in && (in->flags & HOL_INPUT_BOUNDS_SMALL) && !h->hint[0]) {
        char size[32]; /* the room in metres: "3 x 3", "2.5 x 3.75" */
        snprintf(size, sizeof size, "%.3g x %.3g", w, d);
        snprintf(h->hint, sizeof h->hint, "Play area under %.12s m: mind the edges", size);
    }
}

/* The text as drawn: the feedback of a lesson just done, the status or the
 * objective, the steps, the time when the level has a limit; with the
 * debug text on, the tile, the cell and the clock too. */
static void hol__fill_lines(const hol_app *app, hol_app_hud *h)
{
    const hol_app_view *v = &app->view;
    long secs = (long)app->level_t, lim = (long)app->level.time_limit_s;
    h->nlines = 0;
    if (v->state == HOL_APP_ASK) {
        hol__ask_lines(app, h);
        return;
    }
    if (v->state == HOL_APP_SCREEN) { /* the screen's text, whole */
        const char *text = app->screen == HOL_APP_SCREEN_CLOSING ? app->level.closing
                                                                 : app->level.instructions;
        int n = hol_app_wrap(text, HOL_APP_SCREEN_COLS, h->lines, HOL_APP_HUD_LINES);
        h->nlines = n < HOL_APP_HUD_LINES ? n : HOL_APP_HUD_LINES;
        return;
    }
#define HOL__LINE(...)                                                                     \
    (h->nlines < HOL_APP_HUD_LINES                                                         \
         ? (void)snprintf(h->lines[h->nlines++], HOL_APP_TEXT_MAX, __VA_ARGS__)            \
         : (void)0)
    if (h->feedback[0] && (v->state != HOL_APP_DONE || !strcmp(h->feedback, HOL__FIXED_TEXT)))
        HOL__LINE("%s", h->feedback);
    if (h->note[0] && v->state != HOL_APP_DONE)
        HOL__LINE("%s", h->note);
    HOL__LINE("%s", h->status[0] ? h->status : h->objective);
    if (v->seated) /* the panel names the mode */
        HOL__LINE("%s", hol_prompt_seated(h->device));
    HOL__LINE("STEPS %d", h->steps);
    if (lim > 0)
        HOL__LINE("TIME %ld:%02ld OF %ld:%02ld", secs / 60 % 100000, secs % 60, lim / 60 % 100000,
                  lim % 60);
    if (h->debug) {
        HOL__LINE("TILE %.40s", h->address);
        HOL__LINE("CELL %d,%d NORTH %d", v->user.col, v->user.row, v->user.orient);
        if (lim <= 0)
            HOL__LINE("TIME %ld:%02ld", secs / 60 % 100000, secs % 60);
    }
#undef HOL__LINE
}

static void hol__fill_hud(hol_app *app, const hol_input *in)
{
    hol_app_hud *h = &app->view.hud;
    const hol_app_level *L = &app->level;
    int tut = L->mode == HOL_APP_TUTORIAL;
    h->steps = app->steps;
    h->optimum = app->optimum;
    h->remaining = app->remaining;
    h->elapsed_s = app->level_t;
    h->keys_total = L->mode == HOL_APP_KEYS ? L->nkeys : 0;
    h->keys_held = 0;
    h->stage = tut ? app->stage : -1;
    h->stage_steps = tut ? app->stage_steps : 0;
    h->stage_optimum = tut ? app->stage_optimum : -1;
    h->timed_out = app->timed_out;
    h->debug = app->debug;
    h->screen = app->view.state == HOL_APP_SCREEN ? app->screen : 0;
    if (app->view.state != HOL_APP_ASK)
        h->ask_item = h->ask_items = h->ask_value = h->ask_before = 0;
    h->device = app->device;
    for (int k = 0; k < h->keys_total; k++)
        h->keys_held += (int)(app->keys_held >> k & 1);
    hol_tile_print(app->view.user.tile, h->address);
    int fb = tut && app->feedback[0] && app->level_t < app->feedback_until;
    int fixed = app->fixed_shown && in && in->time_s < app->fixed_until;
    snprintf(h->feedback, sizeof h->feedback, "%s",
             fixed ? HOL__FIXED_TEXT : fb ? app->feedback : "");
    snprintf(h->note, sizeof h->note, "%s",
             fb && !fixed && app->nmarks && app->rings_note ? HOL_APP_RINGS_TEXT : "");
    hol__fill_objective(app, h);
    hol__fill_status(app, in, h);
    hol__fill_lines(app, h);
}

/* The minimap model and the game objects in the world: the flag (or a
 * lesson's marker, and lesson 2's marked tree), the keys not yet collected, the chest (open once every
 * key is held); the path when the user strays beyond the optimum (the
 * lesson's, in the tutorial) plus desc.stray_steps. */
static void hol__fill_map(hol_app *app)
{
    hol_app_view *v = &app->view;
    const hol_app_level *L = &app->level;
    const hol_app_hud *h = &v->hud;
    hol_app_minimap *m = &v->map;
    m->cues = L->cues;
    m->nobjectives = 0;
    if (L->mode == HOL_APP_FLAG && !app->done)
        m->objectives[m->nobjectives++] = L->flag;
    if (L->mode == HOL_APP_TUTORIAL && !app->done && app->has_target)
        m->objectives[m->nobjectives++] = app->target;
    if (app->route_k < L->nroute && !app->done)
        m->objectives[m->nobjectives++] = app->route_tiles[app->route_k];
    if (L->mode == HOL_APP_KEYS && !app->done) {
        for (int k = 0; k < L->nkeys; k++)
            if (!(app->keys_held >> k & 1))
                m->objectives[m->nobjectives++] = L->keys[k];
        if (h->keys_held == h->keys_total)
            m->objectives[m->nobjectives++] = L->chest;
    }
    /* the lesson's marks go with its feedback (not with "Minimap fixed") */
    m->nmarks = h->feedback[0] && strcmp(h->feedback, HOL__FIXED_TEXT) ? app->nmarks : 0;
    memcpy(m->marks, app->marks, sizeof m->marks);
    v->nobjects = 0;
    if (L->mode == HOL_APP_FLAG)
        v->objects[v->nobjects++] = (hol_app_object){L->flag, HOL_APP_OBJ_FLAG};
    if (L->mode == HOL_APP_TUTORIAL && app->has_target && !app->done)
        v->objects[v->nobjects++] = (hol_app_object){
            app->target, app->stage == 3 ? HOL_APP_OBJ_FLAG : HOL_APP_OBJ_MARKER};
    if (app->route_k < L->nroute && !app->done)
        v->objects[v->nobjects++] =
            (hol_app_object){app->route_tiles[app->route_k], HOL_APP_OBJ_MARKER};
    v->tree_marked = L->mode == HOL_APP_TUTORIAL && app->stage == 1 && app->has_tree && !app->done;
    v->tree_vertex[0] = v->tree_marked ? app->tree[0] : 0;
    v->tree_vertex[1] = v->tree_marked ? app->tree[1] : 0;
    if (L->mode == HOL_APP_KEYS) {
        for (int k = 0; k < L->nkeys; k++)
            if (!(app->keys_held >> k & 1))
                v->objects[v->nobjects++] = (hol_app_object){L->keys[k], HOL_APP_OBJ_KEY};
        v->objects[v->nobjects++] = (hol_app_object){
            L->chest, h->keys_held == h->keys_total ? HOL_APP_OBJ_CHEST_OPEN : HOL_APP_OBJ_CHEST};
    }
    int tut = L->mode == HOL_APP_TUTORIAL;
    int opt = tut ? app->stage_optimum : app->optimum, taken = tut ? app->stage_steps : app->steps;
    m->npath = 0;
    if ((L->cues & HOL_CUE_PATH) && !app->done && opt >= 0 && app->remaining >= 0 &&
        taken + app->remaining > opt + app->d.stray_steps) {
        m->npath = app->nwalk < HOL_APP_PATH_MAX ? app->nwalk : HOL_APP_PATH_MAX;
        memcpy(m->path, app->walk, (size_t)m->npath);
    }
    if (tut && m->npath && !app->path_told) { /* the first time: what it means */
        app->path_told = 1;
        snprintf(app->feedback, sizeof app->feedback, "%s", HOL_APP_PATH_TEXT);
        app->feedback_until = app->level_t + HOL__FEEDBACK_S;
        app->nmarks = 0;
        app->rings_note = 0;
        v->hud.note[0] = 0;
        snprintf(v->hud.feedback, sizeof v->hud.feedback, "%s", HOL_APP_PATH_TEXT);
    }
}

/* The level's sky and lights: its placed lanterns, then (cue lantern) one
 * on every game object drawn. */
static void hol__fill_lights(hol_app *app)
{
    hol_app_view *v = &app->view;
    const hol_app_level *L = &app->level;
    v->lighting = L->lighting;
    v->sound = L->sound;
    v->nlanterns = 0;
    for (int k = 0; k < L->nlanterns && k < HOL_APP_MAX_LANTERNS; k++) {
        v->lantern_spot[v->nlanterns] = L->lantern_spot[k];
        v->lanterns[v->nlanterns++] = L->lanterns[k];
    }
    for (int k = 0; (L->cues & HOL_CUE_LANTERN) && k < v->nobjects; k++) {
        v->lantern_spot[v->nlanterns] = 0;
        v->lanterns[v->nlanterns++] = v->objects[k].tile;
    }
}

void hol__fill_view(hol_app *app, const hol_input *in)
{
    hol_app_view *v = &app->view;
    if (in)
        v->seated = (in->flags & HOL_INPUT_SEATED) != 0;
    double since = in && app->seat_stepped ? in->time_s - app->seat_step_t : HOL_APP_SEAT_FADE_S;
    v->seat_fade = v->seated && since < HOL_APP_SEAT_FADE_S ? 1 - since / HOL_APP_SEAT_FADE_S : 0;
    hol__fill_eyes(app, in);
    hol__fill_hud(app, in);
    hol__fill_map(app);
    hol__fill_lights(app);
}
