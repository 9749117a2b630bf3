/* SPDX-License-Identifier: MIT */
/* The spline f0's identification along every branch (ident.h,
 * hyst_spline_fit_*): records of a symmetric TCM written here (its own
 * turning-point stack, f0 a C2 cubic spline given by its B-spline weights)
 * driven by a decaying triangle and minor loops with wipe-outs give back
 * f0's knot values and slopes; a weight of 0 too; outputs that dip give an
 * increasing f0 all the same; the refusals, which write nothing. */
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define K 8u
#define WORK_LEN HYST_SPLINE_FIT_WORK(HYST_SPLINE_MAX_INTERVALS, 16u)
#define REF_CAP 64
#define TIGHT 1e-9 /* of the range: the record exact, the fit in double */

static hyst_wide_t work[WORK_LEN], work_copy[WORK_LEN];
static float table32[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
#if HYST_ENABLE_F64
static double table64[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
#endif

void setUp(void) {}
void tearDown(void) {}

/* f0 = y_lo + sum w_j I_j on K uniform intervals of [lo, hi], I_j the
 * integral from lo of the quadratic B-spline B((x - lo) / h - j + 2). */
typedef struct {
    double lo, hi, y_lo;
    double w[K + 2u];
} ref_spline_t;

/* The quadratic B-spline on [0, 3] and its integral from 0, as textbooks
 * write them. */
static double bspline(double t)
{
    if (t <= 0.0 || t >= 3.0) {
        return 0.0;
    }
    if (t < 1.0) {
        return t * t / 2.0;
    }
    if (t < 2.0) {
        return (-2.0 * t * t + 6.0 * t - 3.0) / 2.0;
    }
    return (3.0 - t) * (3.0 - t) / 2.0;
}

static double bspline_integral(double t)
{
    if (t <= 0.0) {
        return 0.0;
    }
    if (t < 1.0) {
        return t * t * t / 6.0;
    }
    if (t < 2.0) {
        return -t * t * t / 3.0 + 1.5 * t * t - 1.5 * t + 0.5;
    }
    if (t < 3.0) {
        return 1.0 - (3.0 - t) * (3.0 - t) * (3.0 - t) / 6.0;
    }
    return 1.0;
}

/* g(d) = f0(lo + d) - f0(lo), and f0'(x). */
static double ref_g(const ref_spline_t *s, double d)
{
    const double u = d * (double)K / (s->hi - s->lo);
    double sum = 0.0;
    unsigned j;
    for (j = 0u; j < K + 2u; ++j) {
        sum += s->w[j] * (bspline_integral(u - (double)j + 2.0) - bspline_integral(2.0 - (double)j));
    }
    return sum;
}

static double ref_slope(const ref_spline_t *s, double x)
{
    const double scale = (double)K / (s->hi - s->lo), u = (x - s->lo) * scale;
    double sum = 0.0;
    unsigned j;
    for (j = 0u; j < K + 2u; ++j) {
        sum += s->w[j] * bspline(u - (double)j + 2.0);
    }
    return sum * scale;
}

static double ref_f0(const ref_spline_t *s, double x) { return s->y_lo + ref_g(s, x - s->lo); }

/* The symmetric TCM from reset: turning points (x, y), A0 = (lo, y_lo) at
 * the bottom, lower ones at even places; the branch from the top one
 * rises as y + g(x' - x) or falls as y - g(x - x'). */
typedef struct {
    const ref_spline_t *f0;
    const hyst_spline_t *fitted; /* if set, g from it: f0(lo + d) - f0(lo) */
    double x[REF_CAP], y[REF_CAP];
    int n, deepest;
    double x_prev, y_prev;
} ref_tcm_t;

static void ref_reset(ref_tcm_t *m, const ref_spline_t *f0)
{
    memset(m, 0, sizeof *m);
    m->f0 = f0;
    m->x[0] = m->x_prev = f0->lo;
    m->y[0] = m->y_prev = f0->y_lo;
    m->n = m->deepest = 1;
}

static double model_g(const ref_tcm_t *m, double d)
{
    const hyst_spline_t *s = m->fitted;
    if (s == NULL) {
        return ref_g(m->f0, d);
    }
    return (double)hyst_spline_eval(s, (hyst_wide_t)(m->f0->lo + d)) - (double)hyst_spline_eval(s, s->lo);
}

static double ref_step(ref_tcm_t *m, double x)
{
    int up, top;
    if (x == m->x_prev) {
        return m->y_prev;
    }
    up = x > m->x_prev;
    if (up != ((m->n - 1) % 2 == 0)) { /* a reversal: the last input turns */
        TEST_ASSERT_TRUE(m->n < REF_CAP);
        m->x[m->n] = m->x_prev;
        m->y[m->n] = m->y_prev;
        ++m->n;
    }
    while (m->n >= 3 && (up ? x >= m->x[m->n - 2] : x <= m->x[m->n - 2])) {
        m->n -= 2; /* wipe-out: the loop closed */
    }
    if (!up && x <= m->x[0]) {
        m->n = 1;
    }
    m->deepest = m->n > m->deepest ? m->n : m->deepest;
    top = m->n - 1;
    m->y_prev = up ? m->y[top] + model_g(m, x - m->x[top]) : m->y[top] - model_g(m, m->x[top] - x);
    m->x_prev = x;
    return m->y_prev;
}

/* Turning levels, fractions of the domain from lo: a decaying triangle,
 * then minor loops inside it, nested and wiped out. */
static const double levels[] = {1.0,  0.05, 0.95, 0.1,  0.9, 0.2,  0.8, 0.3,
                                0.7,  0.4,  0.6,  0.35, 0.55, 0.45, 0.5, 0.42,
                                0.75, 0.25, 0.4,  0.3,  0.65, 0.15, 1.0, 0.0};

/* Fits the plant's record through `levels` from lo (steps of 1/150 of the
 * domain); returns the deepest stack the plant held. */
static int fit_record(hyst_spline_fit_t *fit, const ref_spline_t *f0)
{
    static ref_tcm_t plant;
    const double span = f0->hi - f0->lo;
    double x = f0->lo;
    size_t i;
    ref_reset(&plant, f0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(fit, K, (hyst_wide_t)f0->lo,
                                                        (hyst_wide_t)f0->hi, work, WORK_LEN));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_spline_fit_add(fit, (hyst_wide_t)x, (hyst_wide_t)ref_step(&plant, x)));
    for (i = 0u; i < sizeof levels / sizeof levels[0]; ++i) {
        const double to = f0->lo + span * levels[i], from = x;
        const int steps = (int)ceil(fabs(to - from) / span * 150.0);
        int s;
        for (s = 1; s <= steps; ++s) {
            x = s == steps ? to : from + (to - from) * (double)s / (double)steps;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(fit, (hyst_wide_t)x,
                                                               (hyst_wide_t)ref_step(&plant, x)));
        }
    }
    return plant.deepest;
}

/* The fit of f0's record gives f0: values and slopes at the knots, the
 * Hermite pieces between them (the cubic spline itself), an RMS of
 * rounding, a spline the curve takes. */
static void check_recovers(const ref_spline_t *f0)
{
    hyst_spline_fit_t fit;
    hyst_spline_t got;
    hyst_curve_t curve;
    hyst_wide_t rms = -1;
    const double span = f0->hi - f0->lo, range = ref_g(f0, span), scale = (double)K / span;
    double worst_value = 0.0, worst_slope = 0.0, worst_between = 0.0;
    unsigned k;
    int i;
    TEST_ASSERT_TRUE(fit_record(&fit, f0) >= 9); /* the minor loops nested */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_solve(&fit, &got, &rms));
    TEST_ASSERT_EQUAL_UINT(K, got.intervals);
    TEST_ASSERT_TRUE(got.lo == f0->lo && got.hi == f0->hi);
    for (k = 0u; k <= K; ++k) {
        const double x = f0->lo + span * (double)k / (double)K;
        const double dv = fabs((double)got.value[k] - ref_f0(f0, x)) / range;
        const double ds = fabs((double)got.slope[k] - ref_slope(f0, x)) / (range * scale);
        worst_value = dv > worst_value ? dv : worst_value;
        worst_slope = ds > worst_slope ? ds : worst_slope;
        TEST_ASSERT_TRUE(got.slope[k] >= 0);
    }
    for (i = 0; i <= 400; ++i) {
        const double x = f0->lo + span * (double)i / 400.0;
        const double d = fabs((double)hyst_spline_eval(&got, (hyst_wide_t)x) - ref_f0(f0, x)) / range;
        worst_between = d > worst_between ? d : worst_between;
    }
    TEST_PRINTF("spline fit: worst value %g, slope %g, between knots %g of the range; rms %g of it",
                worst_value, worst_slope, worst_between, (double)rms / range);
    if (SETUP_IN_FLOAT) { /* the fit in float: 2.6e-5 (slope) measured; its rms is
                             * resolved only above about sqrt(eps) of the outputs (ident.h) */
        TEST_ASSERT_TRUE(worst_value <= 1e-4 && worst_slope <= 1e-4 && worst_between <= 1e-4);
        TEST_ASSERT_TRUE(rms >= 0 && (double)rms <= 1e-3 * range);
    } else {
        TEST_ASSERT_TRUE(worst_value <= TIGHT);
        TEST_ASSERT_TRUE(worst_slope <= TIGHT);
        TEST_ASSERT_TRUE(worst_between <= TIGHT);
        TEST_ASSERT_TRUE(rms >= 0 && (double)rms <= 1e-6 * range); /* the root of the normal equations' rounding */
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_from_spline(&curve, &got, table32,
                                                              HYST_SPLINE_TABLE_LEN(K)));
#if HYST_ENABLE_F64
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f64_curve_from_spline(&curve, &got, table64,
                                                              HYST_SPLINE_TABLE_LEN(K)));
#endif
}

static void test_exact_record_with_minor_loops_gives_f0_back(void)
{
    static const ref_spline_t f0 = {-1.5, 2.5, 3.25, {0.3, 1.2, 0.5, 2.0, 0.1, 0.7, 1.5, 0.4, 0.9, 0.2}};
    check_recovers(&f0);
}

/* Weights of 0 (the constraint's boundary): at lo, inside, two in a row
 * (slope 0 at knot 5, a flat point the curve must take) and at hi. */
static void test_weights_of_zero_come_back(void)
{
    static const ref_spline_t f0 = {0.0, 40.0, -7.5, {0.0, 1.2, 0.5, 0.0, 0.8, 0.0, 0.0, 1.4, 0.9, 0.0}};
    check_recovers(&f0);
}

/* Outputs that fall while the input rises (no increasing f0 fits them):
 * f0 fitted increasing all the same, every slope >= 0, between the knots
 * too, and the curve takes it. */
static void test_outputs_that_dip_give_an_increasing_f0(void)
{
    const double lo = 0.0, hi = 10.0, pi = 3.14159265358979323846;
    hyst_spline_fit_t fit;
    hyst_spline_t got;
    hyst_curve_t curve;
    hyst_wide_t rms = -1;
    double prev = -HUGE_VAL, fall = 0.0, least = HUGE_VAL;
    unsigned k;
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, (hyst_wide_t)lo, (hyst_wide_t)hi, work,
                                                        WORK_LEN));
    for (i = 0; i <= 400; ++i) { /* y' = 1 + 1.9 cos(6 pi u): below 0 three times */
        const double u = (double)i / 400.0;
        const double y = u + 0.1 * sin(6.0 * pi * u), y_next = (u + 0.0025) + 0.1 * sin(6.0 * pi * (u + 0.0025));
        fall = y_next < y && y - y_next > fall ? y - y_next : fall;
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_spline_fit_add(&fit, (hyst_wide_t)(lo + (hi - lo) * u), (hyst_wide_t)y));
    }
    TEST_ASSERT_TRUE(fall > 1e-3); /* the record does dip */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_solve(&fit, &got, &rms));
    for (k = 0u; k <= K; ++k) {
        TEST_ASSERT_TRUE(got.slope[k] >= 0);
        least = (double)got.slope[k] < least ? (double)got.slope[k] : least;
    }
    TEST_PRINTF("dipping outputs: least slope %g, rms %g", least, (double)rms);
    TEST_ASSERT_TRUE(least < 1e-6); /* on the constraint: flat where the outputs dip */
    for (i = 0; i <= 1000; ++i) {
        const double y = (double)hyst_spline_eval(&got, (hyst_wide_t)(lo + (hi - lo) * (double)i / 1000.0));
        TEST_ASSERT_TRUE(y >= prev - 1e-12);
        prev = y;
    }
    TEST_ASSERT_TRUE(rms > 0 && rms < 0.1);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_from_spline(&curve, &got, table32,
                                                              HYST_SPLINE_TABLE_LEN(K)));
}

/* The RMS a spline fit returns is its model's residual over the samples it
 * fitted: a record of 100 000 samples (a random walk: minor loops, wipe-outs),
 * noise 1e-6 of the range, outputs offset by up to 1e6, the returned f0 run
 * as the TCM from rest at lo over the same inputs. Within 1e-3 of that
 * residual, plus the outputs' rounding in double (4 eps of the largest).
 * Summed a sample at a time, the normal equations' rounding read the first
 * 12 % low. */
#define RMS_SAMPLES 100000L
static double rms_x[RMS_SAMPLES], rms_y[RMS_SAMPLES];

static void test_fit_rms_is_the_models_residual(void)
{
    static const double offsets[] = {0.0, 1e4, 1e6};
    static ref_spline_t f0 = {-1.5, 2.5, 3.25, {0.3, 1.2, 0.5, 2.0, 0.1, 0.7, 1.5, 0.4, 0.9, 0.2}};
    static ref_tcm_t plant;
    const double span = f0.hi - f0.lo, range = ref_g(&f0, span);
    double worst = 0.0;
    unsigned trial;
    rng_t rng;
    rng_seed(&rng, 1618u);
    for (trial = 0u; trial < 3u; ++trial) {
        hyst_spline_fit_t fit;
        hyst_spline_t got;
        hyst_wide_t rms = -1;
        double v = f0.lo + 0.5 * span, sum_sq = 0.0, residual, floor_abs;
        long k;
        f0.y_lo = 3.25 + offsets[trial];
        ref_reset(&plant, &f0);
        for (k = 0; k < RMS_SAMPLES; ++k) {
            v = rng_below(&rng, 10u) == 0u ? rng_range(&rng, f0.lo, f0.hi) : v + span * rng_range(&rng, -0.05, 0.05);
            v = v < f0.lo ? f0.lo : (v > f0.hi ? f0.hi : v);
            rms_x[k] = v;
            rms_y[k] = ref_step(&plant, v) + 1e-6 * range * (rng_unit(&rng) - 0.5);
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, (hyst_wide_t)f0.lo,
                                                            (hyst_wide_t)f0.hi, work, WORK_LEN));
        for (k = 0; k < RMS_SAMPLES; ++k) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, (hyst_wide_t)rms_x[k],
                                                               (hyst_wide_t)rms_y[k]));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_solve(&fit, &got, &rms));
        ref_reset(&plant, &f0);
        plant.fitted = &got; /* the returned f0 from rest at lo, as the fit */
        plant.y[0] = plant.y_prev = (double)got.value[0];
        for (k = 0; k < RMS_SAMPLES; ++k) {
            const double d = ref_step(&plant, rms_x[k]) - rms_y[k];
            sum_sq += d * d;
        }
        residual = sqrt(sum_sq / (double)RMS_SAMPLES);
        /* the outputs' rounding in hyst_wide_t (float with HYST_NO_DOUBLE) */
        floor_abs = 4.0 * (SETUP_IN_FLOAT ? FLT_EPSILON : DBL_EPSILON) * (fabs(f0.y_lo) + range);
        TEST_PRINTF("spline fit, outputs offset %g: rms %g, the model's residual %g (%g of the range)",
                    offsets[trial], (double)rms, residual, residual / range);
        TEST_ASSERT_TRUE(fabs((double)rms - residual) <= 1e-3 * residual + floor_abs);
        worst = fabs((double)rms / residual - 1.0) > worst ? fabs((double)rms / residual - 1.0) : worst;
    }
    TEST_PRINTF("spline fit: returned rms within %g of the model's residual", worst);
}

static void test_init_refusals_write_nothing(void)
{
    hyst_spline_fit_t fit, copy;
    const size_t need = HYST_SPLINE_FIT_WORK(K, 2u);
    memset(&fit, 0x5a, sizeof fit);
    memcpy(&copy, &fit, sizeof fit);
    UNCHANGED(&copy, &fit, HYST_ERR_NULL, hyst_spline_fit_init(NULL, K, 0.0, 1.0, work, need));
    UNCHANGED(&copy, &fit, HYST_ERR_NULL, hyst_spline_fit_init(&fit, K, 0.0, 1.0, NULL, need));
    UNCHANGED(&copy, &fit, HYST_ERR_DEGREE, hyst_spline_fit_init(&fit, 0u, 0.0, 1.0, work, WORK_LEN));
    UNCHANGED(&copy, &fit, HYST_ERR_DEGREE,
              hyst_spline_fit_init(&fit, HYST_SPLINE_MAX_INTERVALS + 1u, 0.0, 1.0, work, WORK_LEN));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN, hyst_spline_fit_init(&fit, K, 1.0, 1.0, work, need));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN, hyst_spline_fit_init(&fit, K, 2.0, 1.0, work, need));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN, hyst_spline_fit_init(&fit, K, (hyst_wide_t)NAN, 1.0, work, need));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN,
              hyst_spline_fit_init(&fit, K, 0.0, (hyst_wide_t)INFINITY, work, need));
    UNCHANGED(&copy, &fit, HYST_ERR_NOSPACE, hyst_spline_fit_init(&fit, K, 0.0, 1.0, work, need - 1u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, 0.0, 1.0, work, need));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, 1u, 0.0, 1.0, work, WORK_LEN));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, HYST_SPLINE_MAX_INTERVALS, 0.0, 1.0, work,
                                                        HYST_SPLINE_FIT_WORK(HYST_SPLINE_MAX_INTERVALS, 2u)));
}

static void test_add_refusals(void)
{
    hyst_spline_fit_t fit, copy, fresh;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_spline_fit_add(NULL, 0.5, 1.0));
    /* room for A0 and one more turning point: the third is refused, nothing changed */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, 0.0, 1.0, work, HYST_SPLINE_FIT_WORK(K, 2u)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, 0.5, 1.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, HYST_WIDE_C(0.2), 0.5));
    memcpy(&copy, &fit, sizeof fit);
    memcpy(work_copy, work, sizeof work);
    UNCHANGED(&copy, &fit, HYST_ERR_NOSPACE, hyst_spline_fit_add(&fit, HYST_WIDE_C(0.4), HYST_WIDE_C(0.8)));
    UNCHANGED(&copy, &fit, HYST_ERR_NONFINITE, hyst_spline_fit_add(&fit, (hyst_wide_t)NAN, HYST_WIDE_C(0.8)));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN, hyst_spline_fit_add(&fit, 1.5, HYST_WIDE_C(0.8)));
    UNCHANGED(&copy, &fit, HYST_ERR_DOMAIN, hyst_spline_fit_add(&fit, HYST_WIDE_C(-0.1), HYST_WIDE_C(0.8)));
    TEST_ASSERT_EQUAL_MEMORY(work_copy, work, sizeof work);
    /* a NaN output: its row left out, the input moved all the same */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, 0.0, 1.0, work, WORK_LEN));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_spline_fit_add(&fit, HYST_WIDE_C(0.7), (hyst_wide_t)NAN));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, HYST_WIDE_C(0.7), 2.0));
    memcpy(work_copy, work, sizeof work);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fresh, K, 0.0, 1.0, work, WORK_LEN));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fresh, HYST_WIDE_C(0.7), 2.0));
    TEST_ASSERT_EQUAL_MEMORY(&fresh, &fit, sizeof fit);
    TEST_ASSERT_EQUAL_MEMORY(work_copy, work, sizeof work);
}

static void test_solve_refusals_write_nothing(void)
{
    static const hyst_wide_t x[6] = {0.5, 1.5, 2.5, 1.0, 2.0, 0.5};
    /* -1.4e38 in float (HYST_NO_DOUBLE): its square overflows there */
    static const hyst_wide_t y[6] = {1.0, 2.0, 4.0, (hyst_wide_t)(SETUP_IN_FLOAT ? -1.4e38 : -1.4e308),
                                     3.0, 1.5};
    hyst_spline_fit_t fit;
    hyst_spline_t got, before;
    hyst_wide_t rms = -1;
    unsigned k;
    int i;
    memset(&got, 0x5a, sizeof got);
    memcpy(&before, &got, sizeof got);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, 0.0, 3.0, work, WORK_LEN));
    UNCHANGED(&before, &got, HYST_ERR_NULL, hyst_spline_fit_solve(NULL, &got, &rms));
    UNCHANGED(&before, &got, HYST_ERR_NULL, hyst_spline_fit_solve(&fit, NULL, &rms));
    UNCHANGED(&before, &got, HYST_ERR_NULL, hyst_spline_fit_solve(&fit, &got, NULL));
    UNCHANGED(&before, &got, HYST_ERR_SINGULAR, hyst_spline_fit_solve(&fit, &got, &rms));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, x[0], y[0]));
    UNCHANGED(&before, &got, HYST_ERR_SINGULAR, hyst_spline_fit_solve(&fit, &got, &rms));
    /* outputs so large that the normal equations overflow */
    for (i = 1; i < 6; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, x[i], y[i]));
    }
    UNCHANGED(&before, &got, HYST_ERR_COEFF, hyst_spline_fit_solve(&fit, &got, &rms));
    TEST_ASSERT_TRUE(rms == -1);
    /* outputs that never rise: f0 flat, written all the same */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_init(&fit, K, 0.0, 3.0, work, WORK_LEN));
    for (i = 0; i < 6; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_spline_fit_add(&fit, x[i], 2.5));
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_spline_fit_solve(&fit, &got, &rms));
    TEST_ASSERT_EQUAL_UINT(K, got.intervals);
    for (k = 0u; k <= K; ++k) {
        TEST_ASSERT_TRUE(fabs((double)got.value[k] - 2.5) <= 1e-12 && got.slope[k] == 0);
    }
    TEST_ASSERT_TRUE(rms >= 0 && rms <= 1e-12);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_record_with_minor_loops_gives_f0_back);
    RUN_TEST(test_weights_of_zero_come_back);
    RUN_TEST(test_outputs_that_dip_give_an_increasing_f0);
    RUN_TEST(test_fit_rms_is_the_models_residual);
    RUN_TEST(test_init_refusals_write_nothing);
    RUN_TEST(test_add_refusals);
    RUN_TEST(test_solve_refusals_write_nothing);
    return UNITY_END();
}
