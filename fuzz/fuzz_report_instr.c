/* fuzz_report_instr.c - libFuzzer harness for the report's readers of
 * points.csv and answers.csv (platform/cli/report/report_answers.c through
 * report_stats_instrument, their values checked by report_instr.h; issue
 * 39 findings 7, 12 and 17).
 *
 * Input: the first byte picks the file (even: points.csv, odd:
 * answers.csv), the rest (at most 60,000 bytes) is its text, read through
 * a pipe by the bounded line reader as the report reads a file. The run
 * holds three completed attempts (session s, attempts 1..3; conditions a,
 * a, b of study st) for the rows' conditions.
 * Checks: the reader ends in 0 or 2 (bad input), nothing else; when it
 * takes the file, every row (after the header, blank lines and a byte
 * order mark aside) splits as CSV into the header's field count (no torn
 * row is read), and every mean it made is finite and in its measure's
 * range: pointing errors 0..180, each preset's scores 0..their largest
 * (ssq_total 235.62, raw TLX 100; from core/hol_ask.h's table), every
 * Likert item 0..100; no measure has more values than the file has rows.
 */
#define _GNU_SOURCE
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../core/hol_ask.h"
#include "../platform/cli/report/report_stats.h"
#include "../platform/cli/report/report_stats_impl.h"
#include "../platform/file/hol_lines.h"

#include "fuzz_check.h"

/* The data through a pipe as a file's lines (it fits: written first). */
static void open_pipe(const uint8_t *d, size_t n, hol_lines *l)
{
    int p[2];
    CHECK(pipe(p) == 0);
    CHECK(write(p[1], d, n) == (ssize_t)n);
    close(p[1]);
    CHECK(hol_lines_open_fd(l, p[0], REPORT_LINE_MAX) == HOL_OK);
    l->own_fd = 1;
}

/* 1 when every row after the header splits into the header's field
 * count (as the reader must have found to take the file); *rows: rows. */
static int rows_whole(const uint8_t *d, size_t n, long *rows)
{
    static char buf[REPORT_LINE_MAX + 8];
    static const char *f[HOL_REPORT_MAX_COLS];
    hol_lines l;
    open_pipe(d, n, &l);
    char *s, err[HOL_REPORT_ERR];
    size_t len;
    int nf, head = -1, ok = 1;
    *rows = 0;
    while (ok && hol_lines_next(&l, &s, &len) > 0) {
        if (l.lineno == 1 && len >= 3 && !memcmp(s, "\xef\xbb\xbf", 3))
            s += 3, len -= 3;
        if (len == strspn(s, " \t"))
            continue;
        ok = !hol_report_csv_split(s, len, buf, sizeof buf, f, HOL_REPORT_MAX_COLS, &nf, err);
        if (ok && head < 0)
            head = nf;
        else if (ok)
            ok = nf == head, ++*rows;
    }
    hol_lines_close(&l);
    return ok;
}

/* The largest score k of preset p: every item at its top. */
static double score_max(const hol_ask_preset_def *p, int k)
{
    double sum = 0;
    for (int j = 0; j < HOL_ASK_PRESET_SCALES; j++)
        if (p->scores[k].scales & (1u << j))
            for (int i = 0; i < p->nitems; i++)
                if (p->items[i].scales & (1u << j))
                    sum += p->hi;
    return sum * p->scores[k].weight / p->scores[k].div;
}

static void check_range(const hol_stats *st, double lo, double hi, long rows)
{
    CHECK(st->n >= 0 && st->n <= rows);
    if (st->n)
        CHECK(isfinite(st->mean) && st->mean >= lo - 1e-9 && st->mean <= hi + 1e-9 &&
              isfinite(st->m2) && st->m2 >= -1e-9);
}

static void check_stats(const report_stats *s, long rows)
{
    double lo[RS_NFIX], hi[RS_NFIX];
    for (int m = 0; m < RS_NFIX; m++)
        lo[m] = 0, hi[m] = 1e300;
    hi[RS_ERR_TRUE] = hi[RS_ERR_FLAT] = 180;
    for (int i = 0, col = RS_SSQ_T; i < hol_ask_npresets(); i++) {
        const hol_ask_preset_def *p = hol_ask_preset_at(i);
        for (int k = 0; k < p->nscores && col < RS_NFIX; k++, col++)
            hi[col] = score_max(p, k);
    }
    for (int c = 0; c < s->ncond; c++)
        for (int m = RS_ERR_TRUE; m < RS_NFIX; m++)
            check_range(&s->fix[c * RS_NFIX + m], lo[m], hi[m], rows);
    for (int i = 0; i < s->nlik; i++)
        check_range(&s->lik[i].s, 0, 100, rows);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 60001)
        return 0;
    static report_att att[3];
    static report_run r; /* its scratch level is large */
    memset(&r, 0, sizeof r);
    memset(att, 0, sizeof att);
    for (int i = 0; i < 3; i++) {
        hol_report_attempt *a = &att[i].a;
        strcpy(a->session, "s");
        strcpy(a->study, "st");
        strcpy(a->condition, i < 2 ? "a" : "b");
        strcpy(a->level, "l");
        strcpy(a->end, "done");
        a->attempt = i + 1;
        a->position = i + 1;
        a->steps = a->optimum = 5;
        a->tiling_q = 5;
    }
    r.cmd = "report";
    r.att = att;
    r.natt = 3;
    CHECK(report_stats_read(&r) == 0); /* no LOGDIR: the attempts only */
    hol_lines l;
    open_pipe(data + 1, size - 1, &l);
    int answers = data[0] & 1;
    int st = report_stats_instrument(&r, 0, answers ? "answers.csv" : "points.csv", &l);
    CHECK(st == 0 || st == 2);
    if (st == 0) {
        long rows;
        CHECK(rows_whole(data + 1, size - 1, &rows));
        check_stats(r.stats, rows);
    }
    report_stats_free(&r);
    return 0;
}
