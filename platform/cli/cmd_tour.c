/* cmd_tour.c - `holonomy tour PREFIX KEY... CHEST`: keys, then the chest. */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_nav.h"
#include "../../core/hol_nav_line.h"
#include "cli.h"

const char *const cli_tour_usage =
    "usage: holonomy tour [--tiling 4,Q] [--room CxR] [--budget N] [--stats]\n"
    "                     PREFIX KEY... CHEST\n"
    "\n"
    "PREFIX: a walk of room steps (N, E, S, W) from the start, cell (1,1) of\n"
    "tile O, inside the room ('-' for none). KEY... (0 to 5) and CHEST: tile\n"
    "addresses. Prints one line 'K WALK': K the fewest further steps, staying\n"
    "in the room, that stand on every key (any order; a key counts when the\n"
    "user stands on its tile, the start included) and after the last key on\n"
    "the chest, and WALK such a walk ('-' when K is 0).\n"
    "\n"
    "A dynamic program over key orders x room states on the keys answers\n"
    "first: exact when the keys lie within 7 tiles of each other and of the\n"
    "start and the chest within 12 of every key. Otherwise its tour (legs\n"
    "through midway tiles) bounds an A* search over room state x collected\n"
    "keys, exact if it proves the bound or finishes within the node budget,\n"
    "else K is the length of the best tour found (--stats tells which).\n"
    "\n"
    "  --budget N   node budget (default and maximum 262144)\n"
    "  --tiling 4,Q the tiling {4,Q}, Q from 4 to 8 (default 4,5)\n"
    "  --room CxR   a room of C x R cells, 3 to 5 each (default 3x3; the\n"
    "               start is cell (C/2, R/2)). A key or chest that no walk\n"
    "               inside the room reaches is bad input ({4,4}, {4,8})\n"
    "  --stats      also print 'exact|best NODES' on stderr (0 nodes: the\n"
    "               dynamic program answered)\n"
    "  -h, --help   this text\n"
    "\n"
    "Exit status: 0 ok, 1 output or memory failure, 2 bad arguments.\n";

const char *const cli_tour_valued[] = {"--budget", "--tiling", "--room", NULL};

int cli_cmd_tour(int argc, char **argv)
{
    const char *cmd = "tour";
    static const char *const flags[] = {"--stats", NULL};
    size_t budget = 0;
    int stats = 0, q = 0, cols = 0, rows = 0, r;
    const char *pos[HOL_NAV_TOUR_MAX_KEYS + 2];
    int npos = 0;
    cli_opts po;
    const char *a, *val;
    cli_opts_init(&po, cmd, argc, argv, cli_tour_valued, flags);
    while ((r = cli_opts_next(&po, &a, &val)) > 0) {
        if (a && !strcmp(a, "--stats")) {
            stats = 1;
        } else if (a && (!strcmp(a, "--budget") ? cli_budget_value(cmd, val, &budget)
                                                : cli_geometry_value(cmd, a, val, &q, &cols, &rows) < 0)) {
            return CLI_EXIT_USAGE;
        } else if (!a && npos == HOL_NAV_TOUR_MAX_KEYS + 2) {
            cli_error(cmd, 0, "at most %d keys", HOL_NAV_TOUR_MAX_KEYS);
            return CLI_EXIT_USAGE;
        } else if (!a) {
            pos[npos++] = val;
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (npos < 2) {
        cli_error(cmd, 0, "expected PREFIX KEY... CHEST; see --help");
        return CLI_EXIT_USAGE;
    }
    char msg[256];
    hol_room room;
    hol_tile tiles[HOL_NAV_TOUR_MAX_KEYS + 1];
    hol_room start;
    hol_room_start_in(q, cols, rows, &start);
    if (hol_nav_parse_prefix_in(&start, pos[0], strlen(pos[0]), &room, msg, sizeof msg)) {
        cli_error(cmd, 0, "%s", msg);
        return CLI_EXIT_USAGE;
    }
    for (int i = 1; i < npos; i++) {
        if (hol_nav_parse_target_q(hol_tile_q(start.tile), pos[i], strlen(pos[i]), &tiles[i - 1],
                                   msg, sizeof msg)) {
            /* the message says "target"; name the argument instead */
            const char *what = i == npos - 1 ? "chest" : "key";
            char *p = strstr(msg, "target");
            cli_error(cmd, 0, "%s %s", what, p ? p + 7 : msg);
            return CLI_EXIT_USAGE;
        }
    }
    hol_nav *nav;
    hol_nav_desc desc = {0};
    desc.tiling_q = q;
    desc.lazy = 1;
    desc.room_cols = cols;
    desc.room_rows = rows;
    hol_err err = hol_nav_create(&desc, &nav);
    if (err) {
        cli_error(cmd, 0, "cannot build the cost table: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    static uint8_t walk[HOL_NAV_WALK_MAX];
    static char text[HOL_NAV_WALK_MAX + 1];
    hol_nav_result res;
    err = hol_nav_tour(nav, &room, tiles, npos - 2, tiles[npos - 2], budget, walk,
                       sizeof walk, &res);
    hol_nav_destroy(nav);
    if (err == HOL_EUNREACH) {
        cli_error(cmd, 0, "no walk inside the room reaches every key and the chest");
        return CLI_EXIT_USAGE;
    }
    if (err) {
        cli_error(cmd, 0, "no tour: %s", hol_err_str(err));
        return err == HOL_ENOMEM ? CLI_EXIT_FAIL : CLI_EXIT_USAGE;
    }
    for (int i = 0; i < res.len; i++)
        text[i] = hol_dir_to_char(walk[i]);
    text[res.len] = '\0';
    printf("%d %s\n", res.len, res.len ? text : "-");
    if (stats)
        fprintf(stderr, "%s %zu\n", res.exact ? "exact" : "best", res.nodes);
    return cli_finish_output(cmd);
}
