/* session.c - a play session: app step, levels, logs, recording (see
 * session.h). */
#include "session.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_world.h"
#include "cli.h"

static const char *const mode_names[] = {"explore", "flag", "keys", "tutorial"};
static const char *const end_names[] = {"open", "done", "restart", "quit", "timeout"};

/* ---- level files (SPEC section 5) ---------------------------------------- */

/* ---- levels: objectives by distance, placements ------------------------- */

static uint64_t level_mix(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A tile at distance d from `from`, drawn from rng: each step goes to a
 * neighbour one further away (in the {4,5} tiling every tile has one). */
static hol_tile level_tile_at(hol_tile from, int d, uint64_t *rng)
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
        t = cand[level_mix(rng) % (uint64_t)n];
    }
    return t;
}

/* Is t taken: the start tile, an objective or a placement? */
static int level_taken(const hol_app_level *L, hol_tile start, hol_tile t)
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

/* A free tile at a distance in [lo, hi] from start, from rng; 1 if none
 * was found in 256 draws. */
static int level_draw(const hol_app_level *L, hol_tile start, int lo, int hi, uint64_t *rng,
                      hol_tile *out)
{
    for (int tries = 0; tries < 256; tries++) {
        int d = lo + (int)(level_mix(rng) % (uint64_t)(hi - lo + 1));
        hol_tile t = level_tile_at(start, d, rng);
        if (hol_tile_dist(start, t) == d && !level_taken(L, start, t)) {
            *out = t;
            return 0;
        }
    }
    return 1;
}

/* "MIN [MAX]" of a distance key: 1..HOL_LEVEL_MAX_DIST, MIN <= MAX. */
#define LEVEL_MAX_DIST 10
static int level_range(char **f, int nf, int first, int *lo, int *hi)
{
    size_t a = cli_parse_count(f[first]);
    size_t b = nf > first + 1 ? cli_parse_count(f[first + 1]) : a;
    if (!a || !b || a > LEVEL_MAX_DIST || b > LEVEL_MAX_DIST || a > b)
        return 1;
    *lo = (int)a;
    *hi = (int)b;
    return 0;
}

int session_parse_level(const char *text, size_t len, hol_app_level *lvl, char *err,
                        size_t err_cap)
{
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.cues = HOL_CUE_ALL;
    int have_mode = 0;
    long lineno = 0;
    /* objectives by distance (resolved after the last line) and where each
     * objective and placement was given */
    int flag_lo = 0, flag_hi = 0, keys_n = 0, keys_lo = 0, keys_hi = 0, chest_lo = 0,
        chest_hi = 0;
    long flag_line = 0, keys_line = 0, chest_line = 0, place_line[HOL_APP_MAX_PLACES];
    const char *p = text, *end = text + len;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        const char *le = nl ? nl : end;
        lineno++;
        char line[512];
        size_t n = (size_t)(le - p);
        if (n >= sizeof line) {
            snprintf(err, err_cap, "line %ld: longer than %zu bytes", lineno, sizeof line - 1);
            return 1;
        }
        memcpy(line, p, n);
        line[n] = 0;
        p = nl ? nl + 1 : end;
        if (memchr(line, 0, n)) {
            snprintf(err, err_cap, "line %ld: a NUL byte", lineno);
            return 1;
        }
        char *hash = strchr(line, '#');
        if (hash)
            *hash = 0;
        char *f[8];
        size_t fl[8];
        int nf = cli_split(line, strlen(line), f, fl, 7);
        if (nf == 0)
            continue;
        for (int i = 0; i < nf && i < 7; i++)
            f[i][fl[i]] = 0;
        const char *key = f[0];
        if (nf < 2) {
            snprintf(err, err_cap, "line %ld: '%.20s' needs a value", lineno, key);
            return 1;
        }
        if (!strcmp(key, "mode") && nf == 2) {
            int m = -1;
            for (int i = 0; i < 4; i++)
                if (!strcmp(f[1], mode_names[i]))
                    m = i;
            if (m < 0) {
                snprintf(err, err_cap, "line %ld: mode '%.20s' is not explore, tutorial, flag or keys",
                         lineno, f[1]);
                return 1;
            }
            L.mode = m;
            have_mode = 1;
        } else if (!strcmp(key, "seed") && nf == 2) {
            if (!cli_parse_u64(f[1], &L.seed)) {
                snprintf(err, err_cap, "line %ld: seed '%.30s' is not an unsigned 64-bit number",
                         lineno, f[1]);
                return 1;
            }
        } else if (!strcmp(key, "start") && nf == 2) {
            size_t nd = 0;
            if (hol_walk_parse(f[1], strlen(f[1]), L.start, sizeof L.start, &nd, NULL)) {
                snprintf(err, err_cap, "line %ld: start '%.30s' is not a walk of N, E, S, W",
                         lineno, f[1]);
                return 1;
            }
            L.nstart = (int)nd;
        } else if ((!strcmp(key, "flag") || !strcmp(key, "chest")) && nf == 2) {
            hol_tile t;
            if (hol_tile_parse(f[1], -1, &t)) {
                snprintf(err, err_cap, "line %ld: '%.30s' is not a canonical address", lineno,
                         f[1]);
                return 1;
            }
            if (key[0] == 'f') {
                L.flag = t;
                flag_line = lineno;
            } else {
                L.chest = t;
                chest_line = lineno;
            }
        } else if (!strcmp(key, "keys") && nf <= 6) {
            for (int i = 1; i < nf; i++)
                if (hol_tile_parse(f[i], -1, &L.keys[i - 1])) {
                    snprintf(err, err_cap, "line %ld: key '%.30s' is not a canonical address",
                             lineno, f[i]);
                    return 1;
                }
            L.nkeys = nf - 1;
            keys_line = lineno;
        } else if ((!strcmp(key, "flag-distance") || !strcmp(key, "chest-distance")) &&
                   nf <= 3) {
            int lo, hi;
            if (level_range(f, nf, 1, &lo, &hi)) {
                snprintf(err, err_cap, "line %ld: %s needs MIN [MAX] with 1 <= MIN <= MAX <= %d",
                         lineno, key, LEVEL_MAX_DIST);
                return 1;
            }
            if (key[0] == 'f') {
                flag_lo = lo, flag_hi = hi;
                flag_line = lineno;
            } else {
                chest_lo = lo, chest_hi = hi;
                chest_line = lineno;
            }
        } else if (!strcmp(key, "keys-distance") && (nf == 3 || nf == 4)) {
            size_t cnt = cli_parse_count(f[1]);
            if (!cnt || cnt > HOL_APP_MAX_KEYS || level_range(f, nf, 2, &keys_lo, &keys_hi)) {
                snprintf(err, err_cap,
                         "line %ld: keys-distance needs COUNT (1..%d) MIN [MAX] (1 <= MIN <= "
                         "MAX <= %d)", lineno, HOL_APP_MAX_KEYS, LEVEL_MAX_DIST);
                return 1;
            }
            keys_n = (int)cnt;
            keys_line = lineno;
        } else if (!strcmp(key, "time-limit") && nf == 2) {
            size_t secs = cli_parse_count(f[1]);
            if (!secs || secs > 86400) {
                snprintf(err, err_cap, "line %ld: time-limit '%.20s' is not seconds in 1..86400",
                         lineno, f[1]);
                return 1;
            }
            L.time_limit_s = (double)secs;
        } else if (!strcmp(key, "stages")) {
            unsigned st = 0;
            for (int i = 1; i < nf; i++) {
                size_t k = cli_parse_count(f[i]);
                if (!k || k > HOL_APP_TUTORIAL_STAGES || nf > HOL_APP_TUTORIAL_STAGES + 1) {
                    snprintf(err, err_cap, "line %ld: stages are lesson numbers 1..%d",
                             lineno, HOL_APP_TUTORIAL_STAGES);
                    return 1;
                }
                st |= 1u << (k - 1);
            }
            L.stages = st;
        } else if (!strcmp(key, "place") && nf == 3) {
            static const char *const objs[] = {"clearing", "grass", "flowers", "rock",
                                               "mushroom", "pond"};
            static const int ids[] = {HOL_OBJ_NONE, HOL_OBJ_GRASS, HOL_OBJ_FLOWERS,
                                      HOL_OBJ_ROCK, HOL_OBJ_MUSHROOM, HOL_OBJ_POOL};
            int o = -1;
            for (int k = 0; k < 6; k++)
                if (!strcmp(f[1], objs[k]))
                    o = ids[k];
            if (o < 0) {
                snprintf(err, err_cap,
                         "line %ld: place '%.20s' is not clearing, grass, flowers, rock, "
                         "mushroom or pond", lineno, f[1]);
                return 1;
            }
            hol_tile t;
            if (hol_tile_parse(f[2], -1, &t)) {
                snprintf(err, err_cap, "line %ld: '%.30s' is not a canonical address", lineno,
                         f[2]);
                return 1;
            }
            for (int k = 0; k < L.nplaces; k++)
                if (hol_tile_eq(L.places[k].tile, t)) {
                    snprintf(err, err_cap, "line %ld: %.30s is already placed on line %ld",
                             lineno, f[2], place_line[k]);
                    return 1;
                }
            if (L.nplaces >= HOL_APP_MAX_PLACES) {
                snprintf(err, err_cap, "line %ld: more than %d placements", lineno,
                         HOL_APP_MAX_PLACES);
                return 1;
            }
            place_line[L.nplaces] = lineno;
            L.places[L.nplaces].tile = t;
            L.places[L.nplaces++].object = o;
        } else if (!strcmp(key, "cues")) {
            static const char *const cue_names[4] = {"hot-cold", "path", "poles", "arrow"};
            unsigned cues = 0;
            for (int i = 1; i < nf && i < 7; i++) {
                int c = -1;
                for (int k = 0; k < 4; k++)
                    if (!strcmp(f[i], cue_names[k]))
                        c = k;
                if (c < 0 && !(nf == 2 && !strcmp(f[i], "none"))) {
                    snprintf(err, err_cap,
                             "line %ld: cue '%.20s' is not hot-cold, path, poles, arrow or none",
                             lineno, f[i]);
                    return 1;
                }
                if (c >= 0)
                    cues |= 1u << c;
            }
            if (nf > 5) {
                snprintf(err, err_cap, "line %ld: more than the four cues", lineno);
                return 1;
            }
            L.cues = cues;
        } else if (!strcmp(key, "minimap") && nf == 2) {
            static const char *const places[3] = {"hud", "hand", "off"};
            int m = -1;
            for (int k = 0; k < 3; k++)
                if (!strcmp(f[1], places[k]))
                    m = k;
            if (m < 0) {
                snprintf(err, err_cap, "line %ld: minimap '%.20s' is not hud, hand or off",
                         lineno, f[1]);
                return 1;
            }
            L.minimap = m;
        } else {
            snprintf(err, err_cap, "line %ld: unknown key or wrong value count: '%.20s'",
                     lineno, key);
            return 1;
        }
    }
    if (!have_mode) {
        snprintf(err, err_cap, "line %ld: no 'mode' line%s", lineno ? lineno : 1,
                 lineno ? "" : " (the level is empty)");
        return 1;
    }
    /* a placement may not stand where an objective is given */
    hol_room r0 = hol_room_start();
    for (int i = 0; i < L.nstart; i++)
        if (hol_room_step(&r0, L.start[i])) {
            snprintf(err, err_cap, "line %ld: the start walk leaves the room", lineno);
            return 1;
        }
    for (int k = 0; k < L.nplaces; k++) {
        hol_tile t = L.places[k].tile;
        const char *what = NULL;
        long at = 0;
        if (L.mode == HOL_APP_FLAG && flag_line && !flag_lo && hol_tile_eq(t, L.flag))
            what = "the flag", at = flag_line;
        for (int j = 0; L.mode == HOL_APP_KEYS && !keys_n && j < L.nkeys; j++)
            if (hol_tile_eq(t, L.keys[j]))
                what = "a key", at = keys_line;
        if (L.mode == HOL_APP_KEYS && chest_line && !chest_lo && hol_tile_eq(t, L.chest))
            what = "the chest", at = chest_line;
        if (what) {
            char a[HOL_TILE_ADDR_MAX];
            hol_tile_print(t, a);
            snprintf(err, err_cap, "line %ld: the placement on %s conflicts with %s (line %ld)",
                     place_line[k], a, what, at);
            return 1;
        }
    }
    /* objectives by distance from the start tile, drawn from the seed */
    uint64_t rng = L.seed ^ 0x6c6576656cull;
    if (L.mode == HOL_APP_FLAG && flag_lo &&
        level_draw(&L, r0.tile, flag_lo, flag_hi, &rng, &L.flag)) {
        snprintf(err, err_cap, "line %ld: no free tile for the flag at that distance", flag_line);
        return 1;
    }
    if (L.mode == HOL_APP_KEYS && chest_lo &&
        level_draw(&L, r0.tile, chest_lo, chest_hi, &rng, &L.chest)) {
        snprintf(err, err_cap, "line %ld: no free tile for the chest at that distance",
                 chest_line);
        return 1;
    }
    if (L.mode == HOL_APP_KEYS && keys_n) {
        L.nkeys = 0;
        for (int k = 0; k < keys_n; k++) {
            hol_tile t;
            if (level_draw(&L, r0.tile, keys_lo, keys_hi, &rng, &t)) {
                snprintf(err, err_cap, "line %ld: no free tile for key %d at that distance",
                         keys_line, k + 1);
                return 1;
            }
            L.keys[L.nkeys++] = t;
        }
    }
    *lvl = L;
    return 0;
}

/* ---- logs ----------------------------------------------------------------- */

static void ring_push_step(session *s, const hol_app_step_event *e)
{
    long i = (s->step_head + s->step_n) % SESSION_STEP_ROWS;
    s->step_ring[i] = *e;
    if (s->step_n < SESSION_STEP_ROWS)
        s->step_n++;
    else {
        s->step_head = (s->step_head + 1) % SESSION_STEP_ROWS;
        s->step_dropped++;
    }
}

static void ring_push_head(session *s, const session_head_row *r)
{
    long i = (s->head_head + s->head_n) % SESSION_HEAD_ROWS;
    s->head_ring[i] = *r;
    if (s->head_n < SESSION_HEAD_ROWS)
        s->head_n++;
    else {
        s->head_head = (s->head_head + 1) % SESSION_HEAD_ROWS;
        s->head_dropped++;
    }
}

static int log_path(const session *s, char *buf, size_t cap, const char *what)
{
    int n = s->attempt ? snprintf(buf, cap, "%s/%s-%03d.csv", s->log_dir, what, s->attempt)
                       : 0;
    return n < 0 || (size_t)n >= cap;
}

static int write_attempt_logs(session *s, const hol_app_summary *sum)
{
    if (!s->log_dir || !s->attempt_open)
        return 0;
    s->attempt_open = 0;
    const char *lname = s->levels[s->cur].name;
    char path[4096], addr[HOL_TILE_ADDR_MAX];
    hol_file_atomic a;
    /* steps */
    if (log_path(s, path, sizeof path, "steps") || hol_file_atomic_open(&a, path))
        goto fail;
    fprintf(a.f, "attempt,level,t,step,col,row,dir,yaw,tile,orient,remaining,cues\n");
    for (long k = 0; k < s->step_n; k++) {
        const hol_app_step_event *e = &s->step_ring[(s->step_head + k) % SESSION_STEP_ROWS];
        hol_tile_print(e->room.tile, addr);
        fprintf(a.f, "%d,%s,%.4f,%d,%d,%d,%c,%.2f,%s,%d,%d,%u\n", s->attempt, lname, e->t,
                e->index, e->room.col, e->room.row, hol_dir_to_char(e->dir), e->yaw_deg, addr,
                e->room.orient, e->remaining, e->cues);
    }
    if (hol_file_atomic_commit(&a))
        goto fail;
    /* head */
    if (log_path(s, path, sizeof path, "head") || hol_file_atomic_open(&a, path))
        goto fail;
    fprintf(a.f, "attempt,level,t,x,y,z,yaw,pitch,col,row,tile\n");
    for (long k = 0; k < s->head_n; k++) {
        const session_head_row *r = &s->head_ring[(s->head_head + k) % SESSION_HEAD_ROWS];
        hol_tile_print(r->room.tile, addr);
        fprintf(a.f, "%d,%s,%.1f,%.4f,%.4f,%.4f,%.2f,%.2f,%d,%d,%s\n", s->attempt, lname, r->t,
                r->pos[0], r->pos[1], r->pos[2], r->yaw, r->pitch, r->room.col, r->room.row,
                addr);
    }
    if (hol_file_atomic_commit(&a))
        goto fail;
    /* summary: every attempt so far */
    if (s->nsummary < SESSION_MAX_ATTEMPTS) {
        session_summary_row *r = &s->summary[s->nsummary++];
        r->attempt = s->attempt;
        r->level = s->cur;
        r->s = *sum;
        r->dropped = s->step_dropped + s->head_dropped;
    }
    snprintf(path, sizeof path, "%s/summary.csv", s->log_dir);
    if (hol_file_atomic_open(&a, path))
        goto fail;
    fprintf(a.f, "attempt,level,mode,seed,steps,optimum,time,end,dropped\n");
    for (int k = 0; k < s->nsummary; k++) {
        const session_summary_row *r = &s->summary[k];
        fprintf(a.f, "%d,%s,%s,%llu,%d,%d,%.4f,%s,%ld\n", r->attempt, s->levels[r->level].name,
                mode_names[r->s.mode], (unsigned long long)r->s.seed, r->s.steps, r->s.optimum,
                r->s.time_s, end_names[r->s.end], r->dropped);
    }
    if (hol_file_atomic_commit(&a))
        goto fail;
    return 0;
fail:
    cli_error(s->cmd, 0, "cannot write the logs in '%.200s': %s", s->log_dir, strerror(errno));
    return -1;
}

static void begin_attempt(session *s)
{
    s->attempt++;
    s->attempt_open = 1;
    s->step_head = s->step_n = s->step_dropped = 0;
    s->head_head = s->head_n = s->head_dropped = 0;
}

/* ---- the session ------------------------------------------------------------ */

static int start_level(session *s)
{
    hol_err err = hol_app_start_level(s->app, &s->levels[s->cur].lvl);
    if (err) {
        cli_error(s->cmd, 0, "level '%.60s' cannot start: %s", s->levels[s->cur].name,
                  err == HOL_EBUDGET ? "its optimum cannot be proved exact"
                  : err == HOL_EARG  ? "an objective on the start tile, or a start walk "
                                       "leaving the room"
                                     : hol_err_str(err));
        return CLI_EXIT_USAGE;
    }
    return 0;
}

int session_open(session *s, const char *cmd, session_level *levels, int nlevels,
                 const char *log_dir, const char *record_path)
{
    memset(s, 0, sizeof *s);
    s->cmd = cmd;
    s->levels = levels;
    s->nlevels = nlevels;
    s->log_dir = log_dir;
    if (log_dir) {
        s->step_ring = calloc(SESSION_STEP_ROWS, sizeof *s->step_ring);
        s->head_ring = calloc(SESSION_HEAD_ROWS, sizeof *s->head_ring);
        s->summary = calloc(SESSION_MAX_ATTEMPTS, sizeof *s->summary);
        if (!s->step_ring || !s->head_ring || !s->summary) {
            cli_error(cmd, 0, "out of memory");
            session_close(s);
            return CLI_EXIT_FAIL;
        }
    }
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    hol_err err = hol_app_create(&d, &s->app);
    if (err) {
        cli_error(cmd, 0, "cannot create the app: %s", hol_err_str(err));
        session_close(s);
        return CLI_EXIT_FAIL;
    }
    int st = start_level(s);
    if (st) {
        session_close(s);
        return st;
    }
    if (record_path) {
        if (hol_file_atomic_open(&s->rec, record_path)) {
            cli_error(cmd, 0, "cannot write '%.200s': %s", record_path, strerror(errno));
            session_close(s);
            return CLI_EXIT_FAIL;
        }
        s->recording = 1;
        static char recbuf[1 << 20];
        setvbuf(s->rec.f, recbuf, _IOFBF, sizeof recbuf);
        fprintf(s->rec.f, "holonomy-rec %d\n", SESSION_REC_VERSION);
        for (int i = 0; i < nlevels; i++) {
            fprintf(s->rec.f, "level %s\n", levels[i].name);
            const char *p = levels[i].text, *e = p + levels[i].len;
            while (p < e) {
                const char *nl = memchr(p, '\n', (size_t)(e - p));
                size_t n = (size_t)((nl ? nl : e) - p);
                fprintf(s->rec.f, "L %.*s\n", (int)n, p);
                p = nl ? nl + 1 : e;
            }
            fprintf(s->rec.f, "end\n");
        }
    }
    return 0;
}

int session_step(session *s, const hol_input *in)
{
    if (s->finished)
        return 1;
    hol_err err = hol_app_step(s->app, in);
    if (err) {
        cli_error(s->cmd, 0, "frame %ld: the app step failed: %s", s->frame, hol_err_str(err));
        return -1;
    }
    s->frame++;
    if (s->recording) {
        char line[HOL_INPUT_LINE_MAX + 1];
        size_t n = hol_input_format(in, line, sizeof line);
        fwrite(line, 1, n, s->rec.f);
        fputc('\n', s->rec.f);
    }
    const hol_app_events *ev = hol_app_get_events(s->app);
    const hol_app_view *v = hol_app_get_view(s->app);
    if (s->log_dir) {
        /* a restart ends the old attempt before the new one's rows; a
         * completion ends it after this step's rows */
        if (ev->level_ended && ev->level_started && write_attempt_logs(s, &ev->summary))
            return -1;
        if (ev->level_started)
            begin_attempt(s);
        for (int i = 0; i < ev->nsteps; i++)
            ring_push_step(s, &ev->steps[i]);
        if (ev->head_sample) {
            session_head_row r;
            r.t = ev->head_sample_t;
            memcpy(r.pos, v->head, sizeof r.pos);
            r.yaw = v->yaw_deg;
            r.pitch = v->pitch_deg;
            r.room = v->user;
            ring_push_head(s, &r);
        }
        if (ev->level_ended && !ev->level_started && write_attempt_logs(s, &ev->summary))
            return -1;
    }
    if (v->state == HOL_APP_QUIT) {
        s->finished = 1;
        return 1;
    }
    if (ev->next_level) {
        if (s->cur + 1 >= s->nlevels) {
            s->finished = 1;
            return 1;
        }
        s->cur++;
        if (start_level(s))
            return -1;
    }
    return 0;
}

int session_close(session *s)
{
    int status = 0;
    if (s->app && s->attempt_open) {
        const hol_app_view *v = hol_app_get_view(s->app);
        hol_app_summary sum;
        memset(&sum, 0, sizeof sum);
        sum.mode = s->levels[s->cur].lvl.mode;
        sum.seed = s->levels[s->cur].lvl.seed;
        sum.steps = v->hud.steps;
        sum.optimum = v->hud.optimum;
        sum.time_s = v->hud.elapsed_s;
        sum.end = HOL_APP_END_NONE;
        if (write_attempt_logs(s, &sum))
            status = CLI_EXIT_FAIL;
    }
    if (s->recording) {
        if (hol_file_atomic_commit(&s->rec)) {
            cli_error(s->cmd, 0, "cannot write the recording: %s", strerror(errno));
            status = CLI_EXIT_FAIL;
        }
        s->recording = 0;
    }
    hol_app_destroy(s->app);
    free(s->step_ring);
    free(s->head_ring);
    free(s->summary);
    memset(s, 0, sizeof *s);
    return status;
}

long session_read_header(char *const *lines, const size_t *lens, long nlines,
                         session_level *levels, int *nlevels, char *err, size_t err_cap)
{
    char want[32];
    snprintf(want, sizeof want, "holonomy-rec %d", SESSION_REC_VERSION);
    if (nlines < 1 || strncmp(lines[0], "holonomy-rec ", 13)) {
        snprintf(err, err_cap, "line 1: not a recording (no 'holonomy-rec' header)");
        return 0;
    }
    if (lens[0] != strlen(want) || memcmp(lines[0], want, lens[0])) {
        snprintf(err, err_cap, "line 1: recording format '%.30s' is not version %d",
                 lines[0] + 13, SESSION_REC_VERSION);
        return 0;
    }
    int n = 0;
    long i = 1;
    while (i < nlines && !strncmp(lines[i], "level ", 6)) {
        if (n >= SESSION_MAX_LEVELS) {
            snprintf(err, err_cap, "line %ld: more than %d levels", i + 1, SESSION_MAX_LEVELS);
            return 0;
        }
        session_level *L = &levels[n];
        memset(L, 0, sizeof *L);
        snprintf(L->name, sizeof L->name, "%.*s", (int)(lens[i] - 6), lines[i] + 6);
        long first = i + 1;
        for (i++; i < nlines && !strncmp(lines[i], "L ", 2); i++) {
            size_t m = lens[i] - 2;
            if (L->len + m + 1 > sizeof L->text) {
                snprintf(err, err_cap, "line %ld: level '%.40s' longer than %zu bytes", i + 1,
                         L->name, sizeof L->text);
                return 0;
            }
            memcpy(L->text + L->len, lines[i] + 2, m);
            L->len += m;
            L->text[L->len++] = '\n';
        }
        if (i >= nlines || strcmp(lines[i], "end")) {
            snprintf(err, err_cap, "line %ld: level '%.40s' not closed by 'end'", i + 1, L->name);
            return 0;
        }
        char perr[256];
        if (session_parse_level(L->text, L->len, &L->lvl, perr, sizeof perr)) {
            /* name the recording's lines: the level's line N is line
             * first + N, also where the message names another line (a
             * conflict: "... (line M)", "... placed on line M") */
            long ln = strtol(perr + 5, NULL, 10);
            const char *msg = strchr(perr, ':');
            char *other = strstr(perr, " (line ");
            if (other) {
                long m = strtol(other + 7, NULL, 10);
                snprintf(other, sizeof perr - (size_t)(other - perr), " (line %ld)", first + m);
            } else if ((other = strstr(perr, " on line "))) {
                long m = strtol(other + 9, NULL, 10);
                snprintf(other, sizeof perr - (size_t)(other - perr), " on line %ld", first + m);
            }
            snprintf(err, err_cap, "line %ld: level '%.40s'%s", first + ln, L->name,
                     msg ? msg : perr);
            return 0;
        }
        i++;
        n++;
    }
    if (n == 0) {
        snprintf(err, err_cap, "line %ld: the recording holds no level", i + 1);
        return 0;
    }
    *nlevels = n;
    return i + 1;
}
