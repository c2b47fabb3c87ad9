/* report_ids.c - participant ids read in their one spelling (report.h,
 * docs/studies.md "Participant ids"): logs written before the rule may
 * name participant 2 "2", "002" or "p2"; each is read as "P02", and one
 * line on stderr names every id read so. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../../core/hol_study.h"
#include "../cli.h"
#include "report.h"

const char *report_id_logged(const report_att *t)
{
    return t->spelled[0] ? t->spelled : t->a.participant;
}

typedef struct id_key {
    const char *id, *logged;
    int i;
} id_key;

static int by_id(const void *pa, const void *pb)
{
    const id_key *a = pa, *b = pb;
    int c = strcmp(a->id, b->id);
    if (!c)
        c = strcmp(a->logged, b->logged);
    return c ? c : (a->i > b->i) - (a->i < b->i);
}

#define IDS_NAMED 6 /* spellings a line names, then "..." */

/* The spellings of one participant k[lo, hi) (sorted by spelling): one
 * line when they are two or more (a merge); a single other spelling is
 * added to the renames' line (renamed, its text so far). */
static void tell_one(const report_run *r, const id_key *k, int lo, int hi, long *renamed,
                     char *line, size_t cap)
{
    char names[512] = "";
    size_t n = 0;
    int distinct = 0, other = 0;
    for (int j = lo; j < hi; j++) {
        if (j > lo && !strcmp(k[j].logged, k[j - 1].logged))
            continue;
        other |= strcmp(k[j].logged, k[j].id) != 0;
        if (++distinct <= IDS_NAMED && n < sizeof names)
            n += (size_t)snprintf(names + n, sizeof names - n, "%s'%.70s'", distinct > 1 ? ", " : "",
                                  k[j].logged);
    }
    if (!other)
        return;
    if (distinct > 1) {
        fprintf(stderr, "holonomy %s: participant %s is spelled %s%s in the logs: read as one "
                        "participant, %s\n", r->cmd, k[lo].id, names,
                distinct > IDS_NAMED ? ", ..." : "", k[lo].id);
        return;
    }
    size_t l = strlen(line);
    if (++*renamed <= IDS_NAMED && l < cap)
        snprintf(line + l, cap - l, "%s%s as %s", *renamed > 1 ? ", " : "", names, k[lo].id);
}

int report_ids_tell(const report_run *r)
{
    id_key *k = malloc(sizeof *k * (size_t)(r->natt + 1));
    if (!k) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    int n = 0;
    for (int i = 0; i < r->natt; i++)
        k[n++] = (id_key){r->att[i].a.participant, report_id_logged(&r->att[i]), i};
    qsort(k, (size_t)n, sizeof *k, by_id);
    char line[1024] = "";
    long renamed = 0;
    for (int i = 0, j; i < n; i = j) {
        for (j = i + 1; j < n && !strcmp(k[j].id, k[i].id); j++)
            ;
        tell_one(r, k, i, j, &renamed, line, sizeof line);
    }
    if (renamed)
        fprintf(stderr, "holonomy %s: %ld participant id(s) read in their one spelling: %s%s\n",
                r->cmd, renamed, line, renamed > IDS_NAMED ? ", ..." : "");
    free(k);
    return 0;
}

void report_ids_read(report_run *r)
{
    for (int i = 0; i < r->natt; i++) {
        report_att *t = &r->att[i];
        char one[HOL_REC_ID_MAX];
        t->spelled[0] = 0;
        if (hol_study_participant_id(t->a.participant, one, sizeof one) != HOL_STUDY_ID_RENAMED)
            continue;
        snprintf(t->spelled, sizeof t->spelled, "%.63s", t->a.participant); /* renamed: <= 63 */
        snprintf(t->a.participant, sizeof t->a.participant, "%s", one);
    }
}
