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

static void trim(char **s, size_t *len)
{
    while (*len > 0 && (**s == ' ' || **s == '\t')) {
        (*s)++;
        (*len)--;
    }
    while (*len > 0 && ((*s)[*len - 1] == ' ' || (*s)[*len - 1] == '\t'))
        (*len)--;
}

static int tile_walk(void)
{
    const char *cmd = "tile walk";
    cli_lines in;
    char *s;
    size_t len;
    int r, status = CLI_EXIT_OK;
    cli_lines_init(&in, stdin);
    while (status == CLI_EXIT_OK && (r = cli_lines_next(&in, &s, &len)) > 0) {
        trim(&s, &len);
        if (len == 1 && s[0] == '-')
            len = 0;
        hol_tile t = hol_tile_origin();
        int orient = 0;
        for (size_t i = 0; i < len; i++) {
            int d = hol_dir_from_char((unsigned char)s[i]);
            if (d < 0) {
                cli_error(cmd, in.lineno,
                          "character %zu is not a step (N, E, S or W)", i + 1);
                status = CLI_EXIT_USAGE;
                break;
            }
            int arr;
            if (hol_tile_step(t, orient + d, &t, &arr)) {
                cli_error(cmd, in.lineno,
                          "step %zu goes beyond distance %d from O, the reach "
                          "of tile words",
                          i + 1, HOL_TILE_MAX_DIST);
                status = CLI_EXIT_USAGE;
                break;
            }
            orient = (arr - d) & 3;
        }
        if (status == CLI_EXIT_OK) {
            char buf[HOL_TILE_ADDR_MAX];
            hol_tile_print(t, buf);
            printf("%s %d\n", buf, hol_tile_dist0(t));
        }
    }
    if (status == CLI_EXIT_OK && r < 0) {
        cli_error(cmd, 0, "cannot read input");
        status = CLI_EXIT_FAIL;
    }
    cli_lines_fini(&in);
    int out = cli_finish_output(cmd);
    return status ? status : out;
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
    strcpy(shown + n, len > 40 ? "..." : "");
    for (size_t i = 0; i < n; i++)
        if ((unsigned char)shown[i] < 0x20 || (unsigned char)shown[i] > 0x7e)
            shown[i] = '?';
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

static int tile_dist(void)
{
    const char *cmd = "tile dist";
    cli_lines in;
    char *s;
    size_t len;
    int r, status = CLI_EXIT_OK;
    cli_lines_init(&in, stdin);
    while (status == CLI_EXIT_OK && (r = cli_lines_next(&in, &s, &len)) > 0) {
        char *f[2];
        size_t fl[2];
        hol_tile a, b;
        if (memchr(s, '\0', len)) {
            cli_error(cmd, in.lineno, "line holds a NUL byte");
            status = CLI_EXIT_USAGE;
        } else if (cli_split(s, len, f, fl, 2) != 2) {
            cli_error(cmd, in.lineno, "expected two addresses 'A B'");
            status = CLI_EXIT_USAGE;
        } else if (parse_addr(cmd, in.lineno, f[0], fl[0], &a) ||
                   parse_addr(cmd, in.lineno, f[1], fl[1], &b)) {
            status = CLI_EXIT_USAGE;
        } else {
            printf("%d\n", hol_tile_dist(a, b));
        }
    }
    if (status == CLI_EXIT_OK && r < 0) {
        cli_error(cmd, 0, "cannot read input");
        status = CLI_EXIT_FAIL;
    }
    cli_lines_fini(&in);
    int out = cli_finish_output(cmd);
    return status ? status : out;
}

int cli_cmd_tile(int argc, char **argv)
{
    if (cli_wants_help(argc, argv)) {
        fputs(tile_usage, stdout);
        return cli_finish_output("tile");
    }
    if (argc == 2 && !strcmp(argv[1], "walk"))
        return tile_walk();
    if (argc == 2 && !strcmp(argv[1], "dist"))
        return tile_dist();
    if (argc < 2)
        cli_error("tile", 0, "missing subcommand (walk or dist); see --help");
    else if (strcmp(argv[1], "walk") && strcmp(argv[1], "dist"))
        cli_error("tile", 0, "unknown subcommand '%.40s'; see --help", argv[1]);
    else
        cli_error("tile", 0, "'%s' takes no arguments; see --help", argv[1]);
    return CLI_EXIT_USAGE;
}
