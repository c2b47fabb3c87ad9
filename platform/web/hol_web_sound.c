/* hol_web_sound.c - the web build's sound (issue 27): core's sound list
 * (core/hol_sound.h) played by the platform's player (platform/audio,
 * its OpenAL calls carried out on WebAudio by hol_web_al.js).
 *
 * A browser lets an AudioContext run only after a user gesture, so the
 * player opens at the first step after one (a click, a key, a touch, Enter
 * VR: hol_web_lib.js watches for it); ?sound=0 mutes (no AudioContext).
 * When the session is over, the loops stop.
 */
#include <emscripten.h>
#include <stdio.h>
#include <string.h>

#include "../audio/hol_audio.h"
#include "hol_web.h"

extern int hol_web_js_gesture(void);
extern void hol_web_js_config(const char *key, char *buf, int cap);

static struct {
    int want;      /* 1: play once a gesture was seen; 0 muted or failed */
    hol_audio_feed feed; /* its au NULL: not open */
} g;

int hol_web_sound_config(void)
{
    char s[8];
    hol_web_js_config("sound", s, sizeof s);
    if (s[0] && strcmp(s, "0") && strcmp(s, "1"))
        return -1;
    g.want = strcmp(s, "0") != 0;
    return 0;
}

void hol_web_sound_step(int over)
{
    hol_app *app = hol_web_game_app();
    if (!app)
        return;
    if (over) {
        hol_audio_feed_hold(&g.feed, 1); /* the loops stop */
        g.want = 0;
        return;
    }
    if (!g.feed.au) {
        if (!g.want || !hol_web_js_gesture())
            return;
        char msg[160];
        if (hol_audio_feed_open(&g.feed, 1.0, msg, sizeof msg)) {
            g.want = 0;
            printf("web: sound off: %s\n", msg);
            return;
        }
        printf("web: sound: OpenAL on WebAudio%s\n", hol_audio_hrtf(g.feed.au) ? ", HRTF" : "");
    }
    hol_audio_feed_step(&g.feed, app);
}

int hol_web_sound_active(void)
{
    return hol_audio_active(g.feed.au);
}
