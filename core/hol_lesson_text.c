/* hol_lesson_text.c - every text a lesson shows, as one table (see
 * hol_lesson.h), and its expansion with the lesson's facts. The languages
 * work (issue 37) moves this table into the string table.
 *
 * A text names facts as {name}; every number comes from the core
 * (hol_lesson_facts), none is typed here:
 *   {q} squares at a corner; {deg} a corner's degrees; {sum} a square's
 *   four; {end} the route's last
 *   tile; {home} its fewest steps home; {flat} the flat grid's steps home;
 *   {steps} the route's steps; {bearing} the true bearing to the start;
 *   {dir} the right choice of lesson 3; {yesno} lesson 1's; {c1} {c2} {c3}
 *   tiles at 1, 2, 3 steps here, {f1}.. in {4,4}, {h1}.. in {4,5};
 *   {times} the squares walked until home, {walked} their steps. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_lesson.h"

typedef struct hol__lesson_row {
    const char *part[HOL_LESSON_PARTS];
    const char *flat_check; /* the check in {4,4}, NULL: the same */
    const char *labels[HOL_APP_MAX_CHOICES]; /* choices, or the scale's two anchors */
} hol__lesson_row;

static const hol__lesson_row hol__lessons[HOL_LESSONS] = {
    {{"One step, one tile",
      "A square walk N, E, S, W closes on flat paper; in the hyperbolic plane it does not.",
      "You walk N, E, S, W, one tile a step. Are you back on your start tile?",
      "Lesson 1: walk N, E, S, W. A marker shows each next tile: step onto it. Watch where you "
      "end.",
      "Answer: {yesno}. N, E, S, W ended on tile {end}, {home} step(s) from the start tile O. "
      "{q} squares meet at each corner here, so four right turns do not close a square.",
      "Count the squares that meet at one corner of your cell."},
     "Answer: {yesno}. In the flat grid four squares meet at each corner, so N, E, S, W closes "
     "a square: you are on O again. In {4,5} it does not close.",
     {"Yes", "No"}},
    {{"Corners",
      "{q} squares meet at every corner, so a corner is {deg} degrees and a square's angles sum "
      "to {sum}, not 360.",
      "How many squares meet at one corner (round one tree)?",
      "Lesson 2: walk round the tree at the north-west corner of your cell, following the "
      "markers, until you stand on your start tile again. Count the tiles.",
      "Answer: {q}. {q} squares meet at every corner, so a square's corner is 360/{q} = {deg} "
      "degrees and its four corners add up to {sum} degrees (360 on flat paper).",
      "The walk ends on the tile where it began: count the steps."},
     NULL,
     {"fewer", "more"}},
    {{"Holonomy",
      "A walk round one tree brings you back to your cell, but onto another tile "
      "(holonomy): the start is not where a flat map puts it.",
      "You walk N, W, S, E round a tree, back to your cell. Where is the start tile then?",
      "Lesson 3: walk N, W, S, E round the tree, following the markers, back to your own "
      "cell. Then point to the start tile.",
      "Answer: {dir}. You are back in your cell but on tile {end}, not O: {q} squares stand "
      "round the tree and you passed four. The start lies at {bearing} degrees; a flat map "
      "says you are home.",
      "A tree has {q} squares round it, and you walked past four."},
     "Answer: {dir}. In the flat grid a walk round a tree brings you back to the very tile you "
     "left: no holonomy. In {4,5} you land on another tile.",
     {"Under my feet", "North", "East", "South", "West"}},
    {{"Growth",
      "Tiles at 1, 2, 3 steps: {c1}, {c2}, {c3} here, against {f1}, {f2}, {f3} in the flat "
      "grid: the plane grows faster than any flat map.",
      "How many tiles lie exactly 3 steps from the start tile?",
      "Lesson 4: walk the ring of cells round your start: N, E, S, S, W, W, N, N, following "
      "the markers. Watch how far from the start each tile is.",
      "Answer: {c3}. At 1, 2 and 3 steps from the start lie {c1}, {c2} and {c3} tiles; in the "
      "flat grid only {f1}, {f2} and {f3}. The ring you walked ended on {end}, {home} steps "
      "out.",
      "In the flat grid there are {f3}. Here each tile has more neighbours farther out."},
     "Answer: {c3}. At 1, 2 and 3 steps lie {c1}, {c2} and {c3} tiles: four more each step. In "
     "{4,5} it is {h1}, {h2} and {h3}.",
     {"fewer", "more"}},
    {{"No way back",
      "The fewest steps home after a walk are not what a flat map says: {home}, not {flat}.",
      "After N, E, S, W, S, W, N, N, how few steps take you back to the start tile?",
      "Lesson 5: walk N, E, S, W, S, W, N, N, following the markers: a figure eight round two "
      "trees. Then think how you would walk home.",
      "Answer: {home}. You walked {steps} steps and stand {flat} cells from your start cell, "
      "yet the fewest steps home are {home} (tile {end}): a flat map's {flat} is wrong here.",
      "Count the tiles between your end and the start on the picture, not the cells."},
     "Answer: {home}. In the flat grid the way home is what the map says: {home} steps, the "
     "cells between you and the start.",
     {"fewer", "more"}},
    {{"Puzzle: the square walk",
      "A square walk goes round one tree; {q} squares stand round it, so you are home after "
      "{times} squares.",
      "How many times must you walk N, E, S, W to stand on your start tile again?",
      "Lesson 6: walk N, E, S, W again and again, following the markers, until they bring you "
      "home. Count the squares. Hint: every step goes round the same tree.",
      "Answer: {times}. Each step of N, E, S, W goes round the same tree, and {q} squares "
      "stand round it: after {times} square(s), {walked} steps, you are on O again.",
      "Every step of the square goes round the same tree."},
     NULL,
     {"fewer", "more"}},
};

/* A number of degrees: whole when it is, else one decimal. */
static void hol__deg(double d, char *buf, size_t cap)
{
    if (fabs(d - floor(d + 0.5)) < 1e-9)
        snprintf(buf, cap, "%.0f", d);
    else
        snprintf(buf, cap, "%.1f", d);
}

/* The fact named by name (n bytes) as text into buf: 0, or -1 for no
 * such fact. */
static int hol__fact(const hol_lesson_facts *f, const char *name, size_t n, char *buf,
                     size_t cap)
{
    static const char *const counts[3] = {"c", "f", "h"};
    static const char *const dirs[5] = {"under your feet", "north", "east", "south", "west"};
#define HOL__IS(s) (n == strlen(s) && !memcmp(name, s, n))
    if (HOL__IS("q"))
        snprintf(buf, cap, "%d", f->q);
    else if (HOL__IS("deg"))
        hol__deg(f->corner_deg, buf, cap);
    else if (HOL__IS("sum"))
        hol__deg(f->square_deg, buf, cap);
    else if (HOL__IS("end"))
        hol_tile_print(f->end, buf);
    else if (HOL__IS("home"))
        snprintf(buf, cap, "%d", f->home);
    else if (HOL__IS("flat"))
        snprintf(buf, cap, "%d", f->flat_home);
    else if (HOL__IS("steps"))
        snprintf(buf, cap, "%d", f->nroute);
    else if (HOL__IS("bearing"))
        snprintf(buf, cap, "%.0f", f->has_bearing ? f->bearing_deg : 0.0);
    else if (HOL__IS("dir"))
        snprintf(buf, cap, "%s", dirs[f->lesson == 3 ? f->answer : 0]);
    else if (HOL__IS("yesno"))
        snprintf(buf, cap, "%s", f->lesson == 1 && !f->answer ? "yes" : "no");
    else if (HOL__IS("times"))
        snprintf(buf, cap, "%d", f->repeats);
    else if (HOL__IS("walked"))
        snprintf(buf, cap, "%d", 4 * f->repeats);
    else if (n == 2 && name[1] >= '1' && name[1] <= '3') {
        int d = name[1] - '0', k = 0;
        while (k < 3 && name[0] != counts[k][0])
            k++;
        if (k == 3)
            return -1;
        const uint64_t *c = k == 0 ? f->count : k == 1 ? f->flat_count : f->curved_count;
        snprintf(buf, cap, "%llu", (unsigned long long)c[d]);
    } else
        return -1;
#undef HOL__IS
    return 0;
}

int hol_lesson_text(const hol_lesson_facts *f, int part, char *out, size_t cap)
{
    if (!f || f->lesson < 1 || f->lesson > HOL_LESSONS || part < 0 || part >= HOL_LESSON_PARTS ||
        !cap)
        return -1;
    const hol__lesson_row *row = &hol__lessons[f->lesson - 1];
    const char *s = part == HOL_LESSON_CHECK && f->q == 4 && row->flat_check ? row->flat_check
                                                                             : row->part[part];
    size_t len = 0;
    out[0] = 0;
    while (*s) {
        char fact[HOL_TILE_ADDR_MAX + 24];
        const char *piece = s, *close = *s == '{' ? strchr(s, '}') : NULL;
        size_t n = 1;
        /* "{4,5}" is no fact: only {name} of a fact is replaced */
        if (close && !hol__fact(f, s + 1, (size_t)(close - s - 1), fact, sizeof fact)) {
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
    return hol__lessons[f->lesson - 1].labels[k];
}
