/* hol_level_impl.h - the level parser's insides, shared by its files:
 * hol_level_parse.c (the key table, a line read, the two passes),
 * hol_level_keys.c (each key's line but the questionnaires'),
 * hol_level_ask.c (question and ask lines), hol_level_finish.c (the checks
 * after the last line, the objectives drawn by distance),
 * hol_level_write.c (named levels, the geometry lines a session adds) and
 * hol_level.c (the ground: errors, the parser's one way to fail, numbers,
 * words and addresses). Calls go one way, down: hol_level_write.c ->
 * hol_level_parse.c -> hol_level_keys.c, hol_level_ask.c,
 * hol_level_finish.c -> hol_level.c. A new line kind: a function declared
 * here and written in hol_level_keys.c, a row of hol__keys in
 * hol_level_parse.c (docs/hacking.md, "Adding a level line kind"). */
#ifndef HOL_LEVEL_IMPL_H
#define HOL_LEVEL_IMPL_H

#include <stdint.h>

#include "hol_level.h"

/* ---- the parser's state ------------------------------------------------------- */

#define HOL__FIELDS 8 /* fields kept of a line; more are counted as one more */

typedef struct hol__lp {
    hol_app_level L;
    long have_mode; /* the mode line, 0 before it */
    long line;
    /* objectives by distance (drawn after the last line) and where each
     * objective and placement was given */
    int flag_lo, flag_hi, keys_n, keys_lo, keys_hi, chest_lo, chest_hi;
    long flag_line, keys_line, chest_line, place_line[HOL_APP_MAX_PLACES];
    long tiling_line, room_line, lantern_line[HOL_APP_MAX_LANTERNS];
    int geo_only; /* the first pass: only the geometry lines */
    long point_line;   /* the `point` line (0: none) */
    char raw[HOL_LEVEL_LINE_MAX + 1]; /* the line being read, comment removed, unsplit */
    int ndefs;         /* `question` lines read (asks copy theirs) */
    hol_app_question defs[HOL_APP_MAX_QUESTIONS];
    long key_line[32]; /* where each key of hol__keys was given (0: not yet) */
    int repeated;      /* a key given twice: reported in either pass */
    hol_level_err *loud;
    hol_level_err *err;
} hol__lp;

/* ---- hol_level.c: the one way to fail, numbers, words, addresses ---------- */

hol_err hol__lfail(hol__lp *p, hol_err code, long line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* A conflict with another line: "... (line M)", or "... on line M". */
hol_err hol__lv_conflict(hol__lp *p, long line, long other, int on, const char *what,
                         const char *addr);
/* A positive decimal count (digits only, at most 2^40); 0 when it is not. */
uint64_t hol__lv_count(const char *s);
/* An unsigned 64-bit number, decimal or 0x hex: 1 ok. */
int hol__lv_u64(const char *s, uint64_t *out);
/* Index of word in names[n], or -1. */
int hol__lv_word(const char *word, const char *const *names, int n);
/* "MIN [MAX]" of a distance key from field first: 0 ok. */
int hol__lv_range(char **f, int nf, int first, int *lo, int *hi);
/* f[1] one of names[n] into *out, else "KEY 'WORD' is not LIST". */
hol_err hol__lv_one_of(hol__lp *p, char **f, const char *const *names, int n, const char *list,
                       int *out);
/* The level's tiling Q (the geometry lines are read first). */
int hol__lv_q(const hol__lp *p);
/* An address of the level's tiling at s into *t (what: "", "key "). */
hol_err hol__lv_addr(hol__lp *p, const char *s, const char *what, hol_tile *t);
/* A UTF-8 byte order mark at the start of a text is skipped. */
void hol__lv_skip_bom(const char **text, size_t *len);

/* ---- hol_level_keys.c and hol_level_ask.c: a key's line (f[0] the key,
 * nf fields; p->raw the whole line) -------------------------------------------- */

hol_err hol__key_mode(hol__lp *p, char **f, int nf);
hol_err hol__key_seed(hol__lp *p, char **f, int nf);
hol_err hol__key_start(hol__lp *p, char **f, int nf);
hol_err hol__key_tile(hol__lp *p, char **f, int nf);
hol_err hol__key_keys(hol__lp *p, char **f, int nf);
hol_err hol__key_dist(hol__lp *p, char **f, int nf);
hol_err hol__key_keys_dist(hol__lp *p, char **f, int nf);
hol_err hol__key_time_limit(hol__lp *p, char **f, int nf);
hol_err hol__key_stages(hol__lp *p, char **f, int nf);
hol_err hol__key_place(hol__lp *p, char **f, int nf);
hol_err hol__key_cues(hol__lp *p, char **f, int nf);
hol_err hol__key_fixed(hol__lp *p, char **f, int nf);
hol_err hol__key_minimap(hol__lp *p, char **f, int nf);
hol_err hol__key_lighting(hol__lp *p, char **f, int nf);
hol_err hol__key_carried(hol__lp *p, char **f, int nf);
hol_err hol__key_sound(hol__lp *p, char **f, int nf);
hol_err hol__key_lang(hol__lp *p, char **f, int nf);
hol_err hol__key_point(hol__lp *p, char **f, int nf);
hol_err hol__key_text(hol__lp *p, char **f, int nf);
hol_err hol__key_tiling(hol__lp *p, char **f, int nf);
hol_err hol__key_room(hol__lp *p, char **f, int nf);
hol_err hol__key_cell(hol__lp *p, char **f, int nf);
hol_err hol__key_lesson(hol__lp *p, char **f, int nf);
hol_err hol__key_quiz(hol__lp *p, char **f, int nf);
hol_err hol__key_question(hol__lp *p, char **f, int nf);
hol_err hol__key_ask(hol__lp *p, char **f, int nf);

/* ---- hol_level_finish.c: after the last line ----------------------------------- */

hol_err hol__lv_finish(hol__lp *p);

#endif
