/* hol_study_impl.h - what hol_study.c (the study file's parser) and
 * hol_study_level.c (a condition's level) share; not for outside core's
 * study files.
 *
 * Contract
 * - hol__study_fail sets *e (hol_level_err_vset) and returns code.
 * - hol__study_field: the next blank-separated field of [*p, end), its
 *   start in *out, its length returned (0 at the end); *p moves past it.
 *   hol__study_is: [w, w+n) is word. hol__study_key: a level line's key
 *   (its first field before any comment).
 * - hol__study_in_force: set line j is in force for condition c (its own,
 *   or the study's when the condition does not set the same key);
 *   hol__study_set_key: a set line in force for c gives key [k, k+kn).
 * - Pure: no state, no allocation.
 */
#ifndef HOL_STUDY_IMPL_H
#define HOL_STUDY_IMPL_H

#include <stddef.h>

#include "hol_study.h"

hol_err hol__study_fail(hol_level_err *e, hol_err code, long line, long other,
                        const char *fmt, ...) __attribute__((format(printf, 5, 6)));
size_t hol__study_field(const char **p, const char *end, const char **out);
int hol__study_is(const char *w, size_t n, const char *word);
size_t hol__study_key(const char *b, const char *e, const char **out);
int hol__study_in_force(const hol_study *s, int c, int j);
int hol__study_set_key(const hol_study *s, int c, const char *k, size_t kn);

#endif
