/* SPDX-License-Identifier: MIT */
/* Rounding of the branch evaluation in the variant's type (curve.h,
 * "rounding"): init states a bound, refuses curves whose bound exceeds
 * HYST_MAX_ROUNDING of the output range, and every output of an accepted
 * curve lies within (d + 1) bounds of exact arithmetic on the same inputs
 * (d: stored turning points), measured against the double reference of the
 * tests (ref_tcm.c), which shares no code with the library: in the float
 * build (the reference's own rounding is then negligible). */
#include "ref_tcm.h"
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <math.h>

#define CAP 512
#define SAMPLES 6000L
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xs[SAMPLES];
static hyst_t S;
static ref_tcm_t ref;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 4242u); }
void tearDown(void) {}

static hyst_poly_t monomial(unsigned n, double lo, double hi)
{
    hyst_poly_t f;
    unsigned k;
    f.degree = n;
    f.lo = lo;
    f.hi = hi;
    for (k = 0u; k <= n; ++k) {
        f.coeffs[k] = k == 0u ? 1.0 : 0.0;
    }
    return f;
}

/* A random increasing polynomial of odd degree 2m + 1 <= 9 on a random
 * domain (bipolar ones included): f0' = c + q(x)^2 with q random of degree
 * m, integrated. */
static hyst_poly_t random_increasing(void)
{
    hyst_poly_t f;
    double q[5], d[9], scale;
    const unsigned m = rng_below(&rng, 5u), n = 2u * m + 1u;
    const double centre = rng_range(&rng, -60.0, 60.0), half = rng_range(&rng, 0.5, 100.0);
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
    f.lo = centre - half;
    f.hi = centre + half;
    for (i = 0u; i <= n; ++i) {
        f.coeffs[i] = 0.0;
    }
    scale = rng_range(&rng, 0.1, 10.0);
    for (i = n; i-- > 0u;) { /* acc = acc * t + d[i] / (i + 1), acc in x */
        double next[10] = {0};
        for (j = 0u; j < n; ++j) { /* multiply by (x - c) / h: shift up, subtract c */
            next[j] += f.coeffs[j + 1u] / half;
            next[j + 1u] -= f.coeffs[j + 1u] * centre / half;
        }
        next[n] += scale * d[i] / (double)(i + 1u);
        for (j = 0u; j <= n; ++j) {
            f.coeffs[j] = next[j];
        }
    }
    /* one more factor t: f0 = t * acc */
    {
        double next[10] = {0};
        for (j = 0u; j < n; ++j) {
            next[j] += f.coeffs[j + 1u] / half;
            next[j + 1u] -= f.coeffs[j + 1u] * centre / half;
        }
        for (j = 0u; j <= n; ++j) {
            f.coeffs[j] = next[j];
        }
    }
    return f;
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
 * larger than two bounds between consecutive outputs of a monotone sweep. */
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
        if (st == HYST_ERR_ILL_CONDITIONED) {
            ++refused;
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, st);
        ++accepted;
        bound = (double)hyst_rounding_bound(&S);
        range = (double)S.y_hi.HYST_R - (double)S.y_lo.HYST_R;
        TEST_ASSERT_TRUE(bound > 0.0 && bound <= 1e-4 * range);
        ref_init(&ref, f.coeffs, f.degree, f.lo, f.hi);
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
        TEST_ASSERT_TRUE_MESSAGE(worst_drop_ratio <= 1.0, "a drop beyond two rounding bounds");
    }
    TEST_PRINTF("random curves: %d accepted, %d refused; worst |y - y_ref| / ((d + 1) bound) "
                "%g; %ld drops on rising sweeps, worst %g of 2 bounds",
                accepted, refused, worst_ratio, drops, worst_drop_ratio);
    TEST_ASSERT_TRUE(accepted >= 20);
}

/* The paper's curve through adjacent inputs: every float (or double step of
 * the same count) from 10 to 10.5 V on the rising major branch. Drops are
 * counted and printed; each must stay within two rounding bounds. */
static void test_paper_curve_through_adjacent_inputs(void)
{
    hyst_real_t x = (hyst_real_t)10.0, prev;
    double bound;
    long n = 0, drops = 0;
    double worst = 0.0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, CAP));
    bound = 2.0 * (double)hyst_rounding_bound(&S);
    prev = hyst_step(&S, x);
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
        prev = y;
    }
    TEST_PRINTF("Eq. 20, %ld adjacent inputs from 10 V: %ld drops, worst %g (2 bounds: %g)", n,
                drops, worst, bound);
    TEST_ASSERT_TRUE(worst <= bound);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ill_conditioned_curves_are_refused_in_float);
    RUN_TEST(test_outputs_within_the_stated_bound);
    RUN_TEST(test_paper_curve_through_adjacent_inputs);
    return UNITY_END();
}
