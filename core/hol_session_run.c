/* hol_session_run.c - the session: create, a frame, the level sequence,
 * the end (see hol_session.h; its files: hol_session_impl.h). */
#include "hol_session_impl.h"

#include <stdio.h>
#include <string.h>

#include "hol_input_io.h"
#include "hol_sha256.h"
#include "hol_version.h"

#define HOL__REC_BUF (64u << 10)
#define HOL__ROWS_BUF (32u << 10)
#define HOL__TRACK_BUF (128u << 10) /* a second at 90 Hz and a gap's rows */

/* ---- create ---------------------------------------------------------------- */

/* desc.study_text's SHA-256 is meta.study_sha256 (see Studies). */
static int hol__study_hash_ok(const hol_session_desc *d)
{
    uint8_t dig[32];
    char hex[HOL_SHA256_HEX];
    hol_sha256(d->study_text, d->study_len, dig);
    hol_sha256_hex(dig, hex);
    return !strcmp(hex, d->meta.study_sha256);
}

static hol_err hol__check_desc(const hol_session_desc *d, char *msg, size_t cap)
{
    if (!d->levels || d->nlevels < 1 || d->nlevels > HOL_SESSION_MAX_LEVELS) {
        snprintf(msg, cap, "a session plays 1 to %d levels", HOL_SESSION_MAX_LEVELS);
        return HOL_EARG;
    }
    /* ids may be empty only without a recording (a version 1 recording's
     * replay does not know them) */
    const hol_rec_meta *m = &d->meta;
    if ((d->rec || m->session[0]) && !hol_rec_id_ok(m->session)) {
        snprintf(msg, cap, "the session id is not 1..63 letters, digits, '.', '_', '-'");
        return HOL_EARG;
    }
    if ((d->rec || m->start[0]) && !hol_rec_time_ok(m->start)) {
        snprintf(msg, cap, "the start time is not YYYY-MM-DDTHH:MM:SSZ");
        return HOL_EARG;
    }
    if (m->session_no < 0 || m->session_no > 999 ||
        (m->study_sha256[0] && strspn(m->study_sha256, "0123456789abcdef") != 64) ||
        strlen(m->study_sha256) % 64 || !hol_rec_meta_ok(m->meta)) {
        snprintf(msg, cap, "the session number, study hash or meta is not valid");
        return HOL_EARG;
    }
    if (m->participant[0] && !hol_rec_id_ok(m->participant)) {
        snprintf(msg, cap, "the participant is not 1..63 letters, digits, '.', '_', '-'");
        return HOL_EARG;
    }
    if (d->study_text && !hol__study_hash_ok(d)) {
        snprintf(msg, cap, "the study's text is not the one its hash names");
        return HOL_EARG;
    }
    if (d->track_hz && (d->track_hz < HOL_SESSION_TRACK_HZ_MIN ||
                        d->track_hz > HOL_SESSION_TRACK_HZ_MAX)) {
        snprintf(msg, cap, "the tracking rate is not %d..%d", HOL_SESSION_TRACK_HZ_MIN,
                 HOL_SESSION_TRACK_HZ_MAX);
        return HOL_EARG;
    }
    if (d->rec && (!d->rec_name || !d->rec_name[0] ||
                   strlen(d->rec_name) + 6 > HOL_SINK_NAME_MAX || strchr(d->rec_name, '/'))) {
        snprintf(msg, cap, "the recording's name is not valid");
        return HOL_EARG;
    }
    return HOL_OK;
}

static hol_err hol__start_level(hol_session *s)
{
    hol_app_level L = s->levels[s->cur].lvl;
    L.last = s->cur == s->nlevels - 1; /* its end screen says "finish" */
    /* a study's session ends on a closing screen (its `closing` text, or
     * this) */
    if (L.last && s->levels[s->cur].condition[0] && !L.closing[0])
        snprintf(L.closing, sizeof L.closing, "%s", HOL_SESSION_CLOSING);
    s->level_end = HOL_APP_END_NONE;
    hol_err e = hol_app_start_level(s->app, &L);
    long at = e == HOL_EBUDGET || e == HOL_EUNREACH ? hol_level_objective_line(&s->levels[s->cur]) : 0;
    char line[32] = "";
    if (at > 0)
        snprintf(line, sizeof line, "line %ld: ", at);
    if (e)
        snprintf(s->msg, sizeof s->msg, "level '%.60s' cannot start: %s%s",
                 s->levels[s->cur].name, line,
                 e == HOL_EBUDGET     ? "its optimum cannot be proved exact"
                 : e == HOL_EUNREACH ? "no walk inside its room reaches an objective"
                 : e == HOL_EARG     ? "an objective on the start tile, or a start walk leaving "
                                       "the room"
                                     : hol_err_str(e));
    return e;
}

/* The navigators of the levels' geometries, made now (the first
 * HOL_APP_MAX_NAVS of them), and every level of another geometry than
 * {4,5} 3 x 3 started once, so one that cannot start is refused before
 * the session begins; the first level is started last. */
static hol_err hol__prepare_levels(hol_session *s)
{
    int made = 0;
    for (int i = 0; i < s->nlevels; i++) {
        const hol_app_level *L = &s->levels[i].lvl;
        int fresh = 1;
        for (int j = 0; j < i; j++) {
            const hol_app_level *M = &s->levels[j].lvl;
            fresh &= !(M->tiling_q == L->tiling_q && M->room_cols == L->room_cols &&
                       M->room_rows == L->room_rows);
        }
        if (!fresh || made >= HOL_APP_MAX_NAVS)
            continue;
        made++;
        hol_err e = hol_app_prepare(s->app, L->tiling_q, L->room_cols, L->room_rows);
        if (e) {
            snprintf(s->msg, sizeof s->msg, "cannot make the navigator of level '%.60s': %s",
                     s->levels[i].name, hol_err_str(e));
            return e;
        }
    }
    for (s->cur = s->nlevels - 1; s->cur > 0; s->cur--) {
        const hol_app_level *L = &s->levels[s->cur].lvl;
        hol_err e = L->tiling_q || L->room_cols ? hol__start_level(s) : HOL_OK;
        if (e)
            return e;
    }
    return HOL_OK;
}

static void hol__rec_emit(void *ctx, const char *data, size_t n)
{
    hol_session *s = ctx;
    hol__out_put(s, &s->rec_out, data, n);
}

/* The recording: REC.live (refused when a killed session left one), the
 * header, flushed. */
static hol_err hol__rec_open(hol_session *s)
{
    char live[HOL_SINK_NAME_MAX + 8], probe[1];
    size_t got = 0;
    snprintf(live, sizeof live, "%s.live", s->rec_name);
    if (s->rec->read(s->rec->user, live, 0, probe, 1, &got) != HOL_EOPEN) {
        snprintf(s->msg, sizeof s->msg, "'%.100s' is there: the recording of a session that "
                 "did not end (replay it, then move it away)", live);
        return HOL_EARG;
    }
    hol_err e = hol__out_open(s, &s->rec_out, live, 0);
    if (e)
        return e;
    hol_rec_write_header(&s->meta, s->levels, s->nlevels, hol__rec_emit, s);
    hol__out_flush(s, &s->rec_out, 0);
    return s->failed;
}

static hol_err hol__alloc(hol_session *s, const hol_session_desc *d)
{
    size_t lv = (size_t)d->nlevels * sizeof *s->levels;
    size_t bufs = (d->rec ? HOL__REC_BUF : 0) +
                  (d->log ? 2 * HOL__ROWS_BUF + HOL__TRACK_BUF + 2 * HOL__ROW_MAX + HOL__TAIL_MAX
                          : 0);
    char *mem = hol_alloc_mem(&s->alloc, lv + bufs);
    if (!mem)
        return HOL_ENOMEM;
    s->levels = (hol_level *)(void *)mem;
    memcpy(s->levels, d->levels, lv);
    char *b = mem + lv;
    hol__out_init(&s->rec_out, d->rec, d->rec ? b : NULL, d->rec ? HOL__REC_BUF : 0);
    b += d->rec ? HOL__REC_BUF : 0;
    hol__out_init(&s->steps, d->log, d->log ? b : NULL, d->log ? HOL__ROWS_BUF : 0);
    hol__out_init(&s->head, d->log, d->log ? b + HOL__ROWS_BUF : NULL,
                  d->log ? HOL__ROWS_BUF : 0);
    hol__out_init(&s->track, d->log, d->log ? b + 2 * HOL__ROWS_BUF : NULL,
                  d->log ? HOL__TRACK_BUF : 0);
    if (d->log) {
        b += 2 * HOL__ROWS_BUF + HOL__TRACK_BUF;
        s->row = b;
        s->scratch = b + HOL__ROW_MAX;
        s->tail = b + 2 * HOL__ROW_MAX;
        hol__summary_tail(&d->meta, s->tail, HOL__TAIL_MAX, &s->tail_len);
    }
    return HOL_OK;
}

static hol_err hol__create(hol_session *s, const hol_session_desc *d)
{
    hol_err e = hol__alloc(s, d);
    if (e) {
        snprintf(s->msg, sizeof s->msg, "out of memory");
        return e;
    }
    hol_app_desc ad = d->app; /* a recording made before issue 35's flow
                                 replays in the flow it was played in */
    ad.flow_v4 |= d->meta.flow_v4;
    if ((e = hol_app_create(&ad, &s->app))) {
        snprintf(s->msg, sizeof s->msg, "cannot create the app: %s", hol_err_str(e));
        return e;
    }
    if ((e = hol__prepare_levels(s)) || (e = hol__start_level(s)))
        return e;
    if (s->meta.ask_item > 0) { /* a resumed level's questions alone */
        if (s->meta.ask_attempt < 1 || !hol_rec_id_ok(s->meta.ask_session) ||
            hol_app_ask_from(s->app, s->meta.ask_item - 1)) {
            snprintf(s->msg, sizeof s->msg, "level '%.60s' has no question %d to ask",
                     s->levels[0].name, s->meta.ask_item);
            return HOL_EARG;
        }
        s->ask_pending = 1;
        s->level_end = HOL_APP_END_DONE;
    } else if (s->meta.ready && (e = hol_app_ready(s->app))) {
        return e;
    }
    if (s->log && (e = hol__log_open(s, d->append)))
        return e;
    if (s->log)
        hol__log_levels(s);
    if (s->log && d->study_text)
        hol__log_study(s, d->study_text, d->study_len);
    if (s->failed)
        return s->failed;
    if (s->rec && (e = hol__rec_open(s)))
        return e;
    return HOL_OK;
}

hol_err hol_session_create(const hol_session_desc *d, hol_session **out, char *msg, size_t cap)
{
    hol_err e = hol__check_desc(d, msg, cap);
    if (e)
        return e;
    hol_session *s = hol_alloc_mem(&d->alloc, sizeof *s);
    if (!s) {
        snprintf(msg, cap, "out of memory");
        return HOL_ENOMEM;
    }
    memset(s, 0, sizeof *s);
    s->alloc = d->alloc;
    s->nlevels = d->nlevels;
    s->meta = d->meta;
    if (!s->meta.version[0])
        snprintf(s->meta.version, sizeof s->meta.version, "%s", HOL_VERSION);
    s->log = d->log;
    s->rec = d->rec;
    if (d->rec)
        snprintf(s->rec_name, sizeof s->rec_name, "%s", d->rec_name);
    s->flush_s = d->flush_s > 0 ? d->flush_s : 1.0;
    s->track_hz = d->track_hz ? d->track_hz : HOL_SESSION_TRACK_HZ;
    if ((e = hol__create(s, d))) {
        snprintf(msg, cap, "%s", s->msg);
        hol_session_destroy(s);
        return e;
    }
    *out = s;
    return HOL_OK;
}

/* ---- a frame ------------------------------------------------------------------ */

static void hol__flush_all(hol_session *s, int durable)
{
    hol__out_flush(s, &s->rec_out, durable);
    hol__out_flush(s, &s->steps, durable);
    hol__out_flush(s, &s->head, durable);
    hol__out_flush(s, &s->track, durable);
}

hol_err hol_session_step(hol_session *s, const hol_input *in, int *out_over)
{
    *out_over = s->over;
    if (s->over)
        return HOL_OK;
    hol_err e = hol_app_step(s->app, in);
    if (e) {
        snprintf(s->msg, sizeof s->msg, "frame %ld: the app step failed: %s", s->frames,
                 hol_err_str(e));
        return e;
    }
    s->frames++;
    s->now = in->time_s;
    if (s->rec) {
        char line[HOL_INPUT_LINE_MAX + 2];
        size_t n = hol_input_format(in, line, sizeof line);
        line[n++] = '\n';
        hol__out_put(s, &s->rec_out, line, n);
    }
    const hol_app_events *ev = hol_app_get_events(s->app);
    const hol_app_view *v = hol_app_get_view(s->app);
    if (s->log)
        hol__log_frame(s, ev, v, in);
    if (ev->level_started)
        s->level_end = HOL_APP_END_NONE;
    else if (ev->level_ended)
        s->level_end = ev->level_ended;
    if (v->state == HOL_APP_QUIT) {
        s->over = 1;
    } else if (ev->next_level) {
        if (s->cur + 1 >= s->nlevels) {
            s->over = 1;
        } else {
            s->cur++;
            if ((e = hol__start_level(s)))
                return e;
        }
    }
    if (s->now >= s->next_flush) {
        hol__flush_all(s, 0);
        s->next_flush = s->now + s->flush_s;
    }
    *out_over = s->over;
    if (s->failed && !s->failed_told) {
        s->failed_told = 1;
        return s->failed;
    }
    return HOL_OK;
}

/* ---- the end -------------------------------------------------------------------- */

/* The attempt in play ends with end: its summary from the view. */
static void hol__end_attempt_now(hol_session *s, int end)
{
    if (!s->log || !s->attempt_open)
        return;
    const hol_app_view *v = hol_app_get_view(s->app);
    hol_app_summary sum;
    memset(&sum, 0, sizeof sum);
    sum.mode = s->levels[s->cur].lvl.mode;
    sum.seed = s->levels[s->cur].lvl.seed;
    sum.steps = v->hud.steps;
    sum.optimum = v->hud.optimum;
    sum.time_s = v->hud.elapsed_s;
    hol__attempt_end(s, &sum, end);
}

static hol_err hol__end(hol_session *s, int end)
{
    if (s->finished)
        return s->failed;
    s->finished = s->over = 1;
    hol__end_attempt_now(s, end);
    if (s->rec && s->rec_out.h >= 0) {
        if (end == HOL__END_ABORTED) /* a replay ends the same way */
            hol__out_put(s, &s->rec_out, HOL_REC_ABORTED_LINE "\n",
                         sizeof HOL_REC_ABORTED_LINE);
        char live[HOL_SINK_NAME_MAX + 8];
        snprintf(live, sizeof live, "%s.live", s->rec_name);
        hol__out_flush(s, &s->rec_out, 1);
        hol__out_close(s, &s->rec_out);
        if (!s->failed && s->rec->rename(s->rec->user, live, s->rec_name))
            hol__fail_sink(s, s->rec, HOL_EIO, "rename", live);
    }
    return s->failed;
}

hol_err hol_session_abort(hol_session *s)
{
    return hol__end(s, HOL__END_ABORTED);
}

hol_err hol_session_end_killed(hol_session *s)
{
    if (!s->finished && s->log && s->attempt_open && !s->failed) {
        hol__out_flush(s, &s->steps, 1);
        hol__out_flush(s, &s->head, 1);
        hol__out_flush(s, &s->track, 1);
        hol__out_close(s, &s->steps);
        hol__out_close(s, &s->head);
        hol__out_close(s, &s->track);
        s->attempt_open = 0;
        if (!s->failed)
            hol__recover_killed(s, s->attempt);
    }
    return hol__end(s, HOL_APP_END_NONE);
}

hol_err hol_session_finish(hol_session *s)
{
    return hol__end(s, HOL_APP_END_NONE);
}

void hol_session_destroy(hol_session *s)
{
    if (!s)
        return;
    hol__out *outs[4] = {&s->rec_out, &s->steps, &s->head, &s->track};
    for (int i = 0; i < 4; i++)
        if (outs[i]->h >= 0)
            outs[i]->sink->close(outs[i]->sink->user, outs[i]->h);
    hol_app_destroy(s->app);
    hol_alloc a = s->alloc;
    hol_alloc_release(&a, s->levels);
    hol_alloc_release(&a, s);
}

hol_app *hol_session_app(hol_session *s)
{
    return s->app;
}

int hol_session_level_index(const hol_session *s)
{
    return s->cur;
}

const hol_level *hol_session_level(const hol_session *s)
{
    return &s->levels[s->cur];
}

int hol_session_level_end(const hol_session *s)
{
    return s->level_end;
}

const char *hol_session_end_name(hol_session *s)
{
    static const char *const ends[] = {"playing", "done", "restart", "quit", "timeout"};
    const hol_app_view *v = hol_app_get_view(s->app);
    if (!v->hud.timed_out && s->level_end > 0 && s->level_end < 5)
        return ends[s->level_end];
    return hol_app_end_word(v);
}

long hol_session_frames(const hol_session *s)
{
    return s->frames;
}

int hol_session_recovered(const hol_session *s)
{
    return s->recovered;
}

int hol_session_dropped(const hol_session *s)
{
    return s->dropped;
}

const char *hol_session_repaired(hol_session *s)
{
    if (!s->cut[0] && !s->gone[0])
        return "";
    snprintf(s->repaired, sizeof s->repaired, "%s%s%s%s%s%s",
             s->cut[0] ? "the log folder's rows a kill cut removed (" : "", s->cut,
             s->cut[0] ? ")" : "", s->cut[0] && s->gone[0] ? "; " : "",
             s->gone[0] ? "the files of the attempt whose summary row was cut removed with it: "
                        : "",
             s->gone);
    return s->repaired;
}

const char *hol_session_message(const hol_session *s)
{
    return s->msg;
}
