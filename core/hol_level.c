/* hol_level.c - level files: lines, keys, the checks after the last line,
 * objectives drawn by distance, and named levels (see hol_level.h). */
#include "hol_level.h"

#include "hol_ask.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hol_room.h"
#include "hol_sha256.h"
#include "hol_tile.h"

/* ---- the parser's state and its one way to fail --------------------------- */

#define HOL__FIELDS 8 /* fields kept of a line; more are counted as one more */

typedef struct hol__lp {
    hol_app_level L;
    long have_mode; /* the mode line, 0 before it */
    long line;
    /* objectives by distance (drawn after the last line) and where each
     * objective and placement was given */
    int flag_lo, flag_hi, keys_n, keys_lo, keys_hi, chest_lo, chest_hi;
    long flag_line, keys_line, chest_line, place_line[HOL_APP_MAX_PLACES];
    long tiling_line, room_line, lantern_line[HOL_APP_MAX_LANTERNS];
    int geo_only; /* the first pass: only the geometry lines */
    long point_line;   /* the `point` line (0: none) */
    char raw[HOL_LEVEL_LINE_MAX + 1]; /* the line being read, comment removed, unsplit */
    int ndefs;         /* `question` lines read (asks copy theirs) */
    hol_app_question defs[HOL_APP_MAX_QUESTIONS];
    long key_line[32]; /* where each key of hol__keys was given (0: not yet) */
    int repeated;      /* a key given twice: reported in either pass */
    hol_level_err *loud;
    hol_level_err *err;
} hol__lp;

static hol_err hol__lfail(hol__lp *p, hol_err code, long line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static hol_err hol__lfail(hol__lp *p, hol_err code, long line, const char *fmt, ...)
{
    hol_level_err *e = p->err;
    if (e) {
        memset(e, 0, sizeof *e);
        e->code = code;
        e->line = line;
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->msg, sizeof e->msg, fmt, ap);
        va_end(ap);
    }
    return code;
}

/* A conflict with another line: "... (line M)", or "... on line M". */
static hol_err hol__conflict(hol__lp *p, long line, long other, int on, const char *what,
                             const char *addr)
{
    if (on)
        hol__lfail(p, HOL_EARG, line, "%.30s is already placed", addr);
    else
        hol__lfail(p, HOL_EARG, line, "the placement on %.30s conflicts with %s", addr, what);
    if (p->err) {
        p->err->other = other;
        p->err->other_on = on;
    }
    return HOL_EARG;
}

/* ---- numbers and words ------------------------------------------------------ */

/* A positive decimal count (digits only, at most 2^40); 0 when it is not. */
static uint64_t hol__count(const char *s)
{
    uint64_t v = 0;
    if (!*s)
        return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9' || v > (UINT64_C(1) << 40))
            return 0;
        v = v * 10 + (uint64_t)(*s - '0');
    }
    return v <= (UINT64_C(1) << 40) ? v : 0;
}

/* An unsigned 64-bit number, decimal or 0x hex (a leading 0 is not octal;
 * no sign, no blanks): 1 ok. */
static int hol__u64(const char *s, uint64_t *out)
{
    int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    const char *d = hex ? s + 2 : s;
    uint64_t v = 0, base = hex ? 16 : 10;
    if (!*d)
        return 0;
    for (; *d; d++) {
        int c = *d;
        int k = c >= '0' && c <= '9' ? c - '0'
                : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                              : -1;
        if (k < 0 || v > (UINT64_MAX - (uint64_t)k) / base)
            return 0;
        v = v * base + (uint64_t)k;
    }
    *out = v;
    return 1;
}

/* Index of word in names[n], or -1. */
static int hol__word(const char *word, const char *const *names, int n)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(word, names[i]))
            return i;
    return -1;
}

/* "MIN [MAX]" of a distance key from field first: 1 <= MIN <= MAX <= 10. */
static int hol__range(char **f, int nf, int first, int *lo, int *hi)
{
    uint64_t a = hol__count(f[first]);
    uint64_t b = nf > first + 1 ? hol__count(f[first + 1]) : a;
    if (!a || !b || a > HOL_LEVEL_MAX_DIST || b > HOL_LEVEL_MAX_DIST || a > b)
        return 1;
    *lo = (int)a;
    *hi = (int)b;
    return 0;
}

/* ---- the keys ---------------------------------------------------------------- */

static hol_err hol__key_mode(hol__lp *p, char **f, int nf)
{
    static const char *const modes[] = {"explore", "flag", "keys", "tutorial"};
    (void)nf;
    int m = hol__word(f[1], modes, 4);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line,
                         "mode '%.20s' is not explore, tutorial, flag or keys", f[1]);
    p->L.mode = m;
    p->have_mode = p->line;
    return HOL_OK;
}

static hol_err hol__key_seed(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (!hol__u64(f[1], &p->L.seed))
        return hol__lfail(p, HOL_EPARSE, p->line,
                         "seed '%.30s' is not an unsigned 64-bit number", f[1]);
    return HOL_OK;
}

static hol_err hol__key_start(hol__lp *p, char **f, int nf)
{
    size_t nd = 0;
    (void)nf;
    if (hol_walk_parse(f[1], strlen(f[1]), p->L.start, sizeof p->L.start, &nd, NULL))
        return hol__lfail(p, HOL_EPARSE, p->line, "start '%.30s' is not a walk of N, E, S, W",
                         f[1]);
    p->L.nstart = (int)nd;
    return HOL_OK;
}

/* The level's tiling Q (the geometry lines are read first). */
static int hol__q(const hol__lp *p)
{
    return p->L.tiling_q ? p->L.tiling_q : HOL_TILING_DEFAULT_Q;
}

/* An address of the level's tiling at s into *t: 0, or the failure
 * reported for what ("'ADDR'", "key 'ADDR'"). A tile must lie inside the
 * reach of tile words with its neighbours (its distance below
 * hol_tile_reach: 59 letters in {4,6} and {4,7} was exit 1 at start). */
static hol_err hol__addr(hol__lp *p, const char *s, const char *what, hol_tile *t)
{
    int q = hol__q(p), reach = hol_tile_reach(q);
    if (hol_tile_parse_q(q, s, -1, t))
        return hol__lfail(p, HOL_EPARSE, p->line, "%s'%.30s' is not a canonical address of {4,%d}",
                          what, s, q);
    if (hol_tile_dist(hol_tile_origin_q(q), *t) >= reach)
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "%s'%.30s...' lies %d steps from O; a level's tile lies at most %d "
                          "in {4,%d}", what, s, hol_tile_dist(hol_tile_origin_q(q), *t),
                          reach - 1, q);
    return HOL_OK;
}

/* flag ADDRESS, chest ADDRESS */
static hol_err hol__key_tile(hol__lp *p, char **f, int nf)
{
    hol_tile t;
    (void)nf;
    hol_err e = hol__addr(p, f[1], "", &t);
    if (e)
        return e;
    if (f[0][0] == 'f') {
        p->L.flag = t;
        p->flag_line = p->line;
    } else {
        p->L.chest = t;
        p->chest_line = p->line;
    }
    return HOL_OK;
}

static hol_err hol__key_keys(hol__lp *p, char **f, int nf)
{
    for (int i = 1; i < nf; i++)
        if (hol__addr(p, f[i], "key ", &p->L.keys[i - 1]))
            return hol__addr(p, f[i], "key ", &p->L.keys[i - 1]);
    p->L.nkeys = nf - 1;
    p->keys_line = p->line;
    return HOL_OK;
}

/* flag-distance MIN [MAX], chest-distance MIN [MAX] */
static hol_err hol__key_dist(hol__lp *p, char **f, int nf)
{
    int lo, hi;
    if (hol__range(f, nf, 1, &lo, &hi))
        return hol__lfail(p, HOL_ERANGE, p->line, "%s needs MIN [MAX] with 1 <= MIN <= MAX <= %d",
                         f[0], HOL_LEVEL_MAX_DIST);
    if (f[0][0] == 'f') {
        p->flag_lo = lo, p->flag_hi = hi;
        p->flag_line = p->line;
    } else {
        p->chest_lo = lo, p->chest_hi = hi;
        p->chest_line = p->line;
    }
    return HOL_OK;
}

static hol_err hol__key_keys_dist(hol__lp *p, char **f, int nf)
{
    uint64_t cnt = hol__count(f[1]);
    if (!cnt || cnt > HOL_APP_MAX_KEYS || hol__range(f, nf, 2, &p->keys_lo, &p->keys_hi))
        return hol__lfail(p, HOL_ERANGE, p->line,
                         "keys-distance needs COUNT (1..%d) MIN [MAX] (1 <= MIN <= MAX <= %d)",
                         HOL_APP_MAX_KEYS, HOL_LEVEL_MAX_DIST);
    p->keys_n = (int)cnt;
    p->keys_line = p->line;
    return HOL_OK;
}

static hol_err hol__key_time_limit(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t secs = hol__count(f[1]);
    if (!secs || secs > 86400)
        return hol__lfail(p, HOL_ERANGE, p->line, "time-limit '%.20s' is not seconds in 1..86400",
                         f[1]);
    p->L.time_limit_s = (double)secs;
    return HOL_OK;
}

static hol_err hol__key_stages(hol__lp *p, char **f, int nf)
{
    unsigned st = 0;
    for (int i = 1; i < nf; i++) {
        uint64_t k = i < HOL__FIELDS ? hol__count(f[i]) : 0;
        if (!k || k > HOL_APP_TUTORIAL_STAGES || nf > HOL_APP_TUTORIAL_STAGES + 1)
            return hol__lfail(p, HOL_ERANGE, p->line, "stages are lesson numbers 1..%d",
                             HOL_APP_TUTORIAL_STAGES);
        st |= 1u << (k - 1);
    }
    p->L.stages = st;
    return HOL_OK;
}

/* place lantern ADDRESS [spot DIR] (repeatable: one lantern a tile) */
static hol_err hol__key_lantern(hol__lp *p, char **f, int nf)
{
    static const char *const dirs[] = {"ahead", "right", "back", "left", "down"};
    int spot = 0;
    if (nf != 3 && (nf != 5 || strcmp(f[3], "spot") ||
                    (spot = hol__word(f[4], dirs, 5) + 1) <= 0))
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "place lantern takes ADDRESS [spot ahead|right|back|left|down]");
    hol_tile t;
    if (hol_tile_parse_q(hol__q(p), f[2], -1, &t))
        return hol__lfail(p, HOL_EPARSE, p->line, "'%.30s' is not a canonical address", f[2]);
    hol_app_level *L = &p->L;
    for (int k = 0; k < L->nlanterns; k++)
        if (hol_tile_eq(L->lanterns[k], t)) {
            hol__lfail(p, HOL_EARG, p->line, "a lantern on %.30s is already placed", f[2]);
            if (p->err) {
                p->err->other = p->lantern_line[k];
                p->err->other_on = 1;
            }
            return HOL_EARG;
        }
    if (L->nlanterns >= HOL_APP_MAX_LANTERNS)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d lanterns", HOL_APP_MAX_LANTERNS);
    p->lantern_line[L->nlanterns] = p->line;
    L->lantern_spot[L->nlanterns] = (uint8_t)spot;
    L->lanterns[L->nlanterns++] = t;
    return HOL_OK;
}

static hol_err hol__key_place(hol__lp *p, char **f, int nf)
{
    static const char *const objs[] = {"clearing", "grass", "flowers", "rock", "mushroom", "pond"};
    static const int ids[] = {HOL_OBJ_NONE, HOL_OBJ_GRASS, HOL_OBJ_FLOWERS,
                              HOL_OBJ_ROCK, HOL_OBJ_MUSHROOM, HOL_OBJ_POOL};
    if (!strcmp(f[1], "lantern"))
        return hol__key_lantern(p, f, nf);
    if (nf != 3)
        return hol__lfail(p, HOL_EPARSE, p->line, "unknown key or wrong value count: '%.20s'", f[0]);
    int o = hol__word(f[1], objs, 6);
    if (o < 0)
        return hol__lfail(p, HOL_EPARSE, p->line,
                         "place '%.20s' is not clearing, grass, flowers, rock, mushroom, pond or lantern",
                         f[1]);
    hol_tile t;
    hol_err e = hol__addr(p, f[2], "", &t);
    if (e)
        return e;
    hol_app_level *L = &p->L;
    for (int k = 0; k < L->nplaces; k++)
        if (hol_tile_eq(L->places[k].tile, t))
            return hol__conflict(p, p->line, p->place_line[k], 1, NULL, f[2]);
    if (L->nplaces >= HOL_APP_MAX_PLACES)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d placements", HOL_APP_MAX_PLACES);
    p->place_line[L->nplaces] = p->line;
    L->places[L->nplaces].tile = t;
    L->places[L->nplaces++].object = ids[o];
    return HOL_OK;
}

static hol_err hol__key_cues(hol__lp *p, char **f, int nf)
{
    static const char *const names[6] = {"hot-cold", "path", "poles", "arrow", "lantern",
                                         "sound"};
    unsigned cues = 0;
    for (int i = 1; i < nf && i < HOL__FIELDS; i++) {
        int c = hol__word(f[i], names, 6);
        if (c < 0 && !(nf == 2 && !strcmp(f[i], "none")))
            return hol__lfail(p, HOL_EPARSE, p->line,
                             "cue '%.20s' is not hot-cold, path, poles, arrow, lantern, sound or none",
                             f[i]);
        if (c >= 0)
            cues |= 1u << c;
    }
    if (nf > 7)
        return hol__lfail(p, HOL_EPARSE, p->line, "more than the six cues");
    p->L.cues = cues;
    return HOL_OK;
}

/* fixed minimap: the minimap's place holds (HOL_BTN_MINIMAP is refused) */
static hol_err hol__key_fixed(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (strcmp(f[1], "minimap"))
        return hol__lfail(p, HOL_EPARSE, p->line, "fixed '%.20s' is not minimap", f[1]);
    p->L.minimap_fixed = 1;
    return HOL_OK;
}

static hol_err hol__key_minimap(hol__lp *p, char **f, int nf)
{
    static const char *const places[3] = {"hud", "hand", "off"};
    (void)nf;
    int m = hol__word(f[1], places, 3);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "minimap '%.20s' is not hud, hand or off", f[1]);
    p->L.minimap = m;
    return HOL_OK;
}

/* lighting day|dusk|night */
static hol_err hol__key_lighting(hol__lp *p, char **f, int nf)
{
    static const char *const skies[3] = {"day", "dusk", "night"};
    (void)nf;
    int m = hol__word(f[1], skies, 3);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "lighting '%.20s' is not day, dusk or night",
                          f[1]);
    p->L.lighting = m;
    return HOL_OK;
}

/* sound all|cues|off */
static hol_err hol__key_sound(hol__lp *p, char **f, int nf)
{
    static const char *const modes[3] = {"all", "cues", "off"};
    (void)nf;
    int m = hol__word(f[1], modes, 3);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "sound '%.20s' is not all, cues or off", f[1]);
    p->L.sound = m;
    return HOL_OK;
}

/* point start|objective (SPEC 8): the pointing question at the level's end */
static hol_err hol__key_point(hol__lp *p, char **f, int nf)
{
    static const char *const targets[2] = {"start", "objective"};
    (void)nf;
    int m = hol__word(f[1], targets, 2);
    if (m < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "point '%.20s' is not start or objective", f[1]);
    p->L.point = m + 1;
    p->point_line = p->line;
    return HOL_OK;
}

/* instructions TEXT, closing TEXT: the rest of the line (hol_app.h:
 * screens), checked: printable ASCII, wrapped whole on the HUD. */
static hol_err hol__key_text(hol__lp *p, char **f, int nf)
{
    (void)nf;
    const char *r = p->raw;
    while (*r == ' ' || *r == '\t')
        r++;
    r += strlen(f[0]);
    while (*r == ' ' || *r == '\t')
        r++;
    size_t n = strlen(r);
    while (n && (r[n - 1] == ' ' || r[n - 1] == '\t'))
        n--;
    int closing = !strcmp(f[0], "closing");
    char *out = closing ? p->L.closing : p->L.instructions;
    if (n > HOL_APP_SCREEN_TEXT - 1)
        return hol__lfail(p, HOL_ERANGE, p->line, "%s: longer than %d characters", f[0],
                          HOL_APP_SCREEN_TEXT - 1);
    for (size_t i = 0; i < n; i++)
        if ((unsigned char)r[i] < 0x20 || (unsigned char)r[i] > 0x7e || r[i] == '\t')
            return hol__lfail(p, HOL_EPARSE, p->line,
                              "%s: only printable ASCII and spaces (the HUD's font), not byte "
                              "0x%02x", f[0], (unsigned char)r[i]);
    memcpy(out, r, n);
    out[n] = 0;
    int lines = hol_app_wrap(out, HOL_APP_SCREEN_COLS, NULL, 0);
    if (lines > HOL_APP_SCREEN_LINES) {
        out[0] = 0;
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "%s: wraps into %d lines of %d characters; at most %d are shown", f[0],
                          lines, HOL_APP_SCREEN_COLS, HOL_APP_SCREEN_LINES);
    }
    return HOL_OK;
}

/* question ID likert|choice ... (core/hol_ask.h): an item `ask` lines
 * may name (after it). */
static hol_err hol__key_question(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (p->ndefs >= HOL_APP_MAX_QUESTIONS)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d questions",
                          HOL_APP_MAX_QUESTIONS);
    char msg[160];
    hol_app_question *q = &p->defs[p->ndefs];
    hol_err e = hol_ask_parse_question(p->raw, strlen(p->raw), q, msg, sizeof msg);
    if (e)
        return hol__lfail(p, e, p->line, "%s", msg);
    for (int i = 0; i < p->ndefs; i++)
        if (!strcmp(p->defs[i].id, q->id))
            return hol__lfail(p, HOL_EARG, p->line, "question %s is given twice", q->id);
    p->ndefs++;
    (void)f;
    return HOL_OK;
}

/* An ask's items: the preset's (NAME a preset's, no IDs) or the questions
 * named (given before), copied after the level's questions. */
static hol_err hol__ask_items(hol__lp *p, hol_app_ask *a, const char *ids)
{
    hol_app_level *L = &p->L;
    a->first = L->nquestions;
    int room = HOL_APP_MAX_QUESTIONS - L->nquestions;
    if (!*ids) {
        int n = hol_ask_preset(a->name, strlen(a->name), L->questions + L->nquestions, room);
        char presets[HOL_ASK_NAMES_MAX];
        hol_ask_preset_names("and", presets, sizeof presets);
        if (!n)
            return hol__lfail(p, HOL_EPARSE, p->line,
                              "ask %s names no items (IDs of questions; %s need none)", a->name,
                              presets);
        if (n > room)
            return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d items to ask",
                              HOL_APP_MAX_QUESTIONS);
        a->n = n;
        L->nquestions += n;
        return HOL_OK;
    }
    for (const char *s = ids; *s;) {
        size_t n = strcspn(s, " \t");
        int k = 0;
        while (k < p->ndefs && !(strlen(p->defs[k].id) == n && !memcmp(p->defs[k].id, s, n)))
            k++;
        if (k == p->ndefs)
            return hol__lfail(p, HOL_EARG, p->line, "ask %s: no question '%.*s' before it",
                              a->name, (int)(n < 32 ? n : 32), s);
        if (L->nquestions >= HOL_APP_MAX_QUESTIONS)
            return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d items to ask",
                              HOL_APP_MAX_QUESTIONS);
        L->questions[L->nquestions++] = p->defs[k];
        a->n++;
        s += n;
        s += strspn(s, " \t");
    }
    return HOL_OK;
}

/* ask NAME level|condition|study [ID...]: a questionnaire after the end
 * screen (in the order of the lines). */
static hol_err hol__key_ask(hol__lp *p, char **f, int nf)
{
    (void)nf;
    hol_app_level *L = &p->L;
    if (L->nasks >= HOL_APP_MAX_ASKS)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d ask lines", HOL_APP_MAX_ASKS);
    hol_app_ask *a = &L->asks[L->nasks];
    memset(a, 0, sizeof *a);
    if (!hol_ask_id_ok(f[1], strlen(f[1])))
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "ask: '%.31s' is not 1..31 letters, digits, '_', '-', '.'", f[1]);
    snprintf(a->name, sizeof a->name, "%s", f[1]);
    a->when = hol_ask_when(f[2], strlen(f[2]));
    if (a->when < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "ask %s: '%.20s' is not level, condition or "
                          "study", a->name, f[2]);
    /* the IDs: the raw line after the key, NAME and WHEN */
    const char *r = p->raw;
    for (int k = 0; k < 3; k++) {
        r += strspn(r, " \t");
        r += strcspn(r, " \t");
    }
    r += strspn(r, " \t");
    char ids[HOL_LEVEL_LINE_MAX + 1];
    snprintf(ids, sizeof ids, "%s", r);
    size_t n = strlen(ids);
    while (n && (ids[n - 1] == ' ' || ids[n - 1] == '\t'))
        ids[--n] = 0;
    hol_err e = hol__ask_items(p, a, ids);
    if (!e)
        L->nasks++;
    return e;
}

/* tiling 4 Q (SPEC 7) */
static hol_err hol__key_tiling(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t q = hol__count(f[2]);
    if (strcmp(f[1], "4") || q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q)
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "tiling needs 4 Q with Q from 4 to 8 (the tiling {4,Q}), not '%.10s %.10s'",
                          f[1], f[2]);
    p->L.tiling_q = (int)q;
    p->tiling_line = p->line;
    return HOL_OK;
}

/* room C R (SPEC 7) */
static hol_err hol__key_room(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t c = hol__count(f[1]), r = hol__count(f[2]);
    if (c < HOL_ROOM_MIN_SIDE || c > HOL_ROOM_MAX_SIDE || r < HOL_ROOM_MIN_SIDE ||
        r > HOL_ROOM_MAX_SIDE)
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "room needs C R with C and R from 3 to 5 (cells), not '%.10s %.10s'",
                          f[1], f[2]);
    p->L.room_cols = (int)c;
    p->L.room_rows = (int)r;
    p->room_line = p->line;
    return HOL_OK;
}

/* cell M */
static hol_err hol__key_cell(hol__lp *p, char **f, int nf)
{
    (void)nf;
    hol_err e = hol_level_parse_cell(f[1], strlen(f[1]), &p->L.cell_m);
    if (e)
        return hol__lfail(p, e, p->line,
                          "cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '%.20s'",
                          f[1]);
    return HOL_OK;
}

/* Every key, with its least and most fields (the key included). */
static const struct {
    const char *key;
    int min, max;
    hol_err (*fn)(hol__lp *p, char **f, int nf);
} hol__keys[] = {
    {"mode", 2, 2, hol__key_mode},
    {"seed", 2, 2, hol__key_seed},
    {"start", 2, 2, hol__key_start},
    {"flag", 2, 2, hol__key_tile},
    {"chest", 2, 2, hol__key_tile},
    {"keys", 2, 1 + HOL_APP_MAX_KEYS, hol__key_keys},
    {"flag-distance", 2, 3, hol__key_dist},
    {"chest-distance", 2, 3, hol__key_dist},
    {"keys-distance", 3, 4, hol__key_keys_dist},
    {"time-limit", 2, 2, hol__key_time_limit},
    {"stages", 2, HOL__FIELDS + 1, hol__key_stages},
    {"place", 3, 5, hol__key_place},
    {"cues", 2, HOL__FIELDS + 1, hol__key_cues},
    {"minimap", 2, 2, hol__key_minimap},
    {"fixed", 2, 2, hol__key_fixed},
    {"lighting", 2, 2, hol__key_lighting},
    {"sound", 2, 2, hol__key_sound},
    {"point", 2, 2, hol__key_point},
    {"instructions", 2, HOL__FIELDS + 1, hol__key_text},
    {"closing", 2, HOL__FIELDS + 1, hol__key_text},
    {"question", 3, HOL__FIELDS + 1, hol__key_question},
    {"ask", 3, HOL__FIELDS + 1, hol__key_ask},
    {"tiling", 3, 3, hol__key_tiling},
    {"room", 3, 3, hol__key_room},
    {"cell", 2, 2, hol__key_cell},
};
_Static_assert(sizeof hol__keys / sizeof hol__keys[0] <= 32, "hol__lp.key_line holds every key");

/* The geometry keys, read in a first pass (addresses need the tiling). */
static int hol__geo_key(const char *key)
{
    return !strcmp(key, "tiling") || !strcmp(key, "room") || !strcmp(key, "cell");
}

/* ---- lines -------------------------------------------------------------------- */

/* Split line (NUL-terminated, comment removed) at spaces and tabs into at
 * most HOL__FIELDS NUL-terminated fields; returns the count, or
 * HOL__FIELDS + 1 when there are more. */
static int hol__split(char *line, char **f)
{
    int n = 0;
    char *s = line;
    for (;;) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s)
            return n;
        if (n == HOL__FIELDS)
            return n + 1;
        f[n++] = s;
        while (*s && *s != ' ' && *s != '\t')
            s++;
        if (*s)
            *s++ = 0;
    }
}

/* One line (n bytes at s, without its LF): comment, fields, its key. */
static hol_err hol__line(hol__lp *p, const char *s, size_t n)
{
    char line[HOL_LEVEL_LINE_MAX + 1];
    while (n && s[n - 1] == '\r')
        n--;
    if (n > HOL_LEVEL_LINE_MAX)
        return hol__lfail(p, HOL_ENOMEM, p->line, "longer than %d bytes", HOL_LEVEL_LINE_MAX);
    if (memchr(s, 0, n))
        return hol__lfail(p, HOL_EPARSE, p->line, "a NUL byte");
    memcpy(line, s, n);
    line[n] = 0;
    char *hash = strchr(line, '#');
    if (hash)
        *hash = 0;
    memcpy(p->raw, line, strlen(line) + 1);
    char *f[HOL__FIELDS];
    int nf = hol__split(line, f);
    if (nf == 0)
        return HOL_OK;
    if (nf < 2)
        return hol__lfail(p, HOL_EPARSE, p->line, "'%.20s' needs a value", f[0]);
    if (p->geo_only && !hol__geo_key(f[0]))
        return HOL_OK;
    for (size_t k = 0; k < sizeof hol__keys / sizeof hol__keys[0]; k++)
        if (!strcmp(f[0], hol__keys[k].key) && nf >= hol__keys[k].min &&
            nf <= hol__keys[k].max) {
            /* a key given twice is refused, naming both lines (no silent
             * last-wins; `place` is the one key a level repeats) */
            if (p->key_line[k] && strcmp(f[0], "place") && strcmp(f[0], "question") &&
                strcmp(f[0], "ask")) {
                hol_level_err *quiet = p->err;
                p->err = p->loud;
                p->repeated = 1;
                hol__lfail(p, HOL_EARG, p->line, "'%s' is given twice; give each key once",
                           f[0]);
                if (p->err)
                    p->err->other = p->key_line[k];
                p->err = quiet;
                return HOL_EARG;
            }
            p->key_line[k] = p->line;
            return hol__keys[k].fn(p, f, nf);
        }
    return hol__lfail(p, HOL_EPARSE, p->line, "unknown key or wrong value count: '%.20s'", f[0]);
}

/* ---- after the last line -------------------------------------------------------- */

/* A placement may not stand where an objective is given. */
static hol_err hol__check_places(hol__lp *p)
{
    const hol_app_level *L = &p->L;
    for (int k = 0; k < L->nplaces; k++) {
        hol_tile t = L->places[k].tile;
        const char *what = NULL;
        long at = 0;
        if (L->mode == HOL_APP_FLAG && p->flag_line && !p->flag_lo && hol_tile_eq(t, L->flag))
            what = "the flag", at = p->flag_line;
        for (int j = 0; L->mode == HOL_APP_KEYS && !p->keys_n && j < L->nkeys; j++)
            if (hol_tile_eq(t, L->keys[j]))
                what = "a key", at = p->keys_line;
        if (L->mode == HOL_APP_KEYS && p->chest_line && !p->chest_lo && hol_tile_eq(t, L->chest))
            what = "the chest", at = p->chest_line;
        if (what) {
            char a[HOL_TILE_ADDR_MAX];
            hol_tile_print(t, a);
            return hol__conflict(p, p->place_line[k], at, 0, what, a);
        }
    }
    return HOL_OK;
}

static uint64_t hol__mix(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A tile at distance d from `from`, drawn from rng: each step goes to a
 * neighbour one further away (in the {4,5} tiling every tile has one). */
static hol_tile hol__tile_at(hol_tile from, int d, uint64_t *rng)
{
    hol_tile t = from;
    for (int i = 1; i <= d; i++) {
        hol_tile cand[4];
        int n = 0;
        for (int e = 0; e < 4; e++) {
            hol_tile nb;
            int arr;
            if (!hol_tile_step(t, e, &nb, &arr) && hol_tile_dist(from, nb) == i)
                cand[n++] = nb;
        }
        if (n == 0)
            break;
        t = cand[hol__mix(rng) % (uint64_t)n];
    }
    return t;
}

/* Is t taken: the start tile, an objective or a placement? */
static int hol__taken(const hol_app_level *L, hol_tile start, hol_tile t)
{
    if (hol_tile_eq(t, start))
        return 1;
    if (L->mode == HOL_APP_FLAG && hol_tile_eq(t, L->flag))
        return 1;
    if (L->mode == HOL_APP_KEYS) {
        for (int k = 0; k < L->nkeys; k++)
            if (hol_tile_eq(t, L->keys[k]))
                return 1;
        if (hol_tile_eq(t, L->chest))
            return 1;
    }
    for (int k = 0; k < L->nplaces; k++)
        if (hol_tile_eq(t, L->places[k].tile))
            return 1;
    return 0;
}

/* The tiles a walk inside the room reaches, in the flat {4,4} (where a
 * room reaches exactly its own C x R tiles); n 0 in the other tilings,
 * whose reach the navigator decides (HOL_EUNREACH at the app's start). */
typedef struct hol__reach {
    int n;
    hol_tile tiles[HOL_ROOM_MAX_CELLS];
} hol__reach;

static void hol__reach_init(const hol_app_level *L, hol__reach *rc)
{
    rc->n = 0;
    hol_room s;
    if (L->tiling_q != 4 || hol_room_start_in(4, L->room_cols, L->room_rows, &s))
        return;
    int cols = hol_room_cols(&s), rows = hol_room_rows(&s);
    for (int c = 0; c < cols; c++)
        for (int r = 0; r < rows; r++) {
            hol_room u = s;
            while (u.col != c)
                (void)hol_room_step(&u, u.col < c ? HOL_DIR_E : HOL_DIR_W);
            while (u.row != r)
                (void)hol_room_step(&u, u.row < r ? HOL_DIR_S : HOL_DIR_N);
            rc->tiles[rc->n++] = u.tile;
        }
}

static int hol__reached(const hol__reach *rc, hol_tile t)
{
    if (!rc->n)
        return 1;
    for (int i = 0; i < rc->n; i++)
        if (hol_tile_eq(rc->tiles[i], t))
            return 1;
    return 0;
}

/* A free tile at a distance in [lo, hi] from start that a walk reaches; 1
 * if none was found in 256 draws. */
static int hol__draw(const hol_app_level *L, const hol__reach *rc, hol_tile start, int lo,
                     int hi, uint64_t *rng, hol_tile *out)
{
    for (int tries = 0; tries < 256; tries++) {
        int d = lo + (int)(hol__mix(rng) % (uint64_t)(hi - lo + 1));
        hol_tile t = hol__tile_at(start, d, rng);
        if (hol_tile_dist(start, t) == d && !hol__taken(L, start, t) && hol__reached(rc, t)) {
            *out = t;
            return 0;
        }
    }
    return 1;
}

/* Objectives by distance from the start tile, drawn from the seed. */
static hol_err hol__draw_objectives(hol__lp *p, const hol__reach *rc, hol_tile start)
{
    hol_app_level *L = &p->L;
    uint64_t rng = L->seed ^ 0x6c6576656cull;
    const char *none = rc->n ? "that a walk inside the room reaches" : "";
    if (L->mode == HOL_APP_FLAG && p->flag_lo &&
        hol__draw(L, rc, start, p->flag_lo, p->flag_hi, &rng, &L->flag))
        return hol__lfail(p, HOL_EARG, p->flag_line, "no free tile for the flag at that distance%s%s",
                          *none ? " " : "", none);
    if (L->mode == HOL_APP_KEYS && p->chest_lo &&
        hol__draw(L, rc, start, p->chest_lo, p->chest_hi, &rng, &L->chest))
        return hol__lfail(p, HOL_EARG, p->chest_line,
                          "no free tile for the chest at that distance%s%s", *none ? " " : "", none);
    if (L->mode == HOL_APP_KEYS && p->keys_n) {
        L->nkeys = 0;
        for (int k = 0; k < p->keys_n; k++) {
            hol_tile t;
            if (hol__draw(L, rc, start, p->keys_lo, p->keys_hi, &rng, &t))
                return hol__lfail(p, HOL_EARG, p->keys_line,
                                  "no free tile for key %d at that distance%s%s", k + 1,
                                  *none ? " " : "", none);
            L->keys[L->nkeys++] = t;
        }
    }
    return HOL_OK;
}

/* Objectives given by address that no walk inside the room reaches (the
 * flat {4,4}: off the room's own tiles) are bad input naming their line. */
static hol_err hol__check_reach(hol__lp *p, const hol__reach *rc)
{
    const hol_app_level *L = &p->L;
    hol_tile t;
    long at = 0;
    const char *what = NULL;
    if (L->mode == HOL_APP_FLAG && !p->flag_lo && !hol__reached(rc, L->flag))
        t = L->flag, at = p->flag_line, what = "the flag";
    for (int k = 0; !what && L->mode == HOL_APP_KEYS && !p->keys_n && k < L->nkeys; k++)
        if (!hol__reached(rc, L->keys[k]))
            t = L->keys[k], at = p->keys_line, what = "a key";
    if (!what && L->mode == HOL_APP_KEYS && !p->chest_lo && !hol__reached(rc, L->chest))
        t = L->chest, at = p->chest_line, what = "the chest";
    if (!what)
        return HOL_OK;
    char a[HOL_TILE_ADDR_MAX];
    hol_tile_print(t, a);
    return hol__lfail(p, HOL_EARG, at,
                      "no walk inside the room reaches %s's tile %.30s (in the flat {4,4} a "
                      "%dx%d room reaches only its own %d tiles)",
                      what, a, L->room_cols ? L->room_cols : 3, L->room_rows ? L->room_rows : 3,
                      rc->n);
}

static hol_err hol__finish(hol__lp *p)
{
    if (!p->have_mode)
        return hol__lfail(p, HOL_EARG, p->line ? p->line : 1, "no 'mode' line%s",
                         p->line ? "" : " (the level is empty)");
    /* a missing objective is bad input naming the mode's line (it was
     * left on tile O, where the level begins) */
    const char *missing = p->L.mode == HOL_APP_FLAG && !p->flag_line    ? "flag"
                          : p->L.mode == HOL_APP_KEYS && !p->keys_line  ? "keys"
                          : p->L.mode == HOL_APP_KEYS && !p->chest_line ? "chest"
                                                                        : NULL;
    if (missing)
        return hol__lfail(p, HOL_EARG, p->have_mode, "mode %s needs a '%s' or '%s-distance' line",
                          p->L.mode == HOL_APP_FLAG ? "flag" : "keys", missing, missing);
    const hol_app_level *L = &p->L;
    int q = hol__q(p);
    if (L->mode == HOL_APP_TUTORIAL && (q == 4 || q == 8))
        return hol__lfail(p, HOL_EARG, p->tiling_line ? p->tiling_line : p->have_mode,
                          "the tutorial needs the tiling {4,5}, {4,6} or {4,7}: its lessons have "
                          "no walk inside the room in {4,%d}", q);
    if (L->point && (L->mode == HOL_APP_TUTORIAL ||
                     (L->point == HOL_APP_POINT_OBJECTIVE && L->mode == HOL_APP_EXPLORE)))
        return hol__lfail(p, HOL_EARG, p->point_line,
                          "point %s needs a mode with an objective (flag or keys%s)",
                          L->point == HOL_APP_POINT_START ? "start" : "objective",
                          L->point == HOL_APP_POINT_START ? ", or explore" : "");
    hol_room r0;
    (void)hol_room_start_in(q, L->room_cols, L->room_rows, &r0);
    for (int i = 0; i < L->nstart; i++)
        if (hol_room_step(&r0, L->start[i]))
            return hol__lfail(p, HOL_EARG, p->line, "the start walk leaves the room");
    hol__reach rc;
    hol__reach_init(L, &rc);
    hol_err e = hol__check_places(p);
    if (!e)
        e = hol__check_reach(p, &rc);
    return e ? e : hol__draw_objectives(p, &rc, r0.tile);
}

/* ---- the API ------------------------------------------------------------------ */

/* A UTF-8 byte order mark at the start of a text (some editors write
 * one) is skipped: the text begins after it. */
static void hol__skip_bom(const char **text, size_t *len)
{
    if (*len >= 3 && !memcmp(*text, "\xef\xbb\xbf", 3))
        *text += 3, *len -= 3;
}

hol_err hol_level_parse(const char *text, size_t len, hol_app_level *out, hol_level_err *err)
{
    hol__skip_bom(&text, &len);
    static const hol__lp zero;
    hol__lp p = zero;
    p.L.cues = HOL_CUE_ALL;
    p.err = err;
    p.loud = err;
    /* the bound is on the text as a session keeps it (hol_level_make adds
     * a last line end), so what parses is kept whole and parses again */
    size_t kept = len + (len && text[len - 1] != '\n');
    if (kept > HOL_LEVEL_TEXT_MAX)
        return hol__lfail(&p, HOL_ENOMEM, 0, "longer than %d bytes (its last line end counted)",
                          HOL_LEVEL_TEXT_MAX);
    /* two passes: the geometry lines first (quietly: the second pass
     * reports every line's error in order), then every line in the
     * level's tiling */
    for (int pass = 0; pass < 2; pass++) {
        p.geo_only = !pass;
        p.err = pass ? err : NULL;
        p.line = 0;
        memset(p.key_line, 0, sizeof p.key_line);
        const char *s = text, *end = text + len;
        while (s < end) {
            const char *nl = memchr(s, '\n', (size_t)(end - s));
            const char *le = nl ? nl : end;
            p.line++;
            hol_err e = hol__line(&p, s, (size_t)(le - s));
            if (e && pass)
                return e;
            /* a repeated geometry line is refused before any address is
             * read in a tiling that a later line changes */
            if (e && p.repeated)
                return e;
            s = nl ? nl + 1 : end;
        }
    }
    hol_err e = hol__finish(&p);
    if (e)
        return e;
    *out = p.L;
    return HOL_OK;
}

hol_err hol_level_line_check(const char *s, size_t n, hol_level_err *err)
{
    /* an address may be one of any tiling (the level's own tiling line may
     * come from elsewhere): the line is good when some tiling reads it;
     * the error is {4,5}'s */
    static const int qs[5] = {5, 4, 6, 7, 8};
    hol_err first = HOL_OK;
    for (int i = 0; i < 5; i++) {
        static const hol__lp zero;
        hol__lp p = zero;
        p.L.cues = HOL_CUE_ALL;
        p.L.tiling_q = qs[i];
        p.err = i ? NULL : err;
        p.line = 1;
        hol_err e = hol__line(&p, s, n);
        if (!e)
            return HOL_OK;
        if (!i)
            first = e;
    }
    return first;
}

long hol_level_objective_line(const hol_level *lv)
{
    static const char *const keys[] = {"flag", "flag-distance", "keys", "keys-distance",
                                       "chest", "chest-distance"};
    int mode = lv->lvl.mode, from = mode == HOL_APP_FLAG ? 0 : 2, to = mode == HOL_APP_FLAG ? 2 : 6;
    if (mode != HOL_APP_FLAG && mode != HOL_APP_KEYS)
        return 0;
    long line = 0;
    for (const char *s = lv->text, *end = lv->text + lv->len; s < end;) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        const char *le = nl ? nl : end;
        line++;
        while (s < le && (*s == ' ' || *s == '\t'))
            s++;
        size_t n = 0;
        while (s + n < le && s[n] != ' ' && s[n] != '\t' && s[n] != '#')
            n++;
        for (int k = from; k < to; k++)
            if (strlen(keys[k]) == n && !memcmp(s, keys[k], n))
                return line > lv->added ? line - lv->added : 0;
        s = nl ? nl + 1 : end;
    }
    return 0;
}

char *hol_level_err_format(const hol_level_err *err, long first, char *out, size_t cap)
{
    int n = err->line > 0 ? snprintf(out, cap, "line %ld: %s", first + err->line - 1, err->msg)
                          : snprintf(out, cap, "%s", err->msg);
    if (err->other > 0 && n >= 0 && (size_t)n < cap)
        snprintf(out + n, cap - (size_t)n, err->other_on ? " on line %ld" : " (line %ld)",
                 first + err->other - 1);
    return out;
}

int hol_level_name_ok(const char *name, size_t len)
{
    return len > 0 && len < HOL_LEVEL_NAME_MAX && !memchr(name, 0, len) &&
           !memchr(name, '\n', len) && !memchr(name, '\r', len);
}

hol_err hol_level_make(const char *name, size_t name_len, const char *text, size_t len,
                       hol_level *out, hol_level_err *err)
{
    hol__lp p;
    memset(&p, 0, sizeof p);
    p.err = err;
    if (!hol_level_name_ok(name, name_len))
        return hol__lfail(&p, HOL_EARG, 0,
                         name_len == 0 ? "an empty level name"
                         : name_len >= HOL_LEVEL_NAME_MAX
                             ? "a level name longer than 63 bytes"
                             : "a level name with a NUL, CR or LF byte, which a recording "
                               "cannot carry");
    hol__skip_bom(&text, &len); /* not kept: the text may gain lines before it */
    hol_err e = hol_level_parse(text, len, &out->lvl, err);
    if (e)
        return e;
    /* the text as a recording carries it: LF line ends (CRs before them
     * dropped), the last line's too */
    size_t o = 0;
    for (const char *s = text, *end = text + len; s < end;) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        size_t n = (size_t)((nl ? nl : end) - s);
        while (n && s[n - 1] == '\r')
            n--;
        memcpy(out->text + o, s, n);
        o += n;
        out->text[o++] = '\n';
        s = nl ? nl + 1 : end;
    }
    out->text[o] = 0;
    out->len = o;
    memcpy(out->name, name, name_len);
    out->name[name_len] = 0;
    out->condition[0] = 0;
    out->position = 0;
    out->added = 0;
    hol_sha256(out->text, out->len, out->sha256);
    return HOL_OK;
}

/* ---- geometry values and options ------------------------------------------- */

hol_err hol_level_parse_cell(const char *s, size_t len, double *out_m)
{
    long v = 0;
    size_t i = 0, digits = 0, decimals = 0;
    for (; i < len && s[i] >= '0' && s[i] <= '9' && digits < 4; i++, digits++)
        v = v * 10 + (s[i] - '0');
    if (!digits)
        return HOL_EPARSE;
    if (i < len && s[i] == '.') {
        for (i++; i < len && s[i] >= '0' && s[i] <= '9' && decimals < 3; i++, decimals++)
            v = v * 10 + (s[i] - '0');
        if (!decimals)
            return HOL_EPARSE;
    }
    if (i != len)
        return i < len && s[i] >= '0' && s[i] <= '9' ? HOL_ERANGE : HOL_EPARSE;
    for (; decimals < 3; decimals++)
        v *= 10;
    if (v < 500 || v > 1500)
        return HOL_ERANGE;
    *out_m = (double)v / 1000.0; /* the nearest double, as strtod gives */
    return HOL_OK;
}

char *hol_level_format_cell(double m, char out[16])
{
    if (!(m > 0))
        m = 1.0;
    snprintf(out, 16, "%.3f", m);
    char *e = out + strlen(out);
    while (e > out && e[-1] == '0')
        *--e = 0;
    if (e > out && e[-1] == '.')
        *--e = 0;
    return out;
}

hol_err hol_level_set_geometry(hol_level *lv, int q, int cols, int rows, double cell_m,
                               hol_level_err *err)
{
    hol__lp p;
    memset(&p, 0, sizeof p);
    p.err = err;
    const hol_app_level *L = &lv->lvl;
    char add[96], had[32], want[32];
    size_t n = 0;
    had[0] = want[0] = 0;
    if (L->mode == HOL_APP_TUTORIAL) /* its lessons are made for {4,5} 3 x 3 */
        q = cols = rows = 0;
    if (q && L->tiling_q && L->tiling_q != q)
        snprintf(had, sizeof had, "tiling 4 %d", L->tiling_q),
            snprintf(want, sizeof want, "{4,%d}", q);
    else if (cols && L->room_cols && (L->room_cols != cols || L->room_rows != rows))
        snprintf(had, sizeof had, "room %d %d", L->room_cols, L->room_rows),
            snprintf(want, sizeof want, "%dx%d", cols, rows);
    else if (cell_m > 0 && L->cell_m > 0 && L->cell_m != cell_m) {
        char a[16], b[16];
        snprintf(had, sizeof had, "cell %s", hol_level_format_cell(L->cell_m, a));
        snprintf(want, sizeof want, "%s m", hol_level_format_cell(cell_m, b));
    }
    if (had[0])
        return hol__lfail(&p, HOL_EARG, 0,
                          "its own line '%s' differs from the %s asked for", had, want);
    if (q && !L->tiling_q)
        n += (size_t)snprintf(add + n, sizeof add - n, "tiling 4 %d\n", q);
    if (cols && !L->room_cols)
        n += (size_t)snprintf(add + n, sizeof add - n, "room %d %d\n", cols, rows);
    if (cell_m > 0 && !(L->cell_m > 0)) {
        char c[16];
        n += (size_t)snprintf(add + n, sizeof add - n, "cell %s\n", hol_level_format_cell(cell_m, c));
    }
    if (!n)
        return HOL_OK;
    if (n + lv->len > HOL_LEVEL_TEXT_MAX)
        return hol__lfail(&p, HOL_ENOMEM, 0, "longer than %d bytes with the geometry lines",
                          HOL_LEVEL_TEXT_MAX);
    static const hol_level zero;
    hol_level nl = zero;
    char text[HOL_LEVEL_TEXT_MAX + 2];
    memcpy(text, add, n);
    memcpy(text + n, lv->text, lv->len);
    hol_err e = hol_level_make(lv->name, strlen(lv->name), text, n + lv->len, &nl, err);
    if (e && err) {
        /* lines of the file as it was (an added line itself: no line) */
        long added = 0;
        for (size_t i = 0; i < n; i++)
            added += add[i] == '\n';
        err->line = err->line > added ? err->line - added : 0;
        err->other = err->other > added ? err->other - added : 0;
    }
    if (e)
        return e;
    memcpy(nl.condition, lv->condition, sizeof nl.condition);
    nl.position = lv->position;
    for (size_t i = 0; i < n; i++)
        nl.added += add[i] == '\n';
    nl.added += lv->added;
    *lv = nl;
    return HOL_OK;
}
