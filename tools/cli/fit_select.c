/* SPDX-License-Identifier: MIT */
/* hyst fit without --degree: degree and delay chosen by hold-out. Each
 * candidate (degree, delay) is fitted on the first two thirds of the record,
 * then the model (the TCM in double, with that f0 and that delay) runs over
 * the whole record and is scored by its RMS prediction error on the last
 * third, which the fit never saw: a degree that fits noise predicts worse
 * there, so the criterion does not reward it. Of the candidates within
 * FIT_PARSIMONY of the lowest error, the one with the fewest parameters is
 * chosen: a gain below that is not worth a coefficient. */
#include "fit_select.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* RMS error of the TCM with f0 = r over x[skip..n-delay), scored on the
 * samples from `from` on (indices into x), against y[k + delay]. NaN if the
 * model cannot run (memory, or f0 refused). */
static double holdout_rms(const hyst_ident_result_t *r, const double *x, const double *y,
                          size_t n, size_t skip, size_t delay, size_t from)
{
    hyst_poly_t f0;
    hyst_tcm_t S;
    const size_t cap = (n - delay - skip) / 2u + 2u;
    double *mem, ss = 0.0;
    size_t k, used = 0u;
    unsigned i;
    f0.degree = r->degree;
    f0.lo = (double)r->lo;
    f0.hi = (double)r->hi;
    for (i = 0u; i <= r->degree; ++i) {
        f0.coeffs[i] = (double)r->coeffs[i];
    }
    if ((mem = (double *)malloc(4u * cap * sizeof(double))) == NULL) {
        return NAN;
    }
    if (hyst_f64_init(&S, &f0, mem, mem + cap, mem + 2u * cap, mem + 3u * cap, cap) != HYST_OK) {
        free(mem);
        return NAN;
    }
    for (k = skip; k + delay < n; ++k) {
        const double ym = hyst_f64_step(&S, x[k]);
        if (k >= from && isfinite(x[k]) && isfinite(y[k + delay])) {
            const double e = ym - y[k + delay];
            ss += e * e;
            ++used;
        }
    }
    free(mem);
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

size_t fit_select(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                  size_t max_delay, fit_candidate_t *cand, size_t max_cand, size_t *best)
{
    size_t count = 0u, d;
    unsigned deg;
    *best = (size_t)-1;
    for (d = base->delay; d <= max_delay; ++d) {
        size_t m, train;
        if (n <= base->skip + d) {
            break;
        }
        m = n - base->skip - d;
        train = (2u * m) / 3u;
        for (deg = 1u; deg <= HYST_MAX_DEGREE && count < max_cand; ++deg) {
            hyst_ident_config_t cfg = *base;
            hyst_ident_t work;
            fit_candidate_t *c = &cand[count];
            memset(c, 0, sizeof *c);
            cfg.degree = deg;
            cfg.delay = d;
            c->degree = deg;
            c->delay = d;
            c->holdout_rms = NAN;
            /* the training part: samples skip .. skip + train of x, their y d later */
            c->status = hyst_ident_fit(&cfg, x, y, base->skip + train + d, &work, &c->fit);
            if (c->status == HYST_OK && c->fit.increasing) {
                c->holdout_rms =
                    holdout_rms(&c->fit, x, y, n, base->skip, d, base->skip + train);
            }
            if (isfinite(c->holdout_rms) &&
                (*best == (size_t)-1 || c->holdout_rms < cand[*best].holdout_rms)) {
                *best = count;
            }
            ++count;
        }
    }
    if (*best != (size_t)-1) { /* parsimony: the fewest parameters within 1 % of the best */
        const double limit = cand[*best].holdout_rms * (1.0 + FIT_PARSIMONY);
        size_t i;
        for (i = 0u; i < count; ++i) {
            const fit_candidate_t *c = &cand[i], *b = &cand[*best];
            if (isfinite(c->holdout_rms) && c->holdout_rms <= limit &&
                (c->degree < b->degree ||
                 (c->degree == b->degree && c->holdout_rms < b->holdout_rms))) {
                *best = i;
            }
        }
    }
    return count;
}
