/* tests/fake_hidapi/hidapi/hidapi.h - the part of hidapi's API that
 * platform/hid/hol_hid_dev.c uses, declared as hidapi 0.14 declares it, for
 * tests/test_hid_dev.c: the device layer is compiled unchanged against a
 * scripted stand-in (defined in the test), because this machine has no
 * /dev/hidraw and no uhid. Not used by any build of the tool. */
#ifndef FAKE_HIDAPI_H
#define FAKE_HIDAPI_H

#include <stddef.h>
#include <wchar.h>

#define HID_API_MAKE_VERSION(mj, mn, p) (((mj) << 24) | ((mn) << 8) | (p))
#define HID_API_VERSION HID_API_MAKE_VERSION(0, 14, 0)

typedef struct hid_device_ hid_device;

struct hid_device_info {
    char *path;
    unsigned short vendor_id, product_id;
    wchar_t *serial_number;
    unsigned short release_number;
    wchar_t *manufacturer_string, *product_string;
    unsigned short usage_page, usage;
    int interface_number;
    struct hid_device_info *next;
};

int hid_init(void);
struct hid_device_info *hid_enumerate(unsigned short vendor_id, unsigned short product_id);
void hid_free_enumeration(struct hid_device_info *devs);
hid_device *hid_open_path(const char *path);
void hid_close(hid_device *dev);
int hid_set_nonblocking(hid_device *dev, int nonblock);
int hid_read_timeout(hid_device *dev, unsigned char *data, size_t length, int milliseconds);
int hid_write(hid_device *dev, const unsigned char *data, size_t length);
int hid_get_feature_report(hid_device *dev, unsigned char *data, size_t length);
int hid_get_report_descriptor(hid_device *dev, unsigned char *buf, size_t buf_size);

#endif
