/* hol_nav_field.c - the minimap's hot-cold field and direction arrows
 * (hol_nav_field, hol_nav_direction; contract in hol_nav.h). Pure functions
 * of tiles: no navigator, no allocation.
 */
#include "hol_nav.h"

#include "hol_hyper.h"
#include "hol_nav_impl.h"

/* ---- hot-cold field and direction ---- */

#define HOL__FIELD_MAX_RADIUS 8

size_t hol_nav_field_count_q(int q, int radius)
{
    if (radius < 0 || radius > HOL__FIELD_MAX_RADIUS)
        return 0;
    return hol_navtab_count_q(q, radius);
}

size_t hol_nav_field_count(int radius) { return hol_nav_field_count_q(5, radius); }

hol_err hol_nav_field(const hol_room *user, int radius, const hol_tile *objectives,
                      size_t n, hol_nav_cell *out_cells, size_t cap,
                      size_t *out_n)
{
    if (!hol_room_ok(user) || radius < 0 || radius > HOL__FIELD_MAX_RADIUS ||
        (n && !objectives) || !out_cells || !out_n)
        return HOL_EARG;
    int q = hol_tile_q(user->tile);
    for (size_t j = 0; j < n; j++)
        if (hol_tile_q(objectives[j]) != q)
            return HOL_EARG;
    hol_navtab ix;
    hol_navtab_init(&ix, q, 0, 0, radius);
    if (cap < ix.count)
        return HOL_ENOMEM;
    for (uint32_t i = 0; i < ix.count; i++) {
        hol_tile rel = hol_navtab_unrank(&ix, i);
        int len = hol_tile_dist0(rel);
        hol_heading_tile f = {user->tile, user->orient};
        for (int k = 0; k < len; k++) {
            hol_err err = hol_heading_tile_step(f, hol_tile_letter(rel, k), &f);
            if (err)
                return err;
        }
        hol_nav_cell *c = &out_cells[i];
        c->tile = f.tile;
        c->rel = rel;
        c->user_dist = (int16_t)len;
        c->hot = -1;
        for (size_t j = 0; j < n; j++) {
            int dd = hol_tile_dist(f.tile, objectives[j]);
            if (dd >= 0 && (c->hot < 0 || dd < c->hot))
                c->hot = (int16_t)(dd > INT16_MAX ? INT16_MAX : dd);
        }
    }
    *out_n = ix.count;
    return HOL_OK;
}

hol_err hol_nav_direction(const hol_room *user, hol_tile objective,
                          double *out_angle, double *out_dist)
{
    if (!hol_room_ok(user) || hol_tile_q(objective) != hol_tile_q(user->tile))
        return HOL_EARG;
    double angle, dist;
    hol_err err = hol_hyper_pos(user->tile, user->orient, objective, NULL, &angle,
                                &dist);
    if (err)
        return err;
    if (hol_tile_eq(user->tile, objective)) {
        angle = 0.0;
        dist = 0.0;
    }
    if (out_angle)
        *out_angle = angle;
    if (out_dist)
        *out_dist = dist;
    return HOL_OK;
}
