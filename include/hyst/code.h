/**
 * @file code.h
 * @brief The TCM with integer inputs: unsigned DAC codes instead of reals.
 *
 * Same model, same rules and same engine source as hyst/tcm.h, with the
 * turning-point inputs stored as the smallest unsigned type that holds a
 * code (hyst_code_word_t): turning-point comparisons are exact (a code that
 * returns to a stored TP closes the loop bit for bit) and an entry takes
 * 2 + sizeof(hyst_real_t) bytes instead of 2 * sizeof(hyst_real_t) at 16 bits.
 *
 * The curve f0 stays in user units (volts, say) on [lo, hi]; the codes
 * code_lo..code_hi map linearly onto [lo, hi]. The branch formula takes the
 * code difference x - x_k, exact as an integer, converted to hyst_real_t
 * (exact up to 24 bits in float) and scaled once by 1 / (code_hi - code_lo),
 * folded into the curve at init: no extra per-sample work.
 *
 * Bounded memory and the deadband work as in hyst/tcm.h; see
 * docs/memory.md for the policy, its error bound and measured tables.
 */
#ifndef HYST_CODE_H
#define HYST_CODE_H

#include "hyst/tcm.h"

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief Widest code the integer variant accepts, in bits (1..24).
 *
 * 16 by default: codes are stored as uint_least16_t. 17..24 stores
 * uint_least32_t. Above 24 bits a float could not hold a code difference
 * exactly.
 */
#ifndef HYST_CODE_BITS
#define HYST_CODE_BITS 16
#endif
#if HYST_CODE_BITS < 1 || HYST_CODE_BITS > 24
#error "HYST_CODE_BITS must be 1..24"
#endif

#if HYST_CODE_BITS <= 16
typedef uint_least16_t hyst_code_word_t; /**< stored code: HYST_CODE_BITS fit */
#else
typedef uint_least32_t hyst_code_word_t; /**< stored code: HYST_CODE_BITS fit */
#endif

/** Largest code: 2^HYST_CODE_BITS - 1. */
#define HYST_CODE_MAX ((((uint_least32_t)1) << HYST_CODE_BITS) - 1u)

/**
 * @brief A TCM instance over DAC codes. Fields are private; use the
 *        functions below.
 */
typedef struct hyst_code {
    HYST_TCM_MEMBERS_(hyst_code_word_t);
    hyst_code_word_t lo; /**< code of the domain's lower end */
    hyst_code_word_t hi; /**< code of the domain's upper end */
} hyst_code_t;

/**
 * @brief RAM of one instance with @p capacity entries per array, in bytes
 *        (the struct and its four arrays).
 */
#define HYST_CODE_RAM(capacity)                                                    \
    (sizeof(hyst_code_t) +                                                         \
     2u * (size_t)(capacity) * (sizeof(hyst_code_word_t) + sizeof(hyst_real_t)))

/**
 * @brief Declares an instance with @p capacity entries per array, statically.
 *
 * For codes 0..2^bits - 1 that can never overflow, use
 * HYST_CAPACITY(1 << bits); a much smaller capacity is the bounded-memory
 * use (docs/memory.md).
 * @code
 * HYST_CODE_DEFINE(axis_x, 32);                  // 32 entries: 384 B + struct (16-bit codes)
 * ...
 * if (HYST_CODE_INIT(axis_x, &f0, 0u, 65535u) != HYST_OK) { handle_error(); }
 * y = hyst_code_step(&axis_x, dac_code);
 * @endcode
 */
#define HYST_CODE_DEFINE(name, capacity)                                  \
    static hyst_code_word_t name##_xltp[capacity];                        \
    static hyst_real_t name##_yltp[capacity];                             \
    static hyst_code_word_t name##_xrtp[capacity];                        \
    static hyst_real_t name##_yrtp[capacity];                             \
    static hyst_code_t name

/** hyst_code_init() on an instance declared by HYST_CODE_DEFINE(). */
#define HYST_CODE_INIT(name, f0, code_lo, code_hi)                               \
    hyst_code_init(&(name), (f0), (code_lo), (code_hi), name##_xltp, name##_yltp, \
                   name##_xrtp, name##_yrtp,                                     \
                   sizeof(name##_xltp) / sizeof(name##_xltp[0]))

/**
 * @brief Initialises an instance: f0 in user units, codes mapped onto its
 *        domain, caller-owned memory.
 *
 * Code code_lo is the input f0->lo, code code_hi the input f0->hi, linearly
 * in between. Validates everything once (curve checks: hyst_curve_from_poly())
 * and leaves the instance at A0, as hyst_code_reset(). On error nothing is
 * written.
 * @param[out] S         instance.
 * @param[in]  f0        major ascending curve, highest power first.
 * @param[in]  code_lo   code of f0->lo.
 * @param[in]  code_hi   code of f0->hi; code_lo < code_hi <= HYST_CODE_MAX.
 * @param[in]  xltp,yltp,xrtp,yrtp  four arrays of @p capacity entries each.
 * @param[in]  capacity  entries per array, >= 2.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY, HYST_ERR_DOMAIN (code
 *         range empty or wider than HYST_CODE_BITS) or a curve error.
 */
hyst_status_t hyst_code_init(hyst_code_t *S, const hyst_poly_t *f0, uint_least32_t code_lo,
                             uint_least32_t code_hi, hyst_code_word_t *xltp,
                             hyst_real_t *yltp, hyst_code_word_t *xrtp, hyst_real_t *yrtp,
                             size_t capacity);

/**
 * @brief As hyst_code_init(), with a curve already prepared.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY, HYST_ERR_DOMAIN or
 *         HYST_ERR_ARG (a curve not prepared by a hyst_curve_* constructor;
 *         every kind works on codes).
 */
hyst_status_t hyst_code_init_curve(hyst_code_t *S, const hyst_curve_t *curve,
                                   uint_least32_t code_lo, uint_least32_t code_hi,
                                   hyst_code_word_t *xltp, hyst_real_t *yltp,
                                   hyst_code_word_t *xrtp, hyst_real_t *yrtp,
                                   size_t capacity);

/**
 * @brief Forgets all turning points: back at A0 = (code_lo, f0(lo)); clears
 *        the events and the error bound, keeps the deadband.
 * @param[in,out] S initialised instance.
 */
void hyst_code_reset(hyst_code_t *S);

/**
 * @brief Noise deadband in codes (see hyst_set_deadband()); 0 disables it.
 * @param[in,out] S      initialised instance.
 * @param[in]     codes  deadband width, <= code_hi - code_lo.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG (wider than the domain).
 */
hyst_status_t hyst_code_set_deadband(hyst_code_t *S, uint_least32_t codes);

/**
 * @brief Advances the model by one code.
 *
 * As hyst_step(): a constant fast path while the code moves on along its
 * branch; one binary search when a stored TP is passed; a merge (full
 * array) costs at most 6 + 2 * bits evaluations of g (38 at 16 bits).
 * A code outside [code_lo, code_hi] is clamped (status HYST_WARN_CLAMPED).
 * @param[in,out] S     initialised instance.
 * @param[in]     code  input code.
 * @return output y.
 */
hyst_real_t hyst_code_step(hyst_code_t *S, uint_least32_t code);

/**
 * @brief Runs hyst_code_step() over a block of codes.
 * @param[in,out] S  initialised instance.
 * @param[in]     x  @p n codes.
 * @param[out]    y  @p n outputs.
 * @param[in]     n  number of samples.
 * @return HYST_WARN_FULL if any overflow happened, else HYST_WARN_CLAMPED if
 *         any code was clamped, else HYST_OK; HYST_ERR_NULL if a pointer is
 *         NULL with n > 0.
 */
hyst_status_t hyst_code_process(hyst_code_t *S, const hyst_code_word_t *x, hyst_real_t *y,
                                size_t n);

/** @brief Status of the last sample (hyst_status_t). */
static inline int hyst_code_status(const hyst_code_t *S) { return S->status; }

/** @brief Sticky HYST_EVENT_* flags since the last reset or clear. */
static inline unsigned hyst_code_events(const hyst_code_t *S) { return S->events; }

/** @brief Clears the sticky event flags. */
static inline void hyst_code_clear_events(hyst_code_t *S) { S->events = 0u; }

/** @brief Last output (f0(lo) after init or reset). */
static inline hyst_real_t hyst_code_output(const hyst_code_t *S) { return S->y_prev; }

/** @brief Last valid code, after clamping (code_lo after init or reset). */
static inline uint_least32_t hyst_code_input(const hyst_code_t *S)
{
    return S->window[S->moving_end];
}

/** @brief Stored TPs, excluding the anchor A0. */
static inline size_t hyst_code_tp_count(const hyst_code_t *S)
{
    return S->n_ltp - 1u + S->n_rtp;
}

/** @brief 1 if the current branch rises, 0 if it falls. */
static inline int hyst_code_rising(const hyst_code_t *S) { return S->n_ltp > S->n_rtp; }

/** @brief As hyst_error_bound(): bound on the error caused by forgetting. */
static inline hyst_real_t hyst_code_error_bound(const hyst_code_t *S)
{
    return S->forgot + S->db_err;
}

#ifdef __cplusplus
}
#endif

#endif /* HYST_CODE_H */
