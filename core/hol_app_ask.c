/* hol_app_ask.c - questionnaires after a level's end screen (see hol_app.h:
 * HOL_APP_ASK, hol_app_level.asks; core/hol_ask.h): one screen an item,
 * left and right choose, confirm answers; then the closing screen or the
 * next level. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_ask.h"
#include "hol_str.h"

/* The marks of an item: likert (hi - lo) / step + 1, choice its count. */
static int hol__marks(const hol_app_question *q)
{
    if (q->kind == HOL_APP_CHOICE)
        return q->nchoices;
    int step = q->step > 0 ? q->step : 1;
    return (q->hi - q->lo) / step + 1;
}

static const hol_app_question *hol__ask_item(const hol_app *app)
{
    const hol_app_ask *a = &app->level.asks[app->ask_k];
    return &app->level.questions[a->first + app->ask_i];
}

static void hol__item_begin(hol_app *app, const hol_input *in)
{
    app->ask_mark = (hol__marks(hol__ask_item(app)) - 1) / 2; /* the middle */
    app->ask_t0 = in->time_s;
    app->ask_ref_yaw = app->mo.yaw_deg;
    app->place_panel = 1;
}

/* The first ask from k on with items and of the phase asked now (before
 * the level or after it); nasks when none. */
static int hol__next_ask(const hol_app *app, int k)
{
    const hol_app_level *L = &app->level;
    while (k < L->nasks && (L->asks[k].n == 0 || hol_ask_before(L->asks[k].when) != app->ask_before))
        k++;
    return k;
}

int hol__ask_before_start(hol_app *app)
{
    app->ask_before = 1;
    app->ask_k = hol__next_ask(app, 0);
    if (app->ask_k >= app->level.nasks) {
        app->ask_before = 0;
        return 0;
    }
    app->ask_i = 0;
    app->view.state = HOL_APP_ASK;
    app->ask_mark = (hol__marks(hol__ask_item(app)) - 1) / 2;
    app->ask_fresh = 1; /* its time and look at the next frame */
    app->place_panel = 1;
    return 1;
}

/* The `before` asks answered: the instructions, else the ready screen (a
 * resume's, hol_app_ready), else the level begins (pending_start: at the
 * next frame). */
static void hol__before_end(hol_app *app)
{
    app->ask_before = 0;
    if (app->level.instructions[0] || app->ready_after) {
        app->screen = app->level.instructions[0] ? HOL_APP_SCREEN_INSTRUCTIONS
                                                 : HOL_APP_SCREEN_READY;
        app->view.state = HOL_APP_SCREEN;
        app->place_panel = 1;
    } else {
        app->view.state = HOL_APP_PLAYING;
    }
}

/* After the level's end screen: its questionnaires, then the closing
 * screen (the last level), then the next level. */
void hol__after_end(hol_app *app, const hol_input *in, int from_ask)
{
    hol_app_view *v = &app->view;
    if (!from_ask && app->level.nasks > 0) {
        app->ask_i = 0;
        app->ask_before = 0;
        app->ask_k = hol__next_ask(app, 0);
        if (app->ask_k < app->level.nasks) {
            v->state = HOL_APP_ASK;
            hol__item_begin(app, in);
            return;
        }
    }
    if (app->level.last && app->level.closing[0]) {
        app->screen = HOL_APP_SCREEN_CLOSING;
        v->state = HOL_APP_SCREEN;
        app->place_panel = 1;
    } else {
        app->ev.next_level = 1;
        v->state = HOL_APP_DONE;
    }
}

hol_err hol__ask_begin_from(hol_app *app, int item)
{
    if (!app->have_level || item < 0)
        return HOL_EARG;
    int k = 0;
    while (k < app->level.nasks && item >= app->level.asks[k].n)
        item -= app->level.asks[k++].n;
    if (k >= app->level.nasks)
        return HOL_EARG;
    app->ask_k = k;
    app->ask_i = item;
    app->ask_before = 0; /* what is left of the level's asks, after it */
    app->pending_start = 0; /* the level is not played again */
    app->screen = HOL_APP_SCREEN_NONE;
    app->view.state = HOL_APP_ASK;
    app->ask_mark = (hol__marks(hol__ask_item(app)) - 1) / 2;
    app->ask_fresh = 1;
    app->place_panel = 1;
    return HOL_OK;
}

/* Left (-1) or right (+1) pressed in this record: an axis crossing 0.5
 * (the turn axis, positive left; the move axis, positive right), or a snap
 * turn (its new yaw to the left or the right of the look). */
static int hol__lr(hol_app *app, const hol_input *in)
{
    double x = (double)in->move[0] - (double)in->turn[0];
    int dir = x > 0.5 ? 1 : x < -0.5 ? -1 : 0;
    int edge = dir != app->ask_axis ? dir : 0;
    app->ask_axis = dir;
    if (in->flags & HOL_INPUT_SNAP_YAW) {
        double d = fmod(in->snap_yaw_deg - app->mo.yaw_deg + 540.0, 360.0) - 180.0;
        if (d > 1e-6 || d < -1e-6)
            edge = d > 0 ? -1 : 1; /* yaw grows to the left */
    }
    return edge;
}

/* A headset's controller chooses by pointing: 60 degrees across the scale,
 * centred on the look when the item came up. */
static int hol__ray_mark(const hol_app *app, const hol_input *in, int marks)
{
    double yaw = hol__pointed_yaw(app, in);
    double right = fmod(app->ask_ref_yaw - yaw + 540.0, 360.0) - 180.0; /* degrees right */
    double u = (right + 30.0) / 60.0;
    int m = (int)floor(u * marks);
    return m < 0 ? 0 : m >= marks ? marks - 1 : m;
}

void hol__ask_frame(hol_app *app, const hol_input *in, uint32_t pressed)
{
    hol_app_view *v = &app->view;
    if (app->ask_fresh) { /* hol_app_ask_from's item comes up now */
        app->ask_fresh = 0;
        if (in->flags & HOL_INPUT_HEAD_VALID)
            hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
        hol__item_begin(app, in);
    }
    const hol_app_question *q = hol__ask_item(app);
    int marks = hol__marks(q);
    int ray = (in->flags & HOL_INPUT_HEAD_VALID) &&
              (in->flags & (HOL_INPUT_HAND_R_VALID | HOL_INPUT_HAND_L_VALID));
    if (in->flags & HOL_INPUT_HEAD_VALID)
        hol__yaw_pitch_from_quat(in->head.quat, &app->mo.yaw_deg, &app->mo.pitch_deg);
    if (ray) {
        app->ask_mark = hol__ray_mark(app, in, marks);
    } else {
        int lr = hol__lr(app, in);
        app->ask_mark += lr;
        app->ask_mark = app->ask_mark < 0 ? 0 : app->ask_mark >= marks ? marks - 1 : app->ask_mark;
    }
    if (!(pressed & HOL_BTN_CONFIRM) || v->paused)
        return;
    const hol_app_ask *a = &app->level.asks[app->ask_k];
    hol_app_answer *r = &app->ev.answer;
    memset(r, 0, sizeof *r);
    snprintf(r->questionnaire, sizeof r->questionnaire, "%s", a->name);
    r->when = a->when;
    snprintf(r->item, sizeof r->item, "%s", q->id);
    r->kind = q->kind;
    if (q->kind == HOL_APP_CHOICE)
        snprintf(r->choice, sizeof r->choice, "%s", q->choices[app->ask_mark]);
    else
        r->value = q->lo + app->ask_mark * (q->step > 0 ? q->step : 1);
    r->time_s = in->time_s - app->ask_t0;
    r->shown_s = app->ask_t0;
    r->at_s = in->time_s;
    app->ev.answered = 1;
    if (++app->ask_i >= a->n) {
        app->ask_i = 0;
        app->ask_k = hol__next_ask(app, app->ask_k + 1);
        if (app->ask_k >= app->level.nasks && app->ask_before) {
            hol__before_end(app);
            return;
        }
        if (app->ask_k >= app->level.nasks) {
            hol__after_end(app, in, 1);
            return;
        }
    }
    hol__item_begin(app, in);
}

/* The item's screen: its text wrapped (at most 3 lines), the value
 * between arrows with the questionnaire's place, the anchors (a likert's
 * ends, on one line or two): never more than the HUD's 6 lines, none cut. */
void hol__ask_lines(const hol_app *app, hol_app_hud *h)
{
    hol_app_question said; /* the item in the view's language */
    const hol_app_ask *a = &app->level.asks[app->ask_k];
    const char *name;
    const hol_app_question *q = hol__item_said(app, a, hol__ask_item(app), &said, &name);
    int marks = hol__marks(q), m = app->ask_mark, step = q->step > 0 ? q->step : 1;
    h->nlines = 0;
    char wrapped[3][HOL_APP_TEXT_MAX];
    int n = hol_app_wrap(q->text, HOL_APP_SCREEN_COLS, wrapped, 3);
    for (int i = 0; i < n && i < 3; i++)
        memcpy(h->lines[h->nlines++], wrapped[i], HOL_APP_TEXT_MAX);
    char val[HOL_APP_LABEL_MAX];
    if (q->kind == HOL_APP_CHOICE)
        snprintf(val, sizeof val, "%s", q->choices[m]);
    else
        snprintf(val, sizeof val, "%d", q->lo + m * step);
    hol__utf8_cut(val, 20);
    char line[128]; /* at most 45 characters: a value of 20, a name of 12 */
    snprintf(line, sizeof line, "%s %s %s   %.12s %d/%d", m > 0 ? "<" : " ", val,
             m < marks - 1 ? ">" : " ", name, app->ask_i + 1, a->n);
    hol__utf8_cut(line, HOL_APP_TEXT_MAX - 1);
    memcpy(h->lines[h->nlines++], line, strlen(line) + 1);
    if (q->kind == HOL_APP_LIKERT) {
        char both[2 * HOL_APP_TEXT_MAX];
        int len = snprintf(both, sizeof both, "%d %s, %d %s", q->lo, q->low, q->hi, q->high);
        if (len < HOL_APP_TEXT_MAX) {
            memcpy(h->lines[h->nlines++], both, (size_t)len + 1);
        } else {
            snprintf(both, sizeof both, "%d %s", q->lo, q->low);
            snprintf(h->lines[h->nlines++], HOL_APP_TEXT_MAX, "%.47s", both);
            snprintf(both, sizeof both, "%d %s", q->hi, q->high);
            snprintf(h->lines[h->nlines++], HOL_APP_TEXT_MAX, "%.47s", both);
        }
    }
    h->ask_item = app->ask_i;
    h->ask_items = a->n;
    h->ask_before = app->ask_before;
    h->ask_value = q->kind == HOL_APP_CHOICE ? m : q->lo + m * step;
}
