#define _POSIX_C_SOURCE 200809L
#include "../../core/hol_room.h"
#include "../../core/hol_session.h"
#include "../../core/hol_str.h"
#include "cli.h"

#include "../../core/hol_text.h"
#include "../file/hol_file.h"
#include "../file/hol_lines.h"
#include "../file/hol_sink_posix.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int cli__in_list(const char *const *list, const char *a, size_t n);

const char *cli_escape(const char *s, char *buf, size_t cap)
{
    hol_text_escape(s, strlen(s), buf, cap);
    return buf;
}

static int cli__said; /* error lines said in this run (cli_error_end) */

static void cli__verror(const char *cmd, long lineno, const char *fmt, va_list ap)
{
    char msg[512];
    vsnprintf(msg, sizeof msg, fmt, ap);
    /* one line, whatever the message holds: control bytes (from option
     * values, file names, input) are shown escaped, never sent raw */
    char safe[4 * sizeof msg];
    hol_text_escape(msg, strlen(msg), safe, sizeof safe);
    const char *sep = cmd[0] ? " " : "";
    if (lineno > 0)
        fprintf(stderr, "holonomy%s%s: line %ld: %s\n", sep, cmd, lineno, safe);
    else
        fprintf(stderr, "holonomy%s%s: %s\n", sep, cmd, safe);
    cli__said = 1;
}

void cli_error(const char *cmd, long lineno, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cli__verror(cmd, lineno, fmt, ap);
    va_end(ap);
}

void cli_error_end(const char *cmd, const char *fmt, ...)
{
    if (cli__said)
        return;
    va_list ap;
    va_start(ap, fmt);
    cli__verror(cmd, 0, fmt, ap);
    va_end(ap);
}

int cli_split(char *s, size_t len, char **fields, size_t *lens, int max)
{
    int n = 0;
    size_t i = 0;
    while (i < len) {
        while (i < len && (s[i] == ' ' || s[i] == '\t'))
            i++;
        if (i >= len)
            break;
        size_t start = i;
        while (i < len && s[i] != ' ' && s[i] != '\t')
            i++;
        if (n == max)
            return max + 1;
        fields[n] = s + start;
        lens[n] = i - start;
        n++;
    }
    return n;
}

int cli_read_file(const char *cmd, const char *what, const char *path, size_t max,
                  uint8_t **out_data, size_t *out_size)
{
    hol_err err = hol_file_read_all(path, max, out_data, out_size);
    switch (err) {
    case HOL_OK:
        return 0;
    case HOL_EOPEN:
        cli_error(cmd, 0, "cannot open %s '%.200s': %s", what, path, strerror(errno));
        return CLI_EXIT_USAGE;
    case HOL_EARG:
        cli_error(cmd, 0, "%s '%.200s' is %s, not a regular file", what, path,
                  errno == EISDIR ? "a directory" : "a FIFO, socket or device");
        return CLI_EXIT_USAGE;
    case HOL_ECORRUPT:
        cli_error(cmd, 0, "%s '%.200s' is larger than %zu bytes", what, path, max);
        return CLI_EXIT_USAGE;
    case HOL_ENOMEM:
        cli_error(cmd, 0, "out of memory reading %s '%.200s'", what, path);
        return CLI_EXIT_FAIL;
    default:
        cli_error(cmd, 0, "cannot read %s '%.200s': %s", what, path, strerror(errno));
        return CLI_EXIT_FAIL;
    }
}

int cli_open_lines(const char *cmd, const char *what, const char *path, size_t limit,
                   hol_lines *l)
{
    hol_err err = hol_lines_open(l, path, limit);
    if (err == HOL_EARG)
        cli_error(cmd, 0, "%s '%.200s' is %s, not a regular file", what, path,
                  errno == EISDIR ? "a directory" : "a FIFO, socket or device");
    else if (err == HOL_ENOMEM)
        cli_error(cmd, 0, "out of memory reading %s '%.200s'", what, path);
    else if (err)
        cli_error(cmd, 0, "cannot open %s '%.200s': %s", what, path, strerror(errno));
    return !err ? 0 : err == HOL_ENOMEM ? CLI_EXIT_FAIL : CLI_EXIT_USAGE;
}

int cli_lines_failed(const char *cmd, const char *what, const char *path, const hol_lines *l)
{
    if (l->err == HOL_ENOMEM) {
        cli_error(cmd, l->lineno, "%s '%.200s': longer than %zu bytes", what, path, l->limit);
        return CLI_EXIT_USAGE;
    }
    cli_error(cmd, 0, "cannot read %s '%.200s': %s", what, path, strerror(errno));
    return CLI_EXIT_FAIL;
}

int cli_require_folder(const char *cmd, const char *opt, const char *path)
{
    struct stat st;
    if (!path || (!stat(path, &st) && S_ISDIR(st.st_mode)))
        return 0;
    if (opt)
        cli_error(cmd, 0, "%s '%.200s' is not a folder", opt, path);
    else
        cli_error(cmd, 0, "'%.200s' is not a folder", path);
    return CLI_EXIT_USAGE;
}

int cli_check_output(const char *cmd, const char *opt, const char *path)
{
    char why[160];
    if (!path || !hol_file_check_out(path, why, sizeof why))
        return 0;
    cli_error(cmd, 0, "%s%s'%.200s' %s; an output is a regular file or a new name in an "
              "existing folder", opt ? opt : "", opt ? " " : "", path, why);
    return CLI_EXIT_USAGE;
}

int cli_check_distinct(const char *cmd, const cli_path *in, int nin, const cli_path *out,
                       int nout)
{
    for (int o = 0; o < nout; o++) {
        struct stat so, si;
        /* an output that does not exist yet is no input (each input exists) */
        if (!out[o].path || stat(out[o].path, &so))
            continue;
        for (int i = 0; i < nin; i++)
            if (in[i].path && !stat(in[i].path, &si) && si.st_dev == so.st_dev &&
                si.st_ino == so.st_ino) {
                cli_error(cmd, 0, "%s '%.200s' is %s '%.200s', which this command reads; give "
                                  "the output another name",
                          out[o].opt, out[o].path, in[i].opt, in[i].path);
                return CLI_EXIT_USAGE;
            }
    }
    return 0;
}

/* 1 when a --log folder's entry name is a file the session writes there. */
static int cli__written_in_log(const char *name)
{
    size_t n = strlen(name);
    return hol_session_is_log_name(name) || !strcmp(name, "environment.csv") ||
           !strcmp(name, "provenance.csv") || !strcmp(name, "order.csv") ||
           !strcmp(name, "codebook.csv") || !strcmp(name, "codebook.csv.new") ||
           !strcmp(name, HOL_SINK_POSIX_LOCK) ||
           (!strncmp(name, "study-", 6) && n > 10 && !strcmp(name + n - 4, ".txt"));
}

int cli_check_reads(const char *cmd, const cli_path *in, int nin, const cli_outs *outs)
{
    if (cli_check_distinct(cmd, in, nin, outs->out, outs->nout))
        return CLI_EXIT_USAGE;
    DIR *d = outs->log_dir ? opendir(outs->log_dir) : NULL;
    struct dirent *e;
    int st = 0;
    while (d && !st && (e = readdir(d)) != NULL) {
        struct stat sl, si;
        if (!cli__written_in_log(e->d_name) || fstatat(dirfd(d), e->d_name, &sl, 0))
            continue;
        for (int i = 0; i < nin && !st; i++)
            if (in[i].path && !stat(in[i].path, &si) && si.st_dev == sl.st_dev &&
                si.st_ino == sl.st_ino) {
                cli_error(cmd, 0, "%s '%.200s' is '%.60s' of --log '%.200s', which this command "
                                  "writes; read a copy from another folder",
                          in[i].opt, in[i].path, e->d_name, outs->log_dir);
                st = CLI_EXIT_USAGE;
            }
    }
    if (d)
        closedir(d);
    return st;
}

int cli_store_opt(const cli_store *t, const char *a, const char *val, void *opts)
{
    for (; t->opt; t++)
        if (!strcmp(t->opt, a)) {
            char *field = (char *)opts + t->off;
            if (t->is_flag)
                memcpy(field, &t->value, sizeof t->value);
            else
                memcpy(field, &val, sizeof val);
            return 1;
        }
    return 0;
}

int cli_finish_output(const char *cmd)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        cli_error(cmd, 0, "cannot write output: %s", strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return CLI_EXIT_OK;
}

int cli_wants_help(int argc, char **argv, const char *const *valued)
{
    for (int i = 1; i < argc && strcmp(argv[i], "--"); i++) {
        if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help"))
            return 1;
        /* the value of an option is never an option: "--seed -h" */
        if (cli__in_list(valued, argv[i], strlen(argv[i])))
            i++;
    }
    return 0;
}

int cli_help(const char *cmd, int argc, char **argv, const char *const *valued,
             const char *usage)
{
    if (!cli_wants_help(argc, argv, valued))
        return -1;
    fputs(usage, stdout);
    return cli_finish_output(cmd);
}

int cli_for_each_line(const char *cmd, cli_line_fn fn, void *ctx)
{
    hol_lines in;
    char *s;
    size_t len;
    int r = 0, status = CLI_EXIT_OK;
    if (hol_lines_open_fd(&in, 0, CLI_LINE_MAX)) {
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    while (status == CLI_EXIT_OK && (r = hol_lines_next(&in, &s, &len)) > 0) {
        status = fn(ctx, in.lineno, s, len);
        /* the answers so far go out before the reader waits for more
         * input (a program feeding lines one at a time reads each answer) */
        if (in.pos == in.end)
            fflush(stdout);
    }
    if (status == CLI_EXIT_OK && r < 0 && in.err == HOL_ENOMEM) {
        cli_error(cmd, in.lineno, "longer than %d bytes", CLI_LINE_MAX);
        status = CLI_EXIT_USAGE;
    } else if (status == CLI_EXIT_OK && r < 0) {
        cli_error(cmd, 0, "cannot read input: %s", strerror(errno));
        status = CLI_EXIT_FAIL;
    }
    hol_lines_close(&in);
    int out = cli_finish_output(cmd);
    return status ? status : out;
}

void cli_trim(char **s, size_t *len)
{
    while (*len > 0 && (**s == ' ' || **s == '\t')) {
        (*s)++;
        (*len)--;
    }
    while (*len > 0 && ((*s)[*len - 1] == ' ' || (*s)[*len - 1] == '\t'))
        (*len)--;
}

size_t cli_parse_count(const char *s)
{
    /* digits only: strtoull would also take leading blanks and a sign */
    if (!s || !*s)
        return 0;
    for (const char *p = s; *p; p++)
        if (*p < '0' || *p > '9')
            return 0;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || *end || v == 0 || v > (1ull << 40))
        return 0;
    return (size_t)v;
}

int cli_volume_value(const char *cmd, const char *v, double *out_volume)
{
    double x;
    if (!cli_parse_real(v, 0, 1, &x)) {
        cli_error(cmd, 0, "--volume '%.40s' is not a number in 0..1", v);
        return -1;
    }
    *out_volume = x;
    return 0;
}

int cli_lang_value(const char *cmd, const char *v, int *out_lang)
{
    int l = strlen(v) == 2 ? hol_lang_parse(v) : -1;
    if (l < 0 || strcmp(v, hol_lang_code(l))) {
        cli_error(cmd, 0, "--lang '%.40s' is not en, de or nl", v);
        return -1;
    }
    *out_lang = l;
    return 0;
}

int cli_budget_value(const char *cmd, const char *v, size_t *out_budget)
{
    if (!(*out_budget = cli_parse_count(v)) || *out_budget > CLI_BUDGET_MAX) {
        cli_error(cmd, 0, "--budget needs a node count 1..%d; see --help", CLI_BUDGET_MAX);
        return -1;
    }
    return 0;
}

/* The length of the plain decimal number at p (-D[.D][e[-+]D]: an
 * optional minus, digits, a point only between digits, an exponent), 0 if
 * there is none: strtod would also take blanks, a plus, hex, inf, nan, ".5"
 * and "5." (issue 39: one number grammar for every option). */
static size_t cli__decimal_len(const char *p)
{
    size_t i = p[0] == '-', d = 0;
    while (isdigit((unsigned char)p[i]))
        i++, d++;
    if (d == 0)
        return 0;
    if (p[i] == '.') {
        if (!isdigit((unsigned char)p[i + 1]))
            return 0;
        for (i++; isdigit((unsigned char)p[i]); i++)
            ;
    }
    if (p[i] == 'e' || p[i] == 'E') {
        size_t j = i + 1 + (p[i + 1] == '-' || p[i + 1] == '+'), e = j;
        while (isdigit((unsigned char)p[j]))
            j++;
        if (j > e)
            i = j;
    }
    return i;
}

int cli_parse_real(const char *s, double lo, double hi, double *out)
{
    double x;
    if (!cli_parse_doubles(s, &x, 1) || (lo >= 0 && s[0] == '-') || !(x >= lo && x <= hi))
        return 0;
    *out = x;
    return 1;
}

int cli_parse_wxd(const char *s, double lo, double hi, double *w, double *d)
{
    char buf[64];
    size_t n = strlen(s);
    const char *x = strpbrk(s, "xX");
    if (n >= sizeof buf || !x)
        return 0;
    memcpy(buf, s, n + 1);
    buf[x - s] = 0;
    return cli_parse_real(buf, lo, hi, w) && cli_parse_real(buf + (x - s) + 1, lo, hi, d);
}

int cli_parse_decimal(const char *s, uint64_t *out)
{
    for (const char *p = s; *p; p++)
        if (*p < '0' || *p > '9')
            return 0;
    return cli_parse_u64(s, out);
}

int cli_geometry_value(const char *cmd, const char *opt, const char *v, int *q, int *cols,
                       int *rows)
{
    if (!strcmp(opt, "--tiling")) {
        if (hol_room_parse_tiling(v, strlen(v), q)) {
            cli_error(cmd, 0, "--tiling needs 4,Q with Q from 4 to 8 (the tiling {4,Q}), not '%.40s'",
                      v);
            return -1;
        }
        return 1;
    }
    if (!cols || strcmp(opt, "--room"))
        return 0;
    if (hol_room_parse_size(v, strlen(v), cols, rows)) {
        cli_error(cmd, 0, "--room needs CxR with C and R from 3 to 5 (cells), not '%.40s'", v);
        return -1;
    }
    return 1;
}

int cli_parse_doubles(const char *s, double *out, int n)
{
    if (n < 1 || n > 16)
        return 0;
    double v[16];
    const char *p = s;
    for (int i = 0; i < n; i++) {
        char *end;
        size_t len = cli__decimal_len(p);
        errno = 0;
        v[i] = strtod(p, &end);
        if (!len || end != p + len || errno || !isfinite(v[i]))
            return 0;
        if (i + 1 < n ? *end != ',' : *end != 0)
            return 0;
        p = end + 1;
    }
    for (int i = 0; i < n; i++)
        out[i] = v[i];
    return 1;
}

int cli_parse_u64(const char *s, uint64_t *out)
{
    /* digits only: strtoull would also take blanks, a sign, and a second
     * 0x after the first */
    int hex = s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    const char *d = hex ? s + 2 : s;
    if (!*d)
        return 0;
    for (const char *p = d; *p; p++)
        if (hex ? !isxdigit((unsigned char)*p) : (*p < '0' || *p > '9'))
            return 0;
    char *end;
    errno = 0;
    /* decimal, or 0x hex; a leading 0 is not octal */
    unsigned long long v = strtoull(hex ? s + 2 : s, &end, hex ? 16 : 10);
    if (hex && (s[2] == '-' || s[2] == '+' || s[2] == ' '))
        return 0;
    if (errno || *end)
        return 0;
    *out = v;
    return 1;
}

static volatile sig_atomic_t cli__signal;

static void cli__on_signal(int sig)
{
    if (!cli__signal)
        cli__signal = sig;
}

void cli_catch_signals(void)
{
    static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = cli__on_signal;
    /* calls the signal interrupts go on (the loop polls the flag): without
     * it a SIGINT in the OpenXR runtime's IPC (Monado's recvmsg in
     * xrWaitFrame) failed that call, and xr ended as if the instance were
     * lost (exit 1, not 130) */
    sa.sa_flags = SA_RESTART;
    sigemptyset(&sa.sa_mask);
    for (int i = 0; i < 3; i++)
        sigaction(sigs[i], &sa, NULL);
    /* a write to a lost peer (an X display, a closed pipe) fails with EPIPE
     * and is reported, instead of ending the process unsaved */
    signal(SIGPIPE, SIG_IGN);
}

int cli_caught_signal(void)
{
    return (int)cli__signal;
}

void cli_opts_init(cli_opts *p, const char *cmd, int argc, char **argv,
                   const char *const *valued, const char *const *flags)
{
    memset(p, 0, sizeof *p);
    p->cmd = cmd;
    p->argc = argc;
    p->argv = argv;
    p->i = 1;
    p->valued = valued;
    p->flags = flags;
}

static int cli__in_list(const char *const *list, const char *a, size_t n)
{
    for (const char *const *v = list; v && *v; v++)
        if (strlen(*v) == n && !strncmp(a, *v, n))
            return 1;
    return 0;
}

/* The option's index in valued then flags (its first n bytes), or -1;
 * *takes a value. */
static int cli__opt_index(const cli_opts *p, const char *a, size_t n, int *takes,
                          const char **name)
{
    int k = 0;
    for (int t = 1; t >= 0; t--)
        for (const char *const *v = t ? p->valued : p->flags; v && *v; v++, k++)
            if (strlen(*v) == n && !strncmp(a, *v, n)) {
                *takes = t;
                *name = *v;
                return k;
            }
    return -1;
}

int cli_opts_next(cli_opts *p, const char **opt, const char **val)
{
    if (!p->ended && p->i < p->argc && !strcmp(p->argv[p->i], "--")) {
        p->ended = 1; /* the rest are operands, whatever they look like */
        p->i++;
    }
    if (p->i >= p->argc)
        return 0;
    const char *a = p->argv[p->i++];
    *opt = NULL;
    *val = a;
    if (p->ended || a[0] != '-' || !a[1])
        return 1;
    /* "--name=VALUE" is "--name VALUE" */
    size_t n = a[1] == '-' ? strcspn(a, "=") : strlen(a);
    const char *name = NULL;
    int takes = 0, k = cli__opt_index(p, a, n, &takes, &name);
    if (k < 0 || k >= 64) {
        cli_error(p->cmd, 0, "unknown option '%.40s'; see 'holonomy %s --help'", a, p->cmd);
        return -1;
    }
    if ((p->seen >> k & 1) && !cli__in_list(p->repeatable, a, n)) {
        cli_error(p->cmd, 0, "%.*s is given twice; give each option once", (int)(n < 40 ? n : 40), a);
        return -1;
    }
    p->seen |= (uint64_t)1 << k;
    *opt = name;
    *val = NULL;
    if (!takes && a[n] == '=') {
        cli_error(p->cmd, 0, "%s takes no value; see 'holonomy %s --help'", *opt, p->cmd);
        return -1;
    }
    if (takes && a[n] == '=') {
        *val = a + n + 1;
    } else if (takes) {
        if (p->i >= p->argc) {
            cli_error(p->cmd, 0, "%s needs a value; see 'holonomy %s --help'", *opt, p->cmd);
            return -1;
        }
        *val = p->argv[p->i++];
    }
    return 1;
}

int cli_size_value(const char *val, long lo, long hi, long *w, long *h)
{
    char buf[64];
    const char *x = strchr(val, 'x');
    size_t n = x ? (size_t)(x - val) : 0;
    if (!x || n == 0 || n >= sizeof buf)
        return 1;
    memcpy(buf, val, n);
    buf[n] = 0;
    size_t a = cli_parse_count(buf), b = cli_parse_count(x + 1);
    if (a < (size_t)lo || a > (size_t)hi || b < (size_t)lo || b > (size_t)hi)
        return 1;
    *w = (long)a;
    *h = (long)b;
    return 0;
}

int cli_parse_size(const char *cmd, const char *val, int *w, int *h)
{
    long a, b;
    if (cli_size_value(val, 16, 4096, &a, &b)) {
        cli_error(cmd, 0, "--size '%.40s' is not WxH with sides 16..4096", val);
        return 1;
    }
    *w = (int)a;
    *h = (int)b;
    return 0;
}
