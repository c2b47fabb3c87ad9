/* android_main.c - the Quest app's NativeActivity entry, through the NDK's
 * native_app_glue: it maps the activity onto a quest_host (quest_shell.h)
 * and runs quest_run, then finishes the activity.
 * - APP_CMD_RESUME / APP_CMD_PAUSE: the looper is polled without waiting
 *   while resumed, and quest_run pauses the game and holds the sound while
 *   paused;
 * - APP_CMD_DESTROY (or destroyRequested): the session ends properly
 *   (xrRequestExitSession, STOPPING, EXITING) and the activity finishes.
 * This file and the glue are the only sources of the APK that need the
 * NDK's own headers (android_native_app_glue.h, which Debian does not
 * have), so they are the only ones `make quest-link-check` cannot compile
 * here; everything else is compiled and linked for this machine there.
 */
#include <android/log.h>
#include <android_native_app_glue.h>
#include <string.h>

#include "quest_shell.h"

typedef struct quest_glue {
    struct android_app *android;
    int resumed;
    int destroy;
} quest_glue;

static void quest_on_cmd(struct android_app *a, int32_t cmd)
{
    quest_glue *g = a->userData;
    if (cmd == APP_CMD_RESUME)
        g->resumed = 1;
    else if (cmd == APP_CMD_PAUSE)
        g->resumed = 0;
    else if (cmd == APP_CMD_DESTROY)
        g->destroy = 1;
}

static int quest_glue_poll(void *user, int *out_resumed)
{
    quest_glue *g = user;
    int events = 0;
    struct android_poll_source *src = NULL;
    while (ALooper_pollOnce(g->resumed ? 0 : 10, NULL, &events, (void **)&src) >= 0) {
        if (src)
            src->process(g->android, src);
        if (g->android->destroyRequested)
            g->destroy = 1;
        if (g->resumed || g->destroy)
            break;
    }
    *out_resumed = g->resumed;
    return g->destroy;
}

void android_main(struct android_app *a)
{
    quest_glue g;
    memset(&g, 0, sizeof g);
    g.android = a;
    a->userData = &g;
    a->onAppCmd = quest_on_cmd;
    ANativeActivity *act = a->activity;
    quest_host h;
    memset(&h, 0, sizeof h);
    h.vm = act->vm;
    h.activity = act->clazz;
    h.files_dir = act->externalDataPath;
    h.internal_dir = act->internalDataPath;
    h.poll = quest_glue_poll;
    h.user = &g;
    if (quest_run(&h))
        __android_log_print(ANDROID_LOG_ERROR, "holonomy", "Holonomy ended with a failure");
    ANativeActivity_finish(act);
}
