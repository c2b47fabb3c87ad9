/* hol_shell_env.c - environment.csv's row (hol_shell_env.h). */
#include "hol_shell_env.h"

#include <stdio.h>
#include <string.h>

#include "../../core/hol_text.h"

typedef struct env_row {
    char *buf;
    size_t cap, n, field_max;
    int fields, over;
} env_row;

static void env_field(env_row *r, const char *s)
{
    char esc[HOL_SHELL_ENV_FIELD_MAX];
    s = s ? s : "";
    size_t e = hol_text_escape(s, strlen(s), esc, sizeof esc);
    size_t sep = r->fields++ ? 1 : 0;
    if (r->over || e >= r->field_max || r->n + sep >= r->cap) {
        r->over = 1;
        return;
    }
    size_t c = hol_text_csv(esc, e, r->buf + r->n + sep, r->cap - r->n - sep);
    if (c >= r->cap - r->n - sep) {
        r->over = 1;
        return;
    }
    if (sep)
        r->buf[r->n] = ',';
    r->n += sep + c;
}

static void env_int(env_row *r, int v)
{
    char s[16] = "";
    if (v)
        snprintf(s, sizeof s, "%d", v);
    env_field(r, s);
}

int hol_shell_env_row(const hol_shell_env_fields *f, size_t field_max, char *out, size_t cap,
                      size_t *out_len)
{
    env_row r = {out, cap, 0, field_max && field_max < HOL_SHELL_ENV_FIELD_MAX
                                  ? field_max : HOL_SHELL_ENV_FIELD_MAX, 0, cap == 0};
    if (cap)
        out[0] = 0;
    env_field(&r, f->session);
    env_field(&r, f->participant);
    env_int(&r, f->session_no);
    const char *s[] = {f->study_sha256, f->platform, f->os, f->runtime, f->gl_renderer,
                       f->controller};
    for (size_t i = 0; i < sizeof s / sizeof s[0]; i++)
        env_field(&r, s[i]);
    char hz[64] = "";
    if (f->refresh_hz > 0)
        snprintf(hz, sizeof hz, "%.3f", f->refresh_hz);
    env_field(&r, hz);
    env_int(&r, f->width);
    env_int(&r, f->height);
    env_field(&r, f->meta);
    env_field(&r, f->options);
    *out_len = r.n;
    return r.over;
}
