/* hol_level_keys.c - a level line's key, one function a key (see
 * hol_level_impl.h; the table of keys is hol_level_parse.c's hol__keys; the
 * questionnaires' lines are hol_level_ask.c's). */
#include "hol_level_impl.h"

#include <string.h>

#include "hol_face.h"
#include "hol_lesson.h"
#include "hol_quiz.h"
#include "hol_room.h"
#include "hol_str.h"
#include "hol_tile.h"

hol_err hol__key_mode(hol__lp *p, char **f, int nf)
{
    static const char *const modes[] = {"explore", "flag", "keys", "tutorial"};
    (void)nf;
    hol_err e = hol__lv_one_of(p, f, modes, 4, "explore, tutorial, flag or keys", &p->L.mode);
    if (!e)
        p->have_mode = p->line;
    return e;
}

hol_err hol__key_seed(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (!hol__lv_u64(f[1], &p->L.seed))
        return hol__lfail(p, HOL_EPARSE, p->line,
                         "seed '%.30s' is not an unsigned 64-bit number", f[1]);
    return HOL_OK;
}

hol_err hol__key_start(hol__lp *p, char **f, int nf)
{
    size_t nd = 0;
    (void)nf;
    if (hol_walk_parse(f[1], strlen(f[1]), p->L.start, sizeof p->L.start, &nd, NULL))
        return hol__lfail(p, HOL_EPARSE, p->line, "start '%.30s' is not a walk of N, E, S, W",
                         f[1]);
    p->L.nstart = (int)nd;
    return HOL_OK;
}

/* flag ADDRESS, chest ADDRESS */
hol_err hol__key_tile(hol__lp *p, char **f, int nf)
{
    hol_tile t;
    (void)nf;
    hol_err e = hol__lv_addr(p, f[1], "", &t);
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

hol_err hol__key_keys(hol__lp *p, char **f, int nf)
{
    for (int i = 1; i < nf; i++)
        if (hol__lv_addr(p, f[i], "key ", &p->L.keys[i - 1]))
            return hol__lv_addr(p, f[i], "key ", &p->L.keys[i - 1]);
    p->L.nkeys = nf - 1;
    p->keys_line = p->line;
    return HOL_OK;
}

/* flag-distance MIN [MAX], chest-distance MIN [MAX] */
hol_err hol__key_dist(hol__lp *p, char **f, int nf)
{
    int lo, hi;
    if (hol__lv_range(f, nf, 1, &lo, &hi))
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

hol_err hol__key_keys_dist(hol__lp *p, char **f, int nf)
{
    uint64_t cnt = hol__lv_count(f[1]);
    if (!cnt || cnt > HOL_APP_MAX_KEYS || hol__lv_range(f, nf, 2, &p->keys_lo, &p->keys_hi))
        return hol__lfail(p, HOL_ERANGE, p->line,
                         "keys-distance needs COUNT (1..%d) MIN [MAX] (1 <= MIN <= MAX <= %d)",
                         HOL_APP_MAX_KEYS, HOL_LEVEL_MAX_DIST);
    p->keys_n = (int)cnt;
    p->keys_line = p->line;
    return HOL_OK;
}

hol_err hol__key_time_limit(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t secs = hol__lv_count(f[1]);
    if (!secs || secs > 86400)
        return hol__lfail(p, HOL_ERANGE, p->line, "time-limit '%.20s' is not seconds in 1..86400",
                         f[1]);
    p->L.time_limit_s = (double)secs;
    return HOL_OK;
}

hol_err hol__key_stages(hol__lp *p, char **f, int nf)
{
    unsigned st = 0;
    for (int i = 1; i < nf; i++) {
        uint64_t k = i < HOL__FIELDS ? hol__lv_count(f[i]) : 0;
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
                    (spot = hol__lv_word(f[4], dirs, 5) + 1) <= 0))
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "place lantern takes ADDRESS [spot ahead|right|back|left|down]");
    hol_tile t;
    if (hol_tile_parse_q(hol__lv_q(p), f[2], -1, &t))
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

hol_err hol__key_place(hol__lp *p, char **f, int nf)
{
    static const char *const objs[] = {"clearing", "grass", "flowers", "rock", "mushroom", "pond"};
    static const int ids[] = {HOL_OBJ_NONE, HOL_OBJ_GRASS, HOL_OBJ_FLOWERS,
                              HOL_OBJ_ROCK, HOL_OBJ_MUSHROOM, HOL_OBJ_POOL};
    if (!strcmp(f[1], "lantern"))
        return hol__key_lantern(p, f, nf);
    if (nf != 3)
        return hol__lfail(p, HOL_EPARSE, p->line, "unknown key or wrong value count: '%.20s'", f[0]);
    int o = hol__lv_word(f[1], objs, 6);
    if (o < 0)
        return hol__lfail(p, HOL_EPARSE, p->line,
                         "place '%.20s' is not clearing, grass, flowers, rock, mushroom, pond or lantern",
                         f[1]);
    hol_tile t;
    hol_err e = hol__lv_addr(p, f[2], "", &t);
    if (e)
        return e;
    hol_app_level *L = &p->L;
    for (int k = 0; k < L->nplaces; k++)
        if (hol_tile_eq(L->places[k].tile, t))
            return hol__lv_conflict(p, p->line, p->place_line[k], 1, NULL, f[2]);
    if (L->nplaces >= HOL_APP_MAX_PLACES)
        return hol__lfail(p, HOL_ENOMEM, p->line, "more than %d placements", HOL_APP_MAX_PLACES);
    p->place_line[L->nplaces] = p->line;
    L->places[L->nplaces].tile = t;
    L->places[L->nplaces++].object = ids[o];
    return HOL_OK;
}

hol_err hol__key_cues(hol__lp *p, char **f, int nf)
{
    static const char *const names[6] = {"hot-cold", "path", "poles", "arrow", "lantern",
                                         "sound"};
    unsigned cues = 0;
    for (int i = 1; i < nf && i < HOL__FIELDS; i++) {
        int c = hol__lv_word(f[i], names, 6);
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
hol_err hol__key_fixed(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (strcmp(f[1], "minimap"))
        return hol__lfail(p, HOL_EPARSE, p->line, "fixed '%.20s' is not minimap", f[1]);
    p->L.minimap_fixed = 1;
    return HOL_OK;
}

hol_err hol__key_minimap(hol__lp *p, char **f, int nf)
{
    static const char *const places[3] = {"hud", "hand", "off"};
    (void)nf;
    return hol__lv_one_of(p, f, places, 3, "hud, hand or off", &p->L.minimap);
}

/* lighting day|dusk|night, or lighting cycle SECONDS (dusk to night) */
hol_err hol__key_lighting(hol__lp *p, char **f, int nf)
{
    static const char *const skies[3] = {"day", "dusk", "night"};
    if (!strcmp(f[1], "cycle")) {
        uint64_t secs = nf == 3 ? hol__lv_count(f[2]) : 0;
        if (!secs || secs > HOL_APP_CYCLE_MAX_S)
            return hol__lfail(p, secs ? HOL_ERANGE : HOL_EPARSE, p->line,
                              "lighting cycle takes SECONDS in 1..%d", HOL_APP_CYCLE_MAX_S);
        p->L.lighting = HOL_LIGHT_DUSK;
        p->L.lighting_cycle_s = (double)secs;
        return HOL_OK;
    }
    if (nf != 2) /* as the parser says of any key with too many values */
        return hol__lfail(p, HOL_EPARSE, p->line, "unknown key or wrong value count: '%.20s'",
                          f[0]);
    return hol__lv_one_of(p, f, skies, 3, "day, dusk or night", &p->L.lighting);
}

/* lantern carried */
hol_err hol__key_carried(hol__lp *p, char **f, int nf)
{
    (void)nf;
    if (strcmp(f[1], "carried"))
        return hol__lfail(p, HOL_EPARSE, p->line, "lantern '%.20s' is not carried", f[1]);
    p->L.lantern_carried = 1;
    return HOL_OK;
}

/* sound all|cues|off */
hol_err hol__key_sound(hol__lp *p, char **f, int nf)
{
    static const char *const modes[3] = {"all", "cues", "off"};
    (void)nf;
    return hol__lv_one_of(p, f, modes, 3, "all, cues or off", &p->L.sound);
}

/* lang en|de|nl: the language of the level's texts (core/hol_str.h) */
hol_err hol__key_lang(hol__lp *p, char **f, int nf)
{
    static const char *const codes[HOL_LANG_COUNT] = {"en", "de", "nl"};
    (void)nf;
    hol_err e = hol__lv_one_of(p, f, codes, HOL_LANG_COUNT, "en, de or nl", &p->L.lang);
    p->L.lang += !e; /* 1 + the language: 0 is the app's */
    return e;
}

/* point start|objective (SPEC 8): the pointing question at the level's end */
hol_err hol__key_point(hol__lp *p, char **f, int nf)
{
    static const char *const targets[2] = {"start", "objective"};
    (void)nf;
    int m;
    hol_err e = hol__lv_one_of(p, f, targets, 2, "start or objective", &m);
    if (e)
        return e;
    p->L.point = m + 1;
    p->point_line = p->line;
    return HOL_OK;
}

/* instructions TEXT, closing TEXT: the rest of the line (hol_app.h:
 * screens), checked: printable ASCII and Latin-1 in UTF-8 (the face's:
 * hol_face_text_bad), wrapped whole on the HUD. */
hol_err hol__key_text(hol__lp *p, char **f, int nf)
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
    uint32_t c;
    size_t bad = hol_face_text_bad(r, n, &c);
    if (bad < n && (c < 0x80 || c == HOL_FACE_MALFORMED))
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "%s: only printable ASCII, spaces and Latin-1 letters in UTF-8 (the "
                          "HUD's font), not byte 0x%02x", f[0], (unsigned char)r[bad]);
    if (bad < n)
        return hol__lfail(p, HOL_EPARSE, p->line,
                          "%s: only printable ASCII, spaces and Latin-1 letters in UTF-8 (the "
                          "HUD's font), not U+%04X", f[0], (unsigned)c);
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
/* tiling 4 Q (SPEC 7) */
hol_err hol__key_tiling(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t q = hol__lv_count(f[2]);
    if (strcmp(f[1], "4") || q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q)
        return hol__lfail(p, HOL_ERANGE, p->line,
                          "tiling needs 4 Q with Q from 4 to 8 (the tiling {4,Q}), not '%.10s %.10s'",
                          f[1], f[2]);
    p->L.tiling_q = (int)q;
    p->tiling_line = p->line;
    return HOL_OK;
}

/* room C R (SPEC 7) */
hol_err hol__key_room(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t c = hol__lv_count(f[1]), r = hol__lv_count(f[2]);
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
hol_err hol__key_cell(hol__lp *p, char **f, int nf)
{
    (void)nf;
    hol_err e = hol_level_parse_cell(f[1], strlen(f[1]), &p->L.cell_m);
    if (e)
        return hol__lfail(p, e, p->line,
                          "cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '%.20s'",
                          f[1]);
    return HOL_OK;
}

/* lesson N: lesson N of core/hol_lesson.h in the level's tiling (its mode,
 * route, predict question, instructions, pointing and check); the lines
 * it sets are refused beside it (hol_level_parse.c). */
hol_err hol__key_lesson(hol__lp *p, char **f, int nf)
{
    (void)nf;
    uint64_t n = hol__lv_count(f[1]);
    if (!n || n > HOL_LESSONS)
        return hol__lfail(p, HOL_ERANGE, p->line, "lesson '%.20s' is not a lesson 1..%d", f[1],
                          HOL_LESSONS);
    if (hol_lesson_fill((int)n, hol__lv_q(p), &p->L))
        return hol__lfail(p, HOL_ERANGE, p->line, "lesson %d does not fit its screens",
                          (int)n);
    p->have_mode = p->line;
    return HOL_OK;
}

/* quiz pre|post: the class's pre-test or post-test of core/hol_quiz.h in
 * the level's tiling (its mode, questions, screen and time limit). */
hol_err hol__key_quiz(hol__lp *p, char **f, int nf)
{
    (void)nf;
    int phase = !strcmp(f[1], "pre") ? HOL_QUIZ_PRE : !strcmp(f[1], "post") ? HOL_QUIZ_POST : -1;
    if (phase < 0)
        return hol__lfail(p, HOL_EPARSE, p->line, "quiz '%.20s' is not pre or post", f[1]);
    if (hol_quiz_fill(phase, hol__lv_q(p), &p->L))
        return hol__lfail(p, HOL_ERANGE, p->line, "the %s-test does not fit its screens", f[1]);
    p->have_mode = p->line;
    return HOL_OK;
}
