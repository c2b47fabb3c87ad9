/* hol_hid_pad.c - input reports to hol_input (see hol_hid_pad.h). */
#include "hol_hid_pad.h"

#include <math.h>
#include <string.h>

#include "../shell/hol_shell_stick.h"

/* Generic pads: Linux's gamepad button order (south, east, C, north,
 * west, Z, TL, TR, TL2, TR2, select, start, mode, thumbl, thumbr). */
static const uint32_t generic_roles[HOL_HID_PAD_MAX_BUTTONS] = {
    [0] = HOL_BTN_CONFIRM, [1] = HOL_BTN_BACK, [3] = HOL_BTN_RECENTRE,
    [4] = HOL_BTN_MINIMAP, [10] = HOL_BTN_MINIMAP, [11] = HOL_BTN_MENU,
    [12] = HOL_BTN_MENU,
};
/* DualShock 4, DualSense: square, cross, circle, triangle, L1, R1, L2, R2,
 * share/create, options, L3, R3, PS, touchpad. */
static const uint32_t sony_roles[HOL_HID_PAD_MAX_BUTTONS] = {
    [0] = HOL_BTN_RECENTRE, [1] = HOL_BTN_CONFIRM, [2] = HOL_BTN_BACK,
    [3] = HOL_BTN_MINIMAP, [8] = HOL_BTN_MINIMAP, [9] = HOL_BTN_MENU,
    [12] = HOL_BTN_MENU,
};
/* Sixaxis (PS3): select, L3, R3, start, up, right, down, left, L2, R2,
 * L1, R1, triangle, circle, cross, square, PS. */
static const uint32_t ps3_roles[HOL_HID_PAD_MAX_BUTTONS] = {
    [0] = HOL_BTN_MINIMAP, [3] = HOL_BTN_MENU, [4] = HOL_BTN_RECENTRE,
    [6] = HOL_BTN_MINIMAP, [12] = HOL_BTN_MINIMAP, [13] = HOL_BTN_BACK,
    [14] = HOL_BTN_CONFIRM, [15] = HOL_BTN_RECENTRE, [16] = HOL_BTN_MENU,
};
/* Sixaxis over USB sends nothing until feature report 0xf2 is read. */
static const uint8_t ps3_start[] = {0xf2};
/* Switch Pro over USB: handshake, USB HID only, then subcommand 0x03
 * "input report mode 0x30" (with a neutral rumble). Zero-padded to 12. */
static const uint8_t switch_start[] = {
    0x80, 0x02, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0x80, 0x04, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0x01, 0x00, 0x00, 0x01, 0x40, 0x40, 0x00, 0x01, 0x40, 0x40, 0x03, 0x30,
};

/* A Sony pad after the DualShock 3: its descriptor's layout, no start
 * report, the Sony roles. */
#define HOL__SONY_PAD(pid, name)                                                           \
    {0x054c, pid, name, HOL_HID_LAYOUT_DESCRIPTOR, HOL_HID_START_NONE, 0, 0, NULL, sony_roles}

static const hol_hid_known known_pads[] = {
    {0x054c, 0x0268, "Sony Sixaxis / DualShock 3", HOL_HID_LAYOUT_DESCRIPTOR,
     HOL_HID_START_FEATURE, 17, 1, ps3_start, ps3_roles},
    HOL__SONY_PAD(0x05c4, "Sony DualShock 4"),
    HOL__SONY_PAD(0x09cc, "Sony DualShock 4 (2nd gen)"),
    HOL__SONY_PAD(0x0ce6, "Sony DualSense"),
    HOL__SONY_PAD(0x0df2, "Sony DualSense Edge"),
    {0x057e, 0x2009, "Nintendo Switch Pro Controller", HOL_HID_LAYOUT_SWITCH_PRO,
     HOL_HID_START_OUTPUT, 12, 3, switch_start, NULL},
};

const hol_hid_known *hol_hid_known_find(uint16_t vid, uint16_t pid)
{
    for (size_t i = 0; i < sizeof known_pads / sizeof known_pads[0]; i++)
        if (known_pads[i].vid == vid && known_pads[i].pid == pid)
            return &known_pads[i];
    return NULL;
}

/* Axis role of a usage in order of preference (lower is better), or -1. */
static int axis_role(uint32_t usage, int *out_rank)
{
    static const struct { uint32_t usage; int role, rank; } t[] = {
        {HOL_HID_USAGE(1, 0x30), HOL_HID_LX, 0},
        {HOL_HID_USAGE(1, 0x31), HOL_HID_LY, 0},
        {HOL_HID_USAGE(1, 0x32), HOL_HID_RX, 0},
        {HOL_HID_USAGE(1, 0x35), HOL_HID_RY, 0},
        {HOL_HID_USAGE(1, 0x33), HOL_HID_RX, 1},
        {HOL_HID_USAGE(1, 0x34), HOL_HID_RY, 1},
        {HOL_HID_USAGE(2, 0xba), HOL_HID_RX, 2},
        {HOL_HID_USAGE(2, 0xbb), HOL_HID_RY, 2},
    };
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        if (t[i].usage == usage) {
            *out_rank = t[i].rank;
            return t[i].role;
        }
    return -1;
}

static int is_pad_application(uint32_t app)
{
    return app == HOL_HID_USAGE(1, 0x04) || app == HOL_HID_USAGE(1, 0x05) ||
           app == HOL_HID_USAGE(1, 0x08);
}

hol_err hol_hid_pad_init(hol_hid_pad *pad, const hol_hid_field *fields,
                         size_t n, int has_ids, uint16_t vid, uint16_t pid,
                         const hol_hid_pad_desc *desc)
{
    memset(pad, 0, sizeof *pad);
    pad->known = hol_hid_known_find(vid, pid);
    pad->has_ids = has_ids;
    pad->dead_zone = desc && desc->dead_zone > 0 && desc->dead_zone < 1
                         ? desc->dead_zone : 0.15f;
    pad->hat_dir = -1;
    if (pad->known && pad->known->layout == HOL_HID_LAYOUT_SWITCH_PRO) {
        pad->has_ids = 1;
        return HOL_OK;
    }
    /* fields of a game controller collection win over others */
    int has_pad_app = 0;
    for (size_t i = 0; i < n; i++)
        has_pad_app |= is_pad_application(fields[i].application);
    int rank[HOL_HID_AXES] = {99, 99, 99, 99};
    for (size_t i = 0; i < n; i++) {
        const hol_hid_field *f = &fields[i];
        if (has_pad_app && !is_pad_application(f->application))
            continue;
        if ((f->flags & (HOL_HID_F_ARRAY | HOL_HID_F_RELATIVE)) ||
            f->logical_max <= f->logical_min)
            continue;
        int r, role = axis_role(f->usage, &r);
        if (role >= 0 && r < rank[role]) {
            rank[role] = r;
            pad->axis[role] = *f;
            pad->has_axis[role] = 1;
        } else if (f->kind == HOL_HID_HAT && !pad->has_hat) {
            pad->hat = *f;
            pad->has_hat = 1;
        } else if (f->kind == HOL_HID_BUTTON &&
                   pad->n_buttons < HOL_HID_PAD_MAX_BUTTONS) {
            uint32_t num = f->usage & 0xffffu;
            const uint32_t *roles = pad->known && pad->known->button_roles
                                        ? pad->known->button_roles
                                        : generic_roles;
            pad->button[pad->n_buttons] = *f;
            pad->button_role[pad->n_buttons] =
                num >= 1 && num <= HOL_HID_PAD_MAX_BUTTONS ? roles[num - 1] : 0;
            pad->n_buttons++;
        }
    }
    if (!pad->has_axis[HOL_HID_LX] && !pad->has_axis[HOL_HID_RX] &&
        !pad->has_hat && pad->n_buttons == 0)
        return HOL_EUNSUPPORTED;
    return HOL_OK;
}

static float normalise(const hol_hid_field *f, int64_t v)
{
    double lo = (double)f->logical_min, hi = (double)f->logical_max;
    double t = ((double)v - lo) / (hi - lo) * 2.0 - 1.0;
    return (float)(t < -1.0 ? -1.0 : t > 1.0 ? 1.0 : t);
}

void hol_hid_pad_state(const hol_hid_pad *pad, hol_input *io)
{
    float l[2], r[2];
    hol_shell_stick(pad->dead_zone, pad->raw[HOL_HID_LX], pad->raw[HOL_HID_LY], l);
    hol_shell_stick(pad->dead_zone, pad->raw[HOL_HID_RX], pad->raw[HOL_HID_RY], r);
    io->move[0] = l[0];
    io->move[1] = -l[1];
    io->turn[0] = -r[0];
    io->turn[1] = -r[1];
    uint32_t b = 0;
    for (int i = 0; i < pad->n_buttons; i++)
        if (pad->pressed >> i & 1u)
            b |= pad->button_role[i];
    int d = pad->hat_dir;
    if (d == 7 || d == 0 || d == 1)
        b |= HOL_BTN_RECENTRE;
    if (d >= 3 && d <= 5)
        b |= HOL_BTN_MINIMAP;
    io->buttons = b;
}

/* Switch Pro full report 0x30: buttons in bytes 3..5, 12-bit sticks in
 * 6..8 (left) and 9..11 (right), y growing upwards. */
static int decode_switch(hol_hid_pad *pad, const uint8_t *r, size_t len)
{
    if (len < 12 || r[0] != 0x30)
        return 0;
    static const hol_hid_field axis12 = {.size = 12, .logical_max = 4095};
    unsigned lx = r[6] | (r[7] & 0x0fu) << 8, ly = r[7] >> 4 | r[8] << 4;
    unsigned rx = r[9] | (r[10] & 0x0fu) << 8, ry = r[10] >> 4 | r[11] << 4;
    pad->raw[HOL_HID_LX] = normalise(&axis12, lx);
    pad->raw[HOL_HID_LY] = -normalise(&axis12, ly);
    pad->raw[HOL_HID_RX] = normalise(&axis12, rx);
    pad->raw[HOL_HID_RY] = -normalise(&axis12, ry);
    /* buttons: A, B, X, Y, plus, home, minus, d-pad up, down */
    static const struct { uint8_t byte, mask; uint32_t role; } map[] = {
        {3, 0x08, HOL_BTN_CONFIRM}, {3, 0x04, HOL_BTN_BACK},
        {3, 0x02, HOL_BTN_RECENTRE}, {3, 0x01, HOL_BTN_MINIMAP},
        {4, 0x02, HOL_BTN_MENU}, {4, 0x10, HOL_BTN_MENU},
        {4, 0x01, HOL_BTN_MINIMAP}, {5, 0x02, HOL_BTN_RECENTRE},
        {5, 0x01, HOL_BTN_MINIMAP},
    };
    pad->n_buttons = (int)(sizeof map / sizeof map[0]);
    pad->pressed = 0;
    for (int i = 0; i < pad->n_buttons; i++) {
        pad->button_role[i] = map[i].role;
        if (r[map[i].byte] & map[i].mask)
            pad->pressed |= 1u << i;
    }
    pad->hat_dir = -1;
    return 1;
}

int hol_hid_pad_decode(hol_hid_pad *pad, const uint8_t *report, size_t len,
                       hol_input *io)
{
    int used = 0;
    if (pad->known && pad->known->layout == HOL_HID_LAYOUT_SWITCH_PRO) {
        used = decode_switch(pad, report, len);
    } else {
        uint8_t id = 0;
        if (pad->has_ids) {
            if (len == 0)
                return 0;
            id = report[0];
            report++;
            len--;
        }
        int64_t v;
        for (int a = 0; a < HOL_HID_AXES; a++)
            if (pad->has_axis[a] && pad->axis[a].report_id == id &&
                hol_hid_field_read(&pad->axis[a], report, len, &v)) {
                pad->raw[a] = normalise(&pad->axis[a], v);
                used = 1;
            }
        if (pad->has_hat && pad->hat.report_id == id &&
            hol_hid_field_read(&pad->hat, report, len, &v)) {
            /* as Linux: (v - min) * 8 / (max - min + 1) eighths from north */
            const hol_hid_field *h = &pad->hat;
            if (v < h->logical_min || v > h->logical_max)
                pad->hat_dir = -1;
            else
                pad->hat_dir = (int)((v - h->logical_min) * 8 /
                                     (h->logical_max - h->logical_min + 1));
            used = 1;
        }
        for (int i = 0; i < pad->n_buttons; i++)
            if (pad->button[i].report_id == id &&
                hol_hid_field_read(&pad->button[i], report, len, &v)) {
                if (v > pad->button[i].logical_min)
                    pad->pressed |= 1u << i;
                else
                    pad->pressed &= ~(1u << i);
                used = 1;
            }
    }
    if (used)
        hol_hid_pad_state(pad, io);
    return used;
}
