/* hol_file.h - whole-file reads and atomic writes for the desktop tools.
 *
 * Contract
 * - hol_file_write_atomic and hol_file_atomic_* never leave a half-written
 *   file: the data goes to a temporary file next to PATH, named
 *   ".BASE.holonomy-tmp.PID.XXXXXX" (hidden; the target's name and the
 *   writer's process id), is flushed, fsync'ed and closed, gets the usual
 *   0666 & ~umask mode, is renamed over PATH, and the folder is fsync'ed
 *   (best effort). On any failure the temporary file is removed and PATH is
 *   left as it was. A save killed mid-write (kill -9) leaves its temporary
 *   file; the next save into the same folder removes every such file there
 *   whose writer no longer runs on this machine (and nothing else), and
 *   says so in one line on stderr (hol_file_clean_dir).
 * - hol_file_clean_dir(DIR) is that cleaning on its own (`play`, `replay`
 *   and `xr` run it on their --log folder): it returns how many files it
 *   removed and prints "holonomy: removed N temporary file(s) left in
 *   'DIR' by writers that no longer run" when N > 0.
 * - Output targets (every save, recording, log file, PNG, id list):
 *   hol_file_check_out accepts an existing regular file (also through a
 *   symbolic link) or a name that does not exist yet in an existing folder
 *   this process may write in, and refuses anything else - a device node,
 *   a FIFO, a socket, a directory, a symbolic link to one of those or to
 *   nothing, a name ending in '/', a missing or unwritable folder - with
 *   HOL_EARG and the reason in words in msg ("is a FIFO", ...; it follows
 *   the quoted path in a message). Commands call it for every output
 *   before any work. hol_file_atomic_open checks the same (HOL_EARG), and
 *   hol_file_atomic_commit never renames over anything but a regular file
 *   or a symbolic link to one (if the target changed kind meanwhile: HOL_EARG,
 *   errno EEXIST, the temporary file removed): a save never replaces a
 *   device node or a FIFO, even when raced.
 * - Errors are hol_err; errno still holds the cause for messages.
 * - Reading never hangs and never reads more than asked: hol_file_open_in
 *   opens only regular files (a FIFO, a directory or a device is HOL_EARG,
 *   at once: the open does not block), and reports the size first.
 *   hol_file_read_all reads at most `max` bytes into a malloc'ed buffer
 *   (free it with free()); a file larger than max is HOL_ECORRUPT before
 *   anything is read, a file that cannot be opened HOL_EOPEN, a failed read
 *   HOL_EIO.
 */
#ifndef HOL_FILE_H
#define HOL_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "../../core/hol_err.h"

/* HOL_OK when path may be written as an output (see the contract), else
 * HOL_EARG with the reason in msg (cap bytes, NUL-terminated; msg may be
 * NULL). */
hol_err hol_file_check_out(const char *path, char *msg, size_t cap);

hol_err hol_file_write_atomic(const char *path, const void *data, size_t size);
int hol_file_clean_dir(const char *dir);

/* Streaming form: open, write to a->f, then commit (or abort). */
typedef struct hol_file_atomic {
    FILE *f;
    char *tmp;
    const char *path;
} hol_file_atomic;

hol_err hol_file_atomic_open(hol_file_atomic *a, const char *path);
hol_err hol_file_atomic_commit(hol_file_atomic *a);
void hol_file_atomic_abort(hol_file_atomic *a);

hol_err hol_file_read_all(const char *path, size_t max, uint8_t **out_data,
                          size_t *out_size);

/* Piecewise reading (a header first): open a regular file, read up to n
 * bytes at a time (fewer only at the end), close. */
typedef struct hol_file_in {
    int fd;
    uint64_t size; /* at open */
} hol_file_in;

hol_err hol_file_open_in(const char *path, hol_file_in *out);
hol_err hol_file_read_in(hol_file_in *f, void *buf, size_t n, size_t *out_got);
void hol_file_close_in(hol_file_in *f);

#endif
