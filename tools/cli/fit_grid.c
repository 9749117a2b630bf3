/* SPDX-License-Identifier: MIT */
/* hyst fit, the asymmetric kind on a grid: knots at the quantiles of the
 * inputs weighted by the output's steps (hyst_everett_grid_knots()), then
 * each inner knot moved in turn to where the fit's residual is least, on
 * the record thinned to at most FIT_GRID_REFINE_SAMPLES samples; the cells'
 * masses by hyst_everett_grid_fit_*() on the whole of it; the model started
 * from rest at the first sample used, as 'hyst sim --model' runs it. */
#include "fit_select.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Samples the knots are refined on at most (every s-th of the record). */
#define FIT_GRID_REFINE_SAMPLES 3000u
/* Passes over the inner knots, and the places tried for each, between its
 * neighbours. */
#define FIT_GRID_PASSES 3u
#define FIT_GRID_PLACES 10u
/* Bins of the output steps' weights (the knots' resolution). */
#define FIT_GRID_BINS 1024u
/* Turning points the fit's workspace holds at first (doubled as needed). */
#define FIT_GRID_CAP0 256u

const char fit_grid_undetermined[] =
    "the record's turning points do not determine every mass of this grid (major loops alone "
    "leave how the inner cells of 4 or more intervals share theirs open): of the many masses "
    "that fit the record alike and predict differently where it did not go (minor loops, a "
    "branch it did not take), these are the least squared ones; fewer intervals, or a record "
    "whose reversals turn inside every interval";

typedef struct {
    const double *x, *y;
    size_t skip, settle, end, delay, stride; /* outputs fitted from settle on (fit_settled()) */
    double *work;
    size_t work_len;
} grid_data_t;

/* The fit of every stride-th sample on the knots into *g: its residual
 * RMS, or NaN (HYST_ERR_NOSPACE: more turning points than the workspace). */
static double fit_on(const grid_data_t *d, const double *knots, unsigned k, hyst_everett_grid_t *g,
                     hyst_status_t *status, size_t *used, int *determined)
{
    hyst_everett_grid_fit_t fit;
    hyst_wide_t rms = 0;
    size_t i;
    *status = hyst_everett_grid_fit_init(&fit, knots, k, d->work, d->work_len);
    *used = 0u;
    for (i = d->skip; i < d->end && *status == HYST_OK; i += d->stride) {
        const hyst_status_t add = hyst_everett_grid_fit_add(
            &fit, d->x[i], i < d->settle ? (hyst_wide_t)NAN : d->y[i + d->delay]);
        if (add == HYST_ERR_NOSPACE) {
            *status = add;
        }
        *used += add == HYST_OK ? 1u : 0u;
    }
    if (*status == HYST_OK && determined != NULL) {
        *determined = hyst_everett_grid_fit_determined(&fit);
    }
    if (*status == HYST_OK) {
        *status = hyst_everett_grid_fit_solve(&fit, g, &rms);
    }
    return *status == HYST_OK ? (double)rms : NAN;
}

hyst_status_t fit_grid_record(const hyst_ident_config_t *cfg, unsigned k, const double *x,
                              const double *y, size_t n, fit_everett_result_t *res)
{
    static double bins[FIT_GRID_BINS];
    static double table[HYST_EVERETT_GRID_TABLE_LEN(HYST_EVERETT_GRID_MAX_INTERVALS)];
    double lo = (double)cfg->lo, hi = (double)cfg->hi, knots[HYST_EVERETT_GRID_MAX_INTERVALS + 1];
    size_t cap = FIT_GRID_CAP0, i;
    grid_data_t d;
    hyst_curve_t curve;
    hyst_status_t st = HYST_OK;
    memset(res, 0, sizeof *res);
    res->rms = NAN;
    res->max_abs = NAN;
    res->curve_status = HYST_ERR_ARG;
    if (n <= cfg->skip + cfg->delay || k < 1u || k > HYST_EVERETT_GRID_MAX_INTERVALS) {
        return HYST_ERR_ARG;
    }
    d.x = x;
    d.y = y;
    d.skip = cfg->skip;
    d.delay = cfg->delay;
    d.end = n - cfg->delay;
    d.settle = fit_settled(x, d.skip, d.end);
    if (!(lo < hi)) {
        fit_input_range(x, d.skip, d.end, 0.0, &lo, &hi);
    }
    if (!(lo < hi)) {
        return HYST_ERR_DOMAIN;
    }
    /* the knots from the output's steps over the samples fitted */
    st = hyst_everett_grid_knots(x + d.skip, y + d.skip + d.delay, d.end - d.skip, lo, hi, k,
                                 knots, bins, FIT_GRID_BINS);
    if (st != HYST_OK) {
        return st;
    }
    for (;;) {
        double best;
        unsigned pass, m, c;
        d.work_len = HYST_EVERETT_GRID_FIT_WORK(k, cap);
        d.work = (double *)malloc(d.work_len * sizeof(double));
        if (d.work == NULL) {
            return HYST_ERR_NOSPACE;
        }
        d.stride = (d.end - d.skip + FIT_GRID_REFINE_SAMPLES - 1u) / FIT_GRID_REFINE_SAMPLES;
        best = fit_on(&d, knots, k, &res->grid, &st, &res->used, NULL);
        for (pass = 0u; pass < FIT_GRID_PASSES && st == HYST_OK; ++pass) {
            for (m = 1u; m < k && st == HYST_OK; ++m) {
                double place = knots[m];
                for (c = 1u; c <= FIT_GRID_PLACES; ++c) {
                    const double keep = knots[m];
                    double e;
                    knots[m] = knots[m - 1u] +
                               (knots[m + 1u] - knots[m - 1u]) * c / (FIT_GRID_PLACES + 1u);
                    e = fit_on(&d, knots, k, &res->grid, &st, &res->used, NULL);
                    knots[m] = keep;
                    if (st != HYST_OK) {
                        break;
                    }
                    if (e < best) {
                        best = e;
                        place = knots[m - 1u] +
                                (knots[m + 1u] - knots[m - 1u]) * c / (FIT_GRID_PLACES + 1u);
                    }
                }
                knots[m] = place;
            }
        }
        if (st == HYST_OK) { /* the masses on every sample */
            d.stride = 1u;
            res->ls_rms = fit_on(&d, knots, k, &res->grid, &st, &res->used, &res->determined);
        }
        free(d.work);
        if (st != HYST_ERR_NOSPACE || cap > d.end - d.skip) {
            break;
        }
        cap *= 2u;
    }
    /* HYST_ERR_NOT_MONOTONE: every mass 0; the curve's refusal says why */
    if (st != HYST_OK && st != HYST_ERR_NOT_MONOTONE) {
        return st;
    }
    res->curve_status = hyst_f64_curve_from_everett_grid(&curve, &res->grid, table,
                                                         sizeof table / sizeof table[0]);
    if (res->curve_status == HYST_OK) {
        (void)fit_model_run(NULL, &curve, x, y, n, cfg->skip, cfg->delay, d.end, &res->rms,
                            &res->max_abs);
    }
    for (i = 0u; i <= k; ++i) { /* the knots as fitted (exact: the grid's) */
        res->grid.knots[i] = knots[i];
    }
    return HYST_OK;
}
