/* hol_lesson.c - the lessons' facts from the core and a lesson as a level
 * (see hol_lesson.h; the texts: hol_lesson_text.c). */
#include "hol_lesson.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hol_bearing.h"
#include "hol_room.h"
#include "hol_str.h"

/* The lessons' routes as room steps (lesson 2's and 6's made per tiling). */
static const char *const hol__routes[HOL_LESSONS] = {"NESW", "NWSE", "NWSE", "NESSWWNN",
                                                     "NESWSWNN", "NESW"};

/* Choices of the choice questions (lessons 1, 3); the number questions'
 * scales: lo, hi, step. */
static const int hol__scale[HOL_LESSONS][3] = {
    {0, 0, 0}, {3, 9, 1}, {0, 0, 0}, {4, 44, 4}, {0, 10, 1}, {1, 8, 1}};

static int hol__gcd(int a, int b)
{
    while (b) {
        int t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* The route of lesson n in {4,q}: lesson 2 goes round the tree once (q
 * steps of N, W, S, E, ...), lesson 6 walks the square until home. */
static int hol__route(int n, int q, uint8_t *out)
{
    const char *base = hol__routes[n - 1];
    size_t len = strlen(base);
    int steps = n == 2 ? q : n == 6 ? 4 * (q / hol__gcd(4, q)) : (int)len;
    for (int i = 0; i < steps; i++)
        out[i] = (uint8_t)hol_dir_from_char((unsigned char)base[(size_t)i % len]);
    return steps;
}

/* The route's end, its distances home and its bearing to O. */
static hol_err hol__walk_facts(hol_lesson_facts *f)
{
    hol_bearing_walk w;
    hol_room r;
    hol_err e = hol_bearing_begin(&w, hol_tile_origin_q(f->q));
    if (!e)
        e = hol_room_start_in(f->q, 3, 3, &r);
    int c0 = r.col, r0 = r.row;
    for (int i = 0; !e && i < f->nroute; i++) {
        e = hol_bearing_step(&w, f->route[i]);
        if (!e)
            e = hol_room_step(&r, f->route[i]);
    }
    hol_bearing b;
    if (!e)
        e = hol_bearing_end(&w, &b);
    if (e)
        return e;
    f->end = r.tile;
    f->home = hol_tile_dist0(r.tile);
    f->flat_home = abs(r.col - c0) + abs(r.row - r0);
    f->has_bearing = b.has_true;
    f->bearing_deg = b.has_true ? b.true_deg : 0;
    return HOL_OK;
}

hol_err hol_lesson_facts_of(int n, int q, hol_lesson_facts *out)
{
    if (!out || n < 1 || n > HOL_LESSONS || q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q)
        return HOL_EARG;
    hol_lesson_facts f;
    memset(&f, 0, sizeof f);
    f.lesson = n;
    f.q = q;
    f.nroute = hol__route(n, q, f.route);
    hol_err e = hol__walk_facts(&f);
    if (e)
        return e;
    f.corner_deg = 360.0 / q;
    f.square_deg = 4 * f.corner_deg;
    for (int d = 0; d < 4; d++) {
        f.count[d] = hol_tile_count_at(q, d);
        f.flat_count[d] = hol_tile_count_at(4, d);
        f.curved_count[d] = hol_tile_count_at(5, d);
    }
    f.repeats = q / hol__gcd(4, q);
    f.choice = n == 1 || n == 3;
    switch (n) {
    case 1: f.answer = hol_tile_eq(f.end, hol_tile_origin_q(q)) ? 0 : 1; break;
    case 2: f.answer = q; break;
    case 3: /* the nearest of N, E, S, W to the true bearing (a tie: the clockwise one) */
        f.answer = f.has_bearing ? 1 + (int)floor((f.bearing_deg + 45.0) / 90.0) % 4 : 0;
        break;
    case 4: f.answer = (int)f.count[3]; break;
    case 5: f.answer = f.home; break;
    default: f.answer = f.repeats; break;
    }
    *out = f;
    return HOL_OK;
}

void hol_lesson_scale(const hol_lesson_facts *f, int *lo, int *hi, int *step)
{
    int k = f && f->lesson >= 1 && f->lesson <= HOL_LESSONS ? f->lesson - 1 : 0;
    *lo = hol__scale[k][0];
    *hi = hol__scale[k][1];
    *step = hol__scale[k][2];
}

hol_err hol_lesson_question(const hol_lesson_facts *f, int lang, hol_app_question *qn)
{
    memset(qn, 0, sizeof *qn);
    snprintf(qn->id, sizeof qn->id, "lesson%d", f->lesson);
    if (hol_lesson_text(f, lang, HOL_LESSON_QUESTION, qn->text, sizeof qn->text) < 0)
        return HOL_ERANGE;
    if (f->choice) {
        qn->kind = HOL_APP_CHOICE;
        const char *c;
        while (qn->nchoices < HOL_APP_MAX_CHOICES && (c = hol_lesson_label(f, lang, qn->nchoices)))
            snprintf(qn->choices[qn->nchoices++], HOL_APP_LABEL_MAX, "%s", c);
        return HOL_OK;
    }
    qn->kind = HOL_APP_LIKERT;
    hol_lesson_scale(f, &qn->lo, &qn->hi, &qn->step);
    snprintf(qn->low, sizeof qn->low, "%s", hol_lesson_label(f, lang, 0));
    snprintf(qn->high, sizeof qn->high, "%s", hol_lesson_label(f, lang, 1));
    return HOL_OK;
}

hol_err hol_lesson_fill(int n, int q, hol_app_level *L)
{
    hol_lesson_facts f;
    hol_err e = L ? hol_lesson_facts_of(n, q, &f) : HOL_EARG;
    if (e)
        return e;
    if (hol_lesson_question(&f, HOL_LANG_EN, &L->questions[0]) ||
        hol_lesson_text(&f, HOL_LANG_EN, HOL_LESSON_WALK, L->instructions,
                        sizeof L->instructions) < 0 ||
        hol_lesson_text(&f, HOL_LANG_EN, HOL_LESSON_CHECK, L->closing, sizeof L->closing) < 0)
        return HOL_ERANGE;
    L->mode = HOL_APP_EXPLORE;
    L->lesson = n;
    memcpy(L->route, f.route, (size_t)f.nroute);
    L->nroute = f.nroute;
    L->nquestions = 1;
    L->nasks = 1;
    memset(&L->asks[0], 0, sizeof L->asks[0]);
    snprintf(L->asks[0].name, sizeof L->asks[0].name, "predict");
    L->asks[0].when = HOL_APP_BEFORE_LEVEL;
    L->asks[0].first = 0;
    L->asks[0].n = 1;
    L->point = n == 3 ? HOL_APP_POINT_START : HOL_APP_POINT_NONE;
    return HOL_OK;
}
