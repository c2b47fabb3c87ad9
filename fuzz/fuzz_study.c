/* fuzz_study.c - libFuzzer harness for study files (core/hol_study.h).
 *
 * Input: a study file. Checks: it is refused with a line inside the file
 * (0: the whole file) and nothing kept, or parsed to 1..16 conditions with
 * valid, distinct names and 1..16 levels in all, each level in its
 * condition; every participant's order (the first rows and a far one) is a
 * permutation and their session holds every level once; each level made
 * from a fixed level file either succeeds, labelled with its condition and
 * position, or is refused naming a line of the file it blames; a made
 * level's screens and questions hold only what the text face draws
 * (printable ASCII and Latin-1 in UTF-8: hol_face_text_bad) and its
 * screens wrap within the HUD's lines. Parsing again gives the same study.
 */
#include <stdint.h>
#include <string.h>

#include "../core/hol_face.h"
#include "../core/hol_study.h"

#include "fuzz_check.h"

static hol_study s, again;
static hol_level L;

static long count_lines(const uint8_t *d, size_t n)
{
    long k = 1;
    for (size_t i = 0; i < n; i++)
        k += d[i] == '\n';
    return k;
}

static void check_levels(void)
{
    static const char file[] = "mode flag\nseed 3\nflag Nf\nminimap hand\n";
    for (int i = 0; i < s.nlevels; i++) {
        hol_level_err e;
        int in_study = -1, c = hol_study_level_condition(&s, i);
        CHECK(c >= -1 && c < s.nconditions && (c < 0) == (i < s.npractice));
        hol_err r = hol_study_make_level(&s, i, 3, file, sizeof file - 1, "lv", &L, &e, &in_study);
        if (r) {
            CHECK(e.code == r && (in_study == 0 || in_study == 1));
            CHECK(e.line >= 0 && (in_study || e.line <= 4));
            continue;
        }
        CHECK(!strcmp(L.condition, c < 0 ? HOL_STUDY_PRACTICE : s.conditions[c].name));
        CHECK(L.position == (c < 0 ? 0 : 3));
        const char *texts[2] = {L.lvl.instructions, L.lvl.closing};
        for (int k = 0; k < 2; k++) {
            CHECK(hol_face_text_bad(texts[k], strlen(texts[k]), NULL) == strlen(texts[k]));
            CHECK(hol_app_wrap(texts[k], HOL_APP_SCREEN_COLS, NULL, 0) <= HOL_APP_SCREEN_LINES);
        }
        for (int q = 0; q < L.lvl.nquestions; q++) {
            const hol_app_question *qn = &L.lvl.questions[q];
            CHECK(hol_face_text_bad(qn->text, strlen(qn->text), NULL) == strlen(qn->text));
            for (int j = 0; j < qn->nchoices; j++)
                CHECK(hol_face_text_bad(qn->choices[j], strlen(qn->choices[j]), NULL) ==
                      strlen(qn->choices[j]));
        }
    }
}

static void check_orders(void)
{
    uint64_t rows = hol_study_rows(s.rule, s.nconditions);
    CHECK(rows >= 1);
    uint64_t ps[6] = {1, 2, 3, rows, rows + 1, 1000000000};
    for (int k = 0; k < 6; k++) {
        int order[HOL_STUDY_MAX_CONDITIONS], seen[HOL_STUDY_MAX_CONDITIONS] = {0};
        CHECK(hol_study_order(&s, ps[k], order) == HOL_OK);
        for (int j = 0; j < s.nconditions; j++) {
            CHECK(order[j] >= 0 && order[j] < s.nconditions && !seen[order[j]]);
            seen[order[j]] = 1;
        }
        int lv[HOL_STUDY_MAX_LEVELS], cond[HOL_STUDY_MAX_LEVELS], pos[HOL_STUDY_MAX_LEVELS];
        int lseen[HOL_STUDY_MAX_LEVELS] = {0};
        CHECK(hol_study_session(&s, order, lv, cond, pos) == s.nlevels);
        for (int j = 0; j < s.nlevels; j++) {
            CHECK(!lseen[lv[j]]++ && hol_study_level_condition(&s, lv[j]) == cond[j]);
            CHECK(pos[j] == 0 || order[pos[j] - 1] == cond[j]);
        }
    }
}

static int same(const hol_study *a, const hol_study *b)
{
    int ok = !strcmp(a->name, b->name) && a->rule == b->rule && a->npractice == b->npractice &&
             a->nconditions == b->nconditions && a->nlevels == b->nlevels &&
             a->nglobal == b->nglobal && a->nsets == b->nsets;
    for (int i = 0; ok && i < a->nlevels; i++)
        ok = a->levels[i].off == b->levels[i].off && a->levels[i].len == b->levels[i].len &&
             a->levels[i].line == b->levels[i].line;
    for (int i = 0; ok && i < a->nsets; i++)
        ok = a->sets[i].off == b->sets[i].off && a->sets[i].len == b->sets[i].len;
    for (int c = 0; ok && c < a->nconditions; c++) {
        const hol_study_condition *x = &a->conditions[c], *y = &b->conditions[c];
        ok = !strcmp(x->name, y->name) && x->line == y->line && x->first_level == y->first_level &&
             x->nlevels == y->nlevels && x->first_set == y->first_set && x->nsets == y->nsets;
    }
    return ok;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    hol_level_err e;
    hol_err r = hol_study_parse((const char *)data, size, &s, &e);
    if (r) {
        CHECK(e.code == r && e.line >= 0 && e.line <= count_lines(data, size));
        CHECK(s.nconditions == 0 && s.nlevels == 0);
        return 0;
    }
    CHECK(s.nconditions >= 1 && s.nconditions <= HOL_STUDY_MAX_CONDITIONS);
    CHECK(s.nlevels >= s.nconditions && s.nlevels <= HOL_STUDY_MAX_LEVELS);
    CHECK(hol_rec_id_ok(s.name));
    for (int c = 0; c < s.nconditions; c++) {
        CHECK(hol_rec_id_ok(s.conditions[c].name) && s.conditions[c].nlevels >= 1);
        for (int d = 0; d < c; d++)
            CHECK(strcmp(s.conditions[c].name, s.conditions[d].name));
    }
    check_orders();
    check_levels();
    CHECK(hol_study_parse((const char *)data, size, &again, &e) == HOL_OK);
    CHECK(same(&s, &again));
    return 0;
}
