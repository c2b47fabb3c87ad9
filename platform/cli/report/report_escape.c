/* report_escape.c - the report's CSV field and HTML text (report_escape.h). */
#include "report_escape.h"

#include <string.h>

#include "../../../core/hol_text.h"

void report_csv(FILE *f, const char *s, int last)
{
    char clean[REPORT_ESCAPE_MAX + 1], buf[2 * REPORT_ESCAPE_MAX + 3];
    hol_report_clean(s, clean, sizeof clean);
    hol_text_csv(clean, strlen(clean), buf, sizeof buf);
    fputs(buf, f);
    fputc(last ? '\n' : ',', f);
}

void report_html(FILE *f, const char *s)
{
    char clean[REPORT_ESCAPE_MAX + 1];
    hol_report_clean(s, clean, sizeof clean);
    for (const char *c = clean; *c; c++)
        switch (*c) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*c, f);
        }
}
