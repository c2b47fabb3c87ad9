/* cli.h - shared plumbing of the `holonomy` command-line tool.
 *
 * Contract: every subcommand is `int cli_cmd_NAME(int argc, char **argv)`
 * returning the process exit status:
 *   0  success
 *   1  a failure that is not the input's fault (I/O error, failed --check)
 *   2  bad input or bad usage: one line on stderr naming what is wrong (and
 *      the input line number when reading lines); nothing is printed for the
 *      offending line.
 * Line-oriented commands read standard input, strip a trailing "\n" and
 * "\r", and stop at the first bad line.
 */
#ifndef HOL_CLI_H
#define HOL_CLI_H

#include <stdio.h>
#include <stddef.h>
#include <stdint.h>

#define CLI_EXIT_OK 0
#define CLI_EXIT_FAIL 1
#define CLI_EXIT_USAGE 2

/* Run fn on every line of standard input until it returns nonzero (its
 * exit status, after it reported the problem) or the input ends. Lines
 * are streamed (platform/file/hol_lines.h: memory stays flat, each line is
 * answered as it arrives) and bounded: a line longer than CLI_LINE_MAX
 * bytes is bad input, refused when its CLI_LINE_MAX + 1st byte is read
 * ("line N: longer than 1048576 bytes", exit 2). A line is given without
 * its LF and one CR before it; it may hold NUL bytes, which fn refuses.
 * Handles read and write errors. Returns the exit status. */
#define CLI_LINE_MAX 1048576
typedef int (*cli_line_fn)(void *ctx, long lineno, char *s, size_t len);
int cli_for_each_line(const char *cmd, cli_line_fn fn, void *ctx);

/* A positive decimal count (no sign, at most 2^40); 0 on failure. */
size_t cli_parse_count(const char *s);

/* The value of --budget: a node count 1..CLI_BUDGET_MAX (the navigator's
 * arena, HOL_NAV_DEFAULT_NODES) into *out_budget: 0, or -1 after reporting
 * it for cmd. */
#define CLI_BUDGET_MAX 262144
int cli_budget_value(const char *cmd, const char *v, size_t *out_budget);

/* The value of --volume (play, xr): a number in 0..1 into *out_volume: 0,
 * or -1 after reporting it for cmd. */
int cli_volume_value(const char *cmd, const char *v, double *out_volume);
/* --lang L (core/hol_str.h: en, de or nl, exactly): 0 taken into
 * *out_lang; -1 a bad value, reported as one line. */
int cli_lang_value(const char *cmd, const char *v, int *out_lang);
#define CLI_LANG_USAGE                                                                   \
    "  --lang L        the language the player reads: en (the default), de or nl\n"      \
    "                  (the HUD, prompts, end screens and tutorial; logs, recordings\n" \
    "                  and this tool's messages stay in English)\n"

/* The geometry options (SPEC 7): opt "--tiling" with the value "4,Q" into
 * *q and, when cols is not NULL, "--room" with "CxR" into *cols and *rows
 * (a command without a room passes NULL: --room is then not its option).
 * Returns 1 (taken), 0 (another option) or -1 (a bad value, reported for
 * cmd as one line). */
int cli_geometry_value(const char *cmd, const char *opt, const char *v, int *q, int *cols,
                       int *rows);

/* An unsigned 64-bit number, decimal or 0x hex (a leading 0 is not octal;
 * no sign): seeds of every command, and other numbers. 1 ok, 0 bad. Every
 * command's seed defaults to CLI_SEED_DEFAULT. */
#define CLI_SEED_DEFAULT 1
int cli_parse_u64(const char *s, uint64_t *out);

/* One number grammar for every option (issue 39; docs/cli.md):
 * - cli_parse_doubles: "A,B,..." of exactly n finite plain decimal numbers
 *   (-D[.D][e[-+]D]: no blanks, plus, hex, inf, nan, ".5" or "5.", and
 *   none that under- or overflows: 1e-400) into out[0..n-1] (n 1..16):
 *   option values such as --eye X,Y,Z and --orient.
 * - cli_parse_real: one such number in lo..hi; where lo >= 0 no minus is
 *   taken ("-0" is not a volume).
 * - cli_parse_wxd: "WxD" (or "WXD") of two such numbers, each in lo..hi.
 * - cli_parse_decimal: an unsigned 64-bit number of decimal digits only
 *   (counts, radii, scales: only seeds take 0x hex, SPEC 7).
 * Each: 1 ok, 0 bad (the caller reports it). */
int cli_parse_doubles(const char *s, double *out, int n);
int cli_parse_real(const char *s, double lo, double hi, double *out);
int cli_parse_wxd(const char *s, double lo, double hi, double *w, double *d);
int cli_parse_decimal(const char *s, uint64_t *out);

/* Strip spaces and tabs at both ends. */
void cli_trim(char **s, size_t *len);

/* s (a name from a file or a device) escaped for a terminal into buf (cap
 * bytes; core/hol_text.h: control bytes, C1 and bidi controls, bad UTF-8
 * as \xHH, cut between characters when long); returns buf. Everything
 * from outside that reaches stdout goes through it (cli_error escapes its
 * whole message the same way). */
const char *cli_escape(const char *s, char *buf, size_t cap);

/* Print "holonomy CMD: line N: MESSAGE" (or without the line when
 * lineno <= 0) to stderr. */
void cli_error(const char *cmd, long lineno, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* The same, for an error on a command's way out (the session's end, the
 * environment row after the session), which may be the failure already
 * said once more (the disk still full): printed only when no cli_error or
 * cli_error_end line came before in this run. One line per failure. */
void cli_error_end(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Split s (length len) at runs of spaces and tabs; up to max fields.
 * Returns the number of fields found (max + 1 means "more than max"). */
int cli_split(char *s, size_t len, char **fields, size_t *lens, int max);

/* Read a whole input file of at most max bytes (platform/file): 0, or the
 * exit status of a failure reported as one line naming WHAT and PATH: a
 * file that cannot be opened, is not a regular file (a FIFO, a directory:
 * refused at once) or is larger than max is bad input (2); a failed read
 * or no memory is 1. Free *out_data with free(). */
int cli_read_file(const char *cmd, const char *what, const char *path, size_t max,
                  uint8_t **out_data, size_t *out_size);

/* Open a file to read a line at a time (platform/file/hol_lines.h: a
 * regular file only, lines of at most limit bytes): 0, or the exit status
 * of a failure reported as one line naming WHAT and PATH (as
 * cli_read_file). cli_lines_failed reports a failed hol_lines_next (a line
 * longer than the limit is bad input, 2, naming the line; a read error 1)
 * and returns the exit status. */
struct hol_lines;
int cli_open_lines(const char *cmd, const char *what, const char *path, size_t limit,
                   struct hol_lines *l);
int cli_lines_failed(const char *cmd, const char *what, const char *path,
                     const struct hol_lines *l);

/* 0 when path is NULL or names a folder; else report "OPT 'PATH' is not a
 * folder" (without OPT when it is NULL) and return CLI_EXIT_USAGE. */
int cli_require_folder(const char *cmd, const char *opt, const char *path);

/* 0 when path is NULL (no output) or may be written as an output: a
 * regular file or a new name in an existing folder (hol_file_check_out);
 * else report "OPT 'PATH' is a FIFO; an output is a regular file or a new
 * name in an existing folder" (without OPT when it is NULL) and return
 * CLI_EXIT_USAGE. Every command checks each output this way before any
 * work. */
int cli_check_output(const char *cmd, const char *opt, const char *path);

/* The option grammar of every command (docs/cli.md): options are valued
 * (each takes a value) or flags, both NULL-terminated lists, at most 64 in
 * all. A valued option takes its value as "--opt VALUE" (the next
 * argument, whatever it looks like: "--seed -h" is a seed) or
 * "--opt=VALUE"; a flag takes none ("--stats=1" is refused). "--" ends the
 * options: every argument after it is an operand. An argument "-" or one
 * that does not start with '-' is an operand. cli_opts_next gives 1 with
 * *opt one of the listed names (and *val its value, NULL for a flag) or
 * *opt NULL and *val an operand; 0 at the end; -1 after reporting a usage
 * error as one line: an unknown option, a missing value, a value given to
 * a flag, or an option given twice (both spellings count) unless it is in
 * repeatable (NULL: none; render --target). */
typedef struct cli_opts {
    const char *cmd;
    int argc, i, ended;
    char **argv;
    const char *const *valued, *const *flags, *const *repeatable;
    uint64_t seen;
} cli_opts;

void cli_opts_init(cli_opts *p, const char *cmd, int argc, char **argv,
                   const char *const *valued, const char *const *flags);
int cli_opts_next(cli_opts *p, const char **opt, const char **val);

/* "WxH" (--size), each side digits only in lo..hi: 0 ok, 1 not (one
 * parser for every command's --size; each its own range). */
int cli_size_value(const char *val, long lo, long hi, long *w, long *h);
/* --size with sides 16..4096 (play, replay): 0 ok, else reported and 1. */
int cli_parse_size(const char *cmd, const char *val, int *w, int *h);

/* SIGINT, SIGTERM and SIGHUP are caught (not fatal) from the first call of
 * cli_catch_signals on; cli_caught_signal gives the first one caught (0:
 * none) for a loop to end its session cleanly, and the command then exits
 * with 128 + that number, as the shell would report the signal. SIGPIPE is
 * ignored from then on: a write to a lost peer fails and is reported. */
void cli_catch_signals(void);
int cli_caught_signal(void);

/* No output may name a file (or folder) that the same command reads:
 * each output path of out[0..nout-1] that exists is compared with each
 * input of in[0..nin-1] (both resolved: stat follows symbolic links, and
 * device and inode are compared, so a link or a hard link to an input is
 * the input). 0, or report "OPT 'PATH' is INOPT 'PATH', which this
 * command reads" and return CLI_EXIT_USAGE, before anything is written.
 * NULL paths are skipped. Every command with file inputs and outputs
 * calls it (play, xr, replay, world, report). */
typedef struct cli_path {
    const char *opt; /* "--record", "LEVEL" */
    const char *path;
} cli_path;
int cli_check_distinct(const char *cmd, const cli_path *in, int nin, const cli_path *out,
                       int nout);

/* Every file a command reads is never one it writes (issue 39): the
 * outputs out[0..nout-1] as cli_check_distinct compares them, and the
 * files a session writes in its --log folder log_dir (NULL: none): each
 * entry of log_dir that is a log file (hol_session_is_log_name),
 * environment.csv, a study-HASH.txt or the folder's lock is compared (device and inode) with
 * each input, so that `--input DIR/summary.csv`, or a level linked to one,
 * is refused. cli_check_reads: 0, or one line "OPT 'PATH' is ..., which
 * this command writes" and CLI_EXIT_USAGE. play, xr and replay call it on
 * their options, and play_study_levels on every level file a study names. */
typedef struct cli_outs {
    const cli_path *out;
    int nout;
    const char *log_dir;
} cli_outs;
int cli_check_reads(const char *cmd, const cli_path *in, int nin, const cli_outs *outs);

/* The options that only store, as a table (the last entry's opt NULL): a
 * flag sets an int field of the options' struct to its value, a valued
 * option keeps its value in a const char * field. cli_store_opt: 1 when a
 * is one of the table's (stored), 0 not. */
typedef struct cli_store {
    const char *opt;
    size_t off;      /* offsetof the field */
    int is_flag, value;
} cli_store;
#define CLI_STORE_STR(opt, type, field) {opt, offsetof(type, field), 0, 0}
#define CLI_STORE_FLAG(opt, type, field, v) {opt, offsetof(type, field), 1, v}
int cli_store_opt(const cli_store *t, const char *a, const char *val, void *opts);

/* Flush stdout; on failure report it and return CLI_EXIT_FAIL. */
int cli_finish_output(const char *cmd);

/* True when argv[1..] asks for help: -h or --help as an option, before
 * any "--" and not as the value of one of the valued options (the
 * command's list, as for cli_opts_init: "--seed -h" is not help). */
int cli_wants_help(int argc, char **argv, const char *const *valued);
/* A command's --help: usage printed to stdout when cli_wants_help, and
 * cli_finish_output's status returned; -1 when no help is asked. */
int cli_help(const char *cmd, int argc, char **argv, const char *const *valued,
             const char *usage);

/* Subcommands. Each but report has its usage text and its valued options
 * (cli_NAME_usage, cli_NAME_valued): main.c answers its --help from them
 * (cli_help) before it runs the command. */
#define CLI__HELP(name) \
    extern const char *const cli_##name##_usage; \
    extern const char *const cli_##name##_valued[];
CLI__HELP(tile) CLI__HELP(world) CLI__HELP(nav) CLI__HELP(tour) CLI__HELP(render) CLI__HELP(play)
CLI__HELP(game) CLI__HELP(replay) CLI__HELP(hid) CLI__HELP(xr) CLI__HELP(props)
CLI__HELP(lesson)
#undef CLI__HELP
int cli_cmd_tile(int argc, char **argv);
int cli_cmd_world(int argc, char **argv);
int cli_cmd_nav(int argc, char **argv);
int cli_cmd_tour(int argc, char **argv);
int cli_cmd_render(int argc, char **argv);
int cli_cmd_play(int argc, char **argv);
int cli_cmd_game(int argc, char **argv);
int cli_cmd_replay(int argc, char **argv);
int cli_cmd_hid(int argc, char **argv);
int cli_cmd_xr(int argc, char **argv);
int cli_cmd_report(int argc, char **argv);
int cli_cmd_props(int argc, char **argv);
int cli_cmd_lesson(int argc, char **argv);

#endif
