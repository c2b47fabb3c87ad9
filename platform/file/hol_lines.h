/* hol_lines.h - a file read a line at a time: streamed and bounded, so
 * memory stays flat and a bad file is refused at its first bad line
 * (recordings, --input files).
 *
 * Contract
 * - hol_lines_open opens a regular file only (hol_file_open_in: a FIFO, a
 *   folder or a device is HOL_EARG at once, a missing file HOL_EOPEN).
 *   hol_lines_open_fd reads an open descriptor (standard input of the line
 *   commands: a pipe, a terminal, a file), which hol_lines_close leaves
 *   open; a read returns the lines as they arrive (no waiting for more).
 * - hol_lines_next gives the next line without its LF (and without one CR
 *   before it), NUL-terminated in the reader's buffer (valid until the
 *   next call; it may hold NUL bytes, which callers refuse): 1 a line, 0 the
 *   end (a last line without LF is a line, with l->cut set: a reader of
 *   records that must be whole can tell it). -1 on failure with l->err:
 *   HOL_ENOMEM a line longer than the limit (refused when limit + 1 bytes
 *   without LF have been read, not after the whole line), HOL_EIO a read
 *   failure. l->lineno counts the lines given (1-based), the failing one
 *   included.
 * - Memory: the limit plus a 64 KiB read buffer, allocated at open (malloc)
 *   and freed at close; nothing else.
 */
#ifndef HOL_LINES_H
#define HOL_LINES_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_err.h"

typedef struct hol_lines {
    int fd;
    size_t limit;
    char *line;           /* limit + 2 bytes */
    uint8_t *buf;         /* read buffer */
    size_t pos, end;      /* unread bytes in buf */
    int eof;
    int cut; /* the last line given had no LF (the file's end cut it) */
    long lineno;
    hol_err err;
    int own_fd; /* hol_lines_close closes fd */
} hol_lines;

hol_err hol_lines_open(hol_lines *l, const char *path, size_t limit);
hol_err hol_lines_open_fd(hol_lines *l, int fd, size_t limit);
int hol_lines_next(hol_lines *l, char **out_s, size_t *out_len);
void hol_lines_close(hol_lines *l);

#endif
