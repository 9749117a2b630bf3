/* SPDX-License-Identifier: MIT */
/**
 * @file q31.h
 * @brief The TCM in fixed point, for cores without an FPU (Cortex-M0/M0+/M3,
 *        fixed-point DSPs): integer codes in, q31 out.
 *
 * Same model, rules and engine source as hyst/code.h (hyst_tcm_t): inputs are
 * unsigned ADC/DAC codes code_lo..code_hi mapped linearly onto f0's domain
 * [lo, hi], stored as hyst_code_word_t (exact turning-point compares). A
 * signed q15 or q31 signal is a code once offset: code = q15 + 32768 on
 * 0..65535. Outputs and stored turning-point outputs are hyst_q31_t:
 *
 *     y = y_mid + q * (y_hi - y_lo) / 2^HYST_Q31_SPAN_BITS,
 *     y_mid = (y_lo + y_hi) / 2, y_lo = f0(lo), y_hi = f0(hi),
 *
 * so the output range [y_lo, y_hi] is q in [-2^27, 2^27] (q31 +-1/16):
 * three bits of headroom, which every intermediate of the engine (a branch
 * from a merged turning point, the merge's gap and miss, the error bounds)
 * needs to stay inside 32 bits. Resolution: 2^-28 of the range.
 *
 * Per sample, G is evaluated by Horner's rule with 32 x 32 -> 64-bit
 * products keeping the high part (one SMULL and a shift on Cortex-M3):
 *  - G's argument is v = (x - x_k) * unit, exact: unit = round(2^30 / N)
 *    (N = code_hi - code_lo), v in Q30; the scale error of unit is folded
 *    into the coefficients at init (G(v / c) with c = N unit / 2^30);
 *  - the coefficients share one format, 2^HYST_Q31_GUARD_BITS coarser than
 *    the output's, so that Horner's partial sums may reach
 *    2^(31 - 28 + 4) = 128 times the output range. init proves that no partial sum can
 *    overflow for v in [0, c] (sum of |coefficient| c^k, plus the rounding
 *    of each step) and refuses the curve otherwise (HYST_ERR_COEFF).
 *
 * Error bound (hyst_q31_rounding_bound(), in output units q): one branch
 * evaluation y_k +- G errs from the exact real value by at most
 *     (n / 2 + (n - 1)) c^n 2^HYST_Q31_GUARD_BITS + 1
 * (n = degree: the coefficients' rounding, the truncation of each Horner
 * step, the final product's); y_k itself carries one such error per stored
 * turning point below it, so the output errs by at most
 * (stored turning points + 1) times the bound, plus 1/2 for the real
 * reference's rounding to q: 10 q (4e-8 of the output range) at degree 1,
 * 58 q for the paper's cubic, 202 q (8e-7) at degree 9. Measured against
 * the double reference: at most 1.9e-7 of the range (tests/test_q31.c).
 *
 * Bounded memory (merges, deadband) works as in hyst/code.h; the merge
 * error bound saturates at HYST_Q31_BOUND_MAX. Snapshots (snapshot.h) work
 * for the model and the compensator as for the other variants: codes and
 * q31 numbers travel as 4-octet integers (q31 in two's complement), and a
 * restored instance continues bit for bit.
 *
 * Compensator (hyst_q31_inv_*: the inverse model, a feedforward for the
 * same f0 and codes, docs/pi_and_inverse.md). Its input is a desired
 * output in the model's format above (q in [-2^27, 2^27]); its output the
 * drive in codes with F = hyst_q31_inv_drive_bits() fraction bits:
 *
 *     drive = (code - code_lo) 2^F,  F largest with (code_hi - code_lo) 2^F <= 2^28,
 *
 * so the DAC code is code_lo + ((drive + 2^(F-1)) >> F) (hyst_q31_inv_code()),
 * and the fraction keeps the stored turning points' drives 2^-F codes fine
 * (F = 16 for 12-bit codes). The inverse curve is tabulated at init, in
 * hyst_wide_t (double; off the per-sample path), into a caller-owned array
 * of HYST_Q31_INV_TABLE_LEN(N) words: f0^-1 in N monotone cubic Hermite
 * pieces on a grid uniform in the output, as the real variants' table
 * (inverse.h). Per sample: the output step u (q) gives s = u N / 2^28 by
 * one 32 x 32 -> 64-bit product (interval k = its high word, the position
 * in it its low word), and the piece's cubic in drive units, expanded about
 * the interval's middle (t = offset from it, Q32, |t| <= 1/2), by three
 * SMULLs that keep their high word: each step b_j + (acc t) >> 32.
 * Init proves that no coefficient or partial sum can leave 32 bits (a piece
 * that could is evaluated exactly, like one that misses the tolerance), and
 * measures every piece as stored and evaluated against the exact inverse
 * (16 points per interval): the worst error / drive span is
 * hyst_curve_inverse_error(inv), at most HYST_INV_TABLE_TOL plus 8 drive
 * units of truncation. The intervals next to a flat point of f0 (infinite
 * inverse slope) are marked and evaluated exactly: the model's own
 * fixed-point G solved by bisection over the interval's bracket (about 30
 * evaluations of G: rare, slower samples). The drive never steps back while
 * the desired output moves on (the engine's guards).
 */
#ifndef HYST_Q31_H
#define HYST_Q31_H

#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Output range [y_lo, y_hi] = 2^HYST_Q31_SPAN_BITS units of q. */
#define HYST_Q31_SPAN_BITS 28
/** The coefficients' format is 2^HYST_Q31_GUARD_BITS units of q per LSB. */
#define HYST_Q31_GUARD_BITS 4
/** Fractional bits of G's argument v (Q30: v in [0, 1] fits with headroom). */
#define HYST_Q31_U_BITS 30
/** Saturation of hyst_q31_error_bound() (4 output ranges: "no bound"). */
#define HYST_Q31_BOUND_MAX ((hyst_q31_t)1 << (HYST_Q31_SPAN_BITS + 2))

/** @brief RAM of one instance with @p capacity entries per array, in bytes. */
#define HYST_Q31_RAM(capacity) \
    (sizeof(hyst_tcm_t) + 2u * (size_t)(capacity) * (sizeof(hyst_code_word_t) + sizeof(hyst_q31_t)))

/** @brief Declares an instance for inputs with @p nu distinct codes
 *         (as HYST_CODE_DEFINE()). */
#define HYST_Q31_DEFINE(name, nu) HYST_DEFINE_ARRAYS_(name, hyst_code_word_t, hyst_q31_t, nu)

/** hyst_q31_init() on an instance declared by HYST_Q31_DEFINE(). */
#define HYST_Q31_INIT(name, f0, code_lo, code_hi) \
    hyst_q31_init_(&(name), (f0), (code_lo), (code_hi), HYST_ARRAYS_(name), HYST_LAYOUT)

/**
 * @brief Initialises an instance: f0 in user units on [f0->lo, f0->hi],
 *        codes code_lo..code_hi mapped linearly onto it, caller-owned memory.
 *
 * The set-up runs in hyst_wide_t (double): the curve checks of
 * hyst_f64_curve_from_poly(), the fixed-point coefficients, the overflow
 * proof and the error bound. On error nothing is written.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *         HYST_ERR_OVERLAP, HYST_ERR_DOMAIN (code range empty or wider than
 *         HYST_CODE_BITS), a curve error, or HYST_ERR_COEFF (Horner's
 *         partial sums could overflow 32 bits: coefficients that cancel
 *         beyond 128 times the output range).
 */
hyst_status_t hyst_q31_init_(hyst_tcm_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                             uint_least32_t code_hi, hyst_code_word_t *xltp, hyst_q31_t *yltp,
                             hyst_code_word_t *xrtp, hyst_q31_t *yrtp, size_t capacity,
                             unsigned long layout);
#define hyst_q31_init(S, f0, code_lo, code_hi, xltp, yltp, xrtp, yrtp, capacity)           \
    hyst_q31_init_((S), (f0), (code_lo), (code_hi), (xltp), (yltp), (xrtp), (yrtp),       \
                   (capacity), HYST_LAYOUT)

/**
 * @brief The q31 model of a polynomial, prepared and checked ahead of time
 *        (`hyst header --sealed --codes LO,HI`, hyst_q31_seal_poly()) and
 *        sealed, for hyst_q31_init_sealed(): what hyst_q31_init() derives
 *        in double, and a CRC-32 over it (curve.h, "sealed ahead of time").
 */
typedef struct hyst_q31_sealed_poly {
    unsigned long seal;            /**< CRC-32 of the format, kind, variant, degree, numbers */
    unsigned degree;               /**< n, 1..HYST_MAX_DEGREE */
    uint_least32_t code_lo;        /**< the code mapped to f0->lo */
    uint_least32_t code_hi;        /**< the code mapped to f0->hi */
    hyst_q31_t unit;               /**< G's argument per code, Q30 */
    hyst_q31_t rounding;           /**< the error bound's rounding term */
    hyst_q31_t a[HYST_MAX_DEGREE]; /**< the fixed-point coefficients, a[0] of v^n */
} hyst_q31_sealed_poly_t;

/** @brief Runs hyst_q31_init()'s checks and set-up on @p f0 and codes
 *         code_lo..code_hi and writes the result sealed (@p out written
 *         only on success).
 *  @return as hyst_q31_init(), without the arrays' statuses. */
hyst_status_t hyst_q31_seal_poly_(hyst_q31_sealed_poly_t *out, const hyst_poly_t *f0,
                                  uint_least32_t code_lo, uint_least32_t code_hi,
                                  unsigned long layout);
#define hyst_q31_seal_poly(out, f0, code_lo, code_hi) \
    hyst_q31_seal_poly_((out), (f0), (code_lo), (code_hi), HYST_LAYOUT)

/** @brief The instance hyst_q31_init() makes, from a sealed q31 model:
 *         checks the arrays and the caller's layout, the degree and codes,
 *         and the seal (integer work only; HYST_ERR_CRC when the numbers
 *         differ from the ones sealed). On error nothing is written.
 *  @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *          HYST_ERR_OVERLAP, HYST_ERR_DEGREE, HYST_ERR_DOMAIN or HYST_ERR_CRC. */
hyst_status_t hyst_q31_init_sealed_(hyst_tcm_t *S, const hyst_q31_sealed_poly_t *sealed,
                                    hyst_code_word_t *xltp, hyst_q31_t *yltp,
                                    hyst_code_word_t *xrtp, hyst_q31_t *yrtp, size_t capacity,
                                    unsigned long layout);
#define hyst_q31_init_sealed(S, sealed, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_q31_init_sealed_((S), (sealed), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
/** hyst_q31_init_sealed() on an instance declared by HYST_Q31_DEFINE(). */
#define HYST_Q31_INIT_SEALED(name, sealed) \
    hyst_q31_init_sealed_(&(name), (sealed), HYST_ARRAYS_(name), HYST_LAYOUT)

/** @brief Noise deadband in codes (see hyst_code_set_deadband()). */
hyst_status_t hyst_q31_set_deadband(hyst_tcm_t *S, uint_least32_t codes);

/** @brief hyst_q31_set_deadband() as a request from another context. */
hyst_status_t hyst_q31_request_deadband(hyst_tcm_t *S, uint_least32_t codes);

/** @brief Advances the model by one code (as hyst_code_step()); a code
 *         outside [code_lo, code_hi] is clamped (HYST_WARN_CLAMPED). */
hyst_q31_t hyst_q31_step(hyst_tcm_t *S, uint_least32_t code);

/** @brief hyst_q31_step() over a block, bit-identically (statuses as
 *         hyst_code_process()). */
hyst_status_t hyst_q31_process(hyst_tcm_t *S, const hyst_code_word_t *x, hyst_q31_t *y,
                               size_t n);

/** @brief Last output (-2^27, f0(lo), after init or reset). */
hyst_q31_t hyst_q31_output(const hyst_tcm_t *S);

/** @brief Last valid code, after clamping. */
uint_least32_t hyst_q31_input(const hyst_tcm_t *S);

/** @brief Bound on the error caused by forgetting (merges, deadband), in q. */
hyst_q31_t hyst_q31_error_bound(const hyst_tcm_t *S);

/** @brief The a-priori bound of one branch evaluation (above), in q; for a
 *         compensator the measured table error plus 1, in drive units. */
hyst_q31_t hyst_q31_rounding_bound(const hyst_tcm_t *S);

/** @brief An output q of an instance of @p f0 in user units (the mapping
 *         above); 0 if f0 is NULL. */
hyst_wide_t hyst_q31_to_real(const hyst_poly_t *f0, hyst_q31_t q);

/** Words of a q31 compensator's table of @p intervals pieces: its scale,
 *  four per interval, four for the end of the range. */
#define HYST_Q31_INV_TABLE_LEN(intervals) (4u * ((intervals) + 1u) + 1u)
/** Largest table of a q31 compensator, in intervals. */
#define HYST_Q31_INV_MAX_INTERVALS 1048576ul

/** @brief A q31 compensator's instance, arrays (desired outputs and drives,
 *  HYST_CAPACITY(@p nu) each), inverse curve and table of HYST_INV_TABLE
 *  intervals, statically. @p nu: distinct desired outputs. */
#define HYST_Q31_DEFINE_INVERSE(name, nu)                                   \
    static hyst_curve_t name##_curve;                                       \
    static hyst_q31_t name##_table[HYST_Q31_INV_TABLE_LEN(HYST_INV_TABLE)]; \
    HYST_DEFINE_ARRAYS_(name, hyst_q31_t, hyst_q31_t, nu)

/** hyst_q31_init_inverse_table() on an instance declared by
 *  HYST_Q31_DEFINE_INVERSE(). */
#define HYST_Q31_INIT_INVERSE(name, f0, code_lo, code_hi)                           \
    hyst_q31_init_inverse_table_(&(name), &name##_curve, (f0), (code_lo), (code_hi), \
                                 name##_table, HYST_INV_TABLE, HYST_ARRAYS_(name),   \
                                 HYST_LAYOUT)

/**
 * @brief Initialises a q31 compensator of the model hyst_q31_init() builds
 *        from @p f0 and codes @p code_lo .. @p code_hi (see "Compensator").
 *
 * The set-up runs in hyst_wide_t: the curve checks of the model, the table
 * of @p intervals pieces into @p table (HYST_Q31_INV_TABLE_LEN(intervals)
 * words) and the curve into @p inv, both caller storage that must outlive
 * the instance. The arrays hold desired outputs (xltp, xrtp) and drives.
 * @return HYST_OK, HYST_ERR_NULL, a curve error, HYST_ERR_DOMAIN (code
 *         range empty or wider than HYST_CODE_BITS), HYST_ERR_COEFF (as
 *         hyst_q31_init()), HYST_ERR_ARG (@p intervals outside
 *         1..HYST_Q31_INV_MAX_INTERVALS), HYST_ERR_LAYOUT,
 *         HYST_ERR_CAPACITY or HYST_ERR_OVERLAP, in this order. Nothing is
 *         written on error.
 */
hyst_status_t hyst_q31_init_inverse_table_(hyst_tcm_t *S, hyst_curve_t *inv,
                                           const hyst_poly_t *f0, uint_least32_t code_lo,
                                           uint_least32_t code_hi, hyst_q31_t *table,
                                           size_t intervals, hyst_q31_t *xltp,
                                           hyst_q31_t *yltp, hyst_q31_t *xrtp,
                                           hyst_q31_t *yrtp, size_t capacity,
                                           unsigned long layout);
#define hyst_q31_init_inverse_table(S, inv, f0, code_lo, code_hi, table, intervals, xltp, yltp, \
                                    xrtp, yrtp, capacity)                                      \
    hyst_q31_init_inverse_table_((S), (inv), (f0), (code_lo), (code_hi), (table), (intervals), \
                                 (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)

/** @brief The drive for the desired output @p desired (q, the model's
 *         format); outside [-2^27, 2^27] it is clamped (HYST_WARN_CLAMPED). */
hyst_q31_t hyst_q31_inv_step(hyst_tcm_t *S, hyst_q31_t desired);

/** @brief hyst_q31_inv_step() over a block, bit-identically (statuses as
 *         hyst_q31_process()); @p drive may be @p desired. */
hyst_status_t hyst_q31_inv_process(hyst_tcm_t *S, const hyst_q31_t *desired, hyst_q31_t *drive,
                                   size_t n);

/** @brief Noise deadband in desired-output units q (bounded memory, as
 *         hyst_q31_set_deadband()): HYST_ERR_ARG outside 0..2^28. */
hyst_status_t hyst_q31_inv_set_deadband(hyst_tcm_t *S, hyst_q31_t width);

/** @brief hyst_q31_inv_set_deadband() as a request from another context. */
hyst_status_t hyst_q31_inv_request_deadband(hyst_tcm_t *S, hyst_q31_t width);

/** @brief Last drive (0, code_lo, after init or reset). */
hyst_q31_t hyst_q31_inv_output(const hyst_tcm_t *S);

/** @brief Last valid desired output, after clamping. */
hyst_q31_t hyst_q31_inv_input(const hyst_tcm_t *S);

/** @brief Bound on the drive error caused by forgetting, in drive units. */
hyst_q31_t hyst_q31_inv_error_bound(const hyst_tcm_t *S);

/** @brief F, the drive's fraction bits (0 if @p S is not a q31 compensator). */
unsigned hyst_q31_inv_drive_bits(const hyst_tcm_t *S);

/** @brief The DAC code of a drive: code_lo + drive / 2^F rounded, inside
 *         code_lo..code_hi (0 if @p S is not a q31 compensator). */
uint_least32_t hyst_q31_inv_code(const hyst_tcm_t *S, hyst_q31_t drive);

#ifdef __cplusplus
}
#endif

#endif /* HYST_Q31_H */
