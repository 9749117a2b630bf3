/* SPDX-License-Identifier: MIT */
/* PI weights by non-negative least squares (hyst_pi_fit_*): known weights
 * recovered from simulated minor loops, exactly and under noise; a model
 * with a negative weight, where the constrained optimum must satisfy the
 * KKT conditions; the streaming and array entry points agree; bad input. */
#include "support.h"
#include "unity.h"
#include "hyst_port.h"

#include <math.h>
#include <stdio.h>

#define MAXN 4096
#define OPS 6

static hyst_wide_t xs[MAXN], ys[MAXN], zs[OPS][MAXN];
static hyst_real_t path[MAXN];
static hyst_wide_t work[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
static rng_t rng;

void setUp(void) { rng_seed(&rng, 2024u); }
void tearDown(void) {}

static double gauss(void) { return rng_gauss(&rng); }

/* Minor loops over [0, 1] (the paper's shrinking and growing triangle, twice),
 * from 0. Returns the count. */
static size_t excite(void)
{
    double levels[32];
    const int nl = paper_levels(0.0, 1.0, levels);
    long n = 1, k;
    path[0] = 0;
    n += ramp_path(0.0, levels, nl, 0.01, path + n, MAXN / 2 - 1);
    n += ramp_path(0.0, levels, nl, 0.01, path + n, MAXN / 2);
    for (k = 0; k < n; ++k) {
        xs[k] = (hyst_wide_t)path[k];
    }
    return (size_t)n;
}

/* The PI model's output (include/hyst/pi.h, written out here as the reference),
 * plus an offset and Gaussian noise; the operator outputs into zs. */
static void simulate(size_t n, const hyst_wide_t *r, const hyst_wide_t *w, size_t ops,
                     hyst_wide_t offset, double sigma)
{
    hyst_wide_t z[OPS] = {0};
    size_t k, i;
    for (k = 0u; k < n; ++k) {
        hyst_wide_t y = offset;
        for (i = 0u; i < ops; ++i) {
            const hyst_wide_t low = xs[k] < z[i] ? xs[k] : z[i];
            z[i] = xs[k] - r[i] > low ? xs[k] - r[i] : low;
            zs[i][k] = z[i];
            y += w[i] * z[i];
        }
        ys[k] = y + (hyst_wide_t)(sigma * gauss());
    }
}

static hyst_status_t fit_all(size_t n, size_t ops, hyst_wide_t *r, hyst_wide_t *w,
                             hyst_pi_fit_result_t *res)
{
    hyst_pi_fit_config_t cfg = {0};
    cfg.operators = ops;
    return hyst_pi_fit_record(&cfg, xs, ys, n, work, sizeof work / sizeof work[0], r, w, res);
}

static void test_known_weights_are_recovered_exactly(void)
{
    static const hyst_wide_t w_true[OPS] = {0.5, 0.0, HYST_WIDE_C(0.3), HYST_WIDE_C(0.2), 0.0,
                                               HYST_WIDE_C(0.1)};
    const size_t n = excite();
    hyst_wide_t r[OPS], w[OPS], r_true[OPS];
    hyst_pi_fit_result_t res;
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_thresholds(0, 1, OPS, r_true));
    simulate(n, r_true, w_true, OPS, -2.5, 0.0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, fit_all(n, OPS, r, w, &res));
    printf("exact: %u samples, offset %.12f, rms %.3g\n", (unsigned)n, (double)res.offset,
           (double)res.rms);
    /* normal equations in float (ident.h): 1.3e-5 measured */
    const double tol = SETUP_IN_FLOAT ? 1e-4 : 1e-9;
    for (i = 0u; i < OPS; ++i) {
        TEST_ASSERT_EQUAL_DOUBLE((double)r_true[i], (double)r[i]); /* uniform over [0, 1] */
        TEST_ASSERT_TRUE(w[i] >= 0);
        TEST_ASSERT_DOUBLE_WITHIN(tol, (double)w_true[i], (double)w[i]);
    }
    TEST_ASSERT_DOUBLE_WITHIN(tol, -2.5, (double)res.offset);
    TEST_ASSERT_TRUE(res.rms < tol && res.max_abs >= 0 && res.max_abs < tol);
    TEST_ASSERT_EQUAL_UINT(n, (unsigned)res.used);
    TEST_ASSERT_EQUAL_UINT(OPS, (unsigned)res.operators);
    TEST_ASSERT_TRUE(res.invertible);
}

static void test_noisy_weights_are_close_and_residual_is_the_noise(void)
{
    static const hyst_wide_t w_true[OPS] = {HYST_WIDE_C(0.8), HYST_WIDE_C(0.4), 0.0,
                                               HYST_WIDE_C(0.3), HYST_WIDE_C(0.2), HYST_WIDE_C(0.1)};
    const double sigma = 0.002;
    const size_t n = excite();
    hyst_wide_t r[OPS], w[OPS];
    hyst_pi_fit_result_t res;
    double worst = 0.0;
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_thresholds(0, 1, OPS, r));
    simulate(n, r, w_true, OPS, 1.0, sigma);
    TEST_ASSERT_EQUAL_INT(HYST_OK, fit_all(n, OPS, r, w, &res));
    for (i = 0u; i < OPS; ++i) {
        const double e = fabs((double)(w[i] - w_true[i]));
        TEST_ASSERT_TRUE(w[i] >= 0);
        worst = e > worst ? e : worst;
    }
    printf("noisy: sigma %.3g, worst weight error %.3g, offset %.6f, rms %.6g\n", sigma, worst,
           (double)res.offset, (double)res.rms);
    /* a weight's standard error here is about sigma / sqrt(n) / spread of its
     * operator's output (~0.1 to 0.3): 10 sigma is generous and still catches a bias */
    TEST_ASSERT_TRUE(worst < 10.0 * sigma);
    TEST_ASSERT_DOUBLE_WITHIN(10.0 * sigma, 1.0, (double)res.offset);
    TEST_ASSERT_DOUBLE_WITHIN(0.1 * sigma, sigma, (double)res.rms);
}

/* A model with a negative weight: the unconstrained fit would return it; the
 * non-negative one must stop at the constrained optimum. KKT there, with the
 * residual e = y - offset - Z w: the objective's gradient -Z'e is 0 on the
 * positive weights and >= 0 on the zero ones (and sum e = 0: the offset). */
static void test_negative_weight_gives_kkt_point(void)
{
    static const hyst_wide_t w_true[OPS] = {1.0, 0.5, HYST_WIDE_C(-0.3), HYST_WIDE_C(0.4),
                                               HYST_WIDE_C(0.3), HYST_WIDE_C(-0.2)};
    const size_t n = excite();
    hyst_wide_t r[OPS], w[OPS], e[MAXN];
    hyst_pi_fit_result_t res;
    double scale_z = 0.0, scale_e = 0.0, sum_e = 0.0;
    /* rounding's share; in float e's and the NNLS's (ident.h): 1.5e-5 measured */
    const double share = SETUP_IN_FLOAT ? 1e-3 : 1e-9;
    size_t i, k, zeros = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_thresholds(0, 1, OPS, r));
    simulate(n, r, w_true, OPS, 0.0, 0.0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, fit_all(n, OPS, r, w, &res));
    for (k = 0u; k < n; ++k) {
        e[k] = ys[k] - res.offset;
        for (i = 0u; i < OPS; ++i) {
            e[k] -= w[i] * zs[i][k];
        }
        scale_e += (double)(e[k] * e[k]);
        sum_e += (double)e[k];
    }
    for (i = 0u; i < OPS; ++i) {
        for (k = 0u; k < n; ++k) {
            scale_z += (double)(zs[i][k] * zs[i][k]);
        }
    }
    /* Cauchy-Schwarz bounds |Z'e| by this; rounding is a tiny share of it */
    scale_e = sqrt(scale_e * scale_z);
    printf("kkt: rms %.6g, weights", (double)res.rms);
    for (i = 0u; i < OPS; ++i) {
        double grad = 0.0;
        for (k = 0u; k < n; ++k) {
            grad -= (double)(zs[i][k] * e[k]);
        }
        printf(" %.6f (gradient %.3g)", (double)w[i], grad);
        TEST_ASSERT_TRUE(w[i] >= 0);
        if (w[i] > 0) {
            TEST_ASSERT_TRUE(fabs(grad) <= share * scale_e);
        } else {
            TEST_ASSERT_TRUE(grad >= -share * scale_e);
            ++zeros;
        }
    }
    printf("\n");
    TEST_ASSERT_TRUE(fabs(sum_e) <= share * sqrt(scale_e) * (double)n);
    TEST_ASSERT_TRUE(zeros >= 1u);
    TEST_ASSERT_TRUE(res.rms > 1e-4); /* the true model is out of reach */
    TEST_ASSERT_EQUAL_UINT(OPS - zeros, (unsigned)res.positive);
}

/* Streaming (firmware: no record kept) and array entry points give the same model;
 * the fitted model run by hyst_pi_step() reproduces the record. */
static void test_streaming_matches_record_and_pi_model(void)
{
    static const hyst_wide_t w_true[OPS] = {0.25, 0.5, 0.0, 0.125, 0.0, 0.5};
    const size_t n = excite();
    hyst_wide_t r[OPS], w[OPS], w2[OPS];
    hyst_pi_fit_result_t res, res2;
    hyst_pi_fit_t fit;
    size_t i, k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_thresholds(0, 1, OPS, r));
    simulate(n, r, w_true, OPS, 3.0, 0.001);
    TEST_ASSERT_EQUAL_INT(HYST_OK, fit_all(n, OPS, r, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_init(&fit, r, OPS, work, HYST_PI_FIT_WORK(OPS)));
    for (k = 0u; k < n; ++k) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_add(&fit, xs[k], ys[k]));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_solve(&fit, w2, &res2));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_pi_fit_solve(&fit, w2, &res2));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_pi_fit_add(&fit, 0.5, 0.5));
    for (i = 0u; i < OPS; ++i) {
        TEST_ASSERT_EQUAL_DOUBLE((double)w[i], (double)w2[i]);
    }
    TEST_ASSERT_EQUAL_DOUBLE((double)res.offset, (double)res2.offset);
    TEST_ASSERT_TRUE(res2.max_abs < 0); /* no second pass in the streaming API */
    /* float: the streaming rms from the normal equations is not resolved (ident.h): 1.1e-3 */
    TEST_ASSERT_DOUBLE_WITHIN((SETUP_IN_FLOAT ? 1e-2 : 1e-6) * (double)res.rms, (double)res.rms,
                              (double)res2.rms);
    {
        hyst_real_t rr[OPS], ww[OPS], zz[OPS];
        hyst_pi_t P;
        double ss = 0.0;
        for (i = 0u; i < OPS; ++i) {
            rr[i] = (hyst_real_t)r[i];
            ww[i] = (hyst_real_t)w[i];
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, rr, ww, zz, OPS));
        for (k = 0u; k < n; ++k) {
            const double e = (double)hyst_pi_step(&P, path[k]) + (double)res.offset - (double)ys[k];
            ss += e * e;
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e2 * TOL_OF_RANGE, (double)res.rms, sqrt(ss / (double)n));
    }
}

static void test_bad_input_is_refused(void)
{
    static const hyst_wide_t w_true[OPS] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    static const hyst_wide_t bad_r[3] = {0.0, 0.5, 0.5};
    const size_t n = excite();
    hyst_wide_t r[HYST_PI_FIT_MAX_OPERATORS + 1u], w[HYST_PI_FIT_MAX_OPERATORS + 1u];
    hyst_pi_fit_config_t cfg = {0};
    hyst_pi_fit_result_t res;
    hyst_pi_fit_t fit;
    const size_t len = sizeof work / sizeof work[0];
    size_t k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_thresholds(0, 1, OPS, r));
    simulate(n, r, w_true, OPS, 0.0, 0.0);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, fit_all(n, 0u, r, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, fit_all(n, HYST_PI_FIT_MAX_OPERATORS + 1u, r, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_pi_fit_thresholds(0, 1, 0u, r));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_pi_fit_thresholds(1, 1, OPS, r));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_pi_fit_thresholds(0, (hyst_wide_t)INFINITY, OPS, r));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_fit_thresholds(0, 1, OPS, NULL));
    /* too small a workspace */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE,
                          hyst_pi_fit_init(&fit, r, OPS, work, HYST_PI_FIT_WORK(OPS) - 1u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_fit_init(&fit, NULL, OPS, work, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_pi_fit_init(&fit, bad_r, 3u, work, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_pi_fit_init(&fit, bad_r + 1, 2u, work, len));
    /* non-finite samples: the array fit refuses, the streaming one skips them */
    ys[10] = (hyst_wide_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, fit_all(n, OPS, r, w, &res));
    cfg.operators = OPS;
    cfg.skip = 11u; /* ... unless skipped */
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_pi_fit_record(&cfg, xs, ys, n, work, len, r, w, &res));
    TEST_ASSERT_EQUAL_UINT(n - 11u, (unsigned)res.used);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_init(&fit, r, OPS, work, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_pi_fit_add(&fit, (hyst_wide_t)INFINITY, 0));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_pi_fit_add(&fit, 0.5, (hyst_wide_t)NAN));
    /* too few samples: N weights and the offset need N + 1 */
    for (k = 0u; k < OPS; ++k) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_add(&fit, xs[20u + k], ys[20u + k]));
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_SINGULAR, hyst_pi_fit_solve(&fit, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_add(&fit, xs[20u + OPS], ys[20u + OPS]));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_fit_solve(&fit, w, &res));
    /* a constant input: nothing to fit */
    cfg.skip = 0u;
    for (k = 0u; k < n; ++k) {
        xs[k] = 0.25;
        ys[k] = 1.0;
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, fit_all(n, OPS, r, w, &res));
    cfg.thresholds = r; /* also with thresholds given */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN,
                          hyst_pi_fit_record(&cfg, xs, ys, n, work, len, r, w, &res));
    cfg.skip = n; /* skip leaves nothing */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_pi_fit_record(&cfg, xs, ys, n, work, len, r, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_fit_record(NULL, xs, ys, n, work, len, r, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_fit_solve(NULL, w, &res));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_pi_fit_add(NULL, 0, 0));
}

int main(void)
{
    hyst_port_init();
    UNITY_BEGIN();
    RUN_TEST(test_known_weights_are_recovered_exactly);
    RUN_TEST(test_noisy_weights_are_close_and_residual_is_the_noise);
    RUN_TEST(test_negative_weight_gives_kkt_point);
    RUN_TEST(test_streaming_matches_record_and_pi_model);
    RUN_TEST(test_bad_input_is_refused);
    return UNITY_END();
}
