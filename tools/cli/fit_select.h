/* SPDX-License-Identifier: MIT */
/* Model selection for `hyst fit` without --degree (fit_select.c). */
#ifndef HYST_CLI_FIT_SELECT_H
#define HYST_CLI_FIT_SELECT_H

#include "hyst/hyst.h"

#include <stddef.h>

/* Delays tried when --delay is not given: 0 .. FIT_MAX_DELAY samples. */
#define FIT_MAX_DELAY 8u

/* A candidate within this fraction of the lowest hold-out error counts as
 * as good: the fewest parameters among them win. */
#define FIT_PARSIMONY 0.01

/* Kinds of model a candidate may be (a mask for fit_select()): the
 * symmetric TCM's polynomial f0 and the asymmetric kind's E. */
enum { FIT_POLY = 1, FIT_EVERETT = 2 };

/* fit_select(): every t-degree of each everett degree. */
#define FIT_ANY_T_DEGREE 99u

/* Everett candidates of each delay: (degree d, t-degree 0..d - 1), d = 1..4. */
#define FIT_EVERETT_CANDIDATES (HYST_EVERETT_MAX_DEGREE * (HYST_EVERETT_MAX_DEGREE + 1u) / 2u)

typedef struct fit_candidate {
    int kind;                 /* FIT_POLY or FIT_EVERETT */
    unsigned degree;
    unsigned t_degree;        /* everett: the highest power of t fitted (< degree) */
    size_t delay;
    hyst_status_t status;     /* of the training fit (everett: or of its curve) */
    hyst_ident_result_t fit;  /* poly: on the first two thirds */
    double fit_rms;           /* residual of the training fit (poly: fit.rms) */
    double holdout_rms;       /* model's RMS error on the last third; NaN: not scored */
} fit_candidate_t;

/* The asymmetric kind fitted on a record (fit_everett.c). */
typedef struct fit_everett_result {
    hyst_everett_t e;
    hyst_status_t curve_status; /* hyst_f64_curve_from_everett() of e */
    double rms, max_abs;        /* the model run over the samples fitted (NaN if refused) */
    double ls_rms;              /* the least-squares residual (hyst_everett_fit_solve()) */
    size_t used;                /* samples fitted */
} fit_everett_result_t;

/* Real numbers a model of this kind and degree identifies: poly the
 * degree + 1 coefficients, everett E's terms w^i t^j with j <= t_degree
 * and y_lo (t_degree ignored for poly). */
unsigned fit_parameters(int kind, unsigned degree, unsigned t_degree);

/* The TCM (f0, or when f0 is NULL the prepared curve) run from rest over
 * x[skip .. n - delay) against y[k + delay]: the RMS error over the samples
 * from index `from` on (returned; NaN if none, or if the model cannot run),
 * over those before it (*before_rms, may be NULL) and the largest error of
 * all (*max_abs, may be NULL). */
double fit_model_run(const hyst_poly_t *f0, const hyst_curve_t *curve, const double *x,
                     const double *y, size_t n, size_t skip, size_t delay, size_t from,
                     double *before_rms, double *max_abs);

/* The TCM of cfg (degree, delay, skip...) fitted on the first two thirds of
 * the record and run over all of it from rest: its RMS error on the last
 * third (NaN if the fit failed, *status, or f0 is not increasing). */
double fit_tcm_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                       size_t n, hyst_status_t *status, hyst_ident_result_t *fit);

/* E of degree cfg->degree, its terms w^i t^j with j <= t_degree, fitted to x[k] with y[k + delay], skip <= k <
 * n - delay (the model from rest at sample skip), on [cfg->lo, cfg->hi]
 * (samples outside ignored), or the range of those inputs when lo == hi;
 * then the curve checked and, if the library accepts it, the model run over
 * the same samples (res->rms, max_abs). HYST_OK, or the fit's status. */
hyst_status_t fit_everett_record(const hyst_ident_config_t *cfg, unsigned t_degree,
                                 const double *x, const double *y, size_t n,
                                 fit_everett_result_t *res);

/* fit_tcm_holdout() for the asymmetric kind: NaN if the fit failed or the
 * library refused E (*status says which). */
double fit_everett_holdout(const hyst_ident_config_t *cfg, unsigned t_degree, const double *x,
                           const double *y, size_t n, hyst_status_t *status,
                           fit_everett_result_t *fit);

/* The same for the PI model of cfg (operators, skip, delay; the thresholds
 * uniform over the training part's inputs unless given): r, w its N
 * thresholds and weights. NaN if the fit failed (*status) or its weights
 * have w1 = 0, which hyst_pi_init() refuses. */
double fit_pi_holdout(const hyst_pi_fit_config_t *cfg, const double *x, const double *y,
                      size_t n, hyst_status_t *status, hyst_pi_fit_result_t *fit, double *r,
                      double *w);

/* Fits each kind of the mask `kinds` (poly degree 1..HYST_MAX_DEGREE,
 * everett degree 1..HYST_EVERETT_MAX_DEGREE with each t-degree 0..degree - 1;
 * everett_degree, when not 0, the only everett degree, t_degree, when not
 * FIT_ANY_T_DEGREE, the only t-degree) at each delay from base->delay to
 * max_delay (base: method, domain, skip) into cand[0..max_cand); returns
 * the count, *best the index chosen: the fewest parameters within
 * FIT_PARSIMONY of the lowest hold-out RMS; between as many parameters the
 * symmetric kind (its compensator is a table, the asymmetric kind's solves),
 * then the lower RMS ((size_t)-1: none could be scored). */
size_t fit_select(const hyst_ident_config_t *base, int kinds, unsigned everett_degree,
                  unsigned t_degree, const double *x, const double *y, size_t n,
                  size_t max_delay, fit_candidate_t *cand, size_t max_cand, size_t *best);

#endif
