/* hol_sound.c - the sources around the listener and their synthesis (see
 * hol_sound.h). */
#include "hol_sound.h"

#include <math.h>
#include <string.h>

#include "hol_hyper.h"
#include "hol_math.h"
#include "hol_world.h"

#define HOL__PI 3.14159265358979323846
#define HOL__SND_TILES 1024 /* tiles a frame visits at most */
#define HOL__SND_CAND HOL_SOUND_MAX_AMB   /* ambient sources a frame weighs at most */

/* ---- geometry ----------------------------------------------------------------- */

typedef struct hol__sg {
    int flat;
    double klein, mpu;   /* Klein per metre, metres per curvature unit */
    double p[3];         /* the listener's point (user frame) */
    double boost[9];     /* takes p to the origin */
    double head_h;
    double radius;       /* the ambience's window, metres */
    double reach;        /* R in curvature units (tile sides flat) plus rho */
    double rho;          /* a tile's circumradius (the same units) */
    double q[4];         /* head quaternion x, y, z, w */
    hol_room user;
} hol__sg;

static void hol__sg_init(hol__sg *g, const hol_app_view *v)
{
    double m = v->cell_m > 0 ? v->cell_m : 1.0;
    int q = hol_tile_q(v->user.tile);
    g->flat = q == 4;
    g->user = v->user;
    if (g->flat) {
        g->klein = 1 / m;
        g->mpu = m;
    } else {
        double e = hol_hyper_edge_q(q);
        /* tanh(e/2) = sqrt(1 - 1/cosh^2(e/2)), cosh(e/2) = cos(pi/q)/sin(pi/4) */
        double ch = hol_cos(HOL__PI / q) * sqrt(2.0);
        g->klein = sqrt(1 - 1 / (ch * ch)) / (m / 2);
        g->mpu = m / e;
    }
    double kx = (v->head[0] - (v->user.col + 0.5) * m) * g->klein;
    double ky = -(v->head[2] - (v->user.row + 0.5) * m) * g->klein;
    hol_hyper_from_klein(kx, ky, g->flat, g->p);
    double px = g->p[0], py = g->p[1], pw = g->p[2];
    double k = g->flat ? 0 : 1 / (1 + pw);
    double b[9] = {1 + k * px * px, k * px * py, -px, k * px * py, 1 + k * py * py, -py,
                   -px, -py, pw};
    memcpy(g->boost, b, sizeof b);
    g->head_h = v->head[1];
    g->radius = hol_sound_radius_m(q, m);
    g->rho = g->flat ? 0.7072 : hol_acosh(hol_cos(HOL__PI / q) / hol_sin(HOL__PI / q));
    g->reach = g->radius / g->mpu + g->rho;
    for (int i = 0; i < 4; i++)
        g->q[i] = v->head_quat[i];
}

/* Rotate room vector a by the inverse of the head's rotation. */
static void hol__to_head(const double q[4], const double a[3], double out[3])
{
    double x = -q[0], y = -q[1], z = -q[2], w = q[3];
    /* t = 2 (u x a); out = a + w t + u x t, u = (x, y, z) */
    double t0 = 2 * (y * a[2] - z * a[1]), t1 = 2 * (z * a[0] - x * a[2]),
           t2 = 2 * (x * a[1] - y * a[0]);
    out[0] = a[0] + w * t0 + (y * t2 - z * t1);
    out[1] = a[1] + w * t1 + (z * t0 - x * t2);
    out[2] = a[2] + w * t2 + (x * t1 - y * t0);
}

double hol_sound_radius_m(int q, double cell_m)
{
    double m = cell_m > 0 ? cell_m : 1.0, r = HOL_SOUND_RADIUS_M;
    if (q > 4 && q <= 8) { /* the horizon: HOL_SOUND_HORIZON curvature radii */
        double h = HOL_SOUND_HORIZON * m / hol_hyper_edge_q(q);
        r = h < r ? h : r;
    }
    return r;
}

double hol_sound_falloff(double d_m, double chord, int flat, double radius_m)
{
    double w = 1;
    if (radius_m > 0) {
        if (d_m >= radius_m)
            return 0;
        double u = d_m / radius_m;
        w = (1 - u * u) * (1 - u * u);
    }
    double s = 1;
    if (!flat && chord > 1e-6) /* x = 2 asinh(c/2), sinh x = c sqrt(1 + c^2/4) */
        s = 2 * hol_asinh(chord / 2) / (chord * sqrt(1 + chord * chord / 4));
    return w * sqrt(s) / (1 + d_m / HOL_SOUND_D0_M);
}

/* The source at point S (user frame) h metres up: its true distance, the
 * chord to it (Lorentz norm) and its direction in the head's frame. */
static void hol__place(const hol__sg *g, const double S[3], double h, double *out_d,
                       double *out_x, double dir[3])
{
    double dx = S[0] - g->p[0], dy = S[1] - g->p[1];
    double c = hol_hyper_chord(S, g->p, g->flat);
    double x = hol_hyper_dist(S, g->p, g->flat);
    double fm = x * g->mpu, dh = h - g->head_h;
    double v[3];
    if (g->flat) {
        v[0] = dx, v[1] = dy;
    } else {
        double ip = g->p[0] * S[0] + g->p[1] * S[1] - g->p[2] * S[2]; /* <P,S> */
        double t[3] = {S[0] + ip * g->p[0], S[1] + ip * g->p[1], S[2] + ip * g->p[2]};
        for (int i = 0; i < 2; i++)
            v[i] = g->boost[3 * i] * t[0] + g->boost[3 * i + 1] * t[1] + g->boost[3 * i + 2] * t[2];
    }
    double n = sqrt(v[0] * v[0] + v[1] * v[1]);
    double room[3] = {0, dh, 0};
    if (n > 1e-12) {
        room[0] = v[0] / n * fm;  /* east */
        room[2] = -v[1] / n * fm; /* north is -z */
    }
    double d = sqrt(fm * fm + dh * dh);
    if (d > 1e-9)
        for (int i = 0; i < 3; i++)
            room[i] /= d;
    else
        room[0] = 0, room[1] = 0, room[2] = -1;
    hol__to_head(g->q, room, dir);
    *out_d = d;
    *out_x = c;
}

/* ---- the list ------------------------------------------------------------------- */

static uint32_t hol__tile_hash(hol_tile t, int kind)
{
    uint64_t h = t.bits[0] * 0x9E3779B97F4A7C15ull ^ (t.bits[1] + 0x632BE59BD9B4E019ull);
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return (uint32_t)(h & 0xffffff00u) | (uint32_t)kind;
}

/* Insert by gain into the list (loudest first, ties: the one found first). */
static void hol__add(hol_sound_list *o, int first, const hol_sound_src *s)
{
    if (s->gain <= 0)
        return;
    int k = o->n < HOL_SOUND_MAX_SOURCES ? o->n++ : HOL_SOUND_MAX_SOURCES;
    while (k > first && o->src[k - 1].gain < s->gain) {
        if (k < HOL_SOUND_MAX_SOURCES)
            o->src[k] = o->src[k - 1];
        k--;
    }
    if (k < HOL_SOUND_MAX_SOURCES)
        o->src[k] = *s;
}

/* The source of kind on tile t (frame fr) h metres up, its gain windowed
 * by radius_m (0: none). */
static void hol__tile_src(const hol__sg *g, hol_tile t, const double fr[9], int kind, double h,
                          double radius_m, hol_sound_src *out)
{
    double S[3] = {fr[2], fr[5], fr[8]}, x;
    out->kind = kind;
    out->id = hol__tile_hash(t, kind);
    hol__place(g, S, h, &out->dist_m, &x, out->dir);
    out->gain = hol_sound_falloff(out->dist_m, x, g->flat, radius_m);
}

static void hol__beacon(const hol__sg *g, hol_tile t, hol_sound_list *o)
{
    double fr[9];
    hol_sound_src s;
    if (hol_hyper_frame(g->user.tile, g->user.orient, t, fr))
        return;
    hol__tile_src(g, t, fr, HOL_SND_BEACON, 1.5, 0, &s);
    hol__add(o, 0, &s);
}

/* The tiles met so far, with their frames: an open-addressed set of
 * indices into tiles[]. */
typedef struct hol__tset {
    hol_tile tiles[HOL__SND_TILES];
    double fr[HOL__SND_TILES][9];
    int8_t depth[HOL__SND_TILES];     /* room steps from the first */
    int16_t slot[2 * HOL__SND_TILES]; /* index + 1; 0 empty */
    int n;
} hol__tset;

/* 1: t added (new), 0: met before or the set is full. */
static int hol__tset_add(hol__tset *ts, hol_tile t)
{
    uint32_t k = (uint32_t)hol_tile_hash(t) & (2 * HOL__SND_TILES - 1);
    while (ts->slot[k]) {
        if (hol_tile_eq(ts->tiles[ts->slot[k] - 1], t))
            return 0;
        k = (k + 1) & (2 * HOL__SND_TILES - 1);
    }
    if (ts->n >= HOL__SND_TILES)
        return 0;
    ts->tiles[ts->n++] = t;
    ts->slot[k] = (int16_t)ts->n;
    return 1;
}

static void hol__amb_add(hol_sound *st, const double fr[9], hol_tile t, int kind, double h)
{
    if (st->namb >= HOL_SOUND_MAX_AMB)
        return;
    hol_sound_amb *a = &st->amb[st->namb++];
    a->S[0] = fr[2], a->S[1] = fr[5], a->S[2] = fr[8];
    a->h = h;
    a->kind = kind;
    a->id = hol__tile_hash(t, kind);
}

/* The ambience of one tile (its frame fr) into the cache. */
static void hol__tile_ambience(hol_sound *st, const struct hol_world *w, hol_tile t,
                               const double fr[9])
{
    hol_tile_content c;
    if (hol_world_peek(w, t, &c))
        return;
    if (c.object == HOL_OBJ_CREEK || c.object == HOL_OBJ_SPRING || c.object == HOL_OBJ_POOL)
        hol__amb_add(st, fr, t, HOL_SND_WATER, 0);
    int big = 0;
    for (int k = 0; k < 4; k++)
        big |= c.tree[k].size >= 2;
    if (big && (hol__tile_hash(t, 0) >> 8) % 3 == 0)
        hol__amb_add(st, fr, t, HOL_SND_BIRDS, 3.0);
}

/* The cache: every ambient source whose tile's centre may come within R
 * of a listener in the user's tile (centre within R + rho of the user's
 * tile's centre, rho a tile's circumradius), found breadth first through
 * the tiles whose centre is within R + 2 rho (so none is missed); frames
 * carried along the walk (hol_hyper_frame_step). R is cut to the world's
 * generated radius: no nearer than a tile more steps away than the world
 * collapses (minus rho), so that no source appears when a tile collapses. */
static void hol__amb_build(hol_sound *st, const hol__sg *g, const struct hol_world *w)
{
    hol__tset ts;
    ts.n = 0;
    memset(ts.slot, 0, sizeof ts.slot);
    int q = hol_tile_q(g->user.tile), wr = hol_world_radius(w);
    double o[3] = {0, 0, 1}, reach = g->reach, beyond = 1e9;
    st->namb = 0;
    hol__tset_add(&ts, g->user.tile);
    ts.depth[0] = 0;
    if (hol_hyper_frame(g->user.tile, g->user.orient, g->user.tile, ts.fr[0]))
        return;
    for (int head = 0; head < ts.n; head++) {
        const double *fr = ts.fr[head];
        double S[3] = {fr[2], fr[5], fr[8]};
        double x = hol_hyper_dist(S, o, g->flat);
        if (ts.depth[head] > wr) { /* not generated: R ends before it */
            beyond = x < beyond ? x : beyond;
            continue;
        }
        if (x > reach + g->rho)
            continue;
        if (x <= reach)
            hol__tile_ambience(st, w, ts.tiles[head], fr);
        for (int e = 0; e < 4; e++) {
            hol_tile nb;
            int arrive;
            if (!hol_tile_step(ts.tiles[head], e, &nb, &arrive) && hol__tset_add(&ts, nb)) {
                hol_hyper_frame_step(q, fr, e, arrive, ts.fr[ts.n - 1]);
                ts.depth[ts.n - 1] = (int8_t)(ts.depth[head] + 1);
            }
        }
    }
    double rc = beyond - g->rho; /* R in curvature units (tile sides flat) */
    rc = rc < g->radius / g->mpu ? rc : g->radius / g->mpu;
    st->radius = rc > 0 ? rc * g->mpu : 0;
}

/* The ambient sources of this frame into cand[] (the cache rebuilt when
 * stale). */
static int hol__ambience(hol_sound *st, const hol__sg *g, const hol_app_view *v,
                         const struct hol_world *w, hol_sound_src *cand)
{
    hol_world_stats ws;
    hol_world_get_stats(w, &ws);
    uint64_t key[5] = {ws.tiles_collapsed, ws.backtracks, ws.evicted, ws.count,
                       hol_world_seed(w)};
    if (!st->valid || st->world != w || !hol_tile_eq(st->user.tile, v->user.tile) ||
        st->user.orient != v->user.orient || st->cell_m != v->cell_m ||
        memcmp(st->world_key, key, sizeof key)) {
        hol__amb_build(st, g, w);
        st->valid = 1, st->world = w, st->user = v->user, st->cell_m = v->cell_m;
        memcpy(st->world_key, key, sizeof key);
    }
    int nc = 0;
    for (int i = 0; i < st->namb && nc < HOL__SND_CAND; i++) {
        const hol_sound_amb *a = &st->amb[i];
        double x;
        hol_sound_src *s = &cand[nc];
        s->kind = a->kind;
        s->id = a->id;
        hol__place(g, a->S, a->h, &s->dist_m, &x, s->dir);
        s->gain = hol_sound_falloff(s->dist_m, x, g->flat, st->radius);
        nc += s->gain > 0;
    }
    return nc;
}

/* Wind in the room's four hedges: room points, the room is flat. */
static int hol__wind(const hol__sg *g, const hol_app_view *v, hol_sound_src *cand, int nc)
{
    double m = v->cell_m > 0 ? v->cell_m : 1.0;
    double W = hol_room_cols(&v->user) * m, D = hol_room_rows(&v->user) * m;
    const double pts[4][2] = {{W / 2, 0}, {W, D / 2}, {W / 2, D}, {0, D / 2}};
    for (int i = 0; i < 4 && nc < HOL__SND_CAND; i++) {
        double a[3] = {pts[i][0] - v->head[0], 1.0 - v->head[1], pts[i][1] - v->head[2]};
        double d = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        hol_sound_src *s = &cand[nc];
        s->kind = HOL_SND_WIND;
        s->id = (uint32_t)(0x57494e00u + (uint32_t)(i << 8)) | HOL_SND_WIND;
        s->dist_m = d;
        for (int k = 0; k < 3; k++)
            a[k] = d > 1e-9 ? a[k] / d : (k == 2 ? -1 : 0);
        hol__to_head(g->q, a, s->dir);
        s->gain = 0.5 * hol_sound_falloff(d, 0, 1, HOL_SOUND_RADIUS_M);
        nc += s->gain > 0;
    }
    return nc;
}

/* The candidates into the list after its beacons: all of them when they
 * fit; else the loudest that fit, each less the gain of the first left
 * out, so that a source enters or leaves the list at gain 0 (no pop). */
static void hol__choose(hol_sound_list *o, const hol_sound_src *cand, int nc)
{
    int room = HOL_SOUND_MAX_SOURCES - o->n, first = o->n;
    if (nc <= room) {
        for (int i = 0; i < nc; i++)
            hol__add(o, first, &cand[i]);
        return;
    }
    /* the room + 1 loudest, by insertion (ties: the one found first) */
    int top[HOL_SOUND_MAX_SOURCES + 1], nt = 0;
    for (int i = 0; i < nc; i++) {
        int k = nt < room + 1 ? nt++ : room + 1;
        while (k > 0 && cand[top[k - 1]].gain < cand[i].gain) {
            if (k < room + 1)
                top[k] = top[k - 1];
            k--;
        }
        if (k < room + 1)
            top[k] = i;
    }
    double cut = cand[top[room]].gain;
    for (int i = 0; i < room; i++) {
        hol_sound_src s = cand[top[i]];
        s.gain -= cut;
        hol__add(o, first, &s);
    }
}

static void hol__shot(hol_sound_list *o, int kind, double gain, double dy)
{
    if (o->nshots >= HOL_SOUND_MAX_SHOTS)
        return;
    hol_sound_src *s = &o->shot[o->nshots++];
    memset(s, 0, sizeof *s);
    s->kind = kind;
    s->id = (uint32_t)kind;
    s->gain = gain;
    s->dir[1] = dy;
    s->dir[2] = dy < 0 ? -0.2 : -1;
    double n = sqrt(s->dir[1] * s->dir[1] + s->dir[2] * s->dir[2]);
    s->dir[1] /= n, s->dir[2] /= n;
}

static void hol__effects(hol_sound *st, const hol_app_view *v, const hol_app_events *ev,
                         const struct hol_world *w, hol_sound_list *o)
{
    if (ev->level_started)
        hol__shot(o, HOL_SND_CHIME_START, 1.0, 0);
    for (int i = 0; i < ev->nsteps; i++) {
        hol_tile_content c;
        int kind = HOL_SND_STEP_EARTH;
        if (!hol_world_peek(w, ev->steps[i].room.tile, &c)) {
            if (c.object == HOL_OBJ_CREEK || c.object == HOL_OBJ_SPRING || c.object == HOL_OBJ_POOL)
                kind = HOL_SND_STEP_WATER;
            else if (c.object == HOL_OBJ_GRASS || c.object == HOL_OBJ_FLOWERS)
                kind = HOL_SND_STEP_GRASS;
        }
        hol__shot(o, kind, 0.6, -1);
    }
    if (!ev->level_started && v->hud.keys_held > st->keys_held)
        hol__shot(o, HOL_SND_CHIME_KEY, 1.0, 0);
    if (!ev->level_started && v->state == HOL_APP_DONE && st->state == HOL_APP_PLAYING &&
        !v->hud.timed_out)
        hol__shot(o, v->hud.keys_total > 0 ? HOL_SND_CHIME_CHEST : HOL_SND_CHIME_FLAG, 1.0, 0);
}

void hol_sound_init(hol_sound *s)
{
    memset(s, 0, sizeof *s);
}

hol_err hol_sound_update(hol_sound *s, const hol_app_view *v, const hol_app_events *ev,
                         const struct hol_world *w, hol_sound_list *out)
{
    if (!s || !v || !ev || !w || !out)
        return HOL_EARG;
    out->n = 0;
    out->nshots = 0;
    out->beacons = 0;
    if (v->state == HOL_APP_IDLE || v->sound == HOL_SOUND_OFF) {
        s->keys_held = v->hud.keys_held;
        s->state = v->state;
        return HOL_OK;
    }
    hol__sg g;
    hol__sg_init(&g, v);
    if (!v->paused)
        hol__effects(s, v, ev, w, out);
    if (v->state == HOL_APP_PLAYING && (v->map.cues & HOL_CUE_SOUND)) {
        for (int i = 0; i < v->map.nobjectives && out->n < HOL_SOUND_MAX_SOURCES; i++)
            hol__beacon(&g, v->map.objectives[i], out);
        out->beacons = out->n;
    }
    if (v->sound == HOL_SOUND_ALL) {
        hol_sound_src cand[HOL__SND_CAND];
        int nc = hol__ambience(s, &g, v, w, cand);
        hol__choose(out, cand, hol__wind(&g, v, cand, nc));
    }
    s->keys_held = v->hud.keys_held;
    s->state = v->state;
    return HOL_OK;
}

/* ---- synthesis ------------------------------------------------------------------ */

static const char *const hol__kind_names[HOL_SND_KINDS] = {
    "birds", "water", "wind", "beacon", "step-earth", "step-grass", "step-water",
    "chime-key", "chime-chest", "chime-flag", "chime-start"};

const char *hol_sound_kind_name(int kind)
{
    return kind >= 0 && kind < HOL_SND_KINDS ? hol__kind_names[kind] : "?";
}

int hol_sound_loops(int kind)
{
    return kind >= HOL_SND_BIRDS && kind <= HOL_SND_BEACON;
}

int hol_sound_length(int kind, int rate)
{
    if (kind < 0 || kind >= HOL_SND_KINDS || rate < 8000 || rate > 192000)
        return 0;
    if (hol_sound_loops(kind))
        return 2 * rate;
    return kind <= HOL_SND_STEP_WATER ? rate * 12 / 100 : rate * 12 / 10;
}

static double hol__noise(uint64_t *x)
{
    *x ^= *x << 13;
    *x ^= *x >> 7;
    *x ^= *x << 17;
    return (double)(*x >> 11) / 4503599627370496.0 - 1; /* -1..1 */
}

/* One sample of kind at sample i (t seconds), state in st[]. */
static double hol__sample(int kind, int i, int rate, double *st, uint64_t *rng)
{
    double t = (double)i / rate, n = hol__noise(rng), tw = 2 * HOL__PI;
    switch (kind) {
    case HOL_SND_WATER: /* band of noise, bubbling */
        st[0] += 0.25 * (n - st[0]);
        st[1] += 0.05 * (st[0] - st[1]);
        return 1.6 * (st[0] - st[1]) * (0.8 + 0.2 * hol_sin(tw * 3 * t));
    case HOL_SND_WIND: { /* low noise swelling twice in 2 s */
        st[0] += 0.02 * (n - st[0]);
        double sw = 0.5 - 0.5 * hol_cos(tw * t); /* 1 Hz: whole periods in 2 s */
        return 4.0 * st[0] * (0.3 + 0.7 * sw);
    }
    case HOL_SND_BIRDS: { /* three chirps (rising sweeps) in 2 s */
        double u = t * 1.5 - (int)(t * 1.5); /* 0..1 within a chirp slot */
        if (u > 0.25)
            return 0;
        double f = 2600 + 2400 * (u / 0.25);
        st[0] += tw * f / rate;
        if (st[0] > tw)
            st[0] -= tw;
        double env = hol_sin(HOL__PI * u / 0.25);
        return 0.5 * env * hol_sin(st[0]);
    }
    case HOL_SND_BEACON: { /* 880 Hz pips, 4 per second */
        double u = t * 4 - (int)(t * 4);
        double env = u < 0.3 ? hol_sin(HOL__PI * u / 0.3) : 0;
        return 0.6 * env * hol_sin(tw * 880 * t);
    }
    case HOL_SND_STEP_EARTH:
    case HOL_SND_STEP_GRASS:
    case HOL_SND_STEP_WATER: {
        double a = kind == HOL_SND_STEP_EARTH ? 0.08 : kind == HOL_SND_STEP_GRASS ? 0.5 : 0.25;
        st[0] += a * (n - st[0]);
        st[1] = i == 0 ? 1 : st[1] * (1 - 40.0 / rate); /* decay */
        double b = kind == HOL_SND_STEP_WATER ? 0.5 + 0.5 * hol_sin(tw * 300 * t) : 1;
        return (kind == HOL_SND_STEP_EARTH ? 3.0 : 1.2) * st[0] * st[1] * b;
    }
    default: { /* chimes: three partials, decaying */
        static const double base[4] = {1318.5, 659.3, 1046.5, 784.0};
        double f = base[kind - HOL_SND_CHIME_KEY];
        st[1] = i == 0 ? 1 : st[1] * (1 - 4.0 / rate);
        return 0.5 * st[1] *
               (hol_sin(tw * f * t) + 0.5 * hol_sin(tw * 2.76 * f * t) +
                0.25 * hol_sin(tw * 5.4 * f * t)) / 1.75;
    }
    }
}

hol_err hol_sound_synth(int kind, int rate, int16_t *out, int n)
{
    int len = hol_sound_length(kind, rate);
    if (!out || len == 0 || n != len)
        return HOL_EARG;
    uint64_t rng = 0x9E3779B97F4A7C15ull ^ (uint64_t)(kind + 1) * 0xD1B54A32D192ED03ull;
    double st[2] = {0, 0};
    int fade = hol_sound_loops(kind) ? rate / 100 : 0; /* loops meet without a click */
    for (int i = 0; i < n; i++) {
        double y = hol__sample(kind, i, rate, st, &rng);
        if (fade && kind != HOL_SND_BEACON && kind != HOL_SND_BIRDS) {
            if (i < fade)
                y *= (double)i / fade;
            else if (i >= n - fade)
                y *= (double)(n - 1 - i) / fade;
        }
        if (!hol_sound_loops(kind) && i >= n - rate / 100)
            y *= (double)(n - 1 - i) / (rate / 100);
        y = y > 1 ? 1 : y < -1 ? -1 : y;
        out[i] = (int16_t)(y * 32000);
    }
    return HOL_OK;
}
