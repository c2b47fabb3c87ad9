/* hol_program.c - program keys, their slots, preambles and compiles. */
#include "hol_program.h"

#include <stdio.h>
#include <string.h>

#include "../core/hol_face.h"
#include "hol_light.h"

#include "hol_glsl.h" /* made by render/shaders/glsl_c.sh (the build folder) */

#define HOL__STR2(x) #x
#define HOL__STR(x) HOL__STR2(x)

/* The encoding below and the shader's HOL_NIGHT count on these values. */
_Static_assert(HOL_LIGHT_DAY == 0 && HOL_LIGHT_DUSK == 1 && HOL_LIGHT_NIGHT == 2,
               "core's hol_app_lighting: day 0, dusk 1, night 2");

/* Slots: [0, 2) day by wedge; [2, 6) the lit room by (lighting, wedge);
 * [6, HOL_PROG_TEXT_SLOT) the lit tiles by (lighting, flat, wedge, fx,
 * shadow pairs / 2), the last varying fastest; then the text program. */
enum { HOL__DAY0 = 0, HOL__ROOM0 = 2, HOL__TILES0 = 6 };

static int hol__bit(int v)
{
    return v == 0 || v == 1;
}

int hol_prog_slot(const hol_prog_key *k)
{
    if (!hol__bit(k->room) || !hol__bit(k->flat) || !hol__bit(k->wedge) || !hol__bit(k->text))
        return -1;
    if (k->text)
        return k->lighting || k->room || k->flat || k->wedge || k->fx || k->shadow_pairs
                   ? -1
                   : HOL_PROG_TEXT_SLOT;
    int tiles_only = k->flat || k->fx || k->shadow_pairs;
    if (k->lighting == HOL_LIGHT_DAY)
        return k->room || tiles_only ? -1 : HOL__DAY0 + k->wedge;
    if (k->lighting != HOL_LIGHT_DUSK && k->lighting != HOL_LIGHT_NIGHT)
        return -1;
    int night = k->lighting == HOL_LIGHT_NIGHT;
    if (k->room)
        return tiles_only ? -1 : HOL__ROOM0 + 2 * night + k->wedge;
    if (k->fx < 0 || k->fx >= HOL_PROG_FX_COUNT || k->shadow_pairs < 0 || k->shadow_pairs > 4 ||
        k->shadow_pairs % 2)
        return -1;
    int i = ((night * 2 + k->flat) * 2 + k->wedge) * HOL_PROG_FX_COUNT + k->fx;
    return HOL__TILES0 + i * 3 + k->shadow_pairs / 2;
}

hol_prog_key hol_prog_key_of_slot(int slot)
{
    hol_prog_key k;
    memset(&k, 0, sizeof k);
    if (slot == HOL_PROG_TEXT_SLOT) {
        k.text = 1;
        return k;
    }
    if (slot < HOL__ROOM0) {
        k.wedge = slot - HOL__DAY0;
        return k;
    }
    if (slot < HOL__TILES0) {
        int i = slot - HOL__ROOM0;
        k.lighting = i / 2 ? HOL_LIGHT_NIGHT : HOL_LIGHT_DUSK;
        k.room = 1;
        k.wedge = i % 2;
        return k;
    }
    int i = slot - HOL__TILES0;
    k.shadow_pairs = i % 3 * 2;
    i /= 3;
    k.fx = i % HOL_PROG_FX_COUNT;
    i /= HOL_PROG_FX_COUNT;
    k.wedge = i % 2;
    k.flat = i / 2 % 2;
    k.lighting = i / 4 ? HOL_LIGHT_NIGHT : HOL_LIGHT_DUSK;
    return k;
}

int hol_prog_preamble(const hol_prog_key *k, char *out, size_t n)
{
    /* the shadow pairs' vector: HOL_SV of HOL_SHD pairs, HOL_SW its swizzle */
    static const char *const sv[5][2] = {{"float", ""}, {"float", ".x"}, {"vec2", ".xy"},
                                         {"float", ""}, {"vec4", ""}};
    int lit = k->lighting == HOL_LIGHT_DAY ? 0 : k->room ? 2 : 1;
    int nsh = k->shadow_pairs >= 0 && k->shadow_pairs <= 4 ? k->shadow_pairs : 0;
    hol_face_metrics m; /* the atlas's field reach (HOL_SPREAD) */
    hol_face_get_metrics(&m);
    int len = snprintf(out, n,
                       "#version 300 es\n#define HOL_LIT %d\n#define HOL_FLAT %d\n"
                       "#define HOL_WEDGE %d\n#define HOL_NIGHT %d\n#define HOL_FX %d\n"
                       "#define HOL_TEXT %d\n#define HOL_SPREAD %d.0\n"
                       "#define HOL_SHD %d\n#define HOL_SV %s\n#define HOL_SW %s\n"
                       "#define HOL_TX_ROWS " HOL__STR(HOL_PROG_TX_ROWS) "\n"
                       "#define HOL_LIGHT_D0_M " HOL__STR(HOL_LIGHT_D0_M) "\n"
                       "#define HOL_LIGHT_PHYS " HOL__STR(HOL_LIGHT_PHYS) "\n"
                       "#define HOL_LIGHT_RADIUS_M " HOL__STR(HOL_LIGHT_RADIUS_M) "\n"
                       "#define HOL_LIGHT_HEIGHT_M " HOL__STR(HOL_LIGHT_HEIGHT_M) "\n",
                       lit, k->flat, k->wedge, k->lighting == HOL_LIGHT_NIGHT, k->fx, k->text != 0,
                       m.spread, nsh,
                       sv[nsh][0], sv[nsh][1]);
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
                                        "u_lonly", "u_tx", "u_ts", "u_atlas"};
    GLint *loc[] = {&pg->u_vp, &pg->u_model, &pg->u_mode, &pg->u_id, &pg->u_eye,
                    &pg->u_fog, &pg->u_fogd, &pg->u_lin, &pg->u_wedge, &pg->u_wmode,
                    &pg->u_light, &pg->u_klein, &pg->u_mpu2, &pg->u_tl, &pg->u_eyeh,
                    &pg->u_lonly, &pg->u_tx, &pg->u_ts, &pg->u_atlas};
    _Static_assert(sizeof names / sizeof names[0] == sizeof loc / sizeof loc[0],
                   "a name per uniform");
    for (size_t i = 0; i < sizeof loc / sizeof loc[0]; i++)
        *loc[i] = gl->GetUniformLocation(pg->prog, names[i]);
}

int hol_prog_make(const hol_gl *gl, const hol_prog_key *key, hol_prog *pg)
{
    char pre[512];
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
