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

/* f0 fitted on [lo, b] continued to cover [lo, hi] (b < hi) by whole knot
 * intervals above b, a straight line at f0's slope at b: every branch's
 * shape g(d) = f0(lo + d) - f0(lo) is the fitted one up to the longest
 * branch the record takes (b - lo), and continues monotone beyond it, so
 * that inputs beyond the range identified on are predicted rather than
 * held. Below the inputs nothing is added: the knots start at lo, where the
 * model rests, as the fit's turning points do. HYST_ERR_DOMAIN when that
 * needs more than HYST_SPLINE_MAX_INTERVALS in all. */
static hyst_status_t continue_linearly(hyst_spline_t *f, double hi)
{
    const unsigned k = f->intervals;
    const double b = (double)f->hi, h = (b - (double)f->lo) / (double)k;
    const double above = ceil((hi - b) / h);
    unsigned i;
    if (!(above + (double)k <= (double)HYST_SPLINE_MAX_INTERVALS)) {
        return HYST_ERR_DOMAIN;
    }
    f->intervals = k + (unsigned)above;
    f->hi = (hyst_wide_t)(b + above * h);
    for (i = k + 1u; i <= f->intervals; ++i) {
        f->slope[i] = f->slope[k];
        f->value[i] = (hyst_wide_t)((double)f->value[k] + (double)(i - k) * h * (double)f->slope[k]);
    }
    return HYST_OK;
}

hyst_status_t fit_spline_record(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                                const double *y, size_t n, fit_everett_result_t *res)
{
    double lo = 0.0, hi = 0.0, least, b;
    hyst_status_t st = fit_record_start(cfg, x, n, res, &lo, &hi);
    size_t end;
    res->determined = 1;
    if (st != HYST_OK || k < 1u || k > HYST_SPLINE_MAX_INTERVALS) {
        return HYST_ERR_ARG;
    }
    end = n - cfg->delay;
    /* the knots from lo to the largest input fitted (within the domain);
     * above it, to hi, f0 continues as a straight line */
    fit_input_range(x, cfg->skip, end, 0.0, &least, &b); /* least: lo's side stays lo */
    b = b < hi ? b : hi;
    if (!(lo < b)) {
        b = hi;
    }
    /* HYST_ERR_DOMAIN from the fit: inputs that span no range */
    st = fit_samples(k, lo, b, x, y, cfg->skip, fit_settled(x, cfg->skip, end), end, cfg->delay,
                     res);
    if ((st == HYST_OK || st == HYST_ERR_NOT_MONOTONE) && hi > b) {
        const hyst_status_t wide = continue_linearly(&res->spline, hi);
        st = wide != HYST_OK ? wide : st;
    }
    return fit_record_finish(FIT_SPLINE, cfg, x, y, n, st, res);
}
