/* hol_lines.c - streamed, bounded line reading (see hol_lines.h). */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include "hol_lines.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hol_file.h"

#define HOL__CHUNK (64u << 10)

hol_err hol_lines_open_fd(hol_lines *l, int fd, size_t limit)
{
    memset(l, 0, sizeof *l);
    l->fd = -1;
    l->line = malloc(limit + 2);
    l->buf = malloc(HOL__CHUNK);
    if (!l->line || !l->buf) {
        hol_lines_close(l);
        return HOL_ENOMEM;
    }
    l->fd = fd;
    l->limit = limit;
    return HOL_OK;
}

hol_err hol_lines_open(hol_lines *l, const char *path, size_t limit)
{
    hol_file_in f;
    hol_err e = hol_file_open_in(path, &f);
    if (e) {
        memset(l, 0, sizeof *l);
        l->fd = -1;
        return e;
    }
    if ((e = hol_lines_open_fd(l, f.fd, limit))) {
        hol_file_close_in(&f);
        return e;
    }
    l->own_fd = 1;
    return HOL_OK;
}

/* Refill the buffer: 1 bytes came, 0 the end, -1 a failure. */
static int hol__fill(hol_lines *l)
{
    for (;;) {
        ssize_t r = read(l->fd, l->buf, HOL__CHUNK);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            l->err = HOL_EIO;
            return -1;
        }
        l->pos = 0;
        l->end = (size_t)r;
        return r > 0;
    }
}

int hol_lines_next(hol_lines *l, char **out_s, size_t *out_len)
{
    size_t n = 0;
    if (l->eof || l->err)
        return l->err ? -1 : 0;
    l->cut = 0;
    for (;;) {
        if (l->pos == l->end) {
            int f = hol__fill(l);
            if (f < 0)
                return -1;
            if (f == 0) {
                l->eof = 1;
                if (n == 0)
                    return 0;
                l->cut = 1;
                break; /* a last line without LF */
            }
        }
        uint8_t *nl = memchr(l->buf + l->pos, '\n', l->end - l->pos);
        size_t take = (nl ? (size_t)(nl - l->buf) : l->end) - l->pos;
        if (n + take > l->limit + 1) {
            l->lineno++;
            l->err = HOL_ENOMEM;
            return -1;
        }
        memcpy(l->line + n, l->buf + l->pos, take);
        n += take;
        l->pos += take + (nl ? 1 : 0);
        if (nl)
            break;
    }
    if (n && l->line[n - 1] == '\r')
        n--;
    l->lineno++;
    if (n > l->limit) {
        l->err = HOL_ENOMEM;
        return -1;
    }
    l->line[n] = 0;
    *out_s = l->line;
    *out_len = n;
    return 1;
}

void hol_lines_close(hol_lines *l)
{
    if (l->fd >= 0 && l->own_fd)
        close(l->fd);
    free(l->line);
    free(l->buf);
    memset(l, 0, sizeof *l);
    l->fd = -1;
}
