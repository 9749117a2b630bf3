/* SPDX-License-Identifier: MIT */
/* The spline kind (curve.h, hyst_spline_t): f0 a cubic Hermite on uniform
 * knots. Checked against the plain double reference (tests/support/ref_tcm.c,
 * f0 in the Hermite basis) for random monotone splines and random drives
 * with minor loops and wipe-outs; a cubic written as a spline runs as the
 * polynomial kind does; the refusals, with nothing written; the
 * compensator; block call, snapshots and minor loops closing bit for bit. */
#include "ref_tcm.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 3000L
#define TABLE HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xs[SAMPLES], ys[SAMPLES], ys2[SAMPLES];
static hyst_real_t table[TABLE];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t curve, inverse;
static hyst_t S, T;
static rng_t rng;
static ref_tcm_t ref; /* 128 KB: off the stack */

#ifdef HYST_USE_DOUBLE
#define AGREE 1e-9 /* of the output range */
#else
#define AGREE 2e-5
#endif

void setUp(void) { rng_seed(&rng, 1618u); }
void tearDown(void) {}

/* A random increasing spline, some pieces flat with `flat`
 * (support.h). */
static hyst_spline_t random_spline(unsigned intervals, int flat)
{
    return spline_random(&rng, intervals, flat, 0, 0);
}

static hyst_status_t init_spline(hyst_t *I, hyst_curve_t *c, const hyst_spline_t *f)
{
    const hyst_status_t st = hyst_curve_from_spline(c, f, table, TABLE);
    return st != HYST_OK ? st : hyst_init_curve(I, c, xl, yl, xr, yr, CAP);
}

static void walk(double lo, double hi, hyst_real_t *x, long n)
{
    double v = 0.5 * (lo + hi);
    long k;
    for (k = 0; k < n; ++k) {
        x[k] = rng_walk(&rng, &v, lo, hi);
        if (rng_below(&rng, 40u) == 0u) { /* now and then a jump, or an end */
            v = rng_below(&rng, 3u) == 0u ? (rng_below(&rng, 2u) ? lo : hi) : rng_range(&rng, lo, hi);
            x[k] = (hyst_real_t)v;
        }
    }
}

static void test_random_splines_agree_with_the_reference(void)
{
    int trial;
    for (trial = 0; trial < 40; ++trial) {
        const hyst_spline_t f = random_spline(1u + rng_below(&rng, HYST_SPLINE_MAX_INTERVALS), 1);
        const double range = (double)f.value[f.intervals] - (double)f.value[0];
        double y_prev = (double)f.value[0], value[HYST_SPLINE_MAX_INTERVALS + 1];
        double slope[HYST_SPLINE_MAX_INTERVALS + 1];
        long k;
        unsigned i;
        for (i = 0u; i <= f.intervals; ++i) { /* the reference's numbers are double */
            value[i] = (double)f.value[i];
            slope[i] = (double)f.slope[i];
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_spline(&S, &curve, &f));
        ref_init_spline(&ref, f.intervals, value, slope, (double)f.lo, (double)f.hi, 0);
        walk(f.lo, f.hi, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double want = ref_step(&ref, (double)xs[k]);
            TEST_ASSERT_TRUE_MESSAGE(dabs(y - want) <= AGREE * range + 4 * real_ulp(dabs(want)),
                                     "spline output off the reference");
            /* monotone: a sample never moves the output against its input */
            if (k > 0 && xs[k] > xs[k - 1]) {
                TEST_ASSERT_TRUE(y >= y_prev);
            } else if (k > 0 && xs[k] < xs[k - 1]) {
                TEST_ASSERT_TRUE(y <= y_prev);
            }
            y_prev = y;
        }
    }
}

/* x^3 + x on [0, 1] in two pieces is that cubic exactly: the instance runs
 * as the polynomial kind's within rounding. */
static void test_a_cubic_as_a_spline_runs_as_the_polynomial(void)
{
    static const hyst_spline_t f = {2, 0.0, 1.0, {0.0, 0.625, 2.0}, {1.0, 1.75, 4.0}};
    static const hyst_poly_t p = {3, 0.0, 1.0, {1.0, 0.0, 1.0, 0.0}};
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_spline(&S, &curve, &f));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&T, &p, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_TRUE(dabs((double)hyst_curve_eval(&curve, (hyst_real_t)0.3) - 0.327) < 8 * AGREE);
    walk(0.0, 1.0, xs, SAMPLES);
    for (k = 0; k < SAMPLES; ++k) {
        const double a = (double)hyst_step(&S, xs[k]), b = (double)hyst_step(&T, xs[k]);
        TEST_ASSERT_TRUE(dabs(a - b) <= 2.0 * AGREE);
    }
}

/* Nothing written on a refusal: curve and table keep their bytes. */
static void refused(hyst_status_t want, const hyst_spline_t *f, size_t len)
{
    hyst_curve_t c;
    memset(&c, 0x5a, sizeof c);
    table[0] = (hyst_real_t)123.0;
    TEST_ASSERT_EQUAL_INT(want, hyst_curve_from_spline(&c, f, table, len));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&c)[0]);
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&c)[sizeof c - 1u]);
    TEST_ASSERT_TRUE(table[0] == (hyst_real_t)123.0);
}

static void test_refusals_write_nothing(void)
{
    static const hyst_spline_t good = {2, 0.0, 1.0, {0.0, 0.625, 2.0}, {1.0, 1.75, 4.0}};
    hyst_spline_t f = good;
    hyst_curve_t c;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_spline(NULL, &f, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_spline(&c, NULL, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_spline(&c, &f, NULL, TABLE));
    f.intervals = 0u;
    refused(HYST_ERR_DEGREE, &f, TABLE);
    f.intervals = HYST_SPLINE_MAX_INTERVALS + 1u;
    refused(HYST_ERR_DEGREE, &f, TABLE);
    f = good;
    f.hi = 0.0;
    refused(HYST_ERR_DOMAIN, &f, TABLE);
    f.hi = HUGE_VAL;
    refused(HYST_ERR_DOMAIN, &f, TABLE);
    f = good;
    f.value[1] = NAN;
    refused(HYST_ERR_COEFF, &f, TABLE);
    f = good;
    f.slope[2] = NAN;
    refused(HYST_ERR_COEFF, &f, TABLE);
    f = good;
    f.slope[1] = HYST_WIDE_C(-1e-9); /* falls at a knot */
    refused(HYST_ERR_NOT_INCREASING, &f, TABLE);
    f = good;
    f.value[1] = HYST_WIDE_C(0.05); /* slopes 1 and 1.75 overshoot a rise of 0.05 over 0.5: dips inside */
    refused(HYST_ERR_NOT_INCREASING, &f, TABLE);
    f = good;
    f.value[1] = f.value[2] = 0.0; /* constant */
    f.slope[0] = f.slope[1] = f.slope[2] = 0.0;
    refused(HYST_ERR_NOT_INCREASING, &f, TABLE);
    refused(HYST_ERR_NOSPACE, &good, HYST_SPLINE_TABLE_LEN(2u) - 1u);
#if !defined(HYST_USE_DOUBLE) && !defined(HYST_NO_DOUBLE) /* a spline of floats holds no 1e300 */
    f = good;
    f.value[2] = 1e300; /* beyond float: the table cannot hold it */
    f.slope[2] = 0.0;
    f.slope[1] = 0.0;
    refused(HYST_ERR_COEFF, &f, TABLE);
#endif
}

/* Numbers near the type's largest: the refusals keep curve.h's order (a
 * piece's shape, then NOSPACE, then a table number that overflows), an
 * increasing piece whose c2^2 overflows is accepted, and the float variant
 * refusing ends beyond float writes no table. */
static void test_extreme_numbers_keep_the_order_and_write_nothing(void)
{
#ifdef HYST_NO_DOUBLE
    TEST_IGNORE_MESSAGE("numbers beyond float: a spline holds floats with HYST_NO_DOUBLE");
#else
    static const hyst_spline_t dips = {1, 0.0, 10.0, {0.0, 1.0}, {1e308, 1e308}};
    static const hyst_spline_t line = {1, 0.0, 1.0, {0.0, 1.5e308}, {1.5e308, 1.5e308}};
    static const hyst_spline_t beyond_float = {1, 0.0, 1.0, {1e39, 1e39 + 1e31}, {0.0, 0.0}};
    static float t32[HYST_SPLINE_TABLE_LEN(1u)];
    hyst_curve_t c;
    refused(HYST_ERR_NOT_INCREASING, &dips, HYST_SPLINE_TABLE_LEN(1u) - 1u);
    refused(HYST_ERR_NOSPACE, &line, HYST_SPLINE_TABLE_LEN(1u) - 1u);
    refused(HYST_ERR_COEFF, &line, TABLE);
#if HYST_ENABLE_F64
    {
        static const hyst_spline_t vertex = {1, 0.0, 1.0, {0.0, 2e200 - 1e190}, {1e200, 4e200 - 2e190}};
        static double t64[HYST_SPLINE_TABLE_LEN(1u)];
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_f64_curve_from_spline(&c, &vertex, t64, HYST_SPLINE_TABLE_LEN(1u)));
    }
#endif
    t32[0] = 123.0f;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF,
                          hyst_f32_curve_from_spline(&c, &beyond_float, t32, HYST_SPLINE_TABLE_LEN(1u)));
    TEST_ASSERT_TRUE(t32[0] == 123.0f);
#endif
}

/* The boundary of the check: a piece whose slope touches 0 inside (the
 * middle Bernstein coefficient of its slope 0 and the ends' equal) passes. */
static void test_a_slope_touching_zero_inside_a_piece_is_accepted(void)
{
    /* on [0, 1]: f0 = 3 t - 3 t^2 + t^3 = 1 - (1 - t)^3 + ... slope 3 (1 - t)^2: 0 at t = 1 */
    static const hyst_spline_t f = {1, 0.0, 1.0, {0.0, 1.0}, {3.0, 0.0}};
    /* slope 3 - 6 t + 3 t^2... and one that touches 0 at t = 1/2: 12 (t - 1/2)^2 */
    static const hyst_spline_t g = {1, 0.0, 1.0, {0.0, 1.0}, {3.0, 3.0}};
    hyst_curve_t c;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&c, &f, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&c, &g, table, TABLE));
}

/* The compensator undoes the model: model(comp(y_d)) = y_d. */
static void test_the_compensator_undoes_the_model(void)
{
    int trial;
    for (trial = 0; trial < 10; ++trial) {
        const hyst_spline_t f = random_spline(2u + rng_below(&rng, 20u), 0);
        const double range = f.value[f.intervals] - f.value[0];
        long k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_spline(&S, &curve, &f));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&inverse, &curve));
        TEST_ASSERT_EQUAL_INT(HYST_CURVE_SPLINE_INV, (int)inverse.kind);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inverse, xl2, yl2, xr2, yr2, CAP));
        walk(f.value[0], f.value[f.intervals], xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const hyst_real_t drive = hyst_step(&T, xs[k]);
            const double y = (double)hyst_step(&S, drive);
            TEST_ASSERT_TRUE_MESSAGE(dabs(y - (double)xs[k]) <= 20 * AGREE * range,
                                     "the compensated model misses the desired output");
        }
        { /* and its inverse is the spline again, table and all */
            hyst_curve_t back;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&back, &inverse));
            TEST_ASSERT_EQUAL_INT(HYST_CURVE_SPLINE, (int)back.kind);
            TEST_ASSERT_TRUE((double)hyst_curve_eval(&back, xs[0]) ==
                             (double)hyst_curve_eval(&curve, xs[0]));
        }
    }
}

/* The compensator's refusals: a flat piece, another kind, NULL; and the
 * general inverse, which has nothing for the kind. */
static void test_the_compensator_refuses_what_has_no_inverse(void)
{
    static const hyst_spline_t flat = {3, 0.0, 3.0, {0.0, 1.0, 1.0, 2.0}, {1.0, 0.0, 0.0, 1.0}};
    static const hyst_poly_t p = {3, 0.0, 1.0, {1.0, 0.0, 1.0, 0.0}};
    hyst_curve_t c, inv;
    memset(&inv, 0x5a, sizeof inv);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&c, &flat, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INVERTIBLE, hyst_curve_spline_inverse(&inv, &c));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse(&inv, &c));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_spline_inverse(NULL, &c));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_spline_inverse(&inv, NULL));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&inv)[0]);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&c, &p));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_spline_inverse(&inv, &c));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&inv)[0]);
}

/* The block call, a restored snapshot, and a minor loop returning to its
 * turning point bit for bit. */
static void test_block_snapshot_and_loop_closure(void)
{
    const hyst_spline_t f = random_spline(12u, 1);
    const size_t half = (size_t)SAMPLES / 2u;
    size_t need;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_spline(&S, &curve, &f));
    walk(f.lo, f.hi, xs, SAMPLES);
    for (k = 0; k < SAMPLES; ++k) {
        ys[k] = hyst_step(&S, xs[k]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs, ys2, half));
    need = hyst_snapshot_size(&T);
    TEST_ASSERT_TRUE(need > 0u && need <= sizeof snap);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&T, snap, sizeof snap, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, need));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs + half, ys2 + half, (size_t)SAMPLES - half));
    TEST_ASSERT_EQUAL_MEMORY(ys, ys2, sizeof ys);
    { /* a minor loop: up, down below its start, back up: the output at the
       * start's input again is the start's */
        const hyst_real_t a = (hyst_real_t)(f.lo + 0.3 * (f.hi - f.lo));
        const hyst_real_t b = (hyst_real_t)(f.lo + 0.6 * (f.hi - f.lo));
        hyst_real_t at_a;
        hyst_reset(&S);
        (void)hyst_step(&S, b);
        at_a = hyst_step(&S, a);
        (void)hyst_step(&S, (hyst_real_t)(f.lo + 0.5 * (f.hi - f.lo)));
        (void)hyst_step(&S, (hyst_real_t)(f.lo + 0.4 * (f.hi - f.lo)));
        TEST_ASSERT_TRUE(hyst_step(&S, a) == at_a);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_splines_agree_with_the_reference);
    RUN_TEST(test_a_cubic_as_a_spline_runs_as_the_polynomial);
    RUN_TEST(test_refusals_write_nothing);
    RUN_TEST(test_extreme_numbers_keep_the_order_and_write_nothing);
    RUN_TEST(test_a_slope_touching_zero_inside_a_piece_is_accepted);
    RUN_TEST(test_the_compensator_undoes_the_model);
    RUN_TEST(test_the_compensator_refuses_what_has_no_inverse);
    RUN_TEST(test_block_snapshot_and_loop_closure);
    return UNITY_END();
}
