/* cmd_replay.c - `holonomy replay`: a recording through the same session
 * as the play (core/hol_session.h), headless: its options, its setup
 * (the recording read a line at a time, the outputs, an OSMesa renderer
 * for --png-frames) and its loop. */
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_session.h"
#include "../../render/hol_app_frame.h"
#include "../../render/hol_render.h"
#include "../audio/hol_audio.h"
#include "../file/hol_file.h"
#include "../image/hol_png_file.h"
#include "../osmesa/hol_osmesa.h"
#include "cli.h"
#include "play_setup.h"
#include "play_track.h"

const char *const cli_replay_usage =
    "usage: holonomy replay REC [--log DIR [--append]] [--png-frames LIST --out-dir D]\n"
    "                       [--size WxH] [--tiling 4,Q] [--room CxR] [--cell M]\n"
    "                       [--wav FILE] [--track-hz N] [--lang en|de|nl]\n"
    "\n"
    "Run a recording (holonomy play --record) through the same session: the\n"
    "logs come out byte for byte as in the play (the recording names the\n"
    "session, participant, start and version). --log DIR as for play (made\n"
    "when its parent exists; refused when it holds logs, unless --append).\n"
    "--png-frames renders the listed frames (0-based, comma separated)\n"
    "headless with OSMesa to D/frame-NNNNNN.png (--size, default 640x480); a\n"
    "frame beyond the recording is bad input (the others are still written).\n"
    "--wav FILE renders the recording's sound (core/hol_sound.h: the\n"
    "level's 'sound' line and cues) offline through OpenAL Soft's loopback\n"
    "device: 16-bit PCM stereo at 48 kHz, from the first record's time to the\n"
    "last plus 1 s, at most 600 s; the same recording gives the same bytes;\n"
    "written whole or not at all (docs/sound.md).\n"
    "The recording is read a line at a time (lines of at most 1024 bytes).\n"
    "A recording's levels carry their tiling, room and cell size (their\n"
    "'tiling', 'room' and 'cell' lines; without one, the default), so a replay\n"
    "needs no options and is never replayed in another geometry; given, an\n"
    "option must equal every recorded level's (else refused, one line):\n"
    PLAY_GEOMETRY_USAGE
    PLAY_TRACK_USAGE
    "                  the play's --track-hz gives its track rows byte for byte\n"
    CLI_LANG_USAGE
    "                  (--png-frames draws the frames' text in it; the logs are\n"
    "                  the same in every language)\n"
    "\n"
    "SIGINT, SIGTERM or SIGHUP end it cleanly (the attempt in play is logged\n"
    "with end 'aborted'). A killed session's recording (REC.live) ends its\n"
    "attempt 'killed', as the recovery of the play's log folder did.\n"
    "Exit status: 0 ok, 1 failure, 2 bad input (a bad\n"
    "recording line is named), 128+N after signal N.\n";

typedef struct replay_ctx {
    const char *cmd, *rec, *log_dir, *out_dir, *list;
    int w, h, append;
    int track_hz; /* --track-hz; 0: not given (10) */
    int lang;     /* --lang (core/hol_str.h); 0: English */
    play_geometry geo;
    long pngs[4096];
    int npng;
    play_input input;
    int has_input;
    play_out out;
    hol_session *s;
    hol_osmesa gl;
    int have_gl;
    hol_render *r;
    uint8_t *rgba;
    const char *wav;
    hol_audio *au;
    hol_sound snd;
    hol_sound_list sl;
    int16_t *pcm;        /* stereo frames rendered so far */
    long nframes, capframes;
    double t0, last_t;
    int have_t0;
} replay_ctx;

/* ---- options ------------------------------------------------------------------ */

/* "3,10,200" into a list; 1 on a bad list. */
static int parse_frame_list(const char *s, long *out, int cap, int *out_n)
{
    int n = 0;
    const char *p = s;
    while (*p) {
        char *e;
        errno = 0;
        long v = *p >= '0' && *p <= '9' ? strtol(p, &e, 10) : -1; /* digits: no sign, blank */
        if (v < 0 || errno || n >= cap || (*e && *e != ','))
            return 1;
        out[n++] = v;
        p = *e ? e + 1 : e;
        if (*e && !*p)
            return 1;
    }
    *out_n = n;
    return n == 0;
}

const char *const cli_replay_valued[] = {"--log",  "--png-frames", "--out-dir", "--size",
                                            "--wav",  "--track-hz", "--lang", PLAY_GEOMETRY_OPTIONS, NULL};

/* The options that only store their value or set a flag. */
static const cli_store replay_store[] = {
    CLI_STORE_STR("--log", replay_ctx, log_dir),
    CLI_STORE_STR("--png-frames", replay_ctx, list),
    CLI_STORE_STR("--out-dir", replay_ctx, out_dir),
    CLI_STORE_STR("--wav", replay_ctx, wav),
    CLI_STORE_FLAG("--append", replay_ctx, append, 1),
    {NULL, 0, 0, 0}};

static int replay_options(replay_ctx *c, int argc, char **argv)
{
    static const char *const flags[] = {"--append", NULL};
    cli_opts p;
    cli_opts_init(&p, c->cmd, argc, argv, cli_replay_valued, flags);
    const char *a, *val;
    int r, g;
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a && c->rec) {
            cli_error(c->cmd, 0, "more than one recording ('%.40s')", val);
            return CLI_EXIT_USAGE;
        }
        if (!a)
            c->rec = val;
        else if (cli_store_opt(replay_store, a, val, c))
            ;
        else if (!strcmp(a, "--track-hz")) {
            if (play_track_value(c->cmd, val, &c->track_hz))
                return CLI_EXIT_USAGE;
        } else if (!strcmp(a, "--lang")) {
            if (cli_lang_value(c->cmd, val, &c->lang))
                return CLI_EXIT_USAGE;
        } else if ((g = play_geometry_value(c->cmd, a, val, &c->geo)) != 0) {
            if (g < 0)
                return CLI_EXIT_USAGE;
        } else if (cli_parse_size(c->cmd, val, &c->w, &c->h))
            return CLI_EXIT_USAGE;
    }
    const char *bad = r < 0                      ? ""
                      : !c->rec                  ? "no recording given; see 'holonomy replay --help'"
                      : !c->list != !c->out_dir  ? "--png-frames and --out-dir go together"
                      : c->append && !c->log_dir ? "--append goes with --log"
                                                 : NULL;
    if (!bad && c->list && parse_frame_list(c->list, c->pngs, 4096, &c->npng))
        bad = "--png-frames is not a comma-separated list of frames";
    if (bad && bad[0])
        cli_error(c->cmd, 0, "%s", bad);
    if (bad || play_track_check(c->cmd, c->track_hz, c->log_dir))
        return CLI_EXIT_USAGE;
    const cli_path in[] = {{"the recording", c->rec}};
    const cli_path out[] = {{"--log", c->log_dir}, {"--out-dir", c->out_dir}, {"--wav", c->wav}};
    const cli_outs outs = {out, 3, c->log_dir};
    return cli_check_reads(c->cmd, in, 1, &outs);
}

/* ---- setup ------------------------------------------------------------------------ */

/* A recording names the geometry of each level (its lines, or the
 * defaults {4,5} 3 x 3 of 1 m): --tiling, --room and --cell may only
 * repeat it, never replay it in another (0, or refused as one line). */
static int replay_check_geometry(const replay_ctx *c)
{
    const play_geometry *g = &c->geo;
    for (int i = 0; i < c->input.rec.nlevels; i++) {
        const hol_level *lv = &c->input.levels[i];
        const hol_app_level *L = &lv->lvl;
        int q = L->tiling_q ? L->tiling_q : HOL_TILING_DEFAULT_Q;
        int cols = L->room_cols ? L->room_cols : 3, rows = L->room_rows ? L->room_rows : 3;
        double cell = L->cell_m > 0 ? L->cell_m : 1.0;
        char had[48] = "", want[48] = "";
        if (g->q && g->q != q)
            snprintf(had, sizeof had, "{4,%d}", q), snprintf(want, sizeof want, "--tiling 4,%d", g->q);
        else if (g->cols && (g->cols != cols || g->rows != rows))
            snprintf(had, sizeof had, "a %dx%d room", cols, rows),
                snprintf(want, sizeof want, "--room %dx%d", g->cols, g->rows);
        else if (g->cell_m > 0 && g->cell_m != cell) {
            char a[16], b[16];
            snprintf(had, sizeof had, "cells of %s m", hol_level_format_cell(cell, a));
            snprintf(want, sizeof want, "--cell %s", hol_level_format_cell(g->cell_m, b));
        }
        if (had[0]) {
            cli_error(c->cmd, 0, "level '%.60s' was recorded in %s; %s would replay it in "
                                 "another geometry (drop the option)",
                      lv->name, had, want);
            return CLI_EXIT_USAGE;
        }
    }
    return 0;
}

static int replay_renderer(replay_ctx *c)
{
    char msg[256];
    if (hol_osmesa_create(&c->gl, c->w, c->h, msg, sizeof msg)) {
        cli_error(c->cmd, 0, "%s", msg);
        return CLI_EXIT_FAIL;
    }
    c->have_gl = 1;
    hol_render_desc rd;
    memset(&rd, 0, sizeof rd);
    rd.getproc = hol_osmesa_getproc;
    rd.debug = 1; /* a tool's frames: every GL error reported */
    rd.world = hol_app_world(hol_session_app(c->s));
    c->rgba = malloc((size_t)c->w * (size_t)c->h * 4);
    hol_err e = c->rgba ? hol_render_create(&rd, &c->r) : HOL_ENOMEM;
    if (e) {
        cli_error(c->cmd, 0, "cannot initialise the renderer: %s", hol_err_str(e));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

static int replay_prepare(replay_ctx *c)
{
    if (cli_require_folder(c->cmd, "--out-dir", c->out_dir))
        return CLI_EXIT_USAGE;
    for (int k = 0; k < c->npng; k++) { /* every frame's file, before any work */
        char path[4096];
        snprintf(path, sizeof path, "%s/frame-%06ld.png", c->out_dir, c->pngs[k]);
        if (cli_check_output(c->cmd, "--out-dir", path))
            return CLI_EXIT_USAGE;
    }
    if (c->wav && cli_check_output(c->cmd, "--wav", c->wav))
        return CLI_EXIT_USAGE;
    int st = play_out_open(c->cmd, c->log_dir, c->append, NULL, &c->out);
    c->out.track_hz = c->track_hz;
    c->out.lang = c->lang;
    if (!st) {
        st = play_input_open(c->cmd, c->rec, 1, &c->input);
        c->has_input = !st;
    }
    if (!st)
        st = replay_check_geometry(c);
    if (!st)
        st = play_session_open(c->cmd, &c->out, c->input.levels, c->input.rec.nlevels,
                               &c->input.rec.meta, c->append, &c->s);
    if (!st && c->npng)
        st = replay_renderer(c);
    char msg[256];
    if (!st && c->wav && hol_audio_open(1, 1.0, &c->au, msg, sizeof msg)) {
        cli_error(c->cmd, 0, "--wav: %s", msg);
        st = CLI_EXIT_FAIL;
    }
    hol_sound_init(&c->snd);
    return st;
}

/* ---- sound ------------------------------------------------------------------------ */

#define REPLAY_WAV_MAX_S 600

/* Render the sound up to time t (the state of the frame before). */
static int replay_render_to(replay_ctx *c, double t)
{
    long target = (long)((t - c->t0) * HOL_SOUND_RATE + 0.5);
    if (target <= c->nframes)
        return 0;
    if (target > (long)REPLAY_WAV_MAX_S * HOL_SOUND_RATE) {
        cli_error(c->cmd, 0, "--wav: the recording is longer than %d s of sound",
                  REPLAY_WAV_MAX_S);
        return CLI_EXIT_FAIL;
    }
    if (target > c->capframes) {
        long cap = c->capframes ? c->capframes : HOL_SOUND_RATE * 4;
        while (cap < target)
            cap *= 2;
        int16_t *p = realloc(c->pcm, (size_t)cap * 4);
        if (!p) {
            cli_error(c->cmd, 0, "--wav: out of memory");
            return CLI_EXIT_FAIL;
        }
        c->pcm = p, c->capframes = cap;
    }
    hol_audio_render(c->au, c->pcm + 2 * c->nframes, (int)(target - c->nframes));
    c->nframes = target;
    return 0;
}

static int replay_sound(replay_ctx *c, const hol_input *in)
{
    if (!c->have_t0)
        c->t0 = in->time_s, c->have_t0 = 1;
    int r = replay_render_to(c, in->time_s);
    if (r)
        return r;
    hol_app *app = hol_session_app(c->s);
    hol_sound_update(&c->snd, hol_app_get_view(app), hol_app_get_events(app),
                     hol_app_world(app), &c->sl);
    hol_audio_apply(c->au, &c->sl);
    c->last_t = in->time_s;
    return 0;
}

static void replay_le(uint8_t *p, uint32_t v, int n)
{
    for (int i = 0; i < n; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

/* The last record plus 1 s, then the file, whole or not at all. */
static int replay_write_wav(replay_ctx *c)
{
    int r = replay_render_to(c, c->last_t + 1.0);
    if (r)
        return r;
    size_t data = (size_t)c->nframes * 4;
    uint8_t *f = malloc(44 + data);
    if (!f) {
        cli_error(c->cmd, 0, "--wav: out of memory");
        return CLI_EXIT_FAIL;
    }
    memcpy(f, "RIFF", 4), replay_le(f + 4, (uint32_t)(36 + data), 4);
    memcpy(f + 8, "WAVEfmt ", 8), replay_le(f + 16, 16, 4), replay_le(f + 20, 1, 2);
    replay_le(f + 22, 2, 2), replay_le(f + 24, HOL_SOUND_RATE, 4);
    replay_le(f + 28, HOL_SOUND_RATE * 4, 4), replay_le(f + 32, 4, 2), replay_le(f + 34, 16, 2);
    memcpy(f + 36, "data", 4), replay_le(f + 40, (uint32_t)data, 4);
    for (long i = 0; i < 2 * c->nframes; i++)
        replay_le(f + 44 + 2 * i, (uint16_t)c->pcm[i], 2);
    hol_err e = hol_file_write_atomic(c->wav, f, 44 + data);
    int en = errno; /* the cause in errno's own words, not "input/output error" */
    free(f);
    if (e) {
        cli_error(c->cmd, 0, "cannot write '%.200s': %s", c->wav,
                  e == HOL_EIO ? strerror(en) : hol_err_str(e));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

/* ---- the loop ------------------------------------------------------------------------ */

static int replay_png(replay_ctx *c, long frame)
{
    hol_frame_desc fd;
    hol_app_frame_desc(hol_app_get_view(hol_session_app(c->s)), -1, c->w, c->h, 0, &fd);
    hol_err e = hol_render_frame(c->r, &fd, NULL);
    char path[4096];
    snprintf(path, sizeof path, "%s/frame-%06ld.png", c->out_dir, frame);
    if (!e)
        hol_render_read_rgba(c->r, c->w, c->h, c->rgba);
    if (e) {
        cli_error(c->cmd, 0, "cannot render frame %ld to '%.200s'", frame, path);
        return CLI_EXIT_FAIL;
    }
    if (hol_png_write_file(path, c->rgba, c->w, c->h, 0)) {
        cli_error(c->cmd, 0, "cannot write frame %ld to '%.200s': %s", frame, path,
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

static int replay_loop(replay_ctx *c, int *abort)
{
    for (;;) {
        if (cli_caught_signal()) {
            *abort = 1;
            return 0;
        }
        hol_input in;
        int r = play_input_next(&c->input, &in);
        if (r <= 0)
            return -r;
        long frame = hol_session_frames(c->s);
        int over = 0;
        hol_err err = hol_session_step(c->s, &in, &over);
        if (err) {
            cli_error(c->cmd, 0, "%s", hol_session_message(c->s));
            return err == HOL_EARG ? CLI_EXIT_USAGE : CLI_EXIT_FAIL;
        }
        if (c->r && hol_app_get_events(hol_session_app(c->s))->level_started)
            hol_render_invalidate(c->r);
        if (c->au && (r = replay_sound(c, &in)))
            return r;
        for (int k = 0; k < c->npng; k++)
            if (c->pngs[k] == frame && (r = replay_png(c, frame)))
                return r;
        if (over)
            return 0;
    }
}

/* A listed frame the recording never reached is bad input, said once (the
 * frames it reached are written). */
static int replay_missed_frames(replay_ctx *c)
{
    long frames = hol_session_frames(c->s);
    for (int k = 0; k < c->npng; k++)
        if (c->pngs[k] >= frames) {
            cli_error(c->cmd, 0, "--png-frames: frame %ld is beyond the recording (frames 0..%ld)",
                      c->pngs[k], frames - 1);
            return CLI_EXIT_USAGE;
        }
    return 0;
}

int cli_cmd_replay(int argc, char **argv)
{
    static replay_ctx c;
    memset(&c, 0, sizeof c);
    c.cmd = "replay";
    c.w = 640, c.h = 480;
    int status = replay_options(&c, argc, argv);
    if (status)
        return status;
    cli_catch_signals();
    int abort = 0;
    status = replay_prepare(&c);
    if (!status)
        status = replay_loop(&c, &abort);
    if (!status)
        play_print_end(c.s);
    if (!status && !abort)
        status = replay_missed_frames(&c);
    if (!status && !abort && c.au)
        status = replay_write_wav(&c);
    hol_audio_close(c.au);
    free(c.pcm);
    hol_render_destroy(c.r);
    free(c.rgba);
    if (c.have_gl)
        hol_osmesa_destroy(&c.gl);
    /* a recording of an aborted session ends aborted (its exit stays 0);
     * a killed one's (REC.live, never renamed) as the kill and the
     * recovery ended the play's attempt: killed */
    size_t rl = strlen(c.rec);
    int killed = !status && !abort && c.has_input && !c.input.aborted && rl > 5 &&
                 !strcmp(c.rec + rl - 5, ".live");
    int end = play_session_end(c.cmd, c.s,
                               killed ? PLAY_END_KILLED
                                      : abort || (c.has_input && c.input.aborted));
    play_out_close(&c.out);
    if (c.has_input)
        play_input_close(&c.input);
    int out = cli_finish_output(c.cmd);
    status = status ? status : end ? end : out;
    int sig = cli_caught_signal();
    return status ? status : sig ? 128 + sig : 0;
}
