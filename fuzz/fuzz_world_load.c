/* fuzz_world_load.c - libFuzzer harness for the world-image loader.
 *
 * Input: a world image (fuzz/corpus/fuzz_world_load holds small valid ones,
 * one truncated and one of another version). Each input is loaded twice:
 * as given (the checksum stops most mutations) and resealed with a correct
 * checksum, so the structure and constraint checks behind it are fuzzed too.
 * Checks: a rejected image leaves the world byte for byte unchanged and
 * yields a one-line message; an accepted image passes hol_world_check,
 * saves back to the same bytes, and the world keeps generating from it.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_world.h"
#include "../core/hol_world_impl.h"

#include "fuzz_check.h"

static uint8_t *image_of(const hol_world *w, size_t *out_len)
{
    size_t need = hol_world_save_size(w);
    uint8_t *buf = malloc(need);
    CHECK(buf && hol_world_save(w, buf, need, out_len) == HOL_OK);
    return buf;
}

static void try_load(hol_world *w, const uint8_t *data, size_t size)
{
    size_t l0;
    uint8_t *before = image_of(w, &l0);
    char msg[256];
    hol_err err = hol_world_load(w, data, size, msg, sizeof msg);
    if (err) {
        size_t l1;
        uint8_t *after = image_of(w, &l1);
        CHECK(l0 == l1 && memcmp(before, after, l0) == 0);
        CHECK(msg[0] && !strchr(msg, '\n'));
        free(after);
    } else {
        CHECK(hol_world_check(w, NULL, 0) == HOL_OK);
        size_t l1;
        uint8_t *again = image_of(w, &l1);
        CHECK(l1 == size && memcmp(again, data, size) == 0);
        free(again);
        hol_room room = hol_world_user(w);
        hol_err uerr = hol_world_update(w, &room);
        CHECK(uerr == HOL_OK || uerr == HOL_ENOMEM);
        for (int d = 0; d < 4 && uerr == HOL_OK; d++) {
            hol_room next = room;
            if (hol_room_step(&next, d) == HOL_OK) {
                uerr = hol_world_update(w, &next);
                CHECK(uerr == HOL_OK || uerr == HOL_ENOMEM);
            }
        }
        CHECK(hol_world_check(w, NULL, 0) == HOL_OK);
    }
    free(before);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hol_world_desc d;
    memset(&d, 0, sizeof d);
    d.capacity = 4096;
    hol_world *w;
    CHECK(hol_world_make(&d, &w) == HOL_OK);
    try_load(w, data, size);
    if (size >= 8) {
        uint8_t *copy = malloc(size);
        CHECK(copy);
        memcpy(copy, data, size);
        uint64_t h = hol__image_checksum(copy, size - 8);
        for (int i = 0; i < 8; i++)
            copy[size - 8 + i] = (uint8_t)(h >> (8 * i));
        try_load(w, copy, size);
        free(copy);
    }
    hol_world_destroy(w);
    return 0;
}
