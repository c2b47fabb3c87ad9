/* hol_app_lesson.c - a lesson level's texts, the class test's and the
 * questionnaire presets' items in the view's language (see hol_app_impl.h,
 * core/hol_lesson.h, core/hol_quiz.h, core/hol_ask.h): the level holds
 * their English texts (what the logs keep: the English choice); the view
 * shows them in hol__lang, and lesson 6's hint on request. A text that is
 * not its source's English one (a study's own) is shown as written. */
#include <stdio.h>
#include <string.h>

#include "hol_app_impl.h"
#include "hol_ask.h"
#include "hol_lesson.h"
#include "hol_quiz.h"
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
    if (lang != HOL_LANG_EN && part == HOL_LESSON_CHECK &&
        !strcmp(text, hol_str(HOL_LANG_EN, HOL_S_QUIZ_DONE)))
        return hol_str(lang, HOL_S_QUIZ_DONE);
    if (lang == HOL_LANG_EN || hol__lesson_facts(app, &f) ||
        hol_lesson_text(&f, HOL_LANG_EN, part, en, sizeof en) < 0 || strcmp(en, text) ||
        hol_lesson_text(&f, lang, part, out, cap) < 0)
        return text;
    return out;
}

static const hol_app_question *hol__lesson_item(const hol_app *app, const hol_app_question *q,
                                                hol_app_question *tmp)
{
    hol_lesson_facts f;
    int lang = hol__lang(app);
    if (hol__lesson_facts(app, &f) || hol_lesson_question(&f, HOL_LANG_EN, tmp) ||
        strcmp(tmp->id, q->id) || strcmp(tmp->text, q->text) || hol_lesson_question(&f, lang, tmp))
        return q;
    return tmp;
}

/* Item q of the class test's phase (a's name) in the view's language into
 * tmp, or NULL when q is none of its English items. */
static const hol_app_question *hol__quiz_item(const hol_app *app, const hol_app_ask *a,
                                              const hol_app_question *q, hol_app_question *tmp)
{
    int tq = app->level.tiling_q ? app->level.tiling_q : HOL_TILING_DEFAULT_Q;
    for (int phase = 0; phase < 2; phase++)
        for (int k = 0; !strcmp(a->name, hol_quiz_name(phase)) && k < HOL_QUIZ_ITEMS; k++) {
            hol_quiz_item it;
            if (hol_quiz_item_of(phase, k, tq, &it) || strcmp(it.question.id, q->id) ||
                strcmp(it.question.text, q->text) ||
                hol_quiz_item_in(phase, k, tq, hol__lang(app), &it))
                continue;
            *tmp = it.question;
            return tmp;
        }
    return NULL;
}

const hol_app_question *hol__item_said(const hol_app *app, const hol_app_ask *a,
                                       const hol_app_question *q, hol_app_question *tmp,
                                       const char **name)
{
    int lang = hol__lang(app);
    *name = a->name;
    if (lang == HOL_LANG_EN)
        return q;
    if (hol__lesson_item(app, q, tmp) == tmp) {
        *name = hol_str(lang, HOL_S_PREDICT);
        return tmp;
    }
    if (hol__quiz_item(app, a, q, tmp)) {
        *name = hol_str(lang, strcmp(a->name, hol_quiz_name(HOL_QUIZ_PRE)) ? HOL_S_POSTTEST
                                                                         : HOL_S_PRETEST);
        return tmp;
    }
    const hol_ask_preset_def *p = hol_ask_preset_at(hol_ask_preset_index(a->name, strlen(a->name)));
    int k = hol_ask_preset_item(p, q->id);
    if (k < 0 || hol_ask_preset_item_in(p, k, HOL_LANG_EN, tmp) || strcmp(tmp->text, q->text) ||
        hol_ask_preset_item_in(p, k, lang, tmp))
        return q;
    return tmp;
}

int hol__lesson_hint(const hol_app *app, char *out, size_t cap)
{
    hol_lesson_facts f;
    return app->level.lesson == HOL_APP_HINT_LESSON && !hol__lesson_facts(app, &f) &&
           hol_lesson_text(&f, hol__lang(app), HOL_LESSON_HINT, out, cap) > 0;
}
