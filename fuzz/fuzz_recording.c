/* fuzz_recording.c - libFuzzer harness for recording files as `holonomy
 * replay` reads them (platform/cli/session.c: the header with its levels,
 * then input lines).
 *
 * Input: a recording file. Checks: the header parser either refuses with a
 * message naming a line, or returns where the input lines begin (inside the
 * file) with 1..SESSION_MAX_LEVELS levels, each parsed; every later line
 * either parses as an input record or is refused.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_input_io.h"
#include "../platform/cli/session.h"

#include "fuzz_check.h"

static session_level levels[SESSION_MAX_LEVELS];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size > 65536)
        return 0;
    char *buf = malloc(size + 1);
    char **line = malloc((size + 1) * sizeof *line);
    size_t *len = malloc((size + 1) * sizeof *len);
    if (!buf || !line || !len)
        abort();
    memcpy(buf, data, size);
    buf[size] = 0;
    long n = 0;
    size_t start = 0;
    for (size_t i = 0; i <= size; i++)
        if (i == size || buf[i] == '\n') {
            if (i == size && start == size)
                break;
            buf[i] = 0;
            line[n] = buf + start;
            len[n++] = i - start;
            start = i + 1;
        }
    int nlevels = -1;
    char err[256] = "";
    long first = session_read_header(line, len, n, levels, &nlevels, err, sizeof err);
    if (!first) {
        CHECK(!strncmp(err, "line ", 5) && strlen(err) < sizeof err);
    } else {
        CHECK(first >= 2 && first <= n + 1);
        CHECK(nlevels >= 1 && nlevels <= SESSION_MAX_LEVELS);
        for (long k = first - 1; k < n; k++) {
            hol_input in;
            if (hol_input_parse(line[k], len[k], &in, NULL) == HOL_OK)
                CHECK(hol_input_valid(&in));
        }
    }
    free(buf);
    free(line);
    free(len);
    return 0;
}
