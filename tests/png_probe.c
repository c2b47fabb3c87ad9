/* png_probe.c - a test helper for tests/cli_report.sh: decodes a PNG with
 * the project's decoder (render/hol_png.c) and prints facts about it.
 *   png_probe FILE RRGGBB...   prints "W H" then, per colour, the number
 *                              of pixels of exactly that colour
 *   png_probe FILE --vs GOLDEN prints the number of pixels that differ
 * Exit status: 0 ok, 1 a file that cannot be read or decoded. */
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

int main(int argc, char **argv)
{
    int w, h, w2, h2;
    uint8_t *p = argc > 1 ? load(argv[1], &w, &h) : NULL;
    if (!p) {
        fprintf(stderr, "png_probe: cannot decode %s\n", argc > 1 ? argv[1] : "(none)");
        return 1;
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
