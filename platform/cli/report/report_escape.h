/* report_escape.h - a text from the logs as it stands in the report's
 * files (`holonomy report`: attempts.csv, conditions.csv, stats.csv,
 * learning.csv, participants.csv, index.html). The tool's one CSV field
 * writer and one HTML text writer; tests/test_report_escape.c checks them.
 *
 * Contract
 * - Both first clean the text (hol_report_clean, core/hol_report.h): what
 *   a terminal acts on and bad UTF-8 as \xHH per byte, a backslash kept.
 *   The cleaned text is cut at REPORT_ESCAPE_MAX bytes (never inside an
 *   escape or a UTF-8 character): a field of the logs (HOL_REPORT_TEXT
 *   bytes, each at most 4 cleaned) is never cut, nor is a path of up to
 *   1,023 bytes already escaped (hol_text_escape: cleaning keeps it).
 * - report_csv writes it as one CSV field (hol_text_csv, RFC 4180: quoted
 *   when it holds a comma, a double quote, CR or LF or a leading or
 *   trailing space, each double quote doubled), then ',' or, when last is
 *   not 0, '\n'.
 * - Spreadsheet safety (OWASP's CSV injection rule): a text whose cleaned
 *   form starts with '=', '+', '-', '@', a tab or CR and is not a number
 *   (report_csv_number) would be a formula to a spreadsheet; report_csv
 *   writes it quoted with a single quote before it ("'=1+1.lvl"), so a
 *   spreadsheet shows it as text. A number ("-12.5", "+3", "1e-3") stays
 *   as it is.
 * - report_csv_number: 1 when s is a decimal number as a spreadsheet reads
 *   one: [+-]D[.D][e[+-]D] (digits before or after the point), else 0.
 * - report_html writes it as HTML text (in an element or an attribute
 *   value): & < > " ' as &amp; &lt; &gt; &quot; &#39;, every other byte
 *   as it is.
 * - No allocation, no globals; the errors are f's (ferror).
 */
#ifndef REPORT_ESCAPE_H
#define REPORT_ESCAPE_H

#include <stdio.h>

#include "../../../core/hol_report.h"

#define REPORT_ESCAPE_MAX (4 * HOL_REPORT_TEXT + 7) /* cleaned bytes kept */

void report_csv(FILE *f, const char *s, int last);
int report_csv_number(const char *s);
void report_html(FILE *f, const char *s);

#endif
