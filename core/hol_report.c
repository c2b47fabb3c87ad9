/* hol_report.c - research logs read back by column name (hol_report.h). */
#include "hol_report.h"

#include <stdio.h>
#include <string.h>

#include "hol_room.h"
#include "hol_text.h"

/* Column names the report reads; their index in hol_report_header.col. */
enum {
    C_SESSION, C_PARTICIPANT, C_ATTEMPT, C_STUDY, C_CONDITION, C_POSITION, C_LEVEL,
    C_SHA, C_MODE, C_STEPS, C_OPTIMUM, C_TIME, C_END, C_TILING, C_ROOM, C_CELL,
    S_STEP, S_COL, S_ROW, S_DIR, S_TILE, S_ORIENT, C_CUES, C_SESSION_NO, C_COUNT
};
static const char *const col_names[C_COUNT] = {
    "session", "participant", "attempt", "study", "condition", "position", "level",
    "level_sha256", "mode", "steps", "optimum", "time", "end", "tiling", "room", "cell",
    "step", "col", "row", "dir", "tile", "orient", "cues", "session_no"};

static void set_err(char *err, const char *msg, const char *col)
{
    if (err)
        snprintf(err, HOL_REPORT_ERR, "%s%s%s%s", col ? "column " : "", col ? col : "",
                 col ? ": " : "", msg);
}

hol_err hol_report_csv_split(const char *s, size_t len, char *buf, size_t cap,
                             const char **f, int max, int *out_n, char *err)
{
    size_t i = 0, o = 0;
    int n = 0;
    for (;;) {
        if (n == max) {
            set_err(err, "more fields than the report reads", NULL);
            return HOL_ENOMEM;
        }
        f[n++] = buf + o;
        if (i < len && s[i] == '"') {
            for (i++;; i++) {
                if (i >= len) {
                    set_err(err, "a quoted field without its closing quote", NULL);
                    return HOL_EPARSE;
                }
                if (s[i] == '"') {
                    if (i + 1 < len && s[i + 1] == '"')
                        i++;
                    else
                        break;
                }
                if (!s[i] || o + 1 >= cap) {
                    set_err(err, s[i] ? "a line too long" : "a NUL byte", NULL);
                    return s[i] ? HOL_ENOMEM : HOL_EPARSE;
                }
                buf[o++] = s[i];
            }
            i++;
            if (i < len && s[i] != ',') {
                set_err(err, "text after a quoted field", NULL);
                return HOL_EPARSE;
            }
        } else {
            for (; i < len && s[i] != ','; i++) {
                if (s[i] == '"' || !s[i] || o + 1 >= cap) {
                    set_err(err, s[i] == '"' ? "a double quote in a bare field"
                                 : s[i]       ? "a line too long" : "a NUL byte", NULL);
                    return s[i] == '"' || !s[i] ? HOL_EPARSE : HOL_ENOMEM;
                }
                buf[o++] = s[i];
            }
        }
        if (o >= cap) {
            set_err(err, "a line too long", NULL);
            return HOL_ENOMEM;
        }
        buf[o++] = 0;
        if (i >= len)
            break;
        i++; /* the comma */
    }
    *out_n = n;
    return HOL_OK;
}

/* Map a header line; the columns in need[] (indices into col_names, ending
 * with -1) must be there. */
static hol_err read_header(const char *s, size_t len, const int *need, hol_report_header *out,
                           char *err)
{
    char buf[HOL_REPORT_LINE_MAX + 1];
    const char *f[HOL_REPORT_MAX_COLS];
    int n;
    if (len > HOL_REPORT_LINE_MAX) {
        set_err(err, "a line too long", NULL);
        return HOL_ENOMEM;
    }
    hol_err e = hol_report_csv_split(s, len, buf, sizeof buf, f, HOL_REPORT_MAX_COLS, &n, err);
    if (e)
        return e;
    hol_report_header h;
    h.ncols = n;
    for (int c = 0; c < C_COUNT; c++) {
        h.col[c] = -1;
        for (int i = 0; i < n; i++)
            if (!strcmp(f[i], col_names[c]) && h.col[c] < 0)
                h.col[c] = i;
    }
    for (; *need >= 0; need++)
        if (h.col[*need] < 0) {
            set_err(err, "missing from the header", col_names[*need]);
            return HOL_EPARSE;
        }
    *out = h;
    return HOL_OK;
}

hol_err hol_report_summary_header(const char *s, size_t len, hol_report_header *out,
                                  char *err)
{
    static const int need[] = {C_SESSION, C_ATTEMPT, C_LEVEL, C_MODE, C_STEPS,
                               C_OPTIMUM, C_TIME, C_END, -1};
    return read_header(s, len, need, out, err);
}

hol_err hol_report_steps_header(const char *s, size_t len, hol_report_header *out,
                                char *err)
{
    static const int need[] = {C_SESSION, C_ATTEMPT, S_STEP, S_COL, S_ROW, S_DIR,
                               S_TILE, S_ORIENT, -1};
    return read_header(s, len, need, out, err);
}

/* A decimal integer in [lo, hi]. */
static int parse_long(const char *s, long lo, long hi, long *out)
{
    int neg = *s == '-';
    const char *p = s + neg;
    long v = 0;
    if (!*p)
        return 0;
    for (; *p; p++) {
        if (*p < '0' || *p > '9' || v > (hi + 1) / 10 + 1)
            return 0;
        v = v * 10 + (*p - '0');
    }
    v = neg ? -v : v;
    if (v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

/* A plain decimal [-]D[.D] (no exponent, at most 15 digits, at most 1e9):
 * the digits as an integer divided by a power of ten, both exact, so the
 * result is the double nearest the text (as strtod gives it). */
static int parse_decimal(const char *s, double *out)
{
    int neg = *s == '-', digits = 0;
    const char *p = s + neg;
    double v = 0, scale = 1;
    for (; *p >= '0' && *p <= '9'; p++, digits++)
        v = v * 10 + (*p - '0');
    if (*p == '.')
        for (p++; *p >= '0' && *p <= '9'; p++, digits++) {
            v = v * 10 + (*p - '0');
            scale *= 10;
        }
    if (*p || !digits || digits > 15 || v / scale > 1e9)
        return 0;
    *out = neg ? -(v / scale) : v / scale;
    return 1;
}

typedef struct row_ctx {
    const hol_report_header *h;
    const char *const *f;
    char *err;
} row_ctx;

/* Field of column c ("" when the column is absent or the row short). */
static const char *field(const row_ctx *r, int c)
{
    int i = r->h->col[c];
    return i >= 0 ? r->f[i] : "";
}

static int copy_text(const row_ctx *r, int c, char *out)
{
    const char *v = field(r, c);
    size_t n = strlen(v);
    if (n >= HOL_REPORT_TEXT) {
        set_err(r->err, "longer than 255 bytes", col_names[c]);
        return 0;
    }
    memcpy(out, v, n + 1);
    return 1;
}

static int get_long(const row_ctx *r, int c, long lo, long hi, long *out)
{
    if (parse_long(field(r, c), lo, hi, out))
        return 1;
    set_err(r->err, "not a whole number in range", col_names[c]);
    return 0;
}

static int geometry(const row_ctx *r, hol_report_attempt *a)
{
    const char *t = field(r, C_TILING), *m = field(r, C_ROOM), *c = field(r, C_CELL);
    a->tiling_q = 5;
    a->room_cols = a->room_rows = 3;
    a->cell_m = 1;
    if (*t && hol_room_parse_tiling(t, strlen(t), &a->tiling_q)) {
        set_err(r->err, "not a tiling 4,Q (Q 4..8)", "tiling");
        return 0;
    }
    if (*m && hol_room_parse_size(m, strlen(m), &a->room_cols, &a->room_rows)) {
        set_err(r->err, "not a room CxR (3..5 each)", "room");
        return 0;
    }
    if (*c && (!parse_decimal(c, &a->cell_m) || a->cell_m < 0.5 || a->cell_m > 1.5)) {
        set_err(r->err, "not a cell size 0.5..1.5", "cell");
        return 0;
    }
    return 1;
}

static int fill_attempt(const row_ctx *r, hol_report_attempt *a)
{
    static const int texts[] = {C_SESSION, C_PARTICIPANT, C_STUDY, C_CONDITION,
                                C_LEVEL, C_SHA, C_MODE, C_END};
    char *dst[] = {a->session, a->participant, a->study, a->condition,
                   a->level, a->level_sha256, a->mode, a->end};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++)
        if (!copy_text(r, texts[i], dst[i]))
            return 0;
    if (!*a->end) {
        set_err(r->err, "empty", "end");
        return 0;
    }
    a->position = -1;
    if (*field(r, C_POSITION) && !get_long(r, C_POSITION, 0, 1000000, &a->position))
        return 0;
    a->cues = -1;
    if (*field(r, C_CUES) && !get_long(r, C_CUES, 0, 65535, &a->cues))
        return 0;
    a->session_no = -1;
    if (*field(r, C_SESSION_NO) && !get_long(r, C_SESSION_NO, 1, 999, &a->session_no))
        return 0;
    if (!get_long(r, C_ATTEMPT, 1, 999999999, &a->attempt) ||
        !get_long(r, C_STEPS, 0, 999999999, &a->steps) ||
        !get_long(r, C_OPTIMUM, -1, 999999999, &a->optimum))
        return 0;
    if (!parse_decimal(field(r, C_TIME), &a->time_s) || a->time_s < 0) {
        set_err(r->err, "not a time in seconds", "time");
        return 0;
    }
    return geometry(r, a);
}

static hol_err split_row(const hol_report_header *h, const char *s, size_t len, char *buf,
                         size_t cap, const char **f, char *err)
{
    int n;
    if (len > HOL_REPORT_LINE_MAX) {
        set_err(err, "a line too long", NULL);
        return HOL_ENOMEM;
    }
    hol_err e = hol_report_csv_split(s, len, buf, cap, f, HOL_REPORT_MAX_COLS, &n, err);
    if (e)
        return e;
    if (n != h->ncols) {
        if (err)
            snprintf(err, HOL_REPORT_ERR, "%d fields where the header has %d", n, h->ncols);
        return HOL_EPARSE;
    }
    return HOL_OK;
}

/* A summary row's fields into *out (void: read_row's fill), whole or not
 * at all: 1 ok. */
static int fill_summary(const row_ctx *r, void *out)
{
    hol_report_attempt tmp;
    memset(&tmp, 0, sizeof tmp);
    if (!fill_attempt(r, &tmp))
        return 0;
    *(hol_report_attempt *)out = tmp;
    return 1;
}

/* A steps row's fields into *out, likewise. */
static int fill_step(const row_ctx *r, void *out)
{
    hol_report_step st;
    long col, row, orient;
    memset(&st, 0, sizeof st);
    if (!copy_text(r, C_SESSION, st.session) || !copy_text(r, S_TILE, st.tile) ||
        !get_long(r, C_ATTEMPT, 1, 999999999, &st.attempt) ||
        !get_long(r, S_STEP, 1, 999999999, &st.step) ||
        !get_long(r, S_COL, 0, HOL_ROOM_MAX_SIDE - 1, &col) ||
        !get_long(r, S_ROW, 0, HOL_ROOM_MAX_SIDE - 1, &row) ||
        !get_long(r, S_ORIENT, 0, 3, &orient))
        return 0;
    const char *d = field(r, S_DIR);
    st.dir = d[0] && !d[1] ? hol_dir_from_char(d[0]) : -1;
    if (st.dir < 0) {
        set_err(r->err, "not a direction N, E, S or W", "dir");
        return 0;
    }
    st.col = (int)col;
    st.row = (int)row;
    st.orient = (int)orient;
    *(hol_report_step *)out = st;
    return 1;
}

/* A row split against the header, then its fields filled into *out. */
static hol_err read_row(const hol_report_header *h, const char *s, size_t len, char *err,
                        int (*fill)(const row_ctx *r, void *out), void *out)
{
    char buf[HOL_REPORT_LINE_MAX + 1]; /* the fields fit: at most len + 1 bytes */
    const char *f[HOL_REPORT_MAX_COLS];
    hol_err e = split_row(h, s, len, buf, sizeof buf, f, err);
    if (e)
        return e;
    row_ctx r = {h, f, err};
    return fill(&r, out) ? HOL_OK : HOL_EPARSE;
}

hol_err hol_report_summary_row(const hol_report_header *h, const char *s, size_t len,
                               hol_report_attempt *out, char *err)
{
    return read_row(h, s, len, err, fill_summary, out);
}

hol_err hol_report_step_row(const hol_report_header *h, const char *s, size_t len,
                            hol_report_step *out, char *err)
{
    return read_row(h, s, len, err, fill_step, out);
}

double hol_report_efficiency(const hol_report_attempt *a)
{
    if (strcmp(a->end, "done") || a->optimum < 0 || a->steps < a->optimum)
        return -1;
    if (a->steps == 0)
        return 1;
    return (double)a->optimum / (double)a->steps;
}

size_t hol_report_clean(const char *s, char *out, size_t cap)
{
    size_t need = 0, o = 0; /* o: bytes written while everything fitted */
    int whole = 1;
    for (;;) {
        const char *b = strchr(s, '\\');
        size_t k = b ? (size_t)(b - s) : strlen(s);
        size_t room = whole && cap > o ? cap - o : 0;
        size_t n = hol_text_escape(s, k, room ? out + o : NULL, room);
        if (whole && n < room)
            o += n;
        else if (whole && room)
            o += strlen(out + o), whole = 0; /* cut inside this piece */
        else
            whole = 0;
        need += n;
        if (!b)
            break;
        if (whole && o + 1 < cap)
            out[o++] = '\\';
        else
            whole = 0;
        need++;
        s = b + 1;
    }
    if (cap > 0)
        out[o < cap ? o : cap - 1] = 0;
    return need;
}

void hol_report_agg_init(hol_report_agg *g, hol_report_cond *conds, int cap)
{
    g->n = 0;
    g->cap = cap;
    g->overflow = 0;
    g->c = conds;
}

void hol_report_agg_add(hol_report_agg *g, const hol_report_attempt *a)
{
    const char *cond = a->study[0] ? a->condition : a->level;
    int i;
    for (i = 0; i < g->n; i++)
        if (!strcmp(g->c[i].study, a->study) && !strcmp(g->c[i].condition, cond))
            break;
    if (i == g->n) {
        if (g->n == g->cap) {
            g->overflow++;
            return;
        }
        memset(&g->c[i], 0, sizeof g->c[i]);
        memcpy(g->c[i].study, a->study, sizeof g->c[i].study);
        snprintf(g->c[i].condition, sizeof g->c[i].condition, "%s", cond);
        g->n++;
    }
    hol_report_cond *c = &g->c[i];
    double e = hol_report_efficiency(a);
    c->n++;
    c->done += !strcmp(a->end, "done");
    c->steps += (double)a->steps;
    c->time_s += a->time_s;
    if (e >= 0) {
        c->neff++;
        c->eff += e;
    }
}
