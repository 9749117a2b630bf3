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
size_t fit_select(const hyst_ident_config_t *base, const double *x, const double *y, size_t n,
                  size_t max_delay, fit_candidate_t *cand, size_t max_cand, size_t *best);

#endif
