/* props_svg.c - the plan of `holonomy props` as SVG (millimetres; the
 * page's size in width and height, so it prints at scale at 100 %).
 * Elements the tests read: rect.floor (the room's floor), line.hedge,
 * circle.tree-inner / tree-side / tree-corner (trunk footprints at true
 * size, data-m="X,Z" metres), rect.play-area. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../core/hol_props.h"
#include "cli.h"

int props_write_svg(FILE *f, const hol_props *p, int q, const char *level_name,
                    const struct hol_props_desc *d);

/* Metres as the plan writes them: at most 3 decimals, no trailing zeros. */
static const char *props_m(double m, char *buf)
{
    snprintf(buf, 24, "%.3f", m);
    char *e = buf + strlen(buf);
    while (e > buf && e[-1] == '0')
        *--e = '\0';
    if (e > buf && e[-1] == '.')
        e[-1] = '\0';
    return buf;
}

/* A name from outside as XML text: printable ASCII, the markup characters
 * as entities, anything else '?'. */
static void props_xml_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '&')
            fputs("&amp;", f);
        else if (c == '<')
            fputs("&lt;", f);
        else if (c == '>')
            fputs("&gt;", f);
        else if (c == '"')
            fputs("&quot;", f);
        else
            fputc(c >= 0x20 && c < 0x7f ? c : '?', f);
    }
}

static void props_head(FILE *f, const hol_props *p, int q, const char *level_name)
{
    char a[24], b[24], c[24];
    double mm = 1000.0 / p->scale;
    fprintf(f,
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%gmm\" height=\"%gmm\" "
            "viewBox=\"0 0 %g %g\" data-scale=\"%d\" data-page=\"%s\">\n",
            p->page_w, p->page_h, p->page_w, p->page_h, p->scale, p->page);
    fprintf(f, "<title>Holonomy: where the props stand, room %d x %d cells of %s m, 1:%d</title>\n",
            p->cols, p->rows, props_m(p->cell_m, a), p->scale);
    fputs("<style>text{font-family:sans-serif;fill:#222}.small{font-size:2.6px}"
          ".body{font-size:3.4px}.big{font-size:6px;font-weight:bold}"
          ".dim{stroke:#222;stroke-width:0.25}.cell{stroke:#999;stroke-width:0.2;"
          "stroke-dasharray:1.5 1}.hedge{stroke:#2f7d3a;stroke-linecap:square}"
          ".tree-inner{fill:#8a5a2b;stroke:#3b2410;stroke-width:0.3}"
          ".tree-side,.tree-corner{fill:#b98b5e;stroke:#3b2410;stroke-width:0.3}"
          ".play-area{fill:none;stroke:#1f5fbf;stroke-width:0.35;stroke-dasharray:3 1.5}"
          "</style>\n", f);
    fprintf(f, "<rect x=\"0\" y=\"0\" width=\"%g\" height=\"%g\" fill=\"#fff\"/>\n", p->page_w,
            p->page_h);
    double x = HOL_PROPS_MARGIN_MM, y = HOL_PROPS_MARGIN_MM + 6;
    fputs("<g id=\"head\">\n", f);
    fprintf(f, "<text class=\"big\" x=\"%.2f\" y=\"%.2f\">Holonomy: where the props stand", x, y);
    if (level_name && *level_name) {
        fputs(" (level ", f);
        props_xml_text(f, level_name);
        fputc(')', f);
    }
    fputs("</text>\n", f);
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">{4,%d}: room %d x %d cells of %s m = "
               "%s x %s m. Scale 1:%d, %s, millimetres. North up.</text>\n",
            x, y + 6, q, p->cols, p->rows, props_m(p->cell_m, a), props_m(p->room_w, b),
            props_m(p->room_d, c), p->scale, p->page);
    /* the scale bar: one metre, checked with a ruler on the print */
    double by = y + 14;
    fprintf(f, "<path class=\"dim\" id=\"scale-bar\" d=\"M%.2f %.2f v2 h%.2f v-2 M%.2f %.2f v2\" "
               "fill=\"none\" data-mm=\"%.2f\"/>\n",
            x, by - 2, mm, x + mm / 2, by - 1, mm);
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">1 m = %s mm at 1:%d: print at 100 %% "
               "(no fit to page) and measure this bar</text>\n",
            x + mm + 3, by, props_m(mm, a), p->scale);
    /* north arrow */
    double nx = p->page_w - HOL_PROPS_MARGIN_MM - 4, ny = HOL_PROPS_MARGIN_MM;
    fprintf(f, "<path class=\"dim\" d=\"M%.2f %.2f V%.2f M%.2f %.2f L%.2f %.2f L%.2f %.2f\" "
               "fill=\"none\"/><text class=\"body\" x=\"%.2f\" y=\"%.2f\">N</text>\n",
            nx, ny + 16, ny + 4, nx - 2, ny + 7, nx, ny + 4, nx + 2, ny + 7, nx - 1.2, ny + 2);
    fputs("</g>\n", f);
}

static void props_floor(FILE *f, const hol_props *p)
{
    double x0 = hol_props_px(p, 0), y0 = hol_props_py(p, 0);
    double x1 = hol_props_px(p, p->room_w), y1 = hol_props_py(p, p->room_d);
    fputs("<g id=\"floor\">\n", f);
    fprintf(f, "<rect class=\"floor\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
               "fill=\"#f4f1e6\"/>\n",
            x0, y0, x1 - x0, y1 - y0);
    for (int i = 1; i < p->cols; i++) {
        double x = hol_props_px(p, i * p->cell_m);
        fprintf(f, "<line class=\"cell\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", x,
                y0, x, y1);
    }
    for (int j = 1; j < p->rows; j++) {
        double y = hol_props_py(p, j * p->cell_m);
        fprintf(f, "<line class=\"cell\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", x0,
                y, x1, y);
    }
    for (int j = 0; j < p->rows; j++)
        for (int i = 0; i < p->cols; i++)
            fprintf(f, "<text class=\"small\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" "
                       "fill=\"#888\">cell %d,%d</text>\n",
                    hol_props_px(p, (i + 0.5) * p->cell_m), hol_props_py(p, (j + 0.5) * p->cell_m),
                    i, j);
    fputs("</g>\n", f);
}

static void props_things(FILE *f, const hol_props *p)
{
    char a[24], b[24], c[24], e[24];
    double mm = 1000.0 / p->scale;
    fprintf(f, "<g id=\"hedges\" stroke-width=\"%.2f\">\n", 0.1 * mm);
    for (int k = 0; k < p->nhedges; k++) {
        const hol_props_hedge *h = &p->hedges[k];
        fprintf(f, "<line class=\"hedge\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                   "data-m=\"%s,%s,%s,%s\"/>\n",
                hol_props_px(p, h->x0), hol_props_py(p, h->z0), hol_props_px(p, h->x1),
                hol_props_py(p, h->z1), props_m(h->x0, a), props_m(h->z0, b), props_m(h->x1, c),
                props_m(h->z1, e));
    }
    fputs("</g>\n<g id=\"trees\">\n", f);
    static const char *const kinds[] = {"tree-inner", "tree-side", "tree-corner"};
    for (int k = 0; k < p->ntrees; k++) {
        const hol_props_tree *t = &p->trees[k];
        double cx = hol_props_px(p, t->x), cy = hol_props_py(p, t->z);
        fprintf(f, "<circle class=\"%s\" cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" data-m=\"%s,%s\"/>\n",
                kinds[t->kind], cx, cy, HOL_PROPS_TRUNK_M * mm, props_m(t->x, a),
                props_m(t->z, b));
        if (t->kind == HOL_PROPS_INNER)
            fprintf(f, "<text class=\"small\" x=\"%.2f\" y=\"%.2f\">%s, %s</text>\n",
                    cx + HOL_PROPS_TRUNK_M * mm + 0.8, cy - HOL_PROPS_TRUNK_M * mm - 0.5,
                    props_m(t->x, a), props_m(t->z, b));
    }
    fputs("</g>\n", f);
}

/* Dimension lines: the room's width above it (a tick on every cell edge),
 * its depth at its left. */
static void props_dims(FILE *f, const hol_props *p)
{
    char a[24], b[24];
    double x0 = hol_props_px(p, 0), y0 = hol_props_py(p, 0);
    double x1 = hol_props_px(p, p->room_w), y1 = hol_props_py(p, p->room_d);
    double top = fmin(y0, hol_props_py(p, p->area_z0)) - 7;
    double left = fmin(x0, hol_props_px(p, p->area_x0)) - 7;
    fputs("<g id=\"dims\">\n", f);
    fprintf(f, "<line class=\"dim\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", x0, top,
            x1, top);
    for (int i = 0; i <= p->cols; i++) {
        double x = hol_props_px(p, i * p->cell_m);
        fprintf(f, "<line class=\"dim\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", x,
                top - 1.5, x, top + 1.5);
        if (i < p->cols)
            fprintf(f, "<text class=\"small\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%s m"
                       "</text>\n",
                    x + p->cell_m * 500.0 / p->scale, top + 3.5, props_m(p->cell_m, a));
    }
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\">%s m (%d x %s m)"
               "</text>\n",
            (x0 + x1) / 2, top - 2.5, props_m(p->room_w, a), p->cols, props_m(p->cell_m, b));
    fprintf(f, "<line class=\"dim\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", left, y0,
            left, y1);
    for (int j = 0; j <= p->rows; j++) {
        double y = hol_props_py(p, j * p->cell_m);
        fprintf(f, "<line class=\"dim\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                left - 1.5, y, left + 1.5, y);
    }
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\" text-anchor=\"middle\" "
               "transform=\"rotate(-90 %.2f %.2f)\">%s m (%d x %s m)</text>\n",
            left - 2, (y0 + y1) / 2, left - 2, (y0 + y1) / 2, props_m(p->room_d, a), p->rows,
            props_m(p->cell_m, b));
    fputs("</g>\n", f);
}

static void props_area(FILE *f, const hol_props *p)
{
    if (!p->has_area)
        return;
    char a[24], b[24];
    double x0 = hol_props_px(p, p->area_x0), y0 = hol_props_py(p, p->area_z0);
    double w = p->area_w * 1000.0 / p->scale, h = p->area_d * 1000.0 / p->scale;
    fprintf(f, "<rect class=\"play-area\" x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" "
               "data-m=\"%s,%s\"/>\n",
            x0, y0, w, h, props_m(p->area_w, a), props_m(p->area_d, b));
    fprintf(f, "<text class=\"small\" x=\"%.2f\" y=\"%.2f\" fill=\"#1f5fbf\">play area %s x %s m"
               "</text>\n",
            x0 + 1, y0 + h + 3.5, props_m(p->area_w, a), props_m(p->area_d, b));
}

/* The list under the plan: the inner trunks row by row, the rest. */
static void props_foot(FILE *f, const hol_props *p)
{
    char a[24], b[24];
    double x = HOL_PROPS_MARGIN_MM;
    double y = fmax(hol_props_py(p, p->room_d), hol_props_py(p, p->area_z0 + p->area_d)) + 10;
    fputs("<g id=\"foot\">\n", f);
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">Trees inside the room (trunk centres, "
               "metres from the north-west corner; x east, z south):</text>\n", x, y);
    for (int j = 1; j < p->rows; j++) {
        y += 4.5;
        fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">z = %s: x =", x + 4, y,
                props_m(j * p->cell_m, a));
        for (int i = 1; i < p->cols; i++)
            fprintf(f, "%s %s", i > 1 ? "," : "", props_m(i * p->cell_m, b));
        fputs("</text>\n", f);
    }
    static const char *const notes[] = {
        "Corner and side trees stand in the hedge line on every cell edge.",
        "Each virtual trunk is at most %s m across at its base: a post or a padded pole of that size.",
        "Hedges: %d pieces of %s m along the room's edges (drawn 0.1 m thick).",
        "Every tile maps onto this room: these props stand in for every hedge and trunk.",
    };
    y += 6;
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">%s</text>\n", x, y, notes[0]);
    fprintf(f, "<text class=\"body\" x=\"%.2f\" y=\"%.2f\">", x, y + 4.5);
    fprintf(f, notes[1], props_m(2 * HOL_PROPS_TRUNK_M, a));
    fprintf(f, "</text>\n<text class=\"body\" x=\"%.2f\" y=\"%.2f\">", x, y + 9);
    fprintf(f, notes[2], p->nhedges, props_m(p->cell_m, a));
    fprintf(f, "</text>\n<text class=\"body\" x=\"%.2f\" y=\"%.2f\">%s</text>\n", x, y + 13.5,
            notes[3]);
    fputs("</g>\n", f);
}

int props_write_svg(FILE *f, const hol_props *p, int q, const char *level_name,
                    const struct hol_props_desc *d)
{
    (void)d;
    props_head(f, p, q, level_name);
    props_floor(f, p);
    props_area(f, p);
    props_things(f, p);
    props_dims(f, p);
    props_foot(f, p);
    fputs("</svg>\n", f);
    return ferror(f) ? -1 : 0;
}
