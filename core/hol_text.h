/* hol_text.h - text from outside made safe where it goes: a terminal, a CSV
 * field. One helper each; every platform uses these (names from level files
 * and recordings, paths and option values in messages).
 *
 * Contract
 * - Both write into caller memory: out holds cap bytes and is always
 *   NUL-terminated when cap > 0; they return the length the whole result
 *   needs (without the NUL), as snprintf does, so `need >= cap` means it was
 *   cut (never inside an escape or in the middle of a UTF-8 character).
 *   out may be NULL when cap is 0 (to measure). s holds len bytes and may
 *   hold NUL bytes.
 * - hol_text_escape: for a terminal (one line, nothing it obeys). Valid UTF-8
 *   passes unchanged except the code points a terminal may act on: C0
 *   controls (bytes 0x00-0x1f: newline, escape, bell ...), DEL, the C1
 *   controls U+0080-U+009F (U+009B is a CSI), the line and paragraph
 *   separators U+2028-U+2029 and the bidirectional controls U+202A-U+202E
 *   and U+2066-U+2069. Those, and every byte of a sequence that is not valid
 *   UTF-8 (overlong forms, surrogates, beyond U+10FFFF, cut short), are
 *   written as \xHH per byte (lowercase hex). A backslash is written as
 *   \\ so that the escaped text reads back unambiguously.
 * - hol_text_csv: one CSV field per RFC 4180: a field holding a comma, a
 *   double quote, CR or LF (or a leading or trailing space, which some
 *   readers strip) is enclosed in double quotes, each double quote inside
 *   doubled; any other field is written as it is. The bytes are kept: to
 *   write a name from outside into a CSV a person may `cat`, escape it
 *   first (hol_text_escape) and quote the result.
 * - Pure: no I/O, no allocation, no globals.
 */
#ifndef HOL_TEXT_H
#define HOL_TEXT_H

#include <stddef.h>

size_t hol_text_escape(const char *s, size_t len, char *out, size_t cap);
size_t hol_text_csv(const char *s, size_t len, char *out, size_t cap);

#endif
