/* report_escape.c - the report's CSV field and HTML text (report_escape.h). */
#include "report_escape.h"

#include <string.h>

#include "../../../core/hol_text.h"

int report_csv_number(const char *s)
{
    static const char dig[] = "0123456789";
    const char *p = s + (*s == '-' || *s == '+');
    size_t a = strspn(p, dig), b = 0;
    p += a;
    if (*p == '.') {
        b = strspn(p + 1, dig);
        p += 1 + b;
    }
    if (!a && !b)
        return 0;
    if (*p == 'e' || *p == 'E') {
        p += 1 + (p[1] == '-' || p[1] == '+');
        size_t k = strspn(p, dig);
        if (!k)
            return 0;
        p += k;
    }
    return !*p;
}

void report_csv(FILE *f, const char *s, int last)
{
    char clean[REPORT_ESCAPE_MAX + 1], buf[2 * REPORT_ESCAPE_MAX + 3];
    hol_report_clean(s, clean, sizeof clean);
    if (clean[0] && strchr("=+-@\t\r", clean[0]) && !report_csv_number(clean)) {
        /* a formula to a spreadsheet: quoted, a ' before it (OWASP) */
        fputs("\"'", f);
        for (const char *c = clean; *c; c++) {
            if (*c == '"')
                fputc('"', f);
            fputc(*c, f);
        }
        fputc('"', f);
    } else {
        hol_text_csv(clean, strlen(clean), buf, sizeof buf);
        fputs(buf, f);
    }
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
