/* SPDX-License-Identifier: MIT */
/* The q31 compensator (hyst/q31.h, "Compensator") against the exact inverse
 * in double (support/ref_tcm.c's inverse mode, bisection on f0, no library
 * code): the same TP counts at every sample, the drive within 1e-4 of its
 * range on random histories and the paper's signal, for Eq. 20, the curve
 * identified from tests/data and random increasing polynomials; next to
 * flat points of f0 (exact intervals) the round trip through the double
 * model instead; the model driven by the compensator's DAC codes gives the
 * desired output back; the drive monotone along sweeps; step and block
 * bit-identical; the refusals. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hyst/hyst.h"
#include "hyst_port.h"
#include "ref_tcm.h"
#include "signals.h"
#include "support.h"
#include "unity.h"

#define CAP 4096u
#define MAXN 20000L
#define Q31_INV_TOL 1e-4
#define INTERVALS 256u
#define Q_HALF ((hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1))

static hyst_q31_t cx[2][CAP], cy[2][CAP];
static hyst_code_word_t mx[2][CAP];
static hyst_q31_t my[2][CAP];
static hyst_q31_t table[HYST_Q31_INV_TABLE_LEN(1024u)]; /* the largest size tested */
static hyst_curve_t inv;
static hyst_t C, M;
static ref_tcm_t ref, fwd_ref;
static rng_t rng;
static hyst_q31_t desired[MAXN], drives[MAXN];
static double worst_rel, signals_rel;

/* The curve identified from tests/data/piezo_major_loop.dat (as
 * test_inverse_table.c): 0..3.6 V, output range ~45. */
static const hyst_poly_t piezo_fit = {3u, HYST_REAL_C(0.0), HYST_REAL_C(3.6),
                                      {HYST_WIDE_C(-0.00748403379), HYST_WIDE_C(1.48284291),
                                       HYST_WIDE_C(7.19181641), HYST_WIDE_C(-118.387864)}};

void setUp(void) { rng_seed(&rng, 3132u); }
void tearDown(void) {}

static hyst_status_t init_comp(const hyst_poly_t *f0, uint_least32_t lo, uint_least32_t hi,
                               size_t intervals, size_t cap)
{
    return hyst_q31_init_inverse_table(&C, &inv, f0, lo, hi, table, intervals, cx[0], cy[0],
                                       cx[1], cy[1], cap);
}

/* A drive (drive units) as an input of f0 (its domain). */
static double drive_real(const hyst_poly_t *f0, hyst_q31_t d)
{
    return (double)f0->lo +
           ((double)f0->hi - (double)f0->lo) * (double)d / (double)inv.u.inv_table.span.q31;
}

/* Runs desired[0..n) through C (fresh from init) and the exact inverse;
 * checks the TP counts at every sample and, unless `flat`, the drive
 * within 1e-4 of its range (flat: next to a flat point of f0 the inverse is
 * ill-conditioned, and the double model driven by the drive must give the
 * desired output back within 1e-4 of the output range instead). The worst
 * error in worst_rel. */
static void agree(const hyst_poly_t *f0, long n, int flat)
{
    double c[REF_MAX_DEGREE + 1];
    const double y_lo = (double)hyst_poly_eval(f0, f0->lo);
    const double y_hi = (double)hyst_poly_eval(f0, f0->hi);
    long i;
    unsigned k;
    for (k = 0u; k <= f0->degree; ++k) {
        c[k] = (double)f0->coeffs[k];
    }
    ref_init_inverse(&ref, c, f0->degree, (double)f0->lo, (double)f0->hi);
    ref_init(&fwd_ref, c, f0->degree, (double)f0->lo, (double)f0->hi);
    worst_rel = 0.0;
    for (i = 0; i < n; ++i) {
        /* the ends exactly: the rules compare them with the reference's */
        const double yd = desired[i] <= -Q_HALF ? ref.lo
                          : desired[i] >= Q_HALF ? ref.hi
                                                 : (double)hyst_q31_to_real(f0, desired[i]);
        const double d = drive_real(f0, hyst_q31_inv_step(&C, desired[i]));
        const double want = ref_step(&ref, yd);
        const double err = flat ? dabs(ref_step(&fwd_ref, d) - yd) / (y_hi - y_lo)
                                : dabs(d - want) / ((double)f0->hi - (double)f0->lo);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&C));
        TEST_ASSERT_EQUAL_INT32(ref_tp_count(&ref), (long)hyst_tp_count(&C));
        if (!(err <= Q31_INV_TOL)) {
            printf("sample %ld desired %ld (previous %ld): drive %.9g (%ld), exact %.9g, error %.3g\n", i,
                   (long)desired[i], i > 0 ? (long)desired[i - 1] : 0L, d, (long)hyst_q31_inv_output(&C), want, err);
            TEST_FAIL();
        }
        worst_rel = err > worst_rel ? err : worst_rel;
    }
}

/* desired[0..n) of a random history on 2^16 levels of the output range:
 * kind 0 walk, 1 jumps, 2 nested loops (alternating towards the last
 * extreme). */
static void random_desired(int kind, long n)
{
    const long levels = 65536L;
    long c = 0, centre = levels / 2, i;
    for (i = 0; i < n; ++i) {
        if (kind == 0) {
            c += (long)rng_below(&rng, (uint32_t)(levels / 25 + 1)) - levels / 50;
        } else if (kind == 1 || i % 97 == 0) {
            c = (long)rng_below(&rng, (uint32_t)(levels + 1));
        } else {
            const long prev = c;
            c += (long)((double)(centre - c) * rng_range(&rng, 0.05, 0.95));
            centre = prev;
        }
        c = c < 0 ? 0 : c > levels ? levels : c;
        desired[i] = (hyst_q31_t)(-Q_HALF + (hyst_q31_t)c * ((hyst_q31_t)1 << 12));
    }
}

/* Random histories and the paper's signal on 12- and 16-bit codes. */
static void histories(const hyst_poly_t *f0, const char *name, int flat)
{
    static const uint_least32_t his[2] = {4095u, 65535u};
    static hyst_real_t path[MAXN];
    int h, kind;
    long i;
    for (h = 0; h < 2; ++h) {
        for (kind = 0; kind < 4; ++kind) {
            TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(f0, 0u, his[h], INTERVALS, CAP));
            if (kind < 3) {
                random_desired(kind, 3000);
            } else {
                fill_signal(SIG_PAPER, &rng, -1.0, 1.0, path, 3000);
                for (i = 0; i < 3000; ++i) {
                    desired[i] = (hyst_q31_t)((double)path[i] * (double)Q_HALF);
                }
            }
            agree(f0, 3000, flat);
            if (!flat) {
                TEST_ASSERT_TRUE(worst_rel <= hyst_curve_inverse_error(&inv) * 8 + 1e-8);
            }
            signals_rel = !flat && worst_rel > signals_rel ? worst_rel : signals_rel;
        }
        printf("%s, codes 0..%lu: %u of %u intervals exact, init measured %.3g, last history "
               "%.3g of the %s range\n",
               name, (unsigned long)his[h], (unsigned)inv.u.inv_table.exact, INTERVALS,
               (double)hyst_curve_inverse_error(&inv), worst_rel, flat ? "output" : "drive");
    }
}

static void test_eq20_agrees_with_exact_inverse(void)
{
    histories(&paper_eq20, "Eq. 20", 0);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)inv.u.inv_table.exact);
}

static void test_identified_curve_agrees_with_exact_inverse(void)
{
    histories(&piezo_fit, "piezo fit", 0);
}

/* Random increasing polynomials of every degree (test_inverse.c's). */
static void test_random_polynomials_agree_with_exact_inverse(void)
{
    unsigned degree, rep;
    for (degree = 1u; degree <= HYST_MAX_DEGREE; ++degree) {
        for (rep = 0u; rep < 3u; ++rep) {
            const hyst_poly_t f = poly_random_increasing(&rng, degree);
            TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&f, 0u, 65535u, INTERVALS, CAP));
            random_desired((int)rep, 3000);
            agree(&f, 3000, 0);
            signals_rel = worst_rel > signals_rel ? worst_rel : signals_rel;
        }
    }
    printf("q31_inv_max_err_rel %.3g\n", signals_rel); /* bench/run's figure */
}

/* Flat points: x^3 and x^5 at 0 on [-1, 1], x^2 at lo on [0, 1]: the
 * intervals next to them are marked and solved exactly. */
static void test_flat_points_round_trip(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0), fifth = poly_monomial(5u, -1.0, 1.0);
    const hyst_poly_t square = poly_monomial(2u, 0.0, 1.0);
    histories(&cube, "x^3 on [-1, 1]", 1);
    TEST_ASSERT_TRUE(inv.u.inv_table.exact > 0u);
    if (SETUP_IN_FLOAT) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, init_comp(&fifth, 0u, 4095u, INTERVALS, CAP));
    } else {
        histories(&fifth, "x^5 on [-1, 1]", 1);
    }
    histories(&square, "x^2 on [0, 1]", 1);
    TEST_ASSERT_TRUE(inv.u.inv_table.exact > 0u);
}

/* The q31 model of the same f0 and codes, driven by the compensator's DAC
 * codes, gives the desired output back: within 1e-4 of the output range
 * plus the output half a code moves. */
static void test_model_of_compensator_is_identity(void)
{
    const double half_code = 0.5 * 40.0 / 4095.0 * 0.16; /* f0' <= 0.16 on [0, 40] */
    const double range = (double)hyst_poly_eval(&paper_eq20, paper_eq20.hi) -
                         (double)hyst_poly_eval(&paper_eq20, paper_eq20.lo);
    double worst = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_q31_init(&M, &paper_eq20, 0u, 4095u, mx[0], my[0], mx[1], my[1], CAP));
    TEST_ASSERT_EQUAL_UINT(16u, hyst_q31_inv_drive_bits(&C));
    random_desired(2, 5000);
    for (i = 0; i < 5000; ++i) {
        const uint_least32_t code = hyst_q31_inv_code(&C, hyst_q31_inv_step(&C, desired[i]));
        const hyst_q31_t y = hyst_q31_step(&M, code);
        const double err = dabs((double)(y - desired[i])) / (double)((hyst_q31_t)1 << 28);
        TEST_ASSERT_TRUE(code <= 4095u);
        worst = err > worst ? err : worst;
    }
    printf("model(compensator codes): worst |y - desired| %.3g of the range (half a code: %.3g)\n",
           worst, half_code / range);
    TEST_ASSERT_TRUE(worst <= Q31_INV_TOL + 2.0 * half_code / range);
}

/* Sweeps up and down the output range: the drive never steps back, and the
 * ends map onto the ends of the drive (codes code_lo and code_hi). */
static void test_drive_monotone_along_sweeps(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0);
    const hyst_poly_t *curves[3] = {&paper_eq20, &piezo_fit, &cube};
    int cv;
    for (cv = 0; cv < 3; ++cv) {
        hyst_q31_t prev, q;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(curves[cv], 100u, 4195u, INTERVALS, CAP));
        TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_output(&C));
        prev = 0;
        for (q = -Q_HALF; q <= Q_HALF; q += 4099) {
            const hyst_q31_t d = hyst_q31_inv_step(&C, q);
            TEST_ASSERT_TRUE(d >= prev);
            prev = d;
        }
        TEST_ASSERT_EQUAL_INT32(inv.y_hi.q31, hyst_q31_inv_step(&C, Q_HALF));
        TEST_ASSERT_EQUAL_UINT32(4195u, hyst_q31_inv_code(&C, hyst_q31_inv_output(&C)));
        prev = inv.y_hi.q31;
        for (q = Q_HALF; q >= -Q_HALF; q -= 3001) {
            const hyst_q31_t d = hyst_q31_inv_step(&C, q);
            TEST_ASSERT_TRUE(d <= prev);
            prev = d;
        }
        TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_step(&C, -Q_HALF));
        TEST_ASSERT_EQUAL_UINT32(100u, hyst_q31_inv_code(&C, 0));
    }
}

/* process() gives step()'s drives bit for bit (statuses folded), also on a
 * curve with exact intervals and with clamped inputs. */
static void test_block_equals_step(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0);
    const hyst_poly_t *curves[2] = {&paper_eq20, &cube};
    int cv;
    long i;
    for (cv = 0; cv < 2; ++cv) {
        random_desired(2, 4000);
        desired[1000] = Q_HALF + 5; /* clamped */
        desired[2000] = -Q_HALF;
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(curves[cv], 0u, 4095u, INTERVALS, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_q31_inv_process(&C, desired, drives, 4000u));
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(curves[cv], 0u, 4095u, INTERVALS, CAP));
        for (i = 0; i < 4000; ++i) {
            TEST_ASSERT_EQUAL_INT32(drives[i], hyst_q31_inv_step(&C, desired[i]));
        }
    }
}

/* Bounded memory: small arrays merge; the drive stays in its range, the
 * error bound saturates instead of overflowing; the deadband works in q. */
static void test_small_capacity_merges_stay_bounded(void)
{
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 65535u, INTERVALS, 4u));
    random_desired(2, 5000);
    for (i = 0; i < 5000; ++i) {
        const hyst_q31_t d = hyst_q31_inv_step(&C, desired[i]);
        TEST_ASSERT_TRUE(d >= -hyst_q31_rounding_bound(&C) * 8);
        TEST_ASSERT_TRUE(d <= inv.y_hi.q31 + hyst_q31_rounding_bound(&C) * 8);
        TEST_ASSERT_TRUE(hyst_q31_inv_error_bound(&C) >= 0);
        TEST_ASSERT_TRUE(hyst_q31_inv_error_bound(&C) <= HYST_Q31_BOUND_MAX + inv.y_hi.q31 * 3);
    }
    TEST_ASSERT_TRUE((hyst_events(&C) & HYST_EVENT_FULL) != 0u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_set_deadband(&C, (hyst_q31_t)1 << 16));
    for (i = 0; i < 2000; ++i) {
        (void)hyst_q31_inv_step(&C, desired[i]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_request_deadband(&C, 0));
    (void)hyst_q31_inv_step(&C, 0);
    TEST_ASSERT_EQUAL_INT32(0, C.deadband.q31);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_q31_inv_set_deadband(&C, -1));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_q31_inv_set_deadband(&C, ((hyst_q31_t)1 << 28) + 1));
}

/* Small tables: coarse pieces, more of them exact or measured worse, the
 * drive still within init's measured error; the define/init macros. */
static void test_table_sizes_and_macros(void)
{
    static const size_t sizes[4] = {1u, 5u, 32u, 1000u};
    int s;
    HYST_Q31_DEFINE_INVERSE(comp, 4096u);
    for (s = 0; s < 4; ++s) {
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, sizes[s], CAP));
        random_desired(1, 2000);
        agree(&paper_eq20, 2000, 0);
        printf("Eq. 20, %lu intervals: %u exact, init measured %.3g, history %.3g\n",
               (unsigned long)sizes[s], (unsigned)inv.u.inv_table.exact,
               (double)hyst_curve_inverse_error(&inv), worst_rel);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT_INVERSE(comp, &paper_eq20, 0u, 4095u));
    TEST_ASSERT_EQUAL_UINT((unsigned)HYST_INV_TABLE, (unsigned)comp_curve.u.inv_table.intervals);
    TEST_ASSERT_TRUE(hyst_q31_inv_step(&comp, 0) > 0);
}

/* Curves the model refuses are refused; arguments checked in the stated
 * order; nothing written on error. */
static void test_bad_arguments_are_refused(void)
{
    static const hyst_poly_t wild = {7u, 0.0, 1.0,
                                     {1.0, -3.5, 5.25, -4.375, 2.1875, -0.65625, 0.109375,
                                      -0.0078125}};
    unsigned char buf[512];
    size_t len = 0u;
    memset(&C, 0, sizeof C);
    memset(&inv, 0, sizeof inv);
    memset(table, 0, sizeof table);
    TEST_ASSERT_EQUAL_INT(SETUP_IN_FLOAT ? HYST_ERR_ILL_CONDITIONED : HYST_ERR_COEFF,
                          init_comp(&wild, 0u, 4095u, INTERVALS, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, init_comp(NULL, 0u, 4095u, INTERVALS, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_q31_init_inverse_table(&C, NULL, &paper_eq20, 0u, 4095u, table,
                                                      INTERVALS, cx[0], cy[0], cx[1], cy[1], CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_q31_init_inverse_table(&C, &inv, &paper_eq20, 0u, 4095u, NULL,
                                                      INTERVALS, cx[0], cy[0], cx[1], cy[1], CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_comp(&paper_eq20, 7u, 7u, INTERVALS, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN,
                          init_comp(&paper_eq20, 0u, HYST_CODE_MAX + 1u, INTERVALS, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, init_comp(&paper_eq20, 0u, 4095u, 0u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, init_comp(&paper_eq20, 0u, 4095u,
                                                  (size_t)HYST_Q31_INV_MAX_INTERVALS + 1u, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_q31_init_inverse_table(NULL, &inv, &paper_eq20, 0u, 4095u, table,
                                                      INTERVALS, cx[0], cy[0], cx[1], cy[1], CAP));
    TEST_ASSERT_EQUAL_UINT(0u, C.variant); /* nothing written */
    TEST_ASSERT_EQUAL_UINT(0u, inv.kind);
    TEST_ASSERT_EQUAL_INT32(0, table[0]);
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, CAP));
    /* the real variants' calls refuse its curve and instance */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_check(&inv));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_q31_set_deadband(&C, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_q31_inv_set_deadband(&M, 3));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_inv_set_deadband(NULL, 3));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_inv_request_deadband(NULL, 3));
    TEST_ASSERT_EQUAL_UINT32(0u, hyst_q31_inv_code(NULL, 5));
    TEST_ASSERT_EQUAL_UINT32(0u, hyst_q31_inv_code(&M, 5));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_q31_inv_drive_bits(NULL));
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_step(NULL, 5));
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_output(NULL));
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_input(NULL));
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_error_bound(NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_q31_inv_process(&C, NULL, drives, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_process(&C, NULL, NULL, 0u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE, hyst_snapshot_save(&C, buf, 8u, &len));
    /* a snapshot of the compensator restores into the compensator only */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C, buf, sizeof buf, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_init(&M, &paper_eq20, 0u, 4095u, mx[0], my[0], mx[1],
                                                 my[1], CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_snapshot_restore(&M, buf, len));
    /* requests and reset reach this variant's engine */
    (void)hyst_q31_inv_step(&C, 12345);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_request_reset(&C));
    (void)hyst_q31_inv_step(&C, 777);
    TEST_ASSERT_EQUAL_INT32(-Q_HALF, hyst_q31_inv_input(&C));
    (void)hyst_q31_inv_step(&C, 777);
    hyst_reset(&C);
    TEST_ASSERT_EQUAL_INT32(0, hyst_q31_inv_output(&C));
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&C));
}

/* Snapshots: the compensator restored from one (into an instance whose
 * table was built again from the same model: the same curve id) drives
 * bit for bit as the one saved, merged loops and an open deadband window
 * included; a damaged or truncated snapshot is refused with the instance
 * and its arrays untouched; another model's table is another curve. */
#define SNAP_CAP 48u
static hyst_q31_t sx[2][SNAP_CAP], sy[2][SNAP_CAP], sx_kept[2][SNAP_CAP], sy_kept[2][SNAP_CAP];
static hyst_q31_t table2[HYST_Q31_INV_TABLE_LEN(INTERVALS)];
static hyst_curve_t inv2;
static hyst_t C2, C2_kept;
static unsigned char snap[HYST_SNAPSHOT_SIZE(SNAP_CAP)], snap_again[HYST_SNAPSHOT_SIZE(SNAP_CAP)];
static unsigned char damaged[HYST_SNAPSHOT_SIZE(SNAP_CAP)];

static hyst_status_t init_comp2(const hyst_poly_t *f0)
{
    return hyst_q31_init_inverse_table(&C2, &inv2, f0, 0u, 4095u, table2, INTERVALS, sx[0],
                                       sy[0], sx[1], sy[1], SNAP_CAP);
}

static void assert_c2_untouched(void)
{
    TEST_ASSERT_EQUAL_MEMORY(&C2_kept, &C2, sizeof C2);
    TEST_ASSERT_EQUAL_MEMORY(sx_kept, sx, sizeof sx);
    TEST_ASSERT_EQUAL_MEMORY(sy_kept, sy, sizeof sy);
}

static void test_snapshot_round_trips_bit_identically(void)
{
    hyst_poly_t other = paper_eq20;
    size_t len = 0u, len2 = 0u, i;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_set_deadband(&C, 1 << 10));
    for (k = 0; k < MAXN && k < 6000L; ++k) { /* shrinking triangles: deep nests, wiped out */
        const long amp = 60000L - 35L * (k % 1700L);
        desired[k] = (hyst_q31_t)((k % 2L == 0L ? amp : -amp) * 2048L +
                                  (hyst_q31_t)rng_below(&rng, 1000u));
    }
    for (k = 0; k < 2600; ++k) {
        (void)hyst_q31_inv_step(&C, desired[k]);
    }
    TEST_ASSERT_TRUE((hyst_events(&C) & HYST_EVENT_FULL) != 0u); /* loops were merged */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_size_t(hyst_snapshot_size(&C), len);
    other.coeffs[1] = other.coeffs[1] * HYST_REAL_C(1.001);
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp2(&other));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&C2, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp2(&paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_set_deadband(&C2, 1 << 10));
    (void)hyst_q31_inv_step(&C2, 12345);
    memcpy(&C2_kept, &C2, sizeof C2);
    memcpy(sx_kept, sx, sizeof sx);
    memcpy(sy_kept, sy, sizeof sy);
    for (i = 0u; i < len; ++i) { /* one bit of every octet; every truncation */
        memcpy(damaged, snap, len);
        damaged[i] = (unsigned char)(damaged[i] ^ (1u << (i % 8u)));
        TEST_ASSERT_TRUE(hyst_snapshot_restore(&C2, damaged, len) != HYST_OK);
        assert_c2_untouched();
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&C2, snap, i));
        assert_c2_untouched();
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&C2, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C2, snap_again, sizeof snap_again, &len2));
    TEST_ASSERT_EQUAL_size_t(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(snap, snap_again, len);
    for (k = 2600; k < 6000; ++k) {
        TEST_ASSERT_EQUAL_INT32(hyst_q31_inv_step(&C, desired[k]),
                                hyst_q31_inv_step(&C2, desired[k]));
        TEST_ASSERT_EQUAL_INT32(hyst_q31_inv_error_bound(&C), hyst_q31_inv_error_bound(&C2));
    }
}

/* Turning points 2 q apart near the top of the range, where a float holds
 * only multiples of 8 q: restored exactly, and the two instances go on
 * alike (set-up in float, HYST_NO_DOUBLE, once refused such a snapshot). */
static void test_close_turning_points_restore(void)
{
    const hyst_q31_t top = Q_HALF - 1000;
    size_t len = 0u, len2 = 0u;
    hyst_q31_t k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp2(&paper_eq20));
    (void)hyst_q31_inv_step(&C, top - 200);
    for (k = 0; k < 8; ++k) { /* nested loops: TPs top - 2k and top - 100 + 2k */
        (void)hyst_q31_inv_step(&C, top - 2 * k);
        (void)hyst_q31_inv_step(&C, top - 100 + 2 * k);
    }
    TEST_ASSERT_TRUE(hyst_tp_count(&C) >= 14u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&C2, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C2, snap_again, sizeof snap_again, &len2));
    TEST_ASSERT_EQUAL_size_t(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(snap, snap_again, len);
    for (k = 0; k < 40; ++k) {
        const hyst_q31_t d = top - 60 + 3 * (k % 7) - 2 * (k % 3);
        TEST_ASSERT_EQUAL_INT32(hyst_q31_inv_step(&C, d), hyst_q31_inv_step(&C2, d));
    }
}

/* A deadband requested from another context skips reversals as a set one
 * does: the request binds the skip. */
static void test_requested_deadband_skips_as_a_set_one(void)
{
    static const hyst_q31_t walk[] = {40000L * 2048L, 39990L * 2048L, 39995L * 2048L,
                                      39991L * 2048L, 39994L * 2048L, 39980L * 2048L};
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp(&paper_eq20, 0u, 4095u, INTERVALS, SNAP_CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_comp2(&paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_request_deadband(&C, 1 << 16));
    for (i = 0u; i < sizeof walk / sizeof walk[0]; ++i) {
        TEST_ASSERT_EQUAL_INT32(hyst_q31_inv_step(&C2, walk[i]), hyst_q31_inv_step(&C, walk[i]));
        if (i == 0u) { /* the request applies at the end of the first sample */
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_set_deadband(&C2, 1 << 16));
        }
    }
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&C)); /* the first only: the rest skipped */
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&C2));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_eq20_agrees_with_exact_inverse);
    RUN_TEST(test_identified_curve_agrees_with_exact_inverse);
    RUN_TEST(test_random_polynomials_agree_with_exact_inverse);
    RUN_TEST(test_flat_points_round_trip);
    RUN_TEST(test_model_of_compensator_is_identity);
    RUN_TEST(test_drive_monotone_along_sweeps);
    RUN_TEST(test_block_equals_step);
    RUN_TEST(test_small_capacity_merges_stay_bounded);
    RUN_TEST(test_table_sizes_and_macros);
    RUN_TEST(test_snapshot_round_trips_bit_identically);
    RUN_TEST(test_close_turning_points_restore);
    RUN_TEST(test_bad_arguments_are_refused);
    RUN_TEST(test_requested_deadband_skips_as_a_set_one);
    return UNITY_END();
}
