/* cmd_tile.c - `holonomy tile walk` and `holonomy tile dist` (SPEC 4). */
#include <stdint.h>
#include <string.h>

#include "../../core/hol_room.h"
#include "../../core/hol_tile.h"
#include "cli.h"

static const char *const tile_usage =
    "usage: holonomy tile walk|dist\n"
    "\n"
    "  tile walk   read lines of room steps (N, E, S, W; '-' or an empty line\n"
    "              for none), each a free walk from the start, and print per\n"
    "              line the tile reached: ADDRESS DISTANCE\n"
    "  tile dist   read lines 'A B' of two tile addresses and print per line\n"
    "              the fewest steps between the two tiles\n"
    "\n"
    "Addresses: O, or a branch N/E/S/W followed by f/l/r (SPEC section 3).\n"
    "Tiles reach distance 60 from O; a walk that goes farther is bad input.\n"
    "Exit status: 0 ok, 1 output error, 2 bad input (one line on stderr).\n";

/* One line of `tile walk`: a free walk from the start. */
static int walk_line(void *ctx, long lineno, char *s, size_t len)
{
    const char *cmd = "tile walk";
    (void)ctx;
    cli_trim(&s, &len);
    if (len == 1 && s[0] == '-')
        len = 0;
    hol_tile t = hol_tile_origin();
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
                      i + 1, HOL_TILE_MAX_DIST);
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
static int parse_addr(const char *cmd, long lineno, const char *s, size_t len,
                      hol_tile *out)
{
    hol_err err = hol_tile_parse(s, (ptrdiff_t)len, out);
    if (!err)
        return 0;
    char shown[48];
    size_t n = len < 40 ? len : 40;
    memcpy(shown, s, n);
    strcpy(shown + n, len > 40 ? "..." : ""); /* cli_error escapes it */
    if (err == HOL_ENOTCANON) {
        hol_tile t;
        char canon[HOL_TILE_ADDR_MAX];
        if (!hol_tile_resolve(s, (ptrdiff_t)len, &t)) {
            hol_tile_print(t, canon);
            cli_error(cmd, lineno,
                      "'%s' is not a canonical address (that walk reaches %s)",
                      shown, canon);
        } else {
            cli_error(cmd, lineno, "'%s' is not a canonical address", shown);
        }
    } else if (err == HOL_ERANGE) {
        cli_error(cmd, lineno, "'%s' is longer than %d letters, the reach of "
                  "tile words", shown, HOL_TILE_MAX_DIST);
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
    (void)ctx;
    if (memchr(s, '\0', len)) {
        cli_error(cmd, lineno, "line holds a NUL byte");
        return CLI_EXIT_USAGE;
    }
    if (cli_split(s, len, f, fl, 2) != 2) {
        cli_error(cmd, lineno, "expected two addresses 'A B'");
        return CLI_EXIT_USAGE;
    }
    if (parse_addr(cmd, lineno, f[0], fl[0], &a) ||
        parse_addr(cmd, lineno, f[1], fl[1], &b))
        return CLI_EXIT_USAGE;
    printf("%d\n", hol_tile_dist(a, b));
    return CLI_EXIT_OK;
}

int cli_cmd_tile(int argc, char **argv)
{
    if (cli_wants_help(argc, argv)) {
        fputs(tile_usage, stdout);
        return cli_finish_output("tile");
    }
    if (argc == 2 && !strcmp(argv[1], "walk"))
        return cli_for_each_line("tile walk", walk_line, NULL);
    if (argc == 2 && !strcmp(argv[1], "dist"))
        return cli_for_each_line("tile dist", dist_line, NULL);
    if (argc < 2)
        cli_error("tile", 0, "missing subcommand (walk or dist); see --help");
    else if (strcmp(argv[1], "walk") && strcmp(argv[1], "dist"))
        cli_error("tile", 0, "unknown subcommand '%.40s'; see --help", argv[1]);
    else
        cli_error("tile", 0, "'%s' takes no arguments; see --help", argv[1]);
    return CLI_EXIT_USAGE;
}
