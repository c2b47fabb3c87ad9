/* hol_png.c - PNG encode/decode on top of zlib; atomic file writes. */
#include "hol_png.h"

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static void hol__be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

static uint32_t hol__rd32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Append one chunk at out + *pos (capacity checked by the caller). */
static void hol__chunk(uint8_t *out, size_t *pos, const char *type,
                       const uint8_t *data, uint32_t n)
{
    uint8_t *p = out + *pos;
    hol__be32(p, n);
    memcpy(p + 4, type, 4);
    if (n)
        memcpy(p + 8, data, n);
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, p + 4, (uInt)(n + 4));
    hol__be32(p + 8 + n, (uint32_t)crc);
    *pos += 12 + (size_t)n;
}

static int hol__paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    if (pa <= pb && pa <= pc)
        return a;
    return pb <= pc ? b : c;
}

/* Per row, pick the filter (none, sub, up, paeth) with the smallest sum
 * of absolute residuals: the usual heuristic, cheap and effective. */
static void hol__filter_best(const uint8_t *rgba, int w, int h, int bpp, uint8_t *raw,
                             uint8_t *line)
{
    size_t stride = (size_t)w * (size_t)bpp + 1;
    for (int y = 0; y < h; y++) {
        uint8_t *dst = raw + (size_t)y * stride;
        const uint8_t *src = rgba + (size_t)y * (size_t)w * 4;
        const uint8_t *up = y ? rgba + (size_t)(y - 1) * (size_t)w * 4 : NULL;
        unsigned long best = (unsigned long)-1;
        static const int filters[4] = {0, 1, 2, 4};
        for (int fi = 0; fi < 4; fi++) {
            int f = filters[fi];
            unsigned long sum = 0;
            line[0] = (uint8_t)f;
            for (int x = 0; x < w; x++)
                for (int k = 0; k < bpp; k++) {
                    int v = src[4 * x + k];
                    int a = x ? src[4 * (x - 1) + k] : 0;
                    int b = up ? up[4 * x + k] : 0;
                    int c = (x && up) ? up[4 * (x - 1) + k] : 0;
                    int pred = f == 0 ? 0 : f == 1 ? a : f == 2 ? b : hol__paeth(a, b, c);
                    uint8_t r = (uint8_t)(v - pred);
                    line[1 + (size_t)x * (size_t)bpp + (size_t)k] = r;
                    sum += r < 128 ? r : 256u - r;
                }
            if (sum < best) {
                best = sum;
                memcpy(dst, line, stride);
            }
        }
    }
}

/* Every row filtered "up" (the row above subtracted; the first row as it is). */
static void hol__filter_up(const uint8_t *rgba, int w, int h, int bpp, uint8_t *raw)
{
    size_t stride = (size_t)w * (size_t)bpp + 1, row = (size_t)w * 4;
    for (int y = 0; y < h; y++) {
        uint8_t *dst = raw + (size_t)y * stride + 1;
        const uint8_t *src = rgba + (size_t)y * row;
        const uint8_t *up = y ? src - row : NULL;
        dst[-1] = 2;
        if (!up && bpp == 4)
            memcpy(dst, src, row);
        else if (bpp == 4)
            for (size_t i = 0; i < row; i++)
                dst[i] = (uint8_t)(src[i] - up[i]);
        else if (!up)
            for (int x = 0; x < w; x++, dst += 3, src += 4)
                dst[0] = src[0], dst[1] = src[1], dst[2] = src[2];
        else
            for (int x = 0; x < w; x++, dst += 3, src += 4, up += 4) {
                dst[0] = (uint8_t)(src[0] - up[0]);
                dst[1] = (uint8_t)(src[1] - up[1]);
                dst[2] = (uint8_t)(src[2] - up[2]);
            }
    }
}

/* raw (n bytes) deflated into out (*zn bytes there): level 9 as compress2,
 * below with the run-length strategy (fast on pictures of flat colours). */
static int hol__deflate(uint8_t *out, uLongf *zn, const uint8_t *raw, size_t n, int level)
{
    if (level == 9)
        return compress2(out, zn, raw, (uLong)n, 9) == Z_OK;
    z_stream z;
    memset(&z, 0, sizeof z);
    if (deflateInit2(&z, level, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK)
        return 0;
    z.next_in = (Bytef *)(uintptr_t)raw;
    z.avail_in = (uInt)n;
    z.next_out = out;
    z.avail_out = (uInt)*zn;
    int ok = deflate(&z, Z_FINISH) == Z_STREAM_END;
    *zn = z.total_out;
    return deflateEnd(&z) == Z_OK && ok;
}

/* rgba's colours (alpha ignored) as a palette of at most 256 (plte: 3
 * bytes each) and raw (h rows: a filter byte "up", then one index a
 * pixel): the palette's size, or 0 when there are more colours. */
static int hol__palette(const uint8_t *rgba, int w, int h, uint8_t *plte, uint8_t *raw)
{
    uint32_t pal[256], last = 0;
    int n = 0, li = -1;
    size_t stride = (size_t)w + 1;
    for (int y = 0; y < h; y++) {
        uint8_t *dst = raw + (size_t)y * stride;
        const uint8_t *src = rgba + (size_t)y * (size_t)w * 4;
        dst[0] = 2;
        for (int x = 0; x < w; x++, src += 4) {
            uint32_t c = (uint32_t)src[0] << 16 | (uint32_t)src[1] << 8 | src[2];
            if (li < 0 || c != last) {
                li = -1;
                for (int k = 0; k < n && li < 0; k++)
                    if (pal[k] == c)
                        li = k;
                if (li < 0 && n == 256)
                    return 0;
                if (li < 0) {
                    pal[n] = c;
                    li = n++;
                }
                last = c;
            }
            dst[1 + x] = (uint8_t)li;
        }
    }
    for (int y = h - 1; y > 0; y--) { /* "up": the row above subtracted */
        uint8_t *r = raw + (size_t)y * stride + 1;
        for (int x = 0; x < w; x++)
            r[x] = (uint8_t)(r[x] - r[x - (ptrdiff_t)stride]);
    }
    for (int k = 0; k < n; k++) {
        plte[3 * k] = (uint8_t)(pal[k] >> 16);
        plte[3 * k + 1] = (uint8_t)(pal[k] >> 8);
        plte[3 * k + 2] = (uint8_t)pal[k];
    }
    return n;
}

hol_err hol_png_encode(const uint8_t *rgba, int w, int h, int alpha,
                       uint8_t **out_data, size_t *out_size)
{
    return hol_png_encode_level(rgba, w, h, alpha, 9, out_data, out_size);
}

/* raw (rawn bytes: h filtered rows) as a PNG of colour type ctype (with
 * its palette: npal entries, when ctype 3); raw is freed. */
static hol_err hol__png_write(uint8_t *raw, size_t rawn, int w, int h, int ctype,
                              const uint8_t *plte, int npal, int level, uint8_t **out_data,
                              size_t *out_size)
{
    uLongf zn = compressBound((uLong)rawn);
    uint8_t *out = malloc(8 + 25 + 12 + 768 + 12 + (size_t)zn + 12);
    if (!out) {
        free(raw);
        return HOL_ENOMEM;
    }
    size_t pos = 8;
    memcpy(out, "\x89PNG\r\n\x1a\n", 8);
    uint8_t ihdr[13];
    hol__be32(ihdr, (uint32_t)w);
    hol__be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;
    ihdr[9] = (uint8_t)ctype;
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    hol__chunk(out, &pos, "IHDR", ihdr, 13);
    if (ctype == 3)
        hol__chunk(out, &pos, "PLTE", plte, (uint32_t)(3 * npal));
    /* compress straight into the IDAT payload position */
    uint8_t *payload = out + pos + 8;
    if (!hol__deflate(payload, &zn, raw, rawn, level)) {
        free(raw);
        free(out);
        return HOL_ENOMEM;
    }
    free(raw);
    hol__be32(out + pos, (uint32_t)zn);
    memcpy(out + pos + 4, "IDAT", 4);
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, out + pos + 4, (uInt)(zn + 4));
    hol__be32(out + pos + 8 + zn, (uint32_t)crc);
    pos += 12 + (size_t)zn;
    hol__chunk(out, &pos, "IEND", NULL, 0);
    *out_data = out;
    *out_size = pos;
    return HOL_OK;
}

hol_err hol_png_encode_level(const uint8_t *rgba, int w, int h, int alpha, int level,
                             uint8_t **out_data, size_t *out_size)
{
    if (!rgba || w <= 0 || h <= 0 || w > HOL_PNG_MAX_DIM || h > HOL_PNG_MAX_DIM || level < 1 ||
        level > 9)
        return HOL_EARG;
    int bpp = alpha ? 4 : 3;
    size_t stride = (size_t)w * (size_t)bpp + 1;
    size_t rawn = stride * (size_t)h;
    uint8_t *raw = malloc(rawn);
    uint8_t *line = malloc(stride);
    if (!raw || !line) {
        free(raw);
        free(line);
        return HOL_ENOMEM;
    }
    uint8_t plte[768];
    int npal = level < 9 && !alpha ? hol__palette(rgba, w, h, plte, raw) : 0;
    if (npal)
        rawn = ((size_t)w + 1) * (size_t)h;
    else if (level < 9)
        hol__filter_up(rgba, w, h, bpp, raw);
    else
        hol__filter_best(rgba, w, h, bpp, raw, line);
    free(line);
    return hol__png_write(raw, rawn, w, h, npal ? 3 : alpha ? 6 : 2, plte, npal, level,
                          out_data, out_size);
}

/* A raw deflate stream's bits, least significant first (RFC 1951 3.1.1). */
typedef struct hol__bits {
    uint8_t *out;
    size_t pos;
    uint64_t acc;
    int n;
} hol__bits;

static void hol__put(hol__bits *b, uint32_t v, int n)
{
    b->acc |= (uint64_t)v << b->n;
    b->n += n;
    while (b->n >= 8) {
        b->out[b->pos++] = (uint8_t)b->acc;
        b->acc >>= 8;
        b->n -= 8;
    }
}

/* Symbol s of the fixed literal/length code (RFC 1951 3.2.6): its code,
 * most significant bit first, so reversed into the stream (a table made
 * on first use). */
static void hol__put_sym(hol__bits *b, int s)
{
    static uint16_t rev[288];
    static uint8_t len[288];
    if (!len[0])
        for (int t = 0; t < 288; t++) {
            uint32_t code;
            int n;
            if (t < 144)
                code = 0x30u + (uint32_t)t, n = 8;
            else if (t < 256)
                code = 0x190u + (uint32_t)(t - 144), n = 9;
            else if (t < 280)
                code = (uint32_t)(t - 256), n = 7;
            else
                code = 0xc0u + (uint32_t)(t - 280), n = 8;
            uint32_t r = 0;
            for (int i = 0; i < n; i++)
                r |= ((code >> i) & 1u) << (n - 1 - i);
            rev[t] = (uint16_t)r;
            len[t] = (uint8_t)n;
        }
    hol__put(b, rev[s], len[s]);
}

/* A match of length 3..258 at distance 1 (the byte before, repeated). */
static void hol__put_run(hol__bits *b, int len)
{
    static const uint16_t base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const uint8_t extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                      2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    int k = 28;
    while (base[k] > len)
        k--;
    hol__put_sym(b, 257 + k);
    hol__put(b, (uint32_t)(len - base[k]), extra[k]);
    hol__put(b, 0, 5); /* distance code 0: distance 1 */
}

/* raw (n bytes) as a zlib stream of one block with the fixed codes, only
 * literals and runs of the byte before (what "up"-filtered pictures of
 * flat colours are): out holds n + n / 8 + 64 bytes; its length. */
static size_t hol__deflate_runs(const uint8_t *raw, size_t n, uint8_t *out)
{
    hol__bits b = {out, 2, 0, 0};
    out[0] = 0x78, out[1] = 0x01; /* deflate, 32 KB window, no dictionary */
    hol__put(&b, 1, 1);           /* the last block */
    hol__put(&b, 1, 2);           /* fixed codes */
    for (size_t i = 0; i < n;) {
        size_t len = 0, max = n - i < 258 ? n - i : 258;
        if (i > 0) {
            uint64_t pat = raw[i - 1] * 0x0101010101010101u, v;
            while (len + 8 <= max && (memcpy(&v, raw + i + len, 8), v == pat))
                len += 8;
#if defined(__GNUC__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            if (len + 8 <= max) /* v: the first word that differs */
                len += (size_t)__builtin_ctzll(v ^ pat) >> 3;
#endif
            while (len < max && raw[i + len] == raw[i - 1])
                len++;
        }
        if (len >= 3) {
            hol__put_run(&b, (int)len);
            i += len;
        } else {
            hol__put_sym(&b, raw[i++]);
        }
    }
    hol__put_sym(&b, 256);
    hol__put(&b, 0, 7); /* flush the last byte */
    uint32_t a = (uint32_t)adler32(adler32(0L, Z_NULL, 0), raw, (uInt)n);
    hol__be32(out + b.pos, a);
    return b.pos + 4;
}

hol_err hol_png_encode_indexed(const uint8_t *idx, int w, int h, const uint8_t *plte,
                               int npal, uint8_t **out_data, size_t *out_size)
{
    if (!idx || !plte || w <= 0 || h <= 0 || w > HOL_PNG_MAX_DIM || h > HOL_PNG_MAX_DIM ||
        npal < 1 || npal > 256)
        return HOL_EARG;
    size_t stride = (size_t)w + 1, rawn = stride * (size_t)h;
    uint8_t *raw = malloc(rawn), *z = malloc(rawn + rawn / 8 + 64);
    uint8_t *out = malloc(8 + 25 + 12 + 768 + 12 + rawn + rawn / 8 + 64 + 12);
    if (!raw || !z || !out) {
        free(raw);
        free(z);
        free(out);
        return HOL_ENOMEM;
    }
    for (int y = 0; y < h; y++) { /* "up": the row above subtracted */
        uint8_t *dst = raw + (size_t)y * stride;
        const uint8_t *src = idx + (size_t)y * (size_t)w, *up = src - w;
        dst[0] = 2;
        int x = 0;
        if (!y) {
            memcpy(dst + 1, src, (size_t)w);
            continue;
        }
        for (const uint64_t hi = 0x8080808080808080u; x + 8 <= w; x += 8) {
            uint64_t a, b, d; /* eight bytes' differences at once, no borrow across */
            memcpy(&a, src + x, 8);
            memcpy(&b, up + x, 8);
            d = ((a | hi) - (b & ~hi)) ^ ((a ^ ~b) & hi);
            memcpy(dst + 1 + x, &d, 8);
        }
        for (; x < w; x++)
            dst[1 + x] = (uint8_t)(src[x] - up[x]);
    }
    size_t zn = hol__deflate_runs(raw, rawn, z);
    free(raw);
    size_t pos = 8;
    memcpy(out, "\x89PNG\r\n\x1a\n", 8);
    uint8_t ihdr[13];
    hol__be32(ihdr, (uint32_t)w);
    hol__be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8, ihdr[9] = 3, ihdr[10] = ihdr[11] = ihdr[12] = 0;
    hol__chunk(out, &pos, "IHDR", ihdr, 13);
    hol__chunk(out, &pos, "PLTE", plte, (uint32_t)(3 * npal));
    hol__chunk(out, &pos, "IDAT", z, (uint32_t)zn);
    hol__chunk(out, &pos, "IEND", NULL, 0);
    free(z);
    *out_data = out;
    *out_size = pos;
    return HOL_OK;
}

/* What IHDR says (8-bit grey, grey+alpha, RGB or RGBA, not interlaced). */
typedef struct hol__png_hdr {
    uint32_t w, h;
    int ctype;
    int npal;          /* PLTE's entries (ctype 3) */
    uint8_t plte[768];
} hol__png_hdr;

static hol_err hol__png_ihdr(const uint8_t *body, uint32_t n, hol__png_hdr *hd)
{
    if (n != 13)
        return HOL_ECORRUPT;
    hd->w = hol__rd32(body);
    hd->h = hol__rd32(body + 4);
    hd->ctype = body[9];
    if (hd->w == 0 || hd->h == 0 || hd->w > HOL_PNG_MAX_DIM || hd->h > HOL_PNG_MAX_DIM)
        return HOL_ECORRUPT;
    if (body[8] != 8 || body[10] || body[11] || body[12] ||
        (hd->ctype != 0 && hd->ctype != 2 && hd->ctype != 3 && hd->ctype != 4 &&
         hd->ctype != 6))
        return HOL_EUNSUPPORTED;
    return HOL_OK;
}

/* The chunks up to IEND, each checked against its CRC: the header, and
 * the IDAT payloads joined into *out_z (malloc'ed, *out_zn bytes). */
static hol_err hol__png_chunks(const uint8_t *data, size_t size, hol__png_hdr *hd,
                               uint8_t **out_z, size_t *out_zn)
{
    size_t pos = 8, zn = 0;
    int have_ihdr = 0, have_end = 0;
    uint8_t *z = NULL;
    hol_err err = HOL_OK;
    while (!have_end && !err) {
        if (size - pos < 12 || hol__rd32(data + pos) > size - pos - 12) {
            err = HOL_ECORRUPT;
            break;
        }
        uint32_t n = hol__rd32(data + pos);
        const uint8_t *type = data + pos + 4;
        const uint8_t *body = data + pos + 8;
        uLong crc = crc32(0L, Z_NULL, 0);
        crc = crc32(crc, type, (uInt)(n + 4));
        if ((uint32_t)crc != hol__rd32(body + n))
            err = HOL_ECORRUPT;
        else if (!memcmp(type, "IHDR", 4))
            err = have_ihdr++ ? HOL_ECORRUPT : hol__png_ihdr(body, n, hd);
        else if (!memcmp(type, "IDAT", 4) && (!have_ihdr || (hd->ctype == 3 && !hd->npal)))
            err = HOL_ECORRUPT;
        else if (!memcmp(type, "PLTE", 4)) {
            if (!have_ihdr || hd->npal || z || !n || n % 3 || n > 768)
                err = HOL_ECORRUPT;
            else {
                memcpy(hd->plte, body, n);
                hd->npal = (int)(n / 3);
            }
        }
        else if (!memcmp(type, "IDAT", 4)) {
            uint8_t *nz = realloc(z, zn + n + 1);
            if (!nz)
                err = HOL_ENOMEM;
            else {
                z = nz;
                memcpy(z + zn, body, n);
                zn += n;
            }
        } else if (!memcmp(type, "IEND", 4))
            have_end = 1;
        else if (!(type[0] & 0x20))
            err = HOL_EUNSUPPORTED; /* unknown critical chunk */
        pos += 12 + (size_t)n;
    }
    if (!err && (!have_ihdr || !z))
        err = HOL_ECORRUPT;
    if (err) {
        free(z);
        return err;
    }
    *out_z = z;
    *out_zn = zn;
    return HOL_OK;
}

/* Undo the row filters of raw (h rows of stride bytes, a filter byte
 * first) and write RGBA. */
static hol_err hol__png_rows(uint8_t *raw, size_t stride, const hol__png_hdr *hd, int bpp,
                             uint8_t *rgba)
{
    for (uint32_t y = 0; y < hd->h; y++) {
        uint8_t *row = raw + (size_t)y * stride;
        uint8_t *cur = row + 1;
        const uint8_t *up = y ? raw + (size_t)(y - 1) * stride + 1 : NULL;
        int f = row[0];
        if (f > 4)
            return HOL_ECORRUPT;
        for (size_t i = 0; i < stride - 1; i++) {
            int a = i >= (size_t)bpp ? cur[i - (size_t)bpp] : 0;
            int b = up ? up[i] : 0;
            int c = (up && i >= (size_t)bpp) ? up[i - (size_t)bpp] : 0;
            int pred = f == 0 ? 0 : f == 1 ? a : f == 2 ? b : f == 3 ? (a + b) / 2
                                                           : hol__paeth(a, b, c);
            cur[i] = (uint8_t)(cur[i] + pred);
        }
        for (uint32_t x = 0; hd->ctype == 3 && x < hd->w; x++) {
            if (cur[x] >= hd->npal)
                return HOL_ECORRUPT;
            uint8_t *o = rgba + ((size_t)y * hd->w + x) * 4;
            memcpy(o, hd->plte + 3 * cur[x], 3);
            o[3] = 255;
        }
        for (uint32_t x = 0; hd->ctype != 3 && x < hd->w; x++) {
            uint8_t *o = rgba + ((size_t)y * hd->w + x) * 4;
            const uint8_t *s = cur + (size_t)x * (size_t)bpp;
            o[0] = s[0];
            o[1] = bpp <= 2 ? s[0] : s[1];
            o[2] = bpp <= 2 ? s[0] : s[2];
            o[3] = bpp == 2 ? s[1] : bpp == 4 ? s[3] : 255;
        }
    }
    return HOL_OK;
}

hol_err hol_png_decode(const uint8_t *data, size_t size, uint8_t **out_rgba,
                       int *out_w, int *out_h)
{
    if (size < 8 || memcmp(data, "\x89PNG\r\n\x1a\n", 8))
        return HOL_ECORRUPT;
    static hol__png_hdr hd0;
    hol__png_hdr hd = hd0;
    hd.ctype = -1;
    uint8_t *z = NULL;
    size_t zn = 0;
    hol_err err = hol__png_chunks(data, size, &hd, &z, &zn);
    if (err)
        return err;
    int bpp = hd.ctype == 0 || hd.ctype == 3 ? 1 : hd.ctype == 4 ? 2 : hd.ctype == 2 ? 3 : 4;
    size_t stride = (size_t)hd.w * (size_t)bpp + 1;
    uLongf rawn = (uLongf)(stride * hd.h);
    /* deflate expands at most ~1032:1: refuse sizes the data cannot hold
     * before allocating for them */
    if ((double)rawn > (double)zn * 1100.0 + 1024.0) {
        free(z);
        return HOL_ECORRUPT;
    }
    uint8_t *raw = malloc(rawn ? rawn : 1);
    uint8_t *rgba = malloc((size_t)hd.w * hd.h * 4);
    uLongf got = rawn;
    if (!raw || !rgba)
        err = HOL_ENOMEM;
    else if (uncompress(raw, &got, z, (uLong)zn) != Z_OK || got != rawn)
        err = HOL_ECORRUPT;
    else
        err = hol__png_rows(raw, stride, &hd, bpp, rgba);
    free(z);
    free(raw);
    if (err) {
        free(rgba);
        return err;
    }
    *out_rgba = rgba;
    *out_w = (int)hd.w;
    *out_h = (int)hd.h;
    return HOL_OK;
}
