/* hol_app_lesson.c - a lesson level's texts in the view's language (see
 * hol_app_impl.h, core/hol_lesson.h): the level holds its lesson's English
 * texts (what the logs keep: the English choice); the view shows them in
 * hol__lang, and lesson 6's hint on request. A text that is not its
 * lesson's English one (a study's own) is shown as written. */
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_lesson.h"
#include "hol_str.h"

/* The facts of the level's lesson: 0, or -1 for a level with none. */
static int hol__lesson_facts(const hol_app *app, hol_lesson_facts *f)
{
    int q = app->level.tiling_q ? app->level.tiling_q : HOL_TILING_DEFAULT_Q;
    return app->level.lesson && !hol_lesson_facts_of(app->level.lesson, q, f) ? 0 : -1;
}

const char *hol__lesson_say(const hol_app *app, const char *text, int part, char *out,
                            size_t cap)
{
    hol_lesson_facts f;
    char en[HOL_APP_SCREEN_TEXT];
    int lang = hol__lang(app);
    if (lang == HOL_LANG_EN || hol__lesson_facts(app, &f) ||
        hol_lesson_text(&f, HOL_LANG_EN, part, en, sizeof en) < 0 || strcmp(en, text) ||
        hol_lesson_text(&f, lang, part, out, cap) < 0)
        return text;
    return out;
}

const hol_app_question *hol__lesson_item(const hol_app *app, const hol_app_question *q,
                                         hol_app_question *tmp)
{
    hol_lesson_facts f;
    int lang = hol__lang(app);
    if (lang == HOL_LANG_EN || hol__lesson_facts(app, &f) ||
        hol_lesson_question(&f, HOL_LANG_EN, tmp) || strcmp(tmp->id, q->id) ||
        strcmp(tmp->text, q->text) || hol_lesson_question(&f, lang, tmp))
        return q;
    return tmp;
}

int hol__lesson_hint(const hol_app *app, char *out, size_t cap)
{
    hol_lesson_facts f;
    return app->level.lesson == HOL_APP_HINT_LESSON && !hol__lesson_facts(app, &f) &&
           hol_lesson_text(&f, hol__lang(app), HOL_LESSON_HINT, out, cap) > 0;
}
