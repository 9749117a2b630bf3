/* SPDX-License-Identifier: MIT */
/* The fixed-point variant (hyst/q31.h) against the double reference
 * (support/ref_tcm.c, which shares no code with the library): the same TP
 * counts at every sample (the rules), outputs within the stated bound
 * ((stored TPs + 1) rounding bounds + 1, in q) and within 1e-4 of the output
 * range, on random histories, the paper's signal and the measured drive of
 * tests/data; step and block bit-identical; curves whose Horner sums could
 * overflow refused; snapshots refused clearly. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hyst/hyst.h"
#include "hyst_port.h"
#include "ref_tcm.h"
#include "signals.h"
#include "support.h"
#include "piezo_data.h"
#include "unity.h"

#ifndef HYST_TEST_DATA_DIR
#define HYST_TEST_DATA_DIR "data"
#endif

#define CAP 4096u
#define MAXN 8192
#define Q31_TOL_OF_RANGE 1e-4

static hyst_code_word_t qx[2][CAP];
static hyst_q31_t qy[2][CAP];
static hyst_t Q;
static ref_tcm_t ref;
static rng_t rng;
static uint_least32_t codes[MAXN];
static hyst_code_word_t words[MAXN];
static hyst_q31_t outs[MAXN];
static double worst_rel; /* of the last agree() */
static double signals_rel; /* the largest on the paper's signal and the drive */

void setUp(void) { rng_seed(&rng, 3131u); }
void tearDown(void) {}

static hyst_status_t init_q31(const hyst_poly_t *f0, uint_least32_t lo, uint_least32_t hi,
                              size_t cap)
{
    return hyst_q31_init(&Q, f0, lo, hi, qx[0], qy[0], qx[1], qy[1], cap);
}

/* The input a code stands for, codes lo..hi onto [f0->lo, f0->hi]. */
static double input_of(const hyst_poly_t *f0, uint_least32_t code, uint_least32_t lo,
                       uint_least32_t hi)
{
    return (double)f0->lo +
           ((double)f0->hi - (double)f0->lo) * (double)(code - lo) / (double)(hi - lo);
}

/* Runs codes[0..n) through Q (fresh from init) and the reference; checks
 * the TP counts at every sample, the bound and 1e-4 of the range; the
 * largest error relative to the range in worst_rel. */
static void agree(const hyst_poly_t *f0, uint_least32_t lo, uint_least32_t hi, long n)
{
    double c[REF_MAX_DEGREE + 1];
    const double y_lo = (double)hyst_poly_eval(f0, f0->lo);
    const double y_hi = (double)hyst_poly_eval(f0, f0->hi);
    const double per_q = (y_hi - y_lo) / 4294967296.0 * 16.0; /* 2^-28 of the range */
    const double rb = (double)hyst_q31_rounding_bound(&Q);
    long i;
    unsigned k;
    for (k = 0u; k <= f0->degree; ++k) {
        c[k] = (double)f0->coeffs[k];
    }
    ref_init(&ref, c, f0->degree, (double)f0->lo, (double)f0->hi);
    worst_rel = 0.0;
    for (i = 0; i < n; ++i) {
        const hyst_q31_t q = hyst_q31_step(&Q, (uint_least32_t)codes[i]);
        const double want = ref_step(&ref, input_of(f0, codes[i], lo, hi));
        const double err_q = fabs((want - (y_lo + y_hi) / 2) / per_q - (double)q);
        const long tps = (long)hyst_tp_count(&Q);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&Q));
        TEST_ASSERT_EQUAL_INT32(ref_tp_count(&ref), tps);
        if (!(err_q <= (double)(tps + 1) * rb + 1.0)) {
            printf("sample %ld code %lu: q %ld, want %.3f (q units), error %.1f > %.0f x %.0f + 1\n",
                   i, (unsigned long)codes[i], (long)q, (want - (y_lo + y_hi) / 2) / per_q, err_q,
                   (double)(tps + 1), rb);
            TEST_FAIL();
        }
        worst_rel = err_q * per_q / (y_hi - y_lo) > worst_rel ? err_q * per_q / (y_hi - y_lo)
                                                              : worst_rel;
    }
    TEST_ASSERT_TRUE(worst_rel <= Q31_TOL_OF_RANGE);
}

/* codes[0..n) of a random history on lo..hi: kind 0 walk, 1 jumps, 2
 * nested loops (alternating towards the last extreme). */
static void random_codes(int kind, uint_least32_t lo, uint_least32_t hi, long n)
{
    const long span = (long)(hi - lo);
    long c = (long)lo, centre = (long)lo + span / 2, i;
    for (i = 0; i < n; ++i) {
        if (kind == 0) {
            c += (long)rng_below(&rng, (uint32_t)(span / 25 + 1)) - span / 50;
        } else if (kind == 1 || i % 97 == 0) {
            c = (long)lo + (long)rng_below(&rng, (uint32_t)(span + 1));
        } else {
            const long prev = c;
            c += (long)((double)(centre - c) * rng_range(&rng, 0.05, 0.95));
            centre = prev;
        }
        c = c < (long)lo ? (long)lo : c > (long)hi ? (long)hi : c;
        codes[i] = (uint_least32_t)c;
    }
}

static void test_random_histories_agree_with_double(void)
{
    static const uint_least32_t ranges[3][2] = {{0u, 4095u}, {0u, 65535u}, {100u, 1123u}};
    int r, kind;
    for (r = 0; r < 3; ++r) {
        for (kind = 0; kind < 3; ++kind) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, ranges[r][0], ranges[r][1], CAP));
            random_codes(kind, ranges[r][0], ranges[r][1], 3000);
            agree(&paper_eq20, ranges[r][0], ranges[r][1], 3000);
            printf("codes %lu..%lu history %d: max error %.3g of the range, bound %ld q\n",
                   (unsigned long)ranges[r][0], (unsigned long)ranges[r][1], kind, worst_rel,
                   (long)hyst_q31_rounding_bound(&Q));
        }
    }
}

/* The paper's signal on 12-bit and 16-bit codes; and a cubic whose
 * coefficients cancel (x - 1/2)^3: partial sums 13.5 times its range. */
static void test_paper_signal_agrees_within_1e4_of_range(void)
{
    static const hyst_poly_t cancel = {3u, 0.0, 1.0, {1.0, -1.5, 0.75, -0.125}};
    const hyst_poly_t *curves[2] = {&paper_eq20, &cancel};
    static const uint_least32_t his[2] = {4095u, 65535u};
    static hyst_real_t path[MAXN];
    double levels[32];
    int h, cv;
    for (cv = 0; cv < 2; ++cv) {
        for (h = 0; h < 2; ++h) {
            const int nl = paper_levels(0.0, (double)his[h], levels);
            const long n = ramp_path(0.0, levels, nl, (double)his[h] / 300.0, path, MAXN);
            long i;
            TEST_ASSERT_TRUE(n > 1000 && n < MAXN);
            for (i = 0; i < n; ++i) {
                codes[i] = (uint_least32_t)((double)path[i] + 0.5);
            }
            TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(curves[cv], 0u, his[h], CAP));
            agree(curves[cv], 0u, his[h], n);
            signals_rel = worst_rel > signals_rel ? worst_rel : signals_rel;
            printf("paper signal, curve %d, codes 0..%lu: %ld samples, max error %.3g of the range\n",
                   cv, (unsigned long)his[h], n, worst_rel);
        }
    }
}

/* Reads column 1 (the drive) of the measured record into codes[], 16-bit
 * codes over its own range; returns the count. */
static long read_drive(double *lo, double *hi)
{
    static double x[MAXN], y[MAXN];
    long i;
    const long n = piezo_data_load(HYST_TEST_DATA_DIR "/piezo_major_loop.dat", x, y, MAXN);
    TEST_ASSERT_TRUE_MESSAGE(n > 0, "cannot read " HYST_TEST_DATA_DIR "/piezo_major_loop.dat");
    *lo = *hi = x[0];
    for (i = 0; i < n; ++i) {
        *lo = x[i] < *lo ? x[i] : *lo;
        *hi = x[i] > *hi ? x[i] : *hi;
    }
    for (i = 0; i < n; ++i) {
        codes[i] = (uint_least32_t)((x[i] - *lo) / (*hi - *lo) * 65535.0 + 0.5);
    }
    return n;
}

/* The measured drive (8027 samples, 40 cycles with minor loops) through the
 * paper's cubic and a degree-5 curve, stretched onto its range. */
static void test_measured_drive_agrees_within_1e4_of_range(void)
{
    double lo, hi;
    const long n = read_drive(&lo, &hi);
    hyst_poly_t cubic = paper_eq20, quintic = {5u, 0.0, 1.0, {0.0}};
    TEST_ASSERT_EQUAL_INT32(8027, n);
    /* f0(x) = eq20(40 (x - lo) / (hi - lo)) in the drive's units: the same
     * shape; a quintic u + u^5 / 2 - u^3 / 4 (increasing) on [lo, hi]. */
    cubic.lo = (hyst_wide_t)lo;
    cubic.hi = (hyst_wide_t)hi;
    {
        const double s = 40.0 / (hi - lo);
        hyst_wide_t p[4];
        unsigned k, j;
        /* eq20(s (x - lo)) expanded: Taylor shift of eq20 scaled */
        for (k = 0u; k < 4u; ++k) {
            p[k] = paper_eq20.coeffs[k];
        }
        for (k = 0u; k < 4u; ++k) { /* p(s t): coefficient of t^(3-k) times s^(3-k) */
            double sp = 1.0;
            for (j = k; j < 3u; ++j) {
                sp *= s;
            }
            p[k] = (hyst_wide_t)((double)p[k] * sp);
        }
        for (k = 0u; k < 3u; ++k) { /* p(t) -> p(x - lo) */
            for (j = 1u; j <= 3u - k; ++j) {
                p[j] += (hyst_wide_t)(-lo) * p[j - 1u];
            }
        }
        memcpy(cubic.coeffs, p, sizeof p);
    }
    quintic.coeffs[0] = 0.5;
    quintic.coeffs[2] = -0.25;
    quintic.coeffs[4] = 1.0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&cubic, 0u, 65535u, CAP));
    agree(&cubic, 0u, 65535u, n);
    printf("measured drive, cubic: max error %.3g of the range\n", worst_rel);
    signals_rel = worst_rel > signals_rel ? worst_rel : signals_rel;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&quintic, 0u, 65535u, CAP));
    agree(&quintic, 0u, 65535u, n);
    printf("measured drive, quintic: max error %.3g of the range\n", worst_rel);
    signals_rel = worst_rel > signals_rel ? worst_rel : signals_rel;
    printf("q31_max_err_rel %.3g\n", signals_rel); /* bench/run's figure */
}

/* process() gives step()'s outputs bit for bit, statuses folded. */
static void test_block_equals_step(void)
{
    long i;
    random_codes(2, 0u, 4095u, 4000);
    for (i = 0; i < 4000; ++i) {
        words[i] = (hyst_code_word_t)codes[i];
    }
    words[1000] = 4095u; /* at hi */
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 4095u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_process(&Q, words, outs, 4000u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 4095u, CAP));
    for (i = 0; i < 4000; ++i) {
        TEST_ASSERT_EQUAL_INT32(outs[i], hyst_q31_step(&Q, words[i]));
    }
}

/* Outputs are monotone in a monotone input (the guard), stay inside
 * [-2^27, 2^27], and the ends map exactly. */
static void test_scaling_and_monotone_sweeps(void)
{
    const hyst_q31_t half = (hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1);
    hyst_q31_t prev;
    uint_least32_t c;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 4095u, CAP));
    TEST_ASSERT_EQUAL_INT32(-half, hyst_q31_output(&Q));
    prev = -half;
    for (c = 1u; c <= 4095u; ++c) {
        const hyst_q31_t y = hyst_q31_step(&Q, c);
        TEST_ASSERT_TRUE(y >= prev);
        prev = y;
    }
    TEST_ASSERT_INT32_WITHIN(hyst_q31_rounding_bound(&Q), half, prev);
    TEST_ASSERT_EQUAL_UINT32(4095u, hyst_q31_input(&Q));
    for (c = 4094u; c + 1u > 0u; --c) {
        const hyst_q31_t y = hyst_q31_step(&Q, c);
        TEST_ASSERT_TRUE(y <= prev);
        prev = y;
    }
    TEST_ASSERT_INT32_WITHIN(2 * hyst_q31_rounding_bound(&Q), -half, prev);
    /* in hyst_wide_t: a few of float's rounding units with HYST_NO_DOUBLE */
    TEST_ASSERT_DOUBLE_WITHIN(SETUP_IN_FLOAT ? 4.0 * FLT_EPSILON : 1e-9,
                              (double)paper_eq20.coeffs[3],
                              (double)hyst_q31_to_real(&paper_eq20, -half));
    /* clamped above hi */
    (void)hyst_q31_step(&Q, 5000u);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&Q));
    TEST_ASSERT_EQUAL_UINT32(4095u, hyst_q31_input(&Q));
    hyst_reset(&Q);
    TEST_ASSERT_EQUAL_INT32(-half, hyst_q31_output(&Q));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&Q));
}

/* Bounded memory: a small array merges; outputs stay in the range and the
 * error bound saturates instead of overflowing. */
static void test_small_capacity_merges_stay_bounded(void)
{
    const hyst_q31_t half = (hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1);
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 65535u, 4u));
    random_codes(2, 0u, 65535u, 5000);
    for (i = 0; i < 5000; ++i) {
        const hyst_q31_t y = hyst_q31_step(&Q, codes[i]);
        TEST_ASSERT_TRUE(y >= -half - hyst_q31_rounding_bound(&Q) * 8);
        TEST_ASSERT_TRUE(y <= half + hyst_q31_rounding_bound(&Q) * 8);
        TEST_ASSERT_TRUE(hyst_q31_error_bound(&Q) >= 0);
        TEST_ASSERT_TRUE(hyst_q31_error_bound(&Q) <= HYST_Q31_BOUND_MAX + half * 3);
    }
    TEST_ASSERT_TRUE((hyst_events(&Q) & HYST_EVENT_FULL) != 0u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_set_deadband(&Q, 50u));
    for (i = 0; i < 2000; ++i) {
        (void)hyst_q31_step(&Q, codes[i]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_q31_set_deadband(&Q, 70000u));
}

/* Curves whose partial Horner sums could overflow 32 bits are refused,
 * though they are increasing and double evaluates them well: (x - 1/2)^7
 * has partial sums 1093 times its range (the limit is 128); (x - 1/2)^5,
 * 121 times, is accepted and agrees. Set up in float, both are refused
 * sooner (SETUP_IN_FLOAT). */
static void test_overflowing_curves_are_refused(void)
{
    static const hyst_poly_t wild = {7u, 0.0, 1.0,
                                     {1.0, -3.5, 5.25, -4.375, 2.1875, -0.65625, 0.109375,
                                      -0.0078125}};
    static const hyst_poly_t tame = {5u, 0.0, 1.0, {1.0, -2.5, 2.5, -1.25, 0.3125, -0.03125}};
    memset(&Q, 0, sizeof Q);
    TEST_ASSERT_TRUE(hyst_poly_is_increasing(wild.coeffs, wild.degree, wild.lo, wild.hi, NULL));
    if (SETUP_IN_FLOAT) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, init_q31(&wild, 0u, 4095u, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, init_q31(&tame, 0u, 4095u, CAP));
        TEST_ASSERT_EQUAL_UINT(0u, Q.variant); /* nothing written */
        return;
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_COEFF, init_q31(&wild, 0u, 4095u, CAP));
    TEST_ASSERT_EQUAL_UINT(0u, Q.variant); /* nothing written */
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&tame, 0u, 4095u, CAP));
    random_codes(2, 0u, 4095u, 3000);
    agree(&tame, 0u, 4095u, 3000);
    printf("(x - 1/2)^5: max error %.3g of the range, bound %ld q\n", worst_rel,
           (long)hyst_q31_rounding_bound(&Q));
}

static void test_bad_arguments_are_refused(void)
{
    unsigned char buf[64];
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_init(NULL, &paper_eq20, 0u, 4095u, qx[0],
                                                       qy[0], qx[1], qy[1], CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, init_q31(NULL, 0u, 4095u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_q31(&paper_eq20, 10u, 10u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_q31(&paper_eq20, 0u, HYST_CODE_MAX + 1u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, init_q31(&paper_eq20, 0u, 4095u, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 4095u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_code_set_deadband(&Q, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_set_deadband(NULL, 3u));
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_step(NULL, 5u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_process(&Q, NULL, outs, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE, hyst_snapshot_save(&Q, buf, 8u, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&Q));
    (void)hyst_q31_step(&Q, 7u);
    TEST_ASSERT_EQUAL_UINT32(0u, hyst_q31_input(&Q));
}

/* Snapshots (snapshot.h; q31 numbers travel as 4-octet two's complement):
 * a restored instance continues bit for bit, merged loops and an open
 * deadband window included; a damaged or truncated snapshot is refused with
 * the instance and its arrays untouched. */
#define SNAP_CAP 48u
static hyst_code_word_t sx[2][SNAP_CAP];
static hyst_q31_t sy[2][SNAP_CAP];
static hyst_t Q2, Q2_kept;
static hyst_code_word_t sx_kept[2][SNAP_CAP];
static hyst_q31_t sy_kept[2][SNAP_CAP];
static unsigned char snap[HYST_SNAPSHOT_SIZE(SNAP_CAP)], snap_again[HYST_SNAPSHOT_SIZE(SNAP_CAP)];
static unsigned char damaged[HYST_SNAPSHOT_SIZE(SNAP_CAP)];

static void assert_q2_untouched(void)
{
    TEST_ASSERT_EQUAL_MEMORY(&Q2_kept, &Q2, sizeof Q2);
    TEST_ASSERT_EQUAL_MEMORY(sx_kept, sx, sizeof sx);
    TEST_ASSERT_EQUAL_MEMORY(sy_kept, sy, sizeof sy);
}

static void test_snapshot_round_trips_bit_identically(void)
{
    size_t len = 0u, len2 = 0u, i;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_init(&Q, &paper_eq20, 0u, 4095u, qx[0], qy[0], qx[1],
                                                 qy[1], SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_set_deadband(&Q, 3u));
    for (k = 0; k < 6000; ++k) { /* shrinking triangles: deep nests, then wiped out */
        const long amp = 2000L - (k % 1700L);
        codes[k] = (uint_least32_t)(2048L + (k % 2L == 0L ? amp : -amp) + (long)rng_below(&rng, 3u));
    }
    for (k = 0; k < 2600; ++k) {
        (void)hyst_q31_step(&Q, codes[k]);
    }
    TEST_ASSERT_TRUE((hyst_events(&Q) & HYST_EVENT_FULL) != 0u); /* loops were merged */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&Q, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_size_t(hyst_snapshot_size(&Q), len);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_init(&Q2, &paper_eq20, 0u, 4095u, sx[0], sy[0],
                                                 sx[1], sy[1], SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_set_deadband(&Q2, 3u));
    (void)hyst_q31_step(&Q2, 2000u);
    memcpy(&Q2_kept, &Q2, sizeof Q2);
    memcpy(sx_kept, sx, sizeof sx);
    memcpy(sy_kept, sy, sizeof sy);
    for (i = 0u; i < len; ++i) { /* one bit of every octet */
        memcpy(damaged, snap, len);
        damaged[i] = (unsigned char)(damaged[i] ^ (1u << (i % 8u)));
        TEST_ASSERT_TRUE(hyst_snapshot_restore(&Q2, damaged, len) != HYST_OK);
        assert_q2_untouched();
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&Q2, snap, i));
        assert_q2_untouched();
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&Q2, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&Q2, snap_again, sizeof snap_again, &len2));
    TEST_ASSERT_EQUAL_size_t(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(snap, snap_again, len);
    for (k = 2600; k < 6000; ++k) {
        TEST_ASSERT_EQUAL_INT32(hyst_q31_step(&Q, codes[k]), hyst_q31_step(&Q2, codes[k]));
        TEST_ASSERT_EQUAL_INT32(hyst_q31_error_bound(&Q), hyst_q31_error_bound(&Q2));
    }
}

/* A deadband requested from another context skips reversals as a set one
 * does, on codes and in q31: the request binds the skip. */
static void test_requested_deadband_skips_as_a_set_one(void)
{
    static const uint_least32_t walk[] = {40000u, 39998u, 39999u, 39998u, 39999u, 39997u};
    static hyst_code_word_t cx[4][SNAP_CAP];
    static float cy[4][SNAP_CAP];
    hyst_t C1, C2;
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_q31(&paper_eq20, 0u, 65535u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_init(&Q2, &paper_eq20, 0u, 65535u, sx[0], sy[0],
                                                 sx[1], sy[1], SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&C1, &paper_eq20, 0u, 65535u, cx[0], cy[0],
                                                  cx[1], cy[1], SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&C2, &paper_eq20, 0u, 65535u, cx[2], cy[2],
                                                  cx[3], cy[3], SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_request_deadband(&Q, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_request_deadband(&C1, 3u));
    for (i = 0u; i < sizeof walk / sizeof walk[0]; ++i) {
        const hyst_q31_t q1 = hyst_q31_step(&Q, walk[i]), q2 = hyst_q31_step(&Q2, walk[i]);
        const float y1 = hyst_code_step(&C1, walk[i]), y2 = hyst_code_step(&C2, walk[i]);
        TEST_ASSERT_EQUAL_INT32(q1, q2);
        TEST_ASSERT_EQUAL_MEMORY(&y1, &y2, sizeof y1);
        if (i == 0u) { /* the requests apply at the end of the first sample */
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_set_deadband(&Q2, 3u));
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_set_deadband(&C2, 3u));
        }
    }
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&Q)); /* 40000 only: the rest skipped */
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&C1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_histories_agree_with_double);
    RUN_TEST(test_paper_signal_agrees_within_1e4_of_range);
    RUN_TEST(test_measured_drive_agrees_within_1e4_of_range);
    RUN_TEST(test_block_equals_step);
    RUN_TEST(test_scaling_and_monotone_sweeps);
    RUN_TEST(test_small_capacity_merges_stay_bounded);
    RUN_TEST(test_overflowing_curves_are_refused);
    RUN_TEST(test_snapshot_round_trips_bit_identically);
    RUN_TEST(test_bad_arguments_are_refused);
    RUN_TEST(test_requested_deadband_skips_as_a_set_one);
    return UNITY_END();
}
