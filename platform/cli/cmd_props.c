/* cmd_props.c - `holonomy props --out FILE.svg`: a printable plan of the
 * room that shows where real hedges and trees stand (core/hol_props.h;
 * docs/headset.md, "Props"). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_fit.h"
#include "../../core/hol_props.h"
#include "../file/hol_file.h"
#include "cli.h"
#include "play_setup.h"

const char *const cli_props_usage =
    "usage: holonomy props [--room CxR] [--cell M] [--tiling 4,Q] [--level FILE]\n"
    "                      [--play-area WxD] [--scale 1:N] --out FILE.svg\n"
    "\n"
    "Writes a printable plan of the room (SVG, millimetres, the page size\n"
    "stated: A4 or A3) showing where real props stand: the hedges along the\n"
    "room's edges and a tree trunk on every vertex of its grid (the inner\n"
    "ones free-standing, the corner and side ones in the hedge line), with\n"
    "measurements and the trunks' positions in metres from the north-west\n"
    "corner (x east, z south; SPEC 1). Every tile of the forest maps onto the\n"
    "same room, so these few props stand in for every virtual hedge and trunk.\n"
    "\n"
    "  --room CxR        a room of C x R cells, 3 to 5 each (default 3x3)\n"
    "  --cell M          the side of a cell in metres, 0.5 to 1.5 (default 1)\n"
    "  --tiling 4,Q      the tiling {4,Q}, Q from 4 to 8 (default 4,5): named on\n"
    "                    the plan; the room is the same in every tiling\n"
    "  --level FILE      the room and cell of a level file (its 'room' and 'cell'\n"
    "                    lines; --room, --cell and --tiling are its defaults, and a\n"
    "                    level whose own line differs is refused, as in play)\n"
    "  --play-area WxD   the room and cell fitted to a play area of W x D metres\n"
    "                    (0.5 to 20 each; the rule of holonomy xr and the web,\n"
    "                    0.1 m kept clear: docs/headset.md); not with --room or\n"
    "                    --cell; a level's own room and cell are kept. The play\n"
    "                    area is drawn round the room\n"
    "  --scale 1:N       the drawing's scale, N from 5 to 200 (default 1:20, or\n"
    "                    1:25, 1:50, 1:100: the first that fits an A3 page); a\n"
    "                    scale whose plan fits no A3 page is refused\n"
    "  --out FILE.svg    the plan (written atomically; not the level file)\n"
    "  -h, --help        this text\n"
    "\n"
    "Exit status: 0 ok, 1 output failure, 2 bad arguments or level.\n";

typedef struct props_args {
    const char *out, *level;
    play_geometry geo;
    double area_w, area_d;
    int scale;
} props_args;

/* "1:N" (N 5..200): 0 ok, else reported and 2. */
static int props_parse_scale(const char *cmd, const char *val, int *out)
{
    uint64_t n = 0;
    if (!strncmp(val, "1:", 2) && val[2] >= '0' && val[2] <= '9' && cli_parse_decimal(val + 2, &n) &&
        n >= HOL_PROPS_SCALE_MIN && n <= HOL_PROPS_SCALE_MAX) {
        *out = (int)n;
        return 0;
    }
    cli_error(cmd, 0, "--scale needs 1:N with N from %d to %d, not '%.40s'", HOL_PROPS_SCALE_MIN,
              HOL_PROPS_SCALE_MAX, val);
    return CLI_EXIT_USAGE;
}

/* "WxD" metres, each in 0.5..20: 0 ok, else reported and 2. */
static int props_parse_area(const char *cmd, const char *val, double *w, double *d)
{
    if (cli_parse_wxd(val, 0.5, HOL_PROPS_AREA_MAX, w, d))
        return 0;
    cli_error(cmd, 0, "--play-area needs WxD in metres, 0.5 to 20 each, not '%.40s'", val);
    return CLI_EXIT_USAGE;
}

const char *const cli_props_valued[] = {PLAY_GEOMETRY_OPTIONS, "--level", "--play-area",
                                           "--scale", "--out", NULL};

static int props_parse(const char *cmd, int argc, char **argv, props_args *a)
{
    static const char *const *const valued = cli_props_valued;
    static const char *const flags[] = {NULL};
    cli_opts p;
    cli_opts_init(&p, cmd, argc, argv, valued, flags);
    const char *o, *val;
    int r;
    while ((r = cli_opts_next(&p, &o, &val)) > 0) {
        int st = 0;
        if (!o) {
            cli_error(cmd, 0, "unexpected argument '%.40s'; see 'holonomy props --help'", val);
            return CLI_EXIT_USAGE;
        } else if (!strcmp(o, "--out")) {
            a->out = val;
        } else if (!strcmp(o, "--level")) {
            a->level = val;
        } else if (!strcmp(o, "--scale")) {
            st = props_parse_scale(cmd, val, &a->scale);
        } else if (!strcmp(o, "--play-area")) {
            st = props_parse_area(cmd, val, &a->area_w, &a->area_d);
        } else if (play_geometry_value(cmd, o, val, &a->geo) < 0) {
            st = CLI_EXIT_USAGE;
        }
        if (st)
            return st;
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (!a->out) {
        cli_error(cmd, 0, "--out FILE.svg is required; see 'holonomy props --help'");
        return CLI_EXIT_USAGE;
    }
    if (a->area_w > 0 && (a->geo.cols || a->geo.cell_m > 0)) {
        cli_error(cmd, 0, "--play-area fits the room and the cell: give it without --room and "
                          "--cell");
        return CLI_EXIT_USAGE;
    }
    return 0;
}

/* 2 (reported) when out names the level file itself (also through a
 * link): the check every command makes (cli_check_distinct). */
static int props_out_is_input(const char *cmd, const props_args *a)
{
    const cli_path in = {"--level", a->level}, out = {"--out", a->out};
    return cli_check_distinct(cmd, &in, 1, &out, 1);
}

/* The plan's geometry: the level, the options, the fitted play area. */
static int props_geometry(const char *cmd, const props_args *a, hol_props_desc *d, int *q,
                          char *name, size_t cap)
{
    static hol_level L;
    int cols = a->geo.cols, rows = a->geo.rows;
    double cell = a->geo.cell_m;
    *q = a->geo.q;
    name[0] = '\0';
    if (a->level) {
        int st = play_read_level(cmd, a->level, &L);
        if (!st)
            st = play_geometry_apply(cmd, &a->geo, &L, 1);
        if (st)
            return st;
        cols = L.lvl.room_cols;
        rows = L.lvl.room_rows;
        cell = L.lvl.cell_m;
        *q = L.lvl.tiling_q;
        snprintf(name, cap, "%s", L.name);
    }
    if (a->area_w > 0 && !cols && !(cell > 0)) {
        hol_fit f;
        if (hol_fit_rect(a->area_w, a->area_d, -1, &f)) {
            cli_error(cmd, 0, "--play-area cannot be fitted");
            return CLI_EXIT_USAGE;
        }
        cols = f.cols;
        rows = f.rows;
        cell = f.cell_m;
    }
    d->cols = cols ? cols : 3;
    d->rows = rows ? rows : 3;
    d->cell_m = cell > 0 ? cell : 1.0;
    d->scale = a->scale;
    d->area_w = a->area_w;
    d->area_d = a->area_d;
    if (!*q)
        *q = 5;
    return 0;
}

int props_write_svg(FILE *f, const hol_props *p, int q, const char *level_name,
                    const hol_props_desc *d);

int cli_cmd_props(int argc, char **argv)
{
    const char *cmd = "props";
    props_args a;
    memset(&a, 0, sizeof a);
    int st = props_parse(cmd, argc, argv, &a);
    if (!st)
        st = cli_check_output(cmd, "--out", a.out);
    if (!st)
        st = props_out_is_input(cmd, &a);
    hol_props_desc d;
    int q = 5;
    char name[HOL_LEVEL_NAME_MAX];
    if (!st)
        st = props_geometry(cmd, &a, &d, &q, name, sizeof name);
    if (st)
        return st;
    static hol_props plan;
    hol_err e = hol_props_plan(&d, &plan);
    if (e == HOL_ERANGE) {
        cli_error(cmd, 0, "at 1:%d the %g x %g m plan fits no A4 or A3 page; give a smaller "
                          "scale (--scale 1:N with a larger N)",
                  d.scale, fmax(d.cols * d.cell_m, d.area_w), fmax(d.rows * d.cell_m, d.area_d));
        return CLI_EXIT_USAGE;
    } else if (e) {
        cli_error(cmd, 0, "cannot plan the room: %s", hol_err_str(e));
        return CLI_EXIT_USAGE;
    }
    hol_file_atomic w;
    char esc[256];
    if (hol_file_atomic_open(&w, a.out)) {
        cli_error(cmd, 0, "cannot write '%s': %s", cli_escape(a.out, esc, sizeof esc),
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    if (props_write_svg(w.f, &plan, q, name, &d) || hol_file_atomic_commit(&w)) {
        hol_file_atomic_abort(&w);
        cli_error(cmd, 0, "cannot write '%s': %s", cli_escape(a.out, esc, sizeof esc),
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}
