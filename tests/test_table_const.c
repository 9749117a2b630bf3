/* SPDX-License-Identifier: MIT */
/* Tabulated inverses built ahead of time (curve.h, hyst_table_seal_t): a
 * table built and sealed, then copied as firmware would hold it in flash,
 * prepares the same curve as its build and gives the same drives bit for
 * bit, for both the asymmetric compensator (random E) and the symmetric one
 * (Eq. 20, and x^3 with intervals evaluated exactly); a damaged table, the
 * wrong shape or a changed seal is refused (HYST_ERR_CRC), another model's
 * table too (HYST_ERR_CURVE); bad arguments are refused. */
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#include "everett_inv_keeping_pieces.h"

#define CAP 64
#define SAMPLES 3000L
#define ROWS HYST_EVERETT_INV_ROWS
#define INTERVALS HYST_EVERETT_INV_INTERVALS
#define EV_LEN HYST_EVERETT_INV_TABLE_LEN(ROWS, INTERVALS)
#define SYM_INTERVALS HYST_INV_TABLE
#define SYM_LEN HYST_INV_TABLE_LEN(SYM_INTERVALS)

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t xl2[CAP], yl2[CAP], xr2[CAP], yr2[CAP];
static hyst_real_t built[EV_LEN], flash[EV_LEN]; /* flash: the copy firmware would hold */
static hyst_curve_t fwd, other_fwd, inv, from_flash;
static hyst_table_seal_t seal;
static hyst_t B, F;
static rng_t rng;

void setUp(void) { rng_seed(&rng, 27182u); }
void tearDown(void) {}

static hyst_everett_t accepted_e(hyst_curve_t *curve)
{
    for (;;) {
        const hyst_everett_t e = ref_everett_random(&rng);
        if (hyst_curve_from_everett(curve, &e) == HYST_OK) {
            return e;
        }
    }
}

/* The curve from flash is the build's: the same numbers (but the table's
 * address), so the same instance behaviour. */
#define SAME_NUM(a, b) TEST_ASSERT_EQUAL_MEMORY(&CURVE_NUM(a), &CURVE_NUM(b), sizeof CURVE_NUM(a))
static void assert_same_curve(const hyst_curve_t *a, const hyst_curve_t *b)
{
    TEST_ASSERT_EQUAL_UINT(a->kind, b->kind);
    SAME_NUM(a->lo, b->lo);
    SAME_NUM(a->hi, b->hi);
    SAME_NUM(a->y_lo, b->y_lo);
    SAME_NUM(a->y_hi, b->y_hi);
    SAME_NUM(a->unit, b->unit);
    SAME_NUM(a->rounding, b->rounding);
    TEST_ASSERT_TRUE(hyst_curve_inverse_error(a) == hyst_curve_inverse_error(b));
    if (a->kind == (unsigned)HYST_CURVE_EVERETT_INV_TABLE) {
        unsigned m;
        TEST_ASSERT_EQUAL_UINT(a->u.everett.exact, b->u.everett.exact);
        TEST_ASSERT_EQUAL_UINT(a->u.everett.rows, b->u.everett.rows);
        TEST_ASSERT_EQUAL_UINT(a->u.everett.intervals, b->u.everett.intervals);
        for (m = 0u; m <= HYST_EVERETT_MAX_DEGREE; ++m) {
            SAME_NUM(a->u.everett.v_end[0][m], b->u.everett.v_end[0][m]);
            SAME_NUM(a->u.everett.v_end[1][m], b->u.everett.v_end[1][m]);
        }
    } else {
        TEST_ASSERT_EQUAL_UINT(a->u.inv_table.exact, b->u.inv_table.exact);
        TEST_ASSERT_EQUAL_UINT(a->u.inv_table.intervals, b->u.inv_table.intervals);
        SAME_NUM(a->u.inv_table.span, b->u.inv_table.span);
        SAME_NUM(a->u.inv_table.u_per_d, b->u.inv_table.u_per_d);
    }
}

/* B (the built table) and F (from flash) driven alike: equal bit for bit. */
static void assert_same_drives(double lo, double hi)
{
    double v = 0.5 * (lo + hi);
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&B, &inv, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&F, &from_flash, xl2, yl2, xr2, yr2, CAP));
    for (k = 0; k < SAMPLES; ++k) {
        const hyst_real_t y = (hyst_real_t)ref_everett_walk(&rng, &v, lo - 0.05 * (hi - lo),
                                                            hi + 0.05 * (hi - lo));
        const hyst_real_t b = hyst_step(&B, y), f = hyst_step(&F, y);
        if (memcmp(&b, &f, sizeof b) != 0 || hyst_status(&B) != hyst_status(&F)) {
            TEST_PRINTF("sample %ld: built %.9g, from flash %.9g", k, (double)b, (double)f);
            TEST_FAIL();
        }
    }
}

static void test_everett_table_from_flash_is_the_build(void)
{
    unsigned solved = 0u;
    int trial;
    for (trial = 0; trial < 6; ++trial) {
        const hyst_everett_t e = accepted_e(&fwd);
        TEST_ASSERT_EQUAL_INT(HYST_OK,
                              hyst_curve_everett_inverse_table(&inv, &fwd, built, ROWS, INTERVALS));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
        TEST_ASSERT_TRUE(seal.max_err == hyst_curve_inverse_error(&inv));
        memcpy(flash, built, sizeof flash);
        memset(built, 0, sizeof built); /* the build's copy must not be what is read */
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_inverse_table_const(
                                           &from_flash, &fwd, flash, ROWS, INTERVALS, &seal));
        memcpy(built, flash, sizeof built);
        assert_same_curve(&inv, &from_flash);
        solved += (unsigned)from_flash.u.everett.exact;
        assert_same_drives(e.y_lo, e.y_lo + ref_everett_e(&e, e.hi, e.lo));
    }
    TEST_PRINTF("6 random E: curves and 3000 drives each equal; intervals solved %u", solved);
}

/* E's table, sealed, in flash. */
static hyst_everett_t sealed_everett(void)
{
    const hyst_everett_t e = accepted_e(&fwd);
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&inv, &fwd, flash, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
    return e;
}

static hyst_status_t everett_from_flash(size_t rows, size_t intervals)
{
    return hyst_curve_everett_inverse_table_const(&from_flash, &fwd, flash, rows, intervals,
                                                  &seal);
}

static void test_damage_is_refused(void)
{
    int trial;
    (void)sealed_everett();
    for (trial = 0; trial < 20; ++trial) { /* one number one unit off, anywhere */
        const size_t i = (size_t)rng_below(&rng, (uint32_t)EV_LEN);
        const hyst_real_t keep = flash[i];
        flash[i] = NEXT(keep, (hyst_real_t)1e30);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
        flash[i] = keep;
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, everett_from_flash(ROWS, INTERVALS));
    /* the wrong shape (a smaller table: the reads stay in the array) */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS - 1u, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS / 2u));
    /* the seal changed: checksum, error, an error no float holds, NaN */
    seal.crc ^= 0x100ul;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
    seal.crc ^= 0x100ul;
    seal.max_err *= 2;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
    seal.max_err /= 2;
    if (SETUP_IN_FLOAT) { /* every hyst_wide_t is a float there: one unit larger instead */
        seal.max_err = (hyst_wide_t)nextafterf((float)seal.max_err, HUGE_VALF);
    } else {
        seal.max_err = (hyst_wide_t)(seal.max_err + seal.max_err * 1e-12);
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
    seal.max_err = (hyst_wide_t)NAN;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
    /* a failed call leaves its output curve alone */
    memset(&from_flash, 0x5A, sizeof from_flash);
    {
        const hyst_curve_t before = from_flash;
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, everett_from_flash(ROWS, INTERVALS));
        TEST_ASSERT_EQUAL_MEMORY(&before, &from_flash, sizeof before);
    }
}

/* A table sealed after it was changed (the seal only says it is intact):
 * its shape is checked too, every number finite and every row's knots
 * rising to its end (HYST_ERR_CURVE). */
static void test_sealed_garbage_is_refused(void)
{
    const size_t row = HYST_INV_TABLE_LEN(INTERVALS);
    const size_t at[4] = {4u * 5u + 2u,                   /* a slope: NaN */
                          row * 3u + 4u * 7u,             /* a knot below the one before */
                          row * (ROWS + 2u) + 4u * INTERVALS, /* an end below its knots */
                          row * 2u + 4u * 9u + 1u};       /* the slope of a mark, if any */
    const hyst_real_t value[4] = {(hyst_real_t)NAN, 0, 0, 1};
    unsigned i;
    (void)sealed_everett();
    memcpy(built, flash, sizeof built);
    for (i = 0u; i < 4u; ++i) {
        hyst_curve_t resealed = inv; /* its table is flash */
        if (i == 1u) {
            flash[at[i]] = flash[at[i] - 4u] * (hyst_real_t)0.5; /* below knot 6 */
        } else if (i == 3u) {
            flash[at[i] - 1u] = -1; /* interval 9 marked, with a slope */
            flash[at[i]] = value[i];
        } else {
            flash[at[i]] = value[i];
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&resealed, &seal));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, everett_from_flash(ROWS, INTERVALS));
        memcpy(flash, built, sizeof flash);
    }
}

/* Pieces whose slopes were changed, then sealed again: the knots still
 * lie on the model, but the seal's error no longer holds (the compensator
 * missed by 1.6 % of the range and reported the build's error). Every
 * piece is measured as the build measures it (HYST_ERR_CURVE); both kinds,
 * a slope in one row of one direction, or of the symmetric table. */
static void test_resealed_slopes_are_refused(void)
{
    const size_t row = HYST_INV_TABLE_LEN(INTERVALS);
    int trial;
    for (trial = 0; trial < 4; ++trial) {
        const size_t r = (size_t)trial % (ROWS + 1u), k = 3u + 5u * (size_t)trial;
        const size_t at = (trial % 2 ? row * (ROWS + 1u) : 0u) + row * r + 4u * k;
        hyst_curve_t resealed;
        (void)sealed_everett();
        resealed = inv; /* its table is flash */
        if (flash[at] < 0) {
            continue; /* an interval solved instead */
        }
        flash[at + 1u] *= (hyst_real_t)0.5;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&resealed, &seal));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, everett_from_flash(ROWS, INTERVALS));
    }
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&inv, &fwd, flash, SYM_INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_inverse_table_const(&from_flash, &fwd, flash, SYM_INTERVALS, &seal));
    flash[4u * 100u + 1u] *= (hyst_real_t)0.5;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE,
                          hyst_curve_inverse_table_const(&from_flash, &fwd, flash, SYM_INTERVALS, &seal));
}

/* The slope at knot k of a row changed alike on both sides (the end slope
 * of piece k - 1 and the start slope of piece k, each piece still a cubic
 * Hermite piece between the same knots), to a value within Fritsch and
 * Carlson's limits of both pieces: 0, half, or the smaller limit (three
 * times the smaller secant). No piece's shape is broken, every knot stays on
 * the model; the slope is not the model's. Returns 0 if the change is not
 * one (the slope already there, or a piece solved instead). */
static int change_knot_slope(size_t at, int how)
{
    hyst_real_t *left = &flash[at - 4u], *right = &flash[at];
    const hyst_real_t slope = right[1];
    const hyst_real_t sec_left = 3 * (right[0] - left[0]);
    const hyst_real_t sec_right = 3 * (right[4] - right[0]);
    const hyst_real_t limit = sec_left < sec_right ? sec_left : sec_right;
    const hyst_real_t to = how == 0 ? 0 : how == 1 ? slope * (hyst_real_t)0.5 : limit;
    const hyst_real_t change = to - slope;
    if (left[0] < 0 || right[0] < 0 || right[4] < 0 ||
        !(fabs((double)change) > 0.25 * (double)slope)) {
        return 0;
    }
    left[2] -= change; /* piece k - 1: its end slope, its ends kept */
    left[3] += change;
    right[1] = to; /* piece k: its start slope, its ends kept */
    right[2] -= 2 * change;
    right[3] += change;
    return 1;
}

/* A slope changed alike on both sides of a knot within Fritsch and
 * Carlson's limits and the table sealed again: every piece is still the
 * shape of the build's, but the drive there is not the one the build
 * measured (the compensator misses by more than the error sealed). Each
 * knot's slope is the model's, limited as the build limits it
 * (HYST_ERR_CURVE). */
static void test_resealed_knot_slope_is_refused(void)
{
    const size_t row = HYST_INV_TABLE_LEN(INTERVALS);
    int trial, changed = 0;
    for (trial = 0; trial < 12; ++trial) {
        const size_t r = (size_t)(5 * trial) % (ROWS + 1u), k = 1u + (size_t)(7 * trial) % 29u;
        const size_t at = (trial % 2 ? row * (ROWS + 1u) : 0u) + row * r + 4u * k;
        hyst_curve_t resealed;
        (void)sealed_everett();
        resealed = inv; /* its table is flash */
        if (!change_knot_slope(at, trial % 3)) {
            continue;
        }
        ++changed;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&resealed, &seal));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, everett_from_flash(ROWS, INTERVALS));
    }
    TEST_ASSERT_TRUE(changed >= 8);
    TEST_PRINTF("%d knots' slopes changed alike and resealed: all refused", changed);
}

/* An interval the build solves (its pieces blended miss
 * HYST_INV_TABLE_TOL) given back the pieces its rows were built with, and
 * the table sealed again: every piece is the build's, only the mark is
 * gone; the compensator would miss there by 2 % of the drive range
 * (E = w^2 (1 + t / 2)). The check from flash measures each interval it
 * finds with pieces as the build measures it (HYST_ERR_CURVE). */
static void test_solved_interval_given_its_pieces_is_refused(void)
{
    static hyst_real_t kept[EV_LEN];
    const size_t row = HYST_INV_TABLE_LEN(INTERVALS);
    hyst_everett_t e;
    hyst_curve_t unsolved, resealed;
    hyst_ptr_t to;
    size_t k, r, i;
    unsigned given = 0u;
    memset(&e, 0, sizeof e);
    e.degree = 3u;
    e.lo = 0;
    e.hi = 10;
    e.y_lo = -1;
    e.e[1][0] = 2;
    e.e[1][1] = 1;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&fwd, &e));
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&inv, &fwd, flash, ROWS, INTERVALS));
    TEST_ASSERT_TRUE(inv.u.everett.exact > 0u);
    to.HYST_R = kept;
    TEST_ASSERT_EQUAL_INT(HYST_OK, build_keeping_pieces(&unsolved, &fwd, to, ROWS, INTERVALS,
                                                        (unsigned)HYST_DEFAULT_VARIANT));
    TEST_ASSERT_EQUAL_UINT(0u, unsolved.u.everett.exact);
    memcpy(built, flash, sizeof built);
    for (k = 0u; k < 2u * INTERVALS; ++k) {
        /* interval k % INTERVALS of direction k / INTERVALS */
        const size_t at = (k / INTERVALS) * (ROWS + 1u) * row + 4u * (k % INTERVALS);
        if (!(flash[at] < 0)) {
            continue;
        }
        for (r = 0u; r <= ROWS; ++r) {
            for (i = 0u; i < 4u; ++i) {
                flash[at + r * row + i] = kept[at + r * row + i];
            }
        }
        resealed = inv; /* its table is flash */
        --resealed.u.everett.exact;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&resealed, &seal));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, everett_from_flash(ROWS, INTERVALS));
        memcpy(flash, built, sizeof flash);
        ++given;
    }
    TEST_ASSERT_EQUAL_UINT(inv.u.everett.exact, given);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_OK, everett_from_flash(ROWS, INTERVALS));
    TEST_PRINTF("%u solved intervals given back their pieces and resealed: all refused", given);
}

/* A table is in output steps relative to the branch's whole step, so E
 * times a constant has the same table (accepted); any other E is refused. */
static void test_another_models_table_is_refused(void)
{
    int trial, shape_changes = 0;
    for (trial = 0; trial < 8; ++trial) {
        hyst_everett_t e = sealed_everett(), scaled;
        unsigned i, j;
        (void)accepted_e(&other_fwd);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE,
                              hyst_curve_everett_inverse_table_const(&from_flash, &other_fwd, flash,
                                                                     ROWS, INTERVALS, &seal));
        scaled = e;
        for (i = 0u; i < HYST_EVERETT_MAX_DEGREE; ++i) {
            for (j = 0u; j < HYST_EVERETT_MAX_DEGREE; ++j) {
                scaled.e[i][j] *= 2;
            }
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&other_fwd, &scaled));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_inverse_table_const(
                                           &from_flash, &other_fwd, flash, ROWS, INTERVALS, &seal));
        if (e.degree > 1u) { /* the linear term 0.1 % larger: another shape */
            e.e[0][0] *= HYST_WIDE_C(1.001);
            if (hyst_curve_from_everett(&other_fwd, &e) == HYST_OK) {
                TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_curve_everett_inverse_table_const(
                                                          &from_flash, &other_fwd, flash, ROWS,
                                                          INTERVALS, &seal));
                ++shape_changes;
            }
        }
        TEST_ASSERT_EQUAL_INT(HYST_OK, everett_from_flash(ROWS, INTERVALS));
    }
    TEST_ASSERT_TRUE(shape_changes >= 3);
}

/* Eq. 20, and x^3 on [-1, 1] (a flat point: intervals evaluated exactly). */
static void test_symmetric_table_from_flash_is_the_build(void)
{
    static const hyst_poly_t cube = {3u, HYST_REAL_C(-1.0), HYST_REAL_C(1.0), {1.0, 0.0, 0.0, 0.0}};
    const hyst_poly_t *models[2];
    int m;
    models[0] = &paper_eq20;
    models[1] = &cube;
    for (m = 0; m < 2; ++m) {
        double lo, hi;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&fwd, models[m]));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&inv, &fwd, built, SYM_INTERVALS));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_table_seal(&inv, &seal));
        memcpy(flash, built, SYM_LEN * sizeof built[0]);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table_const(&from_flash, &fwd, flash,
                                                                      SYM_INTERVALS, &seal));
        assert_same_curve(&inv, &from_flash);
        TEST_ASSERT_TRUE(m == 0 || from_flash.u.inv_table.exact > 0u);
        lo = (double)CURVE_NUM(inv.lo);
        hi = (double)CURVE_NUM(inv.hi);
        assert_same_drives(lo, hi);
        /* damage, the wrong size, another model */
        flash[4u * SYM_INTERVALS] = NEXT(flash[4u * SYM_INTERVALS], 0); /* the end */
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_curve_inverse_table_const(&from_flash, &fwd, flash,
                                                                           SYM_INTERVALS, &seal));
        memcpy(flash, built, SYM_LEN * sizeof built[0]);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CRC, hyst_curve_inverse_table_const(
                                                &from_flash, &fwd, flash, SYM_INTERVALS - 1u, &seal));
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&other_fwd, models[1 - m]));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_curve_inverse_table_const(
                                                  &from_flash, &other_fwd, flash, SYM_INTERVALS,
                                                  &seal));
    }
}

static void test_bad_arguments(void)
{
    hyst_curve_t out;
    (void)sealed_everett();
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_table_seal(NULL, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_table_seal(&inv, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_table_seal(&fwd, &seal)); /* not a table */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_everett_inverse_table_const(
                                             NULL, &fwd, flash, ROWS, INTERVALS, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_everett_inverse_table_const(
                                             &out, NULL, flash, ROWS, INTERVALS, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_everett_inverse_table_const(
                                             &out, &fwd, NULL, ROWS, INTERVALS, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_everett_inverse_table_const(
                                             &out, &fwd, flash, ROWS, INTERVALS, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_everett_inverse_table_const(
                                            &out, &fwd, flash, 2u, INTERVALS, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG,
                          hyst_curve_everett_inverse_table_const(&out, &fwd, flash, ROWS, 0u, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_inverse_table_const(&out, &fwd, flash,
                                                                       SYM_INTERVALS, &seal));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&other_fwd, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_curve_inverse_table_const(&out, &other_fwd, flash,
                                                                        SYM_INTERVALS, NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_curve_everett_inverse_table_const(
                                            &out, &other_fwd, flash, ROWS, INTERVALS, &seal));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_everett_table_from_flash_is_the_build);
    RUN_TEST(test_damage_is_refused);
    RUN_TEST(test_another_models_table_is_refused);
    RUN_TEST(test_sealed_garbage_is_refused);
    RUN_TEST(test_resealed_slopes_are_refused);
    RUN_TEST(test_resealed_knot_slope_is_refused);
    RUN_TEST(test_solved_interval_given_its_pieces_is_refused);
    RUN_TEST(test_symmetric_table_from_flash_is_the_build);
    RUN_TEST(test_bad_arguments);
    return UNITY_END();
}
