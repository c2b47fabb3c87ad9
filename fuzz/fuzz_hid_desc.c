/* fuzz_hid_desc.c - libFuzzer harness for the HID report descriptor parser.
 *
 * Input: descriptor bytes. Checks: the parse is deterministic; every field
 * it lists is 1..32 bits wide, lies inside a report of at most
 * HOL_HID_REPORT_MAX_BYTES, has a report ID only when the descriptor
 * declares IDs, and an array element's usage range is ordered; a smaller
 * map gives HOL_ENOMEM with the same count and the same first fields.
 */
#include <stdint.h>
#include <string.h>

#include "../platform/hid/hol_hid_desc.h"

#include "fuzz_check.h"

#define CAP 4096

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static hol_hid_field a[CAP], b[CAP];
    size_t n = 0, m = 0;
    int ids = 0, ids2 = 0;
    hol_err err = hol_hid_desc_parse(data, size, a, CAP, &n, &ids);
    hol_err err2 = hol_hid_desc_parse(data, size, b, CAP, &m, &ids2);
    CHECK(err == err2 && n == m && ids == ids2);
    if (err != HOL_OK && err != HOL_ENOMEM) {
        CHECK(n == 0);
        return 0;
    }
    size_t shown = n < CAP ? n : CAP;
    CHECK(memcmp(a, b, shown * sizeof a[0]) == 0);
    for (size_t i = 0; i < shown; i++) {
        const hol_hid_field *f = &a[i];
        CHECK(f->size >= 1 && f->size <= 32);
        CHECK((uint64_t)f->bit_offset + f->size <= 8u * HOL_HID_REPORT_MAX_BYTES);
        CHECK(ids || f->report_id == 0);
        if (f->flags & HOL_HID_F_ARRAY)
            CHECK(f->usage <= f->usage_max && (f->usage >> 16) == (f->usage_max >> 16));
        else
            CHECK(f->usage == f->usage_max);
        int64_t v;
        uint8_t body[HOL_HID_REPORT_MAX_BYTES] = {0};
        if (hol_hid_field_read(f, body, sizeof body, &v))
            CHECK(v == 0);
    }
    if (n > 1) {
        size_t k = 0, cap = (n - 1) < CAP ? n - 1 : CAP;
        CHECK(hol_hid_desc_parse(data, size, b, cap, &k, NULL) == HOL_ENOMEM);
        CHECK(k == n);
        CHECK(memcmp(a, b, cap * sizeof a[0]) == 0);
    }
    return 0;
}
