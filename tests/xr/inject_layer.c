/* inject_layer.c - a test-only OpenXR API layer for `make xr-test`: it
 * gives the application a reference-space change that Monado never sends
 * (a recentre from the runtime's menu, or a play area drawn again), so the
 * handler in platform/openxr/hol_xr_events.c runs against a real loader,
 * runtime and validation layer.
 *
 * Everything passes through to the next layer or the runtime, except
 * xrPollEvent: once HOL_INJECT_AT frames have ended (xrEndFrame calls that
 * succeeded; default 90) it returns, once, an
 * XrEventDataReferenceSpaceChangePending for the session, of the space
 * HOL_INJECT_SPACE ("STAGE", the default, or "LOCAL"), with the previous
 * origin's pose valid (identity). The loader finds it through a manifest
 * (inside.sh writes one) named in XR_API_LAYER_PATH and enabled with
 * XR_ENABLE_API_LAYERS=XR_APILAYER_HOLONOMY_inject.
 *
 * For the panel's quad layer (tests/xr/quad.sh): HOL_INJECT_LAYERS_AT=K
 * prints, on stderr, the layers the application submits in xrEndFrame
 * once K frames have ended ("inject: frame K: 2 layers: projection(2
 * views) quad(...)"), as the runtime receives them; and
 * HOL_INJECT_SWAPCHAIN_FAIL=N makes the N-th xrCreateSwapchain (1: the
 * first) fail with XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED, as a runtime
 * that cannot make it would.
 *
 * For seated play (holonomy xr --seated; Monado's simulated simple
 * controllers have no thumbstick): HOL_INJECT_STICK_AT=K makes every
 * xrGetActionStateVector2f an active stick pushed ahead (0, 1) while
 * K..K+19 frames have ended, to the right (1, 0) while K+40..K+59 have,
 * and at rest (0, 0) otherwise.
 *
 * For the tracked hands (XR_EXT_hand_tracking, issue 36): Monado's
 * simulated controllers track no hands (the system says
 * supportsHandTracking false), so HOL_INJECT_HANDS=down (or up) makes the
 * system say true and answers xrCreateHandTrackerEXT,
 * xrLocateHandJointsEXT and xrDestroyHandTrackerEXT itself: two open hands
 * of the default joint set (26 joints, all valid and tracked), their
 * wrists 0.15 m either side of the stage's -z axis, 1.45 m high and
 * 0.4 m ahead, fingers along -z, palms down (or up: the hands-only
 * recentre's gesture), in the base space asked for (the app's stage).
 * Nothing of it reaches the runtime. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <openxr/openxr.h>
#include <openxr/openxr_loader_negotiation.h>

#define LAYER_NAME "XR_APILAYER_HOLONOMY_inject"

static PFN_xrGetInstanceProcAddr next_gipa;
static PFN_xrPollEvent next_poll;
static PFN_xrEndFrame next_end;
static PFN_xrCreateSession next_create_session;
static PFN_xrCreateSwapchain next_create_swapchain;
static PFN_xrGetActionStateVector2f next_vector2f;
static PFN_xrGetSystemProperties next_system_properties;
static XrSession session;
static long ended, at = 90, swapchains;
static int injected;

static XRAPI_ATTR XrResult XRAPI_CALL inject_create_session(XrInstance instance,
                                                            const XrSessionCreateInfo *info,
                                                            XrSession *out)
{
    XrResult r = next_create_session(instance, info, out);
    if (XR_SUCCEEDED(r))
        session = *out;
    return r;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_create_swapchain(XrSession s,
                                                              const XrSwapchainCreateInfo *info,
                                                              XrSwapchain *out)
{
    const char *f = getenv("HOL_INJECT_SWAPCHAIN_FAIL");
    if (f && *f && ++swapchains == strtol(f, NULL, 10))
        return XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED;
    return next_create_swapchain(s, info, out);
}

static int hands_wanted(void)
{
    const char *h = getenv("HOL_INJECT_HANDS");
    return h && *h;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_system_properties(XrInstance instance,
                                                               XrSystemId system,
                                                               XrSystemProperties *p)
{
    XrResult r = next_system_properties(instance, system, p);
    if (XR_SUCCEEDED(r) && hands_wanted())
        for (XrBaseOutStructure *n = (XrBaseOutStructure *)p->next; n; n = n->next)
            if (n->type == XR_TYPE_SYSTEM_HAND_TRACKING_PROPERTIES_EXT)
                ((XrSystemHandTrackingPropertiesEXT *)n)->supportsHandTracking = XR_TRUE;
    return r;
}

static long trackers; /* made and not destroyed */

static XRAPI_ATTR XrResult XRAPI_CALL inject_create_hand(XrSession s,
                                                         const XrHandTrackerCreateInfoEXT *ci,
                                                         XrHandTrackerEXT *out)
{
    if (s == XR_NULL_HANDLE || !ci || !out ||
        (ci->hand != XR_HAND_LEFT_EXT && ci->hand != XR_HAND_RIGHT_EXT))
        return XR_ERROR_VALIDATION_FAILURE;
    trackers++;
    *out = (XrHandTrackerEXT)(uintptr_t)(0x4a0du + (unsigned)ci->hand); /* 1 left, 2 right */
    return XR_SUCCESS;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_destroy_hand(XrHandTrackerEXT t)
{
    (void)t;
    trackers--;
    return XR_SUCCESS;
}

static void put(XrHandJointLocationEXT *j, float x, float y, float z)
{
    j->locationFlags = XR_SPACE_LOCATION_POSITION_VALID_BIT |
                       XR_SPACE_LOCATION_ORIENTATION_VALID_BIT |
                       XR_SPACE_LOCATION_POSITION_TRACKED_BIT |
                       XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
    j->pose.orientation.w = 1;
    j->pose.position.x = x;
    j->pose.position.y = y;
    j->pose.position.z = z;
    j->radius = 0.01f;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_locate_hand(XrHandTrackerEXT t,
                                                         const XrHandJointsLocateInfoEXT *li,
                                                         XrHandJointLocationsEXT *out)
{
    if (!li || !out || out->jointCount != XR_HAND_JOINT_COUNT_EXT || !out->jointLocations)
        return XR_ERROR_VALIDATION_FAILURE;
    int right = (uintptr_t)t == 0x4a0du + XR_HAND_RIGHT_EXT;
    const char *h = getenv("HOL_INJECT_HANDS");
    int up = h && !strcmp(h, "up");
    /* the thumb's side: palms down, the right hand's thumb is towards -x */
    float side = (right ? -1.0f : 1.0f) * (up ? -1.0f : 1.0f);
    float wx = right ? 0.15f : -0.15f, wy = 1.45f, wz = -0.4f;
    XrHandJointLocationEXT *j = out->jointLocations;
    memset(j, 0, XR_HAND_JOINT_COUNT_EXT * sizeof *j);
    put(&j[XR_HAND_JOINT_PALM_EXT], wx, wy, wz - 0.05f);
    put(&j[XR_HAND_JOINT_WRIST_EXT], wx, wy, wz);
    for (int k = 0; k < 4; k++) /* the thumb, out to the side */
        put(&j[XR_HAND_JOINT_THUMB_METACARPAL_EXT + k], wx + side * (0.03f + 0.012f * (float)k),
            wy, wz - 0.02f - 0.018f * (float)k);
    for (int f = 0; f < 4; f++) /* index, middle, ring, little */
        for (int k = 0; k < 5; k++)
            put(&j[XR_HAND_JOINT_INDEX_METACARPAL_EXT + 5 * f + k],
                wx + side * (0.02f - 0.017f * (float)f), wy, wz - 0.05f - 0.025f * (float)k);
    out->isActive = XR_TRUE;
    return XR_SUCCESS;
}

/* The submitted layers, one line (HOL_INJECT_LAYERS_AT). */
static void print_layers(const XrFrameEndInfo *info)
{
    fprintf(stderr, "inject: frame %ld: %u layers:", ended, info->layerCount);
    for (uint32_t i = 0; i < info->layerCount; i++) {
        const XrCompositionLayerBaseHeader *h = info->layers[i];
        if (h->type == XR_TYPE_COMPOSITION_LAYER_PROJECTION) {
            fprintf(stderr, " projection(%u views)",
                    ((const XrCompositionLayerProjection *)h)->viewCount);
        } else if (h->type == XR_TYPE_COMPOSITION_LAYER_QUAD) {
            const XrCompositionLayerQuad *q = (const XrCompositionLayerQuad *)h;
            fprintf(stderr,
                    " quad(eyes %s, size %.3f %.3f, position %.3f %.3f %.3f, rect %dx%d, "
                    "source alpha %s)",
                    q->eyeVisibility == XR_EYE_VISIBILITY_BOTH ? "both" : "one",
                    q->size.width, q->size.height, q->pose.position.x, q->pose.position.y,
                    q->pose.position.z, q->subImage.imageRect.extent.width,
                    q->subImage.imageRect.extent.height,
                    h->layerFlags & XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT ? "yes"
                                                                                        : "no");
        } else {
            fprintf(stderr, " other(%d)", (int)h->type);
        }
    }
    fprintf(stderr, "\n");
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_end_frame(XrSession s, const XrFrameEndInfo *info)
{
    const char *k = getenv("HOL_INJECT_LAYERS_AT");
    if (k && *k && ended == strtol(k, NULL, 10))
        print_layers(info);
    XrResult r = next_end(s, info);
    if (XR_SUCCEEDED(r))
        ended++;
    return r;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_vector2f(XrSession s, const XrActionStateGetInfo *gi,
                                                      XrActionStateVector2f *st)
{
    const char *k = getenv("HOL_INJECT_STICK_AT");
    XrResult r = next_vector2f(s, gi, st);
    if (!k || !*k || XR_FAILED(r))
        return r;
    long d = ended - strtol(k, NULL, 10);
    st->isActive = XR_TRUE;
    st->currentState.x = d >= 40 && d < 60 ? 1.0f : 0.0f;
    st->currentState.y = d >= 0 && d < 20 ? 1.0f : 0.0f;
    return r;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_poll(XrInstance instance, XrEventDataBuffer *ev)
{
    if (injected || ended < at || session == XR_NULL_HANDLE)
        return next_poll(instance, ev);
    const char *sp = getenv("HOL_INJECT_SPACE");
    XrEventDataReferenceSpaceChangePending *e = (XrEventDataReferenceSpaceChangePending *)ev;
    memset(e, 0, sizeof *e);
    e->type = XR_TYPE_EVENT_DATA_REFERENCE_SPACE_CHANGE_PENDING;
    e->session = session;
    e->referenceSpaceType = sp && !strcmp(sp, "LOCAL") ? XR_REFERENCE_SPACE_TYPE_LOCAL
                                                       : XR_REFERENCE_SPACE_TYPE_STAGE;
    e->poseValid = XR_TRUE;
    e->poseInPreviousSpace.orientation.w = 1;
    injected = 1;
    return XR_SUCCESS;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_gipa(XrInstance instance, const char *name,
                                                  PFN_xrVoidFunction *out)
{
    if (!strcmp(name, "xrGetInstanceProcAddr"))
        *out = (PFN_xrVoidFunction)inject_gipa;
    else if (!strcmp(name, "xrPollEvent"))
        *out = (PFN_xrVoidFunction)inject_poll;
    else if (!strcmp(name, "xrEndFrame"))
        *out = (PFN_xrVoidFunction)inject_end_frame;
    else if (!strcmp(name, "xrCreateSession"))
        *out = (PFN_xrVoidFunction)inject_create_session;
    else if (!strcmp(name, "xrCreateSwapchain"))
        *out = (PFN_xrVoidFunction)inject_create_swapchain;
    else if (!strcmp(name, "xrGetActionStateVector2f"))
        *out = (PFN_xrVoidFunction)inject_vector2f;
    else if (!strcmp(name, "xrGetSystemProperties"))
        *out = (PFN_xrVoidFunction)inject_system_properties;
    else if (hands_wanted() && !strcmp(name, "xrCreateHandTrackerEXT"))
        *out = (PFN_xrVoidFunction)inject_create_hand;
    else if (hands_wanted() && !strcmp(name, "xrLocateHandJointsEXT"))
        *out = (PFN_xrVoidFunction)inject_locate_hand;
    else if (hands_wanted() && !strcmp(name, "xrDestroyHandTrackerEXT"))
        *out = (PFN_xrVoidFunction)inject_destroy_hand;
    else
        return next_gipa(instance, name, out);
    return XR_SUCCESS;
}

static XRAPI_ATTR XrResult XRAPI_CALL inject_create_instance(const XrInstanceCreateInfo *info,
                                                             const XrApiLayerCreateInfo *li,
                                                             XrInstance *out)
{
    if (!li || !li->nextInfo || strcmp(li->nextInfo->layerName, LAYER_NAME))
        return XR_ERROR_INITIALIZATION_FAILED;
    next_gipa = li->nextInfo->nextGetInstanceProcAddr;
    XrApiLayerCreateInfo down = *li;
    down.nextInfo = li->nextInfo->next;
    XrResult r = li->nextInfo->nextCreateApiLayerInstance(info, &down, out);
    if (XR_FAILED(r))
        return r;
    const char *a = getenv("HOL_INJECT_AT");
    if (a && *a)
        at = strtol(a, NULL, 10);
    if (XR_FAILED(next_gipa(*out, "xrPollEvent", (PFN_xrVoidFunction *)&next_poll)) ||
        XR_FAILED(next_gipa(*out, "xrEndFrame", (PFN_xrVoidFunction *)&next_end)) ||
        XR_FAILED(next_gipa(*out, "xrCreateSession",
                            (PFN_xrVoidFunction *)&next_create_session)) ||
        XR_FAILED(next_gipa(*out, "xrCreateSwapchain",
                            (PFN_xrVoidFunction *)&next_create_swapchain)) ||
        XR_FAILED(next_gipa(*out, "xrGetActionStateVector2f",
                            (PFN_xrVoidFunction *)&next_vector2f)) ||
        XR_FAILED(next_gipa(*out, "xrGetSystemProperties",
                            (PFN_xrVoidFunction *)&next_system_properties)))
        return XR_ERROR_INITIALIZATION_FAILED;
    return XR_SUCCESS;
}

XRAPI_ATTR XrResult XRAPI_CALL xrNegotiateLoaderApiLayerInterface(
    const XrNegotiateLoaderInfo *loader, const char *name, XrNegotiateApiLayerRequest *req);

XRAPI_ATTR XrResult XRAPI_CALL xrNegotiateLoaderApiLayerInterface(
    const XrNegotiateLoaderInfo *loader, const char *name, XrNegotiateApiLayerRequest *req)
{
    if (!loader || !req || !name || strcmp(name, LAYER_NAME) ||
        loader->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
        req->structType != XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST ||
        loader->minInterfaceVersion > XR_CURRENT_LOADER_API_LAYER_VERSION ||
        loader->maxInterfaceVersion < XR_CURRENT_LOADER_API_LAYER_VERSION)
        return XR_ERROR_INITIALIZATION_FAILED;
    req->layerInterfaceVersion = XR_CURRENT_LOADER_API_LAYER_VERSION;
    req->layerApiVersion = XR_CURRENT_API_VERSION;
    req->getInstanceProcAddr = inject_gipa;
    req->createApiLayerInstance = inject_create_instance;
    return XR_SUCCESS;
}
