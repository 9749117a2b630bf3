/* SPDX-License-Identifier: MIT */
/*
 * hyst_mex: the MEX gateway of the MATLAB/Octave wrappers (hyst_fit.m,
 * hyst_sim.m, hyst_inv.m, hyst_header.m): one entry point dispatching on a
 * command string, every number computed by the library's C code
 * (docs/matlab.md).
 *
 *   v = hyst_mex('version')                      HYST_VERSION_STRING
 *   s = hyst_mex('status_str', code)             hyst_status_str(code)
 *   [y, st, ntp] = hyst_mex('sim', coeffs, lo, hi, x, capacity, deadband[, ctau, cweight
 *                           [, rtau, rweight]])
 *   [x, st, ntp, err] = hyst_mex('inv', coeffs, lo, hi, y, capacity, deadband, intervals
 *                                [, ctau, cweight[, rtau, rweight]])
 *   [y, st, ntp] = hyst_mex('sim_everett', degree, lo, hi, y_lo, terms, x, capacity, deadband
 *                           [, ctau, cweight[, rtau, rweight]])
 *   [x, st, ntp, err] = hyst_mex('inv_everett', degree, lo, hi, y_lo, terms, y, capacity,
 *                                deadband, intervals, rows[, ctau, cweight[, rtau, rweight]])
 *   [y, st, ntp] = hyst_mex('sim_grid', knots, weights, y_lo, x, capacity, deadband
 *                           [, ctau, cweight[, rtau, rweight]])
 *   [x, st, ntp] = hyst_mex('inv_grid', knots, weights, y_lo, y, capacity, deadband
 *                           [, ctau, cweight[, rtau, rweight]])
 *   [y, st, ntp] = hyst_mex('sim_spline', lo, hi, values, slopes, x, capacity, deadband
 *                           [, ctau, cweight[, rtau, rweight]])
 *   [x, st, ntp, err] = hyst_mex('inv_spline', lo, hi, values, slopes, y, capacity, deadband,
 *                                intervals[, ctau, cweight[, rtau, rweight]])
 *   [c, st] = hyst_mex('creep', tau, weight, x_rest, x)
 *   [rms, creep] = hyst_mex('holdout', coeffs, lo, hi, x, y, skip, delay, from, tau)
 *   [rms, creep] = hyst_mex('holdout_everett', degree, lo, hi, y_lo, terms, x, y, skip, delay,
 *                           from, tau)
 *   [rms, creep] = hyst_mex('holdout_grid', knots, weights, y_lo, x, y, skip, delay, from, tau)
 *   [rms, creep] = hyst_mex('holdout_spline', lo, hi, values, slopes, x, y, skip, delay, from,
 *                           tau)
 *   [t, crc, max_err, exact, err] = hyst_mex('inv_table', coeffs, lo, hi, intervals, class)
 *   [t, crc, max_err, exact, err] = hyst_mex('inv_table_everett', degree, lo, hi, y_lo, terms,
 *                                            intervals, rows, class)
 *   c = hyst_mex('config')                       the compensators' default table sizes
 *   f = hyst_mex('fit', x, y, degree, method, lo, hi, skip, delay)
 *   f = hyst_mex('fit_everett', x, y, degree, lo, hi, skip, delay)
 *   f = hyst_mex('fit_grid', x, y, intervals, lo, hi, skip, delay)
 *   f = hyst_mex('fit_spline', x, y, intervals, lo, hi, skip, delay)
 *   [delay, fraction, x] = hyst_mex('given_delay', x, y, kind, degree, t_degree, method, lo,
 *                                   hi, skip)
 *   e = hyst_mex('excitation', x, y, skip, end, delay)   what the hold-out tests a choice on
 *   r = hyst_mex('record_check', x, y, skip, delay)   what hyst fit refuses in a record
 *   [cands, best, with_creep, widened, fraction, x, rate] = hyst_mex('select', x, y, kinds,
 *       method, lo, hi, skip, delay, t_degree, creep_tau[, rate_tau])
 *   m = hyst_mex('model_parse', bytes, file)    the reader of tools/model_text
 *   t = hyst_mex('model_write', kind, lo, hi, delay, coeffs, degree, y_lo, terms, ctau, cweight
 *                [, identified[, rtau, rweight]])
 *   t = hyst_mex('header_open', name, kind, lo, hi, delay, coeffs, degree, y_lo, terms, ctau,
 *                cweight[, rtau, rweight]), hyst_mex('header_close', name)
 *   t = hyst_mex('header_table', name, kind, lo, hi, delay, coeffs, degree, y_lo, terms, ctau,
 *                cweight, intervals, rows)   the compensator's table of a header
 *
 * sim_grid runs the asymmetric kind on a grid (hyst_everett_grid_t: knots
 * lo .. hi, weights the cells' masses, y_lo), inv_grid its compensator
 * (hyst_*_curve_everett_grid_inverse(), each branch solved in closed form),
 * as `hyst sim --model` and `hyst inv --model` run a file of kind
 * everett_grid. model_write, header_open and model_parse take and give such
 * a file's knots and weights in the places of coeffs and terms (kind
 * 'everett_grid'; model_parse's struct names them knots and weights).
 * fit_grid: the grid of `intervals` knot intervals as `hyst fit --kind
 * everett_grid` fits it (fit_grid_record(), tools/cli/fit_grid.c).
 * sim_spline runs the symmetric kind whose f0 is a monotone cubic spline on
 * uniform knots (hyst_spline_t: lo, hi, f0's values and slopes at the K + 1
 * knots), inv_spline its compensator (hyst_curve_spline_inverse(), each
 * drive solved per sample; intervals > 0: hyst_*_curve_spline_inverse_table(),
 * err its measured error), as `hyst sim --model` and `hyst inv --model
 * [--intervals N]` run a file of kind spline; model_write, header_open and model_parse take
 * and give its values and slopes in the places of coeffs and terms (kind
 * 'spline'; model_parse's struct names them values and slopes).
 * fit_spline: the spline of `intervals` knot intervals as `hyst fit --kind
 * spline` fits it (fit_spline_record(), tools/cli/fit_spline.c).
 * sim_everett runs the asymmetric kind (hyst_everett_t; terms are e[i-1][j]
 * of w^i t^j for i = 1..degree, then j = 0..degree-i), inv_everett its
 * compensator: intervals 0, hyst_curve_inverse() (HYST_CURVE_EVERETT_INV,
 * solved per branch; rows, 3..4096 all the same, is not used); intervals
 * 1..2^20 and rows 3..4096 (both checked before anything is allocated),
 * the tabulated one firmware runs, hyst_*_curve_everett_inverse_table()
 * (HYST_CURVE_EVERETT_INV_TABLE) with a table of
 * HYST_EVERETT_INV_TABLE_LEN(rows, intervals) numbers. inv's intervals
 * (0: hyst_*_init_inverse_exact) tabulates f0's inverse
 * (hyst_*_init_inverse_table). err, of inv and inv_everett: the tabulated
 * compensator's worst error measured by its init, of the drive range
 * (hyst_curve_inverse_error(); 0 for an exact or solved one).
 * inv_table and inv_table_everett build the tabulated compensator alone,
 * the numbers a header's table must hold: hyst_*_curve_from_poly()
 * then hyst_*_curve_inverse_table() (HYST_INV_TABLE_LEN(intervals) numbers),
 * or hyst_*_curve_from_everett() then hyst_*_curve_everett_inverse_table()
 * (HYST_EVERETT_INV_TABLE_LEN(rows, intervals)); intervals 1..2^20 and rows
 * 3..4096 are checked before anything is allocated. class 'double' builds
 * it in f64, 'single' in f32 from the model's numbers as a float build
 * reads their 17-digit literals (strtof). t: the table, a column of that
 * class; crc, max_err: its seal (hyst_curve_table_seal(); the error
 * rounded up to a float); exact: the intervals solved per sample instead;
 * err: hyst_curve_inverse_error().
 * header_table: the text `hyst header --compensator` puts between a header's
 * open and close, from the same C (model_text_header_table()); intervals
 * 1..2^20 and rows 3..4096 (kind everett; another kind ignores it) are
 * checked before anything is allocated.
 * config: a struct of HYST_INV_TABLE (inv_table), HYST_EVERETT_INV_ROWS
 * (everett_inv_rows), HYST_EVERETT_INV_INTERVALS (everett_inv_intervals),
 * HYST_INV_TABLE_TOL (inv_table_tol) and HYST_MAX_DEGREE (max_degree), as
 * this MEX file was built.
 * sim/inv and both *_everett: x of class double runs hyst_f64_*, single runs hyst_f32_*; the
 * result has the class and the shape of x; st is the status of the block
 * call (0, or a warning: 1 clamped, 2 memory full; a non-finite sample gives
 * -7 and is ignored as in firmware), ntp the turning points stored at the end.
 * ctau, cweight (both or neither; [] and []: none): a creep term (hyst/creep.h),
 * 1..HYST_CREEP_MAX_TERMS lags of time constants ctau (samples) and weights
 * cweight, every lag at lo at rest, run as `hyst sim --model` and `hyst inv
 * --model` run it (tools/cli/cli_tcm.c): sim adds hyst_*_creep_step() of the
 * input as the model took it (hyst_*_input()) to each output; inv inverts the
 * hysteresis model for the desired output less hyst_*_creep_output(), then
 * the lags take the drive in. Sample by sample then, the block call's
 * statuses folded as it folds them; the library checks the numbers
 * (hyst_*_creep_init(): hyst:ERR_ARG, hyst:ERR_WEIGHTS).
 * rtau, rweight (both scalars, or both empty: none): a rate term
 * (hyst/rate.h) of time constant rtau samples and weight rweight, at rest at
 * lo, run with the creep term as the tool runs both: sim adds both terms'
 * contributions, inv subtracts both before inverting (the sum in double, as
 * tools/cli/cli_tcm.c sums them); hyst_*_rate_init() checks the numbers.
 * creep: the creep term alone over x (hyst_f64_creep_step, or _f32 for x
 * single), every lag at x_rest first: its contributions c (x's class and
 * shape) and st, 0 or -7 (a non-finite sample, ignored).
 * holdout, holdout_everett: the model in f64 from rest over a record as
 * `hyst fit` scores it (tools/cli/fit_select.c): x(k) paired with
 * y(k + delay), k > skip (1-based); rms its RMS error from sample from + 1
 * on (NaN: none); tau >= 0: the creep term fitted to its residual before
 * sample from + 1 and scored after (tools/cli/fit_creep.c; tau 0: the best
 * of 100, 200, 500, ..., 20000 samples up to the record's length), a struct
 * of tau (0: none could be fitted), weight, offset, holdout_rms, fit_rms and
 * max_abs; tau < 0: creep is [].
 * fit: method 1 joint, 2 reflect; lo == hi takes the domain from the data.
 * fit_everett: E by hyst_everett_fit_*, the record starting from rest at
 * sample skip, inputs clamped to the domain as the model clamps them.
 * A negative status of an init or of the fit raises an error whose
 * identifier is hyst:<status name> (hyst:ERR_NOT_INCREASING) and whose
 * message holds hyst_status_str(); a bad argument raises hyst:usage.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mex.h"

#include "hyst/hyst.h"

/* host modules shared with the `hyst` tool and the Python package: the
 * model file format and fit's hold-out scoring */
#include "fit_select.h"
#include "model_text.h"

/* The name of a status as in status.h without the HYST_ prefix. */
static const char *status_name(int st)
{
    static const struct {
        int code;
        const char *name;
    } names[] = {
        {HYST_OK, "OK"},
        {HYST_WARN_CLAMPED, "WARN_CLAMPED"},
        {HYST_WARN_FULL, "WARN_FULL"},
        {HYST_ERR_NULL, "ERR_NULL"},
        {HYST_ERR_DOMAIN, "ERR_DOMAIN"},
        {HYST_ERR_DEGREE, "ERR_DEGREE"},
        {HYST_ERR_CAPACITY, "ERR_CAPACITY"},
        {HYST_ERR_COEFF, "ERR_COEFF"},
        {HYST_ERR_NOT_INCREASING, "ERR_NOT_INCREASING"},
        {HYST_ERR_NONFINITE, "ERR_NONFINITE"},
        {HYST_ERR_ARG, "ERR_ARG"},
        {HYST_ERR_NOSPACE, "ERR_NOSPACE"},
        {HYST_ERR_SINGULAR, "ERR_SINGULAR"},
        {HYST_ERR_FORMAT, "ERR_FORMAT"},
        {HYST_ERR_CRC, "ERR_CRC"},
        {HYST_ERR_VERSION, "ERR_VERSION"},
        {HYST_ERR_CURVE, "ERR_CURVE"},
        {HYST_ERR_BREAKPOINTS, "ERR_BREAKPOINTS"},
        {HYST_ERR_WEIGHTS, "ERR_WEIGHTS"},
        {HYST_ERR_NOT_INVERTIBLE, "ERR_NOT_INVERTIBLE"},
        {HYST_ERR_LAYOUT, "ERR_LAYOUT"},
        {HYST_ERR_OVERLAP, "ERR_OVERLAP"},
        {HYST_ERR_BUSY, "ERR_BUSY"},
        {HYST_ERR_ILL_CONDITIONED, "ERR_ILL_CONDITIONED"},
        {HYST_ERR_NOT_MONOTONE, "ERR_NOT_MONOTONE"},
    };
    size_t i;
    for (i = 0u; i < sizeof names / sizeof names[0]; ++i) {
        if (names[i].code == st) {
            return names[i].name;
        }
    }
    return "UNKNOWN";
}

/* Raises the library's status: identifier hyst:<name>, message
 * "<context>: <hyst_status_str> (<name>, <code>)". Does not return. */
static void fail_status(const char *context, int st)
{
    char id[64];
    (void)snprintf(id, sizeof id, "hyst:%s", status_name(st));
    mexErrMsgIdAndTxt(id, "%s: %s (%s, %d)", context, hyst_status_str(st), status_name(st), st);
}

static void usage(const char *what) { mexErrMsgIdAndTxt("hyst:usage", "hyst_mex: %s", what); }

static int is_real_double(const mxArray *a)
{
    return mxIsDouble(a) && !mxIsComplex(a) && !mxIsSparse(a);
}

/* A real double scalar argument. */
static double scalar(const mxArray *a, const char *name)
{
    char msg[96];
    if (!is_real_double(a) || mxGetNumberOfElements(a) != 1u) {
        (void)snprintf(msg, sizeof msg, "%s must be a real double scalar", name);
        usage(msg);
    }
    return *(const double *)mxGetData(a);
}

/* A count argument: a whole number in [lo, hi]. */
static size_t count(const mxArray *a, const char *name, double lo, double hi)
{
    char msg[96];
    const double v = scalar(a, name);
    if (!(v >= lo && v <= hi) || floor(v) != v) {
        (void)snprintf(msg, sizeof msg, "%s must be a whole number in %.0f..%.0f", name, lo, hi);
        usage(msg);
    }
    return (size_t)v;
}

/* f0 from coeffs (highest power first), lo, hi; validated by the library. */
static hyst_poly_t poly_arg(const mxArray *c, const mxArray *lo, const mxArray *hi)
{
    hyst_poly_t f0;
    const size_t n = mxGetNumberOfElements(c);
    size_t i;
    memset(&f0, 0, sizeof f0);
    if (!is_real_double(c) || n < 2u || n > HYST_MAX_DEGREE + 1u) {
        usage("coeffs must be a real double vector of 2 to HYST_MAX_DEGREE + 1 entries");
    }
    for (i = 0u; i < n; ++i) {
        f0.coeffs[i] = ((const double *)mxGetData(c))[i];
    }
    f0.degree = (unsigned)(n - 1u);
    f0.lo = scalar(lo, "lo");
    f0.hi = scalar(hi, "hi");
    return f0;
}

/* E from degree, lo, hi, y_lo, terms; validated by the library. */
static hyst_everett_t everett_arg(const mxArray *const prhs[5], const char *context)
{
    hyst_everett_t e;
    const size_t degree = count(prhs[0], "degree", 0.0, 1e9);
    const size_t n = mxGetNumberOfElements(prhs[4]);
    size_t i, j, k = 0u;
    memset(&e, 0, sizeof e);
    if (degree < 1u || degree > HYST_EVERETT_MAX_DEGREE) {
        fail_status(context, HYST_ERR_DEGREE);
    }
    if (!is_real_double(prhs[4]) || n != degree * (degree + 1u) / 2u) {
        usage("terms must be a real double vector of degree (degree + 1) / 2 entries");
    }
    e.degree = (unsigned)degree;
    e.lo = scalar(prhs[1], "lo");
    e.hi = scalar(prhs[2], "hi");
    e.y_lo = scalar(prhs[3], "y_lo");
    for (i = 1u; i <= degree; ++i) {
        for (j = 0u; i + j <= degree; ++j) {
            e.e[i - 1u][j] = ((const double *)mxGetData(prhs[4]))[k++];
        }
    }
    return e;
}

/* The table sizes the library takes (curve.h): intervals of either
 * tabulated compensator, rows of the asymmetric one's. */
#define INTERVALS_MAX 1048576.0 /* 2^20 */
#define ROWS_MIN 3.0
#define ROWS_MAX 4096.0

/* The model a sim/inv call runs: f0 or an E, or the inverse of either. */
typedef struct model_arg {
    int inverse;        /* the compensator */
    int everett;        /* the asymmetric kind: e, not f0 */
    int grid;           /* the asymmetric kind on a grid: g (e, f0 unused) */
    int spline;         /* the symmetric kind, f0 a cubic spline: s (e, f0 unused) */
    size_t intervals;   /* the compensator tabulated (firmware's); 0: exact (or solved) */
    size_t rows;        /* E's tabulated compensator: rows per direction */
    hyst_poly_t f0;
    hyst_everett_t e;
    hyst_everett_grid_t g;
    hyst_spline_t s;
    size_t ncreep;      /* lags of its creep term; 0: none */
    hyst_wide_t creep_tau[HYST_CREEP_MAX_TERMS], creep_weight[HYST_CREEP_MAX_TERMS];
    int has_rate;       /* a rate term of time constant rate_tau, weight rate_weight */
    hyst_wide_t rate_tau, rate_weight;
} model_arg_t;

/* A rate term's time constant and weight into m: two real double scalars,
 * or both empty (none). Their values are the library's to check. */
static void rate_arg(model_arg_t *m, const mxArray *tau, const mxArray *weight)
{
    const size_t n = mxGetNumberOfElements(tau);
    if (!is_real_double(tau) || !is_real_double(weight) ||
        mxGetNumberOfElements(weight) != n || n > 1u) {
        usage("rate_tau and rate_weight must be real double scalars (or both empty: no rate "
              "term)");
    }
    m->has_rate = n == 1u;
    if (m->has_rate) {
        m->rate_tau = (hyst_wide_t)((const double *)mxGetData(tau))[0];
        m->rate_weight = (hyst_wide_t)((const double *)mxGetData(weight))[0];
    }
}

/* A creep term's time constants and weights into m: two real double
 * vectors of 1..HYST_CREEP_MAX_TERMS entries each, as many, or both empty
 * (none). Their values are the library's to check. */
static void creep_arg(model_arg_t *m, const mxArray *tau, const mxArray *weight)
{
    const size_t n = mxGetNumberOfElements(tau);
    size_t i;
    if (!is_real_double(tau) || !is_real_double(weight) ||
        mxGetNumberOfElements(weight) != n || n > HYST_CREEP_MAX_TERMS) {
        usage("creep_tau and creep_weight must be real double vectors of 1 to "
              "HYST_CREEP_MAX_TERMS entries, as many of each (or both empty: no creep term)");
    }
    m->ncreep = n;
    for (i = 0u; i < n; ++i) {
        m->creep_tau[i] = (hyst_wide_t)((const double *)mxGetData(tau))[i];
        m->creep_weight[i] = (hyst_wide_t)((const double *)mxGetData(weight))[i];
    }
}

/* The optional tail of a model's arguments, prhs[0 .. n): none, the creep
 * term's ctau, cweight, or those and the rate term's rtau, rweight. */
static void terms_args(model_arg_t *m, const mxArray *const *prhs, int n)
{
    if (n >= 2) {
        creep_arg(m, prhs[0], prhs[1]);
    }
    if (n == 4) {
        rate_arg(m, prhs[2], prhs[3]);
    }
}

/* Numbers of the table of m's curve itself: a grid's or a spline's (0: the others). */
static size_t own_table_len(const model_arg_t *m)
{
    return m->grid     ? HYST_EVERETT_GRID_TABLE_LEN(m->g.intervals)
           : m->spline ? HYST_SPLINE_TABLE_LEN(m->s.intervals)
                       : 0u;
}

/* Numbers of the tables m and its compensator need (0: none), counted in
 * double where size_t could wrap (rows and intervals at their largest need
 * 2^35): the curve's own, then the compensator's. */
static double table_numbers(const model_arg_t *m)
{
    const double row = 4.0 * ((double)m->intervals + 1.0); /* HYST_INV_TABLE_LEN */
    const double own = (double)own_table_len(m);
    if (!m->inverse || m->intervals == 0u) {
        return own;
    }
    return own + (m->everett ? 2.0 * ((double)m->rows + 1.0) * row : row);
}

/* The same as a size_t, once table_numbers() is known to fit. */
static size_t table_len(const model_arg_t *m)
{
    const size_t own = own_table_len(m);
    if (!m->inverse || m->intervals == 0u) {
        return own;
    }
    return own + (m->everett ? HYST_EVERETT_INV_TABLE_LEN(m->rows, m->intervals)
                             : HYST_INV_TABLE_LEN(m->intervals));
}

/* init_f64, init_f32: init S (and curve, which S may point at) for m in
 * variant P of number type T, tp holding the four turning-point arrays of
 * cap entries, table table_len(m) numbers (a grid's or a spline's own
 * first). An E's solved inverse replaces its forward curve (a copy of it);
 * its tabulated one, and a spline's, is built from it. */
#define DEFINE_INIT(P, T)                                                                   \
    static int init_##P(hyst_tcm_t *S, hyst_curve_t *curve, const model_arg_t *m, T *tp,    \
                        size_t cap, T *table)                                               \
    {                                                                                       \
        T *const xl = tp, *const yl = tp + cap, *const xr = tp + 2u * cap,                  \
                 *const yr = tp + 3u * cap;                                                 \
        int st;                                                                             \
        if (m->grid || m->spline) { /* a curve of its own table */                         \
            const size_t own = own_table_len(m);                                            \
            hyst_curve_t fwd;                                                               \
            st = m->grid ? hyst_##P##_curve_from_everett_grid(&fwd, &m->g, table, own)      \
                         : hyst_##P##_curve_from_spline(&fwd, &m->s, table, own);           \
            if (st == HYST_OK && m->inverse && m->intervals > 0u) { /* a spline's table */  \
                st = hyst_##P##_curve_spline_inverse_table(curve, &fwd, table + own,        \
                                                           m->intervals);                   \
            } else if (st == HYST_OK && m->inverse) {                                       \
                st = m->grid ? hyst_##P##_curve_everett_grid_inverse(curve, &fwd)           \
                             : hyst_curve_spline_inverse(curve, &fwd);                      \
            } else {                                                                        \
                *curve = fwd;                                                               \
            }                                                                               \
            return st != HYST_OK ? st : hyst_##P##_init_curve(S, curve, xl, yl, xr, yr, cap); \
        }                                                                                   \
        if (m->everett) {                                                                   \
            hyst_curve_t fwd;                                                               \
            st = hyst_##P##_curve_from_everett(&fwd, &m->e);                                \
            if (st == HYST_OK && m->inverse && m->intervals > 0u) {                         \
                st = hyst_##P##_curve_everett_inverse_table(curve, &fwd, table, m->rows,    \
                                                            m->intervals);                  \
            } else if (st == HYST_OK && m->inverse) {                                       \
                st = hyst_curve_inverse(curve, &fwd);                                       \
            } else {                                                                        \
                *curve = fwd;                                                               \
            }                                                                               \
            return st != HYST_OK ? st : hyst_##P##_init_curve(S, curve, xl, yl, xr, yr, cap); \
        }                                                                                   \
        if (m->inverse && m->intervals > 0u) {                                              \
            return hyst_##P##_init_inverse_table(S, curve, &m->f0, table, m->intervals, xl, yl, \
                                                 xr, yr, cap);                              \
        }                                                                                   \
        return m->inverse ? hyst_##P##_init_inverse_exact(S, curve, &m->f0, xl, yl, xr, yr, cap)  \
                          : hyst_##P##_init(S, &m->f0, xl, yl, xr, yr, cap);                \
    }
DEFINE_INIT(f64, double)
DEFINE_INIT(f32, float)
#undef DEFINE_INIT

/* build_f64, build_f32: the tabulated compensator of m alone, in variant P
 * of number type T, as `hyst header --compensator` builds it:
 * hyst_*_curve_from_poly() (or _from_everett()) into fwd, then
 * hyst_*_curve_inverse_table() (or _everett_inverse_table()) into inv with
 * table, table_len(m) numbers. */
#define DEFINE_BUILD(P, T)                                                                  \
    static int build_##P(hyst_curve_t *fwd, hyst_curve_t *inv, const model_arg_t *m, T *table) \
    {                                                                                       \
        const int st = m->everett ? hyst_##P##_curve_from_everett(fwd, &m->e)               \
                                  : hyst_##P##_curve_from_poly(fwd, &m->f0);                \
        if (st != HYST_OK) {                                                                \
            return st;                                                                      \
        }                                                                                   \
        return m->everett ? hyst_##P##_curve_everett_inverse_table(inv, fwd, table, m->rows, \
                                                                   m->intervals)            \
                          : hyst_##P##_curve_inverse_table(inv, fwd, table, m->intervals);  \
    }
DEFINE_BUILD(f64, double)
DEFINE_BUILD(f32, float)
#undef DEFINE_BUILD

/* run_f64, run_f32: x[0..n) through S into y in variant P of number type T:
 * the block call, or with m's creep term C sample by sample as `hyst sim
 * --model` (the output plus the creep of the input as the model took it)
 * and `hyst inv --model` (the hysteresis compensator of the desired output
 * less the creep's share, whose lags then take the drive in) run it, the
 * statuses folded as the block call folds them. */
#define DEFINE_RUN(P, T)                                                                    \
    static int run_##P(hyst_tcm_t *S, hyst_creep_t *C, hyst_rate_t *R, const model_arg_t *m, \
                       const T *x, T *y, size_t n)                                          \
    {                                                                                       \
        int worst = HYST_OK, failed = 0, st;                                                \
        size_t i;                                                                           \
        if (m->ncreep == 0u && !m->has_rate) {                                              \
            return hyst_##P##_process(S, x, y, n);                                          \
        }                                                                                   \
        for (i = 0u; i < n; ++i) {                                                          \
            const T xi = x[i];                                                              \
            if (m->inverse) {                                                               \
                const T v = xi - (T)((m->ncreep > 0u ? (double)hyst_##P##_creep_output(C) : 0.0) + \
                                     (m->has_rate ? (double)hyst_##P##_rate_output(R) : 0.0)); \
                const T drive = hyst_##P##_step(S, v);                                      \
                if (m->ncreep > 0u) {                                                       \
                    (void)hyst_##P##_creep_step(C, drive);                                  \
                }                                                                           \
                if (m->has_rate) {                                                          \
                    (void)hyst_##P##_rate_step(R, drive);                                   \
                }                                                                           \
                y[i] = drive;                                                               \
            } else {                                                                        \
                const T h = hyst_##P##_step(S, xi);                                         \
                const T u = hyst_##P##_input(S);                                            \
                const double c = m->ncreep > 0u ? (double)hyst_##P##_creep_step(C, u) : 0.0; \
                y[i] = h + (T)(c + (m->has_rate ? (double)hyst_##P##_rate_step(R, u) : 0.0)); \
            }                                                                               \
            st = hyst_status(S);                                                            \
            if (st < 0) {                                                                   \
                failed = 1;                                                                 \
            } else if (st > worst) {                                                        \
                worst = st;                                                                 \
            }                                                                               \
        }                                                                                   \
        return failed ? HYST_ERR_NONFINITE : worst;                                         \
    }
DEFINE_RUN(f64, double)
DEFINE_RUN(f32, float)
#undef DEFINE_RUN

/* The lo of m's domain: where its creep and rate terms rest. */
static hyst_wide_t model_lo(const model_arg_t *m)
{
    return (hyst_wide_t)(m->grid     ? m->g.knots[0]
                         : m->spline ? m->s.lo
                         : m->everett ? m->e.lo
                                      : m->f0.lo);
}

/* The creep term of m in variant f64 (or f32), every lag at the domain's lo. */
static int creep_init(hyst_creep_t *C, const model_arg_t *m, int f32)
{
    const hyst_wide_t x_rest = model_lo(m);
    if (m->ncreep == 0u) {
        return HYST_OK;
    }
    return f32 ? hyst_f32_creep_init(C, m->ncreep, m->creep_tau, m->creep_weight, x_rest)
               : hyst_f64_creep_init(C, m->ncreep, m->creep_tau, m->creep_weight, x_rest);
}

/* The rate term of m in variant f64 (or f32), at rest at the domain's lo. */
static int rate_init(hyst_rate_t *R, const model_arg_t *m, int f32)
{
    const hyst_wide_t x_rest = model_lo(m);
    if (!m->has_rate) {
        return HYST_OK;
    }
    return f32 ? hyst_f32_rate_init(R, m->rate_tau, m->rate_weight, x_rest)
               : hyst_f64_rate_init(R, m->rate_tau, m->rate_weight, x_rest);
}

/* Runs model m over x: prhs = x, capacity, deadband. */
static void run_tcm(const model_arg_t *m, int nlhs, mxArray *plhs[], const mxArray *prhs[])
{
    const char *context = m->inverse ? "hyst_inv" : "hyst_sim";
    hyst_tcm_t S;
    hyst_curve_t curve;
    hyst_creep_t creep;
    hyst_rate_t rate;
    const mxArray *x = prhs[0];
    mxArray *y;
    size_t n, cap, len;
    int st;
    cap = count(prhs[1], "capacity", 1.0, 1e9);
    n = mxGetNumberOfElements(x);
    if (mxIsComplex(x) || mxIsSparse(x) || !(mxIsDouble(x) || mxIsSingle(x))) {
        usage("the input must be a real double or single array");
    }
    if ((4.0 * (double)cap + table_numbers(m)) * (double)mxGetElementSize(x) >
        (double)(size_t)-1) {
        usage("the turning-point arrays and the table exceed the address space");
    }
    len = table_len(m);
    y = mxCreateNumericArray(mxGetNumberOfDimensions(x), mxGetDimensions(x), mxGetClassID(x),
                             mxREAL);
    if (mxIsDouble(x)) {
        double *tp = mxMalloc((4u * cap + len) * sizeof *tp);
        st = init_f64(&S, &curve, m, tp, cap, tp + 4u * cap);
        if (st == HYST_OK) {
            st = hyst_f64_set_deadband(&S, scalar(prhs[2], "deadband"));
        }
        if (st == HYST_OK) {
            st = creep_init(&creep, m, 0);
        }
        if (st == HYST_OK) {
            st = rate_init(&rate, m, 0);
        }
        if (st == HYST_OK && n > 0u) {
            st = run_f64(&S, &creep, &rate, m, (const double *)mxGetData(x), (double *)mxGetData(y), n);
        }
        if (st < 0 && st != HYST_ERR_NONFINITE) {
            mxFree(tp);
            mxDestroyArray(y);
            fail_status(context, st);
        }
        mxFree(tp);
    } else {
        float *tp = mxMalloc((4u * cap + len) * sizeof *tp);
        st = init_f32(&S, &curve, m, tp, cap, tp + 4u * cap);
        if (st == HYST_OK) {
            st = hyst_f32_set_deadband(&S, (float)scalar(prhs[2], "deadband"));
        }
        if (st == HYST_OK) {
            st = creep_init(&creep, m, 1);
        }
        if (st == HYST_OK) {
            st = rate_init(&rate, m, 1);
        }
        if (st == HYST_OK && n > 0u) {
            st = run_f32(&S, &creep, &rate, m, (const float *)mxGetData(x), (float *)mxGetData(y), n);
        }
        if (st < 0 && st != HYST_ERR_NONFINITE) {
            mxFree(tp);
            mxDestroyArray(y);
            fail_status(context, st);
        }
        mxFree(tp);
    }
    plhs[0] = y;
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleScalar((double)st);
    }
    if (nlhs > 2) {
        plhs[2] = mxCreateDoubleScalar((double)hyst_tp_count(&S));
    }
    if (nlhs > 3) { /* the tabulated compensator's measured error (init succeeded: here,
                       st is a warning or a non-finite sample's -7) */
        plhs[3] = mxCreateDoubleScalar(
            m->inverse && m->intervals > 0u ? (double)hyst_curve_inverse_error(&curve) : 0.0);
    }
}

/* sim or inv: prhs = coeffs, lo, hi, x, capacity, deadband; inv also
 * intervals (0: the exact compensator); then, optionally, the creep term's
 * ctau, cweight. */
static void run_poly(int inverse, int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    model_arg_t m;
    const int args = inverse ? 7 : 6;
    if (nrhs != args && nrhs != args + 2 && nrhs != args + 4) {
        usage(inverse ? "inv takes coeffs, lo, hi, x, capacity, deadband, intervals[, ctau, "
                        "cweight[, rtau, rweight]]"
                      : "sim takes coeffs, lo, hi, x, capacity, deadband[, ctau, cweight[, rtau, "
                        "rweight]]");
    }
    memset(&m, 0, sizeof m);
    m.inverse = inverse;
    m.intervals = inverse ? count(prhs[6], "intervals", 0.0, INTERVALS_MAX) : 0u;
    m.f0 = poly_arg(prhs[0], prhs[1], prhs[2]);
    terms_args(&m, prhs + args, nrhs - args);
    run_tcm(&m, nlhs, plhs, prhs + 3);
}

/* sim_everett or inv_everett: prhs = degree, lo, hi, y_lo, terms, x, capacity, deadband;
 * inv_everett also intervals (0: the solved compensator) and rows. */
static void run_everett(int inverse, int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    model_arg_t m;
    const int args = inverse ? 10 : 8;
    if (nrhs != args && nrhs != args + 2 && nrhs != args + 4) {
        usage(inverse ? "inv_everett takes degree, lo, hi, y_lo, terms, y, capacity, deadband, "
                        "intervals, rows[, ctau, cweight[, rtau, rweight]]"
                      : "sim_everett takes degree, lo, hi, y_lo, terms, x, capacity, "
                        "deadband[, ctau, cweight[, rtau, rweight]]");
    }
    memset(&m, 0, sizeof m);
    m.everett = 1;
    m.inverse = inverse;
    if (inverse) { /* checked before anything is allocated */
        m.intervals = count(prhs[8], "intervals", 0.0, INTERVALS_MAX);
        m.rows = count(prhs[9], "rows", ROWS_MIN, ROWS_MAX);
    }
    m.e = everett_arg(prhs, inverse ? "hyst_inv" : "hyst_sim");
    terms_args(&m, prhs + args, nrhs - args);
    run_tcm(&m, nlhs, plhs, prhs + 5);
}

/* A grid's knots, weights and y_lo (prhs[0..2]) into *g: real double
 * vectors of 2..HYST_EVERETT_GRID_MAX_INTERVALS + 1 knots and K (K + 1) / 2
 * weights for K intervals; their values are the library's to check. */
static void grid_arg(hyst_everett_grid_t *g, const mxArray *const prhs[3])
{
    const size_t nk = mxGetNumberOfElements(prhs[0]), nw = mxGetNumberOfElements(prhs[1]);
    size_t i;
    if (!is_real_double(prhs[0]) || !is_real_double(prhs[1]) || nk < 2u ||
        nk > HYST_EVERETT_GRID_MAX_INTERVALS + 1u || nw != HYST_EVERETT_GRID_CELLS(nk - 1u)) {
        usage("a grid takes 2 to HYST_EVERETT_GRID_MAX_INTERVALS + 1 knots and K (K + 1) / 2 "
              "weights for K knot intervals (real double vectors)");
    }
    memset(g, 0, sizeof *g);
    g->intervals = (unsigned)(nk - 1u);
    for (i = 0u; i < nk; ++i) {
        g->knots[i] = (hyst_wide_t)((const double *)mxGetData(prhs[0]))[i];
    }
    for (i = 0u; i < nw; ++i) {
        g->weight[i] = (hyst_wide_t)((const double *)mxGetData(prhs[1]))[i];
    }
    g->y_lo = (hyst_wide_t)scalar(prhs[2], "y_lo");
}

/* A spline's lo, hi, values and slopes (prhs[0..3]) into *f0: real
 * double vectors of 2..HYST_SPLINE_MAX_INTERVALS + 1 values and as many
 * slopes for K intervals; their values are the library's to check. */
static void spline_arg(hyst_spline_t *f0, const mxArray *const prhs[4])
{
    const size_t n = mxGetNumberOfElements(prhs[2]);
    size_t i;
    if (!is_real_double(prhs[2]) || !is_real_double(prhs[3]) || n < 2u ||
        n > HYST_SPLINE_MAX_INTERVALS + 1u || mxGetNumberOfElements(prhs[3]) != n) {
        usage("a spline takes 2 to HYST_SPLINE_MAX_INTERVALS + 1 values and as many slopes "
              "(real double vectors)");
    }
    memset(f0, 0, sizeof *f0);
    f0->intervals = (unsigned)(n - 1u);
    f0->lo = (hyst_wide_t)scalar(prhs[0], "lo");
    f0->hi = (hyst_wide_t)scalar(prhs[1], "hi");
    for (i = 0u; i < n; ++i) {
        f0->value[i] = (hyst_wide_t)((const double *)mxGetData(prhs[2]))[i];
        f0->slope[i] = (hyst_wide_t)((const double *)mxGetData(prhs[3]))[i];
    }
}

/* sim_grid or inv_grid (prhs = knots, weights, y_lo, x, capacity, deadband
 * [, ctau, cweight[, rtau, rweight]]), or sim_spline or inv_spline (prhs =
 * lo, hi, values, slopes, x, capacity, deadband, inv_spline also intervals
 * (0: the solved compensator), ...): the kinds whose curve has a table of
 * its own; the grid's compensator is solved. */
static void run_own(int spline, int inverse, int nlhs, mxArray *plhs[], int nrhs,
                    const mxArray *prhs[])
{
    const int at = spline ? 4 : 3; /* x, then capacity, deadband[, intervals][, the terms] */
    const int args = at + 3 + (spline && inverse);
    model_arg_t m;
    if (nrhs != args && nrhs != args + 2 && nrhs != args + 4) {
        usage(spline ? (inverse ? "inv_spline takes lo, hi, values, slopes, y, capacity, "
                                  "deadband, intervals[, ctau, cweight[, rtau, rweight]]"
                                : "sim_spline takes lo, hi, values, slopes, x, capacity, "
                                  "deadband[, ctau, cweight[, rtau, rweight]]")
               : inverse ? "inv_grid takes knots, weights, y_lo, y, capacity, deadband[, ctau, "
                           "cweight[, rtau, rweight]]"
                         : "sim_grid takes knots, weights, y_lo, x, capacity, deadband[, ctau, "
                           "cweight[, rtau, rweight]]");
    }
    memset(&m, 0, sizeof m);
    m.grid = !spline;
    m.spline = spline;
    m.inverse = inverse;
    if (spline && inverse) { /* checked before anything is allocated */
        m.intervals = count(prhs[at + 3], "intervals", 0.0, INTERVALS_MAX);
    }
    if (spline) {
        spline_arg(&m.s, prhs);
    } else {
        grid_arg(&m.g, prhs);
    }
    terms_args(&m, prhs + args, nrhs - args);
    run_tcm(&m, nlhs, plhs, prhs + at);
}

/* v as a float build reads the header's literal of it (17 digits; HYST_REAL_C(lit)
 * is lit##f, converted directly to float), as a double. */
static double as_float_literal(double v)
{
    char lit[40];
    (void)snprintf(lit, sizeof lit, "%.17g", v);
    return (double)strtof(lit, NULL);
}

/* m's numbers as a float build of its header has them. */
static void round_to_float(model_arg_t *m)
{
    size_t i, j;
    m->f0.lo = as_float_literal(m->f0.lo);
    m->f0.hi = as_float_literal(m->f0.hi);
    for (i = 0u; i <= HYST_MAX_DEGREE; ++i) {
        m->f0.coeffs[i] = as_float_literal(m->f0.coeffs[i]);
    }
    m->e.lo = as_float_literal(m->e.lo);
    m->e.hi = as_float_literal(m->e.hi);
    m->e.y_lo = as_float_literal(m->e.y_lo);
    for (i = 0u; i < HYST_EVERETT_MAX_DEGREE; ++i) {
        for (j = 0u; j < HYST_EVERETT_MAX_DEGREE; ++j) {
            m->e.e[i][j] = as_float_literal(m->e.e[i][j]);
        }
    }
}

/* inv_table (prhs = coeffs, lo, hi, intervals, class) or inv_table_everett
 * (prhs = degree, lo, hi, y_lo, terms, intervals, rows, class): the
 * compensator's table built and sealed in the variant of the class name
 * ('double': f64; 'single': f32, the model's numbers first read as float
 * literals); plhs = table (a column of that class), crc, max_err (the
 * seal's), exact, inv_err. */
static void run_table(int everett, int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const size_t at = everett ? 5u : 3u; /* intervals, then (rows and) the class */
    char name[8];
    model_arg_t m;
    hyst_curve_t fwd, inv;
    hyst_table_seal_t seal;
    mxArray *t;
    int f32, st;
    if (nrhs != (everett ? 8 : 5)) {
        usage(everett ? "inv_table_everett takes degree, lo, hi, y_lo, terms, intervals, rows, "
                        "class"
                      : "inv_table takes coeffs, lo, hi, intervals, class");
    }
    memset(&m, 0, sizeof m);
    m.inverse = 1;
    m.everett = everett;
    m.intervals = count(prhs[at], "intervals", 1.0, INTERVALS_MAX); /* before allocating */
    if (everett) {
        m.rows = count(prhs[at + 1u], "rows", ROWS_MIN, ROWS_MAX);
        m.e = everett_arg(prhs, "hyst_header");
    } else {
        m.f0 = poly_arg(prhs[0], prhs[1], prhs[2]);
    }
    if (!mxIsChar(prhs[nrhs - 1]) || mxGetString(prhs[nrhs - 1], name, sizeof name) != 0 ||
        (strcmp(name, "double") != 0 && strcmp(name, "single") != 0)) {
        usage("the table's class must be 'double' or 'single'");
    }
    f32 = name[0] == 's';
    if (table_numbers(&m) * (f32 ? (double)sizeof(float) : (double)sizeof(double)) >
        (double)(size_t)-1) {
        usage("the table exceeds the address space");
    }
    if (f32) {
        round_to_float(&m);
    }
    t = mxCreateNumericMatrix((mwSize)table_len(&m), 1, f32 ? mxSINGLE_CLASS : mxDOUBLE_CLASS,
                              mxREAL);
    st = f32 ? build_f32(&fwd, &inv, &m, (float *)mxGetData(t))
             : build_f64(&fwd, &inv, &m, (double *)mxGetData(t));
    if (st == HYST_OK) {
        st = hyst_curve_table_seal(&inv, &seal);
    }
    if (st != HYST_OK) {
        mxDestroyArray(t);
        fail_status("hyst_header", st);
    }
    plhs[0] = t;
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleScalar((double)(seal.crc & 0xFFFFFFFFul));
    }
    if (nlhs > 2) {
        plhs[2] = mxCreateDoubleScalar((double)seal.max_err);
    }
    if (nlhs > 3) {
        plhs[3] = mxCreateDoubleScalar(
            (double)(everett ? inv.u.everett.exact : inv.u.inv_table.exact));
    }
    if (nlhs > 4) {
        plhs[4] = mxCreateDoubleScalar((double)hyst_curve_inverse_error(&inv));
    }
}

static void set_field(mxArray *s, const char *name, mxArray *v)
{
    mxSetField(s, 0, name, v);
}

/* config: the default table sizes of the compensators and f0's highest degree, as built. */
static void run_config(mxArray *plhs[])
{
    static const char *fields[] = {"inv_table",          "everett_inv_rows",
                                   "everett_inv_intervals", "inv_table_tol",
                                   "max_degree",         "everett_max_degree",
                                   "fit_parsimony"};
    mxArray *s = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
    set_field(s, "inv_table", mxCreateDoubleScalar((double)HYST_INV_TABLE));
    set_field(s, "everett_inv_rows", mxCreateDoubleScalar((double)HYST_EVERETT_INV_ROWS));
    set_field(s, "everett_inv_intervals",
              mxCreateDoubleScalar((double)HYST_EVERETT_INV_INTERVALS));
    set_field(s, "inv_table_tol", mxCreateDoubleScalar((double)HYST_INV_TABLE_TOL));
    set_field(s, "max_degree", mxCreateDoubleScalar((double)HYST_MAX_DEGREE));
    set_field(s, "everett_max_degree", mxCreateDoubleScalar((double)HYST_EVERETT_MAX_DEGREE));
    set_field(s, "fit_parsimony", mxCreateDoubleScalar(FIT_PARSIMONY));
    plhs[0] = s;
}

/* fit: prhs = x, y, degree, method, lo, hi, skip, delay. */
static void run_fit(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"coeffs", "lo",      "hi",      "degree",     "method",
                                   "rms",    "max_abs", "used",    "rising",     "falling",
                                   "increasing", "turn"};
    hyst_ident_config_t cfg;
    hyst_ident_t *work;
    hyst_ident_result_t r;
    mxArray *s, *c;
    size_t n, k;
    int st;
    if (nrhs != 8) {
        usage("fit takes x, y, degree, method, lo, hi, skip, delay");
    }
    if (!is_real_double(prhs[0]) || !is_real_double(prhs[1])) {
        usage("x and y must be real double vectors");
    }
    n = mxGetNumberOfElements(prhs[0]);
    if (mxGetNumberOfElements(prhs[1]) != n) {
        usage("x and y must have the same number of elements");
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.degree = (unsigned)count(prhs[2], "degree", 0.0, 1e9);
    cfg.method = (int)count(prhs[3], "method", 1.0, 2.0);
    cfg.lo = scalar(prhs[4], "lo");
    cfg.hi = scalar(prhs[5], "hi");
    cfg.skip = count(prhs[6], "skip", 0.0, 1e15);
    cfg.delay = count(prhs[7], "delay", 0.0, 1e15);
    work = mxMalloc(sizeof *work);
    st = hyst_ident_fit(&cfg, (const double *)mxGetData(prhs[0]),
                        (const double *)mxGetData(prhs[1]), n, work, &r);
    mxFree(work);
    if (st != HYST_OK) {
        fail_status("hyst_fit", st);
    }
    s = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
    c = mxCreateDoubleMatrix(1, (size_t)r.degree + 1u, mxREAL);
    for (k = 0u; k <= r.degree; ++k) {
        ((double *)mxGetData(c))[k] = r.coeffs[k];
    }
    set_field(s, "coeffs", c);
    set_field(s, "lo", mxCreateDoubleScalar(r.lo));
    set_field(s, "hi", mxCreateDoubleScalar(r.hi));
    set_field(s, "degree", mxCreateDoubleScalar((double)r.degree));
    set_field(s, "method", mxCreateString(r.method == HYST_IDENT_REFLECT ? "reflect" : "joint"));
    set_field(s, "rms", mxCreateDoubleScalar(r.rms));
    set_field(s, "max_abs", mxCreateDoubleScalar(r.max_abs));
    set_field(s, "used", mxCreateDoubleScalar((double)r.used));
    set_field(s, "rising", mxCreateDoubleScalar((double)r.rising));
    set_field(s, "falling", mxCreateDoubleScalar((double)r.falling));
    set_field(s, "increasing", mxCreateLogicalScalar(r.increasing != 0));
    set_field(s, "turn", mxCreateDoubleScalar(r.increasing ? 0.0 : r.turn));
    plhs[0] = s;
}

/* poly_from_everett(degree, lo, hi, y_lo, terms): E of t-degree 0 as the
 * symmetric model's f0 in powers of x, highest first, as hyst fit writes
 * the E of t-degree 0 it chooses (fit_poly_from_everett()); [] when E has a
 * term of t, the powers of x cancel or f0 does not increase. */
static void run_poly_from_everett(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    hyst_everett_t e;
    hyst_poly_t f0;
    unsigned k;
    if (nrhs != 5) {
        usage("poly_from_everett takes degree, lo, hi, y_lo, terms");
    }
    e = everett_arg(prhs, "hyst_fit");
    if (!fit_poly_from_everett(&e, &f0)) {
        plhs[0] = mxCreateDoubleMatrix(0, 0, mxREAL);
        return;
    }
    plhs[0] = mxCreateDoubleMatrix(1, f0.degree + 1u, mxREAL);
    for (k = 0u; k <= f0.degree; ++k) {
        mxGetPr(plhs[0])[k] = (double)f0.coeffs[k];
    }
}

/* fit_everett: prhs = x, y, degree, lo, hi, skip, delay[, t_degree]: only
 * E's terms w^i t^j with j <= t_degree fitted (default degree - 1: all). */
static void run_fit_everett(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"kind", "degree", "t_degree", "lo", "hi", "y_lo",
                                   "terms", "rms", "used", "monotone"};
    hyst_everett_fit_t fit;
    hyst_everett_t e;
    hyst_curve_t curve;
    hyst_wide_t *work, rms = 0.0, lo, hi;
    const double *x, *y;
    size_t n, skip, delay, len, i, j, used = 0u;
    unsigned degree, t_degree;
    mxArray *s, *t;
    int st;
    if (nrhs != 7 && nrhs != 8) {
        usage("fit_everett takes x, y, degree, lo, hi, skip, delay[, t_degree]");
    }
    if (!is_real_double(prhs[0]) || !is_real_double(prhs[1])) {
        usage("x and y must be real double vectors");
    }
    n = mxGetNumberOfElements(prhs[0]);
    if (mxGetNumberOfElements(prhs[1]) != n) {
        usage("x and y must have the same number of elements");
    }
    lo = scalar(prhs[3], "lo");
    hi = scalar(prhs[4], "hi");
    skip = count(prhs[5], "skip", 0.0, 1e15);
    delay = count(prhs[6], "delay", 0.0, 1e15);
    if (skip >= n || delay >= n - skip) {
        fail_status("hyst_fit", HYST_ERR_ARG);
    }
    n -= skip + delay; /* the samples paired */
    x = (const double *)mxGetData(prhs[0]) + skip;
    y = (const double *)mxGetData(prhs[1]) + skip + delay;
    if (lo == hi && (st = hyst_ident_domain(x, n, &lo, &hi)) != HYST_OK) {
        fail_status("hyst_fit", st);
    }
    len = HYST_EVERETT_FIT_WORK(n + 2u); /* n samples stack at most n + 1 TPs */
    work = mxMalloc(len * sizeof *work);
    degree = (unsigned)count(prhs[2], "degree", 0.0, 1e9);
    t_degree = nrhs == 8 ? (unsigned)count(prhs[7], "t_degree", 0.0, 1e9)
                         : (degree > 0u ? degree - 1u : 0u);
    st = hyst_everett_fit_init_terms(&fit, degree, t_degree, lo, hi, work, len);
    if (st == HYST_OK) {
        st = fit_everett_add_clamped(&fit, x, y, n, lo, hi, &used);
    }
    if (st == HYST_OK) {
        st = hyst_everett_fit_solve(&fit, &e, &rms);
    }
    mxFree(work);
    /* ERR_NOT_MONOTONE: E is returned all the same, field monotone false */
    if (st != HYST_OK && st != HYST_ERR_NOT_MONOTONE) {
        fail_status("hyst_fit", st);
    }
    s = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
    t = mxCreateDoubleMatrix(1, (mwSize)(e.degree * (e.degree + 1u) / 2u), mxREAL);
    for (i = 1u, n = 0u; i <= e.degree; ++i) {
        for (j = 0u; i + j <= e.degree; ++j) {
            ((double *)mxGetData(t))[n++] = e.e[i - 1u][j];
        }
    }
    set_field(s, "kind", mxCreateString("everett"));
    set_field(s, "degree", mxCreateDoubleScalar((double)e.degree));
    set_field(s, "t_degree", mxCreateDoubleScalar((double)t_degree));
    set_field(s, "lo", mxCreateDoubleScalar(e.lo));
    set_field(s, "hi", mxCreateDoubleScalar(e.hi));
    set_field(s, "y_lo", mxCreateDoubleScalar(e.y_lo));
    set_field(s, "terms", t);
    set_field(s, "rms", mxCreateDoubleScalar(rms));
    set_field(s, "used", mxCreateDoubleScalar((double)used));
    set_field(s, "monotone",
              mxCreateLogicalScalar(hyst_f64_curve_from_everett(&curve, &e) == HYST_OK));
    plhs[0] = s;
}

static mxArray *row_of(const double *v, size_t n);

/* A host tool's fit of a record (fit_grid_record(), fit_spline_record()). */
typedef hyst_status_t (*record_fit_t)(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                                      const double *y, size_t n, fit_everett_result_t *res);

/* fit_grid and fit_spline: prhs = x, y, intervals (1..most), lo, hi, skip,
 * delay; fit's result into *r and the struct of `fields` returned, its
 * kind and degree (the intervals asked for) set; hyst:usage, hyst:ERR_ARG
 * where skip and delay leave no sample, or the fit's refusal
 * (hyst:<status name>). */
static mxArray *fit_record(const char *cmd, const char *kind, double most, record_fit_t fit,
                           const char **fields, int nfields, int nrhs,
                           const mxArray *prhs[], fit_everett_result_t *r)
{
    char msg[128];
    hyst_ident_config_t cfg;
    size_t n;
    hyst_status_t st;
    mxArray *s;
    if (nrhs != 7 || !is_real_double(prhs[0]) || !is_real_double(prhs[1]) ||
        mxGetNumberOfElements(prhs[0]) != mxGetNumberOfElements(prhs[1])) {
        (void)snprintf(msg, sizeof msg, "%s takes x, y (real double vectors of one length), "
                                        "intervals, lo, hi, skip, delay", cmd);
        usage(msg);
    }
    n = mxGetNumberOfElements(prhs[0]);
    memset(&cfg, 0, sizeof cfg);
    cfg.degree = (unsigned)count(prhs[2], "intervals", 1.0, most);
    cfg.lo = scalar(prhs[3], "lo");
    cfg.hi = scalar(prhs[4], "hi");
    cfg.skip = count(prhs[5], "skip", 0.0, 1e15);
    cfg.delay = count(prhs[6], "delay", 0.0, 1e15);
    if (cfg.skip >= n || cfg.delay >= n - cfg.skip) {
        fail_status("hyst_fit", HYST_ERR_ARG);
    }
    st = fit(&cfg, cfg.degree, (const double *)mxGetData(prhs[0]),
             (const double *)mxGetData(prhs[1]), n, r);
    if (st != HYST_OK) {
        fail_status("hyst_fit", st);
    }
    s = mxCreateStructMatrix(1, 1, nfields, fields);
    set_field(s, "kind", mxCreateString(kind));
    set_field(s, "degree", mxCreateDoubleScalar((double)cfg.degree));
    return s;
}

/* A record fit's figures into s: rms (the model's run; the least-squares
 * residual when the library refuses the curve), max_abs, used, and whether
 * the library accepts the curve, in the field named `accepted`. */
static void set_fit_figures(mxArray *s, const fit_everett_result_t *r, const char *accepted)
{
    set_field(s, "rms", mxCreateDoubleScalar(r->curve_status == HYST_OK ? r->rms : r->ls_rms));
    set_field(s, "max_abs", mxCreateDoubleScalar(r->max_abs));
    set_field(s, "used", mxCreateDoubleScalar((double)r->used));
    set_field(s, accepted, mxCreateLogicalScalar(r->curve_status == HYST_OK));
}

/* fit_grid: prhs = x, y, intervals, lo, hi, skip, delay; the grid as `hyst
 * fit --kind everett_grid` fits it (fit_grid_record()): a struct of kind
 * 'everett_grid', degree (its intervals), lo, hi, y_lo, knots, weights,
 * rms (the model's run; the least-squares residual when the library refuses
 * the grid), max_abs, used, monotone (the library accepts it), determined
 * (the record determines every mass) and undetermined_why (the tool's words
 * when it does not, else ''). */
static void run_fit_grid(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"kind",    "degree", "lo",        "hi",
                                   "y_lo",    "knots",  "weights",   "rms",
                                   "max_abs", "used",   "monotone",  "determined",
                                   "undetermined_why"};
    fit_everett_result_t r;
    mxArray *s = fit_record("fit_grid", "everett_grid", (double)HYST_EVERETT_GRID_MAX_INTERVALS,
                            fit_grid_record, fields, (int)(sizeof fields / sizeof fields[0]),
                            nrhs, prhs, &r);
    set_field(s, "lo", mxCreateDoubleScalar(r.grid.knots[0]));
    set_field(s, "hi", mxCreateDoubleScalar(r.grid.knots[r.grid.intervals]));
    set_field(s, "y_lo", mxCreateDoubleScalar(r.grid.y_lo));
    set_field(s, "knots", row_of(r.grid.knots, r.grid.intervals + 1u));
    set_field(s, "weights", row_of(r.grid.weight, HYST_EVERETT_GRID_CELLS(r.grid.intervals)));
    set_fit_figures(s, &r, "monotone");
    set_field(s, "determined", mxCreateLogicalScalar(r.determined != 0));
    set_field(s, "undetermined_why", mxCreateString(r.determined ? "" : fit_grid_undetermined));
    plhs[0] = s;
}

/* fit_spline: prhs = x, y, intervals, lo, hi, skip, delay; f0 the spline
 * as `hyst fit --kind spline` fits it (fit_spline_record(), along every
 * branch, continued over whole intervals to a domain wider than the
 * inputs): a struct of kind 'spline', degree (the intervals fitted),
 * intervals (the model's: more where continued),
 * lo, hi, values, slopes, rms (the model's run; the least-squares residual
 * when the library refuses the spline), max_abs, used and increasing (the
 * library accepts it: f0 increases). */
static void run_fit_spline(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"kind",   "degree", "intervals", "lo",   "hi",
                                   "values", "slopes", "rms",       "max_abs", "used",
                                   "increasing"};
    fit_everett_result_t r;
    mxArray *s = fit_record("fit_spline", "spline", (double)HYST_SPLINE_MAX_INTERVALS,
                            fit_spline_record, fields, (int)(sizeof fields / sizeof fields[0]),
                            nrhs, prhs, &r);
    set_field(s, "intervals", mxCreateDoubleScalar((double)r.spline.intervals));
    set_field(s, "lo", mxCreateDoubleScalar(r.spline.lo));
    set_field(s, "hi", mxCreateDoubleScalar(r.spline.hi));
    set_field(s, "values", row_of(r.spline.value, r.spline.intervals + 1u));
    set_field(s, "slopes", row_of(r.spline.slope, r.spline.intervals + 1u));
    set_fit_figures(s, &r, "increasing");
    plhs[0] = s;
}

/* creep: prhs = tau, weight, x_rest, x; plhs = c (x's class and shape), st. */
static void run_creep(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    model_arg_t m;
    hyst_creep_t C;
    const mxArray *x;
    mxArray *c;
    size_t n, i;
    int st, failed = 0;
    if (nrhs != 4) {
        usage("creep takes tau, weight, x_rest, x");
    }
    memset(&m, 0, sizeof m);
    creep_arg(&m, prhs[0], prhs[1]);
    x = prhs[3];
    if (mxIsComplex(x) || mxIsSparse(x) || !(mxIsDouble(x) || mxIsSingle(x))) {
        usage("the input must be a real double or single array");
    }
    st = mxIsDouble(x) ? hyst_f64_creep_init(&C, m.ncreep, m.creep_tau, m.creep_weight,
                                             (hyst_wide_t)scalar(prhs[2], "x_rest"))
                       : hyst_f32_creep_init(&C, m.ncreep, m.creep_tau, m.creep_weight,
                                             (hyst_wide_t)scalar(prhs[2], "x_rest"));
    if (st != HYST_OK) {
        fail_status("hyst_mex creep", st);
    }
    n = mxGetNumberOfElements(x);
    c = mxCreateNumericArray(mxGetNumberOfDimensions(x), mxGetDimensions(x), mxGetClassID(x),
                             mxREAL);
    for (i = 0u; i < n; ++i) {
        if (mxIsDouble(x)) {
            const double xi = ((const double *)mxGetData(x))[i];
            ((double *)mxGetData(c))[i] = hyst_f64_creep_step(&C, xi);
        } else {
            const float xi = ((const float *)mxGetData(x))[i];
            ((float *)mxGetData(c))[i] = hyst_f32_creep_step(&C, xi);
        }
        failed |= hyst_creep_status(&C) < 0;
    }
    plhs[0] = c;
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleScalar(failed ? (double)HYST_ERR_NONFINITE : 0.0);
    }
}

/* holdout (kind 0; prhs = coeffs, lo, hi, x, y, skip, delay, from, tau),
 * holdout_everett (kind 1; prhs = degree, lo, hi, y_lo, terms, x, y, skip,
 * delay, from, tau), holdout_grid (kind 2; knots, weights, y_lo, x, ...) or
 * holdout_spline (kind 3; lo, hi, values, slopes, x, ...): the model run
 * from rest over the record as `hyst fit` scores it, by the tool's own code
 * (fit_model_run_creep(), tools/cli/fit_select.c);
 * plhs = its RMS error from sample from on (0-based), and the creep term
 * fitted to its residual before `from` and scored after (tau > 0 that time
 * constant, 0 the best of the tool's series; tau < 0: none, []). */
static void run_holdout(int kind, int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"tau", "weight", "offset", "holdout_rms", "fit_rms",
                                   "max_abs", "rate_tau", "rate_weight"};
    static double grid_table[HYST_EVERETT_GRID_TABLE_LEN(HYST_EVERETT_GRID_MAX_INTERVALS)];
    static double spline_table[HYST_SPLINE_TABLE_LEN(HYST_SPLINE_MAX_INTERVALS)];
    const int everett = kind == 1, grid = kind == 2, spline = kind == 3;
    const int at = everett ? 5 : spline ? 4 : 3; /* x, then y, skip, delay, from, tau */
    model_arg_t m;
    hyst_curve_t curve;
    fit_creep_t best;
    double rms;
    size_t n, skip, delay, from;
    int st = HYST_OK, terms;
    if (nrhs != at + 6 && nrhs != at + 7) {
        usage(grid      ? "holdout_grid takes knots, weights, y_lo, x, y, skip, delay, from, tau"
                          "[, rate_tau]"
              : spline  ? "holdout_spline takes lo, hi, values, slopes, x, y, skip, delay, from, "
                          "tau[, rate_tau]"
              : everett ? "holdout_everett takes degree, lo, hi, y_lo, terms, x, y, skip, delay, "
                          "from, tau[, rate_tau]"
                        : "holdout takes coeffs, lo, hi, x, y, skip, delay, from, tau[, rate_tau]");
    }
    memset(&m, 0, sizeof m);
    memset(&best, 0, sizeof best);
    if (grid) {
        grid_arg(&m.g, prhs);
        st = hyst_f64_curve_from_everett_grid(&curve, &m.g, grid_table,
                                              HYST_EVERETT_GRID_TABLE_LEN(m.g.intervals));
    } else if (spline) {
        spline_arg(&m.s, prhs);
        st = hyst_f64_curve_from_spline(&curve, &m.s, spline_table,
                                        HYST_SPLINE_TABLE_LEN((size_t)m.s.intervals));
    } else if (everett) {
        m.e = everett_arg(prhs, "hyst_fit");
        st = hyst_f64_curve_from_everett(&curve, &m.e);
    } else {
        m.f0 = poly_arg(prhs[0], prhs[1], prhs[2]);
        st = hyst_f64_curve_from_poly(&curve, &m.f0);
    }
    if (st != HYST_OK) {
        fail_status("hyst_fit", st);
    }
    if (!is_real_double(prhs[at]) || !is_real_double(prhs[at + 1])) {
        usage("x and y must be real double vectors");
    }
    n = mxGetNumberOfElements(prhs[at]);
    if (mxGetNumberOfElements(prhs[at + 1]) != n) {
        usage("x and y must have the same number of elements");
    }
    skip = count(prhs[at + 2], "skip", 0.0, 1e15);
    delay = count(prhs[at + 3], "delay", 0.0, 1e15);
    from = count(prhs[at + 4], "from", 0.0, 1e15);
    /* tau < 0: no creep lag; a rate term (rate_tau > 0) is fitted with the lag's weight */
    best.tau = scalar(prhs[at + 5], "tau");
    best.rate_tau = nrhs == at + 7 ? scalar(prhs[at + 6], "rate_tau") : 0.0;
    best.rate_tau = best.rate_tau > 0 ? best.rate_tau : 0.0;
    terms = best.tau >= 0 || best.rate_tau > 0;
    best.tau = best.tau >= 0 ? best.tau : 0.0;
    rms = fit_model_run_creep(kind != 0 ? NULL : &m.f0, kind != 0 ? &curve : NULL,
                              (const double *)mxGetData(prhs[at]),
                              (const double *)mxGetData(prhs[at + 1]), n, skip, delay, from, NULL,
                              NULL, terms ? &best : NULL);
    plhs[0] = mxCreateDoubleScalar(rms);
    if (nlhs > 1 && (!terms || n <= delay + skip)) {
        plhs[1] = mxCreateDoubleMatrix(0, 0, mxREAL);
    } else if (nlhs > 1) {
        plhs[1] = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
        set_field(plhs[1], "tau", mxCreateDoubleScalar(best.tau));
        set_field(plhs[1], "weight", mxCreateDoubleScalar(best.weight));
        set_field(plhs[1], "offset", mxCreateDoubleScalar(best.offset));
        set_field(plhs[1], "holdout_rms", mxCreateDoubleScalar(best.holdout_rms));
        set_field(plhs[1], "fit_rms", mxCreateDoubleScalar(best.fit_rms));
        set_field(plhs[1], "max_abs", mxCreateDoubleScalar(best.max_abs));
        set_field(plhs[1], "rate_tau", mxCreateDoubleScalar(best.rate_tau));
        set_field(plhs[1], "rate_weight",
                  mxCreateDoubleScalar(best.rate_tau > 0 ? best.rate_weight : NAN));
    }
}

/* A validation record (`hyst fit --validate`) from the arguments vx, vy
 * (real double vectors of one length; empty: none, the hold-out), from row
 * skip on: its drive copied into *vdrive (mxCalloc'd; NULL with none),
 * which a search interpolates in place by a fraction chosen. v, or NULL. */
static const fit_validation_t *validation_arg(const mxArray *vx, const mxArray *vy, size_t skip,
                                              double **vdrive, fit_validation_t *v)
{
    size_t n;
    *vdrive = NULL;
    if (!is_real_double(vx) || !is_real_double(vy) ||
        mxGetNumberOfElements(vx) != mxGetNumberOfElements(vy)) {
        usage("the validation record is vx, vy: real double vectors of one length");
    }
    n = mxGetNumberOfElements(vx);
    if (n == 0u) {
        return NULL;
    }
    *vdrive = (double *)mxCalloc(n, sizeof **vdrive);
    memcpy(*vdrive, mxGetData(vx), n * sizeof **vdrive);
    v->x = *vdrive;
    v->y = (const double *)mxGetData(vy);
    v->n = n;
    v->skip = skip;
    return v;
}

/* A candidate's kind as fit_select.h numbers it: FIT_POLY 1, FIT_EVERETT 2,
 * FIT_GRID 4 or FIT_SPLINE 8. */
static int fit_kind_arg(const mxArray *a)
{
    const int kind = (int)count(a, "kind", 1.0, 8.0);
    if (kind != FIT_POLY && kind != FIT_EVERETT && kind != FIT_GRID && kind != FIT_SPLINE) {
        usage("kind is 1 (poly), 2 (everett), 4 (everett_grid) or 8 (spline)");
    }
    return kind;
}

/* score: prhs = x, y, kind (1 poly, 2 everett, 4 everett_grid, 8 spline: the
 * last two's degree their intervals), degree, t_degree, method,
 * lo, hi, skip, delay, creep_tau[, vx, vy]; one candidate scored as the
 * automatic choice scores it (fit_score(), tools/cli/fit_select.c: the
 * hold-out splits, or the validation record vx, vy). plhs = its hold-out
 * RMS (NaN: not scored) and its creep term (a struct: tau (0: none),
 * weight, holdout_rms). */
static void run_score(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"tau", "weight", "holdout_rms"};
    hyst_ident_config_t base;
    fit_candidate_t c;
    fit_validation_t v;
    const fit_validation_t *val = NULL;
    double *vdrive = NULL;
    if ((nrhs != 11 && nrhs != 13) || !is_real_double(prhs[0]) || !is_real_double(prhs[1]) ||
        mxGetNumberOfElements(prhs[0]) != mxGetNumberOfElements(prhs[1])) {
        usage("score takes x, y (real double vectors of one length), kind, degree, t_degree, "
              "method, lo, hi, skip, delay, creep_tau[, vx, vy]");
    }
    memset(&base, 0, sizeof base);
    memset(&c, 0, sizeof c);
    c.kind = fit_kind_arg(prhs[2]);
    c.degree = (unsigned)count(prhs[3], "degree", 1.0,
                               c.kind == FIT_GRID     ? (double)HYST_EVERETT_GRID_MAX_INTERVALS
                               : c.kind == FIT_SPLINE ? (double)HYST_SPLINE_MAX_INTERVALS
                                                      : (double)HYST_MAX_DEGREE);
    c.t_degree = (unsigned)count(prhs[4], "t_degree", 0.0, (double)HYST_EVERETT_MAX_DEGREE);
    base.method = (int)count(prhs[5], "method", 1.0, 2.0);
    base.lo = scalar(prhs[6], "lo");
    base.hi = scalar(prhs[7], "hi");
    base.skip = count(prhs[8], "skip", 0.0, 1e15);
    c.delay = count(prhs[9], "delay", 0.0, 1e15);
    if (nrhs == 13) {
        val = validation_arg(prhs[11], prhs[12], base.skip, &vdrive, &v);
    }
    fit_score(&base, (const double *)mxGetData(prhs[0]), (const double *)mxGetData(prhs[1]),
              mxGetNumberOfElements(prhs[0]), val, scalar(prhs[10], "creep_tau"), &c);
    if (vdrive != NULL) {
        mxFree(vdrive);
    }
    plhs[0] = mxCreateDoubleScalar(c.holdout_rms);
    if (nlhs > 1) {
        plhs[1] = mxCreateStructMatrix(1, 1, 3, fields);
        mxSetField(plhs[1], 0, "tau", mxCreateDoubleScalar(c.creep.tau));
        mxSetField(plhs[1], 0, "weight", mxCreateDoubleScalar(c.creep.tau > 0 ? c.creep.weight
                                                                               : NAN));
        mxSetField(plhs[1], 0, "holdout_rms",
                   mxCreateDoubleScalar(c.creep.tau > 0 ? c.creep.holdout_rms : NAN));
    }
}

/* excitation: prhs = x, y, skip, end, delay[, vx, vy]; plhs = what the
 * hold-out's last third of x(skip + 1 .. end) tests a choice on, the output
 * of x(k) being y(k + delay) (fit_holdout_excitation(), tools/cli/fit_select.c),
 * or the validation record vx, vy (the output delay samples later) against
 * x(skip + 1 .. end) (fit_validation_excitation()): a struct fitted_lo,
 * fitted_hi, holdout_n, beyond, span, minor, noise (the scored outputs'
 * noise floor, fit_noise_floor(); NaN: not resolved), and min_span, the span
 * below which hyst fit warns. */
static void run_excitation(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"fitted_lo", "fitted_hi", "holdout_n", "beyond",
                                   "span",      "minor",     "noise",     "min_span"};
    fit_excitation_t e;
    size_t skip, end, delay;
    mxArray *s;
    (void)nlhs;
    if ((nrhs != 5 && nrhs != 7) || !is_real_double(prhs[0]) || !is_real_double(prhs[1])) {
        usage("excitation takes x, y (real double vectors), skip, end, delay[, vx, vy]");
    }
    skip = count(prhs[2], "skip", 0.0, 1e15);
    end = count(prhs[3], "end", 0.0, 1e15);
    delay = count(prhs[4], "delay", 0.0, 1e15);
    if (skip > end || end > mxGetNumberOfElements(prhs[0]) ||
        end + delay > mxGetNumberOfElements(prhs[1])) {
        usage("excitation: skip <= end <= numel(x), end + delay <= numel(y) needed");
    }
    if (nrhs == 7) {
        fit_validation_t v;
        double *vdrive;
        const fit_validation_t *val = validation_arg(prhs[5], prhs[6], skip, &vdrive, &v);
        if (val == NULL) {
            usage("excitation: the validation record is empty");
        }
        fit_validation_excitation((const double *)mxGetData(prhs[0]), skip, end, val, delay, &e);
        if (vdrive != NULL) {
            mxFree(vdrive);
        }
    } else {
        fit_holdout_excitation((const double *)mxGetData(prhs[0]),
                               (const double *)mxGetData(prhs[1]), skip, end, delay, &e);
    }
    s = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
    set_field(s, "fitted_lo", mxCreateDoubleScalar(e.fitted_lo));
    set_field(s, "fitted_hi", mxCreateDoubleScalar(e.fitted_hi));
    set_field(s, "holdout_n", mxCreateDoubleScalar((double)e.holdout_n));
    set_field(s, "beyond", mxCreateDoubleScalar((double)e.beyond));
    set_field(s, "span", mxCreateDoubleScalar(e.span));
    set_field(s, "minor", mxCreateDoubleScalar((double)e.minor));
    set_field(s, "noise", mxCreateDoubleScalar(e.noise));
    set_field(s, "min_span", mxCreateDoubleScalar(FIT_HOLDOUT_MIN_SPAN));
    plhs[0] = s;
}

/* record_check: prhs = x, y, skip, delay; plhs = hyst fit's check of the
 * record before fitting (fit_record_check(), tools/cli/fit_select.c; NaN a
 * missing sample): a struct fault ('ok', 'infinite_input',
 * 'infinite_output', 'no_sample', 'constant_input', 'constant_output' or
 * 'falling'), pairs, at (the infinite sample's 1-based index), value,
 * correlation, minor. */
static void run_record_check(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"fault", "pairs", "at", "value", "correlation", "minor"};
    fit_record_t r;
    int fault;
    mxArray *s;
    (void)nlhs;
    if (nrhs != 4 || !is_real_double(prhs[0]) || !is_real_double(prhs[1])) {
        usage("record_check takes x, y (real double vectors), skip, delay");
    }
    fault = fit_record_check((const double *)mxGetData(prhs[0]), mxGetNumberOfElements(prhs[0]),
                             (const double *)mxGetData(prhs[1]), mxGetNumberOfElements(prhs[1]),
                             count(prhs[2], "skip", 0.0, 1e15), count(prhs[3], "delay", 0.0, 1e15),
                             &r);
    s = mxCreateStructMatrix(1, 1, (int)(sizeof fields / sizeof fields[0]), fields);
    set_field(s, "fault", mxCreateString(fit_record_fault_name(fault)));
    set_field(s, "pairs", mxCreateDoubleScalar((double)r.pairs));
    set_field(s, "at", mxCreateDoubleScalar((double)r.at + 1.0));
    set_field(s, "value", mxCreateDoubleScalar(r.value));
    set_field(s, "correlation", mxCreateDoubleScalar(r.correlation));
    set_field(s, "minor", mxCreateDoubleScalar((double)r.minor));
    plhs[0] = s;
}

/* given_delay: prhs = x, y, kind (1 poly, 2 everett, 4 everett_grid, 8
 * spline: the last two's degree their intervals), degree, t_degree, method, lo, hi, skip[, vx, vy]; the delay
 * of that one model as `hyst fit --degree D` without --delay chooses it
 * (fit_given_delay(), tools/cli/fit_select.c; scored on the validation
 * record vx, vy when given). plhs = the whole delay, the sub-sample
 * fraction (0: none), the drive interpolated by it (a column; x as given
 * without one) and the validation record's drive alike. */
static void run_given_delay(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    hyst_ident_config_t base;
    fit_found_t found;
    size_t n, delay = 0u;
    int kind;
    unsigned t_degree;
    double *drive, *vdrive = NULL;
    fit_validation_t v;
    const fit_validation_t *val = NULL;
    hyst_status_t st;
    if ((nrhs != 9 && nrhs != 11) || !is_real_double(prhs[0]) || !is_real_double(prhs[1]) ||
        mxGetNumberOfElements(prhs[0]) != mxGetNumberOfElements(prhs[1])) {
        usage("given_delay takes x, y (real double vectors of one length), kind, degree, "
              "t_degree, method, lo, hi, skip[, vx, vy]");
    }
    n = mxGetNumberOfElements(prhs[0]);
    memset(&base, 0, sizeof base);
    kind = fit_kind_arg(prhs[2]);
    /* a degree the fit refuses scores nothing here (delay 0): the fit says why */
    base.degree = (unsigned)count(prhs[3], "degree", 0.0, 64.0);
    t_degree = (unsigned)count(prhs[4], "t_degree", 0.0, (double)HYST_EVERETT_MAX_DEGREE);
    base.method = (int)count(prhs[5], "method", 1.0, 2.0);
    base.lo = scalar(prhs[6], "lo");
    base.hi = scalar(prhs[7], "hi");
    base.skip = count(prhs[8], "skip", 0.0, 1e15);
    if (nrhs == 11) {
        val = validation_arg(prhs[9], prhs[10], base.skip, &vdrive, &v);
    }
    plhs[0] = NULL;
    drive = (double *)mxCalloc(n > 0u ? n : 1u, sizeof *drive);
    memcpy(drive, mxGetData(prhs[0]), n * sizeof *drive);
    st = fit_given_delay(&base, kind, t_degree, drive, (const double *)mxGetData(prhs[1]), n,
                         val, &delay, &found);
    if (st != HYST_OK) {
        mxFree(drive);
        if (vdrive != NULL) {
            mxFree(vdrive);
        }
        fail_status("given_delay", (int)st);
    }
    plhs[0] = mxCreateDoubleScalar((double)delay);
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleScalar(found.delay_fraction);
    }
    if (nlhs > 2) {
        plhs[2] = mxCreateDoubleMatrix((mwSize)n, 1, mxREAL);
        memcpy(mxGetPr(plhs[2]), drive, n * sizeof *drive);
    }
    if (nlhs > 3) { /* the validation record's drive, interpolated alike ([] without one) */
        plhs[3] = mxCreateDoubleMatrix(val != NULL ? (mwSize)val->n : 0, val != NULL ? 1 : 0,
                                       mxREAL);
        if (val != NULL) {
            memcpy(mxGetPr(plhs[3]), vdrive, val->n * sizeof *vdrive);
        }
    }
    mxFree(drive);
    if (vdrive != NULL) {
        mxFree(vdrive);
    }
}

/* select: prhs = x, y, kinds (a sum of 1 poly, 2 everett, 4 everett_grid, 8 spline), method,
 * lo, hi,
 * skip, delay (-1: chosen), t_degree (-1: any), creep_tau[, rate_tau[, vx,
 * vy]]; fit's automatic choice by the `hyst` tool's own code (fit_search(),
 * tools/cli/fit_select.c; scored on the validation record vx, vy when given
 * and not empty). plhs = the candidates (a struct array: kind,
 * degree, t_degree, delay, params, holdout_rms, fit_rms, status, creep_tau,
 * creep_weight, creep_holdout_rms), the index chosen (1-based; 0: none),
 * whether with its creep term, the chosen one's domain [lo hi] when
 * widened, else [] (fit_chosen_domain()), the sub-sample delay's fraction
 * (0: none), the drive interpolated by it (x as given without one), the
 * rate term's search and the validation record's drive interpolated alike
 * ([] without one). */
static void run_select(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *fields[] = {"kind",        "degree",  "t_degree", "delay",
                                   "params",      "holdout_rms", "fit_rms", "status",
                                   "creep_tau",   "creep_weight", "creep_holdout_rms",
                                   "widened"};
    hyst_ident_config_t base;
    fit_candidate_t *cand;
    fit_found_t found;
    size_t n, scored, best = 0u, i;
    long t_degree;
    double delay, *drive, *vdrive = NULL;
    int kinds, with_creep = 0;
    fit_validation_t v;
    const fit_validation_t *val = NULL;
    hyst_status_t st;
    mxArray *s;
    if ((nrhs != 10 && nrhs != 11 && nrhs != 13) || !is_real_double(prhs[0]) ||
        !is_real_double(prhs[1]) ||
        mxGetNumberOfElements(prhs[0]) != mxGetNumberOfElements(prhs[1])) {
        usage("select takes x, y (real double vectors of one length), kinds, method, lo, hi, "
              "skip, delay (-1: chosen), t_degree, creep_tau[, rate_tau[, vx, vy]]");
    }
    n = mxGetNumberOfElements(prhs[0]);
    memset(&base, 0, sizeof base);
    kinds = (int)count(prhs[2], "kinds", 1.0, 15.0);
    base.method = (int)count(prhs[3], "method", 1.0, 2.0);
    base.lo = scalar(prhs[4], "lo");
    base.hi = scalar(prhs[5], "hi");
    base.skip = count(prhs[6], "skip", 0.0, 1e15);
    delay = scalar(prhs[7], "delay");
    base.delay = delay < 0 ? 0u : count(prhs[7], "delay", 0.0, 1e15);
    t_degree = (long)scalar(prhs[8], "t_degree");
    if (nrhs == 13) {
        val = validation_arg(prhs[11], prhs[12], base.skip, &vdrive, &v);
    }
    cand = (fit_candidate_t *)mxCalloc(FIT_SEARCH_CANDIDATES, sizeof *cand);
    drive = (double *)mxCalloc(n > 0u ? n : 1u, sizeof *drive); /* interpolated by a fraction */
    memcpy(drive, mxGetData(prhs[0]), n * sizeof *drive);
    st = fit_search(&base, kinds,
                    t_degree < 0 || t_degree >= HYST_EVERETT_MAX_DEGREE ? FIT_ANY_T_DEGREE
                                                                        : (unsigned)t_degree,
                    scalar(prhs[9], "creep_tau"), delay < 0, drive,
                    (const double *)mxGetData(prhs[1]), n, val, cand, FIT_SEARCH_CANDIDATES,
                    &found);
    if (st != HYST_OK) {
        mxFree(cand);
        mxFree(drive);
        if (vdrive != NULL) {
            mxFree(vdrive);
        }
        fail_status("select", (int)st);
    }
    scored = found.count;
    best = found.best;
    with_creep = found.with_creep;
    s = mxCreateStructMatrix(1, (mwSize)scored, (int)(sizeof fields / sizeof fields[0]), fields);
    for (i = 0u; i < scored; ++i) {
        const fit_candidate_t *c = &cand[i];
        const int everett = c->kind == FIT_EVERETT;
        const char *status = c->status == HYST_ERR_NOT_MONOTONE ? "E not monotone"
                             : c->status != HYST_OK             ? status_name(c->status)
                             : c->kind == FIT_POLY && !c->fit.increasing ? "f0 not increasing"
                                                                         : "OK";
        mxSetField(s, (mwIndex)i, "kind", mxCreateString(fit_kind_name(c->kind)));
        mxSetField(s, (mwIndex)i, "degree", mxCreateDoubleScalar((double)c->degree));
        mxSetField(s, (mwIndex)i, "t_degree",
                   everett ? mxCreateDoubleScalar((double)c->t_degree)
                           : mxCreateDoubleMatrix(0, 0, mxREAL));
        mxSetField(s, (mwIndex)i, "delay", mxCreateDoubleScalar((double)c->delay));
        mxSetField(s, (mwIndex)i, "params",
                   mxCreateDoubleScalar((double)fit_parameters(c->kind, c->degree, c->t_degree)));
        mxSetField(s, (mwIndex)i, "holdout_rms", mxCreateDoubleScalar(c->holdout_rms));
        mxSetField(s, (mwIndex)i, "fit_rms", mxCreateDoubleScalar(c->fit_rms));
        mxSetField(s, (mwIndex)i, "status", mxCreateString(status));
        mxSetField(s, (mwIndex)i, "creep_tau", mxCreateDoubleScalar(c->creep.tau));
        mxSetField(s, (mwIndex)i, "creep_weight",
                   mxCreateDoubleScalar(c->creep.tau > 0 ? c->creep.weight : NAN));
        mxSetField(s, (mwIndex)i, "creep_holdout_rms",
                   mxCreateDoubleScalar(c->creep.tau > 0 ? c->creep.holdout_rms : NAN));
        mxSetField(s, (mwIndex)i, "widened", mxCreateLogicalScalar(c->widened != 0));
    }
    if (nlhs > 3) { /* the chosen one's domain when widened, else [] */
        double lo = 0.0, hi = 0.0;
        const int widened = best != (size_t)-1 &&
                            fit_chosen_domain(&cand[best], drive, base.skip, n, &lo, &hi);
        plhs[3] = mxCreateDoubleMatrix(widened ? 1 : 0, widened ? 2 : 0, mxREAL);
        if (widened) {
            mxGetPr(plhs[3])[0] = lo;
            mxGetPr(plhs[3])[1] = hi;
        }
    }
    if (nlhs > 4) {
        plhs[4] = mxCreateDoubleScalar(found.delay_fraction);
    }
    if (nlhs > 5) { /* a column, as hyst_fit holds x */
        plhs[5] = mxCreateDoubleMatrix((mwSize)n, 1, mxREAL);
        memcpy(mxGetPr(plhs[5]), drive, n * sizeof *drive);
    }
    if (nlhs > 6) { /* a rate term scored on the choice's hold-out (fit_rate_search()) */
        static const char *rate_fields[] = {"with_rate", "rate_tau", "holdout_rms", "without"};
        const double rate_tau = nrhs >= 11 ? scalar(prhs[10], "rate_tau") : -1.0;
        fit_candidate_t with_rate;
        int kept = 0;
        memset(&with_rate, 0, sizeof with_rate);
        with_rate.creep.holdout_rms = NAN;
        if (rate_tau >= 0 && best != (size_t)-1) {
            kept = fit_rate_search(&base, drive, (const double *)mxGetData(prhs[1]), n, val,
                                   &cand[best], with_creep, rate_tau, &with_rate);
        }
        plhs[6] = mxCreateStructMatrix(1, 1, 4, rate_fields);
        mxSetField(plhs[6], 0, "with_rate", mxCreateLogicalScalar(kept != 0));
        mxSetField(plhs[6], 0, "rate_tau", mxCreateDoubleScalar(with_rate.creep.rate_tau));
        mxSetField(plhs[6], 0, "holdout_rms", mxCreateDoubleScalar(with_rate.creep.holdout_rms));
        mxSetField(plhs[6], 0, "without",
                   mxCreateDoubleScalar(best != (size_t)-1 ? fit_option_rms(&cand[best], with_creep)
                                                           : NAN));
    }
    if (nlhs > 7) { /* the validation record's drive, interpolated alike ([] without one) */
        plhs[7] = mxCreateDoubleMatrix(val != NULL ? (mwSize)val->n : 0, val != NULL ? 1 : 0,
                                       mxREAL);
        if (val != NULL) {
            memcpy(mxGetPr(plhs[7]), vdrive, val->n * sizeof *vdrive);
        }
    }
    mxFree(cand);
    mxFree(drive);
    if (vdrive != NULL) {
        mxFree(vdrive);
    }
    plhs[0] = s;
    if (nlhs > 1) {
        plhs[1] = mxCreateDoubleScalar(best == (size_t)-1 ? 0.0 : (double)best + 1.0);
    }
    if (nlhs > 2) {
        plhs[2] = mxCreateDoubleScalar(with_creep ? 1.0 : 0.0);
    }
}

/* ---- the model file format, its one implementation (tools/model_text) ---- */

/* A real double vector argument into a[0..cap), its length into *n (the
 * checks refuse a length beyond cap before they read a). */
static void numbers_arg(const mxArray *v, const char *name, double *a, size_t cap, size_t *n)
{
    char msg[96];
    size_t i;
    if (!is_real_double(v)) {
        (void)snprintf(msg, sizeof msg, "%s must be a real double vector", name);
        usage(msg);
    }
    *n = mxGetNumberOfElements(v);
    for (i = 0u; i < *n && i < cap; ++i) {
        a[i] = ((const double *)mxGetData(v))[i];
    }
}

/* A model from prhs = kind, lo, hi, delay, coeffs, degree, y_lo, terms,
 * ctau, cweight (the parts of hyst_model_parts.m) and identified ([LO HI],
 * [] or NULL: none), checked as the reader checks a file: hyst:usage with
 * its reason otherwise. */
static void model_text_arg(model_text_t *m, const mxArray *const prhs[10],
                           const mxArray *identified, const mxArray *const *rate,
                           const char *caller)
{
    char kind[16], msg[MODEL_TEXT_MSG_SIZE];
    double v;
    memset(m, 0, sizeof *m);
    if (!mxIsChar(prhs[0]) || mxGetString(prhs[0], kind, sizeof kind) != 0 ||
        (strcmp(kind, "poly") != 0 && strcmp(kind, "everett") != 0 &&
         strcmp(kind, "everett_grid") != 0 && strcmp(kind, "spline") != 0)) {
        usage("kind must be 'poly', 'everett', 'everett_grid' or 'spline'");
    }
    m->kind = strcmp(kind, "everett_grid") == 0 ? MODEL_TEXT_GRID
              : strcmp(kind, "spline") == 0     ? MODEL_TEXT_SPLINE
              : strcmp(kind, "everett") == 0    ? MODEL_TEXT_EVERETT
                                                : MODEL_TEXT_POLY;
    m->lo = scalar(prhs[1], "lo");
    m->hi = scalar(prhs[2], "hi");
    v = scalar(prhs[3], "delay");
    if (!(v >= 0.0 && v <= (double)MODEL_TEXT_MAX_DELAY)) {
        usage("delay must be a delay of 0 to 1000000000 samples");
    }
    m->delay = (unsigned long)v;
    m->delay_fraction = v - floor(v); /* a sub-sample delay: 3.5 */
    if (m->kind == MODEL_TEXT_EVERETT) {
        v = scalar(prhs[5], "degree");
        m->degree = v >= 1.0 && v <= HYST_EVERETT_MAX_DEGREE && v == floor(v) ? (unsigned)v : 0u;
        m->y_lo = scalar(prhs[6], "y_lo");
        numbers_arg(prhs[7], "terms", m->terms, HYST_EVERETT_TERMS, &m->nterms);
    } else if (m->kind == MODEL_TEXT_GRID) { /* knots in coeffs' place, weights in terms' */
        m->y_lo = scalar(prhs[6], "y_lo");
        numbers_arg(prhs[4], "knots", m->knots, HYST_EVERETT_GRID_MAX_INTERVALS + 1u,
                    &m->nknots);
        numbers_arg(prhs[7], "weights", m->weights,
                    HYST_EVERETT_GRID_CELLS(HYST_EVERETT_GRID_MAX_INTERVALS), &m->nweights);
    } else if (m->kind == MODEL_TEXT_SPLINE) { /* values in coeffs' place, slopes in terms' */
        numbers_arg(prhs[4], "values", m->values, HYST_SPLINE_MAX_INTERVALS + 1u, &m->nvalues);
        numbers_arg(prhs[7], "slopes", m->slopes, HYST_SPLINE_MAX_INTERVALS + 1u, &m->nslopes);
    } else {
        numbers_arg(prhs[4], "coeffs", m->coeffs, HYST_MAX_DEGREE + 1u, &m->ncoef);
    }
    numbers_arg(prhs[8], "creep_tau", m->creep_tau, MODEL_TEXT_CREEP_MAX_TERMS, &m->ncreep);
    numbers_arg(prhs[9], "creep_weight", m->creep_weight, MODEL_TEXT_CREEP_MAX_TERMS,
                &m->ncreep_weights);
    if (identified != NULL && !mxIsEmpty(identified)) {
        if (!mxIsDouble(identified) || mxIsComplex(identified) ||
            mxGetNumberOfElements(identified) != 2u) {
            usage("identified must be [LO HI] or []");
        }
        m->has_identified = 1;
        m->id_lo = mxGetPr(identified)[0];
        m->id_hi = mxGetPr(identified)[1];
    }
    if (rate != NULL) { /* rate_tau, rate_weight: scalars, or both empty */
        model_arg_t r;
        memset(&r, 0, sizeof r);
        rate_arg(&r, rate[0], rate[1]);
        m->has_rate = r.has_rate;
        m->rate_tau = (double)r.rate_tau;
        m->rate_weight = (double)r.rate_weight;
    }
    if (model_text_check(m, msg, sizeof msg) != 0) {
        mexErrMsgIdAndTxt("hyst:usage", "%s: %s", caller, msg);
    }
}

static mxArray *row_of(const double *v, size_t n)
{
    mxArray *a = mxCreateDoubleMatrix(1, (mwSize)n, mxREAL);
    size_t i;
    for (i = 0u; i < n; ++i) {
        mxGetPr(a)[i] = v[i];
    }
    return a;
}

/* model_parse: prhs = the file's bytes (uint8 or char), its name; plhs = the
 * struct hyst_model_load returns, or hyst:model_file with the reader's
 * message. */
static void run_model_parse(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    static const char *poly[] = {"coeffs", "lo", "hi", "delay"};
    static const char *everett[] = {"kind", "lo", "hi", "y_lo", "degree", "terms", "delay"};
    static const char *grid[] = {"kind", "lo", "hi", "y_lo", "knots", "weights", "delay"};
    static const char *spline[] = {"kind", "lo", "hi", "values", "slopes", "delay"};
    model_text_t m;
    char msg[MODEL_TEXT_MSG_SIZE], *path, *text;
    size_t n, i;
    int rc;
    mxArray *s;
    if (nrhs != 2 || !mxIsChar(prhs[1]) || !(mxIsUint8(prhs[0]) || mxIsChar(prhs[0]))) {
        usage("model_parse takes the file's bytes (uint8) and its name");
    }
    n = mxGetNumberOfElements(prhs[0]);
    text = (char *)mxMalloc(n + 1u);
    for (i = 0u; i < n; ++i) { /* char is 16-bit in MATLAB: its low byte */
        text[i] = mxIsUint8(prhs[0]) ? (char)((const unsigned char *)mxGetData(prhs[0]))[i]
                                     : (char)((unsigned)((const mxChar *)mxGetData(prhs[0]))[i] & 0xFFu);
    }
    path = mxArrayToString(prhs[1]);
    rc = model_text_parse(text, n, path, &m, msg, sizeof msg);
    mxFree(text);
    mxFree(path);
    if (rc != 0) {
        mexErrMsgIdAndTxt("hyst:model_file", "%s", msg);
    }
    if (m.kind == MODEL_TEXT_SPLINE) {
        s = mxCreateStructMatrix(1, 1, 6, spline);
        set_field(s, "kind", mxCreateString("spline"));
        set_field(s, "values", row_of(m.values, m.nvalues));
        set_field(s, "slopes", row_of(m.slopes, m.nslopes));
    } else if (m.kind == MODEL_TEXT_GRID) {
        s = mxCreateStructMatrix(1, 1, 7, grid);
        set_field(s, "kind", mxCreateString("everett_grid"));
        set_field(s, "y_lo", mxCreateDoubleScalar(m.y_lo));
        set_field(s, "knots", row_of(m.knots, m.nknots));
        set_field(s, "weights", row_of(m.weights, m.nweights));
    } else if (m.kind == MODEL_TEXT_EVERETT) {
        s = mxCreateStructMatrix(1, 1, 7, everett);
        set_field(s, "kind", mxCreateString("everett"));
        set_field(s, "y_lo", mxCreateDoubleScalar(m.y_lo));
        set_field(s, "degree", mxCreateDoubleScalar((double)m.degree));
        set_field(s, "terms", row_of(m.terms, m.nterms));
    } else {
        s = mxCreateStructMatrix(1, 1, 4, poly);
        set_field(s, "coeffs", row_of(m.coeffs, m.ncoef));
    }
    set_field(s, "lo", mxCreateDoubleScalar(m.lo));
    set_field(s, "hi", mxCreateDoubleScalar(m.hi));
    set_field(s, "delay", mxCreateDoubleScalar(model_text_delay(&m)));
    if (m.has_identified) {
        const double range[2] = {m.id_lo, m.id_hi};
        (void)mxAddField(s, "identified");
        set_field(s, "identified", row_of(range, 2u));
    }
    if (m.ncreep > 0u) {
        (void)mxAddField(s, "creep_tau");
        (void)mxAddField(s, "creep_weight");
        set_field(s, "creep_tau", row_of(m.creep_tau, m.ncreep));
        set_field(s, "creep_weight", row_of(m.creep_weight, m.ncreep));
    }
    if (m.has_rate) {
        (void)mxAddField(s, "rate_tau");
        (void)mxAddField(s, "rate_weight");
        set_field(s, "rate_tau", mxCreateDoubleScalar(m.rate_tau));
        set_field(s, "rate_weight", mxCreateDoubleScalar(m.rate_weight));
    }
    plhs[0] = s;
}

/* header_table: prhs = name, the model's parts as header_open takes them,
 * intervals, rows; plhs = the compensator's table of the header, or the
 * library's refusal (hyst_header: ...). */
static void run_header_table(mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    model_text_t m;
    char name[256], *buf;
    size_t intervals, rows, size, len = 0u;
    hyst_status_t st = HYST_OK;
    if (nrhs != 13) {
        usage("header_table takes NAME, kind, lo, hi, delay, coeffs, degree, y_lo, terms, "
              "creep_tau, creep_weight, intervals, rows");
    }
    if (!mxIsChar(prhs[0]) || mxGetString(prhs[0], name, sizeof name) != 0 ||
        !model_text_identifier(name)) {
        usage("NAME must be a C identifier");
    }
    model_text_arg(&m, prhs + 1, NULL, NULL, "hyst_header");
    intervals = count(prhs[11], "intervals", 1.0, INTERVALS_MAX); /* before allocating */
    rows = m.kind == MODEL_TEXT_EVERETT ? count(prhs[12], "rows", ROWS_MIN, ROWS_MAX) : 0u;
    size = model_text_header_table_size(&m, rows, intervals);
    buf = (char *)mxMalloc(size + 1u);
    if (model_text_header_table(buf, size, &len, name, &m, rows, intervals, 0, &st) != 0) {
        mxFree(buf);
        if (st != HYST_OK) {
            fail_status("hyst_header", st);
        }
        usage("text too long");
    }
    buf[len] = '\0';
    plhs[0] = mxCreateString(buf);
    mxFree(buf);
}

/* model_write: prhs = kind, lo, hi, delay, coeffs, degree, y_lo, terms,
 * ctau, cweight; plhs = the file's text. header_open: prhs = name and the
 * same; plhs = the header's guard, declaration and creep term.
 * header_close: prhs = name. */
static void run_model_text(const char *cmd, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const int header = cmd[0] == 'h', close = strcmp(cmd, "header_close") == 0;
    model_text_t m;
    char name[256], *buf;
    const size_t size = 32768u;
    size_t len = 0u;
    int over;
    if (close ? nrhs != 1
              : header ? nrhs != 11 && nrhs != 13
                       : nrhs != 10 && nrhs != 11 && nrhs != 13) {
        usage("model_write takes kind, lo, hi, delay, coeffs, degree, y_lo, terms, creep_tau, "
              "creep_weight[, identified[, rate_tau, rate_weight]]; header_open NAME and the "
              "same but identified; header_close NAME");
    }
    if (header && (!mxIsChar(prhs[0]) || mxGetString(prhs[0], name, sizeof name) != 0 ||
                   !model_text_identifier(name))) {
        usage("NAME must be a C identifier");
    }
    if (!close) {
        model_text_arg(&m, prhs + (header ? 1 : 0), !header && nrhs >= 11 ? prhs[10] : NULL,
                       nrhs == 13 ? prhs + 11 : NULL, header ? "hyst_header" : "hyst_model_save");
    }
    buf = (char *)mxMalloc(size);
    if (close) {
        over = model_text_header_close(buf, size, &len, name);
    } else if (header) {
        over = model_text_header_open(buf, size, &len, name, &m);
    } else {
        len = model_text_write(&m, buf, size);
        over = len == 0u;
    }
    if (over) {
        mxFree(buf);
        usage("text too long");
    }
    buf[len] = '\0';
    plhs[0] = mxCreateString(buf);
    mxFree(buf);
}

/* The kind of a holdout command's model from the command's suffix: "" f0 0,
 * "_everett" 1, "_grid" 2, "_spline" 3 (run_holdout()); -1: none. */
static int holdout_kind(const char *suffix)
{
    static const char *const suffixes[] = {"", "_everett", "_grid", "_spline"};
    int i;
    for (i = 0; i < (int)(sizeof suffixes / sizeof suffixes[0]); ++i) {
        if (strcmp(suffix, suffixes[i]) == 0) {
            return i;
        }
    }
    return -1;
}

/* The commands mexFunction() dispatches on (for its usage messages). */
#define COMMANDS                                                                             \
    "version, status_str, config, sim, inv, sim_everett, inv_everett, sim_grid, inv_grid, "  \
    "sim_spline, inv_spline, inv_table, inv_table_everett, fit, fit_everett, fit_grid, "     \
    "fit_spline, poly_from_everett, creep, holdout, holdout_everett, holdout_grid, "         \
    "holdout_spline, given_delay, excitation, record_check, select, score, model_parse, "    \
    "model_write, header_open, header_close, header_table"

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    char cmd[24];
    if (nrhs < 1 || !mxIsChar(prhs[0]) || mxGetString(prhs[0], cmd, sizeof cmd) != 0) {
        usage("the first argument is a command: " COMMANDS);
    }
    if (strcmp(cmd, "version") == 0) {
        plhs[0] = mxCreateString(HYST_VERSION_STRING);
    } else if (strcmp(cmd, "status_str") == 0 && nrhs == 2) {
        const double code = scalar(prhs[1], "code");
        const int st = fabs(code) < 1000.0 ? (int)code : 1000;
        plhs[0] = mxCreateString(hyst_status_str(st));
        if (nlhs > 1) {
            plhs[1] = mxCreateString(status_name(st));
        }
    } else if (strcmp(cmd, "sim") == 0 || strcmp(cmd, "inv") == 0) {
        run_poly(cmd[0] == 'i', nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "sim_grid") == 0 || strcmp(cmd, "inv_grid") == 0 ||
               strcmp(cmd, "sim_spline") == 0 || strcmp(cmd, "inv_spline") == 0) {
        run_own(cmd[4] == 's', cmd[0] == 'i', nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "sim_everett") == 0 || strcmp(cmd, "inv_everett") == 0) {
        run_everett(cmd[0] == 'i', nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "inv_table") == 0 || strcmp(cmd, "inv_table_everett") == 0) {
        run_table(cmd[9] == '_', nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "config") == 0 && nrhs == 1) {
        run_config(plhs);
    } else if (strcmp(cmd, "fit") == 0) {
        run_fit(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "fit_grid") == 0) {
        run_fit_grid(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "fit_spline") == 0) {
        run_fit_spline(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "fit_everett") == 0) {
        run_fit_everett(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "poly_from_everett") == 0) {
        run_poly_from_everett(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "creep") == 0) {
        run_creep(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strncmp(cmd, "holdout", 7u) == 0 && holdout_kind(cmd + 7) >= 0) {
        run_holdout(holdout_kind(cmd + 7), nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "given_delay") == 0) {
        run_given_delay(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "excitation") == 0) {
        run_excitation(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "record_check") == 0) {
        run_record_check(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "select") == 0) {
        run_select(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "score") == 0) {
        run_score(nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "model_parse") == 0) {
        run_model_parse(plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "model_write") == 0 || strcmp(cmd, "header_open") == 0 ||
               strcmp(cmd, "header_close") == 0) {
        run_model_text(cmd, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "header_table") == 0) {
        run_header_table(plhs, nrhs - 1, prhs + 1);
    } else {
        usage("unknown command (" COMMANDS ")");
    }
}
