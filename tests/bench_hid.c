/* bench_hid.c - cost of the gamepad decoding (make bench). Prints figures;
 * asserts nothing about time. Per real pad of tests/hid_samples.h: the
 * report decoder (hol_hid_pad_decode) per report in ns, cycling through
 * the pad's five sample reports, and the descriptor parse per descriptor
 * in us. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../platform/hid/hol_hid_desc.h"
#include "../platform/hid/hol_hid_pad.h"
#include "hid_samples.h"

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e9 + ts.tv_nsec;
}

static hol_hid_field map[16384];
static volatile float sink;

static void bench(const char *name, const uint8_t *desc, size_t dlen,
                  const uint8_t *reports, size_t rlen, uint16_t vid, uint16_t pid)
{
    size_t n = 0;
    int ids = 0;
    long np = 2000;
    double t0 = now_ns();
    for (long i = 0; i < np; i++)
        hol_hid_desc_parse(desc, dlen, map, sizeof map / sizeof map[0], &n, &ids);
    double parse_us = (now_ns() - t0) / np / 1e3;
    static hol_hid_pad pad;
    if (hol_hid_pad_init(&pad, map, n, ids, vid, pid, NULL)) {
        printf("%-8s no pad\n", name);
        return;
    }
    hol_input in;
    memset(&in, 0, sizeof in);
    long nr = 2000000;
    t0 = now_ns();
    for (long i = 0; i < nr; i++) {
        hol_hid_pad_decode(&pad, reports + (size_t)(i % 5) * rlen, rlen, &in);
        sink += in.move[0];
    }
    double ns = (now_ns() - t0) / nr;
    printf("%-8s %5zu B desc %4zu fields parse %7.2f us | %3zu B report, %2d buttons: decode %6.1f ns\n",
           name, dlen, n, parse_us, rlen, pad.n_buttons, ns);
}

#define B(x) bench(#x, x##_desc, sizeof x##_desc, &x##_reports[0][0], \
                   sizeof x##_reports[0], x##_vid, x##_pid)

int main(void)
{
    printf("bench_hid: HID descriptor parse and report decode (one core)\n");
    B(saitek);
    B(asus);
    B(raptor);
    B(ps3);
    B(ps4_usb);
    B(ps4_bt);
    B(ps5_usb);
    B(ps5_bt);
    return 0;
}
