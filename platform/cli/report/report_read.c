/* report_read.c - log folders read back for `holonomy report`
 * (report.h): summaries, steps files, levels and their optimal walks. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../../file/hol_lines.h"
#include "../cli.h"
#include "report.h"
#include "../play_setup.h"
#include "../summary_read.h"

static void path_of(char *out, size_t cap, const char *dir, const char *name)
{
    snprintf(out, cap, "%s/%s", dir, name);
}

typedef struct summary_into {
    report_run *r;
    int d;
    const char *path;
} summary_into;

/* A summary row into r->att (summary_read's fn). */
static int summary_row(void *ctx, const hol_report_attempt *a, long line)
{
    summary_into *in = ctx;
    report_run *r = in->r;
    if (r->natt == REPORT_MAX_ATTEMPTS) {
        char msg[64];
        snprintf(msg, sizeof msg, "more than %d attempts in all", REPORT_MAX_ATTEMPTS);
        return summary_bad_line(r->cmd, in->path, line, msg);
    }
    report_att *t = &r->att[r->natt++];
    memset(t, 0, sizeof *t);
    t->dir = in->d;
    t->a = *a;
    return 0;
}

static int warn(const report_run *r, const char *path, const char *what);

/* DIR's summary.csv, read as --resume reads it (summary_read.h). */
static int read_summary(report_run *r, int d)
{
    char path[4200];
    path_of(path, sizeof path, r->dirs[d], "summary.csv");
    summary_into in = {r, d, path};
    long cut = 0;
    int st = summary_read(r->cmd, path, 0, summary_row, &in, &cut);
    if (!st && cut) {
        char what[160];
        snprintf(what, sizeof what, "line %ld: a row a kill cut (no newline at the file's "
                 "end): left out (the next --append session removes it)", cut);
        warn(r, path, what);
    }
    return st;
}

int report_read_summaries(report_run *r)
{
    r->att = malloc(sizeof *r->att * REPORT_MAX_ATTEMPTS);
    if (!r->att) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    for (int d = 0; d < r->ndirs; d++) {
        int st = report_stopped(r);
        if (!st)
            st = read_summary(r, d);
        if (st)
            return st;
    }
    return 0;
}

static int missing(const char *path)
{
    struct stat sb;
    return lstat(path, &sb) != 0;
}

static int warn(const report_run *r, const char *path, const char *what)
{
    char esc[512];
    if (r->quiet)
        return 0;
    fprintf(stderr, "holonomy %s: warning: %s: %s\n", r->cmd, cli_escape(path, esc, sizeof esc),
            what);
    return 0;
}

/* One steps row checked against its attempt; the tile into *out. */
static int step_row(const report_att *t, const hol_report_step *s, long expect, hol_tile *out,
                    char *err)
{
    if (strcmp(s->session, t->a.session) || s->attempt != t->a.attempt) {
        snprintf(err, HOL_REPORT_ERR, "a row of another session or attempt");
        return 0;
    }
    if (s->step != expect) {
        snprintf(err, HOL_REPORT_ERR, "step %ld where step %ld was due", s->step, expect);
        return 0;
    }
    if (s->col >= t->a.room_cols || s->row >= t->a.room_rows) {
        snprintf(err, HOL_REPORT_ERR, "cell %d,%d outside the %dx%d room", s->col, s->row,
                 t->a.room_cols, t->a.room_rows);
        return 0;
    }
    if (hol_tile_parse_q(t->a.tiling_q, s->tile, -1, out)) {
        snprintf(err, HOL_REPORT_ERR, "column tile: not an address of {4,%d}", t->a.tiling_q);
        return 0;
    }
    return 1;
}

int report_stopped(const report_run *r)
{
    int sig = cli_caught_signal();
    if (!sig)
        return 0;
    cli_error(r->cmd, 0, "stopped by signal %d: --out holds no new tables", sig);
    return 128 + sig;
}

int report_walk(report_run *r, report_att *t, hol_tile *tiles, int *out_n)
{
    char name[64], path[4200];
    snprintf(name, sizeof name, "steps-%03ld.csv", t->a.attempt);
    path_of(path, sizeof path, r->dirs[t->dir], name);
    *out_n = 0;
    if (missing(path))
        return warn(r, path, "missing: the attempt gets no picture");
    hol_lines l;
    int st = cli_open_lines(r->cmd, "steps", path, REPORT_LINE_MAX, &l);
    if (st)
        return st;
    hol_report_header h;
    hol_report_step s;
    char err[HOL_REPORT_ERR];
    char *line;
    size_t n;
    int got = 0, ok = 1, header = 0;
    long count = 0;
    while (ok && (got = hol_lines_next(&l, &line, &n)) > 0) {
        hol_tile tile;
        if (!(l.lineno & 4095) && (st = report_stopped(r)))
            break;
        if (!summary_csv_line(&l, &line, &n))
            continue;
        if (!header++) {
            ok = !hol_report_steps_header(line, n, &h, err);
        } else if (count == REPORT_MAX_STEPS) {
            snprintf(err, sizeof err, "more than %d steps", REPORT_MAX_STEPS);
            ok = 0;
        } else {
            ok = !hol_report_step_row(&h, line, n, &s, err) && step_row(t, &s, count + 1, &tile, err);
            if (ok && tiles)
                tiles[count] = tile;
            count += ok;
        }
    }
    if (st)
        ;
    else if (!ok)
        st = summary_bad_line(r->cmd, path, l.lineno, err);
    else if (got < 0)
        st = cli_lines_failed(r->cmd, "steps", path, &l);
    else if (!header)
        st = summary_bad_line(r->cmd, path, 1, "empty: no header");
    hol_lines_close(&l);
    *out_n = (int)count;
    t->has_walk = !st;
    return st;
}

/* The navigator of a geometry, made on first use. */
static hol_nav *nav_for(report_run *r, int q, int cols, int rows)
{
    int key = q * 100 + cols * 10 + rows;
    for (int i = 0; i < r->nnav; i++)
        if (r->nav_key[i] == key)
            return r->nav[i];
    if (r->nnav == (int)(sizeof r->nav / sizeof r->nav[0]))
        return NULL;
    hol_nav_desc d;
    memset(&d, 0, sizeof d);
    d.tiling_q = q;
    d.room_cols = cols;
    d.room_rows = rows;
    d.lazy = 1;
    hol_nav *nav;
    if (hol_nav_create(&d, &nav))
        return NULL;
    r->nav[r->nnav] = nav;
    r->nav_key[r->nnav++] = key;
    return nav;
}

/* A level's tile in the attempt's tiling (the level parser's tiles may be
 * {4,5} words: the address is what the level file says). */
static int in_tiling(hol_tile t, int q, hol_tile *out)
{
    char addr[HOL_TILE_ADDR_MAX];
    if (hol_tile_q(t) == q) {
        *out = t;
        return 1;
    }
    hol_tile_print(t, addr);
    return !hol_tile_parse_q(q, addr, -1, out);
}

static int objectives(const hol_app_level *L, int q, hol_tile *goals, int *ngoals, int *chest)
{
    *ngoals = 0;
    *chest = L->mode == HOL_APP_KEYS;
    if (L->mode == HOL_APP_FLAG)
        return in_tiling(L->flag, q, &goals[(*ngoals)++]);
    if (L->mode != HOL_APP_KEYS)
        return 1;
    for (int k = 0; k < L->nkeys; k++)
        if (!in_tiling(L->keys[k], q, &goals[(*ngoals)++]))
            return 0;
    return in_tiling(L->chest, q, &goals[(*ngoals)++]);
}

/* The level's objectives and optimal walk (report_optimal, the file read
 * and found there): 0, or a warning given (no optimal walk), or the exit
 * status of a refused level. *cacheable: 1 when the result is the level's
 * (not a warning's). */
static int optimal_of(report_run *r, const report_att *t, const char *path, report_opt *o,
                      int *cacheable)
{
    const hol_report_attempt *a = &t->a;
    *cacheable = 0;
    int st = play_read_level(r->cmd, path, &r->level);
    if (st)
        return st;
    const hol_app_level *L = &r->level.lvl;
    o->minimap = L->minimap;
    for (int i = 0; i < L->nstart; i++)
        if (hol_room_step(&o->start, L->start[i]))
            return warn(r, path, "its start walk leaves the room: no optimal walk");
    if (!objectives(L, a->tiling_q, o->goals, &o->ngoals, &o->chest_last))
        return warn(r, path, "an objective outside the tiling: no optimal walk");
    *cacheable = 1;
    if (L->mode != HOL_APP_FLAG && L->mode != HOL_APP_KEYS)
        return 0; /* explore and the tutorial have no optimum */
    *cacheable = 0;
    hol_nav *nav = nav_for(r, a->tiling_q, a->room_cols, a->room_rows);
    uint8_t dirs[HOL_NAV_WALK_MAX];
    hol_nav_result res;
    hol_err e = !nav ? HOL_ENOMEM
                : L->mode == HOL_APP_FLAG
                    ? hol_nav_find(nav, &o->start, o->goals[0], 0, dirs, sizeof dirs, &res)
                    : hol_nav_tour(nav, &o->start, o->goals, o->ngoals - 1,
                                   o->goals[o->ngoals - 1], 0, dirs, sizeof dirs, &res);
    if (e)
        return warn(r, path, "no optimal walk found for it");
    hol_room w = o->start;
    for (int i = 0; i < res.len; i++) {
        if (hol_room_step(&w, dirs[i]))
            return warn(r, path, "the optimal walk failed");
        o->walk[o->nwalk++] = w.tile;
    }
    o->has_optimal = 1;
    o->optimal_len = res.len;
    *cacheable = 1;
    return 0;
}

/* A level's result by its hash and the geometry (the same file content in
 * every folder: its name is its SHA-256), found or NULL. */
static report_opt *cached(report_run *r, const hol_report_attempt *a)
{
    for (int i = 0; i < r->nopt; i++) {
        report_opt *o = &r->opt[i];
        if (o->q == a->tiling_q && o->cols == a->room_cols && o->rows == a->room_rows &&
            !strcmp(o->sha, a->level_sha256))
            return o;
    }
    return NULL;
}

int report_optimal(report_run *r, report_att *t, hol_room *out_start, hol_tile *goals,
                   int *ngoals, int *chest_last, hol_tile *walk, int *nwalk)
{
    const hol_report_attempt *a = &t->a;
    char name[HOL_REPORT_TEXT + 16], path[4400];
    *nwalk = *ngoals = 0;
    t->has_optimal = 0;
    t->optimal_len = -1;
    t->minimap = -1;
    if (hol_room_start_in(a->tiling_q, a->room_cols, a->room_rows, out_start))
        return 0;
    snprintf(name, sizeof name, "level-%s.txt", a->level_sha256);
    path_of(path, sizeof path, r->dirs[t->dir], name);
    if (!a->level_sha256[0] || strchr(a->level_sha256, '/') || missing(path))
        return warn(r, path, "missing: the picture has no optimal walk");
    if (!r->opt && !(r->opt = malloc(sizeof *r->opt * REPORT_OPT_CACHE)))
        return warn(r, path, "out of memory: no optimal walk");
    report_opt *o = cached(r, a);
    int st = 0, keep = 0;
    if (!o) {
        o = &r->opt[r->nopt < REPORT_OPT_CACHE ? r->nopt : r->nopt_next++ % REPORT_OPT_CACHE];
        memset(o, 0, offsetof(report_opt, walk));
        o->start = *out_start;
        o->optimal_len = -1;
        o->minimap = -1;
        st = optimal_of(r, t, path, o, &keep);
        if (keep) {
            snprintf(o->sha, sizeof o->sha, "%s", a->level_sha256);
            o->q = a->tiling_q, o->cols = a->room_cols, o->rows = a->room_rows;
            r->nopt += r->nopt < REPORT_OPT_CACHE;
        } else {
            o->sha[0] = 0; /* a warning's: not kept */
        }
    }
    *out_start = o->start;
    memcpy(goals, o->goals, sizeof *goals * (size_t)o->ngoals);
    *ngoals = o->ngoals;
    *chest_last = o->chest_last;
    memcpy(walk, o->walk, sizeof *walk * (size_t)o->nwalk);
    *nwalk = o->nwalk;
    t->has_optimal = o->has_optimal;
    t->optimal_len = o->optimal_len;
    t->minimap = o->minimap;
    return st;
}

void report_free(report_run *r)
{
    for (int i = 0; i < r->nnav; i++)
        hol_nav_destroy(r->nav[i]);
    r->nnav = 0;
    free(r->opt);
    r->opt = NULL;
    free(r->att);
    r->att = NULL;
}
