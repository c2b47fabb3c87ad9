/* hol_audio.h - the sound player (issue 27): carries out core's sound list
 * (core/hol_sound.h) with OpenAL Soft; decides nothing.
 *
 * Contract
 * - OpenAL Soft is loaded at run time (dlopen of libopenal.so.1), so the
 *   binary runs where it is missing (the xr-test chroot, a machine without
 *   it): hol_audio_open then fails with a message and the caller goes on
 *   silent (play and xr say so in one warning line).
 * - The Quest build (__ANDROID__): the same player linked against the
 *   APK's libopenal.so (OpenAL Soft for Android, its OpenSL ES backend,
 *   built by platform/android/build_apk.sh); no dlopen, so the library is
 *   NEEDED by libholonomy.so (`make quest-link-check` checks it).
 * - Buffers: one per hol_sound_kind, synthesised by hol_sound_synth at
 *   HOL_SOUND_RATE, mono 16-bit.
 * - Voices: HOL_SOUND_MAX_SOURCES looping voices follow the list's ids
 *   (a source keeps its voice while it stays in the list, and stops when
 *   it leaves); HOL_SOUND_MAX_SHOTS voices play the shots in turn. Every
 *   voice is AL_SOURCE_RELATIVE with the listener at the origin, placed at
 *   core's direction (a unit vector, head frame), rolloff 0 and the
 *   distance model AL_NONE: core's gain times the volume is THE gain.
 * - A device (play, xr): the default output, with HRTF asked for where
 *   ALC_SOFT_HRTF is offered. Loopback (replay --wav): ALC_SOFT_loopback,
 *   stereo at 48 kHz rendered as float and rounded here to 16-bit PCM
 *   (OpenAL Soft's own 16-bit output is dithered: silence would not be
 *   zeros), HRTF off, so the channels are the left and right of the
 *   head, panned here by the equal-power law: each voice is two sources,
 *   hard left and hard right, with gains cos and sin of pi/4 + t/2 (t the
 *   lateral angle, asin of the direction's part to the right; OpenAL
 *   Soft's own stereo pan is far harder: 95 % of the power in one ear at
 *   30 degrees); rendering only when asked (hol_audio_render), so the same
 *   calls give the same samples.
 * - The web build (__EMSCRIPTEN__): the same player linked against
 *   emscripten's OpenAL (-lopenal, on WebAudio): a device is an
 *   AudioContext; its ALC_SOFT_HRTF sets the panners' model to WebAudio's
 *   'HRTF'; no loopback.
 * - Not thread safe; one player per process (OpenAL's current context).
 */
#ifndef HOL_AUDIO_H
#define HOL_AUDIO_H

#include <stddef.h>
#include <stdint.h>

#include "../../core/hol_sound.h"

typedef struct hol_audio hol_audio;

/* loopback 1: the offline renderer; volume 0..1. 0 ok, else -1 with msg. */
int hol_audio_open(int loopback, double volume, hol_audio **out, char *msg, size_t cap);
/* Carry out this frame's list (loops followed, shots started). */
void hol_audio_apply(hol_audio *a, const hol_sound_list *l);
/* Loopback only: render n stereo frames (2n int16) into out. 0 ok. */
int hol_audio_render(hol_audio *a, int16_t *out, int n);
/* The looping voices playing now (0..HOL_SOUND_MAX_SOURCES); 0 for NULL. */
int hol_audio_active(const hol_audio *a);
/* 1 when HRTF is in use. */
int hol_audio_hrtf(const hol_audio *a);
/* Hold the sound (on 1: the app lost the focus, the activity paused) or
 * let it go on (on 0); idempotent, NULL ok. Held: every voice stops (the
 * loops are released: the first hol_audio_apply after on 0 starts them
 * again), the output device pauses where OpenAL offers
 * ALC_SOFT_pause_device (OpenAL Soft: its backend's stream stops; not the
 * web's, nor a loopback device), and hol_audio_apply does nothing. */
void hol_audio_pause(hol_audio *a, int on);
int hol_audio_paused(const hol_audio *a); /* 1 while held; 0 for NULL */
void hol_audio_close(hol_audio *a); /* NULL ok */

/* One listener fed by one app frame by frame: what play, xr and the Quest
 * do (the platform decides when to open it and when to hold it; the feed
 * carries out core's list). A zeroed struct is a closed, unheld feed. */
typedef struct hol_audio_feed {
    hol_audio *au; /* NULL: silent */
    hol_sound snd;
    hol_sound_list sl;
    int held;      /* hol_audio_feed_hold's last word, kept across the open */
} hol_audio_feed;

/* The default output device (hol_audio_open(0, volume)); held at once if
 * the feed is held. 0 ok, else -1 with msg (the feed stays silent). */
int hol_audio_feed_open(hol_audio_feed *f, double volume, char *msg, size_t cap);
/* This frame: core's list (hol_sound_update) from app's view, events and
 * world, carried out (hol_audio_apply; nothing plays while held). Silent
 * feed or NULL app: nothing. The app's captions of the sound
 * (hol_app_set_captions) are on while the feed is open, off while it is
 * silent: from the next step on, the HUD names the cue the sound plays. */
void hol_audio_feed_step(hol_audio_feed *f, hol_app *app);
/* Hold (1) or go on (0): hol_audio_pause, remembered for a later open. */
void hol_audio_feed_hold(hol_audio_feed *f, int held);
void hol_audio_feed_close(hol_audio_feed *f); /* then silent; may open again */

#endif
