/* SPDX-License-Identifier: MIT */
/* The library against the simple reference (support/ref_tcm.c) over random
 * walks, random jumps and quantised codes, on the paper's curve and on random
 * increasing curves of every degree. */
#include "ref_tcm.h"
#include "support.h"
#include "unity.h"

#define SAMPLES 100000L
#define CAP 4096

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_t S;
static ref_tcm_t ref;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 2024u); }
void tearDown(void) {}

enum { WALK, JUMPS, CODES };

static double next_input(int kind, double x, double lo, double hi)
{
    const double span = hi - lo;
    switch (kind) {
    case WALK:
        x += rng_range(&rng, -0.02, 0.02) * span;
        break;
    case JUMPS:
        x = rng_range(&rng, lo - 0.05 * span, hi + 0.05 * span); /* some clamped */
        break;
    default: { /* 12-bit codes: mostly small steps, some jumps */
        double code = (x - lo) / span * 4095.0 + 0.5;
        long c = (long)code;
        if (rng_below(&rng, 10u) == 0u) {
            c = (long)rng_below(&rng, 4096u);
        } else {
            c += (long)rng_below(&rng, 81u) - 40;
        }
        c = c < 0 ? 0 : (c > 4095 ? 4095 : c);
        x = lo + span * (double)c / 4095.0;
        break;
    }
    }
    if (kind == WALK) {
        x = x < lo ? lo : (x > hi ? hi : x);
    }
    return x;
}

/* Runs SAMPLES inputs of the given kind through both; returns max |dy| / range. */
static double compare(const hyst_poly_t *f0, const double *c, int kind, long *max_tp)
{
    const double lo = (double)f0->lo, hi = (double)f0->hi;
    double x = 0.5 * (lo + hi), worst = 0.0, range;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, f0, xl, yl, xr, yr, CAP));
    ref_init(&ref, c, f0->degree, lo, hi);
    range = ref_f0(&ref, hi) - ref_f0(&ref, lo);
    *max_tp = 0;
    for (i = 0; i < SAMPLES; ++i) {
        const hyst_real_t xin = (hyst_real_t)(x = next_input(kind, x, lo, hi));
        const double y = (double)hyst_step(&S, xin);
        const double yr_ = ref_step(&ref, (double)xin);
        const double d = y > yr_ ? y - yr_ : yr_ - y;
        worst = d > worst ? d : worst;
        if (ref_tp_count(&ref) != (long)hyst_tp_count(&S)) {
            TEST_FAIL_MESSAGE("turning-point count differs from the reference");
        }
        *max_tp = ref_tp_count(&ref) > *max_tp ? ref_tp_count(&ref) : *max_tp;
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&S) & HYST_EVENT_FULL);
    return worst / range;
}

static void check_kind(int kind)
{
    double c[4];
    long max_tp;
    double err;
    int k;
    for (k = 0; k < 4; ++k) {
        c[k] = (double)paper_eq20.coeffs[k]; /* the very values the library got */
    }
    err = compare(&paper_eq20, c, kind, &max_tp);
    TEST_PRINTF("kind %d: max |error| / range = %g, max TPs %d", kind, err, (int)max_tp);
    TEST_ASSERT_TRUE(max_tp > 4);
    TEST_ASSERT_TRUE(err <= TOL_OF_RANGE);
}

static void test_random_walk_matches_reference(void) { check_kind(WALK); }
static void test_random_jumps_match_reference(void) { check_kind(JUMPS); }
static void test_quantised_codes_match_reference(void) { check_kind(CODES); }

/* f0(x) = sum_i w_i (x / hi)^i, w_i >= 0, lo >= 0: increasing on [lo, hi]. */
static void test_random_curves_of_every_degree_match_reference(void)
{
    unsigned degree;
    for (degree = 1u; degree <= HYST_MAX_DEGREE; ++degree) {
        hyst_poly_t f0;
        double c[HYST_MAX_DEGREE + 1];
        double scale = 1.0;
        long max_tp;
        double err;
        unsigned k;
        f0.degree = degree;
        f0.lo = (hyst_real_t)rng_range(&rng, 0.0, 5.0);
        f0.hi = (hyst_real_t)((double)f0.lo + rng_range(&rng, 1.0, 4000.0));
        for (k = 0u; k <= degree; ++k) { /* c[k] multiplies x^(degree-k) */
            f0.coeffs[degree - k] = (hyst_real_t)(rng_range(&rng, 0.1, 2.0) / scale);
            scale *= (double)f0.hi;
        }
        for (k = 0u; k <= degree; ++k) {
            c[k] = (double)f0.coeffs[k];
        }
        err = compare(&f0, c, (int)(degree % 3u), &max_tp);
        TEST_PRINTF("degree %u on [%g, %g]: max |error| / range = %g", degree,
                    (double)f0.lo, (double)f0.hi, err);
        TEST_ASSERT_TRUE(err <= TOL_OF_RANGE);
    }
}

/* A domain across zero, f0(x) = x^3/3 + x^2/2 + x (f0' = x^2 + x + 1 > 0):
 * the search by bit patterns takes both its signed (x >= 0) and its
 * unsigned (x < 0) ladders, and inputs of -0.0 and +0.0 (equal values) must
 * behave alike, whatever TP they meet. */
static void test_bipolar_domain_and_signed_zeros_match_reference(void)
{
    hyst_poly_t f0;
    const double c[4] = {1.0 / 3.0, 0.5, 1.0, 0.0};
    double worst = 0.0, range;
    long code = 0, i, zeros = 0, negative_tps = 0;
    f0.degree = 3u;
    f0.lo = HYST_REAL_C(-2.0);
    f0.hi = HYST_REAL_C(2.0);
    f0.coeffs[0] = (hyst_real_t)c[0];
    f0.coeffs[1] = (hyst_real_t)c[1];
    f0.coeffs[2] = (hyst_real_t)c[2];
    f0.coeffs[3] = (hyst_real_t)c[3];
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &f0, xl, yl, xr, yr, CAP));
    ref_init(&ref, c, 3u, -2.0, 2.0);
    range = ref_f0(&ref, 2.0) - ref_f0(&ref, -2.0);
    for (i = 0; i < SAMPLES; ++i) {
        hyst_real_t xin;
        double y, yr_, d;
        /* codes -2047..2047, small steps around 0 and some jumps */
        if (rng_below(&rng, 16u) == 0u) {
            code = (long)rng_below(&rng, 4095u) - 2047;
        } else if (rng_below(&rng, 8u) == 0u) {
            code = 0;
        } else {
            code += (long)rng_below(&rng, 9u) - 4;
            code = code < -2047 ? -2047 : (code > 2047 ? 2047 : code);
        }
        xin = (hyst_real_t)(2.0 * (double)code / 2047.0);
        if (code == 0) {
            xin = rng_below(&rng, 2u) ? HYST_REAL_C(-0.0) : HYST_REAL_C(0.0);
            ++zeros;
        }
        y = (double)hyst_step(&S, xin);
        yr_ = ref_step(&ref, (double)xin);
        d = y > yr_ ? y - yr_ : yr_ - y;
        worst = d > worst ? d : worst;
        if (ref_tp_count(&ref) != (long)hyst_tp_count(&S)) {
            TEST_FAIL_MESSAGE("turning-point count differs from the reference");
        }
        if (hyst_ltp_count(&S) > 0u && S.xltp.HYST_R[1] < 0) {
            ++negative_tps;
        }
    }
    TEST_PRINTF("bipolar: max |error| / range = %g, %ld zeros, %ld samples with a negative TP",
                worst / range, zeros, negative_tps);
    TEST_ASSERT_TRUE(zeros > 1000 && negative_tps > 1000);
    TEST_ASSERT_TRUE(worst / range <= TOL_OF_RANGE);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_walk_matches_reference);
    RUN_TEST(test_random_jumps_match_reference);
    RUN_TEST(test_quantised_codes_match_reference);
    RUN_TEST(test_random_curves_of_every_degree_match_reference);
    RUN_TEST(test_bipolar_domain_and_signed_zeros_match_reference);
    return UNITY_END();
}
