/* fuzz_report.c - libFuzzer harness for the report's log reader
 * (core/hol_report.h): summary.csv and steps-NNN.csv lines from outside.
 *
 * Input: a log file's text; its first byte picks the kind (even: a
 * summary, odd: a steps file), the rest is split at LF into a header and
 * rows. Checks: a header or row is refused with a message, or read into
 * values within their documented bounds (steps >= 0, optimum >= -1, a
 * tiling 4..8, a room of 3..5 a side, a cell of 0.5..1.5 m, a cell inside
 * the largest room, a direction 0..3, NUL-terminated texts); efficiency
 * is -1 or in [0, 1]; every line that splits as CSV splits again to the
 * same fields after its fields are written back with hol_text_csv; the
 * per-condition table never overflows its count; a field cleaned for the
 * report's files holds no control byte.
 */
#include <stdint.h>
#include <string.h>

#include "../core/hol_report.h"
#include "../core/hol_text.h"

#include "fuzz_check.h"

static hol_report_agg agg;
static hol_report_cond conds[64];

static void check_split(const char *s, size_t n)
{
    static char buf[1 << 16], buf2[1 << 16], line[1 << 17];
    const char *f[HOL_REPORT_MAX_COLS], *g[HOL_REPORT_MAX_COLS];
    int nf, ng;
    char err[HOL_REPORT_ERR];
    if (hol_report_csv_split(s, n, buf, sizeof buf, f, HOL_REPORT_MAX_COLS, &nf, err))
        return;
    CHECK(nf >= 1 && nf <= HOL_REPORT_MAX_COLS);
    size_t o = 0;
    for (int i = 0; i < nf; i++) {
        size_t need = hol_text_csv(f[i], strlen(f[i]), line + o, sizeof line - o - 1);
        CHECK(need < sizeof line - o - 1);
        o += need;
        if (i + 1 < nf)
            line[o++] = ',';
    }
    CHECK(!hol_report_csv_split(line, o, buf2, sizeof buf2, g, HOL_REPORT_MAX_COLS, &ng, err));
    CHECK(ng == nf);
    for (int i = 0; i < nf; i++)
        CHECK(!strcmp(f[i], g[i]));
}

static void check_attempt(const hol_report_attempt *a)
{
    CHECK(a->steps >= 0 && a->optimum >= -1 && a->attempt >= 1 && a->position >= -1);
    CHECK(a->tiling_q >= 4 && a->tiling_q <= 8 && a->time_s >= 0);
    CHECK(a->room_cols >= 3 && a->room_cols <= 5 && a->room_rows >= 3 && a->room_rows <= 5);
    CHECK(a->cell_m >= 0.5 && a->cell_m <= 1.5 && a->end[0]);
    CHECK(memchr(a->level, 0, sizeof a->level) && memchr(a->condition, 0, sizeof a->condition));
    double e = hol_report_efficiency(a);
    CHECK(e == -1 || (e >= 0 && e <= 1));
    hol_report_agg_add(&agg, a);
    CHECK(agg.n <= agg.cap && (agg.n < agg.cap || agg.overflow >= 0));
    char clean[4 * HOL_REPORT_TEXT];
    size_t n = hol_report_clean(a->condition, clean, sizeof clean);
    CHECK(n == strlen(clean));
    for (size_t i = 0; i < n; i++)
        CHECK((unsigned char)clean[i] >= 0x20 && clean[i] != 0x7f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1 || size > 65536)
        return 0;
    int steps = data[0] & 1;
    const char *s = (const char *)data + 1, *end = (const char *)data + size;
    hol_report_header h;
    int have = 0;
    char err[HOL_REPORT_ERR];
    hol_report_agg_init(&agg, conds, 64);
    while (s <= end) {
        const char *nl = memchr(s, '\n', (size_t)(end - s));
        size_t n = (size_t)((nl ? nl : end) - s);
        check_split(s, n);
        err[0] = 0;
        if (!have) {
            hol_err r = steps ? hol_report_steps_header(s, n, &h, err)
                              : hol_report_summary_header(s, n, &h, err);
            CHECK(r ? err[0] != 0 : h.ncols >= 1);
            have = !r;
        } else if (steps) {
            hol_report_step st;
            if (hol_report_step_row(&h, s, n, &st, err))
                CHECK(err[0]);
            else
                CHECK(st.dir >= 0 && st.dir <= 3 && st.col >= 0 && st.col < 5 &&
                      st.row >= 0 && st.row < 5 && st.orient >= 0 && st.orient <= 3 &&
                      st.step >= 1);
        } else {
            hol_report_attempt a;
            if (hol_report_summary_row(&h, s, n, &a, err))
                CHECK(err[0]);
            else
                check_attempt(&a);
        }
        if (!nl)
            break;
        s = nl + 1;
    }
    return 0;
}
