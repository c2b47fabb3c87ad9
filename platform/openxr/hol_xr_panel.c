/* hol_xr_panel.c - the world panel (HUD text, prompts, menus, end screens,
 * questionnaires) as an OpenXR quad layer (XrCompositionLayerQuad; see
 * hol_xr_state.h and the pure part, hol_xr_quad.h): drawn once per frame
 * at most, not per eye, into its own swapchain, and only when its content
 * changed; the runtime composites it over the projection layer. The quad
 * has no depth: while a hedge or trunk is nearer than the panel can come
 * (core/hol_panel.h, `covered`) it is not submitted and the eyes draw the
 * panel in the scene, depth-tested (hol__xr_quad_covered). */
#define _GNU_SOURCE
#include "hol_xr_state.h"

/* OpenXR structs are initialised by their type alone ({XR_TYPE_...}), the
 * rest zero: the API's own idiom. */
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

/* No quad swapchain: the panel in the scene, said once (not a failure). */
static int hol__quad_off(hol__xr *x, const char *why, XrResult r)
{
    const char *name = hol_xr_result_name((int)r);
    hol__xr_say(x, "xr: panel in the scene: the quad layer's %s failed (%s): the fallback", why,
                name ? name : "an extension's error");
    hol__xr_quad_free(x);
    x->quad_on = 0;
    return 0;
}

int hol__xr_quad_setup(hol__xr *x)
{
    x->quad_on = 0;
    if (x->d->panel == HOL_XR_PANEL_SCENE) {
        hol__xr_say(x, "xr: panel in the scene (--panel scene)");
        return 0;
    }
    hol_xr_quad_image(&x->quad_w, &x->quad_h);
    XrResult r = hol__xr_chain_create(x, x->quad_w, x->quad_h, &x->quad_chain);
    if (XR_FAILED(r)) {
        x->quad_chain = XR_NULL_HANDLE;
        return hol__quad_off(x, "swapchain", r);
    }
    uint32_t n = 0;
    r = xrEnumerateSwapchainImages(x->quad_chain, 0, &n, NULL);
    if (XR_FAILED(r) || !n)
        return hol__quad_off(x, "swapchain images", r);
    x->quad_images = calloc(n, sizeof *x->quad_images);
    x->quad_fbo = calloc(n, sizeof *x->quad_fbo);
    if (!x->quad_images || !x->quad_fbo)
        return hol__xr_error(x, "out of memory");
    for (uint32_t k = 0; k < n; k++)
        x->quad_images[k].type = HOL__XR_TYPE_IMAGE;
    r = xrEnumerateSwapchainImages(x->quad_chain, n, &n,
                                   (XrSwapchainImageBaseHeader *)x->quad_images);
    if (XR_FAILED(r))
        return hol__quad_off(x, "swapchain images", r);
    x->gl.GenFramebuffers((hol__GLsizei)n, x->quad_fbo);
    x->quad_nimages = n;
    int complete = 1;
    for (uint32_t k = 0; k < n; k++) {
        x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, x->quad_fbo[k]);
        x->gl.FramebufferTexture2D(HOL__GL_FRAMEBUFFER, HOL__GL_COLOR_ATTACHMENT0,
                                   HOL__GL_TEXTURE_2D, x->quad_images[k].image, 0);
        complete &= x->gl.CheckFramebufferStatus(HOL__GL_FRAMEBUFFER) ==
                    HOL__GL_FRAMEBUFFER_COMPLETE;
    }
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    if (!complete)
        return hol__quad_off(x, "framebuffer", XR_SUCCESS);
    hol_xr_quad_forget(&x->quad_cache);
    x->quad_on = 1;
    hol__xr_say(x, "xr: panel as a quad layer: %dx%d image, format 0x%llx, %u images, drawn "
                "once per frame at most (when its content changes), composited over the "
                "projection layer (no depth: always in front)",
                x->quad_w, x->quad_h, (unsigned long long)x->format, n);
    return 0;
}

#ifndef __ANDROID__
/* The check frame's image read back: the panel's opaque texels and the
 * box's transparent rest, within the rectangle used. */
static void hol__quad_check(hol__xr *x, const hol_xr_quad *q)
{
    size_t bytes = (size_t)q->rect[0] * (size_t)q->rect[1] * 4;
    uint8_t *px = malloc(bytes);
    if (!px)
        return;
    hol_render_read_rgba(x->rnd, q->rect[0], q->rect[1], px);
    long opaque = 0, clear = 0;
    for (size_t i = 0; i < bytes; i += 4) {
        opaque += px[i + 3] == 255;
        clear += px[i + 3] == 0 && !px[i] && !px[i + 1] && !px[i + 2];
    }
    free(px);
    hol__xr_say(x, "xr: check quad image: %ld opaque, %ld transparent of %dx%d texels", opaque,
                clear, q->rect[0], q->rect[1]);
}
#endif

/* The image drawn again (acquire, draw, release). */
static int hol__quad_draw(hol__xr *x, const hol_frame_desc *fd, const hol_xr_quad *q)
{
    uint32_t idx;
    if (hol__xr_chain_acquire(x, x->quad_chain, x->quad_nimages, "draw the panel", &idx))
        return 1;
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, x->quad_fbo[idx]);
    /* texels outside the rectangle used are never shown */
    hol_err err = hol_render_panel_image(x->rnd, fd, q->rect[0], q->rect[1]);
#ifndef __ANDROID__
    if (!err && x->d->check_dir && x->submitted == x->d->check_frame)
        hol__quad_check(x, q);
#endif
    x->gl.BindFramebuffer(HOL__GL_FRAMEBUFFER, 0);
    XrSwapchainImageReleaseInfo ri = {XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
    HOL__XR(x, "draw the panel", xrReleaseSwapchainImage(x->quad_chain, &ri));
    if (err)
        return hol__xr_error(x, "cannot draw the panel (%s)", hol_err_str(err));
    return 0;
}

int hol__xr_quad_covered(hol__xr *x, const hol_app_view *v)
{
    int c = x->quad_on && v && v->panel.covered;
    if (c != x->quad_covered)
        hol__xr_say(x, "xr: frame %ld: %s", x->submitted,
                    c ? "panel in the scene (depth-tested): a hedge or trunk is nearer than "
                        "the panel can come, and the quad layer has no depth"
                      : "panel as the quad layer again");
    x->quad_covered_frames += c;
    return x->quad_covered = c;
}

int hol__xr_quad_layer(hol__xr *x, const hol_app_view *v, const float shift[3],
                       XrCompositionLayerQuad *out, int *out_submit)
{
    *out_submit = 0;
    if (!x->quad_on || !v || x->quad_covered)
        return 0;
    hol_frame_desc fd;
    hol_app_frame_desc(v, 0, x->quad_w, x->quad_h, 0, &fd);
    hol_app_frame_panel(v, &fd);
    if (fd.flags & HOL_RENDER_NO_HUD)
        return 0;
    int map = (fd.flags & HOL_RENDER_MINIMAP) && !(fd.flags & HOL_RENDER_MINIMAP_HAND);
    hol_xr_quad q;
    hol_xr_quad_place(&x->calib, fd.panel_pos, fd.panel_orient, map, fd.panel_px, shift, &q);
    if (x->d->check_dir && x->submitted == x->d->check_frame)
        hol_xr_quad_forget(&x->quad_cache); /* drawn, to be read back */
    if (hol_xr_quad_stale(&x->quad_cache, hol_render_panel_key(x->rnd, &fd)) &&
        hol__quad_draw(x, &fd, &q))
        return 1;
    out->type = XR_TYPE_COMPOSITION_LAYER_QUAD;
    out->next = NULL;
    out->layerFlags = XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT;
    out->space = x->stage;
    out->eyeVisibility = XR_EYE_VISIBILITY_BOTH;
    out->subImage.swapchain = x->quad_chain;
    out->subImage.imageRect.offset.x = 0;
    out->subImage.imageRect.offset.y = 0;
    out->subImage.imageRect.extent.width = q.rect[0];
    out->subImage.imageRect.extent.height = q.rect[1];
    out->subImage.imageArrayIndex = 0;
    out->pose.position.x = q.pos[0];
    out->pose.position.y = q.pos[1];
    out->pose.position.z = q.pos[2];
    out->pose.orientation.x = q.quat[0];
    out->pose.orientation.y = q.quat[1];
    out->pose.orientation.z = q.quat[2];
    out->pose.orientation.w = q.quat[3];
    out->size.width = q.size[0];
    out->size.height = q.size[1];
    if (!x->quad_frames || x->submitted == x->d->check_frame)
        hol__xr_say(x, "xr: frame %ld ends with the quad layer after the projection layer: eye "
                    "visibility BOTH, pose (%.3f, %.3f, %.3f) (%.4f, %.4f, %.4f, %.4f), size "
                    "%.3f x %.3f m, image %dx%d of %dx%d",
                    x->submitted, q.pos[0], q.pos[1], q.pos[2], q.quat[0], q.quat[1], q.quat[2],
                    q.quat[3], q.size[0], q.size[1], q.rect[0], q.rect[1], x->quad_w, x->quad_h);
    x->quad_frames++;
    x->quad_last = q;
    *out_submit = 1;
    return 0;
}

void hol__xr_quad_free(hol__xr *x)
{
    hol__xr_chain_free(x, &x->quad_chain, &x->quad_images, &x->quad_fbo, &x->quad_nimages,
                       "destroy the panel's swapchain");
}
