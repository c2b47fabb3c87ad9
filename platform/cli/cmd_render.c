/* cmd_render.c - `holonomy render` (placeholder until its issue lands). */
#include "cli.h"

int cli_cmd_render(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("render", 0, "not implemented yet");
    return CLI_EXIT_FAIL;
}
