/* fuzz_input.c - libFuzzer harness for input record lines (recordings and
 * --input scripts, core/hol_input_io.h).
 *
 * Input: one line as read from a recording. Checks: a line that parses is a
 * valid record; its canonical line parses back to the same record, bit for
 * bit, and formats to the same line again; a line that fails names an
 * offset inside it and leaves the output untouched.
 */
#include <stdint.h>
#include <string.h>

#include "../core/hol_input_io.h"

#include "fuzz_check.h"

static int same_input(const hol_input *a, const hol_input *b)
{
    return !memcmp(&a->time_s, &b->time_s, sizeof a->time_s) && a->flags == b->flags &&
           a->buttons == b->buttons && !memcmp(&a->head, &b->head, sizeof a->head) &&
           !memcmp(a->hand, b->hand, sizeof a->hand) &&
           !memcmp(a->move, b->move, sizeof a->move) &&
           !memcmp(a->turn, b->turn, sizeof a->turn);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hol_input in, again, untouched;
    memset(&in, 0x5a, sizeof in);
    untouched = in;
    size_t bad = (size_t)-1;
    hol_err err = hol_input_parse((const char *)data, size, &in, &bad);
    if (err) {
        CHECK(err == HOL_EPARSE);
        CHECK(bad <= size);
        CHECK(!memcmp(&in, &untouched, sizeof in));
        return 0;
    }
    CHECK(hol_input_valid(&in));
    char line[HOL_INPUT_LINE_MAX + 1], line2[HOL_INPUT_LINE_MAX + 1];
    size_t n = hol_input_format(&in, line, sizeof line);
    CHECK(n > 0 && n <= HOL_INPUT_LINE_MAX && strlen(line) == n);
    CHECK(hol_input_parse(line, n, &again, NULL) == HOL_OK);
    CHECK(same_input(&in, &again));
    size_t n2 = hol_input_format(&again, line2, sizeof line2);
    CHECK(n2 == n && !memcmp(line, line2, n));
    /* a buffer one byte short fails cleanly */
    CHECK(hol_input_format(&in, line2, n) == 0);
    return 0;
}
