/* android_main.c - the Quest app's NativeActivity entry: a thin shell.
 *
 * Everything it calls is compiled and tested on the desktop: the app step
 * (core/hol_app.h), the renderer, and the OpenXR layer (platform/openxr/
 * hol_xr.h, whose Android branch creates the EGL context, initialises the
 * loader with the VM and the activity, and binds XR_KHR_opengl_es_enable).
 * This file only maps the activity's lifecycle onto the session and starts
 * the default campaign's first level:
 * - APP_CMD_RESUME / APP_CMD_PAUSE: the looper is polled without waiting
 *   while resumed, and the game is paused (no HOL_INPUT_FOCUSED) while the
 *   activity is paused, whatever the session says;
 * - APP_CMD_DESTROY (or destroyRequested): the session exits properly
 *   (xrRequestExitSession, STOPPING, EXITING) and the activity finishes.
 * It is compiled only by `make quest` with the NDK (native_app_glue comes
 * from the NDK); this machine has no NDK, so it has never been compiled
 * here (README "Quest build").
 */
#include <android/log.h>
#include <android_native_app_glue.h>
#include <string.h>

#include "../../core/hol_app.h"
#include "../openxr/hol_xr.h"

typedef struct quest {
    struct android_app *android;
    hol_app *game;
    int resumed;
    int destroy;
} quest;

static void quest_on_cmd(struct android_app *a, int32_t cmd)
{
    quest *q = a->userData;
    if (cmd == APP_CMD_RESUME)
        q->resumed = 1;
    else if (cmd == APP_CMD_PAUSE)
        q->resumed = 0;
    else if (cmd == APP_CMD_DESTROY)
        q->destroy = 1;
}

static int quest_poll(void *user)
{
    quest *q = user;
    int events = 0;
    struct android_poll_source *src = NULL;
    while (ALooper_pollOnce(q->resumed ? 0 : 10, NULL, &events, (void **)&src) >= 0) {
        if (src)
            src->process(q->android, src);
        if (q->android->destroyRequested)
            return 1;
        if (q->resumed)
            break;
    }
    return q->destroy;
}

static int quest_step(void *user, const hol_input *in, const hol_app_view **out_view)
{
    quest *q = user;
    hol_input i2 = *in;
    if (!q->resumed)
        i2.flags &= ~HOL_INPUT_FOCUSED;
    hol_err err = hol_app_step(q->game, &i2);
    *out_view = hol_app_get_view(q->game);
    if (err)
        return -1;
    return (*out_view)->state == HOL_APP_QUIT;
}

static struct hol_world *quest_world(void *user)
{
    return hol_app_world(((quest *)user)->game);
}

static int quest_level_started(void *user)
{
    return hol_app_get_events(((quest *)user)->game)->level_started;
}

void android_main(struct android_app *a)
{
    quest q;
    memset(&q, 0, sizeof q);
    q.android = a;
    a->userData = &q;
    a->onAppCmd = quest_on_cmd;
    hol_app_desc ad;
    memset(&ad, 0, sizeof ad);
    if (hol_app_create(&ad, &q.game)) {
        __android_log_print(ANDROID_LOG_ERROR, "holonomy", "cannot create the app");
        ANativeActivity_finish(a->activity);
        return;
    }
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.mode = HOL_APP_TUTORIAL;
    L.seed = 1;
    L.cues = HOL_CUE_ALL;
    if (hol_app_start_level(q.game, &L) == HOL_OK) {
        hol_xr_desc d;
        memset(&d, 0, sizeof d);
        d.check_frame = -1;
        d.android_vm = a->activity->vm;
        d.android_activity = a->activity->clazz;
        hol_xr_app_fns fns = {.user = &q, .step = quest_step, .world = quest_world,
                              .level_started = quest_level_started, .poll_platform = quest_poll};
        if (hol_xr_run(&d, &fns))
            __android_log_print(ANDROID_LOG_ERROR, "holonomy", "the OpenXR session failed");
    }
    hol_app_destroy(q.game);
    ANativeActivity_finish(a->activity);
}
