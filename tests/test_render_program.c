/* test_render_program.c - the renderer's programs as data
 * (render/hol_program.h): the one encoding between keys and slots, and the
 * preamble a key gives its shaders. No GL: the keys alone.
 *
 * - test_slot_round_trip: every slot's key encodes back to that slot
 *   (slot -> key -> slot), so no two slots share a key.
 * - test_every_key: over a range of every field wider than the valid one
 *   (bad values too), exactly HOL_PROG_SLOTS keys have a slot, each key
 *   with a slot decodes back to itself (key -> slot -> key), and the
 *   programs that cannot be are refused: day with a room, flat, effects
 *   or shadows; a lit room with tile fields; odd shadow pairs; the text
 *   program with any other field; lamps outside the lit room (the lit
 *   room's trees and hedges have a program of their own, its backdrop
 *   the cheaper one).
 * - test_preamble: a key's preamble names its variant (HOL_LIT, HOL_NIGHT,
 *   HOL_SHD and its vector type, ...) and the lights' constants, and a
 *   buffer too small is refused.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../render/hol_program.h"

static int key_eq(const hol_prog_key *a, const hol_prog_key *b)
{
    return a->lighting == b->lighting && a->room == b->room && a->flat == b->flat &&
           a->wedge == b->wedge && a->fx == b->fx && a->shadow == b->shadow &&
           a->text == b->text && a->lamps == b->lamps && a->vlit == b->vlit &&
           a->floor == b->floor;
}

static void test_slot_round_trip(void **state)
{
    (void)state;
    for (int s = 0; s < HOL_PROG_SLOTS; s++) {
        hol_prog_key k = hol_prog_key_of_slot(s);
        if (hol_prog_slot(&k) != s)
            fail_msg("slot %d -> key (lighting %d room %d flat %d wedge %d fx %d pairs %d) -> %d",
                     s, k.lighting, k.room, k.flat, k.wedge, k.fx, k.shadow,
                     hol_prog_slot(&k));
    }
    /* the first slot is the day program without the wedge (made at create) */
    hol_prog_key day = hol_prog_key_of_slot(0);
    assert_int_equal(day.lighting, HOL_LIGHT_DAY);
    assert_int_equal(day.wedge, 0);
}

static void test_every_key(void **state)
{
    (void)state;
    int valid = 0, seen[HOL_PROG_SLOTS] = {0};
    hol_prog_key k;
    for (k.floor = -1; k.floor <= 2; k.floor++)
    for (k.vlit = -1; k.vlit <= 2; k.vlit++)
    for (k.lamps = -1; k.lamps <= 2; k.lamps++)
    for (k.text = -1; k.text <= 2; k.text++)
    for (k.lighting = -1; k.lighting <= 4; k.lighting++)
        for (k.room = -1; k.room <= 2; k.room++)
            for (k.flat = -1; k.flat <= 2; k.flat++)
                for (k.wedge = -1; k.wedge <= 2; k.wedge++)
                    for (k.fx = -1; k.fx <= HOL_PROG_FX_COUNT; k.fx++)
                        for (k.shadow = -1; k.shadow <= 3; k.shadow++) {
                            int s = hol_prog_slot(&k);
                            if (s < 0)
                                continue;
                            assert_true(s < HOL_PROG_SLOTS);
                            hol_prog_key back = hol_prog_key_of_slot(s);
                            assert_true(key_eq(&k, &back));
                            seen[s]++;
                            valid++;
                        }
    assert_int_equal(valid, HOL_PROG_SLOTS);
    assert_int_equal(HOL_PROG_SLOTS,
                     2 + 12 + 12 * HOL_PROG_FX_COUNT * 2 + 12 * HOL_PROG_FX_SPOTS * 2 +
                         6 * HOL_PROG_FX_COUNT * 2 + 1);
    /* the text program: text alone */
    hol_prog_key text = {HOL_LIGHT_DAY, 0, 0, 0, 0, 0, 1, 0, 0, 0};
    assert_int_equal(hol_prog_slot(&text), HOL_PROG_TEXT_SLOT);
    text.wedge = 1;
    assert_int_equal(hol_prog_slot(&text), -1);
    for (int s = 0; s < HOL_PROG_SLOTS; s++)
        assert_int_equal(seen[s], 1);
    /* what cannot be */
    hol_prog_key day = {HOL_LIGHT_DAY, 0, 0, 1, 0, 0, 0, 0, 0, 0};
    assert_int_equal(hol_prog_slot(&day), 1);
    hol_prog_key bad = day;
    bad.room = 1;
    assert_int_equal(hol_prog_slot(&bad), -1);
    bad = day;
    bad.shadow = 1;
    assert_int_equal(hol_prog_slot(&bad), -1);
    hol_prog_key room = {HOL_LIGHT_NIGHT, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    assert_true(hol_prog_slot(&room) >= 0);
    hol_prog_key lamps = room; /* the lit room's trees and hedges: a program of their own */
    lamps.lamps = 1;
    assert_true(hol_prog_slot(&lamps) >= 0 && hol_prog_slot(&lamps) != hol_prog_slot(&room));
    room.fx = HOL_PROG_FX_SPOTS;
    assert_int_equal(hol_prog_slot(&room), -1);
    hol_prog_key lit_day = day; /* lamps only in the lit room */
    lit_day.lamps = 1;
    assert_int_equal(hol_prog_slot(&lit_day), -1);
    hol_prog_key tiles = {HOL_LIGHT_DUSK, 0, 1, 1, HOL_PROG_FX_SPOTS, 1, 0, 0, 0, 0};
    assert_true(hol_prog_slot(&tiles) >= 0);
    tiles.shadow = 2;
    assert_int_equal(hol_prog_slot(&tiles), -1);
    /* a tile's ground: every effect and mask, no wedge, not per vertex */
    hol_prog_key ground = {HOL_LIGHT_NIGHT, 0, 1, 0, HOL_PROG_FX_SPOTS, 1, 0, 0, 0, 1};
    assert_true(hol_prog_slot(&ground) >= 0);
    ground.wedge = 1;
    assert_int_equal(hol_prog_slot(&ground), -1);
    ground.wedge = 0;
    ground.vlit = 1;
    assert_int_equal(hol_prog_slot(&ground), -1);
    ground.vlit = 0;
    ground.lighting = HOL_LIGHT_DAY;
    assert_int_equal(hol_prog_slot(&ground), -1);
}

static void test_preamble(void **state)
{
    (void)state;
    char pre[768];
    hol_prog_key k = {HOL_LIGHT_NIGHT, 0, 0, 1, HOL_PROG_FX_FIREFLIES, 1, 0, 0, 0, 0};
    int n = hol_prog_preamble(&k, pre, sizeof pre);
    assert_true(n > 0 && (size_t)n == strlen(pre));
    assert_true(strncmp(pre, "#version 300 es\n", 16) == 0);
    const char *want[] = {"#define HOL_LIT 1\n", "#define HOL_FLAT 0\n", "#define HOL_WEDGE 1\n",
                          "#define HOL_NIGHT 1\n", "#define HOL_FX 1\n", "#define HOL_SHD 1\n",
                          "#define HOL_SHM_N 64.0\n",
                          "#define HOL_LIGHT_D0_M ", "#define HOL_LIGHT_RADIUS_M "};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        if (!strstr(pre, want[i]))
            fail_msg("the preamble lacks %s:\n%s", want[i], pre);
    hol_prog_key room = {HOL_LIGHT_DUSK, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    assert_true(hol_prog_preamble(&room, pre, sizeof pre) > 0);
    assert_non_null(strstr(pre, "#define HOL_LIT 2\n"));
    assert_non_null(strstr(pre, "#define HOL_NIGHT 0\n"));
    hol_prog_key day = {HOL_LIGHT_DAY, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    assert_true(hol_prog_preamble(&day, pre, sizeof pre) > 0);
    assert_non_null(strstr(pre, "#define HOL_LIT 0\n"));
    assert_non_null(strstr(pre, "#define HOL_TEXT 0\n"));
    assert_int_equal(hol_prog_preamble(&day, pre, 40), -1);
    hol_prog_key text = {HOL_LIGHT_DAY, 0, 0, 0, 0, 0, 1, 0, 0, 0};
    assert_true(hol_prog_preamble(&text, pre, sizeof pre) > 0);
    assert_non_null(strstr(pre, "#define HOL_TEXT 1\n"));
    assert_non_null(strstr(pre, "#define HOL_SPREAD 2.0\n"));
    assert_non_null(strstr(pre, "#define HOL_FLOOR 0\n"));
    hol_prog_key ground = {HOL_LIGHT_NIGHT, 0, 0, 0, 0, 1, 0, 0, 0, 1};
    assert_true(hol_prog_preamble(&ground, pre, sizeof pre) > 0);
    assert_non_null(strstr(pre, "#define HOL_FLOOR 1\n"));
    assert_non_null(strstr(pre, "#define HOL_VLIT 0\n"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_slot_round_trip),
        cmocka_unit_test(test_every_key),
        cmocka_unit_test(test_preamble),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
