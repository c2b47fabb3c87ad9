/* hol_sink_posix.h - the session's sink (core/hol_sink.h) over a folder of
 * files: the desktop (`play`, `replay`, `xr`), the headset, and the
 * Android app's files directory.
 *
 * Contract
 * - hol_sink_posix_init binds p to an existing folder DIR (HOL_EOPEN when
 *   it is not one); &p->sink is the hol_sink to give the session. Streams
 *   are the folder's files (DIR/NAME).
 * - open refuses (HOL_EOPEN) a name that is there but not a regular file (a
 *   FIFO, a device, a folder), without blocking; files get 0666 & ~umask.
 *   write is write(2) straight away (no buffer of its own), so flush with
 *   durable 0 has nothing to do and everything written survives a kill -9;
 *   durable 1 is fsync. rename is rename(2) then an fsync of the folder.
 *   read opens, preads and closes. list reads the folder (not "." nor
 *   "..").
 * - why gives strerror of the last failure.
 * - stop (NULL after init): when set and it returns nonzero, read fails
 *   (HOL_EIO, why "stopped by a signal") before reading, so a long read of
 *   a stream (recovery of a huge live file) ends soon after a signal. The
 *   caller sets it only around such a read.
 * - hol_sink_posix_fini closes what is still open (nothing is flushed or
 *   renamed). Plain POSIX: no allocation, no globals; one sink per
 *   thread.
 * - hol_sink_posix_meta fills a session's metadata (core/hol_rec.h) from
 *   this machine: the start from the clock, in UTC, the id
 *   YYYYMMDDTHHMMSSZ-XXXXXXXX (8 random hex digits: sessions started in
 *   the same second differ), the participant given (NULL: none).
 * - hol_sink_posix_lock makes this sink the folder's one writer (`play`,
 *   `replay` and `xr` with --log take it before they read or write the
 *   folder): an flock(2) held on DIR/.holonomy-lock (HOL_SINK_POSIX_LOCK),
 *   which holds "pid PID on HOST" of its holder. HOL_OK: held until fini,
 *   which removes the file; *out_took is 1 when the file was there without
 *   a holder (its writer was killed: the kernel dropped its flock; holder
 *   then names that writer). HOL_EARG: another process holds it (holder
 *   names it, "pid PID on HOST"; the caller refuses to start). HOL_EOPEN:
 *   the file cannot be made or locked (errno says why). The file is hidden
 *   and is no log: the log readers (recovery, --resume, report) pass over
 *   it. A folder on a file system without locks is refused (HOL_EOPEN).
 * - hol_sink_posix_make_dir makes the folder DIR when it is missing and its
 *   parent exists (`--log DIR`): HOL_OK when DIR is a folder afterwards,
 *   HOL_EOPEN (errno says why) when it is something else or cannot be
 *   made.
 */
#ifndef HOL_SINK_POSIX_H
#define HOL_SINK_POSIX_H

#include "../../core/hol_rec.h"
#include "../../core/hol_sink.h"

typedef struct hol_sink_posix {
    hol_sink sink;
    char dir[4096];
    int fd[HOL_SINK_MAX_OPEN];
    char why[128];
    int (*stop)(void);
    int lock_fd; /* hol_sink_posix_lock's, -1 without */
} hol_sink_posix;

#define HOL_SINK_POSIX_LOCK ".holonomy-lock"

hol_err hol_sink_posix_init(hol_sink_posix *p, const char *dir);
void hol_sink_posix_fini(hol_sink_posix *p);
hol_err hol_sink_posix_lock(hol_sink_posix *p, char *holder, size_t cap, int *out_took);
hol_err hol_sink_posix_make_dir(const char *dir);
void hol_sink_posix_meta(hol_rec_meta *m, const char *participant);

#endif
