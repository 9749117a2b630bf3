/* SPDX-License-Identifier: MIT */
/* Creep (creep.h): the lags against a plain double reference and within the
 * stated rounding bound, init and reset refusals that write nothing, NaN
 * samples, strict causality, a compensator that subtracts the creep before
 * inverting a TCM, and the fit: weights and offset recovered under noise,
 * singular records, refused input. */
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define SETTLE 1000L   /* samples fed before a fit's training window */
#define WINDOW 4000L   /* equations of a fit */
#define BOUND_SAMPLES 100000L

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t il[CAP], jl[CAP], ir[CAP], jr[CAP];
static hyst_real_t drive[SETTLE + WINDOW];
static double regressor[2][WINDOW];
static hyst_creep_t K, L;
static hyst_creep_fit_t F;
static hyst_t H, Hinv;
static hyst_curve_t Cinv;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 5000u); }
void tearDown(void) {}

/* ---- The model as creep.h states it, in double ---- */

typedef struct {
    size_t n;
    double a[HYST_CREEP_MAX_TERMS], w[HYST_CREEP_MAX_TERMS], s[HYST_CREEP_MAX_TERMS];
} ref_creep_t;

static void ref_init(ref_creep_t *r, size_t n, const hyst_wide_t *tau, const hyst_wide_t *w,
                     double x_rest)
{
    size_t k;
    r->n = n;
    for (k = 0u; k < n; ++k) {
        r->a[k] = 1.0 / (double)tau[k];
        r->w[k] = (double)w[k];
        r->s[k] = x_rest;
    }
}

/* c[n] from the states before x, then s += a (x - s). */
static double ref_step(ref_creep_t *r, double x)
{
    double c = 0.0;
    size_t k;
    for (k = 0u; k < r->n; ++k) {
        c += r->w[k] * r->s[k];
        r->s[k] += r->a[k] * (x - r->s[k]);
    }
    return c;
}

/* ---- Helpers ---- */

/* The bound on c of creep.h: sum_k |w_k| (tau_k + 4 n + 12) ulp(M) / 2. */
static double c_bound(size_t n, const hyst_wide_t *tau, const hyst_wide_t *w, double m)
{
    double sum = 0.0;
    size_t k;
    for (k = 0u; k < n; ++k) {
        sum += dabs((double)w[k]) * ((double)tau[k] + 4.0 * (double)n + 12.0);
    }
    return sum * real_ulp(m) / 2.0;
}

/* ---- The instance ---- */

static void test_init_refuses_each_bad_argument(void)
{
    hyst_wide_t tau[2] = {10.0, 100.0}, w[2] = {0.5, -0.25};
    hyst_creep_t before;
    memset(&K, 0xA5, sizeof K);
    before = K;
    UNCHANGED(&before, &K, HYST_ERR_NULL, hyst_creep_init(NULL, 2u, tau, w, 0.0));
    UNCHANGED(&before, &K, HYST_ERR_NULL, hyst_creep_init(&K, 2u, NULL, w, 0.0));
    UNCHANGED(&before, &K, HYST_ERR_NULL, hyst_creep_init(&K, 2u, tau, NULL, 0.0));
    UNCHANGED(&before, &K, HYST_ERR_LAYOUT,
              HYST_DEFAULT_NAME_(creep_init_)(&K, 2u, tau, w, 0.0, HYST_LAYOUT ^ 1ul));
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 0u, tau, w, 0.0));
    UNCHANGED(&before, &K, HYST_ERR_ARG,
              hyst_creep_init(&K, HYST_CREEP_MAX_TERMS + 1u, tau, w, 0.0));
    tau[1] = HYST_WIDE_C(0.999);
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
    tau[1] = 0.0;
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
    tau[1] = -5.0;
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
    tau[1] = (hyst_wide_t)NAN;
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
    tau[1] = (hyst_wide_t)INFINITY;
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
    tau[1] = 100.0;
    w[1] = (hyst_wide_t)NAN;
    UNCHANGED(&before, &K, HYST_ERR_WEIGHTS, hyst_creep_init(&K, 2u, tau, w, 0.0));
    w[1] = (hyst_wide_t)-INFINITY;
    UNCHANGED(&before, &K, HYST_ERR_WEIGHTS, hyst_creep_init(&K, 2u, tau, w, 0.0));
    w[1] = -0.25;
    UNCHANGED(&before, &K, HYST_ERR_NONFINITE, hyst_creep_init(&K, 2u, tau, w, (hyst_wide_t)NAN));
    UNCHANGED(&before, &K, HYST_ERR_NONFINITE,
              hyst_creep_init(&K, 2u, tau, w, (hyst_wide_t)INFINITY));
#ifndef HYST_USE_DOUBLE
    /* finite in double, not in float: 1e39, and a = 1e-38 below FLT_MIN */
#ifndef HYST_NO_DOUBLE /* hyst_wide_t is float there: it holds no 1e39 */
    UNCHANGED(&before, &K, HYST_ERR_NONFINITE, hyst_creep_init(&K, 2u, tau, w, 1e39));
    w[0] = 1e39;
    UNCHANGED(&before, &K, HYST_ERR_WEIGHTS, hyst_creep_init(&K, 2u, tau, w, 0.0));
    w[0] = 0.5;
#endif
    tau[0] = HYST_WIDE_C(1e38);
    UNCHANGED(&before, &K, HYST_ERR_ARG, hyst_creep_init(&K, 2u, tau, w, 0.0));
#else
    tau[0] = 1e38; /* a = 1e-38 is a normal double */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 1e39));
#endif
    tau[0] = 1.0; /* the least time constant: a one-sample delay of the drive */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 0.5));
    TEST_ASSERT_EQUAL_UINT(2u, (unsigned)hyst_creep_size(&K));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&K));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_creep_events(&K));
    TEST_ASSERT_TRUE(hyst_creep_output(&K) == (hyst_real_t)(0.5 * 0.5 + -0.25 * 0.5));
}

static void test_null_policy(void)
{
    TEST_ASSERT_TRUE(hyst_creep_step(NULL, 1) == 0);
    TEST_ASSERT_TRUE(hyst_creep_output(NULL) == 0);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_reset(NULL, 0));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_status(NULL));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_creep_events(NULL));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_creep_size(NULL));
    hyst_creep_clear_events(NULL);
}

/* Three lags against the double reference, within the bound of creep.h. */
static void test_matches_the_double_reference(void)
{
    static const hyst_wide_t tau[3] = {2.0, 7.5, 300.0}, w[3] = {0.25, -0.5, 1.25};
    const double lo = 20.0, hi = 60.0, x_rest = 35.0;
    const double bound = c_bound(3u, tau, w, hi);
    ref_creep_t ref;
    double x = x_rest, worst = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 3u, tau, w, (hyst_wide_t)x_rest));
    ref_init(&ref, 3u, tau, w, x_rest);
    for (i = 0; i < 20000L; ++i) {
        const hyst_real_t xi = rng_walk(&rng, &x, lo, hi);
        const double c = (double)hyst_creep_step(&K, xi);
        const double err = dabs(c - ref_step(&ref, (double)xi));
        worst = err > worst ? err : worst;
    }
    TEST_PRINTF("3 lags, drive in [%g, %g]: max |c - c_ref| = %g, %g of the bound", lo, hi,
                worst, worst / bound);
    TEST_ASSERT_TRUE(worst <= bound);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&K));
}

/* One lag of tau = 5000 (weight 1: c is the state) over a random walk, and
 * two lags' c: the float state's error within (tau + 10) ulp(M) / 2. */
static void test_state_error_within_the_stated_bound(void)
{
    static const hyst_wide_t tau1[1] = {5000.0}, one[1] = {1.0};
    static const hyst_wide_t tau2[2] = {5000.0, 50.0};
    static const hyst_wide_t w2[2] = {HYST_WIDE_C(0.3), HYST_WIDE_C(-0.7)};
    static const double span[2][2] = {{-1.0, 1.0}, {60.0, 100.0}};
    int d;
    for (d = 0; d < 2; ++d) {
        const double lo = span[d][0], hi = span[d][1];
        const double m = dabs(lo) > dabs(hi) ? dabs(lo) : dabs(hi);
        const double bound = (5000.0 + 10.0) * real_ulp(m) / 2.0, bound2 = c_bound(2u, tau2, w2, m);
        ref_creep_t r1, r2;
        double x = lo, worst = 0.0, worst2 = 0.0;
        long i;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 1u, tau1, one, (hyst_wide_t)lo));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&L, 2u, tau2, w2, (hyst_wide_t)lo));
        ref_init(&r1, 1u, tau1, one, lo);
        ref_init(&r2, 2u, tau2, w2, lo);
        for (i = 0; i < BOUND_SAMPLES; ++i) {
            const hyst_real_t xi = rng_walk(&rng, &x, lo, hi);
            const double e1 = dabs((double)hyst_creep_step(&K, xi) - ref_step(&r1, (double)xi));
            const double e2 = dabs((double)hyst_creep_step(&L, xi) - ref_step(&r2, (double)xi));
            worst = e1 > worst ? e1 : worst;
            worst2 = e2 > worst2 ? e2 : worst2;
        }
        TEST_PRINTF("tau 5000, drive in [%g, %g], %ld samples: state error %g = %g of "
                    "(tau + 10) ulp(M) / 2; two lags' c: %g of its bound",
                    lo, hi, BOUND_SAMPLES, worst, worst / bound, worst2 / bound2);
        TEST_ASSERT_TRUE(worst <= bound);
        TEST_ASSERT_TRUE(worst2 <= bound2);
    }
}

static void test_reset(void)
{
    static const hyst_wide_t tau[2] = {4.0, 40.0}, w[2] = {0.5, 2.0};
    hyst_creep_t copy;
    double x = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 0.25));
    for (i = 0; i < 100; ++i) {
        (void)hyst_creep_step(&K, rng_walk(&rng, &x, -1.0, 1.0));
    }
    (void)hyst_creep_step(&K, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_creep_events(&K));
    copy = K;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_creep_reset(&K, (hyst_real_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_creep_reset(&K, -REAL_INF));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &K, sizeof K);
    memset(&L, 0, sizeof L); /* not initialised */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_creep_reset(&L, 0));
    /* reset to 0.75: the same samples as a fresh instance resting there */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_reset(&K, HYST_REAL_C(0.75)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&K));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_creep_events(&K));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&L, 2u, tau, w, 0.75));
    L.seq = K.seq; /* the sequence counter (snapshots) counts K's changes */
    TEST_ASSERT_EQUAL_MEMORY(&L, &K, sizeof K);
    TEST_ASSERT_TRUE(hyst_creep_output(&K) == (hyst_real_t)(2.5 * 0.75));
    for (i = 0; i < 100; ++i) {
        const hyst_real_t xi = rng_walk(&rng, &x, -1.0, 1.0);
        TEST_ASSERT_TRUE(hyst_creep_step(&K, xi) == hyst_creep_step(&L, xi));
    }
}

/* Finite drives near the type's largest number: x - s overflowed and the
 * lags became NaN for good, status OK (float, drives near 3e38); a large
 * weight overflowed the contribution. A drive beyond the limit (the largest
 * number / (4 max(1, sum |w|))) is refused as a NaN is, nothing moves;
 * at the limit, every lag and output stays finite. */
static void test_extreme_drives_are_refused_not_overflowing(void)
{
#ifdef HYST_USE_DOUBLE
    const double top = DBL_MAX;
#else
    const double top = FLT_MAX;
#endif
    static const hyst_wide_t tau[2] = {3.0, 30.0}, w[2] = {1.0, -0.5};
    const hyst_wide_t big_w[1] = {HYST_WIDE_C(1e30)}, tau1[1] = {5.0};
    const double limit = top / 6.0; /* sum |w| = 1.5 */
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 0.0));
    for (i = 0; i < 40; ++i) {
        hyst_creep_t copy = K;
        const hyst_real_t c = hyst_creep_output(&K);
        const hyst_real_t x = (hyst_real_t)((i % 2 ? -0.9 : 0.9) * top);
        TEST_ASSERT_TRUE(hyst_creep_step(&K, x) == c);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_creep_status(&K));
        TEST_ASSERT_EQUAL_MEMORY(copy.state, K.state, sizeof K.state);
    }
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_creep_events(&K));
    for (i = 0; i < 200; ++i) { /* at the limit, both signs: finite */
        const hyst_real_t x = (hyst_real_t)((i % 7 < 3 ? -0.999 : 0.999) * limit);
        const hyst_real_t c = hyst_creep_step(&K, x);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&K));
        TEST_ASSERT_TRUE(c - c == 0 && hyst_creep_output(&K) - hyst_creep_output(&K) == 0);
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE,
                          hyst_creep_init(&L, 2u, tau, w, (hyst_wide_t)(0.9 * top)));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_creep_reset(&K, (hyst_real_t)(0.9 * top)));
    /* a large weight: the contribution's limit */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&L, 1u, tau1, big_w, 0.0));
    (void)hyst_creep_step(&L, (hyst_real_t)(top / 1e30));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_creep_status(&L));
    for (i = 0; i < 100; ++i) {
        (void)hyst_creep_step(&L, (hyst_real_t)(0.2 * top / 1e30));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&L));
    TEST_ASSERT_TRUE(hyst_creep_output(&L) - hyst_creep_output(&L) == 0);
}

static void test_nonfinite_sample_leaves_the_state(void)
{
    static const hyst_wide_t tau[2] = {3.0, 30.0}, w[2] = {1.0, -0.5};
    const hyst_real_t bad[3] = {(hyst_real_t)NAN, REAL_INF, -REAL_INF};
    double x = 0.0;
    int b;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 0.0));
    for (i = 0; i < 50; ++i) {
        (void)hyst_creep_step(&K, rng_walk(&rng, &x, -1.0, 1.0));
    }
    for (b = 0; b < 3; ++b) {
        hyst_creep_t copy = K;
        const hyst_real_t c = hyst_creep_output(&K);
        TEST_ASSERT_TRUE(hyst_creep_step(&K, bad[b]) == c);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_creep_status(&K));
        TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_creep_events(&K));
        copy.status = K.status;
        copy.events = K.events;
        TEST_ASSERT_TRUE(copy.seq != K.seq); /* a saver must see the new status */
        copy.seq = K.seq;
        TEST_ASSERT_EQUAL_MEMORY(&copy, &K, sizeof K);
    }
    (void)hyst_creep_step(&K, HYST_REAL_C(0.5));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_status(&K));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_creep_events(&K)); /* sticky */
    hyst_creep_clear_events(&K);
    TEST_ASSERT_EQUAL_UINT(0u, hyst_creep_events(&K));
}

/* c[n] does not depend on x[n]: two instances with one history return the
 * same c whatever drive they take now, and output() tells it beforehand. */
static void test_strictly_causal(void)
{
    static const hyst_wide_t tau[3] = {1.0, 10.0, 100.0};
    static const hyst_wide_t w[3] = {HYST_WIDE_C(0.7), HYST_WIDE_C(-0.2), HYST_WIDE_C(0.4)};
    double x = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 3u, tau, w, 0.0));
    for (i = 0; i < 2000; ++i) {
        const hyst_real_t xi = rng_walk(&rng, &x, -1.0, 1.0), before = hyst_creep_output(&K);
        hyst_real_t a, b;
        L = K;
        a = hyst_creep_step(&K, xi);
        b = hyst_creep_step(&L, -xi + HYST_REAL_C(3.0));
        TEST_ASSERT_TRUE(a == before && b == before);
        TEST_ASSERT_TRUE(hyst_creep_output(&K) != hyst_creep_output(&L)); /* x[n] counts at n+1 */
    }
}

/* A plant y = H[x] + c (H a TCM of the paper's Eq. 20, c two lags) and its
 * compensator: x = H^-1[y_d - c] with c known before x; y returns y_d
 * within the round trip's own tolerance (test_inverse.c) and rounding. */
static void test_compensation_round_trip(void)
{
    static const hyst_wide_t tau[2] = {150.0, 2000.0};
    hyst_wide_t w[2];
    hyst_curve_t fwd;
    double range, y_lo, y_hi, worst_all = 0.0, tol;
    int kind;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &paper_eq20));
    y_lo = (double)CURVE_NUM(fwd.y_lo);
    y_hi = (double)CURVE_NUM(fwd.y_hi);
    range = y_hi - y_lo;
    w[0] = (hyst_wide_t)(0.02 * range / 40.0); /* creep up to 5 % of the range at 40 V */
    w[1] = (hyst_wide_t)(0.03 * range / 40.0);
    tol = TOL_OF_RANGE + 8.0 * real_ulp(dabs(y_hi) > dabs(y_lo) ? dabs(y_hi) : dabs(y_lo)) / range;
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        static hyst_real_t desired[20000];
        double worst = 0.0, creep_max = 0.0;
        long i;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&H, &fwd, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_exact(&Hinv, &Cinv, &paper_eq20, il, jl,
                                                               ir, jr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, 0.0)); /* compensator's */
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&L, 2u, tau, w, 0.0)); /* plant's */
        fill_signal(kind, &rng, y_lo + 0.1 * range, y_hi - 0.05 * range, desired, 20000);
        for (i = 0; i < 20000L; ++i) {
            const hyst_real_t c = hyst_creep_output(&K);
            const hyst_real_t x = hyst_step(&Hinv, desired[i] - c);
            double y, err;
            (void)hyst_creep_step(&K, x);
            y = (double)hyst_step(&H, x) + (double)hyst_creep_step(&L, x);
            err = dabs(y - (double)desired[i]) / range;
            worst = err > worst ? err : worst;
            creep_max = (double)c / range > creep_max ? (double)c / range : creep_max;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&Hinv)); /* y_d - c stayed in range */
        }
        TEST_PRINTF("%s: creep up to %g of the range, max |y - y_d| / range = %g "
                    "(tolerance %g)", signal_name[kind], creep_max, worst, tol);
        TEST_ASSERT_TRUE(creep_max > 0.02); /* far above the tolerance: the creep counts */
        worst_all = worst > worst_all ? worst : worst_all;
    }
    TEST_ASSERT_TRUE(worst_all <= tol);
}

/* ---- The fit ---- */

/* The drive of a fit: a random walk on [-1, 1] from rest at -1. */
static void fit_drive(void)
{
    double x = -1.0;
    long i;
    for (i = 0; i < SETTLE + WINDOW; ++i) {
        drive[i] = rng_walk(&rng, &x, -1.0, 1.0);
    }
}

/* Feeds SETTLE samples, then adds WINDOW equations residual = offset +
 * sum w_k s_k + sigma N(0, 1) (the reference's states before x, kept in
 * regressor[]). */
static void fit_simulate(const hyst_wide_t *tau, const hyst_wide_t *w, double offset,
                         double sigma)
{
    ref_creep_t ref;
    long i;
    size_t k;
    ref_init(&ref, 2u, tau, w, -1.0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, tau, -1.0));
    for (i = 0; i < SETTLE + WINDOW; ++i) {
        const double x = (double)drive[i];
        if (i < SETTLE) {
            (void)ref_step(&ref, x);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_feed(&F, (hyst_wide_t)x));
            continue;
        }
        for (k = 0u; k < 2u; ++k) {
            regressor[k][i - SETTLE] = ref.s[k];
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_creep_fit_add(&F, (hyst_wide_t)x,
                                                 (hyst_wide_t)(offset + ref_step(&ref, x) +
                                                               sigma * rng_gauss(&rng))));
    }
}

/* Two lags, 4000 equations with noise: each estimate within 5 standard
 * errors, sigma^2 (X'X)^-1 of the centred regressors (and 1/N + m'(X'X)^-1 m
 * for the offset), computed here from the reference's states. */
static void test_fit_recovers_weights_under_noise(void)
{
    static const hyst_wide_t tau[2] = {30.0, 400.0}, w[2] = {HYST_WIDE_C(0.8), HYST_WIDE_C(-0.3)};
    const double offset = 0.15, sigma = 0.01, n = (double)WINDOW;
    /* a fit in float (HYST_NO_DOUBLE): its lags and sums round (measured 1.6e-6),
     * and its rms, from the sums, keeps sqrt(eps) of the residual's spread */
    const double exact = SETUP_IN_FLOAT ? 1e-5 : 1e-9, rms_floor = SETUP_IN_FLOAT ? 1e-3 : 1e-9;
    double mean[2] = {0.0, 0.0}, g[3] = {0.0, 0.0, 0.0}, inv[3], det, se[2], se_off;
    hyst_wide_t w_fit[2], off_fit, rms;
    long i;
    fit_drive();
    fit_simulate(tau, w, offset, 0.0); /* without noise first: exact */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_solve(&F, w_fit, &off_fit, &rms));
    TEST_PRINTF("no noise: w = (%g, %g), offset %g, rms %g", (double)w_fit[0],
                (double)w_fit[1], (double)off_fit, (double)rms);
    TEST_ASSERT_DOUBLE_WITHIN(exact, 0.8, (double)w_fit[0]);
    TEST_ASSERT_DOUBLE_WITHIN(exact, -0.3, (double)w_fit[1]);
    TEST_ASSERT_DOUBLE_WITHIN(exact, offset, (double)off_fit);
    TEST_ASSERT_TRUE(rms < rms_floor);

    fit_simulate(tau, w, offset, sigma);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_solve(&F, w_fit, &off_fit, &rms));
    for (i = 0; i < WINDOW; ++i) {
        mean[0] += regressor[0][i] / n;
        mean[1] += regressor[1][i] / n;
    }
    for (i = 0; i < WINDOW; ++i) {
        const double d0 = regressor[0][i] - mean[0], d1 = regressor[1][i] - mean[1];
        g[0] += d0 * d0;
        g[1] += d0 * d1;
        g[2] += d1 * d1;
    }
    det = g[0] * g[2] - g[1] * g[1];
    inv[0] = g[2] / det;
    inv[1] = -g[1] / det;
    inv[2] = g[0] / det;
    se[0] = sigma * sqrt(inv[0]);
    se[1] = sigma * sqrt(inv[2]);
    se_off = sigma * sqrt(1.0 / n + mean[0] * mean[0] * inv[0] + 2.0 * mean[0] * mean[1] * inv[1] +
                          mean[1] * mean[1] * inv[2]);
    TEST_PRINTF("sigma %g: w = (%f, %f), errors %f and %f standard errors (%g, %g); "
                "offset %f, %f standard errors; rms %f",
                sigma, (double)w_fit[0], (double)w_fit[1], ((double)w_fit[0] - 0.8) / se[0],
                ((double)w_fit[1] + 0.3) / se[1], se[0], se[1], (double)off_fit,
                ((double)off_fit - offset) / se_off, (double)rms);
    TEST_ASSERT_TRUE(dabs((double)w_fit[0] - 0.8) <= 5.0 * se[0]);
    TEST_ASSERT_TRUE(dabs((double)w_fit[1] + 0.3) <= 5.0 * se[1]);
    TEST_ASSERT_TRUE(dabs((double)off_fit - offset) <= 5.0 * se_off);
    /* the residual's RMS estimates sigma: its relative spread is 1 / sqrt(2 N), 1.1 % */
    TEST_ASSERT_DOUBLE_WITHIN(0.05 * sigma, sigma, (double)rms);
}

/* The fit's regressors are the instance's states before x: data made by
 * the instance itself (in the build's type) gives back its weights. */
static void test_fit_and_instance_share_the_convention(void)
{
    static const hyst_wide_t tau[2] = {20.0, 300.0}, w[2] = {1.5, -0.5};
#ifdef HYST_USE_DOUBLE
    const double tol = 1e-9;
#else
    const double tol = 1e-5; /* the float states' rounding; measured 8e-8 */
#endif
    hyst_wide_t w_fit[2], off_fit;
    long i;
    fit_drive();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&K, 2u, tau, w, -1.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, tau, -1.0));
    for (i = 0; i < SETTLE + WINDOW; ++i) {
        const double c = (double)hyst_creep_step(&K, drive[i]);
        TEST_ASSERT_EQUAL_INT(HYST_OK, i < SETTLE ? hyst_creep_fit_feed(&F, (hyst_wide_t)drive[i])
                                                  : hyst_creep_fit_add(&F, (hyst_wide_t)drive[i],
                                                                       (hyst_wide_t)(c - 0.25)));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_solve(&F, w_fit, &off_fit, NULL));
    TEST_PRINTF("from the instance's c: w = (%f, %f), offset %f", (double)w_fit[0],
                (double)w_fit[1], (double)off_fit);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 1.5, (double)w_fit[0]);
    TEST_ASSERT_DOUBLE_WITHIN(tol, -0.5, (double)w_fit[1]);
    TEST_ASSERT_DOUBLE_WITHIN(tol, -0.25, (double)off_fit);
}

/* Solve returns SINGULAR and writes nothing. */
static void assert_singular(const char *what)
{
    hyst_wide_t w_fit[2] = {-7.0, -7.0}, off_fit = -7.0, rms = -7.0;
    TEST_ASSERT_EQUAL_INT_MESSAGE(HYST_ERR_SINGULAR,
                                  hyst_creep_fit_solve(&F, w_fit, &off_fit, &rms), what);
    TEST_ASSERT_TRUE(w_fit[0] == -7.0 && w_fit[1] == -7.0 && off_fit == -7.0 && rms == -7.0);
}

static void test_fit_singular_cases(void)
{
    static const hyst_wide_t tau[2] = {10.0, 100.0}, same[2] = {50.0, 50.0};
    static const hyst_wide_t tau1[1] = {50.0}, two[1] = {2.0};
    const double exact = SETUP_IN_FLOAT ? 1e-5 : 1e-9; /* a fit in float: measured 6e-7 */
    hyst_wide_t w_fit[1], off_fit;
    ref_creep_t ref;
    double x = 0.0;
    long i;
    /* no equations, then as many as weights: fewer than the unknowns */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, tau, 0.0));
    assert_singular("no equations");
    for (i = 0; i < 2; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_creep_fit_add(&F, rng_walk(&rng, &x, -1.0, 1.0),
                                                 (hyst_wide_t)(0.1 * (double)i)));
    }
    assert_singular("two equations, three unknowns");
    /* a drive that stays where the lags rest: they never move */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, tau, HYST_WIDE_C(0.3)));
    for (i = 0; i < 500; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_add(&F, HYST_WIDE_C(0.3),
                                                          (hyst_wide_t)rng_gauss(&rng)));
    }
    assert_singular("settled drive");
    /* two equal time constants: the same column twice */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, same, 0.0));
    for (i = 0; i < 500; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_creep_fit_add(&F, rng_walk(&rng, &x, -1.0, 1.0),
                                                 (hyst_wide_t)rng_gauss(&rng)));
    }
    assert_singular("equal taus");
    /* a constant drive away from rest is not singular: one lag's step response */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 1u, tau1, 0.0));
    ref_init(&ref, 1u, tau1, two, 0.0);
    for (i = 0; i < 300; ++i) {
        const hyst_wide_t r = (hyst_wide_t)(0.5 + ref_step(&ref, 1.0));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_add(&F, 1.0, r));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_solve(&F, w_fit, &off_fit, NULL));
    TEST_ASSERT_DOUBLE_WITHIN(exact, 2.0, (double)w_fit[0]);
    TEST_ASSERT_DOUBLE_WITHIN(exact, 0.5, (double)off_fit);
}

static void test_fit_refuses_bad_input(void)
{
    hyst_wide_t tau[2] = {10.0, 100.0}, w_fit[2], off_fit;
    hyst_creep_fit_t before;
    double x = 0.0;
    long i;
    memset(&F, 0x5A, sizeof F);
    before = F;
    UNCHANGED(&before, &F, HYST_ERR_NULL, hyst_creep_fit_init(NULL, 2u, tau, 0.0));
    UNCHANGED(&before, &F, HYST_ERR_NULL, hyst_creep_fit_init(&F, 2u, NULL, 0.0));
    UNCHANGED(&before, &F, HYST_ERR_ARG, hyst_creep_fit_init(&F, 0u, tau, 0.0));
    UNCHANGED(&before, &F, HYST_ERR_ARG,
              hyst_creep_fit_init(&F, HYST_CREEP_MAX_TERMS + 1u, tau, 0.0));
    tau[1] = 0.5;
    UNCHANGED(&before, &F, HYST_ERR_ARG, hyst_creep_fit_init(&F, 2u, tau, 0.0));
    tau[1] = (hyst_wide_t)NAN;
    UNCHANGED(&before, &F, HYST_ERR_ARG, hyst_creep_fit_init(&F, 2u, tau, 0.0));
    tau[1] = 100.0;
    UNCHANGED(&before, &F, HYST_ERR_NONFINITE, hyst_creep_fit_init(&F, 2u, tau, (hyst_wide_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_init(&F, 2u, tau, 0.0));
    for (i = 0; i < 100; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_creep_fit_add(&F, rng_walk(&rng, &x, -1.0, 1.0),
                                                 (hyst_wide_t)(0.01 * (double)i)));
    }
    before = F;
    UNCHANGED(&before, &F, HYST_ERR_NONFINITE, hyst_creep_fit_add(&F, (hyst_wide_t)NAN, 0.0));
    UNCHANGED(&before, &F, HYST_ERR_NONFINITE, hyst_creep_fit_add(&F, 0.5, (hyst_wide_t)INFINITY));
    UNCHANGED(&before, &F, HYST_ERR_NONFINITE, hyst_creep_fit_feed(&F, (hyst_wide_t)-INFINITY));
    UNCHANGED(&before, &F, HYST_ERR_NULL, hyst_creep_fit_solve(&F, NULL, &off_fit, NULL));
    UNCHANGED(&before, &F, HYST_ERR_NULL, hyst_creep_fit_solve(&F, w_fit, NULL, NULL));
    /* solve reads the fit only */
    UNCHANGED(&before, &F, HYST_OK, hyst_creep_fit_solve(&F, w_fit, &off_fit, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_fit_solve(NULL, w_fit, &off_fit, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_fit_add(NULL, 0.0, 0.0));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_fit_feed(NULL, 0.0));
}

/* hyst_creep_fit_holdout(): a residual made of a known lag and offset,
 * one sample missing, gives them back fitted on the first part and scores
 * the rest at rounding level; with noise added to the hold-out part only,
 * its score is that noise's RMS; bad arguments refused, nothing written. */
static void test_fit_holdout_scores_the_rest(void)
{
    enum { LEN = 3000, TRAIN = 2000 };
    static hyst_wide_t u[LEN], r[LEN];
    static const hyst_wide_t tau = 700.0, tau_bad = 0.5;
    hyst_creep_holdout_t h, keep;
    ref_creep_t ref;
    const hyst_wide_t w = HYST_WIDE_C(0.4);
    /* fit_rms comes from the fit's sums: in float it keeps sqrt(eps) of the
     * residual's spread (measured 7.6e-5); the scores are summed per sample */
    const double rms_floor = SETUP_IN_FLOAT ? 1e-3 : 1e-6;
    double x = 0.5, ss = 0.0;
    long k;
    ref_init(&ref, 1u, &tau, &w, 0.0);
    for (k = 0; k < LEN; ++k) {
        u[k] = (hyst_wide_t)rng_walk(&rng, &x, 0.0, 1.0);
        r[k] = (hyst_wide_t)(ref_step(&ref, (double)u[k]) - 0.2);
    }
    r[17] = (hyst_wide_t)NAN; /* missing: the lag goes on */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_holdout(1u, &tau, 0, u, r, LEN, TRAIN, &h));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.4, (double)h.weight[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, -0.2, (double)h.offset);
    TEST_ASSERT_EQUAL_UINT((unsigned)(LEN - TRAIN), (unsigned)h.holdout_used);
    TEST_ASSERT_TRUE(h.holdout_rms < 1e-6 && h.fit_rms < rms_floor && h.max_abs < 1e-6);
    for (k = TRAIN; k < LEN; ++k) { /* noise the fit never sees */
        const double e = rng_range(&rng, -0.01, 0.01);
        r[k] += (hyst_wide_t)e;
        ss += e * e;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_holdout(1u, &tau, 0, u, r, LEN, TRAIN, &h));
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.4, (double)h.weight[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, sqrt(ss / (double)(LEN - TRAIN)), (double)h.holdout_rms);
    TEST_ASSERT_TRUE(h.fit_rms < rms_floor);
    /* no hold-out part: the fit alone */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_fit_holdout(1u, &tau, 0, u, r, TRAIN, TRAIN, &h));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)h.holdout_used);
    memset(&keep, 0x5A, sizeof keep);
    h = keep;
    UNCHANGED(&keep, &h, HYST_ERR_ARG, hyst_creep_fit_holdout(1u, &tau, 0, u, r, TRAIN, LEN, &h));
    UNCHANGED(&keep, &h, HYST_ERR_ARG, hyst_creep_fit_holdout(1u, &tau_bad, 0, u, r, LEN, TRAIN, &h));
    UNCHANGED(&keep, &h, HYST_ERR_NULL, hyst_creep_fit_holdout(1u, &tau, 0, NULL, r, LEN, TRAIN, &h));
    UNCHANGED(&keep, &h, HYST_ERR_SINGULAR, hyst_creep_fit_holdout(1u, &tau, 0, u, r, LEN, 1u, &h));
    u[TRAIN + 5] = (hyst_wide_t)NAN;
    UNCHANGED(&keep, &h, HYST_ERR_NONFINITE, hyst_creep_fit_holdout(1u, &tau, 0, u, r, LEN, TRAIN, &h));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_fit_holdout(1u, &tau, 0, u, r, LEN, TRAIN, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_init_refuses_each_bad_argument);
    RUN_TEST(test_null_policy);
    RUN_TEST(test_matches_the_double_reference);
    RUN_TEST(test_state_error_within_the_stated_bound);
    RUN_TEST(test_reset);
    RUN_TEST(test_nonfinite_sample_leaves_the_state);
    RUN_TEST(test_extreme_drives_are_refused_not_overflowing);
    RUN_TEST(test_strictly_causal);
    RUN_TEST(test_compensation_round_trip);
    RUN_TEST(test_fit_recovers_weights_under_noise);
    RUN_TEST(test_fit_and_instance_share_the_convention);
    RUN_TEST(test_fit_singular_cases);
    RUN_TEST(test_fit_refuses_bad_input);
    RUN_TEST(test_fit_holdout_scores_the_rest);
    return UNITY_END();
}
