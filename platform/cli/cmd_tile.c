/* cmd_tile.c - `holonomy tile walk`, `tile dist` (SPEC 4), `tile bearing`
 * (SPEC 8) and `tile count` (SPEC 9). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../../core/hol_bearing.h"
#include "../../core/hol_room.h"
#include "../../core/hol_tile.h"
#include "cli.h"

const char *const cli_tile_usage =
    "usage: holonomy tile walk|dist|bearing [--tiling 4,Q]\n"
    "       holonomy tile count --radius N [--tiling 4,Q]\n"
    "\n"
    "  tile walk   read lines of room steps (N, E, S, W; '-' or an empty line\n"
    "              for none), each a free walk from the start, and print per\n"
    "              line the tile reached: ADDRESS DISTANCE\n"
    "  tile dist   read lines 'A B' of two tile addresses and print per line\n"
    "              the fewest steps between the two tiles\n"
    "  tile bearing  read lines 'WALK TARGET' (WALK a free walk from the\n"
    "              start, '-' for none; TARGET an address) and print per line\n"
    "              'TRUE FLAT': bearings in degrees clockwise from room north\n"
    "              with one decimal (SPEC 8). TRUE: at the walk's end, the\n"
    "              initial direction of the geodesic to TARGET's centre ('-'\n"
    "              when the walk ends on TARGET); FLAT: the direction, in a\n"
    "              flat grid, to where the walk first stood on TARGET ('-'\n"
    "              when it never did or that vector is zero)\n"
    "  tile count  print N + 1 lines 'D COUNT', D = 0..N: the number of tiles\n"
    "              at exactly D steps from O (SPEC 9); reads no input\n"
    "\n"
    "  --radius N     tile count's radius, a whole number from 0 to 12\n"
    "  --tiling 4,Q   the square tiling {4,Q}, Q squares round every vertex,\n"
    "                 Q from 4 (the flat grid) to 8; default 4,5\n"
    "\n"
    "Addresses: O, or a branch N/E/S/W followed by f/l/r (SPEC sections 3\n"
    "and 7): each tile's leftmost shortest walk from O. Tiles reach distance\n"
    "60 from O in {4,5} and 59 in the other tilings; a walk that goes farther\n"
    "is bad input.\n"
    "Exit status: 0 ok, 1 output error, 2 bad input (one line on stderr).\n";

/* One line of `tile walk`: a free walk from the start. */
static int walk_line(void *ctx, long lineno, char *s, size_t len)
{
    const char *cmd = "tile walk";
    int q = *(const int *)ctx;
    cli_trim(&s, &len);
    if (len == 1 && s[0] == '-')
        len = 0;
    hol_tile t = hol_tile_origin_q(q);
    int orient = 0;
    for (size_t i = 0; i < len; i++) {
        int d = hol_dir_from_char((unsigned char)s[i]), arr;
        if (d < 0) {
            cli_error(cmd, lineno, "character %zu is not a step (N, E, S or W)",
                      i + 1);
            return CLI_EXIT_USAGE;
        }
        if (hol_tile_step(t, orient + d, &t, &arr)) {
            cli_error(cmd, lineno,
                      "step %zu goes beyond distance %d from O, the reach of "
                      "tile words",
                      i + 1, hol_tile_reach(q));
            return CLI_EXIT_USAGE;
        }
        orient = (arr - d) & 3;
    }
    char buf[HOL_TILE_ADDR_MAX];
    hol_tile_print(t, buf);
    printf("%s %d\n", buf, hol_tile_dist0(t));
    return CLI_EXIT_OK;
}

/* Parse one address field; on failure report it and return nonzero. */
static int parse_addr(const char *cmd, long lineno, int q, const char *s, size_t len,
                      hol_tile *out)
{
    hol_err err = hol_tile_parse_q(q, s, (ptrdiff_t)len, out);
    if (!err)
        return 0;
    char shown[48];
    size_t n = len < 40 ? len : 40;
    memcpy(shown, s, n);
    strcpy(shown + n, len > 40 ? "..." : ""); /* cli_error escapes it */
    if (err == HOL_ENOTCANON) {
        hol_tile t;
        char canon[HOL_TILE_ADDR_MAX];
        if (!hol_tile_resolve_q(q, s, (ptrdiff_t)len, &t)) {
            hol_tile_print(t, canon);
            cli_error(cmd, lineno,
                      "'%s' is not a canonical address (that walk reaches %s)",
                      shown, canon);
        } else {
            cli_error(cmd, lineno, "'%s' is not a canonical address", shown);
        }
    } else if (err == HOL_ERANGE) {
        cli_error(cmd, lineno, "'%s' is longer than %d letters, the reach of "
                  "tile words", shown, hol_tile_reach(q));
    } else {
        cli_error(cmd, lineno,
                  "'%s' is not an address (O, or N/E/S/W then f/l/r)", shown);
    }
    return 1;
}

/* One line of `tile dist`: two addresses. */
static int dist_line(void *ctx, long lineno, char *s, size_t len)
{
    const char *cmd = "tile dist";
    char *f[2];
    size_t fl[2];
    hol_tile a, b;
    int q = *(const int *)ctx;
    if (memchr(s, '\0', len)) {
        cli_error(cmd, lineno, "line holds a NUL byte");
        return CLI_EXIT_USAGE;
    }
    if (cli_split(s, len, f, fl, 2) != 2) {
        cli_error(cmd, lineno, "expected two addresses 'A B'");
        return CLI_EXIT_USAGE;
    }
    if (parse_addr(cmd, lineno, q, f[0], fl[0], &a) ||
        parse_addr(cmd, lineno, q, f[1], fl[1], &b))
        return CLI_EXIT_USAGE;
    printf("%d\n", hol_tile_dist(a, b));
    return CLI_EXIT_OK;
}

/* One line of `tile bearing`: WALK TARGET. */
static int bearing_line(void *ctx, long lineno, char *s, size_t len)
{
    const char *cmd = "tile bearing";
    char *f[2];
    size_t fl[2];
    hol_tile target;
    int q = *(const int *)ctx;
    if (memchr(s, '\0', len)) {
        cli_error(cmd, lineno, "line holds a NUL byte");
        return CLI_EXIT_USAGE;
    }
    if (cli_split(s, len, f, fl, 2) != 2) {
        cli_error(cmd, lineno, "expected 'WALK TARGET' (WALK '-' for none)");
        return CLI_EXIT_USAGE;
    }
    if (fl[0] == 1 && f[0][0] == '-')
        fl[0] = 0;
    for (size_t i = 0; i < fl[0]; i++)
        if (hol_dir_from_char((unsigned char)f[0][i]) < 0) {
            cli_error(cmd, lineno, "character %zu of the walk is not a step (N, E, S "
                      "or W)", i + 1);
            return CLI_EXIT_USAGE;
        }
    if (parse_addr(cmd, lineno, q, f[1], fl[1], &target))
        return CLI_EXIT_USAGE;
    hol_bearing_walk w;
    hol_bearing b;
    hol_bearing_begin(&w, target);
    for (size_t i = 0; i < fl[0]; i++)
        if (hol_bearing_step(&w, hol_dir_from_char((unsigned char)f[0][i]))) {
            cli_error(cmd, lineno,
                      "step %zu goes beyond distance %d from O, the reach of "
                      "tile words",
                      i + 1, hol_tile_reach(q));
            return CLI_EXIT_USAGE;
        }
    if (hol_bearing_end(&w, &b)) {
        cli_error(cmd, lineno, "no bearing from the walk's end to that tile");
        return CLI_EXIT_USAGE;
    }
    char t[HOL_BEARING_TEXT] = "-", fb[HOL_BEARING_TEXT] = "-";
    if (b.has_true)
        hol_bearing_format(b.true_deg, t);
    if (b.has_flat)
        hol_bearing_format(b.flat_deg, fb);
    printf("%s %s\n", t, fb);
    return CLI_EXIT_OK;
}

/* `tile count`: D COUNT for D = 0..radius (radius -1: --radius missing). */
static int tile_count(int q, int radius)
{
    if (radius < 0) {
        cli_error("tile count", 0, "--radius N is required (N from 0 to 12)");
        return CLI_EXIT_USAGE;
    }
    for (int d = 0; d <= radius; d++)
        printf("%d %llu\n", d, (unsigned long long)hol_tile_count_at(q, d));
    return cli_finish_output("tile count");
}

/* --radius N: a decimal whole number 0..12 (SPEC 9; cli_parse_decimal, the
 * options' one grammar). 0 ok, -1 reported. */
static int radius_value(const char *v, int *out_radius)
{
    uint64_t n;
    if (!cli_parse_decimal(v, &n) || n > 12) {
        cli_error("tile", 0, "--radius '%.40s' is not a whole number from 0 to 12", v);
        return -1;
    }
    *out_radius = (int)n;
    return 0;
}

const char *const cli_tile_valued[] = {"--tiling", "--radius", NULL};

int cli_cmd_tile(int argc, char **argv)
{
    int q = HOL_TILING_DEFAULT_Q, npos = 0, r, radius = -1;
    const char *pos[2] = {NULL, NULL}, *a, *val;
    cli_opts p;
    cli_opts_init(&p, "tile", argc, argv, cli_tile_valued, NULL);
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (a && !strcmp(a, "--radius")) {
            if (radius_value(val, &radius) < 0)
                return CLI_EXIT_USAGE;
            continue;
        }
        if (a && cli_geometry_value("tile", a, val, &q, NULL, NULL) < 0)
            return CLI_EXIT_USAGE;
        if (!a && npos == 2) {
            cli_error("tile", 0, "'%s' takes no arguments; see --help", pos[0]);
            return CLI_EXIT_USAGE;
        }
        if (!a)
            pos[npos++] = val;
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    int is_count = npos >= 1 && !strcmp(pos[0], "count");
    if (is_count && npos > 1) {
        cli_error("tile", 0, "'count' takes no arguments; see --help");
        return CLI_EXIT_USAGE;
    }
    if (radius >= 0 && !is_count) {
        cli_error("tile", 0, "--radius is an option of 'tile count' only");
        return CLI_EXIT_USAGE;
    }
    if (is_count)
        return tile_count(q, radius);
    if (npos == 1 && !strcmp(pos[0], "walk"))
        return cli_for_each_line("tile walk", walk_line, &q);
    if (npos == 1 && !strcmp(pos[0], "dist"))
        return cli_for_each_line("tile dist", dist_line, &q);
    if (npos == 1 && !strcmp(pos[0], "bearing"))
        return cli_for_each_line("tile bearing", bearing_line, &q);
    if (npos == 0)
        cli_error("tile", 0, "missing subcommand (walk, dist, bearing or count); see --help");
    else if (strcmp(pos[0], "walk") && strcmp(pos[0], "dist") && strcmp(pos[0], "bearing"))
        cli_error("tile", 0, "unknown subcommand '%.40s'; see --help", pos[0]);
    else
        cli_error("tile", 0, "'%s' takes no arguments; see --help", pos[0]);
    return CLI_EXIT_USAGE;
}
