/* hol_web_sink.c - the session's sink over the page's store (see
 * hol_web_sink.h; the store is platform/web/store.js, reached through
 * hol_web_lib.js). */
#include "hol_web_sink.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* hol_web_lib.js: the store (ints: a handle, a byte count, 0 ok, -1 fail) */
extern int hol_web_js_store_open(const char *name, int append);
extern int hol_web_js_store_write(int h, const void *data, int n);
extern int hol_web_js_store_flush(int h);
extern int hol_web_js_store_close(int h);
extern int hol_web_js_store_rename(const char *from, const char *to);
extern int hol_web_js_store_remove(const char *name);
extern int hol_web_js_store_read(const char *name, double off, void *buf, int n);
extern int hol_web_js_store_list(char *buf, int cap); /* names, '\n' after each */
extern void hol_web_js_store_why(char *buf, int cap);
extern void hol_web_js_meta(char *start, char *session, int cap);

static hol_err s_open(void *u, const char *name, int append, int *out_h)
{
    (void)u;
    int h = hol_web_js_store_open(name, append);
    if (h < 0)
        return HOL_EOPEN;
    *out_h = h;
    return HOL_OK;
}

static hol_err s_write(void *u, int h, const void *data, size_t n)
{
    (void)u;
    for (size_t at = 0; at < n;) { /* in pieces an int holds */
        int k = n - at > (1u << 30) ? 1 << 30 : (int)(n - at);
        if (hol_web_js_store_write(h, (const char *)data + at, k))
            return HOL_EIO;
        at += (size_t)k;
    }
    return HOL_OK;
}

static hol_err s_flush(void *u, int h, int durable)
{
    (void)u, (void)durable;
    return hol_web_js_store_flush(h) ? HOL_EIO : HOL_OK;
}

static hol_err s_close(void *u, int h)
{
    (void)u;
    return hol_web_js_store_close(h) ? HOL_EIO : HOL_OK;
}

static hol_err s_rename(void *u, const char *from, const char *to)
{
    (void)u;
    return hol_web_js_store_rename(from, to) ? HOL_EOPEN : HOL_OK;
}

static hol_err s_remove(void *u, const char *name)
{
    (void)u;
    return hol_web_js_store_remove(name) ? HOL_EIO : HOL_OK;
}

static hol_err s_read(void *u, const char *name, uint64_t off, void *buf, size_t n,
                      size_t *out_got)
{
    (void)u;
    int k = n > (1u << 30) ? 1 << 30 : (int)n;
    int got = hol_web_js_store_read(name, (double)off, buf, k);
    if (got < 0)
        return HOL_EOPEN;
    *out_got = (size_t)got;
    return HOL_OK;
}

static hol_err s_list(void *u, void (*fn)(void *ctx, const char *name), void *ctx)
{
    (void)u;
    int need = hol_web_js_store_list(NULL, 0);
    char *buf = malloc((size_t)need + 1);
    if (!buf)
        return HOL_ENOMEM;
    hol_web_js_store_list(buf, need + 1);
    for (char *p = buf, *nl; (nl = strchr(p, '\n')); p = nl + 1) {
        *nl = 0;
        fn(ctx, p);
    }
    free(buf);
    return HOL_OK;
}

static const char *s_why(void *u)
{
    (void)u;
    static char why[160];
    hol_web_js_store_why(why, sizeof why);
    return why;
}

const hol_sink *hol_web_sink(void)
{
    static const hol_sink sink = {NULL,     s_open,   s_write, s_flush, s_close,
                                  s_rename, s_remove, s_read,  s_list,  s_why};
    return &sink;
}

void hol_web_sink_meta(hol_rec_meta *m, const char *participant)
{
    memset(m, 0, sizeof *m);
    hol_web_js_meta(m->start, m->session, (int)sizeof m->start);
    if (participant)
        snprintf(m->participant, sizeof m->participant, "%s", participant);
}
