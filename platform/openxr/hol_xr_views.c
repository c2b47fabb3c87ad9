/* hol_xr_views.c - the stereo view configuration and the swapchains (see
 * hol_xr_state.h): every list the runtime sizes is read with the two-call
 * idiom (ask the count, allocate, fill) once, before the first frame. */
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The runtime must offer the stereo configuration, with two views. */
static int hol__stereo_offered(hol__xr *x)
{
    uint32_t n = 0;
    HOL__XR(x, "list the view configurations",
            xrEnumerateViewConfigurations(x->instance, x->system, 0, &n, NULL));
    XrViewConfigurationType *t = calloc(n ? n : 1, sizeof *t);
    if (!t)
        return hol__xr_error(x, "out of memory");
    XrResult r = xrEnumerateViewConfigurations(x->instance, x->system, n, &n, t);
    int stereo = 0;
    for (uint32_t i = 0; XR_SUCCEEDED(r) && i < n; i++)
        stereo |= t[i] == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    free(t);
    if (XR_FAILED(r))
        return hol__xr_fail(x, "list the view configurations", r);
    if (!stereo)
        return hol__xr_error(x, "the OpenXR runtime's device is not a stereo headset (no "
                             "PRIMARY_STEREO view configuration)");
    return 0;
}

int hol__xr_views(hol__xr *x)
{
    if (hol__stereo_offered(x))
        return 1;
    uint32_t n = 0;
    HOL__XR(x, "read the headset's views",
            xrEnumerateViewConfigurationViews(x->instance, x->system,
                                              XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &n,
                                              NULL));
    if (n != 2)
        return hol__xr_error(x, "the headset's stereo configuration has %u views, not 2", n);
    XrViewConfigurationView vc[2] = {{XR_TYPE_VIEW_CONFIGURATION_VIEW},
                                     {XR_TYPE_VIEW_CONFIGURATION_VIEW}};
    HOL__XR(x, "read the headset's views",
            xrEnumerateViewConfigurationViews(x->instance, x->system,
                                              XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, n, &n,
                                              vc));
    if (n != 2)
        return hol__xr_error(x, "the headset's stereo configuration has %u views, not 2", n);
    x->views = calloc(n, sizeof *x->views);
    if (!x->views)
        return hol__xr_error(x, "out of memory");
    x->nviews = n;
    for (uint32_t e = 0; e < n; e++) {
        x->views[e].type = XR_TYPE_VIEW;
        x->eye[e].w = (int32_t)vc[e].recommendedImageRectWidth;
        x->eye[e].h = (int32_t)vc[e].recommendedImageRectHeight;
        x->eye[e].samples = hol_xr_pick_samples(vc[e].recommendedSwapchainSampleCount,
                                                vc[e].maxSwapchainSampleCount);
        if (x->eye[e].w <= 0 || x->eye[e].h <= 0 || x->eye[e].w > 4096 || x->eye[e].h > 4096)
            return hol__xr_error(x, "the headset asks for %dx%d images per eye (1 to 4096 each)",
                                 x->eye[e].w, x->eye[e].h);
    }
    return 0;
}

/* The image format (two-call idiom; hol_xr_pick_format: sRGB first). */
static int hol__format(hol__xr *x, int64_t *out)
{
    uint32_t n = 0;
    HOL__XR(x, "list the image formats", xrEnumerateSwapchainFormats(x->session, 0, &n, NULL));
    int64_t *f = calloc(n ? n : 1, sizeof *f);
    if (!f)
        return hol__xr_error(x, "out of memory");
    XrResult r = xrEnumerateSwapchainFormats(x->session, n, &n, f);
    *out = XR_SUCCEEDED(r) ? hol_xr_pick_format(f, n, &x->srgb) : 0;
    free(f);
    if (XR_FAILED(r))
        return hol__xr_fail(x, "list the image formats", r);
    if (!*out)
        return hol__xr_error(x, "the OpenXR runtime offers no 8-bit RGBA image format (neither "
                             "GL_SRGB8_ALPHA8 nor GL_RGBA8)");
    return 0;
}

/* The eye's multisampled framebuffer (ey->samples > 1): colour in the
 * swapchain's format and depth-stencil, resolved into the image at the
 * eye's end (hol_xr_pick.h). */
static int hol__msaa(hol__xr *x, hol__eye *ey, int64_t fmt)
{
    hol__GLuint rb[2];
    x->gl.GenRenderbuffers(2, rb);
    ey->msaa_color = rb[0];
    ey->msaa_depth = rb[1];
    x->gl.BindRenderbuffer(HOL__GL_RENDERBUFFER, rb[0]);
    x->gl.RenderbufferStorageMultisample(HOL__GL_RENDERBUFFER, ey->samples, (hol__GLenum)fmt,
                                         ey->w, ey->h);
    x->gl.BindRenderbuffer(HOL__GL_RENDERBUFFER, rb[1]);
    x->gl.RenderbufferStorageMultisample(HOL__GL_RENDERBUFFER, ey->samples,
                                         HOL__GL_DEPTH24_STENCIL8, ey->w, ey->h);
    x->gl.GenFramebuffers(1, &ey->msaa_fbo);
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->msaa_fbo);
    x->gl.FramebufferRenderbuffer(HOL__GL_FRAMEBUFFER, HOL__GL_COLOR_ATTACHMENT0,
                                  HOL__GL_RENDERBUFFER, rb[0]);
    x->gl.FramebufferRenderbuffer(HOL__GL_FRAMEBUFFER, HOL__GL_DEPTH_STENCIL_ATTACHMENT,
                                  HOL__GL_RENDERBUFFER, rb[1]);
    int ok = x->gl.CheckFramebufferStatus(HOL__GL_FRAMEBUFFER) == HOL__GL_FRAMEBUFFER_COMPLETE;
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    if (!ok)
        return hol__xr_error(x, "cannot draw %d samples per pixel (multisampled framebuffer "
                             "incomplete)", ey->samples);
    return 0;
}

/* The eye's images (two-call idiom) and a framebuffer for each. */
static int hol__images(hol__xr *x, hol__eye *ey)
{
    uint32_t n = 0;
    HOL__XR(x, "list the swapchain images", xrEnumerateSwapchainImages(ey->swapchain, 0, &n, NULL));
    ey->images = calloc(n ? n : 1, sizeof *ey->images);
    ey->fbo = calloc(n ? n : 1, sizeof *ey->fbo);
    if (!ey->images || !ey->fbo)
        return hol__xr_error(x, "out of memory");
    for (uint32_t k = 0; k < n; k++)
        ey->images[k].type = HOL__XR_TYPE_IMAGE;
    HOL__XR(x, "list the swapchain images",
            xrEnumerateSwapchainImages(ey->swapchain, n, &n,
                                       (XrSwapchainImageBaseHeader *)ey->images));
    x->gl.GenRenderbuffers(1, &ey->depth);
    x->gl.BindRenderbuffer(HOL__GL_RENDERBUFFER, ey->depth);
    x->gl.RenderbufferStorage(HOL__GL_RENDERBUFFER, HOL__GL_DEPTH24_STENCIL8, ey->w, ey->h);
    x->gl.GenFramebuffers((hol__GLsizei)n, ey->fbo);
    ey->nimages = n;
    for (uint32_t k = 0; k < n; k++) {
        x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, ey->fbo[k]);
        x->gl.FramebufferTexture2D(HOL__GL_FRAMEBUFFER, HOL__GL_COLOR_ATTACHMENT0,
                                   HOL__GL_TEXTURE_2D, ey->images[k].image, 0);
        x->gl.FramebufferRenderbuffer(HOL__GL_FRAMEBUFFER, HOL__GL_DEPTH_STENCIL_ATTACHMENT,
                                      HOL__GL_RENDERBUFFER, ey->depth);
        if (x->gl.CheckFramebufferStatus(HOL__GL_FRAMEBUFFER) != HOL__GL_FRAMEBUFFER_COMPLETE)
            return hol__xr_error(x, "cannot draw into the runtime's swapchain image (framebuffer "
                                 "incomplete)");
    }
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    return 0;
}

int hol__xr_swapchains(hol__xr *x)
{
    int64_t fmt = 0;
    if (hol__format(x, &fmt))
        return 1;
    x->format = fmt;
    for (int e = 0; e < 2; e++) {
        hol__eye *ey = &x->eye[e];
        HOL__XR(x, "create the swapchains", hol__xr_chain_create(x, ey->w, ey->h, &ey->swapchain));
        if (hol__images(x, ey) || (ey->samples > 1 && hol__msaa(x, ey, fmt)))
            return 1;
    }
    hol__xr_say(x, "xr: swapchains %dx%d per eye, format 0x%llx (%s), %u images, two passes, "
                "%d sample%s per pixel (the runtime's recommendation%s)",
                x->eye[0].w, x->eye[0].h, (unsigned long long)fmt,
                x->srgb ? "sRGB" : "linear RGBA8", x->eye[0].nimages, x->eye[0].samples,
                x->eye[0].samples > 1 ? "s" : "",
                x->eye[0].samples > 1 ? ": resolved into the swapchain" : "");
    return 0;
}

XrResult hol__xr_chain_create(hol__xr *x, int w, int h, XrSwapchain *out)
{
    XrSwapchainCreateInfo ci = {XR_TYPE_SWAPCHAIN_CREATE_INFO};
    ci.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_SAMPLED_BIT;
    ci.format = x->format;
    ci.sampleCount = 1;
    ci.width = (uint32_t)w;
    ci.height = (uint32_t)h;
    ci.faceCount = 1;
    ci.arraySize = 1;
    ci.mipCount = 1;
    return xrCreateSwapchain(x->session, &ci, out);
}

void hol__xr_chain_free(hol__xr *x, XrSwapchain *chain, hol__image **images, hol__GLuint **fbo,
                        uint32_t *n, const char *doing)
{
    if (*n && x->gl.DeleteFramebuffers)
        x->gl.DeleteFramebuffers((hol__GLsizei)*n, *fbo);
    free(*images);
    free(*fbo);
    *images = NULL;
    *fbo = NULL;
    *n = 0;
    if (*chain != XR_NULL_HANDLE)
        hol__xr_gone(x, doing, xrDestroySwapchain(*chain));
    *chain = XR_NULL_HANDLE;
}

int hol__xr_chain_acquire(hol__xr *x, XrSwapchain chain, uint32_t n, const char *doing,
                          uint32_t *out_idx)
{
    *out_idx = 0;
    XrSwapchainImageAcquireInfo ai = {XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    HOL__XR(x, doing, xrAcquireSwapchainImage(chain, &ai, out_idx));
    XrSwapchainImageWaitInfo wi = {XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wi.timeout = XR_INFINITE_DURATION;
    HOL__XR(x, doing, xrWaitSwapchainImage(chain, &wi));
    if (*out_idx >= n)
        return hol__xr_error(x, "the runtime gave swapchain image %u of %u", *out_idx, n);
    return 0;
}

void hol__xr_views_free(hol__xr *x)
{
    for (int e = 0; e < 2; e++) {
        hol__eye *ey = &x->eye[e];
        if (ey->nimages && x->gl.DeleteFramebuffers)
            x->gl.DeleteRenderbuffers(1, &ey->depth);
        if (ey->msaa_fbo && x->gl.DeleteFramebuffers) {
            hol__GLuint rb[2] = {ey->msaa_color, ey->msaa_depth};
            x->gl.DeleteFramebuffers(1, &ey->msaa_fbo);
            x->gl.DeleteRenderbuffers(2, rb);
        }
        ey->msaa_fbo = ey->msaa_color = ey->msaa_depth = 0;
        hol__xr_chain_free(x, &ey->swapchain, &ey->images, &ey->fbo, &ey->nimages,
                           "destroy an eye's swapchain");
    }
    free(x->views);
    x->views = NULL;
    x->nviews = 0;
}
