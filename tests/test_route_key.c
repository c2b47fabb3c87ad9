/* test_route_key.c - docs/hacking.md's route "Adding a level line kind",
 * walked: the page's example key `limit-minutes M` (the level's time limit
 * in whole minutes, 1..1440), its function as the page writes it and its
 * row in the key table, then levels that use it parsed (its value, its
 * refusals, a second line refused since the row is not HOL__REPEAT), a
 * line checked alone, and the standard keys unchanged.
 *
 * The row is added by building core/hol_level_parse.c into this test with
 * HOL_LEVEL_MORE_KEYS (the key table's hook for a build's own rows): this
 * file then defines every name of that file, so the core library's copy is
 * not linked, and hol_level_parse reads this table.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_level_impl.h"

/* The page's example function (hol_level_keys.c's place for it). */
hol_err hol__key_limit_minutes(hol__lp *p, char **f, int nf);

/* limit-minutes M: the time limit in whole minutes, 1..1440 */
hol_err hol__key_limit_minutes(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t m = hol__lv_count(f[1]);
    if (!m || m > 1440)
        return hol__lfail(p, HOL_ERANGE, p->line, "limit-minutes '%.20s' is not minutes in 1..1440",
                          f[1]);
    p->L.time_limit_s = 60.0 * (double)m;
    return HOL_OK;
}

/* The page's example row of hol__keys. */
#define HOL_LEVEL_MORE_KEYS {"limit-minutes", 2, 2, 0, hol__key_limit_minutes},
#include "../core/hol_level_parse.c"

static hol_err parse(const char *text, hol_app_level *L, hol_level_err *e)
{
    memset(L, 0, sizeof *L);
    return hol_level_parse(text, strlen(text), L, e);
}

static void test_the_new_key(void **state)
{
    (void)state;
    hol_app_level L;
    hol_level_err e;
    assert_int_equal(parse("mode explore\nlimit-minutes 3\n", &L, &e), HOL_OK);
    assert_true(L.time_limit_s == 180.0);
    assert_int_equal(parse("mode explore\nlimit-minutes 0\n", &L, &e), HOL_ERANGE);
    assert_int_equal(e.line, 2);
    assert_string_equal(e.msg, "limit-minutes '0' is not minutes in 1..1440");
    assert_int_equal(parse("mode explore\nlimit-minutes 2 3\n", &L, &e), HOL_EPARSE);
    assert_string_equal(e.msg, "unknown key or wrong value count: 'limit-minutes'");
    /* not HOL__REPEAT: a second line is refused, naming the first */
    assert_int_equal(parse("mode explore\nlimit-minutes 2\nlimit-minutes 3\n", &L, &e), HOL_EARG);
    char msg[256];
    hol_level_err_format(&e, 1, msg, sizeof msg);
    assert_string_equal(msg, "line 3: 'limit-minutes' is given twice; give each key once (line 2)");
    assert_int_equal(hol_level_line_check("limit-minutes 5", 15, &e), HOL_OK);
    assert_int_equal(hol_level_line_check("limit-minutes x", 15, &e), HOL_ERANGE);
}

static void test_the_table_unchanged(void **state)
{
    (void)state;
    hol_app_level L;
    hol_level_err e;
    /* a repeatable key, and a geometry key read in the first pass */
    assert_int_equal(parse("place rock Wrf\nmode flag\nflag N\nplace grass Wr\ntiling 4 5\n", &L,
                           &e),
                     HOL_OK);
    assert_int_equal(L.nplaces, 2);
    assert_int_equal(L.tiling_q, 5);
    assert_int_equal(parse("mode flag\nflag N\nmode flag\n", &L, &e), HOL_EARG);
    assert_int_equal(e.other, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_new_key),
        cmocka_unit_test(test_the_table_unchanged),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
