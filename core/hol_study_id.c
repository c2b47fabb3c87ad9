/* hol_study_id.c - participants' ids (hol_study.h): the number a
 * counterbalancing order reads from an id, an id in its one spelling, and
 * whether a logged id names a participant. Pure; no state. */
#include "hol_study.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

uint64_t hol_study_participant_number(const char *id)
{
    size_t n = strlen(id), b = n;
    while (b > 0 && id[b - 1] >= '0' && id[b - 1] <= '9')
        b--;
    /* an id of digits, or one that begins with a letter: "-1", "1e3" and
     * "0x10" are not participants 1, 3 and 10 */
    if (b > 0 && !((id[0] >= 'A' && id[0] <= 'Z') || (id[0] >= 'a' && id[0] <= 'z')))
        return 0;
    uint64_t v = 0;
    for (size_t i = b; i < n; i++) {
        v = v * 10 + (uint64_t)(id[i] - '0');
        if (v > 1000000000u)
            return 0;
    }
    return v;
}

/* The digits of a participant number in id [b, e) after an optional 'P'
 * or 'p', leading zeros skipped: their start (*out_d, *out_n digits), 1;
 * 0 when [b, e) is not of that form. */
static int hol__id_number(const char *b, const char *e, const char **out_d, size_t *out_n)
{
    if (b < e && (*b == 'P' || *b == 'p'))
        b++;
    if (b == e)
        return 0;
    for (const char *c = b; c < e; c++)
        if (*c < '0' || *c > '9')
            return 0;
    while (e - b > 1 && *b == '0')
        b++;
    *out_d = b;
    *out_n = (size_t)(e - b);
    return 1;
}

int hol_study_participant_id(const char *id, char *out, size_t cap)
{
    char folded[HOL_REC_ID_MAX];
    size_t n = strlen(id), k = 0;
    const char *d;
    size_t nd;
    int form = hol__id_number(id, id + n, &d, &nd);
    for (size_t i = 0; !form && i < n && k + 1 < sizeof folded; i++)
        if (id[i] != '.' && id[i] != '_' && id[i] != '-')
            folded[k++] = id[i];
    int other = !form && n && k < sizeof folded - 1 && hol__id_number(folded, folded + k, &d, &nd);
    if (!form && !other) {
        if (out != id && cap)
            snprintf(out, cap, "%s", id);
        return HOL_STUDY_ID_SAME;
    }
    char buf[HOL_REC_ID_MAX + 4];
    int len = snprintf(buf, sizeof buf, "P%s%.*s", nd < 2 ? "0" : "", (int)(nd < 62 ? nd : 62), d);
    if (nd > 62 || (size_t)len + 1 > cap) {
        if (out != id && cap)
            snprintf(out, cap, "%s", id);
        return HOL_STUDY_ID_AMBIGUOUS;
    }
    int same = !strcmp(buf, id);
    memcpy(out, buf, (size_t)len + 1);
    return other ? HOL_STUDY_ID_AMBIGUOUS : same ? HOL_STUDY_ID_SAME : HOL_STUDY_ID_RENAMED;
}

int hol_study_participant_same(const char *logged, const char *id)
{
    char spelled[HOL_REC_ID_MAX];
    if (!strcmp(logged, id))
        return 1;
    return hol_study_participant_id(logged, spelled, sizeof spelled) == HOL_STUDY_ID_RENAMED &&
           !strcmp(spelled, id);
}
