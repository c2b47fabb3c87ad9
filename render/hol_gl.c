/* hol_gl.c - load the GL entry points (see hol_gl.h). */
#include "hol_gl.h"

hol_err hol_gl_load(hol_gl *gl, hol_gl_getproc getproc)
{
    if (!getproc)
        return HOL_EARG;
#define HOL__GL_LOAD(type, name, str)                                         \
    gl->name = (type)getproc(str);                                            \
    if (!gl->name)                                                            \
        return HOL_EUNSUPPORTED;
    HOL_GL_FUNCS(HOL__GL_LOAD)
#undef HOL__GL_LOAD
    return HOL_OK;
}
