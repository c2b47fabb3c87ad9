/* hol_app_view.c - the view an app step fills (see hol_app.h and
 * hol_app_impl.h): eyes, HUD text and prompts, minimap model, objects. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_lesson.h"
#include "hol_math.h"
#include "hol_prompt.h"
#include "hol_str.h"

/* buf (an array) gets the table's text of id in lang. */
#define HOL__PUT(buf, lang, id) snprintf((buf), sizeof(buf), "%s", hol_str((lang), (id)))

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

/* The map held off by a study (`fixed minimap` with the map off), but
 * with desc.flow_v4: the tutorial does not send the player to it, nor
 * says what its rings mean. */
static int hol__map_held_off(const hol_app *app)
{
    return !app->d.flow_v4 && app->level.minimap_fixed && app->level.minimap == HOL_MINIMAP_OFF;
}

/* The tutorial's prompt for a lesson (the move keys, M): not while a
 * lesson's feedback shows (one idea at a time), and M not on a level
 * whose minimap a study holds; with desc.flow_v4 as before (issue 35). */
static int hol__lesson_prompt(const hol_app *app, const hol_app_hud *h, int stage)
{
    if (app->level.mode != HOL_APP_TUTORIAL || app->stage != stage)
        return 0;
    if (app->d.flow_v4)
        return 1;
    return !h->feedback[0] && !(stage == 2 && app->level.minimap_fixed);
}

static void hol__fill_objective(const hol_app *app, hol_app_hud *h)
{
    int lang = hol__lang(app);
    switch (app->level.mode) {
    case HOL_APP_FLAG: HOL__PUT(h->objective, lang, HOL_S_OBJ_FLAG); break;
    case HOL_APP_KEYS:
        if (h->keys_held < h->keys_total)
            snprintf(h->objective, sizeof h->objective, hol_str(lang, HOL_S_OBJ_KEYS_FMT),
                     h->keys_held, h->keys_total);
        else
            HOL__PUT(h->objective, lang, HOL_S_OBJ_CHEST);
        break;
    case HOL_APP_TUTORIAL:
        HOL__PUT(h->objective, lang,
                 hol__map_held_off(app) && app->stage == 2 ? HOL_S_LESSON_3_NOMAP
                                                           : (hol_str_id)(HOL_S_LESSON_1 + app->stage));
        break;
    default:
        if (app->level.nroute)
            snprintf(h->objective, sizeof h->objective, hol_str(lang, HOL_S_ROUTE_FMT),
                     app->route_k + (app->route_k < app->level.nroute), app->level.nroute);
        else
            HOL__PUT(h->objective, lang, HOL_S_OBJ_EXPLORE);
        break;
    }
}

/* The prompt: "BUTTON: WHAT" for each pair whose action has a control on
 * the device (the first bound of each pair's alternatives), comma
 * separated. */
typedef struct hol__ask {
    uint32_t btn, alt; /* HOL_BTN_*; alt: the control to name when btn has none */
    hol_str_id what;
} hol__ask;

static void hol__prompt(const hol_app *app, hol_app_hud *h, const hol__ask *ask, int n)
{
    uint32_t device = app->device;
    size_t len = 0;
    h->hint[0] = 0;
    for (int i = 0; i < n; i++) {
        const char *b = hol_prompt_button_in(device, ask[i].btn, hol__lang(app));
        if (!b && ask[i].alt)
            b = hol_prompt_button_in(device, ask[i].alt, hol__lang(app));
        if (!b)
            continue;
        int k = snprintf(h->hint + len, sizeof h->hint - len, "%s%s: %s", len ? ", " : "", b,
                         hol_str(hol__lang(app), ask[i].what));
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
    const char *b = hol_prompt_button_in(app->device, HOL_BTN_MENU, hol__lang(app));
    if (!in || !b || app->device < HOL_DEVICE_XR_SIMPLE || app->device == HOL_DEVICE_SCREEN ||
        app->menu ||
        app->level.lesson == HOL_APP_HINT_LESSON || /* its prompt names the button */
        app->view.state != HOL_APP_PLAYING || !(in->time_s - app->device_t < HOL_APP_MENU_HINT_S))
        return;
    size_t len = strlen(h->hint);
    int k = snprintf(h->hint + len, sizeof h->hint - len, "%s%s: %s", len ? ", " : "", b,
                     hol_str(hol__lang(app), HOL_S_DO_MENU));
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
    const hol__ask ask[2] = {
        {HOL_BTN_CONFIRM, 0,
         app->screen == HOL_APP_SCREEN_CLOSING ? HOL_S_DO_FINISH : HOL_S_DO_BEGIN},
        {HOL_BTN_QUIT, 0, HOL_S_DO_QUIT}};
    hol__prompt(app, h, ask, app->screen == HOL_APP_SCREEN_CLOSING ? 1 : 2);
}

/* The pointing question (state HOL_APP_POINT): what to point at, and how
 * (a headset: the controller; else the view). */
static void hol__point_status(const hol_app *app, const hol_input *in, hol_app_hud *h)
{
    const hol_app_level *L = &app->level;
    int what = L->point == HOL_APP_POINT_START ? 0 : L->mode == HOL_APP_KEYS ? 1 : 2;
    int ctrl = in && (in->flags & HOL_INPUT_HEAD_VALID) &&
               (in->flags & (HOL_INPUT_HAND_R_VALID | HOL_INPUT_HAND_L_VALID));
    HOL__PUT(h->status, hol__lang(app),
             (hol_str_id)((ctrl ? HOL_S_POINT_CTRL_START : HOL_S_POINT_FACE_START) + what));
    const hol__ask ask[1] = {{HOL_BTN_CONFIRM, 0, HOL_S_DO_CONFIRM}};
    hol__prompt(app, h, ask, 1);
}

/* Status (end screen, pause, safety) and the prompt of what the buttons do
 * now, worded for the device in use. */
static void hol__fill_status(hol_app *app, const hol_input *in, hol_app_hud *h)
{
    const hol_app_view *v = &app->view;
    uint32_t dev = app->device;
    int lang = hol__lang(app);
    long secs = (long)app->level_t;
    h->hint[0] = 0;
    h->status[0] = 0;
    if (app->menu) {
        HOL__PUT(h->status, lang, HOL_S_PAUSED);
        const hol__ask ask[3] = {{HOL_BTN_MENU, 0, HOL_S_DO_RESUME},
                                 {HOL_BTN_CONFIRM, 0, HOL_S_DO_RESTART},
                                 {HOL_BTN_QUIT, HOL_BTN_BACK, HOL_S_DO_QUIT}};
        hol__prompt(app, h, ask, 3);
    } else if (v->state == HOL_APP_SCREEN) {
        hol__screen_status(app, h);
    } else if (v->state == HOL_APP_ASK) {
        const hol__ask ask[2] = {{HOL_BTN_CONFIRM, 0, HOL_S_DO_ANSWER},
                                 {HOL_BTN_QUIT, 0, HOL_S_DO_QUIT}};
        hol__prompt(app, h, ask, 2);
    } else if (v->state == HOL_APP_POINT) {
        hol__point_status(app, in, h);
    } else if (v->state == HOL_APP_DONE) {
        if (app->timed_out)
            snprintf(h->status, sizeof h->status, hol_str(lang, HOL_S_TIME_UP_FMT), app->steps, app->optimum, secs / 60 % 100000, secs % 60);
        else if (app->level.mode == HOL_APP_TUTORIAL)
            snprintf(h->status, sizeof h->status, hol_str(lang, HOL_S_TUTORIAL_DONE_FMT), app->steps, secs / 60 % 100000, secs % 60);
        else
            snprintf(h->status, sizeof h->status, hol_str(lang, HOL_S_DONE_FMT), app->steps, app->optimum, secs / 60 % 100000, secs % 60);
        const hol__ask ask[2] = {
            {HOL_BTN_CONFIRM, 0, app->level.last ? HOL_S_DO_FINISH : HOL_S_DO_NEXT_LEVEL},
            {HOL_BTN_RESTART, 0, HOL_S_DO_AGAIN}};
        hol__prompt(app, h, ask, 2);
    } else if (v->paused && in && (in->flags & HOL_INPUT_DEVICE_LOST)) {
        HOL__PUT(h->status, lang, HOL_S_DEVICE_LOST);
        HOL__PUT(h->hint, lang, HOL_S_DEVICE_BACK);
    } else if (v->paused) {
        HOL__PUT(h->status, lang, HOL_S_PAUSED);
    } else if (hol__lesson_prompt(app, h, 0) && hol_prompt_move(dev, lang)) {
        snprintf(h->hint, sizeof h->hint, "%s", hol_prompt_move(dev, lang));
    } else if (hol__lesson_prompt(app, h, 2)) {
        const hol__ask ask[1] = {{HOL_BTN_MINIMAP, 0, HOL_S_DO_MAP}};
        hol__prompt(app, h, ask, 1);
    } else if (app->level.lesson == HOL_APP_HINT_LESSON && v->state == HOL_APP_PLAYING) {
        const hol__ask ask[1] = {{HOL_BTN_MENU, 0, HOL_S_DO_HINT}}; /* the menu shows it */
        hol__prompt(app, h, ask, 1);
    }
    hol__menu_hint(app, in, h);
    /* safety: a tracked head beyond the hedges; a play area too small */
    double w = hol_room_cols(&v->user) * app->mo.d.cell_m,
           d = hol_room_rows(&v->user) * app->mo.d.cell_m;
    if (in && (in->flags & HOL_INPUT_HEAD_VALID) &&
        (in->head.pos[0] < 0 || in->head.pos[0] > w || in->head.pos[2] < 0 ||
         in->head.pos[2] > d))
        HOL__PUT(h->status, lang, HOL_S_OUTSIDE);
    if (in && (in->flags & HOL_INPUT_BOUNDS_SMALL) && !h->hint[0]) {
        char size[32]; /* the room in metres: "3 x 3", "2.5 x 3.75" */
        snprintf(size, sizeof size, "%.3g x %.3g", w, d);
        snprintf(h->hint, sizeof h->hint, hol_str(lang, HOL_S_SMALL_AREA_FMT), size);
    }
}

/* The text as drawn: the feedback of a lesson just done, the status or the
 * objective, the steps, the time when the level has a limit; with the
 * debug text on, the tile, the cell and the clock too. */
static void hol__fill_lines(const hol_app *app, hol_app_hud *h)
{
    const hol_app_view *v = &app->view;
    long secs = (long)app->level_t, lim = (long)app->level.time_limit_s;
    int lang = hol__lang(app);
    h->nlines = 0;
    if (v->state == HOL_APP_ASK) {
        hol__ask_lines(app, h);
        return;
    }
    char said[HOL_APP_SCREEN_TEXT];
    if (v->state == HOL_APP_SCREEN) { /* the screen's text, whole */
        const char *text = app->screen == HOL_APP_SCREEN_CLOSING ? app->level.closing
                           : app->screen == HOL_APP_SCREEN_READY ? hol_str(lang, HOL_S_READY)
                                                                 : app->level.instructions;
        if (app->screen != HOL_APP_SCREEN_READY)
            text = hol__lesson_say(app, text,
                                   app->screen == HOL_APP_SCREEN_CLOSING ? HOL_LESSON_CHECK
                                                                         : HOL_LESSON_WALK,
                                   said, sizeof said);
        int n = hol_app_wrap(text, HOL_APP_SCREEN_COLS, h->lines, HOL_APP_HUD_LINES);
        h->nlines = n < HOL_APP_HUD_LINES ? n : HOL_APP_HUD_LINES;
        return;
    }
#define HOL__LINE(...)                                                                     \
    (h->nlines < HOL_APP_HUD_LINES                                                         \
         ? (void)snprintf(h->lines[h->nlines++], HOL_APP_TEXT_MAX, __VA_ARGS__)            \
         : (void)0)
    if (app->menu && v->state == HOL_APP_PLAYING && hol__lesson_hint(app, said, sizeof said)) {
        int n = hol_app_wrap(said, HOL_APP_SCREEN_COLS, h->lines, 3); /* the hint asked for */
        h->nlines = n < 3 ? n : 3;
    }
    if (h->feedback[0] &&
        (v->state != HOL_APP_DONE || !strcmp(h->feedback, hol_str(lang, HOL_S_FIXED))))
        HOL__LINE("%s", h->feedback);
    if (h->note[0] && v->state != HOL_APP_DONE)
        HOL__LINE("%s", h->note);
    /* one idea at a time (issue 35): a lesson's feedback, and its note,
     * alone; the next lesson's objective after it */
    int alone = !app->d.flow_v4 && app->level.mode == HOL_APP_TUTORIAL &&
                v->state == HOL_APP_PLAYING && h->feedback[0] && !h->status[0] &&
                strcmp(h->feedback, hol_str(lang, HOL_S_FIXED));
    if (alone && !h->debug)
        return;
    HOL__LINE("%s", h->status[0] ? h->status : h->objective);
    if (v->seated) /* the panel names the mode */
        HOL__LINE("%s", hol_prompt_seated(h->device, lang));
    HOL__LINE(hol_str(lang, HOL_S_STEPS_FMT), h->steps);
    if (lim > 0)
        HOL__LINE(hol_str(lang, HOL_S_TIME_OF_FMT), secs / 60 % 100000, secs % 60, lim / 60 % 100000,
                  lim % 60);
    if (h->debug) {
        HOL__LINE(hol_str(lang, HOL_S_TILE_FMT), h->address);
        HOL__LINE(hol_str(lang, HOL_S_CELL_FMT), v->user.col, v->user.row, v->user.orient);
        if (lim <= 0)
            HOL__LINE(hol_str(lang, HOL_S_TIME_FMT), secs / 60 % 100000, secs % 60);
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
             fixed ? hol_str(hol__lang(app), HOL_S_FIXED) : fb ? app->feedback : "");
    snprintf(h->note, sizeof h->note, "%s",
             fb && !fixed && app->nmarks && app->rings_note && !hol__map_held_off(app)
                 ? hol_str(hol__lang(app), HOL_S_RINGS)
                 : "");
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
    m->nmarks =
        h->feedback[0] && strcmp(h->feedback, hol_str(hol__lang(app), HOL_S_FIXED)) ? app->nmarks : 0;
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
    if (v->state == HOL_APP_SCREEN && app->screen != HOL_APP_SCREEN_CLOSING) {
        /* before the clock starts: no minimap, no objective (issue 35) */
        m->place = HOL_MINIMAP_OFF;
        m->nobjectives = m->nmarks = v->nobjects = 0;
        v->tree_marked = 0;
        return;
    }
    if ((L->cues & HOL_CUE_PATH) && !app->done && opt >= 0 && app->remaining >= 0 &&
        taken + app->remaining > opt + app->d.stray_steps) {
        m->npath = app->nwalk < HOL_APP_PATH_MAX ? app->nwalk : HOL_APP_PATH_MAX;
        memcpy(m->path, app->walk, (size_t)m->npath);
    }
    if (tut && m->npath && !app->path_told) { /* the first time: what it means */
        app->path_told = 1;
        HOL__PUT(app->feedback, hol__lang(app), HOL_S_PATH);
        app->feedback_until = app->level_t + HOL__FEEDBACK_S;
        app->nmarks = 0;
        app->rings_note = 0;
        v->hud.note[0] = 0;
        HOL__PUT(v->hud.feedback, hol__lang(app), HOL_S_PATH);
    }
}

/* The level's sky and lights: the sky between dusk and night, its placed
 * lanterns, then (cue lantern) one on every game object drawn, and the
 * carried lantern under the head. */
static void hol__fill_lights(hol_app *app)
{
    hol_app_view *v = &app->view;
    const hol_app_level *L = &app->level;
    v->lighting = L->lighting;
    v->night = L->lighting == HOL_LIGHT_NIGHT ? 1 : 0;
    if (L->lighting_cycle_s > 0) {
        double u = app->level_t / L->lighting_cycle_s;
        v->night = u < 0 ? 0 : u > 1 ? 1 : u;
    }
    v->carried = L->lantern_carried != 0;
    v->carried_pos[0] = v->head[0];
    v->carried_pos[1] = v->head[1] - HOL_APP_CARRIED_DROP_M;
    v->carried_pos[2] = v->head[2];
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

/* The sound's caption (hol_app.h: hol_app_hud.caption): a chime seen
 * where core/hol_sound.c plays one (the step's level start; more keys held
 * than the last step ended with; the level done from play, not timed
 * out), not while paused; then the beacons while they sound. */
static void hol__caption(hol_app *app, const hol_input *in)
{
    hol_app_view *v = &app->view;
    hol_app_hud *h = &v->hud;
    /* the chimes are followed with captions off too: a platform that turns
     * them on after its first step (its sound opens then) shows the
     * level's first chime from its next frame */
    int sound = v->state != HOL_APP_IDLE && v->sound != HOL_SOUND_OFF;
    if (in && sound && !v->paused) {
        int id = -1;
        if (app->ev.level_started)
            id = HOL_S_CAP_START;
        else if (v->state == HOL_APP_DONE && app->cap_state == HOL_APP_PLAYING && !h->timed_out)
            id = h->keys_total > 0 ? HOL_S_CAP_CHEST : HOL_S_CAP_FLAG;
        else if (h->keys_held > app->cap_keys)
            id = HOL_S_CAP_KEY;
        if (id >= 0)
            app->cap_id = id, app->cap_until = in->time_s + HOL_APP_CAPTION_S;
    }
    if (in)
        app->cap_keys = h->keys_held, app->cap_state = v->state;
    h->caption[0] = 0;
    if (!sound || !app->captions)
        return;
    if (app->cap_id >= 0 && in && in->time_s < app->cap_until)
        HOL__PUT(h->caption, hol__lang(app), (hol_str_id)app->cap_id);
    else if (v->state == HOL_APP_PLAYING && (v->map.cues & HOL_CUE_SOUND) && v->map.nobjectives)
        HOL__PUT(h->caption, hol__lang(app), HOL_S_CAP_BEACON);
    if (h->caption[0] && h->nlines < HOL_APP_HUD_LINES)
        snprintf(h->lines[h->nlines++], HOL_APP_TEXT_MAX, "%s", h->caption);
}

/* Outside the room: the way back in (hol_app_outside), and its events
 * (from records of platforms that show it: HOL_INPUT_WAY_BACK). */
static void hol__fill_outside(hol_app *app, const hol_input *in)
{
    hol_app_view *v = &app->view;
    hol_app_outside *o = &v->outside;
    if (!in)
        return;
    double m = app->mo.d.cell_m, w = hol_room_cols(&v->user) * m, d = hol_room_rows(&v->user) * m;
    const float *h = in->head.pos;
    double ox = h[0] < 0 ? -h[0] : h[0] > w ? h[0] - w : 0;
    double oz = h[2] < 0 ? -h[2] : h[2] > d ? h[2] - d : 0;
    int on = (in->flags & HOL_INPUT_HEAD_VALID) && (ox > 0 || oz > 0);
    memset(o, 0, sizeof *o);
    if (on) {
        o->on = 1;
        o->dist_m = sqrt(ox * ox + oz * oz);
        o->col = v->user.col;
        o->row = v->user.row;
        double cx = (o->col + 0.5) * m, cz = (o->row + 0.5) * m, y = v->yaw_deg * HOL__PI / 180;
        double ax = v->head[0] - HOL_APP_ARROW_AHEAD_M * hol_sin(y);
        double az = v->head[2] - HOL_APP_ARROW_AHEAD_M * hol_cos(y);
        o->arrow[0] = ax; /* in view wherever it lies: drawn over all */
        o->arrow[2] = az;
        /* forward at yaw y is (-sin y, 0, -cos y) */
        o->arrow_yaw_deg = hol_atan2(-(cx - h[0]), -(cz - h[2])) * 180 / HOL__PI;
    }
    if (!(in->flags & HOL_INPUT_WAY_BACK) || on == app->out)
        return;
    app->out = on;
    if (on) {
        app->ev.outside = 1;
        app->ev.outside_m = o->dist_m;
        app->out_t = in->time_s;
    } else {
        app->ev.inside = 1;
        app->ev.inside_s = in->time_s - app->out_t;
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
    hol__fill_outside(app, in);
    hol__fill_hud(app, in);
    hol__fill_map(app);
    hol__fill_lights(app);
    hol_body *b = &app->view.body;
    hol_body_from_input(in, app->view.state == HOL_APP_POINT, b);
    /* the minimap in the hand is what the left controller holds: drawn
     * instead of it (core/hol_body.h) */
    if (app->view.map.place == HOL_MINIMAP_HAND && b->hand[HOL_HAND_LEFT].kind == HOL_BODY_CONTROLLER)
        b->hand[HOL_HAND_LEFT].kind = HOL_BODY_NONE;
    hol__caption(app, in);
}
