/**
 * @file pi.h
 * @brief The Prandtl-Ishlinskii (PI) model, its analytic inverse and its
 *        loading curve as a TCM curve (METHOD.md section 7).
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

#include "hyst/config.h"
#include "hyst/curve.h"
#include "hyst/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @brief A PI model instance. Fields are private; use the functions below. */
typedef struct hyst_pi {
    const hyst_real_t *r; /**< N thresholds, r[0] = 0, strictly increasing */
    const hyst_real_t *w; /**< N weights, positive partial sums */
    hyst_real_t *z;       /**< N operator states (caller memory) */
    size_t n;             /**< N, number of operators */
    hyst_real_t x_prev;   /**< last valid input (0 after init/reset) */
    hyst_real_t y_prev;   /**< last output (0 after init/reset) */
    int status;           /**< hyst_status_t of the last sample */
    unsigned events;      /**< sticky HYST_EVENT_* flags */
} hyst_pi_t;

/**
 * @brief Declares a PI instance and its N operator states, statically.
 * @code
 * static const hyst_real_t r[10] = { ... }, w[10] = { ... };
 * HYST_PI_DEFINE(plant, 10);
 * if (HYST_PI_INIT(plant, r, w) != HYST_OK) { handle_error(); }
 * @endcode
 */
#define HYST_PI_DEFINE(name, n)       \
    static hyst_real_t name##_z[n];   \
    static hyst_pi_t name

/** hyst_pi_init() on an instance declared by HYST_PI_DEFINE(). */
#define HYST_PI_INIT(name, r, w) \
    hyst_pi_init(&(name), (r), (w), name##_z, sizeof(name##_z) / sizeof(name##_z[0]))

/**
 * @brief Checks PI parameters without creating an instance.
 * @param[in] r thresholds, @p n entries: r[0] = 0, finite, strictly increasing.
 * @param[in] w weights, @p n entries: finite, w[0] + ... + w[i] > 0 for all i.
 * @param[in] n number of operators, >= 1.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (n = 0), HYST_ERR_BREAKPOINTS
 *         or HYST_ERR_WEIGHTS.
 */
hyst_status_t hyst_pi_check(const hyst_real_t *r, const hyst_real_t *w, size_t n);

/**
 * @brief Initialises a PI instance on caller-owned parameters and states.
 *
 * Validates as hyst_pi_check(), then resets (hyst_pi_reset()). On error
 * nothing is written. @p r and @p w are kept by pointer.
 *
 * @param[out] P  instance.
 * @param[in]  r  @p n thresholds.
 * @param[in]  w  @p n weights.
 * @param[in]  z  @p n operator states, written by the model.
 * @param[in]  n  number of operators, >= 1.
 * @return HYST_OK or an error of hyst_pi_check().
 */
hyst_status_t hyst_pi_init(hyst_pi_t *P, const hyst_real_t *r, const hyst_real_t *w,
                           hyst_real_t *z, size_t n);

/**
 * @brief Forgets the history: all operator states 0, output 0; clears events.
 * @param[in,out] P initialised instance.
 */
void hyst_pi_reset(hyst_pi_t *P);

/**
 * @brief Advances the PI model by one input sample. O(N), no branch on history.
 *
 * A NaN or infinite @p x is ignored (state untouched, previous output
 * returned, status HYST_ERR_NONFINITE, event HYST_EVENT_NONFINITE).
 * @param[in,out] P initialised instance.
 * @param[in]     x input sample.
 * @return output y = sum_i w_i z_i.
 */
hyst_real_t hyst_pi_step(hyst_pi_t *P, hyst_real_t x);

/**
 * @brief Runs hyst_pi_step() over a block of samples.
 * @param[in,out] P initialised instance.
 * @param[in]     x @p n inputs.
 * @param[out]    y @p n outputs (may be the same array as @p x).
 * @param[in]     n number of samples.
 * @return HYST_ERR_NONFINITE if any sample was not finite, else HYST_OK;
 *         HYST_ERR_NULL if a pointer is NULL with n > 0.
 */
hyst_status_t hyst_pi_process(hyst_pi_t *P, const hyst_real_t *x, hyst_real_t *y,
                              size_t n);

/**
 * @brief Parameters of the inverse PI model (also of PI type).
 *
 * With W_i = w_1 + ... + w_i and r_i, w_i the forward parameters:
 *     r'_i = sum_{j<i} w_j (r_i - r_j) = f_PI(r_i),
 *     w'_1 = 1 / w_1,   w'_i = -w_i / (W_i W_(i-1)),  i >= 2,
 * so that the inverse loading curve has slope 1 / W_i on [r'_i, r'_i+1].
 * A PI model with (r', w') maps the output of (r, w) back to its input, for
 * any input sequence (both starting from the reset state). Computed in
 * hyst_wide_t. Validates the forward parameters first, and refuses inverse
 * thresholds that rounding to hyst_real_t would make equal (
 * HYST_ERR_BREAKPOINTS) and inverse weights that, rounded, fail
 * hyst_pi_check() (HYST_ERR_WEIGHTS: 1 / w_1 overflows, or the partial sums
 * 1 / W_i cancel to 0 when W_i / W_1 exceeds about 1 / epsilon), so that the
 * inverse's parameters always pass hyst_pi_check(). On error nothing is
 * written. Output arrays must not overlap the inputs.
 *
 * @param[in]  r,w    forward parameters, @p n entries each.
 * @param[in]  n      number of operators.
 * @param[out] r_inv  @p n inverse thresholds.
 * @param[out] w_inv  @p n inverse weights.
 * @return HYST_OK, an error of hyst_pi_check(), HYST_ERR_BREAKPOINTS or
 *         HYST_ERR_WEIGHTS.
 */
hyst_status_t hyst_pi_inverse_params(const hyst_real_t *r, const hyst_real_t *w,
                                     size_t n, hyst_real_t *r_inv, hyst_real_t *w_inv);

/**
 * @brief Initialises @p inv as the inverse of the PI model @p fwd.
 *
 * hyst_pi_inverse_params() into @p r_inv, @p w_inv, then hyst_pi_init() on
 * them with the states @p z_inv (all three of fwd's N entries).
 * @return HYST_OK or an error of those two calls.
 */
hyst_status_t hyst_pi_init_inverse(hyst_pi_t *inv, const hyst_pi_t *fwd,
                                   hyst_real_t *r_inv, hyst_real_t *w_inv,
                                   hyst_real_t *z_inv);

/**
 * @brief The loading curve f_PI on [0, hi] as a piecewise-linear TCM curve.
 *
 * Fills the caller's @p bx with r_1..r_N, hi and @p by with f_PI there
 * (computed in hyst_wide_t), then hyst_curve_from_pwl() on them: a TCM
 * initialised with @p curve reproduces the PI model on inputs in [0, hi]
 * (METHOD.md section 7), and hyst_curve_inverse() of it gives the exact
 * inverse. @p bx and @p by are kept by the curve (see hyst_curve_from_pwl()).
 *
 * @param[out] curve prepared curve, domain [0, hi].
 * @param[in]  r,w   PI parameters, @p n entries each.
 * @param[in]  n     number of operators.
 * @param[in]  hi    upper end of the domain, finite, > r[n-1].
 * @param[out] bx,by @p n + 1 entries each.
 * @return HYST_OK, an error of hyst_pi_check(), HYST_ERR_DOMAIN (hi), or an
 *         error of hyst_curve_from_pwl().
 */
hyst_status_t hyst_pi_loading_curve(hyst_curve_t *curve, const hyst_real_t *r,
                                    const hyst_real_t *w, size_t n, hyst_real_t hi,
                                    hyst_real_t *bx, hyst_real_t *by);

/** @brief Status of the last sample (hyst_status_t). */
static inline int hyst_pi_status(const hyst_pi_t *P) { return P->status; }

/** @brief Sticky HYST_EVENT_* flags since the last reset or clear. */
static inline unsigned hyst_pi_events(const hyst_pi_t *P) { return P->events; }

/** @brief Clears the sticky event flags. */
static inline void hyst_pi_clear_events(hyst_pi_t *P) { P->events = 0u; }

/** @brief Last output (0 after init or reset). */
static inline hyst_real_t hyst_pi_output(const hyst_pi_t *P) { return P->y_prev; }

/** @brief Number of operators N. */
static inline size_t hyst_pi_size(const hyst_pi_t *P) { return P->n; }

#ifdef __cplusplus
}
#endif

#endif /* HYST_PI_H */
