/* hol_sink.h - where a session's files go: a platform's named byte streams.
 *
 * The session (hol_session.h) does no I/O. Each platform gives it sinks:
 * the POSIX one (platform/file/hol_sink_posix.h: a folder on the desktop,
 * the headset, Android's files directory) and the browser's (IndexedDB or
 * OPFS, offered as downloads). A sink is a flat folder of named streams; the
 * session decides every name, when bytes are written and when they must
 * survive, and keeps every policy (live journal files, renames, recovery of
 * a killed session) so that each sink stays a few lines over its storage.
 *
 * Contract (what a sink must do)
 * - Names are 1..255 bytes with no '/' and no NUL (the session makes them).
 *   Handles are ints >= 0 given out by open; the session keeps at most
 *   HOL_SINK_MAX_OPEN open at once, and closes each before it renames or
 *   reads that name.
 * - open(user, name, append, &h): append 0: a new, empty stream NAME (one of
 *   that name is replaced); append 1: NAME opened to add at its end (made
 *   empty if it does not exist).
 * - write(user, h, data, n): appends all n bytes, or fails. The bytes may
 *   sit in the sink's memory until flush.
 * - flush(user, h, durable): everything written to h so far survives the
 *   process ending now (kill -9, a closed tab) - durable 0 - and also a
 *   power loss (POSIX: fsync) - durable 1. The session flushes at least
 *   once per second of play, and durably when an attempt ends.
 * - close(user, h): forgets h (after the flushes the session asked for;
 *   unflushed bytes may be lost).
 * - rename(user, from, to): atomic: afterwards TO holds what FROM held and
 *   FROM is gone, or nothing changed; a TO that existed is replaced;
 *   durable on return.
 * - remove(user, name): NAME is gone (absent already: HOL_OK).
 * - read(user, name, off, buf, n, &got): up to n bytes from offset off;
 *   got < n only at the end. HOL_EOPEN when NAME does not exist.
 * - list(user, fn, ctx): calls fn(ctx, name) once for each stream (any
 *   order; names that the session did not make may be among them).
 * - why(user): optional (may be NULL): a short phrase for the last failure
 *   ("No space left on device"), for the session's one-line messages.
 * - Every call but why returns a hol_err: HOL_OK, HOL_EOPEN (cannot open or
 *   no such stream), HOL_EIO (any other failure), HOL_ENOMEM.
 * - zero = default: an all-zero hol_sink is not a usable sink; the session
 *   takes a NULL sink as "no logs" / "no recording".
 */
#ifndef HOL_SINK_H
#define HOL_SINK_H

#include <stddef.h>
#include <stdint.h>

#include "hol_err.h"

/* steps, head and track rows, a small file, and a recording on the same
 * sink (the web's) */
#define HOL_SINK_MAX_OPEN 5
#define HOL_SINK_NAME_MAX 256 /* with the NUL */

typedef struct hol_sink {
    void *user;
    hol_err (*open)(void *user, const char *name, int append, int *out_h);
    hol_err (*write)(void *user, int h, const void *data, size_t n);
    hol_err (*flush)(void *user, int h, int durable);
    hol_err (*close)(void *user, int h);
    hol_err (*rename)(void *user, const char *from, const char *to);
    hol_err (*remove)(void *user, const char *name);
    hol_err (*read)(void *user, const char *name, uint64_t off, void *buf, size_t n,
                    size_t *out_got);
    hol_err (*list)(void *user, void (*fn)(void *ctx, const char *name), void *ctx);
    const char *(*why)(void *user);
} hol_sink;

#endif
