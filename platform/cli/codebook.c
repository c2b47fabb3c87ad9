/* codebook.c - codebook.csv's text: the log folder's from the writers'
 * tables (the shell's), the report's from its table (codebook.h). */
#include "codebook.h"

#include <stdio.h>
#include <string.h>

#include "codebook_table.h"

#define NROWS (sizeof codebook_rows / sizeof codebook_rows[0])
static const char report_prefix[] = "report:";

/* The meaning of a report column left empty: the log column's of that name. */
static const char *meaning_of(const codebook_row *r)
{
    int nf;
    const hol_codebook_file *f = hol_shell_codebook_logs(&nf);
    for (int i = 0; !r->meaning[0] && i < nf; i++)
        for (int c = 0; c < f[i].n; c++)
            if (!strcmp(f[i].cols[c].column, r->column) && f[i].cols[c].meaning[0])
                return f[i].cols[c].meaning;
    return r->meaning;
}

size_t codebook_csv(int which, char *out, size_t cap)
{
    if (which == CODEBOOK_LOGS)
        return hol_shell_codebook_csv(out, cap);
    if (cap < sizeof CODEBOOK_COLUMNS + 1)
        return 0;
    size_t at = (size_t)snprintf(out, cap, "%s\n", CODEBOOK_COLUMNS);
    for (size_t i = 0; i < NROWS; i++) {
        const codebook_row *r = &codebook_rows[i];
        if (strncmp(r->file, report_prefix, sizeof report_prefix - 1))
            continue;
        const hol_codebook_col c = {r->column, r->type, r->unit, r->allowed, meaning_of(r)};
        if (hol_shell_codebook_put(r->file + sizeof report_prefix - 1, &c, out, cap, &at))
            return 0;
    }
    return at;
}

int codebook_header(const char *file, char *out, size_t cap)
{
    int n = 0;
    size_t at = 0;
    if (strncmp(file, report_prefix, sizeof report_prefix - 1))
        return hol_shell_codebook_header(file, out, cap);
    out[0] = 0;
    for (size_t i = 0; i < NROWS; i++) {
        if (strcmp(codebook_rows[i].file, file))
            continue;
        int w = snprintf(out + at, cap - at, "%s%s", n ? "," : "", codebook_rows[i].column);
        if (w < 0 || (size_t)w >= cap - at)
            return 0;
        at += (size_t)w;
        n++;
    }
    return n;
}
