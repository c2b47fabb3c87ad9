/* cmd_world.c - `holonomy world`: the seeded forest around a walk; save and
 * load world images (written atomically: temporary file, fsync, rename). */
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../core/hol_room.h"
#include "../../core/hol_tile.h"
#include "../../core/hol_world.h"
#include "../file/hol_file.h"
#include "cli.h"

const char *const cli_world_usage =
    "usage: holonomy world [--seed S] [--walk W] [--radius R] [--check]\n"
    "                      [--load FILE] [--save FILE] [--capacity N] [--quiet]\n"
    "                      [--stats] [--tiling 4,Q] [--room CxR]\n"
    "       holonomy world save FILE [OPTIONS]   (same as --save FILE)\n"
    "       holonomy world load FILE [OPTIONS]   (same as --load FILE)\n"
    "\n"
    "Generates the forest for seed S (an unsigned 64-bit number, decimal or\n"
    "0x hex; default 1) as the app does: the user starts on the origin tile in\n"
    "cell (1,1), takes the room steps of W (N, E, S, W; '-' for none; a step\n"
    "that leaves the 3 x 3 room is bad input) and after every step the world\n"
    "collapses every tile within 4 steps of the user. Then it prints every\n"
    "tile within R steps (0..8, default 4) of the tile the walk ends on, one\n"
    "per line, sorted by distance from that tile, then by address:\n"
    "\n"
    "  ADDRESS BIOME OBJECT ROTATION CONNECTORS\n"
    "\n"
    "  BIOME       meadow, pine, wetland or autumn\n"
    "  OBJECT      none, grass, flowers, log, creek, spring, pool, rock,\n"
    "              mushroom (flag, key, chest once the game places them)\n"
    "  ROTATION    0..3 quarter turns counter-clockwise from the tile's\n"
    "              canonical heading (the direction of the last address step)\n"
    "  CONNECTORS  four characters for the edges forward, left, back, right\n"
    "              (relative to the canonical heading): '-' none, 'c' creek,\n"
    "              'l' log (the other half of the log lies across that edge)\n"
    "Example line: Nrf pine creek 1 -c-c\n"
    "Tiles farther than 4 from the user are collapsed on demand. Tiles\n"
    "beyond distance 60 from O do not exist (the reach of tile words).\n"
    "\n"
    "  --tiling 4,Q    the tiling {4,Q}, Q from 4 (the flat grid) to 8, default\n"
    "                  4,5: Q tiles round every vertex and its tree (tiles\n"
    "                  reach 59 in the tilings other than {4,5})\n"
    "  --room CxR      a room of C x R cells (3 to 5 each, default 3x3); the\n"
    "                  walk starts on cell (C/2, R/2). A loaded world keeps\n"
    "                  the tiling and room it was saved with (neither option\n"
    "                  goes with --load)\n"
    "  --check         verify every constraint of every tile in the store\n"
    "                  after the walk; a violation is reported on stderr and\n"
    "                  exits 1\n"
    "  --save FILE     write the world (seed, store, user state) to FILE\n"
    "                  atomically (temporary file, fsync, rename): FILE is\n"
    "                  either the old or the complete new world\n"
    "  --load FILE     start from a saved world and its saved user state\n"
    "                  (a regular file; its header is checked against its\n"
    "                  size before the rest is read)\n"
    "                  instead of a new one (not with --seed); W continues\n"
    "                  from there. A truncated, corrupt or wrong-version\n"
    "                  FILE is bad input (exit 2) and FILE is left untouched\n"
    "  --capacity N    tiles in the store (default 1048576, fixed; rounded up\n"
    "                  to a power of two). Refused below what the radius needs\n"
    "                  (4096 tiles for radius 4), above 2^28, or needing more\n"
    "                  than half of this machine's memory\n"
    "  --quiet         print no tiles\n"
    "  --stats         print a last line: '# tiles N capacity C collapsed X\n"
    "                  evicted Y backtracks Z bytes B' (the store after the walk)\n"
    "\n"
    "Exit status: 0 ok, 1 failed --check or an I/O error, 2 bad usage or\n"
    "input (one line on stderr).\n";

#define CMD "world"
/* --capacity: at most 2^28 tiles (about 9 GiB of store) */
#define WORLD_MAX_CAPACITY (UINT32_C(1) << 28)

typedef struct world_opts {
    uint64_t seed;
    int have_seed;
    const char *walk;
    int radius;
    int check;
    int quiet;
    int stats;
    const char *load;
    const char *save;
    uint32_t capacity;
    int q, cols, rows, have_geometry;
} world_opts;

const char *const cli_world_valued[] = {"--seed", "--walk",     "--radius", "--load",
                                           "--save", "--capacity", "--tiling", "--room",
                                           NULL};

/* One option with a value: 0 ok, else reported and 1. */
static int parse_value(const char *a, const char *v, world_opts *o)
{
    int g = cli_geometry_value(CMD, a, v, &o->q, &o->cols, &o->rows);
    if (g) {
        o->have_geometry = 1;
        return g < 0;
    }
    if (!strcmp(a, "--seed")) {
        if (!cli_parse_u64(v, &o->seed)) {
            cli_error(CMD, 0, "--seed '%.40s' is not an unsigned 64-bit number", v);
            return 1;
        }
        o->have_seed = 1;
    } else if (!strcmp(a, "--walk")) {
        o->walk = v;
    } else if (!strcmp(a, "--radius")) {
        uint64_t r;
        if (!cli_parse_decimal(v, &r) || r > HOL_WORLD_MAX_RADIUS) {
            cli_error(CMD, 0, "--radius '%.40s' is not a number 0..%d", v, HOL_WORLD_MAX_RADIUS);
            return 1;
        }
        o->radius = (int)r;
    } else if (!strcmp(a, "--capacity")) {
        uint64_t c;
        if (!cli_parse_decimal(v, &c) || c < 1 || c > WORLD_MAX_CAPACITY) {
            cli_error(CMD, 0, "--capacity '%.40s' is not a number of tiles 1..%u", v,
                      (unsigned)WORLD_MAX_CAPACITY);
            return 1;
        }
        o->capacity = (uint32_t)c;
    } else {
        const char **slot = a[2] == 'l' ? &o->load : &o->save;
        if (*slot) { /* 'world save FILE --save FILE2' */
            cli_error(CMD, 0, "%s is given twice; give each option once ('world %s FILE' "
                              "is %s FILE)", a, a + 2, a);
            return 1;
        }
        *slot = v;
    }
    return 0;
}

static const cli_store world_store[] = {CLI_STORE_FLAG("--check", world_opts, check, 1),
                                        CLI_STORE_FLAG("--quiet", world_opts, quiet, 1),
                                        CLI_STORE_FLAG("--stats", world_opts, stats, 1),
                                        {NULL, 0, 0, 0}};

static int parse_args(int argc, char **argv, world_opts *o)
{
    static const char *const flags[] = {"--check", "--quiet", "--stats", NULL};
    memset(o, 0, sizeof *o);
    o->seed = CLI_SEED_DEFAULT;
    o->radius = 4;
    o->walk = "-";
    cli_opts p;
    const char *a, *v, *ops[2] = {NULL, NULL};
    int r, nops = 0;
    cli_opts_init(&p, CMD, argc, argv, cli_world_valued, flags);
    while ((r = cli_opts_next(&p, &a, &v)) > 0) {
        if (!a && nops == 2) {
            cli_error(CMD, 0, "unknown argument '%.40s'; see --help", v);
            return 0;
        }
        if (!a)
            ops[nops++] = v;
        else if (!cli_store_opt(world_store, a, v, o) && parse_value(a, v, o))
            return 0;
    }
    if (r < 0)
        return 0;
    if (nops && strcmp(ops[0], "save") && strcmp(ops[0], "load")) {
        cli_error(CMD, 0, "unknown argument '%.40s'; see --help", ops[0]);
        return 0;
    }
    if (nops == 1) {
        cli_error(CMD, 0, "'%s' needs a FILE; see --help", ops[0]);
        return 0;
    }
    if (nops == 2) {
        const char **slot = ops[0][0] == 's' ? &o->save : &o->load;
        if (*slot) {
            cli_error(CMD, 0, "--%s is given twice; give each option once ('world %s FILE' "
                              "is --%s FILE)", ops[0], ops[0], ops[0]);
            return 0;
        }
        *slot = ops[1];
    }
    if (o->load && o->have_seed) {
        cli_error(CMD, 0, "--seed and --load exclude each other (the file holds "
                          "its seed)");
        return 0;
    }
    if (o->load && o->have_geometry) {
        cli_error(CMD, 0, "--tiling and --room do not go with --load (the file holds "
                          "its tiling and room)");
        return 0;
    }
    const cli_path in = {"--load", o->load}, out = {"--save", o->save};
    return !cli_check_distinct(CMD, &in, 1, &out, 1);
}

/* Read a whole file: 0, or the exit status of a failure already reported
 * (a file that cannot be opened is bad input). */
static int read_file(const char *path, uint8_t **out_buf, size_t *out_len)
{
    /* the header first: the length it promises must be the file's size
     * before anything else is read (a huge or endless file is refused at
     * once), and only regular files are opened (a FIFO never blocks) */
    hol_file_in f;
    hol_err err = hol_file_open_in(path, &f);
    if (err == HOL_EOPEN) {
        cli_error(CMD, 0, "cannot open '%.200s': %s", path, strerror(errno));
        return CLI_EXIT_USAGE;
    }
    if (err == HOL_EARG) {
        cli_error(CMD, 0, "'%.200s' is %s, not a regular file", path,
                  errno == EISDIR ? "a directory" : "a FIFO, socket or device");
        return CLI_EXIT_USAGE;
    }
    if (err) {
        cli_error(CMD, 0, "cannot read '%.200s': %s", path, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    uint8_t hdr[HOL_WORLD_IMAGE_HEADER];
    size_t got = 0;
    uint64_t want = 0;
    char msg[160];
    if ((err = hol_file_read_in(&f, hdr, sizeof hdr, &got))) {
        cli_error(CMD, 0, "cannot read '%.200s': %s", path, strerror(errno));
        hol_file_close_in(&f);
        return CLI_EXIT_FAIL;
    }
    if ((err = hol_world_image_size(hdr, got, &want, msg, sizeof msg))) {
        cli_error(CMD, 0, "'%.200s': %s", path, msg);
        hol_file_close_in(&f);
        return CLI_EXIT_USAGE;
    }
    if (want != f.size) {
        cli_error(CMD, 0, "'%.200s': %s%llu bytes, but the header promises %llu", path,
                  f.size < want ? "truncated: " : "", (unsigned long long)f.size,
                  (unsigned long long)want);
        hol_file_close_in(&f);
        return CLI_EXIT_USAGE;
    }
    uint8_t *buf = malloc((size_t)want);
    if (!buf) {
        cli_error(CMD, 0, "'%.200s': out of memory (%llu bytes)", path,
                  (unsigned long long)want);
        hol_file_close_in(&f);
        return CLI_EXIT_FAIL;
    }
    memcpy(buf, hdr, got);
    size_t rest = 0;
    err = hol_file_read_in(&f, buf + got, (size_t)want - got, &rest);
    hol_file_close_in(&f);
    if (err || got + rest != want) {
        cli_error(CMD, 0, "cannot read '%.200s': %s", path,
                  err ? strerror(errno) : "it changed while being read");
        free(buf);
        return err ? CLI_EXIT_FAIL : CLI_EXIT_USAGE;
    }
    *out_buf = buf;
    *out_len = (size_t)want;
    return 0;
}

/* Write buf to path atomically. Returns 1 on success. */
static int write_atomic(const char *path, const uint8_t *buf, size_t len)
{
    if (hol_file_write_atomic(path, buf, len)) {
        cli_error(CMD, 0, "cannot write '%s': %s", path, strerror(errno));
        return 0;
    }
    return 1;
}

typedef struct world_line {
    hol_tile tile;
    int dist;
    char addr[HOL_TILE_ADDR_MAX];
} world_line;

static int line_cmp(const void *a, const void *b)
{
    const world_line *x = a, *y = b;
    if (x->dist != y->dist)
        return x->dist - y->dist;
    size_t lx = strlen(x->addr), ly = strlen(y->addr);
    if (lx != ly)
        return lx < ly ? -1 : 1;
    return strcmp(x->addr, y->addr);
}

static const char *gen_error(hol_err err)
{
    switch (err) {
    case HOL_ENOMEM: return "the world store is full (raise --capacity)";
    case HOL_EBUDGET: return "generation gave up (backtracking budget)";
    default: return hol_err_str(err);
    }
}

static int print_tiles(hol_world *w, hol_tile centre, int radius)
{
    size_t cap = 16384, n = 0; /* radius 8 of {4,8}: 11081 tiles */
    world_line *lines = malloc(cap * sizeof *lines);
    if (!lines) {
        cli_error(CMD, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    lines[n].tile = centre;
    lines[n].dist = 0;
    n++;
    for (size_t q = 0; q < n; q++) {
        if (lines[q].dist >= radius)
            continue;
        for (int d = 0; d < 4; d++) {
            hol_tile t;
            if (hol_tile_step(lines[q].tile, d, &t, NULL))
                continue; /* beyond the reach of tile words */
            int seen = 0;
            for (size_t i = 0; i < n && !seen; i++)
                seen = hol_tile_eq(lines[i].tile, t);
            if (seen || n >= cap)
                continue;
            lines[n].tile = t;
            lines[n].dist = lines[q].dist + 1;
            n++;
        }
    }
    for (size_t i = 0; i < n; i++)
        hol_tile_print(lines[i].tile, lines[i].addr);
    qsort(lines, n, sizeof *lines, line_cmp);
    for (size_t i = 0; i < n; i++) {
        hol_tile_content c;
        hol_err err = hol_world_get(w, lines[i].tile, &c);
        if (err) {
            cli_error(CMD, 0, "tile %s: %s", lines[i].addr, gen_error(err));
            free(lines);
            return CLI_EXIT_FAIL;
        }
        printf("%s %s %s %d %c%c%c%c\n", lines[i].addr, hol_biome_name(c.biome),
               hol_object_name(c.object), c.rotation, hol_conn_char(c.conn[0]),
               hol_conn_char(c.conn[1]), hol_conn_char(c.conn[2]),
               hol_conn_char(c.conn[3]));
    }
    free(lines);
    return CLI_EXIT_OK;
}

/* The world the options ask for: a new one from the seed, or FILE loaded,
 * in a store of --capacity tiles. 0 ok, else the exit status (reported). */
static int check_capacity(const world_opts *o, hol_world_desc *desc)
{
    /* the bounds: at least what the radius needs, and memory the machine
     * has (at most half of it); every refusal says which */
    hol_world_desc lo = *desc;
    lo.capacity = 1;
    uint32_t minimum = hol_world_capacity_of(&lo);
    if (o->capacity < minimum) {
        cli_error(CMD, 0, "--capacity %u is below the minimum of %u tiles for radius %d",
                  (unsigned)o->capacity, (unsigned)minimum,
                  desc->radius ? desc->radius : HOL_WORLD_DEFAULT_RADIUS);
        return CLI_EXIT_USAGE;
    }
    if (o->load && o->capacity < desc->capacity) {
        cli_error(CMD, 0, "--capacity %u cannot hold '%.200s' (it needs %u tiles)",
                  (unsigned)o->capacity, o->load, (unsigned)desc->capacity);
        return CLI_EXIT_USAGE;
    }
    desc->capacity = o->capacity;
    size_t need = hol_world_mem_size(desc);
    long pages = sysconf(_SC_PHYS_PAGES), psize = sysconf(_SC_PAGESIZE);
    double have = pages > 0 && psize > 0 ? (double)pages * (double)psize : 0;
    if (have > 0 && (double)need > have / 2) {
        cli_error(CMD, 0, "--capacity %u needs %.0f MiB, more than half of this "
                  "machine's %.0f MiB", (unsigned)o->capacity, need / 1048576.0,
                  have / 1048576.0);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

static int make_world(const world_opts *o, hol_world **out)
{
    hol_world_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.seed = o->seed;
    desc.tiling_q = o->q;
    uint8_t *image = NULL;
    size_t image_len = 0;
    char msg[200];
    int st = o->load ? read_file(o->load, &image, &image_len) : 0;
    if (!st && o->load && hol_world_image_desc(image, image_len, &desc, msg, sizeof msg)) {
        cli_error(CMD, 0, "'%s': %s", o->load, msg);
        st = CLI_EXIT_USAGE;
    }
    if (!st && o->capacity)
        st = check_capacity(o, &desc);
    hol_err err = st ? HOL_OK : hol_world_make(&desc, out);
    if (err == HOL_ENOMEM)
        cli_error(CMD, 0, "cannot allocate %.0f MiB for the world store",
                  hol_world_mem_size(&desc) / 1048576.0);
    else if (err)
        cli_error(CMD, 0, "cannot make the world: %s", hol_err_str(err));
    if (err)
        st = CLI_EXIT_FAIL;
    if (!st && o->load && hol_world_load(*out, image, image_len, msg, sizeof msg)) {
        cli_error(CMD, 0, "'%s': %s", o->load, msg);
        hol_world_destroy(*out);
        st = CLI_EXIT_USAGE;
    }
    free(image);
    return st;
}

/* --walk parsed into *out (malloc'ed, *n steps): a syntax error comes
 * before any world is made. 0 ok, else the exit status (reported). */
static int parse_walk(const char *walk, uint8_t **out, size_t *n)
{
    size_t wlen = strlen(walk), bad = 0;
    if (!(*out = malloc(wlen + 1))) {
        cli_error(CMD, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    if (hol_walk_parse(walk, wlen, *out, wlen + 1, n, &bad)) {
        cli_error(CMD, 0, "--walk: character %zu is not a step (N, E, S or W)", bad + 1);
        free(*out);
        return CLI_EXIT_USAGE;
    }
    return 0;
}

/* The steps in the room, the world collapsing around the user after each.
 * 0 ok, else the exit status (reported); *room where the walk ends. */
static int walk_world(hol_world *w, const world_opts *o, const uint8_t *dirs, size_t n,
                      hol_room *room)
{
    *room = hol_world_user(w);
    if (!o->load)
        hol_room_start_in(o->q, o->cols, o->rows, room);
    hol_err err = hol_world_update(w, room);
    for (size_t i = 0; !err && i < n; i++) {
        hol_room next = *room;
        hol_err serr = hol_room_step(&next, dirs[i]);
        if (serr == HOL_EROOM) {
            cli_error(CMD, 0, "--walk: step %zu (%c) leaves the room from cell (%d,%d)",
                      i + 1, hol_dir_to_char(dirs[i]), room->col, room->row);
            return CLI_EXIT_USAGE;
        }
        if (serr) {
            cli_error(CMD, 0, "--walk: step %zu goes beyond distance %d from O, the "
                      "reach of tile words", i + 1, hol_tile_reach(hol_tile_q(room->tile)));
            return CLI_EXIT_USAGE;
        }
        *room = next;
        err = hol_world_update(w, room);
    }
    if (err) {
        cli_error(CMD, 0, "generation failed: %s", gen_error(err));
        return CLI_EXIT_FAIL;
    }
    return 0;
}

static void print_stats(hol_world *w)
{
    hol_world_stats st;
    hol_world_get_stats(w, &st);
    printf("# tiles %" PRIu32 " capacity %" PRIu32 " collapsed %" PRIu64 " evicted %" PRIu64
           " backtracks %" PRIu64 " bytes %zu\n",
           st.count, st.capacity, st.tiles_collapsed, st.evicted, st.backtracks, st.bytes);
}

static int save_world(hol_world *w, const char *path)
{
    size_t need = hol_world_save_size(w), len = 0;
    uint8_t *buf = malloc(need);
    if (!buf) {
        cli_error(CMD, 0, "cannot save: out of memory");
        return CLI_EXIT_FAIL;
    }
    hol_err err = hol_world_save(w, buf, need, &len);
    if (err)
        cli_error(CMD, 0, "cannot save: %s", hol_err_str(err));
    int st = err || !write_atomic(path, buf, len) ? CLI_EXIT_FAIL : 0;
    free(buf);
    return st;
}

int cli_cmd_world(int argc, char **argv)
{
    world_opts o;
    if (!parse_args(argc, argv, &o) || cli_check_output(CMD, "--save", o.save))
        return CLI_EXIT_USAGE;
    uint8_t *dirs;
    size_t nsteps = 0;
    int status = parse_walk(o.walk, &dirs, &nsteps);
    if (status)
        return status;
    hol_world *w;
    if ((status = make_world(&o, &w))) {
        free(dirs);
        return status;
    }
    hol_room room;
    status = walk_world(w, &o, dirs, nsteps, &room);
    free(dirs);
    if (!status && !o.quiet)
        status = print_tiles(w, room.tile, o.radius);
    char msg[256];
    if (!status && o.check && hol_world_check(w, msg, sizeof msg)) {
        cli_error(CMD, 0, "check failed: %s", msg);
        status = CLI_EXIT_FAIL;
    }
    if (!status && o.stats)
        print_stats(w);
    if (!status && o.save)
        status = save_world(w, o.save);
    hol_world_destroy(w);
    int out = cli_finish_output(CMD);
    return status ? status : out;
}
