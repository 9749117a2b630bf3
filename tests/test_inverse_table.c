/* SPDX-License-Identifier: MIT */
/* The tabulated compensator (curve.h, hyst_*_curve_inverse_table()): its
 * error against the exact inverse (bisection in double) on Eq. 20, on the
 * curve identified from tests/data, on random increasing polynomials and at
 * flat points of f0; the drive along long sweeps; snapshots, the block call
 * and the code variant; the constructor's checks. */
#include "signals.h"
#include "support.h"
#include "unity.h"
#include "hyst_port.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define CAP 4096
#define SAMPLES 50000L
/* The promise: worst drive error / drive range with the default table. */
#define PROMISE 1e-5
/* Drive steps backwards along a sweep, at most, in units of the drive range:
 * the pieces are monotone in exact arithmetic, and where two meet the
 * rounding of one cubic can step back by a few units in the last place. */
#ifdef HYST_USE_DOUBLE
#define BACKSTEP 1e-14
#else
#define BACKSTEP 5e-7
#endif

static hyst_real_t table[HYST_INV_TABLE_LEN(HYST_INV_TABLE)];
static hyst_real_t table2[HYST_INV_TABLE_LEN(HYST_INV_TABLE)];
static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t il[CAP], jl[CAP], ir[CAP], jr[CAP];
static hyst_real_t sig[SAMPLES], out_step[SAMPLES], out_block[SAMPLES];
static hyst_t H, K;
static hyst_curve_t fwd, inv, inv2;
static rng_t rng;

/* The curve identified from tests/data/piezo_major_loop.dat as test_ident.c
 * fits it (joint, degree 3, rows 350..4150, lag 1; printed by that test):
 * 0..3.6 V, output range ~45. */
static const hyst_poly_t piezo_fit = {3u, HYST_REAL_C(0.0), HYST_REAL_C(3.6),
                                      {HYST_WIDE_C(-0.00748403379), HYST_WIDE_C(1.48284291),
                                       HYST_WIDE_C(7.19181641), HYST_WIDE_C(-118.387864)}};

void setUp(void) { rng_seed(&rng, 4242u); }
void tearDown(void) {}

/* G of the forward curve, in double, from the coefficients the samples use. */
static double fwd_g(const hyst_curve_poly_t *p, double u)
{
    double acc = (double)p->a[0].HYST_R;
    unsigned i;
    for (i = 1u; i < p->degree; ++i) {
        acc = acc * u + (double)p->a[i].HYST_R;
    }
    return acc * u;
}

/* The exact inverse: the drive step d for an output step e, by bisection. */
static double exact_d(const hyst_curve_t *c, double e)
{
    double a = 0.0, b = 1.0;
    int it;
    for (it = 0; it < 200; ++it) {
        const double m = 0.5 * (a + b);
        if (!(m > a && m < b)) {
            break;
        }
        if (fwd_g(&c->u.inv_table.fwd, m) < e) {
            a = m;
        } else {
            b = m;
        }
    }
    return 0.5 * (a + b) * (double)c->u.inv_table.span.HYST_R;
}

static double range_of(const hyst_curve_t *c) { return (double)(c->hi.HYST_R - c->lo.HYST_R); }

/* Next to a flat point of f0 the inverse is ill-conditioned: one rounding
 * of e moves the exact drive by ~eps^(1/3) (x^3). There the drive counts as
 * right if it solves f0 for an e within the rounding of the variant:
 * |G(d) - e| / range <= FLAT_RESIDUAL (test_inverse.c's bound). */
#ifdef HYST_USE_DOUBLE
#define FLAT_RESIDUAL 1e-14
#else
#define FLAT_RESIDUAL 2e-6
#endif
static int near_flat; /* the curve under test has a flat point */

/* |table - exact| / span at output step e (rounded to the variant first);
 * with near_flat, 0 where the output residual meets FLAT_RESIDUAL. */
static double error_at(const hyst_curve_t *c, double e)
{
    const hyst_real_t er = (hyst_real_t)e;
    const double d = (double)hyst_curve_g(c, er);
    const double span = (double)c->u.inv_table.span.HYST_R;
    const double err = dabs(d - exact_d(c, (double)er)) / span;
    if (near_flat && err > PROMISE) {
        const double res = dabs(fwd_g(&c->u.inv_table.fwd, d / span) - (double)er) / range_of(c);
        TEST_ASSERT_TRUE(res <= FLAT_RESIDUAL);
        return 0.0;
    }
    return err;
}

/* Worst error over 16 points per interval, as many random points and 2^-1 .. 2^-40
 * of the range near e_flat (a flat point's output step) and the ends. */
static double table_error(const hyst_poly_t *f0, double e_flat_of_range, const char *name)
{
    double worst = 0.0, tiny = 1.0, range, err;
    long k, n;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, f0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&inv, &fwd, table, HYST_INV_TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_INV_TABLE, inv.kind);
    range = range_of(&inv);
    n = 16L * (long)HYST_INV_TABLE;
    for (k = 0; k <= 2 * n; ++k) {
        const double e = k <= n ? range * (double)k / (double)n : rng_range(&rng, 0.0, range);
        err = error_at(&inv, e);
        worst = err > worst ? err : worst;
    }
    for (k = 0; k < 40; ++k) {
        const double flat = e_flat_of_range * range;
        tiny *= 0.5;
        err = error_at(&inv, range * tiny);
        worst = err > worst ? err : worst;
        err = error_at(&inv, range * (1.0 - tiny));
        worst = err > worst ? err : worst;
        if (flat > 0.0) {
            err = error_at(&inv, flat * (1.0 - tiny));
            worst = err > worst ? err : worst;
            err = error_at(&inv, flat + (range - flat) * tiny);
            worst = err > worst ? err : worst;
        }
    }
    printf("%s: %d intervals, %u exact: worst error / drive range %.3g (init measured %.3g)\n",
                name, HYST_INV_TABLE, (unsigned)inv.u.inv_table.exact, worst,
                (double)hyst_curve_inverse_error(&inv));
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&inv) <= PROMISE);
    return worst;
}

static void test_error_on_eq20(void)
{
    TEST_ASSERT_TRUE(table_error(&paper_eq20, 0.0, "Eq. 20") <= PROMISE);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)inv.u.inv_table.exact); /* f0' > 0: all inline */
}

static void test_error_on_identified_curve(void)
{
    TEST_ASSERT_TRUE(table_error(&piezo_fit, 0.0, "piezo fit") <= PROMISE);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)inv.u.inv_table.exact);
}

/* Random increasing polynomials of every degree, as test_inverse.c draws
 * them: positive coefficients on [lo, lo + 1..4000]. */
static void test_error_on_random_increasing_polynomials(void)
{
    unsigned degree, rep;
    for (degree = 1u; degree <= HYST_MAX_DEGREE; ++degree) {
        for (rep = 0u; rep < 3u; ++rep) {
            const hyst_poly_t f = poly_random_increasing(&rng, degree);
            TEST_ASSERT_TRUE(table_error(&f, 0.0, "random") <= PROMISE);
        }
    }
}

/* Domains far from 0 relative to their span ([1000, 1010] to [500000,
 * 500010]): the drive adds the table's drive step to its turning point's
 * drive, and in float that sum rounds to 1/32 at 500000, 3 000 times the
 * pieces' error, which init did not count. The compensator from reset, up
 * the whole output range: every drive within the error reported of the
 * exact inverse of the model's own G. */
static void test_offset_domains_within_the_reported_error(void)
{
    static const double offsets[4] = {1000.0, 20000.0, 131072.0, 500000.0};
    unsigned i;
    for (i = 0u; i < 4u; ++i) {
        const double off = offsets[i];
        hyst_poly_t f;
        double worst = 0.0, allowed, span;
        long k;
        memset(&f, 0, sizeof f);
        f.degree = 2u; /* 0.5 t + 0.02 t^2, t = x - off */
        f.lo = (hyst_wide_t)off;
        f.hi = (hyst_wide_t)(off + 10.0);
        f.coeffs[0] = HYST_WIDE_C(0.02);
        f.coeffs[1] = (hyst_wide_t)(0.5 - 0.04 * off);
        f.coeffs[2] = (hyst_wide_t)(0.02 * off * off - 0.5 * off);
        if (SETUP_IN_FLOAT) {
            TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_curve_from_poly(&fwd, &f));
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &f));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&inv, &fwd, table, HYST_INV_TABLE));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&K, &inv, il, jl, ir, jr, CAP));
        span = (double)inv.u.inv_table.span.HYST_R;
        allowed = (double)hyst_curve_inverse_error(&inv) * span;
        for (k = 1; k <= 4000L; ++k) {
            const hyst_real_t y = (hyst_real_t)((double)inv.lo.HYST_R +
                                                range_of(&inv) * (double)k / 4000.0);
            const double drive = (double)hyst_step(&K, y);
            const double exact = (double)inv.y_lo.HYST_R +
                                 exact_d(&inv, (double)y - (double)inv.lo.HYST_R);
            worst = fmax(worst, dabs(drive - exact));
        }
        printf("domain [%g, %g]: worst drive error %.3g of the span, %.3g of the error reported\n",
               off, off + 10.0, worst / span, worst / allowed);
        TEST_ASSERT_TRUE(worst <= allowed);
    }
}

/* Flat points: x^3 and x^5 at 0 on [-1, 1] (mid-range), x^2 at lo on
 * [0, 1]: infinite inverse slope; the intervals next to them are exact. */
static void test_error_at_flat_points(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0), fifth = poly_monomial(5u, -1.0, 1.0);
    const hyst_poly_t square = poly_monomial(2u, 0.0, 1.0);
    near_flat = 1;
    TEST_ASSERT_TRUE(table_error(&cube, 0.5, "x^3 on [-1, 1]") <= PROMISE);
    TEST_ASSERT_TRUE(inv.u.inv_table.exact > 0u);
    if (SETUP_IN_FLOAT) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED, hyst_curve_from_poly(&fwd, &fifth));
    } else {
        TEST_ASSERT_TRUE(table_error(&fifth, 0.5, "x^5 on [-1, 1]") <= PROMISE);
    }
    TEST_ASSERT_TRUE(table_error(&square, 0.0, "x^2 on [0, 1]") <= PROMISE);
    TEST_ASSERT_TRUE(inv.u.inv_table.exact > 0u);
    near_flat = 0;
}

/* A compensator of f0 with the default table in H, and the exact one in K. */
static void init_pair(const hyst_poly_t *f0)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&H, &inv, f0, table, HYST_INV_TABLE,
                                                           xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_exact(&K, &inv2, f0, il, jl, ir, jr, CAP));
}

/* Long sweeps up and down the whole range, and a random signal: the drive
 * never steps back (beyond rounding) while the desired output moves on, and
 * stays within the promise of the exact compensator's. */
static void sweep(const hyst_poly_t *f0, const char *name, int flat)
{
    const double lo = (double)hyst_poly_eval(f0, f0->lo), hi = (double)hyst_poly_eval(f0, f0->hi);
    const double span = (double)(f0->hi - f0->lo);
    double worst_back = 0.0, worst = 0.0;
    long i, n;
    int kind;
    init_pair(f0);
    for (kind = 0; kind < 2; ++kind) {
        hyst_real_t prev = hyst_step(&H, (hyst_real_t)(kind == 0 ? lo : hi));
        (void)hyst_step(&K, (hyst_real_t)(kind == 0 ? lo : hi));
        for (i = 1; i <= SAMPLES; ++i) {
            const double f = (double)i / (double)SAMPLES;
            const hyst_real_t yd = (hyst_real_t)(kind == 0 ? lo + (hi - lo) * f : hi - (hi - lo) * f);
            const hyst_real_t d = hyst_step(&H, yd);
            const double back = kind == 0 ? (double)(prev - d) : (double)(d - prev);
            const double err = dabs((double)d - (double)hyst_step(&K, yd)) / span;
            worst_back = back > worst_back ? back : worst_back;
            worst = err > worst ? err : worst;
            prev = d;
        }
    }
    n = SAMPLES;
    fill_signal(SIG_WALK, &rng, lo, hi, sig, n);
    for (i = 0; i < n; ++i) {
        const double err = dabs((double)hyst_step(&H, sig[i]) - (double)hyst_step(&K, sig[i])) / span;
        worst = err > worst ? err : worst;
    }
    printf("%s: sweeps of %ld samples: worst step back %.3g of the drive range; worst "
           "|table - exact compensator| %.3g\n", name, SAMPLES, worst_back / span, worst);
    TEST_ASSERT_TRUE(worst_back / span <= BACKSTEP);
    TEST_ASSERT_TRUE(flat || worst <= PROMISE); /* flat: ill-conditioned, see error_at() */
}

static void test_drive_monotone_along_sweeps(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0);
    sweep(&paper_eq20, "Eq. 20", 0);
    sweep(&piezo_fit, "piezo fit", 0);
    sweep(&cube, "x^3 on [-1, 1]", 1);
}

/* The block call gives step()'s outputs bit for bit, on every signal and
 * on a curve with exact intervals. */
static void test_block_equals_step(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0);
    const hyst_poly_t *curves[2] = {&paper_eq20, &cube};
    int c, kind;
    for (c = 0; c < 2; ++c) {
        const double lo = (double)hyst_poly_eval(curves[c], curves[c]->lo);
        const double hi = (double)hyst_poly_eval(curves[c], curves[c]->hi);
        for (kind = 0; kind < SIG_KINDS; ++kind) {
            long i;
            init_pair(curves[c]);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&K, &inv, curves[c], table,
                                                                   HYST_INV_TABLE, il, jl, ir, jr,
                                                                   CAP));
            fill_signal(kind, &rng, lo, hi, sig, SAMPLES);
            for (i = 0; i < SAMPLES; ++i) {
                out_step[i] = hyst_step(&H, sig[i]);
            }
            TEST_ASSERT_TRUE(hyst_process(&K, sig, out_block, SAMPLES) >= 0); /* clamped ends */
            TEST_ASSERT_EQUAL_MEMORY(out_step, out_block, sizeof out_step);
        }
    }
}

/* A snapshot of a tabulated compensator restores into one with the same
 * table and continues bit for bit; one with another table refuses it. */
static void test_snapshot_round_trip(void)
{
    static unsigned char buf[HYST_SNAPSHOT_SIZE(CAP)];
    const double lo = (double)hyst_poly_eval(&paper_eq20, paper_eq20.lo);
    const double hi = (double)hyst_poly_eval(&paper_eq20, paper_eq20.hi);
    size_t len;
    long i;
    init_pair(&paper_eq20);
    fill_signal(SIG_PAPER, &rng, lo, hi, sig, SAMPLES);
    for (i = 0; i < SAMPLES / 2; ++i) {
        (void)hyst_step(&H, sig[i]);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&H, buf, sizeof buf, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&K, &inv2, &paper_eq20, table2,
                                                           HYST_INV_TABLE, il, jl, ir, jr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&K, buf, len));
    for (; i < SAMPLES; ++i) {
        const hyst_real_t a = hyst_step(&H, sig[i]), b = hyst_step(&K, sig[i]);
        TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&K, &inv2, &paper_eq20, table2,
                                                           HYST_INV_TABLE / 2u, il, jl, ir, jr,
                                                           CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&K, buf, len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_exact(&K, &inv2, &paper_eq20, il, jl, ir, jr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&K, buf, len));
}

/* The default macros declare and initialise the tabulated compensator; the
 * exact one stays available under its own name. */
static void test_define_and_init_macros(void)
{
    HYST_DEFINE_INVERSE(comp, 64);
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_INIT_INVERSE(comp, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_INV_TABLE, comp.curve->kind);
    TEST_ASSERT_EQUAL_UINT(HYST_INV_TABLE, (unsigned)comp.curve->u.inv_table.intervals);
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_INIT_INVERSE_EXACT(comp, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_POLY_INV, comp.curve->kind);
}

#ifndef HYST_USE_DOUBLE
/* The code variant runs an f32 table too: desired outputs as 4096 codes,
 * up the whole range and down again, against the exact inverse. */
static void test_code_variant_runs_the_table(void)
{
    static hyst_code_word_t cl[CAP], cr[CAP];
    double worst = 0.0;
    long i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_from_poly(&fwd, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_curve_inverse_table(&inv, &fwd, table, HYST_INV_TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&H, &inv, 0u, 4095u, cl, yl, cr, yr, CAP));
    for (i = 0; i <= 4095; ++i) { /* rising from A0: the branch is the curve itself */
        const double e = range_of(&inv) * (double)i / 4095.0;
        const double d = (double)hyst_code_step(&H, (uint_least32_t)i) - (double)inv.y_lo.f32;
        const double err = dabs(d - exact_d(&inv, e)) / (double)inv.u.inv_table.span.f32;
        worst = err > worst ? err : worst;
    }
    printf("code variant, Eq. 20, 4096 codes: worst error / drive range %.3g\n", worst);
    TEST_ASSERT_TRUE(worst <= PROMISE);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&H));
}
#endif

/* Bad arguments get a clear status and write nothing. */
static void test_constructor_checks(void)
{
    static const hyst_real_t px[2] = {0, 1}, py[2] = {0, 2};
    hyst_curve_t pwl, out;
    memset(&out, 0x5a, sizeof out);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_inverse_table(NULL, &fwd, table, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_inverse_table(&out, &fwd, NULL, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_inverse_table(&out, NULL, table, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse_table(&out, &fwd, table, 0u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG,
                          hyst_curve_inverse_table(&out, &fwd, table, ((size_t)1 << 20) + 1u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&pwl, px, py, 2u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse_table(&out, &pwl, table, 4u));
    TEST_ASSERT_EQUAL_UINT(0x5a5a5a5au, out.kind);
    /* the inverse of the table is the forward polynomial again */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&out, &fwd, table, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&pwl, &out));
    TEST_ASSERT_EQUAL_INT(HYST_CURVE_POLY, pwl.kind);
    TEST_ASSERT_EQUAL_MEMORY(&fwd.u.poly, &pwl.u.poly, sizeof fwd.u.poly);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, (double)hyst_curve_inverse_error(&fwd));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, (double)hyst_curve_inverse_error(NULL));
}

/* f0 = c x on [0, 1] with c subnormal: the table's scale, intervals / c,
 * overflows the variant's type (every desired output would fall in one
 * interval: the drive was 0 for c / 2); refused, the exact inverse takes the
 * curve. A normal c is tabulated. */
static void test_tiny_output_range(void)
{
#ifdef HYST_USE_DOUBLE
    const double tiny = 1e-320, normal = 1e-300;
#else
    const double tiny = 1e-42, normal = 1e-34;
#endif
    hyst_poly_t p;
    hyst_curve_t out;
    hyst_t S;
    memset(&p, 0, sizeof p);
    p.degree = 1u;
    p.lo = 0.0;
    p.hi = 1.0;
    p.coeffs[0] = (hyst_wide_t)tiny;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &p));
    memset(&out, 0x5a, sizeof out);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ILL_CONDITIONED,
                          hyst_curve_inverse_table(&out, &fwd, table, HYST_INV_TABLE));
    TEST_ASSERT_EQUAL_UINT(0x5a5a5a5au, out.kind); /* nothing written */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&inv, &fwd));
    p.coeffs[0] = (hyst_wide_t)normal;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &p));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&inv, &fwd, table, HYST_INV_TABLE));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &inv, xl, yl, xr, yr, CAP));
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.5f, (float)hyst_step(&S, (hyst_real_t)(normal / 2)));
}

/* f0 = x^9/64 + 63/64 x^8 + x^7/64 + 23/64 on [-1/32, 125/32]: f0' < 0 on
 * [lo, -0.014), a dip of 4e-13 below f0(lo), within the rounding of the
 * range (5.7e4), so the curve is accepted and its first intervals are
 * evaluated exactly. G^-1(0) must be 0: a desired output at or below y_lo
 * after a rise to y_hi drives to lo (the model back at A0). The bisection
 * gave the drive where G is back at 0 (lo + 0.058), and the model, fed
 * that drive, missed y_lo by 6.5e3. */
static void test_descent_to_y_lo_drives_lo_next_to_a_dip(void)
{
    static const hyst_poly_t dip = {9u, HYST_REAL_C(-0.03125), HYST_REAL_C(3.90625),
                                    {0.015625, 0.984375, 0.015625, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                     0.359375}};
    static const size_t counts[] = {1u, 8u, HYST_INV_TABLE};
    hyst_t M;
    unsigned k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &dip));
    for (k = 0u; k < sizeof counts / sizeof counts[0]; ++k) {
        hyst_real_t x, y;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&K, &inv, &dip, table, counts[k],
                                                                il, jl, ir, jr, 8u));
        TEST_ASSERT_TRUE(inv.u.inv_table.exact > 0u);
        TEST_ASSERT_TRUE(hyst_curve_g(&inv, 0) == 0);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&M, &fwd, xl, yl, xr, yr, 8u));
        (void)hyst_step(&M, hyst_step(&K, inv.hi.HYST_R * 2)); /* clamped to y_hi */
        x = hyst_step(&K, inv.lo.HYST_R - 1); /* clamped to y_lo */
        TEST_ASSERT_TRUE(x == dip.lo);
        y = hyst_step(&M, x);
        TEST_ASSERT_TRUE(y == fwd.y_lo.HYST_R);
    }
}

int main(void)
{
    hyst_port_init();
    UNITY_BEGIN();
    RUN_TEST(test_error_on_eq20);
    RUN_TEST(test_error_on_identified_curve);
    RUN_TEST(test_error_on_random_increasing_polynomials);
    RUN_TEST(test_error_at_flat_points);
    RUN_TEST(test_offset_domains_within_the_reported_error);
    RUN_TEST(test_drive_monotone_along_sweeps);
    RUN_TEST(test_block_equals_step);
    RUN_TEST(test_snapshot_round_trip);
    RUN_TEST(test_define_and_init_macros);
    RUN_TEST(test_constructor_checks);
    RUN_TEST(test_tiny_output_range);
    RUN_TEST(test_descent_to_y_lo_drives_lo_next_to_a_dip);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_code_variant_runs_the_table);
#endif
    return UNITY_END();
}
