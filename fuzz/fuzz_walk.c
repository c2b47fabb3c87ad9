/* fuzz_walk.c - libFuzzer harness for walks of room steps (command input).
 *
 * Input: a walk text as the CLI receives it. Checks: hol_walk_parse accepts
 * exactly the strings of N/E/S/W (or "-") and reports the first bad byte;
 * applied in the room, every step either moves to a neighbouring cell or is
 * refused with the state unchanged; the room's tile is the tile of the free
 * walk of the steps that were taken; a free walk never ends farther from O
 * than its length.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_room.h"
#include "../core/hol_tile.h"

#include "fuzz_check.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t dirs[512], taken[512];
    size_t n = 0, bad = (size_t)-1, ntaken = 0;
    hol_err err = hol_walk_parse((const char *)data, size, dirs, sizeof dirs, &n, &bad);
    size_t first_bad = size;
    for (size_t i = 0; i < size; i++)
        if (hol_dir_from_char(data[i]) < 0) {
            first_bad = i;
            break;
        }
    if (size == 1 && data[0] == '-') {
        CHECK(err == HOL_OK && n == 0);
        return 0;
    }
    if (first_bad < size) {
        CHECK(err == HOL_EPARSE && bad == first_bad);
        return 0;
    }
    if (size > sizeof dirs) {
        CHECK(err == HOL_ENOMEM);
        return 0;
    }
    CHECK(err == HOL_OK && n == size);

    hol_room room = hol_room_start();
    for (size_t i = 0; i < n; i++) {
        hol_room before = room;
        hol_err e = hol_room_step(&room, dirs[i]);
        if (e == HOL_EROOM || e == HOL_ERANGE) {
            CHECK(memcmp(&room, &before, sizeof room) == 0);
            continue;
        }
        CHECK(e == HOL_OK);
        int dc, dr;
        hol_dir_delta(dirs[i], &dc, &dr);
        CHECK(room.col == before.col + dc && room.row == before.row + dr);
        CHECK(room.col < 3 && room.row < 3 && room.orient < 4);
        taken[ntaken++] = dirs[i];
    }
    hol_tile t;
    int orient;
    if (hol_tile_from_walk(taken, ntaken, &t, &orient) == HOL_OK) {
        CHECK(hol_tile_eq(t, room.tile) && orient == room.orient);
        CHECK((size_t)hol_tile_dist0(t) <= ntaken);
    }
    return 0;
}
