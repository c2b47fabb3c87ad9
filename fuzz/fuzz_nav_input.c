/* fuzz_nav_input.c - libFuzzer harness for guidance input (nav and tour).
 *
 * Input: text as `holonomy nav` reads it (lines "PREFIX TARGET"); a line
 * starting with "T " is split like `holonomy tour` arguments instead
 * (PREFIX KEY... CHEST). Checks: the parsers either succeed or write a
 * one-line printable message; a parsed target prints back to the same
 * address; for parsed input a small navigator (radius 5, trusted 3) returns
 * walks that stay in the room and end on the target (tours: visit every key,
 * then the chest). A line "G Q CxR" switches the tiling and the room (SPEC
 * 7) for the lines after it: the parsers read in that geometry, the
 * navigator is one of it (radius 6), and a target no walk reaches
 * (HOL_EUNREACH, in {4,4} and {4,8}) is accepted. Only core/ is linked.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../core/hol_nav.h"
#include "../core/hol_nav_line.h"
#include "../core/hol_room.h"
#include "../core/hol_tile.h"

#include "fuzz_check.h"

static int g_q = 5, g_cols = 3, g_rows = 3;

static hol_nav *nav_small(void)
{
    static hol_nav *nav;
    static int q, cols, rows;
    if (nav && (q != g_q || cols != g_cols || rows != g_rows)) {
        hol_nav_destroy(nav);
        nav = NULL;
    }
    if (!nav) {
        hol_nav_desc d = {0};
        d.radius = g_q == 5 && g_cols == 3 && g_rows == 3 ? 5 : 6;
        d.max_nodes = 4096;
        d.tiling_q = q = g_q;
        d.room_cols = cols = g_cols;
        d.room_rows = rows = g_rows;
        CHECK(hol_nav_create(&d, &nav) == HOL_OK);
    }
    return nav;
}

static hol_room start_room(void)
{
    hol_room r;
    CHECK(hol_room_start_in(g_q, g_cols, g_rows, &r) == HOL_OK);
    return r;
}

/* "G Q CxR": the geometry of the following lines (ignored when bad). */
static void run_geometry(const char *s, size_t len)
{
    int q, c, r;
    if (len < 3 || hol_room_parse_size(s + 2, len - 2, &c, &r) || s[0] < '4' || s[0] > '8' ||
        s[1] != ' ')
        return;
    q = s[0] - '0';
    g_q = q;
    g_cols = c;
    g_rows = r;
}

static void check_msg(const char *msg, size_t cap)
{
    size_t n = strnlen(msg, cap);
    CHECK(n > 0 && n < cap);
    for (size_t i = 0; i < n; i++)
        CHECK((unsigned char)msg[i] >= 0x20 && (unsigned char)msg[i] < 0x7f);
}

static uint8_t walk[HOL_NAV_WALK_MAX];

static void run_nav(const hol_room *room, hol_tile target)
{
    if (hol_tile_dist(room->tile, target) > 24)
        return; /* keep each input fast */
    hol_nav_result res;
    hol_err err = hol_nav_find(nav_small(), room, target, 64, walk, sizeof walk, &res);
    if (err == HOL_EUNREACH && (g_q == 4 || g_q == 8))
        return;
    CHECK(err == HOL_OK);
    hol_room r = *room;
    for (int i = 0; i < res.len; i++)
        CHECK(hol_room_step(&r, walk[i]) == HOL_OK);
    CHECK(hol_tile_eq(r.tile, target));
}

static void run_line(const char *s, size_t len)
{
    char msg[96];
    hol_room room;
    hol_tile target;
    memset(msg, 0, sizeof msg);
    hol_room start = start_room();
    hol_err err = hol_nav_parse_line_in(&start, s, len, &room, &target, msg, sizeof msg);
    if (err) {
        check_msg(msg, sizeof msg);
        return;
    }
    char buf[HOL_TILE_ADDR_MAX];
    int n = hol_tile_print(target, buf);
    int found = 0;
    for (size_t i = 0; !found && i + (size_t)n <= len; i++)
        found = !memcmp(s + i, buf, (size_t)n);
    CHECK(n > 0 && found);
    run_nav(&room, target);
}

static void run_tour(const char *s, size_t len)
{
    const char *f[8];
    size_t fl[8];
    int n = 0;
    size_t i = 0;
    while (i < len && n < 8) {
        while (i < len && s[i] == ' ')
            i++;
        if (i >= len)
            break;
        f[n] = s + i;
        while (i < len && s[i] != ' ')
            i++;
        fl[n] = (size_t)(s + i - f[n]);
        n++;
    }
    if (n < 2 || n > HOL_NAV_TOUR_MAX_KEYS + 2)
        return;
    char msg[96];
    hol_room room;
    hol_tile t[HOL_NAV_TOUR_MAX_KEYS + 1];
    memset(msg, 0, sizeof msg);
    hol_room start = start_room();
    if (hol_nav_parse_prefix_in(&start, f[0], fl[0], &room, msg, sizeof msg)) {
        check_msg(msg, sizeof msg);
        return;
    }
    for (int k = 1; k < n; k++) {
        memset(msg, 0, sizeof msg);
        if (hol_nav_parse_target_q(g_q, f[k], fl[k], &t[k - 1], msg, sizeof msg)) {
            check_msg(msg, sizeof msg);
            return;
        }
        if (hol_tile_dist(room.tile, t[k - 1]) > 4)
            return;
    }
    int nk = n - 2;
    hol_nav_result res;
    hol_err err = hol_nav_tour(nav_small(), &room, t, nk, t[nk], 256, walk, sizeof walk, &res);
    if (err == HOL_EUNREACH && (g_q == 4 || g_q == 8))
        return;
    CHECK(err == HOL_OK);
    hol_room r = room;
    unsigned got = 0;
    for (int k = 0; k < nk; k++)
        if (hol_tile_eq(r.tile, t[k]))
            got |= 1u << k;
    for (int j = 0; j < res.len; j++) {
        CHECK(hol_room_step(&r, walk[j]) == HOL_OK);
        for (int k = 0; k < nk; k++)
            if (hol_tile_eq(r.tile, t[k]))
                got |= 1u << k;
    }
    CHECK(got == (1u << nk) - 1);
    CHECK(hol_tile_eq(r.tile, t[nk]));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *s = (const char *)data;
    g_q = 5, g_cols = 3, g_rows = 3;
    size_t start = 0;
    for (size_t i = 0; i <= size; i++) {
        if (i == size || s[i] == '\n') {
            size_t len = i - start;
            if (len > 0 && s[start + len - 1] == '\r')
                len--;
            if (len >= 2 && s[start] == 'T' && s[start + 1] == ' ')
                run_tour(s + start + 2, len - 2);
            else if (len >= 2 && s[start] == 'G' && s[start + 1] == ' ')
                run_geometry(s + start + 2, len - 2);
            else
                run_line(s + start, len);
            start = i + 1;
        }
    }
    return 0;
}
