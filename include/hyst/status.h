/* SPDX-License-Identifier: MIT */
/**
 * @file status.h
 * @brief Status codes and sticky event flags shared by every hyst module.
 *
 * 0 is success, negative values are errors (nothing was changed), positive
 * values are warnings (a valid result was produced, but something was
 * adjusted: an input clamped, a turning point forgotten).
 */
#ifndef HYST_STATUS_H
#define HYST_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

/** @brief Result of a hyst call. */
typedef enum hyst_status {
    HYST_OK = 0,                 /**< success */
    HYST_WARN_CLAMPED = 1,       /**< input outside the domain, clamped to it */
    HYST_WARN_FULL = 2,          /**< memory full: the innermost loop was forgotten */
    HYST_ERR_NULL = -1,          /**< a required pointer is NULL */
    HYST_ERR_DOMAIN = -2,        /**< domain not finite or lo >= hi */
    HYST_ERR_DEGREE = -3,        /**< degree outside 1..HYST_MAX_DEGREE */
    HYST_ERR_CAPACITY = -4,      /**< turning-point capacity too small (< 2) */
    HYST_ERR_COEFF = -5,         /**< a coefficient is not finite, or f0 overflows */
    HYST_ERR_NOT_INCREASING = -6,/**< f0 is not increasing on [lo, hi] */
    HYST_ERR_NONFINITE = -7,     /**< a sample is NaN or infinite: ignored */
    HYST_ERR_ARG = -8,           /**< another argument is invalid (see the call) */
    HYST_ERR_NOSPACE = -9,       /**< a caller buffer is too small */
    HYST_ERR_SINGULAR = -10,     /**< too few distinct inputs for the fit (rank deficient) */
    HYST_ERR_FORMAT = -11,       /**< not a snapshot: bad magic, truncated, bad length or impossible state */
    HYST_ERR_CRC = -12,          /**< checksum mismatch: a snapshot, a prebuilt table or a sealed curve (curve.h) is corrupted */
    HYST_ERR_VERSION = -13,      /**< snapshot format version or real type differs */
    HYST_ERR_CURVE = -14,        /**< a snapshot or a prebuilt table of a different curve, or a curve of another kind than the one named (hyst_*_init_kind()) */
    HYST_ERR_BREAKPOINTS = -15,  /**< PWL breakpoints or PI thresholds not finite,
                                      not strictly increasing (PI: r1 != 0) */
    HYST_ERR_WEIGHTS = -16,      /**< PI weights not finite, or a partial sum
                                      w1 + ... + wi not positive */
    HYST_ERR_NOT_INVERTIBLE = -17, /**< curve not strictly increasing: no inverse */
    HYST_ERR_LAYOUT = -18,       /**< the caller was compiled with other layout options
                                      (HYST_LAYOUT, config.h) or passed a curve or
                                      instance of another variant */
    HYST_ERR_OVERLAP = -19,      /**< caller arrays overlap */
    HYST_ERR_BUSY = -20,         /**< the stepping context kept changing the state (snapshot) */
    HYST_ERR_ILL_CONDITIONED = -21, /**< the curve's rounding bound in this variant's type
                                        exceeds HYST_MAX_ROUNDING of its output range */
    HYST_ERR_NOT_MONOTONE = -22    /**< a branch function E not increasing in a and
                                        decreasing in b on the triangle b <= a */
} hyst_status_t;

/** @name Sticky event flags (hyst_events()): set by samples, cleared by the caller. */
/**@{*/
#define HYST_EVENT_NONFINITE 0x1u /**< a NaN/Inf sample was ignored */
#define HYST_EVENT_CLAMPED 0x2u   /**< an input was clamped to the domain */
#define HYST_EVENT_FULL 0x4u      /**< memory overflowed at least once */
/**@}*/

/**
 * @brief Short English name of a status code, for logs and tools.
 * @param[in] status a hyst_status_t value.
 * @return a static string, never NULL ("unknown status" for other values).
 */
const char *hyst_status_str(int status);

#ifdef __cplusplus
}
#endif

#endif /* HYST_STATUS_H */
