/* test_str.c - core/hol_str.h, the string table: every language complete,
 * every string drawn without the missing-glyph box (core/hol_face.h), the
 * printf formats' conversions the same in every language, every text
 * fitting its buffer with its numbers at their widest, and the language
 * tags a command line or a browser gives. The lessons' table
 * (core/hol_lesson_text.c) likewise: complete, drawn, the same facts
 * named, and every text fitting its screen in every tiling. The seated
 * line, a device's buttons, the class test's and the presets' items
 * (SSQ, TLX) in every language, fitting where the app shows them.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_face.h"
#include "../core/hol_app.h"
#include "../core/hol_ask.h"
#include "../core/hol_input.h"
#include "../core/hol_lesson.h"
#include "../core/hol_prompt.h"
#include "../core/hol_quiz.h"
#include "../core/hol_str.h"

static void test_complete_and_drawn(void **state)
{
    (void)state;
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (int id = 0; id < HOL_S_COUNT; id++) {
            const char *s = hol_str(l, (hol_str_id)id);
            if (!s[0])
                fail_msg("%s: string %d is missing", hol_lang_code(l), id);
            int missing = 0;
            if (id < HOL_S_PAGE_FIRST) /* the page's are the browser's to draw */
                hol_face_units(s, strlen(s), &missing);
            if (missing)
                fail_msg("%s: '%s' draws %d missing-glyph boxes", hol_lang_code(l), s, missing);
        }
    int boxes = 0; /* the check sees a box: the euro sign is not Latin-1 */
    hol_face_units("\xe2\x82\xac", 3, &boxes);
    assert_int_equal(boxes, 1);
    assert_string_equal(hol_str(-1, HOL_S_PAUSED), "Paused");
    assert_string_equal(hol_str(HOL_LANG_COUNT, HOL_S_PAUSED), "Paused");
    assert_string_equal(hol_str(HOL_LANG_DE, HOL_S_COUNT), "");
}

/* The conversions of a printf format, "%d%ld%02ld...", into out. */
static void conversions(const char *f, char *out, size_t cap)
{
    size_t n = 0;
    for (const char *p = strchr(f, '%'); p; p = strchr(p, '%')) {
        size_t k = strspn(p + 1, "0123456789.-+ #lhz") + 2;
        assert_true(n + k < cap);
        memcpy(out + n, p, k);
        n += k;
        p += k;
    }
    out[n] = 0;
}

static void test_formats_match(void **state)
{
    (void)state;
    for (int id = 0; id < HOL_S_COUNT; id++) {
        char en[64], other[64];
        conversions(hol_str(HOL_LANG_EN, (hol_str_id)id), en, sizeof en);
        for (int l = 1; l < HOL_LANG_COUNT; l++) {
            conversions(hol_str(l, (hol_str_id)id), other, sizeof other);
            if (strcmp(en, other))
                fail_msg("%s: string %d has '%s', English '%s'", hol_lang_code(l), id, other,
                         en);
        }
    }
}

/* Each text with its numbers at their widest as the app gives them
 * (steps and best up to 999, a clock up to 99:59, 5 keys, a 40-character
 * address, a 3 x 3.75 room, 8 beacons) fits its buffer. */
static void test_fits(void **state)
{
    (void)state;
    const char *addr = "LRLRLRLRLRLRLRLRLRLRLRLRLRLRLRLRLRLRLRLR";
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (int id = 0; id < HOL_S_COUNT; id++) {
            const char *f = hol_str(l, (hol_str_id)id);
            char buf[256], conv[64];
            if (id >= HOL_S_PAGE_FIRST)
                continue; /* the page's: no buffer (the browser draws them) */
            conversions(f, conv, sizeof conv);
            int n;
            if (!strcmp(conv, "%d%d%ld%02ld"))
                n = snprintf(buf, sizeof buf, f, 999, 999, 99L, 59L);
            else if (!strcmp(conv, "%d%ld%02ld"))
                n = snprintf(buf, sizeof buf, f, 999, 99L, 59L);
            else if (!strcmp(conv, "%ld%02ld%ld%02ld"))
                n = snprintf(buf, sizeof buf, f, 99L, 59L, 99L, 59L);
            else if (!strcmp(conv, "%ld%02ld"))
                n = snprintf(buf, sizeof buf, f, 99L, 59L);
            else if (!strcmp(conv, "%d%d%d"))
                n = snprintf(buf, sizeof buf, f, 4, 4, 3);
            else if (!strcmp(conv, "%d%d"))
                n = snprintf(buf, sizeof buf, f, 5, 5);
            else if (!strcmp(conv, "%d"))
                n = snprintf(buf, sizeof buf, f, id == HOL_S_STEPS_FMT ? 999 : 8);
            else if (!strcmp(conv, "%.40s"))
                n = snprintf(buf, sizeof buf, f, addr);
            else if (!strcmp(conv, "%.12s"))
                n = snprintf(buf, sizeof buf, f, "3 x 3.75");
            else {
                assert_string_equal(conv, "");
                n = (int)strlen(f);
            }
            if (n >= hol_str_cap((hol_str_id)id))
                fail_msg("%s: '%s' takes %d bytes of %d", hol_lang_code(l), buf, n + 1,
                         hol_str_cap((hol_str_id)id));
        }
}

/* The prompts as core/hol_app_view.c composes them ("BUTTON: WHAT, ..."),
 * for every device and language: the pause menu's three pairs, the end
 * screen's and a screen's two, each whole within the prompt's line
 * (HOL_APP_HINT_MAX: a pair that does not fit would be left out). */
static void test_prompts_fit(void **state)
{
    (void)state;
    static const struct {
        uint32_t btn, alt;
        hol_str_id what;
    } sets[4][3] = {{{HOL_BTN_MENU, 0, HOL_S_DO_RESUME},
                     {HOL_BTN_CONFIRM, 0, HOL_S_DO_RESTART},
                     {HOL_BTN_QUIT, HOL_BTN_BACK, HOL_S_DO_QUIT}},
                    {{HOL_BTN_CONFIRM, 0, HOL_S_DO_NEXT_LEVEL}, {HOL_BTN_RESTART, 0, HOL_S_DO_AGAIN}},
                    {{HOL_BTN_CONFIRM, 0, HOL_S_DO_FINISH}, {HOL_BTN_RESTART, 0, HOL_S_DO_AGAIN}},
                    {{HOL_BTN_CONFIRM, 0, HOL_S_DO_BEGIN}, {HOL_BTN_QUIT, 0, HOL_S_DO_QUIT}}};
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (uint32_t d = 0; d < HOL_DEVICE_COUNT; d++)
            for (int s = 0; s < 4; s++) {
                char buf[256] = "";
                for (int i = 0; i < 3 && sets[s][i].btn; i++) {
                    const char *b = hol_prompt_button_in(d, sets[s][i].btn, l);
                    if (!b && sets[s][i].alt)
                        b = hol_prompt_button_in(d, sets[s][i].alt, l);
                    size_t n = strlen(buf);
                    if (b)
                        snprintf(buf + n, sizeof buf - n, "%s%s: %s", n ? ", " : "", b,
                                 hol_str(l, sets[s][i].what));
                }
                if (strlen(buf) >= 60)
                    fail_msg("%s: device %u: '%s' is over the prompt's 59 bytes", hol_lang_code(l),
                             d, buf);
            }
}


/* The {name}s of a lesson's text, sorted, into out ("{4,5}" is no fact). */
static void facts_named(const char *s, char *out, size_t cap)
{
    char names[16][16];
    int n = 0;
    for (const char *b = strchr(s, '{'); b; b = strchr(b + 1, '{')) {
        const char *e = strchr(b, '}');
        if (!e || (b[1] >= '0' && b[1] <= '9'))
            continue;
        assert_true(n < 16 && e - b < 16);
        snprintf(names[n++], 16, "%.*s", (int)(e - b + 1), b);
    }
    for (int i = 1; i < n; i++) /* sort: a language may order them otherwise */
        for (int j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
            char t[16];
            memcpy(t, names[j], 16), memcpy(names[j], names[j - 1], 16), memcpy(names[j - 1], t, 16);
        }
    out[0] = 0;
    for (int i = 0; i < n; i++)
        snprintf(out + strlen(out), cap - strlen(out), "%s", names[i]);
}

/* Every entry of the lessons' table in every language when English has
 * one (and none when it has none), drawn by the face, naming the English
 * entry's facts (its conversions, for the words' formats). */
static void test_lessons_complete(void **state)
{
    (void)state;
    for (int n = 1; n <= HOL_LESSONS; n++)
        for (int k = 0; k < HOL_LESSON_PARTS + HOL_APP_MAX_CHOICES + 16; k++) {
            const char *en = hol_lesson_entry(n, HOL_LANG_EN, k);
            for (int l = 1; l < HOL_LANG_COUNT; l++) {
                const char *s = hol_lesson_entry(n, l, k);
                if (!en != !s)
                    fail_msg("%s: lesson %d entry %d is %s", hol_lang_code(l), n, k,
                             s ? "extra" : "missing");
                if (!s)
                    continue;
                char a[256], b[256];
                int missing = 0;
                hol_face_units(s, strlen(s), &missing);
                if (missing)
                    fail_msg("%s: '%s' draws %d missing-glyph boxes", hol_lang_code(l), s, missing);
                facts_named(en, a, sizeof a), facts_named(s, b, sizeof b);
                if (strcmp(a, b))
                    fail_msg("%s: lesson %d entry %d names %s, English %s", hol_lang_code(l), n, k,
                             b, a);
                conversions(en, a, sizeof a), conversions(s, b, sizeof b);
                if (strcmp(a, b))
                    fail_msg("%s: lesson %d entry %d has '%s', English '%s'", hol_lang_code(l), n,
                             k, b, a);
            }
        }
}

/* Every lesson's texts expanded in every tiling and language fit where
 * the app and the sheet put them: the walk and the check a screen
 * (HOL_APP_SCREEN_LINES wrapped lines), the question an item's text in
 * its 3 lines, a choice or an anchor the item's value (20 bytes), the
 * hint 3 lines of the paused HUD, the predict name 12 bytes. */
static void test_lessons_fit(void **state)
{
    (void)state;
    static const int lines[HOL_LESSON_PARTS] = {1, 12, 3, HOL_APP_SCREEN_LINES,
                                                HOL_APP_SCREEN_LINES, 3};
    for (int l = 0; l < HOL_LANG_COUNT; l++) {
        assert_true(strlen(hol_str(l, HOL_S_PREDICT)) <= 12);
        for (int q = 4; q <= 8; q++)
            for (int n = 1; n <= HOL_LESSONS; n++) {
                hol_lesson_facts f;
                assert_int_equal(hol_lesson_facts_of(n, q, &f), HOL_OK);
                for (int part = 0; part < HOL_LESSON_PARTS; part++) {
                    char s[HOL_LESSON_TEXT_MAX];
                    int len = hol_lesson_text(&f, l, part, s, sizeof s);
                    if (len <= 0 || hol_app_wrap(s, HOL_APP_SCREEN_COLS, NULL, 0) > lines[part])
                        fail_msg("%s: lesson %d {4,%d} part %d does not fit: '%s'",
                                 hol_lang_code(l), n, q, part, len > 0 ? s : "");
                    int missing = 0;
                    hol_face_units(s, strlen(s), &missing);
                    assert_int_equal(missing, 0);
                }
                hol_app_question qn;
                assert_int_equal(hol_lesson_question(&f, l, &qn), HOL_OK);
                const char *c;
                for (int k = 0; (c = hol_lesson_label(&f, l, k)); k++)
                    if (strlen(c) > 20)
                        fail_msg("%s: lesson %d's label '%s' is over 20 bytes", hol_lang_code(l),
                                 n, c);
            }
    }
}

/* 1: the device's button words are the string table's (actions,
 * gestures, the page's on-screen buttons), not names printed on them. */
static int said_device(uint32_t d)
{
    return d == HOL_DEVICE_NONE || d == HOL_DEVICE_WEBXR_HAND || d == HOL_DEVICE_XR_HAND ||
           d == HOL_DEVICE_SCREEN;
}

/* The seated line and a device's buttons in every language: a device
 * with named controls keeps their names; HOL_DEVICE_NONE's actions, the
 * hands' gestures, the touch screen's buttons and the seated line are the
 * table's, English as before the table. */
static void test_seated_and_buttons(void **state)
{
    (void)state;
    assert_string_equal(hol_prompt_seated(HOL_DEVICE_KEYBOARD, HOL_LANG_EN),
                        "SEATED: W/A/S/D OR UP/DOWN: ONE STEP");
    assert_string_equal(hol_prompt_seated(HOL_DEVICE_XR_HAND, HOL_LANG_EN),
                        "SEATED: PINCH AND FLICK: ONE STEP");
    assert_string_equal(hol_prompt_seated(HOL_DEVICE_NONE, HOL_LANG_DE),
                        "SITZEND: WISCHEN ODER PFEILE: EIN SCHRITT");
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (uint32_t d = 0; d < HOL_DEVICE_COUNT; d++) {
            const char *s = hol_prompt_seated(d, l);
            assert_true(s[0] && strlen(s) < HOL_APP_TEXT_MAX);
            for (int k = 0; k < 8; k++) {
                const char *en = hol_prompt_button(d, 1u << k), *w = hol_prompt_button_in(d, 1u << k, l);
                assert_true(!en == !w);
                if (en && (!said_device(d) || l == HOL_LANG_EN))
                    assert_string_equal(en, w);
            }
        }
    assert_string_equal(hol_prompt_button_in(HOL_DEVICE_NONE, HOL_BTN_CONFIRM, HOL_LANG_DE),
                        "BESTÄTIGEN");
}

/* The touch screen (the web page's on-screen buttons: OK, Back, Menu, Map,
 * the arrows) and the hands' gestures, in every language: the words the
 * pupil sees on the page and the gestures' English bytes as before the
 * table; the other languages have words of their own. */
static void test_touch_and_hand_words(void **state)
{
    (void)state;
    static const struct {
        uint32_t device, btn;
        const char *en, *de, *nl;
    } want[] = {
        {HOL_DEVICE_SCREEN, HOL_BTN_CONFIRM, "OK", "OK", "OK"},
        {HOL_DEVICE_SCREEN, HOL_BTN_BACK, "BACK", "ZURÜCK", "TERUG"},
        {HOL_DEVICE_SCREEN, HOL_BTN_MENU, "MENU", "MENÜ", "MENU"},
        {HOL_DEVICE_SCREEN, HOL_BTN_MINIMAP, "MAP", "KARTE", "KAART"},
        {HOL_DEVICE_WEBXR_HAND, HOL_BTN_CONFIRM, "PINCH", "KNIFF", "KNEEP"},
        {HOL_DEVICE_WEBXR_HAND, HOL_BTN_BACK, "LONG PINCH", "KNIFF LANG", "LANGE KNEEP"},
        {HOL_DEVICE_WEBXR_HAND, HOL_BTN_MENU, "LEFT PINCH", "KNIFF LINKS", "LINKER KNEEP"},
        {HOL_DEVICE_XR_HAND, HOL_BTN_RECENTRE, "LEFT GRASP", "GRIFF LINKS", "LINKER GREEP"},
        {HOL_DEVICE_XR_HAND, HOL_BTN_QUIT, "GRASP", "GRIFF", "GREEP"},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        assert_string_equal(hol_prompt_button(want[i].device, want[i].btn), want[i].en);
        assert_string_equal(hol_prompt_button_in(want[i].device, want[i].btn, HOL_LANG_EN),
                            want[i].en);
        assert_string_equal(hol_prompt_button_in(want[i].device, want[i].btn, HOL_LANG_DE),
                            want[i].de);
        assert_string_equal(hol_prompt_button_in(want[i].device, want[i].btn, HOL_LANG_NL),
                            want[i].nl);
    }
    /* the page has no restart, quit nor recentre button (Back quits in
     * the menu); the touch stick walks, the arrows step seated */
    assert_null(hol_prompt_button(HOL_DEVICE_SCREEN, HOL_BTN_RESTART));
    assert_null(hol_prompt_button(HOL_DEVICE_SCREEN, HOL_BTN_QUIT));
    assert_null(hol_prompt_button(HOL_DEVICE_SCREEN, HOL_BTN_RECENTRE));
    assert_string_equal(hol_prompt_move(HOL_DEVICE_SCREEN, HOL_LANG_EN),
                        "SWIPE LEFT HALF: WALK, RIGHT HALF: TURN");
    assert_string_equal(hol_prompt_seated(HOL_DEVICE_SCREEN, HOL_LANG_DE),
                        "SITZEND: WISCHEN ODER PFEILE: EIN SCHRITT");
    /* a page's word and the prompt's name the same button */
    static const hol_str_id page[4] = {HOL_S_PAGE_OK, HOL_S_PAGE_BACK, HOL_S_PAGE_MENU,
                                       HOL_S_PAGE_MAP};
    static const uint32_t btn[4] = {HOL_BTN_CONFIRM, HOL_BTN_BACK, HOL_BTN_MENU, HOL_BTN_MINIMAP};
    for (int l = 0; l < HOL_LANG_COUNT; l++)
        for (int i = 0; i < 4; i++) {
            const char *p = hol_str(l, page[i]), *w = hol_prompt_button_in(HOL_DEVICE_SCREEN, btn[i], l);
            assert_int_equal(strlen(p), strlen(w));
            for (size_t k = 0; p[k]; k++) /* upper case: ASCII, and Ü's second byte */
                assert_true(p[k] == w[k] || (p[k] >= 'a' && p[k] <= 'z' && p[k] - 32 == w[k]) ||
                            ((unsigned char)p[k] == 0xbc && (unsigned char)w[k] == 0x9c));
        }
}

/* A label of an item (a choice, an anchor) within the 20 bytes its value
 * shows; an item's text within its 3 lines. */
static void item_fits(const hol_app_question *q, int l)
{
    if (strlen(q->text) >= HOL_APP_QTEXT_MAX - 1 ||
        hol_app_wrap(q->text, HOL_APP_SCREEN_COLS, NULL, 0) > 3)
        fail_msg("%s: '%s' is over its 3 lines", hol_lang_code(l), q->text);
    int missing = 0;
    hol_face_units(q->text, strlen(q->text), &missing);
    assert_int_equal(missing, 0);
    const char *label[2 + HOL_APP_MAX_CHOICES] = {q->low, q->high};
    for (int c = 0; c < q->nchoices; c++)
        label[2 + c] = q->choices[c];
    for (int c = 0; c < 2 + q->nchoices; c++)
        if (label[c] && strlen(label[c]) > 20)
            fail_msg("%s: label '%s' is over 20 bytes", hol_lang_code(l), label[c]);
}

/* The class test's items and the presets' (SSQ, TLX) in every language:
 * the English item as the level has always held it, the others its
 * translation (the same id, kind, scale, choices' count and right
 * answer), each fitting where the app shows it; the names shown. */
static void test_items_said(void **state)
{
    (void)state;
    hol_quiz_item en, it;
    assert_int_equal(hol_quiz_item_of(HOL_QUIZ_PRE, 0, 5, &en), HOL_OK);
    assert_string_equal(en.question.text, "Walk N, E, S, W. Are you back on your start tile?");
    assert_string_equal(en.question.choices[1], "No");
    assert_string_equal(en.right, "No");
    assert_int_equal(hol_quiz_item_in(HOL_QUIZ_PRE, 0, 5, HOL_LANG_DE, &it), HOL_OK);
    assert_string_equal(it.question.text, "Geh N, O, S, W. Stehst du wieder auf deiner Startkachel?");
    assert_string_equal(it.question.choices[1], "Nein");
    assert_string_equal(it.right, "No"); /* the logs' */
    for (int l = 0; l < HOL_LANG_COUNT; l++) {
        assert_true(strlen(hol_str(l, HOL_S_PRETEST)) <= 12);
        assert_true(strlen(hol_str(l, HOL_S_POSTTEST)) <= 12);
        for (int ph = 0; ph < 2; ph++)
            for (int k = 0; k < HOL_QUIZ_ITEMS; k++)
                for (int q = 4; q <= 8; q++) {
                    assert_int_equal(hol_quiz_item_of(ph, k, q, &en), HOL_OK);
                    assert_int_equal(hol_quiz_item_in(ph, k, q, l, &it), HOL_OK);
                    assert_string_equal(it.question.id, en.question.id);
                    assert_string_equal(it.right, en.right);
                    assert_int_equal(it.question.kind, en.question.kind);
                    assert_int_equal(it.question.nchoices, en.question.nchoices);
                    assert_int_equal(it.question.hi, en.question.hi);
                    item_fits(&it.question, l);
                }
        for (int i = 0; i < hol_ask_npresets(); i++) {
            const hol_ask_preset_def *p = hol_ask_preset_at(i);
            hol_app_question a[HOL_ASK_PRESET_ITEMS], b;
            assert_int_equal(hol_ask_preset(p->name, strlen(p->name), a, HOL_ASK_PRESET_ITEMS),
                             p->nitems);
            for (int k = 0; k < p->nitems; k++) {
                assert_int_equal(hol_ask_preset_item_in(p, k, l, &b), HOL_OK);
                assert_string_equal(b.id, a[k].id);
                assert_int_equal(b.lo, a[k].lo);
                assert_int_equal(b.hi, a[k].hi);
                assert_int_equal(b.step, a[k].step);
                if (l == HOL_LANG_EN)
                    assert_memory_equal(&a[k], &b, sizeof b);
                else if (!strcmp(b.text, a[k].text))
                    fail_msg("%s: %s's %s is not said", hol_lang_code(l), p->name, b.id);
                item_fits(&b, l);
            }
        }
    }
    hol_app_question b;
    assert_int_equal(hol_ask_preset_item_in(hol_ask_preset_at(1), 3, HOL_LANG_DE, &b), HOL_OK);
    assert_string_equal(b.low, "Perfekt");
    assert_int_equal(hol_ask_preset_item_in(hol_ask_preset_at(1), 6, HOL_LANG_DE, &b), HOL_EARG);
}

static void test_tags(void **state)
{
    (void)state;
    assert_int_equal(hol_lang_parse("en"), HOL_LANG_EN);
    assert_int_equal(hol_lang_parse("de"), HOL_LANG_DE);
    assert_int_equal(hol_lang_parse("nl"), HOL_LANG_NL);
    assert_int_equal(hol_lang_parse("de-DE"), HOL_LANG_DE);
    assert_int_equal(hol_lang_parse("DE_at"), HOL_LANG_DE);
    assert_int_equal(hol_lang_parse("en-GB"), HOL_LANG_EN);
    assert_int_equal(hol_lang_parse("nl-BE"), HOL_LANG_NL);
    assert_int_equal(hol_lang_parse("fr"), -1);
    assert_int_equal(hol_lang_parse("d"), -1);
    assert_int_equal(hol_lang_parse(""), -1);
    assert_int_equal(hol_lang_parse("deu"), -1);
    assert_int_equal(hol_lang_parse(NULL), -1);
    assert_string_equal(hol_lang_code(HOL_LANG_DE), "de");
    assert_string_equal(hol_lang_code(99), "en");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_complete_and_drawn),
        cmocka_unit_test(test_formats_match),
        cmocka_unit_test(test_fits),
        cmocka_unit_test(test_prompts_fit),
        cmocka_unit_test(test_lessons_complete),
        cmocka_unit_test(test_lessons_fit),
        cmocka_unit_test(test_seated_and_buttons),
        cmocka_unit_test(test_touch_and_hand_words),
        cmocka_unit_test(test_items_said),
        cmocka_unit_test(test_tags),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
