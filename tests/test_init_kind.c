/* SPDX-License-Identifier: MIT */
/* hyst_*_init_kind(): a curve of every kind, initialised with its kind
 * named, runs as hyst_*_init_curve() runs it, bit for bit; the other kinds
 * refuse it and leave the instance as it was. */
#include "support.h"
#include "unity.h"

#include <string.h>

#define CAP 64
#define SAMPLES 4000
#define KINDS 11
#define INTERVALS 64
#define E_ROWS 4
#define E_INTERVALS 16

static const hyst_kind_t kind_by_index[KINDS] = {
    hyst_kind_poly,          hyst_kind_pwl,            hyst_kind_inverse,        hyst_kind_inverse_table,
    hyst_kind_everett,       hyst_kind_everett_inverse, hyst_kind_everett_inverse_table,
    hyst_kind_everett_grid,  hyst_kind_everett_grid_inverse, hyst_kind_spline,
    hyst_kind_spline_inverse_table};

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t x[SAMPLES], want[SAMPLES], got[SAMPLES];
static hyst_real_t inv_table[HYST_INV_TABLE_LEN(INTERVALS)];
static hyst_real_t e_table[HYST_EVERETT_INV_TABLE_LEN(E_ROWS, E_INTERVALS)];
static hyst_real_t grid_table[HYST_EVERETT_GRID_TABLE_LEN(3)];
static hyst_real_t spline_table[HYST_SPLINE_TABLE_LEN(3)];
static hyst_real_t spline_inv_table[HYST_INV_TABLE_LEN(INTERVALS)];
static hyst_curve_t poly, poly_inv, poly_table, pwl, pwl_inv, everett, everett_inv, everett_table,
    grid, grid_inv, spline, spline_inv, spline_table_curve;
static hyst_t S;

void setUp(void) {}
void tearDown(void) {}

/* A curve and the index of its kind in kind_by_index. */
typedef struct {
    const char *name;
    const hyst_curve_t *curve;
    unsigned kind;
} case_t;

static void prepare(void)
{
    static const hyst_poly_t f0 = {3, 0.0, 40.0,
                                   {HYST_WIDE_C(-6.1876e-6), HYST_WIDE_C(1.1949e-3),
                                    HYST_WIDE_C(8.6444e-2), HYST_WIDE_C(5.8517e-1)}};
    static const hyst_real_t px[4] = {0, 10, 25, 40}, py[4] = {0, 2, 3, 7};
    static const hyst_everett_t e = {
        3, 0.0, 40.0, 1.0, {{10.0, 1.0, 0.5, 0}, {2.0, 0.5, 0, 0}, {1.0, 0, 0, 0}, {0, 0, 0, 0}}};
    static const hyst_everett_grid_t g = {3, {0.0, 10.0, 25.0, 40.0}, 0.5, {1, 2, 1, 0.5, 3, 1}};
    static const hyst_spline_t sp = {
        3, 0.0, 40.0, {0.0, 1.0, 4.0, 5.0},
        {HYST_WIDE_C(0.05), HYST_WIDE_C(0.2), HYST_WIDE_C(0.1), HYST_WIDE_C(0.02)}};
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_poly(&poly, &f0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&poly_inv, &poly));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse_table(&poly_table, &poly, inv_table, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&pwl, px, py, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&pwl_inv, &pwl));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett(&everett, &e));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&everett_inv, &everett));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_inverse_table(&everett_table, &everett, e_table,
                                                                    E_ROWS, E_INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_everett_grid(&grid, &g, grid_table,
                                                                HYST_EVERETT_GRID_TABLE_LEN(3)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_everett_grid_inverse(&grid_inv, &grid));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_spline(&spline, &sp, spline_table,
                                                          HYST_SPLINE_TABLE_LEN(3)));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse(&spline_inv, &spline));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_spline_inverse_table(&spline_table_curve, &spline,
                                                                   spline_inv_table, INTERVALS));
}

#ifdef HYST_USE_DOUBLE
#define REAL_OF(num) ((double)(num).f64)
#else
#define REAL_OF(num) ((double)(num).f32)
#endif

/* Inputs over the curve's domain: reversals every few dozen samples. */
static void walk(const hyst_curve_t *c)
{
    const double lo = REAL_OF(c->lo), hi = REAL_OF(c->hi);
    rng_t rng;
    double at = 0.5 * (lo + hi), dir = 1.0;
    int k;
    rng_seed(&rng, 31u);
    for (k = 0; k < SAMPLES; ++k) {
        if (rng_below(&rng, 40u) == 0u) {
            dir = -dir;
        }
        at += dir * (hi - lo) * 0.004 * (1.0 + (double)rng_below(&rng, 4u));
        at = at < lo ? lo : (at > hi ? hi : at);
        x[k] = (hyst_real_t)at;
    }
}

static void run(hyst_real_t *y)
{
    int k;
    for (k = 0; k < SAMPLES; ++k) {
        y[k] = hyst_step(&S, x[k]);
    }
}

static void test_every_kind_runs_as_init_curve_runs_it(void)
{
    const case_t cases[] = {
        {"poly", &poly, 0u},           {"poly inverse", &poly_inv, 2u},
        {"pwl", &pwl, 1u},             {"pwl inverse", &pwl_inv, 1u},
        {"inverse table", &poly_table, 3u}, {"everett", &everett, 4u},
        {"everett inverse", &everett_inv, 5u}, {"everett table", &everett_table, 6u},
        {"grid", &grid, 7u},           {"grid inverse", &grid_inv, 8u},
        {"spline", &spline, 9u},       {"spline inverse", &spline_inv, 9u},
        {"spline table", &spline_table_curve, 10u}};
    size_t i;
    unsigned k;
    prepare();
    for (i = 0u; i < sizeof cases / sizeof cases[0]; ++i) {
        const case_t *c = &cases[i];
        walk(c->curve);
        TEST_ASSERT_EQUAL_INT_MESSAGE(HYST_OK, hyst_init_curve(&S, c->curve, xl, yl, xr, yr, CAP),
                                      c->name);
        run(want);
        for (k = 0u; k < KINDS; ++k) {
            hyst_t before;
            hyst_status_t st;
            if (k == c->kind) {
                continue;
            }
            memcpy(&before, &S, sizeof S);
            st = hyst_init_kind(&S, c->curve, kind_by_index[k], xl, yl, xr, yr, CAP);
            TEST_ASSERT_EQUAL_INT_MESSAGE(HYST_ERR_CURVE, st, c->name);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &S, sizeof S, c->name); /* nothing written */
        }
        TEST_ASSERT_EQUAL_INT_MESSAGE(
            HYST_OK, hyst_init_kind(&S, c->curve, kind_by_index[c->kind], xl, yl, xr, yr, CAP),
            c->name);
        run(got);
        TEST_ASSERT_TRUE_MESSAGE(got[SAMPLES - 1] != got[0] || got[SAMPLES / 2] != got[0], c->name); /* the outputs move */
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, c->name);
    }
}

static void test_a_kind_of_another_variant_is_refused(void)
{
#if HYST_ENABLE_F64
#ifdef HYST_USE_DOUBLE
    const hyst_kind_t other = hyst_f32_kind_poly;
#else
    const hyst_kind_t other = hyst_f64_kind_poly;
#endif
    hyst_t before;
    prepare();
    memset(&S, 0, sizeof S);
    memcpy(&before, &S, sizeof S);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_init_kind(&S, &poly, other, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_MEMORY(&before, &S, sizeof S);
#endif
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_init_kind(&S, &poly, NULL, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL,
                          hyst_init_kind(NULL, &poly, hyst_kind_poly, xl, yl, xr, yr, CAP));
}

#ifndef HYST_USE_DOUBLE
/* The code variant runs the f32 curves with kinds of its own. */
static void test_the_code_variant_names_its_kinds_too(void)
{
    static hyst_code_word_t cxl[CAP], cxr[CAP];
    static const hyst_curve_t *curves[] = {&everett, &spline, &poly_table};
    static const hyst_kind_t kinds[] = {hyst_code_kind_everett, hyst_code_kind_spline,
                                        hyst_code_kind_inverse_table};
    size_t i;
    int k;
    prepare();
    for (i = 0u; i < sizeof curves / sizeof curves[0]; ++i) {
        hyst_t before;
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&S, curves[i], 0u, 4095u, cxl, yl, cxr,
                                                            yr, CAP));
        for (k = 0; k < SAMPLES; ++k) {
            want[k] = hyst_code_step(&S, (uint_least32_t)((k * 7) % 4096));
        }
        memcpy(&before, &S, sizeof S);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_code_init_kind(&S, curves[i], hyst_code_kind_poly,
                                                                  0u, 4095u, cxl, yl, cxr, yr, CAP));
        TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_code_init_kind(&S, curves[i],
                                                                  hyst_f32_kind_everett, 0u, 4095u,
                                                                  cxl, yl, cxr, yr, CAP));
        TEST_ASSERT_EQUAL_MEMORY(&before, &S, sizeof S);
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_kind(&S, curves[i], kinds[i], 0u, 4095u, cxl,
                                                           yl, cxr, yr, CAP));
        for (k = 0; k < SAMPLES; ++k) {
            got[k] = hyst_code_step(&S, (uint_least32_t)((k * 7) % 4096));
        }
        TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof want);
    }
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_kind_runs_as_init_curve_runs_it);
    RUN_TEST(test_a_kind_of_another_variant_is_refused);
#ifndef HYST_USE_DOUBLE
    RUN_TEST(test_the_code_variant_names_its_kinds_too);
#endif
    return UNITY_END();
}
