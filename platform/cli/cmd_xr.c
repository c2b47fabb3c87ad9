/* cmd_xr.c - `holonomy xr`: the headset app on the desktop's OpenXR runtime
 * (platform/openxr/hol_xr.h), through the session every platform runs
 * (core/hol_session.h): the same campaign, logs and recording as `play`,
 * so a headset session replays headless. Built in only with `make xr`
 * (XR=1; needs libopenxr-dev and GLX). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_session.h"
#include "../shell/hol_xr_pick.h"
#include "../shell/hol_xr_quad.h"
#include "cli.h"
#include "play_env.h"
#include "play_setup.h"
#include "play_study.h"
#include "play_track.h"
#ifdef HOL_XR
#include "../audio/hol_audio.h"
#include "../openxr/hol_xr.h"
#endif

const char *const cli_xr_usage =
    "usage: holonomy xr [LEVEL | --study FILE] [--frames N]\n"
    "                   [--log DIR [--append [--restart-participant]] [--resume]]\n"
    "                   [--participant ID] [--session N] [--meta KEY=VALUE]...\n"
    "                   [--record FILE] [--input FILE] [--space stage|local]\n"
    "                   [--play-area WxD] [--no-haptics] [--mute | --volume V]\n"
    "                   [--track-hz N] [--panel quad|scene] [--lang en|de|nl]\n"
    "                   [--check-frame K --check-dir DIR]\n"
    "                   [--tiling 4,Q] [--room CxR] [--cell M] [--seated]\n"
    "\n"
    "The headset app on this machine's OpenXR runtime (for example Monado):\n"
    "the room centred on the stage origin, north along stage -Z; the\n"
    "recentre action places it from the head. LEVEL is a level file (SPEC\n"
    "section 5); without one, the default campaign. Logs and the recording\n"
    "are those of 'holonomy play' (its --log, --append, --restart-participant, --resume,\n"
    "--participant and --record), so 'holonomy replay' runs a headset session again headless.\n"
    "Where the runtime gives the play area's bounds, the room and cell size\n"
    "are fitted to them (the most cells of at least 0.6 m, 0.1 m clear; a\n"
    "level's room or cell lines win) and an 'xr:' line says what was chosen.\n"
    "Controllers: confirm, menu, recentre, minimap; in the menu, restart\n"
    "(confirm's button) and quit (README: Headset, the bindings).\n"
    "\n"
    "  --seated        seated play (docs/teaching.md): the head walks\n"
    "                  nothing; a push of either thumbstick (the Vive's\n"
    "                  trackpad) takes one room step towards the look's\n"
    "                  nearest direction, with a short fade; recorded, so\n"
    "                  replay plays it again\n"
    "  --study FILE    a study's conditions in the order of the participant's\n"
    "                  number (--participant P07: 7), as 'holonomy play --study'\n"
    "  --frames N      request exit after N submitted frames\n"
    "  --log DIR       research logs (README: Research logs)\n"
    PLAY_ENV_USAGE
    PLAY_TRACK_USAGE
    "  --record FILE   record the session's input\n"
    "  --input FILE    scripted head motion: frame k takes the head pose of\n"
    "                  input line k (room coordinates; the simulated headset\n"
    "                  does not move), repeating; at most 100000 lines;\n"
    "                  a line's flags 200 (headset off) and 400 (position\n"
    "                  untracked) set the headset's state\n"
    "  --space S       the room's reference space: stage (the default: the\n"
    "                  play area, where the runtime has one, else local) or\n"
    "                  local (where the head starts, the floor 1.6 m below:\n"
    "                  seated, or no play area set up)\n"
    PLAY_GEOMETRY_USAGE
    "  --play-area WxD the play area in metres (for example 2.6x2.6), used\n"
    "                  instead of the runtime's stage bounds: a runtime that\n"
    "                  gives none, or a smaller area than it draws\n"
    "  --panel P       the world panel (text, prompts, menus, end screens,\n"
    "                  questionnaires): quad (the default) an OpenXR quad\n"
    "                  layer the runtime composites over the scene (crisp\n"
    "                  text; where the runtime cannot make its image, the\n"
    "                  scene instead, said in an 'xr:' line), or scene: drawn\n"
    "                  in each eye's image (docs/headset.md)\n"
    "  --mute          no sound; --volume V: 0..1 (default 1) times the\n"
    "                  sound's gain (OpenAL Soft, HRTF where offered; a line\n"
    "                  'xr: sound ...' says whether it plays; without a device\n"
    "                  or libopenal.so.1 it goes on silent; --input is silent;\n"
    "                  docs/sound.md)\n"
    CLI_LANG_USAGE
    "  --no-haptics    no controller pulses (by default a short one when a\n"
    "                  controller goes into a hedge or a tree trunk, a gentle\n"
    "                  one on both at each room step: docs/headset.md)\n"
    "  --check-frame K with --check-dir DIR: read eye 0 of frame K back from\n"
    "                  the swapchain, render the same eye with OSMesa, write\n"
    "                  both PNGs to DIR and print how many pixels differ; both\n"
    "                  eyes of frame K go to DIR too (xr-world-eyeE.png without\n"
    "                  the panel, xr-shown-eyeE.png as shown) with each eye's\n"
    "                  'render' arguments\n"
    "\n"
    "SIGINT, SIGTERM or SIGHUP end the OpenXR session (STOPPING), then the\n"
    "session is saved with the attempt in play 'aborted'.\n"
    "Prints 'xr: ...' progress lines (state changes, bindings, frames, the\n"
    "CPU time per stereo frame). Exit status: 0 ok, 1 failure (no runtime,\n"
    "no display, a runtime error), 2 bad input, 128+N after signal N.\n";

#define XR_SCRIPT_MAX 100000

typedef struct xr_opts {
    const char *level_path, *log_dir, *rec, *input_path, *check_dir, *participant, *study;
    long frames, check_frame;
    int append, restart_participant, resume;
    char participant_id[HOL_REC_ID_MAX]; /* --participant in its spelling */
    int space; /* 0 or HOL_XR_SPACE_LOCAL (hol_xr_desc.space) */
    int seated; /* --seated (hol_xr_desc.seated) */
    int panel; /* HOL_XR_PANEL_QUAD (0) or _SCENE (hol_xr_desc.panel) */
    play_geometry geo;
    float play_area[2]; /* --play-area (hol_xr_desc.play_area) */
    int no_haptics;     /* --no-haptics: fns.haptic NULL */
    int mute;           /* --mute */
    double volume;      /* --volume; -1: not given (1) */
    int track_hz;       /* --track-hz; 0: not given (10) */
    int lang;           /* --lang (core/hol_str.h); 0: English */
    play_env env;       /* --session, --meta */
    int argc;
    char **argv;
} xr_opts;

/* --play-area WxD: two sizes in metres, 0.5 to 100 each, "2.6x2.6". 0 ok. */
static int xr_play_area(const char *cmd, const char *val, float out[2])
{
    double w, d;
    if (!cli_parse_wxd(val, 0.5, 100, &w, &d)) {
        cli_error(cmd, 0, "--play-area '%.40s' is not WxD in metres, 0.5 to 100 each (2.6x2.6)",
                  val);
        return 1;
    }
    out[0] = (float)w;
    out[1] = (float)d;
    return 0;
}

static int xr_count(const char *cmd, const char *a, const char *val, xr_opts *o)
{
    size_t n = cli_parse_count(val);
    int zero_ok = !strcmp(a, "--check-frame") && !strcmp(val, "0");
    if ((!n && !zero_ok) || n > 100000000) {
        cli_error(cmd, 0, "%s '%.40s' is not a count in %d..100000000", a, val, zero_ok ? 0 : 1);
        return 1;
    }
    if (!strcmp(a, "--frames"))
        o->frames = (long)n;
    else
        o->check_frame = (long)n;
    return 0;
}

const char *const cli_xr_valued[] = {"--frames",      "--log",       "--record",
                                        "--input",       "--check-frame", "--check-dir",
                                        "--participant", "--space",    "--study", "--panel",
                                        PLAY_GEOMETRY_OPTIONS, "--play-area", "--volume",
                                        "--track-hz", "--lang", PLAY_ENV_OPTIONS, NULL};

/* The options that only store their value or set a flag. */
static const cli_store xr_store[] = {
    CLI_STORE_STR("--log", xr_opts, log_dir),
    CLI_STORE_STR("--record", xr_opts, rec),
    CLI_STORE_STR("--input", xr_opts, input_path),
    CLI_STORE_STR("--check-dir", xr_opts, check_dir),
    CLI_STORE_STR("--study", xr_opts, study),
    CLI_STORE_FLAG("--append", xr_opts, append, 1),
    CLI_STORE_FLAG("--no-haptics", xr_opts, no_haptics, 1),
    CLI_STORE_FLAG("--mute", xr_opts, mute, 1),
    CLI_STORE_FLAG("--restart-participant", xr_opts, restart_participant, 1),
    CLI_STORE_FLAG("--resume", xr_opts, resume, 1),
    CLI_STORE_FLAG("--seated", xr_opts, seated, 1),
    {NULL, 0, 0, 0}};

static int xr_options(const char *cmd, int argc, char **argv, xr_opts *o)
{
    static const char *const flags[] = {"--append", "--no-haptics", "--restart-participant",
                                        "--resume", "--mute", "--seated", NULL};
    memset(o, 0, sizeof *o);
    o->check_frame = -1;
    o->volume = -1;
    cli_opts p;
    cli_opts_init(&p, cmd, argc, argv, cli_xr_valued, flags);
    static const char *const repeatable[] = {"--meta", NULL};
    p.repeatable = repeatable;
    o->argc = argc, o->argv = argv;
    o->env.argc = argc, o->env.argv = argv;
    const char *a, *val;
    int r, bad = 0, g;
    while (!bad && (r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a && o->level_path) {
            cli_error(cmd, 0, "more than one LEVEL ('%.40s')", val);
            bad = 1;
        } else if (!a)
            o->level_path = val;
        else if (val && (g = play_geometry_value(cmd, a, val, &o->geo)) != 0) /* flags: no value */
            bad = g < 0;
        else if (val && (g = play_env_value(cmd, a, val, &o->env)) != 0)
            bad = g < 0;
        else if (!strcmp(a, "--frames") || !strcmp(a, "--check-frame"))
            bad = xr_count(cmd, a, val, o);
        else if (cli_store_opt(xr_store, a, val, o))
            ;
        else if (!strcmp(a, "--volume"))
            bad = cli_volume_value(cmd, val, &o->volume) != 0;
        else if (!strcmp(a, "--track-hz"))
            bad = play_track_value(cmd, val, &o->track_hz);
        else if (!strcmp(a, "--lang"))
            bad = cli_lang_value(cmd, val, &o->lang) != 0;
        else if (!strcmp(a, "--play-area"))
            bad = xr_play_area(cmd, val, o->play_area);
        else if (!strcmp(a, "--panel")) {
            bad = strcmp(val, "quad") && strcmp(val, "scene");
            if (bad)
                cli_error(cmd, 0, "--panel '%.40s' is neither quad nor scene", val);
            o->panel = !strcmp(val, "scene") ? HOL_XR_PANEL_SCENE : HOL_XR_PANEL_QUAD;
        } else if (!strcmp(a, "--space")) {
            bad = strcmp(val, "stage") && strcmp(val, "local");
            if (bad)
                cli_error(cmd, 0, "--space '%.40s' is neither stage nor local", val);
            o->space = !strcmp(val, "local") ? HOL_XR_SPACE_LOCAL : 0;
        }
        else if (!(bad = play_participant(cmd, val, o->participant_id)))
            o->participant = o->participant_id;
    }
    if (bad || r < 0)
        return CLI_EXIT_USAGE;
#define G(x) ((x) ? HOL_SHELL_ON : HOL_SHELL_OFF)
    const unsigned char given[HOL_SHELL_OPT_COUNT] = {
        [HOL_SHELL_OPT_LEVEL] = G(o->level_path), [HOL_SHELL_OPT_STUDY] = G(o->study),
        [HOL_SHELL_OPT_APPEND] = G(o->append), [HOL_SHELL_OPT_LOG] = G(o->log_dir),
        [HOL_SHELL_OPT_RESTART] = G(o->restart_participant),
        [HOL_SHELL_OPT_RESUME] = G(o->resume), [HOL_SHELL_OPT_MUTE] = G(o->mute),
        [HOL_SHELL_OPT_VOLUME] = G(o->volume >= 0),
        [HOL_SHELL_OPT_CHECK_FRAME] = G(o->check_frame >= 0),
        [HOL_SHELL_OPT_CHECK_DIR] = G(o->check_dir)};
#undef G
    if (play_opts_check(cmd, given, &o->env, o->log_dir, o->track_hz))
        return CLI_EXIT_USAGE;
    o->append |= o->resume;
    const cli_path in[] = {{"LEVEL", o->level_path}, {"--input", o->input_path},
                           {"--study", o->study}};
    const cli_path out[] = {{"--record", o->rec}, {"--log", o->log_dir},
                            {"--check-dir", o->check_dir}};
    const cli_outs outs = {out, 3, o->log_dir};
    if (cli_check_reads(cmd, in, 3, &outs))
        return CLI_EXIT_USAGE;
    return cli_require_folder(cmd, "--check-dir", o->check_dir);
}

/* The scripted head motion: every record of the file (at most
 * XR_SCRIPT_MAX). 0 ok, else the exit status (reported). */
static int xr_script(const char *cmd, const char *path, hol_input **out, long *n)
{
    static play_input pi;
    *out = NULL;
    *n = 0;
    if (!path)
        return 0;
    int st = play_input_open(cmd, path, 0, &pi);
    if (st)
        return st;
    hol_input *script = malloc(XR_SCRIPT_MAX * sizeof *script);
    int r = script ? 1 : -CLI_EXIT_FAIL;
    if (!script)
        cli_error(cmd, 0, "out of memory");
    while (r > 0 && (r = play_input_next(&pi, &script[*n])) > 0)
        if (++*n >= XR_SCRIPT_MAX) {
            cli_error(cmd, 0, "--input '%.200s' has more than %d lines", path, XR_SCRIPT_MAX);
            r = -CLI_EXIT_USAGE;
        }
    play_input_close(&pi);
    if (r < 0) {
        free(script);
        return -r;
    }
    *out = script;
    return 0;
}

#ifdef HOL_XR
/* The session is made once the headset knows its play area (xr_fit):
 * levels that name neither a room nor a cell play the room and cell the
 * stage bounds hold (core/hol_fit.h), unless the command line names them. */
typedef struct xr_ctx {
    const char *cmd;
    hol_level *levels;
    int nlevels;
    play_out *out;
    hol_rec_meta meta;
    int append;
    int geo_named; /* --room or --cell given: no fit */
    hol_session *s;
    int st;        /* the session's opening status */
    int sound;     /* 1: try to open the sound at the first step */
    double volume;
    hol_audio_feed snd; /* its au NULL: silent */
    const xr_opts *o;
    char runtime[160], gl[160]; /* the host callback's (environment.csv) */
    int eye_w, eye_h;
    int env_due;   /* the session is open, its environment row not written */
} xr_ctx;

/* The sound opens at the first step (the session is up); its line goes
 * with xr's progress lines on stdout. It is held while the session is not
 * FOCUSED (xr_focus). */
static void xr_sound(xr_ctx *c)
{
    if (c->sound) {
        c->sound = 0;
        char msg[160];
        if (hol_audio_feed_open(&c->snd, c->volume, msg, sizeof msg))
            printf("xr: sound off: %s\n", msg);
        else
            printf("xr: sound: OpenAL Soft%s\n", hol_audio_hrtf(c->snd.au) ? ", HRTF" : "");
    }
    hol_audio_feed_step(&c->snd, hol_session_app(c->s));
}

static void xr_focus(void *user, int focused)
{
    hol_audio_feed_hold(&((xr_ctx *)user)->snd, !focused);
}

static void xr_host(void *user, const char *runtime, const char *gl, int eye_w, int eye_h)
{
    xr_ctx *c = user;
    snprintf(c->runtime, sizeof c->runtime, "%s", runtime);
    snprintf(c->gl, sizeof c->gl, "%s", gl);
    c->eye_w = eye_w, c->eye_h = eye_h;
}

static void xr_apply_fit(xr_ctx *c, const hol_fit *f)
{
    int n = 0;
    for (int i = 0; i < c->nlevels; i++) {
        int changed = 0;
        hol_err e = hol_fit_level(&c->levels[i], f, &changed);
        if (e)
            printf("xr: level %s keeps its room: the fitted one refuses it (%s)\n",
                   c->levels[i].name, hol_err_str(e));
        n += changed;
    }
    printf("xr: the fitted room plays in %d of %d level(s) (the others name their own)\n", n,
           c->nlevels);
}

static int xr_fit(void *user, const hol_fit *f)
{
    xr_ctx *c = user;
    if (f && c->geo_named)
        printf("xr: --room/--cell given: the play area's fit is not used\n");
    else if (f)
        xr_apply_fit(c, f);
    c->st = play_session_open(c->cmd, c->out, c->levels, c->nlevels, &c->meta, c->append, &c->s);
    c->env_due = !c->st; /* written once the controller and refresh rate are known */
    if (!c->st)
        play_study_announce();
    return c->st != 0;
}

/* environment.csv's row (play_env.h), once the frames tell the hands'
 * profile and the refresh rate (hol_xr_app.h), or at the run's end. */
static void xr_environment(void *user, const char *controller, double refresh_hz,
                           const char *how)
{
    xr_ctx *c = user;
    (void)how;
    if (!c->env_due)
        return;
    c->env_due = 0;
    play_env_host h = {"openxr", c->runtime, c->gl, controller, refresh_hz, c->eye_w, c->eye_h};
    if (play_env_write(c->cmd, c->o->log_dir, &c->o->env, c->meta.session, c->o->participant,
                       c->meta.study_sha256, &h, c->o->argc, c->o->argv) && !c->st)
        c->st = CLI_EXIT_FAIL;
}

static const hol_app_view *xr_view(void *user)
{
    xr_ctx *c = user;
    return c->s ? hol_app_get_view(hol_session_app(c->s)) : NULL;
}

static int xr_step(void *user, const hol_input *in, const hol_app_view **out_view)
{
    hol_session *s = ((xr_ctx *)user)->s;
    int over = 0;
    hol_err err = hol_session_step(s, in, &over);
    *out_view = hol_app_get_view(hol_session_app(s));
    if (err)
        cli_error("xr", 0, "%s", hol_session_message(s));
    else
        xr_sound(user);
    return err ? -1 : over ? 1 : 0;
}

static struct hol_world *xr_world(void *user)
{
    return hol_app_world(hol_session_app(((xr_ctx *)user)->s));
}

static int xr_level_started(void *user)
{
    return hol_app_get_events(hol_session_app(((xr_ctx *)user)->s))->level_started;
}

/* The controllers' pulses of the last step (core/hol_haptic.h). */
static const hol_haptic *xr_haptic(void *user)
{
    return &hol_app_get_events(hol_session_app(((xr_ctx *)user)->s))->haptic;
}

/* A signal asks the OpenXR session to end (STOPPING, then the save). */
static int xr_poll(void *user)
{
    (void)user;
    return cli_caught_signal() != 0;
}

static int xr_run(const xr_opts *o, xr_ctx *c, const hol_input *script, long nscript)
{
    hol_xr_desc d;
    memset(&d, 0, sizeof d);
    d.frames = o->frames;
    d.check_frame = o->check_frame;
    d.check_dir = o->check_dir;
    d.script = script;
    d.nscript = nscript;
    d.space = o->space;
    d.seated = o->seated;
    d.panel = o->panel;
    d.play_area[0] = o->play_area[0];
    d.play_area[1] = o->play_area[1];
    hol_xr_app_fns fns = {.user = c, .step = xr_step, .world = xr_world,
                          .level_started = xr_level_started, .poll_platform = xr_poll,
                          .fit = xr_fit, .view = xr_view,
                          .haptic = o->no_haptics ? NULL : xr_haptic, .host = xr_host,
                          .environment = xr_environment, .focus = xr_focus};
    int rc = hol_xr_run(&d, &fns);
    xr_environment(c, "", 0, ""); /* a run that failed before telling */
    return c->st ? c->st : rc ? CLI_EXIT_FAIL : CLI_EXIT_OK;
}
#endif

int cli_cmd_xr(int argc, char **argv)
{
    const char *cmd = "xr";
    xr_opts o;
    int st = xr_options(cmd, argc, argv, &o);
    if (st)
        return st;
    static hol_level levels[HOL_SESSION_MAX_LEVELS];
    int nlevels = 0;
    play_out out;
    memset(&out, 0, sizeof out);
    hol_input *script = NULL;
    long nscript = 0;
    char study[HOL_REC_ID_MAX] = "";
    const cli_path outp[] = {{"--record", o.rec}, {"--log", o.log_dir},
                             {"--check-dir", o.check_dir}};
    const cli_outs outs = {outp, 3, o.log_dir};
    st = o.study ? play_study_levels(cmd, o.study, o.participant,
                                     o.append && !o.restart_participant && !o.resume
                                         ? o.log_dir : NULL,
                                     &outs, levels, &nlevels, study)
                 : play_levels(cmd, o.level_path, NULL, CLI_SEED_DEFAULT, &o.geo, levels,
                               &nlevels);
    if (!st)
        st = play_geometry_apply(cmd, &o.geo, levels, nlevels);
    if (!st && o.resume)
        st = play_study_resume(cmd, o.log_dir, study, o.participant, levels, &nlevels);
    if (!st)
        st = xr_script(cmd, o.input_path, &script, &nscript);
#ifdef HOL_XR
    xr_ctx c = {.cmd = cmd, .levels = levels, .nlevels = nlevels, .out = &out,
                .append = o.append, .o = &o, .geo_named = o.geo.cols > 0 || o.geo.cell_m > 0,
                .volume = o.volume < 0 ? 1.0 : o.volume};
    c.sound = !o.mute && c.volume > 0 && !o.input_path;
    cli_catch_signals();
    if (!st)
        st = play_out_open(cmd, o.log_dir, o.append, o.rec, &out);
    out.track_hz = o.track_hz;
    out.lang = o.lang;
    if (!st) {
        hol_sink_posix_meta(&c.meta, o.participant);
        snprintf(c.meta.study, sizeof c.meta.study, "%s", study);
        if (o.resume) /* unanswered questions first (issue 39), else the ready screen */
            play_study_resume_meta(&c.meta);
        st = play_env_meta(cmd, &o.env, o.study, &c.meta, &out.study_text, &out.study_len)
                 ? CLI_EXIT_FAIL
                 : xr_run(&o, &c, script, nscript);
    }
    hol_audio_feed_close(&c.snd);
    int end = play_session_end(cmd, c.s, cli_caught_signal() != 0);
    st = st ? st : end;
    if (!st && cli_caught_signal())
        st = 128 + cli_caught_signal();
#else
    if (!st) {
        cli_error(cmd, 0, "this build has no OpenXR; build with 'make xr' (needs "
                          "libopenxr-dev, GLX; see README 'Headset')");
        st = CLI_EXIT_FAIL;
    }
#endif
    play_out_close(&out);
    free(script);
    return st;
}
