/* fuzz_tile.c - libFuzzer harness for addresses and tile operations.
 *
 * Input: optionally "Q:" (a digit 4..8: the tiling {4,Q}; {4,5} without),
 * then an address text, optionally followed by '|' and operation bytes.
 * Checks: parse -> print -> parse round trip; hol_tile_resolve agrees with
 * parse on canonical input and never lands farther than the walk is long;
 * every operation byte moves a tile, and a neighbour and back returns;
 * distance is symmetric, zero only on equal tiles, and obeys the triangle
 * inequality; a neighbour is at distance 1.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"

#include "fuzz_check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    int q = 5;
    if (size >= 2 && data[0] >= '4' && data[0] <= '8' && data[1] == ':') {
        q = data[0] - '0';
        data += 2;
        size -= 2;
    }
    const int reach = hol_tile_reach(q);
    const char *s = (const char *)data;
    const uint8_t *bar = memchr(data, '|', size);
    size_t alen = bar ? (size_t)(bar - data) : size;
    const uint8_t *ops = bar ? bar + 1 : data + size;
    size_t nops = bar ? size - alen - 1 : 0;

    hol_tile t = hol_tile_origin_q(q), r;
    hol_err err = hol_tile_parse_q(q, s, (ptrdiff_t)alen, &t);
    hol_err rerr = hol_tile_resolve_q(q, s, (ptrdiff_t)alen, &r);
    if (err == HOL_OK) {
        char buf[HOL_TILE_ADDR_MAX];
        int n = hol_tile_print(t, buf);
        CHECK((size_t)n == alen || (alen == 1 && n == 1));
        CHECK(memcmp(buf, s, alen) == 0);
        hol_tile u;
        CHECK(hol_tile_parse_q(q, buf, -1, &u) == HOL_OK && hol_tile_eq(t, u));
        CHECK(hol_tile_q(t) == q);
        CHECK(rerr == HOL_OK && hol_tile_eq(r, t));
    } else {
        t = hol_tile_origin_q(q);
        if (err == HOL_EPARSE)
            CHECK(rerr == HOL_EPARSE);
        if (err == HOL_ENOTCANON && rerr == HOL_OK) {
            /* a walk is never shorter than the address of its tile */
            CHECK((size_t)hol_tile_dist0(r) <= alen);
            t = r;
        }
    }

    hol_tile a = t, b = t;
    for (size_t i = 0; i < nops && i < 256; i++) {
        int dir = ops[i] & 3, arr, arr2;
        hol_tile nb, back;
        hol_tile *which = (ops[i] & 4) ? &a : &b;
        if (hol_tile_step(*which, dir, &nb, &arr) != HOL_OK) {
            CHECK(hol_tile_dist0(*which) >= reach - 1);
            continue;
        }
        CHECK(hol_tile_step(nb, arr + 2, &back, &arr2) == HOL_OK);
        CHECK(hol_tile_eq(back, *which));
        CHECK(((arr2 + 2) & 3) == dir);
        CHECK(hol_tile_dist(*which, nb) == 1);
        *which = nb;
    }
    int dab = hol_tile_dist(a, b), dba = hol_tile_dist(b, a);
    int dta = hol_tile_dist(t, a), dtb = hol_tile_dist(t, b);
    CHECK(dab >= 0 && dab == dba);
    CHECK((dab == 0) == hol_tile_eq(a, b));
    CHECK(hol_tile_q(a) == q && hol_tile_q(b) == q);
    CHECK(dtb <= dta + dab && dta <= dtb + dab && dab <= dta + dtb);
    return 0;
}
