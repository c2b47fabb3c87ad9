/* report_stats_html.c - the page's statistics section (report_stats.h):
 * the means table with SD, 95 % CI and n, the learning curves and the
 * steps-against-optimum plot as inline SVG, the per-participant table. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "report_escape.h"
#include "report_pstats.h"
#include "report_stats_impl.h"

static const char *const palette[8] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                       "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};


static void stat_cells(FILE *f, const hol_stats *st)
{
    hol_stats_summary m;
    hol_stats_summarize(st, &m);
    fprintf(f, "<td class=\"n\">%ld</td><td class=\"n\">%.3f</td>", m.n, m.mean);
    if (m.has_sd)
        fprintf(f, "<td class=\"n\">%.3f</td><td class=\"n\">[%.3f, %.3f]</td></tr>\n", m.sd,
                m.lo, m.hi);
    else
        fputs("<td></td><td></td></tr>\n", f);
}

static void means_table(FILE *f, const report_run *r)
{
    const report_stats *s = r->stats;
    fputs("<h2>Statistics</h2>\n<p>Per condition, over <b>completed</b> attempts only "
          "(practice left out): mean, sample SD, the 95 % confidence interval of the mean "
          "(Student's t, n &minus; 1 degrees of freedom) and n. Pointing errors: |pointed "
          "&minus; true| and |pointed &minus; flat| in degrees (points.csv); SSQ scores with "
          "Kennedy's weights and raw TLX (mean of the six, 0..100) per complete questionnaire; "
          "other Likert items: every answer (answers.csv; the SSQ's and TLX's items one by one "
          "in stats.csv). Data: <a href=\"stats.csv\">stats.csv</a>, "
          "<a href=\"learning.csv\">learning.csv</a>, "
          "<a href=\"participants.csv\">participants.csv</a>.</p>\n<table>\n<tr><th>condition"
          "</th><th>measure</th><th>n</th><th>mean</th><th>SD</th><th>95 % CI</th></tr>\n", f);
    for (int c = 0; c < s->ncond; c++) {
        for (int m = 0; m < RS_NFIX; m++) {
            if (!s->fix[c * RS_NFIX + m].n)
                continue;
            fputs("<tr><td>", f);
            rs_cond_name(f, &s->cond[c]);
            fprintf(f, "</td><td>%s</td>", rs_measure[m]);
            stat_cells(f, &s->fix[c * RS_NFIX + m]);
        }
        for (int i = 0; i < s->nlik; i++) {
            if (s->lik[i].cond != c || !strcmp(s->lik[i].q, "ssq") ||
                !strcmp(s->lik[i].q, "tlx"))
                continue; /* their scores stand above; each item in stats.csv */
            fputs("<tr><td>", f);
            rs_cond_name(f, &s->cond[c]);
            fputs("</td><td>likert ", f);
            report_html(f, s->lik[i].q);
            fputc('/', f);
            report_html(f, s->lik[i].item);
            fputs("</td>", f);
            stat_cells(f, &s->lik[i].s);
        }
    }
    fputs("</table>\n", f);
}

/* Conditions with a point in the plot (used[c]), in order; with n (not
 * NULL) each says its n: n[2c]..n[2c+1] (one number when equal). */
static int legend(FILE *f, const report_run *r, int x, int y, const int *used, const long *n)
{
    const report_stats *s = r->stats;
    int k = 0;
    for (int c = 0; c < s->ncond; c++) {
        if (!used[c])
            continue;
        fprintf(f, "<rect x=\"%d\" y=\"%d\" width=\"12\" height=\"12\" fill=\"%s\"/>"
                   "<text x=\"%d\" y=\"%d\">", x, y + 16 * k, palette[c % 8], x + 16, y + 16 * k + 11);
        rs_cond_name(f, &s->cond[c]);
        if (n && n[2 * c] == n[2 * c + 1])
            fprintf(f, " (n = %ld)", n[2 * c]);
        else if (n)
            fprintf(f, " (n = %ld&#8211;%ld)", n[2 * c], n[2 * c + 1]);
        fputs("</text>\n", f);
        k++;
    }
    return k;
}

#define PW 640
#define PH 360
#define PL 60 /* left margin */
#define PB 40 /* bottom margin */
#define PR 180 /* legend */

static void axes(FILE *f, const char *xl, const char *yl, double xmax, double ymax, int ticks)
{
    int w = PW - PL - PR, h = PH - PB - 20;
    fprintf(f, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#444\"/>"
               "<line x1=\"%d\" y1=\"20\" x2=\"%d\" y2=\"%d\" stroke=\"#444\"/>\n",
            PL, 20 + h, PL + w, 20 + h, PL, PL, 20 + h);
    for (int t = 0; t <= ticks; t++) {
        double fx = (double)t / ticks;
        fprintf(f, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%.3g</text>"
                   "<text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.3g</text>\n",
                PL + fx * w, 20 + h + 16, fx * xmax, PL - 6, 20 + h - fx * h + 4, fx * ymax);
    }
    fprintf(f, "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>"
               "<text x=\"14\" y=\"%d\" text-anchor=\"middle\" transform=\"rotate(-90 14 %d)\">"
               "%s</text>\n", PL + w / 2, PH - 4, xl, 20 + h / 2, 20 + h / 2, yl);
}

#define RS_YTOP 1.05 /* the learning plot's top (efficiency) */

/* One end of a CI bar at y: a cap, or (cut) an arrowhead pointing out of
 * the plot (dir -1 up, +1 down). */
static void bar_end(FILE *f, double x, double y, int cut, int dir, const char *col)
{
    if (cut)
        fprintf(f, "<polygon class=\"ci-cut\" points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" "
                   "fill=\"%s\"/>", x - 4, y - 7.0 * dir, x + 4, y - 7.0 * dir, x, y, col);
    else
        fprintf(f, "<line class=\"ci-cap\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                   "stroke=\"%s\"/>", x - 4, y, x + 4, y, col);
}

/* A point of a learning curve: its dot (a title with its numbers) and,
 * when it has a CI, its bar cut at 0 and RS_YTOP. */
static void learn_point(FILE *f, const rs_learn *l, double x, int h, const char *col)
{
    double y0 = 20 + h;
    fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"3\" fill=\"%s\"><title>position %ld: mean "
               "%.3f, n = %ld</title></circle>", x, y0 - l->m.mean * h, col, l->pos, l->m.mean,
            l->m.n);
    if (l->m.has_sd) {
        int cut_lo = l->m.lo < 0, cut_hi = l->m.hi > RS_YTOP;
        double lo = cut_lo ? 0 : l->m.lo, hi = cut_hi ? RS_YTOP : l->m.hi;
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\"/>", x,
                y0 - lo * h, x, y0 - hi * h, col);
        bar_end(f, x, y0 - hi * h, cut_hi, -1, col);
        bar_end(f, x, y0 - lo * h, cut_lo, 1, col);
    }
    fputc('\n', f);
}

static void learning_svg(FILE *f, const report_run *r, int *used, long *nrange)
{
    const report_stats *s = r->stats;
    long maxpos = 1;
    for (int i = 0; i < s->nlearn; i++)
        maxpos = s->learn[i].pos > maxpos ? s->learn[i].pos : maxpos;
    int w = PW - PL - PR, h = PH - PB - 20;
    fputs("<h3>Learning curves</h3>\n<p>Mean efficiency (optimum / steps) of completed "
          "attempts by position in the participant's order (outside a study: the attempt "
          "number), per condition; bars: 95 % CI, with a cap at each end; bars cut at the "
          "plot's edge (0 and 1.05) end in an arrow. n: completed attempts at a point "
          "(range per condition in the legend; each point's in its tooltip and in "
          "learning.csv); with n = 2 the interval is wide. Each condition's "
          "curve is drawn a little to the side of its position and narrower than the one "
          "before, so that equal curves stay visible.</p>\n", f);
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "font-family=\"sans-serif\" font-size=\"11\" role=\"img\" "
               "aria-label=\"learning curves\">\n", PW, PH);
    axes(f, "position", "efficiency", (double)maxpos, 1, 4);
    int ncurves = 0;
    for (int i = 0; i < s->nlearn; i++)
        ncurves += i == 0 || s->learn[i].cond != s->learn[i - 1].cond;
    for (int i = 0, g = 0; i < s->nlearn; g++) {
        int c = s->learn[i].cond, j = i;
        /* equal curves stay visible: each is drawn 3 px to the side of the
         * one before (dodged), and narrower (the first 6 px wide, the last 2) */
        double dx = (g - (ncurves - 1) / 2.0) * 3;
        double sw = ncurves > 1 ? 2 + 4.0 * (ncurves - 1 - g) / (ncurves - 1) : 2;
        used[c] = 1;
        fprintf(f, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"%.1f\" points=\"",
                palette[c % 8], sw);
        for (; j < s->nlearn && s->learn[j].cond == c; j++)
            fprintf(f, "%.1f,%.1f ", PL + (double)s->learn[j].pos / maxpos * w + dx,
                    20 + h - s->learn[j].m.mean * h);
        fputs("\"/>\n", f);
        for (; i < j; i++) {
            const rs_learn *l = &s->learn[i];
            long *n = &nrange[2 * c];
            n[0] = !n[1] || l->m.n < n[0] ? l->m.n : n[0];
            n[1] = l->m.n > n[1] ? l->m.n : n[1];
            learn_point(f, l, PL + (double)l->pos / maxpos * w + dx, h, palette[c % 8]);
        }
    }
    legend(f, r, PW - PR + 10, 24, used, nrange);
    fputs("</svg>\n", f);
}

static int by_point(const void *pa, const void *pb)
{
    const rs_pt *a = pa, *b = pb;
    return rs_first(rs_cmp(a->opt, b->opt), rs_cmp(a->steps, b->steps), rs_cmp(a->cond, b->cond));
}

#define RS_R1 4.0    /* the radius of a point of one attempt (px) */
#define RS_RMAX 18.0 /* the largest point's radius, at most */
#define RS_RMIN 1.5  /* the smallest drawn (with thousands in the largest) */

/* The plot's points, one per condition, optimum and steps, in pts (sorted
 * by optimum, steps, condition); their number. */
static int scatter_points(const report_run *r, rs_pt *pts, int *used, long *nrange)
{
    const report_stats *s = r->stats;
    int n = 0, m = 0;
    for (int i = 0; i < r->natt; i++) {
        const hol_report_attempt *a = &r->att[i].a;
        if (!rs_included(r, i) || a->optimum < 0)
            continue;
        int c = s->att_cond[i];
        used[c] = 1;
        nrange[2 * c] = ++nrange[2 * c + 1];
        pts[n++] = (rs_pt){a->optimum, a->steps, c, 1};
    }
    qsort(pts, (size_t)n, sizeof *pts, by_point);
    for (int i = 0; i < n; i++)
        if (m && !by_point(&pts[m - 1], &pts[i]))
            pts[m - 1].n++;
        else
            pts[m++] = pts[i];
    return m;
}

/* A point's radius: its area n times one attempt's (r1 chosen so that the
 * largest point stays within RS_RMAX). */
static double pt_radius(double r1, int n)
{
    double rad = r1 * sqrt((double)n);
    return rad < RS_RMIN ? RS_RMIN : rad;
}

/* The count of a point: inside its circle when it fits, else beside it. */
static void pt_count(FILE *f, double x, double y, double rad, int n)
{
    int digits = snprintf(NULL, 0, "%d", n);
    if (2 * rad >= 6.5 * digits + 2)
        fprintf(f, "<text class=\"count\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%d"
                   "</text>", x, y + 4, n);
    else
        fprintf(f, "<text class=\"count\" x=\"%.1f\" y=\"%.1f\">%d</text>", x + rad + 2, y + 4,
                n);
}

/* The points at one place (pts[0..k-1]: the same optimum and steps), side
 * by side in the conditions' order, centred on the place. */
static void place_points(FILE *f, const report_run *r, const rs_pt *pts, int k, double x,
                         double y, double r1)
{
    double width = 2.0 * (k - 1);
    for (int j = 0; j < k; j++)
        width += 2 * pt_radius(r1, pts[j].n);
    double at = x - width / 2;
    for (int j = 0; j < k; j++) {
        double rad = pt_radius(r1, pts[j].n);
        const char *col = palette[pts[j].cond % 8];
        fprintf(f, "<g class=\"pt\"><circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.2f\" fill=\"%s\" "
                   "fill-opacity=\"0.6\" stroke=\"%s\"><title>", at + rad, y, rad, col, col);
        rs_cond_name(f, &r->stats->cond[pts[j].cond]);
        fprintf(f, ": optimum %ld, steps %ld, %d attempt%s</title></circle>", pts[j].opt,
                pts[j].steps, pts[j].n, pts[j].n == 1 ? "" : "s");
        if (pts[j].n > 1)
            pt_count(f, at + rad, y, rad, pts[j].n);
        fputs("</g>\n", f);
        at += 2 * rad + 2;
    }
}

/* The legend's key to the points' size: one attempt and the most at a
 * point, from y down. */
static void size_key(FILE *f, int x, int y, double r1, int nmax)
{
    int keys[2] = {1, nmax};
    fprintf(f, "<text x=\"%d\" y=\"%d\">circle area: attempts</text>\n", x, y + 11);
    y += 16;
    for (int k = 0; k < (nmax > 1 ? 2 : 1); k++) {
        double rad = pt_radius(r1, keys[k]), big = pt_radius(r1, nmax);
        fprintf(f, "<g class=\"size-key\"><circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.2f\" "
                   "fill=\"#888\" fill-opacity=\"0.6\" stroke=\"#888\"/><text x=\"%.1f\" "
                   "y=\"%.1f\">%d attempt%s</text></g>\n", x + big, y + big, rad,
                x + 2 * big + 6, y + big + 4, keys[k], keys[k] == 1 ? "" : "s");
        y += (int)ceil(2 * big) + 4;
    }
}

static void scatter_svg(FILE *f, const report_run *r, int *used, long *nrange)
{
    const report_stats *s = r->stats;
    rs_pt *pts = s->pts;
    double maxv = 1;
    for (int i = 0; i < r->natt; i++)
        if (rs_included(r, i) && r->att[i].a.optimum >= 0) {
            double m = (double)(r->att[i].a.steps > r->att[i].a.optimum ? r->att[i].a.steps
                                                                         : r->att[i].a.optimum);
            maxv = m > maxv ? m : maxv;
        }
    int w = PW - PL - PR, h = PH - PB - 20;
    fputs("<h3>Steps against optimum</h3>\n<p>Each completed scored attempt (practice left "
          "out); on the grey line steps = optimum; n per condition in the legend. The "
          "attempts of a condition with the same optimum and steps are one circle, its area "
          "their number (written in it, or beside it when it does not fit; each circle's "
          "numbers in its tooltip); the conditions of one place side by side, in the "
          "legend's order.</p>\n", f);
    fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
               "font-family=\"sans-serif\" font-size=\"11\" role=\"img\" "
               "aria-label=\"steps against optimum\">\n", PW, PH);
    axes(f, "optimum (steps)", "steps", maxv, maxv, 4);
    fprintf(f, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"20\" stroke=\"#aaa\"/>\n", PL, 20 + h,
            PL + w);
    memset(used, 0, sizeof *used * (size_t)s->ncond);
    memset(nrange, 0, sizeof *nrange * 2 * (size_t)s->ncond);
    int npts = scatter_points(r, pts, used, nrange), nmax = 1;
    for (int i = 0; i < npts; i++)
        nmax = pts[i].n > nmax ? pts[i].n : nmax;
    double r1 = fmin(RS_R1, RS_RMAX / sqrt((double)nmax));
    for (int i = 0, j; i < npts; i = j) {
        for (j = i + 1; j < npts && pts[j].opt == pts[i].opt && pts[j].steps == pts[i].steps;)
            j++;
        place_points(f, r, pts + i, j - i, PL + (double)pts[i].opt / maxv * w,
                     20 + h - (double)pts[i].steps / maxv * h, r1);
    }
    int k = legend(f, r, PW - PR + 10, 24, used, nrange);
    if (npts)
        size_key(f, PW - PR + 10, 24 + 16 * k + 4, r1, nmax);
    fputs("</svg>\n", f);
}

static void participants_table(FILE *f, const report_run *r)
{
    const report_stats *s = r->stats;
    fputs("<h3>Participants</h3>\n<table>\n<tr><th>participant</th><th>condition</th>"
          "<th>attempts</th><th>done</th><th>mean steps</th><th>mean efficiency</th>"
          "<th>mean time (s)</th></tr>\n", f);
    for (int i = 0; i < s->nprow; i++) {
        const rs_prow *p = &s->prow[i];
        const hol_stats *m[3] = {&p->steps, &p->eff, &p->time};
        fputs("<tr><td>", f);
        report_html(f, r->att[p->att].a.participant);
        fputs("</td><td>", f);
        rs_cond_name(f, &s->cond[p->cond]);
        fprintf(f, "</td><td class=\"n\">%ld</td><td class=\"n\">%ld</td>", p->n, p->done);
        for (int k = 0; k < 3; k++)
            if (m[k]->n)
                fprintf(f, "<td class=\"n\">%.3f</td>", m[k]->mean);
            else
                fputs("<td></td>", f);
        fputs("</tr>\n", f);
    }
    fputs("</table>\n", f);
}

void report_stats_html(FILE *f, const report_run *r)
{
    const report_stats *s = r->stats;
    if (!s)
        return;
    memset(s->used, 0, sizeof *s->used * (size_t)s->ncond);
    memset(s->nrange, 0, sizeof *s->nrange * 2 * (size_t)s->ncond);
    means_table(f, r);
    learning_svg(f, r, s->used, s->nrange);
    scatter_svg(f, r, s->used, s->nrange);
    participants_table(f, r);
    report_pstats_html(f, r);
}
