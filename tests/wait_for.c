/* wait_for.c - test helper: wait, in one process, until something happens
 * (the shell suites polled with a `sleep` process a poll: about 7 ms of CPU
 * each on a loaded machine, hundreds a suite).
 *
 * Usage: wait_for SECONDS COND...  where COND is one of
 *   -e PATH        PATH exists (a file, a folder, a FIFO, anything)
 *   -n DIR PREFIX N  DIR holds at least N entries whose names begin with PREFIX
 *   -c DIR N       DIR holds other than N entries (names beginning with a
 *                  dot not counted, as by ls; a missing DIR holds 0)
 *   -l FILE N      FILE holds at least N lines (newlines)
 *   -p PID         process PID has ended (gone, or a zombie not yet reaped)
 * Polls every 5 ms until one COND holds (exit 0) or SECONDS (wall time,
 * decimals allowed) have passed (exit 1); 2 on a usage error. */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static long count(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    long n = 0;
    size_t k = prefix ? strlen(prefix) : 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.' && (!prefix || prefix[0] != '.'))
            continue;
        if (!prefix || !strncmp(e->d_name, prefix, k))
            n++;
    }
    closedir(d);
    return n;
}

static long lines(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    long n = 0;
    char buf[4096];
    size_t k;
    while ((k = fread(buf, 1, sizeof buf, f)) > 0)
        for (size_t i = 0; i < k; i++)
            n += buf[i] == '\n';
    fclose(f);
    return n;
}

static int ended(long pid)
{
    if (kill((pid_t)pid, 0) != 0 && errno == ESRCH)
        return 1;
    char path[64], buf[512];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *f = fopen(path, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    const char *p = strrchr(buf, ')'); /* "PID (COMM) S ..." */
    return p && p[1] == ' ' && (p[2] == 'Z' || p[2] == 'X');
}

/* 1 when the condition at argv[*i] holds; advances *i past it; -1 on a
 * usage error */
static int holds(int argc, char **argv, int *i)
{
    const char *c = argv[*i];
    struct stat st;
    if (!strcmp(c, "-e") && *i + 1 < argc) {
        *i += 2;
        return lstat(argv[*i - 1], &st) == 0;
    }
    if (!strcmp(c, "-n") && *i + 3 < argc) {
        *i += 4;
        return count(argv[*i - 3], argv[*i - 2]) >= atol(argv[*i - 1]);
    }
    if (!strcmp(c, "-c") && *i + 2 < argc) {
        *i += 3;
        return count(argv[*i - 2], NULL) != atol(argv[*i - 1]);
    }
    if (!strcmp(c, "-l") && *i + 2 < argc) {
        *i += 3;
        return lines(argv[*i - 2]) >= atol(argv[*i - 1]);
    }
    if (!strcmp(c, "-p") && *i + 1 < argc) {
        *i += 2;
        return ended(atol(argv[*i - 1]));
    }
    return -1;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec / 1e9;
}

int main(int argc, char **argv)
{
    char *end = NULL;
    double limit = argc > 2 ? strtod(argv[1], &end) : -1;
    if (argc < 3 || !end || *end || !(limit >= 0)) {
        fprintf(stderr, "usage: wait_for SECONDS -e PATH | -n DIR PREFIX N | -c DIR N | -l FILE N | -p PID ...\n");
        return 2;
    }
    double t_end = now_s() + limit;
    for (;;) {
        for (int i = 2; i < argc;) {
            int h = holds(argc, argv, &i);
            if (h < 0) {
                fprintf(stderr, "wait_for: bad condition '%s'\n", argv[i]);
                return 2;
            }
            if (h)
                return 0;
        }
        if (now_s() >= t_end)
            return 1;
        nanosleep(&(struct timespec){0, 5 * 1000 * 1000}, NULL);
    }
}
