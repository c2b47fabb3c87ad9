/* summary_read.c - summary.csv read back by every reader (summary_read.h). */
#include "summary_read.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"

int summary_bad_line(const char *cmd, const char *path, long line, const char *msg)
{
    /* cli_error escapes the whole message once (the path is raw here) */
    cli_error(cmd, 0, "%.300s: line %ld: %s", path, line, msg);
    return CLI_EXIT_USAGE;
}

int summary_csv_line(const hol_lines *l, char **s, size_t *n)
{
    if (l->lineno == 1 && *n >= 3 && !memcmp(*s, "\xef\xbb\xbf", 3)) {
        *s += 3;
        *n -= 3;
    }
    for (size_t i = 0; i < *n; i++)
        if ((*s)[i] != ' ' && (*s)[i] != '\t')
            return 1;
    return 0;
}

/* A symbolic link, or a name that is not a regular file, refused (2); a
 * missing one 3 (the caller decides); 0 a regular file. */
static int summary_kind(const char *cmd, const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? 3 : 0; /* the open says why */
    if (!S_ISLNK(st.st_mode))
        return 0; /* a FIFO or a folder: the open refuses it */
    cli_error(cmd, 0, "'%.300s' is a symbolic link, not a log file: the logs are never read "
              "or written through one; put the file itself there", path);
    return CLI_EXIT_USAGE;
}

int summary_read(const char *cmd, const char *path, int flags, summary_row_fn fn, void *ctx,
                 long *out_cut)
{
    *out_cut = 0;
    int st = summary_kind(cmd, path);
    if (st == 3 && (flags & SUMMARY_NONE_OK))
        return 0;
    hol_lines l;
    if ((st && st != 3) || (st = cli_open_lines(cmd, "summary", path, SUMMARY_LINE_MAX, &l)))
        return st;
    hol_report_header h;
    hol_report_attempt a;
    char err[HOL_REPORT_ERR], *s;
    size_t n;
    int got = 0, header = 0;
    while (!st && (got = hol_lines_next(&l, &s, &n)) > 0) {
        if (l.cut) { /* the row a kill cut: left out */
            *out_cut = l.lineno;
            break;
        }
        if (!summary_csv_line(&l, &s, &n))
            continue;
        hol_err e = header++ ? hol_report_summary_row(&h, s, n, &a, err)
                             : hol_report_summary_header(s, n, &h, err);
        if (e)
            st = summary_bad_line(cmd, path, l.lineno, err);
        else if (header > 1)
            st = fn(ctx, &a, l.lineno);
    }
    if (!st && got < 0)
        st = cli_lines_failed(cmd, "summary", path, &l);
    if (!st && !header && !(flags & SUMMARY_NONE_OK))
        st = summary_bad_line(cmd, path, 1, "empty: no header");
    hol_lines_close(&l);
    return st;
}
