/* SPDX-License-Identifier: MIT */
/**
 * @file ident.h
 * @brief Identification of the major ascending curve f0 from measured data.
 *
 * Excite the actuator with a full-range periodic wave between lo and hi,
 * record input x and output y, and fit f0 as a polynomial of degree n by
 * least squares (docs/identification.md). Two estimators:
 *
 *  - HYST_IDENT_JOINT (default): rising samples obey y = f0(x), falling
 *    samples y = f0(lo) + f0(hi) - f0(lo + hi - x); both are linear in the
 *    coefficients, so all samples enter one least-squares problem and no
 *    output at the extremes has to be estimated.
 *  - HYST_IDENT_REFLECT (the paper's procedure): falling samples are mapped
 *    onto f0 by the point reflection of Eq. 14, x' = lo + hi - x,
 *    y' = y(lo) + y(hi) - y, with y(lo), y(hi) the mean outputs of the samples
 *    at the extreme inputs seen; then one polynomial fit. The domain should
 *    then be the inputs' range (the reflection uses lo + hi).
 *
 * A sample is rising or falling by its direction of travel: the sign of
 * x - (previous different input); a repeated input keeps the previous
 * direction; samples before the input first moves have no direction and are
 * not used.
 *
 * Streaming and allocation-free: the instance (hyst_ident_t: 872 bytes with
 * hyst_wide_t = double on a 64-bit host, 472 with HYST_NO_DOUBLE) is the whole
 * workspace, whatever the number of samples.
 * Each sample updates a triangular factor by Givens rotations (an orthogonal
 * factorisation, never the normal equations), in hyst_wide_t, on the input
 * scaled to t in [-1, 1] over the domain and a Chebyshev basis in t, so raw
 * units (volts 0..40, DAC codes 0..65535) are fine up to HYST_MAX_DEGREE; with
 * HYST_NO_DOUBLE while the powers of the domain's ends stay within float's
 * range (65535^9 does not: the curve then refuses the f0 fitted).
 * Coefficients come back in the user's units, highest power first.
 *
 * Firmware (domain known, samples streamed, no buffer):
 * @code
 * hyst_ident_t id;
 * hyst_ident_result_t res;
 * hyst_ident_config_t cfg = { 3u, HYST_IDENT_JOINT, 0.0, 4095.0 };
 * hyst_ident_init(&id, &cfg);
 * for (...) { hyst_ident_add(&id, code, measured); }   // pass 1: fit
 * hyst_ident_solve(&id, &res);
 * for (...) { hyst_ident_check(&id, code, measured); } // pass 2 (optional): residuals
 * hyst_ident_residuals(&id, &res);
 * @endcode
 * Host, data in arrays: hyst_ident_fit() does it all, with skip, sensor
 * delay and the domain taken from the data.
 *
 * Also here, to compare with the TCM on the same record: the weights of a
 * Prandtl-Ishlinskii model (include/hyst/pi.h) by non-negative least
 * squares, hyst_pi_fit_*() below, in a caller workspace of
 * HYST_PI_FIT_WORK(N) entries.
 */
#ifndef HYST_IDENT_H
#define HYST_IDENT_H

#include "hyst/curve.h"
#include "hyst/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @brief Estimator of f0 (hyst_ident_config_t::method). */
typedef enum hyst_ident_method {
    HYST_IDENT_DEFAULT = 0, /**< HYST_IDENT_JOINT */
    HYST_IDENT_JOINT = 1,   /**< both branches in one least-squares problem */
    HYST_IDENT_REFLECT = 2  /**< the paper: falling samples reflected by Eq. 14 */
} hyst_ident_method_t;

/** Columns of the triangular factor: n + 1 coefficients and two right-hand sides. */
#define HYST_IDENT_COLS (HYST_MAX_DEGREE + 3)

/**
 * @brief What to fit. Zero fields take their defaults where stated.
 */
typedef struct hyst_ident_config {
    unsigned degree;  /**< n, 1..HYST_MAX_DEGREE */
    int method;       /**< hyst_ident_method_t; 0 = HYST_IDENT_JOINT */
    hyst_wide_t lo;   /**< domain; hyst_ident_fit(): lo == hi takes it from the data */
    hyst_wide_t hi;   /**< upper end of the domain */
    size_t skip;      /**< hyst_ident_fit() only: samples dropped at the start (settling) */
    size_t delay;     /**< hyst_ident_fit() only: output lags the input by this many samples */
} hyst_ident_config_t;

/** @brief Direction-of-travel classifier (private to hyst_ident_t). */
typedef struct hyst_ident_dir {
    hyst_wide_t x_prev; /**< previous input */
    int started;        /**< a previous input exists */
    int dir;            /**< +1 rising, -1 falling, 0 not moved yet */
} hyst_ident_dir_t;

/**
 * @brief An identification in progress. Fields are private.
 *
 * Holds its own workspace: the packed upper-triangular factor of
 * HYST_IDENT_COLS columns. Copyable; instances share nothing.
 */
typedef struct hyst_ident {
    unsigned degree;      /**< n */
    int method;           /**< hyst_ident_method_t, resolved */
    int phase;            /**< 0 fitting, 1 solved (checking) */
    hyst_wide_t lo, hi;   /**< domain */
    hyst_wide_t mid;      /**< (lo + hi) / 2 */
    hyst_wide_t inv_half; /**< 2 / (hi - lo) */
    /** R factor, rows packed: row i holds columns i..HYST_IDENT_COLS-1 */
    hyst_wide_t r[HYST_IDENT_COLS * (HYST_IDENT_COLS + 1) / 2];
    hyst_ident_dir_t dir; /**< classifier of the current pass */
    hyst_wide_t x_min, x_max;   /**< extreme inputs seen */
    hyst_wide_t sy_min, sy_max; /**< sums of the outputs at those inputs */
    size_t n_min, n_max;        /**< samples at those inputs */
    size_t rising, falling;     /**< samples used, by branch */
    size_t ignored;             /**< non-finite, out of domain or before the first move */
    /** solution as a curve runs it: f0(lo + u (hi - lo)) = sum unit_poly[k] u^k */
    hyst_wide_t unit_poly[HYST_MAX_DEGREE + 1];
    hyst_wide_t y_top;          /**< f0(hi) of the solution */
    hyst_wide_t ss, max_abs;    /**< check pass: squared sum, max |residual| */
    size_t checked;             /**< check pass: samples compared */
} hyst_ident_t;

/**
 * @brief An identified f0 and how well it fits.
 */
typedef struct hyst_ident_result {
    unsigned degree;  /**< n */
    int method;       /**< estimator used (resolved, never 0) */
    hyst_wide_t coeffs[HYST_MAX_DEGREE + 1]; /**< c_n ... c_0, user units, highest power first */
    hyst_wide_t lo, hi;  /**< domain */
    /** RMS of the residual y - (major loop): rising samples against f0(x),
     *  falling ones against f0(lo) + f0(hi) - f0(lo + hi - x). After
     *  hyst_ident_solve() alone: the least-squares residual of the fit
     *  (REFLECT: in the reflected coordinates). */
    hyst_wide_t rms;
    hyst_wide_t max_abs; /**< max |residual|; negative until a check pass */
    hyst_wide_t y_lo_est, y_hi_est; /**< REFLECT: y(lo), y(hi) used by Eq. 14; else f0(lo), f0(hi) */
    size_t used;         /**< samples in the fit */
    size_t rising;       /**< of which rising */
    size_t falling;      /**< of which falling */
    int increasing;      /**< 1 if f0 increases on [lo, hi] (hyst_poly_is_increasing()) */
    hyst_wide_t turn;    /**< if not increasing: an x where the slope is negative */
} hyst_ident_result_t;

/**
 * @brief Starts an identification on a known domain.
 * @param[out] id  instance (the whole workspace).
 * @param[in]  cfg degree, method, lo < hi (skip and delay are not used here).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE, HYST_ERR_DOMAIN or
 *         HYST_ERR_ARG (unknown method). Nothing is written on error.
 */
hyst_status_t hyst_ident_init_(hyst_ident_t *id, const hyst_ident_config_t *cfg,
                               unsigned long layout);
#define hyst_ident_init(id, cfg) hyst_ident_init_((id), (cfg), HYST_LAYOUT)

/**
 * @brief Adds one sample (x, y) to the fit. Constant time and memory.
 * @param[in,out] id initialised instance, not yet solved.
 * @param[in]     x  input.
 * @param[in]     y  output measured for @p x (already delay-aligned).
 * @return HYST_OK when used; HYST_ERR_NONFINITE (NaN/Inf) or HYST_ERR_DOMAIN
 *         (x outside [lo, hi]) when ignored; HYST_ERR_ARG after
 *         hyst_ident_solve(). A sample before the input first moves
 *         returns HYST_OK but is not used (it has no direction). A sample
 *         whose output alone is missing (y NaN, x in the domain) is not
 *         used but its input still sets the direction of the next.
 */
hyst_status_t hyst_ident_add(hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief The identification of a lower degree on the samples added so far.
 *
 * Fitting every degree up to n on one record costs one pass at degree n:
 * @p lower becomes what an instance of @p degree holds once fed the same
 * samples (its columns are a prefix of @p id's, rotated alike: its solution
 * is the same bit for bit, its least-squares RMS the same up to rounding),
 * ready for more samples or hyst_ident_solve(). @p id is not changed;
 * @p lower may be @p id.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_ARG (@p id already solved);
 *         HYST_ERR_DEGREE (@p degree 0 or above @p id's). Nothing is
 *         written on error.
 */
hyst_status_t hyst_ident_lower_degree(const hyst_ident_t *id, unsigned degree,
                                      hyst_ident_t *lower);

/**
 * @brief Solves the least-squares problem of the samples added so far.
 *
 * Fills @p res (coefficients in user units, highest power first; domain;
 * least-squares RMS; the monotonicity check) and switches @p id to the
 * check pass: further samples go to hyst_ident_check().
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_ARG (already solved);
 *         HYST_ERR_SINGULAR (too few distinct inputs for degree n);
 *         HYST_ERR_ILL_CONDITIONED (the coefficients in user units cannot
 *         hold the fit: a domain far from 0 relative to its span, where the
 *         expanded coefficients cancel by more than a curve accepts,
 *         HYST_MAX_ROUNDING of the output range; @p res not written).
 *         A fit that does not increase is still HYST_OK: see res->increasing.
 *         The check pass compares with those coefficients as a curve runs them.
 */
hyst_status_t hyst_ident_solve(hyst_ident_t *id, hyst_ident_result_t *res);

/**
 * @brief Check pass: compares one sample with the fitted major loop.
 *
 * Feed the same samples again (classified afresh); then
 * hyst_ident_residuals() gives their RMS and maximum.
 * @return HYST_OK, HYST_ERR_ARG (not solved), or the codes of hyst_ident_add().
 */
hyst_status_t hyst_ident_check(hyst_ident_t *id, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief Writes the check pass's RMS and max residual into @p res.
 * @return HYST_OK, HYST_ERR_NULL or HYST_ERR_ARG (no sample checked).
 */
hyst_status_t hyst_ident_residuals(const hyst_ident_t *id, hyst_ident_result_t *res);

/**
 * @brief Smallest and largest finite entry of an array (the domain of a record).
 * @return HYST_OK, HYST_ERR_NULL, or HYST_ERR_DOMAIN (no finite entry, or all equal).
 */
hyst_status_t hyst_ident_domain(const hyst_wide_t *x, size_t n, hyst_wide_t *lo,
                                hyst_wide_t *hi);

/**
 * @brief Identifies f0 from recorded arrays, in two passes over them.
 *
 * Sample i (skip <= i < n - delay) pairs x[i] with y[i + delay]. The domain
 * is cfg->lo..cfg->hi, or the range of those x when cfg->lo == cfg->hi.
 * Pass 1 fits, pass 2 computes the residuals (res->rms, res->max_abs).
 * @param[in]  cfg  degree, method, domain, skip, delay.
 * @param[in]  x, y @p n samples each.
 * @param[out] work workspace (any content).
 * @param[out] res  result.
 * @return as hyst_ident_init() and hyst_ident_solve(); HYST_ERR_ARG when
 *         skip + delay leaves no sample.
 */
hyst_status_t hyst_ident_fit_(const hyst_ident_config_t *cfg, const hyst_wide_t *x,
                              const hyst_wide_t *y, size_t n, hyst_ident_t *work,
                              hyst_ident_result_t *res, unsigned long layout);
#define hyst_ident_fit(cfg, x, y, n, work, res) \
    hyst_ident_fit_((cfg), (x), (y), (n), (work), (res), HYST_LAYOUT)

/**
 * @brief The identified curve as a hyst_poly_t for hyst_init().
 * @return HYST_OK, HYST_ERR_NULL, or HYST_ERR_COEFF (a coefficient does not
 *         fit hyst_real_t).
 */
hyst_status_t hyst_ident_poly(const hyst_ident_result_t *res, hyst_poly_t *f0);

/* ---- Prandtl-Ishlinskii weights by non-negative least squares ---- */

/** Most play operators hyst_pi_fit_init() accepts. */
#define HYST_PI_FIT_MAX_OPERATORS 64u

/**
 * hyst_wide_t entries of the workspace of a PI fit with @p n operators:
 * thresholds, operator states, the centred normal equations (n x n) and the
 * active-set solver's factor and vectors. O(n^2), whatever the record length:
 * @code
 * static hyst_wide_t work[HYST_PI_FIT_WORK(10)];
 * @endcode
 */
#define HYST_PI_FIT_WORK(n) (2u * (size_t)(n) * (size_t)(n) + 9u * (size_t)(n) + 5u)

/**
 * @brief A PI fit in progress. Fields are private; the numbers live in the
 *        caller's workspace.
 */
typedef struct hyst_pi_fit {
    size_t n;          /**< operators */
    size_t used;       /**< samples in the normal equations */
    size_t ignored;    /**< non-finite samples */
    int phase;         /**< 0 adding, 1 solved */
    hyst_wide_t *work; /**< HYST_PI_FIT_WORK(n) entries of the caller */
} hyst_pi_fit_t;

/**
 * @brief A fitted PI model: y = offset + w_1 z_1 + ... + w_N z_N, the z_i
 *        the play operators of include/hyst/pi.h run from the reset state.
 *        The weights are the caller's array (hyst_pi_fit_solve()).
 */
typedef struct hyst_pi_fit_result {
    size_t operators;   /**< N */
    hyst_wide_t offset; /**< output offset (hyst_pi_t has none: add it to its output) */
    /** RMS of y - model over the samples used: after hyst_pi_fit_solve() from
     *  the normal equations; after hyst_pi_fit_record() from a second pass. */
    hyst_wide_t rms;
    hyst_wide_t max_abs; /**< max |y - model|; negative until a second pass */
    size_t used;         /**< samples in the fit */
    size_t positive;     /**< weights above 0 (the others are exactly 0) */
    /** 1 if w_1 > 0: every partial sum is then positive, so hyst_pi_init()
     *  accepts the weights and the model has an inverse. */
    int invertible;
} hyst_pi_fit_result_t;

/**
 * @brief What hyst_pi_fit_record() fits.
 */
typedef struct hyst_pi_fit_config {
    size_t operators; /**< N, 1..HYST_PI_FIT_MAX_OPERATORS */
    /** N thresholds (r_1 = 0, strictly increasing), or NULL: uniform over the
     *  inputs' range, hyst_pi_fit_thresholds(). */
    const hyst_wide_t *thresholds;
    size_t skip;  /**< samples dropped at the start (settling) */
    size_t delay; /**< output lags the input by this many samples */
} hyst_pi_fit_config_t;

/**
 * @brief Uniform thresholds r_i = (i - 1) (hi - lo) / N, i = 1..N, for an
 *        input moving over [lo, hi].
 *
 * A one-sided play operator's loop is as wide as its threshold: one with
 * r >= hi - lo never turns inside the range, so the thresholds cover
 * [0, hi - lo) evenly.
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (N outside
 *         1..HYST_PI_FIT_MAX_OPERATORS) or HYST_ERR_DOMAIN (lo, hi not
 *         finite or lo >= hi).
 */
hyst_status_t hyst_pi_fit_thresholds(hyst_wide_t lo, hyst_wide_t hi, size_t n, hyst_wide_t *r);

/**
 * @brief Starts a PI fit with @p n operators of thresholds @p r (copied).
 * @param[out] fit      instance.
 * @param[in]  r        n thresholds: r_1 = 0, finite, strictly increasing.
 * @param[in]  n        1..HYST_PI_FIT_MAX_OPERATORS.
 * @param[in]  work     workspace of @p work_len entries (any content).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_ARG (n), HYST_ERR_NOSPACE
 *         (work_len < HYST_PI_FIT_WORK(n)), HYST_ERR_BREAKPOINTS.
 */
hyst_status_t hyst_pi_fit_init(hyst_pi_fit_t *fit, const hyst_wide_t *r, size_t n,
                               hyst_wide_t *work, size_t work_len);

/**
 * @brief Runs the operators over input @p x and adds (z(x), y) to the
 *        normal equations. O(N^2) time, no memory.
 * @return HYST_OK; HYST_ERR_NONFINITE (x or y NaN/Inf: not used; a finite x
 *         still moves the operators, as hyst_pi_step() would); HYST_ERR_ARG
 *         after hyst_pi_fit_solve(); HYST_ERR_NULL.
 */
hyst_status_t hyst_pi_fit_add(hyst_pi_fit_t *fit, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief Solves min ||y - offset - sum w_i z_i|| subject to w_i >= 0 (offset
 *        free) by the Lawson-Hanson active-set method on the normal
 *        equations, centred so that the offset drops out of them.
 * @param[out] w   N weights; every one >= 0.
 * @param[out] res offset, RMS, counts.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_ARG (solved already);
 *         HYST_ERR_SINGULAR (fewer than N + 1 samples); HYST_ERR_DOMAIN
 *         (the input never moved: every operator output is constant).
 */
hyst_status_t hyst_pi_fit_solve(hyst_pi_fit_t *fit, hyst_wide_t *w, hyst_pi_fit_result_t *res);

/**
 * @brief Fits a PI model to recorded arrays: sample i (skip <= i < n -
 *        delay) pairs x[i] with y[i + delay]. Thresholds as given in @p cfg,
 *        or uniform over the range of those x. One pass to fit, a second
 *        one (the model run again from reset) for res->rms and res->max_abs.
 * @param[out] r, w N thresholds and N weights.
 * @return as hyst_pi_fit_init() and hyst_pi_fit_solve(); HYST_ERR_ARG when
 *         skip + delay leaves no sample; HYST_ERR_NONFINITE if a sample used
 *         is NaN or infinite (nothing fitted); HYST_ERR_DOMAIN if the inputs
 *         are all equal.
 */
hyst_status_t hyst_pi_fit_record(const hyst_pi_fit_config_t *cfg, const hyst_wide_t *x,
                                 const hyst_wide_t *y, size_t n, hyst_wide_t *work,
                                 size_t work_len, hyst_wide_t *r, hyst_wide_t *w,
                                 hyst_pi_fit_result_t *res);

/* ---- The asymmetric kind's E by linear least squares ---- */

/** Columns of an E fit: the output at lo, then E's coefficients. */
#define HYST_EVERETT_FIT_COLS (HYST_EVERETT_TERMS + 1u)

/**
 * hyst_wide_t entries of the workspace of an E fit whose input record
 * stacks at most @p capacity turning points (HYST_CAPACITY(Nu) for Nu
 * distinct inputs): each one's input and its regressors.
 */
#define HYST_EVERETT_FIT_WORK(capacity) ((size_t)(capacity) * (HYST_EVERETT_FIT_COLS + 1u))

/** Numbers of an E fit's packed triangular factor: its columns and y. */
#define HYST_EVERETT_FIT_R ((HYST_EVERETT_FIT_COLS + 1u) * (HYST_EVERETT_FIT_COLS + 2u) / 2u)

/**
 * @brief An E fit in progress (hyst_everett_fit_init()). Fields are
 *        private. The model's output is y_lo plus a signed sum of E over
 *        the pairs of stacked turning points (docs/theory.md, "Linear in
 *        E"): linear in E's coefficients, so each sample adds one row of
 *        regressors, kept per turning point like the outputs the model keeps.
 */
typedef struct hyst_everett_fit {
    unsigned degree;   /**< total degree of E */
    unsigned t_degree; /**< highest power of the lower end t fitted (<= degree - 1) */
    size_t cols;       /**< 1 + E's coefficients fitted */
    hyst_wide_t lo, hi; /**< domain */
    hyst_wide_t *tp_x; /**< caller's workspace: TP inputs (capacity) */
    hyst_wide_t *tp_r; /**< and their regressors (capacity x cols) */
    size_t capacity;   /**< TPs the workspace holds (A0 included) */
    size_t n_tp;       /**< stacked, A0 included */
    hyst_wide_t x_prev; /**< last input */
    hyst_wide_t r_prev[HYST_EVERETT_FIT_COLS];  /**< its regressors */
    /** the least squares' factor of [regressors, y - y_ref], rotated in row
     *  by row (square-root-free Givens): D on the diagonal, the unit
     *  upper-triangular U above it, packed by rows */
    hyst_wide_t r[HYST_EVERETT_FIT_R];
    hyst_wide_t y_ref; /**< the first output: the factor takes y - y_ref */
    size_t used;       /**< samples rotated in */
} hyst_everett_fit_t;

/**
 * @brief Starts an E fit of total degree @p degree on [lo, hi], the input
 *        record starting at lo (as an instance after reset).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE (1..HYST_EVERETT_MAX_DEGREE),
 *         HYST_ERR_DOMAIN, HYST_ERR_NOSPACE (work_len below
 *         HYST_EVERETT_FIT_WORK(2)).
 */
hyst_status_t hyst_everett_fit_init(hyst_everett_fit_t *fit, unsigned degree, hyst_wide_t lo,
                                    hyst_wide_t hi, hyst_wide_t *work, size_t work_len);

/**
 * @brief The same, fitting only the terms w^i t^j with j <= @p t_degree
 *        (the others 0): E of degree @p degree in the width, of degree
 *        @p t_degree in the lower end.
 *
 * A record of major loops alone sees E on two edges of its triangle only
 * (rising from lo: t = 0; falling from hi: w + t = 1), where every multiple
 * of w t (1 - w - t) vanishes: from degree 3 on, E of full total degree is
 * not determined by such a record (hyst_everett_fit_solve(): HYST_ERR_SINGULAR).
 * E linear in t (@p t_degree 1) is: its t = 0 edge gives the powers of w,
 * the other edge the t terms. So @p degree 3, @p t_degree 1 (w, w^2, w^3,
 * w t, w^2 t: with y_lo, 6 parameters) identifies a convex, asymmetric loop
 * from major loops; hyst_everett_fit_init() is @p t_degree = @p degree - 1.
 * @return as hyst_everett_fit_init(); HYST_ERR_DEGREE also if @p t_degree
 *         >= @p degree.
 */
hyst_status_t hyst_everett_fit_init_terms(hyst_everett_fit_t *fit, unsigned degree,
                                          unsigned t_degree, hyst_wide_t lo, hyst_wide_t hi,
                                          hyst_wide_t *work, size_t work_len);

/**
 * @brief Moves the record's input to @p x and rotates the row (regressors
 *        at x, y) into the least squares' triangular factor.
 * @return HYST_OK; HYST_ERR_NONFINITE (y NaN or infinite: the input still
 *         moves, the sample is not used; x NaN: ignored); HYST_ERR_DOMAIN (x
 *         outside [lo, hi]: ignored); HYST_ERR_NOSPACE (the record stacks
 *         more turning points than the workspace holds: the fit cannot go
 *         on); HYST_ERR_NULL.
 */
hyst_status_t hyst_everett_fit_add(hyst_everett_fit_t *fit, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief Solves the least-squares problem into @p e (E's coefficients, y_lo,
 *        the domain) and the residual RMS over the samples used, so that
 *        hyst_*_curve_from_everett() accepts E.
 *
 * The unconstrained least-squares E when the curve accepts it (E increases
 * in a and decreases in b on the whole triangle lo <= b <= a <= hi): then
 * bit for bit hyst_everett_fit_solve_unconstrained()'s. Otherwise the
 * least-squares E subject to linear conditions sufficient for that: the
 * Bernstein-Bezier coefficients on the triangle of dE/da >= 0 and of
 * dE/db <= 0 (degree (degree + 1) inequalities, linear in E's
 * coefficients), solved exactly (a small quadratic programme: non-negative
 * least squares on its dual, bounded iterations). Sufficient, not
 * necessary: its residual can exceed that of the best monotone E of the
 * degree, and always is at least the unconstrained one's
 * (docs/identification.md, "Monotone fit"). No workspace besides the
 * fit's; the constrained case takes about 650 hyst_wide_t of stack (5 KB
 * in double).
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_SINGULAR (too few distinct
 *         turning points for the coefficients: a record of major loops
 *         alone determines degree 2 at most); HYST_ERR_NOT_MONOTONE (the
 *         constrained solution did not converge to an E the curve accepts,
 *         a rounding-level failure, or the E fitted is flat, E(hi, lo) not
 *         above the rounding of the outputs' spread: outputs that never
 *         rise, rise by less than the type resolves, or rise and fall
 *         (the nearest monotone E is then 0 up to rounding); @p e and
 *         @p rms hold it all the same); or what else the curve refuses
 *         that E with (in double, or in float without the f64 variant),
 *         HYST_ERR_ILL_CONDITIONED when its rounding bound exceeds
 *         HYST_MAX_ROUNDING of its range (an output offset far above the
 *         range); @p e and @p rms hold it then too. The factor is rotated
 *         from the rows themselves (no normal equations, whose condition
 *         number is the square of the regressors'), so HYST_NO_DOUBLE fits
 *         E of every degree as double does; there the constrained E's
 *         Bernstein-Bezier coefficients are sign-correct only to what the
 *         dual's normal equations resolve in float (the curve's own proof
 *         accepts it all the same).
 *         Outputs whose squares overflow hyst_wide_t fit as scaled ones
 *         do; @p rms is then infinite where its own squares overflow.
 */
hyst_status_t hyst_everett_fit_solve(const hyst_everett_fit_t *fit, hyst_everett_t *e,
                                     hyst_wide_t *rms);

/**
 * @brief The plain least-squares E and its residual RMS, not checked: the
 *        curve refuses it if it is not monotone (for comparison, e.g. what
 *        the monotone fit of hyst_everett_fit_solve() costs).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_SINGULAR.
 */
hyst_status_t hyst_everett_fit_solve_unconstrained(const hyst_everett_fit_t *fit,
                                                   hyst_everett_t *e, hyst_wide_t *rms);

/**
 * hyst_wide_t entries of the workspace of a fit along the record's branches
 * (the grid's, the spline's) of @p cols columns whose input record stacks at
 * most @p capacity turning points: each one's input and regressors, the
 * normal equations (a block of samples and the compensated sums of the
 * blocks) and the solver's (4 cols^2 + cols (capacity + 12) + capacity).
 */
#define HYST_BRANCH_FIT_WORK(cols, capacity)                                                  \
    ((size_t)(capacity) * ((size_t)(cols) + 1u) + 4u * (size_t)(cols) * (size_t)(cols) +      \
     12u * (size_t)(cols))

/**
 * @brief What a fit along the record's branches keeps (inside
 *        hyst_everett_grid_fit_t and hyst_spline_fit_t; private): the
 *        turning-point stack in the caller's workspace and the normal
 *        equations of y_lo (column 0, free) and weights >= 0. As for the
 *        polynomial E (hyst_everett_fit_t), the model's output is y_lo plus
 *        a signed sum of E over the stacked turning points, linear in the
 *        weights: each turning point keeps the regressors of its output.
 */
typedef struct hyst_branch_fit {
    size_t cols;         /**< 1 + the weights */
    hyst_wide_t lo, hi;  /**< the domain */
    hyst_wide_t *tp_x;   /**< caller's workspace: TP inputs (capacity) */
    hyst_wide_t *tp_r;   /**< and their regressors (capacity x cols) */
    hyst_wide_t *r_prev; /**< the last input's regressors (cols) */
    hyst_wide_t *ata;    /**< normal equations of the block (cols x cols, lower half) */
    hyst_wide_t *aty;    /**< (cols) */
    hyst_wide_t *total;  /**< the blocks' sums: A'A's lower half packed then A'y, high
                              parts (cols (cols + 3) / 2) then their rounding errors */
    hyst_wide_t *solver; /**< the solver's (2 cols^2 + 7 cols) */
    size_t capacity;     /**< TPs the workspace holds (A0 included) */
    size_t n_tp;         /**< stacked, A0 included */
    hyst_wide_t x_prev;  /**< last input */
    hyst_wide_t y_ref;   /**< the first output: aty and yy take y - y_ref */
    hyst_wide_t yy;      /**< sum of (y - y_ref)^2 over the block */
    hyst_wide_t yy_total[2]; /**< over the blocks before: high part, its rounding error */
    size_t used;         /**< samples in the normal equations */
    size_t in_block;     /**< of them in the block */
} hyst_branch_fit_t;

/** Columns of a grid fit of @p k knot intervals: y_lo and each cell's mass. */
#define HYST_EVERETT_GRID_FIT_COLS(k) (HYST_EVERETT_GRID_CELLS(k) + 1u)

/**
 * hyst_wide_t entries of the workspace of a grid fit (hyst_everett_grid_fit_init())
 * of @p k knot intervals whose input record stacks at most @p capacity
 * turning points (HYST_BRANCH_FIT_WORK()).
 */
#define HYST_EVERETT_GRID_FIT_WORK(k, capacity)                                               \
    HYST_BRANCH_FIT_WORK(HYST_EVERETT_GRID_FIT_COLS(k), capacity)

/**
 * @brief A grid fit in progress (hyst_everett_grid_fit_init()): the cells'
 *        masses of an E on a grid (hyst_everett_grid_t) by least squares
 *        with every mass >= 0, along the record's branches
 *        (hyst_branch_fit_t). Fields are private.
 */
typedef struct hyst_everett_grid_fit {
    unsigned intervals;  /**< K */
    hyst_wide_t knots[HYST_EVERETT_GRID_MAX_INTERVALS + 1]; /**< the grid */
    hyst_branch_fit_t branch; /**< the stack and the normal equations, cols 1 + the cells */
} hyst_everett_grid_fit_t;

/**
 * @brief Starts a grid fit on the knots @p knots[0..intervals] (strictly
 *        increasing; the domain their ends), the input record starting at
 *        knots[0] (as an instance after reset).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE (intervals outside
 *         1..HYST_EVERETT_GRID_MAX_INTERVALS), HYST_ERR_BREAKPOINTS (knots not
 *         finite or not increasing), HYST_ERR_NOSPACE (work_len below
 *         HYST_EVERETT_GRID_FIT_WORK(intervals, 2)).
 */
hyst_status_t hyst_everett_grid_fit_init(hyst_everett_grid_fit_t *fit, const hyst_wide_t *knots,
                                         unsigned intervals, hyst_wide_t *work, size_t work_len);

/**
 * @brief Moves the record's input to @p x and adds the row (regressors at x,
 *        y) to the normal equations.
 * @return as hyst_everett_fit_add(): HYST_OK; HYST_ERR_NONFINITE (y NaN or
 *         infinite: the input still moves; x NaN: ignored); HYST_ERR_DOMAIN
 *         (x outside the knots: ignored); HYST_ERR_NOSPACE (more turning
 *         points than the workspace holds); HYST_ERR_NULL.
 */
hyst_status_t hyst_everett_grid_fit_add(hyst_everett_grid_fit_t *fit, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief Solves for the masses (each >= 0: Lawson and Hanson's non-negative
 *        least squares on the normal equations, y_lo free) into @p g (the
 *        knots, y_lo, the masses) and the residual RMS over the samples used;
 *        where the record does not determine them, the solution of least
 *        squared masses among those that fit it alike
 *        (hyst_everett_grid_fit_determined()).
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_SINGULAR (fewer than two samples);
 *         HYST_ERR_COEFF (a mass, y_lo or the residual not finite: outputs
 *         so large that the normal equations overflow); HYST_ERR_NOT_MONOTONE
 *         (every mass 0: outputs that never rise; @p g and @p rms hold the
 *         fit all the same). @p g and @p rms not written on another error.
 */
hyst_status_t hyst_everett_grid_fit_solve(const hyst_everett_grid_fit_t *fit,
                                          hyst_everett_grid_t *g, hyst_wide_t *rms);

/**
 * @brief Whether the samples added determine every mass: 1, or 0 when the
 *        record's turning points leave how some cells share their mass
 *        open (major loops alone, for 4 intervals or more: they determine
 *        each diagonal cell and the others' sums by row and by column), or
 *        @p fit is NULL or holds fewer than two samples. Where it is 0,
 *        many non-negative solutions fit the record alike and predict
 *        differently where it did not go (minor loops, branches it did not
 *        take): hyst_everett_grid_fit_solve() then returns the one of least
 *        squared masses (a ridge of 1e4 roundings, 2.2e-12 in double, of
 *        the normal equations' largest diagonal entry), the same whatever
 *        the rounding of the outputs.
 *        Uses the solver's workspace; the solve may follow.
 */
int hyst_everett_grid_fit_determined(const hyst_everett_grid_fit_t *fit);

/**
 * @brief Knots for a grid fit where the output changes: the quantiles of
 *        the inputs x[1..n) weighted by |y[k] - y[k - 1]| (the midpoint of
 *        each step), on [lo, hi] = knots[0], knots[intervals]; no two closer
 *        than (hi - lo) / (16 intervals). The weights are binned into the
 *        caller's @p work (@p work_len >= 16 bins: the knots' resolution is
 *        (hi - lo) / work_len).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE, HYST_ERR_DOMAIN (lo, hi
 *         not finite or lo >= hi, or too close for the type to hold
 *         intervals + 1 knots that far apart), HYST_ERR_NOSPACE; uniform
 *         knots when the output never moves. @p knots written only on
 *         success.
 */
hyst_status_t hyst_everett_grid_knots(const hyst_wide_t *x, const hyst_wide_t *y, size_t n,
                                      hyst_wide_t lo, hyst_wide_t hi, unsigned intervals,
                                      hyst_wide_t *knots, hyst_wide_t *work, size_t work_len);

/** Columns of a spline fit of @p k knot intervals: y_lo and K + 2 weights. */
#define HYST_SPLINE_FIT_COLS(k) ((k) + 3u)

/**
 * hyst_wide_t entries of the workspace of a spline fit (hyst_spline_fit_init())
 * of @p k knot intervals whose input record stacks at most @p capacity
 * turning points (HYST_BRANCH_FIT_WORK()).
 */
#define HYST_SPLINE_FIT_WORK(k, capacity) HYST_BRANCH_FIT_WORK(HYST_SPLINE_FIT_COLS(k), capacity)

/**
 * @brief A spline fit in progress (hyst_spline_fit_init()): the spline f0
 *        (hyst_spline_t) of the symmetric model along every branch of the
 *        record, minor loops included. Fields are private.
 *
 * The branch from a turning point (b, y_b) rises as y_b + g(x - b) and
 * from (a, y_a) falls as y_a - g(a - x), g(d) = f0(lo + d) - f0(lo): the
 * output is y_lo plus a signed sum of g over the stacked turning points,
 * as the grid fit's is of E(a, b) = g(a - b). f0 = y_lo + sum w_j I_j,
 * j = 0..K+1, I_j the integral from lo of the j-th quadratic B-spline on
 * the uniform knots (cubic I-splines): linear in the weights w, f0 a C2
 * cubic spline, increasing where every w_j >= 0 (the constraint).
 */
typedef struct hyst_spline_fit {
    unsigned intervals;       /**< K */
    hyst_wide_t scale;        /**< K / (hi - lo): knot intervals per input unit */
    hyst_branch_fit_t branch; /**< the stack and the normal equations (the domain) */
} hyst_spline_fit_t;

/**
 * @brief Starts a spline fit of @p intervals uniform knot intervals on
 *        [@p lo, @p hi], the input record starting at lo (as an instance
 *        after reset).
 * @return HYST_OK, HYST_ERR_NULL, HYST_ERR_DEGREE (intervals outside
 *         1..HYST_SPLINE_MAX_INTERVALS), HYST_ERR_DOMAIN (lo, hi not finite,
 *         lo >= hi, or a span or knot spacing the type does not hold),
 *         HYST_ERR_NOSPACE (work_len below HYST_SPLINE_FIT_WORK(intervals, 2)).
 */
hyst_status_t hyst_spline_fit_init(hyst_spline_fit_t *fit, unsigned intervals, hyst_wide_t lo,
                                   hyst_wide_t hi, hyst_wide_t *work, size_t work_len);

/**
 * @brief Moves the record's input to @p x and adds the row (regressors at x,
 *        y) to the normal equations.
 * @return as hyst_everett_grid_fit_add(): HYST_OK; HYST_ERR_NONFINITE (y NaN
 *         or infinite: the input still moves; x NaN: ignored);
 *         HYST_ERR_DOMAIN (x outside [lo, hi]: ignored); HYST_ERR_NOSPACE
 *         (more turning points than the workspace holds); HYST_ERR_NULL.
 */
hyst_status_t hyst_spline_fit_add(hyst_spline_fit_t *fit, hyst_wide_t x, hyst_wide_t y);

/**
 * @brief Solves for the weights (each >= 0: Lawson and Hanson's
 *        non-negative least squares on the normal equations, y_lo free)
 *        into @p f0 (the knots' values f0(x_k) and slopes f0'(x_k), in
 *        output units per input unit: the Hermite pieces are the fitted
 *        cubic spline itself) and the residual RMS over the samples used.
 *        Every slope is >= 0 and every piece increases, but for the
 *        values' rounding: an offset far above the range may still make
 *        the curve refuse a flat piece.
 * @return HYST_OK; HYST_ERR_NULL; HYST_ERR_SINGULAR (fewer than two
 *         samples); HYST_ERR_COEFF (a weight, value, slope or the residual
 *         not finite: outputs so large that the normal equations
 *         overflow); HYST_ERR_NOT_MONOTONE (f0 flat: every weight 0, or
 *         value[K] not above value[0] in the type: outputs that never rise;
 *         @p f0 and @p rms hold the fit all the same). @p f0 and @p rms not
 *         written on another error.
 */
hyst_status_t hyst_spline_fit_solve(const hyst_spline_fit_t *fit, hyst_spline_t *f0,
                                    hyst_wide_t *rms);

#ifdef __cplusplus
}
#endif

#endif /* HYST_IDENT_H */
