/* SPDX-License-Identifier: MIT */
/* hyst fit, the spline kind: the symmetric TCM whose f0 is a monotone cubic
 * spline on uniform knots, fitted by hyst_spline_fit_*() along every branch
 * of the record (minor loops included, where the polynomial f0's estimators
 * are biased), the model started from rest at the first sample used, as
 * 'hyst sim --model' runs it. */
#include "fit_select.h"

#include <math.h>
#include <stdlib.h>

/* Turning points the fit's workspace holds at first; doubled, and the fit
 * started again, when the record stacks more (one sample pushes one at most). */
#define FIT_SPLINE_CAP0 256u

/* f0 of k intervals on [lo, hi] fitted to x[i], y[i + delay], settle <= i <
 * end, the inputs from skip on taken in, into res->spline: HYST_OK or the
 * library's status; res->used and res->ls_rms. */
static hyst_status_t fit_samples(unsigned k, double lo, double hi, const double *x,
                                 const double *y, size_t skip, size_t settle, size_t end,
                                 size_t delay, fit_everett_result_t *res)
{
    size_t cap = FIT_SPLINE_CAP0;
    for (;;) {
        hyst_spline_fit_t fit;
        const size_t len = HYST_SPLINE_FIT_WORK(k, cap);
        double *work = (double *)malloc(len * sizeof(double));
        hyst_wide_t rms = 0;
        hyst_status_t st;
        size_t i;
        if (work == NULL) {
            return HYST_ERR_NOSPACE;
        }
        res->used = 0u;
        st = hyst_spline_fit_init(&fit, k, lo, hi, work, len);
        for (i = skip; i < end && st == HYST_OK; ++i) {
            /* HYST_ERR_DOMAIN: outside a given domain, ignored as the poly fit ignores it */
            const hyst_status_t add =
                hyst_spline_fit_add(&fit, x[i], i < settle ? (hyst_wide_t)NAN : y[i + delay]);
            st = add == HYST_ERR_NOSPACE ? add : st;
            res->used += add == HYST_OK ? 1u : 0u;
        }
        if (st == HYST_OK) {
            st = hyst_spline_fit_solve(&fit, &res->spline, &rms);
            res->ls_rms = (double)rms;
        }
        free(work);
        if (st != HYST_ERR_NOSPACE || cap > end - skip) {
            return st;
        }
        cap *= 2u;
    }
}

/* f0 fitted on [a, b] continued to cover [lo, hi] (lo <= a < b <= hi) by
 * whole knot intervals on either side, each a straight line at the slope
 * of f0's end there: monotone, and predicted beyond the inputs fitted
 * rather than held. HYST_ERR_DOMAIN when that needs more than
 * HYST_SPLINE_MAX_INTERVALS in all. */
static hyst_status_t continue_linearly(hyst_spline_t *f, double lo, double hi)
{
    const unsigned k = f->intervals;
    const double a = (double)f->lo, b = (double)f->hi, h = (b - a) / (double)k;
    const double below = lo < a ? ceil((a - lo) / h) : 0.0, above = hi > b ? ceil((hi - b) / h) : 0.0;
    hyst_spline_t out;
    unsigned i, e_lo, e_hi;
    if (!(below + above + (double)k <= (double)HYST_SPLINE_MAX_INTERVALS)) {
        return HYST_ERR_DOMAIN;
    }
    e_lo = (unsigned)below;
    e_hi = (unsigned)above;
    out = *f;
    out.intervals = k + e_lo + e_hi;
    out.lo = (hyst_wide_t)(a - (double)e_lo * h);
    out.hi = (hyst_wide_t)(b + (double)e_hi * h);
    for (i = 0u; i <= out.intervals; ++i) {
        const unsigned at = i < e_lo ? 0u : i - e_lo > k ? k : i - e_lo;
        const double steps = i < e_lo ? -(double)(e_lo - i) : i - e_lo > k ? (double)(i - e_lo - k) : 0.0;
        out.slope[i] = f->slope[at];
        out.value[i] = (hyst_wide_t)((double)f->value[at] + steps * h * (double)f->slope[at]);
    }
    *f = out;
    return HYST_OK;
}

hyst_status_t fit_spline_record(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                                const double *y, size_t n, fit_everett_result_t *res)
{
    double lo = 0.0, hi = 0.0, a, b;
    hyst_status_t st = fit_record_start(cfg, x, n, res, &lo, &hi);
    size_t end;
    res->determined = 1;
    if (st != HYST_OK || k < 1u || k > HYST_SPLINE_MAX_INTERVALS) {
        return HYST_ERR_ARG;
    }
    end = n - cfg->delay;
    /* the knots over the inputs fitted, within the domain; beyond them, to
     * the domain's ends, f0 continues as a straight line */
    fit_input_range(x, cfg->skip, end, 0.0, &a, &b);
    a = a > lo ? a : lo;
    b = b < hi ? b : hi;
    if (!(a < b)) {
        a = lo;
        b = hi;
    }
    /* HYST_ERR_DOMAIN from the fit: inputs that span no range */
    st = fit_samples(k, a, b, x, y, cfg->skip, fit_settled(x, cfg->skip, end), end, cfg->delay,
                     res);
    if ((st == HYST_OK || st == HYST_ERR_NOT_MONOTONE) && (lo < a || hi > b)) {
        const hyst_status_t wide = continue_linearly(&res->spline, lo, hi);
        st = wide != HYST_OK ? wide : st;
    }
    return fit_record_finish(FIT_SPLINE, cfg, x, y, n, st, res);
}
