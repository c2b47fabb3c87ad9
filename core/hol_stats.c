/* hol_stats.c - see hol_stats.h. */
#include "hol_stats.h"

#include "hol_ask.h"

#include <math.h>
#include <string.h>

void hol_stats_init(hol_stats *s)
{
    s->n = 0;
    s->mean = 0;
    s->m2 = 0;
}

void hol_stats_add(hol_stats *s, double x)
{
    s->n++;
    double d = x - s->mean;
    s->mean += d / (double)s->n;
    s->m2 += d * (x - s->mean);
}

/* t(0.975, df) for df 1..30. */
static const double t975[31] = {
    0,           12.706204736, 4.302652730, 3.182446305, 2.776445105, 2.570581836,
    2.446911851, 2.364624252,  2.306004135, 2.262157163, 2.228138852, 2.200985160,
    2.178812830, 2.160368656,  2.144786688, 2.131449546, 2.119905299, 2.109815578,
    2.100922040, 2.093024054,  2.085963447, 2.079613845, 2.073873068, 2.068657610,
    2.063898562, 2.059538553,  2.055529439, 2.051830516, 2.048407142, 2.045229642,
    2.042272456};

double hol_stats_t975(long df)
{
    if (df < 1)
        return 0;
    if (df <= 30)
        return t975[df];
    /* Cornish-Fisher: t = z + g1/v + g2/v^2 + g3/v^3 + g4/v^4 */
    const double z = 1.959963984540054, v = (double)df;
    double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
    double g1 = (z3 + z) / 4;
    double g2 = (5 * z5 + 16 * z3 + 3 * z) / 96;
    double g3 = (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / 384;
    double g4 = (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / 92160;
    return z + g1 / v + g2 / (v * v) + g3 / (v * v * v) + g4 / (v * v * v * v);
}

void hol_stats_summarize(const hol_stats *s, hol_stats_summary *out)
{
    memset(out, 0, sizeof *out);
    out->n = s->n;
    if (s->n < 1)
        return;
    out->has_mean = 1;
    out->mean = s->mean;
    if (s->n < 2)
        return;
    out->has_sd = 1;
    out->sd = sqrt(s->m2 > 0 ? s->m2 / (double)(s->n - 1) : 0);
    double h = hol_stats_t975(s->n - 1) * out->sd / sqrt((double)s->n);
    out->lo = s->mean - h;
    out->hi = s->mean + h;
}

/* The SSQ's items and scores are the questionnaire presets' table's row
 * "ssq" (hol_ask.h): its scores total, nausea, oculomotor, disorientation. */
static const hol_ask_preset_def *hol__ssq(void)
{
    return hol_ask_preset_at(hol_ask_preset_index("ssq", 3));
}

int hol_stats_ssq_index(const char *id)
{
    return hol_ask_preset_item(hol__ssq(), id);
}

void hol_stats_ssq(const double v[HOL_STATS_SSQ_NITEMS], hol_stats_ssq_score *out)
{
    double sc[HOL_ASK_PRESET_SCORES];
    hol_ask_score(hol__ssq(), v, sc);
    out->total = sc[0];
    out->nausea = sc[1];
    out->oculomotor = sc[2];
    out->disorientation = sc[3];
}
