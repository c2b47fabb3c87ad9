/* cmd_nav.c - `holonomy nav` (placeholder until its issue lands). */
#include "cli.h"

int cli_cmd_nav(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("nav", 0, "not implemented yet");
    return CLI_EXIT_FAIL;
}
