/* fuzz_hid_report.c - libFuzzer harness for the pad report decoder.
 *
 * Input: a 2-byte descriptor length L (little-endian), L descriptor bytes,
 * then input reports, each a length byte and that many bytes; the last
 * four bytes of a descriptor-less input pick VID:PID. Checks: decoding
 * never reads outside a report, and after every report the axes are in
 * [-1, 1] (finite) and only HOL_BTN_* pad roles are set.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../platform/hid/hol_hid_desc.h"
#include "../platform/hid/hol_hid_pad.h"

#include "fuzz_check.h"

#define CAP 2048

static int in_unit(float v) { return isfinite(v) && v >= -1.0f && v <= 1.0f; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static hol_hid_field map[CAP];
    static hol_hid_pad pad;
    if (size < 6)
        return 0;
    uint16_t vid = (uint16_t)(data[0] | data[1] << 8);
    uint16_t pid = (uint16_t)(data[2] | data[3] << 8);
    size_t dlen = (size_t)(data[4] | data[5] << 8);
    data += 6;
    size -= 6;
    if (dlen > size)
        dlen = size;
    size_t n = 0;
    int ids = 0;
    hol_err err = hol_hid_desc_parse(data, dlen, map, CAP, &n, &ids);
    if (err == HOL_ENOMEM)
        n = CAP;
    else if (err)
        n = 0;
    if (hol_hid_pad_init(&pad, map, n, ids, vid, pid, NULL))
        return 0;
    data += dlen;
    size -= dlen;
    while (size > 0) {
        size_t len = data[0];
        data++;
        size--;
        if (len > size)
            len = size;
        /* a copy of exactly len bytes: ASan catches any read past it */
        uint8_t *rep = malloc(len ? len : 1);
        CHECK(rep != NULL);
        memcpy(rep, data, len);
        hol_input in;
        memset(&in, 0, sizeof in);
        hol_hid_pad_decode(&pad, rep, len, &in);
        free(rep);
        CHECK(in_unit(in.move[0]) && in_unit(in.move[1]));
        CHECK(in_unit(in.turn[0]) && in_unit(in.turn[1]));
        CHECK((in.buttons & ~(uint32_t)(HOL_BTN_CONFIRM | HOL_BTN_BACK |
                                        HOL_BTN_MENU | HOL_BTN_RECENTRE |
                                        HOL_BTN_MINIMAP)) == 0);
        data += len;
        size -= len;
    }
    return 0;
}
