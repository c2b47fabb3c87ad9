/* test_hid_dev.c - the gamepad device layer up to the hardware boundary.
 *
 * This machine has no /dev/hidraw and no uhid, so platform/hid/hol_hid_dev.c
 * is compiled unchanged against a scripted hidapi (the functions below,
 * declared by tests/fake_hidapi/hidapi/hidapi.h as hidapi 0.14 declares
 * them). The scripted device is the Asus gamepad recorded by hid-tools
 * (tests/hid_samples.h: its real descriptor and reports). Checked: the
 * first controller is found and its reports decoded (the same result as
 * the decoder given the same bytes); reads drain and never block; an
 * unplug mid-game sets HOL_INPUT_DEVICE_LOST and zeroes the input without
 * a crash; re-enumeration waits HOL_HID_REENUM_S and picks the pad up when
 * it is plugged back (hot-plug); a non-controller is ignored. Then the
 * link (platform/hid/hol_hid_link.h) as `holonomy play` uses it: keyboard
 * and pad merged, an unplug pauses the app, the keyboard resumes it, and
 * the left stick walks a room step through the app step.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include <hidapi/hidapi.h>

#include "../core/hol_app.h"
#include "../platform/hid/hol_hid_dev.h"
#include "../platform/hid/hol_hid_link.h"
#include "../platform/hid/hol_hid_script.h"
#include "hid_samples.h"

/* ---- the scripted hidapi ------------------------------------------------ */

static struct {
    int present;        /* the pad is plugged in */
    int other;          /* a keyboard-like HID device is plugged in too */
    int open;           /* handles open */
    int enumerations;
    int fail_reads;     /* the next reads fail (unplugged while open) */
    uint8_t queue[16][64];
    size_t qlen[16];
    int qn, qhead;
} fake;

struct hid_device_ {
    int unused;
};
static struct hid_device_ the_handle;

int hid_init(void) { return 0; }

struct hid_device_info *hid_enumerate(unsigned short vendor_id, unsigned short product_id)
{
    (void)vendor_id;
    (void)product_id;
    static struct hid_device_info kbd, pad;
    static wchar_t name[] = L"Asus gamepad";
    fake.enumerations++;
    struct hid_device_info *head = NULL;
    if (fake.present) {
        memset(&pad, 0, sizeof pad);
        pad.path = "/dev/hidraw-fake1";
        pad.vendor_id = asus_vid;
        pad.product_id = asus_pid;
        pad.usage_page = 0x01;
        pad.usage = 0x05;
        pad.product_string = name;
        head = &pad;
    }
    if (fake.other) {
        memset(&kbd, 0, sizeof kbd);
        kbd.path = "/dev/hidraw-fake0";
        kbd.usage_page = 0x01;
        kbd.usage = 0x06; /* a keyboard: not a game controller */
        kbd.next = head;
        head = &kbd;
    }
    return head;
}

void hid_free_enumeration(struct hid_device_info *devs) { (void)devs; }

hid_device *hid_open_path(const char *path)
{
    if (!fake.present || strcmp(path, "/dev/hidraw-fake1"))
        return NULL;
    fake.open++;
    return &the_handle;
}

void hid_close(hid_device *dev)
{
    assert_ptr_equal(dev, &the_handle);
    fake.open--;
}

int hid_set_nonblocking(hid_device *dev, int nonblock)
{
    (void)dev;
    assert_int_equal(nonblock, 1); /* the frame loop must never block */
    return 0;
}

int hid_read_timeout(hid_device *dev, unsigned char *data, size_t length, int milliseconds)
{
    (void)dev;
    assert_int_equal(milliseconds, 0);
    if (fake.fail_reads)
        return -1;
    if (fake.qhead == fake.qn)
        return 0;
    size_t n = fake.qlen[fake.qhead] < length ? fake.qlen[fake.qhead] : length;
    memcpy(data, fake.queue[fake.qhead++], n);
    return (int)n;
}

int hid_write(hid_device *dev, const unsigned char *data, size_t length)
{
    (void)dev;
    (void)data;
    return (int)length;
}

int hid_get_feature_report(hid_device *dev, unsigned char *data, size_t length)
{
    (void)dev;
    (void)data;
    return (int)length;
}

int hid_get_report_descriptor(hid_device *dev, unsigned char *buf, size_t buf_size)
{
    (void)dev;
    if (buf_size < sizeof asus_desc)
        return -1;
    memcpy(buf, asus_desc, sizeof asus_desc);
    return (int)sizeof asus_desc;
}

static void queue_report(int r)
{
    assert_true(fake.qn < 16);
    memcpy(fake.queue[fake.qn], asus_reports[r], sizeof asus_reports[r]);
    fake.qlen[fake.qn++] = sizeof asus_reports[r];
}

static int reset(void **state)
{
    (void)state;
    memset(&fake, 0, sizeof fake);
    return 0;
}

/* What the decoder alone makes of report r (the device layer must pass the
 * bytes through unchanged). */
static hol_input decoded(int r)
{
    static hol_hid_field fields[HOL_HID_DEV_MAX_FIELDS];
    size_t n = 0;
    int ids = 0;
    assert_int_equal(hol_hid_desc_parse(asus_desc, sizeof asus_desc, fields,
                                        HOL_HID_DEV_MAX_FIELDS, &n, &ids), HOL_OK);
    static hol_hid_pad pad;
    assert_int_equal(hol_hid_pad_init(&pad, fields, n, ids, asus_vid, asus_pid, NULL), HOL_OK);
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_pad_decode(&pad, asus_reports[r], sizeof asus_reports[r], &in), 1);
    return in;
}

static hol_hid_dev dev;

/* ---- the device layer ---------------------------------------------------- */

static void test_no_controller(void **state)
{
    (void)state;
    fake.other = 1;
    assert_int_equal(hol_hid_dev_open_first(&dev), HOL_EOPEN);
    assert_int_equal(fake.open, 0);
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_EIO);
    assert_int_equal(dev.lost, 0); /* never had one: nothing was lost */
}

static void test_reports_drained_and_decoded(void **state)
{
    (void)state;
    fake.present = fake.other = 1;
    assert_int_equal(hol_hid_dev_open_first(&dev), HOL_OK);
    assert_int_equal(dev.info.vid, asus_vid);
    assert_int_equal(fake.open, 1);
    queue_report(1);
    queue_report(2); /* two waiting: the last state wins */
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_int_equal(fake.qhead, 2);
    hol_input want = decoded(2);
    assert_memory_equal(in.move, want.move, sizeof in.move);
    assert_memory_equal(in.turn, want.turn, sizeof in.turn);
    assert_int_equal(in.buttons, want.buttons);
    assert_true(in.move[0] > 0.5f && in.move[1] > 0.5f); /* right and forward */
    /* nothing waiting: the state stays, the poll does not block */
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_memory_equal(in.move, want.move, sizeof in.move);
    hol_hid_dev_close(&dev);
    assert_int_equal(fake.open, 0);
}

static void test_unplug_and_hot_plug(void **state)
{
    (void)state;
    fake.present = 1;
    assert_int_equal(hol_hid_dev_open_first(&dev), HOL_OK);
    queue_report(2);
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = 1.0;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    /* unplugged mid-game */
    fake.fail_reads = 1;
    fake.present = 0;
    memset(&in, 0, sizeof in);
    in.time_s = 2.0;
    in.move[0] = 0.7f;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_EIO);
    assert_true(in.flags & HOL_INPUT_DEVICE_LOST);
    assert_true(in.move[0] == 0.0f && in.buttons == 0);
    assert_int_equal(dev.lost, 1);
    assert_int_equal(fake.open, 0); /* the handle was closed */
    fake.fail_reads = 0;
    int e0 = fake.enumerations;
    /* within HOL_HID_REENUM_S: no re-enumeration */
    memset(&in, 0, sizeof in);
    in.time_s = 2.5;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_EIO);
    assert_int_equal(fake.enumerations, e0);
    /* later, still unplugged: one try, still lost */
    in.time_s = 3.1;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_EIO);
    assert_int_equal(fake.enumerations, e0 + 1);
    /* plugged back: picked up at the next try */
    fake.present = 1;
    queue_report(3);
    memset(&in, 0, sizeof in);
    in.time_s = 3.5;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_EIO); /* too soon */
    in.time_s = 4.2;
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_false(in.flags & HOL_INPUT_DEVICE_LOST);
    assert_int_equal(dev.lost, 0);
    hol_input want = decoded(3);
    assert_memory_equal(in.move, want.move, sizeof in.move);
    hol_hid_dev_close(&dev);
}

/* A button pressed and let go between two polls (two reports waiting) is
 * not held, but pressed: the app acts on the tap. A held button is pressed
 * once, at the poll where it went down. */
static void test_tap_between_polls(void **state)
{
    (void)state;
    fake.present = 1;
    assert_int_equal(hol_hid_dev_open_first(&dev), HOL_OK);
    queue_report(0);
    hol_input in;
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_int_equal(in.buttons | in.pressed, 0);
    queue_report(1); /* south (confirm) down ... */
    queue_report(0); /* ... and up again before the frame */
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_int_equal(in.buttons, 0);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    queue_report(1); /* held over two polls: pressed at the first only */
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, HOL_BTN_CONFIRM);
    memset(&in, 0, sizeof in);
    assert_int_equal(hol_hid_dev_poll(&dev, &in), HOL_OK);
    assert_int_equal(in.buttons, HOL_BTN_CONFIRM);
    assert_int_equal(in.pressed, 0);
    hol_hid_dev_close(&dev);
}

/* ---- the link, as holonomy play uses it --------------------------------- */

static void test_link_merge(void **state)
{
    (void)state;
    hol_hid_link l;
    memset(&l, 0, sizeof l);
    hol_input pad, io;
    memset(&pad, 0, sizeof pad);
    /* never a pad: the keyboard's input as it was */
    memset(&io, 0, sizeof io);
    io.move[1] = 1;
    hol_hid_link_merge(&l, HOL_EIO, 0, &pad, 0, &io);
    assert_true(io.move[1] == 1.0f && io.flags == 0);
    /* a pad: axes add and clamp, buttons OR */
    pad.move[1] = 0.5f;
    pad.turn[0] = -0.25f;
    pad.buttons = HOL_BTN_CONFIRM;
    memset(&io, 0, sizeof io);
    io.move[1] = 1;
    io.turn[0] = 0.5f;
    io.buttons = HOL_BTN_MENU;
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 1, &io);
    assert_true(io.move[1] == 1.0f && io.turn[0] == 0.25f);
    assert_int_equal(io.buttons, HOL_BTN_CONFIRM | HOL_BTN_MENU);
    /* unplugged: the app is told, frame after frame */
    for (int k = 0; k < 3; k++) {
        memset(&io, 0, sizeof io);
        hol_hid_link_merge(&l, HOL_EIO, 1, &pad, 0, &io);
        assert_true(io.flags & HOL_INPUT_DEVICE_LOST);
    }
    /* a key: the keyboard takes over */
    memset(&io, 0, sizeof io);
    hol_hid_link_merge(&l, HOL_EIO, 1, &pad, 1, &io);
    assert_false(io.flags & HOL_INPUT_DEVICE_LOST);
    memset(&io, 0, sizeof io);
    hol_hid_link_merge(&l, HOL_EIO, 1, &pad, 0, &io);
    assert_false(io.flags & HOL_INPUT_DEVICE_LOST);
    /* plugged in again: joins */
    memset(&io, 0, sizeof io);
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io);
    assert_true(io.move[1] == 0.5f);
}

/* The device in use: the keyboard's until the pad is used, the pad's until
 * a key is; pressed buttons (taps) merge like held ones. */
static void test_link_device(void **state)
{
    (void)state;
    hol_hid_link l;
    memset(&l, 0, sizeof l);
    hol_input pad, io;
    memset(&pad, 0, sizeof pad);
    memset(&io, 0, sizeof io);
    io.device = HOL_DEVICE_KEYBOARD;
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io); /* a pad at rest */
    assert_int_equal(io.device, HOL_DEVICE_KEYBOARD);
    pad.pressed = HOL_BTN_CONFIRM; /* a tap on the pad */
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io);
    assert_int_equal(io.device, HOL_DEVICE_GAMEPAD);
    assert_int_equal(io.pressed, HOL_BTN_CONFIRM);
    memset(&pad, 0, sizeof pad);
    memset(&io, 0, sizeof io);
    io.device = HOL_DEVICE_KEYBOARD;
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io); /* idle: still the pad */
    assert_int_equal(io.device, HOL_DEVICE_GAMEPAD);
    pad.move[0] = 0.5f;
    memset(&io, 0, sizeof io);
    io.device = HOL_DEVICE_KEYBOARD;
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 1, &io); /* a key: the keyboard */
    assert_int_equal(io.device, HOL_DEVICE_KEYBOARD);
    memset(&pad, 0, sizeof pad);
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io);
    assert_int_equal(io.device, HOL_DEVICE_KEYBOARD);
    pad.turn[1] = -1;
    hol_hid_link_merge(&l, HOL_OK, 0, &pad, 0, &io); /* the stick: the pad */
    assert_int_equal(io.device, HOL_DEVICE_GAMEPAD);
    memset(&io, 0, sizeof io);
    io.device = HOL_DEVICE_KEYBOARD;
    hol_hid_link_merge(&l, HOL_EIO, 1, &pad, 0, &io); /* unplugged: not the pad */
    assert_int_equal(io.device, HOL_DEVICE_KEYBOARD);
}

/* An app playing an explore level (seed 4, every cue). */
static hol_app *explore_app(void)
{
    hol_app *app;
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    assert_int_equal(hol_app_create(&ad, &app), HOL_OK);
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.seed = 4;
    L.cues = HOL_CUE_ALL;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    return app;
}

/* One frame of play's loop with no key: poll the pad, merge, step; the
 * room steps taken. */
static int play_frame(hol_app *app, hol_hid_link *l, double t)
{
    hol_input in, pad;
    memset(&in, 0, sizeof in);
    memset(&pad, 0, sizeof pad);
    in.time_s = pad.time_s = t;
    in.flags = HOL_INPUT_FOCUSED;
    hol_err e = hol_hid_dev_poll(&dev, &pad);
    hol_hid_link_merge(l, e, dev.lost, &pad, 0, &in);
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    return hol_app_get_events(app)->nsteps;
}

/* The pad walks: the left stick held left, through the device layer, the
 * link and the app step, crosses into the cell west (a room step); an
 * unplug pauses the app (the level clock stops); the keyboard resumes. */
static void test_stick_walks_and_unplug_pauses(void **state)
{
    (void)state;
    hol_app *app = explore_app();
    fake.present = 1;
    assert_int_equal(hol_hid_dev_open_first(&dev), HOL_OK);
    hol_hid_link l;
    memset(&l, 0, sizeof l);
    queue_report(1); /* left stick full left (and button 1): strafe west */
    double t = 0;
    int steps = 0;
    for (int f = 0; f < 120; f++, t += 1.0 / 60)
        steps += play_frame(app, &l, t);
    const hol_app_view *v = hol_app_get_view(app);
    assert_true(steps >= 1);
    assert_int_equal(v->user.col, 0); /* walked a cell west */
    assert_int_equal(v->user.row, 1);
    assert_int_equal(v->hud.steps, steps);
    /* unplug: paused, the clock stops */
    fake.fail_reads = 1;
    double clock = v->hud.elapsed_s;
    for (int f = 0; f < 30; f++, t += 1.0 / 60)
        play_frame(app, &l, t);
    assert_true(v->paused);
    assert_true(v->hud.elapsed_s == clock);
    /* a key: playing again */
    hol_input in, pad;
    memset(&in, 0, sizeof in);
    memset(&pad, 0, sizeof pad);
    in.time_s = pad.time_s = t + 0.1;
    in.flags = HOL_INPUT_FOCUSED;
    in.move[1] = 1;
    hol_err e = hol_hid_dev_poll(&dev, &pad);
    hol_hid_link_merge(&l, e, dev.lost, &pad, 1, &in);
    assert_int_equal(hol_app_step(app, &in), HOL_OK);
    assert_false(v->paused);
    hol_hid_dev_close(&dev);
    hol_app_destroy(app);
}


/* ---- the scripted backend (hol_hid_script.h, play --gamepad-replay) ------ */

static hol_hid_script script;

/* "T report HEX" of Asus report r, appended to text. */
static void add_hex(char *text, size_t cap, const uint8_t *b, size_t n)
{
    for (size_t i = 0; i < n; i++)
        snprintf(text + strlen(text), cap - strlen(text), "%02x", b[i]);
    snprintf(text + strlen(text), cap - strlen(text), "\n");
}

static void add_report(char *text, size_t cap, double t, int r)
{
    snprintf(text + strlen(text), cap - strlen(text), "%.2f report ", t);
    add_hex(text, cap, asus_reports[r], sizeof asus_reports[r]);
}

/* The recorded Asus pad: plugged at 0 with the left stick held left,
 * centred at 1.9, unplugged at 2, plugged back at 3.5 (stick centred). */
static const char *asus_script(void)
{
    static char text[8192];
    snprintf(text, sizeof text, "# the Asus gamepad (hid-tools)\r\n\n0 plug %04x:%04x ", asus_vid,
             asus_pid);
    add_hex(text, sizeof text, asus_desc, sizeof asus_desc);
    add_report(text, sizeof text, 0, 1);
    add_report(text, sizeof text, 1.9, 0);
    snprintf(text + strlen(text), sizeof text - strlen(text), "2 unplug\n3.5 plug\n");
    add_report(text, sizeof text, 3.6, 0);
    return text;
}

static void test_script_parse(void **state)
{
    (void)state;
    const char *t = asus_script();
    long line = -1;
    assert_int_equal(hol_hid_script_parse(&script, t, strlen(t), &line), HOL_OK);
    assert_int_equal(script.n, 6);
    assert_int_equal(script.ev[0].kind, HOL_HID_SCRIPT_PLUG);
    assert_int_equal(script.ev[0].vid, asus_vid);
    assert_int_equal(script.ev[0].len, sizeof asus_desc);
    assert_memory_equal(script.bytes + script.ev[0].off, asus_desc, sizeof asus_desc);
    assert_int_equal(script.ev[1].len, sizeof asus_reports[1]);
    assert_memory_equal(script.bytes + script.ev[1].off, asus_reports[1], 9);
    assert_true(script.ev[2].t == 1.9);
    assert_int_equal(script.ev[4].kind, HOL_HID_SCRIPT_PLUG); /* the same pad again */
    assert_int_equal(script.ev[4].off, script.ev[0].off);
    assert_true(script.ev[4].t == 3.5);
    /* refused, with the line */
    static const struct {
        const char *text;
        long line;
    } bad[] = {
        {"0 report 01\n", 1},                          /* not plugged */
        {"0 plug\n", 1},                               /* no pad yet */
        {"# c\n0 plug 0001:0002 0501\n0 plug\n", 3},   /* plugged twice */
        {"0 plug 0001:0002 0501\n0 unplug\n1 unplug\n", 3},
        {"0 plug 0001:0002 0501\n2 report 01\n1 report 02\n", 3}, /* time back */
        {"0 plug 0001:0002\n", 1},                     /* no descriptor */
        {"0 plug 001:0002 05\n", 1},
        {"0 plug 0001:0002 0\n", 1},                   /* odd digits */
        {"0 plug 0001:0002 05  01\n", 1},              /* two spaces */
        {"0 plug 0001:0002 05 \n", 1},
        {"0 plug 0001:0002 0g\n", 1},
        {"0 plug 0001:0002 05\n1 report\n", 2},
        {"0 plug 0001:0002 05\n1 report \n", 2},
        {"0 plug 0001:0002 05\n1 unplug now\n", 2},
        {"0 plug 0001:0002 05\n1 jump\n", 2},
        {"-1 plug 0001:0002 05\n", 1},
        {"1e3 plug 0001:0002 05\n", 1},
        {"0x1 plug 0001:0002 05\n", 1},
        {"1. plug 0001:0002 05\n", 1},
        {" 0 plug 0001:0002 05\n", 1},
        {"0  plug 0001:0002 05\n", 1},
        {"0 plugs 0001:0002 05\n", 1},
        {"0\n", 1},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        line = -1;
        assert_int_equal(hol_hid_script_parse(&script, bad[i].text, strlen(bad[i].text), &line),
                         HOL_EPARSE);
        if (line != bad[i].line)
            fail_msg("'%s': line %ld, want %ld", bad[i].text, line, bad[i].line);
    }
    /* a report longer than the largest report */
    static char big[2 * HOL_HID_REPORT_MAX_BYTES + 64];
    snprintf(big, sizeof big, "0 plug 0001:0002 05\n1 report ");
    for (int i = 0; i <= HOL_HID_REPORT_MAX_BYTES; i++)
        strcat(big, "01");
    assert_int_equal(hol_hid_script_parse(&script, big, strlen(big), &line), HOL_EPARSE);
    assert_int_equal(line, 2);
    assert_int_equal(hol_hid_script_parse(&script, "", 0, &line), HOL_OK);
    assert_int_equal(script.n, 0);
}

/* The same device layer on the script: connect, the stick walks a room
 * step, the unplug pauses (the clock stops, no crash, polls keep
 * failing), the replug is found by re-enumeration within a second and
 * resumes the game with no key pressed. */
static void test_script_plays(void **state)
{
    (void)state;
    const char *t = asus_script();
    assert_int_equal(hol_hid_script_parse(&script, t, strlen(t), NULL), HOL_OK);
    hol_app *app = explore_app();
    assert_int_equal(hol_hid_dev_open_backend(&dev, hol_hid_script_backend(&script), 0),
                     HOL_OK);
    assert_int_equal(dev.info.vid, asus_vid);
    hol_hid_link l;
    memset(&l, 0, sizeof l);
    const hol_app_view *v = hol_app_get_view(app);
    int f = 0;
    for (; f < 120; f++) /* 0 .. 2 s */
        play_frame(app, &l, f / 60.0);
    assert_true(v->hud.steps >= 1);
    assert_int_equal(v->user.col, 0); /* walked a cell west */
    assert_int_equal(v->user.row, 1);
    assert_false(v->paused);
    double clock = v->hud.elapsed_s;
    assert_true(clock > 1.9);
    for (; f < 210; f++) { /* 2 .. 3.5 s: unplugged */
        play_frame(app, &l, f / 60.0);
        assert_true(v->paused);
        assert_true(dev.handle == NULL && dev.lost);
        assert_string_equal(v->hud.status, "Controller lost");
    }
    assert_true(v->hud.elapsed_s == clock);
    int back = -1;
    for (; f < 330; f++) { /* 3.5 .. 5.5 s: plugged back */
        play_frame(app, &l, f / 60.0);
        if (back < 0 && !v->paused)
            back = f;
    }
    /* found by the first re-enumeration at or after 3.5 s (one a second
     * from the unplug at 2 s: 3, 4, ...) */
    assert_int_equal(back, 240);
    assert_true(dev.handle != NULL);
    assert_true(v->hud.elapsed_s > clock + 1.4);
    assert_int_equal(v->user.col, 0); /* the stick is centred: no more walking */
    hol_hid_dev_close(&dev);
    assert_int_equal(script.open, 0);
    hol_app_destroy(app);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_no_controller, reset),
        cmocka_unit_test_setup(test_reports_drained_and_decoded, reset),
        cmocka_unit_test_setup(test_unplug_and_hot_plug, reset),
        cmocka_unit_test_setup(test_tap_between_polls, reset),
        cmocka_unit_test_setup(test_link_merge, reset),
        cmocka_unit_test_setup(test_link_device, reset),
        cmocka_unit_test_setup(test_stick_walks_and_unplug_pauses, reset),
        cmocka_unit_test_setup(test_script_parse, reset),
        cmocka_unit_test_setup(test_script_plays, reset),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
