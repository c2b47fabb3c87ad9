/* mem_sink.h - a folder in memory behind the hol_sink interface, for the
 * session tests (test_session.c, test_track.c).
 *
 * Contract
 * - Include after <cmocka.h> and core/hol_session.h, once per test program
 *   (static functions marked unused: a program uses what it needs). MEM_TEXT_MAX
 *   (default 1 MB), defined before the include, sizes mem_text's buffer.
 * - mem_init gives an empty folder; streams keep `kept` as of their last
 *   flush or close, so mem_kill is a kill -9 (unflushed bytes and open
 *   handles gone); fail_rename makes the n-th rename from now fail.
 * - mem_text is the stream's text in one static buffer (the next call
 *   overwrites it); mem_free releases every stream.
 */
#ifndef TESTS_MEM_SINK_H
#define TESTS_MEM_SINK_H

#define MEM__UNUSED __attribute__((unused))

#ifndef MEM_TEXT_MAX
#define MEM_TEXT_MAX (1 << 20)
#endif

#define MEM_MAX 64

typedef struct mem_stream {
    char name[HOL_SINK_NAME_MAX];
    char *data;
    size_t len, cap, kept; /* kept: bytes as of the last flush (or close) */
    int used;
} mem_stream;

typedef struct mem_sink {
    hol_sink sink;
    mem_stream s[MEM_MAX];
    int open[HOL_SINK_MAX_OPEN]; /* stream index + 1, 0: free */
    int fail_rename;             /* > 0: the n-th rename from now fails */
    long flushes;
} mem_sink;

MEM__UNUSED static mem_stream *mem_find(mem_sink *m, const char *name)
{
    for (int i = 0; i < MEM_MAX; i++)
        if (m->s[i].used && !strcmp(m->s[i].name, name))
            return &m->s[i];
    return NULL;
}

MEM__UNUSED static mem_stream *mem_make(mem_sink *m, const char *name)
{
    mem_stream *s = mem_find(m, name);
    for (int i = 0; !s && i < MEM_MAX; i++)
        if (!m->s[i].used) {
            s = &m->s[i];
            memset(s, 0, sizeof *s);
            s->used = 1;
            snprintf(s->name, sizeof s->name, "%s", name);
        }
    assert_non_null(s);
    return s;
}

MEM__UNUSED static hol_err mem_open(void *user, const char *name, int append, int *out_h)
{
    mem_sink *m = user;
    mem_stream *s = mem_make(m, name);
    if (!append)
        s->len = s->kept = 0;
    for (int h = 0; h < HOL_SINK_MAX_OPEN; h++)
        if (!m->open[h]) {
            m->open[h] = (int)(s - m->s) + 1;
            *out_h = h;
            return HOL_OK;
        }
    fail_msg("more than %d streams open", HOL_SINK_MAX_OPEN);
    return HOL_EIO;
}

MEM__UNUSED static hol_err mem_write(void *user, int h, const void *data, size_t n)
{
    mem_sink *m = user;
    assert_true(h >= 0 && h < HOL_SINK_MAX_OPEN && m->open[h]);
    mem_stream *s = &m->s[m->open[h] - 1];
    if (s->len + n > s->cap) {
        s->cap = (s->len + n) * 2 + 64;
        s->data = realloc(s->data, s->cap);
        assert_non_null(s->data);
    }
    memcpy(s->data + s->len, data, n);
    s->len += n;
    return HOL_OK;
}

MEM__UNUSED static hol_err mem_flush(void *user, int h, int durable)
{
    mem_sink *m = user;
    (void)durable;
    assert_true(m->open[h]);
    m->s[m->open[h] - 1].kept = m->s[m->open[h] - 1].len;
    m->flushes++;
    return HOL_OK;
}

MEM__UNUSED static hol_err mem_close(void *user, int h)
{
    mem_sink *m = user;
    assert_true(m->open[h]);
    m->open[h] = 0;
    return HOL_OK;
}

MEM__UNUSED static int mem_is_open(mem_sink *m, const mem_stream *s)
{
    for (int h = 0; h < HOL_SINK_MAX_OPEN; h++)
        if (m->open[h] == (int)(s - m->s) + 1)
            return 1;
    return 0;
}

MEM__UNUSED static hol_err mem_rename(void *user, const char *from, const char *to)
{
    mem_sink *m = user;
    if (m->fail_rename > 0 && --m->fail_rename == 0)
        return HOL_EIO;
    mem_stream *s = mem_find(m, from), *t = mem_find(m, to);
    assert_non_null(s);
    assert_false(mem_is_open(m, s));
    if (t) {
        free(t->data);
        memset(t, 0, sizeof *t);
    }
    snprintf(s->name, sizeof s->name, "%s", to);
    return HOL_OK;
}

MEM__UNUSED static hol_err mem_remove(void *user, const char *name)
{
    mem_stream *s = mem_find(user, name);
    if (s) {
        free(s->data);
        memset(s, 0, sizeof *s);
    }
    return HOL_OK;
}

MEM__UNUSED static hol_err mem_read(void *user, const char *name, uint64_t off, void *buf, size_t n,
                        size_t *out_got)
{
    mem_stream *s = mem_find(user, name);
    *out_got = 0;
    if (!s)
        return HOL_EOPEN;
    if (off < s->len) {
        size_t k = s->len - (size_t)off < n ? s->len - (size_t)off : n;
        memcpy(buf, s->data + off, k);
        *out_got = k;
    }
    return HOL_OK;
}

MEM__UNUSED static hol_err mem_list(void *user, void (*fn)(void *ctx, const char *name), void *ctx)
{
    mem_sink *m = user;
    for (int i = 0; i < MEM_MAX; i++)
        if (m->s[i].used)
            fn(ctx, m->s[i].name);
    return HOL_OK;
}

MEM__UNUSED static void mem_init(mem_sink *m)
{
    memset(m, 0, sizeof *m);
    m->sink = (hol_sink){m, mem_open, mem_write, mem_flush, mem_close, mem_rename, mem_remove,
                         mem_read, mem_list, NULL};
}

/* A kill -9: what was not flushed is gone, open handles with it. */
MEM__UNUSED static void mem_kill(mem_sink *m)
{
    for (int i = 0; i < MEM_MAX; i++)
        m->s[i].len = m->s[i].kept;
    memset(m->open, 0, sizeof m->open);
}

MEM__UNUSED static void mem_free(mem_sink *m)
{
    for (int i = 0; i < MEM_MAX; i++)
        free(m->s[i].data);
    memset(m, 0, sizeof *m);
}

/* The stream's text (NUL-terminated copy in a static buffer), or NULL. */
MEM__UNUSED static const char *mem_text(mem_sink *m, const char *name)
{
    static char buf[MEM_TEXT_MAX];
    mem_stream *s = mem_find(m, name);
    if (!s)
        return NULL;
    assert_true(s->len < sizeof buf);
    memcpy(buf, s->data, s->len);
    buf[s->len] = 0;
    return buf;
}

MEM__UNUSED static int count_lines(const char *t)
{
    int n = 0;
    for (; t && *t; t++)
        n += *t == '\n';
    return n;
}


#endif
