/* hol_app_tutorial.c - the tutorial's lessons (see hol_app.h and
 * hol_app_impl.h): targets, completion, feedback, and lesson 2's search. */
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

/* Lesson 3's marker: two tiles away in a straight line that the room
 * allows (room north, else west, east, south: the first with two cells
 * free), so the two tiles are two room steps, not a walk round the hedge;
 * where no line fits (the centre of a 3 x 3 room, a level that begins
 * with this lesson) two tiles ahead. */
static hol_tile hol__two_ahead(const hol_room *r)
{
    static const int order[4] = {HOL_DIR_N, HOL_DIR_W, HOL_DIR_E, HOL_DIR_S};
    static const int two[2] = {0, 0};
    for (int i = 0; i < 4; i++) {
        hol_room n = *r;
        if (!hol_room_step(&n, order[i]) && !hol_room_step(&n, order[i]))
            return n.tile;
    }
    return hol__tile_ahead(r, two, 2);
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
    static const int one[1] = {0}, three[3] = {0, 0, 1};
    app->stage = k;
    app->stage_start = *r;
    app->stage_steps = 0;
    app->stage_optimum = -1;
    app->has_target = k != 1;
    if (k == 0)
        app->target = hol__tile_ahead(r, one, 1);
    else if (k == 2)
        app->target = hol__two_ahead(r);
    else if (k == 3)
        app->target = hol__tile_ahead(r, three, 3);
    if (app->has_target) {
        hol_tile placed;
        (void)hol_world_reserve(app->world, app->target, 0, HOL_OBJ_FLAG, &placed);
    }
    app->has_tree = 0;
    if (k == 1)
        hol__mark_tree(app, r);
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
