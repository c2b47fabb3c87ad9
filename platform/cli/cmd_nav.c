/* cmd_nav.c - `holonomy nav`: fewest room steps to a target tile (SPEC 4). */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_nav.h"
#include "../../core/hol_nav_line.h"
#include "cli.h"

const char *const cli_nav_usage =
    "usage: holonomy nav [--tiling 4,Q] [--room CxR] [--budget N] [--stats]\n"
    "\n"
    "Reads lines 'PREFIX TARGET': PREFIX a walk of room steps (N, E, S, W)\n"
    "from the start, cell (1,1) of tile O, that stays inside the 3 x 3 room\n"
    "('-' for none); TARGET a tile address (O, or N/E/S/W then f/l/r).\n"
    "With --room CxR the room has C columns and R rows (3 to 5 each) and the\n"
    "start is cell (C/2, R/2); with --tiling 4,Q the tiling is {4,Q} (Q from\n"
    "4, the flat grid, to 8; default 4,5), addresses and all.\n"
    "Prints per line 'K WALK': K the fewest further steps, staying inside the\n"
    "room, after which the user stands on TARGET, and WALK such a walk ('-'\n"
    "when K is 0).\n"
    "\n"
    "Targets within 12 tiles of the user's tile (after PREFIX) are answered\n"
    "exactly from a cost table (no search; in other tilings and rooms from 6\n"
    "to 12 tiles, as the README lists for each). Farther\n"
    "targets are answered by an anytime search: K is then the length of the\n"
    "best walk found, an upper bound on the fewest (equal to it in every case\n"
    "the benchmark can check). A target that no walk inside the room reaches\n"
    "(in {4,4} every tile off the room's own C x R; in {4,8} some tiles from\n"
    "some room states) is bad input, named on stderr.\n"
    "\n"
    "  --budget N   node budget of the anytime search for targets beyond 12\n"
    "               tiles (default and maximum 262144, the arena; about 4000\n"
    "               nodes take 1 to 2 ms; see make bench)\n"
    "  --stats      also print per line 'LINE exact|anytime NODES' on stderr\n"
    "  --tiling 4,Q the tiling {4,Q}, Q from 4 to 8 (default 4,5)\n"
    "  --room CxR   a room of C x R cells, 3 to 5 each (default 3x3)\n"
    "  -h, --help   this text\n"
    "\n"
    "Exit status: 0 ok, 1 output or memory failure, 2 bad input or usage\n"
    "(one line on stderr naming the input line; nothing printed for it).\n";

typedef struct nav_ctx {
    hol_nav *nav;
    hol_room start;
    size_t budget;
    int stats;
} nav_ctx;

static int nav_line(void *vctx, long lineno, char *s, size_t len)
{
    nav_ctx *ctx = (nav_ctx *)vctx;
    static uint8_t walk[HOL_NAV_WALK_MAX];
    static char text[HOL_NAV_WALK_MAX + 1];
    hol_room room;
    hol_tile target;
    char msg[256];
    if (hol_nav_parse_line_in(&ctx->start, s, len, &room, &target, msg, sizeof msg)) {
        cli_error("nav", lineno, "%s", msg);
        return CLI_EXIT_USAGE;
    }
    hol_nav_result res;
    hol_err err = hol_nav_find(ctx->nav, &room, target, ctx->budget, walk, sizeof walk, &res);
    if (err == HOL_EUNREACH) {
        char addr[HOL_TILE_ADDR_MAX];
        hol_tile_print(target, addr);
        cli_error("nav", lineno, "no walk inside the room reaches %s", addr);
        return CLI_EXIT_USAGE;
    }
    if (err) {
        cli_error("nav", lineno, "no walk: %s", hol_err_str(err));
        return err == HOL_ENOMEM ? CLI_EXIT_FAIL : CLI_EXIT_USAGE;
    }
    for (int i = 0; i < res.len; i++)
        text[i] = hol_dir_to_char(walk[i]);
    text[res.len] = '\0';
    printf("%d %s\n", res.len, res.len ? text : "-");
    if (ctx->stats)
        fprintf(stderr, "%ld %s %zu\n", lineno, res.exact ? "exact" : "anytime", res.nodes);
    return CLI_EXIT_OK;
}

const char *const cli_nav_valued[] = {"--budget", "--tiling", "--room", NULL};

int cli_cmd_nav(int argc, char **argv)
{
    const char *cmd = "nav";
    static const char *const flags[] = {"--stats", NULL};
    size_t budget = 0;
    int stats = 0, q = 0, cols = 0, rows = 0, r;
    cli_opts p;
    const char *a, *val;
    cli_opts_init(&p, cmd, argc, argv, cli_nav_valued, flags);
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a) {
            cli_error(cmd, 0, "unknown argument '%.40s'; see --help", val);
            return CLI_EXIT_USAGE;
        }
        if (!strcmp(a, "--stats"))
            stats = 1;
        else if (!strcmp(a, "--budget") ? cli_budget_value(cmd, val, &budget)
                                         : cli_geometry_value(cmd, a, val, &q, &cols, &rows) < 0)
            return CLI_EXIT_USAGE;
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    nav_ctx ctx = {NULL, hol_room_start(), budget, stats};
    hol_nav_desc desc = {0};
    desc.tiling_q = q;
    desc.lazy = 1;
    desc.room_cols = cols;
    desc.room_rows = rows;
    hol_room_start_in(q, cols, rows, &ctx.start);
    hol_err err = hol_nav_create(&desc, &ctx.nav);
    if (err) {
        cli_error(cmd, 0, "cannot build the cost table: %s", hol_err_str(err));
        return CLI_EXIT_FAIL;
    }
    int status = cli_for_each_line(cmd, nav_line, &ctx);
    hol_nav_destroy(ctx.nav);
    return status;
}
