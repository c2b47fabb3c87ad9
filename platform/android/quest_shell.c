/* quest_shell.c - the Quest app on a quest_host (see quest_shell.h): the
 * session under the OpenXR layer, files through the POSIX sink, sound
 * through the platform's player (platform/audio: OpenAL Soft), every
 * message through logcat. The session is made once the headset knows its
 * play area (quest_fit): the campaign plays the room and cell size the
 * stage bounds hold (core/hol_fit.h), as `holonomy xr` does. */
#include "quest_shell.h"

#include <android/log.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "../../core/hol_campaign.h"
#include "../../core/hol_session.h"
#include "../audio/hol_audio.h"
#include "../file/hol_sink_posix.h"
#include "../openxr/hol_xr.h"
#include "../shell/hol_shell_prov.h"

typedef struct quest {
    const quest_host *host;
    hol_session *session;
    hol_level levels[HOL_CAMPAIGN_LEVELS];
    hol_sink_posix logs, recs;
    int resumed;
    int focused; /* the OpenXR session is FOCUSED (quest_focus) */
    int destroy;
    int sound_due; /* 1: open the sound at the next step */
    hol_audio_feed sound;
} quest;

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void quest_log(int prio, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    __android_log_vprint(prio, "holonomy", fmt, ap);
    va_end(ap);
}

/* The sound, as `holonomy xr` plays it (platform/audio's feed): opened at
 * the first step (the session is up), then core's list each step; held
 * unless the session is FOCUSED and the activity resumed. */
static void quest_sound(quest *q)
{
    if (q->sound_due) {
        q->sound_due = 0;
        char msg[160];
        if (hol_audio_feed_open(&q->sound, 1.0, msg, sizeof msg))
            quest_log(ANDROID_LOG_WARN, "sound off: %s", msg);
        else
            quest_log(ANDROID_LOG_INFO, "sound: OpenAL Soft%s",
                      hol_audio_hrtf(q->sound.au) ? ", HRTF" : "");
    }
    hol_audio_feed_step(&q->sound, hol_session_app(q->session));
}

static void quest_hold(quest *q)
{
    hol_audio_feed_hold(&q->sound, !(q->focused && q->resumed));
}

static void quest_focus(void *user, int focused)
{
    quest *q = user;
    q->focused = focused;
    quest_hold(q);
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
    if (err) {
        quest_log(ANDROID_LOG_ERROR, "%s", hol_session_message(q->session));
        return -1;
    }
    quest_sound(q);
    return over;
}

static struct hol_world *quest_world(void *user)
{
    return hol_app_world(hol_session_app(((quest *)user)->session));
}

static int quest_level_started(void *user)
{
    return hol_app_get_events(hol_session_app(((quest *)user)->session))->level_started;
}

static const hol_app_view *quest_view(void *user)
{
    quest *q = user;
    return q->session ? hol_app_get_view(hol_session_app(q->session)) : NULL;
}

static int quest_poll(void *user)
{
    quest *q = user;
    q->destroy |= q->host->poll(q->host->user, &q->resumed) != 0;
    quest_hold(q); /* onPause: held at once, whether frames run or not */
    return q->destroy;
}

/* The two folders in FILES (logs, recordings) and their sinks. 0 ok. */
static int quest_folders(quest *q, const char *files)
{
    char logs[4096], recs[4096];
    snprintf(logs, sizeof logs, "%s/logs", files);
    snprintf(recs, sizeof recs, "%s/recordings", files);
    if (hol_sink_posix_make_dir(logs) || hol_sink_posix_make_dir(recs) ||
        hol_sink_posix_init(&q->logs, logs) || hol_sink_posix_init(&q->recs, recs))
        return 1;
    quest_log(ANDROID_LOG_INFO, "logs in %s, recordings in %s", logs, recs);
    return 0;
}

/* The default campaign and the folders for its logs and recording in the
 * app's files directory (the external one, else the internal). 0 ok. */
static int quest_prepare(quest *q)
{
    const char *ext = q->host->files_dir, *in = q->host->internal_dir;
    if (hol_campaign_default(1, NULL, q->levels)) {
        quest_log(ANDROID_LOG_ERROR, "cannot make the default campaign");
        return 1;
    }
    if ((!ext || quest_folders(q, ext)) && (!in || quest_folders(q, in))) {
        quest_log(ANDROID_LOG_ERROR, "cannot make the logs and recordings folders in %s or %s",
                  ext ? ext : "(no external files directory)", in ? in : "(none)");
        return 1;
    }
    return 0;
}

/* The play area's fit (hol_xr_app_fns.fit; NULL: no bounds): told, played
 * in the campaign's levels, then the session made. 0 ok. */
static int quest_fit(void *user, const hol_fit *f)
{
    quest *q = user;
    if (f) {
        char line[160];
        hol_fit_text(f, -1, line, sizeof line);
        quest_log(ANDROID_LOG_INFO, "%s", line);
        for (int i = 0; i < HOL_CAMPAIGN_LEVELS; i++) {
            int changed = 0;
            hol_err e = hol_fit_level(&q->levels[i], f, &changed);
            if (e)
                quest_log(ANDROID_LOG_WARN, "level %s keeps its room: the fitted one refuses "
                                            "it (%s)", q->levels[i].name, hol_err_str(e));
        }
    }
    hol_session_desc d;
    memset(&d, 0, sizeof d);
    d.levels = q->levels;
    d.nlevels = HOL_CAMPAIGN_LEVELS;
    d.log = &q->logs.sink;
    d.append = 1;
    d.rec = &q->recs.sink;
    hol_sink_posix_meta(&d.meta, NULL);
    char rec_name[96], msg[256];
    snprintf(rec_name, sizeof rec_name, "%s.rec", d.meta.session);
    d.rec_name = rec_name;
    if (hol_session_create(&d, &q->session, msg, sizeof msg)) {
        quest_log(ANDROID_LOG_ERROR, "%s", msg);
        return 1;
    }
    /* provenance.csv and codebook.csv, as every platform's log folder */
    const char *bad = hol_shell_prov_write(d.log, &d.meta, NULL);
    if (bad)
        quest_log(ANDROID_LOG_WARN, "cannot write the log folder's %s", bad);
    return 0;
}

int quest_run(const quest_host *host)
{
    static quest q; /* the sinks' paths are large */
    memset(&q, 0, sizeof q);
    for (int i = 0; i < HOL_SINK_MAX_OPEN; i++) /* nothing open: fini closes nothing */
        q.logs.fd[i] = q.recs.fd[i] = -1;
    q.host = host;
    q.resumed = 1;
    q.sound_due = 1;
    q.sound.held = 1; /* until the session is FOCUSED */
    int rc = 1;
    if (quest_prepare(&q) == 0) {
        hol_xr_desc d;
        memset(&d, 0, sizeof d);
        d.check_frame = -1;
        d.android_vm = host->vm;
        d.android_activity = host->activity;
        hol_xr_app_fns fns = {.user = &q, .step = quest_step, .world = quest_world,
                              .level_started = quest_level_started, .poll_platform = quest_poll,
                              .fit = quest_fit, .view = quest_view, .focus = quest_focus};
        rc = hol_xr_run(&d, &fns);
        hol_err e = !q.session ? HOL_OK
                    : q.destroy ? hol_session_abort(q.session)
                                : hol_session_finish(q.session);
        if (e) {
            quest_log(ANDROID_LOG_ERROR, "%s", hol_session_message(q.session));
            rc = 1;
        }
        hol_audio_feed_close(&q.sound);
        hol_session_destroy(q.session);
    }
    hol_sink_posix_fini(&q.logs);
    hol_sink_posix_fini(&q.recs);
    return rc;
}
