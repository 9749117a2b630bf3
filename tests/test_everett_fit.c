/* SPDX-License-Identifier: MIT */
/* The asymmetric kind's identification (ident.h, hyst_everett_fit_*): where
 * the plain least-squares E is not monotone, hyst_everett_fit_solve() gives
 * the least-squares E whose derivatives' Bernstein-Bezier coefficients have
 * the right signs (checked here by an independent conversion), which the
 * curve accepts, fitting no better than the plain one and better than the
 * degree below; where the plain E is monotone, bit for bit that E. */
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define RECORD 3000L

/* The curve whose refusal the fit answers to: f64's, or f32's without the
 * f64 variant (ident.h; HYST_NO_DOUBLE). */
#if HYST_ENABLE_F64
#define curve_from_e hyst_f64_curve_from_everett
#else
#define curve_from_e hyst_f32_curve_from_everett
#endif

static hyst_wide_t work[HYST_EVERETT_FIT_WORK(CAP)];
static double rx[RECORD], ry[RECORD];
static rng_t rng;

void setUp(void) { rng_seed(&rng, 4711u); }
void tearDown(void) {}

/* A plant that is no polynomial: E = 5 h(w) (1 + 0.1 (c - 1/2)) on
 * [-5, 15], h(w) = (1 - e^(-4 w)) / (1 - e^(-4)) saturating in the loop
 * width w, c the loop's centre in units of the span. Monotone (checked in
 * test_the_plant_is_monotone); its slope falls 55-fold over the width, so
 * the plain polynomial fits overshoot into negative slopes. */
#define PLANT_LO (-5.0)
#define PLANT_HI 15.0
static double plant_e(double a, double b)
{
    const double span = PLANT_HI - PLANT_LO, w = (a - b) / span;
    const double c = (0.5 * (a + b) - PLANT_LO) / span;
    return 5.0 * (1.0 - exp(-4.0 * w)) / (1.0 - exp(-4.0)) * (1.0 + 0.1 * (c - 0.5));
}

/* Bursts of shrinking loops, from the bottom and (mirrored) from the top:
 * turning points all over the triangle. */
static double burst_input(long k, double lo, double hi)
{
    const double phase = (double)(k % 1000L) / 1000.0, half = 0.5 * (hi - lo) * (1.0 - phase);
    const double x = half - half * cos(6.283185307179586 * (double)k / 100.0);
    return (k % 2000L) >= 1000L ? hi - x : lo + x;
}

/* The reference running the plant's E (the domain's E unused). */
static ref_everett_t *plant_reference(void)
{
    static hyst_everett_t dom;
    static ref_everett_t r;
    memset(&dom, 0, sizeof dom);
    dom.degree = 1u;
    dom.lo = PLANT_LO;
    dom.hi = PLANT_HI;
    ref_everett_init(&r, &dom);
    r.fn = plant_e;
    return &r;
}

/* The plant's record with Gaussian output noise of `noise`. */
static void record_plant(double noise)
{
    ref_everett_t *const r = plant_reference();
    long k;
    for (k = 0; k < RECORD; ++k) {
        rx[k] = burst_input(k, PLANT_LO, PLANT_HI);
        ry[k] = ref_everett_step(r, rx[k]) + noise * rng_gauss(&rng);
    }
}

static void fit_record(hyst_everett_fit_t *fit, unsigned degree, double lo, double hi, long n)
{
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_init(fit, degree, (hyst_wide_t)lo,
                                                         (hyst_wide_t)hi, work,
                                                         sizeof work / sizeof work[0]));
    for (k = 0; k < n; ++k) {
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_everett_fit_add(fit, (hyst_wide_t)rx[k], (hyst_wide_t)ry[k]));
    }
}

static double binomial(unsigned n, unsigned k)
{
    double c = 1.0;
    unsigned i;
    for (i = 1u; i <= k; ++i) {
        c = c * (double)(n - k + i) / (double)i;
    }
    return c;
}

/* The smallest Bernstein-Bezier coefficient on the unit triangle of p
 * (p[a][b] multiplies s^a t^b, total degree m): s^a t^b is the sum over
 * i >= a, j >= b of C(i, a) C(j, b) / (C(m, a + b) C(a + b, a)) B_ij. */
static double lowest_bernstein(double p[HYST_EVERETT_MAX_DEGREE][HYST_EVERETT_MAX_DEGREE],
                               unsigned m)
{
    double lowest = 1e300;
    unsigned i, j, a, b;
    for (i = 0u; i <= m; ++i) {
        for (j = 0u; i + j <= m; ++j) {
            double c = 0.0;
            for (a = 0u; a <= i; ++a) {
                for (b = 0u; b <= j; ++b) {
                    c += p[a][b] * binomial(i, a) * binomial(j, b) /
                         (binomial(m, a + b) * binomial(a + b, a));
                }
            }
            lowest = c < lowest ? c : lowest;
        }
    }
    return lowest;
}

/* The smallest Bernstein-Bezier coefficient of span dE/da = R_w and of
 * -span dE/db = R_w - R_t, R(w, t) = E's power form, relative to the
 * scale the library's check uses (sum of |e_ij| (i + j)). */
static double bernstein_slack(const hyst_everett_t *e)
{
    double rw[HYST_EVERETT_MAX_DEGREE][HYST_EVERETT_MAX_DEGREE];
    double rb[HYST_EVERETT_MAX_DEGREE][HYST_EVERETT_MAX_DEGREE];
    double scale = 0.0, low_a, low_b;
    unsigned i, j;
    memset(rw, 0, sizeof rw);
    memset(rb, 0, sizeof rb);
    for (i = 1u; i <= e->degree; ++i) {
        for (j = 0u; i + j <= e->degree; ++j) {
            const double c = (double)e->e[i - 1u][j];
            rw[i - 1u][j] += (double)i * c;
            rb[i - 1u][j] += (double)i * c;
            if (j > 0u) {
                rb[i][j - 1u] -= (double)j * c;
            }
            scale += fabs(c) * (double)(i + j);
        }
    }
    low_a = lowest_bernstein(rw, e->degree - 1u);
    low_b = lowest_bernstein(rb, e->degree - 1u);
    return (low_a < low_b ? low_a : low_b) / scale;
}

/* The plant is a valid Preisach-type E: dE/da >= 0, dE/db <= 0 sampled. */
static void test_the_plant_is_monotone(void)
{
    const double span = PLANT_HI - PLANT_LO, h = 1e-6 * span;
    int i, j;
    for (i = 0; i <= 50; ++i) {
        for (j = 0; i + j <= 50; ++j) {
            const double b = PLANT_LO + span * (double)j / 50.0, a = b + span * (double)i / 50.0;
            TEST_ASSERT_TRUE(plant_e(a + h, b) - plant_e(a, b) > 0.0);
            TEST_ASSERT_TRUE(plant_e(a, b + h) - plant_e(a, b) < 0.0);
        }
    }
}

/* Degrees 2..4 of the plant's record: where the plain fit is refused, the
 * monotone one is accepted, its coefficients sign-correct, its residual at
 * least the plain one's; degree 4 needs it and beats degree 2. */
static void test_monotone_fit_where_least_squares_is_not(void)
{
    static hyst_everett_fit_t fit;
    const double noise = 1e-3 * plant_e(PLANT_HI, PLANT_LO);
    double rms_by_degree[HYST_EVERETT_MAX_DEGREE + 1] = {0.0}, mean_square = 0.0;
    int refused[HYST_EVERETT_MAX_DEGREE + 1] = {0};
    unsigned degree;
    long k;
    record_plant(noise);
    for (k = 0; k < RECORD; ++k) {
        mean_square += ry[k] * ry[k] / (double)RECORD;
    }
    for (degree = 2u; degree <= (unsigned)HYST_EVERETT_MAX_DEGREE; ++degree) {
        hyst_everett_t plain, mono;
        hyst_wide_t rms_plain = 0, rms_mono = 0;
        hyst_curve_t c;
        fit_record(&fit, degree, PLANT_LO, PLANT_HI, RECORD);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve_unconstrained(&fit, &plain, &rms_plain));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &mono, &rms_mono));
        TEST_ASSERT_EQUAL_INT(HYST_OK, curve_from_e(&c, &mono));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_from_everett(&c, &mono));
        refused[degree] = curve_from_e(&c, &plain) != HYST_OK;
        if (refused[degree]) {
            const double slack = bernstein_slack(&mono);
            TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, curve_from_e(&c, &plain));
            TEST_ASSERT_TRUE(bernstein_slack(&plain) < 0.0);
            /* every coefficient sign-correct, to the check's rounding allowance;
             * in float, to what the dual's normal equations resolve (the
             * curve's own proof, by subdivision, accepted it above) */
            TEST_ASSERT_TRUE(slack >= (SETUP_IN_FLOAT ? -1e-2 : -64.0 * DBL_EPSILON));
            /* the residual: no lower than the plain fit's, to rounding */
            TEST_ASSERT_TRUE((double)rms_mono * (double)rms_mono >=
                             (double)rms_plain * (double)rms_plain - 1e-12 * mean_square);
            TEST_PRINTF("degree %u: least squares refused (rms %g), monotone fit rms %g, "
                        "lowest Bernstein-Bezier coefficient %g of the scale",
                        degree, (double)rms_plain, (double)rms_mono, slack);
        } else {
            TEST_ASSERT_EQUAL_MEMORY(&plain, &mono, sizeof plain);
            TEST_ASSERT_EQUAL_MEMORY(&rms_plain, &rms_mono, sizeof rms_plain);
            TEST_PRINTF("degree %u: least squares accepted, rms %g", degree, (double)rms_plain);
        }
        rms_by_degree[degree] = (double)rms_mono;
    }
    TEST_ASSERT_TRUE(refused[HYST_EVERETT_MAX_DEGREE]);
    TEST_ASSERT_TRUE(rms_by_degree[HYST_EVERETT_MAX_DEGREE] < rms_by_degree[2]);
    /* fitting a curve the degree cannot follow: still a clear gain over degree 2 */
    TEST_ASSERT_TRUE(rms_by_degree[HYST_EVERETT_MAX_DEGREE] < 0.5 * rms_by_degree[2]);
}

/* Records of monotone polynomial E fitted at their degree: wherever the
 * plain fit is accepted, hyst_everett_fit_solve() gives it bit for bit;
 * wherever not (an E at the edge of monotone, noise), its result is
 * accepted. */
static void test_monotone_least_squares_is_kept_bit_for_bit(void)
{
    static hyst_everett_fit_t fit;
    int trial, kept = 0;
    for (trial = 0; trial < 30; ++trial) {
        const hyst_everett_t e = ref_everett_random(&rng);
        static ref_everett_t r;
        hyst_everett_t plain, mono;
        hyst_wide_t rms_plain = 0, rms_mono = 0;
        hyst_curve_t c;
        double v = (double)e.lo, range;
        long k;
        if (curve_from_e(&c, &e) != HYST_OK || e.degree < 2u) {
            continue;
        }
        range = ref_everett_e(&e, e.hi, e.lo);
        ref_everett_init(&r, &e);
        for (k = 0; k < RECORD; ++k) {
            rx[k] = ref_everett_walk(&rng, &v, (double)e.lo, (double)e.hi);
            ry[k] = ref_everett_step(&r, rx[k]) + 1e-3 * range * rng_gauss(&rng);
        }
        fit_record(&fit, e.degree, (double)e.lo, (double)e.hi, RECORD);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve_unconstrained(&fit, &plain, &rms_plain));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &mono, &rms_mono));
        TEST_ASSERT_EQUAL_INT(HYST_OK, curve_from_e(&c, &mono));
        if (curve_from_e(&c, &plain) == HYST_OK) {
            TEST_ASSERT_EQUAL_MEMORY(&plain, &mono, sizeof plain);
            TEST_ASSERT_EQUAL_MEMORY(&rms_plain, &rms_mono, sizeof rms_plain);
            ++kept;
        }
    }
    TEST_PRINTF("%d plain fits accepted and kept", kept);
    TEST_ASSERT_TRUE(kept >= (SETUP_IN_FLOAT ? 5 : 10)); /* float: degree 2 alone, 7 kept */
}

/* Major loops alone determine E on the triangle's edges only: degree 3 has
 * a direction (w t (1 - w - t)) no such record sees, whatever the
 * constraints; the fit says so instead of guessing. */
static void test_major_loops_alone_are_singular_above_degree_2(void)
{
    static hyst_everett_fit_t fit;
    ref_everett_t *const r = plant_reference();
    hyst_everett_t e;
    long k;
    for (k = 0; k < 1200L; ++k) {
        rx[k] = 5.0 - 10.0 * cos(6.283185307179586 * (double)k / 200.0);
        ry[k] = ref_everett_step(r, rx[k]);
    }
    fit_record(&fit, 2u, PLANT_LO, PLANT_HI, 1200L);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &e, NULL));
    fit_record(&fit, 3u, PLANT_LO, PLANT_HI, 1200L);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_SINGULAR, hyst_everett_fit_solve(&fit, &e, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_SINGULAR, hyst_everett_fit_solve_unconstrained(&fit, &e, NULL));
}

/* A record whose output never moves fits E = 0, which the curve refuses
 * (it never rises): the fit says so (it returned OK). */
static void test_flat_record_is_refused(void)
{
    static hyst_everett_fit_t fit;
    hyst_everett_t e;
    hyst_curve_t curve;
    long k;
    for (k = 0; k < 400L; ++k) {
        rx[k] = 5.0 - 10.0 * cos(6.283185307179586 * (double)k / 100.0) * (double)(k % 7) / 6.0;
        ry[k] = 0.25;
    }
    fit_record(&fit, 2u, PLANT_LO, PLANT_HI, 400L);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_everett_fit_solve(&fit, &e, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_curve_from_everett(&curve, &e));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve_unconstrained(&fit, &e, NULL));
}

/* An output offset far above the range (a 24-bit ADC at mid-scale,
 * 8 388 608 counts): the residual y'y - 2 s'A'y + s'A s cancelled, and an
 * exact fit reported RMS 0.47. Now about the first output: the RMS of an
 * exact fit stays at the rounding level, and with noise it is the RMS of
 * the residual of the E returned, run over the record (both within 1e-6 of
 * the range). An offset so far above the range that the curve refuses E
 * (its rounding bound) is refused by the fit too (it returned OK). */
static void test_offset_outputs_report_their_residual(void)
{
    static hyst_everett_fit_t fit;
    static ref_everett_t r, fitted;
    int trial, checked = 0;
    for (trial = 0; trial < 12; ++trial) {
        hyst_everett_t e = ref_everett_random(&rng), got;
        hyst_wide_t rms = -1;
        hyst_curve_t c;
        const double noise = trial % 2 ? 0.0 : 0.05;
        double v = (double)e.lo, range, ss = 0.0;
        long k;
        e.y_lo = (hyst_wide_t)((double)e.y_lo + 8388608.0);
        if (SETUP_IN_FLOAT) { /* float's rounding at 2^23 is 1: above 1e-4 of these ranges */
            const hyst_status_t st = curve_from_e(&c, &e);
            TEST_ASSERT_TRUE(st == HYST_ERR_ILL_CONDITIONED || st == HYST_ERR_NOT_MONOTONE);
            continue;
        }
        if (curve_from_e(&c, &e) != HYST_OK) {
            continue;
        }
        range = ref_everett_e(&e, e.hi, e.lo);
        ref_everett_init(&r, &e);
        for (k = 0; k < RECORD; ++k) {
            rx[k] = ref_everett_walk(&rng, &v, (double)e.lo, (double)e.hi);
            ry[k] = ref_everett_step(&r, rx[k]) + noise * range * rng_gauss(&rng);
        }
        fit_record(&fit, e.degree, (double)e.lo, (double)e.hi, RECORD);
        if (hyst_everett_fit_solve(&fit, &got, &rms) != HYST_OK) {
            continue; /* a noisy record's E the curve refuses */
        }
        ref_everett_init(&fitted, &got);
        for (k = 0; k < RECORD; ++k) {
            const double d = ry[k] - ref_everett_step(&fitted, rx[k]);
            ss += d * d;
        }
        ss = sqrt(ss / (double)RECORD);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6 * range, ss, (double)rms);
        ++checked;
    }
    TEST_ASSERT_TRUE(checked >= (SETUP_IN_FLOAT ? 0 : 6));
    {
        hyst_everett_t e = ref_everett_random(&rng), got;
        hyst_curve_t c;
        double v = (double)e.lo;
        long k;
        e.y_lo = HYST_WIDE_C(1e15); /* eps y_lo: 0.2, above 1e-4 of any range below 2000 */
        ref_everett_init(&r, &e);
        for (k = 0; k < RECORD; ++k) {
            rx[k] = ref_everett_walk(&rng, &v, (double)e.lo, (double)e.hi);
            ry[k] = ref_everett_step(&r, rx[k]);
        }
        fit_record(&fit, 1u, (double)e.lo, (double)e.hi, RECORD);
        if (SETUP_IN_FLOAT) { /* float's rounding at 1e15 is 1.3e8: the outputs never rise */
            TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_everett_fit_solve(&fit, &got, NULL));
            TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, curve_from_e(&c, &got));
            return;
        }
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_everett_fit_solve(&fit, &got, NULL));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, curve_from_e(&c, &got));
    }
}

/* Outputs so large that their squares overflow (1e200 times the plant's;
 * float: 1e25): the same E, scaled, is fitted and accepted; the RMS is the
 * scaled RMS where its own squares stay finite, else infinite, never 0. */
static void test_huge_outputs_fit_the_scaled_e(void)
{
    static hyst_everett_fit_t fit;
    const double scale = SETUP_IN_FLOAT ? 1e25 : 1e200;
    double emax = 0.0;
    hyst_everett_t e, big;
    hyst_wide_t rms = -1, rms_big = -1;
    unsigned i, j;
    long k;
    record_plant(0.0);
    fit_record(&fit, 2u, PLANT_LO, PLANT_HI, RECORD);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &e, &rms));
    for (k = 0; k < RECORD; ++k) {
        ry[k] *= scale;
    }
    fit_record(&fit, 2u, PLANT_LO, PLANT_HI, RECORD);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &big, &rms_big));
    for (i = 0u; i < 2u; ++i) {
        for (j = 0u; i + j < 2u; ++j) {
            emax = fmax(emax, fabs((double)e.e[i][j]));
        }
    }
    for (i = 0u; i < 2u; ++i) {
        for (j = 0u; i + j < 2u; ++j) {
            TEST_ASSERT_DOUBLE_WITHIN((SETUP_IN_FLOAT ? 1e-4 : 1e-9) * emax, (double)e.e[i][j],
                                      (double)big.e[i][j] / scale);
        }
    }
    TEST_ASSERT_TRUE(rms_big > 0);
    if (isfinite((double)rms_big)) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-3 * (double)rms, (double)rms, (double)rms_big / scale);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_plant_is_monotone);
    RUN_TEST(test_monotone_fit_where_least_squares_is_not);
    RUN_TEST(test_monotone_least_squares_is_kept_bit_for_bit);
    RUN_TEST(test_major_loops_alone_are_singular_above_degree_2);
    RUN_TEST(test_flat_record_is_refused);
    RUN_TEST(test_offset_outputs_report_their_residual);
    RUN_TEST(test_huge_outputs_fit_the_scaled_e);
    return UNITY_END();
}
