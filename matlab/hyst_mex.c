/* SPDX-License-Identifier: MIT */
/*
 * hyst_mex: the MEX gateway of the MATLAB/Octave wrappers (hyst_fit.m,
 * hyst_sim.m, hyst_inv.m): one entry point dispatching on a command string,
 * every number computed by the library's C code (docs/matlab.md).
 *
 *   v = hyst_mex('version')                      HYST_VERSION_STRING
 *   s = hyst_mex('status_str', code)             hyst_status_str(code)
 *   [y, st, ntp] = hyst_mex('sim', coeffs, lo, hi, x, capacity, deadband)
 *   [x, st, ntp] = hyst_mex('inv', coeffs, lo, hi, y, capacity, deadband)
 *   f = hyst_mex('fit', x, y, degree, method, lo, hi, skip, delay)
 *
 * sim/inv: x of class double runs hyst_f64_*, single runs hyst_f32_*; the
 * result has the class and the shape of x; st is the status of the block
 * call (0, or a warning: 1 clamped, 2 memory full; a non-finite sample gives
 * -7 and is ignored as in firmware), ntp the turning points stored at the end.
 * fit: method 1 joint, 2 reflect; lo == hi takes the domain from the data.
 * A negative status of an init or of the fit raises an error whose
 * identifier is hyst:<status name> (hyst:ERR_NOT_INCREASING) and whose
 * message holds hyst_status_str(); a bad argument raises hyst:usage.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "mex.h"

#include "hyst/hyst.h"

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

/* sim or inv over x: prhs = coeffs, lo, hi, x, capacity, deadband. */
static void run_tcm(int inverse, int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    const char *context = inverse ? "hyst_inv" : "hyst_sim";
    hyst_poly_t f0;
    hyst_tcm_t S;
    hyst_curve_t inv;
    const mxArray *x;
    mxArray *y;
    size_t n, cap;
    int st;
    if (nrhs != 6) {
        usage("sim/inv take coeffs, lo, hi, x, capacity, deadband");
    }
    f0 = poly_arg(prhs[0], prhs[1], prhs[2]);
    x = prhs[3];
    cap = count(prhs[4], "capacity", 1.0, 1e9);
    n = mxGetNumberOfElements(x);
    if (mxIsComplex(x) || mxIsSparse(x) || !(mxIsDouble(x) || mxIsSingle(x))) {
        usage("the input must be a real double or single array");
    }
    y = mxCreateNumericArray(mxGetNumberOfDimensions(x), mxGetDimensions(x), mxGetClassID(x),
                             mxREAL);
    if (mxIsDouble(x)) {
        double *tp = mxMalloc(4u * cap * sizeof *tp);
        st = inverse ? hyst_f64_init_inverse(&S, &inv, &f0, tp, tp + cap, tp + 2u * cap,
                                             tp + 3u * cap, cap)
                     : hyst_f64_init(&S, &f0, tp, tp + cap, tp + 2u * cap, tp + 3u * cap, cap);
        if (st == HYST_OK) {
            st = hyst_f64_set_deadband(&S, scalar(prhs[5], "deadband"));
        }
        if (st == HYST_OK && n > 0u) {
            st = hyst_f64_process(&S, (const double *)mxGetData(x), (double *)mxGetData(y), n);
        }
        if (st < 0 && st != HYST_ERR_NONFINITE) {
            mxFree(tp);
            mxDestroyArray(y);
            fail_status(context, st);
        }
        mxFree(tp);
    } else {
        float *tp = mxMalloc(4u * cap * sizeof *tp);
        st = inverse ? hyst_f32_init_inverse(&S, &inv, &f0, tp, tp + cap, tp + 2u * cap,
                                             tp + 3u * cap, cap)
                     : hyst_f32_init(&S, &f0, tp, tp + cap, tp + 2u * cap, tp + 3u * cap, cap);
        if (st == HYST_OK) {
            st = hyst_f32_set_deadband(&S, (float)scalar(prhs[5], "deadband"));
        }
        if (st == HYST_OK && n > 0u) {
            st = hyst_f32_process(&S, (const float *)mxGetData(x), (float *)mxGetData(y), n);
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
}

static void set_field(mxArray *s, const char *name, mxArray *v)
{
    mxSetField(s, 0, name, v);
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

void mexFunction(int nlhs, mxArray *plhs[], int nrhs, const mxArray *prhs[])
{
    char cmd[16];
    if (nrhs < 1 || !mxIsChar(prhs[0]) || mxGetString(prhs[0], cmd, sizeof cmd) != 0) {
        usage("the first argument is a command: version, status_str, sim, inv or fit");
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
        run_tcm(cmd[0] == 'i', nlhs, plhs, nrhs - 1, prhs + 1);
    } else if (strcmp(cmd, "fit") == 0) {
        run_fit(plhs, nrhs - 1, prhs + 1);
    } else {
        usage("unknown command (version, status_str, sim, inv, fit)");
    }
}
