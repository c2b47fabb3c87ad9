/* hol_shell_opts.h - which session options go together, one table for
 * every platform's command line (play, xr; docs/cli.md).
 *
 * Contract
 * - The caller fills given[HOL_SHELL_OPT_COUNT], one entry per option of
 *   the table's: HOL_SHELL_NO (0) when its command has no such option,
 *   HOL_SHELL_OFF when it has it and it was not given, HOL_SHELL_ON when
 *   given.
 * - hol_shell_clash checks the rules in one fixed order and writes the
 *   first one broken as a sentence into out (cap bytes, NUL-terminated):
 *   "give one of A, B or C" / "give A or B, not both" (at most one of the
 *   command's options in a set), "A goes with B" (A needs B), "A and B go
 *   together" (both or neither). The sets name only the command's options.
 *   Returns 1 when one was written, 0 when none is broken (out "").
 * - Pure: no I/O, no globals.
 */
#ifndef HOL_SHELL_OPTS_H
#define HOL_SHELL_OPTS_H

#include <stddef.h>

enum { HOL_SHELL_NO = 0, HOL_SHELL_OFF = 1, HOL_SHELL_ON = 2 };

typedef enum hol_shell_opt {
    HOL_SHELL_OPT_LEVEL,        /* a LEVEL file */
    HOL_SHELL_OPT_MODE,         /* --mode */
    HOL_SHELL_OPT_STUDY,        /* --study */
    HOL_SHELL_OPT_NO_GAMEPAD,   /* --no-gamepad */
    HOL_SHELL_OPT_PAD_REPLAY,   /* --gamepad-replay */
    HOL_SHELL_OPT_APPEND,       /* --append */
    HOL_SHELL_OPT_LOG,          /* --log */
    HOL_SHELL_OPT_RESTART,      /* --restart-participant */
    HOL_SHELL_OPT_RESUME,       /* --resume */
    HOL_SHELL_OPT_MUTE,         /* --mute */
    HOL_SHELL_OPT_VOLUME,       /* --volume */
    HOL_SHELL_OPT_CHECK_FRAME,  /* --check-frame */
    HOL_SHELL_OPT_CHECK_DIR,    /* --check-dir */
    HOL_SHELL_OPT_COUNT
} hol_shell_opt;

int hol_shell_clash(const unsigned char given[HOL_SHELL_OPT_COUNT], char *out, size_t cap);

#endif
