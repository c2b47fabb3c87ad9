/* hol_face.c - the text face's tables, UTF-8 decoding, widths and
 * wrapping (contract in hol_face.h). */
#include "hol_face.h"

#include <string.h>

#include "hol_face_atlas.h"

_Static_assert(sizeof hol__face_advance / sizeof hol__face_advance[0] == HOL_FACE_NGLYPH,
               "the generated glyph table has the set of hol_face.h");

void hol_face_get_metrics(hol_face_metrics *out_metrics)
{
    static const hol_face_metrics m = {HOL_FACE_UNITS_PER_EM, HOL_FACE_ASCENT, HOL_FACE_DESCENT,
                                       HOL_FACE_LINE_GAP, HOL_FACE_CAP_HEIGHT, HOL_FACE_X_HEIGHT,
                                       HOL_FACE_BAKE_EM, HOL_FACE_SPREAD};
    *out_metrics = m;
}

/* ---- the texels packed (tests/gen_font.c's pack_texels says how) ---- */
#define HOL__PROB_BITS 12
#define HOL__PROB_MOVE 4
#define HOL__NLEVEL_MAX 16

_Static_assert(HOL_FACE_NLEVEL <= HOL__NLEVEL_MAX, "a level is four bits");

typedef struct hol__face_model {
    uint16_t texel[(HOL__NLEVEL_MAX + 1) * HOL__NLEVEL_MAX][HOL__NLEVEL_MAX];
    uint16_t has_ref[2], back[256], dy[128], dx[8];
} hol__face_model;

typedef struct hol__face_rc {
    const uint8_t *in;
    size_t n, at;
    uint32_t range, code;
} hol__face_rc;

static uint32_t hol__rc_byte(hol__face_rc *rc)
{
    return rc->at < rc->n ? rc->in[rc->at++] : 0u;
}

static int hol__rc_bit(hol__face_rc *rc, uint16_t *p)
{
    uint32_t bound = (rc->range >> HOL__PROB_BITS) * *p;
    int bit = rc->code >= bound;
    if (!bit) {
        rc->range = bound;
        *p = (uint16_t)(*p + (((1u << HOL__PROB_BITS) - *p) >> HOL__PROB_MOVE));
    } else {
        rc->range -= bound;
        rc->code -= bound;
        *p = (uint16_t)(*p - (*p >> HOL__PROB_MOVE));
    }
    while (rc->range < (1u << 24)) {
        rc->range <<= 8;
        rc->code = (rc->code << 8) | hol__rc_byte(rc);
    }
    return bit;
}

static int hol__rc_tree(hol__face_rc *rc, uint16_t *probs, int nbits)
{
    int node = 1;
    for (int i = 0; i < nbits; i++)
        node = 2 * node + hol__rc_bit(rc, &probs[node]);
    return node - (1 << nbits);
}

/* Glyph g's level at (r, c) of its rectangle in px; 0 outside. */
static int hol__level_at(const uint8_t *px, const uint8_t level_of[256], const hol_face_glyph *g, int r,
                         int c)
{
    if (r < 0 || c < 0 || r >= g->h || c >= g->w)
        return 0;
    return level_of[px[(size_t)(g->y + r) * HOL_FACE_ATLAS_W + g->x + c]];
}

/* Glyph i's texels from the stream into its rectangle of px; -1 when a
 * level or a reference is out of range. */
static int hol__unpack_glyph(hol__face_rc *rc, hol__face_model *m, const hol_face_packed *p,
                             const uint8_t level_of[256], int i, uint8_t *px)
{
    const hol_face_glyph gv = hol_face_glyph_at(i), *g = &gv;
    hol_face_glyph rv_glyph;
    const hol_face_glyph *ref = NULL;
    int dy = 0, dx = 0;
    if (hol__rc_tree(rc, m->has_ref, 1)) {
        int j = i - hol__rc_tree(rc, m->back, 8);
        dy = hol__rc_tree(rc, m->dy, 7) - 64;
        dx = hol__rc_tree(rc, m->dx, 3) - 4;
        if (j < 0 || j >= i)
            return -1;
        rv_glyph = hol_face_glyph_at(j);
        ref = &rv_glyph;
    }
    for (int r = 0; r < g->h; r++)
        for (int c = 0; c < g->w; c++) {
            int l = hol__level_at(px, level_of, g, r, c - 1), u = hol__level_at(px, level_of, g, r - 1, c);
            int grad = l + u - hol__level_at(px, level_of, g, r - 1, c - 1);
            grad = grad < 0 ? 0 : grad > HOL__NLEVEL_MAX - 1 ? HOL__NLEVEL_MAX - 1 : grad;
            int rv = ref ? hol__level_at(px, level_of, ref, r + dy, c + dx) : HOL__NLEVEL_MAX;
            int v = hol__rc_tree(rc, m->texel[rv * HOL__NLEVEL_MAX + grad], 4);
            if (v >= p->nlevel)
                return -1;
            px[(size_t)(g->y + r) * HOL_FACE_ATLAS_W + g->x + c] = p->levels[v];
        }
    return 0;
}

void hol_face_get_packed(hol_face_packed *out_packed)
{
    *out_packed = (hol_face_packed){hol__face_packed, HOL_FACE_NPACKED, hol__face_levels, HOL_FACE_NLEVEL};
}

int hol_face_unpack(const hol_face_packed *p, uint8_t *out_px)
{
    hol__face_model m;
    uint16_t *prob = &m.texel[0][0];
    for (size_t k = 0; k < sizeof m / sizeof *prob; k++)
        prob[k] = 1u << (HOL__PROB_BITS - 1);
    uint8_t level_of[256] = {0};
    for (int k = 0; k < p->nlevel; k++)
        level_of[p->levels[k]] = (uint8_t)k;
    hol__face_rc rc = {p->bytes, p->n, 0, 0xFFFFFFFFu, 0};
    for (int k = 0; k < 5; k++)
        rc.code = (rc.code << 8) | hol__rc_byte(&rc);
    for (int i = 0; i < HOL_FACE_NGLYPH; i++)
        if (hol__unpack_glyph(&rc, &m, p, level_of, i, out_px) != 0)
            return -1;
    return 0;
}

void hol_face_atlas(uint8_t *out_px, int *out_w, int *out_h)
{
    *out_w = HOL_FACE_ATLAS_W;
    *out_h = HOL_FACE_ATLAS_H;
    if (!out_px)
        return;
    memset(out_px, HOL_FACE_CLEAR, (size_t)HOL_FACE_ATLAS_W * HOL_FACE_ATLAS_H);
#ifdef HOL_FACE_PACKED
    hol_face_packed p;
    hol_face_get_packed(&p);
    (void)hol_face_unpack(&p, out_px); /* never fails: make test unpacks the same bytes */
#else
    for (int i = 0; i < HOL_FACE_NGLYPH; i++)
        for (int r = 0; r < hol__face_h[i]; r++)
            memcpy(out_px + (size_t)(hol__face_y[i] + r) * HOL_FACE_ATLAS_W + hol__face_x[i],
                   hol__face_texels + hol__face_texel_at[i] + (size_t)r * hol__face_w[i], hol__face_w[i]);
#endif
}

#ifndef HOL_FACE_PACKED
_Static_assert(HOL_FACE_NTEXEL <= UINT16_MAX, "the glyphs' starts fit hol__face_texel_at");

const uint8_t *hol_face_texels(int index)
{
    if (index < 0 || index >= HOL_FACE_NGLYPH)
        index = 0;
    return hol__face_texels + hol__face_texel_at[index];
}
#endif

float hol_face_em_per_cap(void)
{
    return (float)HOL_FACE_UNITS_PER_EM / (float)HOL_FACE_CAP_HEIGHT;
}

/* The number of continuation bytes after a lead byte, and the least code
 * point of that length (overlong forms are malformed); -1 if not a lead. */
static int hol__utf8_tail(unsigned char c, uint32_t *out_cp, uint32_t *out_min)
{
    if (c >= 0xC2 && c <= 0xDF) {
        *out_cp = c & 0x1Fu;
        *out_min = 0x80;
        return 1;
    }
    if (c >= 0xE0 && c <= 0xEF) {
        *out_cp = c & 0x0Fu;
        *out_min = 0x800;
        return 2;
    }
    if (c >= 0xF0 && c <= 0xF4) {
        *out_cp = c & 0x07u;
        *out_min = 0x10000;
        return 3;
    }
    return -1;
}

uint32_t hol_face_decode(const char *text, size_t len, size_t *pos)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t at = *pos;
    unsigned char c = s[at];
    if (c < 0x80) {
        *pos = at + 1;
        return c;
    }
    uint32_t cp, min;
    int tail = hol__utf8_tail(c, &cp, &min);
    if (tail < 0 || len - at - 1 < (size_t)tail) {
        *pos = at + 1;
        return HOL_FACE_MALFORMED;
    }
    for (int i = 1; i <= tail; i++) {
        unsigned char t = s[at + (size_t)i];
        if ((t & 0xC0u) != 0x80u) {
            *pos = at + 1;
            return HOL_FACE_MALFORMED;
        }
        cp = (cp << 6) | (t & 0x3Fu);
    }
    if (cp < min || cp > 0x10FFFFu || (cp >= 0xD800u && cp <= 0xDFFFu)) {
        *pos = at + 1;
        return HOL_FACE_MALFORMED;
    }
    *pos = at + 1 + (size_t)tail;
    return cp;
}

size_t hol_face_text_bad(const char *s, size_t n, uint32_t *out_code)
{
    size_t pos = 0;
    while (pos < n) {
        size_t at = pos;
        uint32_t c = hol_face_decode(s, n, &pos);
        if (!((c >= 0x20 && c <= 0x7e) || (c >= 0xa0 && c <= 0xff))) {
            if (out_code)
                *out_code = c;
            return at;
        }
    }
    return n;
}

int hol_face_index(uint32_t code)
{
    if (code >= 0x20 && code <= 0x7E)
        return 1 + (int)(code - 0x20);
    if (code >= 0xA0 && code <= 0xFF)
        return 96 + (int)(code - 0xA0);
    return 0;
}

hol_face_glyph hol_face_glyph_at(int index)
{
    if (index < 0 || index >= HOL_FACE_NGLYPH)
        index = 0;
    uint16_t code = (uint16_t)(index == 0 ? 0 : index <= 95 ? 0x20 + index - 1 : 0xA0 + index - 96);
    return (hol_face_glyph){code, hol__face_advance[index], hol__face_x[index], hol__face_y[index],
                            hol__face_w[index], hol__face_h[index], hol__face_qx[index], hol__face_qy[index]};
}

int hol_face_kerning(int a, int b)
{
    if (a <= 0 || b <= 0)
        return 0;
    int key = (a << 8) | b, lo = 0, hi = HOL_FACE_NKERN - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        int k = (hol__face_kern_a[mid] << 8) | hol__face_kern_b[mid];
        if (k == key)
            return hol__face_kern_units[mid];
        if (k < key)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return 0;
}

long hol_face_units(const char *text, size_t len, int *out_missing)
{
    long units = 0;
    int prev = -1, missing = 0;
    for (size_t pos = 0; pos < len;) {
        int g = hol_face_index(hol_face_decode(text, len, &pos));
        missing += g == 0;
        units += hol__face_advance[g] + hol_face_kerning(prev, g);
        prev = g;
    }
    if (out_missing)
        *out_missing += missing;
    return units;
}

float hol_face_width(const char *text, float size)
{
    size_t len = 0;
    while (text[len])
        len++;
    return (float)((double)hol_face_units(text, len, NULL) * size / HOL_FACE_UNITS_PER_EM);
}

/* A space's rank as a break (the higher, the better) in a prompt of
 * "KEY: action" pairs joined by ", " (hol_face_wrap_pairs): between pairs
 * 3, inside an action 2, inside a key 1, between a key and its action or
 * after a number (a number with its unit: "3 x 3 m") 0. Without pairs
 * every space ranks 1. */
static int hol__break_rank(const char *text, size_t at, size_t start, int pairs)
{
    if (!pairs)
        return 1;
    if (text[start - 1] == ',')
        return 3;
    char b = text[start - 1], a = text[start + 1];
    int times = b == 'x' && start - 1 > at && text[start - 2] == ' ' && a >= '0' && a <= '9';
    if (b == ':' || (b >= '0' && b <= '9') || times) /* "3 x 3 m" whole */
        return 0;
    for (size_t i = start; i > at; i--) { /* a ':' since the pair began */
        if (text[i - 1] == ',')
            return 1;
        if (text[i - 1] == ':')
            return 2;
    }
    return 1;
}

/* The end of the line that starts at `at` (no leading blank): out_end past
 * its last byte to draw (trailing blanks included), out_next where the next
 * line's search starts. The break: the last space of the best rank. */
static void hol__line_end(const char *text, size_t len, long max_units, size_t at, int pairs,
                          size_t *out_end, size_t *out_next)
{
    long units = 0;
    int prev = -1, rank = -1;
    size_t pos = at, brk = 0;
    while (pos < len && text[pos] != '\n') {
        size_t start = pos;
        int g = hol_face_index(hol_face_decode(text, len, &pos));
        long w = hol__face_advance[g] + hol_face_kerning(prev, g);
        if (text[start] == ' ') {
            int r = start > at && text[start - 1] != ' ' ? hol__break_rank(text, at, start, pairs)
                                                         : -1;
            if (r >= 0 && r >= rank) {
                brk = start;
                rank = r;
            }
        } else if (units + w > max_units && start > at) {
            *out_end = *out_next = brk ? brk : start;
            return;
        }
        units += w;
        prev = g;
    }
    *out_end = pos;
    *out_next = pos < len ? pos + 1 : pos;
}

static int hol__wrap(const char *text, float size, float width, int pairs, hol_face_line *out,
                     int max)
{
    size_t len = 0;
    while (text[len])
        len++;
    double mu = size > 0 ? (double)width * HOL_FACE_UNITS_PER_EM / size : 0;
    long max_units = mu < 0 ? 0 : mu > 1e9 ? 1000000000L : (long)mu;
    int n = 0;
    size_t at = 0;
    while (at < len && text[at] == ' ')
        at++;
    while (at < len) {
        size_t end, next;
        hol__line_end(text, len, max_units, at, pairs, &end, &next);
        while (end > at && text[end - 1] == ' ')
            end--;
        if (out && n < max) {
            out[n].start = at;
            out[n].len = end - at;
        }
        n++;
        at = next;
        while (at < len && text[at] == ' ')
            at++;
    }
    return n;
}

int hol_face_wrap(const char *text, float size, float width, hol_face_line *out, int max)
{
    return hol__wrap(text, size, width, 0, out, max);
}

int hol_face_wrap_pairs(const char *text, float size, float width, hol_face_line *out, int max)
{
    return hol__wrap(text, size, width, 1, out, max);
}
