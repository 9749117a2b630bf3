/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's tabulated compensator
 * (hyst_*_curve_everett_inverse_table()): for random E that init accepts,
 * with the default table, the drive agrees with the exact inverse of a
 * plain double reference within 1e-5 of the drive span (and within the
 * error init measured, where a sweep adds no turning point); an E with a
 * flat start is solved where the table cannot follow it; on nested loops
 * hundreds deep the model driven by it gives the desired outputs within
 * 1e-5 of its range (turning points at the model's output); the drive never
 * moves against the desired output; block call = steps; snapshots continue
 * bit for bit; integer codes and bounded memory work; bad arguments are
 * refused. */
#include "comp_contract.h"
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 3000L
#define ROWS HYST_EVERETT_INV_ROWS
#define INTERVALS HYST_EVERETT_INV_INTERVALS
#ifdef HYST_USE_DOUBLE
#define REAL_EPS DBL_EPSILON
#else
#define REAL_EPS FLT_EPSILON
#endif
#define TARGET 1e-5 /* of the drive span: the compensator's promise */
#define DEEP 1000u        /* TPs of the nested-loops test (the reference holds 1024) */
#define DEEP_SAMPLES 3600L /* 900 reversals */

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xl3[CAP], yl3[CAP], xr3[CAP], yr3[CAP];
static hyst_real_t yd[SAMPLES], drive[SAMPLES], drive2[SAMPLES];
static hyst_real_t table[HYST_EVERETT_INV_TABLE_LEN(ROWS, INTERVALS)];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t fwd, inv, solved;
static hyst_t C, T, X;
static ref_everett_t ref, probe; /* 16 KB each: off the stack */
static rng_t rng;

void setUp(void) { rng_seed(&rng, 31415u); }
void tearDown(void) {}

/* The reference's output if its next input were x; r unchanged. */
static double response(const ref_everett_t *r, double x) { return ref_everett_response(r, x, &probe); }

/* The exact inverse: the input whose response is y. */
static double exact_drive(const ref_everett_t *r, double y) { return ref_everett_inverse(r, y, &probe); }

/* E's tabulated compensator T and its exact one X (both at reset). */
static void prepare(const hyst_everett_t *e)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&fwd, e));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&inv, &fwd, table, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_EVERETT_INV_TABLE, (int)inv.kind);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&solved, &fwd));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&X, &solved, xl2, yl2, xr2, yr2, CAP));
}

/* An accepted random E, prepared. */
static hyst_everett_t accepted_e(void)
{
    for (;;) {
        const hyst_everett_t e = ref_everett_random(&rng);
        if (hyst_curve_from_everett(&fwd, &e) == HYST_OK) {
            prepare(&e);
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
    double worst = 0.0, worst_measured = 0.0;
    unsigned solved_intervals = 0u;
    int trial;
    for (trial = 0; trial < 25; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double span = e.hi - e.lo;
        long k;
        worst_measured = fmax(worst_measured, (double)hyst_curve_inverse_error(&inv));
        solved_intervals += (unsigned)inv.u.everett.exact;
        /* the pieces within the tolerance; the drive's last rounding on top */
        TEST_ASSERT_TRUE(hyst_curve_inverse_error(&inv) <=
                         HYST_INV_TABLE_TOL + 1.0001 * REAL_EPS * fmax(fabs(e.lo), fabs(e.hi)) / span);
        desired(&e, SAMPLES);
        ref_everett_init(&ref, &e);
        for (k = 0; k < SAMPLES; ++k) {
            const double x = (double)hyst_step(&T, yd[k]);
            const double exact = exact_drive(&ref, (double)yd[k]);
            const double d = fabs(x - exact) / span;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&T));
            worst = d > worst ? d : worst;
            if (d > TARGET) {
                TEST_PRINTF("E %d degree %u sample %ld: drive %g, exact %g (%g of the span)",
                            trial, e.degree, k, x, exact, d);
                TEST_FAIL();
            }
            (void)ref_everett_step(&ref, exact);
        }
    }
    TEST_PRINTF("worst drive error %g of the span (init measured at most %g); intervals solved: "
                "%u of %u", worst, worst_measured, solved_intervals, 25u * 2u * INTERVALS);
}

/* Up the whole range from reset, then down: each drive is one table
 * evaluation from a turning point whose drive is exact or one such
 * evaluation old, so it is within the error init measured (twice, going
 * down) of the exact compensator's, plus the latter's own tolerance. */
static void test_sweeps_within_the_measured_error(void)
{
    int trial;
    for (trial = 0; trial < 10; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double lo = e.y_lo, hi = e.y_lo + ref_everett_e(&e, e.hi, e.lo);
        const double span = e.hi - e.lo;
        const double allowed = hyst_curve_inverse_error(&inv) * span * 1.01 +
                               2.0 * (double)CURVE_NUM(solved.rounding);
        double worst = 0.0;
        int pass;
        long k;
        for (pass = 0; pass < 2; ++pass) {
            for (k = 0; k <= 2000L; ++k) {
                const double f = (double)k / 2000.0;
                const hyst_real_t y = (hyst_real_t)(pass == 0 ? lo + (hi - lo) * f : hi - (hi - lo) * f);
                const double d = fabs((double)hyst_step(&T, y) - (double)hyst_step(&X, y));
                worst = d > worst ? d : worst;
                TEST_ASSERT_TRUE(d <= (pass + 1) * allowed);
            }
        }
        TEST_ASSERT_TRUE(worst > 0.0 || hyst_curve_inverse_error(&inv) == 0.0);
    }
}

/* Few rows, many intervals (3 and 512, both valid): a branch blends
 * rows far apart, and the blended cubic of an interval is off by more than
 * the interval is wide. Init measured it at the cubic's own drive steps
 * and skipped those whose output fell in a neighbouring interval, so it
 * reported a fraction of the error (94 times less at 16 384 intervals).
 * A random walk: within the error reported per stored turning point. */
static hyst_real_t few_rows_table[HYST_EVERETT_INV_TABLE_LEN(3u, 512u)];

static void test_few_rows_within_the_measured_error(void)
{
    double worst_ratio = 0.0, allowed;
    hyst_everett_t e;
    long k;
    int trial;
    for (trial = 0; trial < 2; ++trial) { /* the seed's third E (degree 2): its rows change */
        e = accepted_e();                  /* fast with the anchor */
        desired(&e, SAMPLES);
    }
    e = accepted_e();
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&inv, &fwd, few_rows_table, 3u, 512u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl, yl, xr, yr, CAP));
    hyst_reset(&X);
    allowed = (double)hyst_curve_inverse_error(&inv) * (e.hi - e.lo) * 1.01 +
              2.0 * (double)CURVE_NUM(solved.rounding);
    desired(&e, SAMPLES);
    for (k = 0; k < SAMPLES; ++k) {
        /* each turning point's drive carries one evaluation's error */
        const double d = fabs((double)hyst_step(&T, yd[k]) - (double)hyst_step(&X, yd[k]));
        const double ratio = d / ((double)(hyst_tp_count(&T) + 1u) * allowed);
        worst_ratio = ratio > worst_ratio ? ratio : worst_ratio;
    }
    TEST_PRINTF("3 rows, 512 intervals: worst drive error %g of the error reported; intervals "
                "solved %u of 1024", worst_ratio, (unsigned)inv.u.everett.exact);
    TEST_ASSERT_TRUE(worst_ratio <= 1.0);
}

/* E = w^2 (1 + t / 2): no slope at the start of any branch, where the
 * inverse has an infinite one. The first interval of every row is solved
 * instead, and the drive still agrees with the exact inverse. */
static void test_flat_start_is_solved(void)
{
    hyst_everett_t e;
    double worst = 0.0;
    long k;
    memset(&e, 0, sizeof e);
    e.degree = 3u;
    e.lo = 0.0;
    e.hi = 10.0;
    e.y_lo = -1.0;
    e.e[1][0] = 2.0;
    e.e[1][1] = 1.0;
    prepare(&e);
    TEST_ASSERT_TRUE(inv.u.everett.exact >= 1u);
    TEST_ASSERT_TRUE(inv.u.everett.exact < INTERVALS / 2u);
    desired(&e, SAMPLES);
    ref_everett_init(&ref, &e);
    for (k = 0; k < SAMPLES; ++k) {
        const double x = (double)hyst_step(&T, yd[k]);
        const double exact = exact_drive(&ref, (double)yd[k]);
        /* where the inverse is that steep, compare outputs: the model's at
         * the drive against the desired one */
        const double out = fabs(response(&ref, x) - (double)yd[k]) / ref_everett_e(&e, e.hi, e.lo);
        const double d = fabs(x - exact) / (e.hi - e.lo);
        worst = d > worst ? d : worst;
        TEST_ASSERT_TRUE(d <= TARGET || out <= TARGET);
        (void)ref_everett_step(&ref, exact);
    }
    TEST_PRINTF("flat start: %u of %u intervals solved; worst drive error %g of the span",
                (unsigned)inv.u.everett.exact, (unsigned)INTERVALS, worst);
}

/* Nested loops, hundreds deep (a decaying oscillation, a reversal every
 * four samples): the model driven by the compensator gives the desired
 * outputs within TARGET of its range at every depth. A turning point's
 * drive is one table evaluation off the exact inverse; its desired output
 * is replaced by the model's output for that drive (tcm_engine.h,
 * achieved_top()), so the nested branches do not add up those errors. */
static void test_nested_loops_do_not_add_up(void)
{
    static hyst_real_t dl[DEEP], dyl[DEEP], dr[DEEP], dyr[DEEP];
    hyst_t D;
    int trial;
    for (trial = 0; trial < 10; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double range = ref_everett_e(&e, e.hi, e.lo), mid = e.y_lo + 0.5 * range;
        double worst = 0.0, worst_shallow = 0.0;
        long k, worst_at = 0;
        size_t depth = 0u;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&D, &inv, dl, dyl, dr, dyr, DEEP));
        ref_everett_init(&ref, &e);
        for (k = 0; k < DEEP_SAMPLES; ++k) {
            const double amp = 0.49 * range * (1.0 - (double)k / (double)DEEP_SAMPLES);
            const hyst_real_t y = (hyst_real_t)(mid + amp * sin(0.3 + 6.283185307179586 * (double)k / 8.0));
            const double x = (double)hyst_step(&D, y);
            const double out = fabs(ref_everett_step(&ref, x) - (double)y) / range;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&D));
            if (out > worst) {
                worst = out;
                worst_at = k;
            }
            if (k < DEEP_SAMPLES / 10) {
                worst_shallow = out > worst_shallow ? out : worst_shallow;
            }
            depth = hyst_tp_count(&D) > depth ? hyst_tp_count(&D) : depth;
        }
        TEST_PRINTF("E %d: output error %g of the range (sample %ld), %g in the first tenth; "
                    "%lu TPs deep", trial, worst, worst_at, worst_shallow, (unsigned long)depth);
        TEST_ASSERT_TRUE(depth > DEEP / 2u);
        TEST_ASSERT_TRUE(worst <= TARGET);
    }
}

/* Sweeps by adjacent values up and down through many turning points: the
 * drive never moves against the desired output. */
static void test_drive_is_monotone(void)
{
    int trial;
    for (trial = 0; trial < 10; ++trial) {
        const hyst_everett_t e = accepted_e();
        const double lo = e.y_lo, hi = e.y_lo + ref_everett_e(&e, e.hi, e.lo);
        contract_drive_is_monotone(&T, lo, hi, 1e-2, 20000L, &rng);
    }
}

/* Block call = steps; a snapshot taken anywhere continues bit for bit;
 * the exact compensator's snapshot is not this one's. */
static void test_block_and_snapshots(void)
{
    const hyst_everett_t e = accepted_e();
    const comp_instance_t a = {&T, &inv, xl, yl, xr, yr, CAP};
    const comp_instance_t b = {&C, &inv, xl3, yl3, xr3, yr3, CAP};
    desired(&e, SAMPLES);
    contract_block_and_snapshots(&a, &b, &X, yd, drive, drive2, SAMPLES, snap, sizeof snap);
}

/* Three entries per array: loops merge, the drive stays in its range and
 * the bound stated is the drive range, as for the exact compensator. */
static void test_bounded_memory(void)
{
    static hyst_real_t sl[3], sy[3], sr[3], sry[3];
    const hyst_everett_t e = accepted_e();
    long k;
    hyst_t B;
    desired(&e, SAMPLES);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&B, &inv, sl, sy, sr, sry, 3u));
    for (k = 0; k < SAMPLES; ++k) {
        const hyst_real_t x = hyst_step(&B, yd[k]);
        TEST_ASSERT_TRUE(hyst_status(&B) >= 0);
        TEST_ASSERT_TRUE(x >= CURVE_NUM(inv.y_lo) && x <= CURVE_NUM(inv.y_hi));
        TEST_ASSERT_TRUE((double)hyst_error_bound(&B) <= 1.01 * (e.hi - e.lo));
    }
}

/* Out-of-range and non-finite desired outputs; the inverse of the inverse;
 * arguments refused. */
static void test_bad_input_and_arguments(void)
{
    hyst_curve_t back, other;
    hyst_real_t x;
    (void)accepted_e();
    x = hyst_step(&T, CURVE_NUM(inv.hi) + 1);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&T));
    TEST_ASSERT_EQUAL_MEMORY(&CURVE_NUM(inv.y_hi), &x, sizeof x);
    x = hyst_step(&T, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_status(&T));
    TEST_ASSERT_EQUAL_MEMORY(&CURVE_NUM(inv.y_hi), &x, sizeof x);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_check(&inv));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&back, &inv));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_EVERETT, (int)back.kind);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.u.everett.rise, &back.u.everett.rise, sizeof fwd.u.everett.rise);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.unit, &back.unit, sizeof fwd.unit);

    memcpy(&other, &inv, sizeof other);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_curve_everett_inverse_table(NULL, &fwd, table, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_curve_everett_inverse_table(&other, &fwd, NULL, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG,
                          hyst_curve_everett_inverse_table(&other, &fwd, table, 2u, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG,
                          hyst_curve_everett_inverse_table(&other, &fwd, table, ROWS, 0u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, /* not the forward kind */
                          hyst_curve_everett_inverse_table(&other, &solved, table, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_MEMORY(&inv, &other, sizeof other); /* nothing written */
}

/* The drive's range (tcm.h, "Output range"): desired outputs climbing to
 * within 12 units of the top after a descent, on domains whose ends are not
 * binary fractions, give a drive within 8 units in the last place of hi
 * (the rounding of the turning point's drive plus the step; tabulated and
 * solved). */
static void test_drive_within_8_units_of_the_top(void)
{
    hyst_everett_t e;
    long above = 0, n = 0;
    double worst_units = 0.0;
    int trial;
    memset(&e, 0, sizeof e);
    e.degree = 2u;
    e.y_lo = HYST_WIDE_C(-0.3);
    e.e[0][0] = 1.0;
    e.e[1][0] = 0.5;
    e.e[0][1] = 0.25;
    for (trial = 0; trial < 40; ++trial) {
        hyst_real_t top, y, hi;
        double allowed, worst = 0.0;
        long k;
        int j;
        e.lo = (hyst_wide_t)rng_range(&rng, 0.05, 0.15);
        e.hi = (hyst_wide_t)((double)e.lo + rng_range(&rng, 0.3, 1.3));
        prepare(&e);
        top = CURVE_NUM(inv.hi);
        hi = CURVE_NUM(inv.y_hi);
        allowed = 8.0 * (double)(NEXT(hi, (hyst_real_t)3.0) - hi);
        for (k = 0; k < 200; ++k) {
            const hyst_real_t low = (hyst_real_t)((double)CURVE_NUM(inv.lo) +
                                                  ((double)top - (double)CURVE_NUM(inv.lo)) *
                                                      rng_range(&rng, 0.0, 0.05));
            (void)hyst_step(&T, low);
            (void)hyst_step(&X, low);
            for (j = 12; j > 0; --j) { /* climbing: the fast path's samples */
                double xt, xs;
                int m;
                y = top;
                for (m = 0; m < j; ++m) {
                    y = NEXT(y, (hyst_real_t)-1.0);
                }
                xt = (double)hyst_step(&T, y);
                xs = (double)hyst_step(&X, y);
                above += (xt > (double)hi) + (xs > (double)hi);
                n += 2;
                worst = fmax(worst, fmax(xt, xs) - (double)hi);
                TEST_ASSERT_TRUE(xt <= (double)hi + allowed && xs <= (double)hi + allowed);
            }
        }
        worst_units = fmax(worst_units, worst / (allowed / 8.0));
    }
    TEST_PRINTF("%ld of %ld drives near the top above hi, at most %g units", above, n, worst_units);
}

/* Outputs spanning so little (E = e w, e about 2^31 over the type's largest
 * number: 6e-30 in float, 1.2e-299 in double) that a branch's interval
 * index, intervals over 2^-30 of the range, could overflow: the table is
 * refused (built or from flash; E = 8 least subnormals times w over a 1e303
 * domain, found by fuzzing, overflowed it), the solved compensator takes the
 * curve; four times more and the table is built. */
static void test_tiny_output_range(void)
{
#ifdef HYST_USE_DOUBLE
    const double tiny = 0x1p30 / DBL_MAX;
#else
    const double tiny = 0x1p30 / (double)FLT_MAX;
#endif
    hyst_everett_t e;
    hyst_curve_t other;
    hyst_table_seal_t seal;
    memset(&e, 0, sizeof e);
    e.degree = 1u;
    e.lo = 0.0;
    e.hi = 1.0;
    e.e[0][0] = (hyst_wide_t)tiny;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&fwd, &e));
    memcpy(&other, &inv, sizeof other);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED,
                          hyst_curve_everett_inverse_table(&other, &fwd, table, ROWS, INTERVALS));
    memset(&seal, 0, sizeof seal); /* refused before the seal is read */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED,
                          hyst_curve_everett_inverse_table_const(&other, &fwd, table, ROWS,
                                                                 INTERVALS, &seal));
    TEST_ASSERT_EQUAL_MEMORY(&inv, &other, sizeof other); /* nothing written */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&solved, &fwd));
    e.e[0][0] = (hyst_wide_t)(4.0 * tiny);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&fwd, &e));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&other, &fwd, table, ROWS, INTERVALS));
}

#ifndef HYST_USE_DOUBLE
/* Desired outputs as integer codes 0..4095 over the major loop's range
 * (the code variant). */
static void test_codes_drive_the_tabulated_compensator(void)
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
    TEST_ASSERT_TRUE(worst < TARGET);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_drive_agrees_with_the_exact_inverse);
    RUN_TEST(test_sweeps_within_the_measured_error);
    RUN_TEST(test_few_rows_within_the_measured_error);
    RUN_TEST(test_flat_start_is_solved);
    RUN_TEST(test_nested_loops_do_not_add_up);
    RUN_TEST(test_drive_is_monotone);
    RUN_TEST(test_block_and_snapshots);
    RUN_TEST(test_bounded_memory);
    RUN_TEST(test_bad_input_and_arguments);
    RUN_TEST(test_tiny_output_range);
    RUN_TEST(test_drive_within_8_units_of_the_top);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_codes_drive_the_tabulated_compensator);
#endif
    return UNITY_END();
}
