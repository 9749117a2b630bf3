/* SPDX-License-Identifier: MIT */
/* The Prandtl-Ishlinskii model: parameter checks, the operator rules, the
 * analytic inverse, and the paper's result that TCM with f0 = f_PI
 * reproduces PI exactly (docs/theory.md). */
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <math.h>

#define SAMPLES 100000L
#define MAX_OPS 64
#define CAP 4096

/* Paper Table 1: 10 operators on [0, 1]. */
static const hyst_real_t table1_r[10] = {
    HYST_REAL_C(0.0), HYST_REAL_C(0.1), HYST_REAL_C(0.2), HYST_REAL_C(0.3), HYST_REAL_C(0.4),
    HYST_REAL_C(0.5), HYST_REAL_C(0.6), HYST_REAL_C(0.7), HYST_REAL_C(0.8), HYST_REAL_C(0.9)};
static const hyst_real_t table1_w[10] = {
    HYST_REAL_C(0.0789), HYST_REAL_C(0.2268), HYST_REAL_C(0.1928), HYST_REAL_C(0.2019),
    HYST_REAL_C(0.1995), HYST_REAL_C(0.2001), HYST_REAL_C(0.2000), HYST_REAL_C(0.2000),
    HYST_REAL_C(0.1999), HYST_REAL_C(0.2005)};

#ifdef HYST_USE_DOUBLE
#define EQUIV_TOL_ABS 1e-12  /* target: max |TCM - PI| <= 1e-12 in double */
#define EQUIV_TOL_REL 1e-12
#else
#define EQUIV_TOL_ABS 1e30   /* float: judged relative to the range only */
#define EQUIV_TOL_REL 2e-6   /* target: <= 2e-6 of the output range */
#endif

static hyst_real_t z[MAX_OPS], zi[MAX_OPS], r_inv[MAX_OPS], w_inv[MAX_OPS];
static hyst_real_t bx[MAX_OPS + 1], by[MAX_OPS + 1];
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t sig[SAMPLES];
static hyst_pi_t P, Q;
static hyst_t S;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 4242u); }
void tearDown(void) {}

/* f_PI(x) = sum w_i max(0, x - r_i), in double, from the parameters. */
static double loading(const hyst_real_t *r, const hyst_real_t *w, size_t n, double x)
{
    double y = 0.0;
    size_t i;
    for (i = 0u; i < n; ++i) {
        y += (double)w[i] * (x > (double)r[i] ? x - (double)r[i] : 0.0);
    }
    return y;
}

/* A play-operator PI in double, written from Eq. 15 independently. */
static double ref_pi(const hyst_real_t *r, const hyst_real_t *w, size_t n, double *state,
                     double x)
{
    double y = 0.0;
    size_t i;
    for (i = 0u; i < n; ++i) {
        const double low = x < state[i] ? x : state[i];
        state[i] = x - (double)r[i] > low ? x - (double)r[i] : low;
        y += (double)w[i] * state[i];
    }
    return y;
}

static void test_parameters_are_checked_with_specific_codes(void)
{
    hyst_real_t r[3] = {0, HYST_REAL_C(0.2), HYST_REAL_C(0.5)};
    hyst_real_t w[3] = {HYST_REAL_C(1.0), HYST_REAL_C(0.5), HYST_REAL_C(-0.2)};
    hyst_pi_t untouched;
    hyst_curve_t loading;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, r, w, z, 3u));
    untouched = P;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_init(NULL, r, w, z, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_init(&P, NULL, w, z, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_init(&P, r, NULL, z, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_init(&P, r, w, NULL, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_pi_init(&P, r, w, z, 0u));
    r[0] = HYST_REAL_C(0.1); /* r1 must be 0 */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_pi_init(&P, r, w, z, 3u));
    r[0] = 0;
    r[2] = HYST_REAL_C(0.2); /* not strictly increasing */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_pi_init(&P, r, w, z, 3u));
    r[2] = (hyst_real_t)INFINITY;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_pi_init(&P, r, w, z, 3u));
    r[2] = HYST_REAL_C(0.5);
    w[0] = 0; /* w1 > 0 */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_init(&P, r, w, z, 3u));
    w[0] = HYST_REAL_C(1.0);
    w[2] = HYST_REAL_C(-1.5); /* W3 = 1 + 0.5 - 1.5 = 0 */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_init(&P, r, w, z, 3u));
    w[2] = (hyst_real_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_init(&P, r, w, z, 3u));
    TEST_ASSERT_EQUAL_MEMORY(&untouched, &P, sizeof P);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_inverse_params(r, w, 3u, r_inv, w_inv));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS,
                          hyst_pi_loading_curve(&loading, r, w, 3u, 1, bx, by));
}

/* Two operators, r = (0, 0.5), w = (1, 2): every rule by hand. */
static void test_operators_follow_eq15(void)
{
    static const hyst_real_t r[2] = {0, HYST_REAL_C(0.5)};
    static const hyst_real_t w[2] = {HYST_REAL_C(1.0), HYST_REAL_C(2.0)};
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, r, w, z, 2u));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_pi_output(&P));
    /* first sample 0.8: z = (0.8, 0.3), on the loading curve */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.4f, (float)hyst_pi_step(&P, HYST_REAL_C(0.8)));
    /* fall to 0.6: z1 = max(0.6, min(0.6, 0.8)) = 0.6, z2 = max(0.1, min(0.6, 0.3)) = 0.3 */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.2f, (float)hyst_pi_step(&P, HYST_REAL_C(0.6)));
    /* fall to 0.2: z = (0.2, 0.2) */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.6f, (float)hyst_pi_step(&P, HYST_REAL_C(0.2)));
    /* rise to 0.6: z1 = 0.6, z2 = max(0.1, min(0.6, 0.2)) = 0.2 */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, (float)hyst_pi_step(&P, HYST_REAL_C(0.6)));
    /* NaN: ignored */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, (float)hyst_pi_step(&P, (hyst_real_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_pi_status(&P));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_pi_events(&P));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, (float)hyst_pi_step(&P, HYST_REAL_C(0.6)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_status(&P));
    /* reset: first-sample rule again; a negative start sets every z to x */
    hyst_pi_reset(&P);
    TEST_ASSERT_EQUAL_UINT(0u, hyst_pi_events(&P));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -0.6f, (float)hyst_pi_step(&P, HYST_REAL_C(-0.2)));
}

/* Output of the first sample equals f_PI(x0) for x0 >= 0 (loading curve). */
static void test_first_sample_lands_on_loading_curve(void)
{
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, table1_r, table1_w, z, 10u));
    for (k = 0; k < 100; ++k) {
        const double x0 = rng_range(&rng, 0.0, 1.2);
        hyst_pi_reset(&P);
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, loading(table1_r, table1_w, 10u, x0),
                                  (double)hyst_pi_step(&P, (hyst_real_t)x0));
    }
}

static void test_process_equals_step_and_reference(void)
{
    static hyst_real_t y[1000];
    double state[10] = {0};
    double worst = 0.0;
    long i;
    fill_signal(SIG_JUMPS, &rng, -0.1, 1.1, sig, 1000);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, table1_r, table1_w, z, 10u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_process(&P, sig, y, 1000u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&Q, table1_r, table1_w, zi, 10u));
    for (i = 0; i < 1000; ++i) {
        const double d = fabs((double)y[i] - ref_pi(table1_r, table1_w, 10u, state, (double)sig[i]));
        TEST_ASSERT_EQUAL_MEMORY(&y[i], &(hyst_real_t){hyst_pi_step(&Q, sig[i])}, sizeof y[i]);
        worst = d > worst ? d : worst;
    }
    TEST_ASSERT_TRUE(worst <= 10.0 * TOL_OF_RANGE);
    sig[3] = (hyst_real_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_pi_process(&P, sig, y, 10u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_process(&P, NULL, y, 10u));
}

static void test_loading_curve_is_f_pi(void)
{
    hyst_curve_t c;
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN,
                          hyst_pi_loading_curve(&c, table1_r, table1_w, 10u, HYST_REAL_C(0.9), bx, by));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_pi_loading_curve(&c, table1_r, table1_w, 10u, HYST_REAL_C(1.0), bx, by));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_PWL, c.kind);
    for (k = 0; k <= 200; ++k) {
        const double x = k / 200.0;
        TEST_ASSERT_DOUBLE_WITHIN(TOL_OF_RANGE, loading(table1_r, table1_w, 10u, x),
                                  (double)hyst_curve_eval(&c, (hyst_real_t)x));
    }
}

/* TCM(f_PI) vs PI on n samples of sig; returns max |dy|, *range = f_PI(hi). */
static double tcm_vs_pi(const hyst_real_t *r, const hyst_real_t *w, size_t n_ops,
                        hyst_real_t hi, long n, double *range)
{
    hyst_curve_t c;
    double worst = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_loading_curve(&c, r, w, n_ops, hi, bx, by));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &c, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, r, w, z, n_ops));
    for (i = 0; i < n; ++i) {
        const double a = (double)hyst_step(&S, sig[i]);
        const double b = (double)hyst_pi_step(&P, sig[i]);
        const double d = fabs(a - b);
        worst = d > worst ? d : worst;
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&S));
    *range = (double)c.y_hi.HYST_R - (double)c.y_lo.HYST_R;
    return worst;
}

static void test_tcm_with_f_pi_reproduces_table1_pi(void)
{
    int kind;
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        double range, err;
        fill_signal(kind, &rng, 0.0, 1.0, sig, SAMPLES);
        err = tcm_vs_pi(table1_r, table1_w, 10u, HYST_REAL_C(1.0), SAMPLES, &range);
        TEST_PRINTF("Table 1, %s, %ld samples: max |TCM - PI| = %g (%g of range %g)",
                    signal_name[kind], SAMPLES, err, err / range, range);
        TEST_ASSERT_TRUE(err <= EQUIV_TOL_ABS);
        TEST_ASSERT_TRUE(err <= EQUIV_TOL_REL * range);
    }
}

/* Random PI models: N in 1..MAX_OPS, positive weights, sorted thresholds. */
static void test_tcm_with_f_pi_reproduces_random_pi(void)
{
    static hyst_real_t r[MAX_OPS], w[MAX_OPS];
    double worst_rel = 0.0;
    int model;
    for (model = 0; model < 24; ++model) {
        const size_t n = 1u + (size_t)rng_below(&rng, MAX_OPS);
        const double hi = rng_range(&rng, 0.5, 100.0);
        double range, err;
        size_t i;
        r[0] = 0;
        w[0] = (hyst_real_t)rng_range(&rng, 0.01, 2.0);
        for (i = 1u; i < n; ++i) { /* sorted by construction, spacing >= hi/(8 MAX_OPS) */
            r[i] = (hyst_real_t)((double)r[i - 1u] +
                                 hi / (double)n * rng_range(&rng, 0.125, 0.95));
            w[i] = (hyst_real_t)rng_range(&rng, 0.001, 2.0);
        }
        fill_signal(model % SIG_KINDS, &rng, 0.0, hi, sig, 8000);
        err = tcm_vs_pi(r, w, n, (hyst_real_t)hi, 8000, &range);
        worst_rel = err / range > worst_rel ? err / range : worst_rel;
        TEST_ASSERT_TRUE(err <= EQUIV_TOL_ABS * (range > 1.0 ? range : 1.0));
        TEST_ASSERT_TRUE(err <= EQUIV_TOL_REL * range);
    }
    TEST_PRINTF("24 random PI models: max |TCM - PI| / range = %g", worst_rel);
}

static void test_inverse_parameters(void)
{
    /* r = (0, 0.5), w = (1, 2): f = x, then 1 + 3 (x - 0.5); inverse thresholds
     * (0, 0.5), weights (1, 1/3 - 1 = -2/3). */
    static const hyst_real_t r[2] = {0, HYST_REAL_C(0.5)};
    static const hyst_real_t w[2] = {HYST_REAL_C(1.0), HYST_REAL_C(2.0)};
    static hyst_real_t rr[MAX_OPS], ww[MAX_OPS];
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_inverse_params(r, w, 2u, r_inv, w_inv));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, (float)r_inv[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f, (float)r_inv[1]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, (float)w_inv[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -2.0f / 3.0f, (float)w_inv[1]);
    /* inverse of the inverse is the forward model */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_inverse_params(table1_r, table1_w, 10u, r_inv, w_inv));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_check(r_inv, w_inv, 10u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_inverse_params(r_inv, w_inv, 10u, rr, ww));
    for (i = 0u; i < 10u; ++i) {
        TEST_ASSERT_DOUBLE_WITHIN(10.0 * TOL_OF_RANGE, (double)table1_r[i], (double)rr[i]);
        TEST_ASSERT_DOUBLE_WITHIN(10.0 * TOL_OF_RANGE, (double)table1_w[i], (double)ww[i]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_inverse_params(r, w, 2u, NULL, w_inv));
}

/* Unchecked inverse PI weights (docs/reliability.md): inverse weights that, rounded, fail
 * hyst_pi_check() are refused with HYST_ERR_WEIGHTS, nothing written. */
static void test_inverse_weights_are_checked(void)
{
#ifdef HYST_USE_DOUBLE
    /* regress_pi_inverse_overflow: 1 / w_1 overflows (w_1 subnormal) */
    static const hyst_real_t w_sub[1] = {2.56e-317};
    /* regress_pi_inverse_cancel: W_2 / W_1 > 1 / eps, 1/W_1 + w'_2 = 0 */
    static const hyst_real_t r_fz[3] = {0, 9.1e-314, 5.7e21};
    static const hyst_real_t w_fz[3] = {7.5e20, 4.7e255, 3.7e-188};
#else
    static const hyst_real_t w_sub[1] = {1e-40f}; /* 1 / w_1 > FLT_MAX */
#endif
    static const hyst_real_t r1[1] = {0};
    /* the same cancellation, in both precisions: w'_2 rounds to -1 = -w'_1 */
    static const hyst_real_t r2[2] = {0, HYST_REAL_C(1.0)};
    static const hyst_real_t w2[2] = {HYST_REAL_C(1.0), HYST_REAL_C(1e30)};
    static const hyst_real_t w2_ok[2] = {HYST_REAL_C(1.0), HYST_REAL_C(1e3)};
    size_t i;
    for (i = 0u; i < 3u; ++i) {
        r_inv[i] = HYST_REAL_C(7.0);
        w_inv[i] = HYST_REAL_C(7.0);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_check(r1, w_sub, 1u)); /* the forward is valid */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_inverse_params(r1, w_sub, 1u, r_inv, w_inv));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_check(r2, w2, 2u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_inverse_params(r2, w2, 2u, r_inv, w_inv));
#ifdef HYST_USE_DOUBLE
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_check(r_fz, w_fz, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_WEIGHTS, hyst_pi_inverse_params(r_fz, w_fz, 3u, r_inv, w_inv));
#endif
    for (i = 0u; i < 3u; ++i) { /* nothing written */
        TEST_ASSERT_EQUAL_FLOAT(7.0f, (float)r_inv[i]);
        TEST_ASSERT_EQUAL_FLOAT(7.0f, (float)w_inv[i]);
    }
    /* a ratio well inside the precision is still accepted, and checks */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_inverse_params(r2, w2_ok, 2u, r_inv, w_inv));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_check(r_inv, w_inv, 2u));
}

/* PI(PI^-1(y_d)) = y_d, also outside the loading range (inputs < 0 and > r_N). */
static void test_inverse_pi_undoes_pi(void)
{
    int kind;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, table1_r, table1_w, z, 10u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init_inverse(&Q, &P, r_inv, w_inv, zi));
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        double worst = 0.0;
        long i;
        fill_signal(kind, &rng, -0.2, 1.3, sig, 20000);
        hyst_pi_reset(&P);
        hyst_pi_reset(&Q);
        for (i = 0; i < 20000; ++i) {
            const double y = (double)hyst_pi_step(&P, hyst_pi_step(&Q, sig[i]));
            const double d = fabs(y - (double)sig[i]);
            worst = d > worst ? d : worst;
        }
        TEST_PRINTF("PI(PI^-1(y)), %s: max error %g", signal_name[kind], worst);
        TEST_ASSERT_TRUE(worst <= TOL_OF_RANGE * 1.5);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_parameters_are_checked_with_specific_codes);
    RUN_TEST(test_operators_follow_eq15);
    RUN_TEST(test_first_sample_lands_on_loading_curve);
    RUN_TEST(test_process_equals_step_and_reference);
    RUN_TEST(test_loading_curve_is_f_pi);
    RUN_TEST(test_tcm_with_f_pi_reproduces_table1_pi);
    RUN_TEST(test_tcm_with_f_pi_reproduces_random_pi);
    RUN_TEST(test_inverse_parameters);
    RUN_TEST(test_inverse_weights_are_checked);
    RUN_TEST(test_inverse_pi_undoes_pi);
    return UNITY_END();
}
