/* report_effects.c - effects.csv (report_pstats.h, docs/report.md
 * "Participant-level statistics"): the main effects of a study's factors.
 * A factor is a factor column of trials.csv (q, room, cell, cues, minimap)
 * that takes two or more values over the study's conditions (each
 * condition's first included trial); a participant's value at a level is
 * the mean of their condition means over the conditions of that level,
 * for the participants with a mean in every condition (those of the
 * within-subjects interval); each pair of levels: the paired difference,
 * its 95 % CI and d_z. */
#include <stdio.h>
#include <string.h>

#include "report_escape.h"
#include "report_pstats_impl.h"

typedef struct ef_levels {
    int n;                             /* levels */
    int of[REPORT_PAIR_MAX];           /* per condition of the group: its level, -1 */
    char text[REPORT_PAIR_MAX][24];    /* per level */
    int cond[REPORT_PAIR_MAX];         /* per level: its first condition */
} ef_levels;

/* The levels of factor k over pg's conditions with measure m. */
static void levels(const report_run *r, const ps_pairs *pg, int m, int k, ef_levels *lv)
{
    const report_pstats *p = r->pstats;
    lv->n = 0;
    for (int c = 0; c < pg->n; c++) {
        int cond = pg->first + c, i = p->first[cond];
        char t[24];
        lv->of[c] = -1;
        if (i < 0 || !p->row[cond * PS_NM + m].between.n)
            continue;
        ps_factor_text(&r->att[i], k, t, sizeof t);
        int l = 0;
        while (l < lv->n && strcmp(lv->text[l], t))
            l++;
        if (l == lv->n) {
            memcpy(lv->text[l], t, sizeof t);
            lv->cond[l] = cond;
            lv->n++;
        }
        lv->of[c] = l;
    }
}

/* Each complete participant's level means; the pairs' differences into
 * d (lv->n x lv->n). */
static void differences(const report_pstats *p, const ps_pairs *pg, int m, int J,
                        const ef_levels *lv, hol_stats *d)
{
    int have;
    double sum;
    for (int i = 0, j; i < p->ncell; i = j) {
        double ls[REPORT_PAIR_MAX] = {0};
        int ln[REPORT_PAIR_MAX] = {0};
        j = ps_part_end(p, i, m, &have, &sum);
        if (p->cell[i].group != pg->group || have != J)
            continue;
        for (int l = i; l < j; l++) {
            int c = p->cell[l].cond - pg->first;
            if (p->cell[l].n[m] && c >= 0 && c < pg->n && lv->of[c] >= 0)
                ls[lv->of[c]] += p->cell[l].mean[m], ln[lv->of[c]]++;
        }
        for (int a = 0; a < lv->n; a++)
            for (int b = a + 1; b < lv->n; b++)
                if (ln[a] && ln[b])
                    hol_stats_add(&d[a * lv->n + b], ls[a] / ln[a] - ls[b] / ln[b]);
    }
}

static void effect_rows(FILE *f, const report_run *r, const ps_pairs *pg, int m, int k,
                        const ef_levels *lv, const hol_stats *d)
{
    for (int a = 0; a < lv->n; a++)
        for (int b = a + 1; b < lv->n; b++) {
            const hol_stats *s = &d[a * lv->n + b];
            if (!s->n)
                continue;
            report_csv(f, r->stats->cond[pg->first].study, 0);
            fprintf(f, "%s,%s,", ps_measure[m], ps_factor[k]);
            report_csv(f, lv->text[a], 0);
            report_csv(f, lv->text[b], 0);
            ps_diff_cells(f, s);
        }
}

static int effects_csv(FILE *f, const report_run *r, const void *ctx)
{
    const report_pstats *p = r->pstats;
    hol_stats d[REPORT_PAIR_MAX * REPORT_PAIR_MAX];
    ef_levels lv;
    (void)ctx;
    report_header(f, "effects.csv");
    for (int g = 0; g < p->npg; g++)
        for (int m = 0; m < PS_NM; m++) {
            const ps_pairs *pg = &p->pg[g];
            int J = ps_group_conds(p, pg->group, m, r->stats->ncond);
            for (int k = 0; J >= 2 && k < PS_NF; k++) {
                levels(r, pg, m, k, &lv);
                if (lv.n < 2)
                    continue;
                memset(d, 0, sizeof d);
                differences(p, pg, m, J, &lv, d);
                effect_rows(f, r, pg, m, k, &lv, d);
            }
        }
    return report_pstats_q_effects(f, r);
}

int report_effects_write(const report_run *r)
{
    return report_write_file(r, "effects.csv", effects_csv, NULL);
}
