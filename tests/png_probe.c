/* png_probe.c - a test helper for tests/cli_report.sh: decodes a PNG with
 * the project's decoder (render/hol_png.c) and prints facts about it.
 *   png_probe FILE RRGGBB...   prints "W H" then, per colour, the number
 *                              of pixels of exactly that colour
 *   png_probe FILE --vs GOLDEN prints the number of pixels that differ
 *   png_probe LEFT --beside RIGHT OUT
 *                              writes OUT (RGB): LEFT and RIGHT, of one
 *                              height, side by side with 4 px of near black
 *                              (16, 16, 16) between them (docs/pictures.sh:
 *                              the headset's two eyes)
 * Exit status: 0 ok, 1 a file that cannot be read, decoded or written. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../render/hol_png.h"

static uint8_t *load(const char *path, int *w, int *h)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    static uint8_t data[1 << 22];
    size_t n = fread(data, 1, sizeof data, f);
    fclose(f);
    uint8_t *rgba = NULL;
    if (hol_png_decode(data, n, &rgba, w, h))
        return NULL;
    return rgba;
}

/* LEFT and RIGHT (w x h and w2 x h) side by side into OUT; 0 when written. */
static int beside(const uint8_t *a, int w, int h, const uint8_t *b, int w2, const char *out)
{
    enum { GAP = 4 };
    int W = w + GAP + w2;
    uint8_t *o = malloc((size_t)W * h * 4);
    if (!o)
        return 1;
    for (int y = 0; y < h; y++) {
        uint8_t *row = o + (size_t)y * W * 4;
        memcpy(row, a + (size_t)y * w * 4, (size_t)w * 4);
        for (int x = 0; x < GAP; x++)
            memcpy(row + (size_t)(w + x) * 4, "\x10\x10\x10\xff", 4);
        memcpy(row + (size_t)(w + GAP) * 4, b + (size_t)y * w2 * 4, (size_t)w2 * 4);
    }
    uint8_t *png = NULL;
    size_t size = 0;
    FILE *f = NULL;
    int bad = hol_png_encode(o, W, h, 0, &png, &size) != HOL_OK || !(f = fopen(out, "wb")) ||
              fwrite(png, 1, size, f) != size;
    if (f && fclose(f))
        bad = 1;
    free(png);
    free(o);
    return bad;
}

int main(int argc, char **argv)
{
    int w, h, w2, h2;
    uint8_t *p = argc > 1 ? load(argv[1], &w, &h) : NULL;
    if (!p) {
        fprintf(stderr, "png_probe: cannot decode %s\n", argc > 1 ? argv[1] : "(none)");
        return 1;
    }
    if (argc == 5 && !strcmp(argv[2], "--beside")) {
        uint8_t *b = load(argv[3], &w2, &h2);
        if (!b || h2 != h) {
            fprintf(stderr, "png_probe: %s is not a picture of the same height\n", argv[3]);
            return 1;
        }
        if (beside(p, w, h, b, w2, argv[4])) {
            fprintf(stderr, "png_probe: cannot write %s\n", argv[4]);
            return 1;
        }
        return 0;
    }
    if (argc == 4 && !strcmp(argv[2], "--vs")) {
        uint8_t *g = load(argv[3], &w2, &h2);
        if (!g || w2 != w || h2 != h) {
            fprintf(stderr, "png_probe: %s is not a golden of the same size\n", argv[3]);
            return 1;
        }
        long diff = 0;
        for (long i = 0; i < (long)w * h; i++)
            diff += memcmp(p + 4 * i, g + 4 * i, 4) != 0;
        printf("%ld\n", diff);
        return 0;
    }
    printf("%d %d\n", w, h);
    for (int a = 2; a < argc; a++) {
        unsigned long rgb = strtoul(argv[a], NULL, 16);
        long n = 0;
        for (long i = 0; i < (long)w * h; i++)
            n += p[4 * i] == (rgb >> 16 & 255) && p[4 * i + 1] == (rgb >> 8 & 255) &&
                 p[4 * i + 2] == (rgb & 255);
        printf("%ld\n", n);
    }
    return 0;
}
