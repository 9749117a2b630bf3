/* SPDX-License-Identifier: MIT */
/* The asymmetric kind on a grid (curve.h, hyst_everett_grid_t): E of a
 * density constant on the cells of a grid. Checked against a plain double
 * reference (tests/support/ref_egrid.c: E cell by cell, Madelung's rules on
 * a list of turning points) for random grids and random drives with minor
 * loops and wipe-outs; the refusals; monotone branches; minor loops that
 * close bit for bit; block call, snapshots, bounded memory, the deadband's
 * bound and the code variant as for the polynomial asymmetric kind. */
#include "ref_egrid.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 4000L
#define TABLE HYST_EVERETT_GRID_TABLE_LEN(HYST_EVERETT_GRID_MAX_INTERVALS)

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xs[SAMPLES], ys[SAMPLES], ys2[SAMPLES];
static hyst_real_t table[TABLE], table2[TABLE];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t curve, curve2;
static hyst_t S, T;
static rng_t rng;
static ref_everett_t ref; /* 16 KB: off the stack */
static hyst_everett_t dom;

#ifdef HYST_USE_DOUBLE
#define AGREE 1e-9 /* of the output range */
#else
#define AGREE 2e-5
#endif

void setUp(void) { rng_seed(&rng, 2718u); }
void tearDown(void) {}

static hyst_status_t init_g(hyst_t *I, hyst_curve_t *c, const hyst_everett_grid_t *g,
                            hyst_real_t *tab, hyst_real_t *a, hyst_real_t *b, hyst_real_t *d,
                            hyst_real_t *f, size_t cap)
{
    const hyst_status_t st = hyst_curve_from_everett_grid(c, g, tab, TABLE);
    return st != HYST_OK ? st : hyst_init_curve(I, c, a, b, d, f, cap);
}

static double range_of(const hyst_everett_grid_t *g)
{
    return ref_egrid_e(g, g->knots[0], g->knots[0]) +
           ref_egrid_e(g, g->knots[g->intervals], g->knots[0]);
}

static void walk(const hyst_everett_grid_t *g, hyst_real_t *x, long n)
{
    const double lo = g->knots[0], hi = g->knots[g->intervals];
    double v = 0.5 * (lo + hi);
    long k;
    for (k = 0; k < n; ++k) {
        x[k] = (hyst_real_t)ref_everett_walk(&rng, &v, lo, hi);
        if (rng_below(&rng, 50u) == 0u) { /* now and then exactly on a knot */
            x[k] = (hyst_real_t)g->knots[rng_below(&rng, g->intervals + 1u)];
            v = (double)x[k];
        }
    }
}

static void test_random_grids_agree_with_the_reference(void)
{
    int trial;
    double worst = 0.0;
    for (trial = 0; trial < 60; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, HYST_EVERETT_GRID_MAX_INTERVALS);
        const double range = range_of(&g);
        double x_prev = g.knots[0], y_prev = g.y_lo;
        int up = 1;
        long k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
        ref_egrid_init(&ref, &dom, &g);
        walk(&g, xs, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double d = fabs(y - ref_everett_step(&ref, (double)xs[k])) / range;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&S));
            worst = d > worst ? d : worst;
            /* monotone: the output never moves against the input */
            if ((double)xs[k] != x_prev) {
                up = (double)xs[k] > x_prev;
            }
            TEST_ASSERT_TRUE(up ? y >= y_prev : y <= y_prev);
            x_prev = (double)xs[k];
            y_prev = y;
        }
        TEST_ASSERT_EQUAL_UINT((unsigned)(ref.n - 1), (unsigned)hyst_tp_count(&S));
    }
    TEST_PRINTF("random grids: worst |y - y_ref| %g of the range", worst);
    TEST_ASSERT_TRUE(worst <= AGREE);
}

/* One cell: E(a, b) = W ((a - b) / (hi - lo))^2, exactly at these inputs. */
static void test_one_cell_is_a_parabola(void)
{
    hyst_everett_grid_t g;
    memset(&g, 0, sizeof g);
    g.intervals = 1u;
    g.knots[0] = 0.0;
    g.knots[1] = 2.0;
    g.y_lo = 1.0;
    g.weight[0] = 8.0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
    TEST_ASSERT_TRUE(hyst_step(&S, (hyst_real_t)1.0) == (hyst_real_t)3.0);   /* 1 + 8 / 4 */
    TEST_ASSERT_TRUE(hyst_step(&S, (hyst_real_t)2.0) == (hyst_real_t)9.0);   /* 1 + 8 */
    TEST_ASSERT_TRUE(hyst_step(&S, (hyst_real_t)1.5) == (hyst_real_t)8.5);   /* 9 - 8 / 16 */
    TEST_ASSERT_TRUE(hyst_step(&S, (hyst_real_t)1.75) == (hyst_real_t)8.625); /* 8.5 + 8 / 64 */
    TEST_ASSERT_TRUE(hyst_curve_eval(&curve, (hyst_real_t)0.5) == (hyst_real_t)1.5);
}

/* Rules 2 and 3: an excursion inside the current branch returns to the
 * same output, and continues like a twin that stayed, bit for bit. */
static void test_minor_loops_close_bit_for_bit(void)
{
    int trial;
    for (trial = 0; trial < 100; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, 8u);
        const double lo = g.knots[0], span = g.knots[g.intervals] - lo;
        const hyst_real_t xa = (hyst_real_t)(lo + span * rng_range(&rng, 0.3, 0.6));
        const hyst_real_t xb = (hyst_real_t)(lo + span * rng_range(&rng, 0.05, 0.29));
        const hyst_real_t xc = (hyst_real_t)(lo + span * rng_range(&rng, 0.61, 0.95));
        hyst_real_t ya, y1, y2;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
        (void)hyst_step(&S, (hyst_real_t)(lo + span * 0.02));
        (void)hyst_step(&T, (hyst_real_t)(lo + span * 0.02));
        ya = hyst_step(&S, xa);
        (void)hyst_step(&T, xa);
        (void)hyst_step(&S, xb); /* down and back up to xa: the loop closes */
        TEST_ASSERT_TRUE(hyst_step(&S, xa) == ya);
        y1 = hyst_step(&S, xc);
        y2 = hyst_step(&T, xc);
        TEST_ASSERT_EQUAL_MEMORY(&y2, &y1, sizeof y1);
    }
}

static void test_bad_grids_are_refused(void)
{
    hyst_everett_grid_t g = ref_egrid_random(&rng, 6u), bad;
    memset(&curve, 0x5a, sizeof curve);
    curve2 = curve;
    memset(table, 0, sizeof table);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_everett_grid(NULL, &g, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_everett_grid(&curve, NULL, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_from_everett_grid(&curve, &g, NULL, TABLE));
    bad = g;
    bad.intervals = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad.intervals = HYST_EVERETT_GRID_MAX_INTERVALS + 1u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad = g;
    bad.knots[1] = bad.knots[0];
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad = g;
    bad.knots[g.intervals] = NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad = g;
    /* equal as floats */
    bad.knots[1] = (hyst_wide_t)((double)bad.knots[0] + fabs((double)bad.knots[0]) * 1e-12 + 1e-300);
#ifndef HYST_USE_DOUBLE
    TEST_ASSERT_EQUAL_INT(HYST_ERR_BREAKPOINTS, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
#endif
    bad = g;
    bad.weight[0] = INFINITY;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad = g;
    bad.y_lo = NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    bad = g;
    bad.weight[HYST_EVERETT_GRID_CELLS(g.intervals) - 1u] = HYST_WIDE_C(-1e-9);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    memset(bad.weight, 0, sizeof bad.weight);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_MONOTONE, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE,
                          hyst_curve_from_everett_grid(&curve, &g, table,
                                                       HYST_EVERETT_GRID_TABLE_LEN(g.intervals) - 1u));
    if (!SETUP_IN_FLOAT) { /* with HYST_NO_DOUBLE the grid holds floats: no such density */
        bad = g; /* finite in double, not in float: a density of 1e300 */
        bad.weight[0] = (hyst_wide_t)1e300;
#ifndef HYST_USE_DOUBLE
        TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_curve_from_everett_grid(&curve, &bad, table, TABLE));
#endif
    }
    /* nothing written by a refusal */
    TEST_ASSERT_EQUAL_MEMORY(&curve2, &curve, sizeof curve);
    memset(table2, 0, sizeof table2);
    TEST_ASSERT_EQUAL_MEMORY(table2, table, sizeof table);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett_grid(&curve, &g, table,
                                                                HYST_EVERETT_GRID_TABLE_LEN(g.intervals)));
    /* the inits take it; the functions that take any prepared curve (the
     * compensators, their tables) have nothing for it yet */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &curve, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_check(&curve));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse(&curve2, &curve));
    curve.u.everett_grid.intervals = HYST_EVERETT_GRID_MAX_INTERVALS + 1u; /* not as prepared */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_curve(&S, &curve, xl, yl, xr, yr, CAP));
}

/* The curve's own evaluation: the branch rising from lo. */
static void test_curve_eval_is_the_major_rising_branch(void)
{
    int trial;
    for (trial = 0; trial < 20; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, HYST_EVERETT_GRID_MAX_INTERVALS);
        const double lo = g.knots[0], hi = g.knots[g.intervals], range = range_of(&g);
        int i;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett_grid(&curve, &g, table, TABLE));
        for (i = 0; i <= 100; ++i) {
            const hyst_real_t x = (hyst_real_t)(lo + (hi - lo) * i / 100.0);
            const double want = g.y_lo + ref_egrid_e(&g, (double)x, lo);
            TEST_ASSERT_TRUE(fabs((double)hyst_curve_eval(&curve, x) - want) <= AGREE * range);
        }
        TEST_ASSERT_TRUE(fabs((double)hyst_curve_eval(&curve, (hyst_real_t)hi) - (g.y_lo + range)) <= AGREE * range);
    }
}

/* A random grid of 2 to 8 intervals (an interior knot to move). */
static hyst_everett_grid_t random_grid_of_two_or_more(void)
{
    hyst_everett_grid_t g;
    do {
        g = ref_egrid_random(&rng, 8u);
    } while (g.intervals < 2u);
    return g;
}

static void test_block_and_snapshots(void)
{
    hyst_everett_grid_t g = random_grid_of_two_or_more();
    size_t len = 0u;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
    walk(&g, xs, SAMPLES);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs, ys2, (size_t)SAMPLES));
    for (k = 0; k < SAMPLES; ++k) {
        ys[k] = hyst_step(&S, xs[k]);
    }
    TEST_ASSERT_EQUAL_MEMORY(ys, ys2, sizeof ys);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
    hyst_reset(&T);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
    walk(&g, xs, 500L);
    for (k = 0; k < 500; ++k) {
        const hyst_real_t y1 = hyst_step(&S, xs[k]), y2 = hyst_step(&T, xs[k]);
        TEST_ASSERT_EQUAL_MEMORY(&y1, &y2, sizeof y1);
    }
    { /* another grid of the same domain and range: the snapshot is not its */
        const unsigned last = HYST_EVERETT_GRID_CELLS(g.intervals) - 1u;
        unsigned i;
        for (i = 0u; i <= last; ++i) { /* whole weights: the sums exact */
            g.weight[i] = (hyst_wide_t)(i % 3u + 1u);
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
        g.weight[0] = 2.0;
        g.weight[1] = 1.0;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&T, &curve2, &g, table2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&T, snap, len));
}

/* A snapshot's curve identity is the grid's table, not where it lies: the
 * same grid built into another table takes the snapshot; the grid with an
 * interior knot moved (the same domain and masses) refuses it. */
static void test_snapshot_identity_is_the_table(void)
{
    hyst_everett_grid_t g = random_grid_of_two_or_more();
    size_t len = 0u;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
    walk(&g, xs, 500L);
    for (k = 0; k < 500; ++k) { /* turning points to restore */
        (void)hyst_step(&S, xs[k]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&S, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&T, &curve2, &g, table2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&T, snap, len));
    g.knots[1] = HYST_WIDE_C(0.5) * (g.knots[0] + g.knots[1]);
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&T, &curve2, &g, table2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&T, snap, len));
}

/* Bounded memory: a small capacity merges loops and states a bound that
 * holds against the unbounded reference. */
static void test_bounded_memory_keeps_its_bound(void)
{
    int trial, merged = 0;
    double worst_ratio = 0.0;
    for (trial = 0; trial < 30; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, 8u);
        long k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, 3u));
        ref_egrid_init(&ref, &dom, &g);
        walk(&g, xs, 2000L);
        for (k = 0; k < 2000; ++k) {
            const double y = (double)hyst_step(&S, xs[k]);
            const double err = fabs(y - ref_everett_step(&ref, (double)xs[k]));
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

/* The deadband's stated bound (the window's densest cell times a quarter
 * of its width squared) holds against the full model. */
static void test_deadband_bound_holds(void)
{
    int trial;
    double worst = 0.0, worst_ratio = 0.0;
    for (trial = 0; trial < 200; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, 8u);
        const double lo = g.knots[0], span = g.knots[g.intervals] - lo, range = range_of(&g);
        const int rising = trial % 2 == 0;
        const double tp = lo + span * (rising ? 0.35 : 0.65);
        long k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &curve, xl2, yl2, xr2, yr2, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&S, (hyst_real_t)(0.3 * span)));
        for (k = 0; k < 80; ++k) {
            double x, err, bound;
            if (k == 0) {
                x = lo + span * (rising ? 0.8 : 0.2);
            } else if (k == 1) {
                x = tp;
            } else if (k == 79) {
                x = rising ? lo + span : lo;
            } else {
                x = tp + (rising ? 1.0 : -1.0) * 0.29 * span * rng_unit(&rng);
            }
            err = fabs((double)hyst_step(&S, (hyst_real_t)x) - (double)hyst_step(&T, (hyst_real_t)x));
            bound = (double)hyst_error_bound(&S);
            if (err > bound + AGREE * range) {
                TEST_PRINTF("grid %d, sample %ld: |y - y_full| = %g > bound %g", trial, k, err, bound);
                TEST_FAIL_MESSAGE("deadband error beyond the stated bound");
            }
            worst = err / range > worst ? err / range : worst;
            worst_ratio = bound > 0.0 && err / bound > worst_ratio ? err / bound : worst_ratio;
        }
        TEST_ASSERT_TRUE(hyst_error_bound(&S) == 0);
    }
    TEST_PRINTF("deadband: worst error %g of the range, at most %g of the bound", worst, worst_ratio);
    TEST_ASSERT_TRUE(worst > 100.0 * AGREE);
}

/* Identification: a random grid's record (minor loops, wipe-outs), fitted
 * on its own knots, gives a model whose outputs on a new drive are the
 * grid's within rounding, every mass >= 0; on a noisy record the masses
 * stay >= 0 and the model within a few noise levels; the knots from the
 * record's output steps are strictly increasing on [lo, hi]. */
#define FIT_SAMPLES 3000
static hyst_wide_t fit_work[HYST_EVERETT_GRID_FIT_WORK(6u, 400u)];
static hyst_wide_t fx[FIT_SAMPLES], fy[FIT_SAMPLES];

static void test_identification_recovers_the_grid(void)
{
    int trial;
    double worst = 0.0, worst_noisy = 0.0;
    for (trial = 0; trial < 20; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, 6u);
        const double range = range_of(&g), noise = trial % 2 == 0 ? 0.0 : 0.01 * range;
        hyst_everett_grid_fit_t fit;
        hyst_everett_grid_t got;
        hyst_wide_t rms = 0, knots[HYST_EVERETT_GRID_MAX_INTERVALS + 1];
        hyst_everett_t dom2;
        static ref_everett_t truth;
        long k;
        unsigned i;
        walk(&g, xs, FIT_SAMPLES);
        ref_egrid_init(&ref, &dom, &g);
        for (k = 0; k < FIT_SAMPLES; ++k) {
            fx[k] = (hyst_wide_t)xs[k];
            fy[k] = (hyst_wide_t)(ref_everett_step(&ref, (double)xs[k]) + noise * (rng_unit(&rng) - 0.5));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_init(&fit, g.knots, g.intervals, fit_work,
                                                                   sizeof fit_work / sizeof fit_work[0]));
        for (k = 0; k < FIT_SAMPLES; ++k) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_add(&fit, fx[k], fy[k]));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_solve(&fit, &got, &rms));
        for (i = 0u; i < HYST_EVERETT_GRID_CELLS(g.intervals); ++i) {
            TEST_ASSERT_TRUE(got.weight[i] >= 0);
        }
        /* the fitted model against the true one on a new drive */
        ref_egrid_init(&truth, &dom2, &g);
        walk(&g, xs, 1000L);
        {
            static double want[1000];
            for (k = 0; k < 1000; ++k) {
                want[k] = ref_everett_step(&truth, (double)xs[k]);
            }
            ref_egrid_init(&ref, &dom, &got);
            for (k = 0; k < 1000; ++k) {
                const double d = fabs(ref_everett_step(&ref, (double)xs[k]) - want[k]) / range;
                if (noise > 0.0) {
                    worst_noisy = d > worst_noisy ? d : worst_noisy;
                } else {
                    worst = d > worst ? d : worst;
                }
            }
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_knots(fx, fy, FIT_SAMPLES, g.knots[0],
                                                               g.knots[g.intervals], g.intervals, knots,
                                                               fit_work, 256u));
        for (i = 1u; i <= g.intervals; ++i) {
            TEST_ASSERT_TRUE(knots[i] > knots[i - 1u]);
        }
        TEST_ASSERT_TRUE(knots[0] == g.knots[0] && knots[g.intervals] == g.knots[g.intervals]);
    }
    TEST_PRINTF("grid fit: worst error %g of the range exact, %g with 1 %% noise", worst, worst_noisy);
    /* the fit in float: 2.4e-6 measured */
    TEST_ASSERT_TRUE(worst <= (SETUP_IN_FLOAT ? 1e-5 : 1e-6));
    TEST_ASSERT_TRUE(worst_noisy <= 0.01);
}

/* A grid fit on g's knots of fx[0..n) and g's outputs for them, from rest. */
static void fit_plant(hyst_everett_grid_fit_t *fit, const hyst_everett_grid_t *g, long n)
{
    long k;
    ref_egrid_init(&ref, &dom, g);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_init(fit, g->knots, g->intervals, fit_work,
                                                               sizeof fit_work / sizeof fit_work[0]));
    for (k = 0; k < n; ++k) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_add(fit, fx[k],
                                                                 (hyst_wide_t)ref_everett_step(&ref, (double)fx[k])));
    }
}

/* A grid of `intervals` on the knots 0, 1, ..., its masses 0. */
static hyst_everett_grid_t integer_grid(unsigned intervals)
{
    hyst_everett_grid_t g;
    unsigned i;
    memset(&g, 0, sizeof g);
    g.intervals = intervals;
    for (i = 0u; i <= intervals; ++i) {
        g.knots[i] = (hyst_wide_t)i;
    }
    return g;
}

/* Three major loops 0 -> top -> 0 by 0.1 into fx; returns their samples. */
static long major_loops(unsigned top)
{
    const long steps = 10L * (long)top;
    long n = 0, k;
    int c;
    for (c = 0; c < 3; ++c) {
        for (k = 0; k <= steps; ++k) {
            fx[n++] = (hyst_wide_t)(0.1 * (double)k);
        }
        for (k = steps - 1; k >= 0; --k) {
            fx[n++] = (hyst_wide_t)(0.1 * (double)k);
        }
    }
    return n;
}

/* Where the record does not determine the masses (major loops alone, 6
 * intervals), the fit returns the same masses whatever the rounding: the
 * outputs moved by 1e-12 of themselves, each of 8 ways, give the masses
 * within 1e-9 of the largest (7e-12 measured), every one fitting the record
 * within 1e-7 of its range. Without the fit's ridge the NNLS's order of
 * entry chose among the solutions that fit alike by rounding: masses apart
 * by 1.02 times the largest. */
static void test_undetermined_fit_is_the_same_whatever_the_rounding(void)
{
    hyst_everett_grid_t g = integer_grid(6u), first, got;
    hyst_everett_grid_fit_t fit;
    hyst_wide_t rms = -1;
    double largest = 0.0, worst = 0.0, y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
    const long n = major_loops(6u);
    long k;
    unsigned i, trial;
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) {
        g.weight[i] = (hyst_wide_t)(0.5 + rng_unit(&rng));
    }
    for (trial = 0u; trial <= 8u; ++trial) {
        ref_egrid_init(&ref, &dom, &g);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_init(&fit, g.knots, 6u, fit_work,
                                                                   sizeof fit_work / sizeof fit_work[0]));
        for (k = 0; k < n; ++k) {
            const double y = ref_everett_step(&ref, (double)fx[k]);
            const double moved = trial == 0u ? y : y * (1.0 + 1e-12 * (rng_unit(&rng) - 0.5));
            y_lo = y < y_lo ? y : y_lo;
            y_hi = y > y_hi ? y : y_hi;
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_add(&fit, fx[k], (hyst_wide_t)moved));
        }
        TEST_ASSERT_EQUAL_INT(0, hyst_everett_grid_fit_determined(&fit));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_solve(&fit, &got, &rms));
        /* the fit in float, its ridge 1.2e-3 of the largest diagonal entry
         * (ident.h): 3.7e-4 of the range measured */
        TEST_ASSERT_TRUE(rms <= (SETUP_IN_FLOAT ? 2e-3 : 1e-7) * (y_hi - y_lo));
        if (trial == 0u) {
            first = got;
            for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) {
                largest = (double)got.weight[i] > largest ? (double)got.weight[i] : largest;
            }
            continue;
        }
        for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) {
            const double d = fabs((double)(got.weight[i] - first.weight[i]));
            worst = d > worst ? d : worst;
        }
    }
    TEST_PRINTF("undetermined grid fit: masses within %g of the largest under 1e-12 of the outputs",
                worst / largest);
    TEST_ASSERT_TRUE(worst <= 1e-9 * largest);
}

/* The RMS a grid fit returns is its model's residual over the samples it
 * fitted: a 12-interval grid's record of 100 000 samples, noise 1e-6 of the
 * range, outputs offset by up to 1e6, its model run from rest over the same
 * inputs. Within 1e-3 of that residual, plus the outputs' rounding in double
 * (4 eps of the largest). Summed a sample at a time, the normal
 * equations' rounding read the first 2.2 % low (0 at noise 1e-7).
 * The fit and the reference compute in hyst_wide_t and double only, the
 * same code in the f32 and f64 builds: the f32 build (and HYST_NO_DOUBLE's)
 * runs it, the f64 build would repeat it (minutes of soft double under
 * emulation). */
#ifndef HYST_USE_DOUBLE
#define RMS_SAMPLES 100000L
static hyst_wide_t rms_work[HYST_EVERETT_GRID_FIT_WORK(12u, 64u)];
static hyst_wide_t rx[RMS_SAMPLES], ry[RMS_SAMPLES];

static void test_fit_rms_is_the_models_residual(void)
{
    static const double offsets[] = {0.0, 1e4, 1e6};
    double worst = 0.0;
    unsigned trial;
    for (trial = 0u; trial < 3u; ++trial) {
        hyst_everett_grid_t g = ref_egrid_random(&rng, 12u), got;
        hyst_everett_grid_fit_t fit;
        hyst_wide_t rms = -1;
        double range, v, sum_sq = 0.0, residual, floor_abs;
        long k;
        while (g.intervals < 12u) {
            g = ref_egrid_random(&rng, 12u);
        }
        g.y_lo = (hyst_wide_t)(g.y_lo + offsets[trial]);
        range = range_of(&g);
        v = 0.5 * (g.knots[0] + g.knots[12]);
        ref_egrid_init(&ref, &dom, &g);
        for (k = 0; k < RMS_SAMPLES; ++k) {
            rx[k] = (hyst_wide_t)ref_everett_walk(&rng, &v, g.knots[0], g.knots[12]);
            ry[k] = (hyst_wide_t)(ref_everett_step(&ref, (double)rx[k]) + 1e-6 * range * (rng_unit(&rng) - 0.5));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_init(&fit, g.knots, 12u, rms_work,
                                                                   sizeof rms_work / sizeof rms_work[0]));
        for (k = 0; k < RMS_SAMPLES; ++k) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_add(&fit, rx[k], ry[k]));
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_solve(&fit, &got, &rms));
        ref_egrid_init(&ref, &dom, &got); /* the model from rest at lo, as the fit */
        for (k = 0; k < RMS_SAMPLES; ++k) {
            const double d = ref_everett_step(&ref, (double)rx[k]) - (double)ry[k];
            sum_sq += d * d;
        }
        residual = sqrt(sum_sq / (double)RMS_SAMPLES);
        /* in float the sums the rms is formed from cancel: resolved only
         * above about sqrt(eps) of the outputs (ident.h) */
        floor_abs = (SETUP_IN_FLOAT ? sqrt(8.0 * FLT_EPSILON) : 4.0 * DBL_EPSILON) *
                    (fabs(offsets[trial]) + fabs((double)g.y_lo) + range);
        TEST_PRINTF("grid fit, outputs offset %g: rms %g, the model's residual %g (%g of the range)",
                    offsets[trial], (double)rms, residual, residual / range);
        TEST_ASSERT_TRUE(fabs((double)rms - residual) <= 1e-3 * residual + floor_abs);
        worst = fabs((double)rms / residual - 1.0) > worst ? fabs((double)rms / residual - 1.0) : worst;
    }
    TEST_PRINTF("grid fit: returned rms within %g of the model's residual", worst);
}
#endif

/* Major loops alone do not determine a grid of 4 intervals' 10 masses (how
 * the inner cells share theirs): the fit says so, and its solve is one of
 * many; the same plant's reversal curves from points inside each interval
 * determine them, and are fitted exactly. */
static void test_fit_says_whether_the_record_determines_the_masses(void)
{
    hyst_everett_grid_t g = integer_grid(4u), got;
    hyst_everett_grid_fit_t fit;
    hyst_wide_t rms = -1;
    long n;
    int c, d;
    unsigned i;
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(4u); ++i) {
        g.weight[i] = 1 + (hyst_wide_t)i;
    }
    n = major_loops(4u);
    fit_plant(&fit, &g, n);
    TEST_ASSERT_EQUAL_INT(0, hyst_everett_grid_fit_determined(&fit));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_solve(&fit, &got, &rms));
    /* the fit in float, its ridge as above: 0.011 (of a range of 55) measured */
    TEST_ASSERT_TRUE(rms < (SETUP_IN_FLOAT ? 0.05 : 1e-9));
    /* reversal curves: up from 0 to a, down to 0, a at 0.25 .. 4 */
    n = 0;
    for (c = 1; c <= 16; ++c) {
        const double a = 0.25 * (double)c;
        for (d = 0; 0.07 * d < a; ++d) {
            fx[n++] = (hyst_wide_t)(0.07 * d);
        }
        for (d = 0; a - 0.05 * d > 0.0; ++d) {
            fx[n++] = (hyst_wide_t)(a - 0.05 * d);
        }
    }
    fit_plant(&fit, &g, n);
    TEST_ASSERT_EQUAL_INT(1, hyst_everett_grid_fit_determined(&fit));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_solve(&fit, &got, &rms));
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(4u); ++i) {
        /* normal equations in float: 5.4e-5 measured */
        TEST_ASSERT_TRUE(fabs((double)(got.weight[i] - g.weight[i])) <=
                         (SETUP_IN_FLOAT ? 1e-4 : 1e-6) * (double)g.weight[i]);
    }
}

/* The compensator: the model driven by it follows the desired outputs
 * (random walks with minor loops and wipe-outs) within rounding, the
 * drive is monotone along each monotone run of desired outputs, block =
 * step bit for bit; refusals. */
static void test_compensator_inverts_the_model(void)
{
    int trial;
    double worst = 0.0;
    hyst_curve_t inv;
    for (trial = 0; trial < 40; ++trial) {
        const hyst_everett_grid_t g = ref_egrid_random(&rng, HYST_EVERETT_GRID_MAX_INTERVALS);
        /* inside the compensator's domain, whose ends are rounded */
        const double range = range_of(&g), lo = g.y_lo + 1e-6 * range, hi = g.y_lo + range * (1.0 - 1e-6);
        double v = 0.5 * (lo + hi), d_prev = g.y_lo, x_prev = (double)g.knots[0];
        int up = 1;
        long k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_grid_inverse(&inv, &curve));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl2, yl2, xr2, yr2, CAP));
        for (k = 0; k < SAMPLES; ++k) {
            xs[k] = (hyst_real_t)ref_everett_walk(&rng, &v, lo, hi);
        }
        for (k = 0; k < SAMPLES; ++k) {
            const hyst_real_t x = hyst_step(&T, xs[k]);
            const double y = (double)hyst_step(&S, x);
            const double d = fabs(y - (double)xs[k]) / range;
            worst = d > worst ? d : worst;
            if ((double)xs[k] != d_prev) {
                up = (double)xs[k] > d_prev;
            }
            TEST_ASSERT_TRUE(up ? (double)x >= x_prev : (double)x <= x_prev);
            d_prev = (double)xs[k];
            x_prev = (double)x;
            ys[k] = x;
        }
        hyst_reset(&T);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&T, xs, ys2, (size_t)SAMPLES));
        TEST_ASSERT_EQUAL_MEMORY(ys, ys2, sizeof ys);
    }
    TEST_PRINTF("compensator: worst |model(drive) - desired| %g of the range", worst);
    TEST_ASSERT_TRUE(worst <= 10.0 * AGREE);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_everett_grid_inverse(NULL, &curve));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_everett_grid_inverse(&curve2, &inv));
#ifdef HYST_USE_DOUBLE
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_curve_everett_grid_inverse(&curve2, &curve));
#else
    {
        hyst_poly_t f0 = {1u, 0.0, 1.0, {1.0, 0.0}};
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&curve2, &f0));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_everett_grid_inverse(&inv, &curve2));
    }
#endif
}


/* A grid whose first diagonal cell is empty (the major rising branch is
 * flat over the first interval) while its first column holds mass: driven
 * to y_hi, then to y_lo, the compensator's drive is lo itself, where the
 * plant forgets its memory as the compensator does; a drive at the end of
 * the flat piece would leave the column switched up (the output 16.5 too
 * high here). */
static void test_compensator_reaches_lo_past_an_empty_first_cell(void)
{
    hyst_everett_grid_t g;
    hyst_curve_t inv;
    static const hyst_real_t desired[4] = {HYST_REAL_C(50.0), HYST_REAL_C(97.25), HYST_REAL_C(1.0),
                                           HYST_REAL_C(40.0)};
    unsigned i;
    memset(&g, 0, sizeof g);
    g.intervals = 12u;
    for (i = 1u; i <= 12u; ++i) { /* widths 0.25 .. 1.25: exact in float */
        g.knots[i] = g.knots[i - 1u] + HYST_WIDE_C(0.25) * (hyst_wide_t)(1u + (i - 1u) % 5u);
    }
    g.y_lo = 1.0;
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(12u); ++i) {
        g.weight[i] = (hyst_wide_t)((i * 7u) % 11u) / 4; /* cell (0, 0): 0 */
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_grid_inverse(&inv, &curve));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl2, yl2, xr2, yr2, CAP));
    for (i = 0u; i < 4u; ++i) {
        const hyst_real_t x = hyst_step(&T, desired[i]);
        const double y = (double)hyst_step(&S, x);
        if (i == 2u) {
            TEST_ASSERT_TRUE(x == (hyst_real_t)0.0);
        }
        TEST_ASSERT_TRUE(fabs(y - (double)desired[i]) <= 10.0 * AGREE * 96.25);
    }
}

/* A nearly flat last piece (the last diagonal cell a millionth of the
 * rest, its row empty): a desired output at or near y_hi exceeds the
 * branch's reach by a rounding, and the drive stays on the domain (within
 * the 8 units in the last place tcm.h states), where the solve extrapolated
 * it past hi (by up to 1.8 in float, 6e-9 in double). */
static void test_compensator_drive_stays_on_the_domain(void)
{
    const double hi = 2.0, allowed = 8.0 * (double)(NEXT((hyst_real_t)hi, (hyst_real_t)4.0) - (hyst_real_t)hi);
    hyst_everett_grid_t g;
    hyst_curve_t inv;
    double worst = 0.0;
    int j;
    for (j = 0; j < 200; ++j) {
        hyst_real_t y_hi, x[3];
        int i;
        memset(&g, 0, sizeof g);
        g.intervals = 2u;
        g.knots[1] = 1.0;
        g.knots[2] = (hyst_wide_t)hi;
        g.y_lo = (hyst_wide_t)(0.1 * j + 0.013);
        g.weight[0] = (hyst_wide_t)(1.0 + 0.37 * j);
        g.weight[2] = HYST_WIDE_C(1e-6);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett_grid(&curve, &g, table, TABLE));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_grid_inverse(&inv, &curve));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl2, yl2, xr2, yr2, CAP));
        y_hi = CURVE_NUM(curve.y_hi);
        x[0] = hyst_step(&T, y_hi);
        x[1] = hyst_step(&T, (hyst_real_t)(g.y_lo + 0.5));
        x[2] = hyst_step(&T, y_hi - (y_hi - (hyst_real_t)g.y_lo) * (hyst_real_t)1e-9);
        for (i = 0; i < 3; ++i) {
            worst = (double)x[i] - hi > worst ? (double)x[i] - hi : worst;
        }
    }
    TEST_PRINTF("nearly flat last piece: the drive at most %g past hi", worst);
    TEST_ASSERT_TRUE(worst <= allowed);
}

/* A setpoint come back to: falling from a reversal whose branch is flat
 * below the last LTP (its columns empty there), a desired output at (or a
 * rounding above) that LTP's output carried the drive across the flat
 * stretch when the branch's own value there rounded below it, so the plant
 * wiped out the LTP the compensator kept (up to 21 of a range of 672 off
 * in these walks, float and double). The drive now never passes the
 * stored TP the branch would wipe out next before the desired output
 * passes that TP's. */
static void test_compensator_keeps_the_plants_memory_at_a_setpoint(void)
{
    hyst_everett_grid_t g;
    hyst_curve_t inv;
    double worst = 0.0;
    unsigned i;
    int trial;
    memset(&g, 0, sizeof g);
    g.intervals = 4u;
    g.knots[1] = 0.5;
    g.knots[2] = 4.5;
    g.knots[3] = 5.5;
    g.knots[4] = 7.5;
    g.y_lo = 1.0;
    for (i = 5u; i < 10u; ++i) { /* cells (2, 2), (3, 0..3): below a = 5.5 columns 0, 1 empty */
        g.weight[i] = 134.375;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett_grid(&curve, &g, table, TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_grid_inverse(&inv, &curve));
    for (trial = 0; trial < 4000; ++trial) {
        const hyst_real_t drives[3] = {(hyst_real_t)(5.5 + 2.0 * ((trial * 37) % 101) / 101.0),
                                       (hyst_real_t)(0.5 + 4.0 * ((trial * 53) % 97) / 97.0),
                                       (hyst_real_t)(4.5 + 1.0 * ((trial * 71) % 89) / 89.0)};
        hyst_real_t desired[5];
        int k;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &curve, xl, yl, xr, yr, CAP));
        for (k = 0; k < 3; ++k) { /* the plant's own outputs: up, down to the LTP, up */
            desired[k] = hyst_step(&S, drives[k]);
        }
        desired[3] = trial % 3 == 1 ? NEXT(desired[1], desired[2]) : desired[1]; /* back */
        desired[4] = desired[2];
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &curve, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &inv, xl2, yl2, xr2, yr2, CAP));
        for (k = 0; k < 5; ++k) {
            const double y = (double)hyst_step(&S, hyst_step(&T, desired[k]));
            worst = fabs(y - (double)desired[k]) > worst ? fabs(y - (double)desired[k]) : worst;
        }
    }
    TEST_PRINTF("setpoints come back to: worst |model(drive) - desired| %g", worst);
    TEST_ASSERT_TRUE(worst <= 10.0 * AGREE * 5.0 * 134.375);
}

/* A mass whose density the type holds only as a subnormal or as 0 (a
 * width's square overflowing) is refused (HYST_ERR_COEFF), where the curve
 * was accepted with the mass lost to the model (its output at hi short of
 * y_hi, or its density's precision); a width whose square is subnormal
 * gives its density to rounding. */
static void test_densities_the_type_cannot_hold_are_refused(void)
{
    static float t32[TABLE];
    hyst_everett_grid_t g;
    hyst_curve_t c;
    memset(&g, 0, sizeof g);
    g.intervals = 1u;
    g.knots[1] = HYST_WIDE_C(1e20); /* density 1e-40: subnormal in float */
    g.weight[0] = 1.0;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_f32_curve_from_everett_grid(&c, &g, t32, TABLE));
#if HYST_ENABLE_F64
    {
        static double t64[TABLE];
        g.knots[1] = 1e160; /* h^2 overflows: density 0 */
        TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_f64_curve_from_everett_grid(&c, &g, t64, TABLE));
    }
#endif
    g.knots[1] = HYST_WIDE_C(1e18); /* density 1e-36: normal, accepted */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_from_everett_grid(&c, &g, t32, TABLE));
#if HYST_ENABLE_F64
    { /* a width of 1.6e-159, its square subnormal: the density still exact to rounding
       * (it was off by 1.3e-7, the model's output at hi with it) */
        static double t64[TABLE];
        g.knots[1] = 1.6368713072402582e-159;
        g.weight[0] = 2.639011642716169e-16;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f64_curve_from_everett_grid(&c, &g, t64, TABLE));
        TEST_ASSERT_TRUE(fabs(hyst_f64_curve_eval(&c, g.knots[1]) - g.weight[0]) <= 1e-14 * g.weight[0]);
    }
#endif
}

/* The fit's outputs so large that its normal equations overflow: refused
 * (HYST_ERR_COEFF), the grid and the RMS not written, where it answered
 * HYST_OK with an infinite mass. */
static void test_fit_refuses_outputs_that_overflow(void)
{
    static const hyst_wide_t knots[4] = {0.0, 1.0, 2.0, 3.0};
    static const hyst_wide_t x[6] = {0.5, 1.5, 2.5, 1.0, 2.0, 0.5};
    /* -1.4e38 in float (HYST_NO_DOUBLE): its square overflows there */
    static const hyst_wide_t y[6] = {1.0, 2.0, 4.0, (hyst_wide_t)(SETUP_IN_FLOAT ? -1.4e38 : -1.4e308),
                                     3.0, 1.5};
    hyst_everett_grid_fit_t fit;
    hyst_everett_grid_t got, before;
    hyst_wide_t rms = -1;
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_init(&fit, knots, 3u, fit_work,
                                                               sizeof fit_work / sizeof fit_work[0]));
    for (k = 0; k < 6; ++k) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_fit_add(&fit, x[k], y[k]));
    }
    memset(&got, 0x5a, sizeof got);
    before = got;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, hyst_everett_grid_fit_solve(&fit, &got, &rms));
    TEST_ASSERT_EQUAL_MEMORY(&before, &got, sizeof got);
    TEST_ASSERT_TRUE(rms == -1);
}

/* The knots: output steps whose sum overflows (two of 1.5e308 in one bin)
 * still give finite knots at their quantiles, where they were NaN; a
 * domain too narrow for the type to hold the knots apart is refused, the
 * knots not written, where equal knots were returned (the fit refuses them). */
static void test_knots_of_extreme_records(void)
{
    /* 2.8e38 in float (HYST_NO_DOUBLE): two of them overflow there */
#define BIG ((hyst_wide_t)(SETUP_IN_FLOAT ? 2.8e38 : 1.5e308))
    static const hyst_wide_t x[4] = {HYST_WIDE_C(0.1), 0.5, HYST_WIDE_C(0.1), 0.5};
    static const hyst_wide_t y[4] = {0.0, BIG, 0.0, BIG};
#undef BIG
    /* four units in the last place of 1 (float's with HYST_NO_DOUBLE) */
    const hyst_wide_t wide_narrow = (hyst_wide_t)(1.0 + (SETUP_IN_FLOAT ? 0x1p-21 : 0x1p-50));
    hyst_wide_t knots[5], keep[5];
    unsigned q;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_everett_grid_knots(x, y, 4u, 0.0, 1.0, 4u, knots, fit_work, 64u));
    for (q = 1u; q <= 4u; ++q) {
        TEST_ASSERT_TRUE(knots[q] > knots[q - 1u]); /* NaN fails */
    }
    TEST_ASSERT_TRUE(knots[1] >= 0.29 && knots[3] <= 0.35); /* every step at mid 0.3 */
    memset(knots, 0x5a, sizeof knots);
    memcpy(keep, knots, sizeof knots);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_everett_grid_knots(x, y, 4u, 1.0, wide_narrow, 4u,
                                                                   knots, fit_work, 64u));
    TEST_ASSERT_EQUAL_MEMORY(keep, knots, sizeof knots);
}

#ifndef HYST_USE_DOUBLE
/* The integer-code variant runs the same curve: bit for bit the f32
 * variant's outputs on codes. */
static void test_codes_run_the_grid_kind(void)
{
    static hyst_code_word_t cl[CAP], cr[CAP];
    static float cyl[CAP], cyr[CAP];
    hyst_everett_grid_t g = ref_egrid_random(&rng, 8u);
    const double lo = g.knots[0], span = g.knots[g.intervals] - lo;
    hyst_t C;
    unsigned i;
    long k;
    for (i = 0u; i <= g.intervals; ++i) { /* onto codes 0..4095, knots on whole codes */
        g.knots[i] = (hyst_wide_t)floor(((double)g.knots[i] - lo) * 4095.0 / span + 0.5);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_g(&S, &curve, &g, table, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&C, &curve, 0u, 4095u, cl, cyl, cr, cyr, CAP));
    walk(&g, xs, SAMPLES);
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
    RUN_TEST(test_random_grids_agree_with_the_reference);
    RUN_TEST(test_one_cell_is_a_parabola);
    RUN_TEST(test_minor_loops_close_bit_for_bit);
    RUN_TEST(test_bad_grids_are_refused);
    RUN_TEST(test_curve_eval_is_the_major_rising_branch);
    RUN_TEST(test_block_and_snapshots);
    RUN_TEST(test_snapshot_identity_is_the_table);
    RUN_TEST(test_bounded_memory_keeps_its_bound);
    RUN_TEST(test_deadband_bound_holds);
    RUN_TEST(test_identification_recovers_the_grid);
    RUN_TEST(test_fit_says_whether_the_record_determines_the_masses);
    RUN_TEST(test_undetermined_fit_is_the_same_whatever_the_rounding);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_fit_rms_is_the_models_residual);
#endif
    RUN_TEST(test_compensator_inverts_the_model);
    RUN_TEST(test_compensator_reaches_lo_past_an_empty_first_cell);
    RUN_TEST(test_compensator_drive_stays_on_the_domain);
    RUN_TEST(test_compensator_keeps_the_plants_memory_at_a_setpoint);
    RUN_TEST(test_densities_the_type_cannot_hold_are_refused);
    RUN_TEST(test_fit_refuses_outputs_that_overflow);
    RUN_TEST(test_knots_of_extreme_records);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_codes_run_the_grid_kind);
#endif
    return UNITY_END();
}
