#include "hol_room.h"

hol_room hol_room_start(void)
{
    hol_room r;
    r.tile = hol_tile_origin();
    r.orient = 0;
    r.col = 1;
    r.row = 1;
    return r;
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
    int dc, dr, arr;
    hol_tile t;
    if (dir < 0 || dir > 3)
        return HOL_EARG;
    hol_dir_delta(dir, &dc, &dr);
    int c = room->col + dc, r = room->row + dr;
    if (c < 0 || c >= HOL_ROOM_SIZE || r < 0 || r >= HOL_ROOM_SIZE)
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
