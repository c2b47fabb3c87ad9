/* hol_xr_pick.c - the reference space and the image format (see
 * hol_xr_pick.h). */
#include "hol_xr_pick.h"

int hol_xr_pick_space(const int *types, uint32_t n, int want, double *out_origin_y)
{
    int local = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (types[i] == HOL_XR_SPACE_STAGE && want != HOL_XR_SPACE_LOCAL) {
            *out_origin_y = 0;
            return HOL_XR_SPACE_STAGE;
        }
        local |= types[i] == HOL_XR_SPACE_LOCAL;
    }
    *out_origin_y = local ? -HOL_XR_EYE_HEIGHT : 0;
    return local ? HOL_XR_SPACE_LOCAL : 0;
}

int64_t hol_xr_pick_format(const int64_t *formats, uint32_t n, int *out_srgb)
{
    for (uint32_t i = 0; i < n; i++)
        if (formats[i] == HOL_XR_GL_SRGB8_ALPHA8) {
            *out_srgb = 1;
            return formats[i];
        }
    *out_srgb = 0;
    for (uint32_t i = 0; i < n; i++)
        if (formats[i] == HOL_XR_GL_RGBA8)
            return formats[i];
    return 0;
}

int hol_xr_pick_samples(uint32_t recommended, uint32_t max)
{
    uint32_t s = recommended ? recommended : 1;
    if (max && s > max)
        s = max;
    return (int)(s > HOL_XR_MAX_SAMPLES ? HOL_XR_MAX_SAMPLES : s);
}
