/* cmd_xr.c - `holonomy xr`: the headset app on the desktop's OpenXR runtime
 * (platform/openxr/hol_xr.h), with the desktop session's levels, logs and
 * recording (session.h), so a headset session replays headless. Built in
 * only with `make xr` (XR=1; needs libopenxr-dev and GLX). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "play_setup.h"
#include "session.h"
#ifdef HOL_XR
#include "../openxr/hol_xr.h"
#endif

static const char *const xr_usage =
    "usage: holonomy xr [LEVEL] [--frames N] [--log DIR] [--record FILE]\n"
    "                   [--input FILE] [--check-frame K --check-dir DIR]\n"
    "\n"
    "The headset app on this machine's OpenXR runtime (for example Monado):\n"
    "the room centred on the stage origin, north along stage -Z; the\n"
    "recentre action places it from the head. LEVEL is a level file (SPEC\n"
    "section 5); without one, the default campaign. Logs and the recording\n"
    "are those of 'holonomy play', so 'holonomy replay' runs a headset\n"
    "session again headless.\n"
    "\n"
    "  --frames N      request exit after N submitted frames\n"
    "  --log DIR       research logs (README: Logs)\n"
    "  --record FILE   record the session's input\n"
    "  --input FILE    scripted head motion: frame k takes the head pose of\n"
    "                  input line k (room coordinates; the simulated headset\n"
    "                  does not move), repeating\n"
    "  --check-frame K with --check-dir DIR: read eye 0 of frame K back from\n"
    "                  the swapchain, render the same eye with OSMesa, write\n"
    "                  both PNGs to DIR and print how many pixels differ\n"
    "\n"
    "Prints 'xr: ...' progress lines (state changes, bindings, frames, the\n"
    "CPU time per stereo frame). Exit status: 0 ok, 1 failure (no runtime,\n"
    "no display, a runtime error), 2 bad input.\n";

#ifdef HOL_XR
static int xr_step(void *user, const hol_input *in, const hol_app_view **out_view)
{
    session *s = user;
    int rc = session_step(s, in);
    *out_view = hol_app_get_view(s->app);
    return rc < 0 ? -1 : rc > 0 ? 1 : 0;
}

static struct hol_world *xr_world(void *user)
{
    return hol_app_world(((session *)user)->app);
}

static int xr_level_started(void *user)
{
    return hol_app_get_events(((session *)user)->app)->level_started;
}
#endif

int cli_cmd_xr(int argc, char **argv)
{
    const char *cmd = "xr";
    if (cli_wants_help(argc, argv)) {
        fputs(xr_usage, stdout);
        return cli_finish_output(cmd);
    }
    const char *level_path = NULL, *log_dir = NULL, *rec = NULL, *input_path = NULL,
               *check_dir = NULL;
    long frames = 0, check_frame = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : NULL;
        int takes = !strcmp(a, "--frames") || !strcmp(a, "--log") || !strcmp(a, "--record") ||
                    !strcmp(a, "--input") || !strcmp(a, "--check-frame") ||
                    !strcmp(a, "--check-dir");
        if (takes && !val) {
            cli_error(cmd, 0, "%s needs a value; see 'holonomy xr --help'", a);
            return CLI_EXIT_USAGE;
        }
        if (!strcmp(a, "--frames") || !strcmp(a, "--check-frame")) {
            size_t n = cli_parse_count(val);
            int zero_ok = a[2] == 'c' && !strcmp(val, "0");
            if ((!n && !zero_ok) || n > 100000000) {
                cli_error(cmd, 0, "%s '%.40s' is not a count in %d..100000000", a, val,
                          zero_ok ? 0 : 1);
                return CLI_EXIT_USAGE;
            }
            if (a[2] == 'f')
                frames = (long)n;
            else
                check_frame = (long)n;
        } else if (!strcmp(a, "--log"))
            log_dir = val;
        else if (!strcmp(a, "--record"))
            rec = val;
        else if (!strcmp(a, "--input"))
            input_path = val;
        else if (!strcmp(a, "--check-dir"))
            check_dir = val;
        else if (a[0] == '-' && a[1]) {
            cli_error(cmd, 0, "unknown option '%.40s'; see 'holonomy xr --help'", a);
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
    if ((check_frame >= 0) != (check_dir != NULL)) {
        cli_error(cmd, 0, "--check-frame and --check-dir go together");
        return CLI_EXIT_USAGE;
    }
    if (cli_require_folder(cmd, "--log", log_dir) ||
        cli_require_folder(cmd, "--check-dir", check_dir))
        return CLI_EXIT_USAGE;
    static session_level levels[SESSION_MAX_LEVELS];
    int nlevels = 0;
    int lst = play_levels(cmd, level_path, NULL, CLI_SEED_DEFAULT, levels, &nlevels);
    if (lst)
        return lst;
    /* scripted head motion */
    file_lines fl;
    memset(&fl, 0, sizeof fl);
    hol_input *script = NULL;
    long nscript = 0;
    if (input_path) {
        long first = 0;
        int rs = read_input_lines(cmd, input_path, &fl, &first);
        if (rs)
            return rs;
        script = calloc((size_t)(fl.n - first > 0 ? fl.n - first : 1), sizeof *script);
        if (!script) {
            free_lines(&fl);
            cli_error(cmd, 0, "out of memory");
            return CLI_EXIT_FAIL;
        }
        double prev = 0;
        for (long k = first; k < fl.n; k++)
            if (parse_input_line(cmd, &fl, k, &script[nscript++], &prev)) {
                free(script);
                free_lines(&fl);
                return CLI_EXIT_USAGE;
            }
        free_lines(&fl);
    }
#ifdef HOL_XR
    session s;
    memset(&s, 0, sizeof s);
    int status = session_open(&s, cmd, levels, nlevels, log_dir, rec);
    if (!status) {
        hol_xr_desc d;
        memset(&d, 0, sizeof d);
        d.frames = frames;
        d.check_frame = check_frame;
        d.check_dir = check_dir;
        d.script = script;
        d.nscript = nscript;
        hol_xr_app_fns fns = {.user = &s, .step = xr_step, .world = xr_world,
                               .level_started = xr_level_started};
        status = hol_xr_run(&d, &fns) ? CLI_EXIT_FAIL : CLI_EXIT_OK;
    }
    if (s.app || s.recording) {
        int cs = session_close(&s);
        if (!status)
            status = cs;
    }
    free(script);
    return status;
#else
    (void)frames;
    (void)rec;
    free(script);
    cli_error(cmd, 0, "this build has no OpenXR; build with 'make xr' (needs libopenxr-dev, "
                      "GLX; see README 'Headset')");
    return CLI_EXIT_FAIL;
#endif
}
