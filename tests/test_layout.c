/* SPDX-License-Identifier: MIT */
/* The layout fingerprint covers every option that changes a public struct.
 * This file is compiled with HYST_NO_DOUBLE (hyst_wide_t is float: its
 * hyst_poly_t and hyst_everett_t are half the library's) against a library
 * built without it: every init and curve constructor must refuse the call
 * (HYST_ERR_LAYOUT) before reading a struct whose size differs. The PI
 * model's init takes the caller's layout like the others. */
#include <string.h>

#include "unity.h"

#include "hyst/hyst.h"

#ifndef HYST_NO_DOUBLE
#error "test_layout.c: build with HYST_NO_DOUBLE, against a library built without it"
#endif

#define CAP 16
static float xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_tcm_t S;
static const hyst_poly_t f0 = {3, 0.0f, 40.0f, {-6.1876e-6f, 1.1949e-3f, 8.6444e-2f, 5.8517e-1f}};

void setUp(void) {}
void tearDown(void) {}

static void test_a_poly_of_floats_is_refused(void)
{
    hyst_curve_t c;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_init(&S, &f0, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_UINT(0u, S.variant); /* nothing written */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_curve_from_poly(&c, &f0));
}

static void test_an_everett_of_floats_is_refused(void)
{
    hyst_curve_t c;
    hyst_everett_t e;
    memset(&e, 0, sizeof e);
    e.degree = 1u;
    e.hi = 1.0f;
    e.e[0][0] = 1.0f;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_curve_from_everett(&c, &e));
}

static void test_the_pi_init_takes_the_layout(void)
{
    static const float r[2] = {0.0f, 1.0f}, w[2] = {1.0f, 0.5f};
    float z[2];
    hyst_pi_t P;
    memset(&P, 0, sizeof P);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_pi_init(&P, r, w, z, 2u));
    TEST_ASSERT_EQUAL_UINT(0u, P.variant);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_LAYOUT, hyst_f32_pi_init_(&P, r, w, z, 2u, HYST_LAYOUT ^ 1ul));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_poly_of_floats_is_refused);
    RUN_TEST(test_an_everett_of_floats_is_refused);
    RUN_TEST(test_the_pi_init_takes_the_layout);
    return UNITY_END();
}
