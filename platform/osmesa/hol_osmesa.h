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
 */
#ifndef HOL_OSMESA_H
#define HOL_OSMESA_H

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

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
    o->ctx = OSMesaCreateContextAttribs(attribs, NULL);
    o->buf = NULL;
    o->w = w;
    o->h = h;
    if (!o->ctx) {
        snprintf(err, err_cap, "cannot create an OSMesa GL 3.3 core context");
        return 1;
    }
    o->buf = malloc((size_t)w * (size_t)h * 4);
    if (!o->buf) {
        OSMesaDestroyContext(o->ctx);
        o->ctx = NULL;
        snprintf(err, err_cap, "out of memory for a %d x %d image", w, h);
        return 1;
    }
    if (!OSMesaMakeCurrent(o->ctx, o->buf, GL_UNSIGNED_BYTE, w, h)) {
        OSMesaDestroyContext(o->ctx);
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
    return (hol_osmesa_proc)OSMesaGetProcAddress(name);
}

static inline void hol_osmesa_destroy(hol_osmesa *o)
{
    if (o->ctx)
        OSMesaDestroyContext(o->ctx);
    free(o->buf);
    o->ctx = NULL;
    o->buf = NULL;
}

#endif
