/* report_write.c - the report's files (report.h): attempts.csv,
 * conditions.csv and index.html, each written atomically. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../../core/hol_text.h"
#include "../../shell/hol_shell_build.h"
#include "../cli.h"
#include "../codebook.h"
#include "report.h"
#include "report_escape.h"
#include "report_stats.h"

/* A path from the command line as it may stand in a CSV or on a page. */
static const char *safe_path(const char *p, char *buf, size_t cap)
{
    hol_text_escape(p, strlen(p), buf, cap);
    return buf;
}

static void num_or_empty(char *out, size_t cap, double v, const char *fmt)
{
    if (v < 0)
        out[0] = 0;
    else
        snprintf(out, cap, fmt, v);
}

static void geometry_text(const hol_report_attempt *a, char *tiling, char *room, char *cell)
{
    snprintf(tiling, 16, "4,%d", a->tiling_q);
    snprintf(room, 16, "%dx%d", a->room_cols, a->room_rows);
    snprintf(cell, 16, "%g", a->cell_m);
}

/* The factor columns after picture: q (numeric), cues (the summary's bits),
 * minimap (the level's place), the log folder from DIR. */
static void factor_columns(FILE *f, const report_run *r, int i, const char *rel)
{
    static const char *const place[] = {"hud", "hand", "off"};
    const report_att *t = &r->att[i];
    fprintf(f, "%d,", t->a.tiling_q);
    if (t->a.cues >= 0)
        fprintf(f, "%ld", t->a.cues);
    fprintf(f, ",%s,", t->minimap >= 0 && t->minimap <= 2 ? place[t->minimap] : "");
    report_csv(f, rel, 0);
    if (t->a.session_no > 0) /* the summary's session_no (empty: none) */
        fprintf(f, "%ld", t->a.session_no);
    fputc('\n', f);
}

static int attempts_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)ctx;
    char(*rels)[1024] = calloc((size_t)r->ndirs + 1, sizeof *rels);
    if (!rels) {
        cli_error(r->cmd, 0, "out of memory");
        return CLI_EXIT_FAIL;
    }
    for (int d = 0; d < r->ndirs; d++)
        report_rel_dir(r, d, rels[d], sizeof rels[d]);
    report_header(f, "attempts.csv");
    for (int i = 0; i < r->natt; i++) {
        const hol_report_attempt *t = &r->att[i].a;
        char pos[24], eff[24], tiling[16], room[16], cell[16], dir[1024];
        num_or_empty(pos, sizeof pos, (double)t->position, "%.0f");
        num_or_empty(eff, sizeof eff, hol_report_efficiency(t), "%.4f");
        geometry_text(t, tiling, room, cell);
        report_csv(f, t->participant, 0);
        report_csv(f, t->session, 0);
        fprintf(f, "%ld,", t->attempt);
        report_csv(f, t->study, 0);
        report_csv(f, t->condition, 0);
        fprintf(f, "%s,", pos);
        report_csv(f, t->level, 0);
        report_csv(f, t->mode, 0);
        fprintf(f, "%ld,%ld,%s,%.4f,", t->steps, t->optimum, eff, t->time_s);
        report_csv(f, t->end, 0);
        report_csv(f, tiling, 0);
        fprintf(f, "%s,%s,", room, cell);
        report_csv(f, safe_path(r->dirs[r->att[i].dir], dir, sizeof dir), 0);
        report_csv(f, r->att[i].png, 0);
        factor_columns(f, r, i, rels[r->att[i].dir]);
    }
    free(rels);
    return 0;
}

int report_write_csv(const report_run *r)
{
    return report_write_file(r, "attempts.csv", attempts_csv, NULL);
}

static int conditions_csv(FILE *f, const report_run *r, const void *ctx)
{
    const hol_report_agg *g = ctx;
    report_header(f, "conditions.csv");
    for (int i = 0; i < g->n; i++) {
        const hol_report_cond *c = &g->c[i];
        char eff[24];
        num_or_empty(eff, sizeof eff, c->neff ? c->eff / (double)c->neff : -1, "%.4f");
        report_csv(f, c->study, 0);
        report_csv(f, c->condition, 0);
        fprintf(f, "%ld,%ld,%.2f,%s,%.4f\n", c->n, c->done, c->steps / (double)c->n, eff,
                c->time_s / (double)c->n);
    }
    (void)r;
    return 0;
}

int report_write_conditions(const report_run *r, const hol_report_agg *g)
{
    return report_write_file(r, "conditions.csv", conditions_csv, g);
}

static void html_cell(FILE *f, const char *s)
{
    fputs("<td>", f);
    report_html(f, s);
    fputs("</td>", f);
}

static void html_head(FILE *f, const report_run *r, const hol_report_agg *g)
{
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<title>Holonomy report</title>\n<style>\n"
          "body{font-family:sans-serif;margin:1.5em;color:#222}\n"
          "table{border-collapse:collapse;margin-bottom:2em;font-size:.9em}\n"
          "td,th{border:1px solid #ccc;padding:.3em .5em;text-align:left;vertical-align:top}\n"
          "td.n{text-align:right}\ntr.killed,tr.aborted{background:#fde8e8}\n"
          ".walked{color:#dc5014}.optimal{color:#4a86d8}\n"
          "</style>\n</head>\n<body>\n<h1>Holonomy report</h1>\n<p>", f);
    fprintf(f, "%d attempts from %d log folder%s:", r->natt, r->ndirs, r->ndirs == 1 ? "" : "s");
    for (int d = 0; d < r->ndirs; d++) {
        char dir[1024];
        fputs(d ? ", <code>" : " <code>", f);
        report_html(f, safe_path(r->dirs[d], dir, sizeof dir));
        fputs("</code>", f);
    }
    fputs(". Data: <a href=\"attempts.csv\">attempts.csv</a> (one row per attempt), "
          "<a href=\"conditions.csv\">conditions.csv</a> (means per condition).</p>\n"
          "<h2>Conditions</h2>\n<table>\n<tr><th>study</th><th>condition</th><th>attempts</th>"
          "<th>done</th><th>mean steps</th><th>mean efficiency</th><th>mean time (s)</th></tr>\n",
          f);
    for (int i = 0; i < g->n; i++) {
        const hol_report_cond *c = &g->c[i];
        fputs("<tr>", f);
        html_cell(f, c->study);
        html_cell(f, c->condition);
        fprintf(f, "<td class=\"n\">%ld</td><td class=\"n\">%ld</td><td class=\"n\">%.2f</td>",
                c->n, c->done, c->steps / (double)c->n);
        if (c->neff)
            fprintf(f, "<td class=\"n\">%.4f</td>", c->eff / (double)c->neff);
        else
            fputs("<td class=\"n\"></td>", f);
        fprintf(f, "<td class=\"n\">%.2f</td></tr>\n", c->time_s / (double)c->n);
    }
    fputs("</table>\n", f);
}

static const char pictures_note[] =
    "<p>Pictures: the Poincar&eacute; disk re-centred and zoomed on the walk (on its tile "
    "nearest the walk's centre); the walked path's steps from indigo (the first) to "
    "<span class=\"walked\">orange</span> (the last), numbered, an edge walked again drawn "
    "beside the earlier passes, over the <span class=\"optimal\">optimal walk</span>; the "
    "start green, the objectives red (keys gold, the chest brown), the last tile ringed; "
    "a legend in each picture.</p>\n";

static void html_row(FILE *f, const report_run *r, int i)
{
    const report_att *t = &r->att[i];
    const hol_report_attempt *a = &t->a;
    char pos[24], eff[24], tiling[16], room[16], cell[16], num[64];
    num_or_empty(pos, sizeof pos, (double)a->position, "%.0f");
    num_or_empty(eff, sizeof eff, hol_report_efficiency(a), "%.4f");
    geometry_text(a, tiling, room, cell);
    fputs("<tr class=\"", f);
    report_html(f, a->end);
    fprintf(f, "\"><td class=\"n\">%d</td>", i + 1);
    if (t->png[0]) /* the picture first: the table may be wider than the window */
        fprintf(f, "<td><a href=\"%s\"><img src=\"%s\" width=\"240\" height=\"240\" "
                   "alt=\"attempt %d\"></a></td>", t->png, t->png, i + 1);
    else
        fputs("<td>(no steps file)</td>", f);
    html_cell(f, a->participant);
    html_cell(f, a->session);
    fprintf(f, "<td class=\"n\">%ld</td>", a->attempt);
    html_cell(f, a->study);
    html_cell(f, a->condition);
    html_cell(f, pos);
    html_cell(f, a->level);
    html_cell(f, a->mode);
    fprintf(f, "<td class=\"n\">%ld</td><td class=\"n\">%ld</td>", a->steps, a->optimum);
    html_cell(f, eff);
    snprintf(num, sizeof num, "%.2f", a->time_s);
    html_cell(f, num);
    html_cell(f, a->end);
    snprintf(num, sizeof num, "{%s} %s, %s m", tiling, room, cell);
    html_cell(f, num);
    fputs("</tr>\n", f);
}

static int index_html(FILE *f, const report_run *r, const void *ctx)
{
    const hol_report_agg *g = ctx;
    html_head(f, r, g);
    report_stats_html(f, r);
    fputs("<h2>Attempts</h2>\n", f);
    fputs(pictures_note, f);
    fputs("<table>\n<tr><th>#</th><th>path</th><th>participant</th><th>session</th><th>attempt</th>"
          "<th>study</th><th>condition</th><th>position</th><th>level</th><th>mode</th>"
          "<th>steps</th><th>optimum</th><th>efficiency</th><th>time (s)</th><th>end</th>"
          "<th>geometry</th></tr>\n", f);
    for (int i = 0; i < r->natt; i++)
        html_row(f, r, i);
    fputs("</table>\n", f);
    fprintf(f, "<footer><p>Made by holonomy %s (commit %s, built %s): <a href=\"build.csv\">"
               "build.csv</a>; every column of these files: <a href=\"codebook.csv\">"
               "codebook.csv</a>.</p></footer>\n</body>\n</html>\n",
            hol_shell_build_version(), hol_shell_build_commit(), hol_shell_build_date());
    return 0;
}

int report_write_html(const report_run *r, const hol_report_agg *g)
{
    return report_write_file(r, "index.html", index_html, g);
}

static int build_csv(FILE *f, const report_run *r, const void *ctx)
{
    (void)r;
    (void)ctx;
    report_header(f, "build.csv");
    fprintf(f, "holonomy,%s,%s,%s\n", hol_shell_build_version(),
            hol_shell_build_commit(), hol_shell_build_date());
    return 0;
}

static int codebook_file(FILE *f, const report_run *r, const void *ctx)
{
    static char text[CODEBOOK_TEXT_MAX];
    size_t n = codebook_csv(CODEBOOK_REPORT, text, sizeof text);
    (void)ctx;
    if (!n) {
        cli_error(r->cmd, 0, "the codebook does not fit its buffer");
        return CLI_EXIT_FAIL;
    }
    fwrite(text, 1, n, f);
    return 0;
}

int report_write_provenance(const report_run *r)
{
    int st = report_write_file(r, "build.csv", build_csv, NULL);
    return st ? st : report_write_file(r, "codebook.csv", codebook_file, NULL);
}
