/* SPDX-License-Identifier: MIT */
/**
 * @file pi.h
 * @brief The Prandtl-Ishlinskii (PI) model, its analytic inverse and its
 *        loading curve as a TCM curve (docs/theory.md).
 *
 * N one-sided play operators with thresholds 0 = r1 < r2 < ... < rN and
 * weights wi (paper Eq. 15):
 *
 *     z_i(t) = max(x(t) - r_i, min(x(t), z_i(t-1))),  z_i = 0 before the
 *     first sample;  y(t) = sum_i w_i z_i(t).
 *
 * At the first sample this gives z_i(0) = max(x(0) - r_i, min(x(0), 0)), and
 * the output before any sample is 0. The loading curve (the major ascending
 * curve from x = 0) is f_PI(x) = sum_i w_i max(0, x - r_i), piecewise linear
 * with slope W_i = w_1 + ... + w_i on [r_i, r_i+1].
 *
 * The instance keeps pointers to the caller's thresholds and weights (which
 * must outlive it, unchanged) and works in a caller array of N operator
 * states: no allocation, O(N) per sample, no branch on the history.
 *
 * Parameters are checked once at init: r1 = 0, thresholds finite and strictly
 * increasing, weights finite with every partial sum W_i > 0. The last
 * condition makes the loading curve strictly increasing, which is what an
 * actuator model needs and what makes the inverse exist; the inverse's own
 * parameters satisfy it again.
 *
 * Unlike the TCM, the PI model has no domain: any finite input is used as is
 * (below 0 every operator follows x). A TCM with f0 = f_PI on [0, hi]
 * reproduces it for inputs in [0, hi], starting at 0.
 */
#ifndef HYST_PI_H
#define HYST_PI_H

#include "hyst/curve.h"
#include "hyst/status.h"
#include "hyst/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief A PI model instance of any real variant (f32 or f64: the type of
 *        its numbers). Read it through the functions below.
 */
typedef struct hyst_pi {
    unsigned variant;  /**< HYST_VARIANT_F32 or HYST_VARIANT_F64; 0 before init */
    hyst_cptr_t r;     /**< N thresholds, r[0] = 0, strictly increasing */
    hyst_cptr_t w;     /**< N weights, positive partial sums */
    hyst_ptr_t z;      /**< N operator states (caller memory) */
    size_t n;          /**< N, number of operators */
    hyst_num_t x_prev; /**< last valid input (0 after init/reset) */
    hyst_num_t y_prev; /**< last output (0 after init/reset) */
    int status;        /**< hyst_status_t of the last sample */
    unsigned events;   /**< sticky HYST_EVENT_* flags */
} hyst_pi_t;

/**
 * @brief Declares a PI instance and its N operator states, statically
 *        (default variant; HYST_F32_PI_DEFINE / HYST_F64_PI_DEFINE name one).
 * @code
 * static const hyst_real_t r[10] = { ... }, w[10] = { ... };
 * HYST_PI_DEFINE(plant, 10);
 * if (HYST_PI_INIT(plant, r, w) != HYST_OK) { handle_error(); }
 * @endcode
 */
#define HYST_PI_DEFINE(name, n) HYST_PI_DEFINE_(name, hyst_real_t, n)
#define HYST_F32_PI_DEFINE(name, n) HYST_PI_DEFINE_(name, float, n)
#define HYST_F64_PI_DEFINE(name, n) HYST_PI_DEFINE_(name, double, n)
/** @cond */
#define HYST_PI_DEFINE_(name, type, n) \
    static type name##_z[n];           \
    static hyst_pi_t name
/** @endcond */

/** hyst_pi_init() on an instance declared by HYST_PI_DEFINE(). */
#define HYST_PI_INIT(name, r, w) \
    hyst_pi_init(&(name), (r), (w), name##_z, sizeof(name##_z) / sizeof(name##_z[0]))

/**
 * @name Parameter check
 * @brief r1 = 0, thresholds finite and strictly increasing
 *        (HYST_ERR_BREAKPOINTS), weights finite with every partial sum
 *        w1 + ... + wi > 0 (HYST_ERR_WEIGHTS); n >= 1 (HYST_ERR_ARG).
 */
/**@{*/
hyst_status_t hyst_f32_pi_check(const float *r, const float *w, size_t n);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_check(const double *r, const double *w, size_t n);
#endif
/**@}*/

/**
 * @name Initialisation
 * @brief Checks the parameters (pi_check) and the caller's layout, and
 *        resets the instance. The instance keeps @p r and @p w (which must
 *        outlive it, unchanged) and works in @p z, N operator states.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT or an error of the check;
 *         nothing written on error.
 */
/**@{*/
hyst_status_t hyst_f32_pi_init_(hyst_pi_t *P, const float *r, const float *w, float *z, size_t n,
                                unsigned long layout);
#define hyst_f32_pi_init(P, r, w, z, n) hyst_f32_pi_init_((P), (r), (w), (z), (n), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_init_(hyst_pi_t *P, const double *r, const double *w, double *z,
                                size_t n, unsigned long layout);
#define hyst_f64_pi_init(P, r, w, z, n) hyst_f64_pi_init_((P), (r), (w), (z), (n), HYST_LAYOUT)
#endif
/**@}*/

/** @brief Back to the state before the first sample (z = 0, output 0); NULL: nothing. */
void hyst_pi_reset(hyst_pi_t *P);

/**
 * @name Per sample
 * @brief Advances the PI model by one input sample: y = sum_i w_i z_i. O(N),
 *        no branch on the history.
 *
 * A NaN or infinite @p x is ignored (state untouched, previous output
 * returned, status HYST_ERR_NONFINITE, event HYST_EVENT_NONFINITE).
 */
/**@{*/
float hyst_f32_pi_step(hyst_pi_t *P, float x);
#if HYST_ENABLE_F64
double hyst_f64_pi_step(hyst_pi_t *P, double x);
#endif
/**@}*/

/**
 * @name Block of samples
 * @brief The per-sample call over @p n samples (@p y may be @p x).
 * @return HYST_ERR_NONFINITE if any sample was not finite, else HYST_OK;
 *         HYST_ERR_NULL if a pointer is NULL with n > 0; HYST_ERR_OVERLAP
 *         if @p y overlaps @p x other than exactly in place (nothing
 *         written).
 */
/**@{*/
hyst_status_t hyst_f32_pi_process(hyst_pi_t *P, const float *x, float *y, size_t n);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_process(hyst_pi_t *P, const double *x, double *y, size_t n);
#endif
/**@}*/

/**
 * @name Inverse parameters
 * @brief Parameters of the inverse PI model (also of PI type).
 *
 * With W_i = w_1 + ... + w_i and r_i, w_i the forward parameters:
 *     r'_i = sum_{j<i} w_j (r_i - r_j) = f_PI(r_i),
 *     w'_1 = 1 / w_1,   w'_i = -w_i / (W_i W_(i-1)),  i >= 2,
 * so that the inverse loading curve has slope 1 / W_i on [r'_i, r'_i+1].
 * A PI model with (r', w') maps the output of (r, w) back to its input, for
 * any input sequence (both starting from the reset state). Computed in
 * hyst_wide_t. Validates the forward parameters first, and refuses inverse
 * thresholds that rounding to the variant's type would make equal
 * (HYST_ERR_BREAKPOINTS) and inverse weights that, rounded, fail the check
 * (HYST_ERR_WEIGHTS: 1 / w_1 overflows, or the partial sums 1 / W_i cancel
 * to 0 when W_i / W_1 exceeds about 1 / epsilon), so that the inverse's
 * parameters always pass it. On error nothing is written. Output arrays
 * must not overlap the inputs.
 */
/**@{*/
hyst_status_t hyst_f32_pi_inverse_params(const float *r, const float *w, size_t n, float *r_inv,
                                         float *w_inv);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_inverse_params(const double *r, const double *w, size_t n,
                                         double *r_inv, double *w_inv);
#endif
/**@}*/

/**
 * @name Inverse model
 * @brief Initialises @p inv as the inverse of the PI model @p fwd (same
 *        variant): inverse_params into @p r_inv, @p w_inv, then init with the
 *        states @p z_inv (all three of fwd's N entries).
 * @return HYST_OK, HYST_ERR_ARG (fwd of another variant) or an error of
 *         those two calls.
 */
/**@{*/
hyst_status_t hyst_f32_pi_init_inverse_(hyst_pi_t *inv, const hyst_pi_t *fwd, float *r_inv,
                                        float *w_inv, float *z_inv, unsigned long layout);
#define hyst_f32_pi_init_inverse(inv, fwd, r_inv, w_inv, z_inv) \
    hyst_f32_pi_init_inverse_((inv), (fwd), (r_inv), (w_inv), (z_inv), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_init_inverse_(hyst_pi_t *inv, const hyst_pi_t *fwd, double *r_inv,
                                        double *w_inv, double *z_inv, unsigned long layout);
#define hyst_f64_pi_init_inverse(inv, fwd, r_inv, w_inv, z_inv) \
    hyst_f64_pi_init_inverse_((inv), (fwd), (r_inv), (w_inv), (z_inv), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Loading curve
 * @brief The loading curve f_PI on [0, hi] as a piecewise-linear TCM curve.
 *
 * Fills the caller's @p bx with r_1..r_N, hi and @p by with f_PI there
 * (computed in hyst_wide_t), then the PWL constructor on them: a TCM
 * initialised with @p curve reproduces the PI model on inputs in [0, hi]
 * (docs/theory.md), and hyst_curve_inverse() of it gives the exact
 * inverse. @p bx and @p by (n + 1 entries each) are kept by the curve.
 * @return HYST_OK, an error of the check, HYST_ERR_DOMAIN (hi not finite or
 *         not above r[n-1]), or an error of the PWL constructor.
 */
/**@{*/
hyst_status_t hyst_f32_pi_loading_curve(hyst_curve_t *curve, const float *r, const float *w,
                                        size_t n, float hi, float *bx, float *by);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_pi_loading_curve(hyst_curve_t *curve, const double *r, const double *w,
                                        size_t n, double hi, double *bx, double *by);
#endif
/**@}*/

/** @name Last output (0 after init or reset) */
/**@{*/
float hyst_f32_pi_output(const hyst_pi_t *P);
#if HYST_ENABLE_F64
double hyst_f64_pi_output(const hyst_pi_t *P);
#endif
/**@}*/

/** @brief Status of the last sample (hyst_status_t); NULL: HYST_ERR_NULL. */
int hyst_pi_status(const hyst_pi_t *P);

/** @brief Sticky HYST_EVENT_* flags since the last reset or clear. */
unsigned hyst_pi_events(const hyst_pi_t *P);

/** @brief Clears the sticky event flags. */
void hyst_pi_clear_events(hyst_pi_t *P);

/** @brief Number of operators N. */
size_t hyst_pi_size(const hyst_pi_t *P);

/** @name Default variant (f32, or f64 with HYST_USE_DOUBLE) */
/**@{*/
#define hyst_pi_check HYST_DEFAULT_NAME_(pi_check)
#define hyst_pi_init HYST_DEFAULT_NAME_(pi_init)
#define hyst_pi_step HYST_DEFAULT_NAME_(pi_step)
#define hyst_pi_process HYST_DEFAULT_NAME_(pi_process)
#define hyst_pi_inverse_params HYST_DEFAULT_NAME_(pi_inverse_params)
#define hyst_pi_init_inverse HYST_DEFAULT_NAME_(pi_init_inverse)
#define hyst_pi_loading_curve HYST_DEFAULT_NAME_(pi_loading_curve)
#define hyst_pi_output HYST_DEFAULT_NAME_(pi_output)
/**@}*/

#ifdef __cplusplus
}
#endif

#endif /* HYST_PI_H */
