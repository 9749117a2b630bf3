/* SPDX-License-Identifier: MIT */
/* Identification of the asymmetric kind on a grid (ident.h,
 * hyst_everett_grid_fit_*): Madelung's rules run on the recorded inputs by
 * the turning-point stack the polynomial E's uses (hyst_tp_step_); a
 * sample's row is the current TP's plus or minus the share of each cell
 * inside the triangle of E between them. Normal equations in hyst_wide_t; the masses by the
 * library's non-negative least squares (hyst_nnls_t) with y_lo eliminated. */
#include "hyst/ident.h"

#include "hyst_util.h"

#include <math.h>
#include <string.h>

/* Column of cell (i, j), j <= i: after y_lo's. */
static size_t cell_col(unsigned i, unsigned j) { return 1u + (size_t)i * (i + 1u) / 2u + j; }

/* Regressors of E(a, b), a >= b, scaled by `sign`, added to r: each cell's
 * share inside the triangle, the product of its two intervals' shares of
 * [b, a] (a cell on the diagonal: that share squared). */
static void add_terms(const hyst_everett_grid_fit_t *f, hyst_wide_t a, hyst_wide_t b,
                      hyst_wide_t sign, hyst_wide_t *r)
{
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
    size_t cols;
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
    cols = HYST_EVERETT_GRID_FIT_COLS(intervals);
    fit->cols = cols;
    /* fixed parts first, the TPs in the rest */
    fit->ata = work;
    fit->solver = fit->ata + cols * cols;
    fit->aty = fit->solver + 2u * cols * cols + 7u * cols;
    fit->r_prev = fit->aty + cols;
    fit->capacity = (work_len - (size_t)(fit->r_prev + cols - work)) / (cols + 1u);
    fit->tp_x = fit->r_prev + cols;
    fit->tp_r = fit->tp_x + fit->capacity;
    memset(work, 0, (size_t)(fit->tp_x - work) * sizeof *work);
    hyst_tp_start_(fit->tp_x, fit->tp_r, cols, fit->r_prev, knots[0]);
    fit->n_tp = 1u;
    fit->x_prev = knots[0];
    return HYST_OK;
}

hyst_status_t hyst_everett_grid_fit_add(hyst_everett_grid_fit_t *fit, hyst_wide_t x, hyst_wide_t y)
{
    const hyst_wide_t *r;
    size_t i, j, cols;
    if (fit == NULL) {
        return HYST_ERR_NULL;
    }
    if (!hyst_wide_is_finite(x)) {
        return HYST_ERR_NONFINITE;
    }
    if (x < fit->knots[0] || x > fit->knots[fit->intervals]) {
        return HYST_ERR_DOMAIN;
    }
    if (x > fit->x_prev || x < fit->x_prev) {
        hyst_wide_t a, b;
        const int sign = hyst_tp_step_(fit->tp_x, fit->tp_r, &fit->n_tp, fit->capacity,
                                       fit->cols, fit->r_prev, fit->x_prev, x, &a, &b);
        if (sign == 0) {
            return HYST_ERR_NOSPACE;
        }
        add_terms(fit, a, b, (hyst_wide_t)sign, fit->r_prev);
        fit->x_prev = x;
    }
    if (!hyst_wide_is_finite(y)) {
        return HYST_ERR_NONFINITE;
    }
    if (fit->used == 0u) {
        fit->y_ref = y;
    }
    y -= fit->y_ref;
    r = fit->r_prev;
    cols = fit->cols;
    for (i = 0u; i < cols; ++i) {
        if (r[i] != 0) { /* most cells are 0 on a branch: skip their rows */
            for (j = 0u; j <= i; ++j) {
                fit->ata[i * cols + j] += r[i] * r[j];
            }
            fit->aty[i] += r[i] * y;
        }
    }
    fit->yy += y * y;
    ++fit->used;
    return HYST_OK;
}

/* The masses' normal equations with y_lo eliminated into h (m x m, m the
 * cells) and c (m): H = A'A - s s' / n over the cells, s their sums; the
 * largest diagonal entry returned. */
static hyst_wide_t centre(const hyst_everett_grid_fit_t *fit, hyst_wide_t *h, hyst_wide_t *c)
{
    const size_t cols = fit->cols, m = cols - 1u;
    const hyst_wide_t n = (hyst_wide_t)fit->used;
    hyst_wide_t big = 0;
    size_t i, j;
    for (i = 0u; i < m; ++i) {
        const hyst_wide_t si = fit->ata[(i + 1u) * cols];
        for (j = 0u; j <= i; ++j) {
            const hyst_wide_t v = fit->ata[(i + 1u) * cols + j + 1u] - si * fit->ata[(j + 1u) * cols] / n;
            h[i * m + j] = v;
            h[j * m + i] = v;
        }
        c[i] = fit->aty[i + 1u] - si * fit->aty[0] / n;
        big = h[i * m + i] > big ? h[i * m + i] : big;
    }
    return big;
}

int hyst_everett_grid_fit_determined(const hyst_everett_grid_fit_t *fit)
{
    size_t m, i, j, k;
    hyst_wide_t *h, *l;
    if (fit == NULL || fit->used < 2u) {
        return 0;
    }
    m = fit->cols - 1u;
    h = fit->solver;
    l = h + m * m + m; /* the factor where the solve keeps its weights and the rest */
    (void)centre(fit, h, h + m * m);
    for (i = 0u; i < m; ++i) { /* h = L L', each pivot above its diagonal's rounding */
        for (j = 0u; j <= i; ++j) {
            hyst_wide_t sum = h[i * m + j];
            for (k = 0u; k < j; ++k) {
                sum -= l[i * m + k] * l[j * m + k];
            }
            if (i > j) {
                l[i * m + j] = sum / l[j * m + j];
            } else if (sum > h[i * m + i] * HYST_WIDE_EPS * (hyst_wide_t)1e4) {
                l[i * m + i] = HYST_WIDE_SQRT(sum);
            } else {
                return 0; /* a cell's column in the span of the others' */
            }
        }
    }
    return 1;
}

/* The centred Gram (the solver's first cells^2 numbers) for the NNLS. */
typedef struct {
    const hyst_wide_t *h;
    size_t m;
} centred_t;

static hyst_wide_t centred_gram(const void *ctx, size_t i, size_t j)
{
    const centred_t *c = (const centred_t *)ctx;
    return c->h[i * c->m + j];
}

hyst_status_t hyst_everett_grid_fit_solve(const hyst_everett_grid_fit_t *fit,
                                          hyst_everett_grid_t *g, hyst_wide_t *rms)
{
    const size_t cols = fit != NULL ? fit->cols : 0u, m = cols - 1u;
    hyst_wide_t *h, *c, *w, n, big, syy, tol, rss, sum = 0, offset;
    centred_t ctx;
    hyst_nnls_t p;
    size_t i, j;
    if (fit == NULL || g == NULL || rms == NULL) {
        return HYST_ERR_NULL;
    }
    if (fit->used < 2u) {
        return HYST_ERR_SINGULAR;
    }
    n = (hyst_wide_t)fit->used;
    h = fit->solver;
    c = h + m * m;
    w = c + m;
    big = centre(fit, h, c);
    syy = fit->yy - fit->aty[0] * fit->aty[0] / n;
    tol = HYST_WIDE_SQRT(big * (syy > 0 ? syy : 0)) * HYST_WIDE_EPS * (hyst_wide_t)(1000u * m);
    ctx.h = h;
    ctx.m = m;
    p.n = m;
    p.gram = centred_gram;
    p.ctx = &ctx;
    p.c = c;
    p.w = w;
    p.s = w + m;
    p.g = w + 2u * m;
    p.set = w + 3u * m;
    p.b = w + 4u * m;
    p.l = w + 5u * m; /* m x m: the rest of the solver's numbers */
    p.most = m;
    if (big > 0) {
        (void)hyst_nnls_(&p, tol);
    } else {
        memset(w, 0, m * sizeof *w);
    }
    rss = syy;
    offset = fit->aty[0];
    for (i = 0u; i < m; ++i) {
        hyst_wide_t hw = 0;
        for (j = 0u; j < m; ++j) {
            hw += h[i * m + j] * w[j];
        }
        rss += w[i] * (hw - 2 * c[i]);
        offset -= w[i] * fit->ata[(i + 1u) * cols];
        sum += w[i];
    }
    /* outputs so large that the normal equations overflow: no fit (a NaN
     * residual would read as 0 below) */
    if (!hyst_wide_is_finite(sum) || !hyst_wide_is_finite(rss) ||
        !hyst_wide_is_finite(fit->y_ref + offset / n)) {
        return HYST_ERR_COEFF;
    }
    memset(g, 0, sizeof *g);
    g->intervals = fit->intervals;
    for (i = 0u; i <= fit->intervals; ++i) {
        g->knots[i] = fit->knots[i];
    }
    for (i = 0u; i < m; ++i) {
        g->weight[i] = w[i];
    }
    g->y_lo = fit->y_ref + offset / n;
    *rms = HYST_WIDE_SQRT((rss > 0 ? rss : 0) / n);
    return sum > 0 ? HYST_OK : HYST_ERR_NOT_MONOTONE;
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
