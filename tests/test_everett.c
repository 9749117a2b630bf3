/* SPDX-License-Identifier: MIT */
/* The asymmetric kind (curve.h, hyst_everett_t): branches from a
 * two-variable function E. Checked against a plain double reference written
 * here (a list of turning points and the direct formula), for random E that
 * init accepts; Madelung's rules 2 and 3 bit for bit; rule 4 exactly when E
 * depends on the width only (then equal to the symmetric kind); the
 * monotonicity proof against dense sampling; the refusals; block call,
 * snapshots and bounded memory as for the symmetric kind. */
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 4000L
#define N HYST_EVERETT_MAX_DEGREE

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xs[SAMPLES], ys[SAMPLES], ys2[SAMPLES];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t curve, curve2;
static hyst_t S, T;
static rng_t rng;

#ifdef HYST_USE_DOUBLE
#define AGREE 1e-9 /* of the output range */
#else
#define AGREE 1e-5
#endif

void setUp(void) { rng_seed(&rng, 1312u); }
void tearDown(void) {}

static hyst_everett_t random_e(void) { return ref_everett_random(&rng); }

/* dE/da >= 0 and dE/db <= 0 sampled on a grid of the triangle; the
 * smallest value of both, relative to the range E(hi, lo). */
static double sampled_slack(const hyst_everett_t *e)
{
    const double span = e->hi - e->lo, h = span * 1e-7, range = ref_everett_e(e, e->hi, e->lo);
    double worst = 1e300;
    int i, j;
    for (i = 0; i <= 40; ++i) {
        for (j = 0; i + j <= 40; ++j) {
            const double b = e->lo + span * (double)j / 40.0, a = b + span * (double)i / 40.0;
            const double da = (ref_everett_e(e, a + (i + j < 40 ? h : 0.0), b) - ref_everett_e(e, a - (i > 0 ? h : 0.0), b));
            const double db = (ref_everett_e(e, a, b - (j > 0 ? h : 0.0)) - ref_everett_e(e, a, b + (i > 0 ? h : 0.0)));
            worst = da < worst ? da : worst;
            worst = db < worst ? db : worst;
        }
    }
    return worst / (h * range / span);
}

static hyst_status_t init_e(hyst_t *I, hyst_curve_t *c, const hyst_everett_t *e, hyst_real_t *a,
                            hyst_real_t *b, hyst_real_t *d, hyst_real_t *f, size_t cap)
{
    const hyst_status_t st = hyst_curve_from_everett(c, e);
    return st != HYST_OK ? st : hyst_init_curve(I, c, a, b, d, f, cap);
}

static void walk(const hyst_everett_t *e, hyst_real_t *x, long n)
{
    double v = 0.5 * (e->lo + e->hi);
    long k;
    for (k = 0; k < n; ++k) {
        x[k] = (hyst_real_t)ref_everett_walk(&rng, &v, e->lo, e->hi);
    }
}

static void test_random_e_agree_with_the_reference(void)
{
    int trial, accepted = 0, refused = 0;
    double worst = 0.0;
    for (trial = 0; trial < 60; ++trial) {
        const hyst_everett_t e = random_e();
        static ref_everett_t r; /* 16 KB: off the stack */
        double range;
        long k;
        const hyst_status_t st = init_e(&S, &curve, &e, xl, yl, xr, yr, CAP);
        if (st != HYST_OK) {
            TEST_ASSERT_TRUE(st == HYST_ERR_NOT_MONOTONE || st == HYST_ERR_ILL_CONDITIONED);
            if (st == HYST_ERR_NOT_MONOTONE) { /* refused: negative somewhere, or nearly */
                TEST_ASSERT_TRUE(sampled_slack(&e) < 1e-3);
            }
            ++refused;
            continue;
        }
        ++accepted;
        TEST_ASSERT_TRUE(sampled_slack(&e) > -1e-6); /* the proof holds on samples */
        range = ref_everett_e(&e, e.hi, e.lo);
        ref_everett_init(&r, &e);
        walk(&e, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double d = fabs(y - ref_everett_step(&r, (double)xs[k])) / range;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&S));
            worst = d > worst ? d : worst;
        }
        TEST_ASSERT_EQUAL_UINT((unsigned)(r.n - 1), (unsigned)hyst_tp_count(&S));
    }
    TEST_PRINTF("random E: %d accepted, %d refused; worst |y - y_ref| %g of the range", accepted,
                refused, worst);
    TEST_ASSERT_TRUE(accepted >= 20 && refused >= 1);
    TEST_ASSERT_TRUE(worst <= AGREE);
}

/* Rules 2 and 3: an excursion inside the current branch returns to the
 * same output bit for bit, and continues like a twin that stayed. */
static void test_minor_loops_close_bit_for_bit(void)
{
    int trial, checked = 0;
    for (trial = 0; trial < 200; ++trial) {
        hyst_everett_t e = random_e();
        hyst_real_t xa, ya, xc;
        double lo, hi;
        long k;
        if (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
        walk(&e, xs, 60L);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, xs, ys, 60u));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs, ys2, 60u));
        xa = hyst_input(&S);
        ya = hyst_output(&S);
        xc = hyst_rising(&S) ? S.xltp.HYST_R[S.n_ltp - 1u] : S.xrtp.HYST_R[S.n_rtp - 1u];
        lo = (double)(xa < xc ? xa : xc);
        hi = (double)(xa < xc ? xc : xa);
        if (hi - lo < 1e-3 * (e.hi - e.lo)) {
            continue;
        }
        for (k = 0; k < 1 + (long)rng_below(&rng, 12u); ++k) {
            (void)hyst_step(&S, (hyst_real_t)rng_range(&rng, lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo)));
        }
        {
            const hyst_real_t back = hyst_step(&S, xa);
            TEST_ASSERT_EQUAL_MEMORY(&ya, &back, sizeof ya);
        }
        walk(&e, xs, 40L);
        for (k = 0; k < 40; ++k) {
            const hyst_real_t y1 = hyst_step(&S, xs[k]), y2 = hyst_step(&T, xs[k]);
            TEST_ASSERT_EQUAL_MEMORY(&y2, &y1, sizeof y1);
        }
        ++checked;
    }
    TEST_ASSERT_TRUE(checked >= 50);
}

/* |reflection of the rising branch at 15 - the falling branch at 25| on
 * the loop 10..30 V of the reference (0 for a point-symmetric loop). */
static double loop_asymmetry(const hyst_everett_t *e)
{
    static ref_everett_t r; /* 16 KB: off the stack */
    double y_up, y_down, y10, y30;
    ref_everett_init(&r, e);
    (void)ref_everett_step(&r, 30.0);
    y10 = ref_everett_step(&r, 10.0);
    y_up = ref_everett_step(&r, 15.0);
    y30 = ref_everett_step(&r, 30.0);
    y_down = ref_everett_step(&r, 25.0);
    return fabs(y10 + y30 - y_up - y_down);
}

/* E of the width only is the symmetric kind: the same outputs as
 * hyst_init() with f0(x) = y_lo + E(x, lo), within rounding; and a loop
 * is point-symmetric. With a term in t it is not. */
static void test_width_only_is_the_symmetric_kind(void)
{
    hyst_everett_t e;
    hyst_poly_t f0;
    double range, worst = 0.0, asym;
    long k;
    memset(&e, 0, sizeof e);
    e.degree = 3u;
    e.lo = 0.0;
    e.hi = 40.0;
    e.y_lo = HYST_WIDE_C(0.58517);
    /* Eq. 20 as a function of w = x / 40 (lo = 0): c1 w + c2 w^2 + c3 w^3 */
    e.e[0][0] = HYST_WIDE_C(8.6444e-2) * 40;
    e.e[1][0] = HYST_WIDE_C(1.1949e-3) * 1600;
    e.e[2][0] = HYST_WIDE_C(-6.1876e-6) * 64000;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_e(&S, &curve, &e, xl, yl, xr, yr, CAP));
    f0 = paper_eq20;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&T, &f0, xl2, yl2, xr2, yr2, CAP));
    range = ref_everett_e(&e, 40.0, 0.0);
    walk(&e, xs, SAMPLES);
    for (k = 0; k < SAMPLES; ++k) {
        const double d = fabs((double)hyst_step(&S, xs[k]) - (double)hyst_step(&T, xs[k])) / range;
        worst = d > worst ? d : worst;
    }
    TEST_PRINTF("width-only E vs the symmetric kind: worst %g of the range", worst);
    TEST_ASSERT_TRUE(worst <= 4.0 * AGREE);
    /* rule 4 on the loop 10..30: the rising branch at 15 reflected onto the falling at 25 */
    {
        TEST_ASSERT_TRUE(loop_asymmetry(&e) <= 1e-9 * range);
        e.e[0][1] = HYST_WIDE_C(0.3); /* loops grow with their place: asymmetric */
        asym = loop_asymmetry(&e);
        TEST_ASSERT_TRUE(asym > 1e-3 * range);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&curve2, &e));
    }
}

static void test_bad_e_are_refused(void)
{
    hyst_everett_t e;
    memset(&e, 0, sizeof e);
    e.degree = 2u;
    e.lo = 0.0;
    e.hi = 1.0;
    e.e[0][0] = 1.0;
    e.e[1][0] = 0.5;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&curve, &e));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_everett(NULL, &e));
    e.e[1][0] = HYST_WIDE_C(-0.6); /* dE/da = 1 - 1.2 w < 0 near w = 1 */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_curve_from_everett(&curve, &e));
    e.e[1][0] = 0.0;
    e.e[0][1] = 2.5; /* dE/db = t-slope 2.5 w - 1: positive for w > 0.4 */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_curve_from_everett(&curve, &e));
    e.e[0][1] = HYST_WIDE_C(0.9); /* below 1: still monotone */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&curve, &e));
    e.e[2][0] = 1.0; /* above the degree */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_curve_from_everett(&curve, &e));
    e.e[2][0] = 0.0;
    e.e[0][0] = NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_curve_from_everett(&curve, &e));
    e.e[0][0] = 1.0;
    e.degree = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, hyst_curve_from_everett(&curve, &e));
    e.degree = (unsigned)N + 1u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, hyst_curve_from_everett(&curve, &e));
    e.degree = 2u;
    e.hi = e.lo;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_curve_from_everett(&curve, &e));
}

/* Block call = steps bit for bit; a snapshot restores and continues
 * identically, and is refused by an instance of another E. */
static void test_block_and_snapshots(void)
{
    hyst_everett_t e;
    size_t len = 0u;
    long k;
    do {
        e = random_e();
    } while (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
    walk(&e, xs, SAMPLES);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs, ys2, (size_t)SAMPLES));
    for (k = 0; k < SAMPLES; ++k) {
        ys[k] = hyst_step(&S, xs[k]);
    }
    TEST_ASSERT_EQUAL_MEMORY(ys, ys2, sizeof ys);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
    hyst_reset(&T);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
    walk(&e, xs, 500L);
    for (k = 0; k < 500; ++k) {
        const hyst_real_t y1 = hyst_step(&S, xs[k]), y2 = hyst_step(&T, xs[k]);
        TEST_ASSERT_EQUAL_MEMORY(&y1, &y2, sizeof y1);
    }
    e.e[0][0] *= HYST_WIDE_C(1.5); /* another E: the snapshot is not its */
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_e(&T, &curve2, &e, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&T, snap, len));
}

/* Bounded memory: a small capacity merges loops and states a bound that
 * holds against the unbounded reference. */
static void test_bounded_memory_keeps_its_bound(void)
{
    int trial, merged = 0;
    double worst_ratio = 0.0;
    for (trial = 0; trial < 30; ++trial) {
        const hyst_everett_t e = random_e();
        static ref_everett_t r; /* 16 KB: off the stack */
        long k;
        if (init_e(&S, &curve, &e, xl, yl, xr, yr, 3u) != HYST_OK) {
            continue;
        }
        ref_everett_init(&r, &e);
        walk(&e, xs, 2000L);
        for (k = 0; k < 2000; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double err = fabs(y - ref_everett_step(&r, (double)xs[k]));
            /* the stated bound plus rounding: (d + 1) bounds, d <= 5 TPs */
            const double bound = (double)hyst_error_bound(&S) + 6.0 * (double)hyst_rounding_bound(&S);
            merged += hyst_status(&S) == HYST_WARN_FULL;
            if (err > 0.0) {
                worst_ratio = err / bound > worst_ratio ? err / bound : worst_ratio;
            }
        }
    }
    TEST_PRINTF("bounded memory: %d merges; worst |y - y_ref| / bound %g", merged, worst_ratio);
    TEST_ASSERT_TRUE(merged > 0);
    TEST_ASSERT_TRUE(worst_ratio <= 1.0);
}

/* Identification: from noisy records of a random E's model, walked with
 * minor loops, hyst_everett_fit_* recovers E (outputs of the fitted model
 * within a few noise levels of the true model's on a new input). */
static void test_identification_recovers_e(void)
{
    static hyst_wide_t work[HYST_EVERETT_FIT_WORK(CAP)];
    int trial, fitted = 0;
    double worst = 0.0;
    for (trial = 0; trial < 20; ++trial) {
        const hyst_everett_t e = random_e();
        hyst_everett_fit_t fit;
        hyst_everett_t got;
        hyst_wide_t rms = 0;
        double range, noise;
        long k;
        if (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue;
        }
        range = ref_everett_e(&e, e.hi, e.lo);
        noise = 1e-3 * range;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_init(&fit, e.degree, e.lo, e.hi, work,
                                                             sizeof work / sizeof work[0]));
        walk(&e, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double y = (double)hyst_step(&S, xs[k]) + noise * (2.0 * rng_unit(&rng) - 1.0);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_add(&fit, (hyst_wide_t)xs[k], (hyst_wide_t)y));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_fit_solve(&fit, &got, &rms));
        TEST_ASSERT_TRUE((double)rms < 0.7 * noise); /* uniform noise: RMS noise / sqrt(3) */
        if (init_e(&T, &curve2, &got, xl2, yl2, xr2, yr2, CAP) != HYST_OK) {
            continue; /* a fit at the edge of monotone */
        }
        hyst_reset(&S);
        walk(&e, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double d = fabs((double)hyst_step(&S, xs[k]) - (double)hyst_step(&T, xs[k]));
            worst = d / noise > worst ? d / noise : worst;
        }
        ++fitted;
    }
    TEST_PRINTF("identification: %d fits, worst model difference %g noise levels", fitted, worst);
    TEST_ASSERT_TRUE(fitted >= 10);
    TEST_ASSERT_TRUE(worst < 1.0);
}

/* E at most linear in t: on a domain with |lo| <= hi - lo a slow sample
 * derives a branch from the TP's input itself (curve.h, lin_x), on one
 * farther from zero from its anchor. Either way every output is within
 * (d + 1) stated rounding bounds of the double reference (d: stored TPs,
 * at most; float only, the reference computing in double) and the domain
 * decides the form. */
static void test_linear_e_within_the_rounding_bound(void)
{
    int trial, near = 0, far = 0;
    double worst[2] = {0.0, 0.0};
    for (trial = 0; trial < 40; ++trial) {
        static ref_everett_t r;
        hyst_everett_t e = random_e();
        const double span = e.hi - e.lo;
        const int x_form = trial % 2 == 0;
        unsigned i, j;
        size_t depth = 0u;
        double bound;
        long k;
        for (i = 0u; i < (unsigned)N; ++i) {
            for (j = 2u; j < (unsigned)N; ++j) {
                e.e[i][j] = 0.0;
            }
        }
        e.lo = (hyst_wide_t)(float)(x_form ? span * rng_range(&rng, -1.0, 1.0)
                                           : span * rng_range(&rng, 1.5, 20.0) *
                                                 (trial % 4 == 1 ? -1 : 1));
        e.hi = (hyst_wide_t)(float)((double)e.lo + span);
        if (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_UINT(fabs(e.lo) <= e.hi - e.lo ? 1u : 0u, curve.u.everett.linear_x);
        near += curve.u.everett.linear_x != 0u;
        far += curve.u.everett.linear_x == 0u;
        bound = (double)hyst_rounding_bound(&S);
        TEST_ASSERT_TRUE(bound > 0.0);
        ref_everett_init(&r, &e);
        walk(&e, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double ratio = fabs(y - ref_everett_step(&r, (double)xs[k])) /
                                 ((double)(depth + 1u) * bound);
            double *w = &worst[curve.u.everett.linear_x != 0u];
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&S));
            *w = ratio > *w ? ratio : *w;
            depth = hyst_tp_count(&S) > depth ? hyst_tp_count(&S) : depth;
        }
    }
    TEST_PRINTF("E linear in t: %d curves from the inputs, %d from the anchor; worst |y - y_ref| / "
                "((d + 1) bound) %g and %g",
                near, far, worst[1], worst[0]);
    TEST_ASSERT_TRUE(near >= 10 && far >= 10);
#ifndef HYST_USE_DOUBLE
    TEST_ASSERT_TRUE_MESSAGE(worst[0] <= 1.0 && worst[1] <= 1.0, "an output beyond its stated rounding bound");
#endif
}

/* The deadband on the asymmetric kind: inputs oscillating by less than the
 * deadband next to a stored turning point, on both sides, for random E
 * init accepts. The instance stays within its stated error bound of the
 * full model (the same curve, no deadband) at every sample: the loop the
 * full model runs inside the window need not be highest at its middle. */
static void test_deadband_bound_holds_on_the_asymmetric_kind(void)
{
    int trial, curves = 0;
    double worst = 0.0, worst_ratio = 0.0;
    for (trial = 0; trial < 200; ++trial) {
        const hyst_everett_t e = random_e();
        const double span = e.hi - e.lo;
        const int rising = trial % 2 == 0; /* the window above an LTP, or below an RTP */
        double range, tp;
        long k;
        if (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&S, (hyst_real_t)(0.3 * span)));
        range = ref_everett_e(&e, e.hi, e.lo);
        tp = e.lo + span * (rising ? 0.35 : 0.65);
        for (k = 0; k < 80; ++k) {
            double x, err, bound;
            if (k == 0) {
                x = e.lo + span * (rising ? 0.8 : 0.2);
            } else if (k == 1) {
                x = tp;
            } else if (k == 79) {
                x = rising ? e.hi : e.lo; /* wipes it all */
            } else {
                x = tp + (rising ? 1.0 : -1.0) * 0.29 * span * rng_unit(&rng);
            }
            err = fabs((double)hyst_step(&S, (hyst_real_t)x) - (double)hyst_step(&T, (hyst_real_t)x));
            bound = (double)hyst_error_bound(&S);
            if (err > bound + AGREE * range) {
                TEST_PRINTF("E %d, sample %ld: |y - y_full| = %g > bound %g (range %g)", trial, k,
                            err, bound, range);
                TEST_FAIL_MESSAGE("deadband error beyond the stated bound");
            }
            worst = err / range > worst ? err / range : worst;
            worst_ratio = bound > 0.0 && err / bound > worst_ratio ? err / bound : worst_ratio;
        }
        TEST_ASSERT_TRUE(hyst_error_bound(&S) == 0);
        ++curves;
    }
    TEST_PRINTF("deadband on %d asymmetric curves: worst error %g of the range, at most %g of "
                "the bound", curves, worst, worst_ratio);
    TEST_ASSERT_TRUE(curves >= 100);
    TEST_ASSERT_TRUE(worst > 100.0 * AGREE); /* the skips did cost something */
}

#ifndef HYST_USE_DOUBLE
/* The integer-code variant runs the same curve: on codes 0..4095 of the
 * domain, bit for bit the f32 variant's outputs. */
static void test_codes_run_the_asymmetric_kind(void)
{
    static hyst_code_word_t cl[CAP], cr[CAP];
    static float cyl[CAP], cyr[CAP];
    hyst_everett_t e;
    hyst_t C;
    long k;
    do {
        e = random_e();
        e.lo = 0.0;
        e.hi = 4095.0;
    } while (init_e(&S, &curve, &e, xl, yl, xr, yr, CAP) != HYST_OK);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&C, &curve, 0u, 4095u, cl, cyl, cr, cyr, CAP));
    walk(&e, xs, SAMPLES);
    for (k = 0; k < SAMPLES; ++k) {
        const unsigned long code = (unsigned long)floor((double)xs[k] + 0.5);
        const float yc = hyst_code_step(&C, (uint_least32_t)code);
        const float yf = hyst_step(&S, (hyst_real_t)code);
        TEST_ASSERT_EQUAL_MEMORY(&yf, &yc, sizeof yf);
    }
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_e_agree_with_the_reference);
    RUN_TEST(test_minor_loops_close_bit_for_bit);
    RUN_TEST(test_width_only_is_the_symmetric_kind);
    RUN_TEST(test_bad_e_are_refused);
    RUN_TEST(test_block_and_snapshots);
    RUN_TEST(test_bounded_memory_keeps_its_bound);
    RUN_TEST(test_identification_recovers_e);
    RUN_TEST(test_linear_e_within_the_rounding_bound);
    RUN_TEST(test_deadband_bound_holds_on_the_asymmetric_kind);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_codes_run_the_asymmetric_kind);
#endif
    return UNITY_END();
}
