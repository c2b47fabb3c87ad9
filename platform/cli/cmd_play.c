/* cmd_play.c - `holonomy play` (the desktop game in an EGL/X11 window) and
 * `holonomy replay` (a recording through the same session, headless). */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_tile.h"
#include "../../core/hol_world.h"
#include "../../render/hol_app_frame.h"
#include "../../render/hol_render.h"
#include "../egl/hol_egl.h"
#include "../egl/hol_egl_x11.h"
#include "../file/hol_file.h"
#include "../hid/hol_hid_dev.h"
#include "../hid/hol_hid_link.h"
#include "../image/hol_png_file.h"
#include "../osmesa/hol_osmesa.h"
#include "cli.h"
#include "play_setup.h"
#include "session.h"

static const char *const play_usage =
    "usage: holonomy play [LEVEL | --mode tutorial|flag|keys|explore] [--seed S]\n"
    "                     [--log DIR] [--record FILE] [--frames N] [--input FILE]\n"
    "                     [--size WxH] [--no-gamepad | --gamepad-replay FILE]\n"
    "                     [--snap-turn DEG] [--stats]\n"
    "\n"
    "Play in a desktop window (EGL on X11; also under Xvfb). LEVEL is a level\n"
    "file (SPEC section 5); --mode plays a level of that mode made from the seed\n"
    "(flag 5 steps from the start; 3 keys 2..3 steps out and the chest at 5);\n"
    "neither: the default campaign (the tutorial, three flags at distance 3, 5,\n"
    "7, then two keys-and-chest levels).\n"
    "\n"
    "  W/S or Up/Down   walk forward/back      A/D          step sideways\n"
    "  Left/Right       turn (--snap-turn: snap) PgUp/PgDn  look up/down\n"
    "  mouse drag       look (left button)     P            pause menu\n"
    "  R                restart the level      M            minimap: HUD, hand, off\n"
    "  Enter/Space      next level (end screen); in the menu: restart\n"
    "  F3               debug text (tile, cell)  F2        frame time (fps, CPU)\n"
    "  Esc/Q            quit\n"
    "\n"
    "A game controller (the first found; plugged in later, it joins) plays too:\n"
    "left stick walks, right stick turns and looks, south button confirms,\n"
    "west/select/hat down cycle the minimap, start/mode open the menu (in it,\n"
    "south restarts and east quits); its axes add to the keys' (clamped), its\n"
    "buttons OR with them. Unplugged mid-game, the game pauses until it is back\n"
    "or a key is used. Prompts name the buttons of what was used last.\n"
    "\n"
    "  --mode M        tutorial (four lessons), flag, keys or explore\n"
    "  --seed S        seed of --mode's level or the campaign's first (decimal or\n"
    "                  0x hex; default 1)\n"
    "  --log DIR       research logs: DIR/steps-NNN.csv, DIR/head-NNN.csv per level\n"
    "                  attempt, DIR/summary.csv (README: Logs)\n"
    "  --record FILE   record the session's input (replay with 'holonomy replay')\n"
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
    "  --no-gamepad    do not use game controllers\n"
    "  --gamepad-replay FILE\n"
    "                  the controller is a script of plugs, reports and unplugs\n"
    "                  (README: Gamepads) on the game's clock, not a device; with\n"
    "                  --input the two are merged as keyboard and pad are\n"
    "\n"
    "At the end it prints 'level NAME STATE steps S optimum O tile ADDR cell C,R'\n"
    "(STATE playing, done, timeout at the level's time limit, or quit).\n"
    "Exit status: 0 ok, 1 failure, 2 bad input.\n";

static const char *const replay_usage =
    "usage: holonomy replay REC [--log DIR] [--png-frames LIST --out-dir D]\n"
    "                       [--size WxH]\n"
    "\n"
    "Run a recording (holonomy play --record) through the same app step: the\n"
    "logs come out byte for byte as in the play. --png-frames renders the\n"
    "listed frames (0-based, comma separated) headless with OSMesa to\n"
    "D/frame-NNNNNN.png (--size, default 640x480); a frame beyond the\n"
    "recording is bad input (the others are still written).\n"
    "\n"
    "Exit status: 0 ok, 1 failure, 2 bad input (a bad recording line is named).\n";

static int parse_size(const char *cmd, const char *val, int *w, int *h)
{
    char *e1, *e2;
    errno = 0;
    long a = strtol(val, &e1, 10);
    long b = *e1 == 'x' ? strtol(e1 + 1, &e2, 10) : 0;
    if (*e1 != 'x' || *e2 || errno || a < 16 || a > 4096 || b < 16 || b > 4096) {
        cli_error(cmd, 0, "--size '%.40s' is not WxH with sides 16..4096", val);
        return 1;
    }
    *w = (int)a;
    *h = (int)b;
    return 0;
}

static void print_end(const session *s)
{
    const hol_app_view *v = hol_app_get_view(s->app);
    static const char *const st[] = {"idle", "playing", "done", "quit"};
    printf("level %s %s steps %d optimum %d tile %s cell %d,%d\n", s->levels[s->cur].name,
           v->hud.timed_out ? "timeout" : st[v->state], v->hud.steps, v->hud.optimum, v->hud.address, v->user.col,
           v->user.row);
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

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

/* Frame time: fps and process CPU ms a frame (the renderer's threads
 * included) over the last second, for the F2 overlay and --stats. */
typedef struct frame_stats {
    double wall0, cpu0;      /* this second's start */
    double last_cpu;         /* CPU at the frame's start */
    long frames;             /* in this second */
    double fps, cpu_ms;      /* of the last full second */
    long total;              /* every frame */
    double total_cpu_ms, max_cpu_ms, first_wall;
    char text[48];           /* "FPS 19.8 CPU 41.2 MS" */
} frame_stats;

static double cpu_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* One frame done; every second the figures are renewed (and with print
 * written to stderr). */
static void frame_stats_add(frame_stats *fs, int print)
{
    double w = now_s(), c = cpu_s();
    if (!fs->total) {
        fs->wall0 = fs->first_wall = w;
        fs->cpu0 = fs->last_cpu = c;
        snprintf(fs->text, sizeof fs->text, "FPS - CPU - MS");
    }
    double ms = (c - fs->last_cpu) * 1e3;
    fs->last_cpu = c;
    fs->total++;
    fs->frames++;
    fs->total_cpu_ms += ms;
    fs->max_cpu_ms = ms > fs->max_cpu_ms ? ms : fs->max_cpu_ms;
    if (w - fs->wall0 < 1.0)
        return;
    fs->fps = fs->frames / (w - fs->wall0);
    fs->cpu_ms = (c - fs->cpu0) * 1e3 / fs->frames;
    snprintf(fs->text, sizeof fs->text, "FPS %.1f CPU %.1f MS", fs->fps, fs->cpu_ms);
    if (print)
        fprintf(stderr, "stats: %.0f s: %.1f fps, CPU %.1f ms a frame\n", w - fs->first_wall,
                fs->fps, fs->cpu_ms);
    fs->wall0 = w;
    fs->cpu0 = c;
    fs->frames = 0;
}

int cli_cmd_play(int argc, char **argv)
{
    const char *cmd = "play";
    if (cli_wants_help(argc, argv)) {
        fputs(play_usage, stdout);
        return cli_finish_output(cmd);
    }
    const char *level_path = NULL, *mode = NULL, *log_dir = NULL, *rec = NULL,
               *input_path = NULL, *pad_script = NULL;
    unsigned long long seed = CLI_SEED_DEFAULT;
    long frames = 0;
    int w = 960, h = 720, use_pad = 1, snap_deg = 0, stats = 0, overlay = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        int takes = !strcmp(a, "--mode") || !strcmp(a, "--seed") || !strcmp(a, "--log") ||
                    !strcmp(a, "--record") || !strcmp(a, "--frames") ||
                    !strcmp(a, "--input") || !strcmp(a, "--size") ||
                    !strcmp(a, "--gamepad-replay") || !strcmp(a, "--snap-turn");
        if (takes && !val) {
            cli_error(cmd, 0, "%s needs a value; see 'holonomy play --help'", a);
            return CLI_EXIT_USAGE;
        }
        if (!strcmp(a, "--no-gamepad"))
            use_pad = 0;
        else if (!strcmp(a, "--stats"))
            stats = 1;
        else if (!strcmp(a, "--mode"))
            mode = val;
        else if (!strcmp(a, "--seed")) {
            uint64_t sv;
            if (!cli_parse_u64(val, &sv)) {
                cli_error(cmd, 0, "--seed '%.40s' is not an unsigned 64-bit number", val);
                return CLI_EXIT_USAGE;
            }
            seed = sv;
        } else if (!strcmp(a, "--log"))
            log_dir = val;
        else if (!strcmp(a, "--record"))
            rec = val;
        else if (!strcmp(a, "--input"))
            input_path = val;
        else if (!strcmp(a, "--gamepad-replay"))
            pad_script = val;
        else if (!strcmp(a, "--frames")) {
            size_t n = cli_parse_count(val);
            if (!n || n > 100000000) {
                cli_error(cmd, 0, "--frames '%.40s' is not a count in 1..100000000", val);
                return CLI_EXIT_USAGE;
            }
            frames = (long)n;
        } else if (!strcmp(a, "--size")) {
            if (parse_size(cmd, val, &w, &h))
                return CLI_EXIT_USAGE;
        } else if (!strcmp(a, "--snap-turn")) {
            size_t n = cli_parse_count(val);
            if (!n || n > 180 || 360 % n) {
                cli_error(cmd, 0, "--snap-turn '%.40s' is not a divisor of 360 in 1..180", val);
                return CLI_EXIT_USAGE;
            }
            snap_deg = (int)n;
        } else if (a[0] == '-' && a[1]) {
            cli_error(cmd, 0, "unknown option '%.40s'; see 'holonomy play --help'", a);
            return CLI_EXIT_USAGE;
        } else if (!level_path) {
            level_path = a;
            continue;
        } else {
            cli_error(cmd, 0, "more than one LEVEL ('%.40s')", a);
            return CLI_EXIT_USAGE;
        }
        if (takes)
            i++;
    }
    if (level_path && mode) {
        cli_error(cmd, 0, "give a LEVEL file or --mode, not both");
        return CLI_EXIT_USAGE;
    }
    if (pad_script && !use_pad) {
        cli_error(cmd, 0, "give --no-gamepad or --gamepad-replay, not both");
        return CLI_EXIT_USAGE;
    }
    /* the scripted controller, loaded before anything opens */
    static hol_hid_script script;
    if (pad_script) {
        int st = play_load_pad_script(cmd, pad_script, &script);
        if (st)
            return st;
    }
    if (cli_require_folder(cmd, "--log", log_dir))
        return CLI_EXIT_USAGE;
    static session_level levels[SESSION_MAX_LEVELS];
    int nlevels = 0;
    int lst = play_levels(cmd, level_path, mode, seed, levels, &nlevels);
    if (lst)
        return lst;
    file_lines in_lines;
    memset(&in_lines, 0, sizeof in_lines);
    long in_first = 0;
    if (input_path) {
        int st = read_input_lines(cmd, input_path, &in_lines, &in_first);
        if (st)
            return st;
    }
    char msg[256];
    hol_x11 xw;
    if (hol_x11_create(&xw, w, h, "holonomy", msg, sizeof msg)) {
        cli_error(cmd, 0, "%s", msg);
        free_lines(&in_lines);
        return CLI_EXIT_FAIL;
    }
    session s;
    int status = session_open(&s, cmd, levels, nlevels, log_dir, rec);
    hol_render *r = NULL;
    if (status)
        goto out;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = hol_egl_getproc;
    rd.world = hol_app_world(s.app);
    hol_err err = hol_render_create(&rd, &r);
    if (err) {
        cli_error(cmd, 0, "cannot initialise the renderer: %s", hol_err_str(err));
        status = CLI_EXIT_FAIL;
        goto out;
    }
    hol_x11_keys keys;
    memset(&keys, 0, sizeof keys);
    /* the first game controller; polled (and looked for) in live play, or
     * the scripted one (also beside --input) */
    static hol_hid_dev pad_dev;
    hol_hid_link pad_link;
    memset(&pad_link, 0, sizeof pad_link);
    use_pad = pad_script || (use_pad && !input_path);
    hol_err pad_open = HOL_EOPEN;
    if (pad_script)
        pad_open = hol_hid_dev_open_backend(&pad_dev, hol_hid_script_backend(&script), 0.0);
    else if (use_pad)
        pad_open = hol_hid_dev_open_first(&pad_dev);
    if (pad_open == HOL_OK)
        fprintf(stderr, "play: game controller: %s (%04x:%04x)\n",
                pad_dev.info.name[0] ? pad_dev.info.name : "unnamed", pad_dev.info.vid,
                pad_dev.info.pid);
    frame_stats fs;
    memset(&fs, 0, sizeof fs);
    double t0 = now_s(), last_t = 0, prev_t = 0;
    for (long k = 0; frames <= 0 || k < frames; k++) {
        int open = hol_x11_poll(&xw, &keys);
        hol_input in;
        memset(&in, 0, sizeof in);
        int key_activity = 0;
        if (input_path) {
            long li = in_first + k;
            if (li >= in_lines.n)
                break;
            if (parse_input_line(cmd, &in_lines, li, &in, &prev_t)) {
                status = CLI_EXIT_USAGE;
                goto out;
            }
            if (!open)
                in.buttons |= HOL_BTN_QUIT;
            key_activity = in.buttons || in.move[0] || in.move[1] || in.turn[0] || in.turn[1];
        } else {
            double t = now_s() - t0;
            if (t < last_t)
                t = last_t;
            double dt = t - last_t > 1e-3 ? t - last_t : 1e-3;
            last_t = t;
            key_activity = keys_input(&keys, t, dt, open, snap_deg > 0, &in);
            keys_snap(&keys, snap_deg, hol_app_get_view(s.app)->yaw_deg, &in);
        }
        if (keys.taps & HOL_X11_TAP(HOL_X11_K_STATS))
            overlay = !overlay;
        keys.taps = 0;
        if (use_pad) {
            hol_input pad;
            memset(&pad, 0, sizeof pad);
            pad.time_s = in.time_s;
            hol_err pe = hol_hid_dev_poll(&pad_dev, &pad);
            hol_hid_link_merge(&pad_link, pe, pad_dev.lost, &pad, key_activity != 0, &in);
        }
        int rc = session_step(&s, &in);
        if (rc < 0) {
            status = CLI_EXIT_FAIL;
            goto out;
        }
        if (hol_app_get_events(s.app)->level_started)
            hol_render_invalidate(r);
        if (rc > 0 || !open)
            break;
        hol_frame_desc fd;
        hol_app_frame_desc(hol_app_get_view(s.app), -1, xw.w, xw.h, 0, &fd);
        fd.overlay = overlay ? fs.text : NULL;
        err = hol_render_frame(r, &fd, NULL);
        if (err) {
            cli_error(cmd, 0, "rendering failed: %s", hol_err_str(err));
            status = CLI_EXIT_FAIL;
            goto out;
        }
        hol_x11_swap(&xw);
        frame_stats_add(&fs, stats);
    }
    print_end(&s);
    if (stats && fs.total) {
        double secs = now_s() - fs.first_wall;
        fprintf(stderr, "stats: %ld frames in %.1f s: %.1f fps, CPU %.1f ms a frame (max %.1f)\n",
                fs.total, secs, secs > 0 ? fs.total / secs : 0.0, fs.total_cpu_ms / fs.total,
                fs.max_cpu_ms);
    }
out:
    if (use_pad)
        hol_hid_dev_close(&pad_dev);
    hol_render_destroy(r);
    if (s.app || s.recording) {
        int c = session_close(&s);
        if (!status)
            status = c;
    }
    hol_x11_destroy(&xw);
    free_lines(&in_lines);
    int o = cli_finish_output(cmd);
    return status ? status : o;
}

/* "3,10,200" into a sorted list; 1 on a bad list. */
static int parse_frame_list(const char *s, long *out, int cap, int *out_n)
{
    int n = 0;
    const char *p = s;
    while (*p) {
        char *e;
        errno = 0;
        long v = strtol(p, &e, 10);
        if (e == p || errno || v < 0 || n >= cap || (*e && *e != ','))
            return 1;
        out[n++] = v;
        p = *e ? e + 1 : e;
        if (*e && !*p)
            return 1;
    }
    *out_n = n;
    return n == 0;
}

int cli_cmd_replay(int argc, char **argv)
{
    const char *cmd = "replay";
    if (cli_wants_help(argc, argv)) {
        fputs(replay_usage, stdout);
        return cli_finish_output(cmd);
    }
    const char *rec = NULL, *log_dir = NULL, *out_dir = NULL, *list = NULL;
    int w = 640, h = 480;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        int takes = !strcmp(a, "--log") || !strcmp(a, "--png-frames") ||
                    !strcmp(a, "--out-dir") || !strcmp(a, "--size");
        if (takes && !val) {
            cli_error(cmd, 0, "%s needs a value; see 'holonomy replay --help'", a);
            return CLI_EXIT_USAGE;
        }
        if (!strcmp(a, "--log"))
            log_dir = val;
        else if (!strcmp(a, "--png-frames"))
            list = val;
        else if (!strcmp(a, "--out-dir"))
            out_dir = val;
        else if (!strcmp(a, "--size")) {
            if (parse_size(cmd, val, &w, &h))
                return CLI_EXIT_USAGE;
        } else if (a[0] == '-' && a[1]) {
            cli_error(cmd, 0, "unknown option '%.40s'; see 'holonomy replay --help'", a);
            return CLI_EXIT_USAGE;
        } else if (!rec) {
            rec = a;
            continue;
        } else {
            cli_error(cmd, 0, "more than one recording ('%.40s')", a);
            return CLI_EXIT_USAGE;
        }
        if (takes)
            i++;
    }
    if (!rec) {
        cli_error(cmd, 0, "no recording given; see 'holonomy replay --help'");
        return CLI_EXIT_USAGE;
    }
    if (!list != !out_dir) {
        cli_error(cmd, 0, "--png-frames and --out-dir go together");
        return CLI_EXIT_USAGE;
    }
    static long pngs[4096];
    int npng = 0;
    if (list && parse_frame_list(list, pngs, 4096, &npng)) {
        cli_error(cmd, 0, "--png-frames '%.40s' is not a comma-separated list of frames", list);
        return CLI_EXIT_USAGE;
    }
    if (cli_require_folder(cmd, NULL, log_dir) || cli_require_folder(cmd, NULL, out_dir))
        return CLI_EXIT_USAGE;
    for (int k = 0; k < npng; k++) { /* every frame's file, before any work */
        char path[4096];
        snprintf(path, sizeof path, "%s/frame-%06ld.png", out_dir, pngs[k]);
        if (cli_check_output(cmd, "--out-dir", path))
            return CLI_EXIT_USAGE;
    }
    file_lines fl;
    int status = read_lines(cmd, rec, &fl);
    if (status) {
        free_lines(&fl);
        return status;
    }
    static session_level levels[SESSION_MAX_LEVELS];
    int nlevels = 0;
    char err[256];
    long first = session_read_header(fl.line, fl.len, fl.n, levels, &nlevels, err, sizeof err);
    if (!first) {
        cli_error(cmd, 0, "%.200s: %s", rec, err);
        free_lines(&fl);
        return CLI_EXIT_USAGE;
    }
    hol_osmesa gl = {0};
    int have_gl = 0;
    hol_render *r = NULL;
    uint8_t *rgba = NULL;
    session s;
    memset(&s, 0, sizeof s);
    status = session_open(&s, cmd, levels, nlevels, log_dir, NULL);
    if (status)
        goto out;
    if (npng) {
        char msg[256];
        if (hol_osmesa_create(&gl, w, h, msg, sizeof msg)) {
            cli_error(cmd, 0, "%s", msg);
            status = CLI_EXIT_FAIL;
            goto out;
        }
        have_gl = 1;
        hol_render_desc rd;
        memset(&rd, 0, sizeof rd);
        rd.getproc = hol_osmesa_getproc;
        rd.world = hol_app_world(s.app);
        rgba = malloc((size_t)w * (size_t)h * 4);
        hol_err e = rgba ? hol_render_create(&rd, &r) : HOL_ENOMEM;
        if (e) {
            cli_error(cmd, 0, "cannot initialise the renderer: %s", hol_err_str(e));
            status = CLI_EXIT_FAIL;
            goto out;
        }
    }
    double prev_t = 0;
    for (long li = first - 1; li < fl.n; li++) {
        hol_input in;
        if (parse_input_line(cmd, &fl, li, &in, &prev_t)) {
            status = CLI_EXIT_USAGE;
            goto out;
        }
        long frame = s.frame;
        int rc = session_step(&s, &in);
        if (rc < 0) {
            status = CLI_EXIT_FAIL;
            goto out;
        }
        if (r && hol_app_get_events(s.app)->level_started)
            hol_render_invalidate(r);
        int want = 0;
        for (int k = 0; k < npng; k++)
            want |= pngs[k] == frame;
        if (want) {
            hol_frame_desc fd;
            hol_app_frame_desc(hol_app_get_view(s.app), -1, w, h, 0, &fd);
            hol_err e = hol_render_frame(r, &fd, NULL);
            char path[4096];
            snprintf(path, sizeof path, "%s/frame-%06ld.png", out_dir, frame);
            if (!e)
                hol_render_read_rgba(r, w, h, rgba);
            if (e || hol_png_write_file(path, rgba, w, h, 0)) {
                cli_error(cmd, 0, "cannot render frame %ld to '%.200s'", frame, path);
                status = CLI_EXIT_FAIL;
                goto out;
            }
        }
        if (rc > 0)
            break;
    }
    print_end(&s);
    /* a frame the recording never reached is bad input, said once (the
     * frames it reached are written) */
    for (int k = 0; k < npng; k++)
        if (pngs[k] >= s.frame) {
            cli_error(cmd, 0, "--png-frames: frame %ld is beyond the recording (frames 0..%ld)",
                      pngs[k], s.frame - 1);
            status = CLI_EXIT_USAGE;
            break;
        }
out:
    hol_render_destroy(r);
    free(rgba);
    if (have_gl)
        hol_osmesa_destroy(&gl);
    if (s.app) {
        int c = session_close(&s);
        if (!status)
            status = c;
    }
    free_lines(&fl);
    int o = cli_finish_output(cmd);
    return status ? status : o;
}
