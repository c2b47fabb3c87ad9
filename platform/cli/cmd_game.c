/* cmd_game.c - `holonomy game LEVEL`: plays a level headless from lines of
 * room steps through the same app step as `play` (SPEC section 5). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_app.h"
#include "../../core/hol_room.h"
#include "../file/hol_file.h"
#include "cli.h"
#include "play_setup.h"

const char *const cli_game_usage =
    "usage: holonomy game LEVEL [--tiling 4,Q] [--room CxR] [--cell M] < PLAYS\n"
    "\n"
    "Plays LEVEL (a level file, SPEC section 5) once per line of standard\n"
    "input: the line's room steps (N, E, S, W; '-' or empty for none) from the\n"
    "level's beginning, through the same app step as 'holonomy play' (a\n"
    "tracked head at the cell centres). Prints per line\n"
    "  done STEPS OPTIMUM   the steps until the level was complete\n"
    "  open STEPS OPTIMUM   all of the line's steps; not complete\n"
    "OPTIMUM is the fewest room steps that complete the level (-1 for explore,\n"
    "the tutorial and lessons, which are not scored; a lesson plays its walk,\n"
    "not its question and screens). Steps after completion are ignored. A step that leaves the room is bad input.\n"
    "\n"
    PLAY_GEOMETRY_USAGE
    "\n"
    "Exit status: 0 ok, 1 failure, 2 bad input (one line naming the line).\n";

typedef struct game_ctx {
    hol_app *app;
    const hol_app_level *lvl;
    const char *path;
    double t; /* input time never goes back, across plays too */
} game_ctx;

static hol_input head_at(double t, int col, int row, double m)
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED | HOL_INPUT_HEAD_VALID;
    in.head.pos[0] = (float)((col + 0.5) * m);
    in.head.pos[1] = 1.6f;
    in.head.pos[2] = (float)((row + 0.5) * m);
    in.head.quat[3] = 1;
    return in;
}

/* Why a level cannot start, for the one line. */
static const char *start_error(hol_err err)
{
    return err == HOL_EBUDGET    ? "its optimum cannot be proved exact"
           : err == HOL_EARG     ? "an objective lies on the tile where the level begins"
           : err == HOL_EUNREACH ? "no walk inside the room reaches an objective"
                                 : hol_err_str(err);
}

static int start_status(hol_err err)
{
    return err == HOL_EBUDGET || err == HOL_EARG || err == HOL_EUNREACH ? CLI_EXIT_USAGE
                                                                       : CLI_EXIT_FAIL;
}

static int play_line(void *vctx, long lineno, char *s, size_t len)
{
    game_ctx *g = vctx;
    cli_trim(&s, &len);
    if (memchr(s, 0, len)) {
        cli_error("game", lineno, "a NUL byte");
        return CLI_EXIT_USAGE;
    }
    size_t nd = 0, bad = 0;
    static uint8_t dirs[1 << 16];
    hol_err err = hol_walk_parse(s, len, dirs, sizeof dirs, &nd, &bad);
    if (err == HOL_ENOMEM) {
        cli_error("game", lineno, "more than %zu steps", sizeof dirs);
        return CLI_EXIT_USAGE;
    }
    if (err) {
        cli_error("game", lineno, "character %zu is not a step (N, E, S or W)", bad + 1);
        return CLI_EXIT_USAGE;
    }
    if ((err = hol_app_start_level(g->app, g->lvl))) {
        cli_error("game", 0, "%.200s: %s", g->path, start_error(err));
        return start_status(err);
    }
    const hol_app_view *v = hol_app_get_view(g->app);
    int col = v->user.col, row = v->user.row, done = -1;
    double t = g->t + 1;
    hol_input in = head_at(t, col, row, v->cell_m);
    if (hol_app_step(g->app, &in)) {
        cli_error("game", lineno, "the app step failed");
        return CLI_EXIT_FAIL;
    }
    for (size_t i = 0; i < nd; i++) {
        int dc, dr;
        hol_dir_delta(dirs[i], &dc, &dr);
        if (col + dc < 0 || col + dc >= hol_room_cols(&v->user) || row + dr < 0 ||
            row + dr >= hol_room_rows(&v->user)) {
            cli_error("game", lineno, "step %zu (%c from cell (%d,%d)) leaves the room", i + 1,
                      hol_dir_to_char(dirs[i]), col, row);
            return CLI_EXIT_USAGE;
        }
        col += dc;
        row += dr;
        if (done >= 0)
            continue; /* after completion: checked, not played */
        t += 0.25;
        in = head_at(t, col, row, v->cell_m);
        err = hol_app_step(g->app, &in);
        if (err) {
            cli_error("game", lineno, "step %zu: %s", i + 1, hol_err_str(err));
            return err == HOL_ERANGE ? CLI_EXIT_USAGE : CLI_EXIT_FAIL;
        }
        if (hol_app_get_events(g->app)->level_ended == HOL_APP_END_DONE)
            done = v->hud.steps;
    }
    g->t = t;
    if (done >= 0)
        printf("done %d %d\n", done, v->hud.optimum);
    else
        printf("open %d %d\n", v->hud.steps, v->hud.optimum);
    return 0;
}

const char *const cli_game_valued[] = {PLAY_GEOMETRY_OPTIONS, NULL};

int cli_cmd_game(int argc, char **argv)
{
    const char *cmd = "game";
    static const char *const flags[] = {NULL};
    cli_opts p;
    cli_opts_init(&p, cmd, argc, argv, cli_game_valued, flags);
    const char *a, *val, *path = NULL;
    play_geometry geo = {0, 0, 0, 0};
    int r, operands = 0;
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a) {
            path = val;
            operands++;
        } else if (play_geometry_value(cmd, a, val, &geo) < 0) {
            return CLI_EXIT_USAGE;
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (operands != 1) {
        cli_error(cmd, 0, "usage: holonomy game LEVEL < PLAYS; see 'holonomy game --help'");
        return CLI_EXIT_USAGE;
    }
    static hol_level L;
    int rs = play_read_level(cmd, path, &L);
    if (!rs)
        rs = play_geometry_apply(cmd, &geo, &L, 1);
    if (rs)
        return rs;
    if (L.lvl.lesson) { /* a lesson's walk alone: its question and screens are play's */
        L.lvl.instructions[0] = L.lvl.closing[0] = 0;
        L.lvl.nasks = 0;
        L.lvl.point = HOL_APP_POINT_NONE;
    }
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.lazy_nav = 1; /* headless: tables when first needed */
    d.lazy_world = 1; /* and the world's pages when first written */
    game_ctx g = {NULL, &L.lvl, path, 0};
    hol_err err;
    if ((err = hol_app_create(&d, &g.app))) {
        cli_error(cmd, 0, "cannot create the app: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    /* a bad level is reported before any input is read */
    if ((err = hol_app_start_level(g.app, &L.lvl))) {
        hol_app_destroy(g.app);
        long at = err == HOL_EBUDGET || err == HOL_EUNREACH ? hol_level_objective_line(&L) : 0;
        if (at > 0) /* the objective's line (the level's other lines are good) */
            cli_error(cmd, 0, "%.200s: line %ld: %s", path, at, start_error(err));
        else
            cli_error(cmd, 0, "%.200s: %s", path, start_error(err));
        return start_status(err);
    }
    int status = cli_for_each_line(cmd, play_line, &g);
    hol_app_destroy(g.app);
    return status;
}
