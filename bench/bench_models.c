/* SPDX-License-Identifier: MIT */
#include "bench_models.h"

#include <string.h>

const hyst_real_t bench_pi10_r[BENCH_PI_N] = {
    HYST_REAL_C(0.0), HYST_REAL_C(0.1), HYST_REAL_C(0.2), HYST_REAL_C(0.3),
    HYST_REAL_C(0.4), HYST_REAL_C(0.5), HYST_REAL_C(0.6), HYST_REAL_C(0.7),
    HYST_REAL_C(0.8), HYST_REAL_C(0.9)};

const hyst_real_t bench_pi10_w[BENCH_PI_N] = {
    HYST_REAL_C(0.0789), HYST_REAL_C(0.2268), HYST_REAL_C(0.1928),
    HYST_REAL_C(0.2019), HYST_REAL_C(0.1995), HYST_REAL_C(0.2001),
    HYST_REAL_C(0.2000), HYST_REAL_C(0.2000), HYST_REAL_C(0.1999),
    HYST_REAL_C(0.2005)};

void bench_f0_codes(hyst_poly_t *f0, double offset)
{
    const double s = 40.0 / (double)(BENCH_NU - 1u); /* volts per code */
    double c[4];
    unsigned i, j;
    c[0] = -6.1876e-6 * s * s * s;
    c[1] = 1.1949e-3 * s * s;
    c[2] = 8.6444e-2 * s;
    c[3] = 5.8517e-1;
    /* Taylor shift: q(x) = p(x - offset), highest power first. */
    for (i = 0u; i < 3u; ++i) {
        for (j = 1u; j <= 3u - i; ++j) {
            c[j] -= offset * c[j - 1u];
        }
    }
    f0->degree = 3u;
    f0->lo = (hyst_real_t)offset;
    f0->hi = (hyst_real_t)(offset + (double)(BENCH_NU - 1u));
    for (i = 0u; i < 4u; ++i) {
        f0->coeffs[i] = (hyst_real_t)c[i];
    }
}

/* The asymmetric E of a cubic f0 (its Taylor coefficients at lo: the
 * symmetric kind) with an added lower-end term, 0.1 of the linear one; at
 * degree 4 also a w^4 term, a quarter of the cubic's size (of the sign
 * that keeps E monotone: Eq. 20's cubic term is negative), so that E is
 * linear in t as the identification's usual choice. */
static void everett_of(hyst_everett_t *e, const hyst_poly_t *f0, unsigned degree)
{
    double c[4], lo, span;
    unsigned k;
    for (k = 0u; k < 4u; ++k) {
        c[k] = (double)f0->coeffs[k];
    }
    lo = (double)f0->lo;
    span = (double)f0->hi - lo;
    memset(e, 0, sizeof *e);
    e->degree = 3u;
    e->lo = f0->lo;
    e->hi = f0->hi;
    e->y_lo = ((c[0] * lo + c[1]) * lo + c[2]) * lo + c[3];
    /* g(w) = f0(lo + w span) - f0(lo): Taylor coefficients at lo */
    e->e[0][0] = (3.0 * c[0] * lo * lo + 2.0 * c[1] * lo + c[2]) * span;
    e->e[1][0] = (3.0 * c[0] * lo + c[1]) * span * span;
    e->e[2][0] = c[0] * span * span * span;
    e->e[0][1] = 0.1 * e->e[0][0];
    if (degree == 4u) {
        e->degree = 4u;
        e->e[3][0] = -0.25 * e->e[2][0];
    }
}

void bench_everett_codes(hyst_everett_t *e, double offset, unsigned degree)
{
    hyst_poly_t f0;
    bench_f0_codes(&f0, offset);
    everett_of(e, &f0, degree);
}

void bench_grid_codes(hyst_everett_grid_t *g, double offset)
{
    static const double at[7] = {0.0, 0.1, 0.3, 0.45, 0.55, 0.8, 1.0};
    unsigned i;
    memset(g, 0, sizeof *g);
    g->intervals = 6u;
    for (i = 0u; i <= 6u; ++i) {
        g->knots[i] = (hyst_wide_t)(offset + at[i] * (double)(BENCH_NU - 1u));
    }
    g->y_lo = 0;
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) {
        g->weight[i] = (hyst_wide_t)(i == 9u ? 10.0 : 1.0 + 0.1 * (double)i);
    }
}

hyst_status_t bench_grid_inverse_codes(hyst_curve_t *fwd, hyst_everett_grid_t *g, double offset,
                                       hyst_real_t *table, size_t len)
{
    double sum = 0.0;
    unsigned i;
    bench_grid_codes(g, 0.0);
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) {
        sum += (double)g->weight[i];
    }
    for (i = 0u; i < HYST_EVERETT_GRID_CELLS(6u); ++i) { /* y_hi - y_lo: the codes' span */
        g->weight[i] = (hyst_wide_t)((double)g->weight[i] * (double)(BENCH_NU - 1u) / sum);
    }
    g->y_lo = (hyst_wide_t)offset;
    return hyst_curve_from_everett_grid(fwd, g, table, len);
}

void bench_spline_codes(hyst_spline_t *f, double offset, double out_offset, double out_span)
{
    double v = 0.0;
    unsigned k;
    memset(f, 0, sizeof *f);
    f->intervals = 16u;
    f->lo = (hyst_wide_t)offset;
    f->hi = (hyst_wide_t)(offset + (double)(BENCH_NU - 1u));
    for (k = 0u; k <= 16u; ++k) { /* rises of 1, 1.1, ... and one of 10 (a near step) */
        f->value[k] = (hyst_wide_t)v;
        v += k == 9u ? 10.0 : 1.0 + 0.1 * (double)k;
    }
    v = (double)f->value[16];
    for (k = 0u; k <= 16u; ++k) { /* onto out_offset .. out_offset + out_span */
        f->value[k] = (hyst_wide_t)(out_offset + (double)f->value[k] * out_span / v);
    }
    for (k = 0u; k <= 16u; ++k) { /* the smaller neighbouring secant: every piece increases */
        const double h = (double)(f->hi - f->lo) / 16.0;
        const double left = k > 0u ? (double)(f->value[k] - f->value[k - 1u]) / h : 1e300;
        const double right = k < 16u ? (double)(f->value[k + 1u] - f->value[k]) / h : 1e300;
        f->slope[k] = (hyst_wide_t)(left < right ? left : right);
    }
}

void bench_everett_inverse_codes(hyst_everett_t *e, double offset)
{
    hyst_poly_t f0;
    bench_f0_inverse_codes(&f0, offset);
    everett_of(e, &f0, 3u);
}

void bench_f0_inverse_codes(hyst_poly_t *f0, double offset)
{
    static const double eq20[4] = {-6.1876e-6, 1.1949e-3, 8.6444e-2, 5.8517e-1};
    const double hi = 40.0;
    const double range = ((eq20[0] * hi + eq20[1]) * hi + eq20[2]) * hi; /* f0(hi) - f0(0) */
    const double s = (double)(BENCH_NU - 1u) / range;
    unsigned i;
    f0->degree = 3u;
    f0->lo = (hyst_real_t)0.0;
    f0->hi = (hyst_real_t)hi;
    for (i = 0u; i < 3u; ++i) {
        f0->coeffs[i] = (hyst_real_t)(eq20[i] * s);
    }
    f0->coeffs[3] = (hyst_real_t)offset; /* f0(0) = offset */
}
