/* SPDX-License-Identifier: MIT */
/* The integer-code variant (hyst/code.h). Its engine is the float variant's
 * engine source, so the rules proven in test_tcm_rules.c carry over if the
 * two agree: they are run side by side on the same histories (random,
 * nested, the paper's signal) and must give the same TP counts at every
 * sample and the same outputs within rounding, and both must match the
 * double reference. Plus what only codes have: exact equality with a stored
 * TP, 1-code loops, clamping, code ranges, RAM per entry. */
#include "hyst/hyst.h"
#include "ref_tcm.h"
#include "support.h"
#include "unity.h"

#define NU12 4096u
#define CAP12 HYST_CAPACITY(NU12)

static hyst_code_word_t cx[2][CAP12];
static hyst_real_t cy[2][CAP12];
static hyst_real_t fx[2][CAP12], fy[2][CAP12];
static hyst_t C;
static hyst_t F;
static ref_tcm_t ref;
static rng_t rng;
static size_t peak_tp; /* of the last agree() */

void setUp(void) { rng_seed(&rng, 4242u); }
void tearDown(void) {}

static hyst_status_t init_code(uint_least32_t lo, uint_least32_t hi, size_t cap)
{
    return hyst_code_init(&C, &paper_eq20, lo, hi, cx[0], cy[0], cx[1], cy[1], cap);
}

static double range(void) { return (double)(C.y_hi.f32 - C.y_lo.f32); }

/* The volts a code stands for, with code_lo..code_hi onto [0, 40]. */
static double volts(unsigned long code, unsigned long lo, unsigned long hi)
{
    return 40.0 * (double)(code - lo) / (double)(hi - lo);
}

enum { WALK, JUMPS, NESTED, PAPER };

/* Next code of a history of the given kind within [lo, hi]. */
static long next_code(int kind, long c, long lo, long hi, long *centre, long i)
{
    const long span = hi - lo;
    switch (kind) {
    case WALK:
        c += (long)rng_below(&rng, (uint32_t)(span / 25 + 1)) - span / 50;
        break;
    case JUMPS:
        c = lo + (long)rng_below(&rng, (uint32_t)(span + 1));
        break;
    case NESTED: { /* alternate towards the last extreme: nesting loops */
        const long prev = c;
        if (i % 97 == 0) {
            c = lo + (long)rng_below(&rng, (uint32_t)(span + 1));
        } else {
            c = c + (long)((double)(*centre - c) * rng_range(&rng, 0.05, 0.95));
        }
        *centre = prev;
        break;
    }
    default:
        break;
    }
    return c < lo ? lo : (c > hi ? hi : c);
}

/* Code and float engines and the reference on the same history; returns the
 * largest |y_code - y_ref| / range. */
static double agree(int kind, unsigned long lo, unsigned long hi, size_t cap, long n)
{
    long c = (long)(lo + hi) / 2, centre = (long)lo, i;
    double worst = 0.0;
    /* 24-bit codes over [0, 40] V are closer than a float's spacing near
     * 40 V: there only the code variant keeps them apart (vs the double
     * reference); the float engine is compared where it can. */
    const int float_tells_codes_apart = sizeof(hyst_real_t) > 4u || hi - lo <= (1ul << 20);
    hyst_code_word_t paper[8192];
    long n_paper = 0;
    peak_tp = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code((uint_least32_t)lo, (uint_least32_t)hi, cap));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&F, &paper_eq20, fx[0], fy[0], fx[1], fy[1], cap));
    ref_init(&ref, paper_eq20_coeffs, 3u, 0.0, 40.0);
    if (kind == PAPER) { /* the paper's levels, rounded to codes, 1-code steps */
        double levels[32];
        const int nl = paper_levels((double)lo, (double)hi, levels);
        long at = (long)lo;
        int k;
        for (k = 0; k < nl && n_paper < 8192; ++k) {
            const long target = (long)(levels[k] + 0.5);
            const long stride = (long)(hi - lo) / 400 + 1;
            while (at != target && n_paper < 8192) {
                at = at < target ? (at + stride > target ? target : at + stride)
                                 : (at - stride < target ? target : at - stride);
                paper[n_paper++] = (hyst_code_word_t)at;
            }
        }
        n = n_paper;
    }
    for (i = 0; i < n; ++i) {
        double yc, yf, yr_, d;
        c = kind == PAPER ? (long)paper[i] : next_code(kind, c, (long)lo, (long)hi, &centre, i);
        yc = (double)hyst_code_step(&C, (uint_least32_t)c);
        yr_ = ref_step(&ref, volts((unsigned long)c, lo, hi));
        TEST_ASSERT_EQUAL_UINT((unsigned)ref_tp_count(&ref), (unsigned)hyst_tp_count(&C));
        if (float_tells_codes_apart) {
            yf = (double)hyst_step(&F, (hyst_real_t)volts((unsigned long)c, lo, hi));
            TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&F), (unsigned)hyst_tp_count(&C));
            TEST_ASSERT_EQUAL_INT(hyst_rising(&F), hyst_rising(&C));
            TEST_ASSERT_DOUBLE_WITHIN(TOL_OF_RANGE * range(), yf, yc);
        }
        peak_tp = hyst_tp_count(&C) > peak_tp ? hyst_tp_count(&C) : peak_tp;
        d = yc > yr_ ? yc - yr_ : yr_ - yc;
        worst = d > worst ? d : worst;
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&C) & HYST_EVENT_FULL);
    return worst / range();
}

static void check(int kind)
{
#if HYST_CODE_BITS >= 24
    static const unsigned long his[] = {4095ul, 65535ul, 16777215ul};
#else
    static const unsigned long his[] = {4095ul, 65535ul};
#endif
    unsigned r;
    for (r = 0; r < sizeof his / sizeof his[0]; ++r) {
        const double e = agree(kind, 0ul, his[r], CAP12, 50000L);
        TEST_PRINTF("kind %d, codes 0..%lu: max |y - y_ref| / range = %g", kind,
                    his[r], e);
        TEST_ASSERT_TRUE(e <= TOL_OF_RANGE);
    }
    /* a user code range not starting at 0 */
    TEST_ASSERT_TRUE(agree(kind, 1000ul, 61000ul, CAP12, 20000L) <= TOL_OF_RANGE);
}

static void test_random_walk_agrees_with_float_engine(void) { check(WALK); }
static void test_random_jumps_agree_with_float_engine(void) { check(JUMPS); }
static void test_nested_loops_agree_with_float_engine(void) { check(NESTED); }

/* The paper's experiment on codes: 14 TPs at the peak, back to none. */
static void test_paper_signal_agrees_with_float_engine(void)
{
    check(PAPER);
    TEST_ASSERT_EQUAL_UINT(14u, (unsigned)peak_tp);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&C));
}

/* Any curve kind: the code span is folded into the curve's argument scale,
 * so an instance of `curve` on 16-bit codes runs as the float engine on the
 * volts those codes stand for, loops stored and closed. */
static void agree_on_codes(const hyst_curve_t *curve)
{
    long i, c = 30000, centre = 0;
    size_t peak = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init_curve(&C, curve, 0u, 65535u, cx[0], cy[0], cx[1],
                                                        cy[1], CAP12));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&F, curve, fx[0], fy[0], fx[1], fy[1], CAP12));
    for (i = 0; i < 20000; ++i) {
        hyst_real_t yc, yf;
        c = next_code(i % 3 == 0 ? NESTED : WALK, c, 0, 65535, &centre, i);
        yc = hyst_code_step(&C, (uint_least32_t)c);
        yf = hyst_step(&F, (hyst_real_t)volts((unsigned long)c, 0ul, 65535ul));
        TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&F), (unsigned)hyst_tp_count(&C));
        TEST_ASSERT_DOUBLE_WITHIN(TOL_OF_RANGE * 7.0, (double)yf, (double)yc);
        peak = hyst_tp_count(&C) > peak ? hyst_tp_count(&C) : peak;
    }
    TEST_ASSERT_TRUE(peak > 4u); /* loops were stored and closed */
}

/* A piecewise-linear f0 (as a PI loading curve) on codes. */
static void test_piecewise_linear_curve_on_codes(void)
{
    static const hyst_real_t px[5] = {HYST_REAL_C(0.0), HYST_REAL_C(10.0), HYST_REAL_C(20.0),
                                      HYST_REAL_C(30.0), HYST_REAL_C(40.0)};
    static const hyst_real_t py[5] = {HYST_REAL_C(0.0), HYST_REAL_C(1.0), HYST_REAL_C(2.5),
                                      HYST_REAL_C(4.5), HYST_REAL_C(7.0)};
    hyst_curve_t pwl;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&pwl, px, py, 5u));
    agree_on_codes(&pwl);
}

/* A spline f0 (its pieces a table, as a tabulated inverse's) on codes. */
static void test_spline_curve_on_codes(void)
{
    static const hyst_spline_t f0 = {
        4, 0.0, 40.0, {0.0, 0.5, 2.5, 6.0, 7.0},
        {HYST_WIDE_C(0.04), HYST_WIDE_C(0.1), HYST_WIDE_C(0.3), HYST_WIDE_C(0.1), HYST_WIDE_C(0.05)}};
    static float table[HYST_SPLINE_TABLE_LEN(4u)];
    hyst_curve_t curve;
    TEST_ASSERT_EQUAL_INT(HYST_OK,
                          hyst_curve_from_spline(&curve, &f0, table, HYST_SPLINE_TABLE_LEN(4u)));
    agree_on_codes(&curve);
}

/* 12-bit codes, the paper's sizing: 4095, 1, 4094, 2, ... fills both arrays
 * exactly and never overflows. */
static void test_adversarial_codes_fill_but_never_overflow(void)
{
    unsigned long k;
    size_t peak = 0;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, NU12 - 1u, CAP12));
    for (k = 1; k <= NU12 / 2u; ++k) {
        (void)hyst_code_step(&C, (uint_least32_t)(NU12 - k));
        (void)hyst_code_step(&C, (uint_least32_t)k);
        peak = hyst_tp_count(&C) > peak ? hyst_tp_count(&C) : peak;
        TEST_ASSERT_TRUE(C.n_ltp <= CAP12 && C.n_rtp <= CAP12);
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&C));
    TEST_ASSERT_EQUAL_UINT(2u * (CAP12 - 1u), (unsigned)peak);
}

/* Equality: a code that returns exactly to a stored TP closes the loop at
 * that very code, with the stored output bit for bit, and the trajectory
 * then is that of a twin that never made the loop. */
static void test_return_exactly_to_a_stored_turning_point(void)
{
    static hyst_code_word_t tx[2][16];
    static hyst_real_t ty[2][16];
    hyst_t T;
    hyst_real_t y_l, y, yt;
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, 65535u, 16u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&T, &paper_eq20, 0u, 65535u, tx[0], ty[0],
                                                  tx[1], ty[1], 16u));
    (void)hyst_code_step(&C, 50000u);
    (void)hyst_code_step(&T, 50000u);
    (void)hyst_code_step(&C, 40000u); /* RTP at 50000 */
    (void)hyst_code_step(&T, 40000u);
    y_l = hyst_code_step(&C, 20000u);
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&C));
    (void)hyst_code_step(&C, 30000u); /* LTP at 20000 */
    (void)hyst_code_step(&C, 25000u); /* RTP at 30000 */
    TEST_ASSERT_EQUAL_UINT(3u, (unsigned)hyst_tp_count(&C));
    /* one code above the LTP: nothing closes yet */
    (void)hyst_code_step(&C, 20001u);
    TEST_ASSERT_EQUAL_UINT(3u, (unsigned)hyst_tp_count(&C));
    /* exactly the LTP: loop (20000, 30000) closed, output = stored LTP output */
    y = hyst_code_step(&C, 20000u);
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&C));
    TEST_ASSERT_EQUAL_MEMORY(&y_l, &y, sizeof y);
    TEST_ASSERT_FALSE(hyst_rising(&C)); /* falling again from RTP 50000 */
    /* back up exactly to the RTP: its loop closes with its output */
    (void)hyst_code_step(&C, 45000u);
    y = hyst_code_step(&C, 50000u);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&C));
    yt = hyst_code_step(&T, 50000u); /* the twin went 50000 -> 40000 -> 50000 */
    TEST_ASSERT_EQUAL_MEMORY(&yt, &y, sizeof y);
    for (i = 0; i < 2000; ++i) { /* identical continuation */
        const uint_least32_t code = (uint_least32_t)rng_below(&rng, 65536u);
        const hyst_real_t a = hyst_code_step(&C, code);
        const hyst_real_t b = hyst_code_step(&T, code);
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    }
    /* exactly code_lo: back at A0 with f0(lo) exactly */
    y = hyst_code_step(&C, 0u);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&C));
    TEST_ASSERT_EQUAL_MEMORY(&C.y_lo.f32, &y, sizeof y);
}

/* Inputs one code apart: a loop of width 1 is closed by the next code, so
 * the memory never grows; repeated codes create no TP. */
static void test_one_code_loops_and_repeats_do_not_grow_memory(void)
{
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, 65535u, 4u));
    (void)hyst_code_step(&C, 30000u);
    for (i = 0; i < 1000; ++i) {
        (void)hyst_code_step(&C, 30000u + (uint_least32_t)(i % 2));
        (void)hyst_code_step(&C, 30000u + (uint_least32_t)(i % 2));
        TEST_ASSERT_TRUE(hyst_tp_count(&C) <= 2u);
    }
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&C));
}

static void test_codes_outside_the_range_are_clamped(void)
{
    hyst_real_t y;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(100u, 4000u, 8u));
    TEST_ASSERT_EQUAL_UINT(100u, (unsigned)hyst_code_input(&C));
    y = hyst_code_step(&C, 5000u);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&C));
    TEST_ASSERT_EQUAL_UINT(4000u, (unsigned)hyst_code_input(&C));
    TEST_ASSERT_DOUBLE_WITHIN(TOL_OF_RANGE * range(), (double)C.y_hi.f32, (double)y);
    (void)hyst_code_step(&C, 2000u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_status(&C));
    y = hyst_code_step(&C, 0u);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_status(&C));
    TEST_ASSERT_EQUAL_UINT(100u, (unsigned)hyst_code_input(&C));
    TEST_ASSERT_EQUAL_MEMORY(&C.y_lo.f32, &y, sizeof y);
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_CLAMPED, hyst_events(&C));
    hyst_clear_events(&C);
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&C));
}

static void test_bad_configuration_is_refused(void)
{
    hyst_poly_t bad = paper_eq20;
    bad.coeffs[2] = HYST_REAL_C(-1.0); /* decreasing */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_init(NULL, &paper_eq20, 0u, 10u, cx[0], cy[0], cx[1], cy[1], 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_init(&C, &paper_eq20, 0u, 10u, NULL, cy[0], cx[1], cy[1], 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_init(&C, &paper_eq20, 0u, 10u, cx[0], cy[0], cx[1], NULL, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, init_code(0u, 10u, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_code(10u, 10u, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_code(11u, 10u, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, init_code(0u, (uint_least32_t)HYST_CODE_MAX + 1u, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, (uint_least32_t)HYST_CODE_MAX, 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOT_INCREASING,
                          hyst_code_init(&C, &bad, 0u, 10u, cx[0], cy[0], cx[1], cy[1], 4u));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_init(&C, NULL, 0u, 10u, cx[0], cy[0], cx[1], cy[1], 4u));
}

/* One entry: a code word plus a real per array; smallest type for the bits. */
static void test_code_words_are_small(void)
{
    TEST_ASSERT_TRUE(sizeof(hyst_code_word_t) * 8u >= (unsigned)HYST_CODE_BITS);
#if HYST_CODE_BITS <= 16
    TEST_ASSERT_TRUE(sizeof(hyst_code_word_t) <= sizeof(uint_least16_t));
#endif
    TEST_ASSERT_EQUAL_UINT((unsigned)(sizeof(hyst_t) + 2u * 32u * (sizeof(hyst_code_word_t) +
                                                                       sizeof(hyst_real_t))),
                           (unsigned)HYST_CODE_RAM(32));
}

static void test_define_macro_and_block_call(void)
{
    HYST_CODE_DEFINE(axis, 16);
    static const hyst_code_word_t in[6] = {1000u, 3000u, 2000u, 2500u, 5000u, 4095u};
    hyst_real_t out[6];
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, HYST_CODE_INIT(axis, &paper_eq20, 0u, 4095u));
    TEST_ASSERT_EQUAL_UINT(8u, (unsigned)axis.capacity);
    TEST_ASSERT_EQUAL_INT(HYST_WARN_CLAMPED, hyst_code_process(&axis, in, out, 6u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, 4095u, 8u));
    for (i = 0; i < 6; ++i) {
        const hyst_real_t y = hyst_code_step(&C, in[i]);
        TEST_ASSERT_EQUAL_MEMORY(&y, &out[i], sizeof y);
    }
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_code_process(&axis, NULL, out, 1u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_process(&axis, NULL, NULL, 0u));
    hyst_reset(&axis);
    TEST_ASSERT_EQUAL_UINT(0u, (unsigned)hyst_tp_count(&axis));
    TEST_ASSERT_EQUAL_UINT(0u, hyst_events(&axis));
}

/* The block call's run loop against per-sample steps on codes: runs on one
 * branch, reversals, nested zigzags (capacity 8 overflows), clamped codes,
 * random chunks; outputs bit for bit, statuses, TPs and events alike. */
static void test_block_call_equals_per_sample_steps(void)
{
    enum { N = 20000 };
    static hyst_code_word_t xs[N];
    static hyst_real_t ya[N], yb[N];
    static hyst_t D;
    static hyst_code_word_t dx_[2][8];
    static hyst_real_t dy_[2][8];
    long x = 2000, dx = 3, amp = 0, centre = 0;
    int zig = 0, worst = HYST_OK;
    size_t i, k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, 4095u, 8u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&D, &paper_eq20, 0u, 4095u, dx_[0], dy_[0],
                                                  dx_[1], dy_[1], 8u));
    for (i = 0u; i < (size_t)N; ++i) {
        const uint32_t r = rng_below(&rng, 64u);
        if (zig > 0) {
            x = centre + ((zig & 1) ? amp : -amp);
            amp = amp * 7 / 8;
            --zig;
        } else if (r == 0u) {
            zig = 30;
            centre = 1000 + (long)rng_below(&rng, 2000u);
            amp = 200 + (long)rng_below(&rng, 700u);
        } else if (r < 3u) {
            x = (long)rng_below(&rng, 4096u);
        } else if (r < 9u) {
            dx = -dx;
        } else if (r == 9u) {
            dx = (long)rng_below(&rng, 9u) - 4;
        }
        x += zig > 0 ? 0 : dx;
        x = x < 0 ? 0 : (x > 4095 ? 4095 : x);
        xs[i] = (hyst_code_word_t)(r == 10u ? 4200u : (unsigned long)x); /* some clamped */
        ya[i] = hyst_code_step(&C, xs[i]);
        worst = hyst_status(&C) > worst ? hyst_status(&C) : worst;
    }
    for (i = 0u; i < (size_t)N; i += k) {
        k = 1u + (size_t)rng_below(&rng, 300u);
        k = i + k > (size_t)N ? (size_t)N - i : k;
        (void)hyst_code_process(&D, &xs[i], &yb[i], k);
    }
    TEST_ASSERT_EQUAL_MEMORY(ya, yb, sizeof ya);
    TEST_ASSERT_EQUAL_UINT(hyst_events(&C), hyst_events(&D));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_CLAMPED | HYST_EVENT_FULL,
                           hyst_events(&C) & (HYST_EVENT_CLAMPED | HYST_EVENT_FULL));
    TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&C), (unsigned)hyst_tp_count(&D));
    TEST_ASSERT_EQUAL_UINT((unsigned)C.n_ltp, (unsigned)D.n_ltp);
    TEST_ASSERT_EQUAL_MEMORY(cx[0], dx_[0], C.n_ltp * sizeof cx[0][0]);
    TEST_ASSERT_EQUAL_MEMORY(cy[0], dy_[0], C.n_ltp * sizeof cy[0][0]);
    TEST_ASSERT_TRUE(worst == HYST_WARN_FULL);
}

/* Snapshots are written once for every variant: an instance over codes
 * saves, restores into a fresh one, and both go on bit for bit. */
static void test_snapshot_of_codes_round_trips(void)
{
    static unsigned char buf[HYST_SNAPSHOT_SIZE(64)];
    static hyst_code_word_t dx[2][64];
    static float dy[2][64];
    hyst_t D;
    size_t len = 0u;
    int i;
    TEST_ASSERT_EQUAL_INT(HYST_OK, init_code(0u, 65535u, 64u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_set_deadband(&C, 3u));
    for (i = 0; i < 3000; ++i) { /* nested loops, some inside the deadband */
        (void)hyst_code_step(&C, (uint_least32_t)rng_below(&rng, 65536u));
    }
    TEST_ASSERT_TRUE(hyst_tp_count(&C) > 2u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&C, buf, sizeof buf, &len));
    TEST_ASSERT_EQUAL_size_t(hyst_snapshot_size(&C), len);
    TEST_ASSERT_EQUAL_HEX8(HYST_VARIANT_CODE, buf[7]);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_init(&D, &paper_eq20, 0u, 65535u, dx[0], dy[0], dx[1],
                                                  dy[1], 64u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_code_set_deadband(&D, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&D, buf, len));
    TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&C), (unsigned)hyst_tp_count(&D));
    TEST_ASSERT_EQUAL_UINT(hyst_code_input(&C), hyst_code_input(&D));
    for (i = 0; i < 3000; ++i) {
        const uint_least32_t code = (uint_least32_t)rng_below(&rng, 65536u);
        const float yc = hyst_code_step(&C, code), yd = hyst_code_step(&D, code);
        TEST_ASSERT_EQUAL_MEMORY(&yc, &yd, sizeof yc);
        TEST_ASSERT_EQUAL_INT(hyst_status(&C), hyst_status(&D));
    }
    /* a real instance cannot take a snapshot of codes */
    buf[7] = HYST_VARIANT_F32;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_snapshot_restore(&D, buf, len));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_walk_agrees_with_float_engine);
    RUN_TEST(test_random_jumps_agree_with_float_engine);
    RUN_TEST(test_nested_loops_agree_with_float_engine);
    RUN_TEST(test_paper_signal_agrees_with_float_engine);
    RUN_TEST(test_piecewise_linear_curve_on_codes);
    RUN_TEST(test_spline_curve_on_codes);
    RUN_TEST(test_adversarial_codes_fill_but_never_overflow);
    RUN_TEST(test_return_exactly_to_a_stored_turning_point);
    RUN_TEST(test_one_code_loops_and_repeats_do_not_grow_memory);
    RUN_TEST(test_codes_outside_the_range_are_clamped);
    RUN_TEST(test_bad_configuration_is_refused);
    RUN_TEST(test_code_words_are_small);
    RUN_TEST(test_define_macro_and_block_call);
    RUN_TEST(test_block_call_equals_per_sample_steps);
    RUN_TEST(test_snapshot_of_codes_round_trips);
    return UNITY_END();
}
