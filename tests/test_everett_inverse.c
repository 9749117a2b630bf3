/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's compensator (hyst_curve_inverse() of an
 * HYST_CURVE_EVERETT curve): for random E that init accepts, the drive it
 * gives for a desired output agrees with the exact inverse of a plain double
 * reference (the reference's response to the next input bisected); the
 * model driven by it reproduces the desired output; the drive never goes
 * back while the desired output moves on; block call = steps and restores
 * bit for bit; the inverse of the inverse is the forward curve. */
#include "comp_contract.h"
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 3000L

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xl3[CAP], yl3[CAP], xr3[CAP], yr3[CAP];
static hyst_real_t yd[SAMPLES], drive[SAMPLES], drive2[SAMPLES];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t fwd, inv;
static hyst_t C, M, T;
static ref_everett_t ref, probe; /* 16 KB each: off the stack */
static rng_t rng;

#ifdef HYST_USE_DOUBLE
#define DRIVE_AGREE 1e-9 /* of the drive span */
#else
#define DRIVE_AGREE 1e-5
#endif

void setUp(void) { rng_seed(&rng, 2718u); }
void tearDown(void) {}


/* The exact inverse: the input whose response is y. */
static double exact_drive(const ref_everett_t *r, double y) { return ref_everett_inverse(r, y, &probe); }

/* An accepted random E, its compensator C and model M. */
static hyst_everett_t accepted_e(void)
{
    for (;;) {
        const hyst_everett_t e = ref_everett_random(&rng);
        if (hyst_curve_from_everett(&fwd, &e) == HYST_OK) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&inv, &fwd));
            TEST_ASSERT_EQUAL_INT(HYST_CURVE_EVERETT_INV, (int)inv.kind);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &inv, xl, yl, xr, yr, CAP));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&M, &fwd, xl2, yl2, xr2, yr2, CAP));
            return e;
        }
    }
}

/* Desired outputs: a random walk with jumps over the major loop's range. */
static void desired(const hyst_everett_t *e, long n)
{
    double lo = e->y_lo, hi = e->y_lo + ref_everett_e(e, e->hi, e->lo), v;
    long k;
    if (SETUP_IN_FLOAT) { /* set up in float, the curve's ends may be a unit inside these */
        lo = (double)CURVE_NUM(fwd.y_lo);
        hi = (double)CURVE_NUM(fwd.y_hi);
    }
    v = 0.5 * (lo + hi);
    for (k = 0; k < n; ++k) {
        yd[k] = (hyst_real_t)ref_everett_walk(&rng, &v, lo, hi);
    }
}

static void test_drive_agrees_with_the_exact_inverse(void)
{
    double worst = 0.0, worst_out = 0.0;
    int trial;
    for (trial = 0; trial < 25; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double span = e.hi - e.lo, range = ref_everett_e(&e, e.hi, e.lo);
        long k;
        desired(&e, SAMPLES);
        ref_everett_init(&ref, &e);
        for (k = 0; k < SAMPLES; ++k) {
            const double x = (double)hyst_step(&C, yd[k]);
            const double exact = exact_drive(&ref, (double)yd[k]);
            const double d = fabs(x - exact) / span;
            const double out = fabs((double)hyst_step(&M, (hyst_real_t)x) - (double)yd[k]) / range;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&C));
            worst = d > worst ? d : worst;
            worst_out = out > worst_out ? out : worst_out;
            if (d > DRIVE_AGREE) {
                TEST_PRINTF("E %d degree %u sample %ld: drive %g, exact %g (%g of the span)",
                            trial, e.degree, k, x, exact, d);
                TEST_FAIL();
            }
            (void)ref_everett_step(&ref, exact);
        }
    }
    TEST_PRINTF("worst drive error %g of the span; model(drive) - desired: %g of the range",
                worst, worst_out);
    /* the model, in the variant's type, driven by the compensator */
    TEST_ASSERT_TRUE(worst_out < 10.0 * DRIVE_AGREE);
}

/* Sweeps by adjacent values up and down through many turning points: the
 * drive never moves against the desired output. */
static void test_drive_is_monotone(void)
{
    int trial;
    for (trial = 0; trial < 10; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double lo = e.y_lo, hi = e.y_lo + ref_everett_e(&e, e.hi, e.lo);
        contract_drive_is_monotone(&C, lo, hi, 1e-3, 20000L, &rng);
    }
}

/* Block call = steps; a snapshot taken anywhere continues bit for bit. */
static void test_block_and_snapshots(void)
{
    const hyst_everett_t e = accepted_e();
    const comp_instance_t a = {&C, &inv, xl, yl, xr, yr, CAP};
    const comp_instance_t b = {&T, &inv, xl3, yl3, xr3, yr3, CAP};
    desired(&e, SAMPLES);
    contract_block_and_snapshots(&a, &b, &M, yd, drive, drive2, SAMPLES, snap, sizeof snap);
}

/* Inverting twice gives the forward curve back; out-of-range and
 * non-finite desired outputs are clamped or ignored as for every kind. */
static void test_inverse_of_inverse_and_bad_input(void)
{
    hyst_curve_t back;
    hyst_real_t x;
    (void)accepted_e();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&back, &inv));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_EVERETT, (int)back.kind);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.lo, &back.lo, sizeof fwd.lo);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.hi, &back.hi, sizeof fwd.hi);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.y_lo, &back.y_lo, sizeof fwd.y_lo);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.y_hi, &back.y_hi, sizeof fwd.y_hi);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.unit, &back.unit, sizeof fwd.unit);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.rounding, &back.rounding, sizeof fwd.rounding);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.u.everett, &back.u.everett, sizeof fwd.u.everett);

    x = hyst_step(&C, CURVE_NUM(inv.hi) + 1);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&C));
    TEST_ASSERT_EQUAL_MEMORY(&CURVE_NUM(inv.y_hi), &x, sizeof x); /* the drive's top */
    x = hyst_step(&C, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_status(&C));
    TEST_ASSERT_EQUAL_MEMORY(&CURVE_NUM(inv.y_hi), &x, sizeof x); /* nothing lost */
}

/* A branch that starts flat to second order: E(a, lo) = 1.25 w^3 + 2.5 w^4,
 * so the rising branch from the domain's lower end is p(w) ~ w^3 there and
 * Newton's iteration only creeps towards its start (a ratio of 2/3 per
 * evaluation). Desired outputs (the model's own, so each is reachable) that
 * come back to the branch's start exactly, y_lo, then leave it by a little:
 * the drive is the domain's end exactly there, agrees with the exact
 * inverse elsewhere, and the model driven by it gives the outputs back. */
static void test_flat_branch_start(void)
{
    /* steps of 1/255 of the domain; 0 twice: the same desired output again */
    static const unsigned char steps[] = {160u, 100u, 128u, 19u, 0u, 0u, 1u, 16u, 192u, 0u, 3u, 0u};
    hyst_everett_t e;
    hyst_real_t want[sizeof steps];
    size_t k;
    memset(&e, 0, sizeof e);
    e.degree = 4u;
    e.lo = 0.0;
    e.hi = 0.25;
    e.y_lo = -4.0;
    e.e[0][2] = 0.03125;
    e.e[0][3] = 1.0;
    e.e[1][1] = 0.25;
    e.e[2][0] = 1.25;
    e.e[2][1] = -1.75;
    e.e[3][0] = 2.5;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&fwd, &e));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&inv, &fwd));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &fwd, xl3, yl3, xr3, yr3, CAP));
    for (k = 0u; k < sizeof steps; ++k) {
        want[k] = hyst_step(&T, (hyst_real_t)(e.hi * (double)steps[k] / 255.0));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &inv, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&M, &fwd, xl2, yl2, xr2, yr2, CAP));
    ref_everett_init(&ref, &e);
    for (k = 0u; k < sizeof steps; ++k) {
        const hyst_real_t x = hyst_step(&C, want[k]);
        const double exact = exact_drive(&ref, (double)want[k]);
        const double out =
            fabs((double)hyst_step(&M, x) - (double)want[k]) / ref_everett_e(&e, e.hi, e.lo);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&C));
        if (fabs((double)x - exact) / e.hi > DRIVE_AGREE || out > 10.0 * DRIVE_AGREE ||
            (want[k] == (hyst_real_t)e.y_lo && x != (hyst_real_t)e.lo)) {
            TEST_PRINTF("sample %u: desired %g, drive %g, exact %g, output off by %g of the range",
                        (unsigned)k, (double)want[k], (double)x, exact, out);
            TEST_FAIL();
        }
        (void)ref_everett_step(&ref, exact);
    }
}

#ifndef HYST_USE_DOUBLE
/* Desired outputs as integer codes 0..4095 over the major loop's range
 * (the code variant): the model driven by the compensator gives each
 * code's output back. */
static void test_codes_drive_the_asymmetric_compensator(void)
{
    static hyst_code_word_t cl[CAP], cr[CAP];
    static float cyl[CAP], cyr[CAP];
    const hyst_everett_t e = accepted_e();
    const double lo = (double)inv.lo.f32, hi = (double)inv.hi.f32, span = e.hi - e.lo;
    double worst = 0.0, v = 2048.0;
    hyst_t K;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&K, &inv, 0u, 4095u, cl, cyl, cr, cyr, CAP));
    ref_everett_init(&ref, &e);
    for (k = 0; k < SAMPLES; ++k) {
        const uint_least32_t code = (uint_least32_t)floor(ref_everett_walk(&rng, &v, 0.0, 4095.0) + 0.5);
        const double want = lo + (hi - lo) * (double)code / 4095.0;
        const double x = (double)hyst_code_step(&K, code);
        const double d = fabs(x - exact_drive(&ref, want)) / span;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&K));
        worst = d > worst ? d : worst;
        (void)ref_everett_step(&ref, exact_drive(&ref, want));
    }
    TEST_PRINTF("codes: worst drive error %g of the span", worst);
    TEST_ASSERT_TRUE(worst < DRIVE_AGREE);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_drive_agrees_with_the_exact_inverse);
    RUN_TEST(test_drive_is_monotone);
    RUN_TEST(test_block_and_snapshots);
    RUN_TEST(test_inverse_of_inverse_and_bad_input);
    RUN_TEST(test_flat_branch_start);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_codes_drive_the_asymmetric_compensator);
#endif
    return UNITY_END();
}
