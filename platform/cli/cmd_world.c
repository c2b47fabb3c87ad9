/* cmd_world.c - `holonomy world` (placeholder until its issue lands). */
#include "cli.h"

int cli_cmd_world(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("world", 0, "not implemented yet");
    return CLI_EXIT_FAIL;
}
