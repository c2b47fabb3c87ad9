/* play_setup.c - levels, recorded input, the session's outputs, its start
 * and end, for play, replay, xr and game (see play_setup.h). */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include "play_setup.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../../core/hol_campaign.h"
#include "../../core/hol_input_io.h"
#include "../../core/hol_lesson.h"
#include "../../core/hol_study.h"
#include "../../core/hol_text.h"
#include "../file/hol_file.h"
#include "cli.h"
#include "play_prov.h"

/* ---- levels ---------------------------------------------------------------- */

int play_read_level(const char *cmd, const char *path, hol_level *out)
{
    uint8_t *data = NULL;
    size_t size = 0;
    int rs = cli_read_file(cmd, "level", path, HOL_LEVEL_TEXT_MAX, &data, &size);
    if (rs)
        return rs;
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    size_t bl = strcspn(base, ".");
    if (bl == 0)
        bl = strlen(base);
    hol_level_err le;
    hol_err e = hol_level_make(base, bl < 60 ? bl : 60, (const char *)data, size, out, &le);
    free(data);
    if (e) {
        char msg[256];
        cli_error(cmd, 0, "%.200s: %s", path, hol_level_err_format(&le, 1, msg, sizeof msg));
        return CLI_EXIT_USAGE;
    }
    return 0;
}

int play_geometry_value(const char *cmd, const char *opt, const char *val, play_geometry *g)
{
    if (!val) /* a flag (--append): never a geometry option */
        return 0;
    size_t n = strlen(val);
    if (!strcmp(opt, "--tiling")) {
        if (!hol_room_parse_tiling(val, n, &g->q))
            return 1;
        cli_error(cmd, 0, "--tiling needs 4,Q with Q from 4 to 8 (the tiling {4,Q}), not '%.40s'",
                  val);
    } else if (!strcmp(opt, "--room")) {
        if (!hol_room_parse_size(val, n, &g->cols, &g->rows))
            return 1;
        cli_error(cmd, 0, "--room needs CxR with C and R from 3 to 5 (cells), not '%.40s'", val);
    } else if (!strcmp(opt, "--cell")) {
        if (!hol_level_parse_cell(val, n, &g->cell_m))
            return 1;
        cli_error(cmd, 0,
                  "--cell needs metres from 0.5 to 1.5 (at most 3 decimals), not '%.40s'", val);
    } else {
        return 0;
    }
    return -1;
}

int play_geometry_apply(const char *cmd, const play_geometry *g, hol_level *levels, int n)
{
    for (int i = 0; i < n; i++) {
        hol_level_err le; /* a tutorial takes only the cell (hol_level.h) */
        if (hol_level_set_geometry(&levels[i], g->q, g->cols, g->rows, g->cell_m, &le)) {
            char msg[300], name[HOL_LEVEL_NAME_MAX * 4];
            cli_error(cmd, 0, "level '%s': %s", cli_escape(levels[i].name, name, sizeof name),
                      hol_level_err_format(&le, 1, msg, sizeof msg));
            return CLI_EXIT_USAGE;
        }
    }
    play_prov_order_hash(levels, n); /* order.csv's hashes: the texts are final */
    return 0;
}

int play_lesson_value(const char *cmd, const char *val, int *out)
{
    size_t n = cli_parse_count(val);
    if (!n || n > HOL_LESSONS) {
        cli_error(cmd, 0, "--lesson '%.40s' is not a lesson 1..%d", val, HOL_LESSONS);
        return 1;
    }
    *out = (int)n;
    return 0;
}

int play_lesson_level(const char *cmd, int n, hol_level *levels, int *nlevels)
{
    char name[32], text[32];
    snprintf(name, sizeof name, "lesson-%d", n);
    snprintf(text, sizeof text, "lesson %d\n", n);
    hol_level_err le;
    *nlevels = 0;
    if (hol_level_make(name, strlen(name), text, strlen(text), &levels[0], &le)) {
        char msg[300];
        cli_error(cmd, 0, "cannot make lesson %d: %s", n,
                  hol_level_err_format(&le, 1, msg, sizeof msg));
        return CLI_EXIT_FAIL;
    }
    *nlevels = 1;
    return 0;
}

int play_levels(const char *cmd, const char *level_path, const char *mode, uint64_t seed,
                const play_geometry *g, hol_level *levels, int *nlevels)
{
    hol_campaign_geo geo = {g ? g->q : 0, g ? g->cols : 0, g ? g->rows : 0};
    *nlevels = 0;
    if (level_path) {
        int st = play_read_level(cmd, level_path, &levels[0]);
        *nlevels = st ? 0 : 1;
        return st;
    }
    if (mode) {
        hol_err e = hol_campaign_mode_level(mode, seed, &geo, &levels[0]);
        if (e == HOL_EARG) {
            cli_error(cmd, 0, "--mode '%.40s' is not one of tutorial, flag, keys, explore",
                      mode);
            return CLI_EXIT_USAGE;
        } else if (e) {
            cli_error(cmd, 0, "cannot make a %.40s level: %s", mode, hol_err_str(e));
            return CLI_EXIT_FAIL;
        }
        *nlevels = 1;
        return 0;
    }
    if (hol_campaign_default(seed, &geo, levels)) {
        cli_error(cmd, 0, "cannot make the default campaign");
        return CLI_EXIT_FAIL;
    }
    *nlevels = HOL_CAMPAIGN_LEVELS;
    return 0;
}

/* ---- recorded input ---------------------------------------------------------- */

static int play_input_failed(play_input *pi)
{
    if (pi->lines.err == HOL_ENOMEM)
        cli_error(pi->cmd, pi->lines.lineno, "'%.200s': longer than %d bytes", pi->path,
                  HOL_REC_LINE_MAX);
    else
        cli_error(pi->cmd, 0, "cannot read '%.200s': %s", pi->path, strerror(errno));
    return pi->lines.err == HOL_ENOMEM ? CLI_EXIT_USAGE : CLI_EXIT_FAIL;
}

/* The recording's header, when the file has one (line 1 given). */
static int play_input_header(play_input *pi, char *s, size_t len, int want_header)
{
    pi->recording = len >= 13 && !memcmp(s, "holonomy-rec ", 13);
    if (!pi->recording && !want_header) {
        memcpy(pi->first, s, len + 1);
        pi->first_len = len;
        pi->first_cut = pi->lines.cut;
        pi->have_first = 1;
        return 0;
    }
    hol_rec_reader_init(&pi->rec, pi->levels);
    for (;;) {
        int done = 0;
        hol_err e = hol_rec_read_line(&pi->rec, s, len, &done);
        if (!e && done) {
            memcpy(pi->first, s, len + 1);
            pi->first_len = len;
            pi->have_first = 1;
            return 0;
        }
        if (e) {
            cli_error(pi->cmd, 0, "%.200s: %s", pi->path, pi->rec.msg);
            return CLI_EXIT_USAGE;
        }
        int r = hol_lines_next(&pi->lines, &s, &len);
        if (r < 0)
            return play_input_failed(pi);
        if (r == 0)
            break;
    }
    if (hol_rec_read_end(&pi->rec)) {
        cli_error(pi->cmd, 0, "%.200s: %s", pi->path, pi->rec.msg);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

int play_input_open(const char *cmd, const char *path, int want_header, play_input *pi)
{
    memset(pi, 0, sizeof *pi);
    pi->cmd = cmd;
    pi->path = path;
    hol_err e = hol_lines_open(&pi->lines, path, HOL_REC_LINE_MAX);
    if (e) {
        if (e == HOL_EARG)
            cli_error(cmd, 0, "'%.200s' is %s, not a regular file", path,
                      errno == EISDIR ? "a directory" : "a FIFO, socket or device");
        else
            cli_error(cmd, 0, "cannot open '%.200s': %s", path, strerror(errno));
        return e == HOL_ENOMEM ? CLI_EXIT_FAIL : CLI_EXIT_USAGE;
    }
    char *s;
    size_t len;
    int r = hol_lines_next(&pi->lines, &s, &len);
    int st = r < 0 ? play_input_failed(pi) : 0;
    if (!st && r == 0 && want_header) {
        cli_error(cmd, 0, "%.200s: line 1: not a recording (no 'holonomy-rec' header)", path);
        st = CLI_EXIT_USAGE;
    }
    if (!st && r > 0)
        st = play_input_header(pi, s, len, want_header);
    if (st)
        play_input_close(pi);
    return st;
}

int play_input_next(play_input *pi, hol_input *in)
{
    char *s = pi->first;
    size_t len = pi->first_len;
    long lineno = pi->lines.lineno;
    int cut;
    if (pi->have_first) {
        pi->have_first = 0;
        lineno = pi->recording ? pi->rec.line + 1 : 1;
        cut = pi->first_cut;
    } else {
        int r = hol_lines_next(&pi->lines, &s, &len);
        if (r <= 0)
            return r < 0 ? -play_input_failed(pi) : 0;
        lineno = pi->lines.lineno;
        cut = pi->lines.cut;
    }
    if (cut) { /* a record the file's end cut: never taken (it may be a part) */
        cli_error(pi->cmd, lineno, "'%.200s' ends inside this record (no newline): it is "
                  "dropped", pi->path);
        return 0;
    }
    if (pi->recording && len == sizeof HOL_REC_ABORTED_LINE - 1 &&
        !memcmp(s, HOL_REC_ABORTED_LINE, len)) {
        pi->aborted = 1; /* the session was aborted here: the records end */
        return 0;
    }
    size_t bad = 0;
    if (hol_input_parse(s, len, in, &bad)) {
        cli_error(pi->cmd, lineno, "not an input record (byte %zu)", bad + 1);
        return -CLI_EXIT_USAGE;
    }
    if (in->time_s < pi->prev_t) {
        cli_error(pi->cmd, lineno, "time %.17g goes back (before: %.17g)", in->time_s,
                  pi->prev_t);
        return -CLI_EXIT_USAGE;
    }
    pi->prev_t = in->time_s;
    return 1;
}

void play_input_close(play_input *pi)
{
    hol_lines_close(&pi->lines);
}

/* ---- outputs -------------------------------------------------------------------- */

/* What a log folder's entry is, when it is not a regular file (NULL): a
 * symbolic link is not followed (nor written through), even to a regular
 * file, as `report` and --resume refuse it (summary_read.h). */
static const char *play_not_regular(DIR *d, const char *name)
{
    struct stat st;
    if (fstatat(dirfd(d), name, &st, AT_SYMLINK_NOFOLLOW))
        return "gone while read";
    return S_ISREG(st.st_mode)    ? NULL
           : S_ISLNK(st.st_mode)  ? "a symbolic link"
           : S_ISDIR(st.st_mode)  ? "a folder"
           : S_ISFIFO(st.st_mode) ? "a FIFO"
                                  : "a socket or device";
}

/* One writer per log folder (hol_sink_posix_lock): taken before the
 * folder is read; a second session is refused naming the holder; a lock a
 * killed writer left is taken over, said in one line; then the temporary
 * files of killed writers are removed (hol_file_clean_dir). */
static int play_log_lock(const char *cmd, const char *dir, play_out *po)
{
    char holder[256];
    int took = 0;
    hol_err e = hol_sink_posix_lock(&po->log, holder, sizeof holder, &took);
    if (e == HOL_EARG) {
        cli_error(cmd, 0, "--log '%.200s' is in use by another session (%.200s): one session "
                  "writes a log folder at a time; wait for it to end or choose another folder",
                  dir, holder[0] ? holder : "its holder is starting");
        return CLI_EXIT_USAGE;
    }
    if (e) {
        cli_error(cmd, 0, "--log '%.200s': cannot lock it (%s): %s", dir, HOL_SINK_POSIX_LOCK,
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    if (took)
        fprintf(stderr, "holonomy %s: --log '%.200s': took over the lock of a session that "
                        "no longer runs (%.200s)\n", cmd, dir, holder);
    (void)hol_file_clean_dir(dir);
    return 0;
}

/* --log DIR: made when missing (its parent exists; removed again by
 * play_out_close when no session opened on it); holding logs, refused
 * unless append; with append each log file in it must be a regular file. */
static int play_log_dir(const char *cmd, const char *dir, int append, play_out *po)
{
    struct stat st;
    int missing = stat(dir, &st) && errno == ENOENT;
    if (hol_sink_posix_make_dir(dir) || hol_sink_posix_init(&po->log, dir)) {
        cli_error(cmd, 0, "--log '%.200s' is not a folder and cannot be made: %s", dir,
                  strerror(errno));
        return CLI_EXIT_USAGE;
    }
    po->has_log = 1;
    if (missing && strlen(dir) < sizeof po->made_dir)
        snprintf(po->made_dir, sizeof po->made_dir, "%s", dir);
    int locked = play_log_lock(cmd, dir, po);
    if (locked)
        return locked;
    DIR *d = opendir(dir);
    struct dirent *e;
    const char *what = NULL;
    while (d && !what && (e = readdir(d)) != NULL) {
        if (!hol_session_is_log_name(e->d_name))
            continue;
        /* the name is the DIR's memory: said before closedir frees it */
        if (!append)
            cli_error(cmd, 0, "--log '%.200s' holds earlier logs ('%.60s'): add to them with "
                      "--append, or choose another folder", dir, e->d_name);
        else if ((what = play_not_regular(d, e->d_name)) != NULL)
            cli_error(cmd, 0, "--log '%.200s': '%.60s' is %s, not a log file: move it away",
                      dir, e->d_name, what);
        what = append ? what : "";
    }
    if (d)
        closedir(d);
    return what ? CLI_EXIT_USAGE : 0;
}

/* --record FILE: FILE and FILE.live may be written, and no FILE.live of a
 * session that did not end is in the way. */
static int play_rec_file(const char *cmd, const char *rec_path, play_out *po)
{
    char live[4096];
    struct stat st;
    snprintf(live, sizeof live, "%s.live", rec_path);
    if (cli_check_output(cmd, "--record", rec_path) || cli_check_output(cmd, "--record", live))
        return CLI_EXIT_USAGE;
    if (!lstat(live, &st)) {
        cli_error(cmd, 0, "--record: '%.200s' is there: the recording of a session that did "
                  "not end (replay it, then move it away)", live);
        return CLI_EXIT_USAGE;
    }
    const char *slash = strrchr(rec_path, '/');
    char dir[4096];
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - rec_path) : 1, slash ? rec_path : ".");
    if (slash == rec_path)
        snprintf(dir, sizeof dir, "/");
    const char *base = slash ? slash + 1 : rec_path;
    if (strlen(base) + 6 > sizeof po->rec_name || hol_sink_posix_init(&po->rec, dir)) {
        cli_error(cmd, 0, "--record '%.200s': the name is too long", rec_path);
        return CLI_EXIT_USAGE;
    }
    snprintf(po->rec_name, sizeof po->rec_name, "%s", base);
    po->has_rec = 1;
    return 0;
}

int play_out_open(const char *cmd, const char *log_dir, int append, const char *rec_path,
                  play_out *po)
{
    memset(po, 0, sizeof *po);
    int st = log_dir ? play_log_dir(cmd, log_dir, append, po) : 0;
    return st ? st : rec_path ? play_rec_file(cmd, rec_path, po) : 0;
}

void play_out_close(play_out *po)
{
    if (po->has_log)
        hol_sink_posix_fini(&po->log);
    if (po->made_dir[0] && !po->opened)
        rmdir(po->made_dir); /* made for a session that never began: empty */
    if (po->has_rec)
        hol_sink_posix_fini(&po->rec);
    po->has_log = po->has_rec = 0;
    free(po->study_text);
    po->study_text = NULL;
}

int play_participant(const char *cmd, const char *id, char out[HOL_REC_ID_MAX])
{
    char spelled[HOL_REC_ID_MAX];
    int ok = hol_rec_id_ok(id) && id[0] != '-';
    if (ok && hol_study_participant_id(id, spelled, sizeof spelled) == HOL_STUDY_ID_AMBIGUOUS) {
        const char *num = spelled + 1 + (spelled[1] == '0' && spelled[2]);
        cli_error(cmd, 0, "--participant '%.40s' is ambiguous: participant %s is written %s "
                  "(%s and p%s are read as %s)", id, num, spelled, num, num, spelled);
        return 1;
    }
    if (ok) {
        memcpy(out, spelled, sizeof spelled);
        return 0;
    }
    if (id[0] == '-')
        cli_error(cmd, 0, "--participant '%.40s' starts with '-' (a spreadsheet reads it as a "
                  "formula)", id);
    else
        cli_error(cmd, 0, "--participant '%.40s' is not 1..63 letters, digits, '.', '_', '-'", id);
    return 1;
}

int play_session_open(const char *cmd, play_out *po, const hol_level *levels, int nlevels,
                      const hol_rec_meta *meta, int append, hol_session **out)
{
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = levels;
    d.nlevels = nlevels;
    d.log = po->has_log ? &po->log.sink : NULL;
    d.append = append;
    d.rec = po->has_rec ? &po->rec.sink : NULL;
    d.rec_name = po->rec_name;
    d.meta = *meta;
    d.track_hz = po->track_hz;
    d.study_text = po->study_text;
    d.study_len = po->study_len;
    d.app.lazy_nav = strcmp(cmd, "xr") != 0;
    d.app.lazy_world = d.app.lazy_nav;
    d.app.lang = po->lang;
    char msg[256];
    /* recovery of a killed session's huge live files ends on a signal */
    if (po->has_log)
        po->log.stop = cli_caught_signal;
    hol_err e = hol_session_create(&d, out, msg, sizeof msg);
    if (po->has_log)
        po->log.stop = NULL;
    if (e) {
        cli_error(cmd, 0, "%s", msg);
        return e == HOL_EARG || e == HOL_EVERSION || e == HOL_EBUDGET || e == HOL_EUNREACH
                   ? CLI_EXIT_USAGE
                   : CLI_EXIT_FAIL;
    }
    po->opened = 1;
    play_prov_write(d.log, meta); /* provenance.csv, order.csv, codebook.csv */
    if (hol_session_recovered(*out))
        fprintf(stderr, "holonomy %s: %d unfinished attempt(s) of a killed session finished "
                        "in the log folder (end 'killed')\n",
                cmd, hol_session_recovered(*out));
    if (hol_session_dropped(*out))
        fprintf(stderr, "holonomy %s: %d attempt(s) of a killed session dropped from the log "
                        "folder (killed before their first row reached the disk)\n",
                cmd, hol_session_dropped(*out));
    if (hol_session_repaired(*out)[0])
        fprintf(stderr, "holonomy %s: %s\n", cmd, hol_session_repaired(*out));
    return 0;
}

int play_session_end(const char *cmd, hol_session *s, int abort)
{
    if (!s)
        return 0;
    hol_err e = abort == PLAY_END_KILLED ? hol_session_end_killed(s)
                : abort                    ? hol_session_abort(s)
                                           : hol_session_finish(s);
    if (e) /* the step's failure is not said twice */
        cli_error_end(cmd, "%s", hol_session_message(s));
    hol_session_destroy(s);
    int pf = play_prov_failed(cmd); /* provenance.csv, order.csv, codebook.csv */
    return e || pf ? CLI_EXIT_FAIL : 0;
}

void play_print_end(hol_session *s)
{
    const hol_app_view *v = hol_app_get_view(hol_session_app(s));
    char name[4 * HOL_LEVEL_NAME_MAX];
    cli_escape(hol_session_level(s)->name, name, sizeof name);
    printf("level %s %s steps %d optimum %d tile %s cell %d,%d\n", name,
           hol_session_end_name(s), v->hud.steps, v->hud.optimum, v->hud.address, v->user.col,
           v->user.row);
}

int play_load_pad_script(const char *cmd, const char *path, hol_hid_script *sc)
{
    /* streamed: memory stays flat, the first bad line is refused at once */
    const char *what = "gamepad script";
    hol_lines in;
    int st = cli_open_lines(cmd, what, path, HOL_HID_SCRIPT_LINE_MAX, &in);
    if (st)
        return st;
    char *s;
    size_t len;
    int r = 0;
    hol_err err = HOL_OK;
    hol_hid_script_begin(sc);
    while (!err && (r = hol_lines_next(&in, &s, &len)) > 0)
        err = hol_hid_script_line(sc, s, len);
    if (err)
        cli_error(cmd, sc->line, "'%.200s': %s", path,
                  err == HOL_ENOMEM ? "too many events or report bytes"
                                    : "not a gamepad script event (README: Gamepads)");
    else if (r < 0)
        st = cli_lines_failed(cmd, what, path, &in);
    hol_lines_close(&in);
    return err ? CLI_EXIT_USAGE : st;
}
