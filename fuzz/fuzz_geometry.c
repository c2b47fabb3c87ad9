/* fuzz_geometry.c - libFuzzer harness for the geometry options' text
 * (SPEC 7): "--tiling 4,Q" and "--room CxR" values (hol_room_parse_tiling,
 * hol_room_parse_size).
 *
 * Input: bytes; the text before the first '\n' goes to the tiling parser,
 * the rest to the room parser (both also get the whole input).
 * Checks: an accepted value is in range and prints back to a text the
 * parser accepts with the same value; a refused one leaves the outputs
 * untouched; the parsers read only the bytes they are given; a room of the
 * accepted size starts inside itself and refuses the step off its edge.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_room.h"

#include "fuzz_check.h"

static void check_tiling(const char *s, size_t len)
{
    int q = -7;
    hol_err err = hol_room_parse_tiling(s, len, &q);
    if (err) {
        CHECK(q == -7);
        CHECK(err == HOL_EPARSE || err == HOL_EARG);
        return;
    }
    CHECK(q >= HOL_TILING_MIN_Q && q <= HOL_TILING_MAX_Q);
    char buf[16];
    int n = snprintf(buf, sizeof buf, "4,%d", q), q2 = 0;
    CHECK(hol_room_parse_tiling(buf, (size_t)n, &q2) == HOL_OK && q2 == q);
    CHECK(memchr(s, '\0', len) == NULL);
}

static void check_size(const char *s, size_t len)
{
    int c = -7, r = -7;
    hol_err err = hol_room_parse_size(s, len, &c, &r);
    if (err) {
        CHECK(c == -7 && r == -7);
        CHECK(err == HOL_EPARSE || err == HOL_EARG);
        return;
    }
    CHECK(c >= 3 && c <= 5 && r >= 3 && r <= 5);
    char buf[16];
    int n = snprintf(buf, sizeof buf, "%dx%d", c, r), c2 = 0, r2 = 0;
    CHECK(hol_room_parse_size(buf, (size_t)n, &c2, &r2) == HOL_OK && c2 == c && r2 == r);
    hol_room room;
    CHECK(hol_room_start_in(0, c, r, &room) == HOL_OK);
    CHECK(room.col == c / 2 && room.row == r / 2 && hol_room_ok(&room));
    for (int i = 0; i < c; i++)
        (void)hol_room_step(&room, HOL_DIR_E);
    CHECK(room.col == c - 1 && hol_room_step(&room, HOL_DIR_E) == HOL_EROOM);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* copy so that a read past the end is caught by the sanitizer */
    char *s = malloc(size ? size : 1);
    if (!s)
        return 0;
    memcpy(s, data, size);
    const char *nl = memchr(s, '\n', size);
    size_t first = nl ? (size_t)(nl - s) : size;
    check_tiling(s, first);
    check_size(nl ? nl + 1 : s + size, nl ? size - first - 1 : 0);
    check_tiling(s, size);
    check_size(s, size);
    free(s);
    return 0;
}
