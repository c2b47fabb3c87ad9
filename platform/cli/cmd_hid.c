/* cmd_hid.c - `holonomy hid parse|list|watch`: HID report descriptors and
 * game controllers (SPEC section 6). */
#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../file/hol_file.h"
#include "../hid/hol_hid_desc.h"
#include "../hid/hol_hid_dev.h"
#include "../hid/hol_hid_pad.h"
#include "cli.h"
#include "play_setup.h"

const char *const cli_hid_usage =
    "usage: holonomy hid parse FILE\n"
    "       holonomy hid list\n"
    "       holonomy hid watch [--frames N] [--replay FILE]\n"
    "\n"
    "  hid parse FILE  print the input field map of a HID report descriptor,\n"
    "                  one line per element of every non-constant Input item:\n"
    "                  ID OFFSET SIZE PAGE:USAGE MIN MAX (SPEC section 6);\n"
    "                  an array element prints PAGE:MIN-MAX. FILE holds raw\n"
    "                  bytes or hex text (two hex digits a byte, optional 0x,\n"
    "                  separated by spaces, commas or newlines); '-' reads\n"
    "                  standard input.\n"
    "  hid list        the game controllers found (Generic Desktop Gamepad,\n"
    "                  Joystick, Multi-axis Controller) and their field maps;\n"
    "                  'no game controllers found' when there is none.\n"
    "  hid watch       print the decoded input of the first controller, one\n"
    "                  line a change: buttons, move x y, turn x y; stops\n"
    "                  after --frames N reads of 10 ms (default: until the\n"
    "                  controller goes away). --replay FILE watches a scripted\n"
    "                  controller (README: Gamepads) instead, on a clock of\n"
    "                  10 ms a read, without waiting, until the script ends\n"
    "                  ('# end of script') or unplugs its controller.\n"
    "\n"
    "Exit status: 0 ok, 1 no controller (watch) or an I/O error, 2 bad input\n"
    "or usage (one line on stderr).\n";

#define DESC_MAX (64u * 1024u)
#define MAP_CAP (64u * 1024u)

static int is_hex_text_byte(uint8_t c)
{
    return isxdigit(c) || c == 'x' || c == 'X' || c == ' ' || c == ',' ||
           c == '\t' || c == '\r' || c == '\n';
}

/* Hex text to bytes in place (out <= in). Returns the byte count, or -1
 * after reporting the bad token. */
static long hex_to_bytes(const char *cmd, const char *path, uint8_t *buf,
                         size_t len)
{
    size_t i = 0, n = 0;
    long line = 1;
    while (i < len) {
        uint8_t c = buf[i];
        if (c == ' ' || c == ',' || c == '\t' || c == '\r' || c == '\n') {
            line += c == '\n';
            i++;
            continue;
        }
        size_t start = i;
        while (i < len && isxdigit(buf[i]) | (buf[i] == 'x') | (buf[i] == 'X'))
            i++;
        const uint8_t *t = buf + start;
        size_t tl = i - start;
        if (tl == 4 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
            t += 2;
            tl = 2;
        }
        if (tl != 2 || !isxdigit(t[0]) || !isxdigit(t[1])) {
            cli_error(cmd, line, "'%s': '%.*s' is not a hex byte", path,
                      (int)(i - start < 20 ? i - start : 20),
                      (const char *)buf + start);
            return -1;
        }
        char hx[3] = {(char)t[0], (char)t[1], 0};
        buf[n++] = (uint8_t)strtoul(hx, NULL, 16);
    }
    return (long)n;
}

/* Read a descriptor file (raw or hex text). 0 ok, else the exit status. */
static int load_desc(const char *cmd, const char *path, uint8_t **out,
                     size_t *out_len)
{
    uint8_t *data = NULL;
    size_t size = 0;
    if (!strcmp(path, "-")) {
        data = malloc(DESC_MAX + 1);
        if (!data)
            return CLI_EXIT_FAIL;
        size = fread(data, 1, DESC_MAX + 1, stdin);
        if (ferror(stdin)) {
            free(data);
            cli_error(cmd, 0, "cannot read standard input");
            return CLI_EXIT_FAIL;
        }
        if (size > DESC_MAX) {
            free(data);
            cli_error(cmd, 0, "'-': larger than %u bytes", DESC_MAX);
            return CLI_EXIT_USAGE;
        }
    } else {
        int rs = cli_read_file(cmd, "descriptor", path, DESC_MAX, &data, &size);
        if (rs)
            return rs;
    }
    int text = size > 0;
    for (size_t i = 0; i < size && text; i++)
        text = is_hex_text_byte(data[i]);
    if (text) {
        long n = hex_to_bytes(cmd, path, data, size);
        if (n < 0) {
            free(data);
            return CLI_EXIT_USAGE;
        }
        size = (size_t)n;
    }
    *out = data;
    *out_len = size;
    return 0;
}

static void print_field(FILE *f, const hol_hid_field *fd)
{
    fprintf(f, "%u %" PRIu32 " %u %04" PRIx32 ":%04" PRIx32, fd->report_id,
            fd->bit_offset, fd->size, fd->usage >> 16, fd->usage & 0xffffu);
    if (fd->flags & HOL_HID_F_ARRAY)
        fprintf(f, "-%04" PRIx32, fd->usage_max & 0xffffu);
    fprintf(f, " %" PRId64 " %" PRId64 "\n", fd->logical_min, fd->logical_max);
}

static int cmd_parse(int argc, char **argv)
{
    const char *cmd = "hid parse", *a, *val, *path = NULL;
    cli_opts p;
    int r, nops = 0;
    cli_opts_init(&p, cmd, argc - 1, argv + 1, NULL, NULL);
    while ((r = cli_opts_next(&p, &a, &val)) > 0)
        path = nops++ ? path : val;
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (nops != 1) {
        cli_error(cmd, 0, nops < 1 ? "missing FILE; see --help" : "takes one FILE; see --help");
        return CLI_EXIT_USAGE;
    }
    uint8_t *desc;
    size_t len;
    int st = load_desc(cmd, path, &desc, &len);
    if (st)
        return st;
    hol_hid_field *map = malloc(MAP_CAP * sizeof *map);
    if (!map) {
        free(desc);
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    size_t n;
    hol_err err = hol_hid_desc_parse(desc, len, map, MAP_CAP, &n, NULL);
    if (err == HOL_ENOMEM)
        cli_error(cmd, 0, "'%s': more than %u input elements", path, MAP_CAP);
    else if (err)
        cli_error(cmd, 0, "'%s': not a valid HID report descriptor (%zu bytes)",
                  path, len);
    else
        for (size_t i = 0; i < n; i++)
            print_field(stdout, &map[i]);
    free(map);
    free(desc);
    if (err)
        return CLI_EXIT_USAGE;
    return cli_finish_output(cmd);
}

static void list_one(void *ctx, const hol_hid_dev_info *info,
                     const hol_hid_field *fields, size_t n, hol_err err)
{
    (void)ctx;
    const hol_hid_known *k = hol_hid_known_find(info->vid, info->pid);
    char path[4 * sizeof info->path], name[4 * sizeof info->name];
    printf("%04x:%04x %s usage %04x:%04x %s%s%s\n", info->vid, info->pid,
           cli_escape(info->path, path, sizeof path), info->usage_page, info->usage,
           info->name[0] ? cli_escape(info->name, name, sizeof name) : "(no name)",
           k ? " known: " : "", k ? k->name : "");
    if (err)
        printf("  (descriptor not read: %s)\n", hol_err_str(err));
    for (size_t i = 0; i < n; i++) {
        fputs("  ", stdout);
        print_field(stdout, &fields[i]);
    }
}

static int cmd_list(int argc, char **argv)
{
    (void)argv;
    if (argc != 2) {
        cli_error("hid list", 0, "takes no arguments; see --help");
        return CLI_EXIT_USAGE;
    }
    if (hol_hid_dev_list(list_one, NULL) == 0)
        printf("no game controllers found (hidapi %s backend)\n",
               hol_hid_dev_backend());
    return cli_finish_output("hid list");
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

const char *const cli_hid_valued[] = {"--replay", "--frames", NULL};

static int cmd_watch(int argc, char **argv)
{
    const char *cmd = "hid watch";
    size_t frames = 0;
    const char *script_path = NULL, *a, *val;
    cli_opts p;
    int r;
    cli_opts_init(&p, cmd, argc - 1, argv + 1, cli_hid_valued, NULL);
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a) {
            cli_error(cmd, 0, "unknown argument '%.40s'; see --help", val);
            return CLI_EXIT_USAGE;
        } else if (!strcmp(a, "--replay")) {
            script_path = val;
        } else if (!(frames = cli_parse_count(val))) {
            cli_error(cmd, 0, "--frames needs a positive count; see --help");
            return CLI_EXIT_USAGE;
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    static hol_hid_dev dev;
    static hol_hid_script script;
    if (script_path) {
        int st = play_load_pad_script(cmd, script_path, &script);
        if (st)
            return st;
        if (hol_hid_dev_open_backend(&dev, hol_hid_script_backend(&script), 0.0)) {
            cli_error(cmd, 0, "no game controller plugged in at 0 s in '%.200s'", script_path);
            return CLI_EXIT_FAIL;
        }
    } else if (hol_hid_dev_open_first(&dev)) {
        cli_error(cmd, 0, "no game controller found (hidapi %s backend)",
                  hol_hid_dev_backend());
        return CLI_EXIT_FAIL;
    }
    char name[4 * sizeof dev.info.name];
    printf("# %04x:%04x %s\n", dev.info.vid, dev.info.pid,
           cli_escape(dev.info.name, name, sizeof name));
    hol_input in, last;
    memset(&in, 0, sizeof in);
    memset(&last, 0xff, sizeof last);
    for (size_t f = 0; frames == 0 || f < frames; f++) {
        in.time_s = script_path ? (double)f * 0.01 : now_s();
        hol_err err = hol_hid_dev_poll(&dev, &in);
        /* a change (-0 is 0; the first poll always prints: last is NaN) */
        if (in.buttons != last.buttons || in.move[0] != last.move[0] ||
            in.move[1] != last.move[1] || in.turn[0] != last.turn[0] ||
            in.turn[1] != last.turn[1]) {
            printf("buttons 0x%02x move %.3f %.3f turn %.3f %.3f\n", in.buttons,
                   in.move[0] + 0.0f, in.move[1] + 0.0f, in.turn[0] + 0.0f, in.turn[1] + 0.0f);
            fflush(stdout);
            last = in;
        }
        if (err) {
            printf("# controller lost\n");
            break;
        }
        if (script_path && hol_hid_script_done(&script)) {
            printf("# end of script\n");
            break;
        }
        if (!script_path)
            nanosleep(&(struct timespec){0, 10 * 1000 * 1000}, NULL);
    }
    hol_hid_dev_close(&dev);
    return cli_finish_output(cmd);
}

int cli_cmd_hid(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "parse"))
        return cmd_parse(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "list"))
        return cmd_list(argc, argv);
    if (argc >= 2 && !strcmp(argv[1], "watch"))
        return cmd_watch(argc, argv);
    if (argc < 2)
        cli_error("hid", 0, "missing subcommand (parse, list or watch); see --help");
    else
        cli_error("hid", 0, "unknown subcommand '%.40s'; see --help", argv[1]);
    return CLI_EXIT_USAGE;
}
