/* SPDX-License-Identifier: MIT */
/* Curve set-up, written once for every variant: polynomial validation,
 * shift/scale to [0, 1] and monotonicity proof, the inverse curves, checks.
 * Per-sample evaluation lives in src/curve_eval.h (one copy per real type). */
#include <string.h>

#include "hyst_util.h"

/* Rewrites p (highest power first, degree n) as the coefficients of
 * p(x0 + t) (Ruffini-Horner Taylor shift). */
static void taylor_shift(hyst_wide_t *p, unsigned n, hyst_wide_t x0)
{
    unsigned i, j;
    for (i = 0u; i < n; ++i) {
        for (j = 1u; j <= n - i; ++j) {
            p[j] += x0 * p[j - 1u];
        }
    }
}

/* Coefficients of f0(lo + span u), highest power first, into q[0..n]. */
static void normalise(hyst_wide_t *q, const hyst_wide_t *c, unsigned n,
                      hyst_wide_t lo, hyst_wide_t span)
{
    unsigned j;
    hyst_wide_t scale = 1;
    for (j = 0u; j <= n; ++j) {
        q[j] = c[j];
    }
    taylor_shift(q, n, lo);
    for (j = n + 1u; j-- > 0u;) { /* q[j] multiplies u^(n-j) */
        q[j] *= scale;
        scale *= span;
    }
}

/* Bernstein coefficients on [a, a + w] of d (lowest power first, degree m). */
static void bernstein_on(hyst_wide_t *beta, const hyst_wide_t *d, unsigned m,
                         hyst_wide_t a, hyst_wide_t w)
{
    hyst_wide_t q[HYST_MAX_DEGREE + 1]; /* m <= HYST_MAX_DEGREE */
    hyst_wide_t scale = 1;
    unsigned i, k;
    for (k = 0u; k <= m; ++k) { /* highest power first for taylor_shift */
        q[k] = d[m - k];
    }
    taylor_shift(q, m, a);
    for (k = 0u; k <= m; ++k) { /* q[m-k] multiplies t^k, scale by w^k */
        q[m - k] *= scale;
        scale *= w;
    }
    for (i = 0u; i <= m; ++i) {
        /* beta_i = sum_k C(i,k)/C(m,k) q_k, ratio built incrementally */
        hyst_wide_t sum = 0;
        hyst_wide_t ratio = 1;
        for (k = 0u; k <= i; ++k) {
            sum += ratio * q[m - k];
            if (k < i) {
                ratio *= (hyst_wide_t)(i - k) / (hyst_wide_t)(m - k);
            }
        }
        beta[i] = sum;
    }
}

static unsigned long trailing_zeros(unsigned long v)
{
    unsigned long n = 0u;
    while ((v & 1u) == 0u) {
        v >>= 1u;
        ++n;
    }
    return n;
}

/* Is G (lowest power first, degree n, on u in [0, 1]) non-decreasing?
 * Depth-first dyadic subdivision of the Bernstein form of G', no stack:
 * the next interval after an accepted one follows from its index alone. */
static int unit_increasing(const hyst_wide_t *g, unsigned n, hyst_wide_t *turn_u)
{
    const unsigned long leaves = 1ul << HYST_MONOTONE_DEPTH;
    hyst_wide_t d[HYST_MAX_DEGREE];
    hyst_wide_t beta[HYST_MAX_DEGREE];
    hyst_wide_t bound = 0;
    hyst_wide_t tol;
    unsigned long pos = 0u;  /* interval start, in leaves */
    unsigned long level = 0u;
    const unsigned m = n - 1u;
    unsigned k;

    for (k = 0u; k <= m; ++k) {
        d[k] = (hyst_wide_t)(k + 1u) * g[k + 1u];
        bound += hyst_wide_abs(d[k]);
    }
    /* Slopes within rounding of zero count as zero (x^3 at 0 is increasing):
     * 64 units of the Bernstein conversion's scale, as the asymmetric kind's
     * check. 1e-12 of it once let through a dip 13 % of the domain wide (x^9
     * + x^8 / 6.6 on [-1, 1]: a slope of -5e-8 there, 1e-9 of the range lost). */
    tol = bound * (sizeof(hyst_wide_t) >= 8u ? 64 * HYST_WIDE_EPS : (hyst_wide_t)1e-5);

    for (;;) {
        const hyst_wide_t width = (hyst_wide_t)1 / (hyst_wide_t)(1ul << level);
        const hyst_wide_t a = (hyst_wide_t)pos / (hyst_wide_t)leaves;
        hyst_wide_t lowest;
        int settled;
        bernstein_on(beta, d, m, a, width);
        if (beta[0] < -tol) {
            *turn_u = a;
            return 0;
        }
        lowest = beta[0];
        for (k = 0u; k <= m; ++k) {
            if (!hyst_wide_is_finite(beta[k])) {
                *turn_u = a; /* the slope overflows here: nothing provable */
                return 0;
            }
            lowest = beta[k] < lowest ? beta[k] : lowest;
        }
        settled = lowest >= -tol;
        if (!settled && level == HYST_MONOTONE_DEPTH) {
            if (beta[m] < -tol) {
                *turn_u = a + width;
                return 0;
            }
            settled = 1; /* dip narrower than one leaf: accepted */
        }
        if (settled) {
            pos += leaves >> level;
            if (pos == leaves) {
                return 1;
            }
            level = HYST_MONOTONE_DEPTH - trailing_zeros(pos);
        } else {
            ++level;
        }
    }
}

/* Bound on the error of hyst_unit_poly_()'s coefficients, as the error of
 * f0(lo + span u) - f0(lo) and of f0(lo) for any u in [0, 1]: the Taylor
 * shift by lo rounds each coefficient within gamma(2n) of the same shift of
 * |c| by |lo|, the powers of the span add n + 1 roundings, and storing them in
 * the variant's type is counted by rounding_bound(). Summed over
 * u^k <= 1 that is gamma(3n + 2) P(|lo| + span), P(z) = sum |c_k| z^k.
 * It is this term that grows when the domain lies far from 0 relative to
 * its span (coefficients expanded about 0 cancel there). */
hyst_wide_t hyst_unit_poly_error_(const hyst_wide_t *c, unsigned n, hyst_wide_t lo,
                                  hyst_wide_t hi)
{
    const hyst_wide_t eps = HYST_WIDE_EPS / 2;
    const hyst_wide_t z = hyst_wide_abs(lo) + (hi - lo);
    const hyst_wide_t m = (hyst_wide_t)(3u * n + 2u) * eps;
    hyst_wide_t p = 0;
    unsigned k;
    for (k = 0u; k <= n; ++k) {
        p = p * z + hyst_wide_abs(c[k]);
    }
    return m / (1 - m) * p;
}

/* Normalised coefficients lowest power first: g[k] multiplies u^k. */
void hyst_unit_poly_(hyst_wide_t *g, const hyst_wide_t *c, unsigned n,
                      hyst_wide_t lo, hyst_wide_t hi)
{
    hyst_wide_t q[HYST_MAX_DEGREE + 1];
    unsigned k;
    normalise(q, c, n, lo, hi - lo);
    for (k = 0u; k <= n; ++k) {
        g[k] = q[n - k];
    }
}

int hyst_poly_is_increasing(const hyst_wide_t *coeffs, unsigned degree,
                            hyst_wide_t lo, hyst_wide_t hi, hyst_wide_t *turn)
{
    hyst_wide_t g[HYST_MAX_DEGREE + 1];
    hyst_wide_t total = 0;
    hyst_wide_t turn_u = 0;
    unsigned k;
    int ok;
    hyst_unit_poly_(g, coeffs, degree, lo, hi);
    for (k = 1u; k <= degree; ++k) {
        total += g[k];
    }
    if (!hyst_wide_is_finite(total)) {
        ok = 0; /* the curve overflows hyst_wide_t on the domain: nothing provable */
    } else {
        ok = unit_increasing(g, degree, &turn_u);
        if (ok && !(total > 0)) { /* slope never negative yet f0(hi) <= f0(lo): constant */
            ok = 0;
            turn_u = 0;
        }
    }
    if (!ok && turn != NULL) {
        const hyst_wide_t at = lo + turn_u * (hi - lo);
        *turn = at > hi ? hi : at; /* rounding must not leave the domain */
    }
    return ok;
}

/* Rounding bound of one branch evaluation in the variant's type, from the
 * normalised coefficients g (lowest power first; G(u) = sum g_k u^k, k >= 1,
 * u in [0, 1]). u = (x - x_k) * (+-unit) carries a relative error of at
 * most gamma(2) (the difference, the product), which moves G by at most
 * gamma(2) max |u G'(u)|, bounded by the largest Bernstein coefficient of
 * u G'(u) on [0, 1] (no cancellation counted twice). Horner's rule with n
 * multiply-adds and the final product errs by at most gamma(2n + 1)
 * sum |g_k| (the classical a-priori bound of Horner's rule; it is this term
 * that grows with cancelling coefficients). The sum y_k +- G rounds once
 * more: eps max |y|. gamma(m) = m eps / (1 - m eps), eps the unit roundoff.
 * Storing g in the variant's type rounds each coefficient once more (one
 * more eps in Horner's term). @p shift is the error of g itself
 * (hyst_unit_poly_error_()): the curve that runs is f0 up to it.
 * The bound, 1 % above; its output range G(1) into *range. */
HYST_INLINE hyst_wide_t rounding_of(const hyst_wide_t *g, unsigned n, hyst_wide_t eps,
                                    hyst_wide_t shift, hyst_wide_t *range_out)
{
    hyst_wide_t ug[HYST_MAX_DEGREE + 1], beta[HYST_MAX_DEGREE + 1];
    hyst_wide_t sum = 0, range = 0, slope = 0, bound, y_max, y_hi;
    unsigned k;
    for (k = 0u; k <= n; ++k) {
        ug[k] = (hyst_wide_t)k * g[k]; /* u G'(u), lowest power first */
    }
    bernstein_on(beta, ug, n, 0, 1);
    for (k = 0u; k <= n; ++k) {
        slope = hyst_wide_abs(beta[k]) > slope ? hyst_wide_abs(beta[k]) : slope;
        if (k > 0u) {
            sum += hyst_wide_abs(g[k]);
            range += g[k];
        }
    }
    y_hi = hyst_wide_abs(g[0] + range);
    y_max = y_hi > hyst_wide_abs(g[0]) ? y_hi : hyst_wide_abs(g[0]);
    bound = (2 * eps / (1 - 2 * eps)) * slope +
            ((hyst_wide_t)(2u * n + 2u) * eps / (1 - (hyst_wide_t)(2u * n + 2u) * eps)) * sum +
            eps * y_max + shift;
    *range_out = range;
    return bound * (hyst_wide_t)1.01; /* the bound's own rounding, in hyst_wide_t */
}

/* The unit roundoff of the variant whose rounding a curve's bound counts. */
HYST_INLINE hyst_wide_t variant_eps(unsigned variant)
{
    return variant == (unsigned)HYST_VARIANT_F64 ? (hyst_wide_t)DBL_EPSILON / 2
                                                 : (hyst_wide_t)FLT_EPSILON / 2;
}

/* rounding_of() for the variant, stored in curve->rounding; 0 if it exceeds
 * HYST_MAX_ROUNDING of the output range. */
static int rounding_bound(hyst_curve_t *curve, const hyst_wide_t *g, unsigned n,
                          unsigned variant, hyst_wide_t shift)
{
    hyst_wide_t range;
    const hyst_wide_t bound = rounding_of(g, n, variant_eps(variant), shift, &range);
    (void)hyst_num_set(&curve->rounding, variant, bound);
    return bound <= (hyst_wide_t)HYST_MAX_ROUNDING * range; /* NaN: refused */
}

/* The checks of f0's fields every polynomial curve starts with; its
 * coefficients into c. Inline, as rounding_of(): a firmware usually links one of
 * their two callers, and a copy in it is smaller than a shared call. */
HYST_INLINE hyst_status_t poly_args(const hyst_poly_t *f0, unsigned long layout, hyst_wide_t *c)
{
    hyst_wide_t lo, hi;
    unsigned n, k;
    if (f0 == NULL) {
        return HYST_ERR_NULL;
    }
    if (layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    n = f0->degree;
    if (n < 1u || n > HYST_MAX_DEGREE) {
        return HYST_ERR_DEGREE;
    }
    lo = f0->lo;
    hi = f0->hi;
    if (!hyst_wide_is_finite(lo) || !hyst_wide_is_finite(hi) || !(lo < hi) ||
        !hyst_wide_is_finite(hi - lo)) {
        return HYST_ERR_DOMAIN;
    }
    for (k = 0u; k <= n; ++k) {
        c[k] = f0->coeffs[k];
        if (!hyst_wide_is_finite(c[k])) {
            return HYST_ERR_COEFF;
        }
    }
    return HYST_OK;
}

/* The sum of |g_k|, k >= 1: Horner's partial sums on [0, 1] stay below it. */
HYST_INLINE hyst_wide_t horner_bound(const hyst_wide_t *g, unsigned n)
{
    hyst_wide_t bound = 0;
    unsigned k;
    for (k = 1u; k <= n; ++k) {
        bound += hyst_wide_abs(g[k]);
    }
    return bound;
}

hyst_status_t hyst_poly_check_(const hyst_poly_t *f0, hyst_wide_t *g, unsigned long layout)
{
    hyst_wide_t c[HYST_MAX_DEGREE + 1];
    hyst_wide_t y_hi = 0, ymax, bound, range;
    unsigned n, k;
    int finite;
    const hyst_status_t st = poly_args(f0, layout, c);
    if (st != HYST_OK) {
        return st;
    }
    n = f0->degree;
    hyst_unit_poly_(g, c, n, f0->lo, f0->hi);
    finite = hyst_wide_is_finite(1 / (f0->hi - f0->lo));
    for (k = 0u; k <= n; ++k) {
        y_hi += g[k];
        finite &= hyst_wide_is_finite(g[k]);
    }
    ymax = hyst_wide_abs(g[0]) > hyst_wide_abs(y_hi) ? hyst_wide_abs(g[0]) : hyst_wide_abs(y_hi);
    bound = horner_bound(g, n);
    if (!finite || !hyst_wide_is_finite(y_hi) || !hyst_wide_is_finite(bound) ||
        !hyst_wide_is_finite(2 * ymax + bound)) {
        return HYST_ERR_COEFF;
    }
    if (!hyst_poly_is_increasing(c, n, f0->lo, f0->hi, NULL)) {
        return HYST_ERR_NOT_INCREASING;
    }
    bound = rounding_of(g, n, variant_eps((unsigned)HYST_VARIANT_F64),
                        hyst_unit_poly_error_(c, n, f0->lo, f0->hi), &range);
    return bound <= (hyst_wide_t)HYST_MAX_ROUNDING * range ? HYST_OK : HYST_ERR_ILL_CONDITIONED;
}

hyst_status_t hyst_curve_poly_(hyst_curve_t *curve, const hyst_poly_t *f0, unsigned variant,
                               unsigned long layout)
{
    hyst_wide_t c[HYST_MAX_DEGREE + 1];
    hyst_wide_t g[HYST_MAX_DEGREE + 1];
    hyst_curve_t out;
    hyst_wide_t lo, hi, y_hi;
    unsigned n, k;
    int finite = 1;
    hyst_status_t st;

    if (curve == NULL) {
        return HYST_ERR_NULL;
    }
    st = poly_args(f0, layout, c);
    if (st != HYST_OK) {
        return st;
    }
    n = f0->degree;
    lo = f0->lo;
    hi = f0->hi;
    hyst_unit_poly_(g, c, n, lo, hi);
    y_hi = 0;
    for (k = 0u; k <= n; ++k) {
        y_hi += g[k];
    }
    memset(&out, 0, sizeof out);
    out.kind = HYST_CURVE_POLY;
    out.variant = variant;
    out.layout = HYST_LAYOUT;
    out.u.poly.degree = n;
    finite &= hyst_num_set(&out.lo, variant, lo);
    finite &= hyst_num_set(&out.hi, variant, hi);
    finite &= hyst_num_set(&out.y_lo, variant, g[0]);
    finite &= hyst_num_set(&out.y_hi, variant, y_hi);
    finite &= hyst_num_set(&out.unit, variant, 1 / (hi - lo));
    for (k = 0u; k < n; ++k) {
        finite &= hyst_num_set(&out.u.poly.a[k], variant, g[n - k]); /* a[0] multiplies u^n */
    }
    if (!finite) {
        return HYST_ERR_COEFF;
    }
    /* Every per-sample quantity must be finite in the variant's type: an
     * input difference (up to hi - lo), Horner's partial sums (at most
     * sum |a_k| on [0, 1]) and an output (|y| + the output span). */
    {
        hyst_num_t probe;
        const hyst_wide_t bound = horner_bound(g, n);
        const hyst_wide_t ymax =
            hyst_wide_abs(g[0]) > hyst_wide_abs(y_hi) ? hyst_wide_abs(g[0]) : hyst_wide_abs(y_hi);
        if (!hyst_num_set(&probe, variant, hi - lo) ||
            !(hyst_num_get(&out.lo, variant) < hyst_num_get(&out.hi, variant))) {
            return HYST_ERR_DOMAIN; /* the span overflows, or lo and hi round together */
        }
        if (!hyst_wide_is_finite(bound) || !hyst_num_set(&probe, variant, bound) ||
            !hyst_num_set(&probe, variant, 2 * ymax + bound)) {
            return HYST_ERR_COEFF;
        }
    }
    if (!hyst_poly_is_increasing(c, n, lo, hi, NULL)) {
        return HYST_ERR_NOT_INCREASING;
    }
    if (!rounding_bound(&out, g, n, variant, hyst_unit_poly_error_(c, n, lo, hi))) {
        return HYST_ERR_ILL_CONDITIONED;
    }
    *curve = out;
    return HYST_OK;
}

hyst_status_t hyst_f32_curve_from_poly_(hyst_curve_t *curve, const hyst_poly_t *f0,
                                        unsigned long layout)
{
    return hyst_curve_poly_(curve, f0, HYST_VARIANT_F32, layout);
}

#if HYST_ENABLE_F64
hyst_status_t hyst_f64_curve_from_poly_(hyst_curve_t *curve, const hyst_poly_t *f0,
                                        unsigned long layout)
{
    return hyst_curve_poly_(curve, f0, HYST_VARIANT_F64, layout);
}
#endif

hyst_wide_t hyst_poly_eval(const hyst_poly_t *f0, hyst_wide_t x)
{
    hyst_wide_t acc;
    unsigned k;
    if (f0 == NULL) {
        return 0;
    }
    acc = f0->coeffs[0];
    for (k = 1u; k <= f0->degree && k <= HYST_MAX_DEGREE; ++k) {
        acc = acc * x + f0->coeffs[k];
    }
    return acc;
}

hyst_status_t hyst_curve_check(const hyst_curve_t *curve)
{
    if (curve == NULL) {
        return HYST_ERR_NULL;
    }
    if (curve->layout != HYST_LAYOUT) {
        return HYST_ERR_LAYOUT;
    }
    if (curve->variant != (unsigned)HYST_VARIANT_F32
#if HYST_ENABLE_F64
        && curve->variant != (unsigned)HYST_VARIANT_F64
#endif
    ) {
        return HYST_ERR_ARG;
    }
    if (!(hyst_num_get(&curve->lo, curve->variant) < hyst_num_get(&curve->hi, curve->variant))) {
        return HYST_ERR_ARG;
    }
    switch (curve->kind) {
    case HYST_CURVE_POLY:
        return curve->u.poly.degree >= 1u && curve->u.poly.degree <= HYST_MAX_DEGREE
                   ? HYST_OK
                   : HYST_ERR_ARG;
    case HYST_CURVE_POLY_INV:
        return curve->u.poly_inv.fwd.degree >= 1u &&
                       curve->u.poly_inv.fwd.degree <= HYST_MAX_DEGREE
                   ? HYST_OK
                   : HYST_ERR_ARG;
    case HYST_CURVE_EVERETT_INV_TABLE:
        if (curve->u.everett.table.f32 == NULL || curve->u.everett.rows < 3u ||
            curve->u.everett.intervals < 1u) {
            return HYST_ERR_ARG;
        }
        /* fall through */
    case HYST_CURVE_EVERETT:
    case HYST_CURVE_EVERETT_INV:
        return curve->u.everett.degree >= 1u &&
                       curve->u.everett.degree <= (unsigned)HYST_EVERETT_MAX_DEGREE &&
                       curve->u.everett.degree <= (unsigned)HYST_MAX_DEGREE
                   ? HYST_OK
                   : HYST_ERR_ARG;
    case HYST_CURVE_INV_TABLE:
        return curve->u.inv_table.fwd.degree >= 1u &&
                       curve->u.inv_table.fwd.degree <= HYST_MAX_DEGREE &&
                       curve->u.inv_table.table.f32 != NULL && curve->u.inv_table.intervals >= 1u
                   ? HYST_OK
                   : HYST_ERR_ARG;
    case HYST_CURVE_PWL:
    case HYST_CURVE_PWL_INV:
        return curve->u.pwl.x.f32 != NULL && curve->u.pwl.y.f32 != NULL && curve->u.pwl.n >= 2u
                   ? HYST_OK
                   : HYST_ERR_ARG;
    default:
        return HYST_ERR_ARG;
    }
}
