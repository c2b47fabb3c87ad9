/* cmd_report.c - `holonomy report LOGDIR... --out DIR`: what a researcher
 * looks at first (issue 18 section 7). Reads log folders, writes per-attempt
 * pictures, attempts.csv, conditions.csv and index.html into DIR. */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../image/hol_png_file.h"
#include "cli.h"
#include "cmd_report.h"
#include "report_draw.h"

static const char *const report_usage =
    "usage: holonomy report LOGDIR... --out DIR\n"
    "\n"
    "Reads the research logs of one or more log folders (play/replay/xr --log:\n"
    "summary.csv, steps-NNN.csv, level-HASH.txt) and writes into DIR:\n"
    "  attempts.csv     one row per attempt of every folder: participant, session,\n"
    "                   attempt, study, condition, position, level, mode, steps,\n"
    "                   optimum, efficiency (optimum/steps of a completed scored\n"
    "                   attempt, else empty), time, end, tiling, room, cell,\n"
    "                   logdir, picture (RFC 4180, for R or pandas)\n"
    "  conditions.csv   per condition (study and condition; outside a study the\n"
    "                   level): attempts, done, mean steps, efficiency, time\n"
    "  attempt-NNNN.png each attempt's walked path beside the optimal walk on the\n"
    "                   Poincare disk (360 x 360), numbered in the order of the rows\n"
    "  index.html       a page with both tables and the pictures\n"
    "DIR is made when it does not exist (its parent must); an existing DIR must\n"
    "be empty or hold only a report's files (they are replaced). A malformed log\n"
    "is refused naming its file and line; a missing steps or level file is a\n"
    "warning (no picture, or no optimal walk in it). Killed and aborted attempts\n"
    "are listed with that end.\n"
    "\n"
    "Exit status: 0 ok, 1 failure (writing), 2 bad input or usage.\n";

/* Names a report writes (and the atomic writer's temporary files). */
static int own_name(const char *n)
{
    size_t l = strlen(n);
    if (!strcmp(n, ".") || !strcmp(n, "..") || !strcmp(n, "index.html") ||
        !strcmp(n, "attempts.csv") || !strcmp(n, "conditions.csv"))
        return 1;
    if (n[0] == '.' && strstr(n, ".holonomy-tmp."))
        return 1;
    return l == 16 && !strncmp(n, "attempt-", 8) && strspn(n + 8, "0123456789") == 4 &&
           !strcmp(n + 12, ".png");
}

/* DIR: a folder of a report's files only, or a new name in a folder. */
static int check_out_dir(const char *cmd, const char *dir)
{
    char esc[512];
    struct stat sb;
    cli_escape(dir, esc, sizeof esc);
    if (stat(dir, &sb)) {
        char parent[4096];
        snprintf(parent, sizeof parent, "%s", dir);
        size_t n = strlen(parent);
        while (n > 1 && parent[n - 1] == '/')
            parent[--n] = 0; /* "new/" is the folder "new" */
        char *slash = strrchr(parent, '/');
        const char *p = slash ? (slash == parent ? "/" : (*slash = 0, parent)) : ".";
        if (errno == ENOENT && !stat(p, &sb) && S_ISDIR(sb.st_mode))
            return 0;
        cli_error(cmd, 0, "--out '%s': its folder does not exist", esc);
        return CLI_EXIT_USAGE;
    }
    if (!S_ISDIR(sb.st_mode)) {
        cli_error(cmd, 0, "--out '%s' is not a folder", esc);
        return CLI_EXIT_USAGE;
    }
    DIR *d = opendir(dir);
    if (!d) {
        cli_error(cmd, 0, "--out '%s' cannot be read", esc);
        return CLI_EXIT_USAGE;
    }
    struct dirent *e;
    while ((e = readdir(d)))
        if (!own_name(e->d_name)) {
            char n[256];
            cli_error(cmd, 0, "--out '%s' holds '%s', not a report's file; give an empty "
                      "or new folder", esc, cli_escape(e->d_name, n, sizeof n));
            closedir(d);
            return CLI_EXIT_USAGE;
        }
    closedir(d);
    static const char *const names[] = {"index.html", "attempts.csv", "conditions.csv"};
    for (int i = 0; i < 3; i++) {
        char path[4200];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        if (!stat(path, &sb) && cli_check_output(cmd, "--out", path))
            return CLI_EXIT_USAGE;
    }
    return 0;
}

static const char *const report_valued[] = {"--out", NULL};

static int parse_args(report_run *r, int argc, char **argv)
{
    static const char *const flags[] = {NULL};
    cli_opts p;
    cli_opts_init(&p, r->cmd, argc, argv, report_valued, flags);
    const char *opt, *val;
    int got;
    r->dirs = calloc((size_t)argc, sizeof *r->dirs);
    if (!r->dirs)
        return CLI_EXIT_FAIL;
    while ((got = cli_opts_next(&p, &opt, &val)) > 0) {
        if (opt)
            r->out = val;
        else
            r->dirs[r->ndirs++] = (char *)val;
    }
    if (got < 0)
        return CLI_EXIT_USAGE;
    const char *bad = !r->ndirs ? "no log folder given; see 'holonomy report --help'"
                      : !r->out ? "--out DIR is required; see 'holonomy report --help'"
                                : NULL;
    if (bad) {
        cli_error(r->cmd, 0, "%s", bad);
        return CLI_EXIT_USAGE;
    }
    for (int i = 0; i < r->ndirs; i++) {
        int st = cli_require_folder(r->cmd, NULL, r->dirs[i]);
        const cli_path in = {"the log folder", r->dirs[i]}, out = {"--out", r->out};
        if (!st)
            st = cli_check_distinct(r->cmd, &in, 1, &out, 1);
        if (st)
            return st;
    }
    return check_out_dir(r->cmd, r->out);
}

static int make_out(const report_run *r)
{
    if (mkdir(r->out, 0777) && errno != EEXIST) {
        char esc[512];
        cli_error(r->cmd, 0, "--out '%s' cannot be made: %s",
                  cli_escape(r->out, esc, sizeof esc), strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

typedef struct report_buf {
    hol_tile *walked;
    hol_tile optimal[HOL_NAV_WALK_MAX];
    hol_tile goals[HOL_APP_MAX_OBJECTIVES];
    uint8_t rgba[REPORT_PNG_SIZE * REPORT_PNG_SIZE * 4];
} report_buf;

/* One attempt's picture (when its steps file is there). */
static int picture(report_run *r, report_buf *b, int i, int write)
{
    report_att *t = &r->att[i];
    report_picture p;
    memset(&p, 0, sizeof p);
    int st = report_walk(r, t, write ? b->walked : NULL, &p.nwalked);
    if (!st)
        st = report_optimal(r, t, &p.start, b->goals, &p.ngoals, &p.chest_last, b->optimal,
                            &p.noptimal);
    if (st || !write || !t->has_walk)
        return st;
    p.walked = b->walked;
    p.optimal = b->optimal;
    p.goals = b->goals;
    snprintf(t->png, sizeof t->png, "attempt-%04d.png", i + 1);
    char path[4200], esc[512];
    snprintf(path, sizeof path, "%s/%s", r->out, t->png);
    if (report_draw(&p, b->rgba, REPORT_PNG_SIZE) ||
        hol_png_write_file(path, b->rgba, REPORT_PNG_SIZE, REPORT_PNG_SIZE, 0)) {
        cli_error(r->cmd, 0, "cannot write '%s'", cli_escape(path, esc, sizeof esc));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

/* Pictures from an earlier report in DIR beyond this one's are removed. */
static void remove_stale(const report_run *r)
{
    DIR *d = opendir(r->out);
    struct dirent *e;
    while (d && (e = readdir(d))) {
        int n = atoi(e->d_name + 8);
        if (own_name(e->d_name) && !strncmp(e->d_name, "attempt-", 8) &&
            (n > r->natt || !r->att[n - 1].png[0])) {
            char path[4200];
            snprintf(path, sizeof path, "%s/%s", r->out, e->d_name);
            remove(path);
        }
    }
    if (d)
        closedir(d);
}

static int run(report_run *r, report_buf *b)
{
    int st = report_read_summaries(r);
    /* first every steps file and level is checked, then anything written */
    for (int i = 0; !st && i < r->natt; i++)
        st = picture(r, b, i, 0);
    if (!st)
        st = make_out(r);
    r->quiet = 1;
    for (int i = 0; !st && i < r->natt; i++)
        st = picture(r, b, i, 1);
    static hol_report_agg g;
    memset(&g, 0, sizeof g);
    for (int i = 0; !st && i < r->natt; i++)
        hol_report_agg_add(&g, &r->att[i].a);
    if (!st)
        st = report_write_csv(r);
    if (!st)
        st = report_write_conditions(r, &g);
    if (!st)
        st = report_write_html(r, &g);
    if (!st) {
        remove_stale(r);
        printf("report: %d attempts from %d log folder%s\n", r->natt, r->ndirs,
               r->ndirs == 1 ? "" : "s");
    }
    return st;
}

int cli_cmd_report(int argc, char **argv)
{
    const char *cmd = "report";
    if (cli_wants_help(argc, argv, report_valued)) {
        fputs(report_usage, stdout);
        return cli_finish_output(cmd);
    }
    static report_run r;
    memset(&r, 0, sizeof r);
    r.cmd = cmd;
    report_buf *b = calloc(1, sizeof *b);
    int st = b ? 0 : CLI_EXIT_FAIL;
    if (!st && !(b->walked = malloc(sizeof *b->walked * REPORT_MAX_STEPS)))
        st = CLI_EXIT_FAIL;
    if (st)
        cli_error(cmd, 0, "out of memory");
    if (!st)
        st = parse_args(&r, argc, argv);
    if (!st)
        st = run(&r, b);
    if (!st)
        st = cli_finish_output(cmd);
    report_free(&r);
    free(r.dirs);
    if (b)
        free(b->walked);
    free(b);
    return st;
}
