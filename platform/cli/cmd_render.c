/* cmd_render.c - `holonomy render`: one view to PNG through OSMesa (SPEC 4). */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../core/hol_level.h"
#include "../../core/hol_motion.h"
#include "../../core/hol_nav.h"
#include "../../core/hol_room.h"
#include "../../core/hol_tile.h"
#include "../../core/hol_world.h"
#include "../../render/hol_png.h"
#include "../file/hol_file.h"
#include "../image/hol_png_file.h"
#include "../../render/hol_render.h"
#include "../egl/hol_egl.h"
#include "../egl/hol_egl_x11.h"
#include "../osmesa/hol_osmesa.h"
#include "../../core/hol_str.h"
#include "cli.h"

const char *const cli_render_usage =
    "usage: holonomy render [--walk W] [--eye X,Y,Z] [--yaw DEG] [--pitch DEG]\n"
    "                       [--size WxH] [--out FILE.png] [--tile-ids FILE]\n"
    "                       [--stats] [--euclidean] [--bare] [--fov DEG]\n"
    "                       [--frames N] [--seed S] [--hud] [--hand X,Y,Z]\n"
    "                       [--target ADDR] [--orient X,Y,Z,W --tan L,R,D,U]\n"
    "                       [--gl osmesa|egl] [--stereo IPD] [--window]\n"
    "                       [--keys SCRIPT] [--tiling 4,Q] [--room CxR]\n"
    "                       [--cell M] [--lighting day|dusk|night]\n"
    "                       [--lantern ADDR] [--fireflies SECONDS|off]\n"
    "                       [--lang en|de|nl]\n"
    "\n"
    "Render what the user sees and write a PNG: headless (OSMesa, or EGL\n"
    "surfaceless), or live in a window (--window).\n"
    "\n"
    "  --walk W        walk inside the room from the start (N, E, S, W; '-'\n"
    "                  for none, the default): sets the user's tile,\n"
    "                  orientation and cell\n"
    "  --tiling 4,Q    the tiling {4,Q}, Q from 4 (the flat grid) to 8\n"
    "                  (default 4,5)\n"
    "  --room CxR      a room of C x R cells, 3 to 5 each (default 3x3); the\n"
    "                  walk starts on cell (C/2, R/2)\n"
    "  --cell M        the side of a cell in metres, 0.5 to 1.5, at most 3\n"
    "                  decimals (default 1):\n"
    "                  cell (c,r) spans x in [c*M, (c+1)*M], z in [r*M,\n"
    "                  (r+1)*M]\n"
    "  --eye X,Y,Z     eye in room coordinates (metres; x east, y up, z\n"
    "                  south); x,z strictly inside the cell the walk ends in,\n"
    "                  y in (0.01, 100]. Default: that cell's centre at 1.6\n"
    "  --yaw DEG       0 looks north, positive turns west (default 0)\n"
    "  --pitch DEG     positive looks up, -90..90 (default -30)\n"
    "  --size WxH      image size in pixels, 1..8192 (default 640x480)\n"
    "  --fov DEG       vertical field of view, 10..170 (default 90)\n"
    "  --out FILE      write the view as PNG (atomically)\n"
    "  --tile-ids FILE write 'PX PY ADDRESS' for every pixel showing floor\n"
    "                  (PX from the left, PY from the top, pixel centres)\n"
    "  --stats         print draw calls, triangles, stencil passes, CPU ms\n"
    "  --euclidean     the room's cells as a flat room, no portals\n"
    "  --bare          floors only (no trees, hedges, props): for tests\n"
    "  --frames N      render N times, 1..1000 (stats: median CPU ms), default 1\n"
    "  --seed S        world seed (decimal or 0x hex; default 1): the forest\n"
    "                  content\n"
    "  --hud           draw the HUD text and the Poincare minimap (in {4,4}\n"
    "                  a plain top view, captioned so)\n"
    CLI_LANG_USAGE
    "                  (here: the --hud text)\n"
    "  --hand X,Y,Z    the minimap in the hand instead: a 25 cm square at\n"
    "                  X,Y,Z (room coordinates, 0.05..2 m from the eye across\n"
    "                  the floor) facing the eye; implies --hud\n"
    "  --stereo IPD    two eyes IPD metres apart, (0, 0.2] (e.g. 0.064), side\n"
    "                  by side, each with its own render queue; --eye is the head\n"
    "                  (an eye leaning over a cell edge sees from that cell)\n"
    "  --window        the desktop build: a live window (EGL on X11, also\n"
    "                  under Xvfb) with HUD and minimap; arrows/WASD walk and\n"
    "                  turn, PgUp/PgDn look, Esc quits; with --frames N it\n"
    "                  stops after N frames (and --out gets the last)\n"
    "  --keys SCRIPT   drive --window by a script, one letter per frame:\n"
    "                  w/s forward/back, a/d sideways, l/r turn, u/n look\n"
    "                  up/down, . nothing; prints where the user ends\n"
    "  --gl API        osmesa (default: desktop GL core, no display) or egl\n"
    "                  (OpenGL ES 3 on EGL's surfaceless platform)\n"
    "  --target ADDR   an objective tile (repeatable, up to 8): guide pole,\n"
    "                  minimap marker, hot-cold colours\n"
    "  --lighting SKY  day (default: no lights), dusk or night: lanterns light\n"
    "                  the forest by the true distance, fog by the true\n"
    "                  distance from the eye\n"
    "  --lantern ADDR  a lantern over that tile's centre (repeatable, up to\n"
    "                  16); lit at dusk and night\n"
    "  --fireflies T   the frame's time in seconds, 0..1e9 (default 0): at dusk\n"
    "                  and night the fireflies (over creek, spring, pool and\n"
    "                  flower tiles, as the app draws them) circle with it;\n"
    "                  also the HUD's clock. 'off': no fireflies\n"
    "  --orient X,Y,Z,W with --tan L,R,D,U: the headset's form of the eye (as\n"
    "                  'holonomy xr' prints it): orientation quaternion (view\n"
    "                  to room; roll too) and the tangents of the field of\n"
    "                  view's half-angles (L, D negative); --yaw, --pitch and\n"
    "                  --fov are then ignored\n"
    "\n"
    "Floor outside the room is never shown: 2 m hedges stand on the\n"
    "room boundary. Without --window, at least one of --out, --tile-ids,\n"
    "--stats is needed.\n"
    "Exit status: 0 ok, 1 render or write failure, 2 bad input.\n";

static int parse_double(const char *s, double *out)
{
    return !cli_parse_doubles(s, out, 1);
}

/* Digits only (no blank, no sign) in lo..hi (lo >= 1); nonzero on failure. */
static int parse_int(const char *s, long lo, long hi, long *out)
{
    size_t v = cli_parse_count(s);
    if (v < (size_t)lo || v > (size_t)hi)
        return 1;
    *out = (long)v;
    return 0;
}

/* "X,Y,Z" to three numbers; nonzero on failure. */
static int parse_vec3(const char *s, double out[3])
{
    return !cli_parse_doubles(s, out, 3);
}

/* --orient and --tan: the headset form of the camera (hol_camera.has_pose),
 * as `holonomy xr` prints an eye's view; 0 ok, else exit status 2 reported */
static int parse_head_form(const char *cmd, const char *orient_s, const char *tan_s,
                           hol_camera *cam)
{
    if (!orient_s && !tan_s)
        return 0;
    double q[4], t[4];
    if (!orient_s || !tan_s) {
        cli_error(cmd, 0, "--orient and --tan go together");
        return CLI_EXIT_USAGE;
    }
    double n = 0;
    if (cli_parse_doubles(orient_s, q, 4))
        n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(fabs(n - 1) < 1e-3)) {
        cli_error(cmd, 0, "--orient '%.60s' is not a unit quaternion X,Y,Z,W", orient_s);
        return CLI_EXIT_USAGE;
    }
    if (!cli_parse_doubles(tan_s, t, 4) || !(t[0] < t[1] && t[2] < t[3]) || fabs(t[0]) > 10 ||
        fabs(t[1]) > 10 || fabs(t[2]) > 10 || fabs(t[3]) > 10) {
        cli_error(cmd, 0,
                  "--tan '%.60s' is not L,R,D,U (tangents of the half-angles, L < R, "
                  "D < U, each within 10)", tan_s);
        return CLI_EXIT_USAGE;
    }
    cam->has_pose = 1;
    for (int k = 0; k < 4; k++)
        cam->orient[k] = q[k] / n;
    cam->tan_left = t[0];
    cam->tan_right = t[1];
    cam->tan_down = t[2];
    cam->tan_up = t[3];
    return 0;
}

/* Unit quaternion (x, y, z, w) turning +z towards dir (not vertical),
 * keeping +y up: the hand's minimap faces the eye. */
static void face_towards(const double dir[3], double q[4])
{
    double z[3] = {dir[0], dir[1], dir[2]};
    double n = sqrt(z[0] * z[0] + z[1] * z[1] + z[2] * z[2]);
    for (int i = 0; i < 3; i++)
        z[i] /= n;
    double x[3] = {z[2], 0, -z[0]}; /* up x z */
    n = sqrt(x[0] * x[0] + x[2] * x[2]);
    x[0] /= n;
    x[2] /= n;
    double y[3] = {z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2],
                   z[0] * x[1] - z[1] * x[0]};
    /* rotation matrix with columns x, y, z to a quaternion */
    double m00 = x[0], m11 = y[1], m22 = z[2], tr = m00 + m11 + m22;
    if (tr > 0) {
        double s4 = sqrt(tr + 1.0) * 2;
        q[3] = 0.25 * s4;
        q[0] = (y[2] - z[1]) / s4;
        q[1] = (z[0] - x[2]) / s4;
        q[2] = (x[1] - y[0]) / s4;
    } else if (m00 > m11 && m00 > m22) {
        double s4 = sqrt(1.0 + m00 - m11 - m22) * 2;
        q[3] = (y[2] - z[1]) / s4;
        q[0] = 0.25 * s4;
        q[1] = (y[0] + x[1]) / s4;
        q[2] = (z[0] + x[2]) / s4;
    } else if (m11 > m22) {
        double s4 = sqrt(1.0 + m11 - m00 - m22) * 2;
        q[3] = (z[0] - x[2]) / s4;
        q[0] = (y[0] + x[1]) / s4;
        q[1] = 0.25 * s4;
        q[2] = (z[1] + y[2]) / s4;
    } else {
        double s4 = sqrt(1.0 + m22 - m00 - m11) * 2;
        q[3] = (x[1] - y[0]) / s4;
        q[0] = (z[0] + x[2]) / s4;
        q[1] = (z[1] + y[2]) / s4;
        q[2] = 0.25 * s4;
    }
}

/* Write the tile ids of an ID image to path atomically: streamed into a
 * temporary file next to it, renamed over it only when complete. */
static int write_tile_ids(const char *path, const uint8_t *rgba, long w, long h,
                          const hol_view *v)
{
    static char addr[HOL_VIEW_MAX_BRANCHES][HOL_TILE_ADDR_MAX];
    for (int b = 0; b < v->nbranches; b++)
        hol_tile_print(v->branches[b].state.tile, addr[b]);
    hol_file_atomic a;
    if (hol_file_atomic_open(&a, path))
        return 1;
    for (long y = 0; y < h; y++)
        for (long x = 0; x < w; x++) {
            int id = hol_render_decode_id(rgba + ((size_t)y * (size_t)w + (size_t)x) * 4);
            if (id >= 0 && id < v->nbranches &&
                fprintf(a.f, "%ld %ld %s\n", x, y, addr[id]) < 0) {
                hol_file_atomic_abort(&a);
                return 1;
            }
        }
    return hol_file_atomic_commit(&a) != HOL_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The desktop build: a window (EGL on X11; works under Xvfb). Arrow keys
 * or W/S walk and turn, A/D step sideways, Page Up/Down look up and down,
 * Escape or q quits. Walking over a cell edge is a room step: the user's
 * state follows the eye (hol_motion_pancake), the hedges hold it in.
 * frames > 0 stops after that many frames; out then gets the last. */
static int run_window(const char *cmd, hol_x11 *xw, hol_render *r, hol_world *world,
                      hol_frame_desc *fd, long frames, const char *out, uint8_t *rgba,
                      const char *script)
{
    hol_x11_keys keys;
    memset(&keys, 0, sizeof keys);
    long k = 0;
    double t = fd->time_s; /* --fireflies */
    hol_motion mo;
    hol_motion_desc md;
    memset(&md, 0, sizeof md);
    md.speed = 1.8; /* 3 cm a frame at 60 Hz */
    md.margin = 0.05;
    md.eye_height = fd->cam.eye[1];
    md.cell_m = fd->cell_m;
    hol_motion_init(&mo, &fd->user, &md);
    memcpy(mo.head, fd->cam.eye, sizeof mo.head);
    mo.yaw_deg = fd->cam.yaw_deg;
    mo.pitch_deg = fd->cam.pitch_deg;
    if (script && frames <= 0)
        frames = (long)strlen(script);
    while (hol_x11_poll(xw, &keys) && (frames <= 0 || k < frames)) {
        if (script) {
            /* a key script drives the frame instead of the keyboard */
            char ch = k < (long)strlen(script) ? script[k] : '.';
            memset(&keys, 0, sizeof keys);
            keys.up = ch == 'w';
            keys.down = ch == 's';
            keys.strafe_l = ch == 'a';
            keys.strafe_r = ch == 'd';
            keys.left = ch == 'l';
            keys.right = ch == 'r';
            keys.look_up = ch == 'u';
            keys.look_down = ch == 'n';
        }
        /* pancake motion: the core follows the head over cell edges */
        hol_camera *c = &fd->cam;
        float move[2] = {(float)(keys.strafe_r - keys.strafe_l), (float)(keys.up - keys.down)};
        float turn[2] = {(float)(keys.left - keys.right), (float)(keys.look_up - keys.look_down)};
        hol_motion_steps ms;
        hol_err merr = hol_motion_pancake(&mo, move, turn, 1.0 / 60.0, &ms);
        if (merr && merr != HOL_ERANGE) {
            cli_error(cmd, 0, "motion failed: %s", hol_err_str(merr));
            return CLI_EXIT_FAIL;
        }
        if (ms.n) {
            fd->steps_taken += ms.n;
            fd->user = mo.user;
            if (hol_world_update(world, &fd->user)) {
                cli_error(cmd, 0, "cannot generate the world");
                return CLI_EXIT_FAIL;
            }
        }
        memcpy(c->eye, mo.head, sizeof c->eye);
        c->yaw_deg = mo.yaw_deg;
        c->pitch_deg = mo.pitch_deg;
        c->width = xw->w;
        c->height = xw->h;
        fd->time_s = t;
        hol_err err = hol_render_frame(r, fd, NULL);
        if (err) {
            cli_error(cmd, 0, "rendering failed: %s", hol_err_str(err));
            return CLI_EXIT_FAIL;
        }
        k++;
        if (frames > 0 && k == frames && out) {
            hol_render_read_rgba(r, c->width, c->height, rgba);
            if (hol_png_write_file(out, rgba, c->width, c->height, 0)) {
                cli_error(cmd, 0, "cannot write '%.200s': %s", out, strerror(errno));
                return CLI_EXIT_FAIL;
            }
        }
        hol_x11_swap(xw);
        t += 1.0 / 60.0;
    }
    char addr[HOL_TILE_ADDR_MAX];
    hol_tile_print(fd->user.tile, addr);
    printf("tile %s cell %d,%d steps %d eye %.3f,%.3f,%.3f yaw %.1f pitch %.1f\n", addr,
           fd->user.col, fd->user.row, fd->steps_taken, fd->cam.eye[0], fd->cam.eye[1],
           fd->cam.eye[2], fd->cam.yaw_deg, fd->cam.pitch_deg);
    return CLI_EXIT_OK;
}

/* ---- options ------------------------------------------------------------- */

enum { RENDER_OSMESA, RENDER_EGL, RENDER_WINDOW };

typedef struct render_opts {
    const char *walk, *eye, *out, *ids, *keys, *hand, *orient, *tan;
    const char *target_s[HOL_RENDER_MAX_OBJECTIVES]; /* resolved in the tiling */
    const char *lantern_s[HOL_RENDER_MAX_LANTERNS];
    int nlanterns, lighting;
    int ff_off;         /* --fireflies off */
    double ff_time;     /* --fireflies T */
    hol_tile lanterns[HOL_RENDER_MAX_LANTERNS];
    double yaw, pitch, fov, ipd;
    long w, h, frames;
    int frames_set, stats, flags, ntargets, gl;
    int q, cols, rows;  /* --tiling, --room (0: the defaults) */
    int lang;           /* --lang (core/hol_str.h; 0: English) */
    double cell_m;      /* --cell (default 1) */
    uint64_t seed;
    hol_tile targets[HOL_RENDER_MAX_OBJECTIVES];
} render_opts;

const char *const cli_render_valued[] = {
    "--walk", "--eye", "--hand", "--orient", "--tan", "--yaw", "--pitch", "--size", "--out",
    "--tile-ids", "--fov", "--frames", "--seed", "--target", "--gl", "--stereo", "--keys",
    "--cell", "--tiling", "--room", "--lighting", "--lantern", "--fireflies", "--lang", NULL};

/* The numeric options: 1 taken, 0 not one of them, -1 bad (reported). */
static int parse_number_opt(const char *cmd, render_opts *o, const char *a, const char *val)
{
    const char *bad = NULL;
    if (!strcmp(a, "--yaw")) {
        bad = parse_double(val, &o->yaw) ? "is not a number of degrees" : NULL;
    } else if (!strcmp(a, "--pitch")) {
        if (!cli_parse_real(val, -90, 90, &o->pitch))
            bad = "is not a number of degrees in -90..90";
    } else if (!strcmp(a, "--fov")) {
        if (!cli_parse_real(val, 10, 170, &o->fov))
            bad = "is not a number of degrees in 10..170";
    } else if (!strcmp(a, "--frames")) {
        o->frames_set = 1;
        bad = parse_int(val, 1, 1000, &o->frames) ? "is not a count in 1..1000" : NULL;
    } else if (!strcmp(a, "--size")) {
        bad = cli_size_value(val, 1, 8192, &o->w, &o->h)
                  ? "is not WxH with sides 1..8192 (e.g. 640x480)" : NULL;
    } else if (!strcmp(a, "--seed")) {
        bad = !cli_parse_u64(val, &o->seed) ? "is not an unsigned 64-bit number" : NULL;
    } else if (!strcmp(a, "--stereo")) {
        if (!cli_parse_real(val, 0, 0.2, &o->ipd) || o->ipd <= 0)
            bad = "is not an eye distance in (0, 0.2] m";
    } else if (!strcmp(a, "--fireflies")) {
        o->ff_off = !strcmp(val, "off");
        if (!o->ff_off && !cli_parse_real(val, 0, 1e9, &o->ff_time))
            bad = "is not a time in seconds in 0..1e9 (or off)";
    } else if (!strcmp(a, "--cell")) {
        /* the parser of play's --cell and the level line `cell M` */
        if (hol_level_parse_cell(val, strlen(val), &o->cell_m)) {
            cli_error(cmd, 0, "--cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '%.40s'",
                      val);
            return -1;
        }
    } else {
        return 0;
    }
    if (bad) {
        cli_error(cmd, 0, "%s '%.40s' %s", a, val, bad);
        return -1;
    }
    return 1;
}

/* An option with a value: 0 ok, else the exit status (reported). */
static int parse_value_opt(const char *cmd, render_opts *o, const char *a, const char *val)
{
    const char **str[] = {&o->walk, &o->eye, &o->hand, &o->orient, &o->tan, &o->out, &o->ids};
    static const char *const names[] = {"--walk", "--eye",  "--hand",    "--orient",
                                        "--tan",  "--out", "--tile-ids"};
    for (size_t k = 0; k < sizeof names / sizeof *names; k++)
        if (!strcmp(a, names[k])) {
            *str[k] = val;
            return 0;
        }
    int n = parse_number_opt(cmd, o, a, val);
    if (n)
        return n < 0 ? CLI_EXIT_USAGE : 0;
    if (!strcmp(a, "--lang")) {
        return cli_lang_value(cmd, val, &o->lang) ? CLI_EXIT_USAGE : 0;
    } else if (!strcmp(a, "--target")) {
        if (o->ntargets >= HOL_RENDER_MAX_OBJECTIVES) {
            cli_error(cmd, 0, "more than %d --target options", HOL_RENDER_MAX_OBJECTIVES);
            return CLI_EXIT_USAGE;
        }
        o->target_s[o->ntargets++] = val;
    } else if (!strcmp(a, "--lantern")) {
        if (o->nlanterns >= HOL_RENDER_MAX_LANTERNS) {
            cli_error(cmd, 0, "more than %d --lantern options", HOL_RENDER_MAX_LANTERNS);
            return CLI_EXIT_USAGE;
        }
        o->lantern_s[o->nlanterns++] = val;
    } else if (!strcmp(a, "--lighting")) {
        static const char *const skies[3] = {"day", "dusk", "night"};
        o->lighting = -1;
        for (int k = 0; k < 3; k++)
            if (!strcmp(val, skies[k]))
                o->lighting = k;
        if (o->lighting < 0) {
            cli_error(cmd, 0, "--lighting '%.40s' is not day, dusk or night", val);
            return CLI_EXIT_USAGE;
        }
    } else if (!strcmp(a, "--gl")) {
        if (strcmp(val, "egl") && strcmp(val, "osmesa")) {
            cli_error(cmd, 0, "--gl '%.40s' is not osmesa or egl", val);
            return CLI_EXIT_USAGE;
        }
        if (o->gl != RENDER_WINDOW)
            o->gl = val[0] == 'e' ? RENDER_EGL : RENDER_OSMESA;
    } else if (!strcmp(a, "--keys")) {
        o->keys = val;
        if (strspn(val, "wsadlrun.") != strlen(val)) {
            cli_error(cmd, 0, "--keys '%.40s' has a letter other than w s a d l r u n .", val);
            return CLI_EXIT_USAGE;
        }
    }
    return 0;
}

/* A flag: 1 taken, 0 not a flag. */
static int parse_flag(render_opts *o, const char *a)
{
    if (!strcmp(a, "--hud"))
        o->flags = (o->flags & ~HOL_RENDER_NO_HUD) | HOL_RENDER_MINIMAP;
    else if (!strcmp(a, "--window"))
        o->gl = RENDER_WINDOW;
    else if (!strcmp(a, "--stats"))
        o->stats = 1;
    else if (!strcmp(a, "--euclidean"))
        o->flags |= HOL_RENDER_EUCLIDEAN;
    else if (!strcmp(a, "--bare"))
        o->flags |= HOL_RENDER_BARE;
    else
        return 0;
    return 1;
}

/* What the options say together; the outputs checked before any work. */
static int check_opts(const char *cmd, render_opts *o)
{
    const char *why = NULL;
    if (o->gl == RENDER_WINDOW && (o->ipd > 0 || o->ids || o->stats))
        why = "--window shows one eye live; drop --stereo, --tile-ids, --stats";
    else if (o->keys && o->gl != RENDER_WINDOW)
        why = "--keys drives --window";
    else if (o->ipd > 0 && o->ids)
        why = "--tile-ids works on one eye; drop --stereo";
    else if (o->ipd > 0 && o->w < 2)
        why = "--stereo needs an image at least 2 pixels wide";
    else if (!o->out && !o->ids && !o->stats && o->gl != RENDER_WINDOW)
        why = "nothing to do: give --out FILE.png, --tile-ids FILE or --stats";
    if (why) {
        cli_error(cmd, 0, "%s", why);
        return CLI_EXIT_USAGE;
    }
    if (o->gl == RENDER_WINDOW && !o->frames_set)
        o->frames = 0; /* until the window is closed (or the key script ends) */
    if (cli_check_output(cmd, "--out", o->out) || cli_check_output(cmd, "--tile-ids", o->ids))
        return CLI_EXIT_USAGE;
    struct stat a, b;
    if (o->out && o->ids && (!strcmp(o->out, o->ids) ||
                             (!stat(o->out, &a) && !stat(o->ids, &b) && a.st_dev == b.st_dev &&
                              a.st_ino == b.st_ino))) {
        cli_error(cmd, 0, "--out and --tile-ids name the same file '%.200s'", o->out);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

static int parse_opts(const char *cmd, int argc, char **argv, render_opts *o)
{
    memset(o, 0, sizeof *o);
    o->walk = "-";
    o->pitch = -30;
    o->fov = 90;
    o->w = 640;
    o->h = 480;
    o->frames = 1;
    o->flags = HOL_RENDER_NO_HUD;
    o->seed = CLI_SEED_DEFAULT;
    o->cell_m = 1.0;
    static const char *const flags[] = {"--hud", "--window", "--stats", "--euclidean",
                                        "--bare", NULL};
    static const char *const repeatable[] = {"--target", "--lantern", NULL};
    cli_opts p;
    const char *a, *val;
    int r;
    cli_opts_init(&p, cmd, argc, argv, cli_render_valued, flags);
    p.repeatable = repeatable;
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        int g = a ? cli_geometry_value(cmd, a, val, &o->q, &o->cols, &o->rows) : 0;
        if (g < 0)
            return CLI_EXIT_USAGE;
        if (g > 0)
            continue;
        if (!a) {
            cli_error(cmd, 0, "unknown argument '%.40s'; see 'holonomy render --help'", val);
            return CLI_EXIT_USAGE;
        }
        if (val) {
            int st = parse_value_opt(cmd, o, a, val);
            if (st)
                return st;
        } else {
            parse_flag(o, a);
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    for (int k = 0; k < o->ntargets; k++)
        if (hol_tile_resolve_q(o->q ? o->q : 5, o->target_s[k], -1, &o->targets[k])) {
            cli_error(cmd, 0, "--target '%.40s' is not a tile address", o->target_s[k]);
            return CLI_EXIT_USAGE;
        }
    /* a lantern as a level's `place lantern` takes it: a canonical
     * address, one a tile (issue 39) */
    for (int k = 0; k < o->nlanterns; k++) {
        if (hol_tile_parse_q(o->q ? o->q : 5, o->lantern_s[k], -1, &o->lanterns[k])) {
            cli_error(cmd, 0, "--lantern '%.40s' is not a canonical address of {4,%d}",
                      o->lantern_s[k], o->q ? o->q : 5);
            return CLI_EXIT_USAGE;
        }
        for (int j = 0; j < k; j++)
            if (hol_tile_eq(o->lanterns[j], o->lanterns[k])) {
                cli_error(cmd, 0, "--lantern '%.40s' is given twice", o->lantern_s[k]);
                return CLI_EXIT_USAGE;
            }
    }
    return check_opts(cmd, o);
}

/* ---- setup: the user, the camera, the GL, the scene ------------------------ */

/* --hand: the minimap in the hand, facing the eye. 0 ok, else reported. */
static int setup_hand(const char *cmd, const char *hand, hol_frame_desc *fd)
{
    double d[3];
    if (parse_vec3(hand, fd->hand_pos)) {
        cli_error(cmd, 0, "--hand '%.40s' is not three numbers X,Y,Z", hand);
        return CLI_EXIT_USAGE;
    }
    for (int k = 0; k < 3; k++)
        d[k] = fd->cam.eye[k] - fd->hand_pos[k];
    double hd = sqrt(d[0] * d[0] + d[2] * d[2]);
    if (hd < 0.05 || hd > 2.0) {
        cli_error(cmd, 0, "--hand must be 0.05 to 2 m from the eye across the floor");
        return CLI_EXIT_USAGE;
    }
    face_towards(d, fd->hand_orient);
    fd->hand_size = 0.25;
    fd->flags = (fd->flags & ~HOL_RENDER_NO_HUD) | HOL_RENDER_MINIMAP | HOL_RENDER_MINIMAP_HAND;
    return 0;
}

/* The eye in the cell the walk ends in. 0 ok, else reported. */
static int setup_eye(const char *cmd, const render_opts *o, hol_frame_desc *fd)
{
    const hol_room *u = &fd->user;
    const double m = fd->cell_m;
    fd->cam.eye[0] = (u->col + 0.5) * m;
    fd->cam.eye[1] = 1.6;
    fd->cam.eye[2] = (u->row + 0.5) * m;
    if (o->eye && parse_vec3(o->eye, fd->cam.eye)) {
        cli_error(cmd, 0, "--eye '%.40s' is not three numbers X,Y,Z", o->eye);
        return CLI_EXIT_USAGE;
    }
    if (o->hand && setup_hand(cmd, o->hand, fd))
        return CLI_EXIT_USAGE;
    const double *he = fd->cam.eye;
    if (!(he[0] > u->col * m && he[0] < (u->col + 1) * m && he[2] > u->row * m &&
          he[2] < (u->row + 1) * m)) {
        cli_error(cmd, 0,
                  "--eye x,z = %g,%g is not strictly inside cell (%d,%d) where the "
                  "walk ends (x in (%g,%g), z in (%g,%g))",
                  he[0], he[2], u->col, u->row, u->col * m, (u->col + 1) * m, u->row * m,
                  (u->row + 1) * m);
        return CLI_EXIT_USAGE;
    }
    if (!(he[1] > 0.01 && he[1] <= 100)) {
        cli_error(cmd, 0, "--eye height y = %g is not in (0.01, 100] metres", he[1]);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

/* The frame the options describe. 0 ok, else reported. */
static int setup_frame(const char *cmd, const render_opts *o, hol_frame_desc *fd)
{
    size_t wlen = strlen(o->walk), nd = 0, bad = 0, done = 0;
    uint8_t *dirs = malloc(wlen + 1);
    if (!dirs) {
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    memset(fd, 0, sizeof *fd);
    fd->cell_m = o->cell_m;
    hol_room_start_in(o->q, o->cols, o->rows, &fd->user); /* checked values */
    hol_err err = hol_walk_parse(o->walk, wlen, dirs, wlen + 1, &nd, &bad);
    if (!err)
        err = hol_room_walk(&fd->user, dirs, nd, &done);
    free(dirs);
    if (err == HOL_EPARSE)
        cli_error(cmd, 0, "--walk: character %zu is not a step (N, E, S or W)", bad + 1);
    else if (err == HOL_EROOM)
        cli_error(cmd, 0, "--walk: step %zu leaves the room", done + 1);
    else if (err)
        cli_error(cmd, 0, "--walk: step %zu: %s", done + 1, hol_err_str(err));
    if (err)
        return CLI_EXIT_USAGE;
    fd->flags = o->flags;
    if (setup_eye(cmd, o, fd))
        return CLI_EXIT_USAGE;
    fd->cam.yaw_deg = o->yaw;
    fd->cam.pitch_deg = o->pitch;
    fd->cam.fovy_deg = o->fov;
    fd->cam.width = (int)o->w;
    fd->cam.height = (int)o->h;
    int hf = parse_head_form(cmd, o->orient, o->tan, &fd->cam);
    if (hf)
        return hf;
    fd->nobjectives = o->ntargets;
    memcpy(fd->objectives, o->targets, sizeof o->targets);
    fd->objective_text = o->ntargets ? hol_str(o->lang, HOL_S_GUIDE_POLE) : NULL;
    fd->lang = o->lang;
    fd->lighting = o->lighting;
    fd->fireflies = !o->ff_off; /* drawn at dusk and night, as in the app */
    fd->time_s = o->ff_time;
    fd->nlanterns = o->nlanterns;
    memcpy(fd->lanterns, o->lanterns, sizeof o->lanterns);
    fd->steps_taken = (int)nd;
    return 0;
}

/* The GL context of --gl or --window. */
typedef struct render_gl {
    int kind; /* RENDER_* */
    hol_osmesa os;
    hol_egl egl;
    hol_x11 xw;
} render_gl;

static int gl_create(const char *cmd, render_gl *g, int kind, int w, int h)
{
    char msg[256];
    memset(g, 0, sizeof *g);
    g->kind = kind;
    int bad = kind == RENDER_WINDOW ? hol_x11_create(&g->xw, w, h, "holonomy", msg, sizeof msg)
              : kind == RENDER_EGL  ? hol_egl_create(&g->egl, w, h, msg, sizeof msg)
                                    : hol_osmesa_create(&g->os, w, h, msg, sizeof msg);
    if (bad) {
        cli_error(cmd, 0, "%s", msg);
        return CLI_EXIT_FAIL;
    }
    return 0;
}

static void gl_destroy(render_gl *g)
{
    if (g->kind == RENDER_WINDOW)
        hol_x11_destroy(&g->xw);
    else if (g->kind == RENDER_EGL)
        hol_egl_destroy(&g->egl);
    else
        hol_osmesa_destroy(&g->os);
}

/* What a render holds: the world, the renderer, the pixels. */
typedef struct render_scene {
    hol_world *world;
    hol_render *r;
    uint8_t *rgba, *eyebuf;
    double *cpu;
} render_scene;

static void scene_destroy(render_scene *sc)
{
    free(sc->eyebuf);
    free(sc->cpu);
    free(sc->rgba);
    hol_render_destroy(sc->r);
    hol_world_destroy(sc->world);
}

/* The minimap's shortest-path overlay: to the first target. */
static void setup_path(const render_opts *o, hol_frame_desc *fd)
{
    static uint8_t path[HOL_NAV_WALK_MAX];
    if (o->ntargets == 0 || !(o->flags & HOL_RENDER_MINIMAP))
        return;
    hol_nav *nav = NULL;
    hol_nav_desc navd;
    memset(&navd, 0, sizeof navd);
    navd.tiling_q = hol_tile_q(fd->user.tile);
    navd.room_cols = hol_room_cols(&fd->user);
    navd.room_rows = hol_room_rows(&fd->user);
    navd.lazy = 1;
    hol_nav_result nr;
    if (!hol_nav_create(&navd, &nav) &&
        !hol_nav_find(nav, &fd->user, o->targets[0], 200000, path, sizeof path, &nr)) {
        fd->path = path;
        fd->npath = nr.len;
    }
    hol_nav_destroy(nav);
}

static int setup_scene(const char *cmd, const render_opts *o, int gl, hol_frame_desc *fd,
                       render_scene *sc)
{
    hol_world_desc wd;
    memset(&wd, 0, sizeof wd);
    wd.seed = o->seed;
    wd.capacity = 1u << 14;
    wd.tiling_q = o->q;
    hol_err err = hol_world_make(&wd, &sc->world);
    if (!err)
        err = hol_world_update(sc->world, &fd->user);
    if (err) {
        cli_error(cmd, 0, "cannot generate the world: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    setup_path(o, fd);
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.max_width = rd.max_height = 8192;
    rd.world = sc->world;
    rd.getproc = gl != RENDER_OSMESA ? hol_egl_getproc : hol_osmesa_getproc; /* x11 too */
    rd.debug = gl != RENDER_WINDOW; /* a tool's frames: every GL error reported
                                       (the live window's frames sync nothing) */
    if ((err = hol_render_create(&rd, &sc->r))) {
        cli_error(cmd, 0, "cannot initialise the renderer: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    size_t px = (size_t)o->w * (size_t)o->h * 4;
    sc->rgba = malloc(px);
    sc->eyebuf = malloc(px);
    sc->cpu = malloc((size_t)(o->frames > 0 ? o->frames : 1) * sizeof *sc->cpu);
    if (!sc->rgba || !sc->cpu || !sc->eyebuf) {
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    return 0;
}

/* ---- the work: headless frames, the PNG, the stats, the tile ids ----------- */

/* One frame desc per eye: mono, or two eyes side by side. Returns the
 * number of eyes, or 0 after reporting an eye outside the room. */
static int setup_eyes(const char *cmd, const render_opts *o, const hol_frame_desc *fd,
                      hol_frame_desc eye_fd[2])
{
    int neyes = o->ipd > 0 ? 2 : 1;
    for (int e = 0; e < neyes; e++) {
        eye_fd[e] = *fd;
        if (neyes == 1)
            break;
        double side = e == 0 ? -0.5 * o->ipd : 0.5 * o->ipd;
        double yr = o->yaw * 3.14159265358979323846 / 180;
        eye_fd[e].cam.eye[0] = fd->cam.eye[0] + side * cos(yr);
        eye_fd[e].cam.eye[2] = fd->cam.eye[2] - side * sin(yr);
        eye_fd[e].cam.width = (int)o->w / 2;
        hol_err err = hol_motion_eye_state_m(&fd->user, fd->cell_m, fd->cam.eye,
                                             eye_fd[e].cam.eye, &eye_fd[e].user);
        if (err) {
            cli_error(cmd, 0, "--stereo: the %s eye is %s", e ? "right" : "left",
                      err == HOL_EROOM ? "outside the room" : "not in a cell");
            return 0;
        }
    }
    return neyes;
}

static void print_stats(const render_opts *o, const hol_render_stats *st, int neyes,
                        double *cpu)
{
    qsort(cpu, (size_t)o->frames, sizeof *cpu, cmp_double);
    printf("mode %s\n", (o->flags & HOL_RENDER_EUCLIDEAN) ? "euclidean" : "hyperbolic");
    printf("size %ldx%ld\n", o->w, o->h);
    printf("eyes %d\n", neyes);
    for (int e = 0; e < neyes; e++) {
        const char *pre = neyes == 1 ? "" : e ? "right_" : "left_";
        printf("%sdraw_calls %d\n", pre, st[e].draw_calls);
        printf("%striangles %ld\n", pre, st[e].triangles);
        printf("%sstencil_passes %d\n", pre, st[e].stencil_passes);
        printf("%sbranches %d\n", pre, st[e].branches);
        printf("%sstate_changes %d\n", pre, st[e].state_changes);
        printf("%stiles_built %d\n", pre, st[e].tiles_built);
        printf("%suploaded_bytes %ld\n", pre, st[e].uploaded_bytes);
        printf("%sbuild_ms %.3f\n", pre, st[e].build_ms);
    }
    printf("cpu_ms %.3f\n", cpu[o->frames / 2]);
    printf("wall_ms %.3f\n", st[neyes - 1].wall_ms);
}

/* The frames (the last read back into sc->rgba, eyes side by side), then
 * the PNG and the stats. 0 ok, else reported. */
static int render_frames(const char *cmd, const render_opts *o, const hol_frame_desc *fd,
                         render_scene *sc)
{
    hol_frame_desc eye_fd[2];
    hol_render_stats st[2];
    int neyes = setup_eyes(cmd, o, fd, eye_fd), ew = (int)o->w / (neyes ? neyes : 1);
    if (!neyes)
        return CLI_EXIT_USAGE;
    for (int e = 0; e < neyes && o->stats; e++)
        eye_fd[e].flags |= HOL_RENDER_WAIT; /* the CPU ms include the GPU's */
    for (long k = 0; k < o->frames; k++) {
        sc->cpu[k] = 0;
        for (int e = 0; e < neyes; e++) {
            hol_err err = hol_render_frame(sc->r, &eye_fd[e], &st[e]);
            if (err) {
                cli_error(cmd, 0, "rendering failed: %s", hol_err_str(err));
                return err == HOL_EARG ? CLI_EXIT_USAGE : CLI_EXIT_FAIL;
            }
            sc->cpu[k] += st[e].cpu_ms;
            if (k < o->frames - 1 || !o->out)
                continue;
            hol_render_read_rgba(sc->r, ew, (int)o->h, sc->eyebuf);
            for (long y = 0; y < o->h; y++)
                memcpy(sc->rgba + ((size_t)y * (size_t)o->w + (size_t)(e * ew)) * 4,
                       sc->eyebuf + (size_t)y * (size_t)ew * 4, (size_t)ew * 4);
        }
    }
    if (o->out && hol_png_write_file(o->out, sc->rgba, (int)o->w, (int)o->h, 0)) {
        cli_error(cmd, 0, "cannot write '%.200s': %s", o->out, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    if (o->stats)
        print_stats(o, st, neyes, sc->cpu);
    return 0;
}

/* --tile-ids: one ID frame, written atomically. 0 ok, else reported. */
static int render_tile_ids(const char *cmd, const render_opts *o, hol_frame_desc *fd,
                           render_scene *sc)
{
    fd->flags |= HOL_RENDER_IDS;
    hol_err err = hol_render_frame(sc->r, fd, NULL);
    if (err) {
        cli_error(cmd, 0, "rendering tile ids failed: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    hol_render_read_rgba(sc->r, (int)o->w, (int)o->h, sc->rgba);
    if (write_tile_ids(o->ids, sc->rgba, o->w, o->h, hol_render_last_view(sc->r))) {
        cli_error(cmd, 0, "cannot write '%.200s': %s", o->ids, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

int cli_cmd_render(int argc, char **argv)
{
    const char *cmd = "render";
    render_opts o;
    hol_frame_desc fd;
    int status = parse_opts(cmd, argc, argv, &o);
    if (!status)
        status = setup_frame(cmd, &o, &fd);
    if (status)
        return status;
    render_gl gl;
    if ((status = gl_create(cmd, &gl, o.gl, (int)o.w, (int)o.h)))
        return status;
    render_scene sc;
    memset(&sc, 0, sizeof sc);
    status = setup_scene(cmd, &o, o.gl, &fd, &sc);
    if (!status && o.gl == RENDER_WINDOW) {
        fd.flags = (fd.flags & ~HOL_RENDER_NO_HUD) | HOL_RENDER_MINIMAP;
        status = run_window(cmd, &gl.xw, sc.r, sc.world, &fd, o.frames, o.out, sc.rgba, o.keys);
    } else if (!status) {
        status = render_frames(cmd, &o, &fd, &sc);
        if (!status && o.ids)
            status = render_tile_ids(cmd, &o, &fd, &sc);
    }
    scene_destroy(&sc);
    gl_destroy(&gl);
    int out = cli_finish_output(cmd);
    return status ? status : out;
}
