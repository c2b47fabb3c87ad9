/* report_class.c - `holonomy report --class DIR --out OUT`: a class's
 * results (issue 37; docs/teaching.md "A class's results") from the pupils'
 * answer files in DIR: each a file NAME.csv with answers.csv's header (with
 * or without the answer timestamps' two columns; the
 * web page's download), or a folder NAME holding answers.csv (a pupil's log
 * folder on the desktop). The pre-test's and post-test's items
 * (core/hol_quiz.h, questionnaires pretest and posttest) are judged by the
 * core's key, and so are the lessons' predictions (questionnaire predict,
 * item lessonN: core/hol_lesson.h) in the tiling their attempt played
 * (summary.csv beside answers.csv; {4,5} without it, one stderr line); a
 * pupil is the answers' participant (the file's NAME when empty), an item
 * answered twice counts its last answer.
 * Writes OUT/class_items.csv (per item: answered, right, rate),
 * class_pupils.csv (per pupil: pre and post score, the share of the four
 * items right, and the gain), class_gain.csv (the pupils with both tests:
 * means, SDs, the mean gain with its 95 % CI from Student's t, d_z and
 * Hedges' g_av beside Wu et al. 2020's 0.24 and Coban et al. 2022's g =
 * 0.38) and class_wrong.csv (each wrong answer given, how often, its share
 * of the item's answers), and one line on stdout. tests/class_referee.R
 * recomputes every figure (tests/cli_class.sh). */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../../../core/hol_lesson.h"
#include "../../../core/hol_quiz.h"
#include "../../../core/hol_stats.h"
#include "../../../core/hol_str.h"
#include "../cli.h"
#include "report.h"
#include "report_escape.h"

#define RC_PUPILS 2000
#define RC_ITEMS 64
#define RC_WRONG 1024
#define RC_TEXT 96
#define RC_FIELDS 11 /* with the answer timestamps (shown_ms, answered_ms); 9 before */
#define RC_PHASES 3 /* pretest, posttest, predict (the lessons) */
#define RC_K 6      /* items of a phase: HOL_QUIZ_ITEMS, HOL_LESSONS */
#define RC_TILINGS 256 /* a pupil's attempts whose tiling is known */

typedef struct rc_pupil {
    char id[RC_TEXT];
    /* per phase (pretest, posttest, the lessons' predictions) and item
     * (a test's concept, a lesson's number - 1) */
    signed char got[RC_PHASES][RC_K];  /* -1 unanswered, 0 wrong, 1 right */
    short item[RC_PHASES][RC_K];       /* the answer's item (rc_class.items) */
    char val[RC_PHASES][RC_K][RC_TEXT]; /* the answer given last */
} rc_pupil;

typedef struct rc_item {
    int phase, concept;
    char id[RC_TEXT], right[RC_TEXT];
    long answered, nright;
} rc_item;

typedef struct rc_wrong {
    int item;
    char value[RC_TEXT];
    long count;
} rc_wrong;

/* The tilings of a pupil's attempts (summary.csv beside answers.csv). */
typedef struct rc_tilings {
    char session[RC_TILINGS][RC_TEXT];
    long attempt[RC_TILINGS];
    int q[RC_TILINGS];
    int n;
} rc_tilings;

typedef struct rc_class {
    rc_pupil pupils[RC_PUPILS];
    int npupils;
    rc_item items[RC_ITEMS];
    int nitems;
    rc_wrong wrong[RC_WRONG];
    int nwrong;
    long rows;
    rc_tilings tl; /* the pupil's being read */
} rc_class;

static const char *const rc_header = "session,participant,attempt,questionnaire,when,item,kind,"
                                     "value,time";
static const char *const rc_header_ms = ",shown_ms,answered_ms"; /* the timestamps' */

/* One CSV line (RFC 4180: quoted fields, "" a quote) into fields of buf. */
static int rc_split(const char *s, char (*out)[RC_TEXT], int max)
{
    int n = 0;
    while (n < max) {
        size_t k = 0;
        if (*s == '"') {
            for (s++; *s && !(*s == '"' && s[1] != '"'); s++) {
                if (*s == '"')
                    s++;
                if (k + 1 < RC_TEXT)
                    out[n][k++] = *s;
            }
            if (*s == '"')
                s++;
        } else {
            for (; *s && *s != ',' && *s != '\n' && *s != '\r'; s++)
                if (k + 1 < RC_TEXT)
                    out[n][k++] = *s;
        }
        out[n++][k] = 0;
        if (*s != ',')
            break;
        s++;
    }
    return n;
}

static const char *rc_phase_name(int ph)
{
    return ph < 2 ? hol_quiz_name(ph) : "predict";
}

static rc_pupil *rc_pupil_of(rc_class *c, const char *id)
{
    for (int i = 0; i < c->npupils; i++)
        if (!strcmp(c->pupils[i].id, id))
            return &c->pupils[i];
    if (c->npupils == RC_PUPILS)
        return NULL;
    rc_pupil *p = &c->pupils[c->npupils++];
    snprintf(p->id, sizeof p->id, "%s", id);
    memset(p->got, -1, sizeof p->got);
    return p;
}

static int rc_item_of(rc_class *c, int phase, int concept, const char *id, const char *right)
{
    for (int i = 0; i < c->nitems; i++)
        if (c->items[i].phase == phase && !strcmp(c->items[i].id, id))
            return i;
    if (c->nitems == RC_ITEMS)
        return -1;
    rc_item *it = &c->items[c->nitems];
    memset(it, 0, sizeof *it);
    it->phase = phase, it->concept = concept;
    snprintf(it->id, sizeof it->id, "%s", id);
    snprintf(it->right, sizeof it->right, "%s", right);
    return c->nitems++;
}

static void rc_wrong_add(rc_class *c, int item, const char *value)
{
    for (int i = 0; i < c->nwrong; i++)
        if (c->wrong[i].item == item && !strcmp(c->wrong[i].value, value)) {
            c->wrong[i].count++;
            return;
        }
    if (c->nwrong == RC_WRONG)
        return;
    rc_wrong *w = &c->wrong[c->nwrong++];
    w->item = item, w->count = 1;
    size_t n = strnlen(value, sizeof w->value - 1); /* (value may be a pupil's row) */
    memcpy(w->value, value, n);
    w->value[n] = 0;
}

static void rc_read_tilings(const char *path, rc_tilings *t)
{
    t->n = 0;
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    char line[4096], fld[32][RC_TEXT];
    int cs = -1, ca = -1, ct = -1;
    for (long ln = 1; fgets(line, sizeof line, f) && t->n < RC_TILINGS; ln++) {
        int n = rc_split(line, fld, 32);
        for (int k = 0; ln == 1 && k < n; k++) {
            cs = strcmp(fld[k], "session") ? cs : k;
            ca = strcmp(fld[k], "attempt") ? ca : k;
            ct = strcmp(fld[k], "tiling") ? ct : k;
        }
        if (ln == 1 || cs < 0 || ca < 0 || ct < 0 || n <= ct || n <= ca || n <= cs)
            continue;
        if (strncmp(fld[ct], "4,", 2) || fld[ct][2] < '4' || fld[ct][2] > '8' || fld[ct][3])
            continue;
        snprintf(t->session[t->n], RC_TEXT, "%s", fld[cs]);
        t->attempt[t->n] = atol(fld[ca]);
        t->q[t->n++] = fld[ct][2] - '0';
    }
    fclose(f);
}

/* A lesson's prediction (questionnaire predict, item lessonN): its key in
 * the tiling its attempt played (summary.csv), {4,5} when unknown. The
 * item's id becomes lessonN_qQ; -1 when it is no lesson's. */
static int rc_lesson_key(const rc_tilings *t, char (*fld)[RC_TEXT], int *unknown,
                         char *id, char *right, size_t cap)
{
    const char *it = fld[5];
    if (strcmp(fld[3], "predict") || strncmp(it, "lesson", 6) || it[6] < '1' ||
        it[6] > '0' + HOL_LESSONS || it[7])
        return -1;
    int n = it[6] - '0', q = 0;
    for (int i = 0; i < t->n && !q; i++)
        if (!strcmp(t->session[i], fld[0]) && t->attempt[i] == atol(fld[2]))
            q = t->q[i];
    *unknown += !q;
    q = q ? q : 5;
    hol_lesson_facts f;
    if (hol_lesson_facts_of(n, q, &f))
        return -1;
    const char *label = f.choice ? hol_lesson_label(&f, HOL_LANG_EN, f.answer) : NULL;
    if (f.choice)
        snprintf(right, cap, "%s", label ? label : "");
    else
        snprintf(right, cap, "%d", f.answer);
    snprintf(id, RC_TEXT, "lesson%d_q%d", n, q);
    return n - 1;
}

/* One answers file of the pupil named `name` when its rows name none;
 * summary: its summary.csv (the lessons' tilings), or NULL. */
static int rc_read(const char *cmd, rc_class *c, const char *path, const char *name,
                   const char *summary)
{
    rc_tilings *tl = &c->tl;
    tl->n = 0;
    if (summary)
        rc_read_tilings(summary, tl);
    FILE *f = fopen(path, "r");
    if (!f) {
        cli_error(cmd, 0, "cannot read '%.300s': %s", path, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    char line[2048], fld[RC_FIELDS][RC_TEXT], right[RC_TEXT], id[RC_TEXT];
    long ln = 0;
    int st = 0, unknown = 0, nf = RC_FIELDS - 2;
    size_t hl = strlen(rc_header);
    while (!st && fgets(line, sizeof line, f)) {
        ln++;
        line[strcspn(line, "\r\n")] = 0;
        if (ln == 1) {
            if (!strncmp(line, rc_header, hl) && !strcmp(line + hl, rc_header_ms))
                nf = RC_FIELDS;
            else if (strcmp(line, rc_header)) {
                cli_error(cmd, 0, "'%.300s' is not an answers file (its header is not '%s')",
                          path, rc_header);
                st = CLI_EXIT_USAGE;
            }
            continue;
        }
        if (rc_split(line, fld, RC_FIELDS) != nf) {
            cli_error(cmd, ln, "'%.300s': not %d fields", path, nf);
            st = CLI_EXIT_USAGE;
            break;
        }
        int phase = !strcmp(fld[3], "pretest") ? 0 : !strcmp(fld[3], "posttest") ? 1 : 2;
        snprintf(id, sizeof id, "%s", fld[5]);
        int k = phase < 2 ? hol_quiz_key(fld[3], fld[5], right, sizeof right)
                          : rc_lesson_key(tl, fld, &unknown, id, right, sizeof right);
        if (k < 0)
            continue; /* a questionnaire's answer */
        rc_pupil *p = rc_pupil_of(c, fld[1][0] ? fld[1] : name);
        int it = rc_item_of(c, phase, k, id, right);
        if (!p || it < 0) {
            cli_error(cmd, 0, "more than %d pupils or %d items", RC_PUPILS, RC_ITEMS);
            st = CLI_EXIT_USAGE;
            break;
        }
        p->got[phase][k] = (signed char)!strcmp(fld[7], right);
        p->item[phase][k] = (short)it;
        snprintf(p->val[phase][k], RC_TEXT, "%s", fld[7]);
        c->rows++;
    }
    fclose(f);
    if (!st && unknown)
        fprintf(stderr, "report: %.300s: %d lesson answer(s) of attempts without a known "
                        "tiling (no summary.csv beside it) judged in {4,5}\n", path, unknown);
    return st;
}

/* The items' counts and the wrong answers, from each pupil's last answers. */
static void rc_tally(rc_class *c)
{
    for (int i = 0; i < c->npupils; i++)
        for (int ph = 0; ph < RC_PHASES; ph++)
            for (int k = 0; k < RC_K; k++) {
                const rc_pupil *p = &c->pupils[i];
                if (p->got[ph][k] < 0)
                    continue;
                rc_item *it = &c->items[p->item[ph][k]];
                it->answered++;
                it->nright += p->got[ph][k];
                if (!p->got[ph][k])
                    rc_wrong_add(c, p->item[ph][k], p->val[ph][k]);
            }
}

/* A pupil's score of a phase: the share of its four items right; -1 when
 * the pupil answered none of them. */
static double rc_score(const rc_pupil *p, int ph)
{
    int any = 0, right = 0;
    for (int k = 0; k < HOL_QUIZ_ITEMS; k++) {
        any |= p->got[ph][k] >= 0;
        right += p->got[ph][k] > 0;
    }
    return any ? (double)right / HOL_QUIZ_ITEMS : -1;
}

typedef struct rc_gain {
    long n;
    double pre, pre_sd, post, post_sd, gain, gain_sd, lo, hi, dz, gav;
    int has_sd;
} rc_gain;

static double rc_mean(const double *x, long n)
{
    double s = 0;
    for (long i = 0; i < n; i++)
        s += x[i];
    return s / (double)n;
}

static double rc_sd(const double *x, long n, double m)
{
    double s = 0;
    for (long i = 0; i < n; i++)
        s += (x[i] - m) * (x[i] - m);
    return sqrt(s / (double)(n - 1));
}

/* The pupils with both tests: the means, SDs, the gain's 95 % CI (t),
 * d_z = gain / SD(gain) and g_av = J * gain / ((SD pre + SD post) / 2),
 * J = 1 - 3 / (4 (n - 1) - 1) (Lakens 2013). */
static void rc_gain_of(const rc_class *c, rc_gain *g, double *pre, double *post, double *d)
{
    memset(g, 0, sizeof *g);
    for (int i = 0; i < c->npupils; i++) {
        double a = rc_score(&c->pupils[i], 0), b = rc_score(&c->pupils[i], 1);
        if (a < 0 || b < 0)
            continue;
        pre[g->n] = a, post[g->n] = b, d[g->n] = b - a;
        g->n++;
    }
    if (g->n < 1)
        return;
    g->pre = rc_mean(pre, g->n), g->post = rc_mean(post, g->n), g->gain = rc_mean(d, g->n);
    if (g->n < 2)
        return;
    g->has_sd = 1;
    g->pre_sd = rc_sd(pre, g->n, g->pre), g->post_sd = rc_sd(post, g->n, g->post);
    g->gain_sd = rc_sd(d, g->n, g->gain);
    double h = hol_stats_t975(g->n - 1) * g->gain_sd / sqrt((double)g->n);
    g->lo = g->gain - h, g->hi = g->gain + h;
    double j = 1 - 3.0 / (4.0 * (double)(g->n - 1) - 1);
    double sav = (g->pre_sd + g->post_sd) / 2;
    g->dz = g->gain_sd > 0 ? g->gain / g->gain_sd : NAN;
    g->gav = sav > 0 && g->n > 1 ? j * g->gain / sav : NAN;
}

typedef struct rc_out {
    rc_class *c;
    rc_gain g;
    const double *pre, *post;
} rc_out;

static void rc_num(FILE *f, double v, int last)
{
    if (isfinite(v))
        fprintf(f, "%.10f", v);
    fputc(last ? '\n' : ',', f);
}

static int rc_items_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)r;
    const rc_class *c = ((const rc_out *)ctx)->c;
    fputs("phase,item,concept,right_answer,answered,right,rate\n", f);
    for (int ph = 0; ph < RC_PHASES; ph++)
        for (int i = 0; i < c->nitems; i++) {
            const rc_item *it = &c->items[i];
            if (it->phase != ph)
                continue;
            fprintf(f, "%s,", rc_phase_name(ph));
            report_csv(f, it->id, 0);
            if (ph < 2)
                fprintf(f, "%s,", hol_quiz_concept(it->concept));
            else
                fprintf(f, "lesson %d,", it->concept + 1);
            report_csv(f, it->right, 0);
            fprintf(f, "%ld,%ld,", it->answered, it->nright);
            rc_num(f, it->answered ? (double)it->nright / (double)it->answered : NAN, 1);
        }
    return 0;
}

static int rc_pupils_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)r;
    const rc_class *c = ((const rc_out *)ctx)->c;
    fputs("pupil,pre,post,gain\n", f);
    for (int i = 0; i < c->npupils; i++) {
        double a = rc_score(&c->pupils[i], 0), b = rc_score(&c->pupils[i], 1);
        report_csv(f, c->pupils[i].id, 0);
        rc_num(f, a < 0 ? NAN : a, 0);
        rc_num(f, b < 0 ? NAN : b, 0);
        rc_num(f, a < 0 || b < 0 ? NAN : b - a, 1);
    }
    return 0;
}

#define RC_WU_2020 0.24
#define RC_COBAN_2022 0.38

static int rc_gain_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)r;
    const rc_gain *g = &((const rc_out *)ctx)->g;
    fputs("pupils,pre_mean,pre_sd,post_mean,post_sd,gain_mean,gain_sd,gain_ci_low,"
          "gain_ci_high,d_z,g_av,wu2020_d,coban2022_g\n", f);
    fprintf(f, "%ld,", g->n);
    double v[10] = {g->pre, g->pre_sd, g->post, g->post_sd, g->gain, g->gain_sd,
                    g->lo, g->hi, g->dz, g->gav};
    for (int i = 0; i < 10; i++)
        rc_num(f, (g->n < 1 || (!g->has_sd && i != 0 && i != 2 && i != 4)) ? NAN : v[i], 0);
    fprintf(f, "%.2f,%.2f\n", RC_WU_2020, RC_COBAN_2022);
    return 0;
}

static int rc_wrong_cmp(const void *a, const void *b)
{
    const rc_wrong *x = a, *y = b;
    if (x->item != y->item)
        return x->item - y->item;
    if (x->count != y->count)
        return x->count > y->count ? -1 : 1;
    return strcmp(x->value, y->value);
}

static int rc_wrong_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)r;
    const rc_class *c = ((const rc_out *)ctx)->c;
    fputs("phase,item,answer,count,share\n", f);
    for (int i = 0; i < c->nwrong; i++) {
        const rc_wrong *w = &c->wrong[i];
        const rc_item *it = &c->items[w->item];
        fprintf(f, "%s,", rc_phase_name(it->phase));
        report_csv(f, it->id, 0);
        report_csv(f, w->value, 0);
        fprintf(f, "%ld,", w->count);
        rc_num(f, (double)w->count / (double)it->answered, 1);
    }
    return 0;
}

/* Every pupil's file in dir, in the order of their names. */
static int rc_read_dir(const char *cmd, rc_class *c, const char *dir)
{
    struct dirent **names = NULL;
    int n = scandir(dir, &names, NULL, alphasort);
    if (n < 0) {
        cli_error(cmd, 0, "cannot read the folder '%.300s': %s", dir, strerror(errno));
        return CLI_EXIT_USAGE;
    }
    int st = 0;
    for (int i = 0; i < n; i++) {
        char path[4200], name[RC_TEXT];
        const char *e = names[i]->d_name;
        size_t len = strlen(e);
        struct stat sb;
        snprintf(path, sizeof path, "%s/%s", dir, e);
        if (!st && e[0] != '.' && !stat(path, &sb)) {
            snprintf(name, sizeof name, "%.*s", (int)(len > 4 ? len - 4 : len), e);
            if (S_ISREG(sb.st_mode) && len > 4 && !strcmp(e + len - 4, ".csv")) {
                st = rc_read(cmd, c, path, name, NULL);
            } else if (S_ISDIR(sb.st_mode)) {
                char sum[4200];
                snprintf(path, sizeof path, "%s/%s/answers.csv", dir, e);
                snprintf(sum, sizeof sum, "%s/%s/summary.csv", dir, e);
                snprintf(name, sizeof name, "%.*s", (int)(sizeof name - 1), e);
                if (!stat(path, &sb))
                    st = rc_read(cmd, c, path, name, sum);
            }
        }
        free(names[i]);
    }
    free(names);
    return st;
}

static int rc_write(const char *cmd, const char *out, rc_class *c)
{
    static double pre[RC_PUPILS], post[RC_PUPILS], d[RC_PUPILS];
    rc_out o = {c, {0}, pre, post};
    rc_tally(c);
    qsort(c->wrong, (size_t)c->nwrong, sizeof c->wrong[0], rc_wrong_cmp);
    rc_gain_of(c, &o.g, pre, post, d);
    report_run r;
    memset(&r, 0, sizeof r);
    r.cmd = cmd;
    r.out = out;
    if (mkdir(out, 0777) && errno != EEXIST) {
        cli_error(cmd, 0, "--out '%.300s' cannot be made: %s", out, strerror(errno));
        return CLI_EXIT_FAIL;
    }
    int st = report_write_in(&r, out, "class_items.csv", rc_items_csv, &o);
    if (!st)
        st = report_write_in(&r, out, "class_pupils.csv", rc_pupils_csv, &o);
    if (!st)
        st = report_write_in(&r, out, "class_gain.csv", rc_gain_csv, &o);
    if (!st)
        st = report_write_in(&r, out, "class_wrong.csv", rc_wrong_csv, &o);
    if (st)
        return st;
    const rc_gain *g = &o.g;
    printf("report --class: %d pupils, %ld with both tests", c->npupils, g->n);
    if (g->has_sd)
        printf("; gain %.3f (95 %% CI %.3f to %.3f), d_z %.2f, g_av %.2f (Wu et al. 2020: %.2f; "
               "Coban et al. 2022: g = %.2f)", g->gain, g->lo, g->hi, g->dz, g->gav, RC_WU_2020,
               RC_COBAN_2022);
    printf("\n");
    return cli_finish_output(cmd);
}

int report_class_main(const char *cmd, int argc, char **argv)
{
    const char *dir = NULL, *out = NULL;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--out") && i + 1 < argc)
            out = argv[++i];
        else if (!dir && argv[i][0] != '-')
            dir = argv[i];
        else {
            cli_error(cmd, 0, "--class: unexpected '%.100s'; usage: holonomy report --class "
                              "DIR --out OUT", argv[i]);
            return CLI_EXIT_USAGE;
        }
    }
    if (!dir || !out || !out[0]) {
        cli_error(cmd, 0, "--class DIR --out OUT: give the pupils' folder and --out");
        return CLI_EXIT_USAGE;
    }
    rc_class *c = calloc(1, sizeof *c);
    if (!c) {
        cli_error(cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    int st = rc_read_dir(cmd, c, dir);
    if (!st && !c->rows) {
        cli_error(cmd, 0, "'%.300s' holds no pre-test, post-test or lesson answers", dir);
        st = CLI_EXIT_USAGE;
    }
    if (!st)
        st = rc_write(cmd, out, c);
    free(c);
    return st;
}
