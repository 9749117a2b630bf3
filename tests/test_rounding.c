/* SPDX-License-Identifier: MIT */
/* Rounding of the branch evaluation in the variant's type (curve.h,
 * "rounding"): init states a bound, refuses curves whose bound exceeds
 * HYST_MAX_ROUNDING of the output range, and every output of an accepted
 * curve lies within (d + 1) bounds of exact arithmetic on the same inputs
 * (d: stored turning points), measured against the double reference of the
 * tests (ref_tcm.c), which shares no code with the library: in the float
 * build (the reference's own rounding is then negligible).
 * Outputs are monotone in the input's direction however small its steps
 * (the guards of src/tcm_engine.h, emit()): through adjacent inputs, across
 * reversals and wipe-outs, in the block call, moving back inside the
 * deadband, and after a snapshot restored at a guarded sample. */
#include "ref_tcm.h"
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#define CAP 512
#define SAMPLES 6000L
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xs[SAMPLES];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t sweep_x[SAMPLES], sweep_y[SAMPLES];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_t S, T;
static ref_tcm_t ref;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 4242u); }
void tearDown(void) {}

static hyst_poly_t monomial(unsigned n, double lo, double hi)
{
    hyst_poly_t f;
    unsigned k;
    f.degree = n;
    f.lo = (hyst_wide_t)lo;
    f.hi = (hyst_wide_t)hi;
    for (k = 0u; k <= n; ++k) {
        f.coeffs[k] = k == 0u ? 1.0 : 0.0;
    }
    return f;
}

/* A random increasing polynomial of odd degree 2m + 1 <= 9 on a random
 * domain (bipolar ones included): f0' = c + q(x)^2 with q random of degree
 * m, integrated. */
static hyst_poly_t random_increasing_on(double centre, double half)
{
    hyst_poly_t f;
    double q[5], d[9], c[10], scale; /* c: f's coefficients, in double until stored */
    const unsigned m = rng_below(&rng, 5u), n = 2u * m + 1u;
    unsigned i, j;
    for (i = 0u; i <= m; ++i) {
        q[i] = rng_range(&rng, -1.0, 1.0); /* q[i] multiplies t^i, t = (x - centre) / half */
    }
    for (i = 0u; i <= 2u * m; ++i) {
        d[i] = 0.0;
    }
    for (i = 0u; i <= m; ++i) {
        for (j = 0u; j <= m; ++j) {
            d[i + j] += q[i] * q[j];
        }
    }
    d[0] += rng_range(&rng, 1e-3, 1.0);
    /* f0(x) = sum d[i] t^(i+1) / (i+1) in t; then in x: expand t = (x - c)/h
     * by Horner over the polynomial in x (highest power first). */
    f.degree = n;
    f.lo = (hyst_wide_t)(centre - half);
    f.hi = (hyst_wide_t)(centre + half);
    for (i = 0u; i <= n; ++i) {
        c[i] = 0.0;
    }
    scale = rng_range(&rng, 0.1, 10.0);
    for (i = n; i-- > 0u;) { /* acc = acc * t + d[i] / (i + 1), acc in x */
        double next[10] = {0};
        for (j = 0u; j < n; ++j) { /* multiply by (x - c) / h: shift up, subtract c */
            next[j] += c[j + 1u] / half;
            next[j + 1u] -= c[j + 1u] * centre / half;
        }
        next[n] += scale * d[i] / (double)(i + 1u);
        for (j = 0u; j <= n; ++j) {
            c[j] = next[j];
        }
    }
    /* one more factor t: f0 = t * acc */
    {
        double next[10] = {0};
        for (j = 0u; j < n; ++j) {
            next[j] += c[j + 1u] / half;
            next[j + 1u] -= c[j + 1u] * centre / half;
        }
        for (j = 0u; j <= n; ++j) {
            f.coeffs[j] = (hyst_wide_t)next[j];
        }
    }
    return f;
}

static hyst_poly_t random_increasing(void)
{
    const double centre = rng_range(&rng, -60.0, 60.0), half = rng_range(&rng, 0.5, 100.0);
    return random_increasing_on(centre, half);
}

/* Curves far from 0 relative to their span, given expanded about 0 (as a
 * fit in volts or codes prints them): the conversion to the domain cancels
 * (1e-3 (x - 1e9)^3 + (x - 1e9) on [1e9, 1e9 + 10] was accepted with a
 * bound of 1.5e-8 and outputs 3.6e7 off). Each curve is refused or every
 * output of its rising major branch lies within its stated bound of the
 * exact value of the coefficients given (double-double). Domains and inputs
 * are exact in the build's type (a centre of 8 bits times a power of two,
 * a power-of-two half-span, 256 steps). */
static void test_curves_far_from_zero_are_refused_or_within_the_bound(void)
{
#ifdef HYST_USE_DOUBLE
    const unsigned widest = 30u; /* log2(centre / half) up to */
#else
    const unsigned widest = 9u;
#endif
    const hyst_poly_t issue = {3u, HYST_WIDE_C(1e9), HYST_WIDE_C(1e9) + HYST_WIDE_C(10.0),
                               {HYST_WIDE_C(1e-3), HYST_WIDE_C(-3e6),
                                HYST_WIDE_C(3e15) + HYST_WIDE_C(1.0),
                                HYST_WIDE_C(-1e24) - HYST_WIDE_C(1e9)}};
    int curve, accepted = 0, refused = 0;
    double worst = 0.0;
#ifdef HYST_USE_DOUBLE
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_init(&S, &issue, xl, yl, xr, yr, CAP));
#else /* lo and hi are one float apart */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_init(&S, &issue, xl, yl, xr, yr, CAP));
#endif
    for (curve = 0; curve < 80; ++curve) {
        const double half = ldexp(1.0, (int)rng_below(&rng, 12u) - 4);
        const unsigned ratio = 3u + rng_below(&rng, widest - 2u);
        const double centre = (rng_below(&rng, 2u) ? -1.0 : 1.0) *
                              (double)(1u + 2u * rng_below(&rng, 128u)) * half *
                              ldexp(1.0, (int)ratio - 7);
        const hyst_poly_t f = random_increasing_on(centre, half);
        const hyst_status_t st = hyst_init(&S, &f, xl, yl, xr, yr, CAP);
        double bound;
        long k;
        if (st == HYST_ERR_ILL_CONDITIONED || st == HYST_ERR_NOT_INCREASING) {
            ++refused; /* the rounded expansion may also dip */
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++accepted;
        bound = (double)hyst_rounding_bound(&S);
        for (k = 1; k <= 256; ++k) {
            const double x = f.lo + (f.hi - f.lo) * (double)k / 256.0;
            const double y = (double)hyst_step(&S, (hyst_real_t)x);
            const double err = fabs(y - poly_eval_exact(f.coeffs, f.degree, x)) /
                               ((double)(hyst_tp_count(&S) + 1u) * bound);
            worst = err > worst ? err : worst;
            TEST_ASSERT_TRUE_MESSAGE(err <= 1.0, "an output beyond its stated rounding bound");
        }
    }
    TEST_PRINTF("offset domains: %d accepted, %d refused; worst error %g of its bound", accepted,
                refused, worst);
    TEST_ASSERT_TRUE(accepted >= 10 && refused >= 10);
}

/* Curves whose float evaluation loses more than HYST_MAX_ROUNDING of the
 * range are refused with their own status (x^9 on [-1, 1] measured 2e-4 of
 * the range in float before); double keeps them. */
static void test_ill_conditioned_curves_are_refused_in_float(void)
{
    const hyst_poly_t x9 = monomial(9u, -1.0, 1.0), x7 = monomial(7u, -1.0, 1.0);
    hyst_curve_t c;
#ifdef HYST_USE_DOUBLE
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &x9, xl, yl, xr, yr, CAP));
    TEST_ASSERT_TRUE(hyst_rounding_bound(&S) < 1e-9);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&c, &x7));
#else
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_init(&S, &x9, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_curve_from_poly(&c, &x7));
#endif
    /* the paper's curve: far below the limit in either type */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, CAP));
    TEST_ASSERT_TRUE(hyst_rounding_bound(&S) > 0);
    TEST_ASSERT_TRUE(hyst_rounding_bound(&S) < 1e-5 * (S.y_hi.HYST_R - S.y_lo.HYST_R));
    TEST_PRINTF("Eq. 20: rounding bound %g of the range",
                (double)hyst_rounding_bound(&S) / (double)(S.y_hi.HYST_R - S.y_lo.HYST_R));
}

/* Every output of every accepted random curve within (d + 1) bounds of the
 * double reference (d = stored TPs before the sample, at most), and no drop
 * at all between consecutive outputs of a rising sweep. */
static void test_outputs_within_the_stated_bound(void)
{
    int curve, accepted = 0, refused = 0;
    double worst_ratio = 0.0, worst_drop_ratio = 0.0;
    long drops = 0;
    for (curve = 0; curve < 60; ++curve) {
        const hyst_poly_t f = random_increasing();
        const int kind = curve % SIG_KINDS;
        double bound, range;
        long k;
        size_t depth = 0u;
        hyst_real_t prev = 0;
        const hyst_status_t st = hyst_init(&S, &f, xl, yl, xr, yr, CAP);
        /* in float, f's coefficients rounded may no longer be increasing */
        if (st == HYST_ERR_ILL_CONDITIONED || (SETUP_IN_FLOAT && st == HYST_ERR_NOT_INCREASING)) {
            ++refused;
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++accepted;
        bound = (double)hyst_rounding_bound(&S);
        range = (double)S.y_hi.HYST_R - (double)S.y_lo.HYST_R;
        TEST_ASSERT_TRUE(bound > 0.0 && bound <= 1e-4 * range);
        {
            double c[HYST_MAX_DEGREE + 1]; /* the reference's coefficients are double */
            unsigned j;
            for (j = 0u; j <= f.degree; ++j) {
                c[j] = (double)f.coeffs[j];
            }
            ref_init(&ref, c, f.degree, f.lo, f.hi);
        }
        fill_signal(kind, &rng, f.lo, f.hi, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const hyst_real_t y = hyst_step(&S, xs[k]);
            const double y_ref = ref_step(&ref, (double)xs[k]);
            const double ratio = fabs((double)y - y_ref) / ((double)(depth + 1u) * bound);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&S));
            worst_ratio = ratio > worst_ratio ? ratio : worst_ratio;
            depth = hyst_tp_count(&S) > depth ? hyst_tp_count(&S) : depth;
        }
        /* a rising sweep of the major branch through adjacent inputs */
        hyst_reset(&S);
        for (k = 1; k < 4000L; ++k) {
            const hyst_real_t x = (hyst_real_t)(f.lo + (f.hi - f.lo) * (double)k / 4000.0);
            const hyst_real_t y = hyst_step(&S, x);
            if (k > 1 && y < prev) {
                const double r = (double)(prev - y) / (2.0 * bound);
                ++drops;
                worst_drop_ratio = r > worst_drop_ratio ? r : worst_drop_ratio;
            }
            prev = y;
        }
#ifndef HYST_USE_DOUBLE /* the reference computes in double: a check of float only */
        TEST_ASSERT_TRUE_MESSAGE(worst_ratio <= 1.0, "an output beyond its stated rounding bound");
#endif
    }
    TEST_PRINTF("random curves: %d accepted, %d refused; worst |y - y_ref| / ((d + 1) bound) "
                "%g; %ld drops on rising sweeps, worst %g of 2 bounds",
                accepted, refused, worst_ratio, drops, worst_drop_ratio);
    TEST_ASSERT_TRUE(accepted >= 20);
    TEST_ASSERT_EQUAL_INT32_MESSAGE(0, drops, "the output dropped on a rising input");
}

/* The unguarded branch formula at the instance's last input, from its
 * fast-path cache (tcm.h): what the output would be without the guards. */
static hyst_real_t unguarded(const hyst_t *I)
{
    const hyst_real_t x = hyst_input(I);
    const hyst_real_t u = (x - I->x_ctp.HYST_R) * I->u_scale.HYST_R;
    hyst_real_t acc = I->coef[0].HYST_R;
    unsigned k;
    for (k = 1u; k < I->degree; ++k) {
        acc = acc * u + I->coef[k].HYST_R;
    }
    return I->moving_end == 0u ? I->y_ctp.HYST_R + acc * u : I->y_ctp.HYST_R - acc * u;
}

/* The paper's curve through adjacent inputs: every float (or double step of
 * the same count) from 10 to 10.5 V on the rising major branch. No drop
 * (the unguarded formula's drops printed: none on a host without FMA). */
static void test_paper_curve_through_adjacent_inputs(void)
{
    hyst_real_t x = (hyst_real_t)10.0, prev;
    double bound;
    long n = 0, drops = 0, raw_drops = 0;
    double worst = 0.0;
    hyst_real_t raw_prev;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, CAP));
    bound = 2.0 * (double)hyst_rounding_bound(&S);
    prev = hyst_step(&S, x);
    raw_prev = unguarded(&S);
    for (n = 0; n < 524288L; ++n) {
        hyst_real_t y;
#ifdef HYST_USE_DOUBLE
        x = (hyst_real_t)(10.0 + 0.5 * (double)(n + 1) / 524288.0);
#else
        x = nextafterf(x, 100.0f);
#endif
        y = hyst_step(&S, x);
        if (y < prev) {
            ++drops;
            worst = (double)(prev - y) > worst ? (double)(prev - y) : worst;
        }
        raw_drops += unguarded(&S) < raw_prev;
        raw_prev = unguarded(&S);
        prev = y;
    }
    TEST_PRINTF("Eq. 20, %ld adjacent inputs from 10 V: %ld drops (unguarded formula: %ld; "
                "2 bounds: %g)", n, drops, raw_drops, bound);
    TEST_ASSERT_EQUAL_INT32(0, drops);
    TEST_ASSERT_TRUE(worst == 0.0);
}

/* n inputs from x by steps of `ulps` adjacent values of the variant's type,
 * upwards (dir > 0) or downwards. */
static long adjacent_inputs(hyst_real_t x, int dir, long ulps, hyst_real_t *out, long n)
{
    long k, j;
    for (k = 0; k < n; ++k) {
        for (j = 0; j < ulps; ++j) {
#ifdef HYST_USE_DOUBLE
            x = nextafter(x, dir > 0 ? HUGE_VAL : -HUGE_VAL);
#else
            x = nextafterf(x, dir > 0 ? HUGE_VALF : -HUGE_VALF);
#endif
        }
        out[k] = x;
    }
    return n;
}

/* Counts outputs that move against the inputs' direction. */
static long against(const hyst_real_t *y, long n, int dir, hyst_real_t before)
{
    long k, bad = 0;
    for (k = 0; k < n; ++k) {
        bad += dir > 0 ? y[k] < before : y[k] > before;
        before = y[k];
    }
    return bad;
}

/* A sweep through the newest TP of a random history, by adjacent inputs:
 * it runs along the inner branch, wipes the TP out and resumes the outer
 * branch (rule 3). Per sample (step) and as one block call (process) on a
 * twin: the same outputs bit for bit, never against the input. */
static void test_sweeps_through_wipe_outs_are_monotone(void)
{
    int trial, swept = 0;
    long raw_against = 0;
    for (trial = 0; trial < 40; ++trial) {
        const hyst_poly_t f = trial % 4 == 0 ? paper_eq20 : random_increasing();
        hyst_real_t tp, before;
        int dir;
        long k;
        const long n = 3000L, ulps = 1L + (long)rng_below(&rng, 3u);
        if (hyst_init(&S, &f, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue; /* ill-conditioned in float: refused (above) */
        }
        fill_signal(trial % SIG_KINDS, &rng, f.lo, f.hi, xs, 500L);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, xs, xs, 500L));
        if (hyst_tp_count(&S) == 0u) {
            continue;
        }
        /* the newest TP the input moves towards: the current branch's end */
        dir = hyst_rising(&S) ? 1 : -1;
        tp = dir > 0 ? S.xrtp.HYST_R[S.n_rtp - 1u] : S.xltp.HYST_R[S.n_ltp - 1u];
        if (S.n_rtp == 0u) {
            continue;
        }
        /* start n/2 steps before it, on the current branch */
        adjacent_inputs(tp, -dir, ulps * (n / 2), sweep_x, 1L);
        if (dir > 0 ? !(sweep_x[0] > hyst_input(&S)) : !(sweep_x[0] < hyst_input(&S))) {
            continue;
        }
        before = hyst_step(&S, sweep_x[0]);
        adjacent_inputs(sweep_x[0], dir, ulps, sweep_x, n);
        if (!(sweep_x[n - 1] > S.lo.HYST_R && sweep_x[n - 1] < S.hi.HYST_R)) {
            continue; /* a TP at an end of the domain: nothing beyond it */
        }
        memcpy(&T, &S, sizeof T); /* a twin on its own arrays */
        memcpy(xl2, xl, sizeof xl);
        memcpy(yl2, yl, sizeof yl);
        memcpy(xr2, xr, sizeof xr);
        memcpy(yr2, yr, sizeof yr);
        T.xltp.HYST_R = xl2;
        T.yltp.HYST_R = yl2;
        T.xrtp.HYST_R = xr2;
        T.yrtp.HYST_R = yr2;
        {
            hyst_real_t raw_before = unguarded(&S);
            for (k = 0; k < n; ++k) {
                sweep_y[k] = hyst_step(&S, sweep_x[k]);
                raw_against += dir > 0 ? unguarded(&S) < raw_before : unguarded(&S) > raw_before;
                raw_before = unguarded(&S);
            }
        }
        TEST_ASSERT_EQUAL_INT32_MESSAGE(0, against(sweep_y, n, dir, before),
                                        "an output moved against the input");
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, sweep_x, sweep_x, (size_t)n));
        TEST_ASSERT_EQUAL_MEMORY(sweep_y, sweep_x, (size_t)n * sizeof sweep_x[0]);
        ++swept;
    }
    TEST_PRINTF("%d sweeps through a TP by adjacent inputs: no output against the input "
                "(unguarded formula: %ld)", swept, raw_against);
    TEST_ASSERT_TRUE(swept >= 15);
    TEST_ASSERT_TRUE(raw_against > 0); /* else these sweeps would not test the guard */
}

/* Inside the deadband a reversal is not stored: the output moves back
 * along the branch, monotone in the input's (new) direction. */
static void test_moving_back_inside_the_deadband_is_monotone(void)
{
    const hyst_real_t width = (hyst_real_t)0.5;
    hyst_real_t before;
    const long n = 2000L;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&S, width));
    (void)hyst_step(&S, (hyst_real_t)20.0);
    before = hyst_step(&S, (hyst_real_t)19.75); /* RTP at 20 V, falling */
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&S));
    /* up again by adjacent inputs, less than the deadband from the RTP:
     * the reversal at 19.75 V is skipped */
    adjacent_inputs((hyst_real_t)19.75, 1, 3L, sweep_x, n);
    TEST_ASSERT_TRUE((double)sweep_x[n - 1] < 20.0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, sweep_x, sweep_y, (size_t)n));
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&S)); /* skipped, not stored */
    TEST_ASSERT_FALSE(hyst_rising(&S));                      /* still on the falling branch */
    TEST_ASSERT_EQUAL_INT32(0, against(sweep_y, n, 1, before));
    TEST_ASSERT_TRUE(sweep_y[n - 1] > before); /* it did move back up */
    /* and down again */
    before = sweep_y[n - 1];
    adjacent_inputs(sweep_x[n - 1], -1, 3L, sweep_x, n);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, sweep_x, sweep_y, (size_t)n));
    TEST_ASSERT_EQUAL_INT32(0, against(sweep_y, n, -1, before));
}

/* A snapshot saved at a sample whose output the guard held (the unguarded
 * formula is behind it) restores into an instance that continues bit for
 * bit like the original: restore re-derives the guard's state. */
static void test_restore_at_a_guarded_sample_continues_identically(void)
{
    int curve;
    long held = 0;
    size_t len = 0u;
    for (curve = 0; curve < 40 && held < 25; ++curve) {
        const hyst_poly_t f = random_increasing();
        hyst_real_t x;
        long k;
        if (hyst_init(&S, &f, xl, yl, xr, yr, CAP) != HYST_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&T, &f, xl2, yl2, xr2, yr2, CAP));
        x = (hyst_real_t)rng_range(&rng, f.lo, f.lo + 0.9 * (f.hi - f.lo));
        (void)hyst_step(&S, x);
        for (k = 0; k < 3000L && held < 25; ++k) {
            hyst_real_t y;
            long j;
            adjacent_inputs(x, 1, 1L, &x, 1L);
            y = hyst_step(&S, x);
            if (!(unguarded(&S) < y)) {
                continue;
            }
            ++held; /* the guard holds this output: save here, restore, compare */
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
            adjacent_inputs(x, 1, 1L, sweep_x, 64L);
            for (j = 0; j < 64L; ++j) {
                const hyst_real_t ya = hyst_step(&S, sweep_x[j]), yb = hyst_step(&T, sweep_x[j]);
                TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof ya);
            }
            x = sweep_x[63];
        }
    }
    TEST_PRINTF("%ld restores at guarded samples", held);
    TEST_ASSERT_TRUE(held > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ill_conditioned_curves_are_refused_in_float);
    RUN_TEST(test_outputs_within_the_stated_bound);
    RUN_TEST(test_curves_far_from_zero_are_refused_or_within_the_bound);
    RUN_TEST(test_paper_curve_through_adjacent_inputs);
    RUN_TEST(test_sweeps_through_wipe_outs_are_monotone);
    RUN_TEST(test_moving_back_inside_the_deadband_is_monotone);
    RUN_TEST(test_restore_at_a_guarded_sample_continues_identically);
    return UNITY_END();
}
