/* hol_xr_pick.h - what the headset layer picks from what the runtime
 * offers, as pure functions (no OpenXR or GL headers; the enum values are
 * mirrored and tests/test_xr_pick.c checks them against openxr.h):
 * the reference space the room lives in and the swapchain's image format.
 *
 * Contract
 * - hol_xr_pick_space: STAGE when the runtime offers it (its origin is on
 *   the floor, in the middle of the play area); else LOCAL, whose origin
 *   is where the head was at the start: the room's space is then LOCAL
 *   moved down by HOL_XR_EYE_HEIGHT (*out_origin_y = -1.6), so a standing
 *   user's eye is at 1.6 m as in STAGE, not at y = 0. 0 when the runtime
 *   offers neither (OpenXR requires LOCAL: a broken runtime).
 * - hol_xr_pick_format: 8-bit RGBA with sRGB encoding (GL_SRGB8_ALPHA8)
 *   when the runtime offers it, else 8-bit linear RGBA (GL_RGBA8); 0 when
 *   it offers neither. *out_srgb says which: with sRGB the compositor reads the
 *   image as sRGB, as the colours are authored, so the renderer writes
 *   linear values and the GL encodes them (hol_render_desc.srgb). A linear
 *   RGBA8 image would be read as linear and look washed out.
 * - hol_xr_pick_samples: the multisampling of the eyes: the runtime's
 *   recommendedSwapchainSampleCount, within 1 and its
 *   maxSwapchainSampleCount and at most HOL_XR_MAX_SAMPLES (0 read as 1).
 *   More than 1: each eye draws into a multisampled framebuffer of that
 *   many samples and resolves it into the swapchain image (the swapchain
 *   itself stays single-sampled, which every compositor reads); 1: it
 *   draws into the swapchain image directly.
 */
#ifndef HOL_XR_PICK_H
#define HOL_XR_PICK_H

#include <stdint.h>

/* XrReferenceSpaceType values (OpenXR 1.0). */
enum { HOL_XR_SPACE_VIEW = 1, HOL_XR_SPACE_LOCAL = 2, HOL_XR_SPACE_STAGE = 3 };

/* GL internal formats (the same values in GL and GLES). */
#define HOL_XR_GL_RGBA8 0x8058
#define HOL_XR_GL_SRGB8_ALPHA8 0x8C43

/* The standing eye height the LOCAL fallback assumes (SPEC section 1). */
#define HOL_XR_EYE_HEIGHT 1.6

/* want: 0 for the contract's choice, HOL_XR_SPACE_LOCAL for LOCAL even
 * where STAGE is offered (seated play, no play area set up). */
int hol_xr_pick_space(const int *types, uint32_t n, int want, double *out_origin_y);
int64_t hol_xr_pick_format(const int64_t *formats, uint32_t n, int *out_srgb);

#define HOL_XR_MAX_SAMPLES 8
int hol_xr_pick_samples(uint32_t recommended, uint32_t max);

#endif
