/* fuzz_recording.c - libFuzzer harness for recording files as `holonomy
 * replay` reads them (core/hol_rec.h: the header with its metadata and
 * levels, a line at a time; then input lines).
 *
 * Input: a recording file. Checks: the header reader either refuses with a
 * message naming a line of the file, or stops at a line inside the file (or
 * its end) with 1..HOL_REC_MAX_LEVELS levels, each named as a recording can
 * carry and parsed; written again (hol_rec_write_header), the header reads
 * back to the same levels, study labels and metadata; every later line either parses as
 * an input record or is refused.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_input_io.h"
#include "../core/hol_rec.h"

#include "fuzz_check.h"

static hol_level levels[HOL_REC_MAX_LEVELS], again[HOL_REC_MAX_LEVELS];
static hol_rec_reader r, r2;

typedef struct buf {
    char *p;
    size_t n, cap;
} buf;

static void emit(void *ctx, const char *data, size_t n)
{
    buf *b = ctx;
    CHECK(b->n + n <= b->cap);
    memcpy(b->p + b->n, data, n);
    b->n += n;
}

/* Feed text's lines to a reader: HOL_OK with *stop the 0-based index of the
 * first input line (nlines at the end), or the error. */
static hol_err read_header(hol_rec_reader *rd, hol_level *lv, char **line, size_t *len,
                           long n, long *stop)
{
    hol_rec_reader_init(rd, lv);
    for (long i = 0; i < n; i++) {
        int done = 0;
        hol_err e = hol_rec_read_line(rd, line[i], len[i], &done);
        if (e)
            return e;
        if (done) {
            *stop = i;
            return HOL_OK;
        }
    }
    *stop = n;
    return hol_rec_read_end(rd);
}

/* Split s into lines in place. */
static long split(char *s, size_t size, char **line, size_t *len)
{
    long n = 0;
    size_t start = 0;
    for (size_t i = 0; i <= size; i++)
        if (i == size || s[i] == '\n') {
            if (i == size && start == size)
                break;
            s[i] = 0;
            line[n] = s + start;
            len[n++] = i - start;
            start = i + 1;
        }
    return n;
}

static void check_round_trip(void)
{
    static char text[HOL_REC_MAX_LEVELS * (HOL_LEVEL_TEXT_MAX * 2 + 256) + 1024];
    buf b = {text, 0, sizeof text};
    hol_rec_meta m = r.meta;
    if (r.version == 1) {
        strcpy(m.session, "s");
        strcpy(m.start, "2025-01-01T00:00:00Z");
        strcpy(m.version, "1");
    }
    hol_rec_write_header(&m, levels, r.nlevels, emit, &b);
    static char *line[HOL_REC_MAX_LEVELS * 600 + 16];
    static size_t len[HOL_REC_MAX_LEVELS * 600 + 16];
    long n = split(text, b.n, line, len), stop = 0;
    CHECK(read_header(&r2, again, line, len, n, &stop) == HOL_OK);
    CHECK(r2.nlevels == r.nlevels && stop == n);
    for (int i = 0; i < r.nlevels; i++) {
        CHECK(!strcmp(levels[i].name, again[i].name));
        CHECK(levels[i].len == again[i].len && !memcmp(levels[i].text, again[i].text, levels[i].len));
        CHECK(!memcmp(levels[i].sha256, again[i].sha256, 32));
        CHECK(!strcmp(levels[i].condition, again[i].condition));
        CHECK(levels[i].position == again[i].position);
        CHECK(!levels[i].condition[0] || hol_rec_id_ok(levels[i].condition));
    }
    CHECK(!strcmp(r2.meta.participant, m.participant));
    CHECK(!strcmp(r2.meta.study, m.study));
    /* version 4: the session number, the study's hash, the meta text */
    CHECK(r2.meta.session_no == m.session_no);
    CHECK(!strcmp(r2.meta.study_sha256, m.study_sha256));
    CHECK(!strcmp(r2.meta.meta, m.meta) && hol_rec_meta_ok(m.meta));
    /* version 5: a resumed session's ready screen */
    CHECK(r2.meta.ready == m.ready);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 65536)
        return 0;
    char *text = malloc(size + 1);
    char **line = malloc((size + 1) * sizeof *line);
    size_t *len = malloc((size + 1) * sizeof *len);
    if (!text || !line || !len)
        abort();
    memcpy(text, data, size);
    text[size] = 0;
    long n = split(text, size, line, len), stop = 0;
    hol_err e = read_header(&r, levels, line, len, n, &stop);
    if (e) {
        long ln = 0;
        CHECK(sscanf(r.msg, "line %ld:", &ln) == 1 && ln >= 1 && ln <= n + 1);
        CHECK(strlen(r.msg) < sizeof r.msg);
    } else {
        CHECK(stop >= 2 && stop <= n);
        CHECK(r.nlevels >= 1 && r.nlevels <= HOL_REC_MAX_LEVELS);
        for (int i = 0; i < r.nlevels; i++)
            CHECK(hol_level_name_ok(levels[i].name, strlen(levels[i].name)));
        check_round_trip();
        for (long k = stop; k < n; k++) {
            hol_input in;
            if (hol_input_parse(line[k], len[k], &in, NULL) == HOL_OK)
                CHECK(hol_input_valid(&in));
        }
    }
    free(text);
    free(line);
    free(len);
    return 0;
}
