/* report_pstats_write.c - the participant-level statistics written
 * (report_pstats.h): trials.csv, participants_stats.csv, paired.csv and
 * the page's section. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../../core/hol_text.h"
#include "../cli.h"
#include "report_escape.h"
#include "report_pstats_impl.h"

static void trial_factors(FILE *f, const report_att *t)
{
    static const char *const place[] = {"hud", "hand", "off"};
    const hol_report_attempt *a = &t->a;
    fprintf(f, "\"4,%d\",%d,%dx%d,%g,", a->tiling_q, a->tiling_q, a->room_cols, a->room_rows,
            a->cell_m);
    if (a->cues >= 0)
        fprintf(f, "%ld", a->cues);
    fprintf(f, ",%s,", t->minimap >= 0 && t->minimap <= 2 ? place[t->minimap] : "");
}

static int trials_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_stats *s = r->stats;
    const report_pstats *p = r->pstats;
    (void)ctx;
    report_header(f, "trials.csv");
    for (int i = 0; i < r->natt; i++) {
        const report_att *t = &r->att[i];
        const hol_report_attempt *a = &t->a;
        const hol_stats *pt = &s->tpt[2 * i];
        double v;
        report_csv(f, a->participant, 0);
        report_csv(f, a->session, 0);
        if (a->session_no > 0)
            fprintf(f, "%ld", a->session_no);
        fprintf(f, ",%ld,", a->attempt);
        report_csv(f, a->study, 0);
        report_csv(f, s->cond[s->att_cond[i]].condition, 0);
        if (a->position >= 0)
            fprintf(f, "%ld", a->position);
        fprintf(f, ",%d,%d,", p->trial[i], s->cond[s->att_cond[i]].practice);
        report_csv(f, a->level, 0);
        report_csv(f, a->level_sha256, 0);
        report_csv(f, a->mode, 0);
        trial_factors(f, t);
        report_csv(f, a->end, 0);
        fprintf(f, "%ld,%ld,", a->steps, a->optimum);
        if (ps_value(r, i, PM_EFF, &v))
            fprintf(f, "%.15g", v);
        fprintf(f, ",%.15g,", a->time_s);
        for (int k = 0; k < 2; k++) {
            fprintf(f, "%ld,", pt[k].n);
            if (pt[k].n)
                fprintf(f, "%.15g", pt[k].mean);
            fputc(',', f);
        }
        report_csv(f, report_pstats_excluded(r, i), 0);
        char dir[1024];
        hol_text_escape(r->dirs[t->dir], strlen(r->dirs[t->dir]), dir, sizeof dir);
        report_csv(f, dir, 1);
    }
    return 0;
}


/* Each condition and measure of participants_stats.csv, in its order. */
typedef void (*row_fn)(FILE *f, const report_run *r, int c, int m, const ps_row *w);
static void each_row(FILE *f, const report_run *r, row_fn fn)
{
    const report_pstats *p = r->pstats;
    for (int c = 0; c < r->stats->ncond; c++)
        for (int m = 0; m < PS_NM; m++)
            if (p->group[c] >= 0 && p->row[c * PS_NM + m].between.n)
                fn(f, r, c, m, &p->row[c * PS_NM + m]);
}

/* Each pair of paired.csv (conditions ca before cb), in its order. */
typedef void (*pair_fn)(FILE *f, const report_run *r, int m, int ca, int cb, const hol_stats *d);
static void each_pair(FILE *f, const report_run *r, pair_fn fn)
{
    const report_pstats *p = r->pstats;
    for (int g = 0; g < p->npg; g++)
        for (int m = 0; m < PS_NM; m++)
            for (int a = 0; a < p->pg[g].n; a++)
                for (int b = a + 1; b < p->pg[g].n; b++) {
                    const ps_pairs *pg = &p->pg[g];
                    const hol_stats *d = &p->pair[pg->off + ((size_t)a * pg->n + b) * PS_NM + m];
                    if (d->n)
                        fn(f, r, m, pg->first + a, pg->first + b, d);
                }
}

static void stats_row(FILE *f, const report_run *r, int c, int m, const ps_row *w)
{
    report_csv(f, r->stats->cond[c].study, 0);
    report_csv(f, r->stats->cond[c].condition, 0);
    fprintf(f, "%s,%ld,%ld,", ps_measure[m], w->between.n, w->trials);
    ps_summary(f, &w->between, 1, 1, 0);
    fprintf(f, "%d,%ld,", w->J, w->within.n);
    ps_summary(f, &w->within, w->J >= 2 ? sqrt((double)w->J / (w->J - 1)) : 0, 0, 1);
}

static int participants_stats_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)ctx;
    report_header(f, "participants_stats.csv");
    each_row(f, r, stats_row);
    return report_pstats_q_rows(f, r);
}


static void pair_row(FILE *f, const report_run *r, int m, int ca, int cb, const hol_stats *d)
{
    report_csv(f, r->stats->cond[ca].study, 0);
    fprintf(f, "%s,", ps_measure[m]);
    report_csv(f, r->stats->cond[ca].condition, 0);
    report_csv(f, r->stats->cond[cb].condition, 0);
    ps_differ(f, r, ca, cb, ",");
    ps_diff_cells(f, d);
}

static int paired_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)ctx;
    report_header(f, "paired.csv");
    each_pair(f, r, pair_row);
    return report_pstats_q_pairs(f, r);
}

int report_pstats_write(const report_run *r)
{
    static const report_file_job jobs[] = {{"trials.csv", trials_csv},
                                           {"participants_stats.csv", participants_stats_csv},
                                           {"paired.csv", paired_csv}};
    int st = report_write_files(r, jobs, (int)(sizeof jobs / sizeof jobs[0]));
    return st ? st : report_effects_write(r);
}

/* ---- the page ---- */

/* The interval as a cell (its n after it when show_n). */
static void cell_interval(FILE *f, const hol_stats *st, double k, int show_n)
{
    if (st->n < 2) {
        fputs("<td></td>", f);
        return;
    }
    double h = report_t975(st->n - 1) * k * sqrt(st->m2 / (double)(st->n - 1)) /
               sqrt((double)st->n);
    fprintf(f, "<td class=\"n\">[%.3f, %.3f]", st->mean - h, st->mean + h);
    if (show_n)
        fprintf(f, " (%ld)", st->n);
    fputs("</td>", f);
}

static void html_row(FILE *f, const report_run *r, int c, int m, const ps_row *w)
{
    fputs("<tr><td>", f);
    rs_cond_name(f, &r->stats->cond[c]);
    fprintf(f, "</td><td>%s</td><td class=\"n\">%ld (%ld)</td><td class=\"n\">%.3f</td>",
            ps_measure[m], w->between.n, w->trials, w->between.mean);
    if (w->between.n >= 2)
        fprintf(f, "<td class=\"n\">%.3f</td>", sqrt(w->between.m2 / (double)(w->between.n - 1)));
    else
        fputs("<td></td>", f);
    cell_interval(f, &w->between, 1, 0);
    cell_interval(f, &w->within, w->J >= 2 ? sqrt((double)w->J / (w->J - 1)) : 0, 1);
    fputs("</tr>\n", f);
}

static void html_pair(FILE *f, const report_run *r, int m, int ca, int cb, const hol_stats *d)
{
    double z;
    fprintf(f, "<tr><td>%s</td><td>", ps_measure[m]);
    rs_cond_name(f, &r->stats->cond[ca]);
    fputs("</td><td>", f);
    rs_cond_name(f, &r->stats->cond[cb]);
    fputs("</td><td>", f);
    ps_differ(f, r, ca, cb, "");
    fprintf(f, "</td><td class=\"n\">%ld</td><td class=\"n\">%.3f</td>", d->n, d->mean);
    cell_interval(f, d, 1, 0);
    if (ps_dz(d, &z))
        fprintf(f, "<td class=\"n\">%.3f</td>", z);
    else
        fputs("<td></td>", f);
    fputs("</tr>\n", f);
}

void report_pstats_html(FILE *f, const report_run *r)
{
    if (!r->stats || !r->pstats)
        return;
    fputs("<h3>Participant-level statistics</h3>\n<p>Each participant's mean per condition "
          "(over their completed trials outside practice, ", f);
    fputs(r->include_restarted ? "duplicate and restarted runs counted (--include-restarted): "
                               : "duplicates and restarted runs: ", f);
    fputs("<a href=\"trials.csv\">trials.csv</a>'s <code>excluded</code>), then over the "
          "participants: n participants (trials), mean, SD. The <b>between-subjects</b> 95 % "
          "CI is Student's t on the participants' means; the <b>within-subjects</b> 95 % CI "
          "(Cousineau 2005 with Morey's 2008 correction sqrt(J/(J&minus;1)), J the study's "
          "conditions) is over the participants with a mean in every condition, and is the one "
          "to compare conditions by. Data: <a href=\"participants_stats.csv\">"
          "participants_stats.csv</a>, <a href=\"paired.csv\">paired.csv</a>.</p>\n<table>\n"
          "<tr><th>condition</th><th>measure</th><th>participants (trials)</th><th>mean</th>"
          "<th>SD</th><th>95 % CI between</th><th>95 % CI within (n)</th></tr>\n", f);
    each_row(f, r, html_row);
    fputs("</table>\n", f);
    if (!r->pstats->npg)
        return;
    fputs("<h3>Paired differences</h3>\n<p>For each pair of a study's conditions, A &minus; B "
          "over the participants with a mean in both: the factors in which A and B differ "
          "(one factor: a simple effect), n, the mean difference, its 95 % CI (Student's t) "
          "and Cohen's d<sub>z</sub> (the mean difference over the SD of the differences). "
          "The main effects (each pair of a factor's levels): <a href=\"effects.csv\">"
          "effects.csv</a>.</p>\n<table>\n<tr><th>measure</th><th>A</th><th>B</th><th>differ in</th><th>n</th>"
          "<th>A &minus; B</th><th>95 % CI</th><th>d<sub>z</sub></th></tr>\n", f);
    each_pair(f, r, html_pair);
    fputs("</table>\n", f);
}
