/* cmd_tour.c - `holonomy tour` (placeholder until its issue lands). */
#include "cli.h"

int cli_cmd_tour(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("tour", 0, "not implemented yet");
    return CLI_EXIT_FAIL;
}
