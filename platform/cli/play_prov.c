/* play_prov.c - provenance.csv, order.csv and codebook.csv (play_prov.h). */
#include "play_prov.h"

#include <stdio.h>
#include <string.h>

#include "../../core/hol_sha256.h"
#include "../../core/hol_text.h"
#include "build_info.h"
#include "cli.h"
#include "codebook.h"

static char held_rows[64 * 1024], held_order[64 * 1024 + 64 * 66];
static const hol_level *held_levels;
static char held_fail[300]; /* play_prov_write's failure, said at the end */
static int held_n;

void play_prov_hold_order(const char *rows, const hol_level *levels, int n)
{
    snprintf(held_rows, sizeof held_rows, "%s", rows ? rows : "");
    held_order[0] = 0;
    held_levels = levels;
    held_n = n;
}

void play_prov_order_hash(const hol_level *levels, int n)
{
    if (!levels || levels != held_levels || n != held_n)
        return;
    size_t at = 0;
    const char *r = held_rows;
    for (int i = 0; i < n && *r; i++) {
        const char *nl = strchr(r, '\n');
        char hex[65];
        if (!nl)
            break;
        hol_sha256_hex(levels[i].sha256, hex);
        int w = snprintf(held_order + at, sizeof held_order - at, "%.*s,%s\n", (int)(nl - r), r,
                         hex);
        if (w < 0 || (size_t)w >= sizeof held_order - at) {
            held_order[0] = 0;
            return;
        }
        at += (size_t)w;
        r = nl + 1;
    }
    held_levels = NULL;
}

int play_prov_field(char *out, size_t cap, const char *s, int first)
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
    static char text[CODEBOOK_TEXT_MAX];
    size_t n = codebook_csv(CODEBOOK_LOGS, text, sizeof text);
    int h;
    if (!n || k->open(k->user, "codebook.csv.new", 0, &h))
        return 1;
    int bad = k->write(k->user, h, text, n) || k->flush(k->user, h, 1);
    bad = k->close(k->user, h) || bad;
    return bad || k->rename(k->user, "codebook.csv.new", "codebook.csv");
}

/* order.csv: the held rows, each prefixed with the session. */
static int prov_order(const hol_sink *k, const char *session)
{
    static char text[sizeof held_order + 64 * 64];
    size_t at = 0;
    text[0] = 0;
    for (const char *r = held_order; *r && at < sizeof text;) {
        const char *nl = strchr(r, '\n');
        size_t len = nl ? (size_t)(nl - r) + 1 : strlen(r);
        int w = snprintf(text + at, sizeof text - at, "%s,%.*s", session, (int)len, r);
        if (w < 0 || (size_t)w >= sizeof text - at)
            return 1;
        at += (size_t)w;
        r += len;
    }
    held_order[0] = 0;
    return text[0] ? prov_append(k, "order.csv", PLAY_ORDER_COLUMNS, text) : 0;
}

int play_prov_write(const hol_sink *log, const hol_rec_meta *meta)
{
    if (!log)
        return 0;
    char row[1024] = "";
    int bad = play_prov_field(row, sizeof row, meta->session, 1) ||
              play_prov_field(row, sizeof row, meta->participant, 0) ||
              play_prov_field(row, sizeof row, build_version(), 0) ||
              play_prov_field(row, sizeof row, build_commit(), 0) ||
              play_prov_field(row, sizeof row, build_date(), 0) ||
              strlen(row) + 2 > sizeof row;
    if (!bad) {
        strcat(row, "\n");
        bad = prov_append(log, "provenance.csv", PLAY_PROV_COLUMNS, row);
    }
    const char *what = bad                             ? "provenance.csv"
                       : prov_order(log, meta->session) ? "order.csv"
                       : prov_codebook(log)             ? "codebook.csv"
                                                        : NULL;
    held_fail[0] = 0;
    if (what) {
        const char *why = log->why ? log->why(log->user) : NULL;
        snprintf(held_fail, sizeof held_fail, "cannot write the log folder's %s%s%s", what,
                 why && why[0] ? ": " : "", why ? why : "");
    }
    return what != NULL;
}

int play_prov_failed(const char *cmd)
{
    if (!held_fail[0])
        return 0;
    cli_error_end(cmd, "%s", held_fail);
    held_fail[0] = 0;
    return 1;
}
