/* SPDX-License-Identifier: MIT */
/**
 * @file code.h
 * @brief The TCM with integer inputs: unsigned DAC codes instead of reals.
 *
 * Same model, same rules and same engine source as hyst/tcm.h (hyst_tcm_t), with the
 * turning-point inputs stored as the smallest unsigned type that holds a
 * code (hyst_code_word_t): turning-point comparisons are exact (a code that
 * returns to a stored TP closes the loop bit for bit) and an entry takes
 * 2 + 4 bytes instead of 2 * 4 at 16 bits.
 *
 * The curve f0 stays in user units (volts, say) on [lo, hi]; the codes
 * code_lo..code_hi map linearly onto [lo, hi]. The branch formula takes the
 * code difference x - x_k, exact as an integer, converted to hyst_real_t
 * (exact up to 24 bits in float) and scaled once by 1 / (code_hi - code_lo),
 * folded into the curve at init: no extra per-sample work.
 *
 * Bounded memory and the deadband work as in hyst/tcm.h (hyst_tcm_t); see
 * docs/memory.md for the policy, its error bound and measured tables.
 */
#ifndef HYST_CODE_H
#define HYST_CODE_H

#include "hyst/tcm.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief RAM of one instance with @p capacity entries per array, in bytes
 *        (the struct and its four arrays).
 */
#define HYST_CODE_RAM(capacity) \
    (sizeof(hyst_tcm_t) + 2u * (size_t)(capacity) * (sizeof(hyst_code_word_t) + sizeof(float)))

/**
 * @brief Declares an instance for inputs with @p nu distinct codes
 *        (HYST_CAPACITY(nu) entries per array, which can never overflow),
 *        statically; the same unit as HYST_DEFINE().
 *
 * For bounded memory (docs/memory.md) give the number of codes the arrays
 * may hold without overflow: HYST_CODE_DEFINE(axis, 64) holds 32 entries.
 * @code
 * HYST_CODE_DEFINE(axis_x, 64);            // 32 entries: 384 B + struct (16-bit codes)
 * ...
 * if (HYST_CODE_INIT(axis_x, &f0, 0u, 65535u) != HYST_OK) { handle_error(); }
 * y = hyst_code_step(&axis_x, dac_code);
 * @endcode
 */
#define HYST_CODE_DEFINE(name, nu) HYST_DEFINE_ARRAYS_(name, hyst_code_word_t, float, nu)

/** hyst_code_init() on an instance declared by HYST_CODE_DEFINE(). */
#define HYST_CODE_INIT(name, f0, code_lo, code_hi) \
    hyst_code_init_(&(name), (f0), (code_lo), (code_hi), HYST_ARRAYS_(name), HYST_LAYOUT)

/**
 * @brief Initialises an instance: f0 in user units, codes mapped onto its
 *        domain, caller-owned memory.
 *
 * Code code_lo is the input f0->lo, code code_hi the input f0->hi, linearly
 * in between. Validates everything once (curve checks: hyst_f32_curve_from_poly())
 * and leaves the instance at A0, as hyst_reset(). On error nothing is
 * written. The arrays must not overlap.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *         HYST_ERR_OVERLAP, HYST_ERR_DOMAIN (code range empty or wider than
 *         HYST_CODE_BITS) or a curve error.
 */
hyst_status_t hyst_code_init_(hyst_tcm_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                              uint_least32_t code_hi, hyst_code_word_t *xltp, float *yltp,
                              hyst_code_word_t *xrtp, float *yrtp, size_t capacity,
                              unsigned long layout);
#define hyst_code_init(S, f0, code_lo, code_hi, xltp, yltp, xrtp, yrtp, capacity)          \
    hyst_code_init_((S), (f0), (code_lo), (code_hi), (xltp), (yltp), (xrtp), (yrtp),      \
                    (capacity), HYST_LAYOUT)

/**
 * @brief As hyst_code_init(), with an f32 curve already prepared (any kind).
 *        The instance keeps a pointer to @p curve: it must outlive it.
 * @return as hyst_code_init(), or HYST_ERR_ARG (a curve not prepared by a
 *         constructor).
 */
hyst_status_t hyst_code_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve,
                                    uint_least32_t code_lo, uint_least32_t code_hi,
                                    hyst_code_word_t *xltp, float *yltp, hyst_code_word_t *xrtp,
                                    float *yrtp, size_t capacity, unsigned long layout);
#define hyst_code_init_curve(S, curve, code_lo, code_hi, xltp, yltp, xrtp, yrtp, capacity)  \
    hyst_code_init_curve_((S), (curve), (code_lo), (code_hi), (xltp), (yltp), (xrtp),       \
                          (yrtp), (capacity), HYST_LAYOUT)

/**
 * @brief As hyst_code_init_curve(), with the curve's kind named by the
 *        caller (hyst_f32_init_kind(); the code variant's kinds,
 *        hyst_code_kind_poly, ...): a firmware that names its kinds links
 *        no other.
 * @return as hyst_code_init_curve(), or HYST_ERR_NULL (@p kind NULL) or
 *         HYST_ERR_CURVE (a curve of another kind, or a kind of another
 *         variant).
 */
hyst_status_t hyst_code_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                   uint_least32_t code_lo, uint_least32_t code_hi,
                                   hyst_code_word_t *xltp, float *yltp, hyst_code_word_t *xrtp,
                                   float *yrtp, size_t capacity, unsigned long layout);
#define hyst_code_init_kind(S, curve, kind, code_lo, code_hi, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_code_init_kind_((S), (curve), (kind), (code_lo), (code_hi), (xltp), (yltp), (xrtp),    \
                         (yrtp), (capacity), HYST_LAYOUT)
const void *hyst_code_kind_poly(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_pwl(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_everett(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_everett_grid(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_spline(const hyst_curve_t *curve, unsigned variant);
const void *hyst_code_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant);

/**
 * @brief Noise deadband in codes (see hyst_f32_set_deadband()); 0 disables it.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG (wider than the domain, or
 *         an instance of another variant).
 */
hyst_status_t hyst_code_set_deadband(hyst_tcm_t *S, uint_least32_t codes);

/** @brief hyst_code_set_deadband() as a request from another context (tcm.h,
 *         "Concurrency"): applied by the stepping context at its next step. */
hyst_status_t hyst_code_request_deadband(hyst_tcm_t *S, uint_least32_t codes);

/**
 * @brief Advances the model by one code.
 *
 * As hyst_f32_step(): a constant fast path while the code moves on along its
 * branch; one binary search when a stored TP is passed; a merge (full
 * array) costs at most 6 + 2 * bits evaluations of g (38 at 16 bits).
 * A code outside [code_lo, code_hi] is clamped (status HYST_WARN_CLAMPED).
 */
float hyst_code_step(hyst_tcm_t *S, uint_least32_t code);

/**
 * @brief Runs hyst_code_step() over a block of codes, bit-identically.
 * @return HYST_WARN_FULL if any overflow happened, else HYST_WARN_CLAMPED if
 *         any code was clamped, else HYST_OK; HYST_ERR_NULL if a pointer is
 *         NULL with n > 0; HYST_ERR_OVERLAP if @p y overlaps @p x (in place
 *         only where an output is no larger than a code word; nothing
 *         written).
 */
hyst_status_t hyst_code_process(hyst_tcm_t *S, const hyst_code_word_t *x, float *y, size_t n);

/** @brief Last output (f0(lo) after init or reset). */
float hyst_code_output(const hyst_tcm_t *S);

/** @brief Last valid code, after clamping (code_lo after init or reset). */
uint_least32_t hyst_code_input(const hyst_tcm_t *S);

/** @brief As hyst_f32_error_bound(): bound on the error caused by forgetting. */
float hyst_code_error_bound(const hyst_tcm_t *S);

/** @brief As hyst_f32_rounding_bound(): the curve's rounding bound in float. */
float hyst_code_rounding_bound(const hyst_tcm_t *S);

#ifdef __cplusplus
}
#endif

#endif /* HYST_CODE_H */
