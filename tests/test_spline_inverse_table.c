/* SPDX-License-Identifier: MIT */
/* The spline kind's tabulated compensator (curve.h,
 * hyst_*_curve_spline_inverse_table()): on random monotone splines, zero
 * slopes at knots included (the intervals next to them, and around knots,
 * evaluated exactly), under drives of nested minor loops, its drive
 * against the solved compensator's (hyst_curve_spline_inverse()) and the
 * model driven by it against the desired output; the exact intervals
 * counted and exercised; the block call, snapshots, the refusals with
 * nothing written, forged curves refused by the init, and the way back to
 * the spline. */
#include "support.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define CAP 256
#define SAMPLES 4000L
#define TABLE HYST_INV_TABLE_LEN(HYST_INV_TABLE)
#define FWD_TABLE HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t xl3[CAP], yl3[CAP], xr3[CAP], yr3[CAP];
static hyst_real_t xl4[CAP], yl4[CAP], xr4[CAP], yr4[CAP];
static hyst_real_t ys[SAMPLES], out_step[SAMPLES], out_block[SAMPLES];
static hyst_real_t table[TABLE], table2[TABLE], fwd_table[FWD_TABLE], fwd_table2[FWD_TABLE];
static unsigned char snap[HYST_SNAPSHOT_SIZE(CAP)];
static hyst_curve_t fwd, solved, tab, tab2;
static hyst_t T, C, M, M2;
static rng_t rng;

#ifdef HYST_USE_DOUBLE
#define EPS 2.220446049250313e-16
#else
#define EPS 1.1920928955078125e-7
#endif

/* The table's error is measured at 15 points an interval: between them it
 * was found up to 1.3 % above theirs; a quarter is allowed. */
#define BETWEEN_PROBES 1.25

void setUp(void) { rng_seed(&rng, 2718u); }
void tearDown(void) {}

/* A random increasing spline without a flat piece, a sixth of its pieces
 * near steps, a quarter of its slopes 0 when `zeros` (there f0^-1 has an
 * infinite slope; support.h). */
static hyst_spline_t random_spline(unsigned intervals, int zeros)
{
    return spline_random(&rng, intervals, 0, 1, zeros);
}

/* The steepest slope of f0, output per drive: bounds what a drive error
 * costs the model's output (a piece's slope is a quadratic in t, largest
 * at an end or at its vertex). */
static double steepest(const hyst_spline_t *f)
{
    const double h = (double)(f->hi - f->lo) / f->intervals;
    double worst = 0.0;
    unsigned k;
    for (k = 0u; k < f->intervals; ++k) {
        const double rise = f->value[k + 1u] - f->value[k];
        const double m0 = h * f->slope[k], m1 = h * f->slope[k + 1u];
        const double c2 = 3.0 * rise - 2.0 * m0 - m1, c3 = m0 + m1 - 2.0 * rise;
        double s = m0 > m1 ? m0 : m1;
        if (c3 < 0.0 && c2 > 0.0 && c2 < -3.0 * c3) { /* a maximum inside */
            const double t = -c2 / (3.0 * c3);
            const double v = m0 + t * (2.0 * c2 + 3.0 * c3 * t);
            s = v > s ? v : s;
        }
        worst = s / h > worst ? s / h : worst;
    }
    return worst;
}

/* Desired outputs on [lo, hi]: runs of nested minor loops (reversals
 * closing in on a random point, then opening out past them: wipe-outs),
 * ramps of random steps between the reversals, now and then an end or
 * beyond it (clamped). */
static void nested_loops(double lo, double hi, hyst_real_t *y, long n)
{
    double v = lo;
    long k = 0;
    while (k < n) {
        const double centre = rng_range(&rng, lo, hi);
        const int levels = 2 + (int)rng_below(&rng, 8u);
        double width = rng_range(&rng, 0.3, 1.0) * (hi - lo);
        int i;
        for (i = 0; i < 2 * levels && k < n; ++i) {
            const double step = rng_range(&rng, 0.002, 0.03) * (hi - lo);
            double target = centre + (i % 2 == 0 ? 0.5 : -0.5) * width;
            width *= i < levels ? rng_range(&rng, 0.3, 0.9) : rng_range(&rng, 1.2, 2.5);
            if (rng_below(&rng, 10u) == 0u) {
                target = rng_below(&rng, 2u) ? lo - 1.0 : hi + 1.0;
            }
            while (k < n) {
                const double to = target < lo ? lo : target > hi ? hi : target;
                v = v < to ? (v + step < to ? v + step : to) : (v - step > to ? v - step : to);
                y[k++] = (hyst_real_t)(v == to ? target : v);
                if (v == to) {
                    break;
                }
            }
        }
    }
}

/* The forward curve, the solved and the tabulated compensators of f. */
static void prepare(const hyst_spline_t *f, size_t intervals)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&fwd, f, fwd_table, FWD_TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&solved, &fwd));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse_table(&tab, &fwd, table, intervals));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_SPLINE_INV_TABLE, (int)tab.kind);
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&tab) >= 0);
}

/* The table's error in drive units, and the bounds of a sample with d
 * turning points stacked: each carries the error of the branch it ended
 * (its drive), so d + 1 errors add up, each of them the table's (with its
 * margin between the probes) and the drive's roundings; in the model's
 * output, times f0's steepest slope, and the output's roundings. */
typedef struct {
    double err, slope, ends, scale;
} bounds_t;

static bounds_t bounds_of(const hyst_spline_t *f)
{
    bounds_t b;
    const double span = f->hi - f->lo, range = f->value[f->intervals] - f->value[0];
    b.err = BETWEEN_PROBES * (double)hyst_curve_inverse_error(&tab) * span;
    b.slope = steepest(f);
    b.ends = fmax(fabs(f->lo), fabs(f->hi)) + span;
    b.scale = fabs(f->value[0]) + fabs(f->value[f->intervals]) + range;
    return b;
}

static double drive_tol(const bounds_t *b, double d)
{
    return (d + 1.0) * (b->err + 16.0 * EPS * b->ends);
}

static double output_tol(const bounds_t *b, double d)
{
    return (d + 1.0) * (b->slope * (b->err + 16.0 * EPS * b->ends) + 16.0 * EPS * b->scale);
}

static long n_samples, n_ill;
static double worst_drive, worst_out;

/* One desired output y into the tabulated compensator T and the solved
 * one C, their drives into the models M and M2. The model driven by T
 * gives y back within output_tol(); T's drive is C's within drive_tol(),
 * or, where the drive is ill-conditioned in the output (next to a knot of
 * slope 0 a rounding of the output moves the exact drive by its square
 * root; a small slope magnifies where C stops within its cubic's
 * rounding), both drives give y back within output_tol(). */
static void compare(const bounds_t *b, hyst_real_t y)
{
    const double dt = (double)hyst_step(&T, y), ds = (double)hyst_step(&C, y);
    const double mt = (double)hyst_step(&M, (hyst_real_t)dt);
    const double ms = (double)hyst_step(&M2, (hyst_real_t)ds);
    const size_t tps = hyst_tp_count(&T) > hyst_tp_count(&C) ? hyst_tp_count(&T) : hyst_tp_count(&C);
    const double d = (double)tps;
    const hyst_real_t lo = tab.lo.HYST_R, hi = tab.hi.HYST_R;
    const double yc = (double)(y < lo ? lo : y > hi ? hi : y); /* clamped */
    const double tol_y = output_tol(b, d);
    TEST_ASSERT_TRUE_MESSAGE(fabs(mt - yc) <= tol_y, "the model driven by the table misses");
    worst_out = fmax(worst_out, fabs(mt - yc) / tol_y);
    if (fabs(dt - ds) <= drive_tol(b, d)) {
        worst_drive = fmax(worst_drive, fabs(dt - ds) / drive_tol(b, d));
    } else {
        TEST_ASSERT_TRUE_MESSAGE(fabs(ms - yc) <= tol_y,
                                 "the drives differ where the output is not flat");
        ++n_ill;
    }
    ++n_samples;
}

static void init_all(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &tab, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &solved, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&M, &fwd, xl3, yl3, xr3, yr3, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&M2, &fwd, xl4, yl4, xr4, yr4, CAP));
}

/* Random splines (two in three with zero slopes), tables of 1 to
 * HYST_INV_TABLE intervals, every sample of nested loops. */
static void test_against_the_solved_compensator(void)
{
    static const size_t counts[] = {1u, 5u, 16u, 64u, HYST_INV_TABLE};
    unsigned long exact = 0u;
    int trial;
    for (trial = 0; trial < 60; ++trial) {
        const hyst_spline_t f =
            random_spline(1u + rng_below(&rng, HYST_SPLINE_MAX_INTERVALS), trial % 3 != 0);
        bounds_t b;
        long k;
        prepare(&f, counts[rng_below(&rng, 5u)]);
        exact += (unsigned long)tab.u.inv_table.exact;
        b = bounds_of(&f);
        init_all();
        nested_loops(f.value[0], f.value[f.intervals], ys, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            compare(&b, ys[k]);
        }
    }
    printf("%ld samples of nested loops: worst drive %.3g of its bound, model's output %.3g; "
           "%ld ill-conditioned; %lu intervals evaluated exactly\n",
           n_samples, worst_drive, worst_out, n_ill, exact);
    TEST_ASSERT_TRUE(exact > 0u);
}

/* A spline flat at its middle knot and at lo (x^3-like, and x^2-like),
 * tabulated coarsely: the intervals next to those knots are evaluated
 * exactly. Up the whole range from reset and down again, on a fine grid:
 * the samples in marked intervals counted, each compared as above;
 * G^-1(0) = 0, and a descent to y_lo drives lo. */
static void test_exact_intervals_exercised(void)
{
    static const hyst_spline_t flat = {4, -2.0, 2.0, {-3.0, -1.0, 0.0, 1.0, 4.0},
                                       {0.0, 1.5, 0.0, 1.5, 4.0}};
    bounds_t b;
    long k, in_exact = 0, n = 20000;
    int pass;
    prepare(&flat, 16u);
    TEST_ASSERT_TRUE(tab.u.inv_table.exact > 0u);
    b = bounds_of(&flat);
    init_all();
    for (pass = 0; pass < 2; ++pass) {
        for (k = 0; k <= n; ++k) {
            const double e =
                (flat.value[4] - flat.value[0]) * (double)(pass == 0 ? k : n - k) / (double)n;
            const hyst_real_t y = (hyst_real_t)(flat.value[0] + e);
            const double s = (double)((y - tab.lo.HYST_R) * tab.unit.HYST_R);
            const unsigned long j = s < 0 ? 0ul : (unsigned long)s;
            if (pass == 0 && j < 16ul && table[4u * j] < 0) { /* from reset: G^-1 itself */
                ++in_exact;
            }
            compare(&b, y);
        }
    }
    printf("flat knots: %u of 16 intervals exact, %ld samples in them\n",
           (unsigned)tab.u.inv_table.exact, in_exact);
    TEST_ASSERT_TRUE(in_exact > 100);
    TEST_ASSERT_TRUE(hyst_curve_g(&tab, 0) == 0);
    TEST_ASSERT_TRUE(hyst_step(&T, tab.lo.HYST_R - 1) == fwd.lo.HYST_R);
    TEST_ASSERT_TRUE(hyst_step(&M, fwd.lo.HYST_R) == fwd.y_lo.HYST_R);
}

/* The block call gives step()'s drives bit for bit, on splines with exact
 * intervals. */
static void test_block_equals_step(void)
{
    int trial;
    for (trial = 0; trial < 8; ++trial) {
        const hyst_spline_t f = random_spline(4u + rng_below(&rng, 28u), 1);
        long k;
        prepare(&f, trial % 2 == 0 ? 8u : HYST_INV_TABLE);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &tab, xl, yl, xr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &tab, xl2, yl2, xr2, yr2, CAP));
        nested_loops(f.value[0], f.value[f.intervals], ys, SAMPLES);
        for (k = 0; k < SAMPLES; ++k) {
            out_step[k] = hyst_step(&T, ys[k]);
        }
        TEST_ASSERT_TRUE(hyst_process(&C, ys, out_block, (size_t)SAMPLES) >= 0); /* clamped ends */
        TEST_ASSERT_EQUAL_MEMORY(out_step, out_block, sizeof out_step);
    }
}

/* A snapshot restores into an instance of the same tables (other storage,
 * the same numbers) and continues bit for bit; an instance whose inverse
 * table or forward spline's table differs refuses it, and so does the
 * solved compensator. */
static void test_snapshot_round_trip(void)
{
    const hyst_spline_t f = random_spline(12u, 1);
    const long half = SAMPLES / 2;
    size_t len;
    long k;
    prepare(&f, 32u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &tab, xl, yl, xr, yr, CAP));
    nested_loops(f.value[0], f.value[f.intervals], ys, SAMPLES);
    for (k = 0; k < half; ++k) {
        (void)hyst_step(&T, ys[k]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&T, snap, sizeof snap, &len));
    memcpy(fwd_table2, fwd_table, sizeof fwd_table);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse_table(&tab2, &fwd, table2, 32u));
    tab2.u.inv_table.fwd_spline.table.HYST_R = fwd_table2;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &tab2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&C, snap, len));
    for (k = half; k < SAMPLES; ++k) {
        const hyst_real_t a = hyst_step(&T, ys[k]), b = hyst_step(&C, ys[k]);
        TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
    }
    /* the forward spline's pieces differ in one number, as the exact
     * intervals read them */
    fwd_table2[5] = NEXT(fwd_table2[5], REAL_INF);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &tab2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&C, snap, len));
    /* another inverse table of the same spline */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse_table(&tab2, &fwd, table2, 33u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &tab2, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&C, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&C, &solved, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&C, snap, len));
}

/* One refusal: its status, the curve and the table unwritten. */
static void refused(hyst_status_t want, const hyst_curve_t *from, size_t intervals)
{
    hyst_curve_t out;
    memset(&out, 0x5a, sizeof out);
    table[0] = (hyst_real_t)123.0;
    TEST_ASSERT_EQUAL_INT(want, hyst_curve_spline_inverse_table(&out, from, table, intervals));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&out)[0]);
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&out)[sizeof out - 1u]);
    TEST_ASSERT_TRUE(table[0] == (hyst_real_t)123.0);
}

/* The constructor's refusals, in the polynomial's order, none writing. */
static void test_refusals_write_nothing(void)
{
    static const hyst_spline_t good = {2, 0.0, 1.0, {0.0, 0.625, 2.0}, {1.0, 1.75, 4.0}};
    static const hyst_spline_t flat = {3, 0.0, 3.0, {0.0, 1.0, 1.0, 2.0}, {1.0, 0.0, 0.0, 1.0}};
    static const hyst_poly_t p = {3, 0.0, 1.0, {1.0, 0.0, 1.0, 0.0}};
#ifdef HYST_USE_DOUBLE
    static const hyst_spline_t tiny = {1, 0.0, 1.0, {0.0, 1e-320}, {1e-320, 1e-320}};
#else
    static const hyst_spline_t tiny = {
        1, 0.0, 1.0, {0.0, HYST_WIDE_C(1e-42)}, {HYST_WIDE_C(1e-42), HYST_WIDE_C(1e-42)}};
#endif
    hyst_curve_t c, out;
    prepare(&good, 8u);
    memset(&out, 0x5a, sizeof out);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_spline_inverse_table(NULL, &fwd, table, 8u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_spline_inverse_table(&out, NULL, table, 8u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_spline_inverse_table(&out, &fwd, NULL, 8u));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&out)[0]);
    c = fwd;
    c.layout ^= 1ul;
    refused(HYST_ERR_LAYOUT, &c, 8u);
#if HYST_ENABLE_F64 && !defined(HYST_USE_DOUBLE)
    {
        static double t64[HYST_SPLINE_TABLE_LEN(2u)];
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_f64_curve_from_spline(&c, &good, t64, HYST_SPLINE_TABLE_LEN(2u)));
        refused(HYST_ERR_LAYOUT, &c, 8u); /* a double spline for a float table */
    }
#endif
    refused(HYST_ERR_ARG, &fwd, 0u);
    refused(HYST_ERR_ARG, &fwd, ((size_t)1 << 20) + 1u);
    refused(HYST_ERR_ARG, &solved, 8u);
    refused(HYST_ERR_ARG, &tab, 8u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&c, &p));
    refused(HYST_ERR_ARG, &c, 8u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&c, &flat, fwd_table2, FWD_TABLE));
    refused(HYST_ERR_NOT_INVERTIBLE, &c, 8u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&c, &tiny, fwd_table2, FWD_TABLE));
    refused(HYST_ERR_ILL_CONDITIONED, &c, HYST_INV_TABLE);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&out, &c)); /* the solved one does */
    /* what takes any prepared curve has nothing for the kind */
    memset(&out, 0x5a, sizeof out);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_check(&tab));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse(&out, &tab));
    TEST_ASSERT_EQUAL_UINT(0x5au, ((unsigned char *)&out)[0]);
    {
        hyst_table_seal_t seal;
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_table_seal(&tab, &seal));
    }
}

/* The init refuses a forged curve (no table, no forward pieces, counts out
 * of range) with HYST_ERR_ARG; the compensator's inverse is the spline,
 * number for number (in place too), and reports the table's error. */
static void test_forged_curves_and_the_way_back(void)
{
    static const hyst_spline_t good = {2, 0.0, 1.0, {0.0, 0.625, 2.0}, {1.0, 1.75, 4.0}};
    hyst_curve_t c;
    prepare(&good, 8u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&T, &tab, xl, yl, xr, yr, CAP));
    c = tab;
    c.u.inv_table.table.HYST_R = NULL;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_curve(&T, &c, xl, yl, xr, yr, CAP));
    c = tab;
    c.u.inv_table.intervals = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_curve(&T, &c, xl, yl, xr, yr, CAP));
    c = tab;
    c.u.inv_table.fwd_spline.table.HYST_R = NULL;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_curve(&T, &c, xl, yl, xr, yr, CAP));
    c = tab;
    c.u.inv_table.fwd_spline.intervals = HYST_SPLINE_MAX_INTERVALS + 1u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_curve(&T, &c, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_spline_inverse(&c, &c));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&c, &tab));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_SPLINE, (int)c.kind);
    TEST_ASSERT_TRUE(c.lo.HYST_R == fwd.lo.HYST_R && c.hi.HYST_R == fwd.hi.HYST_R &&
                     c.y_lo.HYST_R == fwd.y_lo.HYST_R && c.y_hi.HYST_R == fwd.y_hi.HYST_R &&
                     c.unit.HYST_R == fwd.unit.HYST_R && c.rounding.HYST_R == fwd.rounding.HYST_R);
    TEST_ASSERT_TRUE(c.u.spline.table.HYST_R == fwd_table && c.u.spline.intervals == 2u &&
                     c.u.spline.span.HYST_R == fwd.u.spline.span.HYST_R);
    c = tab;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&c, &c));
    TEST_ASSERT_TRUE(c.kind == fwd.kind && c.unit.HYST_R == fwd.unit.HYST_R);
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&tab) == tab.u.inv_table.max_err);
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&tab) > 0 &&
                     hyst_curve_inverse_error(&tab) <= HYST_INV_TABLE_TOL + 4 * EPS);
}

#ifndef HYST_USE_DOUBLE
/* The code variant runs the table too: desired outputs as 4096 codes, up
 * the whole range, against the solved compensator within the table's
 * error (from reset: one branch). */
static void test_code_variant_runs_the_table(void)
{
    static hyst_code_word_t cl[CAP], cr[CAP];
    static const hyst_spline_t f = {4, -2.0, 2.0, {-3.0, -1.0, 0.0, 1.0, 4.0},
                                    {1.0, 1.5, 0.5, 1.5, 4.0}};
    double worst = 0.0;
    long i;
    prepare(&f, 64u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&T, &tab, 0u, 4095u, cl, yl, cr, yr, CAP));
    for (i = 0; i <= 4095; ++i) {
        const double d = (double)hyst_code_step(&T, (uint_least32_t)i);
        const double range = (double)tab.hi.f32 - (double)tab.lo.f32;
        const double y = (double)tab.lo.f32 + range * (double)i / 4095.0;
        const double want = (double)hyst_f32_curve_eval(&solved, (float)y);
        worst = fmax(worst, fabs(d - want) / 4.0); /* the drive span */
    }
    printf("code variant, 4096 codes: worst drive error / drive range %.3g (reported %.3g)\n", worst,
           (double)hyst_curve_inverse_error(&tab));
    TEST_ASSERT_TRUE(worst <= BETWEEN_PROBES * (double)hyst_curve_inverse_error(&tab) + 16.0 * EPS);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&T));
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_against_the_solved_compensator);
    RUN_TEST(test_exact_intervals_exercised);
    RUN_TEST(test_block_equals_step);
    RUN_TEST(test_snapshot_round_trip);
    RUN_TEST(test_refusals_write_nothing);
    RUN_TEST(test_forged_curves_and_the_way_back);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_code_variant_runs_the_table);
#endif
    return UNITY_END();
}
