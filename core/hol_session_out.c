/* hol_session_out.c - the session's lowest output helpers, used by its
 * other files (hol_session_run.c, hol_session_log.c, hol_session_track.c,
 * hol_session_recover.c): the end names, the first sink failure, the
 * buffered streams of a sink and the names of an attempt's files. It calls
 * none of them. */
#include "hol_session_impl.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char *const hol__end_names[7] = {"open",    "done",    "restart", "quit",
                                       "timeout", "aborted", "killed"};
hol_err hol__fail_sink(hol_session *s, const hol_sink *k, hol_err e, const char *what,
                       const char *name)
{
    if (!s->failed) {
        const char *why = k && k->why ? k->why(k->user) : NULL;
        s->failed = e;
        snprintf(s->msg, sizeof s->msg, "cannot %s '%.120s'%s%s", what, name, why ? ": " : "",
                 why ? why : "");
    }
    return e;
}

void hol__out_init(hol__out *o, const hol_sink *sink, char *buf, size_t cap)
{
    memset(o, 0, sizeof *o);
    o->sink = sink;
    o->h = -1;
    o->buf = buf;
    o->cap = cap;
}

hol_err hol__out_open(hol_session *s, hol__out *o, const char *name, int append)
{
    if (s->failed)
        return s->failed;
    snprintf(o->name, sizeof o->name, "%s", name);
    o->n = 0;
    hol_err e = o->sink->open(o->sink->user, name, append, &o->h);
    if (e) {
        o->h = -1;
        return hol__fail_sink(s, o->sink, e, "open", name);
    }
    return HOL_OK;
}

static void hol__out_drain(hol_session *s, hol__out *o)
{
    if (o->h < 0 || s->failed || !o->n)
        return;
    hol_err e = o->sink->write(o->sink->user, o->h, o->buf, o->n);
    o->n = 0;
    if (e)
        hol__fail_sink(s, o->sink, e, "write", o->name);
}

void hol__out_put(hol_session *s, hol__out *o, const char *data, size_t n)
{
    if (o->h < 0 || s->failed)
        return;
    if (n > o->cap - o->n)
        hol__out_drain(s, o);
    if (n > o->cap) {
        hol_err e = o->sink->write(o->sink->user, o->h, data, n);
        if (e)
            hol__fail_sink(s, o->sink, e, "write", o->name);
        return;
    }
    memcpy(o->buf + o->n, data, n);
    o->n += n;
}

void hol__out_printf(hol_session *s, hol__out *o, const char *fmt, ...)
{
    char row[1024];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(row, sizeof row, fmt, ap);
    va_end(ap);
    if (n > 0)
        hol__out_put(s, o, row, (size_t)n < sizeof row ? (size_t)n : sizeof row - 1);
}

void hol__out_flush(hol_session *s, hol__out *o, int durable)
{
    hol__out_drain(s, o);
    if (o->h < 0 || s->failed)
        return;
    hol_err e = o->sink->flush(o->sink->user, o->h, durable);
    if (e)
        hol__fail_sink(s, o->sink, e, "flush", o->name);
}

void hol__out_close(hol_session *s, hol__out *o)
{
    if (o->h < 0)
        return;
    hol_err e = o->sink->close(o->sink->user, o->h);
    o->h = -1;
    o->n = 0;
    if (e)
        hol__fail_sink(s, o->sink, e, "close", o->name);
}

/* ---- names ------------------------------------------------------------------ */

void hol__attempt_name(char *out, size_t cap, const char *what, int attempt)
{
    if (!strcmp(what, "attempt"))
        snprintf(out, cap, "attempt-%03d.live", attempt);
    else
        snprintf(out, cap, "%s-%03d.csv", what, attempt);
}
