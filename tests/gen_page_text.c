/* gen_page_text.c - the web page's words as a script (build/web/text.js):
 * core/hol_str.h's page strings (HOL_S_PAGE_*) in every language, so the
 * page (platform/web/page.js) shows them from the first paint, before the
 * game's wasm is loaded, from the one table. Non-ASCII as \uXXXX escapes
 * (the script reads the same whatever its encoding is taken to be). No
 * comment in it: every byte is the page's transfer (docs/web.md).
 * Usage: gen_page_text [LANG...] > text.js: the languages named (en de
 * nl; none: every one), English always (the page's fallback).
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "../core/hol_face.h"
#include "../core/hol_str.h"

/* page.js's key of each page string */
static const struct {
    const char *key;
    hol_str_id id;
} page[] = {
    {"loading", HOL_S_PAGE_LOADING},       {"ok", HOL_S_PAGE_OK},
    {"back", HOL_S_PAGE_BACK},             {"menu", HOL_S_PAGE_MENU},
    {"map", HOL_S_PAGE_MAP},               {"vrEnter", HOL_S_PAGE_VR_ENTER},
    {"vrExit", HOL_S_PAGE_VR_EXIT},        {"vrHttps", HOL_S_PAGE_VR_HTTPS},
    {"vrHttpsWhy", HOL_S_PAGE_VR_HTTPS_WHY}, {"vrNone", HOL_S_PAGE_VR_NONE},
    {"vrNoneWhy", HOL_S_PAGE_VR_NONE_WHY}, {"vrNoHeadset", HOL_S_PAGE_VR_NO_HEADSET},
    {"vrNoHeadsetWhy", HOL_S_PAGE_VR_NO_HEADSET_WHY}, {"again", HOL_S_PAGE_AGAIN},
    {"fit", HOL_S_PAGE_FIT},               {"file", HOL_S_PAGE_FILE},
    {"fileWhy", HOL_S_PAGE_FILE_WHY},      {"logs", HOL_S_PAGE_LOGS},
    {"help", HOL_S_PAGE_HELP},             {"noLogs", HOL_S_PAGE_NO_LOGS},
    {"clear", HOL_S_PAGE_CLEAR},           {"clearAsk", HOL_S_PAGE_CLEAR_ASK},
    {"bytes", HOL_S_PAGE_BYTES},           {"playing", HOL_S_PAGE_PLAYING},
    {"playingLevel", HOL_S_PAGE_PLAYING_LEVEL}, {"inVR", HOL_S_PAGE_IN_VR},
    {"paused", HOL_S_PAGE_PAUSED},         {"over", HOL_S_PAGE_OVER},
    {"failed", HOL_S_PAGE_FAILED},         {"warning", HOL_S_PAGE_WARNING},
    {"vrFailed", HOL_S_PAGE_VR_FAILED},    {"noStudy", HOL_S_PAGE_NO_STUDY},
    {"noLevel", HOL_S_PAGE_NO_LEVEL},      {"noGame", HOL_S_PAGE_NO_GAME},
    {"noStart", HOL_S_PAGE_NO_START},      {"lessons", HOL_S_PAGE_LESSONS},
    {"lessonsWhy", HOL_S_PAGE_LESSONS_WHY}, {"seated", HOL_S_PAGE_SEATED},
    {"seatedWhy", HOL_S_PAGE_SEATED_WHY},  {"send", HOL_S_PAGE_SEND},
    {"sent", HOL_S_PAGE_SENT},             {"sendFailed", HOL_S_PAGE_SEND_FAILED},
};

_Static_assert(sizeof page / sizeof page[0] == HOL_S_COUNT - HOL_S_PAGE_LOADING,
               "every page string has its key");

static void put(const char *s)
{
    putchar('"');
    size_t len = strlen(s), pos = 0;
    while (pos < len) {
        uint32_t c = hol_face_decode(s, len, &pos);
        if (c == '"' || c == '\\')
            printf("\\%c", (char)c);
        else if (c >= 0x20 && c < 0x7f)
            putchar((int)c);
        else
            printf("\\u%04x", (unsigned)c); /* the table's are below U+10000 */
    }
    putchar('"');
}

int main(int argc, char **argv)
{
    printf("window.holonomyText={");
    for (int l = 0; l < HOL_LANG_COUNT; l++) {
        int named = argc < 2 || l == HOL_LANG_EN;
        for (int a = 1; a < argc; a++)
            named |= hol_lang_parse(argv[a]) == l && !strcmp(argv[a], hol_lang_code(l));
        if (!named)
            continue;
        printf("%s\"%s\":{", l ? "," : "", hol_lang_code(l));
        for (size_t i = 0; i < sizeof page / sizeof page[0]; i++) {
            printf("%s\"%s\":", i ? "," : "", page[i].key);
            put(hol_str(l, page[i].id));
        }
        putchar('}');
    }
    printf("};\n");
    return 0;
}
