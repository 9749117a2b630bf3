/* SPDX-License-Identifier: MIT */
/* Snapshot/restore: octet format, round trip, and refusal of every damaged
 * snapshot (each bit flipped once, each truncation) with the instance untouched;
 * the same for a creep term's snapshot and a rate term's. */
#include "support.h"
#include "unity.h"

#include <math.h>
#include <string.h>

#define CAP 16
#define BUF HYST_SNAPSHOT_SIZE(CAP)
#define R ((unsigned)sizeof(hyst_real_t)) /* octets per real of the variant */

typedef struct {
    hyst_t S;
    hyst_real_t xl[CAP], yl[CAP], xr[CAP], yr[CAP];
} inst_t;

static inst_t A, B, saved;
static unsigned char snap[BUF], work[BUF];
static size_t snap_len;

void setUp(void) {}
void tearDown(void) {}

static void init_inst(inst_t *I, const hyst_poly_t *f0, size_t cap)
{
    memset(I, 0, sizeof(*I));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init(&I->S, f0, I->xl, I->yl, I->xr, I->yr, cap));
}

/* A walk that leaves several nested loops open (TPs on both sides). */
static void drive(inst_t *I, uint32_t seed, int n)
{
    rng_t rng;
    int k;
    double lo = 0.0, hi = 40.0;
    rng_seed(&rng, seed);
    for (k = 0; k < n; ++k) { /* shrinking triangle: each reversal nests */
        const double t = k % 2 == 0 ? hi : lo;
        (void)hyst_step(&I->S, (hyst_real_t)t);
        (void)hyst_step(&I->S, (hyst_real_t)(t + (k % 2 == 0 ? -0.3 : 0.3)));
        if (k % 2 == 0) {
            hi -= rng_range(&rng, 0.5, 2.0);
        } else {
            lo += rng_range(&rng, 0.5, 2.0);
        }
    }
}

static void keep(const inst_t *I) { memcpy(&saved, I, sizeof(saved)); }

static void assert_untouched(const inst_t *I)
{
    TEST_ASSERT_EQUAL_MEMORY(&saved, I, sizeof(saved));
}

static void take_snapshot(void)
{
    init_inst(&A, &paper_eq20, CAP);
    drive(&A, 7u, 10);
    TEST_ASSERT_TRUE(hyst_tp_count(&A.S) >= 6u);
    memset(snap, 0xA5, sizeof(snap));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
    TEST_ASSERT_EQUAL_size_t(hyst_snapshot_size(&A.S), snap_len);
    /* a differently-driven target: a restore that touched it would show */
    init_inst(&B, &paper_eq20, CAP);
    drive(&B, 99u, 5);
    keep(&B);
}

static void refix_crc(unsigned char *buf, size_t len)
{
    const unsigned long crc = hyst_crc32(0ul, buf, len - 4u);
    buf[len - 4u] = (unsigned char)(crc & 0xFFu);
    buf[len - 3u] = (unsigned char)((crc >> 8) & 0xFFu);
    buf[len - 2u] = (unsigned char)((crc >> 16) & 0xFFu);
    buf[len - 1u] = (unsigned char)((crc >> 24) & 0xFFu);
}

static void test_crc32_matches_the_standard_check_value(void)
{
    static const unsigned char digits[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926ul, hyst_crc32(0ul, digits, 9u));
    /* continuation equals one pass */
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926ul, hyst_crc32(hyst_crc32(0ul, digits, 4u), digits + 4, 5u));
    TEST_ASSERT_EQUAL_HEX32(0ul, hyst_crc32(0ul, digits, 0u));
}

static void test_layout_is_octets_little_endian_ieee(void)
{
    static const hyst_poly_t line = {1u, HYST_REAL_C(0.0), HYST_REAL_C(1.0),
                                     {HYST_REAL_C(1.0), HYST_REAL_C(0.0)}};
    size_t len = 0u;
    unsigned k;
    init_inst(&A, &line, CAP);
    (void)hyst_step(&A.S, HYST_REAL_C(0.5)); /* rising from A0, no TP */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &len));
    TEST_ASSERT_EQUAL_size_t(40u + 2u * R * 2u + 3u * R, len); /* x/y_prev + A0 + book */
    TEST_ASSERT_EQUAL_HEX8(0x48, snap[0]);
    TEST_ASSERT_EQUAL_HEX8(0x59, snap[1]);
    TEST_ASSERT_EQUAL_HEX8(0x53, snap[2]);
    TEST_ASSERT_EQUAL_HEX8(0x53, snap[3]);
    TEST_ASSERT_EQUAL_HEX8(HYST_SNAPSHOT_VERSION, snap[4]);
    TEST_ASSERT_EQUAL_HEX8(3, snap[4]);
    TEST_ASSERT_EQUAL_HEX8(0, snap[5]);
    TEST_ASSERT_EQUAL_HEX8(R, snap[6]);
    TEST_ASSERT_EQUAL_HEX8(HYST_DEFAULT_VARIANT, snap[7]);
    TEST_ASSERT_EQUAL_HEX8(len, snap[8]);
    TEST_ASSERT_EQUAL_HEX8(0, snap[9]);
    TEST_ASSERT_EQUAL_HEX8(1, snap[16]); /* n_ltp: A0 */
    TEST_ASSERT_EQUAL_HEX8(0, snap[20]); /* n_rtp */
    /* x_prev = 0.5: binary32 0x3F000000, binary64 0x3FE0000000000000, little-endian */
    for (k = 0u; k < R; ++k) {
        static const unsigned char half32[4] = {0x00, 0x00, 0x00, 0x3F};
        static const unsigned char half64[8] = {0, 0, 0, 0, 0, 0, 0xE0, 0x3F};
        TEST_ASSERT_EQUAL_HEX8(R == 4u ? half32[k % 4u] : half64[k], snap[32u + k]);
    }
    /* no live merge: level 0xFFFFFFFF right after the TPs */
    for (k = 0u; k < 4u; ++k) {
        TEST_ASSERT_EQUAL_HEX8(0xFF, snap[32u + 4u * R + k]);
    }
    TEST_ASSERT_EQUAL_HEX32(hyst_crc32(0ul, snap, len - 4u),
                            (unsigned long)snap[len - 4u] | ((unsigned long)snap[len - 3u] << 8) |
                                ((unsigned long)snap[len - 2u] << 16) |
                                ((unsigned long)snap[len - 1u] << 24));
}

static void test_round_trip_continues_bit_identically(void)
{
    rng_t rng;
    int k;
    take_snapshot();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
    TEST_ASSERT_EQUAL_size_t(hyst_tp_count(&A.S), hyst_tp_count(&B.S));
    TEST_ASSERT_EQUAL_MEMORY(A.xl, B.xl, A.S.n_ltp * sizeof(hyst_real_t));
    TEST_ASSERT_EQUAL_MEMORY(A.yl, B.yl, A.S.n_ltp * sizeof(hyst_real_t));
    TEST_ASSERT_EQUAL_MEMORY(A.xr, B.xr, A.S.n_rtp * sizeof(hyst_real_t));
    TEST_ASSERT_EQUAL_MEMORY(A.yr, B.yr, A.S.n_rtp * sizeof(hyst_real_t));
    rng_seed(&rng, 5u);
    for (k = 0; k < 2000; ++k) {
        const hyst_real_t x = (hyst_real_t)rng_range(&rng, -2.0, 42.0);
        const hyst_real_t ya = hyst_step(&A.S, x);
        const hyst_real_t yb = hyst_step(&B.S, x);
        TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof(ya));
        TEST_ASSERT_EQUAL_size_t(hyst_tp_count(&A.S), hyst_tp_count(&B.S));
        TEST_ASSERT_EQUAL_INT(hyst_status(&A.S), hyst_status(&B.S));
    }
    TEST_ASSERT_EQUAL_UINT(hyst_events(&A.S), hyst_events(&B.S));
}

/* A domain that starts at -0.0: the anchor A0 = (lo, f0(lo)) is a stored TP
 * and must have the bit pattern a restore gives it (+0), or a restored
 * instance is not the saved one bit for bit (found by fuzz_hyst). */
static void test_negative_zero_lo_round_trips_bit_identically(void)
{
    hyst_poly_t f = paper_eq20;
    f.lo = -0.0;
    init_inst(&A, &f, CAP);
    drive(&A, 3u, 4);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
    init_inst(&B, &f, CAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
    TEST_ASSERT_EQUAL_MEMORY(A.xl, B.xl, A.S.n_ltp * sizeof(hyst_real_t));
    TEST_ASSERT_EQUAL_MEMORY(A.xr, B.xr, A.S.n_rtp * sizeof(hyst_real_t));
}

static void test_status_and_events_survive(void)
{
    init_inst(&A, &paper_eq20, CAP);
    drive(&A, 3u, 4);
    (void)hyst_step(&A.S, HYST_REAL_C(50.0));     /* clamped */
    (void)hyst_step(&A.S, (hyst_real_t)NAN);      /* ignored, status negative */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
    init_inst(&B, &paper_eq20, CAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_status(&B.S));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_CLAMPED | HYST_EVENT_NONFINITE, hyst_events(&B.S));
    TEST_ASSERT_EQUAL_MEMORY(&A.S.y_prev, &B.S.y_prev, sizeof(hyst_real_t));
}

/* Each bit flip must be refused with the error of the field it hits. */
static int expected_for_offset(size_t i)
{
    if (i < 4u || (i >= 8u && i < 12u) || (i >= 16u && i < 24u)) {
        return HYST_ERR_FORMAT; /* magic; length field; counts (length then disagrees) */
    }
    if (i >= 4u && i < 8u) { /* version, real width, variant */
        return HYST_ERR_VERSION;
    }
    return HYST_ERR_CRC;
}

static void test_every_bit_flip_is_refused_and_leaves_the_instance_untouched(void)
{
    size_t i;
    unsigned bit;
    take_snapshot();
    for (i = 0u; i < snap_len; ++i) {
        for (bit = 0u; bit < 8u; ++bit) {
            memcpy(work, snap, snap_len);
            work[i] = (unsigned char)(work[i] ^ (1u << bit));
            TEST_ASSERT_EQUAL_INT_MESSAGE(expected_for_offset(i),
                                          hyst_snapshot_restore(&B.S, work, snap_len),
                                          "flipped bit not refused as expected");
            assert_untouched(&B);
        }
    }
}

static void test_every_truncation_is_refused(void)
{
    size_t n;
    take_snapshot();
    for (n = 0u; n < snap_len; ++n) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, snap, n));
        assert_untouched(&B);
    }
    /* extra octets after a valid snapshot are ignored (fixed-size NVM slots) */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, sizeof(snap)));
}

static void test_other_version_or_real_width_is_refused(void)
{
    take_snapshot();
    memcpy(work, snap, snap_len);
    work[4] = (unsigned char)(HYST_SNAPSHOT_VERSION + 1u);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_snapshot_restore(&B.S, work, snap_len));
    memcpy(work, snap, snap_len);
    work[6] = (unsigned char)(R == 4u ? 8u : 4u);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_snapshot_restore(&B.S, work, snap_len));
    assert_untouched(&B);
}

static void test_other_curve_is_refused(void)
{
    hyst_poly_t other = paper_eq20;
    take_snapshot();
    other.coeffs[2] = HYST_REAL_C(8.6445e-2); /* a tiny change is another curve */
    init_inst(&B, &other, CAP);
    keep(&B);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&B.S, snap, snap_len));
    assert_untouched(&B);
}

static void test_capacity_must_hold_the_saved_points(void)
{
    take_snapshot();
    init_inst(&B, &paper_eq20, 3u);
    keep(&B);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CAPACITY, hyst_snapshot_restore(&B.S, snap, snap_len));
    assert_untouched(&B);
    init_inst(&B, &paper_eq20, A.S.n_ltp); /* exactly enough */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
}

static inst_t scratch;

/* The octets of v, taken from a snapshot of an instance whose x_prev is v. */
static void set_real(unsigned char *p, hyst_real_t v)
{
    inst_t *T = &scratch;
    size_t len = 0u;
    static unsigned char tmp[BUF];
    static const hyst_poly_t line = {1u, HYST_REAL_C(-100.0), HYST_REAL_C(100.0),
                                     {HYST_REAL_C(1.0), HYST_REAL_C(0.0)}};
    init_inst(T, &line, CAP);
    (void)hyst_step(&T->S, v);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&T->S, tmp, sizeof(tmp), &len));
    memcpy(p, tmp + 32, R);
}

/* A snapshot with a valid CRC but a state the model cannot reach. */
static void test_impossible_state_with_valid_crc_is_refused(void)
{
    const size_t ltp = 32u + 2u * R; /* LTP 0 = A0 */
    size_t rtp;
    unsigned char x[8];
    take_snapshot();
    rtp = ltp + 2u * R * A.S.n_ltp;
    /* LTP 1 moved above RTP 0: nesting broken */
    memcpy(work, snap, snap_len);
    memcpy(work + ltp + 2u * R, work + rtp, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* A0 not at lo */
    set_real(x, HYST_REAL_C(1.0));
    memcpy(work, snap, snap_len);
    memcpy(work + ltp, x, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* last input outside the current branch's interval (x_prev = 41 > hi) */
    set_real(x, HYST_REAL_C(41.0));
    memcpy(work, snap, snap_len);
    memcpy(work + 32, x, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* unknown event flag */
    memcpy(work, snap, snap_len);
    work[24] = (unsigned char)(work[24] | 0x80u);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    assert_untouched(&B);
}

static void test_save_refuses_small_buffers_and_null(void)
{
    size_t len = 123u;
    take_snapshot();
    memset(work, 0x5A, sizeof(work));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE, hyst_snapshot_save(&A.S, work, snap_len - 1u, &len));
    TEST_ASSERT_EQUAL_size_t(123u, len);
    TEST_ASSERT_EACH_EQUAL_HEX8(0x5A, work, sizeof(work));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_snapshot_save(NULL, work, sizeof(work), &len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_snapshot_save(&A.S, NULL, sizeof(work), &len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_snapshot_restore(NULL, snap, snap_len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_snapshot_restore(&B.S, NULL, snap_len));
    assert_untouched(&B);
    TEST_ASSERT_TRUE(snap_len <= HYST_SNAPSHOT_SIZE(CAP));
}

/* Bounded memory: a snapshot taken while merges are alive restores their
 * bookkeeping, so both copies continue bit for bit, error bound included
 * (once found by the fuzzer's twin check: fuzz/corpus/regress_restore_merge_alive). */
static void test_live_merges_continue_bit_identically(void)
{
    rng_t r;
    int i;
    init_inst(&A, &paper_eq20, 2u);
    for (i = 0; i < 12; ++i) { /* nested loops: the 2-entry arrays overflow */
        (void)hyst_step(&A.S, (hyst_real_t)(i % 2 == 0 ? 39.0 - i : 1.0 + i));
    }
    TEST_ASSERT_TRUE(hyst_error_bound(&A.S) > 0);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
    init_inst(&B, &paper_eq20, 2u);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
    TEST_ASSERT_EQUAL_MEMORY(&A.S.forgot, &B.S.forgot, sizeof A.S.forgot);
    rng_seed(&r, 5u);
    for (i = 0; i < 3000; ++i) {
        const hyst_real_t x = (hyst_real_t)rng_range(&r, 5.0, 35.0);
        const hyst_real_t ya = hyst_step(&A.S, x);
        const hyst_real_t yb = hyst_step(&B.S, x);
        TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof ya);
        TEST_ASSERT_TRUE(hyst_error_bound(&A.S) == hyst_error_bound(&B.S));
    }
}

/* Every state an instance reaches restores, however many merges its bound
 * adds up: the bound is capped at the output range, which both the full
 * model and the merged one stay in. */
static void test_any_state_after_many_merges_restores(void)
{
    const double height = hyst_poly_eval(&paper_eq20, 40.0) - hyst_poly_eval(&paper_eq20, 0.0);
    rng_t r;
    int i, restored = 0;
    init_inst(&A, &paper_eq20, 2u);
    rng_seed(&r, 11u);
    for (i = 1; i <= 6000; ++i) {
        (void)hyst_step(&A.S, (hyst_real_t)rng_range(&r, 0.0, 40.0));
        TEST_ASSERT_TRUE(hyst_error_bound(&A.S) <= height * (1.0 + 1e-6));
        if (i % 50 == 0) {
            TEST_ASSERT_EQUAL_INT(HYST_OK,
                                  hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
            init_inst(&B, &paper_eq20, 2u);
            TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
            TEST_ASSERT_TRUE(hyst_error_bound(&A.S) == hyst_error_bound(&B.S));
            ++restored;
        }
    }
    TEST_ASSERT_EQUAL_INT(120, restored);
}

/* A deadband's open window (a skipped reversal, its reach saved) continues
 * in an instance that never set a deadband: the restore binds the skip. */
static void test_deadband_window_continues_without_a_deadband_set(void)
{
    static const double walk[] = {20.0, 19.5, 19.8, 19.6, 19.75, 19.65};
    size_t i;
    init_inst(&A, &paper_eq20, CAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_set_deadband(&A.S, (hyst_real_t)1.0));
    for (i = 0u; i < 3u; ++i) { /* 20 stored, the reversal at 19.5 skipped */
        (void)hyst_step(&A.S, (hyst_real_t)walk[i]);
    }
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_tp_count(&A.S));
    TEST_ASSERT_TRUE(hyst_error_bound(&A.S) > 0); /* the skipped loop's bound */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, snap, sizeof(snap), &snap_len));
    init_inst(&B, &paper_eq20, CAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, snap, snap_len));
    for (; i < sizeof walk / sizeof walk[0]; ++i) { /* reversals inside the reach: skipped */
        const hyst_real_t ya = hyst_step(&A.S, (hyst_real_t)walk[i]);
        const hyst_real_t yb = hyst_step(&B.S, (hyst_real_t)walk[i]);
        TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof ya);
        TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&A.S), (unsigned)hyst_tp_count(&B.S));
    }
}

/* A snapshot whose TP is -0.0 (earlier versions stored the input as given)
 * restores as +0.0 and then behaves exactly like the instance that stored
 * +0.0: the search by bit patterns tells -0 from +0 otherwise. */
static void test_negative_zero_turning_point_restores_as_zero(void)
{
    static const hyst_poly_t f0 = {3u, HYST_REAL_C(-2.0), HYST_REAL_C(2.0),
                                   {HYST_REAL_C(0.3333333), HYST_REAL_C(0.5), HYST_REAL_C(1.0),
                                    HYST_REAL_C(0.0)}};
    const size_t ltp1 = 32u + 2u * R * 2u; /* header, last sample, A0 */
    static const hyst_real_t after[6] = {HYST_REAL_C(0.5), HYST_REAL_C(0.0), HYST_REAL_C(0.25),
                                         HYST_REAL_C(-0.5), HYST_REAL_C(1.0), HYST_REAL_C(0.0)};
    hyst_real_t zero;
    size_t len, k;
    init_inst(&A, &f0, CAP);
    (void)hyst_step(&A.S, HYST_REAL_C(1.0));
    (void)hyst_step(&A.S, HYST_REAL_C(-0.0));
    (void)hyst_step(&A.S, HYST_REAL_C(0.5)); /* LTP at zero, inside the RTP at 1 */
    TEST_ASSERT_EQUAL_UINT(1u, (unsigned)hyst_ltp_count(&A.S));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, work, sizeof(work), &len));
    for (k = 0u; k < R; ++k) {
        TEST_ASSERT_EQUAL_UINT(0u, work[ltp1 + k]); /* stored as +0 */
    }
    work[ltp1 + R - 1u] = 0x80u; /* sign bit: -0 */
    refix_crc(work, len);
    init_inst(&B, &f0, CAP);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, work, len));
    zero = B.xl[1];
    TEST_ASSERT_EQUAL_MEMORY(&A.xl[1], &zero, sizeof zero);
    for (k = 0u; k < 6u; ++k) {
        const hyst_real_t ya = hyst_step(&A.S, after[k]), yb = hyst_step(&B.S, after[k]);
        TEST_ASSERT_EQUAL_MEMORY(&ya, &yb, sizeof ya);
        TEST_ASSERT_EQUAL_UINT((unsigned)hyst_tp_count(&A.S), (unsigned)hyst_tp_count(&B.S));
    }
}

/* Values the model cannot produce, written with a recomputed CRC: an output
 * far outside f0's range, an unknown status, a huge error bound. */
static void test_forged_values_with_a_valid_crc_are_refused(void)
{
    const size_t ltp = 32u + 2u * R; /* LTP 0 = A0 */
    size_t book;
    unsigned char v[8];
    take_snapshot();
    book = ltp + 2u * R * (A.S.n_ltp + A.S.n_rtp);
    set_real(v, HYST_REAL_C(1e30));
    /* the output of LTP 1 */
    memcpy(work, snap, snap_len);
    memcpy(work + ltp + 2u * R + R, v, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* the last output */
    memcpy(work, snap, snap_len);
    memcpy(work + 32u + R, v, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* the error bound of the live merges */
    memcpy(work, snap, snap_len);
    memcpy(work + book + 4u, v, R);
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    /* a status no sample leaves */
    memcpy(work, snap, snap_len);
    work[28] = 0x34u;
    work[29] = 0x12u;
    refix_crc(work, snap_len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_snapshot_restore(&B.S, work, snap_len));
    assert_untouched(&B);
}

/* Two piecewise-linear curves with the same ends but another shape are two
 * curves: a snapshot of one does not restore into the other. */
static void test_piecewise_linear_curve_identity_covers_every_point(void)
{
    static const hyst_real_t x[3] = {0, HYST_REAL_C(20.0), HYST_REAL_C(40.0)};
    static const hyst_real_t y1[3] = {0, HYST_REAL_C(1.0), HYST_REAL_C(6.0)};
    static const hyst_real_t y2[3] = {0, HYST_REAL_C(2.0), HYST_REAL_C(6.0)};
    static hyst_curve_t c1, c2;
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&c1, x, y1, 3u));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_curve_from_pwl(&c2, x, y2, 3u));
    memset(&A, 0, sizeof A);
    memset(&B, 0, sizeof B);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&A.S, &c1, A.xl, A.yl, A.xr, A.yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&B.S, &c2, B.xl, B.yl, B.xr, B.yr, CAP));
    (void)hyst_step(&A.S, HYST_REAL_C(30.0));
    (void)hyst_step(&A.S, HYST_REAL_C(10.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_save(&A.S, work, sizeof work, &len));
    keep(&B);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_snapshot_restore(&B.S, work, len));
    assert_untouched(&B);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_init_curve(&B.S, &c1, B.xl, B.yl, B.xr, B.yr, CAP));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_snapshot_restore(&B.S, work, len));
}

/* ---- Creep snapshots ---- */

static hyst_creep_t KA, KB, Kkeep;
static const hyst_wide_t creep_tau[2] = {300, 4000};
static const hyst_wide_t creep_w[2] = {(hyst_wide_t)0.05, (hyst_wide_t)-0.02};

/* Two lags, stepped on a triangle with a NaN among the samples. */
static size_t creep_snapshot(void)
{
    size_t len = 0u;
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KA, 2u, creep_tau, creep_w, 3.0));
    for (k = 0; k < 700; ++k) {
        (void)hyst_creep_step(&KA, (hyst_real_t)(k % 200 < 100 ? k % 100 : 100 - k % 100) /
                                       HYST_REAL_C(2.5));
    }
    (void)hyst_creep_step(&KA, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_save(&KA, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_size_t(hyst_creep_snapshot_size(&KA), len);
    TEST_ASSERT_EQUAL_size_t(32u + 2u * R, len);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 2u, creep_tau, creep_w, 0.0));
    Kkeep = KB;
    return len;
}

static void assert_creep_untouched(void)
{
    TEST_ASSERT_EQUAL_MEMORY(&Kkeep, &KB, sizeof KB);
}

static void test_creep_round_trip_continues_bit_identically(void)
{
    const size_t len = creep_snapshot();
    unsigned char again[HYST_CREEP_SNAPSHOT_SIZE];
    size_t len2 = 0u;
    int k;
    TEST_ASSERT_EQUAL_UINT8_ARRAY("HYSC", snap, 4);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_restore(&KB, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_creep_status(&KB));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_creep_events(&KB));
    TEST_ASSERT_EQUAL_MEMORY(KA.state, KB.state, sizeof KA.state);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_save(&KB, again, sizeof again, &len2));
    TEST_ASSERT_EQUAL_size_t(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(snap, again, len);
    for (k = 0; k < 500; ++k) {
        const hyst_real_t x = (hyst_real_t)(k % 37) + HYST_REAL_C(0.25);
        const hyst_real_t ca = hyst_creep_step(&KA, x), cb = hyst_creep_step(&KB, x);
        TEST_ASSERT_EQUAL_MEMORY(&ca, &cb, sizeof ca);
    }
    /* an instance that did not restore continues otherwise */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 2u, creep_tau, creep_w, 0.0));
    TEST_ASSERT_FALSE(hyst_creep_output(&KB) == hyst_creep_output(&KA));
}

/* A drive beyond the lags' limit (ignored, HYST_ERR_DOMAIN) is a state a
 * snapshot keeps like any other: it restores, status and events included. */
static void test_creep_snapshot_after_a_drive_beyond_the_limit(void)
{
    unsigned char buf[HYST_CREEP_SNAPSHOT_SIZE];
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KA, 2u, creep_tau, creep_w, 3.0));
    (void)hyst_creep_step(&KA, (hyst_real_t)2.0);
    /* finite, beyond type max / 4 */
    (void)hyst_creep_step(&KA, (hyst_real_t)(sizeof(hyst_real_t) == sizeof(float) ? 3e38 : 1e308));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_creep_status(&KA));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_save(&KA, buf, sizeof buf, &len));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 2u, creep_tau, creep_w, 0.0));
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_restore(&KB, buf, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_DOMAIN, hyst_creep_status(&KB));
    TEST_ASSERT_EQUAL_MEMORY(KA.state, KB.state, sizeof KA.state);
}

/* Each bit flip is refused with its field's error; the instance unchanged. */
static void test_creep_every_bit_flip_and_truncation_is_refused(void)
{
    const size_t len = creep_snapshot();
    size_t i;
    unsigned bit;
    for (i = 0u; i < len; ++i) {
        for (bit = 0u; bit < 8u; ++bit) {
            const int expected = i < 4u || (i >= 8u && i < 12u) || (i >= 16u && i < 20u)
                                     ? HYST_ERR_FORMAT /* magic, length, count */
                                     : i < 8u ? HYST_ERR_VERSION : HYST_ERR_CRC;
            memcpy(work, snap, len);
            work[i] = (unsigned char)(work[i] ^ (1u << bit));
            TEST_ASSERT_EQUAL_INT_MESSAGE(expected, hyst_creep_snapshot_restore(&KB, work, len),
                                          "flipped bit not refused as expected");
            assert_creep_untouched();
        }
    }
    for (i = 0u; i < len; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_creep_snapshot_restore(&KB, snap, i));
        assert_creep_untouched();
    }
    /* extra octets after it are ignored (fixed-size NVM slots) */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_snapshot_restore(&KB, snap, sizeof snap));
}

/* Values no instance can hold, under a valid CRC: refused as FORMAT. */
static void test_creep_forged_values_with_a_valid_crc_are_refused(void)
{
    const size_t len = creep_snapshot();
    static const size_t at[4] = {20u, 24u, 26u, 28u + R - 1u};
    static const unsigned char value[4] = {0x04u, 0x05u, 0x01u, 0x7Fu};
    unsigned i;
    for (i = 0u; i < 4u; ++i) { /* an unknown event, status 5, reserved, a state's exponent */
        memcpy(work, snap, len);
        work[at[i]] = value[i];
        if (i == 3u) { /* every exponent bit: infinity or NaN */
            work[at[i] - 1u] = (unsigned char)(work[at[i] - 1u] | (R == 4u ? 0x80u : 0xF0u));
        }
        refix_crc(work, len);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_creep_snapshot_restore(&KB, work, len));
        assert_creep_untouched();
    }
    memcpy(work, snap, len);
    work[4] = (unsigned char)(HYST_CREEP_SNAPSHOT_VERSION + 1u);
    refix_crc(work, len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_creep_snapshot_restore(&KB, work, len));
    assert_creep_untouched();
}

/* Another creep term (a weight, a time constant, one lag fewer), another
 * variant, an instance not initialised, NULL, a small buffer. */
static void test_creep_other_term_and_bad_calls_are_refused(void)
{
    const size_t len = creep_snapshot();
    const hyst_wide_t w2[2] = {creep_w[0], (hyst_wide_t)-0.021};
    const hyst_wide_t tau2[2] = {creep_tau[0], 4001};
    hyst_creep_t blank;
    unsigned char small[HYST_CREEP_SNAPSHOT_SIZE];
    size_t got = 99u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 2u, creep_tau, w2, 0.0));
    Kkeep = KB;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_creep_snapshot_restore(&KB, snap, len));
    assert_creep_untouched();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 2u, tau2, creep_w, 0.0));
    Kkeep = KB;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_creep_snapshot_restore(&KB, snap, len));
    assert_creep_untouched();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_creep_init(&KB, 1u, creep_tau, creep_w, 0.0));
    Kkeep = KB;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_creep_snapshot_restore(&KB, snap, len));
    assert_creep_untouched();
#if HYST_ENABLE_F64
    {
        hyst_creep_t other;
#ifdef HYST_USE_DOUBLE
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_creep_init(&other, 2u, creep_tau, creep_w, 0.0));
#else
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f64_creep_init(&other, 2u, creep_tau, creep_w, 0.0));
#endif
        TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_creep_snapshot_restore(&other, snap, len));
    }
#endif
    memset(&blank, 0, sizeof blank);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_creep_snapshot_restore(&blank, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_creep_snapshot_save(&blank, small, sizeof small, &got));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_creep_snapshot_size(&blank));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_creep_snapshot_size(NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_snapshot_restore(NULL, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_snapshot_restore(&KA, NULL, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_snapshot_save(NULL, small, sizeof small, &got));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_creep_snapshot_save(&KA, NULL, sizeof small, &got));
    memset(small, 0xA5, sizeof small);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE, hyst_creep_snapshot_save(&KA, small, len - 1u, &got));
    TEST_ASSERT_EQUAL_size_t(99u, got);
    TEST_ASSERT_EACH_EQUAL_HEX8(0xA5, small, sizeof small);
}

/* ---- Rate snapshots ---- */

static hyst_rate_t QA, QB, Qkeep;

/* A rate term of 5 samples stepped on a triangle, a NaN last. */
static size_t rate_snapshot(void)
{
    size_t len = 0u;
    int k;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QA, 5.0, -0.75, 3.0));
    for (k = 0; k < 333; ++k) {
        (void)hyst_rate_step(&QA, (hyst_real_t)(k % 200 < 100 ? k % 100 : 100 - k % 100) /
                                      HYST_REAL_C(2.5));
    }
    (void)hyst_rate_step(&QA, (hyst_real_t)NAN);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_snapshot_save(&QA, snap, sizeof snap, &len));
    TEST_ASSERT_EQUAL_size_t(hyst_rate_snapshot_size(&QA), len);
    TEST_ASSERT_EQUAL_size_t(28u + 2u * R, len);
    TEST_ASSERT_TRUE(len <= HYST_RATE_SNAPSHOT_SIZE);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QB, 5.0, -0.75, 0.0));
    Qkeep = QB;
    return len;
}

static void assert_rate_untouched(void)
{
    TEST_ASSERT_EQUAL_MEMORY(&Qkeep, &QB, sizeof QB);
}

static void test_rate_round_trip_continues_bit_identically(void)
{
    const size_t len = rate_snapshot();
    unsigned char again[HYST_RATE_SNAPSHOT_SIZE];
    size_t len2 = 0u;
    int k;
    TEST_ASSERT_EQUAL_UINT8_ARRAY("HYSR", snap, 4);
    TEST_ASSERT_FALSE(hyst_rate_output(&QB) == hyst_rate_output(&QA)); /* v != 0: it counts */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_snapshot_restore(&QB, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NONFINITE, hyst_rate_status(&QB));
    TEST_ASSERT_EQUAL_UINT(HYST_EVENT_NONFINITE, hyst_rate_events(&QB));
    TEST_ASSERT_EQUAL_MEMORY(&QA.last, &QB.last, sizeof QA.last);
    TEST_ASSERT_EQUAL_MEMORY(&QA.state, &QB.state, sizeof QA.state);
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_snapshot_save(&QB, again, sizeof again, &len2));
    TEST_ASSERT_EQUAL_size_t(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(snap, again, len);
    for (k = 0; k < 500; ++k) {
        const hyst_real_t x = (hyst_real_t)(k % 37) + HYST_REAL_C(0.25);
        const hyst_real_t ra = hyst_rate_step(&QA, x), rb = hyst_rate_step(&QB, x);
        TEST_ASSERT_EQUAL_MEMORY(&ra, &rb, sizeof ra);
    }
}

/* Each bit flip is refused with its field's error; the instance unchanged. */
static void test_rate_every_bit_flip_and_truncation_is_refused(void)
{
    const size_t len = rate_snapshot();
    size_t i;
    unsigned bit;
    for (i = 0u; i < len; ++i) {
        for (bit = 0u; bit < 8u; ++bit) {
            const int expected = i < 4u || (i >= 8u && i < 12u) ? HYST_ERR_FORMAT /* magic, length */
                                 : i < 8u ? HYST_ERR_VERSION
                                          : HYST_ERR_CRC;
            memcpy(work, snap, len);
            work[i] = (unsigned char)(work[i] ^ (1u << bit));
            TEST_ASSERT_EQUAL_INT_MESSAGE(expected, hyst_rate_snapshot_restore(&QB, work, len),
                                          "flipped bit not refused as expected");
            assert_rate_untouched();
        }
    }
    for (i = 0u; i < len; ++i) {
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_rate_snapshot_restore(&QB, snap, i));
        assert_rate_untouched();
    }
    /* extra octets after it are ignored (fixed-size NVM slots) */
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_snapshot_restore(&QB, snap, sizeof snap));
}

/* Values no instance can hold, under a valid CRC: refused as FORMAT. */
static void test_rate_forged_values_with_a_valid_crc_are_refused(void)
{
    const size_t len = rate_snapshot();
    static const size_t at[5] = {16u, 20u, 22u, 24u + R - 1u, 24u + 2u * R - 1u};
    static const unsigned char value[5] = {0x04u, 0x05u, 0x01u, 0x7Fu, 0x7Fu};
    unsigned i;
    /* an unknown event, status 5, reserved, p's exponent, v's exponent */
    for (i = 0u; i < 5u; ++i) {
        memcpy(work, snap, len);
        work[at[i]] = value[i];
        if (i >= 3u) { /* every exponent bit: infinity or NaN */
            work[at[i] - 1u] = (unsigned char)(work[at[i] - 1u] | (R == 4u ? 0x80u : 0xF0u));
        }
        refix_crc(work, len);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_rate_snapshot_restore(&QB, work, len));
        assert_rate_untouched();
    }
    for (i = 0u; i < 2u; ++i) { /* finite but beyond the drive limit (p) or twice it (v) */
        memcpy(work, snap, len);
        work[24u + (i + 1u) * R - 1u] = 0x7Fu; /* exponent just below infinity's */
        work[24u + (i + 1u) * R - 2u] = (unsigned char)(R == 4u ? 0x7Fu : 0xEFu);
        refix_crc(work, len);
        TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_rate_snapshot_restore(&QB, work, len));
        assert_rate_untouched();
    }
    memcpy(work, snap, len);
    work[4] = (unsigned char)(HYST_RATE_SNAPSHOT_VERSION + 1u);
    refix_crc(work, len);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_rate_snapshot_restore(&QB, work, len));
    assert_rate_untouched();
}

/* Another rate term (weight, time constant), another variant, a creep
 * snapshot, an instance not initialised, NULL, a small buffer. */
static void test_rate_other_term_and_bad_calls_are_refused(void)
{
    const size_t len = rate_snapshot();
    hyst_rate_t blank;
    unsigned char small[HYST_RATE_SNAPSHOT_SIZE];
    size_t got = 99u;
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QB, 5.0, HYST_WIDE_C(-0.7501), 0.0));
    Qkeep = QB;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_rate_snapshot_restore(&QB, snap, len));
    assert_rate_untouched();
    TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_rate_init(&QB, 6.0, -0.75, 0.0));
    Qkeep = QB;
    TEST_ASSERT_EQUAL_INT(HYST_ERR_CURVE, hyst_rate_snapshot_restore(&QB, snap, len));
    assert_rate_untouched();
#if HYST_ENABLE_F64
    {
        hyst_rate_t other;
#ifdef HYST_USE_DOUBLE
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f32_rate_init(&other, 5.0, -0.75, 0.0));
#else
        TEST_ASSERT_EQUAL_INT(HYST_OK, hyst_f64_rate_init(&other, 5.0, -0.75, 0.0));
#endif
        TEST_ASSERT_EQUAL_INT(HYST_ERR_VERSION, hyst_rate_snapshot_restore(&other, snap, len));
    }
#endif
    (void)creep_snapshot(); /* a creep term's snapshot in snap: not a rate term's */
    TEST_ASSERT_EQUAL_INT(HYST_ERR_FORMAT, hyst_rate_snapshot_restore(&QB, snap, sizeof snap));
    assert_rate_untouched();
    memset(&blank, 0, sizeof blank);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_rate_snapshot_restore(&blank, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_ARG, hyst_rate_snapshot_save(&blank, small, sizeof small, &got));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_rate_snapshot_size(&blank));
    TEST_ASSERT_EQUAL_size_t(0u, hyst_rate_snapshot_size(NULL));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_snapshot_restore(NULL, snap, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_snapshot_restore(&QA, NULL, len));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_snapshot_save(NULL, small, sizeof small, &got));
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NULL, hyst_rate_snapshot_save(&QA, NULL, sizeof small, &got));
    memset(small, 0xA5, sizeof small);
    TEST_ASSERT_EQUAL_INT(HYST_ERR_NOSPACE,
                          hyst_rate_snapshot_save(&QA, small, hyst_rate_snapshot_size(&QA) - 1u,
                                                  &got));
    TEST_ASSERT_EQUAL_size_t(99u, got);
    TEST_ASSERT_EACH_EQUAL_HEX8(0xA5, small, sizeof small);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc32_matches_the_standard_check_value);
    RUN_TEST(test_layout_is_octets_little_endian_ieee);
    RUN_TEST(test_round_trip_continues_bit_identically);
    RUN_TEST(test_negative_zero_lo_round_trips_bit_identically);
    RUN_TEST(test_status_and_events_survive);
    RUN_TEST(test_every_bit_flip_is_refused_and_leaves_the_instance_untouched);
    RUN_TEST(test_every_truncation_is_refused);
    RUN_TEST(test_other_version_or_real_width_is_refused);
    RUN_TEST(test_live_merges_continue_bit_identically);
    RUN_TEST(test_any_state_after_many_merges_restores);
    RUN_TEST(test_deadband_window_continues_without_a_deadband_set);
    RUN_TEST(test_other_curve_is_refused);
    RUN_TEST(test_capacity_must_hold_the_saved_points);
    RUN_TEST(test_impossible_state_with_valid_crc_is_refused);
    RUN_TEST(test_save_refuses_small_buffers_and_null);
    RUN_TEST(test_negative_zero_turning_point_restores_as_zero);
    RUN_TEST(test_forged_values_with_a_valid_crc_are_refused);
    RUN_TEST(test_piecewise_linear_curve_identity_covers_every_point);
    RUN_TEST(test_creep_round_trip_continues_bit_identically);
    RUN_TEST(test_creep_snapshot_after_a_drive_beyond_the_limit);
    RUN_TEST(test_creep_every_bit_flip_and_truncation_is_refused);
    RUN_TEST(test_creep_forged_values_with_a_valid_crc_are_refused);
    RUN_TEST(test_creep_other_term_and_bad_calls_are_refused);
    RUN_TEST(test_rate_round_trip_continues_bit_identically);
    RUN_TEST(test_rate_every_bit_flip_and_truncation_is_refused);
    RUN_TEST(test_rate_forged_values_with_a_valid_crc_are_refused);
    RUN_TEST(test_rate_other_term_and_bad_calls_are_refused);
    return UNITY_END();
}
