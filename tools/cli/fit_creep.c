/* SPDX-License-Identifier: MIT */
/* hyst fit, the creep term (hyst/creep.h): lags of the model's input fitted
 * to what the hysteresis model leaves (two stages: the model first, then the
 * creep on its residual), a time constant chosen from a 1-2-5 series by the
 * same hold-out as the model's degree and delay. */
#include "fit_select.h"

#include <math.h>
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
