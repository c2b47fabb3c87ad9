/* hol_hid_dev.c - game controllers through hidapi (see hol_hid_dev.h). */
#include "hol_hid_dev.h"

#include <stdio.h>
#include <string.h>
#include <wchar.h>

#include <hidapi/hidapi.h>

#ifndef HOL_HID_BACKEND
#define HOL_HID_BACKEND "hidraw"
#endif

const char *hol_hid_dev_backend(void) { return HOL_HID_BACKEND; }

static int is_controller(const struct hid_device_info *d)
{
    return d->usage_page == 0x01 &&
           (d->usage == 0x04 || d->usage == 0x05 || d->usage == 0x08);
}

/* The report descriptor: hidapi 0.14 has a call; before it, hidraw nodes
 * expose it in sysfs. */
static hol_err read_desc(hid_device *h, const char *path, uint8_t *buf,
                         size_t cap, size_t *out_len)
{
#if defined(HID_API_VERSION) && HID_API_VERSION >= HID_API_MAKE_VERSION(0, 14, 0)
    (void)path;
    int n = hid_get_report_descriptor(h, buf, cap);
    if (n <= 0)
        return HOL_EIO;
    *out_len = (size_t)n;
    return HOL_OK;
#else
    (void)h;
    const char *node = strrchr(path, '/');
    if (!node || strncmp(node + 1, "hidraw", 6))
        return HOL_EUNSUPPORTED; /* libusb paths: needs hidapi >= 0.14 */
    char sys[128];
    snprintf(sys, sizeof sys, "/sys/class/hidraw/%.32s/device/report_descriptor",
             node + 1);
    FILE *f = fopen(sys, "rb");
    if (!f)
        return HOL_EIO;
    size_t n = fread(buf, 1, cap, f);
    fclose(f);
    if (n == 0)
        return HOL_EIO;
    *out_len = n;
    return HOL_OK;
#endif
}

static void fill_info(hol_hid_dev_info *info, const struct hid_device_info *d)
{
    memset(info, 0, sizeof *info);
    info->vid = d->vendor_id;
    info->pid = d->product_id;
    info->usage_page = d->usage_page;
    info->usage = d->usage;
    snprintf(info->path, sizeof info->path, "%s", d->path ? d->path : "");
    if (d->product_string)
        snprintf(info->name, sizeof info->name, "%ls", d->product_string);
}

static hol_err start_pad(hid_device *h, const hol_hid_known *k)
{
    if (!k || k->start_kind == HOL_HID_START_NONE)
        return HOL_OK;
    if (k->start_kind == HOL_HID_START_FEATURE) {
        uint8_t buf[64] = {k->start[0]};
        size_t n = k->start_len < sizeof buf ? k->start_len : sizeof buf;
        return hid_get_feature_report(h, buf, n) < 0 ? HOL_EIO : HOL_OK;
    }
    for (int i = 0; i < k->start_count; i++)
        if (hid_write(h, k->start + (size_t)i * k->start_len, k->start_len) < 0)
            return HOL_EIO;
    return HOL_OK;
}

/* The field map and decoder of a controller whose descriptor was read
 * (desc_err: why it was not). */
static hol_err setup_pad(hol_hid_dev *dev, hol_err desc_err, const uint8_t *desc, size_t len)
{
    hol_err err = desc_err;
    if (!err) {
        err = hol_hid_desc_parse(desc, len, dev->fields, HOL_HID_DEV_MAX_FIELDS,
                                 &dev->n_fields, &dev->has_ids);
        if (err == HOL_ENOMEM) { /* keep the first fields */
            dev->n_fields = HOL_HID_DEV_MAX_FIELDS;
            err = HOL_OK;
        }
    }
    const hol_hid_known *k = hol_hid_known_find(dev->info.vid, dev->info.pid);
    if (err && k && k->layout != HOL_HID_LAYOUT_DESCRIPTOR)
        err = HOL_OK, dev->n_fields = 0; /* its layout is fixed */
    if (!err)
        err = hol_hid_pad_init(&dev->pad, dev->fields, dev->n_fields,
                               dev->has_ids, dev->info.vid, dev->info.pid, NULL);
    return err;
}

static hol_err open_info(hol_hid_dev *dev, const struct hid_device_info *d)
{
    uint8_t desc[HOL_HID_DESC_MAX];
    size_t len = 0;
    hid_device *h = hid_open_path(d->path);
    if (!h)
        return HOL_EOPEN;
    fill_info(&dev->info, d);
    hol_err err = read_desc(h, d->path, desc, sizeof desc, &len);
    err = setup_pad(dev, err, desc, len);
    if (!err)
        err = start_pad(h, hol_hid_known_find(d->vendor_id, d->product_id));
    if (!err && hid_set_nonblocking(h, 1) < 0)
        err = HOL_EIO;
    if (err) {
        hid_close(h);
        return err;
    }
    dev->handle = h;
    dev->lost = 0;
    return HOL_OK;
}

hol_err hol_hid_dev_open_first(hol_hid_dev *dev)
{
    memset(dev, 0, sizeof *dev);
    if (hid_init() < 0)
        return HOL_EOPEN;
    struct hid_device_info *all = hid_enumerate(0, 0);
    hol_err err = HOL_EOPEN;
    for (struct hid_device_info *d = all; d && err; d = d->next)
        if (is_controller(d))
            err = open_info(dev, d);
    hid_free_enumeration(all);
    return err ? HOL_EOPEN : HOL_OK;
}

hol_err hol_hid_dev_open_backend(hol_hid_dev *dev, const hol_hid_backend *be, double now_s)
{
    memset(dev, 0, sizeof *dev);
    dev->be = be;
    uint8_t desc[HOL_HID_DESC_MAX];
    size_t len = 0;
    hol_err err = be->open_first(be->ctx, now_s, &dev->info, desc, sizeof desc, &len);
    if (err)
        return HOL_EOPEN;
    if (setup_pad(dev, HOL_OK, desc, len)) {
        be->close(be->ctx);
        return HOL_EOPEN;
    }
    dev->handle = (void *)be;
    return HOL_OK;
}

static hol_err reopen(hol_hid_dev *dev, double now_s)
{
    return dev->be ? hol_hid_dev_open_backend(dev, dev->be, now_s)
                   : hol_hid_dev_open_first(dev);
}

static int read_report(hol_hid_dev *dev, double now_s, uint8_t *buf, size_t cap)
{
    if (dev->be)
        return dev->be->read(dev->be->ctx, now_s, buf, cap);
    return hid_read_timeout((hid_device *)dev->handle, buf, cap, 0);
}

static void close_handle(hol_hid_dev *dev)
{
    if (dev->be)
        dev->be->close(dev->be->ctx);
    else
        hid_close((hid_device *)dev->handle);
    dev->handle = NULL;
}

hol_err hol_hid_dev_poll(hol_hid_dev *dev, hol_input *io)
{
    double now_s = io->time_s;
    if (!dev->handle) {
        io->flags |= HOL_INPUT_DEVICE_LOST;
        io->buttons = 0;
        io->move[0] = io->move[1] = io->turn[0] = io->turn[1] = 0.0f;
        if (dev->tried && now_s - dev->last_try_s < HOL_HID_REENUM_S)
            return HOL_EIO;
        int was_lost = dev->lost;
        if (reopen(dev, now_s)) { /* leaves dev closed */
            dev->lost = was_lost; /* still away */
            dev->tried = 1;
            dev->last_try_s = now_s;
            return HOL_EIO;
        }
        io->flags &= ~HOL_INPUT_DEVICE_LOST;
    }
    uint8_t buf[HOL_HID_REPORT_MAX_BYTES + 1];
    /* a button down in any report since the last poll is pressed, even if
     * a later report lets it go (a tap between two frames) */
    hol_input before = *io;
    hol_hid_pad_state(&dev->pad, &before);
    uint32_t held = before.buttons;
    for (int i = 0; i < 64; i++) { /* drain, bounded */
        int n = read_report(dev, now_s, buf, sizeof buf);
        if (n == 0)
            break;
        if (n < 0) {
            close_handle(dev);
            dev->lost = 1;
            dev->tried = 1;
            dev->last_try_s = now_s;
            io->flags |= HOL_INPUT_DEVICE_LOST;
            io->buttons = 0;
            io->move[0] = io->move[1] = io->turn[0] = io->turn[1] = 0.0f;
            return HOL_EIO;
        }
        hol_hid_pad_decode(&dev->pad, buf, (size_t)n, io);
        hol_hid_pad_state(&dev->pad, io);
        io->pressed |= io->buttons & ~held;
        held = io->buttons;
    }
    hol_hid_pad_state(&dev->pad, io);
    return HOL_OK;
}

void hol_hid_dev_close(hol_hid_dev *dev)
{
    if (dev->handle)
        close_handle(dev);
}

int hol_hid_dev_list(hol_hid_dev_list_fn fn, void *ctx)
{
    if (hid_init() < 0)
        return 0;
    static hol_hid_field fields[HOL_HID_DEV_MAX_FIELDS];
    struct hid_device_info *all = hid_enumerate(0, 0);
    int count = 0;
    for (struct hid_device_info *d = all; d; d = d->next) {
        if (!is_controller(d))
            continue;
        hol_hid_dev_info info;
        fill_info(&info, d);
        uint8_t desc[HOL_HID_DESC_MAX];
        size_t len = 0, n = 0;
        hol_err err = HOL_EOPEN;
        hid_device *h = hid_open_path(d->path);
        if (h) {
            err = read_desc(h, d->path, desc, sizeof desc, &len);
            if (!err)
                err = hol_hid_desc_parse(desc, len, fields,
                                         HOL_HID_DEV_MAX_FIELDS, &n, NULL);
            if (err == HOL_ENOMEM)
                err = HOL_OK, n = HOL_HID_DEV_MAX_FIELDS;
            hid_close(h);
        }
        fn(ctx, &info, fields, err ? 0 : n, err);
        count++;
    }
    hid_free_enumeration(all);
    return count;
}
