/* SPDX-License-Identifier: MIT */
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
 * Per sample (hyst_f32_step() and its siblings):
 *  1. an input equal to the previous one changes nothing;
 *  2. a reversal of direction stores the previous point as a new TP;
 *  3. TPs the input reaches or passes are wiped out (Madelung's rule 3); the
 *     surviving current TP is found by binary search, only when a TP is passed;
 *  4. the output is y_k + g(x - x_k) on a rising branch from LTP (x_k, y_k) and
 *     y_k - g(x_k - x) on a falling branch from RTP (x_k, y_k).
 * A sample that moves on along its branch without reaching a stored TP takes
 * a constant fast path: two comparisons against a cached window, one
 * evaluation of g (35 Cortex-M4F instructions for a cubic). A sample that
 * passes TPs costs one binary search more (at most 147 instructions at
 * Nu = 4096; docs/timing.md). The block call runs the samples that stay on
 * their branch in a loop of its own, with bit-identical results.
 *
 * Bounded memory (docs/memory.md). When a reversal at P finds the LTP array
 * full, the innermost stored loop (L1, R1) and P are replaced by ONE LTP V:
 * the point of the next outer branch (the falling one from R2) whose rising
 * branch passes through P. The output is continuous at this sample and the
 * stack stays a valid TCM state, so no jump appears at a later wipe-out.
 * The price, m = the miss of V's branch at the forgotten R1, is at most
 * max|f0''| w^2 / 4 (w = input width of the forgotten loop) and at most its
 * output height; hyst_*_error_bound() adds up the misses that can still
 * matter. A merge costs at most 54 evaluations of g, on the overflowing
 * sample only. While a merge is alive every sample takes the slow path and
 * its output is clamped to the curve's output range (where the full model's
 * output lies, so the clamp never adds error).
 *
 * Output range: an output lies in the curve's [y_lo, y_hi] (for a
 * compensator: the drive in the model's [lo, hi]) up to the rounding of
 * the turning point's value plus the branch's step: at most 8 units in the
 * last place of the larger of |y_lo|, |y_hi| beyond an end (measured on
 * the asymmetric compensators, desired outputs climbing to within 12 units
 * of their top: 5 % of the float drives above hi, by at most 4 units; 0.4 %
 * in double, by at most 3; tests/test_everett_inverse_table.c; the
 * symmetric tabulated compensator in float: by 1). Clamping each sample
 * would cost the fast path about 4 instructions; a conversion that rounds
 * or truncates to a DAC's codes stays on them (4 units of a drive range
 * near 1 are 2e-3 of a 12-bit code), one that must never exceed its top
 * clamps first.
 *
 * Variants (types.h): hyst_f32_*, hyst_f64_* and hyst_code_* (code.h) share
 * this struct and the functions written once below (counts, status,
 * events, snapshot.h). The unsuffixed names are the default variant.
 *
 * NULL policy (every entry point of the library): a function that returns a
 * status returns HYST_ERR_NULL for a NULL pointer argument and writes
 * nothing; a per-sample function (step) given a NULL instance returns 0;
 * an accessor given NULL returns 0 (or does nothing).
 *
 * Instances share nothing: several may run side by side (multi-axis stages).
 *
 * Concurrency (docs/reliability.md). The usual firmware pattern is
 * supported without masking interrupts: one STEPPING context (a sampling
 * interrupt, or the highest-priority task) calls step/process on an
 * instance, and OTHER contexts that it preempts on the same core (the main
 * loop, lower-priority tasks) may at any time call:
 *  - hyst_snapshot_save(): a consistent copy of one state the model was in
 *    (retried if a step changed the turning points meanwhile; at worst
 *    HYST_ERR_BUSY, never a torn snapshot, never a write past the buffer);
 *  - hyst_request_reset(), hyst_*_request_deadband(),
 *    hyst_request_clear_events(): requests applied by the stepping context
 *    at the end of its next step, once that step's output is computed, as
 *    the immediate calls would be between that sample and the next (a block
 *    call sees a request posted during it at its next slow sample or its
 *    next call); hyst_request_pending();
 *  - every read: hyst_status(), hyst_events(), the counts, hyst_rising(),
 *    hyst_capacity(), hyst_*_output(), hyst_*_input(),
 *    hyst_*_error_bound() (multi-field reads are re-read until consistent).
 * Only the stepping context (or any context while no step can run: before
 * the interrupt is enabled, or with it masked) may call init, step,
 * process, hyst_reset(), hyst_*_set_deadband(), hyst_clear_events() and
 * hyst_snapshot_restore(). Not supported: two contexts stepping one
 * instance, or contexts running at the same time on two cores (use a lock).
 * The cost: one increment per slow sample (none on the fast path).
 */
#ifndef HYST_TCM_H
#define HYST_TCM_H

#include "hyst/curve.h"
#include "hyst/status.h"
#include "hyst/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Entries per turning-point array for inputs with @p nu distinct values. */
#define HYST_CAPACITY(nu) ((nu) / 2u)

/**
 * @brief A TCM instance of any variant. Read it through the functions below;
 *        the fields are documented for debuggers and reviewers.
 *
 * Numbers are hyst_num_t: member f32 in the f32 variant, f64 in the f64
 * variant; in the code variant inputs (window, deadband, db_reach, lo, hi)
 * are member code and outputs member f32. The first two members sit at the
 * same offsets whatever the layout options.
 */
typedef struct hyst_tcm {
    unsigned variant;        /**< hyst_variant_t; 0 before init */
    unsigned long layout;    /**< HYST_LAYOUT of the library that initialised it */
    /* Fast-path cache, derived from the arrays after every slow sample:
     * while the input moves on inside the open interval (window[0],
     * window[1]), no TP is created or passed and
     * y = y_ctp +- G(u_scale (x - x_ctp)) (+ rising, - falling), never
     * behind y_prev. window[moving_end] is the last valid input. */
    hyst_num_t window[2];
    hyst_num_t x_ctp;        /**< current TP's input, as a real */
    hyst_num_t y_ctp;        /**< current TP's output */
    hyst_num_t g_prev;       /**< G at the last slow sample's input (a merge's settling) */
    hyst_num_t u_scale;      /**< unit rising, -unit falling */
    hyst_num_t y_prev;       /**< output for the last valid input */
    unsigned moving_end;     /**< 0 rising (the lower end follows x), 1 falling */
    /** degree of the per-sample Horner path, or a value above every degree
     *  while a request is pending (posted by another context: the per-sample
     *  paths then serve it at no cost of their own) */
    unsigned horner;
    /** degree of the polynomial curve; 0: the curve is evaluated out of line
     *  and every sample is slow */
    unsigned degree;
    hyst_num_t coef[HYST_MAX_DEGREE]; /**< branch shape G, a copy of the curve's */
    /** the asymmetric compensator: a bound on the current branch's |G''| in
     *  its unit argument, for Newton's error bound (tcm_engine.h, solve()) */
    hyst_num_t curv;
    hyst_num_t w_end;  /**< the asymmetric compensator: its branch's end (the parent TP), as w */
    hyst_num_t secant; /**< the same: w per unit of G's argument from the TP to that end */
    /** the pieces of a tabulated inverse (HYST_CURVE_INV_TABLE, evaluated on
     *  the per-sample path with degree 0), else NULL */
    hyst_cptr_t table;
    int status;              /**< hyst_status_t of the last sample */
    unsigned events;         /**< sticky HYST_EVENT_* flags */
    unsigned detour;         /**< why slow samples leave the plain path (flags) */
    /* Turning points. */
    hyst_ptr_t xltp;         /**< LTP inputs, ascending, [0] = lo */
    hyst_ptr_t yltp;         /**< LTP outputs */
    hyst_ptr_t xrtp;         /**< RTP inputs, descending */
    hyst_ptr_t yrtp;         /**< RTP outputs */
    size_t capacity;         /**< entries of each array */
    size_t n_ltp;            /**< stored LTPs, including A0 (>= 1) */
    size_t n_rtp;            /**< stored RTPs; n_ltp > n_rtp <=> rising */
    /* Curve. */
    const hyst_curve_t *curve; /**< the caller's curve (out-of-line kinds, identity) */
    hyst_num_t lo, hi;       /**< domain, in the stored input type */
    hyst_num_t y_lo, y_hi;   /**< curve values at lo and hi */
    hyst_num_t unit;         /**< scale from an input difference to G's argument */
    hyst_num_t rounding;     /**< the curve's rounding bound (curve.h) */
    /* Bounded memory (docs/memory.md), off the fast path. */
    hyst_num_t deadband;     /**< reversals narrower than this: not stored */
    hyst_num_t db_reach;     /**< widest skipped reversal, open window */
    hyst_num_t db_err;       /**< error bound of that skipped reversal */
    hyst_num_t forgot;       /**< error bound: misses of live merges */
    size_t forgot_level;     /**< all live while stack depth > this */
    /* Concurrency ("Concurrency" above). */
    unsigned long seq;       /**< changed by every state change but a fast-path
                              *   sample's; written by the stepping context only */
    unsigned req_reset;      /**< requests: counters incremented by the other context */
    unsigned req_clear;
    unsigned req_deadband;
    hyst_num_t req_width;    /**< deadband width of the last deadband request */
    unsigned done_reset;     /**< the request counters applied, by the stepping context */
    unsigned done_clear;
    unsigned done_deadband;
    /* Last, so that the fields the per-sample paths read keep their
     * offsets (and their short encodings). */
    /** the tabulated asymmetric compensator (HYST_CURVE_EVERETT_INV_TABLE):
     *  the branch's table index per output step, the weights of its four
     *  rows (table: the first), and the interval whose blended cubic coef
     *  holds (-1: none) */
    hyst_num_t v_scale;
    hyst_num_t blend[4];
    unsigned long cached_k;
    /** the same, fixed at init (a slow sample does not convert them): its
     *  table's rows and intervals as reals, and the least whole output step
     *  of a branch that v_scale divides by, 2^-30 intervals of the desired
     *  output range */
    hyst_num_t table_rows, table_intervals, v_least;
    /** TPs stored at the last derive of the tabulated asymmetric
     *  compensator: one more, and the new TP's input becomes the model's
     *  output for its drive */
    size_t tps_derived;
    /** the curve kind's operations, bound by the init that chose the kind
     *  (src/kinds.h); NULL for the kinds the fast path evaluates alone */
    const void *kind;
    /** the kind's slow sample (repeats, reversals, wipe-outs), bound with it */
    void (*slow)(void);
    /** the deadband's skip of a reversal, bound by the calls that can make
     *  a reversal skip (setting or requesting a deadband, a restore): NULL
     *  until then, so a firmware that sets no deadband does not link it */
    void (*skip)(void);
} hyst_tcm_t;

/**
 * @brief Declares an instance and its four TP arrays, statically, for inputs
 *        with @p nu distinct values (HYST_CAPACITY(nu) entries per array).
 *
 * @code
 * HYST_DEFINE(axis_x, 4096);              // 12-bit DAC: 4 x 2048 entries
 * ...
 * if (HYST_INIT(axis_x, &f0) != HYST_OK) { handle_error(); }
 * @endcode
 * Usable at file scope or in a function (the objects are static). The
 * HYST_F32_/HYST_F64_ forms name the variant; the plain form is the default.
 */
#define HYST_F32_DEFINE(name, nu) HYST_DEFINE_ARRAYS_(name, float, float, nu)
#define HYST_F64_DEFINE(name, nu) HYST_DEFINE_ARRAYS_(name, double, double, nu)
#define HYST_DEFINE(name, nu) HYST_DEFINE_ARRAYS_(name, hyst_real_t, hyst_real_t, nu)
/** @cond */
#define HYST_DEFINE_ARRAYS_(name, xtype, ytype, nu)                     \
    static xtype name##_xltp[HYST_CAPACITY(nu)];                        \
    static ytype name##_yltp[HYST_CAPACITY(nu)];                        \
    static xtype name##_xrtp[HYST_CAPACITY(nu)];                        \
    static ytype name##_yrtp[HYST_CAPACITY(nu)];                        \
    static hyst_tcm_t name
#define HYST_ARRAYS_(name)                                              \
    name##_xltp, name##_yltp, name##_xrtp, name##_yrtp,                 \
        sizeof(name##_xltp) / sizeof(name##_xltp[0])
/** @endcond */

/** hyst_*_init() on an instance declared by a DEFINE macro. */
#define HYST_F32_INIT(name, f0) hyst_f32_init_(&(name), (f0), HYST_ARRAYS_(name), HYST_LAYOUT)
#define HYST_F64_INIT(name, f0) hyst_f64_init_(&(name), (f0), HYST_ARRAYS_(name), HYST_LAYOUT)
#define HYST_INIT(name, f0) \
    HYST_DEFAULT_NAME_(init_)(&(name), (f0), HYST_ARRAYS_(name), HYST_LAYOUT)
/** hyst_*_init_sealed() on an instance declared by a DEFINE macro. */
#define HYST_F32_INIT_SEALED(name, sealed) \
    hyst_f32_init_sealed_(&(name), (sealed), HYST_ARRAYS_(name), HYST_LAYOUT)
#define HYST_F64_INIT_SEALED(name, sealed) \
    hyst_f64_init_sealed_(&(name), (sealed), HYST_ARRAYS_(name), HYST_LAYOUT)
#define HYST_INIT_SEALED(name, sealed) \
    HYST_DEFAULT_NAME_(init_sealed_)(&(name), (sealed), HYST_ARRAYS_(name), HYST_LAYOUT)
/** hyst_*_init_curve() on an instance declared by a DEFINE macro. */
#define HYST_INIT_CURVE(name, curve) \
    HYST_DEFAULT_NAME_(init_curve_)(&(name), (curve), HYST_ARRAYS_(name), HYST_LAYOUT)
/** hyst_*_init_kind() on an instance declared by a DEFINE macro. */
#define HYST_INIT_KIND(name, curve, kind) \
    HYST_DEFAULT_NAME_(init_kind_)(&(name), (curve), (kind), HYST_ARRAYS_(name), HYST_LAYOUT)

/**
 * @name Initialisation with a polynomial f0
 * @brief Validates f0 (hyst_f32_curve_from_poly()), the arrays and the
 *        caller's layout once, and leaves the instance at A0, as reset.
 *        On error nothing is written.
 *
 * The instance copies everything a polynomial curve needs: no curve object
 * has to stay alive. Arguments: S (out); f0; xltp, yltp, xrtp, yrtp, four
 * arrays of @p capacity entries each, which must not overlap; capacity >= 2
 * entries per array, HYST_CAPACITY(Nu) for Nu codes.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *         HYST_ERR_OVERLAP, or a curve error.
 */
/**@{*/
hyst_status_t hyst_f32_init_(hyst_tcm_t *S, const hyst_poly_t *f0, float *xltp, float *yltp,
                             float *xrtp, float *yrtp, size_t capacity, unsigned long layout);
#define hyst_f32_init(S, f0, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f32_init_((S), (f0), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_(hyst_tcm_t *S, const hyst_poly_t *f0, double *xltp, double *yltp,
                             double *xrtp, double *yrtp, size_t capacity, unsigned long layout);
#define hyst_f64_init(S, f0, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f64_init_((S), (f0), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Initialisation with a polynomial sealed ahead of time
 * @brief The instance hyst_*_init() makes, from a curve prepared and
 *        checked on the host and sealed (curve.h, hyst_*_seal_poly();
 *        `hyst header --sealed` writes it as a const initializer).
 *
 * Checks what the seal cannot: the arrays and the caller's layout (as
 * hyst_*_init()), the degree, then the seal itself (a CRC-32 over the
 * numbers as stored): integer work only, no curve construction, no double.
 * A curve whose numbers differ from the ones sealed (a damaged flash image,
 * a number edited by hand) is refused with HYST_ERR_CRC. The sealed curve
 * is copied: it need not outlive the instance. On error nothing is written.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT, HYST_ERR_CAPACITY,
 *         HYST_ERR_OVERLAP, HYST_ERR_DEGREE or HYST_ERR_CRC.
 */
/**@{*/
hyst_status_t hyst_f32_init_sealed_(hyst_tcm_t *S, const hyst_f32_sealed_poly_t *sealed,
                                    float *xltp, float *yltp, float *xrtp, float *yrtp,
                                    size_t capacity, unsigned long layout);
#define hyst_f32_init_sealed(S, sealed, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f32_init_sealed_((S), (sealed), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_sealed_(hyst_tcm_t *S, const hyst_f64_sealed_poly_t *sealed,
                                    double *xltp, double *yltp, double *xrtp, double *yrtp,
                                    size_t capacity, unsigned long layout);
#define hyst_f64_init_sealed(S, sealed, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f64_init_sealed_((S), (sealed), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @name Initialisation with a prepared curve
 * @brief As the polynomial init, with a curve of the same variant prepared
 *        by a hyst_*_curve_* constructor. The instance keeps a pointer to
 *        @p curve: it must outlive the instance, unchanged (it may be const).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_LAYOUT (other layout, or a curve
 *         of another variant), HYST_ERR_CAPACITY, HYST_ERR_OVERLAP or
 *         HYST_ERR_ARG (a curve not prepared by a constructor).
 */
/**@{*/
hyst_status_t hyst_f32_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve, float *xltp,
                                   float *yltp, float *xrtp, float *yrtp, size_t capacity,
                                   unsigned long layout);
#define hyst_f32_init_curve(S, curve, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f32_init_curve_((S), (curve), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_curve_(hyst_tcm_t *S, const hyst_curve_t *curve, double *xltp,
                                   double *yltp, double *xrtp, double *yrtp, size_t capacity,
                                   unsigned long layout);
#define hyst_f64_init_curve(S, curve, xltp, yltp, xrtp, yrtp, capacity) \
    hyst_f64_init_curve_((S), (curve), (xltp), (yltp), (xrtp), (yrtp), (capacity), HYST_LAYOUT)
#endif
/**@}*/

/**
 * @brief A curve kind of the engine in one variant, as hyst_*_init_kind()
 *        takes it (hyst_f32_kind_everett, ...). The init calls it: it
 *        returns the kind's operations for a curve of its kind and an
 *        instance of its variant, NULL for any other curve or variant.
 */
typedef const void *(*hyst_kind_t)(const hyst_curve_t *curve, unsigned variant);

/**
 * @name Initialisation with a prepared curve of a kind the firmware names
 * @brief As hyst_*_init_curve(), with the curve's kind named by the caller:
 *        the instance runs that kind's code, and a firmware that names its
 *        kinds links no other (hyst_*_init_curve() binds whatever kind the
 *        curve has, so it links them all). The kinds and their curves:
 *
 * | kind | curves (constructor) |
 * |---|---|
 * | hyst_*_kind_poly | f0 (hyst_*_curve_from_poly(), hyst_curve_inverse() of an inverted f0) |
 * | hyst_*_kind_pwl | piecewise linear and its inverse (hyst_*_curve_from_pwl(), hyst_curve_inverse()) |
 * | hyst_*_kind_inverse | f0 inverted, the exact compensator (hyst_curve_inverse() of f0) |
 * | hyst_*_kind_inverse_table | tabulated inverse of f0 (hyst_*_curve_inverse_table(), _const()) |
 * | hyst_*_kind_everett | E (hyst_*_curve_from_everett(), hyst_curve_inverse() of its inverse) |
 * | hyst_*_kind_everett_inverse | E's solved inverse (hyst_curve_inverse()) |
 * | hyst_*_kind_everett_inverse_table | E's tabulated inverse (hyst_*_curve_everett_inverse_table(), _const()) |
 * | hyst_*_kind_everett_grid | E on a grid (hyst_*_curve_from_everett_grid()) |
 * | hyst_*_kind_everett_grid_inverse | its inverse (hyst_*_curve_everett_grid_inverse()) |
 * | hyst_*_kind_spline | a spline f0 and its solved inverse (hyst_*_curve_from_spline(), hyst_curve_spline_inverse()) |
 * | hyst_*_kind_spline_inverse_table | its tabulated inverse (hyst_*_curve_spline_inverse_table()) |
 *
 * @return as hyst_*_init_curve(), or HYST_ERR_NULL (@p kind NULL) or
 *         HYST_ERR_CURVE (a curve of another kind, or a kind of another
 *         variant); on error nothing is written.
 */
/**@{*/
hyst_status_t hyst_f32_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                  float *xltp, float *yltp, float *xrtp, float *yrtp,
                                  size_t capacity, unsigned long layout);
#define hyst_f32_init_kind(S, curve, kind, xltp, yltp, xrtp, yrtp, capacity)                   \
    hyst_f32_init_kind_((S), (curve), (kind), (xltp), (yltp), (xrtp), (yrtp), (capacity),      \
                        HYST_LAYOUT)
const void *hyst_f32_kind_poly(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_pwl(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_everett(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_everett_grid(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_spline(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f32_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_init_kind_(hyst_tcm_t *S, const hyst_curve_t *curve, hyst_kind_t kind,
                                  double *xltp, double *yltp, double *xrtp, double *yrtp,
                                  size_t capacity, unsigned long layout);
#define hyst_f64_init_kind(S, curve, kind, xltp, yltp, xrtp, yrtp, capacity)                   \
    hyst_f64_init_kind_((S), (curve), (kind), (xltp), (yltp), (xrtp), (yrtp), (capacity),      \
                        HYST_LAYOUT)
const void *hyst_f64_kind_poly(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_pwl(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_everett(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_everett_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_everett_inverse_table(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_everett_grid(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_everett_grid_inverse(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_spline(const hyst_curve_t *curve, unsigned variant);
const void *hyst_f64_kind_spline_inverse_table(const hyst_curve_t *curve, unsigned variant);
#endif
/**@}*/

/**
 * @name Per sample
 * @brief Advances the model by one input sample; returns the output.
 *
 * Bounded time: O(1) unless the sample passes a stored TP, then one binary
 * search, O(log capacity). Never allocates, never writes out of the arrays.
 *  - NaN or infinite @p x: ignored, state untouched, returns the previous
 *    output; status HYST_ERR_NONFINITE.
 *  - @p x outside [lo, hi]: clamped to the domain; status HYST_WARN_CLAMPED.
 *  - a reversal with a full array: the innermost stored loop is merged
 *    away (see "Bounded memory" above); the output stays continuous, at
 *    this sample and later; status HYST_WARN_FULL. Cannot happen when the
 *    inputs take at most 2 * capacity distinct values.
 * The status of the sample is read by hyst_status(); hyst_events() collects
 * the conditions of all samples.
 */
/**@{*/
float hyst_f32_step(hyst_tcm_t *S, float x);
#if HYST_ENABLE_F64
double hyst_f64_step(hyst_tcm_t *S, double x);
#endif
/**@}*/

/**
 * @name Block of samples
 * @brief The per-sample call over @p n samples, bit-identical to it.
 *
 * @p y may be the same array as @p x; any other overlap is refused.
 * @return HYST_ERR_NONFINITE if any sample was not finite, else HYST_WARN_FULL
 *         if any overflow happened, else HYST_WARN_CLAMPED if any input was
 *         clamped, else HYST_OK. HYST_ERR_NULL if a pointer is NULL with n > 0;
 *         HYST_ERR_OVERLAP if @p y overlaps @p x other than exactly in place
 *         (nothing written, the instance unchanged).
 */
/**@{*/
hyst_status_t hyst_f32_process(hyst_tcm_t *S, const float *x, float *y, size_t n);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_process(hyst_tcm_t *S, const double *x, double *y, size_t n);
#endif
/**@}*/

/**
 * @name Deadband
 * @brief Sets the noise deadband: a reversal closer than @p width (input
 *        units) to the current turning point is not stored.
 *
 * The input then moves back along the current branch (reversibly) instead of
 * starting a minor loop, so sensor or command noise cannot fill the memory.
 * The error is at most that loop's height |g(d) - 2 g(d/2)| <= max|f0''|
 * width^2 / 4 where f0'' has one sign, otherwise a bound on the relay
 * density over the window (docs/memory.md); it is stated in
 * hyst_*_error_bound(), is 0 again once the input leaves the window, never
 * accumulates and never jumps. 0 (the default
 * after init) disables it; kept by reset.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG (negative or not finite, or
 *         an instance of another variant).
 */
/**@{*/
hyst_status_t hyst_f32_set_deadband(hyst_tcm_t *S, float width);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_set_deadband(hyst_tcm_t *S, double width);
#endif
/**@}*/

/**
 * @name Last sample and error bound, in the variant's type
 * @brief Output and input (after clamping) of the last valid sample
 *        (f0(lo) and lo after init or reset); bound on |y - y_full|, y_full
 *        being the output of the same model with unlimited memory and no
 *        deadband: the sum of the misses of the full-array merges whose
 *        outer turning point is still stored, plus the bound of the open
 *        deadband excursion (docs/memory.md; rounding not included).
 *        rounding_bound: the bound the curve's kind states on the rounding
 *        error of one branch evaluation in the variant's type (curve.h,
 *        each constructor's "rounding"; a polynomial's at most
 *        HYST_MAX_ROUNDING of the output range, checked at init); an output
 *        after d stored turning points differs from exact arithmetic on the
 *        same inputs by at most (d + 1) times it. 0 for a kind that states
 *        none.
 */
/**@{*/
float hyst_f32_output(const hyst_tcm_t *S);
float hyst_f32_input(const hyst_tcm_t *S);
float hyst_f32_error_bound(const hyst_tcm_t *S);
float hyst_f32_rounding_bound(const hyst_tcm_t *S);
#if HYST_ENABLE_F64
double hyst_f64_output(const hyst_tcm_t *S);
double hyst_f64_input(const hyst_tcm_t *S);
double hyst_f64_error_bound(const hyst_tcm_t *S);
double hyst_f64_rounding_bound(const hyst_tcm_t *S);
#endif
/**@}*/

/**
 * @brief Forgets all turning points: the trajectory is back at A0 = (lo, f0(lo)).
 *
 * Also clears the sticky events and the error bound; keeps the deadband.
 * Call after a power-up of the actuator that starts from zero drive. Every
 * variant. NULL or an uninitialised instance: nothing happens.
 */
void hyst_reset(hyst_tcm_t *S);

/**
 * @name Requests from another context (see "Concurrency" above)
 * @brief Safe while the stepping context may preempt the caller: the
 *        request is recorded now and applied by the stepping context at the
 *        end of its next step, after that step's output (the next output is
 *        the first to see it). Posting one again before it is applied
 *        applies it once (a deadband request: the last width).
 * @return HYST_OK, HYST_ERR_NULL, or HYST_ERR_ARG (an uninitialised
 *         instance; a deadband as hyst_*_set_deadband() refuses it).
 */
/**@{*/
hyst_status_t hyst_request_reset(hyst_tcm_t *S);
hyst_status_t hyst_request_clear_events(hyst_tcm_t *S);
hyst_status_t hyst_f32_request_deadband(hyst_tcm_t *S, float width);
#if HYST_ENABLE_F64
hyst_status_t hyst_f64_request_deadband(hyst_tcm_t *S, double width);
#endif
/**@}*/

/** @brief 1 while a posted request has not been applied yet; 0 after (and for NULL). */
int hyst_request_pending(const hyst_tcm_t *S);

/** @brief Status of the last sample (hyst_status_t); NULL: HYST_ERR_NULL. */
int hyst_status(const hyst_tcm_t *S);

/** @brief Sticky HYST_EVENT_* flags since the last reset or clear. */
unsigned hyst_events(const hyst_tcm_t *S);

/** @brief Clears the sticky event flags. */
void hyst_clear_events(hyst_tcm_t *S);

/** @brief Stored left TPs, excluding the anchor A0. */
size_t hyst_ltp_count(const hyst_tcm_t *S);

/** @brief Stored right TPs. */
size_t hyst_rtp_count(const hyst_tcm_t *S);

/** @brief Stored TPs, excluding the anchor A0 (the paper's TP count). */
size_t hyst_tp_count(const hyst_tcm_t *S);

/** @brief 1 if the current branch rises (it leaves an LTP), 0 if it falls. */
int hyst_rising(const hyst_tcm_t *S);

/** @brief Entries of each TP array. */
size_t hyst_capacity(const hyst_tcm_t *S);

/** @name Default variant (f32, or f64 with HYST_USE_DOUBLE) */
/**@{*/
typedef hyst_tcm_t hyst_t; /**< an instance (the struct is the same for every variant) */
#define hyst_init HYST_DEFAULT_NAME_(init)
#define hyst_init_curve HYST_DEFAULT_NAME_(init_curve)
#define hyst_init_kind HYST_DEFAULT_NAME_(init_kind)
#define hyst_kind_poly HYST_DEFAULT_NAME_(kind_poly)
#define hyst_kind_pwl HYST_DEFAULT_NAME_(kind_pwl)
#define hyst_kind_inverse HYST_DEFAULT_NAME_(kind_inverse)
#define hyst_kind_inverse_table HYST_DEFAULT_NAME_(kind_inverse_table)
#define hyst_kind_everett HYST_DEFAULT_NAME_(kind_everett)
#define hyst_kind_everett_inverse HYST_DEFAULT_NAME_(kind_everett_inverse)
#define hyst_kind_everett_inverse_table HYST_DEFAULT_NAME_(kind_everett_inverse_table)
#define hyst_kind_everett_grid HYST_DEFAULT_NAME_(kind_everett_grid)
#define hyst_kind_everett_grid_inverse HYST_DEFAULT_NAME_(kind_everett_grid_inverse)
#define hyst_kind_spline HYST_DEFAULT_NAME_(kind_spline)
#define hyst_kind_spline_inverse_table HYST_DEFAULT_NAME_(kind_spline_inverse_table)
#define hyst_init_sealed HYST_DEFAULT_NAME_(init_sealed)
#define hyst_step HYST_DEFAULT_NAME_(step)
#define hyst_process HYST_DEFAULT_NAME_(process)
#define hyst_set_deadband HYST_DEFAULT_NAME_(set_deadband)
#define hyst_request_deadband HYST_DEFAULT_NAME_(request_deadband)
#define hyst_output HYST_DEFAULT_NAME_(output)
#define hyst_input HYST_DEFAULT_NAME_(input)
#define hyst_error_bound HYST_DEFAULT_NAME_(error_bound)
#define hyst_rounding_bound HYST_DEFAULT_NAME_(rounding_bound)
/**@}*/

#ifdef __cplusplus
}
#endif

#endif /* HYST_TCM_H */
