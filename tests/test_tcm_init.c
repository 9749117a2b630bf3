/* Configuration checks at init and bad samples at run time. */
#include "support.h"
#include "unity.h"

#include <math.h>

#define CAP 16
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_t S;

void setUp(void) {}
void tearDown(void) {}

static hyst_status_t init_with(const hyst_poly_t *f0)
{
    return hyst_init(&S, f0, xl, yl, xr, yr, CAP);
}

static void test_valid_curve_is_accepted(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&S));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.58517f, (float)hyst_output(&S));
}

static void test_null_pointers_are_refused(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(NULL, &paper_eq20, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(&S, NULL, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(&S, &paper_eq20, NULL, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(&S, &paper_eq20, xl, NULL, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(&S, &paper_eq20, xl, yl, NULL, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init(&S, &paper_eq20, xl, yl, xr, NULL, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_poly(NULL, &paper_eq20));
}

static void test_bad_domain_is_refused(void)
{
    hyst_poly_t f = paper_eq20;
    f.lo = f.hi;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_with(&f));
    f.lo = HYST_REAL_C(50.0);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_with(&f));
    f = paper_eq20;
    f.hi = (hyst_real_t)INFINITY;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_with(&f));
    f.hi = (hyst_real_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_with(&f));
}

static void test_degree_out_of_range_is_refused(void)
{
    hyst_poly_t f = paper_eq20;
    f.degree = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, init_with(&f));
    f.degree = HYST_MAX_DEGREE + 1u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, init_with(&f));
}

static void test_capacity_too_small_is_refused(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, 0u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, 2u));
}

static void test_non_finite_coefficient_is_refused(void)
{
    hyst_poly_t f = paper_eq20;
    f.coeffs[1] = (hyst_real_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, init_with(&f));
    f.coeffs[1] = (hyst_real_t)-INFINITY;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, init_with(&f));
}

static void test_curve_overflowing_the_real_type_is_refused(void)
{
#ifdef HYST_USE_DOUBLE
    const hyst_poly_t f = {9u, 0.0, 1e40, {1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0}};
#else
    const hyst_poly_t f = {9u, 0.0f, 1e5f, {1.0f, 0, 0, 0, 0, 0, 0, 0, 0, 0}};
#endif
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, init_with(&f));
}

static void test_decreasing_curve_is_refused(void)
{
    /* f0 = -x: decreasing everywhere */
    const hyst_poly_t dec = {1u, HYST_REAL_C(0.0), HYST_REAL_C(1.0), {HYST_REAL_C(-1.0), 0}};
    /* f0 = x^3 - x on [-1, 1]: rises, falls on (-0.577, 0.577), rises */
    const hyst_poly_t wiggle = {3u, HYST_REAL_C(-1.0), HYST_REAL_C(1.0),
                                {HYST_REAL_C(1.0), 0, HYST_REAL_C(-1.0), 0}};
    /* constant */
    const hyst_poly_t flat = {1u, HYST_REAL_C(0.0), HYST_REAL_C(1.0), {0, HYST_REAL_C(3.0)}};
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INCREASING, init_with(&dec));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INCREASING, init_with(&wiggle));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INCREASING, init_with(&flat));
}

static void test_slope_dip_is_located(void)
{
    /* f0 = x^3 - x on [-1, 1]: slope negative on |x| < 1/sqrt(3) */
    const hyst_wide_t c[4] = {1.0, 0.0, -1.0, 0.0};
    hyst_wide_t turn = 99.0;
    TEST_ASSERT_EQUAL_INT(0, hyst_poly_is_increasing(c, 3u, -1.0, 1.0, &turn));
    TEST_ASSERT_TRUE(turn > -0.5774 && turn < 0.5774);
    /* the paper's Eq. 20 turns far beyond its domain (slope 0 near x = 158.2) */
    {
        const hyst_wide_t e[4] = {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1};
        TEST_ASSERT_EQUAL_INT(1, hyst_poly_is_increasing(e, 3u, 0.0, 40.0, NULL));
        TEST_ASSERT_EQUAL_INT(0, hyst_poly_is_increasing(e, 3u, 0.0, 200.0, &turn));
        TEST_ASSERT_TRUE(turn > 157.0 && turn < 160.0);
    }
}

static void test_zero_slope_at_isolated_points_is_accepted(void)
{
    /* x^2 on [0, 1] (paper Example 1) and x^3 on [-1, 1]: slope 0 at one point */
    const hyst_poly_t sq = {2u, HYST_REAL_C(0.0), HYST_REAL_C(1.0), {HYST_REAL_C(1.0), 0, 0}};
    const hyst_poly_t cube = {3u, HYST_REAL_C(-1.0), HYST_REAL_C(1.0), {HYST_REAL_C(1.0), 0, 0, 0}};
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&sq));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&cube));
}

static void test_failed_init_leaves_instance_untouched(void)
{
    hyst_poly_t bad = paper_eq20;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    (void)hyst_step(&S, HYST_REAL_C(30.0));
    (void)hyst_step(&S, HYST_REAL_C(10.0));
    bad.degree = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, init_with(&bad));
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_FLOAT(10.0f, (float)hyst_input(&S));
}

static void test_nan_and_inf_samples_leave_state_untouched(void)
{
    const hyst_real_t bad[3] = {(hyst_real_t)NAN, (hyst_real_t)INFINITY,
                                (hyst_real_t)-INFINITY};
    hyst_t before;
    hyst_real_t y_last;
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    (void)hyst_step(&S, HYST_REAL_C(35.0));
    (void)hyst_step(&S, HYST_REAL_C(5.0));
    y_last = hyst_step(&S, HYST_REAL_C(20.0));
    hyst_clear_events(&S);
    for (i = 0; i < 3; ++i) {
        before = S;
        TEST_ASSERT_EQUAL_FLOAT((float)y_last, (float)hyst_step(&S, bad[i]));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_status(&S));
        TEST_ASSERT_EQUAL_UINT(before.n_ltp, S.n_ltp);
        TEST_ASSERT_EQUAL_UINT(before.n_rtp, S.n_rtp);
        TEST_ASSERT_EQUAL_MEMORY(&before.window, &S.window, sizeof S.window);
        TEST_ASSERT_EQUAL_MEMORY(&before.y_prev, &S.y_prev, sizeof S.y_prev);
    }
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_events(&S));
    /* a valid sample afterwards continues as if the bad ones never came */
    TEST_ASSERT_EQUAL_INT(HYST_OK, (hyst_step(&S, HYST_REAL_C(21.0)), hyst_status(&S)));
}

static void test_out_of_range_inputs_are_clamped_and_reported(void)
{
    hyst_real_t y;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    y = hyst_step(&S, HYST_REAL_C(55.0));
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&S));
    TEST_ASSERT_EQUAL_FLOAT(40.0f, (float)hyst_input(&S));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, (float)hyst_poly_eval(&paper_eq20, HYST_REAL_C(40.0)), (float)y);
    (void)hyst_step(&S, HYST_REAL_C(12.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&S));
    y = hyst_step(&S, HYST_REAL_C(-3.0));
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&S));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_input(&S));
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.58517f, (float)y); /* back at A0: f0(0) exactly */
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_CLAMPED, hyst_events(&S));
}

static void test_block_call_matches_steps_and_reports_worst(void)
{
    hyst_real_t x[6] = {HYST_REAL_C(10.0), HYST_REAL_C(30.0), HYST_REAL_C(45.0),
                        HYST_REAL_C(20.0), HYST_REAL_C(25.0), HYST_REAL_C(15.0)};
    hyst_real_t y[6];
    hyst_real_t expect[6];
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    for (i = 0; i < 6; ++i) {
        expect[i] = hyst_step(&S, x[i]);
    }
    hyst_reset(&S);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_process(&S, x, y, 6u));
    TEST_ASSERT_EQUAL_MEMORY(expect, y, sizeof y);
    x[1] = (hyst_real_t)NAN;
    hyst_reset(&S);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_process(&S, x, y, 6u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_process(&S, NULL, y, 6u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, NULL, NULL, 0u));
    /* in place */
    hyst_reset(&S);
    x[1] = HYST_REAL_C(30.0);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_process(&S, x, x, 6u));
    TEST_ASSERT_EQUAL_MEMORY(expect, x, sizeof x);
}

static void test_reset_returns_to_a0(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_with(&paper_eq20));
    (void)hyst_step(&S, HYST_REAL_C(30.0));
    (void)hyst_step(&S, HYST_REAL_C(10.0));
    (void)hyst_step(&S, HYST_REAL_C(50.0));
    hyst_reset(&S);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&S));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&S));
    TEST_ASSERT_EQUAL_FLOAT(0.0f, (float)hyst_input(&S));
    TEST_ASSERT_TRUE(hyst_rising(&S));
}

static void test_status_strings_are_distinct(void)
{
    int a, b;
    for (a = HYST_ERR_NOT_INVERTIBLE; a <= HYST_WARN_FULL; ++a) {
        for (b = a + 1; b <= HYST_WARN_FULL; ++b) {
            TEST_ASSERT_TRUE(hyst_status_str(a) != hyst_status_str(b));
        }
    }
    TEST_ASSERT_EQUAL_STRING("unknown status", hyst_status_str(42));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_valid_curve_is_accepted);
    RUN_TEST(test_null_pointers_are_refused);
    RUN_TEST(test_bad_domain_is_refused);
    RUN_TEST(test_degree_out_of_range_is_refused);
    RUN_TEST(test_capacity_too_small_is_refused);
    RUN_TEST(test_non_finite_coefficient_is_refused);
    RUN_TEST(test_curve_overflowing_the_real_type_is_refused);
    RUN_TEST(test_decreasing_curve_is_refused);
    RUN_TEST(test_slope_dip_is_located);
    RUN_TEST(test_zero_slope_at_isolated_points_is_accepted);
    RUN_TEST(test_failed_init_leaves_instance_untouched);
    RUN_TEST(test_nan_and_inf_samples_leave_state_untouched);
    RUN_TEST(test_out_of_range_inputs_are_clamped_and_reported);
    RUN_TEST(test_block_call_matches_steps_and_reports_worst);
    RUN_TEST(test_reset_returns_to_a0);
    RUN_TEST(test_status_strings_are_distinct);
    return UNITY_END();
}
