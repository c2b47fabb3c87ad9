#include "hol_room.h"

hol_room hol_room_start(void)
{
    hol_room r;
    r.tile = hol_tile_origin();
    r.orient = 0;
    r.col = 1;
    r.row = 1;
    r.more_cols = r.more_rows = 0;
    return r;
}

hol_err hol_room_start_in(int q, int cols, int rows, hol_room *out_room)
{
    q = q ? q : HOL_TILING_DEFAULT_Q;
    cols = cols ? cols : HOL_ROOM_SIZE;
    rows = rows ? rows : HOL_ROOM_SIZE;
    if (q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q || cols < HOL_ROOM_MIN_SIDE ||
        cols > HOL_ROOM_MAX_SIDE || rows < HOL_ROOM_MIN_SIDE || rows > HOL_ROOM_MAX_SIDE)
        return HOL_EARG;
    hol_room r;
    r.tile = hol_tile_origin_q(q);
    r.orient = 0;
    r.col = (uint8_t)(cols / 2);
    r.row = (uint8_t)(rows / 2);
    r.more_cols = (uint8_t)(cols - HOL_ROOM_MIN_SIDE);
    r.more_rows = (uint8_t)(rows - HOL_ROOM_MIN_SIDE);
    *out_room = r;
    return HOL_OK;
}

int hol_room_ok(const hol_room *r)
{
    return r && r->orient < 4 && r->more_cols <= 2 && r->more_rows <= 2 &&
           r->col < hol_room_cols(r) && r->row < hol_room_rows(r) && hol_tile_q(r->tile);
}

int hol_dir_from_char(int c)
{
    switch (c) {
    case 'N': return HOL_DIR_N;
    case 'W': return HOL_DIR_W;
    case 'S': return HOL_DIR_S;
    case 'E': return HOL_DIR_E;
    default: return -1;
    }
}

char hol_dir_to_char(int dir) { return "NWSE"[dir & 3]; }

void hol_dir_delta(int dir, int *out_dcol, int *out_drow)
{
    static const int8_t dc[4] = {0, -1, 0, 1}, dr[4] = {-1, 0, 1, 0};
    *out_dcol = dc[dir & 3];
    *out_drow = dr[dir & 3];
}

hol_err hol_room_step(hol_room *room, int dir)
{
    static const int8_t dc[4] = {0, -1, 0, 1}, dr[4] = {-1, 0, 1, 0};
    int arr;
    hol_tile t;
    if ((unsigned)dir > 3 || room->more_cols > 2 || room->more_rows > 2)
        return HOL_EARG;
    unsigned c = (unsigned)(room->col + dc[dir]), r = (unsigned)(room->row + dr[dir]);
    if (c >= HOL_ROOM_MIN_SIDE + (unsigned)room->more_cols ||
        r >= HOL_ROOM_MIN_SIDE + (unsigned)room->more_rows)
        return HOL_EROOM;
    hol_err err = hol_tile_step(room->tile, room->orient + dir, &t, &arr);
    if (err)
        return err;
    room->tile = t;
    room->orient = (uint8_t)((arr - dir) & 3);
    room->col = (uint8_t)c;
    room->row = (uint8_t)r;
    return HOL_OK;
}

hol_err hol_walk_parse(const char *s, size_t len, uint8_t *out_dirs, size_t cap,
                       size_t *out_n, size_t *out_bad)
{
    if (len == 1 && s[0] == '-') {
        *out_n = 0;
        return HOL_OK;
    }
    for (size_t i = 0; i < len; i++) {
        if (hol_dir_from_char((unsigned char)s[i]) < 0) {
            if (out_bad)
                *out_bad = i;
            return HOL_EPARSE;
        }
    }
    if (len > cap)
        return HOL_ENOMEM;
    for (size_t i = 0; i < len; i++)
        out_dirs[i] = (uint8_t)hol_dir_from_char((unsigned char)s[i]);
    *out_n = len;
    return HOL_OK;
}

hol_err hol_room_walk(hol_room *room, const uint8_t *dirs, size_t n,
                      size_t *out_done)
{
    size_t i = 0;
    hol_err err = HOL_OK;
    for (; i < n; i++) {
        err = hol_room_step(room, dirs[i]);
        if (err)
            break;
    }
    if (out_done)
        *out_done = i;
    return err;
}

/* A decimal number of 1 to 3 digits at s[*i]; -1 if none. */
static int hol__num(const char *s, size_t len, size_t *i)
{
    int v = 0, n = 0;
    while (*i < len && s[*i] >= '0' && s[*i] <= '9' && n < 3) {
        v = 10 * v + (s[*i] - '0');
        (*i)++;
        n++;
    }
    if (n == 0 || (*i < len && s[*i] >= '0' && s[*i] <= '9'))
        return -1;
    return v;
}

hol_err hol_room_parse_tiling(const char *s, size_t len, int *out_q)
{
    size_t i = 0;
    int brace = len > 0 && s[0] == '{';
    i += (size_t)brace;
    int p = hol__num(s, len, &i);
    if (p < 0 || i >= len || s[i] != ',')
        return HOL_EPARSE;
    i++;
    int q = hol__num(s, len, &i);
    if (q < 0 || (brace && (i >= len || s[i++] != '}')) || i != len)
        return HOL_EPARSE;
    if (p != 4 || q < HOL_TILING_MIN_Q || q > HOL_TILING_MAX_Q)
        return HOL_EARG;
    *out_q = q;
    return HOL_OK;
}

hol_err hol_room_parse_size(const char *s, size_t len, int *out_cols, int *out_rows)
{
    size_t i = 0;
    int c = hol__num(s, len, &i);
    if (c < 0 || i >= len || (s[i] != 'x' && s[i] != 'X'))
        return HOL_EPARSE;
    i++;
    int r = hol__num(s, len, &i);
    if (r < 0 || i != len)
        return HOL_EPARSE;
    if (c < HOL_ROOM_MIN_SIDE || c > HOL_ROOM_MAX_SIDE || r < HOL_ROOM_MIN_SIDE ||
        r > HOL_ROOM_MAX_SIDE)
        return HOL_EARG;
    *out_cols = c;
    *out_rows = r;
    return HOL_OK;
}
