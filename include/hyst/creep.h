/* SPDX-License-Identifier: MIT */
/**
 * @file creep.h
 * @brief Creep: the slow drift of a piezo stage's displacement under a
 *        sustained drive, as a bank of first-order lags of the drive added
 *        to any hysteresis model's output (docs/creep.md).
 *
 * With n_terms <= HYST_CREEP_MAX_TERMS lags of time constants tau_k >= 1
 * (in samples), a_k = 1 / tau_k and weights w_k, sample n contributes
 *
 *     c[n] = sum_k w_k s_k[n],   s_k[n+1] = s_k[n] + a_k (x[n] - s_k[n]),
 *
 * k < n_terms, and every state s_k is x_rest (the drive the actuator rested
 * at) after init or reset. A hysteresis model H and its creep together
 * predict y[n] = H[x[n]] + c[n] (a Hammerstein-type creep term):
 * @code
 * y = hyst_step(&plant, x) + hyst_creep_step(&creep, x);
 * @endcode
 *
 * Strictly causal: c[n] depends on the drives up to x[n-1] only, so a
 * compensator knows it before it chooses x[n], subtracts it from the
 * desired output and inverts the hysteresis model alone:
 * @code
 * const hyst_real_t c = hyst_creep_output(&creep);         // c[n]
 * const hyst_real_t x = hyst_step(&comp, y_desired - c);   // H^-1[y_d - c]
 * (void)hyst_creep_step(&creep, x);                        // takes x[n] in
 * dac_write(x);
 * @endcode
 *
 * Precision. In the variant's type let M be the largest |x| of the drive,
 * x_rest included, and ulp(M) the type's spacing at M (2^-23 M at most in
 * float). An update rounds s_k by at most ulp(M)/2, and the rounding of
 * x - s_k, of the product and of a_k itself adds at most 5 a_k ulp(M); the
 * lag contracts an error by (1 - a_k) per sample, so each state stays
 * within (tau_k + 10) ulp(M) / 2 of the exact lag's (3.0e-4 M in float for
 * tau = 5000), and c within sum_k |w_k| (tau_k + 4 n_terms + 12) ulp(M) / 2
 * of the exact sum (the weights' rounding and the sum's added), to first
 * order in the rounding unit. With tau_k >= 2 no state leaves [-M, M];
 * below 2 a state may round one step past M: take ulp(2M) there.
 *
 * Cost per sample: per term one subtraction and two multiply-adds (the
 * lag's update, the weighted sum), with no division and no call; the
 * instance is statically sized and keeps no pointer.
 *
 * Snapshots (snapshot.h, hyst_creep_snapshot_save() and _restore()) keep
 * the lags through a brown-out, as hyst_snapshot_save() keeps the
 * hysteresis model's turning points. Concurrency as tcm.h's: one stepping
 * context calls step, init, reset, clear_events, output and restore; a
 * context it preempts on the same core may save a snapshot and read the
 * status, the events and the size at any time.
 */
#ifndef HYST_CREEP_H
#define HYST_CREEP_H

#include "hyst/status.h"
#include "hyst/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Most lags of a creep model (and of its fit). */
#define HYST_CREEP_MAX_TERMS 4u

/**
 * @brief A creep model of any real variant (f32 or f64: the type of its
 *        numbers). Read it through the functions below.
 */
typedef struct hyst_creep {
    unsigned variant;                        /**< HYST_VARIANT_F32 or _F64; 0 before init */
    size_t n;                                /**< lags, 1..HYST_CREEP_MAX_TERMS */
    hyst_num_t alpha[HYST_CREEP_MAX_TERMS];  /**< a_k = 1 / tau_k, in the variant's type */
    hyst_num_t weight[HYST_CREEP_MAX_TERMS]; /**< w_k */
    hyst_num_t state[HYST_CREEP_MAX_TERMS];  /**< s_k, the lags of the drive */
    /** largest |drive| taken: the type's largest number / (4 max(1, sum |w_k|)),
     *  so that no lag, difference or contribution overflows */
    hyst_num_t x_limit;
    int status;                              /**< hyst_status_t of the last sample */
    unsigned events;                         /**< sticky HYST_EVENT_* flags */
    unsigned long seq;                       /**< changed by every change of the state
                                                  (a snapshot's consistency check) */
} hyst_creep_t;

/**
 * @name Initialisation
 * @brief Sets up @p n_terms lags of time constants @p tau (samples) and
 *        weights @p weight, every state at @p x_rest, in the variant's type.
 *
 * Macros that pass the caller's HYST_LAYOUT (config.h).
 * @param[out] C       instance.
 * @param[in]  n_terms 1..HYST_CREEP_MAX_TERMS.
 * @param[in]  tau     n_terms time constants, each finite and >= 1, and
 *                     1 / tau a normal number of the type (tau up to about
 *                     8.5e37 in float).
 * @param[in]  weight  n_terms weights, finite in the type.
 * @param[in]  x_rest  the drive the actuator rested at, finite in the type.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_LAYOUT (caller built with other
 *         layout options); HYST_ERR_ARG (n_terms, or a tau); HYST_ERR_WEIGHTS
 *         (a weight not finite, or beyond the type's range); HYST_ERR_NONFINITE
 *         (x_rest not finite, or beyond the type's range, or beyond the drive
 *         limit: the type's largest number / (4 max(1, sum |w_k|))). Nothing
 *         written on error.
 */
/**@{*/
hyst_status_t hyst_f32_creep_init_(hyst_creep_t *C, size_t n_terms, const hyst_wide_t *tau,
                                   const hyst_wide_t *weight, hyst_wide_t x_rest,
                                   unsigned long layout);
#define hyst_f32_creep_init(C, n_terms, tau, weight, x_rest) \
    hyst_f32_creep_init_((C), (n_terms), (tau), (weight), (x_rest), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_creep_init_(hyst_creep_t *C, size_t n_terms, const hyst_wide_t *tau,
                                   const hyst_wide_t *weight, hyst_wide_t x_rest,
                                   unsigned long layout);
#define hyst_f64_creep_init(C, n_terms, tau, weight, x_rest) \
    hyst_f64_creep_init_((C), (n_terms), (tau), (weight), (x_rest), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Reset
 * @brief Every state to @p x_rest (the actuator rested at that drive);
 *        status HYST_OK, events cleared.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_LAYOUT (not an initialised
 *         instance of this variant); HYST_ERR_NONFINITE (x_rest NaN,
 *         infinite or beyond the drive limit). Nothing changed on error.
 */
/**@{*/
hyst_status_t hyst_f32_creep_reset(hyst_creep_t *C, float x_rest);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_creep_reset(hyst_creep_t *C, double x_rest);
#endif
/**@}*/

/**
 * @name Contribution of the next sample
 * @brief c[n] = sum_k w_k s_k[n], from the state: what the next
 *        hyst_*_creep_step() returns, whatever drive it takes. A compensator
 *        subtracts it before inverting the hysteresis model. NULL: 0.
 */
/**@{*/
float hyst_f32_creep_output(const hyst_creep_t *C);
#if HYST_ENABLE_F64
double hyst_f64_creep_output(const hyst_creep_t *C);
#endif
/**@}*/

/**
 * @name Per sample
 * @brief Returns c[n], computed from the state before @p x, then takes the
 *        drive @p x in (s_k += a_k (x - s_k)). O(n_terms), no branch on the
 *        history.
 *
 * A NaN or infinite @p x is ignored: c[n] returned, state unchanged, status
 * HYST_ERR_NONFINITE, event HYST_EVENT_NONFINITE. So is a finite @p x beyond
 * the drive limit (hyst_creep_t.x_limit: 8.5e37 / max(1, sum |w_k|) in
 * float), with status HYST_ERR_DOMAIN: a lag or the contribution would
 * overflow (near 3e38 in float the lags became NaN for good, status OK).
 * NULL: 0.
 */
/**@{*/
float hyst_f32_creep_step(hyst_creep_t *C, float x);
#if HYST_ENABLE_F64
double hyst_f64_creep_step(hyst_creep_t *C, double x);
#endif
/**@}*/

/** @brief Status of the last sample (hyst_status_t); NULL: HYST_ERR_NULL. */
int hyst_creep_status(const hyst_creep_t *C);

/** @brief Sticky HYST_EVENT_* flags since the last init, reset or clear; NULL: 0. */
unsigned hyst_creep_events(const hyst_creep_t *C);

/** @brief Clears the sticky event flags; NULL: nothing. */
void hyst_creep_clear_events(hyst_creep_t *C);

/** @brief Number of lags n_terms; NULL: 0. */
size_t hyst_creep_size(const hyst_creep_t *C);

/** @name Default variant (f32, or f64 with HYST_USE_DOUBLE) */
/**@{*/
#define hyst_creep_init HYST_DEFAULT_NAME_(creep_init)
#define hyst_creep_reset HYST_DEFAULT_NAME_(creep_reset)
#define hyst_creep_output HYST_DEFAULT_NAME_(creep_output)
#define hyst_creep_step HYST_DEFAULT_NAME_(creep_step)
/**@}*/

/* ---- Identification: the weights from a hysteresis model's residual ---- */

/**
 * @brief A creep fit in progress (hyst_creep_fit_init()): the lags of the
 *        drive in hyst_wide_t and the normal equations of their weights and
 *        a constant, accumulated about their running means. Statically
 *        sized; fields are private.
 */
typedef struct hyst_creep_fit {
    size_t n;                                 /**< lags */
    size_t used;                              /**< equations added */
    hyst_wide_t alpha[HYST_CREEP_MAX_TERMS];  /**< a_k = 1 / tau_k */
    hyst_wide_t state[HYST_CREEP_MAX_TERMS];  /**< s_k before the next sample */
    hyst_wide_t mean[HYST_CREEP_MAX_TERMS];   /**< mean of s_k over the equations */
    hyst_wide_t mean_r;                       /**< mean residual */
    /** co-moments of the states (upper triangle, row-major) */
    hyst_wide_t css[HYST_CREEP_MAX_TERMS * HYST_CREEP_MAX_TERMS];
    hyst_wide_t csr[HYST_CREEP_MAX_TERMS];    /**< co-moments of the states and the residual */
    hyst_wide_t crr;                          /**< co-moment of the residual */
} hyst_creep_fit_t;

/**
 * @brief Starts a fit of @p n_terms lags of time constants @p tau
 *        (samples), every lag at @p x_rest: the drive before the record.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_ARG (n_terms outside
 *         1..HYST_CREEP_MAX_TERMS, or a tau not finite or below 1);
 *         HYST_ERR_NONFINITE (x_rest). Nothing written on error.
 */
hyst_status_t hyst_creep_fit_init(hyst_creep_fit_t *F, size_t n_terms, const hyst_wide_t *tau,
                                  hyst_wide_t x_rest);

/**
 * @brief Takes the drive @p x in without an equation: the samples that
 *        settle the lags before a training window, and a sample whose
 *        residual is missing (the lags stay in step with the drive).
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_NONFINITE (x NaN or infinite:
 *         nothing changed).
 */
hyst_status_t hyst_creep_fit_feed(hyst_creep_fit_t *F, hyst_wide_t x);

/**
 * @brief Adds one equation, then takes the drive @p x in.
 *
 * @p residual is the measured output minus the hysteresis model's
 * prediction at this sample; its regressors are the lags' states before
 * @p x (the c[n] of hyst_*_creep_step(), which depends on the drives before
 * this sample) and a constant.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_NONFINITE (x or residual NaN or
 *         infinite: nothing changed; hyst_creep_fit_feed() a finite x whose
 *         residual is missing).
 */
hyst_status_t hyst_creep_fit_add(hyst_creep_fit_t *F, hyst_wide_t x, hyst_wide_t residual);

/**
 * @brief The least-squares weights and offset of the equations added:
 *        residual ~ offset + sum_k w_k s_k.
 *
 * The constant column is eliminated exactly (the equations are kept about
 * their means, whose Schur complement in the (n_terms + 1)-square normal
 * equations is the states' co-moment matrix); that matrix, scaled to a unit
 * diagonal for conditioning, is factored by Cholesky's method. A pivot at or
 * below 1e4 rounding units of its column's uncentred sum of squares means a
 * lag in the span of the others and the constant.
 * @param[in]  F      the fit (unchanged: more equations may follow).
 * @param[out] weight n_terms weights, for hyst_*_creep_init().
 * @param[out] offset the constant: the caller folds it into its hysteresis
 *                    model's output offset (the TCM curve's y_lo, the PI
 *                    fit's offset), or subtracts it from its measurements.
 * @param[out] rms    RMS of the residual minus the fit over the equations;
 *                    may be NULL.
 * @return HYST_OK; HYST_ERR_NULL (F, weight or offset); HYST_ERR_SINGULAR
 *         (no more equations than n_terms, a lag that never moved (a drive
 *         that stays where the lags have settled), two equal taus, lags
 *         otherwise indistinguishable over the record, or sums that
 *         overflowed). Nothing written on error.
 */
hyst_status_t hyst_creep_fit_solve(const hyst_creep_fit_t *F, hyst_wide_t *weight,
                                   hyst_wide_t *offset, hyst_wide_t *rms);

/**
 * @brief A creep term scored as a hold-out scores it (what `hyst fit` and
 *        the Python and MATLAB/Octave front ends choose its time constants
 *        by): fitted on the first samples, run from rest over all of them.
 */
typedef struct hyst_creep_holdout {
    hyst_wide_t weight[HYST_CREEP_MAX_TERMS]; /**< fitted on samples [0, train) */
    hyst_wide_t offset;                       /**< the constant fitted with them */
    hyst_wide_t fit_rms;                      /**< RMS residual over those equations */
    hyst_wide_t holdout_rms; /**< RMS of r - c - offset over [train, len) (0: none) */
    size_t holdout_used;     /**< the finite residuals it is over */
    hyst_wide_t max_abs;     /**< largest |r - c - offset| over every finite residual */
} hyst_creep_holdout_t;

/**
 * @brief Fits @p n_terms lags of time constants @p tau to the residual @p r
 *        of a model over its drive @p u on samples [0, @p train)
 *        (hyst_creep_fit_*(), from @p x_rest; a NaN residual is missing:
 *        the lags take its drive in), then runs the creep with those weights
 *        from rest over [0, @p len) (hyst_*_creep_step(), the f64 variant
 *        where double is linked) and scores it on [train, len).
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_ARG (train > len, n_terms or a
 *         tau as hyst_creep_fit_init()); HYST_ERR_NONFINITE (x_rest or a
 *         drive); HYST_ERR_SINGULAR (as hyst_creep_fit_solve()); the
 *         weights' refusal by hyst_*_creep_init(). Nothing written on error.
 */
hyst_status_t hyst_creep_fit_holdout(size_t n_terms, const hyst_wide_t *tau, hyst_wide_t x_rest,
                                     const hyst_wide_t *u, const hyst_wide_t *r, size_t len,
                                     size_t train, hyst_creep_holdout_t *out);

#ifdef __cplusplus
}
#endif

#endif /* HYST_CREEP_H */
