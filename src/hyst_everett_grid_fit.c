/* SPDX-License-Identifier: MIT */
/* Identification of the asymmetric kind on a grid (ident.h,
 * hyst_everett_grid_fit_*): Madelung's rules run on the recorded inputs by
 * the turning-point stack the polynomial E's uses (hyst_tp_step_); a
 * sample's row is the current TP's plus or minus the share of each cell
 * inside the triangle of E between them. The normal equations and the
 * masses by non-negative least squares with y_lo eliminated: the fits
 * along the branches' (hyst_branch_fit_t). */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <string.h>

/* Column of cell (i, j), j <= i: after y_lo's. */
static size_t cell_col(unsigned i, unsigned j) { return 1u + (size_t)i * (i + 1u) / 2u + j; }

/* Regressors of E(a, b), a >= b, scaled by `sign`, added to r: each cell's
 * share inside the triangle, the product of its two intervals' shares of
 * [b, a] (a cell on the diagonal: that share squared). */
static void grid_terms(const void *ctx, hyst_wide_t a, hyst_wide_t b, hyst_wide_t sign,
                       hyst_wide_t *r)
{
    const hyst_everett_grid_fit_t *f = (const hyst_everett_grid_fit_t *)ctx;
    hyst_wide_t share[HYST_EVERETT_GRID_MAX_INTERVALS];
    unsigned i, j, first = f->intervals, last = 0u;
    memset(share, 0, sizeof share);
    for (i = 0u; i < f->intervals; ++i) {
        const hyst_wide_t lo = f->knots[i] > b ? f->knots[i] : b;
        const hyst_wide_t hi = f->knots[i + 1u] < a ? f->knots[i + 1u] : a;
        share[i] = hi > lo ? (hi - lo) / (f->knots[i + 1u] - f->knots[i]) : 0;
        if (share[i] > 0) {
            first = i < first ? i : first;
            last = i;
        }
    }
    for (i = first; i <= last && first < f->intervals; ++i) {
        const hyst_wide_t si = sign * share[i];
        for (j = first; j <= i; ++j) {
            r[cell_col(i, j)] += si * share[j];
        }
    }
}

hyst_status_t hyst_everett_grid_fit_init(hyst_everett_grid_fit_t *fit, const hyst_wide_t *knots,
                                         unsigned intervals, hyst_wide_t *work, size_t work_len)
{
    unsigned i;
    if (fit == NULL || knots == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (intervals < 1u || intervals > (unsigned)HYST_EVERETT_GRID_MAX_INTERVALS) {
        return HYST_ERR_DEGREE;
    }
    for (i = 0u; i <= intervals; ++i) {
        if (!hyst_wide_is_finite(knots[i]) || (i > 0u && !(knots[i] > knots[i - 1u])) ||
            !hyst_wide_is_finite(knots[i] - knots[0])) {
            return HYST_ERR_BREAKPOINTS;
        }
    }
    if (work_len < HYST_EVERETT_GRID_FIT_WORK(intervals, 2u)) {
        return HYST_ERR_NOSPACE;
    }
    memset(fit, 0, sizeof *fit);
    fit->intervals = intervals;
    for (i = 0u; i <= intervals; ++i) {
        fit->knots[i] = knots[i];
    }
    hyst_branch_fit_start_(&fit->branch, HYST_EVERETT_GRID_FIT_COLS(intervals), knots[0],
                           knots[intervals], work, work_len);
    return HYST_OK;
}

hyst_status_t hyst_everett_grid_fit_add(hyst_everett_grid_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    if (fit == NULL) {
        return HYST_ERR_NULL;
    }
    return hyst_branch_fit_add_(&fit->branch, x, y, grid_terms, fit);
}

int hyst_everett_grid_fit_determined(const hyst_everett_grid_fit_t *fit)
{
    return fit != NULL && hyst_branch_fit_determined_(&fit->branch);
}

hyst_status_t hyst_everett_grid_fit_solve(const hyst_everett_grid_fit_t *fit,
                                          hyst_everett_grid_t *g, hyst_wide_t *rms)
{
    const hyst_wide_t *w = NULL;
    hyst_wide_t y_lo = 0, rms_fit = 0;
    hyst_status_t st;
    size_t i;
    if (fit == NULL || g == NULL || rms == NULL) {
        return HYST_ERR_NULL;
    }
    st = hyst_branch_fit_solve_(&fit->branch, &w, &y_lo, &rms_fit);
    if (st != HYST_OK && st != HYST_ERR_NOT_MONOTONE) {
        return st;
    }
    memset(g, 0, sizeof *g);
    g->intervals = fit->intervals;
    for (i = 0u; i <= fit->intervals; ++i) {
        g->knots[i] = fit->knots[i];
    }
    for (i = 0u; i + 1u < fit->branch.cols; ++i) {
        g->weight[i] = w[i];
    }
    g->y_lo = y_lo;
    *rms = rms_fit;
    return st;
}

hyst_status_t hyst_everett_grid_knots(const hyst_wide_t *x, const hyst_wide_t *y, size_t n,
                                      hyst_wide_t lo, hyst_wide_t hi, unsigned intervals,
                                      hyst_wide_t *knots, hyst_wide_t *work, size_t work_len)
{
    const hyst_wide_t span = hi - lo;
    hyst_wide_t out[HYST_EVERETT_GRID_MAX_INTERVALS + 1];
    hyst_wide_t total = 0, cum = 0, gap, most = 0;
    size_t k, bin = 0u;
    unsigned q;
    if (x == NULL || y == NULL || knots == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (intervals < 1u || intervals > (unsigned)HYST_EVERETT_GRID_MAX_INTERVALS) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(lo) || !hyst_wide_is_finite(hi) || !(lo < hi) ||
        !hyst_wide_is_finite(span)) {
        return HYST_ERR_DOMAIN;
    }
    if (work_len < 16u) {
        return HYST_ERR_NOSPACE;
    }
    memset(work, 0, work_len * sizeof *work);
    /* the steps relative to the largest: their sum cannot overflow */
    for (k = 1u; k < n; ++k) {
        const hyst_wide_t dy = hyst_wide_abs(y[k] - y[k - 1u]);
        most = hyst_wide_is_finite(dy) && dy > most ? dy : most;
    }
    for (k = 1u; k < n; ++k) {
        const hyst_wide_t mid = (x[k] + x[k - 1u]) / 2, dy = hyst_wide_abs(y[k] - y[k - 1u]);
        hyst_wide_t at;
        if (!hyst_wide_is_finite(mid) || !hyst_wide_is_finite(dy) || !(most > 0)) {
            continue;
        }
        at = (mid - lo) / span * (hyst_wide_t)work_len;
        bin = at <= 0 ? 0u : at >= (hyst_wide_t)work_len ? work_len - 1u : (size_t)at;
        work[bin] += dy / most;
        total += dy / most;
    }
    out[0] = lo;
    out[intervals] = hi;
    bin = 0u;
    for (q = 1u; q < intervals; ++q) {
        const hyst_wide_t target = total * (hyst_wide_t)q / (hyst_wide_t)intervals;
        if (!(total > 0)) {
            out[q] = lo + span * (hyst_wide_t)q / (hyst_wide_t)intervals;
            continue;
        }
        while (bin + 1u < work_len && cum + work[bin] < target) {
            cum += work[bin++];
        }
        out[q] = lo + span * ((hyst_wide_t)bin +
                              (work[bin] > 0 ? (target - cum) / work[bin] : 0)) /
                          (hyst_wide_t)work_len;
    }
    /* at least gap apart: pushed up from lo, then down from hi */
    gap = span / (hyst_wide_t)(16u * intervals);
    for (q = 1u; q < intervals; ++q) {
        out[q] = out[q] < out[q - 1u] + gap ? out[q - 1u] + gap : out[q];
    }
    for (q = intervals - 1u; q >= 1u; --q) {
        out[q] = out[q] > out[q + 1u] - gap ? out[q + 1u] - gap : out[q];
    }
    /* a domain too narrow for the type to hold the knots gap apart */
    for (q = 1u; q <= intervals; ++q) {
        if (!(out[q] > out[q - 1u])) {
            return HYST_ERR_DOMAIN;
        }
    }
    for (q = 0u; q <= intervals; ++q) {
        knots[q] = out[q];
    }
    return HYST_OK;
}
