/* hol_hid_desc.c - HID report descriptor parser (see hol_hid_desc.h). */
#include "hol_hid_desc.h"

#include <string.h>

#define STACK_DEPTH 4
#define COLLECTION_DEPTH 64
#define MAX_REPORT_SIZE 256

typedef struct hid_globals {
    uint32_t usage_page;
    int64_t logical_min, logical_max;
    int64_t physical_min, physical_max;
    uint32_t report_size, report_count, report_id;
} hid_globals;

typedef struct hid_usage {
    uint32_t min, max; /* full page:usage; a single usage has min == max */
    uint8_t ext;       /* declared with 4 bytes: carries its own page */
} hid_usage;

typedef struct hid_parser {
    hid_globals g;
    hid_globals stack[STACK_DEPTH];
    int depth;
    hid_usage usages[HOL_HID_MAX_USAGES];
    int n_usages;
    uint32_t pend_min, pend_max; /* usage range halves not yet paired */
    uint8_t have_min, have_max, min_page, max_page;
    int collections;
    uint32_t app[COLLECTION_DEPTH];
    int has_ids;
    uint32_t in_bits[256];  /* input report lengths so far, per report ID */
    uint32_t out_bits[256]; /* output and feature (checked, not listed) */
    uint32_t feat_bits[256];
} hid_parser;

hol_hid_kind hol_hid_usage_kind(uint32_t usage)
{
    uint32_t page = usage >> 16, id = usage & 0xffffu;
    if (page == HOL_HID_PAGE_BUTTON)
        return HOL_HID_BUTTON;
    if (page == HOL_HID_PAGE_DESKTOP) {
        if (id == 0x39)
            return HOL_HID_HAT;
        if (id >= 0x30 && id <= 0x38)
            return HOL_HID_AXIS;
    }
    if (page == HOL_HID_PAGE_SIMULATION && id >= 0xb0 && id <= 0xc5)
        return HOL_HID_AXIS;
    return HOL_HID_OTHER;
}

static void clear_locals(hid_parser *p)
{
    p->n_usages = 0;
    p->have_min = p->have_max = 0;
}

/* A usage (or range) gets the usage page current when it is declared,
 * unless it was declared with 4 bytes (as Linux's hid_add_usage). */
static int add_usage(hid_parser *p, uint32_t min, uint32_t max, int ext)
{
    if (p->n_usages == HOL_HID_MAX_USAGES)
        return -1;
    hid_usage *u = &p->usages[p->n_usages++];
    uint32_t page = ext ? min & 0xffff0000u : p->g.usage_page << 16;
    u->min = page | (min & 0xffffu);
    u->max = page | (max & 0xffffu);
    u->ext = (uint8_t)ext;
    return 0;
}

/* At a main item, the page declared last also applies to the short usages
 * declared before it, back to the first one already on that page (Linux's
 * hid_concatenate_last_usage_page). */
static void concat_last_page(hid_parser *p)
{
    uint32_t page = p->g.usage_page << 16;
    for (int i = p->n_usages - 1; i >= 0; i--) {
        hid_usage *u = &p->usages[i];
        if (u->ext)
            continue;
        if ((u->min & 0xffff0000u) == page)
            break;
        u->min = page | (u->min & 0xffffu);
        u->max = page | (u->max & 0xffffu);
    }
}

/* A range is complete once both halves are declared (either order). */
static int try_range(hid_parser *p)
{
    if (!p->have_min || !p->have_max)
        return 0;
    p->have_min = p->have_max = 0;
    uint32_t min = p->pend_min, max = p->pend_max;
    int ext = p->min_page || p->max_page;
    if (!p->min_page && p->max_page)
        min |= max & 0xffff0000u;
    if (p->min_page && !p->max_page)
        max |= min & 0xffff0000u;
    if (!ext)
        min &= 0xffffu, max &= 0xffffu;
    if (max < min || (max >> 16) != (min >> 16))
        return -1;
    return add_usage(p, min, max, ext);
}

/* The usage of element i: walk the list; past its end the last repeats. */
static uint32_t element_usage(const hid_parser *p, uint32_t i)
{
    if (p->n_usages == 0)
        return HOL_HID_USAGE(p->g.usage_page, 0);
    for (int k = 0; k < p->n_usages; k++) {
        const hid_usage *u = &p->usages[k];
        uint32_t span = u->max - u->min + 1;
        if (i < span)
            return u->min + i;
        i -= span;
    }
    const hid_usage *last = &p->usages[p->n_usages - 1];
    return last->max;
}

static hol_err main_item(hid_parser *p, unsigned tag, uint32_t data,
                         hol_hid_field *fields, size_t cap, size_t *n)
{
    uint32_t id = p->g.report_id;
    uint32_t *bits = tag == 0x8 ? p->in_bits : tag == 0x9 ? p->out_bits
                                                          : p->feat_bits;
    uint32_t size = p->g.report_size, count = p->g.report_count;
    if (size > MAX_REPORT_SIZE || count > HOL_HID_MAX_ELEMENTS)
        return HOL_EPARSE;
    int constant = data & 1u, array = !(data & 2u);
    if (!constant && size > 32 && count > 0)
        return HOL_EPARSE;
    uint64_t end = (uint64_t)bits[id] + (uint64_t)size * count;
    if (end > 8u * HOL_HID_REPORT_MAX_BYTES - (p->has_ids ? 8u : 0u))
        return HOL_EPARSE;
    if (tag == 0x8 && !constant && size > 0) {
        uint32_t umin = 0, umax = 0;
        if (array) {
            /* the item's usage range: page of the first, min..max ids */
            uint32_t first = element_usage(p, 0);
            umin = umax = first;
            for (int k = 0; k < p->n_usages; k++) {
                const hid_usage *u = &p->usages[k];
                uint32_t lo = u->min, hi = u->max;
                if ((lo >> 16) != (first >> 16))
                    continue;
                if (lo < umin)
                    umin = lo;
                if (hi > umax)
                    umax = hi;
            }
        }
        for (uint32_t i = 0; i < count; i++, (*n)++) {
            if (*n >= cap)
                continue;
            hol_hid_field *f = &fields[*n];
            memset(f, 0, sizeof *f);
            f->report_id = (uint8_t)id;
            f->size = (uint8_t)size;
            f->bit_offset = bits[id] + i * size;
            f->usage = array ? umin : element_usage(p, i);
            f->usage_max = array ? umax : f->usage;
            f->flags = (uint8_t)((array ? HOL_HID_F_ARRAY : 0) |
                                 ((data & 4u) ? HOL_HID_F_RELATIVE : 0) |
                                 ((data & 0x40u) ? HOL_HID_F_NULL : 0));
            f->kind = array ? HOL_HID_OTHER : (uint8_t)hol_hid_usage_kind(f->usage);
            f->logical_min = p->g.logical_min;
            f->logical_max = p->g.logical_max;
            f->physical_min = p->g.physical_min;
            f->physical_max = p->g.physical_max;
            f->application = p->collections > 0
                ? p->app[p->collections - 1] : 0;
        }
    }
    bits[id] = (uint32_t)end;
    return HOL_OK;
}

/* A main item: Input, Output, Feature (fields), Collection, End Collection. */
static hol_err main_tag(hid_parser *p, unsigned tag, uint32_t u, hol_hid_field *fields,
                        size_t cap, size_t *n)
{
    hol_err err = HOL_OK;
    concat_last_page(p);
    switch (tag) {
    case 0x8: case 0x9: case 0xb:
        err = main_item(p, tag, u, fields, cap, n);
        break;
    case 0xa: {
        if (p->collections == COLLECTION_DEPTH)
            return HOL_EPARSE;
        /* the usage naming this collection (application) */
        uint32_t cu = element_usage(p, 0);
        uint32_t parent = p->collections ? p->app[p->collections - 1] : 0;
        p->app[p->collections++] = (u & 0xff) == 1 ? cu : parent;
        break;
    }
    case 0xc:
        if (p->collections == 0)
            return HOL_EPARSE;
        p->collections--;
        break;
    default:
        return HOL_EPARSE;
    }
    clear_locals(p);
    return err;
}

/* A global item (u unsigned, s signed: the same data). */
static hol_err global_tag(hid_parser *p, unsigned tag, uint32_t u, int64_t s)
{
    switch (tag) {
    case 0x0: p->g.usage_page = u & 0xffffu; break;
    case 0x1: p->g.logical_min = s; break;
    case 0x2: p->g.logical_max = p->g.logical_min < 0 ? s : (int64_t)u; break;
    case 0x3: p->g.physical_min = s; break;
    case 0x4: p->g.physical_max = p->g.physical_min < 0 ? s : (int64_t)u; break;
    case 0x5: case 0x6: break; /* unit exponent, unit */
    case 0x7:
        if (u > MAX_REPORT_SIZE)
            return HOL_EPARSE;
        p->g.report_size = u;
        break;
    case 0x8:
        if (u == 0 || u > 255)
            return HOL_EPARSE;
        p->g.report_id = u;
        p->has_ids = 1;
        break;
    case 0x9:
        if (u > HOL_HID_MAX_ELEMENTS)
            return HOL_EPARSE;
        p->g.report_count = u;
        break;
    case 0xa:
        if (p->depth == STACK_DEPTH)
            return HOL_EPARSE;
        p->stack[p->depth++] = p->g;
        break;
    case 0xb:
        if (p->depth == 0)
            return HOL_EPARSE;
        p->g = p->stack[--p->depth];
        break;
    default:
        return HOL_EPARSE;
    }
    return HOL_OK;
}

/* A local item: usages (a 4-byte one carries its page). */
static hol_err local_tag(hid_parser *p, unsigned tag, uint32_t u, size_t dsize)
{
    switch (tag) {
    case 0x0:
        return add_usage(p, u, u, dsize == 4) ? HOL_EPARSE : HOL_OK;
    case 0x1:
        p->pend_min = u;
        p->min_page = dsize == 4;
        p->have_min = 1;
        return try_range(p) ? HOL_EPARSE : HOL_OK;
    case 0x2:
        p->pend_max = u;
        p->max_page = dsize == 4;
        p->have_max = 1;
        return try_range(p) ? HOL_EPARSE : HOL_OK;
    default: /* designators, strings, delimiters: not used */
        return HOL_OK;
    }
}

hol_err hol_hid_desc_parse(const uint8_t *desc, size_t len,
                           hol_hid_field *fields, size_t cap,
                           size_t *out_count, int *out_has_ids)
{
    hid_parser p;
    memset(&p, 0, sizeof p);
    size_t n = 0;
    hol_err err = HOL_OK;
    *out_count = 0;
    if (out_has_ids)
        *out_has_ids = 0;
    if (!desc || len == 0)
        return HOL_EPARSE;
    size_t i = 0;
    while (i < len && !err) {
        uint8_t prefix = desc[i];
        if (prefix == 0xfe) { /* long item: size, tag, data */
            if (len - i < 3 || len - i - 3 < desc[i + 1])
                return HOL_EPARSE;
            i += 3 + (size_t)desc[i + 1];
            continue;
        }
        size_t dsize = (size_t[]){0, 1, 2, 4}[prefix & 3];
        if (len - i - 1 < dsize)
            return HOL_EPARSE;
        uint32_t u = 0;
        for (size_t k = 0; k < dsize; k++)
            u |= (uint32_t)desc[i + 1 + k] << (8 * k);
        int64_t s = dsize == 1 ? (int64_t)(int8_t)u
                  : dsize == 2 ? (int64_t)(int16_t)u
                  : dsize == 4 ? (int64_t)(int32_t)u : 0;
        i += 1 + dsize;
        unsigned type = (prefix >> 2) & 3, tag = prefix >> 4;
        err = type == 0   ? main_tag(&p, tag, u, fields, cap, &n)
              : type == 1 ? global_tag(&p, tag, u, s)
              : type == 2 ? local_tag(&p, tag, u, dsize)
                          : HOL_EPARSE; /* reserved item type */
    }
    if (err)
        return err;
    if (p.collections != 0)
        return HOL_EPARSE;
    *out_count = n;
    if (out_has_ids)
        *out_has_ids = p.has_ids;
    return n > cap ? HOL_ENOMEM : HOL_OK;
}

int hol_hid_field_read(const hol_hid_field *f, const uint8_t *body,
                       size_t len, int64_t *out_value)
{
    uint32_t off = f->bit_offset, size = f->size;
    if (size == 0 || size > 32 || (uint64_t)off + size > (uint64_t)len * 8)
        return 0;
    uint64_t v = 0;
    uint32_t first = off / 8, last = (off + size - 1) / 8;
    for (uint32_t b = last + 1; b-- > first;)
        v = (v << 8) | body[b];
    v >>= off % 8;
    v &= size == 32 ? 0xffffffffu : ((1ull << size) - 1);
    int64_t val = (int64_t)v;
    if (f->logical_min < 0 && size < 64 && (v >> (size - 1)) & 1)
        val -= (int64_t)1 << size;
    *out_value = val;
    return 1;
}
