/* cmd_play.c - `holonomy play`: the desktop game in an EGL/X11 window,
 * through the session every platform runs (core/hol_session.h). Its
 * options, its setup (levels, input, outputs, window, renderer, game
 * controller) and its frame loop. */
#include <dlfcn.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <signal.h>
#include <unistd.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_session.h"
#include "../../core/hol_sha256.h"
#include "../../render/hol_app_frame.h"
#include "../../render/hol_render.h"
#include "../egl/hol_egl.h"
#include "../egl/hol_egl_x11.h"
#include "../hid/hol_hid_dev.h"
#include "../hid/hol_hid_link.h"
#include "cli.h"
#include "../audio/hol_audio.h"
#include "play_env.h"
#include "play_setup.h"
#include "play_stats.h"
#include "play_study.h"
#include "play_track.h"
#include "../shell/hol_shell_seat.h"

const char *const cli_play_usage =
    "usage: holonomy play [LEVEL | --mode tutorial|flag|keys|explore | --lesson N |\n"
    "                      --study FILE]\n"
    "                     [--seed S] [--log DIR [--append [--restart-participant]]] [--participant ID]\n"
    "                     [--resume] [--session N] [--meta KEY=VALUE]...\n"
    "                     [--record FILE]\n"
    "                     [--frames N] [--input FILE] [--size WxH]\n"
    "                     [--no-gamepad | --gamepad-replay FILE] [--snap-turn DEG]\n"
    "                     [--seated] [--stats] [--tiling 4,Q] [--room CxR] [--cell M]\n"
    "                     [--mute | --volume V] [--track-hz N] [--lang en|de|nl]\n"
    "\n"
    "Play in a desktop window (EGL on X11; also under Xvfb). LEVEL is a level\n"
    "file (SPEC section 5); --mode plays a level of that mode made from the seed\n"
    "(flag 5 steps from the start; 3 keys 2..3 steps out and the chest at 5;\n"
    "with --tiling 4,4 or 4,8 no farther than the room reaches);\n"
    "neither: the default campaign (the tutorial, three flags at distance 3, 5,\n"
    "7, then two keys-and-chest levels).\n"
    "\n"
    "  W/S or Up/Down   walk forward/back      A/D          step sideways\n"
    "  Left/Right       turn (--snap-turn: snap) PgUp/PgDn  look up/down\n"
    "  mouse drag       look (left button)     P            pause menu\n"
    "  R                restart the level      M            minimap: HUD, hand, off\n"
    "  Enter/Space      next level, or finish after the last (end screen);\n"
    "                   in the menu: restart\n"
    "  F3               debug text (tile, cell)  F2        frame time (fps, CPU)\n"
    "  Esc/Q            quit\n"
    "  --seated         seated play: no walking; W/S, Up/Down, A/D (or the\n"
    "                   controller's stick) take one room step a press, with\n"
    "                   a short fade; Left/Right snap turn (90 degrees unless\n"
    "                   --snap-turn); recorded, so replay plays it again\n"
    "\n"
    "A game controller (the first found; plugged in later, it joins) plays too:\n"
    "left stick walks, right stick turns and looks, south button confirms,\n"
    "west/select/hat down cycle the minimap, start/mode open the menu (in it,\n"
    "south restarts and east quits); its axes add to the keys' (clamped), its\n"
    "buttons OR with them. Unplugged mid-game, the game pauses until it is back\n"
    "or a key is used. Prompts name the buttons of what was used last.\n"
    "\n"
    "  --mode M        tutorial (four lessons), flag, keys or explore\n"
    "  --lesson N      a lesson for a class, 1..6 (docs/teaching.md): predict,\n"
    "                  walk, check; the level 'lesson N' (with --tiling 4,4 the\n"
    "                  flat comparison)\n"
    "  --study FILE    play a study's conditions in the order of the participant's\n"
    "                  number (--participant P07: 7; README: Study designs):\n"
    "                  its practice levels, then each condition's levels; the\n"
    "                  logs name the study, condition and position\n"
    "  --seed S        seed of --mode's level or the campaign's first (decimal or\n"
    "                  0x hex; default 1)\n"
    "  --log DIR       research logs, written as the game goes (README: Research\n"
    "                  logs): DIR/summary.csv, DIR/steps-NNN.csv,\n"
    "                  DIR/head-NNN.csv and DIR/track-NNN.csv per level\n"
    "                  attempt; DIR is made when its\n"
    "                  parent exists; a DIR holding logs is refused without\n"
    "  --append        add this session to the logs already in DIR (finishing\n"
    "                  the attempts a killed session left: end 'killed')\n"
    "  --restart-participant  with --study and --append: start a participant\n"
    "                  who already has rows of this study in DIR again from\n"
    "                  the start of their order (else refused: one line)\n"
    "  --resume        with --study and --log: continue the participant at the\n"
    "                  first level of their order not finished in DIR (no\n"
    "                  attempt ended done or timeout; README: Research logs),\n"
    "                  appending to DIR; positions keep their numbers\n"
    PLAY_ENV_USAGE
    PLAY_TRACK_USAGE
    "  --participant ID  the participant (1..63 letters, digits, '.', '_', '-';\n"
    "                  not first '-'), in the summary and the recording; a\n"
    "                  number is written P and two digits or more: 2, 002\n"
    "                  and p2 are P02 (P-02 is refused as ambiguous)\n"
    "  --record FILE   record the session (replay with 'holonomy replay'),\n"
    "                  written as FILE.live and renamed to FILE at the end\n"
    "  --frames N      stop after N frames\n"
    "  --input FILE    drive the game from recorded input lines (a recording or\n"
    "                  bare lines) instead of the keyboard; frames are the lines\n"
    "  --size WxH      window size (default 960x720)\n"
    "  --snap-turn DEG  Left/Right turn by DEG degrees a press (a divisor of 360\n"
    "                  from 1 to 180; 90 keeps the room's axes on the screen's),\n"
    "                  to the next multiple of DEG, so the look stays aligned\n"
    "  --stats         print the frame rate and the CPU ms a frame on stderr,\n"
    "                  every second and at the end (CPU: the whole process,\n"
    "                  the software rasterizer's threads included)\n"
    PLAY_GEOMETRY_USAGE
    CLI_LANG_USAGE
    "  --no-gamepad    do not use game controllers\n"
    "  --mute          no sound; --volume V: 0..1 (default 1) times the\n"
    "                  forest's and the cues' gain (OpenAL Soft, HRTF where\n"
    "                  offered; docs/sound.md). Without an audio device, or\n"
    "                  without libopenal.so.1, one warning line and play goes\n"
    "                  on silent. A scripted play (--input) is silent: replay\n"
    "                  --wav renders its sound\n"
    "  --gamepad-replay FILE\n"
    "                  the controller is a script of plugs, reports and unplugs\n"
    "                  (README: Gamepads) on the game's clock, not a device; with\n"
    "                  --input the two are merged as keyboard and pad are\n"
    "\n"
    "At the end it prints 'level NAME STATE steps S optimum O tile ADDR cell C,R'\n"
    "(STATE playing, done, timeout at the level's time limit, or quit).\n"
    "Closing the window, SIGINT, SIGTERM or SIGHUP end the session cleanly: the\n"
    "attempt in play is logged with end 'aborted', logs and recording are\n"
    "saved. Exit status: 0 ok (also a closed window), 1 failure, 2 bad input,\n"
    "128+N after signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP).\n";

typedef struct play_opts {
    const char *level_path, *mode, *log_dir, *rec, *input_path, *pad_script, *participant;
    const char *study;
    play_geometry geo;
    uint64_t seed;
    long frames;
    int w, h, use_pad, append, snap_deg, stats, restart_participant, resume, mute, seated;
    int track_hz; /* --track-hz; 0: not given (10) */
    int lesson;   /* --lesson N; 0: none */
    int lang;     /* --lang (core/hol_str.h); 0: English */
    double volume;
    play_env env; /* --session, --meta */
    char participant_id[HOL_REC_ID_MAX]; /* --participant in its spelling */
    int argc;
    char **argv;
} play_opts;

typedef struct play_ctx {
    const char *cmd;
    play_opts o;
    hol_level levels[HOL_SESSION_MAX_LEVELS];
    int nlevels;
    char study[HOL_REC_ID_MAX]; /* --study: its name */
    char study_sha256[HOL_SHA256_HEX]; /* and its hash ("": none) */
    play_input input;
    int has_input;
    play_out out;
    hol_session *s;
    hol_x11 xw;
    int has_window;
    hol_render *r;
    hol_x11_keys keys;
    hol_hid_script script;
    hol_hid_dev pad;
    hol_hid_link link;
    int use_pad;
    int seat_latch; /* --seated: hol_shell_seat's */
    double t0, last_t;
    frame_stats fs;
    int overlay; /* F2: the frame time drawn */
    int drawn_w, drawn_h; /* the window's size at the last frame: a new one
                             is checked for GL errors (no frame waits else) */
    hol_audio_feed snd;   /* its au NULL: silent */
    /* environment.csv's row waits for the measured present rate when
     * XRandR gives none (play_env_due) */
    int env_due;
    long swaps;
    double swap_first, swap_last, refresh_hz;
    char session[HOL_REC_ID_MAX];
    char gl[160]; /* GL_RENDERER, read at the start (no GL call later) */
} play_ctx;

/* ---- options ------------------------------------------------------------------ */

static int play_value(const char *cmd, const char *a, const char *val, play_opts *o)
{
    int g = play_geometry_value(cmd, a, val, &o->geo);
    if (!g)
        g = play_env_value(cmd, a, val, &o->env);
    if (g)
        return g < 0;
    if (!strcmp(a, "--participant")) {
        if (play_participant(cmd, val, o->participant_id))
            return 1;
        o->participant = o->participant_id;
    } else if (!strcmp(a, "--seed")) {
        if (!cli_parse_u64(val, &o->seed)) {
            cli_error(cmd, 0, "--seed '%.40s' is not an unsigned 64-bit number", val);
            return 1;
        }
    } else if (!strcmp(a, "--frames")) {
        size_t n = cli_parse_count(val);
        if (!n || n > 100000000) {
            cli_error(cmd, 0, "--frames '%.40s' is not a count in 1..100000000", val);
            return 1;
        }
        o->frames = (long)n;
    } else if (!strcmp(a, "--size")) {
        return cli_parse_size(cmd, val, &o->w, &o->h);
    } else if (!strcmp(a, "--snap-turn")) {
        size_t n = cli_parse_count(val);
        if (!n || n > 180 || 360 % n) {
            cli_error(cmd, 0, "--snap-turn '%.40s' is not a divisor of 360 in 1..180", val);
            return 1;
        }
        o->snap_deg = (int)n;
    } else if (!strcmp(a, "--volume")) {
        return cli_volume_value(cmd, val, &o->volume) ? 1 : 0;
    } else if (!strcmp(a, "--track-hz")) {
        return play_track_value(cmd, val, &o->track_hz);
    } else if (!strcmp(a, "--lesson")) {
        return play_lesson_value(cmd, val, &o->lesson);
    } else if (!strcmp(a, "--lang")) {
        return cli_lang_value(cmd, val, &o->lang) ? 1 : 0;
    }
    return 0;
}

const char *const cli_play_valued[] = {"--mode",  "--seed",  "--log",  "--record",
                                          "--frames", "--input", "--size", "--gamepad-replay",
                                          "--participant", "--snap-turn", "--study",
                                          "--volume", "--track-hz", "--lesson", "--lang", PLAY_GEOMETRY_OPTIONS, PLAY_ENV_OPTIONS, NULL};

/* The options that only store their value or set a flag. */
static const cli_store play_store[] = {
    CLI_STORE_STR("--mode", play_opts, mode),
    CLI_STORE_STR("--log", play_opts, log_dir),
    CLI_STORE_STR("--record", play_opts, rec),
    CLI_STORE_STR("--input", play_opts, input_path),
    CLI_STORE_STR("--gamepad-replay", play_opts, pad_script),
    CLI_STORE_STR("--study", play_opts, study),
    CLI_STORE_FLAG("--no-gamepad", play_opts, use_pad, 0),
    CLI_STORE_FLAG("--append", play_opts, append, 1),
    CLI_STORE_FLAG("--stats", play_opts, stats, 1),
    CLI_STORE_FLAG("--mute", play_opts, mute, 1),
    CLI_STORE_FLAG("--restart-participant", play_opts, restart_participant, 1),
    CLI_STORE_FLAG("--resume", play_opts, resume, 1),
    CLI_STORE_FLAG("--seated", play_opts, seated, 1),
    {NULL, 0, 0, 0}};

static int play_options(const char *cmd, int argc, char **argv, play_opts *o)
{
    static const char *const flags[] = {"--no-gamepad", "--append", "--stats",
                                        "--restart-participant", "--resume", "--mute",
                                        "--seated", NULL};
    memset(o, 0, sizeof *o);
    o->seed = CLI_SEED_DEFAULT;
    o->w = 960, o->h = 720, o->use_pad = 1, o->volume = -1;
    cli_opts p;
    cli_opts_init(&p, cmd, argc, argv, cli_play_valued, flags);
    static const char *const repeatable[] = {"--meta", NULL};
    p.repeatable = repeatable;
    o->argc = argc, o->argv = argv;
    o->env.argc = argc, o->env.argv = argv;
    const char *a, *val;
    int r;
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a) {
            if (o->level_path) {
                cli_error(cmd, 0, "more than one LEVEL ('%.40s')", val);
                return CLI_EXIT_USAGE;
            }
            o->level_path = val;
        } else if (!cli_store_opt(play_store, a, val, o) && play_value(cmd, a, val, o)) {
            return CLI_EXIT_USAGE;
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
#define G(x) ((x) ? HOL_SHELL_ON : HOL_SHELL_OFF)
    const unsigned char given[HOL_SHELL_OPT_COUNT] = {
        [HOL_SHELL_OPT_LEVEL] = G(o->level_path), [HOL_SHELL_OPT_MODE] = G(o->mode),
        [HOL_SHELL_OPT_STUDY] = G(o->study), [HOL_SHELL_OPT_NO_GAMEPAD] = G(!o->use_pad),
        [HOL_SHELL_OPT_PAD_REPLAY] = G(o->pad_script), [HOL_SHELL_OPT_APPEND] = G(o->append),
        [HOL_SHELL_OPT_LOG] = G(o->log_dir), [HOL_SHELL_OPT_RESTART] = G(o->restart_participant),
        [HOL_SHELL_OPT_RESUME] = G(o->resume), [HOL_SHELL_OPT_MUTE] = G(o->mute),
        [HOL_SHELL_OPT_VOLUME] = G(o->volume >= 0)};
#undef G
    if (play_opts_check(cmd, given, &o->env, o->log_dir, o->track_hz))
        return CLI_EXIT_USAGE;
    if (o->lesson && (o->level_path || o->mode || o->study)) {
        cli_error(cmd, 0, "--lesson plays one lesson: give no LEVEL, --mode or --study with it");
        return CLI_EXIT_USAGE;
    }
    o->append |= o->resume;
    const cli_path in[] = {{"LEVEL", o->level_path}, {"--input", o->input_path},
                           {"--gamepad-replay", o->pad_script}, {"--study", o->study}};
    const cli_path out[] = {{"--record", o->rec}, {"--log", o->log_dir}};
    const cli_outs outs = {out, 2, o->log_dir};
    return cli_check_reads(cmd, in, 4, &outs);
}

/* ---- setup ---------------------------------------------------------------------- */

/* Everything that reads or checks files, before the window opens. */
static int play_prepare_files(play_ctx *c)
{
    const play_opts *o = &c->o;
    int st = o->pad_script ? play_load_pad_script(c->cmd, o->pad_script, &c->script) : 0;
    if (!st)
        st = play_out_open(c->cmd, o->log_dir, o->append, o->rec, &c->out);
    c->out.track_hz = o->track_hz;
    c->out.lang = o->lang;
    const cli_path out[] = {{"--record", o->rec}, {"--log", o->log_dir}};
    const cli_outs outs = {out, 2, o->log_dir};
    if (!st && o->study)
        st = play_study_levels(c->cmd, o->study, o->participant,
                               o->append && !o->restart_participant && !o->resume
                                   ? o->log_dir : NULL,
                               &outs, c->levels, &c->nlevels, c->study);
    else if (!st && o->lesson)
        st = play_lesson_level(c->cmd, o->lesson, c->levels, &c->nlevels);
    else if (!st)
        st = play_levels(c->cmd, o->level_path, o->mode, o->seed, &o->geo, c->levels,
                             &c->nlevels);
    if (!st)
        st = play_geometry_apply(c->cmd, &o->geo, c->levels, c->nlevels);
    if (!st && o->resume)
        st = play_study_resume(c->cmd, o->log_dir, c->study, o->participant, c->levels,
                               &c->nlevels);
    if (!st && o->input_path) {
        st = play_input_open(c->cmd, o->input_path, 0, &c->input);
        c->has_input = !st;
    }
    return st;
}

static void play_open_pad(play_ctx *c)
{
    c->use_pad = c->o.pad_script || (c->o.use_pad && !c->o.input_path);
    hol_err pad_open = HOL_EOPEN;
    if (c->o.pad_script)
        pad_open = hol_hid_dev_open_backend(&c->pad, hol_hid_script_backend(&c->script), 0.0);
    else if (c->use_pad)
        pad_open = hol_hid_dev_open_first(&c->pad);
    if (pad_open == HOL_OK)
        fprintf(stderr, "play: game controller: %s (%04x:%04x)\n",
                c->pad.info.name[0] ? c->pad.info.name : "unnamed", c->pad.info.vid,
                c->pad.info.pid);
}

/* Sound unless muted, at volume 0 or scripted; a missing device is one
 * warning line, then silence. */
static void play_open_audio(play_ctx *c)
{
    double v = c->o.volume < 0 ? 1.0 : c->o.volume;
    if (c->o.mute || v == 0 || c->o.input_path)
        return;
    char msg[160];
    if (hol_audio_feed_open(&c->snd, v, msg, sizeof msg))
        fprintf(stderr, "holonomy play: warning: %s: playing silent\n", msg);
}

static void play_sound(play_ctx *c)
{
    hol_audio_feed_step(&c->snd, hol_session_app(c->s));
}

/* The display's refresh rate for environment.csv: the X screen's current
 * XRandR mode's rate (RandR 1.1, XRRConfigCurrentRate: whole Hz), read
 * through libXrandr.so.2 when the system has it (dlopen: not linked, no
 * package added; kept loaded, as Xlib keeps its close hook); 0 unknown. */
static double play_refresh_hz(const hol_x11 *xw)
{
    void *lib = dlopen("libXrandr.so.2", RTLD_LAZY | RTLD_LOCAL);
    if (!lib)
        return 0;
    typedef void *(*info_fn)(Display *, Window);
    typedef short (*rate_fn)(void *);
    typedef void (*free_fn)(void *);
    info_fn info = (info_fn)dlsym(lib, "XRRGetScreenInfo");
    rate_fn rate = (rate_fn)dlsym(lib, "XRRConfigCurrentRate");
    free_fn done = (free_fn)dlsym(lib, "XRRFreeScreenConfigInfo");
    int ev, er;
    typedef int (*query_fn)(Display *, int *, int *);
    query_fn query = (query_fn)dlsym(lib, "XRRQueryExtension");
    double hz = 0;
    if (info && rate && done && query && query(xw->dpy, &ev, &er)) {
        void *conf = info(xw->dpy, DefaultRootWindow(xw->dpy));
        if (conf) {
            hz = rate(conf);
            done(conf);
        }
    }
    return hz > 0 ? hz : 0;
}

/* environment.csv's row (play_env.h): the desktop, the GL's renderer,
 * the refresh rate (c->refresh_hz). */
static int play_write_env(play_ctx *c)
{
    play_env_host h = {"desktop", "", c->gl,
                       c->use_pad ? c->pad.info.name : "", c->refresh_hz, c->o.w, c->o.h};
    c->env_due = 0;
    return play_env_write(c->cmd, c->o.log_dir, &c->o.env, c->session, c->o.participant,
                          c->study_sha256, &h, c->o.argc, c->o.argv) ? CLI_EXIT_FAIL : 0;
}

/* Without an XRandR rate, the row is written once PLAY_ENV_SWAPS frames
 * were presented, with their mean rate (last: the session ends first, the
 * rate of those presented, 0 with fewer than two). */
#define PLAY_ENV_SWAPS 60
static int play_env_due(play_ctx *c, int last)
{
    if (!c->env_due)
        return 0;
    if (!last) {
        c->swap_last = play_now_s();
        if (c->swaps++ == 0)
            c->swap_first = c->swap_last;
        if (c->swaps <= PLAY_ENV_SWAPS)
            return 0;
    }
    long n = c->swaps - 1;
    double dt = c->swap_last - c->swap_first;
    c->refresh_hz = n > 0 && dt > 0 ? n / dt : 0;
    return play_write_env(c);
}

static int play_prepare(play_ctx *c)
{
    int st = play_prepare_files(c);
    if (st)
        return st;
    char msg[256];
    if (hol_x11_create(&c->xw, c->o.w, c->o.h, "holonomy", msg, sizeof msg)) {
        cli_error(c->cmd, 0, "%s", msg);
        return CLI_EXIT_FAIL;
    }
    c->has_window = 1;
    hol_rec_meta meta;
    hol_sink_posix_meta(&meta, c->o.participant);
    snprintf(meta.study, sizeof meta.study, "%s", c->study);
    if (c->o.resume) /* unanswered questions first (issue 39), else the ready screen */
        play_study_resume_meta(&meta);
    if (play_env_meta(c->cmd, &c->o.env, c->o.study, &meta, &c->out.study_text,
                      &c->out.study_len))
        return CLI_EXIT_FAIL;
    snprintf(c->study_sha256, sizeof c->study_sha256, "%s", meta.study_sha256);
    st = play_session_open(c->cmd, &c->out, c->levels, c->nlevels, &meta, c->o.append, &c->s);
    if (st)
        return st;
    play_study_announce();
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = hol_egl_getproc;
    /* HOLONOMY_GL_DEBUG=1: every frame asks the GL for errors (a wait) */
    const char *dbg = getenv("HOLONOMY_GL_DEBUG");
    rd.debug = dbg && dbg[0] && strcmp(dbg, "0");
    rd.world = hol_app_world(hol_session_app(c->s));
    hol_err err = hol_render_create(&rd, &c->r);
    if (err) {
        cli_error(c->cmd, 0, "cannot initialise the renderer: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    play_open_pad(c);
    play_open_audio(c);
    snprintf(c->session, sizeof c->session, "%s", meta.session);
    typedef const unsigned char *(*get_string_fn)(unsigned);
    get_string_fn gs = (get_string_fn)hol_egl_getproc("glGetString");
    const unsigned char *gl = gs ? gs(0x1F01 /* GL_RENDERER */) : NULL;
    snprintf(c->gl, sizeof c->gl, "%s", gl ? (const char *)gl : "");
    c->refresh_hz = play_refresh_hz(&c->xw);
    if (c->refresh_hz > 0 || !c->o.log_dir)
        return play_write_env(c);
    c->env_due = 1;
    return 0;
}

/* ---- the loop ---------------------------------------------------------------------- */

static float clamp1(double v)
{
    return (float)(v < -1 ? -1 : v > 1 ? 1 : v);
}

/* A key counts for this frame while held or when it went down since the
 * last poll (a tap between two frames). */
static int key_on(const hol_x11_keys *k, int held, int id)
{
    return held || (k->taps & HOL_X11_TAP(id)) != 0;
}

/* The keyboard and mouse as this frame's input record (time t, dt since
 * the last frame; snap: Left and Right snap, they do not turn); returns
 * whether a key or the mouse was used. */
static int keys_input(hol_x11_keys *k, double t, double dt, int open, int snap, hol_input *in)
{
    static const struct {
        int id;
        uint32_t btn;
    } btns[] = {{HOL_X11_K_CONFIRM, HOL_BTN_CONFIRM}, {HOL_X11_K_MENU, HOL_BTN_MENU},
                {HOL_X11_K_RESTART, HOL_BTN_RESTART}, {HOL_X11_K_MINIMAP, HOL_BTN_MINIMAP},
                {HOL_X11_K_DEBUG, HOL_BTN_DEBUG}};
    const int held[] = {k->confirm, k->menu, k->restart, k->minimap, k->debug};
    in->time_s = t;
    in->flags = k->unfocused ? 0 : HOL_INPUT_FOCUSED;
    in->device = HOL_DEVICE_KEYBOARD;
    in->move[0] = (float)(key_on(k, k->strafe_r, HOL_X11_K_STRAFE_R) -
                          key_on(k, k->strafe_l, HOL_X11_K_STRAFE_L));
    in->move[1] = (float)(key_on(k, k->up, HOL_X11_K_UP) - key_on(k, k->down, HOL_X11_K_DOWN));
    /* mouse: 0.2 degrees a pixel, as a turn rate over this frame */
    int turn_keys = snap ? 0 : key_on(k, k->left, HOL_X11_K_LEFT) - key_on(k, k->right, HOL_X11_K_RIGHT);
    in->turn[0] = clamp1(turn_keys - k->mouse_dx * 0.2 / (120 * dt));
    in->turn[1] = clamp1(key_on(k, k->look_up, HOL_X11_K_LOOK_UP) -
                         key_on(k, k->look_down, HOL_X11_K_LOOK_DOWN) -
                         k->mouse_dy * 0.2 / (90 * dt));
    for (size_t i = 0; i < sizeof btns / sizeof btns[0]; i++) {
        in->buttons |= held[i] ? btns[i].btn : 0;
        in->pressed |= (k->taps & HOL_X11_TAP(btns[i].id)) ? btns[i].btn : 0;
    }
    if (!open)
        in->buttons |= HOL_BTN_QUIT;
    int used = k->taps || k->left | k->right | k->up | k->down | k->strafe_l | k->strafe_r |
               k->look_up | k->look_down | k->confirm | k->menu | k->restart | k->minimap |
               k->debug | k->mouse_dx | k->mouse_dy;
    k->mouse_dx = k->mouse_dy = 0;
    return used;
}

/* Snap turn (snap_deg > 0): Left and Right turn by snaps, one a press, to
 * the multiples of snap_deg from the look's yaw. */
static void keys_snap(const hol_x11_keys *k, int snap_deg, double yaw, hol_input *in)
{
    int turns = !!(k->taps & HOL_X11_TAP(HOL_X11_K_LEFT)) - !!(k->taps & HOL_X11_TAP(HOL_X11_K_RIGHT));
    if (snap_deg <= 0 || !turns)
        return;
    in->flags |= HOL_INPUT_SNAP_YAW;
    in->snap_yaw_deg = (float)hol_motion_snap_yaw(yaw, snap_deg, turns);
}

/* The keyboard and mouse on the session's clock; 1 when used. */
static int play_keys_input(play_ctx *c, int open, hol_input *in)
{
    double t = play_now_s() - c->t0;
    if (t < c->last_t)
        t = c->last_t;
    double dt = t - c->last_t > 1e-3 ? t - c->last_t : 1e-3;
    c->last_t = t;
    int snap = c->o.snap_deg > 0 ? c->o.snap_deg : c->o.seated ? 90 : 0;
    int used = keys_input(&c->keys, t, dt, open, snap > 0, in);
    keys_snap(&c->keys, snap, hol_app_get_view(hol_session_app(c->s))->yaw_deg, in);
    return used;
}

/* This frame's record: recorded input or the keys, the controller merged.
 * 1 a record, 0 the input has ended, -status on bad input. */
static int play_frame_input(play_ctx *c, int open, hol_input *in)
{
    memset(in, 0, sizeof *in);
    int activity;
    if (c->has_input) {
        int r = play_input_next(&c->input, in);
        if (r <= 0)
            return r;
        if (!open)
            in->buttons |= HOL_BTN_QUIT;
        activity = in->buttons || in->move[0] || in->move[1] || in->turn[0] || in->turn[1];
    } else {
        activity = play_keys_input(c, open, in);
    }
    if (c->keys.taps & HOL_X11_TAP(HOL_X11_K_STATS))
        c->overlay = !c->overlay;
    c->keys.taps = 0;
    if (c->use_pad) {
        hol_input pad;
        memset(&pad, 0, sizeof pad);
        pad.time_s = in->time_s;
        hol_err pe = hol_hid_dev_poll(&c->pad, &pad);
        hol_hid_link_merge(&c->link, pe, c->pad.lost, &pad, activity, in);
    }
    if (c->o.seated) /* the move axes (keys, stick, a script's) step */
        hol_shell_seat(&c->seat_latch, in);
    return 1;
}

/* The last resort: a swap that never returns (Mesa's software swap spins
 * on an X connection lost in the microseconds between hol_x11_swap's check
 * and the swap) ends the process after PLAY_SWAP_LIMIT s; the logs then
 * keep their rows to the last second, as after a kill -9. */
#define PLAY_SWAP_LIMIT 10
static void play_on_alarm(int sig)
{
    static const char msg[] = "holonomy play: the display stopped answering during a frame; "
                              "the logs keep their rows to the last second\n";
    (void)sig;
    ssize_t w = write(2, msg, sizeof msg - 1);
    (void)w;
    _exit(CLI_EXIT_FAIL);
}

static int play_draw(play_ctx *c)
{
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(hol_session_app(c->s)), -1, c->xw.w, c->xw.h, 0, &fd);
    fd.overlay = c->overlay ? c->fs.text : NULL;
    hol_err err = hol_render_frame(c->r, &fd, NULL);
    if (!err && (c->xw.w != c->drawn_w || c->xw.h != c->drawn_h)) {
        c->drawn_w = c->xw.w; /* the first frame, or a resize: one check */
        c->drawn_h = c->xw.h;
        err = hol_render_check(c->r);
    }
    if (err) {
        cli_error(c->cmd, 0, "rendering failed: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    signal(SIGALRM, play_on_alarm);
    alarm(PLAY_SWAP_LIMIT);
    hol_x11_swap(&c->xw);
    alarm(0);
    play_stats_add(&c->fs, c->o.stats);
    return play_env_due(c, 0);
}

/* The frames: 0 when the session is over (or the input, or --frames), a
 * status on failure; *abort when a signal or the window ended it. */
static int play_loop(play_ctx *c, int *abort)
{
    c->t0 = play_now_s();
    for (long k = 0; c->o.frames <= 0 || k < c->o.frames; k++) {
        int open = hol_x11_poll(&c->xw, &c->keys);
        if (cli_caught_signal() || c->xw.closed) {
            *abort = 1;
            return 0;
        }
        hol_input in;
        int r = play_frame_input(c, open, &in);
        if (r <= 0)
            return -r;
        int over = 0;
        hol_err err = hol_session_step(c->s, &in, &over);
        if (err) {
            cli_error(c->cmd, 0, "%s", hol_session_message(c->s));
            return err == HOL_EARG ? CLI_EXIT_USAGE : CLI_EXIT_FAIL;
        }
        if (hol_app_get_events(hol_session_app(c->s))->level_started)
            hol_render_invalidate(c->r);
        play_sound(c);
        if (over || !open)
            return 0;
        if ((r = play_draw(c)))
            return r;
    }
    return 0;
}

static int play_cleanup(play_ctx *c, int status, int abort)
{
    if (c->s && !status)
        play_print_end(c->s);
    if (c->s && play_env_due(c, 1) && !status)
        status = CLI_EXIT_FAIL;
    if (c->o.stats)
        play_stats_end(&c->fs);
    if (c->use_pad)
        hol_hid_dev_close(&c->pad);
    hol_render_destroy(c->r);
    hol_audio_feed_close(&c->snd);
    int end = play_session_end(c->cmd, c->s, abort || (c->has_input && c->input.aborted));
    play_out_close(&c->out);
    if (c->has_window)
        hol_x11_destroy(&c->xw);
    if (c->has_input)
        play_input_close(&c->input);
    int out = cli_finish_output(c->cmd);
    status = status ? status : end ? end : out;
    int sig = cli_caught_signal();
    return status ? status : sig ? 128 + sig : 0;
}

int cli_cmd_play(int argc, char **argv)
{
    static play_ctx c;
    memset(&c, 0, sizeof c);
    c.cmd = "play";
    int status = play_options(c.cmd, argc, argv, &c.o);
    if (status)
        return status;
    cli_catch_signals();
    int abort = 0;
    status = play_prepare(&c);
    if (!status)
        status = play_loop(&c, &abort);
    return play_cleanup(&c, status, abort);
}
