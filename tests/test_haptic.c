/* test_haptic.c - the controllers' pulses (core/hol_haptic.h): contacts
 * against an independent model (the trunks as a list of the grid's
 * vertices, the hedges as "outside the floor"); one short pulse a hand
 * going in, none while it stays, none again before it came out by the
 * clearance; a gentle pulse on each room step; the off switch; and the app
 * step's output (hol_app_events.haptic) with desc.no_haptics.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../core/hol_app.h"
#include "../core/hol_haptic.h"
#include "../core/hol_nav.h"

/* The model: what a point touches, by brute force over every vertex. */
static int model_contact(double x, double y, double z, int c, int r, double m)
{
    if (y < 0)
        return HOL_HAPTIC_NONE;
    if (y < 2.0 && (x < 0 || z < 0 || x > c * m || z > r * m))
        return HOL_HAPTIC_HEDGE;
    if (y >= 3.2)
        return HOL_HAPTIC_NONE;
    for (int i = 0; i <= c; i++)
        for (int j = 0; j <= r; j++)
            if (hypot(x - i * m, z - j * m) < 0.11)
                return HOL_HAPTIC_TRUNK;
    return HOL_HAPTIC_NONE;
}

static void test_contact_model(void **state)
{
    (void)state;
    static const struct { int c, r; double m; } rooms[] = {{3, 3, 1}, {4, 5, 0.75}, {5, 5, 0.6},
                                                             {3, 4, 1.5}};
    long checked = 0, trunks = 0, hedges = 0;
    for (int k = 0; k < 4; k++) {
        int c = rooms[k].c, r = rooms[k].r;
        double m = rooms[k].m;
        for (double x = -0.3; x < c * m + 0.3; x += 0.0137)
            for (double z = -0.3; z < r * m + 0.3; z += 0.0173)
                for (double y = -0.1; y < 3.5; y += 0.7) {
                    /* skip points within 1e-6 of a surface (float rounding) */
                    float p[3] = {(float)x, (float)y, (float)z};
                    int want = model_contact(p[0], p[1], p[2], c, r, m);
                    int got = hol_haptic_contact(p, c, r, m, 0);
                    assert_int_equal(got, want);
                    checked++;
                    trunks += got == HOL_HAPTIC_TRUNK;
                    hedges += got == HOL_HAPTIC_HEDGE;
                }
    }
    assert_true(checked > 100000);
    assert_true(trunks > 1000 && hedges > 10000);
}

static hol_input hands(double t, const float l[3], const float r[3])
{
    hol_input in;
    memset(&in, 0, sizeof in);
    in.time_s = t;
    in.flags = HOL_INPUT_FOCUSED;
    if (l) {
        in.flags |= HOL_INPUT_HAND_L_VALID;
        memcpy(in.hand[0].pos, l, sizeof in.hand[0].pos);
        in.hand[0].quat[3] = 1;
    }
    if (r) {
        in.flags |= HOL_INPUT_HAND_R_VALID;
        memcpy(in.hand[1].pos, r, sizeof in.hand[1].pos);
        in.hand[1].quat[3] = 1;
    }
    return in;
}

/* The right hand walks into the inner trunk at (1, 1) and out again. */
static void test_one_pulse_a_contact(void **state)
{
    (void)state;
    hol_haptic_state s;
    memset(&s, 0, sizeof s);
    hol_haptic out;
    const float left[3] = {1.5f, 1.0f, 1.5f};
    /* x from 0.7 towards the trunk at x = 1 (its surface at 0.89), z = 1 */
    static const struct { float x; int pulse; } path[] = {
        {0.70f, 0}, {0.85f, 0}, {0.90f, 1}, {0.95f, 0}, {0.90f, 0},
        {0.88f, 0}, /* out by 1 cm: not clear yet */
        {0.90f, 0}, /* back in: no second pulse */
        {0.86f, 0}, /* out by 3 cm: clear */
        {0.90f, 1}, /* in again: a pulse */
    };
    for (int i = 0; i < (int)(sizeof path / sizeof path[0]); i++) {
        const float right[3] = {path[i].x, 1.0f, 1.0f};
        hol_input in = hands(i / 60.0, left, right);
        hol_haptic_step(&s, &in, 3, 3, 1.0, 0, 1, &out);
        assert_true(out.hand[0].amplitude == 0); /* the other hand: nothing */
        if (path[i].pulse) {
            assert_true(out.hand[1].amplitude == HOL_HAPTIC_HIT_AMP);
            assert_int_equal(out.hand[1].duration_ms, HOL_HAPTIC_HIT_MS);
            assert_int_equal(out.hand[1].why, HOL_HAPTIC_TRUNK);
        } else {
            assert_true(out.hand[1].amplitude == 0);
        }
    }
}

/* The left hand pushes through the west hedge; the right is untracked. */
static void test_hedge_and_untracked(void **state)
{
    (void)state;
    hol_haptic_state s;
    memset(&s, 0, sizeof s);
    hol_haptic out;
    int pulses = 0;
    for (int i = 0; i < 40; i++) {
        const float left[3] = {0.3f - 0.02f * i, 1.2f, 1.5f}; /* to x = -0.48 */
        hol_input in = hands(i / 60.0, left, NULL);
        in.hand[1].pos[0] = 1.0f; /* the untracked hand's stale pose on a trunk */
        in.hand[1].pos[1] = 1.0f;
        in.hand[1].pos[2] = 1.0f;
        hol_haptic_step(&s, &in, 3, 3, 1.0, 0, 1, &out);
        assert_true(out.hand[1].amplitude == 0);
        if (out.hand[0].amplitude > 0) {
            pulses++;
            assert_int_equal(out.hand[0].why, HOL_HAPTIC_HEDGE);
            assert_true(left[0] < 0 && left[0] > -0.03f);
        }
    }
    assert_int_equal(pulses, 1);
    /* above the hedge's top: nothing to touch */
    memset(&s, 0, sizeof s);
    const float high[3] = {-0.2f, 2.3f, 1.5f};
    hol_input in = hands(1, high, NULL);
    hol_haptic_step(&s, &in, 3, 3, 1.0, 0, 1, &out);
    assert_true(out.hand[0].amplitude == 0);
}

/* Room steps: a gentle pulse on both tracked hands; a contact wins; the off
 * switch silences both and, switched on inside a trunk, does not pulse. */
static void test_steps_and_off(void **state)
{
    (void)state;
    hol_haptic_state s;
    memset(&s, 0, sizeof s);
    hol_haptic out;
    const float free_l[3] = {1.5f, 1.0f, 1.5f}, free_r[3] = {1.6f, 1.0f, 1.4f};
    hol_input in = hands(0, free_l, free_r);
    hol_haptic_step(&s, &in, 3, 3, 1.0, 1, 1, &out);
    for (int h = 0; h < 2; h++) {
        assert_true(out.hand[h].amplitude == HOL_HAPTIC_STEP_AMP);
        assert_int_equal(out.hand[h].duration_ms, HOL_HAPTIC_STEP_MS);
        assert_int_equal(out.hand[h].why, HOL_HAPTIC_STEP);
    }
    hol_haptic_step(&s, &in, 3, 3, 1.0, 0, 1, &out);
    assert_true(out.hand[0].amplitude == 0 && out.hand[1].amplitude == 0);
    const float trunk[3] = {2.0f, 1.0f, 2.05f};
    in = hands(0.1, free_l, trunk);
    hol_haptic_step(&s, &in, 3, 3, 1.0, 1, 1, &out);
    assert_int_equal(out.hand[0].why, HOL_HAPTIC_STEP);
    assert_int_equal(out.hand[1].why, HOL_HAPTIC_TRUNK);
    assert_true(out.hand[1].amplitude == HOL_HAPTIC_HIT_AMP);
    /* off */
    memset(&s, 0, sizeof s);
    in = hands(0.2, trunk, trunk);
    hol_haptic_step(&s, &in, 3, 3, 1.0, 2, 0, &out);
    assert_true(out.hand[0].amplitude == 0 && out.hand[1].amplitude == 0);
    hol_haptic_step(&s, &in, 3, 3, 1.0, 0, 1, &out); /* on again, still inside */
    assert_true(out.hand[0].amplitude == 0 && out.hand[1].amplitude == 0);
}

/* The app step's output: a tracked walk north with the right hand held out
 * into the trunk at (1, 1) on the way; desc.no_haptics silences it. */
static void app_pulses(int no_haptics, int *out_steps, int *out_trunks)
{
    hol_nav_desc nd;
    memset(&nd, 0, sizeof nd);
    hol_nav *nav = NULL;
    assert_int_equal(hol_nav_create(&nd, &nav), HOL_OK);
    hol_app_desc d;
    memset(&d, 0, sizeof d);
    d.nav = nav;
    d.no_haptics = no_haptics;
    hol_app *app = NULL;
    assert_int_equal(hol_app_create(&d, &app), HOL_OK);
    hol_app_level L;
    memset(&L, 0, sizeof L);
    L.seed = 9;
    assert_int_equal(hol_app_start_level(app, &L), HOL_OK);
    *out_steps = *out_trunks = 0;
    for (int f = 0; f <= 60; f++) {
        float z = 1.5f - f / 60.0f; /* the head from the centre of (1,1) to z = 0.5 */
        const float l[3] = {1.3f, 1.0f, z}, r[3] = {1.05f, 1.0f, z - 0.35f};
        hol_input in = hands(f / 60.0, l, r);
        in.flags |= HOL_INPUT_HEAD_VALID;
        in.head.pos[0] = 1.5f;
        in.head.pos[1] = 1.6f;
        in.head.pos[2] = z;
        in.head.quat[3] = 1;
        assert_int_equal(hol_app_step(app, &in), HOL_OK);
        const hol_app_events *ev = hol_app_get_events(app);
        if (ev->nsteps)
            assert_int_equal(ev->haptic.hand[0].why, no_haptics ? 0 : HOL_HAPTIC_STEP);
        *out_steps += ev->haptic.hand[0].why == HOL_HAPTIC_STEP;
        *out_trunks += ev->haptic.hand[1].why == HOL_HAPTIC_TRUNK;
    }
    hol_app_destroy(app);
    hol_nav_destroy(nav);
}

static void test_app_output(void **state)
{
    (void)state;
    int steps, trunks;
    app_pulses(0, &steps, &trunks);
    assert_int_equal(steps, 1);  /* z = 1 crossed once: one room step */
    assert_int_equal(trunks, 1); /* the right hand through the trunk at (1, 1) */
    app_pulses(1, &steps, &trunks);
    assert_int_equal(steps, 0);
    assert_int_equal(trunks, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_contact_model),
        cmocka_unit_test(test_one_pulse_a_contact),
        cmocka_unit_test(test_hedge_and_untracked),
        cmocka_unit_test(test_steps_and_off),
        cmocka_unit_test(test_app_output),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
