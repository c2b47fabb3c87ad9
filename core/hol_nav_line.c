#include "hol_nav_line.h"

#include <stdio.h>
#include <string.h>

/* Printable excerpt of s for messages: at most 40 characters. */
static void hol__shown(const char *s, size_t len, char out[48])
{
    size_t n = len < 40 ? len : 40;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)s[i];
        out[i] = (c < 0x20 || c > 0x7e) ? '?' : (char)c;
    }
    strcpy(out + n, len > 40 ? "..." : "");
}

static void hol__msg(char *msg, size_t cap, const char *text)
{
    if (msg && cap) {
        strncpy(msg, text, cap - 1);
        msg[cap - 1] = '\0';
    }
}

hol_err hol_nav_parse_prefix(const char *s, size_t len, hol_room *out_room,
                             char *msg, size_t msg_cap)
{
    hol_room start = hol_room_start();
    return hol_nav_parse_prefix_in(&start, s, len, out_room, msg, msg_cap);
}

hol_err hol_nav_parse_prefix_in(const hol_room *start, const char *s, size_t len,
                                hol_room *out_room, char *msg, size_t msg_cap)
{
    char buf[160];
    if (len == 1 && s[0] == '-')
        len = 0;
    for (size_t i = 0; i < len; i++) {
        if (hol_dir_from_char((unsigned char)s[i]) < 0) {
            unsigned char c = (unsigned char)s[i];
            if (c >= 0x21 && c <= 0x7e)
                snprintf(buf, sizeof buf,
                         "prefix character %zu '%c' is not a step (N, E, S, W or '-' for none)",
                         i + 1, c);
            else
                snprintf(buf, sizeof buf,
                         "prefix character %zu (byte 0x%02x) is not a step (N, E, S, W or '-' for none)",
                         i + 1, c);
            hol__msg(msg, msg_cap, buf);
            return HOL_EPARSE;
        }
    }
    if (len > HOL_NAV_PREFIX_MAX) {
        snprintf(buf, sizeof buf, "prefix longer than %d steps", HOL_NAV_PREFIX_MAX);
        hol__msg(msg, msg_cap, buf);
        return HOL_ERANGE;
    }
    hol_room room = *start;
    for (size_t i = 0; i < len; i++) {
        int d = hol_dir_from_char((unsigned char)s[i]);
        hol_err err = hol_room_step(&room, d);
        if (err == HOL_EROOM) {
            snprintf(buf, sizeof buf,
                     "prefix step %zu (%c from cell (%d,%d)) leaves the room", i + 1,
                     s[i], room.col, room.row);
            hol__msg(msg, msg_cap, buf);
            return HOL_EROOM;
        }
        if (err) {
            snprintf(buf, sizeof buf,
                     "prefix step %zu goes beyond distance %d from O, the reach of tile words",
                     i + 1, hol_tile_reach(hol_tile_q(start->tile)));
            hol__msg(msg, msg_cap, buf);
            return HOL_ERANGE;
        }
    }
    *out_room = room;
    return HOL_OK;
}

hol_err hol_nav_parse_target(const char *s, size_t len, hol_tile *out_tile,
                             char *msg, size_t msg_cap)
{
    return hol_nav_parse_target_q(5, s, len, out_tile, msg, msg_cap);
}

hol_err hol_nav_parse_target_q(int q, const char *s, size_t len, hol_tile *out_tile,
                               char *msg, size_t msg_cap)
{
    char buf[200], shown[48];
    hol_tile t;
    hol_err err = hol_tile_parse_q(q, s, (ptrdiff_t)len, &t);
    if (!err && memchr(s, '\0', len))
        err = HOL_EPARSE;
    if (!err) {
        *out_tile = t;
        return HOL_OK;
    }
    hol__shown(s, len, shown);
    if (err == HOL_ENOTCANON) {
        char canon[HOL_TILE_ADDR_MAX];
        if (!hol_tile_resolve_q(q, s, (ptrdiff_t)len, &t)) {
            hol_tile_print(t, canon);
            snprintf(buf, sizeof buf,
                     "target '%s' is not a canonical address (that walk reaches %s)",
                     shown, canon);
        } else {
            snprintf(buf, sizeof buf, "target '%s' is not a canonical address", shown);
        }
    } else if (err == HOL_ERANGE) {
        snprintf(buf, sizeof buf,
                 "target '%s' is longer than %d letters, the reach of tile words",
                 shown, hol_tile_reach(q));
    } else {
        err = HOL_EPARSE;
        snprintf(buf, sizeof buf,
                 "target '%s' is not an address (O, or N/E/S/W then f/l/r)", shown);
    }
    hol__msg(msg, msg_cap, buf);
    return err;
}

static int hol__blank(char c) { return c == ' ' || c == '\t'; }

hol_err hol_nav_parse_line(const char *s, size_t len, hol_room *out_room,
                           hol_tile *out_target, char *msg, size_t msg_cap)
{
    hol_room start = hol_room_start();
    return hol_nav_parse_line_in(&start, s, len, out_room, out_target, msg, msg_cap);
}

hol_err hol_nav_parse_line_in(const hol_room *start, const char *s, size_t len,
                              hol_room *out_room, hol_tile *out_target, char *msg,
                              size_t msg_cap)
{
    if (memchr(s, '\0', len)) {
        hol__msg(msg, msg_cap, "line holds a NUL byte");
        return HOL_EPARSE;
    }
    const char *f[2];
    size_t fl[2];
    int n = 0;
    size_t i = 0;
    while (i < len) {
        while (i < len && hol__blank(s[i]))
            i++;
        if (i >= len)
            break;
        size_t b = i;
        while (i < len && !hol__blank(s[i]))
            i++;
        if (n == 2) {
            n = 3;
            break;
        }
        f[n] = s + b;
        fl[n] = i - b;
        n++;
    }
    if (n != 2) {
        hol__msg(msg, msg_cap,
                 n < 2 ? "expected 'PREFIX TARGET' (a room walk or '-', then an address)"
                       : "expected 'PREFIX TARGET', found more than two fields");
        return HOL_EPARSE;
    }
    hol_room room;
    hol_tile target;
    hol_err err = hol_nav_parse_prefix_in(start, f[0], fl[0], &room, msg, msg_cap);
    if (err)
        return err;
    err = hol_nav_parse_target_q(hol_tile_q(start->tile), f[1], fl[1], &target, msg, msg_cap);
    if (err)
        return err;
    *out_room = room;
    *out_target = target;
    return HOL_OK;
}
