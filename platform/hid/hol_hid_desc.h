/* hol_hid_desc.h - HID report descriptor parser: descriptor bytes to a map
 * of the input fields (one entry per element).
 *
 * Contract
 * - Pure C11: no OS calls, no allocation, no globals. The caller gives the
 *   field array; the parser's own state (globals, a 4-deep push/pop stack,
 *   the local usage list, per-report offsets) lives on the stack, so every
 *   call is bounded in time (linear in the descriptor and the elements)
 *   and memory.
 * - Items: short items of every main, global and local tag; long items
 *   (0xfe) are skipped. Push/pop, report IDs (1..255), logical and
 *   physical ranges, usage pages, usages with a 4-byte page:usage, usage
 *   ranges, variable and array fields, constant padding (any size,
 *   including 0), collections (nesting checked).
 * - Output: one hol_hid_field per element of every Input item that is not
 *   constant, in descriptor order (SPEC section 6). Output and Feature
 *   items are checked but not listed.
 * - Usage pages are applied at the main item (the page last declared then,
 *   as the HID spec and Linux do), except for 4-byte usages, which carry
 *   their own page. Where an item has fewer usages than elements the last
 *   one repeats.
 * - Logical and physical minimum are read signed in the item's size; the
 *   maximum is read unsigned when the current minimum is not negative
 *   (as Linux reads them).
 * - Errors (HOL_EPARSE, *out_count left 0): a truncated item, report ID 0,
 *   report size above 256 or count above 12288, a data field wider than
 *   32 bits, a report longer than HOL_HID_REPORT_MAX_BYTES, pop without
 *   push, push deeper than 4, end collection without collection,
 *   collections open at the end, more than HOL_HID_MAX_USAGES usages in
 *   one local block, an empty descriptor. More elements than `cap`:
 *   HOL_ENOMEM with *out_count = the number needed (fields[0..cap) filled).
 */
#ifndef HOL_HID_DESC_H
#define HOL_HID_DESC_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_err.h"

#define HOL_HID_REPORT_MAX_BYTES 4096 /* hidraw's largest report */
#define HOL_HID_MAX_USAGES 256        /* usages (or ranges) per local block */
#define HOL_HID_MAX_ELEMENTS 12288    /* report count limit (as Linux) */

/* usages: page in the high 16 bits */
#define HOL_HID_USAGE(page, id) (((uint32_t)(page) << 16) | (uint32_t)(id))
#define HOL_HID_PAGE_DESKTOP 0x0001u
#define HOL_HID_PAGE_SIMULATION 0x0002u
#define HOL_HID_PAGE_BUTTON 0x0009u

typedef enum hol_hid_kind {
    HOL_HID_OTHER = 0,
    HOL_HID_AXIS,   /* Generic Desktop X..Wheel, Simulation rudder, throttle, ... */
    HOL_HID_BUTTON, /* Button page, variable */
    HOL_HID_HAT     /* Generic Desktop hat switch */
} hol_hid_kind;

/* hol_hid_field.flags */
#define HOL_HID_F_ARRAY 1u    /* an element of an array item */
#define HOL_HID_F_RELATIVE 2u /* relative values */
#define HOL_HID_F_NULL 4u     /* has a null state (out of range = none) */

typedef struct hol_hid_field {
    uint8_t report_id;   /* 0 when the descriptor declares none */
    uint8_t kind;        /* hol_hid_kind */
    uint8_t flags;       /* HOL_HID_F_* */
    uint8_t size;        /* bits, 1..32 */
    uint32_t bit_offset; /* in its report, not counting the report ID byte */
    uint32_t usage;      /* page:usage; an array element: page:usage_min */
    uint32_t usage_max;  /* array elements: page:usage_max; else == usage */
    int64_t logical_min, logical_max;
    int64_t physical_min, physical_max;
    uint32_t application; /* page:usage of the enclosing application collection */
} hol_hid_field;

/* Parse desc[0..len). Fills fields[0..min(count, cap)) and *out_count;
 * *out_has_ids (may be NULL) tells whether reports carry an ID byte. */
hol_err hol_hid_desc_parse(const uint8_t *desc, size_t len,
                           hol_hid_field *fields, size_t cap,
                           size_t *out_count, int *out_has_ids);

/* The field's value in a report body (after the ID byte, `len` bytes),
 * sign-extended when its logical minimum is negative. Returns 0 and leaves
 * *out_value alone when the report is too short for the field. */
int hol_hid_field_read(const hol_hid_field *f, const uint8_t *body,
                       size_t len, int64_t *out_value);

/* Classify a page:usage (HOL_HID_AXIS, HOL_HID_BUTTON, HOL_HID_HAT or
 * HOL_HID_OTHER). */
hol_hid_kind hol_hid_usage_kind(uint32_t usage);

#endif
