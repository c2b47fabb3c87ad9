/* hol_web_game.c - the page's game: the shared session (core/hol_session.h)
 * over the levels the page asks for, writing its logs and recording to the
 * browser's store (hol_web_sink.h). What to play comes from the page's
 * config (page.js: URL parameters or a level file), as `holonomy play`
 * takes it from its command line: a study (its file and the level files it
 * names, played in the order of the participant's number), a level file's
 * text, or a mode and seed, or neither: the default campaign from the seed
 * (default 1).
 */
#include <emscripten.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_campaign.h"
#include "../../core/hol_session.h"
#include "../../core/hol_sha256.h"
#include "../../core/hol_str.h"
#include "../../core/hol_study.h"
#include "../shell/hol_shell_prov.h"
#include "hol_web.h"
#include "hol_web_sink.h"

extern void hol_web_js_config(const char *key, char *buf, int cap);
extern void hol_web_js_event(const char *kind, const char *text);

static hol_session *sess;
static int lang; /* hol_lang: the page's (config "lang") */
static hol_rec_meta meta; /* the session's (environment.csv) */
static hol_level levels[HOL_SESSION_MAX_LEVELS];
static char study_name[64]; /* a study's, or "" */
static const char *study_text;             /* its text as the page fetched it */
static char study_hex[HOL_SHA256_HEX];     /* its SHA-256, or "" */
static char order_rows[64 * 1024];         /* order.csv's (hol_shell_order_rows), or "" */
static int finished;

/* decimal or 0x hex, nothing else (as the desktop's --seed) */
static int parse_seed(const char *s, uint64_t *out)
{
    int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    const char *p = hex ? s + 2 : s;
    uint64_t v = 0;
    if (!*p)
        return 1;
    for (; *p; p++) {
        int d = *p >= '0' && *p <= '9' ? *p - '0'
                : hex && *p >= 'a' && *p <= 'f' ? *p - 'a' + 10
                : hex && *p >= 'A' && *p <= 'F' ? *p - 'A' + 10 : -1;
        uint64_t base = hex ? 16 : 10;
        if (d < 0 || v > (UINT64_MAX - (uint64_t)d) / base)
            return 1;
        v = v * base + (uint64_t)d;
    }
    *out = v;
    return 0;
}

/* The page's participant= (config "participant") in its one spelling
 * (hol_study_participant_id: "p2" and "002" are "P02") into part, "" for
 * none; 0, or 1 with msg when it is no id or an ambiguous one. */
static int page_participant(char part[HOL_REC_ID_MAX + 8], char *msg, size_t cap)
{
    char spelled[HOL_REC_ID_MAX];
    part[0] = 0;
    hol_web_js_config("participant", part, HOL_REC_ID_MAX + 8);
    if (part[0] && !hol_rec_id_ok(part)) {
        snprintf(msg, cap, "participant '%.40s' is not 1..63 letters, digits, '.', '_' or '-'",
                 part);
        return 1;
    }
    if (hol_study_participant_id(part, spelled, sizeof spelled) == HOL_STUDY_ID_AMBIGUOUS) {
        snprintf(msg, cap, "participant '%.40s' is ambiguous: write it %s", part, spelled);
        return 1;
    }
    memcpy(part, spelled, sizeof spelled);
    return 0;
}

/* A study's levels (core/hol_study.h): the study file's text and each
 * level file it names, which the page fetched (config "level:PATH"), in
 * the order of the participant's number; 0, or 1 with msg. */
static int study_levels(const char *text, const char *part, int *n, char out_name[64],
                        char *msg, size_t cap)
{
    static hol_study st;
    static char lvtext[HOL_LEVEL_TEXT_MAX + 2];
    hol_level_err le;
    char m[256], key[HOL_STUDY_PATH_MAX + 8], rel[HOL_STUDY_PATH_MAX];
    uint64_t p = hol_study_participant_number(part);
    if (!p) {
        snprintf(msg, cap, "a study needs participant=ID ending in the participant's number "
                           "(P07, 12)");
        return 1;
    }
    if (hol_study_parse(text, strlen(text), &st, &le)) {
        snprintf(msg, cap, "study: %s", hol_level_err_format(&le, 1, m, sizeof m));
        return 1;
    }
    int order[HOL_STUDY_MAX_CONDITIONS], lv[HOL_STUDY_MAX_LEVELS], cond[HOL_STUDY_MAX_LEVELS],
        pos[HOL_STUDY_MAX_LEVELS];
    hol_study_order(&st, p, order);
    *n = hol_study_session(&st, order, lv, cond, pos);
    for (int i = 0; i < *n; i++) {
        hol_study_level_path(&st, lv[i], rel);
        snprintf(key, sizeof key, "level:%s", rel);
        lvtext[0] = 0;
        if (rel[0])
            hol_web_js_config(key, lvtext, sizeof lvtext);
        if (rel[0] && !lvtext[0]) {
            snprintf(msg, cap, "study: the level file '%.100s' was not loaded", rel);
            return 1;
        }
        char name[HOL_LEVEL_NAME_MAX] = "";
        const char *base = strrchr(rel, '/') ? strrchr(rel, '/') + 1 : rel;
        size_t bl = strcspn(base, ".");
        snprintf(name, sizeof name, "%.*s", (int)(bl ? (bl < 60 ? bl : 60) : 60), base);
        int in_study = 0;
        size_t len = strlen(lvtext);
        if (len > HOL_LEVEL_TEXT_MAX ||
            hol_study_make_level(&st, lv[i], pos[i], rel[0] ? lvtext : NULL, len,
                                 name[0] ? name : NULL, &levels[i], &le, &in_study)) {
            if (len > HOL_LEVEL_TEXT_MAX)
                snprintf(m, sizeof m, "longer than %d bytes", HOL_LEVEL_TEXT_MAX);
            else
                hol_level_err_format(&le, 1, m, sizeof m);
            snprintf(msg, cap, "%.100s: %s", in_study || !rel[0] ? "study" : rel, m);
            return 1;
        }
    }
    snprintf(out_name, 64, "%s", st.name);
    if (hol_shell_order_rows(&st, part, lv, levels, *n, order_rows, sizeof order_rows))
        printf("web: the study's order does not fit order.csv's buffer: not written\n");
    printf("web: study %s, participant %s (number %llu):", st.name, part, (unsigned long long)p);
    for (int k = 0; k < st.nconditions; k++)
        printf(" %s", st.conditions[order[k]].name);
    printf("\n");
    return 0;
}

static char fit_room[16], fit_cell[16]; /* the play area's fit applied, or "" */

/* The page's room or cell, else the play area's fit applied. */
static void page_room_cell(const char *key, char *buf, int cap)
{
    hol_web_js_config(key, buf, cap);
    const char *fit = !strcmp(key, "room") ? fit_room : fit_cell;
    if (!buf[0] && fit[0])
        snprintf(buf, (size_t)cap, "%s", fit);
}

/* The geometry the page names: ?tiling=4,Q ?room=CxR ?cell=M, every level
 * played in it (as play's --tiling, --room, --cell: hol_level_set_geometry
 * adds the lines to each level's text; a level whose own line differs is
 * refused; the play area's fit leaves what the page names). 0, or 1 with
 * msg. */
static int page_geometry(int n, char *msg, size_t cap)
{
    char t[16], r[16], c[16];
    hol_web_js_config("tiling", t, sizeof t);
    hol_web_js_config("room", r, sizeof r);
    hol_web_js_config("cell", c, sizeof c);
    hol_web_g.geo_named = (r[0] ? 1 : 0) | (c[0] ? 2 : 0);
    page_room_cell("room", r, sizeof r);
    page_room_cell("cell", c, sizeof c);
    int q = 0, cols = 0, rows = 0;
    double cell = 0;
    if (t[0] && hol_room_parse_tiling(t, strlen(t), &q)) {
        snprintf(msg, cap, "tiling '%.12s' is not 4,Q with Q from 4 to 8", t);
        return 1;
    }
    if (r[0] && hol_room_parse_size(r, strlen(r), &cols, &rows)) {
        snprintf(msg, cap, "room '%.12s' is not CxR with C and R from 3 to 5", r);
        return 1;
    }
    if (c[0] && hol_level_parse_cell(c, strlen(c), &cell)) {
        snprintf(msg, cap, "cell '%.12s' is not a size in metres from 0.5 to 1.5", c);
        return 1;
    }
    for (int i = 0; i < n; i++) {
        hol_level_err le;
        char m[256];
        if (hol_level_set_geometry(&levels[i], q, cols, rows, cell, &le)) {
            snprintf(msg, cap, "%.60s: %s", levels[i].name,
                     hol_level_err_format(&le, 1, m, sizeof m));
            return 1;
        }
    }
    if (fit_room[0] || q || cols || cell > 0)
        printf("web: geometry %s: tiling %s, room %s, cell %s\n",
               fit_room[0] ? "fitted to the play area" : "from the page", t[0] ? t : "-",
               r[0] ? r : "-", c[0] ? c : "-");
    return 0;
}

/* The tiling and room the page names, for the levels a seed makes (a bad
 * value is left to page_geometry, which refuses it). */
static hol_campaign_geo page_campaign_geo(void)
{
    char t[16], r[16];
    hol_campaign_geo g = {0, 0, 0};
    hol_web_js_config("tiling", t, sizeof t);
    page_room_cell("room", r, sizeof r);
    if (t[0] && hol_room_parse_tiling(t, strlen(t), &g.q))
        g.q = 0;
    if (r[0] && hol_room_parse_size(r, strlen(r), &g.cols, &g.rows))
        g.cols = g.rows = 0;
    return g;
}

/* The levels the page asks for; 0, or 1 with msg. */
static int page_levels(int *n, char *msg, size_t cap)
{
    char mode[32], seed_s[40], name[HOL_LEVEL_NAME_MAX];
    static char text[HOL_LEVEL_TEXT_MAX + 2];
    hol_web_js_config("mode", mode, sizeof mode);
    hol_web_js_config("seed", seed_s, sizeof seed_s);
    hol_web_js_config("levelName", name, sizeof name);
    hol_web_js_config("level", text, sizeof text);
    static char study[HOL_STUDY_TEXT_MAX + 2];
    hol_web_js_config("study", study, sizeof study);
    if (study[0]) {
        char part[HOL_REC_ID_MAX + 8] = "";
        if (page_participant(part, msg, cap) || study_levels(study, part, n, study_name, msg, cap))
            return 1;
        uint8_t dig[32];
        hol_sha256(study, strlen(study), dig);
        hol_sha256_hex(dig, study_hex);
        study_text = study;
        return 0;
    }
    uint64_t seed = 1;
    if (seed_s[0] && parse_seed(seed_s, &seed)) {
        snprintf(msg, cap, "seed '%.30s' is not an unsigned 64-bit number", seed_s);
        return 1;
    }
    if (text[0]) {
        hol_level_err le;
        size_t len = strlen(text);
        if (len > HOL_LEVEL_TEXT_MAX) {
            snprintf(msg, cap, "the level file is longer than %d bytes", HOL_LEVEL_TEXT_MAX);
            return 1;
        }
        if (!name[0])
            snprintf(name, sizeof name, "level");
        if (hol_level_make(name, strlen(name), text, len, &levels[0], &le)) {
            char m[256];
            snprintf(msg, cap, "%.60s: %s", name, hol_level_err_format(&le, 1, m, sizeof m));
            return 1;
        }
        *n = 1;
    } else if (mode[0]) {
        hol_campaign_geo geo = page_campaign_geo();
        if (hol_campaign_mode_level(mode, seed, &geo, &levels[0])) {
            snprintf(msg, cap, "mode '%.30s' is not one of tutorial, flag, keys, explore", mode);
            return 1;
        }
        *n = 1;
    } else {
        hol_campaign_geo geo = page_campaign_geo();
        if (hol_campaign_default(seed, &geo, levels)) {
            snprintf(msg, cap, "cannot make the default campaign");
            return 1;
        }
        *n = HOL_CAMPAIGN_LEVELS;
    }
    return 0;
}

/* ?track_hz=N: the track rows' rate, 10..90 (as --track-hz), 0 when not
 * given; -1 with msg when not such a number. */
static int page_track_hz(char *msg, size_t cap)
{
    char v[16];
    hol_web_js_config("track_hz", v, sizeof v);
    if (!v[0])
        return 0;
    int hz = 0, ok = strlen(v) <= 2;
    for (const char *p = v; *p && ok; p++) {
        ok = *p >= '0' && *p <= '9';
        hz = hz * 10 + (*p - '0');
    }
    if (!ok || hz < HOL_SESSION_TRACK_HZ_MIN || hz > HOL_SESSION_TRACK_HZ_MAX) {
        snprintf(msg, cap, "track_hz '%.12s' is not a whole number in %d..%d", v,
                 HOL_SESSION_TRACK_HZ_MIN, HOL_SESSION_TRACK_HZ_MAX);
        return -1;
    }
    return hz;
}

int hol_web_game_lang(void)
{
    return lang;
}

int hol_web_game_open(char *msg, size_t cap)
{
    int n = 0;
    if (page_levels(&n, msg, cap) || page_geometry(n, msg, cap))
        return 1;
    int track_hz = page_track_hz(msg, cap);
    if (track_hz < 0)
        return 1;
    char part[HOL_REC_ID_MAX + 8] = "";
    if (page_participant(part, msg, cap))
        return 1;
    char tag[16];
    hol_web_js_config("lang", tag, sizeof tag); /* page.js: ?lang=, else the browser's */
    lang = hol_lang_parse(tag) < 0 ? HOL_LANG_EN : hol_lang_parse(tag);
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.app.lang = lang;
    d.levels = levels;
    d.nlevels = n;
    d.log = hol_web_sink();
    d.append = 1; /* one folder for every visit (hol_web_sink.h) */
    d.rec = hol_web_sink();
    d.track_hz = track_hz;
    hol_web_sink_meta(&d.meta, part[0] ? part : NULL);
    snprintf(d.meta.study, sizeof d.meta.study, "%s", study_name);
    snprintf(d.meta.study_sha256, sizeof d.meta.study_sha256, "%s", study_hex);
    /* kept in the store as study-HASH.txt by the session, as play --study's */
    d.study_text = study_hex[0] ? study_text : NULL;
    d.study_len = study_hex[0] ? strlen(study_text) : 0;
    char rec_name[HOL_REC_ID_MAX + 16];
    snprintf(rec_name, sizeof rec_name, "session-%s.rec", d.meta.session);
    d.rec_name = rec_name;
    hol_err e = hol_session_create(&d, &sess, msg, cap);
    if (e)
        return 1;
    meta = d.meta;
    /* provenance.csv, order.csv (the levels' texts final) and codebook.csv
     * in the store, as the desktop's log folder has them */
    static char order[sizeof order_rows + HOL_SESSION_MAX_LEVELS * HOL_SHA256_HEX];
    const char *bad = hol_shell_order_hash(order_rows, levels, n, order, sizeof order)
                          ? "order.csv"
                          : hol_shell_prov_write(d.log, &d.meta, order);
    if (bad)
        printf("web: cannot write the log folder's %s\n", bad);
    printf("web: session %s, %d level(s), recording %s\n", d.meta.session, n, rec_name);
    if (hol_session_recovered(sess))
        printf("web: %d unfinished attempt(s) of an earlier visit finished (end 'killed')\n",
               hol_session_recovered(sess));
    if (hol_session_repaired(sess)[0])
        printf("web: %s\n", hol_session_repaired(sess));
    return 0;
}

int hol_web_game_step(const hol_input *in)
{
    int over = 0;
    hol_err e = hol_session_step(sess, in, &over);
    if (e == HOL_EIO) { /* the session plays on, writing nothing more */
        printf("web: %s\n", hol_session_message(sess));
        hol_web_js_event("warning", hol_session_message(sess));
    } else if (e) {
        printf("web: the session step failed: %s\n", hol_session_message(sess));
        return -1;
    }
    const hol_app_events *ev = hol_app_get_events(hol_session_app(sess));
    for (int i = 0; i < ev->nsteps; i++)
        printf("web: step %d %c cell %d,%d\n", ev->steps[i].index,
               hol_dir_to_char(ev->steps[i].dir), ev->steps[i].room.col, ev->steps[i].room.row);
    if (ev->level_ended)
        hol_web_js_event("saved", "");
    return over;
}

const hol_rec_meta *hol_web_game_meta(void)
{
    return sess ? &meta : NULL;
}

hol_app *hol_web_game_app(void)
{
    return sess ? hol_session_app(sess) : NULL;
}

void hol_web_game_finish(void)
{
    if (finished)
        return;
    finished = 1;
    if (hol_session_finish(sess))
        printf("web: %s\n", hol_session_message(sess));
    hol_web_js_event("saved", "");
}

int hol_web_game_refit(const char *room, const char *cell, char *msg, size_t cap)
{
    if (!sess || finished || hol_web_g.geo_named || study_name[0] ||
        hol_session_level_index(sess) > 0)
        return 0;
    char was_room[16], was_cell[16];
    snprintf(was_room, sizeof was_room, "%s", fit_room);
    snprintf(was_cell, sizeof was_cell, "%s", fit_cell);
    snprintf(fit_room, sizeof fit_room, "%s", room);
    snprintf(fit_cell, sizeof fit_cell, "%s", cell);
    hol_session_abort(sess); /* as a reload: the attempt aborted, files kept */
    hol_session_destroy(sess);
    sess = NULL;
    if (!hol_web_game_open(msg, cap)) {
        hol_web_js_event("saved", "");
        return 1;
    }
    snprintf(fit_room, sizeof fit_room, "%s", was_room); /* as before, then */
    snprintf(fit_cell, sizeof fit_cell, "%s", was_cell);
    char m2[256];
    if (hol_web_game_open(m2, sizeof m2))
        finished = 1;
    return -1;
}

/* The page is going away (pagehide): the attempt in play ends `aborted`
 * and every file is committed, as the desktop does on SIGTERM. */
EMSCRIPTEN_KEEPALIVE void hol_web_abort(void)
{
    if (!sess || finished)
        return;
    finished = 1;
    hol_session_abort(sess);
}

void hol_web_game_print_end(void)
{
    const hol_app_view *v = hol_app_get_view(hol_session_app(sess));
    printf("level %s %s steps %d optimum %d tile %s cell %d,%d\n", hol_session_level(sess)->name,
           hol_session_end_name(sess), v->hud.steps, v->hud.optimum, v->hud.address, v->user.col,
           v->user.row);
}
