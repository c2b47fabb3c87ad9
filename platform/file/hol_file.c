#define _POSIX_C_SOURCE 200809L
#include "hol_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>


hol_err hol_file_atomic_open(hol_file_atomic *a, const char *path)
{
    size_t n = strlen(path);
    a->f = NULL;
    a->path = path;
    a->tmp = malloc(n + 16);
    if (!a->tmp)
        return HOL_ENOMEM;
    memcpy(a->tmp, path, n);
    memcpy(a->tmp + n, ".tmpXXXXXX", 11);
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
        return HOL_EIO;
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

hol_err hol_file_read_all(const char *path, size_t max, uint8_t **out_data,
                          size_t *out_size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return HOL_EOPEN;
    uint8_t *buf = NULL;
    size_t n = 0, cap = 0;
    hol_err err = HOL_OK;
    for (;;) {
        if (n == cap) {
            if (cap > max) {
                err = HOL_ECORRUPT;
                break;
            }
            cap = cap ? cap * 2 : 65536;
            uint8_t *nb = realloc(buf, cap + 1);
            if (!nb) {
                err = HOL_ENOMEM;
                break;
            }
            buf = nb;
        }
        size_t r = fread(buf + n, 1, cap - n, f);
        n += r;
        if (r == 0)
            break;
    }
    if (!err && ferror(f))
        err = HOL_EIO;
    if (!err && n > max)
        err = HOL_ECORRUPT;
    int e = errno;
    fclose(f);
    errno = e;
    if (err) {
        free(buf);
        return err;
    }
    *out_data = buf;
    *out_size = n;
    return HOL_OK;
}
