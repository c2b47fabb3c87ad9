/* hol_png_file.c - PNG files (see hol_png_file.h). */
#include "hol_png_file.h"

#include <stdlib.h>

#include "../../render/hol_png.h"
#include "../file/hol_file.h"

hol_err hol_png_write_file(const char *path, const uint8_t *rgba, int w, int h,
                           int alpha)
{
    uint8_t *data;
    size_t size;
    hol_err err = hol_png_encode(rgba, w, h, alpha, &data, &size);
    if (err)
        return err;
    err = hol_file_write_atomic(path, data, size);
    free(data);
    return err;
}

hol_err hol_png_read_file(const char *path, uint8_t **out_rgba, int *out_w,
                          int *out_h)
{
    uint8_t *buf;
    size_t n;
    hol_err err = hol_file_read_all(path, (size_t)1 << 30, &buf, &n);
    if (err)
        return err;
    err = hol_png_decode(buf, n, out_rgba, out_w, out_h);
    free(buf);
    return err;
}
