/* android_main.c - the Quest app's NativeActivity entry: a thin shell.
 *
 * Everything it calls is compiled and tested on the desktop: the session
 * (core/hol_session.h: the default campaign, the app step, the research
 * logs and the recording, as `holonomy play` and `holonomy xr` run it), its
 * POSIX sink (platform/file/hol_sink_posix.h), the renderer, and the OpenXR
 * layer (platform/openxr/hol_xr.h, whose Android branch creates the EGL
 * context, initialises the loader with the VM and the activity, and binds
 * XR_KHR_opengl_es_enable). This file maps the activity's lifecycle onto
 * the session:
 * - the default campaign (core/hol_campaign.h, seed 1), logs in the app's
 *   files directory, FILES/logs (appended to from session to session, so an
 *   attempt the system killed is finished with end `killed` at the next
 *   start), and the recording FILES/recordings/SESSION.rec (`holonomy
 *   replay` runs it on a desktop: adb pull the files);
 * - APP_CMD_RESUME / APP_CMD_PAUSE: the looper is polled without waiting
 *   while resumed, and the game is paused (no HOL_INPUT_FOCUSED) while the
 *   activity is paused, whatever the session says;
 * - APP_CMD_DESTROY (or destroyRequested): the OpenXR session exits properly
 *   (xrRequestExitSession, STOPPING, EXITING), the attempt in play is saved
 *   with end `aborted`, and the activity finishes; the app's own quit ends
 *   it as on the desktop.
 * It is compiled only by `make quest` with the NDK (native_app_glue comes
 * from the NDK); this machine has no NDK, so it has never been compiled
 * here (README "Quest build").
 */
#include <android/log.h>
#include <android_native_app_glue.h>
#include <stdio.h>
#include <string.h>

#include "../../core/hol_campaign.h"
#include "../../core/hol_session.h"
#include "../file/hol_sink_posix.h"
#include "../openxr/hol_xr.h"

typedef struct quest {
    struct android_app *android;
    hol_session *session;
    hol_sink_posix logs, recs;
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
            q->destroy = 1;
        if (q->destroy || q->resumed)
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
    int over = 0;
    hol_err err = hol_session_step(q->session, &i2, &over);
    *out_view = hol_app_get_view(hol_session_app(q->session));
    if (err)
        __android_log_print(ANDROID_LOG_ERROR, "holonomy", "%s",
                            hol_session_message(q->session));
    return err ? -1 : over;
}

static struct hol_world *quest_world(void *user)
{
    return hol_app_world(hol_session_app(((quest *)user)->session));
}

static int quest_level_started(void *user)
{
    return hol_app_get_events(hol_session_app(((quest *)user)->session))->level_started;
}

/* The session: the default campaign, logs and a recording in the app's
 * files directory. 0 ok. */
static int quest_session(quest *q, const char *files)
{
    static hol_level levels[HOL_CAMPAIGN_LEVELS];
    char logs[4096], recs[4096], msg[256];
    snprintf(logs, sizeof logs, "%s/logs", files);
    snprintf(recs, sizeof recs, "%s/recordings", files);
    if (hol_campaign_default(1, levels) || hol_sink_posix_make_dir(logs) ||
        hol_sink_posix_make_dir(recs) || hol_sink_posix_init(&q->logs, logs) ||
        hol_sink_posix_init(&q->recs, recs)) {
        __android_log_print(ANDROID_LOG_ERROR, "holonomy", "cannot make the folders in %s",
                            files);
        return 1;
    }
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = levels;
    d.nlevels = HOL_CAMPAIGN_LEVELS;
    d.log = &q->logs.sink;
    d.append = 1;
    d.rec = &q->recs.sink;
    hol_sink_posix_meta(&d.meta, NULL);
    char rec_name[96];
    snprintf(rec_name, sizeof rec_name, "%s.rec", d.meta.session);
    d.rec_name = rec_name;
    if (hol_session_create(&d, &q->session, msg, sizeof msg)) {
        __android_log_print(ANDROID_LOG_ERROR, "holonomy", "%s", msg);
        return 1;
    }
    return 0;
}

void android_main(struct android_app *a)
{
    static quest q;
    memset(&q, 0, sizeof q);
    q.android = a;
    a->userData = &q;
    a->onAppCmd = quest_on_cmd;
    if (quest_session(&q, a->activity->internalDataPath) == 0) {
        hol_xr_desc d;
        memset(&d, 0, sizeof d);
        d.check_frame = -1;
        d.android_vm = a->activity->vm;
        d.android_activity = a->activity->clazz;
        hol_xr_app_fns fns = {.user = &q, .step = quest_step, .world = quest_world,
                              .level_started = quest_level_started, .poll_platform = quest_poll};
        if (hol_xr_run(&d, &fns))
            __android_log_print(ANDROID_LOG_ERROR, "holonomy", "the OpenXR session failed");
        hol_err e = q.destroy ? hol_session_abort(q.session) : hol_session_finish(q.session);
        if (e)
            __android_log_print(ANDROID_LOG_ERROR, "holonomy", "%s",
                                hol_session_message(q.session));
        hol_session_destroy(q.session);
    }
    hol_sink_posix_fini(&q.logs);
    hol_sink_posix_fini(&q.recs);
    ANativeActivity_finish(a->activity);
}
