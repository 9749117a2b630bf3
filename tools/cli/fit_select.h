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

typedef struct fit_candidate {
    unsigned degree;
    size_t delay;
    hyst_status_t status;     /* of the training fit */
    hyst_ident_result_t fit;  /* on the first two thirds */
    double holdout_rms;       /* model's RMS error on the last third; NaN: not scored */
} fit_candidate_t;

/* Fits degree 1..HYST_MAX_DEGREE for each delay from base->delay to
 * max_delay (base: method, domain, skip) into cand[0..max_cand); returns
 * the count, *best the index chosen: the fewest parameters within
 * FIT_PARSIMONY of the lowest hold-out RMS ((size_t)-1: none could be
 * scored: no increasing f0). */
/* The TCM of cfg (degree, delay, skip...) fitted on the first two thirds of
 * the record and run over all of it from rest: its RMS error on the last
 * third (NaN if the fit failed, *status, or f0 is not increasing). */
double fit_tcm_holdout(const hyst_ident_config_t *cfg, const double *x, const double *y,
                       size_t n, hyst_status_t *status, hyst_ident_result_t *fit);

/* The same for the PI model of cfg (operators, skip, delay; the thresholds
 * uniform over the training part's inputs unless given): r, w its N
 * thresholds and weights. NaN if the fit failed (*status) or its weights
 * have w1 = 0, which hyst_pi_init() refuses. */
double fit_pi_holdout(const hyst_pi_fit_config_t *cfg, const double *x, const double *y,
                      size_t n, hyst_status_t *status, hyst_pi_fit_result_t *fit, double *r,
                      double *w);

size_t fit_select(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                  size_t max_delay, fit_candidate_t *cand, size_t max_cand, size_t *best);

#endif
