/* SPDX-License-Identifier: MIT */
/* Identification of the spline kind's f0 (ident.h, hyst_spline_fit_*)
 * along every branch of the record, minor loops included. f0 = y_lo +
 * sum w_j I_j, I_j the integral from lo of the j-th quadratic B-spline on
 * the uniform knots: g(d) = f0(lo + d) - f0(lo) is linear in w, so the
 * symmetric model is a fit along the branches (hyst_branch_fit_t) with
 * E(a, b) = g(a - b), and w >= 0 makes f0 increasing. */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <string.h>

/* The integral from 0 to v of piece p (0..2) of the quadratic B-spline on
 * [0, 3], v clamped to [0, 1]: of v^2 / 2, (1 + 2v - 2v^2) / 2 and
 * (1 - v)^2 / 2, written without cancellation near 0 (1/6, 2/3, 1/6 whole). */
static hyst_wide_t bspline_piece_integral(unsigned p, hyst_wide_t v)
{
    if (!(v > 0)) {
        return 0;
    }
    v = v < 1 ? v : 1;
    if (p == 0u) {
        return v * v * v / 6;
    }
    if (p == 1u) {
        return v * (3 + v * (3 - 2 * v)) / 6;
    }
    return v * (3 - v * (3 - v)) / 6;
}

/* sign I_j at d knot intervals from lo (0 <= d <= K) added to r[j],
 * j = 0..K+1: B_j's pieces 0..2 lie on the intervals j - 2 .. j, those
 * below lo left out. */
static void ispline_add(unsigned intervals, hyst_wide_t d, hyst_wide_t sign, hyst_wide_t *r)
{
    unsigned j, p;
    for (j = 0u; j <= intervals + 1u; ++j) {
        hyst_wide_t sum = 0;
        for (p = 0u; p < 3u; ++p) {
            if (j + p >= 2u) {
                sum += bspline_piece_integral(p, d - (hyst_wide_t)(j + p - 2u));
            }
        }
        r[j] += sign * sum;
    }
}

/* Regressors of E(a, b) = g(a - b), a >= b, scaled by `sign`, added to r
 * after y_lo's column. */
static void spline_terms(const void *ctx, hyst_wide_t a, hyst_wide_t b, hyst_wide_t sign,
                         hyst_wide_t *r)
{
    const hyst_spline_fit_t *f = (const hyst_spline_fit_t *)ctx;
    const hyst_wide_t top = (hyst_wide_t)f->intervals, d = (a - b) * f->scale;
    ispline_add(f->intervals, d < top ? d : top, sign, r + 1); /* hi - lo may round past K */
}

hyst_status_t hyst_spline_fit_init(hyst_spline_fit_t *fit, unsigned intervals, hyst_wide_t lo,
                                   hyst_wide_t hi, hyst_wide_t *work, size_t work_len)
{
    hyst_wide_t scale;
    if (fit == NULL || work == NULL) {
        return HYST_ERR_NULL;
    }
    if (intervals < 1u || intervals > (unsigned)HYST_SPLINE_MAX_INTERVALS) {
        return HYST_ERR_DEGREE;
    }
    if (!hyst_wide_is_finite(lo) || !hyst_wide_is_finite(hi) || !(lo < hi) ||
        !hyst_wide_is_finite(hi - lo)) {
        return HYST_ERR_DOMAIN;
    }
    scale = (hyst_wide_t)intervals / (hi - lo);
    if (!hyst_wide_is_finite(scale)) {
        return HYST_ERR_DOMAIN; /* a span so small its reciprocal overflows */
    }
    if (work_len < HYST_SPLINE_FIT_WORK(intervals, 2u)) {
        return HYST_ERR_NOSPACE;
    }
    memset(fit, 0, sizeof *fit);
    fit->intervals = intervals;
    fit->scale = scale;
    hyst_branch_fit_start_(&fit->branch, HYST_SPLINE_FIT_COLS(intervals), lo, hi, work, work_len);
    return HYST_OK;
}

hyst_status_t hyst_spline_fit_add(hyst_spline_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    if (fit == NULL) {
        return HYST_ERR_NULL;
    }
    return hyst_branch_fit_add_(&fit->branch, x, y, spline_terms, fit);
}

/* f0(x_k) of the weights w and y_lo. */
static hyst_wide_t knot_value(unsigned intervals, const hyst_wide_t *w, hyst_wide_t y_lo,
                              unsigned k)
{
    hyst_wide_t row[HYST_SPLINE_MAX_INTERVALS + 2], rise = 0;
    unsigned j;
    memset(row, 0, sizeof row);
    ispline_add(intervals, (hyst_wide_t)k, 1, row);
    for (j = 0u; j <= intervals + 1u; ++j) {
        rise += w[j] * row[j];
    }
    return y_lo + rise; /* the offset last: the rises keep their precision */
}

/* f0'(x_k): at knot k only B_k and B_(k+1) are non-zero, 1/2 each. */
static hyst_wide_t knot_slope(const hyst_spline_fit_t *f, const hyst_wide_t *w, unsigned k)
{
    return (w[k] + w[k + 1u]) / 2 * f->scale;
}

hyst_status_t hyst_spline_fit_solve(const hyst_spline_fit_t *fit, hyst_spline_t *f0,
                                    hyst_wide_t *rms)
{
    const hyst_wide_t *w = NULL;
    hyst_wide_t y_lo = 0, rms_fit = 0;
    hyst_status_t st;
    unsigned n, k;
    if (fit == NULL || f0 == NULL || rms == NULL) {
        return HYST_ERR_NULL;
    }
    st = hyst_branch_fit_solve_(&fit->branch, &w, &y_lo, &rms_fit);
    if (st != HYST_OK && st != HYST_ERR_NOT_MONOTONE) {
        return st;
    }
    n = fit->intervals;
    for (k = 0u; k <= n; ++k) { /* checked first: f0 written whole or not at all */
        if (!hyst_wide_is_finite(knot_value(n, w, y_lo, k)) ||
            !hyst_wide_is_finite(knot_slope(fit, w, k))) {
            return HYST_ERR_COEFF;
        }
    }
    if (!(knot_value(n, w, y_lo, n) > knot_value(n, w, y_lo, 0u))) {
        st = HYST_ERR_NOT_MONOTONE; /* a rise below the values' rounding */
    }
    memset(f0, 0, sizeof *f0);
    f0->intervals = n;
    f0->lo = fit->branch.lo;
    f0->hi = fit->branch.hi;
    for (k = 0u; k <= n; ++k) {
        f0->value[k] = knot_value(n, w, y_lo, k);
        f0->slope[k] = knot_slope(fit, w, k);
    }
    *rms = rms_fit;
    return st;
}
