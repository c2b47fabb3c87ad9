/* cmd_lesson.c - `holonomy lesson sheet N --out FILE.svg|.html [--key]`: a
 * lesson's A4 worksheet (the predict question, room to answer, the walk,
 * a Poincare-disk picture of its route) or its answer key (the answer and
 * why), from core/hol_lesson.h; the picture is the report's
 * (report/report_draw.h), embedded as a PNG. docs/teaching.md. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../core/hol_lesson.h"
#include "../../core/hol_room.h"
#include "../../core/hol_str.h"
#include "../../render/hol_png.h"
#include "../file/hol_file.h"
#include "cli.h"
#include "play_setup.h"
#include "report/report_draw.h"

const char *const cli_lesson_usage =
    "usage: holonomy lesson sheet N --out FILE.svg|FILE.html [--key] [--tiling 4,Q]\n"
    "                                 [--lang en|de|nl]\n"
    "\n"
    "Writes lesson N's (1..6; docs/teaching.md) worksheet for one A4 page: the\n"
    "question to answer before walking, with room for the answer and why,\n"
    "the walk, and a picture of the route on the Poincare disk (the flat grid\n"
    "for --tiling 4,4). Every number comes from the core, as in the app.\n"
    "\n"
    "  --out FILE     an SVG page (.svg) or an HTML page holding it (.html),\n"
    "                 written atomically\n"
    "  --key          the answer key instead: the right answer, why, the hint\n"
    "  --tiling 4,Q   the tiling {4,Q}, Q from 4 (the flat grid) to 8; default 4,5\n"
    "  --lang L       the sheet's language: en (default), de or nl\n"
    "\n"
    "Exit status: 0 ok, 1 failure, 2 bad input (one line).\n";

const char *const cli_lesson_valued[] = {"--out", "--lang", PLAY_GEOMETRY_OPTIONS, NULL};

/* The sheet's own words, one row a language each (the lesson's texts are
 * core/hol_lesson_text.c's): English, German, Dutch. */
enum { SW_TITLE, SW_HEAD, SW_KEY, SW_NAME, SW_PREDICT, SW_WHY, SW_NUMBER, SW_NUMBER_KEY,
       SW_GOAL, SW_WALK, SW_ROUTE, SW_FIRST, SW_HINT, SW_CHECK, SW_COUNT };
static const char *const sheet_words[SW_COUNT][HOL_LANG_COUNT] = {
    {"Lesson %d", "Lektion %d", "Les %d"},
    {"Lesson %d: %s {4,%d}%s", "Lektion %d: %s {4,%d}%s", "Les %d: %s {4,%d}%s"},
    {" - answer key", " - Lösung", " - antwoorden"},
    {"Name: ______________________   Class: ________",
     "Name: ____________________   Klasse: ________",
     "Naam: ______________________   Klas: ________"},
    {"1. Predict, before you walk:", "1. Sag voraus, bevor du gehst:",
     "1. Voorspel, voordat je loopt:"},
    {"Why do you think so?", "Warum denkst du das?", "Waarom denk je dat?"},
    {"A number from %d to %d: ______", "Eine Zahl von %d bis %d: ______",
     "Een getal van %d tot %d: ______"},
    {"A number from %d to %d: %d", "Eine Zahl von %d bis %d: %d", "Een getal van %d tot %d: %d"},
    {"Goal:", "Ziel:", "Doel:"},
    {"2. Walk:", "2. Geh:", "2. Loop:"},
    {"The route on the Poincare disk:", "Der Weg auf der Poincaré-Scheibe:",
     "De route op de schijf van Poincaré:"},
    {"Your first step on the Poincare disk; draw the rest of your walk:",
     "Dein erster Schritt auf der Poincaré-Scheibe; zeichne den Rest deines Wegs:",
     "Je eerste stap op de schijf van Poincaré; teken de rest van je wandeling:"},
    {"Hint:", "Tipp:", "Tip:"},
    {"3. Check: were you right? What surprised you?",
     "3. Prüfe: Hattest du recht? Was hat dich überrascht?",
     "3. Controleer: had je gelijk? Wat verraste je?"},
};
#define SW(lang, k) sheet_words[k][(lang) >= 0 && (lang) < HOL_LANG_COUNT ? (lang) : 0]

#define SHEET_PX 360 /* the picture's pixels */

static void xml_text(FILE *f, const char *s)
{
    for (; *s; s++) {
        if (*s == '<')
            fputs("&lt;", f);
        else if (*s == '>')
            fputs("&gt;", f);
        else if (*s == '&')
            fputs("&amp;", f);
        else
            fputc(*s, f);
    }
}

/* Text wrapped into lines from y (mm) on: the y after it. */
static double sheet_para(FILE *f, const char *s, double y, double size, const char *weight)
{
    char lines[12][HOL_APP_TEXT_MAX];
    int n = hol_app_wrap(s, 46, lines, 12);
    for (int i = 0; i < n && i < 12; i++, y += size * 1.35) {
        fprintf(f, "<text x=\"20\" y=\"%.1f\" font-size=\"%.1f\" font-weight=\"%s\">", y, size,
                weight);
        xml_text(f, lines[i]);
        fputs("</text>\n", f);
    }
    return y;
}

static void base64(FILE *f, const uint8_t *p, size_t n)
{
    static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)p[i] << 16 | (i + 1 < n ? (uint32_t)p[i + 1] << 8 : 0) |
                     (i + 2 < n ? p[i + 2] : 0);
        fputc(b64[v >> 18 & 63], f);
        fputc(b64[v >> 12 & 63], f);
        fputc(i + 1 < n ? b64[v >> 6 & 63] : '=', f);
        fputc(i + 2 < n ? b64[v & 63] : '=', f);
    }
}

/* The route on the disk (report_draw's picture, the view fitted to the
 * whole route), as a PNG: the key's whole route; the sheet's first step
 * only (the rest is the pupil's to draw: the picture must not answer the
 * question). 0 ok. */
static int sheet_picture(const hol_lesson_facts *lf, int key, uint8_t **png, size_t *npng)
{
    hol_room r;
    hol_tile walked[HOL_APP_ROUTE_MAX];
    if (hol_room_start_in(lf->q, 3, 3, &r))
        return -1;
    report_picture p;
    memset(&p, 0, sizeof p);
    p.start = r;
    for (int i = 0; i < lf->nroute; i++) {
        if (hol_room_step(&r, lf->route[i]))
            return -1;
        walked[i] = r.tile;
    }
    p.walked = walked;
    p.nwalked = lf->nroute;
    report_view view;
    if (report_view_fit(&p, &view))
        return -1;
    p.view = &view;
    p.nwalked = key ? lf->nroute : 1;
    static uint8_t px[SHEET_PX * SHEET_PX];
    uint8_t plte[3 * 256];
    int npal = report_palette(plte);
    if (report_draw(&p, px, SHEET_PX))
        return -1;
    return hol_png_encode_indexed(px, SHEET_PX, SHEET_PX, plte, npal, png, npng) ? -1 : 0;
}

/* n lines to write on, 8 mm apart, from y: the y after them. */
static double sheet_lines(FILE *f, double y, int n)
{
    for (int i = 0; i < n; i++, y += 8)
        fprintf(f, "<line x1=\"20\" y1=\"%.1f\" x2=\"190\" y2=\"%.1f\" stroke=\"#888\" "
                   "stroke-width=\"0.3\"/>\n", y + 6, y + 6);
    return y + 4;
}

/* The question's choices, or its scale, with boxes to tick (the key: the
 * right one ticked, the right number written). */
static double sheet_choices(FILE *f, const hol_lesson_facts *lf, int lang, int key, double y)
{
    char buf[HOL_LESSON_TEXT_MAX];
    if (lf->choice) {
        const char *c;
        for (int k = 0; (c = hol_lesson_label(lf, lang, k)); k++, y += 7) {
            fprintf(f, "<rect x=\"24\" y=\"%.1f\" width=\"4\" height=\"4\" fill=\"%s\" "
                       "stroke=\"black\" stroke-width=\"0.3\"/>\n", y - 3.5,
                    key && k == lf->answer ? "black" : "none");
            fprintf(f, "<text x=\"32\" y=\"%.1f\" font-size=\"4\">", y);
            xml_text(f, c);
            fputs("</text>\n", f);
        }
        return y;
    }
    int lo, hi, step;
    hol_lesson_scale(lf, &lo, &hi, &step);
    if (key)
        snprintf(buf, sizeof buf, SW(lang, SW_NUMBER_KEY), lo, hi, lf->answer);
    else
        snprintf(buf, sizeof buf, SW(lang, SW_NUMBER), lo, hi);
    return sheet_para(f, buf, y, 4, "normal") + 3;
}

static int sheet_svg(FILE *f, const hol_lesson_facts *lf, int lang, int key, const uint8_t *png,
                     size_t npng)
{
    char buf[HOL_LESSON_TEXT_MAX], head[HOL_LESSON_TEXT_MAX + 48];
    fputs("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"210mm\" height=\"297mm\" "
          "viewBox=\"0 0 210 297\" font-family=\"DejaVu Sans, sans-serif\">\n"
          "<rect width=\"210\" height=\"297\" fill=\"white\"/>\n", f);
    hol_lesson_text(lf, lang, HOL_LESSON_TITLE, buf, sizeof buf);
    snprintf(head, sizeof head, SW(lang, SW_HEAD), lf->lesson, buf, lf->q,
             key ? SW(lang, SW_KEY) : "");
    double y = sheet_para(f, head, 22, 7, "bold");
    if (!key)
        y = sheet_para(f, SW(lang, SW_NAME), y + 2, 4, "normal");
    hol_lesson_text(lf, lang, HOL_LESSON_QUESTION, buf, sizeof buf);
    y = sheet_para(f, SW(lang, SW_PREDICT), y + 6, 4.5, "bold");
    y = sheet_choices(f, lf, lang, key, sheet_para(f, buf, y, 4.5, "normal") + 2);
    if (key) {
        hol_lesson_text(lf, lang, HOL_LESSON_CHECK, buf, sizeof buf);
        y = sheet_para(f, buf, y + 2, 4.5, "normal");
        hol_lesson_text(lf, lang, HOL_LESSON_GOAL, buf, sizeof buf);
        y = sheet_para(f, SW(lang, SW_GOAL), y + 4, 4, "bold");
        y = sheet_para(f, buf, y, 4, "normal");
    } else {
        y = sheet_lines(f, sheet_para(f, SW(lang, SW_WHY), y + 2, 4, "normal"), 2);
    }
    hol_lesson_text(lf, lang, HOL_LESSON_WALK, buf, sizeof buf);
    y = sheet_para(f, SW(lang, SW_WALK), y + 6, 4.5, "bold");
    y = sheet_para(f, buf, y, 4.5, "normal");
    y = sheet_para(f, SW(lang, key ? SW_ROUTE : SW_FIRST), y + 1, 4, "normal");
    fprintf(f, "<image x=\"62\" y=\"%.1f\" width=\"86\" height=\"86\" "
               "href=\"data:image/png;base64,", y + 1);
    base64(f, png, npng);
    fputs("\"/>\n", f);
    y += 90;
    hol_lesson_text(lf, lang, HOL_LESSON_HINT, buf, sizeof buf);
    if (key) {
        y = sheet_para(f, SW(lang, SW_HINT), y + 2, 4, "bold");
        sheet_para(f, buf, y, 4, "normal");
    } else {
        sheet_lines(f, sheet_para(f, SW(lang, SW_CHECK), y + 2, 4, "bold"), 2);
    }
    fputs("</svg>\n", f);
    return ferror(f) ? -1 : 0;
}

static int sheet_args(const char *cmd, int argc, char **argv, int *n, const char **out, int *key,
                      int *lang, play_geometry *geo)
{
    static const char *const flags[] = {"--key", NULL};
    cli_opts p;
    cli_opts_init(&p, cmd, argc, argv, cli_lesson_valued, flags);
    const char *a, *val;
    int r, ops = 0;
    while ((r = cli_opts_next(&p, &a, &val)) > 0) {
        if (!a) {
            if (ops++ == 0 && strcmp(val, "sheet")) {
                cli_error(cmd, 0, "'%.40s' is not a lesson command: sheet", val);
                return CLI_EXIT_USAGE;
            }
            if (ops == 2 && play_lesson_value(cmd, val, n))
                return CLI_EXIT_USAGE;
        } else if (!strcmp(a, "--out")) {
            *out = val;
        } else if (!strcmp(a, "--key")) {
            *key = 1;
        } else if (!strcmp(a, "--lang")) {
            if (cli_lang_value(cmd, val, lang))
                return CLI_EXIT_USAGE;
        } else if (play_geometry_value(cmd, a, val, geo) <= 0) {
            cli_error(cmd, 0, "lesson sheet takes --out, --key, --tiling and --lang, not %.40s", a);
            return CLI_EXIT_USAGE;
        }
    }
    if (r < 0)
        return CLI_EXIT_USAGE;
    if (ops != 2 || !*out) {
        cli_error(cmd, 0, "usage: holonomy lesson sheet N --out FILE.svg|FILE.html [--key]");
        return CLI_EXIT_USAGE;
    }
    size_t len = strlen(*out);
    if (!(len > 4 && !strcmp(*out + len - 4, ".svg")) &&
        !(len > 5 && !strcmp(*out + len - 5, ".html"))) {
        cli_error(cmd, 0, "--out needs a name ending in .svg or .html");
        return CLI_EXIT_USAGE;
    }
    return 0;
}

int cli_cmd_lesson(int argc, char **argv)
{
    const char *cmd = "lesson", *out = NULL;
    int n = 0, key = 0, lang = HOL_LANG_EN;
    play_geometry geo = {0, 0, 0, 0};
    int st = sheet_args(cmd, argc, argv, &n, &out, &key, &lang, &geo);
    if (!st)
        st = cli_check_output(cmd, "--out", out);
    if (st)
        return st;
    hol_lesson_facts lf;
    uint8_t *png = NULL;
    size_t npng = 0;
    if (hol_lesson_facts_of(n, geo.q ? geo.q : 5, &lf) || sheet_picture(&lf, key, &png, &npng)) {
        cli_error(cmd, 0, "cannot make lesson %d's sheet", n);
        return CLI_EXIT_FAIL;
    }
    hol_file_atomic w;
    char esc[256];
    int html = out[strlen(out) - 1] == 'l';
    if (hol_file_atomic_open(&w, out)) {
        free(png);
        cli_error(cmd, 0, "cannot write '%s': %s", cli_escape(out, esc, sizeof esc),
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    if (html) {
        fputs("<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>", w.f);
        fprintf(w.f, SW(lang, SW_TITLE), n);
        fputs("</title><style>@page{size:A4;margin:0}body{margin:0}</style></head><body>\n", w.f);
    }
    int bad = sheet_svg(w.f, &lf, lang, key, png, npng);
    if (html)
        fputs("</body></html>\n", w.f);
    free(png);
    if (bad || hol_file_atomic_commit(&w)) {
        hol_file_atomic_abort(&w);
        cli_error(cmd, 0, "cannot write '%s': %s", cli_escape(out, esc, sizeof esc),
                  strerror(errno));
        return CLI_EXIT_FAIL;
    }
    return 0;
}
