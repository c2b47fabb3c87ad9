/* hol_app_impl.h - internals shared by the hol_app*.c files (not an API).
 *
 * Contract
 * - hol_app.c owns the app: create, levels, the step, motion, planning.
 *   It calls the tutorial (hol_app_tutorial.c: lessons, their targets and
 *   feedback, the search for lesson 2's steps left) and the view
 *   (hol_app_view.c: eyes, HUD text and prompts, minimap model, objects).
 *   Neither of those calls back into hol_app.c, nor each other: the view
 *   only reads the state.
 */
#ifndef HOL_APP_IMPL_H
#define HOL_APP_IMPL_H

#include "hol_app.h"
#include "hol_nav.h"

/* "Minimap fixed in this study" stays on the HUD this long (input clock,
 * seconds: it shows on a paused or finished level too). */
#define HOL__FIXED_S 3.0
#define HOL__FIXED_TEXT "Minimap fixed in this study"
/* Tutorial feedback stays on the HUD this long (level clock, seconds). */
#define HOL__FEEDBACK_S 6.0

/* Navigators the app keeps, one per (tiling, room size): a bounded cache
 * (hol_app.h, hol_app_prepare). */
typedef struct hol__app_nav {
    hol_nav *nav;        /* NULL: a free slot */
    int own;             /* created by the app (else desc.nav) */
    int q, cols, rows;
    uint64_t used;       /* the last level start that took it */
} hol__app_nav;

struct hol_app {
    hol_app_desc d;
    hol_nav *nav;        /* the level's navigator (one of navs) */
    hol__app_nav navs[HOL_APP_MAX_NAVS];
    uint64_t starts;     /* level starts so far (the cache's clock) */
    void *world_mem;
    size_t world_size;
    hol_world *world;
    hol_app_level level;
    int have_level;
    hol_room start_room;
    hol_motion mo;
    hol_app_view view;
    hol_app_events ev;
    hol_input prev;
    int have_prev;
    hol_haptic_state haptic; /* the hands' contacts (core/hol_haptic.h) */
    int menu;
    int pending_start;
    int debug;           /* the HUD's debug text (HOL_BTN_DEBUG toggles) */
    uint32_t device;     /* HOL_DEVICE_* of the last record: the prompts' words */
    /* the game */
    int done;
    unsigned keys_held; /* bit per key */
    int timed_out;      /* the end screen is the time limit's */
    int steps, optimum, remaining;
    double level_t;
    double next_sample; /* index of the next 10 Hz head sample (whole; no cast) */
    /* the tutorial */
    int stage;               /* 0..HOL_APP_TUTORIAL_STAGES-1 */
    hol_room stage_start;
    int stage_steps;
    int stage_optimum;       /* the lesson's fewest steps from its start */
    int has_target;          /* the stage has a target tile */
    hol_tile target;
    char feedback[HOL_APP_TEXT_MAX]; /* the last lesson done says so */
    double feedback_until;   /* level time the feedback shows until */
    int fixed_shown;         /* "Minimap fixed" was asked for ... */
    double fixed_until;      /* ... and shows until this input time */
    int path_told;           /* the path cue's meaning said (tutorial) */
    int nmarks;              /* tiles marked on the minimap with it */
    hol_tile marks[HOL_APP_MAX_MARKS];
    uint8_t walk[HOL_NAV_WALK_MAX]; /* replan scratch */
    int nwalk;
};

/* hol_app_tutorial.c */
int hol__next_stage(const hol_app *app, int k);
void hol__stage(hol_app *app, int k, const hol_room *r);
/* A room step of a tutorial entered r: the lesson done (feedback, marks,
 * the next lesson or the level's end). */
void hol__tutorial_enter(hol_app *app, const hol_room *r);
/* Lesson 2's fewest steps left from r (the lesson's steps so far in
 * app->stage_steps): back in the lesson's start cell on another tile, after
 * at least 4 steps, inside the room; the walk in out_walk (cap bytes).
 * -1 when none within HOL__LOOP_MAX steps (never in a 3 x 3 room). */
#define HOL__LOOP_MAX 12
int hol__loop_left(const hol_app *app, const hol_room *r, uint8_t *out_walk, int cap);

/* hol_app_view.c */
void hol__fill_view(hol_app *app, const hol_input *in);
void hol__yaw_pitch_from_quat(const float qf[4], double *yaw, double *pitch);

#endif
