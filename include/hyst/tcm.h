/**
 * @file tcm.h
 * @brief The trajectory construction method (TCM): a hysteresis model instance.
 *
 * One instance models one actuator axis. It keeps the turning points (TPs)
 * that still matter in four caller-owned arrays of equal length:
 *
 *  - xltp/yltp: left TPs (input was falling, then rose), x ascending;
 *    entry 0 is the anchor A0 = (lo, f0(lo)), never removed.
 *  - xrtp/yrtp: right TPs (input was rising, then fell), x descending.
 *
 * With inputs quantised to Nu distinct values in [lo, hi] (an Nu-code DAC),
 * Nu/2 entries per array can never overflow (HYST_CAPACITY()).
 *
 * Per sample (hyst_step()):
 *  1. an input equal to the previous one changes nothing;
 *  2. a reversal of direction stores the previous point as a new TP;
 *  3. TPs the input reaches or passes are wiped out (Madelung's rule 3); the
 *     surviving current TP is found by binary search, only when a TP is passed;
 *  4. the output is y_k + g(x - x_k) on a rising branch from LTP (x_k, y_k) and
 *     y_k - g(x_k - x) on a falling branch from RTP (x_k, y_k).
 * A sample that moves on along its branch without reaching a stored TP takes
 * a constant fast path: two comparisons against a cached window, one
 * evaluation of g (35 Cortex-M4F instructions for a cubic). A sample that
 * passes TPs costs one binary search more (at most 146 instructions at
 * Nu = 4096; docs/timing.md). hyst_process() runs the samples that stay on
 * their branch in a loop of its own, with bit-identical results.
 *
 * Bounded memory (docs/memory.md). When a reversal at P finds the LTP array
 * full, the innermost stored loop (L1, R1) and P are replaced by ONE LTP V:
 * the point of the next outer branch (the falling one from R2) whose rising
 * branch passes through P. The output is continuous at this sample and the
 * stack stays a valid TCM state, so no jump appears at a later wipe-out
 * either (the former policy, dropping L1 and R1 and storing P, jumped by
 * g(R2-L1) - g(R1-L1) - g(R2-P) + g(R1-P) when the trajectory came back to
 * R2 or through P). The price, m = the miss of V's branch at the forgotten
 * R1, is at most max|f0''| w^2 / 4 (w = input width of the forgotten loop),
 * at most its output height and never more than the former jump;
 * hyst_error_bound() adds up the misses that can still matter. A merge costs
 * at most 54 evaluations of g (6 + 2 per bisection step, at most 24 steps),
 * on the overflowing sample only. V's branches are not the full model's and
 * can leave the major loop (x^3's compensator with capacity 2 gave a drive
 * of 1.07 > hi), so while a merge is alive every sample takes the slow path
 * and its output is clamped to [y_lo, y_hi], the curve's output range; the
 * full model's output lies there, so the clamp never adds error. The fast
 * path returns once the input leaves the merged loops (at the latest at lo
 * or hi).
 *
 * Instances share nothing: several may run side by side (multi-axis stages).
 */
#ifndef HYST_TCM_H
#define HYST_TCM_H

#include "hyst/config.h"
#include "hyst/curve.h"
#include "hyst/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Entries per turning-point array for inputs with @p nu distinct values. */
#define HYST_CAPACITY(nu) ((nu) / 2u)

/**
 * @brief Members shared by every TCM instance type (private).
 *
 * @p xtype is the stored input type: hyst_real_t here, an integer code word
 * in hyst/code.h. One engine source (src/tcm_engine.inc) serves both.
 */
#define HYST_TCM_MEMBERS_(xtype)                                           \
    hyst_curve_t curve;  /**< branch shape and domain */                   \
    xtype *xltp;         /**< LTP inputs, ascending, [0] = lo */           \
    hyst_real_t *yltp;   /**< LTP outputs */                               \
    xtype *xrtp;         /**< RTP inputs, descending */                    \
    hyst_real_t *yrtp;   /**< RTP outputs */                               \
    size_t capacity;     /**< entries of each array */                     \
    size_t n_ltp;        /**< stored LTPs, including A0 (>= 1) */          \
    size_t n_rtp;        /**< stored RTPs; n_ltp > n_rtp <=> rising */     \
    /* Fast-path cache, derived from the arrays after every slow step:     \
     * while the input moves on inside the open interval (window[0],       \
     * window[1]), no TP is created or passed and                          \
     * y = y_ctp + sign g(u_scale (x - x_ctp)). window[moving_end] is the  \
     * last valid input. */                                                \
    xtype window[2];                                                       \
    hyst_real_t x_ctp;   /**< current TP's input, as a real */             \
    hyst_real_t y_ctp;                                                     \
    hyst_real_t sign;    /**< +1 on a rising branch, -1 on a falling one */ \
    hyst_real_t u_scale; /**< sign / (hi - lo) */                          \
    hyst_real_t y_prev;  /**< output for the last valid input */           \
    unsigned moving_end; /**< 0 rising (the lower end follows x), 1 falling */ \
    int status;          /**< hyst_status_t of the last sample */          \
    unsigned events;     /**< sticky HYST_EVENT_* flags */                 \
    /* Bounded memory (docs/memory.md), off the fast path. */              \
    xtype deadband;      /**< reversals narrower than this: not stored */  \
    xtype db_reach;      /**< widest skipped reversal, open window */      \
    hyst_real_t db_err;  /**< error bound of that skipped reversal */      \
    hyst_real_t forgot;  /**< error bound: misses of live merges */        \
    size_t forgot_level; /**< all live while stack depth > this */       \
    unsigned detour      /**< why slow samples leave the plain path (flags) */

/**
 * @brief A TCM instance with real inputs. Fields are private; use the
 *        functions below.
 */
typedef struct hyst {
    HYST_TCM_MEMBERS_(hyst_real_t);
} hyst_t;

/**
 * @brief Declares an instance and its four TP arrays, statically.
 *
 * @code
 * HYST_DEFINE(axis_x, 4096);              // 12-bit DAC: 4 x 2048 entries
 * ...
 * if (HYST_INIT(axis_x, &f0) != HYST_OK) { handle_error(); }
 * @endcode
 * Usable at file scope or in a function (the objects are static).
 */
#define HYST_DEFINE(name, nu)                                          \
    static hyst_real_t name##_xltp[HYST_CAPACITY(nu)];                 \
    static hyst_real_t name##_yltp[HYST_CAPACITY(nu)];                 \
    static hyst_real_t name##_xrtp[HYST_CAPACITY(nu)];                 \
    static hyst_real_t name##_yrtp[HYST_CAPACITY(nu)];                 \
    static hyst_t name

/** hyst_init() on an instance declared by HYST_DEFINE(). */
#define HYST_INIT(name, f0)                                            \
    hyst_init(&(name), (f0), name##_xltp, name##_yltp, name##_xrtp,    \
              name##_yrtp, sizeof(name##_xltp) / sizeof(name##_xltp[0]))

/**
 * @brief Initialises an instance with a polynomial f0 and caller-owned memory.
 *
 * Validates everything once (see hyst_curve_from_poly() for the curve checks)
 * and leaves the instance at A0, as hyst_reset(). On error nothing is written.
 *
 * @param[out] S         instance.
 * @param[in]  f0        major ascending curve, coefficients highest power first.
 * @param[in]  xltp,yltp,xrtp,yrtp  four arrays of @p capacity entries each.
 * @param[in]  capacity  entries per array, >= 2; HYST_CAPACITY(Nu) for Nu codes.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY, or a curve error.
 */
hyst_status_t hyst_init(hyst_t *S, const hyst_poly_t *f0, hyst_real_t *xltp,
                        hyst_real_t *yltp, hyst_real_t *xrtp, hyst_real_t *yrtp,
                        size_t capacity);

/**
 * @brief As hyst_init(), with a curve already prepared (hyst_curve_t).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_CAPACITY or HYST_ERR_ARG (a curve
 *         not prepared by a hyst_curve_* function).
 */
hyst_status_t hyst_init_curve(hyst_t *S, const hyst_curve_t *curve,
                              hyst_real_t *xltp, hyst_real_t *yltp,
                              hyst_real_t *xrtp, hyst_real_t *yrtp,
                              size_t capacity);

/**
 * @brief Forgets all turning points: the trajectory is back at A0 = (lo, f0(lo)).
 *
 * Also clears the sticky events. Call after a power-up of the actuator that
 * starts from zero drive.
 * @param[in,out] S initialised instance.
 */
void hyst_reset(hyst_t *S);

/**
 * @brief Advances the model by one input sample.
 *
 * Bounded time: O(1) unless the sample passes a stored TP, then one binary
 * search, O(log capacity). Never allocates, never writes out of the arrays.
 *  - NaN or infinite @p x: ignored, state untouched, returns the previous
 *    output; status HYST_ERR_NONFINITE.
 *  - @p x outside [lo, hi]: clamped to the domain; status HYST_WARN_CLAMPED.
 *  - a reversal with a full array: the innermost stored loop is merged
 *    away (see "Bounded memory" below); the output stays continuous, at
 *    this sample and later; status HYST_WARN_FULL. Cannot happen when the
 *    inputs take at most 2 * capacity distinct values.
 * The status of the sample is read by hyst_status(); hyst_events() collects
 * the conditions of all samples.
 *
 * @param[in,out] S  initialised instance.
 * @param[in]     x  input sample.
 * @return output y.
 */
hyst_real_t hyst_step(hyst_t *S, hyst_real_t x);

/**
 * @brief Runs hyst_step() over a block of samples.
 * @param[in,out] S  initialised instance.
 * @param[in]     x  @p n inputs.
 * @param[out]    y  @p n outputs (may be the same array as @p x).
 * @param[in]     n  number of samples.
 * @return HYST_ERR_NONFINITE if any sample was not finite, else HYST_WARN_FULL
 *         if any overflow happened, else HYST_WARN_CLAMPED if any input was
 *         clamped, else HYST_OK. HYST_ERR_NULL if a pointer is NULL with n > 0.
 */
hyst_status_t hyst_process(hyst_t *S, const hyst_real_t *x, hyst_real_t *y,
                           size_t n);

/**
 * @brief Sets the noise deadband: a reversal closer than @p width (input
 *        units) to the current turning point is not stored.
 *
 * The input then moves back along the current branch (reversibly) instead of
 * starting a minor loop, so sensor or command noise cannot fill the memory.
 * The full model would run a loop of width d < width inside that branch: the
 * error is at most that loop's height |g(d) - 2 g(d/2)| <= max|f0''| width^2
 * / 4 (for f0'' of one sign; docs/memory.md), is 0 again once the input
 * leaves the window, never accumulates and never jumps. Samples inside the
 * window take the slow path. 0 (the default after init) disables it; kept by
 * hyst_reset().
 * @param[in,out] S      initialised instance.
 * @param[in]     width  deadband in input units, finite, >= 0.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG (negative or not finite).
 */
hyst_status_t hyst_set_deadband(hyst_t *S, hyst_real_t width);

/**
 * @brief Bound on |y - y_full|, y_full being the output of the same model
 *        with unlimited memory and no deadband, for the inputs so far.
 *
 * The sum of the misses of the full-array merges whose outer turning point
 * is still stored, plus the bound of the open deadband excursion; 0 while
 * nothing was forgotten, back to 0 when the trajectory leaves all merged
 * loops (at the latest when it reaches lo or hi).
 * Proven for curves whose f0'' keeps one sign on [lo, hi] (docs/memory.md);
 * arithmetic rounding is not included.
 * @param[in] S initialised instance.
 * @return the bound, in output units.
 */
static inline hyst_real_t hyst_error_bound(const hyst_t *S)
{
    return S->forgot + S->db_err;
}

/** @brief Status of the last sample (hyst_status_t). */
static inline int hyst_status(const hyst_t *S) { return S->status; }

/** @brief Sticky HYST_EVENT_* flags since the last reset or clear. */
static inline unsigned hyst_events(const hyst_t *S) { return S->events; }

/** @brief Clears the sticky event flags. */
static inline void hyst_clear_events(hyst_t *S) { S->events = 0u; }

/** @brief Last output (f0(lo) after init or reset). */
static inline hyst_real_t hyst_output(const hyst_t *S) { return S->y_prev; }

/** @brief Last valid input, after clamping (lo after init or reset). */
static inline hyst_real_t hyst_input(const hyst_t *S) { return S->window[S->moving_end]; }

/** @brief Stored left TPs, excluding the anchor A0. */
static inline size_t hyst_ltp_count(const hyst_t *S) { return S->n_ltp - 1u; }

/** @brief Stored right TPs. */
static inline size_t hyst_rtp_count(const hyst_t *S) { return S->n_rtp; }

/** @brief Stored TPs, excluding the anchor A0 (the paper's TP count). */
static inline size_t hyst_tp_count(const hyst_t *S)
{
    return S->n_ltp - 1u + S->n_rtp;
}

/** @brief 1 if the current branch rises (it leaves an LTP), 0 if it falls. */
static inline int hyst_rising(const hyst_t *S) { return S->n_ltp > S->n_rtp; }

#ifdef __cplusplus
}
#endif

#endif /* HYST_TCM_H */
