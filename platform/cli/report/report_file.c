/* report_file.c - a file of the report written atomically (report.h:
 * report_write_file); the writers of report_write.c and report_stats.c
 * call it, it calls none of them. */
#include <stdio.h>

#include "../../file/hol_file.h"
#include "../cli.h"
#include "../codebook.h"
#include "report.h"

void report_header(FILE *f, const char *name)
{
    char key[96], line[1024];
    snprintf(key, sizeof key, "report:%s", name);
    if (codebook_header(key, line, sizeof line) > 0)
        fprintf(f, "%s\n", line);
}

int report_write_file(const report_run *r, const char *name, report_body body, const void *ctx)
{
    return report_write_in(r, r->out, name, body, ctx);
}

int report_write_files(const report_run *r, const report_file_job *jobs, int n)
{
    int st = 0;
    for (int i = 0; !st && i < n; i++)
        st = report_write_file(r, jobs[i].name, jobs[i].body, NULL);
    return st;
}

int report_write_in(const report_run *r, const char *dir, const char *name, report_body body,
                    const void *ctx)
{
    hol_file_atomic a;
    char path[4700];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (hol_file_atomic_open(&a, path)) {
        cli_error(r->cmd, 0, "cannot write '%.300s'", path);
        return CLI_EXIT_FAIL;
    }
    int st = body(a.f, r, ctx);
    if (!st && !ferror(a.f) && !hol_file_atomic_commit(&a))
        return 0;
    if (a.f)
        hol_file_atomic_abort(&a);
    if (!st)
        cli_error(r->cmd, 0, "cannot write '%.300s'", path);
    return st ? st : CLI_EXIT_FAIL;
}
