/* hol_program.c - program keys, their slots, preambles and compiles. */
#include "hol_program.h"

#include <stdio.h>
#include <string.h>

#include "../core/hol_face.h"
#include "../core/hol_shadow.h"
#include "hol_light.h"

#include "hol_glsl.h" /* made by render/shaders/glsl_c.sh (the build folder) */

#define HOL__STR2(x) #x
#define HOL__STR(x) HOL__STR2(x)

/* The encoding below and the shader's HOL_NIGHT count on these values. */
_Static_assert(HOL_LIGHT_DAY == 0 && HOL_LIGHT_DUSK == 1 && HOL_LIGHT_NIGHT == 2 &&
                   HOL_PROG_CYCLE == 3,
               "core's hol_app_lighting: day 0, dusk 1, night 2; then the cycle's 3");

/* The key's dimensions: a field, its first value, step and count (a
 * dimension's index i is the value first + i * step). */
typedef struct hol__dim {
    size_t off;
    int first, step, count;
} hol__dim;

enum {
    HOL__D_LIGHTING,
    HOL__D_LAMPS,
    HOL__D_FLAT,
    HOL__D_WEDGE,
    HOL__D_FX,
    HOL__D_SHADOW,
    HOL__D_FX_VLIT
};

static const hol__dim hol__dims[] = {
    [HOL__D_LIGHTING] = {offsetof(hol_prog_key, lighting), HOL_LIGHT_DUSK, 1, 3},
    [HOL__D_LAMPS] = {offsetof(hol_prog_key, lamps), 0, 1, 2},
    [HOL__D_FLAT] = {offsetof(hol_prog_key, flat), 0, 1, 2},
    [HOL__D_WEDGE] = {offsetof(hol_prog_key, wedge), 0, 1, 2},
    [HOL__D_FX] = {offsetof(hol_prog_key, fx), 0, 1, HOL_PROG_FX_COUNT},
    [HOL__D_SHADOW] = {offsetof(hol_prog_key, shadow), 0, 1, 2},
    /* the small props' per-vertex light: no spots (hol_prog_key.vlit) */
    [HOL__D_FX_VLIT] = {offsetof(hol_prog_key, fx), 0, 1, HOL_PROG_FX_SPOTS},
};

/* The program families, in slot order: the fields a family fixes (its
 * base key; every field not varied must equal the base's) and the
 * dimensions it varies, the last fastest. A new dimension is a row of
 * hol__dims and a column of the families that vary it. */
typedef struct hol__family {
    hol_prog_key base;
    int ndim, dim[6];
} hol__family;

static const hol__family hol__families[] = {
    {{.lighting = HOL_LIGHT_DAY}, 1, {HOL__D_WEDGE}},                        /* day */
    {{.room = 1}, 3, {HOL__D_LIGHTING, HOL__D_LAMPS, HOL__D_WEDGE}},         /* the lit room */
    {{.room = 0},
     5,
     {HOL__D_LIGHTING, HOL__D_FLAT, HOL__D_WEDGE, HOL__D_FX, HOL__D_SHADOW}}, /* lit tiles */
    {{.vlit = 1},
     5,
     {HOL__D_LIGHTING, HOL__D_FLAT, HOL__D_WEDGE, HOL__D_FX_VLIT, HOL__D_SHADOW}}, /* their props */
    {{.floor = 1}, 4, {HOL__D_LIGHTING, HOL__D_FLAT, HOL__D_FX, HOL__D_SHADOW}},   /* their ground */
    {{.text = 1}, 0, {0}},                                                   /* the overlays */
};
#define HOL__NFAM (int)(sizeof hol__families / sizeof hol__families[0])

static int *hol__field(hol_prog_key *k, size_t off)
{
    return (int *)(void *)((char *)k + off);
}

/* The number of programs in family f. */
static int hol__family_size(const hol__family *f)
{
    int n = 1;
    for (int d = 0; d < f->ndim; d++)
        n *= hol__dims[f->dim[d]].count;
    return n;
}

/* Whether field off is one family f varies. */
static int hol__varies(const hol__family *f, size_t off)
{
    for (int d = 0; d < f->ndim; d++)
        if (hol__dims[f->dim[d]].off == off)
            return 1;
    return 0;
}

/* The index of k in family f, or -1 when k is not one of its keys. */
static int hol__family_index(const hol__family *f, const hol_prog_key *k)
{
    static const size_t fields[] = {offsetof(hol_prog_key, lighting), offsetof(hol_prog_key, room),
                                    offsetof(hol_prog_key, flat), offsetof(hol_prog_key, wedge),
                                    offsetof(hol_prog_key, fx), offsetof(hol_prog_key, shadow),
                                    offsetof(hol_prog_key, text), offsetof(hol_prog_key, lamps),
                                    offsetof(hol_prog_key, vlit), offsetof(hol_prog_key, floor)};
    _Static_assert(sizeof fields / sizeof fields[0] * sizeof(int) == sizeof(hol_prog_key),
                   "every field of the key");
    hol_prog_key kc = *k, base = f->base;
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
        if (!hol__varies(f, fields[i]) && *hol__field(&kc, fields[i]) != *hol__field(&base, fields[i]))
            return -1;
    int idx = 0;
    for (int d = 0; d < f->ndim; d++) {
        const hol__dim *dm = &hol__dims[f->dim[d]];
        int v = *hol__field(&kc, dm->off) - dm->first;
        if (v < 0 || v % dm->step || v / dm->step >= dm->count)
            return -1;
        idx = idx * dm->count + v / dm->step;
    }
    return idx;
}

int hol_prog_slot(const hol_prog_key *k)
{
    int first = 0;
    for (int i = 0; i < HOL__NFAM; i++) {
        int idx = hol__family_index(&hol__families[i], k);
        if (idx >= 0)
            return first + idx;
        first += hol__family_size(&hol__families[i]);
    }
    return -1;
}

hol_prog_key hol_prog_key_of_slot(int slot)
{
    int i = 0;
    while (i < HOL__NFAM - 1 && slot >= hol__family_size(&hol__families[i]))
        slot -= hol__family_size(&hol__families[i++]);
    const hol__family *f = &hol__families[i];
    hol_prog_key k = f->base;
    for (int d = f->ndim - 1; d >= 0; d--) {
        const hol__dim *dm = &hol__dims[f->dim[d]];
        *hol__field(&k, dm->off) = dm->first + slot % dm->count * dm->step;
        slot /= dm->count;
    }
    return k;
}

int hol_prog_preamble(const hol_prog_key *k, char *out, size_t n)
{
    int lit = k->lighting == HOL_LIGHT_DAY ? 0 : k->room ? 2 : 1;
    hol_face_metrics m; /* the atlas's field reach (HOL_SPREAD) */
    hol_face_get_metrics(&m);
    int len = snprintf(out, n,
                       "#version 300 es\n#define HOL_LIT %d\n#define HOL_FLAT %d\n"
                       "#define HOL_WEDGE %d\n#define HOL_NIGHT %d\n#define HOL_FX %d\n"
                       "#define HOL_TEXT %d\n#define HOL_LAMPS %d\n#define HOL_SPREAD %d.0\n"
                       "#define HOL_SHD %d\n#define HOL_VLIT %d\n#define HOL_FLOOR %d\n"
                       "#define HOL_SHM_N " HOL__STR(HOL_SHADOW_MASK_N) ".0\n"
                       "#define HOL_SHM_R " HOL__STR(HOL_SHADOW_MASK_RANGE) "\n"
                       "#define HOL_SHM_W " HOL__STR(HOL_SHADOW_ATLAS_COLS) ".0\n"
                       "#define HOL_SHM_H " HOL__STR(HOL_SHADOW_ATLAS_ROWS) ".0\n"
                       "#define HOL_TX_ROWS " HOL__STR(HOL_PROG_TX_ROWS) "\n"
                       "#define HOL_LIGHT_D0_M " HOL__STR(HOL_LIGHT_D0_M) "\n"
                       "#define HOL_LIGHT_PHYS " HOL__STR(HOL_LIGHT_PHYS) "\n"
                       "#define HOL_LIGHT_RADIUS_M " HOL__STR(HOL_LIGHT_RADIUS_M) "\n"
                       "#define HOL_LIGHT_HEIGHT_M " HOL__STR(HOL_LIGHT_HEIGHT_M) "\n"
                       "#define HOL_LIGHT_TONE_K " HOL__STR(HOL_LIGHT_TONE_K) "\n"
                       "#define HOL_SRGB_A " HOL__STR(HOL_SRGB_A) "\n"
                       "#define HOL_SRGB_B " HOL__STR(HOL_SRGB_B) "\n"
                       "#define HOL_SRGB_C " HOL__STR(HOL_SRGB_C) "\n"
                       "#define HOL_SRGB_D " HOL__STR(HOL_SRGB_D) "\n",
                       lit, k->flat, k->wedge,
                       k->lighting == HOL_PROG_CYCLE ? 2 : k->lighting == HOL_LIGHT_NIGHT, k->fx, k->text != 0,
                       k->lamps != 0, m.spread, k->shadow != 0, k->vlit != 0,
                       k->floor != 0);
    return len < 0 || (size_t)len >= n ? -1 : len;
}

static GLuint hol__shader(const hol_gl *gl, GLenum type, const char *pre, const char *body)
{
    const char *src[2] = {pre, body};
    GLuint s = gl->CreateShader(type);
    gl->ShaderSource(s, 2, src, NULL);
    gl->CompileShader(s);
    GLint ok = 0;
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl->DeleteShader(s);
        return 0;
    }
    return s;
}

static void hol__uniforms(const hol_gl *gl, hol_prog *pg)
{
    static const char *const names[] = {"u_vp", "u_model", "u_mode", "u_id", "u_eye",
                                        "u_fog", "u_fogd", "u_lin", "u_wedge", "u_wmode",
                                        "u_light", "u_klein", "u_mpu2", "u_tl", "u_eyeh",
                                        "u_lonly", "u_tx", "u_shr", "u_shm", "u_atlas", "u_amb",
                                        "u_sun"};
    GLint *loc[] = {&pg->u_vp, &pg->u_model, &pg->u_mode, &pg->u_id, &pg->u_eye,
                    &pg->u_fog, &pg->u_fogd, &pg->u_lin, &pg->u_wedge, &pg->u_wmode,
                    &pg->u_light, &pg->u_klein, &pg->u_mpu2, &pg->u_tl, &pg->u_eyeh,
                    &pg->u_lonly, &pg->u_tx, &pg->u_shr, &pg->u_shm, &pg->u_atlas, &pg->u_amb,
                    &pg->u_sun};
    _Static_assert(sizeof names / sizeof names[0] == sizeof loc / sizeof loc[0],
                   "a name per uniform");
    for (size_t i = 0; i < sizeof loc / sizeof loc[0]; i++)
        *loc[i] = gl->GetUniformLocation(pg->prog, names[i]);
}

int hol_prog_make(const hol_gl *gl, const hol_prog_key *key, hol_prog *pg)
{
    char pre[768];
    if (hol_prog_preamble(key, pre, sizeof pre) < 0)
        return 1;
    GLuint vs = hol__shader(gl, GL_VERTEX_SHADER, pre, hol__glsl_scene_vert);
    GLuint fs = hol__shader(gl, GL_FRAGMENT_SHADER, pre, hol__glsl_scene_frag);
    if (!vs || !fs) {
        if (vs)
            gl->DeleteShader(vs);
        if (fs)
            gl->DeleteShader(fs);
        return 1;
    }
    pg->prog = gl->CreateProgram();
    gl->AttachShader(pg->prog, vs);
    gl->AttachShader(pg->prog, fs);
    gl->LinkProgram(pg->prog);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    GLint ok = 0;
    gl->GetProgramiv(pg->prog, GL_LINK_STATUS, &ok);
    if (!ok) { /* none left half-made: a later frame or prepare tries again */
        gl->DeleteProgram(pg->prog);
        pg->prog = 0;
        return 1;
    }
    hol__uniforms(gl, pg);
    return 0;
}
