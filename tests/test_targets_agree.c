/* SPDX-License-Identifier: MIT */
/* The floating-point policy (docs/porting.md, "Floating point"): the f32
 * variant's outputs on a PC (HYST_F32_FMA=1: the C library's fmaf) and on
 * the Cortex-M4F (its vfma) are equal bit for bit, and so are the f64
 * variant's. Each kind runs on fixed signals; the CRC-32 of its outputs'
 * IEEE bits is compared with the host build's, written below: the host
 * test and the Cortex-M4F test under QEMU both assert it, so each equals
 * the other. A change of the library's arithmetic changes the values: run
 * the host test, copy the printed lines here, and the QEMU test must agree. */
#include "ref_everett.h"
#include "support.h"
#include "unity.h"

#include <stdio.h>
#include <string.h>

/* The f32 variant is compared where the library fuses its marked
 * multiply-adds (HYST_F32_FMA, config.h): a target without a fused
 * instruction (the Cortex-M3) rounds them twice, and differs. */

#define CAP 64
#define SAMPLES 20000L
#define ROWS HYST_EVERETT_INV_ROWS
#define INTERVALS HYST_EVERETT_INV_INTERVALS

typedef struct {
    const char *kind;
    unsigned long f32, f64, f32_no_double; /* the last: set up in float (HYST_NO_DOUBLE) */
} expected_t;

/* The host build's checksums (gcc, x86-64, HYST_F32_FMA=1); the last column
 * the library's built with HYST_NO_DOUBLE, whose set-up in float changes the
 * tables and the asymmetric kinds' numbers. */
static const expected_t EXPECTED[] = {
    {"model", 0x7ed7437dul, 0x17d7961aul, 0x7ed7437dul},
    {"compensator table", 0x28df8834ul, 0x5baeb651ul, 0x9e980fc3ul},
    {"asymmetric model", 0xd93dc103ul, 0x0a68943dul, 0xd0eca0d0ul},
    {"asymmetric compensator", 0xe76b3f68ul, 0x6a4fb512ul, 0x7abdce5ful},
    {"asymmetric compensator table", 0xdc85eddbul, 0x31a56264ul, 0xcb5a53e7ul},
    {"PI-10", 0x23bb9837ul, 0xe1e51cadul, 0x23bb9837ul},
    {"creep", 0x03004b7bul, 0xd277fd77ul, 0x03004b7bul},
    {"rate", 0x25a02f6aul, 0xff3a93c9ul, 0x25a02f6aul},
};

static hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
static hyst_real_t x[SAMPLES], y[SAMPLES], out[SAMPLES];
static hyst_real_t inv_table[HYST_INV_TABLE_LEN(HYST_INV_TABLE)];
static hyst_real_t e_table[HYST_EVERETT_INV_TABLE_LEN(ROWS, INTERVALS)];
static hyst_curve_t fwd, inv;
static hyst_t S;

void setUp(void) {}
void tearDown(void) {}

/* A walk over [lo, hi]: runs of small steps (the fast path), reversals
 * every few dozen samples, now and then a long swing (wipe-outs). */
static void walk(double lo, double hi, hyst_real_t *v)
{
    rng_t rng;
    double at = lo + 0.5 * (hi - lo), dir = 1.0;
    long k;
    rng_seed(&rng, 2718u);
    for (k = 0; k < SAMPLES; ++k) {
        if (rng_below(&rng, 40u) == 0u) {
            dir = -dir;
        }
        at += dir * rng_range(&rng, 0.0, 0.004) * (hi - lo);
        if (at >= hi || at <= lo) {
            dir = -dir;
            at = at >= hi ? hi - 0.001 * (hi - lo) : lo + 0.001 * (hi - lo);
        }
        v[k] = (hyst_real_t)at;
    }
}

/* CRC-32 of the outputs' IEEE-754 bits, little-endian octets. */
static unsigned long checksum(const hyst_real_t *v, long n)
{
    unsigned long crc = 0ul;
    long k;
    for (k = 0; k < n; ++k) {
        unsigned char o[sizeof(hyst_real_t)], bits[sizeof(hyst_real_t)];
        size_t i;
        memcpy(bits, &v[k], sizeof bits);
        for (i = 0u; i < sizeof o; ++i) { /* little-endian on every target here */
            o[i] = bits[i];
        }
        crc = hyst_crc32(crc, o, sizeof o);
    }
    return crc;
}

static int failures;

static void agree(unsigned which, const hyst_real_t *v)
{
    const unsigned long got = checksum(v, SAMPLES);
#ifdef HYST_USE_DOUBLE
    const unsigned long want = EXPECTED[which].f64;
    const char *variant = "f64";
#elif defined(HYST_NO_DOUBLE)
    const unsigned long want = EXPECTED[which].f32_no_double;
    const char *variant = "f32 (HYST_NO_DOUBLE)";
#else
    const unsigned long want = EXPECTED[which].f32;
    const char *variant = "f32";
#endif
#if !defined(HYST_USE_DOUBLE) && !HYST_F32_FMA
    printf("%s %s: 0x%08lx (not compared: multiply-adds not fused here)\n", variant,
           EXPECTED[which].kind, got);
    (void)want;
#else
    printf("%s %s: 0x%08lx%s\n", variant, EXPECTED[which].kind, got,
           got == want ? "" : " (differs from the host build's)");
    failures += got != want;
#endif
}

/* The model of Eq. 20, step by step, and its tabulated compensator driven
 * to the model's outputs. */
static void test_polynomial_kinds(void)
{
    long k;
    walk(0.0, 40.0, x);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&S, &paper_eq20, xl, yl, xr, yr, CAP));
    for (k = 0; k < SAMPLES; ++k) {
        y[k] = hyst_step(&S, x[k]);
    }
    agree(0u, y);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_inverse_table(&S, &inv, &paper_eq20, inv_table,
                                                           HYST_INV_TABLE, xl, yl, xr, yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_process(&S, y, out, (size_t)SAMPLES));
    agree(1u, out);
}

/* The asymmetric kind: a fixed E, its model, its solved and tabulated
 * compensators. */
static void test_asymmetric_kinds(void)
{
    rng_t rng;
    hyst_everett_t e;
    long k;
    rng_seed(&rng, 1618u);
    do {
        e = ref_everett_random(&rng);
    } while (hyst_curve_from_everett(&fwd, &e) != HYST_OK);
    walk(CURVE_NUM(fwd.lo), CURVE_NUM(fwd.hi), x);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &fwd, xl, yl, xr, yr, CAP));
    for (k = 0; k < SAMPLES; ++k) {
        y[k] = hyst_step(&S, x[k]);
    }
    agree(2u, y);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_inverse(&inv, &fwd));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &inv, xl, yl, xr, yr, CAP));
    for (k = 0; k < SAMPLES; ++k) {
        out[k] = hyst_step(&S, y[k]);
    }
    agree(3u, out);
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_everett_inverse_table(&inv, &fwd, e_table, ROWS, INTERVALS));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&S, &inv, xl, yl, xr, yr, CAP));
    for (k = 0; k < SAMPLES; ++k) {
        out[k] = hyst_step(&S, y[k]);
    }
    agree(4u, out);
}

/* The PI model of ten operators, a creep term of three lags and a rate
 * term, whose sums and low-pass are marked multiply-adds too. */
static void test_sums(void)
{
    static hyst_real_t r[10], w[10], z[10];
    static const hyst_wide_t tau[3] = {30.0, 300.0, 3000.0}, weight[3] = {HYST_WIDE_C(0.02), HYST_WIDE_C(-0.01),
                                                                          HYST_WIDE_C(0.005)};
    hyst_pi_t P;
    hyst_creep_t C;
    hyst_rate_t R;
    long k;
    unsigned i;
    for (i = 0u; i < 10u; ++i) {
        r[i] = (hyst_real_t)(4.0 * i);
        w[i] = (hyst_real_t)(1.0 / (1.0 + i) - 0.05 * i);
    }
    walk(0.0, 40.0, x);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_init(&P, r, w, z, 10u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_pi_process(&P, x, y, (size_t)SAMPLES));
    agree(5u, y);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&C, 3u, tau, weight, 0.0));
    for (k = 0; k < SAMPLES; ++k) {
        y[k] = hyst_creep_step(&C, x[k]);
    }
    agree(6u, y);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&R, 7.0, HYST_WIDE_C(0.3), 0.0));
    for (k = 0; k < SAMPLES; ++k) {
        y[k] = hyst_rate_step(&R, x[k]);
    }
    agree(7u, y);
}

static void test_every_kind_agrees_with_the_host_build(void)
{
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, failures, "outputs differ from the host build's");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_polynomial_kinds);
    RUN_TEST(test_asymmetric_kinds);
    RUN_TEST(test_sums);
    RUN_TEST(test_every_kind_agrees_with_the_host_build);
    return UNITY_END();
}
