/* main.c - the `holonomy` tool: one binary, subcommands (SPEC section 4). */
#include <signal.h>
#include <string.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "../shell/hol_shell_build.h"
#include "cli.h"

typedef struct cli_command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
    const char *const *usage;   /* its --help (NULL: the command answers it) */
    const char *const *valued;  /* its options that take a value (cli_help) */
} cli_command;

#define CLI__CMD(name, summary) {#name, cli_cmd_##name, summary, &cli_##name##_usage, \
                                 cli_##name##_valued}
static const cli_command commands[] = {
    CLI__CMD(tile, "tile walk|dist: addresses and distances"),
    CLI__CMD(world, "the seeded forest around a walk; save, load"),
    CLI__CMD(nav, "fewest room steps to a target tile"),
    CLI__CMD(tour, "fewest room steps to collect keys, then the chest"),
    CLI__CMD(render, "render a view to PNG (headless OSMesa or EGL) or in a window"),
    CLI__CMD(game, "play a level headless from lines of room steps: done|open STEPS OPTIMUM"),
    CLI__CMD(play, "play in a desktop window (EGL/X11); logs, recording"),
    CLI__CMD(replay, "run a recording again: the same logs, PNG frames"),
    CLI__CMD(xr, "the headset app on this machine's OpenXR runtime (make XR=1)"),
    CLI__CMD(hid, "game controllers: descriptor field maps, list, watch"),
    CLI__CMD(props, "a printable plan of where real hedges and trees stand (SVG)"),
    CLI__CMD(lesson, "a lesson's A4 worksheet or answer key (SVG or HTML)"),
    {"report", cli_cmd_report, "research logs to a report: attempts CSV, pictures, a page",
     NULL, NULL},
};
#undef CLI__CMD

/* The command's --help, else the command. */
static int run(const cli_command *c, int argc, char **argv)
{
    int help = c->usage ? cli_help(c->name, argc, argv, c->valued, *c->usage) : -1;
    return help >= 0 ? help : c->run(argc, argv);
}

static void usage(FILE *f)
{
    fprintf(f, "usage: holonomy [--help] [--version] COMMAND [ARGS]\n\n"
               "Walk an infinite hyperbolic forest {4,5} inside a 3 x 3 m room\n"
               "(--tiling 4,Q for Q 4..8, --room CxR up to 5x5, --cell M metres).\n\n"
               "commands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n'holonomy COMMAND --help' describes each command.\n"
               "Exit status: 0 ok, 1 failure, 2 bad input or usage.\n");
}

int main(int argc, char **argv)
{
#ifdef __GLIBC__
    /* Mesa frees and takes again blocks of a few hundred KB every frame;
     * with glibc's defaults each free at the heap's top gave the pages back
     * (brk) and the next frame faulted them in again: 3/4 of a 64 x 48
     * frame's CPU under llvmpipe (docs/performance.md, Start-up). Kept up
     * to 32 MB; blocks of 4 MB and more are still mapped on their own. */
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 32 << 20);
#endif
    /* A file size limit (ulimit -f) reached: write(2) fails with EFBIG and
     * the command takes its usual failure path (one line, exit 1, its
     * temporary files removed) instead of dying by SIGXFSZ with its
     * temporaries left behind (docs/cli.md, Exit status). */
    signal(SIGXFSZ, SIG_IGN);
    if (argc < 2) {
        cli_error("", 0, "no command given; see 'holonomy --help'");
        return CLI_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") ||
        !strcmp(argv[1], "help")) {
        usage(stdout);
        return cli_finish_output("--help");
    }
    if (!strcmp(argv[1], "--version")) {
        printf("holonomy %s (commit %s, built %s)\n", hol_shell_build_version(),
               hol_shell_build_commit(), hol_shell_build_date());
        return cli_finish_output("--version");
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name))
            /* each command reads its options with cli_opts_next: one
             * grammar, repeated options refused there */
            return run(&commands[i], argc - 1, argv + 1);
    cli_error("", 0, "unknown command '%.40s'; see 'holonomy --help'", argv[1]);
    return CLI_EXIT_USAGE;
}
