/* hol_app.h - the app step: one input record in, the state every platform
 * draws out. Desktop window, headset and headless replay all run it.
 *
 * Contract
 * - hol_app_step(app, &input) is the whole app per frame: pause and menu
 *   (paused while the input lacks HOL_INPUT_FOCUSED, has
 *   HOL_INPUT_DEVICE_LOST, or the menu is open; in the menu confirm
 *   restarts the level and back quits), the debug text toggle
 *   (HOL_BTN_DEBUG), the user's motion (a
 *   tracked head moves the user, else the pancake axes do; hol_motion),
 *   room steps, the world update after each (hol_world_update), the game
 *   (objectives entered by a room step, level end), guidance replan after
 *   each step (hol_nav: the optimal steps left; the path shown on the
 *   minimap when the user strays more than desc.stray_steps beyond the
 *   optimum), the HUD and minimap models, restart, quit. Button edges are
 *   the record's `pressed` bits and the buttons held that the previous
 *   record did not hold, so a tap between two frames acts once.
 * - Out: hol_app_view (user state per eye, HUD model filled at the step,
 *   minimap model) and hol_app_events (what happened in this step: room
 *   steps, a 10 Hz head sample, level start and end) for the research logs.
 *   Platforms draw and log from these and decide nothing themselves.
 * - Time comes only from input.time_s (never decreasing); the app has no
 *   clock. The level clock runs while the level is playing and not paused.
 * - Memory: hol_app_create makes every allocation through the desc's hooks
 *   (the app with its world store sized for every tiling, and the {4,5}
 *   3 x 3 navigator unless desc.nav is given); stepping allocates nothing.
 * - Geometry (SPEC 7): each level is played in its own tiling, room and
 *   cell size (hol_app_level.tiling_q, room_cols/rows, cell_m): it starts
 *   in cell (C/2, R/2) of tile O, the room's bounds are C*M by R*M metres,
 *   the eye stays at the motion's eye height (1.6 m) whatever M is, and the
 *   view says the cell size (view.cell_m) and the room (view.user). Each
 *   (tiling, room size) needs its navigator: hol_app_prepare makes it
 *   (through the hooks; 0.01 to 1 s and 15 to 60 MB, docs/performance.md),
 *   and hol_app_start_level makes it on the first level that needs it
 *   when nobody prepared it. The app keeps at most HOL_APP_MAX_NAVS; a
 *   new one beyond that replaces the one least recently started (never
 *   desc.nav). A restart (in the step) reuses the level's navigator, so
 *   only hol_app_prepare and hol_app_start_level ever allocate after
 *   create. desc.nav serves the geometry it was made for
 *   (hol_nav_geometry).
 * - Deterministic: the same desc, levels and input records give the same
 *   views and events, bit for bit (replay relies on it).
 * - Not thread safe; core rules apply (no OS, no GL, no globals).
 */
#ifndef HOL_APP_H
#define HOL_APP_H

#include <stddef.h>
#include <stdint.h>

#include "hol_alloc.h"
#include "hol_body.h"
#include "hol_err.h"
#include "hol_haptic.h"
#include "hol_input.h"
#include "hol_motion.h"
#include "hol_panel.h"
#include "hol_room.h"
#include "hol_tile.h"
#include "hol_world.h"

struct hol_nav;
struct hol_world;

enum hol_app_mode {
    HOL_APP_EXPLORE = 0,
    HOL_APP_FLAG = 1,
    HOL_APP_KEYS = 2,
    HOL_APP_TUTORIAL = 3
};

/* cues (bit set) */
#define HOL_CUE_HOT_COLD (1u << 0) /* hot-cold minimap colours */
#define HOL_CUE_PATH     (1u << 1) /* shortest path when strayed */
#define HOL_CUE_POLES    (1u << 2) /* guide poles on objectives */
#define HOL_CUE_ARROW    (1u << 3) /* direction arrow */
#define HOL_CUE_ALL      0xfu      /* the default: every cue above */
#define HOL_CUE_LANTERN  (1u << 4) /* a lantern on every objective (lights
                                      at dusk and night); only when a
                                      level's cues line names it */
#define HOL_CUE_SOUND    (1u << 5) /* a sound beacon on every objective
                                      (core/hol_sound.h); only when a
                                      level's cues line names it */

/* A level's sound (`sound all|cues|off`): all is ambience, effects and
 * beacons (the default: a forest that is heard); cues is effects and
 * beacons only; off is silence. */
enum hol_app_sound { HOL_SOUND_ALL = 0, HOL_SOUND_CUES = 1, HOL_SOUND_OFF = 2 };

/* A level's sky (`lighting day|dusk|night`): day is the picture without
 * lights; at dusk and night lanterns light the forest (render/hol_render.h). */
enum hol_app_lighting { HOL_LIGHT_DAY = 0, HOL_LIGHT_DUSK = 1, HOL_LIGHT_NIGHT = 2 };
/* A carried lantern (`lantern carried`) hangs this far below the head,
 * at the head's x and z: it moves with the head in every tile (at the
 * 1.6 m eye, the placed lanterns' 1.3 m). */
#define HOL_APP_CARRIED_DROP_M 0.3
/* The longest dusk-to-night cycle (`lighting cycle SECONDS`). */
#define HOL_APP_CYCLE_MAX_S 86400

/* A level's pointing question (`point start|objective`, SPEC 8): at the
 * level's end (done or time up) the app asks for the direction to the
 * level's start tile, or to its objective (the flag; the chest in mode
 * keys), before the end screen (state HOL_APP_POINT). */
enum hol_app_point_target {
    HOL_APP_POINT_NONE = 0,
    HOL_APP_POINT_START = 1,
    HOL_APP_POINT_OBJECTIVE = 2
};

enum hol_app_minimap_place { HOL_MINIMAP_HUD = 0, HOL_MINIMAP_HAND = 1, HOL_MINIMAP_OFF = 2 };

#define HOL_APP_MAX_KEYS 5
#define HOL_APP_MAX_OBJECTIVES 8
#define HOL_APP_PATH_MAX 64
#define HOL_APP_TEXT_MAX 48
#define HOL_APP_HINT_MAX 60 /* the prompt's line (the HUD draws 60 characters) */
/* Seconds a headset's device shows which control opens the menu, from the
 * moment it is in use (hol_app_hud.hint: "Y: menu", "LEFT PINCH: menu"). */
#define HOL_APP_MENU_HINT_S 10.0
/* The lesson whose hint the app gives on request (core/hol_lesson.h). */
#define HOL_APP_HINT_LESSON 6
/* The tutorial's feedback line the first time the path cue shows is
 * core/hol_str.h's HOL_S_PATH; its line (hol_app_hud.note) the first time
 * the minimap's rings show (lesson 2's two tiles of one cell, map.marks),
 * beside the lesson's feedback, as long as the rings, is HOL_S_RINGS. */
#define HOL_APP_HUD_LINES 6
/* Seconds (input clock) a chime's caption stays (hol_app_hud.caption). */
#define HOL_APP_CAPTION_S 3.0
#define HOL_APP_MAX_MARKS 2
/* Most room steps one app step reports (a frame's motion in sub-steps). */
#define HOL_APP_MAX_STEP_EVENTS 16
/* The minimap shows the tiles within this many steps of the user's tile;
 * an objective farther away gets a rim arrow (render/hol_hud.h draws it). */
#define HOL_APP_MINIMAP_RADIUS 4
/* Navigators the app keeps at once, one per (tiling, room size) that its
 * levels use (hol_app_prepare). */
#define HOL_APP_MAX_NAVS 4
/* A level's designer placements; the world takes these and a clearing on
 * each objective's tile (HOL_WORLD_MAX_PLACES holds both). */
#define HOL_APP_MAX_PLACES 32
/* Placed lanterns of a level (`place lantern ADDRESS`, repeatable). */
#define HOL_APP_MAX_LANTERNS 8
/* The tutorial's lessons, in order, each completed by a room step:
 * 0 step onto the marked tile one step ahead (room north);
 * 1 walk round a tree: back in the cell where the lesson began, after at
 *   least 4 steps, on another tile (holonomy); one tree is marked
 *   (view.tree_marked, view.tree_vertex): the inner corner of that cell
 *   that the lesson's first fewest-steps walk goes round (any loop that
 *   comes back on another tile still counts);
 * 2 reach a marker two tiles away in a straight line the room allows
 *   (room north, else west, east, south; two ahead if none fits), reading
 *   the minimap;
 * 3 find a flag three tiles away (ahead, ahead, left), every cue on.
 * Lessons 1 and 3's targets stand as markers (HOL_APP_OBJ_MARKER), drawn
 * unlike the flag of lesson 4. Targets are placed relative to where the lesson begins; the level is done
 * after the last. Each lesson done says so on the HUD for 6 s of level time
 * (hud.feedback; lesson 2: "Same cell, another tile: that is holonomy",
 * with the cell's two tiles marked on the minimap: map.marks). Each lesson
 * has an exact optimum from where it begins (hud.stage_optimum: the
 * navigator's for a target, an exhaustive search for lesson 2), so the
 * path cue shows when the lesson's steps plus the steps left exceed it by
 * more than desc.stray_steps. The level as a whole is not scored (optimum
 * -1: its lessons begin where the player ends the one before). */
#define HOL_APP_TUTORIAL_STAGES 4
/* Most room steps of a lesson's route (hol_app_level.route), and the HUD's
 * objective while one is walked (the marker K of N). */
#define HOL_APP_ROUTE_MAX 32
#define HOL_APP_ROUTE_TEXT "Follow the markers %d/%d"

/* A screen of text (hol_app_level.instructions, .closing): printable
 * ASCII and Latin-1 in UTF-8 (the HUD's font: hol_face_text_bad), at
 * most HOL_APP_SCREEN_TEXT - 1 bytes, wrapped at spaces into lines of at
 * most HOL_APP_SCREEN_COLS characters (hol_app_wrap), at most HOL_APP_SCREEN_LINES of them (the HUD's lines:
 * the text is shown whole, never cut; the level parser refuses more). */
#define HOL_APP_SCREEN_TEXT 288
#define HOL_APP_SCREEN_COLS 46
#define HOL_APP_SCREEN_LINES 6

enum hol_app_screen {
    HOL_APP_SCREEN_NONE = 0,
    HOL_APP_SCREEN_INSTRUCTIONS = 1, /* before the level: confirm shows the ready screen
                                        (not in a lesson: no clock to start) */
    HOL_APP_SCREEN_CLOSING = 2,      /* after the last level: confirm ends */
    HOL_APP_SCREEN_READY = 3         /* HOL_S_READY's text, after the instructions
                                        and on a resume (hol_app_ready): confirm
                                        begins the level, and its clock */
};
/* Before the clock starts (the instructions, the ready screen) nothing of
 * the level shows but the world around: no minimap (view.map.place
 * HOL_MINIMAP_OFF), no objective on it, no game object (issue 35). */
#define HOL_APP_READY_TEXT "Ready? The clock starts when you begin."


/* Questionnaires (issue 26 item 7; docs/research.md "Questionnaires"):
 * items (`question` level lines, or the presets ssq and tlx: core/hol_ask.h)
 * asked after the level's end screen, one screen an item, answered with
 * left/right and confirm. */
#define HOL_APP_MAX_QUESTIONS 40
#define HOL_APP_MAX_ASKS 4
#define HOL_APP_ID_MAX 32        /* an item's or questionnaire's ID, with the NUL */
#define HOL_APP_QTEXT_MAX 96     /* an item's text, with the NUL */
#define HOL_APP_LABEL_MAX 24     /* an anchor or a choice, with the NUL */
#define HOL_APP_MAX_CHOICES 6
#define HOL_APP_MAX_SCALE 21     /* a likert scale's marks at most */

enum hol_app_question_kind { HOL_APP_LIKERT = 0, HOL_APP_CHOICE = 1 };
/* after: asked after the level's end screen; before (issue 35, a baseline):
 * asked when the level starts, before its instructions and its clock. */
enum hol_app_ask_when { HOL_APP_AFTER_LEVEL = 0, HOL_APP_AFTER_CONDITION = 1,
                        HOL_APP_AFTER_STUDY = 2, HOL_APP_BEFORE_LEVEL = 3,
                        HOL_APP_BEFORE_CONDITION = 4, HOL_APP_BEFORE_STUDY = 5 };
#define HOL_APP_ASK_WHENS 6

typedef struct hol_app_question {
    char id[HOL_APP_ID_MAX];
    int kind;                         /* hol_app_question_kind */
    int lo, hi, step;                 /* likert: lo, lo+step, ..., hi */
    char text[HOL_APP_QTEXT_MAX];
    char low[HOL_APP_LABEL_MAX], high[HOL_APP_LABEL_MAX]; /* likert anchors */
    int nchoices;                     /* choice: 2..HOL_APP_MAX_CHOICES */
    char choices[HOL_APP_MAX_CHOICES][HOL_APP_LABEL_MAX];
} hol_app_question;

/* A questionnaire to ask (level line `ask NAME WHEN [ID...]`): its items
 * are questions[first .. first + n - 1]. */
typedef struct hol_app_ask {
    char name[HOL_APP_ID_MAX];
    int when;                         /* hol_app_ask_when (for the logs) */
    int first, n;
} hol_app_ask;

/* One level as the app plays it. */
typedef struct hol_app_level {
    int mode;                 /* hol_app_mode */
    uint64_t seed;            /* the world's seed */
    uint8_t start[64];        /* room steps before the level begins */
    int nstart;
    hol_tile flag;            /* HOL_APP_FLAG */
    hol_tile keys[HOL_APP_MAX_KEYS]; /* HOL_APP_KEYS: 1..5 keys, then chest */
    int nkeys;
    hol_tile chest;
    unsigned cues;            /* HOL_CUE_* */
    int minimap;              /* hol_app_minimap_place */
    double time_limit_s;      /* > 0: the level ends (HOL_APP_END_TIMEOUT)
                                 when its clock reaches this; 0: no limit */
    unsigned stages;          /* tutorial: the lessons to play, bit k for
                                 lesson k, in order; 0: all four */
    hol_world_place places[HOL_APP_MAX_PLACES]; /* designer placements
                                 (hol_world_desc.places), never on an
                                 objective's tile */
    int nplaces;
    /* The geometry (SPEC 7): tiles, the start walk and the objectives are
     * of this tiling and room. 0 (the level file has no such line) takes
     * the default: {4,5}, 3 x 3 cells of 1 m. */
    int tiling_q;             /* the tiling {4,Q}, 4..8; 0: 5 */
    int room_cols, room_rows; /* cells, 3..5 each; 0: 3 */
    double cell_m;            /* a cell's side in metres, 0.5..1.5; 0: 1.0 */
    int minimap_fixed;        /* 1: the minimap stays where `minimap`
                                 puts it (level line `fixed minimap`; a
                                 study condition that sets the minimap):
                                 HOL_BTN_MINIMAP only says "Minimap fixed
                                 in this study" (hud.feedback, 3 s) */
    int last;                 /* 1: the last level of its session (the
                                 session sets it): the end screen's confirm
                                 finishes, and its prompt says "finish",
                                 not "next level" */
    int lighting;             /* hol_app_lighting; 0: day */
    hol_tile lanterns[HOL_APP_MAX_LANTERNS]; /* `place lantern` tiles */
    uint8_t lantern_spot[HOL_APP_MAX_LANTERNS]; /* `... spot DIR`: 0 round,
                                 1..4 ahead/right/back/left of the tile's
                                 heading (tilted down), 5 down */
    int nlanterns;
    double lighting_cycle_s;  /* `lighting cycle SECONDS`: dusk to night
                                 over that much of the level's clock
                                 (lighting is then dusk); 0: none */
    int lantern_carried;      /* `lantern carried`: the player carries a
                                 lantern (at dusk and night) */
    int sound;                /* hol_app_sound; 0: all */
    int point;                /* hol_app_point_target: the question asked
                                 at the level's end; 0: none */
    int lang;                 /* level line `lang en|de|nl`: 1 + hol_lang
                                 (core/hol_str.h), the language of the
                                 view's texts in this level whatever the
                                 app's (desc.lang); 0: the app's */
    /* Screens (issue 26, session flow): "" none. instructions: shown when
     * the level is started (hol_app_start_level; not on a restart) until
     * confirm; the level (its clock, its attempt: events.level_started)
     * begins at the frame after. closing: on the session's last level
     * (last 1), the end screen's confirm shows it, and its confirm ends
     * (events.next_level). A study puts them there (core/hol_study.h). */
    char instructions[HOL_APP_SCREEN_TEXT];
    char closing[HOL_APP_SCREEN_TEXT];
    /* Questionnaires asked after the end screen's confirm, in order (then
     * the closing screen, then the next level): asks[k]'s items. */
    int nquestions;
    hol_app_question questions[HOL_APP_MAX_QUESTIONS];
    int nasks;
    hol_app_ask asks[HOL_APP_MAX_ASKS];
    /* A lesson (level line `lesson N`, core/hol_lesson.h; 0: none). Its
     * walk is the route: room steps from the level's start, inside the
     * room. In mode explore a route (nroute > 0) is the level's task: a
     * marker (HOL_APP_OBJ_MARKER) stands on the tile its next step reaches
     * and the HUD says "Follow the markers K/N"; a room step onto that
     * tile (by any way) moves the marker on, and the last one completes
     * the level (not scored: optimum -1). nroute 0 plays as before. */
    int lesson;               /* HOL_APP_HINT_LESSON: its hint on request
                                 (the menu's button: the menu shows it; the
                                 prompt names it; events.hint) */
    uint8_t route[HOL_APP_ROUTE_MAX];
    int nroute;
} hol_app_level;

typedef struct hol_app_desc {
    hol_alloc alloc;          /* hooks (core/hol_alloc.h); zero: malloc */
    hol_motion_desc motion;   /* pancake speeds, hedge margin, eye height */
    uint32_t world_capacity;  /* tiles; 0: 2^16 */
    struct hol_nav *nav;      /* optional shared navigator (not owned);
                                 NULL: the app creates one (0.5 s, 30 MB) */
    int stray_steps;          /* N: path shown beyond optimum + N; 0: 3 */
    double ipd;               /* eye distance for the per-eye states; 0: 0.064 */
    int no_haptics;           /* 1: no controller pulses (events.haptic stays 0;
                                 holonomy xr --no-haptics) */
    int lazy_nav;             /* 1 (tools, headless and desktop runs): the
                                 navigator it creates is lazy (hol_nav_desc)
                                 and builds its tours' leg table at the
                                 first keys level's tour (60-140 ms then), not
                                 at create; 0 (a headset): both at create, so
                                 no level start pays. Same answers. */
    int lang;                 /* hol_lang (core/hol_str.h): the language of
                                 every text the view holds (HUD, prompts,
                                 tutorial) unless the level's `lang` line
                                 names one; 0: English. Logs, events and
                                 recordings do not depend on it. */
    int lazy_world;           /* 1 (tools, headless and desktop runs): the
                                 world's memory (14 MB) comes from calloc
                                 and is not cleared at create, so only the
                                 pages a run writes are mapped (when
                                 written, in the frame that writes them);
                                 without allocator hooks only. 0 (a
                                 headset): cleared at create, so no update
                                 takes a page fault. A level start clears a
                                 store only when it holds tiles. */
    int flow_v4;              /* 1: the flow recordings of version 1 to 4
                                 were played in (hol_rec.h meta.flow_v4),
                                 so they replay as they were played: no
                                 ready screen after the instructions (their
                                 confirm begins the level), the tutorial's
                                 lessons as they were (hol_app_tutorial.c);
                                 0 (live play): issue 35's flow */
} hol_app_desc;

typedef enum hol_app_state {
    HOL_APP_IDLE = 0,         /* no level started yet */
    HOL_APP_PLAYING = 1,
    HOL_APP_DONE = 2,         /* the level is complete: the end screen */
    HOL_APP_QUIT = 3,         /* the user asked to quit: the platform exits */
    HOL_APP_POINT = 4,        /* the level is over (done or time up) and
                                 its `point` question is asked: the user
                                 turns (pancake: the view's yaw; a tracked
                                 head: the controller's ray, see
                                 hol_app_point) and confirms; then DONE.
                                 The level clock is stopped, no walking. */
    HOL_APP_ASK = 6,          /* a questionnaire's item (hud.ask_*): left
                                 and right choose, confirm answers
                                 (events.answered), quit quits */
    HOL_APP_SCREEN = 5        /* a screen of text (hud.screen: the level's
                                 instructions before it begins, the closing
                                 screen after the last): its lines are
                                 hud.lines, confirm goes on, quit quits;
                                 nothing else acts, no clock runs */
} hol_app_state;
/* How many states there are (0..HOL_APP_STATE_COUNT-1): tables of them are
 * sized by it. */
#define HOL_APP_STATE_COUNT 7

/* The HUD model: filled at the step, drawn as is. */
typedef struct hol_app_hud {
    char objective[HOL_APP_TEXT_MAX]; /* "Find the flag", "Keys 2/3", ... */
    char status[HOL_APP_TEXT_MAX];    /* "Paused", "Controller lost" (device
                                         lost), "Done: 14 steps, ...", "" */
    char hint[HOL_APP_HINT_MAX];      /* the prompt: what the buttons do now,
                                         named for the device in use
                                         (core/hol_prompt.h): "ENTER: NEXT
                                         LEVEL, R: AGAIN", "A: NEXT LEVEL",
                                         "TRIGGER: NEXT LEVEL" ("FINISH" on
                                         the last level); with a headset's
                                         device (HOL_DEVICE_XR_SIMPLE and
                                         after but the touch screen's), for HOL_APP_MENU_HINT_S
                                         from its first record, the control
                                         that opens the menu ("Y: menu",
                                         after the prompt if one is
                                         shown); or "" */
    char address[HOL_TILE_ADDR_MAX];  /* the current tile */
    char feedback[HOL_APP_TEXT_MAX];  /* tutorial: the lesson just done, or "" */
    char note[HOL_APP_TEXT_MAX];      /* tutorial: HOL_S_RINGS while the
                                         minimap's rings show the first time
                                         in the level (a line after the
                                         feedback), or "" */
    int steps;                        /* room steps this level */
    int optimum;                      /* fewest steps from the level start; -1 none */
    int remaining;                    /* optimal steps left from here; -1 none */
    int keys_held, keys_total;
    int stage;                        /* tutorial lesson 0..3; -1 otherwise */
    int stage_steps, stage_optimum;   /* tutorial: the lesson's steps so far and
                                         its fewest from its start (-1 none) */
    int debug;                        /* the debug text is on (HOL_BTN_DEBUG) */
    uint32_t device;                  /* HOL_DEVICE_* the prompts are worded for */
    int timed_out;                    /* 1: the level ended at its time limit
                                         (state DONE, "Time up"), not complete */
    double elapsed_s;                 /* level clock */
    int screen;                       /* hol_app_screen shown (state
                                         HOL_APP_SCREEN), else 0 */
    int ask_item, ask_items;          /* state HOL_APP_ASK: the item (0-based)
                                         of the questionnaire and its count */
    int ask_before;                   /* and 1: a `before` one (the level
                                         not begun) */
    int ask_value;                    /* the value chosen now (likert: the
                                         number; choice: its index) */
    /* the text as drawn, one line each: the feedback if any, the note
     * if any, the objective (or status), "STEPS n", "TIME m:ss OF m:ss" when the level
     * has a time limit; with debug on also "TILE address", "CELL c,r NORTH
     * o" and the time; "TILE" keeps the address's case, other lines are
     * shown in capitals. The hint (the prompt) is drawn on its own. */
    char lines[HOL_APP_HUD_LINES][HOL_APP_TEXT_MAX];
    int nlines;
    /* The sound's caption (issue 37; W3C XR Accessibility: captions for
     * sound), or "": with captions on (hol_app_set_captions: the platform
     * plays sound) and the level's sound not off, the cue the sound plays
     * now named in the language, the last line of `lines` (when one is
     * free): a chime (hol_sound.h: the level begins, a key is collected,
     * the chest opens, the flag is reached) for HOL_APP_CAPTION_S of input
     * time from its step, else, while beacons sound (cue `sound`, the
     * level in play, objectives left), the beacons' line. Footsteps (every
     * room step, counted on the HUD) and the forest's ambience are not
     * captioned. The same steps as core/hol_sound.h's shots (test_app). */
    char caption[HOL_APP_TEXT_MAX];
} hol_app_hud;

/* The minimap model. */
typedef struct hol_app_minimap {
    int place;                        /* hol_app_minimap_place */
    unsigned cues;                    /* HOL_CUE_* in force */
    int nobjectives;                  /* objectives still to reach */
    hol_tile objectives[HOL_APP_MAX_OBJECTIVES];
    int npath;                        /* >0: the path to draw (strayed) */
    uint8_t path[HOL_APP_PATH_MAX];   /* room steps from the user */
    int nmarks;                       /* tiles to mark (tutorial feedback) */
    hol_tile marks[HOL_APP_MAX_MARKS];
} hol_app_minimap;

/* A game object standing in the world. */
typedef enum hol_app_object_kind {
    HOL_APP_OBJ_NONE = 0,
    HOL_APP_OBJ_FLAG,        /* the flag (a flag level, tutorial lesson 4) */
    HOL_APP_OBJ_KEY,         /* a key not yet collected */
    HOL_APP_OBJ_CHEST,       /* the chest, closed */
    HOL_APP_OBJ_CHEST_OPEN,  /* the chest once every key is held */
    HOL_APP_OBJ_MARKER       /* a tutorial lesson's marker (lessons 1, 3):
                                not a flag */
} hol_app_object_kind;

typedef struct hol_app_object {
    hol_tile tile;
    int kind;                /* hol_app_object_kind */
} hol_app_object;

/* Outside the room (a tracked head beyond the hedges; core/hol_app.h's
 * view.outside): the way back in. Core decides, the platform draws
 * (render/hol_render_types.h, hol_frame_desc.outside): the view from the
 * tracked head where it is (its cells those of the view's head and eyes,
 * which the motion keeps HOL_MOTION's margin inside the hedges), dimmed,
 * the panel over it (readable), and an arrow on the floor pointing to
 * the nearest cell. */
#define HOL_APP_ARROW_AHEAD_M 1.8 /* the arrow's centre ahead of the head, on the floor
                                    (40 degrees below eye level) */
typedef struct hol_app_outside {
    int on;               /* the tracked head is outside the room */
    double dist_m;        /* its floor distance beyond the hedges */
    int col, row;         /* the nearest cell (the view's head stands in it) */
    double arrow[3];      /* the arrow's centre on the floor (y 0), room
                             coordinates: HOL_APP_ARROW_AHEAD_M ahead of the
                             view's head along its yaw (in view, drawn over
                             all, even beyond a hedge) */
    double arrow_yaw_deg; /* where it points: from the tracked head to the
                             nearest cell's centre (SPEC 1's yaw: 0 north,
                             towards -z; positive turns west) */
} hol_app_outside;

/* What every platform draws. */
#define HOL_APP_SEAT_FADE_S 0.2 /* seated: a step's fade, seconds */

typedef struct hol_app_view {
    hol_app_state state;
    int paused;
    hol_room user;                    /* the head's state (its tile word
                                         carries the tiling, the state the
                                         room's C x R) */
    double cell_m;                    /* the side of a cell in metres (SPEC
                                         7: cell (c,r) spans x in [c*M,
                                         (c+1)*M]); always filled, 1.0 by
                                         default */
    double head[3];                   /* room coordinates */
    double yaw_deg, pitch_deg;        /* look direction */
    double head_quat[4];              /* x, y, z, w (from a tracked head, or
                                         from yaw and pitch) */
    hol_room eye_user[2];             /* the state each eye sees from */
    double eye[2][3];                 /* eye positions (head +- ipd / 2) */
    hol_panel panel;                  /* where a headset's UI panel stands:
                                         lazily following the head
                                         (core/hol_panel.h); drawn there
                                         only for a headset's eyes */
    hol_app_outside outside;          /* the way back in (above) */
    hol_app_hud hud;
    int seated;                       /* 1: seated play (HOL_INPUT_SEATED) */
    double seat_fade;                 /* seated: the short fade of a step,
                                         1 at the step down to 0 after
                                         HOL_APP_SEAT_FADE_S (a renderer
                                         blends the frame to black by it) */
    hol_app_minimap map;
    int tree_marked;                  /* 1: the tree on room vertex
                                         tree_vertex is marked (tutorial
                                         lesson 2: the tree to walk round) */
    int tree_vertex[2];               /* its column and row of vertices: it
                                         stands at x = tree_vertex[0] *
                                         cell_m, z = tree_vertex[1] * cell_m
                                         (0..C, 0..R; inside the room) */
    int nobjects;                     /* game objects to draw in the world */
    hol_app_object objects[HOL_APP_MAX_OBJECTIVES];
    uint64_t frame;                   /* steps of the app so far */
    int lighting;                     /* the level's hol_app_lighting */
    int nlanterns;                    /* the level's placed lanterns, then
                                         (cue lantern) one per objective
                                         still to reach */
    hol_tile lanterns[HOL_APP_MAX_LANTERNS + HOL_APP_MAX_OBJECTIVES];
    uint8_t lantern_spot[HOL_APP_MAX_LANTERNS + HOL_APP_MAX_OBJECTIVES]; /* the
                                         level's spots; 0: round */
    double night;                     /* the sky between dusk (0) and
                                         night (1): lighting's own (night 1,
                                         else 0), or with a cycle the level
                                         clock over its seconds (at most
                                         1) */
    int carried;                      /* 1: a carried lantern at carried_pos
                                         (lit at dusk and night) */
    double carried_pos[3];            /* room metres: the head's x and z,
                                         HOL_APP_CARRIED_DROP_M below it */
    int sound;                        /* the level's hol_app_sound (the
                                         sources: core/hol_sound.h) */
    hol_body body;                    /* the controllers and tracked hands
                                         at the record's room poses, and
                                         the pointing question's ray
                                         (core/hol_body.h); drawn in the
                                         room, for every eye */
} hol_app_view;

/* One room step, for the per-step log. */
typedef struct hol_app_step_event {
    double t;          /* level clock */
    int index;         /* 1-based step number in the level */
    uint8_t dir;       /* room direction HOL_DIR_* */
    hol_room room;     /* state after the step */
    double yaw_deg;    /* look direction in the room */
    int remaining;     /* optimal steps left to finish; -1 none */
    unsigned cues;
} hol_app_step_event;

typedef enum hol_app_end {
    HOL_APP_END_NONE = 0,
    HOL_APP_END_DONE,     /* completed */
    HOL_APP_END_RESTART,  /* restarted by the user */
    HOL_APP_END_QUIT,     /* left by the user */
    HOL_APP_END_TIMEOUT   /* the level's time limit ran out (the end screen) */
} hol_app_end;

typedef struct hol_app_summary {
    int mode;
    uint64_t seed;
    int steps, optimum;
    double time_s;
    hol_app_end end;
} hol_app_summary;

/* A pointing answer (SPEC 8, level line `point`). Bearings in degrees
 * clockwise from room north, [0, 360). pointed: the direction the user
 * gave at confirm: with a tracked head (a headset) the yaw of the right
 * controller's pose (its -z axis, the ray) when HOL_INPUT_HAND_R_VALID,
 * else the left's, else the head's; without one (pancake) the view's yaw.
 * true_deg, flat_deg: hol_bearing_end of the level's walk of room steps
 * (core/hol_bearing.h; the same computation as `holonomy tile bearing`),
 * the target the level's start tile or its objective; the flat vector
 * counts the steps from the level's start (after its start walk; the start
 * walk's own visits do not count). has_true 0: the user stands on the
 * target; has_flat 0: the walk never stood on it, or the flat vector is
 * zero. error_*: pointed minus the bearing, wrapped to (-180, 180]. */
typedef struct hol_app_point {
    int target;            /* hol_app_point_target */
    double t;              /* the level clock when it was asked (the end) */
    double asked_s;        /* the input time it was asked */
    double time_s;         /* seconds taken to answer */
    double at_s;           /* the input time of the answer's confirm */
    double pointed_deg;
    int has_true, has_flat;
    double true_deg, flat_deg;
    double error_true, error_flat;
} hol_app_point;

/* A questionnaire item's answer. */
typedef struct hol_app_answer {
    char questionnaire[HOL_APP_ID_MAX];
    int when;                         /* hol_app_ask_when */
    char item[HOL_APP_ID_MAX];
    int kind;                         /* hol_app_question_kind */
    int value;                        /* likert: the number chosen */
    char choice[HOL_APP_LABEL_MAX];   /* choice: its text */
    double time_s;                    /* seconds from the item's screen to
                                         its confirm */
    double shown_s, at_s;             /* the input times of the item's
                                         screen and of its confirm */
} hol_app_answer;

/* A tutorial lesson done (issue 35; not with desc.flow_v4): a row of
 * tutorial.csv (hol_session.h). */
typedef struct hol_app_lesson {
    int lesson;         /* 1..HOL_APP_TUTORIAL_STAGES */
    double started, t;  /* the level times it began and was done */
    int steps, optimum; /* its room steps; its fewest from where it began */
} hol_app_lesson;

typedef struct hol_app_events {
    int nsteps;
    hol_app_step_event steps[HOL_APP_MAX_STEP_EVENTS];
    int head_sample;       /* 1: a 10 Hz head sample is due (view has it) */
    double head_sample_t;  /* its level time (a multiple of 0.1 s) */
    int level_started;     /* the level (re)started in this step */
    hol_app_end level_ended; /* the level attempt ended in this step */
    hol_app_summary summary; /* with level_ended */
    int next_level;        /* confirm on the end screen: the platform
                              starts the next level */
    hol_haptic haptic;     /* the controllers' pulses of this step
                              (core/hol_haptic.h: a hand into a hedge or a
                              trunk, a room step; none while paused or
                              with desc.no_haptics); the platform plays them */
    int minimap_moved;     /* HOL_BTN_MINIMAP moved the minimap (to
                              view.map.place) in this step */
    int minimap_refused;   /* HOL_BTN_MINIMAP was pressed on a level whose
                              minimap is fixed: nothing moved */
    int pointed;           /* the level's pointing question was answered
                              in this step (point) */
    hol_app_point point;
    int answered;          /* a questionnaire's item was answered (answer) */
    hol_app_answer answer;
    int relocated;         /* the room was re-based around the head into
                              another cell, with no room step: the head
                              moved while the headset was off, unfocused or
                              untracked (core/hol_input.h) */
    double relocated_m;    /* with relocated: the head's floor distance
                              from where it last walked, metres */
    int hint;              /* the menu opened on a lesson's walk that has a
                              hint (HOL_APP_HINT_LESSON): the hint shown */
    int nlessons;          /* tutorial lessons done in this step */
    hol_app_lesson lessons[HOL_APP_TUTORIAL_STAGES];
    int outside;           /* the tracked head left the room (view.outside;
                              only from records with HOL_INPUT_WAY_BACK) */
    double outside_m;      /* with outside: how far beyond the hedges */
    int inside;            /* it came back in */
    double inside_s;       /* with inside: the seconds it was outside */
} hol_app_events;

typedef struct hol_app hol_app;

/* Wraps text at spaces into lines of at most cols (1..HOL_APP_TEXT_MAX-1)
 * characters (UTF-8: a character is a whole sequence, never cut, and a
 * line also holds at most HOL_APP_TEXT_MAX-1 bytes; a word longer than a
 * line is cut at the line's end and goes on; runs of blanks at a wrap are
 * dropped); writes at most max lines into
 * out (NULL: none) and returns how many lines the whole text needs. */
int hol_app_wrap(const char *text, int cols, char (*out)[HOL_APP_TEXT_MAX], int max);

/* Errors: HOL_EARG, HOL_ENOMEM (an allocation failed). */
hol_err hol_app_create(const hol_app_desc *desc, hol_app **out_app);
void hol_app_destroy(hol_app *app); /* NULL ok */

/* Start (or restart) a level: the world is re-seeded in place with the
 * level's placements and a clearing (HOL_OBJ_NONE) on every objective's
 * tile, so each objective is reserved on a free tile (no rock, log, creek
 * or pond under it) wherever it lies; the start walk applied, the optimum
 * computed. Errors: HOL_EARG (bad level: no keys, an objective on the start
 * tile, a placement on an objective's tile, a start walk leaving the room,
 * a bad geometry), HOL_EUNREACH (no walk inside the level's room reaches
 * an objective: the flat {4,4} off the room's tiles, or {4,8}),
 * HOL_EBUDGET (the optimum could not be proved exact: the level
 * is refused), HOL_ENOMEM (the world store, a navigator), HOL_ERANGE. On error no level
 * is playing. */
hol_err hol_app_start_level(hol_app *app, const hol_app_level *level);

/* Right after hol_app_start_level: the level is not played; its questions
 * are asked from item (0-based, counted over level.asks in order: a
 * resumed participant's unanswered ones, issue 39), then it goes on as
 * after the last item (the closing screen, or events.next_level). No
 * events.level_started, no clock; the first item's time counts from the
 * next frame. Errors: HOL_EARG (no level, or item not one of its items:
 * nothing changed). */
hol_err hol_app_ask_from(hol_app *app, int item);

/* Right after hol_app_start_level: the level begins on the ready screen
 * (HOL_APP_SCREEN_READY; a resumed session's first level), after its
 * `before` questionnaires and its instructions if it has them. Errors:
 * HOL_EARG (no level: nothing changed). */
hol_err hol_app_ready(hol_app *app);

/* Make (or find) the navigator of the tiling {4,q} and a room of cols x
 * rows cells (0: 5, 3, 3), so that no level start pays for it: platforms
 * call it at init for the geometries of the session's levels. Errors:
 * HOL_EARG (a bad geometry), HOL_ENOMEM. */
hol_err hol_app_prepare(hol_app *app, int q, int cols, int rows);

/* One frame. Errors: HOL_EARG (an invalid record or time going back; the
 * app is unchanged), HOL_ENOMEM (the world store is full). Without a level
 * the view is the idle state. */
hol_err hol_app_step(hol_app *app, const hol_input *in);

const hol_app_view *hol_app_get_view(const hol_app *app);
/* The word the platforms print for how a run ended ("level NAME WORD steps
 * ..."): "timeout" when the level's time ran out, else by state: idle,
 * playing (also the instructions and a `before` questionnaire's item
 * before a level), done (also the pointing question, a questionnaire's
 * item and the closing screen, which come after the level is over), quit.
 * Never NULL. */
const char *hol_app_end_word(const hol_app_view *v);
const hol_app_events *hol_app_get_events(const hol_app *app);
/* The fewest room steps from the user to the objective in play (the
 * flag, the keys and chest, the tutorial lesson's target) as the last step
 * computed them (HOL_DIR_*), at most cap into out; returns how many (0:
 * none known, or no objective). For scripted players and tests. */
int hol_app_walk(const hol_app *app, uint8_t *out, int cap);
/* The world the view shows (for the renderer's content). */
struct hol_world *hol_app_world(hol_app *app);
/* Captions of the sound on (1) or off (0, the default): a platform that
 * plays the app's sound turns them on (hol_app_hud.caption). */
void hol_app_set_captions(hol_app *app, int on);
/* The language of the view's texts from the next step on (hol_lang,
 * core/hol_str.h; out of range: English), as desc.lang at create: a page
 * that changes its language changes nothing else. */
void hol_app_set_lang(hol_app *app, int lang);

#endif
