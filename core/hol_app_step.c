/* hol_app_step.c - the app: create, levels, the step, motion, planning
 * (see hol_app.h; the app's files: hol_app_impl.h). */
#include "hol_app.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_input_io.h"
#include "hol_world.h"

#define HOL__SUBSTEP (1.0 / 60) /* longest pancake motion sub-step, seconds */
#define HOL__STALL_S 0.5        /* a longer frame is a stall: no motion */

/* Seen tiles the app's world remembers after eviction: 6 MB, hours of play. */
#define HOL__APP_KEEP (1u << 18)

static hol_world_desc hol__world_desc(const hol_app *app, uint64_t seed, int q)
{
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = seed;
    wd.capacity = app->d.world_capacity;
    wd.keep_capacity = HOL__APP_KEEP;
    wd.tiling_q = q;
    return wd;
}

/* The level's geometry with the defaults filled in. */
static void hol__geometry(const hol_app_level *L, int *q, int *cols, int *rows, double *cell)
{
    *q = L->tiling_q ? L->tiling_q : HOL_TILING_DEFAULT_Q;
    *cols = L->room_cols ? L->room_cols : HOL_ROOM_SIZE;
    *rows = L->room_rows ? L->room_rows : HOL_ROOM_SIZE;
    *cell = L->cell_m > 0 ? L->cell_m : 1.0;
}

/* The navigator slot of (q, cols, rows), or -1. */
static int hol__nav_slot(const hol_app *app, int q, int cols, int rows)
{
    for (int i = 0; i < HOL_APP_MAX_NAVS; i++) {
        const hol__app_nav *n = &app->navs[i];
        if (n->nav && n->q == q && n->cols == cols && n->rows == rows)
            return i;
    }
    return -1;
}

static hol_err hol__nav_make(hol_app *app, int q, int cols, int rows, int *out_slot)
{
    int k = hol__nav_slot(app, q, cols, rows);
    if (k >= 0) {
        *out_slot = k;
        return HOL_OK;
    }
    /* a free slot, else the app's own least recently started one that
     * the level in play does not use */
    for (int i = 0; i < HOL_APP_MAX_NAVS; i++) {
        const hol__app_nav *n = &app->navs[i];
        if (!n->nav) {
            k = i;
            break;
        }
        if (n->own && n->nav != app->nav && (k < 0 || n->used < app->navs[k].used))
            k = i;
    }
    if (k < 0)
        return HOL_ENOMEM;
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    nd.alloc_fn = app->d.alloc.alloc;
    nd.free_fn = app->d.alloc.free;
    nd.user = app->d.alloc.user;
    nd.tiling_q = q;
    nd.room_cols = cols;
    nd.room_rows = rows;
    nd.lazy = app->d.lazy_nav;
    hol_nav *nav;
    hol_err err = hol_nav_create(&nd, &nav);
    if (err)
        return err;
    if (!app->d.lazy_nav)
        hol_nav_prepare_tours(nav); /* levels never pay for the leg table */
    if (app->navs[k].nav)
        hol_nav_destroy(app->navs[k].nav);
    app->navs[k] = (hol__app_nav){nav, 1, q, cols, rows, app->starts};
    *out_slot = k;
    return HOL_OK;
}

hol_err hol_app_prepare(hol_app *app, int q, int cols, int rows)
{
    hol_room r;
    if (!app || hol_room_start_in(q, cols, rows, &r))
        return HOL_EARG;
    int k;
    return hol__nav_make(app, q ? q : HOL_TILING_DEFAULT_Q, cols ? cols : HOL_ROOM_SIZE,
                         rows ? rows : HOL_ROOM_SIZE, &k);
}

/* The world store holds a world of any tiling (the most curved is the
 * largest). */
static size_t hol__world_size(const hol_app_desc *d)
{
    size_t most = 0;
    for (int q = HOL_TILING_MIN_Q; q <= HOL_TILING_MAX_Q; q++) {
        hol_world_desc wd;
        memset(&wd, 0, sizeof wd);
        wd.capacity = d->world_capacity;
        wd.keep_capacity = HOL__APP_KEEP;
        wd.tiling_q = q;
        size_t n = hol_world_mem_size(&wd);
        if (!n)
            return 0;
        most = n > most ? n : most;
    }
    return most;
}

hol_err hol_app_create(const hol_app_desc *desc, hol_app **out_app)
{
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    if (desc)
        d = *desc;
    if (!out_app || (!d.alloc.alloc != !d.alloc.free) || d.stray_steps < 0 ||
        !(d.ipd >= 0 && d.ipd <= 0.5))
        return HOL_EARG;
    if (!d.world_capacity)
        d.world_capacity = 1u << 16;
    if (!d.stray_steps)
        d.stray_steps = 3;
    if (!(d.ipd > 0))
        d.ipd = 0.064;
    hol_world_desc wd = {0};
    wd.capacity = d.world_capacity;
    wd.keep_capacity = HOL__APP_KEEP;
    size_t wsize = hol__world_size(&d);
    if (!wsize)
        return HOL_EARG;
    size_t head = (sizeof(hol_app) + 63) & ~(size_t)63;
    /* lazy: zero pages (calloc maps them when first written), not cleared */
    int zeroed = d.lazy_world && !(d.alloc.alloc && d.alloc.free);
    uint8_t *mem = zeroed ? calloc(1, head + wsize + 64)
                          : hol_alloc_mem(&d.alloc, head + wsize + 64);
    if (!mem)
        return HOL_ENOMEM;
    hol_app *app = (hol_app *)(void *)mem;
    memset(app, 0, sizeof *app);
    app->d = d;
    app->cap_id = -1;
    uintptr_t w = ((uintptr_t)(mem + head) + 63) & ~(uintptr_t)63;
    app->world_mem = (void *)w;
    app->world_size = wsize;
    wd.mem_zeroed = zeroed;
    hol_err err = hol_world_init(app->world_mem, wsize, &wd, &app->world);
    int slot = 0;
    if (!err && d.nav) {
        hol__app_nav *n = &app->navs[0];
        n->nav = d.nav;
        hol_nav_geometry(d.nav, &n->q, &n->cols, &n->rows);
        if (!d.lazy_nav)
            hol_nav_prepare_tours(d.nav);
    } else if (!err) {
        err = hol__nav_make(app, HOL_TILING_DEFAULT_Q, HOL_ROOM_SIZE, HOL_ROOM_SIZE, &slot);
    }
    if (err) {
        hol_alloc_release(&d.alloc, mem);
        return err;
    }
    app->nav = app->navs[slot].nav;
    app->start_room = hol_room_start();
    hol_motion_init(&app->mo, &app->start_room, &d.motion);
    app->view.cell_m = app->mo.d.cell_m;
    app->optimum = app->remaining = -1;
    *out_app = app;
    return HOL_OK;
}

void hol_app_destroy(hol_app *app)
{
    if (!app)
        return;
    for (int i = 0; i < HOL_APP_MAX_NAVS; i++)
        if (app->navs[i].own)
            hol_nav_destroy(app->navs[i].nav);
    hol_app_desc d = app->d;
    hol_alloc_release(&d.alloc, app);
}

const hol_app_view *hol_app_get_view(const hol_app *app)
{
    return &app->view;
}

const hol_app_events *hol_app_get_events(const hol_app *app)
{
    return &app->ev;
}

int hol_app_walk(const hol_app *app, uint8_t *out, int cap)
{
    if (!app || !app->have_level || app->done || app->nwalk <= 0 || cap <= 0)
        return 0;
    int n = app->nwalk < cap ? app->nwalk : cap;
    memcpy(out, app->walk, (size_t)n);
    return n;
}

hol_world *hol_app_world(hol_app *app)
{
    return app->world;
}

void hol_app_set_captions(hol_app *app, int on)
{
    if (app)
        app->captions = on != 0;
}

void hol_app_set_lang(hol_app *app, int lang)
{
    if (app)
        app->d.lang = lang;
}

/* ---- the game ------------------------------------------------------------ */

/* Optimal steps left from room r (the walk in app->walk), or -1. *exact
 * receives whether the navigator proved it. */
static hol_err hol__plan(hol_app *app, const hol_room *r, int *out_len, int *exact)
{
    hol_nav_result res;
    hol_err err = HOL_OK;
    const hol_app_level *L = &app->level;
    *exact = 1;
    if (L->mode == HOL_APP_FLAG || (L->mode == HOL_APP_TUTORIAL && app->has_target)) {
        hol_tile goal = L->mode == HOL_APP_FLAG ? L->flag : app->target;
        err = hol_nav_find(app->nav, r, goal, 0, app->walk, sizeof app->walk, &res);
    } else if (L->mode == HOL_APP_TUTORIAL) {
        *out_len = app->nwalk = hol__loop_left(app, r, app->walk, (int)sizeof app->walk);
        if (app->nwalk < 0)
            app->nwalk = 0;
        return HOL_OK;
    } else if (L->mode == HOL_APP_KEYS) {
        hol_tile left[HOL_APP_MAX_KEYS];
        int n = 0;
        for (int k = 0; k < L->nkeys; k++)
            if (!(app->keys_held >> k & 1))
                left[n++] = L->keys[k];
        err = hol_nav_tour(app->nav, r, left, n, L->chest, 0, app->walk, sizeof app->walk,
                           &res);
    } else {
        *out_len = -1;
        app->nwalk = 0;
        return HOL_OK;
    }
    if (err)
        return err;
    *out_len = res.len;
    *exact = res.exact;
    app->nwalk = res.len;
    return HOL_OK;
}

/* A room step entered r: collect what lies there. */
static void hol__enter(hol_app *app, const hol_room *r)
{
    const hol_app_level *L = &app->level;
    if (L->mode == HOL_APP_TUTORIAL)
        hol__tutorial_enter(app, r);
    if (L->mode == HOL_APP_EXPLORE && app->route_k < L->nroute &&
        hol_tile_eq(r->tile, app->route_tiles[app->route_k])) {
        hol_tile placed; /* the next marker on a free tile, as the tutorial's */
        if (++app->route_k == L->nroute)
            app->done = 1;
        else
            (void)hol_world_reserve(app->world, app->route_tiles[app->route_k], 0, HOL_OBJ_FLAG,
                                    &placed);
    }
    if (L->mode == HOL_APP_FLAG && hol_tile_eq(r->tile, L->flag))
        app->done = 1;
    if (L->mode == HOL_APP_KEYS) {
        for (int k = 0; k < L->nkeys; k++)
            if (hol_tile_eq(r->tile, L->keys[k]) && !(app->keys_held >> k & 1)) {
                app->keys_held |= 1u << k;
                /* a collected key leaves the world */
                (void)hol_world_release(app->world, L->keys[k]);
            }
        if (app->keys_held == (1u << L->nkeys) - 1 && hol_tile_eq(r->tile, L->chest))
            app->done = 1;
    }
}

static void hol__summary(hol_app *app, hol_app_end end)
{
    hol_app_summary *s = &app->ev.summary;
    s->mode = app->level.mode;
    s->seed = app->level.seed;
    s->steps = app->steps;
    s->optimum = app->optimum;
    s->time_s = app->level_t;
    s->end = end;
    app->ev.level_ended = end;
}

/* A lesson's route from r: its tiles (a step leaving the room is a bad
 * level), the first marker reserved. */
static hol_err hol__route_begin(hol_app *app, const hol_room *r)
{
    const hol_app_level *L = &app->level;
    hol_room at = *r;
    app->route_k = 0;
    if (L->nroute < 0 || L->nroute > HOL_APP_ROUTE_MAX || (L->nroute && L->mode != HOL_APP_EXPLORE))
        return HOL_EARG;
    for (int i = 0; i < L->nroute; i++) {
        if (hol_room_step(&at, L->route[i]))
            return HOL_EARG;
        app->route_tiles[i] = at.tile;
    }
    hol_tile placed;
    if (L->nroute)
        (void)hol_world_reserve(app->world, app->route_tiles[0], 0, HOL_OBJ_FLAG, &placed);
    return HOL_OK;
}

static hol_err hol__begin(hol_app *app)
{
    const hol_app_level *L = &app->level;
    /* the objectives (several may share a tile) */
    hol_tile obj[HOL_APP_MAX_OBJECTIVES];
    hol_object kind[HOL_APP_MAX_OBJECTIVES];
    int nobj = 0;
    if (L->mode == HOL_APP_FLAG) {
        obj[nobj] = L->flag;
        kind[nobj++] = HOL_OBJ_FLAG;
    } else if (L->mode == HOL_APP_KEYS) {
        if (L->nkeys < 1 || L->nkeys > HOL_APP_MAX_KEYS)
            return HOL_EARG;
        for (int k = 0; k < L->nkeys; k++) {
            obj[nobj] = L->keys[k];
            kind[nobj++] = HOL_OBJ_KEY;
        }
        obj[nobj] = L->chest;
        kind[nobj++] = HOL_OBJ_CHEST;
    }
    /* the world: the designer's placements, and a clearing on each
     * objective's tile before generation, so every objective stands on a
     * free tile (no rock, log, creek or pond under it) wherever it is */
    hol_world_place places[HOL_WORLD_MAX_PLACES];
    int np = L->nplaces;
    memcpy(places, L->places, (size_t)np * sizeof places[0]);
    int first[HOL_APP_MAX_OBJECTIVES]; /* the objective's tile is new here */
    for (int i = 0; i < nobj; i++) {
        first[i] = 1;
        for (int j = 0; j < i; j++)
            if (hol_tile_eq(obj[j], obj[i]))
                first[i] = 0;
        for (int k = 0; k < L->nplaces; k++)
            if (hol_tile_eq(L->places[k].tile, obj[i]))
                return HOL_EARG; /* a placement on an objective */
        if (first[i])
            places[np++] = (hol_world_place){obj[i], HOL_OBJ_NONE};
    }
    int q, cols, rows;
    double cell;
    hol__geometry(L, &q, &cols, &rows, &cell);
    hol_world_desc wd = hol__world_desc(app, L->seed, q);
    wd.places = places;
    wd.nplaces = (uint32_t)np;
    /* the store cleared only if it holds tiles (not before the first level) */
    hol_err err = hol_world_reinit(app->world_mem, app->world_size, &wd, &app->world);
    if (err)
        return err;
    hol_room r;
    if ((err = hol_room_start_in(q, cols, rows, &r)))
        return err;
    if ((err = hol_world_update(app->world, &r)))
        return err;
    for (int i = 0; i < L->nstart; i++) {
        err = hol_room_step(&r, L->start[i]);
        if (err)
            return err == HOL_EROOM ? HOL_EARG : err;
        if ((err = hol_world_update(app->world, &r)))
            return err;
    }
    app->start_room = r;
    /* objectives: never on the start tile; reserved in the world (their
     * tiles are clearings, so this cannot find them taken) */
    for (int i = 0; i < nobj; i++) {
        if (hol_tile_eq(obj[i], r.tile))
            return HOL_EARG;
        hol_tile placed;
        if (first[i] && (err = hol_world_reserve(app->world, obj[i], 0, kind[i], &placed)))
            return err;
    }
    app->done = 0;
    app->keys_held = 0;
    app->has_target = 0;
    app->feedback[0] = 0;
    app->feedback_until = 0;
    app->path_told = 0;
    app->rings_told = 0;
    app->rings_note = 0;
    app->has_tree = 0;
    app->nmarks = 0;
    app->face_pending = 0;
    app->stage_t0 = 0;
    app->mo.yaw_deg = 0; /* the look a level begins with (hol_motion_init's) */
    if ((err = hol__route_begin(app, &r)))
        return err;
    if (L->mode == HOL_APP_TUTORIAL)
        hol__stage(app, hol__next_stage(app, 0), &r);
    hol__point_begin(app);
    app->timed_out = 0;
    app->steps = 0;
    app->level_t = 0;
    app->next_sample = 0;
    app->menu = 0;
    int exact = 1;
    if ((err = hol__plan(app, &r, &app->optimum, &exact)))
        return err;
    if (!exact)
        return HOL_EBUDGET;
    app->remaining = app->optimum;
    if (L->mode == HOL_APP_TUTORIAL) {
        app->stage_optimum = app->optimum; /* the first lesson's */
        app->optimum = -1; /* the level is not scored */
    }
    hol_motion_desc md = app->d.motion;
    md.cell_m = cell;
    hol_motion_init(&app->mo, &r, &md);
    app->view.cell_m = app->mo.d.cell_m;
    app->pending_start = 1;
    app->view.state = HOL_APP_PLAYING;
    app->view.paused = 0;
    hol__fill_view(app, NULL);
    return HOL_OK;
}

hol_err hol_app_start_level(hol_app *app, const hol_app_level *level)
{
    if (!level || level->mode < 0 || level->mode > HOL_APP_TUTORIAL || level->nstart < 0 ||
        level->nstart > (int)sizeof level->start || level->nplaces < 0 ||
        level->nplaces > HOL_APP_MAX_PLACES || level->minimap < 0 ||
        level->minimap > HOL_MINIMAP_OFF)
        return HOL_EARG;
    int q, cols, rows, slot;
    double cell;
    hol_room r;
    hol__geometry(level, &q, &cols, &rows, &cell);
    if (hol_room_start_in(q, cols, rows, &r) || !(cell >= HOL_MOTION_MIN_CELL) ||
        !(cell <= HOL_MOTION_MAX_CELL))
        return HOL_EARG;
    app->have_level = 0;
    app->nav = NULL; /* the cache may replace the previous level's */
    app->starts++;
    hol_err err = hol__nav_make(app, q, cols, rows, &slot);
    if (err)
        return err;
    app->nav = app->navs[slot].nav;
    app->navs[slot].used = app->starts;
    app->level = *level;
    app->have_level = 1;
    app->view.map.place = level->minimap;
    app->screen = HOL_APP_SCREEN_NONE;
    err = hol__begin(app);
    if (err) {
        app->have_level = 0;
        return err;
    }
    app->ask_before = 0;
    app->ready_after = 0;
    if (hol__ask_before_start(app)) { /* a baseline: its instructions after */
        hol__fill_view(app, NULL);
    } else if (level->instructions[0]) { /* the level begins after them */
        app->screen = HOL_APP_SCREEN_INSTRUCTIONS;
        app->view.state = HOL_APP_SCREEN;
        app->place_panel = 1;
        hol__fill_view(app, NULL);
    }
    return HOL_OK;
}

hol_err hol_app_ready(hol_app *app)
{
    if (!app->have_level)
        return HOL_EARG;
    if (app->view.state == HOL_APP_ASK && app->ask_before) {
        app->ready_after = 1; /* the baseline first: the ready screen after it */
    } else if (app->screen != HOL_APP_SCREEN_INSTRUCTIONS) {
        app->screen = HOL_APP_SCREEN_READY;
        app->view.state = HOL_APP_SCREEN;
        app->place_panel = 1;
        hol__fill_view(app, NULL);
    }
    return HOL_OK;
}

/* ---- the step ------------------------------------------------------------ */

/* The room steps of one motion, st->n of them, taken at level time t. */
static hol_err hol__room_steps(hol_app *app, const hol_motion_steps *st, double t)
{
    for (int i = 0; i < st->n; i++) {
        hol_err err = hol_world_update(app->world, &st->after[i]);
        if (err)
            return err;
        if (app->done)
            continue;
        app->steps++;
        hol__point_step(app, st->dir[i]);
        int stage = app->stage;
        hol_app_lesson lesson = {stage + 1, app->stage_t0, t, app->stage_steps + 1,
                                 app->stage_optimum};
        hol__enter(app, &st->after[i]);
        int exact;
        if (app->done) {
            app->remaining = 0;
            app->nwalk = 0;
        } else if ((app->optimum >= 0 || app->level.mode == HOL_APP_TUTORIAL) &&
                   !hol__plan(app, &st->after[i], &app->remaining, &exact)) {
            /* remaining and the walk are set */
        }
        if (app->level.mode == HOL_APP_TUTORIAL && (app->stage != stage || app->done))
            hol__lesson_done(app, stage, lesson, t);
        hol_app_step_event *e = &app->ev.steps[app->ev.nsteps++];
        e->t = t;
        e->index = app->steps;
        e->dir = st->dir[i];
        e->room = st->after[i];
        e->yaw_deg = app->mo.yaw_deg;
        e->remaining = app->remaining;
        e->cues = app->level.cues;
    }
    return HOL_OK;
}

/* The room was placed anew around the head (a recentre, a re-basing): the
 * pointing walk, the world and the guidance follow the new room state. */
static hol_err hol__replaced(hol_app *app)
{
    hol__point_sync(app);
    hol_err err = hol_world_update(app->world, &app->mo.user);
    int exact;
    if (!err && !app->done && (app->optimum >= 0 || app->level.mode == HOL_APP_TUTORIAL))
        (void)hol__plan(app, &app->mo.user, &app->remaining, &exact);
    return err;
}

/* A recentre (HOL_BTN_RECENTRE, or the runtime's HOL_INPUT_RECENTRED) with
 * a tracked head: the room is placed anew around the head with no room
 * step (hol_motion_replace); the world and the guidance follow the new
 * room state. */
static hol_err hol__replace(hol_app *app, const hol_input *in)
{
    double pos[3] = {in->head.pos[0], in->head.pos[1], in->head.pos[2]};
    double yaw_was = app->mo.yaw_deg;
    hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    hol_motion_replace(&app->mo, pos, yaw_was);
    return hol__replaced(app);
}

/* 1 when the record's head may walk (hol_input.h): not a headset's, or a
 * worn, focused headset with a tracked position. */
static int hol__may_walk(const hol_input *in)
{
    const uint32_t want = HOL_INPUT_HEAD_VALID | HOL_INPUT_FOCUSED;
    const uint32_t mask = want | HOL_INPUT_HEADSET_OFF | HOL_INPUT_POS_EMULATED;
    return !(in->flags & HOL_INPUT_HEADSET) || (in->flags & mask) == want;
}

/* 1 when the record pauses the game: no focus (a system menu, the window
 * in the background), the controller gone, the headset off. */
static int hol__unfocused(const hol_input *in)
{
    return !(in->flags & HOL_INPUT_FOCUSED) ||
           (in->flags & (HOL_INPUT_DEVICE_LOST | HOL_INPUT_HEADSET_OFF));
}

/* The first record that may walk after one that might not (app->rebase):
 * the room is re-based around the head with no room step and no turn (the
 * tile kept, the cell the head's); another cell than the user's is the
 * `relocated` event, with the head's floor distance from where it last
 * walked. A head still in the user's cell changes nothing a walk there
 * would not. */
static hol_err hol__relocate(hol_app *app, const hol_input *in)
{
    double pos[3] = {in->head.pos[0], in->head.pos[1], in->head.pos[2]};
    double dx = pos[0] - app->mo.head[0], dz = pos[2] - app->mo.head[2];
    hol_room was = app->mo.user;
    app->rebase = 0;
    hol_motion_replace(&app->mo, pos, app->mo.yaw_deg);
    if (was.col == app->mo.user.col && was.row == app->mo.user.row)
        return HOL_OK;
    app->ev.relocated = 1;
    app->ev.relocated_m = sqrt(dx * dx + dz * dz);
    app->place_panel = 1;
    return hol__replaced(app);
}

/* A level begins where a tracked head stands: at the level's first frame
 * (a start or a restart) the room is placed around the head as a recentre
 * places it, with no turn (the look is the head's own), so a player who is
 * not in the start cell takes no room step by standing still; the tile is
 * the level's start tile, the cell the head's, and the optimum (a lesson's,
 * in the tutorial) is planned from there. A head in the start cell changes
 * nothing but its place in the cell. */
static hol_err hol__place_at_start(hol_app *app, const hol_input *in)
{
    double pos[3] = {in->head.pos[0], in->head.pos[1], in->head.pos[2]};
    hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    hol_room was = app->mo.user;
    hol_motion_replace(&app->mo, pos, app->mo.yaw_deg);
    hol__point_sync(app);
    int moved = was.col != app->mo.user.col || was.row != app->mo.user.row;
    /* the lesson begun again where the head stands (the loop: back to
     * this cell) and, but with desc.flow_v4, looks (issue 35) */
    int again = app->level.mode == HOL_APP_TUTORIAL &&
                (app->d.flow_v4 ? moved && !app->has_target : 1);
    if (!moved && !again)
        return HOL_OK;
    hol_err err = moved ? hol_world_update(app->world, &app->mo.user) : HOL_OK;
    if (!err && again) {
        if (app->has_target)
            (void)hol_world_release(app->world, app->target);
        hol__stage(app, app->stage, &app->mo.user);
    }
    int exact = 1, opt = -1;
    if (err || (err = hol__plan(app, &app->mo.user, &opt, &exact)))
        return err;
    if (!exact)
        return HOL_EBUDGET;
    app->remaining = opt;
    if (app->level.mode == HOL_APP_TUTORIAL)
        app->stage_optimum = opt;
    else
        app->optimum = opt;
    return HOL_OK;
}

/* The room placed around a tracked head in this step: at a level's first
 * frame, and by a recentre (the button's edge, the runtime's flag). Placed
 * where a head that may walk stands, nothing is left to re-base. */
static hol_err hol__place(hol_app *app, const hol_input *in, uint32_t pressed)
{
    hol_err err;
    if (!(in->flags & HOL_INPUT_HEAD_VALID) || (in->flags & HOL_INPUT_SEATED))
        return HOL_OK; /* seated: the head's position places nothing */
    int start = app->ev.level_started;
    if (start && (err = hol__place_at_start(app, in)))
        return err;
    int re = (pressed & HOL_BTN_RECENTRE) || (in->flags & HOL_INPUT_RECENTRED);
    if (re && (err = hol__replace(app, in)))
        return err;
    if ((start || re) && hol__may_walk(in))
        app->rebase = 0;
    return HOL_OK;
}

/* Seated play (hol_input.h): the look follows a tracked head or the
 * pancake's turn axes and snap turns, the head's position walks nothing,
 * and the first step button pressed (app->seat_edges) moves the head from
 * its cell's centre to the centre of the neighbouring cell in the room
 * direction nearest the look's: one cell edge crossed, the room step a
 * walk across it takes. A step into the hedge is not taken. */
static hol_err hol__seated_move(hol_app *app, const hol_input *in, double t, double dt)
{
    /* the room directions in yaw order (yaw 0 north, 90 west): dx, dz */
    static const int d[4][2] = {{0, -1}, {-1, 0}, {0, 1}, {1, 0}};
    static const uint32_t btn[4] = {HOL_BTN_STEP_FWD, HOL_BTN_STEP_LEFT, HOL_BTN_STEP_BACK,
                                    HOL_BTN_STEP_RIGHT};
    static const int order[4] = {0, 2, 1, 3}; /* ahead, back, left, right */
    hol_motion_steps st;
    if (in->flags & HOL_INPUT_HEAD_VALID) {
        hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    } else {
        static const float still[2] = {0, 0};
        if (in->flags & HOL_INPUT_SNAP_YAW)
            app->mo.yaw_deg = in->snap_yaw_deg;
        hol_err err = dt > HOL__STALL_S ? HOL_OK
                                        : hol_motion_pancake(&app->mo, still, in->turn, dt, &st);
        if (err && err != HOL_ERANGE)
            return err;
    }
    uint32_t edges = app->seat_edges;
    app->seat_edges = 0;
    double yaw = fmod(app->mo.yaw_deg, 360.0);
    int k = (int)floor((yaw < 0 ? yaw + 360 : yaw) / 90 + 0.5) & 3; /* the look's quarter */
    for (int i = 0; i < 4; i++) {
        int rel = order[i], dir = (k + rel) & 3;
        if (!(edges & btn[rel]))
            continue;
        double m = app->mo.d.cell_m;
        int c = app->mo.user.col + d[dir][0], r = app->mo.user.row + d[dir][1];
        if (c < 0 || r < 0 || c >= hol_room_cols(&app->mo.user) ||
            r >= hol_room_rows(&app->mo.user))
            return HOL_OK; /* the hedge */
        double pos[3] = {(c + 0.5) * m, app->mo.head[1], (r + 0.5) * m};
        hol_err err = hol_motion_move_to(&app->mo, pos, &st);
        if (err && err != HOL_ERANGE)
            return err;
        app->seat_step_t = in->time_s;
        app->seat_stepped = 1;
        return hol__room_steps(app, &st, t);
    }
    return HOL_OK;
}

/* The user's motion over a frame of dt seconds that began at level time
 * t0: a tracked head moves to its pose; the pancake axes are integrated in
 * sub-steps of at most HOL__SUBSTEP, so the distance walked and the angle
 * turned are the same at any frame rate; a frame longer than HOL__STALL_S
 * (a stall) does not move the user. Room steps are taken as they come. */
static hol_err hol__move(hol_app *app, const hol_input *in, double t0, double dt)
{
    hol_motion_steps st;
    hol_err err;
    if (in->flags & HOL_INPUT_SEATED)
        return hol__seated_move(app, in, t0 + dt, dt);
    if (in->flags & HOL_INPUT_HEAD_VALID) {
        double pos[3] = {in->head.pos[0], in->head.pos[1], in->head.pos[2]};
        hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
        app->face_pending = 0; /* a head is turned by the player alone */
        if (!hol__may_walk(in)) /* the look follows; the head walks nothing */
            return HOL_OK;
        if (app->rebase)
            return hol__relocate(app, in);
        err = hol_motion_move_to(&app->mo, pos, &st);
        if (err && err != HOL_ERANGE)
            return err;
        return hol__room_steps(app, &st, t0 + dt);
    }
    if (in->flags & HOL_INPUT_SNAP_YAW)
        app->mo.yaw_deg = in->snap_yaw_deg;
    /* a lesson began: face what it names, once the walk keys are let go
     * (a key still held from the last lesson's step would walk on along
     * the new look) */
    if (app->face_pending && in->move[0] == 0 && in->move[1] == 0) {
        app->mo.yaw_deg = app->face_yaw;
        app->face_pending = 0;
    }
    if (dt > HOL__STALL_S)
        return HOL_OK;
    int n = (int)ceil(dt / HOL__SUBSTEP - 1e-9);
    for (int i = 0; i < n; i++) {
        if (app->ev.nsteps + HOL_MOTION_MAX_STEPS > HOL_APP_MAX_STEP_EVENTS)
            break; /* cannot happen below the stall limit; the events are full */
        err = hol_motion_pancake(&app->mo, in->move, in->turn, dt / n, &st);
        if (err && err != HOL_ERANGE)
            return err;
        if ((err = hol__room_steps(app, &st, t0 + dt * (i + 1) / n)))
            return err;
    }
    return HOL_OK;
}

/* A frame of a screen of text (state HOL_APP_SCREEN): quit quits, confirm
 * goes on (the instructions: the ready screen, or with desc.flow_v4 the
 * level; the ready screen: the level begins at the next frame, its minimap
 * shown; the closing screen: the
 * session ends); nothing else acts. */
static void hol__screen_frame(hol_app *app, const hol_input *in, uint32_t pressed)
{
    hol_app_view *v = &app->view;
    app->device = in->device;
    v->paused = hol__unfocused(in);
    if (pressed & HOL_BTN_DEBUG)
        app->debug = !app->debug;
    if (pressed & HOL_BTN_QUIT) {
        v->state = HOL_APP_QUIT;
    } else if ((pressed & HOL_BTN_CONFIRM) && !v->paused) {
        if (app->screen == HOL_APP_SCREEN_CLOSING) {
            app->ev.next_level = 1;
        } else if (app->screen == HOL_APP_SCREEN_INSTRUCTIONS && !app->d.flow_v4 &&
                   !app->level.lesson) { /* a lesson has no clock to start (its walk line
                                          * is its instructions) */
            app->screen = HOL_APP_SCREEN_READY;
        } else {
            app->screen = HOL_APP_SCREEN_NONE;
            v->state = HOL_APP_PLAYING; /* pending_start: the next frame */
            v->map.place = app->level.minimap;
        }
    }
    if (in->flags & HOL_INPUT_HEAD_VALID) /* the look follows the head */
        hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    hol__fill_view(app, in);
}

/* A frame of a questionnaire's item (state HOL_APP_ASK): quit quits, else
 * hol_app_ask.c chooses and answers. */
static void hol__ask_step(hol_app *app, const hol_input *in, uint32_t pressed)
{
    hol_app_view *v = &app->view;
    app->device = in->device;
    v->paused = hol__unfocused(in);
    if (pressed & HOL_BTN_QUIT)
        v->state = HOL_APP_QUIT;
    else
        hol__ask_frame(app, in, pressed);
    hol__fill_view(app, in);
}

/* The level is over (done or time up): its pointing question, if it has
 * one, before the end screen. */
static void hol__level_over(hol_app *app, const hol_input *in)
{
    if (hol__point_can_ask(app)) {
        app->view.state = HOL_APP_POINT;
        app->asked_s = in->time_s;
    } else {
        app->view.state = HOL_APP_DONE;
    }
}

/* A frame of the pointing question: the user turns (a tracked head looks,
 * pancake turns without walking; the level clock stands) and confirms. */
static hol_err hol__point_frame(hol_app *app, const hol_input *in, uint32_t pressed, double dt)
{
    if (app->view.paused)
        return HOL_OK;
    app->seat_edges = 0; /* seated: no step while pointing */
    if (in->flags & HOL_INPUT_HEAD_VALID) {
        hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    } else {
        hol_input still = *in;
        still.move[0] = still.move[1] = 0;
        int nsteps = app->ev.nsteps;
        hol_err err = hol__move(app, &still, app->level_t, dt);
        app->ev.nsteps = nsteps; /* standing still: no room step */
        if (err)
            return err;
    }
    if (pressed & HOL_BTN_CONFIRM) {
        hol__point_answer(app, in);
        app->view.state = HOL_APP_DONE;
    }
    return HOL_OK;
}

hol_err hol_app_step(hol_app *app, const hol_input *in)
{
    if (!in || !hol_input_valid(in) || (app->have_prev && in->time_s < app->prev.time_s))
        return HOL_EARG;
    memset(&app->ev, 0, sizeof app->ev);
    double dt = app->have_prev ? in->time_s - app->prev.time_s : 0;
    /* edges: pressed since the previous record (taps between frames), or
     * held now and not then (records that predate `pressed`) */
    uint32_t pressed = in->pressed | (in->buttons & ~(app->have_prev ? app->prev.buttons : 0u));
    app->prev = *in;
    app->have_prev = 1;
    app->seat_edges = pressed & HOL_BTN_STEPS; /* seated: hol__seated_move */
    app->view.frame++;
    if (!hol__may_walk(in))
        app->rebase = 1;
    hol_app_view *v = &app->view;
    if (!app->have_level) {
        v->state = (pressed & HOL_BTN_QUIT) ? HOL_APP_QUIT : HOL_APP_IDLE;
        return HOL_OK;
    }
    if (v->state == HOL_APP_QUIT)
        return HOL_OK;
    if (v->state == HOL_APP_SCREEN) {
        hol__screen_frame(app, in, pressed);
        return HOL_OK;
    }
    if (v->state == HOL_APP_ASK) {
        hol__ask_step(app, in, pressed);
        return HOL_OK;
    }
    if (app->pending_start) {
        /* a level started between frames begins at this frame: the time
         * since the previous frame (another level, another play) is not
         * its time */
        app->pending_start = 0;
        app->ev.level_started = 1;
        v->state = HOL_APP_PLAYING;
        dt = 0;
    }
    hol_err err = HOL_OK;
    if (!app->device_seen || in->device != app->device)
        app->device_t = in->time_s; /* the menu's hint starts (hol_app.h) */
    app->device_seen = 1;
    app->device = in->device;
    if (app->menu && !(pressed & HOL_BTN_MENU)) {
        /* the menu: confirm restarts, back quits (menu resumes) */
        if (pressed & HOL_BTN_CONFIRM)
            pressed = (pressed & ~(uint32_t)HOL_BTN_CONFIRM) | HOL_BTN_RESTART;
        if (pressed & HOL_BTN_BACK)
            pressed |= HOL_BTN_QUIT;
    }
    if (pressed & HOL_BTN_DEBUG)
        app->debug = !app->debug;
    if (pressed & HOL_BTN_QUIT) {
        if (v->state == HOL_APP_PLAYING)
            hol__summary(app, HOL_APP_END_QUIT);
        v->state = HOL_APP_QUIT;
        hol__fill_view(app, in);
        return HOL_OK;
    }
    if (pressed & HOL_BTN_MENU) {
        app->menu = !app->menu;
        app->ev.hint = app->menu && v->state == HOL_APP_PLAYING &&
                       app->level.lesson == HOL_APP_HINT_LESSON;
    }
    if ((pressed & HOL_BTN_MINIMAP) && app->level.minimap_fixed) {
        app->ev.minimap_refused = 1; /* a condition's minimap holds */
        app->fixed_shown = 1;
        app->fixed_until = in->time_s + HOL__FIXED_S;
    } else if (pressed & HOL_BTN_MINIMAP) {
        v->map.place = (v->map.place + 1) % 3;
        app->ev.minimap_moved = 1;
    }
    int restarted = 0;
    if (pressed & HOL_BTN_RESTART) {
        restarted = 1;
        if (v->state == HOL_APP_PLAYING)
            hol__summary(app, HOL_APP_END_RESTART);
        if ((err = hol__begin(app)))
            return err;
        app->pending_start = 0;
        app->ev.level_started = 1;
        v->state = HOL_APP_PLAYING;
    }
    v->paused = hol__unfocused(in) || app->menu;
    if ((err = hol__place(app, in, pressed)))
        return err;
    if (v->state == HOL_APP_POINT && !restarted) {
        if ((err = hol__point_frame(app, in, pressed, dt)))
            return err;
    } else if (v->state == HOL_APP_DONE) {
        if ((pressed & HOL_BTN_CONFIRM) && !v->paused)
            hol__after_end(app, in, 0); /* questionnaires, closing, next */
    } else if (!v->paused && !restarted) {
        double t0 = app->level_t;
        app->level_t += dt;
        if ((err = hol__move(app, in, t0, dt)))
            return err;
        /* the 10 Hz head sample */
        if (app->level_t >= app->next_sample / 10.0) {
            app->ev.head_sample = 1;
            app->ev.head_sample_t = app->next_sample / 10.0;
            app->next_sample = floor(app->level_t * 10) + 1;
        }
        if (app->done) {
            hol__summary(app, HOL_APP_END_DONE);
            hol__level_over(app, in);
        } else if (app->level.time_limit_s > 0 && app->level_t >= app->level.time_limit_s) {
            app->timed_out = 1;
            hol__summary(app, HOL_APP_END_TIMEOUT);
            hol__level_over(app, in);
        }
    }
    hol_haptic_step(&app->haptic, in, hol_room_cols(&app->mo.user), hol_room_rows(&app->mo.user),
                    app->mo.d.cell_m, app->ev.nsteps, !app->d.no_haptics && !v->paused,
                    &app->ev.haptic);
    hol__fill_view(app, in);
    return HOL_OK;
}

hol_err hol_app_ask_from(hol_app *app, int item)
{
    hol_err err = hol__ask_begin_from(app, item);
    if (!err)
        hol__fill_view(app, NULL);
    return err;
}
