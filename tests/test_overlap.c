/* SPDX-License-Identifier: MIT */
/* Block calls whose output overlaps their input anywhere but exactly in
 * place would compute from inputs already overwritten: every variant's
 * process() refuses them with HYST_ERR_OVERLAP, writing nothing and leaving
 * the instance as it was. Exactly in place (out == in, same element size)
 * gives the separate-output result bit for bit. */
#include "hyst/hyst.h"
#include "support.h"
#include "unity.h"

#include <string.h>

#define N 32u
#define NU 64u

/* One buffer seen as each element type, so that shifted views can be
 * made without casts. */
static union {
    float f[N + 1u];
    double d[N + 1u];
    hyst_code_word_t w[N + 1u];
    hyst_q31_t q[N + 1u];
    unsigned char bytes[(N + 1u) * sizeof(double)];
} buf;
static unsigned char before[sizeof buf];
static unsigned char model_before[sizeof(hyst_tcm_t)];
static unsigned char pi_before[sizeof(hyst_pi_t)];

HYST_F32_DEFINE(mf, NU);
#if HYST_ENABLE_F64
HYST_F64_DEFINE(md, NU);
#endif
HYST_CODE_DEFINE(mc, NU);
HYST_Q31_DEFINE(mq, NU);
HYST_Q31_DEFINE_INVERSE(mi, NU);
static hyst_pi_t P;
static float pf_z[3], pf_y[N];
#if HYST_ENABLE_F64
static double pd_z[3];
#endif
static float sep_f[N];
static hyst_q31_t sep_q[N];

void setUp(void) {}
void tearDown(void) {}

static void fill(void)
{
    size_t i;
    for (i = 0u; i < sizeof buf.bytes; ++i) {
        buf.bytes[i] = (unsigned char)(i * 37u + 11u);
    }
}

/* The refusal: status, buffer and instance all as they were. */
static void refused(hyst_status_t st, const void *inst, const unsigned char *inst_before,
                    size_t inst_size)
{
    TEST_ASSERT_EQUAL_INT(HYST_ERR_OVERLAP, st);
    TEST_ASSERT_EQUAL_MEMORY(before, buf.bytes, sizeof buf);
    TEST_ASSERT_EQUAL_MEMORY(inst_before, inst, inst_size);
}

static void ramp_f(void)
{
    size_t i;
    for (i = 0u; i <= N; ++i) {
        buf.f[i] = (float)(40.0 * (double)((i * 7u) % N) / (double)N);
    }
    memcpy(before, buf.bytes, sizeof buf);
}

static void test_f32_shifted_views_are_refused(void)
{
    fill();
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_F32_INIT(mf, &paper_eq20));
    ramp_f();
    memcpy(model_before, &mf, sizeof mf);
    refused(hyst_f32_process(&mf, buf.f, buf.f + 1, N), &mf, model_before, sizeof mf);
    refused(hyst_f32_process(&mf, buf.f + 1, buf.f, N), &mf, model_before, sizeof mf);
    /* exactly in place: allowed, and as with a separate output */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_process(&mf, buf.f, sep_f, N));
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_F32_INIT(mf, &paper_eq20));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_process(&mf, buf.f, buf.f, N));
    TEST_ASSERT_EQUAL_MEMORY(sep_f, buf.f, sizeof sep_f);
    /* disjoint views of one buffer stay allowed */
    ramp_f();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_process(&mf, buf.f, buf.f + N / 2u, N / 2u));
}

#if HYST_ENABLE_F64
static void test_f64_shifted_view_is_refused(void)
{
    size_t i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_F64_INIT(md, &paper_eq20));
    for (i = 0u; i <= N; ++i) {
        buf.d[i] = 40.0 * (double)((i * 7u) % N) / (double)N;
    }
    memcpy(before, buf.bytes, sizeof buf);
    memcpy(model_before, &md, sizeof md);
    refused(hyst_f64_process(&md, buf.d, buf.d + 1, N), &md, model_before, sizeof md);
}
#endif

static void codes(void)
{
    size_t i;
    fill();
    for (i = 0u; i <= N; ++i) {
        buf.w[i] = (hyst_code_word_t)((i * 997u) % 4096u);
    }
    memcpy(before, buf.bytes, sizeof buf);
}

static void test_code_and_q31_overlaps_are_refused(void)
{
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_CODE_INIT(mc, &paper_eq20, 0u, 4095u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT(mq, &paper_eq20, 0u, 4095u));
    codes();
    memcpy(model_before, &mc, sizeof mc);
    refused(hyst_code_process(&mc, buf.w, buf.f + 1, N), &mc, model_before, sizeof mc);
    if (sizeof(float) > sizeof(hyst_code_word_t)) { /* in place would outrun the input */
        refused(hyst_code_process(&mc, buf.w, buf.f, N), &mc, model_before, sizeof mc);
    }
    memcpy(model_before, &mq, sizeof mq);
    refused(hyst_q31_process(&mq, buf.w, buf.q + 1, N), &mq, model_before, sizeof mq);
    if (sizeof(hyst_q31_t) > sizeof(hyst_code_word_t)) {
        refused(hyst_q31_process(&mq, buf.w, buf.q, N), &mq, model_before, sizeof mq);
    }
}

static void test_q31_inverse_shifted_view_is_refused(void)
{
    size_t i;
    fill();
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT_INVERSE(mi, &paper_eq20, 0u, 4095u));
    for (i = 0u; i <= N; ++i) {
        buf.q[i] = (hyst_q31_t)(((long)((i * 7u) % N) - (long)(N / 2u)) * (1L << 22));
    }
    memcpy(before, buf.bytes, sizeof buf);
    memcpy(model_before, &mi, sizeof mi);
    refused(hyst_q31_inv_process(&mi, buf.q, buf.q + 1, N), &mi, model_before, sizeof mi);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_process(&mi, buf.q, sep_q, N));
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_Q31_INIT_INVERSE(mi, &paper_eq20, 0u, 4095u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_q31_inv_process(&mi, buf.q, buf.q, N));
    TEST_ASSERT_EQUAL_MEMORY(sep_q, buf.q, sizeof sep_q);
}

static void test_pi_shifted_views_are_refused(void)
{
    static const float r[3] = {0.0f, 0.2f, 0.5f}, w[3] = {1.0f, 0.5f, -0.2f};
    size_t i;
    fill();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_pi_init(&P, r, w, pf_z, 3u));
    for (i = 0u; i <= N; ++i) {
        buf.f[i] = (float)((i * 7u) % N) / (float)N;
    }
    memcpy(before, buf.bytes, sizeof buf);
    memcpy(pi_before, &P, sizeof P);
    refused(hyst_f32_pi_process(&P, buf.f, buf.f + 1, N), &P, pi_before, sizeof P);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_pi_process(&P, buf.f, pf_y, N));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_pi_init(&P, r, w, pf_z, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_pi_process(&P, buf.f, buf.f, N));
    TEST_ASSERT_EQUAL_MEMORY(pf_y, buf.f, sizeof pf_y);
#if HYST_ENABLE_F64
    {
        static const double rd[3] = {0.0, 0.2, 0.5}, wd[3] = {1.0, 0.5, -0.2};
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f64_pi_init(&P, rd, wd, pd_z, 3u));
        for (i = 0u; i <= N; ++i) {
            buf.d[i] = (double)((i * 7u) % N) / (double)N;
        }
        memcpy(before, buf.bytes, sizeof buf);
        memcpy(pi_before, &P, sizeof P);
        refused(hyst_f64_pi_process(&P, buf.d + 1, buf.d, N), &P, pi_before, sizeof P);
    }
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_f32_shifted_views_are_refused);
#if HYST_ENABLE_F64
    RUN_TEST(test_f64_shifted_view_is_refused);
#endif
    RUN_TEST(test_code_and_q31_overlaps_are_refused);
    RUN_TEST(test_q31_inverse_shifted_view_is_refused);
    RUN_TEST(test_pi_shifted_views_are_refused);
    return UNITY_END();
}
