/* hol_shell_prov.c - provenance.csv, order.csv and codebook.csv
 * (hol_shell_prov.h). */
#include "hol_shell_prov.h"

#include <stdio.h>
#include <string.h>

#include "../../core/hol_sha256.h"
#include "../../core/hol_text.h"
#include "hol_shell_build.h"
#include "hol_shell_codebook.h"

int hol_shell_prov_field(char *out, size_t cap, const char *s, int first)
{
    char esc[1024], q[2100];
    size_t at = strlen(out);
    if (hol_text_escape(s, strlen(s), esc, sizeof esc) >= sizeof esc ||
        hol_text_csv(esc, strlen(esc), q, sizeof q) >= sizeof q)
        return 1;
    int n = snprintf(out + at, cap - at, "%s%s", first ? "" : ",", q);
    if (n < 0 || (size_t)n >= cap - at) {
        out[at] = 0;
        return 1;
    }
    return 0;
}

int hol_shell_order_rows(const hol_study *study, const char *participant, const int *lv,
                         const hol_level *levels, int n, char *out, size_t cap)
{
    size_t at = 0;
    out[0] = 0;
    for (int i = 0; i < n; i++) {
        char row[2048] = "", pos[16], rel[HOL_STUDY_PATH_MAX];
        int c = hol_study_level_condition(study, lv[i]);
        snprintf(pos, sizeof pos, "%d", c < 0 ? 0 : levels[i].position);
        hol_study_level_path(study, lv[i], rel);
        int w = hol_shell_prov_field(row, sizeof row, participant, 1) ||
                        hol_shell_prov_field(row, sizeof row, study->name, 0) ||
                        hol_shell_prov_field(row, sizeof row, pos, 0) ||
                        hol_shell_prov_field(row, sizeof row,
                                             c < 0 ? HOL_STUDY_PRACTICE : study->conditions[c].name,
                                             0) ||
                        hol_shell_prov_field(row, sizeof row, levels[i].name, 0) ||
                        hol_shell_prov_field(row, sizeof row, rel, 0)
                    ? -1
                    : snprintf(out + at, cap - at, "%s\n", row);
        if (w < 0 || (size_t)w >= cap - at) {
            out[0] = 0;
            return 1;
        }
        at += (size_t)w;
    }
    return 0;
}

int hol_shell_order_hash(const char *rows, const hol_level *levels, int n, char *out, size_t cap)
{
    size_t at = 0;
    out[0] = 0;
    for (int i = 0; i < n && *rows; i++) {
        const char *nl = strchr(rows, '\n');
        char hex[HOL_SHA256_HEX];
        if (!nl)
            break;
        hol_sha256_hex(levels[i].sha256, hex);
        int w = snprintf(out + at, cap - at, "%.*s,%s\n", (int)(nl - rows), rows, hex);
        if (w < 0 || (size_t)w >= cap - at) {
            out[0] = 0;
            return 1;
        }
        at += (size_t)w;
        rows = nl + 1;
    }
    return 0;
}

/* Appends text to NAME (its header first when NAME is new or empty). */
static int prov_append(const hol_sink *k, const char *name, const char *header, const char *text)
{
    char one;
    size_t got = 0;
    hol_err e = k->read(k->user, name, 0, &one, 1, &got);
    int fresh = e == HOL_EOPEN || (e == HOL_OK && got == 0);
    if (e != HOL_OK && e != HOL_EOPEN)
        return 1;
    int h;
    if (k->open(k->user, name, 1, &h))
        return 1;
    int bad = (fresh && (k->write(k->user, h, header, strlen(header)) ||
                         k->write(k->user, h, "\n", 1))) ||
              k->write(k->user, h, text, strlen(text)) || k->flush(k->user, h, 1);
    return k->close(k->user, h) || bad;
}

/* codebook.csv whole: written as codebook.csv.new, then renamed. */
static int prov_codebook(const hol_sink *k)
{
    static char text[HOL_SHELL_CODEBOOK_TEXT_MAX]; /* constant bytes: the same for every caller */
    size_t n = hol_shell_codebook_csv(text, sizeof text);
    int h;
    if (!n || k->open(k->user, "codebook.csv.new", 0, &h))
        return 1;
    int bad = k->write(k->user, h, text, n) || k->flush(k->user, h, 1);
    bad = k->close(k->user, h) || bad;
    return bad || k->rename(k->user, "codebook.csv.new", "codebook.csv");
}

/* order.csv: the rows, each prefixed with the session. */
static int prov_order(const hol_sink *k, const char *session, const char *order)
{
    static char text[64 * 1024 + 64 * 66 + 64 * 64];
    size_t at = 0;
    text[0] = 0;
    for (const char *r = order ? order : ""; *r;) {
        const char *nl = strchr(r, '\n');
        size_t len = nl ? (size_t)(nl - r) + 1 : strlen(r);
        int w = snprintf(text + at, sizeof text - at, "%s,%.*s", session, (int)len, r);
        if (w < 0 || (size_t)w >= sizeof text - at)
            return 1;
        at += (size_t)w;
        r += len;
    }
    return text[0] ? prov_append(k, "order.csv", HOL_SHELL_ORDER_COLUMNS, text) : 0;
}

const char *hol_shell_prov_write(const hol_sink *log, const hol_rec_meta *meta, const char *order)
{
    if (!log)
        return NULL;
    char row[1024] = "";
    int bad = hol_shell_prov_field(row, sizeof row, meta->session, 1) ||
              hol_shell_prov_field(row, sizeof row, meta->participant, 0) ||
              hol_shell_prov_field(row, sizeof row, hol_shell_build_version(), 0) ||
              hol_shell_prov_field(row, sizeof row, hol_shell_build_commit(), 0) ||
              hol_shell_prov_field(row, sizeof row, hol_shell_build_date(), 0) ||
              strlen(row) + 2 > sizeof row;
    if (!bad) {
        strcat(row, "\n");
        bad = prov_append(log, "provenance.csv", HOL_SHELL_PROV_COLUMNS, row);
    }
    return bad                                   ? "provenance.csv"
           : prov_order(log, meta->session, order) ? "order.csv"
           : prov_codebook(log)                    ? "codebook.csv"
                                                   : NULL;
}
