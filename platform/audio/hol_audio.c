/* hol_audio.c - OpenAL Soft player loaded at run time (see hol_audio.h);
 * in the Quest build (__ANDROID__) the same player linked against the
 * APK's libopenal.so (OpenAL Soft, built by build_apk.sh), and in the web
 * build (__EMSCRIPTEN__) on the OpenAL calls of platform/web/hol_web_al.js
 * (WebAudio, linked in): AUD_LINKED, no dlopen. */
#include "hol_audio.h"

#if defined(__EMSCRIPTEN__) || defined(__ANDROID__)
#define AUD_LINKED 1
#include <AL/al.h>
#include <AL/alc.h>
#else
#include <dlfcn.h>
#endif
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* OpenAL's types and the values used, as al.h, alc.h and alext.h define
 * them (the OpenAL 1.1 ABI and the ALC_SOFT_loopback and ALC_SOFT_HRTF
 * extensions): no header is needed at build time, so the tool builds where
 * libopenal-dev is missing (the xr-test chroot) and runs silent there. */
#ifndef AUD_LINKED
typedef struct ALCdevice ALCdevice;
typedef struct ALCcontext ALCcontext;
typedef char ALCchar, ALCboolean, ALboolean;
typedef int ALCint, ALCenum, ALCsizei, ALint, ALenum, ALsizei;
typedef unsigned int ALuint;
typedef float ALfloat;
typedef void ALvoid;
#define AL_NONE 0
#define AL_FALSE 0
#define AL_TRUE 1
#define AL_SOURCE_RELATIVE 0x202
#define AL_POSITION 0x1004
#define AL_LOOPING 0x1007
#define AL_BUFFER 0x1009
#define AL_GAIN 0x100A
#define AL_ROLLOFF_FACTOR 0x1021
#define AL_FORMAT_MONO16 0x1101
#define AL_NO_ERROR 0
#define ALC_FALSE 0
#define ALC_TRUE 1
#define ALC_FREQUENCY 0x1007
#endif
#define ALC_FORMAT_CHANNELS_SOFT 0x1990
#define ALC_FORMAT_TYPE_SOFT 0x1991
#define ALC_FLOAT_SOFT 0x1406
#define ALC_STEREO_SOFT 0x1501
#define ALC_HRTF_SOFT 0x1992
typedef ALCdevice *(*LPALCLOOPBACKOPENDEVICESOFT)(const ALCchar *);
typedef void (*LPALCRENDERSAMPLESSOFT)(ALCdevice *, void *, ALCsizei);
typedef void (*LPALCDEVICEPAUSESOFT)(ALCdevice *); /* ALC_SOFT_pause_device */

#define AUD_FUNCS(X)                                                                          \
    X(ALCdevice *, alcOpenDevice, (const ALCchar *))                                          \
    X(ALCboolean, alcCloseDevice, (ALCdevice *))                                              \
    X(ALCcontext *, alcCreateContext, (ALCdevice *, const ALCint *))                          \
    X(void, alcDestroyContext, (ALCcontext *))                                                \
    X(ALCboolean, alcMakeContextCurrent, (ALCcontext *))                                      \
    X(ALCboolean, alcIsExtensionPresent, (ALCdevice *, const ALCchar *))                      \
    X(void, alcGetIntegerv, (ALCdevice *, ALCenum, ALCsizei, ALCint *))                       \
    X(void, alGenBuffers, (ALsizei, ALuint *))                                                \
    X(void, alDeleteBuffers, (ALsizei, const ALuint *))                                       \
    X(void, alBufferData, (ALuint, ALenum, const ALvoid *, ALsizei, ALsizei))                 \
    X(void, alGenSources, (ALsizei, ALuint *))                                                \
    X(void, alDeleteSources, (ALsizei, const ALuint *))                                       \
    X(void, alSourcei, (ALuint, ALenum, ALint))                                               \
    X(void, alSourcef, (ALuint, ALenum, ALfloat))                                             \
    X(void, alSource3f, (ALuint, ALenum, ALfloat, ALfloat, ALfloat))                          \
    X(void, alSourcePlay, (ALuint))                                                           \
    X(void, alSourceStop, (ALuint))                                                           \
    X(void, alSourceRewind, (ALuint))                                                         \
    X(void, alDistanceModel, (ALenum))                                                        \
    X(ALenum, alGetError, (void))

/* the loopback device's extensions are looked up (not on the web: aud_load) */
#define AUD_GETPROC(X) X(void *, alcGetProcAddress, (ALCdevice *, const ALCchar *))

#define AUD_PTR(ret, name, args) ret(*name) args;

/* One voice: one OpenAL source, or (a->pair: HRTF off, the loopback
 * device) two, placed hard left and hard right with equal-power gains. */
typedef struct aud_chan {
    ALuint s[2];
} aud_chan;

typedef struct aud_voice {
    aud_chan src;
    uint32_t id;
    int used;
} aud_voice;

struct hol_audio {
    void *lib;
    struct {
        AUD_FUNCS(AUD_PTR)
        AUD_GETPROC(AUD_PTR)
    } f;
    LPALCLOOPBACKOPENDEVICESOFT loop_open;
    LPALCRENDERSAMPLESSOFT render;
    LPALCDEVICEPAUSESOFT dev_pause, dev_resume; /* NULL: not offered */
    ALCdevice *dev;
    ALCcontext *ctx;
    int loopback, hrtf, paused;
    int pair;      /* 1: each voice two sources, panned here (equal power) */
    double volume;
    ALuint buf[HOL_SND_KINDS];
    int nbuf;
    aud_voice loops[HOL_SOUND_MAX_SOURCES];
    aud_chan shots[HOL_SOUND_MAX_SHOTS];
    int nsrc, next_shot;
};

static int aud_fail(char *msg, size_t cap, const char *what)
{
    snprintf(msg, cap, "%s", what);
    return -1;
}

#ifdef AUD_LINKED
#ifdef __EMSCRIPTEN__
/* The web build has no loopback device, so nothing to look up; linking
 * alcGetProcAddress (emscripten's al.c) would bring all of emscripten's
 * OpenAL into the page. */
static void *aud_no_proc(ALCdevice *dev, const ALCchar *name)
{
    (void)dev, (void)name;
    return NULL;
}

#endif

/* the calls are linked in (Android: the APK's libopenal.so; the web:
 * platform/web/hol_web_al.js, on WebAudio) */
static int aud_load(hol_audio *a, char *msg, size_t cap)
{
    (void)msg, (void)cap;
#define AUD_SYM(ret, name, args) a->f.name = name;
    AUD_FUNCS(AUD_SYM)
#ifdef __EMSCRIPTEN__
    a->f.alcGetProcAddress = aud_no_proc;
#else
    AUD_GETPROC(AUD_SYM)
#endif
#undef AUD_SYM
    return 0;
}
#else
static int aud_load(hol_audio *a, char *msg, size_t cap)
{
    setenv("ALSOFT_LOGLEVEL", "0", 0); /* OpenAL Soft's own log off */
    a->lib = dlopen("libopenal.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!a->lib)
        return aud_fail(msg, cap, "OpenAL Soft (libopenal.so.1) is not installed");
#define AUD_SYM(ret, name, args)                                                              \
    *(void **)&a->f.name = dlsym(a->lib, #name);                                              \
    if (!a->f.name)                                                                           \
        return aud_fail(msg, cap, "libopenal.so.1 lacks " #name);
    AUD_FUNCS(AUD_SYM)
    AUD_GETPROC(AUD_SYM)
#undef AUD_SYM
    return 0;
}
#endif

static int aud_device(hol_audio *a, char *msg, size_t cap)
{
    if (a->loopback) {
        *(void **)&a->loop_open = a->f.alcGetProcAddress(NULL, "alcLoopbackOpenDeviceSOFT");
        *(void **)&a->render = a->f.alcGetProcAddress(NULL, "alcRenderSamplesSOFT");
        if (!a->f.alcIsExtensionPresent(NULL, "ALC_SOFT_loopback") || !a->loop_open || !a->render)
            return aud_fail(msg, cap, "OpenAL lacks ALC_SOFT_loopback");
        a->dev = a->loop_open(NULL);
        ALCint attrs[] = {ALC_FORMAT_CHANNELS_SOFT, ALC_STEREO_SOFT, ALC_FORMAT_TYPE_SOFT,
                          ALC_FLOAT_SOFT, ALC_FREQUENCY, HOL_SOUND_RATE, ALC_HRTF_SOFT, ALC_FALSE,
                          0};
        if (a->dev)
            a->ctx = a->f.alcCreateContext(a->dev, attrs);
    } else {
#ifdef __EMSCRIPTEN__
        a->dev = a->f.alcOpenDevice(NULL); /* an AudioContext */
#else
        /* ALSA and OpenAL Soft print their own lines when no device opens:
         * the caller's one warning says it, so theirs go to /dev/null */
        int saved = dup(2), null = open("/dev/null", O_WRONLY);
        if (saved >= 0 && null >= 0)
            dup2(null, 2);
        a->dev = a->f.alcOpenDevice(NULL);
        if (saved >= 0 && null >= 0)
            dup2(saved, 2);
        if (saved >= 0)
            close(saved);
        if (null >= 0)
            close(null);
#endif
        int has = a->dev && a->f.alcIsExtensionPresent(a->dev, "ALC_SOFT_HRTF");
        ALCint attrs[] = {ALC_HRTF_SOFT, ALC_TRUE, 0};
        if (a->dev)
            a->ctx = a->f.alcCreateContext(a->dev, has ? attrs : NULL);
        if (has && a->ctx) {
            ALCint st = 0;
            a->f.alcGetIntegerv(a->dev, ALC_HRTF_SOFT, 1, &st);
            a->hrtf = st == ALC_TRUE;
        }
    }
    if (!a->dev)
        return aud_fail(msg, cap, "no audio device opens");
    if (!a->ctx || !a->f.alcMakeContextCurrent(a->ctx))
        return aud_fail(msg, cap, "cannot make an OpenAL context");
    if (!a->loopback && a->f.alcIsExtensionPresent(a->dev, "ALC_SOFT_pause_device")) {
        *(void **)&a->dev_pause = a->f.alcGetProcAddress(a->dev, "alcDevicePauseSOFT");
        *(void **)&a->dev_resume = a->f.alcGetProcAddress(a->dev, "alcDeviceResumeSOFT");
        if (!a->dev_pause || !a->dev_resume)
            a->dev_pause = a->dev_resume = NULL;
    }
    return 0;
}

static int aud_buffers(hol_audio *a, char *msg, size_t cap)
{
    a->f.alGenBuffers(HOL_SND_KINDS, a->buf);
    a->nbuf = HOL_SND_KINDS;
    for (int k = 0; k < HOL_SND_KINDS; k++) {
        int n = hol_sound_length(k, HOL_SOUND_RATE);
        int16_t *pcm = malloc((size_t)n * sizeof *pcm);
        if (!pcm || hol_sound_synth(k, HOL_SOUND_RATE, pcm, n)) {
            free(pcm);
            return aud_fail(msg, cap, "cannot synthesise the sounds");
        }
        a->f.alBufferData(a->buf[k], AL_FORMAT_MONO16, pcm, n * 2, HOL_SOUND_RATE);
        free(pcm);
    }
    ALuint s[2 * (HOL_SOUND_MAX_SOURCES + HOL_SOUND_MAX_SHOTS)];
    int per = a->pair ? 2 : 1, n = per * (HOL_SOUND_MAX_SOURCES + HOL_SOUND_MAX_SHOTS);
    a->f.alGenSources(n, s);
    if (a->f.alGetError() != AL_NO_ERROR)
        return aud_fail(msg, cap, "cannot make the OpenAL sources");
    a->nsrc = n;
    a->f.alDistanceModel(AL_NONE);
    for (int i = 0; i < n; i++) {
        a->f.alSourcei(s[i], AL_SOURCE_RELATIVE, AL_TRUE);
        a->f.alSourcef(s[i], AL_ROLLOFF_FACTOR, 0);
        int v = i / per;
        if (v < HOL_SOUND_MAX_SOURCES)
            a->loops[v].src.s[i % per] = s[i];
        else
            a->shots[v - HOL_SOUND_MAX_SOURCES].s[i % per] = s[i];
    }
    return 0;
}

int hol_audio_open(int loopback, double volume, hol_audio **out, char *msg, size_t cap)
{
    *out = NULL;
    hol_audio *a = calloc(1, sizeof *a);
    if (!a)
        return aud_fail(msg, cap, "out of memory");
    a->loopback = loopback;
    a->pair = loopback; /* HRTF off there: OpenAL Soft's stereo pan is hard */
    a->volume = volume < 0 ? 0 : volume > 1 ? 1 : volume;
    if (aud_load(a, msg, cap) || aud_device(a, msg, cap) || aud_buffers(a, msg, cap)) {
        hol_audio_close(a);
        return -1;
    }
    *out = a;
    return 0;
}

/* The voice at core's direction with core's gain. A pair: the left
 * source hard left, the right one hard right, with the gains of the
 * equal-power law on the lateral angle t = asin(x) (x the direction's
 * part to the right): cos and sin of pi/4 + t/2, so a source ahead (or
 * behind) gives each ear half the power and one at the side all of it to
 * that ear; no harder than that (OpenAL Soft's own stereo pan puts 95 %
 * of the power in one ear at 30 degrees). */
static void aud_place(hol_audio *a, const aud_chan *c, const hol_sound_src *src)
{
    double g = src->gain * a->volume;
    if (!a->pair) {
        a->f.alSource3f(c->s[0], AL_POSITION, (float)src->dir[0], (float)src->dir[1],
                        (float)src->dir[2]);
        a->f.alSourcef(c->s[0], AL_GAIN, (float)g);
        return;
    }
    double x = src->dir[0] > 1 ? 1 : src->dir[0] < -1 ? -1 : src->dir[0];
    /* cos and sin of pi/4 + t/2 from x = sin t: sqrt((1 -+ x) / 2) */
    double gl = sqrt((1 - x) / 2), gr = sqrt((1 + x) / 2);
    a->f.alSource3f(c->s[0], AL_POSITION, -1, 0, 0);
    a->f.alSource3f(c->s[1], AL_POSITION, 1, 0, 0);
    a->f.alSourcef(c->s[0], AL_GAIN, (float)(g * gl));
    a->f.alSourcef(c->s[1], AL_GAIN, (float)(g * gr));
}

static void aud_each(hol_audio *a, const aud_chan *c, void (*fn)(ALuint))
{
    for (int k = 0; k < (a->pair ? 2 : 1); k++)
        fn(c->s[k]);
}

static void aud_load_buf(hol_audio *a, const aud_chan *c, int kind, int loop)
{
    for (int k = 0; k < (a->pair ? 2 : 1); k++) {
        a->f.alSourcei(c->s[k], AL_BUFFER, kind < 0 ? 0 : (ALint)a->buf[kind]);
        a->f.alSourcei(c->s[k], AL_LOOPING, loop ? AL_TRUE : AL_FALSE);
    }
}

/* loop voice v stops and is free again */
static void aud_release(hol_audio *a, int v)
{
    aud_each(a, &a->loops[v].src, a->f.alSourceStop);
    aud_load_buf(a, &a->loops[v].src, -1, 0);
    a->loops[v].used = 0;
}

void hol_audio_apply(hol_audio *a, const hol_sound_list *l)
{
    if (!a || a->paused)
        return;
    int keep[HOL_SOUND_MAX_SOURCES] = {0}, placed[HOL_SOUND_MAX_SOURCES] = {0};
    for (int i = 0; i < l->n; i++) /* sources that keep their voice */
        for (int v = 0; v < HOL_SOUND_MAX_SOURCES; v++)
            if (a->loops[v].used && !keep[v] && a->loops[v].id == l->src[i].id) {
                keep[v] = 1, placed[i] = 1;
                aud_place(a, &a->loops[v].src, &l->src[i]);
                break;
            }
    for (int v = 0; v < HOL_SOUND_MAX_SOURCES; v++)
        if (a->loops[v].used && !keep[v])
            aud_release(a, v);
    for (int i = 0, v = 0; i < l->n; i++) { /* newcomers take free voices */
        if (placed[i])
            continue;
        while (v < HOL_SOUND_MAX_SOURCES && a->loops[v].used)
            v++;
        if (v == HOL_SOUND_MAX_SOURCES)
            break;
        aud_voice *vo = &a->loops[v];
        vo->used = 1, vo->id = l->src[i].id;
        aud_load_buf(a, &vo->src, l->src[i].kind, 1);
        aud_place(a, &vo->src, &l->src[i]);
        aud_each(a, &vo->src, a->f.alSourcePlay);
    }
    for (int i = 0; i < l->nshots; i++) {
        const aud_chan *c = &a->shots[a->next_shot];
        a->next_shot = (a->next_shot + 1) % HOL_SOUND_MAX_SHOTS;
        aud_each(a, c, a->f.alSourceStop);
        aud_load_buf(a, c, l->shot[i].kind, 0);
        aud_place(a, c, &l->shot[i]);
        aud_each(a, c, a->f.alSourcePlay);
    }
}

void hol_audio_pause(hol_audio *a, int on)
{
    if (!a || !on == !a->paused)
        return;
    a->paused = on != 0;
    if (!on) {
        if (a->dev_resume)
            a->dev_resume(a->dev);
        return;
    }
    for (int v = 0; v < HOL_SOUND_MAX_SOURCES; v++) /* released: apply starts them again */
        if (a->loops[v].used)
            aud_release(a, v);
    for (int i = 0; i < HOL_SOUND_MAX_SHOTS && a->nsrc; i++)
        aud_each(a, &a->shots[i], a->f.alSourceStop);
    if (a->dev_pause)
        a->dev_pause(a->dev);
}

int hol_audio_paused(const hol_audio *a)
{
    return a && a->paused;
}

int hol_audio_render(hol_audio *a, int16_t *out, int n)
{
    if (!a || !a->loopback || n < 0)
        return -1;
    float tmp[2 * 1024];
    while (n > 0) {
        int k = n < 1024 ? n : 1024;
        a->render(a->dev, tmp, k);
        for (int i = 0; i < 2 * k; i++) {
            float f = tmp[i] * 32767.0f;
            f = f > 32767.0f ? 32767.0f : f < -32768.0f ? -32768.0f : f;
            out[i] = (int16_t)(f < 0 ? f - 0.5f : f + 0.5f);
        }
        out += 2 * k, n -= k;
    }
    return 0;
}

int hol_audio_active(const hol_audio *a)
{
    int n = 0;
    for (int v = 0; a && v < HOL_SOUND_MAX_SOURCES; v++)
        n += a->loops[v].used;
    return n;
}

int hol_audio_hrtf(const hol_audio *a)
{
    return a && a->hrtf;
}

void hol_audio_close(hol_audio *a)
{
    if (!a)
        return;
    if (a->ctx) {
        ALuint s[2 * (HOL_SOUND_MAX_SOURCES + HOL_SOUND_MAX_SHOTS)];
        int per = a->pair ? 2 : 1;
        for (int i = 0; i < a->nsrc; i++) {
            int v = i / per;
            s[i] = (v < HOL_SOUND_MAX_SOURCES ? a->loops[v].src
                                              : a->shots[v - HOL_SOUND_MAX_SOURCES]).s[i % per];
        }
        if (a->nsrc)
            a->f.alDeleteSources(a->nsrc, s);
        if (a->nbuf)
            a->f.alDeleteBuffers(a->nbuf, a->buf);
        a->f.alcMakeContextCurrent(NULL);
        a->f.alcDestroyContext(a->ctx);
    }
    if (a->dev)
        a->f.alcCloseDevice(a->dev);
#ifndef AUD_LINKED
    if (a->lib)
        dlclose(a->lib);
#endif
    free(a);
}

int hol_audio_feed_open(hol_audio_feed *f, double volume, char *msg, size_t cap)
{
    hol_sound_init(&f->snd);
    if (hol_audio_open(0, volume, &f->au, msg, cap))
        return -1;
    hol_audio_pause(f->au, f->held);
    return 0;
}

void hol_audio_feed_step(hol_audio_feed *f, hol_app *app)
{
    if (app) /* what the sound plays is captioned on the HUD (hol_app.h) */
        hol_app_set_captions(app, f->au != NULL);
    if (!f->au || !app)
        return;
    /* held too, the list is made (the listener's memory stays true);
     * hol_audio_apply plays nothing while the player is paused */
    hol_sound_update(&f->snd, hol_app_get_view(app), hol_app_get_events(app), hol_app_world(app),
                     &f->sl);
    hol_audio_apply(f->au, &f->sl);
}

void hol_audio_feed_hold(hol_audio_feed *f, int held)
{
    f->held = held != 0;
    hol_audio_pause(f->au, f->held);
}

void hol_audio_feed_close(hol_audio_feed *f)
{
    hol_audio_close(f->au);
    f->au = NULL;
}
