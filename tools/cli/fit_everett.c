/* SPDX-License-Identifier: MIT */
/* hyst fit, the asymmetric kind: E fitted by hyst_everett_fit_*() over a
 * record, the model started from rest at the first sample used, as
 * 'hyst sim --model' runs it. */
#include "fit_select.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Turning points the fit's workspace holds at first; doubled, and the fit
 * started again, when the record stacks more (one sample pushes one at most). */
#define EVERETT_FIT_CAP0 64u

/* E (its terms w^i t^j with j <= t_degree) fitted to x[k], y[k + delay],
 * settle <= k < end, on [lo, hi], into *e, the inputs from skip on taken
 * in (the model from rest at skip, as sim runs it: before settle its state
 * is not the record's, fit_settled()): HYST_OK or the library's status;
 * *used the samples in the fit, *ls_rms its least-squares residual. */
static hyst_status_t fit_samples(unsigned degree, unsigned t_degree, double lo, double hi,
                                 const double *x, const double *y, size_t skip, size_t settle,
                                 size_t end, size_t delay, hyst_everett_t *e, size_t *used,
                                 double *ls_rms)
{
    size_t cap = EVERETT_FIT_CAP0;
    for (;;) {
        hyst_everett_fit_t fit;
        const size_t len = HYST_EVERETT_FIT_WORK(cap);
        double *work = (double *)malloc(len * sizeof(double));
        hyst_status_t st;
        size_t k;
        if (work == NULL) {
            return HYST_ERR_NOSPACE;
        }
        *used = 0u;
        st = hyst_everett_fit_init_terms(&fit, degree, t_degree, lo, hi, work, len);
        for (k = skip; k < end && st == HYST_OK; ++k) {
            const hyst_status_t add =
                hyst_everett_fit_add(&fit, x[k], k < settle ? (hyst_wide_t)NAN : y[k + delay]);
            /* HYST_ERR_DOMAIN: outside a given domain, ignored as the poly fit ignores it */
            if (add == HYST_ERR_NOSPACE) {
                st = add;
            }
            *used += add == HYST_OK ? 1u : 0u;
        }
        if (st == HYST_OK) {
            hyst_wide_t rms = 0;
            st = hyst_everett_fit_solve(&fit, e, &rms);
            *ls_rms = (double)rms;
        }
        free(work);
        if (st != HYST_ERR_NOSPACE || cap > end - skip) {
            return st;
        }
        cap *= 2u;
    }
}

hyst_status_t fit_everett_add_clamped(hyst_everett_fit_t *fit, const double *x, const double *y,
                                      size_t n, double lo, double hi, size_t *used)
{
    const size_t settle = fit_settled(x, 0u, n);
    size_t i;
    *used = 0u;
    for (i = 0u; i < n; ++i) {
        const double xi = x[i] < lo ? lo : (x[i] > hi ? hi : x[i]); /* NaN stays NaN */
        const hyst_status_t st = hyst_everett_fit_add(fit, xi, i < settle ? (double)NAN : y[i]);
        if (st == HYST_ERR_NOSPACE) {
            return st;
        }
        *used += st == HYST_OK ? 1u : 0u;
    }
    return HYST_OK;
}

hyst_status_t fit_everett_record(const hyst_ident_config_t *cfg, unsigned t_degree,
                                 const double *x, const double *y, size_t n,
                                 fit_everett_result_t *res)
{
    double lo = 0.0, hi = 0.0;
    hyst_status_t st = fit_record_start(cfg, x, n, res, &lo, &hi);
    size_t end;
    if (st != HYST_OK) {
        return st;
    }
    end = n - cfg->delay;
    st = fit_samples(cfg->degree, t_degree, lo, hi, x, y, cfg->skip, fit_settled(x, cfg->skip, end),
                     end, cfg->delay, &res->e, &res->used, &res->ls_rms);
    return fit_record_finish(FIT_EVERETT, cfg, x, y, n, st, res);
}

/* y_lo + sum e[i-1][0] u^i at x, u = (x - lo) / (hi - lo): E of the width alone from lo. */
static double everett_width_eval(const hyst_everett_t *e, double x)
{
    const double u = (x - (double)e->lo) / ((double)e->hi - (double)e->lo);
    double s = 0.0;
    unsigned i;
    for (i = e->degree; i >= 1u; --i) {
        s = (s + (double)e->e[i - 1u][0]) * u;
    }
    return (double)e->y_lo + s;
}

int fit_poly_from_everett(const hyst_everett_t *e, hyst_poly_t *f0)
{
    /* c[k]: the coefficient of x^k, lowest first while expanding */
    double c[HYST_EVERETT_MAX_DEGREE + 1u];
    const double a = 1.0 / ((double)e->hi - (double)e->lo), b = -(double)e->lo * a;
    double span, worst = 0.0;
    hyst_poly_t p;
    unsigned i, j, k;
    if (e->degree < 1u || e->degree > HYST_EVERETT_MAX_DEGREE ||
        !((double)e->lo < (double)e->hi)) {
        return 0;
    }
    for (i = 1u; i <= e->degree; ++i) {
        for (j = 1u; i + j <= e->degree; ++j) {
            if (e->e[i - 1u][j] != 0) {
                return 0; /* a term of t: the branches depend on where they start */
            }
        }
    }
    /* Horner in u = a x + b, each step multiplying the polynomial in x by it */
    memset(c, 0, sizeof c);
    for (i = e->degree; i >= 1u; --i) {
        c[0] += (double)e->e[i - 1u][0];
        for (k = e->degree - i + 1u; k >= 1u; --k) {
            c[k] = c[k] * b + c[k - 1u] * a;
        }
        c[0] *= b;
    }
    c[0] += (double)e->y_lo;
    memset(&p, 0, sizeof p);
    p.degree = e->degree;
    p.lo = e->lo;
    p.hi = e->hi;
    for (k = 0u; k <= e->degree; ++k) {
        p.coeffs[e->degree - k] = (hyst_wide_t)c[k];
    }
    /* the powers of x may cancel (a domain far from 0): kept only where they
     * give E's values, and an increasing f0 */
    span = fabs(everett_width_eval(e, (double)e->hi) - everett_width_eval(e, (double)e->lo));
    for (k = 0u; k <= FIT_POLY_CHECK_POINTS; ++k) {
        const double x = (double)e->lo + ((double)e->hi - (double)e->lo) * (double)k /
                                             (double)FIT_POLY_CHECK_POINTS;
        const double d =
            fabs((double)hyst_poly_eval(&p, (hyst_wide_t)x) - everett_width_eval(e, x));
        worst = d > worst || isnan(d) ? d : worst;
    }
    if (!(worst <= FIT_POLY_AGREEMENT * span) ||
        !hyst_poly_is_increasing(p.coeffs, p.degree, p.lo, p.hi, NULL)) {
        return 0;
    }
    *f0 = p;
    return 1;
}
