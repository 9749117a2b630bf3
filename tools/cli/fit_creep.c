/* SPDX-License-Identifier: MIT */
/* hyst fit, the creep term (hyst/creep.h): lags of the model's input fitted
 * to what the hysteresis model leaves (two stages: the model first, then the
 * creep on its residual), a time constant chosen from a 1-2-5 series by the
 * same hold-out as the model's degree and delay. */
#include "fit_select.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Time constants tried (samples) where none is given: those up to the run's
 * length (a longer lag is a ramp over the record, an offset's twin). */
static const double creep_taus[] = {100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0, 20000.0};

/* One time constant: weight and offset from the equations of [0, train),
 * scored on [train, len) (NaN when train == len: no hold-out). */
static void creep_one(const double *u, const double *r, size_t len, size_t train, double x_rest,
                      double tau, fit_creep_t *out)
{
    const hyst_wide_t t = (hyst_wide_t)tau;
    hyst_creep_holdout_t h;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    if (hyst_creep_fit_holdout(1u, &t, (hyst_wide_t)x_rest, u, r, len, train, &h) != HYST_OK) {
        return;
    }
    out->tau = tau;
    out->weight = (double)h.weight[0];
    out->offset = (double)h.offset;
    out->fit_rms = (double)h.fit_rms;
    out->max_abs = (double)h.max_abs;
    out->holdout_rms = h.holdout_used > 0u ? (double)h.holdout_rms : NAN;
}

void fit_creep_score(const double *u, const double *r, size_t len, size_t train, double x_rest,
                     double tau, fit_creep_t *best)
{
    size_t i;
    memset(best, 0, sizeof *best);
    best->holdout_rms = NAN;
    best->fit_rms = NAN;
    if (tau > 0) {
        creep_one(u, r, len, train, x_rest, tau, best);
        return;
    }
    for (i = 0u; i < sizeof creep_taus / sizeof creep_taus[0] && creep_taus[i] <= (double)len;
         ++i) {
        fit_creep_t c;
        creep_one(u, r, len, train, x_rest, creep_taus[i], &c);
        if (isfinite(c.holdout_rms) && !(best->holdout_rms <= c.holdout_rms)) {
            *best = c;
        }
    }
}

/* One time constant fitted on [0, len) but [from, to) (the lags fed
 * through it) and scored on [from, to) from score_from on, the creep run
 * from rest. */
static void creep_one_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                           size_t score_from, double x_rest, double tau, fit_creep_t *out)
{
    const hyst_wide_t t = (hyst_wide_t)tau;
    hyst_creep_fit_t F;
    hyst_creep_t C;
    hyst_wide_t w, offset, fit_rms;
    double ss = 0.0, worst = 0.0;
    size_t k, used = 0u;
    hyst_status_t st;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    st = hyst_creep_fit_init(&F, 1u, &t, (hyst_wide_t)x_rest);
    for (k = 0u; st == HYST_OK && k < len; ++k) {
        st = (k < from || k >= to) && isfinite(r[k]) ? hyst_creep_fit_add(&F, u[k], r[k])
                                                     : hyst_creep_fit_feed(&F, u[k]);
    }
    if (st != HYST_OK || hyst_creep_fit_solve(&F, &w, &offset, &fit_rms) != HYST_OK ||
        hyst_f64_creep_init(&C, 1u, &t, &w, (hyst_wide_t)x_rest) != HYST_OK) {
        return;
    }
    for (k = 0u; k < len; ++k) {
        const double e = r[k] - hyst_f64_creep_step(&C, u[k]) - (double)offset;
        if (isfinite(e)) {
            worst = fabs(e) > worst ? fabs(e) : worst;
            if (k >= from && k < to && k >= score_from) {
                ss += e * e;
                ++used;
            }
        }
    }
    out->tau = tau;
    out->weight = (double)w;
    out->offset = (double)offset;
    out->fit_rms = (double)fit_rms;
    out->max_abs = worst;
    out->holdout_rms = used > 0u ? sqrt(ss / (double)used) : NAN;
}

void fit_creep_score_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                          size_t score_from, double x_rest, double tau, fit_creep_t *best)
{
    size_t i;
    memset(best, 0, sizeof *best);
    best->holdout_rms = NAN;
    best->fit_rms = NAN;
    if (tau > 0) {
        creep_one_part(u, r, len, from, to, score_from, x_rest, tau, best);
        return;
    }
    for (i = 0u; i < sizeof creep_taus / sizeof creep_taus[0] && creep_taus[i] <= (double)len;
         ++i) {
        fit_creep_t c;
        creep_one_part(u, r, len, from, to, score_from, x_rest, creep_taus[i], &c);
        if (isfinite(c.holdout_rms) && !(best->holdout_rms <= c.holdout_rms)) {
            *best = c;
        }
    }
}

/* ---- The rate term (hyst/rate.h), fitted with the creep lag ---- */

/* The regressors of sample k before its input: the creep lag's state
 * (weight 1: its output is the state) and the rate term's low-pass (weight
 * 1), from rest at x_rest, by the library's f64 instances themselves. */
static int terms_regressors(const double *u, size_t len, double x_rest, double creep_tau,
                            double rate_tau, double *s, double *v)
{
    const hyst_wide_t one = 1, t = (hyst_wide_t)creep_tau;
    hyst_creep_t C;
    hyst_rate_t R;
    size_t k;
    if ((creep_tau > 0 && hyst_f64_creep_init(&C, 1u, &t, &one, (hyst_wide_t)x_rest) != HYST_OK) ||
        hyst_f64_rate_init(&R, (hyst_wide_t)rate_tau, one, (hyst_wide_t)x_rest) != HYST_OK) {
        return 1;
    }
    for (k = 0u; k < len; ++k) {
        s[k] = creep_tau > 0 ? hyst_f64_creep_step(&C, u[k]) : 0.0;
        v[k] = hyst_f64_rate_step(&R, u[k]);
    }
    return 0;
}

/* The weights of the creep lag's state s (when lag) and the rate term's
 * low-pass v, and the offset, by least squares on the residual r outside
 * [from, to): 0, or 1 when they are not determined (*fit_rms over the
 * samples fitted). */
static int terms_solve(const double *s, const double *v, const double *r, size_t len,
                       size_t from, size_t to, int lag, double *ws_out, double *wv_out,
                       double *offset_out, double *fit_rms)
{
    double ms = 0.0, mv = 0.0, mr = 0.0, css = 0.0, csv = 0.0, cvv = 0.0, csr = 0.0;
    double cvr = 0.0, crr = 0.0, ws = 0.0, wv, det, fit_ss;
    size_t k, used = 0u;
    for (k = 0u; k < len; ++k) { /* the equations: outside [from, to), residual known */
        if ((k < from || k >= to) && isfinite(r[k])) {
            ms += s[k];
            mv += v[k];
            mr += r[k];
            ++used;
        }
    }
    if (used <= (lag ? 3u : 2u)) {
        return 1;
    }
    ms /= (double)used;
    mv /= (double)used;
    mr /= (double)used;
    for (k = 0u; k < len; ++k) { /* co-moments about the means: the constant eliminated */
        if ((k < from || k >= to) && isfinite(r[k])) {
            const double ds = s[k] - ms, dv = v[k] - mv, dr = r[k] - mr;
            css += ds * ds;
            csv += ds * dv;
            cvv += dv * dv;
            csr += ds * dr;
            cvr += dv * dr;
            crr += dr * dr;
        }
    }
    det = css * cvv - csv * csv;
    if (!(cvv > 0) || (lag && !(det > 1e-12 * css * cvv))) {
        return 1; /* a drive that never moved, or the two indistinguishable */
    }
    if (lag) {
        ws = (cvv * csr - csv * cvr) / det;
        wv = (css * cvr - csv * csr) / det;
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

void fit_terms_part(const double *u, const double *r, size_t len, size_t from, size_t to,
                    size_t score_from, double x_rest, double creep_tau, double rate_tau,
                    fit_creep_t *out)
{
    const int lag = creep_tau > 0;
    double *s, *v, ws, wv, offset, fit_rms, ss = 0.0, worst = 0.0;
    size_t k, scored = 0u;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    if (!(rate_tau >= 1.0) || len == 0u ||
        (s = (double *)malloc(2u * len * sizeof(double))) == NULL) {
        return;
    }
    v = s + len;
    if (terms_regressors(u, len, x_rest, creep_tau, rate_tau, s, v) != 0 ||
        terms_solve(s, v, r, len, from, to, lag, &ws, &wv, &offset, &fit_rms) != 0) {
        free(s);
        return;
    }
    for (k = 0u; k < len; ++k) {
        const double e = r[k] - ws * s[k] - wv * v[k] - offset;
        if (isfinite(e)) {
            worst = fabs(e) > worst ? fabs(e) : worst;
            if (k >= from && k < to && k >= score_from) {
                ss += e * e;
                ++scored;
            }
        }
    }
    free(s);
    out->tau = lag ? creep_tau : 0.0;
    out->weight = ws;
    out->rate_tau = rate_tau;
    out->rate_weight = wv;
    out->offset = offset;
    out->fit_rms = fit_rms;
    out->max_abs = worst;
    out->holdout_rms = scored > 0u ? sqrt(ss / (double)scored) : NAN;
}

/* The RMS of r2 - ws s - wv v - offset over r2's finite entries, s and v
 * the terms' regressors of u2 from rest (NaN if none or out of memory). */
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
        const double e = r2[k] - ws * s[k] - wv * v[k] - offset;
        if (isfinite(e)) {
            ss += e * e;
            ++used;
        }
    }
    free(s);
    return used > 0u ? sqrt(ss / (double)used) : NAN;
}

/* One creep time constant fitted on the whole of r (as the model file's
 * term is: fit_creep_score() with no hold-out), scored on r2. */
static void creep_other(const double *u, const double *r, size_t len, const double *u2,
                        const double *r2, size_t len2, double x_rest, double tau,
                        fit_creep_t *out)
{
    creep_one(u, r, len, len, x_rest, tau, out);
    if (out->tau > 0) {
        out->holdout_rms =
            terms_other_rms(u2, r2, len2, x_rest, tau, 1.0, out->weight, 0.0, out->offset);
    }
}

void fit_terms_other(const double *u, const double *r, size_t len, const double *u2,
                     const double *r2, size_t len2, double x_rest, double creep_tau,
                     double rate_tau, fit_creep_t *out)
{
    size_t i;
    memset(out, 0, sizeof *out);
    out->holdout_rms = NAN;
    out->fit_rms = NAN;
    if (rate_tau > 0) { /* fitted on every sample of r: [len, len) held out */
        fit_terms_part(u, r, len, len, len, len, x_rest, creep_tau, rate_tau, out);
        if (isfinite(out->fit_rms)) {
            out->holdout_rms = terms_other_rms(u2, r2, len2, x_rest, creep_tau, rate_tau,
                                               out->weight, out->rate_weight, out->offset);
        }
        return;
    }
    if (creep_tau > 0) {
        creep_other(u, r, len, u2, r2, len2, x_rest, creep_tau, out);
        return;
    }
    for (i = 0u; i < sizeof creep_taus / sizeof creep_taus[0] && creep_taus[i] <= (double)len;
         ++i) {
        fit_creep_t c;
        creep_other(u, r, len, u2, r2, len2, x_rest, creep_taus[i], &c);
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
