/* SPDX-License-Identifier: MIT */
/* Polynomial curves sealed ahead of time (curve.h, hyst_*_seal_poly();
 * tcm.h, hyst_*_init_sealed()): the header `hyst header --sealed` wrote on
 * the host (tests/data/eq20.h) is accepted here and gives the instance
 * hyst_init() makes from the same header's f0, output for output, bit for
 * bit (on the Cortex-M4F too: its seal is the one this machine makes); so
 * does any curve sealed here; a number changed (one unit in the last place)
 * or the seal changed is refused (HYST_ERR_CRC) with nothing written, as are
 * a degree out of range, another layout and bad memory. The q31 model
 * alike. */
#include "eq20.h"
#include "signals.h"
#include "support.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define CAP 256
#define SAMPLES 4000L

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t x[SAMPLES];
static hyst_t A, B;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 4711u); }
void tearDown(void) {}

static hyst_status_t init_sealed(hyst_t *S, const hyst_sealed_poly_t *c)
{
    return hyst_init_sealed(S, c, xl2, yl2, xr2, yr2, CAP);
}

/* A (built) and B (sealed) give the same outputs, statuses and bounds
 * over every kind of signal on [lo, hi]. With tol > 0 (A set up in float,
 * B sealed on the host in double: SETUP_IN_FLOAT), outputs within (d + 1)
 * tol after d stored turning points, as tcm.h bounds rounding; the same
 * statuses and turning points. */
static void assert_same_run_on(double lo, double hi, double tol)
{
    int kind;
    for (kind = 0; kind < SIG_KINDS; ++kind) {
        long i;
        fill_signal(kind, &rng, lo, hi, x, SAMPLES);
        hyst_reset(&A);
        hyst_reset(&B);
        for (i = 0; i < SAMPLES; ++i) {
            const hyst_real_t ya = hyst_step(&A, x[i]);
            const hyst_real_t yb = hyst_step(&B, x[i]);
            if (tol > 0.0) {
                TEST_ASSERT_TRUE(fabs((double)ya - (double)yb) <=
                                 ((double)hyst_tp_count(&A) + 1.0) * tol);
            } else {
                TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof ya);
            }
            TEST_ASSERT_EQUAL_INT(hyst_status(&A), hyst_status(&B));
        }
        if (tol > 0.0) {
            TEST_ASSERT_EQUAL_UINT(hyst_tp_count(&A), hyst_tp_count(&B));
        } else {
            const hyst_real_t ea = hyst_error_bound(&A), eb = hyst_error_bound(&B);
            const hyst_real_t ra = hyst_rounding_bound(&A), rb = hyst_rounding_bound(&B);
            TEST_ASSERT_EQUAL_MEMORY(&ea, &eb, sizeof ea);
            TEST_ASSERT_EQUAL_MEMORY(&ra, &rb, sizeof ra);
            TEST_ASSERT_EQUAL_UINT(hyst_tp_count(&A), hyst_tp_count(&B));
        }
    }
}

static void assert_same_run(const hyst_poly_t *f0)
{
    assert_same_run_on((double)f0->lo, (double)f0->hi, 0.0);
}

static void test_header_sealed_is_the_init_of_its_f0(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&A, &eq20, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_sealed(&B, &eq20_sealed));
    if (SETUP_IN_FLOAT) { /* the header is double's set-up (curve.h), A float's: close only */
        assert_same_run_on((double)eq20.lo, (double)eq20.hi,
                           (double)hyst_rounding_bound(&A) + (double)hyst_rounding_bound(&B));
        return;
    }
    assert_same_run(&eq20);
}

/* Two float numbers a few rounding units apart at most. */
static void assert_near(hyst_real_t want, hyst_real_t got)
{
    TEST_ASSERT_TRUE(fabs((double)got - (double)want) <= 2.0 * FLT_EPSILON * fabs((double)want));
}

/* What this machine seals is what the host wrote: the same numbers and seal. */
static void test_header_sealed_is_what_seal_poly_makes_here(void)
{
    hyst_sealed_poly_t s;
    unsigned k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_seal_poly(&s, &eq20));
    if (SETUP_IN_FLOAT) { /* sealed here in float, the header in double (curve.h): numbers
                           * within float's rounding, a bound that counts the set-up's */
        TEST_ASSERT_EQUAL_UINT(eq20_sealed.degree, s.degree);
        assert_near(eq20_sealed.lo, s.lo);
        assert_near(eq20_sealed.hi, s.hi);
        assert_near(eq20_sealed.y_lo, s.y_lo);
        assert_near(eq20_sealed.y_hi, s.y_hi);
        assert_near(eq20_sealed.unit, s.unit);
        for (k = 0u; k < s.degree; ++k) {
            assert_near(eq20_sealed.a[k], s.a[k]);
        }
        TEST_ASSERT_TRUE(s.rounding >= eq20_sealed.rounding);
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_sealed(&B, &s));
        return;
    }
    TEST_ASSERT_EQUAL_HEX32(eq20_sealed.seal, s.seal);
    TEST_ASSERT_EQUAL_UINT(eq20_sealed.degree, s.degree);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.lo, &s.lo, sizeof s.lo);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.hi, &s.hi, sizeof s.hi);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.y_lo, &s.y_lo, sizeof s.y_lo);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.y_hi, &s.y_hi, sizeof s.y_hi);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.unit, &s.unit, sizeof s.unit);
    TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.rounding, &s.rounding, sizeof s.rounding);
    for (k = 0u; k < s.degree; ++k) {
        TEST_ASSERT_EQUAL_MEMORY(&eq20_sealed.a[k], &s.a[k], sizeof s.a[k]);
    }
}

/* Random increasing polynomials of every degree, sealed here. */
static void test_any_sealed_curve_is_the_init_of_its_f0(void)
{
    int trial;
    for (trial = 0; trial < 3 * HYST_MAX_DEGREE; ++trial) {
        const hyst_poly_t f0 = poly_random_increasing(&rng, 1u + (unsigned)trial % HYST_MAX_DEGREE);
        hyst_sealed_poly_t s;
        const hyst_status_t st = hyst_seal_poly(&s, &f0);
        TEST_ASSERT_EQUAL_INT(hyst_init(&A, &f0, xl, yl, xr, yr, CAP), st);
        if (st != HYST_OK) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, init_sealed(&B, &s));
        assert_same_run(&f0);
    }
}

/* Refused with `want`, the instance left as it was. */
static void assert_refused(const hyst_sealed_poly_t *c, hyst_status_t want)
{
    static hyst_t before;
    memset(&B, 0x5A, sizeof B);
    before = B;
    TEST_ASSERT_EQUAL_INT(want, init_sealed(&B, c));
    TEST_ASSERT_EQUAL_MEMORY(&before, &B, sizeof B);
}

static hyst_real_t next_up(hyst_real_t v) { return NEXT(v, v + 1); }

static void test_damaged_sealed_curve_is_refused(void)
{
    hyst_sealed_poly_t c;
    hyst_real_t *const number[6] = {&c.lo, &c.hi, &c.y_lo, &c.y_hi, &c.unit, &c.rounding};
    unsigned k;
    for (k = 0u; k < 6u + eq20_sealed.degree; ++k) { /* one number one unit off, the seal kept */
        hyst_real_t *const v = k < 6u ? number[k] : &c.a[k - 6u];
        c = eq20_sealed;
        *v = next_up(*v);
        assert_refused(&c, HYST_ERR_CRC);
    }
    for (k = 0u; k < 32u; ++k) { /* the seal: every bit */
        c = eq20_sealed;
        c.seal ^= 1ul << k;
        assert_refused(&c, HYST_ERR_CRC);
    }
    c = eq20_sealed;
    c.degree = 2u; /* a shorter curve under the same seal */
    assert_refused(&c, HYST_ERR_CRC);
    c = eq20_sealed;
    c.a[2] = next_up(c.a[2]); /* changed, and sealed again wrongly: over the old numbers */
    c.seal = eq20_sealed.seal ^ 0x80000000ul;
    assert_refused(&c, HYST_ERR_CRC);
    c = eq20_sealed;
    c.degree = 0u;
    assert_refused(&c, HYST_ERR_DEGREE);
    c.degree = HYST_MAX_DEGREE + 1u;
    assert_refused(&c, HYST_ERR_DEGREE);
    /* the undamaged curve still goes */
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_sealed(&B, &eq20_sealed));
}

static void test_what_the_seal_cannot_vouch_for_is_checked(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, init_sealed(&B, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init_sealed(NULL, &eq20_sealed, xl2, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init_sealed(&B, &eq20_sealed, NULL, yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, hyst_init_sealed(&B, &eq20_sealed, xl2, yl2, xr2, yr2, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_OVERLAP,
                          hyst_init_sealed(&B, &eq20_sealed, xl2, xl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT,
                          HYST_DEFAULT_NAME_(init_sealed_)(&B, &eq20_sealed, xl2, yl2, xr2, yr2,
                                                           CAP, HYST_LAYOUT ^ 1ul));
}

/* hyst_seal_poly() refuses what hyst_curve_from_poly() refuses, writing nothing. */
static void test_seal_poly_checks_as_the_constructor(void)
{
    hyst_poly_t bad = eq20;
    hyst_sealed_poly_t s, before;
    hyst_curve_t curve;
    memset(&s, 0x5A, sizeof s);
    before = s;
    bad.coeffs[2] = -bad.coeffs[2]; /* falls near lo */
    TEST_ASSERT_EQUAL_INT(hyst_curve_from_poly(&curve, &bad), hyst_seal_poly(&s, &bad));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INCREASING, hyst_seal_poly(&s, &bad));
    bad = eq20;
    bad.degree = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, hyst_seal_poly(&s, &bad));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_seal_poly(&s, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_seal_poly(NULL, &eq20));
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
}

/* ---- the tabulated compensator ---- */

static hyst_real_t table[HYST_INV_TABLE_LEN(HYST_INV_TABLE)];
static hyst_real_t flash[HYST_INV_TABLE_LEN(HYST_INV_TABLE)]; /* the copy firmware would hold */
static hyst_curve_t inv_built, inv_sealed;

/* The compensator of f0 built (A) and from its seal and a copy of its table
 * (B): the same curve numbers, the same drives bit for bit. */
static void assert_sealed_compensator(const hyst_poly_t *f0, size_t intervals)
{
    hyst_sealed_inverse_t s;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, f0, table, intervals,
                                                           xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_seal_inverse_table(&s, &inv_built));
    memcpy(flash, table, HYST_INV_TABLE_LEN(intervals) * sizeof table[0]);
    memset(&inv_sealed, 0x5A, sizeof inv_sealed);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_sealed(&B, &inv_sealed, &s, flash, xl2, yl2,
                                                            xr2, yr2, CAP));
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&inv_built) == hyst_curve_inverse_error(&inv_sealed));
    TEST_ASSERT_EQUAL_UINT(inv_built.u.inv_table.exact, inv_sealed.u.inv_table.exact);
    assert_same_run_on((double)CURVE_NUM(inv_built.lo), (double)CURVE_NUM(inv_built.hi), 0.0);
}

static void test_sealed_compensator_is_the_built_one(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0); /* a flat point: exact intervals */
    assert_sealed_compensator(&eq20, HYST_INV_TABLE);
    assert_sealed_compensator(&cube, 64u);
    TEST_ASSERT_TRUE(inv_sealed.u.inv_table.exact > 0u);
}

/* The compensator sealed with its table by `hyst header` on the host: this
 * machine's build of the same table, drives bit for bit. */
static void test_header_sealed_compensator_is_the_built_one(void)
{
    TEST_ASSERT_EQUAL_UINT(HYST_INV_TABLE, eq20_INTERVALS);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, &eq20, table,
                                                           eq20_INTERVALS, xl, yl, xr, yr, CAP));
    if (!SETUP_IN_FLOAT) { /* in float, the header's table is double's build (curve.h) */
        TEST_ASSERT_EQUAL_MEMORY(eq20_table, table, sizeof eq20_table);
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_DEFAULT_NAME_(init_inverse_sealed_)(
                                       &B, &inv_sealed, &eq20_comp_sealed, eq20_table, xl2, yl2,
                                       xr2, yr2, CAP, HYST_LAYOUT));
    if (SETUP_IN_FLOAT) { /* drives within both tables' errors, not the same */
        assert_same_run_on((double)CURVE_NUM(inv_built.lo), (double)CURVE_NUM(inv_built.hi),
                           ((double)hyst_curve_inverse_error(&inv_built) +
                            (double)hyst_curve_inverse_error(&inv_sealed)) *
                               (double)CURVE_NUM(inv_built.u.inv_table.span));
        return;
    }
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(&inv_built) == hyst_curve_inverse_error(&inv_sealed));
    assert_same_run_on((double)CURVE_NUM(inv_built.lo), (double)CURVE_NUM(inv_built.hi), 0.0);
}

/* The build's error, reported by hyst_curve_inverse_error(), comes back
 * exactly from its float in the seal (widened by its bits on a target
 * whose double is in software): the error measured, and errors above it
 * claimed; one below it (down to zero and subnormal) is refused by the
 * seal, which measures the table first. */
static void test_sealed_compensator_reports_the_built_error(void)
{
    static const float above[] = {3.0314681e-06f, 0.5f, 1.0f};
    static const float below[] = {0.0f, 1.4e-45f, 1e-40f, 1.17549435e-38f};
    hyst_sealed_inverse_t s;
    hyst_curve_t c;
    float built;
    size_t k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, &eq20, table,
                                                           HYST_INV_TABLE, xl, yl, xr, yr, CAP));
    built = (float)hyst_curve_inverse_error(&inv_built);
    TEST_ASSERT_TRUE((hyst_wide_t)built == hyst_curve_inverse_error(&inv_built));
    for (k = 0u; k <= sizeof above / sizeof above[0]; ++k) {
        const float err = k == 0u ? built : above[k - 1u];
        if (err < built) {
            continue;
        }
        c = inv_built;
        c.u.inv_table.max_err = (hyst_wide_t)err;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_seal_inverse_table(&s, &c));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_sealed(&B, &inv_sealed, &s, table, xl2,
                                                                yl2, xr2, yr2, CAP));
        TEST_ASSERT_TRUE(hyst_curve_inverse_error(&inv_sealed) == (hyst_wide_t)err);
    }
    for (k = 0u; k <= sizeof below / sizeof below[0]; ++k) {
        c = inv_built;
        c.u.inv_table.max_err =
            (hyst_wide_t)(k == 0u ? nextafterf(built, 0.0f) : below[k - 1u]);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_seal_inverse_table(&s, &c));
    }
}

static void test_damaged_sealed_compensator_is_refused(void)
{
    hyst_sealed_inverse_t s, c;
    size_t k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, &eq20, table,
                                                           HYST_INV_TABLE, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_seal_inverse_table(&s, &inv_built));
    for (k = 0u; k < HYST_INV_TABLE_LEN(HYST_INV_TABLE); k += 97u) { /* a table number one unit off */
        memcpy(flash, table, sizeof flash);
        flash[k] = next_up(flash[k]);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_init_inverse_sealed(&B, &inv_sealed, &s, flash,
                                                                     xl2, yl2, xr2, yr2, CAP));
    }
    memcpy(flash, table, sizeof flash);
    c = s;
    c.span = next_up(c.span);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_init_inverse_sealed(&B, &inv_sealed, &c, flash, xl2,
                                                                 yl2, xr2, yr2, CAP));
    c = s;
    c.a[0] = next_up(c.a[0]);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_init_inverse_sealed(&B, &inv_sealed, &c, flash, xl2,
                                                                 yl2, xr2, yr2, CAP));
    c = s;
    c.max_err = nextafterf(c.max_err, 1.0f);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_init_inverse_sealed(&B, &inv_sealed, &c, flash, xl2,
                                                                 yl2, xr2, yr2, CAP));
    c = s;
    c.exact += 1ul;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_init_inverse_sealed(&B, &inv_sealed, &c, flash, xl2,
                                                                 yl2, xr2, yr2, CAP));
    c = s;
    c.intervals = 0ul;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_init_inverse_sealed(&B, &inv_sealed, &c, flash, xl2,
                                                                 yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init_inverse_sealed(&B, &inv_sealed, &s, NULL, xl2,
                                                                  yl2, xr2, yr2, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_seal_inverse_table(&c, NULL));
    {   /* a forward curve is not a tabulated compensator */
        hyst_curve_t fwd;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &eq20));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_seal_inverse_table(&c, &fwd));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_sealed(&B, &inv_sealed, &s, flash, xl2, yl2,
                                                            xr2, yr2, CAP));
}

/* A table changed in RAM after its build, then sealed: a slope of one
 * piece halved (its knots still on the model), or an interval the build
 * solves given a cubic piece again (the secant across its solved run). Firmware checks only
 * the seal, so the seal measures every piece as the table from flash is
 * measured: refused (HYST_ERR_CURVE), nothing written; the table put back
 * is sealed again; a claimed error below the measured one is refused. */
static void test_seal_refuses_a_changed_table(void)
{
    const hyst_poly_t cube = poly_monomial(3u, -1.0, 1.0); /* a flat point: exact intervals */
    hyst_sealed_inverse_t s, before;
    hyst_curve_t c;
    size_t k;
    int given_back = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, &eq20, table,
                                                           HYST_INV_TABLE, xl, yl, xr, yr, CAP));
    memset(&before, 0x5A, sizeof before);
    for (k = 3u; k < HYST_INV_TABLE; k += 61u) {
        const hyst_real_t slope = table[4u * k + 1u];
        if (table[4u * k] < 0) {
            continue; /* an interval solved instead */
        }
        table[4u * k + 1u] = slope * (hyst_real_t)0.5;
        s = before;
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_seal_inverse_table(&s, &inv_built));
        TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
        table[4u * k + 1u] = slope;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_seal_inverse_table(&s, &inv_built));
    c = inv_built;
    c.u.inv_table.max_err = 0;
    s = before;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_seal_inverse_table(&s, &c));
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&A, &inv_built, &cube, table, 64u, xl,
                                                           yl, xr, yr, CAP));
    for (k = 1u; k < 64u; ++k) { /* the first solved interval given a piece: the secant */
        if (table[4u * k] < 0 && table[4u * k - 4u] >= 0) {  /* across the solved run */
            const hyst_real_t *left = &table[4u * k - 4u];
            const hyst_real_t from = left[0] + left[1] + left[2] + left[3];
            size_t m = k;
            while (table[4u * m] < 0) {
                ++m;
            }
            table[4u * k] = from;
            table[4u * k + 1u] = (table[4u * m] - from) / (hyst_real_t)(m - k);
            table[4u * k + 2u] = 0;
            table[4u * k + 3u] = 0;
            c = inv_built;
            c.u.inv_table.exact -= 1u;
            s = before;
            TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_seal_inverse_table(&s, &c));
            TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
            ++given_back;
            break;
        }
    }
    TEST_ASSERT_EQUAL_INT(1, given_back);
}

/* ---- the q31 model ---- */

static hyst_code_word_t qx[4][CAP];
static hyst_q31_t qy[4][CAP];

static hyst_status_t q31_sealed(hyst_t *S, const hyst_q31_sealed_poly_t *c)
{
    return hyst_q31_init_sealed(S, c, qx[2], qy[2], qx[3], qy[3], CAP);
}

static void test_q31_header_sealed_is_the_init_of_its_f0(void)
{
    long i;
    hyst_q31_sealed_poly_t s;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_init(&A, &eq20, 0u, 4095u, qx[0], qy[0], qx[1],
                                                 qy[1], CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, q31_sealed(&B, &eq20_q31_sealed));
    for (i = 0; i < 3L * SAMPLES; ++i) {
        const uint_least32_t code = i < SAMPLES ? (uint_least32_t)(i % 4096L)
                                                : (uint_least32_t)rng_below(&rng, 4200u);
        const hyst_q31_t qa = hyst_q31_step(&A, code), qb = hyst_q31_step(&B, code);
        if (SETUP_IN_FLOAT) { /* A set up in float, the header in double (q31.h): close only */
            TEST_ASSERT_TRUE(fabs((double)qa - (double)qb) <=
                             ((double)hyst_tp_count(&A) + 1.0) *
                                 ((double)hyst_q31_rounding_bound(&A) +
                                  (double)hyst_q31_rounding_bound(&B)));
        } else {
            TEST_ASSERT_EQUAL_INT32(qa, qb);
        }
        TEST_ASSERT_EQUAL_INT(hyst_status(&A), hyst_status(&B));
    }
    TEST_ASSERT_EQUAL_INT32(hyst_q31_error_bound(&A), hyst_q31_error_bound(&B));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_seal_poly(&s, &eq20, 0u, 4095u));
    if (SETUP_IN_FLOAT) { /* coefficients within float's rounding of the header's */
        unsigned k;
        for (k = 0u; k < s.degree; ++k) {
            TEST_ASSERT_TRUE(fabs((double)s.a[k] - (double)eq20_q31_sealed.a[k]) <=
                             2.0 * FLT_EPSILON * fabs((double)eq20_q31_sealed.a[k]) + 1.0);
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, q31_sealed(&B, &s));
        return;
    }
    TEST_ASSERT_EQUAL_HEX32(eq20_q31_sealed.seal, s.seal);
    TEST_ASSERT_EQUAL_MEMORY(eq20_q31_sealed.a, s.a, sizeof s.a[0] * s.degree);
}

static void test_q31_damaged_sealed_model_is_refused(void)
{
    hyst_q31_sealed_poly_t c;
    unsigned k;
    for (k = 0u; k < eq20_q31_sealed.degree; ++k) {
        c = eq20_q31_sealed;
        c.a[k] += 1;
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, q31_sealed(&B, &c));
    }
    c = eq20_q31_sealed;
    c.unit += 1;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, q31_sealed(&B, &c));
    c = eq20_q31_sealed;
    c.rounding -= 1;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, q31_sealed(&B, &c));
    c = eq20_q31_sealed;
    c.code_hi = 4094u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, q31_sealed(&B, &c));
    c = eq20_q31_sealed;
    c.code_lo = 4095u; /* an empty code range: refused before the seal */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, q31_sealed(&B, &c));
    c = eq20_q31_sealed;
    c.degree = HYST_MAX_DEGREE + 1u;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DEGREE, q31_sealed(&B, &c));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, q31_sealed(&B, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT,
                          hyst_q31_init_sealed_(&B, &eq20_q31_sealed, qx[2], qy[2], qx[3], qy[3],
                                                CAP, HYST_LAYOUT ^ 1ul));
    TEST_ASSERT_EQUAL_INT(HYST_OK, q31_sealed(&B, &eq20_q31_sealed));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_header_sealed_is_the_init_of_its_f0);
    RUN_TEST(test_header_sealed_is_what_seal_poly_makes_here);
    RUN_TEST(test_any_sealed_curve_is_the_init_of_its_f0);
    RUN_TEST(test_damaged_sealed_curve_is_refused);
    RUN_TEST(test_what_the_seal_cannot_vouch_for_is_checked);
    RUN_TEST(test_seal_poly_checks_as_the_constructor);
    RUN_TEST(test_sealed_compensator_is_the_built_one);
    RUN_TEST(test_header_sealed_compensator_is_the_built_one);
    RUN_TEST(test_sealed_compensator_reports_the_built_error);
    RUN_TEST(test_damaged_sealed_compensator_is_refused);
    RUN_TEST(test_seal_refuses_a_changed_table);
    RUN_TEST(test_q31_header_sealed_is_the_init_of_its_f0);
    RUN_TEST(test_q31_damaged_sealed_model_is_refused);
    return UNITY_END();
}
