/* hol_app_impl.h - internals shared by the hol_app*.c files (not an API).
 *
 * Contract
 * - hol_app_step.c owns the app: create, levels, the step, motion,
 *   planning. It calls the tutorial (hol_app_tutorial.c: lessons, their
 *   targets and feedback, the search for lesson 2's steps left), the view
 *   (hol_app_view.c: eyes, HUD text and prompts, minimap model, objects),
 *   the questionnaires (hol_app_ask.c) and the pointing question
 *   (hol_app_point.c). None of those calls back into hol_app_step.c; the
 *   view calls the questionnaires' HUD lines, the questionnaires the
 *   pointing question, and all of them the lowest file, hol_app_geom.c
 *   (yaw and pitch of a quaternion, text wrapping), which calls none. The
 *   view only reads the state.
 */
#ifndef HOL_APP_IMPL_H
#define HOL_APP_IMPL_H

#include "hol_app.h"
#include "hol_bearing.h"
#include "hol_nav.h"

/* "Minimap fixed in this study" stays on the HUD this long (input clock,
 * seconds: it shows on a paused or finished level too). */
#define HOL__FIXED_S 3.0
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
    int out;             /* the head is outside the room (an event said so) */
    double out_t;        /* the input time it left */
    int rebase;          /* a headset record did not walk: the next that
                            may re-bases the room (hol_input.h) */
    int pending_start;
    uint32_t seat_edges; /* seated: the step buttons pressed this record */
    double seat_step_t;  /* seated: the time of the last step (the fade) */
    int seat_stepped;    /* seated: 1 once a step was taken */
    int debug;           /* the HUD's debug text (HOL_BTN_DEBUG toggles) */
    uint32_t device;     /* HOL_DEVICE_* of the last record: the prompts' words */
    double device_t;     /* the time the device in use became that device */
    int device_seen;     /* 1 once a record named a device */
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
    double stage_t0;         /* the level time it began */
    int face_pending;        /* a lesson began: a pancake view turns, once the
                              * walk axes are zero, ... */
    double face_yaw;         /* ... to this yaw, facing what it names */
    int has_target;          /* the stage has a target tile */
    hol_tile target;
    char feedback[HOL_APP_TEXT_MAX]; /* the last lesson done says so */
    double feedback_until;   /* level time the feedback shows until */
    int fixed_shown;         /* "Minimap fixed" was asked for ... */
    double fixed_until;      /* ... and shows until this input time */
    int path_told;           /* the path cue's meaning said (tutorial) */
    int rings_told;          /* the rings' meaning said (tutorial) ... */
    int rings_note;          /* ... with the marks now shown */
    int has_tree;            /* lesson 2 marks the tree on vertex ... */
    int tree[2];             /* ... (column, row of room vertices) */
    int nmarks;              /* tiles marked on the minimap with it */
    hol_tile marks[HOL_APP_MAX_MARKS];
    /* pointing (level.point): the level's walk as SPEC 8 counts it */
    hol_bearing_walk bw;
    int bw_ok;               /* bw follows the walk (else no question) */
    double asked_s;          /* input time the question was asked */
    /* screens (hol_app_level.instructions, .closing) */
    int screen;              /* hol_app_screen up (state HOL_APP_SCREEN) */
    int place_panel;         /* a screen came up: the panel goes ahead now */
    int ready_after;         /* hol_app_ready during the `before` asks: the
                                ready screen after them */
    /* questionnaires (hol_app_level.asks) */
    int ask_k, ask_i;        /* the ask and its item on screen (state ASK) */
    int ask_mark;            /* the mark chosen (0 .. marks - 1) */
    int ask_axis;            /* the left/right axis's side at the last record */
    double ask_t0;           /* input time the item came up */
    double ask_ref_yaw;      /* the look then (a controller points from it) */
    int ask_fresh;           /* hol_app_ask_from: the item comes up at the
                                next frame (its time, its look) */
    int ask_before;          /* the `before` asks (the level not begun) */
    /* a lesson's route (level.route): its tiles from the level's start,
     * and the next one to enter (route_k == level.nroute: done) */
    hol_tile route_tiles[HOL_APP_ROUTE_MAX];
    int route_k;
    /* captions (hol_app_hud.caption): on, the chime's text until when,
     * and the keys and state the last step ended with (as hol_sound's) */
    int captions;
    int cap_id;              /* hol_str_id of the chime, or -1 */
    double cap_until;
    int cap_keys, cap_state;
    uint8_t walk[HOL_NAV_WALK_MAX]; /* replan scratch */
    int nwalk;
};

/* The language of the view's texts (core/hol_str.h): the level's `lang`
 * line, else the desc's (hol_app_set_lang). */
static inline int hol__lang(const hol_app *app)
{
    return app->level.lang > 0 ? app->level.lang - 1 : app->d.lang;
}

/* hol_app_lesson.c: a lesson level's text (its instructions, closing:
 * part HOL_LESSON_WALK, _CHECK) in the view's language into out when text
 * is the lesson's English one, else text (the class test's closing too);
 * item q of ask a as shown: in the view's language (into tmp) when it is
 * a lesson's predict question, a class test's item (core/hol_quiz.h) or
 * a preset's (core/hol_ask.h) as the level holds it in English, else q,
 * with the questionnaire's name shown (*name); lesson
 * HOL_APP_HINT_LESSON's hint into out (1; 0 for a level without). */
const char *hol__lesson_say(const hol_app *app, const char *text, int part, char *out,
                            size_t cap);
const hol_app_question *hol__item_said(const hol_app *app, const hol_app_ask *a,
                                       const hol_app_question *q, hol_app_question *tmp,
                                       const char **name);
int hol__lesson_hint(const hol_app *app, char *out, size_t cap);

/* hol_app_tutorial.c */
int hol__next_stage(const hol_app *app, int k);
void hol__stage(hol_app *app, int k, const hol_room *r);
/* After a room step at level time t that ended the lesson `stage` (the
 * tutorial done, or another lesson begun): the new lesson's optimum and
 * start time; the lesson's row (issue 35, lesson: its number, start,
 * steps and optimum) in the step's events, but with desc.flow_v4. */
void hol__lesson_done(hol_app *app, int stage, hol_app_lesson lesson, double t);
/* A room step of a tutorial entered r: the lesson done (feedback, marks,
 * the next lesson or the level's end). */
void hol__tutorial_enter(hol_app *app, const hol_room *r);
/* Lesson 2's fewest steps left from r (the lesson's steps so far in
 * app->stage_steps): back in the lesson's start cell on another tile, after
 * at least 4 steps, inside the room; the walk in out_walk (cap bytes).
 * -1 when none within HOL__LOOP_MAX steps (never in a 3 x 3 room). */
#define HOL__LOOP_MAX 12
int hol__loop_left(const hol_app *app, const hol_room *r, uint8_t *out_walk, int cap);

/* hol_app_point.c: the level's walk for its pointing question (begun at
 * the level's start, a room step at a time, synced after a re-placing),
 * whether it can be asked, the direction pointed and the answer (fills
 * app->ev.point, sets ev.pointed). */
void hol__point_begin(hol_app *app);
void hol__point_step(hol_app *app, int dir);
void hol__point_sync(hol_app *app);
int hol__point_can_ask(const hol_app *app);
double hol__pointed_yaw(const hol_app *app, const hol_input *in);
void hol__point_answer(hol_app *app, const hol_input *in);

/* hol_app_ask.c: after the end screen's confirm (from_ask 0) or the last
 * item (1): the questionnaires, the closing screen or the next level; a
 * frame of an item; its lines on the HUD. */
void hol__after_end(hol_app *app, const hol_input *in, int from_ask);
void hol__ask_frame(hol_app *app, const hol_input *in, uint32_t pressed);
void hol__ask_lines(const hol_app *app, hol_app_hud *h);
/* hol_app_ask_from's state change: the level's questions from item ITEM
 * (its view is filled by the caller). HOL_EARG for no level or no such
 * item, app untouched. */
hol_err hol__ask_begin_from(hol_app *app, int item);
/* hol_app_start_level: the level's `before` asks first (state ASK), its
 * instructions and its clock after them; 0 when it has none. */
int hol__ask_before_start(hol_app *app);

/* hol_app_view.c */
void hol__fill_view(hol_app *app, const hol_input *in);

/* hol_app_geom.c: a quaternion's yaw and pitch (degrees; left as they
 * were for a zero quaternion). */
/* s cut to at most max bytes, never inside a UTF-8 sequence. */
void hol__utf8_cut(char *s, size_t max);
void hol__yaw_pitch_from_quat(const float qf[4], double *yaw, double *pitch);

#endif
