/* SPDX-License-Identifier: MIT */
/* hyst fit, the creep term (hyst/creep.h): lags of the model's input fitted
 * to what the hysteresis model leaves (two stages: the model first, then the
 * creep on its residual), a time constant chosen from a 1-2-5 series by the
 * same hold-out as the model's degree and delay. */
#include "fit_select.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Time constants tried (samples) where none is given: those up to the run's
 * length (a longer lag is a ramp over the record, an offset's twin). */
static const double creep_taus[] = {100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0, 20000.0};

/* Time constants of the series: at most this many. */
#define CREEP_TAUS (sizeof creep_taus / sizeof creep_taus[0])

/* The creep lags' states (weight 1: a lag's output is its state) before
 * each input u[k], k < len, from rest at x_rest, for time constants
 * tau[0..count), count <= CREEP_TAUS, into s[i * len + k], by the library's
 * f64 instances themselves. The lags advance side by side: independent
 * chains, which the processor overlaps. 0, or 1 if a lag is refused. */
static int lag_states(const double *u, size_t len, double x_rest, const double *tau,
                      size_t count, double *s)
{
    const hyst_wide_t one = 1;
    hyst_creep_t C[CREEP_TAUS];
    size_t i, k;
    for (i = 0u; i < count; ++i) {
        const hyst_wide_t t = (hyst_wide_t)tau[i];
        if (hyst_f64_creep_init(&C[i], 1u, &t, &one, (hyst_wide_t)x_rest) != HYST_OK) {
            return 1;
        }
    }
    for (k = 0u; k < len; ++k) {
        for (i = 0u; i < count; ++i) {
            s[i * len + k] = hyst_f64_creep_step(&C[i], u[k]);
        }
    }
    return 0;
}

/* The regressors of sample k before its input, from rest at x_rest: the
 * creep lag's state into s when creep_tau > 0, the rate term's low-pass
 * (weight 1) into v when rate_tau > 0. 0, or 1 if refused. */
static int terms_regressors(const double *u, size_t len, double x_rest, double creep_tau,
                            double rate_tau, double *s, double *v)
{
    const hyst_wide_t one = 1;
    hyst_rate_t R;
    size_t k;
    if (creep_tau > 0 && lag_states(u, len, x_rest, &creep_tau, 1u, s) != 0) {
        return 1;
    }
    if (rate_tau > 0) {
        if (hyst_f64_rate_init(&R, (hyst_wide_t)rate_tau, one, (hyst_wide_t)x_rest) != HYST_OK) {
            return 1;
        }
        for (k = 0u; k < len; ++k) {
            v[k] = hyst_f64_rate_step(&R, u[k]);
        }
    }
    return 0;
}

/* The weights of the creep lag's state s and the rate term's low-pass v
 * (either may be NULL: no such term, weight 0) and the offset, by least
 * squares on the residual r outside [from, to), two passes (the means,
 * then the co-moments about them): 0, or 1 when they are not determined
 * (*fit_rms over the samples fitted). */
static int terms_solve(const double *s, const double *v, const double *r, size_t len,
                       size_t from, size_t to, double *ws_out, double *wv_out,
                       double *offset_out, double *fit_rms)
{
    const size_t terms = (s != NULL ? 1u : 0u) + (v != NULL ? 1u : 0u);
    double ms = 0.0, mv = 0.0, mr = 0.0, css = 0.0, csv = 0.0, cvv = 0.0, csr = 0.0;
    double cvr = 0.0, crr = 0.0, ws = 0.0, wv = 0.0, det, fit_ss;
    /* the equations: outside [from, to), residual known */
    const size_t begin[2] = {0u, to > from ? to : from}, end[2] = {from < len ? from : len, len};
    size_t k, used = 0u;
    int part;
    for (part = 0; part <= 1; ++part) {
        for (k = begin[part]; k < end[part]; ++k) {
            if (isfinite(r[k])) {
                ms += s != NULL ? s[k] : 0.0;
                mv += v != NULL ? v[k] : 0.0;
                mr += r[k];
                ++used;
            }
        }
    }
    if (terms == 0u || used <= terms + 1u) {
        return 1;
    }
    ms /= (double)used;
    mv /= (double)used;
    mr /= (double)used;
    for (part = 0; part <= 1; ++part) { /* co-moments about the means: the constant eliminated */
        for (k = begin[part]; k < end[part]; ++k) {
            if (isfinite(r[k])) {
                const double ds = s != NULL ? s[k] - ms : 0.0, dv = v != NULL ? v[k] - mv : 0.0;
                const double dr = r[k] - mr;
                css += ds * ds;
                csv += ds * dv;
                cvv += dv * dv;
                csr += ds * dr;
                cvr += dv * dr;
                crr += dr * dr;
            }
        }
    }
    /* A term that never moved, or moved by too little to tell from the
     * offset (its variance under 1e4 rounding units of its sum of squares),
     * or two terms indistinguishable, leave the weights undetermined. */
    if ((s != NULL && !(css > 1e4 * DBL_EPSILON * (css + (double)used * ms * ms))) ||
        (v != NULL && !(cvv > 0))) {
        return 1;
    }
    if (terms == 2u) {
        det = css * cvv - csv * csv;
        if (!(det > 1e-12 * css * cvv)) {
            return 1;
        }
        ws = (cvv * csr - csv * cvr) / det;
        wv = (css * cvr - csv * csr) / det;
    } else if (s != NULL) {
        ws = csr / css;
    } else {
        wv = cvr / cvv;
    }
    *ws_out = ws;
    *wv_out = wv;
    *offset_out = mr - ws * ms - wv * mv;
    fit_ss = crr - ws * csr - wv * cvr;
    *fit_rms = sqrt((fit_ss > 0 ? fit_ss : 0.0) / (double)used);
    return 0;
}

/* r[k] less the terms' prediction: what the model with its terms leaves. */
static double terms_error(const double *s, const double *v, const double *r, size_t k,
                          double ws, double wv, double offset)
{
    double e = r[k];
    if (s != NULL) {
        e -= ws * s[k];
    }
    if (v != NULL) {
        e -= wv * v[k];
    }
    return e - offset;
}

/* The terms with regressors s (creep lag of creep_tau) and v (rate term of
 * rate_tau), either NULL if absent, fitted and scored as fit_terms_part()
 * says, into *out. */
static void terms_score(const double *s, const double *v, const double *r, size_t len,
                        size_t from, size_t to, size_t score_from, double creep_tau,
                        double rate_tau, fit_creep_t *out)
{
    double ws, wv, offset, fit_rms, ss = 0.0, worst = 0.0;
    size_t k, scored = 0u;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    if (terms_solve(s, v, r, len, from, to, &ws, &wv, &offset, &fit_rms) != 0) {
        return;
    }
    for (k = 0u; k < len; ++k) {
        const double e = terms_error(s, v, r, k, ws, wv, offset);
        if (isfinite(e)) {
            worst = fabs(e) > worst ? fabs(e) : worst;
            if (k >= from && k < to && k >= score_from) {
                ss += e * e;
                ++scored;
            }
        }
    }
    out->tau = s != NULL ? creep_tau : 0.0;
    out->weight = ws;
    out->rate_tau = v != NULL ? rate_tau : 0.0;
    out->rate_weight = wv;
    out->offset = offset;
    out->fit_rms = fit_rms;
    out->max_abs = worst;
    out->holdout_rms = scored > 0u ? sqrt(ss / (double)scored) : NAN;
}

void fit_terms_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                    size_t score_from, double x_rest, double creep_tau, double rate_tau,
                    fit_creep_t *out)
{
    const int lag = creep_tau > 0, rate = rate_tau > 0;
    double *s;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    if ((!lag && !rate) || (rate && !(rate_tau >= 1.0)) || len == 0u ||
        (s = (double *)malloc(2u * len * sizeof(double))) == NULL) {
        return;
    }
    if (terms_regressors(u, len, x_rest, creep_tau, rate_tau, s, s + len) == 0) {
        terms_score(lag ? s : NULL, rate ? s + len : NULL, r, len, from, to, score_from,
                    creep_tau, rate_tau, out);
    }
    free(s);
}

/* The states of creep_taus[0..count) over u[0..len) from rest at x_rest:
 * a run lags keeps of the same inputs from the same rest, or computed, and
 * kept in lags (may be NULL) in place of the run used longest ago while the
 * runs fit in FIT_LAG_BYTES, else into *owned (the caller's to free). NULL
 * when out of memory or a lag is refused. */
static const double *series_states(fit_lags_t *lags, const double *u, size_t len, double x_rest,
                                   size_t count, double **owned)
{
    fit_lag_run_t *run = NULL;
    double *s, *copy;
    size_t i;
    *owned = NULL;
    for (i = 0u; lags != NULL && i < FIT_LAG_RUNS; ++i) {
        fit_lag_run_t *r = &lags->run[i];
        if (r->u != NULL && r->len == len && r->x_rest == x_rest &&
            memcmp(r->u, u, len * sizeof *u) == 0) {
            r->used = ++lags->clock;
            return r->s;
        }
        run = run == NULL || r->used < run->used ? r : run;
    }
    if ((s = (double *)malloc(count * len * sizeof(double))) == NULL ||
        lag_states(u, len, x_rest, creep_taus, count, s) != 0) {
        free(s);
        return NULL;
    }
    if (run == NULL || (count + 1u) * len * sizeof(double) > FIT_LAG_BYTES / FIT_LAG_RUNS ||
        (copy = (double *)malloc(len * sizeof *u)) == NULL) {
        *owned = s;
        return s;
    }
    free(run->u);
    free(run->s);
    memcpy(copy, u, len * sizeof *u);
    run->u = copy;
    run->s = s;
    run->len = len;
    run->x_rest = x_rest;
    run->used = ++lags->clock;
    return s;
}

void fit_lags_free(fit_lags_t *lags)
{
    size_t i;
    for (i = 0u; i < FIT_LAG_RUNS; ++i) {
        free(lags->run[i].u);
        free(lags->run[i].s);
    }
    memset(lags, 0, sizeof *lags);
}

void fit_creep_score_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                          size_t score_from, double x_rest, double tau, fit_lags_t *lags,
                          fit_creep_t *best)
{
    size_t i, count = 0u;
    const double *s;
    double *owned;
    if (tau > 0) {
        fit_terms_part(u, r, len, from, to, score_from, x_rest, tau, 0.0, best);
        return;
    }
    memset(best, 0, sizeof *best);
    best->holdout_rms = NAN;
    best->fit_rms = NAN;
    while (count < CREEP_TAUS && creep_taus[count] <= (double)len) {
        ++count;
    }
    if (count == 0u || (s = series_states(lags, u, len, x_rest, count, &owned)) == NULL) {
        return;
    }
    for (i = 0u; i < count; ++i) {
        fit_creep_t c;
        terms_score(s + i * len, NULL, r, len, from, to, score_from, creep_taus[i], 0.0, &c);
        if (isfinite(c.holdout_rms) && !(best->holdout_rms <= c.holdout_rms)) {
            *best = c;
        }
    }
    free(owned);
}

void fit_creep_score(const double *u, const double *r, size_t len, size_t train, double x_rest,
                     double tau, fit_creep_t *best)
{
    fit_creep_score_part(u, r, len, train, len, train, x_rest, tau, NULL, best);
}

/* The RMS of what the terms leave of r2 over its finite entries, their
 * regressors run over u2 from rest (NaN if none or out of memory). */
static double terms_other_rms(const double *u2, const double *r2, size_t len2, double x_rest,
                              double creep_tau, double rate_tau, double ws, double wv,
                              double offset)
{
    double *s, *v, ss = 0.0;
    size_t k, used = 0u;
    if (len2 == 0u || (s = (double *)malloc(2u * len2 * sizeof(double))) == NULL) {
        return NAN;
    }
    v = s + len2;
    if (terms_regressors(u2, len2, x_rest, creep_tau, rate_tau, s, v) != 0) {
        free(s);
        return NAN;
    }
    for (k = 0u; k < len2; ++k) {
        const double e = terms_error(creep_tau > 0 ? s : NULL, rate_tau > 0 ? v : NULL, r2, k,
                                     ws, wv, offset);
        if (isfinite(e)) {
            ss += e * e;
            ++used;
        }
    }
    free(s);
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

/* The terms fitted on the whole of r (as the model file's are: [len, len)
 * held out), scored on r2. */
static void terms_other(const double *u, const double *r, size_t len, const double *u2,
                        const double *r2, size_t len2, double x_rest, double creep_tau,
                        double rate_tau, fit_creep_t *out)
{
    fit_terms_part(u, r, len, len, len, len, x_rest, creep_tau, rate_tau, out);
    if (isfinite(out->fit_rms)) {
        out->holdout_rms = terms_other_rms(u2, r2, len2, x_rest, creep_tau, rate_tau,
                                           out->weight, out->rate_weight, out->offset);
    }
}

void fit_terms_other(const double *u, const double *r, size_t len, const double *u2,
                     const double *r2, size_t len2, double x_rest, double creep_tau,
                     double rate_tau, fit_creep_t *out)
{
    size_t i;
    if (rate_tau > 0 || creep_tau > 0) {
        terms_other(u, r, len, u2, r2, len2, x_rest, creep_tau, rate_tau, out);
        return;
    }
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    for (i = 0u; i < sizeof creep_taus / sizeof creep_taus[0] && creep_taus[i] <= (double)len;
         ++i) {
        fit_creep_t c;
        terms_other(u, r, len, u2, r2, len2, x_rest, creep_taus[i], 0.0, &c);
        if (isfinite(c.holdout_rms) && !(out->holdout_rms <= c.holdout_rms)) {
            *out = c;
        }
    }
}

size_t fit_rate_taus(const double *x, size_t from, size_t to, double *taus)
{
    static const double fractions[FIT_RATE_TAUS] = {0.0, 1.0 / 256.0, 1.0 / 64.0};
    double lo, hi, period;
    size_t reversals, inner, i, count = 0u;
    if (to <= from + 1u) {
        return 0u;
    }
    fit_input_range(x, from, to, 0.0, &lo, &hi);
    reversals = fit_reversals(x, from, to, lo, hi, &inner);
    period = reversals > 0u ? 2.0 * (double)(to - from) / (double)reversals : 0.0;
    for (i = 0u; i < FIT_RATE_TAUS; ++i) { /* 1, then fractions of the period above it */
        const double tau = i == 0u ? 1.0 : floor(fractions[i] * period + 0.5);
        if (tau >= 1.0 && (count == 0u || tau > taus[count - 1u])) {
            taus[count++] = tau;
        }
    }
    return count;
}

int fit_rate_search(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                    const fit_validation_t *v, const fit_candidate_t *chosen, int with_creep,
                    double rate_tau, fit_candidate_t *out)
{
    const double without = fit_option_rms(chosen, with_creep);
    double taus[FIT_RATE_TAUS], lowest = NAN;
    const size_t count = rate_tau > 0   ? 1u
                         : rate_tau < 0 ? 0u
                                        : fit_rate_taus(x, base->skip, n, taus);
    size_t i;
    int found = 0;
    taus[0] = rate_tau > 0 ? rate_tau : taus[0];
    *out = *chosen;
    memset(&out->creep, 0, sizeof out->creep);
    out->creep.holdout_rms = NAN;
    for (i = 0u; i < count && isfinite(without); ++i) {
        fit_candidate_t trial = *chosen;
        memset(&trial.creep, 0, sizeof trial.creep);
        trial.creep.rate_tau = taus[i];
        fit_score(base, x, y, n, v, with_creep ? chosen->creep.tau : 0.0, &trial);
        if (isfinite(trial.creep.holdout_rms) && trial.creep.rate_tau > 0 &&
            !(lowest <= trial.creep.holdout_rms)) {
            lowest = trial.creep.holdout_rms;
            *out = trial;
            found = 1;
        }
    }
    /* kept when it helps: the model without it errs by more than FIT_PARSIMONY over it */
    return found && (rate_tau > 0 || without > lowest * (1.0 + FIT_PARSIMONY));
}
