/* quest_shell.h - the Quest app, all of it but the NativeActivity glue:
 * what android_main.c (the NDK's native_app_glue entry) hands over, and
 * the shell that runs the headset session on it.
 *
 * Contract
 * - quest_run runs the app on the calling thread until the user quits, the
 *   activity is destroyed, or the session fails: the session every
 *   platform runs (core/hol_session.h: the default campaign, seed 1, as
 *   `holonomy xr` runs it) under the OpenXR layer (platform/openxr/hol_xr.h:
 *   it attaches the thread to the Java VM and initialises the Android
 *   loader before anything else). While the activity is paused the game is
 *   paused, whatever the OpenXR session says.
 * - Sound: as `holonomy xr` plays it (platform/audio/hol_audio.h's feed,
 *   OpenAL Soft linked: the APK's libopenal.so), opened at the first step;
 *   held while the OpenXR session is not FOCUSED (hol_xr_app_fns.focus)
 *   or the activity is paused (host->poll's *out_resumed 0: held at once,
 *   frames or not); a device that does not open is one logcat line, then
 *   silence.
 * - Files, through the POSIX sink (platform/file/hol_sink_posix.h), in the
 *   app's external files directory, which `adb pull` reaches
 *   (/sdcard/Android/data/org.holonomy.app/files), else its internal one:
 *   logs in FILES/logs (appended to from session to session, so an attempt
 *   the system killed is finished with end `killed` at the next start), the
 *   recording FILES/recordings/SESSION.rec (`holonomy replay` runs it on a
 *   desktop). The activity destroyed: the OpenXR session ends properly
 *   (xrRequestExitSession, STOPPING, EXITING) and the attempt in play is
 *   saved with end `aborted`; the app's own quit ends it as on the desktop.
 * - Every message goes to logcat (tag "holonomy"); nothing is printed to
 *   stdout or stderr, which Android discards.
 * - host->poll is called once per loop: it handles the activity's events,
 *   sets *out_resumed, and returns 1 once the activity is being destroyed.
 * - Built only into the APK; `make quest-link-check` compiles it for this
 *   machine with the Android branches on, against Debian's copies of the
 *   NDK's JNI and log headers, and links it.
 * - 0 ok, 1 failure (logged).
 */
#ifndef QUEST_SHELL_H
#define QUEST_SHELL_H

typedef struct quest_host {
    void *vm;              /* JavaVM * */
    void *activity;        /* the activity object (jobject) */
    const char *files_dir;    /* the app's external files directory, or NULL */
    const char *internal_dir; /* its internal files directory */
    int (*poll)(void *user, int *out_resumed);
    void *user;
} quest_host;

int quest_run(const quest_host *host);

#endif
