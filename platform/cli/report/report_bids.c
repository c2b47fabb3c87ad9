/* report_bids.c - the BIDS-Motion export of `holonomy report --bids DIR`
 * (report_bids.h): track-NNN.csv of each attempt as two tracking systems
 * (room and tile frame), with the dataset's top-level files. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <dirent.h>
#include <unistd.h>

#include "../../../core/hol_version.h"
#include "../../file/hol_file.h"
#include "../../file/hol_lines.h"
#include "../cli.h"
#include "../summary_read.h"
#include "report_bids.h"

#define BIDS_LABEL 72
#define BIDS_TRACK_COLS 28

static const char track_header[] =
    "session,attempt,level,sample,t,frame_t,device,head_x,head_y,head_z,head_qx,head_qy,"
    "head_qz,head_qw,left_x,left_y,left_z,left_qx,left_qy,left_qz,left_qw,right_x,right_y,"
    "right_z,right_qx,right_qy,right_qz,right_qw";

static const char *const points[3] = {"head", "left_hand", "right_hand"};
static const char *const comps[7] = {"x", "y", "z", "quat_x", "quat_y", "quat_z", "quat_w"};

/* One attempt's labels; run 0: not exported. */
typedef struct bids_ids {
    char sub[BIDS_LABEL], ses[BIDS_LABEL], task[BIDS_LABEL];
    int run;
} bids_ids;

/* What one attempt's export holds while its track file is read. */
typedef struct bids_att {
    report_run *r;
    const char *dir;
    report_att *t;
    bids_ids *id;
    double cx, cz;       /* the room's centre, metres */
    int start_orient;
    double *step_t;      /* steps rows: level time and orient after the step */
    unsigned char *step_o;
    long nsteps, cap;
    int hz;
    long nsamples;
    const char *sys;     /* "room" or "tile" */
} bids_att;

int report_bids_check(const char *cmd, const char *dir)
{
    struct stat sb;
    if (!dir[0]) {
        cli_error(cmd, 0, "--bids '': an empty name");
        return CLI_EXIT_USAGE;
    }
    if (stat(dir, &sb)) {
        char parent[4096];
        snprintf(parent, sizeof parent, "%s", dir);
        size_t n = strlen(parent);
        while (n > 1 && parent[n - 1] == '/')
            parent[--n] = 0;
        char *slash = strrchr(parent, '/');
        const char *p = slash ? (slash == parent ? "/" : (*slash = 0, parent)) : ".";
        if (errno == ENOENT && lstat(dir, &sb) && !stat(p, &sb) && S_ISDIR(sb.st_mode))
            return 0;
        cli_error(cmd, 0, "--bids '%.300s': its folder does not exist", dir);
        return CLI_EXIT_USAGE;
    }
    DIR *d = S_ISDIR(sb.st_mode) ? opendir(dir) : NULL;
    struct dirent *e;
    int empty = d != NULL;
    while (d && empty && (e = readdir(d)))
        empty = !strcmp(e->d_name, ".") || !strcmp(e->d_name, "..");
    if (d)
        closedir(d);
    if (empty)
        return 0;
    cli_error(cmd, 0, "--bids '%.300s' is %s; give an empty or new folder", dir,
              S_ISDIR(sb.st_mode) ? "not empty" : "not a folder");
    return CLI_EXIT_USAGE;
}

/* The letters and digits of s (at most 40), or dflt when it has none. */
static void label_of(const char *s, const char *dflt, char *out)
{
    size_t o = 0;
    for (; *s && o < 40; s++)
        if (isalnum((unsigned char)*s))
            out[o++] = *s;
    out[o] = 0;
    if (!o)
        snprintf(out, BIDS_LABEL, "%s", dflt);
}

/* Every attempt's subject, session and task labels (report_bids.h). */
static void label_all(const report_run *r, bids_ids *ids)
{
    for (int i = 0; i < r->natt; i++) {
        const hol_report_attempt *a = &r->att[i].a;
        int same = -1, k = 1;
        for (int j = 0; j < i && same < 0; j++)
            if (!strcmp(r->att[j].a.participant, a->participant))
                same = j;
        if (same >= 0) {
            memcpy(ids[i].sub, ids[same].sub, sizeof ids[i].sub); /* same < i */
        } else {
            char base[BIDS_LABEL];
            label_of(a->participant, "anon", base);
            snprintf(ids[i].sub, BIDS_LABEL, "%s", base);
            for (int j = 0; j < i; j++)
                if (!strcmp(ids[j].sub, ids[i].sub)) {
                    snprintf(ids[i].sub, BIDS_LABEL, "%.40sn%d", base, ++k);
                    j = -1; /* again from the first */
                }
        }
        char no[24];
        snprintf(no, sizeof no, "%ld", a->session_no);
        label_of(a->session_no >= 0 ? no : a->session, "none", ids[i].ses);
        label_of(a->condition[0] ? a->condition : a->level, "holonomy", ids[i].task);
        ids[i].run = 0;
    }
}

/* A JSON string (bytes outside printable ASCII as \u00XX). */
static void json_str(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(f, "\\%c", c);
        else if (c < 0x20 || c > 0x7e)
            fprintf(f, "\\u%04x", c);
        else
            fputc(c, f);
    }
    fputc('"', f);
}

static int description_json(FILE *f, const report_run *run, const void *ctx)
{
    (void)run, (void)ctx;
    fputs("{\n  \"Name\": \"Holonomy head and hand tracks\",\n  \"BIDSVersion\": \"1.9.0\",\n"
          "  \"DatasetType\": \"raw\",\n  \"GeneratedBy\": [\n    {\n"
          "      \"Name\": \"holonomy report --bids\",\n      \"Version\": \"" HOL_VERSION "\",\n"
          "      \"Description\": \"track-NNN.csv of each attempt of the log folders\"\n"
          "    }\n  ]\n}\n", f);
    return 0;
}

static int readme(FILE *f, const report_run *run, const void *ctx)
{
    (void)run, (void)ctx;
    fputs("Head and hand tracks of Holonomy attempts, written by `holonomy report --bids`\n"
          "from each attempt's track-NNN.csv. One run per attempt, two tracking systems:\n"
          "tracksys-room (poses in room metres, x east, y up, z south, as logged) and\n"
          "tracksys-tile (the same samples in the frame of the tile the room stood on:\n"
          "origin the room's centre on the floor, axes turned by the room's orientation).\n"
          "participants.tsv maps each subject label to the participant id of the logs.\n", f);
    return 0;
}

static int participants_tsv(FILE *f, const report_run *run, const void *ctx)
{
    const bids_att *b = ctx;
    const report_run *r = run;
    const bids_ids *ids = b->id;
    fputs("participant_id\tholonomy_id\n", f);
    for (int i = 0; i < r->natt; i++) {
        int seen = ids[i].run <= 0;
        for (int j = 0; j < i && !seen; j++)
            seen = ids[j].run > 0 && !strcmp(ids[j].sub, ids[i].sub);
        if (!seen)
            fprintf(f, "sub-%s\t%s\n", ids[i].sub,
                    r->att[i].a.participant[0] ? r->att[i].a.participant : "n/a");
    }
    return 0;
}

static int participants_json(FILE *f, const report_run *run, const void *ctx)
{
    (void)run, (void)ctx;
    fputs("{\n  \"participant_id\": {\"Description\": \"sub- and the letters and digits of the "
          "participant id (n2, n3, ... after it when two ids give one label)\"},\n"
          "  \"holonomy_id\": {\"Description\": \"the participant id as logged "
          "(summary.csv's participant; n/a: none given)\"}\n}\n", f);
    return 0;
}

static int channels_tsv(FILE *f, const report_run *run, const void *ctx)
{
    (void)run, (void)ctx;
    fputs("name\tcomponent\ttype\ttracked_point\tunits\n", f);
    for (int p = 0; p < 3; p++)
        for (int c = 0; c < 7; c++)
            fprintf(f, "%s_%s\t%s\t%s\t%s\t%s\n", points[p], comps[c], comps[c],
                    c < 3 ? "POS" : "ORNT", points[p], c < 3 ? "m" : "n/a");
    return 0;
}

static int motion_json(FILE *f, const report_run *run, const void *ctx)
{
    (void)run;
    const bids_att *b = ctx;
    const hol_report_attempt *a = &b->t->a;
    int tile = !strcmp(b->sys, "tile");
    fputs("{\n  \"TaskName\": ", f);
    json_str(f, a->condition[0] ? a->condition : a->level);
    char what[HOL_REPORT_TEXT * 2 + 64];
    snprintf(what, sizeof what, "a Holonomy level: %s (attempt %ld, ended %s)", a->level,
             a->attempt, a->end);
    fputs(",\n  \"TaskDescription\": ", f);
    json_str(f, what);
    fputs(",\n", f);
    fprintf(f, "  \"SamplingFrequency\": %d,\n  \"RecordingDuration\": %.4f,\n", b->hz,
            (double)b->nsamples / b->hz);
    fprintf(f, "  \"RecordingType\": \"continuous\",\n  \"MotionChannelCount\": 21,\n"
               "  \"POSChannelCount\": 9,\n  \"ORNTChannelCount\": 12,\n"
               "  \"TrackedPointsCount\": 3,\n  \"MissingValues\": \"n/a\",\n");
    fprintf(f, "  \"TrackingSystemName\": \"%s\",\n",
            tile ? "tile frame: the room's poses turned into the frame of the tile it stood on"
                 : "room frame: the poses as logged (head, left and right grip)");
    fputs("  \"Manufacturer\": \"n/a\",\n  \"SoftwareVersions\": \"holonomy " HOL_VERSION
          "\"\n}\n", f);
    return 0;
}

/* One sample of the tile frame: the room's poses (fields 7..27 of a track
 * row) turned by the orient's quarter turns about the room's centre. */
static void tile_row(FILE *f, const bids_att *b, const char *const *fl, int orient)
{
    /* the turn's quaternion (0, sin, 0, cos) of half its angle; 270 as -90 */
    static const double qc[4] = {1, 0.70710678118654752, 0, 0.70710678118654752};
    static const double qs[4] = {0, 0.70710678118654752, 1, -0.70710678118654752};
    static const int c4[4] = {1, 0, -1, 0}, s4[4] = {0, 1, 0, -1};
    int o = orient & 3;
    for (int p = 0; p < 3; p++) {
        const char *const *v = fl + 7 + 7 * p;
        if (!v[0][0]) {
            fputs(p ? "\tn/a\tn/a\tn/a\tn/a\tn/a\tn/a\tn/a" : "n/a\tn/a\tn/a\tn/a\tn/a\tn/a\tn/a",
                  f);
            continue;
        }
        double x = atof(v[0]) - b->cx, y = atof(v[1]), z = atof(v[2]) - b->cz;
        double qx = atof(v[3]), qy = atof(v[4]), qz = atof(v[5]), qw = atof(v[6]);
        /* about +y by o quarter turns (counter-clockwise seen from above) */
        double tx = c4[o] * x + s4[o] * z, tz = -s4[o] * x + c4[o] * z;
        double aw = qc[o], ay = qs[o];
        double rx = aw * qx + ay * qz, ry = aw * qy + ay * qw, rz = aw * qz - ay * qx,
               rw = aw * qw - ay * qy;
        fprintf(f, "%s%.4f\t%.4f\t%.4f\t%.5f\t%.5f\t%.5f\t%.5f", p ? "\t" : "", tx + 0.0, y,
                tz + 0.0, rx + 0.0, ry + 0.0, rz + 0.0, rw + 0.0);
    }
    fputc('\n', f);
}

static void na_row(FILE *f)
{
    for (int i = 0; i < 21; i++)
        fputs(i ? "\tn/a" : "n/a", f);
    fputc('\n', f);
}

/* The orient in force at level time t: the last step at or before it. */
static int orient_at(const bids_att *b, double t, long *j, int cur)
{
    while (*j < b->nsteps && b->step_t[*j] <= t + 1e-6)
        cur = b->step_o[(*j)++];
    return cur;
}

/* The attempt's steps file: each step's level time and orient (a missing
 * file: no steps, the start's orient throughout). */
static int read_steps(bids_att *b)
{
    report_run *r = b->r;
    char path[4600];
    snprintf(path, sizeof path, "%s/steps-%03ld.csv", r->dirs[b->t->dir], b->t->a.attempt);
    b->nsteps = 0;
    struct stat sb;
    if (lstat(path, &sb))
        return 0;
    hol_lines l;
    int st = cli_open_lines(r->cmd, "steps", path, REPORT_LINE_MAX, &l);
    if (st)
        return st;
    char *line, buf[REPORT_LINE_MAX], err[HOL_REPORT_ERR] = "";
    const char *fl[32];
    size_t n;
    int got, nf, ct = -1, co = -1, ok = 1;
    while (ok && (got = hol_lines_next(&l, &line, &n)) > 0) {
        if (!summary_csv_line(&l, &line, &n))
            continue;
        ok = !hol_report_csv_split(line, n, buf, sizeof buf, fl, 32, &nf, err);
        if (ok && ct < 0) {
            for (int i = 0; i < nf; i++)
                ct = !strcmp(fl[i], "t") ? i : ct, co = !strcmp(fl[i], "orient") ? i : co;
            if ((ok = ct >= 0 && co >= 0) == 0)
                snprintf(err, sizeof err, "no t or orient column in the header");
            continue;
        }
        if (ok && (nf <= co || nf <= ct || fl[co][0] < '0' || fl[co][0] > '3' || fl[co][1])) {
            snprintf(err, sizeof err, "column orient: not 0..3");
            ok = 0;
        }
        if (ok && b->nsteps == b->cap) {
            long cap = b->cap ? 2 * b->cap : 1024;
            double *t2 = realloc(b->step_t, sizeof *t2 * (size_t)cap);
            unsigned char *o2 = t2 ? realloc(b->step_o, (size_t)cap) : NULL;
            b->step_t = t2 ? t2 : b->step_t;
            b->step_o = o2 ? o2 : b->step_o;
            b->cap = o2 ? cap : b->cap;
            if (!o2) {
                hol_lines_close(&l);
                cli_error(r->cmd, 0, "out of memory");
                return CLI_EXIT_FAIL;
            }
        }
        if (ok) {
            b->step_t[b->nsteps] = atof(fl[ct]);
            b->step_o[b->nsteps++] = (unsigned char)(fl[co][0] - '0');
        }
    }
    st = !ok ? summary_bad_line(r->cmd, path, l.lineno, err)
         : got < 0 ? cli_lines_failed(r->cmd, "steps", path, &l) : 0;
    hol_lines_close(&l);
    return st;
}

/* One track row into both motion files (and the rows of samples a gap hid
 * before it as n/a). 0, or 1 with err set. */
static int track_row(bids_att *b, const char *const *fl, FILE *room, FILE *tile, long *j,
                     int *orient, char *err)
{
    char *end;
    long k = strtol(fl[3], &end, 10);
    if (!fl[3][0] || *end || k < b->nsamples || k > 100000000L) {
        snprintf(err, HOL_REPORT_ERR, "column sample: not the next sample (%ld or later)",
                 b->nsamples);
        return 1;
    }
    for (; b->nsamples < k; b->nsamples++)
        na_row(room), na_row(tile);
    b->nsamples++;
    double t = atof(fl[4]);
    if (k > 0 && !b->hz && t > 0)
        b->hz = (int)floor(k / t + 0.5); /* 4 decimals tell 10..90 Hz apart at k = 1 */
    if (k > 0 && (b->hz < 10 || b->hz > 90 || fabs(k / (double)b->hz - t) > 0.00006)) {
        snprintf(err, HOL_REPORT_ERR, "column t: not sample / hz for one rate of 10..90");
        return 1;
    }
    if (!strcmp(fl[6], "gap")) {
        na_row(room), na_row(tile);
        return 0;
    }
    for (int i = 7; i < BIDS_TRACK_COLS; i++)
        fprintf(room, "%s%s", i > 7 ? "\t" : "", fl[i][0] ? fl[i] : "n/a");
    fputc('\n', room);
    *orient = orient_at(b, t, j, *orient);
    tile_row(tile, b, fl, *orient);
    return 0;
}

/* The track file read into the two motion files (open atomic files). */
static int read_track(bids_att *b, const char *path, FILE *room, FILE *tile)
{
    report_run *r = b->r;
    hol_lines l;
    int st = cli_open_lines(r->cmd, "track", path, REPORT_LINE_MAX, &l);
    if (st)
        return st;
    char *line, buf[REPORT_LINE_MAX], err[HOL_REPORT_ERR] = "";
    const char *fl[BIDS_TRACK_COLS + 1];
    size_t n;
    int got, nf, ok = 1, header = 0, orient = b->start_orient;
    long j = 0;
    while (ok && (got = hol_lines_next(&l, &line, &n)) > 0) {
        if (!(l.lineno & 4095) && (st = report_stopped(r)))
            break;
        if (!summary_csv_line(&l, &line, &n))
            continue;
        if (!header++) {
            if (!(ok = n == sizeof track_header - 1 && !memcmp(line, track_header, n)))
                snprintf(err, sizeof err, "not the track file's header");
            continue;
        }
        ok = !hol_report_csv_split(line, n, buf, sizeof buf, fl, BIDS_TRACK_COLS + 1, &nf, err);
        if (ok && nf != BIDS_TRACK_COLS)
            snprintf(err, sizeof err, "%d fields where the header has %d", nf, BIDS_TRACK_COLS);
        ok = ok && nf == BIDS_TRACK_COLS && !track_row(b, fl, room, tile, &j, &orient, err);
    }
    if (!st)
        st = !ok ? summary_bad_line(r->cmd, path, l.lineno, err)
             : got < 0 ? cli_lines_failed(r->cmd, "track", path, &l)
             : !header ? summary_bad_line(r->cmd, path, 1, "empty: no header") : 0;
    hol_lines_close(&l);
    return st;
}

/* The attempt's file NAME (motion.tsv, ...) of tracking system sys. */
static void run_name(const bids_att *b, const char *sys, const char *suffix, char *out, size_t cap)
{
    const bids_ids *id = b->id;
    snprintf(out, cap, "sub-%s/ses-%s/motion/sub-%s_ses-%s_task-%s_tracksys-%s_run-%d_%s",
             id->sub, id->ses, id->sub, id->ses, id->task, sys, id->run, suffix);
}

/* sub-L/ses-S/motion made under dir. */
static int make_dirs(const bids_att *b)
{
    char path[4600];
    const char *parts[3] = {"sub-%s", "sub-%s/ses-%s", "sub-%s/ses-%s/motion"};
    for (int i = 0; i < 3; i++) {
        int o = snprintf(path, sizeof path, "%s/", b->dir);
        snprintf(path + o, sizeof path - (size_t)o, parts[i], b->id->sub, b->id->ses);
        if (mkdir(path, 0777) && errno != EEXIST) {
            cli_error(b->r->cmd, 0, "--bids: cannot make '%.300s': %s", path, strerror(errno));
            return CLI_EXIT_FAIL;
        }
    }
    return 0;
}

/* Both motion.tsv files of the attempt, written while its track is read. */
static int write_motion(bids_att *b, const char *track)
{
    hol_file_atomic a[2];
    char path[2][4700], name[600];
    const char *sys[2] = {"room", "tile"};
    int st = 0, open = 0;
    for (; open < 2 && !st; open++) {
        run_name(b, sys[open], "motion.tsv", name, sizeof name);
        snprintf(path[open], sizeof path[open], "%s/%s", b->dir, name);
        if (hol_file_atomic_open(&a[open], path[open])) {
            cli_error(b->r->cmd, 0, "cannot write '%.300s'", path[open]);
            st = CLI_EXIT_FAIL;
        }
    }
    open -= st != 0;
    if (!st)
        st = read_track(b, track, a[0].f, a[1].f);
    int skip = !st && !b->hz; /* fewer than two samples: no rate */
    for (int i = 0; i < open; i++) {
        if (!st && !skip && (ferror(a[i].f) || hol_file_atomic_commit(&a[i]))) {
            cli_error(b->r->cmd, 0, "cannot write '%.300s'", path[i]);
            st = CLI_EXIT_FAIL;
        } else if ((st || skip) && a[i].f) {
            hol_file_atomic_abort(&a[i]);
        }
    }
    return skip ? -1 : st;
}

static void warn(const report_run *r, const char *path, const char *what)
{
    char esc[512];
    fprintf(stderr, "holonomy %s: warning: %s: %s\n", r->cmd, cli_escape(path, esc, sizeof esc),
            what);
}

/* The attempt read up to its track file (named in track): its room's
 * centre, start orient and steps. 0, -1 no track file, or an exit status. */
static int prepare(bids_att *b, bids_ids *ids, int i, char *track, size_t cap)
{
    report_run *r = b->r;
    b->t = &r->att[i];
    b->id = &ids[i];
    snprintf(track, cap, "%s/track-%03ld.csv", r->dirs[b->t->dir], b->t->a.attempt);
    struct stat sb;
    if (lstat(track, &sb))
        return -1;
    const hol_report_attempt *a = &b->t->a;
    b->cx = a->room_cols * a->cell_m / 2, b->cz = a->room_rows * a->cell_m / 2;
    b->hz = 0, b->nsamples = 0;
    hol_room start;
    hol_tile goals[HOL_APP_MAX_OBJECTIVES];
    int ngoals, chest, nwalk;
    hol_tile *walk = malloc(sizeof *walk * HOL_NAV_WALK_MAX);
    int st = walk ? report_optimal(r, b->t, &start, goals, &ngoals, &chest, walk, &nwalk)
                  : CLI_EXIT_FAIL;
    free(walk);
    if (!walk)
        cli_error(r->cmd, 0, "out of memory");
    b->start_orient = start.orient;
    return st ? st : read_steps(b);
}

/* Every attempt's track read before anything is written: a malformed one
 * refused; an attempt without a track or a rate gets run -1 (a warning). */
static int check_all(bids_att *b, bids_ids *ids)
{
    report_run *r = b->r;
    char track[4600];
    FILE *nul = fopen("/dev/null", "w");
    int st = nul ? 0 : CLI_EXIT_FAIL;
    if (!nul)
        cli_error(r->cmd, 0, "cannot open /dev/null");
    for (int i = 0; !st && i < r->natt; i++) {
        if (!(st = report_stopped(r)) && (st = prepare(b, ids, i, track, sizeof track)) < 0)
            warn(r, track, "missing: the attempt has no run in --bids");
        if (!st && !(st = read_track(b, track, nul, nul)) && !b->hz)
            warn(r, track, "fewer than two samples: the attempt has no run in --bids");
        ids[i].run = st < 0 || (!st && !b->hz) ? -1 : 0;
        st = st < 0 ? 0 : st;
    }
    if (nul)
        fclose(nul);
    return st;
}

/* One attempt's run: its two tracking systems' three files each. */
static int export_attempt(bids_att *b, bids_ids *ids, int i)
{
    report_run *r = b->r;
    char track[4600], name[600];
    if (ids[i].run < 0)
        return 0;
    int st = prepare(b, ids, i, track, sizeof track);
    ids[i].run = 1;
    for (int j = 0; j < i; j++)
        ids[i].run += ids[j].run > 0 && !strcmp(ids[j].sub, ids[i].sub) &&
                      !strcmp(ids[j].ses, ids[i].ses) && !strcmp(ids[j].task, ids[i].task);
    if (!st)
        st = make_dirs(b);
    if (!st)
        st = write_motion(b, track);
    for (int k = 0; !st && k < 2; k++) {
        b->sys = k ? "tile" : "room";
        run_name(b, b->sys, "channels.tsv", name, sizeof name);
        st = report_write_in(r, b->dir, name, channels_tsv, b);
        run_name(b, b->sys, "motion.json", name, sizeof name);
        if (!st)
            st = report_write_in(r, b->dir, name, motion_json, b);
    }
    if (st < 0) /* the file changed since check_all */
        cli_error(r->cmd, 0, "'%.300s' changed while the report ran", track);
    if (st)
        ids[i].run = 0;
    return st < 0 ? CLI_EXIT_FAIL : st;
}

int report_bids_write(report_run *r, const char *dir)
{
    bids_ids *ids = calloc((size_t)r->natt + 1, sizeof *ids);
    bids_att b;
    memset(&b, 0, sizeof b);
    b.r = r, b.dir = dir, b.id = ids;
    if (!ids) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    label_all(r, ids);
    int st = check_all(&b, ids), quiet = r->quiet;
    r->quiet = 1; /* the level's warnings were given */
    if (!st && mkdir(dir, 0777) && errno != EEXIST) {
        cli_error(r->cmd, 0, "--bids '%.300s' cannot be made: %s", dir, strerror(errno));
        st = CLI_EXIT_FAIL;
    }
    int runs = 0;
    for (int i = 0; !st && i < r->natt; i++)
        if (!(st = report_stopped(r)) && !(st = export_attempt(&b, ids, i)))
            runs += ids[i].run > 0;
    b.id = ids;
    if (!st)
        st = report_write_in(r, dir, "dataset_description.json", description_json, NULL);
    if (!st)
        st = report_write_in(r, dir, "README", readme, NULL);
    if (!st)
        st = report_write_in(r, dir, "participants.tsv", participants_tsv, &b);
    if (!st)
        st = report_write_in(r, dir, "participants.json", participants_json, NULL);
    if (!st)
        printf("report: %d run%s of head and hand tracks into --bids\n", runs,
               runs == 1 ? "" : "s");
    r->quiet = quiet;
    free(b.step_t);
    free(b.step_o);
    free(ids);
    return st;
}
