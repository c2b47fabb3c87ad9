/* play_prov.c - a log folder's provenance files, through the shell
 * (play_prov.h). */
#include "play_prov.h"

#include <stdio.h>
#include <string.h>

#include "../shell/hol_shell_prov.h"
#include "cli.h"

static char held_rows[64 * 1024], held_order[64 * 1024 + 64 * 66];
static const hol_level *held_levels;
static char held_fail[300]; /* play_prov_write's failure, said at the end */
static int held_n;

void play_prov_hold_order(const char *rows, const hol_level *levels, int n)
{
    snprintf(held_rows, sizeof held_rows, "%s", rows ? rows : "");
    held_order[0] = 0;
    held_levels = levels;
    held_n = n;
}

void play_prov_order_hash(const hol_level *levels, int n)
{
    if (!levels || levels != held_levels || n != held_n)
        return;
    hol_shell_order_hash(held_rows, levels, n, held_order, sizeof held_order);
    held_levels = NULL;
}

int play_prov_write(const hol_sink *log, const hol_rec_meta *meta)
{
    if (!log)
        return 0;
    const char *what = hol_shell_prov_write(log, meta, held_order);
    held_order[0] = 0;
    held_fail[0] = 0;
    if (what) {
        const char *why = log->why ? log->why(log->user) : NULL;
        snprintf(held_fail, sizeof held_fail, "cannot write the log folder's %s%s%s", what,
                 why && why[0] ? ": " : "", why ? why : "");
    }
    return what != NULL;
}

int play_prov_failed(const char *cmd)
{
    if (!held_fail[0])
        return 0;
    cli_error_end(cmd, "%s", held_fail);
    held_fail[0] = 0;
    return 1;
}
