#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include "hol_file.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


/* Temporary files are DIR/.BASE.holonomy-tmp.PID.XXXXXX: hidden, named
 * after their target and their writer, so a later save of the same target
 * can tell its own leftovers (the writer is gone) from anything else. */
#define HOL__TMP_TAG ".holonomy-tmp."

/* A leftover's name: ".BASE" HOL__TMP_TAG "PID.XXXXXX"; its PID, 0 when
 * the name is no temporary file's. */
static long hol__tmp_pid(const char *name)
{
    const char *tag = name[0] == '.' ? strstr(name + 1, HOL__TMP_TAG) : NULL;
    if (!tag || tag == name + 1)
        return 0;
    const char *last;
    while ((last = strstr(tag + 1, HOL__TMP_TAG)) != NULL) /* BASE may hold the tag */
        tag = last;
    char *end = NULL;
    long pid = strtol(tag + strlen(HOL__TMP_TAG), &end, 10);
    return pid > 0 && end && *end == '.' && strlen(end) == 7 ? pid : 0;
}

int hol_file_clean_dir(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int e0 = errno, n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        long pid = hol__tmp_pid(e->d_name);
        if (!pid || kill((pid_t)pid, 0) == 0 || errno != ESRCH)
            continue; /* no temporary file, or its writer may still be at work */
        char full[4608];
        if (snprintf(full, sizeof full, "%s/%s", dir, e->d_name) < (int)sizeof full &&
            unlink(full) == 0)
            n++;
    }
    closedir(d);
    if (n)
        fprintf(stderr, "holonomy: removed %d temporary file(s) left in '%.200s' by writers "
                        "that no longer run\n", n, dir);
    errno = e0;
    return n;
}

/* Remove the leftovers of interrupted saves in path's folder (see
 * hol_file_clean_dir). Best effort. */
static void hol__clean_leftovers(const char *path)
{
    const char *slash = strrchr(path, '/');
    char dir[4096];
    size_t dl = slash ? (size_t)(slash - path) : 0;
    if (dl >= sizeof dir)
        return;
    if (slash) {
        memcpy(dir, path, dl);
        dir[dl] = 0;
        if (dl == 0)
            strcpy(dir, "/");
    } else {
        strcpy(dir, ".");
    }
    (void)hol_file_clean_dir(dir);
}

static const char *hol__kind(mode_t m)
{
    if (S_ISDIR(m))
        return "a directory";
    if (S_ISFIFO(m))
        return "a FIFO";
    if (S_ISSOCK(m))
        return "a socket";
    if (S_ISCHR(m))
        return "a character device";
    if (S_ISBLK(m))
        return "a block device";
    return "not a regular file";
}

/* The reason in msg (fmt holds one %s, for what), errno set for callers
 * that print strerror. */
static hol_err hol__refuse(char *msg, size_t cap, int e, const char *fmt, const char *what)
{
    if (msg && cap)
        snprintf(msg, cap, fmt, what);
    errno = e;
    return HOL_EARG;
}

/* The folder path is in (".", "/", or up to its last '/'): it must exist
 * and be writable (the temporary file and the rename need both). */
static hol_err hol__check_folder(const char *path, char *msg, size_t cap)
{
    const char *slash = strrchr(path, '/');
    char *dir = strdup(slash ? path : ".");
    if (!dir)
        return hol__refuse(msg, cap, ENOMEM, "%s", "cannot be checked (out of memory)");
    if (slash)
        dir[slash == path ? 1 : slash - path] = 0;
    struct stat st;
    hol_err err = HOL_OK;
    if (stat(dir, &st) != 0)
        err = hol__refuse(msg, cap, ENOENT, "%s", "is in a folder that does not exist");
    else if (!S_ISDIR(st.st_mode))
        err = hol__refuse(msg, cap, ENOTDIR, "%s", "is under a file, not a folder");
    else if (access(dir, W_OK | X_OK) != 0)
        err = hol__refuse(msg, cap, EACCES, "%s", "is in a folder this user cannot write");
    free(dir);
    return err;
}

hol_err hol_file_check_out(const char *path, char *msg, size_t cap)
{
    size_t n = strlen(path);
    if (n == 0)
        return hol__refuse(msg, cap, ENOENT, "%s", "is an empty name");
    if (path[n - 1] == '/')
        return hol__refuse(msg, cap, EISDIR, "%s", "names a folder (it ends in '/')");
    struct stat lst, st;
    if (lstat(path, &lst) == 0) {
        if (S_ISLNK(lst.st_mode)) {
            if (stat(path, &st) != 0)
                return hol__refuse(msg, cap, EEXIST, "%s", errno == ELOOP
                                   ? "is a symbolic link loop"
                                   : "is a symbolic link to nothing");
            if (!S_ISREG(st.st_mode))
                return hol__refuse(msg, cap, S_ISDIR(st.st_mode) ? EISDIR : EEXIST,
                                   "is a symbolic link to %s", hol__kind(st.st_mode));
        } else if (!S_ISREG(lst.st_mode)) {
            return hol__refuse(msg, cap, S_ISDIR(lst.st_mode) ? EISDIR : EEXIST,
                               "is %s", hol__kind(lst.st_mode));
        }
    } else if (errno == ENOTDIR) {
        return hol__refuse(msg, cap, ENOTDIR, "%s", "is under a file, not a folder");
    } else if (errno == ENAMETOOLONG) {
        return hol__refuse(msg, cap, ENAMETOOLONG, "%s", "is too long a name");
    } else if (errno != ENOENT) {
        int e = errno;
        return hol__refuse(msg, cap, e, "cannot be checked: %s", strerror(e));
    }
    return hol__check_folder(path, msg, cap);
}

/* At the rename: path is still a new name, a regular file or a symbolic
 * link to one (else errno EEXIST, or lstat's). */
static int hol__replaceable(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return errno == ENOENT;
    if (S_ISLNK(st.st_mode) && stat(path, &st) != 0) {
        errno = EEXIST;
        return 0;
    }
    if (!S_ISREG(st.st_mode))
        errno = EEXIST;
    return S_ISREG(st.st_mode);
}

hol_err hol_file_atomic_open(hol_file_atomic *a, const char *path)
{
    size_t n = strlen(path);
    a->f = NULL;
    a->tmp = NULL;
    a->path = path;
    hol_err cerr = hol_file_check_out(path, NULL, 0);
    if (cerr)
        return cerr;
    hol__clean_leftovers(path);
    a->tmp = malloc(n + 64);
    if (!a->tmp)
        return HOL_ENOMEM;
    const char *slash = strrchr(path, '/');
    size_t dl = slash ? (size_t)(slash - path) + 1 : 0;
    memcpy(a->tmp, path, dl);
    snprintf(a->tmp + dl, n + 64 - dl, ".%s" HOL__TMP_TAG "%ld.XXXXXX", path + dl,
             (long)getpid());
    int fd = mkstemp(a->tmp);
    if (fd >= 0) {
        /* mkstemp makes 0600; give the usual permissions */
        mode_t um = umask(0);
        umask(um);
        (void)fchmod(fd, 0666 & ~um);
        a->f = fdopen(fd, "wb");
        if (!a->f) {
            int e = errno;
            close(fd);
            unlink(a->tmp);
            errno = e;
        }
    }
    if (!a->f) {
        free(a->tmp);
        a->tmp = NULL;
        return HOL_EIO;
    }
    return HOL_OK;
}

void hol_file_atomic_abort(hol_file_atomic *a)
{
    if (a->f) {
        int e = errno;
        fclose(a->f);
        unlink(a->tmp);
        errno = e;
    }
    free(a->tmp);
    a->f = NULL;
    a->tmp = NULL;
}

static void hol__fsync_dir(const char *path)
{
    char *dir = strdup(path);
    if (!dir)
        return;
    char *slash = strrchr(dir, '/');
    const char *d = ".";
    if (slash) {
        *slash = '\0';
        d = slash == dir ? "/" : dir;
    }
    int dfd = open(d, O_RDONLY | O_DIRECTORY);
    if (dfd >= 0) {
        (void)fsync(dfd);
        close(dfd);
    }
    free(dir);
}

hol_err hol_file_atomic_commit(hol_file_atomic *a)
{
    int ok = !ferror(a->f) && fflush(a->f) == 0 && fsync(fileno(a->f)) == 0;
    int e = errno;
    if (fclose(a->f) != 0 && ok) {
        ok = 0;
        e = errno;
    }
    a->f = NULL;
    hol_err err = HOL_EIO;
    if (ok && !hol__replaceable(a->path)) {
        ok = 0;
        e = errno;
        err = HOL_EARG; /* never rename over a device node or a FIFO */
    }
    if (ok && rename(a->tmp, a->path) != 0) {
        ok = 0;
        e = errno;
    }
    if (!ok)
        unlink(a->tmp);
    free(a->tmp);
    a->tmp = NULL;
    if (!ok) {
        errno = e;
        return err;
    }
    hol__fsync_dir(a->path);
    return HOL_OK;
}

hol_err hol_file_write_atomic(const char *path, const void *data, size_t size)
{
    hol_file_atomic a;
    hol_err err = hol_file_atomic_open(&a, path);
    if (err)
        return err;
    if (size && fwrite(data, 1, size, a.f) != size) {
        hol_file_atomic_abort(&a);
        return HOL_EIO;
    }
    return hol_file_atomic_commit(&a);
}

hol_err hol_file_open_in(const char *path, hol_file_in *out)
{
    out->fd = -1;
    out->size = 0;
    /* non-blocking, so that a FIFO cannot hang the open */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return HOL_EOPEN;
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        return HOL_EIO;
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        errno = S_ISDIR(st.st_mode) ? EISDIR : EINVAL;
        return HOL_EARG;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0)
        (void)fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    out->fd = fd;
    out->size = (uint64_t)st.st_size;
    return HOL_OK;
}

hol_err hol_file_read_in(hol_file_in *f, void *buf, size_t n, size_t *out_got)
{
    size_t got = 0;
    while (got < n) {
        ssize_t r = read(f->fd, (uint8_t *)buf + got, n - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            return HOL_EIO;
        if (r == 0)
            break;
        got += (size_t)r;
    }
    *out_got = got;
    return HOL_OK;
}

void hol_file_close_in(hol_file_in *f)
{
    if (f->fd >= 0) {
        int e = errno;
        close(f->fd);
        errno = e;
    }
    f->fd = -1;
}

hol_err hol_file_read_all(const char *path, size_t max, uint8_t **out_data,
                          size_t *out_size)
{
    hol_file_in f;
    hol_err err = hol_file_open_in(path, &f);
    if (err)
        return err;
    /* the size first: a file larger than max is refused without reading it */
    if (f.size > (uint64_t)max) {
        hol_file_close_in(&f);
        return HOL_ECORRUPT;
    }
    size_t cap = (size_t)f.size + 1; /* one more: a file that grew is caught */
    uint8_t *buf = malloc(cap + 1);
    if (!buf) {
        hol_file_close_in(&f);
        return HOL_ENOMEM;
    }
    size_t n = 0;
    err = hol_file_read_in(&f, buf, cap, &n);
    hol_file_close_in(&f);
    if (!err && n > max)
        err = HOL_ECORRUPT;
    if (err) {
        free(buf);
        return err;
    }
    *out_data = buf;
    *out_size = n;
    return HOL_OK;
}
