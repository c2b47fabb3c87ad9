/* hol_world_io.c - the world image: save to and load from memory buffers.
 *
 * Format version 1, all integers little-endian:
 *   offset  size  field
 *        0     8  magic "HOLWORLD"
 *        8     4  version (1)
 *       12     4  record size (24)
 *       16     8  seed
 *       24     4  radius
 *       28     4  record count N
 *       32     4  update stamp
 *       36     4  reserved, 0
 *       40    16  user tile word (bits[0], bits[1])
 *       56     4  user orient, col, row, room size ((cols - 3) | (rows - 3)
 *                 << 4; 0: 3 x 3)
 *       60     4  reserved, 0
 *       64  24*N  records sorted by tile word (bits[1], then bits[0]):
 *                 tile bits[0] (8), bits[1] (8), stamp (4), state (1;
 *                 255 = open), biome (1; 255 = none), depth (1),
 *                 flags (1: bit 0 seen, bits 4..7 game object)
 *   64+24N     8  checksum of every byte before it
 * The loader checks the header, the length, the checksum, the order and
 * every record against the tile set and its neighbours in the image before
 * it changes the world. No file I/O here: the CLI writes files atomically.
 */
#include "hol_world_impl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HOL__MAGIC "HOLWORLD"
#define HOL__VERSION 1u
#define HOL__HDR 64u
#define HOL__REC 24u

static void hol__put32(uint8_t *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

static void hol__put64(uint8_t *p, uint64_t v)
{
    for (int i = 0; i < 8; i++)
        p[i] = (uint8_t)(v >> (8 * i));
}

static uint32_t hol__get32(const uint8_t *p)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++)
        v |= (uint32_t)p[i] << (8 * i);
    return v;
}

static uint64_t hol__get64(const uint8_t *p)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; i++)
        v |= (uint64_t)p[i] << (8 * i);
    return v;
}

uint64_t hol__image_checksum(const uint8_t *p, size_t n)
{
    uint64_t h = UINT64_C(0x484f4c574f524c44) ^ n;
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        h = hol__mix(h, hol__get64(p + i));
    uint64_t tail = 0;
    for (size_t k = 0; i + k < n; k++)
        tail |= (uint64_t)p[i + k] << (8 * k);
    return hol__mix(h, tail ^ UINT64_C(0xFF00000000000000));
}

static int hol__rec_cmp(const void *a, const void *b)
{
    uint64_t a1 = hol__get64((const uint8_t *)a + 8), b1 = hol__get64((const uint8_t *)b + 8);
    if (a1 != b1)
        return a1 < b1 ? -1 : 1;
    uint64_t a0 = hol__get64(a), b0 = hol__get64(b);
    if (a0 != b0)
        return a0 < b0 ? -1 : 1;
    return 0;
}

/* Seen tiles remembered outside the store (they are saved too). */
static uint32_t hol__kept_outside(const hol_world *w)
{
    uint32_t n = 0;
    for (uint32_t i = 0; i <= w->kept_mask; i++)
        n += w->kept[i].used && hol__find(w, w->kept[i].tile) < 0;
    return n;
}

size_t hol_world_save_size(const hol_world *w)
{
    return HOL__HDR + ((size_t)w->count + hol__kept_outside(w)) * HOL__REC + 8;
}

hol_err hol_world_save(const hol_world *w, void *buf, size_t cap,
                       size_t *out_len)
{
    uint32_t nkept = hol__kept_outside(w), nrec = w->count + nkept;
    size_t need = HOL__HDR + (size_t)nrec * HOL__REC + 8;
    if (!buf || !out_len)
        return HOL_EARG;
    if (cap < need)
        return HOL_ENOMEM;
    uint8_t *p = buf;
    memset(p, 0, HOL__HDR);
    memcpy(p, HOL__MAGIC, 8);
    hol__put32(p + 8, HOL__VERSION);
    hol__put32(p + 12, HOL__REC);
    hol__put64(p + 16, w->seed);
    hol__put32(p + 24, (uint32_t)w->radius);
    hol__put32(p + 28, nrec);
    hol__put32(p + 32, w->stamp);
    hol__put64(p + 40, w->user.tile.bits[0]);
    hol__put64(p + 48, w->user.tile.bits[1]);
    p[56] = w->user.orient;
    p[57] = w->user.col;
    p[58] = w->user.row;
    p[59] = (uint8_t)(w->user.more_cols | w->user.more_rows << 4);
    uint8_t *r = p + HOL__HDR;
    for (uint32_t i = 0; i < w->cap; i++) {
        const hol__entry *e = &w->entries[i];
        if (!(e->flags & HOL__F_USED))
            continue;
        hol__put64(r, e->tile.bits[0]);
        hol__put64(r + 8, e->tile.bits[1]);
        hol__put32(r + 16, e->stamp);
        r[20] = e->state;
        r[21] = e->biome;
        r[22] = e->depth;
        r[23] = (uint8_t)(((e->flags & HOL__F_SEEN) ? 1 : 0) |
                          ((e->flags & HOL__F_PLACED) ? 2 : 0) | (e->game << 4));
        r += HOL__REC;
    }
    for (uint32_t i = 0; i <= w->kept_mask && nkept; i++) {
        const hol__kept *k = &w->kept[i];
        if (!k->used || hol__find(w, k->tile) >= 0)
            continue;
        hol__put64(r, k->tile.bits[0]);
        hol__put64(r + 8, k->tile.bits[1]);
        hol__put32(r + 16, 0);
        r[20] = k->state;
        r[21] = k->biome;
        r[22] = k->depth;
        r[23] = (uint8_t)(1 | ((k->used & 2) ? 2 : 0) | 4); /* seen, placed, kept */
        r += HOL__REC;
    }
    qsort(p + HOL__HDR, nrec, HOL__REC, hol__rec_cmp);
    hol__put64(p + need - 8, hol__image_checksum(p, need - 8));
    *out_len = need;
    return HOL_OK;
}

/* ---- loading ---------------------------------------------------------------- */

typedef struct hol__image {
    const uint8_t *p;
    size_t len;
    uint64_t seed;
    uint32_t radius, count, stamp;
    hol_room user;
} hol__image;

static hol_err hol__say(char *msg, size_t cap, hol_err err, const char *fmt,
                        unsigned long long a, unsigned long long b)
{
    if (msg && cap)
        snprintf(msg, cap, fmt, a, b);
    return err;
}

hol_err hol_world_image_size(const void *header, size_t len, uint64_t *out_len, char *msg,
                             size_t msg_cap)
{
    const uint8_t *p = header;
    if (!header || len < 12)
        return hol__say(msg, msg_cap, HOL_ECORRUPT,
                        "truncated: %llu bytes, a world image has at least %llu",
                        (unsigned long long)len, HOL__HDR + 8);
    if (memcmp(p, HOL__MAGIC, 8))
        return hol__say(msg, msg_cap, HOL_ECORRUPT, "not a holonomy world image%.0llu%.0llu",
                        0, 0);
    uint32_t version = hol__get32(p + 8);
    if (version != HOL__VERSION)
        return hol__say(msg, msg_cap, HOL_EVERSION,
                        "format version %llu, this build reads version %llu", version,
                        HOL__VERSION);
    if (len < HOL__HDR)
        return hol__say(msg, msg_cap, HOL_ECORRUPT,
                        "truncated: %llu bytes, a world image has at least %llu",
                        (unsigned long long)len, HOL__HDR + 8);
    if (hol__get32(p + 12) != HOL__REC)
        return hol__say(msg, msg_cap, HOL_ECORRUPT, "record size %llu, expected %llu",
                        hol__get32(p + 12), HOL__REC);
    *out_len = HOL__HDR + (uint64_t)hol__get32(p + 28) * HOL__REC + 8;
    return HOL_OK;
}

/* Header, length, checksum (when `sum`), header fields. */
static hol_err hol__parse_header(const void *buf, size_t len, hol__image *im,
                                 int sum, char *msg, size_t cap)
{
    const uint8_t *p = buf;
    uint64_t expect = 0;
    hol_err err = hol_world_image_size(buf, len, &expect, msg, cap); /* magic, version */
    if (err)
        return err;
    if (len < HOL__HDR + 8)
        return hol__say(msg, cap, HOL_ECORRUPT,
                        "truncated: %llu bytes, a world image has at least %llu",
                        (unsigned long long)len, HOL__HDR + 8);
    im->p = p;
    im->len = len;
    im->seed = hol__get64(p + 16);
    im->radius = hol__get32(p + 24);
    im->count = hol__get32(p + 28);
    im->stamp = hol__get32(p + 32);
    if ((uint64_t)len < expect)
        return hol__say(msg, cap, HOL_ECORRUPT,
                        "truncated: %llu bytes, the header promises %llu",
                        (unsigned long long)len, (unsigned long long)expect);
    if ((uint64_t)len > expect)
        return hol__say(msg, cap, HOL_ECORRUPT,
                        "%llu bytes, but the header promises %llu",
                        (unsigned long long)len, (unsigned long long)expect);
    if (sum && hol__get64(p + len - 8) != hol__image_checksum(p, len - 8))
        return hol__say(msg, cap, HOL_ECORRUPT,
                        "checksum mismatch (corrupted image)%.0llu%.0llu", 0, 0);
    if (im->radius < 1 || im->radius > HOL_WORLD_MAX_RADIUS)
        return hol__say(msg, cap, HOL_ECORRUPT, "radius %llu out of range 1..%llu",
                        im->radius, HOL_WORLD_MAX_RADIUS);
    if (hol__get32(p + 36) || hol__get32(p + 60))
        return hol__say(msg, cap, HOL_ECORRUPT, "reserved header bytes are not zero%.0llu%.0llu",
                        0, 0);
    im->user.tile.bits[0] = hol__get64(p + 40);
    im->user.tile.bits[1] = hol__get64(p + 48);
    im->user.orient = p[56];
    im->user.col = p[57];
    im->user.row = p[58];
    im->user.more_cols = p[59] & 15;
    im->user.more_rows = p[59] >> 4;
    if (!hol__tile_valid(im->user.tile) || !hol_room_ok(&im->user))
        return hol__say(msg, cap, HOL_ECORRUPT, "invalid user state%.0llu%.0llu", 0, 0);
    return HOL_OK;
}

static void hol__decode(const uint8_t *r, hol__rec *out)
{
    out->tile.bits[0] = hol__get64(r);
    out->tile.bits[1] = hol__get64(r + 8);
    out->stamp = hol__get32(r + 16);
    out->state = r[20];
    out->biome = r[21];
    out->depth = r[22];
    out->flags = (uint8_t)(((r[23] & 1) ? HOL__F_SEEN : 0) | ((r[23] & 2) ? HOL__F_PLACED : 0) |
                           ((r[23] & 4) ? HOL__F_KEPT : 0));
    out->game = (uint8_t)(r[23] >> 4);
}

static int hol__image_lookup(const void *ctx, hol_tile t, hol__rec *out)
{
    const hol__image *im = ctx;
    uint8_t key[HOL__REC];
    hol__put64(key, t.bits[0]);
    hol__put64(key + 8, t.bits[1]);
    const uint8_t *r = bsearch(key, im->p + HOL__HDR, im->count, HOL__REC,
                               hol__rec_cmp);
    if (!r)
        return 0;
    hol__decode(r, out);
    return 1;
}

/* An image's reading begun: msg cleared, HOL_EARG without an output
 * (have 0), else its header parsed into *im. */
static hol_err hol__image_begin(const void *buf, size_t len, int have, hol__image *im,
                                char *msg, size_t msg_cap)
{
    if (msg && msg_cap)
        msg[0] = 0;
    if (!have)
        return HOL_EARG;
    return hol__parse_header(buf, len, im, 1, msg, msg_cap);
}

hol_err hol_world_image_desc(const void *buf, size_t len,
                             hol_world_desc *out_desc, char *msg,
                             size_t msg_cap)
{
    hol__image im;
    hol_err err = hol__image_begin(buf, len, out_desc != NULL, &im, msg, msg_cap);
    if (err)
        return err;
    memset(out_desc, 0, sizeof *out_desc);
    out_desc->seed = im.seed;
    out_desc->radius = (int)im.radius;
    out_desc->tiling_q = hol_tile_q(im.user.tile);
    uint64_t cap = HOL_WORLD_DEFAULT_CAPACITY;
    while (cap / 4 * 3 < im.count && cap < (UINT64_C(1) << 31))
        cap <<= 1;
    out_desc->capacity = (uint32_t)cap;
    return HOL_OK;
}

hol_err hol_world_load(hol_world *w, const void *buf, size_t len, char *msg,
                       size_t msg_cap)
{
    hol__image im;
    hol_err err = hol__image_begin(buf, len, w != NULL, &im, msg, msg_cap);
    if (err)
        return err;
    if ((int)im.radius != w->radius)
        return hol__say(msg, msg_cap, HOL_EARG,
                        "image saved with radius %llu, this world has radius %llu",
                        im.radius, (unsigned long long)w->radius);
    if (hol_tile_q(im.user.tile) != w->q)
        return hol__say(msg, msg_cap, HOL_EARG,
                        "image saved in the tiling {4,%llu}, this world is {4,%llu}",
                        (unsigned long long)hol_tile_q(im.user.tile), (unsigned long long)w->q);
    const uint8_t *recs = im.p + HOL__HDR;
    uint32_t nstore = 0, nkept = 0;
    for (uint32_t i = 0; i < im.count; i++) {
        const uint8_t *r = recs + (size_t)i * HOL__REC;
        if (r[23] & 4)
            nkept++;
        else
            nstore++;
    }
    if (nstore > w->cap / 4 * 3)
        return hol__say(msg, msg_cap, HOL_ENOMEM,
                        "image holds %llu tiles, more than 3/4 of the capacity %llu",
                        nstore, w->cap);
    if (nkept > w->kept_max)
        return hol__say(msg, msg_cap, HOL_ENOMEM,
                        "image remembers %llu seen tiles, more than this world keeps (%llu)",
                        nkept, w->kept_max);
    for (uint32_t i = 0; i < im.count; i++) {
        const uint8_t *r = recs + (size_t)i * HOL__REC;
        if (i > 0 && hol__rec_cmp(r - HOL__REC, r) >= 0)
            return hol__say(msg, msg_cap, HOL_ECORRUPT,
                            "record %llu out of order or repeated%.0llu", i, 0);
        if (r[23] & 0x08)
            return hol__say(msg, msg_cap, HOL_ECORRUPT,
                            "record %llu has unknown flags%.0llu", i, 0);
        hol__rec rec;
        hol__decode(r, &rec);
        if (hol_tile_q(rec.tile) != hol_tile_q(im.user.tile))
            return hol__say(msg, msg_cap, HOL_ECORRUPT,
                            "record %llu is a tile of another tiling%.0llu", i, 0);
        if (rec.stamp > im.stamp)
            return hol__say(msg, msg_cap, HOL_ECORRUPT,
                            "record %llu is newer than the image%.0llu", i, 0);
        char why[160];
        err = hol__check_rec(&rec, hol__image_lookup, &im, why, sizeof why);
        if (err) {
            if (msg && msg_cap)
                snprintf(msg, msg_cap, "record %u: %s", i, why);
            return err;
        }
    }
    /* accepted: replace the store and the memory of seen tiles */
    memset(w->entries, 0, (size_t)w->cap * sizeof(hol__entry));
    w->count = 0;
    memset(w->kept, 0, ((size_t)w->kept_mask + 1) * sizeof(hol__kept));
    w->kept_count = 0;
    w->kept_lost = 0;
    for (uint32_t i = 0; i < im.count; i++) {
        hol__rec rec;
        hol__decode(recs + (size_t)i * HOL__REC, &rec);
        if (!(rec.flags & HOL__F_KEPT))
            continue;
        hol__entry e;
        memset(&e, 0, sizeof e);
        e.tile = rec.tile;
        e.state = rec.state;
        e.biome = rec.biome;
        e.depth = rec.depth;
        e.flags = (uint8_t)(rec.flags & HOL__F_PLACED);
        hol__keep(w, &e);
    }
    w->sweep_phase = 0; /* a sweep in progress belonged to the old store */
    w->ready = 0;       /* the next update generates around the user */
    w->seed = im.seed;
    w->stamp = im.stamp;
    w->user = im.user;
    for (uint32_t i = 0; i < im.count; i++) {
        hol__rec rec;
        hol__decode(recs + (size_t)i * HOL__REC, &rec);
        if (rec.flags & HOL__F_KEPT)
            continue;
        int64_t idx = hol__insert(w, rec.tile);
        if (idx < 0)
            return HOL_ENOMEM; /* cannot happen: count <= 3/4 capacity */
        hol__entry *e = &w->entries[idx];
        e->stamp = rec.stamp;
        e->state = rec.state;
        e->biome = rec.biome;
        e->depth = rec.depth;
        e->flags = (uint8_t)(HOL__F_USED | rec.flags);
        e->game = rec.game;
    }
    return HOL_OK;
}
