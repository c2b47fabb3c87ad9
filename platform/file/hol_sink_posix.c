/* hol_sink_posix.c - the session's sink over a folder (see
 * hol_sink_posix.h). */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include "hol_sink_posix.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static hol_err hol__why(hol_sink_posix *p, hol_err e)
{
    snprintf(p->why, sizeof p->why, "%s", strerror(errno));
    return e;
}

static int hol__path(const hol_sink_posix *p, const char *name, char *out, size_t cap)
{
    int n = snprintf(out, cap, "%s/%s", p->dir, name);
    if (n < 0 || (size_t)n >= cap || strchr(name, '/') || !name[0]) {
        errno = ENAMETOOLONG;
        return 1;
    }
    return 0;
}

/* open(2) without blocking on a FIFO; only a regular file is kept. */
static int hol__open_regular(const char *path, int flags)
{
    int fd = open(path, flags | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0)
        return -1;
    struct stat st;
    if (fstat(fd, &st) || !S_ISREG(st.st_mode)) {
        close(fd);
        errno = EINVAL;
        return -1;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0)
        (void)fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    return fd;
}

static hol_err hol__open(void *user, const char *name, int append, int *out_h)
{
    hol_sink_posix *p = user;
    char path[4096 + HOL_SINK_NAME_MAX];
    int slot = -1;
    for (int i = 0; i < HOL_SINK_MAX_OPEN && slot < 0; i++)
        if (p->fd[i] < 0)
            slot = i;
    if (slot < 0) {
        errno = EMFILE;
        return hol__why(p, HOL_EIO);
    }
    if (hol__path(p, name, path, sizeof path))
        return hol__why(p, HOL_EOPEN);
    /* an existing non-regular name is refused before it is truncated */
    int fd = hol__open_regular(path, O_WRONLY | O_CREAT | (append ? O_APPEND : 0));
    if (fd < 0)
        return hol__why(p, HOL_EOPEN);
    if (!append && ftruncate(fd, 0)) {
        close(fd);
        return hol__why(p, HOL_EIO);
    }
    p->fd[slot] = fd;
    *out_h = slot;
    return HOL_OK;
}

static hol_err hol__write(void *user, int h, const void *data, size_t n)
{
    hol_sink_posix *p = user;
    const char *b = data;
    while (n) {
        ssize_t w = write(p->fd[h], b, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return hol__why(p, HOL_EIO);
        b += w;
        n -= (size_t)w;
    }
    return HOL_OK;
}

static hol_err hol__flush(void *user, int h, int durable)
{
    hol_sink_posix *p = user;
    if (durable && fsync(p->fd[h]))
        return hol__why(p, HOL_EIO);
    return HOL_OK;
}

static hol_err hol__close(void *user, int h)
{
    hol_sink_posix *p = user;
    int r = close(p->fd[h]);
    p->fd[h] = -1;
    return r ? hol__why(p, HOL_EIO) : HOL_OK;
}

static hol_err hol__rename(void *user, const char *from, const char *to)
{
    hol_sink_posix *p = user;
    char a[4096 + HOL_SINK_NAME_MAX], b[4096 + HOL_SINK_NAME_MAX];
    if (hol__path(p, from, a, sizeof a) || hol__path(p, to, b, sizeof b) || rename(a, b))
        return hol__why(p, HOL_EIO);
    int dfd = open(p->dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        (void)fsync(dfd);
        close(dfd);
    }
    return HOL_OK;
}

static hol_err hol__remove(void *user, const char *name)
{
    hol_sink_posix *p = user;
    char path[4096 + HOL_SINK_NAME_MAX];
    if (hol__path(p, name, path, sizeof path) || (unlink(path) && errno != ENOENT))
        return hol__why(p, HOL_EIO);
    return HOL_OK;
}

static hol_err hol__read(void *user, const char *name, uint64_t off, void *buf, size_t n,
                         size_t *out_got)
{
    hol_sink_posix *p = user;
    char path[4096 + HOL_SINK_NAME_MAX];
    *out_got = 0;
    if (p->stop && p->stop()) {
        snprintf(p->why, sizeof p->why, "stopped by a signal");
        return HOL_EIO;
    }
    if (hol__path(p, name, path, sizeof path))
        return hol__why(p, HOL_EIO);
    int fd = hol__open_regular(path, O_RDONLY);
    if (fd < 0)
        return hol__why(p, errno == ENOENT ? HOL_EOPEN : HOL_EIO);
    size_t got = 0;
    while (got < n) {
        ssize_t r = pread(fd, (char *)buf + got, n - got, (off_t)(off + got));
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0) {
            close(fd);
            return hol__why(p, HOL_EIO);
        }
        if (r == 0)
            break;
        got += (size_t)r;
    }
    close(fd);
    *out_got = got;
    return HOL_OK;
}

static hol_err hol__list(void *user, void (*fn)(void *ctx, const char *name), void *ctx)
{
    hol_sink_posix *p = user;
    DIR *d = opendir(p->dir);
    if (!d)
        return hol__why(p, HOL_EIO);
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            fn(ctx, e->d_name);
    closedir(d);
    return HOL_OK;
}

static const char *hol__whyfn(void *user)
{
    hol_sink_posix *p = user;
    return p->why[0] ? p->why : NULL;
}

hol_err hol_sink_posix_init(hol_sink_posix *p, const char *dir)
{
    memset(p, 0, sizeof *p);
    for (int i = 0; i < HOL_SINK_MAX_OPEN; i++)
        p->fd[i] = -1;
    struct stat st;
    if (strlen(dir) >= sizeof p->dir) {
        errno = ENAMETOOLONG;
        return HOL_EOPEN;
    }
    if (stat(dir, &st))
        return HOL_EOPEN;
    if (!S_ISDIR(st.st_mode)) {
        errno = ENOTDIR;
        return HOL_EOPEN;
    }
    snprintf(p->dir, sizeof p->dir, "%s", dir);
    p->lock_fd = -1;
    p->sink = (hol_sink){p, hol__open, hol__write, hol__flush, hol__close, hol__rename,
                         hol__remove, hol__read, hol__list, hol__whyfn};
    return HOL_OK;
}

void hol_sink_posix_fini(hol_sink_posix *p)
{
    for (int i = 0; i < HOL_SINK_MAX_OPEN; i++)
        if (p->fd[i] >= 0) {
            close(p->fd[i]);
            p->fd[i] = -1;
        }
    if (p->lock_fd >= 0) {
        /* removed while still held: a writer that opened it meanwhile sees
         * another file at the name and opens again */
        char path[4096 + sizeof HOL_SINK_POSIX_LOCK];
        if (!hol__path(p, HOL_SINK_POSIX_LOCK, path, sizeof path))
            (void)unlink(path);
        close(p->lock_fd);
        p->lock_fd = -1;
    }
}

/* The lock file's text, "pid PID on HOST", into holder (empty when none). */
static void hol__lock_holder(int fd, char *holder, size_t cap)
{
    char buf[256];
    ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    n = n < 0 ? 0 : n;
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == ' '))
        n--;
    buf[n] = 0;
    if (cap)
        snprintf(holder, cap, "%s", buf);
}

/* Open and lock DIR/.holonomy-lock: 1 held, 0 held by another, -1 failed;
 * the file locked is the one at the name (a holder that removed it as this
 * opened it: open again). */
static int hol__lock_take(const char *path, int *out_fd)
{
    for (int tries = 0; tries < 8; tries++) {
        int fd = hol__open_regular(path, O_RDWR | O_CREAT | O_NOFOLLOW);
        if (fd < 0)
            return -1;
        if (flock(fd, LOCK_EX | LOCK_NB)) {
            int e = errno;
            *out_fd = fd;
            errno = e;
            return e == EWOULDBLOCK ? 0 : -1;
        }
        struct stat a, b;
        if (!fstat(fd, &a) && !stat(path, &b) && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
            *out_fd = fd;
            return 1;
        }
        close(fd);
    }
    errno = EAGAIN;
    return -1;
}

hol_err hol_sink_posix_lock(hol_sink_posix *p, char *holder, size_t cap, int *out_took)
{
    char path[4096 + sizeof HOL_SINK_POSIX_LOCK];
    *out_took = 0;
    if (cap)
        holder[0] = 0;
    if (hol__path(p, HOL_SINK_POSIX_LOCK, path, sizeof path))
        return HOL_EOPEN;
    int fd = -1;
    int r = hol__lock_take(path, &fd);
    if (r <= 0) {
        int e = errno;
        if (fd >= 0) {
            if (r == 0)
                hol__lock_holder(fd, holder, cap);
            close(fd);
        }
        errno = e;
        return r == 0 ? HOL_EARG : HOL_EOPEN;
    }
    hol__lock_holder(fd, holder, cap);
    *out_took = cap && holder[0];
    char me[300], host[256];
    if (gethostname(host, sizeof host))
        snprintf(host, sizeof host, "?");
    host[sizeof host - 1] = 0;
    int n = snprintf(me, sizeof me, "pid %ld on %s\n", (long)getpid(), host);
    if (pwrite(fd, me, (size_t)n, 0) != n || ftruncate(fd, n)) {
        int e = errno;
        close(fd);
        (void)unlink(path);
        errno = e;
        return HOL_EOPEN;
    }
    p->lock_fd = fd;
    return HOL_OK;
}

hol_err hol_sink_posix_make_dir(const char *dir)
{
    struct stat st;
    if (!stat(dir, &st)) {
        if (S_ISDIR(st.st_mode))
            return HOL_OK;
        errno = ENOTDIR;
        return HOL_EOPEN;
    }
    if (errno != ENOENT || mkdir(dir, 0777))
        return HOL_EOPEN;
    return HOL_OK;
}

void hol_sink_posix_meta(hol_rec_meta *m, const char *participant)
{
    memset(m, 0, sizeof *m);
    time_t now = time(NULL);
    struct tm tm;
    gmtime_r(&now, &tm);
    strftime(m->start, sizeof m->start, "%Y-%m-%dT%H:%M:%SZ", &tm);
    uint32_t r = 0;
    if (getrandom(&r, sizeof r, GRND_NONBLOCK) != (ssize_t)sizeof r)
        r = (uint32_t)getpid() * 2654435761u ^ (uint32_t)now;
    char stamp[32];
    strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
    snprintf(m->session, sizeof m->session, "%s-%08x", stamp, (unsigned)r);
    if (participant)
        snprintf(m->participant, sizeof m->participant, "%s", participant);
}
