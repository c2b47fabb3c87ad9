/* hol_web_game.c - the web page's game session. (Interim: one level driven
 * through the app step, the recording kept in memory; the shared session,
 * core/hol_session.h, replaces it.) */
#include <emscripten.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_input_io.h"
#include "hol_web.h"

extern void hol_web_js_config(const char *key, char *buf, int cap);
extern void hol_web_js_store_put(const char *name, const char *data, int n);

static hol_app *app;
static char *rec;
static size_t rec_len, rec_cap;
static char level_text[512];

static void rec_add(const char *s, size_t n)
{
    if (rec_len + n + 1 > rec_cap) {
        size_t cap = rec_cap ? rec_cap * 2 : 1 << 16;
        while (cap < rec_len + n + 1)
            cap *= 2;
        char *p = realloc(rec, cap);
        if (!p)
            return;
        rec = p;
        rec_cap = cap;
    }
    memcpy(rec + rec_len, s, n);
    rec_len += n;
    rec[rec_len] = 0;
}

int hol_web_game_open(char *msg, size_t cap)
{
    char seed_s[32] = "";
    hol_web_js_config("seed", seed_s, sizeof seed_s);
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_EXPLORE;
    L.seed = seed_s[0] ? strtoull(seed_s, NULL, 0) : 1;
    L.cues = HOL_CUE_ALL;
    L.minimap = HOL_MINIMAP_OFF;
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    hol_err err = hol_app_create(&d, &app);
    if (!err)
        err = hol_app_start_level(app, &L);
    if (err) {
        snprintf(msg, cap, "cannot start the game: %s", hol_err_str(err));
        return 1;
    }
    snprintf(level_text, sizeof level_text, "mode explore\nseed %llu\nminimap off\n",
             (unsigned long long)L.seed);
    char head[600];
    int n = snprintf(head, sizeof head, "holonomy-rec 1\nlevel explore\nL mode explore\nL seed %llu\nL minimap off\nend\n",
                     (unsigned long long)L.seed);
    rec_add(head, (size_t)n);
    return 0;
}

int hol_web_game_step(const hol_input *in)
{
    hol_err err = hol_app_step(app, in);
    if (err) {
        printf("web: the app step failed: %s\n", hol_err_str(err));
        return -1;
    }
    char line[HOL_INPUT_LINE_MAX + 2];
    size_t n = hol_input_format(in, line, sizeof line);
    line[n++] = '\n';
    rec_add(line, n);
    const hol_app_events *ev = hol_app_get_events(app);
    for (int i = 0; i < ev->nsteps; i++)
        printf("web: step %d %c cell %d,%d\n", ev->steps[i].index,
               hol_dir_to_char(ev->steps[i].dir), ev->steps[i].room.col, ev->steps[i].room.row);
    return hol_app_get_view(app)->state == HOL_APP_QUIT;
}

hol_app *hol_web_game_app(void)
{
    return app;
}

void hol_web_game_finish(void)
{
    hol_web_js_store_put("session.rec", rec ? rec : "", (int)rec_len);
}

void hol_web_game_print_end(void)
{
    const hol_app_view *v = hol_app_get_view(app);
    static const char *const st[] = {"idle", "playing", "done", "quit"};
    printf("level explore %s steps %d optimum %d tile %s cell %d,%d\n", st[v->state],
           v->hud.steps, v->hud.optimum, v->hud.address, v->user.col, v->user.row);
}
