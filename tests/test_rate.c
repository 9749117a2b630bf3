/* SPDX-License-Identifier: MIT */
/* Rate term (rate.h): the low-pass of the drive's change against a plain
 * double reference and within the stated rounding bound (tau = 1, the last
 * change, among them), init and reset refusals that write nothing, NaN and
 * out-of-range samples, strict causality, and a compensator that subtracts
 * the term before inverting a TCM. */
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define BOUND_SAMPLES 100000L

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t il[CAP], jl[CAP], ir[CAP], jr[CAP];
static hyst_rate_t R, Q;
static hyst_t H, Hinv;
static hyst_curve_t Cinv;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 6000u); }
void tearDown(void) {}

/* ---- The term as rate.h states it, in double ---- */

typedef struct {
    double a, w, p, v;
} ref_rate_t;

static void ref_init(ref_rate_t *r, double tau, double w, double x_rest)
{
    r->a = 1.0 / tau;
    r->w = w;
    r->p = x_rest;
    r->v = 0.0;
}

/* r[n] from the state before x, then v += a ((x - p) - v), p = x. */
static double ref_step(ref_rate_t *r, double x)
{
    const double out = r->w * r->v;
    r->v += r->a * ((x - r->p) - r->v);
    r->p = x;
    return out;
}

static void test_init_refuses_each_bad_argument(void)
{
    hyst_rate_t before;
    memset(&R, 0xA5, sizeof R);
    before = R;
    UNCHANGED(&before, &R, HYST_ERR_NULL, hyst_rate_init(NULL, 10.0, 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_LAYOUT,
              HYST_DEFAULT_NAME_(rate_init_)(&R, 10.0, 0.5, 0.0, HYST_LAYOUT ^ 1ul));
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, HYST_WIDE_C(0.999), 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, 0.0, 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, -5.0, 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, (hyst_wide_t)NAN, 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, (hyst_wide_t)INFINITY, 0.5, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_WEIGHTS, hyst_rate_init(&R, 10.0, (hyst_wide_t)NAN, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_WEIGHTS,
              hyst_rate_init(&R, 10.0, (hyst_wide_t)-INFINITY, 0.0));
    UNCHANGED(&before, &R, HYST_ERR_NONFINITE, hyst_rate_init(&R, 10.0, 0.5, (hyst_wide_t)NAN));
    UNCHANGED(&before, &R, HYST_ERR_NONFINITE,
              hyst_rate_init(&R, 10.0, 0.5, (hyst_wide_t)INFINITY));
#ifndef HYST_USE_DOUBLE
    /* finite in double, not in float: 1e39, and a = 1e-38 below FLT_MIN */
#ifndef HYST_NO_DOUBLE /* hyst_wide_t is float there: it holds no 1e39 */
    UNCHANGED(&before, &R, HYST_ERR_NONFINITE, hyst_rate_init(&R, 10.0, 0.5, 1e39));
    UNCHANGED(&before, &R, HYST_ERR_WEIGHTS, hyst_rate_init(&R, 10.0, 1e39, 0.0));
#endif
    UNCHANGED(&before, &R, HYST_ERR_ARG, hyst_rate_init(&R, HYST_WIDE_C(1e38), 0.5, 0.0));
    /* the drive limit: FLT_MAX / (4 |w|) */
    UNCHANGED(&before, &R, HYST_ERR_NONFINITE,
              hyst_rate_init(&R, 10.0, HYST_WIDE_C(1e10), HYST_WIDE_C(1e29)));
#else
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 1e38, 0.5, 1e39));
#endif
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 1.0, 0.5, 0.25)); /* the least tau */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_status(&R));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_rate_events(&R));
    TEST_ASSERT_TRUE(hyst_rate_output(&R) == 0); /* at rest: no change yet */
}

static void test_null_policy(void)
{
    TEST_ASSERT_TRUE(hyst_rate_step(NULL, 1) == 0);
    TEST_ASSERT_TRUE(hyst_rate_output(NULL) == 0);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_reset(NULL, 0));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_status(NULL));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_rate_events(NULL));
    hyst_rate_clear_events(NULL);
}

/* Against the double reference, within rate.h's bound
 * |w| (tau + 12) ulp(2M) / 2, for short and long time constants and a
 * drive away from 0. */
static void test_matches_the_double_reference_within_the_bound(void)
{
    static const double taus[3] = {1.0, 7.5, 2000.0};
    static const double span[2][2] = {{-1.0, 1.0}, {60.0, 100.0}};
    int t, d;
    for (t = 0; t < 3; ++t) {
        for (d = 0; d < 2; ++d) {
            const double lo = span[d][0], hi = span[d][1], w = -1.75;
            const double m = dabs(lo) > dabs(hi) ? dabs(lo) : dabs(hi);
            const double bound = dabs(w) * (taus[t] + 12.0) * real_ulp(2.0 * m) / 2.0;
            ref_rate_t ref;
            double x = lo, worst = 0.0, largest = 0.0;
            long i;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, (hyst_wide_t)taus[t], (hyst_wide_t)w,
                                                          (hyst_wide_t)lo));
            ref_init(&ref, taus[t], w, lo);
            for (i = 0; i < BOUND_SAMPLES; ++i) {
                const hyst_real_t xi = rng_walk(&rng, &x, lo, hi);
                const double r = (double)hyst_rate_step(&R, xi);
                const double want = ref_step(&ref, (double)xi);
                worst = dabs(r - want) > worst ? dabs(r - want) : worst;
                largest = dabs(want) > largest ? dabs(want) : largest;
            }
            TEST_PRINTF("tau %g, drive in [%g, %g]: |r| up to %g, max |r - r_ref| = %g, %g of "
                        "the bound",
                        taus[t], lo, hi, largest, worst, worst / bound);
            TEST_ASSERT_TRUE(worst <= bound);
            TEST_ASSERT_TRUE(largest > 1e-3 * (hi - lo) / taus[t]); /* the term moved */
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_status(&R));
        }
    }
}

static void test_reset(void)
{
    hyst_rate_t copy;
    double x = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 4.0, 2.0, 0.25));
    for (i = 0; i < 100; ++i) {
        (void)hyst_rate_step(&R, rng_walk(&rng, &x, -1.0, 1.0));
    }
    (void)hyst_rate_step(&R, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_rate_events(&R));
    copy = R;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_rate_reset(&R, (hyst_real_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_rate_reset(&R, -REAL_INF));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &R, sizeof R);
    memset(&Q, 0, sizeof Q); /* not initialised */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_rate_reset(&Q, 0));
    /* reset to 0.75: the same samples as a fresh instance resting there */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_reset(&R, HYST_REAL_C(0.75)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_status(&R));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_rate_events(&R));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&Q, 4.0, 2.0, 0.75));
    Q.seq = R.seq; /* the sequence counter (snapshots) counts R's changes */
    TEST_ASSERT_EQUAL_MEMORY(&Q, &R, sizeof R);
    for (i = 0; i < 100; ++i) {
        const hyst_real_t xi = rng_walk(&rng, &x, -1.0, 1.0);
        TEST_ASSERT_TRUE(hyst_rate_step(&R, xi) == hyst_rate_step(&Q, xi));
    }
}

/* NaN, infinities and finite drives beyond the limit (the type's largest
 * number / (4 max(1, |w|))) are ignored, nothing moves; at the limit,
 * swinging from one end to the other, every output stays finite. */
static void test_bad_drives_leave_the_state(void)
{
#ifdef HYST_USE_DOUBLE
    const double top = DBL_MAX;
#else
    const double top = FLT_MAX;
#endif
    const hyst_real_t bad[3] = {(hyst_real_t)NAN, REAL_INF, -REAL_INF};
    const double limit = top / 6.0; /* |w| = 1.5 */
    double x = 0.0;
    int b;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 3.0, -1.5, 0.0));
    for (i = 0; i < 50; ++i) {
        (void)hyst_rate_step(&R, rng_walk(&rng, &x, -1.0, 1.0));
    }
    for (b = 0; b < 4; ++b) {
        hyst_rate_t copy = R;
        const hyst_real_t r = hyst_rate_output(&R);
        const hyst_real_t xb = b < 3 ? bad[b] : (hyst_real_t)(0.9 * top);
        TEST_ASSERT_TRUE(hyst_rate_step(&R, xb) == r);
        TEST_ASSERT_EQUAL_INT(b < 3 ? HYST_ERR_NONFINITE : HYST_ERR_DOMAIN, hyst_rate_status(&R));
        TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_rate_events(&R));
        copy.status = R.status;
        copy.events = R.events;
        copy.seq = R.seq; /* the sequence counter (snapshots) counts every sample */
        TEST_ASSERT_EQUAL_MEMORY(&copy, &R, sizeof R);
    }
    for (i = 0; i < 200; ++i) { /* at the limit, both signs: finite */
        const hyst_real_t xi = (hyst_real_t)((i % 2 ? -0.999 : 0.999) * limit);
        const hyst_real_t r = hyst_rate_step(&R, xi);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_status(&R));
        TEST_ASSERT_TRUE(r - r == 0 && hyst_rate_output(&R) - hyst_rate_output(&R) == 0);
    }
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_rate_events(&R)); /* sticky */
    hyst_rate_clear_events(&R);
    TEST_ASSERT_EQUAL_UINT(0u, hyst_rate_events(&R));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_rate_reset(&R, (hyst_real_t)(0.9 * top)));
}

/* r[n] does not depend on x[n]: two instances with one history return the
 * same r whatever drive they take now, and output() tells it beforehand. */
static void test_strictly_causal(void)
{
    double x = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 10.0, HYST_WIDE_C(0.7), 0.0));
    for (i = 0; i < 2000; ++i) {
        const hyst_real_t xi = rng_walk(&rng, &x, -1.0, 1.0), before = hyst_rate_output(&R);
        hyst_real_t a, b;
        Q = R;
        a = hyst_rate_step(&R, xi);
        b = hyst_rate_step(&Q, -xi + HYST_REAL_C(3.0));
        TEST_ASSERT_TRUE(a == before && b == before);
        TEST_ASSERT_TRUE(hyst_rate_output(&R) != hyst_rate_output(&Q)); /* x[n] counts at n+1 */
    }
}

/* A plant y = H[x] + r (H a TCM of the paper's Eq. 20, r the rate term) and
 * its compensator: x = H^-1[y_d - r] with r known before x; y returns y_d
 * within the round trip's own tolerance and rounding, while the rate term
 * alone moves the output by far more. */
static void test_compensation_round_trip(void)
{
    hyst_curve_t fwd;
    double range, y_lo, y_hi, worst_all = 0.0, tol;
    int kind;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &paper_eq20));
    y_lo = (double)CURVE_NUM(fwd.y_lo);
    y_hi = (double)CURVE_NUM(fwd.y_hi);
    range = y_hi - y_lo;
    tol = TOL_OF_RANGE + 8.0 * real_ulp(dabs(y_hi) > dabs(y_lo) ? dabs(y_hi) : dabs(y_lo)) / range;
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        static hyst_real_t desired[20000];
        /* a jump over the drive's span: 5 % */
        const hyst_wide_t w = (hyst_wide_t)(0.05 * range / 40.0);
        double worst = 0.0, rate_max = 0.0;
        long i;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&H, &fwd, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_exact(&Hinv, &Cinv, &paper_eq20, il, jl,
                                                               ir, jr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 3.0, w, 0.0)); /* compensator's */
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&Q, 3.0, w, 0.0)); /* plant's */
        fill_signal(kind, &rng, y_lo + 0.1 * range, y_hi - 0.1 * range, desired, 20000);
        for (i = 0; i < 20000L; ++i) {
            const hyst_real_t r = hyst_rate_output(&R);
            const hyst_real_t x = hyst_step(&Hinv, desired[i] - r);
            double y, err;
            (void)hyst_rate_step(&R, x);
            y = (double)hyst_step(&H, x) + (double)hyst_rate_step(&Q, x);
            err = dabs(y - (double)desired[i]) / range;
            worst = err > worst ? err : worst;
            rate_max = dabs((double)r) / range > rate_max ? dabs((double)r) / range : rate_max;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&Hinv)); /* y_d - r stayed in range */
        }
        TEST_PRINTF("%s: rate term up to %g of the range, max |y - y_d| / range = %g "
                    "(tolerance %g)",
                    signal_name[kind], rate_max, worst, tol);
        TEST_ASSERT_TRUE(rate_max > 10.0 * tol); /* far above the tolerance: the term counts */
        worst_all = worst > worst_all ? worst : worst_all;
    }
    TEST_ASSERT_TRUE(worst_all <= tol);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_refuses_each_bad_argument);
    RUN_TEST(test_null_policy);
    RUN_TEST(test_matches_the_double_reference_within_the_bound);
    RUN_TEST(test_reset);
    RUN_TEST(test_bad_drives_leave_the_state);
    RUN_TEST(test_strictly_causal);
    RUN_TEST(test_compensation_round_trip);
    return UNITY_END();
}
