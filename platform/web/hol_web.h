/* hol_web.h - the browser platform's loop state (internal to
 * platform/web/): the WebGL 2 context, the renderer, the game session,
 * the pancake devices and the WebXR session's state. One instance (the
 * page runs one game); hol_web_main.c owns setup and the pancake loop,
 * hol_web_xr_loop.c the XR frames, hol_web_game.c the session.
 */
#ifndef HOL_WEB_H
#define HOL_WEB_H

#include <stdint.h>

#include "../../core/hol_app.h"
#include "../../core/hol_fit.h"
#include "../../render/hol_render.h"
#include "hol_web_input.h"
#include "hol_web_xr.h"

typedef struct hol_web {
    int gl;                  /* EMSCRIPTEN_WEBGL_CONTEXT_HANDLE */
    hol_render *rnd;
    hol_web_pancake pan;
    double t0_ms;            /* performance.now() at the start: time 0 */
    double last_t, last_frame_t;
    long frames;             /* app steps, pancake and XR */
    int over;                /* the session is over (quit, campaign done) */
    int drawn_over;          /* the last view was drawn after that */
    int drawn_first;         /* the first frame was drawn */
    int progs_left;          /* shader programs still to compile (all in
                                the pancake frame after the first; <= 0
                                none) */
    int drawn_w, drawn_h;    /* the canvas size of the last pancake frame:
                                a new size is checked for GL errors */
    int xr_checked;          /* this XR session's first frame was checked */
    /* F2: the frame time on the view, as the desktop's (FPS and the main
     * thread's ms a frame: step and GL calls issued, over the last second) */
    int overlay;
    double stats_t0, stats_ms;
    long stats_frames;
    char overlay_text[48];
    double cpu_total_ms;     /* every frame's main-thread ms since the last */
    long cpu_total_frames;   /* hol_web_cpu_mean_ms(1) (make bench-web) */
    const char *pause_told;  /* the pause reason last told to the page
                                (NULL: playing; HOL_WEB_UNTOLD: nothing yet) */
    int failed;
    int geo_named;           /* the page named the room (1) or the cell (2):
                                the play area's fit leaves them */
    int have_fit;            /* bounded-floor gave a polygon: the fit */
    hol_fit fit;
    double fit_t;            /* the XR time it was told from (HUD note) */
    hol_app_view note;       /* the view drawn while the fit is told */
    /* WebXR */
    int xr_active;
    hol_web_xr_state xr;
    int xr_seat_latch;       /* ?seated=1 in the headset: the thumbsticks'
                                push, one room step (hol_shell_seat.h) */
    hol_web_xr_frame xf;     /* written by the glue each XR frame */
    long xr_frames, xr_two_views, xr_focused;
    double xr_cpu_ms[4096];  /* per XR frame: step and both eyes (ms) */
    int xr_ncpu;
    int xr_recentred;        /* the reference space was reset (the browser's
                                recentre): told on the next record with a head */
    int xr_off;              /* the session was hidden (the headset off):
                                told on the next record */
    /* read-back check of both eyes at one XR frame (make web-test) */
    long check_frame;        /* -1: none */
    uint8_t *check_px[4]; /* the check frame's eyes: 0, 1 without the HUD;
                             2, 3 with the UI panel (neither with the
                             body: holonomy render draws none) */
    int check_w[4], check_h[4];
    hol_camera check_cam[2];
    hol_room check_user[2];
} hol_web;

extern hol_web hol_web_g;

/* hol_web_game.c: the session (levels, logs, recording) */
int hol_web_game_open(char *msg, size_t cap);
/* 0 go on, 1 over, -1 failure (reported). */
int hol_web_game_step(const hol_input *in);
hol_app *hol_web_game_app(void);
/* the page's language (hol_lang, core/hol_str.h: config "lang") */
int hol_web_game_lang(void);
void hol_web_game_finish(void);
/* the session's metadata (id, participant), NULL before it opened */
const struct hol_rec_meta *hol_web_game_meta(void);
/* The play area's fit applied (fit on entry, issue 36): where the page
 * names no room or cell, plays no study and the session is still in its
 * first level, the session in play ends as a reload ends it (its attempt
 * aborted, every file committed) and a new one plays the same levels in
 * the room of cols x rows cells of cell (the format of ?room= and ?cell=).
 * 1 applied, 0 not (told only), -1 failure (msg). */
int hol_web_game_refit(const char *room, const char *cell, char *msg, size_t cap);

/* hol_web_env.c: environment.csv (docs/research.md, Session metadata).
 * init: the GL renderer asked once, at setup (no GL call in the frames);
 * pancake: a frame outside VR (the `web` row once the rate is measured);
 * xr: a WebXR session began (1: its row armed; 0, ended: nothing, a
 * session ended before its row has none); xr_frame: an XR frame and the
 * hands' device (its row once the rate is known: XRSession.frameRate with
 * an input source present, else 60 frames measured). */
void hol_web_env_init(void);
void hol_web_env_pancake(double t_ms);
void hol_web_env_xr(int on);
void hol_web_env_xr_frame(double t_ms, uint32_t device);
/* the end line, as `holonomy play` prints it */
void hol_web_game_print_end(void);

/* hol_web_main.c: F2's figures, a frame of c0..now (emscripten_get_now) */
void hol_web_stats_add(double c0);
/* F2's line while it is on, else NULL */
const char *hol_web_overlay(void);

/* hol_web_main.c: one step of the session and what follows it (a level
 * started: meshes rebuilt; over: the end line, the files committed, the
 * page told). 0 go on, 1 over or failed. */
int hol_web_step(const hol_input *in);

/* hol_web_sound.c: ?sound=0|1 read (-1: neither); one step's sound
 * (over: the loops stop); the looping sources playing now. */
int hol_web_sound_config(void);
void hol_web_sound_step(int over);
int hol_web_sound_active(void);

#endif
