/* hol_props.c - where real props stand in the room (hol_props.h). */
#include "hol_props.h"

#include <math.h>

typedef struct hol__page {
    const char *name;
    double w, h;
} hol__page;

static const hol__page hol__pages[] = {
    {"A4 portrait", 210, 297},
    {"A4 landscape", 297, 210},
    {"A3 portrait", 297, 420},
    {"A3 landscape", 420, 297},
};

static int hol__desc_ok(const hol_props_desc *d)
{
    if (d->cols < 3 || d->cols > 5 || d->rows < 3 || d->rows > 5)
        return 0;
    if (!(d->cell_m >= 0.5 && d->cell_m <= 1.5))
        return 0;
    if (d->scale != 0 && (d->scale < HOL_PROPS_SCALE_MIN || d->scale > HOL_PROPS_SCALE_MAX))
        return 0;
    int has_w = d->area_w != 0, has_d = d->area_d != 0;
    if (has_w != has_d)
        return 0;
    if (has_w && !(d->area_w > 0 && d->area_w <= HOL_PROPS_AREA_MAX && d->area_d > 0 &&
                   d->area_d <= HOL_PROPS_AREA_MAX))
        return 0;
    return 1;
}

/* The page where the content box (w x h metres) fits at 1:scale: its index
 * or -1. */
static int hol__fit_page(double w, double h, int scale)
{
    double cw = w * 1000.0 / scale, ch = h * 1000.0 / scale;
    double need_w = 2 * HOL_PROPS_MARGIN_MM + HOL_PROPS_DIM_MM + HOL_PROPS_RIGHT_MM + cw;
    double need_h = 2 * HOL_PROPS_MARGIN_MM + HOL_PROPS_HEAD_MM + HOL_PROPS_DIM_MM +
                    HOL_PROPS_FOOT_MM + ch;
    for (int k = 0; k < (int)(sizeof hol__pages / sizeof hol__pages[0]); k++)
        if (need_w <= hol__pages[k].w && need_h <= hol__pages[k].h)
            return k;
    return -1;
}

static void hol__trees(hol_props *p)
{
    p->ntrees = p->ninner = 0;
    for (int j = 0; j <= p->rows; j++)
        for (int i = 0; i <= p->cols; i++) {
            hol_props_tree *t = &p->trees[p->ntrees++];
            int on_x = i == 0 || i == p->cols, on_z = j == 0 || j == p->rows;
            t->i = i;
            t->j = j;
            t->x = i * p->cell_m;
            t->z = j * p->cell_m;
            t->kind = on_x && on_z ? HOL_PROPS_CORNER : on_x || on_z ? HOL_PROPS_SIDE
                                                                     : HOL_PROPS_INNER;
            p->ninner += t->kind == HOL_PROPS_INNER;
        }
}

static void hol__hedge(hol_props *p, int i0, int j0, int i1, int j1)
{
    hol_props_hedge *h = &p->hedges[p->nhedges++];
    h->x0 = i0 * p->cell_m;
    h->z0 = j0 * p->cell_m;
    h->x1 = i1 * p->cell_m;
    h->z1 = j1 * p->cell_m;
}

static void hol__hedges(hol_props *p)
{
    int c = p->cols, r = p->rows;
    p->nhedges = 0;
    for (int i = 0; i < c; i++)
        hol__hedge(p, i, 0, i + 1, 0);
    for (int j = 0; j < r; j++)
        hol__hedge(p, c, j, c, j + 1);
    for (int i = c; i > 0; i--)
        hol__hedge(p, i, r, i - 1, r);
    for (int j = r; j > 0; j--)
        hol__hedge(p, 0, j, 0, j - 1);
}

hol_err hol_props_plan(const hol_props_desc *d, hol_props *out)
{
    if (!d || !out || !hol__desc_ok(d))
        return HOL_EARG;
    hol_props p;
    p.cols = d->cols;
    p.rows = d->rows;
    p.cell_m = d->cell_m;
    p.room_w = d->cols * d->cell_m;
    p.room_d = d->rows * d->cell_m;
    p.has_area = d->area_w != 0;
    p.area_w = d->area_w;
    p.area_d = d->area_d;
    p.area_x0 = p.has_area ? (p.room_w - d->area_w) / 2 : 0;
    p.area_z0 = p.has_area ? (p.room_d - d->area_d) / 2 : 0;
    /* the content box: the room and the play area */
    double x0 = fmin(0, p.area_x0), z0 = fmin(0, p.area_z0);
    double x1 = p.has_area ? fmax(p.room_w, p.area_x0 + p.area_w) : p.room_w;
    double z1 = p.has_area ? fmax(p.room_d, p.area_z0 + p.area_d) : p.room_d;
    static const int autos[] = {20, 25, 50, 100};
    int k = -1;
    if (d->scale) {
        p.scale = d->scale;
        k = hol__fit_page(x1 - x0, z1 - z0, p.scale);
    } else {
        for (int a = 0; a < 4 && k < 0; a++)
            k = hol__fit_page(x1 - x0, z1 - z0, p.scale = autos[a]);
    }
    if (k < 0)
        return HOL_ERANGE;
    p.page = hol__pages[k].name;
    p.page_w = hol__pages[k].w;
    p.page_h = hol__pages[k].h;
    /* the content box centred across the page, under the header */
    double cw = (x1 - x0) * 1000.0 / p.scale;
    double left = HOL_PROPS_MARGIN_MM + HOL_PROPS_DIM_MM;
    double room_left = left + (p.page_w - HOL_PROPS_MARGIN_MM - HOL_PROPS_RIGHT_MM - left - cw) / 2;
    p.ox = room_left - x0 * 1000.0 / p.scale;
    p.oy = HOL_PROPS_MARGIN_MM + HOL_PROPS_HEAD_MM + HOL_PROPS_DIM_MM - z0 * 1000.0 / p.scale;
    hol__trees(&p);
    hol__hedges(&p);
    *out = p;
    return HOL_OK;
}
