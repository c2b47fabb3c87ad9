/* hol_str.h - the string table: every word the player sees (HUD, panel,
 * prompts, menus, end screens, tutorial, sound captions, the web page's
 * own), one row an id with its text in every language (issue 37).
 *
 * Contract
 * - hol_str(lang, id) is the text of id in lang (HOL_LANG_*): a static,
 *   NUL-terminated UTF-8 string; below HOL_S_PAGE_FIRST (what the app's
 *   HUD and panel draw) its code points are all in the text face
 *   (core/hol_face.h: ASCII and Latin-1; tests/test_str.c draws none as
 *   the missing-glyph box); the page's strings (from HOL_S_PAGE_FIRST on)
 *   are drawn by the browser. A lang out of range reads English; an id
 *   out of range, or an entry a language lacks, reads "". Pure data: no
 *   state, no allocation.
 * - A build may leave a language out (-DHOL_STR_NO_NL: the web's, whose
 *   transfer budget it keeps; Makefile WEB_LANGS): it reads as English and
 *   hol_lang_parse does not take its tag.
 * - English is the reference: its strings are the ones the app showed
 *   before the table, byte for byte (goldens and tests compare them).
 *   Every language is complete (no NULL entry: tests/test_str.c); the
 *   ids whose text is a printf format (the *_FMT ids) have the same
 *   conversions, in the same order, in every language, and every text
 *   fits the buffer its id is drawn into (hol_str_cap) with its numbers
 *   at their widest.
 * - hol_lang_parse(tag) reads a language tag: "en", "de", "nl", or one
 *   with a region ("de-DE", "de_AT", "en-GB"; case ignored, as a browser's
 *   navigator.language gives it); -1 for any other. hol_lang_code(lang)
 *   is its two-letter code ("en" for a lang out of range).
 * - Logs, recordings and the tool's own messages are data and stay in
 *   English: only what the player sees goes through this table.
 */
#ifndef HOL_STR_H
#define HOL_STR_H

enum hol_lang { HOL_LANG_EN = 0, HOL_LANG_DE = 1, HOL_LANG_NL = 2, HOL_LANG_COUNT = 3 };

typedef enum hol_str_id {
    /* objectives (hol_app_hud.objective; 47 bytes) */
    HOL_S_OBJ_FLAG = 0,
    HOL_S_OBJ_KEYS_FMT,   /* %d %d: keys held, keys in all */
    HOL_S_OBJ_CHEST,
    HOL_S_OBJ_EXPLORE,
    HOL_S_GUIDE_POLE,     /* holonomy render --hud --target's objective */
    HOL_S_LESSON_1,       /* the tutorial's four lessons */
    HOL_S_LESSON_2,
    HOL_S_LESSON_3,
    HOL_S_LESSON_4,
    HOL_S_LESSON_3_NOMAP, /* lesson 3's when a study holds the map off */
    HOL_S_ROUTE_FMT,      /* %d %d: a lesson's route, the next marker, all */
    /* feedback and notes (hol_app_hud.feedback, .note; 47 bytes) */
    HOL_S_LESSON_1_DONE,
    HOL_S_LESSON_2_DONE,
    HOL_S_LESSON_3_DONE,
    HOL_S_LESSON_4_DONE,
    HOL_S_PATH,           /* the first time the path cue shows */
    HOL_S_RINGS,          /* the first time the rings show */
    HOL_S_FIXED,          /* the minimap button on a fixed minimap */
    /* status lines (hol_app_hud.status; 47 bytes) */
    HOL_S_PAUSED,
    HOL_S_POINT_CTRL_START, /* the pointing question, with a controller */
    HOL_S_POINT_CTRL_CHEST,
    HOL_S_POINT_CTRL_FLAG,
    HOL_S_POINT_FACE_START, /* the pointing question, by the view */
    HOL_S_POINT_FACE_CHEST,
    HOL_S_POINT_FACE_FLAG,
    HOL_S_TIME_UP_FMT,    /* %d %d %ld %02ld: steps, best, minutes, seconds */
    HOL_S_TUTORIAL_DONE_FMT, /* %d %ld %02ld: steps, minutes, seconds */
    HOL_S_DONE_FMT,       /* %d %d %ld %02ld: steps, best, minutes, seconds */
    HOL_S_DEVICE_LOST,
    HOL_S_OUTSIDE,
    HOL_S_READY,          /* the ready screen (HOL_APP_SCREEN_READY) */
    /* prompts (hol_app_hud.hint; 59 bytes) */
    HOL_S_DEVICE_BACK,
    HOL_S_SMALL_AREA_FMT, /* %.12s: the room's size in metres, "3 x 3" */
    HOL_S_MOVE_KEYBOARD,
    HOL_S_MOVE_GAMEPAD,
    HOL_S_MOVE_ROOM,
    HOL_S_MOVE_SCREEN,    /* HOL_DEVICE_SCREEN: the touch stick and look */
    /* what a button does, after "BUTTON: " in a prompt */
    HOL_S_DO_FINISH,
    HOL_S_DO_BEGIN,
    HOL_S_DO_QUIT,
    HOL_S_DO_CONFIRM,
    HOL_S_DO_RESUME,
    HOL_S_DO_RESTART,
    HOL_S_DO_ANSWER,
    HOL_S_DO_NEXT_LEVEL,
    HOL_S_DO_AGAIN,
    HOL_S_DO_HINT,        /* lesson 6's hint on request (the menu's button) */
    HOL_S_DO_MENU,
    HOL_S_DO_MAP,
    /* the HUD's lines (hol_app_hud.lines; 47 bytes) */
    HOL_S_STEPS_FMT,      /* %d */
    HOL_S_TIME_OF_FMT,    /* %ld %02ld %ld %02ld: the clock and the limit */
    HOL_S_TIME_FMT,       /* %ld %02ld */
    HOL_S_TILE_FMT,       /* %.40s: the tile's address */
    HOL_S_CELL_FMT,       /* %d %d %d: column, row, the room's north */
    /* sound captions (core/hol_caption.h; 47 bytes) */
    HOL_S_CAP_START,
    HOL_S_CAP_KEY,
    HOL_S_CAP_CHEST,
    HOL_S_CAP_FLAG,
    HOL_S_CAP_BEACON,     /* beacons sound at the objectives */
    /* a lesson's predict question's questionnaire name, and the class
     * test's (core/hol_quiz.h) shown for "pretest", "posttest" (12 bytes) */
    HOL_S_PREDICT,
    HOL_S_PRETEST,
    HOL_S_POSTTEST,
    /* the seated mode's panel line (hol_prompt_seated; 47 bytes) */
    HOL_S_SEATED_KEYBOARD,
    HOL_S_SEATED_GAMEPAD,
    HOL_S_SEATED_TOUCH,   /* HOL_DEVICE_NONE: a swipe or the on-screen arrows */
    HOL_S_SEATED_HANDS,   /* a pinch and flick (core/hol_body.h) */
    HOL_S_SEATED_STICK,
    /* HOL_DEVICE_NONE's buttons, named by their action (hol_prompt_button_in;
     * in the prompt's line), in the order of the HOL_BTN_* bits 0..7 */
    HOL_S_BTN_CONFIRM,
    HOL_S_BTN_BACK,
    HOL_S_BTN_MENU,
    HOL_S_BTN_RECENTRE,
    HOL_S_BTN_MINIMAP,
    HOL_S_BTN_RESTART,
    HOL_S_BTN_QUIT,
    HOL_S_BTN_DEBUG,
    /* the buttons' words of the devices that have no names printed on
     * them (hol_prompt_button_in; in the prompt's line): the hands'
     * gestures (HOL_DEVICE_WEBXR_HAND, HOL_DEVICE_XR_HAND) and the web
     * page's on-screen buttons (HOL_DEVICE_SCREEN: as the page labels them,
     * HOL_S_PAGE_OK ...) */
    HOL_S_HAND_PINCH,
    HOL_S_HAND_LONG_PINCH,
    HOL_S_HAND_LEFT_PINCH,
    HOL_S_HAND_GRASP,
    HOL_S_HAND_LEFT_GRASP,
    HOL_S_SCREEN_OK,
    HOL_S_SCREEN_BACK,
    HOL_S_SCREEN_MENU,
    HOL_S_SCREEN_MAP,
    /* item texts (hol_app_question.text; 95 bytes, at most 3 lines of
     * HOL_APP_SCREEN_COLS): the class test's (pre, post; its concepts in
     * order), the SSQ's 16 and the raw TLX's 6 (core/hol_ask.c's rows, in
     * their order). The level and the logs keep the English (ids, codes,
     * choices); the app shows them in its language. */
    HOL_S_QUIZ_PRE_SQUARE,
    HOL_S_QUIZ_PRE_CORNER,
    HOL_S_QUIZ_PRE_GROWTH,
    HOL_S_QUIZ_PRE_HOME,
    HOL_S_QUIZ_POST_SQUARE,
    HOL_S_QUIZ_POST_CORNER,
    HOL_S_QUIZ_POST_GROWTH,
    HOL_S_QUIZ_POST_HOME,
    HOL_S_SSQ_GENERAL_DISCOMFORT,
    HOL_S_SSQ_FATIGUE,
    HOL_S_SSQ_HEADACHE,
    HOL_S_SSQ_EYE_STRAIN,
    HOL_S_SSQ_DIFFICULTY_FOCUSING,
    HOL_S_SSQ_SALIVATION_INCREASING,
    HOL_S_SSQ_SWEATING,
    HOL_S_SSQ_NAUSEA,
    HOL_S_SSQ_DIFFICULTY_CONCENTRATING,
    HOL_S_SSQ_FULLNESS_OF_HEAD,
    HOL_S_SSQ_BLURRED_VISION,
    HOL_S_SSQ_DIZZINESS_EYES_OPEN,
    HOL_S_SSQ_DIZZINESS_EYES_CLOSED,
    HOL_S_SSQ_VERTIGO,
    HOL_S_SSQ_STOMACH_AWARENESS,
    HOL_S_SSQ_BURPING,
    HOL_S_TLX_MENTAL,
    HOL_S_TLX_PHYSICAL,
    HOL_S_TLX_TEMPORAL,
    HOL_S_TLX_PERFORMANCE,
    HOL_S_TLX_EFFORT,
    HOL_S_TLX_FRUSTRATION,
    /* choices and anchors (hol_app_question's labels; 20 bytes, as an
     * item's value shows them) */
    HOL_S_YES,
    HOL_S_NO,
    HOL_S_FEWER,
    HOL_S_MORE,
    HOL_S_DEG_360,
    HOL_S_LESS_360,
    HOL_S_MORE_360,
    HOL_S_SSQ_NONE,
    HOL_S_SSQ_SEVERE,
    HOL_S_TLX_VERY_LOW,
    HOL_S_TLX_VERY_HIGH,
    HOL_S_TLX_PERFECT,
    HOL_S_TLX_FAILURE,
    /* the class test's closing screen (HOL_APP_SCREEN_TEXT) */
    HOL_S_QUIZ_DONE,
    /* the web page's (platform/web/page.js; its copy made by
     * tests/gen_page_text.c) and its pauses' reasons, after "Paused: " */
    HOL_S_PAUSE_UNFOCUSED,
    HOL_S_PAUSE_HEADSET_OFF,
    HOL_S_PAUSE_SYSTEM_MENU,
    HOL_S_PAUSE_PAD_GONE,
    HOL_S_PAUSE_MENU,
    HOL_S_FIT_FMT,        /* %d %d %s %s %s: the play area's fit (hol_fit_say) */
    HOL_S_FIT_SMALL_FMT,  /* %s %s %s: a play area under the smallest room */
    HOL_S_PAGE_LOADING,
    HOL_S_PAGE_OK,
    HOL_S_PAGE_BACK,
    HOL_S_PAGE_MENU,
    HOL_S_PAGE_MAP,
    HOL_S_PAGE_VR_ENTER,
    HOL_S_PAGE_VR_EXIT,
    HOL_S_PAGE_VR_HTTPS,
    HOL_S_PAGE_VR_HTTPS_WHY,
    HOL_S_PAGE_VR_NONE,
    HOL_S_PAGE_VR_NONE_WHY,
    HOL_S_PAGE_VR_NO_HEADSET,
    HOL_S_PAGE_VR_NO_HEADSET_WHY,
    HOL_S_PAGE_AGAIN,
    HOL_S_PAGE_FIT,
    HOL_S_PAGE_FILE,
    HOL_S_PAGE_FILE_WHY,
    HOL_S_PAGE_LOGS,
    HOL_S_PAGE_HELP,
    HOL_S_PAGE_NO_LOGS,
    HOL_S_PAGE_CLEAR,
    HOL_S_PAGE_CLEAR_ASK,
    HOL_S_PAGE_BYTES,
    HOL_S_PAGE_PLAYING,
    HOL_S_PAGE_PLAYING_LEVEL,
    HOL_S_PAGE_IN_VR,
    HOL_S_PAGE_PAUSED,
    HOL_S_PAGE_OVER,
    HOL_S_PAGE_FAILED,
    HOL_S_PAGE_WARNING,
    HOL_S_PAGE_VR_FAILED,
    HOL_S_PAGE_NO_STUDY,
    HOL_S_PAGE_NO_LEVEL,
    HOL_S_PAGE_NO_GAME,
    HOL_S_PAGE_NO_START,
    HOL_S_PAGE_LESSONS,   /* the bar's lesson list (docs/teaching.md) */
    HOL_S_PAGE_LESSONS_WHY,
    HOL_S_PAGE_SEATED,    /* the bar's Seated box and its title */
    HOL_S_PAGE_SEATED_WHY,
    HOL_S_PAGE_SEND,      /* the Logs' "send to teacher" (class=CODE) */
    HOL_S_PAGE_SENT,      /* %s: the files sent */
    HOL_S_PAGE_SEND_FAILED, /* %s: the server's answer */
    HOL_S_COUNT
} hol_str_id;

/* The first of the page's ids: from it on the browser draws the text (in
 * its own fonts: not limited to the face's glyphs, nor to a buffer). */
#define HOL_S_PAGE_FIRST HOL_S_PAUSE_UNFOCUSED

/* A Dutch entry of a table of the languages (this one, the lessons'):
 * NULL in a build without Dutch (see the contract). */
#ifdef HOL_STR_NO_NL
#define HOL_STR_NL(s) NULL
#else
#define HOL_STR_NL(s) s
#endif

const char *hol_str(int lang, hol_str_id id);
/* The buffer (bytes with the NUL) the id's text is written into (a
 * label's: the 20 bytes an item's value shows, and its NUL). */
int hol_str_cap(hol_str_id id);
int hol_lang_parse(const char *tag);
const char *hol_lang_code(int lang);

#endif
