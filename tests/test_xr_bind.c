/* test_xr_bind.c - the headset's suggested bindings and button mapping
 * (platform/openxr/hol_xr_bind.h), without a runtime. The model: the input
 * paths each interaction profile defines, copied from the OpenXR 1.0
 * specification (section 6.4, "Interaction Profile Paths"); a binding
 * outside its profile's list is what a runtime refuses with
 * XR_ERROR_PATH_UNSUPPORTED. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_input.h"
#include "../core/hol_prompt.h"
#include "../platform/openxr/hol_xr_bind.h"

typedef struct spec_profile {
    const char *name;
    const char *left[24], *right[24]; /* input/... components per hand */
} spec_profile;

static const spec_profile spec[] = {
    {"/interaction_profiles/khr/simple_controller",
     {"select/click", "menu/click", "grip/pose", "aim/pose"},
     {"select/click", "menu/click", "grip/pose", "aim/pose"}},
    {"/interaction_profiles/oculus/touch_controller",
     {"x/click", "x/touch", "y/click", "y/touch", "menu/click", "squeeze/value",
      "trigger/value", "trigger/touch", "thumbstick/x", "thumbstick/y", "thumbstick/click",
      "thumbstick/touch", "thumbrest/touch", "grip/pose", "aim/pose"},
     {"a/click", "a/touch", "b/click", "b/touch", "system/click", "squeeze/value",
      "trigger/value", "trigger/touch", "thumbstick/x", "thumbstick/y", "thumbstick/click",
      "thumbstick/touch", "thumbrest/touch", "grip/pose", "aim/pose"}},
    {"/interaction_profiles/htc/vive_controller",
     {"system/click", "squeeze/click", "menu/click", "trigger/click", "trigger/value",
      "trackpad/x", "trackpad/y", "trackpad/click", "trackpad/touch", "grip/pose", "aim/pose"},
     {"system/click", "squeeze/click", "menu/click", "trigger/click", "trigger/value",
      "trackpad/x", "trackpad/y", "trackpad/click", "trackpad/touch", "grip/pose", "aim/pose"}},
    {"/interaction_profiles/valve/index_controller",
     {"system/click", "system/touch", "a/click", "a/touch", "b/click", "b/touch",
      "squeeze/value", "squeeze/force", "trigger/click", "trigger/value", "trigger/touch",
      "thumbstick/x", "thumbstick/y", "thumbstick/click", "thumbstick/touch", "trackpad/x",
      "trackpad/y", "trackpad/force", "trackpad/touch", "grip/pose", "aim/pose"},
     {"system/click", "system/touch", "a/click", "a/touch", "b/click", "b/touch",
      "squeeze/value", "squeeze/force", "trigger/click", "trigger/value", "trigger/touch",
      "thumbstick/x", "thumbstick/y", "thumbstick/click", "thumbstick/touch", "trackpad/x",
      "trackpad/y", "trackpad/force", "trackpad/touch", "grip/pose", "aim/pose"}},
    {"/interaction_profiles/microsoft/motion_controller",
     {"menu/click", "squeeze/click", "trigger/value", "thumbstick/x", "thumbstick/y",
      "thumbstick/click", "trackpad/x", "trackpad/y", "trackpad/click", "trackpad/touch",
      "grip/pose", "aim/pose"},
     {"menu/click", "squeeze/click", "trigger/value", "thumbstick/x", "thumbstick/y",
      "thumbstick/click", "trackpad/x", "trackpad/y", "trackpad/click", "trackpad/touch",
      "grip/pose", "aim/pose"}},
    /* XR_EXT_hand_interaction (the extension's chapter: "The interaction
     * profile path is /interaction_profiles/ext/hand_interaction_ext"),
     * the same components on both hands, no output */
    {"/interaction_profiles/ext/hand_interaction_ext",
     {"aim/pose", "grip/pose", "pinch_ext/pose", "poke_ext/pose", "pinch_ext/value",
      "pinch_ext/ready_ext", "aim_activate_ext/value", "aim_activate_ext/ready_ext",
      "grasp_ext/value", "grasp_ext/ready_ext"},
     {"aim/pose", "grip/pose", "pinch_ext/pose", "poke_ext/pose", "pinch_ext/value",
      "pinch_ext/ready_ext", "aim_activate_ext/value", "aim_activate_ext/ready_ext",
      "grasp_ext/value", "grasp_ext/ready_ext"}},
};
#define NSPEC (sizeof spec / sizeof spec[0])

/* 1 when path is "/user/hand/{left,right}/input/" + a component the
 * profile defines for that hand */
static int spec_has(const spec_profile *p, const char *path)
{
    static const char *const pre[2] = {"/user/hand/left/input/", "/user/hand/right/input/"};
    for (int h = 0; h < 2; h++) {
        size_t n = strlen(pre[h]);
        if (strncmp(path, pre[h], n))
            continue;
        const char *const *c = h ? p->right : p->left;
        for (int i = 0; i < 24 && c[i]; i++)
            if (!strcmp(path + n, c[i]))
                return 1;
    }
    return 0;
}

static const spec_profile *spec_of(const char *name)
{
    for (size_t i = 0; i < NSPEC; i++)
        if (!strcmp(spec[i].name, name))
            return &spec[i];
    return NULL;
}

static void test_the_five_profiles(void **state)
{
    (void)state;
    const hol_xr_profile *p = hol_xr_profiles();
    assert_int_equal(HOL_XR_NPROFILES, NSPEC);
    for (size_t i = 0; i < NSPEC; i++) {
        int seen = 0;
        for (int k = 0; k < HOL_XR_NPROFILES; k++)
            seen += !strcmp(p[k].profile, spec[i].name);
        assert_int_equal(seen, 1);
    }
}

static void test_every_binding_is_in_its_profile(void **state)
{
    (void)state;
    const hol_xr_profile *p = hol_xr_profiles();
    for (int k = 0; k < HOL_XR_NPROFILES; k++) {
        const spec_profile *s = spec_of(p[k].profile);
        assert_non_null(s);
        assert_int_equal(hol_xr_profile_find(p[k].profile), k);
        assert_string_equal(p[k].profile + strlen("/interaction_profiles/"), p[k].name);
        for (int h = 0; h < 2; h++)
            assert_true(spec_has(s, hol_xr_grip_path(h)));
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
            assert_non_null(p[k].path[a]);
            if (!spec_has(s, p[k].path[a]))
                fail_msg("%s: %s not in the profile", p[k].profile, p[k].path[a]);
            /* a label names the input: one label per path */
            assert_true(strlen(hol_xr_input_label(k, a)) > 0);
            for (int b = 0; b < a; b++)
                assert_int_equal(!strcmp(p[k].path[a], p[k].path[b]),
                                 !strcmp(hol_xr_input_label(k, a), hol_xr_input_label(k, b)));
        }
        /* confirm is on the right hand (the minimap hand is the left) */
        assert_true(!strncmp(p[k].path[HOL_XR_ACT_CONFIRM], "/user/hand/right/", 17));
    }
    /* the model catches a wrong path */
    assert_false(spec_has(spec_of("/interaction_profiles/khr/simple_controller"),
                          "/user/hand/right/input/a/click"));
    assert_false(spec_has(spec_of("/interaction_profiles/oculus/touch_controller"),
                          "/user/hand/right/input/x/click"));
    assert_int_equal(hol_xr_profile_find("/interaction_profiles/khr/simple"), -1);
    /* the input record's device: the prompts name this profile's buttons */
    static const struct {
        const char *path;
        uint32_t device;
    } dev[] = {{"/interaction_profiles/khr/simple_controller", HOL_DEVICE_XR_SIMPLE},
               {"/interaction_profiles/oculus/touch_controller", HOL_DEVICE_XR_TOUCH},
               {"/interaction_profiles/htc/vive_controller", HOL_DEVICE_XR_VIVE},
               {"/interaction_profiles/valve/index_controller", HOL_DEVICE_XR_INDEX},
               {"/interaction_profiles/microsoft/motion_controller", HOL_DEVICE_XR_WMR},
               {"/interaction_profiles/ext/hand_interaction_ext", HOL_DEVICE_XR_HAND}};
    for (size_t i = 0; i < sizeof dev / sizeof dev[0]; i++)
        assert_int_equal(hol_xr_profile_device(hol_xr_profile_find(dev[i].path)), dev[i].device);
    /* the core profiles need no extension; the hands need
     * XR_EXT_hand_interaction (suggested only where it is enabled) and have
     * no haptic output */
    for (int k = 0; k < HOL_XR_NPROFILES; k++) {
        int hands = !strcmp(p[k].name, "ext/hand_interaction_ext");
        assert_int_equal(p[k].extension != NULL, hands);
        assert_int_equal(p[k].no_haptic, hands);
        if (hands)
            assert_string_equal(p[k].extension, "XR_EXT_hand_interaction");
    }
    assert_int_equal(hol_xr_profile_device(-1), HOL_DEVICE_XR);
    assert_int_equal(hol_xr_profile_find(NULL), -1);
    assert_string_equal(hol_xr_input_label(HOL_XR_NPROFILES, 0), "");
}

/* Issue 18: quit, menu, restart and recentre in every profile; within a
 * layer, one input per action. */
/* Seated play's sticks (holonomy xr --seated): each a vector2f path whose
 * /x and /y its profile defines for that hand; the thumbstick of Touch,
 * Index and WMR, the Vive's trackpad; none on the simple controller or
 * the hands. */
static void test_seated_sticks(void **state)
{
    (void)state;
    const hol_xr_profile *p = hol_xr_profiles();
    int with = 0;
    for (int k = 0; k < HOL_XR_NPROFILES; k++) {
        const spec_profile *s = spec_of(p[k].profile);
        for (int h = 0; h < 2; h++) {
            const char *st = hol_xr_stick_path(k, h);
            if (!st)
                continue;
            with += h;
            char c[160];
            for (int a = 0; a < 2; a++) {
                snprintf(c, sizeof c, "%s/%c", st, "xy"[a]);
                if (!spec_has(s, c))
                    fail_msg("%s: %s not in the profile", p[k].profile, c);
            }
            assert_true(!strncmp(st, h ? "/user/hand/right/" : "/user/hand/left/", h ? 17 : 16));
        }
    }
    assert_int_equal(with, 4);
    assert_null(hol_xr_stick_path(hol_xr_profile_find("/interaction_profiles/khr/simple_controller"), 1));
    assert_null(hol_xr_stick_path(-1, 0));
    assert_null(hol_xr_stick_path(0, 2));
}

static void test_every_profile_reaches_every_action(void **state)
{
    (void)state;
    const hol_xr_profile *p = hol_xr_profiles();
    static const int play[] = {HOL_XR_ACT_CONFIRM, HOL_XR_ACT_MENU, HOL_XR_ACT_RECENTRE,
                               HOL_XR_ACT_MINIMAP};
    static const int menu[] = {HOL_XR_ACT_MENU, HOL_XR_ACT_RESTART, HOL_XR_ACT_QUIT};
    for (int i = 0; i < 4; i++)
        assert_true(hol_xr_action_in_layer(play[i], 0));
    for (int i = 0; i < 3; i++)
        assert_true(hol_xr_action_in_layer(menu[i], 1));
    /* restart and quit never while playing: not one accidental press away */
    assert_false(hol_xr_action_in_layer(HOL_XR_ACT_RESTART, 0));
    assert_false(hol_xr_action_in_layer(HOL_XR_ACT_QUIT, 0));
    for (int k = 0; k < HOL_XR_NPROFILES; k++)
        for (int layer = 0; layer < 2; layer++)
            for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
                for (int b = 0; b < a; b++)
                    if (hol_xr_action_in_layer(a, layer) && hol_xr_action_in_layer(b, layer) &&
                        !strcmp(p[k].path[a], p[k].path[b]))
                        fail_msg("%s: %s and %s share %s in one layer", p[k].name,
                                 hol_xr_action_name(a), hol_xr_action_name(b), p[k].path[a]);
}

static uint32_t press(hol_xr_keys *k, unsigned held_mask, int in_menu)
{
    int held[HOL_XR_ACT_COUNT];
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
        held[a] = (int)(held_mask >> a & 1) * (a + 1); /* any nonzero is held */
    return hol_xr_buttons(k, held, in_menu);
}

/* The haptic output: the spec gives every one of the five profiles one
 * output per hand, /user/hand/{left,right}/output/haptic (section 6.4:
 * "Supported component paths ... .../output/haptic"); the vibration
 * action binds it on each, one path per hand (its subaction path). */
static int spec_has_output(const char *name, const char *path)
{
    static const char *const out[2] = {"/user/hand/left/output/haptic",
                                       "/user/hand/right/output/haptic"};
    if (!spec_of(name))
        return 0;
    return !strcmp(path, out[0]) || !strcmp(path, out[1]);
}

static void test_haptic_output(void **state)
{
    (void)state;
    const hol_xr_profile *p = hol_xr_profiles();
    for (int i = 0; i < HOL_XR_NPROFILES; i++)
        for (int h = 0; h < 2 && !p[i].no_haptic; h++) {
            const char *path = hol_xr_haptic_path(h);
            assert_true(spec_has_output(p[i].profile, path));
            assert_non_null(strstr(path, h ? "/right/" : "/left/"));
            /* an output, never one of the inputs an action reads */
            assert_false(spec_has(spec_of(p[i].profile), path));
        }
    assert_string_not_equal(hol_xr_haptic_path(0), hol_xr_haptic_path(1));
}

static void test_buttons(void **state)
{
    (void)state;
    static const uint32_t want[HOL_XR_ACT_COUNT] = {HOL_BTN_CONFIRM,  HOL_BTN_MENU,
                                                     HOL_BTN_RECENTRE, HOL_BTN_MINIMAP,
                                                     HOL_BTN_RESTART,  HOL_BTN_QUIT};
    /* a layer held steadily: every combination of the actions it has */
    for (int layer = 0; layer < 2; layer++)
        for (unsigned m = 0; m < 1u << HOL_XR_ACT_COUNT; m++) {
            hol_xr_keys k = {layer, 0};
            uint32_t expect = 0;
            for (int a = 0; a < HOL_XR_ACT_COUNT; a++)
                expect |= (m >> a & 1) && hol_xr_action_in_layer(a, layer) ? want[a] : 0;
            assert_int_equal(press(&k, m, layer), expect);
        }
    for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
        assert_true(strlen(hol_xr_action_name(a)) > 0);
        assert_true(strlen(hol_xr_action_label(a)) > 0);
    }
}

/* One press never acts in both layers: the input held while the layer
 * changes counts again only after a release. */
static void test_layer_change_waits_for_a_release(void **state)
{
    (void)state;
    hol_xr_keys k;
    memset(&k, 0, sizeof k);
    const unsigned menu = 1u << HOL_XR_ACT_MENU, a_btn = 1u << HOL_XR_ACT_CONFIRM;
    assert_int_equal(press(&k, menu, 0), HOL_BTN_MENU); /* opens the menu */
    assert_int_equal(press(&k, menu, 1), 0);            /* still held: not again */
    assert_int_equal(press(&k, 0, 1), 0);
    /* in the menu, the confirm input restarts (it is bound to both) */
    assert_int_equal(press(&k, a_btn | 1u << HOL_XR_ACT_RESTART, 1), HOL_BTN_RESTART);
    /* the menu closes while it is held: no confirm from that press */
    assert_int_equal(press(&k, a_btn | 1u << HOL_XR_ACT_RESTART, 0), 0);
    assert_int_equal(press(&k, a_btn | 1u << HOL_XR_ACT_RESTART, 0), 0);
    assert_int_equal(press(&k, 0, 0), 0);
    assert_int_equal(press(&k, a_btn | 1u << HOL_XR_ACT_RESTART, 0), HOL_BTN_CONFIRM);
    /* an input pressed after the change counts at once */
    assert_int_equal(press(&k, a_btn, 1), 0);
    assert_int_equal(press(&k, a_btn | 1u << HOL_XR_ACT_QUIT, 1), HOL_BTN_QUIT);
}

/* The prompts' words (core/hol_prompt.h) follow each profile's bindings:
 * the bound component in capitals ("a/click": "A", "trackpad/click":
 * "TRACKPAD"), "LEFT " before it on the left hand when the right hand has
 * a component of that name too; an action the profile does not bind has
 * no word, nor has restart (the pause menu's, on confirm's input). */
static void test_prompt_words(void **state)
{
    (void)state;
    static const struct {
        const char *profile;
        uint32_t device;
    } dev[] = {
        {"/interaction_profiles/khr/simple_controller", HOL_DEVICE_XR_SIMPLE},
        {"/interaction_profiles/oculus/touch_controller", HOL_DEVICE_XR_TOUCH},
        {"/interaction_profiles/htc/vive_controller", HOL_DEVICE_XR_VIVE},
        {"/interaction_profiles/valve/index_controller", HOL_DEVICE_XR_INDEX},
        {"/interaction_profiles/microsoft/motion_controller", HOL_DEVICE_XR_WMR},
        {"/interaction_profiles/ext/hand_interaction_ext", HOL_DEVICE_XR_HAND},
    };
    const hol_xr_profile *p = hol_xr_profiles();
    for (int k = 0; k < HOL_XR_NPROFILES; k++) {
        uint32_t device = HOL_DEVICE_NONE;
        const spec_profile *sp = NULL;
        for (size_t j = 0; j < sizeof dev / sizeof dev[0]; j++)
            if (!strcmp(dev[j].profile, p[k].profile))
                device = dev[j].device;
        for (size_t j = 0; j < NSPEC; j++)
            if (!strcmp(spec[j].name, p[k].profile))
                sp = &spec[j];
        if (device == HOL_DEVICE_NONE || !sp)
            fail_msg("profile %s has no HOL_DEVICE_* value", p[k].profile);
        uint32_t bound = 0;
        /* restart has no word: it is the menu's, on confirm's input, and the
         * menu's prompt names confirm's control for it */
        assert_string_equal(p[k].path[HOL_XR_ACT_RESTART], p[k].path[HOL_XR_ACT_CONFIRM]);
        assert_null(hol_prompt_button(device, HOL_BTN_RESTART));
        for (int a = 0; a < HOL_XR_ACT_COUNT; a++) {
            if (a == HOL_XR_ACT_RESTART)
                continue;
            int held[HOL_XR_ACT_COUNT] = {0};
            held[a] = 1;
            /* the action in the layer it counts in (restart, quit: the menu) */
            int in_menu = !hol_xr_action_in_layer(a, 0);
            hol_xr_keys keys = {in_menu, 0};
            uint32_t btn = hol_xr_buttons(&keys, held, in_menu);
            bound |= btn;
            const char *path = p[k].path[a];
            int left = !strncmp(path, "/user/hand/left/input/", 22);
            const char *comp = path + (left ? 22 : 23);
            size_t n = strcspn(comp, "/");
            int both = 0;
            const char *const *other = left ? sp->right : sp->left;
            for (int i = 0; i < 16 && other[i]; i++)
                both |= !strncmp(other[i], comp, n) && other[i][n] == '/';
            if (n > 4 && !strncmp(comp + n - 4, "_ext", 4))
                n -= 4; /* an extension's component: "pinch_ext" is "PINCH" */
            char want[64];
            size_t w = 0;
            if (left && both)
                w = (size_t)snprintf(want, sizeof want, "LEFT ");
            for (size_t i = 0; i < n && w + 1 < sizeof want; i++)
                want[w++] = (char)(comp[i] >= 'a' && comp[i] <= 'z' ? comp[i] - 32 : comp[i]);
            want[w] = 0;
            const char *got = hol_prompt_button(device, btn);
            if (!got || strcmp(got, want))
                fail_msg("%s: the prompt for %s says '%s', the binding %s", p[k].profile,
                         hol_xr_action_name(a), got ? got : "(none)", path);
        }
        for (uint32_t b = 1; b <= HOL_BTN_ALL; b <<= 1)
            if (!(bound & b) && hol_prompt_button(device, b))
                fail_msg("%s: a word for button %x that no action binds", p[k].profile, b);
    }
}

/* Issue 20 item 4: the native Touch's buttons are the web build's
 * (platform/web/hol_web_xr.h: right A confirm, left Y menu, left X
 * minimap, left thumbstick press recentre, right B quits in the menu),
 * and the prompts name the same buttons on both. */
static void test_touch_as_the_web(void **state)
{
    (void)state;
    int k = hol_xr_profile_find("/interaction_profiles/oculus/touch_controller");
    assert_true(k >= 0);
    const hol_xr_profile *p = &hol_xr_profiles()[k];
    static const struct {
        int act;
        const char *path;
        uint32_t btn;
    } web[] = {
        {HOL_XR_ACT_CONFIRM, "/user/hand/right/input/a/click", HOL_BTN_CONFIRM},
        {HOL_XR_ACT_MENU, "/user/hand/left/input/y/click", HOL_BTN_MENU},
        {HOL_XR_ACT_MINIMAP, "/user/hand/left/input/x/click", HOL_BTN_MINIMAP},
        {HOL_XR_ACT_RECENTRE, "/user/hand/left/input/thumbstick/click", HOL_BTN_RECENTRE},
        {HOL_XR_ACT_QUIT, "/user/hand/right/input/b/click", 0},
    };
    for (size_t i = 0; i < sizeof web / sizeof web[0]; i++) {
        assert_string_equal(p->path[web[i].act], web[i].path);
        if (web[i].btn)
            assert_string_equal(hol_prompt_button(HOL_DEVICE_XR_TOUCH, web[i].btn),
                                hol_prompt_button(HOL_DEVICE_WEBXR_TOUCH, web[i].btn));
    }
    /* quit: the native menu's own input, the web's back; both B */
    assert_string_equal(hol_prompt_button(HOL_DEVICE_XR_TOUCH, HOL_BTN_QUIT),
                        hol_prompt_button(HOL_DEVICE_WEBXR_TOUCH, HOL_BTN_BACK));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_prompt_words),
        cmocka_unit_test(test_touch_as_the_web),
        cmocka_unit_test(test_the_five_profiles),
        cmocka_unit_test(test_every_binding_is_in_its_profile),
        cmocka_unit_test(test_every_profile_reaches_every_action),
        cmocka_unit_test(test_seated_sticks),
        cmocka_unit_test(test_buttons),
        cmocka_unit_test(test_haptic_output),
        cmocka_unit_test(test_layer_change_waits_for_a_release),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
