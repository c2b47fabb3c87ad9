/* hol_app_tutorial.c - the tutorial's lessons (see hol_app.h and
 * hol_app_impl.h): targets, completion, feedback, and lesson 2's search.
 * Each lesson begins facing what it names (issue 35; not with
 * desc.flow_v4, the lessons as recordings of version 1 to 4 played them):
 * its marker, tree or flag is chosen on the side the look is nearest to,
 * and a pancake view turns to it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_str.h"

/* The tile reached from room state r by steps given as turns relative to
 * the room's north (0 ahead, 1 left, ...), turning as one walks. */
static hol_tile hol__tile_ahead(const hol_room *r, const int *turns, int n)
{
    hol_heading_tile ht = {r->tile, r->orient};
    for (int i = 0; i < n; i++)
        if (hol_heading_tile_step(ht, turns[i], &ht))
            break;
    return ht.tile;
}

/* The look's bearing (SPEC 1's yaw: 0 north, positive west) and the
 * angle, 0..180, between it and bearing b. */
static double hol__look_bearing(const hol_app *app)
{
    double b = fmod(-app->mo.yaw_deg, 360.0);
    return b < 0 ? b + 360.0 : b;
}

static double hol__off_look(double look, double b)
{
    double d = fabs(fmod(b - look, 360.0));
    return d > 180.0 ? 360.0 - d : d;
}

/* The room directions a lesson tries, in order: north, west, east, south
 * (desc.flow_v4: always), else sorted by how near each is to the look
 * (that order kept among equals). */
static void hol__dirs(const hol_app *app, int out[4])
{
    static const int order[4] = {HOL_DIR_N, HOL_DIR_W, HOL_DIR_E, HOL_DIR_S};
    double look = hol__look_bearing(app), off[4];
    for (int i = 0; i < 4; i++) {
        out[i] = order[i];
        off[i] = hol__off_look(look, (4 - order[i]) % 4 * 90.0); /* N 0, W 270 */
    }
    for (int i = 1; i < 4 && !app->d.flow_v4; i++) /* insertion: stable */
        for (int j = i; j > 0 && off[j] < off[j - 1] - 1e-9; j--) {
            double o = off[j];
            int d = out[j];
            off[j] = off[j - 1], out[j] = out[j - 1];
            off[j - 1] = o, out[j - 1] = d;
        }
}

/* The first of the lesson's directions (hol__dirs) with n cells free
 * ahead of r; -1 when none. */
static int hol__free_dir(const hol_app *app, const hol_room *r, int n)
{
    int dirs[4];
    hol__dirs(app, dirs);
    for (int i = 0; i < 4; i++) {
        hol_room m = *r;
        int k = 0;
        while (k < n && !hol_room_step(&m, dirs[i]))
            k++;
        if (k == n)
            return dirs[i];
    }
    return -1;
}

/* Lesson 3's marker: two tiles away in a straight line that the room
 * allows (the first of the lesson's directions with two cells free: after
 * lessons 1 and 2 by the north hedge, two steps south), so the two tiles
 * are two room steps, not a walk round the hedge; where no line fits (the
 * centre of a 3 x 3 room, a level that begins with this lesson) two tiles
 * ahead. */
static hol_tile hol__two_ahead(const hol_app *app, const hol_room *r)
{
    static const int two[2] = {0, 0};
    int d = hol__free_dir(app, r, 2);
    if (d < 0)
        return hol__tile_ahead(r, two, 2);
    hol_room n = *r;
    (void)hol_room_step(&n, d);
    (void)hol_room_step(&n, d);
    return n.tile;
}

/* Lessons 1 and 4 go first the way hol__free_dir finds for one free cell
 * (desc.flow_v4: north). */
static int hol__first_turn(const hol_app *app, const hol_room *r)
{
    int d = app->d.flow_v4 ? HOL_DIR_N : hol__free_dir(app, r, 1);
    return d < 0 ? HOL_DIR_N : d;
}

/* Lesson 2's marked tree: the room vertex that the lesson's first
 * fewest-steps walk from its start goes round (a square of 4 steps: its
 * first two steps name the corner of the cell); else the first inner
 * corner of the cell (NW, NE, SW, SE). None in no room this game has. */
static void hol__mark_tree(hol_app *app, const hol_room *r)
{
    uint8_t w[HOL__LOOP_MAX];
    int c = r->col, row = r->row, cols = hol_room_cols(r), rows = hol_room_rows(r);
    app->has_tree = 0;
    if (hol__loop_left(app, r, w, (int)sizeof w) == 4 && (w[0] - w[1]) % 2 &&
        w[2] == (w[0] + 2) % 4 && w[3] == (w[1] + 2) % 4) {
        app->tree[0] = c + (w[0] == HOL_DIR_E || w[1] == HOL_DIR_E);
        app->tree[1] = row + (w[0] == HOL_DIR_S || w[1] == HOL_DIR_S);
        app->has_tree = 1;
        return;
    }
    for (int k = 0; k < 4; k++) {
        int x = c + (k & 1), z = row + (k >> 1);
        if (x > 0 && x < cols && z > 0 && z < rows) {
            app->tree[0] = x;
            app->tree[1] = z;
            app->has_tree = 1;
            return;
        }
    }
}

/* The bearing from the centre of r's cell to room vertex (x, z). */
static double hol__vertex_bearing(const hol_room *r, int x, int z)
{
    return hol_bearing_of_vector(x - (r->col + 0.5), (r->row + 0.5) - z);
}

/* Lesson 2's tree where the look is nearest: of the inner corners of the
 * cell, the one nearest the look (hol__mark_tree's first among equals). */
static void hol__tree_in_view(hol_app *app, const hol_room *r)
{
    int cols = hol_room_cols(r), rows = hol_room_rows(r);
    double look = hol__look_bearing(app);
    double best = app->has_tree ? hol__off_look(look, hol__vertex_bearing(r, app->tree[0],
                                                                          app->tree[1]))
                                : 1e9;
    for (int k = 0; k < 4; k++) {
        int x = r->col + (k & 1), z = r->row + (k >> 1);
        double off = hol__off_look(look, hol__vertex_bearing(r, x, z));
        if (x > 0 && x < cols && z > 0 && z < rows && off < best - 1e-9) {
            app->tree[0] = x;
            app->tree[1] = z;
            app->has_tree = 1;
            best = off;
        }
    }
}

/* A pancake view turns at the lesson's next frame to face bearing b (to
 * 0.01 degree). */
static void hol__face(hol_app *app, double b)
{
    double yaw = floor(fmod(720.0 - b, 360.0) * 100.0 + 0.5) / 100.0;
    app->face_yaw = yaw >= 360.0 ? 0.0 : yaw;
    app->face_pending = 1;
}

/* Lesson k's thing in view (not with desc.flow_v4): the tree chosen by
 * the look, and the view turned to the tree or the target. */
static void hol__stage_facing(hol_app *app, int k, const hol_room *r)
{
    double b;
    if (app->d.flow_v4)
        return;
    if (k == 1 && app->has_tree) {
        hol__tree_in_view(app, r);
        hol__face(app, hol__vertex_bearing(r, app->tree[0], app->tree[1]));
    } else if (app->has_target && !hol_bearing_true(r->tile, r->orient, app->target, &b)) {
        hol__face(app, b);
    }
}

/* The first lesson at or after k that the level plays (HOL_APP_TUTORIAL_STAGES:
 * none left). */
int hol__next_stage(const hol_app *app, int k)
{
    unsigned want = app->level.stages ? app->level.stages : (1u << HOL_APP_TUTORIAL_STAGES) - 1;
    while (k < HOL_APP_TUTORIAL_STAGES && !(want >> k & 1))
        k++;
    return k;
}

/* Begin tutorial stage k at room state r: its target (if any) and the
 * world marker on it. The caller plans the lesson's optimum. */
void hol__stage(hol_app *app, int k, const hol_room *r)
{
    int one[1] = {hol__first_turn(app, r)}, three[3] = {one[0], 0, 1};
    app->stage = k;
    app->stage_start = *r;
    app->stage_steps = 0;
    app->stage_optimum = -1;
    app->has_target = k != 1;
    if (k == 0)
        app->target = hol__tile_ahead(r, one, 1);
    else if (k == 2)
        app->target = hol__two_ahead(app, r);
    else if (k == 3)
        app->target = hol__tile_ahead(r, three, 3);
    if (app->has_target) {
        hol_tile placed;
        (void)hol_world_reserve(app->world, app->target, 0, HOL_OBJ_FLAG, &placed);
    }
    app->has_tree = 0;
    if (k == 1)
        hol__mark_tree(app, r);
    hol__stage_facing(app, k, r);
}

void hol__lesson_done(hol_app *app, int stage, hol_app_lesson lesson, double t)
{
    if (app->stage != stage) { /* a lesson begins here */
        app->stage_optimum = app->remaining;
        app->stage_t0 = t;
    }
    if (!app->d.flow_v4 && app->ev.nlessons < HOL_APP_TUTORIAL_STAGES)
        app->ev.lessons[app->ev.nlessons++] = lesson;
}

void hol__tutorial_enter(hol_app *app, const hol_room *r)
{
    app->stage_steps++;
    const hol_room *s0 = &app->stage_start;
    int passed = app->has_target ? hol_tile_eq(r->tile, app->target)
                                 : app->stage_steps >= 4 && r->col == s0->col &&
                                       r->row == s0->row && !hol_tile_eq(r->tile, s0->tile);
    if (!passed)
        return;
    /* feedback: what was learnt, and for the loop both tiles of the cell */
    /* what the lesson's end says (lesson 4's end is the level's end screen) */
    snprintf(app->feedback, sizeof app->feedback, "%s",
             hol_str(hol__lang(app), (hol_str_id)(HOL_S_LESSON_1_DONE + app->stage)));
    app->feedback_until = app->level_t + HOL__FEEDBACK_S;
    app->nmarks = 0;
    app->rings_note = 0;
    if (!app->has_target) {
        app->marks[app->nmarks++] = s0->tile;
        app->marks[app->nmarks++] = r->tile;
        app->rings_note = !app->rings_told; /* the first rings: what they mean */
        app->rings_told = 1;
    }
    int next = hol__next_stage(app, app->stage + 1);
    if (next >= HOL_APP_TUTORIAL_STAGES) {
        app->done = 1;
        return;
    }
    if (app->has_target)
        (void)hol_world_release(app->world, app->target);
    hol__stage(app, next, r);
}

/* ---- lesson 2: the fewest steps back to the cell on another tile -------- */

typedef struct hol__loop {
    int col, row;      /* the lesson's cell */
    hol_tile tile;     /* and its tile then */
    int need;          /* steps still needed to reach 4 */
    uint8_t walk[HOL__LOOP_MAX];
} hol__loop;

static int hol__iabs(int v)
{
    return v < 0 ? -v : v;
}

/* Depth-first: a walk of exactly `left` more steps from r (depth d so far)
 * that ends on the lesson's cell on another tile; 1 found (in q->walk). */
static int hol__loop_dfs(hol__loop *q, const hol_room *r, int d, int left)
{
    int far = hol__iabs(r->col - q->col) + hol__iabs(r->row - q->row);
    if (far > left || (far - left) % 2)
        return 0; /* cannot get back in time (a step changes the parity) */
    if (left == 0)
        return !hol_tile_eq(r->tile, q->tile);
    for (uint8_t dir = 0; dir < 4; dir++) {
        hol_room n = *r;
        if (hol_room_step(&n, dir))
            continue; /* the hedge (or beyond the reach of tile words) */
        q->walk[d] = dir;
        if (hol__loop_dfs(q, &n, d + 1, left - 1))
            return 1;
    }
    return 0;
}

int hol__loop_left(const hol_app *app, const hol_room *r, uint8_t *out_walk, int cap)
{
    hol__loop q;
    q.col = app->stage_start.col;
    q.row = app->stage_start.row;
    q.tile = app->stage_start.tile;
    q.need = 4 - app->stage_steps;
    /* iterative deepening: the first length that works is the fewest */
    for (int n = q.need > 0 ? q.need : 0; n <= HOL__LOOP_MAX; n++)
        if (hol__loop_dfs(&q, r, 0, n)) {
            int m = n < cap ? n : cap;
            memcpy(out_walk, q.walk, (size_t)m);
            return n;
        }
    return -1;
}
