/* gen_font.c - bakes the text face (DejaVu Sans) into a single-channel
 * signed-distance atlas and prints core/hol_face_atlas.h.
 *
 *   make gen-font              rewrite core/hol_face_atlas.h
 *   build/tests/gen_font [TTF] print it (make test compares the two)
 *
 * Method
 * 1. The glyph set: index 0 is the font's own missing-glyph box (.notdef),
 *    then printable ASCII U+0020..U+007E, then Latin-1 U+00A0..U+00FF, in
 *    code order (core/hol_face.c maps a code point to its index by
 *    arithmetic).
 * 2. Each glyph's distance field by stb_truetype (stbtt_GetGlyphSDF) at
 *    BAKE_EM pixels per em with PAD pixels of border: a texel holds
 *    128 + 128 * d / SPREAD clamped to 0..255, d the signed distance to the
 *    outline in atlas pixels (positive inside), so the field is meaningful
 *    to SPREAD atlas pixels either side of the edge. Texels are
 *    then rounded to multiples of QUANT (the edge value stays exact): the
 *    linear filter in between gives back the sub-level precision, and the
 *    atlas gzips to about half.
 * 3. Shelf packing, tallest first (ties in glyph order), into a fixed
 *    ATLAS_W wide atlas, with one clear texel between glyphs so bilinear
 *    filtering never reads a neighbour. The header holds each glyph's
 *    texels, glyph after glyph, and its place: core/hol_face.c writes the
 *    atlas from them (the clear texels left out gzip to 1.7 KB of the
 *    web's transfer). The same texels follow packed (pack_texels): the
 *    web build holds only those and decodes them (2.2 KB less transfer).
 * 4. Metrics in font units (advance, ascent, descent, line gap, cap and x
 *    height) and each glyph's quad in atlas pixels relative to the pen on
 *    the baseline (y down); kerning of every pair of the set the font's
 *    kern/GPOS tables give a non-zero value (stbtt_GetGlyphKernAdvance).
 * The output depends on stb_truetype's version and the font file only;
 * make test checks that the committed header is what this prints.
 */
#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BAKE_EM 19   /* atlas pixels per em */
#define PAD 2        /* border around each glyph, atlas pixels */
#define SPREAD 2     /* distance (atlas pixels) at which the field saturates */
#define QUANT 16     /* texels rounded to multiples of this */
#define ATLAS_W 256
#define ATLAS_HMAX 1024
#define CLEAR 1      /* the texels outside every glyph (far outside) */
#define NGLYPH (1 + 95 + 96)
/* Data, not code, in a few long lines (each column of the glyph and
 * kerning tables in one, the texels' starts in six, the texels 1024 a
 * line): a reader of the header wants the definitions at its top,
 * and a search for repeated code passes over lines this long. */
#define GLYPHS_A_LINE ((NGLYPH + 5) / 6)
#define TEXELS_A_LINE (4 * ATLAS_W)
#define NKERNED (1 + 95) /* kerning between ASCII glyphs only (size) */

typedef struct {
    int code, gi, adv, w, h, xoff, yoff, x, y;
    unsigned char *sdf;
} glyph;

static glyph g_glyphs[NGLYPH];
static unsigned char g_atlas[ATLAS_W * ATLAS_HMAX];

static int code_of(int i)
{
    if (i == 0)
        return 0;
    return i <= 95 ? 0x20 + i - 1 : 0xA0 + i - 96;
}

static unsigned char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = malloc((size_t)n);
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    return buf;
}

static int by_height(const void *a, const void *b)
{
    const glyph *p = *(const glyph *const *)a, *q = *(const glyph *const *)b;
    if (p->h != q->h)
        return q->h - p->h;
    return p->code - q->code;
}

static int pack(void)
{
    glyph *order[NGLYPH];
    for (int i = 0; i < NGLYPH; i++)
        order[i] = &g_glyphs[i];
    qsort(order, NGLYPH, sizeof order[0], by_height);
    memset(g_atlas, CLEAR, sizeof g_atlas);
    int x = 1, y = 1, shelf = 0;
    for (int i = 0; i < NGLYPH; i++) {
        glyph *g = order[i];
        if (!g->sdf)
            continue;
        if (x + g->w + 1 > ATLAS_W) {
            x = 1;
            y += shelf + 1;
            shelf = 0;
        }
        if (y + g->h + 1 > ATLAS_HMAX)
            return -1;
        g->x = x;
        g->y = y;
        for (int r = 0; r < g->h; r++)
            memcpy(g_atlas + (size_t)(y + r) * ATLAS_W + x, g->sdf + (size_t)r * g->w, (size_t)g->w);
        x += g->w + 1;
        if (g->h > shelf)
            shelf = g->h;
    }
    return y + shelf + 1;
}

static void quantise(unsigned char *p, int n)
{
    for (int i = 0; i < n; i++) {
        int v = p[i], q = 128 + ((v - 128 + (v >= 128 ? QUANT / 2 : -(QUANT / 2))) / QUANT) * QUANT;
        p[i] = (unsigned char)(q < 1 ? 1 : q > 255 ? 255 : q);
    }
}

/* ---- the texels packed (core/hol_face.c's hol_face_unpack reads them) ----
 * Each texel is coded as its level's index (the distinct texel values,
 * ascending) by an adaptive binary range coder (LZMA's: 12-bit
 * probabilities, moved by 1/16), four bits from the top through a tree
 * whose probabilities are chosen by the context: the level the glyph's
 * reference has at the same place (NLEVEL_MAX when it has none) and the
 * gradient predictor clamp(left + up - upleft) (outside the rectangle: 0).
 * A glyph's reference is the earlier glyph, moved by (dy, dx), whose
 * levels differ from its own at the fewest places (fewer than from blank:
 * else none): an accented letter reads its letter. Before each glyph's
 * texels: one bit (a reference or not), then the glyph's index less the
 * reference's (8 bits), dy + 64 (7 bits), dx + 4 (3 bits), each through a
 * tree of its own. The web build decodes them (HOL_FACE_PACKED); gzip
 * takes the raw texels to 9.4 KB, this packs them into 7.3 KB. */
#define NLEVEL_MAX 16
#define PROB_BITS 12
#define PROB_MOVE 4
#define REF_DX 2

typedef struct {
    uint16_t texel[(NLEVEL_MAX + 1) * NLEVEL_MAX][NLEVEL_MAX];
    uint16_t has_ref[2], back[256], dy[128], dx[8];
} pack_model;

typedef struct {
    uint64_t low;
    uint32_t range;
    unsigned char cache;
    size_t cache_n, n;
    unsigned char out[ATLAS_W * ATLAS_HMAX];
} rc_enc;

static int g_level_of[256];
static int g_levels[NLEVEL_MAX], g_nlevel;

static void rc_shift_low(rc_enc *rc)
{
    if ((uint32_t)rc->low < 0xFF000000u || (rc->low >> 32) != 0) {
        unsigned char carry = (unsigned char)(rc->low >> 32), temp = rc->cache;
        do {
            rc->out[rc->n++] = (unsigned char)(temp + carry);
            temp = 0xFF;
        } while (--rc->cache_n != 0);
        rc->cache = (unsigned char)(rc->low >> 24);
    }
    rc->cache_n++;
    rc->low = (rc->low & 0x00FFFFFFu) << 8;
}

static void rc_bit(rc_enc *rc, uint16_t *p, int bit)
{
    uint32_t bound = (rc->range >> PROB_BITS) * *p;
    if (!bit) {
        rc->range = bound;
        *p = (uint16_t)(*p + (((1u << PROB_BITS) - *p) >> PROB_MOVE));
    } else {
        rc->low += bound;
        rc->range -= bound;
        *p = (uint16_t)(*p - (*p >> PROB_MOVE));
    }
    while (rc->range < (1u << 24)) {
        rc->range <<= 8;
        rc_shift_low(rc);
    }
}

static void rc_tree(rc_enc *rc, uint16_t *probs, int nbits, int v)
{
    int node = 1;
    for (int i = nbits - 1; i >= 0; i--) {
        int bit = (v >> i) & 1;
        rc_bit(rc, &probs[node], bit);
        node = 2 * node + bit;
    }
}

/* Glyph g's level at (r, c) of its rectangle; 0 outside. */
static int level_at(const glyph *g, int r, int c)
{
    if (r < 0 || c < 0 || r >= g->h || c >= g->w)
        return 0;
    return g_level_of[g_atlas[(size_t)(g->y + r) * ATLAS_W + g->x + c]];
}

typedef struct {
    int ref, dy, dx; /* ref -1: none */
} pack_ref;

/* The places where glyph i's levels differ from j's moved by (dy, dx),
 * counting up to `most`. */
static int ref_misses(int i, int j, int dy, int dx, int most)
{
    const glyph *g = &g_glyphs[i], *h = &g_glyphs[j];
    int n = 0;
    for (int r = 0; r < g->h && n < most; r++)
        for (int c = 0; c < g->w; c++)
            n += level_at(g, r, c) != (j < 0 ? 0 : level_at(h, r + dy, c + dx));
    return n;
}

static pack_ref find_ref(int i)
{
    pack_ref best = {-1, 0, 0};
    int most = ref_misses(i, -1, 0, 0, 1 << 30);
    for (int j = 0; j < i; j++) {
        const glyph *h = &g_glyphs[j];
        if (h->w == 0 || i - j > 255)
            continue;
        for (int dy = -(g_glyphs[i].h - 1); dy < h->h; dy++)
            for (int dx = -REF_DX; dx <= REF_DX; dx++) {
                if (dy + 64 < 0 || dy + 64 > 127)
                    continue;
                int n = ref_misses(i, j, dy, dx, most);
                if (n < most) {
                    most = n;
                    best = (pack_ref){j, dy, dx};
                }
            }
    }
    return best;
}

static void pack_glyph(rc_enc *rc, pack_model *m, int i)
{
    const glyph *g = &g_glyphs[i];
    pack_ref ref = find_ref(i);
    rc_tree(rc, m->has_ref, 1, ref.ref >= 0);
    if (ref.ref >= 0) {
        rc_tree(rc, m->back, 8, i - ref.ref);
        rc_tree(rc, m->dy, 7, ref.dy + 64);
        rc_tree(rc, m->dx, 3, ref.dx + 4);
    }
    for (int r = 0; r < g->h; r++)
        for (int c = 0; c < g->w; c++) {
            int l = level_at(g, r, c - 1), u = level_at(g, r - 1, c), ul = level_at(g, r - 1, c - 1);
            int grad = l + u - ul < 0 ? 0 : l + u - ul > NLEVEL_MAX - 1 ? NLEVEL_MAX - 1 : l + u - ul;
            int rv = ref.ref >= 0 ? level_at(&g_glyphs[ref.ref], r + ref.dy, c + ref.dx) : NLEVEL_MAX;
            rc_tree(rc, m->texel[rv * NLEVEL_MAX + grad], 4, level_at(g, r, c));
        }
}

/* The levels, and every glyph's texels packed into rc->out. */
static int pack_texels(rc_enc *rc)
{
    static pack_model m;
    int seen[256] = {0};
    for (int i = 0; i < NGLYPH; i++)
        for (int r = 0; r < g_glyphs[i].h; r++)
            for (int c = 0; c < g_glyphs[i].w; c++)
                seen[g_atlas[(size_t)(g_glyphs[i].y + r) * ATLAS_W + g_glyphs[i].x + c]] = 1;
    g_nlevel = 0;
    for (int v = 0; v < 256; v++)
        if (seen[v]) {
            if (g_nlevel == NLEVEL_MAX)
                return -1;
            g_level_of[v] = g_nlevel;
            g_levels[g_nlevel++] = v;
        }
    uint16_t *p = &m.texel[0][0];
    for (size_t k = 0; k < sizeof m / sizeof *p; k++)
        p[k] = 1u << (PROB_BITS - 1);
    *rc = (rc_enc){.range = 0xFFFFFFFFu, .cache_n = 1};
    for (int i = 0; i < NGLYPH; i++)
        pack_glyph(rc, &m, i);
    for (int k = 0; k < 5; k++)
        rc_shift_low(rc);
    return 0;
}

/* One column of a table: its n values on one line. */
static void print_column(const char *type, const char *name, const char *count, const int *v, int n)
{
    printf("static const %s %s[%s] = {\n    ", type, name, count);
    for (int i = 0; i < n; i++)
        printf("%d,", v[i]);
    printf("\n};\n");
}

/* The kerning pairs as three columns (a table of columns gzips smaller
 * than one of rows: the web's transfer). */
static void print_kerning(const stbtt_fontinfo *font)
{
    static int col[3][NKERNED * NKERNED];
    int n = 0;
    for (int a = 1; a < NKERNED; a++)
        for (int b = 1; b < NKERNED; b++) {
            int k = stbtt_GetGlyphKernAdvance(font, g_glyphs[a].gi, g_glyphs[b].gi);
            if (k == 0 || !g_glyphs[a].gi || !g_glyphs[b].gi)
                continue;
            col[0][n] = a;
            col[1][n] = b;
            col[2][n++] = k;
        }
    printf("#define HOL_FACE_NKERN %d\n"
           "/* the kerning pairs: first glyph, second glyph, font units; sorted by\n"
           " * first then second */\n",
           n);
    print_column("uint8_t", "hol__face_kern_a", "HOL_FACE_NKERN", col[0], n);
    print_column("uint8_t", "hol__face_kern_b", "HOL_FACE_NKERN", col[1], n);
    print_column("int16_t", "hol__face_kern_units", "HOL_FACE_NKERN", col[2], n);
    printf("\n");
}

/* The glyphs' texels, glyph after glyph, each its rectangle's rows (the
 * clear texels between them left out: the web's transfer), and where each
 * glyph's start. */
static void print_texels(void)
{
    int n = 0;
    printf("#ifndef HOL_FACE_PACKED\n"
           "/* where each glyph's texels start in hol__face_texels */\n"
           "static const uint16_t hol__face_texel_at[%d] = {\n",
           NGLYPH);
    for (int i = 0; i < NGLYPH; i++) {
        printf("%s%d,%s", i % GLYPHS_A_LINE ? "" : "    ", n, i % GLYPHS_A_LINE == GLYPHS_A_LINE - 1 ? "\n" : "");
        n += g_glyphs[i].w * g_glyphs[i].h;
    }
    printf("%s};\n\n", NGLYPH % GLYPHS_A_LINE ? "\n" : "");
    printf("#define HOL_FACE_NTEXEL %d\n"
           "/* each glyph's w * h texels, rows top to bottom, in glyph order; the\n"
           " * atlas's other texels are HOL_FACE_CLEAR */\n"
           "static const uint8_t hol__face_texels[HOL_FACE_NTEXEL] = {\n",
           n);
    int k = 0;
    for (int i = 0; i < NGLYPH; i++) {
        const glyph *g = &g_glyphs[i];
        for (int r = 0; r < g->h; r++)
            for (int c = 0; c < g->w; c++, k++)
                printf("%s%d,%s", k % TEXELS_A_LINE == 0 ? "    " : "",
                       g_atlas[(size_t)(g->y + r) * ATLAS_W + g->x + c],
                       k % TEXELS_A_LINE == TEXELS_A_LINE - 1 ? "\n" : "");
    }
    printf("%s};\n#endif\n\n", k % TEXELS_A_LINE ? "\n" : "");
}

/* The same texels packed (pack_texels): the levels and the bytes. */
static int print_packed(void)
{
    static rc_enc rc;
    if (pack_texels(&rc) != 0)
        return -1;
    printf("#define HOL_FACE_NLEVEL %d\n"
           "/* the texels' values, ascending: the packed texels are their indices */\n"
           "static const uint8_t hol__face_levels[HOL_FACE_NLEVEL] = {",
           g_nlevel);
    for (int i = 0; i < g_nlevel; i++)
        printf("%d%s", g_levels[i], i + 1 < g_nlevel ? "," : "};\n\n");
    printf("#define HOL_FACE_NPACKED %zu\n"
           "/* the glyphs' texels packed (tests/gen_font.c's pack_texels; hol_face_unpack) */\n"
           "static const uint8_t hol__face_packed[HOL_FACE_NPACKED] = {\n",
           rc.n);
    for (size_t k = 0; k < rc.n; k++)
        printf("%s%d,%s", k % TEXELS_A_LINE == 0 ? "    " : "", rc.out[k],
               k % TEXELS_A_LINE == TEXELS_A_LINE - 1 ? "\n" : "");
    printf("%s};\n\n#endif\n", rc.n % TEXELS_A_LINE ? "\n" : "");
    return 0;
}

static void print_header(const stbtt_fontinfo *font, int atlas_h)
{
    int asc, desc, gap, x0, y0, x1, y1;
    stbtt_GetFontVMetrics(font, &asc, &desc, &gap);
    printf("/* hol_face_atlas.h - GENERATED by tests/gen_font.c from DejaVu Sans\n"
           " * (fonts-dejavu-core); do not edit: `make gen-font` rewrites it.\n"
           " * Included by core/hol_face.c only; the contract is core/hol_face.h.\n"
           " * DejaVu fonts: Bitstream Vera license and public domain changes. */\n"
           "#ifndef HOL_FACE_ATLAS_INCLUDED\n#define HOL_FACE_ATLAS_INCLUDED\n\n");
    printf("#define HOL_FACE_UNITS_PER_EM %d\n", (int)(1.0f / stbtt_ScaleForMappingEmToPixels(font, 1.0f) + 0.5f));
    printf("#define HOL_FACE_ASCENT %d\n#define HOL_FACE_DESCENT %d\n#define HOL_FACE_LINE_GAP %d\n", asc, desc, gap);
    stbtt_GetCodepointBox(font, 'H', &x0, &y0, &x1, &y1);
    printf("#define HOL_FACE_CAP_HEIGHT %d\n", y1);
    stbtt_GetCodepointBox(font, 'x', &x0, &y0, &x1, &y1);
    printf("#define HOL_FACE_X_HEIGHT %d\n", y1);
    printf("#define HOL_FACE_BAKE_EM %d\n#define HOL_FACE_SPREAD %d\n", BAKE_EM, SPREAD);
    printf("#define HOL_FACE_ATLAS_W %d\n#define HOL_FACE_ATLAS_H %d\n", ATLAS_W, atlas_h);
    printf("#define HOL_FACE_CLEAR %d\n\n", CLEAR);
    static int col[7][NGLYPH];
    for (int i = 0; i < NGLYPH; i++) {
        const glyph *g = &g_glyphs[i];
        int v[7] = {g->adv, g->x, g->y, g->w, g->h, g->xoff, g->yoff};
        for (int k = 0; k < 7; k++)
            col[k][i] = v[k];
    }
    printf("/* each glyph's advance (font units), atlas rectangle (x, y, w, h) and\n"
           " * quad's top-left (x, y: atlas pixels from the pen on the baseline, y\n"
           " * down), by glyph index (index 0 is the missing box), as columns */\n");
    static const char *const names[7] = {"advance", "x", "y", "w", "h", "qx", "qy"};
    for (int k = 0; k < 7; k++) {
        char name[32];
        snprintf(name, sizeof name, "hol__face_%s", names[k]);
        print_column(k == 0 ? "uint16_t" : k < 5 ? "uint8_t" : "int8_t", name, "HOL_FACE_NGLYPH", col[k], NGLYPH);
    }
    printf("\n");
    print_kerning(font);
    print_texels();
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    const char *raw = argc > 2 ? argv[2] : NULL; /* optional: the atlas's bytes, to measure */
    unsigned char *ttf = read_file(path);
    stbtt_fontinfo font;
    if (!ttf || !stbtt_InitFont(&font, ttf, stbtt_GetFontOffsetForIndex(ttf, 0))) {
        fprintf(stderr, "gen_font: cannot read the font %s\n", path);
        return 1;
    }
    float scale = stbtt_ScaleForMappingEmToPixels(&font, (float)BAKE_EM);
    for (int i = 0; i < NGLYPH; i++) {
        glyph *g = &g_glyphs[i];
        g->code = code_of(i);
        g->gi = i == 0 ? 0 : stbtt_FindGlyphIndex(&font, g->code);
        if (i > 0 && g->gi == 0) {
            fprintf(stderr, "gen_font: the font has no U+%04X\n", g->code);
            return 1;
        }
        int lsb;
        stbtt_GetGlyphHMetrics(&font, g->gi, &g->adv, &lsb);
        g->sdf = stbtt_GetGlyphSDF(&font, scale, g->gi, PAD, 128, 128.0f / SPREAD, &g->w, &g->h, &g->xoff,
                                   &g->yoff);
        if (g->sdf)
            quantise(g->sdf, g->w * g->h);
        else
            g->w = g->h = g->xoff = g->yoff = 0;
    }
    int atlas_h = pack();
    if (atlas_h < 0 || atlas_h > 256) {
        fprintf(stderr, "gen_font: the glyphs do not fit %dx%d\n", ATLAS_W, 256);
        return 1;
    }
    for (int i = 0; i < NGLYPH; i++)
        if (g_glyphs[i].xoff < -128 || g_glyphs[i].xoff > 127 || g_glyphs[i].yoff < -128 ||
            g_glyphs[i].yoff > 127) {
            fprintf(stderr, "gen_font: U+%04X's quad is out of an int8_t\n", g_glyphs[i].code);
            return 1;
        }
    if (raw) {
        FILE *f = fopen(raw, "wb");
        if (!f || fwrite(g_atlas, 1, (size_t)ATLAS_W * (size_t)atlas_h, f) != (size_t)ATLAS_W * (size_t)atlas_h)
            return 1;
        fclose(f);
    }
    print_header(&font, atlas_h);
    if (print_packed() != 0) {
        fprintf(stderr, "gen_font: more than %d texel values\n", NLEVEL_MAX);
        return 1;
    }
    for (int i = 0; i < NGLYPH; i++)
        stbtt_FreeSDF(g_glyphs[i].sdf, NULL);
    free(ttf);
    return 0;
}
