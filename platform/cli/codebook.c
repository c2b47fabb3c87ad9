/* codebook.c - codebook.csv's text from the codebook's table (codebook.h). */
#include "codebook.h"

#include <stdio.h>
#include <string.h>

#include "../../core/hol_text.h"
#include "codebook_table.h"

#define NROWS (sizeof codebook_rows / sizeof codebook_rows[0])
static const char report_prefix[] = "report:";

/* The meaning of a report column left empty: the log column's of that name. */
static const char *meaning_of(const codebook_row *r)
{
    for (size_t i = 0; !r->meaning[0] && i < NROWS; i++)
        if (strncmp(codebook_rows[i].file, report_prefix, sizeof report_prefix - 1) &&
            !strcmp(codebook_rows[i].column, r->column) && codebook_rows[i].meaning[0])
            return codebook_rows[i].meaning;
    return r->meaning;
}

/* Appends s (quoted per RFC 4180 when it needs it) and sep at *at. */
static int put(char *out, size_t cap, size_t *at, const char *s, char sep)
{
    size_t n = hol_text_csv(s, strlen(s), out + *at, cap - *at);
    if (n + 2 > cap - *at)
        return 1;
    *at += n;
    out[(*at)++] = sep;
    out[*at] = 0;
    return 0;
}

size_t codebook_csv(int which, char *out, size_t cap)
{
    size_t at = 0;
    if (cap < sizeof CODEBOOK_COLUMNS + 1)
        return 0;
    at = (size_t)snprintf(out, cap, "%s\n", CODEBOOK_COLUMNS);
    for (size_t i = 0; i < NROWS; i++) {
        const codebook_row *r = &codebook_rows[i];
        int rep = !strncmp(r->file, report_prefix, sizeof report_prefix - 1);
        if (rep != (which == CODEBOOK_REPORT))
            continue;
        const char *f[6] = {rep ? r->file + sizeof report_prefix - 1 : r->file, r->column,
                            r->type, r->unit, r->allowed, meaning_of(r)};
        for (int k = 0; k < 6; k++)
            if (put(out, cap, &at, f[k], k < 5 ? ',' : '\n'))
                return 0;
    }
    return at;
}

int codebook_header(const char *file, char *out, size_t cap)
{
    int n = 0;
    size_t at = 0;
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
