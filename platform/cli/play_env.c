/* play_env.c - --session, --meta, the study's hash and environment.csv
 * (play_env.h). */
#include "play_env.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <sys/utsname.h>
#include <unistd.h>

#include "../../core/hol_rec.h"
#include "../../core/hol_sha256.h"
#include "../../core/hol_text.h"
#include "../file/hol_file.h"
#include "../shell/hol_shell_env.h"
#include "cli.h"
#include "play_track.h"

static int play_env__meta(const char *cmd, const char *val, play_env *e)
{
    const char *eq = strchr(val, '=');
    size_t n = eq ? (size_t)(eq - val) : 0;
    if (!eq || !hol_rec_meta_key_ok(val, n)) {
        cli_error(cmd, 0, "--meta '%.40s' is not KEY=VALUE with KEY 1..32 of a-z, 0-9, '_'", val);
        return -1;
    }
    if (strlen(eq + 1) > 200 || strchr(eq + 1, ';')) {
        cli_error(cmd, 0, "--meta '%.*s': its value is over 200 bytes or holds ';'", (int)n, val);
        return -1;
    }
    if (e->nmeta == PLAY_ENV_META_MAX) {
        cli_error(cmd, 0, "--meta is given more than %d times", PLAY_ENV_META_MAX);
        return -1;
    }
    for (int i = 0; i < e->nmeta; i++)
        if (!strncmp(e->meta[i], val, n + 1)) {
            cli_error(cmd, 0, "--meta key '%.*s' is given twice", (int)n, val);
            return -1;
        }
    e->meta[e->nmeta++] = val;
    return 1;
}

int play_env_value(const char *cmd, const char *opt, const char *val, play_env *e)
{
    if (!strcmp(opt, "--meta"))
        return play_env__meta(cmd, val, e);
    if (strcmp(opt, "--session"))
        return 0;
    size_t n = cli_parse_count(val);
    if (!n || n > 999) {
        cli_error(cmd, 0, "--session '%.40s' is not a session number in 1..999", val);
        return -1;
    }
    e->session_no = (int)n;
    return 1;
}

int play_opts_check(const char *cmd, const unsigned char given[HOL_SHELL_OPT_COUNT],
                    const play_env *e, const char *log_dir, int track_hz)
{
    char msg[200];
    if (hol_shell_clash(given, msg, sizeof msg)) {
        cli_error(cmd, 0, "%s", msg);
        return 1;
    }
    return play_env_check(cmd, e, log_dir) != 0 || play_track_check(cmd, track_hz, log_dir) != 0;
}

int play_env_check(const char *cmd, const play_env *e, const char *log_dir)
{
    if ((e->session_no || e->nmeta) && !log_dir) {
        cli_error(cmd, 0, "%s goes with --log", e->session_no ? "--session" : "--meta");
        return CLI_EXIT_USAGE;
    }
    size_t esc = 0;
    for (int i = 0; log_dir && i < e->argc; i++)
        esc += (i > 0) + hol_text_escape(e->argv[i], strlen(e->argv[i]), NULL, 0);
    if (esc >= HOL_SHELL_ENV_FIELD_MAX) {
        cli_error(cmd, 0, "the command line is %zu bytes once escaped; environment.csv's options "
                          "column holds at most %d: shorten it", esc, HOL_SHELL_ENV_FIELD_MAX - 1);
        return CLI_EXIT_USAGE;
    }
    char name[4200], msg[200];
    struct stat st;
    if (log_dir && snprintf(name, sizeof name, "%s/environment.csv", log_dir) > 0 &&
        lstat(name, &st) == 0 && hol_file_check_out(name, msg, sizeof msg)) {
        cli_error(cmd, 0, "--log: '%.200s' %s", name, msg);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

/* KEY=VALUE;... or the command line, joined with sep into out. */
static void join(char *out, size_t cap, const char *const *v, int n, const char *sep)
{
    size_t at = 0;
    out[0] = 0;
    for (int i = 0; i < n && at < cap; i++) {
        int w = snprintf(out + at, cap - at, "%s%s", i ? sep : "", v[i]);
        if (w < 0)
            break;
        at += (size_t)w;
    }
}

int play_env_meta(const char *cmd, const play_env *e, const char *study_path, hol_rec_meta *m,
                  char **out_study, size_t *out_len)
{
    m->session_no = e->session_no;
    m->study_sha256[0] = 0;
    *out_study = NULL;
    *out_len = 0;
    if (study_path) {
        uint8_t *data = NULL, dig[32];
        if (hol_file_read_all(study_path, 1 << 20, &data, out_len)) {
            cli_error(cmd, 0, "cannot read --study '%.200s' again", study_path);
            return 1;
        }
        hol_sha256(data, *out_len, dig);
        hol_sha256_hex(dig, m->study_sha256);
        *out_study = (char *)data;
    }
    static char raw[PLAY_ENV_META_MAX * 240];
    join(raw, sizeof raw, e->meta, e->nmeta, ";");
    size_t need = hol_text_escape(raw, strlen(raw), m->meta, sizeof m->meta);
    if (need >= sizeof m->meta || !hol_rec_meta_ok(m->meta)) {
        cli_error(cmd, 0, "--meta: the notes do not fit the logs");
        return 1;
    }
    return 0;
}

static int play_env_append(const char *cmd, const char *dir, const char *row)
{
    char name[4200];
    snprintf(name, sizeof name, "%s/environment.csv", dir);
    int fd = open(name, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
    struct stat st;
    int ok = fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    if (fd >= 0 && !ok) {
        close(fd);
        cli_error(cmd, 0, "'%.200s' is not a regular file", name);
        return 1;
    }
    /* the header (a new file), the row and its newline: one writev */
    static const char head[] = HOL_SHELL_ENV_COLUMNS "\n";
    struct iovec v[3] = {{(void *)head, ok && st.st_size == 0 ? sizeof head - 1 : 0},
                         {(void *)row, strlen(row)}, {(void *)"\n", 1}};
    ssize_t want = (ssize_t)(v[0].iov_len + v[1].iov_len + 1);
    ok = ok && writev(fd, v, 3) == want && fsync(fd) == 0;
    int e = errno;
    if (fd >= 0)
        close(fd);
    if (!ok) {
        cli_error_end(cmd, "cannot write '%.200s': %s", name, strerror(e));
        return 1;
    }
    return 0;
}

int play_env_write(const char *cmd, const char *log_dir, const play_env *e, const char *session,
                   const char *participant, const char *study_sha256, const play_env_host *h,
                   int argc, char **argv)
{
    if (!log_dir)
        return 0;
    static char row[HOL_SHELL_ENV_ROW_MAX], opts[HOL_SHELL_ENV_FIELD_MAX];
    char os[400] = "", meta[HOL_REC_META_TEXT];
    struct utsname u;
    if (uname(&u) == 0)
        snprintf(os, sizeof os, "%s %s %s", u.sysname, u.release, u.machine);
    join(meta, sizeof meta, e->meta, e->nmeta, ";");
    join(opts, sizeof opts, (const char *const *)argv, argc, " ");
    const hol_shell_env_fields f = {session, participant, e->session_no, study_sha256,
                                    h->platform, os, h->runtime, h->gl_renderer, h->controller,
                                    h->refresh_hz, h->width, h->height, meta, opts};
    size_t n;
    if (hol_shell_env_row(&f, 0, row, sizeof row, &n)) {
        cli_error(cmd, 0, "the environment row is too long");
        return 1;
    }
    return play_env_append(cmd, log_dir, row);
}
