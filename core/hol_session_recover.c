/* hol_session_recover.c - a log folder's earlier files: a folder with logs
 * is refused without append; with append, every append-only log is cut to
 * its whole rows (a cut summary row's files removed with it), attempts a
 * killed session left unfinished get their summary row (end killed) and
 * their files, and the new attempts are numbered on (see hol_session.h). */
#include "hol_session_impl.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HOL__MAX_LIVE 64

typedef struct hol__scan {
    int logs;        /* a log file is there */
    int max_attempt; /* the highest attempt number named */
    int live[HOL__MAX_LIVE], nlive, too_many;
} hol__scan;

/* "PREFIX<digits>SUFFIX" -> the number, or -1. */
static long hol__numbered(const char *name, const char *prefix, const char *suffix)
{
    size_t pl = strlen(prefix), sl = strlen(suffix), n = strlen(name);
    if (n <= pl + sl || memcmp(name, prefix, pl) || strcmp(name + n - sl, suffix))
        return -1;
    long v = 0;
    for (size_t i = pl; i < n - sl; i++) {
        if (name[i] < '0' || name[i] > '9' || v > 99999999)
            return -1;
        v = v * 10 + (name[i] - '0');
    }
    return v;
}

/* the finished files first (HOL__PAT_DONE of them), then the live ones */
#define HOL__PAT_DONE 3
#define HOL__PAT_N 7
static const char *const hol__pat[HOL__PAT_N][2] = {
    {"steps-", ".csv"},      {"head-", ".csv"},      {"track-", ".csv"},
    {"steps-", ".csv.live"}, {"head-", ".csv.live"}, {"track-", ".csv.live"},
    {"attempt-", ".live"}};

int hol_session_is_log_name(const char *name)
{
    int hit = !strcmp(name, "summary.csv") || !strcmp(name, "events.csv") ||
              !strcmp(name, "points.csv") || !strcmp(name, "answers.csv") ||
              !strcmp(name, "tutorial.csv");
    for (int k = 0; k < HOL__PAT_N && !hit; k++)
        hit = hol__numbered(name, hol__pat[k][0], hol__pat[k][1]) >= 0;
    return hit;
}

static void hol__scan_name(void *ctx, const char *name)
{
    hol__scan *sc = ctx;
    if (hol_session_is_log_name(name))
        sc->logs = 1;
    for (int k = 0; k < HOL__PAT_N; k++) {
        long a = hol__numbered(name, hol__pat[k][0], hol__pat[k][1]);
        if (a < 0)
            continue;
        sc->logs = 1;
        if (a > sc->max_attempt)
            sc->max_attempt = (int)a;
        if (k < HOL__PAT_DONE)
            return;
        for (int i = 0; i < sc->nlive; i++)
            if (sc->live[i] == a)
                return;
        if (sc->nlive < HOL__MAX_LIVE)
            sc->live[sc->nlive++] = (int)a;
        else
            sc->too_many = 1;
        return;
    }
}

/* ---- reading a stream by lines ------------------------------------------------- */

typedef struct hol__lines {
    long complete;      /* complete lines (ending in LF) */
    uint64_t good;      /* bytes up to the end of the last complete line */
    uint64_t size;      /* bytes in all */
    char last[1024];    /* the last complete line (cut at 1023 bytes) */
    size_t last_len;
    int first_is;       /* the first line is `want` (1) or `want_old` (2) */
    const char *want, *want_old;
    long has_field;     /* a line whose 5th field is `field` (0: none asked) */
    const char *field;
    long max_attempt;   /* the highest 5th field of the lines after the first */
} hol__lines;

/* 1 when line is want, after a UTF-8 byte order mark and before a CR
 * (a summary.csv another program saved: read as the logs' own). */
static int hol__is_line(const char *line, size_t n, const char *want)
{
    if (n >= 3 && !memcmp(line, "\xef\xbb\xbf", 3))
        line += 3, n -= 3;
    if (n && line[n - 1] == '\r')
        n--;
    return n == strlen(want) && !memcmp(line, want, n);
}

static void hol__line_done(hol__lines *l, const char *line, size_t n)
{
    if (l->complete == 0 && l->want)
        l->first_is = hol__is_line(line, n, l->want)           ? 1
                      : l->want_old && hol__is_line(line, n, l->want_old) ? 2
                                                                          : 0;
    if (l->complete > 0) {
        /* the fifth field: the first four (ids, a time) hold no comma */
        const char *p = line, *end = line + n;
        for (int c = 0; c < 4 && p; c++) {
            p = memchr(p, ',', (size_t)(end - p));
            p = p ? p + 1 : NULL;
        }
        size_t fl = l->field ? strlen(l->field) : 0;
        if (l->field && !l->has_field && p && (size_t)(end - p) > fl &&
            !memcmp(p, l->field, fl) && p[fl] == ',')
            l->has_field = l->complete + 1;
        long v = 0;
        for (; p && p < end && *p >= '0' && *p <= '9' && v < 99999999; p++)
            v = v * 10 + (*p - '0');
        if (v > l->max_attempt)
            l->max_attempt = v;
    }
    l->complete++;
    l->last_len = n < sizeof l->last ? n : sizeof l->last - 1;
    memcpy(l->last, line, l->last_len);
    l->last[l->last_len] = 0;
}

/* Read stream name by lines into *l: HOL_OK, HOL_EOPEN (absent) or a
 * failure. Lines longer than 1023 bytes are cut in l->last (no row is). */
static hol_err hol__read_lines(const hol_sink *k, const char *name, hol__lines *l)
{
    char chunk[4096], line[1024];
    size_t ln = 0;
    uint64_t off = 0;
    for (;;) {
        size_t got = 0;
        hol_err e = k->read(k->user, name, off, chunk, sizeof chunk, &got);
        if (e)
            return e;
        for (size_t i = 0; i < got; i++) {
            if (chunk[i] == '\n') {
                hol__line_done(l, line, ln);
                l->good = off + i + 1;
                ln = 0;
            } else if (ln < sizeof line) {
                line[ln++] = chunk[i];
            }
        }
        off += got;
        l->size = off;
        if (got < sizeof chunk)
            return HOL_OK;
    }
}

/* A time field [-]D[.D] as written by the logs (%.4f, %.1f): its digits
 * as an integer (below 2^53, so exact) divided by a power of ten (at most 10^22),
 * both exact, so the result is the double nearest the text, as strtod
 * gives it; any other text (an exponent, more digits, none) reads as 0
 * (no strtod: on the web its long double scanner is 5 KB of the
 * transfer). */
static double hol__decimal(const char *p, size_t n)
{
    size_t i = n > 0 && p[0] == '-';
    int digits = 0, frac = -1;
    double v = 0, scale = 1;
    for (; i < n; i++) {
        if (p[i] == '.' && frac < 0) {
            frac = 0;
            continue;
        }
        if (p[i] < '0' || p[i] > '9' || v > 9e14 || frac >= 22)
            return 0;
        v = v * 10 + (p[i] - '0');
        digits++;
        if (frac >= 0) {
            frac++;
            scale *= 10;
        }
    }
    if (!digits)
        return 0;
    return p[0] == '-' ? -(v / scale) : v / scale;
}

/* The k-th comma-separated field counted from the line's end (0: the
 * last), as a number; the fields after a level name hold no comma. */
static double hol__field_right(const char *line, size_t n, int k)
{
    const char *end = line + n;
    for (int c = 0; c < k && end > line; c++) {
        while (end > line && end[-1] != ',')
            end--;
        if (end > line)
            end--;
    }
    const char *b = end;
    while (b > line && b[-1] != ',')
        b--;
    return hol__decimal(b, (size_t)(end - b));
}

/* ---- recovery of one attempt ------------------------------------------------------ */

/* A stream cut to its complete lines (a row cut by the kill dropped). */
static void hol__cut(hol_session *s, const char *name, uint64_t good)
{
    char tmp[96], chunk[4096];
    snprintf(tmp, sizeof tmp, "%s.cut", name);
    hol__out o;
    hol__out_init(&o, s->log, NULL, 0);
    if (hol__out_open(s, &o, tmp, 0))
        return;
    for (uint64_t off = 0; off < good && !s->failed;) {
        size_t want = good - off < sizeof chunk ? (size_t)(good - off) : sizeof chunk, got = 0;
        hol_err e = s->log->read(s->log->user, name, off, chunk, want, &got);
        if (e || got == 0) {
            hol__fail_sink(s, s->log, e ? e : HOL_EIO, "read", name);
            break;
        }
        hol__out_put(s, &o, chunk, got);
        off += got;
    }
    hol__out_flush(s, &o, 1);
    hol__out_close(s, &o);
    if (!s->failed && s->log->rename(s->log->user, tmp, name))
        hol__fail_sink(s, s->log, HOL_EIO, "rename", tmp);
    if (s->failed) /* no half copy left: the live file stays as it was */
        s->log->remove(s->log->user, tmp);
}

/* The live rows of attempt a: steps and the last level time (of the steps
 * and head rows); each stream, the track rows' too, cut to its complete
 * lines. */
static void hol__live_rows(hol_session *s, int a, int *steps, double *time)
{
    static const char *const what[3] = {"steps", "head", "track"};
    static const int tcol[2] = {10, 9}; /* t, counted from the right */
    *steps = 0;
    *time = 0;
    for (int k = 0; k < 3; k++) {
        char name[64], live[80];
        hol__attempt_name(name, sizeof name, what[k], a);
        snprintf(live, sizeof live, "%s.live", name);
        hol__lines l;
        memset(&l, 0, sizeof l);
        hol_err e = hol__read_lines(s->log, live, &l);
        if (e == HOL_EOPEN)
            continue;
        if (e) {
            hol__fail_sink(s, s->log, e, "read", live);
            return;
        }
        char probe[1];
        size_t got = 0;
        if (!s->log->read(s->log->user, live, l.good, probe, 1, &got) && got)
            hol__cut(s, live, l.good); /* bytes after the last LF */
        if (k == 0)
            *steps = l.complete > 1 ? (int)(l.complete - 1) : 0;
        if (l.complete > 1 && k < 2) {
            double t = hol__field_right(l.last, l.last_len, tcol[k]);
            *time = t > *time ? t : *time;
        }
    }
}

/* The starts of line's CSV fields (RFC 4180: a quoted field may hold
 * commas; the logs' fields hold no LF), at most max; their number, or -1
 * when the line is not CSV. at[n] is one past the last field's end + 1. */
static int hol__csv_fields(const char *line, size_t n, size_t *at, int max)
{
    int k = 0;
    size_t i = 0;
    for (;;) {
        if (k == max)
            return -1;
        at[k++] = i;
        if (i < n && line[i] == '"') {
            for (i++;; i++) {
                if (i >= n)
                    return -1;
                if (line[i] == '"' && i + 1 < n && line[i + 1] == '"')
                    i++;
                else if (line[i] == '"')
                    break;
            }
            i++;
            if (i < n && line[i] != ',')
                return -1;
        } else {
            while (i < n && line[i] != ',')
                i++;
        }
        if (i >= n) {
            at[k] = n + 1;
            return k;
        }
        i++;
    }
}

/* The pending row of attempt a (attempt-NNN.live's one line) with its
 * steps, time and end killed; its other fields, the tail's too, kept. */
static size_t hol__killed_row(hol_session *s, int a, char *row, size_t cap)
{
    char name[64];
    hol__attempt_name(name, sizeof name, "attempt", a);
    size_t got = 0;
    if (s->log->read(s->log->user, name, 0, s->scratch, HOL__ROW_MAX, &got))
        return 0;
    const char *line = s->scratch, *lf = memchr(line, '\n', got);
    if (!lf)
        return 0; /* not whole */
    size_t len = (size_t)(lf - line), at[32];
    int nf = hol__csv_fields(line, len, at, 31);
    /* steps, optimum, time, end are the four fields before the tail
     * (session_no, study_sha256, meta: fields 21..23 of this version's
     * 24; none in a row of the columns before them) */
    int k = nf == 24 ? 21 : nf;
    if (k < 5)
        return 0;
    int steps;
    double time;
    hol__live_rows(s, a, &steps, &time);
    int optimum = atoi(line + at[k - 3]);
    int n = snprintf(row, cap, "%.*s%d,%d,%.4f,%s", (int)at[k - 4], line, steps, optimum, time,
                     hol__end_names[HOL__END_KILLED]);
    if (n <= 0 || (size_t)n >= cap)
        return 0;
    size_t m = (size_t)n;
    /* the tail as the killed session wrote it (its meta, not ours) */
    const char *tail = nf == 24 ? line + at[21] - 1 : ",,,";
    size_t tl = nf == 24 ? len - (at[21] - 1) : 3;
    if (s->old_cols)
        tl = 0;
    if (m + tl + 1 >= cap)
        return 0;
    memcpy(row + m, tail, tl);
    m += tl;
    row[m++] = '\n';
    row[m] = 0;
    return m;
}

/* A new stream holding text, durably. */
static void hol__put(hol_session *s, const char *name, const char *text)
{
    hol__out o;
    hol__out_init(&o, s->log, NULL, 0);
    if (!hol__out_open(s, &o, name, 0)) {
        hol__out_put(s, &o, text, strlen(text));
        hol__out_flush(s, &o, 1);
        hol__out_close(s, &o);
    }
}

/* Attempt a has no row and no whole attempt-NNN.live (killed before it
 * reached the disk): nothing says what it played, so its files go. */
static void hol__drop(hol_session *s, int a)
{
    static const char *const what[4] = {"head", "track", "steps", "attempt"};
    for (int k = 0; k < 4 && !s->failed; k++) {
        char name[64], live[80];
        hol__attempt_name(name, sizeof name, what[k], a);
        snprintf(live, sizeof live, "%s%s", name, k < 3 ? ".live" : "");
        char probe[1];
        size_t got;
        if (s->log->read(s->log->user, live, 0, probe, 1, &got) == HOL_EOPEN)
            continue;
        if (s->log->remove(s->log->user, live))
            hol__fail_sink(s, s->log, HOL_EIO, "remove", live);
    }
    if (!s->failed)
        s->dropped++;
}

static void hol__recover(hol_session *s, int a)
{
    char field[16], name[64], live[80], *row = s->row;
    snprintf(field, sizeof field, "%d", a);
    hol__lines l;
    memset(&l, 0, sizeof l);
    l.field = field;
    hol_err e = hol__read_lines(s->log, "summary.csv", &l);
    if (e && e != HOL_EOPEN) {
        hol__fail_sink(s, s->log, e, "read", "summary.csv");
        return;
    }
    if (!l.has_field) {
        size_t n = hol__killed_row(s, a, row, HOL__ROW_MAX);
        if (!n) {
            hol__drop(s, a);
            return;
        }
        hol__out o;
        hol__out_init(&o, s->log, NULL, 0);
        if (!hol__out_open(s, &o, "summary.csv", 1)) {
            hol__out_put(s, &o, row, n);
            hol__out_flush(s, &o, 1);
            hol__out_close(s, &o);
        }
    } else {
        int steps;
        double time;
        hol__live_rows(s, a, &steps, &time); /* cut what the kill cut */
    }
    /* the live files renamed, steps last (as at an attempt's end); one the
     * kill left unmade or without a whole header line (the attempt had
     * just begun) made with its header, so the row has its files */
    static const char *const what[3] = {"head", "track", "steps"};
    static const char *const cols[3] = {HOL_SESSION_HEAD_COLUMNS "\n",
                                        HOL_SESSION_TRACK_COLUMNS "\n",
                                        HOL_SESSION_STEP_COLUMNS "\n"};
    for (int k = 0; k < 3 && !s->failed; k++) {
        hol__attempt_name(name, sizeof name, what[k], a);
        snprintf(live, sizeof live, "%s.live", name);
        char probe[1];
        size_t got;
        hol__lines ll;
        memset(&ll, 0, sizeof ll);
        hol_err le = hol__read_lines(s->log, live, &ll);
        if (le == HOL_EOPEN &&
            s->log->read(s->log->user, name, 0, probe, 1, &got) != HOL_EOPEN)
            continue; /* renamed before the kill */
        if (le && le != HOL_EOPEN) {
            hol__fail_sink(s, s->log, le, "read", live);
            return;
        }
        if (le == HOL_EOPEN || ll.complete == 0)
            hol__put(s, live, cols[k]);
        if (!s->failed && s->log->rename(s->log->user, live, name))
            hol__fail_sink(s, s->log, HOL_EIO, "rename", live);
    }
    hol__attempt_name(name, sizeof name, "attempt", a);
    if (!s->failed && s->log->remove(s->log->user, name))
        hol__fail_sink(s, s->log, HOL_EIO, "remove", name);
    if (!s->failed)
        s->recovered++;
}

void hol__recover_killed(hol_session *s, int a)
{
    hol__recover(s, a);
}

/* ---- opening the folder ------------------------------------------------------------- */

/* 1 when summary.csv holds no more than a first part of its header line
 * (no LF): a first session killed before its header reached the disk. */
static int hol__header_part(hol_session *s)
{
    char buf[sizeof HOL_SESSION_SUMMARY_COLUMNS];
    size_t got = 0;
    if (s->log->read(s->log->user, "summary.csv", 0, buf, sizeof buf, &got))
        return 0;
    return got < sizeof buf && !memcmp(buf, HOL_SESSION_SUMMARY_COLUMNS, got);
}

/* name added to the list of what recovery repaired (s->cut: "a, b"). */
static void hol__note(char *list, size_t cap, const char *name)
{
    size_t n = strlen(list);
    if (n + strlen(name) + 8 < cap)
        snprintf(list + n, cap - n, "%s%s", n ? ", " : "", name);
    else if (n >= 3 && n + 5 < cap && strcmp(list + n - 3, "..."))
        snprintf(list + n, cap - n, ", ...");
}

/* name cut to its whole lines when a kill cut its last row (bytes after
 * its last LF); 1 when it was cut. */
static int hol__cut_torn(hol_session *s, const char *name, hol__lines *l)
{
    hol_err e = hol__read_lines(s->log, name, l);
    if (e && e != HOL_EOPEN)
        hol__fail_sink(s, s->log, e, "read", name);
    if (e || l->size == l->good)
        return 0;
    hol__cut(s, name, l->good);
    if (s->failed)
        return 0;
    hol__note(s->cut, sizeof s->cut, name);
    return 1;
}

/* Finished attempt files (steps-, head-, track-NNN.csv): a steps file
 * whose last row a kill cut, and the files of an attempt above `above`
 * (the highest attempt of summary.csv's whole rows, when recovery cut its
 * last row; -1: none) that has no live file: its row was the cut one. */
typedef struct hol__fin {
    hol_session *s;
    const hol__scan *sc;
    int above;
    char torn[8][64], gone[8][64];
    int ntorn, ngone, more;
} hol__fin;

static void hol__fin_name(void *ctx, const char *name)
{
    hol__fin *f = ctx;
    for (int k = 0; k < HOL__PAT_DONE; k++) {
        long a = hol__numbered(name, hol__pat[k][0], hol__pat[k][1]);
        int live = 0;
        for (int i = 0; a >= 0 && i < f->sc->nlive; i++)
            live |= f->sc->live[i] == a;
        if (a < 0 || live || f->more)
            continue;
        if (f->above >= 0 && a > f->above) {
            if (f->ngone == 8)
                f->more = 1;
            else
                snprintf(f->gone[f->ngone++], 64, "%s", name);
        } else if (k == 0) {
            hol__lines l;
            memset(&l, 0, sizeof l);
            if (hol__read_lines(f->s->log, name, &l) || l.size == l.good)
                continue;
            if (f->ntorn == 8)
                f->more = 1;
            else
                snprintf(f->torn[f->ntorn++], 64, "%s", name);
        }
    }
}

/* Every append-only log cut to its whole rows before rows are added to
 * it (the names in s->cut), and an attempt's files kept only with its
 * row: those of the row recovery cut from summary.csv removed (in
 * s->gone). */
static void hol__cut_logs(hol_session *s, const hol__scan *sc, int above)
{
    static const char *const logs[5] = {"events.csv", "points.csv", "answers.csv",
                                        "environment.csv", "tutorial.csv"};
    for (int k = 0; k < 5 && !s->failed; k++) {
        hol__lines l;
        memset(&l, 0, sizeof l);
        hol__cut_torn(s, logs[k], &l);
    }
    hol__fin f;
    do {
        memset(&f, 0, sizeof f);
        f.s = s, f.sc = sc, f.above = above;
        hol_err e = s->failed ? HOL_OK : s->log->list(s->log->user, hol__fin_name, &f);
        if (e)
            hol__fail_sink(s, s->log, e, "list", "the log folder");
        for (int i = 0; i < f.ntorn && !s->failed; i++) {
            hol__lines l;
            memset(&l, 0, sizeof l);
            hol__cut_torn(s, f.torn[i], &l);
        }
        for (int i = 0; i < f.ngone && !s->failed; i++) {
            if (s->log->remove(s->log->user, f.gone[i]))
                hol__fail_sink(s, s->log, HOL_EIO, "remove", f.gone[i]);
            hol__note(s->gone, sizeof s->gone, f.gone[i]);
        }
    } while (f.more && !s->failed);
}

static int hol__cmp_int(const void *a, const void *b)
{
    return *(const int *)a - *(const int *)b;
}

hol_err hol__log_open(hol_session *s, int append)
{
    hol__scan sc;
    memset(&sc, 0, sizeof sc);
    hol_err e = s->log->list(s->log->user, hol__scan_name, &sc);
    if (e)
        return hol__fail_sink(s, s->log, e, "list", "the log folder");
    if (sc.logs && !append) {
        snprintf(s->msg, sizeof s->msg, "the log folder holds earlier logs%s: add to them "
                 "(--append) or choose another folder",
                 sc.nlive ? " (and an unfinished attempt)" : "");
        return HOL_EARG;
    }
    if (sc.too_many) {
        snprintf(s->msg, sizeof s->msg, "the log folder holds more than %d unfinished attempts",
                 HOL__MAX_LIVE);
        return HOL_EARG;
    }
    hol__lines l;
    memset(&l, 0, sizeof l);
    l.want = HOL_SESSION_SUMMARY_COLUMNS;
    l.want_old = HOL_SESSION_SUMMARY_COLUMNS_OLD;
    e = hol__read_lines(s->log, "summary.csv", &l);
    if (e && e != HOL_EOPEN)
        return hol__fail_sink(s, s->log, e, "read", "summary.csv");
    s->old_cols = l.first_is == 2;
    int above = -1; /* the attempts above it lost their row to the cut */
    if (e == HOL_OK && l.complete == 0 && hol__header_part(s)) {
        e = HOL_EOPEN; /* a kill before its header reached the disk: made again */
    } else if (e == HOL_OK && !l.first_is) {
        snprintf(s->msg, sizeof s->msg, "the log folder's summary.csv has other columns "
                 "(another version's logs): choose another folder");
        return HOL_EVERSION;
    } else if (e == HOL_OK && l.size > l.good) {
        hol__cut(s, "summary.csv", l.good); /* a row cut by the kill */
        hol__note(s->cut, sizeof s->cut, "summary.csv");
        above = (int)l.max_attempt;
    }
    if (!s->failed)
        hol__cut_logs(s, &sc, above);
    if (e == HOL_EOPEN) {
        /* a new summary.csv: its header first */
        hol__out o;
        hol__out_init(&o, s->log, NULL, 0);
        if (!hol__out_open(s, &o, "summary.csv", 0)) {
            hol__out_put(s, &o, HOL_SESSION_SUMMARY_COLUMNS "\n",
                         sizeof HOL_SESSION_SUMMARY_COLUMNS);
            hol__out_flush(s, &o, 1);
            hol__out_close(s, &o);
        }
    }
    qsort(sc.live, (size_t)sc.nlive, sizeof sc.live[0], hol__cmp_int);
    for (int i = 0; i < sc.nlive && !s->failed; i++)
        hol__recover(s, sc.live[i]);
    s->attempt = sc.max_attempt;
    return s->failed;
}
