/* hol_lesson_text.c - every text a lesson shows, as one table (see
 * hol_lesson.h), and its expansion with the lesson's facts. The languages
 * work (issue 37) moves this table into the string table.
 *
 * A text names facts as {name}; every number comes from the core
 * (hol_lesson_facts), none is typed here: {q} squares at a corner, {deg} a
 * corner's degrees, {sum} a square's four, {end} the route's last tile,
 * {home} its fewest steps home, {flat} the flat grid's steps home (the
 * cells), {bearing} where the start lies from the end ("at B degrees",
 * or "under you"), {dir} lesson 3's right choice, {yesno} lesson 1's,
 * {close} "close" in {4,4} and "do not close" else, {steps} the route's steps, {c1} {c2} {c3} the
 * tiles at 1, 2, 3 steps here, {f1}.. in {4,4}, {h1}.. in {4,5}, {times}
 * the squares walked until home and {walked} their steps. Kept short: the
 * web page carries them (docs/web.md, the transfer size). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_lesson.h"

/* The worksheet's texts (title, goal, hint): left out of a build that
 * defines HOL_LESSON_APP_ONLY (the web page: its transfer size), where the
 * app shows none of them. */
#ifdef HOL_LESSON_APP_ONLY
#define HOL__SHEET(s) ""
#else
#define HOL__SHEET(s) s
#endif

/* Per lesson: title, goal, question, walk, check, hint (the columns of
 * enum hol_lesson_part), then the choices or the scale's two anchors. */
static const char *const hol__lessons[HOL_LESSONS][HOL_LESSON_PARTS + HOL_APP_MAX_CHOICES] = {
    {HOL__SHEET("One step, one tile"),
     HOL__SHEET("A square walk N, E, S, W closes on paper, not in the hyperbolic plane."),
     "Walk N, E, S, W. Are you back on your start tile?",
     "Walk N, E, S, W: step onto each marker and watch where you end.",
     "Answer: {yesno}. You ended on tile {end}, {home} step(s) from the start O: {q} squares "
     "meet at each corner, so four right turns {close} a square.",
     HOL__SHEET("Count the squares that meet at one corner of your cell."), "Yes", "No"},
    {HOL__SHEET("Corners"),
     HOL__SHEET("{q} squares meet at a corner: a corner is {deg} degrees, a square's four "
                "sum to {sum}."),
     "How many squares meet at a corner (round one tree)?",
     "Walk round the tree at your cell's north-west corner, following the markers, back to "
     "your start tile. Count the tiles.",
     "Answer: {q}. So a square's corner is 360/{q} = {deg} degrees, and its four corners sum "
     "to {sum} (360 on paper).",
     HOL__SHEET("The walk ends on the tile where it began: count its steps."), "fewer", "more"},
    {HOL__SHEET("Holonomy"),
     HOL__SHEET("A walk round one tree brings you back to your cell but onto another tile "
                "(holonomy)."),
     "You walk N, W, S, E round a tree, back to your cell. Where is the start tile?",
     "Walk N, W, S, E round the tree, following the markers, then point to the start tile.",
     "Answer: {dir}. Back in your cell, you are on tile {end}: {q} squares stand round the "
     "tree and you passed {steps}, so the start lies {bearing}.",
     HOL__SHEET("A tree has {q} squares round it, and you walk past four."), "Under my feet",
     "North", "East", "South", "West"},
    {HOL__SHEET("Growth"),
     HOL__SHEET("Tiles at 1, 2, 3 steps: {c1}, {c2}, {c3}; on a flat grid {f1}, {f2}, {f3}."),
     "How many tiles lie exactly 3 steps from the start tile?",
     "Walk the ring of cells round your start, following the markers.",
     "Answer: {c3}. At 1, 2, 3 steps lie {c1}, {c2}, {c3} tiles; on a flat grid {f1}, {f2}, "
     "{f3}; in {4,5} {h1}, {h2}, {h3}.",
     HOL__SHEET("On a flat grid there are {f3}; here each tile has more neighbours."), "fewer",
     "more"},
    {HOL__SHEET("No way back"),
     HOL__SHEET("The fewest steps home are not what a flat map says: {home}, not {flat}."),
     "After N, E, S, W, S, W, N, N, how few steps take you to the start tile?",
     "Walk N, E, S, W, S, W, N, N, following the markers. Then think how you would walk home.",
     "Answer: {home}. You stand {flat} cells from your start cell but {home} steps from the "
     "start tile (you are on {end}).",
     HOL__SHEET("Count the tiles on the picture, not the cells."), "fewer", "more"},
    {HOL__SHEET("Puzzle: the square walk"),
     HOL__SHEET("A square walk goes round one tree of {q} squares: home after {times}."),
     "How many times must you walk N, E, S, W to stand on your start tile again?",
     "Walk N, E, S, W again and again, following the markers, until you are home. Hint: each "
     "step goes round the same tree.",
     "Answer: {times}. Each step goes round the same tree, which has {q} squares round it: "
     "after {times} square(s), {walked} steps, you are home.",
     HOL__SHEET("Every step of the square goes round the same tree."), "fewer", "more"},
};

/* The facts' names, in the order hol__fact numbers them. */
static const char *const hol__names[] = {
    "q",  "deg", "sum", "home", "flat", "times", "walked", "steps", "c1",    "c2",    "c3",
    "f1", "f2",  "f3",  "h1",   "h2",   "h3",    "end",    "dir",   "yesno", "close", "bearing"};
#define HOL__NUMBERS 17 /* the names before "end" are numbers */

/* The fact named by name (n bytes) as text into buf (at least 32 bytes):
 * 0, or -1 for no such fact. */
static int hol__fact(const hol_lesson_facts *f, const char *name, size_t n, char *buf)
{
    static const char *const dirs[5] = {"under your feet", "north", "east", "south", "west"};
    int k = 0, nn = (int)(sizeof hol__names / sizeof hol__names[0]);
    while (k < nn && !(strlen(hol__names[k]) == n && !memcmp(hol__names[k], name, n)))
        k++;
    double v[HOL__NUMBERS] = {f->q,       f->corner_deg, f->square_deg, f->home,
                              f->flat_home, f->repeats,  4 * f->repeats, f->nroute};
    for (int d = 1; d <= 3; d++) {
        v[7 + d] = (double)f->count[d];
        v[10 + d] = (double)f->flat_count[d];
        v[13 + d] = (double)f->curved_count[d];
    }
    if (k < HOL__NUMBERS) /* a number: whole when it is, else one decimal */
        snprintf(buf, 32, fabs(v[k] - floor(v[k] + 0.5)) < 1e-9 ? "%.0f" : "%.1f", v[k]);
    else if (k == HOL__NUMBERS)
        hol_tile_print(f->end, buf);
    else if (k == HOL__NUMBERS + 4 && f->has_bearing)
        snprintf(buf, 32, "at %.0f degrees", f->bearing_deg);
    else if (k < nn)
        snprintf(buf, 32, "%s",
                 k == HOL__NUMBERS + 1   ? dirs[f->lesson == 3 ? f->answer : 0]
                 : k == HOL__NUMBERS + 2 ? (f->lesson == 1 && !f->answer ? "yes" : "no")
                 : k == HOL__NUMBERS + 3 ? (f->q == 4 ? "close" : "do not close")
                                         : "under you");
    return k < nn ? 0 : -1;
}

int hol_lesson_text(const hol_lesson_facts *f, int part, char *out, size_t cap)
{
    if (!f || f->lesson < 1 || f->lesson > HOL_LESSONS || part < 0 || part >= HOL_LESSON_PARTS ||
        !cap)
        return -1;
    const char *s = hol__lessons[f->lesson - 1][part];
    size_t len = 0;
    out[0] = 0;
    while (*s) {
        char fact[HOL_TILE_ADDR_MAX + 24];
        const char *piece = s, *close = *s == '{' ? strchr(s, '}') : NULL;
        size_t n = 1;
        /* "{4,5}" is no fact: only {name} of a fact is replaced */
        if (close && !hol__fact(f, s + 1, (size_t)(close - s - 1), fact)) {
            piece = fact;
            n = strlen(fact);
            s = close + 1;
        } else {
            s++;
        }
        if (len + n >= cap)
            return -1;
        memcpy(out + len, piece, n);
        len += n;
        out[len] = 0;
    }
    return (int)len;
}

const char *hol_lesson_label(const hol_lesson_facts *f, int k)
{
    if (!f || f->lesson < 1 || f->lesson > HOL_LESSONS || k < 0 || k >= HOL_APP_MAX_CHOICES)
        return NULL;
    return hol__lessons[f->lesson - 1][HOL_LESSON_PARTS + k];
}
