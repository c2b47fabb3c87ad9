/* hol_session_log.c - the session's outputs: the rows of summary, steps
 * and head, and attempts begun and ended, written through the buffered
 * streams of hol_session_out.c (see hol_session.h for the files and their
 * order). */
#include "hol_session_impl.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hol_ask.h"
#include "hol_bearing.h"
#include "hol_sha256.h"
#include "hol_text.h"

static const char *const hol__mode_names[4] = {"explore", "flag", "keys", "tutorial"};

/* A level's name as a CSV field: escaped (no control byte reaches a
 * terminal that shows the file), then quoted per RFC 4180. */
#define HOL__CSV_NAME (8 * HOL_LEVEL_NAME_MAX + 3)
static void hol__csv_name(const char *name, char out[HOL__CSV_NAME])
{
    char esc[4 * HOL_LEVEL_NAME_MAX + 1];
    hol_text_escape(name, strlen(name), esc, sizeof esc);
    hol_text_csv(esc, strlen(esc), out, HOL__CSV_NAME);
}

unsigned hol_session_cues_visible(const hol_app_view *v)
{
    unsigned c = v->map.cues, vis = 0;
    int map = v->map.place != HOL_MINIMAP_OFF, objs = v->map.nobjectives > 0;
    if (map && objs && (c & HOL_CUE_HOT_COLD))
        vis |= HOL_CUE_HOT_COLD;
    if (map && v->map.npath > 0 && (c & HOL_CUE_PATH))
        vis |= HOL_CUE_PATH;
    if (objs && (c & HOL_CUE_POLES))
        vis |= HOL_CUE_POLES;
    for (int i = 0; map && (c & HOL_CUE_ARROW) && i < v->map.nobjectives; i++)
        if (hol_tile_dist(v->user.tile, v->map.objectives[i]) > HOL_APP_MINIMAP_RADIUS)
            vis |= HOL_CUE_ARROW;
    if (objs && (c & HOL_CUE_LANTERN) && v->lighting != HOL_LIGHT_DAY)
        vis |= HOL_CUE_LANTERN;
    if (objs && (c & HOL_CUE_SOUND) && v->sound != HOL_SOUND_OFF)
        vis |= HOL_CUE_SOUND;
    return vis;
}

/* A whole small stream, durably: open, write, flush, close. */
static void hol__put_file(hol_session *s, const char *name, int append, const char *data,
                          size_t n)
{
    hol__out o;
    hol__out_init(&o, s->log, NULL, 0);
    if (hol__out_open(s, &o, name, append))
        return;
    hol__out_put(s, &o, data, n);
    hol__out_flush(s, &o, 1);
    hol__out_close(s, &o);
}

static void hol__rename(hol_session *s, const char *from, const char *to)
{
    if (s->failed)
        return;
    hol_err e = s->log->rename(s->log->user, from, to);
    if (e)
        hol__fail_sink(s, s->log, e, "rename", from);
}

/* Each level's text as level-HASH.txt (see hol_session.h). */
void hol__log_levels(hol_session *s)
{
    for (int i = 0; i < s->nlevels && !s->failed; i++) {
        char hex[HOL_SHA256_HEX], name[96], live[104];
        hol_sha256_hex(s->levels[i].sha256, hex);
        snprintf(name, sizeof name, "level-%s.txt", hex);
        snprintf(live, sizeof live, "%s.live", name);
        int seen = 0;
        for (int j = 0; j < i; j++)
            seen |= !memcmp(s->levels[j].sha256, s->levels[i].sha256, 32);
        if (seen)
            continue;
        char text[HOL_LEVEL_TEXT_MAX + 2];
        hol__put_file(s, live, 0, text, hol_level_hashed_text(&s->levels[i], text));
        hol__rename(s, live, name);
    }
}

/* The study's text as study-HASH.txt, as a level's (see hol_session.h). */
void hol__log_study(hol_session *s, const char *text, size_t len)
{
    char name[96], live[104];
    snprintf(name, sizeof name, "study-%s.txt", s->meta.study_sha256);
    snprintf(live, sizeof live, "%s.live", name);
    hol__put_file(s, live, 0, text, len);
    hol__rename(s, live, name);
}

/* ---- rows ------------------------------------------------------------------- */

size_t hol__summary_row(const hol_session *s, const hol_app_summary *sum, int end, char *out,
                        size_t cap)
{
    const hol_level *L = &s->levels[s->cur];
    char name[HOL__CSV_NAME], hash[HOL_SHA256_HEX];
    hol__csv_name(L->name, name);
    hol_sha256_hex(L->sha256, hash);
    int mode = sum->mode >= 0 && sum->mode < 4 ? sum->mode : 0;
    char pos[16] = "";
    if (L->condition[0])
        snprintf(pos, sizeof pos, "%d", L->position);
    const hol_app_level *G = &L->lvl;
    char cell[16];
    hol_level_format_cell(G->cell_m, cell);
    /* the geometry (tiling "4,Q" quoted: it holds a comma) before the
     * started..end fields, which recovery reads from the row's end */
    int n = snprintf(out, cap,
                     "%s,%s,%s,%s,%d,%s,%s,%s,%s,%s,%s,%llu,%u,\"4,%d\",%dx%d,%s,%.4f,%d,%d,%.4f,%s\n",
                     s->meta.session, s->meta.participant, s->meta.start, s->meta.version,
                     s->attempt, L->condition[0] ? s->meta.study : "", L->condition, pos, name,
                     hash, hol__mode_names[mode], (unsigned long long)sum->seed, L->lvl.cues,
                     G->tiling_q ? G->tiling_q : 5, G->room_cols ? G->room_cols : 3,
                     G->room_rows ? G->room_rows : 3, cell, s->attempt_started, sum->steps,
                     sum->optimum, sum->time_s, hol__end_names[end]);
    if (n <= 0 || (size_t)n >= cap)
        return 0;
    if (s->old_cols || !s->tail)
        return (size_t)n;
    /* the tail before the row's LF */
    if ((size_t)n + s->tail_len >= cap)
        return 0;
    memcpy(out + n - 1, s->tail, s->tail_len);
    out[n - 1 + s->tail_len] = '\n';
    out[n + s->tail_len] = 0;
    return (size_t)n + s->tail_len;
}

void hol__summary_tail(const hol_rec_meta *m, char *out, size_t cap, size_t *out_len)
{
    char num[16] = "";
    if (m->session_no > 0)
        snprintf(num, sizeof num, "%d", m->session_no);
    int n = snprintf(out, cap, ",%s,%s,", num, m->study_sha256);
    size_t at = n > 0 && (size_t)n < cap ? (size_t)n : 0;
    /* meta is escaped already (hol_rec_meta_ok): only quoted here */
    size_t need = hol_text_csv(m->meta, strlen(m->meta), out + at, cap - at);
    *out_len = at + need < cap ? at + need : 0;
    if (!*out_len && cap)
        out[0] = 0;
}

static void hol__step_rows(hol_session *s, const hol_app_events *ev, const hol_app_view *v)
{
    char name[HOL__CSV_NAME], addr[HOL_TILE_ADDR_MAX];
    hol__csv_name(s->levels[s->cur].name, name);
    unsigned vis = hol_session_cues_visible(v);
    for (int i = 0; i < ev->nsteps; i++) {
        const hol_app_step_event *e = &ev->steps[i];
        hol_tile_print(e->room.tile, addr);
        hol__out_printf(s, &s->steps, "%s,%d,%s,%.4f,%d,%d,%d,%c,%.2f,%s,%d,%d,%u,%u\n",
                        s->meta.session, s->attempt, name, e->t, e->index, e->room.col,
                        e->room.row, hol_dir_to_char(e->dir), e->yaw_deg, addr,
                        e->room.orient, e->remaining, e->cues, vis);
    }
}

/* The index of the last 10 Hz sample at or before level time t (a whole
 * number as a double: exact below 2^53, and no cast that can overflow). */
static double hol__last_sample(double t)
{
    double k = floor(t * 10);
    if ((k + 1) / 10.0 <= t)
        k += 1;
    else if (k / 10.0 > t)
        k -= 1;
    return k;
}

/* Head rows at every 0.1 s of level time up to this frame's, between the
 * previous frame of the attempt and this one; over a gap (frames more than
 * HOL_SESSION_GAP_S apart, or more than HOL_SESSION_GAP_ROWS samples due)
 * one gap row instead: t the first sample it stands for, frame_t this
 * frame's time, the pose and cell empty, tile "gap". So a frame writes at
 * most HOL_SESSION_GAP_ROWS rows, whatever its time. */
static void hol__head_rows(hol_session *s, const hol_app_view *v)
{
    hol__head_frame cur = {1, v->hud.elapsed_s, {v->head[0], v->head[1], v->head[2]},
                      v->yaw_deg, v->pitch_deg, v->user};
    const hol__head_frame prev = s->prev.valid ? s->prev : cur, *p = &prev;
    char name[HOL__CSV_NAME], addr[HOL_TILE_ADDR_MAX];
    hol__csv_name(s->levels[s->cur].name, name);
    s->prev = cur;
    double last = hol__last_sample(cur.t), due = last - s->next_sample + 1;
    if (due < 1)
        return;
    if (cur.t - p->t > HOL_SESSION_GAP_S || due > HOL_SESSION_GAP_ROWS) {
        hol__out_printf(s, &s->head, "%s,%d,%s,%.1f,%.4f,,,,,,,,gap\n", s->meta.session,
                        s->attempt, name, s->next_sample / 10.0, cur.t);
        s->next_sample = last + 1;
        return;
    }
    for (int i = 0; i < (int)due; i++, s->next_sample++) {
        double t = s->next_sample / 10.0, span = cur.t - p->t;
        double a = span > 0 ? (t - p->t) / span : 1;
        a = a < 0 ? 0 : a > 1 ? 1 : a;
        double pos[3], dyaw = fmod(cur.yaw - p->yaw + 540.0, 360.0) - 180.0;
        for (int k = 0; k < 3; k++)
            pos[k] = a == 1 ? cur.pos[k] : p->pos[k] + a * (cur.pos[k] - p->pos[k]);
        double yaw = a == 1 ? cur.yaw : fmod(p->yaw + a * dyaw + 360.0, 360.0);
        double pitch = a == 1 ? cur.pitch : p->pitch + a * (cur.pitch - p->pitch);
        const hol_room *room = a >= 0.5 ? &cur.room : &p->room;
        hol_tile_print(room->tile, addr);
        hol__out_printf(s, &s->head, "%s,%d,%s,%.1f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f,%d,%d,%s\n",
                        s->meta.session, s->attempt, name, t, cur.t, pos[0], pos[1], pos[2],
                        yaw, pitch, room->col, room->row, addr);
    }
}

/* ---- attempts ---------------------------------------------------------------- */

static void hol__attempt_begin(hol_session *s, const hol_app_view *v)
{
    s->ask_pending = 0;
    s->attempt++;
    s->attempt_open = 1;
    s->attempt_started = s->now;
    s->next_sample = 0;
    s->prev.valid = 0;
    s->track_next = 0;
    s->track_prev.valid = 0;
    const hol_app_level *L = &s->levels[s->cur].lvl;
    hol_app_summary sum = {L->mode, L->seed, 0, v->hud.optimum, 0, HOL_APP_END_NONE};
    char name[64], live[80];
    size_t n = hol__summary_row(s, &sum, HOL__END_KILLED, s->row, HOL__ROW_MAX);
    hol__attempt_name(name, sizeof name, "attempt", s->attempt);
    hol__put_file(s, name, 0, s->row, n);
    hol__attempt_name(name, sizeof name, "steps", s->attempt);
    snprintf(live, sizeof live, "%s.live", name);
    if (!hol__out_open(s, &s->steps, live, 0))
        hol__out_put(s, &s->steps, HOL_SESSION_STEP_COLUMNS "\n",
                     sizeof HOL_SESSION_STEP_COLUMNS);
    hol__attempt_name(name, sizeof name, "head", s->attempt);
    snprintf(live, sizeof live, "%s.live", name);
    if (!hol__out_open(s, &s->head, live, 0))
        hol__out_put(s, &s->head, HOL_SESSION_HEAD_COLUMNS "\n",
                     sizeof HOL_SESSION_HEAD_COLUMNS);
    hol__attempt_name(name, sizeof name, "track", s->attempt);
    snprintf(live, sizeof live, "%s.live", name);
    if (!hol__out_open(s, &s->track, live, 0))
        hol__out_put(s, &s->track, HOL_SESSION_TRACK_COLUMNS "\n",
                     sizeof HOL_SESSION_TRACK_COLUMNS);
}

void hol__attempt_end(hol_session *s, const hol_app_summary *sum, int end)
{
    if (!s->attempt_open)
        return;
    s->attempt_open = 0;
    /* the rows, durably; the summary row (the commit); the names */
    hol__out_flush(s, &s->steps, 1);
    hol__out_close(s, &s->steps);
    hol__out_flush(s, &s->head, 1);
    hol__out_close(s, &s->head);
    hol__out_flush(s, &s->track, 1);
    hol__out_close(s, &s->track);
    char name[64], live[80];
    size_t n = hol__summary_row(s, sum, end, s->row, HOL__ROW_MAX);
    hol__put_file(s, "summary.csv", 1, s->row, n);
    /* steps last: a steps-NNN.csv always has its head file and row */
    static const char *const what[3] = {"head", "track", "steps"};
    for (int k = 0; k < 3; k++) {
        hol__attempt_name(name, sizeof name, what[k], s->attempt);
        snprintf(live, sizeof live, "%s.live", name);
        hol__rename(s, live, name);
    }
    hol__attempt_name(name, sizeof name, "attempt", s->attempt);
    if (!s->failed && s->log->remove(s->log->user, name))
        hol__fail_sink(s, s->log, HOL_EIO, "remove", name);
}

/* A row of events.csv (see hol_session.h), with the header when the file
 * is new. */
static void hol__event_row(hol_session *s, const char *event, const char *value, double t)
{
    if (s->failed)
        return;
    if (!s->events_known) {
        char c;
        size_t got = 0;
        hol_err e = s->log->read(s->log->user, "events.csv", 0, &c, 1, &got);
        if (e == HOL_EOPEN || (!e && got == 0))
            hol__put_file(s, "events.csv", 1, HOL_SESSION_EVENT_COLUMNS "\n",
                          sizeof HOL_SESSION_EVENT_COLUMNS);
        else if (e)
            hol__fail_sink(s, s->log, e, "read", "events.csv");
        s->events_known = 1;
    }
    char name[HOL__CSV_NAME], row[HOL__CSV_NAME + 256];
    hol__csv_name(s->levels[s->cur].name, name);
    int n = snprintf(row, sizeof row, "%s,%d,%s,%.4f,%s,%s\n", s->meta.session, s->attempt,
                     name, t, event, value);
    if (n > 0 && (size_t)n < sizeof row)
        hol__put_file(s, "events.csv", 1, row, (size_t)n);
}

static void hol__events(hol_session *s, const hol_app_events *ev, const hol_app_view *v)
{
    static const char *const places[3] = {"hud", "hand", "off"};
    const char *place = places[v->map.place >= 0 && v->map.place < 3 ? v->map.place : 0];
    if (ev->minimap_moved)
        hol__event_row(s, "minimap", place, v->hud.elapsed_s);
    if (ev->minimap_refused)
        hol__event_row(s, "minimap-fixed", place, v->hud.elapsed_s);
    if (ev->hint)
        hol__event_row(s, "hint", "lesson6", v->hud.elapsed_s);
    if (ev->relocated) {
        char m[32];
        snprintf(m, sizeof m, "%.3f", ev->relocated_m);
        hol__event_row(s, "relocated", m, v->hud.elapsed_s);
    }
    if (ev->outside || ev->inside) {
        char m[32];
        snprintf(m, sizeof m, "%.3f", ev->outside ? ev->outside_m : ev->inside_s);
        hol__event_row(s, ev->outside ? "outside" : "inside", m, v->hud.elapsed_s);
    }
}

/* Creates name with its header when the file is new or empty (*known
 * keeps that it is done); *known is 2 when the file's first line is old,
 * the header of the build before its timestamps (its rows then keep
 * those columns). Returns 1 when the session writes nothing more. */
static int hol__header_once(hol_session *s, int *known, const char *name, const char *header,
                            const char *old)
{
    if (*known || s->failed)
        return s->failed != 0;
    char c[HOL__CSV_NAME];
    size_t got = 0, n = strlen(old);
    hol_err e = s->log->read(s->log->user, name, 0, c, n + 1 < sizeof c ? n + 1 : sizeof c, &got);
    *known = 1;
    if (e == HOL_EOPEN || (!e && got == 0))
        hol__put_file(s, name, 1, header, strlen(header));
    else if (e)
        hol__fail_sink(s, s->log, e, "read", name);
    else if (got == n + 1 && !memcmp(c, old, n) && (c[n] == '\n' || c[n] == '\r'))
        *known = 2;
    return s->failed != 0;
}

/* The timestamps' fields (",SHOWN,ANSWERED": input times in whole
 * milliseconds) into ts, or "" when the file has the old header (known 2). */
static void hol__stamps(char ts[48], int known, double shown_s, double at_s)
{
    ts[0] = 0;
    if (known != 2)
        snprintf(ts, 48, ",%lld,%lld", (long long)floor(shown_s * 1000.0 + 0.5),
                 (long long)floor(at_s * 1000.0 + 0.5));
}

/* An angle with one decimal, never "-0.0"; "" when absent. */
static void hol__deg(char out[16], int has, double d)
{
    out[0] = 0;
    if (has)
        snprintf(out, 16, "%.1f", fabs(d) < 0.05 ? 0.0 : d);
}

/* A row of points.csv (see hol_session.h). */
static void hol__point_row(hol_session *s, const hol_app_point *p)
{
    if (hol__header_once(s, &s->points_known, "points.csv", HOL_SESSION_POINT_COLUMNS "\n",
                         HOL_SESSION_POINT_COLUMNS_OLD))
        return;
    char name[HOL__CSV_NAME], row[HOL__CSV_NAME + 512];
    char pointed[HOL_BEARING_TEXT], tru[HOL_BEARING_TEXT] = "", flat[HOL_BEARING_TEXT] = "";
    char et[16], ef[16];
    hol__csv_name(s->levels[s->cur].name, name);
    hol_bearing_format(p->pointed_deg, pointed);
    if (p->has_true)
        hol_bearing_format(p->true_deg, tru);
    if (p->has_flat)
        hol_bearing_format(p->flat_deg, flat);
    hol__deg(et, p->has_true, p->error_true);
    hol__deg(ef, p->has_flat, p->error_flat);
    char ts[48];
    hol__stamps(ts, s->points_known, p->asked_s, p->at_s);
    int n = snprintf(row, sizeof row, "%s,%s,%d,%s,%.4f,%s,%s,%s,%s,%s,%s,%.4f%s\n",
                     s->meta.session, s->meta.participant, s->attempt, name, p->t,
                     p->target == HOL_APP_POINT_START ? "start" : "objective", pointed, tru,
                     flat, et, ef, p->time_s, ts);
    if (n > 0 && (size_t)n < sizeof row)
        hol__put_file(s, "points.csv", 1, row, (size_t)n);
}

/* The rows of tutorial.csv (see hol_session.h) of a step's lessons done. */
static void hol__lesson_rows(hol_session *s, const hol_app_events *ev)
{
    for (int i = 0; i < ev->nlessons && !s->failed; i++) {
        hol__header_once(s, &s->lessons_known, "tutorial.csv", HOL_SESSION_LESSON_COLUMNS "\n",
                         HOL_SESSION_LESSON_COLUMNS); /* no older header */
        const hol_app_lesson *l = &ev->lessons[i];
        char name[HOL__CSV_NAME], row[HOL__CSV_NAME + 256];
        hol__csv_name(s->levels[s->cur].name, name);
        int n = snprintf(row, sizeof row, "%s,%s,%d,%s,%d,%.4f,%d,%d,%.4f\n", s->meta.session,
                         s->meta.participant, s->attempt, name, l->lesson, l->started, l->steps,
                         l->optimum, l->t - l->started);
        if (!s->failed && n > 0 && (size_t)n < sizeof row)
            hol__put_file(s, "tutorial.csv", 1, row, (size_t)n);
    }
}

/* A row of answers.csv (see hol_session.h). */
static void hol__answer_row(hol_session *s, const hol_app_answer *a)
{
    if (hol__header_once(s, &s->answers_known, "answers.csv", HOL_SESSION_ANSWER_COLUMNS "\n",
                         HOL_SESSION_ANSWER_COLUMNS_OLD))
        return;
    char value[HOL__CSV_NAME], row[HOL__CSV_NAME + 512];
    if (a->kind == HOL_APP_CHOICE)
        hol__csv_name(a->choice, value);
    else
        snprintf(value, sizeof value, "%d", a->value);
    /* a resumed level's answers go with the attempt that played it; a
     * `before` one's with the attempt its level begins next */
    int attempt = s->ask_pending ? s->meta.ask_attempt : s->attempt;
    if (!s->ask_pending && hol_ask_before(a->when))
        attempt = s->attempt + 1;
    char ts[48];
    hol__stamps(ts, s->answers_known, a->shown_s, a->at_s);
    int n = snprintf(row, sizeof row, "%s,%s,%d,%s,%s,%s,%s,%s,%.4f%s\n",
                     s->ask_pending ? s->meta.ask_session : s->meta.session,
                     s->meta.participant, attempt, a->questionnaire,
                     hol_ask_when_name(a->when), a->item,
                     a->kind == HOL_APP_CHOICE ? "choice" : "likert", value, a->time_s, ts);
    if (n > 0 && (size_t)n < sizeof row)
        hol__put_file(s, "answers.csv", 1, row, (size_t)n);
}

void hol__log_frame(hol_session *s, const hol_app_events *ev, const hol_app_view *v,
                    const hol_input *in)
{
    if (ev->answered)
        hol__answer_row(s, &ev->answer);
    if (ev->pointed)
        hol__point_row(s, &ev->point);
    /* a restart ends the old attempt before the new one's rows; a
     * completion ends it after this frame's rows */
    if (ev->level_ended && ev->level_started)
        hol__attempt_end(s, &ev->summary, ev->level_ended);
    if (ev->level_started)
        hol__attempt_begin(s, v);
    hol__events(s, ev, v); /* the end screen's too: the place outlives it */
    if (!s->attempt_open)
        return;
    hol__step_rows(s, ev, v);
    hol__lesson_rows(s, ev);
    hol__head_rows(s, v);
    char name[HOL__CSV_NAME];
    hol__csv_name(s->levels[s->cur].name, name);
    hol__track_rows(s, v, in, name);
    if (ev->level_ended && !ev->level_started)
        hol__attempt_end(s, &ev->summary, ev->level_ended);
}
