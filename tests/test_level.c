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
#include "../core/hol_str.h"
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

/* lighting and lanterns (issue 27): the sky line, placed lanterns (a
 * repeatable line, one lantern a tile, a lantern may share a tile with an
 * objective or a placement) and the cue lantern, which the default cues
 * leave off. */
static void test_lighting_lines(void **state)
{
    (void)state;
    hol_app_level L;
    char err[256] = "";
    assert_int_equal(parse("mode explore\n", &L, err), 0);
    assert_int_equal(L.lighting, HOL_LIGHT_DAY);
    assert_int_equal(L.nlanterns, 0);
    assert_false(L.cues & HOL_CUE_LANTERN);
    assert_int_equal(parse("mode flag\nflag Wrf\nlighting night\nplace lantern Wrf\n"
                           "place rock Nf\nplace lantern Nf\nplace lantern O\ncues lantern poles\n",
                           &L, err), 0);
    assert_int_equal(L.lighting, HOL_LIGHT_NIGHT);
    assert_int_equal(L.nlanterns, 3);
    assert_int_equal(L.nplaces, 1); /* the rock; lanterns are not content */
    hol_tile t;
    assert_int_equal(hol_tile_parse("Nf", -1, &t), HOL_OK);
    assert_true(hol_tile_eq(L.lanterns[1], t));
    assert_int_equal(L.cues, HOL_CUE_LANTERN | HOL_CUE_POLES);
    assert_int_equal(parse("mode explore\nlighting dusk\ncues hot-cold path poles arrow lantern\n",
                           &L, err), 0);
    assert_int_equal(L.lighting, HOL_LIGHT_DUSK);
    assert_int_equal(L.cues, HOL_CUE_ALL | HOL_CUE_LANTERN);
    /* in {4,6} the addresses are {4,6}'s */
    assert_int_equal(parse("tiling 4 6\nmode explore\nplace lantern Nrr\n", &L, err), 0);
    assert_int_equal(hol_tile_q(L.lanterns[0]), 6);
    /* spots: place lantern ADDRESS spot DIR (render/hol_light.h) */
    assert_int_equal(parse("mode explore\nplace lantern N spot down\nplace lantern E\n"
                           "place lantern S spot ahead\nplace lantern W spot left\n",
                           &L, err), 0);
    assert_int_equal(L.nlanterns, 4);
    assert_int_equal(L.lantern_spot[0], 5);
    assert_int_equal(L.lantern_spot[1], 0);
    assert_int_equal(L.lantern_spot[2], 1);
    assert_int_equal(L.lantern_spot[3], 4);
    /* lighting cycle SECONDS: dusk, turning to night over that time; a
     * carried lantern (issue 38) */
    assert_int_equal(L.lighting_cycle_s, 0);
    assert_int_equal(L.lantern_carried, 0);
    assert_int_equal(parse("mode explore\nlighting cycle 90\nlantern carried\n", &L, err), 0);
    assert_int_equal(L.lighting, HOL_LIGHT_DUSK);
    assert_true(L.lighting_cycle_s == 90);
    assert_int_equal(L.lantern_carried, 1);
    /* lang en|de|nl (issue 37): 1 + the language; none: 0, the app's */
    assert_int_equal(parse("mode explore\n", &L, err), 0);
    assert_int_equal(L.lang, 0);
    assert_int_equal(parse("mode explore\nlang de\n", &L, err), 0);
    assert_int_equal(L.lang, 1 + HOL_LANG_DE);
    assert_int_equal(parse("mode explore\nlang en\n", &L, err), 0);
    assert_int_equal(L.lang, 1 + HOL_LANG_EN);
    static const struct {
        const char *text, *want;
        hol_err code;
    } bad[] = {
        {"mode explore\nlighting noon\n", "line 2: lighting 'noon' is not day, dusk or night",
         HOL_EPARSE},
        {"mode explore\nlighting\n", "line 2: 'lighting' needs a value", HOL_EPARSE},
        {"mode explore\nlang fr\n", "line 2: lang 'fr' is not en, de or nl", HOL_EPARSE},
        {"mode explore\nlang DE\n", "line 2: lang 'DE' is not en, de or nl", HOL_EPARSE},
        {"mode explore\nlang de\nlang en\n", "line 3: 'lang' is given twice", HOL_EARG},
        {"mode explore\nlighting day night\n", "line 2: unknown key or wrong value count",
         HOL_EPARSE},
        {"mode explore\nlighting cycle\n", "line 2: lighting cycle takes SECONDS in 1..86400",
         HOL_EPARSE},
        {"mode explore\nlighting cycle 0\n", "line 2: lighting cycle takes SECONDS", HOL_EPARSE},
        {"mode explore\nlighting cycle 86401\n", "line 2: lighting cycle takes SECONDS",
         HOL_ERANGE},
        {"mode explore\nlantern held\n", "line 2: lantern 'held' is not carried", HOL_EPARSE},
        {"mode explore\nlantern carried\nlantern carried\n", "line 3: 'lantern' is given twice",
         HOL_EARG},
        {"mode explore\nplace lantern Nx\n", "line 2: 'Nx' is not a canonical address",
         HOL_EPARSE},
        {"mode explore\nplace lantern N spot up\n",
         "line 2: place lantern takes ADDRESS [spot ahead|right|back|left|down]", HOL_EPARSE},
        {"mode explore\nplace lantern N cone down\n",
         "line 2: place lantern takes ADDRESS [spot", HOL_EPARSE},
        {"mode explore\nplace lantern N spot\n", "line 2: place lantern takes", HOL_EPARSE},
        {"mode explore\nplace rock N spot down\n", "line 2: unknown key or wrong value count",
         HOL_EPARSE},
        {"mode explore\nplace lantern N\nplace lantern N\n",
         "line 3: a lantern on N is already placed on line 2", HOL_EARG},
        {"mode explore\ncues lantern beacon\n", "line 2: cue 'beacon' is not", HOL_EPARSE},
        {"mode explore\nplace lantern N\nplace lantern E\nplace lantern S\nplace lantern W\n"
         "place lantern Nf\nplace lantern Ef\nplace lantern Sf\nplace lantern Wf\n"
         "place lantern Nl\n",
         "line 10: more than 8 lanterns", HOL_ENOMEM},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        hol_level_err e;
        assert_int_equal(hol_level_parse(bad[i].text, strlen(bad[i].text), &L, &e), bad[i].code);
        hol_level_err_format(&e, 1, err, sizeof err);
        if (strncmp(err, bad[i].want, strlen(bad[i].want)))
            fail_msg("case %zu: got '%s', want '%s...'", i, err, bad[i].want);
    }
    /* a study's set line */
    hol_level_err e;
    assert_int_equal(hol_level_line_check("lighting night", 14, &e), HOL_OK);
    assert_int_equal(hol_level_line_check("place lantern Nrr", 17, &e), HOL_OK);
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

/* Typed errors: the code says what kind of problem, the line where, and a
 * conflict names the other line; the bounds hold. */
static void test_typed_errors(void **state)
{
    (void)state;
    static const struct {
        const char *text;
        hol_err code;
        long line, other;
    } cases[] = {
        {"mode chess\n", HOL_EPARSE, 1, 0},
        {"mode flag\nflag-distance 0\n", HOL_ERANGE, 2, 0},
        {"mode flag\nflag Wrf\n# c\nplace rock Wrf\n", HOL_EARG, 4, 2},
        {"mode explore\nplace rock N\nplace grass N\n", HOL_EARG, 3, 2},
        {"seed 1\n", HOL_EARG, 1, 0},
        {"mode explore\nstart NN\n", HOL_EARG, 2, 0},
        {"mode flag\r\nflag Wrf\r\nbogus 1\r\n", HOL_EPARSE, 3, 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        hol_app_level L;
        hol_level_err e;
        assert_int_equal(hol_level_parse(cases[i].text, strlen(cases[i].text), &L, &e),
                         cases[i].code);
        assert_int_equal(e.code, cases[i].code);
        assert_int_equal(e.line, cases[i].line);
        assert_int_equal(e.other, cases[i].other);
        assert_null(strstr(e.msg, "line ")); /* the lines are fields, not text */
    }
    /* a recording's level: its lines counted from where it starts */
    hol_app_level L;
    hol_level_err e;
    const char *t = "mode flag\nflag Wrf\nplace rock Wrf\n";
    assert_int_equal(hol_level_parse(t, strlen(t), &L, &e), HOL_EARG);
    char msg[256];
    hol_level_err_format(&e, 10, msg, sizeof msg);
    assert_string_equal(msg, "line 12: the placement on Wrf conflicts with the flag (line 11)");
    /* CR LF is read as LF */
    assert_int_equal(parse("mode flag\r\nseed 5\r\nflag Wrf\r\n", &L, msg), 0);
    assert_int_equal(L.seed, 5);
    /* bounds: the text, a line */
    static char big[HOL_LEVEL_TEXT_MAX + 2];
    memset(big, '#', sizeof big - 1);
    big[0] = 'm';
    assert_int_equal(hol_level_parse(big, HOL_LEVEL_TEXT_MAX + 1, &L, &e), HOL_ENOMEM);
    /* the bound counts the last line end a session adds: a full-size text
     * is kept whole only when it ends in LF (found by fuzz_cli) */
    static const char head[] = "mode flag\nflag Wrf\n";
    memcpy(big, head, sizeof head - 1);
    for (int i = (int)sizeof head - 1; i < HOL_LEVEL_TEXT_MAX; i++)
        big[i] = i % 64 ? '#' : '\n'; /* short comment lines */
    big[HOL_LEVEL_TEXT_MAX - 1] = '#';
    assert_int_equal(hol_level_parse(big, HOL_LEVEL_TEXT_MAX, &L, &e), HOL_ENOMEM);
    big[HOL_LEVEL_TEXT_MAX - 1] = '\n';
    assert_int_equal(hol_level_parse(big, HOL_LEVEL_TEXT_MAX, &L, &e), HOL_OK);
    static hol_level kept;
    assert_int_equal(hol_level_make("big", 3, big, HOL_LEVEL_TEXT_MAX - 1, &kept, &e), HOL_OK);
    assert_int_equal(kept.len, HOL_LEVEL_TEXT_MAX);
    assert_int_equal(hol_level_parse(kept.text, kept.len, &L, &e), HOL_OK);
    char line[HOL_LEVEL_LINE_MAX + 40];
    int n = snprintf(line, sizeof line, "mode flag\n#");
    memset(line + n, 'x', HOL_LEVEL_LINE_MAX);
    line[n + HOL_LEVEL_LINE_MAX] = 0;
    assert_int_equal(hol_level_parse(line, strlen(line), &L, &e), HOL_ENOMEM);
    assert_int_equal(e.line, 2);
}

/* A session's level: a name a recording can carry, the text as recorded,
 * its SHA-256 (FIPS 180-4 test vectors first). */
static void test_named_level(void **state)
{
    (void)state;
    uint8_t h[32];
    char hex[HOL_SHA256_HEX];
    hol_sha256("abc", 3, h);
    hol_sha256_hex(h, hex);
    assert_string_equal(hex, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    hol_sha256("", 0, h);
    hol_sha256_hex(h, hex);
    assert_string_equal(hex, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    const char *two = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    hol_sha256(two, strlen(two), h);
    hol_sha256_hex(h, hex);
    assert_string_equal(hex, "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    static hol_level lv;
    hol_level_err e;
    const char *crlf = "mode flag\r\nseed 5\r\nflag Wrf";
    assert_int_equal(hol_level_make("f", 1, crlf, strlen(crlf), &lv, &e), HOL_OK);
    assert_string_equal(lv.text, "mode flag\nseed 5\nflag Wrf\n");
    assert_string_equal(lv.name, "f");
    hol_sha256(lv.text, lv.len, h);
    assert_memory_equal(h, lv.sha256, 32);
    /* names that cannot be a recording's "level NAME" line are refused */
    static const char *const bad[] = {"a\nb", "a\rb", ""};
    for (int i = 0; i < 3; i++) {
        assert_int_equal(hol_level_make(bad[i], strlen(bad[i]), crlf, strlen(crlf), &lv, &e),
                         HOL_EARG);
        assert_int_equal(e.line, 0);
    }
    char longname[HOL_LEVEL_NAME_MAX + 1];
    memset(longname, 'n', sizeof longname);
    assert_int_equal(hol_level_make(longname, HOL_LEVEL_NAME_MAX, crlf, strlen(crlf), &lv, &e),
                     HOL_EARG);
    /* an escape sequence survives a recording: it is kept (and escaped where shown) */
    assert_int_equal(hol_level_make("\033]0;x\007", 6, crlf, strlen(crlf), &lv, &e), HOL_OK);
}

/* The campaign and --mode levels: pure, from the seed, parseable texts. */
/* ---- geometry lines (SPEC 7) ------------------------------------------------ */

static void test_geometry_lines(void **state)
{
    (void)state;
    char err[256];
    hol_app_level L;
    /* absent: zero (the defaults) */
    assert_int_equal(parse("mode flag\nflag Nf\n", &L, err), 0);
    assert_int_equal(L.tiling_q, 0);
    assert_int_equal(L.room_cols, 0);
    assert_true(L.cell_m == 0);
    /* addresses are read in the level's tiling even before its line:
     * Nrr is an address in {4,8}, not in {4,5} */
    assert_int_equal(parse("mode flag\nflag Nrr\ntiling 4 8\nroom 4 5\ncell 0.75\n", &L, err), 0);
    assert_int_equal(L.tiling_q, 8);
    assert_int_equal(hol_tile_q(L.flag), 8);
    assert_int_equal(L.room_cols, 4);
    assert_int_equal(L.room_rows, 5);
    assert_true(L.cell_m == 0.75);
    assert_int_equal(parse("mode flag\nflag Nrr\n", &L, err), 1);
    assert_string_equal(err, "line 2: 'Nrr' is not a canonical address of {4,5}");
    /* bad values: one line naming the line */
    static const struct { const char *text, *msg; hol_err code; } bad[] = {
        {"mode explore\ntiling 4 9\n", "line 2: tiling needs 4 Q with Q from 4 to 8 (the tiling {4,Q}), not '4 9'", HOL_ERANGE},
        {"mode explore\ntiling 3 5\n", "line 2: tiling needs 4 Q with Q from 4 to 8 (the tiling {4,Q}), not '3 5'", HOL_ERANGE},
        {"mode explore\ntiling 4,5\n", "line 2: unknown key or wrong value count: 'tiling'", HOL_EPARSE},
        {"mode explore\n\nroom 2 3\n", "line 3: room needs C R with C and R from 3 to 5 (cells), not '2 3'", HOL_ERANGE},
        {"mode explore\nroom 3x3\n", "line 2: unknown key or wrong value count: 'room'", HOL_EPARSE},
        {"mode explore\ncell 1.6\n", "line 2: cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '1.6'", HOL_ERANGE},
        {"mode explore\ncell 0.7505\n", "line 2: cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '0.7505'", HOL_ERANGE},
        {"mode explore\ncell 1e0\n", "line 2: cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '1e0'", HOL_EPARSE},
        {"mode explore\ncell .5\n", "line 2: cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '.5'", HOL_EPARSE},
        /* the flat grid: a 3 x 3 room reaches its nine tiles only */
        {"tiling 4 4\nmode flag\nflag Nf\n", "line 3: no walk inside the room reaches the flag's tile Nf (in the flat {4,4} a 3x3 room reaches only its own 9 tiles)", HOL_EARG},
        {"tiling 4 4\nmode keys\nkeys N Nr\nchest Sf\n", "line 4: no walk inside the room reaches the chest's tile Sf (in the flat {4,4} a 3x3 room reaches only its own 9 tiles)", HOL_EARG},
        {"tiling 4 4\nmode flag\nflag-distance 3\n", "line 3: no free tile for the flag at that distance that a walk inside the room reaches", HOL_EARG},
        {"tiling 4 4\nmode tutorial\n", "line 1: the tutorial needs the tiling {4,5}, {4,6} or {4,7}: its lessons have no walk inside the room in {4,4}", HOL_EARG},
        {"mode flag\nflag N\nstart NN\n", "line 3: the start walk leaves the room", HOL_EARG},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        hol_level_err e;
        assert_int_equal(hol_level_parse(bad[i].text, strlen(bad[i].text), &L, &e), bad[i].code);
        assert_string_equal(hol_level_err_format(&e, 1, err, 256), bad[i].msg);
    }
    /* a 5 x 5 room: two steps north from (2,2) stay inside; the flat
     * grid reaches Nf there (two ahead) */
    assert_int_equal(parse("mode flag\nflag Wf\nstart NN\nroom 5 5\ntiling 4 4\n", &L, err), 0);
    /* {4,4} 3x3 draws among the room's tiles (distance 1 or 2) */
    for (int seed = 0; seed < 50; seed++) {
        char text[128];
        snprintf(text, sizeof text, "tiling 4 4\nmode keys\nseed %d\nkeys-distance 3 1 2\nchest-distance 2\n", seed);
        assert_int_equal(parse(text, &L, err), 0);
        hol_tile o = hol_tile_origin_q(4);
        for (int k = 0; k < L.nkeys; k++)
            assert_true(hol_tile_dist(o, L.keys[k]) <= 2);
        assert_int_equal(hol_tile_dist(o, L.chest), 2);
        /* the chest on a corner tile of the room: two letters, one turn */
        char a[HOL_TILE_ADDR_MAX];
        hol_tile_print(L.chest, a);
        assert_true(a[1] == 'l' || a[1] == 'r' || a[1] == 'f');
        assert_true(a[1] != 'f');
    }
    /* cell values: the nearest double */
    double m = 0;
    assert_int_equal(hol_level_parse_cell("1", 1, &m), HOL_OK);
    assert_true(m == 1.0);
    assert_int_equal(hol_level_parse_cell("1.25", 4, &m), HOL_OK);
    assert_true(m == 1.25);
    assert_int_equal(hol_level_parse_cell("0.5", 3, &m), HOL_OK);
    assert_true(m == 0.5);
    assert_int_equal(hol_level_parse_cell("1.500", 5, &m), HOL_OK);
    assert_int_equal(hol_level_parse_cell("0.499", 5, &m), HOL_ERANGE);
    assert_int_equal(hol_level_parse_cell("-1", 2, &m), HOL_EPARSE);
    assert_int_equal(hol_level_parse_cell("1.", 2, &m), HOL_EPARSE);
    char c[16];
    assert_string_equal(hol_level_format_cell(1.0, c), "1");
    assert_string_equal(hol_level_format_cell(0.75, c), "0.75");
    assert_string_equal(hol_level_format_cell(1.25, c), "1.25");
    assert_string_equal(hol_level_format_cell(0.5, c), "0.5");
    assert_string_equal(hol_level_format_cell(0, c), "1");
}

/* Options applied to a level: the lines added (the text a recording
 * keeps), or a conflict refused. */
/* Issue 24 findings 9 and 10: a key given twice is refused naming both
 * lines (it was silently last-wins, and two tiling lines read addresses in
 * the last one: "tiling 4 8 / flag Nrr / tiling 4 5" failed with a wrong
 * reason); a tile beyond the reach less one is refused naming its line (59
 * letters in {4,6} and {4,7} parsed, then failed at start with exit 1). */
static void test_repeats_and_reach(void **state)
{
    (void)state;
    char err[256];
    hol_app_level L;
    static const struct { const char *text, *msg; } bad[] = {
        {"tiling 4 8\nmode flag\nflag Nrr\ntiling 4 5\n",
         "line 4: 'tiling' is given twice; give each key once (line 1)"},
        {"mode flag\nflag Nf\nflag Nr\n", "line 3: 'flag' is given twice; give each key once (line 2)"},
        {"mode flag\nroom 3 3\nflag Nf\n# c\nroom 4 4\n",
         "line 5: 'room' is given twice; give each key once (line 2)"},
        {"cell 1\nmode flag\nflag Nf\ncell 1\n", "line 4: 'cell' is given twice; give each key once (line 1)"},
        {"mode flag\nmode keys\n", "line 2: 'mode' is given twice; give each key once (line 1)"},
        {"mode flag\nseed 1\nflag-distance 2\nseed 2\n", "line 4: 'seed' is given twice; give each key once (line 2)"},
        {"mode flag\nflag-distance 2\nflag-distance 3\n",
         "line 3: 'flag-distance' is given twice; give each key once (line 2)"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        assert_int_equal(parse(bad[i].text, &L, err), 1);
        assert_string_equal(err, bad[i].msg);
    }
    /* a UTF-8 byte order mark before the first line is skipped, and a
     * named level's text does not keep it */
    assert_int_equal(parse("\xef\xbb\xbfmode flag\nflag Nf\n", &L, err), 0);
    static hol_level lv;
    hol_level_err le;
    const char *bom = "\xef\xbb\xbfmode flag\nflag Nf\n";
    assert_int_equal(hol_level_make("b", 1, bom, strlen(bom), &lv, &le), HOL_OK);
    assert_string_equal(lv.text, "mode flag\nflag Nf\n");
    /* place repeats (on different tiles) */
    assert_int_equal(parse("mode flag\nflag Nf\nplace rock Sf\nplace pond Ef\n", &L, err), 0);
    /* the reach: 58 letters is a level's tile in every tiling, 59 only
     * in {4,5} (its reach is 60) */
    char text[256], addr[64];
    for (int q = 5; q <= 7; q++)
        for (int n = 58; n <= 59; n++) {
            addr[0] = 'N';
            memset(addr + 1, 'f', (size_t)n - 1);
            addr[n] = 0;
            snprintf(text, sizeof text, "mode flag\ntiling 4 %d\nflag %s\n", q, addr);
            int want_bad = n >= hol_tile_reach(q);
            assert_int_equal(parse(text, &L, err), want_bad);
            if (want_bad)
                assert_non_null(strstr(err, "line 3: 'Nfff"));
        }
}

static void test_set_geometry(void **state)
{
    (void)state;
    static hol_level lv;
    hol_level_err e;
    char err[256];
    const char *t = "mode flag\nflag Nf\n";
    assert_int_equal(hol_level_make("a", 1, t, strlen(t), &lv, &e), HOL_OK);
    assert_int_equal(hol_level_set_geometry(&lv, 0, 0, 0, 0, &e), HOL_OK);
    assert_string_equal(lv.text, t); /* nothing asked: unchanged */
    assert_int_equal(hol_level_set_geometry(&lv, 6, 4, 4, 0.75, &e), HOL_OK);
    assert_string_equal(lv.text, "tiling 4 6\nroom 4 4\ncell 0.75\nmode flag\nflag Nf\n");
    assert_int_equal(lv.lvl.tiling_q, 6);
    assert_int_equal(hol_tile_q(lv.lvl.flag), 6);
    assert_int_equal(lv.lvl.room_rows, 4);
    assert_true(lv.lvl.cell_m == 0.75);
    /* the same again: nothing added; another value: refused */
    assert_int_equal(hol_level_set_geometry(&lv, 6, 4, 4, 0.75, &e), HOL_OK);
    assert_string_equal(lv.text, "tiling 4 6\nroom 4 4\ncell 0.75\nmode flag\nflag Nf\n");
    assert_int_equal(hol_level_set_geometry(&lv, 5, 0, 0, 0, &e), HOL_EARG);
    assert_string_equal(hol_level_err_format(&e, 1, err, 256),
                        "its own line 'tiling 4 6' differs from the {4,5} asked for");
    assert_int_equal(hol_level_set_geometry(&lv, 0, 3, 5, 0, &e), HOL_EARG);
    assert_string_equal(hol_level_err_format(&e, 1, err, 256),
                        "its own line 'room 4 4' differs from the 3x5 asked for");
    assert_int_equal(hol_level_set_geometry(&lv, 0, 0, 0, 1.0, &e), HOL_EARG);
    assert_string_equal(hol_level_err_format(&e, 1, err, 256),
                        "its own line 'cell 0.75' differs from the 1 m asked for");
    /* the flat grid refuses the flag off the room's tiles */
    const char *far = "mode flag\nflag Nf\n";
    assert_int_equal(hol_level_make("b", 1, far, strlen(far), &lv, &e), HOL_OK);
    assert_int_equal(hol_level_set_geometry(&lv, 4, 0, 0, 0, &e), HOL_EARG);
    assert_string_equal(hol_level_err_format(&e, 1, err, 256),
                        "line 2: no walk inside the room reaches the flag's tile Nf (in the "
                        "flat {4,4} a 3x3 room reaches only its own 9 tiles)");
    /* a tutorial takes only the cell: its lessons stay {4,5} 3x3 */
    const char *tut = "mode tutorial\nseed 1\n";
    assert_int_equal(hol_level_make("t", 1, tut, strlen(tut), &lv, &e), HOL_OK);
    assert_int_equal(hol_level_set_geometry(&lv, 4, 5, 5, 0.75, &e), HOL_OK);
    assert_string_equal(lv.text, "cell 0.75\nmode tutorial\nseed 1\n");
    assert_int_equal(lv.lvl.tiling_q, 0);
    assert_int_equal(lv.lvl.room_cols, 0);
}

static void test_campaign(void **state)
{
    (void)state;
    static hol_level a[HOL_CAMPAIGN_LEVELS], b[HOL_CAMPAIGN_LEVELS];
    assert_int_equal(hol_campaign_default(1, NULL, a), HOL_OK);
    assert_int_equal(hol_campaign_default(1, NULL, b), HOL_OK);
    static const char *const names[] = {"tutorial", "flag-1", "flag-2", "flag-3", "keys-1", "keys-2"};
    static const int modes[] = {HOL_APP_TUTORIAL, HOL_APP_FLAG, HOL_APP_FLAG, HOL_APP_FLAG,
                                HOL_APP_KEYS, HOL_APP_KEYS};
    for (int i = 0; i < HOL_CAMPAIGN_LEVELS; i++) {
        assert_string_equal(a[i].name, names[i]);
        assert_int_equal(a[i].lvl.mode, modes[i]);
        assert_string_equal(a[i].text, b[i].text);
        hol_app_level again;
        assert_int_equal(hol_level_parse(a[i].text, a[i].len, &again, NULL), HOL_OK);
    }
    assert_int_equal(hol_tile_dist0(a[1].lvl.flag), 3);
    assert_int_equal(hol_tile_dist0(a[3].lvl.flag), 7);
    assert_int_equal(a[4].lvl.nkeys, 2);
    assert_int_equal(a[5].lvl.nkeys, 3);
    hol_level m;
    assert_int_equal(hol_campaign_mode_level("keys", 16, NULL, &m), HOL_OK);
    assert_string_equal(m.name, "keys-16");
    assert_int_equal(m.lvl.nkeys, 3);
    assert_int_equal(hol_tile_dist0(m.lvl.chest), 5);
    assert_int_equal(hol_campaign_mode_level("chess", 1, NULL, &m), HOL_EARG);
}

/* The campaign and --mode levels of the other geometries: each level
 * holds its tiling (and a room other than 3 x 3), and every one starts in
 * an app, whose navigator (not the walk that placed them) proves each
 * objective reachable inside the room with an exact optimum. In the flat
 * {4,4} a flag asked at distance d lies at min(d, the farthest tile of
 * the room from the start: the largest |dc| + |dr| of its cells). The
 * {4,5} levels are those made before geometries came. */
static void check_geo_level(hol_app *app, const hol_level *lv, const hol_campaign_geo *g, int d)
{
    const hol_app_level *L = &lv->lvl;
    if (L->mode == HOL_APP_TUTORIAL)
        return;
    int cols = g->cols ? g->cols : 3, rows = g->rows ? g->rows : 3;
    assert_int_equal(L->tiling_q, g->q);
    assert_int_equal(L->room_cols ? L->room_cols : 3, cols);
    assert_int_equal(L->room_rows ? L->room_rows : 3, rows);
    hol_err e = hol_app_start_level(app, L);
    if (e)
        fail_msg("{4,%d} %dx%d %s: start %s\n%s", g->q, cols, rows, lv->name, hol_err_str(e),
                 lv->text);
    assert_true(hol_app_get_view(app)->hud.optimum > 0);
    if (g->q == 4 && L->mode == HOL_APP_FLAG) {
        int far = cols / 2 + rows / 2, want = d < far ? d : far;
        assert_int_equal(hol_tile_dist0(L->flag), want);
    }
}

static void test_campaign_geometries(void **state)
{
    (void)state;
    static const hol_campaign_geo geos[] = {{4, 0, 0}, {4, 5, 5}, {4, 4, 3}, {6, 0, 0},
                                            {7, 3, 5}, {8, 0, 0}, {8, 5, 5}, {8, 4, 3}};
    static hol_level a[HOL_CAMPAIGN_LEVELS];
    static const int dist[HOL_CAMPAIGN_LEVELS] = {0, 3, 5, 7, 3, 4};
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    hol_app *app;
    assert_int_equal(hol_app_create(&ad, &app), HOL_OK);
    for (size_t i = 0; i < sizeof geos / sizeof geos[0]; i++) {
        for (uint64_t seed = 1; seed <= 3; seed++) {
            assert_int_equal(hol_campaign_default(seed, &geos[i], a), HOL_OK);
            for (int k = 0; k < HOL_CAMPAIGN_LEVELS; k++)
                check_geo_level(app, &a[k], &geos[i], dist[k]);
            hol_level m;
            assert_int_equal(hol_campaign_mode_level("keys", seed, &geos[i], &m), HOL_OK);
            check_geo_level(app, &m, &geos[i], 5);
            assert_int_equal(hol_campaign_mode_level("flag", seed, &geos[i], &m), HOL_OK);
            check_geo_level(app, &m, &geos[i], 5);
        }
    }
    hol_app_destroy(app);
    /* {4,5}: the same texts with or without a geo, as before geometries */
    static hol_level b[HOL_CAMPAIGN_LEVELS];
    hol_campaign_geo g5 = {5, 5, 5};
    assert_int_equal(hol_campaign_default(1, NULL, a), HOL_OK);
    assert_int_equal(hol_campaign_default(1, &g5, b), HOL_OK);
    for (int k = 0; k < HOL_CAMPAIGN_LEVELS; k++)
        assert_string_equal(a[k].text, b[k].text);
    assert_string_equal(a[3].text, "mode flag\nseed 3\nflag Wffrflf\n");
    assert_string_equal(a[5].text, "mode keys\nseed 5\nkeys Nff Ef Er\nchest Slrf\n");
    hol_campaign_geo bad = {9, 0, 0};
    assert_int_equal(hol_campaign_default(1, &bad, a), HOL_EARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_distances),
        cmocka_unit_test(test_other_keys),
        cmocka_unit_test(test_bad_lines),
        cmocka_unit_test(test_lighting_lines),
        cmocka_unit_test(test_typed_errors),
        cmocka_unit_test(test_named_level),
        cmocka_unit_test(test_campaign),
        cmocka_unit_test(test_campaign_geometries),
        cmocka_unit_test(test_geometry_lines),
        cmocka_unit_test(test_set_geometry),
        cmocka_unit_test(test_repeats_and_reach),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
