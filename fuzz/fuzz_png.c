/* fuzz_png.c - libFuzzer harness for the PNG decoder (golden images and
 * any PNG the tools read). Checks: decoding never reads out of bounds or
 * crashes; an image it accepts has sane dimensions, and encoding it and
 * decoding again gives the same pixels. Each input is decoded as given and
 * again with every chunk CRC corrected, so mutations reach past the CRC
 * checks into the chunk, zlib and filter code. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "../render/hol_png.h"

static void check(const uint8_t *data, size_t size);

static uint32_t rd32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    check(data, size);
    if (size < 8 || size > (1u << 20))
        return 0;
    uint8_t *fixed = malloc(size);
    if (!fixed)
        return 0;
    memcpy(fixed, data, size);
    for (size_t pos = 8; pos + 12 <= size;) {
        uint32_t len = rd32(fixed + pos);
        if (len > size - pos - 12)
            break;
        uint32_t crc = (uint32_t)crc32(0, fixed + pos + 4, len + 4);
        uint8_t *c = fixed + pos + 8 + len;
        c[0] = (uint8_t)(crc >> 24);
        c[1] = (uint8_t)(crc >> 16);
        c[2] = (uint8_t)(crc >> 8);
        c[3] = (uint8_t)crc;
        pos += 12 + (size_t)len;
    }
    check(fixed, size);
    free(fixed);
    return 0;
}

static void check(const uint8_t *data, size_t size)
{
    uint8_t *rgba = NULL, *png = NULL, *back = NULL;
    int w, h, w2, h2;
    size_t n;
    if (hol_png_decode(data, size, &rgba, &w, &h) != HOL_OK)
        return;
    if (w < 1 || h < 1 || w > HOL_PNG_MAX_DIM || h > HOL_PNG_MAX_DIM)
        abort();
    if (hol_png_encode(rgba, w, h, 1, &png, &n) != HOL_OK)
        abort();
    if (hol_png_decode(png, n, &back, &w2, &h2) != HOL_OK || w2 != w || h2 != h ||
        memcmp(back, rgba, (size_t)w * (size_t)h * 4) != 0)
        abort();
    free(rgba);
    free(png);
    free(back);
}
