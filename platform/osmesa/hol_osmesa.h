/* hol_osmesa.h - headless GL context through OSMesa (platform code).
 *
 * Contract
 * - Header-only (static inline), so the CLI and the render tests share it
 *   without extra build rules. Include it in files that do not include the
 *   GLES headers (it pulls in GL/osmesa.h and GL/gl.h).
 * - hol_osmesa_create makes a core-profile context (3.3 or later: Mesa's
 *   llvmpipe gives 4.5, which compiles `#version 300 es` shaders) with a
 *   24-bit depth and 8-bit stencil buffer over a malloc'ed RGBA buffer of
 *   w x h, and makes it current. On failure it returns nonzero and writes a
 *   one-line reason to err.
 * - libOSMesa.so.8 is loaded at run time (dlopen, on the first
 *   hol_osmesa_create), not linked: it pulls in LLVM, whose loading costs
 *   about 0.1 s of CPU, which every command that never renders would pay.
 *   A program that links -lOSMesa itself (the render tests) gets the same
 *   library back from dlopen.
 */
#ifndef HOL_OSMESA_H
#define HOL_OSMESA_H

#include <GL/osmesa.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>

/* The four OSMesa entry points used, loaded by hol__osmesa_load. */
typedef struct hol__osmesa_fns {
    OSMesaContext (*create)(const int *attribs, OSMesaContext share);
    void (*destroy)(OSMesaContext ctx);
    GLboolean (*make_current)(OSMesaContext ctx, void *buf, GLenum type, GLsizei w, GLsizei h);
    void (*(*getproc)(const char *name))(void);
} hol__osmesa_fns;

static hol__osmesa_fns hol__osmesa; /* all NULL until loaded */

/* Load libOSMesa.so.8 once (kept loaded); 0 when its functions are there. */
static inline int hol__osmesa_load(void)
{
    if (hol__osmesa.getproc)
        return 0;
    void *lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!lib)
        return 1;
    hol__osmesa_fns f;
    *(void **)&f.create = dlsym(lib, "OSMesaCreateContextAttribs");
    *(void **)&f.destroy = dlsym(lib, "OSMesaDestroyContext");
    *(void **)&f.make_current = dlsym(lib, "OSMesaMakeCurrent");
    *(void **)&f.getproc = dlsym(lib, "OSMesaGetProcAddress");
    if (!f.create || !f.destroy || !f.make_current || !f.getproc) {
        dlclose(lib);
        return 1;
    }
    hol__osmesa = f;
    return 0;
}

typedef struct hol_osmesa {
    OSMesaContext ctx;
    unsigned char *buf;
    int w, h;
} hol_osmesa;

static inline int hol_osmesa_create(hol_osmesa *o, int w, int h, char *err,
                                    size_t err_cap)
{
    static const int attribs[] = {
        OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
        OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
        OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    o->ctx = NULL;
    o->buf = NULL;
    o->w = w;
    o->h = h;
    if (hol__osmesa_load()) {
        snprintf(err, err_cap, "cannot load libOSMesa.so.8 (Mesa's off-screen GL)");
        return 1;
    }
    o->ctx = hol__osmesa.create(attribs, NULL);
    if (!o->ctx) {
        snprintf(err, err_cap, "cannot create an OSMesa GL 3.3 core context");
        return 1;
    }
    o->buf = malloc((size_t)w * (size_t)h * 4);
    if (!o->buf) {
        hol__osmesa.destroy(o->ctx);
        o->ctx = NULL;
        snprintf(err, err_cap, "out of memory for a %d x %d image", w, h);
        return 1;
    }
    if (!hol__osmesa.make_current(o->ctx, o->buf, GL_UNSIGNED_BYTE, w, h)) {
        hol__osmesa.destroy(o->ctx);
        free(o->buf);
        o->ctx = NULL;
        o->buf = NULL;
        snprintf(err, err_cap, "cannot make the OSMesa context current");
        return 1;
    }
    return 0;
}

/* GL entry points of the current OSMesa context, for hol_render_desc. */
typedef void (*hol_osmesa_proc)(void);
static inline hol_osmesa_proc hol_osmesa_getproc(const char *name)
{
    return hol__osmesa.getproc ? (hol_osmesa_proc)hol__osmesa.getproc(name) : NULL;
}

static inline void hol_osmesa_destroy(hol_osmesa *o)
{
    if (o->ctx)
        hol__osmesa.destroy(o->ctx);
    free(o->buf);
    o->ctx = NULL;
    o->buf = NULL;
}

#endif
