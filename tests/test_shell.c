/* test_shell.c - the platform shell's pure parts (platform/shell/):
 * environment.csv's row (hol_shell_env.h) and the options' clash table
 * (hol_shell_opts.h), each message as play and xr print it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../platform/shell/hol_shell_env.h"
#include "../platform/shell/hol_shell_opts.h"

static void test_env_row(void **state)
{
    (void)state;
    char row[512];
    size_t n = 0;
    const hol_shell_env_fields f = {"s1", "p, 1", 2, "", "desktop", "Linux x", "", "GL \"x\"",
                                    "", 59.951, 960, 720, "a=1;b=2", "play --log d"};
    assert_int_equal(hol_shell_env_row(&f, 0, row, sizeof row, &n), 0);
    assert_string_equal(row, "s1,\"p, 1\",2,,desktop,Linux x,,\"GL \"\"x\"\"\",,59.951,960,720,"
                             "a=1;b=2,play --log d");
    assert_int_equal(n, strlen(row));
    /* zeros and NULL are empty fields; a control byte is escaped */
    const hol_shell_env_fields z = {.session = "a\nb"};
    assert_int_equal(hol_shell_env_row(&z, 0, row, sizeof row, &n), 0);
    assert_string_equal(row, "a\\x0ab,,,,,,,,,,,,,");
    /* too long: a field over field_max, or the row over cap */
    assert_int_equal(hol_shell_env_row(&f, 4, row, sizeof row, &n), 1);
    assert_int_equal(hol_shell_env_row(&f, 0, row, 20, &n), 1);
    char cols[] = HOL_SHELL_ENV_COLUMNS;
    int commas = 0;
    for (char *c = cols; *c; c++)
        commas += *c == ',';
    assert_int_equal(commas, 13);
}

static const char *clash(const unsigned char *g)
{
    static char msg[200];
    return hol_shell_clash(g, msg, sizeof msg) ? msg : NULL;
}

/* play's options: no --check-frame/--check-dir */
static void play(unsigned char *g)
{
    memset(g, HOL_SHELL_OFF, HOL_SHELL_OPT_COUNT);
    g[HOL_SHELL_OPT_CHECK_FRAME] = g[HOL_SHELL_OPT_CHECK_DIR] = HOL_SHELL_NO;
}

/* xr's options: no --mode, --no-gamepad, --gamepad-replay */
static void xr(unsigned char *g)
{
    memset(g, HOL_SHELL_OFF, HOL_SHELL_OPT_COUNT);
    g[HOL_SHELL_OPT_MODE] = g[HOL_SHELL_OPT_NO_GAMEPAD] = g[HOL_SHELL_OPT_PAD_REPLAY] =
        HOL_SHELL_NO;
}

static void test_clash(void **state)
{
    (void)state;
    unsigned char g[HOL_SHELL_OPT_COUNT];
    play(g);
    assert_null(clash(g));
    g[HOL_SHELL_OPT_LEVEL] = g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "give one of a LEVEL file, --mode or --study");
    xr(g);
    g[HOL_SHELL_OPT_LEVEL] = g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "give a LEVEL file or --study, not both");
    play(g);
    g[HOL_SHELL_OPT_NO_GAMEPAD] = g[HOL_SHELL_OPT_PAD_REPLAY] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "give --no-gamepad or --gamepad-replay, not both");
    play(g);
    g[HOL_SHELL_OPT_APPEND] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "--append goes with --log");
    g[HOL_SHELL_OPT_LOG] = HOL_SHELL_ON;
    assert_null(clash(g));
    g[HOL_SHELL_OPT_RESTART] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "--restart-participant goes with --study");
    /* issue 39: and with --append (it starts a participant again in DIR) */
    g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_ON, g[HOL_SHELL_OPT_APPEND] = HOL_SHELL_OFF;
    assert_string_equal(clash(g), "--restart-participant goes with --append");
    g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_OFF, g[HOL_SHELL_OPT_APPEND] = HOL_SHELL_ON;
    g[HOL_SHELL_OPT_STUDY] = g[HOL_SHELL_OPT_RESUME] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "give --resume or --restart-participant, not both");
    g[HOL_SHELL_OPT_RESTART] = g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_OFF;
    assert_string_equal(clash(g), "--resume goes with --study");
    g[HOL_SHELL_OPT_STUDY] = HOL_SHELL_ON, g[HOL_SHELL_OPT_LOG] = HOL_SHELL_OFF;
    g[HOL_SHELL_OPT_APPEND] = HOL_SHELL_OFF;
    assert_string_equal(clash(g), "--resume goes with --log");
    play(g);
    g[HOL_SHELL_OPT_MUTE] = g[HOL_SHELL_OPT_VOLUME] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "give --mute or --volume, not both");
    xr(g);
    g[HOL_SHELL_OPT_CHECK_DIR] = HOL_SHELL_ON;
    assert_string_equal(clash(g), "--check-frame and --check-dir go together");
    g[HOL_SHELL_OPT_CHECK_FRAME] = HOL_SHELL_ON;
    assert_null(clash(g));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_env_row),
        cmocka_unit_test(test_clash),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
