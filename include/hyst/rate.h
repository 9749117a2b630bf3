/* SPDX-License-Identifier: MIT */
/**
 * @file rate.h
 * @brief Rate: a rate-dependent term added to any hysteresis model's output,
 *        a weight times a first-order low-pass of the drive's change per
 *        sample (docs/rate.md).
 *
 * With time constant tau >= 1 (in samples), a = 1 / tau and weight w,
 * sample n contributes
 *
 *     r[n] = w v[n],   v[n+1] = v[n] + a ((x[n] - p[n]) - v[n]),   p[n+1] = x[n],
 *
 * p the drive taken last and v the low-pass of its changes; after init or
 * reset p is x_rest (the drive the actuator rested at) and v is 0. tau = 1
 * makes v[n+1] the last change itself, x[n] - x[n-1]. A hysteresis model H
 * and its rate term together predict y[n] = H[x[n]] + r[n]: the loops a
 * faster drive widens, which a rate-independent H cannot follow.
 * @code
 * y = hyst_step(&plant, x) + hyst_rate_step(&rate, x);
 * @endcode
 *
 * Strictly causal, like creep.h's term: r[n] depends on the drives up to
 * x[n-1] only, so a compensator knows it before it chooses x[n], subtracts
 * it from the desired output and inverts the hysteresis model alone (with
 * a creep term too, both subtracted):
 * @code
 * const hyst_real_t r = hyst_rate_output(&rate);          // r[n]
 * const hyst_real_t x = hyst_step(&comp, y_desired - r);  // H^-1[y_d - r]
 * (void)hyst_rate_step(&rate, x);                         // takes x[n] in
 * dac_write(x);
 * @endcode
 * The compensated output is then y_d exactly where the model is exact:
 * H[x[n]] + r[n] = y_d[n], as r[n] does not depend on x[n].
 *
 * Precision. In the variant's type let M be the largest |x| of the drive,
 * x_rest included, and ulp(2M) the type's spacing at 2M (2^-22 M at most in
 * float). An update rounds the change x - p, its difference from v and a
 * itself, and the multiply-add: the low-pass contracts an error by (1 - a)
 * per sample, so v stays within (tau + 8) ulp(2M) / 2 of the exact
 * low-pass's, and r within |w| (tau + 12) ulp(2M) / 2 of the exact term (the
 * weight's rounding and the product's added), to first order in the
 * rounding unit.
 *
 * Cost per sample: two subtractions and two multiply-adds, no division and
 * no call; the instance is statically sized and keeps no pointer.
 *
 * Concurrency as tcm.h's: one stepping context calls step, init, reset,
 * clear_events and output; a context it preempts on the same core may read
 * the status and the events, and save a snapshot (snapshot.h, "Rate
 * snapshots": p and v through a brown-out), at any time.
 */
#ifndef HYST_RATE_H
#define HYST_RATE_H

#include "hyst/status.h"
#include "hyst/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A rate term of any real variant (f32 or f64: the type of its
 *        numbers). Read it through the functions below.
 */
typedef struct hyst_rate {
    unsigned variant;   /**< HYST_VARIANT_F32 or _F64; 0 before init */
    hyst_num_t alpha;   /**< a = 1 / tau, in the variant's type */
    hyst_num_t weight;  /**< w */
    hyst_num_t last;    /**< p, the drive taken last */
    hyst_num_t state;   /**< v, the low-pass of the drive's change */
    /** largest |drive| taken: the type's largest number / (4 max(1, |w|)),
     *  so that no change, low-pass or contribution overflows */
    hyst_num_t x_limit;
    int status;         /**< hyst_status_t of the last sample */
    unsigned events;    /**< sticky HYST_EVENT_* flags */
    unsigned long seq;  /**< changed by every change of the state (a snapshot's
                             consistency check) */
} hyst_rate_t;

/**
 * @name Initialisation
 * @brief Sets up a rate term of time constant @p tau (samples) and weight
 *        @p weight, at rest at drive @p x_rest, in the variant's type.
 *
 * Macros that pass the caller's HYST_LAYOUT (config.h).
 * @param[out] R      instance.
 * @param[in]  tau    finite and >= 1, and 1 / tau a normal number of the
 *                    type.
 * @param[in]  weight finite in the type.
 * @param[in]  x_rest the drive the actuator rested at, finite in the type.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_LAYOUT (caller built with other
 *         layout options); HYST_ERR_ARG (tau); HYST_ERR_WEIGHTS (the weight
 *         not finite, or beyond the type's range); HYST_ERR_NONFINITE
 *         (x_rest not finite, or beyond the drive limit: the type's largest
 *         number / (4 max(1, |w|))). Nothing written on error.
 */
/**@{*/
hyst_status_t hyst_f32_rate_init_(hyst_rate_t *R, hyst_wide_t tau, hyst_wide_t weight,
                                  hyst_wide_t x_rest, unsigned long layout);
#define hyst_f32_rate_init(R, tau, weight, x_rest) \
    hyst_f32_rate_init_((R), (tau), (weight), (x_rest), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_rate_init_(hyst_rate_t *R, hyst_wide_t tau, hyst_wide_t weight,
                                  hyst_wide_t x_rest, unsigned long layout);
#define hyst_f64_rate_init(R, tau, weight, x_rest) \
    hyst_f64_rate_init_((R), (tau), (weight), (x_rest), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Reset
 * @brief At rest at drive @p x_rest: p = x_rest, v = 0; status HYST_OK,
 *        events cleared.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_LAYOUT (not an initialised
 *         instance of this variant); HYST_ERR_NONFINITE (x_rest NaN,
 *         infinite or beyond the drive limit). Nothing changed on error.
 */
/**@{*/
hyst_status_t hyst_f32_rate_reset(hyst_rate_t *R, float x_rest);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_rate_reset(hyst_rate_t *R, double x_rest);
#endif
/**@}*/

/**
 * @name Contribution of the next sample
 * @brief r[n] = w v[n], from the state: what the next hyst_*_rate_step()
 *        returns, whatever drive it takes. A compensator subtracts it
 *        before inverting the hysteresis model. NULL: 0.
 */
/**@{*/
float hyst_f32_rate_output(const hyst_rate_t *R);
#if HYST_ENABLE_F64
double hyst_f64_rate_output(const hyst_rate_t *R);
#endif
/**@}*/

/**
 * @name Per sample
 * @brief Returns r[n], computed from the state before @p x, then takes the
 *        drive @p x in. No branch on the history.
 *
 * A NaN or infinite @p x is ignored: r[n] returned, state unchanged, status
 * HYST_ERR_NONFINITE, event HYST_EVENT_NONFINITE. So is a finite @p x beyond
 * the drive limit (hyst_rate_t.x_limit), with status HYST_ERR_DOMAIN. NULL: 0.
 */
/**@{*/
float hyst_f32_rate_step(hyst_rate_t *R, float x);
#if HYST_ENABLE_F64
double hyst_f64_rate_step(hyst_rate_t *R, double x);
#endif
/**@}*/

/** @brief Status of the last sample (hyst_status_t); NULL: HYST_ERR_NULL. */
int hyst_rate_status(const hyst_rate_t *R);

/** @brief Sticky HYST_EVENT_* flags since the last init, reset or clear; NULL: 0. */
unsigned hyst_rate_events(const hyst_rate_t *R);

/** @brief Clears the sticky event flags; NULL: nothing. */
void hyst_rate_clear_events(hyst_rate_t *R);

/** @name Default variant (f32, or f64 with HYST_USE_DOUBLE) */
/**@{*/
#define hyst_rate_init HYST_DEFAULT_NAME_(rate_init)
#define hyst_rate_reset HYST_DEFAULT_NAME_(rate_reset)
#define hyst_rate_output HYST_DEFAULT_NAME_(rate_output)
#define hyst_rate_step HYST_DEFAULT_NAME_(rate_step)
/**@}*/

#ifdef __cplusplus
}
#endif

#endif /* HYST_RATE_H */
