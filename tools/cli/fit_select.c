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

/* Samples of the training part: the first two thirds of those the model sees. */
static size_t train_count(size_t n, size_t skip, size_t delay)
{
    return (2u * (n - skip - delay)) / 3u;
}

double fit_tcm_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                       size_t n, hyst_status_t *status, hyst_ident_result_t *fit)
{
    hyst_ident_t work;
    size_t train;
    if (n <= cfg->skip + cfg->delay) {
        *status = HYST_ERR_ARG;
        return NAN;
    }
    train = train_count(n, cfg->skip, cfg->delay);
    /* the training part: samples skip .. skip + train of x, their y delay later */
    *status = hyst_ident_fit(cfg, x, y, cfg->skip + train + cfg->delay, &work, fit);
    if (*status != HYST_OK || !fit->increasing) {
        return NAN;
    }
    return holdout_rms(fit, x, y, n, cfg->skip, cfg->delay, cfg->skip + train);
}

double fit_pi_holdout(const hyst_pi_fit_config_t *cfg, const double *x, const double *y,
                      size_t n, hyst_status_t *status, hyst_pi_fit_result_t *fit, double *r,
                      double *w)
{
    static double work[HYST_PI_FIT_WORK(HYST_PI_FIT_MAX_OPERATORS)];
    static double z[HYST_PI_FIT_MAX_OPERATORS];
    hyst_pi_t P;
    double ss = 0.0;
    size_t train, k, used = 0u;
    if (n <= cfg->skip + cfg->delay) {
        *status = HYST_ERR_ARG;
        return NAN;
    }
    train = train_count(n, cfg->skip, cfg->delay);
    *status = hyst_pi_fit_record(cfg, x, y, cfg->skip + train + cfg->delay, work,
                                 sizeof work / sizeof work[0], r, w, fit);
    /* hyst_pi_init() refuses w1 = 0 (a flat start of the loading curve) */
    if (*status != HYST_OK || hyst_f64_pi_init(&P, r, w, z, cfg->operators) != HYST_OK) {
        return NAN;
    }
    /* the model from reset at the first sample used, scored on the last third */
    for (k = cfg->skip; k + cfg->delay < n; ++k) {
        const double e = hyst_f64_pi_step(&P, x[k]) + (double)fit->offset - y[k + cfg->delay];
        if (k >= cfg->skip + train) {
            ss += e * e;
            ++used;
        }
    }
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

size_t fit_select(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                  size_t max_delay, fit_candidate_t *cand, size_t max_cand, size_t *best)
{
    size_t count = 0u, d;
    unsigned deg;
    *best = (size_t)-1;
    for (d = base->delay; d <= max_delay; ++d) {
        if (n <= base->skip + d) {
            break;
        }
        for (deg = 1u; deg <= HYST_MAX_DEGREE && count < max_cand; ++deg) {
            hyst_ident_config_t cfg = *base;
            fit_candidate_t *c = &cand[count];
            memset(c, 0, sizeof *c);
            cfg.degree = deg;
            cfg.delay = d;
            c->degree = deg;
            c->delay = d;
            c->holdout_rms = fit_tcm_holdout(&cfg, x, y, n, &c->status, &c->fit);
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
