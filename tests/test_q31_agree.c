/* SPDX-License-Identifier: MIT */
/* The fixed-point variants are the same bit for bit whether or not the
 * library has the f64 variant: their set-up runs in hyst_wide_t, not in a
 * real variant's numbers (HYST_ENABLE_F64=0, 4-byte numbers, is what
 * firmware on a core without a double FPU gets; the other tests run with
 * it). Built twice (tests/CMakeLists.txt: q31_agree_f32 with the f64
 * variant, q31_agree_no_f64 without), on the host and on the emulated
 * cores: the CRC-32 of the q31 model's outputs, of the compensator's table
 * and of its drives on fixed codes must be the values written below, which
 * the host build with the f64 variant printed. A change of the q31
 * arithmetic changes them: run that test, copy the printed lines here, and
 * every other build must agree. */
#include "support.h"
#include "unity.h"

#include "hyst/q31.h"

#include <stdio.h>
#include <string.h>

#define SAMPLES 20000L

/* The host build's checksums (HYST_ENABLE_F64=1). */
static const unsigned long EXPECTED_MODEL = 0x735bcceeul;
static const unsigned long EXPECTED_TABLE = 0xf6cbfcc7ul;
static const unsigned long EXPECTED_COMPENSATOR = 0xd80a4e68ul;

HYST_Q31_DEFINE(model, 64);
HYST_Q31_DEFINE_INVERSE(comp, 64);
static uint_least32_t codes[SAMPLES];

void setUp(void) {}
void tearDown(void) {}

/* Codes 0..4095 in runs of small steps, reversals every few dozen samples
 * and now and then a long swing. */
static void walk(void)
{
    rng_t rng;
    long at = 2048, dir = 1, k;
    rng_seed(&rng, 4099u);
    for (k = 0; k < SAMPLES; ++k) {
        if (rng_below(&rng, 40u) == 0u) {
            dir = -dir;
        }
        at += rng_below(&rng, 300u) == 0u ? dir * (long)rng_below(&rng, 2048u)
                                          : dir * (long)rng_below(&rng, 9u);
        at = at < 0 ? 0 : at > 4095 ? 4095 : at;
        codes[k] = (uint_least32_t)at;
    }
}

/* hyst_crc32 continued over a q31 word (4 octets, little-endian). */
static unsigned long crc_word(unsigned long crc, hyst_q31_t v)
{
    const uint_least32_t u = (uint_least32_t)v;
    unsigned char o[4];
    unsigned i;
    for (i = 0u; i < 4u; ++i) {
        o[i] = (unsigned char)((u >> (8u * i)) & 0xffu);
    }
    return hyst_crc32(crc, o, sizeof o);
}

static void check(const char *what, unsigned long got, unsigned long want)
{
    printf("%s: 0x%08lxul (HYST_ENABLE_F64=%d)\n", what, got, (int)HYST_ENABLE_F64);
    TEST_ASSERT_EQUAL_HEX32(want, got);
}

static void test_model_outputs_agree(void)
{
    unsigned long crc = 0ul;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT(model, &paper_eq20, 0u, 4095u));
    for (k = 0; k < SAMPLES; ++k) {
        crc = crc_word(crc, hyst_q31_step(&model, codes[k]));
    }
    check("model", crc, EXPECTED_MODEL);
}

/* The compensator's table, then its drives for desired outputs across the
 * model's output range. */
static void test_compensator_agrees(void)
{
    const hyst_q31_t half = (hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1);
    unsigned long crc = 0ul;
    size_t i;
    long k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT_INVERSE(comp, &paper_eq20, 0u, 4095u));
    for (i = 0u; i < sizeof comp_table / sizeof comp_table[0]; ++i) {
        crc = crc_word(crc, comp_table[i]);
    }
    check("table", crc, EXPECTED_TABLE);
    crc = 0ul;
    for (k = 0; k < SAMPLES; ++k) {
        const hyst_q31_t desired = (hyst_q31_t)((long)codes[k] * 2 * (half / 4096) - half);
        crc = crc_word(crc, hyst_q31_inv_step(&comp, desired));
    }
    check("compensator", crc, EXPECTED_COMPENSATOR);
}

/* The checks too are made in hyst_wide_t: a domain far from 0 whose ends
 * round to one float (1e8 and 1e8 + 1) is a good curve for codes. */
static void test_a_domain_finer_than_a_float_is_accepted(void)
{
    static const hyst_poly_t far = {1u, 1e8, 1e8 + 1.0, {1.0, -1e8}};
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT(model, &far, 0u, 4095u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT_INVERSE(comp, &far, 0u, 4095u));
}

int main(void)
{
    UNITY_BEGIN();
    walk();
    RUN_TEST(test_model_outputs_agree);
    RUN_TEST(test_compensator_agrees);
    RUN_TEST(test_a_domain_finer_than_a_float_is_accepted);
    return UNITY_END();
}
