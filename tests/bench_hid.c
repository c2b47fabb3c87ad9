/* bench_hid.c - cost of the gamepad decoding (make bench). Prints figures;
 * asserts nothing about time. Per real pad of tests/hid_samples.h: the
 * report decoder (hol_hid_pad_decode) per report in ns, cycling through
 * the pad's five sample reports, and the descriptor parse per descriptor
 * in us. Then the device layer (hol_hid_dev.h) in play's frame loop: a
 * poll that reads one report (the Asus pad on the scripted backend), and
 * what a poll costs once a second while no pad is plugged in: the
 * re-enumeration through hidapi (this machine has no HID devices, so a
 * lower bound). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "../platform/hid/hol_hid_desc.h"
#include "../platform/hid/hol_hid_dev.h"
#include "../platform/hid/hol_hid_pad.h"
#include "../platform/hid/hol_hid_script.h"
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

    /* a poll with one report waiting: the stick toggling every poll */
    static hol_hid_script sc;
    static char text[1 << 20];
    size_t len = (size_t)snprintf(text, sizeof text, "0 plug %04x:%04x ", asus_vid, asus_pid);
    for (size_t i = 0; i < sizeof asus_desc; i++)
        len += (size_t)snprintf(text + len, sizeof text - len, "%02x", asus_desc[i]);
    long polls = 10000;
    for (long k = 0; k < polls; k++) {
        len += (size_t)snprintf(text + len, sizeof text - len, "\n%ld report ", k);
        for (int i = 0; i < 9; i++)
            len += (size_t)snprintf(text + len, sizeof text - len, "%02x", asus_reports[k % 2][i]);
    }
    static hol_hid_dev dev;
    if (hol_hid_script_parse(&sc, text, len, NULL) ||
        hol_hid_dev_open_backend(&dev, hol_hid_script_backend(&sc), 0)) {
        printf("scripted pad: cannot open\n");
        return 1;
    }
    hol_input in;
    long left = 0;
    double t0 = now_ns();
    for (long k = 0; k < polls; k++) {
        memset(&in, 0, sizeof in);
        in.time_s = (double)k;
        hol_hid_dev_poll(&dev, &in);
        left += in.move[0] < -0.5f;
    }
    printf("device layer: a frame's poll with one report (scripted Asus): %6.1f ns "
           "(stick left in %ld of %ld)\n", (now_ns() - t0) / polls, left, polls);
    hol_hid_dev_close(&dev);
    /* no pad: the once-a-second re-enumeration of a poll */
    int n = 200;
    t0 = now_ns();
    for (int k = 0; k < n; k++)
        if (hol_hid_dev_open_first(&dev) == HOL_OK)
            hol_hid_dev_close(&dev);
    printf("device layer: re-enumeration with no pad (hidapi %s, once a second): %6.1f us\n",
           hol_hid_dev_backend(), (now_ns() - t0) / n / 1e3);
    return 0;
}
