/* fuzz_lines.c - libFuzzer harness for the bounded line reader
 * (platform/file/hol_lines.h, standard input of the line commands and
 * gamepad scripts) and the option grammar of every command (cli_opts_next).
 *
 * Input: the first byte picks the part and a parameter, the rest is data.
 * - even: the data is read through hol_lines_open_fd (a pipe) with a limit
 *   of 1..64 bytes. Checks, against a model that splits at LF: the same
 *   lines in order (one CR before an LF dropped, NUL bytes kept, a last
 *   line without LF is a line), the count in lineno; a line longer than
 *   the limit stops the reading with HOL_ENOMEM naming that line.
 * - odd: the data is an argument list (one argument a line) given to
 *   cli_opts_next (valued --seed, --size, --target; flags --stats,
 *   --quiet; --target repeatable). Checks against a model of the grammar
 *   (cli.h): the same options, values (both "--opt V" and "--opt=V") and
 *   operands in order; "--" ends the options; a usage error (unknown
 *   option, repeated, missing value, value to a flag) exactly where the
 *   model has one, with one line on stderr and none before.
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

/* The model of the option grammar (cli.h, cli_opts): the next result for
 * argv from *i, as cli_opts_next should give it. */
typedef struct model {
    int i, ended;
    uint64_t seen;
} model;

static const char *const m_valued[] = {"--seed", "--size", "--target", NULL};
static const char *const m_flags[] = {"--stats", "--quiet", NULL};
static const char *const m_repeatable[] = {"--target", NULL};

static int m_find(const char *const *list, const char *a, size_t n)
{
    for (int k = 0; list[k]; k++)
        if (strlen(list[k]) == n && !strncmp(list[k], a, n))
            return k;
    return -1;
}

static int m_next(model *m, int argc, char **argv, const char **opt, const char **val)
{
    if (!m->ended && m->i < argc && !strcmp(argv[m->i], "--")) {
        m->ended = 1;
        m->i++;
    }
    if (m->i >= argc)
        return 0;
    const char *a = argv[m->i++];
    *opt = NULL;
    *val = a;
    if (m->ended || a[0] != '-' || !a[1])
        return 1;
    size_t n = a[1] == '-' ? strcspn(a, "=") : strlen(a);
    int kv = m_find(m_valued, a, n), kf = m_find(m_flags, a, n);
    int bit = kv >= 0 ? kv : kf >= 0 ? 3 + kf : -1;
    if (bit < 0)
        return -1; /* unknown */
    if ((m->seen >> bit & 1) && m_find(m_repeatable, a, n) < 0)
        return -1; /* given twice */
    m->seen |= (uint64_t)1 << bit;
    *opt = kv >= 0 ? m_valued[kv] : m_flags[kf];
    *val = NULL;
    if (kf >= 0)
        return a[n] == '=' ? -1 : 1; /* a flag takes no value */
    if (a[n] == '=') {
        *val = a + n + 1;
        return 1;
    }
    if (m->i >= argc)
        return -1; /* needs a value */
    *val = argv[m->i++];
    return 1;
}

/* An argument list (one argument a line) through cli_opts_next, against
 * the model: the same options, values and operands in order; a usage
 * error exactly where the model has one, as one line on stderr. */
static void check_opts(const uint8_t *d, size_t n)
{
    char *text = malloc(n + 1), *argv[34];
    CHECK(text != NULL);
    memcpy(text, d, n);
    text[n] = 0;
    int argc = 0;
    argv[argc++] = (char *)"fuzz";
    for (char *a = text; argc < 33;) {
        argv[argc++] = a;
        char *e = strchr(a, '\n');
        if (!e)
            break;
        *e = 0;
        a = e + 1;
    }
    argv[argc] = NULL;
    cli_opts p;
    cli_opts_init(&p, "fuzz", argc, argv, m_valued, m_flags);
    p.repeatable = m_repeatable;
    model m = {1, 0, 0};
    char *out = NULL;
    size_t on = 0;
    FILE *mem = open_memstream(&out, &on), *saved = stderr;
    CHECK(mem != NULL);
    int r, want;
    do {
        const char *o1 = NULL, *v1 = NULL, *o2 = NULL, *v2 = NULL;
        stderr = mem;
        r = cli_opts_next(&p, &o1, &v1);
        stderr = saved;
        want = m_next(&m, argc, argv, &o2, &v2);
        CHECK(r == want);
        if (r == 1)
            CHECK(o1 == o2 && v1 == v2);
    } while (r == 1);
    fclose(mem);
    CHECK(r == 0 ? on == 0 : on > 0 && memchr(out, '\n', on) == out + on - 1);
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
        check_opts(data + 1, size - 1);
    return 0;
}
