/* report_pstats_fmt.c - the pieces the report's statistics writers share
 * (report_pstats_impl.h, report_stats_impl.h): a condition's name, a
 * summary's cells and d_z. Below the CSV, effects and page writers, which
 * all call down into it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report_escape.h"
#include "report_pstats_impl.h"
#include "report_stats_impl.h"

void rs_cond_name(FILE *f, const rs_cond *c)
{
    if (c->study[0]) {
        report_html(f, c->study);
        fputs(" / ", f);
    }
    report_html(f, c->condition);
}

void ps_summary(FILE *f, const hol_stats *st, double k, int with_sd, int last)
{
    double sd = st->n > 1 ? sqrt(st->m2 / (double)(st->n - 1)) : 0;
    double h = st->n > 1 ? report_t975(st->n - 1) * k * sd / sqrt((double)st->n) : 0;
    double v[4] = {st->mean, sd, st->mean - h, st->mean + h};
    int have[4] = {st->n > 0, st->n > 1, st->n > 1, st->n > 1};
    for (int i = 0; i < 4; i++) {
        if (i == 1 && !with_sd)
            continue;
        if (have[i])
            fprintf(f, "%.15g", v[i] == 0 ? 0 : v[i]);
        fputc(i == 3 && last ? '\n' : ',', f);
    }
}

int ps_dz(const hol_stats *d, double *out)
{
    double sd = d->n < 2 ? 0 : sqrt(d->m2 / (double)(d->n - 1));
    if (sd <= 0 || sd <= 1e-9 * fabs(d->mean)) /* equal differences but for rounding */
        return 0;
    *out = d->mean / sd;
    return 1;
}

void ps_diff_cells(FILE *f, const hol_stats *d)
{
    double z;
    fprintf(f, "%ld,", d->n);
    ps_summary(f, d, 1, 1, 0);
    if (ps_dz(d, &z))
        fprintf(f, "%.15g", z);
    fputc('\n', f);
}

/* The condition factors' names and a trial's level of each (report_pstats_impl.h;
 * the effects', the pairs' and the questionnaires' writers read them). */
const char *const ps_factor[PS_NF] = {"q", "room", "cell", "cues", "minimap"};

void ps_factor_text(const report_att *t, int k, char *out, size_t cap)
{
    static const char *const place[] = {"hud", "hand", "off"};
    const hol_report_attempt *a = &t->a;
    out[0] = 0;
    if (k == 0)
        snprintf(out, cap, "%d", a->tiling_q);
    else if (k == 1)
        snprintf(out, cap, "%dx%d", a->room_cols, a->room_rows);
    else if (k == 2)
        snprintf(out, cap, "%g", a->cell_m);
    else if (k == 3 && a->cues >= 0)
        snprintf(out, cap, "%ld", a->cues);
    else if (k == 4 && t->minimap >= 0 && t->minimap <= 2)
        snprintf(out, cap, "%s", place[t->minimap]);
}

/* The factor columns of trials.csv in which conditions ca and cb differ
 * (their first included trials'), space-separated, then end (',' in the
 * CSV, "" on the page). */
void ps_differ(FILE *f, const report_run *r, int ca, int cb, const char *end)
{
    const int ia = r->pstats->first[ca], ib = r->pstats->first[cb];
    const report_att *x = &r->att[ia < 0 ? 0 : ia], *y = &r->att[ib < 0 ? 0 : ib];
    const int d[PS_NF] = {x->a.tiling_q != y->a.tiling_q,
                      x->a.room_cols != y->a.room_cols || x->a.room_rows != y->a.room_rows,
                      x->a.cell_m != y->a.cell_m, x->a.cues != y->a.cues,
                      x->minimap != y->minimap};
    const char *sep = "";
    for (int k = 0; ia >= 0 && ib >= 0 && k < PS_NF; k++)
        if (d[k]) {
            fprintf(f, "%s%s", sep, ps_factor[k]);
            sep = " ";
        }
    fputs(end, f);
}
