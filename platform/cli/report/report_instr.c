/* report_instr.c - points.csv's and answers.csv's values checked against
 * their documented ranges (report_instr.h). */
#include "report_instr.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../../core/hol_ask.h"
#include "../../../core/hol_report.h"

int report_instr_whole(const char *s, long lo, long hi, long *out)
{
    const char *d = s + (*s == '-');
    size_t n = strspn(d, "0123456789");
    if (!n || n > 18 || d[n])
        return 0;
    long v = strtol(s, NULL, 10);
    if (v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

/* [-]D[.D]: 1 and *out; 0 for anything else (no exponent, no inf, nan or
 * hex: what the logs write, "%.1f"). */
static int decimal(const char *s, double *out)
{
    const char *d = s + (*s == '-');
    size_t n = strspn(d, "0123456789");
    if (!n)
        return 0;
    if (d[n] == '.') {
        size_t f = strspn(d + n + 1, "0123456789");
        if (!f)
            return 0;
        n += 1 + f;
    }
    if (d[n])
        return 0;
    *out = strtod(s, NULL);
    return 1;
}

int report_instr_point(const char *err_true, const char *err_flat, const char *const bear[3],
                       int has[2], double e[2], char *err)
{
    static const char *const ename[2] = {"error_true", "error_flat"};
    static const char *const bname[3] = {"pointed", "true", "flat"};
    for (int k = 0; k < 2; k++) {
        const char *s = k ? err_flat : err_true;
        has[k] = *s != 0;
        if (has[k] && (!decimal(s, &e[k]) || !(e[k] > -180 && e[k] <= 180))) {
            snprintf(err, HOL_REPORT_ERR, "column %s: '%.40s' is not a number in (-180, 180]",
                     ename[k], s);
            return -1;
        }
    }
    for (int k = 0; k < 3; k++) {
        double b;
        if (bear[k] && *bear[k] && (!decimal(bear[k], &b) || !(b >= 0 && b < 360))) {
            snprintf(err, HOL_REPORT_ERR, "column %s: '%.40s' is not a bearing in [0, 360)",
                     bname[k], bear[k]);
            return -1;
        }
    }
    return 0;
}

/* A likert value on its scale: a preset's marks, else 0..100. */
static int likert_value(const hol_ask_preset_def *p, const char *q, const char *value,
                        double *out_v, char *err)
{
    long v;
    if (!p) {
        if (report_instr_whole(value, 0, 100, &v)) {
            *out_v = (double)v;
            return 0;
        }
        snprintf(err, HOL_REPORT_ERR, "column value: '%.40s' is not a whole number in 0..100",
                 value);
        return -1;
    }
    if (report_instr_whole(value, p->lo, p->hi, &v) && (v - p->lo) % p->step == 0) {
        *out_v = (double)v;
        return 0;
    }
    if (p->step == 1)
        snprintf(err, HOL_REPORT_ERR, "column value: '%.40s' is not one of %s's marks %d..%d",
                 value, q, p->lo, p->hi);
    else
        snprintf(err, HOL_REPORT_ERR,
                 "column value: '%.40s' is not one of %s's marks %d..%d in steps of %d", value, q,
                 p->lo, p->hi, p->step);
    return -1;
}

int report_instr_answer(const char *q, const char *when, const char *item, const char *kind,
                        const char *value, double *out_v, char *err)
{
    int likert = !strcmp(kind, "likert");
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index(q, strlen(q)));
    *out_v = 0;
    if (!hol_ask_id_ok(q, strlen(q)))
        snprintf(err, HOL_REPORT_ERR, "column questionnaire: '%.40s' is not a name", q);
    else if (hol_ask_when(when, strlen(when)) < 0)
        snprintf(err, HOL_REPORT_ERR, "column when: '%.40s' is not level, condition, study, "
                 "before_level, before_condition or before_study",
                 when);
    else if (!hol_ask_id_ok(item, strlen(item)))
        snprintf(err, HOL_REPORT_ERR, "column item: '%.40s' is not an item's ID", item);
    else if (!likert && strcmp(kind, "choice"))
        snprintf(err, HOL_REPORT_ERR, "column kind: '%.40s' is not likert or choice", kind);
    else if (p && hol_ask_preset_item(p, item) < 0)
        snprintf(err, HOL_REPORT_ERR, "column item: '%.40s' is not one of %s's %d items", item,
                 q, p->nitems);
    else if (p && !likert)
        snprintf(err, HOL_REPORT_ERR, "column kind: %s's items are likert", q);
    else
        return likert ? likert_value(p, q, value, out_v, err) : 0;
    return -1;
}

int report_instr_item_new(report_instr_items *s, const char *q, const char *item, char *err)
{
    for (int i = 0; i < s->n; i++)
        if (!strcmp(s->id[i], item)) {
            snprintf(err, HOL_REPORT_ERR, "item '%.40s' answered twice in one %.40s", item, q);
            return -1;
        }
    if (s->n == REPORT_INSTR_ITEMS) {
        snprintf(err, HOL_REPORT_ERR, "more than %d items in one %.40s", REPORT_INSTR_ITEMS, q);
        return -1;
    }
    snprintf(s->id[s->n++], sizeof s->id[0], "%s", item);
    return 0;
}
