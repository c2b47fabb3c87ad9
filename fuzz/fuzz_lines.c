/* fuzz_lines.c - libFuzzer harness for the bounded line reader
 * (platform/file/hol_lines.h, standard input of the line commands and
 * gamepad scripts) and the repeated-option rule (cli_no_repeats).
 *
 * Input: the first byte picks the part and a parameter, the rest is data.
 * - even: the data is read through hol_lines_open_fd (a pipe) with a limit
 *   of 1..64 bytes. Checks, against a model that splits at LF: the same
 *   lines in order (one CR before an LF dropped, NUL bytes kept, a last
 *   line without LF is a line), the count in lineno; a line longer than
 *   the limit stops the reading with HOL_ENOMEM naming that line.
 * - odd: the data is an argument list (one argument a line) of `render`,
 *   `world` or `nav`. Checks against a model: refused (exit status 2, one
 *   line on stderr) exactly when an argument starting with "--" repeats by
 *   its name before '=' ("--" alone is no option), except render's
 *   --target.
 */
#define _GNU_SOURCE
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../platform/cli/cli.h"
#include "../platform/file/hol_lines.h"

#include "fuzz_check.h"

static void check_lines(const uint8_t *d, size_t n, size_t limit)
{
    int p[2];
    CHECK(n <= 60000 && pipe(p) == 0); /* fits in the pipe: written first */
    CHECK(write(p[1], d, n) == (ssize_t)n);
    close(p[1]);
    hol_lines l;
    CHECK(hol_lines_open_fd(&l, p[0], limit) == HOL_OK);
    size_t at = 0;
    long k = 0;
    for (;;) {
        /* the model's next line */
        const uint8_t *nl = memchr(d + at, '\n', n - at);
        size_t end = nl ? (size_t)(nl - d) : n, len = end - at;
        int have = nl || at < n;
        if (have && len && d[end - 1] == '\r')
            len--;
        char *s;
        size_t got;
        int r = hol_lines_next(&l, &s, &got);
        if (!have) {
            CHECK(r == 0 && l.lineno == k);
            break;
        }
        k++;
        if (len > limit) {
            CHECK(r < 0 && l.err == HOL_ENOMEM && l.lineno == k);
            break;
        }
        CHECK(r == 1 && got == len && memcmp(s, d + at, len) == 0 && s[len] == 0);
        CHECK(l.lineno == k);
        at = nl ? end + 1 : n;
    }
    hol_lines_close(&l);
    close(p[0]);
}

static void check_repeats(const uint8_t *d, size_t n, int which)
{
    static const char *const cmds[] = {"render", "world", "nav"};
    const char *cmd = cmds[which % 3];
    char *text = malloc(n + 1), *argv[34];
    CHECK(text != NULL);
    memcpy(text, d, n);
    text[n] = 0;
    int argc = 0;
    argv[argc++] = (char *)cmd;
    for (char *a = text; argc < 33;) {
        argv[argc++] = a;
        char *e = strchr(a, '\n');
        if (!e)
            break;
        *e = 0;
        a = e + 1;
    }
    argv[argc] = NULL;
    /* the model: options end at the first "--" */
    int repeated = 0, end = 1;
    while (end < argc && strcmp(argv[end], "--"))
        end++;
    for (int i = 1; i < end && !repeated; i++) {
        size_t ni = strcspn(argv[i], "=");
        if (strncmp(argv[i], "--", 2) || !argv[i][2])
            continue;
        if (!strcmp(cmd, "render") && ((ni == 8 && !strncmp(argv[i], "--target", 8)) ||
                                       (ni == 9 && !strncmp(argv[i], "--lantern", 9))))
            continue;
        for (int j = i + 1; j < end && !repeated; j++)
            repeated = argv[j][0] == '-' && argv[j][1] == '-' && argv[j][2] &&
                       strcspn(argv[j], "=") == ni && !strncmp(argv[i], argv[j], ni);
    }
    char *out = NULL;
    size_t on = 0;
    FILE *mem = open_memstream(&out, &on), *saved = stderr;
    CHECK(mem != NULL);
    stderr = mem;
    int st = cli_no_repeats(cmd, argc, argv);
    stderr = saved;
    fclose(mem);
    CHECK(st == (repeated ? CLI_EXIT_USAGE : 0));
    CHECK(repeated ? on > 0 && memchr(out, '\n', on) == out + on - 1 : on == 0);
    free(out);
    free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0 || size > 4096)
        return 0;
    if (data[0] % 2 == 0)
        check_lines(data + 1, size - 1, (size_t)(data[0] / 2 % 64) + 1);
    else
        check_repeats(data + 1, size - 1, data[0] / 2);
    return 0;
}
