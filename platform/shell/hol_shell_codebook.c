/* hol_shell_codebook.c - the log folder's codebook.csv (hol_shell_codebook.h). */
#include "hol_shell_codebook.h"

#include <stdio.h>
#include <string.h>

#include "../../core/hol_text.h"
#include "hol_shell_env.h"
#include "hol_shell_prov.h"

#define COLS(name, table) static const hol_codebook_col name[] = {table(HOL_CODEBOOK_COL, )}
COLS(summary_cols, HOL_SESSION_SUMMARY_TABLE);
COLS(step_cols, HOL_SESSION_STEP_TABLE);
COLS(head_cols, HOL_SESSION_HEAD_TABLE);
COLS(track_cols, HOL_SESSION_TRACK_TABLE);
COLS(event_cols, HOL_SESSION_EVENT_TABLE);
COLS(point_cols, HOL_SESSION_POINT_TABLE);
COLS(answer_cols, HOL_SESSION_ANSWER_TABLE);
COLS(env_cols, HOL_SHELL_ENV_TABLE);
COLS(prov_cols, HOL_SHELL_PROV_TABLE);
COLS(order_cols, HOL_SHELL_ORDER_TABLE);
COLS(codebook_cols, HOL_SHELL_CODEBOOK_TABLE);

#define FILE_OF(name, cols) {name, cols, (int)(sizeof cols / sizeof cols[0])}
static const hol_codebook_file files[] = {
    FILE_OF("summary.csv", summary_cols),         FILE_OF("steps-NNN.csv", step_cols),
    FILE_OF("head-NNN.csv", head_cols),           FILE_OF("track-NNN.csv", track_cols),
    FILE_OF("events.csv", event_cols),            FILE_OF("points.csv", point_cols),
    FILE_OF("answers.csv", answer_cols),          FILE_OF("environment.csv", env_cols),
    FILE_OF("provenance.csv", prov_cols),         FILE_OF("order.csv", order_cols),
    FILE_OF("codebook.csv", codebook_cols),
};
#define NFILES ((int)(sizeof files / sizeof files[0]))

const hol_codebook_file *hol_shell_codebook_logs(int *out_n)
{
    *out_n = NFILES;
    return files;
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

int hol_shell_codebook_put(const char *file, const hol_codebook_col *col, char *out, size_t cap,
                           size_t *at)
{
    const char *f[6] = {file, col->column, col->type, col->unit, col->allowed, col->meaning};
    for (int k = 0; k < 6; k++)
        if (*at >= cap || put(out, cap, at, f[k], k < 5 ? ',' : '\n'))
            return 1;
    return 0;
}

size_t hol_shell_codebook_csv(char *out, size_t cap)
{
    static const char head[] = HOL_SHELL_CODEBOOK_COLUMNS "\n";
    if (cap < sizeof head)
        return 0;
    memcpy(out, head, sizeof head);
    size_t at = sizeof head - 1;
    for (int i = 0; i < NFILES; i++)
        for (int c = 0; c < files[i].n; c++)
            if (hol_shell_codebook_put(files[i].name, &files[i].cols[c], out, cap, &at))
                return 0;
    return at;
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
