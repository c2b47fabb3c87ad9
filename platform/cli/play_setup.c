/* play_setup.c - what `holonomy play` and `holonomy xr` share: the level
 * list (a LEVEL file, a --mode level from the seed, or the default
 * campaign) and recorded input lines (see play_setup.h). */
#include "play_setup.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_input_io.h"
#include "../../core/hol_tile.h"
#include "cli.h"

int read_lines(const char *cmd, const char *path, file_lines *fl)
{
    size_t size = 0;
    memset(fl, 0, sizeof *fl);
    int rs = cli_read_file(cmd, "input", path, (size_t)1 << 30, &fl->data, &size);
    if (rs)
        return rs;
    long cap = 1;
    for (size_t i = 0; i < size; i++)
        cap += fl->data[i] == '\n';
    fl->line = malloc((size_t)cap * sizeof *fl->line);
    fl->len = malloc((size_t)cap * sizeof *fl->len);
    uint8_t *buf = realloc(fl->data, size + 1);
    if (!fl->line || !fl->len || !buf) {
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    fl->data = buf;
    fl->data[size] = 0;
    size_t start = 0;
    for (size_t i = 0; i <= size; i++) {
        if (i == size || fl->data[i] == '\n') {
            if (i == size && start == size)
                break;
            size_t e = i;
            if (e > start && fl->data[e - 1] == '\r')
                e--;
            fl->data[e] = 0;
            fl->line[fl->n] = (char *)fl->data + start;
            fl->len[fl->n++] = e - start;
            start = i + 1;
        }
    }
    return 0;
}

int read_input_lines(const char *cmd, const char *path, file_lines *fl, long *out_first)
{
    *out_first = 0;
    int st = read_lines(cmd, path, fl);
    if (st) {
        free_lines(fl);
        return st;
    }
    /* a recording: skip its header */
    if (fl->n && !strncmp(fl->line[0], "holonomy-rec ", 13)) {
        static session_level skip[SESSION_MAX_LEVELS];
        int ns;
        char err[256];
        long first = session_read_header(fl->line, fl->len, fl->n, skip, &ns, err, sizeof err);
        if (!first) {
            cli_error(cmd, 0, "%.200s: %s", path, err);
            free_lines(fl);
            return CLI_EXIT_USAGE;
        }
        *out_first = first - 1;
    }
    return 0;
}

void free_lines(file_lines *fl)
{
    free(fl->data);
    free(fl->line);
    free(fl->len);
}

/* Input line k of a file (after an optional recording header) or 1 with
 * the error reported. */
int parse_input_line(const char *cmd, const file_lines *fl, long k, hol_input *in,
                            double *prev_t)
{
    size_t bad = 0;
    if (hol_input_parse(fl->line[k], fl->len[k], in, &bad)) {
        cli_error(cmd, k + 1, "not an input record (byte %zu)", bad + 1);
        return 1;
    }
    if (in->time_s < *prev_t) {
        cli_error(cmd, k + 1, "time %.17g goes back (before: %.17g)", in->time_s, *prev_t);
        return 1;
    }
    *prev_t = in->time_s;
    return 0;
}

static uint64_t splitmix(uint64_t *x)
{
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* A tile at distance d from O, from the generator: a random canonical
 * address (the branch, then f, l or r wherever the address stays
 * canonical). */
static hol_tile seeded_tile(uint64_t *rng, int d)
{
    static const int letters[3] = {0, 1, 3};
    hol_tile t = hol_tile_origin();
    for (int i = 0; i < d; i++) {
        hol_tile c;
        int first = (int)(splitmix(rng) % (i ? 3 : 4));
        for (int k = 0; k < 3; k++)
            if (!hol_tile_child(t, i ? letters[(first + k) % 3] : first, &c))
                break;
        t = c;
    }
    return t;
}

/* A level of mode m made from the seed: the flag at distance dist; or
 * nkeys keys at distance 2..3 and the chest at distance dist. The level's
 * text is what a level file would hold, so recordings carry it. */
static int mode_level(const char *mode, uint64_t seed, int dist, int nkeys, const char *name,
                      session_level *L)
{
    memset(L, 0, sizeof *L);
    uint64_t rng = seed;
    char a[HOL_TILE_ADDR_MAX];
    int n = 0;
    if (!strcmp(mode, "explore") || !strcmp(mode, "tutorial")) {
        n = snprintf(L->text, sizeof L->text, "mode %s\nseed %llu\n", mode,
                     (unsigned long long)seed);
    } else if (!strcmp(mode, "flag")) {
        hol_tile_print(seeded_tile(&rng, dist), a);
        n = snprintf(L->text, sizeof L->text, "mode flag\nseed %llu\nflag %s\n",
                     (unsigned long long)seed, a);
    } else if (!strcmp(mode, "keys")) {
        hol_tile keys[HOL_APP_MAX_KEYS], chest = seeded_tile(&rng, dist);
        n = snprintf(L->text, sizeof L->text, "mode keys\nseed %llu\nkeys",
                     (unsigned long long)seed);
        for (int k = 0; k < nkeys; k++) {
            int fresh;
            do {
                keys[k] = seeded_tile(&rng, 2 + (int)(splitmix(&rng) % 2));
                fresh = !hol_tile_eq(keys[k], chest);
                for (int j = 0; j < k; j++)
                    fresh &= !hol_tile_eq(keys[k], keys[j]);
            } while (!fresh);
            hol_tile_print(keys[k], a);
            n += snprintf(L->text + n, sizeof L->text - (size_t)n, " %s", a);
        }
        hol_tile_print(chest, a);
        n += snprintf(L->text + n, sizeof L->text - (size_t)n, "\nchest %s\n", a);
    } else {
        return 1;
    }
    L->len = (size_t)n;
    if (name)
        snprintf(L->name, sizeof L->name, "%s", name);
    else
        snprintf(L->name, sizeof L->name, "%s-%llu", mode, (unsigned long long)seed);
    char err[256];
    return session_parse_level(L->text, L->len, &L->lvl, err, sizeof err);
}

/* The default campaign (no LEVEL, no --mode): the tutorial, three flags
 * at growing distance, then two keys-and-chest levels. */
static int default_campaign(uint64_t seed, session_level *levels)
{
    int n = 0;
    if (mode_level("tutorial", seed, 0, 0, "tutorial", &levels[n++]))
        return -1;
    static const int flag_dist[3] = {3, 5, 7};
    char name[32];
    for (int i = 0; i < 3; i++) {
        snprintf(name, sizeof name, "flag-%d", i + 1);
        if (mode_level("flag", seed + (uint64_t)i, flag_dist[i], 0, name, &levels[n++]))
            return -1;
    }
    for (int i = 0; i < 2; i++) {
        snprintf(name, sizeof name, "keys-%d", i + 1);
        if (mode_level("keys", seed + 3 + (uint64_t)i, 3 + i, 2 + i, name, &levels[n++]))
            return -1;
    }
    return n;
}

int play_levels(const char *cmd, const char *level_path, const char *mode, uint64_t seed,
                session_level *levels, int *nlevels)
{
    *nlevels = 0;
    if (level_path) {
        uint8_t *data = NULL;
        size_t size = 0;
        int rs = cli_read_file(cmd, "level", level_path, SESSION_LEVEL_TEXT - 1, &data, &size);
        if (rs)
            return rs;
        session_level *L = &levels[(*nlevels)++];
        memcpy(L->text, data, size);
        L->len = size;
        free(data);
        const char *base = strrchr(level_path, '/');
        base = base ? base + 1 : level_path;
        size_t bl = strcspn(base, ".");
        snprintf(L->name, sizeof L->name, "%.*s", (int)(bl < 60 ? bl : 60), base);
        char perr[256];
        if (session_parse_level(L->text, L->len, &L->lvl, perr, sizeof perr)) {
            cli_error(cmd, 0, "%.200s: %s", level_path, perr);
            return CLI_EXIT_USAGE;
        }
    } else if (mode) {
        if (mode_level(mode, seed, 5, 3, NULL, &levels[(*nlevels)++])) {
            cli_error(cmd, 0, "--mode '%.40s' is not one of tutorial, flag, keys, explore",
                      mode);
            return CLI_EXIT_USAGE;
        }
    } else {
        *nlevels = default_campaign(seed, levels);
        if (*nlevels < 0) {
            cli_error(cmd, 0, "cannot make the default campaign");
            return CLI_EXIT_FAIL;
        }
    }
    return 0;
}

int play_load_pad_script(const char *cmd, const char *path, hol_hid_script *sc)
{
    uint8_t *data = NULL;
    size_t size = 0;
    int st = cli_read_file(cmd, "gamepad script", path, (size_t)64 << 20, &data, &size);
    if (st)
        return st;
    long line = 0;
    hol_err err = hol_hid_script_parse(sc, (const char *)data, size, &line);
    free(data);
    if (err) {
        cli_error(cmd, line, "'%.200s': %s", path,
                  err == HOL_ENOMEM ? "too many events or report bytes"
                                    : "not a gamepad script event (README: Gamepads)");
        return CLI_EXIT_USAGE;
    }
    return 0;
}
