/* fuzz_hid_script.c - libFuzzer harness for the gamepad script parser
 * (platform/hid/hol_hid_script.h, `play --gamepad-replay`) and its
 * playback through the device layer.
 *
 * Input: script text. Checks: a parsed script's events stay in their
 * bounds (bytes inside the pool, times never going back, plug only while
 * unplugged); played back on the device layer at 20 polls a second until
 * a second past its last event (at most 4000 polls), every poll leaves the
 * axes in [-1, 1], only HOL_BTN_* pad roles, and HOL_INPUT_DEVICE_LOST
 * exactly when the poll fails.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "../platform/hid/hol_hid_dev.h"
#include "../platform/hid/hol_hid_script.h"

#include "fuzz_check.h"

static int in_unit(float v) { return isfinite(v) && v >= -1.0f && v <= 1.0f; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static hol_hid_script s;
    static hol_hid_dev dev;
    long line = 0;
    if (hol_hid_script_parse(&s, (const char *)data, size, &line)) {
        CHECK(line >= 1);
        return 0;
    }
    CHECK(s.n <= HOL_HID_SCRIPT_MAX_EVENTS && s.used <= HOL_HID_SCRIPT_MAX_BYTES);
    int plugged = 0;
    for (size_t i = 0; i < s.n; i++) {
        const hol_hid_script_event *e = &s.ev[i];
        CHECK(e->off + (size_t)e->len <= s.used);
        CHECK(i == 0 || e->t >= s.ev[i - 1].t);
        CHECK(e->kind == HOL_HID_SCRIPT_PLUG ? !plugged : plugged);
        if (e->kind == HOL_HID_SCRIPT_PLUG) {
            CHECK(e->len >= 1 && e->len <= HOL_HID_DESC_MAX);
            plugged = 1;
        } else if (e->kind == HOL_HID_SCRIPT_UNPLUG)
            plugged = 0;
        else
            CHECK(e->kind == HOL_HID_SCRIPT_REPORT && e->len >= 1 &&
                  e->len <= HOL_HID_REPORT_MAX_BYTES);
    }
    double end = s.n ? s.ev[s.n - 1].t + 1.0 : 1.0;
    hol_hid_dev_open_backend(&dev, hol_hid_script_backend(&s), 0.0);
    for (int k = 0; k < 4000 && k * 0.05 <= end; k++) {
        hol_input in;
        memset(&in, 0, sizeof in);
        in.time_s = k * 0.05;
        hol_err err = hol_hid_dev_poll(&dev, &in);
        CHECK(!err == !(in.flags & HOL_INPUT_DEVICE_LOST));
        for (int a = 0; a < 2; a++)
            CHECK(in_unit(in.move[a]) && in_unit(in.turn[a]));
        CHECK(!(in.buttons & ~(uint32_t)(HOL_BTN_CONFIRM | HOL_BTN_BACK | HOL_BTN_MENU |
                                         HOL_BTN_RECENTRE | HOL_BTN_MINIMAP)));
    }
    hol_hid_dev_close(&dev);
    CHECK(!s.open);
    return 0;
}
