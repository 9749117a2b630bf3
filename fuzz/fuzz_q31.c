/* SPDX-License-Identifier: MIT */
/* libFuzzer harness for the fixed-point variant (hyst/q31.h): the q31 model
 * (hyst_q31_*: integer codes in, q out) and its compensator (hyst_q31_inv_*:
 * desired outputs in q in, the drive in fixed-point codes out). Arbitrary
 * bytes -> a curve, a code range, a capacity, a deadband and a sequence of
 * codes (model mode) or of desired outputs (compensator mode, flag bit1),
 * fed to:
 *   M   q31 model: gets the blocks (hyst_q31_process) and the immediate
 *       twins of T's requests
 *   T   its twin, sample by sample: M and T must stay bit-identical
 *   Z   q31 model never given a deadband, initialised from the same model
 *       sealed (hyst_q31_init_sealed): bit-identical to T while T's
 *       deadband has always been 0
 *   K   q31 compensator: gets the blocks (hyst_q31_inv_process, in place
 *       or not) and the immediate twins of KT's requests
 *   KT  its twin, sample by sample: K and KT must stay bit-identical
 *   D   the double engine (hyst_init) on the same f0: the init statuses
 *   ref   tests/support/ref_tcm.c, double, unlimited memory: on the volts
 *         of the codes (model), or on the volts of the drive (compensator:
 *         the forward model of the round trip)
 *   rid   the same reference with f0 = identity on the desired outputs: the
 *         compensator's TP count (the rules only see the inputs)
 * Units: q (q31.h) = 2^-28 of the output range R = f0(hi) - f0(lo); S_d =
 * (code_hi - code_lo) << F drive units span the domain X = hi - lo.
 *
 * Checked (model mode):
 *   - init status consistent with the double engine on the same f0: a
 *     capacity below 2 refused first (HYST_ERR_CAPACITY); a curve the double
 *     engine refuses refused with its status (or HYST_ERR_DOMAIN when the
 *     code range is bad too: the order is not documented); else
 *     HYST_ERR_DOMAIN for an empty or too wide code range; else HYST_OK or
 *     HYST_ERR_COEFF, never anything else: q31 may refuse more, never
 *     accept what double refuses. HYST_ERR_COEFF checked independently
 *     (structured curves): with the harness's own Taylor shift f0(lo + t X)
 *     = sum g_j t^j, a curve accepted has sum |g_j| <= 128 (1 + 2^-10) R and
 *     one refused sum |g_j| >= 128 (1 - 2^-10) R (q31.h: refused when
 *     Horner's partial sums could pass 2^31 = 128 R in the coefficients'
 *     format; 2^-10 covers c = N round(2^30 / N) / 2^30, |c - 1| <= 2^-15,
 *     raised to the 9th power at most, and the +1/2 +1 roundings), both
 *     within 300 times a bound on the two Taylor shifts' rounding;
 *     init errors write nothing (memcmp of the instance and its arrays);
 *   - after init: output -2^27, input code_lo, no TP, error bound 0;
 *     hyst_q31_rounding_bound() = q31.h's (n / 2 + n - 1) c^n 2^4 + 1, c as
 *     above, up to the 2 units of rounding up (c < 1 counted as 1, the
 *     proof's v_max); hyst_q31_to_real() maps -2^27 and 2^27 onto f0(lo) and
 *     f0(hi) within 8 eps of their size;
 *   - every sample: clamping reported exactly for codes outside [code_lo,
 *     code_hi] (status HYST_WARN_CLAMPED, or HYST_WARN_FULL on the same
 *     sample; event HYST_EVENT_CLAMPED), hyst_q31_input() = the clamped code,
 *     hyst_q31_output() = the output; the output never moves against the
 *     input and stays when the input does (the engine's monotone guard);
 *     counts, order, nesting of the stored codes, neighbours at least the
 *     deadband apart (as fuzz_code.c); hyst_q31_error_bound() >= 0;
 *   - while nothing was forgotten (never full, deadband 0 since the last
 *     reset), structured curves: the TP count equals the reference's, the
 *     error bound is exactly 0, and
 *       |hyst_q31_to_real(f0, q) - y_ref| <= ((TPs + 1) rb + 1/2) R / 2^28
 *                                            + (TPs + 2) A + 8 eps max|y|,
 *     rb = hyst_q31_rounding_bound(): q31.h's bound of the q31 output
 *     against the exact real value (one rb per stored TP and one for the
 *     branch, 1/2 for the rounding to q); A = 2 horner_bound(f0) + 8 eps
 *     max(|lo|, |hi|) max f0': the double reference's own rounding per TP it
 *     hangs on (two evaluations of f0 per branch, the rounding of the volts
 *     and of the reference's argument times the steepest slope); 8 eps
 *     max|y|: hyst_q31_to_real()'s own. Raw curves are not compared (the
 *     reference itself may be wrong);
 *   - Z bit-identical to T while T's deadband was always 0;
 *   - blocks: hyst_q31_process() on M equals T's steps bit for bit (outputs
 *     and live state), its status HYST_WARN_FULL if any sample overflowed
 *     (seen on T), else HYST_WARN_CLAMPED if any was clamped, else HYST_OK;
 *   - deadband: widths beyond code_hi - code_lo and 0xFFFFFFFF refused
 *     (HYST_ERR_ARG, set and request), the instance untouched; the widest
 *     accepted; requests (hyst_q31_request_deadband(), with a reset and a
 *     clear-events request) posted on T while M gets nothing: pending until
 *     T's next step, whose output is still M's (tcm.h, "Concurrency":
 *     applied at the end of the step, after its output), then applied: M
 *     given the immediate calls after the same step (deadband, clear,
 *     reset, in that order) is bit-identical to T, and T's deadband is the
 *     width requested;
 *   - snapshots refused (HYST_ERR_ARG, size 0, q31.h) with the state
 *     untouched; the compensator's calls refuse a model (HYST_ERR_ARG, 0).
 * Checked (compensator mode, flag bit1):
 *   - init status in the documented order: the model's status on the same
 *     f0 and codes (curve error, HYST_ERR_DOMAIN, HYST_ERR_COEFF: "as
 *     hyst_q31_init()"), then HYST_ERR_ARG for intervals outside
 *     1..HYST_Q31_INV_MAX_INTERVALS, then HYST_ERR_CAPACITY; errors write
 *     nothing to the instance, the curve or the table (memcmp);
 *   - after init: drive 0, desired input -2^27, F = hyst_q31_inv_drive_bits()
 *     the largest with (code_hi - code_lo) 2^F <= 2^28, the table's scale
 *     16 N, the measured error hyst_curve_inverse_error() within
 *     HYST_INV_TABLE_TOL plus 8 drive units (q31.h), the rounding bound its
 *     measured error plus 1 in drive units (q31.h), hyst_q31_inv_code() of
 *     0 and S_d code_lo and code_hi;
 *   - every sample: desired outputs in and beyond [-2^27, 2^27] clamped
 *     exactly as the model's codes; hyst_q31_inv_input() the clamped value;
 *     the drive within [0, S_d]; the drive never moves against the desired
 *     output and stays when it does (q31.h: "the drive never steps back");
 *     hyst_q31_inv_code() = code_lo + ((drive + 2^(F-1)) >> F) within
 *     code_lo..code_hi; the error bound >= 0, and exactly 0 while nothing
 *     was forgotten, when the TP count also equals rid's;
 *   - round trip, structured curves, while nothing was forgotten (a merge or
 *     a deadband: skipped, as fuzz_models.c's fuzz_inverse() does): the
 *     drive as an input of f0 (lo + drive X / S_d) through ref gives the
 *     clamped desired output back within (TPs + 2) E + A' (q), TPs the larger
 *     of K's and ref's count (each stored TP's drive carries the error of one
 *     evaluation into the branches from it: fuzz_inverse()'s depth), with
 *     one evaluation's error E = s (4 e S_d + 2) + rb1 + 1:
 *       s    = max f0' X / S_d 2^28 / R, the steepest output step per drive
 *              unit (max f0' bounded from above by the Bernstein
 *              coefficients of f0' on [lo, hi], the harness's own);
 *       e    = hyst_curve_inverse_error(inv), the table's measured worst
 *              error / S_d (it includes the 8 units of the fixed-point
 *              evaluation's truncations); times 4, as fuzz_inverse() allows
 *              the real table, for the error between init's 16 probes per
 *              interval;
 *       2    drive units: the drive's own resolution (a marked interval
 *              rounds v's share of S_d to an integer, and its bisection
 *              stops at adjacent v, S_d / 2^30 <= 1/4 unit apart);
 *       rb1  = (3 n / 2 - 1) 2^4 + 2 q: q31.h's bound of the model's
 *              fixed-point G with c = 1, which a marked interval (next to a
 *              flat point) solves instead of the table;
 *       1    q: the table's knots sit on the library's G(1), the check
 *              converts with the harness's R and y_mid (their rounding,
 *              about eps R, is far below a q);
 *     A' = (TPs + 2) A + 8 eps max|y| as in the model's check, in q;
 *   - blocks (hyst_q31_inv_process(), in place with a flag bit) equal the
 *     steps bit for bit, statuses as the model's; the deadband (in q:
 *     refused below 0 and above 2^28, set and request) and requests as the
 *     model's; NULL probes; the model's calls refuse a compensator.
 *
 * Input layout (reads past the end yield zeros):
 *   [0] flags: bit0 raw config, bit1 compensator mode, bit2 NULL and
 *       wrong-variant probes, bit3 raw code range (24-bit numbers: DOMAIN
 *       errors), bit4 deadband on, bit5 invalid deadband probes, bit6 with
 *       [1] >= 240: capacity 4100 (deep stacks), bit7 (compensator) a
 *       16-bit interval count
 *   [1] capacity (byte % 20: 0 and 1 invalid, 2..19 the bounded use)
 *   config (fuzz_common.h); code range (structured: a shift byte, a 16-bit
 *   span >> shift, a 16-bit code_lo; raw: two 24-bit numbers);
 *   compensator: intervals (a byte, 0 invalid; bit7: 16 bits % 4097);
 *   deadband (bit4: model 16 bits % (span / 4 + 1) codes; compensator 24
 *   bits times 4 q, below 2^26); bit5: a byte, the invalid width's offset; then
 *   opcodes:
 *   0xF0 reset all, 0xF1 n block (n % 64; compensator: bit6 of n in place),
 *   0xF2 n nested reversals (16 n deep at capacity 4100, n % 40 else;
 *   converging on the middle), 0xF3 b requests (b bit0 deadband, bit3 an
 *   invalid one instead, bit1 clear events, bit2 reset) and one step, 0xF4..
 *   p m accessors, a snapshot of the twin (T, KT) restored into the block
 *   instance (M, K): with octet p len / 256 xor (m | 1) refused, nothing
 *   written; whole, the same state, then bit for bit at every later sample;
 *   and clear events; any other byte one code
 *   (model: next_code) or desired output (next_desired) of kind op & 7. */
#include "hyst/hyst.h"
#include "ref_tcm.h"
#include "fuzz_common.h"

#ifndef HYST_USE_DOUBLE
#error "the differential harness compares against the double reference and engine"
#endif

#define MAX_CAP 4100u /* flag bit6: deep stacks */
#define MAX_SAMPLES 4096u
#define MAX_INTERVALS 4096u /* the 16-bit interval count's range (flag bit7) */
#define QHALF ((hyst_q31_t)1 << (HYST_Q31_SPAN_BITS - 1))
#define QSPAN ((hyst_q31_t)1 << HYST_Q31_SPAN_BITS)
#define Q_MIN ((hyst_q31_t)(-2147483647L - 1L))
#define Q_MAX ((hyst_q31_t)2147483647L)

enum { F_RAW = 1, F_COMP = 2, F_PROBES = 4, F_RAWRANGE = 8, F_DEADBAND = 16, F_BADDB = 32,
       F_DEEP = 64, F_WIDE_N = 128 };

typedef struct { /* the model: codes in, q out */
    hyst_t S;
    hyst_code_word_t xl[MAX_CAP], xr[MAX_CAP];
    hyst_q31_t yl[MAX_CAP], yr[MAX_CAP];
} minst_t;

typedef struct { /* the compensator: desired outputs (q) in, drives out */
    hyst_t S;
    hyst_q31_t xl[MAX_CAP], yl[MAX_CAP], xr[MAX_CAP], yr[MAX_CAP];
} kinst_t;

typedef struct { /* for its init status only */
    hyst_t S;
    double xl[2], yl[2], xr[2], yr[2];
} dinst_t;

static minst_t M, T, Z, keepm;
static kinst_t K, KT, keepk;
static dinst_t D;
static hyst_curve_t inv, inv_t, keep_inv;
static hyst_q31_t table[HYST_Q31_INV_TABLE_LEN(MAX_INTERVALS)];
static hyst_q31_t table_t[HYST_Q31_INV_TABLE_LEN(MAX_INTERVALS)];
static hyst_q31_t keep_table[HYST_Q31_INV_TABLE_LEN(MAX_INTERVALS)];
static unsigned char snap[HYST_SNAPSHOT_SIZE(MAX_CAP)];
static ref_tcm_t ref, rid;

/* How often the checks had something to check, and how close they came:
 * FUZZ_Q31_STATS=1 prints these at exit (reported in docs/reliability.md). */
static unsigned long n_init_ok, n_coeff, n_exact, n_forgot, n_clamped, n_blocks, n_requests;
static unsigned long n_kinit_ok, n_ksamples, n_round_trip, n_kforgot, n_marked;
static double worst_model, worst_rt; /* largest error / tolerance */
static double worst_model_err, worst_model_tps; /* at the worst ratio: error in q, TPs */
static long over_model; /* largest model output beyond [-2^27, 2^27], in q (not a check) */

static void print_stats(void)
{
    fprintf(stderr,
            "fuzz_q31: model inits %lu (COEFF %lu), samples exact %lu (worst %.3g of the "
            "tolerance: %.3g q at %.0f TPs), "
            "after forgetting %lu, clamped %lu, blocks %lu, request steps %lu; compensator inits "
            "%lu (with marked intervals %lu), samples %lu, round trips %lu (worst %.3g of the "
            "tolerance), after forgetting %lu; model outputs up to %ld q beyond [-2^27, 2^27]\n",
            n_init_ok, n_coeff, n_exact, worst_model, worst_model_err, worst_model_tps, n_forgot,
            n_clamped, n_blocks, n_requests,
            n_kinit_ok, n_marked, n_ksamples, n_round_trip, worst_rt, n_kforgot, over_model);
}

/* ---- curve facts, computed here in double, independently of the library ---- */

typedef struct {
    double g[HYST_MAX_DEGREE + 1]; /* f0(lo + t X) = sum g[j] t^j, t in [0, 1] */
    double shift_err;              /* a bound on the rounding of the g[j] (summed) */
    double abs_sum, range;         /* sum |g_j| (j >= 1), sum g_j = f0(hi) - f0(lo) */
    double slope_max;              /* >= max f0' on [lo, hi], in output per input unit */
} facts_t;

static facts_t curve_facts(const hyst_poly_t *f)
{
    facts_t q;
    double p[HYST_MAX_DEGREE + 1], b[HYST_MAX_DEGREE], scale = 1.0, acc = 0.0, abs_a = 0.0;
    const double span = f->hi - f->lo, mag = fabs(f->lo) + span;
    const unsigned n = f->degree;
    unsigned i, j;
    memset(&q, 0, sizeof q);
    if (n < 1u || n > HYST_MAX_DEGREE) return q;
    for (j = 0; j <= n; ++j) p[j] = f->coeffs[j];
    for (i = 0; i < n; ++i) { /* p(lo + s), highest power first (Taylor shift) */
        for (j = 1; j <= n - i; ++j) p[j] += f->lo * p[j - 1u];
    }
    for (j = 0; j <= n; ++j) { /* p[n - j] multiplies s^j, s = t X */
        q.g[j] = p[n - j] * scale;
        scale *= span;
    }
    /* each shifted coefficient is a sum of binom(k, j) c_k lo^(k-j) formed in
     * n roundings; over j, at most sum |c_k| (|lo| + X)^k of magnitude */
    for (j = 0; j <= n; ++j) acc = acc * mag + fabs(f->coeffs[j]);
    q.shift_err = 8.0 * (double)(n + 1u) * DBL_EPSILON * acc;
    for (j = 1; j <= n; ++j) {
        q.abs_sum += fabs(q.g[j]);
        q.range += q.g[j];
    }
    /* G'(t) = sum a_i t^i, a_i = (i + 1) g_(i+1), i < n; its Bernstein
     * coefficients of degree n - 1 bound it from above on [0, 1]:
     * b_i = sum_(k <= i) C(i, k) / C(n - 1, k) a_k */
    for (i = 0; i < n; ++i) {
        double s = 0.0, cik = 1.0, cnk = 1.0;
        unsigned k;
        for (k = 0; k <= i; ++k) {
            if (k > 0u) {
                cik = cik * (double)(i - k + 1u) / (double)k;
                cnk = cnk * (double)(n - 1u - k + 1u) / (double)k;
            }
            s += cik / cnk * (double)(k + 1u) * q.g[k + 1u];
        }
        b[i] = s;
        abs_a += (double)(i + 1u) * fabs(q.g[i + 1u]);
    }
    q.slope_max = b[0];
    for (i = 1; i < n; ++i) q.slope_max = fmax(q.slope_max, b[i]);
    /* the Bernstein sums' own rounding, and that of the g_j, times n */
    q.slope_max = fmax(q.slope_max, 0.0) + 16.0 * (double)(n + 1u) * DBL_EPSILON * abs_a +
                  (double)n * q.shift_err;
    q.slope_max /= span; /* per input unit */
    return q;
}


/* ---- desired outputs, the compensator's inputs ---- */

static hyst_q31_t last_desired;

static hyst_q31_t next_desired(reader_t *r, unsigned op)
{
    long v;
    switch (op & 7u) {
    case 0:
    case 1: /* anywhere in the range: 28 bits */
        return (hyst_q31_t)((long)((rd_u24(r) << 4) | (op >> 4)) - (long)QHALF);
    case 2: /* a small move (1 q or 4096 q per step of the byte) */
        v = (long)last_desired + (long)(signed char)rd_u8(r) * ((op & 8u) ? 4096L : 1L);
        return (hyst_q31_t)v; /* |v| < 2^27 + 2^20: no overflow */
    case 3: return (op & 8u) ? QHALF : -QHALF;
    case 4: /* beyond the range: clamped */
        if (op & 8u) return (op & 16u) ? Q_MIN : Q_MAX;
        if (op & 32u) return (hyst_q31_t)((long)(rd_u24(r) << 7) * ((op & 16u) ? -1L : 1L));
        return (op & 16u) ? -QHALF - 1 - (hyst_q31_t)rd_u8(r) : QHALF + 1 + (hyst_q31_t)rd_u8(r);
    case 5: return last_desired;
    default: return -QHALF + (hyst_q31_t)((QSPAN / 255) * (hyst_q31_t)rd_u8(r));
    }
}

/* The identity reference on desired outputs (the compensator's rules). */
static void rid_init(void)
{
    static const double id[2] = {1.0, 0.0};
    ref_init(&rid, id, 1u, (double)-QHALF, (double)QHALF);
}

/* f0 by Horner on the raw coefficients, as the reference evaluates it. */
static double poly_at(const hyst_poly_t *f, double x)
{
    double acc = 0.0;
    unsigned k;
    for (k = 0; k <= f->degree; ++k) acc = acc * x + f->coeffs[k];
    return acc;
}

static hyst_q31_t clamp_q(hyst_q31_t q) { return q < -QHALF ? -QHALF : q > QHALF ? QHALF : q; }

/* ---- state comparisons and invariants ---- */

/* Live state bit for bit (entries past the counts are stale: not compared). */
static int same_model(const minst_t *a, const minst_t *b)
{
    return a->S.n_ltp == b->S.n_ltp && a->S.n_rtp == b->S.n_rtp &&
           memcmp(a->xl, b->xl, a->S.n_ltp * sizeof(a->xl[0])) == 0 &&
           memcmp(a->yl, b->yl, a->S.n_ltp * sizeof(a->yl[0])) == 0 &&
           memcmp(a->xr, b->xr, a->S.n_rtp * sizeof(a->xr[0])) == 0 &&
           memcmp(a->yr, b->yr, a->S.n_rtp * sizeof(a->yr[0])) == 0 &&
           a->S.y_prev.q31 == b->S.y_prev.q31 && a->S.forgot.q31 == b->S.forgot.q31 &&
           a->S.db_err.q31 == b->S.db_err.q31 && a->S.status == b->S.status &&
           a->S.events == b->S.events && a->S.deadband.code == b->S.deadband.code &&
           hyst_q31_input(&a->S) == hyst_q31_input(&b->S) &&
           hyst_q31_error_bound(&a->S) == hyst_q31_error_bound(&b->S);
}

static int same_comp(const kinst_t *a, const kinst_t *b)
{
    return a->S.n_ltp == b->S.n_ltp && a->S.n_rtp == b->S.n_rtp &&
           memcmp(a->xl, b->xl, a->S.n_ltp * sizeof(a->xl[0])) == 0 &&
           memcmp(a->yl, b->yl, a->S.n_ltp * sizeof(a->yl[0])) == 0 &&
           memcmp(a->xr, b->xr, a->S.n_rtp * sizeof(a->xr[0])) == 0 &&
           memcmp(a->yr, b->yr, a->S.n_rtp * sizeof(a->yr[0])) == 0 &&
           a->S.y_prev.q31 == b->S.y_prev.q31 && a->S.forgot.q31 == b->S.forgot.q31 &&
           a->S.db_err.q31 == b->S.db_err.q31 && a->S.status == b->S.status &&
           a->S.events == b->S.events && a->S.deadband.q31 == b->S.deadband.q31 &&
           hyst_q31_inv_input(&a->S) == hyst_q31_inv_input(&b->S) &&
           hyst_q31_inv_error_bound(&a->S) == hyst_q31_inv_error_bound(&b->S);
}

/* The clear-events (b bit1) and reset (b bit2) requests of opcode 0xF3 on
 * the sample-by-sample twin S (model or compensator: the same calls), after
 * its deadband request; returns the bits it posted (2, 4). */
static unsigned post_clear_and_reset(hyst_t *S, unsigned b)
{
    unsigned posted = 0u;
    if (b & 2u) {
        CHECK(hyst_request_clear_events(S) == HYST_OK);
        posted |= 2u;
    }
    if (b & 4u) {
        CHECK(hyst_request_reset(S) == HYST_OK);
        posted |= 4u;
    }
    return posted;
}

/* A snapshot of the sample-by-sample twin `from` restored into the block
 * instance `to` (the whole of which, arrays included, is `whole`): first
 * with one octet damaged (the reader's choice): refused, nothing written;
 * then whole: OK, and the caller checks that the two are the same state
 * (they then go on bit for bit, checked at every later sample). */
static void snapshot_into(const hyst_t *from, hyst_t *to, const void *whole, void *keep,
                          size_t size, reader_t *r)
{
    const unsigned pick = rd_u8(r), mask = rd_u8(r) | 1u;
    size_t len = 0u, at;
    CHECK(hyst_snapshot_save(from, snap, sizeof(snap), &len) == HYST_OK);
    CHECK(len == hyst_snapshot_size(from) && len <= sizeof(snap));
    at = (size_t)pick * len / 256u;
    snap[at] = (unsigned char)(snap[at] ^ mask);
    memcpy(keep, whole, size);
    CHECK(hyst_snapshot_restore(to, snap, len) != HYST_OK);
    CHECK(memcmp(keep, whole, size) == 0);
    snap[at] = (unsigned char)(snap[at] ^ mask);
    CHECK(hyst_snapshot_restore(to, snap, len) == HYST_OK);
}

/* Counts, order and nesting of the stored inputs, the deadband spacing (a
 * reversal nearer than the deadband is never stored; a merge keeps that);
 * all entries when whole is set or the stack is shallow, else the top four
 * (below the top, a stack that cannot merge, capacity 4100, never changes).
 * I: a model or a compensator (codes or desired outputs, compared as long). */
#define CHECK_STACK(I, lo_, hi_, db_, input_, whole)                                        \
    do {                                                                                    \
        const hyst_t *S_ = &(I)->S;                                                         \
        const size_t nl_ = S_->n_ltp, nr_ = S_->n_rtp;                                      \
        const size_t from_ = (whole) || nl_ < 36u ? 0u : nl_ - 4u;                          \
        size_t i_;                                                                          \
        CHECK(nl_ >= 1u && nl_ <= S_->capacity && nr_ <= S_->capacity);                     \
        CHECK(nr_ == nl_ || nr_ + 1u == nl_);                                               \
        CHECK(hyst_rising(S_) == (nl_ > nr_));                                              \
        CHECK(hyst_tp_count(S_) == nl_ - 1u + nr_);                                         \
        CHECK((long)(I)->xl[0] == (long)(lo_));                                             \
        for (i_ = from_ + 1u; i_ < nl_; ++i_) CHECK((I)->xl[i_] > (I)->xl[i_ - 1u]);        \
        for (i_ = from_ + 1u; i_ < nr_; ++i_) CHECK((I)->xr[i_] < (I)->xr[i_ - 1u]);        \
        if (nr_ > 0u) {                                                                     \
            CHECK((I)->xl[nl_ - 1u] < (I)->xr[nr_ - 1u] && (long)(I)->xr[0] <= (long)(hi_)); \
        }                                                                                   \
        CHECK((long)(input_) >= (long)(lo_) && (long)(input_) <= (long)(hi_));              \
        for (i_ = from_; i_ < nr_; ++i_) {                                                  \
            CHECK((long)(I)->xr[i_] - (long)(I)->xl[i_] >= (long)(db_));                    \
            if (i_ + 1u < nl_) CHECK((long)(I)->xr[i_] - (long)(I)->xl[i_ + 1u] >= (long)(db_)); \
        }                                                                                   \
    } while (0)

/* ---- init statuses ---- */

/* The double engine's status for f0 (its curve checks: the q31 variant's
 * are hyst_f64_curve_from_poly()'s, q31.h). */
static hyst_status_t double_status(const hyst_poly_t *f)
{
    memset(&D.S, 0, sizeof(D.S));
    return hyst_init(&D.S, f, D.xl, D.yl, D.xr, D.yr, 2u);
}

/* HYST_ERR_COEFF against q31.h's criterion (see the header comment): the
 * harness's own sum |g_j| / R, away from the threshold 128 by 2^-10 of it
 * and by the two Taylor shifts' rounding. */
static void check_coeff_decision(const facts_t *q, hyst_status_t st)
{
    const double slack = 300.0 * q->shift_err;
    if (st == HYST_OK) {
        CHECK(q->abs_sum <= 128.0 * (1.0 + 1.0 / 1024.0) * q->range + slack);
    } else if (st == HYST_ERR_COEFF) {
        CHECK(!(q->range > slack) ||
              q->abs_sum >= 128.0 * (1.0 - 1.0 / 1024.0) * q->range - slack);
    }
}

/* Expected status of hyst_q31_init(): capacity first (the q31 init checks
 * the memory first), then the double engine's curve error (or DOMAIN when
 * the range is bad too: either), DOMAIN, then OK or COEFF. */
static void check_model_status(hyst_status_t got, hyst_status_t fst, size_t cap, int range_ok)
{
    if (cap < 2u) {
        CHECK(got == HYST_ERR_CAPACITY);
    } else if (fst != HYST_OK) {
        CHECK(got == fst || (!range_ok && got == HYST_ERR_DOMAIN));
    } else if (!range_ok) {
        CHECK(got == HYST_ERR_DOMAIN);
    } else {
        CHECK(got == HYST_OK || got == HYST_ERR_COEFF); /* never a refusal double does not make */
    }
}

/* ---- the two modes ---- */

typedef struct {
    const hyst_poly_t *f;
    facts_t q;
    int compare;           /* structured config: differential checks on */
    double R, y_mid, ymax; /* output range, its middle, max |f0| at the ends */
    double per_tp;         /* A: the double reference's rounding per TP (real units) */
    size_t cap;
} ctx_t;

/* The output scale (the reference's own f0 at the ends) and A. */
static void set_scale(ctx_t *c, const hyst_poly_t *f)
{
    const double y_lo = poly_at(f, f->lo), y_hi = poly_at(f, f->hi);
    c->R = y_hi - y_lo;
    c->y_mid = (y_lo + y_hi) / 2.0;
    c->ymax = fmax(fabs(y_lo), fabs(y_hi));
    c->per_tp = 2.0 * horner_bound(f) +
                8.0 * DBL_EPSILON * fmax(fabs(f->lo), fabs(f->hi)) * c->q.slope_max;
}

static void run_model(reader_t *r, unsigned flags, const ctx_t *c, hyst_status_t st_model)
{
    const unsigned long span = chi - clo;
    hyst_q31_t rb;
    /* db_floor: the narrowest deadband since the last reset (TPs stored
     * under a wider one keep their wider gaps) */
    unsigned long dbc = 0, prev_c = clo, db_floor;
    hyst_q31_t prev_y = -QHALF;
    int forgot, z_ok, moved_db = 0; /* moved_db: T's deadband was ever nonzero */
    unsigned n, done = 0;
    hyst_code_word_t xs[64];
    hyst_q31_t ys[64];

    CHECK(st_model == HYST_OK);
    CHECK(hyst_q31_init(&T.S, c->f, clo, chi, T.xl, T.yl, T.xr, T.yr, c->cap) == HYST_OK);
    {   /* Z from the same model sealed (hyst_q31_seal_poly): bit-identical to T */
        hyst_q31_sealed_poly_t sealed;
        CHECK(hyst_q31_seal_poly(&sealed, c->f, clo, chi) == HYST_OK);
        CHECK(hyst_q31_init_sealed(&Z.S, &sealed, Z.xl, Z.yl, Z.xr, Z.yr, c->cap) == HYST_OK);
    }
    CHECK(hyst_q31_output(&M.S) == -QHALF && hyst_q31_input(&M.S) == clo);
    CHECK(hyst_tp_count(&M.S) == 0u && hyst_q31_error_bound(&M.S) == 0);
    CHECK(hyst_capacity(&M.S) == c->cap && same_model(&M, &T));
    rb = hyst_q31_rounding_bound(&M.S);
    {   /* q31.h: (n / 2 + n - 1) c^n 2^GUARD + 1, c = N unit / 2^30 */
        const double N = (double)span, unit = floor(1073741824.0 / N + 0.5);
        const double cc = N * unit / 1073741824.0;
        const double k = 1.5 * (double)c->f->degree - 1.0;
        CHECK((double)rb >= k * pow(cc, (double)c->f->degree) * 16.0 + 1.0 - 1e-9);
        CHECK((double)rb <= k * pow(fmax(cc, 1.0), (double)c->f->degree) * 16.0 + 2.0 + 1e-9);
    }
    if (c->compare) { /* the mapping's ends: f0(lo) and f0(hi) */
        const double tol = 8.0 * DBL_EPSILON * c->ymax;
        CHECK(fabs(hyst_q31_to_real(c->f, -QHALF) - (c->y_mid - c->R / 2.0)) <= tol + c->R * 1e-15);
        CHECK(fabs(hyst_q31_to_real(c->f, QHALF) - (c->y_mid + c->R / 2.0)) <= tol + c->R * 1e-15);
    }
    if (flags & F_PROBES) { /* NULL: refused, never dereferenced; the other variant's calls */
        CHECK(hyst_q31_init(NULL, c->f, clo, chi, keepm.xl, keepm.yl, keepm.xr, keepm.yr, c->cap) ==
              HYST_ERR_NULL);
        CHECK(hyst_q31_init(&keepm.S, NULL, clo, chi, keepm.xl, keepm.yl, keepm.xr, keepm.yr,
                            c->cap) == HYST_ERR_NULL);
        CHECK(hyst_q31_init(&keepm.S, c->f, clo, chi, keepm.xl, NULL, keepm.xr, keepm.yr, c->cap) ==
              HYST_ERR_NULL);
        CHECK(hyst_q31_init(&keepm.S, c->f, clo, chi, keepm.xl, keepm.yl, NULL, keepm.yr, c->cap) ==
              HYST_ERR_NULL);
        CHECK(hyst_q31_process(&M.S, NULL, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_process(&M.S, xs, NULL, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_process(NULL, xs, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_process(&M.S, NULL, NULL, 0u) == HYST_OK);
        CHECK(hyst_q31_set_deadband(NULL, 0u) == HYST_ERR_NULL);
        CHECK(hyst_q31_request_deadband(NULL, 0u) == HYST_ERR_NULL);
        CHECK(hyst_q31_step(NULL, clo) == 0 && hyst_q31_output(NULL) == 0);
        CHECK(hyst_q31_input(NULL) == 0u && hyst_q31_error_bound(NULL) == 0);
        CHECK(hyst_q31_rounding_bound(NULL) == 0 && hyst_q31_to_real(NULL, 5) == 0.0);
        memcpy(&keepm, &M, sizeof(M));
        CHECK(hyst_q31_inv_set_deadband(&M.S, 0) == HYST_ERR_ARG);
        CHECK(hyst_q31_inv_request_deadband(&M.S, 0) == HYST_ERR_ARG);
        CHECK(hyst_q31_inv_drive_bits(&M.S) == 0u && hyst_q31_inv_code(&M.S, 5) == 0u);
        CHECK(hyst_code_set_deadband(&M.S, 0u) == HYST_ERR_ARG); /* the code variant's call */
        CHECK(memcmp(&keepm, &M, sizeof(M)) == 0);
    }
    if (flags & F_DEADBAND) dbc = (unsigned long)rd_u16(r) % (span / 4u + 1u);
    if (flags & F_BADDB) { /* invalid deadbands: refused, state untouched */
        memcpy(&keepm, &M, sizeof(M));
        CHECK(hyst_q31_set_deadband(&M.S, span + 1u + rd_u8(r)) == HYST_ERR_ARG);
        CHECK(hyst_q31_set_deadband(&M.S, 0xFFFFFFFFul) == HYST_ERR_ARG);
        CHECK(hyst_q31_request_deadband(&M.S, span + 1u) == HYST_ERR_ARG);
        CHECK(memcmp(&keepm, &M, sizeof(M)) == 0 && !hyst_request_pending(&M.S));
        CHECK(hyst_q31_set_deadband(&M.S, span) == HYST_OK); /* the widest allowed */
        CHECK(M.S.deadband.code == span);
        CHECK(hyst_q31_set_deadband(&M.S, 0u) == HYST_OK);
    }
    /* deadband set explicitly on M and T (0 too); Z never sees the call */
    CHECK(hyst_q31_set_deadband(&M.S, dbc) == HYST_OK);
    CHECK(hyst_q31_set_deadband(&T.S, dbc) == HYST_OK);
    moved_db = dbc != 0u;
    forgot = dbc != 0u;
    db_floor = dbc;
    z_ok = !moved_db;
    ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
    last_code = clo;

    for (n = 0; done < MAX_SAMPLES && r->at < r->n; ++n) {
        const unsigned op = rd_u8(r);
        unsigned m = 1u, k, posted = 0u;
        unsigned long req_w = 0;
        int blk_full = 0;
        if (op == 0xF0u) { /* reset everything; the deadband is kept */
            hyst_reset(&M.S);
            hyst_reset(&T.S);
            hyst_reset(&Z.S);
            ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
            CHECK(hyst_tp_count(&T.S) == 0u && hyst_events(&T.S) == 0u);
            CHECK(hyst_q31_error_bound(&T.S) == 0 && hyst_q31_output(&T.S) == -QHALF);
            CHECK(hyst_q31_input(&T.S) == clo && same_model(&M, &T));
            forgot = T.S.deadband.code != 0u;
            db_floor = T.S.deadband.code;
            prev_c = last_code = clo;
            prev_y = -QHALF;
            continue;
        }
        if (op >= 0xF4u) { /* accessors, T's snapshot into M, clear events */
            CHECK(hyst_q31_output(&T.S) == prev_y && hyst_q31_input(&T.S) == prev_c);
            CHECK(hyst_q31_rounding_bound(&T.S) == rb && hyst_q31_error_bound(&T.S) >= 0);
            CHECK(hyst_capacity(&T.S) == c->cap &&
                  hyst_ltp_count(&T.S) + hyst_rtp_count(&T.S) == hyst_tp_count(&T.S));
            (void)hyst_status(&T.S);
            snapshot_into(&T.S, &M.S, &M, &keepm, sizeof(M), r);
            CHECK(same_model(&M, &T));
            hyst_clear_events(&M.S);
            hyst_clear_events(&T.S);
            hyst_clear_events(&Z.S);
            CHECK(hyst_events(&T.S) == 0u && same_model(&M, &T));
            continue;
        }
        if (op == 0xF3u) { /* requests from "another context", served by T's next step */
            const unsigned b = rd_u8(r);
            if (b & 1u) {
                if (b & 8u) { /* an invalid width: refused, nothing posted */
                    memcpy(&keepm, &T, sizeof(T));
                    CHECK(hyst_q31_request_deadband(&T.S, span + 1u + rd_u8(r)) == HYST_ERR_ARG);
                    CHECK(memcmp(&keepm, &T, sizeof(T)) == 0);
                } else {
                    req_w = (unsigned long)rd_u16(r) % (span / 4u + 1u);
                    CHECK(hyst_q31_request_deadband(&T.S, req_w) == HYST_OK);
                    posted |= 1u;
                }
            }
            posted |= post_clear_and_reset(&T.S, b);
            CHECK(hyst_request_pending(&T.S) == (posted != 0u));
            if (posted != 0u) ++n_requests;
        }
        if (op == 0xF1u) m = rd_u8(r) % 64u;
        if (op == 0xF2u) { /* nested oscillation: up to 4080 reversals (deep), else 39 */
            m = c->cap == MAX_CAP ? 16u * rd_u8(r) : rd_u8(r) % 40u;
        }
        if (m > MAX_SAMPLES - done) m = MAX_SAMPLES - done; /* the budget of one input */
        done += m;
        for (k = 0; k < m; ++k) {
            /* 0xF2: x_k = mid -+ half (1 - k / (m + 1)), each a reversal */
            const unsigned long half = span / 2u, amp = half - half * k / (m + 1u);
            const unsigned long c0 =
                op == 0xF2u ? ((k & 1u) ? clo + half + amp : clo + half - amp)
                            : next_code(r, op == 0xF1u || op == 0xF3u ? rd_u8(r) : op);
            /* a block holds code words */
            const unsigned long cin = op == 0xF1u ? c0 & 0xFFFFul : c0;
            const int clamped = cin < clo || cin > chi;
            const unsigned long cc = cin < clo ? clo : cin > chi ? chi : cin;
            const double x = volts(cc);
            hyst_q31_t y, yz;
            double yr;
            if (op == 0xF1u) xs[k] = (hyst_code_word_t)cin;
            if (op != 0xF1u) ys[0] = hyst_q31_step(&M.S, cin); /* the single-step path through M */
            y = hyst_q31_step(&T.S, cin);
            yz = hyst_q31_step(&Z.S, cin);
            yr = ref_step(&ref, x);
            last_code = cc;
            CHECK(hyst_request_pending(&T.S) == 0); /* served by this step */
            if (op == 0xF3u) { /* M: the immediate calls after the same step */
                CHECK(ys[0] == y); /* the step's output does not see the requests */
                if (posted & 1u) {
                    CHECK(hyst_q31_set_deadband(&M.S, req_w) == HYST_OK);
                    CHECK(T.S.deadband.code == req_w);
                    if (req_w != 0u) moved_db = 1;
                }
                if (posted & 2u) {
                    hyst_clear_events(&M.S);
                    hyst_clear_events(&Z.S);
                }
                if (posted & 4u) {
                    hyst_reset(&M.S);
                    hyst_reset(&Z.S);
                }
            }
            if (moved_db) z_ok = 0;
            /* status and events as the sample left them (a reset request
             * clears both, a clear-events request the events) */
            if ((posted & 4u) == 0u) {
                if (clamped) {
                    CHECK(hyst_status(&T.S) == HYST_WARN_CLAMPED ||
                          hyst_status(&T.S) == HYST_WARN_FULL);
                    if ((posted & 2u) == 0u) CHECK(hyst_events(&T.S) & HYST_EVENT_CLAMPED);
                    ++n_clamped;
                } else {
                    CHECK(hyst_status(&T.S) != HYST_WARN_CLAMPED);
                }
                if (hyst_status(&T.S) == HYST_WARN_FULL) forgot = blk_full = 1;
            } else {
                CHECK(hyst_status(&T.S) == HYST_OK && hyst_events(&T.S) == 0u);
            }
            if (posted & 2u) CHECK(hyst_events(&T.S) == 0u);
            /* the output never moves against the input, and stays with it */
            if (cc > prev_c) CHECK(y >= prev_y);
            if (cc < prev_c) CHECK(y <= prev_y);
            if (cc == prev_c) CHECK(y == prev_y);
            if (z_ok) CHECK(y == yz && same_model(&T, &Z));
            if (y > QHALF && (long)(y - QHALF) > over_model) over_model = (long)(y - QHALF);
            if (y < -QHALF && (long)(-QHALF - y) > over_model) over_model = (long)(-QHALF - y);
            CHECK(hyst_q31_error_bound(&T.S) >= 0);
            if (c->compare && !forgot) { /* exact: the q31 TCM over codes = the reference */
                const double tps = (double)ref_tp_count(&ref);
                const double tol = ((tps + 1.0) * (double)rb + 0.5) * c->R / (double)QSPAN +
                                   (tps + 2.0) * c->per_tp + 8.0 * DBL_EPSILON * c->ymax;
                const double err = fabs(hyst_q31_to_real(c->f, y) - yr);
                if (!(err <= tol)) {
                    fprintf(stderr, "fuzz_q31: model sample %u: code %lu, q %ld, reference %.17g q "
                                    "(%.17g), TPs %.0f, rb %ld: error %.6g q > tolerance %.6g q\n",
                            done, cc, (long)y, (yr - c->y_mid) * (double)QSPAN / c->R, yr, tps,
                            (long)rb, err * (double)QSPAN / c->R, tol * (double)QSPAN / c->R);
                }
                CHECK(err <= tol);
                if (err / tol > worst_model) {
                    worst_model = err / tol;
                    worst_model_err = err * (double)QSPAN / c->R;
                    worst_model_tps = tps;
                }
                if ((posted & 4u) == 0u) {
                    CHECK(hyst_tp_count(&T.S) == (size_t)ref_tp_count(&ref));
                    CHECK(hyst_q31_error_bound(&T.S) == 0);
                }
                ++n_exact;
            } else {
                ++n_forgot;
            }
            if (posted & 4u) { /* the reset was applied after this output */
                ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
                prev_c = last_code = clo;
                prev_y = -QHALF;
                CHECK(hyst_q31_output(&T.S) == -QHALF && hyst_tp_count(&T.S) == 0u);
            } else {
                prev_c = cc;
                prev_y = y;
                CHECK(hyst_q31_input(&T.S) == cc && hyst_q31_output(&T.S) == y);
            }
            if (posted & 4u) {
                forgot = T.S.deadband.code != 0u;
                db_floor = T.S.deadband.code;
            }
            if (posted & 1u) {
                forgot |= req_w != 0u;
                db_floor = req_w < db_floor ? req_w : db_floor;
            }
            CHECK_STACK(&T, clo, chi, db_floor, hyst_q31_input(&T.S),
                        (k & 255u) == 255u || k + 1u == m);
            if (op != 0xF1u) CHECK(same_model(&M, &T));
            if (op == 0xF1u) ys[k] = y; /* expected block output */
        }
        if (op == 0xF1u) { /* the block through M equals T's steps */
            hyst_q31_t yb[64];
            int any_clamp = 0;
            hyst_status_t st;
            for (k = 0; k < m; ++k) any_clamp |= xs[k] < clo || xs[k] > chi;
            st = hyst_q31_process(&M.S, xs, yb, m);
            CHECK(m == 0u || memcmp(yb, ys, m * sizeof(ys[0])) == 0);
            CHECK(same_model(&M, &T));
            /* documented summary: FULL if any overflow (seen on T), else CLAMPED */
            CHECK(st == (blk_full ? HYST_WARN_FULL : any_clamp ? HYST_WARN_CLAMPED : HYST_OK));
            ++n_blocks;
        }
    }
}

static void run_comp(reader_t *r, unsigned flags, const ctx_t *c, hyst_status_t st_model,
                     size_t intervals)
{
    hyst_status_t st, exp;
    hyst_q31_t drive_span, rb_k, prev_d = 0, prev_in = -QHALF, dbq = 0, db_floor;
    unsigned bits, n, done = 0;
    double s_q, e_eval, rb1, emax;
    int forgot;
    hyst_q31_t xs[64], ys[64];

    /* the documented order: the model's checks (curve, DOMAIN, COEFF), the
     * intervals, then the memory */
    exp = st_model != HYST_OK ? st_model
          : intervals < 1u || intervals > HYST_Q31_INV_MAX_INTERVALS ? HYST_ERR_ARG
          : c->cap < 2u ? HYST_ERR_CAPACITY
                        : HYST_OK;
    memset(&K, 0x5A, sizeof(K));
    memset(&inv, 0xA5, sizeof(inv));
    memset(table, 0x3C, sizeof(table));
    memcpy(&keepk, &K, sizeof(K));
    memcpy(&keep_inv, &inv, sizeof(inv));
    memcpy(keep_table, table, sizeof(table));
    if (flags & F_PROBES) { /* one NULL at a time, else valid: HYST_ERR_NULL, nothing written */
        CHECK(hyst_q31_init_inverse_table(&K.S, NULL, c->f, clo, chi, table, intervals, K.xl, K.yl,
                                          K.xr, K.yr, c->cap) == HYST_ERR_NULL);
        CHECK(hyst_q31_init_inverse_table(&K.S, &inv, c->f, clo, chi, NULL, intervals, K.xl, K.yl,
                                          K.xr, K.yr, c->cap) == HYST_ERR_NULL);
        CHECK(hyst_q31_init_inverse_table(&K.S, &inv, NULL, clo, chi, table, intervals, K.xl, K.yl,
                                          K.xr, K.yr, c->cap) == HYST_ERR_NULL);
        if (exp == HYST_OK) {
            CHECK(hyst_q31_init_inverse_table(NULL, &inv, c->f, clo, chi, table, intervals, K.xl,
                                              K.yl, K.xr, K.yr, c->cap) == HYST_ERR_NULL);
            CHECK(hyst_q31_init_inverse_table(&K.S, &inv, c->f, clo, chi, table, intervals, K.xl,
                                              NULL, K.xr, K.yr, c->cap) == HYST_ERR_NULL);
            CHECK(hyst_q31_init_inverse_table(&K.S, &inv, c->f, clo, chi, table, intervals, K.xl,
                                              K.yl, K.xr, NULL, c->cap) == HYST_ERR_NULL);
        }
        /* the largest table plus one: refused before anything is built */
        CHECK(hyst_q31_init_inverse_table(&K.S, &inv, c->f, clo, chi, table,
                                          (size_t)HYST_Q31_INV_MAX_INTERVALS + 1u, K.xl, K.yl, K.xr,
                                          K.yr, c->cap) ==
              (st_model != HYST_OK ? st_model : HYST_ERR_ARG));
        CHECK(memcmp(&keepk, &K, sizeof(K)) == 0 && memcmp(&keep_inv, &inv, sizeof(inv)) == 0);
        CHECK(memcmp(keep_table, table, sizeof(table)) == 0);
    }
    st = hyst_q31_init_inverse_table(&K.S, &inv, c->f, clo, chi, table, intervals, K.xl, K.yl, K.xr,
                                     K.yr, c->cap);
    CHECK(st == exp);
    if (st != HYST_OK) {
        CHECK(memcmp(&keepk, &K, sizeof(K)) == 0 && memcmp(&keep_inv, &inv, sizeof(inv)) == 0);
        CHECK(memcmp(keep_table, table, sizeof(table)) == 0);
        return;
    }
    ++n_kinit_ok;
    CHECK(hyst_q31_init_inverse_table(&KT.S, &inv_t, c->f, clo, chi, table_t, intervals, KT.xl,
                                      KT.yl, KT.xr, KT.yr, c->cap) == HYST_OK);
    CHECK(memcmp(table, table_t, HYST_Q31_INV_TABLE_LEN(intervals) * sizeof(table[0])) == 0);
    CHECK(K.S.curve == &inv && inv.kind == HYST_CURVE_INV_TABLE);
    /* q31.h: F the largest with (code_hi - code_lo) 2^F <= 2^28 */
    bits = hyst_q31_inv_drive_bits(&K.S);
    CHECK(bits < 29u && ((chi - clo) << bits) <= (unsigned long)QSPAN &&
          ((chi - clo) << (bits + 1u)) > (unsigned long)QSPAN);
    drive_span = (hyst_q31_t)((chi - clo) << bits);
    CHECK(table[0] == (hyst_q31_t)(16u * intervals)); /* the scale 16 N */
    emax = (double)hyst_curve_inverse_error(&inv);
    CHECK(emax >= 0.0 &&
          emax * (double)drive_span <= HYST_INV_TABLE_TOL * (double)drive_span + 8.0);
    rb_k = hyst_q31_rounding_bound(&K.S);
    CHECK(rb_k == (hyst_q31_t)(emax * (double)drive_span) + 1); /* measured error + 1 */
    CHECK(hyst_q31_inv_output(&K.S) == 0 && hyst_q31_inv_input(&K.S) == -QHALF);
    CHECK(hyst_tp_count(&K.S) == 0u && hyst_q31_inv_error_bound(&K.S) == 0);
    CHECK(hyst_capacity(&K.S) == c->cap && same_comp(&K, &KT));
    CHECK(hyst_q31_inv_code(&K.S, 0) == clo && hyst_q31_inv_code(&K.S, drive_span) == chi);
    CHECK(hyst_q31_inv_code(&K.S, -5) == clo && hyst_q31_inv_code(&K.S, Q_MAX) == chi);
    n_marked += inv.u.inv_table.exact > 0u;
    if (flags & F_PROBES) { /* NULL; the model's calls refuse a compensator */
        CHECK(hyst_q31_inv_process(&K.S, NULL, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_inv_process(&K.S, xs, NULL, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_inv_process(NULL, xs, ys, 1u) == HYST_ERR_NULL);
        CHECK(hyst_q31_inv_process(&K.S, NULL, NULL, 0u) == HYST_OK);
        CHECK(hyst_q31_inv_set_deadband(NULL, 0) == HYST_ERR_NULL);
        CHECK(hyst_q31_inv_request_deadband(NULL, 0) == HYST_ERR_NULL);
        CHECK(hyst_q31_inv_step(NULL, 0) == 0 && hyst_q31_inv_output(NULL) == 0);
        CHECK(hyst_q31_inv_input(NULL) == 0 && hyst_q31_inv_error_bound(NULL) == 0);
        CHECK(hyst_q31_inv_drive_bits(NULL) == 0u && hyst_q31_inv_code(NULL, 5) == 0u);
        memcpy(&keepk, &K, sizeof(K));
        CHECK(hyst_q31_set_deadband(&K.S, 0u) == HYST_ERR_ARG);
        CHECK(hyst_q31_request_deadband(&K.S, 0u) == HYST_ERR_ARG);
        CHECK(memcmp(&keepk, &K, sizeof(K)) == 0);
    }
    /* up to a quarter of the range, as the model's: 24 bits times 4 */
    if (flags & F_DEADBAND) dbq = (hyst_q31_t)(rd_u24(r) << 2);
    if (flags & F_BADDB) { /* invalid widths: refused, state untouched */
        const hyst_q31_t bad[4] = {-1, QSPAN + 1 + (hyst_q31_t)rd_u8(r), Q_MIN, Q_MAX};
        unsigned j;
        memcpy(&keepk, &K, sizeof(K));
        for (j = 0; j < 4u; ++j) {
            CHECK(hyst_q31_inv_set_deadband(&K.S, bad[j]) == HYST_ERR_ARG);
            CHECK(hyst_q31_inv_request_deadband(&K.S, bad[j]) == HYST_ERR_ARG);
        }
        CHECK(memcmp(&keepk, &K, sizeof(K)) == 0 && !hyst_request_pending(&K.S));
        CHECK(hyst_q31_inv_set_deadband(&K.S, QSPAN) == HYST_OK && K.S.deadband.q31 == QSPAN);
        CHECK(hyst_q31_inv_set_deadband(&K.S, 0) == HYST_OK);
    }
    CHECK(hyst_q31_inv_set_deadband(&K.S, dbq) == HYST_OK);
    CHECK(hyst_q31_inv_set_deadband(&KT.S, dbq) == HYST_OK);
    forgot = dbq != 0;
    db_floor = dbq; /* as the model's */

    /* One evaluation's error in the round trip, in q (see the header). */
    s_q = c->q.slope_max * (c->f->hi - c->f->lo) / (double)drive_span * (double)QSPAN / c->R;
    rb1 = (1.5 * (double)c->f->degree - 1.0) * 16.0 + 2.0;
    e_eval = s_q * (4.0 * emax * (double)drive_span + 2.0) + rb1 + 1.0;
    rid_init();
    ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
    last_desired = -QHALF;

    for (n = 0; done < MAX_SAMPLES && r->at < r->n; ++n) {
        const unsigned op = rd_u8(r);
        unsigned m = 1u, k, posted = 0u, nb = 0u;
        hyst_q31_t req_w = 0;
        int blk_full = 0, in_place = 0;
        if (op == 0xF0u) {
            hyst_reset(&K.S);
            hyst_reset(&KT.S);
            ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
            rid_init();
            CHECK(hyst_tp_count(&KT.S) == 0u && hyst_events(&KT.S) == 0u);
            CHECK(hyst_q31_inv_output(&KT.S) == 0 && hyst_q31_inv_input(&KT.S) == -QHALF);
            CHECK(hyst_q31_inv_error_bound(&KT.S) == 0 && same_comp(&K, &KT));
            forgot = KT.S.deadband.q31 != 0;
            db_floor = KT.S.deadband.q31;
            prev_d = 0;
            prev_in = last_desired = -QHALF;
            continue;
        }
        if (op >= 0xF4u) {
            CHECK(hyst_q31_inv_output(&KT.S) == prev_d && hyst_q31_inv_input(&KT.S) == prev_in);
            CHECK(hyst_q31_rounding_bound(&KT.S) == rb_k && hyst_q31_inv_error_bound(&KT.S) >= 0);
            CHECK(hyst_q31_inv_drive_bits(&KT.S) == bits);
            CHECK(hyst_ltp_count(&KT.S) + hyst_rtp_count(&KT.S) == hyst_tp_count(&KT.S));
            snapshot_into(&KT.S, &K.S, &K, &keepk, sizeof(K), r);
            CHECK(same_comp(&K, &KT));
            hyst_clear_events(&K.S);
            hyst_clear_events(&KT.S);
            CHECK(hyst_events(&KT.S) == 0u && same_comp(&K, &KT));
            continue;
        }
        if (op == 0xF3u) {
            const unsigned b = rd_u8(r);
            if (b & 1u) {
                if (b & 8u) {
                    memcpy(&keepk, &KT, sizeof(KT));
                    CHECK(hyst_q31_inv_request_deadband(&KT.S, QSPAN + 1 + (hyst_q31_t)rd_u8(r)) ==
                          HYST_ERR_ARG);
                    CHECK(memcmp(&keepk, &KT, sizeof(KT)) == 0);
                } else {
                    req_w = (hyst_q31_t)(rd_u24(r) << 2);
                    CHECK(hyst_q31_inv_request_deadband(&KT.S, req_w) == HYST_OK);
                    posted |= 1u;
                }
            }
            posted |= post_clear_and_reset(&KT.S, b);
            CHECK(hyst_request_pending(&KT.S) == (posted != 0u));
            if (posted != 0u) ++n_requests;
        }
        if (op == 0xF1u) {
            nb = rd_u8(r);
            m = nb % 64u;
            in_place = (nb & 64u) != 0u;
        }
        if (op == 0xF2u) m = c->cap == MAX_CAP ? 16u * rd_u8(r) : rd_u8(r) % 40u;
        if (m > MAX_SAMPLES - done) m = MAX_SAMPLES - done;
        done += m;
        for (k = 0; k < m; ++k) {
            const hyst_q31_t half = QHALF;
            const hyst_q31_t amp =
                (hyst_q31_t)((double)half * (1.0 - (double)k / (double)(m + 1u)));
            const hyst_q31_t din =
                op == 0xF2u ? ((k & 1u) ? amp : -amp)
                            : next_desired(r, op == 0xF1u || op == 0xF3u ? rd_u8(r) : op);
            const hyst_q31_t dc = clamp_q(din);
            const int clamped = din != dc;
            hyst_q31_t d, dm = 0;
            if (op == 0xF1u) xs[k] = din;
            if (op != 0xF1u) dm = hyst_q31_inv_step(&K.S, din);
            d = hyst_q31_inv_step(&KT.S, din);
            last_desired = dc;
            ++n_ksamples;
            CHECK(hyst_request_pending(&KT.S) == 0);
            if (op == 0xF3u) {
                CHECK(dm == d);
                if (posted & 1u) {
                    CHECK(hyst_q31_inv_set_deadband(&K.S, req_w) == HYST_OK);
                    CHECK(KT.S.deadband.q31 == req_w);
                }
                if (posted & 2u) hyst_clear_events(&K.S);
                if (posted & 4u) hyst_reset(&K.S);
            }
            if ((posted & 4u) == 0u) {
                if (clamped) {
                    CHECK(hyst_status(&KT.S) == HYST_WARN_CLAMPED ||
                          hyst_status(&KT.S) == HYST_WARN_FULL);
                    if ((posted & 2u) == 0u) CHECK(hyst_events(&KT.S) & HYST_EVENT_CLAMPED);
                    ++n_clamped;
                } else {
                    CHECK(hyst_status(&KT.S) != HYST_WARN_CLAMPED);
                }
                if (hyst_status(&KT.S) == HYST_WARN_FULL) forgot = blk_full = 1;
            } else {
                CHECK(hyst_status(&KT.S) == HYST_OK && hyst_events(&KT.S) == 0u);
            }
            if (posted & 2u) CHECK(hyst_events(&KT.S) == 0u);
            /* the drive: in [0, S_d], never against the desired output */
            CHECK(d >= 0 && d <= drive_span);
            if (dc > prev_in) CHECK(d >= prev_d);
            if (dc < prev_in) CHECK(d <= prev_d);
            if (dc == prev_in) CHECK(d == prev_d);
            CHECK(hyst_q31_inv_code(&KT.S, d) ==
                  clo + (((unsigned long)d + ((1ul << bits) >> 1)) >> bits));
            CHECK(hyst_q31_inv_error_bound(&KT.S) >= 0);
            (void)ref_step(&rid, (double)dc);
            {
                const double x =
                    c->f->lo + (c->f->hi - c->f->lo) * ((double)d / (double)drive_span);
                const double y = ref_step(&ref, x <= c->f->hi ? x : c->f->hi);
                if (c->compare && !forgot) {
                    const double tps =
                        fmax((double)hyst_tp_count(&KT.S), (double)ref_tp_count(&ref));
                    const double tol = (tps + 2.0) * e_eval +
                                       ((tps + 2.0) * c->per_tp + 8.0 * DBL_EPSILON * c->ymax) *
                                           (double)QSPAN / c->R;
                    const double err = fabs((y - c->y_mid) * ((double)QSPAN / c->R) - (double)dc);
                    if (!(err <= tol)) {
                        fprintf(stderr, "fuzz_q31: round trip at sample %u: desired %ld, drive %ld "
                                        "of %ld, model %.17g q, TPs %.0f, one evaluation %.6g q: "
                                        "error %.6g q > tolerance %.6g q\n",
                                done, (long)dc, (long)d, (long)drive_span,
                                (y - c->y_mid) * ((double)QSPAN / c->R), tps, e_eval, err, tol);
                    }
                    CHECK(err <= tol);
                    worst_rt = fmax(worst_rt, err / tol);
                    if ((posted & 4u) == 0u) {
                        CHECK(hyst_tp_count(&KT.S) == (size_t)ref_tp_count(&rid));
                        CHECK(hyst_q31_inv_error_bound(&KT.S) == 0);
                    }
                    ++n_round_trip;
                } else {
                    ++n_kforgot;
                }
            }
            if (posted & 4u) {
                ref_init(&ref, c->f->coeffs, c->f->degree, c->f->lo, c->f->hi);
                rid_init();
                prev_d = 0;
                prev_in = last_desired = -QHALF;
                CHECK(hyst_q31_inv_output(&KT.S) == 0 && hyst_tp_count(&KT.S) == 0u);
                forgot = KT.S.deadband.q31 != 0;
                db_floor = KT.S.deadband.q31;
            } else {
                prev_d = d;
                prev_in = dc;
                CHECK(hyst_q31_inv_input(&KT.S) == dc && hyst_q31_inv_output(&KT.S) == d);
            }
            if (posted & 1u) {
                forgot |= req_w != 0;
                db_floor = req_w < db_floor ? req_w : db_floor;
            }
            CHECK_STACK(&KT, -QHALF, QHALF, db_floor, hyst_q31_inv_input(&KT.S),
                        (k & 255u) == 255u || k + 1u == m);
            if (op != 0xF1u) CHECK(same_comp(&K, &KT));
            if (op == 0xF1u) ys[k] = d;
        }
        if (op == 0xF1u) {
            hyst_q31_t yb[64];
            int any_clamp = 0;
            for (k = 0; k < m; ++k) any_clamp |= xs[k] != clamp_q(xs[k]);
            if (in_place) {
                memcpy(yb, xs, m * sizeof(xs[0]));
                st = hyst_q31_inv_process(&K.S, yb, yb, m);
            } else {
                st = hyst_q31_inv_process(&K.S, xs, yb, m);
            }
            CHECK(m == 0u || memcmp(yb, ys, m * sizeof(ys[0])) == 0);
            CHECK(same_comp(&K, &KT));
            CHECK(st == (blk_full ? HYST_WARN_FULL : any_clamp ? HYST_WARN_CLAMPED : HYST_OK));
            ++n_blocks;
        }
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    if (getenv("FUZZ_Q31_STATS")) atexit(print_stats);
    return 0;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    reader_t r = {data, size, 0};
    hyst_poly_t f;
    ctx_t c;
    const unsigned flags = rd_u8(&r);
    const unsigned cap_byte = rd_u8(&r);
    hyst_status_t st, fst;
    size_t intervals = 0u;
    int range_ok;

    memset(&c, 0, sizeof c);
    /* deep stacks are slow (O(depth) reference and invariants per sample):
     * rare, so that most runs exercise the small capacities */
    c.cap = (flags & F_DEEP) && cap_byte >= 240u ? MAX_CAP : cap_byte % 20u;
    read_config(&r, (int)(flags & F_RAW), &f);
    if ((flags & F_RAW) && !getenv("FUZZ_Q31_SLOW")) {
        /* The known slow path of fuzz_code.c (docs/reliability.md, "Slow
         * init when the normalised curve overflows"): the curve checks the
         * q31 init shares subdivide to full depth. Skipped as there. */
        const double mag = fmax(fabs(f.lo), fabs(f.hi));
        double acc = 0.0;
        unsigned k;
        for (k = 0; k <= f.degree && k <= HYST_MAX_DEGREE; ++k) acc = acc * mag + fabs(f.coeffs[k]);
        if (acc > 1e280) return 0;
    }
    if (flags & F_RAWRANGE) {
        clo = rd_u24(&r);
        chi = rd_u24(&r);
    } else {
        const unsigned shift = rd_u8(&r) % 16u;
        unsigned long span = (unsigned long)rd_u16(&r) >> shift;
        if (span == 0u) span = 1u;
        clo = (unsigned long)rd_u16(&r) % (65536ul - span);
        chi = clo + span;
    }
    range_ok = clo < chi && chi <= HYST_CODE_MAX;
    vlo = f.lo;
    vhi = f.hi;
    if (flags & F_COMP) {
        intervals = (flags & F_WIDE_N) ? (size_t)(rd_u16(&r) % (MAX_INTERVALS + 1u)) : rd_u8(&r);
    }

    /* the model: its status, against the double engine's */
    fst = double_status(&f);
    memset(&M, 0x5A, sizeof(M));
    memcpy(&keepm, &M, sizeof(M));
    st = hyst_q31_init(&M.S, &f, clo, chi, M.xl, M.yl, M.xr, M.yr, c.cap);
    check_model_status(st, fst, c.cap, range_ok);
    c.compare = !(flags & F_RAW); /* raw curves may defeat the reference itself */
    c.f = &f;
    if (st != HYST_OK) {
        CHECK(st < 0);
        CHECK(memcmp(&keepm, &M, sizeof(M)) == 0); /* init errors write nothing */
        n_coeff += st == HYST_ERR_COEFF;
    } else {
        ++n_init_ok;
    }
    if (fst == HYST_OK) {
        c.q = curve_facts(&f);
        if (c.compare && range_ok && c.cap >= 2u) check_coeff_decision(&c.q, st);
    }
    if (flags & F_COMP) {
        /* the model's own status with valid memory: the compensator's
         * reference for the curve, DOMAIN and COEFF checks */
        hyst_status_t smod = st;
        if (c.cap < 2u) {
            smod = hyst_q31_init(&keepm.S, &f, clo, chi, keepm.xl, keepm.yl, keepm.xr, keepm.yr,
                                 2u);
        }
        if (smod == HYST_OK) { /* the model initialised, for the wrong-variant probes too */
            CHECK(hyst_q31_init(&M.S, &f, clo, chi, M.xl, M.yl, M.xr, M.yr, 2u) == HYST_OK);
        }
        if (fst == HYST_OK) set_scale(&c, &f);
        c.compare = c.compare && fst == HYST_OK && c.R > 0.0;
        if (smod == HYST_OK && (flags & F_PROBES)) {
            memcpy(&keepm, &M, sizeof(M));
            CHECK(hyst_q31_inv_set_deadband(&M.S, 0) == HYST_ERR_ARG);
            CHECK(memcmp(&keepm, &M, sizeof(M)) == 0);
        }
        run_comp(&r, flags, &c, smod, intervals);
        return 0;
    }
    if (st != HYST_OK) return 0;
    set_scale(&c, &f);
    c.compare = c.compare && c.R > 0.0;
    run_model(&r, flags, &c, st);
    return 0;
}
