/* hol_shell_codebook.c - the log folder's codebook.csv (hol_shell_codebook.h). */
#include "hol_shell_codebook.h"

#include <stdio.h>
#include <string.h>

#include "hol_shell_env.h"
#include "hol_shell_prov.h"

/* The tables as arrays (for the report's codebook and the tests). */
#define COLS_OF(TABLE) ((const hol_codebook_col[]){TABLE(HOL_CODEBOOK_COL, )})
#define FILE_OF(name, TABLE) \
    {name, COLS_OF(TABLE), (int)(sizeof COLS_OF(TABLE) / sizeof(hol_codebook_col))},
static const hol_codebook_file files[] = {HOL_LOG_FILES(FILE_OF)};
#define NFILES ((int)(sizeof files / sizeof files[0]))

/* The tables as codebook.csv's text: a row's fields after its file, then
 * (the separator between two rows) the file again. */
#define ROW_TAIL(c, t, u, a, m) "," c "," t "," u ",\"" a "\",\"" m "\"\n"
#define FILE_TEXT(name, TABLE) name TABLE(ROW_TAIL, name)
static const char text[] = HOL_SHELL_CODEBOOK_COLUMNS "\n" HOL_LOG_FILES(FILE_TEXT);

const hol_codebook_file *hol_shell_codebook_logs(int *out_n)
{
    *out_n = NFILES;
    return files;
}

/* Appends s (quoted: in double quotes, a quote in it doubled) and sep at
 * *at. */
static int put(char *out, size_t cap, size_t *at, const char *s, int quoted, char sep)
{
    if (*at + 2 * strlen(s) + 4 > cap)
        return 1;
    if (quoted)
        out[(*at)++] = '"';
    for (; *s; s++) {
        if (quoted && *s == '"')
            out[(*at)++] = '"';
        out[(*at)++] = *s;
    }
    if (quoted)
        out[(*at)++] = '"';
    out[(*at)++] = sep;
    out[*at] = 0;
    return 0;
}

int hol_shell_codebook_put(const char *file, const hol_codebook_col *col, char *out, size_t cap,
                           size_t *at)
{
    const char *f[6] = {file, col->column, col->type, col->unit, col->allowed, col->meaning};
    for (int k = 0; k < 6; k++)
        if (put(out, cap, at, f[k], k >= 4, k < 5 ? ',' : '\n'))
            return 1;
    return 0;
}

size_t hol_shell_codebook_csv(char *out, size_t cap)
{
    if (cap < sizeof text)
        return 0;
    memcpy(out, text, sizeof text);
    return sizeof text - 1;
}

int hol_shell_codebook_header(const char *file, char *out, size_t cap)
{
    size_t at = 0;
    out[0] = 0;
    for (int i = 0; i < NFILES; i++) {
        if (strcmp(files[i].name, file))
            continue;
        for (int c = 0; c < files[i].n; c++) {
            int w = snprintf(out + at, cap - at, "%s%s", c ? "," : "", files[i].cols[c].column);
            if (w < 0 || (size_t)w >= cap - at)
                return 0;
            at += (size_t)w;
        }
        return files[i].n;
    }
    return 0;
}
