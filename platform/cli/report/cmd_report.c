/* cmd_report.c - `holonomy report LOGDIR... --out DIR`: what a researcher
 * looks at first (issue 18 section 7). Reads log folders, writes per-attempt
 * pictures, attempts.csv, conditions.csv and index.html into DIR. */
#define _GNU_SOURCE /* syncfs */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../../render/hol_png.h"
#include "../cli.h"
#include "report.h"
#include "report_bids.h"
#include "report_draw.h"
#include "report_pstats.h"
#include "report_stats.h"

static const char *const report_usage =
    "usage: holonomy report LOGDIR... --out DIR [--bids DIR2] [--include-restarted]\n"
    "       holonomy report LOGDIR... --bids DIR2\n"
    "       holonomy report --class PUPILS --out DIR\n"
    "\n"
    "Reads the research logs of one or more log folders (play/replay/xr --log:\n"
    "summary.csv, steps-NNN.csv, level-HASH.txt) and writes into DIR:\n"
    "  attempts.csv     one row per attempt of every folder: participant, session,\n"
    "                   attempt, study, condition, position, level, mode, steps,\n"
    "                   optimum, efficiency (optimum/steps of a completed scored\n"
    "                   attempt, else empty), time, end, tiling, room, cell,\n"
    "                   logdir, picture, q (the tiling's Q), cues, minimap (the\n"
    "                   level's place), logdir_relative (the folder from DIR)\n"
    "                   (RFC 4180, for R or pandas)\n"
    "  conditions.csv   per condition (study and condition; outside a study the\n"
    "                   level): attempts, done, mean steps, efficiency, time\n"
    "  attempt-NNNN.png each attempt's walked path beside the optimal walk on the\n"
    "                   Poincare disk, re-centred and zoomed on the walk, steps as\n"
    "                   a colour ramp with numbers, a legend (480 x 480), numbered\n"
    "                   in the order of the rows\n"
    "  stats.csv        per condition and measure (completed attempts outside\n"
    "                   practice; pointing errors from points.csv, SSQ, TLX and\n"
    "                   Likert items from answers.csv): n, mean, SD, 95 % CI (t)\n"
    "  learning.csv     efficiency by position per condition (learning curves)\n"
    "  participants.csv per participant and condition: attempts, done, means\n"
    "  scores.csv       one row per questionnaire score, subscale or Likert item\n"
    "                   (a partial questionnaire with complete 0)\n"
    "  trials.csv       one row per attempt: participant, block, trial, factors,\n"
    "                   outcome, pointing errors, excluded (the reason it is left\n"
    "                   out of the participant-level statistics)\n"
    "  participants_stats.csv  per condition and measure over the participants'\n"
    "                   means: n, mean, SD, between- and within-subjects 95 % CI\n"
    "  paired.csv       each pair of a study's conditions: paired difference, its\n"
    "                   95 % CI, Cohen's d_z\n"
    "  effects.csv      each pair of a factor's levels (main effects): paired\n"
    "                   difference, its 95 % CI, d_z\n"
    "  index.html       a page with the tables, the statistics and the pictures\n"
    "DIR is made when it does not exist (its parent must); an existing DIR must\n"
    "be empty or hold only a report's files (they are replaced). A malformed log\n"
    "is refused naming its file and line; a missing steps or level file is a\n"
    "warning (no picture, or no optimal walk in it). Killed and aborted attempts\n"
    "are listed with that end.\n"
    "Participant ids are read in their one spelling: '2', '002' and 'p2' are P02\n"
    "(one line on stderr names every id so read). In a study, a participant's\n"
    "second run (in another folder, or in one folder under another spelling) is\n"
    "excluded as 'duplicate' (one line on stderr names it), a run replaced by\n"
    "--restart-participant as 'restarted'.\n"
    "--include-restarted keeps duplicate and restarted trials in the\n"
    "participant-level statistics (trials.csv's excluded still names them).\n"
    "--bids DIR2 writes each attempt's head and hand tracks (track-NNN.csv) as a\n"
    "BIDS-Motion dataset (BIDS 1.9): one run per attempt, tracking systems room and\n"
    "tile; DIR2 must be new or empty.\n"
    "--class PUPILS: a class's results from the pupils' answer files in PUPILS\n"
    "(NAME.csv as the web page downloads it, or NAME/answers.csv of a log folder):\n"
    "the pre-test's and post-test's items (level lines 'quiz pre', 'quiz post')\n"
    "and the lessons' predictions judged by the core's key, into DIR:\n"
    "class_items.csv (per item: answered, right, rate), class_pupils.csv (each\n"
    "pupil's pre and post score, gain),\n"
    "class_gain.csv (the mean gain, its 95 % CI, d_z, g_av beside Wu et al. 2020's\n"
    "0.24 and Coban et al. 2022's g = 0.38) and class_wrong.csv (the wrong answers\n"
    "given, how often).\n"
    "\n"
    "Exit status: 0 ok, 1 failure (writing), 2 bad input or usage.\n";

/* Names a report writes (and the atomic writer's temporary files). */
static int own_name(const char *n)
{
    size_t l = strlen(n);
    if (!strcmp(n, ".") || !strcmp(n, "..") || !strcmp(n, "index.html") ||
        !strcmp(n, "attempts.csv") || !strcmp(n, "conditions.csv") ||
        !strcmp(n, "stats.csv") || !strcmp(n, "learning.csv") || !strcmp(n, "participants.csv") ||
        !strcmp(n, "trials.csv") || !strcmp(n, "participants_stats.csv") ||
        !strcmp(n, "paired.csv") || !strcmp(n, "effects.csv") || !strcmp(n, "scores.csv") ||
        !strcmp(n, "codebook.csv") || !strcmp(n, "build.csv"))
        return 1;
    if (n[0] == '.' && strstr(n, ".holonomy-tmp."))
        return 1;
    /* attempt-NNNN.png: four digits, or the five of the last number a
     * report writes (attempt-10000.png) */
    size_t digits = l > 12 ? strspn(n + 8, "0123456789") : 0;
    return !strncmp(n, "attempt-", 8) && l == 12 + digits && !strcmp(n + 8 + digits, ".png") &&
           (digits == 4 || (digits == 5 && n[8] != '0' && atoi(n + 8) <= REPORT_MAX_ATTEMPTS));
}

/* An entry of DIR with a report's name must be a regular file: a folder,
 * a FIFO or a link there is not a report's (it would fail the writing or be
 * removed). */
static int own_file(const char *cmd, const char *dir, const char *n)
{
    char path[4200];
    struct stat sb;
    if (!strcmp(n, ".") || !strcmp(n, ".."))
        return 0;
    snprintf(path, sizeof path, "%s/%s", dir, n);
    if (!lstat(path, &sb) && S_ISREG(sb.st_mode))
        return 0;
    cli_error(cmd, 0, "--out '%.300s' holds '%.200s', %s; give an empty or new folder", dir, n,
              S_ISDIR(sb.st_mode) ? "a folder, not a report's file"
              : S_ISLNK(sb.st_mode) ? "a symbolic link, not a report's file"
                                     : "not a regular file");
    return CLI_EXIT_USAGE;
}

/* A new DIR: its name is not empty nor a dangling link, its folder exists. */
static int check_new_dir(const char *cmd, const char *dir)
{
    struct stat sb;
    int err = errno;
    if (!dir[0]) {
        cli_error(cmd, 0, "--out '': an empty name");
        return CLI_EXIT_USAGE;
    }
    if (!lstat(dir, &sb)) {
        cli_error(cmd, 0, "--out '%.300s' is a symbolic link to nothing%s", dir,
                  err == ELOOP ? " (a loop)" : "");
        return CLI_EXIT_USAGE;
    }
    char parent[4096];
    snprintf(parent, sizeof parent, "%s", dir);
    size_t n = strlen(parent);
    while (n > 1 && parent[n - 1] == '/')
        parent[--n] = 0; /* "new/" is the folder "new" */
    char *slash = strrchr(parent, '/');
    const char *p = slash ? (slash == parent ? "/" : (*slash = 0, parent)) : ".";
    if (err == ENOENT && !stat(p, &sb) && S_ISDIR(sb.st_mode))
        return 0;
    cli_error(cmd, 0, "--out '%.300s': its folder does not exist", dir);
    return CLI_EXIT_USAGE;
}

/* DIR: a folder of a report's files only, or a new name in a folder. */
static int check_out_dir(const char *cmd, const char *dir)
{
    struct stat sb;
    if (!dir[0] || stat(dir, &sb))
        return check_new_dir(cmd, dir);
    if (!S_ISDIR(sb.st_mode)) {
        cli_error(cmd, 0, "--out '%.300s' is not a folder", dir);
        return CLI_EXIT_USAGE;
    }
    DIR *d = opendir(dir);
    if (!d) {
        cli_error(cmd, 0, "--out '%.300s' cannot be read", dir);
        return CLI_EXIT_USAGE;
    }
    struct dirent *e;
    int st = 0;
    while (!st && (e = readdir(d))) {
        if (!own_name(e->d_name))
            cli_error(cmd, 0, "--out '%.300s' holds '%.200s', not a report's file; give an "
                      "empty or new folder", dir, e->d_name);
        st = !own_name(e->d_name) ? CLI_EXIT_USAGE : own_file(cmd, dir, e->d_name);
    }
    closedir(d);
    return st;
}

static const char *const report_valued[] = {"--out", "--bids", NULL};

static int parse_args(report_run *r, int argc, char **argv)
{
    static const char *const flags[] = {"--include-restarted", NULL};
    cli_opts p;
    cli_opts_init(&p, r->cmd, argc, argv, report_valued, flags);
    const char *opt, *val;
    int got;
    r->dirs = calloc((size_t)argc, sizeof *r->dirs);
    if (!r->dirs)
        return CLI_EXIT_FAIL;
    while ((got = cli_opts_next(&p, &opt, &val)) > 0) {
        if (opt && !strcmp(opt, "--include-restarted"))
            r->include_restarted = 1;
        else if (opt && !strcmp(opt, "--bids"))
            r->bids = val;
        else if (opt)
            r->out = val;
        else
            r->dirs[r->ndirs++] = (char *)val;
    }
    if (got < 0)
        return CLI_EXIT_USAGE;
    const char *bad = !r->ndirs ? "no log folder given; see 'holonomy report --help'"
                      : !r->out && !r->bids
                          ? "--out DIR is required; see 'holonomy report --help'"
                      : r->out && r->bids && !strcmp(r->out, r->bids)
                          ? "--bids must name another folder than --out"
                                : NULL;
    if (bad) {
        cli_error(r->cmd, 0, "%s", bad);
        return CLI_EXIT_USAGE;
    }
    for (int i = 0; i < r->ndirs; i++) {
        int st = cli_require_folder(r->cmd, NULL, r->dirs[i]);
        const cli_path in = {"the log folder", r->dirs[i]};
        const cli_path out[2] = {{"--out", r->out}, {"--bids", r->bids}};
        if (!st)
            st = cli_check_distinct(r->cmd, &in, 1, out, 2);
        if (st)
            return st;
    }
    int st = r->bids ? report_bids_check(r->cmd, r->bids) : 0;
    return st || !r->out ? st : check_out_dir(r->cmd, r->out);
}

static int make_out(const report_run *r)
{
    if (mkdir(r->out, 0777) && errno != EEXIST) {
        cli_error(r->cmd, 0, "--out '%.300s' cannot be made: %s", r->out, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

typedef struct report_buf {
    hol_tile *walked;
    hol_tile optimal[HOL_NAV_WALK_MAX];
    hol_tile goals[HOL_APP_MAX_OBJECTIVES];
    uint8_t px[REPORT_PNG_SIZE * REPORT_PNG_SIZE]; /* palette indices (report_draw.h) */
    uint8_t plte[768];
    int npal;
    uint8_t *background[9][REPORT_ZOOM_MAX + 1]; /* by q (5..8) and zoom, drawn on first use */
    report_edges edges; /* report_draw's, kept from picture to picture */
} report_buf;

/* A picture's bytes into DIR: a temporary file renamed over the name, not
 * synced one by one (10,000 fsyncs took minutes): report_sync syncs them
 * all at once, before the tables that name them are written. */
static int write_png(const char *path, const report_buf *b)
{
    uint8_t *data;
    size_t size;
    char tmp[4300];
    const char *slash = strrchr(path, '/');
    snprintf(tmp, sizeof tmp, "%.*s.holonomy-tmp.%s", (int)(slash - path + 1), path, slash + 1);
    if (hol_png_encode_indexed(b->px, REPORT_PNG_SIZE, REPORT_PNG_SIZE, b->plte, b->npal, &data,
                               &size))
        return -1;
    FILE *f = fopen(tmp, "wb");
    int ok = f && fwrite(data, 1, size, f) == size;
    ok = (f && fclose(f) == 0) && ok;
    free(data);
    if (ok && !rename(tmp, path))
        return 0;
    remove(tmp);
    return -1;
}

/* The pictures written (write_png) reach the disk. */
static int report_sync(const report_run *r)
{
    int fd = open(r->out, O_RDONLY | O_DIRECTORY);
#ifdef __linux__
    int ok = fd >= 0 && syncfs(fd) == 0;
#else
    sync();
    int ok = fd >= 0;
#endif
    if (fd >= 0)
        close(fd);
    if (ok)
        return 0;
    cli_error(r->cmd, 0, "cannot sync '%.300s': %s", r->out, strerror(errno));
    return CLI_EXIT_FAIL;
}

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
    p.edges = &b->edges;
    report_view v;
    if (!report_view_fit(&p, &v))
        p.view = &v;
    int q = t->a.tiling_q;
    uint8_t **bg = q >= 5 && q <= 8 && p.view ? &b->background[q][v.zoom] : NULL;
    if (bg && !*bg && (*bg = malloc(sizeof b->px)) &&
        report_draw_background(q, v.zoom, *bg, REPORT_PNG_SIZE)) {
        free(*bg);
        *bg = NULL;
    }
    p.background = bg ? *bg : NULL;
    snprintf(t->png, sizeof t->png, "attempt-%04d.png", i + 1);
    char path[4200];
    snprintf(path, sizeof path, "%s/%s", r->out, t->png);
    if (report_draw(&p, b->px, REPORT_PNG_SIZE) || write_png(path, b)) {
        if ((st = report_stopped(r)))
            return st;
        cli_error(r->cmd, 0, "cannot write '%.300s'", path);
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
            (n < 1 || n > r->natt || !r->att[n - 1].png[0])) {
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
    if (!st)
        report_ids_read(r);
    if (!r->out) { /* --bids only */
        if (!st)
            st = report_bids_write(r, r->bids);
        return st ? st : report_ids_tell(r);
    }
    if (!st)
        st = report_stats_read(r);
    /* first every steps file and level is checked, then anything written */
    for (int i = 0; !st && i < r->natt; i++)
        if (!(st = report_stopped(r)))
            st = picture(r, b, i, 0);
    if (!st)
        st = report_ids_tell(r);
    if (!st) /* its line on duplicates after those of the logs */
        st = report_pstats_compute(r);
    if (!st)
        st = make_out(r);
    r->quiet = 1;
    for (int i = 0; !st && i < r->natt; i++)
        if (!(st = report_stopped(r)))
            st = picture(r, b, i, 1);
    if (!st)
        st = report_sync(r);
    /* a table as long as the attempts: every condition has its row */
    hol_report_agg g;
    hol_report_cond *conds = st ? NULL : malloc(sizeof *conds * (size_t)(r->natt + 1));
    hol_report_agg_init(&g, conds, r->natt + 1);
    if (!st && !conds) {
        cli_error(r->cmd, 0, "out of memory");
        st = CLI_EXIT_FAIL;
    }
    for (int i = 0; !st && i < r->natt; i++)
        hol_report_agg_add(&g, &r->att[i].a);
    if (!st && g.overflow) { /* cannot happen: never a silent limit */
        cli_error(r->cmd, 0, "more than %d conditions", g.cap);
        st = CLI_EXIT_FAIL;
    }
    if (!st)
        st = report_stats_order_agg(r, &g);
    if (!st)
        st = report_write_csv(r);
    if (!st)
        st = report_write_conditions(r, &g);
    if (!st)
        st = report_stats_write(r);
    if (!st)
        st = report_pstats_write(r);
    if (!st)
        st = report_write_html(r, &g);
    if (!st)
        st = report_write_provenance(r);
    if (!st) {
        remove_stale(r);
        printf("report: %d attempts from %d log folder%s\n", r->natt, r->ndirs,
               r->ndirs == 1 ? "" : "s");
    }
    if (!st && r->bids)
        st = report_bids_write(r, r->bids);
    free(conds);
    return st;
}

int cli_cmd_report(int argc, char **argv)
{
    const char *cmd = "report";
    if (argc > 1 && !strcmp(argv[1], "--class"))
        return report_class_main(cmd, argc, argv);
    if (cli_wants_help(argc, argv, report_valued)) {
        fputs(report_usage, stdout);
        return cli_finish_output(cmd);
    }
#ifdef __GLIBC__
    /* the picture encoder's buffers (about 400 KB each) are reused, not
     * mapped and faulted in again for each of 10,000 pictures */
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 16 << 20);
#endif
    report_run *r = calloc(1, sizeof *r); /* its scratch level is large */
    report_buf *b = calloc(1, sizeof *b);
    int st = r && b ? 0 : CLI_EXIT_FAIL;
    if (r)
        r->cmd = cmd;
    if (!st && !(b->walked = malloc(sizeof *b->walked * REPORT_MAX_STEPS)))
        st = CLI_EXIT_FAIL;
    if (!st)
        b->npal = report_palette(b->plte);
    if (st)
        cli_error(cmd, 0, "out of memory");
    if (!st)
        st = parse_args(r, argc, argv);
    if (!st)
        cli_catch_signals();
    if (!st)
        st = run(r, b);
    if (!st)
        st = cli_finish_output(cmd);
    if (r) {
        report_pstats_free(r);
        report_stats_free(r);
        report_free(r);
        free(r->dirs);
    }
    free(r);
    if (b) {
        free(b->walked);
        for (int q = 0; q < 9; q++)
            for (int z = 0; z <= REPORT_ZOOM_MAX; z++)
                free(b->background[q][z]);
    }
    free(b);
    return st;
}
