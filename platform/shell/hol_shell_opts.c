/* hol_shell_opts.c - the options' clashes as one table (hol_shell_opts.h). */
#include "hol_shell_opts.h"

#include <stdio.h>

static const char *const opt_name[HOL_SHELL_OPT_COUNT] = {
    "a LEVEL file", "--mode",   "--study", "--no-gamepad", "--gamepad-replay",
    "--append",     "--log",    "--restart-participant",  "--resume",
    "--mute",       "--volume", "--check-frame",           "--check-dir"};

typedef enum { ONE_OF, GOES_WITH, TOGETHER } rule_kind;

typedef struct clash_rule {
    rule_kind kind;
    signed char a, b, c; /* c: -1 none */
} clash_rule;

/* The order is the order of the messages when several are broken. */
static const clash_rule rules[] = {
    {TOGETHER, HOL_SHELL_OPT_CHECK_FRAME, HOL_SHELL_OPT_CHECK_DIR, -1},
    {ONE_OF, HOL_SHELL_OPT_LEVEL, HOL_SHELL_OPT_MODE, HOL_SHELL_OPT_STUDY},
    {ONE_OF, HOL_SHELL_OPT_NO_GAMEPAD, HOL_SHELL_OPT_PAD_REPLAY, -1},
    {GOES_WITH, HOL_SHELL_OPT_APPEND, HOL_SHELL_OPT_LOG, -1},
    {GOES_WITH, HOL_SHELL_OPT_RESTART, HOL_SHELL_OPT_STUDY, -1},
    {ONE_OF, HOL_SHELL_OPT_RESUME, HOL_SHELL_OPT_RESTART, -1},
    {GOES_WITH, HOL_SHELL_OPT_RESTART, HOL_SHELL_OPT_APPEND, -1},
    {GOES_WITH, HOL_SHELL_OPT_RESUME, HOL_SHELL_OPT_STUDY, -1},
    {GOES_WITH, HOL_SHELL_OPT_RESUME, HOL_SHELL_OPT_LOG, -1},
    {ONE_OF, HOL_SHELL_OPT_MUTE, HOL_SHELL_OPT_VOLUME, -1},
};

/* "give one of A, B or C" or "give A or B, not both", over the command's
 * options of the set; 1 when more than one of them was given */
static int one_of(const unsigned char *g, const clash_rule *r, char *out, size_t cap)
{
    const char *name[3];
    int n = 0, on = 0;
    const signed char set[3] = {r->a, r->b, r->c};
    for (int i = 0; i < 3; i++)
        if (set[i] >= 0 && g[set[i]] != HOL_SHELL_NO) {
            name[n++] = opt_name[set[i]];
            on += g[set[i]] == HOL_SHELL_ON;
        }
    if (on < 2)
        return 0;
    if (n == 3)
        snprintf(out, cap, "give one of %s, %s or %s", name[0], name[1], name[2]);
    else
        snprintf(out, cap, "give %s or %s, not both", name[0], name[1]);
    return 1;
}

int hol_shell_clash(const unsigned char given[HOL_SHELL_OPT_COUNT], char *out, size_t cap)
{
    if (cap)
        out[0] = 0;
    for (size_t i = 0; i < sizeof rules / sizeof rules[0]; i++) {
        const clash_rule *r = &rules[i];
        int a = given[r->a] == HOL_SHELL_ON, b = given[r->b] == HOL_SHELL_ON;
        if (r->kind == ONE_OF && one_of(given, r, out, cap))
            return 1;
        if (r->kind == GOES_WITH && a && !b) {
            snprintf(out, cap, "%s goes with %s", opt_name[r->a], opt_name[r->b]);
            return 1;
        }
        if (r->kind == TOGETHER && a != b) {
            snprintf(out, cap, "%s and %s go together", opt_name[r->a], opt_name[r->b]);
            return 1;
        }
    }
    return 0;
}
