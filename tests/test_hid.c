/* test_hid.c - the HID descriptor parser and the pad decoder.
 *
 * Data: tests/hid_samples.h holds the report descriptors of eight real
 * pads (Saitek, Asus, Raptor Mach 2, Sony Sixaxis, DualShock 4 and
 * DualSense over USB and Bluetooth; sources in tests/hid/SOURCES) and, per
 * pad, five input reports that hid-tools' report encoder built from the
 * descriptor for known states (hid_states: left x y, right x y, hat,
 * buttons). The decoded sticks, hat and buttons are checked against those
 * states; the field maps are checked against hid-tools' parse by
 * tests/cli_hid.sh. The parser's own cases (push/pop, long items, ranges,
 * errors, bit reads) are built here item by item.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "../platform/hid/hol_hid_desc.h"
#include "../platform/hid/hol_hid_pad.h"
#include "hid_samples.h"

typedef struct sample {
    const char *name;
    const uint8_t *desc;
    size_t desc_len;
    const uint8_t *reports; /* 5 reports of report_len bytes */
    size_t report_len;
    uint16_t vid, pid;
    uint32_t roles[4]; /* HOL_BTN_* expected for buttons 1..4 */
    int has_hat;
} sample;

#define GENERIC {HOL_BTN_CONFIRM, HOL_BTN_BACK, 0, HOL_BTN_RECENTRE}
#define SONY {HOL_BTN_RECENTRE, HOL_BTN_CONFIRM, HOL_BTN_BACK, HOL_BTN_MINIMAP}
#define PS3 {HOL_BTN_MINIMAP, 0, 0, HOL_BTN_MENU}
#define S(n, roles, hat)                                                       \
    {#n, n##_desc, sizeof n##_desc, &n##_reports[0][0], sizeof n##_reports[0], \
     n##_vid, n##_pid, roles, hat}

static const sample samples[] = {
    S(saitek, GENERIC, 1), S(asus, GENERIC, 1),   S(raptor, GENERIC, 1),
    S(ps3, PS3, 0),        S(ps4_usb, SONY, 1),   S(ps4_bt, SONY, 1),
    S(ps5_usb, SONY, 1),   S(ps5_bt, SONY, 1),
};

static hol_hid_field map[16384];

/* The model: normalise from the logical range, radial dead zone. */
static void model_stick(const hol_hid_field *fx, const hol_hid_field *fy,
                        int vx, int vy, double out[2])
{
    double x = (vx - (double)fx->logical_min) /
                   (double)(fx->logical_max - fx->logical_min) * 2 - 1;
    double y = (vy - (double)fy->logical_min) /
                   (double)(fy->logical_max - fy->logical_min) * 2 - 1;
    double m = hypot(x, y), dz = 0.15;
    if (m <= dz) {
        out[0] = out[1] = 0;
        return;
    }
    double s = ((m > 1 ? 1 : m) - dz) / (1 - dz) / m;
    out[0] = x * s;
    out[1] = y * s;
}

static void test_samples_decode(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof samples / sizeof samples[0]; k++) {
        const sample *s = &samples[k];
        size_t n;
        int ids;
        assert_int_equal(hol_hid_desc_parse(s->desc, s->desc_len, map,
                                            sizeof map / sizeof map[0], &n, &ids),
                         HOL_OK);
        static hol_hid_pad pad;
        assert_int_equal(hol_hid_pad_init(&pad, map, n, ids, s->vid, s->pid, NULL),
                         HOL_OK);
        assert_true(pad.has_axis[HOL_HID_LX] && pad.has_axis[HOL_HID_LY]);
        assert_true(pad.has_axis[HOL_HID_RX] && pad.has_axis[HOL_HID_RY]);
        assert_int_equal(pad.has_hat, s->has_hat);
        for (int r = 0; r < 5; r++) {
            const int *st = hid_states[r];
            hol_input in;
            memset(&in, 0, sizeof in);
            assert_true(hol_hid_pad_decode(&pad, s->reports + r * s->report_len,
                                           s->report_len, &in));
            double l[2], rs[2];
            model_stick(&pad.axis[HOL_HID_LX], &pad.axis[HOL_HID_LY], st[0], st[1], l);
            model_stick(&pad.axis[HOL_HID_RX], &pad.axis[HOL_HID_RY], st[2], st[3], rs);
            assert_float_equal(in.move[0], l[0], 1e-4);
            assert_float_equal(in.move[1], -l[1], 1e-4);
            assert_float_equal(in.turn[0], -rs[0], 1e-4);
            assert_float_equal(in.turn[1], -rs[1], 1e-4);
            uint32_t want = 0;
            for (int b = 0; b < 4; b++)
                if (st[5] >> b & 1)
                    want |= s->roles[b];
            /* hat: 15 is the null state; 0 (north) is recentre */
            if (s->has_hat) {
                const hol_hid_field *h = &pad.hat;
                int v = st[4];
                if (v >= h->logical_min && v <= h->logical_max) {
                    int d = (int)((v - h->logical_min) * 8 /
                                  (h->logical_max - h->logical_min + 1));
                    if (d == 7 || d <= 1)
                        want |= HOL_BTN_RECENTRE;
                    if (d >= 3 && d <= 5)
                        want |= HOL_BTN_MINIMAP;
                }
            }
            if (in.buttons != want)
                fail_msg("%s report %d: buttons 0x%x, want 0x%x", s->name, r,
                         in.buttons, want);
        }
    }
}

/* Values a person can check by eye: DualShock 4 over USB, report 2 of the
 * samples (left stick right-up, right stick left-down, hat east, cross). */
static void test_ds4_known_report(void **state)
{
    (void)state;
    size_t n;
    int ids;
    static hol_hid_pad pad;
    assert_int_equal(hol_hid_desc_parse(ps4_usb_desc, sizeof ps4_usb_desc, map,
                                        16384, &n, &ids), HOL_OK);
    assert_int_equal(ids, 1);
    assert_int_equal(hol_hid_pad_init(&pad, map, n, ids, 0x054c, 0x05c4, NULL),
                     HOL_OK);
    assert_non_null(pad.known);
    /* bytes: id 1, lx ff, ly 00, rx 3f, ry bf, hat 2 | cross (0x20) */
    const uint8_t *r = ps4_usb_reports[2];
    assert_int_equal(r[0], 1);
    assert_int_equal(r[1], 0xff);
    assert_int_equal(r[5], 0x22);
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_true(hol_hid_pad_decode(&pad, r, sizeof ps4_usb_reports[2], &in));
    assert_float_equal(in.move[0], 0.7071, 1e-3); /* clipped to the unit disc */
    assert_float_equal(in.move[1], 0.7071, 1e-3); /* y 0 is up: forward */
    assert_true(in.turn[0] > 0.3f && in.turn[1] < -0.3f); /* left, down */
    assert_int_equal(pad.hat_dir, 2);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    /* a report of another ID is not the pad's; a short one changes nothing */
    uint8_t other[8] = {0x05};
    assert_false(hol_hid_pad_decode(&pad, other, sizeof other, &in));
    assert_false(hol_hid_pad_decode(&pad, r, 1, &in));
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
}

static void test_parse_items(void **state)
{
    (void)state;
    /* push, change, pop; a long item; usage range; padding */
    static const uint8_t d[] = {
        0x05, 0x01, 0x09, 0x05, 0xa1, 0x01,
        0x15, 0x00, 0x26, 0xff, 0x03, 0x75, 0x0a, 0x95, 0x01,
        0xa4,                   /* push */
        0x15, 0x81, 0x25, 0x7f, 0x75, 0x08,
        0x09, 0x30, 0x81, 0x02, /* X: 8 bits -127..127 at 0 */
        0xb4,                   /* pop */
        0xfe, 0x02, 0x10, 0xaa, 0xbb, /* long item, skipped */
        0x09, 0x31, 0x81, 0x02, /* Y: 10 bits 0..1023 at 8 */
        0x75, 0x06, 0x81, 0x03, /* constant padding */
        0x05, 0x09, 0x19, 0x01, 0x29, 0x03, 0x15, 0x00, 0x25, 0x01,
        0x75, 0x01, 0x95, 0x04, 0x81, 0x02, /* buttons 1, 2, 3, 3 at 24.. */
        0xc0};
    size_t n;
    int ids;
    assert_int_equal(hol_hid_desc_parse(d, sizeof d, map, 16, &n, &ids), HOL_OK);
    assert_int_equal(n, 6);
    assert_int_equal(ids, 0);
    assert_int_equal(map[0].usage, HOL_HID_USAGE(1, 0x30));
    assert_int_equal(map[0].logical_min, -127);
    assert_int_equal(map[0].size, 8);
    assert_int_equal(map[1].usage, HOL_HID_USAGE(1, 0x31));
    assert_int_equal(map[1].bit_offset, 8);
    assert_int_equal(map[1].size, 10);
    assert_int_equal(map[1].logical_max, 1023);
    assert_int_equal(map[1].kind, HOL_HID_AXIS);
    assert_int_equal(map[2].bit_offset, 24);
    assert_int_equal(map[2].kind, HOL_HID_BUTTON);
    assert_int_equal(map[4].usage, HOL_HID_USAGE(9, 3));
    assert_int_equal(map[5].usage, HOL_HID_USAGE(9, 3)); /* last repeats */
    assert_int_equal(map[5].application, HOL_HID_USAGE(1, 5));
    /* too small a map: ENOMEM with the count needed */
    assert_int_equal(hol_hid_desc_parse(d, sizeof d, map, 2, &n, &ids), HOL_ENOMEM);
    assert_int_equal(n, 6);
    /* every truncation inside the collection is rejected (cut items or
     * the collection left open) */
    for (size_t len = 5; len < sizeof d; len++)
        assert_int_not_equal(hol_hid_desc_parse(d, len, map, 16, &n, &ids), HOL_OK);
}

static void test_parse_errors(void **state)
{
    (void)state;
    static const struct { uint8_t b[8]; size_t len; } bad[] = {
        {{0x85, 0x00}, 2},             /* report ID 0 */
        {{0xb4}, 1},                   /* pop without push */
        {{0xc0}, 1},                   /* end collection without collection */
        {{0xa1, 0x01}, 2},             /* collection left open */
        {{0x75, 0x21, 0x95, 0x01, 0x81, 0x02}, 6}, /* 33-bit data field */
        {{0x96, 0x01, 0x40}, 3},       /* report count 16385 */
        {{0x26, 0xff}, 2},             /* truncated */
        {{0xa4, 0xa4, 0xa4, 0xa4, 0xa4}, 5}, /* push deeper than 4 */
        {{0x0c}, 1},                   /* reserved item type */
    };
    size_t n;
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        if (hol_hid_desc_parse(bad[i].b, bad[i].len, map, 16, &n, NULL) == HOL_OK)
            fail_msg("bad descriptor %zu accepted", i);
}

static void test_field_read(void **state)
{
    (void)state;
    hol_hid_field f = {.size = 12, .bit_offset = 4, .logical_min = -2048,
                       .logical_max = 2047};
    const uint8_t body[] = {0x50, 0xff, 0x12};
    int64_t v;
    assert_true(hol_hid_field_read(&f, body, 3, &v));
    assert_int_equal(v, -11); /* 0xff5 as signed 12 bits */
    f.logical_min = 0;
    assert_true(hol_hid_field_read(&f, body, 3, &v));
    assert_int_equal(v, 0xff5);
    f.bit_offset = 13;
    assert_false(hol_hid_field_read(&f, body, 3, &v)); /* past the end */
    hol_hid_field w = {.size = 32, .bit_offset = 0};
    const uint8_t b4[] = {0x78, 0x56, 0x34, 0x12};
    assert_true(hol_hid_field_read(&w, b4, 4, &v));
    assert_int_equal(v, 0x12345678);
}

/* Known pads: the table and the Switch Pro's fixed layout (its descriptor
 * does not describe report 0x30; the bytes below follow the layout the
 * Linux hid-nintendo driver reads - not a capture). */
static void test_known_pads(void **state)
{
    (void)state;
    assert_non_null(hol_hid_known_find(0x054c, 0x05c4));
    assert_non_null(hol_hid_known_find(0x054c, 0x0ce6));
    assert_null(hol_hid_known_find(0x06a3, 0xff0d));
    const hol_hid_known *k = hol_hid_known_find(0x057e, 0x2009);
    assert_non_null(k);
    assert_int_equal(k->start_kind, HOL_HID_START_OUTPUT);
    assert_int_equal(k->start[0], 0x80);
    static hol_hid_pad pad;
    assert_int_equal(hol_hid_pad_init(&pad, NULL, 0, 0, 0x057e, 0x2009, NULL), HOL_OK);
    /* A pressed (byte 3 bit 3), plus (byte 4 bit 1); left stick full right
     * (x 4095, y 2048), right stick full up (x 2048, y 4095) */
    uint8_t r[49] = {0x30, 0, 0x91, 0x08, 0x02, 0x00,
                     0xff, 0x0f, 0x80, 0x00, 0xf8, 0xff};
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_true(hol_hid_pad_decode(&pad, r, sizeof r, &in));
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM | HOL_BTN_MENU);
    assert_float_equal(in.move[0], 1.0, 1e-3);
    assert_float_equal(in.move[1], 0.0, 1e-3);
    assert_float_equal(in.turn[1], 1.0, 1e-3); /* look up */
    r[0] = 0x21;
    assert_false(hol_hid_pad_decode(&pad, r, sizeof r, &in));
}

/* Dead zone: a stick a little off centre reads zero; past it, the value
 * rises from zero continuously and reaches 1 at the edge. */
static void test_dead_zone(void **state)
{
    (void)state;
    size_t n;
    int ids;
    static hol_hid_pad pad;
    assert_int_equal(hol_hid_desc_parse(asus_desc, sizeof asus_desc, map, 16384,
                                        &n, &ids), HOL_OK);
    hol_hid_pad_desc pd = {.dead_zone = 0.25f};
    assert_int_equal(hol_hid_pad_init(&pad, map, n, ids, asus_vid, asus_pid, &pd),
                     HOL_OK);
    uint8_t r[sizeof asus_reports[0]];
    memcpy(r, asus_reports[0], sizeof r);
    hol_input in;
    float prev = 0;
    for (int x = 128; x <= 255; x++) {
        r[3] = (uint8_t)x; /* left x at byte 2 of the body */
        r[4] = 0x80;
        memset(&in, 0, sizeof in);
        assert_true(hol_hid_pad_decode(&pad, r, sizeof r, &in));
        if (x < 128 + 31)
            assert_true(in.move[0] == 0.0f);
        assert_true(in.move[0] >= prev && in.move[0] - prev < 0.02f);
        prev = in.move[0];
    }
    assert_float_equal(prev, 1.0, 1e-4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_samples_decode),
        cmocka_unit_test(test_ds4_known_report),
        cmocka_unit_test(test_parse_items),
        cmocka_unit_test(test_parse_errors),
        cmocka_unit_test(test_field_read),
        cmocka_unit_test(test_known_pads),
        cmocka_unit_test(test_dead_zone),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
